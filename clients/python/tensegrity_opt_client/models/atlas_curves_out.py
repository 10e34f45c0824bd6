from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="AtlasCurvesOut")


@_attrs_define
class AtlasCurvesOut:
    """Segments `[[dx0, dy0], [dx1, dy1]]` joining the crossings of one kind inside each grid cell.

    Attributes:
        branch_end (list[list[list[float]]]):
        switch (list[list[list[float]]]):
    """

    branch_end: list[list[list[float]]]
    switch: list[list[list[float]]]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        branch_end = []
        for branch_end_item_data in self.branch_end:
            branch_end_item = []
            for branch_end_item_item_data in branch_end_item_data:
                branch_end_item_item = branch_end_item_item_data

                branch_end_item.append(branch_end_item_item)

            branch_end.append(branch_end_item)

        switch = []
        for switch_item_data in self.switch:
            switch_item = []
            for switch_item_item_data in switch_item_data:
                switch_item_item = switch_item_item_data

                switch_item.append(switch_item_item)

            switch.append(switch_item)

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "branch_end": branch_end,
                "switch": switch,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        branch_end = []
        _branch_end = d.pop("branch_end")
        for branch_end_item_data in _branch_end:
            branch_end_item = []
            _branch_end_item = branch_end_item_data
            for branch_end_item_item_data in _branch_end_item:
                branch_end_item_item = cast(list[float], branch_end_item_item_data)

                branch_end_item.append(branch_end_item_item)

            branch_end.append(branch_end_item)

        switch = []
        _switch = d.pop("switch")
        for switch_item_data in _switch:
            switch_item = []
            _switch_item = switch_item_data
            for switch_item_item_data in _switch_item:
                switch_item_item = cast(list[float], switch_item_item_data)

                switch_item.append(switch_item_item)

            switch.append(switch_item)

        atlas_curves_out = cls(
            branch_end=branch_end,
            switch=switch,
        )

        atlas_curves_out.additional_properties = d
        return atlas_curves_out

    @property
    def additional_keys(self) -> list[str]:
        return list(self.additional_properties.keys())

    def __getitem__(self, key: str) -> Any:
        return self.additional_properties[key]

    def __setitem__(self, key: str, value: Any) -> None:
        self.additional_properties[key] = value

    def __delitem__(self, key: str) -> None:
        del self.additional_properties[key]

    def __contains__(self, key: str) -> bool:
        return key in self.additional_properties
