"""Force-deflection curves by continuation (Fig. 6).

``branch="stable"``: at every point the least-energy stable equilibrium. The first deflected point of
each run is :func:`solve_equilibrium`'s answer there (the same global search, the same call), so a curve
never starts on a stable branch of higher energy; the other stable branches present there (Newton from
the global seeds and, on multistable chains, every combination of the segments' wells) are followed
point to point by Newton corrections, each started from the previous point's solution: for
chains of up to ``numerics.DENSE_MAX`` segments the whole path runs in compiled code (the C
kernels of :mod:`tensegrity_opt.numerics.kernels` up to ``KERNEL_MAX`` segments, CasADi ``rootfinder`` under
``mapaccum`` beyond) and is classified in one batch; a point where that fails is retried with
the damped Newton method. At each point the
least-energy stable branch is selected. When every tracked stable branch has ended (a fold,
a joint limit) a global :func:`solve_equilibrium` starts a new one, and every
``recheck_every`` points a global solve checks that no lower stable branch appeared.
``jumps`` lists where the force is discontinuous, between two consecutive points, in the order
followed: ``"buckling"`` where the curve leaves (or returns to) the stable straight chain at ``dy = 0``
(from 0 to the guided critical force), ``"leave_straight"`` where it leaves (returns to) a straight
chain that is not a stable unloaded equilibrium (``K <= 0``) or at ``dy != 0`` (from the straight
force to the first deflected point's), ``"snap"`` where the selected branch ends or loses stability
and the chain jumps to another stable branch, ``"switch"`` where the least-energy stable branch
changes while the previous one is still stable (an exchange of the global minimum).

Where a point has no stable equilibrium (the stable branches end at a fold or the joint range and
the global search finds no other), the curve stops: it holds the points computed before that one,
and ``Curve.ended_at`` says where and why (``Curve.success`` is ``False``, ``Curve.message`` a sentence);
the points after it are not computed (the followed branch is gone, and a curve with a gap would
hide that the chain has nowhere stable to go).

On chains with bistable segments new branches are born inside the range (folds): there a search
from the global seeds and every combination of the segments' wells runs at *every* point, and
each stable equilibrium on no followed branch starts a new one, so the selected branch is the
least-energy stable one at every point (checked against the reference model's descent from all
well patterns, ``tests/analyses/equilibria/test_completeness.py``), each switch a jump located within one grid step.

``branch="all"``: additionally every branch found at the first point (:func:`find_equilibria`)
is followed and returned in ``Curve.branches`` (NaN where it no longer exists); on multistable
chains also every branch born inside the range.

Points with ``dx = dy = 0`` are the straight chain (force 0 for symmetric segments); they split the
path into runs that are followed independently. With asymmetric preloads the straight chain is no
equilibrium there: such points carry ``point_status = "straight_not_equilibrium"`` and ``stable = False``.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any, ClassVar, Literal

import numpy as np

from ...errors import (
    InvalidParameterError,
    NoEquilibriumError,
    SolverError,
    StraightNotEquilibriumError,
    TensegrityError,
    TimeLimitError,
    UnreachableTargetError,
    UnsupportedError,
)
from ...model.loads import loads_json, loads_key, unloaded_only
from ...model.manipulator import Manipulator
from ...model.shapes import shape_label, shape_labels
from ...model.springs import SpringFields, Springs, linear_only
from ...numerics.distinct import same
from ...outcome import Outcome, SolverInfo, freeze
from ...serialize import nullable, number, numbers
from ...timelimit import check_time
from ..equilibria.all_equilibria import find_equilibria
from ..equilibria.buckling import critical_force
from ..equilibria.equilibrium import Equilibrium, straight_equilibrium
from ..equilibria.least_energy import WELLS_MAX, search_stable, solve_equilibrium
from ..equilibria.seeds import seed_starts, well_seeds
from .continuation import BranchPoints, follow

__all__ = ["Curve", "CurveEnd", "Jump", "force_deflection"]

#: Projected random starts per joint of the search for branches born at a point of a ``branch="all"``
#: curve on a multistable chain (the first point gets find_equilibria's default): the branches already
#: followed carry most equilibria along, the search only has to catch the new ones.
BIRTH_PROJECTED = 50


#: A tension-only curve's local continuation that moves a joint more than this (rad) from the previous point has left
#: its branch (it ended there): a snap.
CONTINUE_STEP = 0.5

#: The kinds of :class:`Jump`, in the JSON form's ``kind``.
JUMP_KINDS = ("buckling", "leave_straight", "snap", "switch")

#: The status of each point of a :class:`Curve` (``Curve.point_status``, ``status`` of a point in the JSON form).
POINT_STATUSES = {
    "converged": "a converged equilibrium (the solver's own status and iterations in the point's solver)",
    "straight": "the straight chain at dx = dy = 0, an equilibrium known exactly",
    "straight_not_equilibrium": "the straight chain at dx = dy = 0 where it is no equilibrium (asymmetric preloads: "
                                "an unbounded tension would be needed): kept, marked, stable false",
    "absent": "a followed branch (Curve.branches) does not reach this point: its numbers are NaN",
}


@dataclass(frozen=True)
class Jump:
    """A force discontinuity between the consecutive points ``(dx_before, dy_before)`` and ``(dx_after, dy_after)``.

    ``kind`` is one of :data:`JUMP_KINDS`:

    * ``"buckling"``: leaving the stable straight chain (every ``K > 0``) at ``dx -> 0+``, ``dy = 0``: the
      force goes from the straight value (0) to the guided critical force (compressive, ``fx < 0``), or
      back when the curve returns to the straight point;
    * ``"leave_straight"``: leaving (or returning to) the straight chain when it is no stable unloaded
      equilibrium (``K <= 0`` somewhere) or the deflected point has ``dy != 0``: from the straight force
      to the force at the deflected point;
    * ``"snap"``: the selected stable branch ends or loses stability (a fold, the joint range) and the
      chain jumps to another stable branch;
    * ``"switch"``: the least-energy stable branch changes while the previous one still exists and is
      stable there (an exchange of the global minimum, not a loss of stability).

    ``branch_before`` / ``branch_after`` are the branch identifiers (``-1``: the straight chain). Forces are
    the tip force holding the chain: ``fx > 0`` tensile, ``fx < 0`` compressive (``docs/model.md``).
    ``cause`` (``"leave_straight"`` only) says why it is no buckling, for :attr:`label`. A jump is a fact about
    the curve, not an outcome.
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
    cause: str = ""

    def __post_init__(self) -> None:
        freeze(self)

    @property
    def delta(self) -> np.ndarray:
        """``force_after - force_before``, ndarray (2,)."""
        return np.asarray(self.force_after, dtype=float) - np.asarray(self.force_before, dtype=float)

    @property
    def label(self) -> str:
        """A sentence naming the jump, with sign and size, e.g.
        ``"buckling of the straight chain: F_x 0 -> -0.573 (compressive)"``,
        ``"snap to another stable branch: dF_x = +1.91 (tensile)"``."""
        f0 = np.asarray(self.force_before, dtype=float)
        f1 = np.asarray(self.force_after, dtype=float)
        if self.kind in ("buckling", "leave_straight"):
            returning = self.branch_after == -1 and self.branch_before != -1
            dy = self.dy_before if returning else self.dy_after
            if self.kind == "buckling":
                what = "return to the straight chain (buckling reversed)" if returning else \
                    "buckling of the straight chain"
            else:
                why = self.cause or (f"dy = {_fmt(dy)}" if dy != 0.0 else "not a stable unloaded equilibrium")
                what = f"{'return to' if returning else 'leaving'} the straight chain ({why})"
            parts = [f"F_x {_fmt(f0[0])} -> {_fmt(f1[0])}" + ("" if returning else _word(f1[0]))]
            if _changes(f0[1], f1[1]):
                parts.append(f"F_y {_fmt(f0[1])} -> {_fmt(f1[1])}")
            return f"{what}: " + ", ".join(parts)
        what = {"snap": "snap to another stable branch",
                "switch": "switch of the least-energy stable branch (the previous one stays stable)"}.get(
                    self.kind, self.kind)
        d = self.delta
        parts = []
        if _changes(f0[0], f1[0]):
            parts.append(f"dF_x = {_fmt(d[0], '+')}" + _word(d[0]))
        if _changes(f0[1], f1[1]):
            parts.append(f"dF_y = {_fmt(d[1], '+')}")
        return f"{what}: " + (", ".join(parts) if parts else "no change of the force")

    def to_dict(self) -> dict[str, Any]:
        """JSON form (an item of ``jumps`` in ``POST /v1/force-deflection``): ``kind``, ``dx_before``,
        ``dx_after``, ``force_before`` / ``force_after`` / ``delta`` ``{fx, fy}``, ``branch_before``,
        ``branch_after``, ``label``."""
        return {"kind": self.kind, "dx_before": number(self.dx_before), "dx_after": number(self.dx_after),
                "force_before": _force(self.force_before), "force_after": _force(self.force_after),
                "branch_before": int(self.branch_before), "branch_after": int(self.branch_after),
                "delta": _force(self.delta), "label": self.label}


def _fmt(v: float, sign: str = "") -> str:
    """3 significant digits, no ``-0``."""
    v = float(v) + 0.0
    return f"{v:{sign}.3g}" if v != 0.0 else "0"


def _word(fx: float) -> str:
    return " (tensile)" if fx > 0.0 else (" (compressive)" if fx < 0.0 else "")


def _changes(a: float, b: float) -> bool:
    return abs(float(b) - float(a)) > 1e-12 * max(1.0, abs(float(a)), abs(float(b)))


def _force(v: Any) -> dict[str, float]:
    return {"fx": number(v[0]), "fy": number(v[1])}


@dataclass(frozen=True)
class CurveEnd(Outcome):
    """Where and why a curve stopped before its last requested point.

    Attributes
    ----------
    dx, dy : float
        The first requested point where the curve could not go on (same reference as the curve's points).
    status : str
        Why (:attr:`STATUSES`); never a success: the curve could not go on.
    message : str
        A sentence, with what the followed branch did.
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "no_stable_equilibrium": "no stable equilibrium is found there: the stable branches end (a fold, the joint "
                                 "range) and the global search finds no other",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset()

    dx: float
    dy: float
    status: str
    message: str

    def __post_init__(self) -> None:
        freeze(self)

    def to_dict(self) -> dict[str, Any]:
        """JSON form: ``{success, status, message, dx, dy}``."""
        return {**self.outcome(), "dx": number(self.dx), "dy": number(self.dy)}


@dataclass(frozen=True)
class Curve(Outcome, SpringFields):
    """Per-point results of :func:`force_deflection` (arrays of length ``m`` = number of points computed).

    Attributes
    ----------
    dx, dy : ndarray (m,)
        The deflections, from the straight tip or (``reference="rest"``) from the rest configuration's tip.
    q : ndarray (m, n)
    fx, fy, energy : ndarray (m,)
    stable : ndarray (m,) of bool
    morse_index : ndarray (m,) of int
    shape : tuple of str
    branch : ndarray (m,) of int
        Identifier of the branch each point lies on (-1: straight).
    point_status : tuple of str
        What each point is (:data:`POINT_STATUSES`): ``"converged"``, ``"straight"``,
        ``"straight_not_equilibrium"``, ``"absent"`` (a followed branch of ``branches`` that does not exist there).
    solver : tuple of SolverInfo or None
        The solver's own status and iterations per point (``"straight"`` for the straight chain; None where
        ``"absent"``).
    jumps : tuple of Jump
    branches : tuple of Curve
        ``branch="all"`` only: each branch followed separately.
    reference : str
        ``"straight"`` or ``"rest"``: what ``dx``, ``dy`` (and the jumps' ``dx_before`` ...) are measured from.
    origin : ndarray (2,)
        The reference tip's deflection from the straight tip (zero for ``"straight"``): add it to ``(dx, dy)``
        to get the deflection from straight.
    ended_at : CurveEnd or None
        ``None`` when every requested point was computed; else the first point where the curve could not go
        on (the arrays hold the ``m < requested`` points before it).
    requested : int
        How many points were asked for (``m`` when complete).
    spring_lengths, spring_stretches, spring_forces, spring_states : ndarray (m, n, 2)
        The springs at each point (:class:`~tensegrity_opt.model.springs.SpringFields`; NaN where a branch of
        ``branches`` is absent).
    status : str
        Derived (:attr:`STATUSES`): ``"complete"``, or ``ended_at.status`` where the curve stops early.
    message : str
        Derived: how many points, and for a partial curve where it ends and why, e.g. "The stable branch ends
        between dx = 3.1 and dx = 3.15 (dy = 0): no stable equilibrium at dx = 3.15; 63 of 81 points computed.".
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "complete": "every requested point was computed",
        **CurveEnd.STATUSES,
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"complete"})

    dx: np.ndarray
    dy: np.ndarray
    q: np.ndarray
    fx: np.ndarray
    fy: np.ndarray
    energy: np.ndarray
    stable: np.ndarray
    morse_index: np.ndarray
    shape: tuple[str, ...]
    branch: np.ndarray
    point_status: tuple[str, ...]
    solver: tuple[SolverInfo | None, ...]
    jumps: tuple[Jump, ...] = ()
    branches: tuple["Curve", ...] = field(default=(), repr=False)
    reference: str = "straight"
    origin: np.ndarray = field(default_factory=lambda: np.zeros(2))
    ended_at: CurveEnd | None = None
    requested: int = -1
    springs: Springs | None = field(default=None, repr=False, compare=False)
    loads: tuple | None = None

    def __post_init__(self) -> None:
        if self.requested < 0:
            object.__setattr__(self, "requested", int(self.dx.size))
        for a in (self.dx, self.dy, self.q, self.fx, self.fy, self.energy, self.stable, self.morse_index,
                  self.branch, self.origin):
            a.setflags(write=False)                 # the builders' own arrays, read-only in place
        for name in ("shape", "point_status", "solver", "jumps", "branches"):
            v = getattr(self, name)
            if not isinstance(v, tuple):
                object.__setattr__(self, name, tuple(v))

    @property
    def status(self) -> str:
        """``"complete"``, or why the curve stopped early (``ended_at.status``)."""
        return "complete" if self.ended_at is None else self.ended_at.status

    @property
    def message(self) -> str:
        """How many points were computed; for a partial curve where it ends and why."""
        e = self.ended_at
        m = int(self.dx.size)
        if e is None:
            return f"all {m} requested points computed"
        why = {"no_stable_equilibrium": "no stable equilibrium"}.get(e.status, e.status.replace("_", " "))
        if m == 0:
            where = f"at the first point, dx = {e.dx:g} (dy = {e.dy:g})"
            at = f"dx = {e.dx:g}"
        elif float(self.dy[-1]) == e.dy:
            where = f"between dx = {float(self.dx[-1]):g} and dx = {e.dx:g} (dy = {e.dy:g})"
            at = f"dx = {e.dx:g}"
        else:
            where = (f"between (dx, dy) = ({float(self.dx[-1]):g}, {float(self.dy[-1]):g}) and "
                     f"({e.dx:g}, {e.dy:g})")
            at = f"(dx, dy) = ({e.dx:g}, {e.dy:g})"
        return f"The stable branch ends {where}: {why} at {at}; {m} of {self.requested} points computed."

    def to_dict(self) -> dict[str, Any]:
        """JSON form (the body of ``POST /v1/force-deflection``): ``success``, ``status``, ``message``, ``points``
        (``dx``, ``dy``, ``fx``, ``fy``, ``energy``, ``q``, ``stable``, ``morse_index``, ``shape``, ``branch``,
        ``status`` (:data:`POINT_STATUSES`), ``solver`` ``{status, iterations}``, the spring state ``spring_lengths``,
        ``spring_stretches``, ``spring_forces``, ``spring_states``), ``jumps`` (each
        :meth:`Jump.to_dict`), ``branches`` (``branch="all"``: ``{id, points}`` per followed branch, a point with
        ``exists`` and ``null`` numbers where the branch does not reach), ``reference``, ``origin``, ``ended_at``
        (:meth:`CurveEnd.to_dict` or ``null``), ``requested`` and ``loads`` (the chain's dead loads the curve was
        computed under, ``null`` without)."""
        springs = self._spring_rows()
        points = [{**springs[i], "dx": number(self.dx[i]), "dy": number(self.dy[i]), "fx": number(self.fx[i]),
                   "fy": number(self.fy[i]), "energy": number(self.energy[i]), "q": numbers(self.q[i]),
                   "stable": bool(self.stable[i]), "morse_index": int(self.morse_index[i]), "shape": self.shape[i],
                   "branch": int(self.branch[i]), "status": self.point_status[i],
                   "solver": None if self.solver[i] is None else self.solver[i].to_dict()}
                  for i in range(self.dx.size)]
        return {**self.outcome(), "points": points, "jumps": [j.to_dict() for j in self.jumps],
                "branches": [br._branch_dict(bi) for bi, br in enumerate(self.branches)],
                "reference": self.reference, "origin": numbers(self.origin),
                "ended_at": None if self.ended_at is None else self.ended_at.to_dict(),
                "requested": int(self.requested), "loads": loads_json(self.loads)}

    def _branch_dict(self, position: int) -> dict[str, Any]:
        """This curve as the ``position``-th item of ``branches``: its id and nullable points."""
        bid = int(self.branch[0]) if self.branch.size else position
        springs = self._spring_rows()
        pts = []
        for i in range(self.dx.size):
            exists = bool(np.isfinite(self.energy[i]))
            pts.append({**springs[i], "dx": number(self.dx[i]), "dy": number(self.dy[i]), "exists": exists,
                        "fx": nullable(self.fx[i]), "fy": nullable(self.fy[i]), "energy": nullable(self.energy[i]),
                        "q": [nullable(v) for v in self.q[i]], "stable": bool(self.stable[i]),
                        "morse_index": int(self.morse_index[i]), "shape": self.shape[i]})
        return {"id": bid, "points": pts}

    def _spring_rows(self) -> list[dict[str, Any]]:
        """The spring state of each point as JSON (``null`` fields where a point has no configuration)."""
        d = self.spring_dict()
        k = int(self.dx.size)
        return [{name: (None if v is None else v[i]) for name, v in d.items()} for i in range(k)]


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
    """Every stable equilibrium Newton finds from the global search's seeds and, on a multistable chain, from every
    combination of the segments' wells (:func:`~tensegrity_opt.analyses.equilibria.seeds.well_seeds`)."""
    target = m.target(dx, dy)
    starts = seed_starts(m, dx, dy)
    if not m.monotonic:
        wells = well_seeds(m, dx, dy, hilltops=False, cap=WELLS_MAX)
        if wells.shape[0]:
            starts = np.vstack([starts, wells])
    return search_stable(m, target, starts, {}, minimize=False)[0]


def _least_at(m: Manipulator, dx: float, dy: float) -> Equilibrium | None:
    """The least-energy stable equilibrium of :func:`solve_equilibrium` (its global search, the same call), or
    None when it finds none (the curve then ends there unless another branch is found)."""
    try:
        return solve_equilibrium(m, dx, dy, stops=False)
    except SolverError:                      # NoEquilibriumError included; TimeLimitError is no SolverError
        return None


def force_deflection(m: Manipulator, dx, dy=0.0, branch: Literal["stable", "all"] = "stable", *,
                     recheck_every: int = 250, reference: Literal["straight", "rest"] = "straight") -> Curve:
    """Force-deflection relation ``F(dx, dy)`` along the least-energy stable branch.

    Parameters
    ----------
    m : Manipulator
    dx : array_like (m,)
        Deflections (length units), in the order to follow (increasing or decreasing, or any path).
    dy : float or array_like (m,)
    branch : {"stable", "all"}
        ``"all"`` also follows every branch found at the first deflected point and, on multistable
        chains, every branch born inside the range (``find_equilibria`` at every point: seconds for
        n <= 6, much more for long bistable chains with hundreds of equilibria).
    recheck_every : int
        A global solve every this many points guards against missed lower branches (0: never).
    reference : {"straight", "rest"}
        What ``(dx, dy)`` are measured from: the straight chain's tip ``(2 sum b, 0)`` (the paper's), or the tip
        of the least-energy rest configuration (:func:`~tensegrity_opt.analyses.equilibria.rest.rest_configuration`: a
        pre-bent arm's unloaded shape), so that ``dx = dy = 0`` is the unloaded arm and the force there is 0.
        The returned curve keeps the caller's values and says which (``Curve.reference``, ``Curve.origin``).

    Returns
    -------
    Curve
        The first deflected point (of each run between straight points) is the least-energy stable equilibrium
        of :func:`solve_equilibrium` there (the same search, the same answer); the stable branches of higher
        energy found there are followed too, and the curve moves to one of them only where it becomes the
        least-energy one (a ``"switch"`` jump) or where the selected one ends (a ``"snap"``). The curve is the
        global minimum's path, not the path a loaded chain follows from a given state (that stays on its branch
        until the branch loses stability: :func:`~tensegrity_opt.analyses.paths.simulation.simulate`).
        Every point up to the first one where no stable equilibrium is found. When the curve stops
        there (the stable branches end at a fold or the joint range and the global search finds no
        other), it holds only the points before it, ``Curve.ended_at`` is that point
        (``reason = "no_stable_equilibrium"``), ``Curve.complete`` is ``False`` and ``Curve.note`` says
        so; the later points are not computed. Every point returned is a converged equilibrium or the
        straight chain.

    Raises
    ------
    UnreachableTargetError, InvalidParameterError
        (``ValueError``) for a point beyond reach or malformed input, before any solve.
    TimeLimitError
        (``RuntimeError``) when the time limit of :func:`~tensegrity_opt.time_limit` is reached (no
        partial curve: what it would hold would depend on the machine's speed).
    NoEquilibriumError
        (``RuntimeError``) ``reference="rest"`` only: when the chain has no stable rest configuration
        (nothing to measure from). A point without a stable equilibrium ends the curve instead.
    """
    if branch not in ("stable", "all"):
        raise InvalidParameterError(f"branch must be 'stable' or 'all', got {branch!r}", field="branch")
    if reference not in ("straight", "rest"):
        raise InvalidParameterError(f"reference must be 'straight' or 'rest', got {reference!r}", field="reference")
    if not m.paper_model:
        if reference == "rest":
            linear_only(m, "force_deflection (reference='rest')")
            unloaded_only(m, "force_deflection (reference='rest')")
        return _slack_curve(m, dx, dy, branch)
    if reference == "rest":
        return _from_rest(m, dx, dy, branch, recheck_every)
    return _curve(m, dx, dy, branch, recheck_every, np.zeros(2))


def _curve(m: Manipulator, dx, dy, branch: str, recheck_every: int, origin: np.ndarray) -> Curve:
    """:func:`force_deflection` from the straight tip; ``origin`` only shifts the numbers in the messages
    (``reference="rest"``: they speak of the caller's deflections)."""
    dxs, dys = _points(m, dx, dy)
    npts, n = dxs.size, m.n
    targets = np.column_stack([m.straight_length - dxs, dys])
    straight = (dxs == 0.0) & (dys == 0.0)
    branches: list[BranchPoints] = []
    sel = np.full(npts, -1, dtype=int)
    mirror_free = m == m.mirrored() and np.all(dys == 0.0)
    multistable = not m.monotonic and n >= 2
    end, ended = npts, None

    def new_branch(i: int, eq: Equilibrium, stop: int) -> BranchPoints:
        br = BranchPoints(len(branches), npts, n)
        br.set(i, eq)
        branches.append(br)
        follow(m, br, i, stop, targets, dxs, dys)
        return br

    i = 0
    while i < npts and ended is None:
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
                                          and branches[current].valid[j - 1] else None, stops=False)
                except TimeLimitError:
                    raise
                except TensegrityError:
                    g = None
                if g is not None and not any(np.max(np.abs(br.q[j] - g.q)) < 1e-7 for br in live):
                    live.append(new_branch(j, g, stop))
            closed = None
            if not live and branch == "stable":
                # no stable equilibrium inside the open range: the closed range's, the arm resting on a joint's
                # stop where it reaches one (on the followed branch when the local solve continues it there)
                try:
                    pick = _closed_range_point(m, j, dxs, dys, None if current is None else branches[current],
                                               branches)
                    current = sel[j] = pick.id
                    continue
                except _NoStable as exc:
                    closed = exc.end
            if not live:
                # the stable branches end here and no global search (the closed range's included) finds another
                end = j
                ended = _end(m, dxs, dys, j, None if current is None else branches[current], origin)
                if closed is not None:
                    ended = replace(ended, message=f"{ended.message[:-1]}; over the closed range too: "
                                                   f"{closed.message.split(': ', 1)[-1]}")
                break
            e_min = min(br.E[j] for br in live)
            tol = 1e-9 * max(m.torque_scale, abs(e_min))
            best = [br for br in live if br.E[j] <= e_min + tol]
            pick = next((br for br in best if br.id == current), None) or best[0]
            current = pick.id
            sel[j] = pick.id
        i = stop

    curve = _assemble(m, dxs[:end], dys[:end], branches, sel[:end], straight[:end])
    extra: dict[str, Any] = {"ended_at": ended, "requested": npts}
    if branch == "all":
        # a branch born at the end point has no point on the curve: left out
        extra["branches"] = [_branch_curve(dxs[:end], dys[:end], br, m.springs) for br in branches
                             if br.valid[:end].any()]
    return replace(curve, **extra)


def _slack_curve(m: Manipulator, dx, dy, branch: str) -> Curve:
    """:func:`force_deflection` of a chain with tension-only springs: at every point the least-energy stable
    equilibrium of the closed range (the global search of :mod:`~..equilibria.tension_only`, the previous point's
    configuration one of its starts: the same definition as the linear law's curve), stops included. The branch
    followed from the previous point is continued by a local solve from its configuration; where the selected one
    differs, the jump is a ``"switch"`` when that continuation is still a stable equilibrium (of higher energy),
    else a ``"snap"``. A point with no stable equilibrium (or a free joint left undetermined) ends the curve."""
    if branch != "stable":
        what = "tension-only springs" if not m.linear_springs else "dead loads"
        raise UnsupportedError("branch='all' follows every branch by the linear law's compiled continuation; for a "
                               f"chain with {what} the curve follows the least-energy stable one "
                               "(branch='stable')", field="branch",
                               spring="tension_only" if not m.linear_springs else "linear")
    dxs, dys = _points(m, dx, dy)
    npts = dxs.size
    straight = (dxs == 0.0) & (dys == 0.0)
    branches: list[BranchPoints] = []
    sel = np.full(npts, -1, dtype=int)
    end, ended = npts, None
    prev: BranchPoints | None = None
    for j in range(npts):
        check_time("the force-deflection curve")
        if straight[j]:
            prev = None
            continue
        try:
            prev = _closed_range_point(m, j, dxs, dys, prev, branches)
        except _NoStable as exc:
            end, ended = j, exc.end
            break
        sel[j] = prev.id
    curve = _assemble(m, dxs[:end], dys[:end], branches, sel[:end], straight[:end])
    return replace(curve, ended_at=ended, requested=npts, loads=loads_key(m))


class _NoStable(Exception):
    """No stable equilibrium at a point of the closed range: the curve ends (``end``, a :class:`CurveEnd`)."""

    def __init__(self, end: CurveEnd) -> None:
        super().__init__(end.message)
        self.end = end


def _closed_range_point(m: Manipulator, j: int, dxs, dys, prev: BranchPoints | None,
                        branches: list[BranchPoints]) -> BranchPoints:
    """Point ``j`` of a curve over the closed range (stops included, under the springs' laws): the least-energy
    stable equilibrium (the global search of :mod:`~..equilibria.tension_only`, ``prev``'s configuration at the
    point before one of its starts) set on the branch it lies on: ``prev`` where the local solve from there (its
    continuation) is that equilibrium or no higher, else a new branch in ``branches`` (a switch when the
    continuation is still stable, else a snap). :class:`_NoStable` where there is none."""
    from ..equilibria.tension_only import least_energy_slack

    target = m.target(dxs[j], dys[j])
    q0 = prev.q[j - 1] if prev is not None and prev.valid[j - 1] else None
    try:
        g = least_energy_slack(m, float(dxs[j]), float(dys[j]), target, q0=q0)
    except (NoEquilibriumError, UnreachableTargetError, UnsupportedError) as exc:
        dxo, dyo = float(dxs[j]), float(dys[j])
        raise _NoStable(CurveEnd(dxo, dyo, "no_stable_equilibrium",
                                 f"No stable equilibrium at dx = {dxo:g}, dy = {dyo:g} under the springs' laws: "
                                 f"{exc}.")) from None
    cont = None
    if q0 is not None:
        try:
            cont = least_energy_slack(m, float(dxs[j]), float(dys[j]), target, q0=q0, local=True)
        except (NoEquilibriumError, UnreachableTargetError, UnsupportedError):
            cont = None
        if cont is not None and (not cont.stable or float(np.abs(cont.q - q0).max()) > CONTINUE_STEP):
            cont = None                          # the branch ended (a fold, a stop) or the solve left it
    scale = m.torque_scale
    if prev is not None and cont is not None and (
            float(np.abs(cont.q - g.q).max()) < 1e-6 or cont.energy <= g.energy + 1e-9 * max(scale, abs(g.energy))):
        prev.set(j, cont)
        return prev
    if prev is not None and cont is not None:
        prev.set(j, cont)                        # still stable there: the new one is a switch
    new = BranchPoints(len(branches), dxs.size, m.n)
    new.set(j, g)
    branches.append(new)
    return new


def _end(m: Manipulator, dxs, dys, j: int, followed: BranchPoints | None, origin: np.ndarray) -> CurveEnd:
    """The :class:`CurveEnd` at point ``j`` (no stable equilibrium found), saying what the followed branch did."""
    dx, dy = float(dxs[j] - origin[0]), float(dys[j] - origin[1])
    if followed is None:
        what = "the global search finds none"
    elif followed.valid[j]:
        what = (f"the followed branch is unstable there (Morse index {int(followed.morse[j])}: a fold or branch "
                f"point since the last point) and the global search finds no other stable equilibrium")
    else:
        q = followed.q[j - 1]
        margin = m.joint_limits - np.abs(q)
        k = int(np.argmin(margin))
        what = (f"the followed branch ends (no converged point inside the physical range from the last point, "
                f"where joint {k + 1} is {margin[k]:.3g} rad from its limit {m.joint_limits[k]:.4g}) and the "
                f"global search finds no other stable equilibrium")
    return CurveEnd(dx, dy, "no_stable_equilibrium",
                    f"No stable equilibrium at dx = {dx:g}, dy = {dy:g}: {what}.")


def _from_rest(m: Manipulator, dx, dy, branch: str, recheck_every: int) -> Curve:
    """The curve with ``(dx, dy)`` measured from the rest configuration's tip (``reference="rest"``)."""
    from ..equilibria.rest import rest_configuration

    rest = rest_configuration(m)
    origin = np.array([m.straight_length - rest.tip[0], rest.tip[1]])
    if np.max(np.abs(origin)) <= 1e-12 * m.straight_length:
        origin = np.zeros(2)
    rel_x = np.atleast_1d(np.asarray(dx, dtype=float))
    rel_y = np.asarray(dy, dtype=float)
    try:
        c = _curve(m, rel_x + origin[0], rel_y + origin[1], branch, recheck_every, origin)
    except InvalidParameterError as exc:
        raise InvalidParameterError(exc.message, field=exc.field, **exc.details) from None

    def shift(cv: Curve) -> Curve:           # ended_at speaks of the caller's deflections already (origin)
        return replace(cv, **{"dx": cv.dx - origin[0], "dy": cv.dy - origin[1], "reference": "rest",
                        "origin": origin.copy(),
                        "jumps": [replace(j, dx_before=j.dx_before - origin[0], dx_after=j.dx_after - origin[0],
                                          dy_before=j.dy_before - origin[1], dy_after=j.dy_after - origin[1])
                                  for j in cv.jumps],
                        "branches": [shift(b) for b in cv.branches]})

    return shift(c)


def _run_branches(m: Manipulator, dx: float, dy: float, branch: str, mirror_free: bool) -> list[Equilibrium]:
    """The branches a run starts from at its first point: the least-energy stable equilibrium of
    :func:`solve_equilibrium` and every stable one Newton finds from the global seeds (every equilibrium of
    :func:`find_equilibria` for ``branch="all"``), the least-energy one added last when the others miss it."""
    least = _least_at(m, dx, dy)
    if m.n == 1:
        return [] if least is None else [least]
    eqs = list(find_equilibria(m, dx, dy)) if branch == "all" else _newton_stable(m, dx, dy)
    if least is not None and not any(same(e.q, least.q) for e in eqs):
        eqs.append(least)
    if mirror_free and branch != "all":
        # mirror images (q -> -q) of a mirror-symmetric chain at dy = 0 have equal energy all
        # along: following one of each pair is enough
        kept: list[Equilibrium] = []
        for e in sorted(eqs, key=lambda e: -e.q[0]):
            if not any(np.max(np.abs(e.q + k.q)) < 1e-7 for k in kept):
                kept.append(e)
        eqs = kept
    return eqs


def _assemble(m, dxs, dys, branches, sel, straight) -> Curve:
    """The selected points (the first ``dxs.size`` of the run) and their jumps."""
    npts, n = dxs.size, m.n
    q = np.zeros((npts, n))
    F = np.zeros((npts, 2))
    E = np.zeros(npts)
    morse = np.zeros(npts, dtype=int)
    stable = np.ones(npts, dtype=bool)
    status = ["straight"] * npts
    solver: list[SolverInfo | None] = [None] * npts
    try:
        s0, s0_ok = straight_equilibrium(m), True
    except StraightNotEquilibriumError:
        # asymmetric preloads: at dx = dy = 0 only the straight chain reaches the tip, and it is no
        # equilibrium (an unbounded tension would be needed): the point is kept, marked, not stable
        s0, s0_ok = straight_equilibrium(m, check=False), False
    for j in range(npts):
        if straight[j]:
            q[j], F[j], E[j], solver[j] = s0.q, s0.force, s0.energy, s0.solver
            if not s0_ok:
                stable[j], status[j] = False, "straight_not_equilibrium"
            continue
        br = branches[sel[j]]
        q[j], F[j], E[j], morse[j], stable[j] = br.q[j], br.F[j], br.E[j], br.morse[j], br.stable[j]
        status[j], solver[j] = "converged", br.solver[j]
    shapes = shape_labels(q)
    jumps: list[Jump] = []
    # Leaving (or returning to) the straight chain: the force jumps between the straight value and the
    # branch's limit as dx -> 0+ — the guided critical force when the straight chain is a stable
    # equilibrium (every K > 0: critical_force refuses otherwise) and dy = 0 ("buckling"), else (K <= 0,
    # dy != 0) the force at the deflected point ("leave_straight"). No jump when the straight chain is
    # no equilibrium (asymmetric preloads): the straight point has no force to jump from.
    fx0 = None
    if s0_ok and m.n >= 2 and straight.any():
        try:
            fx0 = critical_force(m, "guided").force
        except TensegrityError:
            fx0 = None
    for j in range(1, npts):
        a, b = bool(straight[j - 1]), bool(straight[j])
        if a and b:
            continue
        if a != b:
            if not s0_ok:
                continue
            d = j if a else j - 1                       # the deflected one of the two points
            cause = ""
            if fx0 is not None and dys[d] == 0.0:
                kind, limit = "buckling", np.array([fx0, s0.force[1]])
            else:
                kind, limit = "leave_straight", F[d].copy()
                cause = (f"dy = {_fmt(dys[d])}" if dys[d] != 0.0 else "unstable unloaded: K <= 0"
                         if np.any(m.stiffness <= 0.0) else "not a stable unloaded equilibrium")
            before, after = (F[j - 1].copy(), limit) if a else (limit, F[j].copy())
        elif sel[j] != sel[j - 1]:
            cause = ""
            prev = branches[sel[j - 1]]
            kind = "switch" if (prev.valid[j] and prev.stable[j]) else "snap"
            before, after = F[j - 1].copy(), F[j].copy()
        else:
            continue
        jumps.append(Jump(kind, float(dxs[j - 1]), float(dxs[j]), before, after, int(sel[j - 1]), int(sel[j]),
                          float(dys[j - 1]), float(dys[j]), cause))
    return Curve(dx=dxs.copy(), dy=dys.copy(), q=q, fx=F[:, 0].copy(), fy=F[:, 1].copy(), energy=E,
                 stable=stable, morse_index=morse, shape=shapes, branch=sel.copy(), point_status=status,
                 solver=solver, jumps=jumps, springs=m.springs)


def _branch_curve(dxs, dys, br: BranchPoints, springs: Springs) -> Curve:
    """One followed branch over the points ``dxs``, ``dys`` (the first ``dxs.size`` of the run)."""
    end = dxs.size
    return Curve(dx=dxs.copy(), dy=dys.copy(), q=br.q[:end].copy(), fx=br.F[:end, 0].copy(),
                 fy=br.F[:end, 1].copy(), energy=br.E[:end].copy(), stable=br.stable[:end].copy(),
                 morse_index=br.morse[:end].copy(),
                 shape=[shape_label(q) if v else "" for q, v in zip(br.q[:end], br.valid[:end])],
                 branch=np.full(end, br.id), point_status=["converged" if v else "absent" for v in br.valid[:end]],
                 solver=br.solver[:end], springs=springs)
