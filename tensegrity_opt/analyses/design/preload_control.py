"""Control in actuation space: the springs' rest lengths for tip poses over time (inverse statics).

The control inputs of the arm are the rest lengths ``(L1_0, L2_0)`` of its ``2 n`` springs; a tip pose is
2 numbers (``x, y``) or 3 (with the last link's absolute angle): the inputs are redundant. A step asks
for rest lengths putting the tip at the target, stable, under a dead tip load, close to the previous
step's (no snap between steps: the configuration moves continuously on one branch), inside the actuator
bounds and a rate limit, with a stability margin (the smallest eigenvalue of the Hessian of ``E - F . tip`` in
the joint angles, torque per radian).

**Time and the start.** The start is the state at time ``0``: the arm's current rest lengths
(``rest_lengths0``, default the Manipulator's own) and the equilibrium with them under the load. A rate limit is
a length per second: step ``k`` at time ``t_k`` may change each rest length by at most
``rate_limit * (t_k - t_{k-1})`` from the previous step's (``t_{-1} = 0``: the first step's change is measured
from ``rest_lengths0``). The times are given as ``times`` (``0 < t_0 < t_1 < ...``, seconds) or a fixed step
``dt`` (``t_k = (k + 1) dt``); a rate limit without either is refused (the field ``dt``).

**The margin** is absolute, in the chain's torque per radian (force x length / rad), as every stability margin
the library accepts (:func:`~tensegrity_opt.analyses.design.preloads.preloads_for_pose`,
:func:`~tensegrity_opt.analyses.design.stiffness_shaping.preloads_for_stiffness`): a requirement on a physical
stiffness (a torque disturbance ``dtau`` at the joints moves them by at most ``|dtau| / margin`` rad) that the
results report in the same unit. The library's tolerances, judgements of "numerically zero", are relative to the
chain's torque scale ``max k c^2`` (``Manipulator.torque_scale``) instead; to ask for a relative margin pass
``r * m.torque_scale``.

:class:`PreloadController` answers one step at a time, warm-started from the last:

1. **Newton** on the KKT system of the least-change problem (``objective="change"``; the compiled step
   of :mod:`tensegrity_opt.numerics.inverse_statics`): ``min 1/2 sum w_j (l_j - l_prev_j)^2 +
   1/2 eps |q - q_prev|^2`` subject to the equilibrium under the load and the tip pose. Accepted when it
   converges to a strict local minimum (the inertia of the KKT matrix) and its solution satisfies
   everything: the bounds, the rate box, the range, the margin.
2. **IPOPT** otherwise, or for ``objective="margin"`` (largest margin) and ``"energy"`` (least spring
   energy): :func:`~tensegrity_opt.analyses.design.preloads.preloads_for_pose` with the previous rest lengths as
   the nominal ones, the bounds intersected with the rate box, warm-started from the previous
   configuration.
3. Where neither finds admissible rest lengths the step is **infeasible**. Its **proposal** is the admissible
   pose nearest to the target (:meth:`PreloadController.nearest`: the preload NLP minimising the tip's distance
   to the target subject to the equilibrium under the load, the margin, the bounds intersected with the rate
   box and the joint range, from several starts, each candidate kept only where the forward solve from the
   current configuration lands on it, stable; verified, along its transition). What the step **commands** depends
   on ``on_infeasible``:

   * ``"hold"``: the previous command. The arm's state is where holding takes it (the same state when the load does
     not change; else the transition of the held command under the changing load). A target more than one rate box
     away is never reached by holding, even a still one;
   * ``"approach"``: the nearest admissible pose's rest lengths: the arm moves there, as close to the target
     as the bounds, the rate limit and the margin allow, and the controller catches up once the target is
     in reach again.

Every step carries the ``command`` to send and, apart, the ``proposal``; ``q``, ``tip``, ``margin``, ``energy``
describe the arm under the command (what a pipeline will observe), ``tip_error`` its distance to the target.
Consecutive commands never differ by more than ``rate_limit * dt`` (the time between them). ``residual`` is the
scaled KKT residual of a Newton step.

**Verified along the transition** (``verify=True``, the default). A controller ramps each rest length linearly in
time from one command to the next over the step's interval, and the load ramps with it: the step's *transition*
(:mod:`tensegrity_opt.analyses.paths.transition`). Every candidate command (Newton's, IPOPT's, the nearest
pose's) is followed along it from the current state: it is sent only where the arm stays on its branch (no fold,
no branch point, no joint stop), its margin never below the required one (nor below the current state's, when
that is already lower) and at least the required one at the end, ending on the candidate's pose
(``verified=True``, ``transition_margin`` the least margin on the way). A candidate that fails is refused and the
nearest-pose search looks for another; where nothing admissible avoids it (a held command under a changing load),
the step says what happens: ``status="snap"`` (``q``, ``tip`` where the arm landed; ``events`` the snaps) or
``"no_equilibrium"`` (a joint reached its stop: ``q`` there); the state moves there, and a step from a stop
releases the arm by descent (never verified). :func:`plan_preloads` runs a controller over a trajectory.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from ...bounds import bound_pair
from ...checks import is_real, real_array
from ...errors import (
    InfeasibleDesignError,
    InvalidParameterError,
    NoEquilibriumError,
    TensegrityError,
    TimeLimitError,
    UnsupportedError,
)
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...model.springs import SpringFields, Springs
from ...numerics import chain_solver
from ...numerics.inverse_statics import inverse_statics
from ...numerics.inverse_statics import layouts as step_layouts
from ...numerics.layout import rest_lengths
from ...outcome import Outcome, SolverInfo, freeze
from ...serialize import nullable, number, numbers
from ...timelimit import expired, time_limit
from ..equilibria.equilibrium import Equilibrium, check_q0, settle_under_force, solve_equilibrium_under_force
from ..paths.control import checked_vector
from ..paths.descent import ArmState
from ..paths.problem import refuse_start_on_stop
from ..paths.transition import Transition, follow, law_margin, released
from .follower import loaded_rest
from .preloads import LAND_TOL, OBJECTIVES, TAUT_FLOOR, preloads_for_pose, solve_pose_nlp, stability_margin

__all__ = ["PreloadController", "PreloadStep", "PreloadPlan", "plan_preloads", "step_times", "ON_INFEASIBLE", "ON_SNAP",
           "METHODS"]

#: What an infeasible step commands: ``"hold"`` the previous command, ``"approach"`` the nearest admissible pose's
#: rest lengths.
ON_INFEASIBLE = ("hold", "approach")
#: What a plan does after a step where the arm snapped or had no equilibrium: ``"continue"`` from where it went,
#: or ``"stop"`` there.
ON_SNAP = ("continue", "stop")
#: How a step's command was found: the least-change ``"newton"`` step, ``"ipopt"`` (the fallback or the
#: objective), ``"nearest"`` (the nearest admissible pose: an approach step, or the target reached by it where
#: the other two failed), ``"horizon"`` (a step of a horizon plan, :mod:`.horizon`), ``"none"`` (held: no new
#: command).
METHODS = ("newton", "ipopt", "nearest", "horizon", "none")
#: A target farther than this many times the chain's straight length from its base is refused (out of reach is
#: approached; this far is a mistake, and its distances overflow the objectives).
FAR_TARGET = 1e4
#: Joint angles (rad) within which a transition must end on the planned configuration.
SAME_POSE = 1e-6
#: Spread starts of the nearest-pose search (besides the current state, IPOPT's last point and the held state).
NEAREST_SPREAD = 2

#: KKT residual (max-norm, force and length units) below which the Newton step has converged.
NEWTON_TOL = 1e-10
#: Weight of ``|q - q_prev|^2`` in the least-change objective (regularises the joint angles' null space).
Q_WEIGHT = 1e-8
#: The solver detail of a Newton step, per iteration count (immutable, so shared).
_NEWTON: dict[int, SolverInfo] = {}


def _seconds(v, field: str) -> float:
    """A duration in seconds: a finite number > 0 (a string or a bool is refused)."""
    h = float(v) if is_real(v) else math.nan
    if not (math.isfinite(h) and h > 0):
        raise InvalidParameterError(f"{field} must be a finite number of seconds > 0, got {v!r}", field=field)
    return h


def step_times(K: int, times=None, dt: float | None = None, rate_limit=None) -> np.ndarray:
    """The instants ``t_0 .. t_{K-1}`` (s) of ``K`` steps after the start at ``t = 0``: ``times`` (strictly
    increasing, ``t_0 > 0``) or ``(k + 1) dt``; NaN without either (then no ``rate_limit`` may be given: a rate is
    per second)."""
    if times is not None and dt is not None:
        raise InvalidParameterError("give the steps' times or a fixed step dt, not both", field="times")
    if times is not None:
        t = real_array(times, "times")
        if t.shape != (K,) or not np.all(np.isfinite(t)):
            raise InvalidParameterError(f"times must be {K} finite instants (seconds), one per target",
                                        field="times")
        if t[0] <= 0 or np.any(np.diff(t) <= 0):
            raise InvalidParameterError("times must increase strictly from a first instant > 0 (the start is the "
                                        "state at time 0)", field="times")
        return t.copy()
    if dt is not None:
        return _seconds(dt, "dt") * np.arange(1, K + 1)
    if rate_limit is not None:
        raise InvalidParameterError("rate_limit is a length per second: give the steps' times or a fixed step dt "
                                    "(seconds)", field="dt")
    return np.full(K, math.nan)


@dataclass(frozen=True)
class PreloadStep(Outcome, SpringFields):
    """One control step (:meth:`PreloadController.step`).

    Attributes
    ----------
    command : ndarray (n, 2)
        ``L1_0, L2_0`` per segment: what to send to the actuators (on an infeasible step the held value with
        ``on_infeasible="hold"``, the nearest admissible pose's with ``"approach"``).
    proposal : ndarray (n, 2)
        The controller's proposal: the command, except on an infeasible step held, where it is the nearest
        admissible pose's rest lengths (the held value when there is none).
    q : ndarray (n,)
        The arm's equilibrium configuration under the command (relative joint angles, rad).
    tip : ndarray (2,)
        The arm's tip under the command.
    end_angle : float
        The last link's absolute angle ``sum(q)``.
    margin : float
        Smallest eigenvalue of the Hessian of ``E - F . tip`` in ``q`` at the arm's state (torque / rad); NaN
        (``null`` in :meth:`to_dict`) when the held rest lengths have no equilibrium under the step's load.
    energy : float
        The spring energy there (NaN likewise).
    tip_error : float
        ``|tip - target|`` (length units).
    proposal_tip : ndarray (2,)
        The tip the proposal reaches.
    feasible : bool
        Rest lengths satisfying every requirement put the tip on the target.
    method : str
        How the command was found (:data:`METHODS`): ``"newton"``, ``"ipopt"``, ``"nearest"``, ``"none"`` (held).
    solver : SolverInfo
        The solver's status (``"Newton_Converged"``, IPOPT's return status; for an infeasible step the status
        of the failed solve, ``"none"`` when there is none) and its iterations.
    residual : float or None
        Max-norm of the equilibrium and pose equations at the result (Newton steps).
    target : ndarray (2,)
    message : str
        How the step was solved, or why it is infeasible.
    verified : bool
        The step's transition was followed (:mod:`~tensegrity_opt.analyses.paths.transition`: the previous command
        and load moving linearly to this step's): no fold, no branch point, no joint limit, the margin held all
        along it, and the arm ends on the reported pose (False with ``verify=False``: not checked; False for a
        step that starts against a joint's stop, whose release is not a followed path).
    transition_margin : float
        The least stability margin along the step's transition (torque / rad; 0 where the arm snapped; NaN when no
        transition was followed).
    spring_lengths, spring_stretches, spring_forces, spring_states : ndarray (n, 2)
        The springs at ``q`` under the command (:class:`~tensegrity_opt.model.springs.SpringFields`).
    events : tuple of SimulationEvent
        What happened during the transition: the snaps (``kind`` ``"snap"`` or ``"bifurcation"``, with the landing
        ``q_after`` and ``tip_after``) and a joint reaching its stop (``"joint_limit"``); ``step`` is the step's index
        since the controller's start, ``fraction`` where in the move.
    status : str
        :attr:`STATUSES`: ``"feasible"``, ``"infeasible"``, ``"snap"`` (the arm snapped during the transition:
        ``q``, ``tip`` are where it landed) or ``"no_equilibrium"`` (a joint reached its stop: ``q`` is the
        configuration there, ``margin`` and ``energy`` NaN).
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "feasible": "rest lengths meeting every requirement were found: the tip on the target, stable with the "
                    "margin, inside the bounds and the rate limit (and, verified, all along the transition)",
        "infeasible": "no admissible rest lengths put the tip on the target: the command is the held value "
                      "(on_infeasible hold) or the nearest admissible pose's rest lengths (approach); q, tip, "
                      "margin and energy describe the arm under the command, proposal and proposal_tip the "
                      "nearest admissible pose",
        "snap": "the arm snapped during the step's transition (nothing admissible avoided it, e.g. a held command "
                "under a changing load): q and tip are where it landed (events give where it snapped)",
        "no_equilibrium": "the arm has no equilibrium inside the physical range under the step's inputs: a joint "
                          "reached its stop during the transition; q is the configuration there (margin and "
                          "energy null) and the next step starts from it",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"feasible"})

    command: np.ndarray
    proposal: np.ndarray
    q: np.ndarray
    tip: np.ndarray
    end_angle: float
    margin: float
    energy: float
    tip_error: float
    proposal_tip: np.ndarray
    feasible: bool
    method: str
    solver: SolverInfo
    residual: float | None
    target: np.ndarray
    message: str
    verified: bool = False
    transition_margin: float = math.nan
    events: tuple = ()
    springs: Springs | None = field(default=None, repr=False, compare=False)

    def _spring_rest_lengths(self) -> np.ndarray:
        return self.command

    def __post_init__(self) -> None:
        # the controller passes arrays it owns: read-only in place (this is on the control loop's path)
        for a in (self.command, self.proposal, self.q, self.tip, self.proposal_tip, self.target):
            a.setflags(write=False)

    @classmethod
    def _of(cls, **fields: Any) -> PreloadStep:
        """The controller's constructor, every field by keyword: the frozen dataclass's ``__init__`` sets each
        field through ``object.__setattr__``, which costs a twentieth of a warm step."""
        step = object.__new__(cls)
        step.__dict__.update(fields)
        step.__post_init__()
        return step

    def _but(self, **fields: Any) -> PreloadStep:
        """This step with ``fields`` replaced (the controller's; arrays passed are owned by the new step)."""
        return PreloadStep._of(**{**self.__dict__, **fields})

    @property
    def status(self) -> str:
        if any(e.status == "joint_limit" for e in self.events):     # on the branch or in a snap's descent
            return "no_equilibrium"
        if any(e.kind in ("snap", "bifurcation") for e in self.events):
            return "snap"
        return "feasible" if self.feasible else "infeasible"

    @property
    def snap(self):
        """The first snap of the step's transition (a :class:`~.transition.SimulationEvent`), or None."""
        return next((e for e in self.events if e.kind in ("snap", "bifurcation")), None)

    def to_dict(self) -> dict[str, Any]:
        """JSON form: ``success``, ``status``, ``message``, ``command``, ``proposal``, ``q``, ``tip``, ``end_angle``,
        ``margin`` and ``energy`` (null: no equilibrium), ``tip_error``, ``proposal_tip``, ``feasible``, ``method``,
        ``solver`` ``{status, iterations}``, ``residual`` (null: not a Newton step), ``target``, ``verified``,
        ``transition_margin`` (null: none followed), ``events``, the spring state under the command
        (``spring_lengths``, ``spring_stretches``, ``spring_forces``, ``spring_states``)."""
        return {**self.outcome(), **self.spring_dict(), "command": [numbers(r) for r in self.command],
                "proposal": [numbers(r) for r in self.proposal], "q": numbers(self.q), "tip": numbers(self.tip),
                "end_angle": number(self.end_angle), "margin": nullable(self.margin),
                "energy": nullable(self.energy), "tip_error": number(self.tip_error),
                "proposal_tip": numbers(self.proposal_tip), "feasible": self.feasible, "method": self.method,
                "solver": self.solver.to_dict(), "residual": None if self.residual is None else nullable(self.residual),
                "target": numbers(self.target), "verified": bool(self.verified),
                "transition_margin": nullable(self.transition_margin), "events": [e.to_dict() for e in self.events]}


@dataclass(frozen=True)
class _Pose:
    """A candidate state of the arm: rest lengths (segment-major 2n), its configuration, tip, margin, energy; and
    the transition that gets it there (``tr``, None when not followed: ``verify=False``)."""

    ell: np.ndarray
    q: np.ndarray
    tip: np.ndarray
    margin: float
    energy: float
    solver: SolverInfo
    tr: Transition | None = None

    @property
    def verified(self) -> bool:
        return self.tr is not None and self.tr.status == "followed"


class PreloadController:
    """Rest lengths step by step, warm-started from the last step (module docstring).

    Parameters
    ----------
    m : Manipulator
        Geometry and stiffness (kept); its rest lengths are the start's unless ``rest_lengths0`` is given.
        ``2 <= n <= KERNEL_MAX`` for the compiled Newton step (longer chains: CasADi's virtual machine, slower).
    start : Equilibrium or array_like (n,), optional
        The configuration with the start's rest lengths (``rest_lengths0``) under ``load``; default the
        equilibrium under ``load`` reached from the least-energy rest configuration of the chain with those rest
        lengths.
    load : (fx, fy)
        The dead tip load (each step may give its own).
    rest_lengths0 : array_like (n, 2), optional
        The arm's current rest lengths ``L1_0, L2_0`` per segment (length units): the first step's change is
        measured from them and the start is an equilibrium with them. Default ``m``'s own. Finite, inside
        ``bounds``.
    bounds : (lo, hi), optional
        Actuator bounds on every rest length (numbers, or ``2 n`` values ``L1_0`` of every segment then
        ``L2_0``); default ``(0.1 b_min, 4 b_max)``.
    rate_limit : float or array_like, optional
        Largest speed of each rest length (length units per second; a number or ``2 n`` values): a step ``dt``
        seconds after the last changes each by at most ``rate_limit * dt``. Needs a time base: ``dt`` here or
        per :meth:`step`.
    dt : float, optional
        The time between steps (s, > 0), used by every :meth:`step` that gives none.
    margin : float
        Required stability margin (>= 0): the smallest eigenvalue of the Hessian of ``E - F . tip`` in the joint
        angles, absolute, torque per radian (module docstring).
    objective : {"change", "margin", "energy"}
    weights : array_like (n, 2), optional
        Weights of each rest length's change in the least-change objective (default 1).
    on_infeasible : {"hold", "approach"}
        What an infeasible step commands (:data:`ON_INFEASIBLE`): the previous command, or the rest lengths of
        the admissible pose nearest to the target (the arm moves toward the target as far as the bounds, the
        rate limit and the margin allow).
    verify : bool
        Follow every step's transition (default): a command is adopted only where the arm gets to its pose along
        the move from the previous command, stable with the margin all along (module docstring); False: the end
        pose only, nothing verified (faster).
    taut : bool
        Keep every spring in tension (``L >= L0``) at every planned pose: a Newton step that lets one go slack or
        push is refused and IPOPT's (:func:`~.preloads.preloads_for_pose` with ``taut``) and the nearest-pose search
        keep them taut. Required for a chain with tension-only springs (there the laws agree at the poses; the
        transitions between them, and the arm's state where it snaps or is held, follow the tension-only law).
    """

    def __init__(self, m: Manipulator, start=None, *, rest_lengths0=None, load=(0.0, 0.0), bounds=None,
                 rate_limit=None, dt: float | None = None, margin: float = 1e-3, objective: str = "change",
                 weights=None, on_infeasible: str = "hold", verify: bool = True, taut: bool = False) -> None:
        unloaded_only(m, "PreloadController")
        if not isinstance(m, Manipulator):
            raise InvalidParameterError("m must be a Manipulator", field="m")
        if not isinstance(taut, bool):
            raise InvalidParameterError(f"taut must be true or false, got {taut!r}", field="taut")
        if not m.linear_springs and not taut:
            raise UnsupportedError("preload control of a chain with tension-only springs keeps every spring taut at "
                                   "its poses (there the laws agree; the moves between them are verified under the "
                                   "laws): set taut=True", field="taut", spring="tension_only")
        n = m.n
        if n < 2:
            raise InvalidParameterError("preload control needs a chain of n >= 2 segments", field="n")
        if objective not in OBJECTIVES:
            raise InvalidParameterError(f"objective must be one of {OBJECTIVES}, got {objective!r}",
                                        field="objective")
        if not (isinstance(margin, (int, float)) and math.isfinite(margin) and margin >= 0):
            raise InvalidParameterError(f"margin must be finite and >= 0, got {margin!r}", field="margin")
        if on_infeasible not in ON_INFEASIBLE:
            raise InvalidParameterError(f"on_infeasible must be one of {ON_INFEASIBLE}, got {on_infeasible!r}",
                                        field="on_infeasible")
        self.m, self.n, self.objective, self.margin, self.taut = m, n, objective, float(margin), taut
        #: the chain the design numerics solve (the linear law: the laws agree where every spring is taut)
        self.lin = m if m.linear_springs else m.with_spring("linear")
        self.on_infeasible = on_infeasible
        self.load = checked_vector(load, 2, "load")
        lo, hi = bound_pair(bounds) if bounds is not None else (0.1 * float(m.b.min()), 4.0 * float(m.b.max()))
        self.lo = self._per_spring(lo, "bounds")
        self.hi = self._per_spring(hi, "bounds")
        if not (np.all(self.lo > 0) and np.all(self.lo < self.hi)):
            raise InvalidParameterError("bounds need 0 < lo < hi", field="bounds")
        self.rate = None if rate_limit is None else self._per_spring(rate_limit, "rate_limit")
        if self.rate is not None and not np.all(self.rate > 0):
            raise InvalidParameterError("rate_limit must be > 0", field="rate_limit")
        self.dt = None if dt is None else _seconds(dt, "dt")
        self.w = np.ones(2 * n) if weights is None else self._per_spring_pairs(weights, "weights")
        if not np.all(self.w > 0):
            raise InvalidParameterError("weights must be > 0", field="weights")
        self.geo = step_layouts(n, False).geometry.pack(a=m.a, b=m.b, k1=m.k1, k2=m.k2)
        self.limits = m.joint_limits
        self.scale = float(np.max(m.b))
        self.ell = self._rest_lengths0(rest_lengths0)               # segment-major: l[2i], l[2i+1]
        self.q = self._start(start)
        self.state_load = self.load.copy()          # the load the state q is an equilibrium under
        self.at_stop = False                        # the state is against a joint's stop (no equilibrium)
        self.verify = bool(verify)
        self.index = 0                              # steps taken (the events' step)
        self._rollout = False                       # inside rollout(): held steps need no proposal
        self._state_margin: tuple = (None, math.nan)    # (index, at_stop) of the state it was computed for
        self.mu: dict[bool, np.ndarray] = {}
        self.last: PreloadStep | None = None

    # ------------------------------------------------------------------ setup
    def _per_spring(self, v, name: str) -> np.ndarray:
        """A number or 2n values (``L1_0`` of every segment, then ``L2_0``) -> segment-major 2n."""
        n = self.n
        a = np.asarray(v, dtype=float).ravel() if np.ndim(v) else np.full(2 * n, float(v))
        if a.size != 2 * n or not np.all(np.isfinite(a)):
            raise InvalidParameterError(f"{name} must be a number or {2 * n} finite values", field=name)
        springs = rest_lengths(n).unpack(a)
        return np.column_stack([springs["L10"], springs["L20"]]).ravel()

    def _per_spring_pairs(self, v, name: str) -> np.ndarray:
        a = np.asarray(v, dtype=float)
        if a.shape != (self.n, 2) or not np.all(np.isfinite(a)):
            raise InvalidParameterError(f"{name} must be {self.n} pairs of finite numbers", field=name)
        return a.ravel()

    def _rest_lengths0(self, r0) -> np.ndarray:
        """The start's rest lengths, segment-major 2n: ``m``'s own, or ``rest_lengths0`` checked."""
        if r0 is None:
            return np.column_stack([self.m.L1_0, self.m.L2_0]).ravel()
        try:
            a = np.asarray(r0, dtype=float)
        except (TypeError, ValueError):
            a = np.empty(0)
        if a.shape != (self.n, 2) or not np.all(np.isfinite(a)):
            raise InvalidParameterError(f"rest_lengths0 must be {self.n} pairs (L1_0, L2_0) of finite numbers, got "
                                        f"shape {a.shape}", field="rest_lengths0")
        ell = a.ravel()
        out = np.flatnonzero((ell < self.lo) | (ell > self.hi))
        if out.size:
            i = int(out[0])
            raise InvalidParameterError(
                f"rest_lengths0[{i // 2}][{i % 2}] = {ell[i]:g} is outside the actuator bounds "
                f"[{self.lo[i]:g}, {self.hi[i]:g}]", field="rest_lengths0")
        return ell.copy()

    def _start(self, start) -> np.ndarray:
        if isinstance(start, Equilibrium):
            return start.q.copy()
        if start is not None:
            try:
                q = check_q0(self.manipulator(), start)
            except InvalidParameterError as exc:
                raise InvalidParameterError(exc.message.replace("q0", "start"), field="start") from None
            if q is None:
                raise InvalidParameterError("start must be an Equilibrium or n joint angles", field="start")
            return q
        try:
            eq = loaded_rest(self.manipulator(), self.load)
            refuse_start_on_stop(eq.at_stop, "start", "the moves are followed (give a start)")
        except NoEquilibriumError as exc:
            raise NoEquilibriumError(f"no equilibrium under the load from the rest configuration: {exc.message}; "
                                     "give a start", field="load") from None
        if not eq.stable:
            raise InvalidParameterError("the equilibrium under the load reached from the rest configuration is "
                                        "unstable: give a stable start", field="load")
        return eq.q.copy()

    def manipulator(self, ell: np.ndarray | None = None, *, linear: bool = False) -> Manipulator:
        """The chain with rest lengths ``ell`` (segment-major 2n; default the current ones); ``linear``: its
        linear-law twin, which the design numerics solve."""
        ell = self.ell if ell is None else ell
        return self.m.with_segments(s.replace(L0=(float(ell[2 * i]), float(ell[2 * i + 1])))
                                    for i, s in enumerate((self.lin if linear else self.m).segments))

    def _margin_energy(self, ell: np.ndarray, q: np.ndarray, F: np.ndarray) -> tuple[float, float]:
        """``(stability margin, elastic energy)`` of the arm at ``q`` with rest lengths ``ell`` under ``F``, under
        each spring's law."""
        m = self.manipulator(ell)
        if m.linear_springs:
            E, _, _, _, _ = chain_solver(m).evaluate(q, F)
            return stability_margin(m, q, F), float(E)
        return law_margin(m, q, F), float(m.energy(q))

    # ------------------------------------------------------------------ one step
    def step(self, target, load=None, end_angle: float | None = None, *, dt: float | None = None) -> PreloadStep:
        """Rest lengths for the tip at ``target = (x, y)`` (and the last link at ``end_angle``, rad) under
        ``load`` (default the controller's), from the current state, ``dt`` seconds after the last step (default
        the controller's ``dt``; needed with a rate limit: each rest length moves by at most ``rate_limit * dt``);
        the state moves to where the arm goes under the step's command (module docstring)."""
        F = self.load if load is None else checked_vector(load, 2, "load")
        st = self.propose(target, F, end_angle, dt=dt)
        self.commit(st, F)
        return st

    def propose(self, target, load=None, end_angle: float | None = None, *, dt: float | None = None) -> PreloadStep:
        """The step :meth:`step` takes, without taking it: the state does not move (:meth:`commit` moves it)."""
        target = checked_vector(target, 2, "target")
        F = self.load if load is None else checked_vector(load, 2, "load")
        if end_angle is not None:
            end_angle = checked_vector(end_angle, 1, "end_angle")[0]
        lo, hi = self.box(dt)
        res = None
        if self.objective == "change":
            res = self._newton(target, F, end_angle, lo, hi)
        if res is None:
            res = self._ipopt(target, F, end_angle, lo, hi)
        if not isinstance(res, TensegrityError) and self.verify:
            tr = self.transition(res.command.ravel(), F)
            if self._safe(tr, res.q):
                res = res._but(verified=True, transition_margin=tr.margin,
                               message=res.message.replace(", verified by the forward solve", "")
                               + ", verified along its transition")
            elif tr.status == "released" and float(np.max(np.abs(tr.q - res.q))) <= SAME_POSE:
                res = res._but(message=res.message.replace(", verified by the forward solve", "")
                               + "; the arm, released from its joint stop, settles on the step's pose (a release "
                                 "from a stop is not a followed path: not verified)")
            else:
                res = InfeasibleDesignError(
                    f"the {res.method} step's command reaches the target but not along the way: "
                    f"{self._unsafe_why(tr, res.q)}", status="transition")
        if isinstance(res, TensegrityError):
            res = self._infeasible(target, F, end_angle, lo, hi, res)
        return res

    def commit(self, st: PreloadStep, load=None) -> None:
        """Take the step ``st`` (a :meth:`propose` from the current state) under ``load`` (default the
        controller's): the command becomes the current one, the state where the arm went."""
        F = self.load if load is None else checked_vector(load, 2, "load")
        if st.method != "none":
            self.ell = st.command.ravel().copy()
        if st.method in ("ipopt", "nearest", "horizon") or st.status != "feasible":
            self.mu.clear()                 # the multipliers of the least-change problem start again
        if st.status == "no_equilibrium":
            self.q, self.state_load, self.at_stop = st.q.copy(), F.copy(), True
        elif math.isfinite(st.energy):      # the state is an equilibrium under F
            self.q, self.state_load, self.at_stop = st.q.copy(), F.copy(), False
        self.last = st
        self.index += 1

    # ------------------------------------------------------------------ transitions
    def transition(self, ell: np.ndarray, F: np.ndarray) -> Transition:
        """What the arm does while the command moves linearly from the current one to ``ell`` (segment-major
        ``2n``) and the load from the state's to ``F``, from the current state
        (:mod:`~tensegrity_opt.analyses.paths.transition`); from a joint's stop, its release under ``(ell, F)``."""
        P0, P1 = self.ell.reshape(self.n, 2), np.asarray(ell, float).reshape(self.n, 2)
        if self.at_stop:
            return released(self.m, self.q, P1, F, step=self.index)
        m0 = self.manipulator()
        E = chain_solver(m0).evaluate(self.q, self.state_load)[0] if m0.linear_springs else m0.energy(self.q)
        state = ArmState(self.q.copy(), self.state_load.copy(), m0.tip(self.q), float(E), 0, True)
        return follow(self.m, state, P0, P1, self.state_load, F, step=self.index)

    def _margin_tol(self) -> float:
        return 1e-9 * self.m.torque_scale + 1e-7 * self.margin

    def state_margin(self) -> float:
        """The stability margin of the current state (NaN against a joint's stop)."""
        key = (self.index, self.at_stop)
        if self._state_margin[0] != key:
            mu = math.nan if self.at_stop else self._margin_energy(self.ell, self.q, self.state_load)[0]
            self._state_margin = (key, mu)
        return self._state_margin[1]

    def _floor(self) -> float:
        """The least margin a transition may pass through: the required one, or the state's own where the arm
        already is below it (a move never makes the margin worse than required, or than where the arm was)."""
        mu0 = self.state_margin()
        return self.margin if not math.isfinite(mu0) else min(self.margin, mu0)

    def _safe(self, tr: Transition, q: np.ndarray) -> bool:
        """The transition ``tr`` gets the arm to ``q`` along its branch, stable all along, its margin never below
        :meth:`_floor`, and at ``q`` at least the required one."""
        if not (tr.status == "followed" and float(np.max(np.abs(tr.q - q))) <= SAME_POSE):
            return False
        tol = self._margin_tol()
        return tr.margin >= self._floor() - tol and tr.margin_end >= self.margin - tol

    def _unsafe_why(self, tr: Transition, q: np.ndarray) -> str:
        """Why :meth:`_safe` refuses ``tr`` (a phrase)."""
        if tr.status == "snapped":
            e = tr.snaps[0]
            return (f"the arm snaps at {e.fraction:.4g} of the move (largest joint motion {e.distance:.3g} rad) and "
                    f"lands with the tip at ({e.tip_after[0]:.6g}, {e.tip_after[1]:.6g})")
        if tr.status == "joint_limit":
            return f"a joint reaches its stop at {tr.fraction:.4g} of the move (no equilibrium beyond)"
        if tr.status == "released":
            return "the arm starts against a joint's stop: its release is not a followed path"
        if tr.status != "followed":
            return f"the transition could not be followed ({tr.message})"
        if tr.margin < self._floor() - self._margin_tol():
            return (f"the margin falls to {tr.margin:.6g} at {tr.margin_at:.4g} of the move, below the required "
                    f"{self.margin:.6g}")
        if tr.margin_end < self.margin - self._margin_tol():
            return f"the margin at the end of the move is {tr.margin_end:.6g}, below the required {self.margin:.6g}"
        return f"the followed branch ends {float(np.max(np.abs(tr.q - q))):.3g} rad away from the planned pose"

    def _pose_of(self, ell: np.ndarray, tr: Transition, F: np.ndarray, solver: SolverInfo) -> _Pose:
        """The arm's state at the end of the transition ``tr`` under ``(ell, F)`` (NaN margin and energy at a
        joint's stop)."""
        if tr.status in ("followed", "snapped", "released"):
            p = self._pose(ell, tr.q, F, solver)
            return _Pose(p.ell, p.q, p.tip, p.margin, p.energy, solver, tr)
        q = np.array(tr.q, dtype=float)
        tip = np.array(tr.tip, dtype=float)
        ell = np.array(ell, dtype=float)
        for v in (q, tip, ell):
            v.setflags(write=False)
        return _Pose(ell, q, tip, math.nan, math.nan, solver, tr)

    def rollout(self, targets, loads, end_angles=None, dts=None) -> list[PreloadStep]:
        """The steps the controller would take over ``targets`` (``(k, 2)``) under ``loads`` (``(k, 2)``), with
        ``end_angles`` (NaN: free) and ``dts`` (seconds; NaN: none), from the current state; the state is left as
        it was (the horizon planner's comparison)."""
        saved = self.snapshot()
        out = []
        self._rollout = True
        try:
            for k in range(len(targets)):
                a = None if end_angles is None or math.isnan(end_angles[k]) else float(end_angles[k])
                h = None if dts is None or math.isnan(dts[k]) else float(dts[k])
                out.append(self.step(targets[k], loads[k], a, dt=h))
        finally:
            self.restore(saved)
            self._rollout = False
        return out

    def snapshot(self) -> tuple:
        """The controller's state (its command, the arm's configuration and load, the step count, the warm
        start), for :meth:`restore`."""
        return (self.ell.copy(), self.q.copy(), self.state_load.copy(), self.at_stop, self.index,
                {k: v.copy() for k, v in self.mu.items()}, self.last)

    def restore(self, saved: tuple) -> None:
        """Back to a :meth:`snapshot`."""
        ell, q, F, at_stop, index, mu, last = saved
        self.ell, self.q, self.state_load, self.at_stop, self.index = ell.copy(), q.copy(), F.copy(), at_stop, index
        self.mu, self.last = {k: v.copy() for k, v in mu.items()}, last

    def box(self, dt: float | None = None) -> tuple[np.ndarray, np.ndarray]:
        """The bounds of a step's rest lengths ``dt`` seconds after the last step (default the controller's
        ``dt``), segment-major 2n: the actuator bounds intersected with the rate box ``rate_limit * dt`` around
        the current command."""
        h = self.dt if dt is None else _seconds(dt, "dt")
        if self.rate is None:
            return self.lo, self.hi
        if h is None:
            raise InvalidParameterError("rate_limit is a length per second: give the time since the last step, dt "
                                        "(seconds), to the step or the controller", field="dt")
        return np.maximum(self.lo, self.ell - self.rate * h), np.minimum(self.hi, self.ell + self.rate * h)

    def _newton(self, target, F, end_angle, lo, hi) -> PreloadStep | None:
        angle = end_angle is not None
        inv = inverse_statics(self.n, angle)
        mu = self.mu.get(angle)
        if mu is None or mu.size != inv.rows:
            mu = np.zeros(inv.rows)
        # the step's vectors filled block by block at the layouts' places (on the control loop's path: no
        # keyword packing)
        at, tg = inv.unknowns.places, inv.target.places
        y0 = np.empty(inv.unknowns.size)
        y0[at["q"]], y0[at["ell"]], y0[at["mu"]] = self.q, self.ell, mu
        tgt = np.empty(inv.target.size)
        tgt[tg["tip"]], tgt[tg["angle"]] = target, float(end_angle) if angle else 0.0
        y, resid, iters, H, E, tip, KKT = inv.step(y0, self.geo, F, tgt, self.ell, self.w, self.q, Q_WEIGHT,
                                                   NEWTON_TOL)
        n = self.n
        q, ell = y[at["q"]], y[at["ell"]]
        if not (resid <= 1e3 * NEWTON_TOL and np.all(np.isfinite(y))):
            return None
        if np.any(np.abs(q) >= self.limits * (1 - 1e-6)) or np.any(ell < lo - 1e-12) or np.any(ell > hi + 1e-12):
            return None
        margin = float(np.linalg.eigvalsh(H)[0])
        if margin < self.margin:
            return None
        if self.taut and not self._taut_at(ell, q):
            return None                     # a spring slack or pushing at the pose: IPOPT keeps them taut
        kk = np.linalg.eigvalsh(KKT)
        if int(np.sum(kk > 0)) != 3 * n or int(np.sum(kk < 0)) != inv.rows:
            return None                     # a KKT point that is not a local minimum of the least change
        self.mu[angle] = y[at["mu"]].copy()
        solver = _NEWTON.get(iters) or _NEWTON.setdefault(iters, SolverInfo("Newton_Converged", iters))
        # q and ell are views of the step's own iterate y: no copy needed before they turn read-only
        command = ell.reshape(n, 2)
        return PreloadStep._of(springs=self.m.springs,
                               command=command, proposal=command, q=q, tip=tip, end_angle=float(np.sum(q)),
                               margin=margin, energy=E, tip_error=_distance(tip, target), proposal_tip=tip,
                               feasible=True, method="newton", solver=solver, residual=resid, target=target.copy(),
                               message="the least-change Newton step converged")

    def _taut_at(self, ell: np.ndarray, q: np.ndarray) -> bool:
        """Every spring at least ``TAUT_FLOOR * max b`` longer than its rest length at ``q`` with rest lengths ``ell``
        (segment-major 2n): the taut constraint IPOPT's steps keep."""
        L1, L2 = self.m.spring_lengths(q)
        floor = TAUT_FLOOR * float(np.max(self.m.b))
        return bool(np.all(L1 - ell[0::2] >= floor) and np.all(L2 - ell[1::2] >= floor))

    def _springs(self, v: np.ndarray) -> np.ndarray:
        """Segment-major 2n -> the design problems' ``L10``, ``L20`` blocks."""
        return rest_lengths(self.n).pack(L10=v[0::2], L20=v[1::2])

    def _ipopt(self, target, F, end_angle, lo, hi) -> PreloadStep | TensegrityError:
        """IPOPT's step (:func:`preloads_for_pose`), or the error saying why it found none."""
        nominal = self.manipulator()
        try:
            d = preloads_for_pose(nominal, target, load=F, objective=self.objective, margin=self.margin,
                                  bounds=(self._springs(lo), self._springs(hi)), end_angle=end_angle, start=self.q,
                                  taut=self.taut)
        except TimeLimitError:
            raise
        except TensegrityError as exc:
            return exc
        q = d.q
        command = d.preloads.copy()
        return PreloadStep._of(springs=self.m.springs, command=command, proposal=command, q=q.copy(), tip=d.tip.copy(),
                               end_angle=float(np.sum(q)), margin=float(d.margin), energy=float(d.energy),
                               tip_error=_distance(d.tip, target), proposal_tip=d.tip.copy(), feasible=True,
                               method="ipopt", solver=d.solver, residual=None, target=target.copy(),
                               message=f"IPOPT ({self.objective}) converged, verified by the forward solve")

    def evaluate(self, command, F, target, end_angle: float | None = None, *, method: str, solver: SolverInfo,
                 planned_q: np.ndarray | None = None, message: str = "") -> PreloadStep:
        """The step that sends ``command`` (``(n, 2)``) under the load ``F`` from the current state, toward
        ``target``: where the arm goes along the transition (``verify``; else the forward solve), feasible when it
        ends on the target, stable with the margin (along the whole transition when verified) and, with
        ``planned_q``, on that configuration. The state does not move (:meth:`commit`)."""
        ell = np.asarray(command, float).ravel()
        target = checked_vector(target, 2, "target")
        F = checked_vector(F, 2, "load")
        if self.verify:
            tr = self.transition(ell, F)
            pose = self._pose_of(ell, tr, F, solver)
            verified = self._safe(tr, tr.q if planned_q is None else planned_q)
            why = "" if verified else self._unsafe_why(tr, tr.q if planned_q is None else planned_q)
        else:
            tr = None
            eq = self._forward(ell, F, self.q)
            if eq is None:
                q = self.q.copy()
                q.setflags(write=False)
                pose = _Pose(ell.copy(), q, self.m_tip(q), math.nan, math.nan, solver)
            else:
                pose = self._pose(ell, eq.q, F, solver)
            verified, why = False, "" if eq is not None else "the forward solve finds no equilibrium"
            if planned_q is not None and eq is not None and float(np.max(np.abs(eq.q - planned_q))) > SAME_POSE:
                why = "the forward solve does not land on the planned pose"
        on_target = _distance(pose.tip, target) <= LAND_TOL * self.scale and (
            end_angle is None or abs(float(np.sum(pose.q)) - float(end_angle)) <= LAND_TOL)
        ok = (verified or (not self.verify and not why)) and math.isfinite(pose.margin) \
            and pose.margin >= self.margin - self._margin_tol()
        feasible = bool(on_target and ok)
        text = message or f"the {method} command"
        text += (", verified along its transition" if verified else "") if not why else f" (refused: {why})"
        if ok and not on_target:
            text += f"; {_distance(pose.tip, target):.6g} from the target"
        command = ell.reshape(self.n, 2).copy()
        return PreloadStep._of(springs=self.m.springs, command=command, proposal=command, q=pose.q, tip=pose.tip,
                               end_angle=float(np.sum(pose.q)), margin=pose.margin, energy=pose.energy,
                               tip_error=_distance(pose.tip, target), proposal_tip=pose.tip, feasible=feasible,
                               method=method, solver=solver, residual=None, target=target.copy(), message=text,
                               verified=verified, transition_margin=math.nan if tr is None else tr.margin,
                               events=() if tr is None else tr.events)

    # ------------------------------------------------------------------ infeasible steps
    def _infeasible(self, target, F, end_angle, lo, hi, exc: TensegrityError) -> PreloadStep:
        """An infeasible step: the nearest admissible pose (the proposal; the command with ``"approach"``, or
        the target itself where it reaches it) and the held state."""
        n = self.n
        held = self.hold(F)
        best = getattr(exc, "best", None)
        if self._rollout and self.on_infeasible == "hold":
            near = None                     # a rollout holds: the proposal is not needed
        else:
            near = self.nearest(target, F, end_angle, lo, hi, best=best if isinstance(best, dict) else None,
                                held=held)
        solver = SolverInfo(str(exc.status) if exc.status else "none", 0)
        reaches = near is not None and _distance(near.tip, target) <= LAND_TOL * self.scale and (
            end_angle is None or abs(float(np.sum(near.q)) - float(end_angle)) <= 1e-6)
        if reaches or (near is not None and self.on_infeasible == "approach"):
            command = near.ell.reshape(n, 2).copy()
            checked = ", verified along its transition" if near.verified else ""
            message = ("the nearest admissible pose reaches the target (the step's own solve failed: "
                       f"{exc.message}){checked}") if reaches else \
                (f"{exc.message}; approaching: the nearest admissible pose, {_distance(near.tip, target):.6g} from "
                 f"the target{checked}")
            return PreloadStep._of(springs=self.m.springs, command=command, proposal=command, q=near.q, tip=near.tip,
                                   end_angle=float(np.sum(near.q)), margin=near.margin, energy=near.energy,
                                   tip_error=_distance(near.tip, target), proposal_tip=near.tip, feasible=reaches,
                                   method="nearest", solver=near.solver, residual=None, target=target.copy(),
                                   message=message, verified=near.verified,
                                   transition_margin=math.nan if near.tr is None else near.tr.margin, events=())
        prop = near if near is not None else held
        why = ("" if near is not None else "; no admissible pose found, the proposal is the held value")
        what = f"{exc.message}; holding the previous command{why}"
        if self.on_infeasible == "hold" and near is not None and not reaches:
            what += (f" (the target is {_distance(near.tip, target):.6g} from the nearest admissible pose: held, the "
                     "arm does not move toward it; on_infeasible='approach' moves it as far as the rate limit "
                     "allows)")
        tr = held.tr
        if tr is not None and tr.status == "snapped":
            e = tr.snaps[0]
            what += (f"; the held arm snaps at {e.fraction:.4g} of the step (largest joint motion "
                     f"{e.distance:.3g} rad): q and tip are where it lands")
        elif tr is not None and tr.status == "joint_limit":
            what += (f"; the arm has no equilibrium under the held command and the step's load: a joint reaches its "
                     f"stop at {tr.fraction:.4g} of the step (q is the configuration there)")
        elif tr is not None and tr.status == "released":
            what += "; the arm, released from its joint stop under the held command, settles at q"
        elif tr is not None and tr.status == "followed" and min(tr.margin, tr.margin_end) < \
                self.margin - self._margin_tol():
            what += (f"; the held arm's margin is {tr.margin_end:.6g} at the end of the step (least "
                     f"{tr.margin:.6g} at {tr.margin_at:.4g} of it), below the required {self.margin:.6g}")
        elif tr is None and not math.isfinite(held.energy):
            what += "; the held rest lengths have no equilibrium under the step's load"
        verified = tr is not None and self._safe(tr, held.q)
        return PreloadStep._of(springs=self.m.springs, command=self.ell.reshape(n, 2).copy(),
                               proposal=prop.ell.reshape(n, 2).copy(),
                               q=held.q, tip=held.tip, end_angle=float(np.sum(held.q)), margin=held.margin,
                               energy=held.energy, tip_error=_distance(held.tip, target), proposal_tip=prop.tip,
                               feasible=False, method="none", solver=solver, residual=None, target=target.copy(),
                               message=what, verified=verified,
                               transition_margin=math.nan if tr is None else tr.margin,
                               events=() if tr is None else tr.events)

    def hold(self, F) -> _Pose:
        """The arm's state with the current command under the load ``F``: where the transition of holding takes
        it (the load moving from the state's to ``F``; with ``verify=False`` the current state when ``F`` is its
        load, else the forward equilibrium from it); NaN margin and energy where there is no equilibrium."""
        F = checked_vector(F, 2, "load")
        if self.verify:
            return self._pose_of(self.ell, self.transition(self.ell, F), F, SolverInfo("none", 0))
        if np.array_equal(F, self.state_load) and not self.at_stop:
            return self._pose(self.ell, self.q, F, SolverInfo("none", 0))
        eq = self._forward(self.ell, F, self.q)
        if eq is None:
            q = self.q.copy()
            q.setflags(write=False)
            return _Pose(self.ell.copy(), q, self.m_tip(q), math.nan, math.nan, SolverInfo("none", 0))
        return self._pose(self.ell, eq.q, F, SolverInfo("none", 0))

    def m_tip(self, q: np.ndarray) -> np.ndarray:
        tip = self.m.tip(q)
        tip.setflags(write=False)
        return tip

    def _pose(self, ell: np.ndarray, q: np.ndarray, F: np.ndarray, solver: SolverInfo) -> _Pose:
        margin, E = self._margin_energy(ell, q, F)
        q = np.array(q, dtype=float)
        ell = np.array(ell, dtype=float)
        tip = self.m.tip(q)
        for v in (q, ell, tip):
            v.setflags(write=False)
        return _Pose(ell, q, tip, margin, E, solver)

    def _forward(self, ell: np.ndarray, F: np.ndarray, q_from: np.ndarray) -> Equilibrium | None:
        """The forward quasi-static solve: the equilibrium with rest lengths ``ell`` under ``F`` reached from
        ``q_from`` (Newton; IPOPT's descent where Newton does not settle), or None."""
        m = self.manipulator(ell)
        eq = settle_under_force(m, F, q_from) if m.linear_springs else None
        if eq is None:
            try:
                eq = solve_equilibrium_under_force(m, *F, q0=q_from)
            except TimeLimitError:
                raise
            except TensegrityError:
                return None
        return eq

    def nearest(self, target, F, end_angle=None, lo=None, hi=None, *, best: dict | None = None,
                held: _Pose | None = None) -> _Pose | None:
        """The admissible pose nearest to ``target`` (and ``end_angle``) under ``F`` from the current state:
        rest lengths within ``lo``, ``hi`` (default :meth:`box`), stable with the margin, inside the joint
        range. The preload NLP minimising the tip's distance (:func:`~.preloads.solve_pose_nlp`) from several
        starts: the current state, IPOPT's last point ``best`` (``{"q", "preloads"}``), the held state and
        :data:`NEAREST_SPREAD` rest lengths spread in the box; a candidate counts only where the forward solve
        from the current configuration with its rest lengths lands on it (``q`` within 1e-6, stable, the
        margin held; with ``verify``, along its whole transition). ``held`` (:meth:`hold`) is a candidate itself.
        None: no admissible pose found."""
        target = checked_vector(target, 2, "target")
        F = checked_vector(F, 2, "load")
        if lo is None or hi is None:
            lo, hi = self.box()
        springs = rest_lengths(self.n)
        nominal = self.manipulator(linear=True)
        lo_s, hi_s = self._springs(lo), self._springs(hi)
        starts: list[tuple[np.ndarray, np.ndarray]] = [(self.q, self._springs(self.ell))]
        if best is not None and "q" in best and "preloads" in best:
            pre = np.asarray(best["preloads"], dtype=float).reshape(self.n, 2)
            starts.append((np.asarray(best["q"], dtype=float), springs.pack(L10=pre[:, 0], L20=pre[:, 1])))
        if held is not None and math.isfinite(held.energy) and not np.array_equal(held.q, self.q):
            starts.append((held.q, self._springs(held.ell)))
        rng = np.random.default_rng(0)
        for u in [np.full(2 * self.n, 0.5), *rng.uniform(size=(NEAREST_SPREAD - 1, 2 * self.n))]:
            ell0 = lo + u * (hi - lo)
            eq = settle_under_force(self.manipulator(ell0, linear=True), F, self.q)
            starts.append((self.q if eq is None else eq.q, self._springs(ell0)))
        candidates: list[_Pose] = []
        if held is not None and math.isfinite(held.margin) and held.margin >= self.margin - 1e-9 and (
                held.tr is None or self._safe(held.tr, held.q)):
            candidates.append(held)
        for q0, ell0 in starts:
            q0 = np.clip(q0, -self.limits * 0.999, self.limits * 0.999)
            res, q, L10, L20, _, _ = solve_pose_nlp(nominal, target, F, "change", self.margin, self.taut, lo_s,
                                                    hi_s, end_angle, q0, ell0, nearest=True)
            ell = np.column_stack([L10, L20]).ravel()
            solver = SolverInfo(res.status, res.iterations)
            if self.verify:
                tr = self.transition(ell, F)
                if not self._safe(tr, q):
                    continue                # the arm does not get there from here along the move (a snap, ...)
                pose = self._pose_of(ell, tr, F, solver)
            else:
                eq = self._forward(ell, F, self.q)
                if eq is None or not eq.stable or float(np.max(np.abs(eq.q - q))) > 1e-6:
                    continue                # the arm does not get there from here (another well, or none)
                pose = self._pose(ell, eq.q, F, solver)
            if pose.margin >= self.margin - 1e-7 * max(1.0, self.margin):
                candidates.append(pose)
        if not candidates:
            return None

        def distance(p: _Pose) -> tuple[float, float]:
            d = float(np.sum((p.tip - target) ** 2)) / self.scale ** 2
            if end_angle is not None:
                d += (float(np.sum(p.q)) - float(end_angle)) ** 2
            return round(d, 14), float(np.sum((p.ell - self.ell) ** 2))

        return min(candidates, key=distance)


def _distance(tip: np.ndarray, target: np.ndarray) -> float:
    return float(math.hypot(float(tip[0]) - float(target[0]), float(tip[1]) - float(target[1])))


@dataclass(frozen=True)
class PreloadPlan(Outcome, SpringFields):
    """The result of :func:`plan_preloads` (``K`` steps done).

    Attributes
    ----------
    commands : ndarray (K, n, 2)
        ``L1_0, L2_0`` per segment and step: what to send (:attr:`PreloadStep.command`). Consecutive commands
        differ by at most ``rate_limit`` times the time between them.
    proposals : ndarray (K, n, 2)
        The controller's proposals (:attr:`PreloadStep.proposal`; the commands except on held steps).
    q : ndarray (K, n)
        The arm's configuration under each command.
    tip : ndarray (K, 2)
    tip_error : ndarray (K,)
        ``|tip - target|`` per step.
    end_angle, margin : ndarray (K,)
    feasible : ndarray (K,) of bool
    verified : ndarray (K,) of bool
        Each step's transition was followed (:attr:`PreloadStep.verified`): the previous command and load moving
        linearly to this step's over the step's interval, the arm stays on its branch -- no fold, no branch point,
        no joint limit -- with the margin all along, and ends on the step's pose (False everywhere with
        ``verify=False``: not checked).
    transition_margin : ndarray (K,)
        The least stability margin along each step's transition (torque / rad; NaN where none was followed).
    method : tuple of str
        Per step (:data:`METHODS`) ``"newton"``, ``"ipopt"``, ``"nearest"``, ``"horizon"`` or ``"none"`` (held).
    status : str
        :attr:`STATUSES`: ``"complete"``, ``"infeasible_steps"`` (some steps infeasible: see ``feasible``; approach
        steps that did not reach the target count), ``"snapped"`` (the arm snapped in some step),
        ``"no_equilibrium"`` (in some step the arm had no equilibrium: a joint reached its stop), ``"time_limit"``
        (the steps done so far). With ``on_snap="stop"`` the plan ends after the first step that snapped or had no
        equilibrium.
    steps : tuple of PreloadStep
    seconds : float
    targets : ndarray (K, 2)
        The targets of the steps done.
    margin_required : float
    objective : str
    times : ndarray (K,)
        The steps' instants (s; the start at 0), NaN without a time base (``null`` in :meth:`to_dict`).
    on_infeasible : str
        ``"hold"`` or ``"approach"`` (:data:`ON_INFEASIBLE`).
    on_snap : str
        ``"continue"`` or ``"stop"`` (:data:`ON_SNAP`).
    start : ndarray (n,)
        The arm's configuration at time 0 (the first step's transition starts there): ``start`` as given, or the
        default (:class:`PreloadController`); the same whatever the ``horizon``.
    note : str
        Part of :attr:`message`: with a ``horizon``, that the step-by-step plan was returned (it was better).
    spring_lengths, spring_stretches, spring_forces, spring_states : ndarray (K, n, 2)
        The springs at each step's ``q`` under its command (:class:`~tensegrity_opt.model.springs.SpringFields`).
    horizon : int, str or None
        None (step by step), ``N`` (a receding horizon) or ``"all"`` (:func:`plan_preloads`).
    message : str
        The status in a sentence.
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "complete": "every step is feasible",
        "infeasible_steps": "some steps are infeasible (see feasible): each commands the held value (hold) or the "
                            "nearest admissible pose's rest lengths (approach), the next starting from the arm's "
                            "state under that command",
        "snapped": "the arm snapped during some step's transition (nothing admissible avoided it): that step "
                   "reports where it landed and the next starts from there (on_snap continue), or the plan ends "
                   "after it (stop)",
        "no_equilibrium": "in some step the arm had no equilibrium inside the physical range (a joint reached its "
                          "stop): that step reports the configuration there and the next starts from it, released "
                          "(on_snap continue), or the plan ends after it (stop)",
        "time_limit": "the time limit ran out: the steps done so far",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"complete"})

    commands: np.ndarray
    proposals: np.ndarray
    q: np.ndarray
    tip: np.ndarray
    tip_error: np.ndarray
    end_angle: np.ndarray
    margin: np.ndarray
    feasible: np.ndarray
    verified: np.ndarray
    method: tuple[str, ...]
    status: str
    steps: tuple[PreloadStep, ...]
    seconds: float
    targets: np.ndarray
    margin_required: float = 0.0
    objective: str = "change"
    times: np.ndarray | None = None
    on_infeasible: str = "hold"
    horizon: int | str | None = None
    on_snap: str = "continue"
    transition_margin: np.ndarray | None = None
    start: np.ndarray | None = None
    note: str = ""
    springs: Springs | None = field(default=None, repr=False, compare=False)

    def _spring_rest_lengths(self) -> np.ndarray:
        return self.commands

    def __post_init__(self) -> None:
        if self.times is None:
            object.__setattr__(self, "times", np.full(len(self.steps), math.nan))
        if self.transition_margin is None:
            object.__setattr__(self, "transition_margin", np.array([s.transition_margin for s in self.steps], float))
        freeze(self, copy=False)

    @property
    def message(self) -> str:
        """A sentence: how many steps, feasible and verified; where the arm snapped or had no equilibrium."""
        K = len(self.steps)
        done = f"{K} step(s), {int(np.sum(self.feasible))} feasible, {int(np.sum(self.verified))} verified"
        snaps = [k for k, s in enumerate(self.steps) if s.status == "snap"]
        lost = [k for k, s in enumerate(self.steps) if s.status == "no_equilibrium"]
        if snaps:
            done += f"; the arm snapped in step(s) {', '.join(map(str, snaps))}"
        if lost:
            done += f"; no equilibrium (a joint at its stop) in step(s) {', '.join(map(str, lost))}"
        if (snaps or lost) and self.on_snap == "stop" and self.status != "time_limit":
            done += f"; stopped after step {K - 1} (on_snap='stop')"
        held = [k for k, s in enumerate(self.steps) if s.method == "none" and s.status == "infeasible"]
        if held and self.on_infeasible == "hold" and len(held) >= 2:
            done += (f"; {len(held)} step(s) held (on_infeasible='hold' never moves toward a target out of reach: "
                     "'approach' does)")
        if self.note:
            done += f"; {self.note}"
        if self.status == "time_limit":
            return f"the time limit ran out after {done}"
        return done

    def to_dict(self) -> dict[str, Any]:
        """JSON form: ``success``, ``status``, ``message``, ``seconds``, the per-step arrays (``commands``,
        ``proposals``, ``q``, ``tip``, ``tip_error``, ``end_angle``, ``margin`` (null: no equilibrium),
        ``feasible``, ``verified``, ``transition_margin`` (null: none followed), ``method``), ``targets``, ``times``
        (null: no time base), ``margin_required``, ``objective``, ``on_infeasible``, ``on_snap``, ``horizon``,
        ``start`` (the configuration at time 0), ``steps`` (:meth:`PreloadStep.to_dict`) and the spring state per
        step under its command (``spring_lengths``, ``spring_stretches``, ``spring_forces``, ``spring_states``:
        (K, n, 2))."""
        return {**self.outcome(), **self.spring_dict(), "seconds": number(self.seconds),
                "commands": [[numbers(r) for r in s] for s in self.commands],
                "proposals": [[numbers(r) for r in s] for s in self.proposals],
                "q": [numbers(r) for r in self.q], "tip": [numbers(r) for r in self.tip],
                "tip_error": numbers(self.tip_error), "end_angle": numbers(self.end_angle),
                "margin": [nullable(v) for v in self.margin], "feasible": [bool(v) for v in self.feasible],
                "verified": [bool(v) for v in self.verified],
                "transition_margin": [nullable(v) for v in self.transition_margin], "method": list(self.method),
                "targets": [numbers(r) for r in self.targets], "times": [nullable(t) for t in self.times],
                "margin_required": number(self.margin_required), "objective": self.objective,
                "on_infeasible": self.on_infeasible, "on_snap": self.on_snap, "horizon": self.horizon,
                "start": None if self.start is None else numbers(self.start),
                "steps": [s.to_dict() for s in self.steps]}


def plan_preloads(m: Manipulator, targets, *, loads=None, end_angles=None, times=None, dt: float | None = None,
                  rest_lengths0=None, bounds=None, rate_limit=None, margin: float = 1e-3, objective: str = "change",
                  weights=None, start=None, on_infeasible: str = "hold", horizon: int | str | None = None,
                  verify: bool = True, on_snap: str = "continue", taut: bool = False, timeout: float | None = None,
                  progress: Callable[[int, int], Any] | None = None) -> PreloadPlan:
    """Rest lengths for a trajectory of tip poses, on one stable branch (module docstring).

    Parameters
    ----------
    m : Manipulator
    targets : array_like (K, 2)
        Tip positions ``(x, y)`` per step (length units).
    loads : array_like (2,) or (K, 2), optional
        Dead tip loads (default none).
    end_angles : array_like (K,), optional
        The last link's absolute angle per step (rad); NaN leaves a step's angle free.
    times : array_like (K,), optional
        The steps' instants (s): the start is the state at time 0, ``0 < times[0] < times[1] < ...``; step ``k``
        changes each rest length by at most ``rate_limit * (times[k] - times[k-1])`` (``times[-1] = 0``).
    dt : float, optional
        A fixed step (s) instead of ``times``: ``times[k] = (k + 1) dt``.
    rest_lengths0 : array_like (n, 2), optional
        The arm's rest lengths at time 0 (default ``m``'s own): the first step's change is measured from them and
        the start is an equilibrium with them.
    rate_limit : float or array_like, optional
        Largest speed of each rest length (length units per second); needs ``times`` or ``dt``.
    margin : float
        Required stability margin: absolute, torque per radian (module docstring).
    bounds, objective, weights, start, on_infeasible
        As :class:`PreloadController`.
    horizon : int or "all", optional
        None (default): step by step (:class:`PreloadController`). A positive int ``N``: a receding horizon, each
        step planned with the ``N`` steps after it as one IPOPT problem (the equilibrium, range, bounds, margin of
        every step and the rate box between steps as constraints; the tip error and the actuators' motion as
        objective), the first applied; ``"all"``: the whole trajectory as one problem (:mod:`.horizon`). Its steps
        have ``method`` ``"horizon"`` (``"none"``: held); ``objective`` must be ``"change"``.
    verify : bool
        Verify every step along its transition (default): the previous command and load moving linearly to the
        step's over its interval (:mod:`~tensegrity_opt.analyses.paths.transition`), a command is adopted only
        where the arm follows its branch to the step's pose with the margin all along; False: the end pose only,
        nothing verified.
    on_snap : {"continue", "stop"}
        When the arm snaps during a step (nothing admissible avoids it) or has no equilibrium (a joint reaches its
        stop): ``"continue"`` (default) plans the next steps from where it went, ``"stop"`` ends the plan after
        that step (:data:`ON_SNAP`).
    taut : bool
        Keep every spring in tension at every planned pose (:class:`PreloadController`); required for a chain with
        tension-only springs, whose plans are step by step (a horizon is refused, ``field="horizon"``).
    timeout : float, optional
        Seconds; on expiry the steps done are returned with ``status="time_limit"``.
    progress : callable(done, total), optional
        Called after each step with the steps done and ``K``.

    Returns
    -------
    PreloadPlan
    """
    unloaded_only(m, "plan_preloads")
    if isinstance(m, Manipulator) and not m.linear_springs and horizon is not None:
        raise UnsupportedError("a horizon plan's problem models the linear spring law: a chain with tension-only "
                               "springs is planned step by step (horizon=None, taut=True)", field="horizon",
                               spring="tension_only")
    T = real_array(targets, "targets")
    if T.ndim != 2 or T.shape[1] != 2 or T.shape[0] < 1 or not np.all(np.isfinite(T)):
        raise InvalidParameterError("targets must be K >= 1 finite tip positions (x, y)", field="targets")
    far = np.flatnonzero(np.hypot(T[:, 0], T[:, 1]) > FAR_TARGET * m.straight_length)
    if far.size:
        k = int(far[0])
        raise InvalidParameterError(
            f"targets[{k}] = ({T[k, 0]:.6g}, {T[k, 1]:.6g}) is more than {FAR_TARGET:g} times the chain's length "
            f"({m.straight_length:.6g}) from its base: not a tip position (a target out of reach is approached; "
            "give one within that distance)", field="targets")
    K = T.shape[0]
    if loads is None:
        Ls = np.zeros((K, 2))
    else:
        Ls = real_array(loads, "loads")
        Ls = np.broadcast_to(Ls, (K, 2)).copy() if Ls.shape in ((2,), (1, 2)) else Ls
        if Ls.shape != (K, 2) or not np.all(np.isfinite(Ls)):
            raise InvalidParameterError(f"loads must be one (fx, fy) or {K} of them, finite", field="loads")
    A = None
    if end_angles is not None:
        A = real_array(end_angles, "end_angles").ravel()
        if A.size != K or np.any(np.isinf(A)):
            raise InvalidParameterError(f"end_angles must be {K} numbers (NaN: free)", field="end_angles")
    t_steps = step_times(K, times, dt, rate_limit)
    h_steps = np.diff(t_steps, prepend=0.0)
    if horizon is not None:
        from .horizon import check_horizon

        horizon = check_horizon(horizon)
        if objective != "change":
            raise InvalidParameterError("a horizon plan minimises the tip error and the actuators' motion: objective "
                                        f"must be 'change', got {objective!r}", field="objective")
    if on_snap not in ON_SNAP:
        raise InvalidParameterError(f"on_snap must be one of {ON_SNAP}, got {on_snap!r}", field="on_snap")
    ctl = PreloadController(m, start, rest_lengths0=rest_lengths0, load=Ls[0], bounds=bounds, rate_limit=rate_limit,
                            margin=margin, objective=objective, weights=weights, on_infeasible=on_infeasible,
                            verify=verify, taut=taut)
    q_start = ctl.q.copy()
    t0 = time.perf_counter()
    steps: list[PreloadStep] = []
    status = "complete"
    note = ""
    with time_limit(timeout):
        if horizon is None:
            status = _step_by_step(ctl, T, Ls, A, h_steps, steps, on_snap, progress)
        else:
            from .horizon import horizon_steps

            saved = ctl.snapshot()
            try:
                horizon_steps(ctl, T, Ls, A, h_steps, horizon, steps, stop=on_snap == "stop", progress=progress)
            except TimeLimitError:
                status = "time_limit"
            if status == "complete":
                # never worse than step by step: the step-by-step plan of the same trajectory from the same start,
                # returned where it is better (more steps on target, or as many nearer in sum)
                ctl.restore(saved)
                own: list[PreloadStep] = []
                if _step_by_step(ctl, T, Ls, A, h_steps, own, on_snap, None) == "complete" and \
                        _score(own, ctl.scale) > _score(steps, ctl.scale):
                    f_h, e_h = _score(steps, ctl.scale)
                    note = (f"the step-by-step plan is returned: it is better on this trajectory than the horizon's "
                            f"({int(f_h)} steps on target, summed distance {-e_h:.6g} to the others)")
                    steps = own
    n = m.n
    if status == "complete":
        kinds = {s.status for s in steps}
        status = "no_equilibrium" if "no_equilibrium" in kinds else "snapped" if "snap" in kinds else \
            "infeasible_steps" if not all(s.feasible for s in steps) else "complete"
    P = len(steps)

    def arr(get, shape):
        return np.array([get(s) for s in steps], dtype=float).reshape((P, *shape))

    return PreloadPlan(commands=arr(lambda s: s.command, (n, 2)), proposals=arr(lambda s: s.proposal, (n, 2)),
                       q=arr(lambda s: s.q, (n,)), tip=arr(lambda s: s.tip, (2,)),
                       tip_error=arr(lambda s: s.tip_error, ()), end_angle=arr(lambda s: s.end_angle, ()),
                       margin=arr(lambda s: s.margin, ()), feasible=np.array([s.feasible for s in steps], dtype=bool),
                       verified=np.array([s.verified for s in steps], dtype=bool),
                       method=tuple(s.method for s in steps), status=status,
                       steps=tuple(steps), seconds=time.perf_counter() - t0, targets=T[:P].copy(),
                       margin_required=float(margin), objective=objective, times=t_steps[:P].copy(),
                       on_infeasible=on_infeasible, horizon=horizon, on_snap=on_snap, start=q_start, note=note,
                       springs=m.springs)


def _step_by_step(ctl: PreloadController, T, Ls, A, h_steps, steps: list, on_snap: str, progress) -> str:
    """The controller's steps over the trajectory, appended to ``steps``: ``"complete"`` or ``"time_limit"``."""
    K = T.shape[0]
    for k in range(K):
        if expired():
            return "time_limit"
        try:
            st = ctl.step(T[k], Ls[k], None if A is None or math.isnan(A[k]) else float(A[k]),
                          dt=None if math.isnan(h_steps[k]) else float(h_steps[k]))
        except TimeLimitError:
            return "time_limit"
        steps.append(st)
        if progress is not None:
            progress(k + 1, K)
        if on_snap == "stop" and st.status in ("snap", "no_equilibrium"):
            break
    return "complete"


def _score(steps, scale: float) -> tuple[float, float]:
    """``(steps on target, minus the summed distance of the others)``: larger is better (the tip on its target:
    within the landing tolerance)."""
    tol = LAND_TOL * scale
    return (float(sum(s.tip_error <= tol for s in steps)), -float(sum(s.tip_error for s in steps if s.tip_error > tol)))
