from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.plan_step_out_method import PlanStepOutMethod
from ..models.plan_step_out_spring_states_type_0_item_item import PlanStepOutSpringStatesType0ItemItem
from ..models.plan_step_out_status import PlanStepOutStatus

if TYPE_CHECKING:
    from ..models.simulation_event_out import SimulationEventOut
    from ..models.solver_info import SolverInfo


T = TypeVar("T", bound="PlanStepOut")


@_attrs_define
class PlanStepOut:
    """One step of a plan (`PreloadStep.to_dict()`).

    Attributes:
        command (list[list[float]]): [L1_0, L2_0] per segment: what to send (an infeasible step: the held value, or with
            approach the nearest admissible pose's)
        end_angle (float):
        energy (float | None): the spring energy there (null likewise)
        events (list[SimulationEventOut]): what happened during the transition: snaps (with the landing q_after,
            tip_after) and a joint reaching its stop; `step` is the step's index, `fraction` where in its move
        feasible (bool):
        margin (float | None): the arm's stability margin under the command (torque / rad; null: the held rest lengths
            have no equilibrium under the step's load)
        message (str): what happened, in a sentence
        method (PlanStepOutMethod): how the command was found: newton, ipopt, nearest (the nearest admissible pose),
            horizon (a step of a horizon plan), none (held)
        proposal (list[list[float]]): the controller's proposal (the command, except on a held step: the nearest
            admissible pose's rest lengths)
        proposal_tip (list[float]): the tip the proposal reaches
        q (list[float]): the arm's configuration under the command (rad)
        residual (float | None): max-norm of the equilibrium and pose equations (Newton steps)
        solver (SolverInfo):
        spring_forces (list[list[float]] | None): each spring's force, tension positive: k (L - L0) (linear law), k
            max(0, L - L0) (tension-only)
        spring_lengths (list[list[float]] | None): each spring's length L (length units), [spring 1, spring 2] per
            segment
        spring_states (list[list[PlanStepOutSpringStatesType0ItemItem]] | None): `taut` (L >= L0), `slack` (tension-
            only, L < L0: no force) or `pushing` (linear law, L < L0: a compressive force a real tension spring cannot
            carry)
        spring_stretches (list[list[float]] | None): L - L0 per spring (negative: shorter than its rest length)
        status (PlanStepOutStatus): `feasible`: rest lengths meeting every requirement were found: the tip on the
            target, stable with the margin, inside the bounds and the rate limit (and, verified, all along the transition);
            `infeasible`: no admissible rest lengths put the tip on the target: the command is the held value (on_infeasible
            hold) or the nearest admissible pose's rest lengths (approach); q, tip, margin and energy describe the arm under
            the command, proposal and proposal_tip the nearest admissible pose; `snap`: the arm snapped during the step's
            transition (nothing admissible avoided it, e.g. a held command under a changing load): q and tip are where it
            landed (events give where it snapped); `no_equilibrium`: the arm has no equilibrium inside the physical range
            under the step's inputs: a joint reached its stop during the transition; q is the configuration there (margin
            and energy null) and the next step starts from it
        success (bool): whether it worked: `status` is one of feasible
        target (list[float]):
        tip (list[float]): the arm's tip under the command
        tip_error (float): |tip - target| (length units)
        transition_margin (float | None): the least stability margin along the step's transition (torque / rad; 0 where
            the arm snapped; null: none followed)
        verified (bool): the step's transition was followed: no fold, branch point or joint stop, the margin held all
            along, and the arm ends on the step's pose (false with `verify: false`, and for a step that starts against a
            joint's stop)
    """

    command: list[list[float]]
    end_angle: float
    energy: float | None
    events: list[SimulationEventOut]
    feasible: bool
    margin: float | None
    message: str
    method: PlanStepOutMethod
    proposal: list[list[float]]
    proposal_tip: list[float]
    q: list[float]
    residual: float | None
    solver: SolverInfo
    spring_forces: list[list[float]] | None
    spring_lengths: list[list[float]] | None
    spring_states: list[list[PlanStepOutSpringStatesType0ItemItem]] | None
    spring_stretches: list[list[float]] | None
    status: PlanStepOutStatus
    success: bool
    target: list[float]
    tip: list[float]
    tip_error: float
    transition_margin: float | None
    verified: bool
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        command = []
        for command_item_data in self.command:
            command_item = command_item_data

            command.append(command_item)

        end_angle = self.end_angle

        energy: float | None
        energy = self.energy

        events = []
        for events_item_data in self.events:
            events_item = events_item_data.to_dict()
            events.append(events_item)

        feasible = self.feasible

        margin: float | None
        margin = self.margin

        message = self.message

        method = self.method.value

        proposal = []
        for proposal_item_data in self.proposal:
            proposal_item = proposal_item_data

            proposal.append(proposal_item)

        proposal_tip = self.proposal_tip

        q = self.q

        residual: float | None
        residual = self.residual

        solver = self.solver.to_dict()

        spring_forces: list[list[float]] | None
        if isinstance(self.spring_forces, list):
            spring_forces = []
            for spring_forces_type_0_item_data in self.spring_forces:
                spring_forces_type_0_item = spring_forces_type_0_item_data

                spring_forces.append(spring_forces_type_0_item)

        else:
            spring_forces = self.spring_forces

        spring_lengths: list[list[float]] | None
        if isinstance(self.spring_lengths, list):
            spring_lengths = []
            for spring_lengths_type_0_item_data in self.spring_lengths:
                spring_lengths_type_0_item = spring_lengths_type_0_item_data

                spring_lengths.append(spring_lengths_type_0_item)

        else:
            spring_lengths = self.spring_lengths

        spring_states: list[list[str]] | None
        if isinstance(self.spring_states, list):
            spring_states = []
            for spring_states_type_0_item_data in self.spring_states:
                spring_states_type_0_item = []
                for spring_states_type_0_item_item_data in spring_states_type_0_item_data:
                    spring_states_type_0_item_item = spring_states_type_0_item_item_data.value
                    spring_states_type_0_item.append(spring_states_type_0_item_item)

                spring_states.append(spring_states_type_0_item)

        else:
            spring_states = self.spring_states

        spring_stretches: list[list[float]] | None
        if isinstance(self.spring_stretches, list):
            spring_stretches = []
            for spring_stretches_type_0_item_data in self.spring_stretches:
                spring_stretches_type_0_item = spring_stretches_type_0_item_data

                spring_stretches.append(spring_stretches_type_0_item)

        else:
            spring_stretches = self.spring_stretches

        status = self.status.value

        success = self.success

        target = self.target

        tip = self.tip

        tip_error = self.tip_error

        transition_margin: float | None
        transition_margin = self.transition_margin

        verified = self.verified

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "command": command,
                "end_angle": end_angle,
                "energy": energy,
                "events": events,
                "feasible": feasible,
                "margin": margin,
                "message": message,
                "method": method,
                "proposal": proposal,
                "proposal_tip": proposal_tip,
                "q": q,
                "residual": residual,
                "solver": solver,
                "spring_forces": spring_forces,
                "spring_lengths": spring_lengths,
                "spring_states": spring_states,
                "spring_stretches": spring_stretches,
                "status": status,
                "success": success,
                "target": target,
                "tip": tip,
                "tip_error": tip_error,
                "transition_margin": transition_margin,
                "verified": verified,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.simulation_event_out import SimulationEventOut  # noqa: PLC0415
        from ..models.solver_info import SolverInfo  # noqa: PLC0415

        d = dict(src_dict)
        command = []
        _command = d.pop("command")
        for command_item_data in _command:
            command_item = cast(list[float], command_item_data)

            command.append(command_item)

        end_angle = d.pop("end_angle")

        def _parse_energy(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        energy = _parse_energy(d.pop("energy"))

        events = []
        _events = d.pop("events")
        for events_item_data in _events:
            events_item = SimulationEventOut.from_dict(events_item_data)

            events.append(events_item)

        feasible = d.pop("feasible")

        def _parse_margin(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        margin = _parse_margin(d.pop("margin"))

        message = d.pop("message")

        method = PlanStepOutMethod(d.pop("method"))

        proposal = []
        _proposal = d.pop("proposal")
        for proposal_item_data in _proposal:
            proposal_item = cast(list[float], proposal_item_data)

            proposal.append(proposal_item)

        proposal_tip = cast(list[float], d.pop("proposal_tip"))

        q = cast(list[float], d.pop("q"))

        def _parse_residual(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        residual = _parse_residual(d.pop("residual"))

        solver = SolverInfo.from_dict(d.pop("solver"))

        def _parse_spring_forces(data: object) -> list[list[float]] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                spring_forces_type_0 = []
                _spring_forces_type_0 = data
                for spring_forces_type_0_item_data in _spring_forces_type_0:
                    spring_forces_type_0_item = cast(list[float], spring_forces_type_0_item_data)

                    spring_forces_type_0.append(spring_forces_type_0_item)

                return spring_forces_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None, data)

        spring_forces = _parse_spring_forces(d.pop("spring_forces"))

        def _parse_spring_lengths(data: object) -> list[list[float]] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                spring_lengths_type_0 = []
                _spring_lengths_type_0 = data
                for spring_lengths_type_0_item_data in _spring_lengths_type_0:
                    spring_lengths_type_0_item = cast(list[float], spring_lengths_type_0_item_data)

                    spring_lengths_type_0.append(spring_lengths_type_0_item)

                return spring_lengths_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None, data)

        spring_lengths = _parse_spring_lengths(d.pop("spring_lengths"))

        def _parse_spring_states(data: object) -> list[list[PlanStepOutSpringStatesType0ItemItem]] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                spring_states_type_0 = []
                _spring_states_type_0 = data
                for spring_states_type_0_item_data in _spring_states_type_0:
                    spring_states_type_0_item = []
                    _spring_states_type_0_item = spring_states_type_0_item_data
                    for spring_states_type_0_item_item_data in _spring_states_type_0_item:
                        spring_states_type_0_item_item = PlanStepOutSpringStatesType0ItemItem(
                            spring_states_type_0_item_item_data
                        )

                        spring_states_type_0_item.append(spring_states_type_0_item_item)

                    spring_states_type_0.append(spring_states_type_0_item)

                return spring_states_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[PlanStepOutSpringStatesType0ItemItem]] | None, data)

        spring_states = _parse_spring_states(d.pop("spring_states"))

        def _parse_spring_stretches(data: object) -> list[list[float]] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                spring_stretches_type_0 = []
                _spring_stretches_type_0 = data
                for spring_stretches_type_0_item_data in _spring_stretches_type_0:
                    spring_stretches_type_0_item = cast(list[float], spring_stretches_type_0_item_data)

                    spring_stretches_type_0.append(spring_stretches_type_0_item)

                return spring_stretches_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None, data)

        spring_stretches = _parse_spring_stretches(d.pop("spring_stretches"))

        status = PlanStepOutStatus(d.pop("status"))

        success = d.pop("success")

        target = cast(list[float], d.pop("target"))

        tip = cast(list[float], d.pop("tip"))

        tip_error = d.pop("tip_error")

        def _parse_transition_margin(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        transition_margin = _parse_transition_margin(d.pop("transition_margin"))

        verified = d.pop("verified")

        plan_step_out = cls(
            command=command,
            end_angle=end_angle,
            energy=energy,
            events=events,
            feasible=feasible,
            margin=margin,
            message=message,
            method=method,
            proposal=proposal,
            proposal_tip=proposal_tip,
            q=q,
            residual=residual,
            solver=solver,
            spring_forces=spring_forces,
            spring_lengths=spring_lengths,
            spring_states=spring_states,
            spring_stretches=spring_stretches,
            status=status,
            success=success,
            target=target,
            tip=tip,
            tip_error=tip_error,
            transition_margin=transition_margin,
            verified=verified,
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
