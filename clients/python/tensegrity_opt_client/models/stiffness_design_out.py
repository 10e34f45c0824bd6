from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.stiffness_design_out_spring_states_type_0_item_item import StiffnessDesignOutSpringStatesType0ItemItem
from ..models.stiffness_design_out_status import StiffnessDesignOutStatus

if TYPE_CHECKING:
    from ..models.active_bound_out import ActiveBoundOut
    from ..models.solver_info import SolverInfo
    from ..models.stiffness_design_out_bounds_k import StiffnessDesignOutBoundsK
    from ..models.stiffness_design_out_manipulator import StiffnessDesignOutManipulator


T = TypeVar("T", bound="StiffnessDesignOut")


@_attrs_define
class StiffnessDesignOut:
    """`StiffnessDesign.to_dict()`: verified by the forward solve and `cartesian_stiffness`.

    Attributes:
        k (list[list[float]]): the verified Cartesian stiffness (force / length)
        k_desired (list[list[float]] | None):
        active_bounds (list[ActiveBoundOut]): the rest lengths at (or near) their bounds: the design is the best within
            them
        bounds_k (StiffnessDesignOutBoundsK):
        eig_bounds (list[float | None] | None):
        eigenvalues (list[float]):
        exact (bool):
        load (list[float]):
        manipulator (StiffnessDesignOutManipulator):
        margin (float):
        message (str): what happened, in a sentence
        q (list[float]):
        residual (float): |K - K_desired|_F / |K_desired|_F, or the largest bound violation (0)
        rest_lengths (list[list[float]]): [L1_0, L2_0] per segment
        solver (SolverInfo):
        spring_forces (list[list[float]] | None): each spring's force, tension positive: k (L - L0) (linear law), k
            max(0, L - L0) (tension-only)
        spring_lengths (list[list[float]] | None): each spring's length L (length units), [spring 1, spring 2] per
            segment
        spring_states (list[list[StiffnessDesignOutSpringStatesType0ItemItem]] | None): `taut` (L >= L0), `slack`
            (tension-only, L < L0: no force) or `pushing` (linear law, L < L0: a compressive force a real tension spring
            cannot carry)
        spring_stretches (list[list[float]] | None): L - L0 per spring (negative: shorter than its rest length)
        status (StiffnessDesignOutStatus): `exact`: K = K_desired holds at the verified pose (residual <= EXACT_TOL),
            with the least change of the preloads (within the bounds, where some are given); `closest`: K_desired is not
            reachable from any start: the least-squares fit with the smallest misfit (residual, relative), within the bounds
            where some are given; `within_bounds`: the bounds on the entries and eigenvalues of K hold at the verified pose,
            with the least change of the preloads
        success (bool): whether it worked: `status` is one of exact, within_bounds
        tip (list[float]):
    """

    k: list[list[float]]
    k_desired: list[list[float]] | None
    active_bounds: list[ActiveBoundOut]
    bounds_k: StiffnessDesignOutBoundsK
    eig_bounds: list[float | None] | None
    eigenvalues: list[float]
    exact: bool
    load: list[float]
    manipulator: StiffnessDesignOutManipulator
    margin: float
    message: str
    q: list[float]
    residual: float
    rest_lengths: list[list[float]]
    solver: SolverInfo
    spring_forces: list[list[float]] | None
    spring_lengths: list[list[float]] | None
    spring_states: list[list[StiffnessDesignOutSpringStatesType0ItemItem]] | None
    spring_stretches: list[list[float]] | None
    status: StiffnessDesignOutStatus
    success: bool
    tip: list[float]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        k = []
        for k_item_data in self.k:
            k_item = k_item_data

            k.append(k_item)

        k_desired: list[list[float]] | None
        if isinstance(self.k_desired, list):
            k_desired = []
            for k_desired_type_0_item_data in self.k_desired:
                k_desired_type_0_item = k_desired_type_0_item_data

                k_desired.append(k_desired_type_0_item)

        else:
            k_desired = self.k_desired

        active_bounds = []
        for active_bounds_item_data in self.active_bounds:
            active_bounds_item = active_bounds_item_data.to_dict()
            active_bounds.append(active_bounds_item)

        bounds_k = self.bounds_k.to_dict()

        eig_bounds: list[float | None] | None
        if isinstance(self.eig_bounds, list):
            eig_bounds = []
            for eig_bounds_type_0_item_data in self.eig_bounds:
                eig_bounds_type_0_item: float | None
                eig_bounds_type_0_item = eig_bounds_type_0_item_data
                eig_bounds.append(eig_bounds_type_0_item)

        else:
            eig_bounds = self.eig_bounds

        eigenvalues = self.eigenvalues

        exact = self.exact

        load = self.load

        manipulator = self.manipulator.to_dict()

        margin = self.margin

        message = self.message

        q = self.q

        residual = self.residual

        rest_lengths = []
        for rest_lengths_item_data in self.rest_lengths:
            rest_lengths_item = rest_lengths_item_data

            rest_lengths.append(rest_lengths_item)

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

        tip = self.tip

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "K": k,
                "K_desired": k_desired,
                "active_bounds": active_bounds,
                "bounds_K": bounds_k,
                "eig_bounds": eig_bounds,
                "eigenvalues": eigenvalues,
                "exact": exact,
                "load": load,
                "manipulator": manipulator,
                "margin": margin,
                "message": message,
                "q": q,
                "residual": residual,
                "rest_lengths": rest_lengths,
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
        from ..models.solver_info import SolverInfo  # noqa: PLC0415
        from ..models.stiffness_design_out_bounds_k import StiffnessDesignOutBoundsK  # noqa: PLC0415
        from ..models.stiffness_design_out_manipulator import StiffnessDesignOutManipulator  # noqa: PLC0415

        d = dict(src_dict)
        k = []
        _k = d.pop("K")
        for k_item_data in _k:
            k_item = cast(list[float], k_item_data)

            k.append(k_item)

        def _parse_k_desired(data: object) -> list[list[float]] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                k_desired_type_0 = []
                _k_desired_type_0 = data
                for k_desired_type_0_item_data in _k_desired_type_0:
                    k_desired_type_0_item = cast(list[float], k_desired_type_0_item_data)

                    k_desired_type_0.append(k_desired_type_0_item)

                return k_desired_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None, data)

        k_desired = _parse_k_desired(d.pop("K_desired"))

        active_bounds = []
        _active_bounds = d.pop("active_bounds")
        for active_bounds_item_data in _active_bounds:
            active_bounds_item = ActiveBoundOut.from_dict(active_bounds_item_data)

            active_bounds.append(active_bounds_item)

        bounds_k = StiffnessDesignOutBoundsK.from_dict(d.pop("bounds_K"))

        def _parse_eig_bounds(data: object) -> list[float | None] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                eig_bounds_type_0 = []
                _eig_bounds_type_0 = data
                for eig_bounds_type_0_item_data in _eig_bounds_type_0:

                    def _parse_eig_bounds_type_0_item(data: object) -> float | None:
                        if data is None:
                            return data
                        return cast(float | None, data)

                    eig_bounds_type_0_item = _parse_eig_bounds_type_0_item(eig_bounds_type_0_item_data)

                    eig_bounds_type_0.append(eig_bounds_type_0_item)

                return eig_bounds_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float | None] | None, data)

        eig_bounds = _parse_eig_bounds(d.pop("eig_bounds"))

        eigenvalues = cast(list[float], d.pop("eigenvalues"))

        exact = d.pop("exact")

        load = cast(list[float], d.pop("load"))

        manipulator = StiffnessDesignOutManipulator.from_dict(d.pop("manipulator"))

        margin = d.pop("margin")

        message = d.pop("message")

        q = cast(list[float], d.pop("q"))

        residual = d.pop("residual")

        rest_lengths = []
        _rest_lengths = d.pop("rest_lengths")
        for rest_lengths_item_data in _rest_lengths:
            rest_lengths_item = cast(list[float], rest_lengths_item_data)

            rest_lengths.append(rest_lengths_item)

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

        def _parse_spring_states(data: object) -> list[list[StiffnessDesignOutSpringStatesType0ItemItem]] | None:
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
                        spring_states_type_0_item_item = StiffnessDesignOutSpringStatesType0ItemItem(
                            spring_states_type_0_item_item_data
                        )

                        spring_states_type_0_item.append(spring_states_type_0_item_item)

                    spring_states_type_0.append(spring_states_type_0_item)

                return spring_states_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[StiffnessDesignOutSpringStatesType0ItemItem]] | None, data)

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

        status = StiffnessDesignOutStatus(d.pop("status"))

        success = d.pop("success")

        tip = cast(list[float], d.pop("tip"))

        stiffness_design_out = cls(
            k=k,
            k_desired=k_desired,
            active_bounds=active_bounds,
            bounds_k=bounds_k,
            eig_bounds=eig_bounds,
            eigenvalues=eigenvalues,
            exact=exact,
            load=load,
            manipulator=manipulator,
            margin=margin,
            message=message,
            q=q,
            residual=residual,
            rest_lengths=rest_lengths,
            solver=solver,
            spring_forces=spring_forces,
            spring_lengths=spring_lengths,
            spring_states=spring_states,
            spring_stretches=spring_stretches,
            status=status,
            success=success,
            tip=tip,
        )

        stiffness_design_out.additional_properties = d
        return stiffness_design_out

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
