from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar

from attrs import define as _attrs_define
from attrs import field as _attrs_field

if TYPE_CHECKING:
    from ..models.equilibrium_out import EquilibriumOut


T = TypeVar("T", bound="EquilibriaOut")


@_attrs_define
class EquilibriaOut:
    """
    Attributes:
        certified (bool): true only when the set is proven complete (the homotopy tracked every path to an end and every
            real root polished; or a trivial case)
        equilibria (list[EquilibriumOut]): every equilibrium found, sorted by energy
        failed_paths (int): homotopy paths that failed (any makes `certified` false)
        method (str): how they were found: `search`, `homotopy`, or `straight` / `closed_form` for the trivial cases
        paths (int): homotopy paths tracked (0 for the search)
    """

    certified: bool
    equilibria: list[EquilibriumOut]
    failed_paths: int
    method: str
    paths: int
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        certified = self.certified

        equilibria = []
        for equilibria_item_data in self.equilibria:
            equilibria_item = equilibria_item_data.to_dict()
            equilibria.append(equilibria_item)

        failed_paths = self.failed_paths

        method = self.method

        paths = self.paths

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "certified": certified,
                "equilibria": equilibria,
                "failed_paths": failed_paths,
                "method": method,
                "paths": paths,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.equilibrium_out import EquilibriumOut  # noqa: PLC0415

        d = dict(src_dict)
        certified = d.pop("certified")

        equilibria = []
        _equilibria = d.pop("equilibria")
        for equilibria_item_data in _equilibria:
            equilibria_item = EquilibriumOut.from_dict(equilibria_item_data)

            equilibria.append(equilibria_item)

        failed_paths = d.pop("failed_paths")

        method = d.pop("method")

        paths = d.pop("paths")

        equilibria_out = cls(
            certified=certified,
            equilibria=equilibria,
            failed_paths=failed_paths,
            method=method,
            paths=paths,
        )

        equilibria_out.additional_properties = d
        return equilibria_out

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
