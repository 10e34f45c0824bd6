"""A horizon planner: the springs' rest lengths for several steps of a trajectory at once, as one CasADi NLP.

The method behind :func:`~.preload_control.plan_preloads` with ``horizon=N`` or ``horizon="all"`` (its result, a
:class:`~.preload_control.PreloadPlan` of :class:`~.preload_control.PreloadStep`, is the step-by-step plan's). The
step-by-step controller (:class:`~.preload_control.PreloadController`) answers each step alone: it cannot start
moving a slow actuator before a step that needs it (a load arriving, a jump of the target), and such a step goes
infeasible. :func:`horizon_steps` plans ``N`` steps together
(:class:`tensegrity_opt.numerics.horizon_nlp.HorizonNLP`: the equilibrium of every step, the joint range, the
actuator bounds, the stability margin in Cholesky form and the rate box between consecutive steps as constraints;
the pose error and the actuators' motion in the objective):

* ``horizon=N`` (a positive int): **receding horizon**. At step ``j`` the steps ``j .. j+N-1`` are solved (past
  the end of the trajectory its last target and load repeat), the first is applied, and the next solve starts
  from this solution and its multipliers shifted by one step (IPOPT's warm start: a few iterations); a window
  solved afresh starts from the step-by-step controller's own steps over it (the shapes the controller would
  take, not their mirror images).
* ``horizon="all"``: the whole trajectory as one NLP.

Every pose error is an exact penalty (a first power plus a square, see the numerics module): a reachable target
is met, an out-of-reach one approached, and one step out of reach does not make the window infeasible; a window
with no solution at all (a step whose load leaves no stable equilibrium) is solved shorter (``N/2, N/4, ...``).

**Never worse than step by step.** A window's first step is taken only where the window is not worse than the
controller's own steps over the same targets from the same state (:meth:`_Planner.worse`: fewer steps on target,
or as many farther in sum), the command lies in the rate box of the command applied before it, its transition is
verified (:meth:`~.preload_control.PreloadController.evaluate`: the arm follows its branch to the planned pose with
the margin), and it is on its target, or -- approaching, where the controller's own answer is off its target too --
no farther from it. Otherwise the step is the controller's own answer from that state
(:meth:`~.preload_control.PreloadController.propose`), and the next window is solved from the state reached;
``plan_preloads`` finally returns the step-by-step plan of the trajectory where that one is better. Under a time
limit a window's solve takes at most half the time left; a window that runs out of it leaves the rest to the
step-by-step controller (the steps get done).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from ...errors import InvalidParameterError, TimeLimitError
from ...model.manipulator import Manipulator
from ...numerics import RANGE_SHRINK, chain_solver
from ...outcome import SolverInfo
from ...timelimit import expired, remaining, time_limit
from .preloads import LAND_TOL

__all__ = ["horizon_steps", "check_horizon", "HORIZONS", "TIP_WEIGHTS"]

#: The ``horizon`` vocabulary besides a positive int ``N`` (receding): ``"all"``, the whole trajectory at once.
HORIZONS = ("all",)
#: The pose error's weights ``(square, first power)`` in the objective, relative to the motion's weight 1 (all
#: lengths divided by ``max b``): the first power makes the penalty exact (a reachable target is met).
TIP_WEIGHTS = (100.0, 100.0)
#: The share of the time left that one window's solve may take under a time limit; a window that runs out of it
#: leaves the rest of the plan to the step-by-step controller (the steps get done before the limit).
WINDOW_SHARE = 0.5
#: How far (times ``max b``) beyond its rate box a converged solve's command may lie: it is clipped into the box.
RATE_TOL = 1e-7
_INF = math.inf




def check_horizon(horizon, field: str = "horizon") -> int | str:
    """``horizon``: a positive int ``N`` or ``"all"`` (:data:`HORIZONS`), else ``InvalidParameterError``."""
    if isinstance(horizon, str) and horizon in HORIZONS:
        return horizon
    if isinstance(horizon, (int, np.integer)) and not isinstance(horizon, bool) and horizon >= 1:
        return int(horizon)
    raise InvalidParameterError(f"horizon must be a positive int or 'all', got {horizon!r}", field=field)


def horizon_steps(ctl: Any, targets: np.ndarray, loads: np.ndarray, end_angles: np.ndarray | None,
                  dts: np.ndarray, horizon: int | str, out: list, *, stop: bool = False,
                  progress: Callable[[int, int], Any] | None = None) -> None:
    """The steps of a trajectory planned over a horizon (module docstring), taken by the controller ``ctl`` and
    appended to ``out`` as they are taken (a :class:`~tensegrity_opt.errors.TimeLimitError` leaves those done).

    ``ctl`` (a :class:`~.preload_control.PreloadController`) carries the validated chain, the state (its
    configuration, command and load), bounds, rate limit (per second), margin, motion weights, ``on_infeasible``
    and ``verify``; ``dts`` the seconds of each step (NaN: no time base, only without a rate limit);
    ``end_angles`` NaN where free (None: none given); ``stop``: end after a step where the arm snapped or had no
    equilibrium. Called by :func:`~.preload_control.plan_preloads`, which checks every argument.
    """
    from ...numerics.horizon_nlp import horizon_nlp

    K, n = targets.shape[0], ctl.n
    N = K if horizon == "all" else min(int(horizon), K)        # a window past the trajectory's end repeats its last
    A = None if end_angles is None or np.all(np.isnan(end_angles)) else end_angles
    block = lambda v: np.asarray(v, float).reshape(n, 2).T.ravel()     # noqa: E731  segment-major -> L10, L20 blocks
    if ctl.rate is None:
        R = np.full((K, 2 * n), _INF)
    else:
        R = np.outer(dts, block(ctl.rate))
    plan = _Planner(ctl, targets, loads, A, R, dts, block(ctl.w), block(ctl.lo), block(ctl.hi),
                    horizon_nlp(n, N, A is not None), out, stop, progress)
    if horizon == "all":
        plan.run_all()
    else:
        plan.run_receding()


class _NoSolve:
    """A window not solved (its share of the time spent): its ``status`` for the steps' solver detail."""

    success = False
    iterations = 0

    def __init__(self, status: str) -> None:
        self.status = status


class _Once:
    """A value computed on the first call and kept (a window's step-by-step rollout, only when it is needed)."""

    def __init__(self, make: Callable[[], Any]) -> None:
        self._make, self._done, self._value = make, False, None

    def __call__(self) -> Any:
        if not self._done:
            self._value, self._done = self._make(), True
        return self._value


class _Stop(Exception):
    """The plan ends (a step where the arm snapped or had no equilibrium, with ``on_snap="stop"``)."""


class _Planner:
    """One plan: the controller (the arm's state: its command and configuration), the last solution (for the warm
    start); the rest lengths in the NLP's order (the ``L1_0`` block, then ``L2_0``)."""

    def __init__(self, ctl, T, Ls, A, R, dts, v, lo, hi, nlp, out, stop, progress) -> None:
        m = ctl.m
        self.ctl = ctl
        self.m, self.T, self.Ls, self.A, self.R, self.dts = m, T, Ls, A, R, dts
        self.v, self.lo, self.hi = v, lo, hi
        self.margin, self.nlp = ctl.margin, nlp
        self.approach = ctl.on_infeasible == "approach"
        self.out, self.stop, self.progress = out, stop, progress
        self.n, self.K, self.N = m.n, T.shape[0], nlp.N
        self.scale = float(np.max(m.b))
        self.limits = m.joint_limits * (1 - RANGE_SHRINK)
        self.out_of_time = False

    # ------------------------------------------------------------------ the arm (the controller's state)
    @property
    def ell(self) -> np.ndarray:
        """The current command in the NLP's order."""
        return np.asarray(self.ctl.ell, float).reshape(self.n, 2).T.ravel()

    @property
    def q(self) -> np.ndarray:
        return self.ctl.q

    def _segment_major(self, ell: np.ndarray) -> np.ndarray:
        return np.column_stack([ell[:self.n], ell[self.n:]]).ravel()

    def manipulator(self, ell: np.ndarray) -> Manipulator:
        """The chain with rest lengths ``ell`` (the L10 block, then L20): the controller's."""
        return self.ctl.manipulator(self._segment_major(ell))

    # ------------------------------------------------------------------ one solve
    def _index(self, j: int, N: int | None = None) -> np.ndarray:
        """The trajectory's steps of the window of ``N`` (default the plan's) starting at ``j`` (its last step
        repeated past the end)."""
        return np.minimum(np.arange(j, j + (self.N if N is None else N)), self.K - 1)

    def _cold(self, idx: np.ndarray, nlp=None) -> np.ndarray:
        """A start: the current state at every step of the window."""
        N = idx.size
        return self._assemble(np.tile(self.q, (N, 1)), np.tile(self.ell, (N, 1)), idx, nlp)

    def _assemble(self, Q: np.ndarray, Ell: np.ndarray, idx: np.ndarray, nlp=None) -> np.ndarray:
        """The variables for configurations ``Q`` (N, n) and rest lengths ``Ell`` (N, 2n): the margin's factors
        and the pose errors computed (floored where a Hessian is below the margin)."""
        from ...numerics.design_nlp import tril_vector

        nlp = self.nlp if nlp is None else nlp
        n, N = self.n, nlp.N
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
        x = nlp.variables
        return x.pack(phi=np.cumsum(Q, axis=1).ravel(), L10=Ell[:, :n].ravel(), L20=Ell[:, n:].ravel(),
                      L=np.concatenate(Lf), e=E.ravel(), t=np.linalg.norm(E, axis=1) + 1e-3 * self.scale)

    def _pose(self, m: Manipulator, q: np.ndarray) -> np.ndarray:
        tip = m.tip(q)
        return np.append(tip, self.scale * float(np.sum(q))) if self.nlp.angles else tip

    def _pose_target(self, k: int) -> np.ndarray:
        if not self.nlp.angles:
            return self.T[k]
        return np.append(self.T[k], self.scale * self.A[k])            # NaN: free

    def _own(self, j: int) -> list:
        """The step-by-step controller's steps over the window from ``j`` (from the current state; the state is
        left as it is): the comparison of :meth:`worse`, and the start of a window solved afresh."""
        ks = list(range(j, min(self.K, j + self.N)))
        return self.ctl.rollout(self.T[ks], self.Ls[ks], None if self.A is None else self.A[ks], self.dts[ks])

    def _guess(self, j: int, own: list) -> np.ndarray:
        """A start for the window from ``j``: the step-by-step controller's steps (``own``; past the trajectory's
        end its last repeated), so that the window plans the shapes the controller would take (not their mirror
        images, which a symmetric start leaves free)."""
        idx = self._index(j)
        Q = np.array([own[min(i, len(own) - 1)].q for i in range(self.N)])
        Ell = np.array([np.asarray(own[min(i, len(own) - 1)].command).T.ravel() for i in range(self.N)])
        return self._assemble(Q, Ell, idx)

    def _window(self, j: int, warm, own):
        """The window starting at ``j`` solved: from ``warm`` (a shifted solution and its multipliers, when given),
        else from the step-by-step controller's steps (``own()``, :meth:`_own`), else from the current state; where
        its solve fails (e.g. a step of it has no stable
        equilibrium under its load at all), the shorter windows ``N/2, N/4, ..., 1`` from ``j``, from the current
        state. ``(result, Q, Ell)``; ``Q``, ``Ell`` None when every solve failed (the last result is returned)."""
        if self.out_of_time:
            return _NoSolve("time_budget"), None, None
        left = remaining()
        budget = None if left is None else WINDOW_SHARE * left
        try:
            with time_limit(budget):
                res = None
                if warm is not None:
                    x0, lam = warm
                    res = self._solve(j, x0, lam=lam)
                if res is None or not res.success:
                    res = self._solve(j, self._guess(j, own()))
                if not res.success:
                    res = self._solve(j, self._cold(self._index(j)))
                nlp = self.nlp
                while not res.success and nlp.N > 1:
                    from ...numerics.horizon_nlp import horizon_nlp

                    nlp = horizon_nlp(self.n, max(1, nlp.N // 2), nlp.angles)
                    res = self._solve(j, self._cold(self._index(j, nlp.N), nlp), nlp)
        except TimeLimitError:
            if expired():
                raise                               # the plan's own time is up
            # the window's share of the time is spent: the rest of the plan step by step (the steps get done)
            self.out_of_time = True
            return _NoSolve("time_budget"), None, None
        if not res.success:
            return res, None, None
        Q, Ell = self._split(res.x, nlp)
        return res, Q, Ell

    def _shifted(self, res) -> tuple[np.ndarray, tuple[np.ndarray, np.ndarray]]:
        """The solution ``res`` and its multipliers shifted by one step (its last step repeated): the warm start of
        the next receding window."""
        nlp = self.nlp

        def shift(v, layout) -> np.ndarray:
            parts = {}
            for name, block in layout.unpack(v).items():
                a = np.asarray(block, float).reshape(nlp.N, -1)
                parts[name] = np.concatenate([a[1:], a[-1:]]).ravel()
            return layout.pack(**parts)

        return shift(res.x, nlp.variables), (shift(res.lam_x, nlp.variables), shift(res.lam_g, nlp.constraints))

    def _solve(self, j: int, x0: np.ndarray, nlp=None, lam=None):
        """The window starting at ``j`` from ``x0`` (``nlp``: a shorter window's problem; default the plan's):
        IPOPT's result. Every pose is in the exact penalty (a reachable target is met, an unreachable one
        approached), never a hard constraint: one step out of reach does not make the window infeasible."""
        nlp = self.nlp if nlp is None else nlp
        n, N, m = self.n, nlp.N, self.m
        idx = self._index(j, N)
        x, g, p = nlp.variables, nlp.constraints, nlp.parameters
        P = np.array([self._pose_target(k) for k in idx])            # (N, d); NaN: a free angle
        free = np.isnan(P)
        e_lo = np.where(free, 0.0, -_INF)
        e_hi = np.where(free, 0.0, _INF)
        t_hi = np.where(free.all(axis=1), 0.0, _INF)
        lbx = x.pack(phi=-_INF, L10=np.tile(self.lo[:n], N), L20=np.tile(self.lo[n:], N),
                     L=np.tile(nlp.factor_floor, N), e=e_lo.ravel(), t=0.0)
        ubx = x.pack(phi=_INF, L10=np.tile(self.hi[:n], N), L20=np.tile(self.hi[n:], N), L=_INF, e=e_hi.ravel(),
                     t=t_hi.ravel())
        slack = -_INF                               # slack springs allowed, as the step-by-step controller
        r = self.R[idx].ravel()
        lim = np.tile(self.limits, N)
        lbg = g.pack(grad=0.0, psd=0.0, q=-lim, stretch1=slack, stretch2=slack,
                     pose=np.where(free, -_INF, P).ravel(), norm=0.0, rate=-r)
        ubg = g.pack(grad=0.0, psd=0.0, q=lim, stretch1=_INF, stretch2=_INF, pose=np.where(free, _INF, P).ravel(),
                     norm=_INF, rate=r)
        w2, w1 = TIP_WEIGHTS
        pv = p.pack(a=m.a, b=m.b, k1=m.k1, k2=m.k2, F=self.Ls[idx].ravel(), ell0=self.ell, v=self.v,
                    w=[w2, w1, 1.0], scale=self.scale, margin=self.margin)
        if lam is not None:
            return nlp.solve(x0, lbx, ubx, lbg, ubg, pv, *lam)
        return nlp.solve(x0, lbx, ubx, lbg, ubg, pv)

    def _split(self, xs: np.ndarray, nlp=None) -> tuple[np.ndarray, np.ndarray]:
        """``(Q (N, n), Ell (N, 2n))`` of a solution."""
        nlp = self.nlp if nlp is None else nlp
        n, N = self.n, nlp.N
        v = nlp.variables.unpack(xs)
        phi = v["phi"].reshape(N, n)
        Q = np.diff(np.concatenate([np.zeros((N, 1)), phi], axis=1), axis=1)
        Ell = np.concatenate([v["L10"].reshape(N, n), v["L20"].reshape(N, n)], axis=1)
        return Q, Ell

    # ------------------------------------------------------------------ taking a step
    def worse(self, j: int, Q: np.ndarray, Ell: np.ndarray, own_steps) -> str:
        """Why the window's plan from step ``j`` (configurations ``Q``, rest lengths ``Ell``) is worse than the
        step-by-step controller over the same steps from the same state ("" when it is not): fewer steps on their
        targets, or (as many) a larger summed distance to them; the window's steps as planned, the controller's as
        it would take them (``own_steps``: a callable giving :meth:`_own`'s steps, called only when the window has
        a step off its target: a window with every step on target cannot be worse)."""
        ks = list(range(j, min(self.K, j + len(Q))))
        tol = LAND_TOL * self.scale
        planned = [float(np.linalg.norm(self.manipulator(Ell[i]).tip(Q[i]) - self.T[k])) for i, k in enumerate(ks)]
        if all(e <= tol for e in planned):
            return ""
        own = [st.tip_error if st.feasible else max(st.tip_error, 2 * tol) for st in own_steps()[:len(ks)]]
        on = lambda e: sum(v <= tol for v in e)                      # noqa: E731
        cost = lambda e: sum(v for v in e if v > tol)               # noqa: E731
        if on(planned) < on(own):
            return (f"the window puts {on(planned)} of its {len(ks)} steps on their targets where step by step "
                    f"puts {on(own)}")
        if on(planned) == on(own) and cost(planned) > cost(own) * (1 + 1e-9) + tol:
            return (f"the window's summed distance to the targets ({cost(planned):.6g}) exceeds step by step's "
                    f"({cost(own):.6g})")
        return ""

    def apply(self, k: int, plan_q: np.ndarray | None, plan_ell: np.ndarray | None, info: SolverInfo,
              worse: str = "") -> bool:
        """Step ``k``: the horizon's command where it is safe and not worse than the step-by-step controller's
        answer from the same state (module docstring), else that answer; the step is taken and appended to the
        output. True when the horizon's command was taken."""
        ctl, F = self.ctl, self.Ls[k]
        angle = None if self.A is None or math.isnan(self.A[k]) else float(self.A[k])
        dt = None if math.isnan(self.dts[k]) else float(self.dts[k])
        if expired():
            raise TimeLimitError("the horizon plan ran out of time")
        own = None                          # the step-by-step answer from this state, when it is needed
        hz = None
        why = f"the horizon's IPOPT solve ended {info.status}" if not worse else worse
        if plan_ell is not None and not worse:
            ell_prev = self.ell
            proposal = np.clip(plan_ell, self.lo, self.hi)
            # IPOPT holds the rate rows to its (scaled) tolerance: a proposal that far outside is clipped in
            inside = bool(np.all(np.abs(proposal - ell_prev) <= self.R[k] * (1 + 1e-6) + RATE_TOL * self.scale))
            if not inside:
                why = "the horizon's command leaves the rate box"
            else:
                command = np.clip(proposal, ell_prev - self.R[k], ell_prev + self.R[k])
                hz = ctl.evaluate(self._segment_major(command), F, self.T[k], angle, method="horizon",
                                  solver=info, planned_q=plan_q, message="the horizon plan's step")
                if not hz.feasible and (hz.verified or not ctl.verify) and math.isfinite(hz.margin):
                    own = ctl.propose(self.T[k], F, angle, dt=dt)
                if hz.feasible:
                    why = ""
                elif not (hz.verified or not ctl.verify) or not math.isfinite(hz.margin):
                    why = hz.message
                elif own.feasible:
                    why = "the horizon's step is off its target where the step-by-step answer reaches it"
                elif not self.approach:
                    why = "the horizon's step is off its target (on_infeasible hold)"
                elif hz.tip_error > own.tip_error * (1 + 1e-9) + LAND_TOL * self.scale:
                    why = "the horizon's step is farther from its target than the step-by-step answer"
                else:
                    why = ""
        if hz is not None and not why:
            take = hz
        else:
            own = ctl.propose(self.T[k], F, angle, dt=dt) if own is None else own
            take = own._but(message=f"{own.message} (the step-by-step answer: {why})")
        ctl.commit(take, F)
        self.out.append(take)
        if self.progress is not None:
            self.progress(len(self.out), self.K)
        if self.stop and take.status in ("snap", "no_equilibrium"):
            raise _Stop
        return take is hz

    # ------------------------------------------------------------------ the plan
    def run_all(self) -> None:
        """One NLP over the trajectory; where a step's command is not the horizon's (the step-by-step answer was
        taken), the steps after it are planned again from the state reached (the same NLP, its window past the end
        repeating the last step)."""
        j = 0
        try:
            while j < self.K:
                own = _Once(lambda: self._own(j))
                res, Q, Ell = self._window(j, None, own)                    # from the current state
                info = SolverInfo(res.status, res.iterations)
                if Q is None:                       # no window solved from here: the step-by-step answer
                    self.apply(j, None, None, info)
                    j += 1
                    continue
                worse = self.worse(j, Q, Ell, own)
                if worse:                           # step by step does better from here: its step, then again
                    self.apply(j, None, None, info, worse)
                    j += 1
                    continue
                first = j
                for k in range(first, min(self.K, first + len(Q))):
                    adopted = self.apply(k, Q[k - first], Ell[k - first], info)
                    j = k + 1
                    if not adopted:
                        break
        except _Stop:
            return

    def run_receding(self) -> None:
        warm = None
        try:
            for j in range(self.K):
                if expired():
                    raise TimeLimitError("the horizon plan ran out of time")
                own = _Once(lambda: self._own(j))
                res, Q, Ell = self._window(j, warm, own)
                info = SolverInfo(res.status, res.iterations)
                worse = "" if Q is None else self.worse(j, Q, Ell, own)
                if Q is not None and not worse:
                    adopted = self.apply(j, Q[0], Ell[0], info)
                else:
                    adopted = self.apply(j, None, None, info, worse)
                if Q is not None and adopted and len(Q) == self.N:
                    warm = self._shifted(res)       # the solution shifted by one step, its last step repeated
                else:
                    warm = None
        except _Stop:
            return
