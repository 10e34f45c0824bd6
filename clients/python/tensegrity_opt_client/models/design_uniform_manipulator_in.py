from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.design_uniform_manipulator_in_spring import DesignUniformManipulatorInSpring
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.joint_force_in import JointForceIn


T = TypeVar("T", bound="DesignUniformManipulatorIn")


@_attrs_define
class DesignUniformManipulatorIn:
    """`n` identical segments (design endpoints: at most 60).

    Attributes:
        n (int): number of segments (at most 60 for the design endpoints)
        L0 (float | list[float] | Unset): spring rest length L0 (length units): one number for both springs or the pair
            [spring 1, spring 2] Default: 1.0.
        a (float | Unset): triangle half-height (length units) Default: 1.0.
        b (float | Unset): triangle half-length (length units) Default: 1.0.
        gravity (list[float] | None | Unset): the gravity vector [gx, gy] in the chain's plane (default none: no
            weight); [0, -9.81] for a chain pointing along +x in a vertical plane, any direction (a tilted base). The
            triangles' and the payload's weights then load the chain in every analysis that honours dead loads; the others
            refuse it (422 `unsupported`, field `gravity`)
        inertia (float | Unset): each triangle's rotational inertia about its centroid (>= 0, default 0; mass x
            length^2) Default: 0.0.
        joint_forces (list[JointForceIn] | Unset): dead point forces at joints, beside the tip's load: [{"joint": j,
            "force": [fx, fy]}], joints counted from 1 at the base (joint 1 is fixed: a force there does no work); analyses
            that do not honour dead loads refuse them (422 `unsupported`, field `joint_forces`)
        k (float | list[float] | Unset): spring stiffness k (force / length): one number for both springs or the pair
            [spring 1, spring 2] Default: 1.0.
        mass (float | Unset): the segment's mass (>= 0, default 0): two equal triangles whose centroids lie on the
            chain's axis 2b/3 from the joint; without gravity it changes no equilibrium, it sets the vibration modes
            (`/v1/modes`) Default: 0.0.
        payload (float | Unset): a point mass at the tip (>= 0, default 0): it sets the vibration modes (`/v1/modes`)
            and, under `gravity`, weighs on the chain Default: 0.0.
        spring (DesignUniformManipulatorInSpring | Unset): the springs' law: `linear` (the paper's model: force k (L -
            L0) at every length, a spring shorter than its rest length pushes) or `tension_only` (force k max(0, L - L0): it
            goes slack, as a real extension spring or cable). Analyses that do not honour `tension_only` refuse it (422
            `unsupported`, field `segments[i].spring`) Default: DesignUniformManipulatorInSpring.LINEAR.
    """

    n: int
    L0: float | list[float] | Unset = 1.0
    a: float | Unset = 1.0
    b: float | Unset = 1.0
    gravity: list[float] | None | Unset = UNSET
    inertia: float | Unset = 0.0
    joint_forces: list[JointForceIn] | Unset = UNSET
    k: float | list[float] | Unset = 1.0
    mass: float | Unset = 0.0
    payload: float | Unset = 0.0
    spring: DesignUniformManipulatorInSpring | Unset = DesignUniformManipulatorInSpring.LINEAR

    def to_dict(self) -> dict[str, Any]:
        n = self.n

        L0: float | list[float] | Unset
        if isinstance(self.L0, Unset):
            L0 = UNSET
        elif isinstance(self.L0, list):
            L0 = self.L0

        else:
            L0 = self.L0

        a = self.a

        b = self.b

        gravity: list[float] | None | Unset
        if isinstance(self.gravity, Unset):
            gravity = UNSET
        elif isinstance(self.gravity, list):
            gravity = self.gravity

        else:
            gravity = self.gravity

        inertia = self.inertia

        joint_forces: list[dict[str, Any]] | Unset = UNSET
        if not isinstance(self.joint_forces, Unset):
            joint_forces = []
            for joint_forces_item_data in self.joint_forces:
                joint_forces_item = joint_forces_item_data.to_dict()
                joint_forces.append(joint_forces_item)

        k: float | list[float] | Unset
        if isinstance(self.k, Unset):
            k = UNSET
        elif isinstance(self.k, list):
            k = self.k

        else:
            k = self.k

        mass = self.mass

        payload = self.payload

        spring: str | Unset = UNSET
        if not isinstance(self.spring, Unset):
            spring = self.spring.value

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "n": n,
            }
        )
        if L0 is not UNSET:
            field_dict["L0"] = L0
        if a is not UNSET:
            field_dict["a"] = a
        if b is not UNSET:
            field_dict["b"] = b
        if gravity is not UNSET:
            field_dict["gravity"] = gravity
        if inertia is not UNSET:
            field_dict["inertia"] = inertia
        if joint_forces is not UNSET:
            field_dict["joint_forces"] = joint_forces
        if k is not UNSET:
            field_dict["k"] = k
        if mass is not UNSET:
            field_dict["mass"] = mass
        if payload is not UNSET:
            field_dict["payload"] = payload
        if spring is not UNSET:
            field_dict["spring"] = spring

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.joint_force_in import JointForceIn  # noqa: PLC0415

        d = dict(src_dict)
        n = d.pop("n")

        def _parse_l0(data: object) -> float | list[float] | Unset:
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                l0_type_1 = cast(list[float], data)

                return l0_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(float | list[float] | Unset, data)

        L0 = _parse_l0(d.pop("L0", UNSET))

        a = d.pop("a", UNSET)

        b = d.pop("b", UNSET)

        def _parse_gravity(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                gravity_type_0 = cast(list[float], data)

                return gravity_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        gravity = _parse_gravity(d.pop("gravity", UNSET))

        inertia = d.pop("inertia", UNSET)

        _joint_forces = d.pop("joint_forces", UNSET)
        joint_forces: list[JointForceIn] | Unset = UNSET
        if _joint_forces is not UNSET:
            joint_forces = []
            for joint_forces_item_data in _joint_forces:
                joint_forces_item = JointForceIn.from_dict(joint_forces_item_data)

                joint_forces.append(joint_forces_item)

        def _parse_k(data: object) -> float | list[float] | Unset:
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                k_type_1 = cast(list[float], data)

                return k_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(float | list[float] | Unset, data)

        k = _parse_k(d.pop("k", UNSET))

        mass = d.pop("mass", UNSET)

        payload = d.pop("payload", UNSET)

        _spring = d.pop("spring", UNSET)
        spring: DesignUniformManipulatorInSpring | Unset
        if isinstance(_spring, Unset):
            spring = UNSET
        else:
            spring = DesignUniformManipulatorInSpring(_spring)

        design_uniform_manipulator_in = cls(
            n=n,
            L0=L0,
            a=a,
            b=b,
            gravity=gravity,
            inertia=inertia,
            joint_forces=joint_forces,
            k=k,
            mass=mass,
            payload=payload,
            spring=spring,
        )

        return design_uniform_manipulator_in
