"""Configurations of one value per joint: the Cartesian product of per-segment choices, as rows.

A chain's configurations built from one candidate angle per segment (its unloaded wells, hilltops,
critical points) are rows of a ``(count, n)`` array. ``numpy.meshgrid`` / ``numpy.ix_`` / ``np.indices``
would build them through an array of ``n`` dimensions, which numpy refuses beyond 32 (64 in places): a
chain of 33 segments would fail even when every segment has a single candidate. These build the rows
column by column instead, in two dimensions whatever ``n``.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

__all__ = ["combination_count", "combination_indices", "combinations", "sample_combinations"]


def combination_count(choices: Sequence[Sequence[float] | np.ndarray]) -> int:
    """How many rows :func:`combinations` gives: the product of the choices' sizes (``1`` for no joint)."""
    return math.prod(len(c) for c in choices)


def combination_indices(sizes: Sequence[int]) -> np.ndarray:
    """Every index combination ``(i_1, ..., i_n)``, ``0 <= i_j < sizes[j]``, as rows ``(prod(sizes), n)``, the
    first index varying slowest (the order of ``numpy.meshgrid(..., indexing="ij")`` raveled)."""
    idx = np.zeros((1, 0), dtype=np.intp)
    for size in sizes:
        idx = np.column_stack([np.repeat(idx, int(size), axis=0),
                               np.tile(np.arange(int(size), dtype=np.intp), idx.shape[0])])
    return idx


def combinations(choices: Sequence[Sequence[float] | np.ndarray]) -> np.ndarray:
    """Every configuration taking joint ``j``'s angle from ``choices[j]``, as float rows ``(count, n)``, the
    first joint varying slowest; ``(0, n)`` when a joint has no choice."""
    cols = [np.asarray(c, dtype=float).ravel() for c in choices]
    idx = combination_indices([c.size for c in cols])
    if not cols:
        return np.zeros((1, 0))
    return np.column_stack([c[idx[:, j]] for j, c in enumerate(cols)]).reshape(idx.shape[0], len(cols))


def sample_combinations(choices: Sequence[Sequence[float] | np.ndarray], cap: int, seed: int) -> np.ndarray:
    """Every combination (:func:`combinations`) while there are at most ``cap``, else ``cap`` rows: all joints at
    their first choice, all at their last, and a random sample drawn with ``seed`` (the same rows for the same
    seed); ``(0, n)`` when a joint has no choice."""
    if any(len(c) == 0 for c in choices):
        return np.zeros((0, len(choices)))
    if combination_count(choices) <= cap:
        return combinations(choices)
    rng = np.random.default_rng(seed)
    rows = [[c[0] for c in choices], [c[-1] for c in choices]]
    rows += [[c[int(rng.integers(len(c)))] for c in choices] for _ in range(cap - 2)]
    return np.array(rows, dtype=float)
