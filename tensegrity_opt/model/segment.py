"""One dual-triangle tensegrity segment: geometry, springs, torque and stiffness.

Conventions (``docs/model.md``): ``c = hypot(a, b)``,
``beta = atan2(a, b)``, spring lengths ``L1 = 2c cos(beta + q/2)`` and
``L2 = 2c cos(beta - q/2)``, energy ``E = k1/2 (L1 - L1_0)^2 + k2/2 (L2 - L2_0)^2``,
spring torque ``M(q) = -dE/dq`` (eq. 1-2), joint stiffness ``K = E''(0)``.
Angles are in radians, lengths in the caller's length unit, stiffnesses in
force per length; torques are then force x length.

The unloaded segment's critical angles (the zeros of its torque inside the range: wells, hilltops) are
found here once (:meth:`Segment.critical_points`, :meth:`Segment.critical_angles`), for every analysis
that needs them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np

from ..errors import InvalidParameterError, UnsupportedError
from .springs import spring_law

__all__ = ["Segment", "clean_coefficients", "torque_coefficients", "CLEAN_TOL", "MERGE_TOL"]

#: Polynomial coefficients smaller than this relative to the largest one are zero (:func:`clean_coefficients`).
CLEAN_TOL = 1e-14
#: Critical angles of one segment closer than this (rad) are one: below it two zeros of the torque are not
#: resolved in double precision (near a pitchfork, ``K ~ 0``, the zeros spread as ``sqrt(-K)``).
MERGE_TOL = 1e-7
#: Grid points over the range on which the torque's sign changes are looked for (then bisected).
CRITICAL_GRID = 801


def _positive(value: Any, field: str) -> float:
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise InvalidParameterError(f"{field} must be a number, got {value!r}", field=field) from None
    if not math.isfinite(x) or x <= 0.0:
        raise InvalidParameterError(f"{field} must be finite and > 0, got {value!r}", field=field)
    return x


def _nonnegative(value: Any, field: str) -> float:
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise InvalidParameterError(f"{field} must be a number, got {value!r}", field=field) from None
    if not math.isfinite(x) or x < 0.0:
        raise InvalidParameterError(f"{field} must be finite and >= 0, got {value!r}", field=field)
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
    spring : {"linear", "tension_only"}
        The springs' law (:data:`~tensegrity_opt.model.springs.SPRING_LAWS`): ``"linear"`` (the paper's
        model: a spring shorter than its rest length pushes) or ``"tension_only"`` (it goes slack and
        carries nothing: a real extension spring or cable).
    mass : float
        The segment's mass (>= 0, default 0): two equal triangles of ``mass / 2``, their centroids on the chain's
        axis ``2 b / 3`` from the joint, the lower one on the link before the joint, the upper one on the link after
        it (``docs/model.md``, "Masses and modes"). Without gravity it changes no equilibrium; it sets the
        vibration modes (:func:`~tensegrity_opt.modes`).
    inertia : float
        Each triangle's rotational inertia about its centroid (>= 0, default 0; mass x length^2).

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
    spring: str
    mass: float
    inertia: float

    def __init__(self, a: float, b: float, k: float | tuple[float, float] = 1.0,
                 L0: float | tuple[float, float] = 1.0, spring: str = "linear", mass: float = 0.0,
                 inertia: float = 0.0) -> None:
        object.__setattr__(self, "a", _positive(a, "a"))
        object.__setattr__(self, "b", _positive(b, "b"))
        k1, k2 = _pair(k, "k", ("k1", "k2"))
        l1, l2 = _pair(L0, "L0", ("L1_0", "L2_0"))
        object.__setattr__(self, "k1", k1)
        object.__setattr__(self, "k2", k2)
        object.__setattr__(self, "L1_0", l1)
        object.__setattr__(self, "L2_0", l2)
        object.__setattr__(self, "spring", spring_law(spring))
        object.__setattr__(self, "mass", _nonnegative(mass, "mass"))
        object.__setattr__(self, "inertia", _nonnegative(inertia, "inertia"))

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
        """A copy with some of ``a``, ``b``, ``k``, ``L0``, ``spring``, ``mass``, ``inertia`` changed."""
        args = {"a": self.a, "b": self.b, "k": (self.k1, self.k2), "L0": (self.L1_0, self.L2_0),
                "spring": self.spring, "mass": self.mass, "inertia": self.inertia}
        unknown = set(changes) - set(args)
        if unknown:
            raise InvalidParameterError(f"unknown segment field(s): {sorted(unknown)}", field=sorted(unknown)[0])
        args.update(changes)
        return Segment(**args)

    def to_dict(self) -> dict[str, Any]:
        """JSON-friendly form accepted back by ``Segment(**d)`` (``spring``, ``mass``, ``inertia`` only where they
        are not their defaults ``"linear"``, 0, 0)."""
        k = self.k
        L0 = self.L0
        out = {"a": self.a, "b": self.b, "k": list(k) if isinstance(k, tuple) else k,
               "L0": list(L0) if isinstance(L0, tuple) else L0}
        if self.spring != "linear":
            out["spring"] = self.spring
        if self.mass:
            out["mass"] = self.mass
        if self.inertia:
            out["inertia"] = self.inertia
        return out

    @property
    def tension_only(self) -> bool:
        """The springs follow the tension-only law (slack below their rest length)."""
        return self.spring == "tension_only"

    # ------------------------------------------------------------------ springs
    def spring_lengths(self, q: Any) -> tuple[np.ndarray, np.ndarray]:
        """Spring lengths ``(L1, L2)`` at joint angle(s) ``q`` (rad)."""
        q = np.asarray(q, dtype=float)
        return (2.0 * self.c * np.cos(self.beta + q / 2.0), 2.0 * self.c * np.cos(self.beta - q / 2.0))

    def spring_rates(self, q: Any) -> tuple[tuple[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]]:
        """The derivatives of the spring lengths in the joint angle: ``((L1', L2'), (L1'', L2''))`` at ``q``."""
        q = np.asarray(q, dtype=float)
        c, a1, a2 = self.c, self.beta + q / 2.0, self.beta - q / 2.0
        return (-c * np.sin(a1), c * np.sin(a2)), (-0.5 * c * np.cos(a1), -0.5 * c * np.cos(a2))

    def spring_forces(self, q: Any) -> tuple[np.ndarray, np.ndarray]:
        """Spring tensions ``F_i = k_i (L_i - L_i0)`` (force units; > 0 in tension); ``k_i max(0, L_i - L_i0)``
        under the tension-only law."""
        L1, L2 = self.spring_lengths(q)
        s1, s2 = L1 - self.L1_0, L2 - self.L2_0
        if self.tension_only:
            s1, s2 = np.maximum(s1, 0.0), np.maximum(s2, 0.0)
        return self.k1 * s1, self.k2 * s2

    def _taut(self, q: Any) -> tuple[Any, Any]:
        """The factors ``dF_i/dL_i / k_i``: 1 (linear law, or taut), 0 where a tension-only spring is slack."""
        if not self.tension_only:
            return 1.0, 1.0
        L1, L2 = self.spring_lengths(q)
        return (L1 > self.L1_0).astype(float), (L2 > self.L2_0).astype(float)

    def energy(self, q: Any) -> np.ndarray:
        """Elastic energy ``k1/2 (L1 - L1_0)^2 + k2/2 (L2 - L2_0)^2`` (each stretch clipped at 0 under the
        tension-only law)."""
        if self.tension_only:
            F1, F2 = self.spring_forces(q)
            return 0.5 * F1 * F1 / self.k1 + 0.5 * F2 * F2 / self.k2
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
        """Derivative ``M'(q) = -E''(q)``; the segment alone is stable where it is < 0 (under the tension-only law
        the one-sided value on the side where the springs' states hold: a slack spring adds nothing)."""
        q = np.asarray(q, dtype=float)
        c = self.c
        F1, F2 = self.spring_forces(q)
        t1, t2 = self._taut(q)
        s1, c1 = np.sin(self.beta + q / 2.0), np.cos(self.beta + q / 2.0)
        s2, c2 = np.sin(self.beta - q / 2.0), np.cos(self.beta - q / 2.0)
        return (-t1 * self.k1 * c * c * s1 * s1 + 0.5 * c * F1 * c1
                - t2 * self.k2 * c * c * s2 * s2 + 0.5 * c * F2 * c2)

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

    # ------------------------------------------------------------------ unloaded critical angles
    def torque_polynomial(self) -> dict[int, complex]:
        """``E'(q) = -M(q)`` as a Laurent polynomial in ``z = exp(i q/2)``: ``{power: coefficient}``, powers -2..2.

        ``c = cos(q/2) = (z + 1/z)/2``, ``s = sin(q/2) = -i (z - 1/z)/2``;
        ``E' = -k1 (L1 - L10)(b s + a c) + k2 (L2 - L20)(a c - b s)`` with ``L1 = 2 b c - 2 a s``,
        ``L2 = 2 b c + 2 a s``, i.e. ``E' = A c^2 + B s^2 + C c s + D c + Es s``, and
        ``c^2 = (z^2 + 2 + z^-2)/4``, ``s^2 = -(z^2 - 2 + z^-2)/4``, ``c s = -i (z^2 - z^-2)/4``.

        The linear law's torque only: a tension-only segment's torque is piecewise (one polynomial per
        taut / slack pattern), so this refuses it (:class:`UnsupportedError`, ``field="spring"``).
        """
        if self.tension_only:
            raise UnsupportedError("the torque polynomial (and the unloaded critical angles built on it) holds for "
                                   "the linear spring law only; this segment's spring is 'tension_only'",
                                   field="spring", spring="tension_only")
        return torque_coefficients(self.a, self.b, self.k1, self.k2, self.L1_0, self.L2_0)

    def critical_points(self) -> np.ndarray:
        """Every angle inside the open range where the unloaded torque vanishes (``E'(q) = 0``), ascending
        (read only; computed once per segment).

        Two routes, united: the roots of the torque's quartic ``z^2 E'(z) = 0`` on the unit circle (companion
        matrix eigenvalues: every root, also a close pair no grid separates, but ill-conditioned near a
        multiple root) and the sign changes of the torque on a grid of ``CRITICAL_GRID`` points refined by
        bisection (accurate to the last bit for simple roots). Each is polished by up to three Newton steps on
        the torque (kept when they lower ``|M|`` and move it by less than ``1e-6`` rad), then points closer than
        ``MERGE_TOL`` are merged (the one with the least ``|M|`` kept). A symmetric segment's set is made exactly
        symmetric (``0`` and ``+-w``): the mirror images of a mirror-symmetric chain come out exact.
        """
        return self._critical[0]

    def critical_angles(self) -> tuple[np.ndarray, np.ndarray]:
        """The unloaded segment's wells (minima of ``E(q)``) and hilltops (maxima) inside its range, ascending.

        A monotonic segment has one well (``q = 0`` when symmetric, its rest angle when pre-bent) and no
        hilltop; a bistable one (``K < 0``) two wells around a hilltop. The points of :meth:`critical_points`
        classified by the sign of ``E''`` (beyond ``1e-9`` of the torque scale ``max(k1, k2) c^2``), a degenerate
        one (``E'' ~ 0``, a pitchfork) by the torque's sign on either side; an inflection is neither.
        """
        return self._critical[1], self._critical[2]

    @cached_property
    def _critical(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        lim = self.joint_limit
        cand = np.concatenate([self._quartic_roots(), *self._sign_changes()]).astype(float)
        pts: list[tuple[float, float]] = []          # (q, |M(q)|)
        for q0 in cand.tolist():
            x, r = q0, abs(float(self.torque(q0)))
            for _ in range(3):
                d = float(self.dtorque(x))
                if d == 0.0:
                    break
                y = x - float(self.torque(x)) / d
                ry = abs(float(self.torque(y))) if abs(y) < lim else math.inf
                if not ry < r or abs(y - q0) >= 1e-6:
                    break
                x, r = y, ry
            pts.append((x, r))
        pts.sort()
        merged: list[tuple[float, float]] = []
        for x, r in pts:
            if merged and x - merged[-1][0] < MERGE_TOL:
                if r < merged[-1][1]:
                    merged[-1] = (x, r)
            else:
                merged.append((x, r))
        q = np.array([x for x, _ in merged if abs(x) < lim], dtype=float)
        if self.symmetric:                           # M(0) = 0 exactly; the roots pair as +-w
            keep: list[float] = []
            for v in sorted(x for x in np.abs(q).tolist() if x >= MERGE_TOL):
                if not keep or v - keep[-1] >= MERGE_TOL:
                    keep.append(v)
            q = np.concatenate([-np.array(keep[::-1]), [0.0], np.array(keep)])
        q = np.sort(q)
        kind = self._kinds(q)
        out = (q, q[kind > 0], q[kind < 0])
        for a in out:
            a.setflags(write=False)
        return out

    def _kinds(self, q: np.ndarray) -> np.ndarray:
        """``+1`` minimum, ``-1`` maximum, ``0`` inflection at the critical angles ``q`` (ascending)."""
        d2 = -np.asarray(self.dtorque(q), dtype=float).reshape(-1)
        tol = 1e-9 * max(self.k1, self.k2) * self.c ** 2
        kind = np.where(d2 > tol, 1, np.where(d2 < -tol, -1, 0))
        lim = self.joint_limit
        for i in np.flatnonzero(kind == 0).tolist():  # degenerate: the torque's sign on either side
            lo = q[i - 1] if i > 0 else -lim
            hi = q[i + 1] if i + 1 < q.size else lim
            h = min(1e-3 * lim, 0.5 * (q[i] - lo), 0.5 * (hi - q[i]))
            left, right = float(self.torque(q[i] - h)), float(self.torque(q[i] + h))
            kind[i] = 1 if left > 0 > right else (-1 if left < 0 < right else 0)   # M = -E'
        return kind

    def _quartic_roots(self) -> np.ndarray:
        """The angles inside the range of the roots on the unit circle of ``z^2 E'(z) = 0`` (rounded to 13
        decimals, distinct)."""
        c = clean_coefficients(self.torque_polynomial())
        roots = np.roots([c.get(p, 0.0) for p in (2, 1, 0, -1, -2)])      # leading zeros are dropped by np.roots
        roots = roots[np.abs(np.abs(roots) - 1.0) < 1e-8]
        q = 2.0 * np.angle(roots)
        return np.unique(np.round(q[np.abs(q) < self.joint_limit], 13))

    def _sign_changes(self) -> tuple[list[float], list[float]]:
        """The torque's sign changes on the grid, refined by bisection: ``(+ to -, - to +)`` (wells, hilltops)."""
        lim = self.joint_limit
        qs = np.linspace(-lim, lim, CRITICAL_GRID)[1:-1]
        qs = qs + 0.5 * (qs[1] - qs[0]) * (np.abs(qs) < 1e-12)   # no grid point exactly on q = 0 (M(0) = 0 there)
        M = self.torque(qs)
        wells, tops = [], []
        for i in np.flatnonzero((M[:-1] > 0) != (M[1:] > 0)).tolist():
            lo, hi = float(qs[i]), float(qs[i + 1])
            flo = float(M[i])
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                fm = float(self.torque(mid))
                if (fm > 0) == (flo > 0):
                    lo, flo = mid, fm
                else:
                    hi = mid
            (wells if M[i] > 0 else tops).append(0.5 * (lo + hi))    # M = -E': + -> - is a minimum of E
        return _merged(wells), _merged(tops)


def _merged(roots: list[float], tol: float = 1e-9) -> list[float]:
    """The roots with near-duplicates (closer than ``tol``) merged."""
    out: list[float] = []
    for r in sorted(roots):
        if not out or r - out[-1] > tol:
            out.append(r)
    return out


def torque_coefficients(a: float, b: float, k1: float, k2: float, L10: float, L20: float) -> dict[int, complex]:
    """The linear law's ``E'(q)`` of a segment as a Laurent polynomial in ``z = exp(i q/2)`` (powers -2..2): see
    :meth:`Segment.torque_polynomial`. Linear in ``(k1, k2)``: ``k_i = 0`` is the segment with spring ``i`` slack
    (the torque of one taut/slack pattern of the tension-only law)."""
    A = -2.0 * a * b * k1 + 2.0 * a * b * k2
    B = 2.0 * a * b * k1 - 2.0 * a * b * k2
    C = (2.0 * a * a - 2.0 * b * b) * (k1 + k2)
    D = k1 * L10 * a - k2 * L20 * a
    Es = k1 * L10 * b + k2 * L20 * b
    return {2: complex(A / 4 - B / 4 - 1j * C / 4), 0: complex(A / 2 + B / 2),
            -2: complex(A / 4 - B / 4 + 1j * C / 4), 1: complex(D / 2 - 1j * Es / 2),
            -1: complex(D / 2 + 1j * Es / 2)}


def clean_coefficients(poly: dict, tol: float = CLEAN_TOL) -> dict:
    """A polynomial's coefficients (``{exponent: complex}``) with the real and imaginary parts smaller than
    ``tol`` times the largest coefficient set to zero (and the terms left zero dropped): coefficients that
    vanish analytically come out of floating point as roundoff."""
    scale = max(abs(c) for c in poly.values())
    out = {}
    for e, c in poly.items():
        re_ = c.real if abs(c.real) > tol * scale else 0.0
        im_ = c.imag if abs(c.imag) > tol * scale else 0.0
        if re_ or im_:
            out[e] = complex(re_, im_)
    return out
