"""The FastAPI application: ``create_app(settings)`` and the module-level ``app``; wiring only.

Run it with ``tensegrity-opt serve`` (one uvicorn process; the executors of :mod:`service.execution` supply the
parallelism). The app holds its settings, its executors, its job runner and its metrics in ``app.state``; the
routers of :mod:`service.api.routes`, the error handlers, the middleware and the offline docs are attached here.
Nothing imports this module but the entry points (the console script, ``uvicorn service.main:app``).
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

from . import tasks
from .api import errors, swagger
from .api.deps import require_api_key
from .api.metrics import Metrics, MetricsMiddleware
from .api.middleware import BodyLimitMiddleware, MethodsMiddleware
from .api.openapi import DESCRIPTION, TAGS, finish_document
from .api.routes import (
    atlas,
    batch,
    buckling,
    control,
    curves,
    design,
    equilibrium,
    health,
    landscape,
    modes,
    ops,
    paths,
    plots,
    segment,
    stiffness,
    stream,
    web,
)
from .api.routes import jobs as jobs_routes
from .config import Settings, get_settings
from .execution import Executors
from .jobs import JobRunner
from .responses import SafeJSONResponse

#: Routers behind the API key (when keys are configured: the API, its version and metrics; the OpenAPI document
#: too, :mod:`service.api.swagger`) and the open ones (health, the page).
API_ROUTERS = (equilibrium, buckling, curves, stiffness, modes, segment, landscape, batch, design, paths, atlas,
               control, plots, jobs_routes, ops)
OPEN_ROUTERS = (health, web)
#: The WebSocket routes: they check the API key themselves (a FastAPI dependency on ``Request`` does not
#: apply to a WebSocket; the key may also come as ``?api_key=``, which browsers can send).
STREAM_ROUTERS = (stream,)
#: Seconds the job runner and the solver threads each get to stop at shutdown.
SHUTDOWN_JOIN = 0.5
#: Methods a browser page may use across origins (DELETE: remove a job).
CORS_METHODS = ["GET", "HEAD", "POST", "DELETE"]

log = logging.getLogger("service")

__all__ = ["create_app", "openapi_document", "openapi_json", "SafeJSONResponse"]


def create_app(settings: Settings | None = None) -> FastAPI:
    """A new application (its own solver pool and metrics registry) for ``settings``."""
    settings = settings if settings is not None else get_settings()
    executors = Executors(settings, warmup=tasks.equilibria.warmup, loaded=tasks.loaded)
    metrics = Metrics(executors)
    runner = JobRunner(settings)

    @asynccontextmanager
    async def lifespan(app: FastAPI) -> AsyncIterator[None]:
        if settings.kernel_builds == "background":
            tasks.equilibria.build_in_background()     # before the warm-up: it never waits for the compiler
        await executors.start()
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
            executors.stop(SHUTDOWN_JOIN)

    app = FastAPI(
        title="tensegrity-opt service", version=tensegrity_opt.__version__, description=DESCRIPTION,
        # the document and the docs pages are service.api.swagger's (answered from bytes built once)
        openapi_tags=TAGS, openapi_url=None, docs_url=None, redoc_url=None, lifespan=lifespan,
        # No trailing-slash redirect: it builds an absolute Location from the request's Host header
        # (an open redirect through a forged Host); "/healthz/" is a plain 404 instead.
        redirect_slashes=False,
        default_response_class=SafeJSONResponse,
        license_info={"name": "MIT"},
    )
    app.state.settings = settings
    app.state.executors = executors
    app.state.metrics = metrics
    app.state.jobs = runner
    app.state.ready = False

    errors.install(app)
    # The API key check is attached only where it can refuse anything: a FastAPI dependency costs
    # ~35 us per request even when it returns at once. The document still declares it (see below).
    auth = [Depends(require_api_key)] if settings.auth_enabled else []
    for module in API_ROUTERS:
        app.include_router(module.router, dependencies=auth)
    for module in OPEN_ROUTERS + STREAM_ROUTERS:
        app.include_router(module.router)
    swagger.install(app, auth)
    # Every server serves the same document (the committed openapi/openapi.json): the API as
    # declared, X-API-Key included, whether or not this server has keys configured.
    app.openapi = openapi_document  # type: ignore[method-assign]

    # Order (outermost first): metrics, CORS, the answer of a request cut by shutdown, body size limit,
    # HEAD/OPTIONS, the app.
    app.add_middleware(MethodsMiddleware, routes=lambda: app.router.routes)
    app.add_middleware(BodyLimitMiddleware, max_bytes=settings.max_body_bytes)
    app.add_middleware(errors.ShutdownAnswerMiddleware, retry_after=settings.retry_after)
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
    return finish_document(FastAPI.openapi(app))


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
