from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.plot_curve_request_branch import PlotCurveRequestBranch
from ..models.plot_curve_request_format_type_0 import PlotCurveRequestFormatType0
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.deflection_range import DeflectionRange
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.uniform_manipulator_in import UniformManipulatorIn


T = TypeVar("T", bound="PlotCurveRequest")


@_attrs_define
class PlotCurveRequest:
    """Force-deflection curves Fx, Fy against dx with their jumps (Fig. 6).

    Attributes:
        dx (DeflectionRange | list[float]): deflections in the order to follow: a list or {start, stop, num} (at most
            501 points)
        manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
            (uniform) or {"segments": [...]}
        branch (PlotCurveRequestBranch | Unset): "all" also draws every branch found at the first deflected point
            (unstable dashed) Default: PlotCurveRequestBranch.STABLE.
        dpi (int | Unset): PNG resolution in dots per inch (30..200; default 120, the command line's too) Default: 120.
        dy (float | Unset): tip deflection along y, the same at every point Default: 0.0.
        format_ (None | PlotCurveRequestFormatType0 | Unset): "png" or "svg"; when absent the Accept header decides
            (image/svg+xml or image/png), PNG by default
    """

    dx: DeflectionRange | list[float]
    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    branch: PlotCurveRequestBranch | Unset = PlotCurveRequestBranch.STABLE
    dpi: int | Unset = 120
    dy: float | Unset = 0.0
    format_: None | PlotCurveRequestFormatType0 | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        dx: dict[str, Any] | list[float]
        if isinstance(self.dx, list):
            dx = self.dx

        else:
            dx = self.dx.to_dict()

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, UniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        branch: str | Unset = UNSET
        if not isinstance(self.branch, Unset):
            branch = self.branch.value

        dpi = self.dpi

        dy = self.dy

        format_: None | str | Unset
        if isinstance(self.format_, Unset):
            format_ = UNSET
        elif isinstance(self.format_, PlotCurveRequestFormatType0):
            format_ = self.format_.value
        else:
            format_ = self.format_

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "dx": dx,
                "manipulator": manipulator,
            }
        )
        if branch is not UNSET:
            field_dict["branch"] = branch
        if dpi is not UNSET:
            field_dict["dpi"] = dpi
        if dy is not UNSET:
            field_dict["dy"] = dy
        if format_ is not UNSET:
            field_dict["format"] = format_

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.deflection_range import DeflectionRange  # noqa: PLC0415
        from ..models.segmented_manipulator_in import SegmentedManipulatorIn  # noqa: PLC0415
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        d = dict(src_dict)

        def _parse_dx(data: object) -> DeflectionRange | list[float]:
            try:
                if not isinstance(data, list):
                    raise TypeError()
                dx_type_0 = cast(list[float], data)

                return dx_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            if not isinstance(data, dict):
                raise TypeError()
            dx_type_1 = DeflectionRange.from_dict(data)

            return dx_type_1

        dx = _parse_dx(d.pop("dx"))

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

        _branch = d.pop("branch", UNSET)
        branch: PlotCurveRequestBranch | Unset
        if isinstance(_branch, Unset):
            branch = UNSET
        else:
            branch = PlotCurveRequestBranch(_branch)

        dpi = d.pop("dpi", UNSET)

        dy = d.pop("dy", UNSET)

        def _parse_format_(data: object) -> None | PlotCurveRequestFormatType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                format_type_0 = PlotCurveRequestFormatType0(data)

                return format_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PlotCurveRequestFormatType0 | Unset, data)

        format_ = _parse_format_(d.pop("format", UNSET))

        plot_curve_request = cls(
            dx=dx,
            manipulator=manipulator,
            branch=branch,
            dpi=dpi,
            dy=dy,
            format_=format_,
        )

        return plot_curve_request
