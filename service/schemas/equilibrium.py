"""Models of ``/v1/equilibrium``, ``/v1/equilibrium/force`` and ``/v1/equilibria``."""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

import tensegrity_opt as to

from ..config import HARD_MAX_SEGMENTS
from .common import (
    LOADS_OUT_DOC,
    PAPER_CHAIN,
    Angle,
    Deflection,
    Force,
    ForceValue,
    LoadsOut,
    ManipulatorIn,
    SolverInfo,
    SpringStateOut,
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
    certify: bool = Field(False, description="prove the answer least: a rigorous lower bound on the energy of every "
                                             "configuration meeting the tip constraint in the closed joint range "
                                             "(`certificate`: bound, gap, tolerance); `status` `certified` when the "
                                             "gap is within the tolerance; up to ~5 s more, longer for 2^17+ "
                                             "well patterns (not with `local`)")


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
                              "equilibrium certified (chains up to the server's `homotopy_max_segments`, default 5; "
                              "seconds; needs the `phcpack` package on the server, else 503 `homotopy_unavailable`)")
    stops: bool | None = Field(
        None, description="include the equilibria resting on a joint's stop (`at_stop`, `contact_torques`); null: "
                          "yes for a chain with tension-only springs, no under the linear law (the open range). "
                          "Under the linear law `true` adds Newton with each joint held on either stop (search) or "
                          "one system per free/stop pattern (homotopy, certified, n <= 5)")


# ---------------------------------------------------------------------------- responses
class EnergyBoundOut(outcome_model(to.EnergyBound)):
    """The least-energy certificate (`tensegrity_opt.EnergyBound`)."""

    bound: float = Field(description="no configuration meeting the tip constraint in the closed joint range has a "
                                     "lower energy")
    energy: float = Field(description="the least energy of a feasible configuration known (the answer's)")
    gap: float = Field(description="energy - bound (>= 0)")
    tolerance: float = Field(description="certified when gap <= tolerance (1e-7 |E| + 1e-9 max k c^2)")
    certified: bool
    improved: bool = Field(description="the bound found a lower configuration than the search's (returned instead)")
    patterns: int = Field(description="pattern boxes (products of the joints' low-energy pieces) enumerated")
    boxes: int = Field(description="boxes bounded in all")
    newton: int = Field(description="Newton re-centrings of open boxes")
    seconds: float = Field(description="wall time of the bound (s)")


class EquilibriumOut(SpringStateOut, outcome_model(to.Equilibrium)):
    """An equilibrium configuration."""

    q: list[float] = Field(description="relative joint angles (rad)")
    energy: float = Field(description="the chain's potential energy (force x length): its springs' elastic energy, "
                                      "plus the potential of its dead loads where it carries some (`loads`)")
    force: Force
    morse_index: int = Field(description="negative eigenvalues of the reduced Hessian (0: stable)")
    stable: bool
    kind: Literal["minimum", "saddle", "maximum", "degenerate"]
    shape: str = Field(description="shape label: I, C, U, ZU, Z or W<s>")
    signs: str = Field(description="sign of each joint angle: +, - or 0")
    tip: list[float] = Field(description="tip position [x, y]")
    solver: SolverInfo
    certificate: EnergyBoundOut | None = Field(
        None, description="the rigorous lower bound on the energy and its gap: with `certify: true`, or where the "
                          "default search's short way (short multistable chains) proved its answer; else null")
    at_stop: list[bool] = Field(description="the joints resting on their mechanical stop |q| = pi - 2 beta (reached "
                                            "where springs go slack: the tension-only law); false inside the range")
    contact_torques: list[float] = Field(description="the torque each stop supplies (>= 0; 0 where a joint is not "
                                                     "at its stop)")
    loads: LoadsOut | None = Field(description=LOADS_OUT_DOC)


class RootBoxOut(BaseModel):
    """The interval proof about one equilibrium (`tensegrity_opt.results.RootBox`)."""

    lower: list[float] = Field(description="the box's lower bounds (outward-rounded): q (rad), then Fx, Fy under "
                                           "displacement control")
    upper: list[float] = Field(description="the box's upper bounds, as `lower`")
    proven: bool = Field(description="Krawczyk's test passed: exactly one real equilibrium in the box, the box "
                                     "strictly inside the joint range and disjoint from the other boxes")
    morse_index: int | None = Field(description="the Morse index proven over the box (null: not proven)")
    morse_proven: bool = Field(description="the Morse index is proven; false: the equilibrium's own index is "
                                           "floating-point")
    reason: Literal["", "krawczyk", "singular", "range", "outside", "overlap", "moved"] = Field(
        description="why not proven (empty when proven): `krawczyk` the test did not contract (singular or "
                    "ill-conditioned), `singular` no float inverse, `range` the box straddles a joint limit, `outside` "
                    "it lies beyond one, "
                    "`overlap` the box meets another, `moved` the refined point left the given one")


class IntervalCertificateOut(outcome_model(to.results.IntervalCertificate)):
    """The interval (ball-arithmetic) proofs of a homotopy's equilibria
    (`tensegrity_opt.results.IntervalCertificate`)."""

    method: str = Field(description="`krawczyk (arb)`: Krawczyk's test in Arb's ball arithmetic (python-flint)")
    control: Literal["displacement", "force"] = Field(description="the unknowns proven: (q, Fx, Fy) or q")
    paths: int = Field(description="homotopy paths behind the equilibria")
    roots_proven: bool = Field(description="every equilibrium proven (unique in its box, real, in range, disjoint)")
    morse_proven: bool = Field(description="every Morse index proven")
    nonreal_checked: int = Field(description="homotopy roots classed non-real but near the real set (within 0.1)")
    nonreal_proven: int = Field(description="of those, proven non-real (complex Krawczyk, a box off the real set)")
    outside_checked: int = Field(description="homotopy real roots just beyond the joint range (by less than 0.1 rad)")
    outside_proven: int = Field(description="of those, proven beyond it (Krawczyk, a box beyond a joint limit)")
    seconds: float = Field(description="wall time of the proofs (s)")
    boxes: list[RootBoxOut] = Field(description="one per equilibrium, in the order of `equilibria`")


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
    certificate: IntervalCertificateOut | None = Field(
        description="the homotopy's interval proofs of its equilibria (null for the other methods); `certified` "
                    "needs every equilibrium proven")
