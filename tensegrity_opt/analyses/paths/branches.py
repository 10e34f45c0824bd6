"""Equilibrium branches by pseudo-arclength continuation: the :class:`Branch` result and the engine.

:func:`trace_branch` follows the equilibrium branch of a chain through a start as the parameter ``t`` of a
:class:`~.control.Control` moves: tangent predictor, Newton corrector on the bordered system
``[R(z, t); tau . (x - x_pred)] = 0`` (compiled, :mod:`tensegrity_opt.numerics.path_system`, with a numpy
fallback), adaptive step (iterations, the step's turn: its end tangents and its chord), in the scaled units of
:class:`~.problem.PathProblem` (angles in rad, forces in ``k c^2 / (2 b)``, lengths in ``2 b``). Between two accepted
points the events (folds, branch points, joint limits) are detected and located (:mod:`.events`); a step across which
the Morse index changes with no event located between its points is refused and shortened (it jumped over a fold
sharper than the step onto a neighbouring branch; down to ``min_step`` the branch ends before it,
``status="step_too_small"``). The branch ends at a joint limit, at ``t_max`` / ``t_min``, at the first
(stability-losing) event on request, where it closes on its start, where the held tip reaches the edge of its
workspace or the force grows beyond :data:`FORCE_BOUND`, or when the step or the time runs out
(:attr:`Branch.status`).

Branch switching and bifurcation diagrams build on it (:mod:`.diagram`); the natural-parameter followers
(batches of targets, the :class:`~.continuation.Tracker`, force-deflection branches) are :mod:`.continuation`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from ...errors import InvalidParameterError, NoEquilibriumError
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...model.springs import SpringFields, Springs
from ...outcome import Outcome
from ...serialize import number, numbers
from ...timelimit import expired, time_limit
from ..equilibria.equilibrium import Equilibrium, check_q0
from .control import Control, as_control
from .events import BranchEvent, events_between, joint_limit_events, locate_joint_limit
from .problem import LIMIT_MARGIN, NEWTON_ITER, NEWTON_TOL, PathPoint, PathProblem, path_point

__all__ = ["Branch", "trace_branch", "continue_branch", "FORCE_BOUND", "SINGULAR_TIP", "MAX_TURN"]

#: The branch ends where the held tip reaches the edge of its workspace: the smallest singular value of the
#: held rows of the tip Jacobian below this fraction of its largest (the holding force then diverges).
SINGULAR_TIP = 1e-3
#: ... or where ``|F|`` exceeds this many force units ``k c^2 / (2 b)``.
FORCE_BOUND = 1e4

#: Largest turn (rad) of a step before it is refused and halved: the angle between its end tangents, or between
#: the chord and either tangent (a chord at a large angle to both tangents left the branch, e.g. over a sharp fold).
MAX_TURN = 0.35


@dataclass(frozen=True)
class Branch(Outcome, SpringFields):
    """An equilibrium branch: ``P`` points along the arclength with their stability and events.

    Attributes
    ----------
    control : Control
    t : ndarray (P,)
        The control parameter (0 at the start).
    q : ndarray (P, n)
        Joint angles (rad), each inside the physical range.
    force : ndarray (P, 2)
        Tip force ``[Fx, Fy]`` (``grad E = J^T F``; a reaction where the tip is held).
    tip : ndarray (P, 2)
    energy : ndarray (P,)
        Elastic energy.
    morse_index : ndarray (P,) of int
        Negative eigenvalues of the reduced Hessian (0: stable).
    stable : ndarray (P,) of bool
    s : ndarray (P,)
        Arclength in the scaled units (angles, forces / (k c^2 / 2b), lengths / 2b).
    events : tuple of BranchEvent
    status : str
        How it ended (:attr:`STATUSES`); ``success`` unless the continuation was cut (the points computed are
        kept).
    message : str
        The same in a sentence, with where.
    straight_length : float
        ``2 sum b``, the straight chain's tip (for :attr:`deflection`).
    rest_lengths : ndarray (P, n, 2) or None
        The rest lengths at each point, for a preload or move control.
    problem : PathProblem
        The path system it was traced on (switching at its branch points, the limit loads' stiffness).
    spring_lengths, spring_stretches, spring_forces, spring_states : ndarray (P, n, 2)
        The springs at each point (:class:`~tensegrity_opt.model.springs.SpringFields`).
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "t_max": "t reached t_max (the end point is solved there)",
        "t_min": "t reached t_min (the end point is solved there)",
        "joint_limit": "a joint reached its range bound (the end point is located on it)",
        "max_points": "max_points points were computed",
        "stability_loss": "stopped after the first event where stability is lost (stop_at='stability_loss')",
        "event": "stopped after the first event (stop_at='event')",
        "closed_loop": "the branch closed on its start",
        "workspace_boundary": "the held tip reached the edge of its workspace (the tip Jacobian loses rank)",
        "force_bound": "the tip force exceeded FORCE_BOUND force units",
        "step_too_small": "the step fell below min_step: the corrector cannot pass a singular point or a cusp, "
                          "or a change of stability between two points could not be located",
        "corrector_failed": "the corrector did not converge down to min_step",
        "time_limit": "the time limit ran out",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset(STATUSES) - {"step_too_small", "corrector_failed", "time_limit"}

    control: Control
    t: np.ndarray
    q: np.ndarray
    force: np.ndarray
    tip: np.ndarray
    energy: np.ndarray
    morse_index: np.ndarray
    stable: np.ndarray
    s: np.ndarray
    events: tuple
    status: str
    message: str
    straight_length: float
    rest_lengths: np.ndarray | None = None
    problem: Any = field(default=None, repr=False, compare=False)

    def __post_init__(self) -> None:
        # the engine passes arrays it owns: read-only in place (a simulation traces a branch per step)
        for a in (self.t, self.q, self.force, self.tip, self.energy, self.morse_index, self.stable, self.s,
                  self.rest_lengths):
            if a is not None:
                a.setflags(write=False)
        if not isinstance(self.events, tuple):
            object.__setattr__(self, "events", tuple(self.events))
        if self.status not in self.STATUSES:
            self._check_outcome()

    @property
    def manipulator(self) -> Manipulator | None:
        """The chain it was traced on."""
        return None if self.problem is None else self.problem.m

    @property
    def springs(self) -> Springs | None:
        """The chain's springs (the spring state's model; ``rest_lengths`` per point under a preload control)."""
        return None if self.problem is None else self.problem.m.springs

    def _spring_rest_lengths(self) -> np.ndarray | None:
        return self.rest_lengths

    @property
    def deflection(self) -> np.ndarray:
        """``(dx, dy) = (2 sum b - x, y)`` at each point."""
        return np.column_stack([self.straight_length - self.tip[:, 0], self.tip[:, 1]])

    @property
    def displacement(self) -> np.ndarray:
        """The tip's displacement from the start point, ``tip - tip[0]`` (from the rest configuration when the
        branch starts there, the default): the deflection measured from the rest shape, not from straight."""
        return self.tip - self.tip[:1]

    @property
    def folds(self) -> list:
        """The fold events."""
        return [e for e in self.events if e.kind == "fold"]

    @property
    def branch_points(self) -> list:
        """The branch-point events."""
        return [e for e in self.events if e.kind == "branch_point"]

    @property
    def stability_changes(self) -> list:
        """The events where the stability changes."""
        return [e for e in self.events if e.stability != "unchanged"]

    def __len__(self) -> int:
        return int(self.t.size)

    def to_dict(self) -> dict[str, Any]:
        """JSON form: ``success``, ``status``, ``message``, ``control``, ``points``; per point ``t, q, force, tip,
        deflection`` (from straight), ``displacement`` (from the start), ``energy, morse_index, stable, s``;
        ``events``; ``rest_lengths`` (preload and move controls); the spring state per point (``spring_lengths``,
        ``spring_stretches``, ``spring_forces``, ``spring_states``: (points, n, 2))."""
        d = {**self.outcome(), **self.spring_dict(), "control": self.control.to_dict(), "points": int(self.t.size),
             "t": numbers(self.t), "q": [numbers(r) for r in self.q],
             "force": [{"fx": number(f[0]), "fy": number(f[1])} for f in self.force],
             "tip": [numbers(r) for r in self.tip], "deflection": [numbers(r) for r in self.deflection],
             "displacement": [numbers(r) for r in self.displacement],
             "energy": numbers(self.energy), "morse_index": [int(v) for v in self.morse_index],
             "stable": [bool(v) for v in self.stable], "s": numbers(self.s),
             "events": [e.to_dict() for e in self.events]}
        if self.rest_lengths is not None:
            d["rest_lengths"] = [[numbers(r) for r in pt] for pt in self.rest_lengths]
        return d


def _start_point(m: Manipulator, prob: PathProblem, sign: float) -> PathPoint:
    x, _ = prob.correct_t(prob.x0_guess, 0.0)
    if x is None:
        raise NoEquilibriumError("the start is not an equilibrium under this control at t = 0 and Newton did not "
                                 "reach one from it", status="start_not_converged")
    if prob.limit_ratio(x)[0] >= 1.0 - LIMIT_MARGIN:
        raise InvalidParameterError("the start lies on or outside the physical joint range", field="start")
    tau = prob.tangent(x, None, sign)
    return path_point(prob, x, tau)


def _branch_from(prob: PathProblem, pts: list[PathPoint], s: list[float], events: list, status: str,
                 message: str) -> Branch:
    m = prob.m
    X = prob.point.unpack(np.array([p.x for p in pts]))
    rest = None
    if prob.control.kind in ("preload", "move"):
        base = np.column_stack([m.L1_0, m.L2_0])
        dl = prob.control.preload_direction
        rest = base[None, :, :] + X["t"][:, None, None] * dl[None, :, :]
    return Branch(control=prob.control, t=X["t"].copy(), q=X["q"].copy(), force=X["F"].copy(),
                  tip=np.array([p.tip for p in pts]), energy=np.array([p.E for p in pts]),
                  morse_index=np.array([p.morse for p in pts], dtype=int),
                  stable=np.array([p.stable for p in pts], dtype=bool), s=np.array(s), events=tuple(events),
                  status=status, message=message, straight_length=m.straight_length, rest_lengths=rest,
                  problem=prob)


def _start_of(m: Manipulator, start, control: Control):
    if start is None:
        from ..equilibria.rest import rest_configuration

        eq = rest_configuration(m)
        return eq.q.copy(), None
    if isinstance(start, Equilibrium):
        F = start.force.copy() if control.kind == "displacement" or any(control.held) else None
        return start.q.copy(), F
    q = check_q0(m, start)
    if q is None:
        raise InvalidParameterError("start must be an Equilibrium or n joint angles", field="start")
    return q, None


def trace_branch(m: Manipulator, start=None, control: Control | str = "load", *, t_max: float | None = None,
                 t_min: float | None = None, max_points: int = 1000, step: float = 0.02, max_step: float = 0.1,
                 min_step: float = 1e-7, stop_at: str | None = None, orientation: int = 1,
                 timeout: float | None = None, **control_kw) -> Branch:
    """Follow the equilibrium branch through ``start`` by pseudo-arclength continuation in ``t``.

    Parameters
    ----------
    m : Manipulator
        Up to ``numerics.DENSE_MAX`` segments.
    start : Equilibrium, array_like (n,) or None
        The start (``t = 0``), corrected by Newton onto the branch; None: the least-energy rest
        configuration (:func:`~tensegrity_opt.analyses.equilibria.rest.rest_configuration`; only meaningful for
        controls whose ``t = 0`` is the unloaded chain). For a displacement control the tip's start is
        the start's tip; a guide or wall passes through it.
    control : Control or str
        A :class:`Control`, or its kind (``"displacement"``, ``"load"``, ``"guided"``, ``"wall"``,
        ``"preload"``, ``"move"``) with the constructor's keywords in ``control_kw``.
    t_max, t_min : float, optional
        Stop where ``t`` reaches these (the end point is solved at exactly that ``t``).
    max_points : int
        At most this many points (start included).
    step, max_step, min_step : float
        Initial, largest and smallest arclength steps (scaled units, see :class:`Branch`).
    stop_at : {None, "stability_loss", "event"}
        Stop after the first event where stability is lost, or after any event.
    orientation : {1, -1}
        Leave the start with ``t`` increasing (1) or decreasing (-1).
    timeout : float, optional
        Seconds; on expiry the points so far are returned with ``status="time_limit"``.

    Returns
    -------
    Branch
        Never a point outside the physical range: the branch ends at a joint limit (an event).
        ``status`` says how it ended; ``success`` is False when the corrector failed or time ran out
        (the points computed are kept).

    Raises
    ------
    InvalidParameterError
        (``ValueError``) for a malformed control or start, or ``n > DENSE_MAX``.
    NoEquilibriumError
        (``RuntimeError``) when Newton cannot put the start on the branch.
    """
    unloaded_only(m, "trace_branch")
    if timeout is not None:
        with time_limit(timeout):
            return trace_branch(m, start, control, t_max=t_max, t_min=t_min, max_points=max_points, step=step,
                                max_step=max_step, min_step=min_step, stop_at=stop_at, orientation=orientation,
                                **control_kw)
    ctl = as_control(m, control, control_kw)
    if stop_at not in (None, "stability_loss", "event"):
        raise InvalidParameterError(f"stop_at must be None, 'stability_loss' or 'event', got {stop_at!r}",
                                    field="stop_at")
    if orientation not in (1, -1):
        raise InvalidParameterError(f"orientation must be 1 or -1, got {orientation!r}", field="orientation")
    if isinstance(max_points, bool) or not isinstance(max_points, (int, np.integer)) or max_points < 2:
        raise InvalidParameterError(f"max_points must be an integer >= 2, got {max_points!r}", field="max_points")
    for name, v in (("step", step), ("max_step", max_step), ("min_step", min_step)):
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise InvalidParameterError(f"{name} must be finite and > 0, got {v!r}", field=name)
    for name, v in (("t_max", t_max), ("t_min", t_min)):
        if v is not None and not math.isfinite(float(v)):
            raise InvalidParameterError(f"{name} must be finite, got {v!r}", field=name)
    q0, F0 = _start_of(m, start, ctl)
    prob = PathProblem(m, ctl, q0, F0)
    first = _start_point(m, prob, float(orientation))
    return continue_branch(prob, first, t_max=t_max, t_min=t_min, max_points=int(max_points), step=step,
                           max_step=max_step, min_step=min_step, stop_at=stop_at)


def _compiled_step(prob: PathProblem, a: PathPoint, h: float, Xa: np.ndarray):
    """The compiled predictor-corrector step (:mod:`tensegrity_opt.numerics.path_system`): ``(y, tau, iters)``
    when it converged (its evaluation at ``y`` kept for the classification), else ``(None, None, 0)``."""
    y, res, iters, tau, out = prob.ps.step(a.x, a.tau, h, prob.w, prob.rs, NEWTON_TOL, prob.p, prob.dp, prob.dp2,
                                           prob.ctl)
    b = float(a.tau @ Xa) + h
    if not (res <= NEWTON_TOL and abs(float(a.tau @ (prob.w * y)) - b) <= 1e-10 * max(1.0, abs(b))
            and np.all(np.isfinite(tau))):
        return None, None, 0
    prob.keep(y, out)
    return y, tau, max(iters, 1)


def _bound_before_limit(prob: PathProblem, a: PathPoint, y: np.ndarray, t_max, t_min) -> bool:
    """Whether the step ``a -> y`` that crosses a joint limit crosses t_max / t_min first: the point solved at
    that bound is inside the range."""
    at_t = prob.point["t"]
    for bound in (t_max, t_min):
        if bound is None:
            continue
        if (y[at_t] - bound) * (a.x[at_t] - bound) < 0.0:
            frac = (bound - a.x[at_t]) / (y[at_t] - a.x[at_t])
            ye, _ = prob.correct_t(a.x + frac * (y - a.x), float(bound))
            if ye is not None and prob.limit_ratio(ye)[0] < 1.0 - LIMIT_MARGIN:
                return True
    return False


def _tip_rank(p: PathPoint) -> float:
    """Smallest over largest singular value of the tip Jacobian at ``p``."""
    sv = np.linalg.svd(p.J, compute_uv=False)
    return float(sv[-1] / sv[0]) if sv[0] > 0 else 0.0


def _step_shape(tau_a: np.ndarray, tau_b: np.ndarray, chord: np.ndarray, h: float) -> tuple[float, float]:
    """``(moved, turn)`` of a step of length ``h`` (scaled; unit tangents): how far the corrector moved from the
    predictor ``h tau_a``, and the step's turn, the largest angle between its end tangents and between its chord
    and either tangent. On an arc of the branch the chord lies between the tangents; a step that crossed onto a
    neighbouring branch (over a fold sharper than the step) has a chord at a large angle to both, even where the
    end tangents are nearly parallel."""
    c2, ca, cb, ct = float(chord @ chord), float(chord @ tau_a), float(chord @ tau_b), float(tau_a @ tau_b)
    moved = math.sqrt(max(c2 - 2.0 * h * ca + h * h, 0.0))
    length = math.sqrt(c2)
    cos = min(ct, ca / length, cb / length) if length > 0.0 else ct
    return moved, math.acos(max(-1.0, min(1.0, cos)))


def _unlocated(a: PathPoint, b: PathPoint, new: list[BranchEvent]) -> bool:
    """Whether the Morse index changes from ``a`` to ``b`` by more than the folds, branch points and spring events
    located between them account for (one per eigenvalue crossing zero or jumping through it)."""
    # a spring going slack or taut may change it too (the stiffness jumps: a fold or a loss of stability at the kink)
    return b.morse != a.morse and abs(b.morse - a.morse) > sum(e.kind != "joint_limit" for e in new)


#: A step shorter than this (scaled) that still fails, with a tension-only spring changing state within it, is taken
#: across the kink: the branch's tangent jumps where a spring goes slack or taut (its stiffness does), which the
#: arclength predictor from the near side cannot pass.
KINK_STEP = 1e-5
#: ... a spring changing state within this scaled distance ahead along the tangent.
KINK_AHEAD = 1e-3
#: The kink's point is taken this far (relative to the rest length) past it, on the far side: its classification,
#: its tangent and the spring's state are the far side's, and the spring event lies between it and the point before.
KINK_PAST = 1e-12


def _stop_for(stop_at: str | None, new: list[BranchEvent]) -> tuple[str, str] | None:
    """``(status, message)`` where ``stop_at`` ends the branch after the events ``new`` of its last step, else None."""
    if stop_at == "event" and new:
        return "event", f"stopped at the first event ({new[0].kind})"
    if stop_at == "stability_loss" and any(e.stability == "lost" for e in new):
        return "stability_loss", "stopped where the branch first loses stability"
    return None


def _kinks_crossed(prob: PathProblem, xa: np.ndarray, xb: np.ndarray) -> int:
    """How many tension-only springs change state (slack / taut) between the points ``xa`` and ``xb``. A step that
    crosses two kinks at once may have jumped onto another branch (the stiffness changes at each): it is halved."""
    m = prob.m
    if m.linear_springs:
        return 0
    at = prob.point
    ra = prob.springs_at(float(xa[at["t"]])).stretches(xa[at["q"]])
    rb = prob.springs_at(float(xb[at["t"]])).stretches(xb[at["q"]])
    return int(np.sum(((ra > 0.0) != (rb > 0.0)) & m.springs.tension_only[:, None]))


def _across_kink(prob: PathProblem, a: PathPoint, h: float) -> PathPoint | None:
    """The kink just ahead of ``a`` (a tension-only spring reaching its rest length within ``h`` along the tangent):
    the point of the branch where its stretch is just past zero (``KINK_PAST``, on the far side; Newton on ``R = 0``
    and that stretch from ``a``; the rest length moves with ``t`` under a preload or move control) with the branch's
    tangent beyond it: the far side's equations' tangent there, oriented so that the stretch goes on across zero
    (the branch may turn back in ``t`` there: a fold at the kink, where the stability changes; the point is classified
    as the far side, so the spring event located between ``a`` and it carries the change). None when no spring
    changes state ahead or Newton fails."""
    m = prob.m
    if m.linear_springs:
        return None
    at = prob.point
    iq = at["q"].start
    q = a.x[at["q"]]
    ahead = a.x + h * a.tau / prob.w
    sp = prob.springs_at(float(a.x[at["t"]]))
    r0, r1 = sp.stretches(q), prob.springs_at(float(ahead[at["t"]])).stretches(ahead[at["q"]])
    cross = [(int(j), int(i)) for j, i in zip(*np.nonzero((r0 > 0.0) != (r1 > 0.0))) if m.segments[int(j)].tension_only]
    if len(cross) != 1:
        return None
    j, i = cross[0]
    seg = m.segments[j]
    it = at["t"]
    L0 = float(sp.L0[j, i])
    dl = prob.control.preload_direction                # the rest lengths move with t (preload, move controls)
    rate_t = 0.0 if dl is None else float(dl[j, i])

    def stretch(x):
        qj = float(x[iq + j])
        L0t = float(prob.springs_at(float(x[it])).L0[j, i])
        return float(seg.spring_lengths(qj)[i]) - L0t, float(seg.spring_rates(qj)[0][i])     # L - L0, dL/dq_j

    want = -1.0 if r0[j, i] > 0.0 else 1.0              # the far side: the stretch goes on across zero
    past = want * KINK_PAST * max(1.0, L0)              # the point just past the rest length: the far side's
    x = a.x.copy()
    for _ in range(NEWTON_ITER):
        R, Rx = prob.eval(x)
        r, d = stretch(x)
        if prob.residual(R) <= NEWTON_TOL and abs(r - past) <= 1e-14 * max(1.0, L0):
            break
        row = np.zeros(Rx.shape[1])
        row[iq + j], row[it] = d, -rate_t
        try:
            x = x + np.linalg.solve(np.vstack([Rx, row]), -np.concatenate([R, [r - past]]))
        except np.linalg.LinAlgError:
            return None
    else:
        return None
    r, d = stretch(x)
    if d == 0.0 or not np.all(np.isfinite(x)) or float(np.linalg.norm((x - a.x) * prob.w)) > h:
        return None
    try:
        tau = prob.tangent(x, a.tau)
    except (np.linalg.LinAlgError, ValueError):
        return None
    rate = d * float(tau[iq + j]) / float(prob.w[iq + j]) - rate_t * float(tau[it]) / float(prob.w[it])     # of L - L0
    if not np.all(np.isfinite(tau)) or rate == 0.0:
        return None
    return path_point(prob, x, tau if rate * want > 0.0 else -tau)


def continue_branch(prob: PathProblem, first: PathPoint, *, t_max, t_min, max_points, step, max_step, min_step,
                    stop_at, prefix: list[PathPoint] | None = None) -> Branch:
    """The arclength engine: continue the branch of ``prob`` from ``first`` (or from the accepted points
    ``prefix``, :func:`~.diagram.switch_branch`) until one of its ends (module docstring); keywords as
    :func:`trace_branch`."""
    pts = [first] if prefix is None else list(prefix)
    s = [0.0] * len(pts) if prefix is None else [0.0] + [float(np.linalg.norm((pts[i + 1].x - pts[i].x) * prob.w))
                                                          for i in range(len(pts) - 1)]
    s = list(np.cumsum(s))
    events: list[BranchEvent] = []
    h = float(step)
    status, message = "max_points", ""
    X0 = pts[0].x * prob.w
    at_t, at_F = prob.point["t"], prob.point["F"]
    kinked = False                        # the last point's tangent was turned across a kink (once a point)
    while len(pts) < max_points:
        if expired():
            status, message = "time_limit", "the time limit ran out: the points computed so far"
            break
        a = pts[-1]
        Xa = prob.w * a.x
        pred = a.x + h * a.tau / prob.w
        y, tau, iters = _compiled_step(prob, a, h, Xa)
        if y is None:
            y, iters = prob.correct(pred, a.tau, float(a.tau @ Xa) + h)
            tau = None
        ok = y is not None
        if ok:
            tau = prob.tangent(y, a.tau) if tau is None else tau
            moved, turn = _step_shape(a.tau, tau, prob.w * y - Xa, h)
            ok = turn <= MAX_TURN and moved <= max(0.5 * h, 1e-9) and _kinks_crossed(prob, a.x, y) <= 1
        if not ok:
            h *= 0.5
            if h < KINK_STEP and not kinked:
                k = _across_kink(prob, a, KINK_AHEAD)
                if k is not None:                 # a spring's state changes just ahead: the kink, then its far side
                    hk = float(np.linalg.norm((k.x - a.x) * prob.w))
                    new = events_between(prob, len(pts) - 1, a, k, hk)
                    events.extend(new)
                    pts.append(k)
                    s.append(s[-1] + hk)
                    h, kinked = max(2.0 * h, min(step, max_step) * 0.1), True
                    stop = _stop_for(stop_at, new)
                    if stop is not None:
                        status, message = stop
                        break
                    continue
            if h < min_step:
                if len(pts) == 1 and prob.held_rows.shape[0] == 2 and _tip_rank(a) < SINGULAR_TIP:
                    # the held tip starts on the edge of its workspace (the straight chain at full reach) and
                    # cannot move this way: it would have to leave the workspace
                    status = "workspace_boundary"
                    message = ("the held tip starts at the edge of its workspace (the chain is straight) and cannot "
                               "move in this direction")
                    break
                status = "step_too_small" if y is not None else "corrector_failed"
                message = (f"the step fell below min_step = {min_step:g} at t = {a.x[at_t]:.6g}: the branch could not "
                           "be continued (a singular point the corrector cannot pass, or a cusp)")
                break
            continue
        b = path_point(prob, y, tau)
        lim, joint = prob.limit_ratio(y)
        # joint limit: the point where the largest |q_i| / limit reaches 1 - LIMIT_MARGIN ends the branch, unless
        # t_max / t_min comes first on this step (the end point there is inside the range: the t bounds below)
        bound_first = lim >= 1.0 - LIMIT_MARGIN and _bound_before_limit(prob, a, y, t_max, t_min)
        if lim >= 1.0 - LIMIT_MARGIN and not bound_first:
            located = locate_joint_limit(prob, a, b, h)
            if located is None:
                status, message = "joint_limit", "a joint reached its range bound (the last point inside is kept)"
                break
            yl, sig = located
            bl = path_point(prob, yl, prob.tangent(yl, a.tau))
            events.extend(joint_limit_events(prob, len(pts) - 1, a, bl, sig))
            pts.append(bl)
            s.append(s[-1] + sig)
            status = "joint_limit"
            message = f"joint {prob.limit_ratio(yl)[1] + 1} reached its range bound at t = {yl[at_t]:.6g}"
            break
        # t bounds: the end point at exactly t_max / t_min
        h_step = h
        for bound, name, crossed in ((t_max, "t_max", lambda v, bd: v > bd), (t_min, "t_min", lambda v, bd: v < bd)):
            if bound is not None and crossed(y[at_t], bound) and not crossed(a.x[at_t], bound):
                frac = (bound - a.x[at_t]) / (y[at_t] - a.x[at_t])
                ye, _ = prob.correct_t(a.x + frac * (y - a.x), float(bound))
                if ye is not None:
                    b = path_point(prob, ye, prob.tangent(ye, a.tau))
                    h = float(np.linalg.norm((ye - a.x) * prob.w))
                    status = name
                break
        else:
            name = None
        turned = a.tau[at_t] * b.tau[at_t] < 0
        new = events_between(prob, len(pts) - 1, a, b, h)
        if turned and not new and prob.held_rows.shape[0] == 2 and min(_tip_rank(a), _tip_rank(b)) < 0.1:
            # t turned with no fold of the reduced Hessian: the held tip passed the edge of its workspace (J loses
            # rank between the points: the chain straightens) and the branch would come back on the other side
            status = "workspace_boundary"
            t_edge = max(a.x[at_t], b.x[at_t]) if a.tau[at_t] > 0 else min(a.x[at_t], b.x[at_t])
            message = (f"the held tip reached the edge of its workspace at t = {t_edge:.6g} (the tip Jacobian loses "
                       "rank: the chain straightens); the branch ends there")
            break
        if _unlocated(a, b, new):
            # the Morse index changes across the step with no event located between the points: the step jumped
            # over a sharp fold (or onto a neighbouring branch); a shorter step follows the branch through it
            status, h = "max_points", 0.5 * h_step
            if h < min_step:
                status = "step_too_small"
                message = (f"the stability changes between t = {a.x[at_t]:.7g} (Morse index {a.morse}) and "
                           f"t = {b.x[at_t]:.7g} (Morse index {b.morse}) with no fold or branch point located "
                           f"between them down to min_step = {min_step:g}: the branch is cut before the change")
                break
            continue
        events.extend(new)
        pts.append(b)
        kinked = False
        s.append(s[-1] + float(np.linalg.norm((b.x - a.x) * prob.w)))
        if status in ("t_max", "t_min") and name is not None:
            message = f"t reached {status} = {b.x[at_t]:.6g}"
            break
        stop = _stop_for(stop_at, new)
        if stop is not None:
            status, message = stop
            break
        Xa, Xb = prob.w * a.x, prob.w * b.x
        seg = Xb - Xa
        theta = min(1.0, max(0.0, float((X0 - Xa) @ seg) / max(float(seg @ seg), 1e-300)))
        if len(pts) > 10 and s[-1] > 5 * max_step and float(np.linalg.norm(Xa + theta * seg - X0)) < 0.1 * h:
            status, message = "closed_loop", "the branch closed on its start"
            break
        if float(np.linalg.norm(b.x[at_F])) > FORCE_BOUND * prob.Fs:
            status, message = "force_bound", f"|F| exceeded {FORCE_BOUND:g} force units k c^2/(2b)"
            break
        if prob.held_rows.shape[0] == 2:
            JJ = b.J @ b.J.T                 # singular values of J: the square roots of JJ^T's eigenvalues
            tr, det = float(JJ[0, 0] + JJ[1, 1]), float(JJ[0, 0] * JJ[1, 1] - JJ[0, 1] * JJ[1, 0])
            big = 0.5 * tr + math.sqrt(max(0.25 * tr * tr - det, 0.0))
            if det <= (SINGULAR_TIP ** 2) * big * big:
                status = "workspace_boundary"
                message = ("the held tip reached the edge of its workspace (the chain straightens, the tip Jacobian "
                           "loses rank): the holding force grows without bound")
                break
        h = min(max_step, h * (1.4 if iters <= 3 else 1.0 if iters <= 6 else 0.6))
    else:
        message = f"max_points = {max_points} reached"
    if status == "max_points" and not message:
        message = f"max_points = {max_points} reached"
    return _branch_from(prob, pts, s, events, status, message)

