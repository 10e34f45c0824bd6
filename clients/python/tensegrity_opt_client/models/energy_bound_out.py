from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.energy_bound_out_status import EnergyBoundOutStatus

T = TypeVar("T", bound="EnergyBoundOut")


@_attrs_define
class EnergyBoundOut:
    """The least-energy certificate (`tensegrity_opt.EnergyBound`).

    Attributes:
        bound (float): no configuration meeting the tip constraint in the closed joint range has a lower energy
        boxes (int): boxes bounded in all
        certified (bool):
        energy (float): the least energy of a feasible configuration known (the answer's)
        gap (float): energy - bound (>= 0)
        improved (bool): the bound found a lower configuration than the search's (returned instead)
        message (str): what happened, in a sentence
        newton (int): Newton re-centrings of open boxes
        patterns (int): pattern boxes (products of the joints' low-energy pieces) enumerated
        seconds (float): wall time of the bound (s)
        status (EnergyBoundOutStatus): `certified`: the gap between the best energy and the rigorous lower bound is
            within the tolerance: the configuration is the least-energy one up to that tolerance; `open`: the lower bound is
            rigorous but the gap exceeds the tolerance (too many pieces or boxes, or the bounds were not tight enough): the
            configuration is not proven least
        success (bool): whether it worked: `status` is one of certified
        tolerance (float): certified when gap <= tolerance (1e-7 |E| + 1e-9 max k c^2)
    """

    bound: float
    boxes: int
    certified: bool
    energy: float
    gap: float
    improved: bool
    message: str
    newton: int
    patterns: int
    seconds: float
    status: EnergyBoundOutStatus
    success: bool
    tolerance: float
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        bound = self.bound

        boxes = self.boxes

        certified = self.certified

        energy = self.energy

        gap = self.gap

        improved = self.improved

        message = self.message

        newton = self.newton

        patterns = self.patterns

        seconds = self.seconds

        status = self.status.value

        success = self.success

        tolerance = self.tolerance

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "bound": bound,
                "boxes": boxes,
                "certified": certified,
                "energy": energy,
                "gap": gap,
                "improved": improved,
                "message": message,
                "newton": newton,
                "patterns": patterns,
                "seconds": seconds,
                "status": status,
                "success": success,
                "tolerance": tolerance,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        bound = d.pop("bound")

        boxes = d.pop("boxes")

        certified = d.pop("certified")

        energy = d.pop("energy")

        gap = d.pop("gap")

        improved = d.pop("improved")

        message = d.pop("message")

        newton = d.pop("newton")

        patterns = d.pop("patterns")

        seconds = d.pop("seconds")

        status = EnergyBoundOutStatus(d.pop("status"))

        success = d.pop("success")

        tolerance = d.pop("tolerance")

        energy_bound_out = cls(
            bound=bound,
            boxes=boxes,
            certified=certified,
            energy=energy,
            gap=gap,
            improved=improved,
            message=message,
            newton=newton,
            patterns=patterns,
            seconds=seconds,
            status=status,
            success=success,
            tolerance=tolerance,
        )

        energy_bound_out.additional_properties = d
        return energy_bound_out

    @property
    def additional_keys(self) -> list[str]:
        return list(self.additional_properties.keys())

    def __getitem__(self, key: str) -> Any:
        return self.additional_properties[key]

    def __setitem__(self, key: str, value: Any) -> None:
        self.additional_properties[key] = value

    def __delitem__(self, key: str) -> None:
        del self.additional_properties[key]

    def __contains__(self, key: str) -> bool:
        return key in self.additional_properties
