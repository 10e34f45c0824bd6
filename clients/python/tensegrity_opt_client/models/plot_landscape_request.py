from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.plot_landscape_request_format_type_0 import PlotLandscapeRequestFormatType0
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.uniform_manipulator_in import UniformManipulatorIn


T = TypeVar("T", bound="PlotLandscapeRequest")


@_attrs_define
class PlotLandscapeRequest:
    """Energy contours E(q_i, q_j) with every equilibrium marked (n = 4, Figs. 4-5).

    Attributes:
        dx (float): tip deflection along x (length units)
        manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
            (uniform) or {"segments": [...]}
        dpi (int | Unset): PNG resolution in dots per inch (30..200; default 120, the command line's too) Default: 120.
        dy (float | Unset): tip deflection along y (length units) Default: 0.0.
        format_ (None | PlotLandscapeRequestFormatType0 | Unset): "png" or "svg"; when absent the Accept header decides
            (image/svg+xml or image/png), PNG by default
        grid (int | Unset): points per axis (2..201); default 61: the contours of the smooth energy at that many points
            and the region's boundary on a grid four times finer (a finer grid changes little that shows and costs time)
            Default: 61.
        pair (list[int] | Unset): the two grid joints, 0-based and different
        span (float | None | Unset): half-width of both axes (rad); default: the reachable region of the landscape
    """

    dx: float
    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    dpi: int | Unset = 120
    dy: float | Unset = 0.0
    format_: None | PlotLandscapeRequestFormatType0 | Unset = UNSET
    grid: int | Unset = 61
    pair: list[int] | Unset = UNSET
    span: float | None | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        dx = self.dx

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, UniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        dpi = self.dpi

        dy = self.dy

        format_: None | str | Unset
        if isinstance(self.format_, Unset):
            format_ = UNSET
        elif isinstance(self.format_, PlotLandscapeRequestFormatType0):
            format_ = self.format_.value
        else:
            format_ = self.format_

        grid = self.grid

        pair: list[int] | Unset = UNSET
        if not isinstance(self.pair, Unset):
            pair = self.pair

        span: float | None | Unset
        if isinstance(self.span, Unset):
            span = UNSET
        else:
            span = self.span

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "dx": dx,
                "manipulator": manipulator,
            }
        )
        if dpi is not UNSET:
            field_dict["dpi"] = dpi
        if dy is not UNSET:
            field_dict["dy"] = dy
        if format_ is not UNSET:
            field_dict["format"] = format_
        if grid is not UNSET:
            field_dict["grid"] = grid
        if pair is not UNSET:
            field_dict["pair"] = pair
        if span is not UNSET:
            field_dict["span"] = span

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.segmented_manipulator_in import SegmentedManipulatorIn  # noqa: PLC0415
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        d = dict(src_dict)
        dx = d.pop("dx")

        def _parse_manipulator(data: object) -> SegmentedManipulatorIn | UniformManipulatorIn:
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                manipulator_type_0 = UniformManipulatorIn.from_dict(data)

                return manipulator_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            if not isinstance(data, dict):
                raise TypeError()
            manipulator_type_1 = SegmentedManipulatorIn.from_dict(data)

            return manipulator_type_1

        manipulator = _parse_manipulator(d.pop("manipulator"))

        dpi = d.pop("dpi", UNSET)

        dy = d.pop("dy", UNSET)

        def _parse_format_(data: object) -> None | PlotLandscapeRequestFormatType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                format_type_0 = PlotLandscapeRequestFormatType0(data)

                return format_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PlotLandscapeRequestFormatType0 | Unset, data)

        format_ = _parse_format_(d.pop("format", UNSET))

        grid = d.pop("grid", UNSET)

        pair = cast(list[int], d.pop("pair", UNSET))

        def _parse_span(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        span = _parse_span(d.pop("span", UNSET))

        plot_landscape_request = cls(
            dx=dx,
            manipulator=manipulator,
            dpi=dpi,
            dy=dy,
            format_=format_,
            grid=grid,
            pair=pair,
            span=span,
        )

        return plot_landscape_request
