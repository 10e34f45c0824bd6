from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.segment_in_spring import SegmentInSpring
from ..types import UNSET, Unset

T = TypeVar("T", bound="SegmentIn")


@_attrs_define
class SegmentIn:
    """One dual-triangle segment.

    Attributes:
        a (float): triangle half-height (length units)
        b (float): triangle half-length (length units); the segment is 2b long
        L0 (float | list[float] | Unset): spring rest length L0 (length units): one number for both springs or the pair
            [spring 1, spring 2] Default: 1.0.
        inertia (float | Unset): each triangle's rotational inertia about its centroid (>= 0, default 0; mass x
            length^2) Default: 0.0.
        k (float | list[float] | Unset): spring stiffness k (force / length): one number for both springs or the pair
            [spring 1, spring 2] Default: 1.0.
        mass (float | Unset): the segment's mass (>= 0, default 0): two equal triangles whose centroids lie on the
            chain's axis 2b/3 from the joint; without gravity it changes no equilibrium, it sets the vibration modes
            (`/v1/modes`) Default: 0.0.
        spring (SegmentInSpring | Unset): the springs' law: `linear` (the paper's model: force k (L - L0) at every
            length, a spring shorter than its rest length pushes) or `tension_only` (force k max(0, L - L0): it goes slack,
            as a real extension spring or cable). Analyses that do not honour `tension_only` refuse it (422 `unsupported`,
            field `segments[i].spring`) Default: SegmentInSpring.LINEAR.
    """

    a: float
    b: float
    L0: float | list[float] | Unset = 1.0
    inertia: float | Unset = 0.0
    k: float | list[float] | Unset = 1.0
    mass: float | Unset = 0.0
    spring: SegmentInSpring | Unset = SegmentInSpring.LINEAR

    def to_dict(self) -> dict[str, Any]:
        a = self.a

        b = self.b

        L0: float | list[float] | Unset
        if isinstance(self.L0, Unset):
            L0 = UNSET
        elif isinstance(self.L0, list):
            L0 = self.L0

        else:
            L0 = self.L0

        inertia = self.inertia

        k: float | list[float] | Unset
        if isinstance(self.k, Unset):
            k = UNSET
        elif isinstance(self.k, list):
            k = self.k

        else:
            k = self.k

        mass = self.mass

        spring: str | Unset = UNSET
        if not isinstance(self.spring, Unset):
            spring = self.spring.value

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "a": a,
                "b": b,
            }
        )
        if L0 is not UNSET:
            field_dict["L0"] = L0
        if inertia is not UNSET:
            field_dict["inertia"] = inertia
        if k is not UNSET:
            field_dict["k"] = k
        if mass is not UNSET:
            field_dict["mass"] = mass
        if spring is not UNSET:
            field_dict["spring"] = spring

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        a = d.pop("a")

        b = d.pop("b")

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

        inertia = d.pop("inertia", UNSET)

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

        _spring = d.pop("spring", UNSET)
        spring: SegmentInSpring | Unset
        if isinstance(_spring, Unset):
            spring = UNSET
        else:
            spring = SegmentInSpring(_spring)

        segment_in = cls(
            a=a,
            b=b,
            L0=L0,
            inertia=inertia,
            k=k,
            mass=mass,
            spring=spring,
        )

        return segment_in
