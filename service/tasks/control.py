"""Tasks of the design and control requests: the strongest chain, preloads for a load or a pose, rest-length plans,
simulations, force estimates, stiffness shaping, the load capacity of a pose.

The design NLPs (``/v1/design/*``), the plans (their IPOPT fallback is ``preloads_for_pose``) and stiffness
shaping run in a killable solver process; the others in the solver threads. ``deadline`` is the soft
``time.monotonic()`` deadline of :func:`service.api.deps.path_deadline`: the plan, the simulation and the load
capacity stop there and answer what they have (``status: "time_limit"``) instead of a 504.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

import numpy as np

import tensegrity_opt as to
from tensegrity_opt.analyses.design.preload_control import PreloadPlan, plan_preloads
from tensegrity_opt.errors import NonFiniteResult

from .. import schemas as s
from ..adapters.inputs import PRELOAD_OBJECTIVES, build_manipulator, number_or_array, optional_array
from .paths import seconds_left

__all__ = ["design_critical_force_task", "preloads_for_load_task", "preloads_task", "find_plan", "find_simulation",
           "force_estimate_task", "stiffness_design_task", "load_capacity_task", "weight_capacity_task"]


def _best_as_json(exc: to.InfeasibleDesignError) -> to.InfeasibleDesignError:
    """The best point of an infeasible design, made JSON-ready for the error body."""
    best = exc.best
    if isinstance(best, to.Design):
        try:
            exc.best = best.to_dict()
        except NonFiniteResult:
            exc.best = None
    elif isinstance(best, dict):
        exc.best = {k: v for k, v in best.items()}
    return exc


def _infeasible_with_best(task: Callable[..., Any]) -> Callable[..., Any]:
    """``task`` whose :class:`tensegrity_opt.InfeasibleDesignError` carries its best point JSON-ready."""

    @functools.wraps(task)
    def run(*args: Any) -> Any:
        try:
            return task(*args)
        except to.InfeasibleDesignError as exc:
            raise _best_as_json(exc) from None

    return run


def _bounds(b: Any) -> tuple[Any, Any] | None:
    """Rest-length bounds ``[lo, hi]`` (each a number or one per spring) as the library's ``(lo, hi)``."""
    return None if b is None else (number_or_array(b[0]), number_or_array(b[1]))


@_infeasible_with_best
def design_critical_force_task(req: s.DesignCriticalForceRequest) -> Any:
    m = build_manipulator(req.manipulator)
    constraints: dict[str, Any] = {}
    if req.total_length is not None and req.total_length is not False:
        constraints["total_length"] = req.total_length
    if req.tension is not None:
        constraints["tension"] = tuple(req.tension)
    if req.K_min is not None:
        constraints["K_min"] = req.K_min
    return to.maximize_critical_force(m, vary=tuple(dict.fromkeys(req.vary)),
                                      bounds={k: _bounds(v) for k, v in req.bounds.items()},
                                      budget=dict(req.budget), boundary=req.boundary, **constraints)


@_infeasible_with_best
def preloads_for_load_task(req: s.PreloadsForLoadRequest) -> Any:
    m = build_manipulator(req.manipulator)
    d = to.preloads_for_critical_force(m, req.required, boundary=req.boundary,
                                       bounds=_bounds(req.bounds))
    if not d.feasible:
        raise to.InfeasibleDesignError(
            f"no rest lengths within the bounds give a critical load of {req.required:g}: the best achievable "
            f"is {d.load:.6g}", status=d.solver.status, best=d)
    return d


@_infeasible_with_best
def preloads_task(req: s.PreloadsRequest) -> Any:
    m = build_manipulator(req.manipulator)
    return to.preloads_for_pose(m, tuple(req.target), load=tuple(req.load),
                                objective=PRELOAD_OBJECTIVES[req.objective], margin=req.margin, taut=req.taut,
                                bounds=_bounds(req.bounds), end_angle=req.end_angle)


@_infeasible_with_best
def holding_task(req: s.HoldingRequest) -> Any:
    m = build_manipulator(req.manipulator)
    return to.preloads_for_holding(m, vary=req.vary, margin=req.margin, max_angle=req.max_angle)


def find_plan(req: Any, deadline: float) -> PreloadPlan:
    """The plan of a plan request (``/v1/control/plan``, ``/v1/plots/plan``) within the soft ``deadline``."""
    m = build_manipulator(req.manipulator)
    end_angles = None if req.end_angles is None else [np.nan if a is None else a for a in req.end_angles]
    return plan_preloads(m, np.asarray(req.targets, dtype=float), loads=req.loads, end_angles=end_angles,
                         times=optional_array(req.times), dt=req.dt, rest_lengths0=optional_array(req.rest_lengths0),
                         bounds=_bounds(req.bounds), rate_limit=number_or_array(req.rate_limit),
                         margin=req.margin, objective=req.objective, weights=req.weights,
                         start=optional_array(None if req.start is None else req.start.q),
                         on_infeasible=req.on_infeasible, horizon=req.horizon, verify=req.verify,
                         on_snap=req.on_snap, taut=req.taut, timeout=seconds_left(deadline))


def find_simulation(req: Any, deadline: float) -> to.Simulation:
    """The simulation of a simulate request (``/v1/control/simulate``, ``/v1/plots/simulation``) within the soft
    ``deadline``."""
    m = build_manipulator(req.manipulator)
    return to.simulate(m, req.preloads, req.loads, tip=req.tip, targets=req.targets,
                       start=optional_array(None if req.start is None else req.start.q),
                       perturbation=req.perturbation, timeout=seconds_left(deadline))


def force_estimate_task(req: Any) -> Any:
    m = build_manipulator(req.manipulator)
    q = np.array([np.nan if v is None else v for v in req.q_measured], dtype=float)
    measured = None if req.measured is None else (np.asarray(req.measured, dtype=bool)
                                                   if req.measured and isinstance(req.measured[0], bool)
                                                   else np.asarray(req.measured, dtype=int))
    return to.estimate_tip_force(m, q, sigma_q=number_or_array(req.sigma_q), measured=measured)


@_infeasible_with_best
def stiffness_design_task(req: Any) -> Any:
    """``preloads_for_stiffness`` (``/v1/control/stiffness``; the killable solver process, like the design NLPs)."""
    m = build_manipulator(req.manipulator)
    bounds_K = None
    if req.bounds_K is not None:
        bounds_K = {k: tuple(v) for k, v in req.bounds_K.model_dump(exclude_none=True).items()}
    return to.preloads_for_stiffness(m, req.target, K_desired=req.K_desired, bounds_K=bounds_K,
                                     eig_bounds=None if req.eig_bounds is None else tuple(req.eig_bounds),
                                     load=req.load, end_angle=req.end_angle, margin=req.margin,
                                     bounds=_bounds(req.bounds), max_starts=req.max_starts)


def load_capacity_task(req: Any, deadline: float) -> Any:
    """``load_capacity`` (``/v1/control/load-capacity``) within the soft ``deadline``."""
    m = build_manipulator(req.manipulator)
    pose = optional_array(None if req.start is None else req.start.q)
    return to.load_capacity(m, pose, base=req.base, directions=req.directions, boundary=req.boundary,
                            max_load=req.max_load, timeout=seconds_left(deadline))


def weight_capacity_task(req: Any, deadline: float) -> Any:
    """``weight_capacity`` (``/v1/control/weight-capacity``) within the soft ``deadline``."""
    m = build_manipulator(req.manipulator)
    pose = optional_array(None if req.start is None else req.start.q)
    return to.weight_capacity(m, pose, max_factor=req.max_factor, timeout=seconds_left(deadline))
