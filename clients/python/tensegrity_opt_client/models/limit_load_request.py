from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.limit_load_request_boundary import LimitLoadRequestBoundary
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.start_q import StartQ
    from ..models.uniform_manipulator_in import UniformManipulatorIn


T = TypeVar("T", bound="LimitLoadRequest")


@_attrs_define
class LimitLoadRequest:
    """The dead load where the branch from a rest configuration first loses stability (`tensegrity_opt.limit_load`).

    Attributes:
        manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
            (uniform) or {"segments": [...]}
        boundary (LimitLoadRequestBoundary | Unset): "free": the tip free, F = t d; "guided": y held, Fx = t d_x, Fy the
            reaction Default: LimitLoadRequestBoundary.FREE.
        direction (list[float] | Unset): the load's direction (normalised; [-1, 0] compresses)
        include_branch (bool | Unset): also return the traced path (`branch`) Default: False.
        max_load (float | None | Unset): stop there (force units); default 100 k c^2 / (2b)
        max_points (int | Unset): at most this many points per branch, the start included (2..5000; server limit
            TENSEGRITY_MAX_PATH_POINTS) Default: 4000.
        start (None | StartQ | Unset): {"q": [...]}: a rest configuration to start from; null: the least-energy rest
            configuration
    """

    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    boundary: LimitLoadRequestBoundary | Unset = LimitLoadRequestBoundary.FREE
    direction: list[float] | Unset = UNSET
    include_branch: bool | Unset = False
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

        boundary: str | Unset = UNSET
        if not isinstance(self.boundary, Unset):
            boundary = self.boundary.value

        direction: list[float] | Unset = UNSET
        if not isinstance(self.direction, Unset):
            direction = self.direction

        include_branch = self.include_branch

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
        if boundary is not UNSET:
            field_dict["boundary"] = boundary
        if direction is not UNSET:
            field_dict["direction"] = direction
        if include_branch is not UNSET:
            field_dict["include_branch"] = include_branch
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

        _boundary = d.pop("boundary", UNSET)
        boundary: LimitLoadRequestBoundary | Unset
        if isinstance(_boundary, Unset):
            boundary = UNSET
        else:
            boundary = LimitLoadRequestBoundary(_boundary)

        direction = cast(list[float], d.pop("direction", UNSET))

        include_branch = d.pop("include_branch", UNSET)

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

        limit_load_request = cls(
            manipulator=manipulator,
            boundary=boundary,
            direction=direction,
            include_branch=include_branch,
            max_load=max_load,
            max_points=max_points,
            start=start,
        )

        return limit_load_request
