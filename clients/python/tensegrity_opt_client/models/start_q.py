from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

T = TypeVar("T", bound="StartQ")


@_attrs_define
class StartQ:
    """Joint angles to start from (Newton puts them on the branch at t = 0).

    Attributes:
        q (list[float]): relative joint angles (rad), n of them, inside the physical range
    """

    q: list[float]

    def to_dict(self) -> dict[str, Any]:
        q = self.q

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "q": q,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        q = cast(list[float], d.pop("q"))

        start_q = cls(
            q=q,
        )

        return start_q
