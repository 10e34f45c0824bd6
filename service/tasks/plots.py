"""Tasks of the figure requests (``POST /v1/plots/<kind>``): each computes what its figure draws (the library call
of the matching endpoint, or that endpoint's own task) and answers the rendered bytes.

A figure task is ``task(req, fmt, *args)``: it draws the request's figure with
:mod:`tensegrity_opt.applications.plots` (matplotlib objects only, no pyplot: thread-safe) and renders it as
``fmt`` (``"png"`` or ``"svg"``) at the request's ``dpi``. ``deadline``, where a task takes it, is the soft
``time.monotonic()`` deadline of :func:`service.api.deps.path_deadline` (the figure draws what the computation
has by then). Matplotlib is imported on the first figure, not with the tasks.

A figure may also run as a job (``POST /v1/plots/<kind>/job``): :data:`FIGURE_TASKS` names each kind's request
and task, :func:`figure_steps` the job's steps (its ``total``) and :func:`figure_job_task` draws a stored request,
reporting each step done (the atlas: each target, then the drawing).
"""

from __future__ import annotations

import functools
import json
from collections.abc import Callable, Mapping
from typing import Any

from ..adapters.inputs import build_manipulator, build_segment, values
from ..schemas import plots as ps
from .control import find_plan, find_simulation
from .paths import (
    find_atlas,
    find_imperfection_sensitivity,
    find_job_atlas,
    find_limit_arms,
    find_limit_load,
    find_stability_boundary,
    trace_branches,
)

__all__ = ["plot_curve_task", "plot_landscape_task", "plot_shapes_task", "plot_torque_task", "plot_map_task",
           "plot_branch_task", "plot_limit_load_task", "plot_imperfection_task", "plot_boundary_task",
           "plot_atlas_task", "plot_job_atlas_task", "plot_plan_task", "plot_simulation_task", "FIGURE_TASKS",
           "FIGURE_ANALYSIS", "figure_steps", "figure_job_task", "figure_request"]


def _rendered(draw: Callable[..., Any]) -> Callable[..., bytes]:
    """The figure task of ``draw(req, *args)`` (a matplotlib figure): ``task(req, fmt, *args)``, its bytes."""

    @functools.wraps(draw)
    def task(req: Any, fmt: str, *args: Any) -> bytes:
        from tensegrity_opt.applications import plots

        return plots.render(draw(req, *args), fmt, dpi=req.dpi)

    return task


@_rendered
def plot_curve_task(req: ps.PlotCurveRequest) -> Any:
    from tensegrity_opt import force_deflection
    from tensegrity_opt.applications import plots

    m = build_manipulator(req.manipulator)
    return plots.plot_curve(force_deflection(m, values(req.dx), req.dy, branch=req.branch), m)


@_rendered
def plot_landscape_task(req: ps.PlotLandscapeRequest) -> Any:
    from tensegrity_opt import energy_landscape, find_equilibria
    from tensegrity_opt.analyses.equilibria.landscape import landscape_span
    from tensegrity_opt.applications import plots

    m = build_manipulator(req.manipulator)
    pair = (req.pair[0], req.pair[1])
    span = landscape_span(m, req.dx, req.dy, pair) if req.span is None else req.span
    land = energy_landscape(m, req.dx, req.dy, pair=pair, grid=req.grid, span=span)
    eqs = find_equilibria(m, req.dx, req.dy)
    return plots.plot_landscape(land, eqs, m, req.dx, req.dy)


@_rendered
def plot_shapes_task(req: ps.PlotShapesRequest) -> Any:
    from tensegrity_opt import find_equilibria
    from tensegrity_opt.applications import plots

    m = build_manipulator(req.manipulator)
    return plots.plot_shapes(find_equilibria(m, req.dx, req.dy), m, req.dx, req.dy, max_panels=req.max_panels,
                             spring_colors=req.spring_colors)


@_rendered
def plot_modes_task(req: ps.PlotModesRequest) -> Any:
    from tensegrity_opt.applications import plots

    from .equilibria import find_modes

    m, md = find_modes(req)
    return plots.plot_modes(md, m, excursion=req.excursion, max_panels=req.max_panels)


@_rendered
def plot_holding_task(req: ps.PlotHoldingRequest) -> Any:
    from tensegrity_opt.analyses.design.holding import holding_map
    from tensegrity_opt.applications import plots

    m = build_manipulator(req.manipulator)
    hmap = holding_map(m, req.directions, vary=req.vary, margin=req.margin, max_angle=req.max_angle)
    return plots.plot_holding(hmap, m)


@_rendered
def plot_torque_task(req: ps.PlotTorqueRequest) -> Any:
    from tensegrity_opt.applications import plots

    segs = [build_segment(sg) for sg in req.segments]
    q = None if req.q is None else values(req.q)
    return plots.plot_torque(segs, q, num=req.num)


@_rendered
def plot_map_task(req: ps.PlotMapRequest) -> Any:
    from tensegrity_opt.applications import plots
    from tensegrity_opt.applications.sweeps import critical_load_map

    m = build_manipulator(req.manipulator)
    cmap = critical_load_map(m, req.param_x, values(req.values_x), req.param_y, values(req.values_y), req.boundary)
    return plots.plot_map(cmap, m)


@_rendered
def plot_branch_task(req: ps.PlotBranchRequest, deadline: float) -> Any:
    from tensegrity_opt.applications import plots

    m = build_manipulator(req.manipulator)
    return plots.plot_branches(trace_branches(req, deadline), x=req.x, y=req.y, m=m)


@_rendered
def plot_limit_load_task(req: ps.PlotLimitLoadRequest, deadline: float) -> Any:
    from tensegrity_opt.applications import plots

    m = build_manipulator(req.manipulator)
    result = find_limit_load(req, deadline)
    return plots.plot_limit_load(result, m, arms=find_limit_arms(result, deadline) if req.arms else None)


@_rendered
def plot_imperfection_task(req: ps.PlotImperfectionRequest, deadline: float) -> Any:
    from tensegrity_opt.applications import plots

    return plots.plot_imperfection(find_imperfection_sensitivity(req, deadline), build_manipulator(req.manipulator))


@_rendered
def plot_boundary_task(req: ps.PlotBoundaryRequest, deadline: float) -> Any:
    from tensegrity_opt.applications import plots

    m = build_manipulator(req.manipulator)
    return plots.plot_boundary(find_stability_boundary(req, deadline), m=m)


@_rendered
def plot_atlas_task(req: ps.PlotAtlasGridRequest, deadline: float,
                    progress: Callable[[Any], Any] | None = None) -> Any:
    from tensegrity_opt.applications import plots

    return plots.plot_atlas(find_atlas(req, deadline, progress), m=build_manipulator(req.manipulator))


@_rendered
def plot_job_atlas_task(req: ps.PlotAtlasJobRequest, deadline: float, spec: dict[str, Any],
                        rows: list[dict[str, Any]]) -> Any:
    """The atlas of a finished atlas job (its normalised ``spec`` and stored ``rows``)."""
    from tensegrity_opt import Manipulator
    from tensegrity_opt.applications import plots

    at = find_job_atlas(spec, rows, req.edges, deadline)
    return plots.plot_atlas(at, m=Manipulator.from_dict(spec["manipulator"]))


@_rendered
def plot_plan_task(req: ps.PlotPlanRequest, deadline: float) -> Any:
    from tensegrity_opt.applications import plots

    return plots.plot_preload_plan(find_plan(req, deadline), build_manipulator(req.manipulator), margin=req.margin)


@_rendered
def plot_simulation_task(req: ps.PlotSimulationRequest, deadline: float) -> Any:
    from tensegrity_opt.applications import plots

    return plots.plot_simulation(find_simulation(req, deadline), build_manipulator(req.manipulator))


# ---------------------------------------------------------------------------- figures as jobs
#: The ``analysis`` of a figure job.
FIGURE_ANALYSIS = "figure"

#: Each figure kind's job form: its request model, its task (``task(req, fmt, *args)``) and whether the task takes
#: the soft deadline of a continuation. The atlas as a job takes the grid form only.
FIGURE_TASKS: dict[str, tuple[Any, Callable[..., bytes], bool]] = {
    "curve": (ps.PlotCurveRequest, plot_curve_task, False),
    "landscape": (ps.PlotLandscapeRequest, plot_landscape_task, False),
    "shapes": (ps.PlotShapesRequest, plot_shapes_task, False),
    "modes": (ps.PlotModesRequest, plot_modes_task, False),
    "holding": (ps.PlotHoldingRequest, plot_holding_task, False),
    "torque": (ps.PlotTorqueRequest, plot_torque_task, False),
    "map": (ps.PlotMapRequest, plot_map_task, False),
    "branch": (ps.PlotBranchRequest, plot_branch_task, True),
    "limit-load": (ps.PlotLimitLoadRequest, plot_limit_load_task, True),
    "imperfection": (ps.PlotImperfectionRequest, plot_imperfection_task, True),
    "boundary": (ps.PlotBoundaryRequest, plot_boundary_task, True),
    "atlas": (ps.PlotAtlasGridRequest, plot_atlas_task, True),
    "plan": (ps.PlotPlanRequest, plot_plan_task, True),
    "simulation": (ps.PlotSimulationRequest, plot_simulation_task, True),
}


def _axis_size(v: Any) -> int:
    return len(values(v))


def figure_steps(kind: str, req: Any) -> int:
    """The steps of a figure job (its ``total``): each target of an atlas, then the drawing, then the stored
    image."""
    extra = _axis_size(req.dx) * _axis_size(req.dy) if kind == "atlas" else 0
    return extra + 2


def figure_request(kind: str, body: Mapping[str, Any]) -> Any:
    """The request of a stored figure job (its JSON form, as :meth:`pydantic.BaseModel.model_dump` gave it)."""
    return FIGURE_TASKS[kind][0].model_validate_json(json.dumps(body))


def figure_job_task(spec: Mapping[str, Any], deadline: float, progress: Callable[[str], Any]) -> bytes:
    """The image of a figure job's ``spec`` (``{"analysis": "figure", "kind", "format", "request"}``):
    ``progress(stage)`` after each target of an atlas and after the drawing; ``deadline`` is the soft deadline of
    a continuation (a figure that has no continuation ignores it)."""
    from tensegrity_opt.applications import plots

    kind = spec["kind"]
    _, task, continuation = FIGURE_TASKS[kind]
    req = figure_request(kind, spec["request"])
    draw = task.__wrapped__                  # the figure before rendering (functools.wraps in _rendered)
    args = (deadline,) if continuation else ()
    kwargs: dict[str, Any] = {}
    if kind == "atlas":
        kwargs["progress"] = lambda t: progress(f"target dx = {t.dx:g}, dy = {t.dy:g}"
                                                + (f" ({t.error})" if t.error else ""))
    fig = draw(req, *args, **kwargs)
    progress("drawn")
    return plots.render(fig, spec["format"], dpi=req.dpi)
