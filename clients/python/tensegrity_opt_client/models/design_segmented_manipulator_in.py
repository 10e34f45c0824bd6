from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar

from attrs import define as _attrs_define

from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.segment_in import SegmentIn


T = TypeVar("T", bound="DesignSegmentedManipulatorIn")


@_attrs_define
class DesignSegmentedManipulatorIn:
    """Segments listed from base to tip (design endpoints: at most 60).

    Attributes:
        segments (list[SegmentIn]): segments from base to tip (at most 60)
        payload (float | Unset): a point mass at the tip (>= 0, default 0): it sets the vibration modes (`/v1/modes`)
            Default: 0.0.
    """

    segments: list[SegmentIn]
    payload: float | Unset = 0.0

    def to_dict(self) -> dict[str, Any]:
        segments = []
        for segments_item_data in self.segments:
            segments_item = segments_item_data.to_dict()
            segments.append(segments_item)

        payload = self.payload

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "segments": segments,
            }
        )
        if payload is not UNSET:
            field_dict["payload"] = payload

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.segment_in import SegmentIn  # noqa: PLC0415

        d = dict(src_dict)
        segments = []
        _segments = d.pop("segments")
        for segments_item_data in _segments:
            segments_item = SegmentIn.from_dict(segments_item_data)

            segments.append(segments_item)

        payload = d.pop("payload", UNSET)

        design_segmented_manipulator_in = cls(
            segments=segments,
            payload=payload,
        )

        return design_segmented_manipulator_in
