from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.plot_shapes_request_format_type_0 import PlotShapesRequestFormatType0
from ..models.plot_shapes_request_spring_colors import PlotShapesRequestSpringColors
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.uniform_manipulator_in import UniformManipulatorIn


T = TypeVar("T", bound="PlotShapesRequest")


@_attrs_define
class PlotShapesRequest:
    """The chain drawn in every equilibrium, coloured by stability (Table 2's shapes).

    Attributes:
        dx (float): tip deflection along x (length units)
        manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
            (uniform) or {"segments": [...]}
        dpi (int | Unset): PNG resolution in dots per inch (30..200; default 120, the command line's too) Default: 120.
        dy (float | Unset): tip deflection along y (length units) Default: 0.0.
        format_ (None | PlotShapesRequestFormatType0 | Unset): "png" or "svg"; when absent the Accept header decides
            (image/svg+xml or image/png), PNG by default
        max_panels (int | Unset): draw at most this many equilibria, the lowest energies (1..24) Default: 24.
        spring_colors (PlotShapesRequestSpringColors | Unset): `state`: taut springs solid, pushing ones (linear law,
            shorter than their rest length) red dashed, slack ones grey dotted; `tension`: every spring coloured by its
            force Default: PlotShapesRequestSpringColors.STATE.
    """

    dx: float
    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    dpi: int | Unset = 120
    dy: float | Unset = 0.0
    format_: None | PlotShapesRequestFormatType0 | Unset = UNSET
    max_panels: int | Unset = 24
    spring_colors: PlotShapesRequestSpringColors | Unset = PlotShapesRequestSpringColors.STATE

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
        elif isinstance(self.format_, PlotShapesRequestFormatType0):
            format_ = self.format_.value
        else:
            format_ = self.format_

        max_panels = self.max_panels

        spring_colors: str | Unset = UNSET
        if not isinstance(self.spring_colors, Unset):
            spring_colors = self.spring_colors.value

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
        if max_panels is not UNSET:
            field_dict["max_panels"] = max_panels
        if spring_colors is not UNSET:
            field_dict["spring_colors"] = spring_colors

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

        def _parse_format_(data: object) -> None | PlotShapesRequestFormatType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                format_type_0 = PlotShapesRequestFormatType0(data)

                return format_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PlotShapesRequestFormatType0 | Unset, data)

        format_ = _parse_format_(d.pop("format", UNSET))

        max_panels = d.pop("max_panels", UNSET)

        _spring_colors = d.pop("spring_colors", UNSET)
        spring_colors: PlotShapesRequestSpringColors | Unset
        if isinstance(_spring_colors, Unset):
            spring_colors = UNSET
        else:
            spring_colors = PlotShapesRequestSpringColors(_spring_colors)

        plot_shapes_request = cls(
            dx=dx,
            manipulator=manipulator,
            dpi=dpi,
            dy=dy,
            format_=format_,
            max_panels=max_panels,
            spring_colors=spring_colors,
        )

        return plot_shapes_request
