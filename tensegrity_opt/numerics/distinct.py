"""When two configurations are the same equilibrium: the one rule of every analysis and of the compiled kernels.

Two configurations are the same when every joint angle differs by less than the tolerance (the max-norm of
their difference is below it; :data:`SAME_Q` unless a caller's ``dedupe_tol`` says otherwise). A list is
reduced to its distinct members in order: a member is kept when it is not the same as any member kept before
it (the first of each group of coinciding members stands for the group; every member lies within the
tolerance of a kept one, and no two kept ones are the same). The compiled ``seeds`` kernel marks its
distinct rows by this rule (:func:`.kernels.distinct_function`, from :func:`same` itself).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from functools import lru_cache
from typing import TypeVar

import numpy as np

__all__ = ["SAME_Q", "same", "distinct", "distinct_rows", "distinct_indices"]

#: Two configurations closer than this in every joint angle (rad) are the same equilibrium.
SAME_Q = 1e-7
#: Up to this many rows are compared all at once (k x k); beyond, each with the kept rows near its first angle.
_PAIRWISE_MAX = 64

T = TypeVar("T")


def _row_max(d):
    return np.max(d, axis=-1)


def same(qa, qb, tol=SAME_Q, *, fabs: Callable = np.abs, largest: Callable = _row_max):
    """True where the configurations ``qa`` and ``qb`` are the same: ``largest(fabs(qa - qb)) < tol``.

    numpy arrays broadcast (rows of joint angles: one answer per row); the compiled kernels pass CasADi's
    ``fabs`` and ``mmax`` to build the same comparison symbolically.
    """
    return largest(fabs(qa - qb)) < tol


def distinct_rows(Q: np.ndarray, tol: float = SAME_Q) -> np.ndarray:
    """Boolean mask of the distinct rows of ``Q`` (k, n): each row not the same as any earlier kept row."""
    Q = np.asarray(Q, dtype=float)
    k = Q.shape[0]
    if k < 2:
        return np.ones(k, dtype=bool)
    if k > _PAIRWISE_MAX:
        keep = np.zeros(k, dtype=bool)
        keep[distinct_indices(Q, range(k), tol)] = True
        return keep
    close = same(Q[:, None, :], Q[None, :, :], tol) & _earlier(k)
    keep = ~close.any(axis=1)                       # nothing earlier is near: kept
    for i in np.flatnonzero(~keep).tolist():        # in order: the rows before i are settled
        keep[i] = not (close[i] & keep).any()
    return keep


def distinct_indices(Q: np.ndarray, idx: Sequence[int], tol: float = SAME_Q) -> list[int]:
    """The indices in ``idx`` (in order) whose rows of ``Q`` are distinct among those rows (:func:`distinct_rows`).

    Beyond ``_PAIRWISE_MAX`` rows (the thousands of starts of a multistable chain) without the k x k
    comparison: the first row left is kept and every later row the same as it is dropped, all at once, until
    no row is left (one pass over the rows left per kept row; a few passes for the few equilibria that
    thousands of starts converge to).
    """
    idx = list(idx)
    if len(idx) <= _PAIRWISE_MAX:
        return [j for j, keep in zip(idx, distinct_rows(Q[idx], tol).tolist()) if keep] if len(idx) > 1 else idx
    rest = np.asarray(idx, dtype=int)
    rows = np.asarray(Q, dtype=float)[rest]
    out = []
    while rest.size:
        out.append(int(rest[0]))
        other = ~same(rows[1:], rows[0], tol)
        rest, rows = rest[1:][other], rows[1:][other]
    return out


def distinct(items: Sequence[T], tol: float = SAME_Q) -> list[T]:
    """The distinct members of ``items`` (each with joint angles ``.q``), in order (:func:`distinct_rows`)."""
    if len(items) < 2:
        return list(items)
    Q = np.array([r.q for r in items])
    return [items[j] for j in distinct_indices(Q, range(len(items)), tol)]


@lru_cache(maxsize=64)
def _earlier(k: int) -> np.ndarray:
    """``[i, j]`` true where ``j < i`` (k x k), read only."""
    lower = np.tri(k, k, -1, dtype=bool)
    lower.setflags(write=False)
    return lower
