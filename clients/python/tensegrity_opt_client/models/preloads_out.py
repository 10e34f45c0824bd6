from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, Literal, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.preloads_out_spring_states_type_0_item_item import PreloadsOutSpringStatesType0ItemItem

if TYPE_CHECKING:
    from ..models.active_bound_out import ActiveBoundOut
    from ..models.manipulator_out import ManipulatorOut
    from ..models.solver_info import SolverInfo


T = TypeVar("T", bound="PreloadsOut")


@_attrs_define
class PreloadsOut:
    """`PreloadDesign.to_dict()`: rest lengths for a pose, verified by the forward equilibrium.

    Attributes:
        active_bounds (list[ActiveBoundOut]): the rest lengths at (or near) their bounds
        energy (float):
        manipulator (ManipulatorOut):
        margin (float): achieved stability margin (recomputed)
        message (str): what happened, in a sentence
        preloads (list[list[float]]): rest lengths [L1_0, L2_0] per segment
        q (list[float]): verified equilibrium configuration (rad)
        solver (SolverInfo):
        spring_forces (list[list[float]] | None): each spring's force, tension positive: k (L - L0) (linear law), k
            max(0, L - L0) (tension-only)
        spring_lengths (list[list[float]] | None): each spring's length L (length units), [spring 1, spring 2] per
            segment
        spring_states (list[list[PreloadsOutSpringStatesType0ItemItem]] | None): `taut` (L >= L0), `slack` (tension-
            only, L < L0: no force) or `pushing` (linear law, L < L0: a compressive force a real tension spring cannot
            carry)
        spring_stretches (list[list[float]] | None): L - L0 per spring (negative: shorter than its rest length)
        status (Literal['optimal']): `optimal`: IPOPT converged to rest lengths meeting every requirement, and the
            forward equilibrium with them, from the optimiser's configuration, lands on the target, stable
        success (bool): whether it worked: `status` is one of optimal
        tip (list[float]):
    """

    active_bounds: list[ActiveBoundOut]
    energy: float
    manipulator: ManipulatorOut
    margin: float
    message: str
    preloads: list[list[float]]
    q: list[float]
    solver: SolverInfo
    spring_forces: list[list[float]] | None
    spring_lengths: list[list[float]] | None
    spring_states: list[list[PreloadsOutSpringStatesType0ItemItem]] | None
    spring_stretches: list[list[float]] | None
    status: Literal["optimal"]
    success: bool
    tip: list[float]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        active_bounds = []
        for active_bounds_item_data in self.active_bounds:
            active_bounds_item = active_bounds_item_data.to_dict()
            active_bounds.append(active_bounds_item)

        energy = self.energy

        manipulator = self.manipulator.to_dict()

        margin = self.margin

        message = self.message

        preloads = []
        for preloads_item_data in self.preloads:
            preloads_item = preloads_item_data

            preloads.append(preloads_item)

        q = self.q

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

        status = self.status

        success = self.success

        tip = self.tip

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "active_bounds": active_bounds,
                "energy": energy,
                "manipulator": manipulator,
                "margin": margin,
                "message": message,
                "preloads": preloads,
                "q": q,
                "solver": solver,
                "spring_forces": spring_forces,
                "spring_lengths": spring_lengths,
                "spring_states": spring_states,
                "spring_stretches": spring_stretches,
                "status": status,
                "success": success,
                "tip": tip,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.active_bound_out import ActiveBoundOut  # noqa: PLC0415
        from ..models.manipulator_out import ManipulatorOut  # noqa: PLC0415
        from ..models.solver_info import SolverInfo  # noqa: PLC0415

        d = dict(src_dict)
        active_bounds = []
        _active_bounds = d.pop("active_bounds")
        for active_bounds_item_data in _active_bounds:
            active_bounds_item = ActiveBoundOut.from_dict(active_bounds_item_data)

            active_bounds.append(active_bounds_item)

        energy = d.pop("energy")

        manipulator = ManipulatorOut.from_dict(d.pop("manipulator"))

        margin = d.pop("margin")

        message = d.pop("message")

        preloads = []
        _preloads = d.pop("preloads")
        for preloads_item_data in _preloads:
            preloads_item = cast(list[float], preloads_item_data)

            preloads.append(preloads_item)

        q = cast(list[float], d.pop("q"))

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

        def _parse_spring_states(data: object) -> list[list[PreloadsOutSpringStatesType0ItemItem]] | None:
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
                        spring_states_type_0_item_item = PreloadsOutSpringStatesType0ItemItem(
                            spring_states_type_0_item_item_data
                        )

                        spring_states_type_0_item.append(spring_states_type_0_item_item)

                    spring_states_type_0.append(spring_states_type_0_item)

                return spring_states_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[PreloadsOutSpringStatesType0ItemItem]] | None, data)

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

        status = cast(Literal["optimal"], d.pop("status"))
        if status != "optimal":
            raise ValueError(f"status must match const 'optimal', got '{status}'")

        success = d.pop("success")

        tip = cast(list[float], d.pop("tip"))

        preloads_out = cls(
            active_bounds=active_bounds,
            energy=energy,
            manipulator=manipulator,
            margin=margin,
            message=message,
            preloads=preloads,
            q=q,
            solver=solver,
            spring_forces=spring_forces,
            spring_lengths=spring_lengths,
            spring_states=spring_states,
            spring_stretches=spring_stretches,
            status=status,
            success=success,
            tip=tip,
        )

        preloads_out.additional_properties = d
        return preloads_out

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
