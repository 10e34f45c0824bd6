"""Equilibria under a prescribed tip displacement or force, and all equilibria."""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import APIRouter, Body, Request

from ... import examples as ex
from ... import schemas as s
from ...adapters.inputs import bounded_search_may_settle, equilibrium_args
from ...config import Settings
from ...tasks.equilibria import equilibria_task, equilibrium_task, force_equilibrium_task
from ..deps import SettingsDep, check_homotopy, check_manipulator, placement
from ..dispatch import run_task
from ..json_bodies import JSONBodyRoute
from ..openapi import solve_responses

router = APIRouter(route_class=JSONBodyRoute, prefix="/v1", tags=["equilibrium"])

_M = ex.PAPER_CHAIN


@router.post(
    "/equilibrium", operation_id="solve_equilibrium", response_model=s.EquilibriumOut,
    summary="Least-energy stable equilibrium for a tip deflection",
    description="The least-energy **stable** equilibrium with the tip held at `(2 sum(b) - dx, dy)` "
                "(`tensegrity_opt.solve_equilibrium`). `q0` (optional) is a nearby configuration, e.g. the "
                "previous answer of a control loop; it competes with the global search. With `local: true` "
                "only the local solve from `q0` runs: the equilibrium on the branch through `q0` (read "
                "`stable`), what a control loop following its arm wants, much cheaper than the search. With "
                "`certify: true` the answer carries `certificate`, a rigorous lower bound on the energy of every "
                "configuration meeting the tip constraint and its gap (`status` `certified` when within tolerance).",
    responses=solve_responses(ex.EQUILIBRIUM, "unreachable_target", "solver_failed", "no_equilibrium"))
async def solve_equilibrium(
    request: Request,
    req: Annotated[s.EquilibriumRequest, Body(openapi_examples={
        "paper": {"summary": "the paper's chain, dx = 0.1", "value": {"manipulator": _M, "dx": 0.1, "dy": 0.0}},
        "segments": {"summary": "segments listed, with q0", "value": {
            "manipulator": {"segments": [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}] * 4}, "dx": 0.1, "dy": 0.02,
            "q0": [0.17, -0.07, -0.24, -0.13]}},
        "control_step": {"summary": "control loop: the branch through the previous answer", "value": {
            "manipulator": _M, "dx": 0.101, "dy": 0.0, "q0": [0.17815, -0.07659, -0.24505, -0.13118],
            "local": True}}})],
) -> Any:
    # the settings from app.state, not the dependency: this route is the control loops' hot path and a
    # FastAPI dependency costs ~15-35 us per request even when it returns at once
    settings: Settings = request.app.state.settings
    ctx = check_manipulator(req.manipulator, settings)
    # the bounded Newton-only search settles short monotonic chains (in a solver process); the
    # others go straight to the solver threads
    args = equilibrium_args(req)
    return await run_task(request, equilibrium_task, *args, fields=ctx,
                          bounded=not req.certify and bounded_search_may_settle(args[0], settings.inline_max_segments))


@router.post(
    "/equilibrium/force", operation_id="solve_equilibrium_under_force", response_model=s.EquilibriumOut,
    summary="Equilibrium under a prescribed tip force (dead load)",
    description="A local minimiser of `E(q) - F . tip(q)` for the tip force `F = (fx, fy)` "
                "(`tensegrity_opt.solve_equilibrium_under_force`); `fx < 0` compresses.",
    responses=solve_responses(ex.FORCE_EQUILIBRIUM, "solver_failed", "no_equilibrium"))
async def solve_equilibrium_under_force(
    request: Request,
    req: Annotated[s.ForceEquilibriumRequest, Body(openapi_examples={
        "paper": {"summary": "the paper's chain under fx = -0.3",
                  "value": {"manipulator": _M, "fx": -0.3, "fy": 0.0}}})],
    settings: SettingsDep,
) -> Any:
    ctx = check_manipulator(req.manipulator, settings)
    return await run_task(request, force_equilibrium_task, req, fields=ctx)


@router.post(
    "/equilibria", operation_id="find_equilibria", response_model=s.EquilibriaOut,
    summary="Every equilibrium for a tip deflection (minima, saddles, maxima)",
    description="All equilibria inside the physical range (`tensegrity_opt.find_equilibria`), sorted by energy; "
                "`morse_index`/`kind` classify each one. `method: homotopy` certifies the set (`certified`) "
                "for chains up to the server's `homotopy_max_segments` (default 5); the default search is complete in "
                "practice, not certified.",
    responses=solve_responses(ex.EQUILIBRIA, "unreachable_target", "solver_failed"))
async def find_equilibria(
    request: Request,
    req: Annotated[s.EquilibriaRequest, Body(openapi_examples={
        "paper": {"summary": "the paper's chain, dx = 0.1", "value": {"manipulator": _M, "dx": 0.1, "dy": 0.0}}})],
    settings: SettingsDep,
) -> Any:
    ctx = check_manipulator(req.manipulator, settings)
    check_homotopy(req, settings)
    return await run_task(request, equilibria_task, req, settings.solve_timeout, fields=ctx,
                          placement=placement(settings, req.manipulator, homotopy=req.method == "homotopy"))
