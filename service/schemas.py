"""Request and response models of the HTTP API (pydantic v2), separate from the library's types.

Units are the caller's: lengths in one length unit, stiffness in force per length, forces in
force units, energies in force x length, angles in radians.

Requests are validated strictly (a number must be a JSON number, not a string; booleans are not
numbers; NaN/Infinity are refused) and unknown fields are refused, so a typo is a 422 naming the
field instead of a silently ignored input. The bounds below are hard caps of the schema; the
server's configured limits (`/version` reports them) can be tighter and are then answered with
a domain code (`too_many_segments`, `batch_too_large`).
"""

from __future__ import annotations

from typing import Annotated, Any, Literal, Union

from pydantic import BaseModel, BeforeValidator, ConfigDict, Discriminator, Field, Tag

from .config import HARD_MAX_BATCH, HARD_MAX_SEGMENTS

# ---------------------------------------------------------------------------- limits
#: Range of the lengths (a, b, L0) and spring stiffnesses accepted (caller's units). Values far
#: outside any physical design (e.g. subnormal numbers) only make the model underflow.
MIN_LENGTH = 1.0e-6
MAX_LENGTH = 1.0e6
MIN_STIFFNESS = 1.0e-6
MAX_STIFFNESS = 1.0e9
#: Largest |dx|, |dy| (length units) and |force| accepted.
MAX_DEFLECTION = 1.0e9
MAX_FORCE = 1.0e12
#: Joint angles in requests (rad): q0 and the torque-curve abscissae.
MAX_ANGLE = 6.283185307179586
#: Points of a force-deflection curve.
MAX_CURVE_POINTS = 501
#: Points per axis of an energy landscape.
MAX_GRID = 201
#: Abscissae of a segment torque curve.
MAX_TORQUE_POINTS = 10001

_STRICT = ConfigDict(strict=True, extra="forbid")


def integral(v: Any) -> Any:
    """A float with an integral value (``4.0``, ``5e2``) as the ``int`` it is: JSON Schema's ``integer``
    is any number with a zero fractional part, so ``"n": 4.0`` is valid by the document. Anything
    else goes on unchanged to the strict ``int`` check (``4.5``, ``"4"``, ``true`` are refused)."""
    if type(v) is float and v.is_integer():
        return int(v)
    return v


#: The request schema's integer: strict (no strings, no booleans) but integral floats accepted.
#: As a field's type with ``= Field(ge=..)``; inside ``Annotated`` put the ``Field`` *before* the
#: validator (``Annotated[int, Field(ge=0), BeforeValidator(integral)]``): after it, pydantic writes
#: ``ge``/``le`` into the JSON schema instead of ``minimum``/``maximum``.
Int = Annotated[int, BeforeValidator(integral)]

Length = Annotated[float, Field(ge=MIN_LENGTH, le=MAX_LENGTH, allow_inf_nan=False)]
Stiff = Annotated[float, Field(ge=MIN_STIFFNESS, le=MAX_STIFFNESS, allow_inf_nan=False)]
Deflection = Annotated[float, Field(ge=-MAX_DEFLECTION, le=MAX_DEFLECTION, allow_inf_nan=False)]
ForceValue = Annotated[float, Field(ge=-MAX_FORCE, le=MAX_FORCE, allow_inf_nan=False)]
Angle = Annotated[float, Field(ge=-MAX_ANGLE, le=MAX_ANGLE, allow_inf_nan=False)]


def _number_or_pair(v: Any) -> str:
    return "<pair>" if isinstance(v, (list, tuple)) else "<number>"


def _pair_of(item: Any, what: str) -> Any:
    return Annotated[
        Union[
            Annotated[item, Tag("<number>")],
            Annotated[list[item], Field(min_length=2, max_length=2), Tag("<pair>")],
        ],
        Discriminator(_number_or_pair),
        Field(description=f"{what}: one number for both springs or the pair [spring 1, spring 2]"),
    ]


StiffPair = _pair_of(Stiff, "spring stiffness k (force / length)")
LengthPair = _pair_of(Length, "spring rest length L0 (length units)")


# ---------------------------------------------------------------------------- manipulator
class SegmentIn(BaseModel):
    """One dual-triangle segment."""

    model_config = ConfigDict(strict=True, extra="forbid",
                              json_schema_extra={"examples": [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0},
                                                              {"a": 1.0, "b": 1.0, "k": [1.0, 2.0], "L0": 1.0}]})

    a: Length = Field(description="triangle half-height (length units)")
    b: Length = Field(description="triangle half-length (length units); the segment is 2b long")
    k: StiffPair = 1.0
    L0: LengthPair = 1.0


class UniformManipulatorIn(BaseModel):
    """`n` identical segments."""

    model_config = ConfigDict(strict=True, extra="forbid",
                              json_schema_extra={"examples": [{"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}]})

    n: Int = Field(ge=1, le=HARD_MAX_SEGMENTS, description=f"number of segments (server limit "
                                                         f"TENSEGRITY_MAX_SEGMENTS, at most {HARD_MAX_SEGMENTS})")
    a: Length = Field(1.0, description="triangle half-height (length units)")
    b: Length = Field(1.0, description="triangle half-length (length units)")
    k: StiffPair = 1.0
    L0: LengthPair = 1.0


class SegmentedManipulatorIn(BaseModel):
    """Segments listed from base to tip; they may differ in every parameter."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"segments": [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}] * 4}]})

    segments: list[SegmentIn] = Field(min_length=1, max_length=HARD_MAX_SEGMENTS,
                                      description="segments from base to tip (server limit TENSEGRITY_MAX_SEGMENTS)")


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


def _manipulator_kind(v: Any) -> str:
    if isinstance(v, SegmentedManipulatorIn) or (isinstance(v, dict) and "segments" in v):
        return "<segments>"
    return "<uniform>"


def _manipulator_union(uniform: type, segmented: type, what: str) -> Any:
    """The request's chain: the uniform or the segmented form, told apart by ``segments``."""
    return Annotated[
        Union[Annotated[uniform, Tag("<uniform>")], Annotated[segmented, Tag("<segments>")]],
        Discriminator(_manipulator_kind),
        Field(description=f'{what}: {{"n", "a", "b", "k", "L0"}} (uniform) or {{"segments": [...]}}'),
    ]


ManipulatorIn = _manipulator_union(UniformManipulatorIn, SegmentedManipulatorIn, "the chain")
DesignManipulatorIn = _manipulator_union(DesignUniformManipulatorIn, DesignSegmentedManipulatorIn,
                                         "the chain (at most 60 segments)")

PAPER_CHAIN = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}


class RangeIn(BaseModel):
    """`num` evenly spaced values from `start` to `stop` inclusive (like `numpy.linspace`)."""

    model_config = _STRICT

    start: float = Field(allow_inf_nan=False)
    stop: float = Field(allow_inf_nan=False)
    num: Int = Field(ge=1)


def _list_or_range(v: Any) -> str:
    return "<range>" if isinstance(v, (dict, RangeIn)) else "<list>"


class DeflectionRange(RangeIn):
    start: Deflection
    stop: Deflection
    num: Int = Field(ge=1, le=MAX_CURVE_POINTS, description=f"number of points (at most {MAX_CURVE_POINTS})")


class AngleRange(RangeIn):
    start: Angle
    stop: Angle
    num: Int = Field(ge=1, le=MAX_TORQUE_POINTS, description=f"number of points (at most {MAX_TORQUE_POINTS})")


# ---------------------------------------------------------------------------- requests
class EquilibriumRequest(BaseModel):
    """Least-energy stable equilibrium with the tip held at `(2 sum(b) - dx, dy)`."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": PAPER_CHAIN, "dx": 0.1, "dy": 0.0}]})

    manipulator: ManipulatorIn
    dx: Deflection = Field(description="tip deflection along x (length units); dx > 0 shortens the chain")
    dy: Deflection = Field(0.0, description="tip deflection along y (length units)")
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
    dx: Deflection = Field(description="tip deflection along x (length units)")
    dy: Deflection = Field(0.0, description="tip deflection along y (length units)")
    method: Literal["search", "homotopy"] = Field(
        "search", description="`search`: multi-start Newton (any n; complete in practice, not certified); "
                              "`homotopy`: PHCpack's polyhedral homotopy on the polynomial KKT system, every "
                              "equilibrium certified (chains up to the server's `homotopy_max_segments`, default 4; "
                              "seconds; needs the `phcpack` package on the server, else 503 `homotopy_unavailable`)")


class BucklingRequest(BaseModel):
    """Critical loads and buckling modes of the straight configuration."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": PAPER_CHAIN, "boundary": "guided"}]})

    manipulator: ManipulatorIn
    boundary: Literal["guided", "free"] = Field(
        "guided", description='"guided": tip held at dy = 0 (the paper); "free": cantilever')


class ForceDeflectionRequest(BaseModel):
    """Force-deflection curve by continuation along the least-energy stable branch."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": PAPER_CHAIN, "dx": {"start": 0.0, "stop": 0.5, "num": 6}, "dy": 0.0,
                      "branch": "stable"}]})

    manipulator: ManipulatorIn
    dx: Annotated[
        Union[
            Annotated[list[Deflection], Field(min_length=1, max_length=MAX_CURVE_POINTS), Tag("<list>")],
            Annotated[DeflectionRange, Tag("<range>")],
        ],
        Discriminator(_list_or_range),
        Field(description=f"deflections in the order to follow: a list or {{start, stop, num}} "
                          f"(at most {MAX_CURVE_POINTS} points)"),
    ]
    dy: Deflection = Field(0.0, description="tip deflection along y, the same at every point")
    branch: Literal["stable", "all"] = Field(
        "stable", description='"all" also returns every branch found at the first deflected point')


class StiffnessRequest(BaseModel):
    """Cartesian tangent stiffness at the equilibrium `/v1/equilibrium` returns."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": PAPER_CHAIN, "dx": 0.1, "dy": 0.0}]})

    manipulator: ManipulatorIn
    dx: Deflection = Field(description="tip deflection along x (length units)")
    dy: Deflection = Field(0.0, description="tip deflection along y (length units)")
    q0: list[Angle] | None = Field(None, max_length=HARD_MAX_SEGMENTS, description="optional nearby configuration")


class SegmentTorqueRequest(BaseModel):
    """Torque curve `M(q)` of one segment."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"segment": {"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}, "q": [-0.5, 0.0, 0.5]},
                     {"segment": {"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0},
                      "q": {"start": -1.0, "stop": 1.0, "num": 5}}]})

    segment: SegmentIn
    q: Annotated[
        Union[
            Annotated[list[Angle], Field(min_length=1, max_length=MAX_TORQUE_POINTS), Tag("<list>")],
            Annotated[AngleRange, Tag("<range>")],
        ],
        Discriminator(_list_or_range),
        Field(description=f"joint angles (rad, |q| <= 2 pi): a list or {{start, stop, num}} "
                          f"(at most {MAX_TORQUE_POINTS} points)"),
    ]


class EnergyLandscapeRequest(BaseModel):
    """Energy over a grid of two joint angles, the other two from inverse kinematics (n = 4 only)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": PAPER_CHAIN, "dx": 0.1, "dy": 0.0, "pair": [0, 3], "grid": 3}]})

    manipulator: ManipulatorIn
    dx: Deflection = Field(description="tip deflection along x (length units)")
    dy: Deflection = Field(0.0, description="tip deflection along y (length units)")
    pair: list[Annotated[int, Field(ge=0, le=3), BeforeValidator(integral)]] = Field(
        [0, 3], min_length=2, max_length=2, description="the two grid joints, 0-based and different")
    grid: Int = Field(51, ge=2, le=MAX_GRID, description=f"points per axis (2..{MAX_GRID})")
    span: Annotated[float, Field(gt=0, le=MAX_ANGLE, allow_inf_nan=False)] | None = Field(
        None, description="half-width of both axes (rad); default: the smaller joint limit of the pair")


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


# ---------------------------------------------------------------------------- responses
class Force(BaseModel):
    fx: float = Field(description="tip force along x (force units)")
    fy: float = Field(description="tip force along y (force units)")


class SolverInfo(BaseModel):
    status: str = Field(description="the solver's return status (IPOPT return_status, Newton status, or 'straight')")
    iterations: int


class EquilibriumOut(BaseModel):
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


class EquilibriaOut(BaseModel):
    equilibria: list[EquilibriumOut] = Field(description="every equilibrium found, sorted by energy")
    method: str = Field(description="how they were found: `search`, `homotopy`, or `straight` / `closed_form` "
                                    "for the trivial cases")
    certified: bool = Field(description="true only when the set is proven complete (the homotopy tracked every "
                                        "path to an end and every real root polished; or a trivial case)")
    paths: int = Field(description="homotopy paths tracked (0 for the search)")
    failed_paths: int = Field(description="homotopy paths that failed (any makes `certified` false)")


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


class BucklingOut(BaseModel):
    boundary: Literal["guided", "free"]
    critical_force: float = Field(description="signed critical Fx0 = -min(loads) (negative: compressive)")
    loads: list[float] = Field(description="all critical loads, ascending")
    modes: list[ModeOut]


class CurvePoint(BaseModel):
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


class JumpOut(BaseModel):
    kind: Literal["buckling", "branch_switch"]
    dx_before: float
    dx_after: float
    force_before: Force
    force_after: Force
    branch_before: int
    branch_after: int


class BranchPoint(BaseModel):
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


class ForceDeflectionOut(BaseModel):
    points: list[CurvePoint]
    jumps: list[JumpOut]
    branches: list[BranchOut] = Field(description='branch = "all" only (else empty)')


class StiffnessOut(BaseModel):
    matrix: list[list[float]] = Field(description="2 x 2 tangent stiffness dF_i / d tip_j (force / length)")
    equilibrium: EquilibriumOut


class SegmentTorqueOut(BaseModel):
    q: list[float] = Field(description="joint angles (rad)")
    torque: list[float] = Field(description="spring torque M(q) = -dE/dq")
    dtorque: list[float] = Field(description="M'(q); the segment alone is stable where < 0")
    energy: list[float] = Field(description="segment energy E(q)")
    stiffness: float = Field(description="joint stiffness K = E''(0)")
    monotonic: bool = Field(description="M(q) decreases over the whole physical range")
    joint_limit: float = Field(description="physical range |q| < pi - 2 beta (rad)")


class EnergyLandscapeOut(BaseModel):
    pair: list[int]
    qi: list[float] = Field(description="grid axis of joint pair[0] (rad)")
    qj: list[float] = Field(description="grid axis of joint pair[1] (rad)")
    energy: list[list[list[float | None]]] = Field(
        description="energy[elbow][i][j], elbow 0: +1, 1: -1; null where unreachable or out of range")


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


class Health(BaseModel):
    status: Literal["ok"]


class Ready(BaseModel):
    status: Literal["ready", "starting"]
    workers: int
    queue_size: int
    in_flight: int


class Limits(BaseModel):
    max_segments: int
    max_batch: int
    solve_timeout: float
    batch_timeout: float
    workers: int
    queue_size: int
    inline_max_segments: int
    # NB the description below is stale since issue 15 (with 0 processes the solver threads run the search);
    # kept as it is because it is part of the committed OpenAPI document (change both together)
    inline_processes: int = Field(description="solver processes running the short chains' bounded search "
                                              "(service.lane); 0: the event loop runs it")
    max_body_bytes: int
    max_response_bytes: int = Field(description="largest JSON answer (422 response_too_large above)")
    max_curve_points: int
    max_grid: int
    max_torque_points: int


class KernelsOut(BaseModel):
    """How the compiled Newton kernels run in this server process (`tensegrity_opt.numerics.kernels`)."""

    compiler: str | None = Field(description="the C compiler used; null: none (kernels run in CasADi's VM)")
    max_segments: int = Field(description="chains up to this long have kernels")
    compiled: list[int] = Field(description="chain lengths loaded as compiled code so far")
    virtual_machine: list[int] = Field(description="chain lengths running in CasADi's virtual machine "
                                                   "(no compiler, or compiling failed: about 4x slower)")


class VersionOut(BaseModel):
    service: str
    version: str
    library_version: str
    api: str
    auth: bool
    limits: Limits
    kernels: KernelsOut


# ---------------------------------------------------------------------------- design and control
DesignVar = Literal["a", "b", "k", "L0"]
Positive = Annotated[float, Field(gt=0.0, le=MAX_STIFFNESS, allow_inf_nan=False)]


class BoundsIn(BaseModel):
    model_config = _STRICT
    lo: Positive = Field(description="lower bound (same for every segment)")
    hi: Positive = Field(description="upper bound")


class DesignCriticalForceRequest(BaseModel):
    """Maximise the critical load over per-segment design variables."""

    model_config = _STRICT
    manipulator: DesignManipulatorIn
    vary: list[DesignVar] = Field(["k"], min_length=1, max_length=4, description="per-segment variables to optimise")
    bounds: dict[DesignVar, BoundsIn] = Field(default_factory=dict,
                                              description="bounds per variable; default (x0 / 10, 10 x0)")
    budget: dict[DesignVar, Positive] = Field(default_factory=dict, description="cap on the sum over the segments")
    boundary: Literal["guided", "free"] = "guided"
    total_length: Annotated[float, Field(gt=0, le=MAX_LENGTH, allow_inf_nan=False)] | bool | None = Field(
        None, description="fix 2 sum(b): a length, or true to keep the initial one")
    tension: BoundsIn | None = Field(None, description="bounds on the preload tension k (2b - L0) at straight")
    K_min: Annotated[float, Field(ge=-MAX_STIFFNESS, le=MAX_STIFFNESS, allow_inf_nan=False)] | None = Field(
        None, description="lower bound on every joint stiffness K_i")


class PreloadsForLoadRequest(BaseModel):
    """The smallest change of the rest lengths L0 making the critical load at least `required`."""

    model_config = _STRICT
    manipulator: DesignManipulatorIn
    required: Positive = Field(description="required critical compressive load (force units)")
    boundary: Literal["guided", "free"] = "guided"
    bounds: BoundsIn | None = Field(None, description="bounds on every L0; default (0.05 * 2b, 2b)")


class Point(BaseModel):
    model_config = _STRICT
    x: Deflection
    y: Deflection


class LoadIn(BaseModel):
    model_config = _STRICT
    fx: ForceValue = 0.0
    fy: ForceValue = 0.0


class PreloadsRequest(BaseModel):
    """Rest lengths putting the tip at a target, stably, under a tip load."""

    model_config = _STRICT
    manipulator: DesignManipulatorIn
    target: Point = Field(description="tip position (length units)")
    load: LoadIn = Field(default_factory=lambda: LoadIn(), description="tip force (dead load)")
    objective: Literal["nominal", "margin", "energy"] = "nominal"
    margin: Annotated[float, Field(ge=0, le=MAX_STIFFNESS, allow_inf_nan=False)] = Field(
        1e-3, description="required smallest eigenvalue of the joint-space Hessian (torque / rad)")
    taut: bool = Field(False, description="keep every spring in tension (L >= L0)")
    bounds: BoundsIn | None = Field(None, description="bounds on every rest length; default (0.1 b_min, 4 b_max)")
    end_angle: Angle | None = Field(None, description="absolute angle of the last link (rad), optional")


class SegmentOut(BaseModel):
    a: float
    b: float
    k: float | list[float]
    L0: float | list[float]


class ManipulatorOut(BaseModel):
    segments: list[SegmentOut]


class DesignOut(BaseModel):
    manipulator: ManipulatorOut
    critical_force: float = Field(description="signed critical force, recomputed by critical_force on the design")
    loads: list[float] = Field(description="all critical loads of the design, ascending (recomputed)")
    multiplicity: int = Field(description="how many critical loads coincide with the smallest")
    active: list[str] = Field(description="active constraints at the optimum")
    initial_critical_force: float | None = Field(description="the starting design's critical force")
    feasible: bool = Field(description="preloads-for-load: whether the required load is reached")
    solver: SolverInfo


class PreloadsOut(BaseModel):
    manipulator: ManipulatorOut
    preloads: list[list[float]] = Field(description="rest lengths [L1_0, L2_0] per segment")
    q: list[float] = Field(description="verified equilibrium configuration (rad)")
    margin: float = Field(description="achieved stability margin (recomputed)")
    tip: list[float]
    energy: float
    solver: SolverInfo


# ---------------------------------------------------------------------------- errors
class FieldError(BaseModel):
    field: str = Field(description="dotted path of the offending input, e.g. manipulator.segments[0].a")
    message: str
    type: str


class ErrorOut(BaseModel):
    """Every refusal has this shape."""

    code: str = Field(description="machine-readable reason, e.g. validation_error, unreachable_target, "
                                  "straight_not_equilibrium, straight_unstable, too_many_segments, "
                                  "solver_failed, no_equilibrium, timeout, overloaded, body_too_large, "
                                  "unauthorized")
    message: str = Field(description="human-readable explanation")
    field: str | None = Field(None, description="the input to blame, when there is one")
    status: str | None = Field(None, description="solver return status(es), for solver failures")
    errors: list[FieldError] | None = Field(None, description="every schema violation (validation_error only)")
    details: dict[str, Any] | None = Field(None, description="extra numbers (e.g. distance and reach)")
    best: dict[str, Any] | None = Field(None, description="design_infeasible only: the best point IPOPT found")


BatchItem.model_rebuild()
