from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.limit_load_out_boundary import LimitLoadOutBoundary
from ..models.limit_load_out_branch_status import LimitLoadOutBranchStatus
from ..models.limit_load_out_kind import LimitLoadOutKind
from ..models.limit_load_out_spring_states_type_0_item_item import LimitLoadOutSpringStatesType0ItemItem
from ..models.limit_load_out_status import LimitLoadOutStatus
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.equilibrium_out import EquilibriumOut
    from ..models.force import Force
    from ..models.traced_branch_out import TracedBranchOut


T = TypeVar("T", bound="LimitLoadOut")


@_attrs_define
class LimitLoadOut:
    """The limit load: `status` stability_lost (`kind` fold or bifurcation), or why the path has none.

    Attributes:
        boundary (LimitLoadOutBoundary):
        branch_points (int):
        branch_status (LimitLoadOutBranchStatus): how the traced path ended (its status)
        direction (list[float]):
        end_load (float): the last load reached on the stable path
        force (Force | None):
        kind (LimitLoadOutKind):
        load (float | None): the load where stability is first lost (null for kind none)
        message (str): what happened, in a sentence
        null_vector (list[float] | None):
        q (list[float] | None):
        quasi_buckling_force (Force | None):
        quasi_buckling_load (float | None): the load of least tangent stiffness along the load
        quasi_buckling_stiffness (float | None): the tangent stiffness along the load there, 1 / (d . C d) (force per
            length; guided: y held), the least on the stable path
        spring_forces (list[list[float]] | None): each spring's force, tension positive: k (L - L0) (linear law), k
            max(0, L - L0) (tension-only)
        spring_lengths (list[list[float]] | None): each spring's length L (length units), [spring 1, spring 2] per
            segment
        spring_states (list[list[LimitLoadOutSpringStatesType0ItemItem]] | None): `taut` (L >= L0), `slack` (tension-
            only, L < L0: no force) or `pushing` (linear law, L < L0: a compressive force a real tension spring cannot
            carry)
        spring_stretches (list[list[float]] | None): L - L0 per spring (negative: shorter than its rest length)
        start (EquilibriumOut): An equilibrium configuration.
        status (LimitLoadOutStatus): `stability_lost`: the path loses stability at load: a fold or a bifurcation (kind);
            `joint_limit`: no limit point: the path stays stable until a joint reaches its range bound; `max_load`: no limit
            point up to max_load; `max_points`: no limit point within max_points points of the path; `closed_loop`: the path
            closed on its start without losing stability; `force_bound`: the tip force exceeded the continuation's force
            bound without a limit point; `step_too_small`: the path could not be continued (the step fell below its
            minimum); `corrector_failed`: the path could not be continued (the corrector failed); `time_limit`: the time
            limit ran out before a limit point was found
        success (bool): whether it worked: `status` is one of joint_limit, max_load, stability_lost
        branch (None | TracedBranchOut | Unset): include_branch only: the traced path
    """

    boundary: LimitLoadOutBoundary
    branch_points: int
    branch_status: LimitLoadOutBranchStatus
    direction: list[float]
    end_load: float
    force: Force | None
    kind: LimitLoadOutKind
    load: float | None
    message: str
    null_vector: list[float] | None
    q: list[float] | None
    quasi_buckling_force: Force | None
    quasi_buckling_load: float | None
    quasi_buckling_stiffness: float | None
    spring_forces: list[list[float]] | None
    spring_lengths: list[list[float]] | None
    spring_states: list[list[LimitLoadOutSpringStatesType0ItemItem]] | None
    spring_stretches: list[list[float]] | None
    start: EquilibriumOut
    status: LimitLoadOutStatus
    success: bool
    branch: None | TracedBranchOut | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        from ..models.force import Force  # noqa: PLC0415
        from ..models.traced_branch_out import TracedBranchOut  # noqa: PLC0415

        boundary = self.boundary.value

        branch_points = self.branch_points

        branch_status = self.branch_status.value

        direction = self.direction

        end_load = self.end_load

        force: dict[str, Any] | None
        if isinstance(self.force, Force):
            force = self.force.to_dict()
        else:
            force = self.force

        kind = self.kind.value

        load: float | None
        load = self.load

        message = self.message

        null_vector: list[float] | None
        if isinstance(self.null_vector, list):
            null_vector = self.null_vector

        else:
            null_vector = self.null_vector

        q: list[float] | None
        if isinstance(self.q, list):
            q = self.q

        else:
            q = self.q

        quasi_buckling_force: dict[str, Any] | None
        if isinstance(self.quasi_buckling_force, Force):
            quasi_buckling_force = self.quasi_buckling_force.to_dict()
        else:
            quasi_buckling_force = self.quasi_buckling_force

        quasi_buckling_load: float | None
        quasi_buckling_load = self.quasi_buckling_load

        quasi_buckling_stiffness: float | None
        quasi_buckling_stiffness = self.quasi_buckling_stiffness

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

        start = self.start.to_dict()

        status = self.status.value

        success = self.success

        branch: dict[str, Any] | None | Unset
        if isinstance(self.branch, Unset):
            branch = UNSET
        elif isinstance(self.branch, TracedBranchOut):
            branch = self.branch.to_dict()
        else:
            branch = self.branch

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "boundary": boundary,
                "branch_points": branch_points,
                "branch_status": branch_status,
                "direction": direction,
                "end_load": end_load,
                "force": force,
                "kind": kind,
                "load": load,
                "message": message,
                "null_vector": null_vector,
                "q": q,
                "quasi_buckling_force": quasi_buckling_force,
                "quasi_buckling_load": quasi_buckling_load,
                "quasi_buckling_stiffness": quasi_buckling_stiffness,
                "spring_forces": spring_forces,
                "spring_lengths": spring_lengths,
                "spring_states": spring_states,
                "spring_stretches": spring_stretches,
                "start": start,
                "status": status,
                "success": success,
            }
        )
        if branch is not UNSET:
            field_dict["branch"] = branch

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.equilibrium_out import EquilibriumOut  # noqa: PLC0415
        from ..models.force import Force  # noqa: PLC0415
        from ..models.traced_branch_out import TracedBranchOut  # noqa: PLC0415

        d = dict(src_dict)
        boundary = LimitLoadOutBoundary(d.pop("boundary"))

        branch_points = d.pop("branch_points")

        branch_status = LimitLoadOutBranchStatus(d.pop("branch_status"))

        direction = cast(list[float], d.pop("direction"))

        end_load = d.pop("end_load")

        def _parse_force(data: object) -> Force | None:
            if data is None:
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                force_type_0 = Force.from_dict(data)

                return force_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(Force | None, data)

        force = _parse_force(d.pop("force"))

        kind = LimitLoadOutKind(d.pop("kind"))

        def _parse_load(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        load = _parse_load(d.pop("load"))

        message = d.pop("message")

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

        def _parse_q(data: object) -> list[float] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                q_type_0 = cast(list[float], data)

                return q_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None, data)

        q = _parse_q(d.pop("q"))

        def _parse_quasi_buckling_force(data: object) -> Force | None:
            if data is None:
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                quasi_buckling_force_type_0 = Force.from_dict(data)

                return quasi_buckling_force_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(Force | None, data)

        quasi_buckling_force = _parse_quasi_buckling_force(d.pop("quasi_buckling_force"))

        def _parse_quasi_buckling_load(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        quasi_buckling_load = _parse_quasi_buckling_load(d.pop("quasi_buckling_load"))

        def _parse_quasi_buckling_stiffness(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        quasi_buckling_stiffness = _parse_quasi_buckling_stiffness(d.pop("quasi_buckling_stiffness"))

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

        def _parse_spring_states(data: object) -> list[list[LimitLoadOutSpringStatesType0ItemItem]] | None:
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
                        spring_states_type_0_item_item = LimitLoadOutSpringStatesType0ItemItem(
                            spring_states_type_0_item_item_data
                        )

                        spring_states_type_0_item.append(spring_states_type_0_item_item)

                    spring_states_type_0.append(spring_states_type_0_item)

                return spring_states_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[LimitLoadOutSpringStatesType0ItemItem]] | None, data)

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

        start = EquilibriumOut.from_dict(d.pop("start"))

        status = LimitLoadOutStatus(d.pop("status"))

        success = d.pop("success")

        def _parse_branch(data: object) -> None | TracedBranchOut | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                branch_type_0 = TracedBranchOut.from_dict(data)

                return branch_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | TracedBranchOut | Unset, data)

        branch = _parse_branch(d.pop("branch", UNSET))

        limit_load_out = cls(
            boundary=boundary,
            branch_points=branch_points,
            branch_status=branch_status,
            direction=direction,
            end_load=end_load,
            force=force,
            kind=kind,
            load=load,
            message=message,
            null_vector=null_vector,
            q=q,
            quasi_buckling_force=quasi_buckling_force,
            quasi_buckling_load=quasi_buckling_load,
            quasi_buckling_stiffness=quasi_buckling_stiffness,
            spring_forces=spring_forces,
            spring_lengths=spring_lengths,
            spring_states=spring_states,
            spring_stretches=spring_stretches,
            start=start,
            status=status,
            success=success,
            branch=branch,
        )

        limit_load_out.additional_properties = d
        return limit_load_out

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
