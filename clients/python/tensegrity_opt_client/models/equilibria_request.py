from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.equilibria_request_method import EquilibriaRequestMethod
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.uniform_manipulator_in import UniformManipulatorIn


T = TypeVar("T", bound="EquilibriaRequest")


@_attrs_define
class EquilibriaRequest:
    """Every equilibrium (minima, saddles, maxima) for a tip deflection.

    Attributes:
        dx (float): tip deflection along x (length units)
        manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
            (uniform) or {"segments": [...]}
        dy (float | Unset): tip deflection along y (length units) Default: 0.0.
        method (EquilibriaRequestMethod | Unset): `search`: multi-start Newton (any n; complete in practice, not
            certified); `homotopy`: PHCpack's polyhedral homotopy on the polynomial KKT system, every equilibrium certified
            (chains up to the server's `homotopy_max_segments`, default 5; seconds; needs the `phcpack` package on the
            server, else 503 `homotopy_unavailable`) Default: EquilibriaRequestMethod.SEARCH.
        stops (bool | None | Unset): include the equilibria resting on a joint's stop (`at_stop`, `contact_torques`);
            null: yes for a chain with tension-only springs, no under the linear law (the open range). Under the linear law
            `true` adds Newton with each joint held on either stop (search) or one system per free/stop pattern (homotopy,
            certified, n <= 5)
    """

    dx: float
    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    dy: float | Unset = 0.0
    method: EquilibriaRequestMethod | Unset = EquilibriaRequestMethod.SEARCH
    stops: bool | None | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        dx = self.dx

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, UniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        dy = self.dy

        method: str | Unset = UNSET
        if not isinstance(self.method, Unset):
            method = self.method.value

        stops: bool | None | Unset
        if isinstance(self.stops, Unset):
            stops = UNSET
        else:
            stops = self.stops

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "dx": dx,
                "manipulator": manipulator,
            }
        )
        if dy is not UNSET:
            field_dict["dy"] = dy
        if method is not UNSET:
            field_dict["method"] = method
        if stops is not UNSET:
            field_dict["stops"] = stops

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

        _method = d.pop("method", UNSET)
        method: EquilibriaRequestMethod | Unset
        if isinstance(_method, Unset):
            method = UNSET
        else:
            method = EquilibriaRequestMethod(_method)

        def _parse_stops(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        stops = _parse_stops(d.pop("stops", UNSET))

        equilibria_request = cls(
            dx=dx,
            manipulator=manipulator,
            dy=dy,
            method=method,
            stops=stops,
        )

        return equilibria_request
