from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.plot_holding_request_format_type_0 import PlotHoldingRequestFormatType0
from ..models.plot_holding_request_vary_item import PlotHoldingRequestVaryItem
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.design_segmented_manipulator_in import DesignSegmentedManipulatorIn
    from ..models.design_uniform_manipulator_in import DesignUniformManipulatorIn


T = TypeVar("T", bound="PlotHoldingRequest")


@_attrs_define
class PlotHoldingRequest:
    """The chain under its weight as its base turns: its sagged shapes and the least design holding it.

    Attributes:
        manipulator (DesignSegmentedManipulatorIn | DesignUniformManipulatorIn): the chain (at most 60 segments): {"n",
            "a", "b", "k", "L0", "spring"} (uniform) or {"segments": [...]}
        directions (int | Unset): gravity directions (base orientations) over a full turn (1..72) Default: 12.
        dpi (int | Unset): PNG resolution in dots per inch (30..200; default 120, the command line's too) Default: 120.
        format_ (None | PlotHoldingRequestFormatType0 | Unset): "png" or "svg"; when absent the Accept header decides
            (image/svg+xml or image/png), PNG by default
        margin (float | Unset): required stability margin: the smallest eigenvalue of the Hessian of E - F . tip in the
            joint angles, absolute, in torque per radian (force x length / rad) like every margin of the API; for a margin
            relative to the chain's torque scale max k c^2, multiply by that scale Default: 0.001.
        max_angle (float | None | Unset): the sag allowed (rad); default anywhere in range
        vary (list[PlotHoldingRequestVaryItem] | Unset): what the holding design varies (one of k, L0)
    """

    manipulator: DesignSegmentedManipulatorIn | DesignUniformManipulatorIn
    directions: int | Unset = 12
    dpi: int | Unset = 120
    format_: None | PlotHoldingRequestFormatType0 | Unset = UNSET
    margin: float | Unset = 0.001
    max_angle: float | None | Unset = UNSET
    vary: list[PlotHoldingRequestVaryItem] | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.design_uniform_manipulator_in import DesignUniformManipulatorIn  # noqa: PLC0415

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, DesignUniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        directions = self.directions

        dpi = self.dpi

        format_: None | str | Unset
        if isinstance(self.format_, Unset):
            format_ = UNSET
        elif isinstance(self.format_, PlotHoldingRequestFormatType0):
            format_ = self.format_.value
        else:
            format_ = self.format_

        margin = self.margin

        max_angle: float | None | Unset
        if isinstance(self.max_angle, Unset):
            max_angle = UNSET
        else:
            max_angle = self.max_angle

        vary: list[str] | Unset = UNSET
        if not isinstance(self.vary, Unset):
            vary = []
            for vary_item_data in self.vary:
                vary_item = vary_item_data.value
                vary.append(vary_item)

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "manipulator": manipulator,
            }
        )
        if directions is not UNSET:
            field_dict["directions"] = directions
        if dpi is not UNSET:
            field_dict["dpi"] = dpi
        if format_ is not UNSET:
            field_dict["format"] = format_
        if margin is not UNSET:
            field_dict["margin"] = margin
        if max_angle is not UNSET:
            field_dict["max_angle"] = max_angle
        if vary is not UNSET:
            field_dict["vary"] = vary

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.design_segmented_manipulator_in import DesignSegmentedManipulatorIn  # noqa: PLC0415
        from ..models.design_uniform_manipulator_in import DesignUniformManipulatorIn  # noqa: PLC0415

        d = dict(src_dict)

        def _parse_manipulator(data: object) -> DesignSegmentedManipulatorIn | DesignUniformManipulatorIn:
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                manipulator_type_0 = DesignUniformManipulatorIn.from_dict(data)

                return manipulator_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            if not isinstance(data, dict):
                raise TypeError()
            manipulator_type_1 = DesignSegmentedManipulatorIn.from_dict(data)

            return manipulator_type_1

        manipulator = _parse_manipulator(d.pop("manipulator"))

        directions = d.pop("directions", UNSET)

        dpi = d.pop("dpi", UNSET)

        def _parse_format_(data: object) -> None | PlotHoldingRequestFormatType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                format_type_0 = PlotHoldingRequestFormatType0(data)

                return format_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PlotHoldingRequestFormatType0 | Unset, data)

        format_ = _parse_format_(d.pop("format", UNSET))

        margin = d.pop("margin", UNSET)

        def _parse_max_angle(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        max_angle = _parse_max_angle(d.pop("max_angle", UNSET))

        _vary = d.pop("vary", UNSET)
        vary: list[PlotHoldingRequestVaryItem] | Unset = UNSET
        if _vary is not UNSET:
            vary = []
            for vary_item_data in _vary:
                vary_item = PlotHoldingRequestVaryItem(vary_item_data)

                vary.append(vary_item)

        plot_holding_request = cls(
            manipulator=manipulator,
            directions=directions,
            dpi=dpi,
            format_=format_,
            margin=margin,
            max_angle=max_angle,
            vary=vary,
        )

        return plot_holding_request
