from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.job_summary_analysis import JobSummaryAnalysis
from ..models.job_summary_status import JobSummaryStatus
from ..types import UNSET, Unset

T = TypeVar("T", bound="JobSummary")


@_attrs_define
class JobSummary:
    """
    Attributes:
        analysis (JobSummaryAnalysis): the sweep's analysis, or figure (a figure as a job)
        created_at (str): ISO 8601, UTC
        done (int): points finished and stored (failed points included)
        failed (int): finished points whose row has an error
        id (str):
        progress (float): done / total
        runs (int): times the job was started (> 1: resumed after a server restart)
        status (JobSummaryStatus): queued | running | done | failed | cancelled | interrupted
        total (int): points in the sweep (a figure job: its steps)
        finished_at (None | str | Unset):
        message (None | str | Unset): why the job failed, was cancelled or interrupted
        started_at (None | str | Unset):
    """

    analysis: JobSummaryAnalysis
    created_at: str
    done: int
    failed: int
    id: str
    progress: float
    runs: int
    status: JobSummaryStatus
    total: int
    finished_at: None | str | Unset = UNSET
    message: None | str | Unset = UNSET
    started_at: None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        analysis = self.analysis.value

        created_at = self.created_at

        done = self.done

        failed = self.failed

        id = self.id

        progress = self.progress

        runs = self.runs

        status = self.status.value

        total = self.total

        finished_at: None | str | Unset
        if isinstance(self.finished_at, Unset):
            finished_at = UNSET
        else:
            finished_at = self.finished_at

        message: None | str | Unset
        if isinstance(self.message, Unset):
            message = UNSET
        else:
            message = self.message

        started_at: None | str | Unset
        if isinstance(self.started_at, Unset):
            started_at = UNSET
        else:
            started_at = self.started_at

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "analysis": analysis,
                "created_at": created_at,
                "done": done,
                "failed": failed,
                "id": id,
                "progress": progress,
                "runs": runs,
                "status": status,
                "total": total,
            }
        )
        if finished_at is not UNSET:
            field_dict["finished_at"] = finished_at
        if message is not UNSET:
            field_dict["message"] = message
        if started_at is not UNSET:
            field_dict["started_at"] = started_at

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        analysis = JobSummaryAnalysis(d.pop("analysis"))

        created_at = d.pop("created_at")

        done = d.pop("done")

        failed = d.pop("failed")

        id = d.pop("id")

        progress = d.pop("progress")

        runs = d.pop("runs")

        status = JobSummaryStatus(d.pop("status"))

        total = d.pop("total")

        def _parse_finished_at(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        finished_at = _parse_finished_at(d.pop("finished_at", UNSET))

        def _parse_message(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        message = _parse_message(d.pop("message", UNSET))

        def _parse_started_at(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        started_at = _parse_started_at(d.pop("started_at", UNSET))

        job_summary = cls(
            analysis=analysis,
            created_at=created_at,
            done=done,
            failed=failed,
            id=id,
            progress=progress,
            runs=runs,
            status=status,
            total=total,
            finished_at=finished_at,
            message=message,
            started_at=started_at,
        )

        job_summary.additional_properties = d
        return job_summary

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
