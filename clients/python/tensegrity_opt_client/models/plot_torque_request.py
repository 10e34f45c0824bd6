from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.plot_torque_request_format_type_0 import PlotTorqueRequestFormatType0
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.plot_angle_range import PlotAngleRange
    from ..models.segment_in import SegmentIn


T = TypeVar("T", bound="PlotTorqueRequest")


@_attrs_define
class PlotTorqueRequest:
    """Torque-angle curves M(q) of one or several segments (Fig. 2).

    Attributes:
        segments (list[SegmentIn]): the segments compared (1..12)
        dpi (int | Unset): PNG resolution in dots per inch (30..200; default 120, the command line's too) Default: 120.
        format_ (None | PlotTorqueRequestFormatType0 | Unset): "png" or "svg"; when absent the Accept header decides
            (image/svg+xml or image/png), PNG by default
        num (int | Unset): points per curve over each segment's physical range (when q is absent) Default: 401.
        q (None | PlotAngleRange | Unset): angles {start, stop, num} (rad) for every curve; default: each segment's
            physical range
    """

    segments: list[SegmentIn]
    dpi: int | Unset = 120
    format_: None | PlotTorqueRequestFormatType0 | Unset = UNSET
    num: int | Unset = 401
    q: None | PlotAngleRange | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.plot_angle_range import PlotAngleRange  # noqa: PLC0415

        segments = []
        for segments_item_data in self.segments:
            segments_item = segments_item_data.to_dict()
            segments.append(segments_item)

        dpi = self.dpi

        format_: None | str | Unset
        if isinstance(self.format_, Unset):
            format_ = UNSET
        elif isinstance(self.format_, PlotTorqueRequestFormatType0):
            format_ = self.format_.value
        else:
            format_ = self.format_

        num = self.num

        q: dict[str, Any] | None | Unset
        if isinstance(self.q, Unset):
            q = UNSET
        elif isinstance(self.q, PlotAngleRange):
            q = self.q.to_dict()
        else:
            q = self.q

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "segments": segments,
            }
        )
        if dpi is not UNSET:
            field_dict["dpi"] = dpi
        if format_ is not UNSET:
            field_dict["format"] = format_
        if num is not UNSET:
            field_dict["num"] = num
        if q is not UNSET:
            field_dict["q"] = q

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.plot_angle_range import PlotAngleRange  # noqa: PLC0415
        from ..models.segment_in import SegmentIn  # noqa: PLC0415

        d = dict(src_dict)
        segments = []
        _segments = d.pop("segments")
        for segments_item_data in _segments:
            segments_item = SegmentIn.from_dict(segments_item_data)

            segments.append(segments_item)

        dpi = d.pop("dpi", UNSET)

        def _parse_format_(data: object) -> None | PlotTorqueRequestFormatType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                format_type_0 = PlotTorqueRequestFormatType0(data)

                return format_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PlotTorqueRequestFormatType0 | Unset, data)

        format_ = _parse_format_(d.pop("format", UNSET))

        num = d.pop("num", UNSET)

        def _parse_q(data: object) -> None | PlotAngleRange | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                q_type_0 = PlotAngleRange.from_dict(data)

                return q_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PlotAngleRange | Unset, data)

        q = _parse_q(d.pop("q", UNSET))

        plot_torque_request = cls(
            segments=segments,
            dpi=dpi,
            format_=format_,
            num=num,
            q=q,
        )

        return plot_torque_request
