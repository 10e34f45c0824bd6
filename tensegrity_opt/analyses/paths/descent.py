"""The quasi-static arm's state and its snap: :class:`ArmState`, :class:`Descent`.

Where the followed branch loses stability (:mod:`.simulation`) the arm leaves it by descent, the gradient flow
``dq/dtau = -grad V(q)`` of the potential ``V = E - F . tip`` (free tip; the load held at its value at the fold)
or of ``E`` on the tip constraint ``tip(q) = target`` (held tip; the projected flow), with the inputs frozen.
:meth:`Descent.run` integrates it with scipy's BDF (tolerances ``1e-8`` relative, ``1e-10`` absolute) until the
point is in the Newton neighbourhood of a strict minimum (:meth:`Descent.landing`), or a joint reaches its range
bound, or the time runs out.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.optimize as so
from scipy.integrate import BDF

from ...outcome import SolverInfo
from ...timelimit import expired
from ..equilibria.equilibrium import Equilibrium
from .problem import LIMIT_MARGIN

__all__ = ["ArmState", "state_at", "Descent", "MAX_DESCENT_STEPS", "POLISH_RADIUS"]

#: Integration steps of one descent before it is given up.
MAX_DESCENT_STEPS = 20000
#: Newton from a descent point is accepted when it lands within this distance (rad, largest joint).
POLISH_RADIUS = 0.05


@dataclass
class ArmState:
    """A converged equilibrium of the arm under the current inputs: configuration, force (the load when free,
    the holding force when held), tip, energy, Morse index and stability."""

    q: np.ndarray
    force: np.ndarray
    tip: np.ndarray
    energy: float
    morse: int
    stable: bool

    def potential(self, held: bool) -> float:
        """``E - F . tip`` (free) or ``E`` (held)."""
        return self.energy if held else self.energy - float(self.force @ self.tip)

    def equilibrium(self, held: bool) -> Equilibrium:
        """The state as an :class:`Equilibrium` (the start of the next step's branch)."""
        return Equilibrium(q=self.q.copy(), energy=self.energy, force=self.force.copy(), morse_index=self.morse,
                           stable=self.stable, solver=SolverInfo("simulation", 0), tip=self.tip.copy(),
                           control="displacement" if held else "force")


def state_at(prob, x: np.ndarray) -> ArmState:
    """The :class:`ArmState` at the point ``x`` of the path problem ``prob``, classified."""
    w, _, E, tip = prob.reduced(x)
    idx, st = prob.morse(w)
    at = prob.point
    return ArmState(x[at["q"]].copy(), x[at["F"]].copy(), np.asarray(tip, float).copy(), float(E), int(idx), bool(st))


class Descent:
    """The gradient flow of the potential at fixed inputs (``t`` of ``prob``), and its landing."""

    def __init__(self, prob, t: float, held: bool, F: np.ndarray) -> None:
        self.prob, self.t, self.held, self.F = prob, float(t), held, np.asarray(F, float)
        self.Ts = float(prob.m.torque_scale)
        self.at = prob.point
        rows = prob.ps.layouts.rows
        self.grad, self.control = rows["grad"], rows["control"]

    def x(self, q: np.ndarray, F: np.ndarray | None = None) -> np.ndarray:
        """The path problem's point at ``q`` under ``F`` (default the descent's) at its ``t``."""
        return self.at.pack(q=q, F=self.F if F is None else F, t=self.t)

    def multiplier(self, q: np.ndarray):
        """``(grad E, J, tip residual, F)`` for the held tip: ``F`` the least-squares multiplier."""
        R, _, _, J, _, _ = self.prob.eval_all(self.x(q, np.zeros(2)))
        g = R[self.grad]
        F = np.linalg.lstsq(J.T, g, rcond=None)[0]
        return g, J, R[self.control], F

    def field(self, _tau: float, q: np.ndarray) -> np.ndarray:
        if not self.held:
            R = self.prob.eval_all(self.x(q))[0]
            return -R[self.grad] / self.Ts
        g, J, r, F = self.multiplier(q)
        back = np.linalg.lstsq(J, r, rcond=None)[0]             # pulls the drift back onto tip(q) = target
        return -(g - J.T @ F) / self.Ts - back

    def jac(self, _tau: float, q: np.ndarray) -> np.ndarray:
        return -self.prob.eval_all(self.x(q))[2] / self.Ts

    def onto(self, q: np.ndarray) -> np.ndarray:
        """``q`` moved onto the tip constraint (Gauss-Newton, least-norm)."""
        for _ in range(8):
            _, J, r, _ = self.multiplier(q)
            if float(np.abs(r).max()) <= 1e-13 * self.prob.Ls:
                break
            q = q - np.linalg.lstsq(J, r, rcond=None)[0]
        return q

    def potential(self, q: np.ndarray) -> float:
        _, _, _, _, E, tip = self.prob.eval_all(self.x(q, np.zeros(2) if self.held else None))
        return float(E) if self.held else float(E) - float(self.F @ tip)

    def point(self, q: np.ndarray) -> np.ndarray:
        """The full ``x`` at ``q`` (held: with its least-squares multiplier)."""
        return self.x(q, self.multiplier(q)[3] if self.held else None)

    def landing(self, q: np.ndarray):
        """The polished minimum near ``q`` when ``q`` is in its Newton neighbourhood, else None."""
        prob = self.prob
        x = self.point(q)
        idx, st = prob.morse(prob.reduced(x)[0])
        if not st:
            return None
        y, _ = prob.correct_t(x, self.t)
        if y is None or float(np.abs(y[self.at["q"]] - q).max()) > POLISH_RADIUS:
            return None
        if prob.limit_ratio(y)[0] >= 1.0 - LIMIT_MARGIN:
            return None
        s = state_at(prob, y)
        if not s.stable or s.potential(self.held) > self.potential(q) + 1e-12 * self.Ts:
            return None
        return s

    def run(self, q0: np.ndarray):
        """``("landed", state)``, ``("joint_limit", q at the bound)``, ``("time_limit", q)`` or ``("failed", q)``."""
        prob = self.prob
        q0 = self.onto(q0) if self.held else q0
        solver = BDF(self.field, 0.0, q0, 1e12, rtol=1e-8, atol=1e-10,
                     jac=None if self.held else self.jac)
        q = q0
        for _ in range(MAX_DESCENT_STEPS):
            if expired():
                return "time_limit", q
            tau_a, qa = solver.t, solver.y.copy()
            msg = solver.step()
            if msg is not None or solver.status == "failed":
                return "failed", qa
            q = solver.y.copy()
            lim, _ = prob.limit_ratio(q)
            if lim >= 1.0 - LIMIT_MARGIN:
                dense = solver.dense_output()
                target = 1.0 - LIMIT_MARGIN
                try:
                    tau = so.brentq(lambda s: prob.limit_ratio(dense(s))[0] - target, tau_a, solver.t, xtol=1e-14)
                    ql = dense(tau)
                    if prob.limit_ratio(ql)[0] > target:
                        ql = qa
                except ValueError:
                    ql = qa
                return "joint_limit", ql
            s = self.landing(q)
            if s is not None:
                return "landed", s
            if solver.status == "finished":
                break
        return "failed", q

