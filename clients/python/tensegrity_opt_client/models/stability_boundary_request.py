from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar

from attrs import define as _attrs_define

from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.displacement_control_in import DisplacementControlIn
    from ..models.guided_control_in import GuidedControlIn
    from ..models.load_control_in import LoadControlIn
    from ..models.preload_control_in import PreloadControlIn
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.uniform_manipulator_in import UniformManipulatorIn
    from ..models.wall_control_in import WallControlIn


T = TypeVar("T", bound="StabilityBoundaryRequest")


@_attrs_define
class StabilityBoundaryRequest:
    """The curve of folds or branch points in (parameter, t) (`tensegrity_opt.stability_boundary`).

    Attributes:
        manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
            (uniform) or {"segments": [...]}
        control (DisplacementControlIn | GuidedControlIn | LoadControlIn | PreloadControlIn | Unset | WallControlIn):
            the control of the one-parameter branches (default guided)
        max_points (int | Unset): at most this many points per branch, the start included (2..5000; server limit
            TENSEGRITY_MAX_PATH_POINTS) Default: 400.
        p_max (float | Unset): upper end of p Default: 0.1.
        p_min (float | Unset): the boundary is followed for p_min <= p <= p_max Default: -0.1.
        parameter (str | Unset): the second parameter p the boundary is followed in (the library's names; an unknown one
            is refused with invalid_parameter on `parameter`) Default: 'asymmetry'.
    """

    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    control: DisplacementControlIn | GuidedControlIn | LoadControlIn | PreloadControlIn | Unset | WallControlIn = UNSET
    max_points: int | Unset = 400
    p_max: float | Unset = 0.1
    p_min: float | Unset = -0.1
    parameter: str | Unset = "asymmetry"

    def to_dict(self) -> dict[str, Any]:
        from ..models.displacement_control_in import DisplacementControlIn  # noqa: PLC0415
        from ..models.guided_control_in import GuidedControlIn  # noqa: PLC0415
        from ..models.load_control_in import LoadControlIn  # noqa: PLC0415
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415
        from ..models.wall_control_in import WallControlIn  # noqa: PLC0415

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, UniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        control: dict[str, Any] | Unset
        if isinstance(self.control, Unset):
            control = UNSET
        elif isinstance(self.control, DisplacementControlIn):
            control = self.control.to_dict()
        elif isinstance(self.control, LoadControlIn):
            control = self.control.to_dict()
        elif isinstance(self.control, GuidedControlIn):
            control = self.control.to_dict()
        elif isinstance(self.control, WallControlIn):
            control = self.control.to_dict()
        else:
            control = self.control.to_dict()

        max_points = self.max_points

        p_max = self.p_max

        p_min = self.p_min

        parameter = self.parameter

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "manipulator": manipulator,
            }
        )
        if control is not UNSET:
            field_dict["control"] = control
        if max_points is not UNSET:
            field_dict["max_points"] = max_points
        if p_max is not UNSET:
            field_dict["p_max"] = p_max
        if p_min is not UNSET:
            field_dict["p_min"] = p_min
        if parameter is not UNSET:
            field_dict["parameter"] = parameter

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.displacement_control_in import DisplacementControlIn  # noqa: PLC0415
        from ..models.guided_control_in import GuidedControlIn  # noqa: PLC0415
        from ..models.load_control_in import LoadControlIn  # noqa: PLC0415
        from ..models.preload_control_in import PreloadControlIn  # noqa: PLC0415
        from ..models.segmented_manipulator_in import SegmentedManipulatorIn  # noqa: PLC0415
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415
        from ..models.wall_control_in import WallControlIn  # noqa: PLC0415

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

        def _parse_control(
            data: object,
        ) -> DisplacementControlIn | GuidedControlIn | LoadControlIn | PreloadControlIn | Unset | WallControlIn:
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                control_type_0 = DisplacementControlIn.from_dict(data)

                return control_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                control_type_1 = LoadControlIn.from_dict(data)

                return control_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                control_type_2 = GuidedControlIn.from_dict(data)

                return control_type_2
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                control_type_3 = WallControlIn.from_dict(data)

                return control_type_3
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            if not isinstance(data, dict):
                raise TypeError()
            control_type_4 = PreloadControlIn.from_dict(data)

            return control_type_4

        control = _parse_control(d.pop("control", UNSET))

        max_points = d.pop("max_points", UNSET)

        p_max = d.pop("p_max", UNSET)

        p_min = d.pop("p_min", UNSET)

        parameter = d.pop("parameter", UNSET)

        stability_boundary_request = cls(
            manipulator=manipulator,
            control=control,
            max_points=max_points,
            p_max=p_max,
            p_min=p_min,
            parameter=parameter,
        )

        return stability_boundary_request
