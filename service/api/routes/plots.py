"""Figures: ``POST /v1/plots/{curve,landscape,shapes,torque,map,branch,limit-load,boundary,atlas,plan,simulation}``
answering PNG or SVG.

Each route validates its request, then draws the figure in the solver threads (the library call
and matplotlib's rendering are both CPU-bound) and answers the bytes: ``image/png`` by
default, ``image/svg+xml`` when the body says ``"format": "svg"`` or, without ``format``, when
the ``Accept`` header prefers ``image/svg+xml``. Refusals are the usual JSON ``ErrorOut``.
Drawing uses :mod:`tensegrity_opt.applications.plots` (matplotlib objects only, no pyplot: thread-safe).
"""

from __future__ import annotations

import copy
from typing import Annotated, Any

from fastapi import APIRouter, Body, Depends, Request
from starlette.concurrency import run_in_threadpool
from starlette.responses import Response

from ... import examples as ex
from ...adapters.fields import LIMIT_LOAD_ALIASES, FieldContext
from ...adapters.inputs import build_manipulator, build_segment, values
from ...config import Settings
from ...schemas import ErrorOut
from ...schemas import plots as ps
from ...schemas.atlas import ATLAS_REQUEST_EXAMPLE
from ...schemas.control import PLAN_REQUEST_EXAMPLE, SIMULATION_REQUEST_EXAMPLE
from ...tasks.control import find_plan, find_simulation
from ...tasks.paths import find_atlas, find_job_atlas, find_limit_load, find_stability_boundary, trace_branches
from ..deps import (Owner, Runner, check_atlas_targets, check_homotopy, check_manipulator, check_path, check_plan,
                    check_simulation, finished_atlas_job, get_settings_dep, path_deadline, placement)
from ..dispatch import Placement, run_task
from ..openapi import ATLAS_LIMITS, PLAN_LIMITS, SIMULATION_LIMITS, SOLVE_ERRORS, error_responses

__all__ = ["router", "negotiate", "plot_curve_task", "plot_landscape_task", "plot_shapes_task", "plot_torque_task",
           "plot_map_task", "plot_branch_task", "plot_limit_load_task", "plot_boundary_task", "plot_atlas_task",
           "plot_job_atlas_task", "plot_plan_task", "plot_simulation_task"]

router = APIRouter(prefix="/v1/plots", tags=["plots"])

MEDIA = {"png": "image/png", "svg": "image/svg+xml"}

_SVG_EXAMPLE = ('<?xml version="1.0" encoding="utf-8" standalone="no"?>\n'
                '<svg xmlns="http://www.w3.org/2000/svg" width="720pt" height="302pt" viewBox="0 0 720 302">...</svg>')

_EXTRA_422 = {
    "unsupported": {"summary": "the landscape needs n = 4", "value": {
        "code": "unsupported", "message": "the energy landscape is defined for n = 4 segments, got n = 5",
        "field": "manipulator.n"}},
    "invalid_parameter": {"summary": "map values not strictly monotonic", "value": {
        "code": "invalid_parameter", "message": "values_x must be strictly increasing or strictly decreasing",
        "field": "values_x"}},
    "atlas_too_large": ex.ERRORS[422]["atlas_too_large"],
    "bad_grid": ex.ERRORS[422]["bad_grid"],
    "not_an_atlas": {"summary": "the job is not a done atlas job", "value": {
        "code": "invalid_parameter", "field": "job",
        "message": "job '3f0c9a4e1b7d4c2a9e8f6d5c4b3a2910' is a 'buckling' sweep, not an atlas (analysis 'atlas' "
                   "over a grid in dx and dy)"}},
}


# ---------------------------------------------------------------------------- content negotiation
def _accept_q(accept: str) -> dict[str, float]:
    """``{media range: q}`` of an Accept header (malformed parts are skipped)."""
    out: dict[str, float] = {}
    for part in accept.split(","):
        items = [p.strip() for p in part.split(";")]
        media = items[0].lower()
        if not media:
            continue
        q = 1.0
        for param in items[1:]:
            if param.lower().startswith("q="):
                try:
                    q = float(param[2:])
                except ValueError:
                    q = 0.0
        out[media] = max(q, out.get(media, 0.0)) if media in out else q
    return out


def negotiate(fmt: str | None, accept: str | None) -> str:
    """``"png"`` or ``"svg"``: the request's ``format`` if given, else the Accept header's preference
    between ``image/svg+xml`` and ``image/png`` (a tie, a wildcard or nothing: PNG)."""
    if fmt is not None:
        return fmt
    if not accept:
        return "png"
    q = _accept_q(accept)
    wild = max(q.get("*/*", 0.0), q.get("image/*", 0.0))
    svg = q.get("image/svg+xml", wild)
    png = q.get("image/png", wild)
    return "svg" if svg > png else "png"


# ---------------------------------------------------------------------------- tasks (solver threads)
def _image(fig: Any, fmt: str, dpi: int) -> bytes:
    from tensegrity_opt.applications import plots

    return plots.render(fig, fmt, dpi=dpi)


def plot_curve_task(req: ps.PlotCurveRequest, fmt: str) -> bytes:
    from tensegrity_opt import force_deflection
    from tensegrity_opt.applications import plots

    m = build_manipulator(req.manipulator)
    c = force_deflection(m, values(req.dx), req.dy, branch=req.branch)
    return _image(plots.plot_curve(c, m), fmt, req.dpi)


def plot_landscape_task(req: ps.PlotLandscapeRequest, fmt: str) -> bytes:
    from tensegrity_opt import energy_landscape, find_equilibria
    from tensegrity_opt.analyses.equilibria.landscape import landscape_span
    from tensegrity_opt.applications import plots

    m = build_manipulator(req.manipulator)
    pair = (req.pair[0], req.pair[1])
    span = landscape_span(m, req.dx, req.dy, pair) if req.span is None else req.span
    land = energy_landscape(m, req.dx, req.dy, pair=pair, grid=req.grid, span=span)
    eqs = find_equilibria(m, req.dx, req.dy)
    return _image(plots.plot_landscape(land, eqs, m, req.dx, req.dy), fmt, req.dpi)


def plot_shapes_task(req: ps.PlotShapesRequest, fmt: str) -> bytes:
    from tensegrity_opt import find_equilibria
    from tensegrity_opt.applications import plots

    m = build_manipulator(req.manipulator)
    eqs = find_equilibria(m, req.dx, req.dy)
    return _image(plots.plot_shapes(eqs, m, req.dx, req.dy, max_panels=req.max_panels), fmt, req.dpi)


def plot_torque_task(req: ps.PlotTorqueRequest, fmt: str) -> bytes:
    from tensegrity_opt.applications import plots

    segs = [build_segment(sg) for sg in req.segments]
    q = None if req.q is None else values(req.q)
    return _image(plots.plot_torque(segs, q, num=req.num), fmt, req.dpi)


def plot_map_task(req: ps.PlotMapRequest, fmt: str) -> bytes:
    from tensegrity_opt.applications import plots
    from tensegrity_opt.applications.sweeps import critical_load_map

    m = build_manipulator(req.manipulator)
    cmap = critical_load_map(m, req.param_x, values(req.values_x), req.param_y, values(req.values_y), req.boundary)
    return _image(plots.plot_map(cmap, m), fmt, req.dpi)


def plot_branch_task(req: ps.PlotBranchRequest, fmt: str, deadline: float) -> bytes:
    from tensegrity_opt.applications import plots

    m = build_manipulator(req.manipulator)
    return _image(plots.plot_branches(trace_branches(req, deadline), x=req.x, y=req.y, m=m), fmt, req.dpi)


def plot_limit_load_task(req: ps.PlotLimitLoadRequest, fmt: str, deadline: float) -> bytes:
    from tensegrity_opt.applications import plots

    m = build_manipulator(req.manipulator)
    return _image(plots.plot_limit_load(find_limit_load(req, deadline), m), fmt, req.dpi)


def plot_boundary_task(req: ps.PlotBoundaryRequest, fmt: str, deadline: float) -> bytes:
    from tensegrity_opt.applications import plots

    m = build_manipulator(req.manipulator)
    b = find_stability_boundary(req, deadline)
    return _image(plots.plot_boundary(b, m=m, control=req.control.kind), fmt, req.dpi)


def _atlas_image(at: Any, m: Any, fmt: str, dpi: int) -> bytes:
    from tensegrity_opt.applications import plots

    return _image(plots.plot_atlas(at, m=m), fmt, dpi)


def plot_atlas_task(req: ps.PlotAtlasGridRequest, fmt: str, deadline: float) -> bytes:
    return _atlas_image(find_atlas(req, deadline), build_manipulator(req.manipulator), fmt, req.dpi)


def plot_job_atlas_task(spec: dict[str, Any], rows: list[dict[str, Any]], req: ps.PlotAtlasJobRequest, fmt: str,
                        deadline: float) -> bytes:
    from tensegrity_opt import Manipulator

    at = find_job_atlas(spec, rows, req.edges, deadline)
    return _atlas_image(at, Manipulator.from_dict(spec["manipulator"]), fmt, req.dpi)


def plot_plan_task(req: ps.PlotPlanRequest, fmt: str, deadline: float) -> bytes:
    from tensegrity_opt.applications import plots

    fig = plots.plot_preload_plan(find_plan(req, deadline), build_manipulator(req.manipulator), margin=req.margin)
    return _image(fig, fmt, req.dpi)


def plot_simulation_task(req: ps.PlotSimulationRequest, fmt: str, deadline: float) -> bytes:
    from tensegrity_opt.applications import plots

    fig = plots.plot_simulation(find_simulation(req, deadline), build_manipulator(req.manipulator))
    return _image(fig, fmt, req.dpi)


# ---------------------------------------------------------------------------- documentation
def image_responses(*examples_422: str) -> dict[int | str, Any]:
    """200 with both image types, and the refusals of a solve (JSON ``ErrorOut``)."""
    out: dict[int | str, Any] = {200: {
        "description": "The figure: PNG by default, SVG with `\"format\": \"svg\"` or `Accept: image/svg+xml`.",
        "content": {"image/png": {"schema": {"type": "string", "format": "binary"}},
                    "image/svg+xml": {"schema": {"type": "string"}, "example": _SVG_EXAMPLE}}}}
    errs = copy.deepcopy(error_responses(*SOLVE_ERRORS, examples_422=("validation_error", "too_many_segments",
                                                                       *examples_422)))
    for name in examples_422:
        if name in _EXTRA_422:
            errs[422]["content"]["application/json"]["examples"][name] = _EXTRA_422[name]
    out.update(errs)
    return out


def _reply(data: bytes, fmt: str, kind: str) -> Response:
    return Response(content=data, media_type=MEDIA[fmt],
                    headers={"Content-Disposition": f'inline; filename="{kind}.{fmt}"', "Vary": "Accept"})


_FORMATS = ("Answers `image/png`, or `image/svg+xml` with `\"format\": \"svg\"` (or, without `format`, an "
            "`Accept` header preferring `image/svg+xml`); `dpi` sets the PNG resolution.")


# ---------------------------------------------------------------------------- routes
@router.post(
    "/curve", operation_id="plot_curve", response_class=Response, response_model=None,
    summary="Figure: force-deflection curves with their jumps (Fig. 6)",
    description="`Fx` and `Fy` against `dx` along the least-energy stable branch "
                "(`tensegrity_opt.force_deflection`, the data of `/v1/force-deflection`): the buckling jump at "
                "dx -> 0+ from 0 to the critical force drawn as a vertical dashed segment, branch switches dotted; "
                "`branch = \"all\"` also draws every branch, unstable parts dashed. " + _FORMATS,
    responses=image_responses("unreachable_target", "no_equilibrium"))
async def plot_curve(
    request: Request,
    req: Annotated[ps.PlotCurveRequest, Body(openapi_examples={
        "fig6": {"summary": "Fig. 6: the paper's chain, dx from 0 to 2", "value": {
            "manipulator": ex.PAPER_CHAIN, "dx": {"start": 0.0, "stop": 2.0, "num": 41}, "dy": 0.0}},
        "all": {"summary": "every branch, as SVG", "value": {
            "manipulator": ex.PAPER_CHAIN, "dx": {"start": 0.0, "stop": 1.0, "num": 21}, "branch": "all",
            "format": "svg"}}})],
    settings: Annotated[Settings, Depends(get_settings_dep)],
) -> Response:
    ctx = check_manipulator(req.manipulator, settings)
    fmt = negotiate(req.format, request.headers.get("accept"))
    return _reply(await run_task(request, plot_curve_task, req, fmt, fields=ctx,
                                 placement=placement(settings, req.manipulator, branch_all=req.branch == "all")),
                  fmt, "curve")


@router.post(
    "/landscape", operation_id="plot_landscape", response_class=Response, response_model=None,
    summary="Figure: energy landscape with every equilibrium marked (n = 4, Figs. 4-5)",
    description="Energy contours `E(q_i, q_j)` on both elbow branches (`tensegrity_opt.energy_landscape`, the data "
                "of `/v1/energy-landscape`) with every equilibrium of `/v1/equilibria` marked at its `(q_i, q_j)`, "
                "coloured by stability and labelled with its shape. n = 4 only (other n: 422 `unsupported`). "
                "Without `span` the axes cover the reachable region. " + _FORMATS,
    responses=image_responses("unsupported", "unreachable_target", "solver_failed"))
async def plot_landscape(
    request: Request,
    req: Annotated[ps.PlotLandscapeRequest, Body(openapi_examples={
        "fig4": {"summary": "Fig. 4: E(q1, q4) at dx = 0.1", "value": {
            "manipulator": ex.PAPER_CHAIN, "dx": 0.1, "dy": 0.0, "pair": [0, 3], "grid": 101}},
        "q1q2": {"summary": "E(q1, q2) off-axis, as SVG", "value": {
            "manipulator": ex.PAPER_CHAIN, "dx": 1.0, "dy": 0.5, "pair": [0, 1], "grid": 81, "format": "svg"}}})],
    settings: Annotated[Settings, Depends(get_settings_dep)],
) -> Response:
    ctx = check_manipulator(req.manipulator, settings)
    fmt = negotiate(req.format, request.headers.get("accept"))
    return _reply(await run_task(request, plot_landscape_task, req, fmt, fields=ctx), fmt, "landscape")


@router.post(
    "/shapes", operation_id="plot_shapes", response_class=Response, response_model=None,
    summary="Figure: the chain in every equilibrium, coloured by stability",
    description="One panel per equilibrium of `/v1/equilibria` (at most `max_panels`, the lowest energies): both "
                "triangles of every segment, the joints and both springs, green when stable, orange for a saddle, "
                "red for a maximum, titled with Table 2's shape label (U / ZU / Z). " + _FORMATS,
    responses=image_responses("unreachable_target", "solver_failed"))
async def plot_shapes(
    request: Request,
    req: Annotated[ps.PlotShapesRequest, Body(openapi_examples={
        "table2": {"summary": "Table 2: the six equilibria at dx = 0.1", "value": {
            "manipulator": ex.PAPER_CHAIN, "dx": 0.1, "dy": 0.0}}})],
    settings: Annotated[Settings, Depends(get_settings_dep)],
) -> Response:
    ctx = check_manipulator(req.manipulator, settings)
    fmt = negotiate(req.format, request.headers.get("accept"))
    return _reply(await run_task(request, plot_shapes_task, req, fmt, fields=ctx), fmt, "shapes")


@router.post(
    "/torque", operation_id="plot_torque", response_class=Response, response_model=None,
    summary="Figure: torque-angle curves of segments (Fig. 2)",
    description="`M(q)` of each segment (`Segment.torque`, the data of `/v1/segment/torque`) over its physical "
                "range `|q| < pi - 2 beta` (dotted bounds), or over `q` when given. " + _FORMATS,
    responses=image_responses())
async def plot_torque(
    request: Request,
    req: Annotated[ps.PlotTorqueRequest, Body(openapi_examples={
        "fig2": {"summary": "Fig. 2: rest lengths compared", "value": {"segments": [
            {"a": 1.0, "b": 1.0, "k": 1.0, "L0": 0.5}, {"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0},
            {"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.5}]}},
        "range": {"summary": "one segment over an explicit range, as SVG", "value": {
            "segments": [{"a": 1.0, "b": 1.0, "k": [1.0, 2.0], "L0": [1.0, 1.2]}],
            "q": {"start": -1.0, "stop": 1.0, "num": 201}, "format": "svg"}}})],
) -> Response:
    fmt = negotiate(req.format, request.headers.get("accept"))
    return _reply(await run_task(request, plot_torque_task, req, fmt, fields=FieldContext()), fmt, "torque")


@router.post(
    "/map", operation_id="plot_map", response_class=Response, response_model=None,
    summary="Figure: critical load over two design parameters",
    description="The critical load `P = -Fx0` (`tensegrity_opt.critical_force`, the data of `/v1/buckling`) with "
                "`param_x` and `param_y` (two of a, b, k, L0) set in every segment to each pair of `values_x`, "
                f"`values_y` (2..{ps.MAX_MAP_AXIS} each, strictly monotonic); blank where the straight chain is not "
                "a stable equilibrium. " + _FORMATS,
    responses=image_responses("invalid_parameter"))
async def plot_map(
    request: Request,
    req: Annotated[ps.PlotMapRequest, Body(openapi_examples={
        "k_L0": {"summary": "stiffness against rest length", "value": {
            "manipulator": ex.PAPER_CHAIN, "param_x": "k", "values_x": {"start": 0.5, "stop": 2.0, "num": 16},
            "param_y": "L0", "values_y": {"start": 0.5, "stop": 2.5, "num": 21}}},
        "a_L0": {"summary": "triangle height against rest length (unstable region blank), as SVG", "value": {
            "manipulator": ex.PAPER_CHAIN, "param_x": "a", "values_x": [0.4, 0.6, 0.8, 1.0, 1.2],
            "param_y": "L0", "values_y": [0.5, 1.0, 1.5, 2.0], "boundary": "guided", "format": "svg"}}})],
    settings: Annotated[Settings, Depends(get_settings_dep)],
) -> Response:
    ctx = check_manipulator(req.manipulator, settings)
    fmt = negotiate(req.format, request.headers.get("accept"))
    return _reply(await run_task(request, plot_map_task, req, fmt, fields=ctx), fmt, "map")


_STRAIGHT = {"q": [0.0, 0.0, 0.0, 0.0]}
_GUIDED = {"kind": "guided", "direction": [-1.0, 0.0]}
_PARTIAL = ("The continuation stops shortly before the server's time limit and draws what it has (the title says "
            "so). ")


@router.post(
    "/branch", operation_id="plot_branch", response_class=Response, response_model=None,
    summary="Figure: branch diagram, coloured by Morse index, events marked",
    description="`y` against `x` along the branch of `/v1/branch` (or, with `depth`, every branch of "
                "`/v1/bifurcation-diagram`; `stop_at` and `direction` are for one branch only): stable pieces "
                "solid, unstable ones dashed and coloured by their Morse index, folds, branch points and joint "
                "limits marked, the legend beside the axes, the axes in the caller's units. " + _PARTIAL + _FORMATS,
    responses=image_responses("continuation_too_long", "bad_start", "too_many_points", "no_equilibrium"))
async def plot_branch(
    request: Request,
    req: Annotated[ps.PlotBranchRequest, Body(openapi_examples={
        "guided": {"summary": "the paper's chain, guided: Fy against t with the three branch points", "value": {
            "manipulator": ex.PAPER_CHAIN, "start": _STRAIGHT, "control": _GUIDED, "t_max": 2.0, "x": "t",
            "y": "fy"}},
        "diagram": {"summary": "the bifurcation diagram, t against q1, as SVG", "value": {
            "manipulator": ex.PAPER_CHAIN, "start": _STRAIGHT, "control": _GUIDED, "t_max": 2.0, "t_min": -0.2,
            "depth": 1, "max_points": 200, "x": "q1", "y": "t", "format": "svg"}}})],
    settings: Annotated[Settings, Depends(get_settings_dep)],
) -> Response:
    ctx = check_path(req, settings)
    fmt = negotiate(req.format, request.headers.get("accept"))
    return _reply(await run_task(request, plot_branch_task, req, fmt, path_deadline(settings), fields=ctx,
                                 placement=Placement.HEAVY),
                  fmt, "branch")


@router.post(
    "/limit-load", operation_id="plot_limit_load", response_class=Response, response_model=None,
    summary="Figure: the load path of a limit load, the limit point and quasi-buckling load marked",
    description="The load `t` against the tip displacement along it on the path of `/v1/limit-load`, in pieces of "
                "constant Morse index, with the limit point (fold or bifurcation) or the path's end, and the "
                "quasi-buckling load as a dotted level. " + _PARTIAL + _FORMATS,
    responses=image_responses("continuation_too_long", "bad_start", "too_many_points"))
async def plot_limit_load(
    request: Request,
    req: Annotated[ps.PlotLimitLoadRequest, Body(openapi_examples={
        "guided": {"summary": "the paper's chain, guided: the bifurcation at 0.572793", "value": {
            "manipulator": ex.PAPER_CHAIN, "direction": [-1.0, 0.0], "boundary": "guided", "start": _STRAIGHT}}})],
    settings: Annotated[Settings, Depends(get_settings_dep)],
) -> Response:
    ctx = check_path(req, settings, LIMIT_LOAD_ALIASES)
    fmt = negotiate(req.format, request.headers.get("accept"))
    return _reply(await run_task(request, plot_limit_load_task, req, fmt, path_deadline(settings), fields=ctx,
                                 placement=Placement.HEAVY), fmt, "limit-load")


@router.post(
    "/boundary", operation_id="plot_boundary", response_class=Response, response_model=None,
    summary="Figure: a stability boundary, critical t against the second parameter, cusps marked",
    description="The boundary of `/v1/stability-boundary` drawn as `t` against `p`, its cusps marked. " + _PARTIAL
                + _FORMATS,
    responses=image_responses("continuation_too_long", "too_many_points"))
async def plot_boundary(
    request: Request,
    req: Annotated[ps.PlotBoundaryRequest, Body(openapi_examples={
        "guided": {"summary": "the paper's chain, guided, over the asymmetry", "value": {
            "manipulator": ex.PAPER_CHAIN, "control": _GUIDED, "parameter": "asymmetry", "p_min": -0.1,
            "p_max": 0.1}}})],
    settings: Annotated[Settings, Depends(get_settings_dep)],
) -> Response:
    ctx = check_path(req, settings)
    fmt = negotiate(req.format, request.headers.get("accept"))
    return _reply(await run_task(request, plot_boundary_task, req, fmt, path_deadline(settings), fields=ctx,
                                 placement=Placement.HEAVY),
                  fmt, "boundary")


@router.post(
    "/atlas", operation_id="plot_atlas", response_class=Response, response_model=None,
    summary="Figure: the stability atlas, stable equilibria over (dx, dy) with the switch and branch-end curves",
    description="The number of stable equilibria of the held tip as a map over the deflection (one cell per "
                "target, one colour per count, unreachable targets hatched light grey, failed ones dark), the "
                "curves where the least-energy branch switches (solid) and where stable branches end (dashed) with "
                "their crossings marked, the legend beside the axes. Body: that of `/v1/atlas` (the atlas computed "
                "for the figure), or `{\"job\": id}` for a finished atlas job (`GET /v1/jobs/{id}/atlas`: 404 for "
                "an unknown job, 409 `job_not_done`, 422 `invalid_parameter` on `job` for another analysis). "
                + ATLAS_LIMITS + " " + _FORMATS,
    responses={**image_responses("atlas_too_large", "bad_grid", "not_an_atlas"),
               404: {"model": ErrorOut, "description": "`job`: no job with this id (or someone else's).",
                     "content": {"application/json": {"examples": {"not_found": {
                         "summary": "unknown job id", "value": {
                             "code": "not_found", "message": "no job with id '0123456789abcdef0123456789abcdef'",
                             "field": "job"}}}}}},
               409: {"model": ErrorOut, "description": "`job`: the job is not done (`job_not_done`).",
                     "content": {"application/json": {"examples": {"job_not_done": {
                         "summary": "the job still runs", "value": {
                             "code": "job_not_done", "field": "job", "details": {"status": "running", "done": 4,
                                                                                 "total": 9},
                             "message": "job '3f0c9a4e1b7d4c2a9e8f6d5c4b3a2910' is running (4 of 9 points): its "
                                        "atlas is made from the rows of a done job"}}}}}}})
async def plot_atlas(
    request: Request, runner: Runner, owner: Owner,
    req: Annotated[ps.PlotAtlasRequest, Body(openapi_examples={
        "bistable": {"summary": "a bistable chain (a = 0.5), 3 x 3 targets", "value": ATLAS_REQUEST_EXAMPLE},
        "job": {"summary": "the atlas of a finished atlas job, as SVG", "value": {
            "job": "3f0c9a4e1b7d4c2a9e8f6d5c4b3a2910", "format": "svg"}}})],
    settings: Annotated[Settings, Depends(get_settings_dep)],
) -> Response:
    fmt = negotiate(req.format, request.headers.get("accept"))
    if isinstance(req, ps.PlotAtlasJobRequest):
        spec, rows, ctx = await run_in_threadpool(finished_atlas_job, runner, owner, req.job, "job")
        data = await run_task(request, plot_job_atlas_task, spec, rows, req, fmt, path_deadline(settings),
                              fields=ctx, placement=Placement.HEAVY)
    else:
        ctx = check_manipulator(req.manipulator, settings)
        check_homotopy(req, settings)
        check_atlas_targets(req, settings)
        data = await run_task(request, plot_atlas_task, req, fmt, path_deadline(settings), fields=ctx,
                              placement=Placement.HEAVY)
    return _reply(data, fmt, "atlas")


_PLAN = ex.PAPER_CHAIN


@router.post(
    "/plan", operation_id="plot_plan", response_class=Response, response_model=None,
    summary="Figure: a rest-length plan, per step the rest lengths, the margin and the tip path with the targets",
    description="The plan of `/v1/control/plan` (the same body, computed for the figure): the rest lengths of every "
                "spring per step (spring 1 solid, spring 2 dashed, one colour per segment), the stability margin "
                "per step with the required one dotted, and the tip path with the targets; infeasible steps are "
                "shaded and their best reachable tips marked, the legend below the panels. " + PLAN_LIMITS + " "
                + _FORMATS,
    responses=image_responses("too_many_steps"))
async def plot_plan(
    request: Request,
    req: Annotated[ps.PlotPlanRequest, Body(openapi_examples={
        "arc": {"summary": "the paper's chain, the tip along a short arc under a small load",
                "value": PLAN_REQUEST_EXAMPLE},
        "rate_limited": {"summary": "a bending arc, its third target out of reach of the rate limit, as SVG", "value": {
            "manipulator": _PLAN, "targets": [[7.997, 0.2], [7.986, 0.4], [7.369, 1.399], [7.945, 0.797],
                                                 [7.914, 0.994]],
            "rate_limit": 0.05, "margin": 0.3, "format": "svg"}}})],
    settings: Annotated[Settings, Depends(get_settings_dep)],
) -> Response:
    ctx = check_plan(req, settings)
    fmt = negotiate(req.format, request.headers.get("accept"))
    return _reply(await run_task(request, plot_plan_task, req, fmt, path_deadline(settings), fields=ctx,
                                 placement=Placement.KILLABLE), fmt,
                  "plan")


@router.post(
    "/simulation", operation_id="plot_simulation", response_class=Response, response_model=None,
    summary="Figure: the hysteresis loop of a quasi-static simulation, the snaps as arrows from fold to landing",
    description="The simulation of `/v1/control/simulate` (the same body, computed for the figure): the driving "
                "input against the tip's response sample by sample (a free tip under varying loads: the load "
                "component that varies most against the deflection along it; varying preloads: the preload "
                "parameter `p = d . (L0 - L0(0))` against the deflection that varies most; a held tip: the holding "
                "force against the held deflection), each snap an arrow from its fold to its landing, a joint-limit "
                "end marked, the legend beside the axes. " + SIMULATION_LIMITS + " " + _FORMATS,
    responses=image_responses("too_many_steps", "continuation_too_long", "bad_start", "unreachable_target"))
async def plot_simulation(
    request: Request,
    req: Annotated[ps.PlotSimulationRequest, Body(openapi_examples={
        "load_cycle": {"summary": "a load cycle along y on three bistable segments: two snaps (hysteresis)",
                       "value": SIMULATION_REQUEST_EXAMPLE},
        "held": {"summary": "the tip of the paper's chain held and pushed in along x, as SVG", "value": {
            "manipulator": _PLAN, "tip": "held", "targets": [[0.1, 0.0], [0.3, 0.0], [0.5, 0.0], [0.7, 0.0]],
            "format": "svg"}}})],
    settings: Annotated[Settings, Depends(get_settings_dep)],
) -> Response:
    ctx = check_simulation(req, settings)
    fmt = negotiate(req.format, request.headers.get("accept"))
    return _reply(await run_task(request, plot_simulation_task, req, fmt, path_deadline(settings), fields=ctx,
                                 placement=Placement.HEAVY),
                  fmt, "simulation")
