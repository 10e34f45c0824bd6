"""Force-deflection curves by continuation (Fig. 6).

``branch="stable"``: at every ``dx`` the least-energy stable equilibrium. The
branches present at the first deflected point (:func:`find_equilibria`) are
followed by warm-started Newton corrections (a square-root predictor when
``dy = 0``: near the straight configuration ``q ~ sqrt(dx)``); at each point the
least-energy stable one is selected. When every tracked stable branch has ended
(a fold, a joint limit) a global :func:`solve_equilibrium` starts a new one, and
every ``recheck_every`` points a global solve checks that no lower stable branch
appeared. ``jumps`` lists where the force is discontinuous: the buckling jump at
``dx -> 0+`` (from 0 to the critical force, ``dy = 0``) and every switch of the
selected branch.

``branch="all"``: additionally every branch found at the first point is returned
in ``Curve.branches`` (NaN where it no longer exists).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Literal

import numpy as np

from .buckling import critical_force
from .equilibria import find_equilibria
from .equilibrium import Equilibrium, _straight, _valid, make_equilibrium, solve_equilibrium
from .errors import InvalidParameterError, TensegrityError
from .manipulator import Manipulator
from .solvers import model

__all__ = ["Curve", "Jump", "force_deflection"]


@dataclass(frozen=True)
class Jump:
    """A force discontinuity between the points ``(dx_before, dy_before)`` and ``(dx_after, dy_after)``.

    ``kind`` is ``"buckling"`` (at ``dx -> 0+``: from 0 to the critical force) or
    ``"branch_switch"`` (the least-energy stable branch changes).
    """

    kind: str
    dx_before: float
    dx_after: float
    force_before: np.ndarray
    force_after: np.ndarray
    branch_before: int
    branch_after: int
    dy_before: float = 0.0
    dy_after: float = 0.0


@dataclass(frozen=True)
class Curve:
    """Per-point results of :func:`force_deflection` (arrays of length ``m`` = number of points).

    Attributes
    ----------
    dx, dy : ndarray (m,)
    q : ndarray (m, n)
    fx, fy, energy : ndarray (m,)
    stable : ndarray (m,) of bool
    morse_index : ndarray (m,) of int
    shape : list of str
    branch : ndarray (m,) of int
        Identifier of the branch each point lies on (-1: straight).
    status : list of str
        Solver status per point (``"nan"`` where a followed branch does not exist).
    jumps : list of Jump
    branches : list of Curve
        ``branch="all"`` only: each branch followed separately.
    """

    dx: np.ndarray
    dy: np.ndarray
    q: np.ndarray
    fx: np.ndarray
    fy: np.ndarray
    energy: np.ndarray
    stable: np.ndarray
    morse_index: np.ndarray
    shape: list[str]
    branch: np.ndarray
    status: list[str]
    jumps: list[Jump] = field(default_factory=list)
    branches: list["Curve"] = field(default_factory=list, repr=False)


class _Track:
    def __init__(self, bid: int, eq: Equilibrium, dx: float) -> None:
        self.id = bid
        self.eq = eq
        self.alive = True
        self.last_dx = dx


def _points(m: Manipulator, dx, dy) -> tuple[np.ndarray, np.ndarray]:
    dxs = np.atleast_1d(np.asarray(dx, dtype=float))
    if dxs.ndim != 1 or dxs.size == 0:
        raise InvalidParameterError("dx must be a non-empty 1-D array of deflections", field="dx")
    dys = np.asarray(dy, dtype=float)
    if dys.ndim == 0:
        dys = np.full(dxs.shape, float(dys))
    if dys.shape != dxs.shape:
        raise InvalidParameterError("dy must be a number or have the length of dx", field="dy")
    if not (np.all(np.isfinite(dxs)) and np.all(np.isfinite(dys))):
        raise InvalidParameterError("dx and dy must be finite", field="dx")
    for a, b in zip(dxs, dys):
        m.check_reachable(a, b)
    return dxs, dys


def _continue(m: Manipulator, tr: _Track, dx: float, dy: float) -> Equilibrium | None:
    """Newton corrector from the branch's last point (square-root predictor on dx when dy = 0)."""
    eq = tr.eq
    q0, F0 = eq.q, eq.force
    if dy == 0.0 and eq.tip[1] == 0.0 and tr.last_dx > 0.0 and dx > 0.0:
        r = math.sqrt(dx / tr.last_dx)
        q0, F0 = q0 * r, np.array([F0[0], F0[1] * r])
    target = m.target(dx, dy)
    res = model(m.n).newton_kkt(m.params, m.joint_limits, target, q0, F0)
    if not _valid(m, res, target):
        return None
    return make_equilibrium(m, res, constrained=True)


def force_deflection(m: Manipulator, dx, dy=0.0, branch: Literal["stable", "all"] = "stable", *,
                     recheck_every: int = 20) -> Curve:
    """Force-deflection relation ``F(dx, dy)`` along the least-energy stable branch.

    Parameters
    ----------
    m : Manipulator
    dx : array_like (m,)
        Deflections (length units), in the order to follow (usually increasing).
    dy : float or array_like (m,)
    branch : {"stable", "all"}
        ``"all"`` also follows every branch found at the first deflected point.
    recheck_every : int
        A global solve every this many points guards against missed lower branches (0: never).

    Returns
    -------
    Curve
    """
    if branch not in ("stable", "all"):
        raise InvalidParameterError(f"branch must be 'stable' or 'all', got {branch!r}", field="branch")
    dxs, dys = _points(m, dx, dy)
    npts = dxs.size
    tracks: list[_Track] = []
    history: dict[int, list[Equilibrium | None]] = {}
    selected: list[Equilibrium] = []
    sel_ids: list[int] = []
    next_id = 0
    current: int | None = None
    since_check = 0

    def add(eq: Equilibrium, dxv: float) -> _Track:
        nonlocal next_id
        tr = _Track(next_id, eq, dxv)
        next_id += 1
        tracks.append(tr)
        history[tr.id] = [None] * npts
        return tr

    for i, (dxv, dyv) in enumerate(zip(dxs, dys)):
        if dxv == 0.0 and dyv == 0.0:
            selected.append(_straight(m))
            sel_ids.append(-1)
            current = None
            continue
        if not tracks:
            for eq in find_equilibria(m, dxv, dyv):
                if branch == "all" or eq.stable:
                    add(eq, dxv)
        else:
            for tr in tracks:
                if not tr.alive:
                    continue
                eq = _continue(m, tr, dxv, dyv)
                if eq is None or any(o is not tr and o.alive and o.last_dx == dxv
                                     and np.max(np.abs(o.eq.q - eq.q)) < 1e-7 for o in tracks):
                    tr.alive = False        # the branch ended, or merged into another one
                    continue
                tr.eq, tr.last_dx = eq, dxv
        for tr in tracks:
            if tr.alive and tr.last_dx == dxv:
                history[tr.id][i] = tr.eq
        live = [tr for tr in tracks if tr.alive and tr.last_dx == dxv and tr.eq.stable]
        since_check += 1
        if not live or (recheck_every and since_check >= recheck_every):
            since_check = 0
            try:
                q0 = live[0].eq.q if live else (selected[-1].q if selected and sel_ids[-1] >= 0 else None)
                g = solve_equilibrium(m, dxv, dyv, q0=q0)
            except TensegrityError:
                g = None
            if g is not None and not any(np.max(np.abs(tr.eq.q - g.q)) < 1e-7 for tr in live):
                tr = add(g, dxv)
                history[tr.id][i] = g
                live.append(tr)
        if not live:
            raise TensegrityError(f"no stable equilibrium at dx={dxv:g}, dy={dyv:g}")
        e_min = min(tr.eq.energy for tr in live)
        tol = 1e-9 * max(1.0, abs(e_min))
        best = [tr for tr in live if tr.eq.energy <= e_min + tol]
        pick = next((tr for tr in best if tr.id == current), None) or best[0]
        current = pick.id
        selected.append(pick.eq)
        sel_ids.append(pick.id)

    jumps = _jumps(m, dxs, dys, selected, sel_ids)
    curve = _curve(dxs, dys, selected, sel_ids, jumps)
    if branch == "all":
        curve = Curve(**{**curve.__dict__, "branches": [
            _branch_curve(m, dxs, dys, tr.id, history[tr.id]) for tr in tracks]})
    return curve


def _jumps(m, dxs, dys, selected, sel_ids) -> list[Jump]:
    jumps: list[Jump] = []
    pos = dxs > 0
    if np.all(dys == 0.0) and np.any(pos) and np.all(dxs >= 0.0):
        try:
            fx0 = critical_force(m, "guided").force
        except TensegrityError:
            fx0 = None
        if fx0 is not None:
            i = int(np.argmax(pos))
            before = i - 1 if i > 0 and dxs[i - 1] == 0.0 else None
            jumps.append(Jump("buckling", 0.0 if before is None else float(dxs[before]), float(dxs[i]),
                              np.zeros(2), np.array([fx0, 0.0]), -1, sel_ids[i]))
            # (dy is 0 on both sides)
    for i in range(1, len(selected)):
        if sel_ids[i] != sel_ids[i - 1] and sel_ids[i] >= 0 and sel_ids[i - 1] >= 0:
            jumps.append(Jump("branch_switch", float(dxs[i - 1]), float(dxs[i]), selected[i - 1].force.copy(),
                              selected[i].force.copy(), sel_ids[i - 1], sel_ids[i], float(dys[i - 1]),
                              float(dys[i])))
    return jumps


def _curve(dxs, dys, eqs, ids, jumps) -> Curve:
    return Curve(dx=dxs.copy(), dy=dys.copy(), q=np.array([e.q for e in eqs]),
                 fx=np.array([e.force[0] for e in eqs]), fy=np.array([e.force[1] for e in eqs]),
                 energy=np.array([e.energy for e in eqs]), stable=np.array([e.stable for e in eqs]),
                 morse_index=np.array([e.morse_index for e in eqs]), shape=[e.shape for e in eqs],
                 branch=np.array(ids), status=[e.status for e in eqs], jumps=jumps)


def _branch_curve(m, dxs, dys, bid, eqs) -> Curve:
    nan = float("nan")
    n = m.n
    return Curve(dx=dxs.copy(), dy=dys.copy(),
                 q=np.array([e.q if e is not None else np.full(n, nan) for e in eqs]),
                 fx=np.array([e.force[0] if e is not None else nan for e in eqs]),
                 fy=np.array([e.force[1] if e is not None else nan for e in eqs]),
                 energy=np.array([e.energy if e is not None else nan for e in eqs]),
                 stable=np.array([bool(e.stable) if e is not None else False for e in eqs]),
                 morse_index=np.array([e.morse_index if e is not None else -1 for e in eqs]),
                 shape=[e.shape if e is not None else "" for e in eqs], branch=np.full(len(eqs), bid),
                 status=[e.status if e is not None else "nan" for e in eqs])
