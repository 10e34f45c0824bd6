from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, Literal, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.plan_out_method_item import PlanOutMethodItem
from ..models.plan_out_objective import PlanOutObjective
from ..models.plan_out_on_infeasible import PlanOutOnInfeasible
from ..models.plan_out_on_snap import PlanOutOnSnap
from ..models.plan_out_spring_states_type_0_item_type_0_item_item import PlanOutSpringStatesType0ItemType0ItemItem
from ..models.plan_out_status import PlanOutStatus

if TYPE_CHECKING:
    from ..models.plan_step_out import PlanStepOut


T = TypeVar("T", bound="PlanOut")


@_attrs_define
class PlanOut:
    """`PreloadPlan.to_dict()`: per step done (`K` rows, fewer when the time limit cut the plan).

    Attributes:
        commands (list[list[list[float]]]): [L1_0, L2_0] per segment per step: what to send (consecutive commands differ
            by at most rate_limit times the time between them)
        end_angle (list[float]): the last link's absolute angle sum(q) per step (rad)
        feasible (list[bool]): rest lengths meeting every requirement put the tip on the target (false: the command
            held, or approaching with on_infeasible approach)
        horizon (int | Literal['all'] | None): null (step by step), N (receding) or all
        margin (list[float | None]): the arm's stability margin per step (torque / rad; null: no equilibrium under the
            held command)
        margin_required (float): the stability margin asked for (torque / rad)
        message (str): what happened, in a sentence
        method (list[PlanOutMethodItem]): how each step's command was found
        objective (PlanOutObjective): how the redundancy was resolved
        on_infeasible (PlanOutOnInfeasible): what the infeasible steps commanded
        on_snap (PlanOutOnSnap): what the plan did after a snap or a step without equilibrium
        proposals (list[list[list[float]]]): the controller's proposal per step (the commands, except on held steps: the
            nearest admissible pose's)
        q (list[list[float]]): the arm's configuration under each command (rad)
        seconds (float): wall time of the plan (s)
        spring_forces (list[list[list[float]] | None] | None): each spring's force, tension positive: k (L - L0) (linear
            law), k max(0, L - L0) (tension-only), per point
        spring_lengths (list[list[list[float]] | None] | None): each spring's length L (length units), [spring 1, spring
            2] per segment, per point
        spring_states (list[list[list[PlanOutSpringStatesType0ItemType0ItemItem]] | None] | None): `taut` (L >= L0),
            `slack` (tension-only, L < L0: no force) or `pushing` (linear law, L < L0: a compressive force a real tension
            spring cannot carry), per point
        spring_stretches (list[list[list[float]] | None] | None): L - L0 per spring (negative: shorter than its rest
            length), per point
        start (list[float] | None): the arm's configuration at time 0 (rad): where the first step's transition starts
        status (PlanOutStatus): `complete`: every step is feasible; `infeasible_steps`: some steps are infeasible (see
            feasible): each commands the held value (hold) or the nearest admissible pose's rest lengths (approach), the
            next starting from the arm's state under that command; `snapped`: the arm snapped during some step's transition
            (nothing admissible avoided it): that step reports where it landed and the next starts from there (on_snap
            continue), or the plan ends after it (stop); `no_equilibrium`: in some step the arm had no equilibrium inside
            the physical range (a joint reached its stop): that step reports the configuration there and the next starts
            from it, released (on_snap continue), or the plan ends after it (stop); `time_limit`: the time limit ran out:
            the steps done so far
        steps (list[PlanStepOut]): every step in full (why an infeasible step failed: `message`)
        success (bool): whether it worked: `status` is one of complete
        targets (list[list[float]]): the targets of the steps done
        times (list[float | None]): the instants of the steps done (seconds; the start at 0); null without a time base
        tip (list[list[float]]): the arm's tip under each command (the target when feasible)
        tip_error (list[float]): |tip - target| per step (length units)
        transition_margin (list[float | None]): the least stability margin along each step's transition (torque / rad;
            null: none followed)
        verified (list[bool]): each step's transition was followed (the previous command and load moving linearly to the
            step's): no fold, branch point or joint stop, the margin held all along, the arm ends on the step's pose (with
            `verify: false` nothing is followed: false everywhere)
    """

    commands: list[list[list[float]]]
    end_angle: list[float]
    feasible: list[bool]
    horizon: int | Literal["all"] | None
    margin: list[float | None]
    margin_required: float
    message: str
    method: list[PlanOutMethodItem]
    objective: PlanOutObjective
    on_infeasible: PlanOutOnInfeasible
    on_snap: PlanOutOnSnap
    proposals: list[list[list[float]]]
    q: list[list[float]]
    seconds: float
    spring_forces: list[list[list[float]] | None] | None
    spring_lengths: list[list[list[float]] | None] | None
    spring_states: list[list[list[PlanOutSpringStatesType0ItemType0ItemItem]] | None] | None
    spring_stretches: list[list[list[float]] | None] | None
    start: list[float] | None
    status: PlanOutStatus
    steps: list[PlanStepOut]
    success: bool
    targets: list[list[float]]
    times: list[float | None]
    tip: list[list[float]]
    tip_error: list[float]
    transition_margin: list[float | None]
    verified: list[bool]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        commands = []
        for commands_item_data in self.commands:
            commands_item = []
            for commands_item_item_data in commands_item_data:
                commands_item_item = commands_item_item_data

                commands_item.append(commands_item_item)

            commands.append(commands_item)

        end_angle = self.end_angle

        feasible = self.feasible

        horizon: int | Literal["all"] | None
        horizon = self.horizon

        margin = []
        for margin_item_data in self.margin:
            margin_item: float | None
            margin_item = margin_item_data
            margin.append(margin_item)

        margin_required = self.margin_required

        message = self.message

        method = []
        for method_item_data in self.method:
            method_item = method_item_data.value
            method.append(method_item)

        objective = self.objective.value

        on_infeasible = self.on_infeasible.value

        on_snap = self.on_snap.value

        proposals = []
        for proposals_item_data in self.proposals:
            proposals_item = []
            for proposals_item_item_data in proposals_item_data:
                proposals_item_item = proposals_item_item_data

                proposals_item.append(proposals_item_item)

            proposals.append(proposals_item)

        q = []
        for q_item_data in self.q:
            q_item = q_item_data

            q.append(q_item)

        seconds = self.seconds

        spring_forces: list[list[list[float]] | None] | None
        if isinstance(self.spring_forces, list):
            spring_forces = []
            for spring_forces_type_0_item_data in self.spring_forces:
                spring_forces_type_0_item: list[list[float]] | None
                if isinstance(spring_forces_type_0_item_data, list):
                    spring_forces_type_0_item = []
                    for spring_forces_type_0_item_type_0_item_data in spring_forces_type_0_item_data:
                        spring_forces_type_0_item_type_0_item = spring_forces_type_0_item_type_0_item_data

                        spring_forces_type_0_item.append(spring_forces_type_0_item_type_0_item)

                else:
                    spring_forces_type_0_item = spring_forces_type_0_item_data
                spring_forces.append(spring_forces_type_0_item)

        else:
            spring_forces = self.spring_forces

        spring_lengths: list[list[list[float]] | None] | None
        if isinstance(self.spring_lengths, list):
            spring_lengths = []
            for spring_lengths_type_0_item_data in self.spring_lengths:
                spring_lengths_type_0_item: list[list[float]] | None
                if isinstance(spring_lengths_type_0_item_data, list):
                    spring_lengths_type_0_item = []
                    for spring_lengths_type_0_item_type_0_item_data in spring_lengths_type_0_item_data:
                        spring_lengths_type_0_item_type_0_item = spring_lengths_type_0_item_type_0_item_data

                        spring_lengths_type_0_item.append(spring_lengths_type_0_item_type_0_item)

                else:
                    spring_lengths_type_0_item = spring_lengths_type_0_item_data
                spring_lengths.append(spring_lengths_type_0_item)

        else:
            spring_lengths = self.spring_lengths

        spring_states: list[list[list[str]] | None] | None
        if isinstance(self.spring_states, list):
            spring_states = []
            for spring_states_type_0_item_data in self.spring_states:
                spring_states_type_0_item: list[list[str]] | None
                if isinstance(spring_states_type_0_item_data, list):
                    spring_states_type_0_item = []
                    for spring_states_type_0_item_type_0_item_data in spring_states_type_0_item_data:
                        spring_states_type_0_item_type_0_item = []
                        for (
                            spring_states_type_0_item_type_0_item_item_data
                        ) in spring_states_type_0_item_type_0_item_data:
                            spring_states_type_0_item_type_0_item_item = (
                                spring_states_type_0_item_type_0_item_item_data.value
                            )
                            spring_states_type_0_item_type_0_item.append(spring_states_type_0_item_type_0_item_item)

                        spring_states_type_0_item.append(spring_states_type_0_item_type_0_item)

                else:
                    spring_states_type_0_item = spring_states_type_0_item_data
                spring_states.append(spring_states_type_0_item)

        else:
            spring_states = self.spring_states

        spring_stretches: list[list[list[float]] | None] | None
        if isinstance(self.spring_stretches, list):
            spring_stretches = []
            for spring_stretches_type_0_item_data in self.spring_stretches:
                spring_stretches_type_0_item: list[list[float]] | None
                if isinstance(spring_stretches_type_0_item_data, list):
                    spring_stretches_type_0_item = []
                    for spring_stretches_type_0_item_type_0_item_data in spring_stretches_type_0_item_data:
                        spring_stretches_type_0_item_type_0_item = spring_stretches_type_0_item_type_0_item_data

                        spring_stretches_type_0_item.append(spring_stretches_type_0_item_type_0_item)

                else:
                    spring_stretches_type_0_item = spring_stretches_type_0_item_data
                spring_stretches.append(spring_stretches_type_0_item)

        else:
            spring_stretches = self.spring_stretches

        start: list[float] | None
        if isinstance(self.start, list):
            start = self.start

        else:
            start = self.start

        status = self.status.value

        steps = []
        for steps_item_data in self.steps:
            steps_item = steps_item_data.to_dict()
            steps.append(steps_item)

        success = self.success

        targets = []
        for targets_item_data in self.targets:
            targets_item = targets_item_data

            targets.append(targets_item)

        times = []
        for times_item_data in self.times:
            times_item: float | None
            times_item = times_item_data
            times.append(times_item)

        tip = []
        for tip_item_data in self.tip:
            tip_item = tip_item_data

            tip.append(tip_item)

        tip_error = self.tip_error

        transition_margin = []
        for transition_margin_item_data in self.transition_margin:
            transition_margin_item: float | None
            transition_margin_item = transition_margin_item_data
            transition_margin.append(transition_margin_item)

        verified = self.verified

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "commands": commands,
                "end_angle": end_angle,
                "feasible": feasible,
                "horizon": horizon,
                "margin": margin,
                "margin_required": margin_required,
                "message": message,
                "method": method,
                "objective": objective,
                "on_infeasible": on_infeasible,
                "on_snap": on_snap,
                "proposals": proposals,
                "q": q,
                "seconds": seconds,
                "spring_forces": spring_forces,
                "spring_lengths": spring_lengths,
                "spring_states": spring_states,
                "spring_stretches": spring_stretches,
                "start": start,
                "status": status,
                "steps": steps,
                "success": success,
                "targets": targets,
                "times": times,
                "tip": tip,
                "tip_error": tip_error,
                "transition_margin": transition_margin,
                "verified": verified,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.plan_step_out import PlanStepOut  # noqa: PLC0415

        d = dict(src_dict)
        commands = []
        _commands = d.pop("commands")
        for commands_item_data in _commands:
            commands_item = []
            _commands_item = commands_item_data
            for commands_item_item_data in _commands_item:
                commands_item_item = cast(list[float], commands_item_item_data)

                commands_item.append(commands_item_item)

            commands.append(commands_item)

        end_angle = cast(list[float], d.pop("end_angle"))

        feasible = cast(list[bool], d.pop("feasible"))

        def _parse_horizon(data: object) -> int | Literal["all"] | None:
            if data is None:
                return data
            horizon_type_1 = cast(Literal["all"], data)
            if horizon_type_1 != "all":
                raise ValueError(f"horizon_type_1 must match const 'all', got '{horizon_type_1}'")
            return horizon_type_1
            return cast(int | Literal["all"] | None, data)

        horizon = _parse_horizon(d.pop("horizon"))

        margin = []
        _margin = d.pop("margin")
        for margin_item_data in _margin:

            def _parse_margin_item(data: object) -> float | None:
                if data is None:
                    return data
                return cast(float | None, data)

            margin_item = _parse_margin_item(margin_item_data)

            margin.append(margin_item)

        margin_required = d.pop("margin_required")

        message = d.pop("message")

        method = []
        _method = d.pop("method")
        for method_item_data in _method:
            method_item = PlanOutMethodItem(method_item_data)

            method.append(method_item)

        objective = PlanOutObjective(d.pop("objective"))

        on_infeasible = PlanOutOnInfeasible(d.pop("on_infeasible"))

        on_snap = PlanOutOnSnap(d.pop("on_snap"))

        proposals = []
        _proposals = d.pop("proposals")
        for proposals_item_data in _proposals:
            proposals_item = []
            _proposals_item = proposals_item_data
            for proposals_item_item_data in _proposals_item:
                proposals_item_item = cast(list[float], proposals_item_item_data)

                proposals_item.append(proposals_item_item)

            proposals.append(proposals_item)

        q = []
        _q = d.pop("q")
        for q_item_data in _q:
            q_item = cast(list[float], q_item_data)

            q.append(q_item)

        seconds = d.pop("seconds")

        def _parse_spring_forces(data: object) -> list[list[list[float]] | None] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                spring_forces_type_0 = []
                _spring_forces_type_0 = data
                for spring_forces_type_0_item_data in _spring_forces_type_0:

                    def _parse_spring_forces_type_0_item(data: object) -> list[list[float]] | None:
                        if data is None:
                            return data
                        try:
                            if not isinstance(data, list):
                                raise TypeError()
                            spring_forces_type_0_item_type_0 = []
                            _spring_forces_type_0_item_type_0 = data
                            for spring_forces_type_0_item_type_0_item_data in _spring_forces_type_0_item_type_0:
                                spring_forces_type_0_item_type_0_item = cast(
                                    list[float], spring_forces_type_0_item_type_0_item_data
                                )

                                spring_forces_type_0_item_type_0.append(spring_forces_type_0_item_type_0_item)

                            return spring_forces_type_0_item_type_0
                        except (TypeError, ValueError, AttributeError, KeyError):
                            pass
                        return cast(list[list[float]] | None, data)

                    spring_forces_type_0_item = _parse_spring_forces_type_0_item(spring_forces_type_0_item_data)

                    spring_forces_type_0.append(spring_forces_type_0_item)

                return spring_forces_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[list[float]] | None] | None, data)

        spring_forces = _parse_spring_forces(d.pop("spring_forces"))

        def _parse_spring_lengths(data: object) -> list[list[list[float]] | None] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                spring_lengths_type_0 = []
                _spring_lengths_type_0 = data
                for spring_lengths_type_0_item_data in _spring_lengths_type_0:

                    def _parse_spring_lengths_type_0_item(data: object) -> list[list[float]] | None:
                        if data is None:
                            return data
                        try:
                            if not isinstance(data, list):
                                raise TypeError()
                            spring_lengths_type_0_item_type_0 = []
                            _spring_lengths_type_0_item_type_0 = data
                            for spring_lengths_type_0_item_type_0_item_data in _spring_lengths_type_0_item_type_0:
                                spring_lengths_type_0_item_type_0_item = cast(
                                    list[float], spring_lengths_type_0_item_type_0_item_data
                                )

                                spring_lengths_type_0_item_type_0.append(spring_lengths_type_0_item_type_0_item)

                            return spring_lengths_type_0_item_type_0
                        except (TypeError, ValueError, AttributeError, KeyError):
                            pass
                        return cast(list[list[float]] | None, data)

                    spring_lengths_type_0_item = _parse_spring_lengths_type_0_item(spring_lengths_type_0_item_data)

                    spring_lengths_type_0.append(spring_lengths_type_0_item)

                return spring_lengths_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[list[float]] | None] | None, data)

        spring_lengths = _parse_spring_lengths(d.pop("spring_lengths"))

        def _parse_spring_states(
            data: object,
        ) -> list[list[list[PlanOutSpringStatesType0ItemType0ItemItem]] | None] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                spring_states_type_0 = []
                _spring_states_type_0 = data
                for spring_states_type_0_item_data in _spring_states_type_0:

                    def _parse_spring_states_type_0_item(
                        data: object,
                    ) -> list[list[PlanOutSpringStatesType0ItemType0ItemItem]] | None:
                        if data is None:
                            return data
                        try:
                            if not isinstance(data, list):
                                raise TypeError()
                            spring_states_type_0_item_type_0 = []
                            _spring_states_type_0_item_type_0 = data
                            for spring_states_type_0_item_type_0_item_data in _spring_states_type_0_item_type_0:
                                spring_states_type_0_item_type_0_item = []
                                _spring_states_type_0_item_type_0_item = spring_states_type_0_item_type_0_item_data
                                for (
                                    spring_states_type_0_item_type_0_item_item_data
                                ) in _spring_states_type_0_item_type_0_item:
                                    spring_states_type_0_item_type_0_item_item = (
                                        PlanOutSpringStatesType0ItemType0ItemItem(
                                            spring_states_type_0_item_type_0_item_item_data
                                        )
                                    )

                                    spring_states_type_0_item_type_0_item.append(
                                        spring_states_type_0_item_type_0_item_item
                                    )

                                spring_states_type_0_item_type_0.append(spring_states_type_0_item_type_0_item)

                            return spring_states_type_0_item_type_0
                        except (TypeError, ValueError, AttributeError, KeyError):
                            pass
                        return cast(list[list[PlanOutSpringStatesType0ItemType0ItemItem]] | None, data)

                    spring_states_type_0_item = _parse_spring_states_type_0_item(spring_states_type_0_item_data)

                    spring_states_type_0.append(spring_states_type_0_item)

                return spring_states_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[list[PlanOutSpringStatesType0ItemType0ItemItem]] | None] | None, data)

        spring_states = _parse_spring_states(d.pop("spring_states"))

        def _parse_spring_stretches(data: object) -> list[list[list[float]] | None] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                spring_stretches_type_0 = []
                _spring_stretches_type_0 = data
                for spring_stretches_type_0_item_data in _spring_stretches_type_0:

                    def _parse_spring_stretches_type_0_item(data: object) -> list[list[float]] | None:
                        if data is None:
                            return data
                        try:
                            if not isinstance(data, list):
                                raise TypeError()
                            spring_stretches_type_0_item_type_0 = []
                            _spring_stretches_type_0_item_type_0 = data
                            for spring_stretches_type_0_item_type_0_item_data in _spring_stretches_type_0_item_type_0:
                                spring_stretches_type_0_item_type_0_item = cast(
                                    list[float], spring_stretches_type_0_item_type_0_item_data
                                )

                                spring_stretches_type_0_item_type_0.append(spring_stretches_type_0_item_type_0_item)

                            return spring_stretches_type_0_item_type_0
                        except (TypeError, ValueError, AttributeError, KeyError):
                            pass
                        return cast(list[list[float]] | None, data)

                    spring_stretches_type_0_item = _parse_spring_stretches_type_0_item(
                        spring_stretches_type_0_item_data
                    )

                    spring_stretches_type_0.append(spring_stretches_type_0_item)

                return spring_stretches_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[list[float]] | None] | None, data)

        spring_stretches = _parse_spring_stretches(d.pop("spring_stretches"))

        def _parse_start(data: object) -> list[float] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                start_type_0 = cast(list[float], data)

                return start_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None, data)

        start = _parse_start(d.pop("start"))

        status = PlanOutStatus(d.pop("status"))

        steps = []
        _steps = d.pop("steps")
        for steps_item_data in _steps:
            steps_item = PlanStepOut.from_dict(steps_item_data)

            steps.append(steps_item)

        success = d.pop("success")

        targets = []
        _targets = d.pop("targets")
        for targets_item_data in _targets:
            targets_item = cast(list[float], targets_item_data)

            targets.append(targets_item)

        times = []
        _times = d.pop("times")
        for times_item_data in _times:

            def _parse_times_item(data: object) -> float | None:
                if data is None:
                    return data
                return cast(float | None, data)

            times_item = _parse_times_item(times_item_data)

            times.append(times_item)

        tip = []
        _tip = d.pop("tip")
        for tip_item_data in _tip:
            tip_item = cast(list[float], tip_item_data)

            tip.append(tip_item)

        tip_error = cast(list[float], d.pop("tip_error"))

        transition_margin = []
        _transition_margin = d.pop("transition_margin")
        for transition_margin_item_data in _transition_margin:

            def _parse_transition_margin_item(data: object) -> float | None:
                if data is None:
                    return data
                return cast(float | None, data)

            transition_margin_item = _parse_transition_margin_item(transition_margin_item_data)

            transition_margin.append(transition_margin_item)

        verified = cast(list[bool], d.pop("verified"))

        plan_out = cls(
            commands=commands,
            end_angle=end_angle,
            feasible=feasible,
            horizon=horizon,
            margin=margin,
            margin_required=margin_required,
            message=message,
            method=method,
            objective=objective,
            on_infeasible=on_infeasible,
            on_snap=on_snap,
            proposals=proposals,
            q=q,
            seconds=seconds,
            spring_forces=spring_forces,
            spring_lengths=spring_lengths,
            spring_states=spring_states,
            spring_stretches=spring_stretches,
            start=start,
            status=status,
            steps=steps,
            success=success,
            targets=targets,
            times=times,
            tip=tip,
            tip_error=tip_error,
            transition_margin=transition_margin,
            verified=verified,
        )

        plan_out.additional_properties = d
        return plan_out

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
