"""Numbers from callers: the one test of "a real number" every public function shares.

``float(v)`` and ``np.asarray(v, dtype=float)`` take more than numbers: ``float("1")`` is 1.0 and
``np.asarray([True, 0.01], float)`` is ``[1.0, 0.01]``. A parameter that is a number must be an ``int`` or a
``float`` (or their numpy kinds), never a ``bool`` or a string: :func:`real` and :func:`real_array` refuse anything
else with an :class:`~tensegrity_opt.errors.InvalidParameterError` naming the field.
"""

from __future__ import annotations

from numbers import Real
from typing import Any

import numpy as np

from .errors import InvalidParameterError

__all__ = ["is_real", "real", "real_array"]


def is_real(v: Any) -> bool:
    """``v`` is one real number: an int or float (numpy's included), not a bool."""
    return isinstance(v, (Real, np.integer, np.floating)) and not isinstance(v, (bool, np.bool_))


def real(v: Any, field: str) -> float:
    """``v`` as a float, when it is one real number (:func:`is_real`); else ``InvalidParameterError`` (``field``)."""
    if not is_real(v):
        raise InvalidParameterError(f"{field} must be a number, got {v!r}", field=field)
    return float(v)


def _all_real(v: Any) -> bool:
    if isinstance(v, np.ndarray):
        return v.dtype.kind in "iuf"
    if isinstance(v, (list, tuple)):
        return all(_all_real(x) for x in v)
    return is_real(v)


def real_array(v: Any, field: str) -> np.ndarray:
    """``v`` (a number, or nested lists / tuples / an array of numbers) as a float array; any element that is not a
    real number (a bool, a string, None) is refused with ``InvalidParameterError`` (``field``). NaN and infinities
    pass (the caller decides)."""
    if not _all_real(v):
        raise InvalidParameterError(f"{field} must be numbers, got {v!r}"[:300], field=field)
    try:
        return np.asarray(v, dtype=float)
    except (TypeError, ValueError):
        raise InvalidParameterError(f"{field} must be numbers of one shape (a rectangular array)", field=field) \
            from None
