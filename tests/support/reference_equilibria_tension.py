"""Independent reference: EVERY equilibrium of a chain (n = 2, 3, 4) with its tip held at a target, in the CLOSED
joint range, under each segment's own spring law (linear or tension-only), the joint stops included.

Imports numpy, scipy and the sibling reference :mod:`reference_tension_only` (for :func:`segs_of`, the limits and
the target) -- never ``tensegrity_opt``. The model is the one of :mod:`reference_tension_only` (its docstring);
here the one-joint energy and its first two derivatives are written in closed form from
``L1 = 2c cos(beta + q/2)``, ``L2 = 2c cos(beta - q/2)`` (the self-tests check them against
``reference_tension_only``'s vertex-built energy and force-vector torques), and the tip's first and second
derivatives from ``x = b_1 + sum l_j cos phi_j``, ``y = sum l_j sin phi_j``.

What is an equilibrium (``E`` the energy, ``J`` the 2 x n tip Jacobian, ``F`` the tip force):

* **interior**: all ``|q_i| < lim_i = pi - 2 beta_i``, ``grad E = J^T F``, ``tip(q) = target``;
* **on stops**: a set ``S`` (``1 <= |S| <= n - 2``) of joints at ``q_i = s_i lim_i``, the others free and strictly
  inside; the free rows of ``grad E = J^T F`` hold, ``tip = target``, and each stop's contact torque
  ``c_i = -s_i (dE/dq_i - (J^T F)_i) >= 0`` (records with ``c_i < -CONTACT_TOL`` are not equilibria; with
  ``|c_i| <= CONTACT_TOL`` they are kept and flagged ``degenerate``).

Morse index: the negative eigenvalues of the Hessian of ``E - F . tip`` (the diagonal energy part uses the taut
branch only where ``L - L0 > 0`` strictly) reduced to ``null([J; e_i, i in S])``.

Method (for every stop set ``S`` and sign pattern, ``S`` empty included, the free joints ``f`` with
``m = |f| - 2 >= 0`` degrees of freedom on the manifold ``tip = target``):

* **charts**: for every pair ``(i, j)`` of free joints the other free joints are parameters ``p``; ``(q_i, q_j)``
  follow in closed form from the tip (two-link inverse kinematics with the fixed links folded into two offset
  vectors ``u``, ``v``; elbow ``sigma = +-1``). On a chart the tip force is ``F = J_r^{-T} dE_r`` (``r = (i, j)``)
  and the total derivative of ``E`` along the manifold is ``g = dE_p - J_p^T F``: its zeros are exactly the
  equilibria. ``g`` has a pole where ``det J_r = 0`` (the branch's fold, ``|C| = 1`` in the cosine law), so the
  search uses ``g det J_r`` (no pole; ``det J_r`` keeps the elbow's sign on a branch, so the sign changes are
  those of ``g``). A fold of one chart is a regular point of another (``J`` has rank 2, so some 2 x 2 minor is
  nonsingular): using ALL pairs covers every point of the manifold by a chart in which it is well conditioned
  -- this is how the turning points of the n = 3 curve (folds in ``q_1``) are handled: the curve is searched
  with each of ``q_1``, ``q_2``, ``q_3`` as the parameter, both elbows, and the results merged.
* ``m = 0`` (n = 2, or ``|S| = n - 2``: "rigid"): the two elbow solutions, each checked.
* ``m = 1`` (n = 3 interior, n = 4 with one stop): the parameter on ``grid1`` points (default 20001) of its closed
  range, the IK joints allowed ``margin`` beyond their range (the closed-form energy is analytic there, so a root
  just inside a limit is still bracketed; roots outside are dropped); sign changes of ``g det J_r`` between
  consecutive valid points of one elbow branch are bisected by Brent (``xtol`` 1e-14).
* ``m = 2`` (n = 4 interior): the two parameters on a ``grid2 x grid2`` grid (default 801) per chart (6 charts x 2
  elbows); seeds are the cells whose four valid corners show a sign change of both components (seeded at the
  cell's linearised zero), plus the grid's local minima of the normalised ``|g det J_r|`` ("small gradient":
  catches close pairs of roots in one cell and nearly tangent zero curves).
* every seed is polished by damped Newton on the full KKT system in ``(q_f, F)`` (analytic Hessian), accepted when
  the residual is below 1e-11 (relative to ``max k c^2`` and ``sum b``) and the point lies in the closed range,
  then deduplicated (1e-7 in ``q``, max-norm).
* classification: a free joint within ``STOP_TOL`` of its stop is moved to the stop set (``degenerate``); when
  the free rows do not determine ``F`` (fewer than two free joints, e.g. three joints of n = 4 at their stops, or a
  singular minor) the record is kept iff a linear programme finds an ``F`` balancing the free rows with every
  contact torque ``>= 0`` (the least ``|F_x| + |F_y|`` such ``F`` is reported; ``degenerate``, "tip force not
  unique"); a stop with a contact torque below ``-CONTACT_TOL`` rejects the candidate.

:func:`multistart` is an independent cross-check: many random starts per stop set, projected on the manifold by
Gauss-Newton, then the same KKT Newton, batched.

Not covered (not generic): non-isolated critical sets -- with ``F = 0`` and three or more free joints fully slack
(both springs of each below rest length, tension-only) those joints' angles are free along the manifold: a
continuum of equilibria, only SAMPLED (the ends of each flat run in 1-D, five flat grid points per chart in 2-D),
its records flagged ``degenerate`` with reason :data:`CONTINUUM` and counted apart by :func:`count_by_kind`;
a root of even multiplicity (a tangency of the zero curves: no sign change; only the small-gradient seeds can
find it); two roots closer than a grid cell in every chart (only one is seeded by the sign test; the second needs
a small-gradient seed); chains near a kinematic singularity of the whole arm (target distance equal to
``|sum +- l_j|``, where every minor of ``J`` is small). The Morse index at a tension-only kink (a spring exactly at
rest length) uses the slack side's second derivative and is flagged ``degenerate``.

Cost (one core): n = 3 about 0.1 s; n = 4 about 2.5 s at ``grid2 = 401`` and 9-10 s at the default 801.
"""

from __future__ import annotations

import collections
import itertools
import math
from dataclasses import dataclass

import numpy as np
import reference_tension_only as RT
import scipy.linalg as sl
import scipy.optimize as so

#: a free joint within this of its stop counts as at the stop (then the record is ``degenerate``)
STOP_TOL = 1e-9
#: contact torques (relative to ``max k c^2``): below ``-CONTACT_TOL`` rejected, ``|c| <= CONTACT_TOL`` degenerate
CONTACT_TOL = 1e-8
#: reduced-Hessian eigenvalues (relative to ``max k c^2``) this small are singular: ``degenerate``
EIG_TOL = 1e-8
#: KKT residual accepted after Newton (relative)
KKT_TOL = 1e-11
#: deduplication, max-norm in q
DEDUP = 1e-7
#: a 2-D chart seeds only where its IK minor is at least this fraction of the best minor over all pairs
RESPONSIBLE = 0.3
#: small-gradient seeds: grid local minima of |g1|/s1 + |g2|/s2 (s the 90th percentile) below this
SMALL_GRADIENT = 0.05
#: the reason given to a sample point of a continuum of equilibria (F = 0 and at least three fully slack joints,
#: whose angles are then free along the manifold); such sets are only sampled
CONTINUUM = "continuum (F = 0, three or more free joints fully slack)"
#: a tension-only spring this close to its rest length sits on the energy's kink: ``degenerate`` (one-sided Hessian)
KINK_TOL = 1e-9


# ---------------------------------------------------------------------------- records
@dataclass
class Record:
    q: np.ndarray                 # (n,)
    F: np.ndarray                 # (2,) tip force: grad E = J^T F on the free rows
    energy: float
    morse_index: int              # negative eigenvalues of the reduced Hessian of E - F . tip
    stops: np.ndarray             # (n,) int: -1 / +1 at the negative / positive stop, 0 free
    contact_torques: np.ndarray   # (n,) >= 0 (up to CONTACT_TOL): -s_i (dE/dq_i - (J^T F)_i) at stops, 0 free
    degenerate: bool              # tiny contact torque, singular reduced Hessian, free joint at a stop, or a kink
    residual: float = 0.0         # max |KKT residual| (torque rows and tip rows, absolute)
    eigenvalues: np.ndarray | None = None   # of the reduced Hessian (m,)
    reasons: tuple = ()           # why degenerate

    @property
    def kind(self) -> str:
        return "stop" if np.any(self.stops) else "interior"

    @property
    def stable(self) -> bool:
        return self.morse_index == 0


def count_by_kind(records) -> dict:
    """``{"interior": {index: count}, "stop": {index: count}, "degenerate": count, "total": count}``, plus
    ``"continuum": count`` (sample points of a continuum of equilibria, left out of the interior / stop counts)
    when any."""
    out = {"interior": collections.Counter(), "stop": collections.Counter()}
    flat = 0
    for r in records:
        if CONTINUUM in r.reasons:
            flat += 1
        else:
            out[r.kind][r.morse_index] += 1
    res = {"interior": dict(sorted(out["interior"].items())), "stop": dict(sorted(out["stop"].items())),
           "degenerate": sum(r.degenerate for r in records), "total": len(records)}
    if flat:
        res["continuum"] = flat
    return res


# ---------------------------------------------------------------------------- the chain, closed forms
@dataclass(frozen=True)
class _Chain:
    a: np.ndarray
    b: np.ndarray
    c: np.ndarray
    beta: np.ndarray
    k: np.ndarray        # (n, 2)
    L0: np.ndarray       # (n, 2)
    slack: np.ndarray    # (n,) tension-only
    lim: np.ndarray
    links: np.ndarray
    scale_e: float       # torque / energy scale max k c^2
    scale_x: float       # length scale sum b

    @property
    def n(self) -> int:
        return int(self.a.size)


def _chain(segs) -> _Chain:
    for s in segs:
        if s["law"] not in RT.LAWS:
            raise ValueError(f"unknown spring law {s['law']!r}")
    a = np.array([s["a"] for s in segs], float)
    b = np.array([s["b"] for s in segs], float)
    k = np.array([[s["k1"], s["k2"]] for s in segs], float)
    links = b.copy()
    links[:-1] = b[:-1] + b[1:]
    c = np.hypot(a, b)
    return _Chain(a=a, b=b, c=c, beta=np.arctan2(a, b), k=k,
                  L0=np.array([[s["L10"], s["L20"]] for s in segs], float),
                  slack=np.array([s["law"] == "tension_only" for s in segs]),
                  lim=np.asarray(RT.limits(segs), float), links=links,
                  scale_e=float(max(np.max(k * (c ** 2)[:, None]), 1e-300)), scale_x=float(b.sum()))


def _springs(ch: _Chain, q):
    """``L, dL/dq, d2L/dq2`` each (..., n, 2), from ``L1 = 2c cos(beta + q/2)``, ``L2 = 2c cos(beta - q/2)``."""
    q = np.asarray(q, float)
    h1, h2 = ch.beta + q / 2, ch.beta - q / 2
    c = ch.c
    L = np.stack([2 * c * np.cos(h1), 2 * c * np.cos(h2)], -1)
    dL = np.stack([-c * np.sin(h1), c * np.sin(h2)], -1)
    d2L = np.stack([-0.5 * c * np.cos(h1), -0.5 * c * np.cos(h2)], -1)
    return L, dL, d2L


def _energy_derivs(ch: _Chain, q, second=True):
    """``E (...,)``, ``dE/dq (..., n)``, ``d2E/dq2 (..., n)`` (None unless ``second``); E is a sum of one-joint
    terms. Written spring by spring (no stacking): it runs on the whole grid."""
    q = np.asarray(q, float)
    E = 0.0
    dE = 0.0
    d2E = 0.0 if second else None
    for s, sgn in ((0, 1.0), (1, -1.0)):
        h = ch.beta + sgn * 0.5 * q
        ch_, sh = np.cos(h), np.sin(h)
        x = 2.0 * ch.c * ch_ - ch.L0[:, s]
        if ch.slack.any():
            taut = (x > 0) | ~ch.slack
            x = np.where(taut, x, 0.0)
        k = ch.k[:, s]
        dL = -sgn * ch.c * sh
        E = E + 0.5 * np.sum(k * x * x, -1)
        dE = dE + k * x * dL
        if second:
            d2L = -0.5 * ch.c * ch_
            d2E = d2E + k * ((taut if ch.slack.any() else 1.0) * dL * dL + x * d2L)
    return E, dE, d2E


def _kin(ch: _Chain, q):
    """``tip (..., 2)``, ``J (..., 2, n)``, and the reversed cumulative sums ``Cx = sum_{j>=i} l_j cos phi_j``,
    ``Sy = sum_{j>=i} l_j sin phi_j`` (..., n) that give the second derivatives."""
    q = np.asarray(q, float)
    phi = np.cumsum(q, -1)
    lc, ls = ch.links * np.cos(phi), ch.links * np.sin(phi)
    Cx = np.flip(np.cumsum(np.flip(lc, -1), -1), -1)
    Sy = np.flip(np.cumsum(np.flip(ls, -1), -1), -1)
    tip = np.stack([ch.b[0] + Cx[..., 0], Sy[..., 0]], -1)
    J = np.stack([-Sy, Cx], -2)
    return tip, J, Cx, Sy


def _hess_L(ch: _Chain, q, F):
    """Hessian of ``E - F . tip`` in q, (..., n, n): ``diag(E'') + F_x Cx[max(i,m)] + F_y Sy[max(i,m)]``."""
    q = np.asarray(q, float)
    F = np.asarray(F, float)
    _, _, d2E = _energy_derivs(ch, q)
    _, _, Cx, Sy = _kin(ch, q)
    n = ch.n
    M = np.maximum.outer(np.arange(n), np.arange(n))
    H = F[..., 0, None, None] * Cx[..., M] + F[..., 1, None, None] * Sy[..., M]
    return H + d2E[..., None, :] * np.eye(n)


def _wrap(x):
    return np.remainder(x + math.pi, 2 * math.pi) - math.pi


def _ik(ch: _Chain, Q, i, j, sigma, tgt):
    """Solve joints ``i < j`` of the rows of ``Q`` (N, n) (the other entries given) so the tip is at ``tgt``.

    ``tip = P_i + R(phi_{i-1} + q_i) (u + R(alpha + q_j) v)``; ``|u + R(.) v| = |tgt - P_i|`` is the cosine law
    ``cos(alpha + q_j + ang v - ang u) = C``; elbow ``sigma`` picks ``+-arccos C``. Returns ``(Q', valid)``,
    ``valid = |C| <= 1``.
    """
    Q = np.array(Q, float)
    Q0 = Q.copy()
    Q0[:, i] = 0.0
    Q0[:, j] = 0.0
    th = np.cumsum(Q0, 1)
    l = ch.links
    Px = ch.b[0] + np.sum(l[:i] * np.cos(th[:, :i]), 1)
    Py = np.sum(l[:i] * np.sin(th[:, :i]), 1)
    phib = th[:, i]
    psi = th[:, i:j] - th[:, [i]]
    ux, uy = np.sum(l[i:j] * np.cos(psi), 1), np.sum(l[i:j] * np.sin(psi), 1)
    alpha = th[:, j] - th[:, i]
    chi = th[:, j:] - th[:, [j]]
    vx, vy = np.sum(l[j:] * np.cos(chi), 1), np.sum(l[j:] * np.sin(chi), 1)
    dx, dy = tgt[0] - Px, tgt[1] - Py
    ru, rv = np.hypot(ux, uy), np.hypot(vx, vy)
    C = (dx * dx + dy * dy - ru * ru - rv * rv) / (2 * ru * rv)
    valid = np.abs(C) <= 1.0
    gam = sigma * np.arccos(np.clip(C, -1.0, 1.0))
    qj = _wrap(gam - alpha - np.arctan2(vy, vx) + np.arctan2(uy, ux))
    ang = alpha + qj
    wx = ux + np.cos(ang) * vx - np.sin(ang) * vy
    wy = uy + np.sin(ang) * vx + np.cos(ang) * vy
    qi = _wrap(np.arctan2(dy, dx) - np.arctan2(wy, wx) - phib)
    Q[:, i], Q[:, j] = qi, qj
    return Q, valid


def _g_scaled(ch: _Chain, Q, i, j, params):
    """``(dE_p - J_p^T F) det J_r`` with ``F = J_r^{-T} dE_r`` (N, len(params)), and ``det J_r`` (N,)."""
    _, dE, _ = _energy_derivs(ch, Q, second=False)
    _, J, _, _ = _kin(ch, Q)
    Jx, Jy = J[:, 0], J[:, 1]
    det = Jx[:, i] * Jy[:, j] - Jy[:, i] * Jx[:, j]
    gi, gj = dE[:, i], dE[:, j]
    Fdx = Jy[:, j] * gi - Jy[:, i] * gj
    Fdy = -Jx[:, j] * gi + Jx[:, i] * gj
    G = np.stack([dE[:, p] * det - (Jx[:, p] * Fdx + Jy[:, p] * Fdy) for p in params], -1) if params else \
        np.zeros((Q.shape[0], 0))
    return G, det, J


def _best_minor(J, free):
    """``max |det J[:, (a, b)]|`` over pairs of free joints (N,): the best-conditioned chart at each point."""
    Jx, Jy = J[:, 0], J[:, 1]
    return np.max([np.abs(Jx[:, a] * Jy[:, b] - Jy[:, a] * Jx[:, b]) for a, b in itertools.combinations(free, 2)],
                  0)


# ---------------------------------------------------------------------------- Newton on the KKT system
def _kkt(ch, q, F, free, tgt):
    _, dE, _ = _energy_derivs(ch, q)
    tip, J, _, _ = _kin(ch, q)
    r = np.concatenate([dE[free] - J[:, free].T @ F, tip - tgt])
    return r, J


def _residual_norm(ch, r, nf):
    return max(float(np.max(np.abs(r[:nf]))) / ch.scale_e, float(np.max(np.abs(r[nf:]))) / ch.scale_x)


def _newton(ch: _Chain, q0, free, tgt, F0=None, iters=80):
    """Damped Newton on ``dE_f - J_f^T F = 0``, ``tip = tgt`` in ``(q_f, F)``. Returns ``(q, F, ok)``."""
    free = np.asarray(free)
    nf = free.size
    q = np.array(q0, float)
    _, dE, _ = _energy_derivs(ch, q)
    _, J, _, _ = _kin(ch, q)
    F = np.linalg.lstsq(J[:, free].T, dE[free], rcond=None)[0] if F0 is None else np.array(F0, float)
    r, J = _kkt(ch, q, F, free, tgt)
    nr = _residual_norm(ch, r, nf)
    for _ in range(iters):
        if nr < 1e-14:
            break
        H = _hess_L(ch, q, F)[np.ix_(free, free)]
        Jf = J[:, free]
        K = np.block([[H, -Jf.T], [Jf, np.zeros((2, 2))]])
        try:
            step = np.linalg.solve(K, -r)
        except np.linalg.LinAlgError:
            step = np.linalg.lstsq(K, -r, rcond=None)[0]
        dq = step[:nf]
        big = float(np.max(np.abs(dq)))
        t = 1.0 if big < 0.5 else 0.5 / big
        improved = False
        for _ in range(30):
            qt = q.copy()
            qt[free] += t * dq
            Ft = F + t * step[nf:]
            rt, Jt = _kkt(ch, qt, Ft, free, tgt)
            nt = _residual_norm(ch, rt, nf)
            if nt < nr or nt < 1e-14:
                improved = True
                break
            t *= 0.5
        if not improved:
            break
        q, F, r, J, nr = qt, Ft, rt, Jt, nt
    return q, F, nr < KKT_TOL


# ---------------------------------------------------------------------------- seeds on one stop set
def _seeds_rigid(ch, tgt, base, free):
    i, j = free
    out = []
    for sigma in (1.0, -1.0):
        Q, ok = _ik(ch, base[None], i, j, sigma, tgt)
        if ok[0]:
            out.append(Q[0])
    return out


def _in_ext(ch, Q, margin):
    return np.all(np.abs(Q) <= ch.lim + margin, axis=-1)


def _seeds_curve(ch, tgt, base, free, grid, margin):
    """m = 1: every chart (parameter p, IK joints the other two), both elbows; Brent on sign changes."""
    out = []
    for p in free:
        i, j = sorted(set(free) - {p})
        xs = np.linspace(-ch.lim[p], ch.lim[p], grid)
        Q = np.tile(base, (grid, 1))
        Q[:, p] = xs
        for sigma in (1.0, -1.0):
            Qs, ok = _ik(ch, Q, i, j, sigma, tgt)
            ok &= _in_ext(ch, Qs, margin)
            G = _g_scaled(ch, Qs, i, j, [p])[0][:, 0]
            # exact zeros: a flat (all-slack) stretch gives runs of them; seed only the ends of each run
            z = ok & (G == 0.0)
            inner = z.copy()
            inner[1:-1] = z[:-2] & z[1:-1] & z[2:]
            inner[[0, -1]] = False
            exact = np.flatnonzero(z & ~inner)
            out.extend(Qs[e] for e in exact)
            br = np.flatnonzero(ok[:-1] & ok[1:] & (G[:-1] * G[1:] < 0))

            def f(x, i=i, j=j, p=p, sigma=sigma):
                row = base.copy()
                row[p] = x
                Qx, okx = _ik(ch, row[None], i, j, sigma, tgt)
                if not okx[0]:
                    raise ValueError("left the branch")
                return float(_g_scaled(ch, Qx, i, j, [p])[0][0, 0])

            for kk in br:
                try:
                    x = so.brentq(f, xs[kk], xs[kk + 1], xtol=1e-14, rtol=4 * np.finfo(float).eps, maxiter=200)
                except ValueError:
                    x = 0.5 * (xs[kk] + xs[kk + 1])
                row = base.copy()
                row[p] = x
                Qx, okx = _ik(ch, row[None], i, j, sigma, tgt)
                out.append(Qx[0] if okx[0] else Qs[kk])
    return out


def _seeds_surface(ch, tgt, base, free, grid, margin, minima=200):
    """m = 2: every chart (IK pair, the other two on a grid x grid grid), both elbows."""
    out = []
    for i, j in itertools.combinations(free, 2):
        p1, p2 = sorted(set(free) - {i, j})
        x1 = np.linspace(-ch.lim[p1], ch.lim[p1], grid)
        x2 = np.linspace(-ch.lim[p2], ch.lim[p2], grid)
        h1, h2 = x1[1] - x1[0], x2[1] - x2[0]
        X1, X2 = np.meshgrid(x1, x2, indexing="ij")
        Q = np.tile(base, (grid * grid, 1))
        Q[:, p1], Q[:, p2] = X1.ravel(), X2.ravel()
        for sigma in (1.0, -1.0):
            Qs, ok = _ik(ch, Q, i, j, sigma, tgt)
            ok &= _in_ext(ch, Qs, margin)
            G, det, J = _g_scaled(ch, Qs, i, j, [p1, p2])
            G = np.where(ok[:, None], G, np.nan).reshape(grid, grid, 2)
            okg = ok.reshape(grid, grid)
            # this chart answers for the points where its minor is within RESPONSIBLE of the best one (every point
            # of the manifold has a chart whose minor is the best: the charts overlap, none has to reach its folds)
            resp = (ok & (np.abs(det) >= RESPONSIBLE * _best_minor(J, free))).reshape(grid, grid)
            # flat points (g exactly 0, e.g. every spring slack: a continuum of equilibria): a few samples seed,
            # their cells and minima do not (they would be thousands)
            flat = okg & np.all(G == 0.0, -1)
            V = okg[:-1, :-1] & okg[1:, :-1] & okg[:-1, 1:] & okg[1:, 1:]
            V &= resp[:-1, :-1] | resp[1:, :-1] | resp[:-1, 1:] | resp[1:, 1:]
            V &= ~(flat[:-1, :-1] | flat[1:, :-1] | flat[:-1, 1:] | flat[1:, 1:])
            corners = np.stack([G[:-1, :-1], G[1:, :-1], G[:-1, 1:], G[1:, 1:]])
            with np.errstate(invalid="ignore"):
                mn, mx = np.nanmin(np.where(V[None, ..., None], corners, 0), 0), \
                    np.nanmax(np.where(V[None, ..., None], corners, 0), 0)
            cand = V & (mn[..., 0] <= 0) & (mx[..., 0] >= 0) & (mn[..., 1] <= 0) & (mx[..., 1] >= 0)
            a_idx, b_idx = np.nonzero(cand)
            pts = []
            if a_idx.size:
                g00 = G[a_idx, b_idx]
                d1 = (G[a_idx + 1, b_idx] - g00) / h1
                d2 = (G[a_idx, b_idx + 1] - g00) / h2
                A = np.stack([d1, d2], -1)                    # (N, 2 comps, 2 params)
                dlin = A[:, 0, 0] * A[:, 1, 1] - A[:, 0, 1] * A[:, 1, 0]
                with np.errstate(divide="ignore", invalid="ignore"):     # the cell's linearised zero
                    s1 = -(A[:, 1, 1] * g00[:, 0] - A[:, 0, 1] * g00[:, 1]) / dlin
                    s2 = -(-A[:, 1, 0] * g00[:, 0] + A[:, 0, 0] * g00[:, 1]) / dlin
                s1 = np.where(np.isfinite(s1), np.clip(s1, -h1, 2 * h1), 0.5 * h1)
                s2 = np.where(np.isfinite(s2), np.clip(s2, -h2, 2 * h2), 0.5 * h2)
                pts.append(np.column_stack([x1[a_idx] + s1, x2[b_idx] + s2]))
            # small-gradient seeds: local minima of the normalised |G| over 3 x 3 neighbourhoods
            scale = np.nanpercentile(np.abs(G[okg]), 90, axis=0) if okg.any() else np.ones(2)
            scale = np.where(scale > 0, scale, 1.0)
            fa, fb = np.nonzero(flat)
            if fa.size:
                pick = np.linspace(0, fa.size - 1, min(fa.size, 5)).astype(int)
                pts.append(np.column_stack([x1[fa[pick]], x2[fb[pick]]]))
            rho = np.where(okg & resp & ~flat, np.abs(G[..., 0]) / scale[0] + np.abs(G[..., 1]) / scale[1], np.inf)
            inner = rho[1:-1, 1:-1]
            is_min = np.isfinite(inner)
            for da in (-1, 0, 1):
                for db in (-1, 0, 1):
                    if da or db:
                        is_min &= inner <= rho[1 + da:grid - 1 + da, 1 + db:grid - 1 + db]
            ma, mb = np.nonzero(is_min & (inner < SMALL_GRADIENT))
            if ma.size:
                order = np.argsort(inner[ma, mb])[:minima]
                pts.append(np.column_stack([x1[ma[order] + 1], x2[mb[order] + 1]]))
            if not pts:
                continue
            P = np.concatenate(pts)
            Qp = np.tile(base, (P.shape[0], 1))
            Qp[:, p1], Qp[:, p2] = P[:, 0], P[:, 1]
            Qp, okp = _ik(ch, Qp, i, j, sigma, tgt)
            out.extend(Qp[okp])
    return out


def _stopset(ch, tgt, fixed: dict, grid1, grid2, margin):
    n = ch.n
    base = np.zeros(n)
    for i, v in fixed.items():
        base[i] = v
    free = [i for i in range(n) if i not in fixed]
    m = len(free) - 2
    if m == 0:
        seeds = _seeds_rigid(ch, tgt, base, free)
    elif m == 1:
        seeds = _seeds_curve(ch, tgt, base, free, grid1, margin)
    elif m == 2:
        seeds = _seeds_surface(ch, tgt, base, free, grid2, margin)
    else:
        raise ValueError("n <= 4 only")
    found = []
    for s in seeds:
        q, F, ok = _newton(ch, s, free, tgt)
        if ok and np.all(np.abs(q) <= ch.lim + STOP_TOL):
            q = np.clip(q, -ch.lim, ch.lim)
            if not any(np.max(np.abs(q - g[0])) < DEDUP for g in found):
                found.append((q, F))
    return found


# ---------------------------------------------------------------------------- classification
def _record(ch: _Chain, q, F, stops, tgt) -> Record | None:
    """Classify ``(q, F)`` with the given stop pattern; None when a contact torque is negative."""
    stops = np.array(stops, int)
    reasons = []
    near = (stops == 0) & (np.abs(q) >= ch.lim - STOP_TOL)
    if near.any():
        reasons.append("free joint at its stop")
        stops = np.where(near, np.sign(q).astype(int), stops)
    q = np.where(stops != 0, stops * ch.lim, q)
    free = np.flatnonzero(stops == 0)
    E, dE, _ = _energy_derivs(ch, q)
    tip, J, _, _ = _kin(ch, q)
    Jf = J[:, free]
    if np.linalg.matrix_rank(Jf, tol=1e-10 * ch.scale_x) < 2:
        # the free rows do not fix F (fewer than two free joints, or a singular minor): an equilibrium iff SOME F
        # balances the free rows with every contact torque >= 0 -- the linear programme max t, c_i >= t
        F, t = _contact_lp(ch, q, stops, dE, J)
        if F is None or t < -CONTACT_TOL * ch.scale_e:
            return None
        reasons.append("tip force not unique")
    res = dE - J.T @ F
    contact = np.where(stops != 0, -stops * res, 0.0)
    if np.any(contact < -CONTACT_TOL * ch.scale_e):
        return None
    if np.any((stops != 0) & (np.abs(contact) <= CONTACT_TOL * ch.scale_e)):
        reasons.append("contact torque ~ 0")
    residual = max(float(np.max(np.abs(res[free]))) if free.size else 0.0, float(np.max(np.abs(tip - tgt))))
    Z = sl.null_space(Jf) if free.size > 2 else np.zeros((free.size, 0))
    if Z.shape[1]:
        H = _hess_L(ch, q, F)[np.ix_(free, free)]
        eig = np.linalg.eigvalsh(Z.T @ H @ Z)
    else:
        eig = np.zeros(0)
    if np.any(np.abs(eig) <= EIG_TOL * ch.scale_e):
        reasons.append("singular reduced Hessian")
    L, _, _ = _springs(ch, q)
    # F = 0 and three or more free joints with both springs strictly slack: those joints move freely along the
    # manifold (it keeps |slack| - 2 >= 1 dimensions of them) -- a continuum, not an isolated equilibrium
    full_slack = ch.slack & np.all(L - ch.L0 < -KINK_TOL * ch.scale_x, -1) & (stops == 0)
    if full_slack.sum() >= 3 and np.max(np.abs(F)) <= 1e-9 * ch.scale_e / ch.scale_x:
        reasons.append(CONTINUUM)
    if np.any(ch.slack[:, None] & (np.abs(L - ch.L0) <= KINK_TOL * ch.scale_x)):
        reasons.append("tension-only spring at its rest length")
    return Record(q=q, F=np.array(F, float), energy=float(E), morse_index=int(np.sum(eig < -EIG_TOL * ch.scale_e)),
                  stops=stops, contact_torques=np.maximum(contact, 0.0) * (stops != 0), degenerate=bool(reasons),
                  residual=residual, eigenvalues=eig, reasons=tuple(reasons))


def _contact_lp(ch, q, stops, dE, J):
    """When the free rows leave ``F`` open: first ``t* = max t`` over ``(F, t)`` with ``(J^T F)_i = dE_i`` on the
    free rows and every contact torque ``-s_i (dE_i - (J^T F)_i) >= t`` (``t <= max k c^2``); then, if
    ``t* >= -CONTACT_TOL``, the least ``|F_x| + |F_y|`` keeping the contact torques ``>= min(t*, 0)`` (a
    representative: such an F is a ray or a segment). Returns ``(F, t*)``, or ``(None, -inf)`` when infeasible."""
    free = stops == 0
    st = np.flatnonzero(~free)
    big = 1e6 * ch.scale_e / ch.scale_x
    # contact >= t  <=>  t - s_i J_i . F <= -s_i dE_i
    G = -stops[st, None] * J[:, st].T
    h = -stops[st] * dE[st]
    A_eq = J[:, free].T if free.any() else np.zeros((0, 2))
    b_eq = dE[free] if free.any() else np.zeros(0)
    r = so.linprog([0.0, 0.0, -1.0], A_ub=np.column_stack([G, np.ones(st.size)]) if st.size else None,
                   b_ub=h if st.size else None, A_eq=np.column_stack([A_eq, np.zeros(A_eq.shape[0])]) if free.any()
                   else None, b_eq=b_eq if free.any() else None,
                   bounds=[(-big, big), (-big, big), (None, ch.scale_e)], method="highs")
    if r.status != 0:
        return None, -math.inf
    t = float(r.x[2])
    if t < -CONTACT_TOL * ch.scale_e:
        return r.x[:2], t
    floor = min(t, 0.0)
    # variables (Fx, Fy, ux, uy): min ux + uy, |F| <= u, contact >= floor
    A_ub = [np.concatenate([G[i], [0.0, 0.0]]) for i in range(st.size)]
    b_ub = list(h - floor)
    for d in range(2):
        for sg in (1.0, -1.0):
            row = np.zeros(4)
            row[d], row[2 + d] = sg, -1.0
            A_ub.append(row)
            b_ub.append(0.0)
    r2 = so.linprog([0.0, 0.0, 1.0, 1.0], A_ub=np.array(A_ub), b_ub=np.array(b_ub),
                    A_eq=np.column_stack([A_eq, np.zeros((A_eq.shape[0], 2))]) if free.any() else None,
                    b_eq=b_eq if free.any() else None, bounds=[(-big, big)] * 2 + [(0, None)] * 2, method="highs")
    return (r2.x[:2] if r2.status == 0 else r.x[:2]), t


def _merge(records):
    out: list[Record] = []
    for r in records:
        twin = next((o for o in out if np.max(np.abs(o.q - r.q)) < DEDUP), None)
        if twin is None:
            out.append(r)
        elif r.degenerate and not twin.degenerate:
            twin.degenerate, twin.reasons = True, tuple(set(twin.reasons) | set(r.reasons))
    return sorted(out, key=lambda r: (r.energy, tuple(r.q)))


def _stop_sets(n):
    for size in range(0, n - 1):
        for S in itertools.combinations(range(n), size):
            for signs in itertools.product((-1, 1), repeat=size):
                yield S, signs


# ---------------------------------------------------------------------------- public
def equilibria(segs, dx, dy=0.0, *, grid1=20001, grid2=801) -> list[Record]:
    """Every equilibrium of the chain (``2 <= n <= 4``) with the tip at ``target(dx, dy)``, sorted by energy.

    ``grid1``: points of the parameter of the one-dimensional searches (n = 3 interior, n = 4 with one stop);
    ``grid2``: points per axis of the two-dimensional search (n = 4 interior). See the module docstring.
    """
    ch = _chain(segs)
    n = ch.n
    if not 2 <= n <= 4:
        raise ValueError("equilibria enumerates 2 <= n <= 4 segments")
    tgt = np.asarray(RT.target(segs, dx, dy), float)
    margin = float(min(0.05, 0.5 * np.min(math.pi - ch.lim)))
    recs = []
    for S, signs in _stop_sets(n):
        fixed = {i: s * ch.lim[i] for i, s in zip(S, signs)}
        stops = np.zeros(n, int)
        stops[list(S)] = signs
        for q, F in _stopset(ch, tgt, fixed, grid1, grid2, margin):
            r = _record(ch, q, F, stops, tgt)
            if r is not None:
                recs.append(r)
    return _merge(recs)


def multistart(segs, dx, dy=0.0, *, starts=3000, seed=0, iters=60) -> list[Record]:
    """Independent cross-check: random starts per stop set (``starts`` for the interior, ``starts // 4`` for each
    stop set with a curve, 32 for a rigid one), projected on ``tip = target`` by Gauss-Newton (minimum-norm steps),
    then KKT Newton (batched; steps capped at 0.3 rad), the converged ones polished by :func:`_newton`."""
    ch = _chain(segs)
    n = ch.n
    tgt = np.asarray(RT.target(segs, dx, dy), float)
    rng = np.random.default_rng(seed)
    recs = []
    for S, signs in _stop_sets(n):
        free = np.array([i for i in range(n) if i not in S])
        nf = free.size
        N = starts if not S else (max(starts // 4, 20) if nf > 2 else 32)
        Q = np.tile(np.zeros(n), (N, 1))
        Q[:, list(S)] = np.array(signs) * ch.lim[list(S)]
        Q[:, free] = rng.uniform(-1, 1, (N, nf)) * ch.lim[free]
        for _ in range(40):                                   # projection on the manifold
            tip, J, _, _ = _kin(ch, Q)
            Jf = J[:, :, free]
            r = tip - tgt
            JJt = Jf @ np.swapaxes(Jf, 1, 2) + 1e-12 * np.eye(2)
            dq = -np.einsum("nij,nj->ni", np.swapaxes(Jf, 1, 2), np.linalg.solve(JJt, r[..., None])[..., 0])
            big = np.max(np.abs(dq), 1, keepdims=True)
            Q[:, free] += dq * np.minimum(1.0, 0.3 / np.maximum(big, 1e-300))
        _, dE, _ = _energy_derivs(ch, Q)
        _, J, _, _ = _kin(ch, Q)
        Jf = J[:, :, free]
        A = Jf @ np.swapaxes(Jf, 1, 2) + 1e-12 * np.eye(2)
        F = np.linalg.solve(A, np.einsum("nij,nj->ni", Jf, dE[:, free])[..., None])[..., 0]
        for _ in range(iters):                                # batched KKT Newton
            _, dE, _ = _energy_derivs(ch, Q)
            tip, J, _, _ = _kin(ch, Q)
            Jf = J[:, :, free]
            r = np.concatenate([dE[:, free] - np.einsum("nij,ni->nj", Jf, F), tip - tgt], 1)
            H = _hess_L(ch, Q, F)[:, free][:, :, free]
            K = np.zeros((N, nf + 2, nf + 2))
            K[:, :nf, :nf] = H
            K[:, :nf, nf:] = -np.swapaxes(Jf, 1, 2)
            K[:, nf:, :nf] = Jf
            K += 1e-14 * np.eye(nf + 2)
            step = np.linalg.solve(K, -r[..., None])[..., 0]
            step = np.where(np.isfinite(step), step, 0.0)
            big = np.max(np.abs(step[:, :nf]), 1, keepdims=True)
            step *= np.minimum(1.0, 0.3 / np.maximum(big, 1e-300))
            Q[:, free] += step[:, :nf]
            F += step[:, nf:]
        stops = np.zeros(n, int)
        stops[list(S)] = signs
        _, dE, _ = _energy_derivs(ch, Q, second=False)
        tip, J, _, _ = _kin(ch, Q)
        r = np.concatenate([(dE[:, free] - np.einsum("nij,ni->nj", J[:, :, free], F)) / ch.scale_e,
                            (tip - tgt) / ch.scale_x], 1)
        good = np.all(np.isfinite(Q), 1) & np.all(np.abs(Q) <= ch.lim + 1e-6, 1)
        good &= np.max(np.abs(np.where(np.isfinite(r), r, np.inf)), 1) < 1e-8
        # one polish per cluster (the batch's converged points rounded to 1e-6; a cluster split by the rounding
        # only costs a second polish, the records are merged at the end)
        _, first = np.unique(np.round(Q[good], 6), axis=0, return_index=True)
        for qq, FF in zip(Q[good][first], F[good][first]):
            q, Fp, ok = _newton(ch, qq, free, tgt, F0=FF, iters=20)
            if ok and np.all(np.abs(q) <= ch.lim + STOP_TOL):
                r = _record(ch, np.clip(q, -ch.lim, ch.lim), Fp, stops, tgt)
                if r is not None:
                    recs.append(r)
    return _merge(recs)


def missing(reference, other, tol=1e-6) -> list[Record]:
    """The records of ``other`` with no record of ``reference`` within ``tol`` (max-norm in q)."""
    return [r for r in other if not any(np.max(np.abs(r.q - s.q)) < tol for s in reference)]
