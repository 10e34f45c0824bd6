from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.plot_imperfection_request_boundary import PlotImperfectionRequestBoundary
from ..models.plot_imperfection_request_format_type_0 import PlotImperfectionRequestFormatType0
from ..models.plot_imperfection_request_imperfection import PlotImperfectionRequestImperfection
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.uniform_manipulator_in import UniformManipulatorIn


T = TypeVar("T", bound="PlotImperfectionRequest")


@_attrs_define
class PlotImperfectionRequest:
    """The imperfection-sensitivity curve of `/v1/imperfection-sensitivity`: the limit load against the amplitude,
    a marker per kind, the perfect chain's limit load as a line, the fitted small-imperfection law dashed.

        Attributes:
            amplitudes (list[float]): the amplitudes p, computed in this order (1..64; 0 is the given chain)
            manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
                (uniform) or {"segments": [...]}
            boundary (PlotImperfectionRequestBoundary | Unset): "guided": y held at each imperfect chain's rest tip, Fx = t
                d_x; "free": F = t d Default: PlotImperfectionRequestBoundary.GUIDED.
            direction (list[float] | Unset): the load's direction (normalised; [-1, 0] compresses)
            dpi (int | Unset): PNG resolution in dots per inch (30..200; default 120, the command line's too) Default: 120.
            format_ (None | PlotImperfectionRequestFormatType0 | Unset): "png" or "svg"; when absent the Accept header
                decides (image/svg+xml or image/png), PNG by default
            imperfection (PlotImperfectionRequestImperfection | Unset): what p moves: asymmetry (every segment's rest
                lengths L1_0 + p, L2_0 - p: a pre-bend), L0 (both + p), a, b, k (both springs) Default:
                PlotImperfectionRequestImperfection.ASYMMETRY.
            max_load (float | None | Unset): stop each path there (force units); default 100 k c^2 / (2b)
            max_points (int | Unset): at most this many points per branch, the start included (2..5000; server limit
                TENSEGRITY_MAX_PATH_POINTS) Default: 4000.
    """

    amplitudes: list[float]
    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    boundary: PlotImperfectionRequestBoundary | Unset = PlotImperfectionRequestBoundary.GUIDED
    direction: list[float] | Unset = UNSET
    dpi: int | Unset = 120
    format_: None | PlotImperfectionRequestFormatType0 | Unset = UNSET
    imperfection: PlotImperfectionRequestImperfection | Unset = PlotImperfectionRequestImperfection.ASYMMETRY
    max_load: float | None | Unset = UNSET
    max_points: int | Unset = 4000

    def to_dict(self) -> dict[str, Any]:
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        amplitudes = self.amplitudes

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, UniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        boundary: str | Unset = UNSET
        if not isinstance(self.boundary, Unset):
            boundary = self.boundary.value

        direction: list[float] | Unset = UNSET
        if not isinstance(self.direction, Unset):
            direction = self.direction

        dpi = self.dpi

        format_: None | str | Unset
        if isinstance(self.format_, Unset):
            format_ = UNSET
        elif isinstance(self.format_, PlotImperfectionRequestFormatType0):
            format_ = self.format_.value
        else:
            format_ = self.format_

        imperfection: str | Unset = UNSET
        if not isinstance(self.imperfection, Unset):
            imperfection = self.imperfection.value

        max_load: float | None | Unset
        if isinstance(self.max_load, Unset):
            max_load = UNSET
        else:
            max_load = self.max_load

        max_points = self.max_points

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "amplitudes": amplitudes,
                "manipulator": manipulator,
            }
        )
        if boundary is not UNSET:
            field_dict["boundary"] = boundary
        if direction is not UNSET:
            field_dict["direction"] = direction
        if dpi is not UNSET:
            field_dict["dpi"] = dpi
        if format_ is not UNSET:
            field_dict["format"] = format_
        if imperfection is not UNSET:
            field_dict["imperfection"] = imperfection
        if max_load is not UNSET:
            field_dict["max_load"] = max_load
        if max_points is not UNSET:
            field_dict["max_points"] = max_points

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.segmented_manipulator_in import SegmentedManipulatorIn  # noqa: PLC0415
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        d = dict(src_dict)
        amplitudes = cast(list[float], d.pop("amplitudes"))

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

        _boundary = d.pop("boundary", UNSET)
        boundary: PlotImperfectionRequestBoundary | Unset
        if isinstance(_boundary, Unset):
            boundary = UNSET
        else:
            boundary = PlotImperfectionRequestBoundary(_boundary)

        direction = cast(list[float], d.pop("direction", UNSET))

        dpi = d.pop("dpi", UNSET)

        def _parse_format_(data: object) -> None | PlotImperfectionRequestFormatType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                format_type_0 = PlotImperfectionRequestFormatType0(data)

                return format_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PlotImperfectionRequestFormatType0 | Unset, data)

        format_ = _parse_format_(d.pop("format", UNSET))

        _imperfection = d.pop("imperfection", UNSET)
        imperfection: PlotImperfectionRequestImperfection | Unset
        if isinstance(_imperfection, Unset):
            imperfection = UNSET
        else:
            imperfection = PlotImperfectionRequestImperfection(_imperfection)

        def _parse_max_load(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        max_load = _parse_max_load(d.pop("max_load", UNSET))

        max_points = d.pop("max_points", UNSET)

        plot_imperfection_request = cls(
            amplitudes=amplitudes,
            manipulator=manipulator,
            boundary=boundary,
            direction=direction,
            dpi=dpi,
            format_=format_,
            imperfection=imperfection,
            max_load=max_load,
            max_points=max_points,
        )

        return plot_imperfection_request
