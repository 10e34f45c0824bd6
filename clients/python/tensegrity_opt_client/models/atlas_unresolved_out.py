from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="AtlasUnresolvedOut")


@_attrs_define
class AtlasUnresolvedOut:
    """
    Attributes:
        edge (list[list[int]]):
        reason (str):
    """

    edge: list[list[int]]
    reason: str
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        edge = []
        for edge_item_data in self.edge:
            edge_item = edge_item_data

            edge.append(edge_item)

        reason = self.reason

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "edge": edge,
                "reason": reason,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        edge = []
        _edge = d.pop("edge")
        for edge_item_data in _edge:
            edge_item = cast(list[int], edge_item_data)

            edge.append(edge_item)

        reason = d.pop("reason")

        atlas_unresolved_out = cls(
            edge=edge,
            reason=reason,
        )

        atlas_unresolved_out.additional_properties = d
        return atlas_unresolved_out

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
