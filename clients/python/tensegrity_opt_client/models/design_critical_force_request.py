from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.design_critical_force_request_boundary import DesignCriticalForceRequestBoundary
from ..models.design_critical_force_request_vary_item import DesignCriticalForceRequestVaryItem
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.design_critical_force_request_bounds import DesignCriticalForceRequestBounds
    from ..models.design_critical_force_request_budget import DesignCriticalForceRequestBudget
    from ..models.design_segmented_manipulator_in import DesignSegmentedManipulatorIn
    from ..models.design_uniform_manipulator_in import DesignUniformManipulatorIn
    from ..models.tension_bounds_in import TensionBoundsIn


T = TypeVar("T", bound="DesignCriticalForceRequest")


@_attrs_define
class DesignCriticalForceRequest:
    """Maximise the critical load over per-segment design variables.

    Attributes:
        manipulator (DesignSegmentedManipulatorIn | DesignUniformManipulatorIn): the chain (at most 60 segments): {"n",
            "a", "b", "k", "L0", "spring"} (uniform) or {"segments": [...]}
        K_min (float | None | Unset): lower bound on every joint stiffness K_i
        boundary (DesignCriticalForceRequestBoundary | Unset):  Default: DesignCriticalForceRequestBoundary.GUIDED.
        bounds (DesignCriticalForceRequestBounds | Unset): bounds per variable; default (x0 / 10, 10 x0)
        budget (DesignCriticalForceRequestBudget | Unset): cap on the sum over the segments
        tension (list[float] | None | TensionBoundsIn | Unset):
        total_length (bool | float | None | Unset):
        vary (list[DesignCriticalForceRequestVaryItem] | Unset): per-segment variables to optimise
    """

    manipulator: DesignSegmentedManipulatorIn | DesignUniformManipulatorIn
    K_min: float | None | Unset = UNSET
    boundary: DesignCriticalForceRequestBoundary | Unset = DesignCriticalForceRequestBoundary.GUIDED
    bounds: DesignCriticalForceRequestBounds | Unset = UNSET
    budget: DesignCriticalForceRequestBudget | Unset = UNSET
    tension: list[float] | None | TensionBoundsIn | Unset = UNSET
    total_length: bool | float | None | Unset = UNSET
    vary: list[DesignCriticalForceRequestVaryItem] | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.design_uniform_manipulator_in import DesignUniformManipulatorIn  # noqa: PLC0415
        from ..models.tension_bounds_in import TensionBoundsIn  # noqa: PLC0415

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, DesignUniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        K_min: float | None | Unset
        if isinstance(self.K_min, Unset):
            K_min = UNSET
        else:
            K_min = self.K_min

        boundary: str | Unset = UNSET
        if not isinstance(self.boundary, Unset):
            boundary = self.boundary.value

        bounds: dict[str, Any] | Unset = UNSET
        if not isinstance(self.bounds, Unset):
            bounds = self.bounds.to_dict()

        budget: dict[str, Any] | Unset = UNSET
        if not isinstance(self.budget, Unset):
            budget = self.budget.to_dict()

        tension: dict[str, Any] | list[float] | None | Unset
        if isinstance(self.tension, Unset):
            tension = UNSET
        elif isinstance(self.tension, list):
            tension = self.tension

        elif isinstance(self.tension, TensionBoundsIn):
            tension = self.tension.to_dict()
        else:
            tension = self.tension

        total_length: bool | float | None | Unset
        if isinstance(self.total_length, Unset):
            total_length = UNSET
        else:
            total_length = self.total_length

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
        if K_min is not UNSET:
            field_dict["K_min"] = K_min
        if boundary is not UNSET:
            field_dict["boundary"] = boundary
        if bounds is not UNSET:
            field_dict["bounds"] = bounds
        if budget is not UNSET:
            field_dict["budget"] = budget
        if tension is not UNSET:
            field_dict["tension"] = tension
        if total_length is not UNSET:
            field_dict["total_length"] = total_length
        if vary is not UNSET:
            field_dict["vary"] = vary

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.design_critical_force_request_bounds import DesignCriticalForceRequestBounds  # noqa: PLC0415
        from ..models.design_critical_force_request_budget import DesignCriticalForceRequestBudget  # noqa: PLC0415
        from ..models.design_segmented_manipulator_in import DesignSegmentedManipulatorIn  # noqa: PLC0415
        from ..models.design_uniform_manipulator_in import DesignUniformManipulatorIn  # noqa: PLC0415
        from ..models.tension_bounds_in import TensionBoundsIn  # noqa: PLC0415

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

        def _parse_k_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        K_min = _parse_k_min(d.pop("K_min", UNSET))

        _boundary = d.pop("boundary", UNSET)
        boundary: DesignCriticalForceRequestBoundary | Unset
        if isinstance(_boundary, Unset):
            boundary = UNSET
        else:
            boundary = DesignCriticalForceRequestBoundary(_boundary)

        _bounds = d.pop("bounds", UNSET)
        bounds: DesignCriticalForceRequestBounds | Unset
        if isinstance(_bounds, Unset):
            bounds = UNSET
        else:
            bounds = DesignCriticalForceRequestBounds.from_dict(_bounds)

        _budget = d.pop("budget", UNSET)
        budget: DesignCriticalForceRequestBudget | Unset
        if isinstance(_budget, Unset):
            budget = UNSET
        else:
            budget = DesignCriticalForceRequestBudget.from_dict(_budget)

        def _parse_tension(data: object) -> list[float] | None | TensionBoundsIn | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                tension_type_0_type_0 = cast(list[float], data)

                return tension_type_0_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                tension_type_0_type_1 = TensionBoundsIn.from_dict(data)

                return tension_type_0_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | TensionBoundsIn | Unset, data)

        tension = _parse_tension(d.pop("tension", UNSET))

        def _parse_total_length(data: object) -> bool | float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | float | None | Unset, data)

        total_length = _parse_total_length(d.pop("total_length", UNSET))

        _vary = d.pop("vary", UNSET)
        vary: list[DesignCriticalForceRequestVaryItem] | Unset = UNSET
        if _vary is not UNSET:
            vary = []
            for vary_item_data in _vary:
                vary_item = DesignCriticalForceRequestVaryItem(vary_item_data)

                vary.append(vary_item)

        design_critical_force_request = cls(
            manipulator=manipulator,
            K_min=K_min,
            boundary=boundary,
            bounds=bounds,
            budget=budget,
            tension=tension,
            total_length=total_length,
            vary=vary,
        )

        return design_critical_force_request
