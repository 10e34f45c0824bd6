"""Library calls and their JSON bodies; everything here runs in a solver thread (or,
:func:`equilibrium_newton_task`, in a solver process), never on the event loop.

Each ``*_task`` function (a task of the solver pool; "job" means a persistent sweep, see
:mod:`service.jobs`) takes validated request models (read only) and returns the result's own
``to_dict()`` (the one serialiser per result type, :mod:`tensegrity_opt.serialize`'s NaN policy),
which is the response model's shape. Library exceptions propagate unchanged to the route, which maps
them through :mod:`service.errors` (batch items are mapped here, one error per target).
"""

from __future__ import annotations

import time
from functools import lru_cache
from typing import Any

import numpy as np

import tensegrity_opt as to
from tensegrity_opt.analyses.equilibria.equilibrium import Equilibrium
from tensegrity_opt.applications.sweeps import atlas_from_rows
from tensegrity_opt.errors import NonFiniteResult
from tensegrity_opt.numerics import DENSE_MAX
from tensegrity_opt.serialize import number, numbers

from . import schemas as s
from .errors import FieldContext, error_body

__all__ = [
    "build_manipulator", "manipulator_key", "segment_count", "manipulator_form", "equilibrium_task",
    "equilibrium_newton_task", "equilibrium_newton_args", "force_equilibrium_task", "equilibria_task", "buckling_task",
    "force_deflection_task", "stiffness_task",
    "segment_torque_task", "energy_landscape_task", "batch_task", "warmup_task",
    "rest_configurations_task", "branch_task", "bifurcation_diagram_task", "limit_load_task",
    "stability_boundary_task", "trace_branches", "find_limit_load", "find_stability_boundary", "build_control",
    "control_kwargs", "BRANCH_ALIASES", "LIMIT_LOAD_ALIASES", "atlas_values", "find_atlas", "atlas_task",
    "find_job_atlas", "job_atlas_task", "JOB_ATLAS_ALIASES",
]


def _pair(v: float | list[float]) -> float | tuple[float, float]:
    return (float(v[0]), float(v[1])) if isinstance(v, list) else float(v)


def segment_count(m: s.UniformManipulatorIn | s.SegmentedManipulatorIn) -> int:
    return m.n if isinstance(m, s.UniformManipulatorIn) else len(m.segments)


def manipulator_form(m: Any) -> str:
    return "uniform" if isinstance(m, s.UniformManipulatorIn) else "segments"


def build_segment(seg: s.SegmentIn) -> to.Segment:
    return to.Segment(seg.a, seg.b, _pair(seg.k), _pair(seg.L0))


def build_manipulator(m: s.UniformManipulatorIn | s.SegmentedManipulatorIn) -> to.Manipulator:
    """The chain of a request; the same description gives the same (cached, immutable) object, so its
    derived arrays, buckling modes and seed directions are computed once, not per request."""
    return _manipulator(manipulator_key(m))


def manipulator_key(m: s.UniformManipulatorIn | s.SegmentedManipulatorIn) -> tuple[Any, ...]:
    """A chain description as a hashable tuple of plain numbers (cache key; cheap to send to a process)."""
    if isinstance(m, s.UniformManipulatorIn):
        return ("uniform", m.n, m.a, m.b, _pair(m.k), _pair(m.L0))
    return ("segments",) + tuple((seg.a, seg.b, _pair(seg.k), _pair(seg.L0)) for seg in m.segments)


@lru_cache(maxsize=256)
def _manipulator(key: tuple[Any, ...]) -> to.Manipulator:
    """The chain of a key, by the library's own reader of the two JSON forms (:meth:`Manipulator.from_dict`)."""
    if key[0] == "uniform":
        return to.Manipulator.from_dict(dict(zip(("n", "a", "b", "k", "L0"), key[1:])))
    return to.Manipulator.from_dict({"segments": [dict(zip(("a", "b", "k", "L0"), seg)) for seg in key[1:]]})


def _q0(q0: list[float] | tuple[float, ...] | None) -> np.ndarray | None:
    return None if q0 is None else np.asarray(q0, dtype=float)


# ---------------------------------------------------------------------------- tasks
def warmup_task() -> None:
    """Build this thread's CasADi instances for the paper's chain (first-request latency)."""
    to.solve_equilibrium(to.Manipulator.uniform(4), 0.1)


def equilibrium_task(req: s.EquilibriumRequest) -> dict[str, Any]:
    m = build_manipulator(req.manipulator)
    return to.solve_equilibrium(m, req.dx, req.dy, q0=_q0(req.q0), local=req.local).to_dict()


def equilibrium_newton_args(req: s.EquilibriumRequest, max_segments: int) -> tuple[Any, ...] | None:
    """The arguments of :func:`equilibrium_newton_task` for a request it may settle (plain numbers,
    cheap to pickle), or ``None`` when it could only answer "not settled": a chain longer than
    ``max_segments`` (decided from the request, the chain is not built) or with a segment that is not
    monotonic (bistable: Newton alone often finds saddles only). Decided here, by the caller, so such
    a request goes straight to the solver threads instead of a round trip to a solver process."""
    if segment_count(req.manipulator) > max_segments:
        return None
    key = manipulator_key(req.manipulator)
    if not _manipulator(key).monotonic:     # the chain is cached: the solve reuses it
        return None
    return (key, req.dx, req.dy, None if req.q0 is None else tuple(req.q0), req.local)


def equilibrium_newton_task(key: tuple[Any, ...], dx: float, dy: float, q0: tuple[float, ...] | None,
                            local: bool) -> dict[str, Any] | None:
    """:func:`equilibrium_task` by the bounded Newton-only search (``method="newton"``); ``None`` when
    it finds no stable equilibrium (then :func:`equilibrium_task` decides, IPOPT included).

    For the chains :func:`equilibrium_newton_args` admits (monotonic segments)
    ``solve_equilibrium(method="auto")`` returns exactly the Newton-only answer whenever that finds
    one (and with ``local`` the same Newton solve before its IPOPT fallback), so the answer does not
    depend on which of the two ran (the service tests compare the bytes). Runs in a solver process
    (``service.lane``), hence plain numbers in.
    """
    m = _manipulator(key)
    try:
        eq = to.solve_equilibrium(m, dx, dy, q0=_q0(q0), local=local, method="newton")
    except (to.NoEquilibriumError, to.SolverError):
        return None
    return eq.to_dict()


def force_equilibrium_task(req: s.ForceEquilibriumRequest) -> dict[str, Any]:
    m = build_manipulator(req.manipulator)
    return to.solve_equilibrium_under_force(m, req.fx, req.fy, q0=_q0(req.q0)).to_dict()


def equilibria_task(req: s.EquilibriaRequest, timeout: float | None = None) -> dict[str, Any]:
    """Every equilibrium; ``timeout`` bounds the homotopy's external solver (killed then, freeing the thread)."""
    m = build_manipulator(req.manipulator)
    eqs = to.find_equilibria(m, req.dx, req.dy, method=req.method, timeout=timeout)
    return eqs.to_dict()


def buckling_task(req: s.BucklingRequest) -> dict[str, Any]:
    m = build_manipulator(req.manipulator)
    bk = to.critical_force(m, req.boundary)
    return bk.to_dict()


def deflections(dx: list[float] | s.RangeIn) -> np.ndarray:
    if isinstance(dx, s.RangeIn):
        return np.linspace(dx.start, dx.stop, dx.num)
    return np.asarray(dx, dtype=float)


def force_deflection_task(req: s.ForceDeflectionRequest) -> dict[str, Any]:
    m = build_manipulator(req.manipulator)
    c = to.force_deflection(m, deflections(req.dx), req.dy, branch=req.branch, reference=req.reference)
    return c.to_dict()


def stiffness_task(req: s.StiffnessRequest) -> dict[str, Any]:
    m = build_manipulator(req.manipulator)
    eq = to.solve_equilibrium(m, req.dx, req.dy, q0=_q0(req.q0))
    K = to.cartesian_stiffness(m, eq)
    return {"matrix": numbers(K), "equilibrium": eq.to_dict()}


def angles(q: list[float] | s.RangeIn) -> np.ndarray:
    if isinstance(q, s.RangeIn):
        return np.linspace(q.start, q.stop, q.num)
    return np.asarray(q, dtype=float)


def segment_torque_task(req: s.SegmentTorqueRequest) -> dict[str, Any]:
    seg = build_segment(req.segment)
    q = angles(req.q)
    return {"q": numbers(q), "torque": numbers(seg.torque(q)), "dtorque": numbers(seg.dtorque(q)),
            "energy": numbers(seg.energy(q)), "stiffness": number(seg.stiffness), "monotonic": bool(seg.monotonic()),
            "joint_limit": number(seg.joint_limit)}


def energy_landscape_task(req: s.EnergyLandscapeRequest) -> dict[str, Any]:
    m = build_manipulator(req.manipulator)
    land = to.energy_landscape(m, req.dx, req.dy, pair=(req.pair[0], req.pair[1]), grid=req.grid, span=req.span)
    return land.to_dict()


def batch_task(req: s.BatchEquilibriumRequest, deadline: float, form: str) -> dict[str, Any]:
    """Solve the targets in order (:func:`tensegrity_opt.solve_equilibria_batch`).

    With ``continuation`` each target continues the branch through the previous result (compiled
    continuation for short chains); a target that fails gets an error object and the next one starts
    from the last success. Targets not started before ``deadline`` (``time.monotonic()``) get
    ``code = "timeout"``.
    """
    m = build_manipulator(req.manipulator)
    q_prev = _q0(req.q0)
    if q_prev is not None and (q_prev.shape != (m.n,) or not m.in_range(q_prev)):
        # A bad start would fail every target of the trajectory: refuse the request instead.
        raise to.InvalidParameterError(
            f"q0 must hold {m.n} joint angles inside the physical range |q_i| < pi - 2 beta_i", field="q0")
    targets = [(t.dx, t.dy) for t in req.targets]
    solved = to.solve_equilibria_batch(m, targets, continuation=req.continuation, q0=q_prev, deadline=deadline)
    results: list[dict[str, Any]] = []
    ok = 0
    for i, (t, r) in enumerate(zip(req.targets, solved)):
        item: dict[str, Any] = {"index": i, "dx": t.dx, "dy": t.dy, "equilibrium": None, "error": None}
        if isinstance(r, Equilibrium):
            try:
                item["equilibrium"] = r.to_dict()
                ok += 1
            except NonFiniteResult as exc:
                item["error"] = error_body(exc, FieldContext(manipulator=form, index=i))
        else:
            body = error_body(r, FieldContext(manipulator=form, index=i))
            if body is None:
                raise r
            item["error"] = body
        results.append(item)
    return {"results": results, "succeeded": ok, "failed": len(results) - ok}


# ---------------------------------------------------------------------------- design and control
def _best_as_json(exc: to.InfeasibleDesignError) -> to.InfeasibleDesignError:
    """The best point of an infeasible design, made JSON-ready for the error body."""
    best = exc.best
    if isinstance(best, to.Design):
        try:
            exc.best = best.to_dict()
        except NonFiniteResult:
            exc.best = None
    elif isinstance(best, dict):
        exc.best = {k: v for k, v in best.items()}
    return exc


def design_critical_force_task(req: s.DesignCriticalForceRequest) -> dict[str, Any]:
    m = build_manipulator(req.manipulator)
    constraints: dict[str, Any] = {}
    if req.total_length is not None and req.total_length is not False:
        constraints["total_length"] = req.total_length
    if req.tension is not None:
        constraints["tension"] = (req.tension.lo, req.tension.hi)
    if req.K_min is not None:
        constraints["K_min"] = req.K_min
    try:
        d = to.maximize_critical_force(m, vary=tuple(dict.fromkeys(req.vary)),
                                       bounds={k: (v.lo, v.hi) for k, v in req.bounds.items()},
                                       budget=dict(req.budget), boundary=req.boundary, **constraints)
    except to.InfeasibleDesignError as exc:
        raise _best_as_json(exc) from None
    return d.to_dict()


def preloads_for_load_task(req: s.PreloadsForLoadRequest) -> dict[str, Any]:
    m = build_manipulator(req.manipulator)
    try:
        d = to.preloads_for_critical_force(m, req.required, boundary=req.boundary,
                                           bounds=(req.bounds.lo, req.bounds.hi) if req.bounds else None)
    except to.InfeasibleDesignError as exc:
        raise _best_as_json(exc) from None
    if not d.feasible:
        raise _best_as_json(to.InfeasibleDesignError(
            f"no rest lengths within the bounds give a critical load of {req.required:g}: the best achievable "
            f"is {d.load:.6g}", status=d.solver.status, best=d))
    return d.to_dict()


#: The request's ``objective`` -> the library's (``"nominal"``: the least change from the chain's own rest lengths).
PRELOADS_OBJECTIVES = {"nominal": "change", "margin": "margin", "energy": "energy"}


def preloads_task(req: s.PreloadsRequest) -> dict[str, Any]:
    m = build_manipulator(req.manipulator)
    try:
        r = to.preloads_for_pose(m, (req.target.x, req.target.y), load=(req.load.fx, req.load.fy),
                                 objective=PRELOADS_OBJECTIVES[req.objective], margin=req.margin, taut=req.taut,
                                 bounds=(req.bounds.lo, req.bounds.hi) if req.bounds else None,
                                 end_angle=req.end_angle)
    except to.InfeasibleDesignError as exc:
        raise _best_as_json(exc) from None
    return r.to_dict()


# ---------------------------------------------------------------------------- loading paths
#: Library field -> request path, for the path requests (``FieldContext.aliases``).
BRANCH_ALIASES = (("q0", "start.q"), ("dx", "start.dx"), ("dy", "start.dy"), ("direction", "control.direction"),
                  ("base", "control.base"), ("normal", "control.normal"), ("load", "control.load"),
                  ("tip", "control.tip"))
LIMIT_LOAD_ALIASES = (("q0", "start.q"),)


def _continuable(m: to.Manipulator) -> None:
    """The continuation's own limit, before anything is solved (a rest configuration of a long chain)."""
    if m.n > DENSE_MAX:
        raise to.InvalidParameterError(f"arclength continuation handles chains of up to {DENSE_MAX} segments, "
                                       f"got n = {m.n}", field="n")


def _seconds_left(deadline: float) -> float:
    """The library ``timeout`` of a path computation with the soft ``deadline`` (``deps.path_deadline``)."""
    return max(deadline - time.monotonic(), 1e-3)


def build_control(c: Any) -> to.Control:
    """The :class:`tensegrity_opt.Control` of a control request (``schemas.ControlIn``)."""
    if c.kind == "displacement":
        return to.Control.displacement(c.direction)
    if c.kind == "load":
        return to.Control.load(c.direction, c.base)
    if c.kind == "guided":
        return to.Control.guided(c.direction, c.base)
    if c.kind == "wall":
        return to.Control.wall(c.normal, c.direction, c.base)
    return to.Control.preload(c.direction, tip=c.tip, load=c.load)


def control_kwargs(c: Any) -> tuple[str, dict[str, Any]]:
    """A control request as the kind and the constructor keywords (the ``control, **control_kw`` of the analyses)."""
    return c.kind, c.model_dump(exclude={"kind"})


def _start(m: to.Manipulator, start: Any, control: Any) -> Any:
    """The library's ``start`` of a start request (``schemas.StartIn`` or None: the rest configuration)."""
    if start is None:
        return None
    if isinstance(start, s.StartQ):
        return np.asarray(start.q, dtype=float)
    if not (control.kind == "displacement" or (control.kind == "preload" and control.tip == "held")):
        raise to.InvalidParameterError(
            "a start {dx, dy} (the least-energy equilibrium with the tip held there) needs a control that holds the "
            f"tip (displacement, or preload with tip 'held'); the {control.kind} control starts from joint angles "
            "{q} or the rest configuration (null)", field="start")
    return to.solve_equilibrium(m, start.dx, start.dy)


def rest_configurations_task(req: s.RestConfigurationsRequest, timeout: float | None = None) -> dict[str, Any]:
    """Every equilibrium under the dead load ``(fx, fy)`` (``analyses.rest.find_equilibria_under_force``);
    ``timeout`` bounds the homotopy's external solver."""
    m = build_manipulator(req.manipulator)
    fn = to.find_equilibria_under_force
    return fn(m, req.fx, req.fy, method=req.method, stable_only=req.stable_only, timeout=timeout).to_dict()


def trace_branches(req: Any, deadline: float) -> to.Branch | list[to.Branch]:
    """The branch of a branch request (``trace_branch``), or the bifurcation diagram (a list) of a request
    with ``depth`` (``bifurcation_diagram``), within the soft ``deadline``."""
    m = build_manipulator(req.manipulator)
    _continuable(m)
    ctl = build_control(req.control)
    start = _start(m, req.start, req.control)
    depth = getattr(req, "depth", None)
    if depth is None:
        return to.trace_branch(m, start, ctl, t_max=req.t_max, t_min=req.t_min, max_points=req.max_points,
                               stop_at=req.stop_at, orientation=req.orientation, timeout=_seconds_left(deadline))
    if getattr(req, "stop_at", None) is not None or getattr(req, "orientation", 1) != 1:
        raise to.InvalidParameterError("stop_at and orientation belong to one branch: a bifurcation diagram (depth) "
                                       "follows every branch both ways", field="stop_at"
                                       if getattr(req, "stop_at", None) is not None else "orientation")
    return to.bifurcation_diagram(m, start, ctl, depth=req.depth, max_branches=req.max_branches,
                                  timeout=_seconds_left(deadline), t_max=req.t_max, t_min=req.t_min,
                                  max_points=req.max_points)


def branch_task(req: s.BranchRequest, deadline: float) -> dict[str, Any]:
    return trace_branches(req, deadline).to_dict()


def bifurcation_diagram_task(req: s.BifurcationDiagramRequest, deadline: float) -> dict[str, Any]:
    return {"branches": [b.to_dict() for b in trace_branches(req, deadline)]}


def find_limit_load(req: Any, deadline: float) -> to.LimitLoad:
    m = build_manipulator(req.manipulator)
    _continuable(m)
    start = None if req.start is None else np.asarray(req.start.q, dtype=float)
    return to.limit_load(m, req.direction, req.boundary, req.max_load, start, max_points=req.max_points,
                         timeout=_seconds_left(deadline))


def limit_load_task(req: s.LimitLoadRequest, deadline: float) -> dict[str, Any]:
    return find_limit_load(req, deadline).to_dict(include_branch=req.include_branch)


def find_stability_boundary(req: Any, deadline: float) -> Any:
    m = build_manipulator(req.manipulator)
    _continuable(m)
    fn = to.stability_boundary
    kind, kw = control_kwargs(req.control)
    return fn(m, kind, req.parameter, p_min=req.p_min, p_max=req.p_max, max_points=req.max_points,
              timeout=_seconds_left(deadline), **kw)


def stability_boundary_task(req: s.StabilityBoundaryRequest, deadline: float) -> dict[str, Any]:
    return find_stability_boundary(req, deadline).to_dict()


# ---------------------------------------------------------------------------- stability atlas
#: Library field -> request path for the atlas of a job (the inputs are the job's stored spec and rows).
JOB_ATLAS_ALIASES = (("analysis", "spec.analysis"), ("grid", "spec.grid"), ("dx", "spec.grid.dx"),
                     ("dy", "spec.grid.dy"), ("targets", "spec.grid"), ("rows", "id"), ("method", "spec.options.method"))


def atlas_values(v: list[float] | s.RangeIn) -> np.ndarray:
    """The grid values of an atlas axis: a list, or ``{start, stop, num}`` as ``numpy.linspace``."""
    if isinstance(v, s.RangeIn):
        return np.linspace(v.start, v.stop, v.num)
    return np.asarray(v, dtype=float)


def find_atlas(req: Any, deadline: float) -> to.StabilityAtlas:
    """The atlas of an atlas request (``/v1/atlas``, ``/v1/plots/atlas``) within the soft ``deadline``: what is
    done by then is answered with ``status: "time_limit"`` (``deps.path_deadline``)."""
    m = build_manipulator(req.manipulator)
    return to.stability_atlas(m, atlas_values(req.dx), atlas_values(req.dy), method=req.method, edges=req.edges,
                              timeout=_seconds_left(deadline))


def atlas_task(req: Any, deadline: float) -> dict[str, Any]:
    return find_atlas(req, deadline).to_dict()


def find_job_atlas(spec: dict[str, Any], rows: list[dict[str, Any]], edges: bool,
                   deadline: float) -> to.StabilityAtlas:
    """The atlas of a finished atlas job from its stored rows (``sweeps.atlas_from_rows``: each stored stable
    equilibrium re-solved, then the edges analysed), within the soft ``deadline`` (the re-solves count: the limit
    is around the whole call)."""
    left = _seconds_left(deadline)
    with to.time_limit(left):
        return atlas_from_rows(spec, rows, edges=edges, timeout=left)


def job_atlas_task(spec: dict[str, Any], rows: list[dict[str, Any]], edges: bool, deadline: float) -> dict[str, Any]:
    return find_job_atlas(spec, rows, edges, deadline).to_dict()
