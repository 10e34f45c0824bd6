from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.ready_status import ReadyStatus

T = TypeVar("T", bound="Ready")


@_attrs_define
class Ready:
    """
    Attributes:
        in_flight (int):
        queue_size (int):
        status (ReadyStatus):
        workers (int):
    """

    in_flight: int
    queue_size: int
    status: ReadyStatus
    workers: int
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        in_flight = self.in_flight

        queue_size = self.queue_size

        status = self.status.value

        workers = self.workers

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "in_flight": in_flight,
                "queue_size": queue_size,
                "status": status,
                "workers": workers,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        in_flight = d.pop("in_flight")

        queue_size = d.pop("queue_size")

        status = ReadyStatus(d.pop("status"))

        workers = d.pop("workers")

        ready = cls(
            in_flight=in_flight,
            queue_size=queue_size,
            status=status,
            workers=workers,
        )

        ready.additional_properties = d
        return ready

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
