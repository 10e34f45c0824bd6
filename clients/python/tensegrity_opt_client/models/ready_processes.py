from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar

from attrs import define as _attrs_define
from attrs import field as _attrs_field

if TYPE_CHECKING:
    from ..models.processes_state import ProcessesState


T = TypeVar("T", bound="ReadyProcesses")


@_attrs_define
class ReadyProcesses:
    """the solver processes: fast (the short chains' bounded first try; while it is not up the solver threads answer those
    requests, slower) and design (/v1/design/*, plans, stiffness shaping); absent when the server has none

    """

    additional_properties: dict[str, ProcessesState] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:

        field_dict: dict[str, Any] = {}
        for prop_name, prop in self.additional_properties.items():
            field_dict[prop_name] = prop.to_dict()

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.processes_state import ProcessesState  # noqa: PLC0415

        d = dict(src_dict)
        ready_processes = cls()

        additional_properties = {}
        for prop_name, prop_dict in d.items():
            additional_property = ProcessesState.from_dict(prop_dict)

            additional_properties[prop_name] = additional_property

        ready_processes.additional_properties = additional_properties
        return ready_processes

    @property
    def additional_keys(self) -> list[str]:
        return list(self.additional_properties.keys())

    def __getitem__(self, key: str) -> ProcessesState:
        return self.additional_properties[key]

    def __setitem__(self, key: str, value: ProcessesState) -> None:
        self.additional_properties[key] = value

    def __delitem__(self, key: str) -> None:
        del self.additional_properties[key]

    def __contains__(self, key: str) -> bool:
        return key in self.additional_properties
