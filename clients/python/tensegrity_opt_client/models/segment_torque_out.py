from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="SegmentTorqueOut")


@_attrs_define
class SegmentTorqueOut:
    """
    Attributes:
        dtorque (list[float]): M'(q); the segment alone is stable where < 0
        energy (list[float]): segment energy E(q)
        joint_limit (float): physical range |q| < pi - 2 beta (rad)
        monotonic (bool): M(q) decreases over the whole physical range
        q (list[float]): joint angles (rad)
        stiffness (float): joint stiffness K = E''(0)
        torque (list[float]): spring torque M(q) = -dE/dq
    """

    dtorque: list[float]
    energy: list[float]
    joint_limit: float
    monotonic: bool
    q: list[float]
    stiffness: float
    torque: list[float]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        dtorque = self.dtorque

        energy = self.energy

        joint_limit = self.joint_limit

        monotonic = self.monotonic

        q = self.q

        stiffness = self.stiffness

        torque = self.torque

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "dtorque": dtorque,
                "energy": energy,
                "joint_limit": joint_limit,
                "monotonic": monotonic,
                "q": q,
                "stiffness": stiffness,
                "torque": torque,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        dtorque = cast(list[float], d.pop("dtorque"))

        energy = cast(list[float], d.pop("energy"))

        joint_limit = d.pop("joint_limit")

        monotonic = d.pop("monotonic")

        q = cast(list[float], d.pop("q"))

        stiffness = d.pop("stiffness")

        torque = cast(list[float], d.pop("torque"))

        segment_torque_out = cls(
            dtorque=dtorque,
            energy=energy,
            joint_limit=joint_limit,
            monotonic=monotonic,
            q=q,
            stiffness=stiffness,
            torque=torque,
        )

        segment_torque_out.additional_properties = d
        return segment_torque_out

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
