from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.design_segmented_manipulator_in import DesignSegmentedManipulatorIn
    from ..models.design_uniform_manipulator_in import DesignUniformManipulatorIn
    from ..models.rest_length_bounds_in import RestLengthBoundsIn
    from ..models.stiffness_bound_in import StiffnessBoundIn
    from ..models.stiffness_bounds_in import StiffnessBoundsIn


T = TypeVar("T", bound="StiffnessDesignRequest")


@_attrs_define
class StiffnessDesignRequest:
    """Rest lengths for a stable pose at `target` with a shaped tip stiffness (`preloads_for_stiffness`).

    Attributes:
        manipulator (DesignSegmentedManipulatorIn | DesignUniformManipulatorIn): the chain (at most 60 segments): {"n",
            "a", "b", "k", "L0", "spring"} (uniform) or {"segments": [...]}
        target (list[float]): tip position [x, y] (length units)
        K_desired (list[list[float]] | None | Unset): the wanted 2 x 2 stiffness (symmetric; met exactly where
            reachable, else the closest in the Frobenius norm: `exact`, `residual`)
        bounds (list[float | list[float]] | None | RestLengthBoundsIn | Unset): bounds on the rest lengths; default (0.1
            b_min, 4 b_max)
        bounds_K (None | StiffnessBoundsIn | Unset): bounds on kxx, kxy, kyy
        eig_bounds (list[float | None] | None | StiffnessBoundIn | Unset): bounds [lo, hi] on both eigenvalues of K
        end_angle (float | None | Unset): the last link's absolute angle (rad), optional
        load (list[float] | Unset): the dead tip load [fx, fy] (force units)
        margin (float | Unset): required stability margin: the smallest eigenvalue of the Hessian of E - F . tip in the
            joint angles, absolute, in torque per radian (force x length / rad) like every margin of the API; for a margin
            relative to the chain's torque scale max k c^2, multiply by that scale Default: 0.001.
        max_starts (int | Unset): arm shapes tried (the target's equilibria, stable first) Default: 4.
    """

    manipulator: DesignSegmentedManipulatorIn | DesignUniformManipulatorIn
    target: list[float]
    K_desired: list[list[float]] | None | Unset = UNSET
    bounds: list[float | list[float]] | None | RestLengthBoundsIn | Unset = UNSET
    bounds_K: None | StiffnessBoundsIn | Unset = UNSET
    eig_bounds: list[float | None] | None | StiffnessBoundIn | Unset = UNSET
    end_angle: float | None | Unset = UNSET
    load: list[float] | Unset = UNSET
    margin: float | Unset = 0.001
    max_starts: int | Unset = 4

    def to_dict(self) -> dict[str, Any]:
        from ..models.design_uniform_manipulator_in import DesignUniformManipulatorIn  # noqa: PLC0415
        from ..models.rest_length_bounds_in import RestLengthBoundsIn  # noqa: PLC0415
        from ..models.stiffness_bound_in import StiffnessBoundIn  # noqa: PLC0415
        from ..models.stiffness_bounds_in import StiffnessBoundsIn  # noqa: PLC0415

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, DesignUniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        target = self.target

        K_desired: list[list[float]] | None | Unset
        if isinstance(self.K_desired, Unset):
            K_desired = UNSET
        elif isinstance(self.K_desired, list):
            K_desired = []
            for k_desired_type_0_item_data in self.K_desired:
                k_desired_type_0_item = k_desired_type_0_item_data

                K_desired.append(k_desired_type_0_item)

        else:
            K_desired = self.K_desired

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

        elif isinstance(self.bounds, RestLengthBoundsIn):
            bounds = self.bounds.to_dict()
        else:
            bounds = self.bounds

        bounds_K: dict[str, Any] | None | Unset
        if isinstance(self.bounds_K, Unset):
            bounds_K = UNSET
        elif isinstance(self.bounds_K, StiffnessBoundsIn):
            bounds_K = self.bounds_K.to_dict()
        else:
            bounds_K = self.bounds_K

        eig_bounds: dict[str, Any] | list[float | None] | None | Unset
        if isinstance(self.eig_bounds, Unset):
            eig_bounds = UNSET
        elif isinstance(self.eig_bounds, list):
            eig_bounds = []
            for eig_bounds_type_0_type_0_item_data in self.eig_bounds:
                eig_bounds_type_0_type_0_item: float | None
                eig_bounds_type_0_type_0_item = eig_bounds_type_0_type_0_item_data
                eig_bounds.append(eig_bounds_type_0_type_0_item)

        elif isinstance(self.eig_bounds, StiffnessBoundIn):
            eig_bounds = self.eig_bounds.to_dict()
        else:
            eig_bounds = self.eig_bounds

        end_angle: float | None | Unset
        if isinstance(self.end_angle, Unset):
            end_angle = UNSET
        else:
            end_angle = self.end_angle

        load: list[float] | Unset = UNSET
        if not isinstance(self.load, Unset):
            load = self.load

        margin = self.margin

        max_starts = self.max_starts

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "manipulator": manipulator,
                "target": target,
            }
        )
        if K_desired is not UNSET:
            field_dict["K_desired"] = K_desired
        if bounds is not UNSET:
            field_dict["bounds"] = bounds
        if bounds_K is not UNSET:
            field_dict["bounds_K"] = bounds_K
        if eig_bounds is not UNSET:
            field_dict["eig_bounds"] = eig_bounds
        if end_angle is not UNSET:
            field_dict["end_angle"] = end_angle
        if load is not UNSET:
            field_dict["load"] = load
        if margin is not UNSET:
            field_dict["margin"] = margin
        if max_starts is not UNSET:
            field_dict["max_starts"] = max_starts

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.design_segmented_manipulator_in import DesignSegmentedManipulatorIn  # noqa: PLC0415
        from ..models.design_uniform_manipulator_in import DesignUniformManipulatorIn  # noqa: PLC0415
        from ..models.rest_length_bounds_in import RestLengthBoundsIn  # noqa: PLC0415
        from ..models.stiffness_bound_in import StiffnessBoundIn  # noqa: PLC0415
        from ..models.stiffness_bounds_in import StiffnessBoundsIn  # noqa: PLC0415

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

        def _parse_k_desired(data: object) -> list[list[float]] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                k_desired_type_0 = []
                _k_desired_type_0 = data
                for k_desired_type_0_item_data in _k_desired_type_0:
                    k_desired_type_0_item = cast(list[float], k_desired_type_0_item_data)

                    k_desired_type_0.append(k_desired_type_0_item)

                return k_desired_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None | Unset, data)

        K_desired = _parse_k_desired(d.pop("K_desired", UNSET))

        def _parse_bounds(data: object) -> list[float | list[float]] | None | RestLengthBoundsIn | Unset:
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
                bounds_type_0_type_1 = RestLengthBoundsIn.from_dict(data)

                return bounds_type_0_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float | list[float]] | None | RestLengthBoundsIn | Unset, data)

        bounds = _parse_bounds(d.pop("bounds", UNSET))

        def _parse_bounds_k(data: object) -> None | StiffnessBoundsIn | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                bounds_k_type_0 = StiffnessBoundsIn.from_dict(data)

                return bounds_k_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | StiffnessBoundsIn | Unset, data)

        bounds_K = _parse_bounds_k(d.pop("bounds_K", UNSET))

        def _parse_eig_bounds(data: object) -> list[float | None] | None | StiffnessBoundIn | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                eig_bounds_type_0_type_0 = []
                _eig_bounds_type_0_type_0 = data
                for eig_bounds_type_0_type_0_item_data in _eig_bounds_type_0_type_0:

                    def _parse_eig_bounds_type_0_type_0_item(data: object) -> float | None:
                        if data is None:
                            return data
                        return cast(float | None, data)

                    eig_bounds_type_0_type_0_item = _parse_eig_bounds_type_0_type_0_item(
                        eig_bounds_type_0_type_0_item_data
                    )

                    eig_bounds_type_0_type_0.append(eig_bounds_type_0_type_0_item)

                return eig_bounds_type_0_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                eig_bounds_type_0_type_1 = StiffnessBoundIn.from_dict(data)

                return eig_bounds_type_0_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float | None] | None | StiffnessBoundIn | Unset, data)

        eig_bounds = _parse_eig_bounds(d.pop("eig_bounds", UNSET))

        def _parse_end_angle(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        end_angle = _parse_end_angle(d.pop("end_angle", UNSET))

        load = cast(list[float], d.pop("load", UNSET))

        margin = d.pop("margin", UNSET)

        max_starts = d.pop("max_starts", UNSET)

        stiffness_design_request = cls(
            manipulator=manipulator,
            target=target,
            K_desired=K_desired,
            bounds=bounds,
            bounds_K=bounds_K,
            eig_bounds=eig_bounds,
            end_angle=end_angle,
            load=load,
            margin=margin,
            max_starts=max_starts,
        )

        return stiffness_design_request
