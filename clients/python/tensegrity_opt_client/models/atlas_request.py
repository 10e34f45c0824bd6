from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.atlas_request_method import AtlasRequestMethod
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.atlas_range import AtlasRange
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.uniform_manipulator_in import UniformManipulatorIn


T = TypeVar("T", bound="AtlasRequest")


@_attrs_define
class AtlasRequest:
    """The stability atlas of the held tip over the grid `dx x dy` (`tensegrity_opt.stability_atlas`).

    Attributes:
        dx (AtlasRange | list[float]): the grid's dx (along the chain; dx > 0 shortens it) values (tip deflection,
            length units), strictly increasing: a list or {start, stop, num} (1..400 values)
        dy (AtlasRange | list[float]): the grid's dy (sideways) values (tip deflection, length units), strictly
            increasing: a list or {start, stop, num} (1..400 values)
        manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
            (uniform) or {"segments": [...]}
        edges (bool | Unset): locate the switches and branch ends on the grid edges (false: the counts only) Default:
            True.
        method (AtlasRequestMethod | Unset): how each target's equilibria are found: `search` (multi-start Newton,
            complete in practice, measured) or `homotopy` (PHCpack, certified counts; chains up to the server's
            `homotopy_max_segments`) Default: AtlasRequestMethod.SEARCH.
    """

    dx: AtlasRange | list[float]
    dy: AtlasRange | list[float]
    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    edges: bool | Unset = True
    method: AtlasRequestMethod | Unset = AtlasRequestMethod.SEARCH

    def to_dict(self) -> dict[str, Any]:
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        dx: dict[str, Any] | list[float]
        if isinstance(self.dx, list):
            dx = self.dx

        else:
            dx = self.dx.to_dict()

        dy: dict[str, Any] | list[float]
        if isinstance(self.dy, list):
            dy = self.dy

        else:
            dy = self.dy.to_dict()

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, UniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        edges = self.edges

        method: str | Unset = UNSET
        if not isinstance(self.method, Unset):
            method = self.method.value

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "dx": dx,
                "dy": dy,
                "manipulator": manipulator,
            }
        )
        if edges is not UNSET:
            field_dict["edges"] = edges
        if method is not UNSET:
            field_dict["method"] = method

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.atlas_range import AtlasRange  # noqa: PLC0415
        from ..models.segmented_manipulator_in import SegmentedManipulatorIn  # noqa: PLC0415
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        d = dict(src_dict)

        def _parse_dx(data: object) -> AtlasRange | list[float]:
            try:
                if not isinstance(data, list):
                    raise TypeError()
                dx_type_0 = cast(list[float], data)

                return dx_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            if not isinstance(data, dict):
                raise TypeError()
            dx_type_1 = AtlasRange.from_dict(data)

            return dx_type_1

        dx = _parse_dx(d.pop("dx"))

        def _parse_dy(data: object) -> AtlasRange | list[float]:
            try:
                if not isinstance(data, list):
                    raise TypeError()
                dy_type_0 = cast(list[float], data)

                return dy_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            if not isinstance(data, dict):
                raise TypeError()
            dy_type_1 = AtlasRange.from_dict(data)

            return dy_type_1

        dy = _parse_dy(d.pop("dy"))

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

        edges = d.pop("edges", UNSET)

        _method = d.pop("method", UNSET)
        method: AtlasRequestMethod | Unset
        if isinstance(_method, Unset):
            method = UNSET
        else:
            method = AtlasRequestMethod(_method)

        atlas_request = cls(
            dx=dx,
            dy=dy,
            manipulator=manipulator,
            edges=edges,
            method=method,
        )

        return atlas_request
