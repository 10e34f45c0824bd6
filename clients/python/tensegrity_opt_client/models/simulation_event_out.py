from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.simulation_event_out_kind import SimulationEventOutKind
from ..models.simulation_event_out_status import SimulationEventOutStatus

T = TypeVar("T", bound="SimulationEventOut")


@_attrs_define
class SimulationEventOut:
    """Something that happened during a move of the inputs (a simulation's step from sample `step` to `step + 1`,
    a plan's step `step` from the previous command to its own), at `time = step + fraction`: where the arm went
    (`status`) and what it did there.

        Attributes:
            direction (int): the sign of null_vector the descent left along (0: joint limit)
            energy_after (float | None):
            energy_before (float | None):
            energy_released (float | None): potential_before - potential_after (> 0 for a snap)
            force_after (list[float] | None):
            force_before (list[float] | None):
            fraction (float): where in the step (0 at sample step, 1 at step + 1)
            kind (SimulationEventOutKind): snap (the followed branch folded: the arm jumps), bifurcation (lost stability at
                a branch point), joint_limit (a joint reached its range bound: the end)
            load (list[float] | None): the dead tip load there (tip free)
            message (str): what happened, in a sentence
            method (str): moore_spence, test_function or limit
            null_vector (list[float] | None): the snapping mode (largest entry +1)
            potential_after (float | None):
            potential_before (float | None): E - F . tip (free) or E (held) at the fold
            preloads (list[list[float]]): the rest lengths [L1_0, L2_0] per segment there
            q_after (list[float] | None): the landing configuration (null: a joint limit, or the descent ran into a joint's
                bound)
            q_before (list[float]): the configuration at the fold (branch point, joint limit)
            status (SimulationEventOutStatus): `landed`: the arm left the lost branch and landed on a stable equilibrium
                under the same inputs; `joint_limit`: a joint reached its range bound (on the followed branch, or during the
                snap's descent): no equilibrium beyond inside the physical range; the move ends there
            step (int):
            success (bool): whether it worked: `status` is one of landed
            target (list[float] | None): the tip deflection there (tip held)
            time (float): step + fraction
            tip_after (list[float] | None):
            tip_before (list[float] | None):
    """

    direction: int
    energy_after: float | None
    energy_before: float | None
    energy_released: float | None
    force_after: list[float] | None
    force_before: list[float] | None
    fraction: float
    kind: SimulationEventOutKind
    load: list[float] | None
    message: str
    method: str
    null_vector: list[float] | None
    potential_after: float | None
    potential_before: float | None
    preloads: list[list[float]]
    q_after: list[float] | None
    q_before: list[float]
    status: SimulationEventOutStatus
    step: int
    success: bool
    target: list[float] | None
    time: float
    tip_after: list[float] | None
    tip_before: list[float] | None
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        direction = self.direction

        energy_after: float | None
        energy_after = self.energy_after

        energy_before: float | None
        energy_before = self.energy_before

        energy_released: float | None
        energy_released = self.energy_released

        force_after: list[float] | None
        if isinstance(self.force_after, list):
            force_after = self.force_after

        else:
            force_after = self.force_after

        force_before: list[float] | None
        if isinstance(self.force_before, list):
            force_before = self.force_before

        else:
            force_before = self.force_before

        fraction = self.fraction

        kind = self.kind.value

        load: list[float] | None
        if isinstance(self.load, list):
            load = self.load

        else:
            load = self.load

        message = self.message

        method = self.method

        null_vector: list[float] | None
        if isinstance(self.null_vector, list):
            null_vector = self.null_vector

        else:
            null_vector = self.null_vector

        potential_after: float | None
        potential_after = self.potential_after

        potential_before: float | None
        potential_before = self.potential_before

        preloads = []
        for preloads_item_data in self.preloads:
            preloads_item = preloads_item_data

            preloads.append(preloads_item)

        q_after: list[float] | None
        if isinstance(self.q_after, list):
            q_after = self.q_after

        else:
            q_after = self.q_after

        q_before = self.q_before

        status = self.status.value

        step = self.step

        success = self.success

        target: list[float] | None
        if isinstance(self.target, list):
            target = self.target

        else:
            target = self.target

        time = self.time

        tip_after: list[float] | None
        if isinstance(self.tip_after, list):
            tip_after = self.tip_after

        else:
            tip_after = self.tip_after

        tip_before: list[float] | None
        if isinstance(self.tip_before, list):
            tip_before = self.tip_before

        else:
            tip_before = self.tip_before

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "direction": direction,
                "energy_after": energy_after,
                "energy_before": energy_before,
                "energy_released": energy_released,
                "force_after": force_after,
                "force_before": force_before,
                "fraction": fraction,
                "kind": kind,
                "load": load,
                "message": message,
                "method": method,
                "null_vector": null_vector,
                "potential_after": potential_after,
                "potential_before": potential_before,
                "preloads": preloads,
                "q_after": q_after,
                "q_before": q_before,
                "status": status,
                "step": step,
                "success": success,
                "target": target,
                "time": time,
                "tip_after": tip_after,
                "tip_before": tip_before,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        direction = d.pop("direction")

        def _parse_energy_after(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        energy_after = _parse_energy_after(d.pop("energy_after"))

        def _parse_energy_before(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        energy_before = _parse_energy_before(d.pop("energy_before"))

        def _parse_energy_released(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        energy_released = _parse_energy_released(d.pop("energy_released"))

        def _parse_force_after(data: object) -> list[float] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                force_after_type_0 = cast(list[float], data)

                return force_after_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None, data)

        force_after = _parse_force_after(d.pop("force_after"))

        def _parse_force_before(data: object) -> list[float] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                force_before_type_0 = cast(list[float], data)

                return force_before_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None, data)

        force_before = _parse_force_before(d.pop("force_before"))

        fraction = d.pop("fraction")

        kind = SimulationEventOutKind(d.pop("kind"))

        def _parse_load(data: object) -> list[float] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                load_type_0 = cast(list[float], data)

                return load_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None, data)

        load = _parse_load(d.pop("load"))

        message = d.pop("message")

        method = d.pop("method")

        def _parse_null_vector(data: object) -> list[float] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                null_vector_type_0 = cast(list[float], data)

                return null_vector_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None, data)

        null_vector = _parse_null_vector(d.pop("null_vector"))

        def _parse_potential_after(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        potential_after = _parse_potential_after(d.pop("potential_after"))

        def _parse_potential_before(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        potential_before = _parse_potential_before(d.pop("potential_before"))

        preloads = []
        _preloads = d.pop("preloads")
        for preloads_item_data in _preloads:
            preloads_item = cast(list[float], preloads_item_data)

            preloads.append(preloads_item)

        def _parse_q_after(data: object) -> list[float] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                q_after_type_0 = cast(list[float], data)

                return q_after_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None, data)

        q_after = _parse_q_after(d.pop("q_after"))

        q_before = cast(list[float], d.pop("q_before"))

        status = SimulationEventOutStatus(d.pop("status"))

        step = d.pop("step")

        success = d.pop("success")

        def _parse_target(data: object) -> list[float] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                target_type_0 = cast(list[float], data)

                return target_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None, data)

        target = _parse_target(d.pop("target"))

        time = d.pop("time")

        def _parse_tip_after(data: object) -> list[float] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                tip_after_type_0 = cast(list[float], data)

                return tip_after_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None, data)

        tip_after = _parse_tip_after(d.pop("tip_after"))

        def _parse_tip_before(data: object) -> list[float] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                tip_before_type_0 = cast(list[float], data)

                return tip_before_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None, data)

        tip_before = _parse_tip_before(d.pop("tip_before"))

        simulation_event_out = cls(
            direction=direction,
            energy_after=energy_after,
            energy_before=energy_before,
            energy_released=energy_released,
            force_after=force_after,
            force_before=force_before,
            fraction=fraction,
            kind=kind,
            load=load,
            message=message,
            method=method,
            null_vector=null_vector,
            potential_after=potential_after,
            potential_before=potential_before,
            preloads=preloads,
            q_after=q_after,
            q_before=q_before,
            status=status,
            step=step,
            success=success,
            target=target,
            time=time,
            tip_after=tip_after,
            tip_before=tip_before,
        )

        simulation_event_out.additional_properties = d
        return simulation_event_out

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
