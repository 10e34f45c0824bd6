"""Independent reference model of a serial chain of dual-triangle tensegrity segments.

Written from ``docs/model.md`` only; it does NOT import ``tensegrity_opt``.
Everything is in the relative joint angles ``q`` (the library works in absolute
angles with CasADi), with hand-derived analytic derivatives, plus finite
differences where an extra independent route is wanted.

Model (``docs/model.md``):
  segment i: a_i, b_i, k1_i, k2_i, L1_0_i, L2_0_i; c = hypot(a, b), beta = atan2(a, b)
  L1 = 2c cos(beta + q/2), L2 = 2c cos(beta - q/2)
  E = sum k1/2 (L1 - L1_0)^2 + k2/2 (L2 - L2_0)^2
  phi_j = q_1 + ... + q_j; base half-link b_1 along +x; link j has length b_j + b_{j+1}
  (j < n), the last b_n; tip = (b_1 + sum l_j cos phi_j, sum l_j sin phi_j)
  target for a deflection (dx, dy): (2 sum b - dx, dy); physical range |q_i| < pi - 2 beta_i
  equilibrium: grad E = J^T F.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla
import scipy.optimize as so


@dataclass
class Chain:
    a: np.ndarray
    b: np.ndarray
    k1: np.ndarray
    k2: np.ndarray
    L10: np.ndarray
    L20: np.ndarray

    def __post_init__(self):
        self._c = np.sqrt(self.a ** 2 + self.b ** 2)
        self._beta = np.arctan2(self.a, self.b)
        links = np.empty(self.n)
        for j in range(self.n - 1):
            links[j] = self.b[j] + self.b[j + 1]
        links[-1] = self.b[-1]
        self._links = links

    # -------------------------------------------------------------- construction
    @classmethod
    def from_segments(cls, segs):
        """``segs``: iterable of (a, b, k, L0) with symmetric springs, or (a, b, k1, k2, L10, L20)."""
        rows = []
        for s in segs:
            if len(s) == 4:
                a, b, k, L0 = s
                rows.append((a, b, k, k, L0, L0))
            else:
                rows.append(tuple(s))
        arr = np.array(rows, dtype=float)
        return cls(*(arr[:, i].copy() for i in range(6)))

    @classmethod
    def uniform(cls, n, a, b, k, L0):
        return cls.from_segments([(a, b, k, L0)] * n)

    # -------------------------------------------------------------- geometry
    @property
    def n(self) -> int:
        return int(self.a.size)

    @property
    def c(self):
        return self._c

    @property
    def beta(self):
        return self._beta

    @property
    def limits(self):
        return math.pi - 2.0 * self.beta

    @property
    def links(self):
        return self._links

    def symmetric_K(self):
        """Closed-form joint stiffness for symmetric segments: k (b L0 - 2 (b^2 - a^2))."""
        return self.k1 * (self.b * self.L10 - 2.0 * (self.b ** 2 - self.a ** 2))

    def target(self, dx, dy=0.0):
        return np.array([2.0 * self.b.sum() - dx, dy])

    def in_range(self, q, margin=0.0):
        return bool(np.all(np.abs(q) < self.limits - margin))

    # -------------------------------------------------------------- energy
    def lengths(self, q):
        q = np.asarray(q, float)
        return (2 * self.c * np.cos(self.beta + q / 2), 2 * self.c * np.cos(self.beta - q / 2))

    def energy(self, q):
        L1, L2 = self.lengths(q)
        return 0.5 * float(np.dot(self.k1, (L1 - self.L10) ** 2) + np.dot(self.k2, (L2 - self.L20) ** 2))

    def grad(self, q):
        """Analytic dE/dq_i (each E_i depends on q_i only)."""
        q = np.asarray(q, float)
        L1, L2 = self.lengths(q)
        dL1 = -self.c * np.sin(self.beta + q / 2)
        dL2 = self.c * np.sin(self.beta - q / 2)
        return self.k1 * (L1 - self.L10) * dL1 + self.k2 * (L2 - self.L20) * dL2

    def hess_diag(self, q):
        """Analytic E_i''(q_i)."""
        q = np.asarray(q, float)
        L1, L2 = self.lengths(q)
        dL1 = -self.c * np.sin(self.beta + q / 2)
        dL2 = self.c * np.sin(self.beta - q / 2)
        d2L1 = -0.5 * self.c * np.cos(self.beta + q / 2)
        d2L2 = -0.5 * self.c * np.cos(self.beta - q / 2)
        return (self.k1 * (dL1 ** 2 + (L1 - self.L10) * d2L1)
                + self.k2 * (dL2 ** 2 + (L2 - self.L20) * d2L2))

    # -------------------------------------------------------------- kinematics
    def tip(self, q):
        phi = np.cumsum(np.asarray(q, float))
        l = self._links
        return np.array([self.b[0] + np.dot(l, np.cos(phi)), np.dot(l, np.sin(phi))])

    def jac(self, q):
        """d tip / d q (2 x n): column i = sum_{j >= i} l_j (-sin phi_j, cos phi_j)."""
        q = np.asarray(q, float)
        phi = np.cumsum(q)
        l = self.links
        J = np.zeros((2, self.n))
        sx, sy = 0.0, 0.0
        for i in range(self.n - 1, -1, -1):     # suffix sums from the tip backwards
            sx -= l[i] * math.sin(phi[i])
            sy += l[i] * math.cos(phi[i])
            J[0, i] = sx
            J[1, i] = sy
        return J

    def tip_hessians(self, q):
        """(Hess x, Hess y): entry (i, k) = -sum_{j >= max(i,k)} l_j (cos phi_j, sin phi_j)."""
        q = np.asarray(q, float)
        phi = np.cumsum(q)
        l = self.links
        Hx = np.zeros((self.n, self.n))
        Hy = np.zeros((self.n, self.n))
        for i in range(self.n):
            for k in range(self.n):
                m = max(i, k)
                Hx[i, k] = -np.sum(l[m:] * np.cos(phi[m:]))
                Hy[i, k] = -np.sum(l[m:] * np.sin(phi[m:]))
        return Hx, Hy

    # -------------------------------------------------------------- statics
    def force_eq8(self, q):
        """Eq. 8: least-squares F with J^T F = grad E, F = (J J^T)^-1 J grad E."""
        J = self.jac(q)
        return np.linalg.lstsq(J.T, self.grad(q), rcond=None)[0]

    def lagrangian_grad(self, q, F):
        return self.grad(q) - self.jac(q).T @ np.asarray(F, float)

    def lagrangian_hess(self, q, F):
        Hx, Hy = self.tip_hessians(q)
        return np.diag(self.hess_diag(q)) - F[0] * Hx - F[1] * Hy

    def lagrangian_hess_fd(self, q, F, h=1e-6):
        """Hessian of E - F.tip by central differences of the analytic gradient (symmetrised)."""
        q = np.asarray(q, float)
        H = np.zeros((self.n, self.n))
        for i in range(self.n):
            e = np.zeros(self.n)
            e[i] = h
            H[:, i] = (self.lagrangian_grad(q + e, F) - self.lagrangian_grad(q - e, F)) / (2 * h)
        return 0.5 * (H + H.T)

    def reduced_eigs(self, q, F, constrained=True, fd=True):
        H = self.lagrangian_hess_fd(q, F) if fd else self.lagrangian_hess(q, F)
        if not constrained:
            return np.linalg.eigvalsh(H)
        Z = sla.null_space(self.jac(q))
        return np.linalg.eigvalsh(Z.T @ H @ Z)

    # -------------------------------------------------------------- solvers
    def newton_kkt(self, target, q, F=None, tol=1e-13, maxit=50):
        """Newton on [grad E - J^T F; tip - target] = 0 with the analytic Jacobian."""
        q = np.array(q, float)
        F = self.force_eq8(q) if F is None else np.array(F, float)
        n = self.n
        for _ in range(maxit):
            r = np.concatenate([self.lagrangian_grad(q, F), self.tip(q) - target])
            if np.max(np.abs(r)) < tol:
                return q, F, True
            J = self.jac(q)
            A = np.zeros((n + 2, n + 2))
            A[:n, :n] = self.lagrangian_hess(q, F)
            A[:n, n:] = -J.T
            A[n:, :n] = J
            try:
                d = np.linalg.solve(A, -r)
            except np.linalg.LinAlgError:
                return q, F, False
            q = q + d[:n]
            F = F + d[n:]
        r = np.concatenate([self.lagrangian_grad(q, F), self.tip(q) - target])
        return q, F, bool(np.max(np.abs(r)) < 1e3 * tol)

    def newton_force(self, F, q, tol=1e-13, maxit=50):
        """Newton on grad E - J^T F = 0 (prescribed dead load)."""
        q = np.array(q, float)
        for _ in range(maxit):
            r = self.lagrangian_grad(q, F)
            if np.max(np.abs(r)) < tol:
                return q, True
            q = q - np.linalg.solve(self.lagrangian_hess(q, F), r)
        return q, bool(np.max(np.abs(self.lagrangian_grad(q, F))) < 1e3 * tol)

    def local_min(self, target, q0):
        """SLSQP on min E s.t. tip = target inside the range, then a Newton KKT polish.

        Returns (q, F) of a strict interior constrained local minimum, or None."""
        lim = self.limits * (1 - 1e-6)
        res = so.minimize(self.energy, q0, jac=self.grad, method="SLSQP",
                          bounds=list(zip(-lim, lim)),
                          constraints=[{"type": "eq", "fun": lambda q: self.tip(q) - target,
                                        "jac": self.jac}],
                          options={"maxiter": 300, "ftol": 1e-10})
        if not np.all(np.isfinite(res.x)) or np.max(np.abs(self.tip(res.x) - target)) > 1e-4:
            return None
        q, F, ok = self.newton_kkt(target, res.x)
        if not ok or not self.in_range(q, 1e-7) or np.max(np.abs(q - res.x)) > 1e-3:
            return None
        w = self.reduced_eigs(q, F, fd=False)
        if w.size and w.min() <= 1e-9 * max(1.0, np.abs(w).max()):
            return None
        return q, F

    def global_min(self, dx, dy=0.0, n_random=200, seed=12345):
        """Least-energy strict interior constrained minimum from many starts.

        Ties (mirror images at dy = 0) go to the one with q_1 > 0."""
        target = self.target(dx, dy)
        rng = np.random.default_rng(seed)
        lim = self.limits
        starts = [rng.uniform(-0.95, 0.95, self.n) * lim for _ in range(n_random)]
        for amp in (0.05, 0.15, 0.4):
            for _ in range(20):
                starts.append(amp * rng.standard_normal(self.n) * lim)
        best = []
        for s in starts:
            r = self.local_min(target, s)
            if r is not None:
                best.append((self.energy(r[0]), r[0], r[1]))
        if not best:
            raise RuntimeError("reference minimiser found nothing")
        e_min = min(b[0] for b in best)
        ties = [b for b in best if b[0] <= e_min + 1e-10 * max(1, abs(e_min))]
        ties.sort(key=lambda b: -b[1][0])
        return ties[0]


# ------------------------------------------------------------------ buckling (independent route)
def fd_second_derivs(chain: Chain):
    """K = diag E_i''(0) and G = -Hess x at q = 0, S0 = d y/dq at 0, all by finite differences
    of the reference energy / tip (5-point stencils)."""
    n = chain.n
    h = 1e-3
    z = np.zeros(n)

    def d2(f, i, k):
        ei = np.zeros(n)
        ek = np.zeros(n)
        ei[i] = h
        ek[k] = h
        if i == k:
            return (-f(z + 2 * ei) + 16 * f(z + ei) - 30 * f(z) + 16 * f(z - ei) - f(z - 2 * ei)) / (12 * h * h)
        # central mixed difference D(h), Richardson-extrapolated: (4 D(h) - D(2h)) / 3 = O(h^4)
        def D(s):
            return ((f(z + s * (ei + ek)) - f(z + s * (ei - ek)) - f(z - s * (ei - ek)) + f(z - s * (ei + ek)))
                    / (4 * h * h * s * s))
        return (4 * D(1) - D(2)) / 3

    K = np.array([d2(chain.energy, i, i) for i in range(n)])
    def tipx(q):
        return chain.tip(q)[0]
    def tipy(q):
        return chain.tip(q)[1]
    G = np.array([[-d2(tipx, i, k) for k in range(n)] for i in range(n)])
    G = 0.5 * (G + G.T)
    S0 = np.zeros(n)
    for i in range(n):
        e = np.zeros(n)
        e[i] = h
        S0[i] = (-tipy(2 * e) + 8 * tipy(e) - 8 * tipy(-e) + tipy(-2 * e)) / (12 * h)
    return K, G, S0


def _roots_of(f, upper, num=20000):
    """All sign changes of f on (0, upper], refined by brentq (log-spaced + linear grid)."""
    grid = np.unique(np.concatenate([np.geomspace(upper * 1e-6, upper, num // 2),
                                     np.linspace(upper * 1e-6, upper, num // 2)]))
    vals = np.array([f(p) for p in grid])
    roots = []
    for i in range(grid.size - 1):
        if vals[i] == 0.0:
            roots.append(grid[i])
        elif vals[i] * vals[i + 1] < 0:
            roots.append(so.brentq(f, grid[i], grid[i + 1], xtol=1e-15, rtol=1e-14, maxiter=200))
    return np.array(roots)


def critical_loads_guided(chain: Chain):
    """All P > 0 with det [[K - P G, S0], [S0^T, 0]] = 0 (ascending)."""
    K, G, S0 = fd_second_derivs(chain)
    n = chain.n

    def det(P):
        A = np.zeros((n + 1, n + 1))
        A[:n, :n] = np.diag(K) - P * G
        A[:n, n] = S0
        A[n, :n] = S0
        return np.linalg.det(A)

    upper = 2.0 * K.max() / np.linalg.eigvalsh(G).min()
    return _roots_of(det, upper)


def critical_loads_free(chain: Chain):
    """All P > 0 with det (K - P G) = 0 (ascending)."""
    K, G, _ = fd_second_derivs(chain)
    upper = 2.0 * K.max() / np.linalg.eigvalsh(G).min()
    return _roots_of(lambda P: np.linalg.det(np.diag(K) - P * G), upper)


# ------------------------------------------------------------------ n = 4 two-link inverse kinematics
def ik_q14(chain: Chain, target, q1, q4, elbow):
    """q = (q1, q2, q3, q4) with the tip at ``target`` for given q1, q4 (n = 4), or None.

    Joint 2 sits at p2 = (b_1, 0) + l_1 (cos q1, sin q1). From joint 2 the rigid link 2 (length
    l_2, direction phi2 = q1 + q2) reaches joint 3; from joint 3 links 3 and 4 (relative angle q4)
    form a rigid arm w = (l_3 + l_4 cos q4, l_4 sin q4) in the frame of link 3. Triangle
    (p2, joint 3, target): phi2 = angle(target - p2) + elbow * gamma (law of cosines)."""
    assert chain.n == 4
    l = chain.links
    p2 = np.array([chain.b[0] + l[0] * math.cos(q1), l[0] * math.sin(q1)])
    d = np.asarray(target, float) - p2
    D = math.hypot(d[0], d[1])
    w = np.array([l[2] + l[3] * math.cos(q4), l[3] * math.sin(q4)])
    r2 = math.hypot(w[0], w[1])
    if D == 0.0:
        return None
    cg = (D * D + l[1] ** 2 - r2 * r2) / (2 * D * l[1])
    if abs(cg) > 1.0:
        return None
    phi2 = math.atan2(d[1], d[0]) + elbow * math.acos(cg)
    p3 = p2 + l[1] * np.array([math.cos(phi2), math.sin(phi2)])
    e = np.asarray(target, float) - p3
    phi3 = math.atan2(e[1], e[0]) - math.atan2(w[1], w[0])
    # relative angles between link directions, the representative in (-pi, pi]
    q2 = math.remainder(phi2 - q1, 2 * math.pi)
    q3 = math.remainder(phi3 - phi2, 2 * math.pi)
    return np.array([q1, q2, q3, q4])


def ik_energy(chain: Chain, target, q1, q4, elbow):
    """Energy at the IK completion, NaN when unreachable or outside the physical range."""
    q = ik_q14(chain, target, q1, q4, elbow)
    if q is None or not chain.in_range(q):
        return float("nan"), q
    return chain.energy(q), q


# ------------------------------------------------------------------ all equilibria (random Newton)
def all_equilibria(chain: Chain, dx, dy=0.0, n_starts=400, seed=1, dedupe=1e-6):
    """Every KKT point found by Newton from random starts projected on tip = target (min-norm
    Gauss-Newton), kept when strictly inside the physical range. Returns a list of (q, F)."""
    rng = np.random.default_rng(seed)
    target = chain.target(dx, dy)
    sols = []
    for _ in range(n_starts):
        q = rng.uniform(-0.98, 0.98, chain.n) * chain.limits
        for _ in range(40):
            r = target - chain.tip(q)
            if np.max(np.abs(r)) < 1e-12:
                break
            q = q + np.linalg.lstsq(chain.jac(q), r, rcond=None)[0]
        if not np.all(np.isfinite(q)):
            continue
        q, F, ok = chain.newton_kkt(target, q)
        if ok and chain.in_range(q) and not any(np.max(np.abs(q - s)) < dedupe for s, _ in sols):
            sols.append((q, F))
    return sols


def all_force_equilibria(chain: Chain, F, n_starts=500, seed=2, dedupe=1e-6):
    """Every solution of grad E = J^T F (dead load) found by Newton from random starts, strictly
    inside the physical range. Returns a list of q."""
    rng = np.random.default_rng(seed)
    F = np.asarray(F, float)
    sols = []
    for _ in range(n_starts):
        q, ok = chain.newton_force(F, rng.uniform(-0.98, 0.98, chain.n) * chain.limits)
        if ok and np.all(np.isfinite(q)) and chain.in_range(q) \
                and not any(np.max(np.abs(q - s)) < dedupe for s in sols):
            sols.append(q)
    return sols


def kkt_least_squares(chain: Chain, dx, dy=0.0, n_starts=2000, seed=3, dedupe=1e-6):
    """Brute force over the whole range: ``scipy.optimize.least_squares`` (Levenberg-Marquardt, the analytic
    Jacobian) on the equilibrium equations ``[grad E - J^T F; tip - target] = 0`` in ``(q, F)`` from
    ``n_starts`` uniform random ``q`` inside the physical range (random ``F``). Returns the distinct solutions
    strictly inside the range (a list of ``(q, F)``) and how many starts converged to one outside it."""
    rng = np.random.default_rng(seed)
    target = chain.target(dx, dy)
    n = chain.n
    scale = float(np.mean((chain.k1 + chain.k2) * chain.c ** 2))

    def residual(z):
        return np.concatenate([chain.lagrangian_grad(z[:n], z[n:]), chain.tip(z[:n]) - target])

    def jacobian(z):
        J = chain.jac(z[:n])
        A = np.zeros((n + 2, n + 2))
        A[:n, :n] = chain.lagrangian_hess(z[:n], z[n:])
        A[:n, n:] = -J.T
        A[n:, :n] = J
        return A

    sols, outside = [], 0
    for _ in range(n_starts):
        z0 = np.concatenate([rng.uniform(-1.0, 1.0, n) * chain.limits, scale * rng.standard_normal(2)])
        r = so.least_squares(residual, z0, jac=jacobian, method="lm", xtol=1e-15, ftol=1e-15, gtol=1e-15,
                             max_nfev=200)
        if not (np.all(np.isfinite(r.fun)) and np.max(np.abs(r.fun)) < 1e-9 * max(1.0, scale)):
            continue
        q = r.x[:n]
        if not chain.in_range(q):
            outside += 1
        elif not any(np.max(np.abs(q - s)) < dedupe for s, _ in sols):
            sols.append((q, r.x[n:]))
    return sols, outside


def tip_stiffness_fd(chain: Chain, target, q, F, h: float, max_move: float) -> np.ndarray:
    """``dF/d(tip)`` by central differences: the force holding the tip at ``target +- h e_j``, each found by
    Newton from the equilibrium ``(q, F)`` at ``target``, which it must not leave by more than ``max_move``."""
    target = np.asarray(target, float)
    K = np.zeros((2, 2))
    for j in range(2):
        e = np.zeros(2)
        e[j] = h
        qp, Fp, okp = chain.newton_kkt(target + e, q, F)
        qm, Fm, okm = chain.newton_kkt(target - e, q, F)
        assert okp and okm and np.abs(qp - q).max() < max_move and np.abs(qm - q).max() < max_move
        K[:, j] = (Fp - Fm) / (2 * h)
    return K
