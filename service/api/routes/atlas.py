"""The workspace stability atlas of a small grid, inline: ``POST /v1/atlas``.

Larger grids are sweep jobs (``POST /v1/jobs`` with ``analysis: atlas``, then ``GET /v1/jobs/{id}/atlas``,
:mod:`.jobs`); the figure is ``POST /v1/plots/atlas`` (:mod:`.plots`).
"""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import APIRouter, Body, Request

from ... import examples as ex
from ... import schemas as s
from ...schemas.atlas import ATLAS_CHAIN, ATLAS_REQUEST_EXAMPLE
from ...tasks.paths import find_atlas
from ..deps import SettingsDep, check_atlas_targets, check_homotopy, check_manipulator, path_deadline
from ..dispatch import Placement, run_task
from ..json_bodies import JSONBodyRoute
from ..openapi import ATLAS_LIMITS, solve_responses

router = APIRouter(route_class=JSONBodyRoute, prefix="/v1", tags=["atlas"])

@router.post(
    "/atlas", operation_id="stability_atlas", response_model=s.AtlasOut,
    summary="The stability atlas of the held tip over a small grid of deflections",
    description="With the tip held at every target `(dx, dy)` of the grid, every equilibrium is found and counted "
                "(minima, saddles, maxima; the least-energy stable one and its sign string); then each grid edge is "
                "followed by continuation: where a stable branch loses stability on it (a fold: the arm snaps) is "
                "a `branch_end` crossing, where the least-energy branch changes a `switch` (the point of equal "
                "energy), each located on the edge (`tensegrity_opt.stability_atlas`). `curves` joins the crossings "
                "of one kind inside each grid cell into segments. `edges: false` gives the counts only. The counts "
                "are certified with `method: homotopy` (`certified`), measured with the search. " + ATLAS_LIMITS,
    responses=solve_responses(ex.ATLAS, "atlas_too_large", "bad_grid", "response_too_large"))
async def stability_atlas(
    request: Request,
    req: Annotated[s.AtlasRequest, Body(openapi_examples={
        "bistable": {"summary": "a bistable chain (a = 0.5), 3 x 3 targets", "value": ATLAS_REQUEST_EXAMPLE},
        "lists": {"summary": "grid values as lists, the counts only, certified by the homotopy", "value": {
            "manipulator": {**ATLAS_CHAIN, "n": 2}, "dx": [0.2, 0.6], "dy": [0.0, 0.3], "method": "homotopy",
            "edges": False}},
        "pre_bent": {"summary": "a pre-bent chain given by its segments", "value": {
            "manipulator": {"segments": [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": [1.05, 0.95]}] * 2
                            + [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}]},
            "dx": [0.2, 0.8], "dy": [0.0, 0.4]}}})],
    settings: SettingsDep,
) -> Any:
    ctx = check_manipulator(req.manipulator, settings)
    check_homotopy(req, settings)
    check_atlas_targets(req, settings)
    return await run_task(request, find_atlas, req, path_deadline(settings), fields=ctx, placement=Placement.HEAVY,
                          size_field="dx")
