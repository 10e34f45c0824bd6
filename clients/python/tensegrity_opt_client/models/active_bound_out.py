from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.active_bound_out_side import ActiveBoundOutSide

T = TypeVar("T", bound="ActiveBoundOut")


@_attrs_define
class ActiveBoundOut:
    """A decision variable at (or within 1 % of its interval of) one of its bounds at the optimum (`ActiveBound`).

    Attributes:
        bound (float): the bound it is at
        segment (int): the segment, 0-based
        side (ActiveBoundOutSide):
        value (float): the variable's value at the optimum
        variable (str): the variable: L1_0, L2_0 (rest lengths), a, b, k, L0
    """

    bound: float
    segment: int
    side: ActiveBoundOutSide
    value: float
    variable: str
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        bound = self.bound

        segment = self.segment

        side = self.side.value

        value = self.value

        variable = self.variable

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "bound": bound,
                "segment": segment,
                "side": side,
                "value": value,
                "variable": variable,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        bound = d.pop("bound")

        segment = d.pop("segment")

        side = ActiveBoundOutSide(d.pop("side"))

        value = d.pop("value")

        variable = d.pop("variable")

        active_bound_out = cls(
            bound=bound,
            segment=segment,
            side=side,
            value=value,
            variable=variable,
        )

        active_bound_out.additional_properties = d
        return active_bound_out

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
