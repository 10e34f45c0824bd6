from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.target import Target
    from ..models.uniform_manipulator_in import UniformManipulatorIn


T = TypeVar("T", bound="BatchEquilibriumRequest")


@_attrs_define
class BatchEquilibriumRequest:
    """Equilibria for a sequence of targets (a trajectory), solved in order.

    Attributes:
        manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
            (uniform) or {"segments": [...]}
        targets (list[Target]): targets in order (server limit TENSEGRITY_MAX_BATCH)
        continuation (bool | Unset): start each solve from the previous result (q0) Default: True.
        q0 (list[float] | None | Unset): optional configuration near the first target
    """

    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    targets: list[Target]
    continuation: bool | Unset = True
    q0: list[float] | None | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, UniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        targets = []
        for targets_item_data in self.targets:
            targets_item = targets_item_data.to_dict()
            targets.append(targets_item)

        continuation = self.continuation

        q0: list[float] | None | Unset
        if isinstance(self.q0, Unset):
            q0 = UNSET
        elif isinstance(self.q0, list):
            q0 = self.q0

        else:
            q0 = self.q0

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "manipulator": manipulator,
                "targets": targets,
            }
        )
        if continuation is not UNSET:
            field_dict["continuation"] = continuation
        if q0 is not UNSET:
            field_dict["q0"] = q0

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.segmented_manipulator_in import SegmentedManipulatorIn  # noqa: PLC0415
        from ..models.target import Target  # noqa: PLC0415
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

        targets = []
        _targets = d.pop("targets")
        for targets_item_data in _targets:
            targets_item = Target.from_dict(targets_item_data)

            targets.append(targets_item)

        continuation = d.pop("continuation", UNSET)

        def _parse_q0(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                q0_type_0 = cast(list[float], data)

                return q0_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        q0 = _parse_q0(d.pop("q0", UNSET))

        batch_equilibrium_request = cls(
            manipulator=manipulator,
            targets=targets,
            continuation=continuation,
            q0=q0,
        )

        return batch_equilibrium_request
