from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

if TYPE_CHECKING:
    from ..models.joint_force_in import JointForceIn


T = TypeVar("T", bound="LoadsOut")


@_attrs_define
class LoadsOut:
    """The dead loads a result was computed under (null where the chain carries none).

    Attributes:
        gravity (list[float] | None): the gravity vector [gx, gy], or null
        joint_forces (list[JointForceIn]): the dead forces at joints
        payload (float): the point mass at the tip
    """

    gravity: list[float] | None
    joint_forces: list[JointForceIn]
    payload: float
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        gravity: list[float] | None
        if isinstance(self.gravity, list):
            gravity = self.gravity

        else:
            gravity = self.gravity

        joint_forces = []
        for joint_forces_item_data in self.joint_forces:
            joint_forces_item = joint_forces_item_data.to_dict()
            joint_forces.append(joint_forces_item)

        payload = self.payload

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "gravity": gravity,
                "joint_forces": joint_forces,
                "payload": payload,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.joint_force_in import JointForceIn  # noqa: PLC0415

        d = dict(src_dict)

        def _parse_gravity(data: object) -> list[float] | None:
            if data is None:
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                gravity_type_0 = cast(list[float], data)

                return gravity_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None, data)

        gravity = _parse_gravity(d.pop("gravity"))

        joint_forces = []
        _joint_forces = d.pop("joint_forces")
        for joint_forces_item_data in _joint_forces:
            joint_forces_item = JointForceIn.from_dict(joint_forces_item_data)

            joint_forces.append(joint_forces_item)

        payload = d.pop("payload")

        loads_out = cls(
            gravity=gravity,
            joint_forces=joint_forces,
            payload=payload,
        )

        loads_out.additional_properties = d
        return loads_out

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
