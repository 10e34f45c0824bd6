"""Operations: the server's version and limits, and its metrics (behind the API key when the server has keys; the
health routes, always open, are :mod:`.health`).

``/version`` is answered from bytes built once and built again only when the kernels loaded in the process change
(its only part that changes while the server runs): answering it must not cost the event loop more than the
bytes' hand-off, whatever a client pipelines.
"""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter, Request
from starlette.responses import Response

import tensegrity_opt
from tensegrity_opt.numerics import kernels
from tensegrity_opt.numerics.build import compiler_name

from ... import schemas as s
from ...responses import render_json
from ..metrics import CONTENT_TYPE_LATEST
from ..openapi import error_responses

router = APIRouter(tags=["ops"])

API_VERSION = "v1"
METRICS_EXAMPLE = ("# HELP tensegrity_http_requests_total HTTP requests answered\n"
                   "# TYPE tensegrity_http_requests_total counter\n")


@router.get(
    "/version", operation_id="version", response_model=s.VersionOut,
    summary="Versions, the server's limits and how its Newton kernels run",
    responses={200: {"description": "versions and limits", "content": {"application/json": {"example": {
        "service": "tensegrity-opt", "version": tensegrity_opt.__version__,
        "library_version": tensegrity_opt.__version__, "api": API_VERSION, "auth": False,
        "limits": {"max_segments": 200, "max_batch": 1000, "solve_timeout": 10.0, "batch_timeout": 60.0,
                   "workers": 2, "queue_size": 64, "inline_max_segments": 8, "inline_processes": 1,
                   "max_body_bytes": 1048576, "max_response_bytes": 8388608,
                   "max_curve_points": s.MAX_CURVE_POINTS, "max_path_points": 5000, "max_atlas_targets": 400,
                   "max_trajectory_steps": 2000, "max_grid": s.MAX_GRID,
                   "max_torque_points": s.MAX_TORQUE_POINTS, "max_stream_connections": 16,
                   "stream_idle_timeout": 60.0},
        "kernels": {"compiler": "cc 12.2.0", "max_segments": 8, "compiled": [4], "virtual_machine": [],
                    "building": [5, 6]}}}}},
               **error_responses(401)})
async def version(request: Request) -> Response:
    state = request.app.state
    loaded = (kernels.libraries(), tuple(n for n in range(2, kernels.KERNEL_MAX + 1) if kernels.pending(n)))
    built = getattr(state, "version_bytes", None)
    if built is None or built[0] != loaded:
        built = state.version_bytes = (loaded, render_json(version_body(request)))
    return Response(built[1], media_type="application/json")


def version_body(request: Request) -> dict[str, Any]:
    """The body of ``/version`` (built when the kernels loaded in the process change: :func:`version`)."""
    st = request.app.state.settings
    k = kernels.status()
    return {"service": "tensegrity-opt", "version": tensegrity_opt.__version__,
            "library_version": tensegrity_opt.__version__, "api": API_VERSION, "auth": st.auth_enabled,
            "limits": {"max_segments": st.max_segments, "max_batch": st.max_batch, "solve_timeout": st.solve_timeout,
                       "batch_timeout": st.batch_timeout, "workers": st.workers, "queue_size": st.queue_size,
                       "inline_max_segments": st.inline_max_segments,
                       "inline_processes": fast.workers if (fast := request.app.state.executors.fast) else 0,
                       "max_body_bytes": st.max_body_bytes, "max_response_bytes": st.max_response_bytes,
                       "max_curve_points": s.MAX_CURVE_POINTS, "max_path_points": st.max_path_points,
                       "max_atlas_targets": st.max_atlas_targets, "max_trajectory_steps": st.max_trajectory_steps,
                       "max_grid": s.MAX_GRID, "max_torque_points": s.MAX_TORQUE_POINTS,
                       "max_stream_connections": st.max_stream_connections,
                       "stream_idle_timeout": st.stream_idle_timeout},
            "kernels": {"compiler": compiler_name(),
                        **{key: k[key] for key in ("max_segments", "compiled", "virtual_machine", "building")}}}


@router.get(
    "/metrics", operation_id="metrics", summary="Prometheus metrics (text exposition format)",
    response_class=Response,
    responses={200: {"description": "request counts, latencies, solver failures, pool gauges",
                     "content": {"text/plain": {"schema": {"type": "string"}, "example": METRICS_EXAMPLE}}},
               **error_responses(401)})
async def metrics(request: Request) -> Response:
    return Response(content=request.app.state.metrics.render(), media_type=CONTENT_TYPE_LATEST)
