from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.displacement_control_in import DisplacementControlIn
    from ..models.guided_control_in import GuidedControlIn
    from ..models.load_control_in import LoadControlIn
    from ..models.preload_control_in import PreloadControlIn
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.start_deflection import StartDeflection
    from ..models.start_q import StartQ
    from ..models.uniform_manipulator_in import UniformManipulatorIn
    from ..models.wall_control_in import WallControlIn


T = TypeVar("T", bound="BifurcationDiagramRequest")


@_attrs_define
class BifurcationDiagramRequest:
    """Every branch reached from the start through branch points (`tensegrity_opt.bifurcation_diagram`).

    Attributes:
        control (DisplacementControlIn | GuidedControlIn | LoadControlIn | PreloadControlIn | WallControlIn): what the
            continuation parameter t moves: {"kind": displacement | load | guided | wall | preload, ...}
            (tensegrity_opt.Control)
        manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
            (uniform) or {"segments": [...]}
        depth (int | Unset): branch switches followed (0..6) Default: 2.
        max_branches (int | Unset): at most this many branches (1..64) Default: 24.
        max_points (int | Unset): at most this many points per branch, the start included (2..5000; server limit
            TENSEGRITY_MAX_PATH_POINTS) Default: 1000.
        start (None | StartDeflection | StartQ | Unset): where t = 0 is: null (default) the least-energy rest
            configuration, {"q"} or {"dx", "dy"}
        t_max (float | None | Unset): stop where t reaches this (the control's unit)
        t_min (float | None | Unset): stop where t falls to this
    """

    control: DisplacementControlIn | GuidedControlIn | LoadControlIn | PreloadControlIn | WallControlIn
    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    depth: int | Unset = 2
    max_branches: int | Unset = 24
    max_points: int | Unset = 1000
    start: None | StartDeflection | StartQ | Unset = UNSET
    t_max: float | None | Unset = UNSET
    t_min: float | None | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.displacement_control_in import DisplacementControlIn  # noqa: PLC0415
        from ..models.guided_control_in import GuidedControlIn  # noqa: PLC0415
        from ..models.load_control_in import LoadControlIn  # noqa: PLC0415
        from ..models.start_deflection import StartDeflection  # noqa: PLC0415
        from ..models.start_q import StartQ  # noqa: PLC0415
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415
        from ..models.wall_control_in import WallControlIn  # noqa: PLC0415

        control: dict[str, Any]
        if isinstance(self.control, DisplacementControlIn):
            control = self.control.to_dict()
        elif isinstance(self.control, LoadControlIn):
            control = self.control.to_dict()
        elif isinstance(self.control, GuidedControlIn):
            control = self.control.to_dict()
        elif isinstance(self.control, WallControlIn):
            control = self.control.to_dict()
        else:
            control = self.control.to_dict()

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, UniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        depth = self.depth

        max_branches = self.max_branches

        max_points = self.max_points

        start: dict[str, Any] | None | Unset
        if isinstance(self.start, Unset):
            start = UNSET
        elif isinstance(self.start, StartQ):
            start = self.start.to_dict()
        elif isinstance(self.start, StartDeflection):
            start = self.start.to_dict()
        else:
            start = self.start

        t_max: float | None | Unset
        if isinstance(self.t_max, Unset):
            t_max = UNSET
        else:
            t_max = self.t_max

        t_min: float | None | Unset
        if isinstance(self.t_min, Unset):
            t_min = UNSET
        else:
            t_min = self.t_min

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "control": control,
                "manipulator": manipulator,
            }
        )
        if depth is not UNSET:
            field_dict["depth"] = depth
        if max_branches is not UNSET:
            field_dict["max_branches"] = max_branches
        if max_points is not UNSET:
            field_dict["max_points"] = max_points
        if start is not UNSET:
            field_dict["start"] = start
        if t_max is not UNSET:
            field_dict["t_max"] = t_max
        if t_min is not UNSET:
            field_dict["t_min"] = t_min

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.displacement_control_in import DisplacementControlIn  # noqa: PLC0415
        from ..models.guided_control_in import GuidedControlIn  # noqa: PLC0415
        from ..models.load_control_in import LoadControlIn  # noqa: PLC0415
        from ..models.preload_control_in import PreloadControlIn  # noqa: PLC0415
        from ..models.segmented_manipulator_in import SegmentedManipulatorIn  # noqa: PLC0415
        from ..models.start_deflection import StartDeflection  # noqa: PLC0415
        from ..models.start_q import StartQ  # noqa: PLC0415
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415
        from ..models.wall_control_in import WallControlIn  # noqa: PLC0415

        d = dict(src_dict)

        def _parse_control(
            data: object,
        ) -> DisplacementControlIn | GuidedControlIn | LoadControlIn | PreloadControlIn | WallControlIn:
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

        control = _parse_control(d.pop("control"))

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

        depth = d.pop("depth", UNSET)

        max_branches = d.pop("max_branches", UNSET)

        max_points = d.pop("max_points", UNSET)

        def _parse_start(data: object) -> None | StartDeflection | StartQ | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                start_type_0_type_0 = StartQ.from_dict(data)

                return start_type_0_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                start_type_0_type_1 = StartDeflection.from_dict(data)

                return start_type_0_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | StartDeflection | StartQ | Unset, data)

        start = _parse_start(d.pop("start", UNSET))

        def _parse_t_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        t_max = _parse_t_max(d.pop("t_max", UNSET))

        def _parse_t_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        t_min = _parse_t_min(d.pop("t_min", UNSET))

        bifurcation_diagram_request = cls(
            control=control,
            manipulator=manipulator,
            depth=depth,
            max_branches=max_branches,
            max_points=max_points,
            start=start,
            t_max=t_max,
            t_min=t_min,
        )

        return bifurcation_diagram_request
