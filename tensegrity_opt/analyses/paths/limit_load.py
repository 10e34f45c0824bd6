"""Limit loads: how far a dead tip load can grow before the branch from a rest configuration loses stability.

:func:`limit_load` traces the dead-load path ``F = base + t d`` (``t >= 0``, ``d`` a unit direction; ``base``
a load the start is in equilibrium under, zero by default: the start is then a rest configuration) by
arclength continuation (:func:`~tensegrity_opt.analyses.paths.branches.trace_branch`) and stops
at the first event where stability is lost: a **fold** (the load passes a maximum along the branch: the
arm snaps through) or a **bifurcation** (a branch point: the straight symmetric chain buckles at its
critical load, :func:`~tensegrity_opt.analyses.equilibria.buckling.critical_force`). Where neither happens — a pre-bent
arm under compression bends smoothly ("quasi-buckling") until a joint reaches its range bound, or the
load reaches ``max_load`` — ``kind == "none"`` and ``status`` says why, and :attr:`LimitLoad.quasi_buckling_load` is the
load at which the arm is softest along the load: the interior minimum along the path of the tangent
stiffness ``k(t) = 1 / (d . C(t) d)``, ``C = J H^-1 J^T`` the tip compliance (guided: the compliance in
``x`` with ``y`` held, ``C_xx - C_xy^2 / C_yy``), located as an event of the path: the zero of ``dk/dt``
(exact, from the path's first and second derivatives, :func:`~.events.load_compliance`) by Brent's method
between the path points where it changes sign, each trial point solved on the path at its load
(:func:`~.events.locate_stiffness_minimum`); :attr:`LimitLoad.quasi_buckling_stiffness` is ``k`` there. For an
imperfect (pre-bent) column this tends to the critical load as the imperfection vanishes (Southwell); it is
None where ``k`` only decreases or only grows along the path.

:func:`limit_arms` follows the branches that leave the limit point of a bifurcation (the buckled arms, two mirror
images ``q -> -q`` for a symmetric chain) with the branch switching of :mod:`.diagram`: the shapes the arm buckles
into and whether they carry more load (supercritical) or less (subcritical).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from ...errors import InvalidParameterError, NoEquilibriumError
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...model.springs import SpringFields, Springs
from ...outcome import Outcome
from ...serialize import nullable, number, numbers
from ...timelimit import time_limit
from ..equilibria.equilibrium import Equilibrium, check_q0
from .branches import Branch, trace_branch
from .control import Control
from .diagram import switch_branch
from .events import load_compliance, locate_stiffness_minimum
from .problem import refuse_start_on_stop

__all__ = ["LimitLoad", "limit_load", "limit_arms", "check_max_load", "DEFAULT_MAX_LOAD", "ARMS_REACH"]

#: Without ``max_load`` the path is followed up to this many force units ``k c^2 / (2 b)``.
DEFAULT_MAX_LOAD = 100.0
#: :func:`limit_arms` follows each arm at most up to this many times the limit load.
ARMS_REACH = 5.0


@dataclass(frozen=True)
class LimitLoad(Outcome, SpringFields):
    """The result of :func:`limit_load`.

    Attributes
    ----------
    status : str
        How the path ended (:attr:`STATUSES`): ``"stability_lost"`` at a limit point (``kind`` says which),
        ``"joint_limit"`` or ``"max_load"`` where it stays stable to its end (``kind == "none"``), else how the
        continuation was cut (the branch's status: not a success).
    message : str
        The same in a sentence.
    load : float or None
        The load magnitude ``t >= 0`` where the branch first loses stability (None for ``kind == "none"``).
    force : ndarray (2,) or None
        The tip force there (guided: ``Fy`` the guide's reaction).
    q : ndarray (n,) or None
        The configuration there.
    kind : str
        ``"fold"``, ``"bifurcation"`` or ``"none"``.
    null_vector : ndarray (n,) or None
        The mode of the instability (largest entry +1).
    quasi_buckling_load : float or None
        The load of least tangent stiffness along the load on the stable path (module docstring).
    quasi_buckling_force : ndarray (2,) or None
    end_load : float
        The last load reached on the stable path.
    direction : ndarray (2,)
    boundary : str
    start : Equilibrium
        The configuration the path starts from (a rest configuration when ``base`` is zero).
    branch : Branch
        The traced path (up to the limit).
    base : ndarray (2,)
        The base load: the tip force is ``base + t d`` (guided: ``Fx = base_x + t d_x``).
    quasi_buckling_stiffness : float or None
        The tangent stiffness along the load ``k = 1 / (d . C d)`` at :attr:`quasi_buckling_load` (force per
        length; guided: with ``y`` held), the least on the stable path.
    spring_lengths, spring_stretches, spring_forces, spring_states : ndarray (n, 2)
        The springs at ``q`` (:class:`~tensegrity_opt.model.springs.SpringFields`).
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "stability_lost": "the path loses stability at load: a fold or a bifurcation (kind)",
        "joint_limit": "no limit point: the path stays stable until a joint reaches its range bound",
        "max_load": "no limit point up to max_load",
        "max_points": "no limit point within max_points points of the path",
        "closed_loop": "the path closed on its start without losing stability",
        "force_bound": "the tip force exceeded the continuation's force bound without a limit point",
        "step_too_small": "the path could not be continued (the step fell below its minimum)",
        "corrector_failed": "the path could not be continued (the corrector failed)",
        "time_limit": "the time limit ran out before a limit point was found",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"stability_lost", "joint_limit", "max_load"})

    status: str
    message: str
    load: float | None
    force: np.ndarray | None
    q: np.ndarray | None
    kind: str
    null_vector: np.ndarray | None
    quasi_buckling_load: float | None
    quasi_buckling_force: np.ndarray | None
    end_load: float
    direction: np.ndarray
    boundary: str
    start: Equilibrium
    branch: Branch
    base: np.ndarray = field(default_factory=lambda: np.zeros(2))
    quasi_buckling_stiffness: float | None = None

    def __post_init__(self) -> None:
        for a in (self.force, self.q, self.null_vector, self.quasi_buckling_force, self.direction, self.base):
            if a is not None:
                a.setflags(write=False)             # the builder's own arrays, read-only in place
        if self.status not in self.STATUSES:
            self._check_outcome()

    @property
    def springs(self) -> Springs | None:
        """The chain's springs (the spring state's model, at ``q``)."""
        return self.branch.springs

    def to_dict(self, *, include_branch: bool = False) -> dict[str, Any]:
        """JSON form (the body of ``POST /v1/limit-load``): ``success``, ``status``, ``message``, ``load``,
        ``kind``, ``force``, ``q``, ``null_vector``, ``quasi_buckling_load``, ``quasi_buckling_force``,
        ``quasi_buckling_stiffness``, ``end_load``, ``direction``, ``boundary``, ``base``, ``start``
        (:meth:`Equilibrium.to_dict`), ``branch_status``, ``branch_points``, the spring state at ``q``
        (``spring_lengths``, ``spring_stretches``, ``spring_forces``, ``spring_states``; null without ``q``), and
        with ``include_branch`` the ``branch``."""
        d = {**self.outcome(), **self.spring_dict(),
             "load": None if self.load is None else nullable(self.load), "kind": self.kind,
             "force": None if self.force is None else {"fx": number(self.force[0]), "fy": number(self.force[1])},
             "q": None if self.q is None else numbers(self.q),
             "null_vector": None if self.null_vector is None else numbers(self.null_vector),
             "quasi_buckling_load": None if self.quasi_buckling_load is None else nullable(self.quasi_buckling_load),
             "quasi_buckling_force": None if self.quasi_buckling_force is None else
             {"fx": number(self.quasi_buckling_force[0]), "fy": number(self.quasi_buckling_force[1])},
             "quasi_buckling_stiffness": None if self.quasi_buckling_stiffness is None else
             nullable(self.quasi_buckling_stiffness),
             "end_load": number(self.end_load), "direction": numbers(self.direction), "boundary": self.boundary,
             "base": numbers(self.base), "start": self.start.to_dict(),
             "branch_status": self.branch.status, "branch_points": len(self.branch)}
        if include_branch:
            d["branch"] = self.branch.to_dict()
        return d


def check_max_load(max_load) -> float | None:
    """``max_load`` as a float (None stays None), or :class:`InvalidParameterError` unless finite and > 0."""
    if max_load is None:
        return None
    try:
        max_load = float(max_load)
    except (TypeError, ValueError):
        raise InvalidParameterError(f"max_load must be a number, got {max_load!r}", field="max_load") from None
    if not math.isfinite(max_load) or max_load <= 0:
        raise InvalidParameterError(f"max_load must be finite and > 0, got {max_load!r}", field="max_load")
    return max_load


def _quasi_buckling(br: Branch, d: np.ndarray, upto: int):
    """``(load, force, stiffness)`` of the least tangent stiffness along the load on the stable path up to point
    ``upto`` when it lies inside the path, else ``(None, None, None)`` (module docstring)."""
    prob = br.problem
    P = min(upto + 1, len(br))
    if P < 3:
        return None, None, None
    X = prob.point.stack(P, q=br.q[:P], F=br.force[:P], t=br.t[:P])
    c, rate = np.array([load_compliance(prob, X[i], d) for i in range(P)]).T
    # c = 0: no compliance along the load (the straight chain, guided); t must grow (no fold on a stable path)
    ok = np.isfinite(c) & (c > 0.0) & np.isfinite(rate) & br.stable[:P]
    ok[1:] &= np.diff(br.t[:P]) > 0.0
    inside = np.flatnonzero(ok)
    if inside.size < 3:
        return None, None, None
    best = None
    for i in inside[:-1]:
        if ok[i + 1] and rate[i] > 0.0 > rate[i + 1]:
            found = locate_stiffness_minimum(prob, X[i], X[i + 1], d, float(rate[i]), float(rate[i + 1]))
            if found is not None and (best is None or found[1] > best[1]):
                best = found
    # the softest point of the path: inside it (else k only decreases or only grows)
    if best is None or best[1] <= max(c[inside[0]], c[inside[-1]]):
        return None, None, None
    y, cy = best
    return float(y[prob.point["t"]]), y[prob.point["F"]].copy(), 1.0 / cy


def limit_load(m: Manipulator, direction=(-1.0, 0.0), boundary: str = "free", max_load: float | None = None,
               start=None, *, base=(0.0, 0.0), max_points: int = 4000, timeout: float | None = None) -> LimitLoad:
    """The dead tip load ``base + t d`` at which the branch from a start (a rest configuration by default)
    first loses stability; ``t`` is the load added to ``base``.

    Parameters
    ----------
    m : Manipulator
    direction : (float, float)
        The load's direction (normalised); ``(-1, 0)`` compresses the straight chain.
    boundary : {"free", "guided"}
        ``"free"``: the tip free, ``F = t d`` prescribed, stability from the full Hessian of
        ``E - F . tip``. ``"guided"``: the tip's ``y`` held at its rest value, ``Fx = t d_x``, ``Fy`` the
        guide's reaction, stability reduced to ``dy/dq . v = 0`` (the paper's case).
    max_load : float, optional
        Stop there (``status="max_load"``). Default ``DEFAULT_MAX_LOAD`` force units ``k c^2 / (2 b)``.
    start : Equilibrium or array_like (n,), optional
        A configuration at the base load (with ``base`` zero a rest configuration; Newton under ``base``
        puts it on the equilibrium set). Default the least-energy stable rest configuration
        (:func:`~tensegrity_opt.analyses.equilibria.rest.rest_configuration`: equal-energy wells are separated by
        its documented rule — the one closest to straight, then the largest ``q_1``, ...); with a non-zero
        ``base`` the equilibrium under it from the default start of
        :func:`~tensegrity_opt.analyses.equilibria.equilibrium.solve_equilibrium_under_force`.
    base : (float, float)
        A dead tip load already applied at the start (default none): the path is ``F = base + t d``,
        ``t >= 0`` the load added (guided: ``Fx = base_x + t d_x``, the guide's reaction at the start is
        the start's ``Fy``).
    max_points, timeout
        As :func:`~tensegrity_opt.analyses.paths.branches.trace_branch`.

    Returns
    -------
    LimitLoad
        For a straight symmetric chain under ``(-1, 0)``: ``kind="bifurcation"``, ``load`` equal to
        ``-critical_force(m, boundary).force``; a bistable segment snaps at a fold; a pre-bent chain under
        free compression is typically smooth (``kind="none"``, ``quasi_buckling_load`` near the straight
        chain's critical load).

    Raises
    ------
    InvalidParameterError
        (``ValueError``) for a bad direction, boundary, ``base``, ``max_load``, or a start that is not a
        stable equilibrium under ``base`` (a rest configuration when it is zero).
    """
    unloaded_only(m, "limit_load")
    if boundary not in ("free", "guided"):
        raise InvalidParameterError(f"boundary must be 'free' or 'guided', got {boundary!r}", field="boundary")
    control = Control.load(direction, base) if boundary == "free" else Control.guided(direction, base)
    F0 = control.base
    loaded = bool(np.any(F0 != 0.0))
    d = control.direction
    max_load = check_max_load(max_load)
    from ..equilibria.equilibrium import solve_equilibrium_under_force

    if start is None and not loaded:
        from ..equilibria.rest import rest_configuration

        eq0 = rest_configuration(m)
    elif start is None:
        eq0 = solve_equilibrium_under_force(m, F0[0], F0[1])
    else:
        q0 = start.q if isinstance(start, Equilibrium) else check_q0(m, start)
        if q0 is None:
            raise InvalidParameterError("start must be an Equilibrium or n joint angles", field="start")
        eq0 = solve_equilibrium_under_force(m, F0[0], F0[1], q0=q0)
        if np.abs(eq0.q - q0).max() > 1e-3:
            what = "an equilibrium under the base load" if loaded else "a rest configuration"
            raise InvalidParameterError(f"start is not (near) {what}: Newton under that load moved it "
                                        f"by {np.abs(eq0.q - q0).max():.3g} rad", field="start")
    refuse_start_on_stop(eq0.at_stop, "start", "the loading path is followed by arclength continuation")
    bound = max_load
    br0 = trace_branch(m, eq0.q, control, t_max=1.0, max_points=3)        # its problem gives the force scale
    if bound is None:
        bound = DEFAULT_MAX_LOAD * br0.problem.Fs
    br = trace_branch(m, eq0.q, control, t_max=bound, max_points=max_points, stop_at="stability_loss",
                      timeout=timeout)
    if not br.stable[0]:
        raise InvalidParameterError("the start is not a stable equilibrium under this boundary condition "
                                    f"(Morse index {int(br.morse_index[0])} at the base load)", field="start")
    lost = [e for e in br.events if e.stability == "lost"]
    qb_upto = len(br) - 1
    if lost:
        e = lost[0]
        qb_upto = e.index
        # a spring going slack (or taut) where stability is lost: the load turns back at the kink (a fold of a
        # tension-only chain's path, whose tangent jumps there)
        kind = "fold" if e.kind in ("fold", "spring_slack", "spring_taut") else "bifurcation"
        where = (f" where spring {e.joint + 1}.{e.spring} goes {'slack' if e.kind == 'spring_slack' else 'taut'}"
                 if e.kind in ("spring_slack", "spring_taut") else "")
        qb, qbf, qbk = _quasi_buckling(br, d, qb_upto)
        return LimitLoad("stability_lost", f"stability is lost at a {kind}{where} at load {e.t:.7g}", e.t,
                         e.force.copy(),
                         e.q.copy(), kind, e.null_vector, qb, qbf, e.t, d, boundary, eq0, br, F0.copy(), qbk)
    status = {"t_max": "max_load"}.get(br.status, br.status)
    stable_end = int(np.flatnonzero(br.stable)[-1]) if br.stable.any() else 0
    qb, qbf, qbk = _quasi_buckling(br, d, min(qb_upto, stable_end))
    end_load = float(br.t[stable_end])
    if status in LimitLoad.SUCCESS:
        message = f"no limit point: the path stays stable to its end ({status}) at load {end_load:.7g}"
    else:
        message = f"no limit point found before the path was cut: {br.message}"
    return LimitLoad(status, message, None, None, None, "none", None, qb, qbf, end_load, d, boundary, eq0, br,
                     F0.copy(), qbk)


def limit_arms(result: LimitLoad, *, reach: float = ARMS_REACH, max_points: int = 400,
               timeout: float | None = None) -> list[Branch]:
    """The branches leaving the limit point of a bifurcation (:func:`limit_load` with ``kind="bifurcation"``):
    the buckled arms, both sides of the branch point (:func:`~tensegrity_opt.analyses.paths.diagram.switch_branch`).

    Each arm starts at the branch point and is followed to its first event (a fold: it snaps; a joint limit; a
    further branch point), with the load ``t`` kept within ``[0, reach * load]``. For a symmetric chain the two
    arms are mirror images (``q -> -q``); on a supercritical arm ``t`` grows past the limit load, on a
    subcritical one it falls.

    Parameters
    ----------
    result : LimitLoad
    reach : float
        The largest load followed, in multiples of the limit load (default :data:`ARMS_REACH`).
    max_points : int
        At most this many points per arm.
    timeout : float, optional
        Seconds for both arms; an arm cut by it keeps its points (``status="time_limit"``).

    Returns
    -------
    list of Branch
        The arms, the one leaving along the mode :attr:`LimitLoad.null_vector` first; empty unless the limit is a
        bifurcation (and without an arm the switch could not leave the branch point on).
    """
    if not isinstance(result, LimitLoad):
        raise InvalidParameterError(f"limit_arms needs a LimitLoad, got {type(result).__name__}", field="result")
    if not (isinstance(reach, (int, float)) and math.isfinite(reach) and reach > 1.0):
        raise InvalidParameterError(f"reach must be a number > 1, got {reach!r}", field="reach")
    if result.kind != "bifurcation" or result.load is None:
        return []
    ev = next(e for e in result.branch.events if e.stability == "lost" and e.kind == "branch_point")
    arms = []
    with time_limit(timeout):
        for side in (1, -1):
            try:
                arms.append(switch_branch(result.branch, ev, side, t_min=0.0, t_max=float(reach) * result.load,
                                          max_points=max_points, stop_at="event"))
            except NoEquilibriumError:
                continue
    if result.null_vector is not None:           # the arm along the mode first
        arms.sort(key=lambda b: -float((b.q[min(1, len(b) - 1)] - b.q[0]) @ result.null_vector))
    return arms
