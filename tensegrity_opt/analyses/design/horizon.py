"""A horizon planner: the springs' rest lengths for several steps of a trajectory at once, as one CasADi NLP.

The step-by-step controller (:mod:`.preload_control`) answers each step alone: it cannot start moving a slow
actuator before a step that needs it (a load arriving, a jump of the target), and such a step goes infeasible.
:func:`plan_horizon` plans ``N`` steps together (:class:`tensegrity_opt.numerics.horizon_nlp.HorizonNLP`: the
equilibrium of every step, the joint range, the actuator bounds, the stability margin in Cholesky form and the
rate box between consecutive steps as constraints; the pose error and the actuators' motion in the objective):

* ``horizon=N`` (a positive int): **receding horizon**. At step ``j`` the steps ``j .. j+N-1`` are solved (past
  the end of the trajectory its last target and load repeat), the first is applied, and the next solve starts
  from this solution shifted by one step (warm); the first solve starts from the current state.
* ``horizon="all"``: the whole trajectory as one NLP, solved once from the current state.

The pose error is soft by default (``tracking="soft"``): an exact penalty (a first power plus a square, see the
numerics module), so a reachable target is met exactly while an out-of-reach stretch still has a solution that
moves toward the targets as fast as the bounds, rates and margin allow and catches up when it can;
``tracking="exact"`` makes every pose a constraint (one unreachable target in the horizon then leaves the whole
solve without a solution).

Every step is applied only when it is safe: its solve converged (IPOPT's return status is reported per step), the
command lies inside the rate box of the command actually applied before it, and the forward quasi-static solve
(:func:`~tensegrity_opt.analyses.equilibria.equilibrium.settle_under_force`, IPOPT's descent where Newton does not
settle) from the previous configuration with the step's rest lengths lands on the step's planned pose, stable.
Otherwise the step **holds** the previous command (``adopted`` False; ``q``, ``tip`` are then where the arm goes
under it and the step's load) and the next solve starts from that state.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ...errors import InvalidParameterError, TensegrityError, TimeLimitError
from ...model.manipulator import Manipulator
from ...numerics import RANGE_SHRINK, chain_solver
from ...numerics.layout import rest_lengths
from ...outcome import Outcome, SolverInfo, freeze
from ...timelimit import expired, time_limit
from ..equilibria.equilibrium import Equilibrium, settle_under_force, solve_equilibrium_under_force
from .follower import loaded_rest
from .preloads import LAND_TOL, checked_start, rest_length_bounds, spring_bounds, stability_margin

__all__ = ["HorizonPlan", "plan_horizon", "HORIZONS", "TRACKING", "TIP_WEIGHTS"]

#: The ``horizon`` vocabulary besides a positive int ``N`` (receding): ``"all"``, the whole trajectory at once.
HORIZONS = ("all",)
#: How the pose enters the horizon problem: ``"soft"`` (an exact penalty) or ``"exact"`` (constraints).
TRACKING = ("soft", "exact")
#: The pose error's weights ``(square, first power)`` in the objective, relative to the motion's weight 1 (all
#: lengths divided by ``max b``): the first power makes the penalty exact (a reachable target is met).
TIP_WEIGHTS = (100.0, 100.0)
#: Joint angles (rad) within which the forward solve must land on the planned configuration.
SAME_POSE = 1e-6
#: How far (times ``max b``) beyond its rate box a converged solve's command may lie: it is clipped into the box.
RATE_TOL = 1e-7
_INF = math.inf


@dataclass(frozen=True)
class HorizonPlan(Outcome):
    """The result of :func:`plan_horizon` (``K`` steps done), per step ``k``.

    Attributes
    ----------
    commands : ndarray (K, n, 2)
        ``L1_0, L2_0`` per segment: what to send (on a held step, the held value).
    proposals : ndarray (K, n, 2)
        The planned rest lengths (equal to ``commands`` on an adopted step; NaN where no solve converged).
    q : ndarray (K, n)
        The arm's equilibrium under the command (relative joint angles, rad).
    tip : ndarray (K, 2)
    tip_error : ndarray (K,)
        ``|tip - target|``.
    end_angle, margin, energy : ndarray (K,)
        The last link's absolute angle, the stability margin (smallest eigenvalue of the Hessian of
        ``E - F . tip`` in the joint angles, torque / rad; recomputed at ``q``) and the spring energy.
    adopted : ndarray (K,) of bool
        The step's solve converged and its command was applied (else the step held the previous command).
    verified : ndarray (K,) of bool
        The forward quasi-static solve from the previous configuration with the command landed on the planned
        pose, stable (False everywhere with ``verify=False``: not checked).
    on_target : ndarray (K,) of bool
        ``tip_error <= LAND_TOL max b`` (and the end angle, when given, within ``LAND_TOL``).
    solver : tuple of SolverInfo
        The status and iterations of the IPOPT solve that planned each step (``"none"``: no solve).
    targets : ndarray (K, 2)
    horizon : int or str
        ``N`` or ``"all"``.
    solves : int
        IPOPT solves run (a receding plan: one per step, plus the cold retries).
    seconds : float
    status : str
        :attr:`STATUSES`.
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "complete": "every step was adopted, verified where asked, and on its target",
        "off_target": "every step was adopted, some off their targets: out of reach within the bounds, rates and "
                      "margin (the plan moves toward them as fast as allowed)",
        "held_steps": "some steps held the previous command (their solve did not converge, or the forward solve did "
                      "not land on the plan): see adopted and solver",
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
    energy: np.ndarray
    adopted: np.ndarray
    verified: np.ndarray
    on_target: np.ndarray
    solver: tuple[SolverInfo, ...]
    targets: np.ndarray
    horizon: int | str
    solves: int
    seconds: float
    status: str
    margin_required: float = 0.0
    tracking: str = "soft"

    def __post_init__(self) -> None:
        freeze(self, copy=False)

    @property
    def feasible(self) -> np.ndarray:
        """Per step: adopted and on target (what the step-by-step controller calls a feasible step)."""
        return self.adopted & self.on_target

    @property
    def message(self) -> str:
        """A sentence: how many steps, adopted, on target and verified."""
        K = len(self.solver)
        done = (f"{K} step(s) planned with horizon {self.horizon}: {int(self.adopted.sum())} adopted, "
                f"{int(self.on_target.sum())} on target, {int(self.verified.sum())} verified, largest tip error "
                f"{float(np.max(self.tip_error, initial=0.0)):.3g}")
        if self.status == "time_limit":
            return f"the time limit ran out after {done}"
        return done


def plan_horizon(m: Manipulator, targets, *, horizon: int | str, loads=None, end_angles=None, rest_lengths0=None,
                 bounds=None, rate=None, margin: float = 1e-3, weights=None, start=None, tracking: str = "soft",
                 taut: bool = False, verify: bool = True, timeout: float | None = None) -> HorizonPlan:
    """Rest lengths for a trajectory of tip poses, planned over a horizon (module docstring).

    Parameters
    ----------
    m : Manipulator
        Geometry and stiffness (kept); its rest lengths are the current ones unless ``rest_lengths0`` is given.
    targets : array_like (K, 2)
        Tip positions ``(x, y)`` per step.
    horizon : int or "all"
        ``N >= 1`` steps solved at each step (receding), or ``"all"`` (the whole trajectory in one NLP).
    loads : array_like (2,) or (K, 2), optional
        Dead tip loads per step (default none).
    end_angles : array_like (K,), optional
        The last link's absolute angle per step (rad); NaN leaves a step's angle free.
    rest_lengths0 : array_like (n, 2), optional
        The arm's current rest lengths ``(L1_0, L2_0)`` per segment: the first step's rate box is measured from
        them (default ``m``'s).
    bounds : (lo, hi), optional
        Actuator bounds (:func:`~.preloads.rest_length_bounds`).
    rate : float or array_like (K,), optional
        The largest change of every rest length at each step (length units; step ``k``'s change is measured from
        step ``k - 1``'s command); default none.
    margin : float
        Required stability margin (torque / rad, absolute: as :func:`~.preloads.preloads_for_pose`).
    weights : array_like (n, 2), optional
        Weights of each rest length's motion in the objective (default 1).
    start : array_like (n,) or Equilibrium, optional
        The current configuration (an equilibrium with ``rest_lengths0`` under the first load); default the one
        reached from the least-energy rest configuration (:func:`~.follower.loaded_rest`).
    tracking : {"soft", "exact"}
        The pose as an exact penalty (default: a solution exists whatever the targets) or as constraints.
    taut : bool
        Keep every spring in tension.
    verify : bool
        Adopt a step only when the forward solve lands on its planned pose (default).
    timeout : float, optional
        Seconds; on expiry the steps done are returned with ``status="time_limit"``.

    Returns
    -------
    HorizonPlan
    """
    from ...numerics.horizon_nlp import horizon_nlp

    if not isinstance(m, Manipulator):
        raise InvalidParameterError("m must be a Manipulator", field="m")
    n = m.n
    if n < 2:
        raise InvalidParameterError("the horizon planner needs a chain of n >= 2 segments", field="n")
    T = np.asarray(targets, dtype=float)
    if T.ndim != 2 or T.shape[1] != 2 or T.shape[0] < 1 or not np.all(np.isfinite(T)):
        raise InvalidParameterError("targets must be K >= 1 finite tip positions (x, y)", field="targets")
    K = T.shape[0]
    if isinstance(horizon, str):
        if horizon not in HORIZONS:
            raise InvalidParameterError(f"horizon must be a positive int or 'all', got {horizon!r}", field="horizon")
        N = K
    elif isinstance(horizon, (int, np.integer)) and not isinstance(horizon, bool) and horizon >= 1:
        N = int(horizon)
    else:
        raise InvalidParameterError(f"horizon must be a positive int or 'all', got {horizon!r}", field="horizon")
    if tracking not in TRACKING:
        raise InvalidParameterError(f"tracking must be one of {TRACKING}, got {tracking!r}", field="tracking")
    if not (isinstance(margin, (int, float)) and math.isfinite(margin) and margin >= 0):
        raise InvalidParameterError(f"margin must be finite and >= 0, got {margin!r}", field="margin")
    Ls = _per_step(loads, K, (2,), "loads", default=0.0)
    A = None
    if end_angles is not None:
        A = np.asarray(end_angles, dtype=float).ravel()
        if A.size != K or np.any(np.isinf(A)):
            raise InvalidParameterError(f"end_angles must be {K} numbers (NaN: free)", field="end_angles")
        if np.all(np.isnan(A)):
            A = None
    R = _per_step(rate, K, (), "rate", default=_INF)
    if np.any(R <= 0):
        raise InvalidParameterError("rate must be > 0", field="rate")
    springs = rest_lengths(n)
    if rest_lengths0 is None:
        ell0 = springs.pack(L10=m.L1_0, L20=m.L2_0)
    else:
        r0 = np.asarray(rest_lengths0, dtype=float)
        if r0.shape != (n, 2) or not np.all(np.isfinite(r0)) or not np.all(r0 > 0):
            raise InvalidParameterError(f"rest_lengths0 must be {n} pairs of positive numbers", field="rest_lengths0")
        ell0 = springs.pack(L10=r0[:, 0], L20=r0[:, 1])
    v = np.ones(2 * n)
    if weights is not None:
        wa = np.asarray(weights, dtype=float)
        if wa.shape != (n, 2) or not np.all(np.isfinite(wa)) or not np.all(wa > 0):
            raise InvalidParameterError(f"weights must be {n} pairs of positive numbers", field="weights")
        v = springs.pack(L10=wa[:, 0], L20=wa[:, 1])
    lo, hi = rest_length_bounds(m, bounds)
    lo2, hi2 = spring_bounds(n, lo, hi)
    plan = _Planner(m, T, Ls, A, R, ell0, v, springs.pack(**lo2), springs.pack(**hi2), float(margin), tracking,
                    bool(taut), bool(verify), horizon_nlp(n, N, A is not None))
    plan.q = plan.start(start)
    return plan.run(horizon if isinstance(horizon, str) else N, timeout)


def _per_step(value, K: int, shape: tuple, name: str, default: float) -> np.ndarray:
    """``value`` given once (``shape``) or per step (``(K, *shape)``), finite, as ``(K, *shape)``."""
    if value is None:
        return np.full((K, *shape), default)
    a = np.asarray(value, dtype=float)
    if a.shape == shape or a.shape == (1, *shape):
        a = np.broadcast_to(a.reshape(shape), (K, *shape)).copy()
    if a.shape != (K, *shape) or not np.all(np.isfinite(a)):
        what = "one number" if shape == () else f"one {shape} value"
        raise InvalidParameterError(f"{name} must be {what} or {K} of them, finite", field=name)
    return a


@dataclass
class _Step:
    command: np.ndarray
    proposal: np.ndarray
    eq_q: np.ndarray
    adopted: bool
    verified: bool
    solver: SolverInfo


class _Planner:
    """One plan's state: the current command and configuration, the last solution (for the warm start)."""

    def __init__(self, m, T, Ls, A, R, ell0, v, lo, hi, margin, tracking, taut, verify, nlp) -> None:
        self.m, self.T, self.Ls, self.A, self.R = m, T, Ls, A, R
        self.ell, self.v, self.lo, self.hi = ell0.copy(), v, lo, hi
        self.margin, self.tracking, self.taut, self.verify, self.nlp = margin, tracking, taut, verify, nlp
        self.n, self.K, self.N = m.n, T.shape[0], nlp.N
        self.scale = float(np.max(m.b))
        self.limits = m.joint_limits * (1 - RANGE_SHRINK)
        self.solves = 0
        self.q = np.zeros(self.n)

    # ------------------------------------------------------------------ the arm
    def manipulator(self, ell: np.ndarray) -> Manipulator:
        n = self.n
        return Manipulator(s.replace(L0=(float(ell[i]), float(ell[n + i]))) for i, s in enumerate(self.m.segments))

    def start(self, start) -> np.ndarray:
        m0 = self.manipulator(self.ell)
        if isinstance(start, Equilibrium):
            return start.q.copy()
        q = checked_start(m0, start)
        if q is not None:
            return q
        eq = loaded_rest(m0, self.Ls[0])
        if not eq.stable:
            raise InvalidParameterError("the equilibrium under the first load reached from the rest configuration "
                                        "is unstable: give a stable start", field="start")
        return eq.q.copy()

    def forward(self, ell: np.ndarray, F: np.ndarray, q_prev: np.ndarray) -> Equilibrium | None:
        """The forward quasi-static solve: the arm with rest lengths ``ell`` under ``F`` from ``q_prev``."""
        m = self.manipulator(ell)
        eq = settle_under_force(m, F, q_prev)
        if eq is None:
            try:
                eq = solve_equilibrium_under_force(m, *F, q0=q_prev)
            except TimeLimitError:
                raise
            except TensegrityError:
                return None
        return eq

    # ------------------------------------------------------------------ one solve
    def _index(self, j: int) -> np.ndarray:
        """The trajectory's steps of the window starting at ``j`` (its last step repeated past the end)."""
        return np.minimum(np.arange(j, j + self.N), self.K - 1)

    def _cold(self, idx: np.ndarray) -> np.ndarray:
        """A start: the current state at every step of the window."""
        return self._assemble(np.tile(self.q, (self.N, 1)), np.tile(self.ell, (self.N, 1)), idx)

    def _assemble(self, Q: np.ndarray, Ell: np.ndarray, idx: np.ndarray) -> np.ndarray:
        """The variables for configurations ``Q`` (N, n) and rest lengths ``Ell`` (N, 2n): the margin's factors
        and the pose errors computed (floored where a Hessian is below the margin)."""
        from ...numerics.design_nlp import tril_vector

        n, N = self.n, self.N
        Lf, E = [], []
        for k in range(N):
            mk = self.manipulator(Ell[k])
            _, _, Hphi, _, _ = chain_solver(mk).evaluate(Q[k], self.Ls[idx[k]])
            Tm = np.tril(np.ones((n, n)))
            w_, V_ = np.linalg.eigh(Tm.T @ Hphi @ Tm - self.margin * np.eye(n))
            floor = 1e-6 * max(1.0, float(np.abs(w_).max()))
            Lf.append(tril_vector(np.linalg.cholesky(V_ @ np.diag(np.maximum(w_, floor)) @ V_.T)))
            E.append(self._pose(mk, Q[k]) - self._pose_target(idx[k]))
        E = np.nan_to_num(np.array(E))
        x = self.nlp.variables
        return x.pack(phi=np.cumsum(Q, axis=1).ravel(), L10=Ell[:, :n].ravel(), L20=Ell[:, n:].ravel(),
                      L=np.concatenate(Lf), e=E.ravel(), t=(np.abs(E) + 1e-3 * self.scale).ravel())

    def _pose(self, m: Manipulator, q: np.ndarray) -> np.ndarray:
        tip = m.tip(q)
        return np.append(tip, self.scale * float(np.sum(q))) if self.nlp.angles else tip

    def _pose_target(self, k: int) -> np.ndarray:
        if not self.nlp.angles:
            return self.T[k]
        return np.append(self.T[k], self.scale * self.A[k])            # NaN: free

    def _solve(self, j: int, x0: np.ndarray):
        """The window starting at ``j`` from ``x0``: IPOPT's result."""
        nlp, n, N, m = self.nlp, self.n, self.N, self.m
        idx = self._index(j)
        x, g, p = nlp.variables, nlp.constraints, nlp.parameters
        P = np.array([self._pose_target(k) for k in idx])            # (N, d); NaN: a free angle
        free = np.isnan(P)
        soft = self.tracking == "soft"
        e_lo = np.where(free, 0.0, -_INF if soft else 0.0)
        e_hi = np.where(free, 0.0, _INF if soft else 0.0)
        t_hi = np.where(free, 0.0, _INF if soft else 0.0)
        lbx = x.pack(phi=-_INF, L10=np.tile(self.lo[:n], N), L20=np.tile(self.lo[n:], N),
                     L=np.tile(nlp.factor_floor, N), e=e_lo.ravel(), t=0.0)
        ubx = x.pack(phi=_INF, L10=np.tile(self.hi[:n], N), L20=np.tile(self.hi[n:], N), L=_INF, e=e_hi.ravel(),
                     t=t_hi.ravel())
        slack = 0.0 if self.taut else -_INF
        r = np.repeat(self.R[idx], 2 * n)
        lim = np.tile(self.limits, N)
        lbg = g.pack(grad=0.0, psd=0.0, q=-lim, stretch1=slack, stretch2=slack,
                     pose=np.where(free, -_INF, P).ravel(), abs_hi=0.0, abs_lo=0.0, rate=-r)
        ubg = g.pack(grad=0.0, psd=0.0, q=lim, stretch1=_INF, stretch2=_INF, pose=np.where(free, _INF, P).ravel(),
                     abs_hi=_INF, abs_lo=_INF, rate=r)
        w2, w1 = TIP_WEIGHTS
        pv = p.pack(a=m.a, b=m.b, k1=m.k1, k2=m.k2, F=self.Ls[idx].ravel(), ell0=self.ell, v=self.v,
                    w=[w2, w1, 1.0], scale=self.scale, margin=self.margin)
        self.solves += 1
        return nlp.solve(x0, lbx, ubx, lbg, ubg, pv)

    def _split(self, xs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``(Q (N, n), Ell (N, 2n))`` of a solution."""
        n, N = self.n, self.N
        v = self.nlp.variables.unpack(xs)
        phi = v["phi"].reshape(N, n)
        Q = np.diff(np.concatenate([np.zeros((N, 1)), phi], axis=1), axis=1)
        Ell = np.concatenate([v["L10"].reshape(N, n), v["L20"].reshape(N, n)], axis=1)
        return Q, Ell

    # ------------------------------------------------------------------ applying a step
    def apply(self, k: int, plan_q: np.ndarray | None, plan_ell: np.ndarray | None, info: SolverInfo) -> _Step:
        """Step ``k``: adopt the planned command when it is safe (module docstring), else hold."""
        F = self.Ls[k]
        proposal = np.full(2 * self.n, math.nan) if plan_ell is None else np.clip(plan_ell, self.lo, self.hi)
        adopted = verified = False
        eq = None
        if plan_ell is not None:
            # IPOPT holds the rate rows to its (scaled) tolerance: a proposal that far outside is clipped in
            inside = bool(np.all(np.abs(proposal - self.ell) <= self.R[k] * (1 + 1e-6) + RATE_TOL * self.scale))
            if inside:
                command = np.clip(proposal, self.ell - self.R[k], self.ell + self.R[k])
                eq = self.forward(command, F, self.q)
                lands = (eq is not None and bool(eq.stable)
                         and float(np.max(np.abs(eq.q - plan_q))) <= SAME_POSE)
                if lands or not self.verify:
                    adopted, verified = True, bool(lands and self.verify)
                    self.ell = command
        if not adopted:
            eq = self.forward(self.ell, F, self.q)
        q = self.q if eq is None else eq.q
        self.q = q.copy()
        return _Step(self.ell.copy(), proposal, q.copy(), adopted, verified, info)

    # ------------------------------------------------------------------ the plan
    def run(self, horizon: int | str, timeout: float | None) -> HorizonPlan:
        t0 = time.perf_counter()
        steps: list[_Step] = []
        status = None
        with time_limit(timeout):
            try:
                if horizon == "all":
                    self._run_all(steps)
                else:
                    self._run_receding(steps)
            except TimeLimitError:
                status = "time_limit"
        return self._result(steps, horizon, status, time.perf_counter() - t0)

    def _run_all(self, steps: list[_Step]) -> None:
        """One NLP over the steps left; where a step cannot be applied (it holds), the steps after it are planned
        again from the state reached."""
        from ...numerics.horizon_nlp import horizon_nlp

        j = 0
        while j < self.K:
            self.nlp = horizon_nlp(self.n, self.K - j, self.A is not None)
            self.N = self.K - j
            res = self._solve(j, self._cold(self._index(j)))            # from the current state
            info = SolverInfo(res.status, res.iterations)
            Q, Ell = self._split(res.x) if res.success else (None, None)
            first = j
            for k in range(first, self.K):
                if expired():
                    raise TimeLimitError("the horizon plan ran out of time")
                st = self.apply(k, None if Q is None else Q[k - first], None if Ell is None else Ell[k - first], info)
                steps.append(st)
                j = k + 1
                if not st.adopted:
                    break

    def _run_receding(self, steps: list[_Step]) -> None:
        warm = None
        for j in range(self.K):
            if expired():
                raise TimeLimitError("the horizon plan ran out of time")
            idx = self._index(j)
            res = None
            if warm is not None:
                res = self._solve(j, warm)
            if res is None or not res.success:
                res = self._solve(j, self._cold(idx))             # from the current state
            info = SolverInfo(res.status, res.iterations)
            if res.success:
                Q, Ell = self._split(res.x)
                st = self.apply(j, Q[0], Ell[0], info)
            else:
                st = self.apply(j, None, None, info)
            steps.append(st)
            if res.success and st.adopted and self.N > 1:
                # the solution shifted by one step, its last step repeated
                Qs = np.concatenate([Q[1:], Q[-1:]])
                Es = np.concatenate([Ell[1:], Ell[-1:]])
                warm = self._assemble(Qs, Es, self._index(j + 1))
            elif res.success and st.adopted:
                warm = self._assemble(Q, Ell, self._index(j + 1))
            else:
                warm = None

    def _result(self, steps: list[_Step], horizon, status, seconds: float) -> HorizonPlan:
        n, P = self.n, len(steps)
        cmd = np.array([s.command for s in steps]).reshape(P, 2 * n)
        prop = np.array([s.proposal for s in steps]).reshape(P, 2 * n)
        Q = np.array([s.eq_q for s in steps]).reshape(P, n)
        tips, err, ang, mar, ene, on = [], [], [], [], [], []
        for k, s in enumerate(steps):
            mk = self.manipulator(s.command)
            tip = mk.tip(s.eq_q)
            tips.append(tip)
            err.append(float(np.linalg.norm(tip - self.T[k])))
            ang.append(float(np.sum(s.eq_q)))
            mar.append(stability_margin(mk, s.eq_q, self.Ls[k]))
            ene.append(float(mk.energy(s.eq_q)))
            ok = float(np.max(np.abs(tip - self.T[k]))) <= LAND_TOL * self.scale
            if ok and self.A is not None and not math.isnan(self.A[k]):
                ok = abs(ang[-1] - self.A[k]) <= LAND_TOL
            on.append(ok)
        adopted = np.array([s.adopted for s in steps], dtype=bool)
        on_target = np.array(on, dtype=bool)
        if status is None:
            status = "held_steps" if not adopted.all() else "off_target" if not on_target.all() else "complete"
        pairs = lambda a: np.stack([a[:, :n], a[:, n:]], axis=2)          # noqa: E731  (P, 2n) -> (P, n, 2)
        return HorizonPlan(commands=pairs(cmd), proposals=pairs(prop), q=Q, tip=np.array(tips).reshape(P, 2),
                           tip_error=np.array(err), end_angle=np.array(ang), margin=np.array(mar),
                           energy=np.array(ene), adopted=adopted,
                           verified=np.array([s.verified for s in steps], dtype=bool), on_target=on_target,
                           solver=tuple(s.solver for s in steps), targets=self.T[:P].copy(), horizon=horizon,
                           solves=self.solves, seconds=seconds, status=status, margin_required=self.margin,
                           tracking=self.tracking)

