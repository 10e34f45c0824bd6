"""Vibration modes."""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import APIRouter, Body, Request

from ... import examples as ex
from ... import schemas as s
from ...tasks.equilibria import modes_task
from ..deps import SettingsDep, check_manipulator
from ..dispatch import run_task
from ..json_bodies import JSONBodyRoute
from ..openapi import solve_responses

router = APIRouter(route_class=JSONBodyRoute, prefix="/v1", tags=["modes"])


@router.post(
    "/modes", operation_id="modes", response_model=s.ModesOut,
    summary="Natural frequencies and mode shapes of an equilibrium",
    description="Solves the equilibrium as `/v1/equilibrium` (dx, dy: the tip held) or `/v1/equilibrium/force` "
                "(fx, fy: the tip loaded) does, then its linearised vibration modes (`tensegrity_opt.modes`): the "
                "segments' `mass` (two triangles, centroids 2b/3 from the joint), their `inertia` and the chain's "
                "`payload` as the mass matrix, the Hessian of the potential as the stiffness, on the motions the "
                "equilibrium allows (the tip held or loaded; a joint on its stop held). A chain without mass: 422 "
                "`invalid_parameter`, field `mass`.",
    responses=solve_responses(ex.MODES, "unreachable_target", "solver_failed"))
async def modes(
    request: Request,
    req: Annotated[s.ModesRequest, Body(openapi_examples={
        "paper": {"summary": "the paper's chain with masses 0.1, dx = 1", "value": {
            "manipulator": {**ex.PAPER_CHAIN, "mass": 0.1}, "dx": 1.0, "dy": 0.0}}})],
    settings: SettingsDep,
) -> Any:
    ctx = check_manipulator(req.manipulator, settings)
    return await run_task(request, modes_task, req, fields=ctx)
