"""Energy landscape of the 4-segment chain."""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import APIRouter, Body, Request

from ... import examples as ex
from ... import schemas as s
from ...tasks.equilibria import energy_landscape_task
from ..deps import SettingsDep, check_manipulator
from ..dispatch import run_task
from ..json_bodies import JSONBodyRoute
from ..openapi import solve_responses

router = APIRouter(route_class=JSONBodyRoute, prefix="/v1", tags=["landscape"])


@router.post(
    "/energy-landscape", operation_id="energy_landscape", response_model=s.EnergyLandscapeOut,
    summary="Energy over a grid of two joint angles (n = 4)",
    description="The paper's straightforward energy method (`tensegrity_opt.energy_landscape`, n = 4 only; other "
                "n: 422 `unsupported`): `(q_i, q_j)` on a `grid` x `grid` mesh (at most "
                f"{s.MAX_GRID} per axis), the other two joints from inverse kinematics on both elbow branches. "
                "`energy[elbow][i][j]` is null where the tip cannot be reached or the configuration leaves the "
                "physical range.",
    responses=solve_responses(ex.ENERGY_LANDSCAPE, "unreachable_target"))
async def energy_landscape(
    request: Request,
    req: Annotated[s.EnergyLandscapeRequest, Body(openapi_examples={
        "paper": {"summary": "Fig. 4 on a 3 x 3 grid", "value": {
            "manipulator": ex.PAPER_CHAIN, "dx": 0.1, "dy": 0.0, "pair": [0, 3], "grid": 3}}})],
    settings: SettingsDep,
) -> Any:
    ctx = check_manipulator(req.manipulator, settings)
    return await run_task(request, energy_landscape_task, req, fields=ctx, size_field="grid")
