from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.modes_request_tip_type_0 import ModesRequestTipType0
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.uniform_manipulator_in import UniformManipulatorIn


T = TypeVar("T", bound="ModesRequest")


@_attrs_define
class ModesRequest:
    """The vibration modes of an equilibrium: the least-energy stable one for a tip deflection (`dx`, `dy`: the tip
    held), or the local minimiser under a dead tip force (`fx`, `fy`: the tip loaded).

        Attributes:
            manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
                (uniform) or {"segments": [...]}
            dx (float | None | Unset):
            dy (float | None | Unset):
            fx (float | None | Unset): a dead tip force along x instead of the deflection (force units; < 0 compresses)
            fy (float | None | Unset): the dead tip force along y (force units)
            q0 (list[float] | None | Unset): optional nearby configuration
            tip (ModesRequestTipType0 | None | Unset): `held`: the modes with the tip kept where it is (tangent to the tip
                constraint); `loaded`: the tip free under its dead load. Default: as the equilibrium is posed (held for dx, dy;
                loaded for fx, fy)
    """

    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    dx: float | None | Unset = UNSET
    dy: float | None | Unset = UNSET
    fx: float | None | Unset = UNSET
    fy: float | None | Unset = UNSET
    q0: list[float] | None | Unset = UNSET
    tip: ModesRequestTipType0 | None | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, UniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        dx: float | None | Unset
        if isinstance(self.dx, Unset):
            dx = UNSET
        else:
            dx = self.dx

        dy: float | None | Unset
        if isinstance(self.dy, Unset):
            dy = UNSET
        else:
            dy = self.dy

        fx: float | None | Unset
        if isinstance(self.fx, Unset):
            fx = UNSET
        else:
            fx = self.fx

        fy: float | None | Unset
        if isinstance(self.fy, Unset):
            fy = UNSET
        else:
            fy = self.fy

        q0: list[float] | None | Unset
        if isinstance(self.q0, Unset):
            q0 = UNSET
        elif isinstance(self.q0, list):
            q0 = self.q0

        else:
            q0 = self.q0

        tip: None | str | Unset
        if isinstance(self.tip, Unset):
            tip = UNSET
        elif isinstance(self.tip, ModesRequestTipType0):
            tip = self.tip.value
        else:
            tip = self.tip

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "manipulator": manipulator,
            }
        )
        if dx is not UNSET:
            field_dict["dx"] = dx
        if dy is not UNSET:
            field_dict["dy"] = dy
        if fx is not UNSET:
            field_dict["fx"] = fx
        if fy is not UNSET:
            field_dict["fy"] = fy
        if q0 is not UNSET:
            field_dict["q0"] = q0
        if tip is not UNSET:
            field_dict["tip"] = tip

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

        def _parse_dx(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        dx = _parse_dx(d.pop("dx", UNSET))

        def _parse_dy(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        dy = _parse_dy(d.pop("dy", UNSET))

        def _parse_fx(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        fx = _parse_fx(d.pop("fx", UNSET))

        def _parse_fy(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        fy = _parse_fy(d.pop("fy", UNSET))

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

        def _parse_tip(data: object) -> ModesRequestTipType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                tip_type_0 = ModesRequestTipType0(data)

                return tip_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ModesRequestTipType0 | None | Unset, data)

        tip = _parse_tip(d.pop("tip", UNSET))

        modes_request = cls(
            manipulator=manipulator,
            dx=dx,
            dy=dy,
            fx=fx,
            fy=fy,
            q0=q0,
            tip=tip,
        )

        return modes_request
