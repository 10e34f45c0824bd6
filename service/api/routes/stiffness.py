"""Cartesian stiffness."""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import APIRouter, Body, Request

from ... import examples as ex
from ... import schemas as s
from ...tasks.equilibria import stiffness_task
from ..deps import SettingsDep, check_manipulator
from ..dispatch import run_task
from ..json_bodies import JSONBodyRoute
from ..openapi import solve_responses

router = APIRouter(route_class=JSONBodyRoute, prefix="/v1", tags=["stiffness"])


@router.post(
    "/stiffness", operation_id="cartesian_stiffness", response_model=s.StiffnessOut,
    summary="Cartesian tangent stiffness at the least-energy stable equilibrium",
    description="Solves the equilibrium as `/v1/equilibrium` does, then returns the 2 x 2 tangent stiffness "
                "`dF_i / d tip_j` there (`tensegrity_opt.cartesian_stiffness`). At dx = dy = 0 (fully extended "
                "chain) it is undefined: 422 `invalid_parameter`.",
    responses=solve_responses(ex.STIFFNESS, "unreachable_target", "solver_failed"))
async def cartesian_stiffness(
    request: Request,
    req: Annotated[s.StiffnessRequest, Body(openapi_examples={
        "paper": {"summary": "the paper's chain, dx = 0.1", "value": {"manipulator": ex.PAPER_CHAIN, "dx": 0.1,
                                                                       "dy": 0.0}}})],
    settings: SettingsDep,
) -> Any:
    ctx = check_manipulator(req.manipulator, settings)
    return await run_task(request, stiffness_task, req, fields=ctx)
