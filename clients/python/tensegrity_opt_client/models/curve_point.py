from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.curve_point_status import CurvePointStatus

if TYPE_CHECKING:
    from ..models.solver_info import SolverInfo


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
        solver (SolverInfo):
        stable (bool):
        status (CurvePointStatus): what the point is: `converged`: a converged equilibrium (the solver's own status and
            iterations in the point's solver); `straight`: the straight chain at dx = dy = 0, an equilibrium known exactly;
            `straight_not_equilibrium`: the straight chain at dx = dy = 0 where it is no equilibrium (asymmetric preloads:
            an unbounded tension would be needed): kept, marked, stable false; `absent`: a followed branch (Curve.branches)
            does not reach this point: its numbers are NaN
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
    solver: SolverInfo
    stable: bool
    status: CurvePointStatus
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

        solver = self.solver.to_dict()

        stable = self.stable

        status = self.status.value

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
                "solver": solver,
                "stable": stable,
                "status": status,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.solver_info import SolverInfo  # noqa: PLC0415

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

        solver = SolverInfo.from_dict(d.pop("solver"))

        stable = d.pop("stable")

        status = CurvePointStatus(d.pop("status"))

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
            solver=solver,
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
