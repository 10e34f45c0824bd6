from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.stiffness_bound_in import StiffnessBoundIn


T = TypeVar("T", bound="StiffnessBoundsIn")


@_attrs_define
class StiffnessBoundsIn:
    """Bounds on the entries of the tip's Cartesian stiffness (force / length).

    Attributes:
        kxx (list[float | None] | None | StiffnessBoundIn | Unset):
        kxy (list[float | None] | None | StiffnessBoundIn | Unset):
        kyy (list[float | None] | None | StiffnessBoundIn | Unset):
    """

    kxx: list[float | None] | None | StiffnessBoundIn | Unset = UNSET
    kxy: list[float | None] | None | StiffnessBoundIn | Unset = UNSET
    kyy: list[float | None] | None | StiffnessBoundIn | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.stiffness_bound_in import StiffnessBoundIn  # noqa: PLC0415

        kxx: dict[str, Any] | list[float | None] | None | Unset
        if isinstance(self.kxx, Unset):
            kxx = UNSET
        elif isinstance(self.kxx, list):
            kxx = []
            for kxx_type_0_type_0_item_data in self.kxx:
                kxx_type_0_type_0_item: float | None
                kxx_type_0_type_0_item = kxx_type_0_type_0_item_data
                kxx.append(kxx_type_0_type_0_item)

        elif isinstance(self.kxx, StiffnessBoundIn):
            kxx = self.kxx.to_dict()
        else:
            kxx = self.kxx

        kxy: dict[str, Any] | list[float | None] | None | Unset
        if isinstance(self.kxy, Unset):
            kxy = UNSET
        elif isinstance(self.kxy, list):
            kxy = []
            for kxy_type_0_type_0_item_data in self.kxy:
                kxy_type_0_type_0_item: float | None
                kxy_type_0_type_0_item = kxy_type_0_type_0_item_data
                kxy.append(kxy_type_0_type_0_item)

        elif isinstance(self.kxy, StiffnessBoundIn):
            kxy = self.kxy.to_dict()
        else:
            kxy = self.kxy

        kyy: dict[str, Any] | list[float | None] | None | Unset
        if isinstance(self.kyy, Unset):
            kyy = UNSET
        elif isinstance(self.kyy, list):
            kyy = []
            for kyy_type_0_type_0_item_data in self.kyy:
                kyy_type_0_type_0_item: float | None
                kyy_type_0_type_0_item = kyy_type_0_type_0_item_data
                kyy.append(kyy_type_0_type_0_item)

        elif isinstance(self.kyy, StiffnessBoundIn):
            kyy = self.kyy.to_dict()
        else:
            kyy = self.kyy

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if kxx is not UNSET:
            field_dict["kxx"] = kxx
        if kxy is not UNSET:
            field_dict["kxy"] = kxy
        if kyy is not UNSET:
            field_dict["kyy"] = kyy

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.stiffness_bound_in import StiffnessBoundIn  # noqa: PLC0415

        d = dict(src_dict)

        def _parse_kxx(data: object) -> list[float | None] | None | StiffnessBoundIn | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                kxx_type_0_type_0 = []
                _kxx_type_0_type_0 = data
                for kxx_type_0_type_0_item_data in _kxx_type_0_type_0:

                    def _parse_kxx_type_0_type_0_item(data: object) -> float | None:
                        if data is None:
                            return data
                        return cast(float | None, data)

                    kxx_type_0_type_0_item = _parse_kxx_type_0_type_0_item(kxx_type_0_type_0_item_data)

                    kxx_type_0_type_0.append(kxx_type_0_type_0_item)

                return kxx_type_0_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                kxx_type_0_type_1 = StiffnessBoundIn.from_dict(data)

                return kxx_type_0_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float | None] | None | StiffnessBoundIn | Unset, data)

        kxx = _parse_kxx(d.pop("kxx", UNSET))

        def _parse_kxy(data: object) -> list[float | None] | None | StiffnessBoundIn | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                kxy_type_0_type_0 = []
                _kxy_type_0_type_0 = data
                for kxy_type_0_type_0_item_data in _kxy_type_0_type_0:

                    def _parse_kxy_type_0_type_0_item(data: object) -> float | None:
                        if data is None:
                            return data
                        return cast(float | None, data)

                    kxy_type_0_type_0_item = _parse_kxy_type_0_type_0_item(kxy_type_0_type_0_item_data)

                    kxy_type_0_type_0.append(kxy_type_0_type_0_item)

                return kxy_type_0_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                kxy_type_0_type_1 = StiffnessBoundIn.from_dict(data)

                return kxy_type_0_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float | None] | None | StiffnessBoundIn | Unset, data)

        kxy = _parse_kxy(d.pop("kxy", UNSET))

        def _parse_kyy(data: object) -> list[float | None] | None | StiffnessBoundIn | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                kyy_type_0_type_0 = []
                _kyy_type_0_type_0 = data
                for kyy_type_0_type_0_item_data in _kyy_type_0_type_0:

                    def _parse_kyy_type_0_type_0_item(data: object) -> float | None:
                        if data is None:
                            return data
                        return cast(float | None, data)

                    kyy_type_0_type_0_item = _parse_kyy_type_0_type_0_item(kyy_type_0_type_0_item_data)

                    kyy_type_0_type_0.append(kyy_type_0_type_0_item)

                return kyy_type_0_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                kyy_type_0_type_1 = StiffnessBoundIn.from_dict(data)

                return kyy_type_0_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float | None] | None | StiffnessBoundIn | Unset, data)

        kyy = _parse_kyy(d.pop("kyy", UNSET))

        stiffness_bounds_in = cls(
            kxx=kxx,
            kxy=kxy,
            kyy=kyy,
        )

        return stiffness_bounds_in
