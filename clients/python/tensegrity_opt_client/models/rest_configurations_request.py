from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar

from attrs import define as _attrs_define

from ..models.rest_configurations_request_method import RestConfigurationsRequestMethod
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.uniform_manipulator_in import UniformManipulatorIn


T = TypeVar("T", bound="RestConfigurationsRequest")


@_attrs_define
class RestConfigurationsRequest:
    """Every equilibrium under a dead tip load `F = (fx, fy)`; `F = 0` (default): the rest configurations.

    Attributes:
        manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
            (uniform) or {"segments": [...]}
        fx (float | Unset): tip force along x (force units); fx < 0 compresses Default: 0.0.
        fy (float | Unset): tip force along y (force units) Default: 0.0.
        method (RestConfigurationsRequestMethod | Unset): for F != 0: `search` (multi-start Newton, complete in
            practice, not certified) or `homotopy` (PHCpack, certified; chains up to the server's `homotopy_max_segments`).
            F = 0 is exact either way (a product of the segments' own critical points) Default:
            RestConfigurationsRequestMethod.SEARCH.
        stable_only (bool | Unset): only the stable equilibria (minima of E - F . tip) Default: False.
    """

    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    fx: float | Unset = 0.0
    fy: float | Unset = 0.0
    method: RestConfigurationsRequestMethod | Unset = RestConfigurationsRequestMethod.SEARCH
    stable_only: bool | Unset = False

    def to_dict(self) -> dict[str, Any]:
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, UniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        fx = self.fx

        fy = self.fy

        method: str | Unset = UNSET
        if not isinstance(self.method, Unset):
            method = self.method.value

        stable_only = self.stable_only

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "manipulator": manipulator,
            }
        )
        if fx is not UNSET:
            field_dict["fx"] = fx
        if fy is not UNSET:
            field_dict["fy"] = fy
        if method is not UNSET:
            field_dict["method"] = method
        if stable_only is not UNSET:
            field_dict["stable_only"] = stable_only

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

        fx = d.pop("fx", UNSET)

        fy = d.pop("fy", UNSET)

        _method = d.pop("method", UNSET)
        method: RestConfigurationsRequestMethod | Unset
        if isinstance(_method, Unset):
            method = UNSET
        else:
            method = RestConfigurationsRequestMethod(_method)

        stable_only = d.pop("stable_only", UNSET)

        rest_configurations_request = cls(
            manipulator=manipulator,
            fx=fx,
            fy=fy,
            method=method,
            stable_only=stable_only,
        )

        return rest_configurations_request
