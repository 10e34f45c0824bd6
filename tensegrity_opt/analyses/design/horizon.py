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
  from this solution shifted by one step (warm); the first solve starts from the current state.
* ``horizon="all"``: the whole trajectory as one NLP, solved once from the current state.

What an off-target step does is the plan's ``on_infeasible``:

* ``"approach"``: the pose error is an exact penalty (a first power plus a square, see the numerics module), so an
  out-of-reach stretch still has a solution that moves toward the targets as fast as the bounds, rates and margin
  allow and catches up when it can; the plan minimises the errors' sum over the window, and may leave a reachable
  step a little off its target to be nearer the next ones (a step off its target is infeasible, and reported so).
* ``"hold"``: the pose of the first step of each solve (the step about to be applied) is a constraint, the later
  steps' poses the penalty: a step is met exactly or not at all, the freedom left (the redundant rest lengths)
  moves ahead for the steps to come; a step whose pose cannot be met (the solve infeasible, or with ``"all"`` a
  later step of the solve off its target) holds the previous command, and the plan is solved again from the state
  reached.

Every step is applied only when it is safe: its solve converged (IPOPT's return status is reported per step), the
command lies inside the rate box of the command actually applied before it, and the forward quasi-static solve
(:func:`~tensegrity_opt.analyses.equilibria.equilibrium.settle_under_force`, IPOPT's descent where Newton does not
settle) from the previous configuration with the step's rest lengths lands on the step's planned pose, stable.
Otherwise the step **holds** the previous command (``method`` ``"none"``; ``q``, ``tip`` are then where the arm
goes under it and the step's load, the IPOPT status in ``solver``) and the next solve starts from that state.
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
from ...timelimit import expired
from ..equilibria.equilibrium import Equilibrium
from .preloads import LAND_TOL, stability_margin

__all__ = ["horizon_steps", "check_horizon", "HORIZONS", "TIP_WEIGHTS"]

#: The ``horizon`` vocabulary besides a positive int ``N`` (receding): ``"all"``, the whole trajectory at once.
HORIZONS = ("all",)
#: The pose error's weights ``(square, first power)`` in the objective, relative to the motion's weight 1 (all
#: lengths divided by ``max b``): the first power makes the penalty exact (a reachable target is met).
TIP_WEIGHTS = (100.0, 100.0)
#: Joint angles (rad) within which the forward solve must land on the planned configuration.
SAME_POSE = 1e-6
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
                  dts: np.ndarray, horizon: int | str, out: list[tuple[Any, bool]], make_step: Callable[..., Any], *,
                  verify: bool = True, progress: Callable[[int, int], Any] | None = None) -> None:
    """The steps of a trajectory planned over a horizon (module docstring), appended to ``out`` as ``(step,
    verified)`` pairs as they are applied (a :class:`~tensegrity_opt.errors.TimeLimitError` leaves those done).

    ``ctl`` (a :class:`~.preload_control.PreloadController`) carries the validated chain, start, rest lengths,
    bounds, rate limit (per second), margin, motion weights and ``on_infeasible``; ``dts`` the seconds of each step
    (NaN: no time base, only without a rate limit); ``end_angles`` NaN where free (None: none given); ``make_step``
    builds a step from its fields by keyword (:class:`~.preload_control.PreloadStep`'s). Called by
    :func:`~.preload_control.plan_preloads`, which checks every argument.
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
    plan = _Planner(ctl, targets, loads, A, R, block(ctl.ell), block(ctl.w), block(ctl.lo), block(ctl.hi),
                    bool(verify), horizon_nlp(n, N, A is not None), out, make_step, progress)
    plan.q = ctl.q.copy()
    if horizon == "all":
        plan.run_all()
    else:
        plan.run_receding()


class _Planner:
    """One plan's state: the current command and configuration, the last solution (for the warm start); the
    rest lengths in the NLP's order (the ``L1_0`` block, then ``L2_0``)."""

    def __init__(self, ctl, T, Ls, A, R, ell0, v, lo, hi, verify, nlp, out, make_step, progress) -> None:
        m = ctl.m
        self.ctl = ctl
        self.m, self.T, self.Ls, self.A, self.R = m, T, Ls, A, R
        self.ell, self.v, self.lo, self.hi = ell0.copy(), v, lo, hi
        self.margin, self.verify, self.nlp = ctl.margin, verify, nlp
        self.hold_off_target = ctl.on_infeasible == "hold"
        self.out, self.make_step, self.progress = out, make_step, progress
        self.n, self.K, self.N = m.n, T.shape[0], nlp.N
        self.scale = float(np.max(m.b))
        self.limits = m.joint_limits * (1 - RANGE_SHRINK)
        self.q = np.zeros(self.n)

    # ------------------------------------------------------------------ the arm
    def _segment_major(self, ell: np.ndarray) -> np.ndarray:
        return np.column_stack([ell[:self.n], ell[self.n:]]).ravel()

    def manipulator(self, ell: np.ndarray) -> Manipulator:
        """The chain with rest lengths ``ell`` (the L10 block, then L20): the controller's."""
        return self.ctl.manipulator(self._segment_major(ell))

    def forward(self, ell: np.ndarray, F: np.ndarray, q_prev: np.ndarray) -> Equilibrium | None:
        """The forward quasi-static solve: the arm with rest lengths ``ell`` under ``F`` from ``q_prev`` (the
        controller's), or None."""
        return self.ctl._forward(self._segment_major(ell), F, q_prev)

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
                      L=np.concatenate(Lf), e=E.ravel(), t=np.linalg.norm(E, axis=1) + 1e-3 * self.scale)

    def _pose(self, m: Manipulator, q: np.ndarray) -> np.ndarray:
        tip = m.tip(q)
        return np.append(tip, self.scale * float(np.sum(q))) if self.nlp.angles else tip

    def _pose_target(self, k: int) -> np.ndarray:
        if not self.nlp.angles:
            return self.T[k]
        return np.append(self.T[k], self.scale * self.A[k])            # NaN: free

    def _solve(self, j: int, x0: np.ndarray, hard_first: bool | None = None):
        """The window starting at ``j`` from ``x0``: IPOPT's result; ``hard_first``: the first step's pose a
        constraint (default: holding off-target steps)."""
        nlp, n, N, m = self.nlp, self.n, self.N, self.m
        idx = self._index(j)
        x, g, p = nlp.variables, nlp.constraints, nlp.parameters
        P = np.array([self._pose_target(k) for k in idx])            # (N, d); NaN: a free angle
        free = np.isnan(P)
        hard = np.zeros((N, 1), dtype=bool)             # a pose held exactly: e = 0 (module docstring)
        hard[0] = self.hold_off_target if hard_first is None else hard_first
        fixed = free | hard
        e_lo = np.where(fixed, 0.0, -_INF)
        e_hi = np.where(fixed, 0.0, _INF)
        t_hi = np.where(fixed.all(axis=1), 0.0, _INF)
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
    def _on_target(self, k: int, tip: np.ndarray, q: np.ndarray) -> bool:
        ok = float(np.max(np.abs(tip - self.T[k]))) <= LAND_TOL * self.scale
        if ok and self.A is not None and not math.isnan(self.A[k]):
            ok = abs(float(np.sum(q)) - self.A[k]) <= LAND_TOL
        return ok

    def apply(self, k: int, plan_q: np.ndarray | None, plan_ell: np.ndarray | None, info: SolverInfo) -> bool:
        """Step ``k``: adopt the planned command when it is safe (module docstring), else hold; the step is
        appended to the output. True when the plan's command was adopted."""
        n, F = self.n, self.Ls[k]
        ell_prev, q_prev = self.ell, self.q
        adopted = lands = False
        eq = None
        why = f"the horizon's IPOPT solve ended {info.status}: the previous command held"
        proposal, proposal_tip = ell_prev, None
        if plan_ell is not None:
            proposal = np.clip(plan_ell, self.lo, self.hi)
            proposal_tip = self.manipulator(proposal).tip(plan_q)
            # IPOPT holds the rate rows to its (scaled) tolerance: a proposal that far outside is clipped in
            inside = bool(np.all(np.abs(proposal - ell_prev) <= self.R[k] * (1 + 1e-6) + RATE_TOL * self.scale))
            on_target = self._on_target(k, proposal_tip, plan_q)
            if not inside:
                why = "the horizon's command leaves the rate box: the previous command held"
            elif self.hold_off_target and not on_target:
                why = (f"the target is out of reach this step (the horizon's pose is "
                       f"{float(np.linalg.norm(proposal_tip - self.T[k])):.6g} from it): the previous command held")
            else:
                command = np.clip(proposal, ell_prev - self.R[k], ell_prev + self.R[k])
                eq = self.forward(command, F, q_prev)
                lands = (eq is not None and bool(eq.stable) and float(np.max(np.abs(eq.q - plan_q))) <= SAME_POSE)
                if lands or not self.verify:
                    adopted = True
                    self.ell = command
                    why = "the horizon plan's step, verified by the forward solve" if lands else \
                        "the horizon plan's step (not verified)"
                else:
                    why = "the forward solve with the horizon's command does not land on its pose: the previous " \
                          "command held"
        if not adopted:
            eq = self.forward(self.ell, F, q_prev)
        q = q_prev if eq is None else eq.q
        self.q = q.copy()
        mk = self.manipulator(self.ell)
        tip = mk.tip(q)
        feasible = adopted and self._on_target(k, tip, q)
        held_ok = not adopted and eq is not None and bool(eq.stable)
        verified = bool(self.verify) and (lands or held_ok)
        pairs = lambda v: np.column_stack([v[:n], v[n:]])              # noqa: E731  blocks -> (n, 2)
        step = self.make_step(
            command=pairs(self.ell), proposal=pairs(proposal), q=q.copy(), tip=tip, end_angle=float(np.sum(q)),
            margin=math.nan if eq is None else stability_margin(mk, q, F),       # no equilibrium: no margin
            energy=math.nan if eq is None else float(mk.energy(q)),
            tip_error=float(np.linalg.norm(tip - self.T[k])),
            proposal_tip=tip if proposal_tip is None else proposal_tip,
            feasible=feasible, method="horizon" if adopted else "none", solver=info, residual=None,
            target=self.T[k].copy(), message=why)
        self.out.append((step, verified))
        if self.progress is not None:
            self.progress(len(self.out), self.K)
        return adopted

    def _proposal(self, j: int) -> tuple[np.ndarray | None, np.ndarray | None]:
        """Where the solve with the first step's pose held exactly failed (``"hold"``): the first step of the
        window solved with every pose in the penalty, from the current state — the pose ``"approach"`` would
        command, reported as the held step's proposal. ``(None, None)`` without one."""
        if not self.hold_off_target:
            return None, None
        res = self._solve(j, self._cold(self._index(j)), hard_first=False)
        if not res.success:
            return None, None
        Q, Ell = self._split(res.x)
        return Q[0], Ell[0]

    # ------------------------------------------------------------------ the plan
    def run_all(self) -> None:
        """One NLP over the trajectory; where a step cannot be applied (it holds), the steps after it are planned
        again from the state reached (the same NLP, its window past the end repeating the last step)."""
        j = 0
        while j < self.K:
            res = self._solve(j, self._cold(self._index(j)))            # from the current state
            info = SolverInfo(res.status, res.iterations)
            if res.success:
                Q, Ell = self._split(res.x)
            else:
                q1, e1 = self._proposal(j)
                Q, Ell = (None, None) if q1 is None else (q1[None, :], e1[None, :])
            first = j
            for k in range(first, self.K):
                if expired():
                    raise TimeLimitError("the horizon plan ran out of time")
                has = Q is not None and k - first < len(Q)
                adopted = self.apply(k, Q[k - first] if has else None, Ell[k - first] if has else None, info)
                j = k + 1
                if not adopted or not res.success:
                    break

    def run_receding(self) -> None:
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
                adopted = self.apply(j, Q[0], Ell[0], info)
            else:
                adopted = self.apply(j, *self._proposal(j), info)
            if res.success and adopted and self.N > 1:
                # the solution shifted by one step, its last step repeated
                Qs = np.concatenate([Q[1:], Q[-1:]])
                Es = np.concatenate([Ell[1:], Ell[-1:]])
                warm = self._assemble(Qs, Es, self._index(j + 1))
            elif res.success and adopted:
                warm = self._assemble(Q, Ell, self._index(j + 1))
            else:
                warm = None
