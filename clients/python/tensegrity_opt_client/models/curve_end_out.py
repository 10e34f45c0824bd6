from __future__ import annotations

from collections.abc import Mapping
from typing import Any, Literal, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="CurveEndOut")


@_attrs_define
class CurveEndOut:
    """Where a partial curve stopped: the first requested point it could not compute.

    Attributes:
        dx (float):
        dy (float):
        message (str):
        reason (Literal['no_stable_equilibrium']): "no_stable_equilibrium": no stable equilibrium is found there (the
            stable branches end at a fold or the joint range and the global search finds no other)
    """

    dx: float
    dy: float
    message: str
    reason: Literal["no_stable_equilibrium"]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        dx = self.dx

        dy = self.dy

        message = self.message

        reason = self.reason

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "dx": dx,
                "dy": dy,
                "message": message,
                "reason": reason,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        dx = d.pop("dx")

        dy = d.pop("dy")

        message = d.pop("message")

        reason = cast(Literal["no_stable_equilibrium"], d.pop("reason"))
        if reason != "no_stable_equilibrium":
            raise ValueError(f"reason must match const 'no_stable_equilibrium', got '{reason}'")

        curve_end_out = cls(
            dx=dx,
            dy=dy,
            message=message,
            reason=reason,
        )

        curve_end_out.additional_properties = d
        return curve_end_out

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
