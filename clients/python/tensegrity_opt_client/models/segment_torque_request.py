from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

if TYPE_CHECKING:
    from ..models.angle_range import AngleRange
    from ..models.segment_in import SegmentIn


T = TypeVar("T", bound="SegmentTorqueRequest")


@_attrs_define
class SegmentTorqueRequest:
    """Torque curve `M(q)` of one segment.

    Attributes:
        q (AngleRange | list[float]): joint angles (rad, |q| <= 2 pi): a list or {start, stop, num} (at most 10001
            points)
        segment (SegmentIn): One dual-triangle segment.
    """

    q: AngleRange | list[float]
    segment: SegmentIn

    def to_dict(self) -> dict[str, Any]:
        q: dict[str, Any] | list[float]
        if isinstance(self.q, list):
            q = self.q

        else:
            q = self.q.to_dict()

        segment = self.segment.to_dict()

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "q": q,
                "segment": segment,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.angle_range import AngleRange  # noqa: PLC0415
        from ..models.segment_in import SegmentIn  # noqa: PLC0415

        d = dict(src_dict)

        def _parse_q(data: object) -> AngleRange | list[float]:
            try:
                if not isinstance(data, list):
                    raise TypeError()
                q_type_0 = cast(list[float], data)

                return q_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            if not isinstance(data, dict):
                raise TypeError()
            q_type_1 = AngleRange.from_dict(data)

            return q_type_1

        q = _parse_q(d.pop("q"))

        segment = SegmentIn.from_dict(d.pop("segment"))

        segment_torque_request = cls(
            q=q,
            segment=segment,
        )

        return segment_torque_request
