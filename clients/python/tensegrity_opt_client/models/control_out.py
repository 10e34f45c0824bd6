from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.control_out_kind import ControlOutKind
from ..models.control_out_tip_type_0 import ControlOutTipType0
from ..types import UNSET, Unset

T = TypeVar("T", bound="ControlOut")


@_attrs_define
class ControlOut:
    """
    Attributes:
        direction (list[float]): the unit direction
        kind (ControlOutKind):
        base (list[float] | None | Unset): the load at t = 0 (load, guided, wall)
        load (list[float] | None | Unset): the tip load (preload)
        normal (list[float] | None | Unset): the wall's unit normal (wall)
        tip (ControlOutTipType0 | None | Unset): preload only
    """

    direction: list[float]
    kind: ControlOutKind
    base: list[float] | None | Unset = UNSET
    load: list[float] | None | Unset = UNSET
    normal: list[float] | None | Unset = UNSET
    tip: ControlOutTipType0 | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        direction = self.direction

        kind = self.kind.value

        base: list[float] | None | Unset
        if isinstance(self.base, Unset):
            base = UNSET
        elif isinstance(self.base, list):
            base = self.base

        else:
            base = self.base

        load: list[float] | None | Unset
        if isinstance(self.load, Unset):
            load = UNSET
        elif isinstance(self.load, list):
            load = self.load

        else:
            load = self.load

        normal: list[float] | None | Unset
        if isinstance(self.normal, Unset):
            normal = UNSET
        elif isinstance(self.normal, list):
            normal = self.normal

        else:
            normal = self.normal

        tip: None | str | Unset
        if isinstance(self.tip, Unset):
            tip = UNSET
        elif isinstance(self.tip, ControlOutTipType0):
            tip = self.tip.value
        else:
            tip = self.tip

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "direction": direction,
                "kind": kind,
            }
        )
        if base is not UNSET:
            field_dict["base"] = base
        if load is not UNSET:
            field_dict["load"] = load
        if normal is not UNSET:
            field_dict["normal"] = normal
        if tip is not UNSET:
            field_dict["tip"] = tip

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        direction = cast(list[float], d.pop("direction"))

        kind = ControlOutKind(d.pop("kind"))

        def _parse_base(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                base_type_0 = cast(list[float], data)

                return base_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        base = _parse_base(d.pop("base", UNSET))

        def _parse_load(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                load_type_0 = cast(list[float], data)

                return load_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        load = _parse_load(d.pop("load", UNSET))

        def _parse_normal(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                normal_type_0 = cast(list[float], data)

                return normal_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        normal = _parse_normal(d.pop("normal", UNSET))

        def _parse_tip(data: object) -> ControlOutTipType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                tip_type_0 = ControlOutTipType0(data)

                return tip_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ControlOutTipType0 | None | Unset, data)

        tip = _parse_tip(d.pop("tip", UNSET))

        control_out = cls(
            direction=direction,
            kind=kind,
            base=base,
            load=load,
            normal=normal,
            tip=tip,
        )

        control_out.additional_properties = d
        return control_out

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
