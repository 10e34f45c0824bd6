"""Force-deflection curves by continuation (Fig. 6).

``branch="stable"``: at every point the least-energy stable equilibrium. The stable
branches present at the first deflected point (a Newton-seeded global search) are followed
point to point by Newton corrections, each started from the previous point's solution: for
chains of up to ``numerics.DENSE_MAX`` segments the whole path runs in compiled code (the C
kernels of :mod:`.kernels` up to ``KERNEL_MAX`` segments, CasADi ``rootfinder`` under
``mapaccum`` beyond) and is classified in one batch; a point where that fails is retried with
the damped Newton method. At each point the
least-energy stable branch is selected. When every tracked stable branch has ended (a fold,
a joint limit) a global :func:`solve_equilibrium` starts a new one, and every
``recheck_every`` points a global solve checks that no lower stable branch appeared.
``jumps`` lists where the force is discontinuous: the buckling jump at ``dx -> 0+`` (from 0
to the critical force, ``dy = 0``) and every switch of the selected branch.

On chains with bistable segments new branches are born inside the range (folds): there a search
from the global seeds and every combination of the segments' wells runs at *every* point, and
each stable equilibrium on no followed branch starts a new one, so the selected branch is the
least-energy stable one at every point (checked against the reference model's descent from all
well patterns, ``tests/test_completeness.py``), each switch a jump located within one grid step.

``branch="all"``: additionally every branch found at the first point (:func:`find_equilibria`)
is followed and returned in ``Curve.branches`` (NaN where it no longer exists); on multistable
chains also every branch born inside the range.

Points with ``dx = dy = 0`` are the straight chain (force 0 for symmetric segments); they split the
path into runs that are followed independently. With asymmetric preloads the straight chain is no
equilibrium there: such points carry ``status = "straight_not_equilibrium"`` and ``stable = False``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Literal

import numpy as np

from ..errors import (
    InvalidParameterError,
    NoEquilibriumError,
    StraightNotEquilibriumError,
    TensegrityError,
    TimeLimitError,
)
from ..model.manipulator import Manipulator
from ..model.shapes import shape_label, shape_labels
from ..serialize import nullable, number, numbers
from ..timelimit import check_time
from .all_equilibria import find_equilibria
from .buckling import critical_force
from .continuation import BranchPoints, follow
from .equilibrium import Equilibrium, straight_equilibrium
from .least_energy import WELLS_MAX, search_stable, solve_equilibrium
from .seeds import seed_starts, well_seeds

__all__ = ["Curve", "Jump", "force_deflection"]

#: Projected random starts per joint of the search for branches born at a point of a ``branch="all"``
#: curve on a multistable chain (the first point gets find_equilibria's default): the branches already
#: followed carry most equilibria along, the search only has to catch the new ones.
BIRTH_PROJECTED = 50


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

    def to_dict(self) -> dict[str, Any]:
        """JSON form (an item of ``jumps`` in ``POST /v1/force-deflection``): ``kind``, ``dx_before``,
        ``dx_after``, ``force_before`` / ``force_after`` ``{fx, fy}``, ``branch_before``, ``branch_after``."""
        return {"kind": self.kind, "dx_before": number(self.dx_before), "dx_after": number(self.dx_after),
                "force_before": _force(self.force_before), "force_after": _force(self.force_after),
                "branch_before": int(self.branch_before), "branch_after": int(self.branch_after)}


def _force(v: Any) -> dict[str, float]:
    return {"fx": number(v[0]), "fy": number(v[1])}


@dataclass(frozen=True)
class Curve:
    """Per-point results of :func:`force_deflection` (arrays of length ``m`` = number of points).

    Attributes
    ----------
    dx, dy : ndarray (m,)
        The deflections, from the straight tip or (``reference="rest"``) from the rest configuration's tip.
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
    reference : str
        ``"straight"`` or ``"rest"``: what ``dx``, ``dy`` (and the jumps' ``dx_before`` ...) are measured from.
    origin : ndarray (2,)
        The reference tip's deflection from the straight tip (zero for ``"straight"``): add it to ``(dx, dy)``
        to get the deflection from straight.
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
    reference: str = "straight"
    origin: np.ndarray = field(default_factory=lambda: np.zeros(2))

    def to_dict(self) -> dict[str, Any]:
        """JSON form (the body of ``POST /v1/force-deflection``): ``points`` (``dx``, ``dy``, ``fx``, ``fy``,
        ``energy``, ``q``, ``stable``, ``morse_index``, ``shape``, ``branch``), ``jumps`` (each
        :meth:`Jump.to_dict`) and ``branches`` (``branch="all"``: ``{id, points}`` per followed branch,
        a point with ``exists`` and ``null`` numbers where the branch does not reach)."""
        points = [{"dx": number(self.dx[i]), "dy": number(self.dy[i]), "fx": number(self.fx[i]),
                   "fy": number(self.fy[i]), "energy": number(self.energy[i]), "q": numbers(self.q[i]),
                   "stable": bool(self.stable[i]), "morse_index": int(self.morse_index[i]), "shape": self.shape[i],
                   "branch": int(self.branch[i])} for i in range(self.dx.size)]
        return {"points": points, "jumps": [j.to_dict() for j in self.jumps],
                "branches": [br._branch_dict(bi) for bi, br in enumerate(self.branches)],
                "reference": self.reference, "origin": numbers(self.origin)}

    def _branch_dict(self, position: int) -> dict[str, Any]:
        """This curve as the ``position``-th item of ``branches``: its id and nullable points."""
        bid = int(self.branch[0]) if self.branch.size else position
        pts = []
        for i in range(self.dx.size):
            exists = bool(np.isfinite(self.energy[i]))
            pts.append({"dx": number(self.dx[i]), "dy": number(self.dy[i]), "exists": exists,
                        "fx": nullable(self.fx[i]), "fy": nullable(self.fy[i]), "energy": nullable(self.energy[i]),
                        "q": [nullable(v) for v in self.q[i]], "stable": bool(self.stable[i]),
                        "morse_index": int(self.morse_index[i]), "shape": self.shape[i]})
        return {"id": bid, "points": pts}


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
    dist = np.hypot(m.straight_length - dxs - m.base_length, dys)
    far = np.flatnonzero(dist > float(m.link_lengths.sum()) * (1.0 + 1e-12))
    if far.size:
        m.check_reachable(dxs[far[0]], dys[far[0]])      # raises with the full message
    return dxs, dys


def _newton_stable(m: Manipulator, dx: float, dy: float) -> list[Equilibrium]:
    """Every stable equilibrium Newton finds from the global search's seeds and, on a multistable
    chain, from every combination of the segments' wells (:func:`~tensegrity_opt.analyses.seeds.well_seeds`)."""
    target = m.target(dx, dy)
    starts = seed_starts(m, dx, dy)
    if not m.monotonic:
        wells = well_seeds(m, dx, dy, hilltops=False, cap=WELLS_MAX)
        if wells.shape[0]:
            starts = np.vstack([starts, wells])
    return search_stable(m, target, starts, {}, minimize=False)[0]


def _stable_at(m: Manipulator, dx: float, dy: float) -> list[Equilibrium]:
    """Every stable equilibrium the Newton-seeded global search finds (IPOPT when it finds none)."""
    stable = _newton_stable(m, dx, dy)
    if not stable:
        try:
            stable = [solve_equilibrium(m, dx, dy)]
        except NoEquilibriumError:
            stable = []
    return stable


def force_deflection(m: Manipulator, dx, dy=0.0, branch: Literal["stable", "all"] = "stable", *,
                     recheck_every: int = 250, reference: Literal["straight", "rest"] = "straight") -> Curve:
    """Force-deflection relation ``F(dx, dy)`` along the least-energy stable branch.

    Parameters
    ----------
    m : Manipulator
    dx : array_like (m,)
        Deflections (length units), in the order to follow (usually increasing).
    dy : float or array_like (m,)
    branch : {"stable", "all"}
        ``"all"`` also follows every branch found at the first deflected point and, on multistable
        chains, every branch born inside the range (``find_equilibria`` at every point: seconds for
        n <= 6, much more for long bistable chains with hundreds of equilibria).
    recheck_every : int
        A global solve every this many points guards against missed lower branches (0: never).
    reference : {"straight", "rest"}
        What ``(dx, dy)`` are measured from: the straight chain's tip ``(2 sum b, 0)`` (the paper's), or the tip
        of the least-energy rest configuration (:func:`~tensegrity_opt.analyses.rest.rest_configuration`: a
        pre-bent arm's unloaded shape), so that ``dx = dy = 0`` is the unloaded arm and the force there is 0.
        The returned curve keeps the caller's values and says which (``Curve.reference``, ``Curve.origin``).

    Returns
    -------
    Curve

    Raises
    ------
    UnreachableTargetError, InvalidParameterError
        (``ValueError``) for a point beyond reach or malformed input, before any solve.
    NoEquilibriumError
        (``RuntimeError``) when some point has no stable equilibrium at all.
    """
    if branch not in ("stable", "all"):
        raise InvalidParameterError(f"branch must be 'stable' or 'all', got {branch!r}", field="branch")
    if reference not in ("straight", "rest"):
        raise InvalidParameterError(f"reference must be 'straight' or 'rest', got {reference!r}", field="reference")
    if reference == "rest":
        return _from_rest(m, dx, dy, branch, recheck_every)
    dxs, dys = _points(m, dx, dy)
    npts, n = dxs.size, m.n
    targets = np.column_stack([m.straight_length - dxs, dys])
    straight = (dxs == 0.0) & (dys == 0.0)
    branches: list[BranchPoints] = []
    sel = np.full(npts, -1, dtype=int)
    mirror_free = m == m.mirrored() and np.all(dys == 0.0)
    multistable = not m.monotonic and n >= 2

    def new_branch(i: int, eq: Equilibrium, stop: int) -> BranchPoints:
        br = BranchPoints(len(branches), npts, n)
        br.set(i, eq)
        branches.append(br)
        follow(m, br, i, stop, targets, dxs, dys)
        return br

    i = 0
    while i < npts:
        if straight[i]:
            i += 1
            continue
        stop = i
        while stop < npts and not straight[stop]:
            stop += 1
        run = _run_branches(m, dxs[i], dys[i], branch, mirror_free)
        for eq in run:
            new_branch(i, eq, stop)
        current = None
        since = 0
        for j in range(i, stop):
            check_time("the force-deflection curve")
            if multistable and j > i:
                # branches are born inside the range (folds): search at every point and follow each
                # equilibrium (stable ones; every one for branch="all") on no branch followed so far
                born = (find_equilibria(m, dxs[j], dys[j], n_projected=BIRTH_PROJECTED * n) if branch == "all"
                        else _newton_stable(m, dxs[j], dys[j]))
                for g in born:
                    if not any(br.valid[j] and np.max(np.abs(br.q[j] - g.q)) < 1e-6 for br in branches):
                        new_branch(j, g, stop)
            live = [br for br in branches if br.valid[j] and br.stable[j]]
            since += 1
            if not live or (recheck_every and since >= recheck_every and j > i):
                since = 0
                try:
                    g = solve_equilibrium(m, dxs[j], dys[j], q0=branches[current].q[j - 1] if current is not None
                                          and branches[current].valid[j - 1] else None)
                except TimeLimitError:
                    raise
                except TensegrityError:
                    g = None
                if g is not None and not any(np.max(np.abs(br.q[j] - g.q)) < 1e-7 for br in live):
                    live.append(new_branch(j, g, stop))
            if not live:
                raise NoEquilibriumError(f"no stable equilibrium at dx={dxs[j]:g}, dy={dys[j]:g}")
            e_min = min(br.E[j] for br in live)
            tol = 1e-9 * max(m.torque_scale, abs(e_min))
            best = [br for br in live if br.E[j] <= e_min + tol]
            pick = next((br for br in best if br.id == current), None) or best[0]
            current = pick.id
            sel[j] = pick.id
        i = stop

    curve = _assemble(m, dxs, dys, branches, sel, straight)
    if branch == "all":
        curve = Curve(**{**curve.__dict__, "branches": [_branch_curve(dxs, dys, br) for br in branches]})
    return curve


def _from_rest(m: Manipulator, dx, dy, branch: str, recheck_every: int) -> Curve:
    """The curve with ``(dx, dy)`` measured from the rest configuration's tip (``reference="rest"``)."""
    from .rest import rest_configuration

    rest = rest_configuration(m)
    origin = np.array([m.straight_length - rest.tip[0], rest.tip[1]])
    if np.max(np.abs(origin)) <= 1e-12 * m.straight_length:
        origin = np.zeros(2)
    rel_x = np.atleast_1d(np.asarray(dx, dtype=float))
    rel_y = np.asarray(dy, dtype=float)
    try:
        c = force_deflection(m, rel_x + origin[0], rel_y + origin[1], branch, recheck_every=recheck_every)
    except InvalidParameterError as exc:
        raise InvalidParameterError(exc.message, field=exc.field, **exc.details) from None

    def shift(cv: Curve) -> Curve:
        return Curve(**{**cv.__dict__, "dx": cv.dx - origin[0], "dy": cv.dy - origin[1], "reference": "rest",
                        "origin": origin.copy(),
                        "jumps": [Jump(j.kind, j.dx_before - origin[0], j.dx_after - origin[0], j.force_before,
                                       j.force_after, j.branch_before, j.branch_after, j.dy_before - origin[1],
                                       j.dy_after - origin[1]) for j in cv.jumps],
                        "branches": [shift(b) for b in cv.branches]})

    return shift(c)


def _run_branches(m: Manipulator, dx: float, dy: float, branch: str, mirror_free: bool) -> list[Equilibrium]:
    if m.n == 1:
        return [solve_equilibrium(m, dx, dy)]
    if branch == "all":
        return find_equilibria(m, dx, dy)
    eqs = _stable_at(m, dx, dy)
    if mirror_free:
        # mirror images (q -> -q) of a mirror-symmetric chain at dy = 0 have equal energy all
        # along: following one of each pair is enough
        kept: list[Equilibrium] = []
        for e in sorted(eqs, key=lambda e: -e.q[0]):
            if not any(np.max(np.abs(e.q + k.q)) < 1e-7 for k in kept):
                kept.append(e)
        eqs = kept
    return eqs


def _assemble(m, dxs, dys, branches, sel, straight) -> Curve:
    npts, n = dxs.size, m.n
    q = np.zeros((npts, n))
    F = np.zeros((npts, 2))
    E = np.zeros(npts)
    morse = np.zeros(npts, dtype=int)
    stable = np.ones(npts, dtype=bool)
    status = ["straight"] * npts
    try:
        s0, s0_ok = straight_equilibrium(m), True
    except StraightNotEquilibriumError:
        # asymmetric preloads: at dx = dy = 0 only the straight chain reaches the tip, and it is no
        # equilibrium (an unbounded tension would be needed): the point is kept, marked, not stable
        s0, s0_ok = straight_equilibrium(m, check=False), False
    for j in range(npts):
        if straight[j]:
            q[j], F[j], E[j] = s0.q, s0.force, s0.energy
            if not s0_ok:
                stable[j], status[j] = False, "straight_not_equilibrium"
            continue
        br = branches[sel[j]]
        q[j], F[j], E[j], morse[j], stable[j], status[j] = br.q[j], br.F[j], br.E[j], br.morse[j], \
            br.stable[j], br.status[j]
    shapes = shape_labels(q)
    jumps: list[Jump] = []
    # Leaving the straight chain: the force jumps from the straight value to the branch's limit
    # as dx -> 0+ — the critical force when the straight chain is a stable equilibrium and dy = 0,
    # else (K <= 0, asymmetric preloads, dy != 0) the force at the first deflected point.
    try:
        fx0 = critical_force(m, "guided").force if m.n >= 2 else None
    except TensegrityError:
        fx0 = None
    for j in range(npts):
        if straight[j] or (j > 0 and not straight[j - 1]):
            continue                    # not the first deflected point after the straight chain
        if j == 0 and dys[0] != 0.0:
            continue                    # a curve starting off the dx axis does not leave the straight chain
        limit = np.array([fx0, 0.0]) if (fx0 is not None and dys[j] == 0.0) else F[j].copy()
        before = float(dxs[j - 1]) if j > 0 else 0.0
        jumps.append(Jump("buckling", before, float(dxs[j]), F[j - 1].copy() if j > 0 else np.zeros(2), limit,
                          -1, int(sel[j]), float(dys[j - 1]) if j > 0 else 0.0, float(dys[j])))
    for j in range(1, npts):
        if sel[j] != sel[j - 1] and sel[j] >= 0 and sel[j - 1] >= 0:
            jumps.append(Jump("branch_switch", float(dxs[j - 1]), float(dxs[j]), F[j - 1].copy(), F[j].copy(),
                              int(sel[j - 1]), int(sel[j]), float(dys[j - 1]), float(dys[j])))
    return Curve(dx=dxs.copy(), dy=dys.copy(), q=q, fx=F[:, 0].copy(), fy=F[:, 1].copy(), energy=E,
                 stable=stable, morse_index=morse, shape=shapes, branch=sel.copy(), status=status, jumps=jumps)


def _branch_curve(dxs, dys, br: BranchPoints) -> Curve:
    return Curve(dx=dxs.copy(), dy=dys.copy(), q=br.q.copy(), fx=br.F[:, 0].copy(), fy=br.F[:, 1].copy(),
                 energy=br.E.copy(), stable=br.stable.copy(), morse_index=br.morse.copy(),
                 shape=[shape_label(q) if v else "" for q, v in zip(br.q, br.valid)],
                 branch=np.full(dxs.size, br.id), status=list(br.status))
