"""Figures: ``POST /v1/plots/{curve,landscape,shapes,torque,map}`` answering PNG or SVG.

Each route validates its request, then draws the figure in the solver pool (the library call
and matplotlib's rendering are both CPU-bound) and answers the bytes: ``image/png`` by
default, ``image/svg+xml`` when the body says ``"format": "svg"`` or, without ``format``, when
the ``Accept`` header prefers ``image/svg+xml``. Refusals are the usual JSON ``ErrorOut``.
Drawing uses :mod:`tensegrity_opt.applications.plots` (matplotlib objects only, no pyplot: thread-safe).
"""

from __future__ import annotations

import copy
from typing import Annotated, Any

import numpy as np
from fastapi import APIRouter, Body, Depends, Request
from starlette.responses import Response

from .. import examples as ex
from ..compute import build_manipulator, build_segment, deflections
from ..config import Settings
from ..deps import check_manipulator, get_settings_dep, is_heavy, solve
from ..errors import FieldContext
from ..schemas import plots as ps
from . import SOLVE_ERRORS, error_responses

__all__ = ["router", "negotiate", "plot_curve_task", "plot_landscape_task", "plot_shapes_task", "plot_torque_task",
           "plot_map_task"]

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


# ---------------------------------------------------------------------------- jobs (solver threads)
def _image(fig: Any, fmt: str, dpi: int) -> bytes:
    from tensegrity_opt.applications import plots

    return plots.render(fig, fmt, dpi=dpi)


def plot_curve_task(req: ps.PlotCurveRequest, fmt: str) -> bytes:
    from tensegrity_opt.applications import plots

    m = build_manipulator(req.manipulator)
    return _image(plots.plot_curve(m, deflections(req.dx), req.dy, req.branch), fmt, req.dpi)


def plot_landscape_task(req: ps.PlotLandscapeRequest, fmt: str) -> bytes:
    from tensegrity_opt.applications import plots

    m = build_manipulator(req.manipulator)
    span: float | str = "auto" if req.span is None else req.span
    fig = plots.plot_landscape(m, req.dx, req.dy, pair=(req.pair[0], req.pair[1]), grid=req.grid, span=span)
    return _image(fig, fmt, req.dpi)


def plot_shapes_task(req: ps.PlotShapesRequest, fmt: str) -> bytes:
    from tensegrity_opt.applications import plots

    m = build_manipulator(req.manipulator)
    return _image(plots.plot_shapes(m, req.dx, req.dy, max_panels=req.max_panels), fmt, req.dpi)


def plot_torque_task(req: ps.PlotTorqueRequest, fmt: str) -> bytes:
    from tensegrity_opt.applications import plots

    segs = [build_segment(sg) for sg in req.segments]
    q = None if req.q is None else np.linspace(req.q.start, req.q.stop, req.q.num)
    return _image(plots.plot_torque(segs, q, num=req.num), fmt, req.dpi)


def _values(v: list[float] | ps.MapValuesRange) -> np.ndarray:
    if isinstance(v, ps.MapValuesRange):
        return np.linspace(v.start, v.stop, v.num)
    return np.asarray(v, dtype=float)


def plot_map_task(req: ps.PlotMapRequest, fmt: str) -> bytes:
    from tensegrity_opt.applications import plots

    m = build_manipulator(req.manipulator)
    fig = plots.plot_map(m, req.param_x, _values(req.values_x), req.param_y, _values(req.values_y), req.boundary)
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
    return _reply(await solve(request, plot_curve_task, req, fmt, ctx=ctx,
                              heavy=is_heavy(settings, req.manipulator, branch_all=req.branch == "all")),
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
    return _reply(await solve(request, plot_landscape_task, req, fmt, ctx=ctx), fmt, "landscape")


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
    return _reply(await solve(request, plot_shapes_task, req, fmt, ctx=ctx), fmt, "shapes")


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
    return _reply(await solve(request, plot_torque_task, req, fmt, ctx=FieldContext()), fmt, "torque")


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
    return _reply(await solve(request, plot_map_task, req, fmt, ctx=ctx), fmt, "map")
