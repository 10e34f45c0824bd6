"""The bounds a design presses against: the decision variables at, or within :data:`ACTIVE_TOL` of, a bound at
the optimum (:func:`active_bounds`), one :class:`ActiveBound` each.

A design whose variable sits on its bound is the best *within the bounds*: widening them may change it. The
design results of rest lengths carry them (``StiffnessDesign.active_bounds``, ``PreloadDesign.active_bounds``;
the critical-force ``Design`` lists its own ``active`` strings), and their ``to_dict()`` as ``active_bounds``, a
list of ``{"segment", "variable", "side", "value", "bound"}``.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any, NamedTuple

import numpy as np

__all__ = ["ActiveBound", "active_bounds", "ACTIVE_TOL"]

#: A variable is at its bound when within this fraction of its interval's width ``hi - lo`` of it (a half-open
#: interval: of the bound's size, at least 1): close enough that the bound shapes the design.
ACTIVE_TOL = 1e-2


class ActiveBound(NamedTuple):
    """A decision variable at (or within :data:`ACTIVE_TOL` of) one of its bounds at the optimum."""

    segment: int
    """The segment, 0-based."""
    variable: str
    """The variable's name (``"L1_0"``, ``"L2_0"``, ``"a"``, ``"b"``, ``"k"``, ``"L0"``)."""
    side: str
    """``"lower"`` or ``"upper"``."""
    value: float
    """The variable's value at the optimum."""
    bound: float
    """The bound."""

    def to_dict(self) -> dict[str, Any]:
        """``{"segment", "variable", "side", "value", "bound"}``."""
        return {"segment": int(self.segment), "variable": self.variable, "side": self.side,
                "value": float(self.value), "bound": float(self.bound)}

    def describe(self) -> str:
        """``L1_0[3] = 0.104853 (lower bound 0.1)``."""
        return f"{self.variable}[{self.segment}] = {self.value:.6g} ({self.side} bound {self.bound:.6g})"


def active_bounds(values: Mapping[str, Any], lo: Mapping[str, Any], hi: Mapping[str, Any],
                  names: Iterable[str] | None = None, tol: float = ACTIVE_TOL) -> tuple[ActiveBound, ...]:
    """The active bounds of the variables ``values[name]`` (one value per segment) between ``lo[name]`` and
    ``hi[name]`` (a number or one per segment; infinite: none), for each name of ``names`` (default: every key
    of ``values``), segment by segment in the names' order."""
    out: list[ActiveBound] = []
    for name in (values if names is None else names):
        x = np.atleast_1d(np.asarray(values[name], dtype=float))
        lo_v = np.broadcast_to(np.asarray(lo[name], dtype=float), x.shape)
        hi_v = np.broadcast_to(np.asarray(hi[name], dtype=float), x.shape)
        for i, (v, a, b) in enumerate(zip(x, lo_v, hi_v)):
            if np.isfinite(a) and np.isfinite(b):
                width = tol * (b - a)
                near_lo, near_hi = v - a <= width, b - v <= width
            else:
                near_lo = bool(np.isfinite(a)) and v - a <= tol * max(1.0, abs(a))
                near_hi = bool(np.isfinite(b)) and b - v <= tol * max(1.0, abs(b))
            if near_lo and (not near_hi or v - a <= b - v):
                out.append(ActiveBound(i, name, "lower", float(v), float(a)))
            elif near_hi:
                out.append(ActiveBound(i, name, "upper", float(v), float(b)))
    return tuple(out)
