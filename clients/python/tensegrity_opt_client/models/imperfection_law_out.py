from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="ImperfectionLawOut")


@_attrs_define
class ImperfectionLawOut:
    """The small-imperfection law `perfect_load - load = coefficient |p|^exponent` fitted at `amplitudes`.

    Attributes:
        amplitudes (list[float]):
        coefficient (float):
        expected (float): the classical exponent: 2/3 (unstable-symmetric), 1/2 (asymmetric)
        exponent (float):
    """

    amplitudes: list[float]
    coefficient: float
    expected: float
    exponent: float
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        amplitudes = self.amplitudes

        coefficient = self.coefficient

        expected = self.expected

        exponent = self.exponent

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "amplitudes": amplitudes,
                "coefficient": coefficient,
                "expected": expected,
                "exponent": exponent,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        amplitudes = cast(list[float], d.pop("amplitudes"))

        coefficient = d.pop("coefficient")

        expected = d.pop("expected")

        exponent = d.pop("exponent")

        imperfection_law_out = cls(
            amplitudes=amplitudes,
            coefficient=coefficient,
            expected=expected,
            exponent=exponent,
        )

        imperfection_law_out.additional_properties = d
        return imperfection_law_out

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
