from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="Limits")


@_attrs_define
class Limits:
    """
    Attributes:
        batch_timeout (float):
        inline_max_segments (int):
        inline_processes (int): solver processes running the short chains' bounded search (service.execution); 0: the
            solver threads run it
        max_atlas_targets (int): most targets of one /v1/atlas or /v1/plots/atlas (422 atlas_too_large; larger grids: a
            job with analysis atlas)
        max_batch (int):
        max_body_bytes (int):
        max_curve_points (int):
        max_grid (int):
        max_path_points (int): most points per branch of the path endpoints (422 too_many_points)
        max_response_bytes (int): largest JSON answer (422 response_too_large above)
        max_segments (int):
        max_stream_connections (int): control streams (WebSocket /v1/control/stream) open at once; beyond, closed with
            1013
        max_torque_points (int):
        max_trajectory_steps (int): most steps of one /v1/control/plan or /v1/control/simulate trajectory (422
            too_many_steps)
        queue_size (int):
        solve_timeout (float):
        stream_idle_timeout (float): seconds a control stream may send nothing before it is closed with 1001
        workers (int):
    """

    batch_timeout: float
    inline_max_segments: int
    inline_processes: int
    max_atlas_targets: int
    max_batch: int
    max_body_bytes: int
    max_curve_points: int
    max_grid: int
    max_path_points: int
    max_response_bytes: int
    max_segments: int
    max_stream_connections: int
    max_torque_points: int
    max_trajectory_steps: int
    queue_size: int
    solve_timeout: float
    stream_idle_timeout: float
    workers: int
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        batch_timeout = self.batch_timeout

        inline_max_segments = self.inline_max_segments

        inline_processes = self.inline_processes

        max_atlas_targets = self.max_atlas_targets

        max_batch = self.max_batch

        max_body_bytes = self.max_body_bytes

        max_curve_points = self.max_curve_points

        max_grid = self.max_grid

        max_path_points = self.max_path_points

        max_response_bytes = self.max_response_bytes

        max_segments = self.max_segments

        max_stream_connections = self.max_stream_connections

        max_torque_points = self.max_torque_points

        max_trajectory_steps = self.max_trajectory_steps

        queue_size = self.queue_size

        solve_timeout = self.solve_timeout

        stream_idle_timeout = self.stream_idle_timeout

        workers = self.workers

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "batch_timeout": batch_timeout,
                "inline_max_segments": inline_max_segments,
                "inline_processes": inline_processes,
                "max_atlas_targets": max_atlas_targets,
                "max_batch": max_batch,
                "max_body_bytes": max_body_bytes,
                "max_curve_points": max_curve_points,
                "max_grid": max_grid,
                "max_path_points": max_path_points,
                "max_response_bytes": max_response_bytes,
                "max_segments": max_segments,
                "max_stream_connections": max_stream_connections,
                "max_torque_points": max_torque_points,
                "max_trajectory_steps": max_trajectory_steps,
                "queue_size": queue_size,
                "solve_timeout": solve_timeout,
                "stream_idle_timeout": stream_idle_timeout,
                "workers": workers,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        batch_timeout = d.pop("batch_timeout")

        inline_max_segments = d.pop("inline_max_segments")

        inline_processes = d.pop("inline_processes")

        max_atlas_targets = d.pop("max_atlas_targets")

        max_batch = d.pop("max_batch")

        max_body_bytes = d.pop("max_body_bytes")

        max_curve_points = d.pop("max_curve_points")

        max_grid = d.pop("max_grid")

        max_path_points = d.pop("max_path_points")

        max_response_bytes = d.pop("max_response_bytes")

        max_segments = d.pop("max_segments")

        max_stream_connections = d.pop("max_stream_connections")

        max_torque_points = d.pop("max_torque_points")

        max_trajectory_steps = d.pop("max_trajectory_steps")

        queue_size = d.pop("queue_size")

        solve_timeout = d.pop("solve_timeout")

        stream_idle_timeout = d.pop("stream_idle_timeout")

        workers = d.pop("workers")

        limits = cls(
            batch_timeout=batch_timeout,
            inline_max_segments=inline_max_segments,
            inline_processes=inline_processes,
            max_atlas_targets=max_atlas_targets,
            max_batch=max_batch,
            max_body_bytes=max_body_bytes,
            max_curve_points=max_curve_points,
            max_grid=max_grid,
            max_path_points=max_path_points,
            max_response_bytes=max_response_bytes,
            max_segments=max_segments,
            max_stream_connections=max_stream_connections,
            max_torque_points=max_torque_points,
            max_trajectory_steps=max_trajectory_steps,
            queue_size=queue_size,
            solve_timeout=solve_timeout,
            stream_idle_timeout=stream_idle_timeout,
            workers=workers,
        )

        limits.additional_properties = d
        return limits

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
