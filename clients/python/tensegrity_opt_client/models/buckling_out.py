from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, Literal, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.buckling_out_boundary import BucklingOutBoundary

if TYPE_CHECKING:
    from ..models.mode_out import ModeOut


T = TypeVar("T", bound="BucklingOut")


@_attrs_define
class BucklingOut:
    """Critical loads and modes of the straight chain (`tensegrity_opt.Buckling`).

    Attributes:
        boundary (BucklingOutBoundary):
        critical_force (float): signed critical Fx0 = -min(loads) (negative: compressive)
        loads (list[float]): all critical loads, ascending
        message (str): what happened, in a sentence
        modes (list[ModeOut]):
        status (Literal['solved']): `solved`: the linearised eigenproblem of the straight chain was solved: every
            critical load asked for (all of them, or the lowest n_modes) with its mode
        success (bool): whether it worked: `status` is one of solved
    """

    boundary: BucklingOutBoundary
    critical_force: float
    loads: list[float]
    message: str
    modes: list[ModeOut]
    status: Literal["solved"]
    success: bool
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        boundary = self.boundary.value

        critical_force = self.critical_force

        loads = self.loads

        message = self.message

        modes = []
        for modes_item_data in self.modes:
            modes_item = modes_item_data.to_dict()
            modes.append(modes_item)

        status = self.status

        success = self.success

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "boundary": boundary,
                "critical_force": critical_force,
                "loads": loads,
                "message": message,
                "modes": modes,
                "status": status,
                "success": success,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.mode_out import ModeOut  # noqa: PLC0415

        d = dict(src_dict)
        boundary = BucklingOutBoundary(d.pop("boundary"))

        critical_force = d.pop("critical_force")

        loads = cast(list[float], d.pop("loads"))

        message = d.pop("message")

        modes = []
        _modes = d.pop("modes")
        for modes_item_data in _modes:
            modes_item = ModeOut.from_dict(modes_item_data)

            modes.append(modes_item)

        status = cast(Literal["solved"], d.pop("status"))
        if status != "solved":
            raise ValueError(f"status must match const 'solved', got '{status}'")

        success = d.pop("success")

        buckling_out = cls(
            boundary=boundary,
            critical_force=critical_force,
            loads=loads,
            message=message,
            modes=modes,
            status=status,
            success=success,
        )

        buckling_out.additional_properties = d
        return buckling_out

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
