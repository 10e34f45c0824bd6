from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.sweep_options_boundary import SweepOptionsBoundary
from ..models.sweep_options_method import SweepOptionsMethod
from ..models.sweep_options_vary_item import SweepOptionsVaryItem
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.sweep_options_bounds import SweepOptionsBounds
    from ..models.sweep_options_budget import SweepOptionsBudget
    from ..models.sweep_tension_in import SweepTensionIn


T = TypeVar("T", bound="SweepOptions")


@_attrs_define
class SweepOptions:
    """``boundary`` for buckling and design; ``method`` for atlas; the rest are ``maximize_critical_force``'s
    (design only).

        Attributes:
            K_min (float | Unset): design: lower bound on every joint stiffness
            boundary (SweepOptionsBoundary | Unset): tip boundary condition (default guided)
            bounds (SweepOptionsBounds | Unset): design: {name: [lo, hi] or {lo, hi}}, numbers or per-segment lists
            budget (SweepOptionsBudget | Unset): design: {name: total}, sum over the segments <= total
            method (SweepOptionsMethod | Unset): atlas only: how each target's equilibria are found, search (default) or
                homotopy (certified counts; chains up to the server's homotopy_max_segments)
            tension (list[float] | SweepTensionIn | Unset): design: [T_min, T_max] (or {lo, hi}) on the spring preloads at
                straight
            total_length (bool | float | Unset): design: total length 2 sum(b) (true: keep the initial one)
            vary (list[SweepOptionsVaryItem] | Unset): design: per-segment variables to optimise (default [k])
    """

    K_min: float | Unset = UNSET
    boundary: SweepOptionsBoundary | Unset = UNSET
    bounds: SweepOptionsBounds | Unset = UNSET
    budget: SweepOptionsBudget | Unset = UNSET
    method: SweepOptionsMethod | Unset = UNSET
    tension: list[float] | SweepTensionIn | Unset = UNSET
    total_length: bool | float | Unset = UNSET
    vary: list[SweepOptionsVaryItem] | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
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

        method: str | Unset = UNSET
        if not isinstance(self.method, Unset):
            method = self.method.value

        tension: dict[str, Any] | list[float] | Unset
        if isinstance(self.tension, Unset):
            tension = UNSET
        elif isinstance(self.tension, list):
            tension = self.tension

        else:
            tension = self.tension.to_dict()

        total_length: bool | float | Unset
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

        field_dict.update({})
        if K_min is not UNSET:
            field_dict["K_min"] = K_min
        if boundary is not UNSET:
            field_dict["boundary"] = boundary
        if bounds is not UNSET:
            field_dict["bounds"] = bounds
        if budget is not UNSET:
            field_dict["budget"] = budget
        if method is not UNSET:
            field_dict["method"] = method
        if tension is not UNSET:
            field_dict["tension"] = tension
        if total_length is not UNSET:
            field_dict["total_length"] = total_length
        if vary is not UNSET:
            field_dict["vary"] = vary

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.sweep_options_bounds import SweepOptionsBounds  # noqa: PLC0415
        from ..models.sweep_options_budget import SweepOptionsBudget  # noqa: PLC0415
        from ..models.sweep_tension_in import SweepTensionIn  # noqa: PLC0415

        d = dict(src_dict)
        K_min = d.pop("K_min", UNSET)

        _boundary = d.pop("boundary", UNSET)
        boundary: SweepOptionsBoundary | Unset
        if isinstance(_boundary, Unset):
            boundary = UNSET
        else:
            boundary = SweepOptionsBoundary(_boundary)

        _bounds = d.pop("bounds", UNSET)
        bounds: SweepOptionsBounds | Unset
        if isinstance(_bounds, Unset):
            bounds = UNSET
        else:
            bounds = SweepOptionsBounds.from_dict(_bounds)

        _budget = d.pop("budget", UNSET)
        budget: SweepOptionsBudget | Unset
        if isinstance(_budget, Unset):
            budget = UNSET
        else:
            budget = SweepOptionsBudget.from_dict(_budget)

        _method = d.pop("method", UNSET)
        method: SweepOptionsMethod | Unset
        if isinstance(_method, Unset):
            method = UNSET
        else:
            method = SweepOptionsMethod(_method)

        def _parse_tension(data: object) -> list[float] | SweepTensionIn | Unset:
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                tension_type_0 = cast(list[float], data)

                return tension_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            if not isinstance(data, dict):
                raise TypeError()
            tension_type_1 = SweepTensionIn.from_dict(data)

            return tension_type_1

        tension = _parse_tension(d.pop("tension", UNSET))

        def _parse_total_length(data: object) -> bool | float | Unset:
            if isinstance(data, Unset):
                return data
            return cast(bool | float | Unset, data)

        total_length = _parse_total_length(d.pop("total_length", UNSET))

        _vary = d.pop("vary", UNSET)
        vary: list[SweepOptionsVaryItem] | Unset = UNSET
        if _vary is not UNSET:
            vary = []
            for vary_item_data in _vary:
                vary_item = SweepOptionsVaryItem(vary_item_data)

                vary.append(vary_item)

        sweep_options = cls(
            K_min=K_min,
            boundary=boundary,
            bounds=bounds,
            budget=budget,
            method=method,
            tension=tension,
            total_length=total_length,
            vary=vary,
        )

        return sweep_options
