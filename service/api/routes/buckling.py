"""Buckling of the straight configuration."""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import APIRouter, Body, Request

from ... import examples as ex
from ... import schemas as s
from ...tasks.equilibria import buckling_task
from ..deps import SettingsDep, check_manipulator
from ..dispatch import run_task
from ..json_bodies import JSONBodyRoute
from ..openapi import solve_responses

router = APIRouter(route_class=JSONBodyRoute, prefix="/v1", tags=["buckling"])


@router.post(
    "/buckling", operation_id="critical_force", response_model=s.BucklingOut,
    summary="Critical force and buckling modes of the straight chain",
    description="Critical loads and modes (`tensegrity_opt.critical_force`): `guided` holds the tip at dy = 0 "
                "(the paper's Table 1), `free` is a cantilever. Needs symmetric segments (straight is an "
                "equilibrium) with joint stiffness K > 0.",
    responses=solve_responses(ex.BUCKLING, "straight_not_equilibrium", "straight_unstable"))
async def critical_force(
    request: Request,
    req: Annotated[s.BucklingRequest, Body(openapi_examples={
        "paper": {"summary": "Table 1 of the paper", "value": {"manipulator": ex.PAPER_CHAIN, "boundary": "guided"}},
        "free": {"summary": "cantilever", "value": {"manipulator": ex.PAPER_CHAIN, "boundary": "free"}}})],
    settings: SettingsDep,
) -> Any:
    ctx = check_manipulator(req.manipulator, settings)
    return await run_task(request, buckling_task, req, fields=ctx)
