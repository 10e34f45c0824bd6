from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.stability_boundary_out_kind import StabilityBoundaryOutKind
from ..models.stability_boundary_out_status import StabilityBoundaryOutStatus

if TYPE_CHECKING:
    from ..models.control_out import ControlOut
    from ..models.cusp_out import CuspOut
    from ..models.force import Force


T = TypeVar("T", bound="StabilityBoundaryOut")


@_attrs_define
class StabilityBoundaryOut:
    """`StabilityBoundary.to_dict()` of the library (`tensegrity_opt.analyses.paths.boundaries`): the first
    stability-losing fold or branch point against the parameter `p`.

        Attributes:
            control (ControlOut):
            cusps (list[CuspOut]):
            force (list[Force]):
            kind (StabilityBoundaryOutKind):
            message (str): what happened, in a sentence
            null_vectors (list[list[float]]): the mode at each point (largest entry +1)
            p (list[float]): the parameter along the curve (0: the given chain)
            parameter (str): the parameter's name (or `direction`)
            points (int):
            q (list[list[float]]): joint angles (rad) per point
            status (StabilityBoundaryOutStatus): `p_range`: p left [p_min, p_max]; `max_points`: max_points points were
                computed on a side; `joint_limit`: the fold configuration reached a joint limit; `ended`: the branch point of
                the symmetric chain is not found beyond the last p (it ends there); `step_too_small`: the fold curve could not
                be continued (the step fell below its minimum); `time_limit`: the time limit ran out (the points computed are
                kept)
            success (bool): whether it worked: `status` is one of ended, joint_limit, max_points, p_range
            t (list[float]): the limit or critical load (the control's parameter) at each p
    """

    control: ControlOut
    cusps: list[CuspOut]
    force: list[Force]
    kind: StabilityBoundaryOutKind
    message: str
    null_vectors: list[list[float]]
    p: list[float]
    parameter: str
    points: int
    q: list[list[float]]
    status: StabilityBoundaryOutStatus
    success: bool
    t: list[float]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        control = self.control.to_dict()

        cusps = []
        for cusps_item_data in self.cusps:
            cusps_item = cusps_item_data.to_dict()
            cusps.append(cusps_item)

        force = []
        for force_item_data in self.force:
            force_item = force_item_data.to_dict()
            force.append(force_item)

        kind = self.kind.value

        message = self.message

        null_vectors = []
        for null_vectors_item_data in self.null_vectors:
            null_vectors_item = null_vectors_item_data

            null_vectors.append(null_vectors_item)

        p = self.p

        parameter = self.parameter

        points = self.points

        q = []
        for q_item_data in self.q:
            q_item = q_item_data

            q.append(q_item)

        status = self.status.value

        success = self.success

        t = self.t

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "control": control,
                "cusps": cusps,
                "force": force,
                "kind": kind,
                "message": message,
                "null_vectors": null_vectors,
                "p": p,
                "parameter": parameter,
                "points": points,
                "q": q,
                "status": status,
                "success": success,
                "t": t,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.control_out import ControlOut  # noqa: PLC0415
        from ..models.cusp_out import CuspOut  # noqa: PLC0415
        from ..models.force import Force  # noqa: PLC0415

        d = dict(src_dict)
        control = ControlOut.from_dict(d.pop("control"))

        cusps = []
        _cusps = d.pop("cusps")
        for cusps_item_data in _cusps:
            cusps_item = CuspOut.from_dict(cusps_item_data)

            cusps.append(cusps_item)

        force = []
        _force = d.pop("force")
        for force_item_data in _force:
            force_item = Force.from_dict(force_item_data)

            force.append(force_item)

        kind = StabilityBoundaryOutKind(d.pop("kind"))

        message = d.pop("message")

        null_vectors = []
        _null_vectors = d.pop("null_vectors")
        for null_vectors_item_data in _null_vectors:
            null_vectors_item = cast(list[float], null_vectors_item_data)

            null_vectors.append(null_vectors_item)

        p = cast(list[float], d.pop("p"))

        parameter = d.pop("parameter")

        points = d.pop("points")

        q = []
        _q = d.pop("q")
        for q_item_data in _q:
            q_item = cast(list[float], q_item_data)

            q.append(q_item)

        status = StabilityBoundaryOutStatus(d.pop("status"))

        success = d.pop("success")

        t = cast(list[float], d.pop("t"))

        stability_boundary_out = cls(
            control=control,
            cusps=cusps,
            force=force,
            kind=kind,
            message=message,
            null_vectors=null_vectors,
            p=p,
            parameter=parameter,
            points=points,
            q=q,
            status=status,
            success=success,
            t=t,
        )

        stability_boundary_out.additional_properties = d
        return stability_boundary_out

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
