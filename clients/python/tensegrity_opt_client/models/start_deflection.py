from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar

from attrs import define as _attrs_define

from ..types import UNSET, Unset

T = TypeVar("T", bound="StartDeflection")


@_attrs_define
class StartDeflection:
    """The least-energy stable equilibrium with the tip held at this deflection (`/v1/equilibrium`).

    Attributes:
        dx (float): tip deflection along x (length units)
        dy (float | Unset): tip deflection along y (length units) Default: 0.0.
    """

    dx: float
    dy: float | Unset = 0.0

    def to_dict(self) -> dict[str, Any]:
        dx = self.dx

        dy = self.dy

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "dx": dx,
            }
        )
        if dy is not UNSET:
            field_dict["dy"] = dy

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        dx = d.pop("dx")

        dy = d.pop("dy", UNSET)

        start_deflection = cls(
            dx=dx,
            dy=dy,
        )

        return start_deflection
