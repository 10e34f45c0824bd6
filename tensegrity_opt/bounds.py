"""Bounds ``(lo, hi)``: the one reading of a pair of bounds every interface shares.

A pair of bounds is written ``[lo, hi]`` (the canonical form: the library's tuple ``(lo, hi)``, the command
line's ``LO HI``, a JSON array) or ``{"lo": lo, "hi": hi}`` (a JSON object); each side a number or, where the
problem allows it, a list (one value per segment or per spring) or ``None`` (an open side). Every function
taking bounds (``maximize_critical_force``'s ``bounds`` and ``tension``, the preload problems' ``bounds``,
``preloads_for_stiffness``'s ``eig_bounds`` and ``bounds_K``), the sweep spec and the service read them
through :func:`bound_pair`.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from .errors import InvalidParameterError

__all__ = ["BOUND_KEYS", "bound_pair"]

#: The keys of the object form ``{"lo": .., "hi": ..}``.
BOUND_KEYS = ("lo", "hi")


def bound_pair(value: Any, field: str = "bounds") -> tuple[Any, Any]:
    """``(lo, hi)`` of ``value``: ``[lo, hi]``, ``(lo, hi)`` or ``{"lo": lo, "hi": hi}``; the sides unchanged.

    Raises ``InvalidParameterError`` (``field``) for any other shape; the sides' values are the caller's to
    check (a number, a per-segment list, ``None``).
    """
    if isinstance(value, Mapping):
        keys = set(value)
        if keys != set(BOUND_KEYS):
            extra = sorted(str(k) for k in keys - set(BOUND_KEYS))
            missing = [k for k in BOUND_KEYS if k not in keys]
            why = f"unknown key {extra[0]!r}" if extra else f"missing {missing[0]!r}"
            raise InvalidParameterError(f"{field}: {why}; bounds are [lo, hi] or {{\"lo\": lo, \"hi\": hi}}",
                                        field=field)
        return value["lo"], value["hi"]
    if isinstance(value, (str, bytes)) or not hasattr(value, "__len__") or len(value) != 2:
        raise InvalidParameterError(f"{field}: bounds are [lo, hi] or {{\"lo\": lo, \"hi\": hi}}, got {value!r}",
                                    field=field)
    return value[0], value[1]
