"""Service settings: one pydantic-settings class read from ``TENSEGRITY_*`` environment variables.

Every field has an embedded default, so ``tensegrity-opt serve`` runs with no configuration.

=====================================  =========  ==================================================
variable                               default    meaning
=====================================  =========  ==================================================
``TENSEGRITY_MAX_SEGMENTS``            200        largest chain accepted (``too_many_segments`` above)
``TENSEGRITY_MAX_BATCH``               1000       most targets in one ``/v1/batch/equilibrium``
``TENSEGRITY_SOLVE_TIMEOUT``           10         seconds one request may run (504; its computation is stopped)
``TENSEGRITY_HOMOTOPY_MAX_SEGMENTS``   5          longest chain for ``method: homotopy`` (``too_many_segments``)
``TENSEGRITY_BATCH_TIMEOUT``           60         seconds a batch may run (later targets: ``timeout``)
``TENSEGRITY_MAX_PATH_POINTS``         5000       most points of one branch (``max_points`` of the path endpoints)
``TENSEGRITY_MAX_ATLAS_TARGETS``       400        most targets of ``/v1/atlas`` (``atlas_too_large`` above: a job)
``TENSEGRITY_MAX_TRAJECTORY_STEPS``    2000       most steps of ``/v1/control/plan``, ``/v1/control/simulate``
``TENSEGRITY_WORKERS``                 2          solver threads (each owns its CasADi instances)
``TENSEGRITY_INLINE_MAX_SEGMENTS``     8          short monotonic chains: bounded Newton-only search first
``TENSEGRITY_INLINE_PROCESSES``        1          solver processes for that search (0: none, the solver threads)
``TENSEGRITY_QUEUE_SIZE``              64         requests waiting for a solver thread (503 beyond)
``TENSEGRITY_HEAVY_THREADS``           (auto)     solver threads heavy requests may hold at once (``WORKERS`` - 1, >= 1)
``TENSEGRITY_HEAVY_SEGMENTS``          50         chains longer than this make curves/equilibria requests heavy
``TENSEGRITY_HEAVY_WORKERS``           1          killable processes for ``/v1/design/*`` (0: the solver threads)
``TENSEGRITY_HEAVY_QUEUE_SIZE``        4          design requests waiting for such a process (503 beyond)
``TENSEGRITY_HEAVY_GRACE``             0.5        seconds after a 504 before a design process still busy is killed
``TENSEGRITY_REQUEST_TIMEOUT``         10         seconds to receive a whole request (headers + body): 408/closed
``TENSEGRITY_MAX_CONNECTIONS``         (auto)     open connections; beyond, the oldest idle/half-sent one is closed
``TENSEGRITY_MAX_HEADER_BYTES``        65536      bytes of a request's line and headers (431 above)
``TENSEGRITY_MAX_HEADERS``             100        header fields of one request (431 above)
``TENSEGRITY_LIMIT_CONCURRENCY``       (auto)     uvicorn ``limit_concurrency``: 503 beyond this many requests
``TENSEGRITY_KEEP_ALIVE``              5          seconds an idle keep-alive connection stays open
``TENSEGRITY_BACKLOG``                 2048       listen backlog (connections not accepted yet)
``TENSEGRITY_RETRY_AFTER``             1          ``Retry-After`` seconds sent with 503
``TENSEGRITY_API_KEYS``                (empty)    comma-separated or JSON list; empty: auth off
``TENSEGRITY_CORS_ORIGINS``            (empty)    comma-separated or JSON list; empty: CORS off (also the stream's)
``TENSEGRITY_MAX_BODY_BYTES``          1048576    request bodies above this get 413
``TENSEGRITY_MAX_RESPONSE_BYTES``      8388608    JSON answers above this: 422 ``response_too_large``
``TENSEGRITY_WARMUP``                  true       build each thread's solvers (n = 4) at start-up
``TENSEGRITY_KERNEL_BUILDS``           background compiled code built in the background (``request``: on first use)
``TENSEGRITY_SHUTDOWN_TIMEOUT``        1          seconds requests in flight get at SIGTERM, then cancelled (503)
``TENSEGRITY_MAX_STREAM_CONNECTIONS``  16         open ``/v1/control/stream`` WebSockets (beyond: closed with 1013)
``TENSEGRITY_STREAM_IDLE_TIMEOUT``     60         seconds a stream may stay silent (then closed with 1001)
``TENSEGRITY_JOBS_DB``                 (file)     SQLite job store, ``tensegrity_jobs.sqlite3`` in the working dir
``TENSEGRITY_JOBS_SCHEDULER``          (unset)    jobs: unset/``serial`` runner thread; ``local``/``tcp://..`` Dask
``TENSEGRITY_JOBS_MAX_POINTS``         100000     most points in one job (422 above)
``TENSEGRITY_JOBS_RESUME``             true       resume jobs a stopped server left running
``TENSEGRITY_JOBS_SYNCHRONOUS``        NORMAL     SQLite ``synchronous`` (NORMAL survives a kill, FULL a power cut)
``TENSEGRITY_JOBS_CHUNK_SIZE``         (auto)     points per Dask task
``TENSEGRITY_JOBS_POINT_TIMEOUT``      300        seconds one job point may run (then an error row ``timeout``)
``TENSEGRITY_JOBS_MAX_RUNNING``        2          jobs a server runs at once (the rest wait, ``queued``)
``TENSEGRITY_JOBS_SLICE_SECONDS``      30         a running job yields to a waiting one after this (round-robin)
``TENSEGRITY_JOBS_RETENTION_DAYS``     7          finished jobs older than this are deleted; 0: kept forever
``TENSEGRITY_JOBS_LEASE_SECONDS``      60         a server's claim on a running job, renewed every third of it
``TENSEGRITY_JOBS_RESULTS_MAX_LIMIT``  10000      most rows in one JSON page of ``/v1/jobs/{id}/results``
``TENSEGRITY_JOBS_RETRY_SECONDS``      5          a failing job store is retried this often (``/readyz``: 503 till then)
=====================================  =========  ==================================================

(auto): ``MAX_CONNECTIONS`` is the process's descriptor limit (``RLIMIT_NOFILE``) minus 64 for the
server's own files, at most 1024; ``LIMIT_CONCURRENCY`` that plus 8 (the cap, which makes room by closing
idle or half-sent connections, decides first). The request timeout, the
connection cap and the header bounds are enforced by ``tensegrity-opt serve`` (:mod:`service.api.connections`);
an app started by a bare ``uvicorn service.main:app`` has only what uvicorn's own options give.
"""

from __future__ import annotations

import json
import resource
from functools import lru_cache
from typing import Annotated, Any, Literal

from pydantic import Field, field_validator
from pydantic_settings import BaseSettings, NoDecode, SettingsConfigDict

#: Caps baked into the request schema (the OpenAPI document does not depend on the settings).
#: They are the defaults of the settings below, so the committed document says exactly what a
#: server at its default settings accepts; the settings can only be tighter (then the domain codes
#: ``too_many_segments`` / ``batch_too_large`` answer what the document allows and the server not).
HARD_MAX_SEGMENTS = 200
HARD_MAX_BATCH = 1000
HARD_MAX_PATH_POINTS = 5000
#: Most targets (dx values x dy values) of one inline atlas (``/v1/atlas``, ``/v1/plots/atlas``); larger grids
#: are jobs (``/v1/jobs`` with ``analysis: atlas``). The schema bounds each axis by it; the product is the
#: setting's to check (JSON Schema cannot bound a product).
HARD_MAX_ATLAS_TARGETS = 400
#: Most steps (samples) of one trajectory of the control endpoints (``/v1/control/plan``: targets,
#: ``/v1/control/simulate``: preloads, loads, targets; their figures).
HARD_MAX_TRAJECTORY_STEPS = 2000


def _split(value: Any) -> Any:
    if isinstance(value, str):
        text = value.strip()
        if not text:
            return []
        if text.startswith("["):
            return json.loads(text)
        return [part.strip() for part in text.split(",") if part.strip()]
    return value


class Settings(BaseSettings):
    """Configuration of one service process (environment prefix ``TENSEGRITY_``)."""

    model_config = SettingsConfigDict(env_prefix="TENSEGRITY_", extra="ignore", frozen=True)

    max_segments: int = Field(HARD_MAX_SEGMENTS, ge=1, le=HARD_MAX_SEGMENTS, description="largest chain accepted")
    max_batch: int = Field(HARD_MAX_BATCH, ge=1, le=HARD_MAX_BATCH, description="most targets in one batch")
    solve_timeout: float = Field(10.0, gt=0, description="seconds one request may wait for its result")
    homotopy_max_segments: int = Field(
        5, ge=0, le=6,
        description="longest chain for which /v1/equilibria accepts method=homotopy (the parameter homotopy, "
                    "batched tracker; measured on 2 cores: n = 4 ~0.25 s, n = 5 ~2 s (up to 4.5 s), n = 6 ~20 s: "
                    "raise solve_timeout with it); 0: refused")
    batch_timeout: float = Field(60.0, gt=0, description="seconds one batch may run")
    max_path_points: int = Field(
        HARD_MAX_PATH_POINTS, ge=2, le=HARD_MAX_PATH_POINTS,
        description="most points of one branch the path endpoints (/v1/branch, /v1/bifurcation-diagram, "
                    "/v1/limit-load, /v1/stability-boundary and their figures) follow (max_points above: "
                    "422 too_many_points)")
    max_atlas_targets: int = Field(
        HARD_MAX_ATLAS_TARGETS, ge=1, le=HARD_MAX_ATLAS_TARGETS,
        description="most targets (dx values x dy values) of one /v1/atlas or /v1/plots/atlas request (above: 422 "
                    "atlas_too_large; larger grids run as a job, POST /v1/jobs with analysis atlas)")
    max_trajectory_steps: int = Field(
        HARD_MAX_TRAJECTORY_STEPS, ge=1, le=HARD_MAX_TRAJECTORY_STEPS,
        description="most steps of one trajectory of /v1/control/plan (targets) and /v1/control/simulate "
                    "(preloads, loads, targets) and their figures (above: 422 too_many_steps naming the field)")
    workers: int = Field(2, ge=1, le=64, description="solver worker threads")
    inline_max_segments: int = Field(
        8, ge=0, le=64,
        description="/v1/equilibrium for chains up to this many segments (with monotonic segments) is first "
                    "solved by the bounded Newton-only search in a solver process (a few hundred microseconds, "
                    "less than the hand-off to a worker thread); what it does not settle goes to the workers. "
                    "0: always the workers")
    inline_processes: int = Field(
        1, ge=0, le=64,
        description="solver processes for that bounded search (service.execution): the event loop hands the "
                    "request over and goes on with HTTP meanwhile; while none is ready the workers solve it. 0: no "
                    "process, the workers solve every request")
    queue_size: int = Field(64, ge=0, le=100000, description="requests waiting for a worker before 503")
    heavy_threads: int | None = Field(
        None, ge=1, le=64,
        description="solver threads the heavy request classes (batches, curves and figures with branch=all, "
                    "method=homotopy, curves/equilibria of chains longer than heavy_segments) may hold at once; "
                    "default workers - 1 (at least 1), so a light request always finds a thread")
    heavy_segments: int = Field(50, ge=1, le=HARD_MAX_SEGMENTS,
                                description="curves/equilibria requests on longer chains count as heavy")
    heavy_workers: int = Field(
        1, ge=0, le=64,
        description="killable solver processes for the design endpoints (service.execution): killed after the "
                    "deadline when a solve cannot stop by itself, so a 504 frees its capacity; these requests never "
                    "hold a solver thread. 0: design requests run in the solver threads")
    heavy_queue_size: int = Field(4, ge=0, le=10000, description="design requests waiting for a process before 503")
    heavy_grace: float = Field(0.5, ge=0, le=60,
                               description="seconds after a design 504 before a busy process is killed")
    request_timeout: float = Field(10.0, gt=0, le=3600,
                                   description="seconds to receive a whole request (408 / connection closed)")
    max_connections: int | None = Field(None, ge=1, le=1_000_000,
                                        description="open connections (default: descriptor limit - 64, <= 1024)")
    limit_concurrency: int | None = Field(None, ge=1, le=1_000_000,
                                          description="uvicorn limit_concurrency (default: max_connections + 8)")
    max_header_bytes: int = Field(
        65536, ge=1024, le=16 * 1024 * 1024,
        description="bytes of a request's line and headers together (above: 431 headers_too_large and the "
                    "connection closed; tensegrity-opt serve)")
    max_headers: int = Field(100, ge=8, le=10000,
                             description="header fields of one request (above: 431 headers_too_large)")
    keep_alive: int = Field(5, ge=1, le=3600, description="seconds an idle keep-alive connection stays open")
    backlog: int = Field(2048, ge=1, le=65535, description="listen backlog")
    retry_after: int = Field(1, ge=0, description="Retry-After seconds sent with 503")
    api_keys: Annotated[list[str], NoDecode] = Field(default_factory=list, description="accepted X-API-Key values")
    cors_origins: Annotated[list[str], NoDecode] = Field(
        default_factory=list, description="allowed CORS origins; also the web pages' origins that may open the "
                                          "control stream besides the server's own (others: 403 forbidden_origin)")
    max_body_bytes: int = Field(1024 * 1024, ge=1, description="largest request body (413 above)")
    max_response_bytes: int = Field(
        8 * 1024 * 1024, ge=1024,
        description="largest JSON answer (422 response_too_large above: estimated before solving where the "
                    "request says enough, else counted while rendering in the solver thread)")
    warmup: bool = Field(True, description="build each worker's solvers at start-up")
    kernel_builds: Literal["background", "request"] = Field(
        "background",
        description="background: the server compiles the short chains' Newton kernels in the background at start-up "
                    "(and any other compiled function, or one whose file left the cache, when first needed), and a "
                    "request arriving before its code is compiled is solved in CasADi's virtual machine (slower, the "
                    "same answers) instead of waiting for the C compiler; request: the first request for a chain "
                    "length waits for the compiler (the library's own default)")
    shutdown_timeout: float = Field(
        1.0, ge=0, le=600,
        description="seconds requests in flight get to finish at SIGTERM/SIGINT before they are cancelled "
                    "and answered 503 shutting_down with Retry-After (uvicorn's timeout_graceful_shutdown; "
                    "tensegrity-opt serve)")
    max_stream_connections: int = Field(
        16, ge=1, le=1024,
        description="control streams (/v1/control/stream) open at once, each with its own solver thread; a "
                    "stream beyond it gets an error message and is closed with 1013 (try again later)")
    stream_idle_timeout: float = Field(
        60.0, gt=0, le=86400,
        description="seconds a control stream may send nothing; then it gets an error message (idle_timeout) "
                    "and is closed with 1001 (going away)")
    jobs_db: str = Field("tensegrity_jobs.sqlite3", min_length=1, description="SQLite file of the job store")
    jobs_scheduler: str | None = Field(None, description="None/serial: in-process thread; local; tcp://host:port")
    jobs_max_points: int = Field(100_000, ge=1, le=1_000_000, description="most points in one job")
    jobs_resume: bool = Field(True, description="resume jobs left running by a previous process")
    jobs_synchronous: Literal["NORMAL", "FULL"] = Field("NORMAL", description="SQLite synchronous mode")
    jobs_chunk_size: int | None = Field(None, ge=1, description="points per Dask task (default: automatic)")
    jobs_point_timeout: float = Field(
        300.0, gt=0, description="seconds one job point may run in the runner thread; then its row is the error "
                                 "'timeout: ...' and the job goes on (not applied on Dask)")
    jobs_max_running: int = Field(2, ge=1, le=64, description="jobs this server runs at the same time")
    jobs_slice_seconds: float = Field(
        30.0, gt=0, description="a running job hands its runner over to a waiting job after this many seconds "
                                "(between two points; round-robin in order of arrival)")
    jobs_retention_days: float = Field(
        7.0, ge=0, description="finished jobs (done, failed, cancelled, interrupted) older than this are deleted "
                               "with their rows, at start-up and hourly; 0: kept forever")
    jobs_lease_seconds: float = Field(
        60.0, ge=0.3, le=3600, description="a server's lease on a job it runs, renewed every third of it; a job "
                                           "whose lease expired (its server died) is taken over by another server")
    jobs_results_max_limit: int = Field(10_000, ge=1, le=1_000_000,
                                        description="most rows in one JSON page of GET /v1/jobs/{id}/results")
    jobs_retry_seconds: float = Field(
        5.0, ge=0.05, le=3600, description="while the job store fails (a full disk, an unreadable file ...), it is "
                                           "retried this often; /readyz answers 503 until a retry succeeds")

    @field_validator("jobs_scheduler", mode="before")
    @classmethod
    def _scheduler(cls, value: Any) -> Any:
        if value is None:
            return None
        text = str(value).strip()
        if text in ("", "serial", "none", "None"):
            return None
        if text != "local" and "://" not in text:
            raise ValueError("expected serial, local or a Dask scheduler address like tcp://host:8786")
        return text

    @field_validator("api_keys", "cors_origins", mode="before")
    @classmethod
    def _lists(cls, value: Any) -> Any:
        return _split(value)

    @property
    def auth_enabled(self) -> bool:
        return bool(self.api_keys)

    @property
    def connection_cap(self) -> int:
        """``max_connections``, or the default derived from the descriptor limit."""
        return self.max_connections if self.max_connections is not None else _default_connections()

    @property
    def concurrency_cap(self) -> int:
        # above the connection cap by default: uvicorn counts connections too, and the cap (which
        # closes idle or half-sent connections to make room) must decide before uvicorn's 503 does
        return self.limit_concurrency if self.limit_concurrency is not None else self.connection_cap + 8


def _default_connections() -> int:
    try:
        soft = resource.getrlimit(resource.RLIMIT_NOFILE)[0]
    except (OSError, ValueError):  # pragma: no cover
        soft = 1024
    if soft == resource.RLIM_INFINITY or soft <= 0:
        soft = 1 << 20
    return max(16, min(1024, soft - 64))


@lru_cache
def get_settings() -> Settings:
    """The process settings (read once from the environment)."""
    return Settings()
