from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.plot_limit_load_request_boundary import PlotLimitLoadRequestBoundary
from ..models.plot_limit_load_request_format_type_0 import PlotLimitLoadRequestFormatType0
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.start_q import StartQ
    from ..models.uniform_manipulator_in import UniformManipulatorIn


T = TypeVar("T", bound="PlotLimitLoadRequest")


@_attrs_define
class PlotLimitLoadRequest:
    """The load path of `/v1/limit-load`, the limit point and the quasi-buckling load marked; at a bifurcation
    also the buckled arms leaving it (load against the end angle), else load against the tip displacement along
    the load.

        Attributes:
            manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
                (uniform) or {"segments": [...]}
            arms (bool | Unset): at a bifurcation, also draw the buckled arms leaving it (to their first fold or joint
                limit) against the end angle phi; false: the path only, against the tip displacement along the load Default:
                True.
            boundary (PlotLimitLoadRequestBoundary | Unset): "free": the tip free, F = t d; "guided": y held, Fx = t d_x, Fy
                the reaction Default: PlotLimitLoadRequestBoundary.FREE.
            direction (list[float] | Unset): the load's direction (normalised; [-1, 0] compresses)
            dpi (int | Unset): PNG resolution in dots per inch (30..200; default 120, the command line's too) Default: 120.
            format_ (None | PlotLimitLoadRequestFormatType0 | Unset): "png" or "svg"; when absent the Accept header decides
                (image/svg+xml or image/png), PNG by default
            max_load (float | None | Unset): stop there (force units); default 100 k c^2 / (2b)
            max_points (int | Unset): at most this many points per branch, the start included (2..5000; server limit
                TENSEGRITY_MAX_PATH_POINTS) Default: 4000.
            start (None | StartQ | Unset): {"q": [...]}: a rest configuration to start from; null: the least-energy rest
                configuration
    """

    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    arms: bool | Unset = True
    boundary: PlotLimitLoadRequestBoundary | Unset = PlotLimitLoadRequestBoundary.FREE
    direction: list[float] | Unset = UNSET
    dpi: int | Unset = 120
    format_: None | PlotLimitLoadRequestFormatType0 | Unset = UNSET
    max_load: float | None | Unset = UNSET
    max_points: int | Unset = 4000
    start: None | StartQ | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.start_q import StartQ  # noqa: PLC0415
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, UniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        arms = self.arms

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
        elif isinstance(self.format_, PlotLimitLoadRequestFormatType0):
            format_ = self.format_.value
        else:
            format_ = self.format_

        max_load: float | None | Unset
        if isinstance(self.max_load, Unset):
            max_load = UNSET
        else:
            max_load = self.max_load

        max_points = self.max_points

        start: dict[str, Any] | None | Unset
        if isinstance(self.start, Unset):
            start = UNSET
        elif isinstance(self.start, StartQ):
            start = self.start.to_dict()
        else:
            start = self.start

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "manipulator": manipulator,
            }
        )
        if arms is not UNSET:
            field_dict["arms"] = arms
        if boundary is not UNSET:
            field_dict["boundary"] = boundary
        if direction is not UNSET:
            field_dict["direction"] = direction
        if dpi is not UNSET:
            field_dict["dpi"] = dpi
        if format_ is not UNSET:
            field_dict["format"] = format_
        if max_load is not UNSET:
            field_dict["max_load"] = max_load
        if max_points is not UNSET:
            field_dict["max_points"] = max_points
        if start is not UNSET:
            field_dict["start"] = start

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.segmented_manipulator_in import SegmentedManipulatorIn  # noqa: PLC0415
        from ..models.start_q import StartQ  # noqa: PLC0415
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

        arms = d.pop("arms", UNSET)

        _boundary = d.pop("boundary", UNSET)
        boundary: PlotLimitLoadRequestBoundary | Unset
        if isinstance(_boundary, Unset):
            boundary = UNSET
        else:
            boundary = PlotLimitLoadRequestBoundary(_boundary)

        direction = cast(list[float], d.pop("direction", UNSET))

        dpi = d.pop("dpi", UNSET)

        def _parse_format_(data: object) -> None | PlotLimitLoadRequestFormatType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                format_type_0 = PlotLimitLoadRequestFormatType0(data)

                return format_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PlotLimitLoadRequestFormatType0 | Unset, data)

        format_ = _parse_format_(d.pop("format", UNSET))

        def _parse_max_load(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        max_load = _parse_max_load(d.pop("max_load", UNSET))

        max_points = d.pop("max_points", UNSET)

        def _parse_start(data: object) -> None | StartQ | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                start_type_0 = StartQ.from_dict(data)

                return start_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | StartQ | Unset, data)

        start = _parse_start(d.pop("start", UNSET))

        plot_limit_load_request = cls(
            manipulator=manipulator,
            arms=arms,
            boundary=boundary,
            direction=direction,
            dpi=dpi,
            format_=format_,
            max_load=max_load,
            max_points=max_points,
            start=start,
        )

        return plot_limit_load_request
