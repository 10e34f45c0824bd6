from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.preloads_for_load_request_boundary import PreloadsForLoadRequestBoundary
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.bounds_in import BoundsIn
    from ..models.design_segmented_manipulator_in import DesignSegmentedManipulatorIn
    from ..models.design_uniform_manipulator_in import DesignUniformManipulatorIn


T = TypeVar("T", bound="PreloadsForLoadRequest")


@_attrs_define
class PreloadsForLoadRequest:
    """The smallest change of the rest lengths L0 making the critical load at least `required`.

    Attributes:
        manipulator (DesignSegmentedManipulatorIn | DesignUniformManipulatorIn): the chain (at most 60 segments): {"n",
            "a", "b", "k", "L0", "spring"} (uniform) or {"segments": [...]}
        required (float): required critical compressive load (force units)
        boundary (PreloadsForLoadRequestBoundary | Unset):  Default: PreloadsForLoadRequestBoundary.GUIDED.
        bounds (BoundsIn | list[float | list[float]] | None | Unset): bounds on every L0; default (0.05 * 2b, 2b)
    """

    manipulator: DesignSegmentedManipulatorIn | DesignUniformManipulatorIn
    required: float
    boundary: PreloadsForLoadRequestBoundary | Unset = PreloadsForLoadRequestBoundary.GUIDED
    bounds: BoundsIn | list[float | list[float]] | None | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.bounds_in import BoundsIn  # noqa: PLC0415
        from ..models.design_uniform_manipulator_in import DesignUniformManipulatorIn  # noqa: PLC0415

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, DesignUniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        required = self.required

        boundary: str | Unset = UNSET
        if not isinstance(self.boundary, Unset):
            boundary = self.boundary.value

        bounds: dict[str, Any] | list[float | list[float]] | None | Unset
        if isinstance(self.bounds, Unset):
            bounds = UNSET
        elif isinstance(self.bounds, list):
            bounds = []
            for bounds_type_0_type_0_item_data in self.bounds:
                bounds_type_0_type_0_item: float | list[float]
                if isinstance(bounds_type_0_type_0_item_data, list):
                    bounds_type_0_type_0_item = bounds_type_0_type_0_item_data

                else:
                    bounds_type_0_type_0_item = bounds_type_0_type_0_item_data
                bounds.append(bounds_type_0_type_0_item)

        elif isinstance(self.bounds, BoundsIn):
            bounds = self.bounds.to_dict()
        else:
            bounds = self.bounds

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "manipulator": manipulator,
                "required": required,
            }
        )
        if boundary is not UNSET:
            field_dict["boundary"] = boundary
        if bounds is not UNSET:
            field_dict["bounds"] = bounds

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.bounds_in import BoundsIn  # noqa: PLC0415
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

        required = d.pop("required")

        _boundary = d.pop("boundary", UNSET)
        boundary: PreloadsForLoadRequestBoundary | Unset
        if isinstance(_boundary, Unset):
            boundary = UNSET
        else:
            boundary = PreloadsForLoadRequestBoundary(_boundary)

        def _parse_bounds(data: object) -> BoundsIn | list[float | list[float]] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                bounds_type_0_type_0 = []
                _bounds_type_0_type_0 = data
                for bounds_type_0_type_0_item_data in _bounds_type_0_type_0:

                    def _parse_bounds_type_0_type_0_item(data: object) -> float | list[float]:
                        try:
                            if not isinstance(data, list):
                                raise TypeError()
                            bounds_type_0_type_0_item_type_1 = cast(list[float], data)

                            return bounds_type_0_type_0_item_type_1
                        except (TypeError, ValueError, AttributeError, KeyError):
                            pass
                        return cast(float | list[float], data)

                    bounds_type_0_type_0_item = _parse_bounds_type_0_type_0_item(bounds_type_0_type_0_item_data)

                    bounds_type_0_type_0.append(bounds_type_0_type_0_item)

                return bounds_type_0_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                bounds_type_0_type_1 = BoundsIn.from_dict(data)

                return bounds_type_0_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(BoundsIn | list[float | list[float]] | None | Unset, data)

        bounds = _parse_bounds(d.pop("bounds", UNSET))

        preloads_for_load_request = cls(
            manipulator=manipulator,
            required=required,
            boundary=boundary,
            bounds=bounds,
        )

        return preloads_for_load_request
