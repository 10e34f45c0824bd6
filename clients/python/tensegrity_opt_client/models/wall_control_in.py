from __future__ import annotations

from collections.abc import Mapping
from typing import Any, Literal, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

T = TypeVar("T", bound="WallControlIn")


@_attrs_define
class WallControlIn:
    """A frictionless wall through the start's tip: the tip slides along it, the load along the wall is
    `tau . (base + t d)`, the wall's reaction along its normal.

        Attributes:
            kind (Literal['wall']):
            base (list[float] | Unset): the load at t = 0 (force units)
            direction (list[float] | Unset): load direction (normalised; needs a component along the wall)
            normal (list[float] | Unset): the wall's normal (normalised)
    """

    kind: Literal["wall"]
    base: list[float] | Unset = UNSET
    direction: list[float] | Unset = UNSET
    normal: list[float] | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        kind = self.kind

        base: list[float] | Unset = UNSET
        if not isinstance(self.base, Unset):
            base = self.base

        direction: list[float] | Unset = UNSET
        if not isinstance(self.direction, Unset):
            direction = self.direction

        normal: list[float] | Unset = UNSET
        if not isinstance(self.normal, Unset):
            normal = self.normal

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "kind": kind,
            }
        )
        if base is not UNSET:
            field_dict["base"] = base
        if direction is not UNSET:
            field_dict["direction"] = direction
        if normal is not UNSET:
            field_dict["normal"] = normal

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        kind = cast(Literal["wall"], d.pop("kind"))
        if kind != "wall":
            raise ValueError(f"kind must match const 'wall', got '{kind}'")

        base = cast(list[float], d.pop("base", UNSET))

        direction = cast(list[float], d.pop("direction", UNSET))

        normal = cast(list[float], d.pop("normal", UNSET))

        wall_control_in = cls(
            kind=kind,
            base=base,
            direction=direction,
            normal=normal,
        )

        return wall_control_in
