"""Tasks of the loading-path requests: rest configurations, branches, bifurcation diagrams, limit loads, imperfection
sensitivity, stability boundaries, the stability atlas (inline and of a job).

``deadline`` is the soft ``time.monotonic()`` deadline of :func:`service.api.deps.path_deadline`: the computation
stops there and answers what it has (``status: "time_limit"``) instead of a 504. The ``find_*`` tasks return the
library's result, which the endpoint renders (its ``to_dict()``) and the figure draws.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import Any

import tensegrity_opt as to
from tensegrity_opt.applications.sweeps import atlas_from_rows
from tensegrity_opt.numerics import DENSE_MAX

from .. import schemas as s
from ..adapters.inputs import branch_start, build_control, build_manipulator, control_kwargs, optional_array, values

__all__ = ["seconds_left", "rest_configurations_task", "trace_branches", "bifurcation_diagram_task",
           "find_limit_load", "find_limit_arms", "limit_load_task", "find_imperfection_sensitivity",
           "imperfection_sensitivity_task", "find_stability_boundary", "find_atlas",
           "find_job_atlas"]


def seconds_left(deadline: float) -> float:
    """The library ``timeout`` of a computation with the soft ``deadline`` (the time spent queued counts)."""
    return max(deadline - time.monotonic(), 1e-3)


def _continuable(m: to.Manipulator) -> None:
    """The continuation's own limit, before anything is solved (a rest configuration of a long chain)."""
    if m.n > DENSE_MAX:
        raise to.InvalidParameterError(f"arclength continuation handles chains of up to {DENSE_MAX} segments, "
                                       f"got n = {m.n}", field="n")


def rest_configurations_task(req: s.RestConfigurationsRequest, timeout: float | None = None) -> Any:
    """Every equilibrium under the dead load ``(fx, fy)`` (``find_equilibria_under_force``); ``timeout`` bounds
    the homotopy's external solver."""
    m = build_manipulator(req.manipulator)
    return to.find_equilibria_under_force(m, req.fx, req.fy, method=req.method, stable_only=req.stable_only,
                                          timeout=timeout)


def trace_branches(req: Any, deadline: float) -> to.Branch | list[to.Branch]:
    """The branch of a branch request (``trace_branch``), or the bifurcation diagram (a list) of a request
    with ``depth`` (``bifurcation_diagram``), within the soft ``deadline``."""
    m = build_manipulator(req.manipulator)
    _continuable(m)
    ctl = build_control(req.control)
    start = branch_start(m, req.start, req.control)
    depth = getattr(req, "depth", None)
    if depth is None:
        return to.trace_branch(m, start, ctl, t_max=req.t_max, t_min=req.t_min, max_points=req.max_points,
                               stop_at=req.stop_at, orientation=req.orientation, timeout=seconds_left(deadline))
    if getattr(req, "stop_at", None) is not None or getattr(req, "orientation", 1) != 1:
        raise to.InvalidParameterError("stop_at and orientation belong to one branch: a bifurcation diagram (depth) "
                                       "follows every branch both ways", field="stop_at"
                                       if getattr(req, "stop_at", None) is not None else "orientation")
    return to.bifurcation_diagram(m, start, ctl, depth=req.depth, max_branches=req.max_branches,
                                  timeout=seconds_left(deadline), t_max=req.t_max, t_min=req.t_min,
                                  max_points=req.max_points)


def bifurcation_diagram_task(req: s.BifurcationDiagramRequest, deadline: float) -> dict[str, Any]:
    return {"branches": [b.to_dict() for b in trace_branches(req, deadline)]}


def find_limit_load(req: Any, deadline: float) -> to.LimitLoad:
    m = build_manipulator(req.manipulator)
    _continuable(m)
    start = optional_array(None if req.start is None else req.start.q)
    return to.limit_load(m, req.direction, req.boundary, req.max_load, start, max_points=req.max_points,
                         timeout=seconds_left(deadline))


def find_limit_arms(result: to.LimitLoad, deadline: float) -> list[to.Branch]:
    """The buckled arms leaving the limit point of ``result`` (none unless it is a bifurcation) within the soft
    ``deadline``."""
    return to.limit_arms(result, timeout=seconds_left(deadline))


def limit_load_task(req: s.LimitLoadRequest, deadline: float) -> dict[str, Any]:
    return find_limit_load(req, deadline).to_dict(include_branch=req.include_branch)


def find_imperfection_sensitivity(req: Any, deadline: float) -> to.ImperfectionSensitivity:
    m = build_manipulator(req.manipulator)
    _continuable(m)
    return to.imperfection_sensitivity(m, req.amplitudes, imperfection=req.imperfection, direction=req.direction,
                                       boundary=req.boundary, max_load=req.max_load, max_points=req.max_points,
                                       timeout=seconds_left(deadline))


def imperfection_sensitivity_task(req: s.ImperfectionSensitivityRequest, deadline: float) -> dict[str, Any]:
    return find_imperfection_sensitivity(req, deadline).to_dict(include_limit_loads=req.include_limit_loads)


def find_stability_boundary(req: Any, deadline: float) -> Any:
    m = build_manipulator(req.manipulator)
    _continuable(m)
    kind, kw = control_kwargs(req.control)
    return to.stability_boundary(m, kind, req.parameter, p_min=req.p_min, p_max=req.p_max, max_points=req.max_points,
                                 timeout=seconds_left(deadline), **kw)


def find_atlas(req: Any, deadline: float, progress: Callable[[Any], Any] | None = None) -> to.StabilityAtlas:
    """The atlas of an atlas request (``/v1/atlas``, ``/v1/plots/atlas``) within the soft ``deadline``: what is
    done by then is answered with ``status: "time_limit"``. ``progress(target)`` after each target (a job's
    progress)."""
    m = build_manipulator(req.manipulator)
    return to.stability_atlas(m, values(req.dx), values(req.dy), method=req.method, edges=req.edges,
                              timeout=seconds_left(deadline), progress=progress)


def find_job_atlas(spec: dict[str, Any], rows: list[dict[str, Any]], edges: bool,
                   deadline: float) -> to.StabilityAtlas:
    """The atlas of a finished atlas job from its stored rows (``sweeps.atlas_from_rows``: each stored stable
    equilibrium re-solved, then the edges analysed), within the soft ``deadline`` (the re-solves count: the limit
    is around the whole call)."""
    left = seconds_left(deadline)
    with to.time_limit(left):
        return atlas_from_rows(spec, rows, edges=edges, timeout=left)
