"""One dual-triangle tensegrity segment: geometry, springs, torque and stiffness.

Conventions (``shared/spec/conventions.md``): ``c = hypot(a, b)``,
``beta = atan2(a, b)``, spring lengths ``L1 = 2c cos(beta + q/2)`` and
``L2 = 2c cos(beta - q/2)``, energy ``E = k1/2 (L1 - L1_0)^2 + k2/2 (L2 - L2_0)^2``,
spring torque ``M(q) = -dE/dq`` (eq. 1-2), joint stiffness ``K = E''(0)``.
Angles are in radians, lengths in the caller's length unit, stiffnesses in
force per length; torques are then force x length.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import InvalidParameterError

__all__ = ["Segment"]


def _positive(value: Any, field: str) -> float:
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise InvalidParameterError(f"{field} must be a number, got {value!r}", field=field) from None
    if not math.isfinite(x) or x <= 0.0:
        raise InvalidParameterError(f"{field} must be finite and > 0, got {value!r}", field=field)
    return x


def _pair(value: Any, field: str, names: tuple[str, str]) -> tuple[float, float]:
    if isinstance(value, (list, tuple, np.ndarray)):
        if len(value) != 2:
            raise InvalidParameterError(
                f"{field} must be a number or a pair ({names[0]}, {names[1]}), got {len(value)} values",
                field=field,
            )
        return _positive(value[0], f"{field}[0]"), _positive(value[1], f"{field}[1]")
    x = _positive(value, field)
    return x, x


@dataclass(frozen=True, init=False)
class Segment:
    """A dual-triangle segment: two rigid triangles on a passive joint and two springs.

    Parameters
    ----------
    a, b : float
        Triangle half-height and half-length (length units, > 0). The segment is
        ``2 b`` long when straight.
    k : float or (float, float)
        Spring stiffness; one number for both springs or the pair ``(k1, k2)``.
    L0 : float or (float, float)
        Spring rest lengths (the preloads / control inputs); one number or the
        pair ``(L1_0, L2_0)``.

    Raises
    ------
    InvalidParameterError
        (a ``ValueError``) when a value is not finite and positive; ``field``
        names it.
    """

    a: float
    b: float
    k1: float
    k2: float
    L1_0: float
    L2_0: float

    def __init__(self, a: float, b: float, k: float | tuple[float, float] = 1.0,
                 L0: float | tuple[float, float] = 1.0) -> None:
        object.__setattr__(self, "a", _positive(a, "a"))
        object.__setattr__(self, "b", _positive(b, "b"))
        k1, k2 = _pair(k, "k", ("k1", "k2"))
        l1, l2 = _pair(L0, "L0", ("L1_0", "L2_0"))
        object.__setattr__(self, "k1", k1)
        object.__setattr__(self, "k2", k2)
        object.__setattr__(self, "L1_0", l1)
        object.__setattr__(self, "L2_0", l2)

    # ------------------------------------------------------------------ geometry
    @property
    def c(self) -> float:
        """Half-diagonal ``hypot(a, b)``."""
        return math.hypot(self.a, self.b)

    @property
    def beta(self) -> float:
        """Triangle half-angle ``atan2(a, b)`` (rad)."""
        return math.atan2(self.a, self.b)

    @property
    def joint_limit(self) -> float:
        """Physical joint range bound: configurations satisfy ``|q| < pi - 2 beta`` (rad)."""
        return math.pi - 2.0 * self.beta

    @property
    def symmetric(self) -> bool:
        """True when ``k1 == k2`` and ``L1_0 == L2_0`` (straight is then an equilibrium)."""
        return self.k1 == self.k2 and self.L1_0 == self.L2_0

    @property
    def k(self) -> float | tuple[float, float]:
        """Stiffness as given: one number when both springs agree, else the pair."""
        return self.k1 if self.k1 == self.k2 else (self.k1, self.k2)

    @property
    def L0(self) -> float | tuple[float, float]:
        """Rest lengths as given: one number when both springs agree, else the pair."""
        return self.L1_0 if self.L1_0 == self.L2_0 else (self.L1_0, self.L2_0)

    def replace(self, **changes: Any) -> "Segment":
        """A copy with some of ``a``, ``b``, ``k``, ``L0`` changed."""
        args = {"a": self.a, "b": self.b, "k": (self.k1, self.k2), "L0": (self.L1_0, self.L2_0)}
        unknown = set(changes) - set(args)
        if unknown:
            raise InvalidParameterError(f"unknown segment field(s): {sorted(unknown)}", field=sorted(unknown)[0])
        args.update(changes)
        return Segment(**args)

    def to_dict(self) -> dict[str, Any]:
        """JSON-friendly form accepted back by ``Segment(**d)``."""
        k = self.k
        L0 = self.L0
        return {"a": self.a, "b": self.b, "k": list(k) if isinstance(k, tuple) else k,
                "L0": list(L0) if isinstance(L0, tuple) else L0}

    # ------------------------------------------------------------------ springs
    def spring_lengths(self, q: Any) -> tuple[np.ndarray, np.ndarray]:
        """Spring lengths ``(L1, L2)`` at joint angle(s) ``q`` (rad)."""
        q = np.asarray(q, dtype=float)
        return (2.0 * self.c * np.cos(self.beta + q / 2.0), 2.0 * self.c * np.cos(self.beta - q / 2.0))

    def spring_forces(self, q: Any) -> tuple[np.ndarray, np.ndarray]:
        """Spring tensions ``F_i = k_i (L_i - L_i0)`` (force units; > 0 in tension)."""
        L1, L2 = self.spring_lengths(q)
        return self.k1 * (L1 - self.L1_0), self.k2 * (L2 - self.L2_0)

    def energy(self, q: Any) -> np.ndarray:
        """Elastic energy ``k1/2 (L1 - L1_0)^2 + k2/2 (L2 - L2_0)^2``."""
        L1, L2 = self.spring_lengths(q)
        return 0.5 * self.k1 * (L1 - self.L1_0) ** 2 + 0.5 * self.k2 * (L2 - self.L2_0) ** 2

    def torque(self, q: Any) -> np.ndarray:
        """Spring torque ``M(q) = M1 + M2 = -dE/dq`` (eq. 1, general form)."""
        q = np.asarray(q, dtype=float)
        F1, F2 = self.spring_forces(q)
        s1 = np.sin(self.beta + q / 2.0)
        s2 = np.sin(self.beta - q / 2.0)
        return self.c * (F1 * s1 - F2 * s2)

    def dtorque(self, q: Any) -> np.ndarray:
        """Derivative ``M'(q) = -E''(q)``; the segment alone is stable where it is < 0."""
        q = np.asarray(q, dtype=float)
        c = self.c
        F1, F2 = self.spring_forces(q)
        s1, c1 = np.sin(self.beta + q / 2.0), np.cos(self.beta + q / 2.0)
        s2, c2 = np.sin(self.beta - q / 2.0), np.cos(self.beta - q / 2.0)
        return (-self.k1 * c * c * s1 * s1 + 0.5 * c * F1 * c1
                - self.k2 * c * c * s2 * s2 + 0.5 * c * F2 * c2)

    @property
    def stiffness(self) -> float:
        """Joint stiffness ``K = E''(0)``; ``k (b L0 - 2 (b^2 - a^2))`` when symmetric."""
        return float(-self.dtorque(0.0))

    @property
    def condition4(self) -> bool:
        """Condition (4): straight is a stable equilibrium of the unloaded segment, ``K > 0``."""
        return self.stiffness > 0.0

    def monotonic(self, num: int = 2001) -> bool:
        """True when ``M(q)`` decreases over the whole physical range (one equilibrium)."""
        lim = self.joint_limit
        qs = np.linspace(-lim, lim, num)[1:-1]
        return bool(np.all(self.dtorque(qs) < 0.0))
