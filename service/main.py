"""The FastAPI application: ``create_app(settings)`` and the module-level ``app``.

Run it with ``tensegrity-opt serve`` (one uvicorn process; the solver threads of
:mod:`service.pool` and the solver processes of :mod:`service.lane` supply the parallelism).
"""

from __future__ import annotations

import asyncio
import gc
import json
import logging
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from functools import lru_cache
from typing import Any

from fastapi import Depends, FastAPI
from fastapi.middleware.cors import CORSMiddleware

import tensegrity_opt

from . import docs, errors, jobs
from .compute import warmup_task
from .config import Settings, get_settings
from .deps import require_api_key
from .heavy import ProcessLane
from .lane import SolverLane
from .metrics import Metrics, MetricsMiddleware
from .middleware import BodyLimitMiddleware, MethodsMiddleware
from .pool import SolverPool
from .sessions import StreamSlots
from .responses import SafeJSONResponse
from .routes import (atlas, batch, buckling, control, curves, design, equilibrium, landscape, ops, paths, plots,
                     segment, stiffness, stream, web)
from .routes import jobs as jobs_routes

#: Routers behind the API key (when keys are configured) and the open ones (health, version, page).
API_ROUTERS = (equilibrium, buckling, curves, stiffness, segment, landscape, batch, design, paths, atlas, control,
               plots, jobs_routes)
OPEN_ROUTERS = (ops, web)
#: The WebSocket routes: they check the API key themselves (a FastAPI dependency on ``Request`` does not
#: apply to a WebSocket; the key may also come as ``?api_key=``, which browsers can send).
STREAM_ROUTERS = (stream,)
#: Seconds the job runner and the solver threads each get to stop at shutdown.
SHUTDOWN_JOIN = 0.5
#: Methods a browser page may use across origins (DELETE: remove a job).
CORS_METHODS = ["GET", "HEAD", "POST", "DELETE"]

log = logging.getLogger("service")

__all__ = ["create_app", "openapi_document", "openapi_json", "SafeJSONResponse"]

DESCRIPTION = """\
Equilibria, stability, buckling and stiffness of compliant serial manipulators built from
dual-triangle tensegrity segments (the `tensegrity_opt` library) over HTTP.

Every `POST /v1/...` takes JSON and answers JSON in the caller's units (lengths, force per length,
forces, energies = force x length, angles in radians). A manipulator `M` is either
`{"n": 4, "a": 1, "b": 1, "k": 1, "L0": 1}` (n identical segments) or
`{"segments": [{"a", "b", "k": 1.0 | [k1, k2], "L0": 1.0 | [L1_0, L2_0]}, ...]}`.

Every refusal has the body `{"code", "message", "field", ...}`: 422 for schema violations
(`validation_error`, with the field path) and domain errors (`unreachable_target`,
`straight_not_equilibrium`, `straight_unstable`, `too_many_segments`, `solver_failed` /
`no_equilibrium` with the solver `status`, ...), 401 without a valid `X-API-Key` when the server has
keys, 413 for an oversized body, 422 `response_too_large` for an answer over the server's response size
limit (`field` names what to ask less of), 503 (`Retry-After`) when the solver pool is saturated, 504 when a
solve exceeds the time limit. The server's limits are at `GET /version`.

Control loops may use the WebSocket `/v1/control/stream` instead (one connection per chain, a step per
message, the same validation and error codes; OpenAPI does not describe WebSockets: see `docs/stream.md`).
"""

TAGS = [
    {"name": "equilibrium", "description": "Equilibria under a prescribed tip displacement or force."},
    {"name": "buckling", "description": "Critical loads and buckling modes of the straight chain."},
    {"name": "curves", "description": "Force-deflection curves by continuation."},
    {"name": "stiffness", "description": "Cartesian tangent stiffness."},
    {"name": "segment", "description": "One segment's torque and stiffness."},
    {"name": "landscape", "description": "Energy landscape of the 4-segment chain."},
    {"name": "batch", "description": "Many targets in one request (trajectories)."},
    {"name": "design", "description": "Design and control: strongest chain, preloads for a pose or a load."},
    {"name": "paths", "description": "Loading paths: rest configurations, equilibrium branches by arclength "
                                     "continuation, bifurcation diagrams, limit loads, stability boundaries."},
    {"name": "atlas", "description": "The workspace stability atlas of the held tip: stable equilibria over a grid "
                                     "of deflections, where the least-energy branch switches and where stable "
                                     "branches end (large grids: a job with analysis atlas)."},
    {"name": "control", "description": "Control: rest-length plans for tip trajectories (inverse statics per step), "
                                       "quasi-static simulation under sampled inputs with the snaps at folds, the "
                                       "tip force estimated from measured joint angles."},
    {"name": "plots", "description": "Figures (PNG or SVG): force-deflection curves, energy landscapes, equilibrium "
                                     "shapes, torque curves, critical-load maps, branch diagrams, limit loads, "
                                     "stability boundaries, stability atlases, rest-length plans, simulations."},
    {"name": "jobs", "description": "Sweeps as background jobs, stored in SQLite and resumed after a restart."},
    {"name": "ops", "description": "Health, readiness, version and Prometheus metrics."},
]


def create_app(settings: Settings | None = None) -> FastAPI:
    """A new application (its own solver pool and metrics registry) for ``settings``."""
    settings = settings if settings is not None else get_settings()
    pool = SolverPool(settings.workers, settings.queue_size, heavy_limit=settings.heavy_threads)
    heavy = (ProcessLane(settings.heavy_workers, settings.heavy_queue_size, grace=settings.heavy_grace)
             if settings.heavy_workers else None)
    streams = StreamSlots(settings.max_stream_connections)
    metrics = Metrics(pool, heavy, streams)
    runner = jobs.JobRunner(settings)
    lanes = [SolverLane(max_in_flight=max(settings.queue_size, 1))
             for _ in range(settings.inline_processes if settings.inline_max_segments else 0)]

    @asynccontextmanager
    async def lifespan(app: FastAPI) -> AsyncIterator[None]:
        pool.start()
        if heavy is not None and settings.warmup:
            heavy.start()       # the design processes import the library while the threads warm up
                                # (without warm-up: on the first design request)
        for lane in lanes:          # the solver processes warm up while the threads do
            try:
                await lane.start()
            except (OSError, ValueError) as exc:    # ValueError: no pass_fds on this platform
                log.warning("could not start a solver process (requests run in the solver threads): %r", exc)
        if settings.warmup:
            # One warm-up call per worker (best effort): each thread builds its CasADi instances.
            warmups = [pool.run(warmup_task, timeout=max(settings.solve_timeout, 30.0)) for _ in range(pool.workers)]
            for res in await asyncio.gather(*warmups, return_exceptions=True):
                if isinstance(res, BaseException):
                    log.warning("solver warm-up failed: %r", res)
            for lane in lanes:
                if not await lane.wait_ready(60.0):
                    log.warning("a solver process is not ready after 60 s; requests run in the solver threads")
        runner.start()
        # Everything built so far (modules, solvers, caches) lives as long as the process: move it
        # out of the collector's view. A full collection otherwise walks it all, ~50 ms every second
        # or so under load, which is a 50 ms stall of every request in flight (the p99).
        gc.collect()
        gc.freeze()
        app.state.ready = True
        try:
            yield
        finally:
            # Prompt (SIGTERM: well under 2 s): uvicorn first gives requests in flight
            # ``shutdown_timeout`` seconds, then cancels them (which interrupts their solves); the
            # job runner gets a second to finish its point (else the job stays ``running`` and is
            # resumed, that point again, by the next server); solver threads are daemons.
            app.state.ready = False
            await asyncio.to_thread(runner.stop, SHUTDOWN_JOIN)
            for lane in lanes:
                lane.close()
            if heavy is not None:
                heavy.close()
            streams.shutdown(SHUTDOWN_JOIN)
            pool.shutdown(wait=True, timeout=SHUTDOWN_JOIN)

    app = FastAPI(
        title="tensegrity-opt service", version=tensegrity_opt.__version__, description=DESCRIPTION,
        openapi_tags=TAGS, docs_url=None, redoc_url=None, lifespan=lifespan,
        # No trailing-slash redirect: it built an absolute Location from the request's Host header
        # (an open redirect through a forged Host); "/healthz/" is a plain 404 instead.
        redirect_slashes=False,
        default_response_class=SafeJSONResponse,
        license_info={"name": "MIT"},
    )
    app.state.settings = settings
    app.state.pool = pool
    app.state.lanes = lanes
    app.state.heavy = heavy
    app.state.metrics = metrics
    app.state.jobs = runner
    app.state.stream_slots = streams
    app.state.ready = False

    errors.install(app)
    # The API key check is attached only where it can refuse anything: a FastAPI dependency costs
    # ~35 us per request even when it returns at once. The document still declares it (see below).
    auth = [Depends(require_api_key)] if settings.auth_enabled else []
    for module in API_ROUTERS:
        app.include_router(module.router, dependencies=auth)
    for module in OPEN_ROUTERS + STREAM_ROUTERS:
        app.include_router(module.router)
    docs.install(app)
    # Every server serves the same document (the committed openapi/openapi.json): the API as
    # declared, X-API-Key included, whether or not this server has keys configured.
    app.openapi = openapi_document  # type: ignore[method-assign]

    # Order (outermost first): metrics, CORS, body size limit, HEAD/OPTIONS, the app.
    app.add_middleware(MethodsMiddleware, routes=lambda: app.router.routes)
    app.add_middleware(BodyLimitMiddleware, max_bytes=settings.max_body_bytes)
    if settings.cors_origins:
        app.add_middleware(CORSMiddleware, allow_origins=list(settings.cors_origins), allow_methods=CORS_METHODS,
                           allow_headers=["Content-Type", "X-API-Key"], expose_headers=["Retry-After"])
    app.add_middleware(MetricsMiddleware, metrics=metrics)
    return app


@lru_cache(maxsize=1)
def openapi_document() -> dict[str, Any]:
    """The OpenAPI document (built once per process); it does not depend on the environment: the
    defaults, with API keys configured so that the routes declare the ``X-API-Key`` scheme."""
    app = create_app(Settings.model_construct(api_keys=["(declared in the document)"]))
    doc = FastAPI.openapi(app)
    # A submitted job's id leads to its status, results and cancellation (OpenAPI links: clients
    # and stateful testing follow them).
    created = doc["paths"]["/v1/jobs"]["post"]["responses"]["202"]
    created["links"] = {op: {"operationId": op, "parameters": {"job_id": "$response.body#/id"},
                             "description": f"{op.replace('_', ' ')} of the job just submitted"}
                        for op in ("get_job", "get_job_results", "get_job_atlas", "cancel_job", "delete_job")}
    # The key is required only by servers that have keys: ``{}`` (no requirement) is the alternative.
    for item in doc["paths"].values():
        for op in item.values():
            if op.get("security") == [{"ApiKey": []}]:
                op["security"] = [{"ApiKey": []}, {}]
    return doc


def openapi_json() -> str:
    """``tensegrity-opt openapi`` output: sorted keys, indent 2, trailing newline."""
    return json.dumps(openapi_document(), sort_keys=True, indent=2) + "\n"


def __getattr__(name: str) -> Any:
    # ``service.main:app`` for ``uvicorn service.main:app``: built on first access from the environment.
    if name == "app":
        global app
        app = create_app()
        return app
    raise AttributeError(name)
