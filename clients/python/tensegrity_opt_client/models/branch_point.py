from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="BranchPoint")


@_attrs_define
class BranchPoint:
    """A point of one followed branch; numbers are null where the branch does not exist.

    Attributes:
        dx (float):
        dy (float):
        energy (float | None):
        exists (bool):
        fx (float | None):
        fy (float | None):
        morse_index (int): -1 where the branch does not exist
        q (list[float | None]):
        shape (str):
        stable (bool):
    """

    dx: float
    dy: float
    energy: float | None
    exists: bool
    fx: float | None
    fy: float | None
    morse_index: int
    q: list[float | None]
    shape: str
    stable: bool
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        dx = self.dx

        dy = self.dy

        energy: float | None
        energy = self.energy

        exists = self.exists

        fx: float | None
        fx = self.fx

        fy: float | None
        fy = self.fy

        morse_index = self.morse_index

        q = []
        for q_item_data in self.q:
            q_item: float | None
            q_item = q_item_data
            q.append(q_item)

        shape = self.shape

        stable = self.stable

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "dx": dx,
                "dy": dy,
                "energy": energy,
                "exists": exists,
                "fx": fx,
                "fy": fy,
                "morse_index": morse_index,
                "q": q,
                "shape": shape,
                "stable": stable,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        dx = d.pop("dx")

        dy = d.pop("dy")

        def _parse_energy(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        energy = _parse_energy(d.pop("energy"))

        exists = d.pop("exists")

        def _parse_fx(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        fx = _parse_fx(d.pop("fx"))

        def _parse_fy(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        fy = _parse_fy(d.pop("fy"))

        morse_index = d.pop("morse_index")

        q = []
        _q = d.pop("q")
        for q_item_data in _q:

            def _parse_q_item(data: object) -> float | None:
                if data is None:
                    return data
                return cast(float | None, data)

            q_item = _parse_q_item(q_item_data)

            q.append(q_item)

        shape = d.pop("shape")

        stable = d.pop("stable")

        branch_point = cls(
            dx=dx,
            dy=dy,
            energy=energy,
            exists=exists,
            fx=fx,
            fy=fy,
            morse_index=morse_index,
            q=q,
            shape=shape,
            stable=stable,
        )

        branch_point.additional_properties = d
        return branch_point

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
