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

import numpy as np
import scipy.linalg as sla

from .buckling import critical_force, straight_matrices
from .errors import TensegrityError
from .manipulator import Manipulator

__all__ = ["Seed", "seeds"]


@dataclass(frozen=True)
class Seed:
    q: np.ndarray
    force: np.ndarray | None
    origin: str


@lru_cache(maxsize=64)
def _directions(m: Manipulator, max_modes: int) -> list[tuple[np.ndarray, float | None, float | None]]:
    """Mode shapes with their predicted ``(Fx, Fy per t)``; geometric modes when buckling is undefined.

    Cached per manipulator (``Manipulator`` is immutable and hashable): continuation and
    repeated solves on one chain do not recompute its modes."""
    if m.n >= 2:
        try:
            bk = critical_force(m, "guided")
            return [(md.q, -md.load, md.fy) for md in bk.modes[:max_modes]]
        except (TensegrityError, np.linalg.LinAlgError):
            pass
    _, G, S0 = straight_matrices(m)
    if m.n >= 2:
        Z = sla.null_space(S0[None, :])
        _, V = sla.eigh(Z.T @ Z, Z.T @ G @ Z)
        vecs = Z @ V
    else:
        vecs = np.ones((1, 1))
    return [(v / np.linalg.norm(v), None, None) for v in vecs.T[:max_modes]]


def seeds(m: Manipulator, dx: float, dy: float, *, max_modes: int = 6, amplitudes=(1.0,),
          n_random: int = 8, rng_seed: int = 20201) -> list[Seed]:
    """Seeds for the deflection ``(dx, dy)``: ``±`` each mode at each amplitude factor, then random."""
    _, G, S0 = straight_matrices(m)
    lim = m.joint_limits * 0.9
    qy = S0 * (dy / (S0 @ S0))          # least-norm q with S0^T q = dy
    dxe = max(float(dx), 1e-12)
    out: list[Seed] = []

    def shrink(q: np.ndarray) -> np.ndarray:
        r = np.max(np.abs(q) / lim)
        return q / r if r > 1.0 else q

    for alpha, fx, fy in _directions(m, max_modes):
        t0 = np.sqrt(2.0 * dxe / float(alpha @ G @ alpha))
        for amp in amplitudes:
            for sign in (1.0, -1.0):
                t = sign * amp * t0
                F = None if fx is None else np.array([fx, fy * t])
                out.append(Seed(shrink(t * alpha + qy), F, f"mode{'+' if sign > 0 else '-'}"))
    rng = np.random.default_rng(rng_seed + m.n)
    for _ in range(n_random):
        v = rng.standard_normal(m.n)
        v -= S0 * (S0 @ v) / (S0 @ S0)
        t0 = np.sqrt(2.0 * dxe / float(v @ G @ v))
        out.append(Seed(shrink(t0 * rng.uniform(0.5, 2.0) * v + qy), None, "random"))
    return out
