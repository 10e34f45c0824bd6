"""A rigorous lower bound on the least energy under a tip displacement: the least-energy certificate.

``energy_lower_bound(m, dx, dy, q_best)`` proves that no configuration ``q`` of the *closed* joint range
``|q_j| <= pi - 2 beta_j`` with ``tip(q) = target`` has an energy below ``bound``; with the energy of the
best configuration known (``energy``, an upper bound: a feasible point) the *gap* ``energy - bound`` says
how far the search can be from the global minimum. ``certified`` when the gap is within ``tolerance``
(``TOL_REL |E| + TOL_ABS k c^2``).

Method (branch and bound over boxes of joint angles, bounds from the Lagrangian):

1. **Exclusion by energy.** ``E(q) = sum_j E_j(q_j)`` and each segment's least energy ``e_j`` over its
   closed range is bounded below (second-order Taylor bounds on cells of a grid). With the incumbent
   energy ``E*``, a configuration that beats it has ``E_j(q_j) <= e_j + (E* - sum e)`` for every ``j``: each
   joint lies in a few short *pieces* (around the wells of a bistable segment, around the rest angle of a
   monotonic one). Every other configuration is excluded.
2. **Pattern boxes.** The boxes are the products of the pieces (one piece per joint; ``2^n`` for a chain
   of bistable segments near its wells), enumerated in vectorised chunks.
3. **Bound of a box** ``R`` around a centre ``c``: for any ``lambda`` in ``R^2`` and every feasible ``q`` in
   ``R``, ``E(q) = E(q) - lambda . (tip(q) - T)``, and with ``e = q - c``

       E_j(c_j + e_j) >= E_j(c_j) + E_j'(c_j) e_j + 1/2 m_j e_j^2      (m_j <= E_j'' on the piece)
       -lambda . tip(c + e) >= -lambda . tip(c) - (J^T lambda) . e - 1/2 sum_i w_i e_i^2

   (the tip's Taylor remainder: ``lambda . u(phi_j) >= gamma_j`` over the box and Cauchy-Schwarz on the
   partial sums of ``e``), so the bound is a sum of one-dimensional quadratics minimised over intervals in
   closed form. ``lambda`` is chosen per box by a few Newton steps on that piecewise-quadratic dual. At a
   KKT point ``q*`` of the box with its multiplier (the tip force) the bound equals ``E(q*)`` whenever the
   Lagrangian is convex over the box (strong duality: the second-order condition holds on the whole box).
4. **Pruning and refinement.** Boxes whose bound is within the tolerance of the incumbent are closed.
   The others are re-centred by Newton on the KKT system (batched, numpy) from their centre projected on
   the tip constraint: a converged point inside the box tightens its bound (often to its own energy) and,
   when lower than the incumbent, becomes the new incumbent; boxes still open are bisected (along the joint
   whose term loses most) until ``max_boxes``.

The bound is the least of the incumbent and of the bounds of every box not closed: rigorous up to floating
point rounding, which a margin of ``ROUND_REL`` times the magnitude of the terms covers (the analytic
derivative bounds, ``|E_j''|`` and ``|E_j'''|`` over the whole range, are exact expressions of the
parameters). It certifies where the Lagrangian is convex over the boxes that compete with the incumbent:
chains of bistable segments near their wells (the least energy within ~1e-4 of the sum of the well energies;
measured: n = 8-20 in 0.01-8 s). Where a competing configuration is held in compression, the Lagrangian is
not convex over its box (the chain would buckle under that dead load: the paper's monotonic chains under
``dx > 0``, bistable chains under larger deflections) and the dual bound stays below its energy; such cases
end with a gap (``status`` ``"open"``) after the budget. The bound stays valid.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from ...errors import InvalidParameterError
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...outcome import Outcome
from ...serialize import number
from .seeds import project_to_target

__all__ = ["EnergyBound", "energy_lower_bound", "bound_tolerance", "segment_pieces", "TOL_REL", "TOL_ABS",
           "MAX_PATTERNS", "MAX_BOXES", "MAX_SECONDS"]

#: The certificate's tolerance: ``TOL_REL |E| + TOL_ABS max(k c^2)`` (energy units).
TOL_REL = 1e-7
TOL_ABS = 1e-9
#: Most products of pieces (pattern boxes) enumerated; more and the bound is the trivial one (open).
MAX_PATTERNS = 1 << 21
#: Most boxes bounded in all (patterns included) before the branch and bound stops (open).
MAX_BOXES = 1 << 16
#: Rounds of the refinement at most.
MAX_ROUNDS = 25
#: Wall-time budget (s) of the refinement.
MAX_SECONDS = 5.0
#: Boxes bounded at once (numpy arrays of CHUNK x n).
CHUNK = 1 << 15
#: Relative rounding margin subtracted from every box bound (times the magnitude of its terms).
ROUND_REL = 1e-12
#: Cells per joint of the fine bound (the refinement of the boxes the pattern sweep leaves open).
FINE = 48
#: Cells of the grid over a segment's range on which its sublevel pieces are found.
GRID = 4096


@dataclass(frozen=True)
class EnergyBound(Outcome):
    """A rigorous lower bound on the energy of every configuration meeting the tip constraint.

    Attributes
    ----------
    bound : float
        No ``q`` with ``|q_j| <= pi - 2 beta_j`` and ``tip(q) = target`` has ``E(q) < bound``.
    energy : float
        The least energy of a feasible configuration known (the incumbent, ``q``).
    gap : float
        ``energy - bound`` (>= 0).
    tolerance : float
        ``TOL_REL |energy| + TOL_ABS max(k c^2)``: ``certified`` when ``gap <= tolerance``.
    q : ndarray (n,)
        The incumbent configuration (the search's, or a better one the bound found).
    force : ndarray (2,)
        Its tip force when a Newton solve of the bound produced it, else the caller's.
    improved : bool
        The bound found a configuration of lower energy than the one it was given.
    patterns, boxes, newton : int
        Pattern boxes enumerated, boxes bounded in all, Newton re-centrings.
    seconds : float
        Wall time.
    status : str
        :attr:`STATUSES`.
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "certified": "the gap between the best energy and the rigorous lower bound is within the tolerance: "
                     "the configuration is the least-energy one up to that tolerance",
        "open": "the lower bound is rigorous but the gap exceeds the tolerance (too many pieces or boxes, or "
                "the bounds were not tight enough): the configuration is not proven least",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"certified"})

    bound: float
    energy: float
    tolerance: float
    q: np.ndarray
    force: np.ndarray
    improved: bool
    patterns: int
    boxes: int
    newton: int
    seconds: float
    status: str
    reason: str = field(default="", repr=False)

    def __post_init__(self) -> None:
        self.q.setflags(write=False)
        self.force.setflags(write=False)
        self._check_outcome()

    @property
    def gap(self) -> float:
        """``energy - bound``."""
        return max(0.0, self.energy - self.bound)

    @property
    def certified(self) -> bool:
        """``gap <= tolerance``."""
        return self.status == "certified"

    @property
    def message(self) -> str:
        """A sentence: the bound, the gap and how it was obtained."""
        how = (f"{self.patterns} pattern boxes, {self.boxes} boxes bounded, {self.newton} Newton re-centrings, "
               f"{self.seconds:.3g} s")
        if self.certified:
            return (f"certified: no configuration meeting the tip constraint in the closed joint range has an "
                    f"energy below {self.bound:.12g} (gap {self.gap:.3g} <= tolerance {self.tolerance:.3g}; {how})")
        return (f"not certified: lower bound {self.bound:.12g}, gap {self.gap:.3g} > tolerance "
                f"{self.tolerance:.3g} ({self.reason or 'bounds not tight'}; {how})")

    def to_dict(self) -> dict[str, Any]:
        """JSON form: ``success``, ``status``, ``message``, ``bound``, ``energy``, ``gap``, ``tolerance``,
        ``certified``, ``patterns``, ``boxes``, ``newton``, ``seconds``."""
        return {**self.outcome(), "bound": number(self.bound), "energy": number(self.energy),
                "gap": number(self.gap), "tolerance": number(self.tolerance), "certified": self.certified,
                "improved": bool(self.improved), "patterns": int(self.patterns), "boxes": int(self.boxes),
                "newton": int(self.newton), "seconds": number(self.seconds)}


def bound_tolerance(m: Manipulator, energy: float) -> float:
    """The certificate's tolerance ``TOL_REL |energy| + TOL_ABS max(k c^2)``."""
    return TOL_REL * abs(float(energy)) + TOL_ABS * m.torque_scale


# ----------------------------------------------------------------------------- one segment, vectorised
class _Seg:
    """A segment's energy and derivatives, vectorised over angles, with analytic bounds of ``|E''|, |E'''|``.

    Under the tension-only law (``tension``) each spring's terms are its linear ones where it is taut
    (``r = L - L0 > 0``) and zero where it is slack: ``E`` is C^1 and ``E''`` jumps where a spring goes slack. The
    curvature bounds then take each spring apart (:meth:`cell_curvature`): its linear ``E''`` (Lipschitz ``M3_i``)
    where the cell is taut throughout, 0 where slack throughout, the least of the two where it changes state."""

    def __init__(self, seg) -> None:
        self.c, self.beta = seg.c, seg.beta
        self.k1, self.k2, self.L10, self.L20 = seg.k1, seg.k2, seg.L1_0, seg.L2_0
        self.lim = seg.joint_limit
        self.tension = bool(getattr(seg, "tension_only", False))
        c = self.c
        # |L'| <= c, |L''| <= c/2, |L'''| <= c/4, |L - L0| <= 2c + L0  (L = 2c cos(beta +- q/2))
        self.M2 = sum(k * (c * c + (2 * c + L0) * c / 2) for k, L0 in ((self.k1, self.L10), (self.k2, self.L20)))
        self.M3s = tuple(k * (1.5 * c * c + (2 * c + L0) * c / 4)
                         for k, L0 in ((self.k1, self.L10), (self.k2, self.L20)))
        self.M3 = sum(self.M3s)

    def _springs(self, q: np.ndarray):
        """Per spring: ``r = L - L0``, ``L'``, ``L''`` at ``q``."""
        c, b = self.c, self.beta
        a1, a2 = b + q / 2.0, b - q / 2.0
        return ((2 * c * np.cos(a1) - self.L10, -c * np.sin(a1), -0.5 * c * np.cos(a1)),
                (2 * c * np.cos(a2) - self.L20, c * np.sin(a2), -0.5 * c * np.cos(a2)))

    def derivs(self, q: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``E, E', E''`` at ``q`` (the one-sided ``E''`` of the slack side at a spring's rest length)."""
        (r1, d1, s1), (r2, d2, s2) = self._springs(q)
        if not self.tension:
            E = 0.5 * self.k1 * r1 * r1 + 0.5 * self.k2 * r2 * r2
            E1 = self.k1 * r1 * d1 + self.k2 * r2 * d2
            E2 = self.k1 * (d1 * d1 + r1 * s1) + self.k2 * (d2 * d2 + r2 * s2)
            return E, E1, E2
        E = E1 = E2 = 0.0
        for k, r, d, s in ((self.k1, r1, d1, s1), (self.k2, r2, d2, s2)):
            t = r > 0.0
            rp = np.where(t, r, 0.0)
            E = E + 0.5 * k * rp * rp
            E1 = E1 + k * rp * d
            E2 = E2 + np.where(t, k * (d * d + r * s), 0.0)
        return E, E1, E2

    def cell_curvature(self, mid: np.ndarray, half: np.ndarray) -> np.ndarray:
        """A lower bound of ``E''`` over each cell ``[mid - half, mid + half]`` (elementwise), before the rounding
        margin: ``E''(mid) - M3 half`` under the linear law; under the tension-only law per spring as in the class
        docstring (``L`` is concave in ``q`` over the closed range, so ``r``'s least value over a cell is at an end,
        its largest at an end or at the top ``q = -+2 beta``)."""
        if not self.tension:
            return self.derivs(mid)[2] - self.M3 * half
        out = 0.0
        lo, hi = mid - half, mid + half
        for i, (k, M3, L0) in enumerate(zip((self.k1, self.k2), self.M3s, (self.L10, self.L20))):
            r, d, s = self._springs(mid)[i]
            lin = k * (d * d + r * s) - M3 * half
            rlo, rhi = self._springs(lo)[i][0], self._springs(hi)[i][0]
            top = -2.0 * self.beta if i == 0 else 2.0 * self.beta
            rmax = np.where((lo < top) & (top < hi), 2 * self.c - L0, np.maximum(rlo, rhi))
            slack_somewhere = np.minimum(rlo, rhi) <= 0.0
            taut_somewhere = rmax > 0.0
            out = out + np.where(~taut_somewhere, 0.0, np.where(slack_somewhere, np.minimum(lin, 0.0), lin))
        return out

    def curvature_lower(self, lo: np.ndarray, hi: np.ndarray, parts: int = 4) -> np.ndarray:
        """A lower bound of ``E''`` over each ``[lo, hi]`` (``parts`` sub-intervals, Lipschitz ``M3``)."""
        w = (hi - lo) / parts
        out = np.full(np.shape(lo), np.inf)
        for p in range(parts):
            mid = lo + (p + 0.5) * w
            out = np.minimum(out, self.cell_curvature(mid, 0.5 * w))
        return out - ROUND_REL * self.M2


def _quad_min(t: np.ndarray, a: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Minimum and minimiser of ``t e + a e^2 / 2`` over ``e in [lo, hi]`` (elementwise; ``lo <= 0 <= hi``)."""
    flo = t * lo + 0.5 * a * lo * lo
    fhi = t * hi + 0.5 * a * hi * hi
    e = np.where(flo <= fhi, lo, hi)
    f = np.minimum(flo, fhi)
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.where(a > 0, -t / np.where(a > 0, a, 1.0), np.nan)
    inside = (a > 0) & (s > lo) & (s < hi)
    fs = np.where(inside, 0.5 * t * np.where(inside, s, 0.0), np.inf)     # t s + a s^2 / 2 = t s / 2
    better = fs < f
    return np.where(better, fs, f), np.where(better, s, e)


@dataclass
class _Pieces:
    """Per joint: the pieces (intervals) of its sublevel set, their centres and curvature lower bounds."""

    lo: list[np.ndarray]
    hi: list[np.ndarray]
    centre: list[np.ndarray]
    curv: list[np.ndarray]
    emin: np.ndarray            # per joint: a lower bound of min E_j over the closed range


def segment_pieces(seg, budget: float, grid: int = GRID) -> tuple[float, np.ndarray]:
    """A rigorous lower bound of a segment's least energy over its closed range, and the intervals (rows
    ``[lo, hi]``) outside which its energy exceeds that bound plus ``budget``.

    Each of ``grid`` cells is bounded below by the second-order Taylor model at its midpoint with the curvature
    bounded below by ``E''(mid) - M3 h/2`` (:func:`_quad_min`); cells whose bound is within ``budget`` of the least
    one are kept and merged into intervals (the closed range: the end cells reach ``+-(pi - 2 beta)``).
    """
    S = seg if isinstance(seg, _Seg) else _Seg(seg)
    return _segment_pieces(S, budget, grid)[:2]


def _segment_pieces(S: _Seg, budget: float, grid: int):
    edges = np.linspace(-S.lim, S.lim, grid + 1)
    lo, hi = edges[:-1], edges[1:]
    mid = 0.5 * (lo + hi)
    h2 = 0.5 * (hi - lo)
    E, E1, E2 = S.derivs(mid)
    m = S.cell_curvature(mid, h2)
    low, _ = _quad_min(E1, m, -h2, h2)
    cell = E + low - ROUND_REL * (abs(E) + S.M2 * (1 + S.lim ** 2))
    emin = float(cell.min())
    keep = cell <= emin + budget
    idx = np.flatnonzero(keep)
    runs = np.split(idx, np.flatnonzero(np.diff(idx) > 1) + 1)
    iv = np.array([[lo[r[0]], hi[r[-1]]] for r in runs if r.size])
    cen = []
    for r in runs:
        if not r.size:
            continue
        j = r[np.argmin(E[r])]
        # the centre: the cell's Taylor minimiser (near the segment's local minimum), inside the piece
        cen.append(float(np.clip(mid[j] - (E1[j] / E2[j] if E2[j] > 0 else 0.0), lo[r[0]], hi[r[-1]])))
    return emin, iv, np.array(cen)


def _pieces(m: Manipulator, segs: list[_Seg], incumbent: float, emin_cache: dict) -> _Pieces | None:
    """Each joint's pieces for the incumbent energy (None: a joint has none, impossible for a valid incumbent)."""
    emins = []
    for S in segs:
        key = id(S)
        if key not in emin_cache:
            emin_cache[key] = _segment_pieces(S, 0.0, GRID)[0]
        emins.append(emin_cache[key])
    emin = np.array(emins)
    budget = incumbent - float(emin.sum())
    budget = max(budget, 0.0) * (1 + 1e-12) + 1e-15 * m.torque_scale
    P = _Pieces([], [], [], [], emin)
    cache: dict[int, tuple] = {}
    for S in segs:
        if id(S) not in cache:
            _, iv, cen = _segment_pieces(S, budget, GRID)
            curv = S.curvature_lower(iv[:, 0], iv[:, 1], parts=16) if iv.size else np.zeros(0)
            cache[id(S)] = (iv, cen, curv)
        iv, cen, curv = cache[id(S)]
        if not iv.size:
            return None
        P.lo.append(iv[:, 0])
        P.hi.append(iv[:, 1])
        P.centre.append(cen)
        P.curv.append(curv)
    return P


# ----------------------------------------------------------------------------- the chain, vectorised
class _Chain:
    def __init__(self, m: Manipulator, target: np.ndarray) -> None:
        self.m = m
        self.n = m.n
        self.l = m.link_lengths
        self.base = m.base_length
        self.T = np.asarray(target, dtype=float)
        uniq: dict = {}
        self.segs = [uniq.setdefault(s, _Seg(s)) for s in m.segments]
        self.groups: dict[int, list[int]] = {}
        for j, S in enumerate(self.segs):
            self.groups.setdefault(id(S), []).append(j)
        self.M2 = np.array([S.M2 for S in self.segs])

    def derivs(self, Q: np.ndarray):
        E = np.empty_like(Q)
        E1 = np.empty_like(Q)
        E2 = np.empty_like(Q)
        for js in self.groups.values():
            E[:, js], E1[:, js], E2[:, js] = self.segs[js[0]].derivs(Q[:, js])
        return E, E1, E2

    def curvature_lower(self, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
        out = np.empty_like(lo)
        for js in self.groups.values():
            out[:, js] = self.segs[js[0]].curvature_lower(lo[:, js], hi[:, js])
        return out

    # ------------------------------------------------------------------ the bound of boxes
    def bound(self, lo, hi, C, lam0: np.ndarray | None, curv=None, iters: int = 5, fine: int = 0):
        """Rigorous lower bounds of ``E`` over the feasible points of each box (rows), and the multipliers used.

        ``fine == 0``: each joint's energy bounded below by its second-order Taylor model at the centre with
        the curvature bound ``curv`` (cheap: the pattern sweep). ``fine > 0``: each joint's one-dimensional
        term ``E_j(q) - tau_j (q - c_j) - w_j (q - c_j)^2 / 2`` minimised over ``fine`` cells of its interval,
        each bounded by its own second-order model (error ``O(M3 h^3)``: the refinement)."""
        B, n = lo.shape
        E, g, _ = self.derivs(C)
        cphi, sphi, tip, Jx, Jy = self.m.tip_kinematics(C)
        d = tip - self.T
        elo, ehi = lo - C, hi - C
        rho = np.maximum(np.maximum(-elo, ehi), 1e-300)
        R = np.cumsum(rho, axis=1)
        reach = float(self.l.sum()) + float(np.abs(self.T).sum()) + self.base
        if fine:
            h = (hi - lo) / fine                                            # (B, n)
            mids = lo[:, :, None] + (np.arange(fine) + 0.5) * h[:, :, None]  # (B, n, G)
            Em = np.empty_like(mids)
            E1m = np.empty_like(mids)
            E2m = np.empty_like(mids)
            for js in self.groups.values():
                S = self.segs[js[0]]
                Em[:, js], E1m[:, js], _ = S.derivs(mids[:, js])
                half = np.broadcast_to(0.5 * h[:, js, None], mids[:, js].shape)
                E2m[:, js] = S.cell_curvature(mids[:, js], half) - ROUND_REL * S.M2
            em = mids - C[:, :, None]
            hh = 0.5 * h[:, :, None]
            scale0 = np.abs(Em).max(axis=2).sum(axis=1) + self.M2.sum() * (1.0 + (rho * rho).sum(axis=1))
        else:
            if curv is None:
                curv = self.curvature_lower(lo, hi)
            scale0 = np.abs(E).sum(axis=1) + self.M2.sum() * (1.0 + (rho * rho).sum(axis=1))
        E0 = E.sum(axis=1)

        def evaluate(lam):
            ln = np.hypot(lam[:, 0], lam[:, 1])
            gamma = lam[:, :1] * cphi + lam[:, 1:] * sphi - ln[:, None] * R
            neg = np.maximum(0.0, -gamma) * self.l * R
            w = np.cumsum(neg[:, ::-1], axis=1)[:, ::-1] / rho
            tau = Jx * lam[:, :1] + Jy * lam[:, 1:]
            if fine:
                t3, w3 = tau[:, :, None], w[:, :, None]
                f0 = Em - t3 * em - 0.5 * w3 * em * em
                f1 = E1m - t3 - w3 * em
                fc, ec = _quad_min(f1, E2m - w3, -hh, hh)
                cell = f0 + fc
                k = np.argmin(cell, axis=2)
                f = np.take_along_axis(cell, k[:, :, None], axis=2)[:, :, 0]
                e = np.take_along_axis(em + ec, k[:, :, None], axis=2)[:, :, 0]
                a = np.take_along_axis(E2m, k[:, :, None], axis=2)[:, :, 0] - w
                t = np.take_along_axis(f1, k[:, :, None], axis=2)[:, :, 0]
                val = -(lam * d).sum(axis=1) + f.sum(axis=1)
            else:
                a = curv - w
                t = g - tau
                f, e = _quad_min(t, a, elo, ehi)
                val = E0 - (lam * d).sum(axis=1) + f.sum(axis=1)
            margin = ROUND_REL * (scale0 + ln * reach * (1.0 + R[:, -1]) + (np.abs(t) * rho).sum(axis=1)) * n
            return val - margin, a, t, e

        lam = np.zeros((B, 2)) if lam0 is None else np.array(np.broadcast_to(lam0, (B, 2)), dtype=float)
        best, a, t, e = evaluate(lam)
        best_lam = lam.copy()
        if lam0 is not None and fine:              # lambda = 0: the sum of the joints' own minima over the box
            v0 = evaluate(np.zeros((B, 2)))[0]
            up = v0 > best
            best = np.where(up, v0, best)
            best_lam[up] = 0.0
        for _ in range(iters):
            # Newton step on the piecewise-quadratic dual: gradient -d - J e, Hessian -sum_free J J^T / a
            free = (a > 0) & (e > elo + 1e-15) & (e < ehi - 1e-15)
            ia = np.where(free, 1.0 / np.where(free, a, 1.0), 0.0)
            gx = -d[:, 0] - (Jx * e).sum(axis=1)
            gy = -d[:, 1] - (Jy * e).sum(axis=1)
            hxx = (Jx * Jx * ia).sum(axis=1)
            hxy = (Jx * Jy * ia).sum(axis=1)
            hyy = (Jy * Jy * ia).sum(axis=1)
            reg = 1e-9 * (hxx + hyy) + 1e-300
            hxx, hyy = hxx + reg, hyy + reg
            det = hxx * hyy - hxy * hxy
            ok = det > 1e-14 * hxx * hyy
            det = np.where(ok, det, 1.0)
            dlx = np.where(ok, (hyy * gx - hxy * gy) / det, 0.0)
            dly = np.where(ok, (hxx * gy - hxy * gx) / det, 0.0)
            step = np.stack([dlx, dly], axis=1)
            cand = lam + step
            val, a2, t2, e2 = evaluate(cand)
            worse = ~(val > best)
            if worse.any():                        # a damped step where the full one does not improve
                half = lam + 0.25 * step
                v2, a3, t3_, e3 = evaluate(half)
                pick = worse & (v2 > val)
                cand = np.where(pick[:, None], half, cand)
                val = np.where(pick, v2, val)
                a2 = np.where(pick[:, None], a3, a2)
                e2 = np.where(pick[:, None], e3, e2)
            lam, a, e = cand, a2, e2
            up = val > best
            best = np.where(up, val, best)
            best_lam[up] = lam[up]
        return best, best_lam

    def infeasible(self, lo, hi, C, directions: int = 8) -> np.ndarray:
        """Boxes proven to hold no configuration with the tip at the target: along some direction ``v`` the
        target's projection lies beyond ``max v . tip`` over the box, bounded link by link (each link's angle
        ``phi_j`` ranges over the interval of the partial sums of the joint intervals)."""
        Plo, Phi = np.cumsum(lo, axis=1), np.cumsum(hi, axis=1)
        tip = self.m.tip_kinematics(C)[2]
        thetas = [np.full(lo.shape[0], 2 * math.pi * k / directions) for k in range(directions)]
        dd = self.T - tip
        thetas.append(np.arctan2(dd[:, 1], dd[:, 0]))
        out = np.zeros(lo.shape[0], dtype=bool)
        reach = float(self.l.sum()) + self.base + float(np.abs(self.T).sum())
        for th in thetas:
            a, b = Plo - th[:, None], Phi - th[:, None]
            k = np.ceil(a / (2 * math.pi))
            top = np.where(2 * math.pi * k <= b, 1.0, np.maximum(np.cos(a), np.cos(b)))
            vmax = self.base * np.cos(th) + (self.l * top).sum(axis=1)
            vT = self.T[0] * np.cos(th) + self.T[1] * np.sin(th)
            out |= vT > vmax + 1e-12 * reach
        return out

    # ------------------------------------------------------------------ batched Newton on the KKT system
    def newton(self, Q0: np.ndarray, iters: int = 40, tol: float = 1e-12):
        """Newton on ``grad E = J^T lambda``, ``tip = T`` from each row (projected onto the tip first); the
        converged rows ``(Q, lambda, ok)`` (``ok``: residual below ``tol`` scaled, inside the closed range)."""
        n = self.n
        Q = np.array(Q0, dtype=float)
        B = Q.shape[0]
        lam = np.zeros((B, 2))
        lim = self.m.joint_limits
        ts = self.m.torque_scale
        scale = float(self.m.b.sum())
        idx = np.maximum.outer(np.arange(n), np.arange(n))
        ok = np.zeros(B, dtype=bool)
        for it in range(iters):
            _, g, h = self.derivs(Q)
            cphi, sphi, tip, Jx, Jy = self.m.tip_kinematics(Q)
            r1 = g - Jx * lam[:, :1] - Jy * lam[:, 1:]
            r2 = tip - self.T
            res = np.maximum(np.abs(r1).max(axis=1) / ts, np.abs(r2).max(axis=1) / scale)
            ok = np.isfinite(res) & (res < tol)
            if it == iters - 1 or ok.all():
                break
            if it == 0:             # the multiplier that best balances the torques at the start
                axx, axy, ayy = (Jx * Jx).sum(axis=1), (Jx * Jy).sum(axis=1), (Jy * Jy).sum(axis=1)
                bx, by = (Jx * g).sum(axis=1), (Jy * g).sum(axis=1)
                det = axx * ayy - axy * axy
                det = np.where(det > 1e-14 * axx * ayy, det, np.inf)
                lam = np.stack([(ayy * bx - axy * by) / det, (axx * by - axy * bx) / det], axis=1)
                continue
            wgt = self.l * (lam[:, :1] * cphi + lam[:, 1:] * sphi)   # lambda . l_j u(phi_j)
            cw = np.cumsum(wgt[:, ::-1], axis=1)[:, ::-1]
            K = np.zeros((B, n + 2, n + 2))
            K[:, :n, :n] = cw[:, idx]
            K[:, np.arange(n), np.arange(n)] += h
            K[:, :n, n] = -Jx
            K[:, :n, n + 1] = -Jy
            K[:, n, :n] = Jx
            K[:, n + 1, :n] = Jy
            rhs = -np.concatenate([r1, r2], axis=1)
            try:
                step = np.linalg.solve(K, rhs[:, :, None])[:, :, 0]
            except np.linalg.LinAlgError:
                step = np.stack([np.linalg.lstsq(K[i], rhs[i], rcond=None)[0] for i in range(B)])
            big = np.abs(step[:, :n]).max(axis=1)
            fac = np.minimum(1.0, 0.3 / np.maximum(big, 1e-300))[:, None]
            step = np.where(np.isfinite(step), step, 0.0) * fac
            Q = Q + step[:, :n]
            lam = lam + step[:, n:]
        ok &= np.all(np.abs(Q) <= lim, axis=1)
        return Q, lam, ok


def energy_lower_bound(m: Manipulator, dx: float, dy: float = 0.0, q_best: Any = None, *,
                       force: Any = None, max_patterns: int = MAX_PATTERNS, max_boxes: int = MAX_BOXES,
                       max_seconds: float = MAX_SECONDS, fine: int = FINE, max_rounds: int = MAX_ROUNDS
                       ) -> EnergyBound:
    """A rigorous lower bound on ``E(q)`` over every ``q`` of the closed joint range with the tip at the target
    of ``(dx, dy)``, and the best feasible configuration known (method: the module's docstring).

    Parameters
    ----------
    m : Manipulator
    dx, dy : float
        Tip deflection (the tip at ``(2 sum(b) - dx, dy)``).
    q_best : array_like (n,), optional
        A feasible configuration (the search's answer): its energy is the incumbent that prunes. Without it
        the bound starts from its own Newton solves from the pattern boxes.
    force : array_like (2,), optional
        ``q_best``'s tip force (the first multiplier tried in each box).
    max_patterns, max_boxes : int
        Limits of the enumeration (beyond them ``status`` is ``"open"``).
    max_seconds : float
        Wall-time budget of the refinement (checked between rounds; the pattern sweep always completes):
        when spent, ``status`` is ``"open"`` with the bound reached.
    max_rounds : int
        Rounds of the refinement (Newton re-centring, bound, bisection) at most: a limit on the work that does not
        depend on the machine's speed (the default search's short sweep uses a few).
    fine : int
        Cells per joint of the refinement's bound (fewer: cheaper and looser; the default search's short
        pattern sweep uses a few to find lower configurations, not to certify).

    Returns
    -------
    EnergyBound
        ``bound``, ``energy``, ``gap``, ``tolerance``, ``status`` (``"certified"`` or ``"open"``).
    """
    unloaded_only(m, "energy_lower_bound")
    t0 = time.perf_counter()
    target = m.check_reachable(dx, dy)
    ch = _Chain(m, target)
    n = m.n
    if q_best is not None:
        q_best = np.asarray(q_best, dtype=float).reshape(n)
        if not np.all(np.abs(q_best) <= m.joint_limits) or \
                np.abs(m.tip(q_best) - target).max() > 1e-9 * float(m.b.sum()):
            raise InvalidParameterError("q_best must meet the tip constraint inside the joint range", field="q_best")
        inc_q, inc_e = q_best.copy(), m.energy(q_best)
        inc_f = np.zeros(2) if force is None else np.asarray(force, dtype=float).reshape(2)
    else:
        inc_q, inc_e, inc_f = None, math.inf, np.zeros(2)
    improved = False
    counts = {"patterns": 0, "boxes": 0, "newton": 0}
    emin_cache: dict = {}

    def result(bound: float, status: str, why: str = "") -> EnergyBound:
        if inc_q is None:
            return EnergyBound(bound=bound, energy=math.inf, tolerance=math.inf, q=np.full(n, np.nan),
                               force=np.full(2, np.nan), improved=False, seconds=time.perf_counter() - t0,
                               status="open", reason=why or "no feasible configuration found", **counts)
        return EnergyBound(bound=min(bound, inc_e), energy=inc_e, tolerance=bound_tolerance(m, inc_e),
                           q=inc_q.copy(), force=np.asarray(inc_f, float).copy(), improved=improved,
                           seconds=time.perf_counter() - t0, status=status, reason=why, **counts)

    if inc_q is not None and (n == 1 or (float(dx) == 0.0 and float(dy) == 0.0)):
        # one configuration meets the constraint: the single joint's angle fixed by the target, or the straight
        # chain (the only one reaching full extension): its energy is the least
        return result(inc_e, "certified")
    if inc_q is None:
        # no incumbent: Newton from the well patterns' centres of a budget-free enumeration is the caller's job
        emins = [_segment_pieces(S, 0.0, GRID)[0] for S in ch.segs]
        return result(float(sum(emins)), "open", "no feasible configuration given")

    P = _pieces(m, ch.segs, inc_e, emin_cache)
    trivial = float(P.emin.sum())
    sizes = [len(x) for x in P.lo]
    total = math.prod(sizes)
    if total > max_patterns:
        return result(trivial, "open", f"{total} pattern boxes exceed max_patterns = {max_patterns}")
    tol = bound_tolerance(m, inc_e)
    low = math.inf                       # least bound of the boxes closed so far (capped at the incumbent)
    pmax = max(sizes)
    pad = lambda arrs: np.array([np.pad(a, (0, pmax - len(a)), mode="edge") for a in arrs])   # noqa: E731
    Plo, Phi, Pc, Pk = pad(P.lo), pad(P.hi), pad(P.centre), pad(P.curv)
    radix = np.array(sizes)
    cols = np.arange(n)
    open_boxes: list[tuple[np.ndarray, ...]] = []

    def new_incumbent(Q, lam, ok, lo=None, hi=None):
        nonlocal inc_q, inc_e, inc_f, improved
        if not ok.any():
            return
        Eq = ch.derivs(Q)[0].sum(axis=1)
        Eq = np.where(ok, Eq, np.inf)
        j = int(np.argmin(Eq))
        if Eq[j] < inc_e - 1e-13 * max(1.0, abs(inc_e)):
            inc_q, inc_e, inc_f, improved = Q[j].copy(), float(m.energy(Q[j])), lam[j].copy(), True

    for start in range(0, total, CHUNK):
        ids = np.arange(start, min(total, start + CHUNK))
        digits = np.empty((ids.size, n), dtype=np.int64)
        rem = ids.copy()
        for j in range(n - 1, -1, -1):
            rem, digits[:, j] = np.divmod(rem, radix[j])
        lo, hi, C, K = Plo[cols, digits], Phi[cols, digits], Pc[cols, digits], Pk[cols, digits]
        counts["patterns"] += ids.size
        counts["boxes"] += ids.size
        bnd, lam = ch.bound(lo, hi, C, np.broadcast_to(inc_f, (ids.size, 2)), curv=K, iters=1)
        op = bnd < inc_e - 0.5 * tol
        if op.any():                               # more dual steps where one did not close the box
            b2, l2 = ch.bound(lo[op], hi[op], C[op], lam[op], curv=K[op], iters=6)
            bnd[op], lam[op] = np.maximum(bnd[op], b2), np.where((b2 > bnd[op])[:, None], l2, lam[op])
            op = bnd < inc_e - 0.5 * tol
        if op.any():
            bnd[np.flatnonzero(op)[ch.infeasible(lo[op], hi[op], C[op])]] = math.inf
        shut = bnd >= inc_e - 0.5 * tol
        if shut.any():
            low = min(low, float(bnd[shut].min()))
        keep = ~shut
        if keep.any():
            open_boxes.append((lo[keep], hi[keep], C[keep], lam[keep], bnd[keep]))

    # refinement: Newton re-centring, then bisection
    rounds = 0
    while open_boxes:
        lo = np.concatenate([b[0] for b in open_boxes])
        hi = np.concatenate([b[1] for b in open_boxes])
        C = np.concatenate([b[2] for b in open_boxes])
        lam = np.concatenate([b[3] for b in open_boxes])
        bnd = np.concatenate([b[4] for b in open_boxes])
        open_boxes = []
        keep = bnd < inc_e - 0.5 * tol            # the incumbent may have dropped since
        if (~keep).any():
            low = min(low, float(bnd[~keep].min()))
        lo, hi, C, lam, bnd = lo[keep], hi[keep], C[keep], lam[keep], bnd[keep]
        if not lo.shape[0]:
            break
        if counts["boxes"] + 2 * lo.shape[0] > max_boxes or rounds >= max_rounds:
            return result(min(low, float(bnd.min())), "open", f"{lo.shape[0]} boxes still open at max_boxes")
        if time.perf_counter() - t0 > max_seconds:
            return result(min(low, float(bnd.min())), "open", f"{lo.shape[0]} boxes still open at max_seconds")
        rounds += 1
        # Newton from the centres projected onto the tip constraint (rows that do not project keep the centre)
        Qs = project_to_target(m, C, target, tol=1e-13, drop=False)
        Qn, ln, okn = ch.newton(Qs)
        counts["newton"] += Qs.shape[0]
        new_incumbent(Qn, ln, okn)
        if time.perf_counter() - t0 > max_seconds:
            return result(min(low, float(bnd.min())), "open", f"{lo.shape[0]} boxes still open at max_seconds")
        C2 = np.where(okn[:, None], np.clip(Qn, lo, hi), C)
        lam2 = np.where(okn[:, None], ln, lam)
        counts["boxes"] += lo.shape[0]
        b2, l2 = ch.bound(lo, hi, C2, lam2, fine=fine)
        up = b2 > bnd
        bnd = np.where(up, b2, bnd)
        lam = np.where(up[:, None], l2, lam)
        C = np.where(up[:, None], C2, C)
        tol = bound_tolerance(m, inc_e)
        shut = bnd >= inc_e - 0.5 * tol
        if shut.any():
            low = min(low, float(bnd[shut].min()))
        lo, hi, C, lam, bnd = lo[~shut], hi[~shut], C[~shut], lam[~shut], bnd[~shut]
        if not lo.shape[0]:
            break
        if rounds >= max_rounds:                   # the last round: no children to bound
            return result(min(low, float(bnd.min())), "open", f"{lo.shape[0]} boxes still open at max_rounds")
        # bisect each open box along its widest joint (relative to the joint's curvature loss)
        width = hi - lo
        j = np.argmax(width * (1.0 + np.abs(C - 0.5 * (lo + hi))), axis=1)
        r = np.arange(lo.shape[0])
        mid = 0.5 * (lo[r, j] + hi[r, j])
        lo_a, hi_a, lo_b, hi_b = lo.copy(), hi.copy(), lo.copy(), hi.copy()
        hi_a[r, j] = mid
        lo_b[r, j] = mid
        for L, H in ((lo_a, hi_a), (lo_b, hi_b)):
            Cc = np.clip(C, L, H)
            counts["boxes"] += L.shape[0]
            if time.perf_counter() - t0 > max_seconds:
                return result(min(low, float(bnd.min())), "open", f"{lo.shape[0]} boxes still open at max_seconds")
            b, lb = ch.bound(L, H, Cc, lam, fine=fine)
            b[ch.infeasible(L, H, Cc)] = math.inf
            up = bnd > b                           # a child's bound is at least its parent's
            open_boxes.append((L, H, Cc, np.where(up[:, None], lam, lb), np.where(up, bnd, b)))
    bound = min(low, inc_e)
    status = "certified" if inc_e - bound <= tol else "open"
    return result(bound, status, "" if status == "certified" else "bounds not tight")


