from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.plot_map_request_boundary import PlotMapRequestBoundary
from ..models.plot_map_request_format_type_0 import PlotMapRequestFormatType0
from ..models.plot_map_request_param_x import PlotMapRequestParamX
from ..models.plot_map_request_param_y import PlotMapRequestParamY
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.map_values_range import MapValuesRange
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.uniform_manipulator_in import UniformManipulatorIn


T = TypeVar("T", bound="PlotMapRequest")


@_attrs_define
class PlotMapRequest:
    """Critical load over two design parameters, applied uniformly to every segment.

    Attributes:
        manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
            (uniform) or {"segments": [...]}
        param_x (PlotMapRequestParamX): horizontal axis: a, b, k or L0
        param_y (PlotMapRequestParamY): vertical axis: a, b, k or L0 (not param_x)
        values_x (list[float] | MapValuesRange): values of the parameter (> 0, strictly increasing or decreasing): a
            list or {start, stop, num} (2..41 values)
        values_y (list[float] | MapValuesRange): values of the parameter (> 0, strictly increasing or decreasing): a
            list or {start, stop, num} (2..41 values)
        boundary (PlotMapRequestBoundary | Unset): "guided": tip held at dy = 0 (the paper); "free": cantilever Default:
            PlotMapRequestBoundary.GUIDED.
        dpi (int | Unset): PNG resolution in dots per inch (30..200; default 120, the command line's too) Default: 120.
        format_ (None | PlotMapRequestFormatType0 | Unset): "png" or "svg"; when absent the Accept header decides
            (image/svg+xml or image/png), PNG by default
    """

    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    param_x: PlotMapRequestParamX
    param_y: PlotMapRequestParamY
    values_x: list[float] | MapValuesRange
    values_y: list[float] | MapValuesRange
    boundary: PlotMapRequestBoundary | Unset = PlotMapRequestBoundary.GUIDED
    dpi: int | Unset = 120
    format_: None | PlotMapRequestFormatType0 | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, UniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        param_x = self.param_x.value

        param_y = self.param_y.value

        values_x: dict[str, Any] | list[float]
        if isinstance(self.values_x, list):
            values_x = self.values_x

        else:
            values_x = self.values_x.to_dict()

        values_y: dict[str, Any] | list[float]
        if isinstance(self.values_y, list):
            values_y = self.values_y

        else:
            values_y = self.values_y.to_dict()

        boundary: str | Unset = UNSET
        if not isinstance(self.boundary, Unset):
            boundary = self.boundary.value

        dpi = self.dpi

        format_: None | str | Unset
        if isinstance(self.format_, Unset):
            format_ = UNSET
        elif isinstance(self.format_, PlotMapRequestFormatType0):
            format_ = self.format_.value
        else:
            format_ = self.format_

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "manipulator": manipulator,
                "param_x": param_x,
                "param_y": param_y,
                "values_x": values_x,
                "values_y": values_y,
            }
        )
        if boundary is not UNSET:
            field_dict["boundary"] = boundary
        if dpi is not UNSET:
            field_dict["dpi"] = dpi
        if format_ is not UNSET:
            field_dict["format"] = format_

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.map_values_range import MapValuesRange  # noqa: PLC0415
        from ..models.segmented_manipulator_in import SegmentedManipulatorIn  # noqa: PLC0415
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        d = dict(src_dict)

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

        param_x = PlotMapRequestParamX(d.pop("param_x"))

        param_y = PlotMapRequestParamY(d.pop("param_y"))

        def _parse_values_x(data: object) -> list[float] | MapValuesRange:
            try:
                if not isinstance(data, list):
                    raise TypeError()
                values_x_type_0 = cast(list[float], data)

                return values_x_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            if not isinstance(data, dict):
                raise TypeError()
            values_x_type_1 = MapValuesRange.from_dict(data)

            return values_x_type_1

        values_x = _parse_values_x(d.pop("values_x"))

        def _parse_values_y(data: object) -> list[float] | MapValuesRange:
            try:
                if not isinstance(data, list):
                    raise TypeError()
                values_y_type_0 = cast(list[float], data)

                return values_y_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            if not isinstance(data, dict):
                raise TypeError()
            values_y_type_1 = MapValuesRange.from_dict(data)

            return values_y_type_1

        values_y = _parse_values_y(d.pop("values_y"))

        _boundary = d.pop("boundary", UNSET)
        boundary: PlotMapRequestBoundary | Unset
        if isinstance(_boundary, Unset):
            boundary = UNSET
        else:
            boundary = PlotMapRequestBoundary(_boundary)

        dpi = d.pop("dpi", UNSET)

        def _parse_format_(data: object) -> None | PlotMapRequestFormatType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                format_type_0 = PlotMapRequestFormatType0(data)

                return format_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PlotMapRequestFormatType0 | Unset, data)

        format_ = _parse_format_(d.pop("format", UNSET))

        plot_map_request = cls(
            manipulator=manipulator,
            param_x=param_x,
            param_y=param_y,
            values_x=values_x,
            values_y=values_y,
            boundary=boundary,
            dpi=dpi,
            format_=format_,
        )

        return plot_map_request
