from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.simulation_out_mode import SimulationOutMode
from ..models.simulation_out_spring_states_type_0_item_type_0_item_item import (
    SimulationOutSpringStatesType0ItemType0ItemItem,
)
from ..models.simulation_out_status import SimulationOutStatus
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.force import Force
    from ..models.simulation_event_out import SimulationEventOut


T = TypeVar("T", bound="SimulationOut")


@_attrs_define
class SimulationOut:
    """`Simulation.to_dict()`: the state at each sample done (`done` of `steps`) and the events; `status` says how
    it ended (time_limit: cut by the server's time limit; the samples done are kept).

        Attributes:
            deflection (list[list[float]]): (dx, dy) = (2 sum b - x, y) per sample done
            done (int): samples simulated
            energy (list[float]): elastic energy (force x length)
            events (list[SimulationEventOut]): snaps, bifurcations and the joint-limit end, in time order
            force (list[Force]): the load (free) or the holding force (held) per sample done
            message (str): what happened, in a sentence
            mode (SimulationOutMode):
            morse_index (list[int]):
            potential (list[float]): E - F . tip (free) or E (held)
            preloads (list[list[list[float]]]): the rest lengths at every sample (the input)
            q (list[list[float]]): joint angles (rad) per sample done
            spring_forces (list[list[list[float]] | None] | None): each spring's force, tension positive: k (L - L0) (linear
                law), k max(0, L - L0) (tension-only), per point
            spring_lengths (list[list[list[float]] | None] | None): each spring's length L (length units), [spring 1, spring
                2] per segment, per point
            spring_states (list[list[list[SimulationOutSpringStatesType0ItemType0ItemItem]] | None] | None): `taut` (L >=
                L0), `slack` (tension-only, L < L0: no force) or `pushing` (linear law, L < L0: a compressive force a real
                tension spring cannot carry), per point
            spring_stretches (list[list[list[float]] | None] | None): L - L0 per spring (negative: shorter than its rest
                length), per point
            stable (list[bool]):
            status (SimulationOutStatus): `complete`: every sample simulated; `joint_limit`: a joint reached its range bound
                (on the followed branch or during a snap): no equilibrium beyond inside the physical range;
                `workspace_boundary`: the held tip reached the edge of its workspace; `force_bound`: the tip force grew beyond
                the continuation's bound; `time_limit`: the time limit ran out; `failed`: the followed branch or a snap could
                not be computed (message says where)
            steps (int): samples asked for (K)
            success (bool): whether it worked: `status` is one of complete
            tip (list[list[float]]):
            loads (list[list[float]] | None | Unset): the dead tip loads (free)
            targets (list[list[float]] | None | Unset): the tip deflections (held)
    """

    deflection: list[list[float]]
    done: int
    energy: list[float]
    events: list[SimulationEventOut]
    force: list[Force]
    message: str
    mode: SimulationOutMode
    morse_index: list[int]
    potential: list[float]
    preloads: list[list[list[float]]]
    q: list[list[float]]
    spring_forces: list[list[list[float]] | None] | None
    spring_lengths: list[list[list[float]] | None] | None
    spring_states: list[list[list[SimulationOutSpringStatesType0ItemType0ItemItem]] | None] | None
    spring_stretches: list[list[list[float]] | None] | None
    stable: list[bool]
    status: SimulationOutStatus
    steps: int
    success: bool
    tip: list[list[float]]
    loads: list[list[float]] | None | Unset = UNSET
    targets: list[list[float]] | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        deflection = []
        for deflection_item_data in self.deflection:
            deflection_item = deflection_item_data

            deflection.append(deflection_item)

        done = self.done

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

        mode = self.mode.value

        morse_index = self.morse_index

        potential = self.potential

        preloads = []
        for preloads_item_data in self.preloads:
            preloads_item = []
            for preloads_item_item_data in preloads_item_data:
                preloads_item_item = preloads_item_item_data

                preloads_item.append(preloads_item_item)

            preloads.append(preloads_item)

        q = []
        for q_item_data in self.q:
            q_item = q_item_data

            q.append(q_item)

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

        steps = self.steps

        success = self.success

        tip = []
        for tip_item_data in self.tip:
            tip_item = tip_item_data

            tip.append(tip_item)

        loads: list[list[float]] | None | Unset
        if isinstance(self.loads, Unset):
            loads = UNSET
        elif isinstance(self.loads, list):
            loads = []
            for loads_type_0_item_data in self.loads:
                loads_type_0_item = loads_type_0_item_data

                loads.append(loads_type_0_item)

        else:
            loads = self.loads

        targets: list[list[float]] | None | Unset
        if isinstance(self.targets, Unset):
            targets = UNSET
        elif isinstance(self.targets, list):
            targets = []
            for targets_type_0_item_data in self.targets:
                targets_type_0_item = targets_type_0_item_data

                targets.append(targets_type_0_item)

        else:
            targets = self.targets

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "deflection": deflection,
                "done": done,
                "energy": energy,
                "events": events,
                "force": force,
                "message": message,
                "mode": mode,
                "morse_index": morse_index,
                "potential": potential,
                "preloads": preloads,
                "q": q,
                "spring_forces": spring_forces,
                "spring_lengths": spring_lengths,
                "spring_states": spring_states,
                "spring_stretches": spring_stretches,
                "stable": stable,
                "status": status,
                "steps": steps,
                "success": success,
                "tip": tip,
            }
        )
        if loads is not UNSET:
            field_dict["loads"] = loads
        if targets is not UNSET:
            field_dict["targets"] = targets

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.force import Force  # noqa: PLC0415
        from ..models.simulation_event_out import SimulationEventOut  # noqa: PLC0415

        d = dict(src_dict)
        deflection = []
        _deflection = d.pop("deflection")
        for deflection_item_data in _deflection:
            deflection_item = cast(list[float], deflection_item_data)

            deflection.append(deflection_item)

        done = d.pop("done")

        energy = cast(list[float], d.pop("energy"))

        events = []
        _events = d.pop("events")
        for events_item_data in _events:
            events_item = SimulationEventOut.from_dict(events_item_data)

            events.append(events_item)

        force = []
        _force = d.pop("force")
        for force_item_data in _force:
            force_item = Force.from_dict(force_item_data)

            force.append(force_item)

        message = d.pop("message")

        mode = SimulationOutMode(d.pop("mode"))

        morse_index = cast(list[int], d.pop("morse_index"))

        potential = cast(list[float], d.pop("potential"))

        preloads = []
        _preloads = d.pop("preloads")
        for preloads_item_data in _preloads:
            preloads_item = []
            _preloads_item = preloads_item_data
            for preloads_item_item_data in _preloads_item:
                preloads_item_item = cast(list[float], preloads_item_item_data)

                preloads_item.append(preloads_item_item)

            preloads.append(preloads_item)

        q = []
        _q = d.pop("q")
        for q_item_data in _q:
            q_item = cast(list[float], q_item_data)

            q.append(q_item)

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
        ) -> list[list[list[SimulationOutSpringStatesType0ItemType0ItemItem]] | None] | None:
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
                    ) -> list[list[SimulationOutSpringStatesType0ItemType0ItemItem]] | None:
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
                                        SimulationOutSpringStatesType0ItemType0ItemItem(
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
                        return cast(list[list[SimulationOutSpringStatesType0ItemType0ItemItem]] | None, data)

                    spring_states_type_0_item = _parse_spring_states_type_0_item(spring_states_type_0_item_data)

                    spring_states_type_0.append(spring_states_type_0_item)

                return spring_states_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[list[SimulationOutSpringStatesType0ItemType0ItemItem]] | None] | None, data)

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

        status = SimulationOutStatus(d.pop("status"))

        steps = d.pop("steps")

        success = d.pop("success")

        tip = []
        _tip = d.pop("tip")
        for tip_item_data in _tip:
            tip_item = cast(list[float], tip_item_data)

            tip.append(tip_item)

        def _parse_loads(data: object) -> list[list[float]] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                loads_type_0 = []
                _loads_type_0 = data
                for loads_type_0_item_data in _loads_type_0:
                    loads_type_0_item = cast(list[float], loads_type_0_item_data)

                    loads_type_0.append(loads_type_0_item)

                return loads_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None | Unset, data)

        loads = _parse_loads(d.pop("loads", UNSET))

        def _parse_targets(data: object) -> list[list[float]] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                targets_type_0 = []
                _targets_type_0 = data
                for targets_type_0_item_data in _targets_type_0:
                    targets_type_0_item = cast(list[float], targets_type_0_item_data)

                    targets_type_0.append(targets_type_0_item)

                return targets_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None | Unset, data)

        targets = _parse_targets(d.pop("targets", UNSET))

        simulation_out = cls(
            deflection=deflection,
            done=done,
            energy=energy,
            events=events,
            force=force,
            message=message,
            mode=mode,
            morse_index=morse_index,
            potential=potential,
            preloads=preloads,
            q=q,
            spring_forces=spring_forces,
            spring_lengths=spring_lengths,
            spring_states=spring_states,
            spring_stretches=spring_stretches,
            stable=stable,
            status=status,
            steps=steps,
            success=success,
            tip=tip,
            loads=loads,
            targets=targets,
        )

        simulation_out.additional_properties = d
        return simulation_out

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
