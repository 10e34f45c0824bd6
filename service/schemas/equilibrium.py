"""Models of ``/v1/equilibrium``, ``/v1/equilibrium/force`` and ``/v1/equilibria``."""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

import tensegrity_opt as to

from ..config import HARD_MAX_SEGMENTS
from .common import (
    PAPER_CHAIN,
    Angle,
    Deflection,
    Force,
    ForceValue,
    ManipulatorIn,
    SolverInfo,
    TipDx,
    TipDy,
    outcome_model,
)


# ---------------------------------------------------------------------------- requests
class EquilibriumRequest(BaseModel):
    """Least-energy stable equilibrium with the tip held at `(2 sum(b) - dx, dy)`."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": PAPER_CHAIN, "dx": 0.1, "dy": 0.0}]})

    manipulator: ManipulatorIn
    dx: Deflection = Field(description="tip deflection along x (length units); dx > 0 shortens the chain")
    dy: TipDy = 0.0
    q0: list[Angle] | None = Field(None, max_length=HARD_MAX_SEGMENTS,
                                   description="optional nearby configuration (rad, one angle per joint) "
                                               "for continuation; it competes with the global search")
    local: bool = Field(False, description="only the local solve from `q0` (required): the equilibrium on the "
                                           "branch through `q0`, whatever its stability (read `stable`) — for "
                                           "control loops sending their previous answer; no global search")


class ForceEquilibriumRequest(BaseModel):
    """A local minimiser of `E(q) - F . tip(q)` for a dead tip load `F = (fx, fy)`."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": PAPER_CHAIN, "fx": -0.3, "fy": 0.0}]})

    manipulator: ManipulatorIn
    fx: ForceValue = Field(description="tip force along x (force units); fx < 0 compresses")
    fy: ForceValue = Field(0.0, description="tip force along y (force units)")
    q0: list[Angle] | None = Field(None, max_length=HARD_MAX_SEGMENTS,
                                   description="optional start configuration (rad)")


class EquilibriaRequest(BaseModel):
    """Every equilibrium (minima, saddles, maxima) for a tip deflection."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": PAPER_CHAIN, "dx": 0.1, "dy": 0.0}]})

    manipulator: ManipulatorIn
    dx: TipDx
    dy: TipDy = 0.0
    method: Literal["search", "homotopy"] = Field(
        "search", description="`search`: multi-start Newton (any n; complete in practice, not certified); "
                              "`homotopy`: PHCpack's polyhedral homotopy on the polynomial KKT system, every "
                              "equilibrium certified (chains up to the server's `homotopy_max_segments`, default 4; "
                              "seconds; needs the `phcpack` package on the server, else 503 `homotopy_unavailable`)")


# ---------------------------------------------------------------------------- responses
class EquilibriumOut(outcome_model(to.Equilibrium)):
    """An equilibrium configuration."""

    q: list[float] = Field(description="relative joint angles (rad)")
    energy: float = Field(description="elastic energy (force x length)")
    force: Force
    morse_index: int = Field(description="negative eigenvalues of the reduced Hessian (0: stable)")
    stable: bool
    kind: Literal["minimum", "saddle", "maximum", "degenerate"]
    shape: str = Field(description="shape label: I, C, U, ZU, Z or W<s>")
    signs: str = Field(description="sign of each joint angle: +, - or 0")
    tip: list[float] = Field(description="tip position [x, y]")
    solver: SolverInfo


class EquilibriaOut(outcome_model(to.EquilibriumSet)):
    """Every equilibrium found and what the set claims (`tensegrity_opt.EquilibriumSet`)."""

    equilibria: list[EquilibriumOut] = Field(description="every equilibrium found, sorted by energy (under a dead "
                                                         "load: by the total potential E - F . tip)")
    method: str = Field(description="how they were found: `search`, `homotopy`, `exact` (the unloaded chain), or "
                                    "`straight` / `closed_form` for the trivial cases")
    certified: bool = Field(description="true only when the set is proven complete (`status` `certified` or "
                                        "`exact`)")
    paths: int = Field(description="homotopy paths tracked (0 for the search)")
    failed_paths: int = Field(description="homotopy paths that failed (any makes `certified` false)")
