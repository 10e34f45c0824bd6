from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.load_capacity_out_status import LoadCapacityOutStatus

if TYPE_CHECKING:
    from ..models.load_capacity_out_manipulator import LoadCapacityOutManipulator
    from ..models.load_capacity_out_start import LoadCapacityOutStart
    from ..models.load_capacity_out_weakest_type_0 import LoadCapacityOutWeakestType0


T = TypeVar("T", bound="LoadCapacityOut")


@_attrs_define
class LoadCapacityOut:
    """`LoadCapacity.to_dict()`: a polar curve of the pose's load capacity.

    Attributes:
        angles (list[float]): direction angles (rad)
        base (list[float]):
        boundary (str):
        directions (list[list[float]]):
        end_loads (list[float]):
        forces (list[list[float | None]]): the total tip force there
        kinds (list[str]): fold, bifurcation or none
        loads (list[float | None]): the extra load at the first loss of stability (null: none)
        manipulator (LoadCapacityOutManipulator):
        max_load (float):
        message (str): what happened, in a sentence
        reasons (list[None | str]):
        start (LoadCapacityOutStart):
        status (LoadCapacityOutStatus): `complete`: every direction was followed to its first loss of stability, a
            joint's range bound or max_load; `time_limit`: the time limit ran out before every direction was followed
            (reasons: time_limit); `path_failed`: the path of some direction could not be followed (reasons: the branch's
            status or the error's code)
        success (bool): whether it worked: `status` is one of complete
        weakest (LoadCapacityOutWeakestType0 | None):
    """

    angles: list[float]
    base: list[float]
    boundary: str
    directions: list[list[float]]
    end_loads: list[float]
    forces: list[list[float | None]]
    kinds: list[str]
    loads: list[float | None]
    manipulator: LoadCapacityOutManipulator
    max_load: float
    message: str
    reasons: list[None | str]
    start: LoadCapacityOutStart
    status: LoadCapacityOutStatus
    success: bool
    weakest: LoadCapacityOutWeakestType0 | None
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        from ..models.load_capacity_out_weakest_type_0 import LoadCapacityOutWeakestType0  # noqa: PLC0415

        angles = self.angles

        base = self.base

        boundary = self.boundary

        directions = []
        for directions_item_data in self.directions:
            directions_item = directions_item_data

            directions.append(directions_item)

        end_loads = self.end_loads

        forces = []
        for forces_item_data in self.forces:
            forces_item = []
            for forces_item_item_data in forces_item_data:
                forces_item_item: float | None
                forces_item_item = forces_item_item_data
                forces_item.append(forces_item_item)

            forces.append(forces_item)

        kinds = self.kinds

        loads = []
        for loads_item_data in self.loads:
            loads_item: float | None
            loads_item = loads_item_data
            loads.append(loads_item)

        manipulator = self.manipulator.to_dict()

        max_load = self.max_load

        message = self.message

        reasons = []
        for reasons_item_data in self.reasons:
            reasons_item: None | str
            reasons_item = reasons_item_data
            reasons.append(reasons_item)

        start = self.start.to_dict()

        status = self.status.value

        success = self.success

        weakest: dict[str, Any] | None
        if isinstance(self.weakest, LoadCapacityOutWeakestType0):
            weakest = self.weakest.to_dict()
        else:
            weakest = self.weakest

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "angles": angles,
                "base": base,
                "boundary": boundary,
                "directions": directions,
                "end_loads": end_loads,
                "forces": forces,
                "kinds": kinds,
                "loads": loads,
                "manipulator": manipulator,
                "max_load": max_load,
                "message": message,
                "reasons": reasons,
                "start": start,
                "status": status,
                "success": success,
                "weakest": weakest,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.load_capacity_out_manipulator import LoadCapacityOutManipulator  # noqa: PLC0415
        from ..models.load_capacity_out_start import LoadCapacityOutStart  # noqa: PLC0415
        from ..models.load_capacity_out_weakest_type_0 import LoadCapacityOutWeakestType0  # noqa: PLC0415

        d = dict(src_dict)
        angles = cast(list[float], d.pop("angles"))

        base = cast(list[float], d.pop("base"))

        boundary = d.pop("boundary")

        directions = []
        _directions = d.pop("directions")
        for directions_item_data in _directions:
            directions_item = cast(list[float], directions_item_data)

            directions.append(directions_item)

        end_loads = cast(list[float], d.pop("end_loads"))

        forces = []
        _forces = d.pop("forces")
        for forces_item_data in _forces:
            forces_item = []
            _forces_item = forces_item_data
            for forces_item_item_data in _forces_item:

                def _parse_forces_item_item(data: object) -> float | None:
                    if data is None:
                        return data
                    return cast(float | None, data)

                forces_item_item = _parse_forces_item_item(forces_item_item_data)

                forces_item.append(forces_item_item)

            forces.append(forces_item)

        kinds = cast(list[str], d.pop("kinds"))

        loads = []
        _loads = d.pop("loads")
        for loads_item_data in _loads:

            def _parse_loads_item(data: object) -> float | None:
                if data is None:
                    return data
                return cast(float | None, data)

            loads_item = _parse_loads_item(loads_item_data)

            loads.append(loads_item)

        manipulator = LoadCapacityOutManipulator.from_dict(d.pop("manipulator"))

        max_load = d.pop("max_load")

        message = d.pop("message")

        reasons = []
        _reasons = d.pop("reasons")
        for reasons_item_data in _reasons:

            def _parse_reasons_item(data: object) -> None | str:
                if data is None:
                    return data
                return cast(None | str, data)

            reasons_item = _parse_reasons_item(reasons_item_data)

            reasons.append(reasons_item)

        start = LoadCapacityOutStart.from_dict(d.pop("start"))

        status = LoadCapacityOutStatus(d.pop("status"))

        success = d.pop("success")

        def _parse_weakest(data: object) -> LoadCapacityOutWeakestType0 | None:
            if data is None:
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                weakest_type_0 = LoadCapacityOutWeakestType0.from_dict(data)

                return weakest_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(LoadCapacityOutWeakestType0 | None, data)

        weakest = _parse_weakest(d.pop("weakest"))

        load_capacity_out = cls(
            angles=angles,
            base=base,
            boundary=boundary,
            directions=directions,
            end_loads=end_loads,
            forces=forces,
            kinds=kinds,
            loads=loads,
            manipulator=manipulator,
            max_load=max_load,
            message=message,
            reasons=reasons,
            start=start,
            status=status,
            success=success,
            weakest=weakest,
        )

        load_capacity_out.additional_properties = d
        return load_capacity_out

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
