"""Batches of equilibria along a trajectory."""

from __future__ import annotations

import time
from typing import Annotated, Any

from fastapi import APIRouter, Body, Request

from ... import examples as ex
from ... import schemas as s
from ...tasks.equilibria import batch_task
from ..deps import SettingsDep, check_batch, check_manipulator
from ..dispatch import Placement, run_task
from ..json_bodies import JSONBodyRoute
from ..openapi import solve_responses

router = APIRouter(route_class=JSONBodyRoute, prefix="/v1", tags=["batch"])


@router.post(
    "/batch/equilibrium", operation_id="batch_equilibrium", response_model=s.BatchOut,
    summary="Equilibria for a sequence of tip deflections, in order",
    description="Solves each target as `/v1/equilibrium` does, in order, in one solver worker. With "
                "`continuation` (default) each solve starts from the previous result (`q0`), so a trajectory stays "
                "on its branch. Each target gets either `equilibrium` or `error` (the same error object as a "
                "single request, with the field path `targets[i].dx`); targets not started within the batch time "
                "limit (`TENSEGRITY_BATCH_TIMEOUT`) get the error code `timeout`. More targets than the server "
                "accepts (`TENSEGRITY_MAX_BATCH`): 422 `batch_too_large`.",
    responses=solve_responses(ex.BATCH))
async def batch_equilibrium(
    request: Request,
    req: Annotated[s.BatchEquilibriumRequest, Body(openapi_examples={
        "trajectory": {"summary": "two targets by continuation", "value": {
            "manipulator": ex.PAPER_CHAIN, "targets": [{"dx": 0.05, "dy": 0.0}, {"dx": 0.1, "dy": 0.01}],
            "continuation": True}}})],
    settings: SettingsDep,
) -> Any:
    ctx = check_manipulator(req.manipulator, settings)
    check_batch(req, settings)
    deadline = time.monotonic() + settings.batch_timeout
    # The hard limit leaves one solve time limit for the target running at the soft deadline.
    return await run_task(request, batch_task, req, deadline, ctx.manipulator or "uniform", fields=ctx,
                          timeout=settings.batch_timeout + settings.solve_timeout, placement=Placement.HEAVY,
                          size_field="targets")
