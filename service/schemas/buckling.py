"""Models of ``/v1/buckling``."""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

import tensegrity_opt as to

from .common import PAPER_CHAIN, ManipulatorIn, outcome_model


class BucklingRequest(BaseModel):
    """Critical loads and buckling modes of the straight configuration."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": PAPER_CHAIN, "boundary": "guided"}]})

    manipulator: ManipulatorIn
    boundary: Literal["guided", "free"] = Field(
        "guided", description='"guided": tip held at dy = 0 (the paper); "free": cantilever')


class ModeOut(BaseModel):
    load: float = Field(description="critical compressive load P (> 0); Fx = -load")
    q: list[float] = Field(description="mode shape (rad per unit amplitude)")
    fy: float = Field(description="Fy per unit amplitude (guided; 0 for free)")
    energy_factor: float
    mu_x: float
    fy_coefficient: float
    shape: str
    signs: str
    stable: bool


class BucklingOut(outcome_model(to.Buckling)):
    """Critical loads and modes of the straight chain (`tensegrity_opt.Buckling`)."""

    boundary: Literal["guided", "free"]
    critical_force: float = Field(description="signed critical Fx0 = -min(loads) (negative: compressive)")
    loads: list[float] = Field(description="all critical loads, ascending")
    modes: list[ModeOut]
