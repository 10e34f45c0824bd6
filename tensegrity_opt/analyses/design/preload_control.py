"""Control in actuation space: the springs' rest lengths for tip poses over time (inverse statics).

The control inputs of the arm are the rest lengths ``(L1_0, L2_0)`` of its ``2 n`` springs; a tip pose is
2 numbers (``x, y``) or 3 (with the last link's absolute angle): the inputs are redundant. A step asks
for rest lengths putting the tip at the target, stable, under a dead tip load, close to the previous
step's (no snap between steps: the configuration moves continuously on one branch), inside the actuator
bounds and a per-step rate limit, with a stability margin (the smallest eigenvalue of the Hessian of
``E - F . tip`` in the joint angles, torque per radian).

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

__all__ = ["PreloadController", "PreloadStep", "PreloadPlan", "plan_preloads"]

#: KKT residual (max-norm, force and length units) below which the Newton step has converged.
NEWTON_TOL = 1e-10
#: Weight of ``|q - q_prev|^2`` in the least-change objective (regularises the joint angles' null space).
Q_WEIGHT = 1e-8
#: The solver detail of a Newton step, per iteration count (immutable, so shared).
_NEWTON: dict[int, SolverInfo] = {}


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
        Geometry and stiffness (kept); its rest lengths are the start's. ``2 <= n <= KERNEL_MAX`` for the
        compiled Newton step (longer chains: CasADi's virtual machine, slower).
    start : Equilibrium or array_like (n,), optional
        The configuration with ``m``'s rest lengths under ``load``; default the equilibrium under ``load``
        reached from the least-energy rest configuration.
    load : (fx, fy)
        The dead tip load (each step may give its own).
    bounds : (lo, hi), optional
        Actuator bounds on every rest length (numbers, or ``2 n`` values ``L1_0`` of every segment then
        ``L2_0``); default ``(0.1 b_min, 4 b_max)``.
    rate_limit : float or array_like, optional
        Largest change of each rest length per step (length units).
    margin : float
        Required stability margin (>= 0).
    objective : {"change", "margin", "energy"}
    weights : array_like (n, 2), optional
        Weights of each rest length's change in the least-change objective (default 1).
    """

    def __init__(self, m: Manipulator, start=None, *, load=(0.0, 0.0), bounds=None, rate_limit=None,
                 margin: float = 1e-3, objective: str = "change", weights=None) -> None:
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
        self.w = np.ones(2 * n) if weights is None else self._per_spring_pairs(weights, "weights")
        if not np.all(self.w > 0):
            raise InvalidParameterError("weights must be > 0", field="weights")
        self.geo = step_layouts(n, False).geometry.pack(a=m.a, b=m.b, k1=m.k1, k2=m.k2)
        self.limits = m.joint_limits
        self.scale = float(np.max(m.b))
        self.ell = np.column_stack([m.L1_0, m.L2_0]).ravel()        # segment-major: l[2i], l[2i+1]
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

    def _start(self, start) -> np.ndarray:
        if isinstance(start, Equilibrium):
            return start.q.copy()
        if start is not None:
            try:
                q = check_q0(self.m, start)
            except InvalidParameterError as exc:
                raise InvalidParameterError(exc.message.replace("q0", "start"), field="start") from None
            if q is None:
                raise InvalidParameterError("start must be an Equilibrium or n joint angles", field="start")
            return q
        try:
            eq = loaded_rest(self.m, self.load)
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
    def step(self, target, load=None, end_angle: float | None = None) -> PreloadStep:
        """Rest lengths for the tip at ``target = (x, y)`` (and the last link at ``end_angle``, rad) under
        ``load`` (default the controller's), from the current state; the state moves there when the step
        is feasible."""
        target = checked_vector(target, 2, "target")
        F = self.load if load is None else checked_vector(load, 2, "load")
        if end_angle is not None and not math.isfinite(float(end_angle)):
            raise InvalidParameterError("end_angle must be finite", field="end_angle")
        lo, hi = self.lo, self.hi
        if self.rate is not None:
            lo, hi = np.maximum(lo, self.ell - self.rate), np.minimum(hi, self.ell + self.rate)
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

    def __post_init__(self) -> None:
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
        ``targets``, ``margin_required``, ``objective`` and ``steps`` (:meth:`PreloadStep.to_dict`)."""
        return {**self.outcome(), "seconds": number(self.seconds),
                "rest_lengths": [[numbers(r) for r in s] for s in self.rest_lengths],
                "q": [numbers(r) for r in self.q], "tip": [numbers(r) for r in self.tip],
                "end_angle": numbers(self.end_angle), "margin": [nullable(v) for v in self.margin],
                "feasible": [bool(v) for v in self.feasible], "verified": [bool(v) for v in self.verified],
                "method": list(self.method), "targets": [numbers(r) for r in self.targets],
                "margin_required": number(self.margin_required), "objective": self.objective,
                "steps": [s.to_dict() for s in self.steps]}


def plan_preloads(m: Manipulator, targets, *, loads=None, end_angles=None, bounds=None, rate_limit=None,
                            margin: float = 1e-3, objective: str = "change", weights=None, start=None,
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
    bounds, rate_limit, margin, objective, weights, start
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
    ctl = PreloadController(m, start, load=Ls[0], bounds=bounds, rate_limit=rate_limit, margin=margin,
                            objective=objective, weights=weights)
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
                st = ctl.step(T[k], Ls[k], None if A is None or math.isnan(A[k]) else float(A[k]))
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
                       margin_required=float(margin), objective=objective)


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
