from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.root_box_out_reason import RootBoxOutReason

T = TypeVar("T", bound="RootBoxOut")


@_attrs_define
class RootBoxOut:
    """The interval proof about one equilibrium (`tensegrity_opt.results.RootBox`).

    Attributes:
        lower (list[float]): the box's lower bounds (outward-rounded): q (rad), then Fx, Fy under displacement control
        morse_index (int | None): the Morse index proven over the box (null: not proven)
        morse_proven (bool): the Morse index is proven; false: the equilibrium's own index is floating-point
        proven (bool): Krawczyk's test passed: exactly one real equilibrium in the box, the box strictly inside the
            joint range and disjoint from the other boxes
        reason (RootBoxOutReason): why not proven (empty when proven): `krawczyk` the test did not contract (singular or
            ill-conditioned), `singular` no float inverse, `range` the box straddles a joint limit, `outside` it lies beyond
            one, `overlap` the box meets another, `moved` the refined point left the given one
        upper (list[float]): the box's upper bounds, as `lower`
    """

    lower: list[float]
    morse_index: int | None
    morse_proven: bool
    proven: bool
    reason: RootBoxOutReason
    upper: list[float]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        lower = self.lower

        morse_index: int | None
        morse_index = self.morse_index

        morse_proven = self.morse_proven

        proven = self.proven

        reason = self.reason.value

        upper = self.upper

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "lower": lower,
                "morse_index": morse_index,
                "morse_proven": morse_proven,
                "proven": proven,
                "reason": reason,
                "upper": upper,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        lower = cast(list[float], d.pop("lower"))

        def _parse_morse_index(data: object) -> int | None:
            if data is None:
                return data
            return cast(int | None, data)

        morse_index = _parse_morse_index(d.pop("morse_index"))

        morse_proven = d.pop("morse_proven")

        proven = d.pop("proven")

        reason = RootBoxOutReason(d.pop("reason"))

        upper = cast(list[float], d.pop("upper"))

        root_box_out = cls(
            lower=lower,
            morse_index=morse_index,
            morse_proven=morse_proven,
            proven=proven,
            reason=reason,
            upper=upper,
        )

        root_box_out.additional_properties = d
        return root_box_out

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
