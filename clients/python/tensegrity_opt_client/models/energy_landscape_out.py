from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, Literal, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

if TYPE_CHECKING:
    from ..models.loads_out import LoadsOut


T = TypeVar("T", bound="EnergyLandscapeOut")


@_attrs_define
class EnergyLandscapeOut:
    """Energy over a grid of two joint angles (`tensegrity_opt.Landscape`).

    Attributes:
        energy (list[list[list[float | None]]]): energy[elbow][i][j], elbow 0: +1, 1: -1; null where unreachable or out
            of range
        loads (LoadsOut | None): the dead loads this was computed under (gravity on the chain's masses, joint forces);
            null where the chain carries none
        message (str): what happened, in a sentence
        pair (list[int]):
        qi (list[float]): grid axis of joint pair[0] (rad)
        qj (list[float]): grid axis of joint pair[1] (rad)
        status (Literal['evaluated']): `evaluated`: the energy was evaluated at every grid point on both elbow branches
            (NaN, null in JSON, where the tip is out of the two arms' reach or the configuration leaves the physical range)
        success (bool): whether it worked: `status` is one of evaluated
    """

    energy: list[list[list[float | None]]]
    loads: LoadsOut | None
    message: str
    pair: list[int]
    qi: list[float]
    qj: list[float]
    status: Literal["evaluated"]
    success: bool
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        from ..models.loads_out import LoadsOut  # noqa: PLC0415

        energy = []
        for energy_item_data in self.energy:
            energy_item = []
            for energy_item_item_data in energy_item_data:
                energy_item_item = []
                for energy_item_item_item_data in energy_item_item_data:
                    energy_item_item_item: float | None
                    energy_item_item_item = energy_item_item_item_data
                    energy_item_item.append(energy_item_item_item)

                energy_item.append(energy_item_item)

            energy.append(energy_item)

        loads: dict[str, Any] | None
        if isinstance(self.loads, LoadsOut):
            loads = self.loads.to_dict()
        else:
            loads = self.loads

        message = self.message

        pair = self.pair

        qi = self.qi

        qj = self.qj

        status = self.status

        success = self.success

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "energy": energy,
                "loads": loads,
                "message": message,
                "pair": pair,
                "qi": qi,
                "qj": qj,
                "status": status,
                "success": success,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.loads_out import LoadsOut  # noqa: PLC0415

        d = dict(src_dict)
        energy = []
        _energy = d.pop("energy")
        for energy_item_data in _energy:
            energy_item = []
            _energy_item = energy_item_data
            for energy_item_item_data in _energy_item:
                energy_item_item = []
                _energy_item_item = energy_item_item_data
                for energy_item_item_item_data in _energy_item_item:

                    def _parse_energy_item_item_item(data: object) -> float | None:
                        if data is None:
                            return data
                        return cast(float | None, data)

                    energy_item_item_item = _parse_energy_item_item_item(energy_item_item_item_data)

                    energy_item_item.append(energy_item_item_item)

                energy_item.append(energy_item_item)

            energy.append(energy_item)

        def _parse_loads(data: object) -> LoadsOut | None:
            if data is None:
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                loads_type_0 = LoadsOut.from_dict(data)

                return loads_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(LoadsOut | None, data)

        loads = _parse_loads(d.pop("loads"))

        message = d.pop("message")

        pair = cast(list[int], d.pop("pair"))

        qi = cast(list[float], d.pop("qi"))

        qj = cast(list[float], d.pop("qj"))

        status = cast(Literal["evaluated"], d.pop("status"))
        if status != "evaluated":
            raise ValueError(f"status must match const 'evaluated', got '{status}'")

        success = d.pop("success")

        energy_landscape_out = cls(
            energy=energy,
            loads=loads,
            message=message,
            pair=pair,
            qi=qi,
            qj=qj,
            status=status,
            success=success,
        )

        energy_landscape_out.additional_properties = d
        return energy_landscape_out

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
