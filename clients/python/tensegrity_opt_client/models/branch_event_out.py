from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.branch_event_out_kind import BranchEventOutKind
from ..models.branch_event_out_spring_states_type_0_item_item import BranchEventOutSpringStatesType0ItemItem
from ..models.branch_event_out_stability import BranchEventOutStability
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.force import Force


T = TypeVar("T", bound="BranchEventOut")


@_attrs_define
class BranchEventOut:
    """A special point, located between points `index` and `index + 1`.

    Attributes:
        energy (float):
        force (Force):
        index (int):
        joint (int | None): the joint at its limit (0-based), joint_limit; the segment whose spring changes state,
            spring_slack / spring_taut
        kind (BranchEventOutKind): fold (t turns back: snap-through under this control), branch_point (another branch
            crosses), joint_limit (the end), spring_slack / spring_taut (a tension-only spring reaches its rest length: the
            joint's stiffness jumps)
        method (str): moore_spence, test_function or limit
        morse_after (int):
        morse_before (int):
        null_vector (list[float] | None): the buckling or snapping mode (largest entry +1)
        q (list[float]):
        residual (float | None):
        spring_forces (list[list[float]] | None): each spring's force, tension positive: k (L - L0) (linear law), k
            max(0, L - L0) (tension-only)
        spring_lengths (list[list[float]] | None): each spring's length L (length units), [spring 1, spring 2] per
            segment
        spring_states (list[list[BranchEventOutSpringStatesType0ItemItem]] | None): `taut` (L >= L0), `slack` (tension-
            only, L < L0: no force) or `pushing` (linear law, L < L0: a compressive force a real tension spring cannot
            carry)
        spring_stretches (list[list[float]] | None): L - L0 per spring (negative: shorter than its rest length)
        stability (BranchEventOutStability):
        t (float):
        tip (list[float]):
        spring (int | None | Unset): which of the segment's springs (1 or 2), spring events only
        stiffness_after (float | None | Unset): the joint's stiffness d2E/dq2 after a spring event
        stiffness_before (float | None | Unset): the joint's stiffness d2E/dq2 before a spring event
    """

    energy: float
    force: Force
    index: int
    joint: int | None
    kind: BranchEventOutKind
    method: str
    morse_after: int
    morse_before: int
    null_vector: list[float] | None
    q: list[float]
    residual: float | None
    spring_forces: list[list[float]] | None
    spring_lengths: list[list[float]] | None
    spring_states: list[list[BranchEventOutSpringStatesType0ItemItem]] | None
    spring_stretches: list[list[float]] | None
    stability: BranchEventOutStability
    t: float
    tip: list[float]
    spring: int | None | Unset = UNSET
    stiffness_after: float | None | Unset = UNSET
    stiffness_before: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        energy = self.energy

        force = self.force.to_dict()

        index = self.index

        joint: int | None
        joint = self.joint

        kind = self.kind.value

        method = self.method

        morse_after = self.morse_after

        morse_before = self.morse_before

        null_vector: list[float] | None
        if isinstance(self.null_vector, list):
            null_vector = self.null_vector

        else:
            null_vector = self.null_vector

        q = self.q

        residual: float | None
        residual = self.residual

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

        stability = self.stability.value

        t = self.t

        tip = self.tip

        spring: int | None | Unset
        if isinstance(self.spring, Unset):
            spring = UNSET
        else:
            spring = self.spring

        stiffness_after: float | None | Unset
        if isinstance(self.stiffness_after, Unset):
            stiffness_after = UNSET
        else:
            stiffness_after = self.stiffness_after

        stiffness_before: float | None | Unset
        if isinstance(self.stiffness_before, Unset):
            stiffness_before = UNSET
        else:
            stiffness_before = self.stiffness_before

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "energy": energy,
                "force": force,
                "index": index,
                "joint": joint,
                "kind": kind,
                "method": method,
                "morse_after": morse_after,
                "morse_before": morse_before,
                "null_vector": null_vector,
                "q": q,
                "residual": residual,
                "spring_forces": spring_forces,
                "spring_lengths": spring_lengths,
                "spring_states": spring_states,
                "spring_stretches": spring_stretches,
                "stability": stability,
                "t": t,
                "tip": tip,
            }
        )
        if spring is not UNSET:
            field_dict["spring"] = spring
        if stiffness_after is not UNSET:
            field_dict["stiffness_after"] = stiffness_after
        if stiffness_before is not UNSET:
            field_dict["stiffness_before"] = stiffness_before

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.force import Force  # noqa: PLC0415

        d = dict(src_dict)
        energy = d.pop("energy")

        force = Force.from_dict(d.pop("force"))

        index = d.pop("index")

        def _parse_joint(data: object) -> int | None:
            if data is None:
                return data
            return cast(int | None, data)

        joint = _parse_joint(d.pop("joint"))

        kind = BranchEventOutKind(d.pop("kind"))

        method = d.pop("method")

        morse_after = d.pop("morse_after")

        morse_before = d.pop("morse_before")

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

        q = cast(list[float], d.pop("q"))

        def _parse_residual(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        residual = _parse_residual(d.pop("residual"))

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

        def _parse_spring_states(data: object) -> list[list[BranchEventOutSpringStatesType0ItemItem]] | None:
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
                        spring_states_type_0_item_item = BranchEventOutSpringStatesType0ItemItem(
                            spring_states_type_0_item_item_data
                        )

                        spring_states_type_0_item.append(spring_states_type_0_item_item)

                    spring_states_type_0.append(spring_states_type_0_item)

                return spring_states_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[BranchEventOutSpringStatesType0ItemItem]] | None, data)

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

        stability = BranchEventOutStability(d.pop("stability"))

        t = d.pop("t")

        tip = cast(list[float], d.pop("tip"))

        def _parse_spring(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        spring = _parse_spring(d.pop("spring", UNSET))

        def _parse_stiffness_after(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        stiffness_after = _parse_stiffness_after(d.pop("stiffness_after", UNSET))

        def _parse_stiffness_before(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        stiffness_before = _parse_stiffness_before(d.pop("stiffness_before", UNSET))

        branch_event_out = cls(
            energy=energy,
            force=force,
            index=index,
            joint=joint,
            kind=kind,
            method=method,
            morse_after=morse_after,
            morse_before=morse_before,
            null_vector=null_vector,
            q=q,
            residual=residual,
            spring_forces=spring_forces,
            spring_lengths=spring_lengths,
            spring_states=spring_states,
            spring_stretches=spring_stretches,
            stability=stability,
            t=t,
            tip=tip,
            spring=spring,
            stiffness_after=stiffness_after,
            stiffness_before=stiffness_before,
        )

        branch_event_out.additional_properties = d
        return branch_event_out

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
