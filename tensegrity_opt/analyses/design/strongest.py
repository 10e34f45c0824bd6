"""The strongest chain: per-segment design variables maximising the critical load of the straight chain.

:func:`maximize_critical_force` is a CasADi NLP solved by IPOPT with exact derivatives
(:func:`tensegrity_opt.numerics.buckling_design_nlp`): the critical load ``P`` as a variable, the
positive semidefiniteness of ``Z^T (K - P G) Z`` by a Cholesky factor. :func:`buckling_design` is the problem
behind it, shared with :func:`~tensegrity_opt.analyses.design.preloads.preloads_for_critical_force` (the least
change of the rest lengths reaching a required load). Every :class:`Design` is verified by an independent
forward computation (:func:`~tensegrity_opt.analyses.equilibria.buckling.critical_force` on the returned chain)
before it is returned. Formulations and worked examples: ``docs/design.md``.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np
import scipy.linalg as sla

from ...bounds import bound_pair
from ...errors import (
    InfeasibleDesignError,
    InvalidParameterError,
    SolverError,
    StraightNotEquilibriumError,
    TensegrityError,
)
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...model.segment import Segment
from ...model.springs import linear_only
from ...outcome import Outcome, SolverInfo, freeze
from ...serialize import nullable, number, numbers
from ...timelimit import time_limit as _time_limit
from ..equilibria.buckling import critical_force, straight_matrices

__all__ = ["Design", "maximize_critical_force", "buckling_design", "DESIGN_VARIABLES", "K_FLOOR_REL"]

#: Per-segment design variables of the buckling design problem (symmetric segments).
DESIGN_VARIABLES = ("a", "b", "k", "L0")
#: Default floor on every joint stiffness in the buckling design problems, relative to the initial
#: chain's stiffness scale ``max_i k_i (a_i^2 + b_i^2)``: condition (4) is ``K_i > 0`` (strict), so
#: the design problem imposes ``K_i >= K_FLOOR_REL * scale``. An optimum that wants ``K_i -> 0+``
#: is returned with that segment on the floor.
K_FLOOR_REL = 1e-9
_INF = float("inf")


@dataclass(frozen=True)
class Design(Outcome):
    """Result of :func:`maximize_critical_force` and
    :func:`~tensegrity_opt.analyses.design.preloads.preloads_for_critical_force`.

    Attributes
    ----------
    manipulator : Manipulator
        The optimised chain.
    critical_force : float
        Signed critical force ``-min(loads)``, recomputed by :func:`critical_force` on it.
    loads : ndarray
        All its critical loads (ascending), recomputed.
    multiplicity : int
        How many critical loads coincide with the smallest (relative gap < 1e-4).
    active : tuple of str
        Active constraints at the optimum (bounds, budgets, tension, stiffness rows).
    solver : SolverInfo
        IPOPT's return status and iterations.
    boundary : str
        ``"guided"`` or ``"free"``.
    initial_critical_force : float
        The starting design's critical force (NaN when undefined there).
    feasible : bool
        ``preloads_for_critical_force``: whether the required load is reached.
    K_min : float
        The joint-stiffness floor the design was held to: ``max(K_min, K_FLOOR_REL * scale)``
        with ``scale = max_i k_i (a_i^2 + b_i^2)`` of the initial chain (the default floor when
        no ``K_min`` was given). Every returned segment has ``K_i > 0`` and ``K_i >= K_min``
        (exactly: a segment the optimiser stopped a roundoff below is lifted onto it by a varied
        ``L0``, ``k``, ``a`` or ``b``; otherwise to the solver's tolerance).
    status : str
        One of :attr:`STATUSES`: ``"optimal"`` for every design returned by :func:`maximize_critical_force`;
        ``"below_required"`` for the strongest design returned when no rest lengths reach the required load;
        ``"infeasible"`` only for the last point of a failed solve (``InfeasibleDesignError.best``).
    message : str
        The same in a sentence, with the critical load.
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "optimal": "IPOPT converged to a design meeting every constraint (and the required load, where one is "
                   "asked); its critical load is recomputed by critical_force",
        "below_required": "the strongest design within the bounds, whose critical load stays below the required one",
        "infeasible": "IPOPT found no feasible design: its last point, lifted onto the joint-stiffness floor",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"optimal"})

    manipulator: Manipulator
    critical_force: float
    loads: np.ndarray
    multiplicity: int
    active: tuple[str, ...]
    solver: SolverInfo
    boundary: str
    initial_critical_force: float
    feasible: bool = True
    K_min: float = math.nan
    status: str = "optimal"

    def __post_init__(self) -> None:
        freeze(self)

    @property
    def load(self) -> float:
        """The critical compressive load ``-critical_force``."""
        return -self.critical_force

    @property
    def message(self) -> str:
        """A sentence: what the design reaches and how IPOPT ended."""
        ipopt = f"IPOPT {self.solver.status}, {self.solver.iterations} iterations"
        if self.status == "optimal":
            return f"optimal design: critical load {self.load:.6g}, recomputed by critical_force ({ipopt})"
        if self.status == "below_required":
            return (f"no design within the bounds reaches the required load: the strongest has a critical load of "
                    f"{self.load:.6g} ({ipopt})")
        return f"no feasible design found: the last point has a critical load of {self.load:.6g} ({ipopt})"

    def to_dict(self) -> dict[str, Any]:
        """JSON form (the body of ``POST /v1/design/critical-force`` and ``/v1/design/preloads-for-load``):
        ``success``, ``status``, ``message``, ``manipulator`` (:meth:`Manipulator.to_dict`), ``critical_force``,
        ``loads``, ``multiplicity``, ``active``, ``initial_critical_force`` (``null`` when undefined), ``feasible``,
        ``solver`` ``{status, iterations}``."""
        return {**self.outcome(), "manipulator": self.manipulator.to_dict(),
                "critical_force": number(self.critical_force), "loads": numbers(self.loads),
                "multiplicity": int(self.multiplicity), "active": list(self.active),
                "initial_critical_force": nullable(self.initial_critical_force), "feasible": bool(self.feasible),
                "solver": self.solver.to_dict()}


# --------------------------------------------------------------------------- helpers
def _per_segment(value, n: int, field_name: str) -> np.ndarray:
    arr = np.asarray(value, dtype=float)
    if arr.ndim == 0:
        arr = np.full(n, float(arr))
    if arr.shape != (n,) or not np.all(np.isfinite(arr)):
        raise InvalidParameterError(f"{field_name} must be a number or {n} finite numbers", field=field_name)
    return arr


def _symmetric_columns(m: Manipulator) -> dict[str, np.ndarray]:
    bad = [i for i, s in enumerate(m.segments) if not s.symmetric]
    if bad:
        raise StraightNotEquilibriumError(
            f"buckling design needs symmetric segments (k1 == k2, L1_0 == L2_0); segment {bad[0]} is not",
            field=f"segments[{bad[0]}]")
    return {"a": m.a.copy(), "b": m.b.copy(), "k": m.k1.copy(), "L0": m.L1_0.copy()}


def _build(cols: Mapping[str, np.ndarray], like: Manipulator) -> Manipulator:
    """The chain of the design columns, with ``like``'s masses and payload (a design changes the geometry and the
    springs, not what the arm carries)."""
    return like.with_segments(Segment(a, b, k, L0, mass=s.mass, inertia=s.inertia)
                              for a, b, k, L0, s in zip(cols["a"], cols["b"], cols["k"], cols["L0"], like.segments))


def _invalid_design(m: Manipulator, boundary: str, vary: Iterable[str], exc: TensegrityError,
                    status: str) -> InfeasibleDesignError:
    """The refusal of a design that is not a valid chain, saying whose fault it is: the input chain's, when it is
    not valid itself (then ``field`` names its culprit), else the optimiser's."""
    try:
        critical_force(m, boundary)
    except TensegrityError as given:
        return InfeasibleDesignError(
            f"the input chain is not a valid chain, and varying {', '.join(vary)} within the bounds did not make "
            f"it one: {given}", field=given.field, status=status)
    return InfeasibleDesignError(f"the optimiser's design is not a valid chain (the input chain is): {exc}",
                                 status=status)


def _multiplicity(loads: np.ndarray, rel: float = 1e-4) -> int:
    return int(np.sum(loads <= loads[0] * (1.0 + rel)))


def _safe_critical(m: Manipulator, boundary: str) -> float:
    try:
        return critical_force(m, boundary).force
    except TensegrityError:
        return float("nan")


# --------------------------------------------------------------------------- the strongest chain
def maximize_critical_force(m: Manipulator, vary: Iterable[str] = ("k",),
                            bounds: Mapping[str, tuple] | None = None,
                            budget: Mapping[str, float] | None = None, boundary: str = "guided", *,
                            timeout: float | None = None, **constraints) -> Design:
    """Maximise the critical load of the straight chain over per-segment design variables.

    Parameters
    ----------
    m : Manipulator
        The initial design (symmetric segments); what is not varied stays fixed.
    vary : iterable of {"a", "b", "k", "L0"}
        The per-segment variables to optimise.
    bounds : dict, optional
        ``{name: (lo, hi)}`` (or ``{name: {"lo": lo, "hi": hi}}``, :func:`tensegrity_opt.bounds.bound_pair`)
        with numbers or per-segment arrays. Default for a varied variable: ``(x0 / 10, 10 x0)``.
    budget : dict, optional
        ``{name: total}``: ``sum(name) <= total`` over the segments.
    boundary : {"guided", "free"}
    **constraints
        ``total_length`` (float, or ``True`` to keep the initial ``2 sum(b)``),
        ``tension=(T_min, T_max)`` (or ``{"lo", "hi"}``) bounds on the spring preload ``k (2b - L0)`` at straight,
        ``K_min`` a lower bound on every joint stiffness ``K_i = k (b L0 - 2 (b^2 - a^2))``.
        Condition (4), ``K_i > 0``, is always imposed: as ``K_i >= K_min`` with ``K_min`` raised
        to at least the floor ``K_FLOOR_REL * max_i k_i (a_i^2 + b_i^2)`` (``1e-9`` times the
        initial chain's stiffness scale); without ``K_min`` the floor alone. An optimum at
        ``K_i -> 0+`` (stiffness and preload moved off a segment) is returned with ``K_i`` on the
        floor; the bound used is recorded in ``Design.K_min`` and listed in ``active`` when it holds.
    timeout : float, optional
        Seconds this call may take (see :func:`tensegrity_opt.time_limit`, which bounds any block of
        calls): checked before and, once per IPOPT iteration, during each solve.

    Returns
    -------
    Design
        ``status="optimal"``. Verified: ``critical_force`` is recomputed by :func:`critical_force` on the returned
        chain. A segment the optimiser left below ``K_min`` by roundoff is lifted onto it
        (the smallest change of one varied variable) before that check.

    Raises
    ------
    InvalidParameterError
        Unknown variable/constraint, bad bounds.
    InfeasibleDesignError
        (``RuntimeError``) IPOPT found no feasible design; ``best`` holds its last point
        (a :class:`Design` with ``status="infeasible"``, lifted onto ``K_i >= K_min``) when that is a valid chain.
    TimeLimitError
        (``RuntimeError``, ``code = "timeout"``) the time limit was reached, or IPOPT stopped at its
        own ``max_wall_time`` (``status = "Maximum_WallTime_Exceeded"``): no result.
    """
    unloaded_only(m, "maximize_critical_force")
    linear_only(m, "maximize_critical_force")
    with _time_limit(timeout):
        return buckling_design(m, vary, bounds, budget, boundary, constraints, required=None)


def _tension_bounds(tension) -> tuple[float, float]:
    """``(T_min, T_max)`` from the ``tension`` constraint (``None``: unbounded), checked before any solve."""
    if tension is None:
        return -_INF, _INF
    try:
        tmin, tmax = (float(v) for v in bound_pair(tension, "tension"))
    except InvalidParameterError:
        raise                                # bound_pair's own words (an unknown key, lo or hi missing)
    except (TypeError, ValueError):
        raise InvalidParameterError("tension must be a pair (T_min, T_max) of numbers", field="tension") from None
    if math.isnan(tmin) or math.isnan(tmax) or tmin > tmax or tmin == _INF or tmax == -_INF:
        raise InvalidParameterError(f"tension bounds need T_min <= T_max (got {tmin:g}, {tmax:g})", field="tension")
    return tmin, tmax


def buckling_design(m: Manipulator, vary: Iterable[str], bounds: Mapping | None, budget: Mapping | None,
                    boundary: str, constraints: Mapping[str, Any], required: float | None) -> Design:
    """The buckling design problem behind :func:`maximize_critical_force` (``required=None``: maximise the
    critical load) and :func:`~tensegrity_opt.analyses.design.preloads.preloads_for_critical_force`
    (``required``: the least change of the varied rest lengths with a critical load of at least ``required``).
    Arguments as :func:`maximize_critical_force` (``constraints`` its keyword constraints); raises as it does,
    and :class:`InfeasibleDesignError` (``best`` the design, ``status="below_required"``) when the verified load
    stays below ``required``. Runs under the caller's time limit."""
    from ...numerics import buckling_design_nlp
    from ...numerics.design_nlp import tril_vector

    if boundary not in ("guided", "free"):
        raise InvalidParameterError(f"boundary must be 'guided' or 'free', got {boundary!r}", field="boundary")
    if boundary == "guided" and m.n < 2:
        raise InvalidParameterError("a guided tip needs n >= 2 segments", field="n")
    vary = tuple(vary)
    for v in vary:
        if v not in DESIGN_VARIABLES:
            raise InvalidParameterError(f"cannot vary {v!r}: choose from {DESIGN_VARIABLES}", field="vary")
    unknown = set(constraints) - {"total_length", "tension", "K_min"}
    if unknown:
        raise InvalidParameterError(f"unknown constraint(s) {sorted(unknown)}: use total_length, tension, K_min",
                                    field=sorted(unknown)[0])
    _tension_bounds(constraints.get("tension"))
    bounds = dict(bounds or {})
    budget = dict(budget or {})
    for name in list(bounds) + list(budget):
        if name not in DESIGN_VARIABLES:
            raise InvalidParameterError(f"unknown design variable {name!r}", field=name)
    n = m.n
    x0 = _symmetric_columns(m)
    lo, hi = {}, {}
    for name in DESIGN_VARIABLES:
        if name in vary:
            blo, bhi = bound_pair(bounds.get(name, (x0[name] / 10.0, x0[name] * 10.0)), f"bounds.{name}")
            lo[name] = _per_segment(blo, n, f"bounds.{name}")
            hi[name] = _per_segment(bhi, n, f"bounds.{name}")
            if np.any(lo[name] <= 0) or np.any(hi[name] < lo[name]):
                raise InvalidParameterError(f"bounds for {name} need 0 < lo <= hi", field=f"bounds.{name}")
        else:
            lo[name] = hi[name] = x0[name]
    start = {name: np.clip(x0[name], lo[name], hi[name]) for name in DESIGN_VARIABLES}
    # Start inside the budgets: scale a varied variable down to its budget.
    for name, total in budget.items():
        total = float(total)
        if not math.isfinite(total) or total <= 0:
            raise InvalidParameterError(f"budget for {name} must be positive and finite", field=f"budget.{name}")
        if start[name].sum() > total:
            start[name] = np.maximum(start[name] * total / start[name].sum(), lo[name])
    nlp = buckling_design_nlp(n, boundary == "guided")
    # Initial load and Cholesky factor.
    m_start = _build(start, m)
    K, G, S0 = straight_matrices(m_start)
    Z = _basis(S0, boundary == "guided", n)
    if required is None:
        try:
            P0 = 0.5 * float(sla.eigh(Z.T @ np.diag(K) @ Z, Z.T @ G @ Z, eigvals_only=True)[0])
        except (np.linalg.LinAlgError, ValueError):
            P0 = 0.0
        P0 = max(P0, 0.0)
    else:
        P0 = required
    Mz = Z.T @ (np.diag(K) - P0 * G) @ Z
    w_, V_ = np.linalg.eigh(Mz)
    Lc = np.linalg.cholesky(V_ @ np.diag(np.maximum(w_, 1e-6 * max(1.0, abs(w_).max()))) @ V_.T)
    x, g = nlp.variables, nlp.constraints
    xv0 = x.pack(**start, P=P0, L=tril_vector(Lc))
    lbx = x.pack(**lo, P=required if required is not None else 0.0, L=nlp.factor_floor)
    ubx = x.pack(**hi, P=_INF, L=_INF)
    tl = constraints.get("total_length")
    if tl is True:
        tl = m.straight_length
    tmin, tmax = _tension_bounds(constraints.get("tension"))
    kmin = _stiffness_floor(x0, constraints.get("K_min"))
    budgets = {f"budget_{name}": float(budget[name]) if name in budget else _INF for name in DESIGN_VARIABLES}
    lbg_a = g.pack(psd=0.0, **dict.fromkeys(budgets, -_INF), length=float(tl) if tl is not None else -_INF,
                   tension=float(tmin), K=kmin)
    ubg_a = g.pack(psd=0.0, **budgets, length=float(tl) if tl is not None else _INF, tension=float(tmax), K=_INF)
    weights = [1.0, 0.0] if required is None else [0.0, 1.0]
    p = nlp.parameters.pack(L0nom=x0["L0"], w=weights)
    res = nlp.solve(xv0, lbx, ubx, lbg_a, ubg_a, p)
    v = x.unpack(res.x)
    cols = {name: v[name].copy() for name in DESIGN_VARIABLES}
    for name in DESIGN_VARIABLES:          # IPOPT may step 1e-8 outside a bound: snap back
        cols[name] = np.clip(cols[name], lo[name], hi[name])
    # IPOPT honours the K rows only to its (relaxed) tolerance: K_i = K_min - 1e-9 is a normal
    # answer when the optimum sits on the floor. Lift such segments onto K_i = K_min (a roundoff-
    # sized change of one varied variable), then re-check every row and recompute the load there.
    # After a failed solve any lift is allowed: it makes the reported ``best`` a valid chain.
    _lift_stiffness(cols, lo, hi, vary, kmin, max_rel=1e-6 if res.success else _INF)
    xv = res.x.copy()
    for name in DESIGN_VARIABLES:
        xv[x[name]] = cols[name]
    P_opt = float(v["P"])
    try:
        m_opt = _build(cols, m)
        bk = critical_force(m_opt, boundary)
    except TensegrityError as exc:
        raise _invalid_design(m, boundary, vary, exc, res.status) from exc
    rows = nlp.rows(xv)
    viol = max(float(np.max(lbg_a - rows, initial=0.0)), float(np.max(rows - ubg_a, initial=0.0)))
    solved = res.success and viol <= 1e-6
    feasible = required is None or bk.loads[0] >= required * (1 - 1e-6)
    design = Design(manipulator=m_opt, critical_force=bk.force, loads=bk.loads,
                    multiplicity=_multiplicity(bk.loads),
                    active=_active(cols, lo, hi, vary, budget, g.unpack(rows), n, tl, tmin, tmax, kmin),
                    solver=SolverInfo(res.status, res.iterations), boundary=boundary,
                    initial_critical_force=_safe_critical(m, boundary), feasible=feasible, K_min=kmin,
                    status="infeasible" if not solved else "optimal" if feasible else "below_required")
    if not solved:
        raise InfeasibleDesignError(
            f"IPOPT did not find a feasible design ({res.status}); constraint violation {viol:.3g}",
            status=res.status, best=design)
    # Independent check: the recomputed critical load is the optimiser's P (to its tolerance).
    if required is None and abs(bk.loads[0] - P_opt) > 1e-5 * max(1.0, P_opt):
        raise SolverError(f"verification failed: optimiser's load {P_opt:.8g} but critical_force gives "
                          f"{bk.loads[0]:.8g}", status=res.status)
    if required is not None and not design.feasible:
        raise InfeasibleDesignError(f"the design reaches only {bk.loads[0]:.6g} < required {required:.6g}",
                                    status=res.status, best=design)
    return design


def _stiffness_floor(x0: Mapping[str, np.ndarray], K_min) -> float:
    """The joint-stiffness bound of the design problem: ``K_min`` raised to the floor (condition (4))."""
    scale = float(np.max(x0["k"] * (x0["a"] ** 2 + x0["b"] ** 2)))
    floor = K_FLOOR_REL * scale
    if K_min is None:
        return floor
    try:
        K_min = float(K_min)
    except (TypeError, ValueError):
        raise InvalidParameterError("K_min must be a finite number", field="K_min") from None
    if not math.isfinite(K_min):
        raise InvalidParameterError("K_min must be a finite number", field="K_min")
    return max(K_min, floor)


def _joint_stiffness(a, b, k, L0) -> float:
    """``K = E''(0)`` evaluated as the library does (:attr:`Segment.stiffness`, the quantity
    :func:`critical_force` checks), not the closed form: the two differ by roundoff."""
    return Segment(a, b, k, L0).stiffness


def _lift_stiffness(cols: dict[str, np.ndarray], lo, hi, vary, kmin: float, max_rel: float = _INF) -> list[int]:
    """Put every segment with ``K_i < kmin`` onto ``K_i = kmin`` (in place) by changing one varied
    variable: the smallest relative change among ``L0``, ``k``, ``a`` that stays within its bounds
    and ``max_rel``, else ``b`` (which also moves the chain's geometry; the caller re-checks every
    row). Returns the segments changed. A segment no single variable can lift so is left as it is."""
    changed = []
    for i in range(cols["k"].size):
        a, b, k, L0 = (float(cols[nm][i]) for nm in DESIGN_VARIABLES)
        if _joint_stiffness(a, b, k, L0) >= kmin:
            continue
        cands = []
        if "L0" in vary:
            cands.append(("L0", (kmin / k + 2.0 * (b * b - a * a)) / b))
        if "k" in vary and b * L0 - 2.0 * (b * b - a * a) > 0:
            cands.append(("k", kmin / (b * L0 - 2.0 * (b * b - a * a))))
        if "a" in vary:
            s = b * b - (b * L0 - kmin / k) / 2.0
            if s > 0:
                cands.append(("a", math.sqrt(s)))
        if "b" in vary:                         # K >= kmin  <=>  2 b^2 - L0 b - (2 a^2 - kmin / k) <= 0
            disc = L0 * L0 + 8.0 * (2.0 * a * a - kmin / k)
            if disc >= 0:
                ends = ((L0 - math.sqrt(disc)) / 4.0, (L0 + math.sqrt(disc)) / 4.0)
                cands.append(("b", min((e for e in ends if e > 0), key=lambda e: abs(e - b), default=-1.0)))
        best = None
        for name, x in cands:
            if not x > 0:
                continue
            vals = {"a": a, "b": b, "k": k, "L0": L0}
            step = _INF if name != "b" or x >= b else -_INF     # the side on which K grows
            for _ in range(64):                 # nudge until K >= kmin holds in floating point
                vals[name] = x
                if _joint_stiffness(vals["a"], vals["b"], vals["k"], vals["L0"]) >= kmin:
                    break
                x = float(np.nextafter(x, step))
            else:
                continue
            if not lo[name][i] <= x <= hi[name][i]:
                continue
            rel = abs(x - float(cols[name][i])) / abs(float(cols[name][i]))
            if rel > max_rel:
                continue
            key = (name == "b", rel)
            if best is None or key < best[0]:
                best = (key, name, x)
        if best is not None:
            cols[best[1]][i] = best[2]
            changed.append(i)
    return changed


def _basis(S0: np.ndarray, guided: bool, n: int) -> np.ndarray:
    if not guided:
        return np.eye(n)
    return np.vstack([np.eye(n - 1), -S0[None, : n - 1] / S0[n - 1]])


def _active(cols, lo, hi, vary, budget, rows, n, tl, tmin, tmax, kmin, tol=1e-6) -> list[str]:
    """The active constraints at the design ``cols``: bounds, budgets, total length, tension and stiffness rows
    (``rows`` the NLP's constraint rows by name)."""
    act = []
    for name in vary:
        for i in range(n):
            x = cols[name][i]
            scale = max(1.0, abs(x))
            if x <= lo[name][i] + tol * scale:
                act.append(f"{name}[{i}] >= {lo[name][i]:.6g}")
            elif x >= hi[name][i] - tol * scale:
                act.append(f"{name}[{i}] <= {hi[name][i]:.6g}")
    for name in DESIGN_VARIABLES:
        if name in budget and rows[f"budget_{name}"] >= float(budget[name]) - tol * max(1.0, abs(float(budget[name]))):
            act.append(f"sum({name}) <= {float(budget[name]):.6g}")
    if tl is not None:
        act.append(f"2 sum(b) == {float(tl):.6g}")
    ten, K = rows["tension"], rows["K"]
    for i in range(n):
        if math.isfinite(tmin) and ten[i] <= tmin + tol * max(1.0, abs(tmin)):
            act.append(f"tension[{i}] >= {tmin:.6g}")
        if math.isfinite(tmax) and ten[i] >= tmax - tol * max(1.0, abs(tmax)):
            act.append(f"tension[{i}] <= {tmax:.6g}")
        if K[i] <= kmin + tol * max(1.0, abs(kmin)):
            act.append(f"K[{i}] >= {kmin:.6g}")
    return act
