"""The least preload (or stiffness) with which a chain holds itself up under its own weight.

A chain in a vertical plane (``Manipulator(..., gravity=)``: its triangles' and payload's weights, its joint forces)
sags; pointing up it may not stand at all (an inverted pendulum: below a stiffness it leans over onto a stop).
:func:`preloads_for_holding` finds the least preload (``vary="L0"``: the rest lengths lengthened, the springs' pull
reduced) or the least stiffness (``vary="k"``) per segment for which the chain rests in a stable equilibrium, its
tip free, every joint within ``max_angle`` of straight, every spring taut (a real spring's law is then the linear
one), with the stability ``margin`` (the smallest eigenvalue of
the Hessian of its potential, torque per radian): the NLP of :mod:`tensegrity_opt.numerics.holding_nlp`, then
verified as every design is:

1. forward: the designed chain's equilibrium from the optimiser's configuration (the closed-range solve under the
   loads, :func:`~..equilibria.equilibrium.solve_equilibrium_under_force`) lands on it, stable, with the margin
   recomputed in numpy;
2. globally: the designed chain's least-potential rest configuration (:func:`~..equilibria.rest.rest_configuration`,
   a measured search) is that pose (status ``"optimal"``); where the chain has a lower rest elsewhere (it would
   fall there if disturbed enough) the design is returned with status ``"metastable"`` and ``success`` False.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from ...errors import InfeasibleDesignError, InvalidParameterError, NoEquilibriumError, TensegrityError
from ...model.loads import describe
from ...model.manipulator import Manipulator
from ...model.springs import SpringFields, Springs, linear_only
from ...numerics import RANGE_SHRINK
from ...numerics.holding_nlp import VARY, holding_nlp
from ...outcome import Outcome, SolverInfo, freeze
from ...serialize import number, numbers
from ...timelimit import time_limit as _time_limit
from ..equilibria.equilibrium import Equilibrium, solve_equilibrium_under_force
from ..equilibria.modes import stiffness_matrix
from ..equilibria.rest import rest_configuration

__all__ = ["HoldingDesign", "HoldingMap", "preloads_for_holding", "holding_map", "SAME_POSE"]

#: The forward solve lands on the designed pose within this (rad, largest joint).
SAME_POSE = 1e-6
#: The design scale's range (``vary="k"``): the stiffness may be divided or multiplied by this much at most.
K_RANGE = 1e3


@dataclass(frozen=True)
class HoldingDesign(Outcome, SpringFields):
    """Result of :func:`preloads_for_holding`.

    Attributes
    ----------
    manipulator : Manipulator
        The designed chain (its loads unchanged).
    vary : str
        ``"L0"`` (the rest lengths) or ``"k"`` (the stiffnesses).
    change : ndarray (n,)
        Per segment: the rest lengths' change (``vary="L0"``, both springs; > 0 lengthens, less preload) or the
        stiffness scale (``vary="k"``, both springs).
    q : ndarray (n,)
        The verified rest configuration under the loads.
    margin : float
        The smallest eigenvalue of the Hessian of the potential there (torque / rad), recomputed.
    tension : float
        The total spring tension of the designed chain when straight, ``sum k (L(0) - L0)`` (the preload).
    stiffness : float
        The total stiffness ``sum (k1 + k2)``.
    equilibrium : Equilibrium
        The verified equilibrium (tip free, the chain's loads).
    solver : SolverInfo
        IPOPT's return status and iterations.
    status : str
        :attr:`STATUSES`.
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "optimal": "IPOPT converged; the designed chain's forward equilibrium lands on the designed pose, stable with "
                   "the margin, and it is the chain's least-potential rest configuration",
        "metastable": "the designed pose is verified stable with the margin, but the designed chain has a rest "
                      "configuration of lower potential elsewhere (it may fall there if disturbed)",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"optimal"})

    manipulator: Manipulator
    vary: str
    change: np.ndarray
    q: np.ndarray
    margin: float
    tension: float
    stiffness: float
    equilibrium: Equilibrium = field(repr=False)
    solver: SolverInfo = field(repr=False)
    status: str = "optimal"

    def __post_init__(self) -> None:
        freeze(self)

    @property
    def springs(self) -> Springs:
        return self.manipulator.springs

    @property
    def message(self) -> str:
        what = "preload (total tension when straight " + f"{self.tension:.6g})" if self.vary == "L0" else \
            f"stiffness (total {self.stiffness:.6g})"
        where = f"largest joint angle {float(np.abs(self.q).max()):.4g} rad, margin {self.margin:.4g}"
        loads = describe(self.equilibrium.loads) or "no dead load"
        floor = ((self.change <= 1.0 / K_RANGE * (1.0 + 1e-6)) if self.vary == "k" else
                 np.zeros(self.change.size, bool))
        if floor.any():
            where += (f"; segments {', '.join(str(i + 1) for i in np.flatnonzero(floor))} at the design's lower bound "
                      f"(k / {K_RANGE:g}: they need no stiffness)")
        if self.status == "optimal":
            return f"the least {what} holding the chain under {loads}: {where} ({self.solver.status})"
        return (f"the least {what} holding the chain under {loads} in a stable pose ({where}), but the designed chain "
                "rests with less potential elsewhere: the pose is metastable")

    def to_dict(self) -> dict[str, Any]:
        """JSON form: ``success``, ``status``, ``message``, ``manipulator`` (the designed chain), ``vary`` (a one-item
        list, as the requests take it),
        ``change``, ``q``, ``margin``, ``tension``, ``stiffness``, ``equilibrium``, ``solver``, the spring state."""
        return {**self.outcome(), **self.spring_dict(), "manipulator": self.manipulator.to_dict(), "vary": [self.vary],
                "change": numbers(self.change), "q": numbers(self.q), "margin": number(self.margin),
                "tension": number(self.tension), "stiffness": number(self.stiffness),
                "equilibrium": self.equilibrium.to_dict(), "solver": self.solver.to_dict()}


def _designed(m: Manipulator, vary: str, s: np.ndarray) -> Manipulator:
    if vary == "k":
        return m.with_segments(seg.replace(k=(seg.k1 * v, seg.k2 * v)) for seg, v in zip(m.segments, s))
    return m.with_segments(seg.replace(L0=(seg.L1_0 + v, seg.L2_0 + v)) for seg, v in zip(m.segments, s))


def _margin(m: Manipulator, q: np.ndarray) -> float:
    """The smallest eigenvalue of the Hessian of ``E + V`` at ``q`` with the tip free (the modes' stiffness matrix,
    numpy: the segments' ``E''`` and the loads')."""
    return float(np.linalg.eigvalsh(stiffness_matrix(m, q, np.zeros(2)))[0])


def preloads_for_holding(m: Manipulator, *, vary: Any = "L0", margin: float = 1e-3, max_angle: float | None = None,
                         timeout: float | None = None) -> HoldingDesign:
    """The least preload (``vary="L0"``) or stiffness (``vary="k"``) per segment with which ``m`` holds itself up
    under its dead loads (module docstring).

    Parameters
    ----------
    m : Manipulator
        The chain with its loads (``gravity`` on its masses and payload, ``joint_forces``); its springs' rest
        lengths and stiffnesses are the design's start and the unchanged part (``vary="k"`` keeps the rest lengths,
        ``"L0"`` the stiffnesses; each segment's two springs change together, keeping its pre-bend).
    vary : {"L0", "k"} or a one-item sequence of it
        What is designed (as the other designs' ``vary``, one variable).
    margin : float
        The required stability margin (>= 0, torque per radian): the smallest eigenvalue of the potential's Hessian.
    max_angle : float, optional
        The sag allowed: every joint within this of straight (rad). Default: anywhere inside the joint range.
    timeout : float, optional
        Seconds.

    Returns
    -------
    HoldingDesign
        ``status`` ``"optimal"`` or ``"metastable"`` (module docstring).

    Raises
    ------
    InvalidParameterError
        (``ValueError``) an unknown ``vary``, a negative ``margin``, a ``max_angle`` not in (0, pi).
    UnsupportedError
        (``ValueError``) a chain with tension-only springs (``field="segments[i].spring"``).
    InfeasibleDesignError
        (``RuntimeError``) IPOPT found no design, or the forward check failed; ``best`` the designed chain where
        there is one.

    Examples
    --------
    >>> import tensegrity_opt as to
    >>> up = to.Manipulator.uniform(6, a=0.04, b=0.05, k=300.0, L0=0.05, mass=0.05, payload=0.1, gravity=(-9.81, 0))
    >>> d = to.preloads_for_holding(up, vary="k", max_angle=0.05)
    >>> d.status, round(float(d.change.max()), 2)          # doctest: +SKIP
    """
    linear_only(m, "preloads_for_holding")
    if isinstance(vary, (list, tuple)) and len(vary) == 1:
        vary = vary[0]                          # the one-item list of the other designs' ``vary``
    if vary not in VARY:
        raise InvalidParameterError(f"vary must be one of {VARY}, got {vary!r}", field="vary")
    mu = float(margin)
    if not math.isfinite(mu) or mu < 0.0:
        raise InvalidParameterError(f"margin must be finite and >= 0, got {margin!r}", field="margin")
    lim = m.joint_limits * (1.0 - RANGE_SHRINK)
    if max_angle is not None:
        a = float(max_angle)
        if not (0.0 < a < math.pi):
            raise InvalidParameterError(f"max_angle must be in (0, pi) rad, got {max_angle!r}", field="max_angle")
        lim = np.minimum(lim, a)
    with _time_limit(timeout):
        return _design(m, vary, mu, lim)


def _design(m: Manipulator, vary: str, mu: float, lim: np.ndarray) -> HoldingDesign:
    n = m.n
    nlp = holding_nlp(n, vary)
    G = m.link_loads
    kk = m.k1 + m.k2
    w = kk / float(kk.sum()) if vary == "k" else -kk / float(kk.sum())
    p = nlp.p.pack(a=m.a, b=m.b, k1=m.k1, k2=m.k2, L10=m.L1_0, L20=m.L2_0, Gx=G[:, 0], Gy=G[:, 1], mu=mu, w=w)
    two_c = 2.0 * np.hypot(m.a, m.b)
    if vary == "k":
        s_lo, s_hi, s0 = np.full(n, 1.0 / K_RANGE), np.full(n, K_RANGE), np.ones(n)
    else:
        shortest = np.minimum(m.L1_0, m.L2_0)
        s_lo = -shortest + 1e-6 * two_c                       # a rest length stays > 0 ...
        s_hi = two_c - np.maximum(m.L1_0, m.L2_0)             # ... and at most the longest a spring gets
        s0 = np.clip(np.zeros(n), s_lo, s_hi)
    try:
        q0 = np.clip(rest_configuration(m).q, -lim, lim)
    except TensegrityError:
        q0 = np.zeros(n)
    starts = [q0] if np.allclose(q0, 0.0) else [q0, np.zeros(n)]
    best, statuses = None, []
    for qs in starts:
        H, _ = (np.asarray(v, float) for v in nlp.hessian(s0, qs, p))
        Hs = H - mu * np.eye(n)
        w_, V_ = np.linalg.eigh(0.5 * (Hs + Hs.T))
        Lc = np.linalg.cholesky(V_ @ np.diag(np.maximum(w_, 1e-8)) @ V_.T)
        x0 = nlp.x.pack(s=s0, q=qs, L=np.array([Lc[i, j] for i in range(n) for j in range(i + 1)]))
        lo_L, hi_L = nlp.factor_floor, np.full(nlp.x["L"].stop - nlp.x["L"].start, np.inf)
        lbx = nlp.x.pack(s=s_lo, q=-lim, L=lo_L)
        ubx = nlp.x.pack(s=s_hi, q=lim, L=hi_L)
        res = nlp.solve(x0, p, lbx, ubx)
        statuses.append(res.status)
        if res.success and (best is None or float(w @ nlp.x.unpack(res.x)["s"]) <
                            float(w @ nlp.x.unpack(best.x)["s"]) - 1e-12):
            best = res
    if best is None:
        raise InfeasibleDesignError(f"IPOPT found no {'stiffness' if vary == 'k' else 'preload'} holding the chain "
                                    f"with the margin {mu:g} within the joints' allowed sag "
                                    f"({', '.join(sorted(set(statuses)))})", status=statuses[-1])
    x = nlp.x.unpack(best.x)
    s, q = np.asarray(x["s"], float), np.asarray(x["q"], float)
    md = _designed(m, vary, s)
    solver = SolverInfo(best.status, best.iterations)
    try:
        eq = solve_equilibrium_under_force(md, 0.0, 0.0, q0=q)
    except NoEquilibriumError as exc:
        raise InfeasibleDesignError(f"the designed chain's forward solve from the designed pose failed: {exc}",
                                    status="forward_check_failed", best=md) from None
    got = _margin(md, eq.q)
    if float(np.abs(eq.q - q).max()) > SAME_POSE or not eq.stable or eq.at_stop.any() or \
            got < mu - 1e-7 * max(1.0, md.torque_scale):
        off = float(np.abs(eq.q - q).max())
        raise InfeasibleDesignError(
            f"the designed chain's forward equilibrium does not check out: it lands {off:.3g} rad from the designed "
            f"pose, stable {eq.stable}, margin {got:.6g} (required {mu:g})",
            status="forward_check_failed", best=md)
    status = "optimal"
    try:
        rest = rest_configuration(md)
        if float(np.abs(rest.q - eq.q).max()) > SAME_POSE and rest.energy < eq.energy - 1e-9 * md.torque_scale:
            status = "metastable"
    except TensegrityError:
        pass
    tension = float(sum(np.sum(f) for f in md.spring_forces(np.zeros(n))))      # the straight chain's springs
    return HoldingDesign(md, vary, s, eq.q.copy(), got, tension, float(np.sum(md.k1 + md.k2)), eq, solver, status)


# ---------------------------------------------------------------------------- over the base's orientation
@dataclass(frozen=True)
class HoldingMap(Outcome):
    """Result of :func:`holding_map`: the chain's sagged shape and the least design holding it, per orientation.

    Attributes
    ----------
    angles : ndarray (K,)
        The gravity vector's angle to the chain's axis (rad; ``pi``: the chain points up, ``-pi/2``: held out
        sideways, ``0``: hanging down).
    gravity : ndarray (K, 2)
        The gravity vectors (the chain's ``|g|`` turned by ``angles``).
    q : ndarray (K, n)
        The rest configuration (least potential, tip free) under each; NaN rows where none was found.
    tip : ndarray (K, 2)
        Its tip.
    sag : ndarray (K,)
        Its largest joint angle (rad).
    stiffness, tension : ndarray (K,)
        The holding design's total stiffness ``sum (k1 + k2)`` and total tension when straight
        (:func:`preloads_for_holding`); NaN where infeasible.
    outcomes : tuple of str
        Per orientation: the design's status (``"optimal"``, ``"metastable"``) or why there is none
        (``"infeasible"``, the error's code).
    vary : str
        ``"k"`` or ``"L0"``.
    max_angle : float or None
    margin : float
    status : str
        ``"complete"`` (every orientation has a rest configuration and a design answer) or ``"partial"``.
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "complete": "every orientation has its rest configuration and its design's answer (a design or "
                    "'infeasible')",
        "partial": "some orientation has no rest configuration or its design failed for another reason (outcomes)",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"complete"})

    angles: np.ndarray
    gravity: np.ndarray
    q: np.ndarray
    tip: np.ndarray
    sag: np.ndarray
    stiffness: np.ndarray
    tension: np.ndarray
    outcomes: tuple[str, ...]
    vary: str
    max_angle: float | None
    margin: float
    status: str = "complete"

    def __post_init__(self) -> None:
        freeze(self)

    @property
    def message(self) -> str:
        held = sum(o in ("optimal", "metastable") for o in self.outcomes)
        return (f"{len(self.outcomes)} orientations: {held} held by a design, "
                f"{sum(o == 'infeasible' for o in self.outcomes)} infeasible, "
                f"{len(self.outcomes) - held - sum(o == 'infeasible' for o in self.outcomes)} without an answer")

    def to_dict(self) -> dict[str, Any]:
        """JSON form: the attributes (NaN as null)."""
        from ...serialize import nullables

        return {**self.outcome(), "angles": numbers(self.angles), "gravity": numbers(self.gravity),
                "q": [nullables(r) for r in self.q], "tip": [nullables(r) for r in self.tip],
                "sag": nullables(self.sag), "stiffness": nullables(self.stiffness), "tension": nullables(self.tension),
                "outcomes": list(self.outcomes), "vary": [self.vary], "max_angle": self.max_angle,
                "margin": number(self.margin)}


def holding_map(m: Manipulator, directions: Any = 12, *, vary: Any = "k", margin: float = 1e-3,
                max_angle: float | None = None, timeout: float | None = None) -> HoldingMap:
    """The chain's sagged shape and the least preload or stiffness holding it, as its base turns in a vertical
    plane: for each orientation the chain ``m`` with its gravity (``|g|`` of ``m.gravity``, 9.81 without) turned
    to the angle, its rest configuration (:func:`~..equilibria.rest.rest_configuration`) and
    :func:`preloads_for_holding` (``vary``, ``margin``, ``max_angle``).

    ``directions``: ``K`` (the angles ``2 pi i / K``) or a sequence of angles (rad) of gravity to the chain's axis
    (as :func:`~.load_capacity.load_capacity`'s ``directions`` of the tip load).
    """
    if isinstance(directions, (int, np.integer)) and not isinstance(directions, bool):
        if directions < 1:
            raise InvalidParameterError(f"directions must be >= 1, got {directions}", field="directions")
        angles = 2 * np.pi * np.arange(int(directions)) / int(directions) - np.pi
    else:
        try:
            angles = np.asarray(directions, dtype=float).ravel()
        except (TypeError, ValueError):
            raise InvalidParameterError("directions must be a count or a list of angles (rad)",
                                        field="directions") from None
        if not angles.size or not np.all(np.isfinite(angles)):
            raise InvalidParameterError("directions must be finite angles (rad)", field="directions")
    if isinstance(vary, (list, tuple)) and len(vary) == 1:
        vary = vary[0]
    if vary not in VARY:
        raise InvalidParameterError(f"vary must be one of {VARY}, got {vary!r}", field="vary")
    g = 9.81 if m.gravity is None else float(np.hypot(*m.gravity))
    K, n = angles.size, m.n
    gravity = g * np.column_stack([np.cos(angles), np.sin(angles)])
    q, tip = np.full((K, n), np.nan), np.full((K, 2), np.nan)
    stiff, tens = np.full(K, np.nan), np.full(K, np.nan)
    outcomes = []
    with _time_limit(timeout):
        for i, gv in enumerate(gravity):
            mi = Manipulator(m.segments, m.payload, tuple(gv), m.joint_forces)
            try:
                rest = rest_configuration(mi)
                q[i], tip[i] = rest.q, rest.tip
            except TensegrityError as exc:
                outcomes.append(exc.code)
                continue
            try:
                d = preloads_for_holding(mi, vary=vary, margin=margin, max_angle=max_angle)
                stiff[i], tens[i] = d.stiffness, d.tension
                outcomes.append(d.status)
            except InfeasibleDesignError:
                outcomes.append("infeasible")
            except TensegrityError as exc:
                outcomes.append(exc.code)
    status = "complete" if all(o in ("optimal", "metastable", "infeasible") for o in outcomes) else "partial"
    return HoldingMap(angles, gravity, q, tip, np.nanmax(np.abs(q), axis=1, initial=0.0) if K else np.zeros(0),
                      stiff, tens, tuple(outcomes), vary, max_angle, float(margin), status)
