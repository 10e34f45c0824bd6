from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.preloads_request_objective import PreloadsRequestObjective
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.bounds_in import BoundsIn
    from ..models.design_segmented_manipulator_in import DesignSegmentedManipulatorIn
    from ..models.design_uniform_manipulator_in import DesignUniformManipulatorIn


T = TypeVar("T", bound="PreloadsRequest")


@_attrs_define
class PreloadsRequest:
    """Rest lengths putting the tip at a target, stably, under a tip load.

    Attributes:
        manipulator (DesignSegmentedManipulatorIn | DesignUniformManipulatorIn): the chain (at most 60 segments): {"n",
            "a", "b", "k", "L0", "spring"} (uniform) or {"segments": [...]}
        target (list[float]): tip position [x, y] (length units)
        bounds (BoundsIn | list[float | list[float]] | None | Unset): bounds on every rest length; default (0.1 b_min, 4
            b_max)
        end_angle (float | None | Unset): absolute angle of the last link (rad), optional
        load (list[float] | Unset): the dead tip load [fx, fy] (force units)
        margin (float | Unset): required stability margin: the smallest eigenvalue of the Hessian of E - F . tip in the
            joint angles, absolute, in torque per radian (force x length / rad) like every margin of the API; for a margin
            relative to the chain's torque scale max k c^2, multiply by that scale Default: 0.001.
        objective (PreloadsRequestObjective | Unset): nominal: least change from the chain's own rest lengths (the
            library's objective `change`); margin: largest stability margin; energy: least spring energy Default:
            PreloadsRequestObjective.NOMINAL.
        taut (bool | Unset): keep every spring in tension (L > L0, strictly) at every designed pose; required for a
            chain with tension-only springs (there the laws agree; the moves between a plan's poses are verified under the
            laws) Default: False.
    """

    manipulator: DesignSegmentedManipulatorIn | DesignUniformManipulatorIn
    target: list[float]
    bounds: BoundsIn | list[float | list[float]] | None | Unset = UNSET
    end_angle: float | None | Unset = UNSET
    load: list[float] | Unset = UNSET
    margin: float | Unset = 0.001
    objective: PreloadsRequestObjective | Unset = PreloadsRequestObjective.NOMINAL
    taut: bool | Unset = False

    def to_dict(self) -> dict[str, Any]:
        from ..models.bounds_in import BoundsIn  # noqa: PLC0415
        from ..models.design_uniform_manipulator_in import DesignUniformManipulatorIn  # noqa: PLC0415

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, DesignUniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        target = self.target

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

        end_angle: float | None | Unset
        if isinstance(self.end_angle, Unset):
            end_angle = UNSET
        else:
            end_angle = self.end_angle

        load: list[float] | Unset = UNSET
        if not isinstance(self.load, Unset):
            load = self.load

        margin = self.margin

        objective: str | Unset = UNSET
        if not isinstance(self.objective, Unset):
            objective = self.objective.value

        taut = self.taut

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "manipulator": manipulator,
                "target": target,
            }
        )
        if bounds is not UNSET:
            field_dict["bounds"] = bounds
        if end_angle is not UNSET:
            field_dict["end_angle"] = end_angle
        if load is not UNSET:
            field_dict["load"] = load
        if margin is not UNSET:
            field_dict["margin"] = margin
        if objective is not UNSET:
            field_dict["objective"] = objective
        if taut is not UNSET:
            field_dict["taut"] = taut

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

        target = cast(list[float], d.pop("target"))

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

        def _parse_end_angle(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        end_angle = _parse_end_angle(d.pop("end_angle", UNSET))

        load = cast(list[float], d.pop("load", UNSET))

        margin = d.pop("margin", UNSET)

        _objective = d.pop("objective", UNSET)
        objective: PreloadsRequestObjective | Unset
        if isinstance(_objective, Unset):
            objective = UNSET
        else:
            objective = PreloadsRequestObjective(_objective)

        taut = d.pop("taut", UNSET)

        preloads_request = cls(
            manipulator=manipulator,
            target=target,
            bounds=bounds,
            end_angle=end_angle,
            load=load,
            margin=margin,
            objective=objective,
            taut=taut,
        )

        return preloads_request
