"""Loading paths: rest configurations, equilibrium branches, bifurcation diagrams, limit loads, imperfection
sensitivity, stability boundaries."""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import APIRouter, Body, Request

from ... import examples as ex
from ... import schemas as s
from ...adapters.fields import BRANCH_ALIASES, LIMIT_LOAD_ALIASES
from ...config import Settings
from ...tasks.paths import (
    bifurcation_diagram_task,
    find_stability_boundary,
    imperfection_sensitivity_task,
    limit_load_task,
    rest_configurations_task,
    trace_branches,
)
from ..deps import SettingsDep, check_homotopy, check_manipulator, check_path, path_deadline, placement
from ..dispatch import Placement, run_task
from ..json_bodies import JSONBodyRoute
from ..openapi import solve_responses

router = APIRouter(route_class=JSONBodyRoute, prefix="/v1", tags=["paths"])

_M = ex.PAPER_CHAIN
_STRAIGHT = {"q": [0.0, 0.0, 0.0, 0.0]}
_GUIDED = {"kind": "guided", "direction": [-1.0, 0.0]}

_CONTINUATION = ("Pseudo-arclength continuation (`tensegrity_opt.analyses.paths.branches`): chains of up to 64 "
                 "segments (longer: 422 `invalid_parameter` on `manipulator.n`); `max_points` up to the server's "
                 "`TENSEGRITY_MAX_PATH_POINTS` (default 5000; above: 422 `too_many_points`). The computation stops "
                 "shortly before the server's time limit and answers what it has (200, `status: \"time_limit\"`, "
                 "`success: false`) instead of a 504.")
_CONTROL = ("`control` says what `t` moves: `displacement` (the tip along `direction` in (dx, dy), `t` a length), "
            "`load` (a dead load `base + t direction`), `guided` (the tip's y held, `Fx = base_x + t d_x`, `Fy` the "
            "guide's reaction: the paper's case), `wall` (the tip on a frictionless wall of `normal`), `preload` "
            "(the rest lengths along `direction`, 2n numbers, the tip `free` under `load` or `held`). `start`: "
            "`{\"q\"}` joint angles, `{\"dx\", \"dy\"}` the least-energy equilibrium with the tip held there "
            "(displacement and held-tip preload controls), or null: the least-energy rest configuration.")


@router.post(
    "/rest-configurations", operation_id="rest_configurations", response_model=s.EquilibriaOut,
    summary="Every equilibrium under a dead tip load (F = 0: the rest configurations)",
    description="All equilibria inside the physical range under the tip force `F = (fx, fy)` held fixed "
                "(`tensegrity_opt.analyses.equilibria.rest.find_equilibria_under_force`), each classified by the full "
                "Hessian of `E - F . tip`, sorted by that potential. `F = 0` is exact (`method: \"exact\"`, "
                "certified): the product of the segments' unloaded critical points; a bistable segment gives two "
                "wells. `stable_only` keeps the minima. For `F != 0`, `method: homotopy` is accepted for chains up to "
                "the server's `homotopy_max_segments`.",
    responses=solve_responses(ex.REST_CONFIGURATIONS, "solver_failed", "response_too_large"))
async def rest_configurations(
    request: Request,
    req: Annotated[s.RestConfigurationsRequest, Body(openapi_examples={
        "rest": {"summary": "the paper's chain unloaded: straight", "value": {"manipulator": _M}},
        "loaded": {"summary": "stable equilibria under a compressive load", "value": {
            "manipulator": _M, "fx": -0.3, "fy": 0.0, "stable_only": True}}})],
    settings: SettingsDep,
) -> Any:
    ctx = check_manipulator(req.manipulator, settings)
    loaded = req.fx != 0.0 or req.fy != 0.0
    if loaded:
        check_homotopy(req, settings)       # F = 0 is exact whatever the method
    return await run_task(request, rest_configurations_task, req, settings.solve_timeout, fields=ctx,
                          size_field="stable_only",
                          placement=placement(settings, req.manipulator, homotopy=loaded and req.method == "homotopy"))


@router.post(
    "/branch", operation_id="trace_branch", response_model=s.TracedBranchOut,
    summary="One equilibrium branch by arclength continuation, with its events",
    description="The branch through `start` followed in the control parameter `t` (`tensegrity_opt.trace_branch`): "
                "per point `t`, `q`, the tip force, tip, deflection, energy and the Morse index (0: stable); "
                "`events` are the folds (t turns back: snap-through), branch points (another branch crosses: "
                "`/v1/bifurcation-diagram` follows it) and the joint limit that ends a branch, each located "
                "precisely. `t_max` / `t_min` stop it, `stop_at` after the first event (or loss of stability), "
                "`direction: -1` leaves the start with `t` decreasing. " + _CONTROL + " " + _CONTINUATION,
    responses=solve_responses(ex.BRANCH, "continuation_too_long", "bad_start", "too_many_points", "no_equilibrium",
                              "response_too_large"))
async def trace_branch(
    request: Request,
    req: Annotated[s.BranchRequest, Body(openapi_examples={
        "guided": {"summary": "the paper's chain, guided tip, from straight: the branch points at the critical "
                              "loads 0.572793, 1.362906, 1.921444", "value": {
            "manipulator": _M, "start": _STRAIGHT, "control": _GUIDED, "t_max": 2.0}},
        "first_event": {"summary": "a dead compressive load from the rest configuration, up to the first event",
                        "value": {"manipulator": _M, "control": {"kind": "load", "direction": [-1.0, 0.0]},
                                  "stop_at": "event", "max_points": 200}},
        "displacement": {"summary": "the tip pushed in from the equilibrium at dx = 0.1", "value": {
            "manipulator": _M, "start": {"dx": 0.1, "dy": 0.0},
            "control": {"kind": "displacement", "direction": [1.0, 0.0]}, "t_max": 1.0}}})],
    settings: SettingsDep,
) -> Any:
    return await _follow(request, trace_branches, req, settings)


@router.post(
    "/bifurcation-diagram", operation_id="bifurcation_diagram", response_model=s.BifurcationDiagramOut,
    summary="Every branch connected to the start through branch points",
    description="The start's branch both ways (`t` up, then down), then at each branch point both sides of the "
                "bifurcating branch, recursively to `depth` switches, at most `max_branches` branches "
                "(`tensegrity_opt.bifurcation_diagram`); each branch as `/v1/branch` answers it. " + _CONTROL + " "
                + _CONTINUATION + " An answer over `TENSEGRITY_MAX_RESPONSE_BYTES` is refused with 422 "
                "`response_too_large` on `max_points`.",
    responses=solve_responses(ex.BIFURCATION_DIAGRAM, "continuation_too_long", "bad_start", "too_many_points",
                              "no_equilibrium", "response_too_large"))
async def bifurcation_diagram(
    request: Request,
    req: Annotated[s.BifurcationDiagramRequest, Body(openapi_examples={
        "guided": {"summary": "the paper's chain, guided: the pitchfork branches of the first two critical loads",
                   "value": {"manipulator": _M, "start": _STRAIGHT, "control": _GUIDED, "t_max": 2.0,
                             "t_min": -0.2, "depth": 1, "max_points": 200}}})],
    settings: SettingsDep,
) -> Any:
    return await _follow(request, bifurcation_diagram_task, req, settings)


@router.post(
    "/limit-load", operation_id="limit_load", response_model=s.LimitLoadOut,
    summary="The dead load at which the path from a rest configuration loses stability",
    description="The dead-load path `F = t d` from a rest configuration (`start`, default the least-energy one) "
                "followed until stability is first lost (`tensegrity_opt.limit_load`): `kind` `fold` (snap-through) "
                "or `bifurcation` (the straight symmetric chain buckles at its critical load, `/v1/buckling`), with "
                "`load`, the configuration and the mode there; `none` when the path stays stable to a joint limit "
                "or `max_load` (`status`), with `quasi_buckling_load`, the load of least tangent stiffness along "
                "the load. `boundary: guided` holds the tip's y (the paper's case). `include_branch` adds the path. "
                + _CONTINUATION,
    responses=solve_responses(ex.LIMIT_LOAD, "continuation_too_long", "bad_start", "too_many_points",
                              "response_too_large"))
async def limit_load(
    request: Request,
    req: Annotated[s.LimitLoadRequest, Body(openapi_examples={
        "guided": {"summary": "the paper's chain, guided: the critical load 0.572793", "value": {
            "manipulator": _M, "direction": [-1.0, 0.0], "boundary": "guided", "start": _STRAIGHT}},
        "pre_bent": {"summary": "a pre-bent chain, free tip: smooth (quasi-buckling), with the path", "value": {
            "manipulator": {"segments": [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": [1.0, 1.02]}]
                            + [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}] * 3},
            "direction": [-1.0, 0.0], "boundary": "free", "max_load": 0.2, "include_branch": True}}})],
    settings: SettingsDep,
) -> Any:
    return await _follow(request, limit_load_task, req, settings, LIMIT_LOAD_ALIASES)


@router.post(
    "/imperfection-sensitivity", operation_id="imperfection_sensitivity", response_model=s.ImperfectionSensitivityOut,
    summary="The limit load an imperfect arm reaches, against the imperfection's amplitude",
    description="Koiter's imperfection-sensitivity curve (`tensegrity_opt.imperfection_sensitivity`): for each "
                "amplitude `p` the chain made imperfect (`asymmetry`: every segment's rest lengths `L1_0 + p`, "
                "`L2_0 - p`) and the limit load of its dead-load path from its own rest shape, as `/v1/limit-load` "
                "computes it (guided: the guide through its rest tip): `loads` and `kinds` (`fold`, `bifurcation`, "
                "`joint_limit`, `none`, `unknown`). `bifurcation` classifies the given chain's bifurcation by its "
                "buckled arms and `law` is the small-imperfection law fitted where one applies (the 2/3 power of an "
                "unstable-symmetric bifurcation). Not the fold curve of `/v1/stability-boundary`, whose guide stays "
                "fixed. " + _CONTINUATION,
    responses=solve_responses(ex.IMPERFECTION_SENSITIVITY, "continuation_too_long", "too_many_points",
                              "response_too_large"))
async def imperfection_sensitivity(
    request: Request,
    req: Annotated[s.ImperfectionSensitivityRequest, Body(openapi_examples={
        "guided": {"summary": "the paper's chain, guided: folds below the critical load 0.572793", "value": {
            "manipulator": _M, "amplitudes": [0.0, 0.01, 0.02851, 0.061]}},
        "subcritical": {"summary": "two segments a = 1.5, guided: the 2/3-power drop", "value": {
            "manipulator": {"n": 2, "a": 1.5, "b": 1.0, "k": 1.0, "L0": 1.0},
            "amplitudes": [0.0003, 0.001, 0.003, 0.01]}}})],
    settings: SettingsDep,
) -> Any:
    return await _follow(request, imperfection_sensitivity_task, req, settings, LIMIT_LOAD_ALIASES)


@router.post(
    "/stability-boundary", operation_id="stability_boundary", response_model=s.StabilityBoundaryOut,
    summary="The curve of folds or branch points over a second parameter",
    description="Two-parameter continuation (`tensegrity_opt.analyses.paths.boundaries.stability_boundary`): the "
                "critical `t` of the one-parameter branches under `control` (a fold or a branch point: `kind` says "
                "which curve) followed as `parameter` moves from `p_min` to `p_max`, with its cusps; the control's "
                "references stay fixed (a guide at the start's tip). The limit load an imperfect arm reaches from "
                "its rest shape is `/v1/imperfection-sensitivity`. " + _CONTINUATION,
    responses=solve_responses(ex.STABILITY_BOUNDARY, "continuation_too_long", "too_many_points",
                              "response_too_large"))
async def stability_boundary(
    request: Request,
    req: Annotated[s.StabilityBoundaryRequest, Body(openapi_examples={
        "guided": {"summary": "the paper's chain, guided, over the asymmetry", "value": {
            "manipulator": _M, "control": _GUIDED, "parameter": "asymmetry", "p_min": -0.1, "p_max": 0.1,
            "max_points": 400}}})],
    settings: SettingsDep,
) -> Any:
    return await _follow(request, find_stability_boundary, req, settings)


async def _follow(request: Request, task: Any, req: Any, settings: Settings,
                  aliases: tuple[tuple[str, str], ...] = BRANCH_ALIASES) -> Any:
    """A continuation request: its limits, then ``task`` in the heavy solver threads within the soft deadline."""
    ctx = check_path(req, settings, aliases)
    return await run_task(request, task, req, path_deadline(settings), fields=ctx, placement=Placement.HEAVY,
                          size_field="max_points")
