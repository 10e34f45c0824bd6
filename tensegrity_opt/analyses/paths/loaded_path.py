"""The dead-load path of a chain with dead loads, from a stable pose to its first loss of stability.

A chain carrying weights (``Manipulator(..., gravity=)``) or joint forces rests sagged, not straight: its stability
limit under a growing tip load is a limit-load problem from that configuration, not the straight chain's buckling
(``docs/model.md``, "Weights and loads"). :func:`loaded_limit` follows ``F = base + t d`` from the pose by
natural-parameter continuation in ``t``: each point predicted along the branch's tangent
(``H_ff dq/dt = (J^T d)_f``), then corrected by Newton's method on the free joints' rows
``d(E + V)/dq - J^T F = 0`` (the closed-range route's derivatives, :mod:`tensegrity_opt.numerics.slack_nlp`; a joint
resting on its stop held there), the step halved where Newton fails or lands far from the prediction (another
branch), and the smallest eigenvalue ``lambda`` of the Hessian of ``E + V - F . tip`` on the free joints watched:

* a **fold** (the arm snaps through): the path ends, no equilibrium near the last point for a slightly larger
  load; the step is halved down to ``LOAD_TOL`` relative and the last converged load reported;
* a **bifurcation** (it buckles): the path goes on but ``lambda`` changes sign; the load where it is zero is bisected
  to ``LOAD_TOL`` (a fold reached from its unstable side is told apart: past it no equilibrium is near).

Where a free joint reaches its range bound, or ``t`` reaches ``max_load``, there is no limit (``kind "none"``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from ...model.manipulator import Manipulator
from ...numerics.slack_nlp import slack_nlp
from ...timelimit import check_time
from ..equilibria.equilibrium import Equilibrium

__all__ = ["LoadedLimit", "loaded_limit", "weight_limit", "LOAD_TOL"]

#: The limit load is located to this, relative to ``max_load``.
LOAD_TOL = 1e-9
#: Points of the path at most (each a Newton solve).
MAX_STEPS = 2000
#: A step moving a joint by more than this (rad) is a jump off the branch: halved.
JUMP = 0.2
#: Newton iterations per point at most.
NEWTON_ITER = 30


@dataclass(frozen=True)
class LoadedLimit:
    """One direction's path: ``kind`` (``"fold"``, ``"bifurcation"`` or ``"none"``), ``load`` (``t`` at the limit,
    NaN for none), ``end_load`` (the last ``t`` on the stable path), ``q`` (there), ``reason`` (for none:
    ``"joint_limit"`` or ``"max_load"``), ``points`` (Newton solves)."""

    kind: str
    load: float
    end_load: float
    q: np.ndarray
    reason: str | None
    points: int


class _Solved(NamedTuple):
    """One corrector's answer: ``q`` and the smallest Hessian eigenvalue ``lam`` of the equilibrium found, or ``q``
    None where Newton failed; ``left``: it failed by leaving the joint range (a joint reaching its bound ends the path
    there, not a fold)."""

    q: np.ndarray | None
    lam: float = math.nan
    left: bool = False


_FAILED = _Solved(None)
_LEFT_RANGE = _Solved(None, left=True)


def _newton(m: Manipulator, nlp, q: np.ndarray, F: np.ndarray, free: np.ndarray) -> _Solved:
    """The equilibrium under ``F`` near ``q`` (the free joints moved) by Newton's method (:class:`_Solved`)."""
    idx = np.flatnonzero(free)
    lim = m.joint_limits
    scale = m.torque_scale
    q = q.copy()
    if np.any(np.abs(q[idx]) > lim[idx]):      # a start (the predictor) beyond the range: never an answer there
        return _LEFT_RANGE
    for _ in range(NEWTON_ITER):
        _, g, H, _, J = nlp.derivatives(m, q, F)
        r = (g - J.T @ F)[idx]
        if float(np.abs(r).max(initial=0.0)) <= 1e-12 * scale:
            w = np.linalg.eigvalsh(H[np.ix_(idx, idx)]) if idx.size else np.zeros(1)
            return _Solved(q, float(w[0]))
        try:
            step = np.linalg.solve(H[np.ix_(idx, idx)], -r)
        except np.linalg.LinAlgError:
            return _FAILED
        if not np.all(np.isfinite(step)) or float(np.abs(step).max(initial=0.0)) > JUMP:
            return _FAILED
        q[idx] += step
        if np.any(np.abs(q) > lim):
            return _LEFT_RANGE
    return _FAILED


def _tangent(m: Manipulator, nlp, q: np.ndarray, F: np.ndarray, dr_dt: np.ndarray, free: np.ndarray) -> np.ndarray:
    """``dq/dt`` along the path at ``q`` (the free joints): ``H_ff dq = -(dr/dt)_f``; zeros where ``H`` is
    singular."""
    idx = np.flatnonzero(free)
    _, _, H, _, _ = nlp.derivatives(m, q, F)
    out = np.zeros_like(q)
    try:
        out[idx] = np.linalg.solve(H[np.ix_(idx, idx)], -dr_dt[idx])
    except np.linalg.LinAlgError:
        pass
    return out if np.all(np.isfinite(out)) else np.zeros_like(q)


class _TipLoad:
    """The path ``F = base + t d`` of a tip load on the chain ``m``."""

    def __init__(self, m: Manipulator, base: np.ndarray, d: np.ndarray) -> None:
        self.m, self.base, self.d = m, np.asarray(base, float), np.asarray(d, float)

    def at(self, t: float) -> tuple[Manipulator, np.ndarray]:
        return self.m, self.base + t * self.d

    def dr_dt(self, q: np.ndarray, t: float) -> np.ndarray:
        return -self.m.jacobian(q).T @ self.d          # r = grad(E + V) - J^T F


class _Weight:
    """The path of the chain's weights scaled by ``1 + t`` (gravity's magnitude; the joint forces and the tip load
    ``base`` held)."""

    def __init__(self, m: Manipulator, base: np.ndarray) -> None:
        self.m, self.base = m, np.asarray(base, float)
        self.unit = Manipulator(m.segments, m.payload, m.gravity)          # the weights alone, at factor 1
        self._chains: dict[float, Manipulator] = {}

    def at(self, t: float) -> tuple[Manipulator, np.ndarray]:
        mt = self._chains.get(t)
        if mt is None:
            g = self.m.gravity
            mt = Manipulator(self.m.segments, self.m.payload, (g[0] * (1.0 + t), g[1] * (1.0 + t)),
                             self.m.joint_forces)
            self._chains = {t: mt}
        return mt, self.base

    def dr_dt(self, q: np.ndarray, t: float) -> np.ndarray:
        return self.unit.load_gradient(q)


def loaded_limit(m: Manipulator, start: Equilibrium, base: np.ndarray, direction: np.ndarray,
                 max_load: float) -> LoadedLimit:
    """The path ``F = base + t d`` from the stable ``start`` (an equilibrium of ``m`` under ``base``, tip free) to
    its first loss of stability (module docstring)."""
    return _follow(_TipLoad(m, base, direction), start, max_load)


def weight_limit(m: Manipulator, start: Equilibrium, base: np.ndarray, max_factor: float) -> LoadedLimit:
    """The path of the chain's weights growing, gravity scaled by ``1 + t`` from the stable ``start`` (tip free
    under ``base``), ``t`` up to ``max_factor - 1``, to its first loss of stability: ``load`` is ``t`` there (the
    weights may grow by that fraction). ``m`` must have ``gravity``."""
    return _follow(_Weight(m, base), start, max_factor - 1.0)


def _follow(path, start: Equilibrium, max_load: float) -> LoadedLimit:
    """Follow ``path`` (``at(t) -> (chain, F)``, ``dr_dt(q, t)``) from ``start`` to its first loss of stability
    (module docstring)."""
    m0, _ = path.at(0.0)
    nlp = slack_nlp(m0.n, True)
    free = ~np.asarray(start.at_stop, bool)
    lim = m0.joint_limits
    q, t = np.asarray(start.q, float).copy(), 0.0
    h = max_load / 50.0
    tol = LOAD_TOL * max_load
    points = 0

    def solve(qs: np.ndarray, tt: float) -> _Solved:
        mt, F = path.at(tt)
        return _newton(mt, nlp, qs, F, free)

    while t < max_load and points < MAX_STEPS:
        check_time("the load path")
        tn = min(t + h, max_load)
        mt, F = path.at(t)
        qp = q + (tn - t) * _tangent(mt, nlp, q, F, path.dr_dt(q, t), free)     # the predictor: the branch's tangent
        res = solve(qp, tn)
        points += 1
        if res.q is not None and float(np.abs(res.q - qp).max()) > max(0.25 * float(np.abs(qp - q).max()), 1e-6):
            res = _FAILED                       # the corrector went far from the prediction: another branch, shorter
        if res.q is None:
            if h <= tol:                        # no equilibrium near for any larger load: the range ends, or a fold
                if res.left or np.any(np.abs(q[free]) > lim[free] * (1.0 - 1e-3)):
                    return LoadedLimit("none", np.nan, t, q, "joint_limit", points)
                return LoadedLimit("fold", t, t, q, None, points)
            h *= 0.5
            continue
        qn, lam_n = res.q, res.lam
        if lam_n < 0.0:                         # stability lost on a continuing branch: a bifurcation, bisected
            lo, hi, q_lo = t, tn, q
            while hi - lo > tol:
                mid = 0.5 * (lo + hi)
                r = solve(q_lo, mid)
                points += 1
                if r.q is None or r.lam < 0.0:  # none near (past a fold) or unstable: the limit is below
                    hi = mid
                else:
                    lo, q_lo = mid, r.q
            # at a fold lambda is zero too (Newton may reach the unstable side below it): past a fold there is no
            # equilibrium near, past a bifurcation the branch goes on
            on = solve(q_lo, lo + 1e-6 * max_load)
            points += 1
            return LoadedLimit("bifurcation" if on.q is not None else "fold", lo, lo, q_lo, None, points)
        q, t = qn, tn
        h = min(h * 1.5, max_load / 20.0)
    return LoadedLimit("none", np.nan, t, q, "max_load", points)
