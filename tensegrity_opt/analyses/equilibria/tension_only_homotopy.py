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
2. **Pruning.** A pattern can have an equilibrium only if its box (each joint's option hull, a stop a point) can put the
   tip on the target: the tip's interval enclosure over the box, bisected (:data:`REACH_DEPTH` levels at most), must
   contain the target. Patterns with fewer than two free joints meet a target only by coincidence (a rigid pose);
   each is checked directly (the tip of the rigid pose or the circle of its one free joint) and one that meets the
   target leaves the set uncertified (its tip force is not determined).
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

__all__ = ["joint_options", "patterns", "certified_equilibria_slack", "PATTERN_TOL", "REACH_DEPTH"]

#: A root this far (rad) outside its option's intervals still belongs to it (a root on a breakpoint).
PATTERN_TOL = 1e-8
#: Bisection levels of a pattern's box before the tip enclosure's answer "may reach" is taken.
REACH_DEPTH = 10
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

    __slots__ = ("side", "taut", "intervals", "sign", "zeros")

    def __init__(self, side: int, taut: tuple[bool, bool], intervals: np.ndarray) -> None:
        self.side, self.taut, self.intervals = side, taut, intervals
        #: ``s`` with ``s tau_j >= 0`` at every equilibrium of this option (``tau = J^T F``, the tip force's moment
        #: about the joint), 0 when the option says nothing; the angles where ``tau_j = 0`` is possible (``None``:
        #: all of them): :func:`_signs`.
        self.sign: int = 0
        self.zeros: np.ndarray | None = None

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
    its intervals), then the two stops; each with the sign its joint's moment must have (:func:`_signs`)."""
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
    for o in free + stops:
        o.sign, o.zeros = _signs(seg, o)
    return free + stops


def _signs(seg, o: Option) -> tuple[int, np.ndarray | None]:
    """What an equilibrium of option ``o`` says of the joint's moment ``tau = (J^T F)_j``: ``(sign, zeros)``, with
    ``s tau >= 0`` for ``sign = s`` (0: nothing said) and ``zeros`` the angles of the option where ``tau = 0`` is
    possible (an equilibrium with no tip force), ``None`` for every angle (both springs slack: a free joint).

    * free, one spring taut: ``tau = dE/dq = k (L - L0) L'`` with ``L >= L0`` on the option, and
      ``L' = -+c sin(beta +- q/2)`` changes sign only at ``q = -+2 beta``: a definite weak sign when that angle is not
      inside the option's intervals; ``tau = 0`` at the ends where ``L = L0`` and at ``-+2 beta``;
    * free, both taut (or the linear law): no sign; ``tau = 0`` at the linear law's critical points in the intervals;
    * on the stop ``s`` (contact torque ``-s (dE/dq - tau) >= 0``): ``s tau >= s dE/dq(s lim)``, sign ``s`` when that
      is ``>= 0``; ``tau = 0`` possible when it is ``<= 0``."""
    lim = seg.joint_limit
    if o.side:
        d = float(-seg.torque(o.side * lim)) * o.side
        return (o.side if d >= 0.0 else 0), (np.array([o.side * lim]) if d <= 0.0 else np.zeros(0))
    iv = o.intervals
    if o.taut == (False, False):
        return 0, None

    def inside(q: np.ndarray) -> np.ndarray:
        q = np.asarray(q, dtype=float)
        keep = np.any((q[:, None] >= iv[:, 0] - PATTERN_TOL) & (q[:, None] <= iv[:, 1] + PATTERN_TOL), axis=1)
        return q[keep]

    if o.taut == (True, True):
        lin = seg if not seg.tension_only else seg.replace(spring="linear")
        ends = iv.ravel()
        return 0, np.concatenate([inside(lin.critical_points()), ends[np.abs(lin.torque(ends)) <= 1e-12 * seg.k1]])
    spring = 1 if o.taut[0] else 2                       # the taut one
    turn = -2.0 * seg.beta if spring == 1 else 2.0 * seg.beta     # where its L' = 0
    L0 = seg.L1_0 if spring == 1 else seg.L2_0
    ends = iv.ravel()
    Ls = seg.spring_lengths(ends)[spring - 1]
    zeros = np.concatenate([ends[np.abs(Ls - L0) <= 1e-9 * L0], inside(np.array([turn]))])
    if np.any((iv[:, 0] < turn) & (turn < iv[:, 1])):
        return 0, zeros
    # each interval has one sign; two intervals of one option may lie on either side of the turn (opposite signs)
    signs = {int(np.sign(float(-seg.torque(0.5 * (lo + hi))))) for lo, hi in iv}
    return (signs.pop() if len(signs) == 1 else 0), zeros


# ----------------------------------------------------------------------------- pruning by the tip's reach
def _cos_range(lo: float, hi: float) -> tuple[float, float]:
    """The range of ``cos`` over ``[lo, hi]`` (exact up to rounding)."""
    if hi - lo >= 2.0 * math.pi:
        return -1.0, 1.0
    a, b = math.cos(lo), math.cos(hi)
    top = 1.0 if math.floor(hi / (2 * math.pi)) * 2 * math.pi >= lo else max(a, b)
    bot = -1.0 if math.floor((hi - math.pi) / (2 * math.pi)) * 2 * math.pi + math.pi >= lo else min(a, b)
    return bot, top


#: Directions of the tip force tried by the sign test (a grid; each arc widened by half its step: sound).
DIRECTIONS = 720
_THETA = np.linspace(0.0, 2.0 * np.pi, DIRECTIONS, endpoint=False)


def _may_reach(links: np.ndarray, base: float, target: np.ndarray, lo: np.ndarray, hi: np.ndarray, depth: int,
               tol: float, signs: np.ndarray | None = None) -> bool:
    """False only when no equilibrium of the box ``[lo, hi]`` can put the tip on ``target``: the tip's interval
    enclosure misses it, or (``signs``: the moments' signs of the pattern, when its tip force cannot be zero) no
    direction of the tip force gives every joint's moment ``r_j x F`` its sign for some ``r_j`` (the tip from joint
    ``j``) in its enclosure. The box is bisected along its widest joint up to ``depth`` levels."""
    plo, phi = np.cumsum(lo), np.cumsum(hi)
    n = lo.size
    X = np.zeros((n, 2))
    Y = np.zeros((n, 2))
    for j, (l, a, b) in enumerate(zip(links, plo, phi)):
        c0, c1 = _cos_range(a, b)
        s0, s1 = _cos_range(a - math.pi / 2, b - math.pi / 2)
        X[j], Y[j] = (l * c0, l * c1), (l * s0, l * s1)
    RX, RY = np.cumsum(X[::-1], axis=0)[::-1], np.cumsum(Y[::-1], axis=0)[::-1]     # r_j: joint j to the tip
    x0, x1 = base + RX[0]
    y0, y1 = RY[0]
    if not (x0 - tol <= target[0] <= x1 + tol and y0 - tol <= target[1] <= y1 + tol):
        return False
    if signs is not None and not _directions(RX, RY, signs, tol):
        return False
    w = hi - lo
    j = int(np.argmax(w))
    if depth <= 0 or w[j] <= 1e-12:
        return True
    mid = 0.5 * (lo[j] + hi[j])
    hi1, lo2 = hi.copy(), lo.copy()
    hi1[j], lo2[j] = mid, mid
    return (_may_reach(links, base, target, lo, hi1, depth - 1, tol, signs)
            or _may_reach(links, base, target, lo2, hi, depth - 1, tol, signs))


def _directions(RX: np.ndarray, RY: np.ndarray, signs: np.ndarray, tol: float) -> bool:
    """Some direction ``theta`` of a nonzero tip force gives ``s_j (r_j x F) >= 0`` for every joint with a sign,
    ``r_j`` anywhere in its box ``RX[j] x RY[j]``: ``r x F = |r| |F| sin(theta - alpha_r)``, so joint ``j`` allows
    ``theta`` in ``[alpha_min, alpha_max + pi]`` (``s = +1``) or ``[alpha_min - pi, alpha_max]`` (``s = -1``), the
    box's angles ``alpha``; a box about the origin allows every direction."""
    ok = np.ones(DIRECTIONS, dtype=bool)
    half = math.pi / DIRECTIONS + 1e-9
    for j in np.flatnonzero(signs):
        (a0, a1), (b0, b1) = RX[j], RY[j]
        if a0 - tol <= 0.0 <= a1 + tol and b0 - tol <= 0.0 <= b1 + tol:
            continue
        ang = np.arctan2([b0, b0, b1, b1], [a0, a1, a0, a1])
        ref = math.atan2(0.5 * (b0 + b1), 0.5 * (a0 + a1))
        d = (ang - ref + np.pi) % (2 * np.pi) - np.pi
        lo_a, hi_a = ref + d.min(), ref + d.max()
        start, end = (lo_a, hi_a + math.pi) if signs[j] > 0 else (lo_a - math.pi, hi_a)
        ok &= ((_THETA - (start - half)) % (2 * np.pi)) <= (end - start + 2 * half)
        if not ok.any():
            return False
    return True


#: Grid points (in all) on which :func:`_distance_may_reach` samples a pattern's box.
DISTANCE_GRID = 4096


def _distance_may_reach(links: np.ndarray, dist: float, lo: np.ndarray, hi: np.ndarray, tol: float) -> bool:
    """False only when no configuration of the box ``[lo, hi]`` puts the tip at the distance ``dist`` from joint 1.

    That distance ``|sum_k l_k e^{i psi_k}|`` (``psi_k = q_2 + ... + q_k``) does not depend on ``q_1`` (free of the
    wrapping of the tip's interval enclosure); it is sampled on a grid of the box and bounded between the samples by
    its Lipschitz constants ``sum_{k >= i} l_k`` in ``q_i`` (the reach of joint ``i``): sound."""
    n = lo.size
    w = hi[1:] - lo[1:]
    dims = int(np.count_nonzero(w > 0.0))
    per = max(2, int(round(DISTANCE_GRID ** (1.0 / dims)))) if dims else 1
    axes = [np.linspace(a, b, per) if b > a else np.array([a]) for a, b in zip(lo[1:], hi[1:])]
    Q = np.array(np.meshgrid(*axes, indexing="ij")).reshape(n - 1, -1).T if n > 1 else np.zeros((1, 0))
    psi = np.concatenate([np.zeros((Q.shape[0], 1)), np.cumsum(Q, axis=1)], axis=1)
    r = np.abs(np.exp(1j * psi) @ links)
    reach = np.cumsum(links[::-1])[::-1][1:]
    half = np.array([0.5 * (b - a) / (per - 1) if b > a else 0.0 for a, b in zip(lo[1:], hi[1:])])
    margin = float(reach @ half) + tol
    return bool(r.min() - margin <= dist <= r.max() + margin)


def patterns(m: Manipulator, target, *, depth: int = REACH_DEPTH) -> tuple[list[tuple[Option, ...]], int]:
    """The patterns (one option per joint) whose box may reach ``target`` (module docstring, step 2), and how many
    patterns there are in all."""
    options = [joint_options(seg) for seg in m.segments]
    target = np.asarray(target, dtype=float)
    tol = 1e-9 * float(m.link_lengths.sum())
    out: list[tuple[Option, ...]] = []
    total = 0
    dist = math.hypot(target[0] - m.base_length, target[1])
    for idx in np.ndindex(*[len(o) for o in options]):
        total += 1
        pat = tuple(options[j][i] for j, i in enumerate(idx))
        lo = np.array([o.hull[0] for o in pat])
        hi = np.array([o.hull[1] for o in pat])
        if not _distance_may_reach(m.link_lengths, dist, lo, hi, tol):
            continue
        signs = None if _unloaded_may_reach(m, pat, target, tol) else np.array([o.sign for o in pat])
        if _may_reach(m.link_lengths, m.base_length, target, lo, hi, depth, tol, signs):
            out.append(pat)
    return out, total


def _unloaded_may_reach(m: Manipulator, pat: tuple[Option, ...], target: np.ndarray, tol: float) -> bool:
    """An equilibrium of ``pat`` with no tip force may put the tip on ``target``: every joint at a zero of its
    option's moment (:func:`_signs`), a free joint anywhere in its option; two or more free joints: assumed."""
    loose = [j for j, o in enumerate(pat) if o.zeros is None]
    if len(loose) >= 2:
        return True
    sets = [o.zeros if o.zeros is not None else np.zeros(1) for o in pat]
    if any(z.size == 0 for z in sets):
        return False
    Q = np.array(np.meshgrid(*sets, indexing="ij")).reshape(m.n, -1).T
    if not loose:
        return bool((np.abs(m.tip_kinematics(Q).tip - target).max(axis=1) <= tol).any())
    j = loose[0]
    grid = np.concatenate([np.linspace(lo, hi, 721) for lo, hi in pat[j].intervals])
    step = float(m.link_lengths.sum()) * float(np.max(np.diff(grid), initial=0.0))
    for q in Q:
        G = np.tile(q, (grid.size, 1))
        G[:, j] = grid
        if np.linalg.norm(m.tip_kinematics(G).tip - target, axis=1).min() <= step + tol:
            return True
    return False


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
