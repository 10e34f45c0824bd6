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
   current configuration lands on it, stable). What the step **commands** depends on ``on_infeasible``:

   * ``"hold"``: the previous command. The arm's state is the forward equilibrium with the held rest lengths
     under the step's load from the previous configuration (the same state when the load does not change);
   * ``"approach"``: the nearest admissible pose's rest lengths: the arm moves there, as close to the target
     as the bounds, the rate limit and the margin allow, and the controller catches up once the target is
     in reach again.

Every step carries the ``command`` to send and, apart, the ``proposal``; ``q``, ``tip``, ``margin``, ``energy``
describe the arm under the command (what a pipeline will observe), ``tip_error`` its distance to the target.
Consecutive commands never differ by more than ``rate_limit * dt`` (the time between them). ``residual`` is the
scaled KKT residual of a Newton step. :func:`plan_preloads` runs a controller over a trajectory and verifies each
step by the forward quasi-static solve
(:func:`~tensegrity_opt.analyses.equilibria.equilibrium.solve_equilibrium_under_force` from the previous step's
configuration with the step's command: it must land on the step's pose, stable).
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from ...bounds import bound_pair
from ...errors import InvalidParameterError, NoEquilibriumError, TensegrityError, TimeLimitError
from ...model.manipulator import Manipulator
from ...numerics import chain_solver
from ...numerics.inverse_statics import inverse_statics
from ...numerics.inverse_statics import layouts as step_layouts
from ...numerics.layout import rest_lengths
from ...outcome import Outcome, SolverInfo, freeze
from ...serialize import nullable, number, numbers
from ...timelimit import expired, time_limit
from ..equilibria.equilibrium import Equilibrium, check_q0, settle_under_force, solve_equilibrium_under_force
from ..paths.control import checked_vector
from .follower import loaded_rest
from .preloads import LAND_TOL, OBJECTIVES, preloads_for_pose, solve_pose_nlp, stability_margin

__all__ = ["PreloadController", "PreloadStep", "PreloadPlan", "plan_preloads", "step_times", "ON_INFEASIBLE", "METHODS"]

#: What an infeasible step commands: ``"hold"`` the previous command, ``"approach"`` the nearest admissible pose's
#: rest lengths.
ON_INFEASIBLE = ("hold", "approach")
#: How a step's command was found: the least-change ``"newton"`` step, ``"ipopt"`` (the fallback or the
#: objective), ``"nearest"`` (the nearest admissible pose: an approach step, or the target reached by it where
#: the other two failed), ``"horizon"`` (a step of a horizon plan, :mod:`.horizon`), ``"none"`` (held: no new
#: command).
METHODS = ("newton", "ipopt", "nearest", "horizon", "none")
#: Spread starts of the nearest-pose search (besides the current state, IPOPT's last point and the held state).
NEAREST_SPREAD = 2

#: KKT residual (max-norm, force and length units) below which the Newton step has converged.
NEWTON_TOL = 1e-10
#: Weight of ``|q - q_prev|^2`` in the least-change objective (regularises the joint angles' null space).
Q_WEIGHT = 1e-8
#: The solver detail of a Newton step, per iteration count (immutable, so shared).
_NEWTON: dict[int, SolverInfo] = {}


def _seconds(v, field: str) -> float:
    """A duration in seconds: finite and > 0."""
    try:
        h = float(v)
    except (TypeError, ValueError):
        h = math.nan
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
        try:
            t = np.asarray(times, dtype=float)
        except (TypeError, ValueError):
            t = np.empty((0, 0))
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
class PreloadStep(Outcome):
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
    status : str
        ``"feasible"`` or ``"infeasible"`` (:attr:`STATUSES`, from ``feasible``).
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "feasible": "rest lengths meeting every requirement were found: the tip on the target, stable with the "
                    "margin, inside the bounds and the rate limit",
        "infeasible": "no admissible rest lengths put the tip on the target: the command is the held value "
                      "(on_infeasible hold) or the nearest admissible pose's rest lengths (approach); q, tip, "
                      "margin and energy describe the arm under the command, proposal and proposal_tip the "
                      "nearest admissible pose",
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

    @property
    def status(self) -> str:
        return "feasible" if self.feasible else "infeasible"

    def to_dict(self) -> dict[str, Any]:
        """JSON form: ``success``, ``status``, ``message``, ``command``, ``proposal``, ``q``, ``tip``, ``end_angle``,
        ``margin`` and ``energy`` (null: no equilibrium), ``tip_error``, ``proposal_tip``, ``feasible``, ``method``,
        ``solver`` ``{status, iterations}``, ``residual`` (null: not a Newton step), ``target``."""
        return {**self.outcome(), "command": [numbers(r) for r in self.command],
                "proposal": [numbers(r) for r in self.proposal], "q": numbers(self.q), "tip": numbers(self.tip),
                "end_angle": number(self.end_angle), "margin": nullable(self.margin),
                "energy": nullable(self.energy), "tip_error": number(self.tip_error),
                "proposal_tip": numbers(self.proposal_tip), "feasible": self.feasible, "method": self.method,
                "solver": self.solver.to_dict(), "residual": None if self.residual is None else nullable(self.residual),
                "target": numbers(self.target)}


@dataclass(frozen=True)
class _Pose:
    """A candidate state of the arm: rest lengths (segment-major 2n), its configuration, tip, margin, energy."""

    ell: np.ndarray
    q: np.ndarray
    tip: np.ndarray
    margin: float
    energy: float
    solver: SolverInfo


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
    """

    def __init__(self, m: Manipulator, start=None, *, rest_lengths0=None, load=(0.0, 0.0), bounds=None,
                 rate_limit=None, dt: float | None = None, margin: float = 1e-3, objective: str = "change",
                 weights=None, on_infeasible: str = "hold") -> None:
        if not isinstance(m, Manipulator):
            raise InvalidParameterError("m must be a Manipulator", field="m")
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
        self.m, self.n, self.objective, self.margin = m, n, objective, float(margin)
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
        except NoEquilibriumError as exc:
            raise NoEquilibriumError(f"no equilibrium under the load from the rest configuration: {exc.message}; "
                                     "give a start", field="load") from None
        if not eq.stable:
            raise InvalidParameterError("the equilibrium under the load reached from the rest configuration is "
                                        "unstable: give a stable start", field="load")
        return eq.q.copy()

    def manipulator(self, ell: np.ndarray | None = None) -> Manipulator:
        """The chain with rest lengths ``ell`` (segment-major 2n; default the current ones)."""
        ell = self.ell if ell is None else ell
        return Manipulator(s.replace(L0=(float(ell[2 * i]), float(ell[2 * i + 1])))
                           for i, s in enumerate(self.m.segments))

    # ------------------------------------------------------------------ one step
    def step(self, target, load=None, end_angle: float | None = None, *, dt: float | None = None) -> PreloadStep:
        """Rest lengths for the tip at ``target = (x, y)`` (and the last link at ``end_angle``, rad) under
        ``load`` (default the controller's), from the current state, ``dt`` seconds after the last step (default
        the controller's ``dt``; needed with a rate limit: each rest length moves by at most ``rate_limit * dt``);
        the state moves to the arm's equilibrium under the step's command (module docstring)."""
        target = checked_vector(target, 2, "target")
        F = self.load if load is None else checked_vector(load, 2, "load")
        if end_angle is not None and not math.isfinite(float(end_angle)):
            raise InvalidParameterError("end_angle must be finite", field="end_angle")
        lo, hi = self.box(dt)
        res = None
        if self.objective == "change":
            res = self._newton(target, F, end_angle, lo, hi)
        if res is None:
            res = self._ipopt(target, F, end_angle, lo, hi)
        if isinstance(res, TensegrityError):
            res = self._infeasible(target, F, end_angle, lo, hi, res)
        if res.method != "none":
            self.ell = res.command.ravel().copy()
        if res.method in ("ipopt", "nearest"):
            self.mu.clear()                 # the multipliers of the least-change problem start again
        if math.isfinite(res.energy):       # the state is an equilibrium under F
            self.q, self.state_load = res.q.copy(), F.copy()
        self.last = res
        return res

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
        kk = np.linalg.eigvalsh(KKT)
        if int(np.sum(kk > 0)) != 3 * n or int(np.sum(kk < 0)) != inv.rows:
            return None                     # a KKT point that is not a local minimum of the least change
        self.mu[angle] = y[at["mu"]].copy()
        solver = _NEWTON.get(iters) or _NEWTON.setdefault(iters, SolverInfo("Newton_Converged", iters))
        # q and ell are views of the step's own iterate y: no copy needed before they turn read-only
        command = ell.reshape(n, 2)
        return PreloadStep._of(command=command, proposal=command, q=q, tip=tip, end_angle=float(np.sum(q)),
                               margin=margin, energy=E, tip_error=_distance(tip, target), proposal_tip=tip,
                               feasible=True, method="newton", solver=solver, residual=resid, target=target.copy(),
                               message="the least-change Newton step converged")

    def _springs(self, v: np.ndarray) -> np.ndarray:
        """Segment-major 2n -> the design problems' ``L10``, ``L20`` blocks."""
        return rest_lengths(self.n).pack(L10=v[0::2], L20=v[1::2])

    def _ipopt(self, target, F, end_angle, lo, hi) -> PreloadStep | TensegrityError:
        """IPOPT's step (:func:`preloads_for_pose`), or the error saying why it found none."""
        nominal = self.manipulator()
        try:
            d = preloads_for_pose(nominal, target, load=F, objective=self.objective, margin=self.margin,
                                  bounds=(self._springs(lo), self._springs(hi)), end_angle=end_angle, start=self.q)
        except TimeLimitError:
            raise
        except TensegrityError as exc:
            return exc
        q = d.q
        command = d.preloads.copy()
        return PreloadStep._of(command=command, proposal=command, q=q.copy(), tip=d.tip.copy(),
                               end_angle=float(np.sum(q)), margin=float(d.margin), energy=float(d.energy),
                               tip_error=_distance(d.tip, target), proposal_tip=d.tip.copy(), feasible=True,
                               method="ipopt", solver=d.solver, residual=None, target=target.copy(),
                               message=f"IPOPT ({self.objective}) converged, verified by the forward solve")

    # ------------------------------------------------------------------ infeasible steps
    def _infeasible(self, target, F, end_angle, lo, hi, exc: TensegrityError) -> PreloadStep:
        """An infeasible step: the nearest admissible pose (the proposal; the command with ``"approach"``, or
        the target itself where it reaches it) and the held state."""
        n = self.n
        held = self.hold(F)
        best = getattr(exc, "best", None)
        near = self.nearest(target, F, end_angle, lo, hi, best=best if isinstance(best, dict) else None, held=held)
        solver = SolverInfo(str(exc.status) if exc.status else "none", 0)
        reaches = near is not None and _distance(near.tip, target) <= LAND_TOL * self.scale and (
            end_angle is None or abs(float(np.sum(near.q)) - float(end_angle)) <= 1e-6)
        if reaches or (near is not None and self.on_infeasible == "approach"):
            command = near.ell.reshape(n, 2).copy()
            message = ("the nearest admissible pose reaches the target (the step's own solve failed: "
                       f"{exc.message}), verified by the forward solve") if reaches else \
                (f"{exc.message}; approaching: the nearest admissible pose, {_distance(near.tip, target):.6g} from "
                 "the target")
            return PreloadStep._of(command=command, proposal=command, q=near.q, tip=near.tip,
                                   end_angle=float(np.sum(near.q)), margin=near.margin, energy=near.energy,
                                   tip_error=_distance(near.tip, target), proposal_tip=near.tip, feasible=reaches,
                                   method="nearest", solver=near.solver, residual=None, target=target.copy(),
                                   message=message)
        prop = near if near is not None else held
        why = ("" if near is not None else "; no admissible pose found, the proposal is the held value")
        return PreloadStep._of(command=self.ell.reshape(n, 2).copy(), proposal=prop.ell.reshape(n, 2).copy(),
                               q=held.q, tip=held.tip, end_angle=float(np.sum(held.q)), margin=held.margin,
                               energy=held.energy, tip_error=_distance(held.tip, target), proposal_tip=prop.tip,
                               feasible=False, method="none", solver=solver, residual=None, target=target.copy(),
                               message=f"{exc.message}; holding the previous command{why}")

    def hold(self, F) -> _Pose:
        """The arm's state with the current command under the load ``F``: the current state when ``F`` is its
        load, else the forward equilibrium from it (NaN margin and energy when there is none)."""
        F = checked_vector(F, 2, "load")
        if np.array_equal(F, self.state_load):
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
        m = self.manipulator(ell)
        E, _, _, _, _ = chain_solver(m).evaluate(q, F)
        q = np.array(q, dtype=float)
        ell = np.array(ell, dtype=float)
        tip = m.tip(q)
        for v in (q, ell, tip):
            v.setflags(write=False)
        return _Pose(ell, q, tip, stability_margin(m, q, F), float(E), solver)

    def _forward(self, ell: np.ndarray, F: np.ndarray, q_from: np.ndarray) -> Equilibrium | None:
        """The forward quasi-static solve: the equilibrium with rest lengths ``ell`` under ``F`` reached from
        ``q_from`` (Newton; IPOPT's descent where Newton does not settle), or None."""
        m = self.manipulator(ell)
        eq = settle_under_force(m, F, q_from)
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
        margin held). ``held`` (:meth:`hold`) is a candidate itself. None: no admissible pose found."""
        target = checked_vector(target, 2, "target")
        F = checked_vector(F, 2, "load")
        if lo is None or hi is None:
            lo, hi = self.box()
        springs = rest_lengths(self.n)
        nominal = self.manipulator()
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
            eq = settle_under_force(self.manipulator(ell0), F, self.q)
            starts.append((self.q if eq is None else eq.q, self._springs(ell0)))
        candidates: list[_Pose] = []
        if held is not None and math.isfinite(held.margin) and held.margin >= self.margin - 1e-9:
            candidates.append(held)
        for q0, ell0 in starts:
            q0 = np.clip(q0, -self.limits * 0.999, self.limits * 0.999)
            res, q, L10, L20, _, _ = solve_pose_nlp(nominal, target, F, "change", self.margin, False, lo_s, hi_s,
                                                    end_angle, q0, ell0, nearest=True)
            ell = np.column_stack([L10, L20]).ravel()
            eq = self._forward(ell, F, self.q)
            if eq is None or not eq.stable or float(np.max(np.abs(eq.q - q))) > 1e-6:
                continue                    # the arm does not get there from here (another well, or none)
            pose = self._pose(ell, eq.q, F, SolverInfo(res.status, res.iterations))
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
class PreloadPlan(Outcome):
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
        The forward quasi-static solve from the previous step's configuration with this step's command lands on
        the step's pose (``LAND_TOL max b`` on the tip, 1e-6 on the joint angles; on the target for a feasible
        step), stable (False everywhere with ``verify=False``: not checked).
    method : tuple of str
        Per step (:data:`METHODS`) ``"newton"``, ``"ipopt"``, ``"nearest"`` or ``"none"`` (held).
    status : str
        ``"complete"``, ``"infeasible_steps"`` (some steps infeasible: see ``feasible``; approach steps that did
        not reach the target count), ``"time_limit"`` (the steps done so far) (:attr:`STATUSES`).
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

    def __post_init__(self) -> None:
        if self.times is None:
            object.__setattr__(self, "times", np.full(len(self.steps), math.nan))
        freeze(self, copy=False)

    @property
    def message(self) -> str:
        """A sentence: how many steps, feasible and verified."""
        K = len(self.steps)
        done = f"{K} step(s), {int(np.sum(self.feasible))} feasible, {int(np.sum(self.verified))} verified"
        if self.status == "time_limit":
            return f"the time limit ran out after {done}"
        return done

    def to_dict(self) -> dict[str, Any]:
        """JSON form: ``success``, ``status``, ``message``, ``seconds``, the per-step arrays (``commands``,
        ``proposals``, ``q``, ``tip``, ``tip_error``, ``end_angle``, ``margin`` (null: no equilibrium),
        ``feasible``, ``verified``, ``method``), ``targets``, ``times`` (null: no time base), ``margin_required``,
        ``objective``, ``on_infeasible``, ``horizon`` and ``steps`` (:meth:`PreloadStep.to_dict`)."""
        return {**self.outcome(), "seconds": number(self.seconds),
                "commands": [[numbers(r) for r in s] for s in self.commands],
                "proposals": [[numbers(r) for r in s] for s in self.proposals],
                "q": [numbers(r) for r in self.q], "tip": [numbers(r) for r in self.tip],
                "tip_error": numbers(self.tip_error), "end_angle": numbers(self.end_angle),
                "margin": [nullable(v) for v in self.margin], "feasible": [bool(v) for v in self.feasible],
                "verified": [bool(v) for v in self.verified], "method": list(self.method),
                "targets": [numbers(r) for r in self.targets], "times": [nullable(t) for t in self.times],
                "margin_required": number(self.margin_required), "objective": self.objective,
                "on_infeasible": self.on_infeasible, "horizon": self.horizon,
                "steps": [s.to_dict() for s in self.steps]}


def plan_preloads(m: Manipulator, targets, *, loads=None, end_angles=None, times=None, dt: float | None = None,
                  rest_lengths0=None, bounds=None, rate_limit=None, margin: float = 1e-3, objective: str = "change",
                  weights=None, start=None, on_infeasible: str = "hold", horizon: int | str | None = None,
                  verify: bool = True, timeout: float | None = None,
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
        Verify every step by the forward quasi-static solve (default).
    timeout : float, optional
        Seconds; on expiry the steps done are returned with ``status="time_limit"``.
    progress : callable(done, total), optional
        Called after each step with the steps done and ``K``.

    Returns
    -------
    PreloadPlan
    """
    T = np.asarray(targets, dtype=float)
    if T.ndim != 2 or T.shape[1] != 2 or T.shape[0] < 1 or not np.all(np.isfinite(T)):
        raise InvalidParameterError("targets must be K >= 1 finite tip positions (x, y)", field="targets")
    K = T.shape[0]
    if loads is None:
        Ls = np.zeros((K, 2))
    else:
        Ls = np.asarray(loads, dtype=float)
        Ls = np.broadcast_to(Ls, (K, 2)).copy() if Ls.shape in ((2,), (1, 2)) else Ls
        if Ls.shape != (K, 2) or not np.all(np.isfinite(Ls)):
            raise InvalidParameterError(f"loads must be one (fx, fy) or {K} of them, finite", field="loads")
    A = None
    if end_angles is not None:
        A = np.asarray(end_angles, dtype=float).ravel()
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
    ctl = PreloadController(m, start, rest_lengths0=rest_lengths0, load=Ls[0], bounds=bounds, rate_limit=rate_limit,
                            margin=margin, objective=objective, weights=weights, on_infeasible=on_infeasible)
    t0 = time.perf_counter()
    steps: list[PreloadStep] = []
    verified: list[bool] = []
    status = "complete"
    with time_limit(timeout):
        if horizon is not None:
            from .horizon import horizon_steps

            done: list[tuple[PreloadStep, bool]] = []
            try:
                horizon_steps(ctl, T, Ls, A, h_steps, horizon, done, PreloadStep._of, verify=verify,
                              progress=progress)
            except TimeLimitError:
                status = "time_limit"
            steps = [st for st, _ in done]
            verified = [v for _, v in done]
        for k in range(K if horizon is None else 0):
            if expired():
                status = "time_limit"
                break
            q_prev = ctl.q.copy()
            try:
                st = ctl.step(T[k], Ls[k], None if A is None or math.isnan(A[k]) else float(A[k]),
                              dt=None if math.isnan(h_steps[k]) else float(h_steps[k]))
            except TimeLimitError:
                status = "time_limit"
                break
            steps.append(st)
            verified.append(bool(verify) and _lands(ctl, st, Ls[k], q_prev))
            if progress is not None:
                progress(k + 1, K)
    n = m.n
    if status == "complete" and not all(s.feasible for s in steps):
        status = "infeasible_steps"
    P = len(steps)

    def arr(get, shape):
        return np.array([get(s) for s in steps], dtype=float).reshape((P, *shape))

    return PreloadPlan(commands=arr(lambda s: s.command, (n, 2)), proposals=arr(lambda s: s.proposal, (n, 2)),
                       q=arr(lambda s: s.q, (n,)), tip=arr(lambda s: s.tip, (2,)),
                       tip_error=arr(lambda s: s.tip_error, ()), end_angle=arr(lambda s: s.end_angle, ()),
                       margin=arr(lambda s: s.margin, ()), feasible=np.array([s.feasible for s in steps], dtype=bool),
                       verified=np.array(verified, dtype=bool), method=tuple(s.method for s in steps), status=status,
                       steps=tuple(steps), seconds=time.perf_counter() - t0, targets=T[:P].copy(),
                       margin_required=float(margin), objective=objective, times=t_steps[:P].copy(),
                       on_infeasible=on_infeasible, horizon=horizon)


def _lands(ctl: PreloadController, st: PreloadStep, F: np.ndarray, q_prev: np.ndarray) -> bool:
    """The forward quasi-static solve from the previous configuration with the step's command lands on the
    step's pose (on the target for a feasible step), stable."""
    try:
        eq = ctl._forward(st.command.ravel(), F, q_prev)
    except TimeLimitError:
        return False                # out of time: not verified (the plan stops before its next step)
    if eq is None:
        return False
    tol = LAND_TOL * ctl.scale
    return bool(eq.stable) and float(np.max(np.abs(eq.tip - st.tip))) <= tol \
        and float(np.max(np.abs(eq.q - st.q))) <= 1e-6 \
        and (not st.feasible or float(np.max(np.abs(eq.tip - st.target))) <= tol)
