from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.force_deflection_out_reference import ForceDeflectionOutReference
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.branch_out import BranchOut
    from ..models.curve_end_out import CurveEndOut
    from ..models.curve_point import CurvePoint
    from ..models.jump_out import JumpOut


T = TypeVar("T", bound="ForceDeflectionOut")


@_attrs_define
class ForceDeflectionOut:
    """
    Attributes:
        branches (list[BranchOut]): branch = "all" only (else empty)
        complete (bool): every requested point was computed (ended_at is null)
        ended_at (CurveEndOut | None): null when complete; else the first requested point where no stable equilibrium is
            found: points holds only the points before it (the later ones are not computed)
        jumps (list[JumpOut]):
        note (str): "" when complete, else a sentence saying where the curve ends and how many points it holds
        points (list[CurvePoint]):
        requested (int): how many points were asked for (len(points) when complete)
        origin (list[float] | Unset): the reference tip's deflection from the straight tip (add it to dx, dy for the
            deflection from straight)
        reference (ForceDeflectionOutReference | Unset): what dx, dy are measured from Default:
            ForceDeflectionOutReference.STRAIGHT.
    """

    branches: list[BranchOut]
    complete: bool
    ended_at: CurveEndOut | None
    jumps: list[JumpOut]
    note: str
    points: list[CurvePoint]
    requested: int
    origin: list[float] | Unset = UNSET
    reference: ForceDeflectionOutReference | Unset = ForceDeflectionOutReference.STRAIGHT
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        from ..models.curve_end_out import CurveEndOut  # noqa: PLC0415

        branches = []
        for branches_item_data in self.branches:
            branches_item = branches_item_data.to_dict()
            branches.append(branches_item)

        complete = self.complete

        ended_at: dict[str, Any] | None
        if isinstance(self.ended_at, CurveEndOut):
            ended_at = self.ended_at.to_dict()
        else:
            ended_at = self.ended_at

        jumps = []
        for jumps_item_data in self.jumps:
            jumps_item = jumps_item_data.to_dict()
            jumps.append(jumps_item)

        note = self.note

        points = []
        for points_item_data in self.points:
            points_item = points_item_data.to_dict()
            points.append(points_item)

        requested = self.requested

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
                "complete": complete,
                "ended_at": ended_at,
                "jumps": jumps,
                "note": note,
                "points": points,
                "requested": requested,
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

        d = dict(src_dict)
        branches = []
        _branches = d.pop("branches")
        for branches_item_data in _branches:
            branches_item = BranchOut.from_dict(branches_item_data)

            branches.append(branches_item)

        complete = d.pop("complete")

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

        note = d.pop("note")

        points = []
        _points = d.pop("points")
        for points_item_data in _points:
            points_item = CurvePoint.from_dict(points_item_data)

            points.append(points_item)

        requested = d.pop("requested")

        origin = cast(list[float], d.pop("origin", UNSET))

        _reference = d.pop("reference", UNSET)
        reference: ForceDeflectionOutReference | Unset
        if isinstance(_reference, Unset):
            reference = UNSET
        else:
            reference = ForceDeflectionOutReference(_reference)

        force_deflection_out = cls(
            branches=branches,
            complete=complete,
            ended_at=ended_at,
            jumps=jumps,
            note=note,
            points=points,
            requested=requested,
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
