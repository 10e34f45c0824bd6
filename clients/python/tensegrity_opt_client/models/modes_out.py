from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.modes_out_status import ModesOutStatus
from ..models.modes_out_tip import ModesOutTip

if TYPE_CHECKING:
    from ..models.equilibrium_out import EquilibriumOut
    from ..models.loads_out import LoadsOut


T = TypeVar("T", bound="ModesOut")


@_attrs_define
class ModesOut:
    """:meth:`tensegrity_opt.Modes.to_dict`, with the equilibrium.

    Attributes:
        eigenvalues (list[float]): w^2, ascending (negative: unstable directions)
        equilibrium (EquilibriumOut): An equilibrium configuration.
        frequencies (list[float | None]): natural frequencies w (rad/s with kg, N/m, m), ascending; null where a
            direction does not vibrate
        held_joints (list[bool]): the joints held on their stop
        loads (LoadsOut | None): the dead loads this was computed under (gravity on the chain's masses, joint forces);
            null where the chain carries none
        message (str):
        shapes (list[list[float]]): mode k's joint angles (row k), mass-normalised
        status (ModesOutStatus): `solved`: stable, every mode vibrates; `unstable`: some w^2 < 0 (frequency null there);
            `degenerate`: some w^2 ~ 0
        success (bool):
        tip (ModesOutTip):
        total_mass (float): the segments' masses and the payload
    """

    eigenvalues: list[float]
    equilibrium: EquilibriumOut
    frequencies: list[float | None]
    held_joints: list[bool]
    loads: LoadsOut | None
    message: str
    shapes: list[list[float]]
    status: ModesOutStatus
    success: bool
    tip: ModesOutTip
    total_mass: float
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        from ..models.loads_out import LoadsOut  # noqa: PLC0415

        eigenvalues = self.eigenvalues

        equilibrium = self.equilibrium.to_dict()

        frequencies = []
        for frequencies_item_data in self.frequencies:
            frequencies_item: float | None
            frequencies_item = frequencies_item_data
            frequencies.append(frequencies_item)

        held_joints = self.held_joints

        loads: dict[str, Any] | None
        if isinstance(self.loads, LoadsOut):
            loads = self.loads.to_dict()
        else:
            loads = self.loads

        message = self.message

        shapes = []
        for shapes_item_data in self.shapes:
            shapes_item = shapes_item_data

            shapes.append(shapes_item)

        status = self.status.value

        success = self.success

        tip = self.tip.value

        total_mass = self.total_mass

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "eigenvalues": eigenvalues,
                "equilibrium": equilibrium,
                "frequencies": frequencies,
                "held_joints": held_joints,
                "loads": loads,
                "message": message,
                "shapes": shapes,
                "status": status,
                "success": success,
                "tip": tip,
                "total_mass": total_mass,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.equilibrium_out import EquilibriumOut  # noqa: PLC0415
        from ..models.loads_out import LoadsOut  # noqa: PLC0415

        d = dict(src_dict)
        eigenvalues = cast(list[float], d.pop("eigenvalues"))

        equilibrium = EquilibriumOut.from_dict(d.pop("equilibrium"))

        frequencies = []
        _frequencies = d.pop("frequencies")
        for frequencies_item_data in _frequencies:

            def _parse_frequencies_item(data: object) -> float | None:
                if data is None:
                    return data
                return cast(float | None, data)

            frequencies_item = _parse_frequencies_item(frequencies_item_data)

            frequencies.append(frequencies_item)

        held_joints = cast(list[bool], d.pop("held_joints"))

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

        shapes = []
        _shapes = d.pop("shapes")
        for shapes_item_data in _shapes:
            shapes_item = cast(list[float], shapes_item_data)

            shapes.append(shapes_item)

        status = ModesOutStatus(d.pop("status"))

        success = d.pop("success")

        tip = ModesOutTip(d.pop("tip"))

        total_mass = d.pop("total_mass")

        modes_out = cls(
            eigenvalues=eigenvalues,
            equilibrium=equilibrium,
            frequencies=frequencies,
            held_joints=held_joints,
            loads=loads,
            message=message,
            shapes=shapes,
            status=status,
            success=success,
            tip=tip,
            total_mass=total_mass,
        )

        modes_out.additional_properties = d
        return modes_out

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
