"""Models of the loading-path endpoints: ``/v1/rest-configurations``, ``/v1/branch``,
``/v1/bifurcation-diagram``, ``/v1/limit-load``, ``/v1/imperfection-sensitivity`` and ``/v1/stability-boundary``.

A *control* says what the continuation parameter ``t`` moves (``tensegrity_opt.Control``): the tip
along a line (``displacement``), a dead tip load (``load``), the paper's guided tip (``guided``: ``y``
held, the load along ``x``), a frictionless wall (``wall``) or the springs' rest lengths
(``preload``). A *start* is joint angles (``{"q": [...]}``), the least-energy equilibrium with the tip
held at a deflection (``{"dx", "dy"}``: displacement controls, and preload with the tip held), or
null: the least-energy rest configuration. Same conventions as :mod:`service.schemas` (strict, no
NaN, unknown fields refused); what JSON Schema cannot say (a preload direction of ``2n`` numbers, a
start that is not an equilibrium ...) is refused by the library with a domain code naming the field.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal, Union

from pydantic import BaseModel, BeforeValidator, ConfigDict, Discriminator, Field, Tag

import tensegrity_opt as to
from tensegrity_opt.analyses.paths.boundaries import PARAMETERS
from tensegrity_opt.analyses.paths.events import EVENT_KINDS
from tensegrity_opt.analyses.paths.imperfection import AMPLITUDE_STATUSES, BIFURCATIONS, KINDS

from ..config import HARD_MAX_PATH_POINTS, HARD_MAX_SEGMENTS
from .common import (
    _STRICT,
    MAX_FORCE,
    PAPER_CHAIN,
    Angle,
    Force,
    ForceValue,
    Int,
    ManipulatorIn,
    SpringSeriesOut,
    SpringStateOut,
    TipDx,
    TipDy,
    integral,
    outcome_model,
)
from .equilibrium import EquilibriumOut

#: Most bifurcation switches (depth) and branches of one diagram.
MAX_DEPTH = 6
MAX_BRANCHES = 64
#: Most amplitudes of one imperfection-sensitivity curve.
MAX_AMPLITUDES = 64
#: Largest |t| bound and |p| accepted (the units of the control: force or length).
MAX_PARAMETER = MAX_FORCE

Vec2 = Annotated[list[ForceValue], Field(min_length=2, max_length=2)]
Parameter = Annotated[float, Field(ge=-MAX_PARAMETER, le=MAX_PARAMETER, allow_inf_nan=False)]
MaxPoints = Annotated[int, Field(ge=2, le=HARD_MAX_PATH_POINTS,
                                 description=f"at most this many points per branch, the start included (2.."
                                             f"{HARD_MAX_PATH_POINTS}; server limit TENSEGRITY_MAX_PATH_POINTS)"),
                      BeforeValidator(integral)]

_TIME = ("The computation runs within the server's time limit: when it runs out, what was computed so far is "
         "answered (200) with `status: \"time_limit\"` and `success: false`.")


# ---------------------------------------------------------------------------- controls
class DisplacementControlIn(BaseModel):
    """The tip moved along a line: the deflection `(dx, dy)` is the start's plus `t` times the unit direction
    (`t` in length units); the force is the one holding the tip there."""

    model_config = _STRICT
    kind: Literal["displacement"]
    direction: Vec2 = Field([1.0, 0.0], description="direction in (dx, dy) (normalised; dx > 0 shortens the chain)")


class LoadControlIn(BaseModel):
    """A dead tip load `F = base + t d` (`d` the unit direction, `t` in force units), the tip free."""

    model_config = _STRICT
    kind: Literal["load"]
    direction: Vec2 = Field([-1.0, 0.0], description="load direction (normalised; [-1, 0] compresses)")
    base: Vec2 = Field([0.0, 0.0], description="the load at t = 0 (force units)")


class GuidedControlIn(BaseModel):
    """The paper's guided tip: `y` held at the start's value, `Fx = base_x + t d_x`, `Fy` the guide's reaction."""

    model_config = _STRICT
    kind: Literal["guided"]
    direction: Vec2 = Field([-1.0, 0.0], description="load direction (normalised; needs an x component)")
    base: Vec2 = Field([0.0, 0.0], description="the load at t = 0 (force units)")


class WallControlIn(BaseModel):
    """A frictionless wall through the start's tip: the tip slides along it, the load along the wall is
    `tau . (base + t d)`, the wall's reaction along its normal."""

    model_config = _STRICT
    kind: Literal["wall"]
    normal: Vec2 = Field([0.0, 1.0], description="the wall's normal (normalised)")
    direction: Vec2 = Field([-1.0, 0.0], description="load direction (normalised; needs a component along the wall)")
    base: Vec2 = Field([0.0, 0.0], description="the load at t = 0 (force units)")


class PreloadControlIn(BaseModel):
    """The rest lengths moved along a unit direction of `2n` numbers (`L1_0, L2_0` of segment 1, then of
    segment 2, ...; `t` the distance in rest-length space, length units), the tip free under `load` or held."""

    model_config = _STRICT
    kind: Literal["preload"]
    direction: list[ForceValue] = Field(min_length=2, max_length=2 * HARD_MAX_SEGMENTS,
                                        description="2n numbers: the direction in rest-length space (normalised)")
    tip: Literal["free", "held"] = Field("free", description="free under `load`, or held where the start has it")
    load: Vec2 = Field([0.0, 0.0], description="the fixed tip load with a free tip (force units)")


CONTROL_KINDS = ("displacement", "load", "guided", "wall", "preload")


def _control_kind(v: Any) -> str | None:
    kind = v.get("kind") if isinstance(v, dict) else getattr(v, "kind", None)
    return f"<{kind}>" if isinstance(kind, str) else None


ControlIn = Annotated[
    Union[
        Annotated[DisplacementControlIn, Tag("<displacement>")],
        Annotated[LoadControlIn, Tag("<load>")],
        Annotated[GuidedControlIn, Tag("<guided>")],
        Annotated[WallControlIn, Tag("<wall>")],
        Annotated[PreloadControlIn, Tag("<preload>")],
    ],
    Discriminator(_control_kind, custom_error_type="invalid_control",
                  custom_error_message="kind must be one of " + ", ".join(CONTROL_KINDS),
                  custom_error_context={"kinds": ", ".join(CONTROL_KINDS)}),
    Field(description="what the continuation parameter t moves: {\"kind\": " + " | ".join(CONTROL_KINDS)
                      + ", ...} (tensegrity_opt.Control)"),
]


# ---------------------------------------------------------------------------- starts
class StartQ(BaseModel):
    """Joint angles to start from (Newton puts them on the branch at t = 0)."""

    model_config = _STRICT
    q: list[Angle] = Field(min_length=1, max_length=HARD_MAX_SEGMENTS,
                           description="relative joint angles (rad), n of them, inside the physical range")


class StartDeflection(BaseModel):
    """The least-energy stable equilibrium with the tip held at this deflection (`/v1/equilibrium`)."""

    model_config = _STRICT
    dx: TipDx
    dy: TipDy = 0.0


def _start_kind(v: Any) -> str:
    if isinstance(v, StartQ) or (isinstance(v, dict) and "q" in v):
        return "<q>"
    return "<deflection>"


StartIn = Annotated[
    Union[Annotated[StartQ, Tag("<q>")], Annotated[StartDeflection, Tag("<deflection>")]],
    Discriminator(_start_kind),
    Field(description='{"q": [...]} joint angles, or {"dx", "dy"}: the least-energy equilibrium with the tip held '
                      "there (a control holding the tip: displacement, preload with tip held)"),
]


# ---------------------------------------------------------------------------- requests
class RestConfigurationsRequest(BaseModel):
    """Every equilibrium under a dead tip load `F = (fx, fy)`; `F = 0` (default): the rest configurations."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": PAPER_CHAIN, "fx": 0.0, "fy": 0.0, "method": "search", "stable_only": False}]})

    manipulator: ManipulatorIn
    fx: ForceValue = Field(0.0, description="tip force along x (force units); fx < 0 compresses")
    fy: ForceValue = Field(0.0, description="tip force along y (force units)")
    method: Literal["search", "homotopy"] = Field(
        "search", description="for F != 0: `search` (multi-start Newton, complete in practice, not certified) or "
                              "`homotopy` (PHCpack, certified; chains up to the server's `homotopy_max_segments`). "
                              "F = 0 is exact either way (a product of the segments' own critical points)")
    stable_only: bool = Field(False, description="only the stable equilibria (minima of E - F . tip)")


class _BranchFields(BaseModel):
    model_config = ConfigDict(strict=True, extra="forbid")

    manipulator: ManipulatorIn
    start: StartIn | None = Field(None, description="where t = 0 is: null (default) the least-energy rest "
                                                    "configuration, {\"q\"} or {\"dx\", \"dy\"}")
    control: ControlIn
    t_max: Parameter | None = Field(None, description="stop where t reaches this (the control's unit)")
    t_min: Parameter | None = Field(None, description="stop where t falls to this")
    max_points: MaxPoints = 1000


class BranchRequest(_BranchFields):
    """One equilibrium branch by pseudo-arclength continuation (`tensegrity_opt.trace_branch`)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": PAPER_CHAIN, "start": {"q": [0.0, 0.0, 0.0, 0.0]},
                      "control": {"kind": "guided", "direction": [-1.0, 0.0]}, "t_max": 2.0}]})

    stop_at: Literal["stability_loss", "event"] | None = Field(
        None, description="stop after the first event where stability is lost, or after any event")
    orientation: Annotated[Literal[1, -1], BeforeValidator(integral)] = Field(
        1, description="leave the start with t increasing (1) or decreasing (-1)")


class BifurcationDiagramRequest(_BranchFields):
    """Every branch reached from the start through branch points (`tensegrity_opt.bifurcation_diagram`)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": PAPER_CHAIN, "start": {"q": [0.0, 0.0, 0.0, 0.0]},
                      "control": {"kind": "guided", "direction": [-1.0, 0.0]}, "t_max": 2.0, "depth": 1,
                      "max_points": 200}]})

    depth: Int = Field(2, ge=0, le=MAX_DEPTH, description=f"branch switches followed (0..{MAX_DEPTH})")
    max_branches: Int = Field(24, ge=1, le=MAX_BRANCHES, description=f"at most this many branches (1..{MAX_BRANCHES})")


class _LimitLoadFields(BaseModel):
    model_config = ConfigDict(strict=True, extra="forbid")

    manipulator: ManipulatorIn
    direction: Vec2 = Field([-1.0, 0.0], description="the load's direction (normalised; [-1, 0] compresses)")
    boundary: Literal["free", "guided"] = Field(
        "free", description='"free": the tip free, F = t d; "guided": y held, Fx = t d_x, Fy the reaction')
    max_load: Annotated[float, Field(gt=0, le=MAX_FORCE, allow_inf_nan=False)] | None = Field(
        None, description="stop there (force units); default 100 k c^2 / (2b)")
    start: StartQ | None = Field(None, description='{"q": [...]}: a rest configuration to start from; null: the '
                                                   "least-energy rest configuration")
    max_points: MaxPoints = 4000


class LimitLoadRequest(_LimitLoadFields):
    """The dead load where the branch from a rest configuration first loses stability (`tensegrity_opt.limit_load`)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": PAPER_CHAIN, "direction": [-1.0, 0.0], "boundary": "guided",
                      "start": {"q": [0.0, 0.0, 0.0, 0.0]}}]})

    include_branch: bool = Field(False, description="also return the traced path (`branch`)")


class _ImperfectionFields(BaseModel):
    model_config = ConfigDict(strict=True, extra="forbid")

    manipulator: ManipulatorIn
    amplitudes: list[Parameter] = Field(
        min_length=1, max_length=MAX_AMPLITUDES,
        description=f"the amplitudes p, computed in this order (1..{MAX_AMPLITUDES}; 0 is the given chain)")
    imperfection: Literal[PARAMETERS] = Field(
        "asymmetry", description="what p moves: asymmetry (every segment's rest lengths L1_0 + p, L2_0 - p: a "
                                 "pre-bend), L0 (both + p), a, b, k (both springs)")
    direction: Vec2 = Field([-1.0, 0.0], description="the load's direction (normalised; [-1, 0] compresses)")
    boundary: Literal["free", "guided"] = Field(
        "guided", description='"guided": y held at each imperfect chain\'s rest tip, Fx = t d_x; "free": F = t d')
    max_load: Annotated[float, Field(gt=0, le=MAX_FORCE, allow_inf_nan=False)] | None = Field(
        None, description="stop each path there (force units); default 100 k c^2 / (2b)")
    max_points: MaxPoints = 4000


class ImperfectionSensitivityRequest(_ImperfectionFields):
    """The limit load of each imperfect chain's dead-load path from its rest shape, against the imperfection's
    amplitude (`tensegrity_opt.imperfection_sensitivity`)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": PAPER_CHAIN, "amplitudes": [0.0, 0.01, 0.02851, 0.061]}]})

    include_limit_loads: bool = Field(False, description="also return each amplitude's limit load (`limit_loads`, "
                                                         "as `/v1/limit-load` answers it) and `perfect`")


class StabilityBoundaryRequest(BaseModel):
    """The curve of folds or branch points in (parameter, t) (`tensegrity_opt.stability_boundary`)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": PAPER_CHAIN, "control": {"kind": "guided", "direction": [-1.0, 0.0]},
                      "parameter": "asymmetry", "p_min": -0.1, "p_max": 0.1, "max_points": 400}]})

    manipulator: ManipulatorIn
    control: ControlIn = Field(default_factory=lambda: GuidedControlIn(kind="guided"),
                               description="the control of the one-parameter branches (default guided)")
    parameter: str = Field("asymmetry", min_length=1, max_length=64, pattern=r"^[A-Za-z0-9_.\[\]]+$",
                           description="the second parameter p the boundary is followed in (the library's names; "
                                       "an unknown one is refused with invalid_parameter on `parameter`)")
    p_min: Parameter = Field(-0.1, description="the boundary is followed for p_min <= p <= p_max")
    p_max: Parameter = Field(0.1, description="upper end of p")
    max_points: MaxPoints = 400


# ---------------------------------------------------------------------------- responses
class ControlOut(BaseModel):
    kind: Literal["displacement", "load", "guided", "wall", "preload"]
    direction: list[float] = Field(description="the unit direction")
    base: list[float] | None = Field(None, description="the load at t = 0 (load, guided, wall)")
    load: list[float] | None = Field(None, description="the tip load (preload)")
    normal: list[float] | None = Field(None, description="the wall's unit normal (wall)")
    tip: Literal["free", "held"] | None = Field(None, description="preload only")


class BranchEventOut(SpringStateOut):
    """A special point, located between points `index` and `index + 1`."""

    kind: Literal[EVENT_KINDS] = Field(description="fold (t turns back: snap-through under this control), "
                                                   "branch_point (another branch crosses), joint_limit (the end), "
                                                   "spring_slack / spring_taut (a tension-only spring reaches its "
                                                   "rest length: the joint's stiffness jumps)")
    index: int
    t: float
    q: list[float]
    force: Force
    tip: list[float]
    energy: float
    null_vector: list[float] | None = Field(description="the buckling or snapping mode (largest entry +1)")
    morse_before: int
    morse_after: int
    stability: Literal["lost", "gained", "unchanged"]
    method: str = Field(description="moore_spence, test_function or limit")
    residual: float | None
    joint: int | None = Field(description="the joint at its limit (0-based), joint_limit; the segment whose spring "
                                          "changes state, spring_slack / spring_taut")
    spring: int | None = Field(None, description="which of the segment's springs (1 or 2), spring events only")
    stiffness_before: float | None = Field(None, description="the joint's stiffness d2E/dq2 before a spring event")
    stiffness_after: float | None = Field(None, description="the joint's stiffness d2E/dq2 after a spring event")


class TracedBranchOut(SpringSeriesOut, outcome_model(to.Branch)):
    """An equilibrium branch: per point the parameter, configuration, force, tip, energy and stability; `status`
    says how it ended (`success` false: the corrector failed or time ran out, the points computed are kept)."""

    control: ControlOut
    points: int
    t: list[float] = Field(description="the control parameter (0 at the start)")
    q: list[list[float]] = Field(description="joint angles (rad) per point")
    force: list[Force] = Field(description="tip force per point (a reaction where the tip is held)")
    tip: list[list[float]]
    deflection: list[list[float]] = Field(description="(dx, dy) = (2 sum b - x, y) per point")
    energy: list[float] = Field(description="elastic energy per point (force x length)")
    morse_index: list[int] = Field(description="negative eigenvalues of the reduced Hessian (0: stable)")
    stable: list[bool]
    s: list[float] = Field(description="arclength (normalised: rad, F / (k c^2 / 2b), length / 2b)")
    events: list[BranchEventOut]
    rest_lengths: list[list[list[float]]] | None = Field(None, description="preload only: [L1_0, L2_0] per segment "
                                                                           "per point")


class BifurcationDiagramOut(BaseModel):
    branches: list[TracedBranchOut] = Field(description="the start's branch with t increasing, then decreasing, then "
                                                        "the switched branches breadth-first")


class LimitLoadOut(SpringStateOut, outcome_model(to.LimitLoad)):
    """The limit load: `status` stability_lost (`kind` fold or bifurcation), or why the path has none."""

    load: float | None = Field(description="the load where stability is first lost (null for kind none)")
    kind: Literal["fold", "bifurcation", "none"]
    force: Force | None
    q: list[float] | None
    null_vector: list[float] | None
    quasi_buckling_load: float | None = Field(description="the load of least tangent stiffness along the load")
    quasi_buckling_force: Force | None
    quasi_buckling_stiffness: float | None = Field(description="the tangent stiffness along the load there, "
                                                               "1 / (d . C d) (force per length; guided: y held), "
                                                               "the least on the stable path")
    end_load: float = Field(description="the last load reached on the stable path")
    direction: list[float]
    boundary: Literal["free", "guided"]
    start: EquilibriumOut = Field(description="the rest configuration the path starts from")
    branch_status: Literal[tuple(to.Branch.STATUSES)] = Field(description="how the traced path ended (its status)")
    branch_points: int
    branch: TracedBranchOut | None = Field(None, description="include_branch only: the traced path")


class ImperfectionLawOut(BaseModel):
    """The small-imperfection law `perfect_load - load = coefficient |p|^exponent` fitted at `amplitudes`."""

    exponent: float
    expected: float = Field(description="the classical exponent: 2/3 (unstable-symmetric), 1/2 (asymmetric)")
    coefficient: float
    amplitudes: list[float]


class ImperfectionSensitivityOut(outcome_model(to.ImperfectionSensitivity)):
    """The imperfection-sensitivity curve: per amplitude the limit load and its kind."""

    imperfection: Literal[PARAMETERS]
    direction: list[float]
    boundary: Literal["free", "guided"]
    max_load: float | None
    amplitudes: list[float]
    loads: list[float | None] = Field(description="the limit load per amplitude (a joint limit: the load where the "
                                                  "stable path reaches it; null for kind none or unknown)")
    kinds: list[Literal[KINDS]] = Field(description="fold, bifurcation, joint_limit, none (stable to max_load), "
                                                    "unknown (the path was cut, or time ran out before it)")
    statuses: list[Literal[AMPLITUDE_STATUSES]] = Field(
        description="per amplitude the limit load's status, failed (its chain could not be followed) or "
                    "not_computed (time ran out before it)")
    messages: list[str]
    perfect_load: float | None = Field(description="the given chain's limit load")
    perfect_kind: Literal[KINDS]
    bifurcation: Literal[tuple(BIFURCATIONS)] | None = Field(
        description="the given chain's bifurcation by its buckled arms (null: its limit is not a bifurcation)")
    law: ImperfectionLawOut | None = Field(description="the fitted small-imperfection law, where one applies")
    limit_loads: list[LimitLoadOut | None] | None = Field(None, description="include_limit_loads only")
    perfect: LimitLoadOut | None = Field(None, description="include_limit_loads only: the given chain's limit load")


class CuspOut(BaseModel):
    """A cusp of a fold curve: where the fold's quadratic coefficient changes sign."""

    kind: Literal["cusp"]
    p: float
    t: float
    q: list[float]
    force: Force


class StabilityBoundaryOut(outcome_model(to.StabilityBoundary)):
    """`StabilityBoundary.to_dict()` of the library (`tensegrity_opt.analyses.paths.boundaries`): the first
    stability-losing fold or branch point against the parameter `p`."""

    kind: Literal["fold", "branch_point"]
    parameter: str = Field(description="the parameter's name (or `direction`)")
    control: ControlOut
    points: int
    p: list[float] = Field(description="the parameter along the curve (0: the given chain)")
    t: list[float] = Field(description="the limit or critical load (the control's parameter) at each p")
    q: list[list[float]] = Field(description="joint angles (rad) per point")
    force: list[Force]
    null_vectors: list[list[float]] = Field(description="the mode at each point (largest entry +1)")
    cusps: list[CuspOut]
