"""Events of a branch: :class:`BranchEvent`, their detection between two accepted points and their location.

Between two accepted points ``a`` and ``b`` of a branch (:mod:`.branches`) an event is detected by a change
of a test function's sign and located precisely on the branch:

* a change of the Morse index (stability) is located at the zero of the reduced Hessian's eigenvalue that
  changes sign; a **fold** (the tangent's ``t`` component changes sign) without one at the zero of that
  component; both by Brent's method on the arclength, the corrector solving each trial point;
* the point is a **branch point** when the left null vector ``u`` of ``R_z`` is orthogonal to ``R_t``
  (``|u . R_t| / |R_t| < BP_TOL``: another branch crosses), else a fold, which is then refined by Newton on
  the Moore-Spence system ``R = 0, R_z phi = 0, l . phi = 1`` (:func:`moore_spence`, regular at a quadratic
  fold);
* a **joint limit** (``|q_i| = (1 - LIMIT_MARGIN)(pi - 2 beta_i)``) is located at the zero of the largest
  ``|q_i| / limit_i - (1 - LIMIT_MARGIN)``; the branch ends there;
* the **least tangent stiffness** along a dead load ``F = base + t d`` (the quasi-buckling load,
  :mod:`.limit_load`) is located at the zero of the derivative of the compliance ``c = d . dtip/dt``
  (:func:`load_compliance`: exact, from the path's first and second derivatives in ``t``), by Brent's method
  on ``t`` between two points of the stable path where that derivative falls through zero, the corrector solving
  each trial point at its ``t`` (:func:`locate_stiffness_minimum`).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import scipy.optimize as so

from ...model.springs import SpringFields, Springs
from ...serialize import nullable, number, numbers
from .problem import LIMIT_MARGIN, NEWTON_TOL, PathPoint, PathProblem

__all__ = ["BranchEvent", "EVENT_KINDS", "SINGULAR_KINDS", "BP_TOL", "events_between", "locate_joint_limit",
           "joint_limit_events",
           "moore_spence", "load_compliance", "locate_stiffness_minimum"]

#: Kinds of :class:`BranchEvent`.
EVENT_KINDS = ("fold", "branch_point", "joint_limit", "spring_slack", "spring_taut")
#: The kinds that account for a change of the Morse index (the others: a joint limit ends the branch, a spring's
#: state changes the stiffness only).
SINGULAR_KINDS = ("fold", "branch_point")
#: ``|u . R_t| / |R_t|`` below which a singular point is a branch point rather than a fold.
BP_TOL = 1e-6
#: A located eigenvalue zero is one where that eigenvalue of the reduced Hessian is below this many torque units
#: (a sign change across a jump between branches is not a zero).
ZERO_EIG = 1e-6


@dataclass(frozen=True)
class BranchEvent(SpringFields):
    """A special point of a branch, located between points ``index`` and ``index + 1``.

    An event is a fact about the branch, not an outcome: an event that cannot be located is not reported.

    Attributes
    ----------
    kind : str
        ``"fold"`` (a limit point: ``t`` turns back; snap-through under this control),
        ``"branch_point"`` (a simple bifurcation: another branch crosses; :func:`~.diagram.switch_branch`),
        ``"joint_limit"`` (a joint reaches its range bound, ``|q_i| = (1 - LIMIT_MARGIN)(pi - 2 beta_i)``:
        the branch ends), ``"spring_slack"`` / ``"spring_taut"`` (a tension-only spring reaches its rest length
        and goes slack / taut: the joint's stiffness jumps; ``joint``, ``spring``, ``stiffness_before``,
        ``stiffness_after``).
    index : int
    t, q, force, tip, energy
        The point itself (inside the open range).
    null_vector : ndarray (n,) or None
        The joint-angle part of the right null vector of ``R_z`` (largest entry +1), the buckling or
        snapping mode; None for a joint limit.
    morse_before, morse_after : int
        Morse index at points ``index`` and ``index + 1``.
    stability : str
        ``"lost"`` (stable before, not after), ``"gained"`` or ``"unchanged"``.
    method : str
        How it was located: ``"moore_spence"`` (the fold's extended system), ``"test_function"`` (the
        root of the eigenvalue along the branch), ``"limit"``.
    residual : float
        Scaled residual of the equilibrium equations at the point.
    joint : int or None
        The joint at its limit (0-based), for ``"joint_limit"``; the segment whose spring changes state, for the
        spring events.
    spring : int or None
        Which of the segment's springs (1 or 2), for the spring events.
    stiffness_before, stiffness_after : float or None
        The joint's stiffness ``d^2E/dq^2`` on either side of a spring event (one-sided: the springs' states
        before and after).
    spring_lengths, spring_stretches, spring_forces, spring_states : ndarray (n, 2)
        The springs at ``q`` (:class:`~tensegrity_opt.model.springs.SpringFields`).
    """

    kind: str
    index: int
    t: float
    q: np.ndarray
    force: np.ndarray
    tip: np.ndarray
    energy: float
    null_vector: np.ndarray | None
    morse_before: int
    morse_after: int
    stability: str
    method: str
    residual: float
    joint: int | None = None
    x: np.ndarray | None = field(default=None, repr=False)
    null_x: np.ndarray | None = field(default=None, repr=False)
    springs: Springs | None = field(default=None, repr=False, compare=False)
    spring: int | None = None
    stiffness_before: float | None = None
    stiffness_after: float | None = None

    def __post_init__(self) -> None:
        for a in (self.q, self.force, self.tip, self.null_vector, self.x, self.null_x):   # the builder's own arrays
            if a is not None:
                a.setflags(write=False)

    def to_dict(self) -> dict[str, Any]:
        """JSON form (an item of a branch's ``events``)."""
        return {**self.spring_dict(), "kind": self.kind, "index": int(self.index), "t": number(self.t),
                "q": numbers(self.q),
                "force": {"fx": number(self.force[0]), "fy": number(self.force[1])}, "tip": numbers(self.tip),
                "energy": number(self.energy),
                "null_vector": None if self.null_vector is None else numbers(self.null_vector),
                "morse_before": int(self.morse_before), "morse_after": int(self.morse_after),
                "stability": self.stability, "method": self.method, "residual": nullable(self.residual),
                "joint": self.joint, "spring": self.spring,
                "stiffness_before": None if self.stiffness_before is None else number(self.stiffness_before),
                "stiffness_after": None if self.stiffness_after is None else number(self.stiffness_after)}


def _on_step(prob: PathProblem, a: PathPoint, b: PathPoint, sigma: float, h: float) -> np.ndarray | None:
    """The branch point at scaled arclength ``sigma`` beyond ``a`` (secant-guided)."""
    guess = a.x + (b.x - a.x) * (sigma / h if h > 0 else 0.0)
    y, _ = prob.correct(guess, a.tau, float(a.tau @ (prob.w * a.x)) + sigma)
    return y


def _brent(f, lo: float, hi: float, flo: float, fhi: float) -> float:
    if flo == 0.0:
        return lo
    if fhi == 0.0:
        return hi
    return so.brentq(f, lo, hi, xtol=1e-14 * max(1.0, hi), rtol=4 * np.finfo(float).eps, maxiter=80)


class _Unlocatable(Exception):
    pass


def _locate_eigen(prob: PathProblem, a: PathPoint, b: PathPoint, h: float, j: int) -> np.ndarray:
    """The point between ``a`` and ``b`` where the ``j``-th smallest reduced eigenvalue vanishes."""
    def g(sig: float) -> float:
        y = a.x if sig == 0.0 else (b.x if sig == h else _on_step(prob, a, b, sig, h))
        if y is None:
            raise _Unlocatable
        w = prob.reduced(y)[0]
        return float(w[j + k]) / prob.m.torque_scale

    k = prob.held_rows.shape[0]
    ga, gb = float(a.w[j + k]) / prob.m.torque_scale, float(b.w[j + k]) / prob.m.torque_scale
    if ga * gb > 0:
        raise _Unlocatable
    sig = _brent(g, 0.0, h, ga, gb)
    y = _on_step(prob, a, b, sig, h) if 0.0 < sig < h else (a.x if sig == 0.0 else b.x)
    # a sign change without a zero (the trial points crossed onto another branch) locates nothing
    if y is None or abs(float(prob.reduced(y)[0][j + k])) > ZERO_EIG * prob.m.torque_scale:
        raise _Unlocatable
    return y


def _locate_turn(prob: PathProblem, a: PathPoint, b: PathPoint, h: float) -> np.ndarray:
    """The point between ``a`` and ``b`` where the tangent's ``t`` component vanishes."""
    def g(sig: float) -> float:
        y = _on_step(prob, a, b, sig, h) if 0.0 < sig < h else (a.x if sig == 0.0 else b.x)
        if y is None:
            raise _Unlocatable
        return float(prob.tangent(y, a.tau)[at_t])

    at_t = prob.point["t"]
    return _on_step(prob, a, b, _brent(g, 0.0, h, float(a.tau[at_t]), float(b.tau[at_t])), h) \
        if a.tau[at_t] * b.tau[at_t] < 0 else b.x


def _null(prob: PathProblem, x: np.ndarray):
    """Right and left null vectors of ``R_z`` (smallest singular pair) and ``R_t``, at ``x``."""
    _, Rx = prob.eval(x)
    Rz = Rx[:, prob.point.span("q", "F")]
    U, S, Vt = np.linalg.svd(Rz)
    return Vt[-1], U[:, -1], Rx[:, prob.point["t"]], S


def moore_spence(prob: PathProblem, x: np.ndarray, phi: np.ndarray, *, s: float = 0.0, iters: int = 20):
    """Newton on the fold system ``R(z, t) = 0, R_z phi = 0, l . phi = 1`` (``l`` the start's ``phi``).

    Returns ``(x, phi)`` converged, or ``None``. Regular at a quadratic fold (not at a branch point).
    """
    at, rows, col = prob.ps.layouts.fold, prob.ps.layouts.fold_rows, prob.point
    x_at, z_at = at.span("q", "t"), col.span("q", "F")
    ell = phi / float(phi @ phi)
    y = at.pack(**col.unpack(x), phi=phi / float(ell @ phi))
    for _ in range(iters):
        xs, ph = y[x_at], y[at["phi"]]
        R, Rx = prob.eval(xs, s)
        Rzv, dRzv, _ = prob.ps.second(prob.full(xs, s), ph, prob.p, prob.dp, prob.dp2, prob.ctl)
        G = rows.pack(R=R, Rz_phi=Rzv, norm=ell @ ph - 1.0)
        if prob.residual(R) <= NEWTON_TOL and float(np.abs(Rzv * prob.rs).max()) <= 1e-10:
            return xs, ph
        M = np.zeros((rows.size, at.size))
        M[rows["R"], x_at] = Rx
        M[rows["Rz_phi"], x_at] = dRzv[:, prob.ps.point.span("q", "t")]
        M[rows["Rz_phi"], at["phi"]] = Rx[:, z_at]
        M[rows["norm"], at["phi"]] = ell
        try:
            dy = np.linalg.solve(M, -G)
        except np.linalg.LinAlgError:
            return None
        y = y + dy
        if not np.all(np.isfinite(y)):
            return None
    return None


def _make_event(prob: PathProblem, kind: str, index: int, x: np.ndarray, a: PathPoint, b: PathPoint, method: str,
                null: np.ndarray | None, joint: int | None = None, null_x: np.ndarray | None = None) -> BranchEvent:
    R, _ = prob.eval(x)
    _, _, E, tip = prob.reduced(x)
    nv = None
    if null is not None:
        nq = null[prob.ps.layouts.z["q"]]
        big = int(np.argmax(np.abs(nq)))
        nv = nq / nq[big] if nq[big] != 0.0 else nq.copy()
    stab = ("lost" if a.stable and not b.stable else "gained" if b.stable and not a.stable else "unchanged")
    at = prob.point
    return BranchEvent(kind, index, float(x[at["t"]]), x[at["q"]].copy(), x[at["F"]].copy(), tip.copy(),
                       float(E), nv, a.morse, b.morse, stab, method, prob.residual(R), joint, x.copy(),
                       None if null_x is None else null_x.copy(), prob.springs_at(float(x[at["t"]])))


def _singular_events(prob: PathProblem, index: int, a: PathPoint, b: PathPoint, h: float) -> list[BranchEvent]:
    """Folds and branch points between two accepted points (located; see the module docstring)."""
    out = []
    at_t = prob.point["t"]
    turned = a.tau[at_t] * b.tau[at_t] < 0
    lo, hi = sorted((a.morse, b.morse))
    crossings = list(range(lo, hi))
    if not crossings and turned:
        crossings = [None]
    for j in crossings:
        try:
            x = _locate_eigen(prob, a, b, h, j) if j is not None else _locate_turn(prob, a, b, h)
        except (_Unlocatable, ValueError, RuntimeError):
            x = None
        if x is None:
            continue
        phi, u, Rt, _ = _null(prob, x)
        ratio = abs(float(u @ Rt)) / max(float(np.linalg.norm(Rt)), 1e-300)
        kind = "fold" if (turned and ratio > BP_TOL) or (not turned and ratio > 1e-3) else "branch_point"
        method = "test_function"
        if kind == "fold":
            ms = moore_spence(prob, x, phi)
            if ms is not None and np.abs((ms[0] - x) * prob.w).max() < 1e-4:
                x, phi = ms
                method = "moore_spence"
        out.append(_make_event(prob, kind, index, x, a, b, method, phi, null_x=phi))
    return out


def _joint_stiffness(seg, q: float, taut: tuple[bool, bool]) -> float:
    """``d^2E/dq^2`` of one segment at ``q`` with its springs in the states ``taut`` (a taut spring at its rest
    length counts with its ``k L'^2``: the one-sided stiffness of that side)."""
    L, (d, dd) = seg.spring_lengths(q), seg.spring_rates(q)
    out = 0.0
    for i, (t, k, L0) in enumerate(((taut[0], seg.k1, seg.L1_0), (taut[1], seg.k2, seg.L2_0))):
        if t:
            out += k * (d[i] * d[i] + (L[i] - L0) * dd[i])
    return float(out)


def _spring_events(prob: PathProblem, index: int, a: PathPoint, b: PathPoint, h: float
                   ) -> list[tuple[float, BranchEvent]]:
    """The tension-only springs that go slack or taut between ``a`` and ``b``: each located at the zero of its
    stretch ``L - L0`` along the step (Brent's method, the corrector solving each trial point), with the joint's
    stiffness ``d^2E/dq^2`` on either side (``(sigma, event)`` pairs)."""
    m = prob.m
    if m.linear_springs:
        return []
    at = prob.point
    ra = prob.springs_at(float(a.x[at["t"]])).stretches(a.x[at["q"]])
    rb = prob.springs_at(float(b.x[at["t"]])).stretches(b.x[at["q"]])
    out = []
    for j, i in zip(*np.nonzero((ra > 0.0) != (rb > 0.0))):
        seg = m.segments[int(j)]
        if not seg.tension_only:
            continue

        def g(sig: float, j=int(j), i=int(i)) -> float:
            y = a.x if sig == 0.0 else (b.x if sig == h else _on_step(prob, a, b, sig, h))
            if y is None:
                raise _Unlocatable
            return float(prob.springs_at(float(y[at["t"]])).stretches(y[at["q"]])[j, i])

        try:
            sig = _brent(g, 0.0, h, float(ra[j, i]), float(rb[j, i]))
            y = a.x if sig == 0.0 else (b.x if sig == h else _on_step(prob, a, b, sig, h))
        except (_Unlocatable, ValueError, RuntimeError):
            continue
        if y is None:
            continue
        qj = float(y[at["q"]][j])
        sp = prob.springs_at(float(y[at["t"]]))
        seg = seg.replace(L0=(float(sp.L0[j, 0]), float(sp.L0[j, 1])))       # its rest lengths there
        state = [bool(s) for s in (sp.stretches(y[at["q"]])[j] > 0.0)]
        before, after = list(state), list(state)
        before[i], after[i] = bool(ra[j, i] > 0.0), bool(rb[j, i] > 0.0)
        kind = "spring_slack" if before[i] else "spring_taut"
        ev = _make_event(prob, kind, index, y, a, b, "test_function", None, joint=int(j))
        out.append((sig, dataclasses.replace(ev, spring=int(i) + 1,
                                             stiffness_before=_joint_stiffness(seg, qj, tuple(before)),
                                             stiffness_after=_joint_stiffness(seg, qj, tuple(after)))))
    return out


def events_between(prob: PathProblem, index: int, a: PathPoint, b: PathPoint, h: float) -> list[BranchEvent]:
    """The folds and branch points between the accepted points ``a`` (number ``index``) and ``b``, ``h`` apart in
    scaled arclength: none unless the Morse index changes or ``t`` turns back (located; module docstring); then the
    tension-only springs going slack or taut between them (:func:`_spring_events`), in their order along the step."""
    at_t = prob.point["t"]
    out = []
    if b.morse != a.morse or a.tau[at_t] * b.tau[at_t] < 0:
        out = _singular_events(prob, index, a, b, h)
    springs = _spring_events(prob, index, a, b, h)
    return out + [e for _, e in sorted(springs, key=lambda se: se[0])]


def locate_joint_limit(prob: PathProblem, a: PathPoint, b: PathPoint, h: float) -> tuple[np.ndarray, float] | None:
    """``(x, sigma)``: the point between ``a`` and ``b`` (``h`` apart) where the largest ``|q_i| / limit_i``
    reaches ``1 - LIMIT_MARGIN``, at scaled arclength ``sigma`` from ``a``; None when it cannot be located."""
    target = 1.0 - LIMIT_MARGIN

    def g(sig: float) -> float:
        yy = _on_step(prob, a, b, sig, h)
        if yy is None:
            raise _Unlocatable
        return prob.limit_ratio(yy)[0] - target

    try:
        sig = _brent(g, 0.0, h, prob.limit_ratio(a.x)[0] - target, prob.limit_ratio(b.x)[0] - target)
        y = _on_step(prob, a, b, sig, h)
    except (_Unlocatable, ValueError, RuntimeError):
        return None
    return None if y is None else (y, sig)


def joint_limit_events(prob: PathProblem, index: int, a: PathPoint, end: PathPoint, sigma: float) -> list[BranchEvent]:
    """The events from ``a`` (number ``index``) to ``end``, the point at a joint limit ``sigma`` beyond it
    (:func:`locate_joint_limit`): the folds and branch points on the way, then the joint limit."""
    out = events_between(prob, index, a, end, sigma)
    out.append(_make_event(prob, "joint_limit", index, end.x, a, end, "limit", None,
                           joint=prob.limit_ratio(end.x)[1]))
    return out


def load_compliance(prob: PathProblem, x: np.ndarray, d: np.ndarray) -> tuple[float, float]:
    """``(c, dc/dt)`` at the point ``x`` of a dead-load path ``F = base + t d`` (free or guided): the tip's
    compliance along the load ``c = d . dtip/dt = 1 / k`` (``k`` the tangent stiffness; free ``d . C d``,
    guided the compliance in ``x`` with ``y`` held, ``C = J H^-1 J^T``) and its rate along the path.

    Exact: the path's tangent ``z' = -R_z^-1 R_t``, its second derivative ``z'' = -R_z^-1 R_xx[x', x']``
    (``x' = (z', 1)``, the path system's ``curvature``) and ``tip'' = J q'' + tip_qq[q', q']``, so
    ``dc/dt = d . tip''``; ``(inf, nan)`` where ``R_z`` is singular (a fold or a branch point)."""
    at = prob.point
    R, Rx = prob.eval(x)
    Rz, Rt = Rx[:, at.span("q", "F")], Rx[:, at["t"]]
    try:
        zp = -np.linalg.solve(Rz, Rt)
    except np.linalg.LinAlgError:
        return math.inf, math.nan
    xp = np.zeros(prob.ps.point.size)
    xp[at.span("q", "F")] = zp
    xp[at["t"]] = 1.0
    Rxx, tip_xx = prob.ps.curvature(prob.full(x), xp, prob.p, prob.dp, prob.dp2, prob.ctl)
    J = prob.eval_all(x)[3]
    zpp = -np.linalg.solve(Rz, Rxx)
    q = prob.ps.layouts.z["q"]
    return float(d @ (J @ zp[q])), float(d @ (J @ zpp[q] + tip_xx))


def locate_stiffness_minimum(prob: PathProblem, xa: np.ndarray, xb: np.ndarray, d: np.ndarray,
                             rate_a: float, rate_b: float) -> tuple[np.ndarray, float] | None:
    """``(x, c)``: the point between the path points ``xa`` and ``xb`` (``t`` growing, no fold between them)
    where the compliance along the load is largest (the stiffness least), ``dc/dt`` there zero, with ``c``
    there (:func:`load_compliance`; ``rate_a > 0 > rate_b`` its rates at the two points); None when it cannot be
    located. Brent's method on ``t``, each trial point corrected at its ``t`` from the chord."""
    at_t = prob.point["t"]
    ta, tb = float(xa[at_t]), float(xb[at_t])

    def solve(t: float) -> np.ndarray:
        y, _ = prob.correct_t(xa + (xb - xa) * ((t - ta) / (tb - ta)), t)
        if y is None:
            raise _Unlocatable
        return y

    def rate(t: float) -> float:
        g = load_compliance(prob, solve(t), d)[1]
        if not math.isfinite(g):
            raise _Unlocatable
        return g

    if not (tb > ta and rate_a > 0.0 > rate_b):
        return None
    try:
        y = solve(_brent(rate, ta, tb, rate_a, rate_b))
    except (_Unlocatable, ValueError, RuntimeError):
        return None
    c = load_compliance(prob, y, d)[0]
    return (y, c) if math.isfinite(c) and c > 0.0 else None
