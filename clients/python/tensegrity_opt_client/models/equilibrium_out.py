from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.equilibrium_out_kind import EquilibriumOutKind
from ..models.equilibrium_out_status import EquilibriumOutStatus

if TYPE_CHECKING:
    from ..models.force import Force
    from ..models.solver_info import SolverInfo


T = TypeVar("T", bound="EquilibriumOut")


@_attrs_define
class EquilibriumOut:
    """An equilibrium configuration.

    Attributes:
        energy (float): elastic energy (force x length)
        force (Force):
        kind (EquilibriumOutKind):
        message (str): what happened, in a sentence
        morse_index (int): negative eigenvalues of the reduced Hessian (0: stable)
        q (list[float]): relative joint angles (rad)
        shape (str): shape label: I, C, U, ZU, Z or W<s>
        signs (str): sign of each joint angle: +, - or 0
        solver (SolverInfo):
        stable (bool):
        status (EquilibriumOutStatus): `converged`: a numerical solve converged to it (Newton on the KKT system, IPOPT,
            a continuation step; the solver's own status is in solver) and the equilibrium equations hold; `exact`: known in
            closed form: the straight chain, a single segment, or an unloaded chain (a product of its segments' critical
            points); `certified`: the least-energy stable member of a set of equilibria proven complete by the polynomial
            homotopy (method='homotopy')
        success (bool): whether it worked: `status` is one of certified, converged, exact
        tip (list[float]): tip position [x, y]
    """

    energy: float
    force: Force
    kind: EquilibriumOutKind
    message: str
    morse_index: int
    q: list[float]
    shape: str
    signs: str
    solver: SolverInfo
    stable: bool
    status: EquilibriumOutStatus
    success: bool
    tip: list[float]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        energy = self.energy

        force = self.force.to_dict()

        kind = self.kind.value

        message = self.message

        morse_index = self.morse_index

        q = self.q

        shape = self.shape

        signs = self.signs

        solver = self.solver.to_dict()

        stable = self.stable

        status = self.status.value

        success = self.success

        tip = self.tip

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "energy": energy,
                "force": force,
                "kind": kind,
                "message": message,
                "morse_index": morse_index,
                "q": q,
                "shape": shape,
                "signs": signs,
                "solver": solver,
                "stable": stable,
                "status": status,
                "success": success,
                "tip": tip,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.force import Force  # noqa: PLC0415
        from ..models.solver_info import SolverInfo  # noqa: PLC0415

        d = dict(src_dict)
        energy = d.pop("energy")

        force = Force.from_dict(d.pop("force"))

        kind = EquilibriumOutKind(d.pop("kind"))

        message = d.pop("message")

        morse_index = d.pop("morse_index")

        q = cast(list[float], d.pop("q"))

        shape = d.pop("shape")

        signs = d.pop("signs")

        solver = SolverInfo.from_dict(d.pop("solver"))

        stable = d.pop("stable")

        status = EquilibriumOutStatus(d.pop("status"))

        success = d.pop("success")

        tip = cast(list[float], d.pop("tip"))

        equilibrium_out = cls(
            energy=energy,
            force=force,
            kind=kind,
            message=message,
            morse_index=morse_index,
            q=q,
            shape=shape,
            signs=signs,
            solver=solver,
            stable=stable,
            status=status,
            success=success,
            tip=tip,
        )

        equilibrium_out.additional_properties = d
        return equilibrium_out

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
