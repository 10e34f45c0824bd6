"""Models of ``/v1/energy-landscape``."""

from __future__ import annotations

from typing import Annotated

from pydantic import BaseModel, BeforeValidator, ConfigDict, Field

import tensegrity_opt as to

from .common import (
    LOADS_OUT_DOC,
    MAX_ANGLE,
    MAX_GRID,
    PAPER_CHAIN,
    Int,
    LoadsOut,
    ManipulatorIn,
    TipDx,
    TipDy,
    integral,
    outcome_model,
)


class EnergyLandscapeRequest(BaseModel):
    """Energy over a grid of two joint angles, the other two from inverse kinematics (n = 4 only)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": PAPER_CHAIN, "dx": 0.1, "dy": 0.0, "pair": [0, 3], "grid": 3}]})

    manipulator: ManipulatorIn
    dx: TipDx
    dy: TipDy = 0.0
    pair: list[Annotated[int, Field(ge=0, le=3), BeforeValidator(integral)]] = Field(
        [0, 3], min_length=2, max_length=2, description="the two grid joints, 0-based and different")
    grid: Int = Field(51, ge=2, le=MAX_GRID, description=f"points per axis (2..{MAX_GRID})")
    span: Annotated[float, Field(gt=0, le=MAX_ANGLE, allow_inf_nan=False)] | None = Field(
        None, description="half-width of both axes (rad); default: the smaller joint limit of the pair")


class EnergyLandscapeOut(outcome_model(to.Landscape)):
    """Energy over a grid of two joint angles (`tensegrity_opt.Landscape`)."""

    pair: list[int]
    qi: list[float] = Field(description="grid axis of joint pair[0] (rad)")
    qj: list[float] = Field(description="grid axis of joint pair[1] (rad)")
    energy: list[list[list[float | None]]] = Field(
        description="energy[elbow][i][j], elbow 0: +1, 1: -1; null where unreachable or out of range")
    loads: LoadsOut | None = Field(description=LOADS_OUT_DOC)
