"""Starting points for the global searches: buckling modes, their mirrors, random starts.

A seed is a configuration ``q`` (and a guess of the tip force) near which a
local solver is started. For a deflection ``(dx, dy)`` a mode ``alpha`` is
scaled by eq. 23 (``dx ~ 1/2 t^2 alpha^T G alpha``) and shifted by the smallest
``q`` giving ``dy`` to first order; every seed is shrunk into the physical range.
Random starts use a fixed-seed generator: the same call gives the same answer.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import math

import numpy as np

from .buckling import critical_force, quad_G, tip_slope
from .errors import TensegrityError
from .manipulator import Manipulator
from .segment import Segment

__all__ = ["Seed", "seeds", "seed_matrix", "seed_starts"]


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
                n_random: int = 8, rng_seed: int = 20201) -> tuple[np.ndarray, np.ndarray, tuple[str, ...]]:
    """The seeds of :func:`seeds` as arrays: ``(Q (S, n), F (S, 2) with NaN rows where no guess, origins)``."""
    amplitudes = tuple(float(a) for a in amplitudes)
    _, fx, fy, origins, _ = _basis(m, int(max_modes), amplitudes, int(n_random), int(rng_seed))
    Q = seed_starts(m, dx, dy, max_modes=max_modes, amplitudes=amplitudes, n_random=n_random, rng_seed=rng_seed)
    return Q, np.column_stack([fx, fy * np.sqrt(max(float(dx), 1e-12))]), origins


def seed_starts(m: Manipulator, dx: float, dy: float, *, max_modes: int = 6, amplitudes=(1.0,),
                n_random: int = 8, rng_seed: int = 20201) -> np.ndarray:
    """The configurations of :func:`seed_matrix` alone, ``(S, n)`` (what a global search starts from)."""
    D, _, _, _, S0 = _basis(m, int(max_modes), tuple(float(a) for a in amplitudes), int(n_random), int(rng_seed))
    Q = math.sqrt(max(float(dx), 1e-12)) * D
    if dy:
        Q += S0 * (float(dy) / float(S0 @ S0))            # plus the least-norm q with S0^T q = dy
    r = np.max(np.abs(Q) / _room(m), axis=1)
    Q /= np.maximum(r, 1.0)[:, None]
    return Q


@lru_cache(maxsize=256)
def _room(m: Manipulator) -> np.ndarray:
    """``0.9 * joint limit`` per joint: seeds stay within 90 % of the range."""
    room = m.joint_limits * 0.9
    room.setflags(write=False)
    return room


def seeds(m: Manipulator, dx: float, dy: float, *, max_modes: int = 6, amplitudes=(1.0,),
          n_random: int = 8, rng_seed: int = 20201) -> list[Seed]:
    """Seeds for the deflection ``(dx, dy)``: ``±`` each mode at each amplitude factor, then random."""
    Q, F, origins = seed_matrix(m, dx, dy, max_modes=max_modes, amplitudes=amplitudes, n_random=n_random,
                                rng_seed=rng_seed)
    return [Seed(q, None if np.isnan(f[0]) else f, o) for q, f, o in zip(Q, F, origins)]
