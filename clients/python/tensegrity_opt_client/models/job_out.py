from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.job_out_analysis import JobOutAnalysis
from ..models.job_out_status import JobOutStatus
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.job_out_results_item import JobOutResultsItem
    from ..models.job_out_spec import JobOutSpec


T = TypeVar("T", bound="JobOut")


@_attrs_define
class JobOut:
    """
    Attributes:
        analysis (JobOutAnalysis): the sweep's analysis, or figure (a figure as a job)
        columns (list[str]): column order of the rows
        created_at (str): ISO 8601, UTC
        done (int): points finished and stored (failed points included)
        failed (int): finished points whose row has an error
        id (str):
        offset (int):
        progress (float): done / total
        results (list[JobOutResultsItem]): finished rows so far, by index (a page: offset, limit)
        runs (int): times the job was started (> 1: resumed after a server restart)
        spec (JobOutSpec): the normalised sweep spec (a figure job: analysis, kind, format and the figure's request)
        status (JobOutStatus): queued | running | done | failed | cancelled | interrupted
        total (int): points in the sweep (a figure job: its steps)
        finished_at (None | str | Unset):
        message (None | str | Unset): why the job failed, was cancelled or interrupted
        next_offset (int | None | Unset): offset of the next page of rows, when there is one
        started_at (None | str | Unset):
    """

    analysis: JobOutAnalysis
    columns: list[str]
    created_at: str
    done: int
    failed: int
    id: str
    offset: int
    progress: float
    results: list[JobOutResultsItem]
    runs: int
    spec: JobOutSpec
    status: JobOutStatus
    total: int
    finished_at: None | str | Unset = UNSET
    message: None | str | Unset = UNSET
    next_offset: int | None | Unset = UNSET
    started_at: None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        analysis = self.analysis.value

        columns = self.columns

        created_at = self.created_at

        done = self.done

        failed = self.failed

        id = self.id

        offset = self.offset

        progress = self.progress

        results = []
        for results_item_data in self.results:
            results_item = results_item_data.to_dict()
            results.append(results_item)

        runs = self.runs

        spec = self.spec.to_dict()

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

        next_offset: int | None | Unset
        if isinstance(self.next_offset, Unset):
            next_offset = UNSET
        else:
            next_offset = self.next_offset

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
                "columns": columns,
                "created_at": created_at,
                "done": done,
                "failed": failed,
                "id": id,
                "offset": offset,
                "progress": progress,
                "results": results,
                "runs": runs,
                "spec": spec,
                "status": status,
                "total": total,
            }
        )
        if finished_at is not UNSET:
            field_dict["finished_at"] = finished_at
        if message is not UNSET:
            field_dict["message"] = message
        if next_offset is not UNSET:
            field_dict["next_offset"] = next_offset
        if started_at is not UNSET:
            field_dict["started_at"] = started_at

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.job_out_results_item import JobOutResultsItem  # noqa: PLC0415
        from ..models.job_out_spec import JobOutSpec  # noqa: PLC0415

        d = dict(src_dict)
        analysis = JobOutAnalysis(d.pop("analysis"))

        columns = cast(list[str], d.pop("columns"))

        created_at = d.pop("created_at")

        done = d.pop("done")

        failed = d.pop("failed")

        id = d.pop("id")

        offset = d.pop("offset")

        progress = d.pop("progress")

        results = []
        _results = d.pop("results")
        for results_item_data in _results:
            results_item = JobOutResultsItem.from_dict(results_item_data)

            results.append(results_item)

        runs = d.pop("runs")

        spec = JobOutSpec.from_dict(d.pop("spec"))

        status = JobOutStatus(d.pop("status"))

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

        def _parse_next_offset(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        next_offset = _parse_next_offset(d.pop("next_offset", UNSET))

        def _parse_started_at(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        started_at = _parse_started_at(d.pop("started_at", UNSET))

        job_out = cls(
            analysis=analysis,
            columns=columns,
            created_at=created_at,
            done=done,
            failed=failed,
            id=id,
            offset=offset,
            progress=progress,
            results=results,
            runs=runs,
            spec=spec,
            status=status,
            total=total,
            finished_at=finished_at,
            message=message,
            next_offset=next_offset,
            started_at=started_at,
        )

        job_out.additional_properties = d
        return job_out

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
