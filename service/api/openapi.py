"""The OpenAPI document's words: the API's description and tags, the documented refusals of a route
(``responses=``), the limits the descriptions of several operations share, and the document's final touches
(the links of a submitted job, the optional API key)."""

from __future__ import annotations

from typing import Any

from ..examples import ERRORS
from ..schemas import ErrorOut

__all__ = ["DESCRIPTION", "TAGS", "error_responses", "ok_response", "solve_responses", "SOLVE_ERRORS",
           "ATLAS_LIMITS", "PLAN_LIMITS", "SIMULATION_LIMITS", "finish_document"]

DESCRIPTION = """\
Equilibria, stability, buckling and stiffness of compliant serial manipulators built from
dual-triangle tensegrity segments (the `tensegrity_opt` library) over HTTP.

Every `POST /v1/...` takes JSON and answers JSON in the caller's units (lengths, force per length,
forces, energies = force x length, angles in radians). A manipulator `M` is either
`{"n": 4, "a": 1, "b": 1, "k": 1, "L0": 1}` (n identical segments) or
`{"segments": [{"a", "b", "k": 1.0 | [k1, k2], "L0": 1.0 | [L1_0, L2_0]}, ...]}`.

Every refusal has the body `{"code", "message", "field", ...}`: 422 for schema violations
(`validation_error`, with the field path) and domain errors (`unreachable_target`,
`straight_not_equilibrium`, `straight_unstable`, `too_many_segments`, `solver_failed` /
`no_equilibrium` with the solver `status`, ...), 401 without a valid `X-API-Key` when the server has
keys, 413 for an oversized body, 422 `response_too_large` for an answer over the server's response size
limit (`field` names what to ask less of), 503 (`Retry-After`) when the solver pool is saturated, 504 when a
solve exceeds the time limit. The server's limits are at `GET /version`.

Figures (`POST /v1/plots/{kind}`) answer the image within the same time limit. A figure that needs longer
(a large atlas grid, a long curve) runs as a job with the same body: `POST /v1/plots/{kind}/job` answers 202
with the job's `id`, `GET /v1/jobs/{id}` shows its progress (`done` of `total` steps, one row per step: each
target of an atlas, the drawing, the stored image; a failure is a row's `error` and the job's `message`), and
`GET /v1/jobs/{id}/figure` serves the image once the job is `done` (409 `job_not_done` before). A figure's 504
names its job route.

```
curl -s -X POST http://127.0.0.1:8000/v1/plots/atlas/job -H 'Content-Type: application/json' \\
     -d '{"manipulator": {"n": 3, "a": 0.5}, "dx": {"start": 0.2, "stop": 1.4, "num": 7},
          "dy": {"start": -0.6, "stop": 0.6, "num": 7}}'
# 202 {"id": "3f0c...", "status": "queued", "total": 51, "analysis": "figure"}
curl -s http://127.0.0.1:8000/v1/jobs/3f0c...?limit=0      # "status": "running", "done": 12, "progress": 0.235
curl -s http://127.0.0.1:8000/v1/jobs/3f0c.../figure -o atlas.png
```

Control loops may use the WebSocket `/v1/control/stream` instead (one connection per chain, a step per
message, the same validation and error codes; OpenAPI does not describe WebSockets: see `docs/stream.md`).
"""

TAGS = [
    {"name": "equilibrium", "description": "Equilibria under a prescribed tip displacement or force."},
    {"name": "buckling", "description": "Critical loads and buckling modes of the straight chain."},
    {"name": "curves", "description": "Force-deflection curves by continuation."},
    {"name": "stiffness", "description": "Cartesian tangent stiffness."},
    {"name": "segment", "description": "One segment's torque and stiffness."},
    {"name": "landscape", "description": "Energy landscape of the 4-segment chain."},
    {"name": "batch", "description": "Many targets in one request (trajectories)."},
    {"name": "design", "description": "Design and control: strongest chain, preloads for a pose or a load."},
    {"name": "paths", "description": "Loading paths: rest configurations, equilibrium branches by arclength "
                                     "continuation, bifurcation diagrams, limit loads, stability boundaries."},
    {"name": "atlas", "description": "The workspace stability atlas of the held tip: stable equilibria over a grid "
                                     "of deflections, where the least-energy branch switches and where stable "
                                     "branches end (large grids: a job with analysis atlas)."},
    {"name": "control", "description": "Control: rest-length plans for tip trajectories (inverse statics per step), "
                                       "quasi-static simulation under sampled inputs with the snaps at folds, the "
                                       "tip force estimated from measured joint angles."},
    {"name": "plots", "description": "Figures (PNG or SVG): force-deflection curves, energy landscapes, equilibrium "
                                     "shapes, torque curves, critical-load maps, branch diagrams, limit loads, "
                                     "stability boundaries, stability atlases, rest-length plans, simulations; "
                                     "each also as a job (`POST /v1/plots/{kind}/job`, the image at "
                                     "`GET /v1/jobs/{id}/figure`)."},
    {"name": "jobs", "description": "Sweeps and figures as background jobs, stored in SQLite and resumed after a "
                                    "restart."},
    {"name": "ops", "description": "Health, readiness, version and Prometheus metrics."},
]


_DESCRIPTIONS = {
    401: "Missing or wrong `X-API-Key` (only when the server has API keys configured).",
    413: "Request body larger than the server's limit (`TENSEGRITY_MAX_BODY_BYTES`).",
    422: "Refused input: a schema violation (`validation_error`, with the field path) or a domain error "
         "with a machine-readable `code` (unreachable target, straight configuration not an equilibrium or "
         "unstable, too many segments, solver did not converge with its IPOPT `status` ...).",
    503: "Solver pool saturated: every worker is busy and the queue is full. Retry after `Retry-After` seconds.",
    504: "The solve did not finish within the server's time limit (`TENSEGRITY_SOLVE_TIMEOUT`): it was stopped "
         "(no result; its capacity is free again). `status`, when present, says what stopped it "
         "(`User_Requested_Stop`: the limit inside IPOPT, `Maximum_WallTime_Exceeded`: IPOPT's own limit).",
}


def error_responses(*statuses: int, examples_422: tuple[str, ...] = ("validation_error",)) -> dict[int | str, Any]:
    """``responses=`` entries documenting the refusals of a route (all with the ``ErrorOut`` body)."""
    out: dict[int | str, Any] = {}
    for st in statuses:
        ex = ERRORS[st]
        if st == 422:
            ex = {k: v for k, v in ERRORS[422].items() if k in examples_422}
        entry: dict[str, Any] = {"model": ErrorOut, "description": _DESCRIPTIONS[st],
                                 "content": {"application/json": {"examples": ex}}}
        if st == 503:
            entry["headers"] = {"Retry-After": {"description": "seconds to wait before retrying",
                                                "schema": {"type": "integer", "minimum": 0}}}
        if st == 401:
            entry["headers"] = {"WWW-Authenticate": {"description": "the scheme: ApiKey",
                                                     "schema": {"type": "string"}}}
        out[st] = entry
    return out


def ok_response(example: Any, description: str = "Successful answer") -> dict[int | str, Any]:
    return {200: {"description": description, "content": {"application/json": {"example": example}}}}


SOLVE_ERRORS = (401, 413, 422, 503, 504)


def solve_responses(example: Any, *examples_422: str) -> dict[int | str, Any]:
    return {**ok_response(example),
            **error_responses(*SOLVE_ERRORS, examples_422=("validation_error", "too_many_segments", *examples_422))}


#: What every atlas answer says about the grid, the bound and the time limit (also the figure's).
ATLAS_LIMITS = ("The grid is `dx x dy` (each a list or `{start, stop, num}`, strictly increasing); at most the "
                "server's `TENSEGRITY_MAX_ATLAS_TARGETS` targets (default 400; above: 422 `atlas_too_large`: "
                "submit the grid as a job, `POST /v1/jobs` with `analysis: atlas`, then `GET /v1/jobs/{id}/atlas`). "
                "Chains of 2 to 64 segments; `method: homotopy` up to the server's `homotopy_max_segments`. The "
                "computation stops shortly before the server's time limit and answers what it has (200, "
                "`status: \"time_limit\"`; targets not computed carry `error: \"time_limit: ...\"`) instead of a "
                "504. A target costs ~40-150 ms with the search, seconds with the homotopy.")
#: What every plan answer says about its bounds and the time limit (also the figure's).
PLAN_LIMITS = ("At most the server's `TENSEGRITY_MAX_TRAJECTORY_STEPS` targets (default 2000; above: 422 "
               "`too_many_steps` naming `targets`), chains of 2 to 60 segments (as `/v1/design/*`: the IPOPT "
               "fallback is the same problem). The plan runs in a solver process and stops shortly before the "
               "server's time limit, answering the steps done (200, `status: \"time_limit\"`, `success: false`) "
               "instead of a 504. A step costs ~4 ms by Newton with its verification (n = 4), tens of milliseconds by "
               "IPOPT; the first plan for a chain length builds its IPOPT problem in one call nothing interrupts "
               "(n = 40: ~1.5 s; n = 60: ~40 s, a 504, and the process is replaced).")
SIMULATION_LIMITS = ("At most the server's `TENSEGRITY_MAX_TRAJECTORY_STEPS` samples (default 2000; above: 422 "
                     "`too_many_steps` naming the field), chains of up to 64 segments (longer: 422 "
                     "`invalid_parameter` on `manipulator.n`). The simulation stops shortly before the server's "
                     "time limit and answers the samples done (200, `status: \"time_limit\"`, `success: false`) "
                     "instead of a 504. About 1 ms a sample without a snap (n = 3), tens of milliseconds a snap.")


def finish_document(doc: dict[str, Any]) -> dict[str, Any]:
    """The document FastAPI built, with the links of a submitted job and the API key made optional."""
    # A submitted job's id leads to its status, results and cancellation (OpenAPI links: clients
    # and stateful testing follow them).
    created = doc["paths"]["/v1/jobs"]["post"]["responses"]["202"]
    created["links"] = {op: {"operationId": op, "parameters": {"job_id": "$response.body#/id"},
                             "description": f"{op.replace('_', ' ')} of the job just submitted"}
                        for op in ("get_job", "get_job_results", "get_job_atlas", "cancel_job", "delete_job")}
    # The key is required only by servers that have keys: ``{}`` (no requirement) is the alternative.
    for item in doc["paths"].values():
        for op in item.values():
            if op.get("security") == [{"ApiKey": []}]:
                op["security"] = [{"ApiKey": []}, {}]
    return doc
