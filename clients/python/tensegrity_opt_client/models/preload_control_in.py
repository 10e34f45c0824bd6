from __future__ import annotations

from collections.abc import Mapping
from typing import Any, Literal, TypeVar, cast

from attrs import define as _attrs_define

from ..models.preload_control_in_tip import PreloadControlInTip
from ..types import UNSET, Unset

T = TypeVar("T", bound="PreloadControlIn")


@_attrs_define
class PreloadControlIn:
    """The rest lengths moved along a unit direction of `2n` numbers (`L1_0, L2_0` of segment 1, then of
    segment 2, ...; `t` the distance in rest-length space, length units), the tip free under `load` or held.

        Attributes:
            direction (list[float]): 2n numbers: the direction in rest-length space (normalised)
            kind (Literal['preload']):
            load (list[float] | Unset): the fixed tip load with a free tip (force units)
            tip (PreloadControlInTip | Unset): free under `load`, or held where the start has it Default:
                PreloadControlInTip.FREE.
    """

    direction: list[float]
    kind: Literal["preload"]
    load: list[float] | Unset = UNSET
    tip: PreloadControlInTip | Unset = PreloadControlInTip.FREE

    def to_dict(self) -> dict[str, Any]:
        direction = self.direction

        kind = self.kind

        load: list[float] | Unset = UNSET
        if not isinstance(self.load, Unset):
            load = self.load

        tip: str | Unset = UNSET
        if not isinstance(self.tip, Unset):
            tip = self.tip.value

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "direction": direction,
                "kind": kind,
            }
        )
        if load is not UNSET:
            field_dict["load"] = load
        if tip is not UNSET:
            field_dict["tip"] = tip

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        direction = cast(list[float], d.pop("direction"))

        kind = cast(Literal["preload"], d.pop("kind"))
        if kind != "preload":
            raise ValueError(f"kind must match const 'preload', got '{kind}'")

        load = cast(list[float], d.pop("load", UNSET))

        _tip = d.pop("tip", UNSET)
        tip: PreloadControlInTip | Unset
        if isinstance(_tip, Unset):
            tip = UNSET
        else:
            tip = PreloadControlInTip(_tip)

        preload_control_in = cls(
            direction=direction,
            kind=kind,
            load=load,
            tip=tip,
        )

        return preload_control_in
