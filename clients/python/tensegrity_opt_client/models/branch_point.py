from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.branch_point_spring_states_type_0_item_item import BranchPointSpringStatesType0ItemItem

T = TypeVar("T", bound="BranchPoint")


@_attrs_define
class BranchPoint:
    """A point of one followed branch; numbers are null where the branch does not exist.

    Attributes:
        dx (float):
        dy (float):
        energy (float | None):
        exists (bool):
        fx (float | None):
        fy (float | None):
        morse_index (int): -1 where the branch does not exist
        q (list[float | None]):
        shape (str):
        spring_forces (list[list[float]] | None): each spring's force, tension positive: k (L - L0) (linear law), k
            max(0, L - L0) (tension-only)
        spring_lengths (list[list[float]] | None): each spring's length L (length units), [spring 1, spring 2] per
            segment
        spring_states (list[list[BranchPointSpringStatesType0ItemItem]] | None): `taut` (L >= L0), `slack` (tension-
            only, L < L0: no force) or `pushing` (linear law, L < L0: a compressive force a real tension spring cannot
            carry)
        spring_stretches (list[list[float]] | None): L - L0 per spring (negative: shorter than its rest length)
        stable (bool):
    """

    dx: float
    dy: float
    energy: float | None
    exists: bool
    fx: float | None
    fy: float | None
    morse_index: int
    q: list[float | None]
    shape: str
    spring_forces: list[list[float]] | None
    spring_lengths: list[list[float]] | None
    spring_states: list[list[BranchPointSpringStatesType0ItemItem]] | None
    spring_stretches: list[list[float]] | None
    stable: bool
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        dx = self.dx

        dy = self.dy

        energy: float | None
        energy = self.energy

        exists = self.exists

        fx: float | None
        fx = self.fx

        fy: float | None
        fy = self.fy

        morse_index = self.morse_index

        q = []
        for q_item_data in self.q:
            q_item: float | None
            q_item = q_item_data
            q.append(q_item)

        shape = self.shape

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

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "dx": dx,
                "dy": dy,
                "energy": energy,
                "exists": exists,
                "fx": fx,
                "fy": fy,
                "morse_index": morse_index,
                "q": q,
                "shape": shape,
                "spring_forces": spring_forces,
                "spring_lengths": spring_lengths,
                "spring_states": spring_states,
                "spring_stretches": spring_stretches,
                "stable": stable,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        dx = d.pop("dx")

        dy = d.pop("dy")

        def _parse_energy(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        energy = _parse_energy(d.pop("energy"))

        exists = d.pop("exists")

        def _parse_fx(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        fx = _parse_fx(d.pop("fx"))

        def _parse_fy(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        fy = _parse_fy(d.pop("fy"))

        morse_index = d.pop("morse_index")

        q = []
        _q = d.pop("q")
        for q_item_data in _q:

            def _parse_q_item(data: object) -> float | None:
                if data is None:
                    return data
                return cast(float | None, data)

            q_item = _parse_q_item(q_item_data)

            q.append(q_item)

        shape = d.pop("shape")

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

        def _parse_spring_states(data: object) -> list[list[BranchPointSpringStatesType0ItemItem]] | None:
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
                        spring_states_type_0_item_item = BranchPointSpringStatesType0ItemItem(
                            spring_states_type_0_item_item_data
                        )

                        spring_states_type_0_item.append(spring_states_type_0_item_item)

                    spring_states_type_0.append(spring_states_type_0_item)

                return spring_states_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[BranchPointSpringStatesType0ItemItem]] | None, data)

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

        branch_point = cls(
            dx=dx,
            dy=dy,
            energy=energy,
            exists=exists,
            fx=fx,
            fy=fy,
            morse_index=morse_index,
            q=q,
            shape=shape,
            spring_forces=spring_forces,
            spring_lengths=spring_lengths,
            spring_states=spring_states,
            spring_stretches=spring_stretches,
            stable=stable,
        )

        branch_point.additional_properties = d
        return branch_point

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
