from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.holding_out_spring_states_type_0_item_item import HoldingOutSpringStatesType0ItemItem
from ..models.holding_out_status import HoldingOutStatus
from ..models.holding_out_vary_item import HoldingOutVaryItem

if TYPE_CHECKING:
    from ..models.equilibrium_out import EquilibriumOut
    from ..models.holding_out_manipulator import HoldingOutManipulator
    from ..models.solver_info import SolverInfo


T = TypeVar("T", bound="HoldingOut")


@_attrs_define
class HoldingOut:
    """`HoldingDesign.to_dict()`: the designed chain holding itself up, verified by forward solves.

    Attributes:
        change (list[float]): per segment: the rest lengths' change (L0) or the stiffness scale (k)
        equilibrium (EquilibriumOut): An equilibrium configuration.
        manipulator (HoldingOutManipulator): the designed chain (its segments and its loads, as a request takes it)
        margin (float): the smallest eigenvalue of the potential's Hessian there (recomputed)
        message (str): what happened, in a sentence
        q (list[float]): the verified rest configuration under the loads (rad)
        solver (SolverInfo):
        spring_forces (list[list[float]] | None): each spring's force, tension positive: k (L - L0) (linear law), k
            max(0, L - L0) (tension-only)
        spring_lengths (list[list[float]] | None): each spring's length L (length units), [spring 1, spring 2] per
            segment
        spring_states (list[list[HoldingOutSpringStatesType0ItemItem]] | None): `taut` (L >= L0), `slack` (tension-only,
            L < L0: no force) or `pushing` (linear law, L < L0: a compressive force a real tension spring cannot carry)
        spring_stretches (list[list[float]] | None): L - L0 per spring (negative: shorter than its rest length)
        status (HoldingOutStatus): `optimal`: IPOPT converged; the designed chain's forward equilibrium lands on the
            designed pose, stable with the margin, and it is the chain's least-potential rest configuration; `metastable`:
            the designed pose is verified stable with the margin, but the designed chain has a rest configuration of lower
            potential elsewhere (it may fall there if disturbed)
        stiffness (float): the total stiffness sum(k1 + k2)
        success (bool): whether it worked: `status` is one of optimal
        tension (float): the total spring tension of the designed chain when straight
        vary (list[HoldingOutVaryItem]): what was designed
    """

    change: list[float]
    equilibrium: EquilibriumOut
    manipulator: HoldingOutManipulator
    margin: float
    message: str
    q: list[float]
    solver: SolverInfo
    spring_forces: list[list[float]] | None
    spring_lengths: list[list[float]] | None
    spring_states: list[list[HoldingOutSpringStatesType0ItemItem]] | None
    spring_stretches: list[list[float]] | None
    status: HoldingOutStatus
    stiffness: float
    success: bool
    tension: float
    vary: list[HoldingOutVaryItem]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        change = self.change

        equilibrium = self.equilibrium.to_dict()

        manipulator = self.manipulator.to_dict()

        margin = self.margin

        message = self.message

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

        status = self.status.value

        stiffness = self.stiffness

        success = self.success

        tension = self.tension

        vary = []
        for vary_item_data in self.vary:
            vary_item = vary_item_data.value
            vary.append(vary_item)

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "change": change,
                "equilibrium": equilibrium,
                "manipulator": manipulator,
                "margin": margin,
                "message": message,
                "q": q,
                "solver": solver,
                "spring_forces": spring_forces,
                "spring_lengths": spring_lengths,
                "spring_states": spring_states,
                "spring_stretches": spring_stretches,
                "status": status,
                "stiffness": stiffness,
                "success": success,
                "tension": tension,
                "vary": vary,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.equilibrium_out import EquilibriumOut  # noqa: PLC0415
        from ..models.holding_out_manipulator import HoldingOutManipulator  # noqa: PLC0415
        from ..models.solver_info import SolverInfo  # noqa: PLC0415

        d = dict(src_dict)
        change = cast(list[float], d.pop("change"))

        equilibrium = EquilibriumOut.from_dict(d.pop("equilibrium"))

        manipulator = HoldingOutManipulator.from_dict(d.pop("manipulator"))

        margin = d.pop("margin")

        message = d.pop("message")

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

        def _parse_spring_states(data: object) -> list[list[HoldingOutSpringStatesType0ItemItem]] | None:
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
                        spring_states_type_0_item_item = HoldingOutSpringStatesType0ItemItem(
                            spring_states_type_0_item_item_data
                        )

                        spring_states_type_0_item.append(spring_states_type_0_item_item)

                    spring_states_type_0.append(spring_states_type_0_item)

                return spring_states_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[HoldingOutSpringStatesType0ItemItem]] | None, data)

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

        status = HoldingOutStatus(d.pop("status"))

        stiffness = d.pop("stiffness")

        success = d.pop("success")

        tension = d.pop("tension")

        vary = []
        _vary = d.pop("vary")
        for vary_item_data in _vary:
            vary_item = HoldingOutVaryItem(vary_item_data)

            vary.append(vary_item)

        holding_out = cls(
            change=change,
            equilibrium=equilibrium,
            manipulator=manipulator,
            margin=margin,
            message=message,
            q=q,
            solver=solver,
            spring_forces=spring_forces,
            spring_lengths=spring_lengths,
            spring_states=spring_states,
            spring_stretches=spring_stretches,
            status=status,
            stiffness=stiffness,
            success=success,
            tension=tension,
            vary=vary,
        )

        holding_out.additional_properties = d
        return holding_out

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
