from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.uniform_manipulator_in import UniformManipulatorIn


T = TypeVar("T", bound="ForceEstimateRequest")


@_attrs_define
class ForceEstimateRequest:
    """The tip force from measured joint angles (`tensegrity_opt.estimate_tip_force`).

    Attributes:
        manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
            (uniform) or {"segments": [...]}
        q_measured (list[float | None]): joint angles (rad): all n (entries at unmeasured joints only start the solver;
            null there: 0), or the k measured ones in joint order; each inside the physical range |q_i| < pi - 2 beta_i
        measured (list[bool] | list[int] | None | Unset):
        sigma_q (float | list[float] | list[list[float]] | None | Unset): the angle noise (see the schema); null: the
            plain least-squares estimate, no statistics
    """

    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    q_measured: list[float | None]
    measured: list[bool] | list[int] | None | Unset = UNSET
    sigma_q: float | list[float] | list[list[float]] | None | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, UniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        q_measured = []
        for q_measured_item_data in self.q_measured:
            q_measured_item: float | None
            q_measured_item = q_measured_item_data
            q_measured.append(q_measured_item)

        measured: list[bool] | list[int] | None | Unset
        if isinstance(self.measured, Unset):
            measured = UNSET
        elif isinstance(self.measured, list):
            measured = self.measured

        elif isinstance(self.measured, list):
            measured = self.measured

        else:
            measured = self.measured

        sigma_q: float | list[float] | list[list[float]] | None | Unset
        if isinstance(self.sigma_q, Unset):
            sigma_q = UNSET
        elif isinstance(self.sigma_q, list):
            sigma_q = self.sigma_q

        elif isinstance(self.sigma_q, list):
            sigma_q = []
            for sigma_q_type_0_type_2_item_data in self.sigma_q:
                sigma_q_type_0_type_2_item = sigma_q_type_0_type_2_item_data

                sigma_q.append(sigma_q_type_0_type_2_item)

        else:
            sigma_q = self.sigma_q

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "manipulator": manipulator,
                "q_measured": q_measured,
            }
        )
        if measured is not UNSET:
            field_dict["measured"] = measured
        if sigma_q is not UNSET:
            field_dict["sigma_q"] = sigma_q

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.segmented_manipulator_in import SegmentedManipulatorIn  # noqa: PLC0415
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

        q_measured = []
        _q_measured = d.pop("q_measured")
        for q_measured_item_data in _q_measured:

            def _parse_q_measured_item(data: object) -> float | None:
                if data is None:
                    return data
                return cast(float | None, data)

            q_measured_item = _parse_q_measured_item(q_measured_item_data)

            q_measured.append(q_measured_item)

        def _parse_measured(data: object) -> list[bool] | list[int] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                measured_type_0_type_0 = cast(list[bool], data)

                return measured_type_0_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, list):
                    raise TypeError()
                measured_type_0_type_1 = cast(list[int], data)

                return measured_type_0_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[bool] | list[int] | None | Unset, data)

        measured = _parse_measured(d.pop("measured", UNSET))

        def _parse_sigma_q(data: object) -> float | list[float] | list[list[float]] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                sigma_q_type_0_type_1 = cast(list[float], data)

                return sigma_q_type_0_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, list):
                    raise TypeError()
                sigma_q_type_0_type_2 = []
                _sigma_q_type_0_type_2 = data
                for sigma_q_type_0_type_2_item_data in _sigma_q_type_0_type_2:
                    sigma_q_type_0_type_2_item = cast(list[float], sigma_q_type_0_type_2_item_data)

                    sigma_q_type_0_type_2.append(sigma_q_type_0_type_2_item)

                return sigma_q_type_0_type_2
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(float | list[float] | list[list[float]] | None | Unset, data)

        sigma_q = _parse_sigma_q(d.pop("sigma_q", UNSET))

        force_estimate_request = cls(
            manipulator=manipulator,
            q_measured=q_measured,
            measured=measured,
            sigma_q=sigma_q,
        )

        return force_estimate_request
