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
3. Where neither finds admissible rest lengths the step is **infeasible**: reported with the best
   reachable pose (the forward equilibrium with the IPOPT's best rest lengths, or the previous state
   when there is none), and the controller stays where it was.

A step's result is the equilibrium itself: ``q``, the rest lengths, the tip and the margin, with
``residual`` the scaled KKT residual; every accepted step is an equilibrium of the chain with those rest
lengths at the target (the residual), stable with the margin. :func:`plan_preloads` runs a controller
over a trajectory and verifies each step by the forward quasi-static solve
(:func:`~tensegrity_opt.analyses.equilibria.equilibrium.solve_equilibrium_under_force` from the previous step's
configuration: it must land on the target, stable).
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from ...bounds import bound_pair
from ...errors import InfeasibleDesignError, InvalidParameterError, NoEquilibriumError, TensegrityError, TimeLimitError
from ...model.manipulator import Manipulator
from ...numerics.inverse_statics import inverse_statics
from ...numerics.inverse_statics import layouts as step_layouts
from ...numerics.layout import rest_lengths
from ...outcome import Outcome, SolverInfo, freeze
from ...serialize import nullable, number, numbers
from ...timelimit import expired, time_limit
from ..equilibria.equilibrium import Equilibrium, check_q0, settle_under_force, solve_equilibrium_under_force
from ..paths.control import checked_vector
from .follower import loaded_rest
from .preloads import LAND_TOL, OBJECTIVES, preloads_for_pose

__all__ = ["PreloadController", "PreloadStep", "PreloadPlan", "plan_preloads", "step_times"]

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
    rest_lengths : ndarray (n, 2)
        ``L1_0, L2_0`` per segment (what to command).
    q : ndarray (n,)
        The equilibrium configuration (relative joint angles, rad).
    tip : ndarray (2,)
    end_angle : float
        The last link's absolute angle ``sum(q)``.
    margin : float
        Smallest eigenvalue of the Hessian of ``E - F . tip`` in ``q`` (torque / rad); NaN for an infeasible
        step (``null`` in :meth:`to_dict`).
    energy : float
        NaN for an infeasible step (``null`` in :meth:`to_dict`).
    feasible : bool
        Rest lengths satisfying every requirement were found (False: ``q``, ``tip`` are the best reachable
        pose, ``rest_lengths`` what reaches it).
    method : str
        ``"newton"`` (the compiled KKT step), ``"ipopt"`` (the fallback or the objective), ``"none"``.
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
        "infeasible": "no admissible rest lengths: q and tip are the best reachable pose (rest_lengths what reaches "
                      "it); the controller stays where it was",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"feasible"})

    rest_lengths: np.ndarray
    q: np.ndarray
    tip: np.ndarray
    end_angle: float
    margin: float
    energy: float
    feasible: bool
    method: str
    solver: SolverInfo
    residual: float | None
    target: np.ndarray
    message: str

    def __post_init__(self) -> None:
        # the controller passes arrays it owns: read-only in place (this is on the control loop's path)
        self.rest_lengths.setflags(write=False)
        self.q.setflags(write=False)
        self.tip.setflags(write=False)
        self.target.setflags(write=False)

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
        """JSON form: ``success``, ``status``, ``message``, ``rest_lengths``, ``q``, ``tip``, ``end_angle``,
        ``margin`` and ``energy`` (null: infeasible), ``feasible``, ``method``, ``solver`` ``{status,
        iterations}``, ``residual`` (null: not a Newton step), ``target``."""
        return {**self.outcome(), "rest_lengths": [numbers(r) for r in self.rest_lengths], "q": numbers(self.q),
                "tip": numbers(self.tip), "end_angle": number(self.end_angle), "margin": nullable(self.margin),
                "energy": nullable(self.energy), "feasible": self.feasible, "method": self.method,
                "solver": self.solver.to_dict(), "residual": None if self.residual is None else nullable(self.residual),
                "target": numbers(self.target)}


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
    """

    def __init__(self, m: Manipulator, start=None, *, rest_lengths0=None, load=(0.0, 0.0), bounds=None,
                 rate_limit=None, dt: float | None = None, margin: float = 1e-3, objective: str = "change",
                 weights=None) -> None:
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
        self.m, self.n, self.objective, self.margin = m, n, objective, float(margin)
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
        the state moves there when the step is feasible."""
        target = checked_vector(target, 2, "target")
        F = self.load if load is None else checked_vector(load, 2, "load")
        if end_angle is not None and not math.isfinite(float(end_angle)):
            raise InvalidParameterError("end_angle must be finite", field="end_angle")
        h = self.dt if dt is None else _seconds(dt, "dt")
        lo, hi = self.lo, self.hi
        if self.rate is not None:
            if h is None:
                raise InvalidParameterError(
                    "rate_limit is a length per second: give the time since the last step, dt (seconds), to the "
                    "step or the controller", field="dt")
            lo, hi = np.maximum(lo, self.ell - self.rate * h), np.minimum(hi, self.ell + self.rate * h)
        res = None
        if self.objective == "change":
            res = self._newton(target, F, end_angle, lo, hi)
        if res is None:
            res = self._ipopt(target, F, end_angle, lo, hi)
        if res.feasible:
            self.q, self.ell = res.q.copy(), res.rest_lengths.ravel().copy()
        self.last = res
        return res

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
        return PreloadStep._of(rest_lengths=ell.reshape(n, 2), q=q, tip=tip, end_angle=float(np.sum(q)),
                               margin=margin, energy=E, feasible=True, method="newton", solver=solver,
                               residual=resid, target=target.copy(), message="the least-change Newton step converged")

    def _ipopt(self, target, F, end_angle, lo, hi) -> PreloadStep:
        nominal = self.manipulator()
        springs = rest_lengths(self.n)
        to_spec = lambda v: springs.pack(L10=v[0::2], L20=v[1::2])   # noqa: E731  segment-major -> the L10, L20 blocks
        try:
            d = preloads_for_pose(nominal, target, load=F, objective=self.objective, margin=self.margin,
                                  bounds=(to_spec(lo), to_spec(hi)), end_angle=end_angle, start=self.q)
        except TimeLimitError:
            raise
        except InfeasibleDesignError as exc:
            return self._best(target, F, exc)
        except TensegrityError as exc:
            return self._best(target, F, exc)
        self.mu.clear()                     # the multipliers of the least-change problem start again
        q = d.q
        return PreloadStep._of(rest_lengths=d.preloads.copy(), q=q.copy(), tip=d.tip.copy(),
                               end_angle=float(np.sum(q)), margin=float(d.margin), energy=float(d.energy),
                               feasible=True, method="ipopt", solver=d.solver, residual=None, target=target.copy(),
                               message=f"IPOPT ({self.objective}) converged, verified by the forward solve")

    def _best(self, target, F, exc: TensegrityError) -> PreloadStep:
        """The best reachable pose of an infeasible step: the forward equilibrium with the IPOPT's best rest
        lengths (when it has them and they hold the arm), else the current state."""
        n = self.n
        best = getattr(exc, "best", None)
        ell, q = self.ell, self.q
        if isinstance(best, dict) and "preloads" in best:
            cand = np.clip(np.asarray(best["preloads"], float).ravel(), self.lo, self.hi)
            try:
                eq = solve_equilibrium_under_force(self.manipulator(cand), *F, q0=self.q)
                if eq.stable:
                    ell, q = cand, eq.q
            except TensegrityError:
                pass
        m = self.manipulator(ell)
        tip = m.tip(q)
        return PreloadStep._of(rest_lengths=ell.reshape(n, 2).copy(), q=q.copy(), tip=tip,
                               end_angle=float(np.sum(q)), margin=math.nan, energy=math.nan, feasible=False,
                               method="none", solver=SolverInfo(str(exc.status) if exc.status else "none", 0),
                               residual=None, target=np.asarray(target, float).copy(), message=exc.message)


@dataclass(frozen=True)
class PreloadPlan(Outcome):
    """The result of :func:`plan_preloads` (``K`` steps done).

    Attributes
    ----------
    rest_lengths : ndarray (K, n, 2)
        ``L1_0, L2_0`` per segment and step.
    q : ndarray (K, n)
    tip : ndarray (K, 2)
    end_angle, margin : ndarray (K,)
    feasible : ndarray (K,) of bool
    verified : ndarray (K,) of bool
        The forward quasi-static solve from the previous step's configuration with this step's rest lengths
        lands on the target (``LAND_TOL max b``), stable (False everywhere with ``verify=False``: not checked).
    method : tuple of str
        Per step ``"newton"``, ``"ipopt"`` or ``"none"``.
    status : str
        ``"complete"``, ``"infeasible_steps"`` (some steps infeasible: see ``feasible``), ``"time_limit"``
        (the steps done so far) (:attr:`STATUSES`).
    steps : tuple of PreloadStep
    seconds : float
    targets : ndarray (K, 2)
        The targets of the steps done.
    margin_required : float
    objective : str
    times : ndarray (K,)
        The steps' instants (s; the start at 0), NaN without a time base (``null`` in :meth:`to_dict`).
    message : str
        The status in a sentence.
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "complete": "every step is feasible",
        "infeasible_steps": "some steps are infeasible (see feasible): each answered with the best reachable pose, "
                            "the next starting from the last feasible state",
        "time_limit": "the time limit ran out: the steps done so far",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"complete"})

    rest_lengths: np.ndarray
    q: np.ndarray
    tip: np.ndarray
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
        """JSON form: ``success``, ``status``, ``message``, ``seconds``, the per-step arrays (``rest_lengths``,
        ``q``, ``tip``, ``end_angle``, ``margin`` (null: infeasible), ``feasible``, ``verified``, ``method``),
        ``targets``, ``times`` (null: no time base), ``margin_required``, ``objective`` and ``steps``
        (:meth:`PreloadStep.to_dict`)."""
        return {**self.outcome(), "seconds": number(self.seconds),
                "rest_lengths": [[numbers(r) for r in s] for s in self.rest_lengths],
                "q": [numbers(r) for r in self.q], "tip": [numbers(r) for r in self.tip],
                "end_angle": numbers(self.end_angle), "margin": [nullable(v) for v in self.margin],
                "feasible": [bool(v) for v in self.feasible], "verified": [bool(v) for v in self.verified],
                "method": list(self.method), "targets": [numbers(r) for r in self.targets],
                "times": [nullable(t) for t in self.times], "margin_required": number(self.margin_required),
                "objective": self.objective,
                "steps": [s.to_dict() for s in self.steps]}


def plan_preloads(m: Manipulator, targets, *, loads=None, end_angles=None, times=None, dt: float | None = None,
                  rest_lengths0=None, bounds=None, rate_limit=None, margin: float = 1e-3, objective: str = "change",
                  weights=None, start=None, verify: bool = True, timeout: float | None = None,
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
    bounds, objective, weights, start
        As :class:`PreloadController`.
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
    ctl = PreloadController(m, start, rest_lengths0=rest_lengths0, load=Ls[0], bounds=bounds, rate_limit=rate_limit,
                            margin=margin, objective=objective, weights=weights)
    t0 = time.perf_counter()
    steps: list[PreloadStep] = []
    verified: list[bool] = []
    status = "complete"
    with time_limit(timeout):
        for k in range(K):
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
            verified.append(bool(verify) and bool(st.feasible) and _lands(ctl, st, Ls[k], q_prev))
            if progress is not None:
                progress(k + 1, K)
    n = m.n
    if status == "complete" and not all(s.feasible for s in steps):
        status = "infeasible_steps"
    P = len(steps)

    def arr(get, shape):
        return np.array([get(s) for s in steps], dtype=float).reshape((P, *shape))

    return PreloadPlan(rest_lengths=arr(lambda s: s.rest_lengths, (n, 2)), q=arr(lambda s: s.q, (n,)),
                       tip=arr(lambda s: s.tip, (2,)), end_angle=arr(lambda s: s.end_angle, ()),
                       margin=arr(lambda s: s.margin, ()), feasible=np.array([s.feasible for s in steps], dtype=bool),
                       verified=np.array(verified, dtype=bool), method=tuple(s.method for s in steps), status=status,
                       steps=tuple(steps), seconds=time.perf_counter() - t0, targets=T[:P].copy(),
                       margin_required=float(margin), objective=objective, times=t_steps[:P].copy())


def _lands(ctl: PreloadController, st: PreloadStep, F: np.ndarray, q_prev: np.ndarray) -> bool:
    """The forward quasi-static solve from the previous configuration with the step's rest lengths lands on
    the target, stable."""
    m = ctl.manipulator(st.rest_lengths.ravel())
    eq = settle_under_force(m, F, q_prev)        # Newton from the previous state; IPOPT's descent if it fails
    if eq is None:
        try:
            eq = solve_equilibrium_under_force(m, *F, q0=q_prev)
        except TensegrityError:
            return False
    return bool(eq.stable) and float(np.max(np.abs(eq.tip - st.target))) <= LAND_TOL * ctl.scale \
        and float(np.max(np.abs(eq.q - st.q))) <= 1e-6
