"""Every equilibrium for a prescribed tip displacement: minima, saddles and maxima.

The KKT system ``grad E(q) = J(q)^T F``, ``tip(q) = target`` (n + 2 equations in
``q, F``) is solved by damped Newton (CasADi residual and exact Jacobian) from
many seeds: every buckling mode with both signs at several amplitudes, random
starts, and IPOPT's minima (so that no minimum is missed). Solutions outside the
physical range or on a joint limit are dropped, duplicates merged, the rest
classified by the Morse index of the reduced Hessian and sorted by energy.
"""

from __future__ import annotations

import numpy as np

from .equilibrium import (Equilibrium, check_q0, one_segment_equilibrium, straight_equilibrium, is_equilibrium, local_equilibrium,
                          make_equilibrium)
from .errors import SolverError
from .manipulator import Manipulator
from .seeds import seeds

__all__ = ["find_equilibria"]


def find_equilibria(m: Manipulator, dx: float, dy: float = 0.0, *, n_random: int = 16,
                    amplitudes=(0.6, 1.0, 1.6), max_modes: int = 12, extra_seeds=None,
                    dedupe_tol: float = 1e-6) -> list[Equilibrium]:
    """All equilibria inside the physical range for the tip at ``(2 sum(b) - dx, dy)``.

    Parameters
    ----------
    m : Manipulator
    dx, dy : float
        Tip deflection (length units).
    n_random : int
        Random Newton starts (fixed seed: the answer is reproducible).
    amplitudes : sequence of float
        Multiples of the eq.-23 amplitude at which each mode seeds Newton.
    max_modes : int
        At most this many buckling modes are used as seeds (all ``n - 1`` for ``n <= 13``).
    extra_seeds : iterable of array_like, optional
        More starting configurations (e.g. a previous solution).
    dedupe_tol : float
        Two solutions closer than this (max-norm of ``q``, rad) are one.

    Returns
    -------
    list of Equilibrium
        No duplicates, sorted by energy (ties: ``q_1`` descending). For the paper's chain at
        small ``dx > 0, dy = 0``: 2 stable U, 2 saddles ZU, 2 maxima Z.

    Raises
    ------
    UnreachableTargetError
        (``ValueError``) beyond the chain's reach.
    SolverError
        (``RuntimeError``) when no Newton start converged at all.
    """
    target = m.check_reachable(dx, dy)
    if dx == 0.0 and dy == 0.0:
        return [straight_equilibrium(m)]
    if m.n == 1:
        return [one_segment_equilibrium(m, target)]
    results = []
    statuses: dict[str, int] = {}
    starts = [(s.q, s.force) for s in seeds(m, dx, dy, max_modes=max_modes, amplitudes=amplitudes,
                                              n_random=n_random)]
    for q in extra_seeds or ():
        starts.append((check_q0(m, q), None))
    for q, F in starts:
        res = local_equilibrium(m, target, q, F)
        statuses[res.status] = statuses.get(res.status, 0) + 1
        if is_equilibrium(m, res, target):
            results.append(res)
    # IPOPT's minima from the mode seeds: a cheap guarantee that the stable ones are present.
    for s in seeds(m, dx, dy, max_modes=2, n_random=0):
        res = local_equilibrium(m, target, s.q, minimize=True)
        if is_equilibrium(m, res, target):
            results.append(res)
    if not results:
        raise SolverError(f"no Newton start converged inside the physical range for dx={dx:g}, dy={dy:g}",
                          status=", ".join(f"{k} x{v}" for k, v in sorted(statuses.items())))
    unique: list = []
    for res in results:
        if not any(np.max(np.abs(res.q - u.q)) < dedupe_tol for u in unique):
            unique.append(res)
    eqs = [make_equilibrium(m, r, constrained=True) for r in unique]
    eqs.sort(key=lambda e: (round(e.energy, 10), -e.q[0]))
    return eqs
