"""Models of ``/v1/force-deflection``."""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

import tensegrity_opt as to
from tensegrity_opt.analyses.paths.curves import POINT_STATUSES

from .common import (
    LOADS_OUT_DOC,
    MAX_CURVE_POINTS,
    PAPER_CHAIN,
    Deflection,
    DeflectionRange,
    Force,
    LoadsOut,
    ManipulatorIn,
    SolverInfo,
    SpringStateOut,
    list_or_range,
    outcome_model,
)

#: The deflections of a curve, in the order to follow (``/v1/force-deflection``, its figure).
CurveDeflections = list_or_range(Deflection, DeflectionRange, 1, MAX_CURVE_POINTS,
                                 f"deflections in the order to follow: a list or {{start, stop, num}} "
                                 f"(at most {MAX_CURVE_POINTS} points)")


class ForceDeflectionRequest(BaseModel):
    """Force-deflection curve by continuation along the least-energy stable branch."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": PAPER_CHAIN, "dx": {"start": 0.0, "stop": 0.5, "num": 6}, "dy": 0.0,
                      "branch": "stable"}]})

    manipulator: ManipulatorIn
    dx: CurveDeflections
    dy: Deflection = Field(0.0, description="tip deflection along y, the same at every point")
    branch: Literal["stable", "all"] = Field(
        "stable", description='"all" also returns every branch found at the first deflected point')
    reference: Literal["straight", "rest"] = Field(
        "straight", description='what dx, dy are measured from: the straight tip (the paper\'s) or "rest", the tip '
                                'of the least-energy rest configuration (a pre-bent arm unloaded: force 0 at '
                                'dx = dy = 0)')


class CurvePoint(SpringStateOut):
    dx: float
    dy: float
    fx: float
    fy: float
    energy: float
    q: list[float]
    stable: bool
    morse_index: int
    shape: str
    branch: int = Field(description="branch identifier (-1: straight)")
    status: Literal[tuple(POINT_STATUSES)] = Field(
        description="what the point is: " + "; ".join(f"`{k}`: {v}" for k, v in POINT_STATUSES.items()))
    solver: SolverInfo = Field(description='the solver\'s own status and iterations (e.g. "Newton_Converged"; '
                                           '"straight" for the straight chain)')


class JumpOut(BaseModel):
    """A force discontinuity between two consecutive points (in the order followed)."""

    kind: Literal["buckling", "leave_straight", "snap", "switch"] = Field(
        description='"buckling": leaving (or returning to) the stable straight chain at dx -> 0+, dy = 0, from 0 to '
                    'the guided critical force; "leave_straight": leaving (returning to) a straight chain that is not '
                    'stable unloaded (K <= 0) or at dy != 0, from the straight force to the deflected point\'s; '
                    '"snap": '
                    'the selected stable branch ends or loses stability and the chain jumps to another stable branch; '
                    '"switch": the least-energy stable branch changes while the previous one is still stable')
    dx_before: float
    dx_after: float
    force_before: Force
    force_after: Force
    branch_before: int = Field(description="branch identifier before (-1: straight)")
    branch_after: int = Field(description="branch identifier after (-1: straight)")
    delta: Force = Field(description="force_after - force_before (fx > 0 tensile, fx < 0 compressive)")
    label: str = Field(description='a sentence naming the jump with sign and size, e.g. "buckling of the straight '
                                   'chain: F_x 0 -> -0.573 (compressive)"')


class CurveEndOut(outcome_model(to.results.CurveEnd)):
    """Where a partial curve stopped: the first requested point it could not compute."""

    success: bool = Field(description="always false: the curve could not go on there")
    dx: float
    dy: float


class BranchPoint(SpringStateOut):
    """A point of one followed branch; numbers are null where the branch does not exist."""

    dx: float
    dy: float
    exists: bool
    fx: float | None
    fy: float | None
    energy: float | None
    q: list[float | None]
    stable: bool
    morse_index: int = Field(description="-1 where the branch does not exist")
    shape: str


class BranchOut(BaseModel):
    id: int
    points: list[BranchPoint]


class ForceDeflectionOut(outcome_model(to.Curve)):
    """A force-deflection curve: `success` when every requested point was computed; else `ended_at` says where it
    stops and `message` why."""

    points: list[CurvePoint]
    jumps: list[JumpOut]
    branches: list[BranchOut] = Field(description='branch = "all" only (else empty)')
    reference: Literal["straight", "rest"] = Field("straight", description="what dx, dy are measured from")
    origin: list[float] = Field([0.0, 0.0], description="the reference tip's deflection from the straight tip "
                                                        "(add it to dx, dy for the deflection from straight)")
    ended_at: CurveEndOut | None = Field(
        description="null when complete; else the first requested point where no stable equilibrium is found: "
                    "points holds only the points before it (the later ones are not computed)")
    requested: int = Field(description="how many points were asked for (len(points) when complete)")
    loads: LoadsOut | None = Field(description=LOADS_OUT_DOC)
