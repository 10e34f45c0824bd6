from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.processes_state_state import ProcessesStateState

T = TypeVar("T", bound="ProcessesState")


@_attrs_define
class ProcessesState:
    """Solver processes of one kind and where they stand.

    Attributes:
        ready (int): processes ready
        restarts (int): processes started to replace lost ones since the server started
        state (ProcessesStateState): up: every process ready; starting: warming up; restarting: processes were lost and
            are replaced (after a delay growing with each loss in a row, at most 30 s); down: stopped, or this platform
            cannot start them
        workers (int): processes configured
    """

    ready: int
    restarts: int
    state: ProcessesStateState
    workers: int
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        ready = self.ready

        restarts = self.restarts

        state = self.state.value

        workers = self.workers

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "ready": ready,
                "restarts": restarts,
                "state": state,
                "workers": workers,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        ready = d.pop("ready")

        restarts = d.pop("restarts")

        state = ProcessesStateState(d.pop("state"))

        workers = d.pop("workers")

        processes_state = cls(
            ready=ready,
            restarts=restarts,
            state=state,
            workers=workers,
        )

        processes_state.additional_properties = d
        return processes_state

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
