from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.imperfection_sensitivity_request_boundary import ImperfectionSensitivityRequestBoundary
from ..models.imperfection_sensitivity_request_imperfection import ImperfectionSensitivityRequestImperfection
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.uniform_manipulator_in import UniformManipulatorIn


T = TypeVar("T", bound="ImperfectionSensitivityRequest")


@_attrs_define
class ImperfectionSensitivityRequest:
    """The limit load of each imperfect chain's dead-load path from its rest shape, against the imperfection's
    amplitude (`tensegrity_opt.imperfection_sensitivity`).

        Attributes:
            amplitudes (list[float]): the amplitudes p, computed in this order (1..64; 0 is the given chain)
            manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
                (uniform) or {"segments": [...]}
            boundary (ImperfectionSensitivityRequestBoundary | Unset): "guided": y held at each imperfect chain's rest tip,
                Fx = t d_x; "free": F = t d Default: ImperfectionSensitivityRequestBoundary.GUIDED.
            direction (list[float] | Unset): the load's direction (normalised; [-1, 0] compresses)
            imperfection (ImperfectionSensitivityRequestImperfection | Unset): what p moves: asymmetry (every segment's rest
                lengths L1_0 + p, L2_0 - p: a pre-bend), L0 (both + p), a, b, k (both springs) Default:
                ImperfectionSensitivityRequestImperfection.ASYMMETRY.
            include_limit_loads (bool | Unset): also return each amplitude's limit load (`limit_loads`, as `/v1/limit-load`
                answers it) and `perfect` Default: False.
            max_load (float | None | Unset): stop each path there (force units); default 100 k c^2 / (2b)
            max_points (int | Unset): at most this many points per branch, the start included (2..5000; server limit
                TENSEGRITY_MAX_PATH_POINTS) Default: 4000.
    """

    amplitudes: list[float]
    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    boundary: ImperfectionSensitivityRequestBoundary | Unset = ImperfectionSensitivityRequestBoundary.GUIDED
    direction: list[float] | Unset = UNSET
    imperfection: ImperfectionSensitivityRequestImperfection | Unset = (
        ImperfectionSensitivityRequestImperfection.ASYMMETRY
    )
    include_limit_loads: bool | Unset = False
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

        imperfection: str | Unset = UNSET
        if not isinstance(self.imperfection, Unset):
            imperfection = self.imperfection.value

        include_limit_loads = self.include_limit_loads

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
        if imperfection is not UNSET:
            field_dict["imperfection"] = imperfection
        if include_limit_loads is not UNSET:
            field_dict["include_limit_loads"] = include_limit_loads
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
        boundary: ImperfectionSensitivityRequestBoundary | Unset
        if isinstance(_boundary, Unset):
            boundary = UNSET
        else:
            boundary = ImperfectionSensitivityRequestBoundary(_boundary)

        direction = cast(list[float], d.pop("direction", UNSET))

        _imperfection = d.pop("imperfection", UNSET)
        imperfection: ImperfectionSensitivityRequestImperfection | Unset
        if isinstance(_imperfection, Unset):
            imperfection = UNSET
        else:
            imperfection = ImperfectionSensitivityRequestImperfection(_imperfection)

        include_limit_loads = d.pop("include_limit_loads", UNSET)

        def _parse_max_load(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        max_load = _parse_max_load(d.pop("max_load", UNSET))

        max_points = d.pop("max_points", UNSET)

        imperfection_sensitivity_request = cls(
            amplitudes=amplitudes,
            manipulator=manipulator,
            boundary=boundary,
            direction=direction,
            imperfection=imperfection,
            include_limit_loads=include_limit_loads,
            max_load=max_load,
            max_points=max_points,
        )

        return imperfection_sensitivity_request
