"""Stability boundaries: the limit or critical load against a design or control parameter.

:func:`stability_boundary` follows the first point where a branch loses stability (a fold or a branch
point of :func:`~tensegrity_opt.analyses.paths.branches.trace_branch`) as a second parameter ``p`` moves the
chain along a direction in its parameter space (:data:`PARAMETERS`: a preload asymmetry, both rest
lengths, ``a``, ``b``, the stiffness, or any direction of the ``6n`` numbers). These are curves of singular
points with the control's references fixed; the limit load an imperfect arm reaches when loaded from its own
rest shape is :func:`~tensegrity_opt.analyses.paths.imperfection.imperfection_sensitivity`.

* **Folds** are continued by pseudo-arclength on the Moore-Spence system in ``Y = (z, t, phi, p)``::

      R(z, t; p) = 0,   R_z(z, t; p) phi = 0,   l . phi = 1

  (``2N + 1`` equations, ``2N + 2`` unknowns: a curve), predictor along the null vector of its Jacobian,
  Newton corrector on the bordered system, adaptive step. This system stays regular where a
  symmetry-breaking parameter (``"asymmetry"``) unfolds a pitchfork of the straight chain: the curve
  passes through the branch point, whose projection on ``(p, t)`` is a **cusp** (the fold load tends to the
  critical load like ``|p|^(2/3)`` near it). Cusps are marked where the fold's
  quadratic coefficient ``u . R_zz[phi, phi]`` (``u`` the left null vector, oriented continuously)
  changes sign, located by Brent's method along the curve.
* **Branch points** persist only by symmetry (the straight symmetric chain under a symmetric
  parameter: ``a``, ``b``, ``L0``, ``k``), where the Moore-Spence system is singular. They are followed
  in ``p`` by natural-parameter steps, each point the first stability-losing branch point of the branch
  traced on the chain at that ``p`` (located there by the test function, :mod:`.branches`).

Which case applies is decided at the start point: the Moore-Spence Jacobian with the ``p`` column has
full rank (a fold, or a branch point that the parameter unfolds) or not (a branch point it keeps).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np
import scipy.optimize as so

from ...errors import InvalidParameterError, NoEquilibriumError, TensegrityError
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...model.segment import Segment
from ...model.springs import linear_only
from ...numerics.layout import chain_parameters
from ...outcome import Outcome, freeze
from ...serialize import number, numbers
from ...timelimit import expired, time_limit
from .branches import Branch, trace_branch
from .control import Control, as_control
from .events import BranchEvent
from .problem import NEWTON_TOL, PathProblem

__all__ = ["StabilityBoundary", "BoundaryPoint", "stability_boundary", "parameter_direction", "chain_at", "PARAMETERS"]

#: Named parameter directions: ``p`` is added to these entries of every segment.
PARAMETERS = ("asymmetry", "L0", "a", "b", "k")
#: Smallest singular value of the Moore-Spence Jacobian (relative to its largest) for the regular case.
RANK_TOL = 1e-8
#: The blocks of the chain's parameters (:func:`tensegrity_opt.numerics.layout.chain_parameters`) each named
#: direction moves, and by how much per unit ``p``.
_MOVES = {"asymmetry": {"L10": 1.0, "L20": -1.0},        # L1_0 = L0 + p, L2_0 = L0 - p
          "L0": {"L10": 1.0, "L20": 1.0}, "a": {"a": 1.0}, "b": {"b": 1.0}, "k": {"k1": 1.0, "k2": 1.0}}


def parameter_direction(m: Manipulator, parameter) -> tuple[str, np.ndarray]:
    """``(name, dp)``: the direction ``dp`` a parameter moves, ``6n`` numbers in the order of
    :attr:`Manipulator.params <tensegrity_opt.Manipulator.params>` (the blocks of
    :func:`~tensegrity_opt.numerics.layout.chain_parameters`): the ``n`` values of ``a`` (segment 1 to n), then
    the ``n`` of ``b``, of ``k1``, ``k2``, ``L1_0`` and ``L2_0``.

    ``parameter`` is a name of :data:`PARAMETERS`, or such a direction: ``6n`` numbers in that order, or a
    ``(6, n)`` array whose rows are ``a, b, k1, k2, L1_0, L2_0`` (a column per segment). Any other shape — e.g.
    ``(n, 6)``, a row per segment — is refused."""
    at = chain_parameters(m.n)
    if isinstance(parameter, str):
        if parameter in _MOVES:
            d = at.pack(**{**dict.fromkeys(at.places, 0.0), **_MOVES[parameter]})
        else:
            raise InvalidParameterError(f"parameter must be one of {PARAMETERS} or a vector of 6n numbers, got "
                                        f"{parameter!r}", field="parameter")
        return parameter, d
    order = ("6n numbers in the order of Manipulator.params: the n values of a (segment 1 to n), then of b, k1, k2, "
             "L1_0 and L2_0; or a (6, n) array with these rows")
    try:
        d = np.asarray(parameter, dtype=float)
    except (TypeError, ValueError):
        raise InvalidParameterError(f"parameter must be a name or a direction: {order}", field="parameter") from None
    if d.shape not in ((at.size,), (len(at.places), m.n)):
        raise InvalidParameterError(f"a parameter direction of n = {m.n} segments is {order} (shape "
                                    f"({at.size},) or (6, {m.n})), got shape {d.shape}", field="parameter")
    d = d.ravel()
    if not np.all(np.isfinite(d)) or not np.any(d):
        raise InvalidParameterError(f"a parameter direction has 6n = {at.size} finite numbers, not all zero",
                                    field="parameter")
    return "direction", d


def _chain_at(m: Manipulator, dp: np.ndarray, p: float) -> Manipulator:
    v = chain_parameters(m.n).unpack(np.array(m.params) + p * dp)
    return Manipulator(Segment(a, b, (k1, k2), (l1, l2))
                       for a, b, k1, k2, l1, l2 in zip(*(v[k] for k in ("a", "b", "k1", "k2", "L10", "L20"))))


def chain_at(m: Manipulator, parameter, p: float) -> Manipulator:
    """The chain ``m`` moved by ``p`` along a parameter (a name of :data:`PARAMETERS` or a direction, as
    :func:`parameter_direction`): for ``"asymmetry"`` every segment's rest lengths become ``L1_0 + p`` and
    ``L2_0 - p`` (a symmetric segment of rest length ``L0``: ``L0 + p``, ``L0 - p``, pre-bent towards its
    shorter spring). ``p = 0`` is ``m`` itself; :func:`stability_boundary` and
    :func:`~.imperfection.imperfection_sensitivity` move the chain this way."""
    return _chain_at(m, parameter_direction(m, parameter)[1], float(p))


@dataclass(frozen=True)
class BoundaryPoint:
    """A special point of a boundary (a cusp): the parameter, the load, the configuration. A fact about the
    boundary, not an outcome."""

    kind: str
    p: float
    t: float
    q: np.ndarray
    force: np.ndarray

    def __post_init__(self) -> None:
        freeze(self)

    def to_dict(self) -> dict[str, Any]:
        """``{kind, p, t, q, force {fx, fy}}``."""
        return {"kind": self.kind, "p": number(self.p), "t": number(self.t), "q": numbers(self.q),
                "force": {"fx": number(self.force[0]), "fy": number(self.force[1])}}


@dataclass(frozen=True)
class StabilityBoundary(Outcome):
    """The limit (fold) or critical (branch-point) load ``t`` against the parameter ``p``.

    Attributes
    ----------
    kind : str
        Which curve it is: ``"fold"`` (a fold continued by the Moore-Spence system) or ``"branch_point"`` (a
        branch point kept by symmetry). Neither is the imperfection-sensitivity curve of an arm loaded from its
        rest shape (:func:`~.imperfection.imperfection_sensitivity`).
    parameter : str
        Its name (or ``"direction"``); ``parameter_direction`` the 6n direction, in the order of
        :attr:`Manipulator.params <tensegrity_opt.Manipulator.params>` (:func:`parameter_direction`).
    p, t : ndarray (P,)
        Along the curve (``p = 0`` is the given chain).
    q : ndarray (P, n)
    force : ndarray (P, 2)
    null_vectors : ndarray (P, n)
        The mode at each point (largest entry +1).
    cusps : tuple of BoundaryPoint
    status : str
        How the curve ended (:attr:`STATUSES`; a fold curve: the end on the ``p_max`` side unless that is
        ``"p_range"``, then the other side's).
    message : str
        How each side ended, in words.
    control : Control
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "p_range": "p left [p_min, p_max]",
        "max_points": "max_points points were computed on a side",
        "joint_limit": "the fold configuration reached a joint limit",
        "ended": "the branch point of the symmetric chain is not found beyond the last p (it ends there)",
        "step_too_small": "the fold curve could not be continued (the step fell below its minimum)",
        "time_limit": "the time limit ran out (the points computed are kept)",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"p_range", "max_points", "joint_limit", "ended"})

    kind: str
    parameter: str
    parameter_direction: np.ndarray
    p: np.ndarray
    t: np.ndarray
    q: np.ndarray
    force: np.ndarray
    null_vectors: np.ndarray
    cusps: tuple
    status: str
    message: str
    control: Control
    start: BranchEvent | None = field(default=None, repr=False)

    def __post_init__(self) -> None:
        freeze(self)

    def to_dict(self) -> dict[str, Any]:
        """JSON form (the body of ``POST /v1/stability-boundary``): ``success``, ``status``, ``message``,
        ``kind``, ``parameter``, ``control``, ``points``, ``p``, ``t``, ``q``, ``force``, ``null_vectors``,
        ``cusps``."""
        return {**self.outcome(), "kind": self.kind, "parameter": self.parameter, "control": self.control.to_dict(),
                "points": int(self.p.size), "p": numbers(self.p), "t": numbers(self.t),
                "q": [numbers(r) for r in self.q],
                "force": [{"fx": number(f[0]), "fy": number(f[1])} for f in self.force],
                "null_vectors": [numbers(r) for r in self.null_vectors],
                "cusps": [c.to_dict() for c in self.cusps]}


class _Fold:
    """The Moore-Spence system of one problem in ``Y = (z, t, phi, p)`` (the blocks ``q, F, t, phi, p`` of
    the path system's ``fold_curve`` layout); its rows ``R``, ``R_z phi`` and ``l . phi = 1`` (``fold_rows``)."""

    def __init__(self, prob: PathProblem, ell: np.ndarray, p_scale: float) -> None:
        self.prob, self.ell = prob, ell
        self.rows = prob.ps.layouts.fold_rows
        self.at = at = prob.ps.layouts.fold_curve
        self.x_at = at.span("q", "t")
        pt = prob.ps.point                  # the columns of the path system's Jacobians
        self.x_cols, self.z_cols, self.p_col = pt.span("q", "t"), pt.span("q", "F"), pt["s"]
        self.w = at.pack(**prob.point.unpack(prob.w), phi=1.0, p=1.0 / p_scale)

    def split(self, Y):
        """``(x, phi, p)``: the branch point, the null vector, the parameter."""
        return Y[self.x_at], Y[self.at["phi"]], float(Y[self.at["p"]])

    def G(self, Y):
        prob, at, rows = self.prob, self.at, self.rows
        x, ph, p = self.split(Y)
        R, Rx, *_ = prob.ps.evaluate(prob.full(x, p), prob.p, prob.dp, prob.dp2, prob.ctl)
        Rzv, dRzv, _ = prob.ps.second(prob.full(x, p), ph, prob.p, prob.dp, prob.dp2, prob.ctl)
        G = rows.pack(R=R, Rz_phi=Rzv, norm=self.ell @ ph - 1.0)
        M = np.zeros((rows.size, at.size))
        M[rows["R"], self.x_at] = Rx[:, self.x_cols]
        M[rows["R"], at["p"]] = Rx[:, self.p_col]
        M[rows["Rz_phi"], self.x_at] = dRzv[:, self.x_cols]
        M[rows["Rz_phi"], at["p"]] = dRzv[:, self.p_col]
        M[rows["Rz_phi"], at["phi"]] = Rx[:, self.z_cols]
        M[rows["norm"], at["phi"]] = self.ell
        return G, M

    def residual(self, G) -> float:
        prob, rows = self.prob, self.rows
        return max(float(np.abs(G[rows["R"]] * prob.rs).max()), float(np.abs(G[rows["Rz_phi"]] * prob.rs).max()),
                   abs(float(G[rows["norm"]])))

    def correct(self, Y, a, b, iters: int = 15):
        Y = Y.copy()
        aw = a * self.w
        for it in range(iters):
            G, M = self.G(Y)
            g = float(aw @ Y - b)
            if self.residual(G) <= NEWTON_TOL and abs(g) < 1e-12:
                return Y, it
            try:
                dY = np.linalg.solve(np.vstack([M, aw]), -np.concatenate([G, [g]]))
            except np.linalg.LinAlgError:
                return None, it
            Y = Y + dY
            if not np.all(np.isfinite(Y)):
                return None, it
        G, _ = self.G(Y)
        return (Y, iters) if self.residual(G) <= NEWTON_TOL * 10 else (None, iters)

    def tangent(self, Y, prev):
        _, M = self.G(Y)
        A = M / self.w
        if prev is not None:
            rhs = np.zeros(A.shape[1])
            rhs[-1] = 1.0
            try:
                v = np.linalg.solve(np.vstack([A, prev]), rhs)
                return v / np.linalg.norm(v)
            except np.linalg.LinAlgError:
                pass
        v = np.linalg.svd(A)[2][-1]
        return v if prev is None or v @ prev >= 0 else -v

    def cusp_coefficient(self, Y, u_ref):
        """``u . R_zz[phi, phi]`` (normalised), ``u`` the left null vector of ``R_z`` oriented along ``u_ref``."""
        prob = self.prob
        x, ph, p = self.split(Y)
        _, Rx, *_ = prob.ps.evaluate(prob.full(x, p), prob.p, prob.dp, prob.dp2, prob.ctl)
        U = np.linalg.svd(Rx[:, self.z_cols])[0]
        u = U[:, -1]
        if u_ref is not None and u @ u_ref < 0:
            u = -u
        _, _, Rzz = prob.ps.second(prob.full(x, p), ph, prob.p, prob.dp, prob.dp2, prob.ctl)
        return float(u @ (Rzz * prob.rs)) / max(float(np.linalg.norm(ph * prob.w[self.z_cols])) ** 2, 1e-300), u


def _null_q(ph: np.ndarray, at) -> np.ndarray:
    """The joint-angle part of the null vector ``ph`` (its ``q`` block in the layout ``at``), largest entry +1."""
    nq = ph[at["q"]]
    j = int(np.argmax(np.abs(nq)))
    return nq / nq[j] if nq[j] != 0 else nq.copy()


def _fold_half(fs: _Fold, Y0, tau0, p_min, p_max, max_points, step, max_step):
    prob, at = fs.prob, fs.prob.point
    pts, taus = [Y0], [tau0]
    cus = []
    u_prev = fs.cusp_coefficient(Y0, None)[1]
    c_prev = fs.cusp_coefficient(Y0, u_prev)[0]
    h = step
    status, message = "max_points", ""
    while len(pts) < max_points:
        if expired():
            status, message = "time_limit", "the time limit ran out"
            break
        Ya, ta = pts[-1], taus[-1]
        Yp = Ya + h * ta / fs.w
        Y, it = fs.correct(Yp, ta, float(ta @ (fs.w * Ya)) + h)
        ok = Y is not None
        if ok:
            tb = fs.tangent(Y, ta)
            ok = float(tb @ ta) > math.cos(0.3) and np.linalg.norm(fs.w * Y - fs.w * Yp) <= 0.5 * h
        if not ok:
            h *= 0.5
            if h < 1e-8:
                status, message = "step_too_small", "the fold curve could not be continued"
                break
            continue
        x, _, p = fs.split(Y)
        if np.any(np.abs(x[at["q"]]) >= prob.limits * (1 - 1e-6)):
            status, message = "joint_limit", "the fold configuration reached a joint limit"
            break
        c, u = fs.cusp_coefficient(Y, u_prev)
        if c * c_prev < 0:
            def g(sig, Ya=Ya, ta=ta, Y=Y):
                yy, _ = fs.correct(Ya + (Y - Ya) * sig / h, ta, float(ta @ (fs.w * Ya)) + sig)
                if yy is None:
                    raise ValueError
                return fs.cusp_coefficient(yy, u_prev)[0]
            try:
                sig = so.brentq(g, 0.0, h, xtol=1e-13)
                yc, _ = fs.correct(Ya + (Y - Ya) * sig / h, ta, float(ta @ (fs.w * Ya)) + sig)
            except (ValueError, RuntimeError):
                yc = None
            if yc is not None:
                xc, _, pc = fs.split(yc)
                cus.append(BoundaryPoint("cusp", pc, float(xc[at["t"]]), xc[at["q"]].copy(), xc[at["F"]].copy()))
        c_prev, u_prev = c, u
        pts.append(Y)
        taus.append(tb)
        if p > p_max or p < p_min:
            status, message = "p_range", f"p left [{p_min:g}, {p_max:g}]"
            break
        h = min(max_step, h * (1.4 if it <= 3 else 1.0))
    return pts, cus, status, message


def _first_loss(br: Branch) -> BranchEvent | None:
    ev = [e for e in br.events if e.kind in ("fold", "branch_point") and e.stability == "lost"]
    if not ev:
        ev = [e for e in br.events if e.kind in ("fold", "branch_point")]
    return ev[0] if ev else None


def stability_boundary(m: Manipulator, control: Control | str = "guided", parameter="asymmetry", *, start=None,
                       p_min: float = -0.1, p_max: float = 0.1, max_points: int = 400, t_max: float | None = None,
                       step: float = 0.01, max_step: float = 0.05, timeout: float | None = None,
                       **control_kw) -> StabilityBoundary:
    """The first stability-losing fold or branch point of a branch, continued in a second parameter ``p``.

    The curve is the singular point itself, followed in ``p`` (:attr:`StabilityBoundary.kind`: ``"fold"`` or
    ``"branch_point"``), with the control's references fixed where they are at ``p = 0`` and the branch found at
    ``p = 0`` only. With ``parameter="asymmetry"`` and the guided load on the straight chain it is the curve of
    the fold where the branch bent *against* the pre-bend is born (guide fixed at ``y = 0``, start straight):
    loading the imperfect arm from its rest shape never reaches it. It is not the limit load an imperfect arm
    carries: that is :func:`~.imperfection.imperfection_sensitivity` (the dead-load path from the rest shape of
    each imperfect chain, the guide through its rest tip).

    Parameters
    ----------
    m : Manipulator
        The chain at ``p = 0``.
    control : Control or str
        The one-parameter control whose branch loses stability (:class:`~.branches.Control`; default the
        guided compression of the paper). Keywords of its constructor in ``control_kw``. Its references
        stay where they are at ``p = 0`` while ``p`` moves: a guide or wall through the start's tip (``y = 0``
        for the straight chain), a held tip at the start's position.
    parameter : str or array_like (6n,) or (6, n)
        ``"asymmetry"`` (``L1_0 = L0 + p``, ``L2_0 = L0 - p`` on every segment: a pre-bend), ``"L0"``
        (both rest lengths ``+ p``), ``"a"``, ``"b"``, ``"k"`` (both springs), or a direction in the
        chain's parameters: 6n numbers in the order of :attr:`Manipulator.params
        <tensegrity_opt.Manipulator.params>` — the n values of ``a`` (segment 1 to n), then the n of ``b``,
        ``k1``, ``k2``, ``L1_0``, ``L2_0`` — or a ``(6, n)`` array with these rows (:func:`parameter_direction`).
    start : Equilibrium, array_like or None
        The branch's start at ``p = 0`` (None: the rest configuration).
    p_min, p_max : float
        The range of ``p`` (the parameter's units).
    max_points, step, max_step : int, float
        Points per half-curve and arclength steps (scaled: angles, ``k c^2/2b`` forces, ``2b`` lengths).
    t_max : float, optional
        Bound of the one-parameter trace that finds the start event (default: 20 force scales).
    timeout : float, optional
        Seconds; the points so far are kept (``status="time_limit"``).

    Returns
    -------
    StabilityBoundary
        Sorted by arclength from ``p_min``'s side to ``p_max``'s; ``cusps`` on fold curves.

    Raises
    ------
    InvalidParameterError
        (``ValueError``) for a bad parameter or range.
    NoEquilibriumError
        (``RuntimeError``) when the branch at ``p = 0`` never loses stability before ``t_max``.
    """
    unloaded_only(m, "stability_boundary")
    linear_only(m, "stability_boundary")
    with time_limit(timeout):
        return _boundary(m, control, parameter, start, p_min, p_max, max_points, t_max, step, max_step, control_kw)


def _boundary(m, control, parameter, start, p_min, p_max, max_points, t_max, step, max_step, control_kw):
    for name, v in (("p_min", p_min), ("p_max", p_max), ("step", step), ("max_step", max_step)):
        if not isinstance(v, (int, float)) or not math.isfinite(v):
            raise InvalidParameterError(f"{name} must be a finite number, got {v!r}", field=name)
    if not p_min < 0.0 < p_max:
        raise InvalidParameterError("the range must contain p = 0 (the given chain): p_min < 0 < p_max",
                                    field="p_min")
    if isinstance(max_points, bool) or not isinstance(max_points, (int, np.integer)) or max_points < 2:
        raise InvalidParameterError(f"max_points must be an integer >= 2, got {max_points!r}", field="max_points")
    ctl = as_control(m, control, control_kw)
    name, dp2 = parameter_direction(m, parameter)
    probe = PathProblem(m, ctl, np.zeros(m.n), None)
    t_bound = 20.0 * (probe.Fs if ctl.kind in ("load", "guided", "wall") else probe.Ls) if t_max is None else t_max
    br = trace_branch(m, start, ctl, t_max=t_bound, stop_at="stability_loss")
    ev = _first_loss(br)
    if ev is None:
        raise NoEquilibriumError(f"the branch does not lose stability up to t = {t_bound:g} ({br.status}): no "
                                 "boundary to follow", status=br.status)
    prob: PathProblem = br.problem
    prob.dp2 = dp2
    p_scale = 1.0 if name == "k" else prob.Ls
    if name == "k":
        p_scale = float(max(np.max(m.k1), np.max(m.k2)))
    fs = _Fold(prob, ev.null_x / float(ev.null_x @ ev.null_x), p_scale)
    at = fs.at
    Y0 = at.pack(**prob.point.unpack(ev.x), phi=ev.null_x / float(fs.ell @ ev.null_x), p=0.0)
    G, M = fs.G(Y0)
    sv = np.linalg.svd(M / fs.w, compute_uv=False)
    regular = sv[-1] > RANK_TOL * sv[0]
    if regular:
        fix_p = np.zeros(at.size)
        fix_p[at["p"]] = 1.0 / fs.w[at["p"]]
        Yc, _ = fs.correct(Y0, fix_p, 0.0)
        if Yc is not None:
            Y0 = Yc
        tau0 = fs.tangent(Y0, None)
        if tau0[at["p"]] < 0:
            tau0 = -tau0
        up, cu_up, st_up, msg_up = _fold_half(fs, Y0, tau0, p_min, p_max, max_points, step, max_step)
        dn, cu_dn, st_dn, msg_dn = _fold_half(fs, Y0, -tau0, p_min, p_max, max_points, step, max_step)
        pts = dn[::-1] + up[1:]
        cusps = cu_dn[::-1] + cu_up
        if ev.kind == "branch_point":
            # the start itself: a pitchfork the parameter unfolds is the cusp of the fold curve
            cusps.insert(len(cu_dn), BoundaryPoint("cusp", 0.0, ev.t, ev.q.copy(), ev.force.copy()))
        Y = at.unpack(np.array(pts))
        status = st_up if st_up != "p_range" else st_dn
        message = "; ".join(s for s in (f"p up: {msg_up}", f"p down: {msg_dn}") if s)
        return StabilityBoundary("fold", name, dp2, Y["p"].copy(), Y["t"].copy(), Y["q"].copy(), Y["F"].copy(),
                                 np.array([_null_q(ph, prob.ps.layouts.z) for ph in Y["phi"]]), cusps, status, message,
                                 ctl, ev)
    return _branch_point_curve(m, ctl, name, dp2, ev, br, p_min, p_max, max_points, t_bound)


def _branch_point_curve(m, ctl, name, dp2, ev, br, p_min, p_max, max_points, t_bound):
    """Natural-parameter continuation in ``p`` of a branch point kept by symmetry (module docstring)."""
    span = p_max - p_min
    num = max(3, min(int(max_points), 41))
    out = {0.0: ev}
    status, message = "p_range", ""
    q_start = br.q[0]
    for sign, bound in ((1.0, p_max), (-1.0, p_min)):
        h = span / (num - 1)
        p, last = 0.0, ev
        while sign * (bound - p) > 1e-12:
            if expired():
                status, message = "time_limit", "the time limit ran out"
                break
            p_new = p + sign * min(h, abs(bound - p))
            try:
                mp = _chain_at(m, dp2, p_new)
                b = trace_branch(mp, q_start, ctl, t_max=max(t_bound, 2.0 * last.t), stop_at="stability_loss")
                e = _first_loss(b)
            except TensegrityError:
                e = None
            if e is None or e.kind != "branch_point":
                status, message = "ended", f"no branch point on the branch at p = {p_new:.6g}"
                break
            out[p_new] = e
            p, last = p_new, e
    ps = np.array(sorted(out))
    evs = [out[v] for v in ps]
    return StabilityBoundary("branch_point", name, dp2, ps, np.array([e.t for e in evs]), np.array([e.q for e in evs]),
                             np.array([e.force for e in evs]), np.array([e.null_vector for e in evs]), [], status,
                             message, ctl, ev)
