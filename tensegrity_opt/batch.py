"""A trajectory of tip targets solved in one call (control loops).

``solve_equilibria_batch`` follows the targets in order. The first reachable target gets
the global least-energy stable equilibrium (:func:`solve_equilibrium`); with
``continuation=True`` every next one continues the branch through the previous solution —
what a manipulator driven along a trajectory actually does — by Newton corrections run
in compiled code for short chains (the C kernels of :mod:`.kernels` up to ``KERNEL_MAX``
segments, CasADi's ``rootfinder`` under ``mapaccum`` up to ``solvers.DENSE_MAX``), classified
in one batch. For one target at a time (a control loop) see :class:`tensegrity_opt.Tracker`. A point where the branch ends or loses stability is re-solved globally
(warm-started from the previous configuration) and the continuation goes on from there.
With ``continuation=False`` every target is solved globally on its own.

Each target yields an :class:`Equilibrium` or the exception explaining why it has none
(unreachable, no stable equilibrium...): one bad target never loses the others.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

from .equilibrium import Equilibrium, check_q0, make_equilibrium, solve_equilibrium
from .errors import InvalidParameterError, TensegrityError, TimeLimitError
from .manipulator import Manipulator
from .solvers import model
from .stability import classify_batch, classify_reduced

__all__ = ["solve_equilibria_batch", "continuation_prefix", "Prefix"]


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
    pts = _targets(targets)
    N = pts.shape[0]
    out: list[Equilibrium | TensegrityError | None] = [None] * N
    prev: Equilibrium | None = None
    start_q = check_q0(m, q0)
    mdl = model(m.n)
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
            if isinstance(prev_or_error, Equilibrium) and prev_or_error.status != "straight":
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
        res = mdl.newton_kkt(m.params, m.joint_limits, m.target(dx, dy), prev.q, prev.force)
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


def continuation_prefix(m: Manipulator, targets: np.ndarray, q0: np.ndarray, F0: np.ndarray) -> Prefix:
    """Compiled continuation (short chains) from ``(q0, F0)`` along ``targets`` (tip positions, N x 2).

    Returns the leading points where Newton converged (KKT residual within ``1e-9`` of the torque
    scale) inside the physical range — the first failure ends the prefix — classified.
    """
    n = m.n
    mdl = model(n)
    c = mdl.batch_continue(m.params, targets, np.concatenate([np.cumsum(q0), F0]))
    Z = c.Z
    Q = np.diff(np.hstack([np.zeros((Z.shape[0], 1)), Z[:, :n]]), axis=1)
    tol = 1e-9 * max(1.0, c.torque_scale)        # the residual is in the solver's units
    ok = (c.residual <= tol) & np.all(np.abs(Q) < m.joint_limits, axis=1) & np.all(np.isfinite(Z), axis=1)
    k = int(np.argmin(ok)) if not ok.all() else ok.size
    Q, Fs = Q[:k], Z[:k, n:]
    if c.reduced_hessian is not None:
        return Prefix(Q, Fs, c.energy[:k], c.tip[:k], *classify_reduced(c.reduced_hessian[:k], scale=m.torque_scale))
    E, H, J, T = mdl.batch_derivs(m.params, Q, Fs)
    return Prefix(Q, Fs, E, T, *classify_batch(H, J, scale=m.torque_scale))


def _global(m: Manipulator, dx: float, dy: float, q0) -> Equilibrium | TensegrityError:
    try:
        return solve_equilibrium(m, dx, dy, q0=q0)
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
    Q, Fs, E, T, stable, w = pre.q, pre.force, pre.energy, pre.tip, pre.stable, pre.eigenvalues
    k = Q.shape[0]
    if k == 0:
        return i
    k_st = int(np.argmin(stable)) if not stable.all() else k
    for j in range(k_st):
        q = Q[j]
        out[i + j] = Equilibrium(q=q.copy(), energy=float(E[j]), force=Fs[j].copy(), morse_index=0, stable=True,
                                 status="Newton_Converged",
                                 iterations=-1, tip=T[j].copy(), control="displacement",
                                 hessian_eigenvalues=w[j].copy())
    return i + k_st

