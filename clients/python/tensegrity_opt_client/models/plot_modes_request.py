from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.plot_modes_request_format_type_0 import PlotModesRequestFormatType0
from ..models.plot_modes_request_tip_type_0 import PlotModesRequestTipType0
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.uniform_manipulator_in import UniformManipulatorIn


T = TypeVar("T", bound="PlotModesRequest")


@_attrs_define
class PlotModesRequest:
    """The vibration modes of an equilibrium drawn: the chain displaced along each mode both ways.

    Attributes:
        manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
            (uniform) or {"segments": [...]}
        dpi (int | Unset): PNG resolution in dots per inch (30..200; default 120, the command line's too) Default: 120.
        dx (float | None | Unset):
        dy (float | None | Unset):
        excursion (float | Unset): each mode drawn with its largest joint excursion this many rad Default: 0.3.
        format_ (None | PlotModesRequestFormatType0 | Unset): "png" or "svg"; when absent the Accept header decides
            (image/svg+xml or image/png), PNG by default
        fx (float | None | Unset): a dead tip force along x instead of the deflection (force units; < 0 compresses)
        fy (float | None | Unset): the dead tip force along y (force units)
        max_panels (int | Unset): draw at most this many modes, the lowest (1..24) Default: 8.
        q0 (list[float] | None | Unset): optional nearby configuration
        tip (None | PlotModesRequestTipType0 | Unset): `held`: the modes with the tip kept where it is (tangent to the
            tip constraint); `loaded`: the tip free under its dead load. Default: as the equilibrium is posed (held for dx,
            dy; loaded for fx, fy)
    """

    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    dpi: int | Unset = 120
    dx: float | None | Unset = UNSET
    dy: float | None | Unset = UNSET
    excursion: float | Unset = 0.3
    format_: None | PlotModesRequestFormatType0 | Unset = UNSET
    fx: float | None | Unset = UNSET
    fy: float | None | Unset = UNSET
    max_panels: int | Unset = 8
    q0: list[float] | None | Unset = UNSET
    tip: None | PlotModesRequestTipType0 | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, UniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        dpi = self.dpi

        dx: float | None | Unset
        if isinstance(self.dx, Unset):
            dx = UNSET
        else:
            dx = self.dx

        dy: float | None | Unset
        if isinstance(self.dy, Unset):
            dy = UNSET
        else:
            dy = self.dy

        excursion = self.excursion

        format_: None | str | Unset
        if isinstance(self.format_, Unset):
            format_ = UNSET
        elif isinstance(self.format_, PlotModesRequestFormatType0):
            format_ = self.format_.value
        else:
            format_ = self.format_

        fx: float | None | Unset
        if isinstance(self.fx, Unset):
            fx = UNSET
        else:
            fx = self.fx

        fy: float | None | Unset
        if isinstance(self.fy, Unset):
            fy = UNSET
        else:
            fy = self.fy

        max_panels = self.max_panels

        q0: list[float] | None | Unset
        if isinstance(self.q0, Unset):
            q0 = UNSET
        elif isinstance(self.q0, list):
            q0 = self.q0

        else:
            q0 = self.q0

        tip: None | str | Unset
        if isinstance(self.tip, Unset):
            tip = UNSET
        elif isinstance(self.tip, PlotModesRequestTipType0):
            tip = self.tip.value
        else:
            tip = self.tip

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "manipulator": manipulator,
            }
        )
        if dpi is not UNSET:
            field_dict["dpi"] = dpi
        if dx is not UNSET:
            field_dict["dx"] = dx
        if dy is not UNSET:
            field_dict["dy"] = dy
        if excursion is not UNSET:
            field_dict["excursion"] = excursion
        if format_ is not UNSET:
            field_dict["format"] = format_
        if fx is not UNSET:
            field_dict["fx"] = fx
        if fy is not UNSET:
            field_dict["fy"] = fy
        if max_panels is not UNSET:
            field_dict["max_panels"] = max_panels
        if q0 is not UNSET:
            field_dict["q0"] = q0
        if tip is not UNSET:
            field_dict["tip"] = tip

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
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

        dpi = d.pop("dpi", UNSET)

        def _parse_dx(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        dx = _parse_dx(d.pop("dx", UNSET))

        def _parse_dy(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        dy = _parse_dy(d.pop("dy", UNSET))

        excursion = d.pop("excursion", UNSET)

        def _parse_format_(data: object) -> None | PlotModesRequestFormatType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                format_type_0 = PlotModesRequestFormatType0(data)

                return format_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PlotModesRequestFormatType0 | Unset, data)

        format_ = _parse_format_(d.pop("format", UNSET))

        def _parse_fx(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        fx = _parse_fx(d.pop("fx", UNSET))

        def _parse_fy(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        fy = _parse_fy(d.pop("fy", UNSET))

        max_panels = d.pop("max_panels", UNSET)

        def _parse_q0(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                q0_type_0 = cast(list[float], data)

                return q0_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        q0 = _parse_q0(d.pop("q0", UNSET))

        def _parse_tip(data: object) -> None | PlotModesRequestTipType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                tip_type_0 = PlotModesRequestTipType0(data)

                return tip_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PlotModesRequestTipType0 | Unset, data)

        tip = _parse_tip(d.pop("tip", UNSET))

        plot_modes_request = cls(
            manipulator=manipulator,
            dpi=dpi,
            dx=dx,
            dy=dy,
            excursion=excursion,
            format_=format_,
            fx=fx,
            fy=fy,
            max_panels=max_panels,
            q0=q0,
            tip=tip,
        )

        return plot_modes_request
