from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar

from attrs import define as _attrs_define

from ..types import UNSET, Unset

T = TypeVar("T", bound="LoadIn")


@_attrs_define
class LoadIn:
    """
    Attributes:
        fx (float | Unset):  Default: 0.0.
        fy (float | Unset):  Default: 0.0.
    """

    fx: float | Unset = 0.0
    fy: float | Unset = 0.0

    def to_dict(self) -> dict[str, Any]:
        fx = self.fx

        fy = self.fy

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if fx is not UNSET:
            field_dict["fx"] = fx
        if fy is not UNSET:
            field_dict["fy"] = fy

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        fx = d.pop("fx", UNSET)

        fy = d.pop("fy", UNSET)

        load_in = cls(
            fx=fx,
            fy=fy,
        )

        return load_in
