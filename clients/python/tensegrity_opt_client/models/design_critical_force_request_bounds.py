from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

if TYPE_CHECKING:
    from ..models.bounds_in import BoundsIn


T = TypeVar("T", bound="DesignCriticalForceRequestBounds")


@_attrs_define
class DesignCriticalForceRequestBounds:
    """bounds per variable; default (x0 / 10, 10 x0)"""

    additional_properties: dict[str, BoundsIn | list[float | list[float]]] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:

        field_dict: dict[str, Any] = {}
        for prop_name, prop in self.additional_properties.items():
            if isinstance(prop, list):
                field_dict[prop_name] = []
                for additional_property_type_0_item_data in prop:
                    additional_property_type_0_item: float | list[float]
                    if isinstance(additional_property_type_0_item_data, list):
                        additional_property_type_0_item = additional_property_type_0_item_data

                    else:
                        additional_property_type_0_item = additional_property_type_0_item_data
                    field_dict[prop_name].append(additional_property_type_0_item)

            else:
                field_dict[prop_name] = prop.to_dict()

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.bounds_in import BoundsIn  # noqa: PLC0415

        d = dict(src_dict)
        design_critical_force_request_bounds = cls()

        additional_properties = {}
        for prop_name, prop_dict in d.items():

            def _parse_additional_property(data: object) -> BoundsIn | list[float | list[float]]:
                try:
                    if not isinstance(data, list):
                        raise TypeError()
                    additional_property_type_0 = []
                    _additional_property_type_0 = data
                    for additional_property_type_0_item_data in _additional_property_type_0:

                        def _parse_additional_property_type_0_item(data: object) -> float | list[float]:
                            try:
                                if not isinstance(data, list):
                                    raise TypeError()
                                additional_property_type_0_item_type_1 = cast(list[float], data)

                                return additional_property_type_0_item_type_1
                            except (TypeError, ValueError, AttributeError, KeyError):
                                pass
                            return cast(float | list[float], data)

                        additional_property_type_0_item = _parse_additional_property_type_0_item(
                            additional_property_type_0_item_data
                        )

                        additional_property_type_0.append(additional_property_type_0_item)

                    return additional_property_type_0
                except (TypeError, ValueError, AttributeError, KeyError):
                    pass
                if not isinstance(data, dict):
                    raise TypeError()
                additional_property_type_1 = BoundsIn.from_dict(data)

                return additional_property_type_1

            additional_property = _parse_additional_property(prop_dict)

            additional_properties[prop_name] = additional_property

        design_critical_force_request_bounds.additional_properties = additional_properties
        return design_critical_force_request_bounds

    @property
    def additional_keys(self) -> list[str]:
        return list(self.additional_properties.keys())

    def __getitem__(self, key: str) -> BoundsIn | list[float | list[float]]:
        return self.additional_properties[key]

    def __setitem__(self, key: str, value: BoundsIn | list[float | list[float]]) -> None:
        self.additional_properties[key] = value

    def __delitem__(self, key: str) -> None:
        del self.additional_properties[key]

    def __contains__(self, key: str) -> bool:
        return key in self.additional_properties
