"""Shared route dependencies: settings, API-key auth, size limits, and :func:`solve`, the one place
that decides where a solve runs (a solver process or the solver pool; never the event loop)."""

from __future__ import annotations

import asyncio
import secrets
import time
from collections.abc import Callable
from typing import Any

from fastapi import Request, Security
from fastapi.security import APIKeyHeader
from starlette.responses import Response

from . import schemas as s
from .compute import manipulator_form, segment_count
from .config import Settings
from .errors import FieldContext, ServiceError
from .lane import LaneUnavailable, SolverLane
from .pool import SolveTimeout
from .responses import JSONBody, ResponseTooLarge, render_task

__all__ = ["api_key_header", "require_api_key", "api_key_valid", "get_settings_dep", "check_manipulator", "check_batch",
           "check_curve_size", "check_path_points", "check_atlas_targets", "check_trajectory_steps", "path_deadline",
           "solve", "solve_heavy",
           "is_heavy"]

api_key_header = APIKeyHeader(
    name="X-API-Key", auto_error=False, scheme_name="ApiKey",
    description="Required only when the server is configured with API keys (TENSEGRITY_API_KEYS); "
                "otherwise ignored.")


async def get_settings_dep(request: Request) -> Settings:
    # async on purpose: FastAPI runs a plain ``def`` dependency in a worker thread, a ~0.1 ms hand-off
    return request.app.state.settings


async def require_api_key(request: Request, key: str | None = Security(api_key_header)) -> None:
    """401 unless auth is off or ``X-API-Key`` is one of the configured keys (constant-time compare)."""
    settings: Settings = request.app.state.settings
    if not settings.api_keys or api_key_valid(key, settings):
        return
    raise ServiceError(401, "unauthorized",
                       "missing API key: send the X-API-Key header" if not key else "invalid API key",
                       field="X-API-Key", headers={"WWW-Authenticate": "ApiKey"})


def api_key_valid(key: str | None, settings: Settings) -> bool:
    """``key`` is one of the configured API keys (constant-time compare; the REST routes and the stream)."""
    if not key:
        return False
    given = key.encode("utf-8", "surrogateescape")
    return any(secrets.compare_digest(given, k.encode("utf-8", "surrogateescape")) for k in settings.api_keys)


def check_manipulator(m: Any, settings: Settings) -> FieldContext:
    """Refuse chains longer than ``settings.max_segments`` (422 ``too_many_segments``)."""
    n = segment_count(m)
    form = manipulator_form(m)
    if n > settings.max_segments:
        raise ServiceError(422, "too_many_segments",
                           f"the chain has {n} segments; this server accepts at most {settings.max_segments}",
                           field="manipulator.n" if form == "uniform" else "manipulator.segments",
                           details={"n": n, "max_segments": settings.max_segments})
    return FieldContext(manipulator=form)


def check_homotopy(req: s.EquilibriaRequest, settings: Settings) -> None:
    """Refuse ``method: homotopy`` for chains longer than ``settings.homotopy_max_segments`` (422)."""
    if req.method != "homotopy":
        return
    n = segment_count(req.manipulator)
    if n > settings.homotopy_max_segments:
        raise ServiceError(422, "too_many_segments",
                           f"method 'homotopy' is accepted here for chains of up to {settings.homotopy_max_segments} "
                           f"segments (its path count grows ~8x a segment); the chain has {n}: use method 'search'",
                           field="method", details={"n": n, "homotopy_max_segments": settings.homotopy_max_segments})


#: Rough bytes of one curve row: ~20 per joint angle plus the other fields.
CURVE_ROW_BYTES_PER_JOINT = 20
CURVE_ROW_BYTES = 300


def check_curve_size(n: int, points: int, branch: str, settings: Settings) -> None:
    """Refuse before solving a curve whose answer is sure to exceed ``max_response_bytes`` (422
    ``response_too_large`` on ``dx``): ``points`` rows of ``n`` angles, twice for ``branch = "all"``
    (the stable rows and at least one branch). The rendered body is counted too (the number of
    branches is known only after solving)."""
    estimate = points * (n * CURVE_ROW_BYTES_PER_JOINT + CURVE_ROW_BYTES) * (2 if branch == "all" else 1)
    if estimate > settings.max_response_bytes:
        raise ResponseTooLarge(settings.max_response_bytes, "dx", estimate)


def check_batch(req: s.BatchEquilibriumRequest, settings: Settings) -> None:
    if len(req.targets) > settings.max_batch:
        raise ServiceError(422, "batch_too_large",
                           f"the batch has {len(req.targets)} targets; this server accepts at most "
                           f"{settings.max_batch}", field="targets",
                           details={"targets": len(req.targets), "max_batch": settings.max_batch})


def check_path_points(max_points: int, settings: Settings) -> None:
    """Refuse a branch of more points than ``settings.max_path_points`` (422 ``too_many_points``)."""
    if max_points > settings.max_path_points:
        raise ServiceError(422, "too_many_points",
                           f"max_points = {max_points}; this server follows at most {settings.max_path_points} "
                           "points per branch", field="max_points",
                           details={"max_points": max_points, "max_path_points": settings.max_path_points})


def _axis_size(v: Any) -> int:
    return int(v.num) if isinstance(v, s.RangeIn) else len(v)


def check_atlas_targets(req: Any, settings: Settings) -> None:
    """Refuse an inline atlas of more targets (dx values x dy values) than ``settings.max_atlas_targets`` (422
    ``atlas_too_large`` on ``dx``): a larger grid is a job (``POST /v1/jobs`` with ``analysis: atlas``)."""
    nx, ny = _axis_size(req.dx), _axis_size(req.dy)
    if nx * ny > settings.max_atlas_targets:
        raise ServiceError(422, "atlas_too_large",
                           f"the atlas has {nx * ny} targets ({nx} dx x {ny} dy); this server computes at most "
                           f"{settings.max_atlas_targets} in one request: submit it as a job, POST /v1/jobs with "
                           '{"analysis": "atlas", "grid": {"dx": [...], "dy": [...]}}, then GET /v1/jobs/{id}/atlas',
                           field="dx", details={"targets": nx * ny, "nx": nx, "ny": ny,
                                                "max_atlas_targets": settings.max_atlas_targets})


def check_trajectory_steps(settings: Settings, **series: Any) -> None:
    """Refuse a trajectory of more steps than ``settings.max_trajectory_steps`` (422 ``too_many_steps`` naming the
    first series over it): ``series`` are the request's per-step lists by field name (``None``: not given)."""
    limit = settings.max_trajectory_steps
    for field, values in series.items():
        if values is not None and len(values) > limit:
            raise ServiceError(422, "too_many_steps",
                               f"{field} holds {len(values)} steps; this server computes at most {limit} steps of a "
                               "trajectory in one request", field=field,
                               details={"steps": len(values), "max_trajectory_steps": limit})


#: Seconds of the time limit a path computation leaves for its answer (rendering, the hand-off back):
#: ``max(PATH_MARGIN, PATH_MARGIN_FRACTION * solve_timeout)``, at most half the limit.
PATH_MARGIN = 0.5
PATH_MARGIN_FRACTION = 0.1


def path_deadline(settings: Settings) -> float:
    """The ``time.monotonic()`` deadline of a continuation (``tensegrity_opt.trace_branch`` and the analyses
    on it take ``timeout`` and answer the points computed so far, ``status: "time_limit"``): before the
    request's time limit, so that the partial answer is sent instead of a 504. The task turns it into the
    seconds left when it starts (time spent queued counts)."""
    t = settings.solve_timeout
    return time.monotonic() + max(t - max(PATH_MARGIN, PATH_MARGIN_FRACTION * t), 0.5 * t)


async def solve(request: Request, fn: Callable[..., Any], *args: Any, ctx: FieldContext,
                timeout: float | None = None,
                fast: tuple[Callable[..., Any], tuple[Any, ...]] | None = None,
                heavy: bool = False, size_field: str | None = None) -> Any:
    """The one dispatcher of a solve: ``fn(*args)`` under the time limit, never on the event loop.

    Where the call runs is decided here, once:

    * ``fast = (g, g_args)`` (given by the route only for a request the bounded search may settle,
      e.g. :func:`service.compute.equilibrium_newton_args`) and a solver process is ready and not
      saturated: ``g(*g_args)`` runs in that process (:mod:`service.lane`), so the event loop goes on
      with HTTP meanwhile (a thread hand-off costs ~0.1-0.2 ms, as much as a whole short-chain solve).
      Its answer is sent as it is; when it does not settle the request (``None``) or the process
      cannot answer (not running, restarting, saturated, died, or the call raised there: the pool
      then raises that error again with its full type), ``fn`` runs in the pool with the time left.
    * otherwise: ``fn(*args)`` in the solver pool (:mod:`service.pool`); ``heavy`` marks a long
      request class (:func:`is_heavy`): such calls hold at most ``heavy_threads`` solver threads.

    Both sites produce the body the same way (:func:`service.responses.render_task`: the task's
    JSON-ready dict, rendered where it ran within ``max_response_bytes``; over it, 422
    ``response_too_large`` naming ``size_field``), so FastAPI's response-model pass is skipped and
    the response schema is checked by the tests for both. Errors map through ``service.errors``.
    """
    request.state.field_context = ctx
    settings: Settings = request.app.state.settings
    timeout = timeout or settings.solve_timeout
    limit = settings.max_response_bytes
    if fast is not None:
        lane = _pick_lane(request.app.state.lanes)
        if lane is not None:
            g, g_args = fast
            start = time.monotonic()
            try:
                body = await lane.run(render_task, g, g_args, limit, size_field, timeout=timeout)
            except LaneUnavailable:
                body = None
            except (asyncio.TimeoutError, TimeoutError):
                raise SolveTimeout(timeout) from None
            if body is not None:
                return Response(body, media_type="application/json")
            timeout = max(timeout - (time.monotonic() - start), MIN_TIME_LEFT)
    body = await request.app.state.pool.run(render_task, fn, args, limit, size_field, timeout=timeout, heavy=heavy)
    if isinstance(body, JSONBody):
        return Response(body, media_type="application/json")
    return body             # a figure's bytes (the route adds its media type)


#: Seconds the pool gets at least after a solver process's miss (the request's time limit goes on).
MIN_TIME_LEFT = 0.001


def is_heavy(settings: Settings, m: Any, *, branch_all: bool = False, homotopy: bool = False) -> bool:
    """The fairness class of a solver-thread request: every branch, the homotopy, or a long chain."""
    return branch_all or homotopy or segment_count(m) > settings.heavy_segments


async def solve_heavy(request: Request, fn: Callable[..., Any], *args: Any, ctx: FieldContext,
                      size_field: str | None = None) -> Any:
    """:func:`solve` for the heavy request classes (``/v1/design/*``, ``/v1/control/plan``): in a killable solver
    process (:mod:`service.heavy`) under the time limit, so a 504 frees its capacity and these requests never
    hold a solver thread; in the solver threads when ``heavy_workers`` is 0. With ``size_field`` the result is
    rendered where it was computed (:func:`service.responses.render_task`, within ``max_response_bytes``,
    ``response_too_large`` naming ``size_field``) and answered as those bytes (a figure's bytes come back as
    they are either way)."""
    heavy = request.app.state.heavy
    if heavy is None:
        return await solve(request, fn, *args, ctx=ctx, heavy=True, size_field=size_field)
    request.state.field_context = ctx
    settings: Settings = request.app.state.settings
    if size_field is None:
        return await heavy.run(fn, *args, timeout=settings.solve_timeout)
    body = await heavy.run(render_task, fn, args, settings.max_response_bytes, size_field,
                           timeout=settings.solve_timeout)
    if isinstance(body, JSONBody):
        return Response(bytes(body), media_type="application/json")
    return body


def _pick_lane(lanes: list[SolverLane]) -> SolverLane | None:
    """The solver process with the fewest calls outstanding (the first one if none is ready)."""
    if len(lanes) == 1:
        return lanes[0]
    return min(lanes, key=lambda la: (not la.ready, la.in_flight), default=None)
