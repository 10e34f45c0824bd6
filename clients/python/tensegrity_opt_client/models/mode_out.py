from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="ModeOut")


@_attrs_define
class ModeOut:
    """
    Attributes:
        energy_factor (float):
        fy (float): Fy per unit amplitude (guided; 0 for free)
        fy_coefficient (float):
        load (float): critical compressive load P (> 0); Fx = -load
        mu_x (float):
        q (list[float]): mode shape (rad per unit amplitude)
        shape (str):
        signs (str):
        stable (bool):
    """

    energy_factor: float
    fy: float
    fy_coefficient: float
    load: float
    mu_x: float
    q: list[float]
    shape: str
    signs: str
    stable: bool
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        energy_factor = self.energy_factor

        fy = self.fy

        fy_coefficient = self.fy_coefficient

        load = self.load

        mu_x = self.mu_x

        q = self.q

        shape = self.shape

        signs = self.signs

        stable = self.stable

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "energy_factor": energy_factor,
                "fy": fy,
                "fy_coefficient": fy_coefficient,
                "load": load,
                "mu_x": mu_x,
                "q": q,
                "shape": shape,
                "signs": signs,
                "stable": stable,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        energy_factor = d.pop("energy_factor")

        fy = d.pop("fy")

        fy_coefficient = d.pop("fy_coefficient")

        load = d.pop("load")

        mu_x = d.pop("mu_x")

        q = cast(list[float], d.pop("q"))

        shape = d.pop("shape")

        signs = d.pop("signs")

        stable = d.pop("stable")

        mode_out = cls(
            energy_factor=energy_factor,
            fy=fy,
            fy_coefficient=fy_coefficient,
            load=load,
            mu_x=mu_x,
            q=q,
            shape=shape,
            signs=signs,
            stable=stable,
        )

        mode_out.additional_properties = d
        return mode_out

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
