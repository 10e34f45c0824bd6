from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.design_out_status import DesignOutStatus

if TYPE_CHECKING:
    from ..models.manipulator_out import ManipulatorOut
    from ..models.solver_info import SolverInfo


T = TypeVar("T", bound="DesignOut")


@_attrs_define
class DesignOut:
    """`Design.to_dict()`: the designed chain, its critical loads recomputed by `critical_force`.

    Attributes:
        active (list[str]): active constraints at the optimum
        critical_force (float): signed critical force, recomputed by critical_force on the design
        feasible (bool): preloads-for-load: whether the required load is reached
        initial_critical_force (float | None): the starting design's critical force
        loads (list[float]): all critical loads of the design, ascending (recomputed)
        manipulator (ManipulatorOut):
        message (str): what happened, in a sentence
        multiplicity (int): how many critical loads coincide with the smallest
        solver (SolverInfo):
        status (DesignOutStatus): `optimal`: IPOPT converged to a design meeting every constraint (and the required
            load, where one is asked); its critical load is recomputed by critical_force; `below_required`: the strongest
            design within the bounds, whose critical load stays below the required one; `infeasible`: IPOPT found no
            feasible design: its last point, lifted onto the joint-stiffness floor
        success (bool): whether it worked: `status` is one of optimal
    """

    active: list[str]
    critical_force: float
    feasible: bool
    initial_critical_force: float | None
    loads: list[float]
    manipulator: ManipulatorOut
    message: str
    multiplicity: int
    solver: SolverInfo
    status: DesignOutStatus
    success: bool
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        active = self.active

        critical_force = self.critical_force

        feasible = self.feasible

        initial_critical_force: float | None
        initial_critical_force = self.initial_critical_force

        loads = self.loads

        manipulator = self.manipulator.to_dict()

        message = self.message

        multiplicity = self.multiplicity

        solver = self.solver.to_dict()

        status = self.status.value

        success = self.success

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "active": active,
                "critical_force": critical_force,
                "feasible": feasible,
                "initial_critical_force": initial_critical_force,
                "loads": loads,
                "manipulator": manipulator,
                "message": message,
                "multiplicity": multiplicity,
                "solver": solver,
                "status": status,
                "success": success,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.manipulator_out import ManipulatorOut  # noqa: PLC0415
        from ..models.solver_info import SolverInfo  # noqa: PLC0415

        d = dict(src_dict)
        active = cast(list[str], d.pop("active"))

        critical_force = d.pop("critical_force")

        feasible = d.pop("feasible")

        def _parse_initial_critical_force(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        initial_critical_force = _parse_initial_critical_force(d.pop("initial_critical_force"))

        loads = cast(list[float], d.pop("loads"))

        manipulator = ManipulatorOut.from_dict(d.pop("manipulator"))

        message = d.pop("message")

        multiplicity = d.pop("multiplicity")

        solver = SolverInfo.from_dict(d.pop("solver"))

        status = DesignOutStatus(d.pop("status"))

        success = d.pop("success")

        design_out = cls(
            active=active,
            critical_force=critical_force,
            feasible=feasible,
            initial_critical_force=initial_critical_force,
            loads=loads,
            manipulator=manipulator,
            message=message,
            multiplicity=multiplicity,
            solver=solver,
            status=status,
            success=success,
        )

        design_out.additional_properties = d
        return design_out

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
