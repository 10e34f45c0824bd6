from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.force_deflection_request_branch import ForceDeflectionRequestBranch
from ..models.force_deflection_request_reference import ForceDeflectionRequestReference
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.deflection_range import DeflectionRange
    from ..models.segmented_manipulator_in import SegmentedManipulatorIn
    from ..models.uniform_manipulator_in import UniformManipulatorIn


T = TypeVar("T", bound="ForceDeflectionRequest")


@_attrs_define
class ForceDeflectionRequest:
    """Force-deflection curve by continuation along the least-energy stable branch.

    Attributes:
        dx (DeflectionRange | list[float]): deflections in the order to follow: a list or {start, stop, num} (at most
            501 points)
        manipulator (SegmentedManipulatorIn | UniformManipulatorIn): the chain: {"n", "a", "b", "k", "L0", "spring"}
            (uniform) or {"segments": [...]}
        branch (ForceDeflectionRequestBranch | Unset): "all" also returns every branch found at the first deflected
            point Default: ForceDeflectionRequestBranch.STABLE.
        dy (float | Unset): tip deflection along y, the same at every point Default: 0.0.
        reference (ForceDeflectionRequestReference | Unset): what dx, dy are measured from: the straight tip (the
            paper's) or "rest", the tip of the least-energy rest configuration (a pre-bent arm unloaded: force 0 at dx = dy
            = 0) Default: ForceDeflectionRequestReference.STRAIGHT.
    """

    dx: DeflectionRange | list[float]
    manipulator: SegmentedManipulatorIn | UniformManipulatorIn
    branch: ForceDeflectionRequestBranch | Unset = ForceDeflectionRequestBranch.STABLE
    dy: float | Unset = 0.0
    reference: ForceDeflectionRequestReference | Unset = ForceDeflectionRequestReference.STRAIGHT

    def to_dict(self) -> dict[str, Any]:
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        dx: dict[str, Any] | list[float]
        if isinstance(self.dx, list):
            dx = self.dx

        else:
            dx = self.dx.to_dict()

        manipulator: dict[str, Any]
        if isinstance(self.manipulator, UniformManipulatorIn):
            manipulator = self.manipulator.to_dict()
        else:
            manipulator = self.manipulator.to_dict()

        branch: str | Unset = UNSET
        if not isinstance(self.branch, Unset):
            branch = self.branch.value

        dy = self.dy

        reference: str | Unset = UNSET
        if not isinstance(self.reference, Unset):
            reference = self.reference.value

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "dx": dx,
                "manipulator": manipulator,
            }
        )
        if branch is not UNSET:
            field_dict["branch"] = branch
        if dy is not UNSET:
            field_dict["dy"] = dy
        if reference is not UNSET:
            field_dict["reference"] = reference

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.deflection_range import DeflectionRange  # noqa: PLC0415
        from ..models.segmented_manipulator_in import SegmentedManipulatorIn  # noqa: PLC0415
        from ..models.uniform_manipulator_in import UniformManipulatorIn  # noqa: PLC0415

        d = dict(src_dict)

        def _parse_dx(data: object) -> DeflectionRange | list[float]:
            try:
                if not isinstance(data, list):
                    raise TypeError()
                dx_type_0 = cast(list[float], data)

                return dx_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            if not isinstance(data, dict):
                raise TypeError()
            dx_type_1 = DeflectionRange.from_dict(data)

            return dx_type_1

        dx = _parse_dx(d.pop("dx"))

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

        _branch = d.pop("branch", UNSET)
        branch: ForceDeflectionRequestBranch | Unset
        if isinstance(_branch, Unset):
            branch = UNSET
        else:
            branch = ForceDeflectionRequestBranch(_branch)

        dy = d.pop("dy", UNSET)

        _reference = d.pop("reference", UNSET)
        reference: ForceDeflectionRequestReference | Unset
        if isinstance(_reference, Unset):
            reference = UNSET
        else:
            reference = ForceDeflectionRequestReference(_reference)

        force_deflection_request = cls(
            dx=dx,
            manipulator=manipulator,
            branch=branch,
            dy=dy,
            reference=reference,
        )

        return force_deflection_request
