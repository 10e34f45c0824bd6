from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.atlas_out_status import AtlasOutStatus

if TYPE_CHECKING:
    from ..models.atlas_crossing_out import AtlasCrossingOut
    from ..models.atlas_curves_out import AtlasCurvesOut
    from ..models.atlas_target_out import AtlasTargetOut
    from ..models.atlas_unresolved_out import AtlasUnresolvedOut


T = TypeVar("T", bound="AtlasOut")


@_attrs_define
class AtlasOut:
    """`StabilityAtlas.to_dict()`: the per-target arrays are `[dy index][dx index]`, `null` where absent.

    Attributes:
        certified (list[list[bool]]):
        count (list[list[int]]): equilibria per target (-1: failed)
        crossings (list[AtlasCrossingOut]):
        curves (AtlasCurvesOut): Segments `[[dx0, dy0], [dx1, dy1]]` joining the crossings of one kind inside each grid
            cell.
        dx (list[float]):
        dy (list[float]):
        least_energy (list[list[float | None]]):
        least_signs (list[list[None | str]]):
        message (str): what happened, in a sentence
        method (str):
        n_maximum (list[list[int]]):
        n_saddle (list[list[int]]):
        n_stable (list[list[int]]): stable equilibria per target (-1: failed)
        seconds (float):
        status (AtlasOutStatus): `complete`: every target computed and every edge analysed; `partial`: some targets
            failed or some edges could not be analysed (the rest is complete); `time_limit`: the time limit ran out: targets
            or edges not reached are missing
        success (bool): whether it worked: `status` is one of complete
        targets (list[list[AtlasTargetOut]]):
        unresolved (list[AtlasUnresolvedOut]): edges whose analysis failed, with the reason
    """

    certified: list[list[bool]]
    count: list[list[int]]
    crossings: list[AtlasCrossingOut]
    curves: AtlasCurvesOut
    dx: list[float]
    dy: list[float]
    least_energy: list[list[float | None]]
    least_signs: list[list[None | str]]
    message: str
    method: str
    n_maximum: list[list[int]]
    n_saddle: list[list[int]]
    n_stable: list[list[int]]
    seconds: float
    status: AtlasOutStatus
    success: bool
    targets: list[list[AtlasTargetOut]]
    unresolved: list[AtlasUnresolvedOut]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        certified = []
        for certified_item_data in self.certified:
            certified_item = certified_item_data

            certified.append(certified_item)

        count = []
        for count_item_data in self.count:
            count_item = count_item_data

            count.append(count_item)

        crossings = []
        for crossings_item_data in self.crossings:
            crossings_item = crossings_item_data.to_dict()
            crossings.append(crossings_item)

        curves = self.curves.to_dict()

        dx = self.dx

        dy = self.dy

        least_energy = []
        for least_energy_item_data in self.least_energy:
            least_energy_item = []
            for least_energy_item_item_data in least_energy_item_data:
                least_energy_item_item: float | None
                least_energy_item_item = least_energy_item_item_data
                least_energy_item.append(least_energy_item_item)

            least_energy.append(least_energy_item)

        least_signs = []
        for least_signs_item_data in self.least_signs:
            least_signs_item = []
            for least_signs_item_item_data in least_signs_item_data:
                least_signs_item_item: None | str
                least_signs_item_item = least_signs_item_item_data
                least_signs_item.append(least_signs_item_item)

            least_signs.append(least_signs_item)

        message = self.message

        method = self.method

        n_maximum = []
        for n_maximum_item_data in self.n_maximum:
            n_maximum_item = n_maximum_item_data

            n_maximum.append(n_maximum_item)

        n_saddle = []
        for n_saddle_item_data in self.n_saddle:
            n_saddle_item = n_saddle_item_data

            n_saddle.append(n_saddle_item)

        n_stable = []
        for n_stable_item_data in self.n_stable:
            n_stable_item = n_stable_item_data

            n_stable.append(n_stable_item)

        seconds = self.seconds

        status = self.status.value

        success = self.success

        targets = []
        for targets_item_data in self.targets:
            targets_item = []
            for targets_item_item_data in targets_item_data:
                targets_item_item = targets_item_item_data.to_dict()
                targets_item.append(targets_item_item)

            targets.append(targets_item)

        unresolved = []
        for unresolved_item_data in self.unresolved:
            unresolved_item = unresolved_item_data.to_dict()
            unresolved.append(unresolved_item)

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "certified": certified,
                "count": count,
                "crossings": crossings,
                "curves": curves,
                "dx": dx,
                "dy": dy,
                "least_energy": least_energy,
                "least_signs": least_signs,
                "message": message,
                "method": method,
                "n_maximum": n_maximum,
                "n_saddle": n_saddle,
                "n_stable": n_stable,
                "seconds": seconds,
                "status": status,
                "success": success,
                "targets": targets,
                "unresolved": unresolved,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.atlas_crossing_out import AtlasCrossingOut  # noqa: PLC0415
        from ..models.atlas_curves_out import AtlasCurvesOut  # noqa: PLC0415
        from ..models.atlas_target_out import AtlasTargetOut  # noqa: PLC0415
        from ..models.atlas_unresolved_out import AtlasUnresolvedOut  # noqa: PLC0415

        d = dict(src_dict)
        certified = []
        _certified = d.pop("certified")
        for certified_item_data in _certified:
            certified_item = cast(list[bool], certified_item_data)

            certified.append(certified_item)

        count = []
        _count = d.pop("count")
        for count_item_data in _count:
            count_item = cast(list[int], count_item_data)

            count.append(count_item)

        crossings = []
        _crossings = d.pop("crossings")
        for crossings_item_data in _crossings:
            crossings_item = AtlasCrossingOut.from_dict(crossings_item_data)

            crossings.append(crossings_item)

        curves = AtlasCurvesOut.from_dict(d.pop("curves"))

        dx = cast(list[float], d.pop("dx"))

        dy = cast(list[float], d.pop("dy"))

        least_energy = []
        _least_energy = d.pop("least_energy")
        for least_energy_item_data in _least_energy:
            least_energy_item = []
            _least_energy_item = least_energy_item_data
            for least_energy_item_item_data in _least_energy_item:

                def _parse_least_energy_item_item(data: object) -> float | None:
                    if data is None:
                        return data
                    return cast(float | None, data)

                least_energy_item_item = _parse_least_energy_item_item(least_energy_item_item_data)

                least_energy_item.append(least_energy_item_item)

            least_energy.append(least_energy_item)

        least_signs = []
        _least_signs = d.pop("least_signs")
        for least_signs_item_data in _least_signs:
            least_signs_item = []
            _least_signs_item = least_signs_item_data
            for least_signs_item_item_data in _least_signs_item:

                def _parse_least_signs_item_item(data: object) -> None | str:
                    if data is None:
                        return data
                    return cast(None | str, data)

                least_signs_item_item = _parse_least_signs_item_item(least_signs_item_item_data)

                least_signs_item.append(least_signs_item_item)

            least_signs.append(least_signs_item)

        message = d.pop("message")

        method = d.pop("method")

        n_maximum = []
        _n_maximum = d.pop("n_maximum")
        for n_maximum_item_data in _n_maximum:
            n_maximum_item = cast(list[int], n_maximum_item_data)

            n_maximum.append(n_maximum_item)

        n_saddle = []
        _n_saddle = d.pop("n_saddle")
        for n_saddle_item_data in _n_saddle:
            n_saddle_item = cast(list[int], n_saddle_item_data)

            n_saddle.append(n_saddle_item)

        n_stable = []
        _n_stable = d.pop("n_stable")
        for n_stable_item_data in _n_stable:
            n_stable_item = cast(list[int], n_stable_item_data)

            n_stable.append(n_stable_item)

        seconds = d.pop("seconds")

        status = AtlasOutStatus(d.pop("status"))

        success = d.pop("success")

        targets = []
        _targets = d.pop("targets")
        for targets_item_data in _targets:
            targets_item = []
            _targets_item = targets_item_data
            for targets_item_item_data in _targets_item:
                targets_item_item = AtlasTargetOut.from_dict(targets_item_item_data)

                targets_item.append(targets_item_item)

            targets.append(targets_item)

        unresolved = []
        _unresolved = d.pop("unresolved")
        for unresolved_item_data in _unresolved:
            unresolved_item = AtlasUnresolvedOut.from_dict(unresolved_item_data)

            unresolved.append(unresolved_item)

        atlas_out = cls(
            certified=certified,
            count=count,
            crossings=crossings,
            curves=curves,
            dx=dx,
            dy=dy,
            least_energy=least_energy,
            least_signs=least_signs,
            message=message,
            method=method,
            n_maximum=n_maximum,
            n_saddle=n_saddle,
            n_stable=n_stable,
            seconds=seconds,
            status=status,
            success=success,
            targets=targets,
            unresolved=unresolved,
        )

        atlas_out.additional_properties = d
        return atlas_out

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
