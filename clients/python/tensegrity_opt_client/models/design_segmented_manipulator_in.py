from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.joint_force_in import JointForceIn
    from ..models.segment_in import SegmentIn


T = TypeVar("T", bound="DesignSegmentedManipulatorIn")


@_attrs_define
class DesignSegmentedManipulatorIn:
    """Segments listed from base to tip (design endpoints: at most 60).

    Attributes:
        segments (list[SegmentIn]): segments from base to tip (at most 60)
        gravity (list[float] | None | Unset): the gravity vector [gx, gy] in the chain's plane (default none: no
            weight); [0, -9.81] for a chain pointing along +x in a vertical plane, any direction (a tilted base). The
            triangles' and the payload's weights then load the chain in every analysis that honours dead loads; the others
            refuse it (422 `unsupported`, field `gravity`)
        joint_forces (list[JointForceIn] | Unset): dead point forces at joints, beside the tip's load: [{"joint": j,
            "force": [fx, fy]}], joints counted from 1 at the base (joint 1 is fixed: a force there does no work); analyses
            that do not honour dead loads refuse them (422 `unsupported`, field `joint_forces`)
        payload (float | Unset): a point mass at the tip (>= 0, default 0): it sets the vibration modes (`/v1/modes`)
            and, under `gravity`, weighs on the chain Default: 0.0.
    """

    segments: list[SegmentIn]
    gravity: list[float] | None | Unset = UNSET
    joint_forces: list[JointForceIn] | Unset = UNSET
    payload: float | Unset = 0.0

    def to_dict(self) -> dict[str, Any]:
        segments = []
        for segments_item_data in self.segments:
            segments_item = segments_item_data.to_dict()
            segments.append(segments_item)

        gravity: list[float] | None | Unset
        if isinstance(self.gravity, Unset):
            gravity = UNSET
        elif isinstance(self.gravity, list):
            gravity = self.gravity

        else:
            gravity = self.gravity

        joint_forces: list[dict[str, Any]] | Unset = UNSET
        if not isinstance(self.joint_forces, Unset):
            joint_forces = []
            for joint_forces_item_data in self.joint_forces:
                joint_forces_item = joint_forces_item_data.to_dict()
                joint_forces.append(joint_forces_item)

        payload = self.payload

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "segments": segments,
            }
        )
        if gravity is not UNSET:
            field_dict["gravity"] = gravity
        if joint_forces is not UNSET:
            field_dict["joint_forces"] = joint_forces
        if payload is not UNSET:
            field_dict["payload"] = payload

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.joint_force_in import JointForceIn  # noqa: PLC0415
        from ..models.segment_in import SegmentIn  # noqa: PLC0415

        d = dict(src_dict)
        segments = []
        _segments = d.pop("segments")
        for segments_item_data in _segments:
            segments_item = SegmentIn.from_dict(segments_item_data)

            segments.append(segments_item)

        def _parse_gravity(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                gravity_type_0 = cast(list[float], data)

                return gravity_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        gravity = _parse_gravity(d.pop("gravity", UNSET))

        _joint_forces = d.pop("joint_forces", UNSET)
        joint_forces: list[JointForceIn] | Unset = UNSET
        if _joint_forces is not UNSET:
            joint_forces = []
            for joint_forces_item_data in _joint_forces:
                joint_forces_item = JointForceIn.from_dict(joint_forces_item_data)

                joint_forces.append(joint_forces_item)

        payload = d.pop("payload", UNSET)

        design_segmented_manipulator_in = cls(
            segments=segments,
            gravity=gravity,
            joint_forces=joint_forces,
            payload=payload,
        )

        return design_segmented_manipulator_in
