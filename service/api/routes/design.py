"""Design and control: the strongest chain, preloads for a load, preloads for a pose, the preload holding a chain
up under its weight."""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import APIRouter, Body, Request

from ... import examples as ex
from ... import schemas as s
from ...adapters.inputs import segment_count
from ...config import Settings
from ...tasks.control import design_critical_force_task, holding_task, preloads_for_load_task, preloads_task
from ..deps import SettingsDep, check_manipulator
from ..dispatch import Placement, run_task
from ..errors import ServiceError
from ..json_bodies import JSONBodyRoute
from ..openapi import solve_responses

router = APIRouter(route_class=JSONBodyRoute, prefix="/v1/design", tags=["design"])

_INFEASIBLE = ("design_infeasible",)


async def _design(request: Request, task: Any, req: Any, settings: Settings) -> Any:
    """A design request: the server's limits, the design endpoints' own, then ``task`` in a killable process."""
    ctx = check_manipulator(req.manipulator, settings)
    n = segment_count(req.manipulator)
    if n > s.MAX_DESIGN_SEGMENTS:
        raise ServiceError(422, "too_many_segments",
                           f"the design endpoints accept at most {s.MAX_DESIGN_SEGMENTS} segments (got {n})",
                           field="manipulator", details={"n": n, "max_segments": s.MAX_DESIGN_SEGMENTS})
    return await run_task(request, task, req, fields=ctx, placement=Placement.KILLABLE)


@router.post(
    "/critical-force", operation_id="design_critical_force", response_model=s.DesignOut,
    summary="Maximise the critical load over per-segment design variables",
    description="`tensegrity_opt.maximize_critical_force`: maximise P subject to Z^T (K - P G) Z = L L^T "
                "(positive semidefinite through a Cholesky factor, smooth at repeated eigenvalues), bounds, "
                "budgets (`sum(x) <= budget`), optional total length, preload tension and joint-stiffness "
                "limits. The returned critical force is recomputed by `critical_force` on the design. "
                "Infeasible: 422 `design_infeasible` with IPOPT's `status` and the `best` point found.",
    responses=solve_responses(ex.DESIGN, *_INFEASIBLE))
async def design_critical_force(
    request: Request,
    req: Annotated[s.DesignCriticalForceRequest, Body(openapi_examples={
        "stiffness_budget": {"summary": "redistribute a stiffness budget (paper's chain)", "value": {
            "manipulator": ex.PAPER_CHAIN, "vary": ["k"], "bounds": {"k": {"lo": 0.2, "hi": 5.0}},
            "budget": {"k": 4.0}, "boundary": "guided"}},
        "lengths": {"summary": "segment lengths with the total length fixed (n = 6)", "value": {
            "manipulator": {"n": 6, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}, "vary": ["b"],
            "bounds": {"b": {"lo": 0.3, "hi": 3.0}}, "total_length": True}}})],
    settings: SettingsDep,
) -> Any:
    return await _design(request, design_critical_force_task, req, settings)


@router.post(
    "/preloads-for-load", operation_id="design_preloads_for_load", response_model=s.DesignOut,
    summary="Smallest rest-length change giving a required critical load",
    description="`tensegrity_opt.preloads_for_critical_force`: minimise |L0 - L0_nom|^2 subject to "
                "Z^T (K(L0) - P_req G) Z positive semidefinite and L0 within bounds. When no rest lengths reach "
                "the load: 422 `design_infeasible` with `best` = the strongest achievable design.",
    responses=solve_responses(ex.DESIGN, *_INFEASIBLE))
async def design_preloads_for_load(
    request: Request,
    req: Annotated[s.PreloadsForLoadRequest, Body(openapi_examples={
        "paper": {"summary": "the paper's chain to carry 0.7", "value": {
            "manipulator": ex.PAPER_CHAIN, "required": 0.7}}})],
    settings: SettingsDep,
) -> Any:
    return await _design(request, preloads_for_load_task, req, settings)


@router.post(
    "/preloads", operation_id="design_preloads", response_model=s.PreloadsOut,
    summary="Rest lengths (control inputs) for a stable pose under a tip load",
    description="`tensegrity_opt.preloads_for_pose`: rest lengths (L1_0, L2_0) per segment such that under the "
                "tip load the chain has a stable equilibrium with the tip at `target` (optionally the last "
                "link's angle), with the joint-space Hessian >= `margin`; objectives: least change from the "
                "nominal preloads, largest margin, least energy. Verified by re-solving the force-controlled "
                "equilibrium before answering. Infeasible: 422 `design_infeasible` with `best`.",
    responses=solve_responses(ex.PRELOADS, "unreachable_target", *_INFEASIBLE))
async def design_preloads(
    request: Request,
    req: Annotated[s.PreloadsRequest, Body(openapi_examples={
        "pose": {"summary": "tip at (7, 1.5) under a small load", "value": {
            "manipulator": ex.PAPER_CHAIN, "target": [7.0, 1.5], "load": [0.05, -0.02],
            "objective": "nominal", "margin": 0.05}}})],
    settings: SettingsDep,
) -> Any:
    return await _design(request, preloads_task, req, settings)


@router.post(
    "/holding", operation_id="design_holding", response_model=s.HoldingOut,
    summary="The least preload (or stiffness) holding the chain up under its weight",
    description="`tensegrity_opt.preloads_for_holding`: per segment, the least preload (`vary: [L0]`, the rest "
                "lengths lengthened) or stiffness (`vary: [k]`) for which the chain, under its dead loads (`gravity` "
                "on its masses and payload, `joint_forces`), rests in a stable equilibrium with its tip free, every "
                "joint within `max_angle` of straight, every spring taut, the potential's Hessian >= `margin`. "
                "Verified: the designed chain's forward equilibrium lands on the designed pose, and its "
                "least-potential rest configuration is that pose (status `optimal`; else `metastable`). "
                "Infeasible: 422 `design_infeasible`.",
    responses=solve_responses(ex.HOLDING, *_INFEASIBLE))
async def design_holding(
    request: Request,
    req: Annotated[s.HoldingRequest, Body(openapi_examples={
        "upright": {"summary": "the least stiffness standing a 6-segment arm upright", "value": {
            "manipulator": ex.UPRIGHT_ARM, "vary": ["k"], "max_angle": 0.05}}})],
    settings: SettingsDep,
) -> Any:
    return await _design(request, holding_task, req, settings)
