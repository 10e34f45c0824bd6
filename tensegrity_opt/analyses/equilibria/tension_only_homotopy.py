"""Every equilibrium of a chain with tension-only springs, certified: one polynomial system per taut/slack/stop pattern.

Under the tension-only law a segment's torque is piecewise: on each interval of its joint angle where each of its
springs keeps one state (taut or slack) the torque is the linear law's with the slack springs' stiffness set to zero,
a Laurent polynomial of the same kind (:func:`~tensegrity_opt.model.segment.torque_coefficients`). The springs change
state where ``L_i(q) = L_i0``, at most twice each over the range (``L_i = 2c cos(beta +- q/2)`` is concave there), so
each joint has a few *options*: the distinct taut/slack states of its intervals, and its two stops ``q = +-lim``
(``lim = pi - 2 beta``), where it is held with a contact torque ``>= 0``. A *pattern* picks one option per joint.

An equilibrium of the chain is a real root of its pattern's system that lies in that pattern (each free joint's angle in
one of its option's intervals, each stop's contact torque ``>= 0``); conversely every such root is one (the torques
agree on the closed intervals: a spring at ``L = L0`` carries nothing under both states). So:

1. **Options.** Per joint the breakpoints ``q = 2 (+-acos(L0 / 2c) - beta)`` (spring 1) and
   ``2 (beta -+ acos(L0 / 2c))`` (spring 2) inside the range cut it into intervals; intervals of one state are one
   option. A linear-law segment has one free option (its whole range) and its stops.
2. **Pruning** (which patterns cannot occur). A pattern can hold an equilibrium only if some configuration in its box
   (each free joint in one of its option's intervals, a stop a point) puts the tip on the target *and* some tip force
   ``F`` balances it: each free joint's ``dE/dq_j = r_j x F`` (``r_j`` from the joint to the tip) and each held
   joint's contact torque ``>= 0``. The test is a branch and bound over the box (:func:`_may_balance`, sound: it
   drops a pattern only when no box of it can hold such a configuration). All patterns' boxes are bisected level by
   level together, up to :data:`BOX_BUDGET` boxes a pattern. On each box: ``r_j`` enclosed from the tip's side (the
   links after ``j``) and from the base's (the target minus the joint's position), the two intersected (empty: no
   tip on the target); ``dE/dq_j`` bounded exactly (:class:`_TorqueTables`: its values at the box's ends and at its
   critical points inside, plus a rounding margin); and, in each sign quadrant of ``F``, the extreme moments over
   the box are linear in ``F``, so "some ``F``" is a 2-D linear feasibility problem (:func:`_force_exists`,
   Fourier-Motzkin). A pattern all of whose boxes fail is dropped; one with a box left when its budget is spent is
   solved, and so is one where Newton's method from one of its boxes lands on a root inside it (that can only keep
   a pattern).

   On the benchmark's n = 4 targets the four-free-joint patterns kept are exactly those that hold an equilibrium
   (9, 8 and 5 of 37, 37 and 49). Patterns with fewer than two free joints meet a target only by coincidence (a rigid
   pose); one the test keeps is checked directly (the tip of the rigid pose or the circle of its one free joint) and
   one that meets the target leaves the set uncertified (its tip force is not determined); one whose pose touches
   the target but which no tip force can balance (a contact torque would be negative) is dropped by the test, so it
   no longer leaves the set uncertified.
3. **One system per pattern.** With the joints on stops fixed, the links between two consecutive free joints fold into
   one rigid *complex* link (``mu = sum l_j e^{i sigma_j}``, ``sigma_j`` the stop angles before link ``j``) and the
   links before the first free joint into the target: the displacement system of a chain of the free joints
   (:func:`~tensegrity_opt.numerics.parameter_homotopy.link_family`), solved by the parameter homotopy from the
   cached start roots of that many joints (:func:`~tensegrity_opt.numerics.parameter_homotopy.solve_link_homotopy`).
   Every isolated root is reached (the coefficient-parameter theorem, as in :mod:`.all_equilibria`).
4. **Roots to equilibria.** The real roots inside the closed range that lie in their pattern are polished and
   classified under the springs' laws (:func:`.tension_only._classified`: residuals in numpy, contact torques, Morse
   index of the Hessian reduced to the tip and the stops), then merged (a root on a breakpoint belongs to two
   patterns).

The set is ``certified`` when every pattern's homotopy is complete (every path ended, none failed, no two coincide),
every real root in its pattern polished onto an equilibrium, no rigid pose meets the target, and no pattern with three
or more free joints whose springs are all slack can reach it (with the tip force zero those joints would move freely
along the target: a continuum of equilibria, named in the message). There are no interval (Krawczyk) boxes for this
law (``certificate`` is ``None``): the proof is the homotopy's, as for the linear law before its boxes.
"""

from __future__ import annotations

import math
import time

import numpy as np

from ...model.manipulator import Manipulator
from ...model.segment import torque_coefficients
from ...numerics.parameter_homotopy import TORQUE_POWERS, solve_link_homotopy, unit_chain
from ...numerics.slack_nlp import slack_nlp
from ...outcome import SolverInfo
from ...timelimit import check_time
from .tension_only import SAME_EQUILIBRIUM, _classified

__all__ = ["joint_options", "patterns", "certified_equilibria_slack", "PATTERN_TOL", "BOX_BUDGET"]

#: A root this far (rad) outside its option's intervals still belongs to it (a root on a breakpoint).
PATTERN_TOL = 1e-8
#: A stop's contact torque above ``-CONTACT_TOL k c^2`` keeps the root a candidate (it must then classify).
CONTACT_TOL = 1e-9
#: Parameter-homotopy runs (each with a new ``gamma``) of a pattern before the polyhedral fallback. A pattern whose
#: system has paths to toric infinity (some ``z_j -> 0``: joints with one slack spring of a symmetric segment) loses
#: one or two of them to the batched tracker's end game in about 3 runs of 8 (measured), and PHCpack's re-tracking
#: and polyhedral solve report those as failed: more runs make the set complete (~0.2 s each at n = 4).
ATTEMPTS = 6
#: A root is real when ``||z| - 1|`` and ``|g - conj h|`` (relative) are below this.
REAL_TOL = 1e-6


class Option:
    """One joint's choice in a pattern: free in the intervals where its springs have the states ``taut``, or held on
    the stop ``side`` (+1 / -1)."""

    __slots__ = ("side", "taut", "intervals")

    def __init__(self, side: int, taut: tuple[bool, bool], intervals: np.ndarray) -> None:
        self.side, self.taut, self.intervals = side, taut, intervals

    @property
    def loose(self) -> bool:
        """A free joint both of whose springs are slack (no stiffness)."""
        return self.side == 0 and not any(self.taut)

    @property
    def hull(self) -> tuple[float, float]:
        return float(self.intervals[:, 0].min()), float(self.intervals[:, 1].max())

    def contains(self, q: float) -> bool:
        return bool(np.any((q >= self.intervals[:, 0] - PATTERN_TOL) & (q <= self.intervals[:, 1] + PATTERN_TOL)))

    def __repr__(self) -> str:
        if self.side:
            return f"Option(stop {'+' if self.side > 0 else '-'})"
        return f"Option(taut={self.taut}, intervals={self.intervals.round(4).tolist()})"


def joint_options(seg) -> list[Option]:
    """The options of one segment's joint (module docstring, step 1): the free ones (one per taut/slack state, with
    its intervals), then the two stops."""
    lim = seg.joint_limit
    stops = [Option(-1, (False, False), np.array([[-lim, -lim]])), Option(1, (False, False), np.array([[lim, lim]]))]
    if not seg.tension_only:
        free = [Option(0, (True, True), np.array([[-lim, lim]]))]
    else:
        c, beta = seg.c, seg.beta
        cuts = [-lim, lim]
        for L0, sign in ((seg.L1_0, 1.0), (seg.L2_0, -1.0)):
            if L0 < 2.0 * c:
                th = math.acos(L0 / (2.0 * c))
                for q in (2.0 * (th - beta), 2.0 * (-th - beta)):
                    q = sign * q
                    if -lim < q < lim:
                        cuts.append(q)
        cuts = np.unique(np.array(cuts))
        groups: dict[tuple[bool, bool], list[list[float]]] = {}
        for lo, hi in zip(cuts[:-1], cuts[1:]):
            if hi <= lo:
                continue
            L1, L2 = seg.spring_lengths(0.5 * (lo + hi))
            key = (bool(L1 > seg.L1_0), bool(L2 > seg.L2_0))
            groups.setdefault(key, []).append([float(lo), float(hi)])
        free = [Option(0, key, np.array(iv)) for key, iv in sorted(groups.items(), reverse=True)]
    return free + stops


# ----------------------------------------------------------------------------- pruning: reach and balance
#: Boxes (in all, over the bisection) a pattern with so many free joints may use before its balance test gives up and
#: the pattern is solved: about what its homotopy costs (a box ~10 us; a four-free-joint pattern's homotopy 0.15-0.7 s).
BOX_BUDGET = {0: 64, 1: 256, 2: 1000, 3: 4000, 4: 24000}
#: Every so many bisection levels a few of a pattern's boxes start Newton's method on its system: a root found inside
#: the pattern ends its test (it must be solved), so the budget goes to the patterns that may be dropped.
NEWTON_EVERY = 3
#: Boxes handed to the force test at once (memory: ~3 kB each).
BOX_CHUNK = 8192
#: The four sign quadrants of the tip force ``(Fx, Fy)``.
_QUADRANTS = ((1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0))
_TWO_PI = 2.0 * math.pi


def _cos_ranges(lo: np.ndarray, hi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The range of ``cos`` over each ``[lo, hi]`` (elementwise; exact up to rounding, ``[-1, 1]`` once the interval
    spans a period)."""
    a, b = np.cos(lo), np.cos(hi)
    top = np.where(np.ceil(lo / _TWO_PI) * _TWO_PI <= hi, 1.0, np.maximum(a, b))
    bot = np.where(np.ceil((lo - math.pi) / _TWO_PI) * _TWO_PI + math.pi <= hi, -1.0, np.minimum(a, b))
    return bot, top


class _TorqueTables:
    """Exact bounds of each joint's ``dE/dq`` under each taut/slack state over any ``[lo, hi]``: its values at the
    ends and at its critical points inside. With ``u = beta + q/2``, ``v = beta - q/2`` a taut spring adds
    ``-k1 c (c sin 2u - L10 sin u)`` (spring 1) or ``k2 c (c sin 2v - L20 sin v)`` (spring 2); the derivative's zeros
    are the unit roots of a quartic in ``e^{i q/2}`` (at most four; a root within 1e-3 of the circle is kept: a
    multiple root may come off it by ~eps^(1/3), and an extra candidate only widens the bound)."""

    STATES = ((True, True), (True, False), (False, True), (False, False))

    def __init__(self, m: Manipulator) -> None:
        coef, crit = [], []
        for seg in m.segments:
            c, beta, lim = seg.c, seg.beta, seg.joint_limit
            for t1, t2 in self.STATES:
                k1, k2 = seg.k1 * t1, seg.k2 * t2
                coef.append((k1, k2, seg.L1_0, seg.L2_0, c, beta))
                A, B, C, D = -2 * k1 * c * c, k1 * c * seg.L1_0, -2 * k2 * c * c, k2 * c * seg.L2_0
                e1, e2 = np.exp(1j * beta), np.exp(2j * beta)
                poly = [(A * e2 + C / e2) / 2, (B * e1 + D / e1) / 2, 0.0, (B / e1 + D * e1) / 2, (A / e2 + C * e2) / 2]
                qs = np.zeros(0)
                if max(abs(v) for v in poly) > 0.0:
                    z = np.roots(poly)
                    z = z[np.abs(np.abs(z) - 1.0) < 1e-3]       # generous: an extra candidate only widens
                    qs = 2.0 * np.angle(z)
                    qs = qs[np.abs(qs) <= lim + 1e-6]
                crit.append(np.pad(qs, (0, 4 - qs.size), constant_values=np.nan))
        self.coef = np.array(coef).T                       # (6, tables)
        self.crit = np.array(crit)                         # (tables, 4)
        self.crit_g = self._g(np.arange(len(crit))[:, None], np.nan_to_num(self.crit))
        self.scale = 1e-12 * (self.coef[0] + self.coef[1] + 1e-300) * self.coef[4] ** 2 * 4.0

    def _g(self, table: np.ndarray, q: np.ndarray) -> np.ndarray:
        k1, k2, L10, L20, c, beta = (row[table] for row in self.coef)
        u, v = beta + 0.5 * q, beta - 0.5 * q
        return -k1 * c * (c * np.sin(2 * u) - L10 * np.sin(u)) + k2 * c * (c * np.sin(2 * v) - L20 * np.sin(v))

    def dg(self, table: np.ndarray, q: np.ndarray) -> np.ndarray:
        """``d^2 E / dq^2`` of the tables ``table`` at ``q``."""
        k1, k2, L10, L20, c, beta = (row[table] for row in self.coef)
        u, v = beta + 0.5 * q, beta - 0.5 * q
        return (-k1 * c * (c * np.cos(2 * u) - 0.5 * L10 * np.cos(u))
                - k2 * c * (c * np.cos(2 * v) - 0.5 * L20 * np.cos(v)))

    def index(self, j: int, taut: tuple[bool, bool]) -> int:
        return 4 * j + self.STATES.index(tuple(bool(t) for t in taut))

    def bounds(self, table: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Lower and upper bounds of ``dE/dq`` over ``[lo, hi]`` (B, n) for the tables ``table`` (B, n)."""
        g0, g1 = self._g(table, lo), self._g(table, hi)
        cq, cg = self.crit[table], self.crit_g[table]
        inside = (cq >= lo[..., None]) & (cq <= hi[..., None])
        mg = self.scale[table]
        low = np.minimum(np.minimum(g0, g1), np.where(inside, cg, np.inf).min(axis=-1))
        high = np.maximum(np.maximum(g0, g1), np.where(inside, cg, -np.inf).max(axis=-1))
        return low - mg, high + mg


def _force_exists(a: np.ndarray, b: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Whether some ``F = (fx, fy)`` meets every row ``a fx + b fy >= t`` (rows on the last axis): ``fx`` eliminated
    (Fourier-Motzkin: each pair of rows with opposite signs of ``a`` gives one row in ``fy``), then the interval of
    ``fy`` left. Sound up to rounding: near-parallel pairs are dropped (a relaxation) and a tolerance widens the
    end test."""
    big = np.maximum(np.abs(a), np.abs(b))
    big = np.where(big > 0.0, big, 1.0)
    a, b, t = a / big, b / big, t / big
    ai, bi, ti = a[..., :, None], b[..., :, None], t[..., :, None]
    ak, bk, tk = a[..., None, :], b[..., None, :], t[..., None, :]
    c = ak * bi - ai * bk                    # from (t_i - b_i fy) / a_i <= (t_k - b_k fy) / a_k, a_i > 0 > a_k
    d = ak * ti - ai * tk                    # c fy <= d
    pair = (a > 0.0)[..., :, None] & (a < 0.0)[..., None, :]
    tol = 1e-9 * (1.0 + np.abs(t).max(axis=-1))
    use = pair & (np.abs(c) > 1e-12 * (np.abs(ak * bi) + np.abs(ai * bk)))
    bad = (pair & (c == 0.0) & (d < -tol[..., None, None])).any(axis=(-1, -2))
    zero = a == 0.0
    with np.errstate(divide="ignore", invalid="ignore"):
        r, rz = d / c, t / b
    up = np.minimum(np.where(use & (c > 0.0), r, np.inf).min(axis=(-1, -2)),
                    np.where(zero & (b < 0.0), rz, np.inf).min(axis=-1))
    low = np.maximum(np.where(use & (c < 0.0), r, -np.inf).max(axis=(-1, -2)),
                     np.where(zero & (b > 0.0), rz, -np.inf).max(axis=-1))
    bad |= (zero & (b == 0.0) & (t > tol[..., None])).any(axis=-1)
    size = np.abs(np.where(np.isfinite(low), low, 0.0)) + np.abs(np.where(np.isfinite(up), up, 0.0))
    return (low <= up + tol * (1.0 + size)) & ~bad


def _boxes_pass(m: Manipulator, target: np.ndarray, lo: np.ndarray, hi: np.ndarray, table: np.ndarray,
                side: np.ndarray, held: np.ndarray, tables: _TorqueTables, tol: float, slack: float) -> np.ndarray:
    """The boxes ``[lo, hi]`` (B, n) that may hold an equilibrium with the tip on ``target`` (module docstring, step
    2): the vector ``r_j`` from joint ``j`` to the tip, enclosed from the tip's side (the links after ``j``) and from
    the base's (``target`` minus the joint's position), must exist; and some tip force ``F`` must give each free
    joint's moment ``r_j x F`` a value in its ``dE/dq`` bounds and each held joint's a contact torque ``>= 0``
    (``side (r_j x F) >= side dE/dq(stop)``, ``held``), for some ``r_j`` in its enclosure: in each quadrant of
    ``F`` the extreme moments over the box are linear in ``F`` (:func:`_force_exists`)."""
    B = lo.shape[0]
    l, base = m.link_lengths, m.base_length
    plo, phi = np.cumsum(lo, axis=1), np.cumsum(hi, axis=1)
    c0, c1 = _cos_ranges(plo, phi)
    s0, s1 = _cos_ranges(plo - 0.5 * math.pi, phi - 0.5 * math.pi)
    X0, X1, Y0, Y1 = l * c0, l * c1, l * s0, l * s1

    def after(v):            # sum over the links from j on
        return np.cumsum(v[:, ::-1], axis=1)[:, ::-1]

    def before(v):           # sum over the links before j
        return np.hstack([np.zeros((B, 1)), np.cumsum(v, axis=1)[:, :-1]])

    rx0 = np.maximum(after(X0), target[0] - base - before(X1)) - tol
    rx1 = np.minimum(after(X1), target[0] - base - before(X0)) + tol
    ry0 = np.maximum(after(Y0), target[1] - before(Y1)) - tol
    ry1 = np.minimum(after(Y1), target[1] - before(Y0)) + tol
    ok = (rx0 <= rx1).all(axis=1) & (ry0 <= ry1).all(axis=1)
    rows = np.flatnonzero(ok)
    if rows.size == 0:
        return ok
    rx0, rx1, ry0, ry1, lo, hi = rx0[rows], rx1[rows], ry0[rows], ry1[rows], lo[rows], hi[rows]
    table, side = table[rows], side[rows]
    glo, ghi = tables.bounds(table, lo, hi)
    on = side != 0.0
    glo = np.where(on, held[rows] - slack, glo)
    ghi = np.where(on, held[rows] + slack, ghi)
    lower = ~on | (side > 0.0)               # a row "moment >= glo"
    upper = ~on | (side < 0.0)               # a row "moment <= ghi"
    nb = rows.size
    A, Bm, T = [], [], []
    for sx, sy in _QUADRANTS:                # r x F = ax fx + ay fy with ax = -ry, ay = rx
        ax_max, ax_min = (-ry0, -ry1) if sx > 0 else (-ry1, -ry0)
        ay_max, ay_min = (rx1, rx0) if sy > 0 else (rx0, rx1)
        A.append(np.hstack([np.where(lower, ax_max, 0.0), np.where(upper, -ax_min, 0.0), np.full((nb, 1), sx),
                            np.zeros((nb, 1))]))
        Bm.append(np.hstack([np.where(lower, ay_max, 0.0), np.where(upper, -ay_min, 0.0), np.zeros((nb, 1)),
                             np.full((nb, 1), sy)]))
        T.append(np.hstack([np.where(lower, glo, -1.0), np.where(upper, -ghi, -1.0), np.zeros((nb, 2))]))
    A, Bm, T = np.stack(A, axis=1), np.stack(Bm, axis=1), np.stack(T, axis=1)
    feasible = np.zeros(nb, dtype=bool)
    for s in range(0, nb, BOX_CHUNK):
        part = slice(s, s + BOX_CHUNK)
        feasible[part] = _force_exists(A[part], Bm[part], T[part]).any(axis=1)
    ok[rows] = feasible
    return ok


def _newton_finds(m: Manipulator, target: np.ndarray, q: np.ndarray, table: np.ndarray, side: np.ndarray,
                  tables: _TorqueTables, iterations: int = 12) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Newton's method on each row's pattern system (unknowns ``q`` and the tip force ``F``; a held joint's row
    ``q_j = its stop``) from the configurations ``q`` (B, n). Returns the end points and which converged (residual
    below ``1e-10`` of the chain's scales) and each joint's moment ``r_j x F`` there; where they lie (and the contact
    torques) is the caller's to check."""
    B, n = q.shape
    l = m.link_lengths
    lim = m.joint_limits
    free = side == 0.0
    stop = side * lim
    q = np.where(free, q, stop)
    later = np.maximum.outer(np.arange(n), np.arange(n))            # r_{max(j, k)}
    rows = np.arange(n)

    def geometry(q):
        r = np.cumsum((l * np.exp(1j * np.cumsum(q, axis=1)))[:, ::-1], axis=1)[:, ::-1]
        return r, m.base_length + r[:, 0]

    r, tip = geometry(q)
    g = tables._g(table, q)
    M = np.stack([-r.imag, r.real], axis=2) * free[..., None]         # r_j x F = M_j . F
    F = np.linalg.lstsq(M.reshape(-1, 2), np.where(free, g, 0.0).reshape(-1), rcond=None)[0] if B == 1 else \
        np.stack([np.linalg.lstsq(M[b], np.where(free[b], g[b], 0.0), rcond=None)[0] for b in range(B)])
    F = np.broadcast_to(F, (B, 2)).copy()
    scale = m.torque_scale
    length = float(l.sum())
    ok = np.zeros(B, dtype=bool)
    for _ in range(iterations):
        r, tip = geometry(q)
        g, dg = tables._g(table, q), tables.dg(table, q)
        mom = r.real * F[:, 1:2] - r.imag * F[:, 0:1]
        res = np.hstack([np.where(free, g - mom, q - stop), (tip.real - target[0])[:, None],
                         (tip.imag - target[1])[:, None]])
        ok = (np.abs(res[:, :n]).max(axis=1) <= 1e-10 * scale) & (np.abs(res[:, n:]).max(axis=1) <= 1e-10 * length)
        if ok.all():
            break
        Rl = r[:, later]                                              # (B, n, n)
        J = np.zeros((B, n + 2, n + 2))
        J[:, :n, :n] = np.where(free[..., None], Rl.real * F[:, None, 0:1] + Rl.imag * F[:, None, 1:2], 0.0)
        J[:, rows, rows] += np.where(free, dg, 1.0)
        J[:, :n, n] = np.where(free, r.imag, 0.0)
        J[:, :n, n + 1] = np.where(free, -r.real, 0.0)
        J[:, n, :n], J[:, n + 1, :n] = -r.imag, r.real
        with np.errstate(all="ignore"):
            try:
                step = np.linalg.solve(J, res[..., None])[..., 0]
            except np.linalg.LinAlgError:
                step = np.stack([np.linalg.lstsq(Jb, rb, rcond=None)[0] for Jb, rb in zip(J, res)])
        big = np.abs(step[:, :n]).max(axis=1, keepdims=True)
        step *= np.minimum(1.0, 0.5 / np.maximum(big, 1e-300))       # at most half a radian a step
        q, F = q - step[:, :n], F - step[:, n:]
        q = np.where(np.isfinite(q), q, 0.0)
        F = np.where(np.isfinite(F), F, 0.0)
    r, _ = geometry(q)
    return q, ok & np.isfinite(q).all(axis=1), r.real * F[:, 1:2] - r.imag * F[:, 0:1]


def _may_balance(m: Manipulator, pats: list[tuple[Option, ...]], target: np.ndarray,
                 budget: dict[int, int] | None = None) -> np.ndarray:
    """For each pattern, False when no equilibrium of it can put the tip on ``target`` (proved by bisection of its
    box with :func:`_boxes_pass`), True when one may (a box is left after ``budget`` boxes). All the patterns'
    boxes go through each bisection level together."""
    P, n = len(pats), m.n
    lim = m.joint_limits
    tol = 1e-9 * float(m.link_lengths.sum())
    slack = CONTACT_TOL * 1e3 * m.torque_scale
    tables = _TorqueTables(m)
    reach = np.cumsum(m.link_lengths[::-1])[::-1]          # how far a joint's turn moves the tip: bisect by it
    table = np.zeros((P, n), dtype=int)
    side = np.zeros((P, n))
    held = np.zeros((P, n))
    los, his, owner = [], [], []
    for p, pat in enumerate(pats):
        ivs = []
        for j, o in enumerate(pat):
            side[p, j] = o.side
            if o.side:
                held[p, j] = float(-m.segments[j].torque(o.side * lim[j]))
                ivs.append(np.array([[o.side * lim[j], o.side * lim[j]]]))
            else:
                table[p, j] = tables.index(j, o.taut)
                ivs.append(o.intervals + [-PATTERN_TOL, PATTERN_TOL])    # a root this close still belongs
        for idx in np.ndindex(*[len(v) for v in ivs]):
            los.append([ivs[j][i, 0] for j, i in enumerate(idx)])
            his.append([ivs[j][i, 1] for j, i in enumerate(idx)])
            owner.append(p)
    lo, hi, owner = np.array(los, dtype=float).reshape(-1, n), np.array(his, dtype=float).reshape(-1, n), \
        np.array(owner, dtype=int)
    budget = BOX_BUDGET if budget is None else budget
    cap = np.array([budget.get(int((side[p] == 0).sum()), max(budget.values())) for p in range(P)])
    may = np.zeros(P, dtype=bool)
    used = np.zeros(P, dtype=int)
    level = 0
    while owner.size:
        check_time("the tension-only homotopy's pattern test")
        used += np.bincount(owner, minlength=P)
        keep = _boxes_pass(m, target, lo, hi, table[owner], side[owner], held[owner], tables, tol, slack)
        lo, hi, owner = lo[keep], hi[keep], owner[keep]
        level += 1
        if level % NEWTON_EVERY == 0 and owner.size:
            first = np.unique(owner, return_index=True)[1]
            q, ok, mom = _newton_finds(m, target, 0.5 * (lo[first] + hi[first]), table[owner[first]],
                                       side[owner[first]], tables)
            for i in np.flatnonzero(ok):
                p = owner[first[i]]
                contact = side[p] * (mom[i] - held[p])           # >= 0 on a stop
                if all(o.contains(q[i, j]) if not o.side else contact[j] >= -slack for j, o in enumerate(pats[p])):
                    may[p] = True                          # a root of its system in the pattern: it is solved
            keep = ~may[owner]
            lo, hi, owner = lo[keep], hi[keep], owner[keep]
        alive = np.bincount(owner, minlength=P)
        width = np.where(side[owner] != 0.0, -1.0, (hi - lo) * reach)
        point = np.bincount(owner[width.max(axis=1, initial=-1.0) <= 1e-12], minlength=P) > 0   # nothing to bisect
        spent = (alive > 0) & ((used + 2 * alive > cap) | point)
        may |= spent
        keep = ~spent[owner]
        lo, hi, owner, width = lo[keep], hi[keep], owner[keep], width[keep]
        j = np.argmax(width, axis=1)
        r = np.arange(owner.size)
        mid = 0.5 * (lo[r, j] + hi[r, j])
        upper_lo, lower_hi = lo.copy(), hi.copy()
        lower_hi[r, j] = mid
        upper_lo[r, j] = mid
        lo, hi, owner = np.concatenate([lo, upper_lo]), np.concatenate([lower_hi, hi]), np.concatenate([owner, owner])
    return may


def patterns(m: Manipulator, target, *, budget: dict[int, int] | None = None) -> tuple[list[tuple[Option, ...]], int]:
    """The patterns (one option per joint) that may hold an equilibrium with the tip on ``target`` (module docstring,
    step 2), and how many patterns there are in all."""
    options = [joint_options(seg) for seg in m.segments]
    every = [tuple(options[j][i] for j, i in enumerate(idx)) for idx in np.ndindex(*[len(o) for o in options])]
    may = _may_balance(m, every, np.asarray(target, dtype=float), budget)
    return [p for p, k in zip(every, may) if k], len(every)


# ----------------------------------------------------------------------------- one pattern's system
def _pattern_system(u: Manipulator, pat: tuple[Option, ...], target: np.ndarray):
    """The folded chain of the free joints of ``pat`` (module docstring, step 3) for the unit chain ``u``:
    ``(free, torques, mu, mu', T, T')``."""
    free = [j for j, o in enumerate(pat) if o.side == 0]
    lim = u.joint_limits
    sigma = np.cumsum([o.side * lim[j] for j, o in enumerate(pat)])     # the stop angles up to each link
    l = u.link_lengths
    rot = l * np.exp(1j * sigma)
    rot_c = l * np.exp(-1j * sigma)
    T = complex(target[0] - u.base_length, target[1]) - rot[:free[0]].sum()
    Tc = complex(target[0] - u.base_length, -target[1]) - rot_c[:free[0]].sum()
    ends = free[1:] + [u.n]
    mu = np.array([rot[a:b].sum() for a, b in zip(free, ends)])
    mu_c = np.array([rot_c[a:b].sum() for a, b in zip(free, ends)])
    tq = np.zeros((len(free), len(TORQUE_POWERS)), dtype=complex)
    for r, j in enumerate(free):
        s = u.segments[j]
        t1, t2 = pat[j].taut
        poly = torque_coefficients(s.a, s.b, s.k1 * t1, s.k2 * t2, s.L1_0, s.L2_0)
        tq[r] = [poly[p] for p in TORQUE_POWERS]
    return free, tq, mu, mu_c, T, Tc


def _rigid_meets(m: Manipulator, pat: tuple[Option, ...], target: np.ndarray) -> bool:
    """A pattern with fewer than two free joints puts the tip on ``target`` (within rounding) somewhere in its box."""
    lim = m.joint_limits
    free = [j for j, o in enumerate(pat) if o.side == 0]
    q = np.array([o.side * lim[j] for j, o in enumerate(pat)], dtype=float)
    tol = 1e-9 * float(m.link_lengths.sum())
    if not free:
        return float(np.abs(m.tip(q) - target).max()) <= tol
    j = free[0]
    grid = np.concatenate([np.linspace(lo, hi, 2001) for lo, hi in pat[j].intervals])
    Q = np.tile(q, (grid.size, 1))
    Q[:, j] = grid
    d = np.linalg.norm(m.tip_kinematics(Q).tip - target, axis=1)
    step = float(m.link_lengths.sum()) * float(np.max(np.diff(grid), initial=0.0))
    return bool(d.min() <= step + tol)


# ----------------------------------------------------------------------------- the set
def certified_equilibria_slack(m: Manipulator, target, *, timeout: float | None = None):
    """Every equilibrium of ``m`` (tension-only springs, any mix of laws) with the tip on ``target`` in the closed
    joint range, by one homotopy per pattern (module docstring). Returns ``(equilibria sorted by energy, report)``:
    ``report`` holds ``certified`` (bool), ``paths``, ``failed_paths``, ``seconds``, ``patterns`` (solved),
    ``total`` (all patterns), ``message``."""
    t0 = time.monotonic()
    deadline = None if timeout is None else t0 + float(timeout)
    target = np.asarray(target, dtype=float)
    u, lam, kap = unit_chain(m)
    tu = target * lam
    nlp = slack_nlp(m.n)
    lim = m.joint_limits
    scale = m.torque_scale
    pats, total = patterns(m, target)
    found: list = []
    paths = failed = solved = lost = 0
    why: list[str] = []
    rigid = 0
    doubtful: list = []
    loose_reach: set[int] = set()
    systems = []
    check_time("the tension-only homotopy")
    for pat in pats:
        free = [j for j, o in enumerate(pat) if o.side == 0]
        loose = [j for j in free if pat[j].loose]
        if len(loose) >= 3:
            loose_reach.update(loose)
        if len(free) < 2:
            rigid += _rigid_meets(m, pat, target)
        else:
            systems.append((pat, _pattern_system(u, pat, tu)))

    def solve(job):
        check_time("the tension-only homotopy")
        _, (fj, tq, mu, mu_c, T, Tc) = job
        left = None if deadline is None else deadline - time.monotonic()
        return solve_link_homotopy(tq, mu, mu_c, T, Tc, timeout=left, attempts=ATTEMPTS)

    # one after the other: two side by side in threads took as long in all (measured: the tracker's many small numpy
    # operations hold the GIL)
    sols = [solve(job) for job in systems]
    for (pat, (fj, *_)), sol in zip(systems, sols):
        loose = [j for j in fj if pat[j].loose]
        solved += 1
        paths += sol.paths
        failed += sol.failures
        if not (sol.complete and sol.consistent):
            why.append(f"pattern {_name(pat)}: {sol.failures} of {sol.paths} paths failed or coincided")
        if sol.engine != "parameter" and len(loose) >= 2:
            why.append(f"pattern {_name(pat)}: the polyhedral fallback does not count roots with zero tip force")
        R = sol.roots
        if R.size == 0:
            continue
        k = len(fj)
        z, g, h = R[:, :k], R[:, k], R[:, k + 1]
        fs = max(1.0, u.torque_scale / float(u.b.sum()))
        dist = np.maximum(np.abs(np.abs(z) - 1.0).max(axis=1), np.abs(g - np.conj(h)) / np.maximum(fs, np.abs(g)))
        for r in np.flatnonzero(dist < np.where(sol.regular, REAL_TOL, 1e-3)):
            qf = 2.0 * np.angle(z[r])
            q = np.array([o.side * lim[j] for j, o in enumerate(pat)], dtype=float)
            q[fj] = qf
            if np.any(np.abs(q) > lim * (1 + 1e-9)) or not all(pat[j].contains(q[j]) for j in fj):
                continue
            G = 0.5 * (g[r] + np.conj(h[r])) / (kap * lam)
            F = np.array([G.real, G.imag])
            held = [j for j, o in enumerate(pat) if o.side != 0]
            contact = -np.array([pat[j].side for j in held]) * (m.gradient(q) - m.jacobian(q).T @ F)[held]
            if held and sol.regular[r] and contact.min() < -CONTACT_TOL * scale * 1e3:
                continue                        # a regular root: the joint would leave its stop, no equilibrium
            eq = _classified(m, nlp, q, F, target, SolverInfo("Homotopy_Polished", 0), refuse_free=False)
            if eq is None:
                if held and contact.min() < -CONTACT_TOL * scale * 1e3:
                    continue                    # (a singular root) polished, the contact torque stays negative
                # a contact torque ~0 (the neighbouring free pattern's root, found there) or a failed polish: decided
                # once every pattern is done
                doubtful.append((pat, q))
                continue
            if not any(float(np.abs(eq.q - e.q).max()) < SAME_EQUILIBRIUM for e in found):
                found.append(eq)
    for pat, q in doubtful:
        if not any(float(np.abs(e.q - q).max()) < 1e-6 for e in found):
            lost += 1
            why.append(f"pattern {_name(pat)}: a real root at q = {np.round(q, 6).tolist()} did not polish")
    if rigid:
        why.append(f"{rigid} pattern(s) with fewer than two free joints meet the target (a rigid pose: its tip force "
                   "is not determined)")
    if loose_reach:
        segs = ", ".join(str(j) for j in sorted(loose_reach))
        why.append(f"three or more free joints with both springs slack (segments {segs}) may reach the target: with "
                   "no tip force they would move freely (a continuum of equilibria)")
    certified = not why
    found.sort(key=lambda e: (round(e.energy, 10), -e.q[0]))
    on_stop = sum(bool(e.at_stop.any()) for e in found)
    msg = (f"{len(found)} equilibria ({on_stop} resting on a stop) from {solved} taut/slack/stop patterns of "
           f"{total} (the others cannot reach the target), {paths} homotopy paths in all")
    msg += "; certified: every pattern's homotopy complete and every real root in its pattern polished" if certified \
        else "; not certified: " + "; ".join(why[:5]) + (f" (and {len(why) - 5} more)" if len(why) > 5 else "")
    return found, {"certified": certified, "paths": paths, "failed_paths": failed, "patterns": solved,
                   "total": total, "seconds": time.monotonic() - t0, "message": msg}


def _name(pat: tuple[Option, ...]) -> str:
    def one(o: Option) -> str:
        if o.side:
            return "+" if o.side > 0 else "-"
        return {(True, True): "T", (False, True): "1", (True, False): "2", (False, False): "0"}[o.taut]
    return "".join(one(o) for o in pat)
