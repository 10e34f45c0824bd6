"""Interval certificates of equilibria: Krawczyk's test in ball arithmetic (Arb, through python-flint).

A homotopy (:mod:`.homotopy`) finds every complex root in floating point; this module *proves*, for each
equilibrium it returns, that an exact real equilibrium lies in a small box around it, that it is the only one
in that box, that the box lies strictly inside the physical range ``|q_j| < pi - 2 beta_j``, that the boxes of
different equilibria are pairwise disjoint (so the equilibria are distinct), and, where it can be decided, the
Morse index of the exact equilibrium. Everything that is claimed is computed in ball arithmetic (Arb's
``arb`` / ``arb_mat``: every operation returns a ball certainly containing the exact result), from the model's
formulas in the real unknowns; the floating-point numbers only choose *what* to test.

The systems
-----------
Displacement control (the tip held at ``target``): unknowns ``x = (q_1..q_n, Fx, Fy)``,

``f(x) = [grad E(q) - J(q)^T F ; tip(q) - target]`` (``n + 2`` equations).

Force control (the dead tip load ``F`` given): unknowns ``x = q``, ``f(q) = grad E(q) - J(q)^T F``.

Per joint ``L1 = 2 (b cos(q/2) - a sin(q/2))``, ``L2 = 2 (b cos(q/2) + a sin(q/2))`` (``= 2c cos(beta -+ q/2)``,
:mod:`tensegrity_opt.model.segment`), ``E_j = k1/2 (L1 - L1_0)^2 + k2/2 (L2 - L2_0)^2``; absolute angles
``phi_j = q_1 + ... + q_j``, links ``l_j`` (:attr:`Manipulator.link_lengths`), tip
``(b_1 + sum l_j cos phi_j, sum l_j sin phi_j)``.

Krawczyk's test
---------------
For a box ``X = x~ +- r`` (``x~`` the equilibrium refined by a few float Newton steps, ``r`` a small radius),
``Y`` a float approximate inverse of ``f'(x~)`` and ``f'(X)`` the interval Jacobian over the box,

``K(X) = x~ - Y f(x~) + (I - Y f'(X)) (X - x~)``.

If ``K(X)`` lies in the interior of ``X``, ``f`` has exactly one zero in ``X`` (Krawczyk 1969, Moore 1977) -
it also proves ``Y`` and every matrix of ``f'(X)`` nonsingular - and the zero is real because ``X`` is a real
box. A singular (degenerate) equilibrium never passes: there ``I - Y f'(X)`` cannot be contracting.

The Morse index
---------------
By Sylvester's law of inertia the inertia of a symmetric matrix ``B`` is that of ``C = V^T B V`` for any
nonsingular ``V``. ``V`` is the float eigenvector matrix of the midpoint of ``B(X)`` (proven nonsingular:
``||I - V^T V||_inf < 1`` in ball arithmetic), ``C`` is computed in ball arithmetic over the whole box, and
Gershgorin's discs of ``C`` decide the signs of its eigenvalues when every disc excludes 0 (the discs left of 0
then hold exactly as many eigenvalues as there are of them). Force control: ``B = H_L``, the Hessian of
``E - F . tip``; displacement control: the bordered Hessian ``B = [[H_L, J^T], [J, 0]]``, whose inertia is that of
the reduced Hessian ``Z^T H_L Z`` plus ``(2, 2)`` (``J`` has full rank where ``B`` is nonsingular). The index is
constant over the box, in particular at the exact equilibrium; the reduced Hessian is nonsingular there, so
"stable" (index 0) is proven too. Where a disc touches 0 (a near-degenerate equilibrium) the index is not
proven: :attr:`RootBox.morse_proven` is false and the caller's floating-point index stands.

Non-real roots
--------------
The homotopy classes a complex root real by its distance from the real set against a tolerance (floating point).
:func:`prove_nonreal` proves a root classed non-real is not real: the same equations continued to complex
``(q, F)`` (the homotopy's polynomial system is their image under ``z_j = exp(i q_j / 2)``, ``g, h = Fx +- i Fy``),
Krawczyk's test in complex ball arithmetic (Arb's ``acb``) on a box around it whose imaginary parts exclude 0: a
root exists in the box, and no point of the box is real. The certificate runs it on the roots within
:data:`NEAR_REAL` of the real set (the only ones a floating-point error could misclass; ~1 ms a root); the
farther ones are non-real in floating point, by that margin.

The real roots the homotopy puts just beyond the joint range (by less than :data:`NEAR_REAL` rad) are proven
beyond it the same way: Krawczyk's test, the box beyond a joint limit.

What it does not prove
----------------------
That the homotopy found every root (that is the path tracking's claim, :mod:`.homotopy`); the roots farther from
the real set or from the range than :data:`NEAR_REAL` are classed in floating point.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from ..model.manipulator import Manipulator
from ..outcome import Outcome, freeze

__all__ = ["RootBox", "IntervalCertificate", "prove_equilibria", "prove_root", "krawczyk_test", "certificate",
           "prove_nonreal", "homotopy_unknowns", "METHOD", "RADII"]

#: The method's name as the results state it.
METHOD = "krawczyk (arb)"
#: Box half-widths tried in turn (relative: radians for ``q``, the chain's force scale for ``F``); the first
#: that passes is kept. Below ~1e-12 the rounding of ``f(x~)`` dominates, above ~1e-6 the interval Jacobian
#: spreads: 1e-9 passes at every regular equilibrium met; the others serve ill-conditioned ones.
RADII = (1e-9, 1e-11, 1e-7, 1e-5)
#: Float Newton steps refining the point before the test (kept only while the residual decreases).
NEWTON_STEPS = 3
#: The homotopy's roots classed non-real whose imaginary parts (``|Im q_j| / 2`` ~ ``| |z_j| - 1 |``, ``|Im F|``
#: over the force scale) are all below this are proven non-real (:func:`prove_nonreal`, ~1 ms a root); those above
#: ``NONREAL_FLOOR`` only (below it the homotopy classes a root real). Measured on n = 3 oracle chains: the
#: non-real roots lie 0.04-1 from the real set, the real ones within 1e-14.
NEAR_REAL = 0.1
NONREAL_FLOOR = 1e-6


def _arb():
    try:
        import flint
    except ImportError as exc:            # a core dependency: this only happens in a broken install
        raise ImportError("the interval certificates need python-flint (pip install python-flint)") from exc
    return flint


# ----------------------------------------------------------------------------- the model in any arithmetic
def _system(m: Manipulator, q: list, F: list, sin, cos, half, two, quarter):
    """``(grad_L, H_L, J, tip)`` at ``q`` (list of n scalars) and ``F`` (2 scalars) in the arithmetic of the
    scalars (python floats, or ``arb`` balls with ``sin``/``cos`` their functions): the gradient of the
    Lagrangian ``E - F . tip`` (n), its Hessian (n x n lists), the tip Jacobian (2 x n) and the tip (2)."""
    n = m.n
    a, b, k1, k2, L10, L20 = (m.a.tolist(), m.b.tolist(), m.k1.tolist(), m.k2.tolist(), m.L1_0.tolist(),
                              m.L2_0.tolist())
    # the link lengths b_j + b_{j+1} summed in the scalars' arithmetic (a float sum may round): half * two is an
    # exact 1 of that arithmetic
    one = half * two
    links = [one * b[j] + one * b[j + 1] for j in range(n - 1)] + [one * b[-1]]
    Fx, Fy = F
    g, h = [], []
    for j in range(n):
        s, c = sin(q[j] * half), cos(q[j] * half)
        L1 = two * (b[j] * c - a[j] * s)
        L2 = two * (b[j] * c + a[j] * s)
        d1 = -(b[j] * s + a[j] * c)           # dL1/dq
        d2 = a[j] * c - b[j] * s              # dL2/dq
        e1 = k1[j] * (L1 - L10[j])
        e2 = k2[j] * (L2 - L20[j])
        g.append(e1 * d1 + e2 * d2)
        # d2L/dq2 = -L/4
        h.append(k1[j] * d1 * d1 + k2[j] * d2 * d2 - (e1 * L1 + e2 * L2) * quarter)
    phi = q[0]
    lc, ls = [], []
    for j in range(n):
        if j:
            phi = phi + q[j]
        lc.append(links[j] * cos(phi))
        ls.append(links[j] * sin(phi))
    SC, SS = [None] * n, [None] * n           # suffix sums over the links j >= i
    accc, accs = lc[-1], ls[-1]
    SC[-1], SS[-1] = accc, accs
    for i in range(n - 2, -1, -1):
        accc = accc + lc[i]
        accs = accs + ls[i]
        SC[i], SS[i] = accc, accs
    J = [[-v for v in SS], list(SC)]
    grad = [g[i] + Fx * SS[i] - Fy * SC[i] for i in range(n)]
    H = [[None] * n for _ in range(n)]
    for i in range(n):
        for k in range(i, n):
            v = Fx * SC[k] + Fy * SS[k]      # - Fx d2x/dq_i dq_k - Fy d2y/dq_i dq_k, k >= i
            if k == i:
                v = v + h[i]
            H[i][k] = H[k][i] = v
    tip = [m.base_length + SC[0], SS[0]]
    return grad, H, J, tip


def _residual_and_jacobian(m: Manipulator, x: list, target, force, sin, cos, half, two, quarter):
    """``(f, f')`` of the displacement system (``target`` given; ``x = (q, Fx, Fy)``) or the force system
    (``force`` given; ``x = q``), as lists, in the scalars' arithmetic."""
    n = m.n
    if target is not None:
        q, F = x[:n], x[n:]
    else:
        q, F = x, list(force)
    grad, H, J, tip = _system(m, q, F, sin, cos, half, two, quarter)
    if target is None:
        return grad, H
    f = grad + [tip[0] - target[0], tip[1] - target[1]]
    fp = [H[i] + [-J[0][i], -J[1][i]] for i in range(n)]
    fp += [J[0] + [0.0 * J[0][0], 0.0 * J[0][0]], J[1] + [0.0 * J[0][0], 0.0 * J[0][0]]]
    return f, fp


def _float_system(m: Manipulator, x: np.ndarray, target, force) -> tuple[np.ndarray, np.ndarray]:
    f, fp = _residual_and_jacobian(m, x.tolist(), target, force, math.sin, math.cos, 0.5, 2.0, 0.25)
    return np.array(f, dtype=float), np.array(fp, dtype=float)


# ----------------------------------------------------------------------------- results
@dataclass(frozen=True)
class RootBox:
    """The interval proof about one equilibrium.

    Attributes
    ----------
    lower, upper : ndarray (d,)
        The box (``d = n + 2``: ``q`` then ``(Fx, Fy)`` under displacement control; ``d = n``: ``q`` under force
        control), its bounds rounded outward to floats.
    proven : bool
        Krawczyk's test passed: exactly one real equilibrium in the box, the box strictly inside the physical
        range, and disjoint from every other box of the certificate.
    morse_index : int or None
        The Morse index proven over the box (``None`` when not proven).
    morse_proven : bool
        The Morse index is proven (every Gershgorin disc decided); when false the equilibrium's own
        (floating-point) index stands.
    reason : str
        Why not proven (``""`` when proven): ``"krawczyk"`` (the test did not contract at any radius; a singular
        or ill-conditioned equilibrium), ``"singular"`` (the float Jacobian could not be inverted), ``"range"``
        (the box straddles a joint limit), ``"outside"`` (the box lies beyond a joint limit: a real root of the
        equations, proven not a configuration), ``"overlap"`` (the box meets another), ``"moved"`` (Newton's
        refinement left the neighbourhood of the given point).
    """

    lower: np.ndarray
    upper: np.ndarray
    proven: bool
    morse_index: int | None
    morse_proven: bool
    reason: str = ""

    def __post_init__(self) -> None:
        freeze(self)

    def contains(self, x: Any) -> bool:
        """True when the point ``x`` (``q``, or ``(q, Fx, Fy)``) lies in the closed box."""
        x = np.asarray(x, dtype=float)
        return bool(np.all(self.lower <= x) and np.all(x <= self.upper))

    def to_dict(self) -> dict[str, Any]:
        """``{"lower", "upper", "proven", "morse_index", "morse_proven", "reason"}``."""
        return {"lower": self.lower.tolist(), "upper": self.upper.tolist(), "proven": bool(self.proven),
                "morse_index": None if self.morse_index is None else int(self.morse_index),
                "morse_proven": bool(self.morse_proven), "reason": self.reason}


@dataclass(frozen=True)
class IntervalCertificate(Outcome):
    """Which proofs a set of equilibria carries: one :class:`RootBox` per equilibrium, in the set's order.

    Attributes
    ----------
    status : str
        :attr:`STATUSES`: ``proven`` (every equilibrium and its Morse index), ``roots_proven`` (every
        equilibrium; some Morse indices are floating-point), ``not_proven`` (some equilibrium is not).
    message : str
        The same in a sentence, with the counts.
    method : str
        ``"krawczyk (arb)"``.
    control : str
        ``"displacement"`` (unknowns ``q, Fx, Fy``) or ``"force"`` (unknowns ``q``).
    paths : int
        Homotopy paths whose end points the equilibria are (0 when not from a homotopy).
    boxes : tuple of RootBox
    seconds : float
        Wall time of the proofs.
    nonreal_checked, nonreal_proven : int
        The homotopy's roots classed non-real yet near the real set (within :data:`NEAR_REAL`), and how many of
        them :func:`prove_nonreal` proved non-real (the others' split is floating-point; the roots farther from
        the real set are non-real in floating point, by that margin).
    outside_checked, outside_proven : int
        The homotopy's real roots beyond the joint range by less than :data:`NEAR_REAL` (rad), and how many of
        them are proven beyond it (a box with exactly one root, beyond a joint limit; :attr:`RootBox.reason`
        ``"outside"``).
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "proven": "every equilibrium proven by Krawczyk's test in ball arithmetic (exactly one real equilibrium in "
                  "its box, the box inside the joint range, the boxes pairwise disjoint) and every Morse index "
                  "proven over its box",
        "roots_proven": "every equilibrium proven as for 'proven'; the Morse index of some (near-degenerate) is "
                        "floating-point",
        "not_proven": "some equilibrium was not proven (singular, ill-conditioned, against the range limit, or "
                      "its box meets another): the boxes say which",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"proven", "roots_proven"})

    status: str
    message: str
    control: str
    boxes: tuple[RootBox, ...]
    paths: int = 0
    seconds: float = 0.0
    method: str = METHOD
    nonreal_checked: int = 0
    nonreal_proven: int = 0
    outside_checked: int = 0
    outside_proven: int = 0

    def __post_init__(self) -> None:
        object.__setattr__(self, "boxes", tuple(self.boxes))
        freeze(self)

    def select(self, keep) -> "IntervalCertificate":
        """The certificate of the boxes at the indices ``keep`` (e.g. the stable members of a set), restated."""
        return certificate([self.boxes[i] for i in keep], self.control, paths=self.paths, seconds=self.seconds,
                           nonreal=(self.nonreal_checked, self.nonreal_proven),
                           outside=(self.outside_checked, self.outside_proven))

    @property
    def roots_proven(self) -> bool:
        """Every equilibrium proven (unique in its box, real, inside the range, boxes pairwise disjoint)."""
        return all(b.proven for b in self.boxes)

    @property
    def morse_proven(self) -> bool:
        """Every equilibrium's Morse index proven."""
        return all(b.morse_proven for b in self.boxes)

    def to_dict(self) -> dict[str, Any]:
        """JSON form: ``success``, ``status``, ``message``, ``method``, ``control``, ``paths``, ``roots_proven``,
        ``morse_proven``, ``nonreal_checked``, ``nonreal_proven``, ``outside_checked``, ``outside_proven``,
        ``seconds``, ``boxes`` (each
        :meth:`RootBox.to_dict`)."""
        return {**self.outcome(), "method": self.method, "control": self.control, "paths": int(self.paths),
                "roots_proven": self.roots_proven, "morse_proven": self.morse_proven,
                "nonreal_checked": int(self.nonreal_checked), "nonreal_proven": int(self.nonreal_proven),
                "outside_checked": int(self.outside_checked), "outside_proven": int(self.outside_proven),
                "seconds": float(self.seconds), "boxes": [b.to_dict() for b in self.boxes]}


# ----------------------------------------------------------------------------- the proofs
def _refine(m: Manipulator, x0: np.ndarray, target, force) -> np.ndarray:
    """A few float Newton steps from ``x0``, each kept only when it lowers the residual."""
    x = x0.copy()
    f, fp = _float_system(m, x, target, force)
    r = float(np.max(np.abs(f)))
    for _ in range(NEWTON_STEPS):
        if r == 0.0:
            break
        try:
            step = np.linalg.solve(fp, f)
        except np.linalg.LinAlgError:
            break
        y = x - step
        if not np.all(np.isfinite(y)):
            break
        fy, fpy = _float_system(m, y, target, force)
        ry = float(np.max(np.abs(fy)))
        if not ry < r:
            break
        x, f, fp, r = y, fy, fpy, ry
    return x


def _outward(mid: np.ndarray, rad: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Float bounds certainly enclosing ``[mid - rad, mid + rad]`` (each rounded once, then one ulp out)."""
    return np.nextafter(mid - rad, -np.inf), np.nextafter(mid + rad, np.inf)


def _morse(flint, B) -> int | None:
    """The number of negative eigenvalues of every symmetric matrix in the interval matrix ``B`` (an
    ``arb_mat``), or ``None`` when Gershgorin's discs of ``V^T B V`` do not decide it."""
    d = B.nrows()
    mid = np.array([[float(B[i, j].mid()) for j in range(d)] for i in range(d)])
    mid = 0.5 * (mid + mid.T)
    try:
        _, V = np.linalg.eigh(mid)
    except np.linalg.LinAlgError:
        return None
    if not np.all(np.isfinite(V)):
        return None
    Va = flint.arb_mat(V.tolist())
    Vt = Va.transpose()
    # V nonsingular: ||I - V^T V||_inf < 1
    G = Vt * Va
    one = flint.arb(1)
    for i in range(d):
        row = flint.arb(0)
        for j in range(d):
            row += abs((one if i == j else 0) - G[i, j])
        if not row < one:
            return None
    C = Vt * B * Va
    neg = 0
    for i in range(d):
        R = flint.arb(0)
        for j in range(d):
            if j != i:
                R += abs(C[i, j])
        c = C[i, i]
        if c + R < 0:
            neg += 1
        elif not c - R > 0:
            return None
    return neg


class _Ball:
    """The ball-arithmetic pieces of one problem: the chain's constants as balls, ``f`` at a point and ``f'`` over a
    box."""

    def __init__(self, m: Manipulator, target, force) -> None:
        if (target is None) == (force is None):
            raise ValueError("give exactly one of target (displacement control) and force (force control)")
        self.flint = flint = _arb()
        arb = flint.arb
        self.m, self.target, self.force = m, target, force
        self.d = m.n + 2 if target is not None else m.n
        self.tgt = None if target is None else [arb(float(v)) for v in target]
        self.frc = None if force is None else [arb(float(v)) for v in force]
        self.consts = (lambda v: v.sin(), lambda v: v.cos(), arb(0.5), arb(2), arb(0.25))
        self.limits = [arb.pi() - 2 * (arb(a) / arb(b)).atan() for a, b in zip(m.a.tolist(), m.b.tolist())]
        self.eye = flint.arb_mat(self.d, self.d, [1 if i == j else 0 for i in range(self.d) for j in range(self.d)])

    def system(self, x: list):
        return _residual_and_jacobian(self.m, x, self.tgt, self.frc, *self.consts)

    def krawczyk(self, xt: np.ndarray, rad: np.ndarray, Y: np.ndarray | None = None):
        """Krawczyk's test on the box ``xt +- rad``: ``(passed, X, f'(X) as lists)``; ``Y`` defaults to the float
        inverse of ``f'(xt)`` (``None`` returned for ``X`` when it cannot be formed)."""
        arb, arb_mat = self.flint.arb, self.flint.arb_mat
        d = self.d
        if Y is None:
            _, fp0 = _float_system(self.m, xt, self.target, self.force)
            try:
                Y = np.linalg.inv(fp0)
            except np.linalg.LinAlgError:
                return False, None, None
        if not np.all(np.isfinite(Y)):
            return False, None, None
        xa = [arb(float(v)) for v in xt]
        f, _ = self.system(xa)
        Ya = arb_mat(Y.tolist())
        X = [arb(float(xt[i]), float(rad[i])) for i in range(d)]
        _, fpX = self.system(X)
        dX = arb_mat(d, 1, [X[i] - xa[i] for i in range(d)])
        K = Ya * arb_mat(d, 1, f) * (-1) + (self.eye - Ya * arb_mat(fpX)) * dX
        return all(X[i].contains_interior(xa[i] + K[i, 0]) for i in range(d)), X, fpX


def krawczyk_test(m: Manipulator, center: Any, radius: Any, *, target=None, force=None) -> bool:
    """Krawczyk's test alone on the box ``center +- radius`` (``(q, Fx, Fy)`` with ``target``, ``q`` with
    ``force``; ``radius`` a number or one per unknown): True proves exactly one zero of the equilibrium
    equations in the box (no range check, no refinement)."""
    ball = _Ball(m, target, force)
    xt = np.asarray(center, dtype=float).reshape(-1)
    rad = np.broadcast_to(np.asarray(radius, dtype=float), xt.shape)
    return ball.krawczyk(xt, rad)[0]


def prove_root(m: Manipulator, x: Any, *, target=None, force=None, radii=RADII
               ) -> tuple[bool, np.ndarray, np.ndarray, int | None, str]:
    """Krawczyk's test about one equilibrium ``x`` (``(q, Fx, Fy)`` with ``target``, or ``q`` with ``force``).

    ``x`` is refined by a few float Newton steps (``x~``; more than ``1e-6`` away from ``x``, relative: not
    proven, ``"moved"``), then the boxes ``x~ +- r`` are tried for ``r`` in ``radii`` (relative: rad for ``q``,
    the chain's force scale for ``F``; at least four Newton steps and twice the refinement's move).

    Returns ``(proven, lower, upper, morse_index, reason)``: ``proven`` when some box passes Krawczyk's test,
    holds ``x`` itself and lies strictly inside the joint range; the box's float bounds (outward; the last box
    tried when none passed); the Morse index proven over the box (``None`` when not decided or not proven);
    ``reason`` as :attr:`RootBox.reason` (without ``"overlap"``, which needs the other boxes). Exactly one of
    ``target`` and ``force`` must be given."""
    ball = _Ball(m, target, force)
    n, d = m.n, ball.d
    x0 = np.asarray(x, dtype=float).reshape(-1)
    if x0.shape != (d,):
        raise ValueError(f"the point must have {d} entries, got {x0.shape}")
    scale = np.ones(d)
    scale[n:] = float(m.torque_scale / float(m.b.sum()))
    lower, upper = _outward(x0, np.zeros(d))
    if not np.all(np.isfinite(x0)):
        return False, lower, upper, None, "singular"
    xt = _refine(m, x0, target, force)
    moved = np.abs(xt - x0) / scale
    if float(moved.max()) > 1e-6:
        return False, lower, upper, None, "moved"
    f0, fp0 = _float_system(m, xt, target, force)
    try:
        Y = np.linalg.inv(fp0)
    except np.linalg.LinAlgError:
        return False, lower, upper, None, "singular"
    if not np.all(np.isfinite(Y)):
        return False, lower, upper, None, "singular"
    step = np.abs(Y @ f0) / scale
    reason = "krawczyk"
    for rel in radii:
        rad = max(rel, 4.0 * float(step.max()), 2.0 * float(moved.max())) * scale
        ok, X, fpX = ball.krawczyk(xt, rad, Y)
        lower, upper = _outward(xt, np.array([float(v.rad()) for v in X]))
        if not ok:
            continue
        if not (np.all(lower <= x0) and np.all(x0 <= upper)):
            reason = "moved"
            continue
        if not all((X[j] < ball.limits[j]) and (X[j] > -ball.limits[j]) for j in range(n)):
            beyond = any((X[j] > ball.limits[j]) or (X[j] < -ball.limits[j]) for j in range(n))
            return False, lower, upper, None, "outside" if beyond else "range"
        # the Morse index over the box: the bordered Hessian (displacement) or the Hessian (force)
        flint = ball.flint
        if target is not None:
            B = flint.arb_mat([[fpX[i][j] if j < n or i >= n else -fpX[i][j] for j in range(d)] for i in range(d)])
            neg = _morse(flint, B)
            morse = None if neg is None or neg < 2 else neg - 2
        else:
            morse = _morse(flint, flint.arb_mat(fpX))
        return True, lower, upper, morse, ""
    return False, lower, upper, None, reason


# ----------------------------------------------------------------------------- non-real roots
def homotopy_unknowns(m: Manipulator, roots: Any, *, displacement: bool = True) -> np.ndarray:
    """The homotopy's roots (rows ``z_1..z_n, g, h``, or ``z_1..z_n`` under force control) in the real problem's
    unknowns continued to complex values: ``q_j = -2i log z_j`` (principal branch: ``Re q_j = 2 arg z_j``),
    ``Fx = (g + h)/2``, ``Fy = (g - h)/(2i)``. A root is real exactly when these are."""
    R = np.asarray(roots, dtype=complex).reshape(-1, m.n + 2 if displacement else m.n)
    q = -2j * np.log(R[:, :m.n])
    if not displacement:
        return q
    g, h = R[:, m.n], R[:, m.n + 1]
    return np.column_stack([q, 0.5 * (g + h), (g - h) / 2j])


def prove_nonreal(m: Manipulator, x: Any, *, target=None, force=None, radii=(1e-9, 1e-11, 1e-7)) -> bool:
    """True proves that a root of the equilibrium equations continued to complex unknowns lies in a small
    complex box around ``x`` (:func:`homotopy_unknowns` of a homotopy root) and that the box holds no real point:
    the root is not a real equilibrium. Krawczyk's test in complex ball arithmetic (Arb's ``acb``) on the same
    equations as :func:`prove_root`, whose analytic continuation in ``(q, F)`` the homotopy's polynomial system is
    (``z_j = exp(i q_j / 2)``); a box meets no real point when some unknown's imaginary part excludes 0."""
    import cmath

    ball = _Ball(m, target, force)
    acb, arb, acb_mat = ball.flint.acb, ball.flint.arb, ball.flint.acb_mat
    d = ball.d
    xt = np.asarray(x, dtype=complex).reshape(-1)
    if xt.shape != (d,) or not np.all(np.isfinite(xt)):
        return False

    def fsys(v):
        f, fp = _residual_and_jacobian(m, v.tolist(), target, force, cmath.sin, cmath.cos, 0.5, 2.0, 0.25)
        return np.array(f, dtype=complex), np.array(fp, dtype=complex)

    f0, fp0 = fsys(xt)
    for _ in range(NEWTON_STEPS):             # refine (kept while the residual drops)
        try:
            y = xt - np.linalg.solve(fp0, f0)
        except np.linalg.LinAlgError:
            return False
        fy, fpy = fsys(y)
        if not np.all(np.isfinite(fy)) or not np.max(np.abs(fy)) < np.max(np.abs(f0)):
            break
        xt, f0, fp0 = y, fy, fpy
    try:
        Y = np.linalg.inv(fp0)
    except np.linalg.LinAlgError:
        return False
    if not np.all(np.isfinite(Y)):
        return False
    scale = np.ones(d)
    scale[m.n:] = float(m.torque_scale / float(m.b.sum()))
    step = float(np.max(np.abs(Y @ f0) / scale))
    tgt = None if target is None else [acb(float(v)) for v in target]
    frc = None if force is None else [acb(float(v)) for v in force]
    consts = (lambda v: v.sin(), lambda v: v.cos(), acb(0.5), acb(2), acb(0.25))
    xa = [acb(complex(v)) for v in xt]
    f, _ = _residual_and_jacobian(m, xa, tgt, frc, *consts)
    Ya = acb_mat(Y.tolist())
    Yf = Ya * acb_mat(d, 1, f)
    eye = acb_mat(d, d, [1 if i == j else 0 for i in range(d) for j in range(d)])
    for rel in radii:
        rad = max(rel, 4.0 * step) * scale
        X = [acb(arb(xt[i].real, rad[i]), arb(xt[i].imag, rad[i])) for i in range(d)]
        if not any(X[i].imag > 0 or X[i].imag < 0 for i in range(d)):
            return False                          # the box meets the real set: nothing to prove at this size
        _, fpX = _residual_and_jacobian(m, X, tgt, frc, *consts)
        dX = acb_mat(d, 1, [X[i] - xa[i] for i in range(d)])
        K = Yf * (-1) + (eye - Ya * acb_mat(fpX)) * dX
        if all(X[i].contains_interior(xa[i] + K[i, 0]) for i in range(d)):
            return True
    return False


def _overlapping(lower: np.ndarray, upper: np.ndarray) -> np.ndarray:
    """Rows whose closed box meets another row's."""
    k = lower.shape[0]
    hit = np.zeros(k, dtype=bool)
    for i in range(k - 1):
        meet = np.all((lower[i + 1:] <= upper[i]) & (lower[i] <= upper[i + 1:]), axis=1)
        if meet.any():
            hit[i] = True
            hit[i + 1:][meet] = True
    return hit


def prove_equilibria(m: Manipulator, q: Any, force: Any, *, target=None, control: str = "displacement",
                     paths: int = 0, float_morse: Any = None, roots: Any = None) -> IntervalCertificate:
    """The :class:`IntervalCertificate` of the equilibria ``q`` (k, n) with tip forces ``force`` (k, 2).

    Parameters
    ----------
    m : Manipulator
    q, force : array_like (k, n), (k, 2)
        The equilibria, in the order the certificate's boxes follow (under force control ``force`` may hold one
        row more: the load, also where there is no equilibrium).
    target : array_like (2,), optional
        The tip position (displacement control; required there).
    control : {"displacement", "force"}
        Displacement control proves ``(q, F)`` against ``target``; force control proves ``q`` under the given
        load (every row of ``force`` the same load).
    paths : int
        Homotopy paths behind the equilibria (reported).
    float_morse : array_like (k,) of int, optional
        The equilibria's floating-point Morse indices: a proven index that differs from it is reported and that
        box counts as not Morse-proven (the float classification it is set against is then wrong).
    roots : array_like, optional
        Every finite root of the homotopy (rows ``z_1..z_n, g, h``, or ``z_1..z_n`` under force control): those
        classed non-real but within :data:`NEAR_REAL` of the real set are proven non-real
        (:func:`prove_nonreal`; counted in ``nonreal_checked``, ``nonreal_proven``).

    Returns
    -------
    IntervalCertificate
    """
    if control not in ("displacement", "force"):
        raise ValueError(f"control must be 'displacement' or 'force', got {control!r}")
    if control == "displacement" and target is None:
        raise ValueError("displacement control needs the target")
    t0 = time.perf_counter()
    Q = np.asarray(q, dtype=float).reshape(-1, m.n)
    Fs = np.asarray(force, dtype=float).reshape(-1, 2)
    proofs = []
    for i in range(Q.shape[0]):
        if control == "displacement":
            proofs.append(prove_root(m, np.concatenate([Q[i], Fs[i]]), target=target))
        else:
            proofs.append(prove_root(m, Q[i], force=Fs[i]))
    d = m.n + 2 if control == "displacement" else m.n
    lower = np.array([p[1] for p in proofs], dtype=float).reshape(-1, d)
    upper = np.array([p[2] for p in proofs], dtype=float).reshape(-1, d)
    overlap = _overlapping(lower, upper)
    boxes = []
    for i, (ok, lo, hi, morse, reason) in enumerate(proofs):
        if ok and overlap[i]:
            ok, reason = False, "overlap"
        morse_ok = ok and morse is not None
        if morse_ok and float_morse is not None and int(float_morse[i]) != morse:
            morse_ok = False            # the proven index stays in the box; the float one it contradicts is wrong
        boxes.append(RootBox(lo, hi, ok, morse if ok else None, morse_ok, reason))
    checked = proven = out_checked = out_proven = 0
    if roots is not None and len(roots):
        disp = control == "displacement"
        X = homotopy_unknowns(m, roots, displacement=disp)
        scale = np.ones(X.shape[1])
        scale[m.n:] = float(m.torque_scale / float(m.b.sum()))
        im = np.max(np.abs(X.imag) / scale * np.r_[0.5 * np.ones(m.n), np.ones(X.shape[1] - m.n)], axis=1)
        for x in X[(im > NONREAL_FLOOR) & (im < NEAR_REAL)]:
            checked += 1
            proven += prove_nonreal(m, x, target=target if disp else None, force=None if disp else Fs[0])
        # the real roots the homotopy put beyond the range, near it: proven beyond it
        R = X[im <= NONREAL_FLOOR].real
        excess = np.max(np.abs(R[:, :m.n]) - m.joint_limits, axis=1) if len(R) else np.zeros(0)
        for x in R[(excess >= -NONREAL_FLOOR) & (excess < NEAR_REAL)]:
            out_checked += 1
            out_proven += prove_root(m, x, target=target if disp else None,
                                     force=None if disp else Fs[0])[4] == "outside"
    return certificate(boxes, control, paths=paths, seconds=time.perf_counter() - t0, nonreal=(checked, proven),
                       outside=(out_checked, out_proven))


def certificate(boxes, control: str, *, paths: int = 0, seconds: float = 0.0,
                nonreal: tuple[int, int] = (0, 0), outside: tuple[int, int] = (0, 0)) -> IntervalCertificate:
    """The :class:`IntervalCertificate` of the proofs ``boxes`` (status and message from them): how
    :func:`prove_equilibria` ends, and how a subset of its boxes (the stable equilibria of a set) is restated."""
    boxes = list(boxes)
    k = len(boxes)
    roots = sum(b.proven for b in boxes)
    morses = sum(b.morse_proven for b in boxes)
    mismatch = sum(b.proven and b.morse_index is not None and not b.morse_proven for b in boxes)
    status = "not_proven" if roots < k else ("proven" if morses == k else "roots_proven")
    why: dict[str, int] = {}
    for b in boxes:
        if not b.proven:
            why[b.reason] = why.get(b.reason, 0) + 1
    msg = (f"Krawczyk's test in ball arithmetic proved {roots} of {k} equilibria (each the only one in its box, "
           f"real, inside the joint range, the boxes pairwise disjoint) and {morses} Morse indices")
    if why:
        msg += "; not proven: " + ", ".join(f"{v} {r}" for r, v in sorted(why.items()))
    if mismatch:
        msg += f"; {mismatch} proven Morse indices differ from the floating-point ones"
    if morses < roots:
        msg += "; the others' Morse indices are floating-point"
    checked, proven = nonreal
    if checked:
        msg += (f"; {proven} of {checked} complex roots near the real set (within {NEAR_REAL:g}) proven non-real"
                + ("" if proven == checked else " (the others' split is floating-point)"))
    if outside[0]:
        msg += (f"; {outside[1]} of {outside[0]} real roots just beyond the joint range (within {NEAR_REAL:g}) proven "
                "beyond it" + ("" if outside[1] == outside[0] else " (the others' side is floating-point)"))
    return IntervalCertificate(status, msg, control, tuple(boxes), paths=int(paths), seconds=float(seconds),
                               nonreal_checked=int(checked), nonreal_proven=int(proven),
                               outside_checked=int(outside[0]), outside_proven=int(outside[1]))
