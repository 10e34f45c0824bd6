"""Shared route dependencies: settings, API-key auth, size limits, running a solve in the pool."""

from __future__ import annotations

import asyncio
import secrets
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
from .responses import ResponseTooLarge, render_json_bounded

__all__ = ["api_key_header", "require_api_key", "get_settings_dep", "check_manipulator", "check_batch",
           "check_curve_size", "solve", "solve_heavy", "is_heavy"]

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
    if not settings.api_keys:
        return
    if key:
        given = key.encode("utf-8", "surrogateescape")
        if any(secrets.compare_digest(given, k.encode("utf-8", "surrogateescape")) for k in settings.api_keys):
            return
    raise ServiceError(401, "unauthorized",
                       "missing API key: send the X-API-Key header" if not key else "invalid API key",
                       field="X-API-Key", headers={"WWW-Authenticate": "ApiKey"})


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


def _rendered(fn: Callable[..., Any], args: tuple[Any, ...], limit: int, field: str | None) -> Any:
    """``fn(*args)``; a JSON result is rendered here, in the solver thread, within ``limit`` bytes
    (:class:`ResponseTooLarge` naming ``field`` otherwise). Bytes (figures) are returned as they are."""
    result = fn(*args)
    if isinstance(result, (bytes, Response)):
        return result
    return Response(render_json_bounded(result, limit, field), media_type="application/json")


async def solve(request: Request, fn: Callable[..., Any], *args: Any, ctx: FieldContext,
                timeout: float | None = None,
                inline: tuple[Callable[..., bytes | None], tuple[Any, ...]] | None = None,
                heavy: bool = False, size_field: str | None = None) -> Any:
    """Run ``fn(*args)`` in the solver pool under the time limit; errors map through ``service.errors``.

    ``inline = (g, g_args)``, when given, runs first: ``g(*g_args, max_segments=...)`` is a bounded
    fast path (``compute.equilibrium_inline``) that returns the rendered JSON body, or ``None`` to
    hand the request to the pool. ``heavy`` marks a long request class (:func:`is_heavy`): such calls
    hold at most ``heavy_threads`` solver threads at once. A JSON result of the pool is rendered in the
    solver thread (the event loop only sends the bytes; FastAPI's response-model pass is skipped),
    bounded by ``max_response_bytes``: over it, 422 ``response_too_large`` naming ``size_field``.
    The inline fast path runs in a solver process (:mod:`service.lane`) when one is
    ready, so the event loop goes on with HTTP meanwhile; otherwise (no process configured,
    starting, restarting, saturated, or the call raised there) on the event loop itself, which also
    raises any error again in-process. A thread hand-off costs ~0.1-0.2 ms here, as much as a whole
    short-chain solve, hence no solver thread for this path.
    """
    request.state.field_context = ctx
    settings: Settings = request.app.state.settings
    timeout = timeout or settings.solve_timeout
    if inline is not None and settings.inline_max_segments:
        g, g_args = inline
        body = None
        lane = _pick_lane(request.app.state.lanes)
        try:
            if lane is None:
                raise LaneUnavailable("no solver process")
            body = await lane.run(g, *g_args, timeout=timeout, max_segments=settings.inline_max_segments)
        except LaneUnavailable:
            body = g(*g_args, max_segments=settings.inline_max_segments)
        except (asyncio.TimeoutError, TimeoutError):
            raise SolveTimeout(timeout) from None
        if body is not None:
            return Response(body, media_type="application/json")
    return await request.app.state.pool.run(_rendered, fn, args, settings.max_response_bytes, size_field,
                                            timeout=timeout, heavy=heavy)


def is_heavy(settings: Settings, m: Any, *, branch_all: bool = False, homotopy: bool = False) -> bool:
    """The fairness class of a solver-thread request: every branch, the homotopy, or a long chain."""
    return branch_all or homotopy or segment_count(m) > settings.heavy_segments


async def solve_heavy(request: Request, fn: Callable[..., Any], *args: Any, ctx: FieldContext) -> Any:
    """:func:`solve` for the heavy request classes (``/v1/design/*``): in a killable solver process
    (:mod:`service.heavy`) under the time limit, so a 504 frees its capacity and these requests never
    hold a solver thread; in the solver threads when ``heavy_workers`` is 0."""
    heavy = request.app.state.heavy
    if heavy is None:
        return await solve(request, fn, *args, ctx=ctx, heavy=True)
    request.state.field_context = ctx
    settings: Settings = request.app.state.settings
    return await heavy.run(fn, *args, timeout=settings.solve_timeout)


def _pick_lane(lanes: list[SolverLane]) -> SolverLane | None:
    """The solver process with the fewest calls outstanding (the first one if none is ready)."""
    if len(lanes) == 1:
        return lanes[0]
    return min(lanes, key=lambda la: (not la.ready, la.in_flight), default=None)
