from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.job_results_status import JobResultsStatus
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.job_results_rows_item import JobResultsRowsItem


T = TypeVar("T", bound="JobResults")


@_attrs_define
class JobResults:
    """
    Attributes:
        columns (list[str]):
        complete (bool): every point is done
        done (int): rows there are (finished points, failed ones included)
        id (str):
        limit (int): most rows in this page (the one asked for, cut to the server's maximum)
        offset (int): index in the rows of the first row of this page
        rows (list[JobResultsRowsItem]): a page of rows, by index: index, the swept parameters, the analysis's columns,
            error
        status (JobResultsStatus):
        total (int):
        next_offset (int | None | Unset): offset of the next page; null on the last one
    """

    columns: list[str]
    complete: bool
    done: int
    id: str
    limit: int
    offset: int
    rows: list[JobResultsRowsItem]
    status: JobResultsStatus
    total: int
    next_offset: int | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        columns = self.columns

        complete = self.complete

        done = self.done

        id = self.id

        limit = self.limit

        offset = self.offset

        rows = []
        for rows_item_data in self.rows:
            rows_item = rows_item_data.to_dict()
            rows.append(rows_item)

        status = self.status.value

        total = self.total

        next_offset: int | None | Unset
        if isinstance(self.next_offset, Unset):
            next_offset = UNSET
        else:
            next_offset = self.next_offset

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "columns": columns,
                "complete": complete,
                "done": done,
                "id": id,
                "limit": limit,
                "offset": offset,
                "rows": rows,
                "status": status,
                "total": total,
            }
        )
        if next_offset is not UNSET:
            field_dict["next_offset"] = next_offset

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.job_results_rows_item import JobResultsRowsItem  # noqa: PLC0415

        d = dict(src_dict)
        columns = cast(list[str], d.pop("columns"))

        complete = d.pop("complete")

        done = d.pop("done")

        id = d.pop("id")

        limit = d.pop("limit")

        offset = d.pop("offset")

        rows = []
        _rows = d.pop("rows")
        for rows_item_data in _rows:
            rows_item = JobResultsRowsItem.from_dict(rows_item_data)

            rows.append(rows_item)

        status = JobResultsStatus(d.pop("status"))

        total = d.pop("total")

        def _parse_next_offset(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        next_offset = _parse_next_offset(d.pop("next_offset", UNSET))

        job_results = cls(
            columns=columns,
            complete=complete,
            done=done,
            id=id,
            limit=limit,
            offset=offset,
            rows=rows,
            status=status,
            total=total,
            next_offset=next_offset,
        )

        job_results.additional_properties = d
        return job_results

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
