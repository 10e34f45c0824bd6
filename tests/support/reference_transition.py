"""Independent reference of a *transition*: the inputs of a chain moved linearly, the arm following quasi-statically.

Imports numpy, scipy and the other references of ``tests/support`` (``reference_model``, ``reference_paths``)
only -- it does NOT import ``tensegrity_opt``.

The model (``docs/model.md``, ``/work/shared/spec/conventions.md``): the control inputs are the rest lengths
``ell = (L1_0, L2_0)`` per segment (array ``(n, 2)``), a dead load ``F = (Fx, Fy)`` acts at the free tip. An
equilibrium under ``F`` is ``R(q) = grad_q [E(q; ell) - F . tip(q)] = 0`` (``Chain.lagrangian_grad``); it is stable
when the Hessian ``H`` of ``E - F . tip`` in ``q`` is positive definite, and its *margin* is the smallest eigenvalue
of ``H`` (torque per rad). A state is at a joint limit when ``max_i |q_i| / (pi - 2 beta_i) >= 1 - 1e-6``.

A transition moves the inputs together, ``ell(s) = ell0 + s (ell1 - ell0)``, ``F(s) = F0 + s (F1 - F0)``,
``s`` in ``[0, 1]``, from a stable equilibrium ``q0`` of ``(ell0, F0)``. :func:`transition` computes what the
overdamped, quasi-static arm does:

1. **Continuation** in the natural parameter ``s``: a tangent predictor ``dq/ds = -H^-1 dR/ds`` (``dR/ds`` is
   exact: ``grad E`` is affine in the rest lengths and ``F . tip`` in ``F``, so ``dR/ds = R(q; ell1, F1) -
   R(q; ell0, F0)``), a Newton corrector on the reference's own gradient and Hessian (``|R| < 1e-12 max k c^2``),
   steps up to ``ds_max``, doubled after a success. A step is *refused* when Newton does not converge, when the
   corrected point is far from the predicted one (``|q - q_pred| > 0.25 |q_pred - q_prev| + 1e-3``) or from the
   last point (``> 0.2`` rad), when it is unstable (margin <= 0) or at a joint limit.
2. **Event location** after a refused step: bisection on ``s`` between the last accepted point ``lo`` and the
   refused fraction ``hi``, each trial solved by plain Newton from the last good point (from the stable side of a
   fold Newton converges monotonically to the stable root), a trial good when it converges, stays within 0.2 rad,
   is stable and inside the range; down to ``hi - lo <= 1e-10``. If ``hi`` then solves from the final good point,
   the refusal was only the step's size and continuation resumes. Otherwise the event is a **joint limit** when
   the last good point's joint ratio is ``>= 1 - 2e-6`` (the transition ends there), a **loss of stability**
   (fold or branch point) when its margin is below ``1e-3 max k c^2``; anything else raises ``RuntimeError``.
3. **Snap** at a loss of stability: the inputs frozen at ``s* = hi`` (within ``1e-10`` past the last stable point
   ``q*``), the gradient flow ``dq/dtau = -grad V``, ``V = E(q; ell(s*)) - F(s*) . tip(q)``, is integrated by
   ``scipy.integrate.solve_ivp`` (LSODA, rtol 1e-10, atol 1e-12, the analytic Jacobian ``-H``) from ``q* + eps
   phi`` (``phi`` the eigenvector of the smallest eigenvalue at ``q*``, largest ``|entry|`` 1, ``eps = 1e-4`` rad)
   on the side of lower ``V``, with terminal events at a joint limit and where ``|grad V|`` falls below
   ``1e-9 max k c^2``; there, if ``H`` is positive definite, Newton polishes the landing (it must converge to a
   stable minimum); otherwise the flow goes on. From the landing the continuation resumes at ``s*``.
4. **Least margin** over the first followed stretch (``[0, 1]`` when nothing happens, else up to the first fold or
   joint limit): the smallest margin among the accepted points, refined by ``minimize_scalar(method="bounded")``
   on ``s`` between that sample's neighbours (each trial corrected at its ``s`` by Newton from the nearest
   accepted point below it).

The result, :class:`TransitionRef`: ``status`` "followed" (stable all along, ends on the branch at ``s = 1``),
"snapped" (one snap or more, ends on a stable equilibrium at ``s = 1``) or "joint_limit" (a joint reached its limit
on a branch or during a descent: no equilibrium in the range; ``q_end`` is where it reached it); ``q_end``,
``tip_end``; ``snaps`` the ``(s_star, q_before, q_after)`` per snap; ``min_margin``, ``min_margin_at`` over the
first stretch (``[0, stretch_end]``); ``fold_at`` the first ``s*`` (or None); ``limit_at`` the ``s`` of a joint
limit (or None); ``points`` (and ``tips``) the accepted ``(s, q, margin)`` samples; with ``margin`` given,
``margin_ok`` and ``margin_lost_at``.

``chain_at`` is a callable ``ell (n, 2) -> reference_model.Chain`` (the caller supplies geometry and stiffness,
e.g. ``lambda ell: reference_control.ref_chain(m, ell)``, or :func:`chain_factory` of arrays ``a, b, k1, k2``);
its chain must take ``L10 = ell[:, 0]``, ``L20 = ell[:, 1]`` (checked).

Not handled (documented limits): a *supercritical* branch point (a symmetric pitchfork whose bent branches are
stable, e.g. the straight paper chain under growing compression at ``P = 0.0761``): the flow from ``q* + eps phi``
settles within ``100 eps`` of ``q*`` and :class:`BranchPointError` is raised rather than report a "snap"; a fold
between two accepted points that is entered and left again within one step (the margin dipping below 0 and back)
is missed -- keep ``ds_max`` small.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable

import numpy as np
import reference_paths as RP  # noqa: E402
import scipy.integrate as si
import scipy.optimize as so
from reference_model import Chain

#: A state is at a joint limit when ``max |q_i| / limit_i`` reaches this.
LIMIT_RATIO = 1.0 - 1e-6
#: Newton's tolerance on ``|R|`` relative to the torque scale ``max k c^2``.
GRAD_TOL = 1e-12
#: Bisection resolution in ``s``.
S_TOL = 1e-10
#: Initial offset (rad, largest joint) of a descent from a fold.
EPS = 1e-4
#: The largest move (rad) of one accepted continuation or bisection step.
MAX_JUMP = 0.2

STATUSES = ("followed", "snapped", "joint_limit")


class BranchPointError(RuntimeError):
    """Stability lost at a supercritical branch point: the flow from the lost point settles next to it (a
    stable branch bifurcates there) -- no snap, and out of this reference's scope."""


def chain_factory(a, b, k1, k2) -> Callable[[np.ndarray], Chain]:
    """``chain_at`` for the geometry ``a, b`` and stiffnesses ``k1, k2`` (arrays of n, or scalars broadcast)."""
    def chain_at(ell):
        ell = np.asarray(ell, float).reshape(-1, 2)
        n = ell.shape[0]
        arr = [np.broadcast_to(np.asarray(x, float), (n,)).copy() for x in (a, b, k1, k2)]
        return Chain(*arr, ell[:, 0].copy(), ell[:, 1].copy())
    return chain_at


def joint_ratio(chain: Chain, q) -> float:
    """``max_i |q_i| / (pi - 2 beta_i)``."""
    return float(np.max(np.abs(np.asarray(q, float)) / chain.limits))


@dataclass
class TransitionRef:
    status: str                          # "followed" | "snapped" | "joint_limit"
    q_end: np.ndarray                    # the state at s = 1, or where a joint reached its limit
    tip_end: np.ndarray
    snaps: list = field(default_factory=list)          # (s_star, q_before, q_after) per snap
    min_margin: float = math.nan         # least margin over the first followed stretch
    min_margin_at: float = math.nan      # its s
    fold_at: float | None = None         # the first s* (a loss of stability), or None
    limit_at: float | None = None        # s at which a joint reached its limit, or None
    points: list = field(default_factory=list, repr=False)   # accepted (s, q, margin) on the branches
    tips: list = field(default_factory=list, repr=False)     # the tip at each of ``points``
    stretch_end: float = 1.0             # where the first followed stretch ends (fold, limit or 1)
    margin_ok: bool | None = None        # min_margin >= margin (when ``margin`` was given)
    margin_lost_at: float | None = None  # first s of the first stretch where the margin falls below ``margin``


class _Problem:
    """``R(q, s)``, its Hessian and ``dR/ds`` along the transition."""

    def __init__(self, chain_at, ell0, ell1, F0, F1):
        self.chain_at = chain_at
        self.ell0 = np.asarray(ell0, float)
        self.ell1 = np.asarray(ell1, float)
        if self.ell0.ndim != 2 or self.ell0.shape[1] != 2 or self.ell1.shape != self.ell0.shape:
            raise ValueError("ell0 and ell1 must be (n, 2) arrays of the same shape")
        self.F0 = np.asarray(F0, float).reshape(2)
        self.F1 = np.asarray(F1, float).reshape(2)
        self.c0 = chain_at(self.ell0)
        self.c1 = chain_at(self.ell1)
        for c, ell in ((self.c0, self.ell0), (self.c1, self.ell1)):
            if c.n != ell.shape[0] or not (np.array_equal(c.L10, ell[:, 0]) and np.array_equal(c.L20, ell[:, 1])):
                raise ValueError("chain_at(ell) must be the chain with L10 = ell[:, 0], L20 = ell[:, 1]")
        self.n = self.c0.n
        self.scale = float(np.max(np.maximum(self.c0.k1, self.c0.k2)) * np.max(self.c0.c) ** 2)
        self.limits = self.c0.limits

    def inputs(self, s):
        return self.ell0 + s * (self.ell1 - self.ell0), self.F0 + s * (self.F1 - self.F0)

    def chain(self, s) -> Chain:
        return self.chain_at(self.inputs(s)[0])

    def residual(self, q, s):
        ell, F = self.inputs(s)
        return self.chain_at(ell).lagrangian_grad(q, F)

    def hess(self, q, s):
        ell, F = self.inputs(s)
        return RP.lagrangian_hess(self.chain_at(ell), q, F)

    def dR_ds(self, q):
        """Exact: R is affine in (ell, F) at fixed q."""
        return self.c1.lagrangian_grad(q, self.F1) - self.c0.lagrangian_grad(q, self.F0)

    def margin(self, q, s) -> float:
        H = self.hess(q, s)
        return float(np.linalg.eigvalsh(0.5 * (H + H.T))[0])

    def ratio(self, q) -> float:
        return float(np.max(np.abs(q) / self.limits))

    def tangent(self, q, s):
        try:
            t = -np.linalg.solve(self.hess(q, s), self.dR_ds(q))
        except np.linalg.LinAlgError:
            return np.zeros(self.n)
        return t if np.all(np.isfinite(t)) else np.zeros(self.n)

    def newton(self, q, s, maxit=30):
        """Newton on R(., s) from ``q``: (q, converged)."""
        q = np.array(q, float)
        tol = GRAD_TOL * self.scale
        for _ in range(maxit):
            r = self.residual(q, s)
            if not np.all(np.isfinite(r)):
                return q, False
            if np.max(np.abs(r)) < tol:
                return q, True
            try:
                q = q - np.linalg.solve(self.hess(q, s), r)
            except np.linalg.LinAlgError:
                return q, False
            if not np.all(np.isfinite(q)) or np.max(np.abs(q)) > 10.0 * np.max(self.limits):
                return q, False
        return q, bool(np.max(np.abs(self.residual(q, s))) < tol)

    def good(self, q_new, ok, q_prev):
        """Converged, within MAX_JUMP of q_prev and inside the range (stability is checked by the callers)."""
        return (ok and np.max(np.abs(q_new - q_prev)) <= MAX_JUMP and self.ratio(q_new) < LIMIT_RATIO)


def _bisect(P: _Problem, s_lo, q_lo, s_hi, record):
    """Bisection to S_TOL between a good point (s_lo, q_lo) and a refused fraction s_hi. Accepted trial points
    are appended through ``record``. Returns (s_lo, q_lo, s_hi)."""
    while s_hi - s_lo > S_TOL:
        mid = 0.5 * (s_lo + s_hi)
        q_mid, ok = P.newton(q_lo, mid)
        if P.good(q_mid, ok, q_lo) and P.margin(q_mid, mid) > 0.0:
            s_lo, q_lo = mid, q_mid
            record(s_lo, q_lo)
        else:
            s_hi = mid
    return s_lo, q_lo, s_hi


def _descend(P: _Problem, q_star, s_star):
    """Gradient flow of V at the frozen inputs s_star from q_star + eps phi (the side of lower V).

    Returns ("landed", q) with q a stable minimum, or ("joint_limit", q) where a joint reached its limit."""
    ell, F = P.inputs(s_star)
    c = P.chain_at(ell)
    H = RP.lagrangian_hess(c, q_star, F)
    w, V = np.linalg.eigh(0.5 * (H + H.T))
    phi = V[:, 0] / np.max(np.abs(V[:, 0]))

    def pot(q):
        return c.energy(q) - float(F @ c.tip(q))

    starts = [q_star + EPS * phi, q_star - EPS * phi]
    y = min(starts, key=pot)
    gtol = 1e-9 * P.scale

    def rhs(t, q):
        return -c.lagrangian_grad(q, F)

    def jac(t, q):
        return -RP.lagrangian_hess(c, q, F)

    def at_limit(t, q):
        return LIMIT_RATIO - float(np.max(np.abs(q) / P.limits))
    at_limit.terminal = True
    at_limit.direction = -1

    def settled(t, q):
        return float(np.max(np.abs(c.lagrangian_grad(q, F)))) - gtol
    settled.terminal = True
    settled.direction = -1

    # the time scale of the slowest relaxation: the flow leaves a fold like 1 / (curvature * eps)
    T = 1e7 / max(P.scale, 1e-300)
    for _ in range(50):
        sol = si.solve_ivp(rhs, (0.0, T), y, method="LSODA", jac=jac, rtol=1e-10, atol=1e-12,
                           events=(at_limit, settled))
        y = sol.y[:, -1]
        if sol.status == -1:
            raise RuntimeError(f"descent failed: {sol.message}")
        if sol.t_events[0].size:
            return "joint_limit", sol.y_events[0][0]
        Hy = RP.lagrangian_hess(c, y, F)
        if np.linalg.eigvalsh(0.5 * (Hy + Hy.T))[0] > 0.0:
            q, ok = P.newton(y, s_star)
            if ok and np.max(np.abs(q - y)) < 1e-4 and P.margin(q, s_star) > 0.0 and P.ratio(q) < LIMIT_RATIO:
                return "landed", q
        if sol.t_events[1].size:
            # stopped near a saddle (H not positive definite): step off it on the side of lower V
            v = np.linalg.eigh(0.5 * (Hy + Hy.T))[1][:, 0]
            y = min([y + EPS * v, y - EPS * v], key=pot)
        # else: the flow ran out of time before settling; it goes on from where it is
    raise RuntimeError("descent did not land")


def _least_margin(P: _Problem, pts, s_end):
    """Least margin over the accepted points with s <= s_end, refined by bounded minimize_scalar."""
    S = np.array([p[0] for p in pts if p[0] <= s_end])
    Q = np.array([p[1] for p in pts if p[0] <= s_end])
    M = np.array([p[2] for p in pts if p[0] <= s_end])
    i = int(np.argmin(M))
    best_m, best_s = float(M[i]), float(S[i])
    if S.size < 2:
        return best_m, best_s
    lo, hi = S[max(i - 1, 0)], S[min(i + 1, S.size - 1)]

    def f(s):
        j = int(np.searchsorted(S, s, side="right")) - 1      # the nearest accepted point at or below s
        j = min(max(j, 0), S.size - 1)
        q, ok = P.newton(Q[j], s)
        if not (ok and np.max(np.abs(q - Q[j])) <= MAX_JUMP):
            return float(M[j])
        m = P.margin(q, s)
        return m if m > 0.0 else float(M[j])

    res = so.minimize_scalar(f, bounds=(lo, hi), method="bounded", options={"xatol": 1e-10})
    if res.fun < best_m:
        best_m, best_s = float(res.fun), float(res.x)
    return best_m, best_s


def _margin_lost(P: _Problem, pts, s_end, margin):
    """First s (<= s_end) of the accepted points' stretch where the margin falls below ``margin`` (brentq)."""
    S = [p[0] for p in pts if p[0] <= s_end]
    Q = [p[1] for p in pts if p[0] <= s_end]
    M = [p[2] for p in pts if p[0] <= s_end]
    if M[0] < margin:
        return S[0]
    for j in range(1, len(S)):
        if M[j] < margin:
            def g(s, j=j):
                q, _ = P.newton(Q[j - 1], s)
                return P.margin(q, s) - margin
            return float(so.brentq(g, S[j - 1], S[j], xtol=1e-12))
    return None


def transition(chain_at, q0, ell0, ell1, F0, F1, *, margin=None, ds_max=0.02) -> TransitionRef:
    """The quasi-static transition from the stable equilibrium ``q0`` of ``(ell0, F0)`` as the inputs move
    linearly to ``(ell1, F1)`` (see the module docstring). ``chain_at(ell)`` returns the reference ``Chain`` with
    rest lengths ``ell`` ``(n, 2)``. ``margin`` (optional): a required stability margin; the result then says
    whether the least margin meets it (``margin_ok``) and where the first stretch first falls below it
    (``margin_lost_at``). Raises ValueError when ``q0`` is not a stable equilibrium inside the range."""
    P = _Problem(chain_at, ell0, ell1, F0, F1)
    q_in = np.asarray(q0, float).reshape(P.n)
    q, ok = P.newton(q_in, 0.0)
    if not ok or np.max(np.abs(q - q_in)) > 1e-3:
        raise ValueError("q0 is not an equilibrium of (ell0, F0)")
    if P.ratio(q) >= LIMIT_RATIO:
        raise ValueError("q0 is at or beyond a joint limit")
    if P.margin(q, 0.0) <= 0.0:
        raise ValueError("q0 is not a stable equilibrium of (ell0, F0)")

    pts: list = []
    tips: list = []

    def record(s, qq):
        pts.append((float(s), np.array(qq, float), P.margin(qq, s)))
        tips.append(P.chain(s).tip(qq))

    s = 0.0
    record(s, q)
    snaps: list = []
    fold_at = limit_at = None
    stretch_end = None
    ds = ds_max
    status = None
    while s < 1.0:
        s_new = min(1.0, s + ds)
        q_pred = q + (s_new - s) * P.tangent(q, s)
        if np.max(np.abs(q_pred - q)) > MAX_JUMP:           # a long predicted step: a shorter one
            ds = 0.5 * ds
            if ds > S_TOL:
                continue
            q_pred = q
        q_new, ok = P.newton(q_pred, s_new)
        if (P.good(q_new, ok, q)
                and np.max(np.abs(q_new - q_pred)) <= 0.25 * np.max(np.abs(q_pred - q)) + 1e-3
                and P.margin(q_new, s_new) > 0.0):
            s, q = s_new, q_new
            record(s, q)
            ds = min(ds_max, 2.0 * ds)
            continue
        # refused: locate the event by bisection from the last good point
        s_lo, q_lo, s_hi = _bisect(P, s, q, s_new, record)
        q_hi, ok = P.newton(q_lo, s_hi)
        if P.good(q_hi, ok, q_lo) and P.margin(q_hi, s_hi) > 0.0:     # only the step was too long
            s, q = s_hi, q_hi
            record(s, q)
            ds = max(0.25 * ds, 1e3 * S_TOL)
            continue
        if P.ratio(q_lo) >= 1.0 - 2e-6:
            status, limit_at, q, s = "joint_limit", s_lo, q_lo, s_lo
            if stretch_end is None:
                stretch_end = s_lo
            break
        if P.margin(q_lo, s_lo) >= 1e-3 * P.scale:
            raise RuntimeError(f"continuation failed at s = {s_lo!r} (margin {P.margin(q_lo, s_lo)!r})")
        # a loss of stability: snap at s* = s_hi
        s_star = s_hi
        if fold_at is None:
            fold_at = s_star
        if stretch_end is None:
            stretch_end = s_lo
        kind, q_land = _descend(P, q_lo, s_star)
        if kind == "joint_limit":
            status, limit_at, q, s = "joint_limit", s_star, q_land, s_star
            break
        if np.max(np.abs(q_land - q_lo)) < 100.0 * EPS:
            raise BranchPointError(f"the arm lands next to where it lost stability (s* = {s_star!r}): a "
                                   "supercritical branch point, not a snap (out of this reference's scope)")
        snaps.append((s_star, q_lo.copy(), q_land.copy()))
        s, q = s_star, q_land
        record(s, q)
        ds = ds_max
    if status is None:
        status = "snapped" if snaps else "followed"
    if stretch_end is None:
        stretch_end = 1.0
    min_m, min_at = _least_margin(P, pts, stretch_end)
    out = TransitionRef(status=status, q_end=np.array(q), tip_end=P.chain(s).tip(q), snaps=snaps,
                        min_margin=min_m, min_margin_at=min_at, fold_at=fold_at, limit_at=limit_at, points=pts,
                        tips=tips, stretch_end=stretch_end)
    if margin is not None:
        out.margin_ok = bool(min_m >= margin)
        out.margin_lost_at = _margin_lost(P, pts, stretch_end, float(margin))
    return out
