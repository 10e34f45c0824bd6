from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

T = TypeVar("T", bound="JointForceIn")


@_attrs_define
class JointForceIn:
    """A dead point force at a joint.

    Attributes:
        force (list[float]): the force [fx, fy] (force units), fixed in direction
        joint (int): the joint, counted from 1 at the base (at most n)
    """

    force: list[float]
    joint: int

    def to_dict(self) -> dict[str, Any]:
        force = self.force

        joint = self.joint

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "force": force,
                "joint": joint,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        force = cast(list[float], d.pop("force"))

        joint = d.pop("joint")

        joint_force_in = cls(
            force=force,
            joint=joint,
        )

        return joint_force_in
