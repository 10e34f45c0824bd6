from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.plot_atlas_job_request_format_type_0 import PlotAtlasJobRequestFormatType0
from ..types import UNSET, Unset

T = TypeVar("T", bound="PlotAtlasJobRequest")


@_attrs_define
class PlotAtlasJobRequest:
    """The atlas of a finished atlas job (`GET /v1/jobs/{id}/atlas`).

    Attributes:
        job (str): the id of a finished job with analysis atlas over a grid in dx and dy
        dpi (int | Unset): PNG resolution in dots per inch (30..200; default 120, the command line's too) Default: 120.
        edges (bool | Unset): locate the switches and branch ends on the grid edges (false: the counts only) Default:
            True.
        format_ (None | PlotAtlasJobRequestFormatType0 | Unset): "png" or "svg"; when absent the Accept header decides
            (image/svg+xml or image/png), PNG by default
    """

    job: str
    dpi: int | Unset = 120
    edges: bool | Unset = True
    format_: None | PlotAtlasJobRequestFormatType0 | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        job = self.job

        dpi = self.dpi

        edges = self.edges

        format_: None | str | Unset
        if isinstance(self.format_, Unset):
            format_ = UNSET
        elif isinstance(self.format_, PlotAtlasJobRequestFormatType0):
            format_ = self.format_.value
        else:
            format_ = self.format_

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "job": job,
            }
        )
        if dpi is not UNSET:
            field_dict["dpi"] = dpi
        if edges is not UNSET:
            field_dict["edges"] = edges
        if format_ is not UNSET:
            field_dict["format"] = format_

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        job = d.pop("job")

        dpi = d.pop("dpi", UNSET)

        edges = d.pop("edges", UNSET)

        def _parse_format_(data: object) -> None | PlotAtlasJobRequestFormatType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                format_type_0 = PlotAtlasJobRequestFormatType0(data)

                return format_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PlotAtlasJobRequestFormatType0 | Unset, data)

        format_ = _parse_format_(d.pop("format", UNSET))

        plot_atlas_job_request = cls(
            job=job,
            dpi=dpi,
            edges=edges,
            format_=format_,
        )

        return plot_atlas_job_request
