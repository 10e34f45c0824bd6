from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.uniform_manipulator_in import UniformManipulatorIn


T = TypeVar("T", bound="StiffnessRequest")


@_attrs_define
class StiffnessRequest:
    """Cartesian tangent stiffness at the equilibrium `/v1/equilibrium` returns.

    Attributes:
        dx (float): tip deflection along x (length units)
        manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
            (uniform) or {"segments": [...]}
        dy (float | Unset): tip deflection along y (length units) Default: 0.0.
        q0 (list[float] | None | Unset): optional nearby configuration
    """

    dx: float
    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    dy: float | Unset = 0.0
    q0: list[float] | None | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        dx = self.dx

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, UniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        dy = self.dy

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
                "dx": dx,
                "manipulator": manipulator,
            }
        )
        if dy is not UNSET:
            field_dict["dy"] = dy
        if q0 is not UNSET:
            field_dict["q0"] = q0

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.segmented_manipulator_in import SegmentedManipulatorIn  # noqa: PLC0415
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        d = dict(src_dict)
        dx = d.pop("dx")

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

        dy = d.pop("dy", UNSET)

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

        stiffness_request = cls(
            dx=dx,
            manipulator=manipulator,
            dy=dy,
            q0=q0,
        )

        return stiffness_request
