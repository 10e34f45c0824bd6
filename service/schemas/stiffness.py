"""Models of ``/v1/stiffness``."""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict, Field

from ..config import HARD_MAX_SEGMENTS
from .common import PAPER_CHAIN, Angle, ManipulatorIn, TipDx, TipDy
from .equilibrium import EquilibriumOut


class StiffnessRequest(BaseModel):
    """Cartesian tangent stiffness at the equilibrium `/v1/equilibrium` returns."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": PAPER_CHAIN, "dx": 0.1, "dy": 0.0}]})

    manipulator: ManipulatorIn
    dx: TipDx
    dy: TipDy = 0.0
    q0: list[Angle] | None = Field(None, max_length=HARD_MAX_SEGMENTS, description="optional nearby configuration")


class StiffnessOut(BaseModel):
    matrix: list[list[float]] = Field(description="2 x 2 tangent stiffness dF_i / d tip_j (force / length)")
    equilibrium: EquilibriumOut
