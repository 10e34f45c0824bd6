"""Continuation: equilibria followed along a sequence of tip targets, in one home.

Three users, one mechanism (warm-started Newton on the KKT system, the compiled continuation
kernel of :meth:`ChainSolver.batch_continue <tensegrity_opt.numerics.ChainSolver.batch_continue>`
for short chains):

* :func:`solve_equilibria_batch` - a whole trajectory of targets in one call;
* :class:`Tracker` - one target per call (control loops);
* :func:`follow` - one branch of a force-deflection curve (:mod:`.curves`).

Trajectories (:func:`solve_equilibria_batch`)
---------------------------------------------
A trajectory of tip targets solved in one call (control loops).

``solve_equilibria_batch`` follows the targets in order. The first reachable target gets
the global least-energy stable equilibrium (:func:`solve_equilibrium`); with
``continuation=True`` every next one continues the branch through the previous solution —
what a manipulator driven along a trajectory actually does — by Newton corrections run
in compiled code for short chains (the C kernels of :mod:`tensegrity_opt.numerics.kernels` up to ``KERNEL_MAX``
segments, CasADi's ``rootfinder`` under ``mapaccum`` up to ``numerics.DENSE_MAX``), classified
in one batch. For one target at a time (a control loop) see :class:`tensegrity_opt.Tracker`. A point where the
branch ends or loses stability is re-solved globally (warm-started from the previous configuration) and the
continuation goes on from there.
With ``continuation=False`` every target is solved globally on its own.

Each target yields an :class:`Equilibrium` or the exception explaining why it has none
(unreachable, no stable equilibrium...): one bad target never loses the others.

Control steps (:class:`Tracker`)
--------------------------------
Equilibria along a moving tip target, one call per control step (the control-loop API).

A control loop asks for the equilibrium at a target a little away from the last one, every
few milliseconds. :class:`Tracker` keeps the previous solution ``(q, F)`` and answers each
new target with one warm-started Newton solve on the KKT system (compiled code for chains of
up to ``kernels.KERNEL_MAX`` segments: tens of microseconds for ``n = 4``), the way a
manipulator driven along a path stays on its equilibrium branch. Where that branch ends or
loses stability the tracker does what the mechanism does: it jumps, by a global search
started from the previous configuration, to the least-energy stable equilibrium
(``jump=False`` keeps the branch and reports ``stable=False`` instead).

>>> import tensegrity_opt as to
>>> tr = to.Tracker(to.Manipulator.uniform(4))
>>> eq = tr.solve(0.10)              # first call: global least-energy stable equilibrium
>>> eq = tr.solve(0.101, 0.002)      # next calls: one warm-started local solve
>>> round(eq.fx, 4), eq.stable
(-0.5751, True)

A tracker is not thread-safe (it holds one branch); use one per control loop.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from ...errors import InvalidParameterError, SolverError, TensegrityError, TimeLimitError
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...model.springs import linear_only
from ...numerics import chain_solver
from ...numerics.layout import equilibrium_unknowns
from ...outcome import SolverInfo
from ...timelimit import check_time
from ..equilibria.equilibrium import (
    Equilibrium,
    check_q0,
    is_equilibrium,
    local_equilibrium,
    make_equilibrium,
)
from ..equilibria.least_energy import solve_equilibrium
from ..equilibria.stability import classify_batch, classify_reduced

__all__ = ["solve_equilibria_batch", "continuation_prefix", "Prefix", "Tracker", "BranchPoints", "follow"]


def _targets(targets) -> np.ndarray:
    arr = np.asarray(targets, dtype=float)
    if arr.ndim == 1 and arr.size == 2:
        arr = arr[None, :]
    if arr.ndim != 2 or arr.shape[1] != 2 or arr.shape[0] == 0:
        raise InvalidParameterError("targets must be a non-empty sequence of (dx, dy) pairs", field="targets")
    return arr


def solve_equilibria_batch(m: Manipulator, targets, *, continuation: bool = True, q0=None,
                           deadline: float | None = None) -> list[Equilibrium | TensegrityError]:
    """Equilibria for a sequence of deflections ``(dx, dy)``, in order.

    Parameters
    ----------
    m : Manipulator
    targets : array_like (N, 2)
        Deflections ``(dx, dy)`` (length units); the tip goes to ``(2 sum(b) - dx, dy)``.
    continuation : bool
        Follow the branch through the previous solution (default) or solve each globally.
    q0 : array_like (n,), optional
        A configuration near the first target (seeds its global solve).
    deadline : float, optional
        A ``time.monotonic()`` instant: targets not started by then get a
        :class:`TimeLimitError` (``code = "timeout"``).

    Returns
    -------
    list
        One entry per target: an :class:`Equilibrium` (stable) or a :class:`TensegrityError`
        (a ``ValueError`` or ``RuntimeError`` subclass with ``code``, ``field``, ``status``).
    """
    unloaded_only(m, "solve_equilibria_batch")
    linear_only(m, "solve_equilibria_batch")
    pts = _targets(targets)
    N = pts.shape[0]
    out: list[Equilibrium | TensegrityError | None] = [None] * N
    prev: Equilibrium | None = None
    start_q = check_q0(m, q0)
    mdl = chain_solver(m)
    i = 0
    while i < N:
        if deadline is not None and time.monotonic() > deadline:
            for j in range(i, N):
                out[j] = TimeLimitError("the batch time limit was reached before this target")
            break
        dx, dy = pts[i]
        try:
            m.check_reachable(dx, dy)
        except TensegrityError as exc:
            out[i] = exc
            i += 1
            continue
        if not continuation or prev is None or (dx == 0.0 and dy == 0.0) or m.n < 2:
            seed = prev.q if (continuation and prev is not None) else (start_q if i == 0 else None)
            out[i] = prev_or_error = _global(m, dx, dy, seed)
            if isinstance(prev_or_error, Equilibrium) and prev_or_error.solver.status != "straight":
                prev = prev_or_error
            i += 1
            continue
        if mdl.dense:
            j = _run(m, pts, i, prev, out)
            if j > i:
                prev = out[j - 1]        # type: ignore[assignment]
                i = j
                continue
        # one point by the damped Newton method, else globally
        res = mdl.newton_kkt(m.target(dx, dy), prev.q, prev.force)
        eq = make_equilibrium(m, res, constrained=True) if (res.success and not res.on_bound) else None
        if eq is None or not eq.stable:
            eq = _global(m, dx, dy, prev.q)
        out[i] = eq
        if isinstance(eq, Equilibrium):
            prev = eq
        i += 1
    return out  # type: ignore[return-value]


@dataclass(frozen=True)
class Prefix:
    """The leading converged points of a compiled continuation (k of them), classified."""

    q: np.ndarray             # (k, n) joint angles
    force: np.ndarray         # (k, 2)
    energy: np.ndarray        # (k,)
    tip: np.ndarray           # (k, 2)
    morse_index: np.ndarray   # (k,)
    stable: np.ndarray        # (k,) bool
    eigenvalues: np.ndarray   # (k, n-2) of the reduced Hessian, ascending
    iterations: np.ndarray | None = None   # (k,) Newton iterations per point (kernels), None: not counted


def continuation_prefix(m: Manipulator, targets: np.ndarray, q0: np.ndarray, F0: np.ndarray) -> Prefix:
    """Compiled continuation (short chains) from ``(q0, F0)`` along ``targets`` (tip positions, N x 2).

    Returns the leading points where Newton converged (KKT residual within ``1e-9`` of the torque
    scale) inside the physical range — the first failure ends the prefix — classified.
    """
    mdl = chain_solver(m)
    c = mdl.batch_continue(targets, equilibrium_unknowns(m.n).pack(phi=np.cumsum(q0), F=F0))
    Q = np.diff(np.hstack([np.zeros((c.Z.shape[0], 1)), c.phi]), axis=1)
    tol = 1e-9 * max(1.0, c.torque_scale)        # the residual is in the solver's units
    ok = (c.residual <= tol) & np.all(np.abs(Q) < m.joint_limits, axis=1) & np.all(np.isfinite(c.Z), axis=1)
    k = int(np.argmin(ok)) if not ok.all() else ok.size
    Q, Fs = Q[:k], c.force[:k]
    its = None if c.iterations is None else c.iterations[:k]
    if c.reduced_hessian is not None:
        return Prefix(Q, Fs, c.energy[:k], c.tip[:k], *classify_reduced(c.reduced_hessian[:k], scale=m.torque_scale),
                      iterations=its)
    E, H, J, T = mdl.batch_derivs(Q, Fs)
    return Prefix(Q, Fs, E, T, *classify_batch(H, J, scale=m.torque_scale), iterations=its)


def _global(m: Manipulator, dx: float, dy: float, q0) -> Equilibrium | TensegrityError:
    try:
        return solve_equilibrium(m, dx, dy, q0=q0, stops=False)
    except TensegrityError as exc:
        return exc


def _run(m: Manipulator, pts: np.ndarray, i: int, prev: Equilibrium, out: list) -> int:
    """Compiled continuation from ``prev`` over the reachable points from ``i``; fills ``out`` with
    the accepted (valid and stable) points and returns the index of the first one not accepted."""
    N = pts.shape[0]
    dist = np.hypot(m.straight_length - pts[i:, 0] - m.base_length, pts[i:, 1])
    bad = (dist > float(m.link_lengths.sum()) * (1 + 1e-12)) | ((pts[i:, 0] == 0.0) & (pts[i:, 1] == 0.0))
    stop = i + (int(np.argmax(bad)) if bad.any() else N - i)
    if stop <= i:
        return i
    targets = np.column_stack([m.straight_length - pts[i:stop, 0], pts[i:stop, 1]])
    pre = continuation_prefix(m, targets, prev.q, prev.force)
    Q, Fs, E, T, stable, w, its = pre.q, pre.force, pre.energy, pre.tip, pre.stable, pre.eigenvalues, pre.iterations
    k = Q.shape[0]
    if k == 0:
        return i
    k_st = int(np.argmin(stable)) if not stable.all() else k
    for j in range(k_st):
        q = Q[j]
        out[i + j] = Equilibrium(q=q.copy(), energy=float(E[j]), force=Fs[j].copy(), morse_index=0, stable=True,
                                 solver=SolverInfo("Newton_Converged", None if its is None else int(its[j])),
                                 tip=T[j].copy(),
                                 control="displacement", springs=m.springs,
                                 hessian_eigenvalues=w[j].copy())
    return i + k_st


# ---------------------------------------------------------------------------- control steps
class Tracker:
    """Follow the equilibrium of ``m`` as the tip deflection ``(dx, dy)`` changes.

    Parameters
    ----------
    m : Manipulator
    start : Equilibrium, optional
        A displacement-controlled equilibrium of ``m`` to continue from; default: the first
        :meth:`solve` runs the global search.
    jump : bool
        Where the followed branch ends or becomes unstable, re-solve globally (warm-started from
        the previous configuration) — what the physical chain does (default). ``False``: stay on
        the branch while it exists and report its stability.

    Attributes
    ----------
    current : Equilibrium or None
        The last answer.
    jumps : int
        How many times the tracker left its branch for a global re-solve.
    """

    def __init__(self, m: Manipulator, start: Equilibrium | None = None, *, jump: bool = True) -> None:
        unloaded_only(m, "Tracker")
        if start is not None and (start.control != "displacement" or start.q.shape != (m.n,)):
            raise ValueError("start must be a displacement-controlled equilibrium of this manipulator")
        linear_only(m, "Tracker")
        self.m = m
        self.jump = bool(jump)
        self.current = start
        self.jumps = 0

    def solve(self, dx: float, dy: float = 0.0) -> Equilibrium:
        """The equilibrium with the tip at ``(2 sum(b) - dx, dy)`` (length units), continuing the last one.

        Raises what :func:`solve_equilibrium` raises: ``UnreachableTargetError`` (a ``ValueError``)
        beyond reach, ``NoEquilibriumError``/``SolverError`` (``RuntimeError``) when no equilibrium is
        found; the tracker then keeps its previous state.
        """
        m = self.m
        prev = self.current
        if prev is None or prev.status == "exact" or m.n < 2 or (dx == 0.0 and dy == 0.0):
            eq = solve_equilibrium(m, dx, dy, q0=None if prev is None else prev.q, stops=False)
        else:
            target = m.check_reachable(dx, dy)
            res = chain_solver(m).newton_kkt(target, prev.q, prev.force)
            if not is_equilibrium(m, res, target, check_residual=False):
                res = local_equilibrium(m, target, prev.q, minimize=True)     # IPOPT from the previous shape
                if not is_equilibrium(m, res, target):
                    res = None
            eq = make_equilibrium(m, res, constrained=True) if res is not None else None
            if eq is None or (self.jump and not eq.stable):
                if eq is None and not self.jump:
                    raise SolverError(f"the followed branch ends before dx={dx:g}, dy={dy:g}",
                                      status="branch_ended")
                eq = solve_equilibrium(m, dx, dy, q0=prev.q, stops=False)
                self.jumps += 1
        self.current = eq
        return eq

    def reset(self, start: Equilibrium | None = None) -> None:
        """Forget the branch (the next :meth:`solve` searches globally), or continue from ``start``."""
        self.__init__(self.m, start, jump=self.jump)

    @property
    def q(self) -> np.ndarray | None:
        """Joint angles of the last answer (rad), or ``None``."""
        return None if self.current is None else self.current.q


# ---------------------------------------------------------------------------- curve branches
@lru_cache(maxsize=64)
def _newton_info(iterations: int | None) -> SolverInfo:
    """The (shared, immutable) solver detail of a compiled continuation point."""
    return SolverInfo("Newton_Converged", iterations)


class BranchPoints:
    """One branch followed over the points of a run (arrays over all points of the curve)."""

    def __init__(self, bid: int, npts: int, n: int) -> None:
        self.id = bid
        self.q = np.full((npts, n), np.nan)
        self.F = np.full((npts, 2), np.nan)
        self.E = np.full(npts, np.nan)
        self.morse = np.full(npts, -1, dtype=int)
        self.stable = np.zeros(npts, dtype=bool)
        self.valid = np.zeros(npts, dtype=bool)
        self.solver: list[SolverInfo | None] = [None] * npts

    def set(self, i: int, eq: Equilibrium) -> None:
        self.q[i], self.F[i], self.E[i] = eq.q, eq.force, eq.energy
        self.morse[i], self.stable[i], self.valid[i], self.solver[i] = eq.morse_index, eq.stable, True, eq.solver


def follow(m: Manipulator, br: BranchPoints, start: int, stop: int, targets: np.ndarray, dxs, dys) -> None:
    """Continue ``br`` from its solution at ``start`` over the points ``start+1 .. stop-1``."""
    mdl = chain_solver(m)
    n = m.n
    if n == 1:                       # no continuation: every point is fixed by its target
        for i in range(start + 1, stop):
            try:
                br.set(i, solve_equilibrium(m, dxs[i], dys[i], stops=False))
            except TimeLimitError:
                raise
            except TensegrityError:
                return
        return
    lim = m.joint_limits
    s = start
    while s + 1 < stop:
        check_time("the force-deflection curve")
        if mdl.dense:
            pre = continuation_prefix(m, targets[s + 1:stop], br.q[s], br.F[s])
            good = pre.q.shape[0]
            if good:
                idx = np.arange(s + 1, s + 1 + good)
                br.q[idx], br.F[idx], br.E[idx] = pre.q, pre.force, pre.energy
                br.morse[idx], br.stable[idx], br.valid[idx] = pre.morse_index, pre.stable, True
                its = [None] * good if pre.iterations is None else pre.iterations.tolist()
                br.solver[s + 1:s + 1 + good] = map(_newton_info, its)
                s += good
        if s + 1 >= stop:
            break
        # damped Newton (square-root predictor near the straight chain) for the next point
        i = s + 1
        q0, F0 = br.q[s], br.F[s]
        if dys[i] == 0.0 and dys[s] == 0.0 and dxs[s] > 0.0 and dxs[i] > 0.0:
            r = math.sqrt(dxs[i] / dxs[s])
            q0, F0 = q0 * r, np.array([F0[0], F0[1] * r])
        res = mdl.newton_kkt(targets[i], q0, F0)
        if not (res.success and np.all(np.abs(res.q) < lim)):
            return                      # the branch ends here
        br.set(i, make_equilibrium(m, res, constrained=True))
        s = i
