from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar

from attrs import define as _attrs_define

T = TypeVar("T", bound="SweepTensionIn")


@_attrs_define
class SweepTensionIn:
    """[T_min, T_max] on the spring preloads at straight: the object form of [lo, hi].

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

        sweep_tension_in = cls(
            hi=hi,
            lo=lo,
        )

        return sweep_tension_in
