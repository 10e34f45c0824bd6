"""The one NaN policy of every JSON form of a result (``to_dict()``, the CLI's ``--json``, sweep rows).

- A field whose schema promises a number gets a finite Python ``float`` (:func:`number`,
  :func:`numbers`), or :class:`~tensegrity_opt.errors.NonFiniteResult` is raised: a number
  never silently becomes ``null``.
- A field documented as nullable (a force-deflection branch point that does not exist, a landscape
  cell outside the reachable set, ``Design.initial_critical_force``, every result column of a sweep
  row) gets ``None`` for NaN and infinities (:func:`nullable`, :func:`nullables`).
- Everything else is a plain ``int`` / ``bool`` / ``str`` / ``list`` / ``dict``, so the dicts pass
  ``json.dumps(..., allow_nan=False)``.

Foundation level: numpy and :mod:`tensegrity_opt.errors` only, imported by the model, the
analyses and the applications alike.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .errors import NonFiniteResult

__all__ = ["NonFiniteResult", "number", "numbers", "nullable", "nullables"]

_MESSAGE = "the result is not finite for this input (overflow or underflow in the model)"


def number(x: Any) -> float:
    """``x`` as a finite ``float``, or :class:`NonFiniteResult`."""
    v = float(x)
    if not math.isfinite(v):
        raise NonFiniteResult(_MESSAGE)
    return v


def numbers(a: Any) -> list[Any]:
    """``a`` as (nested) lists of finite floats, or :class:`NonFiniteResult`."""
    if type(a) is np.ndarray and a.ndim == 1 and a.dtype == np.float64:     # the common case, as plain floats
        vals = a.tolist()
        if all(map(math.isfinite, vals)):
            return vals
    arr = np.asarray(a, dtype=float)
    if not bool(np.all(np.isfinite(arr))):
        raise NonFiniteResult(_MESSAGE)
    return arr.tolist()


def nullable(x: Any) -> float | None:
    """``x`` as a ``float``; ``None`` for NaN and infinities (fields documented as nullable)."""
    v = float(x)
    return v if math.isfinite(v) else None


def nullables(a: Any) -> list[Any]:
    """``a`` (an array of any dimension >= 1) as (nested) lists of floats, ``None`` for each NaN or infinity."""
    vals = np.asarray(a, dtype=float).tolist()
    if not isinstance(vals, list):
        raise ValueError("nullables() takes an array, not a scalar: use nullable()")
    return _nulls(vals)


def _nulls(vals: list[Any]) -> list[Any]:
    if vals and isinstance(vals[0], list):
        return [_nulls(v) for v in vals]
    return [v if math.isfinite(v) else None for v in vals]
