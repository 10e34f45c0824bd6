"""Starting points for the global searches: buckling modes, their mirrors, random starts, arcs.

A seed is a configuration ``q`` (and a guess of the tip force) near which a
local solver is started. For a deflection ``(dx, dy)`` a mode ``alpha`` is
scaled by eq. 23 (``dx ~ 1/2 t^2 alpha^T G alpha``) and shifted by the smallest
``q`` giving ``dy`` to first order; every seed is shrunk into the physical range.
Random starts use a fixed-seed generator: the same call gives the same answer.

The modes describe small deflections. Under large ones the least-energy shape can be a
C curled close to the joint limits, which neither the scaled modes nor the random starts
reach (measured: 1 of 114 random monotonic chains and targets missed it; Newton from the
seeds stopped on the U branch, 2.1 energy units higher); two *arc* seeds cover it: every
joint bent the same way, the same fraction of its range, ``q = ±t * limit`` with ``t <= 0.9``
chosen so the tip lands nearest the target, used when that arc is curled (``t >= 0.25``; at
small deflections the nearest arc is nearly straight and adds nothing). They come last, so they
only change an answer when they find a lower minimum.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from ...errors import TensegrityError
from ...model.combinations import sample_combinations
from ...model.manipulator import Manipulator
from ...model.segment import Segment
from ...numerics import distinct_rows
from .buckling import critical_force, quad_G, tip_slope

__all__ = ["Seed", "seeds", "seed_matrix", "seed_starts", "arc_seeds", "well_seeds", "project_to_target",
           "projected_sample", "ranked_well_seeds"]


@dataclass(frozen=True)
class Seed:
    q: np.ndarray
    force: np.ndarray | None
    origin: str


@lru_cache(maxsize=64)
def _directions(m: Manipulator, max_modes: int) -> list[tuple[np.ndarray, float | None, float | None]]:
    """Mode shapes with their predicted ``(Fx, Fy per t)``.

    The guided buckling modes when they exist; otherwise (asymmetric preloads, ``K <= 0``) the
    modes of the same geometry with stiff symmetric springs, which only serve as directions.
    Cached per manipulator (``Manipulator`` is immutable and hashable): continuation and
    repeated solves on one chain do not recompute its modes."""
    if m.n < 2:
        return [(np.ones(1), None, None)]
    k = min(max_modes, m.n - 1)
    try:
        bk = critical_force(m, "guided", n_modes=k)
        return [(md.q, -md.load, md.fy) for md in bk.modes]
    except (TensegrityError, np.linalg.LinAlgError):
        pass
    # K_i = 1 + max(0, 2 (a^2 - b^2)) keeps the rest lengths positive
    K = 1.0 + np.maximum(0.0, 2.0 * (m.a ** 2 - m.b ** 2))
    proxy = Manipulator(Segment(a, b, 1.0, (Ki + 2.0 * (b * b - a * a)) / b) for a, b, Ki in zip(m.a, m.b, K))
    bk = critical_force(proxy, "guided", n_modes=k)
    return [(md.q, None, None) for md in bk.modes]


@lru_cache(maxsize=256)
def _basis(m: Manipulator, max_modes: int, amplitudes: tuple[float, ...], n_random: int, rng_seed: int):
    """Seed directions scaled for ``dx = 1`` (rows), their force guesses and origins; cached per call pattern.

    A seed for ``dx`` is ``sqrt(dx) * row + qy``, shrunk into the range: ``t0 = sqrt(2 dx / alpha^T G alpha)``
    (eq. 23) scales as ``sqrt(dx)``, and the random directions come from a fixed-seed generator.
    """
    S0 = tip_slope(m)
    rows, fxs, fys, origins = [], [], [], []
    for alpha, fx, fy in _directions(m, max_modes):
        s1 = np.sqrt(2.0 / quad_G(m, alpha))
        for amp in amplitudes:
            for sign in (1.0, -1.0):
                t = sign * amp * s1
                rows.append(t * alpha)
                fxs.append(np.nan if fx is None else fx)
                fys.append(np.nan if fx is None else fy * t)
                origins.append(f"mode{'+' if sign > 0 else '-'}")
    rng = np.random.default_rng(rng_seed + m.n)
    for _ in range(n_random):
        v = rng.standard_normal(m.n)
        v -= S0 * (S0 @ v) / (S0 @ S0)
        rows.append(np.sqrt(2.0 / quad_G(m, v)) * rng.uniform(0.5, 2.0) * v)
        fxs.append(np.nan)
        fys.append(np.nan)
        origins.append("random")
    D = np.array(rows).reshape(len(rows), m.n)
    for a in (D, S0):
        a.setflags(write=False)
    return D, np.array(fxs), np.array(fys), tuple(origins), S0


def seed_matrix(m: Manipulator, dx: float, dy: float, *, max_modes: int = 6, amplitudes=(1.0,),
                n_random: int = 8, rng_seed: int = 20201, arcs: bool = True
                ) -> tuple[np.ndarray, np.ndarray, tuple[str, ...]]:
    """The seeds of :func:`seeds` as arrays: ``(Q (S, n), F (S, 2) with NaN rows where no guess, origins)``."""
    amplitudes = tuple(float(a) for a in amplitudes)
    _, fx, fy, origins, _ = _basis(m, int(max_modes), amplitudes, int(n_random), int(rng_seed))
    Q, arc_signs = _starts(m, dx, dy, max_modes, amplitudes, n_random, rng_seed, arcs)
    F = np.column_stack([fx, fy * np.sqrt(max(float(dx), 1e-12))])
    if arc_signs:                                    # the arc seeds used for this target
        F = np.vstack([F, np.full((len(arc_signs), 2), np.nan)])
        origins = origins + tuple("arc+" if s > 0 else "arc-" for s in arc_signs)
    return Q, F, origins


def seed_starts(m: Manipulator, dx: float, dy: float, *, max_modes: int = 6, amplitudes=(1.0,),
                n_random: int = 8, rng_seed: int = 20201, arcs: bool = True) -> np.ndarray:
    """The configurations of :func:`seed_matrix` alone, ``(S, n)`` (what a global search starts from)."""
    return _starts(m, dx, dy, max_modes, amplitudes, n_random, rng_seed, arcs)[0]


def _starts(m: Manipulator, dx: float, dy: float, max_modes: int, amplitudes, n_random: int, rng_seed: int,
            arcs: bool) -> tuple[np.ndarray, list[float]]:
    """The seed configurations and the signs of the arc seeds among them (the last rows)."""
    D, _, _, _, S0 = _basis(m, int(max_modes), tuple(float(a) for a in amplitudes), int(n_random), int(rng_seed))
    Q = math.sqrt(max(float(dx), 1e-12)) * D
    if dy:
        Q += S0 * (float(dy) / float(S0 @ S0))            # plus the least-norm q with S0^T q = dy
    r = np.max(np.abs(Q) / _room(m), axis=1)
    Q /= np.maximum(r, 1.0)[:, None]
    fractions = _arc_fractions(m, dx, dy) if arcs and m.n >= 2 else []
    if fractions:
        shape = _arcs(m)[0]
        Q = np.vstack([Q] + [s * t * shape for s, t in fractions])
    return Q, [s for s, _ in fractions]


def arc_seeds(m: Manipulator, dx: float, dy: float) -> np.ndarray:
    """The arc seeds ``(k, n)``, ``k <= 2``: ``q = s * t * limit`` (the joint range ``|q| < limit``)
    for ``s = +1, -1``, each with the fraction ``t`` of a grid over ``(0, 0.9]`` whose tip lands
    nearest the target, kept when curled (``t >= ARC_MIN``): nearly straight arcs are the small
    deflections the mode seeds already cover (and Newton from them converges slowly)."""
    return np.array([s * t * _arcs(m)[0] for s, t in _arc_fractions(m, dx, dy)]).reshape(-1, m.n)


def _arc_fractions(m: Manipulator, dx: float, dy: float) -> list[tuple[float, float]]:
    _, thetas, tips = _arcs(m)
    tx, ty = m.target(dx, dy)
    # q -> -q mirrors the tip: (x, y) -> (x, -y); rows: s = +1, -1. At ty = 0 both rows are the same
    # distances ((y - 0)^2 is y^2 exactly): one row, from the grid's y^2 computed once per chain.
    if ty == 0.0:
        near = [int(np.argmin((tips[0] - tx) ** 2 + tips[2]))] * 2
    else:
        near = np.argmin((tips[0] - tx) ** 2 + (tips[1] - np.array([[ty], [-ty]])) ** 2, axis=1).tolist()
    return [(s, t) for s, t in zip((1.0, -1.0), thetas[near].tolist()) if t >= ARC_MIN]


#: Points of the grid over the arc family's fraction of the range, and the least fraction used.
ARC_GRID = 128
ARC_MIN = 0.25


@lru_cache(maxsize=256)
def _arcs(m: Manipulator) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The arc family of a chain: its shape (the joint limits), the grid of fractions and the tips there
    (rows: x, y, y^2)."""
    shape = np.array(m.joint_limits, dtype=float)
    thetas = np.linspace(0.9 / ARC_GRID, 0.9, ARC_GRID)
    xy = np.array([m.tip(t * shape) for t in thetas]).T
    tips = np.vstack([xy, xy[1] ** 2])
    for a in (shape, thetas, tips):
        a.setflags(write=False)
    return shape, thetas, tips


@lru_cache(maxsize=256)
def _room(m: Manipulator) -> np.ndarray:
    """``0.9 * joint limit`` per joint: seeds stay within 90 % of the range."""
    room = m.joint_limits * 0.9
    room.setflags(write=False)
    return room


def seeds(m: Manipulator, dx: float, dy: float, *, max_modes: int = 6, amplitudes=(1.0,),
          n_random: int = 8, rng_seed: int = 20201, arcs: bool = True) -> list[Seed]:
    """Seeds for the deflection ``(dx, dy)``: ``±`` each mode at each amplitude factor, then random,
    then (``arcs``) the two arcs."""
    Q, F, origins = seed_matrix(m, dx, dy, max_modes=max_modes, amplitudes=amplitudes, n_random=n_random,
                                rng_seed=rng_seed, arcs=arcs)
    return [Seed(q, None if np.isnan(f[0]) else f, o) for q, f, o in zip(Q, F, origins)]


# ----------------------------------------------------------------------------- wells of multistable chains
#: Most sign patterns tried exhaustively; beyond, a fixed-seed sample of this many (plus the uniform ones).
WELL_PATTERNS = 729


def _pattern_matrix(m: Manipulator, hilltops: bool, cap: int, rng_seed: int) -> np.ndarray:
    """Configurations built from one unloaded critical point per segment: every combination while
    there are at most ``cap``, else the combinations with all segments in the same well plus a
    fixed-seed random sample."""
    choices = []
    for s in m.segments:
        wells, tops = s.critical_angles()
        pts = list(wells) + (list(tops) if hilltops else [])
        choices.append(pts or [0.0])
    return sample_combinations(choices, cap, rng_seed + m.n)


def project_to_target(m: Manipulator, Q: np.ndarray, target: np.ndarray, *, iters: int = 30,
                      tol: float = 1e-11, drop: bool = True) -> np.ndarray:
    """Each row of ``Q`` moved onto ``tip(q) = target`` by minimum-norm Gauss-Newton steps
    (``q <- q + J^T (J J^T)^-1 (target - tip)``, at most 0.5 rad a step), all rows at once. A row stops once its
    tip is within ``tol`` of the chain's half length ``sum b`` of the target (the rows still moving are the only
    ones evaluated: thousands of starts, most settled in a few steps). With ``drop`` the rows that do not converge
    (within ``1e-8 sum b``), meet a singular Jacobian or leave the physical range are dropped; without it every row
    is returned, in order, each where it got to (a row at a singular Jacobian stays where it was)."""
    Q = np.array(Q, dtype=float, copy=True)
    if Q.size == 0:
        return Q.reshape(0, m.n)
    lim = m.joint_limits
    scale = float(m.b.sum())
    tx, ty = float(target[0]), float(target[1])
    ok = np.ones(Q.shape[0], dtype=bool)
    active = np.arange(Q.shape[0])                  # rows still moving (not yet within tol, not broken)
    A = Q
    for _ in range(iters + 1):
        k = m.tip_kinematics(A)
        rx, ry = tx - k.tip[:, 0], ty - k.tip[:, 1]
        Jx, Jy = k.Jx, k.Jy
        moving = np.maximum(np.abs(rx), np.abs(ry)) >= tol * scale
        if not moving.all():                        # settled rows leave the active set
            Q[active] = A
            active, A, Jx, Jy, rx, ry = active[moving], A[moving], Jx[moving], Jy[moving], rx[moving], ry[moving]
        if active.size == 0 or _ == iters:
            break
        a11 = (Jx * Jx).sum(axis=1)
        a12 = (Jx * Jy).sum(axis=1)
        a22 = (Jy * Jy).sum(axis=1)
        det = a11 * a22 - a12 * a12
        bad = det <= 1e-14 * np.maximum(a11 * a22, 1e-300)
        det = np.where(bad, 1.0, det)
        w1 = (a22 * rx - a12 * ry) / det
        w2 = (a11 * ry - a12 * rx) / det
        step = Jx * w1[:, None] + Jy * w2[:, None]
        big = np.abs(step).max(axis=1)
        step *= np.minimum(1.0, 0.5 / np.maximum(big, 1e-300))[:, None]      # at most 0.5 rad a step
        broken = bad | ~np.all(np.isfinite(step), axis=1)
        if broken.any():                            # a singular Jacobian or a non-finite step: stops (dropped)
            ok[active[broken]] = False
            Q[active[broken]] = A[broken]
            keep = ~broken
            active, A, step = active[keep], A[keep], step[keep]
        A = A + step
    Q[active] = A
    if not drop:
        return Q
    ok &= np.abs(m.tip_kinematics(Q).tip - (tx, ty)).max(axis=1) < 1e-8 * scale
    ok &= np.all(np.abs(Q) < lim, axis=1)
    return Q[ok]


def projected_sample(m: Manipulator, target: np.ndarray, count: int, rng_seed: int) -> np.ndarray:
    """``count`` uniform random configurations in 95 % of the joint range (generator seeded with
    ``rng_seed + n``: reproducible), projected onto ``tip(q) = target`` (:func:`project_to_target`)."""
    rng = np.random.default_rng(rng_seed + m.n)
    return project_to_target(m, rng.uniform(-0.95, 0.95, (int(count), m.n)) * m.joint_limits, target)


def well_seeds(m: Manipulator, dx: float, dy: float, *, hilltops: bool = True, cap: int = WELL_PATTERNS,
               rng_seed: int = 7, dedupe: float = 1e-3) -> np.ndarray:
    """Seeds of a multistable chain: one unloaded critical point per segment (its wells and, with
    ``hilltops``, its hilltop), combined over the segments (the ``3^k`` critical points of the
    unloaded energy, ``k`` bistable segments; exhaustive up to ``cap``, sampled beyond), each projected
    onto the tip constraint. Empty for chains whose segments are all monotonic (one pattern: the
    rest shape, which the mode seeds cover)."""
    if m.n < 2 or m.monotonic:
        return np.zeros((0, m.n))
    P = _pattern_matrix(m, hilltops, cap, rng_seed)
    Q = project_to_target(m, P, m.target(dx, dy))
    return Q[distinct_rows(Q, dedupe)]


#: Most well patterns :func:`ranked_well_seeds` ranks exhaustively; beyond, a local search over the patterns.
RANK_PATTERNS_MAX = 1 << 14
#: The local search: random patterns to start from, the best kept each round, and the rounds of one- and
#: two-segment flips of the kept ones.
RANK_SAMPLE = 4096
RANK_KEEP = 32
RANK_ROUNDS = 6


def ranked_well_seeds(m: Manipulator, dx: float, dy: float, count: int, *, rng_seed: int = 29) -> np.ndarray:
    """The ``count`` well patterns (one unloaded well per segment) that reach the target with the least
    elastic work found, projected onto the tip constraint: ``(k, n)``, ``k <= count``.

    Each pattern ``w`` is ranked by ``E(w) + 1/2 d^T C^-1 d``: its energy plus the work of moving its tip by
    ``d = target - tip(w)`` through the linear compliance ``C = J diag(1/E_j''(w_j)) J^T`` (the least-energy
    configuration of a chain of bistable segments near its wells is a pattern whose tip lies close to the
    target in that metric; there are ``2^n`` patterns and the default search tries at most ``WELLS_MAX``).
    Every pattern while there are at most :data:`RANK_PATTERNS_MAX`; beyond, a local search: a fixed-seed random
    sample, then rounds of every one- and two-segment change of the best ones (heuristic: it ranks seeds, the
    certificate is :mod:`.lower_bound`'s). Empty when the chain is monotonic or ``n < 2``."""
    if m.n < 2 or m.monotonic or count <= 0:
        return np.zeros((0, m.n))
    wells = [np.asarray(s.critical_angles()[0], dtype=float) for s in m.segments]
    wells = [w if w.size else np.zeros(1) for w in wells]
    sizes = np.array([w.size for w in wells])
    total = float(np.prod(sizes.astype(float)))
    if total <= 1:
        return np.zeros((0, m.n))
    pmax = int(sizes.max())
    W = np.array([np.pad(w, (0, pmax - w.size), mode="edge") for w in wells])           # (n, pmax)
    Ew = np.array([m.segments[j].energy(W[j]) for j in range(m.n)])
    Kw = np.array([np.maximum(-m.segments[j].dtorque(W[j]), 1e-12 * m.torque_scale) for j in range(m.n)])
    target = m.target(dx, dy)
    cols = np.arange(m.n)

    def score(D: np.ndarray) -> np.ndarray:
        _, _, tip, Jx, Jy = m.tip_kinematics(W[cols, D])
        d0, d1 = target[0] - tip[:, 0], target[1] - tip[:, 1]
        ik = 1.0 / Kw[cols, D]
        cxx, cxy, cyy = (Jx * Jx * ik).sum(axis=1), (Jx * Jy * ik).sum(axis=1), (Jy * Jy * ik).sum(axis=1)
        det = cxx * cyy - cxy * cxy
        with np.errstate(divide="ignore", over="ignore", invalid="ignore"):      # a singular C: rank it last
            work = 0.5 * (cyy * d0 ** 2 - 2 * cxy * d0 * d1 + cxx * d1 ** 2) / det
        work = np.where(np.isfinite(work) & (det > 0), work, np.inf)
        return Ew[cols, D].sum(axis=1) + work

    def digits(ids: np.ndarray) -> np.ndarray:
        D = np.empty((ids.size, m.n), dtype=np.int64)
        rem = ids
        for j in range(m.n - 1, -1, -1):
            rem, D[:, j] = np.divmod(rem, sizes[j])
        return D

    if total <= RANK_PATTERNS_MAX:
        D = digits(np.arange(int(total)))
        best = D[np.argsort(score(D), kind="stable")[:count]]
    else:
        rng = np.random.default_rng(rng_seed + m.n)
        D = (rng.random((RANK_SAMPLE, m.n)) * sizes).astype(np.int64)
        D = np.vstack([D, np.zeros((1, m.n), dtype=np.int64), sizes[None, :] - 1])
        sc = score(D)
        pairs = [(i, j) for i in range(m.n) for j in range(i, m.n)]
        pi = np.array([p[0] for p in pairs])
        pj = np.array([p[1] for p in pairs])
        for _ in range(RANK_ROUNDS):
            D, idx = np.unique(D, axis=0, return_index=True)
            sc = sc[idx]
            top = D[np.argsort(sc, kind="stable")[:RANK_KEEP]]
            # every one-segment (i == j) and two-segment change of the best: the next well of each
            nb = np.repeat(top, len(pairs), axis=0)
            r = np.arange(nb.shape[0])
            ii, jj = np.tile(pi, top.shape[0]), np.tile(pj, top.shape[0])
            nb[r, ii] = (nb[r, ii] + 1) % sizes[ii]
            nb[r, jj] = np.where(ii == jj, nb[r, jj], (nb[r, jj] + 1) % sizes[jj])
            D = np.vstack([top, nb])
            sc = score(D)
        D, idx = np.unique(D, axis=0, return_index=True)
        best = D[np.argsort(sc[idx], kind="stable")[:count]]
    Qp = project_to_target(m, W[cols, best], target)
    return Qp[distinct_rows(Qp, 1e-3)] if Qp.shape[0] else Qp
