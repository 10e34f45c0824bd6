"""Preloads: the springs' rest lengths for a pose, or for a required critical load.

Every preload problem of the package (this module's two, :func:`~.stiffness_shaping.preloads_for_stiffness` and
:func:`~.preload_control.plan_preloads`) is a function ``preloads_for_<requirement>(m, <requirement>,
*, ...)`` with the same keywords for the same things: ``load`` (the dead tip load ``(fx, fy)``; ``loads`` per
step of a trajectory), ``bounds`` (the actuator bounds on the rest lengths, :func:`rest_length_bounds`),
``margin`` (the required stability margin), ``end_angle`` (the last link's absolute angle; ``end_angles`` per
step), ``start`` (the configuration to start from), ``objective`` (:data:`OBJECTIVES`) and ``timeout`` (seconds).

* :func:`preloads_for_pose` - rest lengths ``(L1_0, L2_0)`` per segment putting the tip at a target, stably,
  under a dead tip load (:func:`tensegrity_opt.numerics.preload_nlp`); the result, :class:`PreloadDesign`, is
  verified by the forward equilibrium with those rest lengths (:func:`forward_check`);
* :func:`preloads_for_critical_force` - the least change of the (symmetric) rest lengths giving the straight
  chain a required critical load (the buckling design problem of
  :func:`~tensegrity_opt.analyses.design.strongest.buckling_design`, returning its :class:`Design`).

Formulations and worked examples: ``docs/design.md``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any, ClassVar

import numpy as np

from ...bounds import bound_pair
from ...errors import (
    InfeasibleDesignError,
    InvalidParameterError,
    TensegrityError,
    TimeLimitError,
    UnreachableTargetError,
    UnsupportedError,
)
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...model.springs import SpringFields, Springs
from ...numerics import RANGE_SHRINK, chain_solver
from ...numerics.layout import rest_lengths
from ...outcome import Outcome, SolverInfo, freeze
from ...serialize import number, numbers
from ...timelimit import time_limit as _time_limit
from ..equilibria.equilibrium import Equilibrium, check_q0, settle_under_force, solve_equilibrium_under_force
from ..equilibria.least_energy import solve_equilibrium
from .active_bounds import ActiveBound, active_bounds
from .strongest import Design, _safe_critical, buckling_design

__all__ = ["PreloadDesign", "preloads_for_pose", "preloads_for_critical_force", "rest_length_bounds", "OBJECTIVES",
           "forward_check", "stability_margin", "checked_start", "nlp_pose", "spring_bounds", "solve_pose_nlp",
           "NEAREST_REGULARISER"]

#: What a preload problem minimises: ``"change"`` the (weighted) change of the rest lengths from the reference
#: ones (the chain's own for a pose, the previous step's along a trajectory), ``"margin"`` minus the stability
#: margin, ``"energy"`` the spring energy.
OBJECTIVES = ("change", "margin", "energy")
#: Tip error (times ``max b``) within which a forward solve lands on the target.
LAND_TOL = 1e-6
#: Weight of the (normalised) change of the rest lengths in the nearest-pose objective, against the tip distance
#: in units of ``max b``: it picks the least change among equally near poses and moves the distance by ~1e-6.
NEAREST_REGULARISER = 1e-6
_INF = float("inf")
#: ``taut``: every spring at least this much (times the longest link ``b``) longer than its rest length, so that it is
#: strictly in tension beyond IPOPT's feasibility tolerance (a spring ending 1e-9 short would read ``slack`` or
#: ``pushing``, and its one-sided stiffness be the slack side's under the tension-only law).
TAUT_FLOOR = 1e-7


@dataclass(frozen=True)
class PreloadDesign(Outcome, SpringFields):
    """Result of :func:`preloads_for_pose`.

    Attributes
    ----------
    manipulator : Manipulator
        The chain with the chosen rest lengths ``(L1_0, L2_0)`` per segment.
    preloads : ndarray (n, 2)
        The chosen rest lengths.
    q : ndarray (n,)
        The verified equilibrium configuration (force control from the optimiser's ``q``).
    margin : float
        Smallest eigenvalue of the Hessian of ``E - F.tip`` in joint angles at ``q``
        (torque per radian), recomputed.
    tip : ndarray (2,)
        The verified tip position.
    energy : float
        The spring energy there.
    solver : SolverInfo
        IPOPT's return status and iterations.
    equilibrium : Equilibrium
        The full verified equilibrium.
    active_bounds : tuple of ActiveBound
        The rest lengths at (or near) their bounds (:func:`~.active_bounds.active_bounds`).
    status : str
        ``"optimal"`` (:attr:`STATUSES`): a result is returned only when the solve converged and the forward
        check holds; otherwise :func:`preloads_for_pose` raises.
    message : str
        The same in a sentence.
    spring_lengths, spring_stretches, spring_forces, spring_states : ndarray (n, 2)
        The springs at ``q`` (:class:`~tensegrity_opt.model.springs.SpringFields`).
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "optimal": "IPOPT converged to rest lengths meeting every requirement, and the forward equilibrium with "
                   "them, from the optimiser's configuration, lands on the target, stable",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset(STATUSES)

    manipulator: Manipulator
    preloads: np.ndarray
    q: np.ndarray
    margin: float
    tip: np.ndarray
    energy: float
    solver: SolverInfo
    equilibrium: Equilibrium = field(repr=False)
    active_bounds: tuple[ActiveBound, ...] = ()
    status: str = "optimal"

    def __post_init__(self) -> None:
        freeze(self)

    @property
    def springs(self) -> Springs:
        """The designed chain's springs (the spring state's model)."""
        return self.manipulator.springs

    @property
    def message(self) -> str:
        """A sentence: the verified pose and how IPOPT ended."""
        return (f"optimal rest lengths: the tip on the target, stable with margin {self.margin:.6g} "
                f"(IPOPT {self.solver.status}, {self.solver.iterations} iterations)")

    def to_dict(self) -> dict[str, Any]:
        """JSON form (the body of ``POST /v1/design/preloads``): ``success``, ``status``, ``message``,
        ``manipulator``, ``preloads``, ``q``, ``margin``, ``tip``, ``energy``, ``active_bounds``, ``solver``
        ``{status, iterations}``, the spring state (``spring_lengths``, ``spring_stretches``, ``spring_forces``,
        ``spring_states``)."""
        return {**self.outcome(), **self.spring_dict(),
                "manipulator": self.manipulator.to_dict(), "preloads": numbers(self.preloads),
                "q": numbers(self.q), "margin": number(self.margin), "tip": numbers(self.tip),
                "energy": number(self.energy), "active_bounds": [b.to_dict() for b in self.active_bounds],
                "solver": self.solver.to_dict()}


def preloads_for_critical_force(m: Manipulator, required: float, *, boundary: str = "guided",
                                bounds: tuple | None = None, timeout: float | None = None) -> Design:
    """The smallest change of the rest lengths ``L0`` (symmetric) giving a critical load ``>= required``.

    Minimises ``sum((L0 - L0_nom)^2) / sum(L0_nom^2)`` subject to
    ``Z^T (K(L0) - required G) Z`` positive semidefinite and ``L0`` within ``bounds``
    (default ``(0.05 * 2b, 2b)``: springs in tension at straight; each a number or ``n`` values, one per
    segment: both springs of a segment keep one rest length). A chain with tension-only springs: the upper bound is
    capped just below ``2b`` (``TAUT_FLOOR``), so every spring is taut at the straight chain, where the laws agree.
    ``timeout`` (seconds) bounds the whole call,
    both solves, as in :func:`~tensegrity_opt.analyses.design.strongest.maximize_critical_force`.

    Returns
    -------
    Design
        ``status="optimal"``, ``feasible=True`` with the minimal change; or, when no rest lengths within the
        bounds reach ``required``, ``status="below_required"``, ``feasible=False`` with the strongest achievable
        design.

    Raises
    ------
    TimeLimitError
        (``RuntimeError``, ``code = "timeout"``) the time limit was reached, or IPOPT stopped at its
        own ``max_wall_time`` (``status = "Maximum_WallTime_Exceeded"``): no result.
    """
    unloaded_only(m, "preloads_for_critical_force")
    required = float(required)
    if not math.isfinite(required) or required <= 0:
        raise InvalidParameterError("required must be a positive finite load", field="required")
    b = m.b
    bnds = {"L0": bound_pair(bounds) if bounds is not None else (0.05 * 2 * b, 2 * b)}
    law = m
    if not m.linear_springs:
        # the critical load is the straight chain's: where every spring is taut there (L0 < L = 2b) the laws agree,
        # so the linear law's design with the rest lengths capped below 2b holds for the arm as built
        lo, hi = bnds["L0"]
        cap = 2.0 * b * (1.0 - TAUT_FLOOR)
        if np.any(np.asarray(lo, float) >= cap):
            raise InvalidParameterError("bounds: a tension-only spring is slack at the straight chain unless its rest "
                                        "length is below its length there, 2 b: the lower bound must be below 2 b",
                                        field="bounds")
        bnds["L0"] = (lo, np.minimum(np.asarray(hi, float), cap))
        m = m.with_spring("linear")
    with _time_limit(timeout):
        try:
            d = buckling_design(m, ("L0",), bnds, None, boundary, {}, required=required)
        except InfeasibleDesignError:
            best = buckling_design(m, ("L0",), bnds, None, boundary, {}, required=None)
            d = replace(best, feasible=False, status="below_required")
    if law is m:
        return d
    # the starting critical load is the arm's as built: undefined (null) where a spring is slack at straight
    return replace(d, manipulator=law.with_segments(s.replace(spring=t.spring)
                                                    for s, t in zip(d.manipulator.segments, law.segments)),
                   initial_critical_force=_safe_critical(law, boundary))



def preloads_for_pose(m: Manipulator, target, *, load=(0.0, 0.0), objective: str = "change", margin: float = 1e-3,
                      taut: bool = False, bounds: tuple | None = None, end_angle: float | None = None, start=None,
                      timeout: float | None = None) -> PreloadDesign:
    """Rest lengths ``(L1_0, L2_0)`` per segment putting the tip at ``target`` stably under ``load``.

    Parameters
    ----------
    m : Manipulator
        Geometry and stiffness (kept); its rest lengths are the nominal preloads.
    target : (float, float)
        Tip position ``(x, y)`` (length units).
    load : (float, float)
        Tip force ``(fx, fy)`` (a dead load).
    objective : {"change", "margin", "energy"}
        Least change from the nominal preloads (``m``'s rest lengths); largest stability margin; least spring
        energy (:data:`OBJECTIVES`).
    margin : float
        Required smallest eigenvalue of the joint-space Hessian of ``E - F.tip`` (torque/rad);
        the lower bound of the margin for ``objective="margin"``.
    taut : bool
        Keep every spring in tension (``L - L0 >= TAUT_FLOOR * max b``: strictly, beyond IPOPT's tolerance). A chain
        with tension-only springs needs it (where every spring is taut the two laws agree: the design holds for the
        arm as built); without it the chain is refused (``UnsupportedError``, ``field="taut"``).
    bounds : (lo, hi), optional
        Bounds on every rest length, each a number or ``2 n`` values (``L1_0`` of every segment, then every
        ``L2_0``); default ``(0.1 b_min, 4 b_max)`` (:func:`rest_length_bounds`).
    end_angle : float, optional
        Also prescribe the absolute angle of the last link (rad).
    start : array_like (n,), optional
        The configuration to start from (the result is sought in its family of shapes); default the
        least-energy equilibrium at the target with the nominal preloads (or a straight-line guess when there
        is none).
    timeout : float, optional
        Seconds this call may take, as in :func:`~tensegrity_opt.analyses.design.strongest.maximize_critical_force`.

    Returns
    -------
    PreloadDesign
        ``status="optimal"``. Verified (:func:`forward_check`): the force-controlled equilibrium with these
        preloads, started from the optimiser's ``q``, lands on the target within ``1e-6 max(b)`` with Morse
        index 0.

    Raises
    ------
    InfeasibleDesignError
        (``RuntimeError``) IPOPT found no feasible preloads (``best`` holds its last point as a
        dict), or the verification failed.
    TimeLimitError
        (``RuntimeError``, ``code = "timeout"``) the time limit was reached, or IPOPT stopped at its
        own ``max_wall_time`` (``status = "Maximum_WallTime_Exceeded"``): no result.
    """
    unloaded_only(m, "preloads_for_pose")
    if not m.linear_springs:
        if not taut:
            raise UnsupportedError("preloads_for_pose designs a tension-only chain with every spring kept taut (there "
                                   "the laws agree): set taut=True", field="taut", spring="tension_only")
        with _time_limit(timeout):
            d = _preloads_for_pose(m.with_spring("linear"), target, load, objective, margin, True, bounds, end_angle,
                                   start)
        built = m.with_segments(s.replace(spring=t.spring) for s, t in zip(d.manipulator.segments, m.segments))
        return replace(d, manipulator=built, equilibrium=replace(d.equilibrium, springs=built.springs))
    with _time_limit(timeout):
        return _preloads_for_pose(m, target, load, objective, margin, taut, bounds, end_angle, start)



def _preloads_for_pose(m, target, load, objective, margin, taut, bounds, end_angle, start) -> PreloadDesign:
    from ...numerics import preload_nlp

    if objective not in OBJECTIVES:
        raise InvalidParameterError(f"objective must be one of {OBJECTIVES}, got {objective!r}", field="objective")
    target = np.asarray(target, dtype=float)
    load = np.asarray(load, dtype=float)
    if target.shape != (2,) or not np.all(np.isfinite(target)):
        raise InvalidParameterError("target must be two finite numbers (x, y)", field="target")
    if load.shape != (2,) or not np.all(np.isfinite(load)):
        raise InvalidParameterError("load must be two finite numbers (fx, fy)", field="load")
    if not math.isfinite(margin) or margin < 0:
        raise InvalidParameterError("margin must be finite and >= 0", field="margin")
    n = m.n
    if n < 2:
        # one segment: the target alone fixes its angle (a point of a circle) and two rest lengths hold it;
        # the NLP is written for chains (its rows assume n >= 2)
        raise InvalidParameterError("preloads_for_pose needs a chain of n >= 2 segments", field="n")
    dx, dy = m.straight_length - target[0], target[1]
    try:
        m.check_reachable(dx, dy)
    except UnreachableTargetError as exc:        # the caller gave a tip position, not a deflection
        raise UnreachableTargetError(exc.message, field="target", **exc.details) from None
    lo, hi = rest_length_bounds(m, bounds)
    q0 = checked_start(m, start)
    if q0 is None:
        try:
            q0 = solve_equilibrium(m, dx, dy, stops=False).q
        except TensegrityError:
            q0 = _reach_guess(m, target)
    res, q, L10, L20, lo2, hi2 = solve_pose_nlp(m, target, load, objective, margin, taut, lo, hi, end_angle, q0)
    best = {"q": q.tolist(), "preloads": np.column_stack([L10, L20]).tolist(),
            "margin": float(res.x[preload_nlp(n).variables["mu"]])}
    if not res.success:
        raise InfeasibleDesignError(f"IPOPT found no feasible preloads ({res.status})", status=res.status,
                                    best=best)
    m_new = m.with_segments(s.replace(L0=(l1, l2)) for s, l1, l2 in zip(m.segments, L10, L20))
    # the forward solve from the optimiser's q: Newton (IPOPT's own descent from an exact minimum near a joint
    # bound can be pushed into another well by its barrier), IPOPT's descent where Newton does not settle
    eq = forward_check(m_new, load, q, target, settle=True, status=res.status, best=best)
    return PreloadDesign(manipulator=m_new, preloads=np.column_stack([L10, L20]), q=eq.q,
                         margin=stability_margin(m_new, eq.q, load), tip=eq.tip, energy=eq.energy,
                         solver=SolverInfo(res.status, res.iterations), equilibrium=eq,
                         active_bounds=rest_length_active_bounds(L10, L20, lo2, hi2))


def solve_pose_nlp(m: Manipulator, target, load, objective: str, margin: float, taut: bool, lo, hi, end_angle,
                   q0: np.ndarray, ell0: np.ndarray | None = None, *, nearest: bool = False):
    """One IPOPT solve of the preload NLP (:func:`tensegrity_opt.numerics.preload_nlp`) from the configuration
    ``q0`` and the rest lengths ``ell0`` (the :func:`~tensegrity_opt.numerics.layout.rest_lengths` layout;
    default ``m``'s, clipped into the bounds ``lo``, ``hi`` of :func:`rest_length_bounds`); ``m``'s rest lengths
    are the nominal ones of ``objective="change"``.

    ``nearest=False``: the tip on ``target`` (and the last link at ``end_angle``), ``objective`` minimised.
    ``nearest=True``: the tip rows free, minimising ``|tip - target|^2 / max(b)^2`` (plus ``(phi_n -
    end_angle)^2``) plus :data:`NEAREST_REGULARISER` times the change: the admissible pose nearest to the target
    (every other requirement kept: equilibrium under ``load``, the margin, the bounds, the joint range).

    Returns ``(NLPResult, q, L10, L20, lo2, hi2)``: IPOPT's result, its configuration and rest lengths
    (:func:`nlp_pose`) and the bounds' blocks (:func:`spring_bounds`).
    """
    from ...numerics import preload_nlp
    from ...numerics.design_nlp import tril_vector

    n = m.n
    nlp = preload_nlp(n)
    springs = rest_lengths(n)
    L0nom = springs.pack(L10=m.L1_0, L20=m.L2_0)
    L0start = springs.unpack(np.clip(L0nom if ell0 is None else ell0, lo, hi))
    m_start = m.with_segments(s.replace(L0=(l1, l2)) for s, l1, l2 in zip(m.segments, L0start["L10"], L0start["L20"]))
    _, _, Hphi, _, _ = chain_solver(m_start).evaluate(q0, load)
    Hq = _relative(Hphi)
    mu0 = margin if objective != "margin" else max(margin, float(np.linalg.eigvalsh(Hq)[0]))
    w_, V_ = np.linalg.eigh(Hq - mu0 * np.eye(n))
    # a start for the margin's Cholesky factor; the floor relative to the Hessian's size (loads of 1e12
    # give entries of 1e12, where an absolute 1e-6 is below roundoff and the factorisation fails)
    Lc = np.linalg.cholesky(V_ @ np.diag(np.maximum(w_, 1e-6 * max(1.0, float(np.abs(w_).max())))) @ V_.T)
    x, g = nlp.variables, nlp.constraints
    lo2, hi2 = spring_bounds(n, lo, hi)
    x0 = x.pack(phi=np.cumsum(q0), **L0start, mu=mu0, L=tril_vector(Lc))
    lbx = x.pack(phi=-_INF, **lo2, mu=margin, L=nlp.factor_floor)
    ubx = x.pack(phi=_INF, **hi2, mu=margin if objective != "margin" else _INF, L=_INF)
    lim = m.joint_limits * (1 - RANGE_SHRINK)
    slack = TAUT_FLOOR * float(np.max(m.b)) if taut else -_INF
    if nearest:
        tip_lo, tip_hi, ea = -_INF, _INF, (-_INF, _INF)
        weights = [NEAREST_REGULARISER, 0.0, 0.0, 1.0 / float(np.max(m.b)) ** 2, float(end_angle is not None)]
    else:
        tip_lo = tip_hi = target
        ea = (-_INF, _INF) if end_angle is None else (float(end_angle), float(end_angle))
        weights = {"change": [1.0, 0.0, 0.0], "margin": [1e-6, 1.0, 0.0], "energy": [0.0, 0.0, 1.0]}[objective]
        weights = [*weights, 0.0, 0.0]
    lbg = g.pack(grad=0.0, tip=tip_lo, angle=ea[0], psd=0.0, stretch1=slack, stretch2=slack, q=-lim)
    ubg = g.pack(grad=0.0, tip=tip_hi, angle=ea[1], psd=0.0, stretch1=_INF, stretch2=_INF, q=lim)
    aim = [float(target[0]), float(target[1]), 0.0 if end_angle is None else float(end_angle)]
    p = nlp.parameters.pack(a=m.a, b=m.b, k1=m.k1, k2=m.k2, F=load, L0nom=L0nom, w=weights, aim=aim)
    res = nlp.solve(x0, lbx, ubx, lbg, ubg, p)
    q, L10, L20 = nlp_pose(x, res.x, lo2, hi2)
    return res, q, L10, L20, lo2, hi2


def rest_length_active_bounds(L10, L20, lo: dict, hi: dict) -> tuple[ActiveBound, ...]:
    """The rest lengths ``L1_0`` (``L10``), ``L2_0`` (``L20``) at or near their bounds ``lo``, ``hi``
    (:func:`spring_bounds`' blocks), segment by segment (:func:`~.active_bounds.active_bounds`)."""
    found = active_bounds({"L1_0": L10, "L2_0": L20}, {"L1_0": lo["L10"], "L2_0": lo["L20"]},
                          {"L1_0": hi["L10"], "L2_0": hi["L20"]})
    return tuple(sorted(found, key=lambda b: (b.segment, b.variable)))


def spring_bounds(n: int, lo, hi) -> tuple[dict[str, np.ndarray], dict[str, np.ndarray]]:
    """The bounds ``(lo, hi)`` of :func:`rest_length_bounds` as the design problems' blocks ``L10``, ``L20``
    (:func:`tensegrity_opt.numerics.layout.rest_lengths`)."""
    springs = rest_lengths(n)
    return springs.unpack(np.broadcast_to(lo, springs.size)), springs.unpack(np.broadcast_to(hi, springs.size))


def nlp_pose(variables, x: np.ndarray, lo: dict, hi: dict) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(q, L10, L20)`` at the point ``x`` of a preload NLP (its ``variables``' blocks ``phi``, ``L10``,
    ``L20``): the relative joint angles and the rest lengths, clipped into their bounds ``lo``, ``hi``
    (:func:`spring_bounds`; IPOPT may step 1e-8 outside)."""
    v = variables.unpack(x)
    return (np.diff(np.concatenate([[0.0], v["phi"]])), np.clip(v["L10"], lo["L10"], hi["L10"]),
            np.clip(v["L20"], lo["L20"], hi["L20"]))


def forward_check(m: Manipulator, load: np.ndarray, q: np.ndarray, target: np.ndarray, *, settle: bool,
                  status: str, best: Any) -> Equilibrium:
    """The verification of a preload design: the forward equilibrium of ``m`` (the chain with the found rest
    lengths) under the dead ``load`` from the optimiser's ``q`` must land on ``target`` (within ``LAND_TOL``
    times ``max b``), stable. ``settle``: Newton from ``q`` first (:func:`settle_under_force`), IPOPT's descent
    (:func:`solve_equilibrium_under_force`) where Newton does not settle; otherwise the descent alone.

    Returns
    -------
    Equilibrium
        The verified equilibrium.

    Raises
    ------
    InfeasibleDesignError
        The check fails (``status`` and ``best`` passed on).
    TimeLimitError
        The time limit ran out.
    """
    eq = settle_under_force(m, load, q) if settle else None
    try:
        eq = eq if eq is not None else solve_equilibrium_under_force(m, load[0], load[1], q0=q)
    except TimeLimitError:
        raise
    except TensegrityError as exc:
        raise InfeasibleDesignError(f"verification failed: no force-controlled equilibrium from the returned q "
                                    f"({exc})", status=status, best=best) from exc
    if not eq.stable or np.max(np.abs(eq.tip - target)) > LAND_TOL * float(m.b.max()):     # in the chain's units
        raise InfeasibleDesignError(
            f"verification failed: the force-controlled equilibrium lands at {eq.tip.tolist()} "
            f"(target {target.tolist()}), Morse index {eq.morse_index}", status=status, best=best)
    return eq


def _relative(H_phi: np.ndarray) -> np.ndarray:
    """A Hessian in the absolute angles ``phi = T q`` as one in the relative angles: ``T^T H T``."""
    T = np.tril(np.ones(H_phi.shape))
    return T.T @ H_phi @ T


def stability_margin(m: Manipulator, q: np.ndarray, load) -> float:
    """The smallest eigenvalue of the Hessian of ``E - F . tip`` in the joint angles at ``q`` under the dead
    ``load`` (torque / rad): the stability margin every preload problem requires and reports."""
    _, _, H_phi, _, _ = chain_solver(m).evaluate(q, load)
    return float(np.linalg.eigvalsh(_relative(H_phi))[0])


def checked_start(m: Manipulator, start) -> np.ndarray | None:
    """A preload problem's ``start`` (None, or ``n`` joint angles inside the physical range), checked
    (``field="start"``)."""
    try:
        return check_q0(m, start)
    except InvalidParameterError as exc:
        raise InvalidParameterError(exc.message.replace("q0", "start"), field="start") from None


def rest_length_bounds(m: Manipulator, bounds) -> tuple[Any, Any]:
    """``(lo, hi)`` of a preload problem's ``bounds`` (``[lo, hi]`` or ``{"lo", "hi"}``, each a number or ``2 n``
    values: ``L1_0`` of every segment, then every ``L2_0``; default ``(0.1 b_min, 4 b_max)``), checked
    (``field="bounds"``)."""
    n = m.n
    try:
        lo, hi = bound_pair(bounds) if bounds is not None else (0.1 * float(m.b.min()), 4.0 * float(m.b.max()))
        lo = np.broadcast_to(np.asarray(lo, dtype=float), (2 * n)).copy() if np.ndim(lo) else float(lo)
        hi = np.broadcast_to(np.asarray(hi, dtype=float), (2 * n)).copy() if np.ndim(hi) else float(hi)
    except (TypeError, ValueError):
        raise InvalidParameterError("bounds: lo and hi are numbers or 2n values (L1_0 of every segment, then "
                                    "L2_0)", field="bounds") from None
    if not (np.all(np.isfinite(lo)) and np.all(np.isfinite(hi)) and np.all(0 < np.asarray(lo))
            and np.all(np.asarray(lo) < np.asarray(hi))):
        raise InvalidParameterError("bounds need 0 < lo < hi", field="bounds")
    return lo, hi


def _reach_guess(m: Manipulator, target: np.ndarray) -> np.ndarray:
    """A configuration bending every joint equally toward the target (a start, not a solution)."""
    ang = math.atan2(target[1], target[0] - m.base_length)
    return np.concatenate([[ang], np.zeros(m.n - 1)]) * 0.5
