"""The path problem of one chain under one control: :class:`PathProblem` and its points.

``x = (q, F, t)`` (``n + 3`` numbers) solves the ``n + 2`` equations ``R(z, t) = 0`` of
:mod:`tensegrity_opt.numerics.path_system` (``z = (q, F)``; the control sets which rows hold the tip and
which prescribe the force, :mod:`.control`). :class:`PathProblem` evaluates them, corrects a guess onto the
solution set (Newton on the bordered system ``[R(x); a . (w x) = b]``), gives the unit tangent and
classifies a point: its stability is the inertia of the Hessian of ``E - F . tip`` reduced to the tip motions
the control leaves free (``docs/model.md``): ``Z = I`` under a dead load, the null space of ``dy/dq`` when
guided, of ``J`` when the tip is held. The scaled coordinates ``X = w * x`` balance radians, forces (in
``k c^2 / (2 b)``) and lengths (in ``2 b``) in the arclength. Chains up to ``numerics.DENSE_MAX`` segments.

The arclength engine (:mod:`.branches`), the event location (:mod:`.events`), branch switching
(:mod:`.diagram`), the stability boundaries, the limit loads and the simulation all work on it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...errors import InvalidParameterError, SingularStartError, UnsupportedError
from ...model.manipulator import Manipulator
from ...model.springs import Springs
from ...numerics import DENSE_MAX
from ...numerics.path_system import control_vector, path_system
from .control import Control

__all__ = ["PathProblem", "PathPoint", "path_point", "refuse_start_on_stop", "LIMIT_MARGIN", "NEWTON_TOL",
           "NEWTON_ITER", "EIG_REL_TOL", "SINGULAR_START"]

#: A point is on a joint limit at ``|q_i| >= (1 - LIMIT_MARGIN) (pi - 2 beta_i)``: the branch ends there.
LIMIT_MARGIN = 1e-6
#: Scaled residual below which the corrector has converged.
NEWTON_TOL = 1e-11
#: Corrector iterations allowed per step.
NEWTON_ITER = 12
#: Relative eigenvalue tolerance of the stability classification (as
#: :mod:`tensegrity_opt.analyses.equilibria.stability`).
EIG_REL_TOL = 1e-9
#: A start whose unit tangent (scaled) has a ``t`` component below this is singular: t has no direction there.
SINGULAR_START = 1e-10


def refuse_start_on_stop(stopped, field: str, doing: str) -> None:
    """Refuse a start resting on a joint's stop (``stopped``: per joint, True on a stop): the path engine follows
    branches inside the range only. ``UnsupportedError`` naming ``field``, status ``start_on_stop``; ``doing`` says
    what is followed (``"the loading path is followed by arclength continuation"``)."""
    on = np.flatnonzero(np.asarray(stopped, dtype=bool))
    if on.size:
        raise UnsupportedError(f"the {field} rests on joint {int(on[0]) + 1}'s stop (the arm as built: a slack spring "
                               f"lets it reach it); {doing} inside the range only", field=field,
                               status="start_on_stop")


class PathProblem:
    """The path system of one chain and control: evaluation, corrector, tangent, classification.

    ``x = (q, F, t)`` (``N + 1 = n + 3`` numbers); the scaled coordinates ``X = w * x`` balance
    radians, forces (``Fs = k c^2 / (2 b)``) and lengths (``Ls = 2 b``) in the arclength.
    """

    def __init__(self, m: Manipulator, control: Control, start_q: np.ndarray, start_F: np.ndarray | None,
                 dp2: np.ndarray | None = None) -> None:
        if m.n > DENSE_MAX:
            raise InvalidParameterError(f"arclength continuation handles chains of up to {DENSE_MAX} segments, "
                                        f"got n = {m.n}", field="n")
        self.m, self.control, self.n = m, control, m.n
        n = m.n
        self.N = n + 2
        tension = () if m.linear_springs else tuple(seg.tension_only for seg in m.segments)
        self.ps = path_system(n, tension)
        #: the blocks of a point ``x = (q, F, t)``, of a tangent and of the columns of ``R_x`` in ``(z, t)``
        self.point = self.ps.layouts.branch_point
        # the chain's numbers (the law is the path system's: the parameters are the same under both)
        self.p = np.array((m if m.linear_springs else m.with_spring("linear")).params, dtype=float)
        self.dp = np.zeros(self.p.size)
        self.dp2 = np.zeros(self.p.size) if dp2 is None else np.asarray(dp2, float)
        at_p = self.ps.layouts.parameters
        self.Ls = float(m.straight_length / n)
        self.Fs = float(m.torque_scale / self.Ls)
        tip0 = m.tip(start_q)
        eye, zero = np.eye(2), np.zeros((2, 2))
        k = control.kind
        if k == "displacement":
            A_tip, A_F, c, F_ref = eye, zero, np.array([-control.direction[0], control.direction[1]]), np.zeros(2)
            t_scale = self.Ls
        elif k == "load":
            A_tip, A_F, c, F_ref = zero, eye, control.direction, control.base
            t_scale = self.Fs
        elif k in ("guided", "wall"):
            nu = control.normal
            tau = np.array([nu[1], -nu[0]])
            A_tip = np.array([nu, [0.0, 0.0]])
            A_F = np.array([[0.0, 0.0], tau])
            c = np.array([0.0, float(tau @ control.direction)])
            F_ref = control.base
            t_scale = self.Fs
        elif k == "move":                                # every input along a segment, t in [0, 1]
            dl = control.preload_direction
            self.dp[at_p["L10"]] = dl[:, 0]
            self.dp[at_p["L20"]] = dl[:, 1]
            last = control.tip_direction
            if control.tip == "held":
                A_tip, A_F, c, F_ref = eye, zero, np.array([-last[0], last[1]]), np.zeros(2)
                size = math.sqrt(float(dl.ravel() @ dl.ravel()) + float(last @ last)) / self.Ls
            else:
                A_tip, A_F, c, F_ref = zero, eye, last, control.base
                size = math.hypot(math.sqrt(float(dl.ravel() @ dl.ravel())) / self.Ls,
                                  math.sqrt(float(last @ last)) / self.Fs)
            t_scale = 1.0 / size                         # the arclength in t: the scaled distance moved
        else:                                            # preload
            dl = control.preload_direction
            self.dp[at_p["L10"]] = dl[:, 0]
            self.dp[at_p["L20"]] = dl[:, 1]
            if control.tip == "held":
                A_tip, A_F, c, F_ref = eye, zero, np.zeros(2), np.zeros(2)
            else:
                A_tip, A_F, c, F_ref = zero, eye, np.zeros(2), control.base
            t_scale = self.Ls
        self.A_tip = A_tip
        self.held_rows = A_tip[[i for i in range(2) if np.any(A_tip[i] != 0.0)]]
        self.ctl = control_vector(A_tip, A_F, c, tip0, F_ref)
        self.w = self.point.pack(q=1.0, F=1.0 / self.Fs, t=1.0 / t_scale)
        rows = [1.0 / (self.Ls if np.any(A_tip[i] != 0.0) else self.Fs) for i in range(2)]
        self.rs = self.ps.layouts.rows.pack(grad=1.0 / m.torque_scale, control=rows)
        self.limits = m.joint_limits
        if start_F is None:
            start_F = m.force_from_torques(start_q) if k in ("displacement",) or control.held[0] else F_ref
        self.x0_guess = self.point.pack(q=start_q, F=start_F, t=0.0)
        self._last = None
        # the held rows scaled to torque units: the bordered Hessian's entries are then of one size
        self.kkt_scale = m.torque_scale / self.Ls

    # -------------------------------------------------------------- evaluation
    def full(self, x: np.ndarray, s: float = 0.0) -> np.ndarray:
        """``x`` with the second parameter ``s`` appended (the path system's argument; ``s = 0``: the chain
        itself, else moved along ``dp2``, as the stability boundaries do)."""
        return np.concatenate([x, [s]])

    def keep(self, x: np.ndarray, out) -> None:
        """Remember ``out``, the evaluation at ``x`` (a compiled step's last one), for :meth:`eval_all`."""
        self._last = (x.copy(), out)

    def eval_all(self, x: np.ndarray, s: float = 0.0):
        """``(R, R_x, H, J, E, tip)`` at ``x`` (the last evaluation is kept: the corrector's final check
        serves the tangent and the classification of the same point)."""
        c = self._last
        if c is not None and s == 0.0 and np.array_equal(c[0], x):
            return c[1]
        out = self.ps.evaluate(self.full(x, s), self.p, self.dp, self.dp2, self.ctl)
        if s == 0.0:
            self._last = (x.copy(), out)
        return out

    def eval(self, x: np.ndarray, s: float = 0.0):
        """``(R, R_x)`` with ``R_x`` the ``N x (N + 1)`` Jacobian in ``(z, t)`` (its columns the blocks of
        :attr:`point`)."""
        out = self.eval_all(x, s)
        return out[0], out[1][:, :self.point.size]

    def residual(self, R: np.ndarray) -> float:
        return float(np.abs(R * self.rs).max())

    # -------------------------------------------------------------- corrector and tangent
    def correct(self, x_guess: np.ndarray, a: np.ndarray, b: float, *, iters: int = NEWTON_ITER):
        """Newton on ``[R(x); a . (w x) = b]``; returns ``(x, iterations)`` or ``(None, iterations)``."""
        x = x_guess.copy()
        aw = a * self.w
        last = math.inf
        for it in range(1, iters + 1):
            R, Rx = self.eval(x)
            r = self.residual(R)
            g = float(aw @ x - b)
            if not (math.isfinite(r) and math.isfinite(g)):
                return None, it
            if r <= NEWTON_TOL and abs(g) <= 1e-12 * max(1.0, abs(b)):
                return x, it
            M = np.vstack([Rx, aw])
            try:
                dx = np.linalg.solve(M, -np.concatenate([R, [g]]))
            except np.linalg.LinAlgError:       # exactly at a branch point the bordered matrix is singular
                dx = np.linalg.lstsq(M, -np.concatenate([R, [g]]), rcond=None)[0]
            x = x + dx
            step = float(np.abs(dx * self.w).max())
            if it > 4 and step > last * 0.9 and step > 1e-8:
                return None, it              # not contracting
            last = step
            if step < 1e-14 and r <= NEWTON_TOL * 10:
                R, _ = self.eval(x)
                if self.residual(R) <= NEWTON_TOL:
                    return x, it
        R, _ = self.eval(x)
        return (x, iters) if self.residual(R) <= NEWTON_TOL else (None, iters)

    def correct_t(self, x_guess: np.ndarray, t: float):
        """The point at a given ``t`` (a natural-parameter solve)."""
        a = np.zeros(self.point.size)
        at_t = self.point["t"]
        a[at_t] = 1.0 / self.w[at_t]
        return self.correct(x_guess, a, t)

    def tangent(self, x: np.ndarray, prev: np.ndarray | None, sign: float = 1.0) -> np.ndarray:
        """Unit tangent in scaled coordinates, oriented along ``prev`` (or with ``t`` growing by ``sign``)."""
        _, Rx = self.eval(x)
        A = Rx / self.w
        if prev is not None:
            M = np.vstack([A, prev])
            rhs = np.zeros(self.point.size)
            rhs[-1] = 1.0                       # the last row: prev . v = 1
            try:
                v = np.linalg.solve(M, rhs)
                return v / np.linalg.norm(v)
            except np.linalg.LinAlgError:
                pass
        _, _, Vt = np.linalg.svd(A)
        v = Vt[-1]                              # the right singular vector of the smallest singular value
        if prev is not None:
            return v if v @ prev >= 0 else -v
        at_t = self.point["t"]
        if abs(v[at_t]) < SINGULAR_START:
            raise SingularStartError(
                "start is a singular point of its path under this control (a fold or a branch point; "
                "e.g. the straight chain with its tip held at full reach, where it buckles): the path has no single "
                "direction in which t grows there. Start from an equilibrium nearby, or use the bifurcation diagram "
                "(its branches through the point)", field="start")
        return v if v[at_t] * sign > 0 else -v

    # -------------------------------------------------------------- classification
    def reduced(self, x: np.ndarray, s: float = 0.0):
        """Stability data at ``x``: ``(w, J, E, tip)`` with ``w`` the ascending eigenvalues of the Hessian
        ``H`` of ``E - F . tip`` (tip free) or of the bordered matrix ``[[H, C^T], [C, 0]]`` (``C`` the held
        rows of ``J``, scaled to torque units), whose inertia is that of the reduced Hessian ``Z^T H Z``
        plus ``k`` negative and ``k`` positive eigenvalues (``k`` held rows): :meth:`morse` subtracts them,
        and the reduced eigenvalue ``j`` crosses zero where ``w[k + j]`` does."""
        _, _, H, J, E, tip = self.eval_all(x, s)
        k = self.held_rows.shape[0]
        if k:
            C = (self.held_rows @ J) * self.kkt_scale
            K = np.zeros((self.n + k, self.n + k))
            K[:self.n, :self.n] = H
            K[:self.n, self.n:] = C.T
            K[self.n:, :self.n] = C
            H = K
        w = np.linalg.eigvalsh(H) if H.shape[0] else np.zeros(0)
        return w, J, E, tip

    def morse(self, w: np.ndarray) -> tuple[int, bool]:
        """``(Morse index, stable)`` from :meth:`reduced`'s eigenvalues."""
        k = self.held_rows.shape[0]
        if w.size <= 2 * k:
            return 0, True
        tol = EIG_REL_TOL * max(self.m.torque_scale, float(np.abs(w).max()))
        idx = int(np.sum(w < -tol)) - k
        return idx, idx == 0 and not bool(np.any(np.abs(w) <= tol))

    def springs_at(self, t) -> Springs:
        """The chain's springs with the rest lengths at ``t`` (a number, or an array for a series): the start's,
        moved along the control's preload direction (preload and move controls)."""
        sp = self.m.springs
        dl = self.control.preload_direction
        if dl is None:
            return sp
        t = np.asarray(t, dtype=float)
        return sp.with_rest_lengths(sp.L0 + t[..., None, None] * dl)

    def limit_ratio(self, x: np.ndarray) -> tuple[float, int]:
        """``(max_i |q_i| / limit_i, i)``: how close the point is to a joint's range bound, and which joint."""
        r = np.abs(x[self.point["q"]]) / self.limits
        j = int(np.argmax(r))
        return float(r[j]), j


@dataclass
class PathPoint:
    """An accepted point of a branch: ``x``, the unit tangent ``tau`` (scaled coordinates), the eigenvalues
    ``w`` of :meth:`PathProblem.reduced`, the Morse index and stability, the energy ``E``, the tip and the tip
    Jacobian ``J``."""

    x: np.ndarray
    tau: np.ndarray
    w: np.ndarray
    morse: int
    stable: bool
    E: float
    tip: np.ndarray
    J: np.ndarray


def path_point(prob: PathProblem, x: np.ndarray, tau: np.ndarray) -> PathPoint:
    """The :class:`PathPoint` at ``x`` with tangent ``tau``, classified."""
    w, J, E, tip = prob.reduced(x)
    idx, st = prob.morse(w)
    return PathPoint(x, tau, w, idx, st, E, tip, J)

