from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.job_created_analysis import JobCreatedAnalysis
from ..models.job_created_status import JobCreatedStatus

T = TypeVar("T", bound="JobCreated")


@_attrs_define
class JobCreated:
    """
    Attributes:
        analysis (JobCreatedAnalysis):
        id (str): job id (use it in /v1/jobs/{id})
        status (JobCreatedStatus):
        total (int): number of points (a figure job: its steps)
    """

    analysis: JobCreatedAnalysis
    id: str
    status: JobCreatedStatus
    total: int
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        analysis = self.analysis.value

        id = self.id

        status = self.status.value

        total = self.total

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "analysis": analysis,
                "id": id,
                "status": status,
                "total": total,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        analysis = JobCreatedAnalysis(d.pop("analysis"))

        id = d.pop("id")

        status = JobCreatedStatus(d.pop("status"))

        total = d.pop("total")

        job_created = cls(
            analysis=analysis,
            id=id,
            status=status,
            total=total,
        )

        job_created.additional_properties = d
        return job_created

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
