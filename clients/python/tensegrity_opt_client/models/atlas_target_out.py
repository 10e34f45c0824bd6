from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.atlas_target_out_status import AtlasTargetOutStatus

T = TypeVar("T", bound="AtlasTargetOut")


@_attrs_define
class AtlasTargetOut:
    """The equilibria with the tip held at one target (`AtlasTarget.to_dict()`).

    Attributes:
        certified (bool): the set is proven complete (homotopy, or a trivial case)
        count (int): equilibria inside the physical range (-1: the solve failed, see error)
        dx (float):
        dy (float):
        error (None | str): `code: message` where the target failed (counts -1), e.g. time_limit
        least_energy (float | None): energy of the least-energy stable equilibrium (force x length)
        least_signs (None | str): its sign string (+/- per joint)
        message (str): what happened, in a sentence
        method (str):
        n_maximum (int):
        n_saddle (int):
        n_stable (int): minima (-1: failed)
        reachable (bool): false beyond the chain's reach (every count 0)
        stable_energy (list[float]):
        stable_q (list[list[float]]): joint angles (rad) of each stable equilibrium, least energy first
        status (AtlasTargetOutStatus): `solved`: every equilibrium found (the search, or certified by the homotopy) and
            classified; `unreachable`: the target is beyond the chain's reach: every count 0; `failed`: the solve failed
            (error says why): the counts are -1; `time_limit`: not computed before the time limit: the counts are -1
        success (bool): whether it worked: `status` is one of solved, unreachable
        tie (bool): two stable equilibria share the least energy (e.g. mirror images on dy = 0)
    """

    certified: bool
    count: int
    dx: float
    dy: float
    error: None | str
    least_energy: float | None
    least_signs: None | str
    message: str
    method: str
    n_maximum: int
    n_saddle: int
    n_stable: int
    reachable: bool
    stable_energy: list[float]
    stable_q: list[list[float]]
    status: AtlasTargetOutStatus
    success: bool
    tie: bool
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        certified = self.certified

        count = self.count

        dx = self.dx

        dy = self.dy

        error: None | str
        error = self.error

        least_energy: float | None
        least_energy = self.least_energy

        least_signs: None | str
        least_signs = self.least_signs

        message = self.message

        method = self.method

        n_maximum = self.n_maximum

        n_saddle = self.n_saddle

        n_stable = self.n_stable

        reachable = self.reachable

        stable_energy = self.stable_energy

        stable_q = []
        for stable_q_item_data in self.stable_q:
            stable_q_item = stable_q_item_data

            stable_q.append(stable_q_item)

        status = self.status.value

        success = self.success

        tie = self.tie

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "certified": certified,
                "count": count,
                "dx": dx,
                "dy": dy,
                "error": error,
                "least_energy": least_energy,
                "least_signs": least_signs,
                "message": message,
                "method": method,
                "n_maximum": n_maximum,
                "n_saddle": n_saddle,
                "n_stable": n_stable,
                "reachable": reachable,
                "stable_energy": stable_energy,
                "stable_q": stable_q,
                "status": status,
                "success": success,
                "tie": tie,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        certified = d.pop("certified")

        count = d.pop("count")

        dx = d.pop("dx")

        dy = d.pop("dy")

        def _parse_error(data: object) -> None | str:
            if data is None:
                return data
            return cast(None | str, data)

        error = _parse_error(d.pop("error"))

        def _parse_least_energy(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        least_energy = _parse_least_energy(d.pop("least_energy"))

        def _parse_least_signs(data: object) -> None | str:
            if data is None:
                return data
            return cast(None | str, data)

        least_signs = _parse_least_signs(d.pop("least_signs"))

        message = d.pop("message")

        method = d.pop("method")

        n_maximum = d.pop("n_maximum")

        n_saddle = d.pop("n_saddle")

        n_stable = d.pop("n_stable")

        reachable = d.pop("reachable")

        stable_energy = cast(list[float], d.pop("stable_energy"))

        stable_q = []
        _stable_q = d.pop("stable_q")
        for stable_q_item_data in _stable_q:
            stable_q_item = cast(list[float], stable_q_item_data)

            stable_q.append(stable_q_item)

        status = AtlasTargetOutStatus(d.pop("status"))

        success = d.pop("success")

        tie = d.pop("tie")

        atlas_target_out = cls(
            certified=certified,
            count=count,
            dx=dx,
            dy=dy,
            error=error,
            least_energy=least_energy,
            least_signs=least_signs,
            message=message,
            method=method,
            n_maximum=n_maximum,
            n_saddle=n_saddle,
            n_stable=n_stable,
            reachable=reachable,
            stable_energy=stable_energy,
            stable_q=stable_q,
            status=status,
            success=success,
            tie=tie,
        )

        atlas_target_out.additional_properties = d
        return atlas_target_out

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
