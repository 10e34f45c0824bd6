"""Service settings: one pydantic-settings class read from ``TENSEGRITY_*`` environment variables.

Every field has an embedded default, so ``tensegrity-opt serve`` runs with no configuration.

=====================================  =========  ==================================================
variable                               default    meaning
=====================================  =========  ==================================================
``TENSEGRITY_MAX_SEGMENTS``            200        largest chain accepted (``too_many_segments`` above)
``TENSEGRITY_MAX_BATCH``               1000       most targets in one ``/v1/batch/equilibrium``
``TENSEGRITY_SOLVE_TIMEOUT``           10         seconds one request may wait for its result (504)
``TENSEGRITY_HOMOTOPY_MAX_SEGMENTS``   4          longest chain for ``method: homotopy`` (``too_many_segments`` on ``method``)
``TENSEGRITY_BATCH_TIMEOUT``           60         seconds a batch may run (later targets: ``timeout``)
``TENSEGRITY_WORKERS``                 2          solver threads (each owns its CasADi instances)
``TENSEGRITY_INLINE_MAX_SEGMENTS``     8          short monotonic chains: bounded Newton-only search first
``TENSEGRITY_INLINE_PROCESSES``        1          solver processes for that search (0: on the event loop)
``TENSEGRITY_QUEUE_SIZE``              64         requests waiting for a solver thread (503 beyond)
``TENSEGRITY_RETRY_AFTER``             1          ``Retry-After`` seconds sent with 503
``TENSEGRITY_API_KEYS``                (empty)    comma-separated or JSON list; empty: auth off
``TENSEGRITY_CORS_ORIGINS``            (empty)    comma-separated or JSON list; empty: CORS off
``TENSEGRITY_MAX_BODY_BYTES``          1048576    request bodies above this get 413
``TENSEGRITY_MAX_RESPONSE_BYTES``      8388608    JSON answers above this: 422 ``response_too_large``
``TENSEGRITY_WARMUP``                  true       build each thread's solvers (n = 4) at start-up
``TENSEGRITY_SHUTDOWN_TIMEOUT``        1          seconds requests in flight get at SIGTERM, then cancelled
``TENSEGRITY_JOBS_DB``                 (file)     SQLite job store, ``tensegrity_jobs.sqlite3`` in the working dir
``TENSEGRITY_JOBS_SCHEDULER``          (unset)    jobs: unset/``serial`` runner thread; ``local``/``tcp://..`` Dask
``TENSEGRITY_JOBS_MAX_POINTS``         100000     most points in one job (422 above)
``TENSEGRITY_JOBS_RESUME``             true       resume jobs a stopped server left running
``TENSEGRITY_JOBS_SYNCHRONOUS``        NORMAL     SQLite ``synchronous`` (NORMAL survives a kill, FULL a power cut)
``TENSEGRITY_JOBS_CHUNK_SIZE``         (auto)     points per Dask task
=====================================  =========  ==================================================
"""

from __future__ import annotations

import json
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
        4, ge=0, le=6,
        description="longest chain for which /v1/equilibria accepts method=homotopy (PHCpack; n = 4 takes "
                    "4-8 s, n = 5 one to two minutes: raise solve_timeout with it); 0: refused")
    batch_timeout: float = Field(60.0, gt=0, description="seconds one batch may run")
    workers: int = Field(2, ge=1, le=64, description="solver worker threads")
    inline_max_segments: int = Field(
        8, ge=0, le=64,
        description="chains up to this many segments (with monotonic segments) are first solved on the event "
                    "loop by the bounded Newton-only search (a few hundred microseconds, less than the hand-off "
                    "to a worker thread); what it does not settle goes to the workers. 0: always the workers")
    inline_processes: int = Field(
        1, ge=0, le=64,
        description="solver processes for that bounded search (service.lane): the event loop hands the request "
                    "over and goes on with HTTP meanwhile. 0: the event loop solves it itself")
    queue_size: int = Field(64, ge=0, le=100000, description="requests waiting for a worker before 503")
    retry_after: int = Field(1, ge=0, description="Retry-After seconds sent with 503")
    api_keys: Annotated[list[str], NoDecode] = Field(default_factory=list, description="accepted X-API-Key values")
    cors_origins: Annotated[list[str], NoDecode] = Field(default_factory=list, description="allowed CORS origins")
    max_body_bytes: int = Field(1024 * 1024, ge=1, description="largest request body (413 above)")
    max_response_bytes: int = Field(
        8 * 1024 * 1024, ge=1024,
        description="largest JSON answer (422 response_too_large above: estimated before solving where the "
                    "request says enough, else counted while rendering in the solver thread)")
    warmup: bool = Field(True, description="build each worker's solvers at start-up")
    shutdown_timeout: float = Field(
        1.0, ge=0, le=600,
        description="seconds requests in flight get to finish at SIGTERM/SIGINT before they are cancelled "
                    "(uvicorn's timeout_graceful_shutdown; tensegrity-opt serve)")
    jobs_db: str = Field("tensegrity_jobs.sqlite3", min_length=1, description="SQLite file of the job store")
    jobs_scheduler: str | None = Field(None, description="None/serial: in-process thread; local; tcp://host:port")
    jobs_max_points: int = Field(100_000, ge=1, le=1_000_000, description="most points in one job")
    jobs_resume: bool = Field(True, description="resume jobs left running by a previous process")
    jobs_synchronous: Literal["NORMAL", "FULL"] = Field("NORMAL", description="SQLite synchronous mode")
    jobs_chunk_size: int | None = Field(None, ge=1, description="points per Dask task (default: automatic)")

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


@lru_cache
def get_settings() -> Settings:
    """The process settings (read once from the environment)."""
    return Settings()
