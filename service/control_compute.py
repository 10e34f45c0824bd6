"""Library calls of the control endpoints (``/v1/control/*`` and their figures) and their JSON bodies.

The tasks of :mod:`service.compute`, for the control layer of the library: :func:`plan_task`
(``preloads_for_trajectory``, run in a killable solver process like ``/v1/design/preloads``: its IPOPT fallback
is ``preloads_for_pose``), :func:`simulate_task` (``simulate``, in the solver threads like the path endpoints) and
:func:`force_estimate_task` (``estimate_tip_force``). Each returns the result's own ``to_dict()``; library
exceptions propagate unchanged and are mapped by :mod:`service.errors`. ``deadline`` is the soft
``time.monotonic()`` deadline of :func:`service.deps.path_deadline`: the plan and the simulation stop there and
answer the steps done (``status: "time_limit"``) instead of a 504.
"""

from __future__ import annotations

from typing import Any

import numpy as np

import tensegrity_opt as to
from tensegrity_opt.analyses.design.preload_control import PreloadPlan, preloads_for_trajectory

from .compute import _best_as_json, _seconds_left, build_manipulator

__all__ = ["PLAN_ALIASES", "SIMULATION_ALIASES", "find_plan", "plan_task", "find_simulation", "simulate_task",
           "force_estimate_task", "stiffness_task", "load_capacity_task"]

#: Library field -> request path (``FieldContext.aliases``): the start is given as ``{"q": [...]}``.
PLAN_ALIASES = (("start", "start.q"), ("q0", "start.q"))
SIMULATION_ALIASES = (("start", "start.q"), ("q0", "start.q"))


def _per_spring(v: Any) -> Any:
    """A number or a list of 2n numbers, as the library takes it."""
    return None if v is None else (np.asarray(v, dtype=float) if isinstance(v, list) else float(v))


def find_plan(req: Any, deadline: float) -> PreloadPlan:
    """The plan of a plan request (``/v1/control/plan``, ``/v1/plots/plan``) within the soft ``deadline``."""
    m = build_manipulator(req.manipulator)
    end_angles = None if req.end_angles is None else [np.nan if a is None else a for a in req.end_angles]
    bounds = None if req.bounds is None else (_per_spring(req.bounds.lo), _per_spring(req.bounds.hi))
    return preloads_for_trajectory(m, np.asarray(req.targets, dtype=float), loads=req.loads, end_angles=end_angles,
                                   bounds=bounds, rate_limit=_per_spring(req.rate_limit), margin=req.margin,
                                   objective=req.objective, weights=req.weights,
                                   start=None if req.start is None else np.asarray(req.start.q, dtype=float),
                                   verify=req.verify, timeout=_seconds_left(deadline))


def plan_task(req: Any, deadline: float) -> dict[str, Any]:
    return find_plan(req, deadline).to_dict()


def find_simulation(req: Any, deadline: float) -> to.Simulation:
    """The simulation of a simulate request (``/v1/control/simulate``, ``/v1/plots/simulation``) within the soft
    ``deadline``."""
    m = build_manipulator(req.manipulator)
    return to.simulate(m, req.preloads, req.loads, tip=req.tip, targets=req.targets,
                       start=None if req.start is None else np.asarray(req.start.q, dtype=float),
                       perturbation=req.perturbation, timeout=_seconds_left(deadline))


def simulate_task(req: Any, deadline: float) -> dict[str, Any]:
    return find_simulation(req, deadline).to_dict()


def _sigma(v: Any) -> Any:
    return None if v is None else (np.asarray(v, dtype=float) if isinstance(v, list) else float(v))


def force_estimate_task(req: Any) -> dict[str, Any]:
    m = build_manipulator(req.manipulator)
    q = np.array([np.nan if v is None else v for v in req.q_measured], dtype=float)
    measured = None if req.measured is None else (np.asarray(req.measured, dtype=bool)
                                                   if req.measured and isinstance(req.measured[0], bool)
                                                   else np.asarray(req.measured, dtype=int))
    return to.estimate_tip_force(m, q, sigma_q=_sigma(req.sigma_q), measured=measured).to_dict()


def stiffness_task(req: Any) -> dict[str, Any]:
    """``preloads_for_stiffness`` (``/v1/control/stiffness``; the killable solver process, like the design NLPs)."""
    m = build_manipulator(req.manipulator)
    bounds_K = None
    if req.bounds_K is not None:
        bounds_K = {k: tuple(v) for k, v in req.bounds_K.model_dump(exclude_none=True).items()}
    bounds = None if req.bounds is None else (_per_spring(req.bounds.lo), _per_spring(req.bounds.hi))
    try:
        d = to.preloads_for_stiffness(m, req.target, K_desired=req.K_desired, bounds_K=bounds_K,
                                      eig_bounds=None if req.eig_bounds is None else tuple(req.eig_bounds),
                                      load=req.load, end_angle=req.end_angle, margin=req.margin, bounds=bounds,
                                      max_starts=req.max_starts)
    except to.InfeasibleDesignError as exc:
        raise _best_as_json(exc) from None
    return d.to_dict()


def load_capacity_task(req: Any, deadline: float) -> dict[str, Any]:
    """``load_capacity`` (``/v1/control/load-capacity``) within the soft ``deadline``."""
    m = build_manipulator(req.manipulator)
    pose = None if req.start is None else np.asarray(req.start.q, dtype=float)
    return to.load_capacity(m, pose, base=req.base, directions=req.directions, boundary=req.boundary,
                            max_load=req.max_load, timeout=_seconds_left(deadline)).to_dict()
