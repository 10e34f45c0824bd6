from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="SegmentOut")


@_attrs_define
class SegmentOut:
    """
    Attributes:
        l0 (float | list[float]):
        a (float):
        b (float):
        k (float | list[float]):
    """

    l0: float | list[float]
    a: float
    b: float
    k: float | list[float]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        l0: float | list[float]
        if isinstance(self.l0, list):
            l0 = self.l0

        else:
            l0 = self.l0

        a = self.a

        b = self.b

        k: float | list[float]
        if isinstance(self.k, list):
            k = self.k

        else:
            k = self.k

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "L0": l0,
                "a": a,
                "b": b,
                "k": k,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_l0(data: object) -> float | list[float]:
            try:
                if not isinstance(data, list):
                    raise TypeError()
                l0_type_1 = cast(list[float], data)

                return l0_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(float | list[float], data)

        l0 = _parse_l0(d.pop("L0"))

        a = d.pop("a")

        b = d.pop("b")

        def _parse_k(data: object) -> float | list[float]:
            try:
                if not isinstance(data, list):
                    raise TypeError()
                k_type_1 = cast(list[float], data)

                return k_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(float | list[float], data)

        k = _parse_k(d.pop("k"))

        segment_out = cls(
            l0=l0,
            a=a,
            b=b,
            k=k,
        )

        segment_out.additional_properties = d
        return segment_out

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
