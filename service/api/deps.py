"""Route dependencies: the settings, the API key, the job runner and the caller's jobs, and the server's limits
on a request (checked on the event loop, before any task is handed to an executor: :mod:`.dispatch`)."""

from __future__ import annotations

import secrets
import time
from typing import Annotated, Any
from urllib.parse import urlsplit

from fastapi import Depends, Request, Security
from fastapi.security import APIKeyHeader

from .. import schemas as s
from ..adapters.fields import BRANCH_ALIASES, JOB_ATLAS_ALIASES, PLAN_ALIASES, SIMULATION_ALIASES, FieldContext
from ..adapters.inputs import manipulator_form, segment_count
from ..config import Settings
from ..jobs import JobNotFound, JobRunner, owner_hash
from ..responses import ResponseTooLarge
from .dispatch import Placement
from .errors import ServiceError

__all__ = ["api_key_header", "require_api_key", "api_key_valid", "origin_allowed", "get_settings_dep", "SettingsDep",
           "get_runner", "get_owner",
           "Runner", "Owner", "check_manipulator", "check_homotopy", "check_batch", "check_curve_size",
           "check_path_points", "check_path", "check_atlas_targets", "check_trajectory_steps", "check_plan",
           "check_simulation",
           "steps_field", "path_deadline", "placement", "finished_atlas_job"]

api_key_header = APIKeyHeader(
    name="X-API-Key", auto_error=False, scheme_name="ApiKey",
    description="Required only when the server is configured with API keys (TENSEGRITY_API_KEYS); "
                "otherwise ignored.")


async def get_settings_dep(request: Request) -> Settings:
    # async on purpose: FastAPI runs a plain ``def`` dependency in a worker thread, a ~0.1 ms hand-off
    return request.app.state.settings


#: The server's settings as a route's parameter (``settings: SettingsDep``).
SettingsDep = Annotated[Settings, Depends(get_settings_dep)]


async def require_api_key(request: Request, key: str | None = Security(api_key_header)) -> None:
    """401 unless auth is off or ``X-API-Key`` is one of the configured keys (constant-time compare)."""
    settings: Settings = request.app.state.settings
    if not settings.api_keys or api_key_valid(key, settings):
        return
    raise ServiceError(401, "unauthorized",
                       "missing API key: send the X-API-Key header" if not key else "invalid API key",
                       field="X-API-Key", headers={"WWW-Authenticate": "ApiKey"})


def api_key_valid(key: str | None, settings: Settings) -> bool:
    """``key`` is one of the configured API keys (constant-time compare; the REST routes and the stream)."""
    if not key:
        return False
    given = key.encode("utf-8", "surrogateescape")
    return any(secrets.compare_digest(given, k.encode("utf-8", "surrogateescape")) for k in settings.api_keys)


_DEFAULT_PORTS = {"http": 80, "https": 443, "ws": 80, "wss": 443}


def _host_port(netloc: str, scheme: str) -> tuple[str, int] | None:
    """``(host, port)`` of ``netloc`` (``host[:port]``, IPv6 in brackets), the port defaulting by ``scheme``;
    ``None`` when it does not parse."""
    try:
        parts = urlsplit(f"//{netloc}")
        host, port = parts.hostname, parts.port
    except ValueError:
        return None
    if not host:
        return None
    return host.lower(), port if port is not None else _DEFAULT_PORTS.get(scheme, 0)


def origin_allowed(origin: str | None, host: str | None, settings: Settings) -> bool:
    """Whether a WebSocket handshake with this ``Origin`` header may open a control stream: no ``Origin`` (a script,
    not a browser page), the server's own origin (the ``Host`` the client connected to, same host and port), or one
    of ``settings.cors_origins`` (``*``: any). Browsers apply no CORS to WebSockets, so without this check any page
    the user opens could drive the streams of a server on ``127.0.0.1``."""
    if origin is None:
        return True
    origin = origin.strip().rstrip("/").lower()
    allowed = {o.strip().rstrip("/").lower() for o in settings.cors_origins}
    if "*" in allowed or origin in allowed:
        return True
    try:
        parts = urlsplit(origin)
    except ValueError:
        return False
    if parts.scheme not in ("http", "https") or not parts.netloc or parts.path or parts.query:
        return False                    # "null" (a sandboxed frame, a file), or not an origin at all
    own = _host_port(parts.netloc, parts.scheme)
    server = _host_port(host, parts.scheme) if host else None
    return own is not None and own == server


def check_manipulator(m: Any, settings: Settings, aliases: tuple[tuple[str, str], ...] = ()) -> FieldContext:
    """Refuse chains longer than ``settings.max_segments`` (422 ``too_many_segments``); the request's field
    context, with the library's names of its inputs (``aliases``)."""
    n = segment_count(m)
    form = manipulator_form(m)
    if n > settings.max_segments:
        raise ServiceError(422, "too_many_segments",
                           f"the chain has {n} segments; this server accepts at most {settings.max_segments}",
                           field="manipulator.n" if form == "uniform" else "manipulator.segments",
                           details={"n": n, "max_segments": settings.max_segments})
    return FieldContext(manipulator=form, aliases=aliases)


def check_homotopy(req: s.EquilibriaRequest, settings: Settings) -> None:
    """Refuse ``method: homotopy`` for chains longer than ``settings.homotopy_max_segments`` (422)."""
    if req.method != "homotopy":
        return
    n = segment_count(req.manipulator)
    if n > settings.homotopy_max_segments:
        raise ServiceError(422, "too_many_segments",
                           f"method 'homotopy' is accepted here for chains of up to {settings.homotopy_max_segments} "
                           f"segments (its path count grows ~8x a segment); the chain has {n}: use method 'search'",
                           field="method", details={"n": n, "homotopy_max_segments": settings.homotopy_max_segments})


#: Rough bytes of one curve row: ~20 per joint angle plus the other fields.
CURVE_ROW_BYTES_PER_JOINT = 20
CURVE_ROW_BYTES = 300


def check_curve_size(n: int, points: int, branch: str, settings: Settings) -> None:
    """Refuse before solving a curve whose answer is sure to exceed ``max_response_bytes`` (422
    ``response_too_large`` on ``dx``): ``points`` rows of ``n`` angles, twice for ``branch = "all"``
    (the stable rows and at least one branch). The rendered body is counted too (the number of
    branches is known only after solving)."""
    estimate = points * (n * CURVE_ROW_BYTES_PER_JOINT + CURVE_ROW_BYTES) * (2 if branch == "all" else 1)
    if estimate > settings.max_response_bytes:
        raise ResponseTooLarge(settings.max_response_bytes, "dx", estimate)


def check_batch(req: s.BatchEquilibriumRequest, settings: Settings) -> None:
    if len(req.targets) > settings.max_batch:
        raise ServiceError(422, "batch_too_large",
                           f"the batch has {len(req.targets)} targets; this server accepts at most "
                           f"{settings.max_batch}", field="targets",
                           details={"targets": len(req.targets), "max_batch": settings.max_batch})


def check_path_points(max_points: int, settings: Settings) -> None:
    """Refuse a branch of more points than ``settings.max_path_points`` (422 ``too_many_points``)."""
    if max_points > settings.max_path_points:
        raise ServiceError(422, "too_many_points",
                           f"max_points = {max_points}; this server follows at most {settings.max_path_points} "
                           "points per branch", field="max_points",
                           details={"max_points": max_points, "max_path_points": settings.max_path_points})


def check_path(req: Any, settings: Settings, aliases: tuple[tuple[str, str], ...] = BRANCH_ALIASES) -> FieldContext:
    """The limits of a continuation request (a branch, a bifurcation diagram, a limit load, a stability boundary,
    their figures): its field context, with the library's names of its inputs (``aliases``)."""
    ctx = check_manipulator(req.manipulator, settings, aliases)
    check_path_points(req.max_points, settings)
    return ctx


def _axis_size(v: Any) -> int:
    return int(v.num) if isinstance(v, s.RangeIn) else len(v)


def check_atlas_targets(req: Any, settings: Settings) -> None:
    """Refuse an inline atlas of more targets (dx values x dy values) than ``settings.max_atlas_targets`` (422
    ``atlas_too_large`` on ``dx``): a larger grid is a job (``POST /v1/jobs`` with ``analysis: atlas``)."""
    nx, ny = _axis_size(req.dx), _axis_size(req.dy)
    if nx * ny > settings.max_atlas_targets:
        raise ServiceError(422, "atlas_too_large",
                           f"the atlas has {nx * ny} targets ({nx} dx x {ny} dy); this server computes at most "
                           f"{settings.max_atlas_targets} in one request: submit it as a job, POST /v1/jobs with "
                           '{"analysis": "atlas", "grid": {"dx": [...], "dy": [...]}}, then GET /v1/jobs/{id}/atlas',
                           field="dx", details={"targets": nx * ny, "nx": nx, "ny": ny,
                                                "max_atlas_targets": settings.max_atlas_targets})


def check_trajectory_steps(settings: Settings, **series: Any) -> None:
    """Refuse a trajectory of more steps than ``settings.max_trajectory_steps`` (422 ``too_many_steps`` naming the
    first series over it): ``series`` are the request's per-step lists by field name (``None``: not given)."""
    limit = settings.max_trajectory_steps
    for field, values in series.items():
        if values is not None and len(values) > limit:
            raise ServiceError(422, "too_many_steps",
                               f"{field} holds {len(values)} steps; this server computes at most {limit} steps of a "
                               "trajectory in one request", field=field,
                               details={"steps": len(values), "max_trajectory_steps": limit})


#: Seconds of the time limit a path computation leaves for its answer (rendering, the hand-off back):
#: ``max(PATH_MARGIN, PATH_MARGIN_FRACTION * solve_timeout)``, at most half the limit.
PATH_MARGIN = 0.5
PATH_MARGIN_FRACTION = 0.1


def path_deadline(settings: Settings) -> float:
    """The ``time.monotonic()`` deadline of a continuation (``tensegrity_opt.trace_branch`` and the analyses
    on it take ``timeout`` and answer the points computed so far, ``status: "time_limit"``): before the
    request's time limit, so that the partial answer is sent instead of a 504. The task turns it into the
    seconds left when it starts (time spent queued counts)."""
    t = settings.solve_timeout
    return time.monotonic() + max(t - max(PATH_MARGIN, PATH_MARGIN_FRACTION * t), 0.5 * t)


def placement(settings: Settings, m: Any, *, branch_all: bool = False, homotopy: bool = False) -> Placement:
    """The thread class of a request: ``HEAVY`` for every branch, the homotopy, or a long chain."""
    heavy = branch_all or homotopy or segment_count(m) > settings.heavy_segments
    return Placement.HEAVY if heavy else Placement.LIGHT


def _per_step(v: Any) -> Any:
    """A per-step list of pairs (its length is the step count), or None for one load for every step."""
    return v if isinstance(v, list) and v and isinstance(v[0], list) else None


def check_plan(req: Any, settings: Settings) -> FieldContext:
    """The limits of a plan request (the endpoint's and the figure's): its field context."""
    ctx = check_manipulator(req.manipulator, settings, PLAN_ALIASES)
    check_trajectory_steps(settings, targets=req.targets, loads=_per_step(req.loads), end_angles=req.end_angles,
                           times=req.times)
    return ctx


def steps_field(req: Any) -> str:
    """The input setting a simulation's size (what to ask less of)."""
    return next((f for f in ("preloads", "loads", "targets") if getattr(req, f) is not None), "preloads")


def check_simulation(req: Any, settings: Settings) -> FieldContext:
    """The limits of a simulate request (the endpoint's and the figure's): its field context."""
    ctx = check_manipulator(req.manipulator, settings, SIMULATION_ALIASES)
    check_trajectory_steps(settings, preloads=req.preloads, loads=req.loads, targets=req.targets)
    return ctx


# ---------------------------------------------------------------------------- jobs
async def get_runner(request: Request) -> JobRunner:
    runner = getattr(request.app.state, "jobs", None)
    if runner is None:  # pragma: no cover - the router is only included together with a runner
        raise ServiceError(503, "jobs_unavailable", "this server has no job runner")
    return runner


async def get_owner(request: Request) -> str | None:
    """The job owner of this request: the SHA-256 of its API key when keys are configured, else ``None``
    (auth off: every job is everyone's). ``require_api_key`` has checked the key already."""
    settings = request.app.state.settings
    if not settings.auth_enabled:
        return None
    return owner_hash(request.headers.get("x-api-key") or "")


Runner = Annotated[JobRunner, Depends(get_runner)]
Owner = Annotated[str | None, Depends(get_owner)]


def finished_atlas_job(runner: JobRunner, owner: str | None, job_id: str,
                       field: str = "id") -> tuple[dict[str, Any], list[dict[str, Any]], FieldContext]:
    """The normalised spec and every row of a finished atlas job, with the field context of its errors (a plain
    function: it reads the store, so a route on the event loop calls it in a thread). 404 for an unknown job
    (or someone else's), 422 ``invalid_parameter`` when it is not an atlas over a grid in ``dx`` and ``dy``
    (``spec.analysis`` / ``spec.grid``; ``field`` when given otherwise), 409 ``job_not_done`` unless it is done."""
    try:
        job = runner.get(job_id, owner)
    except JobNotFound:
        raise ServiceError(404, "not_found", f"no job with id {job_id!r}", field=field) from None
    spec = job["spec"]
    on = (lambda name: f"spec.{name}") if field == "id" else (lambda name: field)
    if spec.get("analysis") != "atlas":
        raise ServiceError(422, "invalid_parameter", f"job {job_id!r} is a {spec.get('analysis')!r} sweep, not an "
                           "atlas (analysis 'atlas' over a grid in dx and dy)", field=on("analysis"))
    grid = spec.get("grid")
    if grid is None or set(grid) != {"dx", "dy"}:
        over = "a list of points" if grid is None else "a grid in " + ", ".join(grid)
        raise ServiceError(422, "invalid_parameter", f"job {job_id!r} is an atlas sweep over {over}: an atlas needs "
                           "a grid over exactly dx and dy", field=on("grid"))
    if job["status"] != "done":
        raise ServiceError(409, "job_not_done", f"job {job_id!r} is {job['status']} ({job['done']} of {job['total']} "
                           "points): its atlas is made from the rows of a done job", field=field,
                           details={"status": job["status"], "done": job["done"], "total": job["total"]})
    uniform = "segments" not in spec["manipulator"]
    aliases = JOB_ATLAS_ALIASES if field == "id" else tuple((name, field) for name, _ in JOB_ATLAS_ALIASES)
    n_field = ("spec.manipulator.n" if uniform else "spec.manipulator.segments") if field == "id" else field
    ctx = FieldContext(manipulator="uniform" if uniform else "segments", aliases=(("n", n_field), *aliases))
    return spec, runner.rows(job_id), ctx
