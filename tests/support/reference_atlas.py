"""Independent references for the workspace stability atlas (held tip, displacement control).

Imports numpy, scipy, ``tests/support/reference_model.py`` and ``tests/support/reference_paths.py`` only -- NOT
``tensegrity_opt``. Conventions (``docs/model.md``): relative joint angles ``q``; the tip held
at ``(2 sum b - dx, dy)``; an equilibrium solves ``grad E = J^T F``, ``tip(q) = target``; it is stable
when the Hessian of ``E - F . tip`` reduced to the null space of ``J`` is positive definite; only
configurations strictly inside the physical range ``|q_i| < pi - 2 beta_i`` count.

Routes:

* :func:`stable_equilibria` -- every stable equilibrium of one target by brute force: several hundred
  starts (uniform random in the range, every sign pattern of the segments' wells at a few scalings, small
  random configurations) projected onto the tip constraint and run downhill on the constraint manifold by a
  batched trust-region, saddle-free Newton iteration (numpy, all starts at once; energy decrease enforced,
  steps leaving the range rejected); the distinct end points are then minimised again with scipy SLSQP
  with the tip equality constraint and the range as bounds (``reference_model.Chain.local_min``), polished
  by Newton on the KKT system, deduplicated, and kept when strictly inside the range with a positive
  definite reduced Hessian. Sorted by energy.
* :func:`follow_branch` -- a stable equilibrium followed along the straight segment ``a -> b`` of
  deflections by natural-parameter steps (``scipy.optimize.root`` on the KKT system from a tangent
  predictor; ``reference_paths.PathSystem`` / ``_step``), a step rejected when it fails, jumps, leaves the
  range or lands on an unstable point, and halved (a bisection of the stability loss, to 1e-4 of the
  segment); it stops there.
* :func:`maxwell_point` -- two stable equilibria (one at ``a``, one at ``b``) followed along the segment,
  the point where their energies are equal by ``brentq`` on the difference (each trial a fresh
  ``scipy.optimize.root`` solve on each branch).
* :func:`edge_fold` -- where the stable equilibrium from one end loses stability on the segment: the
  bracket of :func:`follow_branch`, then the extended system ``R = 0, R_z phi = 0, |phi| = 1``
  (``reference_paths.solve_extended``) for a fold, brentq on ``|q_k| - limit_k`` for a joint reaching its
  bound; or, as a second route, ``reference_paths.fold_in_displacement`` (its own natural path bisected to
  1e-12, the extended system and the joint-angle parametrisation).
* :func:`edge_reference` -- everything the atlas reports on one grid edge, from the above: the branch
  ends of every stable equilibrium at either end, and whether (and where) the least-energy branch
  switches.

A target beyond the links' reach of joint 1 is met by a branch as the arm straightens: that is reported
with kind ``"reach"`` (no stability loss; the atlas does not report it).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field

import numpy as np
import reference_model as R
import reference_paths as RP
import scipy.linalg as sla
import scipy.optimize as so

Chain = R.Chain

__all__ = [
    "Branch",
    "Chain",
    "EdgeFold",
    "EdgeReference",
    "MaxwellPoint",
    "NarrowedChain",
    "StableEq",
    "default_starts",
    "edge_fold",
    "edge_reference",
    "follow_branch",
    "maxwell_point",
    "narrowed",
    "reduced_eigs",
    "same_q",
    "stable_equilibria",
]

#: Two configurations closer than this (max-norm, rad) are the same equilibrium.
SAME_Q = 1e-6


@dataclass
class StableEq:
    q: np.ndarray
    F: np.ndarray
    energy: float
    lam_min: float          # smallest eigenvalue of the reduced Hessian (> 0)


def same_q(q1, q2, tol=1e-5):
    return bool(np.max(np.abs(np.asarray(q1, float) - np.asarray(q2, float))) < tol)


def reduced_eigs(chain: Chain, q, F):
    """Eigenvalues of the Hessian of ``E - F . tip`` on the null space of ``J`` (analytic Hessian)."""
    H = RP.lagrangian_hess(chain, np.asarray(q, float), np.asarray(F, float))
    Z = sla.null_space(chain.jac(q))
    return np.linalg.eigvalsh(Z.T @ H @ Z) if Z.shape[1] else np.zeros(0)


# ============================================================================ batched kinematics
def _rev_cumsum(A):
    return np.cumsum(A[:, ::-1], axis=1)[:, ::-1]


def _tip(chain: Chain, Q):
    phi = np.cumsum(Q, axis=1)
    l = chain.links
    return np.stack([chain.b[0] + (l * np.cos(phi)).sum(1), (l * np.sin(phi)).sum(1)], axis=1)


def _kin(chain: Chain, Q):
    """(tip (N, 2), J (N, 2, n), suffix sums of l cos phi and l sin phi (N, n))."""
    phi = np.cumsum(Q, axis=1)
    l = chain.links
    lc, ls = l * np.cos(phi), l * np.sin(phi)
    sc, ss = _rev_cumsum(lc), _rev_cumsum(ls)
    tip = np.stack([chain.b[0] + lc.sum(1), ls.sum(1)], axis=1)
    J = np.stack([-ss, sc], axis=1)
    return tip, J, sc, ss


def _energy(chain: Chain, Q):
    L1, L2 = 2 * chain.c * np.cos(chain.beta + Q / 2), 2 * chain.c * np.cos(chain.beta - Q / 2)
    return 0.5 * ((chain.k1 * (L1 - chain.L10) ** 2).sum(1) + (chain.k2 * (L2 - chain.L20) ** 2).sum(1))


def _retract(chain: Chain, Q, target, iters=12, max_step=0.5):
    """Min-norm Gauss-Newton onto ``tip = target`` (batched). Returns (Q, converged mask)."""
    Q = Q.copy()
    for _ in range(iters):
        tip, J, _, _ = _kin(chain, Q)
        r = target[None, :] - tip
        if np.all(np.max(np.abs(r), axis=1) < 1e-13):
            break
        JJt = np.einsum("nij,nkj->nik", J, J) + 1e-14 * np.eye(2)
        dq = np.einsum("nji,nj->ni", J, np.linalg.solve(JJt, r[..., None])[..., 0])
        big = np.max(np.abs(dq), axis=1, keepdims=True)
        dq *= np.minimum(1.0, max_step / np.maximum(big, 1e-300))
        Q += dq
    tip = _tip(chain, Q)
    ok = np.all(np.isfinite(Q), axis=1) & (np.max(np.abs(tip - target[None, :]), axis=1) < 1e-11)
    return Q, ok


def _descend(chain: Chain, Q, target, iters=20):
    """Batched trust-region saddle-free Newton on the manifold ``tip = target`` (the Hessian of the
    Lagrangian reduced to the null space of J, its eigenvalues taken in absolute value; along negative
    curvature at least half the trust radius). A step is accepted when the retraction converges, the
    point stays inside the physical range and the energy does not increase. Returns
    (Q, converged mask): converged = reduced gradient ~ 0 with a positive definite reduced Hessian."""
    n = chain.n
    lim = chain.limits
    scale = float(np.max(np.maximum(chain.k1, chain.k2)) * np.max(chain.c) ** 2)
    Q, alive = _retract(chain, Q, target)
    alive &= np.all(np.abs(Q) < lim, axis=1)
    E = _energy(chain, Q)
    delta = np.full(Q.shape[0], 0.2)
    done = np.zeros(Q.shape[0], bool)
    idx = np.maximum.outer(np.arange(n), np.arange(n))
    for _ in range(iters):
        act = alive & ~done
        if not act.any():
            break
        Qa = Q[act]
        _, J, sc, ss = _kin(chain, Qa)
        g = chain.grad(Qa)
        JJt = np.einsum("nij,nkj->nik", J, J)
        F = np.linalg.solve(JJt, np.einsum("nij,nj->ni", J, g)[..., None])[..., 0]
        H = (np.einsum("ni,ij->nij", chain.hess_diag(Qa), np.eye(n))
             + F[:, 0, None, None] * sc[:, idx] + F[:, 1, None, None] * ss[:, idx])
        Vt = np.linalg.svd(J, full_matrices=True)[2]
        Z = np.transpose(Vt[:, 2:, :], (0, 2, 1))                     # (N, n, n-2)
        gr = np.einsum("nik,ni->nk", Z, g)
        Hr = np.einsum("nik,nij,njl->nkl", Z, H, Z)
        w, V = np.linalg.eigh(0.5 * (Hr + np.transpose(Hr, (0, 2, 1))))
        c = np.einsum("nkl,nk->nl", V, gr)                            # gradient in the eigenbasis
        wabs = np.maximum(np.abs(w), 1e-8 * scale)
        s = -c / wabs
        da = delta[act]
        neg = w < 0
        sgn = np.where(c > 0, -1.0, 1.0)
        s = np.where(neg & (np.abs(s) < 0.5 * da[:, None]), sgn * 0.5 * da[:, None], s)
        grn = np.max(np.abs(gr), axis=1)
        conv = (grn < 1e-10 * scale) & (w[:, 0] > 0)
        dq = np.einsum("nik,nlk,nl->ni", Z, V, s)
        big = np.max(np.abs(dq), axis=1)
        dq *= np.minimum(1.0, da / np.maximum(big, 1e-300))[:, None]
        Qt, okt = _retract(chain, Qa + dq, target, iters=8)
        okt &= np.all(np.abs(Qt) < lim, axis=1)
        Et = np.where(okt, _energy(chain, np.where(okt[:, None], Qt, 0.0)), np.inf)
        Ea = E[act]
        acc = okt & (Et <= Ea + 1e-14 * max(1.0, scale)) & ~conv
        ia = np.nonzero(act)[0]
        Q[ia[acc]] = Qt[acc]
        E[ia[acc]] = Et[acc]
        delta[ia[acc]] = np.minimum(2.0 * da[acc], 0.5)
        rej = ~acc & ~conv
        delta[ia[rej]] = da[rej] / 4.0
        done[ia[conv]] = True
        alive[ia[rej & (da / 4.0 < 1e-9)]] = False
    return Q, alive & done


# ============================================================================ starts
def default_starts(chain: Chain, n_random=200, seed=0):
    """Uniform random configurations in ``(-0.95, 0.95) x range``, every sign pattern of the segments'
    wells (a monotonic segment's single well, or +-0.4 range when its well is at 0) at scalings 0.5, 1,
    and small random configurations."""
    rng = np.random.default_rng(seed)
    lim = chain.limits
    starts = [rng.uniform(-0.95, 0.95, (n_random, chain.n)) * lim]
    mags = []
    for i in range(chain.n):
        w = RP.segment_wells(chain.a[i], chain.b[i], chain.k1[i], chain.k2[i], chain.L10[i], chain.L20[i])
        m = float(np.max(np.abs(w))) if w.size else 0.0
        mags.append(m if m > 0.05 * lim[i] else 0.4 * lim[i])
    mags = np.array(mags)
    pats = np.array(list(itertools.product((-1.0, 1.0), repeat=chain.n)))
    for f in (0.5, 1.0):
        starts.append(np.clip(f * pats * mags, -0.95 * lim, 0.95 * lim))
    for amp in (0.05, 0.2):
        starts.append(amp * rng.standard_normal((40, chain.n)) * lim)
    return np.vstack(starts)


def stable_equilibria(chain: Chain, dx, dy=0.0, starts=None, *, n_random=200, seed=0):
    """Every stable equilibrium of the tip held at ``(dx, dy)``, least energy first (a list of
    :class:`StableEq`). ``starts``: an (N, n) array replacing :func:`default_starts`."""
    target = chain.target(dx, dy)
    S = default_starts(chain, n_random, seed) if starts is None else np.atleast_2d(np.asarray(starts, float))
    Q, conv = _descend(chain, S, target)
    cands = []
    for q in Q[conv]:
        if not any(same_q(q, c, 1e-4) for c in cands):
            cands.append(q)
    out: list[StableEq] = []
    for q0 in cands:
        r = chain.local_min(target, q0)           # scipy SLSQP (tip equality, range bounds) + Newton KKT
        if r is None:
            q, F, ok = chain.newton_kkt(target, q0)
            if not ok or not chain.in_range(q, 1e-7) or not same_q(q, q0, 1e-3):
                continue
        else:
            q, F = r
        w = reduced_eigs(chain, q, F)
        if w.size and w[0] <= 1e-9 * max(1.0, np.abs(w).max()):
            continue
        if any(same_q(q, e.q, SAME_Q * 10) for e in out):
            continue
        out.append(StableEq(q, F, chain.energy(q), float(w[0]) if w.size else math.inf))
    out.sort(key=lambda e: e.energy)
    return out


# ============================================================================ following along an edge
class _System(RP.PathSystem):
    """``reference_paths.PathSystem`` (displacement control) whose solve stops scipy's ``hybr`` at
    ``xtol = 1e-9`` and leaves the last digits to the Newton polish (fewer residual evaluations; the same
    acceptance test, residual below ``tol`` of the torque scale)."""

    XTOL = 1e-9


@dataclass
class Branch:
    """A stable branch along the segment ``a -> b`` (``u`` the distance from ``a``), followed from
    ``side`` ("A": from ``a``, path parameter ``t = u``; "B": from ``b``, ``t = L - u``)."""

    system: RP.PathSystem
    side: str
    length: float
    u: np.ndarray
    z: np.ndarray
    lam: np.ndarray
    reached: bool                  # stable all the way to the other end
    reason: str | None = None      # why a step past the last point failed ("unstable", "no_convergence", ...)
    t_bad: float | None = None     # the nearest rejected path parameter (the bracket's other side)
    a: np.ndarray | None = None    # the segment's ends (deflections)
    b: np.ndarray | None = None

    def t_of(self, u):
        return u if self.side == "A" else self.length - u

    @property
    def q_end(self):
        return self.system.split(self.z[-1], self.t_of(self.u[-1]))[0]

    def solve_at(self, u):
        """The branch's equilibrium at ``u`` (scipy root from the nearest stored point with a tangent
        predictor). Returns (q, F) or None."""
        sysm = self.system
        k = int(np.argmin(np.abs(self.u - u)))
        t0, t = self.t_of(self.u[k]), self.t_of(u)
        z0 = self.z[k]
        try:
            pred = z0 + (t - t0) * sysm.tangent(z0, t0)
        except np.linalg.LinAlgError:
            pred = z0
        z, ok = sysm.solve(pred, t)
        if not ok or np.max(np.abs(z[:sysm.n] - z0[:sysm.n])) > 0.1:
            z, ok = sysm.solve(z0, t)
        if not ok or np.max(np.abs(z[:sysm.n] - z0[:sysm.n])) > 0.1:
            return None
        return sysm.split(z, t)


def follow_branch(chain: Chain, q0, a_point, b_point, side="A", steps=8, t_tol=1e-4):
    """Follow the stable equilibrium ``q0`` (at ``a_point`` when ``side="A"``, at ``b_point`` when
    ``side="B"``) along the segment by natural-parameter steps (``reference_paths._step``: scipy root on
    the KKT system from a tangent predictor, rejecting jumps, kinks and points outside the range), a step
    also rejected when the smallest reduced eigenvalue is not positive; a rejected step is halved (a
    bisection of the stability loss) until it is below ``t_tol`` of the length (the extended system does the rest),
    and the branch stops there."""
    a, b = np.asarray(a_point, float), np.asarray(b_point, float)
    vec = b - a
    L = float(np.linalg.norm(vec))
    d = vec / L if side == "A" else -vec / L
    sysm = _System(chain, q0, d, "displacement")
    z, ok = sysm.solve(sysm.start_z(), 0.0)
    if not ok or not same_q(z[:chain.n], q0, 1e-6):
        raise RuntimeError("the start is not an equilibrium")
    ts, zs, lams = [0.0], [z], [sysm.lam_min(z, 0.0)]
    t, dt0 = 0.0, L / steps
    dt = dt0
    reason, t_bad = None, None
    while L - t > 1e-12 * L:
        t_try = t + dt if L - (t + dt) > 1e-12 * L else L
        z_new, st = RP._step(sysm, zs[-1], t, t_try, max_jump=0.25)
        if st == "ok" and sysm.lam_min(z_new, t_try) <= 0.0:
            st = "unstable"
        if st == "ok":
            t = t_try
            ts.append(t)
            zs.append(z_new)
            lams.append(sysm.lam_min(z_new, t))
            if t_bad is None or t_bad - t > 2 * dt:
                dt = min(2 * dt, dt0)
            continue
        reason, t_bad = st, t_try
        dt *= 0.5
        if dt < t_tol * L:
            break
    reached = not (L - t > 1e-12 * L)
    ts = np.array(ts)
    u = ts if side == "A" else L - ts
    return Branch(sysm, side, L, u, np.array(zs), np.array(lams), reached,
                  None if reached else reason, None if reached else t_bad, a, b)


# ============================================================================ the Maxwell point
@dataclass
class MaxwellPoint:
    u: float                 # distance from a
    fraction: float
    point: np.ndarray        # (dx, dy)
    energy: float
    qA: np.ndarray
    FA: np.ndarray
    qB: np.ndarray
    FB: np.ndarray
    gap: float               # |E_A - E_B| there


def maxwell_point(chain: Chain, qA, qB, a_point, b_point, *, branches=None, steps=8):
    """Where the branch of ``qA`` (a stable equilibrium at ``a_point``) and the branch of ``qB`` (one at
    ``b_point``), followed along the segment, have equal energy: ``brentq`` on ``E_A(u) - E_B(u)`` over
    the interval where both are stable (each trial a fresh scipy root solve on each branch). ``None`` when
    the difference keeps one sign there (the least branch then ends before the other appears: no
    equal-energy point). ``branches``: the two :class:`Branch` es (from A, from B) when already followed."""
    a, b = np.asarray(a_point, float), np.asarray(b_point, float)
    PA, PB = branches if branches is not None else (follow_branch(chain, qA, a, b, "A", steps),
                                                    follow_branch(chain, qB, a, b, "B", steps))
    L = PA.length
    lo, hi = max(PA.u.min(), PB.u.min()), min(PA.u.max(), PB.u.max())
    if hi <= lo:
        return None

    def g(u):
        ra, rb = PA.solve_at(u), PB.solve_at(u)
        if ra is None or rb is None:
            raise RuntimeError(f"a branch could not be solved at u = {u}")
        return chain.energy(ra[0]) - chain.energy(rb[0])

    us = np.unique(np.concatenate([PA.u[(PA.u >= lo) & (PA.u <= hi)], PB.u[(PB.u >= lo) & (PB.u <= hi)],
                                   [lo, hi]]))
    gs = np.array([g(u) for u in us])
    for k in range(us.size):
        if gs[k] == 0.0 or (k + 1 < us.size and gs[k] * gs[k + 1] < 0):
            u0 = us[k] if gs[k] == 0.0 else so.brentq(g, us[k], us[k + 1], xtol=1e-15, rtol=1e-15, maxiter=200)
            qa, Fa = PA.solve_at(u0)
            qb, Fb = PB.solve_at(u0)
            return MaxwellPoint(float(u0), float(u0 / L), a + u0 * (b - a) / L, chain.energy(qa), qa, Fa, qb, Fb,
                                abs(chain.energy(qa) - chain.energy(qb)))
    return None


# ============================================================================ the fold on an edge
@dataclass
class EdgeFold:
    u: float                 # distance from a (whatever end the branch was followed from)
    fraction: float
    point: np.ndarray        # (dx, dy)
    q: np.ndarray
    F: np.ndarray
    energy: float
    kind: str                # "fold" | "bifurcation" | "joint_limit" | "kinematic_singularity" | "reach" | ...
    side: str                # the end the branch was followed from
    q_start: np.ndarray      # the stable equilibrium at that end
    lam_min: float = float("nan")
    u_dot_rt: float = float("nan")
    converged: bool = False  # the extended system (or the joint-limit brentq) converged inside the bracket
    u_coordinate: float | None = None   # route "fold_in_displacement": the joint-angle route's position


def _reachable(chain: Chain, deflection) -> bool:
    """The tip target of ``deflection`` is within the links' reach of joint 1 (annulus test)."""
    tgt = chain.target(*deflection)
    dist = math.hypot(tgt[0] - chain.b[0], tgt[1])
    l = chain.links
    return bool(max(0.0, 2 * l.max() - l.sum()) <= dist <= l.sum())


def _u_of(br: Branch, t):
    return t if br.side == "A" else br.length - t


def _joint_limit_point(chain: Chain, br: Branch, z_good, t_good, t_bad):
    """Where the branch reaches a joint's range bound between ``t_good`` (inside) and ``t_bad`` (the
    solve converged outside): brentq on ``|q_k(t)| - limit_k`` for the joint ``k`` outside at ``t_bad``,
    each trial a scipy root solve from the last point inside. Returns (z, t) or None."""
    sysm = br.system
    lim = chain.limits
    try:
        tan = sysm.tangent(z_good, t_good)
    except np.linalg.LinAlgError:
        tan = np.zeros_like(z_good)

    def solve(t):
        z, ok = sysm.solve(z_good + (t - t_good) * tan, t)
        if not ok or np.max(np.abs(z - z_good)[:chain.n]) > 0.05:
            z, ok = sysm.solve(z_good, t)
        if not ok or np.max(np.abs(z - z_good)[:chain.n]) > 0.05:
            raise RuntimeError("joint-limit bracket: the branch could not be solved")
        return z

    try:
        qb = sysm.split(solve(t_bad), t_bad)[0]
        k = int(np.argmax(np.abs(qb) - lim))
        def h(t):
            return abs(sysm.split(solve(t), t)[0][k]) - lim[k]
        if not (h(t_good) < 0 < h(t_bad)):
            return None
        te = so.brentq(h, t_good, t_bad, xtol=1e-15, rtol=1e-15, maxiter=200)
        return solve(te), te
    except (RuntimeError, ValueError):
        return None


def _fold_from_branch(chain: Chain, br: Branch, q_start) -> EdgeFold:
    """The stability loss that stopped ``br``: the extended system ``R = 0, R_z phi = 0, |phi| = 1``
    (``reference_paths.solve_extended``) from the last stable point, accepted inside the bisection
    bracket; a joint reaching its range bound located by brentq (:func:`_joint_limit_point`); else (a
    kinematic singularity, the target leaving the workspace: kind "reach") the bracket's stable end."""
    sysm, L = br.system, br.length
    t_good = br.t_of(br.u[-1])
    z_good = br.z[-1]
    kind, z, t, ok, ratio = br.reason, z_good, t_good, False, float("nan")
    q_good = sysm.split(z_good, t_good)[0]
    singular_J = np.linalg.svd(chain.jac(q_good), compute_uv=False)[-1] < 1e-4 * float(np.min(chain.b))
    if br.reason not in ("joint_limit",) and not singular_J:
        _, _, phi0 = RP.classify_singular_point(sysm, z_good, t_good)
        ze, te, _, ok = RP.solve_extended(sysm, z_good, t_good, phi0)
        tb = br.t_bad if br.t_bad is not None else L
        ok = bool(ok and t_good - 1e-9 * L <= te <= tb + 1e-9 * L and np.max(np.abs(ze - z_good)[:chain.n]) < 0.05)
        if ok:
            z, t = ze, te
            kind, ratio, _ = RP.classify_singular_point(sysm, z, t)
    elif singular_J:
        kind = "kinematic_singularity"
    if br.reason == "joint_limit" and br.t_bad is not None:
        zt = _joint_limit_point(chain, br, z_good, t_good, br.t_bad)
        if zt is not None:
            z, t = zt
            ok = True
    if not ok and br.t_bad is not None and not _reachable(chain, br.a + _u_of(br, br.t_bad) * (br.b - br.a) / L):
        kind = "reach"            # the target leaves the workspace (the arm straightens): no stability loss
    q, F = sysm.split(z, t)
    u = t if br.side == "A" else L - t
    return EdgeFold(float(u), float(u / L), br.a + u * (br.b - br.a) / L, q, F, chain.energy(q), kind, br.side,
                    np.asarray(q_start, float).copy(), sysm.lam_min(z, t), ratio, ok)


def edge_fold(chain: Chain, q_start, a_point, b_point, side="A", *, steps=8, route="extended"):
    """Where the stable equilibrium ``q_start`` (at ``a_point`` for ``side="A"``, at ``b_point`` for
    ``"B"``), followed along the segment, loses stability; ``None`` when it stays stable to the other end.

    ``route="extended"``: :func:`follow_branch` (natural steps, bisection of the loss to 1e-4 of the length)
    then the extended system (a joint limit: brentq). ``route="fold_in_displacement"``:
    ``reference_paths.fold_in_displacement`` (its own natural path bisected to 1e-12, the extended system;
    the joint-angle route's position in ``u_coordinate``), a second, slower route."""
    a, b = np.asarray(a_point, float), np.asarray(b_point, float)
    vec = b - a
    L = float(np.linalg.norm(vec))
    if route == "extended":
        br = follow_branch(chain, q_start, a, b, side, steps)
        return None if br.reached else _fold_from_branch(chain, br, q_start)
    d = vec / L if side == "A" else -vec / L
    res = RP.fold_in_displacement(chain, q_start, direction=(float(d[0]), float(d[1])), t_max=L, dt0=L / 16)
    if res.kind == "none" and res.reason == "max_load":
        return None
    t = float(res.t)
    u = t if side == "A" else L - t
    out = EdgeFold(u, u / L, a + u * vec / L, res.q, res.force, chain.energy(res.q),
                   res.kind if res.kind != "none" else res.reason, side, np.asarray(q_start, float).copy(),
                   res.lam_min, res.u_dot_rt, res.extended_converged)
    tc = getattr(res, "t_coordinate", None)
    if tc is not None:
        out.u_coordinate = float(tc) if side == "A" else L - float(tc)
    return out


# ============================================================================ one edge, everything
@dataclass
class EdgeReference:
    a: np.ndarray
    b: np.ndarray
    stable_A: list
    stable_B: list
    folds: list = field(default_factory=list)        # EdgeFold of every stable branch from either end
    reached: dict = field(default_factory=dict)      # index at A -> index at B it arrives at stably
    least_continues: bool = True                     # A's least branch arrives at B's least equilibrium
    maxwell: MaxwellPoint | None = None              # the switch when not least_continues (None: none found)
    tie: bool = False                                # a tie for the least energy at either end
    fold_of_A: dict = field(default_factory=dict)    # index at A -> its EdgeFold (branches not arriving)
    fold_of_B: dict = field(default_factory=dict)    # index at B -> its EdgeFold
    switch_method: str | None = None                 # "equal_energy" | "branch_end" | None (no switch)
    switch_point: np.ndarray | None = None           # where the least branch switches
    switch_q: np.ndarray | None = None               # A's least branch there (B's for a late-born B branch)


@dataclass
class NarrowedChain(Chain):
    """``Chain`` whose joint range is narrowed by a relative ``margin``: ``|q_i| < (1 - margin)(pi - 2
    beta_i)`` (to place a joint-limit event where a library documents it)."""

    margin: float = 0.0

    @property
    def limits(self):
        return (math.pi - 2.0 * self.beta) * (1.0 - self.margin)


def narrowed(chain: Chain, margin: float) -> Chain:
    if not margin:
        return chain
    return NarrowedChain(chain.a, chain.b, chain.k1, chain.k2, chain.L10, chain.L20, margin)


def _least(stable, tol):
    return {k for k, e in enumerate(stable) if e.energy - stable[0].energy <= tol}


def edge_reference(chain: Chain, a_point, b_point, stable_A, stable_B, *, tie_tol=1e-9, steps=8,
                   limit_margin=0.0):
    """The reference picture of one grid edge from the brute-force sets at its ends: every stable
    equilibrium at ``A`` followed towards ``B`` and every one at ``B`` not so reached followed back; a
    branch that does not arrive gives a fold (:func:`edge_fold`'s extended route); the least-energy branch's
    continuity and, when it does not continue, the switch: the Maxwell point of the least equilibria at
    both ends (:func:`maxwell_point`) or, when their energies are never equal while both are stable, the
    end of A's least branch (else the end, seen from B, of B's least one). ``tie_tol`` is relative to the energy
    scale ``max k1 (sum rest lengths)^2``.
    Raises when a branch arrives stable at an end at no brute-force equilibrium (the brute force missed
    one). ``limit_margin``: the branches are followed in the range narrowed by this relative margin (a
    joint-limit end at ``|q_k| = (1 - margin)(pi - 2 beta_k)``)."""
    chain = narrowed(chain, limit_margin)
    a, b = np.asarray(a_point, float), np.asarray(b_point, float)
    out = EdgeReference(a, b, stable_A, stable_B)
    fwd = [follow_branch(chain, e.q, a, b, "A", steps) for e in stable_A]
    for k, p in enumerate(fwd):
        if p.reached:
            jb = next((j for j, e in enumerate(stable_B) if same_q(p.q_end, e.q, 1e-6)), None)
            if jb is None:
                raise RuntimeError(f"branch {k} from A arrives stable at B at no brute-force equilibrium: {p.q_end}")
            out.reached[k] = jb
        else:
            out.fold_of_A[k] = _fold_from_branch(chain, p, stable_A[k].q)
            out.folds.append(out.fold_of_A[k])
    got_B = set(out.reached.values())
    back = {}
    for jb, e in enumerate(stable_B):
        if jb in got_B:
            continue
        p = follow_branch(chain, e.q, a, b, "B", steps)
        back[jb] = p
        if p.reached:
            raise RuntimeError(f"branch {jb} from B arrives stable at A ({p.q_end}) but no A branch arrived at it")
        out.fold_of_B[jb] = _fold_from_branch(chain, p, e.q)
        out.folds.append(out.fold_of_B[jb])
    if stable_A and stable_B:
        scale = float(np.max(chain.k1) * (np.sum(chain.L10) + np.sum(chain.L20)) ** 2)
        lA, lB = _least(stable_A, tie_tol * scale), _least(stable_B, tie_tol * scale)
        out.tie = len(lA) > 1 or len(lB) > 1
        out.least_continues = any(out.reached.get(ka) in lB for ka in lA)
        if not out.least_continues and not out.tie:
            PB = back[0] if 0 in back else follow_branch(chain, stable_B[0].q, a, b, "B", steps)
            out.maxwell = maxwell_point(chain, stable_A[0].q, stable_B[0].q, a, b, branches=(fwd[0], PB))
            if out.maxwell is not None:
                out.switch_method, out.switch_point, out.switch_q = "equal_energy", out.maxwell.point, out.maxwell.qA
            elif 0 in out.fold_of_A:        # no shared equal-energy point: A's least branch ends first
                f = out.fold_of_A[0]
                out.switch_method, out.switch_point, out.switch_q = "branch_end", f.point, f.q
            elif 0 in out.fold_of_B:        # or B's least branch is born on the edge (its end seen from B)
                f = out.fold_of_B[0]
                out.switch_method, out.switch_point, out.switch_q = "branch_end", f.point, f.q
    return out
