"""One transition of the arm's inputs: what the arm does while they move from one sample to the next.

The one place where the arm's quasi-static motion between two samples of its inputs is computed: the forward
simulation (:func:`~.simulation.simulate`) runs one transition per step, the preload controller and the horizon
planner verify every command by one (:mod:`tensegrity_opt.analyses.design.preload_control`), the preload follower
answers every command with one (:mod:`tensegrity_opt.analyses.design.follower`).

**The move.** The inputs -- the rest lengths ``(L1_0, L2_0)`` of every segment, and the dead tip load (tip
``"free"``) or the tip deflection (tip ``"held"``) -- move *linearly together* from one sample to the next, ``s``
the fraction of the move (0 at the first sample, 1 at the second). A controller whose actuators ramp each rest
length linearly in time from one command to the next over the step's interval (a first-order hold; at most the
rate limit, since consecutive commands differ by at most ``rate_limit * dt``), with the load ramping likewise, is
this move with ``s = (t - t_{k-1}) / (t_k - t_{k-1})``.

**The arm** (inputs slow against its dynamics, the dynamics overdamped):

* follows the equilibrium branch it is on, continuously, by pseudo-arclength continuation in ``s``
  (:func:`~.branches.trace_branch` with a :meth:`~.control.Control.move`);
* where that branch loses stability -- a fold (located by the Moore-Spence system) or a branch point -- it
  **snaps**: the new state is the equilibrium reached by *descent* (:class:`~.descent.Descent`: the gradient flow
  of ``V = E - F . tip``, or of ``E`` on the tip constraint when held) from the fold moved by ``perturbation``
  along its null vector, on the side the branch continues to, the inputs frozen there; it goes on from the
  landing for the rest of the move (a :class:`SimulationEvent` per snap: where, from which configuration, to
  which, the energy released);
* where a joint reaches its range bound (on the branch, or during a snap's descent) the model has no
  equilibrium beyond inside the physical range: the transition ends there, ``status="joint_limit"``, with the
  configuration at the bound (the arm against the stop of that joint).

**The margin** along the move (``watch_margin=True``): the smallest eigenvalue of the Hessian of ``E - F . tip``
in the joint angles (reduced to the tip motions left free when the tip is held) -- the stability margin of the
preload problems, torque per radian -- evaluated at every point of the followed branch up to the first loss of
stability, its least value located by Brent's method on ``s`` between the neighbours of the least point (each
trial point solved at its ``s`` by the corrector). It is measured on the continuation's points (the step control
keeps them at most ``max_step`` apart in scaled arclength), not bounded rigorously between them.

:func:`transition` is the public form (a :class:`Transition`); :class:`Move` is the engine.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np
import scipy.optimize as so

from ...errors import InvalidParameterError, TensegrityError, TimeLimitError
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...model.springs import SpringFields, Springs
from ...numerics import DENSE_MAX, chain_solver
from ...outcome import Outcome, freeze
from ...serialize import nullable, number, numbers
from ...timelimit import time_limit
from ..equilibria.equilibrium import Equilibrium, check_q0, is_equilibrium, local_equilibrium, make_equilibrium
from .branches import trace_branch
from .control import Control
from .descent import ArmState, Descent, state_at
from .problem import LIMIT_MARGIN, PathProblem, refuse_start_on_stop

__all__ = ["transition", "Transition", "Move", "SimulationEvent", "EVENT_KINDS", "PERTURBATION", "law_margin",
           "BRANCH_POINT_OFFSET", "MAX_EVENTS_PER_STEP", "MAX_STEP", "release", "released", "follow", "chain_with"]

#: Kinds of :class:`SimulationEvent`: a snap at a fold, a snap (or a continuous buckling, then with
#: ``energy_released`` near 0) at a branch point, the end at a joint's range bound.
EVENT_KINDS = ("snap", "bifurcation", "joint_limit")
#: The descent after a fold starts this far (rad, the largest joint) from the fold along its null vector.
PERTURBATION = 1e-4
#: A branch point is left by descent at this scaled arclength past it (in the units of
#: :func:`~tensegrity_opt.analyses.paths.branches.trace_branch`).
BRANCH_POINT_OFFSET = 1e-5
#: Branch events where the followed branch can lose stability: a fold, a branch point, and a tension-only spring
#: going slack or taut (the joint's stiffness jumps there: the branch may turn back at the kink, a fold there).
LOSSES = ("fold", "branch_point", "spring_slack", "spring_taut")
#: At most this many snaps within one move (a longer cascade ends it, ``"failed"``).
MAX_EVENTS_PER_STEP = 32
#: The largest continuation step (scaled arclength) when the margin is watched: the points where it is sampled.
MAX_STEP = 0.05


@dataclass(frozen=True)
class SimulationEvent(Outcome):
    """Something that happened during a move: between sample ``step`` and ``step + 1``, at ``time = step +
    fraction`` (a :func:`~.simulation.simulate` step, a plan's step, a follower's command).

    Attributes
    ----------
    status : str
        Where the arm went (:attr:`STATUSES`): ``"landed"`` on a stable equilibrium under the same inputs
        (``q_after``), or ``"joint_limit"``: a joint reached its range bound (the end of the move).
    message : str
        The same in a sentence.
    kind : str
        ``"snap"`` (the followed branch folded: the arm jumps), ``"bifurcation"`` (it lost stability at
        a branch point: a snap, or a continuous buckling onto a stable bifurcating branch when
        ``energy_released`` is near 0), ``"joint_limit"`` (a joint reached its range bound: the end).
    step : int
    fraction : float
        Where in the move (0 at sample ``step``, 1 at ``step + 1``); the inputs there are the linear
        interpolation of the two samples.
    preloads : ndarray (n, 2)
        The rest lengths ``(L1_0, L2_0)`` of each segment there.
    load : ndarray (2,) or None
        The dead tip load there (tip free).
    target : ndarray (2,) or None
        The tip deflection ``(dx, dy)`` there (tip held).
    q_before : ndarray (n,)
        The configuration at the fold (branch point, joint limit).
    q_after : ndarray (n,) or None
        The landing configuration: a stable equilibrium under the same inputs (None for a joint limit,
        or when the descent ran into a joint's bound: then ``message`` says so).
    force_before, force_after : ndarray (2,) or None
        The tip force (the load when free; the holding force when held).
    tip_before, tip_after : ndarray (2,) or None
    energy_before, energy_after : float or None
        Elastic energy ``E``.
    potential_before, potential_after : float or None
        The potential that the descent decreases: ``E - F . tip`` (free) or ``E`` (held).
    energy_released : float or None
        ``potential_before - potential_after`` (> 0 for a snap).
    null_vector : ndarray (n,) or None
        The joint-angle part of the fold's null vector (largest entry +1), the snapping mode.
    direction : int
        The sign of ``null_vector`` the descent left along (0 for a joint limit).
    method : str
        How the point was located (``"moore_spence"``, ``"test_function"``, ``"limit"``).
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "landed": "the arm left the lost branch and landed on a stable equilibrium under the same inputs",
        "joint_limit": "a joint reached its range bound (on the followed branch, or during the snap's descent): "
                       "no equilibrium beyond inside the physical range; the move ends there",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"landed"})

    status: str
    message: str
    kind: str
    step: int
    fraction: float
    preloads: np.ndarray
    load: np.ndarray | None
    target: np.ndarray | None
    q_before: np.ndarray
    q_after: np.ndarray | None
    force_before: np.ndarray | None
    force_after: np.ndarray | None
    tip_before: np.ndarray | None
    tip_after: np.ndarray | None
    energy_before: float | None
    energy_after: float | None
    potential_before: float | None
    potential_after: float | None
    energy_released: float | None
    null_vector: np.ndarray | None
    direction: int
    method: str

    def __post_init__(self) -> None:
        freeze(self, copy=False)            # the builder passes arrays it owns

    @property
    def time(self) -> float:
        """``step + fraction``."""
        return self.step + self.fraction

    @property
    def distance(self) -> float:
        """The largest joint motion of the snap (rad; NaN for a joint limit)."""
        return math.nan if self.q_after is None else float(np.abs(self.q_after - self.q_before).max())

    def to_dict(self) -> dict[str, Any]:
        def opt(v, f=numbers):
            return None if v is None else f(v)

        return {**self.outcome(), "kind": self.kind, "step": int(self.step), "fraction": number(self.fraction),
                "time": number(self.time), "preloads": [numbers(r) for r in self.preloads],
                "load": opt(self.load), "target": opt(self.target), "q_before": numbers(self.q_before),
                "q_after": opt(self.q_after), "force_before": opt(self.force_before),
                "force_after": opt(self.force_after), "tip_before": opt(self.tip_before),
                "tip_after": opt(self.tip_after), "energy_before": opt(self.energy_before, number),
                "energy_after": opt(self.energy_after, number),
                "potential_before": opt(self.potential_before, number),
                "potential_after": opt(self.potential_after, number),
                "energy_released": opt(self.energy_released, number), "null_vector": opt(self.null_vector),
                "direction": int(self.direction), "method": self.method}


def chain_with(m: Manipulator, P: np.ndarray) -> Manipulator:
    """``m`` with the rest lengths ``P`` (n, 2) (``m`` itself when they are its own)."""
    if np.array_equal(P[:, 0], m.L1_0) and np.array_equal(P[:, 1], m.L2_0):
        return m
    return m.with_segments(s.replace(L0=(float(P[i, 0]), float(P[i, 1]))) for i, s in enumerate(m.segments))


def margin_at(prob: PathProblem, x: np.ndarray) -> float:
    """The stability margin at the point ``x`` of ``prob``: the smallest eigenvalue of the Hessian of
    ``E - F . tip`` in the joint angles, reduced to the null space of the held rows of the tip Jacobian when the tip
    is held (torque / rad)."""
    Z, H = _reduced_hessian(prob, x)
    return math.inf if Z.shape[1] == 0 else float(np.linalg.eigvalsh(H)[0])


def _reduced_hessian(prob: PathProblem, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(Z, Z^T H Z)`` at ``x``: ``H`` the Hessian of ``E - F . tip`` in the joint angles, ``Z`` an orthonormal basis
    of the null space of the held rows of the tip Jacobian (the identity under a dead load)."""
    _, _, H, J, _, _ = prob.eval_all(x)
    k = prob.held_rows.shape[0]
    if not k:
        return np.eye(prob.n), H
    Z = np.linalg.svd(prob.held_rows @ J)[2][k:].T
    return Z, Z.T @ H @ Z


def law_margin(m: Manipulator, q: np.ndarray, load) -> float:
    """The stability margin of the arm at ``q`` under the dead ``load``: the smallest eigenvalue of the Hessian of
    ``E - F . tip`` in the joint angles (torque / rad), under each spring's law (the path problem's Hessian; on the
    side where each spring's state holds)."""
    F = np.asarray(load, float)
    prob = PathProblem(m, Control.load((1.0, 0.0), base=F), q, F)
    return margin_at(prob, prob.point.pack(q=q, F=F, t=0.0))


# ---------------------------------------------------------------------------- the engine
class Move:
    """The inputs moving linearly from ``(P0, A0)`` to ``(P1, A1)`` and the arm following them (module docstring).

    ``P`` are rest lengths ``(n, 2)``; ``A`` the dead tip load (``held=False``) or the tip deflection ``(dx, dy)``
    (``held=True``). After :meth:`run`: :attr:`events` (the move's :class:`SimulationEvent`), :attr:`least` (the
    least margin and its fraction, with ``watch_margin``), :attr:`fraction` (where the move ended: 1 unless it
    stopped early) and :attr:`limit_q` (the configuration at a joint's bound, when it ended at one).
    """

    def __init__(self, m: Manipulator, P0, P1, A0, A1, held: bool, *, step: int = 0,
                 perturbation: float = PERTURBATION, watch_margin: bool = False) -> None:
        self.m, self.held, self.eps, self.step_index = m, bool(held), float(perturbation), int(step)
        self.P0, self.P1 = np.asarray(P0, float), np.asarray(P1, float)
        self.A0, self.A1 = np.asarray(A0, float), np.asarray(A1, float)
        self.watch = bool(watch_margin)
        self.events: list[SimulationEvent] = []
        self.least: tuple[float, float] = (math.inf, math.nan)
        self.end_margin = math.nan
        self.fraction = 0.0
        self.limit_q: np.ndarray | None = None

    def inputs(self, s: float):
        """``(P, F, T)`` at fraction ``s``: the rest lengths, and the load (free) or the deflection (held)."""
        P = self.P0 + s * (self.P1 - self.P0)
        A = self.A0 + s * (self.A1 - self.A0)
        return (P, None, A) if self.held else (P, A, None)

    def run(self, state: ArmState):
        """The state at the end of the move from ``state`` (a stable equilibrium at its start):
        ``(state, status, message)`` with status ``"complete"``; on an irregular end ``state`` is None and the
        status says why (``"joint_limit"``, ``"workspace_boundary"``, ``"force_bound"``, ``"time_limit"``,
        ``"failed"``)."""
        s0 = 0.0
        n = self.m.n
        k = self.step_index
        for _ in range(MAX_EVENTS_PER_STEP + 1):
            P0, F0, T0 = self.inputs(s0)
            r = 1.0 - s0
            dP = r * (self.P1 - self.P0)
            d2 = r * (self.A1 - self.A0)
            if not (np.any(dP != 0.0) or np.any(d2 != 0.0)):
                self.fraction = 1.0
                if self.watch:
                    self._watch_point(state, 1.0)
                return state, "complete", ""
            mk = chain_with(self.m, P0)
            ctl = (Control.move(n, preload=dP, displacement=d2, tip="held") if self.held
                   else Control.move(n, preload=dP, load=d2, base=F0))
            br = trace_branch(mk, state.equilibrium(self.held), ctl, t_max=1.0, stop_at="stability_loss",
                              max_points=5000, max_step=MAX_STEP if self.watch else 0.1)
            prob = br.problem
            # (a stability loss on the last step to t = 1 ends the branch as "t_max": the events decide)
            lost = [e for e in br.events if e.stability == "lost" and e.kind in LOSSES]
            if self.watch:
                self._watch(prob, br, lost[0] if lost else None, s0, r)
            if not lost and br.status == "t_max":
                end = state_at(prob, prob.point.pack(q=br.q[-1], F=br.force[-1], t=br.t[-1]))
                if end.stable:
                    self.fraction = 1.0
                    return end, "complete", ""
                self.fraction = s0 + r * float(br.t[-1])
                return None, "failed", (f"step {k}: the followed branch became unstable without a located fold or "
                                        "branch point")
            if lost:
                landed, s_d, status, msg = self.snap(s0, r, prob, br, lost[0])
                if landed is None:
                    self.fraction = s_d
                    return None, status, msg
                state, s0 = landed, s_d
                continue
            self.fraction = s0 + r * float(br.t[-1])
            if br.status == "joint_limit":
                ev = next((e for e in br.events if e.kind == "joint_limit"), None)
                if ev is not None:
                    s_ev = s0 + r * ev.t
                    self.fraction = s_ev
                    self.limit_q = np.asarray(ev.q, float).copy()
                    self.events.append(self._event("joint_limit", "joint_limit", s_ev, ev.q, None, ev.force, None,
                                                   ev.tip, None, ev.energy, None, None, None, 0, "limit",
                                                   f"joint {ev.joint + 1} reached its range bound"))
                else:
                    self.limit_q = np.asarray(br.q[-1], float).copy()
                return None, "joint_limit", (f"a joint reached its range bound in step {k} (at fraction "
                                             f"{self.fraction:.6g}): no equilibrium beyond inside the physical "
                                             "range")
            if br.status in ("workspace_boundary", "force_bound", "time_limit"):
                return None, br.status, f"step {k}: {br.message}"
            return None, "failed", f"step {k}: the branch could not be followed ({br.status}: {br.message})"
        return None, "failed", f"more than {MAX_EVENTS_PER_STEP} snaps in step {k}"

    # ------------------------------------------------------------------ the margin along the move
    def _keep(self, mu: float, s: float) -> None:
        if mu < self.least[0]:
            self.least = (float(mu), float(s))

    def _watch_point(self, state: ArmState, s: float) -> None:
        """The margin of a state at fraction ``s`` (a move with nothing left to move)."""
        P, F, T = self.inputs(s)
        mk = chain_with(self.m, P)
        ctl = Control.load((1.0, 0.0), base=F) if not self.held else Control.displacement((1.0, 0.0))
        prob = PathProblem(mk, ctl, state.q, state.force)
        self.end_margin = margin_at(prob, prob.point.pack(q=state.q, F=state.force, t=0.0))
        self._keep(self.end_margin, s)

    def _watch(self, prob: PathProblem, br, lost, s0: float, r: float) -> None:
        """The least margin of the stable stretch of ``br`` (the sub-move from fraction ``s0``, of length ``r``):
        its points up to the first loss of stability (``lost``), the least located between its neighbours."""
        at = prob.point
        last = len(br) - 1 if lost is None else int(lost.index)
        X = [at.pack(q=br.q[i], F=br.force[i], t=br.t[i]) for i in range(last + 1)]
        mu = np.array([margin_at(prob, x) for x in X])
        if lost is None and br.status == "t_max":
            self.end_margin = float(mu[-1])
        if lost is not None:                        # the stability loss itself: the margin reaches zero there
            self._keep(0.0, s0 + r * float(lost.t))
        i = int(np.argmin(mu))
        self._keep(mu[i], s0 + r * float(br.t[i]))
        t = br.t

        def g(tt: float) -> float:
            """The margin on the branch at ``tt`` (corrected from the chord of its neighbouring points)."""
            j = min(max(int(np.searchsorted(t[:last + 1], tt)), 1), last)
            xa, xb, ta, tb = X[j - 1], X[j], float(t[j - 1]), float(t[j])
            y, _ = prob.correct_t(xa + (xb - xa) * ((tt - ta) / (tb - ta)), tt)
            return math.inf if y is None else margin_at(prob, y)

        if not np.all(np.diff(t[:last + 1]) > 0):
            return                                  # t not monotone on the stretch: the samples are the measure
        # a bracket of the least: the least point and its neighbours, or at an end the end, the middle of the
        # neighbouring interval (evaluated) and the neighbour; then Brent's parabolic search inside it
        bracket = None
        if 0 < i < last:
            bracket = (float(t[i - 1]), float(t[i]), float(t[i + 1]))
        elif last >= 1:
            j = 1 if i == 0 else last - 1
            mid = 0.5 * (float(t[i]) + float(t[j]))
            gm = g(mid)
            self._keep(gm, s0 + r * mid)
            if gm < mu[i] and gm < mu[j]:
                bracket = tuple(sorted((float(t[i]), float(t[j]))))
                bracket = (bracket[0], mid, bracket[1])
        if bracket is None:
            return
        try:
            # at a minimum the value's error is quadratic in the location's: 1e-4 of the bracket is ample (Brent's
            # tolerance is relative to |t|)
            tol = max(1e-4 * (bracket[2] - bracket[0]) / max(abs(bracket[1]), 1e-12), 1e-12)
            res = so.minimize_scalar(g, bracket=bracket, method="brent", tol=tol)
        except (ValueError, RuntimeError, np.linalg.LinAlgError):
            return
        if math.isfinite(float(res.fun)) and bracket[0] <= float(res.x) <= bracket[2]:
            self._keep(float(res.fun), s0 + r * float(res.x))

    # ------------------------------------------------------------------ events
    def _event(self, status, kind, s, qb, qa, Fb, Fa, tb, ta, Eb, Ea, Vb, Va, sign, method, msg, nv=None):
        P, F, T = self.inputs(s)
        return SimulationEvent(status, msg, kind, self.step_index, float(s), P.copy(), None if F is None else F.copy(),
                               None if T is None else T.copy(), np.asarray(qb, float).copy(),
                               None if qa is None else np.asarray(qa, float).copy(),
                               None if Fb is None else np.asarray(Fb, float).copy(),
                               None if Fa is None else np.asarray(Fa, float).copy(),
                               None if tb is None else np.asarray(tb, float).copy(),
                               None if ta is None else np.asarray(ta, float).copy(),
                               None if Eb is None else float(Eb), None if Ea is None else float(Ea),
                               None if Vb is None else float(Vb), None if Va is None else float(Va),
                               None if (Vb is None or Va is None) else float(Vb - Va),
                               None if nv is None else np.asarray(nv, float).copy(), int(sign), method)

    def snap(self, s0: float, r: float, prob, br, ev):
        """Descent from the fold (branch point) ``ev`` of ``br`` (the sub-move from fraction ``s0``, of length
        ``r``): ``(state, fraction, "landed", "")`` with the event recorded, or ``(None, fraction, status,
        message)``."""
        k = self.step_index
        kink = ev.kind in ("spring_slack", "spring_taut")
        fold = ev.kind == "fold" or kink
        at = prob.point
        x_ev = ev.x.copy()
        phi = _kink_mode(prob, ev) if kink else np.asarray(ev.null_vector, float)
        phi = phi / max(float(np.abs(phi).max()), 1e-300)
        note = ""
        if not fold:
            # just past the branch point along the traced branch (unstable there): at the branch point itself the
            # flow would leave only algebraically slowly
            after = at.pack(q=br.q[-1], F=br.force[-1], t=br.t[-1])
            t_ev, t_after = x_ev[at["t"]], after[at["t"]]
            t_d = min(float(t_ev) + BRANCH_POINT_OFFSET / float(prob.w[at["t"]]), float(t_after))
            frac = (t_d - t_ev) / max(t_after - t_ev, 1e-300)
            y, _ = prob.correct_t(x_ev + (after - x_ev) * frac, t_d)
            if y is None:
                return None, s0 + r * ev.t, "failed", f"step {k}: no point on the branch just past its branch point"
            note = f"the branch point is at fraction {s0 + r * ev.t:.12g}; the arm leaves it just past, here"
            x_ev = y
        t_d = float(x_ev[at["t"]])
        s_d = s0 + r * t_d
        d = Descent(prob, t_d, self.held, x_ev[at["F"]].copy())
        q_ev = x_ev[at["q"]].copy()
        V_ev = d.potential(q_ev)
        cands = {}
        for sign in (1, -1):
            qs = q_ev + sign * self.eps * phi
            qs = d.onto(qs) if self.held else qs
            cands[sign] = (d.potential(qs), qs)
        if kink:
            # phi points into the far side of the kink (where the branch lost its stability)
            sign = -1 if cands[1][0] > V_ev and cands[-1][0] < V_ev else 1
        elif fold:
            # the unstable side: where the traced branch goes on past the fold (V decreases along it at the fold)
            side = float(phi @ (br.q[-1] - ev.q))
            sign = 1 if side > 0 else -1 if side < 0 else (1 if cands[1][0] <= cands[-1][0] else -1)
            if cands[sign][0] > V_ev and cands[-sign][0] < V_ev:
                sign = -sign
        else:
            sign = 1 if cands[1][0] <= cands[-1][0] + 1e-15 * max(1.0, abs(V_ev)) else -1
        before = state_at(prob, x_ev)
        outcome, res = d.run(cands[sign][1])
        kind = "snap" if fold else "bifurcation"
        if outcome == "landed":
            s = res
            if fold and float(np.abs(s.q - q_ev).max()) < 10 * self.eps:
                return None, s_d, "failed", f"step {k}: the descent from the fold came back to it"
            released = before.potential(self.held) - s.potential(self.held)
            note = note or (f"snap at fraction {s_d:.6g} of step {k}: landed on a stable equilibrium (potential "
                            f"released {released:.6g})")
            self.events.append(self._event("landed", kind, s_d, q_ev, s.q, before.force, s.force, before.tip,
                                           s.tip, before.energy, s.energy, before.potential(self.held),
                                           s.potential(self.held), sign, ev.method, note,
                                           phi if kink else ev.null_vector))
            return s, s_d, "landed", ""
        if outcome == "joint_limit":
            self.limit_q = np.asarray(res, float).copy()
            msg = (f"the snap at step {k} + {s_d:.6g} runs into a joint's range bound (no equilibrium inside the "
                   "physical range on the way)")
            self.events.append(self._event("joint_limit", kind, s_d, q_ev, None, before.force, None, before.tip,
                                           None, before.energy, None, before.potential(self.held), None, sign,
                                           ev.method, msg, phi if kink else ev.null_vector))
            return None, s_d, "joint_limit", msg
        if outcome == "time_limit":
            return None, s_d, "time_limit", "the time limit ran out during a snap"
        return None, s_d, "failed", f"step {k}: the descent from the fold at fraction {s_d:.6g} did not land"


def _kink_mode(prob: PathProblem, ev) -> np.ndarray:
    """The snapping mode where the followed branch loses stability at a kink (a tension-only spring going slack or
    taut, ``ev``): there is no null vector (the stiffness jumps, no eigenvalue passes through zero); the mode is the
    eigenvector of the least eigenvalue of the Hessian of the potential on the far side of the kink (the kink point
    moved 1e-9 across the spring's rest length in its joint), reduced to the tip motions left free when the tip is
    held, signed into the far side (where the spring's stretch has the far side's sign)."""
    j, i = int(ev.joint), int(ev.spring) - 1
    dL = float(prob.m.segments[j].spring_rates(float(ev.q[j]))[0][i])      # dL/dq_j at the kink
    far = -1.0 if ev.kind == "spring_slack" else 1.0                        # the stretch's sign on the far side
    x_far = ev.x.copy()
    x_far[prob.point["q"].start + j] += far * 1e-9 / dL                   # 1e-9 across the rest length
    Z, H = _reduced_hessian(prob, x_far)
    phi = Z @ np.linalg.eigh(H)[1][:, 0]
    return phi if dL * phi[j] * far >= 0.0 else -phi


def release(m: Manipulator, q: np.ndarray, load, *, perturbation: float = PERTURBATION):
    """The arm released at ``q`` (a configuration that is no equilibrium, e.g. against a joint's stop) under the
    dead ``load``: the descent (:class:`~.descent.Descent`, the gradient flow of ``E - F . tip``) from ``q``
    moved inside the range by ``perturbation``: ``("landed", ArmState)``, ``("joint_limit", q at the bound)``,
    ``("time_limit", q)`` or ``("failed", q)``."""
    F = np.asarray(load, float)
    q = np.asarray(q, float)
    lim = m.joint_limits * (1.0 - LIMIT_MARGIN)
    q_in = np.clip(q, -(lim - perturbation), lim - perturbation)
    prob = PathProblem(m, Control.load((1.0, 0.0), base=F), q_in, F)
    return Descent(prob, 0.0, False, F).run(q_in)


# ---------------------------------------------------------------------------- the public form
@dataclass(frozen=True)
class Transition(Outcome, SpringFields):
    """What the arm does while its inputs move from one sample to the next (:func:`transition`).

    Attributes
    ----------
    status : str
        :attr:`STATUSES`: ``"followed"`` (the arm stayed on its branch, stable, to the end of the move),
        ``"snapped"`` (it lost its branch and snapped, once or more, and ends on a stable equilibrium),
        ``"joint_limit"`` (a joint reached its range bound: no equilibrium beyond), ``"released"`` (it started
        against a joint's stop: :func:`released`), ``"failed"``, ``"time_limit"``.
    message : str
    q : ndarray (n,)
        The arm at the end of the move; at a joint limit, the configuration at the bound (no equilibrium).
    force : ndarray (2,)
        The tip force there: the load (free), the holding force (held); at a joint limit the load at that point.
    tip : ndarray (2,)
    energy : float
        Elastic energy there.
    stable : bool
        The end state is a stable equilibrium (False at a joint limit).
    margin : float
        The least stability margin along the move up to the first loss of stability (torque / rad; 0 where the
        arm snapped: stability is lost there), located (module docstring).
    margin_at : float
        The fraction where it is least.
    margin_end : float
        The margin of the end state (NaN at a joint limit, and for a release: not measured).
    fraction : float
        Where the move ended: 1, or the fraction of the joint limit (or of the failure).
    events : tuple of SimulationEvent
        The snaps (``kind`` ``"snap"``, ``"bifurcation"``) and the joint limit, in order.
    spring_lengths, spring_stretches, spring_forces, spring_states : ndarray (n, 2)
        The springs at ``q`` under the final rest lengths (:class:`~tensegrity_opt.model.springs.SpringFields`).
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "followed": "the arm followed its equilibrium branch, stable, to the end of the move",
        "snapped": "the followed branch lost stability (a fold or a branch point): the arm snapped (see events) and "
                   "ends on a stable equilibrium under the final inputs",
        "joint_limit": "a joint reached its range bound, on the branch or during a snap: no equilibrium beyond "
                       "inside the physical range; q is the configuration at the bound",
        "released": "the arm started against a joint's stop (no equilibrium there) and, released under the final "
                    "inputs, settled on a stable equilibrium by descent (not a followed path)",
        "failed": "the branch or a snap could not be computed (message says where)",
        "time_limit": "the time limit ran out",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"followed"})

    status: str
    message: str
    q: np.ndarray
    force: np.ndarray
    tip: np.ndarray
    energy: float
    stable: bool
    margin: float
    margin_at: float
    margin_end: float
    fraction: float
    events: tuple
    springs: Springs | None = field(default=None, repr=False, compare=False)

    def __post_init__(self) -> None:
        freeze(self, copy=False)

    @property
    def snaps(self) -> list:
        """The snap and bifurcation events, in order."""
        return [e for e in self.events if e.kind in ("snap", "bifurcation")]

    def to_dict(self) -> dict[str, Any]:
        """JSON form: ``success``, ``status``, ``message``, ``q``, ``force`` ``{fx, fy}``, ``tip``, ``energy``,
        ``stable``, ``margin`` (null: none measured), ``margin_at``, ``margin_end``, ``fraction``, ``events``, the
        spring state (``spring_lengths``, ``spring_stretches``, ``spring_forces``, ``spring_states``)."""
        return {**self.outcome(), **self.spring_dict(), "q": numbers(self.q), "force": {"fx": number(self.force[0]),
                                                                  "fy": number(self.force[1])},
                "tip": numbers(self.tip), "energy": nullable(self.energy), "stable": bool(self.stable),
                "margin": nullable(self.margin), "margin_at": nullable(self.margin_at),
                "margin_end": nullable(self.margin_end), "fraction": number(self.fraction),
                "events": [e.to_dict() for e in self.events]}


def start_state(m: Manipulator, q0, load=None, *, target=None, force=None, moved: bool = True,
                field: str = "start") -> ArmState:
    """The stable equilibrium of ``m`` at ``q0`` polished by Newton, as an :class:`~.descent.ArmState`: under the
    dead ``load`` (tip free), or with the tip held at ``target`` (``force`` a guess of the holding force).
    ``InvalidParameterError`` (``field``) when Newton does not converge from ``q0`` inside the range, moves it by
    more than 1e-3 rad (``moved``: checked) or ends on an unstable equilibrium."""
    held = target is not None
    q0 = np.asarray(q0, float)
    if not m.linear_springs:
        return _start_state_slack(m, q0, load, target, force, moved, field)
    if held:
        res = local_equilibrium(m, target, q0, force)
        ok = is_equilibrium(m, res, target)
    else:
        res = chain_solver(m).newton_force(np.asarray(load, float), q0)
        ok = is_equilibrium(m, res)
    if not ok:
        raise InvalidParameterError(f"{field} is not (near) an equilibrium under the first inputs: Newton did not "
                                    "converge from it inside the joint range", field=field)
    eq = make_equilibrium(m, res, constrained=held)
    _check_start(field, eq.q, q0 if moved else None, eq.stable, eq.morse_index)
    F = eq.force.copy() if held else np.asarray(load, float).copy()
    return ArmState(eq.q.copy(), F, eq.tip.copy(), float(eq.energy), 0, True)


def _start_state_slack(m: Manipulator, q0: np.ndarray, load, target, force, moved: bool, field: str) -> ArmState:
    """:func:`start_state` of a chain with tension-only springs: the path problem's corrector (Newton on the
    equilibrium under each spring's law, the tip held at ``target`` or loaded by ``load``). The moves are followed
    by arclength continuation inside the range only: a start resting on a joint's stop is refused
    (``UnsupportedError``, status ``start_on_stop``)."""
    held = target is not None
    refuse_start_on_stop(np.abs(q0) >= m.joint_limits * (1.0 - LIMIT_MARGIN), field,
                         "a move is followed by arclength continuation")
    q = q0.copy()
    if held:
        for _ in range(8):                          # onto the tip constraint (Gauss-Newton, least norm)
            r = m.tip(q) - target
            if float(np.abs(r).max()) <= 1e-13 * m.straight_length:
                break
            q = q - np.linalg.lstsq(m.jacobian(q), r, rcond=None)[0]
        F = m.force_from_torques(q) if force is None else np.asarray(force, float)
        ctl = Control.displacement((1.0, 0.0))
    else:
        F = np.asarray(load, float)
        ctl = Control.load((1.0, 0.0), base=F)
    y = None
    if np.all(np.isfinite(q)) and m.in_range(q):
        prob = PathProblem(m, ctl, q, F)
        y, _ = prob.correct_t(prob.x0_guess, 0.0)
    if y is None or prob.limit_ratio(y)[0] >= 1.0 - LIMIT_MARGIN:
        raise InvalidParameterError(f"{field} is not (near) an equilibrium under the first inputs: Newton did not "
                                    "converge from it inside the joint range", field=field)
    s = state_at(prob, y)
    if held and float(np.abs(s.tip - target).max()) > 1e-9 * m.straight_length:
        raise InvalidParameterError(f"{field} could not be put on the first target", field=field)
    _check_start(field, s.q, q0 if moved else None, s.stable, s.morse)
    return s


def _check_start(field: str, q: np.ndarray, q0: np.ndarray | None, stable: bool, morse: int) -> None:
    """The start Newton put at ``q`` is near the given ``q0`` (when given: 1e-3 rad) and stable, else
    :class:`InvalidParameterError` naming ``field``."""
    if q0 is not None and np.abs(q - q0).max() > 1e-3:
        raise InvalidParameterError(f"{field} is not (near) an equilibrium under the first inputs: Newton moved it "
                                    f"by {np.abs(q - q0).max():.3g} rad", field=field)
    if not stable:
        raise InvalidParameterError(f"{field} is not a stable equilibrium under the first inputs (Morse index "
                                    f"{morse})", field=field)


def _pair(v, shape: tuple[int, ...], name: str) -> np.ndarray:
    try:
        a = np.asarray(v, dtype=float)
    except (TypeError, ValueError):
        raise InvalidParameterError(f"{name} must be numbers", field=name) from None
    if a.shape != (2, *shape) or not np.all(np.isfinite(a)):
        raise InvalidParameterError(f"{name} must be two samples (from, to) of shape {shape}, finite",
                                    field=name)
    return a


def transition(m: Manipulator, start, preloads, loads=None, *, perturbation: float = PERTURBATION,
               timeout: float | None = None) -> Transition:
    """What the arm does while its rest lengths and tip load move linearly from one sample to the next
    (module docstring): the branch followed, the least stability margin along it, the snaps, the end state.

    Parameters
    ----------
    m : Manipulator
        Geometry and stiffness (its own rest lengths are not used: ``preloads`` gives them); up to
        ``numerics.DENSE_MAX`` segments.
    start : Equilibrium or array_like (n,)
        The arm's configuration at the first sample: a stable equilibrium under its inputs (Newton polishes it).
    preloads : array_like (2, n, 2)
        The rest lengths ``(L1_0, L2_0)`` per segment at the two samples (> 0).
    loads : array_like (2, 2), optional
        The dead tip load at the two samples (default none).
    perturbation : float
        Where a snap's descent starts (rad from the fold along its null vector).
    timeout : float, optional
        Seconds (``status="time_limit"`` on expiry).

    Returns
    -------
    Transition

    Examples
    --------
    A bistable segment in front of a straight one: tilting its rest lengths ends the well it sits in.

    >>> import numpy as np, tensegrity_opt as to
    >>> from tensegrity_opt.analyses.paths.transition import transition
    >>> m = to.Manipulator([to.Segment(0.5, 1.0, 1.0, 1.0), to.Segment(1.0, 1.0, 1.0, 1.0)])
    >>> rest = to.rest_configuration(m)
    >>> tr = transition(m, rest, [[[1.0, 1.0], [1.0, 1.0]], [[1.4, 0.6], [1.0, 1.0]]])
    >>> tr.status, len(tr.snaps)
    ('snapped', 1)
    """
    unloaded_only(m, "transition")
    if not isinstance(m, Manipulator):
        raise InvalidParameterError("m must be a Manipulator", field="m")
    if m.n > DENSE_MAX:
        raise InvalidParameterError(f"a transition handles chains of up to {DENSE_MAX} segments, got n = {m.n}",
                                    field="n")
    P = _pair(preloads, (m.n, 2), "preloads")
    if not np.all(P > 0.0):
        raise InvalidParameterError("preloads (rest lengths) must be > 0", field="preloads")
    L = np.zeros((2, 2)) if loads is None else _pair(loads, (2,), "loads")
    if not (isinstance(perturbation, (int, float)) and math.isfinite(perturbation) and 0 < perturbation < 0.1):
        raise InvalidParameterError(f"perturbation must be in (0, 0.1) rad, got {perturbation!r}",
                                    field="perturbation")
    q0 = start.q if isinstance(start, Equilibrium) else check_q0(m, start, closed=not m.linear_springs)
    if q0 is None:
        raise InvalidParameterError("start must be an Equilibrium or n joint angles", field="start")
    with time_limit(timeout):
        state = start_state(chain_with(m, P[0]), q0, L[0])
        return follow(m, state, P[0], P[1], L[0], L[1], perturbation=float(perturbation))


def follow(m: Manipulator, state: ArmState, P0, P1, F0, F1, *, perturbation: float = PERTURBATION,
           step: int = 0) -> Transition:
    """The :class:`Transition` of the free-tip arm in ``state`` (a stable equilibrium with ``P0`` under ``F0``)
    while the inputs move to ``(P1, F1)``, the margin watched: :func:`transition` without the checks."""
    mv = Move(m, P0, P1, F0, F1, False, step=step, perturbation=perturbation, watch_margin=True)
    try:
        end, status, message = mv.run(state)
    except TimeLimitError:
        end, status, message = None, "time_limit", "the time limit ran out"
    except TensegrityError as exc:
        end, status, message = None, "failed", str(exc)
    least, at = mv.least
    events = tuple(mv.events)
    if end is not None:
        snapped = any(e.kind in ("snap", "bifurcation") for e in events)
        return Transition("snapped" if snapped else "followed",
                          ("the arm snapped: " + "; ".join(e.message for e in events)) if snapped else
                          f"the arm followed its branch to the end of the move, least margin {least:.6g}",
                          end.q.copy(), np.asarray(end.force, float).copy(), np.asarray(end.tip, float).copy(),
                          float(end.energy), bool(end.stable), least, at, mv.end_margin, 1.0, events,
                          m.springs.with_rest_lengths(P1))
    s = mv.fraction
    P, F, _ = mv.inputs(s)
    q = mv.limit_q if mv.limit_q is not None else state.q
    mk = chain_with(m, P)
    E = float(mk.energy(q))
    status = "joint_limit" if status == "joint_limit" else ("time_limit" if status == "time_limit" else "failed")
    return Transition(status, message, np.asarray(q, float).copy(), np.asarray(F, float).copy(), mk.tip(q), E,
                      False, least, at, math.nan, float(s), events, mk.springs)


def released(m: Manipulator, q: np.ndarray, P1, F1, *, step: int = 0,
             perturbation: float = PERTURBATION) -> Transition:
    """The :class:`Transition` of an arm that starts against a joint's stop at ``q`` (no equilibrium there): its
    release under the final inputs ``(P1, F1)`` (:func:`release`): ``"released"`` where it settles on a stable
    equilibrium, ``"joint_limit"`` where the descent reaches a bound again (``q`` there). The model has no
    equilibrium along the way, so nothing is followed and no margin is measured (NaN)."""
    P1 = np.asarray(P1, float)
    F1 = np.asarray(F1, float)
    mk = chain_with(m, P1)
    try:
        outcome, res = release(mk, q, F1, perturbation=perturbation)
    except TimeLimitError:
        outcome, res = "time_limit", q
    if outcome == "landed":
        return Transition("released", "the arm, released from its joint stop under the step's inputs, settled on a "
                          "stable equilibrium (not a followed path)", res.q.copy(), F1.copy(),
                          np.asarray(res.tip, float).copy(), float(res.energy), True, math.nan, math.nan, math.nan,
                          1.0, (), mk.springs)
    qe = np.asarray(res, float).copy()
    if outcome == "joint_limit":
        ev = SimulationEvent("joint_limit", "the released arm reaches a joint's stop again: no equilibrium under the "
                             "step's inputs", "joint_limit", int(step), 1.0, P1.copy(), F1.copy(), None,
                             np.asarray(q, float).copy(), None, F1.copy(), None, mk.tip(q), None,
                             float(mk.energy(q)), None, None, None, None, None, 0, "limit")
        return Transition("joint_limit", "released from its joint stop under the step's inputs, the arm reaches a "
                          "stop again: no equilibrium", qe, F1.copy(), mk.tip(qe), float(mk.energy(qe)), False,
                          math.nan, math.nan, math.nan, 1.0, (ev,), mk.springs)
    status = "time_limit" if outcome == "time_limit" else "failed"
    return Transition(status, "the release from the joint stop did not settle", qe, F1.copy(), mk.tip(qe),
                      float(mk.energy(qe)), False, math.nan, math.nan, math.nan, 1.0, (), mk.springs)
