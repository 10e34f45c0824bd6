from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.force_deflection_out_reference import ForceDeflectionOutReference
from ..models.force_deflection_out_status import ForceDeflectionOutStatus
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.branch_out import BranchOut
    from ..models.curve_end_out import CurveEndOut
    from ..models.curve_point import CurvePoint
    from ..models.jump_out import JumpOut
    from ..models.loads_out import LoadsOut


T = TypeVar("T", bound="ForceDeflectionOut")


@_attrs_define
class ForceDeflectionOut:
    """A force-deflection curve: `success` when every requested point was computed; else `ended_at` says where it
    stops and `message` why.

        Attributes:
            branches (list[BranchOut]): branch = "all" only (else empty)
            ended_at (CurveEndOut | None): null when complete; else the first requested point where no stable equilibrium is
                found: points holds only the points before it (the later ones are not computed)
            jumps (list[JumpOut]):
            loads (LoadsOut | None): the dead loads this was computed under (gravity on the chain's masses, joint forces);
                null where the chain carries none
            message (str): what happened, in a sentence
            points (list[CurvePoint]):
            requested (int): how many points were asked for (len(points) when complete)
            status (ForceDeflectionOutStatus): `complete`: every requested point was computed; `no_stable_equilibrium`: no
                stable equilibrium is found there: the stable branches end (a fold, the joint range) and the global search finds
                no other
            success (bool): whether it worked: `status` is one of complete
            origin (list[float] | Unset): the reference tip's deflection from the straight tip (add it to dx, dy for the
                deflection from straight)
            reference (ForceDeflectionOutReference | Unset): what dx, dy are measured from Default:
                ForceDeflectionOutReference.STRAIGHT.
    """

    branches: list[BranchOut]
    ended_at: CurveEndOut | None
    jumps: list[JumpOut]
    loads: LoadsOut | None
    message: str
    points: list[CurvePoint]
    requested: int
    status: ForceDeflectionOutStatus
    success: bool
    origin: list[float] | Unset = UNSET
    reference: ForceDeflectionOutReference | Unset = ForceDeflectionOutReference.STRAIGHT
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        from ..models.curve_end_out import CurveEndOut  # noqa: PLC0415
        from ..models.loads_out import LoadsOut  # noqa: PLC0415

        branches = []
        for branches_item_data in self.branches:
            branches_item = branches_item_data.to_dict()
            branches.append(branches_item)

        ended_at: dict[str, Any] | None
        if isinstance(self.ended_at, CurveEndOut):
            ended_at = self.ended_at.to_dict()
        else:
            ended_at = self.ended_at

        jumps = []
        for jumps_item_data in self.jumps:
            jumps_item = jumps_item_data.to_dict()
            jumps.append(jumps_item)

        loads: dict[str, Any] | None
        if isinstance(self.loads, LoadsOut):
            loads = self.loads.to_dict()
        else:
            loads = self.loads

        message = self.message

        points = []
        for points_item_data in self.points:
            points_item = points_item_data.to_dict()
            points.append(points_item)

        requested = self.requested

        status = self.status.value

        success = self.success

        origin: list[float] | Unset = UNSET
        if not isinstance(self.origin, Unset):
            origin = self.origin

        reference: str | Unset = UNSET
        if not isinstance(self.reference, Unset):
            reference = self.reference.value

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "branches": branches,
                "ended_at": ended_at,
                "jumps": jumps,
                "loads": loads,
                "message": message,
                "points": points,
                "requested": requested,
                "status": status,
                "success": success,
            }
        )
        if origin is not UNSET:
            field_dict["origin"] = origin
        if reference is not UNSET:
            field_dict["reference"] = reference

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.branch_out import BranchOut  # noqa: PLC0415
        from ..models.curve_end_out import CurveEndOut  # noqa: PLC0415
        from ..models.curve_point import CurvePoint  # noqa: PLC0415
        from ..models.jump_out import JumpOut  # noqa: PLC0415
        from ..models.loads_out import LoadsOut  # noqa: PLC0415

        d = dict(src_dict)
        branches = []
        _branches = d.pop("branches")
        for branches_item_data in _branches:
            branches_item = BranchOut.from_dict(branches_item_data)

            branches.append(branches_item)

        def _parse_ended_at(data: object) -> CurveEndOut | None:
            if data is None:
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                ended_at_type_0 = CurveEndOut.from_dict(data)

                return ended_at_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(CurveEndOut | None, data)

        ended_at = _parse_ended_at(d.pop("ended_at"))

        jumps = []
        _jumps = d.pop("jumps")
        for jumps_item_data in _jumps:
            jumps_item = JumpOut.from_dict(jumps_item_data)

            jumps.append(jumps_item)

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

        points = []
        _points = d.pop("points")
        for points_item_data in _points:
            points_item = CurvePoint.from_dict(points_item_data)

            points.append(points_item)

        requested = d.pop("requested")

        status = ForceDeflectionOutStatus(d.pop("status"))

        success = d.pop("success")

        origin = cast(list[float], d.pop("origin", UNSET))

        _reference = d.pop("reference", UNSET)
        reference: ForceDeflectionOutReference | Unset
        if isinstance(_reference, Unset):
            reference = UNSET
        else:
            reference = ForceDeflectionOutReference(_reference)

        force_deflection_out = cls(
            branches=branches,
            ended_at=ended_at,
            jumps=jumps,
            loads=loads,
            message=message,
            points=points,
            requested=requested,
            status=status,
            success=success,
            origin=origin,
            reference=reference,
        )

        force_deflection_out.additional_properties = d
        return force_deflection_out

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
