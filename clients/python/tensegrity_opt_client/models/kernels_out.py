from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="KernelsOut")


@_attrs_define
class KernelsOut:
    """How the compiled Newton kernels run in this server process (`tensegrity_opt.numerics.kernels`).

    Attributes:
        compiled (list[int]): chain lengths loaded as compiled code so far
        compiler (None | str): the C compiler used, by name and version (e.g. cc 12.2.0); null: none (kernels run in
            CasADi's VM)
        max_segments (int): chains up to this long have kernels
        virtual_machine (list[int]): chain lengths running in CasADi's virtual machine (no compiler, or compiling
            failed: about 4x slower)
        building (list[int] | Unset): chain lengths whose kernels compile in the background; their requests are answered
            in the virtual machine meanwhile
    """

    compiled: list[int]
    compiler: None | str
    max_segments: int
    virtual_machine: list[int]
    building: list[int] | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        compiled = self.compiled

        compiler: None | str
        compiler = self.compiler

        max_segments = self.max_segments

        virtual_machine = self.virtual_machine

        building: list[int] | Unset = UNSET
        if not isinstance(self.building, Unset):
            building = self.building

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "compiled": compiled,
                "compiler": compiler,
                "max_segments": max_segments,
                "virtual_machine": virtual_machine,
            }
        )
        if building is not UNSET:
            field_dict["building"] = building

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        compiled = cast(list[int], d.pop("compiled"))

        def _parse_compiler(data: object) -> None | str:
            if data is None:
                return data
            return cast(None | str, data)

        compiler = _parse_compiler(d.pop("compiler"))

        max_segments = d.pop("max_segments")

        virtual_machine = cast(list[int], d.pop("virtual_machine"))

        building = cast(list[int], d.pop("building", UNSET))

        kernels_out = cls(
            compiled=compiled,
            compiler=compiler,
            max_segments=max_segments,
            virtual_machine=virtual_machine,
            building=building,
        )

        kernels_out.additional_properties = d
        return kernels_out

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
