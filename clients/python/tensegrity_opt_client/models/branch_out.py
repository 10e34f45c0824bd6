from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar

from attrs import define as _attrs_define
from attrs import field as _attrs_field

if TYPE_CHECKING:
    from ..models.branch_point import BranchPoint


T = TypeVar("T", bound="BranchOut")


@_attrs_define
class BranchOut:
    """
    Attributes:
        id (int):
        points (list[BranchPoint]):
    """

    id: int
    points: list[BranchPoint]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        id = self.id

        points = []
        for points_item_data in self.points:
            points_item = points_item_data.to_dict()
            points.append(points_item)

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "id": id,
                "points": points,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.branch_point import BranchPoint  # noqa: PLC0415

        d = dict(src_dict)
        id = d.pop("id")

        points = []
        _points = d.pop("points")
        for points_item_data in _points:
            points_item = BranchPoint.from_dict(points_item_data)

            points.append(points_item)

        branch_out = cls(
            id=id,
            points=points,
        )

        branch_out.additional_properties = d
        return branch_out

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
