from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.uniform_manipulator_in import UniformManipulatorIn


T = TypeVar("T", bound="EnergyLandscapeRequest")


@_attrs_define
class EnergyLandscapeRequest:
    """Energy over a grid of two joint angles, the other two from inverse kinematics (n = 4 only).

    Attributes:
        dx (float): tip deflection along x (length units)
        manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
            (uniform) or {"segments": [...]}
        dy (float | Unset): tip deflection along y (length units) Default: 0.0.
        grid (int | Unset): points per axis (2..201) Default: 51.
        pair (list[int] | Unset): the two grid joints, 0-based and different
        span (float | None | Unset): half-width of both axes (rad); default: the smaller joint limit of the pair
    """

    dx: float
    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    dy: float | Unset = 0.0
    grid: int | Unset = 51
    pair: list[int] | Unset = UNSET
    span: float | None | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        dx = self.dx

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, UniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        dy = self.dy

        grid = self.grid

        pair: list[int] | Unset = UNSET
        if not isinstance(self.pair, Unset):
            pair = self.pair

        span: float | None | Unset
        if isinstance(self.span, Unset):
            span = UNSET
        else:
            span = self.span

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "dx": dx,
                "manipulator": manipulator,
            }
        )
        if dy is not UNSET:
            field_dict["dy"] = dy
        if grid is not UNSET:
            field_dict["grid"] = grid
        if pair is not UNSET:
            field_dict["pair"] = pair
        if span is not UNSET:
            field_dict["span"] = span

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

        grid = d.pop("grid", UNSET)

        pair = cast(list[int], d.pop("pair", UNSET))

        def _parse_span(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        span = _parse_span(d.pop("span", UNSET))

        energy_landscape_request = cls(
            dx=dx,
            manipulator=manipulator,
            dy=dy,
            grid=grid,
            pair=pair,
            span=span,
        )

        return energy_landscape_request
