from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

T = TypeVar("T", bound="RestLengthBoundsIn")


@_attrs_define
class RestLengthBoundsIn:
    """Actuator bounds {lo, hi} on every rest length (the object form of [lo, hi]).

    Attributes:
        hi (float | list[float]): upper bound
        lo (float | list[float]): lower bound
    """

    hi: float | list[float]
    lo: float | list[float]

    def to_dict(self) -> dict[str, Any]:
        hi: float | list[float]
        if isinstance(self.hi, list):
            hi = self.hi

        else:
            hi = self.hi

        lo: float | list[float]
        if isinstance(self.lo, list):
            lo = self.lo

        else:
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

        def _parse_hi(data: object) -> float | list[float]:
            try:
                if not isinstance(data, list):
                    raise TypeError()
                hi_type_1 = cast(list[float], data)

                return hi_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(float | list[float], data)

        hi = _parse_hi(d.pop("hi"))

        def _parse_lo(data: object) -> float | list[float]:
            try:
                if not isinstance(data, list):
                    raise TypeError()
                lo_type_1 = cast(list[float], data)

                return lo_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(float | list[float], data)

        lo = _parse_lo(d.pop("lo"))

        rest_length_bounds_in = cls(
            hi=hi,
            lo=lo,
        )

        return rest_length_bounds_in
