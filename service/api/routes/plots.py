"""Figures: ``POST /v1/plots/{curve,landscape,shapes,torque,map,branch,limit-load,imperfection,boundary,atlas,plan,
simulation}``
answering PNG or SVG.

One table, :data:`FIGURES`, declares every figure kind (its request, examples, words, limits, task and placement);
:func:`register` makes its route. Each route validates its request, applies the server's limits and hands the
figure's task (:mod:`service.tasks.plots`: the library call and matplotlib's rendering, both CPU-bound) to the
dispatcher, then answers the bytes: ``image/png`` by default, ``image/svg+xml`` when the body says
``"format": "svg"`` or, without ``format``, when the ``Accept`` header prefers ``image/svg+xml``. Refusals are
the usual JSON ``ErrorOut``.

Every figure is also offered as a job, ``POST /v1/plots/{kind}/job`` (the same body; the atlas in its grid form):
202 with the job's id at once, then ``GET /v1/jobs/{id}`` for its progress (one row per step) and
``GET /v1/jobs/{id}/figure`` for the image. It runs in the job runner's threads (:mod:`service.jobs.runner`) under
``TENSEGRITY_JOBS_POINT_TIMEOUT`` instead of the request's time limit; a synchronous figure that runs out of time
answers a 504 naming its job route.
"""

from __future__ import annotations

import copy
import inspect
from collections.abc import Awaitable, Callable
from dataclasses import dataclass
from typing import Annotated, Any

from fastapi import APIRouter, Body, Request
from starlette.concurrency import run_in_threadpool
from starlette.responses import JSONResponse, Response

from ... import examples as ex
from ...adapters.fields import LIMIT_LOAD_ALIASES, FieldContext
from ...adapters.inputs import modes_pose
from ...config import Settings
from ...schemas import ErrorOut
from ...schemas import jobs as js
from ...schemas import plots as ps
from ...schemas.atlas import ATLAS_REQUEST_EXAMPLE
from ...schemas.control import PLAN_REQUEST_EXAMPLE, SIMULATION_REQUEST_EXAMPLE
from ...tasks import plots as tasks
from ..deps import (
    check_atlas_targets,
    check_homotopy,
    check_manipulator,
    check_path,
    check_plan,
    check_simulation,
    finished_atlas_job,
    get_owner,
    get_runner,
    path_deadline,
    placement,
)
from ..dispatch import Placement, run_task
from ..json_bodies import JSONBodyRoute
from ..openapi import ATLAS_LIMITS, PLAN_LIMITS, SIMULATION_LIMITS, SOLVE_ERRORS, error_responses

__all__ = ["router", "negotiate", "image_responses", "Figure", "FIGURES", "register", "job_route", "timeout_hint"]

router = APIRouter(route_class=JSONBodyRoute, prefix="/v1/plots", tags=["plots"])

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


def _job_error(description: str, name: str, summary: str, value: dict[str, Any]) -> dict[str, Any]:
    """A refusal of the atlas figure's ``job`` form (``ErrorOut``, one example)."""
    return {"model": ErrorOut, "description": description,
            "content": {"application/json": {"examples": {name: {"summary": summary, "value": value}}}}}


_FORMATS = ("Answers `image/png`, or `image/svg+xml` with `\"format\": \"svg\"` (or, without `format`, an "
            "`Accept` header preferring `image/svg+xml`); `dpi` sets the PNG resolution.")
_PARTIAL = ("The continuation stops shortly before the server's time limit and draws what it has (the title says "
            "so). ")
_STRAIGHT = {"q": [0.0, 0.0, 0.0, 0.0]}
_GUIDED = {"kind": "guided", "direction": [-1.0, 0.0]}
_M = ex.PAPER_CHAIN


# ---------------------------------------------------------------------------- the figure kinds
def _chain(req: Any, settings: Settings) -> FieldContext:
    return check_manipulator(req.manipulator, settings)


def _modes(req: Any, settings: Settings) -> FieldContext:
    modes_pose(req)                      # a deflection or a force: refused before a job is stored
    return _chain(req, settings)


def _no_chain(req: Any, settings: Settings) -> FieldContext:
    return FieldContext()


def _limit_load(req: Any, settings: Settings) -> FieldContext:
    return check_path(req, settings, LIMIT_LOAD_ALIASES)


def _atlas_grid(req: Any, settings: Settings) -> FieldContext:
    ctx = check_manipulator(req.manipulator, settings)
    check_homotopy(req, settings)
    check_atlas_targets(req, settings)
    return ctx


def _curve_placement(req: Any, settings: Settings) -> Placement:
    return placement(settings, req.manipulator, branch_all=req.branch == "all")


#: A figure's task on stored inputs, the inputs, and their field context.
Stored = tuple[Callable[..., bytes], tuple[Any, ...], FieldContext]


async def _atlas_job(request: Request, req: Any) -> Stored | None:
    """The atlas figure's ``job`` form: its task, the task's stored inputs and their field context (the job is read
    from the store in a thread); ``None`` for every other request."""
    if not isinstance(req, ps.PlotAtlasJobRequest):
        return None
    runner, owner = await get_runner(request), await get_owner(request)
    spec, rows, ctx = await run_in_threadpool(finished_atlas_job, runner, owner, req.job, "job")
    return tasks.plot_job_atlas_task, (spec, rows), ctx


@dataclass(frozen=True)
class Figure:
    """One figure kind: ``POST /v1/plots/<kind>``, operation ``plot_<kind>`` (``-`` read as ``_``), answered as
    ``<kind>.png`` or ``<kind>.svg``.

    ``model`` is the request body with its OpenAPI ``examples``; ``summary``, ``description`` and ``responses``
    document the operation. ``limits(req, settings)`` applies the server's limits and gives the request's field
    context; ``task(req, fmt, *args)`` draws it (:mod:`service.tasks.plots`), with ``path_deadline`` as its one
    argument when ``continuation``; ``placement`` says where it runs (a :class:`Placement`, or
    ``placement(req, settings)``). ``stored(request, req)``, where given, may name another task instead, on
    stored inputs, with their field context: ``(task, inputs, context)`` (the atlas of a job).
    """

    kind: str
    model: Any
    examples: dict[str, Any]
    summary: str
    description: str
    responses: dict[int | str, Any]
    task: Callable[..., bytes]
    limits: Callable[[Any, Settings], FieldContext] = _chain
    continuation: bool = False
    placement: Placement | Callable[[Any, Settings], Placement] = Placement.LIGHT
    stored: Callable[[Request, Any], Awaitable[Stored | None]] | None = None

    def where(self, req: Any, settings: Settings) -> Placement:
        return self.placement if isinstance(self.placement, Placement) else self.placement(req, settings)


FIGURES: tuple[Figure, ...] = (
    Figure(
        "curve", ps.PlotCurveRequest, task=tasks.plot_curve_task, placement=_curve_placement,
        summary="Figure: force-deflection curves with their jumps (Fig. 6)",
        description="`Fx` and `Fy` against `dx` along the least-energy stable branch "
                    "(`tensegrity_opt.force_deflection`, the data of `/v1/force-deflection`): the buckling jump at "
                    "dx -> 0+ from 0 to the critical force drawn as a vertical dashed segment, branch switches "
                    "dotted; `branch = \"all\"` also draws every branch, unstable parts dashed. " + _FORMATS,
        responses=image_responses("unreachable_target", "no_equilibrium"),
        examples={
            "fig6": {"summary": "Fig. 6: the paper's chain, dx from 0 to 2", "value": {
                "manipulator": _M, "dx": {"start": 0.0, "stop": 2.0, "num": 41}, "dy": 0.0}},
            "all": {"summary": "every branch, as SVG", "value": {
                "manipulator": _M, "dx": {"start": 0.0, "stop": 1.0, "num": 21}, "branch": "all",
                "format": "svg"}}}),
    Figure(
        "landscape", ps.PlotLandscapeRequest, task=tasks.plot_landscape_task,
        summary="Figure: energy landscape with every equilibrium marked (n = 4, Figs. 4-5)",
        description="Energy contours `E(q_i, q_j)` on both elbow branches (`tensegrity_opt.energy_landscape`, the "
                    "data of `/v1/energy-landscape`) with every equilibrium of `/v1/equilibria` marked at its "
                    "`(q_i, q_j)`, coloured by stability and labelled with its shape. n = 4 only (other n: 422 "
                    "`unsupported`). Without `span` the axes cover the reachable region. " + _FORMATS,
        responses=image_responses("unsupported", "unreachable_target", "solver_failed"),
        examples={
            "fig4": {"summary": "Fig. 4: E(q1, q4) at dx = 0.1", "value": {
                "manipulator": _M, "dx": 0.1, "dy": 0.0, "pair": [0, 3]}},
            "q1q2": {"summary": "E(q1, q2) off-axis, as SVG", "value": {
                "manipulator": _M, "dx": 1.0, "dy": 0.5, "pair": [0, 1], "grid": 81, "format": "svg"}}}),
    Figure(
        "shapes", ps.PlotShapesRequest, task=tasks.plot_shapes_task,
        summary="Figure: the chain in every equilibrium, coloured by stability",
        description="One panel per equilibrium of `/v1/equilibria` (at most `max_panels`, the lowest energies): both "
                    "triangles of every segment, the joints and both springs, green when stable, orange for a "
                    "saddle, red for a maximum, titled with Table 2's shape label (U / ZU / Z). " + _FORMATS,
        responses=image_responses("unreachable_target", "solver_failed"),
        examples={
            "table2": {"summary": "Table 2: the six equilibria at dx = 0.1", "value": {
                "manipulator": _M, "dx": 0.1, "dy": 0.0}}}),
    Figure(
        "modes", ps.PlotModesRequest, task=tasks.plot_modes_task, limits=_modes,
        summary="Figure: the vibration modes of an equilibrium",
        description="One panel per mode of `/v1/modes` (at most `max_panels`, the lowest): the equilibrium's centre "
                    "line, the chain displaced along the mode both ways (largest joint excursion `excursion` rad), "
                    "the masses as dots, the frequency in the title. A chain without mass: 422 `invalid_parameter`, "
                    "field `mass`. " + _FORMATS,
        responses=image_responses("unreachable_target", "solver_failed"),
        examples={
            "paper": {"summary": "the paper's chain with masses 0.1 at dx = 1", "value": {
                "manipulator": {**_M, "mass": 0.1}, "dx": 1.0, "dy": 0.0}}}),
    Figure(
        "holding", ps.PlotHoldingRequest, task=tasks.plot_holding_task,
        summary="Figure: the chain under its weight as its base turns, and the least design holding it",
        description="For `directions` gravity directions (base orientations) over a full turn (the chain's gravity "
                    "magnitude, 9.81 without `gravity`): left, the rest configuration under its weight drawn with "
                    "gravity down; "
                    "right, the least total stiffness (`vary: [k]`) or preload tension (`vary: [L0]`) of "
                    "`/v1/design/holding` holding it within `max_angle` with `margin`, against the base's elevation "
                    "(a cross where none holds it), and the sag without a design. At most 60 segments. " + _FORMATS,
        responses=image_responses("solver_failed"),
        examples={
            "arm": {"summary": "a 6-segment arm over 16 orientations, held within 0.05 rad", "value": {
                "manipulator": ps.UPRIGHT_ARM, "max_angle": 0.05, "directions": 16}}}),
    Figure(
        "torque", ps.PlotTorqueRequest, task=tasks.plot_torque_task, limits=_no_chain,
        summary="Figure: torque-angle curves of segments (Fig. 2)",
        description="`M(q)` of each segment (`Segment.torque`, the data of `/v1/segment/torque`) over its physical "
                    "range `|q| < pi - 2 beta` (dotted bounds), or over `q` when given. " + _FORMATS,
        responses=image_responses(),
        examples={
            "fig2": {"summary": "Fig. 2: rest lengths compared", "value": {"segments": [
                {"a": 1.0, "b": 1.0, "k": 1.0, "L0": 0.5}, {"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0},
                {"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.5}]}},
            "range": {"summary": "one segment over an explicit range, as SVG", "value": {
                "segments": [{"a": 1.0, "b": 1.0, "k": [1.0, 2.0], "L0": [1.0, 1.2]}],
                "q": {"start": -1.0, "stop": 1.0, "num": 201}, "format": "svg"}}}),
    Figure(
        "map", ps.PlotMapRequest, task=tasks.plot_map_task,
        summary="Figure: critical load over two design parameters",
        description="The critical load `P = -Fx0` (`tensegrity_opt.critical_force`, the data of `/v1/buckling`) with "
                    "`param_x` and `param_y` (two of a, b, k, L0) set in every segment to each pair of `values_x`, "
                    f"`values_y` (2..{ps.MAX_MAP_AXIS} each, strictly monotonic); blank where the straight chain is "
                    "not a stable equilibrium. " + _FORMATS,
        responses=image_responses("invalid_parameter"),
        examples={
            "k_L0": {"summary": "stiffness against rest length", "value": {
                "manipulator": _M, "param_x": "k", "values_x": {"start": 0.5, "stop": 2.0, "num": 16},
                "param_y": "L0", "values_y": {"start": 0.5, "stop": 2.5, "num": 21}}},
            "a_L0": {"summary": "triangle height against rest length (unstable region blank), as SVG", "value": {
                "manipulator": _M, "param_x": "a", "values_x": [0.4, 0.6, 0.8, 1.0, 1.2],
                "param_y": "L0", "values_y": [0.5, 1.0, 1.5, 2.0], "boundary": "guided", "format": "svg"}}}),
    Figure(
        "branch", ps.PlotBranchRequest, task=tasks.plot_branch_task, limits=check_path, continuation=True,
        placement=Placement.HEAVY,
        summary="Figure: branch diagram, coloured by Morse index, events marked",
        description="`y` against `x` along the branch of `/v1/branch` (or, with `depth`, every branch of "
                    "`/v1/bifurcation-diagram`; `stop_at` and `direction` are for one branch only): stable pieces "
                    "solid, unstable ones dashed and coloured by their Morse index, folds, branch points and joint "
                    "limits marked, the legend beside the axes, the axes in the caller's units. " + _PARTIAL
                    + _FORMATS,
        responses=image_responses("continuation_too_long", "bad_start", "too_many_points", "no_equilibrium"),
        examples={
            "guided": {"summary": "the paper's chain, guided: Fy against t with the three branch points", "value": {
                "manipulator": _M, "start": _STRAIGHT, "control": _GUIDED, "t_max": 2.0, "x": "t", "y": "fy"}},
            "diagram": {"summary": "the bifurcation diagram, t against q1, as SVG", "value": {
                "manipulator": _M, "start": _STRAIGHT, "control": _GUIDED, "t_max": 2.0, "t_min": -0.2,
                "depth": 1, "max_points": 200, "x": "q1", "y": "t", "format": "svg"}}}),
    Figure(
        "limit-load", ps.PlotLimitLoadRequest, task=tasks.plot_limit_load_task, limits=_limit_load,
        continuation=True, placement=Placement.HEAVY,
        summary="Figure: the load path of a limit load, the limit point and quasi-buckling load marked",
        description="The load `t` against the tip displacement along it on the path of `/v1/limit-load`, in pieces "
                    "of constant Morse index, with the limit point (fold or bifurcation) or the path's end, and the "
                    "quasi-buckling load as a dotted level. " + _PARTIAL + _FORMATS,
        responses=image_responses("continuation_too_long", "bad_start", "too_many_points"),
        examples={
            "guided": {"summary": "the paper's chain, guided: the bifurcation at 0.572793", "value": {
                "manipulator": _M, "direction": [-1.0, 0.0], "boundary": "guided", "start": _STRAIGHT}}}),
    Figure(
        "imperfection", ps.PlotImperfectionRequest, task=tasks.plot_imperfection_task, limits=_limit_load,
        continuation=True, placement=Placement.HEAVY,
        summary="Figure: the imperfection-sensitivity curve, limit load against the imperfection's amplitude",
        description="The limit loads of `/v1/imperfection-sensitivity` against the amplitude, a marker per kind "
                    "(fold, bifurcation, joint limit; no limit and unknown at the bottom), the perfect chain's limit "
                    "load as a line and the fitted small-imperfection law dashed where one applies. " + _PARTIAL
                    + _FORMATS,
        responses=image_responses("continuation_too_long", "too_many_points"),
        examples={
            "guided": {"summary": "the paper's chain, guided", "value": {
                "manipulator": _M, "amplitudes": [0.0, 0.005, 0.01, 0.02, 0.03, 0.04, 0.061]}}}),
    Figure(
        "boundary", ps.PlotBoundaryRequest, task=tasks.plot_boundary_task, limits=check_path, continuation=True,
        placement=Placement.HEAVY,
        summary="Figure: a stability boundary, critical t against the second parameter, cusps marked",
        description="The boundary of `/v1/stability-boundary` drawn as `t` against `p`, its cusps marked. "
                    + _PARTIAL + _FORMATS,
        responses=image_responses("continuation_too_long", "too_many_points"),
        examples={
            "guided": {"summary": "the paper's chain, guided, over the asymmetry", "value": {
                "manipulator": _M, "control": _GUIDED, "parameter": "asymmetry", "p_min": -0.1, "p_max": 0.1}}}),
    Figure(
        "atlas", ps.PlotAtlasRequest, task=tasks.plot_atlas_task, limits=_atlas_grid, stored=_atlas_job,
        continuation=True, placement=Placement.HEAVY,
        summary="Figure: the stability atlas, stable equilibria over (dx, dy) with the switch and branch-end curves",
        description="The number of stable equilibria of the held tip as a map over the deflection (one cell per "
                    "target, one colour per count, unreachable targets hatched light grey, failed ones dark), the "
                    "curves where the least-energy branch switches (solid) and where stable branches end (dashed) "
                    "with their crossings marked, the legend beside the axes. Body: that of `/v1/atlas` (the atlas "
                    "computed for the figure), or `{\"job\": id}` for a finished atlas job "
                    "(`GET /v1/jobs/{id}/atlas`: 404 for an unknown job, 409 `job_not_done`, 422 "
                    "`invalid_parameter` on `job` for another analysis). " + ATLAS_LIMITS + " " + _FORMATS,
        responses={
            **image_responses("atlas_too_large", "bad_grid", "not_an_atlas"),
            404: _job_error("`job`: no job with this id (or someone else's).", "not_found", "unknown job id", {
                "code": "not_found", "message": "no job with id '0123456789abcdef0123456789abcdef'", "field": "job"}),
            409: _job_error("`job`: the job is not done (`job_not_done`).", "job_not_done", "the job still runs", {
                "code": "job_not_done", "field": "job", "details": {"status": "running", "done": 4, "total": 9},
                "message": "job '3f0c9a4e1b7d4c2a9e8f6d5c4b3a2910' is running (4 of 9 points): its atlas is made "
                           "from the rows of a done job"})},
        examples={
            "bistable": {"summary": "a bistable chain (a = 0.5), 3 x 3 targets", "value": ATLAS_REQUEST_EXAMPLE},
            "job": {"summary": "the atlas of a finished atlas job, as SVG", "value": {
                "job": "3f0c9a4e1b7d4c2a9e8f6d5c4b3a2910", "format": "svg"}}}),
    Figure(
        "plan", ps.PlotPlanRequest, task=tasks.plot_plan_task, limits=check_plan, continuation=True,
        placement=Placement.KILLABLE,
        summary="Figure: a rest-length plan, per step the rest lengths, the margin and the tip path with the targets",
        description="The plan of `/v1/control/plan` (the same body, computed for the figure): the rest lengths of "
                    "every spring per step (spring 1 solid, spring 2 dashed, one colour per segment), the stability "
                    "margin per step with the required one dotted, and the tip path with the targets; infeasible "
                    "steps are shaded and their best reachable tips marked, the legend below the panels. "
                    + PLAN_LIMITS + " " + _FORMATS,
        responses=image_responses("too_many_steps"),
        examples={
            "arc": {"summary": "the paper's chain, the tip along a short arc under a small load",
                    "value": PLAN_REQUEST_EXAMPLE},
            "rate_limited": {"summary": "a bending arc, its third target out of reach of the rate limit, as SVG",
                             "value": {"manipulator": _M, "targets": [[7.997, 0.2], [7.986, 0.4], [7.369, 1.399],
                                                                      [7.945, 0.797], [7.914, 0.994]],
                                       "rate_limit": 0.05, "dt": 1.0, "margin": 0.3, "format": "svg"}}}),
    Figure(
        "simulation", ps.PlotSimulationRequest, task=tasks.plot_simulation_task, limits=check_simulation,
        continuation=True, placement=Placement.HEAVY,
        summary="Figure: the hysteresis loop of a quasi-static simulation, the snaps as arrows from fold to landing",
        description="The simulation of `/v1/control/simulate` (the same body, computed for the figure): the driving "
                    "input against the tip's response sample by sample (a free tip under varying loads: the load "
                    "component that varies most against the deflection along it; varying preloads: the preload "
                    "parameter `p = d . (L0 - L0(0))` against the deflection that varies most; a held tip: the "
                    "holding force against the held deflection), each snap an arrow from its fold to its landing, a "
                    "joint-limit end marked, the legend beside the axes. " + SIMULATION_LIMITS + " " + _FORMATS,
        responses=image_responses("too_many_steps", "continuation_too_long", "bad_start", "unreachable_target"),
        examples={
            "load_cycle": {"summary": "a load cycle along y on three bistable segments: two snaps (hysteresis)",
                           "value": SIMULATION_REQUEST_EXAMPLE},
            "held": {"summary": "the tip of the paper's chain held and pushed in along x, as SVG", "value": {
                "manipulator": _M, "tip": "held", "targets": [[0.1, 0.0], [0.3, 0.0], [0.5, 0.0], [0.7, 0.0]],
                "format": "svg"}}}),
)


# ---------------------------------------------------------------------------- the routes
def job_route(kind: str) -> str:
    """The job form of the figure ``kind``."""
    return f"/v1/plots/{kind}/job"


def timeout_hint(kind: str) -> str:
    """What a 504 of the figure ``kind`` adds to its message: the job form."""
    return (f"a figure that needs longer runs as a job: POST {job_route(kind)} with the same body (202, its id), "
            "follow GET /v1/jobs/{id}, then GET /v1/jobs/{id}/figure")


def _reply(data: bytes, fmt: str, kind: str) -> Response:
    return Response(content=data, media_type=MEDIA[fmt],
                    headers={"Content-Disposition": f'inline; filename="{kind}.{fmt}"', "Vary": "Accept"})


def _endpoint(fig: Figure) -> Callable[..., Awaitable[Response]]:
    """The route of ``fig``: the limits, the format, the task handed to the dispatcher, the bytes answered."""

    async def endpoint(request: Request, req: Any) -> Response:
        settings: Settings = request.app.state.settings
        call = None if fig.stored is None else await fig.stored(request, req)
        if call is None:
            task, extra, ctx = fig.task, (), fig.limits(req, settings)
        else:
            task, extra, ctx = call
        fmt = negotiate(req.format, request.headers.get("accept"))
        args = (req, fmt, path_deadline(settings), *extra) if fig.continuation else (req, fmt)
        data = await run_task(request, task, *args, fields=ctx, placement=fig.where(req, settings),
                              timeout_hint=timeout_hint(fig.kind))
        return _reply(data, fmt, fig.kind)

    endpoint.__name__ = endpoint.__qualname__ = "plot_" + fig.kind.replace("-", "_")
    body = Annotated[fig.model, Body(openapi_examples=fig.examples)]
    endpoint.__signature__ = inspect.Signature(  # type: ignore[attr-defined]
        [inspect.Parameter("request", inspect.Parameter.POSITIONAL_OR_KEYWORD, annotation=Request),
         inspect.Parameter("req", inspect.Parameter.POSITIONAL_OR_KEYWORD, annotation=body)],
        return_annotation=Response)
    return endpoint


def _job_endpoint(fig: Figure) -> Callable[..., Awaitable[Response]]:
    """The job form of ``fig``: the limits, the job stored (202 with its id); the figure is drawn by the job runner."""
    model = tasks.FIGURE_TASKS[fig.kind][0]

    async def endpoint(request: Request, req: Any) -> Response:
        settings: Settings = request.app.state.settings
        fig.limits(req, settings)
        runner, owner = await get_runner(request), await get_owner(request)
        fmt = req.format or "png"
        job = await run_in_threadpool(runner.submit_figure, fig.kind, fmt, req.model_dump(mode="json"),
                                      tasks.figure_steps(fig.kind, req), owner)
        return JSONResponse({"id": job["id"], "status": job["status"], "total": job["total"],
                             "analysis": job["analysis"]}, status_code=202,
                            headers={"Location": f"/v1/jobs/{job['id']}"})

    endpoint.__name__ = endpoint.__qualname__ = "submit_plot_" + fig.kind.replace("-", "_") + "_job"
    examples = {k: v for k, v in fig.examples.items() if k != "job"}
    body = Annotated[model, Body(openapi_examples=examples)]
    endpoint.__signature__ = inspect.Signature(  # type: ignore[attr-defined]
        [inspect.Parameter("request", inspect.Parameter.POSITIONAL_OR_KEYWORD, annotation=Request),
         inspect.Parameter("req", inspect.Parameter.POSITIONAL_OR_KEYWORD, annotation=body)],
        return_annotation=Response)
    return endpoint


def _job_responses(fig: Figure) -> dict[int | str, Any]:
    """202 with the job, and the refusals of the figure's limits and of the job store."""
    limits = {k: v for k, v in fig.responses.items() if k in (401, 413, 422)}
    return {
        202: {"description": "The figure job is stored (`queued`): follow `GET /v1/jobs/{id}` (`done` / `total` "
                             "steps), then `GET /v1/jobs/{id}/figure`.", "model": js.JobCreated,
              "headers": {"Location": {"description": "the job's URL", "schema": {"type": "string"}}},
              "content": {"application/json": {"example": {"id": "3f0c9a4e1b7d4c2a9e8f6d5c4b3a2910",
                                                           "status": "queued", "total": 2, "analysis": "figure"}}}},
        **limits,
        503: _job_error("The job store cannot be used (`jobs_unavailable`).", "jobs_unavailable",
                        "job store unavailable", {"code": "jobs_unavailable",
                                                  "message": "the job store cannot be used: disk I/O error"}),
    }


def register(fig: Figure) -> None:
    """Add the routes of ``fig`` to :data:`router`: the figure, and its job form."""
    endpoint = _endpoint(fig)
    router.post(f"/{fig.kind}", operation_id=endpoint.__name__, response_class=Response, response_model=None,
                summary=fig.summary, description=fig.description, responses=fig.responses)(endpoint)
    job = _job_endpoint(fig)
    router.post(f"/{fig.kind}/job", operation_id=job.__name__, status_code=202, response_class=JSONResponse,
                response_model=None, summary=f"{fig.summary.split(':', 1)[0]} as a job: "
                                             f"{fig.summary.split(':', 1)[-1].strip()}",
                description=f"The figure of `POST /v1/plots/{fig.kind}` (the same body"
                            + (", the grid form" if fig.kind == "atlas" else "") + ") computed as a background job: "
                            "202 at once with the job's `id` (`analysis: figure`, `total`: its steps"
                            + (": one per target, then the drawing and the image" if fig.kind == "atlas" else
                               ": the drawing and the image") + "). Follow it with `GET /v1/jobs/{id}` (`done`, "
                            "`progress`, one row per step, a failure as a row's `error` and the job's `message`), "
                            "then fetch the image with `GET /v1/jobs/{id}/figure` (PNG, or SVG with "
                            "`\"format\": \"svg\"` in the body). It runs under the server's "
                            "`TENSEGRITY_JOBS_POINT_TIMEOUT` (300 s by default) instead of the request time limit; "
                            "the server's limits on the request apply as to the figure. With API keys configured the "
                            "job belongs to the key that submitted it.",
                responses=_job_responses(fig))(job)


for _fig in FIGURES:
    register(_fig)
