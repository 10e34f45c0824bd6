"""Service settings: one pydantic-settings class read from ``TENSEGRITY_*`` environment variables.

Every field has an embedded default, so ``tensegrity-opt serve`` runs with no configuration.

============================  =========  ==================================================
variable                      default    meaning
============================  =========  ==================================================
``TENSEGRITY_MAX_SEGMENTS``   200        largest chain accepted (``too_many_segments`` above)
``TENSEGRITY_MAX_BATCH``      1000       most targets in one ``/v1/batch/equilibrium``
``TENSEGRITY_SOLVE_TIMEOUT``  10         seconds one request may wait for its result (504)
``TENSEGRITY_BATCH_TIMEOUT``  60         seconds a batch may run (later targets: ``timeout``)
``TENSEGRITY_WORKERS``        2          solver threads (each owns its CasADi instances)
``TENSEGRITY_QUEUE_SIZE``     64         requests waiting for a solver thread (503 beyond)
``TENSEGRITY_RETRY_AFTER``    1          ``Retry-After`` seconds sent with 503
``TENSEGRITY_API_KEYS``       (empty)    comma-separated or JSON list; empty: auth off
``TENSEGRITY_CORS_ORIGINS``   (empty)    comma-separated or JSON list; empty: CORS off
``TENSEGRITY_MAX_BODY_BYTES`` 1048576    request bodies above this get 413
``TENSEGRITY_WARMUP``         true       build each thread's solvers (n = 4) at start-up
============================  =========  ==================================================
"""

from __future__ import annotations

import json
from functools import lru_cache
from typing import Annotated, Any

from pydantic import Field, field_validator
from pydantic_settings import BaseSettings, NoDecode, SettingsConfigDict

#: Hard caps baked into the request schema (the OpenAPI document does not depend on the
#: settings); the configurable limits below can only be tighter.
HARD_MAX_SEGMENTS = 1000
HARD_MAX_BATCH = 10000


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

    max_segments: int = Field(200, ge=1, le=HARD_MAX_SEGMENTS, description="largest chain accepted")
    max_batch: int = Field(1000, ge=1, le=HARD_MAX_BATCH, description="most targets in one batch")
    solve_timeout: float = Field(10.0, gt=0, description="seconds one request may wait for its result")
    batch_timeout: float = Field(60.0, gt=0, description="seconds one batch may run")
    workers: int = Field(2, ge=1, le=64, description="solver worker threads")
    queue_size: int = Field(64, ge=0, le=100000, description="requests waiting for a worker before 503")
    retry_after: int = Field(1, ge=0, description="Retry-After seconds sent with 503")
    api_keys: Annotated[list[str], NoDecode] = Field(default_factory=list, description="accepted X-API-Key values")
    cors_origins: Annotated[list[str], NoDecode] = Field(default_factory=list, description="allowed CORS origins")
    max_body_bytes: int = Field(1024 * 1024, ge=1, description="largest request body (413 above)")
    warmup: bool = Field(True, description="build each worker's solvers at start-up")

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
