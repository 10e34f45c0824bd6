from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

T = TypeVar("T", bound="SweepGrid")


@_attrs_define
class SweepGrid:
    """``{parameter: [values]}``: the cartesian product, in the order the keys are given (first slowest).

    Attributes:
        L0 (list[float] | Unset): spring rest lengths
        a (list[float] | Unset): triangle half-heights
        b (list[float] | Unset): triangle half-lengths
        dx (list[float] | Unset): tip deflections along x (equilibrium, stiffness, equilibria_count, atlas)
        dy (list[float] | Unset): tip deflections along y (equilibrium, stiffness, equilibria_count, atlas)
        k (list[float] | Unset): spring stiffnesses
        load (list[list[float]] | Unset): tip forces [fx, fy] (equilibrium, stiffness; not with dx/dy)
        n (list[int] | Unset): segment counts
    """

    L0: list[float] | Unset = UNSET
    a: list[float] | Unset = UNSET
    b: list[float] | Unset = UNSET
    dx: list[float] | Unset = UNSET
    dy: list[float] | Unset = UNSET
    k: list[float] | Unset = UNSET
    load: list[list[float]] | Unset = UNSET
    n: list[int] | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        L0: list[float] | Unset = UNSET
        if not isinstance(self.L0, Unset):
            L0 = self.L0

        a: list[float] | Unset = UNSET
        if not isinstance(self.a, Unset):
            a = self.a

        b: list[float] | Unset = UNSET
        if not isinstance(self.b, Unset):
            b = self.b

        dx: list[float] | Unset = UNSET
        if not isinstance(self.dx, Unset):
            dx = self.dx

        dy: list[float] | Unset = UNSET
        if not isinstance(self.dy, Unset):
            dy = self.dy

        k: list[float] | Unset = UNSET
        if not isinstance(self.k, Unset):
            k = self.k

        load: list[list[float]] | Unset = UNSET
        if not isinstance(self.load, Unset):
            load = []
            for load_item_data in self.load:
                load_item = load_item_data

                load.append(load_item)

        n: list[int] | Unset = UNSET
        if not isinstance(self.n, Unset):
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
        L0 = cast(list[float], d.pop("L0", UNSET))

        a = cast(list[float], d.pop("a", UNSET))

        b = cast(list[float], d.pop("b", UNSET))

        dx = cast(list[float], d.pop("dx", UNSET))

        dy = cast(list[float], d.pop("dy", UNSET))

        k = cast(list[float], d.pop("k", UNSET))

        _load = d.pop("load", UNSET)
        load: list[list[float]] | Unset = UNSET
        if _load is not UNSET:
            load = []
            for load_item_data in _load:
                load_item = cast(list[float], load_item_data)

                load.append(load_item)

        n = cast(list[int], d.pop("n", UNSET))

        sweep_grid = cls(
            L0=L0,
            a=a,
            b=b,
            dx=dx,
            dy=dy,
            k=k,
            load=load,
            n=n,
        )

        return sweep_grid
