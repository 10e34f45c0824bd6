"""Equilibrium branches by pseudo-arclength continuation: predictor, corrector, events, branch switching.

One concept in one place (the natural-parameter followers — batches of targets, the
:class:`~tensegrity_opt.analyses.paths.continuation.Tracker`, force-deflection branches — are in
:mod:`.continuation`):

* a :class:`Control` says what the parameter ``t`` moves: the tip along a line in ``(dx, dy)``
  (:meth:`Control.displacement`), a dead tip load ``base + t d`` (:meth:`Control.load`), the paper's
  guided tip (``y`` held, the load along ``x``, ``Fy`` the reaction: :meth:`Control.guided`), a
  frictionless wall (:meth:`Control.wall`), or rest lengths along a direction in preload space with
  the tip free under a load or held (:meth:`Control.preload`), or rest lengths and the load (or the held
  tip) together along a segment, ``t`` its fraction (:meth:`Control.move`);
* :func:`trace_branch` follows the branch through a start: tangent predictor, Newton corrector on the
  bordered system ``[R(z, t); tau . (x - x_pred)] = 0``, adaptive step (iterations, tangent angle), in
  the units of :class:`_Problem` (angles in rad, forces in ``k c^2 / (2 b)``, lengths in ``2 b``);
* events between two points — a change of the Morse index (stability), a fold (the tangent's ``t``
  component changes sign), a branch point (a singular ``R_z`` with ``u . R_t = 0``), a joint limit —
  located precisely: the zero of a smooth test function along the branch (the eigenvalue of the
  reduced Hessian that changes sign; the joint angle), solved by Brent's method on the arclength with
  the corrector at each trial, then for folds the Moore-Spence extended system
  ``R = 0, R_z phi = 0, l . phi = 1`` by Newton (regular at a quadratic fold);
* :func:`switch_branch` starts the bifurcating branch at a branch point (the second direction of the
  2-dimensional null space of ``[R_z, R_t]``), :func:`bifurcation_diagram` every branch reached from
  a start through branch points, recursively.

The system (``n + 2`` equations in ``z = (q, F)``) is :mod:`tensegrity_opt.numerics.path_system`; the
stability of a point is the inertia of the Hessian of ``E - F . tip`` reduced to the tip motions the
control leaves free (conventions.md): ``Z = I`` under a dead load, the null space of ``dy/dq`` when
guided, of ``J`` when the tip is held. Chains up to ``numerics.DENSE_MAX`` segments.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import scipy.optimize as so

from ...errors import InvalidParameterError, NoEquilibriumError, TensegrityError
from ...model.manipulator import Manipulator
from ...numerics import DENSE_MAX
from ...numerics.path_system import control_vector, path_system
from ...serialize import nullable, number, numbers
from ...timelimit import expired, time_limit
from ..equilibria.equilibrium import Equilibrium, check_q0

__all__ = ["Control", "Branch", "BranchEvent", "trace_branch", "switch_branch", "bifurcation_diagram",
           "EVENT_KINDS", "STATUSES"]

#: Kinds of :class:`BranchEvent`.
EVENT_KINDS = ("fold", "branch_point", "joint_limit")
#: How a :class:`Branch` ended.
STATUSES = ("t_max", "t_min", "joint_limit", "max_points", "stability_loss", "event", "closed_loop",
            "workspace_boundary", "force_bound", "step_too_small", "time_limit", "corrector_failed")
#: Statuses of a branch traced to a regular end (``Branch.success``).
REGULAR_ENDS = ("t_max", "t_min", "joint_limit", "max_points", "stability_loss", "event", "closed_loop",
                "workspace_boundary", "force_bound")
#: The branch ends where the held tip reaches the edge of its workspace: the smallest singular value of the
#: held rows of the tip Jacobian below this fraction of its largest (the holding force then diverges).
SINGULAR_TIP = 1e-3
#: ... or where ``|F|`` exceeds this many force units ``k c^2 / (2 b)``.
FORCE_BOUND = 1e4

#: A point is on a joint limit at ``|q_i| >= (1 - LIMIT_MARGIN) (pi - 2 beta_i)``: the branch ends there.
LIMIT_MARGIN = 1e-6
#: Scaled residual below which the corrector has converged.
NEWTON_TOL = 1e-11
#: Corrector iterations allowed per step.
NEWTON_ITER = 12
#: Largest angle (rad) between consecutive tangents before the step is refused and halved.
MAX_TURN = 0.35
#: Relative eigenvalue tolerance of the stability classification (as :mod:`.stability`).
EIG_REL_TOL = 1e-9
#: ``|u . R_t| / |R_t|`` below which a singular point is a branch point rather than a fold.
BP_TOL = 1e-6

KINDS = ("displacement", "load", "guided", "wall", "preload", "move")


def _unit(v, field: str, size: int | None = None) -> np.ndarray:
    try:
        d = np.asarray(v, dtype=float).ravel()
    except (TypeError, ValueError):
        raise InvalidParameterError(f"{field} must be a vector of numbers, got {v!r}", field=field) from None
    if size is not None and d.size != size:
        raise InvalidParameterError(f"{field} must have {size} components, got {d.size}", field=field)
    if not np.all(np.isfinite(d)):
        raise InvalidParameterError(f"{field} must be finite, got {v!r}", field=field)
    norm = float(np.linalg.norm(d))
    if norm == 0.0:
        raise InvalidParameterError(f"{field} must not be zero", field=field)
    return d / norm


def _finite(v, field: str, size: int) -> np.ndarray:
    try:
        d = np.asarray(v, dtype=float).ravel()
    except (TypeError, ValueError):
        raise InvalidParameterError(f"{field} must be numbers, got {v!r}", field=field) from None
    if d.size != size or not np.all(np.isfinite(d)):
        raise InvalidParameterError(f"{field} must be {size} finite numbers, got {v!r}", field=field)
    return d


def _vec2(v, field: str) -> np.ndarray:
    try:
        d = np.asarray(v, dtype=float).ravel()
    except (TypeError, ValueError):
        raise InvalidParameterError(f"{field} must be a pair of numbers, got {v!r}", field=field) from None
    if d.size != 2 or not np.all(np.isfinite(d)):
        raise InvalidParameterError(f"{field} must be two finite numbers, got {v!r}", field=field)
    return d


@dataclass(frozen=True)
class Control:
    """What the continuation parameter ``t`` moves (``t = 0`` at the start point).

    Build it with a constructor: :meth:`displacement`, :meth:`load`, :meth:`guided`, :meth:`wall`,
    :meth:`preload`, :meth:`move`. Directions are normalised: ``t`` is the distance moved (length units
    for the tip and the rest lengths, force units for a load); for :meth:`move` (rest lengths and the
    load or the held tip together) ``t`` is the fraction of the move.
    """

    kind: str
    direction: np.ndarray
    base: np.ndarray = field(default_factory=lambda: np.zeros(2))
    normal: np.ndarray | None = None
    tip: str = "free"

    @classmethod
    def displacement(cls, direction=(1.0, 0.0)) -> "Control":
        """The tip moved along a line: the deflection ``(dx, dy)`` is the start's plus ``t`` times the
        unit ``direction`` (``dx > 0`` shortens the chain); ``F`` is the force holding it."""
        return cls("displacement", _unit(direction, "direction", 2))

    @classmethod
    def load(cls, direction=(-1.0, 0.0), base=(0.0, 0.0)) -> "Control":
        """A dead tip load ``F = base + t d`` (``d`` the unit ``direction``; ``(-1, 0)`` compresses),
        the tip free."""
        return cls("load", _unit(direction, "direction", 2), _vec2(base, "base"))

    @classmethod
    def guided(cls, direction=(-1.0, 0.0), base=(0.0, 0.0)) -> "Control":
        """The paper's guided tip: ``y`` held at the start's value, ``Fx = base_x + t d_x`` (``d`` the unit
        ``direction``), ``Fy`` the reaction of the guide. A wall of normal ``(0, 1)``."""
        d = _unit(direction, "direction", 2)
        if abs(d[0]) < 1e-12:
            raise InvalidParameterError("a guided load needs an x component (the guide takes y)", field="direction")
        return cls("guided", d, _vec2(base, "base"), np.array([0.0, 1.0]))

    @classmethod
    def wall(cls, normal=(0.0, 1.0), direction=(-1.0, 0.0), base=(0.0, 0.0)) -> "Control":
        """A frictionless wall through the start's tip: the tip slides along it (held along the unit
        ``normal``), the load along the wall is ``tau . (base + t d)`` (``tau`` the wall's tangent), the
        wall's reaction along the normal is part of ``F``."""
        nu = _unit(normal, "normal", 2)
        d = _unit(direction, "direction", 2)
        if abs(nu[1] * d[0] - nu[0] * d[1]) < 1e-12:
            raise InvalidParameterError("the load must have a component along the wall", field="direction")
        return cls("wall", d, _vec2(base, "base"), nu)

    @classmethod
    def preload(cls, direction, tip: str = "free", load=(0.0, 0.0)) -> "Control":
        """Rest lengths moved along a unit ``direction`` of ``2n`` numbers (``L1_0, L2_0`` of segment 1,
        then of segment 2, ...): ``t`` is the distance in rest-length space. ``tip="free"``: under the
        fixed tip ``load``; ``"held"``: the tip held where the start has it (``F`` the holding force)."""
        if tip not in ("free", "held"):
            raise InvalidParameterError(f"tip must be 'free' or 'held', got {tip!r}", field="tip")
        return cls("preload", _unit(direction, "direction"), _vec2(load, "load"), None, tip)

    @classmethod
    def move(cls, n: int, *, preload=None, load=None, displacement=None, tip: str = "free",
             base=(0.0, 0.0)) -> "Control":
        """Every input moved at once along a straight segment, ``t`` the fraction of the move (0 at the
        start, 1 at its end; not normalised, unlike the other controls).

        ``preload`` (``(n, 2)`` or ``2n`` numbers, default none): the change of the rest lengths
        ``(L1_0, L2_0)`` of each segment over the whole move. ``tip="free"``: the dead tip load is
        ``F = base + t load`` (``load`` its change, default none). ``tip="held"``: the tip deflection
        ``(dx, dy)`` is the start's plus ``t displacement`` (``dx > 0`` shortens), ``F`` the holding force.
        A combined preload and load (or tip) move in one parameter, as the quasi-static simulation
        (:func:`~tensegrity_opt.analyses.paths.simulation.simulate`) needs between two samples of its inputs.
        """
        if tip not in ("free", "held"):
            raise InvalidParameterError(f"tip must be 'free' or 'held', got {tip!r}", field="tip")
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 1:
            raise InvalidParameterError(f"n must be an integer >= 1, got {n!r}", field="n")
        dl = np.zeros(2 * int(n)) if preload is None else _finite(preload, "preload", 2 * int(n))
        if tip == "free":
            if displacement is not None:
                raise InvalidParameterError("a free tip takes a load change, not a displacement",
                                            field="displacement")
            last = np.zeros(2) if load is None else _vec2(load, "load")
        else:
            if load is not None:
                raise InvalidParameterError("a held tip takes a displacement, not a load change", field="load")
            last = np.zeros(2) if displacement is None else _vec2(displacement, "displacement")
        d = np.concatenate([dl, last])
        if not np.any(d != 0.0):
            raise InvalidParameterError("the move must change at least one input", field="preload")
        return cls("move", d, _vec2(base, "base") if tip == "free" else np.zeros(2), None, tip)

    @classmethod
    def spring(cls, n: int, segment: int, spring: int = 1, *, tip: str = "free", load=(0.0, 0.0)) -> "Control":
        """One spring's rest length (``segment`` 0-based, ``spring`` 1 or 2) as the parameter."""
        if not (0 <= int(segment) < n):
            raise InvalidParameterError(f"segment must be in 0..{n - 1}, got {segment!r}", field="segment")
        if spring not in (1, 2):
            raise InvalidParameterError(f"spring must be 1 or 2, got {spring!r}", field="spring")
        d = np.zeros(2 * n)
        d[2 * int(segment) + spring - 1] = 1.0
        return cls.preload(d, tip=tip, load=load)

    def to_dict(self) -> dict[str, Any]:
        if self.kind == "move":
            n = (self.direction.size - 2) // 2
            d = {"kind": "move", "tip": self.tip,
                 "preload": [numbers(r) for r in self.direction[:2 * n].reshape(n, 2)]}
            if self.tip == "free":
                d["load"], d["base"] = numbers(self.direction[2 * n:]), numbers(self.base)
            else:
                d["displacement"] = numbers(self.direction[2 * n:])
            return d
        d = {"kind": self.kind, "direction": numbers(self.direction)}
        if self.kind != "displacement":
            d["load" if self.kind == "preload" else "base"] = numbers(self.base)
        if self.normal is not None and self.kind == "wall":
            d["normal"] = numbers(self.normal)
        if self.kind == "preload":
            d["tip"] = self.tip
        return d

    @property
    def held(self) -> tuple[bool, bool]:
        """Which of the two control rows hold the tip (the rest prescribe a force)."""
        if self.kind == "displacement" or (self.kind in ("preload", "move") and self.tip == "held"):
            return (True, True)
        if self.kind in ("guided", "wall"):
            return (True, False)
        return (False, False)


def as_control(m: Manipulator, control, kw: dict) -> Control:
    """A :class:`Control` from itself or a kind name with the constructor's keywords."""
    if isinstance(control, Control):
        if kw:
            raise InvalidParameterError(f"unexpected keyword(s) {sorted(kw)} with a Control object",
                                        field=sorted(kw)[0])
        if control.kind == "preload" and control.direction.size != 2 * m.n:
            raise InvalidParameterError(f"a preload direction has 2n = {2 * m.n} components, got "
                                        f"{control.direction.size}", field="direction")
        if control.kind == "move" and control.direction.size != 2 * m.n + 2:
            raise InvalidParameterError(f"a move has 2n + 2 = {2 * m.n + 2} components, got "
                                        f"{control.direction.size}", field="preload")
        return control
    if control not in KINDS:
        raise InvalidParameterError(f"control must be a Control or one of {KINDS}, got {control!r}", field="control")
    if control == "move":
        kw = {"n": m.n, **kw}
    try:
        c = getattr(Control, control)(**kw)
    except TypeError as e:
        raise InvalidParameterError(f"bad arguments for the {control} control: {e}", field="control") from None
    return as_control(m, c, {})


@dataclass(frozen=True)
class BranchEvent:
    """A special point of a branch, located between points ``index`` and ``index + 1``.

    Attributes
    ----------
    kind : str
        ``"fold"`` (a limit point: ``t`` turns back; snap-through under this control),
        ``"branch_point"`` (a simple bifurcation: another branch crosses; :func:`switch_branch`),
        ``"joint_limit"`` (a joint reaches its range bound, ``|q_i| = (1 - LIMIT_MARGIN)(pi - 2 beta_i)``:
        the branch ends).
    index : int
    t, q, force, tip, energy
        The point itself (inside the open range).
    null_vector : ndarray (n,) or None
        The joint-angle part of the right null vector of ``R_z`` (largest entry +1), the buckling or
        snapping mode; None for a joint limit.
    morse_before, morse_after : int
        Morse index at points ``index`` and ``index + 1``.
    stability : str
        ``"lost"`` (stable before, not after), ``"gained"`` or ``"unchanged"``.
    method : str
        How it was located: ``"moore_spence"`` (the fold's extended system), ``"test_function"`` (the
        root of the eigenvalue along the branch), ``"limit"``.
    residual : float
        Scaled residual of the equilibrium equations at the point.
    joint : int or None
        The joint at its limit (0-based), for ``"joint_limit"``.
    """

    kind: str
    index: int
    t: float
    q: np.ndarray
    force: np.ndarray
    tip: np.ndarray
    energy: float
    null_vector: np.ndarray | None
    morse_before: int
    morse_after: int
    stability: str
    method: str
    residual: float
    joint: int | None = None
    x: np.ndarray | None = field(default=None, repr=False)
    null_x: np.ndarray | None = field(default=None, repr=False)

    def to_dict(self) -> dict[str, Any]:
        return {"kind": self.kind, "index": int(self.index), "t": number(self.t), "q": numbers(self.q),
                "force": {"fx": number(self.force[0]), "fy": number(self.force[1])}, "tip": numbers(self.tip),
                "energy": number(self.energy),
                "null_vector": None if self.null_vector is None else numbers(self.null_vector),
                "morse_before": int(self.morse_before), "morse_after": int(self.morse_after),
                "stability": self.stability, "method": self.method, "residual": nullable(self.residual),
                "joint": self.joint}


@dataclass
class Branch:
    """An equilibrium branch: ``P`` points along the arclength with their stability and events.

    Attributes
    ----------
    control : Control
    t : ndarray (P,)
        The control parameter (0 at the start).
    q : ndarray (P, n)
        Joint angles (rad), each inside the physical range.
    force : ndarray (P, 2)
        Tip force ``[Fx, Fy]`` (``grad E = J^T F``; a reaction where the tip is held).
    tip : ndarray (P, 2)
    energy : ndarray (P,)
        Elastic energy.
    morse_index : ndarray (P,) of int
        Negative eigenvalues of the reduced Hessian (0: stable).
    stable : ndarray (P,) of bool
    s : ndarray (P,)
        Arclength in the scaled units (angles, forces / (k c^2 / 2b), lengths / 2b).
    events : list of BranchEvent
    status : str
        How it ended (:data:`STATUSES`).
    rest_lengths : ndarray (P, n, 2) or None
        The rest lengths at each point, for a preload or move control.
    """

    control: Control
    t: np.ndarray
    q: np.ndarray
    force: np.ndarray
    tip: np.ndarray
    energy: np.ndarray
    morse_index: np.ndarray
    stable: np.ndarray
    s: np.ndarray
    events: list
    status: str
    straight_length: float
    rest_lengths: np.ndarray | None = None
    message: str = ""
    _problem: Any = field(default=None, repr=False)

    @property
    def success(self) -> bool:
        """Traced to a regular end (not cut by the time limit or a failing corrector)."""
        return self.status in REGULAR_ENDS

    @property
    def deflection(self) -> np.ndarray:
        """``(dx, dy) = (2 sum b - x, y)`` at each point."""
        return np.column_stack([self.straight_length - self.tip[:, 0], self.tip[:, 1]])

    @property
    def displacement(self) -> np.ndarray:
        """The tip's displacement from the start point, ``tip - tip[0]`` (from the rest configuration when the
        branch starts there, the default): the deflection measured from the rest shape, not from straight."""
        return self.tip - self.tip[:1]

    @property
    def folds(self) -> list:
        return [e for e in self.events if e.kind == "fold"]

    @property
    def branch_points(self) -> list:
        return [e for e in self.events if e.kind == "branch_point"]

    @property
    def stability_changes(self) -> list:
        return [e for e in self.events if e.stability != "unchanged"]

    def __len__(self) -> int:
        return int(self.t.size)

    def to_dict(self) -> dict[str, Any]:
        """JSON form: per point ``t, q, force, tip, deflection`` (from straight), ``displacement`` (from the
        start), ``energy, morse_index, stable, s``;
        ``events``; ``status``, ``success``, ``message``, ``control``."""
        d = {"control": self.control.to_dict(), "status": self.status, "success": self.success,
             "message": self.message, "points": int(self.t.size),
             "t": numbers(self.t), "q": [numbers(r) for r in self.q],
             "force": [{"fx": number(f[0]), "fy": number(f[1])} for f in self.force],
             "tip": [numbers(r) for r in self.tip], "deflection": [numbers(r) for r in self.deflection],
             "displacement": [numbers(r) for r in self.displacement],
             "energy": numbers(self.energy), "morse_index": [int(v) for v in self.morse_index],
             "stable": [bool(v) for v in self.stable], "s": numbers(self.s),
             "events": [e.to_dict() for e in self.events]}
        if self.rest_lengths is not None:
            d["rest_lengths"] = [[numbers(r) for r in pt] for pt in self.rest_lengths]
        return d


class _Problem:
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
        self.ps = path_system(n)
        self.p = np.array(m.params, dtype=float)
        self.dp = np.zeros(6 * n)
        self.dp2 = np.zeros(6 * n) if dp2 is None else np.asarray(dp2, float)
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
            dl = control.direction[:2 * n].reshape(n, 2)
            self.dp[4 * n:5 * n] = dl[:, 0]
            self.dp[5 * n:6 * n] = dl[:, 1]
            last = control.direction[2 * n:]
            if control.tip == "held":
                A_tip, A_F, c, F_ref = eye, zero, np.array([-last[0], last[1]]), np.zeros(2)
                size = math.sqrt(float(dl.ravel() @ dl.ravel()) + float(last @ last)) / self.Ls
            else:
                A_tip, A_F, c, F_ref = zero, eye, last, control.base
                size = math.hypot(math.sqrt(float(dl.ravel() @ dl.ravel())) / self.Ls,
                                  math.sqrt(float(last @ last)) / self.Fs)
            t_scale = 1.0 / size                         # the arclength in t: the scaled distance moved
        else:                                            # preload
            dl = control.direction.reshape(n, 2)
            self.dp[4 * n:5 * n] = dl[:, 0]
            self.dp[5 * n:6 * n] = dl[:, 1]
            if control.tip == "held":
                A_tip, A_F, c, F_ref = eye, zero, np.zeros(2), np.zeros(2)
            else:
                A_tip, A_F, c, F_ref = zero, eye, np.zeros(2), control.base
            t_scale = self.Ls
        self.A_tip = A_tip
        self.held_rows = A_tip[[i for i in range(2) if np.any(A_tip[i] != 0.0)]]
        self.ctl = control_vector(A_tip, A_F, c, tip0, F_ref)
        self.w = np.concatenate([np.ones(n), np.full(2, 1.0 / self.Fs), [1.0 / t_scale]])
        rows = [1.0 / (self.Ls if np.any(A_tip[i] != 0.0) else self.Fs) for i in range(2)]
        self.rs = np.concatenate([np.full(n, 1.0 / m.torque_scale), rows])
        self.limits = m.joint_limits
        if start_F is None:
            start_F = m.force_from_torques(start_q) if k in ("displacement",) or control.held[0] else F_ref
        self.x0_guess = np.concatenate([start_q, start_F, [0.0]])
        self._last = None
        # the held rows scaled to torque units: the bordered Hessian's entries are then of one size
        self.kkt_scale = m.torque_scale / self.Ls

    # -------------------------------------------------------------- evaluation
    def _full(self, x: np.ndarray, s: float = 0.0) -> np.ndarray:
        return np.concatenate([x, [s]])

    def eval_all(self, x: np.ndarray, s: float = 0.0):
        """``(R, R_x, H, J, E, tip)`` at ``x`` (the last evaluation is kept: the corrector's final check
        serves the tangent and the classification of the same point)."""
        c = self._last
        if c is not None and s == 0.0 and np.array_equal(c[0], x):
            return c[1]
        out = self.ps.evaluate(self._full(x, s), self.p, self.dp, self.dp2, self.ctl)
        if s == 0.0:
            self._last = (x.copy(), out)
        return out

    def eval(self, x: np.ndarray, s: float = 0.0):
        """``(R, R_x)`` with ``R_x`` the ``N x (N + 1)`` Jacobian in ``(z, t)``."""
        out = self.eval_all(x, s)
        return out[0], out[1][:, :self.N + 1]

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
        a = np.zeros(self.N + 1)
        a[-1] = 1.0 / self.w[-1]
        return self.correct(x_guess, a, t)

    def tangent(self, x: np.ndarray, prev: np.ndarray | None, sign: float = 1.0) -> np.ndarray:
        """Unit tangent in scaled coordinates, oriented along ``prev`` (or with ``t`` growing by ``sign``)."""
        _, Rx = self.eval(x)
        A = Rx / self.w
        if prev is not None:
            M = np.vstack([A, prev])
            rhs = np.zeros(self.N + 1)
            rhs[-1] = 1.0
            try:
                v = np.linalg.solve(M, rhs)
                return v / np.linalg.norm(v)
            except np.linalg.LinAlgError:
                pass
        _, _, Vt = np.linalg.svd(A)
        v = Vt[-1]
        if prev is not None:
            return v if v @ prev >= 0 else -v
        if abs(v[-1]) < 1e-10:
            raise InvalidParameterError("the start is a singular point of the branch (a fold or a branch point): "
                                        "the direction of increasing t is not defined; start nearby",
                                        field="start")
        return v if v[-1] * sign > 0 else -v

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

    def limit_ratio(self, x: np.ndarray) -> tuple[float, int]:
        r = np.abs(x[:self.n]) / self.limits
        j = int(np.argmax(r))
        return float(r[j]), j


@dataclass
class _Point:
    x: np.ndarray
    tau: np.ndarray
    w: np.ndarray
    morse: int
    stable: bool
    E: float
    tip: np.ndarray
    J: np.ndarray


def _point(prob: _Problem, x: np.ndarray, tau: np.ndarray) -> _Point:
    w, J, E, tip = prob.reduced(x)
    idx, st = prob.morse(w)
    return _Point(x, tau, w, idx, st, E, tip, J)


def _start_point(m: Manipulator, prob: _Problem, sign: float) -> _Point:
    x, _ = prob.correct_t(prob.x0_guess, 0.0)
    if x is None:
        raise NoEquilibriumError("the start is not an equilibrium under this control at t = 0 and Newton did not "
                                 "reach one from it", status="start_not_converged")
    if prob.limit_ratio(x)[0] >= 1.0 - LIMIT_MARGIN:
        raise InvalidParameterError("the start lies on or outside the physical joint range", field="start")
    tau = prob.tangent(x, None, sign)
    return _point(prob, x, tau)


def _on_step(prob: _Problem, a: _Point, b: _Point, sigma: float, h: float) -> np.ndarray | None:
    """The branch point at scaled arclength ``sigma`` beyond ``a`` (secant-guided)."""
    guess = a.x + (b.x - a.x) * (sigma / h if h > 0 else 0.0)
    y, _ = prob.correct(guess, a.tau, float(a.tau @ (prob.w * a.x)) + sigma)
    return y


def _brent(f, lo: float, hi: float, flo: float, fhi: float) -> float:
    if flo == 0.0:
        return lo
    if fhi == 0.0:
        return hi
    return so.brentq(f, lo, hi, xtol=1e-14 * max(1.0, hi), rtol=4 * np.finfo(float).eps, maxiter=80)


class _Unlocatable(Exception):
    pass


def _locate_eigen(prob: _Problem, a: _Point, b: _Point, h: float, j: int) -> np.ndarray:
    """The point between ``a`` and ``b`` where the ``j``-th smallest reduced eigenvalue vanishes."""
    def g(sig: float) -> float:
        y = a.x if sig == 0.0 else (b.x if sig == h else _on_step(prob, a, b, sig, h))
        if y is None:
            raise _Unlocatable
        w = prob.reduced(y)[0]
        return float(w[j + k]) / prob.m.torque_scale

    k = prob.held_rows.shape[0]
    ga, gb = float(a.w[j + k]) / prob.m.torque_scale, float(b.w[j + k]) / prob.m.torque_scale
    if ga * gb > 0:
        raise _Unlocatable
    sig = _brent(g, 0.0, h, ga, gb)
    y = _on_step(prob, a, b, sig, h) if 0.0 < sig < h else (a.x if sig == 0.0 else b.x)
    if y is None:
        raise _Unlocatable
    return y


def _locate_turn(prob: _Problem, a: _Point, b: _Point, h: float) -> np.ndarray:
    """The point between ``a`` and ``b`` where the tangent's ``t`` component vanishes."""
    def g(sig: float) -> float:
        y = _on_step(prob, a, b, sig, h) if 0.0 < sig < h else (a.x if sig == 0.0 else b.x)
        if y is None:
            raise _Unlocatable
        return float(prob.tangent(y, a.tau)[-1])

    return _on_step(prob, a, b, _brent(g, 0.0, h, float(a.tau[-1]), float(b.tau[-1])), h) \
        if a.tau[-1] * b.tau[-1] < 0 else b.x


def _null(prob: _Problem, x: np.ndarray):
    """Right and left null vectors of ``R_z`` (smallest singular pair) and ``R_t``, at ``x``."""
    _, Rx = prob.eval(x)
    Rz = Rx[:, :prob.N]
    U, S, Vt = np.linalg.svd(Rz)
    return Vt[-1], U[:, -1], Rx[:, -1], S


def moore_spence(prob: _Problem, x: np.ndarray, phi: np.ndarray, *, s: float = 0.0, iters: int = 20):
    """Newton on the fold system ``R(z, t) = 0, R_z phi = 0, l . phi = 1`` (``l`` the start's ``phi``).

    Returns ``(x, phi)`` converged, or ``None``. Regular at a quadratic fold (not at a branch point).
    """
    N = prob.N
    ell = phi / float(phi @ phi)
    y = np.concatenate([x, phi / float(ell @ phi)])
    for _ in range(iters):
        xs, ph = y[:N + 1], y[N + 1:]
        R, Rx = prob.eval(xs, s)
        Rzv, dRzv, _ = prob.ps.second(prob._full(xs, s), ph, prob.p, prob.dp, prob.dp2, prob.ctl)
        G = np.concatenate([R, Rzv, [ell @ ph - 1.0]])
        if prob.residual(R) <= NEWTON_TOL and float(np.abs(Rzv * prob.rs).max()) <= 1e-10:
            return xs, ph
        M = np.zeros((2 * N + 1, 2 * N + 1))
        M[:N, :N + 1] = Rx
        M[N:2 * N, :N + 1] = dRzv[:, :N + 1]
        M[N:2 * N, N + 1:] = Rx[:, :N]
        M[2 * N, N + 1:] = ell
        try:
            dy = np.linalg.solve(M, -G)
        except np.linalg.LinAlgError:
            return None
        y = y + dy
        if not np.all(np.isfinite(y)):
            return None
    return None


def _make_event(prob: _Problem, kind: str, index: int, x: np.ndarray, a: _Point, b: _Point, method: str,
                null: np.ndarray | None, joint: int | None = None, null_x: np.ndarray | None = None) -> BranchEvent:
    R, _ = prob.eval(x)
    _, _, E, tip = prob.reduced(x)
    nv = None
    if null is not None:
        nq = null[:prob.n]
        big = int(np.argmax(np.abs(nq)))
        nv = nq / nq[big] if nq[big] != 0.0 else nq.copy()
    stab = ("lost" if a.stable and not b.stable else "gained" if b.stable and not a.stable else "unchanged")
    return BranchEvent(kind, index, float(x[-1]), x[:prob.n].copy(), x[prob.n:prob.n + 2].copy(), tip.copy(),
                       float(E), nv, a.morse, b.morse, stab, method, prob.residual(R), joint, x.copy(),
                       None if null_x is None else null_x.copy())


def _singular_events(prob: _Problem, index: int, a: _Point, b: _Point, h: float) -> list[BranchEvent]:
    """Folds and branch points between two accepted points (located; see the module docstring)."""
    out = []
    turned = a.tau[-1] * b.tau[-1] < 0
    lo, hi = sorted((a.morse, b.morse))
    crossings = list(range(lo, hi))
    if not crossings and turned:
        crossings = [None]
    for j in crossings:
        try:
            x = _locate_eigen(prob, a, b, h, j) if j is not None else _locate_turn(prob, a, b, h)
        except (_Unlocatable, ValueError, RuntimeError):
            x = None
        if x is None:
            continue
        phi, u, Rt, _ = _null(prob, x)
        ratio = abs(float(u @ Rt)) / max(float(np.linalg.norm(Rt)), 1e-300)
        kind = "fold" if (turned and ratio > BP_TOL) or (not turned and ratio > 1e-3) else "branch_point"
        method = "test_function"
        if kind == "fold":
            ms = moore_spence(prob, x, phi)
            if ms is not None and np.abs((ms[0] - x) * prob.w).max() < 1e-4:
                x, phi = ms
                method = "moore_spence"
        out.append(_make_event(prob, kind, index, x, a, b, method, phi, null_x=phi))
    return out


def _branch_from(prob: _Problem, pts: list[_Point], s: list[float], events: list, status: str,
                 message: str) -> Branch:
    m = prob.m
    X = np.array([p.x for p in pts])
    n = prob.n
    rest = None
    if prob.control.kind in ("preload", "move"):
        base = np.column_stack([m.L1_0, m.L2_0])
        dl = prob.control.direction[:2 * n].reshape(n, 2)
        rest = base[None, :, :] + X[:, -1][:, None, None] * dl[None, :, :]
    return Branch(control=prob.control, t=X[:, -1].copy(), q=X[:, :n].copy(), force=X[:, n:n + 2].copy(),
                  tip=np.array([p.tip for p in pts]), energy=np.array([p.E for p in pts]),
                  morse_index=np.array([p.morse for p in pts], dtype=int),
                  stable=np.array([p.stable for p in pts], dtype=bool), s=np.array(s), events=events,
                  status=status, straight_length=m.straight_length, rest_lengths=rest, message=message,
                  _problem=prob)


def _start_of(m: Manipulator, start, control: Control):
    if start is None:
        from ..equilibria.rest import rest_configuration

        eq = rest_configuration(m)
        return eq.q.copy(), None
    if isinstance(start, Equilibrium):
        F = start.force.copy() if control.kind == "displacement" or any(control.held) else None
        return start.q.copy(), F
    q = check_q0(m, start)
    if q is None:
        raise InvalidParameterError("start must be an Equilibrium or n joint angles", field="start")
    return q, None


def trace_branch(m: Manipulator, start=None, control: Control | str = "load", *, t_max: float | None = None,
                 t_min: float | None = None, max_points: int = 1000, step: float = 0.02, max_step: float = 0.1,
                 min_step: float = 1e-7, stop_at: str | None = None, orientation: int = 1,
                 timeout: float | None = None, **control_kw) -> Branch:
    """Follow the equilibrium branch through ``start`` by pseudo-arclength continuation in ``t``.

    Parameters
    ----------
    m : Manipulator
        Up to ``numerics.DENSE_MAX`` segments.
    start : Equilibrium, array_like (n,) or None
        The start (``t = 0``), corrected by Newton onto the branch; None: the least-energy rest
        configuration (:func:`~tensegrity_opt.analyses.equilibria.rest.rest_configuration`; only meaningful for
        controls whose ``t = 0`` is the unloaded chain). For a displacement control the tip's start is
        the start's tip; a guide or wall passes through it.
    control : Control or str
        A :class:`Control`, or its kind (``"displacement"``, ``"load"``, ``"guided"``, ``"wall"``,
        ``"preload"``, ``"move"``) with the constructor's keywords in ``control_kw``.
    t_max, t_min : float, optional
        Stop where ``t`` reaches these (the end point is solved at exactly that ``t``).
    max_points : int
        At most this many points (start included).
    step, max_step, min_step : float
        Initial, largest and smallest arclength steps (scaled units, see :class:`Branch`).
    stop_at : {None, "stability_loss", "event"}
        Stop after the first event where stability is lost, or after any event.
    orientation : {1, -1}
        Leave the start with ``t`` increasing (1) or decreasing (-1).
    timeout : float, optional
        Seconds; on expiry the points so far are returned with ``status="time_limit"``.

    Returns
    -------
    Branch
        Never a point outside the physical range: the branch ends at a joint limit (an event).
        ``status`` says how it ended; ``success`` is False when the corrector failed or time ran out
        (the points computed are kept).

    Raises
    ------
    InvalidParameterError
        (``ValueError``) for a malformed control or start, or ``n > DENSE_MAX``.
    NoEquilibriumError
        (``RuntimeError``) when Newton cannot put the start on the branch.
    """
    if timeout is not None:
        with time_limit(timeout):
            return trace_branch(m, start, control, t_max=t_max, t_min=t_min, max_points=max_points, step=step,
                                max_step=max_step, min_step=min_step, stop_at=stop_at, orientation=orientation,
                                **control_kw)
    ctl = as_control(m, control, control_kw)
    if stop_at not in (None, "stability_loss", "event"):
        raise InvalidParameterError(f"stop_at must be None, 'stability_loss' or 'event', got {stop_at!r}",
                                    field="stop_at")
    if orientation not in (1, -1):
        raise InvalidParameterError(f"orientation must be 1 or -1, got {orientation!r}", field="orientation")
    if isinstance(max_points, bool) or not isinstance(max_points, (int, np.integer)) or max_points < 2:
        raise InvalidParameterError(f"max_points must be an integer >= 2, got {max_points!r}", field="max_points")
    for name, v in (("step", step), ("max_step", max_step), ("min_step", min_step)):
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise InvalidParameterError(f"{name} must be finite and > 0, got {v!r}", field=name)
    for name, v in (("t_max", t_max), ("t_min", t_min)):
        if v is not None and not math.isfinite(float(v)):
            raise InvalidParameterError(f"{name} must be finite, got {v!r}", field=name)
    q0, F0 = _start_of(m, start, ctl)
    prob = _Problem(m, ctl, q0, F0)
    first = _start_point(m, prob, float(orientation))
    return _continue(prob, first, t_max=t_max, t_min=t_min, max_points=int(max_points), step=step,
                     max_step=max_step, min_step=min_step, stop_at=stop_at)


def _compiled_step(prob: _Problem, a: _Point, h: float, Xa: np.ndarray):
    """The compiled predictor-corrector step (:mod:`tensegrity_opt.numerics.path_system`): ``(y, tau, iters)``
    when it converged (its evaluation at ``y`` kept for the classification), else ``(None, None, 0)``."""
    y, res, iters, tau, out = prob.ps.step(a.x, a.tau, h, prob.w, prob.rs, NEWTON_TOL, prob.p, prob.dp, prob.dp2,
                                           prob.ctl)
    b = float(a.tau @ Xa) + h
    if not (res <= NEWTON_TOL and abs(float(a.tau @ (prob.w * y)) - b) <= 1e-10 * max(1.0, abs(b))
            and np.all(np.isfinite(tau))):
        return None, None, 0
    prob._last = (y.copy(), out)
    return y, tau, max(iters, 1)


def _bound_before_limit(prob: _Problem, a: _Point, y: np.ndarray, t_max, t_min) -> bool:
    """Whether the step ``a -> y`` that crosses a joint limit crosses t_max / t_min first: the point solved at
    that bound is inside the range."""
    for bound in (t_max, t_min):
        if bound is None:
            continue
        if (y[-1] - bound) * (a.x[-1] - bound) < 0.0:
            frac = (bound - a.x[-1]) / (y[-1] - a.x[-1])
            ye, _ = prob.correct_t(a.x + frac * (y - a.x), float(bound))
            if ye is not None and prob.limit_ratio(ye)[0] < 1.0 - LIMIT_MARGIN:
                return True
    return False


def _tip_rank(p: _Point) -> float:
    """Smallest over largest singular value of the tip Jacobian at ``p``."""
    sv = np.linalg.svd(p.J, compute_uv=False)
    return float(sv[-1] / sv[0]) if sv[0] > 0 else 0.0


def _continue(prob: _Problem, first: _Point, *, t_max, t_min, max_points, step, max_step, min_step, stop_at,
              prefix: list[_Point] | None = None) -> Branch:
    pts = [first] if prefix is None else list(prefix)
    s = [0.0] * len(pts) if prefix is None else [0.0] + [float(np.linalg.norm((pts[i + 1].x - pts[i].x) * prob.w))
                                                          for i in range(len(pts) - 1)]
    s = list(np.cumsum(s))
    events: list[BranchEvent] = []
    h = float(step)
    status, message = "max_points", ""
    X0 = pts[0].x * prob.w
    while len(pts) < max_points:
        if expired():
            status, message = "time_limit", "the time limit ran out: the points computed so far"
            break
        a = pts[-1]
        Xa = prob.w * a.x
        pred = a.x + h * a.tau / prob.w
        y, tau, iters = _compiled_step(prob, a, h, Xa)
        if y is None:
            y, iters = prob.correct(pred, a.tau, float(a.tau @ Xa) + h)
            tau = None
        ok = y is not None
        if ok:
            tau = prob.tangent(y, a.tau) if tau is None else tau
            turn = math.acos(max(-1.0, min(1.0, float(tau @ a.tau))))
            moved = float(np.linalg.norm(prob.w * y - (Xa + h * a.tau)))
            ok = turn <= MAX_TURN and moved <= max(0.5 * h, 1e-9)
        if not ok:
            h *= 0.5
            if h < min_step:
                status = "step_too_small" if y is not None else "corrector_failed"
                message = (f"the step fell below min_step = {min_step:g} at t = {a.x[-1]:.6g}: the branch could not "
                           "be continued (a singular point the corrector cannot pass, or a cusp)")
                break
            continue
        b = _point(prob, y, tau)
        lim, joint = prob.limit_ratio(y)
        # joint limit: the point where the largest |q_i| / limit reaches 1 - LIMIT_MARGIN ends the branch, unless
        # t_max / t_min comes first on this step (the end point there is inside the range: the t bounds below)
        bound_first = lim >= 1.0 - LIMIT_MARGIN and _bound_before_limit(prob, a, y, t_max, t_min)
        if lim >= 1.0 - LIMIT_MARGIN and not bound_first:
            target = 1.0 - LIMIT_MARGIN

            def g(sig, a=a, b=b, h=h):
                yy = _on_step(prob, a, b, sig, h)
                if yy is None:
                    raise _Unlocatable
                return prob.limit_ratio(yy)[0] - target
            try:
                sig = _brent(g, 0.0, h, prob.limit_ratio(a.x)[0] - target, lim - target)
                yl = _on_step(prob, a, b, sig, h)
            except (_Unlocatable, ValueError, RuntimeError):
                yl = None
            if yl is None:
                status, message = "joint_limit", "a joint reached its range bound (the last point inside is kept)"
                break
            bl = _point(prob, yl, prob.tangent(yl, a.tau))
            events.extend(_singular_events(prob, len(pts) - 1, a, bl, sig) if bl.morse != a.morse
                          or a.tau[-1] * bl.tau[-1] < 0 else [])
            events.append(_make_event(prob, "joint_limit", len(pts) - 1, yl, a, bl, "limit", None,
                                      joint=prob.limit_ratio(yl)[1]))
            pts.append(bl)
            s.append(s[-1] + sig)
            status = "joint_limit"
            message = f"joint {prob.limit_ratio(yl)[1] + 1} reached its range bound at t = {yl[-1]:.6g}"
            break
        # t bounds: the end point at exactly t_max / t_min
        for bound, name, crossed in ((t_max, "t_max", lambda v, bd: v > bd), (t_min, "t_min", lambda v, bd: v < bd)):
            if bound is not None and crossed(y[-1], bound) and not crossed(a.x[-1], bound):
                frac = (bound - a.x[-1]) / (y[-1] - a.x[-1])
                ye, _ = prob.correct_t(a.x + frac * (y - a.x), float(bound))
                if ye is not None:
                    b = _point(prob, ye, prob.tangent(ye, a.tau))
                    h = float(np.linalg.norm((ye - a.x) * prob.w))
                    status = name
                break
        else:
            name = None
        turned = a.tau[-1] * b.tau[-1] < 0
        new = _singular_events(prob, len(pts) - 1, a, b, h) if (b.morse != a.morse or turned) else []
        if turned and not new and prob.held_rows.shape[0] == 2 and min(_tip_rank(a), _tip_rank(b)) < 0.1:
            # t turned with no fold of the reduced Hessian: the held tip passed the edge of its workspace (J loses
            # rank between the points: the chain straightens) and the branch would come back on the other side
            status = "workspace_boundary"
            message = ("the held tip reached the edge of its workspace at t = {:.6g} (the tip Jacobian loses rank: "
                       "the chain straightens); the branch ends there".format(max(a.x[-1], b.x[-1])
                                                                            if a.tau[-1] > 0 else min(a.x[-1], b.x[-1])))
            break
        events.extend(new)
        pts.append(b)
        s.append(s[-1] + float(np.linalg.norm((b.x - a.x) * prob.w)))
        if status in ("t_max", "t_min") and name is not None:
            message = f"t reached {status} = {b.x[-1]:.6g}"
            break
        if stop_at == "event" and new:
            status, message = "event", f"stopped at the first event ({new[0].kind})"
            break
        if stop_at == "stability_loss" and any(e.stability == "lost" for e in new):
            status, message = "stability_loss", "stopped where the branch first loses stability"
            break
        Xa, Xb = prob.w * a.x, prob.w * b.x
        seg = Xb - Xa
        theta = min(1.0, max(0.0, float((X0 - Xa) @ seg) / max(float(seg @ seg), 1e-300)))
        if len(pts) > 10 and s[-1] > 5 * max_step and float(np.linalg.norm(Xa + theta * seg - X0)) < 0.1 * h:
            status, message = "closed_loop", "the branch closed on its start"
            break
        if float(np.linalg.norm(b.x[prob.n:prob.n + 2])) > FORCE_BOUND * prob.Fs:
            status, message = "force_bound", f"|F| exceeded {FORCE_BOUND:g} force units k c^2/(2b)"
            break
        if prob.held_rows.shape[0] == 2:
            JJ = b.J @ b.J.T                 # singular values of J: the square roots of JJ^T's eigenvalues
            tr, det = float(JJ[0, 0] + JJ[1, 1]), float(JJ[0, 0] * JJ[1, 1] - JJ[0, 1] * JJ[1, 0])
            big = 0.5 * tr + math.sqrt(max(0.25 * tr * tr - det, 0.0))
            if det <= (SINGULAR_TIP ** 2) * big * big:
                status = "workspace_boundary"
                message = ("the held tip reached the edge of its workspace (the chain straightens, the tip Jacobian "
                           "loses rank): the holding force grows without bound")
                break
        h = min(max_step, h * (1.4 if iters <= 3 else 1.0 if iters <= 6 else 0.6))
    else:
        message = f"max_points = {max_points} reached"
    if status == "max_points" and not message:
        message = f"max_points = {max_points} reached"
    return _branch_from(prob, pts, s, events, status, message)


def switch_branch(branch: Branch, event: BranchEvent, side: int = 1, *, step: float = 0.02, **kw) -> Branch:
    """The branch bifurcating at a branch point of ``branch``, left on ``side`` (+1 or -1).

    At a simple branch point the Jacobian ``[R_z, R_t]`` has a 2-dimensional null space: the traced
    branch's tangent and a second direction ``v``; the new branch is the solution of
    ``R = 0, v . (x - x_bp) = side * step`` (then continued like :func:`trace_branch`, same keywords).
    Its ``t`` is the control parameter of ``branch``.
    """
    if not isinstance(event, BranchEvent) or event.kind != "branch_point":
        raise InvalidParameterError("event must be a branch_point of the branch", field="event")
    if side not in (1, -1):
        raise InvalidParameterError(f"side must be 1 or -1, got {side!r}", field="side")
    prob: _Problem = branch._problem
    x = event.x
    _, Rx = prob.eval(x)
    A = Rx / prob.w
    _, _, Vt = np.linalg.svd(A)
    t0 = prob.tangent(x, _tangent_near(branch, event))
    basis = Vt[-2:]
    # the null direction orthogonal to the traced tangent
    c = basis @ t0
    v = basis[0] * c[1] - basis[1] * c[0]
    v = v / np.linalg.norm(v)
    if event.null_x is not None:
        nz = np.concatenate([event.null_x, [0.0]]) * prob.w
        if v @ nz < 0:
            v = -v
    v = side * v
    Xbp = prob.w * x
    y = None
    for hh in (step, step / 4, step / 16):
        y, _ = prob.correct(x + hh * v / prob.w, v, float(v @ Xbp) + hh)
        if y is not None and np.linalg.norm(prob.w * y - Xbp) > 0.5 * hh:
            break
        y = None
    if y is None:
        raise NoEquilibriumError("no bifurcating branch found at this branch point", status="switch_failed")
    tau = prob.tangent(y, v)
    first = _point(prob, x.copy(), v)
    second = _point(prob, y, tau)
    opts = {k: kw.pop(k) for k in ("t_max", "t_min", "max_points", "max_step", "min_step", "stop_at") if k in kw}
    if kw:
        raise InvalidParameterError(f"unexpected keyword(s) {sorted(kw)}", field=sorted(kw)[0])
    opts.setdefault("max_points", 1000)
    timeout = opts.pop("timeout", None)
    with time_limit(timeout):
        return _continue(prob, first, t_max=opts.get("t_max"), t_min=opts.get("t_min"),
                         max_points=opts["max_points"], step=step, max_step=opts.get("max_step", 0.1),
                         min_step=opts.get("min_step", 1e-7), stop_at=opts.get("stop_at"),
                         prefix=[first, second])


def _tangent_near(branch: Branch, event: BranchEvent) -> np.ndarray:
    prob: _Problem = branch._problem
    i = min(event.index, len(branch) - 1)
    x = np.concatenate([branch.q[i], branch.force[i], [branch.t[i]]])
    j = min(i + 1, len(branch) - 1)
    x2 = np.concatenate([branch.q[j], branch.force[j], [branch.t[j]]])
    d = (x2 - x) * prob.w
    nrm = np.linalg.norm(d)
    return d / nrm if nrm > 0 else prob.tangent(x, None)


def bifurcation_diagram(m: Manipulator, start=None, control: Control | str = "load", *, depth: int = 2,
                        max_branches: int = 24, timeout: float | None = None, **kw) -> list[Branch]:
    """Every branch connected to the start through branch points, to ``depth`` switches.

    The start's branch is traced both ways (``t`` increasing, then decreasing); at each branch point
    both sides of the bifurcating branch are traced (:func:`switch_branch`), recursively. A branch
    point met again on a later branch (the same point, within ``1e-6`` scaled) is not switched twice.
    Keywords as :func:`trace_branch` (``t_max``, ``t_min``, ``max_points``, ...; the control's own).

    Returns
    -------
    list of Branch
        The start's two halves first (``t`` up, ``t`` down), then the switched branches breadth-first;
        at most ``max_branches``.
    """
    if isinstance(depth, bool) or not isinstance(depth, (int, np.integer)) or depth < 0:
        raise InvalidParameterError(f"depth must be an integer >= 0, got {depth!r}", field="depth")
    trace_kw = {k: kw.pop(k) for k in ("t_max", "t_min", "max_points", "step", "max_step", "min_step") if k in kw}
    with time_limit(timeout):
        up = trace_branch(m, start, control, orientation=1, **trace_kw, **kw)
        branches = [up]
        try:
            branches.append(trace_branch(m, start, control, orientation=-1, **trace_kw, **kw))
        except TensegrityError:
            pass
        seen: list[np.ndarray] = []
        frontier = [(b, 0) for b in branches]
        while frontier and len(branches) < max_branches:
            br, level = frontier.pop(0)
            if level >= depth:
                continue
            for ev in br.branch_points:
                X = ev.x * br._problem.w
                if any(np.linalg.norm(X - S) < 1e-6 for S in seen):
                    continue
                seen.append(X)
                for side in (1, -1):
                    if len(branches) >= max_branches or expired():
                        break
                    try:
                        nb = switch_branch(br, ev, side, **{k: v for k, v in trace_kw.items() if k != "step"})
                    except TensegrityError:
                        continue
                    # the new branch starts at the branch point: mark it as seen from there too
                    branches.append(nb)
                    frontier.append((nb, level + 1))
    return branches
