from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar

from attrs import define as _attrs_define

from ..models.buckling_request_boundary import BucklingRequestBoundary
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.uniform_manipulator_in import UniformManipulatorIn


T = TypeVar("T", bound="BucklingRequest")


@_attrs_define
class BucklingRequest:
    """Critical loads and buckling modes of the straight configuration.

    Attributes:
        manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
            (uniform) or {"segments": [...]}
        boundary (BucklingRequestBoundary | Unset): "guided": tip held at dy = 0 (the paper); "free": cantilever
            Default: BucklingRequestBoundary.GUIDED.
    """

    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    boundary: BucklingRequestBoundary | Unset = BucklingRequestBoundary.GUIDED

    def to_dict(self) -> dict[str, Any]:
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, UniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        boundary: str | Unset = UNSET
        if not isinstance(self.boundary, Unset):
            boundary = self.boundary.value

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "manipulator": manipulator,
            }
        )
        if boundary is not UNSET:
            field_dict["boundary"] = boundary

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

        _boundary = d.pop("boundary", UNSET)
        boundary: BucklingRequestBoundary | Unset
        if isinstance(_boundary, Unset):
            boundary = UNSET
        else:
            boundary = BucklingRequestBoundary(_boundary)

        buckling_request = cls(
            manipulator=manipulator,
            boundary=boundary,
        )

        return buckling_request
