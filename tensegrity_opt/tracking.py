"""Equilibria along a moving tip target, one call per control step (the control-loop API).

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

import numpy as np

from .equilibrium import (Equilibrium, is_equilibrium, local_equilibrium, make_equilibrium, solve_equilibrium)
from .errors import SolverError
from .manipulator import Manipulator
from .solvers import model

__all__ = ["Tracker"]


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
        if start is not None and (start.control != "displacement" or start.q.shape != (m.n,)):
            raise ValueError("start must be a displacement-controlled equilibrium of this manipulator")
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
        if prev is None or prev.status in ("straight", "closed_form") or m.n < 2 or (dx == 0.0 and dy == 0.0):
            eq = solve_equilibrium(m, dx, dy, q0=None if prev is None else prev.q)
        else:
            target = m.check_reachable(dx, dy)
            res = model(m.n).newton_kkt(m.params, m.joint_limits, target, prev.q, prev.force)
            if not is_equilibrium(m, res, target, check_residual=False):
                res = local_equilibrium(m, target, prev.q, minimize=True)     # IPOPT from the previous shape
                if not is_equilibrium(m, res, target):
                    res = None
            eq = make_equilibrium(m, res, constrained=True) if res is not None else None
            if eq is None or (self.jump and not eq.stable):
                if eq is None and not self.jump:
                    raise SolverError(f"the followed branch ends before dx={dx:g}, dy={dy:g}",
                                      status="branch_ended")
                eq = solve_equilibrium(m, dx, dy, q0=prev.q)
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
