from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="CurvePoint")


@_attrs_define
class CurvePoint:
    """
    Attributes:
        branch (int): branch identifier (-1: straight)
        dx (float):
        dy (float):
        energy (float):
        fx (float):
        fy (float):
        morse_index (int):
        q (list[float]):
        shape (str):
        stable (bool):
        status (str): solver status: "straight", "straight_not_equilibrium" (asymmetric preloads: the straight point is
            no equilibrium, stable false), or the solver's status of a converged equilibrium (e.g. "Newton_Converged")
    """

    branch: int
    dx: float
    dy: float
    energy: float
    fx: float
    fy: float
    morse_index: int
    q: list[float]
    shape: str
    stable: bool
    status: str
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        branch = self.branch

        dx = self.dx

        dy = self.dy

        energy = self.energy

        fx = self.fx

        fy = self.fy

        morse_index = self.morse_index

        q = self.q

        shape = self.shape

        stable = self.stable

        status = self.status

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "branch": branch,
                "dx": dx,
                "dy": dy,
                "energy": energy,
                "fx": fx,
                "fy": fy,
                "morse_index": morse_index,
                "q": q,
                "shape": shape,
                "stable": stable,
                "status": status,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        branch = d.pop("branch")

        dx = d.pop("dx")

        dy = d.pop("dy")

        energy = d.pop("energy")

        fx = d.pop("fx")

        fy = d.pop("fy")

        morse_index = d.pop("morse_index")

        q = cast(list[float], d.pop("q"))

        shape = d.pop("shape")

        stable = d.pop("stable")

        status = d.pop("status")

        curve_point = cls(
            branch=branch,
            dx=dx,
            dy=dy,
            energy=energy,
            fx=fx,
            fy=fy,
            morse_index=morse_index,
            q=q,
            shape=shape,
            stable=stable,
            status=status,
        )

        curve_point.additional_properties = d
        return curve_point

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
