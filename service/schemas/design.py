"""Models of the design and control endpoints (``/v1/design/...``): the design chain inputs (at most 60
segments), the requests and the designed chain out."""

from __future__ import annotations

from typing import Annotated, Literal, Union

from pydantic import BaseModel, Field

import tensegrity_opt as to

from .common import (
    _STRICT,
    MARGIN_DOC,
    MAX_STIFFNESS,
    TAUT_DOC,
    Angle,
    Deflection,
    Finite,
    ForceValue,
    Int,
    SegmentedManipulatorIn,
    SegmentIn,
    SolverInfo,
    SpringStateOut,
    TotalLength,
    UniformManipulatorIn,
    _manipulator_union,
    bounds_of,
    outcome_model,
)
from .equilibrium import EquilibriumOut

# ---------------------------------------------------------------------------- the design chain
#: Chains accepted by the design endpoints (their NLPs carry a dense n x n Cholesky factor).
MAX_DESIGN_SEGMENTS = 60


class DesignUniformManipulatorIn(UniformManipulatorIn):
    """`n` identical segments (design endpoints: at most 60)."""

    n: Int = Field(ge=1, le=MAX_DESIGN_SEGMENTS, description=f"number of segments (at most {MAX_DESIGN_SEGMENTS} "
                                                             "for the design endpoints)")


class DesignSegmentedManipulatorIn(SegmentedManipulatorIn):
    """Segments listed from base to tip (design endpoints: at most 60)."""

    segments: list[SegmentIn] = Field(min_length=1, max_length=MAX_DESIGN_SEGMENTS,
                                      description=f"segments from base to tip (at most {MAX_DESIGN_SEGMENTS})")


DesignManipulatorIn = _manipulator_union(DesignUniformManipulatorIn, DesignSegmentedManipulatorIn,
                                         "the chain (at most 60 segments)")


# ---------------------------------------------------------------------------- requests
DesignVar = Literal["a", "b", "k", "L0"]
Positive = Annotated[float, Field(gt=0.0, le=MAX_STIFFNESS, allow_inf_nan=False)]


#: A side of a design variable's bounds: one number for every segment, or one per segment.
DesignBound = Union[Positive, Annotated[list[Positive], Field(min_length=1, max_length=MAX_DESIGN_SEGMENTS)]]
#: Bounds on a design variable (``bounds.<name>``), on every rest length (the preload problems).
BoundsIn = bounds_of(DesignBound, "BoundsIn", "bounds (each side a number, or one per segment)",
                     object_doc="Bounds {lo, hi}, each a number or one per segment (the object form of [lo, hi]).")
#: Bounds on the spring preload tension at straight.
TensionBounds = bounds_of(Finite, "TensionBoundsIn", "bounds [T_min, T_max] on the preload tension k (2b - L0) at "
                                                     "straight (force units)")


class DesignCriticalForceRequest(BaseModel):
    """Maximise the critical load over per-segment design variables."""

    model_config = _STRICT
    manipulator: DesignManipulatorIn
    vary: list[DesignVar] = Field(["k"], min_length=1, max_length=4, description="per-segment variables to optimise")
    bounds: dict[DesignVar, BoundsIn] = Field(default_factory=dict,
                                              description="bounds per variable; default (x0 / 10, 10 x0)")
    budget: dict[DesignVar, Positive] = Field(default_factory=dict, description="cap on the sum over the segments")
    boundary: Literal["guided", "free"] = "guided"
    total_length: TotalLength | None = None
    tension: TensionBounds | None = None
    K_min: Annotated[float, Field(ge=-MAX_STIFFNESS, le=MAX_STIFFNESS, allow_inf_nan=False)] | None = Field(
        None, description="lower bound on every joint stiffness K_i")


class PreloadsForLoadRequest(BaseModel):
    """The smallest change of the rest lengths L0 making the critical load at least `required`."""

    model_config = _STRICT
    manipulator: DesignManipulatorIn
    required: Positive = Field(description="required critical compressive load (force units)")
    boundary: Literal["guided", "free"] = "guided"
    bounds: BoundsIn | None = Field(None, description="bounds on every L0; default (0.05 * 2b, 2b)")


#: A tip position ``[x, y]`` (length units), as every request takes it.
Point = Annotated[list[Deflection], Field(min_length=2, max_length=2)]
#: A tip force ``[fx, fy]`` (force units), as every request takes it.
LoadIn = Annotated[list[ForceValue], Field(min_length=2, max_length=2)]


class PreloadsRequest(BaseModel):
    """Rest lengths putting the tip at a target, stably, under a tip load."""

    model_config = _STRICT
    manipulator: DesignManipulatorIn
    target: Point = Field(description="tip position [x, y] (length units)")
    load: LoadIn = Field([0.0, 0.0], description="the dead tip load [fx, fy] (force units)")
    objective: Literal["nominal", "margin", "energy"] = Field(
        "nominal", description="nominal: least change from the chain's own rest lengths (the library's "
                               "objective `change`); margin: largest stability margin; energy: least spring energy")
    margin: Annotated[float, Field(ge=0, le=MAX_STIFFNESS, allow_inf_nan=False)] = Field(1e-3, description=MARGIN_DOC)
    taut: bool = Field(False, description=TAUT_DOC)
    bounds: BoundsIn | None = Field(None, description="bounds on every rest length; default (0.1 b_min, 4 b_max)")
    end_angle: Angle | None = Field(None, description="absolute angle of the last link (rad), optional")


# ---------------------------------------------------------------------------- responses
class SegmentOut(BaseModel):
    a: float
    b: float
    k: float | list[float]
    L0: float | list[float]


class ManipulatorOut(BaseModel):
    segments: list[SegmentOut]


class DesignOut(outcome_model(to.Design)):
    """`Design.to_dict()`: the designed chain, its critical loads recomputed by `critical_force`."""

    manipulator: ManipulatorOut
    critical_force: float = Field(description="signed critical force, recomputed by critical_force on the design")
    loads: list[float] = Field(description="all critical loads of the design, ascending (recomputed)")
    multiplicity: int = Field(description="how many critical loads coincide with the smallest")
    active: list[str] = Field(description="active constraints at the optimum")
    initial_critical_force: float | None = Field(description="the starting design's critical force")
    feasible: bool = Field(description="preloads-for-load: whether the required load is reached")
    solver: SolverInfo


class ActiveBoundOut(BaseModel):
    """A decision variable at (or within 1 % of its interval of) one of its bounds at the optimum (`ActiveBound`)."""

    segment: int = Field(description="the segment, 0-based")
    variable: str = Field(description="the variable: L1_0, L2_0 (rest lengths), a, b, k, L0")
    side: Literal["lower", "upper"]
    value: float = Field(description="the variable's value at the optimum")
    bound: float = Field(description="the bound it is at")


class PreloadsOut(SpringStateOut, outcome_model(to.PreloadDesign)):
    """`PreloadDesign.to_dict()`: rest lengths for a pose, verified by the forward equilibrium."""

    manipulator: ManipulatorOut
    preloads: list[list[float]] = Field(description="rest lengths [L1_0, L2_0] per segment")
    q: list[float] = Field(description="verified equilibrium configuration (rad)")
    margin: float = Field(description="achieved stability margin (recomputed)")
    tip: list[float]
    energy: float
    active_bounds: list[ActiveBoundOut] = Field(description="the rest lengths at (or near) their bounds")
    solver: SolverInfo


# ---------------------------------------------------------------------------- holding up under the loads
class HoldingRequest(BaseModel):
    """The least preload (or stiffness) with which the chain holds itself up under its dead loads."""

    model_config = _STRICT
    manipulator: DesignManipulatorIn
    vary: list[Literal["L0", "k"]] = Field(["L0"], min_length=1, max_length=1,
                                           description="what is designed, one of: the rest lengths (`L0`: the preload; "
                                                       "both springs of a segment together) or the stiffnesses (`k`: a "
                                                       "scale per segment)")
    margin: Annotated[float, Field(ge=0, le=MAX_STIFFNESS, allow_inf_nan=False)] = Field(1e-3, description=MARGIN_DOC)
    max_angle: Annotated[float, Field(gt=0, lt=3.141592653589793, allow_inf_nan=False)] | None = Field(
        None, description="the sag allowed: every joint within this of straight (rad); default anywhere in range")


class HoldingOut(SpringStateOut, outcome_model(to.HoldingDesign)):
    """`HoldingDesign.to_dict()`: the designed chain holding itself up, verified by forward solves."""

    manipulator: dict = Field(description="the designed chain (its segments and its loads, as a request takes it)")
    vary: list[Literal["L0", "k"]] = Field(description="what was designed")
    change: list[float] = Field(description="per segment: the rest lengths' change (L0) or the stiffness scale (k)")
    q: list[float] = Field(description="the verified rest configuration under the loads (rad)")
    margin: float = Field(description="the smallest eigenvalue of the potential's Hessian there (recomputed)")
    tension: float = Field(description="the total spring tension of the designed chain when straight")
    stiffness: float = Field(description="the total stiffness sum(k1 + k2)")
    equilibrium: EquilibriumOut
    solver: SolverInfo
