from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.plan_step_out_method import PlanStepOutMethod
from ..models.plan_step_out_status import PlanStepOutStatus

if TYPE_CHECKING:
    from ..models.solver_info import SolverInfo


T = TypeVar("T", bound="PlanStepOut")


@_attrs_define
class PlanStepOut:
    """One step of a plan (`PreloadStep.to_dict()`).

    Attributes:
        end_angle (float):
        energy (float | None): null: infeasible
        feasible (bool):
        margin (float | None): null: infeasible
        message (str): what happened, in a sentence
        method (PlanStepOutMethod):
        q (list[float]):
        residual (float | None): max-norm of the equilibrium and pose equations (Newton steps)
        rest_lengths (list[list[float]]): [L1_0, L2_0] per segment
        solver (SolverInfo):
        status (PlanStepOutStatus): `feasible`: rest lengths meeting every requirement were found: the tip on the
            target, stable with the margin, inside the bounds and the rate limit; `infeasible`: no admissible rest lengths:
            q and tip are the best reachable pose (rest_lengths what reaches it); the controller stays where it was
        success (bool): whether it worked: `status` is one of feasible
        target (list[float]):
        tip (list[float]):
    """

    end_angle: float
    energy: float | None
    feasible: bool
    margin: float | None
    message: str
    method: PlanStepOutMethod
    q: list[float]
    residual: float | None
    rest_lengths: list[list[float]]
    solver: SolverInfo
    status: PlanStepOutStatus
    success: bool
    target: list[float]
    tip: list[float]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        end_angle = self.end_angle

        energy: float | None
        energy = self.energy

        feasible = self.feasible

        margin: float | None
        margin = self.margin

        message = self.message

        method = self.method.value

        q = self.q

        residual: float | None
        residual = self.residual

        rest_lengths = []
        for rest_lengths_item_data in self.rest_lengths:
            rest_lengths_item = rest_lengths_item_data

            rest_lengths.append(rest_lengths_item)

        solver = self.solver.to_dict()

        status = self.status.value

        success = self.success

        target = self.target

        tip = self.tip

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "end_angle": end_angle,
                "energy": energy,
                "feasible": feasible,
                "margin": margin,
                "message": message,
                "method": method,
                "q": q,
                "residual": residual,
                "rest_lengths": rest_lengths,
                "solver": solver,
                "status": status,
                "success": success,
                "target": target,
                "tip": tip,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.solver_info import SolverInfo  # noqa: PLC0415

        d = dict(src_dict)
        end_angle = d.pop("end_angle")

        def _parse_energy(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        energy = _parse_energy(d.pop("energy"))

        feasible = d.pop("feasible")

        def _parse_margin(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        margin = _parse_margin(d.pop("margin"))

        message = d.pop("message")

        method = PlanStepOutMethod(d.pop("method"))

        q = cast(list[float], d.pop("q"))

        def _parse_residual(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        residual = _parse_residual(d.pop("residual"))

        rest_lengths = []
        _rest_lengths = d.pop("rest_lengths")
        for rest_lengths_item_data in _rest_lengths:
            rest_lengths_item = cast(list[float], rest_lengths_item_data)

            rest_lengths.append(rest_lengths_item)

        solver = SolverInfo.from_dict(d.pop("solver"))

        status = PlanStepOutStatus(d.pop("status"))

        success = d.pop("success")

        target = cast(list[float], d.pop("target"))

        tip = cast(list[float], d.pop("tip"))

        plan_step_out = cls(
            end_angle=end_angle,
            energy=energy,
            feasible=feasible,
            margin=margin,
            message=message,
            method=method,
            q=q,
            residual=residual,
            rest_lengths=rest_lengths,
            solver=solver,
            status=status,
            success=success,
            target=target,
            tip=tip,
        )

        plan_step_out.additional_properties = d
        return plan_step_out

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
