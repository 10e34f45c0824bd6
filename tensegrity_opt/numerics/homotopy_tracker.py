"""A batched path tracker for the parameter homotopy: every path of one homotopy advanced together in numpy.

:mod:`.parameter_homotopy` tracks the ``N`` start roots of a generic instance ``F(x; p0)`` to a query's system
``F(x; p1)`` along PHCpack's linear homotopy

    ``H(x, t) = gamma (1 - t) F(x; p0) + t F(x; p1)``,  ``t`` real from 0 to 1,

(``phc -p`` with relaxation power 1 and accessibility constant ``gamma``). PHCpack tracks one path at a time, at
~2-3 ms of CPU a path for n = 4..5 (43648 paths at n = 6: ~3-4 min on 2 cores); the same paths advanced as one
batch share every evaluation and linear solve (numpy's batched ``solve`` and one matrix product for all the
monomials), so the cost a path falls to ~0.2-0.4 ms (n = 4: ~0.25 s, n = 5: ~2 s, n = 6: ~20 s). This module
follows the regular paths and calls the ones leaving the torus diverged (:data:`INFINITE`); each path it cannot end
cleanly (a step below :data:`H_MIN`, an ill-conditioned or unconverged end point, a path its end game does not
settle) comes back as :data:`FAILED` and is tracked again by ``phc -p`` on the *same* homotopy (same ``gamma``),
whose end games handle singular end points.

Method (per path, all paths at once, each with its own ``t`` and step ``h``)
----------------------------------------------------------------------------
* predictor: the cubic Hermite extrapolation through the last two accepted points and their tangents
  ``x' = -H_x^{-1} H_t`` (Euler on the first step);
* corrector: two Newton steps at ``t + h``; the step is accepted when the first correction is at most
  :data:`BETA` (relative to ``1 + |x|``: the predictor landed well inside the path's basin) and the second
  contracted it by :data:`CONTRACTION` or reached round-off (quadratic convergence: on the path, not on a
  neighbour); else ``h`` is halved;
* step control: after an accepted step ``h`` grows by up to 2, by the predictor error's ratio to :data:`BETA`;
* end: at ``t = 1`` three more Newton steps; the end point counts when the last correction is at round-off
  (:data:`CONVERGED`) and the Jacobian's reciprocal condition number is above :data:`RCOND_MIN` (a regular root;
  PHCpack's singular end points are its to judge);
* path variable: ``s = 1 - t``, from 1 to 0, so that near the end ``s`` keeps its relative precision;
* end game: from ``s <=`` :data:`ENDGAME` on, the valuations ``nu_j = d log|x_j| / d log s = s Re(x_j' / x_j)``
  are read at checkpoints, each a halving of ``s`` past the last. On a path to a finite root of the torus they
  tend to 0; on a path leaving it (``x_j -> 0`` or infinity, ``x_j ~ s^w`` with ``w`` rational) to ``w``. A path
  whose valuations agree within :data:`VALUATION_TOL` at :data:`VALUATION_CHECKS` checkpoints in a row and one of
  whose *watched* unknowns (``angles``: the joints' ``z_j``, of modulus 1 at every real point) is already beyond
  :data:`FAR` (``|z_j| <= 1e-3`` or ``>= 1e3``, i.e. ``|Im q_j| >= 13.8``) and still going that way with
  ``|nu_j| >=`` :data:`VALUATION_MIN` is :data:`INFINITE`: it cannot end on a real equilibrium, whether it diverges
  or ends on a far complex root. The force unknowns are not watched: a root with a small but finite force (a
  target next to a rest configuration) has small ``g, h`` most of the way and is followed to its end. A path whose
  current valuation is not near zero steps at most half way to ``s = 0``, so it never lands there out of the
  torus.

Nothing here decides completeness: :mod:`.parameter_homotopy` checks that the end points are pairwise distinct
(two paths on one regular root means one jumped) and re-tracks the failed and coinciding paths by ``phc -p``.
When every one of the ``N`` paths ends on a distinct regular finite root, those are all the isolated roots in
the torus whatever happened along the way: ``N`` is the family's generic root count, the mixed volume, and
Bernstein's theorem bounds the isolated roots of *every* member by it, with multiplicity.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, replace

import numpy as np

__all__ = ["TrackedPaths", "track_batch", "FINITE", "INFINITE", "FAILED", "BETA", "CONTRACTION", "H_MIN",
           "RCOND_MIN", "MAX_STEPS", "MIN_SLICE", "ENDGAME", "VALUATION_TOL", "VALUATION_MIN",
           "VALUATION_CHECKS", "FAR"]

#: Per-path end states (as :mod:`.parameter_homotopy` reads PHCpack's): ended on a finite root at ``t = 1``,
#: diverged, or not ended (to be tracked again).
FINITE, INFINITE, FAILED = 0, 1, 2
#: Largest first Newton correction of an accepted step, relative to ``1 + max|x|``.
BETA = 1e-2
#: The second Newton correction must be at most this times the first (or at round-off).
CONTRACTION = 0.1
#: A path whose step fell below this (times ``s``) is not ended here.
H_MIN = 1e-9
#: A path that took more steps than this is not ended here.
MAX_STEPS = 3000
#: An end point whose Jacobian has a reciprocal condition number below this is left to PHCpack (singular or nearly).
RCOND_MIN = 1e-9
#: The end game watches the paths from ``1 - t`` below this on (:func:`track_batch`).
ENDGAME = 5e-2
#: A path diverges when its valuation estimates agree within this at :data:`VALUATION_CHECKS` checkpoints in a
#: row (each a halving of ``1 - t`` past the last), one unknown's at least :data:`VALUATION_MIN` in modulus.
VALUATION_TOL = 1e-2
VALUATION_MIN = 0.1
VALUATION_CHECKS = 3
#: ... and one of the watched unknowns (the joints' ``z_j``, of modulus 1 at every real point) is already below this
#: in modulus, or above its reciprocal: a path there cannot end on a real equilibrium, whether it diverges or not.
FAR = 1e-3
#: A path whose unknowns exceed this in modulus (or fall below its reciprocal: a ``z_j -> 0``) leaves the torus.
BIG = 1e8
_ROUNDOFF = 1e-13
#: Fewest paths a thread's batch (smaller batches cost more in overhead than a second core saves).
MIN_SLICE = 1000
#: The last Newton correction at ``t = 1`` of an end point that counts (relative to ``1 + max|x|``).
CONVERGED = 1e-10


@dataclass(frozen=True)
class TrackedPaths:
    """The end of every path of one batch.

    Attributes
    ----------
    state : ndarray (N,) int
        :data:`FINITE`, :data:`INFINITE` (the end game: the path leaves the torus) or :data:`FAILED` (not ended here,
        for PHCpack) per path.
    roots : ndarray (N, nv) complex
        The end points (``nan`` where not :data:`FINITE`).
    regular : ndarray (N,) bool
        The end point is regular (every :data:`FINITE` one is).
    steps : int
        Accepted steps, summed over the paths.
    rejected : int
        Rejected steps, summed over the paths.
    iterations : int
        Batch iterations (the longest path's steps and rejections).
    seconds : float
    """

    state: np.ndarray
    roots: np.ndarray
    regular: np.ndarray
    steps: int
    rejected: int
    iterations: int
    seconds: float


class _Family:
    """``H(x, s) = s gamma F0(x) + (1 - s) F1(x)`` (``s = 1 - t``) of two Laurent systems (dicts exponent ->
    coefficient), evaluated with its Jacobian on a batch of points, each at its own ``s``. The path variable is
    ``s``, not ``t``: near the end ``s`` keeps its relative precision down to any size (``t = 1 - s`` would lose it
    below ``1e-16``), which the end game needs."""

    def __init__(self, polys0: list[dict], polys1: list[dict], gamma: complex, nv: int):
        keys = sorted(set().union(*(p.keys() for p in polys0), *(p.keys() for p in polys1)))
        self.nv = nv
        self.neq = len(polys1)
        E = np.array(keys, dtype=int).reshape(len(keys), nv)
        K = E.shape[0]
        index = {k: i for i, k in enumerate(keys)}
        C0 = np.zeros((self.neq, K), complex)
        C1 = np.zeros((self.neq, K), complex)
        for C, polys, scale in ((C0, polys0, gamma), (C1, polys1, 1.0)):
            for i, p in enumerate(polys):
                for e, c in p.items():
                    C[i, index[e]] += scale * complex(c)
        # one matrix product of the monomials gives F1, F0 - F1 (F0 = gamma F(p0)) and their Jacobians' numerators
        # (d/dx_v x^e = e_v x^e / x_v): H = F1 + s (F0 - F1), H_x likewise, H_s = F0 - F1
        CE0 = (C0[:, :, None] * E[None, :, :]).transpose(1, 0, 2).reshape(K, -1)
        CE1 = (C1[:, :, None] * E[None, :, :]).transpose(1, 0, 2).reshape(K, -1)
        self.W = np.ascontiguousarray(np.hstack([C1.T, CE1, (C0 - C1).T, CE0 - CE1]))
        self.K = K
        self._plan(E)

    def _plan(self, E: np.ndarray) -> None:
        """The monomials as a chain of products: each is an earlier one (its prefix with the last unknown's power
        one step nearer zero) times ``x_v`` or ``1 / x_v``, so a monomial costs one or two multiplications a point
        (the link directions ``prod_{i<=j} z_i^2`` share their prefixes)."""
        slot = {(0,) * self.nv: 0}
        steps: list[tuple[int, int, int, int]] = []     # (new slot, parent slot, unknown, +1 or -1)

        def get(e: tuple[int, ...]) -> int:
            if e in slot:
                return slot[e]
            v = max(i for i, p in enumerate(e) if p)
            sign = 1 if e[v] > 0 else -1
            parent = list(e)
            parent[v] -= sign
            ps = get(tuple(parent))
            slot[e] = len(slot)
            steps.append((slot[e], ps, v, sign))
            return slot[e]

        self.index = np.array([get(tuple(int(p) for p in row)) for row in E], dtype=int)
        self.steps = steps
        self.slots = len(slot)

    def monomials(self, X: np.ndarray) -> np.ndarray:
        """The monomials ``x^e`` (M, K) at the points ``X`` (M, nv)."""
        XT = np.ascontiguousarray(X.T)
        inv = 1.0 / XT
        S = np.empty((self.slots, X.shape[0]), complex)
        S[0] = 1.0
        for new, parent, v, sign in self.steps:
            np.multiply(S[parent], XT[v] if sign > 0 else inv[v], out=S[new])
        return np.ascontiguousarray(S[self.index].T)

    def evaluate(self, X: np.ndarray, s: np.ndarray, *, tangent: bool = False):
        """``H``, ``H_x`` (and ``H_s`` with ``tangent``) at the points ``X`` (M, nv) and path variables ``s`` (M,)."""
        neq, nv = self.neq, self.nv
        c = neq + neq * nv
        R = self.monomials(X) @ self.W
        HJ = R[:, :c] + s[:, None] * R[:, c:]
        H = HJ[:, :neq]
        J = HJ[:, neq:].reshape(-1, neq, nv) / X[:, None, :]
        if tangent:
            return H, J, R[:, c:c + neq]
        return H, J


def _norm(d: np.ndarray, x: np.ndarray) -> np.ndarray:
    return np.abs(d).max(axis=1) / (1.0 + np.abs(x).max(axis=1))


def _solve(J: np.ndarray, rhs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Batched ``J^{-1} rhs`` (rhs (M, nv, r)); rows whose matrix is singular get ``nan`` and ``ok = False``."""
    try:
        return np.linalg.solve(J, rhs), np.ones(J.shape[0], bool)
    except np.linalg.LinAlgError:
        out = np.full(rhs.shape, np.nan + 0j)
        ok = np.zeros(J.shape[0], bool)
        for i in range(J.shape[0]):
            try:
                out[i] = np.linalg.solve(J[i], rhs[i])
                ok[i] = True
            except np.linalg.LinAlgError:
                pass
        return out, ok


def track_batch(polys0: list[dict], polys1: list[dict], gamma: complex, starts: np.ndarray, *,
                threads: int = 1, deadline: float | None = None, angles: int | None = None) -> TrackedPaths:
    """Track the roots ``starts`` (N, nv) of ``polys0`` along ``gamma (1 - t) polys0 + t polys1`` to ``t = 1``.

    ``polys0`` and ``polys1`` are Laurent systems as dicts exponent tuple -> coefficient (:mod:`.homotopy`'s form);
    ``threads`` batches run side by side (numpy releases the GIL in its products and solves), each on a slice of
    at least :data:`MIN_SLICE` paths; ``deadline`` a :func:`time.monotonic` instant after which the paths still
    running are :data:`FAILED`; ``angles`` the leading unknowns of unit modulus at every real point (the joints'
    ``z_j``; default all), the ones the end game watches. Returns a :class:`TrackedPaths`; see the module for the
    method and what counts as ended.
    """
    t_start = time.perf_counter()
    starts = np.asarray(starts, dtype=complex)
    N, nv = starts.shape
    fam = _Family(polys0, polys1, complex(gamma), nv)
    angles = nv if angles is None else max(1, min(int(angles), nv))
    k = max(1, min(int(threads), N // MIN_SLICE))
    if k == 1:
        out = _track(fam, starts, deadline, angles)
    else:
        from concurrent.futures import ThreadPoolExecutor

        slices = np.array_split(np.arange(N), k)
        with ThreadPoolExecutor(max_workers=k) as pool:
            parts = list(pool.map(lambda rows: _track(fam, starts[rows], deadline, angles), slices))
        state = np.concatenate([p.state for p in parts])
        roots = np.concatenate([p.roots for p in parts])
        regular = np.concatenate([p.regular for p in parts])
        out = TrackedPaths(state, roots, regular, sum(p.steps for p in parts), sum(p.rejected for p in parts),
                           max(p.iterations for p in parts), 0.0)
    return replace(out, seconds=time.perf_counter() - t_start)


def _track(fam: _Family, starts: np.ndarray, deadline: float | None, angles: int) -> TrackedPaths:
    """:func:`track_batch` on one batch; the path variable is ``s = 1 - t``, from 1 down to 0."""
    N, nv = starts.shape
    state = np.full(N, FAILED)
    roots = np.full((N, nv), np.nan + 0j)
    regular = np.zeros(N, bool)

    # the running paths' state, compacted as paths end: x at s, its tangent v = dx/ds, the previous point
    idx = np.arange(N)
    x = starts.copy()
    s = np.ones(N)
    H, J, Hs = fam.evaluate(x, s, tangent=True)
    sol, ok = _solve(J, -Hs[:, :, None])
    v = sol[:, :, 0]
    x_prev = np.full_like(x, np.nan)
    v_prev = np.full_like(x, np.nan)
    s_prev = np.full(N, np.nan)
    h = np.full(N, 0.02)
    steps = np.zeros(N, int)
    # the end game's valuation checkpoints: the last estimate, the s it was taken at, how many agreed in a row
    nu_ck = np.full((N, nv), np.nan)
    s_ck = np.full(N, np.inf)
    agree = np.zeros(N, int)
    alive = ok & np.isfinite(v).all(axis=1)
    total_steps = total_rejected = iterations = 0

    def drop(keep: np.ndarray) -> None:
        nonlocal idx, x, s, v, x_prev, v_prev, s_prev, h, steps, nu_ck, s_ck, agree
        idx, x, s, v, x_prev, v_prev, s_prev, h, steps, nu_ck, s_ck, agree = (
            a[keep] for a in (idx, x, s, v, x_prev, v_prev, s_prev, h, steps, nu_ck, s_ck, agree))

    drop(alive)
    done_x, done_idx = [], []
    while idx.size:
        if deadline is not None and time.monotonic() > deadline:
            break
        iterations += 1
        h = np.minimum(h, s)
        # a path whose valuation is not near zero (heading for 0 or infinity, see the end game below) steps at
        # most half way to s = 0: its end game's checkpoints come, and it never lands on s = 0 out of the torus
        away = np.abs(s[:, None] * (v / x).real).max(axis=1) >= VALUATION_MIN
        h[away] = np.minimum(h[away], 0.5 * s[away])
        sn = s - h
        # predictor: cubic Hermite through (s_prev, x_prev, v_prev), (s, x, v); Euler without a previous point
        xp = x - h[:, None] * v
        have = np.isfinite(s_prev)
        if have.any():
            d = (s - s_prev)[have][:, None]
            u = 1.0 - h[have][:, None] / d
            h00, h10 = 2 * u**3 - 3 * u**2 + 1, u**3 - 2 * u**2 + u
            h01, h11 = -2 * u**3 + 3 * u**2, u**3 - u**2
            xp[have] = h00 * x_prev[have] + h10 * d * v_prev[have] + h01 * x[have] + h11 * d * v[have]
        # corrector: two Newton steps at sn
        H1, J1 = fam.evaluate(xp, sn)
        d1, ok1 = _solve(J1, H1[:, :, None])
        x1 = xp - d1[:, :, 0]
        H2, J2, Hs2 = fam.evaluate(x1, sn, tangent=True)
        d2, ok2 = _solve(J2, np.stack([H2, Hs2], axis=2))
        x2 = x1 - d2[:, :, 0]
        r1, r2 = _norm(d1[:, :, 0], x1), _norm(d2[:, :, 0], x2)
        good = ok1 & ok2 & np.isfinite(x2).all(axis=1) & (r1 <= BETA) & ((r2 <= CONTRACTION * r1) | (r2 <= _ROUNDOFF))
        # accepted: move; the tangent at the new point from the second Jacobian (at x1, within r2 of x2)
        acc = np.flatnonzero(good)
        total_steps += acc.size
        total_rejected += idx.size - acc.size
        x_prev[acc], v_prev[acc], s_prev[acc] = x[acc], v[acc], s[acc]
        x[acc], s[acc] = x2[acc], sn[acc]
        v[acc] = -d2[acc, :, 1]
        steps[acc] += 1
        grow = np.clip(0.9 * (BETA / np.maximum(r1[acc], 1e-16)) ** 0.25, 0.5, 2.0)
        h[acc] *= grow
        rej = ~good
        h[rej] *= 0.5
        # end game: near s = 0 the valuations nu_j = d log|x_j| / d log s = s Re(x_j' / x_j), estimated at
        # checkpoints each a halving of s apart; a path whose valuations agree at VALUATION_CHECKS checkpoints in a
        # row, one of its first `angles` unknowns already beyond FAR (below, or above its reciprocal) and still
        # going that way, is leaving the torus (x_j -> 0 or infinity as a power of s) and cannot end on a real
        # point (|z_j| = 1). Only those unknowns count: a root with a small but finite force (a target near a
        # rest configuration) has small g, h on the way and is followed to its end.
        ck = acc[(s[acc] <= ENDGAME) & (s[acc] > 0.0) & (s[acc] <= 0.5 * s_ck[acc])]
        diverged = np.zeros(idx.size, bool)
        if ck.size:
            nu = s[ck][:, None] * (v[ck] / x[ck]).real
            same = (np.abs(nu - nu_ck[ck]).max(axis=1) <= VALUATION_TOL) & (np.abs(nu).max(axis=1) >= VALUATION_MIN)
            agree[ck] = np.where(same, agree[ck] + 1, 0)
            nu_ck[ck], s_ck[ck] = nu, s[ck]
            xa = np.abs(x[ck, :angles])
            na = nu[:, :angles]
            far = (((na >= VALUATION_MIN) & (xa <= FAR)) | ((na <= -VALUATION_MIN) & (xa >= 1.0 / FAR))).any(axis=1)
            diverged[ck] = (agree[ck] >= VALUATION_CHECKS - 1) & far
        # ended, diverged or lost (magnitudes are bounded by BIG until the end game, where they may run far)
        mag = np.abs(x).max(axis=1)
        small = np.abs(x).min(axis=1)
        big = np.where(s <= ENDGAME, BIG ** 4, BIG)
        lost = (h < H_MIN * s) | (steps > MAX_STEPS) | (mag > big) | (small < 1.0 / big) | ~np.isfinite(mag)
        lost &= ~diverged
        ended = (s <= 0.0) & ~lost & ~diverged
        if ended.any():
            done_x.append(x[ended])
            done_idx.append(idx[ended])
        state[idx[diverged]] = INFINITE
        drop(~(ended | lost | diverged))

    if done_idx:
        ids = np.concatenate(done_idx)
        X = np.concatenate(done_x)
        zero = np.zeros(ids.size)
        last = np.full(ids.size, np.inf)
        for _ in range(3):
            H, J = fam.evaluate(X, zero)
            d, ok = _solve(J, H[:, :, None])
            X = np.where(ok[:, None], X - d[:, :, 0], np.nan)
            last = np.where(ok, _norm(d[:, :, 0], X), np.inf)
        H, J = fam.evaluate(X, zero)
        fine = np.isfinite(X).all(axis=1) & np.isfinite(J).all(axis=(1, 2)) & np.isfinite(last)
        rc = np.zeros(ids.size)
        if fine.any():
            sv = np.linalg.svd(J[fine], compute_uv=False)
            rc[fine] = sv[:, -1] / sv[:, 0]
        good = fine & (rc > RCOND_MIN) & (last <= CONVERGED)
        state[ids[good]] = FINITE
        roots[ids[good]] = X[good]
        regular[ids[good]] = True
    return TrackedPaths(state=state, roots=roots, regular=regular, steps=int(total_steps),
                        rejected=int(total_rejected), iterations=int(iterations), seconds=0.0)
