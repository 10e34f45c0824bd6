"""Baselines a user would write with plain numpy/scipy (no ``tensegrity_opt`` internals).

Only :class:`tensegrity_opt.Manipulator` is used, for its *parameters* (``a, b, k1, k2, L1_0,
L2_0`` per segment) and for the target ``(2 sum(b) - dx, dy)``. Energy, gradient, Hessian, tip
and tip Jacobian are re-implemented here in relative angles ``q`` following
the model's conventions (``docs/model.md``):

* ``c = hypot(a, b)``, ``beta = atan2(a, b)``, ``L1 = 2c cos(beta + q/2)``,
  ``L2 = 2c cos(beta - q/2)``, ``E = sum k1/2 (L1 - L1_0)^2 + k2/2 (L2 - L2_0)^2``;
* ``phi_j = q_1 + ... + q_j``; tip ``x = b_1 + sum_j l_j cos(phi_j)``,
  ``y = sum_j l_j sin(phi_j)`` with links ``l_j = b_j + b_{j+1}`` (``l_n = b_n``);
* physical range ``|q_i| < pi - 2 beta_i``.

Baselines
---------
``slsqp_equilibrium``         SLSQP: min E(q) s.t. tip(q) = target, bounds on q, analytic jacobians.
``trust_constr_equilibrium``  the same with ``trust-constr`` (analytic Hessians too).
``slsqp_multistart``          SLSQP from several random starts, least energy kept.
``energy_method_n4``          the paper's "straightforward energy method" (n = 4): grid search of E
                              over (q1, q4), q2/q3 by two-link inverse kinematics (both elbows),
                              then Nelder-Mead on the best grid point.
``slsqp_force_deflection``    SLSQP over a list of deflections, each warm-started from the previous.
``dense_critical_loads``      the dense reduced generalised eigenproblem ``Z^T K Z v = P Z^T G Z v``.
``mode_start``                a start ``q = t * mode`` with the amplitude matching ``dx`` to 2nd order.
"""

from __future__ import annotations

import math
import time
import warnings
from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla
from scipy.optimize import BFGS, Bounds, NonlinearConstraint, minimize

__all__ = ["Chain", "BaselineResult", "slsqp_equilibrium", "trust_constr_equilibrium", "slsqp_multistart",
           "energy_method_n4", "slsqp_force_deflection", "dense_critical_loads", "mode_start"]

#: Bounds are imposed this much inside the open physical range (relative).
_BOUND_SHRINK = 1e-9


class Chain:
    """Plain-numpy model of the chain built from a ``Manipulator``'s segment parameters."""

    def __init__(self, m) -> None:
        segs = m.segments
        self.n = len(segs)
        self.a = np.array([s.a for s in segs], float)
        self.b = np.array([s.b for s in segs], float)
        self.k1 = np.array([s.k1 for s in segs], float)
        self.k2 = np.array([s.k2 for s in segs], float)
        self.L10 = np.array([s.L1_0 for s in segs], float)
        self.L20 = np.array([s.L2_0 for s in segs], float)
        self.c = np.hypot(self.a, self.b)
        self.beta = np.arctan2(self.a, self.b)
        self.links = np.concatenate([self.b[:-1] + self.b[1:], self.b[-1:]])
        self.base = float(self.b[0])
        self.length = float(2.0 * self.b.sum())
        self.limits = np.pi - 2.0 * self.beta

    # ---------------------------------------------------------------- energy
    def _springs(self, q):
        L1 = 2.0 * self.c * np.cos(self.beta + q / 2.0)
        L2 = 2.0 * self.c * np.cos(self.beta - q / 2.0)
        return L1, L2

    def energy(self, q: np.ndarray) -> float:
        L1, L2 = self._springs(q)
        return float(0.5 * (self.k1 @ (L1 - self.L10) ** 2 + self.k2 @ (L2 - self.L20) ** 2))

    def gradient(self, q: np.ndarray) -> np.ndarray:
        L1, L2 = self._springs(q)
        d1 = -self.c * np.sin(self.beta + q / 2.0)     # dL1/dq
        d2 = self.c * np.sin(self.beta - q / 2.0)      # dL2/dq
        return self.k1 * (L1 - self.L10) * d1 + self.k2 * (L2 - self.L20) * d2

    def hessian_diag(self, q: np.ndarray) -> np.ndarray:
        """``d2E/dq_i^2`` (the energy Hessian is diagonal in relative angles)."""
        L1, L2 = self._springs(q)
        d1 = -self.c * np.sin(self.beta + q / 2.0)
        d2 = self.c * np.sin(self.beta - q / 2.0)
        # d2L/dq2 = -L/4 for both springs
        return self.k1 * (d1 ** 2 - (L1 - self.L10) * L1 / 4.0) + self.k2 * (d2 ** 2 - (L2 - self.L20) * L2 / 4.0)

    def joint_stiffness(self) -> np.ndarray:
        return self.hessian_diag(np.zeros(self.n))

    # ---------------------------------------------------------------- kinematics
    def tip(self, q: np.ndarray) -> np.ndarray:
        phi = np.cumsum(q)
        return np.array([self.base + self.links @ np.cos(phi), self.links @ np.sin(phi)])

    def jacobian(self, q: np.ndarray) -> np.ndarray:
        phi = np.cumsum(q)
        jx = -self.links * np.sin(phi)
        jy = self.links * np.cos(phi)
        # d phi_j / d q_i = 1 for j >= i: reverse cumulative sums
        return np.vstack([np.cumsum(jx[::-1])[::-1], np.cumsum(jy[::-1])[::-1]])

    def tip_hessians(self, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``d2x/dq2`` and ``d2y/dq2``: entry ``(i, k)`` is ``-C[max(i, k)]`` / ``-S[max(i, k)]``."""
        phi = np.cumsum(q)
        C = np.cumsum((self.links * np.cos(phi))[::-1])[::-1]
        S = np.cumsum((self.links * np.sin(phi))[::-1])[::-1]
        idx = np.maximum.outer(np.arange(self.n), np.arange(self.n))
        return -C[idx], -S[idx]

    def target(self, dx: float, dy: float) -> np.ndarray:
        return np.array([self.length - dx, dy])

    def bounds(self) -> Bounds:
        lim = self.limits * (1.0 - _BOUND_SHRINK)
        return Bounds(-lim, lim)

    def multipliers_force(self, q: np.ndarray) -> np.ndarray:
        """Tip force from ``grad E = J^T F`` (least squares)."""
        J = self.jacobian(q)
        return np.linalg.lstsq(J.T, self.gradient(q), rcond=None)[0]


@dataclass
class BaselineResult:
    q: np.ndarray
    energy: float
    success: bool
    message: str
    nit: int
    tip_error: float
    force: np.ndarray | None = None


def _result(ch: Chain, q: np.ndarray, target: np.ndarray, success: bool, message: str, nit: int) -> BaselineResult:
    q = np.asarray(q, float)
    return BaselineResult(q=q, energy=ch.energy(q), success=bool(success), message=str(message), nit=int(nit),
                          tip_error=float(np.abs(ch.tip(q) - target).max()))


def _chain(m) -> Chain:
    return m if isinstance(m, Chain) else Chain(m)


# -------------------------------------------------------------------- constrained minimisation
def slsqp_equilibrium(m, dx: float, dy: float, q0, tol: float = 1e-10, maxiter: int = 500) -> BaselineResult:
    """``scipy.optimize.minimize(method="SLSQP")`` of ``E`` s.t. ``tip(q) = target`` from ``q0``."""
    ch = _chain(m)
    target = ch.target(dx, dy)
    cons = {"type": "eq", "fun": lambda q: ch.tip(q) - target, "jac": ch.jacobian}
    res = minimize(ch.energy, np.asarray(q0, float), jac=ch.gradient, method="SLSQP", constraints=[cons],
                   bounds=ch.bounds(), options={"ftol": tol, "maxiter": maxiter})
    return _result(ch, res.x, target, res.success, res.message, res.nit)


def trust_constr_equilibrium(m, dx: float, dy: float, q0, tol: float = 1e-10, maxiter: int = 1000,
                             exact_hessian: bool = True) -> BaselineResult:
    """The same problem with ``method="trust-constr"`` (``gtol = xtol = tol``), analytic Hessians."""
    ch = _chain(m)
    target = ch.target(dx, dy)
    if exact_hessian:
        def chess(q, v):
            Hx, Hy = ch.tip_hessians(q)
            return v[0] * Hx + v[1] * Hy

        con = NonlinearConstraint(ch.tip, target, target, jac=ch.jacobian, hess=chess)
        hess = lambda q: np.diag(ch.hessian_diag(q))  # noqa: E731
    else:
        con = NonlinearConstraint(ch.tip, target, target, jac=ch.jacobian, hess=BFGS())
        hess = BFGS()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = minimize(ch.energy, np.asarray(q0, float), jac=ch.gradient, hess=hess, method="trust-constr",
                       constraints=[con], bounds=ch.bounds(),
                       options={"gtol": tol, "xtol": tol, "maxiter": maxiter})
    return _result(ch, res.x, target, res.status in (1, 2), res.message, res.nit)


def slsqp_multistart(m, dx: float, dy: float, n_starts: int = 14, seed: int = 0, spread: float = 0.5,
                     tol: float = 1e-10) -> BaselineResult:
    """SLSQP from ``n_starts`` uniform random starts in ``|q_i| < spread * limit_i``; least energy kept.

    Only converged solutions that meet the target and stay strictly inside the range compete.
    """
    ch = _chain(m)
    rng = np.random.default_rng(seed)
    best: BaselineResult | None = None
    nit = 0
    for _ in range(n_starts):
        q0 = rng.uniform(-spread, spread, ch.n) * ch.limits
        r = slsqp_equilibrium(ch, dx, dy, q0, tol=tol)
        nit += r.nit
        ok = r.success and r.tip_error < 1e-8 and bool(np.all(np.abs(r.q) < ch.limits * (1 - 1e-7)))
        if ok and (best is None or r.energy < best.energy):
            best = r
    if best is None:
        return BaselineResult(q=np.full(ch.n, np.nan), energy=math.inf, success=False,
                              message="no start converged", nit=nit, tip_error=math.inf)
    best.nit = nit
    return best


# -------------------------------------------------------------------- the paper's energy method (n = 4)
def _two_angle_ik(ch: Chain, target: np.ndarray, q1: np.ndarray, q4: np.ndarray, elbow: int):
    """``(q2, q3)`` placing the tip on ``target`` for given ``(q1, q4)`` (arrays), one elbow (+1/-1).

    Links 3 and 4 rotate together for fixed ``q4``: ``l3 e^{i phi3} + l4 e^{i(phi3 + q4)} =
    e^{i phi3} (l3 + l4 e^{i q4})``, one rigid link of length ``r`` at the angle offset ``gamma``.
    Returns NaN where the target is out of reach for these ``(q1, q4)``.
    """
    l1, l2, l3, l4 = ch.links
    px = ch.base + l1 * np.cos(q1)
    py = l1 * np.sin(q1)
    wx = l3 + l4 * np.cos(q4)
    wy = l4 * np.sin(q4)
    r = np.hypot(wx, wy)
    gamma = np.arctan2(wy, wx)
    ex = target[0] - px
    ey = target[1] - py
    d2 = ex * ex + ey * ey
    cosb = (d2 - l2 * l2 - r * r) / (2.0 * l2 * r)
    with np.errstate(invalid="ignore"):
        bend = elbow * np.arccos(cosb)                          # angle of the combined link relative to link 2
        phi2 = np.arctan2(ey, ex) - np.arctan2(r * np.sin(bend), l2 + r * np.cos(bend))
    psi = phi2 + bend                                           # absolute angle of the combined link
    phi3 = psi - gamma
    q2 = phi2 - q1
    q3 = phi3 - phi2
    # angles are relative joint angles: bring them to (-pi, pi] (the range is far inside)
    q2 = (q2 + np.pi) % (2 * np.pi) - np.pi
    q3 = (q3 + np.pi) % (2 * np.pi) - np.pi
    return q2, q3


def _energy_grid(ch: Chain, Q: np.ndarray) -> np.ndarray:
    """Energies of configurations ``Q`` (..., 4); ``inf`` outside the open range or where NaN."""
    L1 = 2.0 * ch.c * np.cos(ch.beta + Q / 2.0)
    L2 = 2.0 * ch.c * np.cos(ch.beta - Q / 2.0)
    E = 0.5 * ((ch.k1 * (L1 - ch.L10) ** 2).sum(-1) + (ch.k2 * (L2 - ch.L20) ** 2).sum(-1))
    ok = np.all(np.abs(Q) < ch.limits, axis=-1) & np.isfinite(E)
    return np.where(ok, E, np.inf)


def energy_method_n4(m, dx: float, dy: float, grid: int = 101, maxiter: int = 400,
                     margin: float = 1e-6) -> BaselineResult:
    """The paper's "straightforward energy method" for n = 4.

    Grid search of ``E`` over ``(q1, q4)`` (``grid x grid`` points spanning the open physical
    range) with ``(q2, q3)`` from two-link inverse kinematics on both elbows; the least-energy
    grid point is refined by Nelder-Mead in ``(q1, q4)`` on its elbow (``maxiter`` iterations).
    """
    ch = _chain(m)
    if ch.n != 4:
        raise ValueError("the energy method baseline is for n = 4")
    target = ch.target(dx, dy)
    lim1, lim4 = ch.limits[0] * (1 - margin), ch.limits[3] * (1 - margin)
    g1 = np.linspace(-lim1, lim1, grid)
    g4 = np.linspace(-lim4, lim4, grid)
    Q1, Q4 = np.meshgrid(g1, g4, indexing="ij")
    best = (math.inf, None, 0)
    for elbow in (+1, -1):
        q2, q3 = _two_angle_ik(ch, target, Q1, Q4, elbow)
        E = _energy_grid(ch, np.stack([Q1, q2, q3, Q4], axis=-1))
        i = int(np.argmin(E))
        if E.flat[i] < best[0]:
            best = (float(E.flat[i]), (Q1.flat[i], Q4.flat[i]), elbow)
    if best[1] is None:
        return BaselineResult(q=np.full(4, np.nan), energy=math.inf, success=False,
                              message="no grid point reaches the target", nit=0, tip_error=math.inf)
    elbow = best[2]

    def reduced(p):
        q2, q3 = _two_angle_ik(ch, target, np.array(p[0]), np.array(p[1]), elbow)
        return float(_energy_grid(ch, np.array([p[0], q2, q3, p[1]])))

    res = minimize(reduced, np.array(best[1]), method="Nelder-Mead",
                   options={"maxiter": maxiter, "xatol": 1e-10, "fatol": 1e-15})
    q2, q3 = _two_angle_ik(ch, target, np.array(res.x[0]), np.array(res.x[1]), elbow)
    q = np.array([res.x[0], float(q2), float(q3), res.x[1]])
    return _result(ch, q, target, bool(np.isfinite(res.fun)), res.message, res.nit)


# -------------------------------------------------------------------- buckling (dense) and starts
def dense_critical_loads(m, n_modes: int | None = None):
    """Lowest compressive critical loads (tip guided) from the dense reduced eigenproblem.

    ``K = diag(E''(0))``, ``G = T^T diag(links) T`` (``T`` lower-triangular ones),
    ``S0 = T^T links``, ``Z`` = orthonormal null space of ``S0^T`` (SVD);
    ``scipy.linalg.eigh(Z^T K Z, Z^T G Z)``. Returns ``(loads, modes)`` with modes in ``q``.
    """
    ch = _chain(m)
    n = ch.n
    T = np.tril(np.ones((n, n)))
    G = T.T @ (ch.links[:, None] * T)
    S0 = T.T @ ch.links
    Z = sla.null_space(S0[None, :])
    Kd = ch.joint_stiffness()
    A = Z.T @ (Kd[:, None] * Z)
    B = Z.T @ G @ Z
    kw = {} if n_modes is None else {"subset_by_index": [0, min(n_modes, n - 1) - 1]}
    w, V = sla.eigh(A, B, **kw)
    return w, Z @ V


def mode_start(m, dx: float, mode: np.ndarray | None = None) -> np.ndarray:
    """``q = t * mode`` (first guided buckling mode by default) with ``dx = t^2/2 mode^T G mode``."""
    ch = _chain(m)
    if mode is None:
        mode = dense_critical_loads(ch, n_modes=1)[1][:, 0]
    mode = np.asarray(mode, float)
    if mode[np.flatnonzero(np.abs(mode) > 1e-12 * np.abs(mode).max())[0]] < 0:
        mode = -mode
    quad = float(ch.links @ np.cumsum(mode) ** 2)          # mode^T G mode without forming G
    t = math.sqrt(2.0 * dx / quad)
    q = t * mode
    return np.clip(q, -0.9 * ch.limits, 0.9 * ch.limits)


def slsqp_force_deflection(m, dxs, dy: float = 0.0, tol: float = 1e-10) -> list[BaselineResult]:
    """SLSQP at every deflection in order, each from the previous solution.

    ``dx = dy = 0`` is the straight chain (no solve); the first deflected point starts from the
    first buckling mode scaled to its ``dx`` (SLSQP cannot leave ``q = 0``: ``dx/dq = 0`` there).
    """
    ch = _chain(m)
    out: list[BaselineResult] = []
    q_prev: np.ndarray | None = None
    mode = None
    for dx in np.asarray(dxs, float):
        if dx == 0.0 and dy == 0.0:
            out.append(_result(ch, np.zeros(ch.n), ch.target(0.0, 0.0), True, "straight", 0))
            q_prev = None
            continue
        if q_prev is None:
            if mode is None:
                mode = dense_critical_loads(ch, n_modes=1)[1][:, 0]
            q_prev = mode_start(ch, max(dx, 1e-12), mode)
        r = slsqp_equilibrium(ch, float(dx), dy, q_prev, tol=tol)
        out.append(r)
        q_prev = r.q
    return out


def slsqp_preload_step(m, ell_prev, q_prev, target, F, tol: float = 1e-12, maxiter: int = 300):
    """What a user would write for one inverse-statics control step: SLSQP on ``(q, L1_0, L2_0)``,
    ``min 1/2 |l - l_prev|^2`` subject to the equilibrium under the dead load ``F`` and the tip at ``target``
    (numpy model, analytic objective gradient, constraint Jacobian by scipy's finite differences), warm-started
    from the previous step. ``ell`` is segment-major (``L1_0, L2_0`` of segment 1, then 2, ...)."""
    ch = Chain(m)
    n = ch.n
    F = np.asarray(F, float)
    ell_prev = np.asarray(ell_prev, float)

    def cons(x):
        q, ell = x[:n], x[n:]
        L1, L2 = ch._springs(q)
        g = (-ch.k1 * (L1 - ell[0::2]) * ch.c * np.sin(ch.beta + q / 2.0)
             + ch.k2 * (L2 - ell[1::2]) * ch.c * np.sin(ch.beta - q / 2.0))
        return np.concatenate([g - ch.jacobian(q).T @ F, ch.tip(q) - target])

    def f(x):
        d = x[n:] - ell_prev
        return 0.5 * float(d @ d)

    def df(x):
        return np.concatenate([np.zeros(n), x[n:] - ell_prev])

    res = minimize(f, np.concatenate([q_prev, ell_prev]), jac=df, method="SLSQP",
                      constraints=[{"type": "eq", "fun": cons}], options={"ftol": tol, "maxiter": maxiter})
    return res


def timed(fn, *args, **kw):
    """``(result, seconds)`` of one call."""
    t0 = time.perf_counter()
    r = fn(*args, **kw)
    return r, time.perf_counter() - t0
