from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.equilibrium_out_kind import EquilibriumOutKind
from ..models.equilibrium_out_spring_states_type_0_item_item import EquilibriumOutSpringStatesType0ItemItem
from ..models.equilibrium_out_status import EquilibriumOutStatus
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.energy_bound_out import EnergyBoundOut
    from ..models.force import Force
    from ..models.loads_out import LoadsOut
    from ..models.solver_info import SolverInfo


T = TypeVar("T", bound="EquilibriumOut")


@_attrs_define
class EquilibriumOut:
    """An equilibrium configuration.

    Attributes:
        at_stop (list[bool]): the joints resting on their mechanical stop |q| = pi - 2 beta (reached where springs go
            slack: the tension-only law); false inside the range
        contact_torques (list[float]): the torque each stop supplies (>= 0; 0 where a joint is not at its stop)
        energy (float): the chain's potential energy (force x length): its springs' elastic energy, plus the potential
            of its dead loads where it carries some (`loads`)
        force (Force):
        kind (EquilibriumOutKind):
        loads (LoadsOut | None): the dead loads this was computed under (gravity on the chain's masses, joint forces);
            null where the chain carries none
        message (str): what happened, in a sentence
        morse_index (int): negative eigenvalues of the reduced Hessian (0: stable)
        q (list[float]): relative joint angles (rad)
        shape (str): shape label: I, C, U, ZU, Z or W<s>
        signs (str): sign of each joint angle: +, - or 0
        solver (SolverInfo):
        spring_forces (list[list[float]] | None): each spring's force, tension positive: k (L - L0) (linear law), k
            max(0, L - L0) (tension-only)
        spring_lengths (list[list[float]] | None): each spring's length L (length units), [spring 1, spring 2] per
            segment
        spring_states (list[list[EquilibriumOutSpringStatesType0ItemItem]] | None): `taut` (L >= L0), `slack` (tension-
            only, L < L0: no force) or `pushing` (linear law, L < L0: a compressive force a real tension spring cannot
            carry)
        spring_stretches (list[list[float]] | None): L - L0 per spring (negative: shorter than its rest length)
        stable (bool):
        status (EquilibriumOutStatus): `converged`: a numerical solve converged to it (Newton on the KKT system, IPOPT,
            a continuation step; the solver's own status is in solver) and the equilibrium equations hold; `exact`: known in
            closed form: the straight chain, a single segment, or an unloaded chain (a product of its segments' critical
            points); `certified`: the least-energy stable member of a set of equilibria proven complete by the polynomial
            homotopy (method='homotopy'), or the least-energy one proven by a rigorous lower bound on the energy of every
            configuration meeting the tip constraint (certify=True; certificate)
        success (bool): whether it worked: `status` is one of certified, converged, exact
        tip (list[float]): tip position [x, y]
        certificate (EnergyBoundOut | None | Unset): the rigorous lower bound on the energy and its gap: with `certify:
            true`, or where the default search's short way (short multistable chains) proved its answer; else null
    """

    at_stop: list[bool]
    contact_torques: list[float]
    energy: float
    force: Force
    kind: EquilibriumOutKind
    loads: LoadsOut | None
    message: str
    morse_index: int
    q: list[float]
    shape: str
    signs: str
    solver: SolverInfo
    spring_forces: list[list[float]] | None
    spring_lengths: list[list[float]] | None
    spring_states: list[list[EquilibriumOutSpringStatesType0ItemItem]] | None
    spring_stretches: list[list[float]] | None
    stable: bool
    status: EquilibriumOutStatus
    success: bool
    tip: list[float]
    certificate: EnergyBoundOut | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        from ..models.energy_bound_out import EnergyBoundOut  # noqa: PLC0415
        from ..models.loads_out import LoadsOut  # noqa: PLC0415

        at_stop = self.at_stop

        contact_torques = self.contact_torques

        energy = self.energy

        force = self.force.to_dict()

        kind = self.kind.value

        loads: dict[str, Any] | None
        if isinstance(self.loads, LoadsOut):
            loads = self.loads.to_dict()
        else:
            loads = self.loads

        message = self.message

        morse_index = self.morse_index

        q = self.q

        shape = self.shape

        signs = self.signs

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

        stable = self.stable

        status = self.status.value

        success = self.success

        tip = self.tip

        certificate: dict[str, Any] | None | Unset
        if isinstance(self.certificate, Unset):
            certificate = UNSET
        elif isinstance(self.certificate, EnergyBoundOut):
            certificate = self.certificate.to_dict()
        else:
            certificate = self.certificate

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "at_stop": at_stop,
                "contact_torques": contact_torques,
                "energy": energy,
                "force": force,
                "kind": kind,
                "loads": loads,
                "message": message,
                "morse_index": morse_index,
                "q": q,
                "shape": shape,
                "signs": signs,
                "solver": solver,
                "spring_forces": spring_forces,
                "spring_lengths": spring_lengths,
                "spring_states": spring_states,
                "spring_stretches": spring_stretches,
                "stable": stable,
                "status": status,
                "success": success,
                "tip": tip,
            }
        )
        if certificate is not UNSET:
            field_dict["certificate"] = certificate

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.energy_bound_out import EnergyBoundOut  # noqa: PLC0415
        from ..models.force import Force  # noqa: PLC0415
        from ..models.loads_out import LoadsOut  # noqa: PLC0415
        from ..models.solver_info import SolverInfo  # noqa: PLC0415

        d = dict(src_dict)
        at_stop = cast(list[bool], d.pop("at_stop"))

        contact_torques = cast(list[float], d.pop("contact_torques"))

        energy = d.pop("energy")

        force = Force.from_dict(d.pop("force"))

        kind = EquilibriumOutKind(d.pop("kind"))

        def _parse_loads(data: object) -> LoadsOut | None:
            if data is None:
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                loads_type_0 = LoadsOut.from_dict(data)

                return loads_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(LoadsOut | None, data)

        loads = _parse_loads(d.pop("loads"))

        message = d.pop("message")

        morse_index = d.pop("morse_index")

        q = cast(list[float], d.pop("q"))

        shape = d.pop("shape")

        signs = d.pop("signs")

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

        def _parse_spring_states(data: object) -> list[list[EquilibriumOutSpringStatesType0ItemItem]] | None:
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
                        spring_states_type_0_item_item = EquilibriumOutSpringStatesType0ItemItem(
                            spring_states_type_0_item_item_data
                        )

                        spring_states_type_0_item.append(spring_states_type_0_item_item)

                    spring_states_type_0.append(spring_states_type_0_item)

                return spring_states_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[EquilibriumOutSpringStatesType0ItemItem]] | None, data)

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

        stable = d.pop("stable")

        status = EquilibriumOutStatus(d.pop("status"))

        success = d.pop("success")

        tip = cast(list[float], d.pop("tip"))

        def _parse_certificate(data: object) -> EnergyBoundOut | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                certificate_type_0 = EnergyBoundOut.from_dict(data)

                return certificate_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(EnergyBoundOut | None | Unset, data)

        certificate = _parse_certificate(d.pop("certificate", UNSET))

        equilibrium_out = cls(
            at_stop=at_stop,
            contact_torques=contact_torques,
            energy=energy,
            force=force,
            kind=kind,
            loads=loads,
            message=message,
            morse_index=morse_index,
            q=q,
            shape=shape,
            signs=signs,
            solver=solver,
            spring_forces=spring_forces,
            spring_lengths=spring_lengths,
            spring_states=spring_states,
            spring_stretches=spring_stretches,
            stable=stable,
            status=status,
            success=success,
            tip=tip,
            certificate=certificate,
        )

        equilibrium_out.additional_properties = d
        return equilibrium_out

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
