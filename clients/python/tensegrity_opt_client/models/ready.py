from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.ready_degraded_item import ReadyDegradedItem
from ..models.ready_status import ReadyStatus
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.jobs_health import JobsHealth
    from ..models.ready_processes import ReadyProcesses


T = TypeVar("T", bound="Ready")


@_attrs_define
class Ready:
    """
    Attributes:
        in_flight (int):
        jobs (JobsHealth):
        queue_size (int):
        status (ReadyStatus): ready (200); starting (503); degraded (503): the solvers answer but the job store fails
            (see jobs)
        workers (int):
        degraded (list[ReadyDegradedItem] | Unset): what works degraded while the server answers: fast_path (the fast
            solver process is not up), design_processes (the design processes are restarting or down: those requests get
            503), job_store (the job store fails: status degraded, the jobs API answers 503)
        processes (ReadyProcesses | Unset): the solver processes: fast (the short chains' bounded first try; while it is
            not up the solver threads answer those requests, slower) and design (/v1/design/*, plans, stiffness shaping);
            absent when the server has none
    """

    in_flight: int
    jobs: JobsHealth
    queue_size: int
    status: ReadyStatus
    workers: int
    degraded: list[ReadyDegradedItem] | Unset = UNSET
    processes: ReadyProcesses | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        in_flight = self.in_flight

        jobs = self.jobs.to_dict()

        queue_size = self.queue_size

        status = self.status.value

        workers = self.workers

        degraded: list[str] | Unset = UNSET
        if not isinstance(self.degraded, Unset):
            degraded = []
            for degraded_item_data in self.degraded:
                degraded_item = degraded_item_data.value
                degraded.append(degraded_item)

        processes: dict[str, Any] | Unset = UNSET
        if not isinstance(self.processes, Unset):
            processes = self.processes.to_dict()

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "in_flight": in_flight,
                "jobs": jobs,
                "queue_size": queue_size,
                "status": status,
                "workers": workers,
            }
        )
        if degraded is not UNSET:
            field_dict["degraded"] = degraded
        if processes is not UNSET:
            field_dict["processes"] = processes

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.jobs_health import JobsHealth  # noqa: PLC0415
        from ..models.ready_processes import ReadyProcesses  # noqa: PLC0415

        d = dict(src_dict)
        in_flight = d.pop("in_flight")

        jobs = JobsHealth.from_dict(d.pop("jobs"))

        queue_size = d.pop("queue_size")

        status = ReadyStatus(d.pop("status"))

        workers = d.pop("workers")

        _degraded = d.pop("degraded", UNSET)
        degraded: list[ReadyDegradedItem] | Unset = UNSET
        if _degraded is not UNSET:
            degraded = []
            for degraded_item_data in _degraded:
                degraded_item = ReadyDegradedItem(degraded_item_data)

                degraded.append(degraded_item)

        _processes = d.pop("processes", UNSET)
        processes: ReadyProcesses | Unset
        if isinstance(_processes, Unset):
            processes = UNSET
        else:
            processes = ReadyProcesses.from_dict(_processes)

        ready = cls(
            in_flight=in_flight,
            jobs=jobs,
            queue_size=queue_size,
            status=status,
            workers=workers,
            degraded=degraded,
            processes=processes,
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
