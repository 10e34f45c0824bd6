from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

if TYPE_CHECKING:
    from ..models.equilibrium_out import EquilibriumOut


T = TypeVar("T", bound="StiffnessOut")


@_attrs_define
class StiffnessOut:
    """
    Attributes:
        equilibrium (EquilibriumOut): An equilibrium configuration.
        matrix (list[list[float]]): 2 x 2 tangent stiffness dF_i / d tip_j (force / length)
    """

    equilibrium: EquilibriumOut
    matrix: list[list[float]]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        equilibrium = self.equilibrium.to_dict()

        matrix = []
        for matrix_item_data in self.matrix:
            matrix_item = matrix_item_data

            matrix.append(matrix_item)

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "equilibrium": equilibrium,
                "matrix": matrix,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.equilibrium_out import EquilibriumOut  # noqa: PLC0415

        d = dict(src_dict)
        equilibrium = EquilibriumOut.from_dict(d.pop("equilibrium"))

        matrix = []
        _matrix = d.pop("matrix")
        for matrix_item_data in _matrix:
            matrix_item = cast(list[float], matrix_item_data)

            matrix.append(matrix_item)

        stiffness_out = cls(
            equilibrium=equilibrium,
            matrix=matrix,
        )

        stiffness_out.additional_properties = d
        return stiffness_out

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
