from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar

from attrs import define as _attrs_define

T = TypeVar("T", bound="TensionBoundsIn")


@_attrs_define
class TensionBoundsIn:
    """bounds [T_min, T_max] on the preload tension k (2b - L0) at straight (force units): the object form of [lo, hi].

    Attributes:
        hi (float): upper bound
        lo (float): lower bound
    """

    hi: float
    lo: float

    def to_dict(self) -> dict[str, Any]:
        hi = self.hi

        lo = self.lo

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "hi": hi,
                "lo": lo,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        hi = d.pop("hi")

        lo = d.pop("lo")

        tension_bounds_in = cls(
            hi=hi,
            lo=lo,
        )

        return tension_bounds_in
