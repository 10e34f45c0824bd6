"""Shape labels of equilibria and buckling modes, from the sign pattern of ``q``.

The sign string has one character per joint: ``+``, ``-`` or ``0`` (``|q_i|``
below ``1e-6`` of the largest ``|q_j|``). The label counts the sign changes
``s`` along the chain, zeros skipped:

======  =========  =========================================================
``s``   label      meaning
======  =========  =========================================================
(all 0) ``I``      straight
0       ``C``      bent one way only (an arc)
1       ``U``      one sign change: the chain bows once (Table 2's U shape)
2       ``ZU``     two sign changes (Table 2's ZU shape)
3       ``Z``      three sign changes (Table 2's Z shape, alternating for n = 4)
>= 4    ``W<s>``   ``s`` sign changes, e.g. ``W4``
======  =========  =========================================================

For ``n = 4`` and the equilibria born from buckling this reproduces Table 2
exactly: ``-+++`` / ``+---`` are U, ``-+-+`` / ``+-+-`` are Z and
``-+--`` / ``+-++`` are ZU.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["sign_string", "shape_label"]

_NAMES = {0: "C", 1: "U", 2: "ZU", 3: "Z"}


def _small(q, rel_tol: float) -> tuple[list[float], float] | None:
    """``(values, threshold)`` for a short finite nonzero ``q`` handled with plain floats (several times
    faster than numpy for a few joints), else ``None``."""
    vals = np.asarray(q, dtype=float).ravel().tolist()
    if not 0 < len(vals) <= 32 or not math.isfinite(sum(vals)):
        return None
    scale = max(abs(v) for v in vals)
    return (vals, rel_tol * scale) if scale > 0.0 else None


def sign_string(q, rel_tol: float = 1e-6) -> str:
    """``"+"``/``"-"``/``"0"`` per joint angle."""
    small = _small(q, rel_tol)
    if small is not None:
        vals, t = small
        return "".join("0" if abs(v) <= t else ("+" if v > 0 else "-") for v in vals)
    q = np.asarray(q, dtype=float).ravel()
    scale = float(np.abs(q).max()) if q.size else 0.0
    if scale == 0.0:
        return "0" * q.size
    idx = np.where(np.abs(q) <= rel_tol * scale, 1, np.where(q > 0, 0, 2))
    return _CHARS[idx].tobytes().decode("ascii")


def shape_label(q, rel_tol: float = 1e-6) -> str:
    """The documented label (``I``, ``C``, ``U``, ``ZU``, ``Z``, ``W<s>``) of a configuration."""
    small = _small(q, rel_tol)
    if small is not None:
        vals, t = small
        pos = [v > 0 for v in vals if abs(v) > t]
        s = sum(a != b for a, b in zip(pos, pos[1:]))
        return _NAMES.get(s, f"W{s}")
    q = np.asarray(q, dtype=float).ravel()
    scale = float(np.abs(q).max()) if q.size else 0.0
    if scale == 0.0:
        return "I"
    sg = np.sign(q[np.abs(q) > rel_tol * scale])
    s = int(np.count_nonzero(sg[1:] != sg[:-1]))
    return _NAMES.get(s, f"W{s}")


def shape_labels(Q, rel_tol: float = 1e-6) -> list[str]:
    """:func:`shape_label` of every row of ``Q`` (m, n), vectorised."""
    Q = np.asarray(Q, dtype=float)
    if Q.shape[0] == 0:
        return []
    scale = np.abs(Q).max(axis=1, keepdims=True)
    sg = np.where(np.abs(Q) > rel_tol * scale, np.sign(Q), 0.0)
    # carry the last nonzero sign over zeros, then count the changes between nonzero neighbours
    idx = np.where(sg != 0.0, np.arange(sg.shape[1]), 0)
    np.maximum.accumulate(idx, axis=1, out=idx)
    filled = np.take_along_axis(sg, idx, axis=1)
    changes = np.count_nonzero((filled[:, 1:] != filled[:, :-1]) & (filled[:, :-1] != 0.0), axis=1)
    names = [_NAMES.get(c, f"W{c}") for c in range(int(changes.max(initial=0)) + 1)]
    return ["I" if not sc > 0.0 else names[c] for c, sc in zip(changes.tolist(), scale[:, 0].tolist())]


_CHARS = np.array([b"+", b"0", b"-"], dtype="S1")
