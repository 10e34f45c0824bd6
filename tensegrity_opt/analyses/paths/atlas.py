"""The workspace stability atlas: over a grid of tip targets ``(dx, dy)``, how many stable equilibria the
held tip has, where the least-energy equilibrium switches branch, and where stable branches end.

At each target every equilibrium is found (:func:`~tensegrity_opt.analyses.equilibria.all_equilibria.find_equilibria`:
the multi-start search, complete in practice and measured; or the certified homotopy, ``n <= 6``) and
classified: the counts of minima, saddles and maxima, the least-energy stable equilibrium and its sign
string (:class:`AtlasTarget`). Then each grid edge between two neighbouring targets ``A -> B`` is
examined by arclength continuation with the tip moved along the edge
(:func:`~tensegrity_opt.analyses.paths.branches.trace_branch`, displacement control, stopping where stability
is lost):

* every stable equilibrium at ``A`` is followed towards ``B`` and every stable equilibrium at ``B`` not
  reached that way is followed back towards ``A``. A branch that loses stability on the edge (a fold of
  the held-tip problem: the stable equilibrium merges with a saddle and the arm snaps; a branch point; a
  joint reaching its range bound) gives a **branch end** crossing, located by the continuation's event
  (Moore-Spence for a fold, to ~1e-10), not by the grid;
* where the least-energy equilibrium at ``B`` is not the continuation of the one at ``A``, the least-energy
  branch **switches** on the edge: the point where the two branches' energies are equal (the Maxwell
  point of the held tip), found by Brent's method on the energy difference with a Newton solve on each
  branch at each trial. Where the two branches never share a point with equal energy, the least branch
  ended first: the switch is at that branch end (``method="branch_end"``).

The straight chain held at full reach (``dx = dy = 0`` on a symmetric chain) is a branch point of the held tip
(the buckling): its edges follow the buckled arms through it (:func:`~.diagram.branches_from`). An edge whose
continuation fails is listed in ``unresolved`` with the reason in the atlas's words; the rest is kept.

A crossing is a point on one grid edge; :meth:`StabilityAtlas.curves` joins the crossings of one kind
inside each grid cell into segments (two per cell, or nearest pairs), the curves of the figure.

What is certified and what is measured: the counts are exact when the per-target sets are certified
(``method="homotopy"``; ``AtlasTarget.certified``), measured otherwise. The edge analysis assumes at most
one switch per edge and sees the branch ends of the stable equilibria present at either end; a stable
branch born and dying inside one edge, or two switches on one edge, need a finer grid.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np
import scipy.optimize as so

from ...errors import (
    InvalidParameterError,
    SingularStartError,
    SolverError,
    TensegrityError,
    TimeLimitError,
    UnreachableTargetError,
)
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...numerics import DENSE_MAX, chain_solver
from ...numerics.homotopy import homotopy_available
from ...outcome import Outcome, freeze
from ...serialize import nullable, number, numbers
from ...timelimit import expired, remaining, time_limit
from ..equilibria.all_equilibria import HOMOTOPY_MAX_N, EquilibriumSet, find_equilibria
from ..equilibria.equilibrium import Equilibrium, make_equilibrium
from .branches import Branch
from .control import Control
from .diagram import branches_from
from .transition import start_state

__all__ = ["StabilityAtlas", "AtlasTarget", "AtlasCrossing", "stability_atlas", "atlas_target", "assemble_atlas",
           "MAX_TARGETS", "CROSSING_KINDS"]

#: Largest grid :func:`stability_atlas` accepts (targets).
MAX_TARGETS = 10_000
#: Kinds of :class:`AtlasCrossing`.
CROSSING_KINDS = ("switch", "branch_end")
#: Two stable equilibria of one target whose energies differ by less than this (relative to the
#: energy scale ``k (sum of rest lengths)^2``) tie for the least energy.
TIE_TOL = 1e-9
#: Chains up to this long get the homotopy's certified answer where the search finds no equilibrium (n = 3: ~0.3 s;
#: n = 4: 1-3 s a target, too dear for a grid: its empty targets stay measured).
HOMOTOPY_NONE_N = 3
#: Two configurations closer than this (max-norm, rad) are the same equilibrium.
SAME_Q = 1e-5


@dataclass(frozen=True)
class AtlasTarget(Outcome):
    """The equilibria at one grid target (the tip held at ``(dx, dy)``).

    Attributes
    ----------
    dx, dy : float
    reachable : bool
        False beyond the chain's reach (every count 0).
    count, n_stable, n_saddle, n_maximum : int
        Equilibria inside the physical range, and of each kind (-1 where the solve failed: ``error``).
    least_energy : float or None
        Energy of the least-energy stable equilibrium.
    least_signs : str or None
        Its sign string (:attr:`Equilibrium.signs`).
    tie : bool
        Two stable equilibria share the least energy (within :data:`TIE_TOL`; e.g. mirror images on
        ``dy = 0``): ``least`` is the first by the set's order.
    stable : tuple of Equilibrium
        The stable equilibria, least energy first.
    certified : bool
        The set is proven complete (the homotopy, or a trivial case).
    method : str
    error : str or None
        ``"code: message"`` where the solve failed (the counts are then -1; ``"time_limit: ..."``: not
        computed before the time limit).
    status : str
        Derived (:attr:`STATUSES`): ``"solved"``, ``"unreachable"``, ``"failed"`` or ``"time_limit"``.
    message : str
        Derived: the counts, or why there are none.
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "solved": "every equilibrium found (the search, or certified by the homotopy) and classified",
        "unreachable": "the target is beyond the chain's reach: every count 0",
        "failed": "the solve failed (error says why): the counts are -1",
        "time_limit": "not computed before the time limit: the counts are -1",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"solved", "unreachable"})

    dx: float
    dy: float
    reachable: bool = True
    count: int = -1
    n_stable: int = -1
    n_saddle: int = -1
    n_maximum: int = -1
    least_energy: float | None = None
    least_signs: str | None = None
    tie: bool = False
    stable: tuple = field(default=(), repr=False)
    certified: bool = False
    method: str = ""
    error: str | None = None

    def __post_init__(self) -> None:
        freeze(self)

    @property
    def status(self) -> str:
        """How the target was computed (:attr:`STATUSES`)."""
        if self.error is not None:
            return "time_limit" if self.error.startswith("time_limit") else "failed"
        return "solved" if self.reachable else "unreachable"

    @property
    def message(self) -> str:
        """The counts in a sentence, or why there are none."""
        if self.error is not None:
            return self.error
        if not self.reachable:
            return "beyond the chain's reach"
        return (f"{self.count} equilibria ({self.n_stable} stable, {self.n_saddle} saddles, {self.n_maximum} "
                f"maxima), {'certified' if self.certified else 'measured'}")

    def to_dict(self) -> dict[str, Any]:
        """JSON form (an item of the atlas's ``targets``): ``success``, ``status``, ``message``, ``dx``, ``dy``,
        ``reachable``, the counts, ``least_energy``, ``least_signs``, ``tie``, ``stable_q``, ``stable_energy``,
        ``certified``, ``method``, ``error``."""
        return {**self.outcome(), "dx": number(self.dx), "dy": number(self.dy), "reachable": self.reachable,
                "count": self.count, "n_stable": self.n_stable, "n_saddle": self.n_saddle,
                "n_maximum": self.n_maximum,
                "least_energy": None if self.least_energy is None else nullable(self.least_energy),
                "least_signs": self.least_signs, "tie": self.tie,
                "stable_q": [numbers(e.q) for e in self.stable],
                "stable_energy": [number(e.energy) for e in self.stable],
                "certified": self.certified, "method": self.method, "error": self.error}


@dataclass(frozen=True)
class AtlasCrossing:
    """A point on a grid edge where the least-energy branch switches or a stable branch ends (a fact about the
    atlas, not an outcome).

    Attributes
    ----------
    kind : str
        ``"switch"`` or ``"branch_end"``.
    dx, dy : float
        The point (tip deflection).
    edge : tuple
        ``((iA, jA), (iB, jB))``: grid indices (``dx`` index, ``dy`` index) of the edge's ends.
    fraction : float
        Position along the edge from ``A`` (0) to ``B`` (1).
    energy : float
    q, force : ndarray
        The configuration there: for a branch end the equilibrium where stability is lost; for a switch the
        least-energy equilibrium on ``A``'s side.
    q_other, force_other : ndarray or None
        For a switch: the equilibrium on ``B``'s side (same energy).
    event : str
        For a branch end, the continuation's event kind (``"fold"``, ``"branch_point"``, ``"joint_limit"``);
        for a switch ``"maxwell"``.
    null_vector : ndarray or None
        The mode of a fold or branch point.
    method : str
        ``"moore_spence"`` / ``"test_function"`` / ``"limit"`` (the event's), ``"equal_energy"`` (Brent on the
        energy difference) or ``"branch_end"`` (a switch at the end of the least branch).
    """

    kind: str
    dx: float
    dy: float
    edge: tuple
    fraction: float
    energy: float
    q: np.ndarray
    force: np.ndarray
    event: str
    method: str
    q_other: np.ndarray | None = None
    force_other: np.ndarray | None = None
    null_vector: np.ndarray | None = None

    def __post_init__(self) -> None:
        freeze(self)

    def to_dict(self) -> dict[str, Any]:
        """JSON form (an item of the atlas's ``crossings``)."""
        return {"kind": self.kind, "dx": number(self.dx), "dy": number(self.dy),
                "edge": [list(map(int, self.edge[0])), list(map(int, self.edge[1]))],
                "fraction": number(self.fraction), "energy": number(self.energy), "q": numbers(self.q),
                "force": numbers(self.force), "event": self.event, "method": self.method,
                "q_other": None if self.q_other is None else numbers(self.q_other),
                "force_other": None if self.force_other is None else numbers(self.force_other),
                "null_vector": None if self.null_vector is None else numbers(self.null_vector)}


@dataclass(frozen=True)
class StabilityAtlas(Outcome):
    """The result of :func:`stability_atlas`.

    Attributes
    ----------
    dx : ndarray (nx,)
    dy : ndarray (ny,)
    targets : tuple of tuple of AtlasTarget
        ``targets[j][i]`` at ``(dx[i], dy[j])``.
    count, n_stable, n_saddle, n_maximum : ndarray (ny, nx) of int
        -1 where the target failed.
    least_energy : ndarray (ny, nx)
        NaN where no stable equilibrium.
    least_signs : ndarray (ny, nx) of object
    certified : ndarray (ny, nx) of bool
    crossings : tuple of AtlasCrossing
    unresolved : tuple of tuple
        Edges whose analysis failed (a continuation that could not be followed), with the reason.
    status : str
        :attr:`STATUSES`.
    message : str
        The same in a sentence, with the counts of failures.
    seconds : float
    method : str
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "complete": "every target computed and every edge analysed",
        "partial": "some targets failed or some edges could not be analysed (the rest is complete)",
        "time_limit": "the time limit ran out: targets or edges not reached are missing",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"complete"})

    dx: np.ndarray
    dy: np.ndarray
    targets: tuple
    crossings: tuple
    unresolved: tuple
    status: str
    message: str
    seconds: float
    method: str

    def __post_init__(self) -> None:
        object.__setattr__(self, "targets", tuple(tuple(row) for row in self.targets))
        freeze(self)

    def _grid(self, attr: str, dtype, missing) -> np.ndarray:
        out = np.full((self.dy.size, self.dx.size), missing, dtype=dtype)
        for j, row in enumerate(self.targets):
            for i, t in enumerate(row):
                v = getattr(t, attr)
                out[j, i] = missing if v is None else v
        return out

    @property
    def count(self) -> np.ndarray:
        return self._grid("count", int, -1)

    @property
    def n_stable(self) -> np.ndarray:
        return self._grid("n_stable", int, -1)

    @property
    def n_saddle(self) -> np.ndarray:
        return self._grid("n_saddle", int, -1)

    @property
    def n_maximum(self) -> np.ndarray:
        return self._grid("n_maximum", int, -1)

    @property
    def least_energy(self) -> np.ndarray:
        return self._grid("least_energy", float, np.nan)

    @property
    def least_signs(self) -> np.ndarray:
        return self._grid("least_signs", object, None)

    @property
    def certified(self) -> np.ndarray:
        return self._grid("certified", bool, False)

    @property
    def switches(self) -> list:
        return [c for c in self.crossings if c.kind == "switch"]

    @property
    def branch_ends(self) -> list:
        return [c for c in self.crossings if c.kind == "branch_end"]

    def curves(self, kind: str) -> list[np.ndarray]:
        """Segments ``[[dx0, dy0], [dx1, dy1]]`` joining the crossings of ``kind`` inside each grid cell.

        A curve enters a cell through one edge and leaves through another: crossings on two different edges of
        the cell are joined, the pairs whose configurations are closest first (one fold curve is one family of
        fold shapes; two fold curves crossing one cell are told apart by their shapes, not by where they cross).
        Crossings at one point (mirror-image branches ending together) count once; an unpaired crossing (a
        curve ending inside the cell) draws no segment.
        """
        if kind not in CROSSING_KINDS:
            raise InvalidParameterError(f"kind must be one of {CROSSING_KINDS}, got {kind!r}", field="kind")
        cells: dict[tuple[int, int], list] = {}
        for c in self.crossings:
            if c.kind != kind:
                continue
            (ia, ja), (ib, jb) = c.edge
            for cell in _cells_of(ia, ja, ib, jb, self.dx.size, self.dy.size):
                cells.setdefault(cell, []).append((np.array([c.dx, c.dy]), c.q, c.edge))
        segs = []
        for items in cells.values():
            uniq: list = []
            for it in items:
                if not any(np.max(np.abs(it[0] - u[0])) <= 1e-9 * (1.0 + np.max(np.abs(u[0]))) for u in uniq):
                    uniq.append(it)
            pairs = sorted((float(np.max(np.abs(uniq[a][1] - uniq[b][1]))), a, b)
                           for a in range(len(uniq)) for b in range(a + 1, len(uniq)) if uniq[a][2] != uniq[b][2])
            used: set[int] = set()
            for _, a, b in pairs:
                if a not in used and b not in used:
                    used.update((a, b))
                    segs.append(np.array([uniq[a][0], uniq[b][0]]))
        seen, out = set(), []
        for sg in segs:     # a segment between two grid points belongs to two cells: once
            key = tuple(sorted((tuple(np.round(sg[0], 12)), tuple(np.round(sg[1], 12)))))
            if key not in seen:
                seen.add(key)
                out.append(sg)
        return out

    def to_dict(self) -> dict[str, Any]:
        """JSON form: the grid, the per-target arrays (``null`` where absent), every target, the crossings and
        the curves."""
        def grid(a):
            return [[None if (v is None or (isinstance(v, float) and not math.isfinite(v))) else
                     (v.item() if hasattr(v, "item") else v) for v in row] for row in a]

        return {**self.outcome(), "dx": numbers(self.dx), "dy": numbers(self.dy),
                "method": self.method, "seconds": number(self.seconds),
                "count": grid(self.count), "n_stable": grid(self.n_stable), "n_saddle": grid(self.n_saddle),
                "n_maximum": grid(self.n_maximum), "least_energy": grid(self.least_energy),
                "least_signs": grid(self.least_signs), "certified": grid(self.certified),
                "targets": [[t.to_dict() for t in row] for row in self.targets],
                "crossings": [c.to_dict() for c in self.crossings],
                "curves": {k: [[numbers(p) for p in s] for s in self.curves(k)] for k in CROSSING_KINDS},
                "unresolved": [{"edge": [list(a), list(b)], "reason": r} for (a, b), r in self.unresolved]}


def _cells_of(ia: int, ja: int, ib: int, jb: int, nx: int, ny: int) -> list[tuple[int, int]]:
    """Grid cells (lower-left corner indices) sharing the edge ``(ia, ja) - (ib, jb)``."""
    i0, j0 = min(ia, ib), min(ja, jb)
    if (ia, ja) == (ib, jb):    # a grid point: its four cells
        return [(i, j) for i in (ia - 1, ia) for j in (ja - 1, ja) if 0 <= i < nx - 1 and 0 <= j < ny - 1]
    if ja == jb:    # an edge along dx: the cells below and above
        return [(i0, j) for j in (j0 - 1, j0) if 0 <= j < ny - 1]
    return [(i, j0) for i in (i0 - 1, i0) if 0 <= i < nx - 1]


def _energy_scale(m: Manipulator) -> float:
    return float(np.max(m.k1) * (np.sum(m.L1_0) + np.sum(m.L2_0)) ** 2) or 1.0


def atlas_target(m: Manipulator, dx: float, dy: float, *, method: str = "search",
                 timeout: float | None = None, strict: bool = False) -> AtlasTarget:
    """Every equilibrium with the tip held at ``(dx, dy)``, counted and classified. A failed solve is
    recorded in :attr:`AtlasTarget.error` (``strict=True``: raised); an unreachable target has every count 0."""
    try:
        try:
            eqs = find_equilibria(m, dx, dy, method=method, timeout=timeout)
        except SolverError as exc:
            if method != "search" or exc.details.get("found") != 0:
                raise
            eqs = _none_found(m, dx, dy, timeout)
    except UnreachableTargetError:
        return AtlasTarget(float(dx), float(dy), False, 0, 0, 0, 0, certified=True, method=method)
    except TimeLimitError:
        raise
    except TensegrityError as exc:
        if strict:
            raise
        return AtlasTarget(float(dx), float(dy), method=method, error=f"{exc.code}: {exc.message}")
    kinds = [e.kind for e in eqs]
    stable = sorted((e for e in eqs if e.stable), key=lambda e: e.energy)
    least = {}
    if stable:
        least = {"least_energy": float(stable[0].energy), "least_signs": stable[0].signs,
                 "tie": len(stable) > 1 and stable[1].energy - stable[0].energy <= TIE_TOL * _energy_scale(m)}
    return AtlasTarget(float(dx), float(dy), True, len(eqs), len(stable), kinds.count("saddle"), kinds.count("maximum"),
                       stable=tuple(stable), certified=bool(eqs.certified), method=eqs.method, **least)


def _none_found(m: Manipulator, dx: float, dy: float, timeout: float | None) -> EquilibriumSet:
    """The search found no equilibrium inside the range (near the edge of the joint range's workspace): the
    homotopy decides where it is cheap (``n <= HOMOTOPY_NONE_N`` and PHCpack installed; certified), else the
    search's empty answer stands (measured)."""
    left = remaining()
    if left is not None:
        timeout = left if timeout is None else min(timeout, left)
    if m.n <= HOMOTOPY_NONE_N and homotopy_available() and (timeout is None or timeout > 0.05):
        try:
            return find_equilibria(m, dx, dy, method="homotopy", timeout=timeout)
        except SolverError as exc:
            if exc.status != "phc_timeout":
                raise
            if expired():
                raise TimeLimitError("time limit reached in the atlas's homotopy") from None
    return EquilibriumSet([], method="search", status="searched",
                          message="the multi-start search found no equilibrium inside the physical range")


def _grid_values(v, name: str) -> np.ndarray:
    try:
        a = np.asarray(v, dtype=float).ravel()
    except (TypeError, ValueError):
        raise InvalidParameterError(f"{name} must be a list of numbers, got {v!r}", field=name) from None
    if a.size < 1 or not np.all(np.isfinite(a)):
        raise InvalidParameterError(f"{name} must be a non-empty list of finite numbers", field=name)
    if a.size > 1 and not np.all(np.diff(a) > 0):
        raise InvalidParameterError(f"{name} must be strictly increasing", field=name)
    return a


def _check(m: Manipulator, dx, dy, method: str):
    if not isinstance(m, Manipulator):
        raise InvalidParameterError("m must be a Manipulator", field="m")
    if m.n < 2 or m.n > DENSE_MAX:
        raise InvalidParameterError(f"the atlas needs 2 <= n <= {DENSE_MAX} segments, got {m.n}", field="n")
    if method not in ("search", "homotopy"):
        raise InvalidParameterError(f"method must be 'search' or 'homotopy', got {method!r}", field="method")
    if method == "homotopy" and m.n > HOMOTOPY_MAX_N:
        raise InvalidParameterError(f"the homotopy takes n <= {HOMOTOPY_MAX_N}, got {m.n}", field="method")
    X, Y = _grid_values(dx, "dx"), _grid_values(dy, "dy")
    if X.size * Y.size > MAX_TARGETS:
        raise InvalidParameterError(f"{X.size * Y.size} targets; the atlas takes at most {MAX_TARGETS}",
                                    field="dx")
    return X, Y


def stability_atlas(m: Manipulator, dx, dy, *, method: str = "search", edges: bool = True,
                    timeout: float | None = None, progress: Callable[[AtlasTarget], Any] | None = None
                    ) -> StabilityAtlas:
    """The stability atlas of the held tip over the grid ``dx x dy`` (module docstring).

    Parameters
    ----------
    m : Manipulator
        ``2 <= n <= numerics.DENSE_MAX``.
    dx, dy : array_like
        Strictly increasing grid values (tip deflection, length units); at most :data:`MAX_TARGETS` targets.
    method : {"search", "homotopy"}
        How the equilibria of each target are found (:func:`find_equilibria`); ``"homotopy"`` certifies the
        counts (``n <= 6``, PHCpack).
    edges : bool
        Locate the switch and branch-end crossings on the grid edges (default); False: the counts only.
    timeout : float, optional
        Seconds; on expiry what is done is returned with ``status="time_limit"`` (targets not reached
        carry ``error="time_limit: ..."``).
    progress : callable, optional
        Called with each :class:`AtlasTarget` once it is computed (row by row: ``dx`` fastest), before the edges.

    Returns
    -------
    StabilityAtlas

    Examples
    --------
    >>> import numpy as np, tensegrity_opt as to
    >>> m = to.Manipulator.uniform(3, a=0.5, b=1.0, k=1.0, L0=1.0)      # bistable segments
    >>> at = to.stability_atlas(m, np.linspace(0.2, 1.4, 7), np.linspace(-0.6, 0.6, 7))
    >>> at.n_stable.max(), len(at.switches) > 0                          # doctest: +SKIP
    (4, True)
    """
    unloaded_only(m, "stability_atlas")
    X, Y = _check(m, dx, dy, method)
    targets = [[AtlasTarget(float(x), float(y), error="time_limit: not computed") for x in X] for y in Y]

    def fill() -> None:
        for j, y in enumerate(Y):
            for i, x in enumerate(X):
                targets[j][i] = atlas_target(m, x, y, method=method)
                if progress is not None:
                    progress(targets[j][i])

    return _run(m, X, Y, targets, method, fill, edges, timeout)


def assemble_atlas(m: Manipulator, targets: list, *, edges: bool = True,
                   timeout: float | None = None) -> StabilityAtlas:
    """An atlas from targets computed elsewhere (a sweep's rows, :func:`atlas_target` on Dask): ``targets``
    is a list of :class:`AtlasTarget` forming a full grid in ``(dx, dy)`` (any order); the edges are
    analysed here."""
    if not targets:
        raise InvalidParameterError("no targets", field="targets")
    X = np.unique([t.dx for t in targets])
    Y = np.unique([t.dy for t in targets])
    if X.size * Y.size != len(targets):
        raise InvalidParameterError(f"{len(targets)} targets do not form a full grid ({X.size} dx x {Y.size} dy)",
                                    field="targets")
    _check(m, X, Y, "search")
    grid = [[None] * X.size for _ in Y]
    for t in targets:
        grid[int(np.searchsorted(Y, t.dy))][int(np.searchsorted(X, t.dx))] = t
    if any(v is None for row in grid for v in row):
        raise InvalidParameterError("targets repeat a grid point", field="targets")
    return _run(m, X, Y, grid, targets[0].method or "search", None, edges, timeout)


def _run(m: Manipulator, X: np.ndarray, Y: np.ndarray, targets: list, method: str, fill, edges: bool,
         timeout: float | None) -> StabilityAtlas:
    """Fill the grid of ``targets`` (``fill``, or None when given), analyse the edges, within ``timeout``; the
    status: ``"time_limit"`` when time ran out or a target was not computed in time, ``"partial"`` when a target
    failed or an edge is unresolved."""
    t0 = time.perf_counter()
    crossings: list[AtlasCrossing] = []
    unresolved: list[tuple] = []
    status = "complete"
    try:
        with time_limit(timeout):
            if fill is not None:
                fill()
            if edges:
                _edges(m, X, Y, targets, crossings, unresolved)
    except TimeLimitError:
        status = "time_limit"
    statuses = [t.status for row in targets for t in row]
    failed = sum(st == "failed" for st in statuses)
    late = sum(st == "time_limit" for st in statuses)
    if late:
        status = "time_limit"
    elif status == "complete" and (unresolved or failed):
        status = "partial"
    if status == "complete":
        message = f"all {len(statuses)} targets computed" + (" and every edge analysed" if edges else "")
    else:
        done = [f"{failed} target(s) failed"] if failed else []
        done += [f"{len(unresolved)} edge(s) unresolved"] if unresolved else []
        done += [f"{late} target(s) not computed"] if late else []
        message = ("the time limit ran out" if status == "time_limit" else "incomplete") + (
            ": " + ", ".join(done) if done else "")
    return StabilityAtlas(X, Y, targets, crossings, unresolved, status, message, time.perf_counter() - t0, method)


# ---------------------------------------------------------------------------------------------------
# the edges


def _edges(m: Manipulator, X: np.ndarray, Y: np.ndarray, T: list, crossings: list, unresolved: list) -> None:
    """The crossings on every grid edge into ``crossings`` (as they are found), the edges that failed into
    ``unresolved``."""
    crossings.extend(_ties(m, T))
    for j in range(Y.size):
        for i in range(X.size):
            for (i2, j2) in ((i + 1, j), (i, j + 1)):
                if i2 >= X.size or j2 >= Y.size:
                    continue
                if expired():
                    raise TimeLimitError("time limit reached in the atlas's edges")
                A, B = T[j][i], T[j2][i2]
                if not (A.success and B.success) or not (A.stable or B.stable):
                    continue
                try:
                    crossings.extend(_edge(m, A, B, ((i, j), (i2, j2))))
                except TimeLimitError:
                    raise
                except TensegrityError as exc:               # an edge that fails costs that edge only
                    unresolved.append((((i, j), (i2, j2)), f"the edge could not be analysed: {exc.message}"))
                except _EdgeFailed as exc:
                    unresolved.append((((i, j), (i2, j2)), str(exc)))


class _EdgeFailed(Exception):
    pass


@dataclass
class _Path:
    """A stable branch along an edge, parametrised by the distance ``u`` from ``A`` (0 .. L)."""

    branch: Branch
    u: np.ndarray          # edge coordinate of each point
    reached: bool          # it reaches the other end stable
    start_side: str        # "A" or "B"


def _trace_edge(m: Manipulator, eq: Equilibrium, vec: np.ndarray, length: float, side: str,
                where: tuple) -> list[_Path]:
    """The stable branches leaving ``eq`` along the edge: one, or at the straight chain held at full reach (a
    branch point, where the chain buckles) the arms crossing there (:func:`branches_from`); none when the tip
    cannot move that way (the edge of the workspace)."""
    if eq.at_stop.any():
        j = int(np.flatnonzero(eq.at_stop)[0])
        raise _EdgeFailed(f"{_follow(eq, where)}: it rests on joint {j + 1}'s stop (the arm as built: a slack spring "
                          "lets it reach it); branches are followed inside the range only")
    scale = 2.0 * float(np.mean(m.b))
    h = min(0.02, 0.25 * length / scale)
    direction = vec if side == "A" else -vec
    try:
        brs = branches_from(m, eq, Control.displacement(direction), t_max=length, stop_at="stability_loss",
                            step=h, max_step=max(h, 0.5 * length / scale), max_points=400)
    except TimeLimitError:
        raise
    except TensegrityError as exc:
        raise _EdgeFailed(f"{_follow(eq, where)}: {_plain(exc)}") from None
    paths = []
    for br in brs:
        if not br.success:
            raise _EdgeFailed(f"{_follow(eq, where)}: {_BRANCH_ENDS.get(br.status, br.message)}")
        u = br.t if side == "A" else length - br.t
        reached = br.status == "t_max" and bool(br.stable[-1])
        paths.append(_Path(br, u, reached, side))
    return paths


#: The atlas's words for a continuation that ended without an answer (:attr:`Branch.STATUSES`).
_BRANCH_ENDS = {
    "step_too_small": "the branch could not be followed past a singular point on the edge (a finer grid may help)",
    "corrector_failed": "the branch could not be followed along the edge (a finer grid may help)",
    "time_limit": "the time limit ran out",
}


def _follow(eq: Equilibrium, where: tuple) -> str:
    (dx, dy), (dx2, dy2) = where
    return f"the stable equilibrium {eq.signs} at (dx, dy) = ({dx:g}, {dy:g}) could not be followed towards " \
           f"({dx2:g}, {dy2:g})"


def _plain(exc: TensegrityError) -> str:
    if isinstance(exc, SingularStartError):
        return "it is a fold or a branch point of the held tip's paths (a finer or shifted grid may help)"
    return exc.message


def _match(q: np.ndarray, stable: list) -> int | None:
    for k, e in enumerate(stable):
        if np.max(np.abs(e.q - q)) < SAME_Q * 10:
            return k
    return None


def _edge(m: Manipulator, A: AtlasTarget, B: AtlasTarget, edge: tuple) -> list[AtlasCrossing]:
    a, b = np.array([A.dx, A.dy]), np.array([B.dx, B.dy])
    vec = b - a
    length = float(np.linalg.norm(vec))
    unit = vec / length
    out: list[AtlasCrossing] = []
    ab, ba = ((A.dx, A.dy), (B.dx, B.dy)), ((B.dx, B.dy), (A.dx, A.dy))
    # every stable branch from A (the arms of a branch point count for their equilibrium: fwd[k] the first)
    arms = {k: _trace_edge(m, e, unit, length, "A", ab) for k, e in enumerate(A.stable)}
    reached_B, reaching = {}, {}
    for k, ps in arms.items():
        for p in ps:
            if p.reached:
                jb = _match(p.branch.q[-1], B.stable)
                if jb is not None and jb not in reached_B:
                    reached_B[jb], reaching[jb] = k, p
    back = {jb: _trace_edge(m, e, unit, length, "B", ba) for jb, e in enumerate(B.stable) if jb not in reached_B}
    fwd = [ps[0] if ps else None for ps in arms.values()]
    for p in [*(p for ps in arms.values() for p in ps), *(p for ps in back.values() for p in ps)]:
        if p.reached:
            continue
        ev = next((e for e in p.branch.events if e.stability == "lost" or e.kind == "joint_limit"), None)
        if ev is None:  # ended otherwise (t_max on an unstable point cannot happen with stop_at); keep the last
            continue
        u = float(ev.t) if p.start_side == "A" else length - float(ev.t)
        d = a + u * unit
        out.append(AtlasCrossing("branch_end", float(d[0]), float(d[1]), edge, u / length, float(ev.energy),
                                 ev.q.copy(), ev.force.copy(), ev.kind, ev.method,
                                 null_vector=None if ev.null_vector is None else ev.null_vector.copy()))
    if A.stable and B.stable:
        least_A, least_B = _least_set(m, A), _least_set(m, B)
        if any(reached_B.get(jb) in least_A for jb in least_B):
            return out                                   # a least branch at A is a least one at B
        if len(least_A) > 1 or len(least_B) > 1:
            return out                                   # a tie at an end: the switch is that target (_ties)
        P = fwd[0]                                       # A's least-energy branch
        Q = reaching[0] if 0 in reaching else (back[0][0] if back[0] else None)
        if P is None or Q is None:                       # a branch that cannot leave its end: no shared stretch
            return out
        sw = _switch(m, P, Q, a, unit, length, edge)
        if sw is not None:
            out.append(sw)
    return out


def _least_set(m: Manipulator, t: AtlasTarget) -> set[int]:
    """Indices of the stable equilibria of ``t`` tying for the least energy."""
    tol = TIE_TOL * _energy_scale(m)
    return {k for k, e in enumerate(t.stable) if e.energy - t.stable[0].energy <= tol}


def _ties(m: Manipulator, targets: list) -> list[AtlasCrossing]:
    """A target where two stable equilibria tie for the least energy is on a switch curve: a crossing there."""
    out = []
    for j, row in enumerate(targets):
        for i, t in enumerate(row):
            if t.success and t.tie:
                a, b = t.stable[0], t.stable[1]
                out.append(AtlasCrossing("switch", t.dx, t.dy, ((i, j), (i, j)), 0.0, float(a.energy), a.q.copy(),
                                         a.force.copy(), "maxwell", "tie", b.q.copy(), b.force.copy()))
    return out


def _solve_on(m: Manipulator, p: _Path, u: float, a: np.ndarray, unit: np.ndarray):
    """The equilibrium of branch ``p`` at edge coordinate ``u`` (Newton from the interpolated point), or None."""
    U = p.u
    order = np.argsort(U)
    Us, Q, F = U[order], p.branch.q[order], p.branch.force[order]
    if u < Us[0] - 1e-12 or u > Us[-1] + 1e-12:
        return None
    q0 = np.array([np.interp(u, Us, Q[:, c]) for c in range(Q.shape[1])])
    F0 = np.array([np.interp(u, Us, F[:, c]) for c in range(2)])
    d = a + u * unit
    target = m.target(float(d[0]), float(d[1]))
    if not m.linear_springs:                 # Newton under the laws (the path problem's corrector), stable only
        try:
            st = start_state(m, q0, target=target, force=F0, moved=False)
        except TensegrityError:
            return None
        return st if np.max(np.abs(st.q - q0)) <= 0.05 else None
    res = chain_solver(m).newton_kkt(target, q0, F0)
    if not res.success or res.on_bound or np.max(np.abs(res.q - q0)) > 0.05:
        return None
    eq = make_equilibrium(m, res, constrained=True)
    return eq if eq.stable else None


def _switch(m: Manipulator, P: _Path, Q: _Path, a: np.ndarray, unit: np.ndarray, length: float,
            edge: tuple) -> AtlasCrossing | None:
    lo = max(P.u.min(), Q.u.min())
    hi = min(P.u.max(), Q.u.max())

    def g(u: float) -> float:
        ep, eq = _solve_on(m, P, u, a, unit), _solve_on(m, Q, u, a, unit)
        if ep is None or eq is None:
            return math.nan
        return ep.energy - eq.energy

    def crossing(u: float, method: str, ep: Equilibrium, eq: Equilibrium) -> AtlasCrossing:
        d = a + u * unit
        return AtlasCrossing("switch", float(d[0]), float(d[1]), edge, u / length, float(ep.energy),
                             ep.q.copy(), ep.force.copy(), "maxwell", method, eq.q.copy(), eq.force.copy())

    if hi > lo:
        us = np.linspace(lo, hi, 9)
        us[-1] = hi - 1e-9 * length if hi < length else hi
        us[0] = lo + 1e-9 * length if lo > 0 else lo
        gs = np.array([g(u) for u in us])
        for k in range(us.size - 1):
            if math.isfinite(gs[k]) and math.isfinite(gs[k + 1]) and gs[k] <= 0.0 <= gs[k + 1] \
                    or math.isfinite(gs[k]) and math.isfinite(gs[k + 1]) and gs[k + 1] <= 0.0 <= gs[k]:
                if gs[k] == 0.0:
                    us0 = us[k]
                elif gs[k + 1] == 0.0:
                    us0 = us[k + 1]
                else:
                    us0 = so.brentq(lambda u: _finite_or_raise(g(u)), us[k], us[k + 1], xtol=1e-13 * length,
                                    rtol=1e-14)
                ep, eq = _solve_on(m, P, us0, a, unit), _solve_on(m, Q, us0, a, unit)
                if ep is not None and eq is not None:
                    if np.max(np.abs(ep.q - eq.q)) < SAME_Q:
                        return None          # one branch seen from both ends: no switch
                    return crossing(us0, "equal_energy", ep, eq)
    # no equal-energy point shared: the least branch at A ends first (or starts late at B's side)
    if P.u.max() < length - 1e-12:
        u = float(P.u.max())
        ep, eq = P.branch, None
        k = int(np.argmax(P.u))
        other = _solve_on(m, Q, u, a, unit)
        d = a + u * unit
        return AtlasCrossing("switch", float(d[0]), float(d[1]), edge, u / length, float(ep.energy[k]),
                             ep.q[k].copy(), ep.force[k].copy(), "maxwell", "branch_end",
                             None if other is None else other.q.copy(),
                             None if other is None else other.force.copy())
    if Q.u.min() > 1e-12:        # B's least branch is born on the edge (its end seen from B) already lower
        u = float(Q.u.min())
        k = int(np.argmin(Q.u))
        mine = _solve_on(m, P, u, a, unit)
        d = a + u * unit
        return AtlasCrossing("switch", float(d[0]), float(d[1]), edge, u / length, float(Q.branch.energy[k]),
                             Q.branch.q[k].copy() if mine is None else mine.q.copy(),
                             Q.branch.force[k].copy() if mine is None else mine.force.copy(), "maxwell",
                             "branch_end", Q.branch.q[k].copy(), Q.branch.force[k].copy())
    return None


def _finite_or_raise(v: float) -> float:
    if not math.isfinite(v):
        raise _EdgeFailed("a branch could not be solved inside the bracket of the switch")
    return v
