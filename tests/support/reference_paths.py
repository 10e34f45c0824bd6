"""Independent reference computations for equilibrium paths and limit points.

Imports numpy, scipy and ``tests/support/reference_model.py`` only -- NOT ``tensegrity_opt``.
Written from ``docs/model.md`` ("Loading paths and limit points"):

* relative joint angles ``q``; equilibrium ``grad E(q) = J(q)^T F`` with ``F`` the tip force
  that holds the chain; dead load ``F = base + t d`` (``d`` a unit vector, ``t`` the load).
* ``"free"``: ``F`` fully prescribed, unknowns ``z = q``; stability from the full Hessian
  of ``E - F . tip``.
* ``"guided"``: the tip ``y`` held at its start value, ``Fx = base_x + t d_x``, ``Fy`` a
  reaction, unknowns ``z = (q, Fy)``; stability from that Hessian reduced to the null space
  of ``dy/dq``.
* ``"displacement"``: the deflection ``(dx, dy)`` moves by ``t d`` from the start, i.e. the
  tip by ``t (-d_x, d_y)`` (the tip sits at ``(2 sum b - dx, dy)``); unknowns ``z = (q, F)``;
  stability from the Hessian reduced to the null space of ``J``.

The path is ``R(z, t) = 0``.  A limit point is where ``R_z`` is singular: a **fold** when the
left null vector ``u`` has ``u . dR/dt != 0`` (``t`` has a turning point along the branch),
a **bifurcation** (branch point) when ``u . dR/dt = 0``.

Routes used here (independent of any continuation code):
* :func:`load_path` -- natural-parameter path on a given increasing grid of ``t`` (scipy
  ``root`` from the previous point with a tangent predictor);
* :func:`limit_load_reference` -- the same natural path with step halving on "the next point
  is not a stable continuation" (bisection to ``1e-12`` in ``t``), then the extended system
  ``R = 0, R_z phi = 0, phi . phi = 1`` solved by ``scipy.optimize.root`` (``hybr``) and a
  Newton polish, then the fold / bifurcation classification;
* :func:`fold_by_coordinate` -- a second route to a fold: the path parametrised by one joint
  angle (smooth through the fold) and ``t`` maximised (minimised) along it with
  ``scipy.optimize.minimize_scalar``;
* :func:`fold_in_displacement` -- a fold (turning point in the deflection) of a
  displacement-controlled path, by both routes above;
* :func:`buckling_modes` -- critical loads and modes of the straight chain from the analytic
  second derivatives (generalised symmetric eigenproblem; reference_model's bordered
  determinant is the other route);
* :func:`coordinate_path`, :func:`post_buckling` -- a path parametrised by one joint angle
  (through folds), the branch born at a critical load;
* :func:`single_segment_curve` / :func:`single_segment_folds` -- ``n = 1`` in closed form;
* :func:`energy_integral` -- ``int F . dtip`` along a displacement branch, refined on the
  reference between the given points.

Findings (see tests/support/test_reference_paths.py): the paper chain's pitchforks are supercritical
both guided and free (the bent branch carries more load and is stable); a pre-bent arm
(every L1_0 0.1 shorter) under free compression has a smooth path, stable up to the joint
range (quasi-buckling), while guided it snaps at a fold (n = 3: t = 0.825957) at large
rotations; with the pre-bend in segment 1 only, the guided path keeps segments 2..n
exactly straight and meets a genuine branch point (t = 0.561844 for n = 4), numerically
fragile. Uniform free chains: ``P_j = (K / b) (1 - cos((2j - 1) pi / (2n)))``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import reference_model as R  # noqa: E402
import scipy.linalg as sla
import scipy.optimize as so

Chain = R.Chain

__all__ = [
    "Chain", "lagrangian_hess", "PathSystem", "PathResult", "LimitResult", "unit",
    "load_path", "limit_load_reference", "solve_extended", "classify_singular_point",
    "fold_by_coordinate", "coordinate_path", "fold_in_displacement", "displacement_path",
    "buckling_modes", "single_segment_curve", "single_segment_folds", "post_buckling", "rest_configuration",
    "segment_wells",
    "equilibrium_residual", "smallest_eigenvalue", "morse_index", "energy_integral",
    "bistable_segment", "pre_bent_chain", "bistable_chain",
]

BOUNDARIES = ("free", "guided", "displacement")


def unit(d):
    d = np.asarray(d, float)
    nrm = float(np.linalg.norm(d))
    if nrm == 0.0:
        raise ValueError("direction must be non-zero")
    return d / nrm


# ============================================================================ fast Hessian
def lagrangian_hess(chain: Chain, q, F):
    """Hessian of ``E - F . tip`` in ``q``: ``reference_model.Chain.lagrangian_hess`` vectorised
    (entry (i, k) of Hess x / Hess y is ``-sum_{j >= max(i, k)} l_j (cos, sin) phi_j``)."""
    q = np.asarray(q, float)
    phi = np.cumsum(q)
    l = chain.links
    sc = np.cumsum((l * np.cos(phi))[::-1])[::-1]
    ss = np.cumsum((l * np.sin(phi))[::-1])[::-1]
    idx = np.maximum.outer(np.arange(q.size), np.arange(q.size))
    return np.diag(chain.hess_diag(q)) + F[0] * sc[idx] + F[1] * ss[idx]


# ============================================================================ the path system
class PathSystem:
    """``R(z, t) = 0`` for one control of ``chain`` starting at ``q_start`` (``t = 0`` there
    for the displacement control; the load controls use ``F = base + t d`` absolutely)."""

    #: scipy ``hybr``'s ``xtol`` before the Newton polish.
    XTOL = 1e-14

    def __init__(self, chain: Chain, q_start, direction, boundary="free", base=(0.0, 0.0)):
        if boundary not in BOUNDARIES:
            raise ValueError(f"boundary must be one of {BOUNDARIES}")
        self.chain = chain
        self.boundary = boundary
        self.n = chain.n
        self.d = unit(direction)
        self.base = np.asarray(base, float)
        self.q_start = np.asarray(q_start, float).copy()
        self.tip0 = chain.tip(self.q_start)
        self.w = np.array([-self.d[0], self.d[1]])          # d tip / dt under displacement control
        self.m = {"free": self.n, "guided": self.n + 1, "displacement": self.n + 2}[boundary]
        c2 = float(np.max(chain.c) ** 2)
        self.scale = max(1e-300, float(np.max(np.maximum(chain.k1, chain.k2))) * c2)

    # ---------------------------------------------------------------- unknowns
    def split(self, z, t):
        z = np.asarray(z, float)
        n = self.n
        if self.boundary == "free":
            return z, self.base + t * self.d
        if self.boundary == "guided":
            return z[:n], np.array([self.base[0] + t * self.d[0], z[n]])
        return z[:n], z[n:n + 2]

    def start_z(self, q=None, t=0.0):
        """``z`` at configuration ``q``: the reaction / force from least squares on
        ``grad E = J^T F``."""
        c = self.chain
        q = self.q_start if q is None else np.asarray(q, float)
        if self.boundary == "free":
            return q.copy()
        g = c.grad(q)
        J = c.jac(q)
        if self.boundary == "guided":
            fx = self.base[0] + t * self.d[0]
            r = g - J[0] * fx
            fy = float(J[1] @ r / (J[1] @ J[1]))
            return np.concatenate([q, [fy]])
        return np.concatenate([q, c.force_eq8(q)])

    # ---------------------------------------------------------------- residual and derivatives
    def residual(self, z, t):
        c = self.chain
        q, F = self.split(z, t)
        g = c.grad(q) - c.jac(q).T @ F
        if self.boundary == "free":
            return g
        tip = c.tip(q)
        if self.boundary == "guided":
            return np.concatenate([g, [tip[1] - self.tip0[1]]])
        return np.concatenate([g, tip - (self.tip0 + t * self.w)])

    def _hessian(self, z, t):
        """The Hessian of ``E - F . tip`` at ``z`` and, for the held controls, the tip Jacobian (else ``None``)."""
        q, F = self.split(z, t)
        H = lagrangian_hess(self.chain, q, F)
        return H, None if self.boundary == "free" else self.chain.jac(q)

    def jac_z(self, z, t):
        H, J = self._hessian(z, t)
        if J is None:
            return H
        n = self.n
        A = np.zeros((self.m, self.m))
        A[:n, :n] = H
        if self.boundary == "guided":
            A[:n, n] = -J[1]
            A[n, :n] = J[1]
        else:
            A[:n, n:] = -J.T
            A[n:, :n] = J
        return A

    def jac_t(self, z, t):
        c = self.chain
        q, _ = self.split(z, t)
        J = c.jac(q)
        n = self.n
        if self.boundary == "free":
            return -J.T @ self.d
        if self.boundary == "guided":
            return np.concatenate([-J[0] * self.d[0], [0.0]])
        return np.concatenate([np.zeros(n), -self.w])

    def tangent(self, z, t):
        """``dz/dt`` on the natural parametrisation (infinite at a fold)."""
        return -np.linalg.solve(self.jac_z(z, t), self.jac_t(z, t))

    # ---------------------------------------------------------------- stability
    def reduced_hessian(self, z, t):
        H, J = self._hessian(z, t)
        if J is None:
            return H
        Z = sla.null_space(J[1][None, :]) if self.boundary == "guided" else sla.null_space(J)
        return Z.T @ H @ Z

    def eigs(self, z, t):
        Hr = self.reduced_hessian(z, t)
        if Hr.size == 0:
            return np.zeros(0)
        return np.linalg.eigvalsh(0.5 * (Hr + Hr.T))

    def lam_min(self, z, t):
        w = self.eigs(z, t)
        return float(w[0]) if w.size else math.inf

    # ---------------------------------------------------------------- one solve
    def solve(self, z0, t, tol=1e-11):
        """Equilibrium at load ``t`` from ``z0``: scipy ``root`` (hybr, analytic Jacobian) and a
        Newton polish. Returns ``(z, ok)``."""
        def f(z):
            return self.residual(z, t)
        try:
            sol = so.root(f, np.asarray(z0, float), jac=lambda z: self.jac_z(z, t), method="hybr",
                          options={"xtol": self.XTOL, "maxfev": 400})
            z = sol.x
        except (ValueError, np.linalg.LinAlgError, FloatingPointError):
            return np.asarray(z0, float), False
        for _ in range(4):
            r = f(z)
            if not np.all(np.isfinite(r)):
                return z, False
            if np.max(np.abs(r)) < 1e-14 * self.scale:
                break
            try:
                z = z - np.linalg.solve(self.jac_z(z, t), r)
            except np.linalg.LinAlgError:
                break
        r = f(z)
        ok = bool(np.all(np.isfinite(z)) and np.all(np.isfinite(r)) and np.max(np.abs(r)) < tol * self.scale)
        return z, ok

    def in_range(self, z, t, margin=0.0):
        q, _ = self.split(z, t)
        return self.chain.in_range(q, margin)


# ============================================================================ results
@dataclass
class PathResult:
    t: np.ndarray
    q: np.ndarray
    force: np.ndarray
    tip: np.ndarray
    lam_min: np.ndarray
    z: np.ndarray
    status: str                     # "done" | "no_convergence" | "jump" | "joint_limit"


@dataclass
class LimitResult:
    """``t, q, force, kind`` (iterable as that 4-tuple) plus diagnostics."""
    t: float | None
    q: np.ndarray
    force: np.ndarray
    kind: str                       # "fold" | "bifurcation" | "none"
    reason: str | None = None       # None | "joint_limit" | "max_load"
    z: np.ndarray | None = None
    phi: np.ndarray | None = None   # right null vector of R_z (z-space, unit)
    u_dot_rt: float = float("nan")  # |u . R_t| / |R_t| (0 at a bifurcation)
    lam_min: float = float("nan")   # smallest reduced-Hessian eigenvalue at the point
    t_bisect: float | None = None   # the bracket from the natural-path bisection
    extended_converged: bool = False
    path: PathResult | None = field(default=None, repr=False)

    def __iter__(self):
        return iter((self.t, self.q, self.force, self.kind))


def _pack(system: PathSystem, ts, zs, lams, status):
    c = system.chain
    qs, Fs, tips = [], [], []
    for z, t in zip(zs, ts):
        q, F = system.split(z, t)
        qs.append(q)
        Fs.append(F)
        tips.append(c.tip(q))
    n = system.n
    return PathResult(np.array(ts, float), np.array(qs).reshape(-1, n), np.array(Fs).reshape(-1, 2),
                      np.array(tips).reshape(-1, 2), np.array(lams, float),
                      np.array(zs).reshape(-1, system.m), status)


def _unit_tangent(system: PathSystem, z, t):
    """The path tangent in (z, t) space, oriented with dt > 0, or None where R_z is singular."""
    try:
        tan = system.tangent(z, t)
    except np.linalg.LinAlgError:
        return None
    if not np.all(np.isfinite(tan)):
        return None
    T = np.concatenate([tan, [1.0]])
    return T / np.linalg.norm(T)


def _step(system: PathSystem, z, t, t_new, max_jump, max_turn=0.2):
    """Solve at ``t_new`` from the point ``(z, t)`` with a tangent predictor (dropped when it
    is long). Rejected: no convergence, a jump of more than ``max_jump`` rad in ``q``, a point
    outside the joint range, or a "kink" -- the secant or the new tangent turned by more than
    ``max_turn`` rad from the old tangent (the solver crossed onto another branch at a branch
    point, e.g. a transcritical one where stability is exchanged). Returns (z_new, status)."""
    dt = t_new - t
    T_old = _unit_tangent(system, z, t)
    pred = z
    if T_old is not None:
        tan = T_old[:-1] / T_old[-1]
        if np.max(np.abs(dt * tan[:system.n])) <= 0.5 * max_jump:
            pred = z + dt * tan
    z_new, ok = system.solve(pred, t_new)
    if not ok:
        z_new, ok = system.solve(z, t_new)
    if not ok:
        return z_new, "no_convergence"
    if np.max(np.abs(z_new[:system.n] - z[:system.n])) > max_jump:
        return z_new, "jump"
    if not system.in_range(z_new, t_new):
        return z_new, "joint_limit"
    if T_old is not None:
        S = np.concatenate([z_new - z, [dt]])
        S = S / np.linalg.norm(S)
        T_new = _unit_tangent(system, z_new, t_new)
        cmin = math.cos(max_turn)
        if S @ T_old < cmin or T_new is None or T_new @ T_old < cmin:
            return z_new, "kink"
    return z_new, "ok"


# ============================================================================ 1. natural path
def load_path(chain: Chain, q_start, direction, boundary, t_grid, *, base=(0.0, 0.0), max_jump=0.25):
    """Natural-parameter path: the equilibrium at each ``t`` of the increasing ``t_grid``,
    warm-started from the previous point. ``boundary`` is "free", "guided" (dead load ``F =
    base + t d``) or "displacement" (deflection ``t d`` from the start). Stops at the first
    failure (no convergence, a jump, a point outside the joint range).

    Returns a :class:`PathResult` (``t``, ``q``, ``force``, ``tip``, ``lam_min`` the smallest
    eigenvalue of the free / reduced Hessian of ``E - F . tip``, ``z``, ``status``)."""
    system = PathSystem(chain, q_start, direction, boundary, base)
    t_grid = np.asarray(t_grid, float)
    z, ok = system.solve(system.start_z(t=t_grid[0]), t_grid[0])
    if not ok or not system.in_range(z, t_grid[0]):
        return _pack(system, [], [], [], "no_convergence")
    ts, zs, lams = [t_grid[0]], [z], [system.lam_min(z, t_grid[0])]
    status = "done"
    for t in t_grid[1:]:
        z_new, st = _step(system, zs[-1], ts[-1], t, max_jump)
        if st != "ok":
            status = st
            break
        ts.append(t)
        zs.append(z_new)
        lams.append(system.lam_min(z_new, t))
    return _pack(system, ts, zs, lams, status)


# ============================================================================ 2. limit points
def classify_singular_point(system: PathSystem, z, t, rel_tol=1e-6):
    """(kind, ratio, phi): the left / right null vectors of ``R_z`` by SVD; ``ratio =
    |u . R_t| / |R_t|`` (0 when ``R_t`` itself vanishes); "fold" when ``ratio > rel_tol``."""
    A = system.jac_z(z, t)
    U, s, Vt = np.linalg.svd(A)
    u, phi = U[:, -1], Vt[-1]
    rt = system.jac_t(z, t)
    nrt = float(np.linalg.norm(rt))
    if nrt <= 1e-9 * max(system.scale, s[0]):
        ratio = 0.0
    else:
        ratio = abs(float(u @ rt)) / nrt
    return ("fold" if ratio > rel_tol else "bifurcation"), ratio, phi


def solve_extended(system: PathSystem, z0, t0, phi0=None, tol=1e-12):
    """Solve ``R(z, t) = 0, R_z(z, t) phi = 0, phi . phi = 1`` (unknowns ``z, t, phi``) with
    ``scipy.optimize.root`` (hybr) from ``(z0, t0, phi0)`` and polish by Newton with a
    central-difference Jacobian (the residual itself is analytic). Returns (z, t, phi, ok)."""
    m = system.m
    if phi0 is None:
        phi0 = np.linalg.svd(system.jac_z(z0, t0))[2][-1]
    phi0 = phi0 / np.linalg.norm(phi0)

    def F(x):
        z, t, phi = x[:m], x[m], x[m + 1:]
        return np.concatenate([system.residual(z, t), system.jac_z(z, t) @ phi, [phi @ phi - 1.0]])

    def Jac(x, h=1e-6):
        N = x.size
        out = np.zeros((N, N))
        for i in range(N):
            e = np.zeros(N)
            e[i] = h * max(1.0, abs(x[i]))
            out[:, i] = (F(x + e) - F(x - e)) / (2 * e[i])
        return out

    x0 = np.concatenate([z0, [t0], phi0])
    try:
        x = so.root(F, x0, jac=Jac, method="hybr", options={"xtol": 1e-14, "maxfev": 2000}).x
    except (ValueError, np.linalg.LinAlgError):
        x = x0
    for _ in range(6):
        r = F(x)
        if np.max(np.abs(r)) < 1e-15 * system.scale:
            break
        try:
            x = x - np.linalg.lstsq(Jac(x), r, rcond=None)[0]
        except np.linalg.LinAlgError:
            break
    r = F(x)
    ok = bool(np.all(np.isfinite(x)) and np.max(np.abs(r)) < tol * system.scale)
    return x[:m], float(x[m]), x[m + 1:], ok


def _first_loss(system: PathSystem, z0, t_end, dt0, max_jump, t_tol):
    """Natural path from ``(z0, 0)`` towards ``t_end`` with step halving: returns
    ``(z_good, t_good, last_reject_reason, ts, zs, lams)``; ``last_reject_reason`` is None when
    ``t_end`` was reached. A step is rejected when it does not converge, jumps, leaves the
    joint range or lands on an unstable point."""
    ts, zs, lams = [0.0], [z0], [system.lam_min(z0, 0.0)]
    z, t, dt = z0, 0.0, dt0
    reason = None
    accepted_in_row = 0
    while t < t_end:
        t_try = min(t + dt, t_end)
        z_new, st = _step(system, z, t, t_try, max_jump)
        if st == "ok" and system.lam_min(z_new, t_try) <= 0.0:
            st = "unstable"
        if st == "ok":
            z, t = z_new, t_try
            ts.append(t)
            zs.append(z)
            lams.append(system.lam_min(z, t))
            accepted_in_row += 1
            if accepted_in_row >= 4 and dt < dt0:
                dt = min(2 * dt, dt0)
                accepted_in_row = 0
            continue
        reason = st
        accepted_in_row = 0
        dt *= 0.5
        if dt < t_tol * max(1.0, abs(t)):
            return z, t, reason, ts, zs, lams
    return z, t, None, ts, zs, lams


def limit_load_reference(chain: Chain, q_start, direction=(-1.0, 0.0), boundary="free", max_load=None,
                         *, base=(0.0, 0.0), dt0=None, max_jump=0.25, rel_tol=1e-6):
    """First loss of stability along the natural load path from ``q_start`` (``t = 0``).

    Returns a :class:`LimitResult`, iterable as ``(t, q, force, kind)``: ``kind`` "fold" or
    "bifurcation" with ``t`` the limit load (extended-system solve, ``1e-9`` or better), or
    "none" with ``reason`` "max_load" (stable up to ``max_load``) or "joint_limit" (the path
    leaves the joint range while stable; ``t`` is then the load at the bound)."""
    system = PathSystem(chain, q_start, direction, boundary, base)
    if max_load is None:
        max_load = 20.0 * system.scale / float(np.min(chain.b))
    if dt0 is None:
        dt0 = max_load / 200.0
    z0, ok = system.solve(system.start_z(t=0.0), 0.0)
    if not ok:
        raise RuntimeError("the start is not an equilibrium at t = 0")
    if system.lam_min(z0, 0.0) <= 0.0:
        raise RuntimeError("the start is not stable")
    z, t, reason, ts, zs, lams = _first_loss(system, z0, max_load, dt0, max_jump, 1e-12)
    path = _pack(system, ts, zs, lams, reason or "done")
    q, F = system.split(z, t)
    if reason is None:
        return LimitResult(None, q, F, "none", "max_load", z=z, lam_min=system.lam_min(z, t),
                           t_bisect=t, path=path)
    if reason == "joint_limit":
        return LimitResult(t, q, F, "none", "joint_limit", z=z, lam_min=system.lam_min(z, t),
                           t_bisect=t, path=path)
    _, _, phi0 = classify_singular_point(system, z, t, rel_tol)
    ze, te, _, ok = solve_extended(system, z, t, phi0)
    if ok and abs(te - t) <= 1e-6 * max(1.0, abs(t)) and np.max(np.abs(ze - z)) < 1e-2:
        z, t, ext = ze, te, True
    else:
        ext = False                 # singular extended system (a symmetric branch point): bisection
    kind, ratio, phi = classify_singular_point(system, z, t, rel_tol)
    q, F = system.split(z, t)
    return LimitResult(t, q, F, kind, None, z=z, phi=phi, u_dot_rt=ratio, lam_min=system.lam_min(z, t),
                       t_bisect=path.t[-1], extended_converged=ext, path=path)


# ============================================================================ folds: second route
def fold_by_coordinate(system: PathSystem, z_near, t_near, k=None, half_width=0.05, maximize=True):
    """Route 2 to a fold: parametrise the path by the joint angle ``q_k`` (smooth through a
    fold, where ``t`` is not), solve ``R = 0`` for the other unknowns and ``t`` at each
    ``q_k``, and find the extremum of ``t(q_k)`` with ``minimize_scalar`` (bounded) on
    ``[q_k - half_width, q_k + half_width]`` around ``z_near``. ``k`` defaults to the largest
    q-component of the null vector. Returns (t, z)."""
    n = system.n
    if k is None:
        phi = np.linalg.svd(system.jac_z(z_near, t_near))[2][-1]
        k = int(np.argmax(np.abs(phi[:n])))
    cache = {"x": np.concatenate([np.delete(z_near, k), [t_near]])}

    def solve_at(p):
        def f(x):
            z = np.insert(x[:-1], k, p)
            return system.residual(z, x[-1])

        def jac(x):
            z = np.insert(x[:-1], k, p)
            A = system.jac_z(z, x[-1])
            return np.column_stack([np.delete(A, k, axis=1), system.jac_t(z, x[-1])])
        x = so.root(f, cache["x"], jac=jac, method="hybr", options={"xtol": 1e-15}).x
        for _ in range(3):
            x = x - np.linalg.solve(jac(x), f(x))
        if np.max(np.abs(f(x))) > 1e-11 * system.scale:
            raise RuntimeError("coordinate parametrisation failed")
        cache["x"] = x
        return x

    sign = -1.0 if maximize else 1.0
    p0 = z_near[k]
    res = so.minimize_scalar(lambda p: sign * solve_at(p)[-1], bounds=(p0 - half_width, p0 + half_width),
                             method="bounded", options={"xatol": 1e-10})
    x = solve_at(res.x)
    return float(x[-1]), np.insert(x[:-1], k, res.x)


def coordinate_path(system: PathSystem, z_start, t_start, k, qk_grid):
    """The path through ``(z_start, t_start)`` parametrised by the joint angle ``q_k`` (a
    second parametrisation, smooth through folds in ``t`` as long as ``q_k`` is monotonic
    along the branch): for each value of the grid (starting near ``z_start[k]``) solve ``R = 0``
    for the other unknowns and ``t``. Stops at the first failure or point outside the range.
    Returns a :class:`PathResult` (``lam_min`` the smallest free / reduced eigenvalue)."""
    z = np.asarray(z_start, float)
    x = np.concatenate([np.delete(z, k), [t_start]])
    ts, zs, lams = [], [], []
    status = "done"
    for p in qk_grid:
        def f(x, p=p):
            return system.residual(np.insert(x[:-1], k, p), x[-1])

        def jac(x, p=p):
            zz = np.insert(x[:-1], k, p)
            A = system.jac_z(zz, x[-1])
            return np.column_stack([np.delete(A, k, axis=1), system.jac_t(zz, x[-1])])
        x_new = so.root(f, x, jac=jac, method="hybr", options={"xtol": 1e-14}).x
        try:
            for _ in range(3):
                x_new = x_new - np.linalg.solve(jac(x_new), f(x_new))
        except np.linalg.LinAlgError:
            status = "no_convergence"
            break
        zz = np.insert(x_new[:-1], k, p)
        moved = np.max(np.abs(zz[:system.n] - np.insert(x[:-1], k, p)[:system.n]))
        if np.max(np.abs(f(x_new))) > 1e-10 * system.scale or moved > 0.25:
            status = "no_convergence"
            break
        if not system.in_range(zz, x_new[-1]):
            status = "joint_limit"
            break
        x = x_new
        ts.append(x[-1])
        zs.append(zz)
        lams.append(system.lam_min(zz, x[-1]))
    return _pack(system, ts, zs, lams, status)


def displacement_path(chain: Chain, q_start, direction, t_grid, max_jump=0.25):
    """Natural-parameter displacement path (deflection ``t d`` from ``q_start``)."""
    return load_path(chain, q_start, direction, "displacement", t_grid, max_jump=max_jump)


def fold_in_displacement(chain: Chain, q_start, direction=(0.0, 1.0), t_max=1.0, *, dt0=None,
                         max_jump=0.25, rel_tol=1e-6):
    """First fold (turning point in the deflection parameter ``t``) of the displacement-
    controlled path from ``q_start`` (the deflection moves by ``t d``). Found by the natural
    path with step halving and the extended system, and checked against the joint-angle
    parametrisation (:func:`fold_by_coordinate`). Returns a :class:`LimitResult` (``force``
    the tip force there) with extra attribute ``t_coordinate`` (route 2); ``kind`` "none" with
    ``reason`` "kinematic_singularity" when the path runs into a configuration where ``J`` loses
    rank (the arm beyond some joint straightens: the force diverges, not a fold)."""
    system = PathSystem(chain, q_start, direction, "displacement")
    if dt0 is None:
        dt0 = t_max / 200.0
    z0, ok = system.solve(system.start_z(), 0.0)
    if not ok:
        raise RuntimeError("the start is not an equilibrium")
    z, t, reason, ts, zs, lams = _first_loss(system, z0, t_max, dt0, max_jump, 1e-12)
    path = _pack(system, ts, zs, lams, reason or "done")
    q, F = system.split(z, t)
    if reason is None or reason == "joint_limit":
        return LimitResult(None, q, F, "none", "max_load" if reason is None else "joint_limit", z=z, path=path)
    if np.linalg.svd(system.chain.jac(q), compute_uv=False)[-1] < 1e-4 * float(np.min(chain.b)):
        # the arm straightens (J loses rank, the force blows up): a workspace boundary, no fold
        return LimitResult(t, q, F, "none", "kinematic_singularity", z=z, path=path)
    _, _, phi0 = classify_singular_point(system, z, t, rel_tol)
    ze, te, _, ok = solve_extended(system, z, t, phi0)
    ext = bool(ok and abs(te - t) <= 1e-6 * max(1.0, abs(t)))
    if ext:
        z, t = ze, te
    kind, ratio, phi = classify_singular_point(system, z, t, rel_tol)
    q, F = system.split(z, t)
    out = LimitResult(t, q, F, kind, None, z=z, phi=phi, u_dot_rt=ratio, lam_min=system.lam_min(z, t),
                      t_bisect=path.t[-1], extended_converged=ext, path=path)
    if kind == "fold":
        out.t_coordinate, out.z_coordinate = fold_by_coordinate(system, z, t)
    return out


# ============================================================================ one segment: closed form
def single_segment_curve(chain1: Chain, direction):
    """One segment (``n = 1``) under the dead tip load ``t d``: the whole equilibrium curve is
    ``t(q) = E'(q) / (d . J(q))`` with ``J = (-b sin q, b cos q)`` -- a closed form, no path
    following. Returns ``(t_of_q, dt_dq)`` (vectorised callables)."""
    assert chain1.n == 1
    d = unit(direction)
    b = float(chain1.links[0])

    def dJ(q):
        return d[0] * (-b * np.sin(q)) + d[1] * (b * np.cos(q))

    def dJp(q):
        return d[0] * (-b * np.cos(q)) + d[1] * (-b * np.sin(q))

    def Ep(q):
        return chain1.grad(np.atleast_1d(np.asarray(q, float)))       # broadcasts for n = 1

    def Epp(q):
        return chain1.hess_diag(np.atleast_1d(np.asarray(q, float)))

    def t_of_q(q):
        return Ep(q) / dJ(np.atleast_1d(q))

    def dt_dq(q):
        q = np.atleast_1d(q)
        return (Epp(q) * dJ(q) - Ep(q) * dJp(q)) / dJ(q) ** 2
    return t_of_q, dt_dq


def single_segment_folds(chain1: Chain, direction, q_lo, q_hi, num=4001):
    """The folds of the one-segment curve on ``(q_lo, q_hi)``: roots of ``dt/dq`` (brentq).
    Returns a list of ``(q, t)``."""
    t_of_q, dt_dq = single_segment_curve(chain1, direction)
    qs = np.linspace(q_lo, q_hi, num)
    g = dt_dq(qs)
    out = []
    for i in range(num - 1):
        if np.isfinite(g[i]) and np.isfinite(g[i + 1]) and g[i] * g[i + 1] < 0:
            qf = so.brentq(lambda x: dt_dq(x)[0], qs[i], qs[i + 1], xtol=1e-15, rtol=1e-15)
            out.append((qf, float(t_of_q(qf)[0])))
    return out


def post_buckling(chain: Chain, boundary="guided", amplitudes=(1e-3, 1e-2, 0.05, 0.1), mode=0):
    """The branch bifurcating from the straight chain at its ``mode``-th critical load,
    parametrised by the joint angle ``q_k`` (``k`` the largest mode component, ``q_k =
    amplitude``). Returns ``(t, lam_min, q)`` per amplitude: ``t > P`` growing with the
    amplitude is a supercritical pitchfork (and the branch is stable, lam_min > 0, for the
    first mode), ``t < P`` subcritical."""
    P, V = buckling_modes(chain, boundary)
    v = V[:, mode]
    k = int(np.argmax(np.abs(v)))
    v = v / v[k]
    system = PathSystem(chain, np.zeros(chain.n), (-1.0, 0.0), boundary)
    out_t, out_l, out_q = [], [], []
    z = np.concatenate([amplitudes[0] * v, [0.0]]) if boundary == "guided" else amplitudes[0] * v
    t = float(P[mode])
    for amp in amplitudes:
        p = coordinate_path(system, np.concatenate([z[:k], [amp], z[k + 1:]]), t, k, [amp])
        if p.t.size == 0:
            raise RuntimeError("post-buckling solve failed")
        z, t = p.z[0], float(p.t[0])
        out_t.append(t)
        out_l.append(float(p.lam_min[0]))
        out_q.append(p.q[0])
    return np.array(out_t), np.array(out_l), np.array(out_q)


# ============================================================================ straight chain
def buckling_modes(chain: Chain, boundary="guided"):
    """Compressive critical loads ``P`` (ascending) and modes (columns, in ``q``) of the
    straight chain from the analytic ``K = diag E_i''(0)``, ``G = -Hess x(0)``, ``S0 = dy/dq(0)``:
    free ``K v = P G v``; guided the same on the null space of ``S0^T``. Only ``P > 0``."""
    n = chain.n
    z = np.zeros(n)
    K = np.diag(chain.hess_diag(z))
    G = -chain.tip_hessians(z)[0]
    if boundary == "free":
        P, V = sla.eigh(K, G)
    else:
        S0 = chain.jac(z)[1]
        Z = sla.null_space(S0[None, :])
        P, W = sla.eigh(Z.T @ K @ Z, Z.T @ G @ Z)
        V = Z @ W
    keep = P > 0
    V = V[:, keep]
    V = V / np.linalg.norm(V, axis=0)
    return P[keep], V


# ============================================================================ chains used by the tests
def segment_wells(a, b, k1, k2, L10, L20, num=20001):
    """Local minima of one segment's energy inside its range (sign changes of E' on a grid,
    refined by brentq)."""
    c1 = Chain.from_segments([(a, b, k1, k2, L10, L20)])
    lim = c1.limits[0]
    qs = np.linspace(-lim, lim, num)[1:-1]
    g = c1.grad(qs)                      # one segment: the formulas broadcast over q
    wells = []
    for i in np.nonzero((g[:-1] < 0) & (g[1:] >= 0))[0]:
        wells.append(so.brentq(lambda x: c1.grad(np.array([x]))[0], qs[i], qs[i + 1], xtol=1e-15))
    return np.array(wells)


def rest_configuration(chain: Chain, q0=None):
    """The rest configuration (zero tip force) nearest ``q0``: each joint independently at a
    local minimum of its own energy (the energy is separable). Newton polish."""
    q0 = np.zeros(chain.n) if q0 is None else np.asarray(q0, float)
    q, ok = chain.newton_force(np.zeros(2), q0)
    if not ok or not chain.in_range(q) or np.any(chain.hess_diag(q) <= 0):
        raise RuntimeError("no rest configuration near q0")
    return q


def bistable_segment():
    """(a, b, k, L0) of a bistable segment: K = k (b L0 - 2 (b^2 - a^2)) = -0.5."""
    return (0.5, 1.0, 1.0, 1.0)


def pre_bent_chain(n=3, a=1.0, b=1.0, k=1.0, L0=1.0, dL=0.1):
    """Symmetric paper-like segments whose first spring is ``dL`` shorter (a pre-bent arm)."""
    return Chain.from_segments([(a, b, k, k, L0 - dL, L0 + 0.0)] * n)


def bistable_chain(n=2):
    return Chain.from_segments([bistable_segment()] * n)


# ============================================================================ checks
def equilibrium_residual(chain: Chain, q, F):
    """``max |grad E - J^T F|`` relative to the torque scale ``max k c^2``."""
    q = np.asarray(q, float)
    scale = float(np.max(np.maximum(chain.k1, chain.k2)) * np.max(chain.c) ** 2)
    return float(np.max(np.abs(chain.lagrangian_grad(q, F)))) / scale


def smallest_eigenvalue(chain: Chain, q, F, boundary="free"):
    """Smallest eigenvalue of the Hessian of ``E - F . tip`` (free), reduced to ``dy/dq . v = 0``
    (guided) or to ``J v = 0`` (displacement)."""
    H = lagrangian_hess(chain, np.asarray(q, float), np.asarray(F, float))
    if boundary == "free":
        return float(np.linalg.eigvalsh(H)[0])
    J = chain.jac(q)
    Z = sla.null_space(J[1][None, :]) if boundary == "guided" else sla.null_space(J)
    if Z.shape[1] == 0:
        return math.inf
    return float(np.linalg.eigvalsh(Z.T @ H @ Z)[0])


def morse_index(chain: Chain, q, F, boundary="free", rel_tol=1e-8):
    H = lagrangian_hess(chain, np.asarray(q, float), np.asarray(F, float))
    if boundary != "free":
        J = chain.jac(q)
        Z = sla.null_space(J[1][None, :]) if boundary == "guided" else sla.null_space(J)
        H = Z.T @ H @ Z
    w = np.linalg.eigvalsh(H) if H.size else np.zeros(0)
    return int(np.sum(w < -rel_tol * max(1.0, np.abs(w).max() if w.size else 1.0)))


def energy_integral(chain: Chain, q, F, w, nodes=6, max_depth=8):
    """``int F . d tip`` along a displacement branch given by its points ``q`` (P, n) and
    forces ``F`` (P, 2) (the tip moves on a line of unit direction ``w``), by a reference
    refinement independent of the step sizes: each interval between consecutive points is
    re-solved at the Gauss-Legendre nodes of its secant in ``q`` -- unknowns ``(q, F, tau)``
    with ``grad E = J^T F``, ``tip(q) = tip_i + tau w`` and ``(q - q_i - theta dq) . dq = 0``
    (a pseudo-arclength, fine through folds) -- and ``F . w dtau/dtheta`` integrated
    (``dtau/dtheta`` by implicit differentiation). An interval whose nodes do not converge
    close to the secant is split at its (re-solved) midpoint. Returns ``(integral,
    trapezoid)``, the latter the plain trapezoid rule ``sum (F_i + F_{i+1})/2 . (tip_{i+1} -
    tip_i)`` for comparison."""
    q = np.asarray(q, float)
    F = np.asarray(F, float)
    w = unit(w)
    n = chain.n
    tips = np.array([chain.tip(x) for x in q])
    trap = float(np.sum(0.5 * (F[1:] + F[:-1]) * (tips[1:] - tips[:-1])))
    xg, wg = np.polynomial.legendre.leggauss(nodes)

    def solve_node(qa, Fa, tipa, qb, Fb, theta):
        dq = qb - qa
        dtau = float((chain.tip(qb) - tipa) @ w)
        x = np.concatenate([qa + theta * dq, Fa + theta * (Fb - Fa), [theta * dtau]])

        def G(x):
            qq, FF, tau = x[:n], x[n:n + 2], x[n + 2]
            return np.concatenate([chain.lagrangian_grad(qq, FF), chain.tip(qq) - tipa - tau * w,
                                   [(qq - qa - theta * dq) @ dq]])

        def DG(x):
            qq, FF = x[:n], x[n:n + 2]
            J = chain.jac(qq)
            A = np.zeros((n + 3, n + 3))
            A[:n, :n] = lagrangian_hess(chain, qq, FF)
            A[:n, n:n + 2] = -J.T
            A[n:n + 2, :n] = J
            A[n:n + 2, n + 2] = -w
            A[n + 2, :n] = dq
            return A
        try:
            for _ in range(30):
                r = G(x)
                if np.max(np.abs(r)) < 1e-14:
                    break
                x = x - np.linalg.solve(DG(x), r)
            ok = bool(np.max(np.abs(G(x))) < 1e-11
                      and np.max(np.abs(x[:n] - qa - theta * dq)) <= max(0.05, 0.5 * np.max(np.abs(dq))))
            rhs = np.zeros(n + 3)
            rhs[n + 2] = float(dq @ dq)
            dx = np.linalg.solve(DG(x), rhs)
        except np.linalg.LinAlgError:
            return None
        return (x, dx[n + 2]) if ok else None

    def interval(qa, Fa, qb, Fb, depth):
        dq = qb - qa
        tipa = chain.tip(qa)
        if float(dq @ dq) < 1e-28:
            return float(0.5 * (Fa + Fb) @ (chain.tip(qb) - tipa))
        acc = 0.0
        for xi, wi in zip(xg, wg):
            r = solve_node(qa, Fa, tipa, qb, Fb, 0.5 * (xi + 1.0))
            if r is None:
                break
            x, dtau_dtheta = r
            acc += wi * float(x[n:n + 2] @ w) * dtau_dtheta
        else:
            return 0.5 * acc
        if depth >= max_depth:
            raise RuntimeError("energy_integral: refinement failed")
        mid = solve_node(qa, Fa, tipa, qb, Fb, 0.5)
        if mid is None:
            raise RuntimeError("energy_integral: refinement failed at a midpoint")
        qm, Fm = mid[0][:n], mid[0][n:n + 2]
        return interval(qa, Fa, qm, Fm, depth + 1) + interval(qm, Fm, qb, Fb, depth + 1)

    total = sum(interval(q[i], F[i], q[i + 1], F[i + 1], 0) for i in range(q.shape[0] - 1))
    return total, trap
