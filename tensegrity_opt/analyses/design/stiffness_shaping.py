"""Stiffness shaping: rest lengths for a pose with a desired or bounded Cartesian stiffness of the tip.

:func:`preloads_for_stiffness` finds rest lengths ``(L1_0, L2_0)`` per segment giving a stable pose with the
tip at a target under a dead tip load **and** a prescribed Cartesian tangent stiffness of the free tip: a desired
2 x 2 matrix (least squares on its entries; exact, with the least change of the preloads, when it is
reachable), bounds on its entries, or bounds on its eigenvalues. An IPOPT NLP
(:class:`~tensegrity_opt.numerics.design_nlp.StiffnessNLP`) started from
:func:`~tensegrity_opt.analyses.design.preloads.preloads_for_pose`' pose; the result is verified by the forward
equilibrium (:func:`~tensegrity_opt.analyses.equilibria.equilibrium.solve_equilibrium_under_force` with the found
rest lengths, from the found ``q``) and :func:`~tensegrity_opt.analyses.equilibria.stiffness.cartesian_stiffness`
there.

The stiffness is the one of :func:`~tensegrity_opt.analyses.equilibria.stiffness.cartesian_stiffness`:
``K = dF/d(tip)`` along the equilibria, ``F`` the tip force holding the chain (``grad E = J^T F``,
``docs/model.md``). With the tip free under a dead load, at an equilibrium where ``H``, the Hessian of
``E - F . tip`` in the joint angles, is positive definite, ``K = (J H^-1 J^T)^-1`` (the inverse of the tip
compliance), which is how the NLP writes it. Formulations and measured numbers: ``docs/design.md``, "Stiffness
shaping and load capacity".

Example (the paper's chain, tip at ``(7, 1)``: both eigenvalues of the tip stiffness pushed to bounds)::

    >>> import tensegrity_opt as to
    >>> m = to.Manipulator.uniform(4)
    >>> d = to.preloads_for_stiffness(m, (7.0, 1.0), eig_bounds=[0.04, 0.6])
    >>> [round(float(w), 6) for w in d.eigenvalues], bool(d.equilibrium.stable)
    ([0.04, 0.6], True)
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from ...bounds import bound_pair
from ...errors import InfeasibleDesignError, InvalidParameterError, TensegrityError
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...model.springs import SpringFields, Springs, linear_only
from ...numerics import RANGE_SHRINK, chain_solver
from ...numerics.layout import rest_lengths
from ...outcome import Outcome, SolverInfo, freeze
from ...serialize import nullables, number, numbers
from ...timelimit import time_limit as _time_limit
from ..equilibria.equilibrium import Equilibrium
from ..equilibria.stiffness import cartesian_stiffness
from .active_bounds import ActiveBound
from .preloads import (
    PreloadDesign,
    checked_start,
    forward_check,
    nlp_pose,
    preloads_for_pose,
    rest_length_active_bounds,
    rest_length_bounds,
    spring_bounds,
    stability_margin,
)

__all__ = ["StiffnessDesign", "preloads_for_stiffness", "STIFFNESS_KEYS", "EXACT_TOL", "K_TOL"]

#: The entries of the 2 x 2 stiffness ``bounds_K`` may bound (``kxy`` and ``kyx`` are the same entry: ``K`` is
#: symmetric).
STIFFNESS_KEYS = ("kxx", "kxy", "kyx", "kyy")
#: Relative misfit ``|K - K_desired|_F / |K_desired|_F`` below which a desired stiffness counts as reached: the
#: least-squares solution is then replaced by the least change of the preloads with ``K = K_desired`` held
#: exactly.
EXACT_TOL = 1e-6
#: Tolerance of the verification of bounds on ``K`` (relative to ``max(|K|, stiffness scale)``).
K_TOL = 1e-6
#: Weight of the relative change of the preloads in the least-squares fit (picks one of its minimisers).
FIT_REG = 1e-8
#: Relative misfit of the least-squares fit below which ``K = K_desired`` is tried exactly from it.
EXACT_TRY = 1e-2
_INF = float("inf")
_ENTRY = {"kxx": 0, "kxy": 1, "kyx": 1, "kyy": 2}


@dataclass(frozen=True)
class StiffnessDesign(Outcome, SpringFields):
    """Result of :func:`preloads_for_stiffness`.

    Attributes
    ----------
    manipulator : Manipulator
        The chain with the found rest lengths.
    rest_lengths : ndarray (n, 2)
        ``(L1_0, L2_0)`` per segment.
    q : ndarray (n,)
        The verified equilibrium (the forward solve under ``load`` from the optimiser's ``q``).
    tip : ndarray (2,)
        Its tip (on the target within ``1e-6 max(b)``).
    K : ndarray (2, 2)
        :func:`cartesian_stiffness` at the verified equilibrium (force / length).
    eigenvalues : ndarray (2,)
        Of ``K``, ascending.
    margin : float
        Smallest eigenvalue of the Hessian of ``E - F . tip`` in the joint angles (torque / rad), recomputed.
    residual : float
        With ``K_desired``: ``|K - K_desired|_F / |K_desired|_F`` (0 to the solver's tolerance when reached);
        otherwise the largest violation of the bounds by ``K`` (force / length; 0 when they hold).
    exact : bool
        ``K_desired``: ``residual <= EXACT_TOL`` (then the preloads are the least change from the nominal ones
        holding ``K = K_desired``; otherwise the least-squares fit). Bounds: they hold (always, when returned).
    solver : SolverInfo
        IPOPT's return status and iterations (of the final solve).
    load : ndarray (2,)
        The dead tip load.
    K_desired : ndarray (2, 2) or None
    bounds_K : dict
        ``{"kxx" | "kxy" | "kyy": (lo, hi)}`` as imposed (``kyx`` merged into ``kxy``; infinite for none).
    eig_bounds : tuple or None
    equilibrium : Equilibrium
        The verified forward equilibrium.
    active_bounds : tuple of ActiveBound
        The rest lengths at (or near) their bounds (:func:`~.active_bounds.active_bounds`): the design is the
        best within them, and wider bounds may change it.
    status : str
        :attr:`STATUSES`, from ``K_desired`` and ``exact``: ``"exact"``, ``"closest"`` (not a success: the wanted
        stiffness is out of reach) or ``"within_bounds"``.
    message : str
        The same in a sentence, with the residual.
    spring_lengths, spring_stretches, spring_forces, spring_states : ndarray (n, 2)
        The springs at ``q`` (:class:`~tensegrity_opt.model.springs.SpringFields`).
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "exact": "K = K_desired holds at the verified pose (residual <= EXACT_TOL), with the least change of the "
                 "preloads (within the bounds, where some are given)",
        "closest": "K_desired is not reachable from any start: the least-squares fit with the smallest misfit "
                   "(residual, relative), within the bounds where some are given",
        "within_bounds": "the bounds on the entries and eigenvalues of K hold at the verified pose, with the least "
                         "change of the preloads",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"exact", "within_bounds"})

    manipulator: Manipulator
    rest_lengths: np.ndarray
    q: np.ndarray
    tip: np.ndarray
    K: np.ndarray
    eigenvalues: np.ndarray
    margin: float
    residual: float
    exact: bool
    solver: SolverInfo
    load: np.ndarray
    K_desired: np.ndarray | None
    bounds_K: dict
    eig_bounds: tuple | None
    equilibrium: Equilibrium = field(repr=False)
    active_bounds: tuple[ActiveBound, ...] = ()

    def __post_init__(self) -> None:
        freeze(self)

    @property
    def springs(self) -> Springs:
        """The designed chain's springs (the spring state's model)."""
        return self.manipulator.springs

    @property
    def status(self) -> str:
        """``"exact"``, ``"closest"`` or ``"within_bounds"`` (:attr:`STATUSES`)."""
        if self.K_desired is None:
            return "within_bounds"
        return "exact" if self.exact else "closest"

    @property
    def message(self) -> str:
        """A sentence: what the stiffness reaches."""
        if self.status == "exact":
            return f"K = K_desired reached (relative misfit {self.residual:.3g})"
        if self.status == "closest":
            return (f"K_desired is not reachable: the closest stiffness found misses it by {self.residual:.6g} "
                    "(relative, Frobenius norm)")
        return (f"the stiffness bounds hold: eigenvalues {self.eigenvalues[0]:.6g}, {self.eigenvalues[1]:.6g} "
                "(force / length)")

    def to_dict(self) -> dict[str, Any]:
        """JSON form: ``success``, ``status``, ``message``, ``manipulator``, ``rest_lengths``, ``q``, ``tip``,
        ``K``, ``eigenvalues``, ``margin``, ``residual``, ``exact``, ``load``, ``K_desired`` (or null), ``bounds_K``
        (``[lo, hi]`` per entry, null for an open side), ``eig_bounds`` (the same, or null), ``active_bounds``
        (``{segment, variable, side, value, bound}`` each), ``solver`` ``{status, iterations}``, the spring state
        (``spring_lengths``, ``spring_stretches``, ``spring_forces``, ``spring_states``)."""
        return {**self.outcome(), **self.spring_dict(),
                "manipulator": self.manipulator.to_dict(), "rest_lengths": numbers(self.rest_lengths),
                "q": numbers(self.q), "tip": numbers(self.tip), "K": numbers(self.K),
                "eigenvalues": numbers(self.eigenvalues), "margin": number(self.margin),
                "residual": number(self.residual), "exact": bool(self.exact), "load": numbers(self.load),
                "K_desired": None if self.K_desired is None else numbers(self.K_desired),
                "bounds_K": {k: nullables(v) for k, v in self.bounds_K.items()},
                "eig_bounds": None if self.eig_bounds is None else nullables(self.eig_bounds),
                "active_bounds": [b.to_dict() for b in self.active_bounds], "solver": self.solver.to_dict()}


def _pair(v, name: str) -> tuple[float, float]:
    """``(lo, hi)`` from a pair of numbers or None (an open side), checked (``field=name``)."""
    lo, hi = bound_pair(v, name)
    try:
        lo = -_INF if lo is None else float(lo)
        hi = _INF if hi is None else float(hi)
    except (TypeError, ValueError):
        raise InvalidParameterError(f"{name} must be a pair [lo, hi] of numbers or None, got {v!r}",
                                    field=name) from None
    if math.isnan(lo) or math.isnan(hi) or lo == _INF or hi == -_INF or lo > hi:
        raise InvalidParameterError(f"{name} needs lo <= hi (got {lo:g}, {hi:g})", field=name)
    return lo, hi


def _check_stiffness_args(K_desired, bounds_K, eig_bounds):
    if K_desired is None and not bounds_K and eig_bounds is None:
        raise InvalidParameterError("give K_desired, bounds_K or eig_bounds (what stiffness to shape)",
                                    field="K_desired")
    Kd = None
    if K_desired is not None:
        try:
            Kd = np.asarray(K_desired, dtype=float)
        except (TypeError, ValueError):
            raise InvalidParameterError("K_desired must be a 2 x 2 matrix of numbers", field="K_desired") from None
        if Kd.shape != (2, 2) or not np.all(np.isfinite(Kd)):
            raise InvalidParameterError(f"K_desired must be a finite 2 x 2 matrix, got shape {Kd.shape}",
                                        field="K_desired")
        if abs(Kd[0, 1] - Kd[1, 0]) > 1e-6 * max(1e-300, float(np.abs(Kd).max())):
            raise InvalidParameterError("K_desired must be symmetric: the tangent stiffness is (it is the Hessian "
                                        "of the equilibrium energy in the tip position)", field="K_desired")
        if not np.any(Kd != 0.0):
            raise InvalidParameterError("K_desired must not be zero (a stable free tip has a positive definite "
                                        "stiffness)", field="K_desired")
        Kd = 0.5 * (Kd + Kd.T)
    kb = {"kxx": (-_INF, _INF), "kxy": (-_INF, _INF), "kyy": (-_INF, _INF)}
    if bounds_K:
        if not isinstance(bounds_K, Mapping):
            raise InvalidParameterError("bounds_K must be a dict {'kxx' | 'kxy' | 'kyy': [lo, hi]}", field="bounds_K")
        for key, v in bounds_K.items():
            if key not in _ENTRY:
                raise InvalidParameterError(f"bounds_K: unknown entry {key!r}, use {STIFFNESS_KEYS}",
                                            field="bounds_K")
            lo, hi = _pair(v, f"bounds_K.{key}")
            name = "kxy" if key == "kyx" else key
            lo0, hi0 = kb[name]
            lo, hi = max(lo, lo0), min(hi, hi0)
            if lo > hi:
                raise InvalidParameterError("bounds_K: kxy and kyx (the same entry) have disjoint bounds",
                                            field=f"bounds_K.{key}")
            kb[name] = (lo, hi)
    eb = None
    if eig_bounds is not None:
        eb = _pair(eig_bounds, "eig_bounds")
        if eb[1] <= 0.0:
            raise InvalidParameterError("eig_bounds: the upper bound must be > 0 (a stable free tip has a positive "
                                        "definite stiffness)", field="eig_bounds")
    return Kd, kb, eb


def _violations(K: np.ndarray, kb: dict, eb, Ks: float) -> list[tuple[str, float]]:
    """``(description, amount)`` of every bound on ``K`` violated by more than the tolerance."""
    tol = K_TOL * max(Ks, float(np.abs(K).max()))
    out = []
    vals = {"kxx": K[0, 0], "kxy": 0.5 * (K[0, 1] + K[1, 0]), "kyy": K[1, 1]}
    for name, (lo, hi) in kb.items():
        v = float(vals[name])
        if v < lo - tol:
            out.append((f"{name} = {v:.6g} below its lower bound {lo:.6g}", lo - v))
        if v > hi + tol:
            out.append((f"{name} = {v:.6g} above its upper bound {hi:.6g}", v - hi))
    if eb is not None:
        w = np.linalg.eigvalsh(0.5 * (K + K.T))
        if w[0] < eb[0] - tol:
            out.append((f"the smallest eigenvalue {w[0]:.6g} below eig_bounds' lower bound {eb[0]:.6g}",
                        eb[0] - w[0]))
        if w[1] > eb[1] + tol:
            out.append((f"the largest eigenvalue {w[1]:.6g} above eig_bounds' upper bound {eb[1]:.6g}",
                        w[1] - eb[1]))
    return out


def preloads_for_stiffness(m: Manipulator, target, *, K_desired=None, bounds_K: Mapping | None = None,
                           eig_bounds=None, load=(0.0, 0.0), end_angle: float | None = None, margin: float = 1e-3,
                           bounds: tuple | None = None, start=None, max_starts: int = 4,
                           timeout: float | None = None) -> StiffnessDesign:
    """Rest lengths putting the tip at ``target``, stable under ``load``, with a shaped Cartesian stiffness.

    Parameters
    ----------
    m : Manipulator
        Geometry and stiffness (kept); its rest lengths are the nominal preloads. ``n >= 2``.
    target : (float, float)
        Tip position ``(x, y)``.
    K_desired : 2 x 2 array_like, optional
        The stiffness wanted (symmetric to ``1e-6`` relative, its symmetric part is used; force / length). First
        held exactly (``K = K_desired`` as constraints, the least change of the preloads as objective); where
        that fails, the least-squares fit on its entries, ``min |K - K_desired|_F^2 / |K_desired|_F^2`` (plus
        ``FIT_REG`` times the relative change of the preloads, to pick one of its minimisers), and, where the
        fit comes within ``EXACT_TRY``, the exact problem again from it. Reached: ``exact=True``, ``residual``
        ~1e-9. Not reachable from any start: the fit with the smallest misfit, ``exact=False``,
        ``status="closest"``, ``residual`` its relative misfit (no error).
    bounds_K : dict, optional
        ``{"kxx": [lo, hi], "kxy": [lo, hi], "kyy": [lo, hi]}`` (``kyx`` = ``kxy``; ``None`` an open side):
        bounds on the entries of ``K``.
    eig_bounds : [lo, hi], optional
        Bounds on both eigenvalues of ``K`` (``None`` an open side; ``hi > 0``).
        With bounds only, the objective is the least change from the nominal preloads
        (``|L0 - L0_nom|^2 / |L0_nom|^2``, as :func:`preloads_for_pose`). Bounds and ``K_desired`` combine
        (the fit within the bounds). At least one of the three is needed.
    load : (float, float)
        The dead tip load ``(fx, fy)``.
    end_angle : float, optional
        Also prescribe the last link's absolute angle (rad).
    margin : float
        Required smallest eigenvalue of the joint-space Hessian of ``E - F . tip`` (torque / rad; > 0 makes
        the pose stable with the tip free, and ``K`` positive definite).
    bounds : (lo, hi), optional
        Bounds on every rest length, as :func:`preloads_for_pose` (default ``(0.1 b_min, 4 b_max)``).
    start : array_like (n,), optional
        The configuration to start from (:func:`preloads_for_pose`' ``start``): the result is then sought in its
        family of shapes only. Default: the equilibria of the nominal chain at the target
        (:func:`~tensegrity_opt.analyses.equilibria.all_equilibria.find_equilibria`; stable ones first, by energy),
        each a start in turn (different shapes reach different stiffnesses), until one meets the requirement
        (an exact ``K_desired``, or the bounds); an inexact fit keeps the smallest residual over the starts.
    max_starts : int
        At most this many of those starts (default 4).
    timeout : float, optional
        Seconds this call may take (:func:`tensegrity_opt.time_limit`).

    Returns
    -------
    StiffnessDesign
        Verified: the forward equilibrium with the found rest lengths, from the found ``q``, lands on the
        target within ``1e-6 max(b)``, is stable with the margin, and :func:`cartesian_stiffness` there is
        within the bounds (``K_TOL``); ``K``, ``q``, ``tip``, ``margin`` and ``residual`` are the verified ones.

    Raises
    ------
    InvalidParameterError
        (``ValueError``) bad arguments; ``field`` names the argument (``bounds_K.kxx`` for one entry).
    UnreachableTargetError
        (``ValueError``) the target is beyond the chain's reach (``field="target"``).
    InfeasibleDesignError
        (``RuntimeError``) no stable pose at the target (from :func:`preloads_for_pose`), or no rest lengths
        meet the stiffness bounds: ``best`` holds the best point found — the least relaxation of the bounds
        that a stable pose reaches (elastic mode): ``q``, ``rest_lengths``, ``K``, ``violations`` (the bounds
        violated there, also named in the message) and ``least_violation`` (force / length); or the
        verification failed.
    TimeLimitError
        (``RuntimeError``) the time limit was reached: no result.
    """
    unloaded_only(m, "preloads_for_stiffness")
    linear_only(m, "preloads_for_stiffness")
    Kd, kb, eb = _check_stiffness_args(K_desired, bounds_K, eig_bounds)
    if isinstance(max_starts, bool) or not isinstance(max_starts, (int, np.integer)) or max_starts < 1:
        raise InvalidParameterError(f"max_starts must be an integer >= 1, got {max_starts!r}", field="max_starts")
    with _time_limit(timeout):
        return _preloads_for_stiffness(m, target, Kd, kb, eb, load, end_angle, margin, bounds, start,
                                       int(max_starts))


class _Shaper:
    """One call's stiffness NLP: its bounds, rows and parameters (packed by the NLP's layouts) and the solves."""

    def __init__(self, m, target, Kd, kb, eb, load, end_angle, margin, lo, hi) -> None:
        from ...numerics import stiffness_nlp

        n = self.n = m.n
        self.m, self.target, self.Kd, self.kb, self.eb, self.load, self.margin = m, target, Kd, kb, eb, load, margin
        self.lo2, self.hi2 = spring_bounds(n, lo, hi)
        self.Ts = float(m.torque_scale)
        self.Ls = float(m.straight_length / n)
        self.Ks = self.Ts / self.Ls ** 2                # the stiffness scale: the NLP's K is K / Ks
        self.nlp = stiffness_nlp(n)
        self.x, self.g, self.p = self.nlp.variables, self.nlp.constraints, self.nlp.parameters
        self.lim = m.joint_limits * (1 - RANGE_SHRINK)
        self.ea = (-_INF, _INF) if end_angle is None else (float(end_angle), float(end_angle))
        Ks = self.Ks
        self.kb_lo = np.array([kb[k][0] for k in ("kxx", "kxy", "kyy")]) / Ks
        self.kb_hi = np.array([kb[k][1] for k in ("kxx", "kxy", "kyy")]) / Ks
        self.elo, self.ehi = (eb[0] / Ks, eb[1] / Ks) if eb is not None else (-_INF, _INF)
        self.e_lb = np.array([0.0 if math.isfinite(self.elo) else -_INF] * 2
                             + [0.0 if math.isfinite(self.ehi) else -_INF] * 2)
        self.e_p = [self.elo if math.isfinite(self.elo) else 0.0, self.ehi if math.isfinite(self.ehi) else 0.0]
        self.L0nom = rest_lengths(n).pack(L10=m.L1_0, L20=m.L2_0)
        self.Kd_s = np.zeros(3) if Kd is None else np.array([Kd[0, 0], Kd[0, 1], Kd[1, 1]]) / Ks
        self.nd = float(self.Kd_s[0] ** 2 + 2 * self.Kd_s[1] ** 2 + self.Kd_s[2] ** 2) if Kd is not None else 1.0
        self.T = np.tril(np.ones((n, n)))

    # ------------------------------------------------------------------ layout
    def start(self, pose: PreloadDesign) -> np.ndarray:
        """``x`` at a verified pose: its angles and rest lengths, the compliance columns, the margin's factor."""
        from ...numerics.design_nlp import tril_vector

        n = self.n
        _, _, Hphi, J, _ = chain_solver(pose.manipulator).evaluate(pose.q, self.load)
        Hq = self.T.T @ Hphi @ self.T
        Y = np.linalg.solve(Hphi, J.T) * self.Ts / self.Ls
        w_, V_ = np.linalg.eigh(Hq - self.margin * np.eye(n))
        Lc = np.linalg.cholesky(V_ @ np.diag(np.maximum(w_, 1e-6 * max(1.0, float(np.abs(w_).max())))) @ V_.T)
        return self.x.pack(phi=np.cumsum(pose.q), L10=pose.preloads[:, 0], L20=pose.preloads[:, 1], mu=self.margin,
                           L=tril_vector(Lc), Y=Y.ravel(order="F"), s=0.0)

    def box(self, elastic: bool):
        floor = self.nlp.factor_floor
        lbx = self.x.pack(phi=-_INF, **self.lo2, mu=self.margin, L=floor, Y=-_INF, s=0.0)
        ubx = self.x.pack(phi=_INF, **self.hi2, mu=self.margin, L=_INF, Y=_INF, s=_INF if elastic else 0.0)
        return lbx, ubx

    def rows(self, k_lo, k_hi):
        lbg = self.g.pack(grad=0.0, tip=self.target, angle=self.ea[0], psd=0.0, compliance=0.0, q=-self.lim,
                          K_lo=k_lo, K_hi=-_INF, eig=self.e_lb)
        ubg = self.g.pack(grad=0.0, tip=self.target, angle=self.ea[1], psd=0.0, compliance=0.0, q=self.lim,
                          K_lo=_INF, K_hi=k_hi, eig=_INF)
        return lbg, ubg

    def params(self, w):
        m = self.m
        return self.p.pack(a=m.a, b=m.b, k1=m.k1, k2=m.k2, F=self.load, L0nom=self.L0nom, Kd=self.Kd_s, w=w,
                           eig=self.e_p, scales=[self.Ts, self.Ls])

    def slack(self, x) -> float:
        """The relaxation ``s`` of the stiffness bounds at ``x`` (scaled; 0 outside the elastic mode)."""
        return float(x[self.x["s"]])

    def with_slack(self, x, s: float) -> np.ndarray:
        """A copy of ``x`` with the relaxation ``s``."""
        out = x.copy()
        out[self.x["s"]] = s
        return out

    def pose(self, x) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(q, L10, L20)`` of the NLP's point ``x`` (:func:`~.preloads.nlp_pose`)."""
        return nlp_pose(self.x, x, self.lo2, self.hi2)

    def K_of(self, x) -> np.ndarray:
        """The stiffness (force / length) of the NLP's point ``x`` (its ``K`` rows)."""
        g = self.nlp.rows(x, self.params([0.0, 0.0, 0.0]))
        kxx, kxy, kyy = (self.g.unpack(g)["K_lo"] - self.slack(x)) * self.Ks
        return np.array([[kxx, kxy], [kxy, kyy]])

    def misfit(self, x) -> float:
        return float(np.linalg.norm(self.K_of(x) - self.Kd) / np.linalg.norm(self.Kd))

    def best(self, x) -> dict[str, Any]:
        q, L10, L20 = self.pose(x)
        K = self.K_of(x)
        return {"q": q.tolist(), "rest_lengths": np.column_stack([L10, L20]).tolist(), "K": K.tolist(),
                "violations": [v for v, _ in _violations(K, self.kb, self.eb, self.Ks)]}

    def slack_needed(self, x) -> float:
        """The relaxation (scaled) that makes ``x``'s stiffness meet every bound."""
        K = self.K_of(x) / self.Ks
        kv = np.array([K[0, 0], K[0, 1], K[1, 1]])
        w = np.linalg.eigvalsh(K)
        need = [0.0, *(self.kb_lo - kv), *(kv - self.kb_hi), self.elo - w[0], w[1] - self.ehi]
        return max(v for v in need if math.isfinite(v))

    # ------------------------------------------------------------------ solves
    def solve(self, x, *, elastic=False, exact=False, w=None):
        k_lo, k_hi = self.kb_lo, self.kb_hi
        if exact:                                   # K = Kd held (within the bounds on its entries)
            k_lo, k_hi = np.maximum(self.Kd_s, k_lo), np.minimum(self.Kd_s, k_hi)
        if w is None:
            w = [0.0, 1.0, 0.0] if exact or self.Kd is None else [1.0 / self.nd, FIT_REG, 0.0]
        return self.nlp.solve(x, *self.box(elastic), *self.rows(k_lo, k_hi), self.params(w))

    def feasible(self, x):
        """The bounds problem from ``x``: directly; else the least relaxation ``s`` of the stiffness bounds
        (elastic mode, feasible from any pose) and, where it reaches 0, directly again from there.
        Returns ``(result or None, elastic result or None)``."""
        res = self.solve(x)
        if res.success:
            return res, None
        xe = self.with_slack(x, self.slack_needed(x) + 0.1)
        el = self.solve(xe, elastic=True, w=[0.0, 1e-6, 1.0])
        if el.success and self.slack(el.x) <= 1e-8:
            res = self.solve(self.with_slack(el.x, 0.0))
            if res.success:
                return res, el
        return None, el if el.success else None

    def fit(self, x):
        """``K_desired`` from ``x``: held exactly (least change); else the least-squares fit and, where it
        comes within ``EXACT_TRY``, held exactly from there. Returns ``(result or None, exact)``."""
        r = self.solve(x, exact=True)
        if r.success:
            return r, True
        if self.kb_lo.max() > -_INF or self.kb_hi.min() < _INF or self.eb is not None:
            r, _ = self.feasible(x)                 # the fit starts inside the bounds
            if r is None:
                return None, False
            x = r.x
        r = self.solve(x)
        if not r.success:
            return None, False
        if self.misfit(r.x) <= EXACT_TRY:
            r2 = self.solve(r.x, exact=True)
            if r2.success:
                return r2, True
        return r, False


def _starts(m: Manipulator, target: np.ndarray, start, max_starts: int) -> list[np.ndarray | None]:
    """Configurations to start the pose from: ``start``; else the equilibria of the nominal chain at the target
    (:func:`find_equilibria`: stable ones first, by energy), at most ``max_starts``, or None (the default)."""
    if start is not None:
        return [start]
    from ..equilibria.all_equilibria import find_equilibria

    try:
        eqs = list(find_equilibria(m, m.straight_length - target[0], target[1]))
    except TensegrityError:
        eqs = []
    eqs.sort(key=lambda e: (e.morse_index, e.energy))
    out = [e.q for e in eqs[:max_starts]]
    return out or [None]


def _preloads_for_stiffness(m, target, Kd, kb, eb, load, end_angle, margin, bounds, start,
                            max_starts) -> StiffnessDesign:
    n = m.n
    if n < 2:
        raise InvalidParameterError("preloads_for_stiffness needs a chain of n >= 2 segments", field="n")
    if end_angle is not None and not math.isfinite(float(end_angle)):
        raise InvalidParameterError("end_angle must be finite", field="end_angle")
    start = checked_start(m, start)
    lo, hi = rest_length_bounds(m, bounds)
    tgt = np.asarray(target, dtype=float)
    if tgt.shape != (2,) or not np.all(np.isfinite(tgt)):
        raise InvalidParameterError("target must be two finite numbers (x, y)", field="target")
    sh = None
    pose_error = None
    verify_error = None
    fits = []                                       # inexact least-squares fits: (misfit, result)
    elastic_best = None
    for qs in _starts(m, tgt, start, max_starts):
        # the pose: a stable equilibrium at the target from this start (validates target, load, margin, bounds)
        try:
            pose = preloads_for_pose(m, target, load=load, objective="change", margin=margin, bounds=bounds,
                                     end_angle=end_angle, start=qs)
        except InfeasibleDesignError as exc:
            pose_error = pose_error or exc
            continue
        if sh is None:
            sh = _Shaper(m, tgt, Kd, kb, eb, np.asarray(load, dtype=float), end_angle, margin, lo, hi)
        x0 = sh.start(pose)
        if Kd is None:
            res, el = sh.feasible(x0)
            if el is not None and (elastic_best is None or sh.slack(el.x) < sh.slack(elastic_best.x)):
                elastic_best = el
        else:
            res, exact = sh.fit(x0)
            if res is not None and not exact:
                fits.append((sh.misfit(res.x), res))
                res = None
        if res is not None:                         # the requirement met from this start: verified, or the next
            try:
                return _verified(sh, res)
            except InfeasibleDesignError as exc:
                verify_error = verify_error or exc
    if sh is None:
        raise pose_error
    for _, res in sorted(fits, key=lambda f: f[0]):
        try:
            return _verified(sh, res)
        except InfeasibleDesignError as exc:
            verify_error = verify_error or exc
    if verify_error is not None:
        raise verify_error
    if elastic_best is not None:
        best = sh.best(elastic_best.x)
        best["least_violation"] = float(sh.slack(elastic_best.x) * sh.Ks)
        why = "; ".join(best["violations"])
        msg = (f"no rest lengths within their bounds give this stiffness at a stable pose: the least violation "
               f"of the stiffness bounds found is {best['least_violation']:.6g} (force / length), at "
               f"rest lengths where {why}")
        raise InfeasibleDesignError(msg, status=elastic_best.status, best=best)
    raise InfeasibleDesignError("IPOPT found no rest lengths meeting the stiffness requirement from any start",
                                status="no_start_converged", best=None)


def _verified(sh: _Shaper, res) -> StiffnessDesign:
    """The forward check of an NLP solution, and the result built from the recomputed numbers."""
    m, load, target = sh.m, sh.load, sh.target
    kb, eb, Kd, Ks = sh.kb, sh.eb, sh.Kd, sh.Ks
    best = sh.best(res.x)
    q, L10, L20 = sh.pose(res.x)
    m_new = m.with_segments(s.replace(L0=(l1, l2)) for s, l1, l2 in zip(m.segments, L10, L20))
    eq = forward_check(m_new, load, q, target, settle=False, status=res.status, best=best)
    try:
        K = cartesian_stiffness(m_new, eq)
    except InvalidParameterError as exc:
        raise InfeasibleDesignError(f"verification failed: {exc}", status=res.status, best=best) from exc
    K = 0.5 * (K + K.T)
    viol = _violations(K, kb, eb, Ks)
    if viol:
        raise InfeasibleDesignError("verification failed: at the forward equilibrium " +
                                    "; ".join(v for v, _ in viol), status=res.status, best=best)
    achieved = stability_margin(m_new, eq.q, load)
    if Kd is not None:
        residual = float(np.linalg.norm(K - Kd) / np.linalg.norm(Kd))
        exact = residual <= EXACT_TOL
    else:
        residual = max([0.0] + [a for _, a in _violations(K, kb, eb, 0.0)])
        exact = True
    return StiffnessDesign(manipulator=m_new, rest_lengths=np.column_stack([L10, L20]), q=eq.q, tip=eq.tip, K=K,
                           eigenvalues=np.linalg.eigvalsh(K), margin=achieved, residual=residual, exact=exact,
                           solver=SolverInfo(res.status, res.iterations), load=load.copy(),
                           K_desired=None if Kd is None else Kd.copy(),
                           bounds_K={k: (float(a), float(b)) for k, (a, b) in kb.items()
                                     if math.isfinite(a) or math.isfinite(b)},
                           eig_bounds=None if eb is None else (float(eb[0]), float(eb[1])), equilibrium=eq,
                           active_bounds=rest_length_active_bounds(L10, L20, sh.lo2, sh.hi2))
