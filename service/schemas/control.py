"""Models of the control endpoints: ``/v1/control/plan``, ``/v1/control/simulate``, ``/v1/control/force-estimate``.

* *plan*: rest lengths for a trajectory of tip positions (``tensegrity_opt.plan_preloads``);
* *simulate*: the quasi-static forward simulation under sampled inputs, snapping at folds
  (``tensegrity_opt.simulate``);
* *force-estimate*: the tip force from measured joint angles (``tensegrity_opt.estimate_tip_force``).

Same conventions as :mod:`service.schemas` (strict, no NaN, unknown fields refused). A trajectory holds at most
``HARD_MAX_TRAJECTORY_STEPS`` steps (the default of ``TENSEGRITY_MAX_TRAJECTORY_STEPS``; a server with a lower
setting answers 422 ``too_many_steps`` naming the field). What JSON Schema cannot say (``loads`` of the wrong
count, ``2 n`` bounds, a ``sigma_q`` that is not a covariance, ``measured`` indices out of range ...) is
refused by the library with a domain code naming the field.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal, Union

from pydantic import BaseModel, BeforeValidator, ConfigDict, Discriminator, Field, Tag

import tensegrity_opt as to
from tensegrity_opt.analyses.design.horizon import HORIZONS
from tensegrity_opt.analyses.design.preload_control import METHODS, ON_INFEASIBLE, ON_SNAP
from tensegrity_opt.analyses.design.preloads import OBJECTIVES
from tensegrity_opt.analyses.paths.simulation import EVENT_KINDS as SIMULATION_EVENT_KINDS
from tensegrity_opt.analyses.paths.simulation import Simulation, SimulationEvent

from ..config import HARD_MAX_SEGMENTS, HARD_MAX_TRAJECTORY_STEPS
from .common import (
    _STRICT,
    MARGIN_DOC,
    MAX_ANGLE,
    MAX_STIFFNESS,
    PAPER_CHAIN,
    TAUT_DOC,
    Angle,
    Deflection,
    Force,
    ForceValue,
    Length,
    ManipulatorIn,
    SolverInfo,
    SpringSeriesOut,
    SpringStateOut,
    bounds_of,
    integral,
    outcome_model,
    rectangular,
)
from .design import MAX_DESIGN_SEGMENTS, ActiveBoundOut, DesignManipulatorIn
from .paths import StartQ

#: Most steps of a trajectory (the schema's cap; the server's setting may be lower).
MAX_STEPS = HARD_MAX_TRAJECTORY_STEPS
#: Largest angle standard deviation (rad) and |covariance entry| (rad^2) of a force estimate.
MAX_SIGMA = MAX_ANGLE
MAX_COVARIANCE = MAX_ANGLE ** 2

Vec2 = Annotated[list[ForceValue], Field(min_length=2, max_length=2)]
Position = Annotated[list[Deflection], Field(min_length=2, max_length=2)]
PositiveLength = Annotated[float, Field(gt=0.0, le=1.0e6, allow_inf_nan=False)]
Weight = Annotated[float, Field(gt=0.0, le=MAX_STIFFNESS, allow_inf_nan=False)]

Seconds = Annotated[float, Field(gt=0.0, le=1.0e9, allow_inf_nan=False)]

_TIME = ("Computed within the server's time limit: when it runs out, the steps done so far are answered (200, "
         "`status: \"time_limit\"`, `success: false`).")


def _one_or_steps(v: Any) -> str:
    return "<steps>" if isinstance(v, list) and v and isinstance(v[0], list) else "<one>"


def _number_or_list(v: Any) -> str:
    return "<list>" if isinstance(v, list) else "<number>"


def _per_spring(item: Any, what: str) -> Any:
    return Annotated[
        Union[Annotated[item, Tag("<number>")],
              Annotated[list[item], Field(min_length=2, max_length=2 * MAX_DESIGN_SEGMENTS), Tag("<list>")]],
        Discriminator(_number_or_list),
        Field(description=f"{what}: one number for every spring, or 2n numbers (L1_0 of every segment, then L2_0)"),
    ]


# ---------------------------------------------------------------------------- plan
#: Actuator bounds on every rest length (length units): each side a number or 2n numbers.
RestLengthBoundsIn = bounds_of(_per_spring(PositiveLength, "a side of the bounds"), "RestLengthBoundsIn",
                               "actuator bounds on every rest length (length units; each side a number or 2n "
                               "numbers, lo < hi)",
                               object_doc="Actuator bounds {lo, hi} on every rest length (the object form of "
                                          "[lo, hi]).")


PlanLoads = Annotated[
    Union[Annotated[Vec2, Tag("<one>")],
          Annotated[list[Vec2], Field(min_length=1, max_length=MAX_STEPS), Tag("<steps>")]],
    Discriminator(_one_or_steps),
    Field(description="the dead tip load (force units): one [fx, fy] for every step, or one per step (as many as "
                      "targets)"),
]


def _int_or_name(v: Any) -> str:
    return "<name>" if isinstance(v, str) else "<int>"


#: A horizon: a number of steps or ``"all"`` (:data:`tensegrity_opt.analyses.design.horizon.HORIZONS`).
Horizon = Annotated[
    Union[Annotated[int, Field(ge=1, le=MAX_STEPS), Tag("<int>")], Annotated[Literal[HORIZONS], Tag("<name>")]],
    Discriminator(_int_or_name),
]


class _PlanFields(BaseModel):
    model_config = ConfigDict(strict=True, extra="forbid")

    manipulator: DesignManipulatorIn
    targets: list[Position] = Field(min_length=1, max_length=MAX_STEPS,
                                    description=f"tip positions [x, y] per step (length units; 1..{MAX_STEPS}, server "
                                                "limit TENSEGRITY_MAX_TRAJECTORY_STEPS)")
    loads: PlanLoads | None = Field(None, description="dead tip load: one [fx, fy] or one per step; default none")
    end_angles: list[Angle | None] | None = Field(
        None, max_length=MAX_STEPS, description="the last link's absolute angle per step (rad; null: free), as many "
                                                "as targets; default free")
    bounds: RestLengthBoundsIn | None = Field(None, description="actuator bounds on the rest lengths; default "
                                                                "(0.1 b_min, 4 b_max)")
    rate_limit: _per_spring(PositiveLength, "largest speed of a rest length (length units per second, > 0)") | None = \
        Field(None, description="largest speed of each rest length (length units per second): a number or 2n "
                                "numbers; step k changes each rest length by at most rate_limit * (t_k - t_{k-1}). "
                                "Needs `times` or `dt`; default none")
    times: list[Seconds] | None = Field(
        None, min_length=1, max_length=MAX_STEPS,
        description="the steps' instants (seconds), as many as targets, strictly increasing from a first one > 0: "
                    "the start (`rest_lengths0`, `start`) is the state at time 0; default none (or `dt`)")
    dt: Seconds | None = Field(None, description="a fixed time between steps (seconds, > 0) instead of `times`: "
                                                 "t_k = (k + 1) dt")
    rest_lengths0: list[Annotated[list[PositiveLength], Field(min_length=2, max_length=2)]] | None = Field(
        None, min_length=1, max_length=MAX_DESIGN_SEGMENTS,
        description="the arm's current rest lengths [L1_0, L2_0] per segment (n pairs, length units, inside `bounds`): "
                    "the start is an equilibrium with them and the first step's change is measured from them; "
                    "default the manipulator's own")
    margin: Annotated[float, Field(ge=0.0, le=MAX_STIFFNESS, allow_inf_nan=False)] = Field(
        1e-3, description=MARGIN_DOC)
    objective: Literal[OBJECTIVES] = Field(
        "change", description="change: least change from the previous step (compiled Newton, IPOPT where a bound "
                              "is active); margin: largest margin; energy: least spring energy (IPOPT)")
    weights: list[Annotated[list[Weight], Field(min_length=2, max_length=2)]] | None = Field(
        None, min_length=1, max_length=MAX_DESIGN_SEGMENTS,
        description="weights [w1, w2] of each segment's rest-length changes in the least-change objective "
                    "(n pairs, > 0); default 1")
    start: StartQ | None = Field(None, description='{"q": [...]}: the configuration with the start\'s rest lengths '
                                                   "(`rest_lengths0`) under the first load; null: the equilibrium "
                                                   "under it reached from the least-energy rest configuration")
    on_infeasible: Literal[ON_INFEASIBLE] = Field(
        "hold", description="what an infeasible step commands: hold (the previous command; the arm stays, under the "
                            "step's load) or approach (the rest lengths of the admissible pose nearest to the "
                            "target, within the bounds, the rate limit and the margin: the arm moves toward the "
                            "target and catches up when it is in reach)")
    horizon: Horizon | None = Field(
        None, description="null: step by step; N: a receding horizon, each step planned with the N steps from it as "
                          "one IPOPT problem (equilibrium, range, bounds, margin of every step and the rate box "
                          "between steps as constraints; tip error and actuator motion as objective), the first "
                          "applied; all: the whole trajectory as one problem. Needs `objective: change`; its steps' "
                          "method is horizon (none: held)")
    verify: bool = Field(True, description="verify every step along its transition (`verified`): the previous "
                                           "command and load moving linearly to the step's over its interval, a "
                                           "command is sent only where the arm follows its branch to the step's "
                                           "pose, stable with the margin all along (no fold, branch point or joint "
                                           "stop on the way); false: the end pose only, nothing verified")
    on_snap: Literal[ON_SNAP] = Field(
        "continue", description="when the arm snaps during a step (nothing admissible avoids it) or has no "
                                "equilibrium (a joint reaches its stop): continue (the next steps start from where "
                                "it went) or stop (the plan ends after that step)")
    taut: bool = Field(False, description=TAUT_DOC)


PLAN_REQUEST_EXAMPLE = {"manipulator": PAPER_CHAIN, "targets": [[7.6, 0.5], [7.5, 0.75], [7.4, 1.0], [7.3, 1.25]],
                        "loads": [0.0, -0.02], "margin": 0.01}


class PlanRequest(_PlanFields):
    """Rest lengths for a trajectory of tip positions, on one stable branch (`plan_preloads`)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={"examples": [PLAN_REQUEST_EXAMPLE]})


class SimulationEventOut(outcome_model(SimulationEvent)):
    """Something that happened during a move of the inputs (a simulation's step from sample `step` to `step + 1`,
    a plan's step `step` from the previous command to its own), at `time = step + fraction`: where the arm went
    (`status`) and what it did there."""

    kind: Literal[SIMULATION_EVENT_KINDS] = Field(
        description="snap (the followed branch folded: the arm jumps), bifurcation (lost stability at a branch "
                    "point), joint_limit (a joint reached its range bound: the end)")
    step: int
    fraction: float = Field(description="where in the step (0 at sample step, 1 at step + 1)")
    time: float = Field(description="step + fraction")
    preloads: list[list[float]] = Field(description="the rest lengths [L1_0, L2_0] per segment there")
    load: list[float] | None = Field(description="the dead tip load there (tip free)")
    target: list[float] | None = Field(description="the tip deflection there (tip held)")
    q_before: list[float] = Field(description="the configuration at the fold (branch point, joint limit)")
    q_after: list[float] | None = Field(description="the landing configuration (null: a joint limit, or the descent "
                                                    "ran into a joint's bound)")
    force_before: list[float] | None
    force_after: list[float] | None
    tip_before: list[float] | None
    tip_after: list[float] | None
    energy_before: float | None
    energy_after: float | None
    potential_before: float | None = Field(description="E - F . tip (free) or E (held) at the fold")
    potential_after: float | None
    energy_released: float | None = Field(description="potential_before - potential_after (> 0 for a snap)")
    null_vector: list[float] | None = Field(description="the snapping mode (largest entry +1)")
    direction: int = Field(description="the sign of null_vector the descent left along (0: joint limit)")
    method: str = Field(description="moore_spence, test_function or limit")


class PlanStepOut(SpringStateOut, outcome_model(to.results.PreloadStep)):
    """One step of a plan (`PreloadStep.to_dict()`)."""

    command: list[list[float]] = Field(description="[L1_0, L2_0] per segment: what to send (an infeasible step: the "
                                                   "held value, or with approach the nearest admissible pose's)")
    proposal: list[list[float]] = Field(description="the controller's proposal (the command, except on a held step: "
                                                    "the nearest admissible pose's rest lengths)")
    q: list[float] = Field(description="the arm's configuration under the command (rad)")
    tip: list[float] = Field(description="the arm's tip under the command")
    end_angle: float
    margin: float | None = Field(description="the arm's stability margin under the command (torque / rad; null: "
                                             "the held rest lengths have no equilibrium under the step's load)")
    energy: float | None = Field(description="the spring energy there (null likewise)")
    tip_error: float = Field(description="|tip - target| (length units)")
    proposal_tip: list[float] = Field(description="the tip the proposal reaches")
    feasible: bool
    method: Literal[METHODS] = Field(description="how the command was found: newton, ipopt, nearest (the nearest "
                                                 "admissible pose), horizon (a step of a horizon plan), none (held)")
    solver: SolverInfo = Field(description="the solver's status (Newton_Converged, IPOPT's; for an infeasible step "
                                           "the failed solve's, or none) and iterations")
    residual: float | None = Field(description="max-norm of the equilibrium and pose equations (Newton steps)")
    target: list[float]
    verified: bool = Field(description="the step's transition was followed: no fold, branch point or joint stop, the "
                                       "margin held all along, and the arm ends on the step's pose (false with "
                                       "`verify: false`, and for a step that starts against a joint's stop)")
    transition_margin: float | None = Field(description="the least stability margin along the step's transition "
                                                        "(torque / rad; 0 where the arm snapped; null: none "
                                                        "followed)")
    events: list[SimulationEventOut] = Field(
        description="what happened during the transition: snaps (with the landing q_after, tip_after) and a joint "
                    "reaching its stop; `step` is the step's index, `fraction` where in its move")


class PlanOut(SpringSeriesOut, outcome_model(to.PreloadPlan)):
    """`PreloadPlan.to_dict()`: per step done (`K` rows, fewer when the time limit cut the plan)."""

    seconds: float = Field(description="wall time of the plan (s)")
    commands: list[list[list[float]]] = Field(description="[L1_0, L2_0] per segment per step: what to send "
                                                          "(consecutive commands differ by at most rate_limit "
                                                          "times the time between them)")
    proposals: list[list[list[float]]] = Field(description="the controller's proposal per step (the commands, except "
                                                           "on held steps: the nearest admissible pose's)")
    q: list[list[float]] = Field(description="the arm's configuration under each command (rad)")
    tip: list[list[float]] = Field(description="the arm's tip under each command (the target when feasible)")
    tip_error: list[float] = Field(description="|tip - target| per step (length units)")
    end_angle: list[float] = Field(description="the last link's absolute angle sum(q) per step (rad)")
    margin: list[float | None] = Field(description="the arm's stability margin per step (torque / rad; null: no "
                                                   "equilibrium under the held command)")
    feasible: list[bool] = Field(description="rest lengths meeting every requirement put the tip on the target "
                                             "(false: the command held, or approaching with on_infeasible approach)")
    verified: list[bool] = Field(description="each step's transition was followed (the previous command and load "
                                             "moving linearly to the step's): no fold, branch point or joint stop, "
                                             "the margin held all along, the arm ends on the step's pose (with "
                                             "`verify: false` nothing is followed: false everywhere)")
    transition_margin: list[float | None] = Field(description="the least stability margin along each step's "
                                                              "transition (torque / rad; null: none followed)")
    method: list[Literal[METHODS]] = Field(description="how each step's command was found")
    targets: list[list[float]] = Field(description="the targets of the steps done")
    times: list[float | None] = Field(description="the instants of the steps done (seconds; the start at 0); null "
                                                  "without a time base")
    margin_required: float = Field(description="the stability margin asked for (torque / rad)")
    objective: Literal["change", "margin", "energy"] = Field(description="how the redundancy was resolved")
    on_infeasible: Literal[ON_INFEASIBLE] = Field(description="what the infeasible steps commanded")
    on_snap: Literal[ON_SNAP] = Field(description="what the plan did after a snap or a step without equilibrium")
    horizon: int | Literal[HORIZONS] | None = Field(description="null (step by step), N (receding) or all")
    start: list[float] | None = Field(description="the arm's configuration at time 0 (rad): where the first step's "
                                                  "transition starts")
    steps: list[PlanStepOut] = Field(description="every step in full (why an infeasible step failed: `message`)")


# ---------------------------------------------------------------------------- simulate
class _SimulationFields(BaseModel):
    model_config = ConfigDict(strict=True, extra="forbid")

    manipulator: ManipulatorIn
    preloads: rectangular(Annotated[list[Annotated[list[Length], Field(min_length=2, max_length=2)]],
                                    Field(min_length=1, max_length=HARD_MAX_SEGMENTS)]) | None = Field(
        None, min_length=1, max_length=MAX_STEPS,
        description="the rest lengths [L1_0, L2_0] of every segment at each sample, (K, n, 2) (length units); "
                    "default the chain's own, constant")
    loads: list[Vec2] | None = Field(None, min_length=1, max_length=MAX_STEPS,
                                     description="the dead tip load [fx, fy] at each sample (tip free; force units; "
                                                 "default zero); fx < 0 compresses")
    tip: Literal["free", "held"] = Field("free", description="free: the tip is loaded by `loads`; held: the tip is "
                                                             "held at `targets`")
    targets: list[Position] | None = Field(None, min_length=1, max_length=MAX_STEPS,
                                           description="the tip deflection [dx, dy] at each sample (tip held; length "
                                                       "units; the tip at (2 sum b - dx, dy))")
    start: StartQ | None = Field(None, description='{"q": [...]}: the state at sample 0 (must be a stable '
                                                   "equilibrium under the first inputs); null: free, the least-energy "
                                                   "rest configuration (under a non-zero first load the "
                                                   "least-potential stable equilibrium); held, the least-energy "
                                                   "stable equilibrium at the first target")
    perturbation: Annotated[float, Field(gt=0.0, lt=0.1, allow_inf_nan=False)] = Field(
        1e-4, description="where a snap's descent starts: this far (rad, the largest joint) from the fold along its "
                          "null vector")


def _load_cycle(amplitude: float, steps: int) -> list[list[float]]:
    """Loads [0, fy] from 0 up to +amplitude, down to -amplitude and back to 0 in ``steps`` samples (piecewise
    linear, as ``tensegrity-opt simulate --load-cycle``)."""
    out = []
    for i in range(steps):
        t = 4.0 * i / (steps - 1)
        f = t if t <= 1.0 else 2.0 - t if t <= 3.0 else t - 4.0
        out.append([0.0, round(amplitude * f, 6)])
    return out


#: A load cycle on three bistable segments (a = 0.5): a snap up and a snap down (hysteresis).
BISTABLE_CHAIN = {"n": 3, "a": 0.5, "b": 1.0, "k": 1.0, "L0": 1.0}
SIMULATION_REQUEST_EXAMPLE = {"manipulator": BISTABLE_CHAIN, "loads": _load_cycle(0.3, 13)}


class SimulationRequest(_SimulationFields):
    """Quasi-static simulation under sampled preloads and a tip load or deflection (`tensegrity_opt.simulate`)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [SIMULATION_REQUEST_EXAMPLE]})


class SimulationOut(SpringSeriesOut, outcome_model(Simulation)):
    """`Simulation.to_dict()`: the state at each sample done (`done` of `steps`) and the events; `status` says how
    it ended (time_limit: cut by the server's time limit; the samples done are kept)."""

    mode: Literal["free", "held"]
    steps: int = Field(description="samples asked for (K)")
    done: int = Field(description="samples simulated")
    q: list[list[float]] = Field(description="joint angles (rad) per sample done")
    force: list[Force] = Field(description="the load (free) or the holding force (held) per sample done")
    tip: list[list[float]]
    deflection: list[list[float]] = Field(description="(dx, dy) = (2 sum b - x, y) per sample done")
    energy: list[float] = Field(description="elastic energy (force x length)")
    potential: list[float] = Field(description="E - F . tip (free) or E (held)")
    stable: list[bool]
    morse_index: list[int]
    events: list[SimulationEventOut] = Field(description="snaps, bifurcations and the joint-limit end, in time order")
    preloads: list[list[list[float]]] = Field(description="the rest lengths at every sample (the input)")
    loads: list[list[float]] | None = Field(None, description="the dead tip loads (free)")
    targets: list[list[float]] | None = Field(None, description="the tip deflections (held)")


# ---------------------------------------------------------------------------- force estimate
Sigma = Annotated[float, Field(gt=0.0, le=MAX_SIGMA, allow_inf_nan=False)]
CovarianceEntry = Annotated[float, Field(ge=-MAX_COVARIANCE, le=MAX_COVARIANCE, allow_inf_nan=False)]
JointIndex = Annotated[int, Field(ge=0, le=HARD_MAX_SEGMENTS - 1), BeforeValidator(integral)]


def _sigma_form(v: Any) -> str:
    if not isinstance(v, list):
        return "<number>"
    return "<matrix>" if v and isinstance(v[0], list) else "<vector>"


SigmaIn = Annotated[
    Union[Annotated[Sigma, Tag("<number>")],
          Annotated[list[Sigma], Field(min_length=1, max_length=HARD_MAX_SEGMENTS), Tag("<vector>")],
          Annotated[rectangular(Annotated[list[CovarianceEntry], Field(min_length=1, max_length=HARD_MAX_SEGMENTS)],
                                min_length=1, max_length=HARD_MAX_SEGMENTS), Tag("<matrix>")]],
    Discriminator(_sigma_form),
    Field(description="angle noise: one standard deviation for every joint (rad, > 0), one per joint (n, or k: the "
                      "measured ones), or a covariance matrix (rad^2; n x n or k x k, symmetric positive "
                      "semidefinite with positive variances)"),
]


def _measured_form(v: Any) -> str:
    return "<mask>" if isinstance(v, list) and v and isinstance(v[0], bool) else "<indices>"


MeasuredIn = Annotated[
    Union[Annotated[list[bool], Field(min_length=1, max_length=HARD_MAX_SEGMENTS), Tag("<mask>")],
          Annotated[list[JointIndex], Field(max_length=HARD_MAX_SEGMENTS), Tag("<indices>")]],
    Discriminator(_measured_form),
    Field(description="which joints are measured: a mask of n booleans, or 0-based joint indices; default all"),
]


class ForceEstimateRequest(BaseModel):
    """The tip force from measured joint angles (`tensegrity_opt.estimate_tip_force`)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={"examples": [
        {"manipulator": PAPER_CHAIN, "q_measured": [0.742754, 0.522806, 0.297158, 0.0953], "sigma_q": 0.001}]})

    manipulator: ManipulatorIn
    q_measured: list[Angle | None] = Field(
        min_length=1, max_length=HARD_MAX_SEGMENTS,
        description="joint angles (rad): all n (entries at unmeasured joints only start the solver; null there: 0), "
                    "or the k measured ones in joint order; each inside the physical range |q_i| < pi - 2 beta_i")
    sigma_q: SigmaIn | None = Field(None, description="the angle noise (see the schema); null: the plain least-squares "
                                                      "estimate, no statistics")
    measured: MeasuredIn | None = None


class ForceEstimateOut(SpringStateOut, outcome_model(to.ForceEstimate)):
    """`ForceEstimate.to_dict()`."""

    force: Force = Field(description="the estimated tip force (force units)")
    covariance: list[list[float]] | None = Field(description="2 x 2 covariance of the force (null without sigma_q)")
    residual_torque: list[float] = Field(description="grad E - J^T F at the estimate: the joint torques no tip "
                                                     "force explains (torque units)")
    residual_norm: float
    chi2: float | None = Field(description="r^T W r (null without sigma_q)")
    dof: int = Field(description="degrees of freedom: n - 2 - unmeasured joints")
    p_value: float | None = Field(description="P(chi2_dof >= chi2): small when the angles are not those of an "
                                              "equilibrium under a tip force only (null without sigma_q or dof 0)")
    joint_chi2: list[float] | None = Field(description="per joint: the decrease of chi2 an extra torque there "
                                                       "would give (where the load not at the tip is)")
    q: list[float] = Field(description="the configuration used: measured angles as given, unmeasured estimated")
    measured: list[int] = Field(description="the measured joints (0-based)")
    hidden_covariance: list[list[float]] | None = Field(description="covariance of the estimated unmeasured angles "
                                                                    "(rad^2)")
    iterations: int = Field(description="Gauss-Newton and re-weighting iterations made")


__all__ = ["PlanRequest", "PlanOut", "RestLengthBoundsIn", "SimulationRequest", "SimulationOut",
           "SimulationEventOut", "ForceEstimateRequest", "ForceEstimateOut", "PLAN_REQUEST_EXAMPLE",
           "SIMULATION_REQUEST_EXAMPLE", "BISTABLE_CHAIN", "MAX_STEPS"]


# ---------------------------------------------------------------------------- stiffness shaping, load capacity
Stiffness = Annotated[float, Field(ge=-MAX_STIFFNESS, le=MAX_STIFFNESS, allow_inf_nan=False)]
StiffnessBound = bounds_of(Stiffness | None, "StiffnessBoundIn", "bounds on a stiffness (force / length; null for "
                                                                  "an open side)")


class StiffnessBoundsIn(BaseModel):
    """Bounds on the entries of the tip's Cartesian stiffness (force / length)."""

    model_config = _STRICT
    kxx: StiffnessBound | None = None
    kxy: StiffnessBound | None = None
    kyy: StiffnessBound | None = None


class StiffnessDesignRequest(BaseModel):
    """Rest lengths for a stable pose at `target` with a shaped tip stiffness (`preloads_for_stiffness`)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={"examples": [
        {"manipulator": PAPER_CHAIN, "target": [7.0, 1.0], "eig_bounds": [0.04, 0.6]}]})

    manipulator: DesignManipulatorIn
    target: Position = Field(description="tip position [x, y] (length units)")
    K_desired: Annotated[list[Annotated[list[Stiffness], Field(min_length=2, max_length=2)]],
                         Field(min_length=2, max_length=2)] | None = Field(
        None, description="the wanted 2 x 2 stiffness (symmetric; met exactly where reachable, else the closest in "
                          "the Frobenius norm: `exact`, `residual`)")
    bounds_K: StiffnessBoundsIn | None = Field(None, description="bounds on kxx, kxy, kyy")
    eig_bounds: StiffnessBound | None = Field(None, description="bounds [lo, hi] on both eigenvalues of K")
    load: Vec2 = Field([0.0, 0.0], description="the dead tip load [fx, fy] (force units)")
    end_angle: Angle | None = Field(None, description="the last link's absolute angle (rad), optional")
    margin: Annotated[float, Field(ge=0, le=MAX_STIFFNESS, allow_inf_nan=False)] = Field(1e-3, description=MARGIN_DOC)
    bounds: RestLengthBoundsIn | None = Field(None, description="bounds on the rest lengths; default "
                                                                "(0.1 b_min, 4 b_max)")
    max_starts: Annotated[int, Field(ge=1, le=16), BeforeValidator(integral)] = Field(
        4, description="arm shapes tried (the target's equilibria, stable first)")


class StiffnessDesignOut(SpringStateOut, outcome_model(to.StiffnessDesign)):
    """`StiffnessDesign.to_dict()`: verified by the forward solve and `cartesian_stiffness`."""

    manipulator: dict[str, Any]
    rest_lengths: list[list[float]] = Field(description="[L1_0, L2_0] per segment")
    q: list[float]
    tip: list[float]
    K: list[list[float]] = Field(description="the verified Cartesian stiffness (force / length)")
    eigenvalues: list[float]
    margin: float
    residual: float = Field(description="|K - K_desired|_F / |K_desired|_F, or the largest bound violation (0)")
    exact: bool
    load: list[float]
    K_desired: list[list[float]] | None
    bounds_K: dict[str, list[float | None]]
    eig_bounds: list[float | None] | None
    active_bounds: list[ActiveBoundOut] = Field(description="the rest lengths at (or near) their bounds: the design "
                                                            "is the best within them")
    solver: SolverInfo


class LoadCapacityRequest(BaseModel):
    """The largest extra tip load per direction before a stable pose loses stability (`load_capacity`)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={"examples": [
        {"manipulator": PAPER_CHAIN, "directions": 8, "max_load": 2.0}]})

    manipulator: ManipulatorIn
    start: StartQ | None = Field(None, description='{"q": [...]}: the pose (a stable equilibrium under `base`); null: '
                                                   "the least-energy rest configuration")
    base: Vec2 = Field([0.0, 0.0], description="the load the pose carries [fx, fy] (force units)")
    directions: Annotated[int, Field(ge=1, le=360), BeforeValidator(integral)] = Field(
        36, description="how many evenly spaced directions")
    boundary: Literal["free", "guided"] = "free"
    max_load: Annotated[float, Field(gt=0, le=1e4, allow_inf_nan=False)] = Field(
        10.0, description="each path is followed up to this extra load (force units)")


class LoadCapacityOut(outcome_model(to.LoadCapacity)):
    """`LoadCapacity.to_dict()`: a polar curve of the pose's load capacity."""

    angles: list[float] = Field(description="direction angles (rad)")
    directions: list[list[float]]
    loads: list[float | None] = Field(description="the extra load at the first loss of stability (null: none)")
    forces: list[list[float | None]] = Field(description="the total tip force there")
    kinds: list[str] = Field(description="fold, bifurcation or none")
    reasons: list[str | None]
    end_loads: list[float]
    base: list[float]
    boundary: str
    max_load: float
    weakest: dict[str, float] | None
    start: dict[str, Any]
    manipulator: dict[str, Any]


class WeightCapacityRequest(BaseModel):
    """By how much the chain's weights may grow before its rest pose loses stability (`weight_capacity`)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={"examples": [
        {"manipulator": {"n": 6, "a": 0.04, "b": 0.05, "k": 5000.0, "L0": 0.05, "mass": 0.05, "payload": 0.1,
                         "gravity": [-9.81, 0.0]}, "max_factor": 10.0}]})

    manipulator: ManipulatorIn
    start: StartQ | None = Field(None, description='{"q": [...]}: the pose (a stable equilibrium under the loads); '
                                                   "null: the least-potential rest configuration")
    max_factor: Annotated[float, Field(gt=1, le=1e6, allow_inf_nan=False)] = Field(
        10.0, description="follow the weights up to this multiple of gravity")


class WeightCapacityOut(outcome_model(to.WeightCapacity)):
    """`WeightCapacity.to_dict()`: the gravity multiple at which the rest pose first loses stability."""

    factor: float | None = Field(description="the multiple of gravity at the limit (null: none)")
    kind: Literal["fold", "bifurcation", "none"]
    reason: Literal["joint_limit", "max_factor"] | None
    end_factor: float = Field(description="the last multiple on the stable path")
    q: list[float] = Field(description="the configuration there (rad)")
    max_factor: float
    start: dict[str, Any]
