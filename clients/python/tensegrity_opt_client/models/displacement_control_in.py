from __future__ import annotations

from collections.abc import Mapping
from typing import Any, Literal, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

T = TypeVar("T", bound="DisplacementControlIn")


@_attrs_define
class DisplacementControlIn:
    """The tip moved along a line: the deflection `(dx, dy)` is the start's plus `t` times the unit direction
    (`t` in length units); the force is the one holding the tip there.

        Attributes:
            kind (Literal['displacement']):
            direction (list[float] | Unset): direction in (dx, dy) (normalised; dx > 0 shortens the chain)
    """

    kind: Literal["displacement"]
    direction: list[float] | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        kind = self.kind

        direction: list[float] | Unset = UNSET
        if not isinstance(self.direction, Unset):
            direction = self.direction

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "kind": kind,
            }
        )
        if direction is not UNSET:
            field_dict["direction"] = direction

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        kind = cast(Literal["displacement"], d.pop("kind"))
        if kind != "displacement":
            raise ValueError(f"kind must match const 'displacement', got '{kind}'")

        direction = cast(list[float], d.pop("direction", UNSET))

        displacement_control_in = cls(
            kind=kind,
            direction=direction,
        )

        return displacement_control_in
