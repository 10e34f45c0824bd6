from __future__ import annotations

from collections.abc import Mapping
from typing import Any, Literal, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

T = TypeVar("T", bound="GuidedControlIn")


@_attrs_define
class GuidedControlIn:
    """The paper's guided tip: `y` held at the start's value, `Fx = base_x + t d_x`, `Fy` the guide's reaction.

    Attributes:
        kind (Literal['guided']):
        base (list[float] | Unset): the load at t = 0 (force units)
        direction (list[float] | Unset): load direction (normalised; needs an x component)
    """

    kind: Literal["guided"]
    base: list[float] | Unset = UNSET
    direction: list[float] | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        kind = self.kind

        base: list[float] | Unset = UNSET
        if not isinstance(self.base, Unset):
            base = self.base

        direction: list[float] | Unset = UNSET
        if not isinstance(self.direction, Unset):
            direction = self.direction

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

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        kind = cast(Literal["guided"], d.pop("kind"))
        if kind != "guided":
            raise ValueError(f"kind must match const 'guided', got '{kind}'")

        base = cast(list[float], d.pop("base", UNSET))

        direction = cast(list[float], d.pop("direction", UNSET))

        guided_control_in = cls(
            kind=kind,
            base=base,
            direction=direction,
        )

        return guided_control_in
