from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.load_capacity_request_boundary import LoadCapacityRequestBoundary
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.start_q import StartQ
    from ..models.uniform_manipulator_in import UniformManipulatorIn


T = TypeVar("T", bound="LoadCapacityRequest")


@_attrs_define
class LoadCapacityRequest:
    """The largest extra tip load per direction before a stable pose loses stability (`load_capacity`).

    Attributes:
        manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
            (uniform) or {"segments": [...]}
        base (list[float] | Unset): the load the pose carries [fx, fy] (force units)
        boundary (LoadCapacityRequestBoundary | Unset):  Default: LoadCapacityRequestBoundary.FREE.
        directions (int | Unset): how many evenly spaced directions Default: 36.
        max_load (float | Unset): each path is followed up to this extra load (force units) Default: 10.0.
        start (None | StartQ | Unset): {"q": [...]}: the pose (a stable equilibrium under `base`); null: the least-
            energy rest configuration
    """

    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    base: list[float] | Unset = UNSET
    boundary: LoadCapacityRequestBoundary | Unset = LoadCapacityRequestBoundary.FREE
    directions: int | Unset = 36
    max_load: float | Unset = 10.0
    start: None | StartQ | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.start_q import StartQ  # noqa: PLC0415
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, UniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        base: list[float] | Unset = UNSET
        if not isinstance(self.base, Unset):
            base = self.base

        boundary: str | Unset = UNSET
        if not isinstance(self.boundary, Unset):
            boundary = self.boundary.value

        directions = self.directions

        max_load = self.max_load

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
        if base is not UNSET:
            field_dict["base"] = base
        if boundary is not UNSET:
            field_dict["boundary"] = boundary
        if directions is not UNSET:
            field_dict["directions"] = directions
        if max_load is not UNSET:
            field_dict["max_load"] = max_load
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

        base = cast(list[float], d.pop("base", UNSET))

        _boundary = d.pop("boundary", UNSET)
        boundary: LoadCapacityRequestBoundary | Unset
        if isinstance(_boundary, Unset):
            boundary = UNSET
        else:
            boundary = LoadCapacityRequestBoundary(_boundary)

        directions = d.pop("directions", UNSET)

        max_load = d.pop("max_load", UNSET)

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

        load_capacity_request = cls(
            manipulator=manipulator,
            base=base,
            boundary=boundary,
            directions=directions,
            max_load=max_load,
            start=start,
        )

        return load_capacity_request
