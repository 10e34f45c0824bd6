"""Control: rest-length plans for tip trajectories, quasi-static simulation with snaps, the arm as a force sensor.

``POST /v1/control/plan`` (``plan_preloads``; in a killable solver process, as ``/v1/design/preloads``:
its IPOPT fallback is ``preloads_for_pose``), ``POST /v1/control/simulate`` (``simulate``; in the solver threads, as
the path endpoints) and ``POST /v1/control/force-estimate`` (``estimate_tip_force``). The figures of the first two are
``POST /v1/plots/plan`` and ``POST /v1/plots/simulation`` (:mod:`.plots`).
"""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import APIRouter, Body, Request

from ... import examples as ex
from ... import schemas as s
from ...adapters.fields import LOAD_CAPACITY_ALIASES
from ...tasks.control import (
    find_plan,
    find_simulation,
    force_estimate_task,
    load_capacity_task,
    stiffness_design_task,
    weight_capacity_task,
)
from ..deps import SettingsDep, check_manipulator, check_plan, check_simulation, path_deadline, placement, steps_field
from ..dispatch import Placement, run_task
from ..json_bodies import JSONBodyRoute
from ..openapi import PLAN_LIMITS, SIMULATION_LIMITS, solve_responses

__all__ = ["router"]

router = APIRouter(route_class=JSONBodyRoute, prefix="/v1/control", tags=["control"])

_M = ex.PAPER_CHAIN

@router.post(
    "/plan", operation_id="control_plan", response_model=s.PlanOut,
    summary="Rest lengths for a trajectory of tip positions, on one stable branch",
    description="Per step the springs' rest lengths `(L1_0, L2_0)` putting the tip at the target, stable with "
                "`margin` under the dead tip load, inside `bounds` and within `rate_limit` (length per second) times "
                "the time since the previous step (`times`, or a fixed `dt`; the start, with the arm's current "
                "rest lengths `rest_lengths0`, is the state at time 0) "
                "(`tensegrity_opt.plan_preloads`): `objective: change` is the least change "
                "from the previous step (a compiled Newton step on its KKT system, warm-started; IPOPT where a bound "
                "is active), `margin` / `energy` IPOPT (`preloads_for_pose`). A step no admissible rest lengths reach "
                "is `feasible: false` with the best reachable pose, and the next step starts from the last feasible "
                "state (`status: \"infeasible_steps\"`). `verified`: the forward quasi-static solve from the "
                "previous step's configuration with the step's rest lengths lands on the target, stable. "
                "`end_angles` (optional, null entries free) fix the last link's absolute angle. " + PLAN_LIMITS,
    responses=solve_responses(ex.PLAN, "too_many_steps", "response_too_large"))
async def control_plan(
    request: Request,
    req: Annotated[s.PlanRequest, Body(openapi_examples={
        "arc": {"summary": "the paper's chain, the tip along a short arc under a small load",
                "value": s.PLAN_REQUEST_EXAMPLE},
        "rate_limited": {"summary": "a line of targets every 0.5 s, a rate limit (length / s), a margin and bounds",
                         "value": {
            "manipulator": _M, "targets": [[7.9, 0.2], [7.85, 0.4], [7.8, 0.6], [7.7, 0.8]], "rate_limit": 0.1,
            "dt": 0.5, "bounds": {"lo": 0.5, "hi": 2.0}, "margin": 0.05}},
        "end_angles": {"summary": "the last link kept level (end angle 0) along a vertical line", "value": {
            "manipulator": _M, "targets": [[7.8, 0.3], [7.8, 0.6], [7.8, 0.9]], "end_angles": [0.0, 0.0, None]}}})],
    settings: SettingsDep,
) -> Any:
    ctx = check_plan(req, settings)
    return await run_task(request, find_plan, req, path_deadline(settings), fields=ctx, placement=Placement.KILLABLE,
                          size_field="targets")


@router.post(
    "/simulate", operation_id="control_simulate", response_model=s.SimulationOut,
    summary="Quasi-static simulation under sampled inputs, with the snaps at folds",
    description="The chain driven by time series of its inputs over samples `k = 0 .. K-1` "
                "(`tensegrity_opt.simulate`): the rest lengths `preloads` (K, n, 2) (default the chain's own), and "
                "a dead tip load `loads` (K, 2) (`tip: free`, default zero) or a tip deflection `targets` (K, 2) "
                "(`tip: held`, required). Between samples the inputs move linearly and the configuration follows "
                "its branch by continuation; where the branch loses stability (a fold, or a branch point) the arm "
                "snaps: the new state is reached by the gradient flow from there (an overdamped arm), each snap an "
                "event with the fold and landing configurations and the energy released. It ends early at a joint's "
                "range bound (`joint_limit`) or the workspace edge, keeping the samples done. " + SIMULATION_LIMITS,
    responses=solve_responses(ex.SIMULATION, "too_many_steps", "continuation_too_long", "bad_start",
                              "unreachable_target", "response_too_large"))
async def control_simulate(
    request: Request,
    req: Annotated[s.SimulationRequest, Body(openapi_examples={
        "load_cycle": {"summary": "a load cycle along y on three bistable segments: two snaps (hysteresis)",
                       "value": s.SIMULATION_REQUEST_EXAMPLE},
        "held": {"summary": "the tip of the paper's chain held and pushed in along x", "value": {
            "manipulator": _M, "tip": "held", "targets": [[0.1, 0.0], [0.3, 0.0], [0.5, 0.0], [0.7, 0.0]]}},
        "preloads": {"summary": "the rest lengths of the first bistable segment tilted (1 + d, 1 - d), no load",
                     "value": {"manipulator": s.BISTABLE_CHAIN, "preloads": [
                         [[1.0 + d, 1.0 - d], [1.0, 1.0], [1.0, 1.0]] for d in (0.0, 0.1, 0.2, 0.3, 0.4)]}}})],
    settings: SettingsDep,
) -> Any:
    ctx = check_simulation(req, settings)
    return await run_task(request, find_simulation, req, path_deadline(settings), fields=ctx,
                          placement=Placement.HEAVY, size_field=steps_field(req))


@router.post(
    "/force-estimate", operation_id="control_force_estimate", response_model=s.ForceEstimateOut,
    summary="The tip force from measured joint angles (the arm as a force sensor)",
    description="At a static equilibrium under a tip force only, the spring torques balance it: `grad E(q) = J(q)^T "
                "F` (`tensegrity_opt.estimate_tip_force`). `F` by least squares on these `n` equations; with "
                "`sigma_q` (the angle noise: one standard deviation, one per joint, or a covariance) by generalised "
                "least squares with the residual's covariance at the estimate, with the force's `covariance`, the "
                "chi-square test of the `n - 2` spare equations (`chi2`, `dof`, `p_value`: small when the arm is "
                "loaded elsewhere too) and `joint_chi2` (where such a load is). With `measured` the unmeasured "
                "angles are estimated too (`hidden_covariance`). Refused: angles outside the physical range or a "
                "configuration where the torques do not determine the force (collinear links: `q_measured`), a "
                "noise that is not positive or not a covariance (`sigma_q`), fewer equations than unknowns "
                "(`measured`).",
    responses=solve_responses(ex.FORCE_ESTIMATE, "no_equilibrium"))
async def control_force_estimate(
    request: Request,
    req: Annotated[s.ForceEstimateRequest, Body(openapi_examples={
        "noise": {"summary": "the paper's chain under (-0.1, 0.05), angles read with a noise of 1e-3 rad",
                  "value": {"manipulator": _M, "q_measured": ex.FORCE_ESTIMATE_Q, "sigma_q": 0.001}},
        "plain": {"summary": "no noise model: the least-squares force and the residual torque", "value": {
            "manipulator": _M, "q_measured": ex.FORCE_ESTIMATE_Q}},
        "hidden": {"summary": "joint 3 (0-based 2) not measured, per-joint noise", "value": {
            "manipulator": _M, "q_measured": [ex.FORCE_ESTIMATE_Q[i] for i in (0, 1, 3)],
            "sigma_q": [0.001, 0.001, 0.002], "measured": [0, 1, 3]}}})],
    settings: SettingsDep,
) -> Any:
    ctx = check_manipulator(req.manipulator, settings)
    return await run_task(request, force_estimate_task, req, fields=ctx, placement=placement(settings, req.manipulator))


@router.post(
    "/stiffness", operation_id="control_stiffness", response_model=s.StiffnessDesignOut,
    summary="Rest lengths for a stable pose with a shaped tip stiffness (variable stiffness)",
    description="Rest lengths putting the tip at `target`, stable under the dead `load`, with the Cartesian tangent "
                "stiffness of the free tip (`K = (J H^-1 J^T)^-1`, as `/v1/stiffness`) equal to `K_desired` (the "
                "closest where it cannot be reached: `exact`, `residual`), or inside `bounds_K` (per entry) and "
                "`eig_bounds` (both eigenvalues) (`tensegrity_opt.preloads_for_stiffness`: IPOPT from the target's "
                "equilibria, `max_starts` shapes). Verified by the forward solve and `cartesian_stiffness`. Bounds "
                "that cannot be met: 422 `design_infeasible` with the least-violation point in `best`.",
    responses=solve_responses(ex.STIFFNESS_DESIGN, "design_infeasible", "unreachable_target"))
async def control_stiffness(
    request: Request,
    req: Annotated[s.StiffnessDesignRequest, Body(openapi_examples={
        "eigenvalues": {"summary": "the paper's chain, tip at (7, 1), both stiffness eigenvalues in [0.04, 0.6]",
                        "value": {"manipulator": _M, "target": [7.0, 1.0], "eig_bounds": [0.04, 0.6]}},
        "exact": {"summary": "a decoupled stiffness diag(0.4, 0.03)", "value": {
            "manipulator": _M, "target": [7.0, 1.0], "K_desired": [[0.4, 0.0], [0.0, 0.03]]}}})],
    settings: SettingsDep,
) -> Any:
    ctx = check_manipulator(req.manipulator, settings)
    return await run_task(request, stiffness_design_task, req, fields=ctx, placement=Placement.KILLABLE)


@router.post(
    "/load-capacity", operation_id="control_load_capacity", response_model=s.LoadCapacityOut,
    summary="How much more tip load a stable pose carries, per direction (a polar curve)",
    description="For each of `directions` evenly spaced unit directions `d`, the dead-load path `F = base + t d` "
                "from the pose (`start`, a stable equilibrium under `base`; default the least-energy rest "
                "configuration) followed by arclength continuation until it first loses stability: a fold (snap) "
                "or a bifurcation (buckling) (`tensegrity_opt.load_capacity`). `loads` is null where the path stays "
                "stable up to a joint's range bound or `max_load` (`reasons`). Computed within the server's time "
                "limit: directions not reached answer `reasons: \"time_limit\"`.",
    responses=solve_responses(ex.LOAD_CAPACITY, "no_equilibrium"))
async def control_load_capacity(
    request: Request,
    req: Annotated[s.LoadCapacityRequest, Body(openapi_examples={
        "paper": {"summary": "the straight paper chain: buckles at 0.0761 under compression", "value": {
            "manipulator": _M, "directions": 8, "max_load": 2.0}}})],
    settings: SettingsDep,
) -> Any:
    ctx = check_manipulator(req.manipulator, settings, LOAD_CAPACITY_ALIASES)
    return await run_task(request, load_capacity_task, req, path_deadline(settings), fields=ctx,
                          placement=Placement.HEAVY)


@router.post(
    "/weight-capacity", operation_id="control_weight_capacity", response_model=s.WeightCapacityOut,
    summary="By how much the chain's weights may grow before its rest pose loses stability",
    description="The rest configuration under the chain's loads (`gravity` on its masses and payload; or `start`) "
                "followed as gravity is scaled from 1 up to `max_factor`, until it first loses stability: a fold "
                "(snap) or a bifurcation (buckling), located to 1e-9 of the range (`tensegrity_opt.weight_capacity`). "
                "`factor` is null where the path stays stable to a joint's range bound or `max_factor` (`reason`). "
                "A chain without weight: 422 `invalid_parameter`, field `gravity`.",
    responses=solve_responses(ex.WEIGHT_CAPACITY, "no_equilibrium"))
async def control_weight_capacity(
    request: Request,
    req: Annotated[s.WeightCapacityRequest, Body(openapi_examples={
        "upright": {"summary": "a 6-segment arm standing upright: buckles at 1.259 times its weight", "value": {
            "manipulator": ex.UPRIGHT_STIFF_ARM, "max_factor": 10.0}}})],
    settings: SettingsDep,
) -> Any:
    ctx = check_manipulator(req.manipulator, settings)
    return await run_task(request, weight_capacity_task, req, path_deadline(settings), fields=ctx,
                          placement=Placement.HEAVY)
