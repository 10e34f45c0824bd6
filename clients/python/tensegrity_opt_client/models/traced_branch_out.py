from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.traced_branch_out_spring_states_type_0_item_type_0_item_item import (
    TracedBranchOutSpringStatesType0ItemType0ItemItem,
)
from ..models.traced_branch_out_status import TracedBranchOutStatus
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.branch_event_out import BranchEventOut
    from ..models.control_out import ControlOut
    from ..models.force import Force


T = TypeVar("T", bound="TracedBranchOut")


@_attrs_define
class TracedBranchOut:
    """An equilibrium branch: per point the parameter, configuration, force, tip, energy and stability; `status`
    says how it ended (`success` false: the corrector failed or time ran out, the points computed are kept).

        Attributes:
            control (ControlOut):
            deflection (list[list[float]]): (dx, dy) = (2 sum b - x, y) per point
            energy (list[float]): elastic energy per point (force x length)
            events (list[BranchEventOut]):
            force (list[Force]): tip force per point (a reaction where the tip is held)
            message (str): what happened, in a sentence
            morse_index (list[int]): negative eigenvalues of the reduced Hessian (0: stable)
            points (int):
            q (list[list[float]]): joint angles (rad) per point
            s (list[float]): arclength (normalised: rad, F / (k c^2 / 2b), length / 2b)
            spring_forces (list[list[list[float]] | None] | None): each spring's force, tension positive: k (L - L0) (linear
                law), k max(0, L - L0) (tension-only), per point
            spring_lengths (list[list[list[float]] | None] | None): each spring's length L (length units), [spring 1, spring
                2] per segment, per point
            spring_states (list[list[list[TracedBranchOutSpringStatesType0ItemType0ItemItem]] | None] | None): `taut` (L >=
                L0), `slack` (tension-only, L < L0: no force) or `pushing` (linear law, L < L0: a compressive force a real
                tension spring cannot carry), per point
            spring_stretches (list[list[list[float]] | None] | None): L - L0 per spring (negative: shorter than its rest
                length), per point
            stable (list[bool]):
            status (TracedBranchOutStatus): `t_max`: t reached t_max (the end point is solved there); `t_min`: t reached
                t_min (the end point is solved there); `joint_limit`: a joint reached its range bound (the end point is located
                on it); `max_points`: max_points points were computed; `stability_loss`: stopped after the first event where
                stability is lost (stop_at='stability_loss'); `event`: stopped after the first event (stop_at='event');
                `closed_loop`: the branch closed on its start; `workspace_boundary`: the held tip reached the edge of its
                workspace (the tip Jacobian loses rank); `force_bound`: the tip force exceeded FORCE_BOUND force units;
                `step_too_small`: the step fell below min_step: the corrector cannot pass a singular point or a cusp, or a
                change of stability between two points could not be located; `corrector_failed`: the corrector did not converge
                down to min_step; `time_limit`: the time limit ran out
            success (bool): whether it worked: `status` is one of closed_loop, event, force_bound, joint_limit, max_points,
                stability_loss, t_max, t_min, workspace_boundary
            t (list[float]): the control parameter (0 at the start)
            tip (list[list[float]]):
            rest_lengths (list[list[list[float]]] | None | Unset): preload only: [L1_0, L2_0] per segment per point
    """

    control: ControlOut
    deflection: list[list[float]]
    energy: list[float]
    events: list[BranchEventOut]
    force: list[Force]
    message: str
    morse_index: list[int]
    points: int
    q: list[list[float]]
    s: list[float]
    spring_forces: list[list[list[float]] | None] | None
    spring_lengths: list[list[list[float]] | None] | None
    spring_states: list[list[list[TracedBranchOutSpringStatesType0ItemType0ItemItem]] | None] | None
    spring_stretches: list[list[list[float]] | None] | None
    stable: list[bool]
    status: TracedBranchOutStatus
    success: bool
    t: list[float]
    tip: list[list[float]]
    rest_lengths: list[list[list[float]]] | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        control = self.control.to_dict()

        deflection = []
        for deflection_item_data in self.deflection:
            deflection_item = deflection_item_data

            deflection.append(deflection_item)

        energy = self.energy

        events = []
        for events_item_data in self.events:
            events_item = events_item_data.to_dict()
            events.append(events_item)

        force = []
        for force_item_data in self.force:
            force_item = force_item_data.to_dict()
            force.append(force_item)

        message = self.message

        morse_index = self.morse_index

        points = self.points

        q = []
        for q_item_data in self.q:
            q_item = q_item_data

            q.append(q_item)

        s = self.s

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

        stable = self.stable

        status = self.status.value

        success = self.success

        t = self.t

        tip = []
        for tip_item_data in self.tip:
            tip_item = tip_item_data

            tip.append(tip_item)

        rest_lengths: list[list[list[float]]] | None | Unset
        if isinstance(self.rest_lengths, Unset):
            rest_lengths = UNSET
        elif isinstance(self.rest_lengths, list):
            rest_lengths = []
            for rest_lengths_type_0_item_data in self.rest_lengths:
                rest_lengths_type_0_item = []
                for rest_lengths_type_0_item_item_data in rest_lengths_type_0_item_data:
                    rest_lengths_type_0_item_item = rest_lengths_type_0_item_item_data

                    rest_lengths_type_0_item.append(rest_lengths_type_0_item_item)

                rest_lengths.append(rest_lengths_type_0_item)

        else:
            rest_lengths = self.rest_lengths

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "control": control,
                "deflection": deflection,
                "energy": energy,
                "events": events,
                "force": force,
                "message": message,
                "morse_index": morse_index,
                "points": points,
                "q": q,
                "s": s,
                "spring_forces": spring_forces,
                "spring_lengths": spring_lengths,
                "spring_states": spring_states,
                "spring_stretches": spring_stretches,
                "stable": stable,
                "status": status,
                "success": success,
                "t": t,
                "tip": tip,
            }
        )
        if rest_lengths is not UNSET:
            field_dict["rest_lengths"] = rest_lengths

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.branch_event_out import BranchEventOut  # noqa: PLC0415
        from ..models.control_out import ControlOut  # noqa: PLC0415
        from ..models.force import Force  # noqa: PLC0415

        d = dict(src_dict)
        control = ControlOut.from_dict(d.pop("control"))

        deflection = []
        _deflection = d.pop("deflection")
        for deflection_item_data in _deflection:
            deflection_item = cast(list[float], deflection_item_data)

            deflection.append(deflection_item)

        energy = cast(list[float], d.pop("energy"))

        events = []
        _events = d.pop("events")
        for events_item_data in _events:
            events_item = BranchEventOut.from_dict(events_item_data)

            events.append(events_item)

        force = []
        _force = d.pop("force")
        for force_item_data in _force:
            force_item = Force.from_dict(force_item_data)

            force.append(force_item)

        message = d.pop("message")

        morse_index = cast(list[int], d.pop("morse_index"))

        points = d.pop("points")

        q = []
        _q = d.pop("q")
        for q_item_data in _q:
            q_item = cast(list[float], q_item_data)

            q.append(q_item)

        s = cast(list[float], d.pop("s"))

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
        ) -> list[list[list[TracedBranchOutSpringStatesType0ItemType0ItemItem]] | None] | None:
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
                    ) -> list[list[TracedBranchOutSpringStatesType0ItemType0ItemItem]] | None:
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
                                        TracedBranchOutSpringStatesType0ItemType0ItemItem(
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
                        return cast(list[list[TracedBranchOutSpringStatesType0ItemType0ItemItem]] | None, data)

                    spring_states_type_0_item = _parse_spring_states_type_0_item(spring_states_type_0_item_data)

                    spring_states_type_0.append(spring_states_type_0_item)

                return spring_states_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[list[TracedBranchOutSpringStatesType0ItemType0ItemItem]] | None] | None, data)

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

        stable = cast(list[bool], d.pop("stable"))

        status = TracedBranchOutStatus(d.pop("status"))

        success = d.pop("success")

        t = cast(list[float], d.pop("t"))

        tip = []
        _tip = d.pop("tip")
        for tip_item_data in _tip:
            tip_item = cast(list[float], tip_item_data)

            tip.append(tip_item)

        def _parse_rest_lengths(data: object) -> list[list[list[float]]] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                rest_lengths_type_0 = []
                _rest_lengths_type_0 = data
                for rest_lengths_type_0_item_data in _rest_lengths_type_0:
                    rest_lengths_type_0_item = []
                    _rest_lengths_type_0_item = rest_lengths_type_0_item_data
                    for rest_lengths_type_0_item_item_data in _rest_lengths_type_0_item:
                        rest_lengths_type_0_item_item = cast(list[float], rest_lengths_type_0_item_item_data)

                        rest_lengths_type_0_item.append(rest_lengths_type_0_item_item)

                    rest_lengths_type_0.append(rest_lengths_type_0_item)

                return rest_lengths_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[list[float]]] | None | Unset, data)

        rest_lengths = _parse_rest_lengths(d.pop("rest_lengths", UNSET))

        traced_branch_out = cls(
            control=control,
            deflection=deflection,
            energy=energy,
            events=events,
            force=force,
            message=message,
            morse_index=morse_index,
            points=points,
            q=q,
            s=s,
            spring_forces=spring_forces,
            spring_lengths=spring_lengths,
            spring_states=spring_states,
            spring_stretches=spring_stretches,
            stable=stable,
            status=status,
            success=success,
            t=t,
            tip=tip,
            rest_lengths=rest_lengths,
        )

        traced_branch_out.additional_properties = d
        return traced_branch_out

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
