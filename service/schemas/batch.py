"""Models of ``/v1/batch/equilibrium``."""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict, Field

from ..config import HARD_MAX_BATCH, HARD_MAX_SEGMENTS
from .common import _STRICT, PAPER_CHAIN, Angle, Deflection, ErrorOut, ManipulatorIn
from .equilibrium import EquilibriumOut


class Target(BaseModel):
    """One tip deflection."""

    model_config = _STRICT

    dx: Deflection
    dy: Deflection = 0.0


class BatchEquilibriumRequest(BaseModel):
    """Equilibria for a sequence of targets (a trajectory), solved in order."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": PAPER_CHAIN, "targets": [{"dx": 0.05, "dy": 0.0}, {"dx": 0.1, "dy": 0.0}],
                      "continuation": True}]})

    manipulator: ManipulatorIn
    targets: list[Target] = Field(min_length=1, max_length=HARD_MAX_BATCH,
                                  description="targets in order (server limit TENSEGRITY_MAX_BATCH)")
    continuation: bool = Field(True, description="start each solve from the previous result (q0)")
    q0: list[Angle] | None = Field(None, max_length=HARD_MAX_SEGMENTS,
                                   description="optional configuration near the first target")


class BatchItem(BaseModel):
    """The result for one target: `equilibrium` or `error` (the other is null)."""

    index: int
    dx: float
    dy: float
    equilibrium: EquilibriumOut | None
    error: "ErrorOut | None"


class BatchOut(BaseModel):
    results: list[BatchItem]
    succeeded: int
    failed: int
