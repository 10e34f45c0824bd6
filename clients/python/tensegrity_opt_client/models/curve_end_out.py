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
        message (str): what happened, in a sentence
        status (Literal['no_stable_equilibrium']): `no_stable_equilibrium`: no stable equilibrium is found there: the
            stable branches end (a fold, the joint range) and the global search finds no other
        success (bool): always false: the curve could not go on there
    """

    dx: float
    dy: float
    message: str
    status: Literal["no_stable_equilibrium"]
    success: bool
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        dx = self.dx

        dy = self.dy

        message = self.message

        status = self.status

        success = self.success

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "dx": dx,
                "dy": dy,
                "message": message,
                "status": status,
                "success": success,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        dx = d.pop("dx")

        dy = d.pop("dy")

        message = d.pop("message")

        status = cast(Literal["no_stable_equilibrium"], d.pop("status"))
        if status != "no_stable_equilibrium":
            raise ValueError(f"status must match const 'no_stable_equilibrium', got '{status}'")

        success = d.pop("success")

        curve_end_out = cls(
            dx=dx,
            dy=dy,
            message=message,
            status=status,
            success=success,
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
