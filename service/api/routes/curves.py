"""Force-deflection curves."""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import APIRouter, Body, Request

from ... import examples as ex
from ... import schemas as s
from ...adapters.inputs import segment_count
from ...tasks.equilibria import force_deflection_task
from ..deps import SettingsDep, check_curve_size, check_manipulator, placement
from ..dispatch import run_task
from ..json_bodies import JSONBodyRoute
from ..openapi import solve_responses

router = APIRouter(route_class=JSONBodyRoute, prefix="/v1", tags=["curves"])


@router.post(
    "/force-deflection", operation_id="force_deflection", response_model=s.ForceDeflectionOut,
    summary="Force-deflection curve along the least-energy stable branch",
    description="Continuation over the deflections `dx` (a list, or `{start, stop, num}`; at most "
                f"{s.MAX_CURVE_POINTS} points) at fixed `dy` (`tensegrity_opt.force_deflection`). `jumps` lists the "
                "force discontinuities (`kind`: `buckling` at dx -> 0+ from the stable straight chain, "
                "`leave_straight` from a straight chain that is not stable unloaded or at dy != 0, `snap` where the "
                "selected stable "
                "branch ends, `switch` where the least-energy stable branch changes while the old one stays stable; "
                "each with `delta` and a `label`); `branch = \"all\"` also returns every "
                "branch found at the first deflected point, with null where it no longer exists. Where a point has "
                "no stable equilibrium (a fold, the joint range) the curve stops: the answer is still 200, with the "
                "points before it, `success = false`, `ended_at` (that point and why) and a `message`. An answer over "
                "the server's `TENSEGRITY_MAX_RESPONSE_BYTES` (default 8 MiB; n = 200 with 301 points and `branch = "
                "\"all\"` is ~40 MB) is refused with 422 `response_too_large` on `dx`: ask for fewer points or "
                "`branch = \"stable\"`.",
    responses=solve_responses(ex.FORCE_DEFLECTION, "unreachable_target", "no_equilibrium", "response_too_large"))
async def force_deflection(
    request: Request,
    req: Annotated[s.ForceDeflectionRequest, Body(openapi_examples={
        "range": {"summary": "Fig. 6: 3 points from 0 to 0.1", "value": {
            "manipulator": ex.PAPER_CHAIN, "dx": {"start": 0.0, "stop": 0.1, "num": 3}, "dy": 0.0,
            "branch": "stable"}},
        "list": {"summary": "explicit deflections, every branch", "value": {
            "manipulator": ex.PAPER_CHAIN, "dx": [0.05, 0.1, 0.2], "dy": 0.0, "branch": "all"}}})],
    settings: SettingsDep,
) -> Any:
    ctx = check_manipulator(req.manipulator, settings)
    points = req.dx.num if isinstance(req.dx, s.RangeIn) else len(req.dx)
    check_curve_size(segment_count(req.manipulator), points, req.branch, settings)
    return await run_task(request, force_deflection_task, req, fields=ctx, size_field="dx",
                          placement=placement(settings, req.manipulator, branch_all=req.branch == "all"))
