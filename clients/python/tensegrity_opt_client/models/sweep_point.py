from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

T = TypeVar("T", bound="SweepPoint")


@_attrs_define
class SweepPoint:
    """One point: any of the parameters (the rest from the base chain; dx = dy = 0).

    Attributes:
        L0 (float | Unset):
        a (float | Unset):
        b (float | Unset):
        dx (float | Unset):
        dy (float | Unset):
        k (float | Unset):
        load (list[float] | Unset): tip force [fx, fy]
        n (int | Unset):
    """

    L0: float | Unset = UNSET
    a: float | Unset = UNSET
    b: float | Unset = UNSET
    dx: float | Unset = UNSET
    dy: float | Unset = UNSET
    k: float | Unset = UNSET
    load: list[float] | Unset = UNSET
    n: int | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        L0 = self.L0

        a = self.a

        b = self.b

        dx = self.dx

        dy = self.dy

        k = self.k

        load: list[float] | Unset = UNSET
        if not isinstance(self.load, Unset):
            load = self.load

        n = self.n

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if L0 is not UNSET:
            field_dict["L0"] = L0
        if a is not UNSET:
            field_dict["a"] = a
        if b is not UNSET:
            field_dict["b"] = b
        if dx is not UNSET:
            field_dict["dx"] = dx
        if dy is not UNSET:
            field_dict["dy"] = dy
        if k is not UNSET:
            field_dict["k"] = k
        if load is not UNSET:
            field_dict["load"] = load
        if n is not UNSET:
            field_dict["n"] = n

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        L0 = d.pop("L0", UNSET)

        a = d.pop("a", UNSET)

        b = d.pop("b", UNSET)

        dx = d.pop("dx", UNSET)

        dy = d.pop("dy", UNSET)

        k = d.pop("k", UNSET)

        load = cast(list[float], d.pop("load", UNSET))

        n = d.pop("n", UNSET)

        sweep_point = cls(
            L0=L0,
            a=a,
            b=b,
            dx=dx,
            dy=dy,
            k=k,
            load=load,
            n=n,
        )

        return sweep_point
