from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

T = TypeVar("T", bound="StiffnessBoundIn")


@_attrs_define
class StiffnessBoundIn:
    """bounds on a stiffness (force / length; null for an open side): the object form of [lo, hi].

    Attributes:
        hi (float | None): upper bound
        lo (float | None): lower bound
    """

    hi: float | None
    lo: float | None

    def to_dict(self) -> dict[str, Any]:
        hi: float | None
        hi = self.hi

        lo: float | None
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

        def _parse_hi(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        hi = _parse_hi(d.pop("hi"))

        def _parse_lo(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        lo = _parse_lo(d.pop("lo"))

        stiffness_bound_in = cls(
            hi=hi,
            lo=lo,
        )

        return stiffness_bound_in
