from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar

from attrs import define as _attrs_define

from ..types import UNSET, Unset

T = TypeVar("T", bound="SweepUniformManipulator")


@_attrs_define
class SweepUniformManipulator:
    """The uniform base chain; a point's own n, a, b, k, L0 replace these.

    Attributes:
        l0 (float | Unset): spring rest length (both springs) Default: 1.0.
        a (float | Unset): triangle half-height Default: 1.0.
        b (float | Unset): triangle half-length Default: 1.0.
        k (float | Unset): spring stiffness (both springs) Default: 1.0.
        n (int | Unset): number of segments Default: 4.
    """

    l0: float | Unset = 1.0
    a: float | Unset = 1.0
    b: float | Unset = 1.0
    k: float | Unset = 1.0
    n: int | Unset = 4

    def to_dict(self) -> dict[str, Any]:
        l0 = self.l0

        a = self.a

        b = self.b

        k = self.k

        n = self.n

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if l0 is not UNSET:
            field_dict["L0"] = l0
        if a is not UNSET:
            field_dict["a"] = a
        if b is not UNSET:
            field_dict["b"] = b
        if k is not UNSET:
            field_dict["k"] = k
        if n is not UNSET:
            field_dict["n"] = n

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        l0 = d.pop("L0", UNSET)

        a = d.pop("a", UNSET)

        b = d.pop("b", UNSET)

        k = d.pop("k", UNSET)

        n = d.pop("n", UNSET)

        sweep_uniform_manipulator = cls(
            l0=l0,
            a=a,
            b=b,
            k=k,
            n=n,
        )

        return sweep_uniform_manipulator
