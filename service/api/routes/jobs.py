"""Sweep jobs: submit a sweep spec, follow it, fetch its rows (JSON pages or streamed CSV), cancel or
delete it.

Handlers are plain functions (FastAPI runs them in its thread pool): they only touch the
SQLite job store; the sweeps (and the figures submitted as jobs, ``POST /v1/plots/{kind}/job``, whose image
``GET /v1/jobs/{id}/figure`` serves) run in the job runner's threads (:mod:`service.jobs.runner`). The one
exception, ``GET /v1/jobs/{id}/atlas``, reads the job's rows in a thread and assembles its stability atlas in the
solver threads (:func:`service.api.dispatch.run_task`, under the time limit). With API keys configured a job
belongs to the key that submitted it (the store keeps the key's SHA-256): every other key gets 404 for it, as for
an unknown id. Storage faults raise ``JobsUnavailable``, answered 503 ``jobs_unavailable`` by
:mod:`service.api.errors`.
"""

from __future__ import annotations

import io
import logging
from collections.abc import Iterator, Mapping
from datetime import UTC, datetime
from typing import Annotated, Any, Literal

from fastapi import APIRouter, Body, Query, Request, Response
from starlette.concurrency import run_in_threadpool
from starlette.responses import Response as PlainResponse
from starlette.responses import StreamingResponse

from tensegrity_opt.applications.sweeps import write_csv
from tensegrity_opt.errors import InvalidParameterError

from ... import examples as ex
from ...config import Settings
from ...examples import ERRORS
from ...jobs import JobFinished, JobNotFound, JobRunner
from ...responses import render_json_bounded
from ...schemas import AtlasOut, ErrorOut
from ...schemas import jobs as js
from ...tasks.paths import find_job_atlas
from ...tasks.plots import FIGURE_ANALYSIS
from ..deps import Owner, Runner, SettingsDep, finished_atlas_job, path_deadline
from ..dispatch import Placement, run_task
from ..errors import ServiceError
from ..json_bodies import JSONBodyRoute

router = APIRouter(route_class=JSONBodyRoute, prefix="/v1/jobs", tags=["jobs"])
log = logging.getLogger("service.jobs")

_NOT_FOUND = {"code": "not_found", "message": "no job with id '0123456789abcdef0123456789abcdef'", "field": "id"}
_UNAVAILABLE = {"code": "jobs_unavailable",
                "message": "the job store (TENSEGRITY_JOBS_DB) cannot be written: database or disk is full"}
_INVALID = {
    "validation_error": ERRORS[422]["validation_error"],
    "invalid_parameter": {"summary": "the spec does not fit the analysis", "value": {
        "code": "invalid_parameter", "field": "grid.dx",
        "message": "grid.dx: 'dx' is not used by analysis 'buckling' (it uses n, a, b, k, L0)"}},
    "sweep_too_large": {"summary": "more points than the server runs in one job", "value": {
        "code": "sweep_too_large", "field": "grid",
        "message": "grid: the sweep has 250000 points; this server runs at most 100000 per job",
        "details": {"total": 250000, "max_points": 100000}}},
    "too_many_segments": {"summary": "a chain longer than the server accepts", "value": {
        "code": "too_many_segments", "field": "grid.n[2]",
        "message": "grid.n[2]: the chain has 500 segments; this server accepts at most 200",
        "details": {"n": 500, "max_segments": 200}}},
}


def _err(status: int, description: str, examples: dict[str, Any]) -> dict[str, Any]:
    entry: dict[str, Any] = {"model": ErrorOut, "description": description,
                             "content": {"application/json": {"examples": examples}}}
    if status == 401:
        entry["headers"] = {"WWW-Authenticate": {"description": "the scheme: ApiKey", "schema": {"type": "string"}}}
    return entry


_401 = _err(401, "Missing or wrong `X-API-Key` (only when the server has API keys configured).", ERRORS[401])
_404 = _err(404, "No job with this id.", {"not_found": {"summary": "unknown job id", "value": _NOT_FOUND}})
_422_ID = _err(422, "Invalid path or query parameter (`validation_error`, with its name in `field`).",
               {"validation_error": {
    "summary": "bad query parameter", "value": {
        "code": "validation_error", "message": "limit: Input should be greater than or equal to 0", "field": "limit",
        "errors": [{"field": "limit", "message": "Input should be greater than or equal to 0",
                    "type": "greater_than_equal"}]}}})
_503 = _err(503, "The job store cannot be used: its SQLite file cannot be opened, is damaged or read-only, or "
                 "was deleted or replaced while the server runs.",
            {"jobs_unavailable": {"summary": "job store unavailable", "value": _UNAVAILABLE}})
_503["headers"] = {"Retry-After": {"description": "seconds (TENSEGRITY_RETRY_AFTER)", "schema": {"type": "integer"}}}


#: Rows in one JSON page of ``GET /v1/jobs/{id}/results`` when ``limit`` is not given (at most the server's
#: ``TENSEGRITY_JOBS_RESULTS_MAX_LIMIT``).
RESULTS_DEFAULT_LIMIT = 1000
#: Rows read from the store per batch of a streamed CSV download.
CSV_BATCH = 1000


def _not_found(job_id: str) -> ServiceError:
    return ServiceError(404, "not_found", f"no job with id {job_id!r}", field="id")


def _job(runner: JobRunner, job_id: str, owner: str | None) -> dict[str, Any]:
    try:
        return runner.get(job_id, owner)
    except JobNotFound:
        raise _not_found(job_id) from None


@router.post(
    "", operation_id="submit_job", status_code=202, response_model=js.JobCreated,
    summary="Submit a sweep as a background job",
    description="Body: a sweep spec (`analysis`, `manipulator`, `grid` | `points`, `options`; see "
                "`tensegrity_opt.applications.sweeps`). The base chain is uniform (`{n, a, b, k, L0}`, which the "
                "points may vary) or given by its segments (`{\"segments\": [{a, b, k, L0}, ...]}`, `k` and `L0` a "
                "number or the two springs' pair: pre-bent, heterogeneous; the points then vary only dx, dy, load). "
                "`analysis: atlas` over a grid in `dx` and `dy` (option `method`: search | homotopy) computes every "
                "equilibrium of each target; `GET /v1/jobs/{id}/atlas` then gives the stability atlas. Answers 202 "
                "at once with the job `id` and its number of points. A "
                "server runs at most `TENSEGRITY_JOBS_MAX_RUNNING` jobs at a time; jobs take turns of "
                "`TENSEGRITY_JOBS_SLICE_SECONDS` (round-robin in order of arrival), so a huge job does not hold "
                "later ones `queued`. A point longer than `TENSEGRITY_JOBS_POINT_TIMEOUT` becomes an error row "
                "`timeout: ...` and the job goes on. Every finished point is stored in SQLite, so a server "
                "restart resumes the job where it stopped. With API keys configured the job belongs to the key "
                "that submitted it. Follow it with `GET /v1/jobs/{id}`.",
    responses={
        202: {"description": "Job accepted (queued)", "headers": {"Location": {
            "description": "the job's URL", "schema": {"type": "string"}}},
              "content": {"application/json": {"example": {"id": js.JOB_EXAMPLE["id"], "status": "queued",
                                                           "total": 9, "analysis": "buckling"}}}},
        401: _401,
        413: _err(413, "Request body larger than the server's limit (`TENSEGRITY_MAX_BODY_BYTES`).", ERRORS[413]),
        422: _err(422, "Invalid spec: a schema violation (`validation_error`) or a spec that does not fit its "
                       "analysis (`invalid_parameter`), more points than the server runs (`sweep_too_large`), "
                       "a chain over the server's limit (`too_many_segments`; on `options.method`: an atlas by "
                       "the homotopy on a chain over `homotopy_max_segments`); `field` names the culprit.",
                  _INVALID),
        503: _503,
    })
def submit_job(
    runner: Runner, owner: Owner, response: Response,
    spec: Annotated[js.JobSpec, Body(openapi_examples=js.SPEC_EXAMPLES)],
) -> Any:
    try:
        job = runner.submit(spec.to_spec(), owner)
    except InvalidParameterError as exc:
        details = {k: v for k, v in exc.details.items() if v is not None} or None
        raise ServiceError(422, exc.code, exc.message, field=exc.field, details=details) from None
    response.headers["Location"] = f"/v1/jobs/{job['id']}"
    return {"id": job["id"], "status": job["status"], "total": job["total"], "analysis": job["analysis"]}


@router.get(
    "", operation_id="list_jobs", response_model=js.JobList, summary="List jobs, newest first",
    description="With API keys configured: the jobs of the calling key only.",
    responses={200: {"description": "jobs (no rows)", "content": {"application/json": {"example": {"jobs": [
        {k: v for k, v in js.JOB_EXAMPLE.items() if k not in ("spec", "columns", "results", "offset", "next_offset")}
    ]}}}}, 401: _401, 422: _422_ID, 503: _503})
def list_jobs(
    runner: Runner, owner: Owner,
    limit: Annotated[int, Query(ge=1, le=1000, description="most jobs listed")] = 50,
    status: Annotated[js.JobStatus | None, Query(description="only jobs with this status")] = None,
) -> Any:
    return {"jobs": [summary(j) for j in runner.list(limit, status, owner)]}


@router.get(
    "/{job_id}", operation_id="get_job", response_model=js.JobOut,
    summary="Status, progress and the rows finished so far",
    description="`status`: queued | running | done | failed | cancelled | interrupted (a started job waiting "
                "for its next turn is `queued` again); `done` / `total` points (`progress`); `results`: a page "
                "of the finished rows by index (`offset`, `limit`; `next_offset` when there are more). All "
                "rows: `GET /v1/jobs/{id}/results`. Someone else's job (API keys configured) is 404.",
    responses={200: {"description": "the job", "content": {"application/json": {"example": js.JOB_EXAMPLE}}},
               401: _401, 404: _404, 422: _422_ID, 503: _503})
def get_job(
    runner: Runner, owner: Owner, job_id: str, settings: SettingsDep,
    offset: Annotated[int, Query(ge=0, le=10_000_000, description="rows to skip")] = 0,
    limit: Annotated[int, Query(ge=0, le=10_000, description="most rows returned")] = 100,
) -> Any:
    job = _job(runner, job_id, owner)
    limit = min(limit, runner.results_max_limit)
    rows = runner.rows(job_id, offset, limit + 1)
    more = len(rows) > limit and limit > 0
    return _bounded({**summary(job), "spec": job["spec"], "columns": job["columns"], "results": rows[:limit],
                     "offset": offset, "next_offset": offset + limit if more else None}, settings)


@router.get(
    "/{job_id}/results", operation_id="get_job_results", response_model=js.JobResults,
    summary="The finished rows: JSON pages, or CSV streamed (?format=csv or Accept: text/csv)",
    description="One row per finished point, by index: `index`, the swept parameters, the analysis's columns and "
                "`error` (`null`, or `code: message` for a point that failed). While the job runs these are the "
                "partial results (`complete`: false).\n\n"
                f"JSON is paged: `offset` (default 0) and `limit` (default {RESULTS_DEFAULT_LIMIT}; a larger one "
                "is cut to the server's `TENSEGRITY_JOBS_RESULTS_MAX_LIMIT`, 10000 by default, and the answer's "
                "`limit` says the one applied); `done` is the number of rows there are, `next_offset` the offset "
                "of the next page (`null` on the last one).\n\n"
                "CSV is streamed from the store in batches: every row from `offset` (all of them by default; "
                "`limit` bounds it, without the JSON maximum). Header = `columns`, lists as JSON text, missing "
                "values empty; response headers `X-Total-Rows` (rows there are) and, when `limit` leaves rows "
                "out, `X-Next-Offset`.",
    responses={200: {"description": "the rows", "content": {
        "application/json": {"example": js.RESULTS_EXAMPLE},
        "text/csv": {"schema": {"type": "string"}, "example": js.CSV_EXAMPLE}},
        "headers": {"X-Total-Rows": {"description": "CSV: rows stored for the job", "schema": {"type": "integer"}},
                    "X-Next-Offset": {"description": "CSV with `limit`: offset of the rows left out",
                                      "schema": {"type": "integer"}}}},
        401: _401, 404: _404,
        422: _422_ID,
        503: _503})
def get_job_results(
    request: Request, runner: Runner, owner: Owner, job_id: str,
    settings: SettingsDep,
    format: Annotated[Literal["json", "csv"] | None, Query(
        description="json or csv (default: from the Accept header, else json)")] = None,
    offset: Annotated[int, Query(ge=0, le=10_000_000, description="rows to skip")] = 0,
    limit: Annotated[int | None, Query(ge=0, le=10_000_000, description=(
        f"most rows: JSON default {RESULTS_DEFAULT_LIMIT}, cut to TENSEGRITY_JOBS_RESULTS_MAX_LIMIT; "
        "CSV default all"))] = None,
) -> Any:
    job = _job(runner, job_id, owner)
    fmt = format or ("csv" if "text/csv" in request.headers.get("accept", "").lower() else "json")
    total_rows = job["done"]
    if fmt == "csv":
        return _csv_response(runner, job, offset, limit)
    # A larger limit is cut to the server's maximum (not refused: the maximum is a setting, the schema cannot
    # say it); the answer's ``limit`` and ``next_offset`` say what was sent and where the rest starts.
    limit = min(RESULTS_DEFAULT_LIMIT if limit is None else limit, runner.results_max_limit)
    rows = runner.rows(job_id, offset, limit + 1)
    more = len(rows) > limit and limit > 0          # limit = 0: the counts only, no next page
    return _bounded({"id": job_id, "status": job["status"], "complete": job["status"] == "done",
                     "total": job["total"], "done": total_rows, "columns": job["columns"], "offset": offset,
                     "limit": limit, "next_offset": offset + limit if more else None, "rows": rows[:limit]},
                    settings)


def _bounded(content: dict[str, Any], settings: Settings) -> PlainResponse:
    """The page rendered here (a plain ``def`` route: in the thread pool, not on the event loop), within
    ``max_response_bytes`` (422 ``response_too_large`` naming ``limit``: ask for fewer rows)."""
    return PlainResponse(render_json_bounded(content, settings.max_response_bytes, "limit"),
                         media_type="application/json")


def _csv_response(runner: JobRunner, job: dict[str, Any], offset: int, limit: int | None) -> Any:
    job_id = job["id"]
    batches = runner.row_batches(job_id, offset, limit, CSV_BATCH)
    first = next(batches, [])            # storage faults before the first byte are still a 503

    def body() -> Iterator[str]:
        buf = io.StringIO()
        write_csv(buf, job["columns"], first)
        yield buf.getvalue()
        try:
            for rows in batches:
                buf = io.StringIO()
                write_csv(buf, job["columns"], rows, header=False)
                yield buf.getvalue()
        except Exception:  # the status line is sent: all that is left is to end the body early
            log.exception("job %s: the CSV download stopped", job_id)

    headers = {"Content-Disposition": f'attachment; filename="job-{job_id}.csv"',
               "X-Total-Rows": str(job["done"])}
    if limit is not None and offset + limit < job["done"]:
        headers["X-Next-Offset"] = str(offset + limit)
    return StreamingResponse(body(), media_type="text/csv; charset=utf-8", headers=headers)


_ATLAS_409 = _err(409, "The job is not done (`job_not_done`, `details.status` says what it is): its atlas is made "
                       "from the rows of a done job.", {"job_not_done": {"summary": "the job still runs", "value": {
                           "code": "job_not_done", "field": "id",
                           "message": "job '3f0c9a4e1b7d4c2a9e8f6d5c4b3a2910' is running (4 of 9 points): its atlas "
                                      "is made from the rows of a done job",
                           "details": {"status": "running", "done": 4, "total": 9}}}})
_ATLAS_422 = _err(422, "Not an atlas job (`invalid_parameter` on `spec.analysis`, or on `spec.grid` for an atlas "
                       "not over a grid in exactly dx and dy), or a bad query parameter (`validation_error`).",
                  {**_422_ID["content"]["application/json"]["examples"],
                   "not_an_atlas": {"summary": "the job is another analysis", "value": {
                       "code": "invalid_parameter", "field": "spec.analysis",
                       "message": "job '3f0c9a4e1b7d4c2a9e8f6d5c4b3a2910' is a 'buckling' sweep, not an atlas "
                                  "(analysis 'atlas' over a grid in dx and dy)"}},
                   "response_too_large": ERRORS[422]["response_too_large"]})
_ATLAS_503 = _err(503, "The job store cannot be used (`jobs_unavailable`), or the solver pool is saturated "
                       "(`overloaded`).", {**_503["content"]["application/json"]["examples"], **ERRORS[503]})
_ATLAS_503["headers"] = _503["headers"]


@router.get(
    "/{job_id}/atlas", operation_id="get_job_atlas", response_model=AtlasOut,
    summary="The stability atlas of a finished atlas job",
    description="For a job with `analysis: atlas` over a grid in `dx` and `dy` that is `done`: the atlas "
                "(`tensegrity_opt.applications.sweeps.atlas_from_rows`: each stored stable equilibrium re-solved, "
                "then the grid edges analysed for the least-energy switches and the branch ends), the body of "
                "`POST /v1/atlas` for the same grid. Targets whose point failed are in it with their `error` "
                "(`status: partial`). `edges=false`: the counts only. The edge analysis stops shortly before the "
                "server's time limit and answers what it has (`status: \"time_limit\"`) instead of a 504. A job "
                "not done yet: 409 `job_not_done`; another analysis, or an atlas not over dx x dy: 422 "
                "`invalid_parameter` on `spec.analysis` / `spec.grid`. Someone else's job (API keys configured) "
                "is 404.",
    responses={200: {"description": "the atlas", "content": {"application/json": {"example": ex.ATLAS}}},
               401: _401, 404: _404, 409: _ATLAS_409, 422: _ATLAS_422, 503: _ATLAS_503,
               504: _err(504, "The re-solve of the stored equilibria did not finish within the server's time limit.",
                         ERRORS[504])})
async def get_job_atlas(
    request: Request, runner: Runner, owner: Owner, job_id: str,
    settings: SettingsDep,
    edges: Annotated[bool, Query(description="locate the switches and branch ends on the grid edges")] = True,
) -> Any:
    spec, rows, ctx = await run_in_threadpool(finished_atlas_job, runner, owner, job_id)
    return await run_task(request, find_job_atlas, spec, rows, edges, path_deadline(settings), fields=ctx,
                          placement=Placement.HEAVY, size_field="id")


_FIGURE_409 = _err(409, "The figure job is not done (`job_not_done`; `details.status` says what it is, "
                        "`details.message` why a failed job failed).", {"job_not_done": {
                            "summary": "the figure is being drawn", "value": {
                                "code": "job_not_done", "field": "id",
                                "message": "job '3f0c9a4e1b7d4c2a9e8f6d5c4b3a2910' is running (4 of 11 steps): its "
                                           "figure is served once the job is done",
                                "details": {"status": "running", "done": 4, "total": 11}}}})
_FIGURE_422 = _err(422, "Not a figure job (`invalid_parameter` on `id`), or a bad path parameter.", {
    **_422_ID["content"]["application/json"]["examples"],
    "not_a_figure": {"summary": "the job is a sweep", "value": {
        "code": "invalid_parameter", "field": "id",
        "message": "job '3f0c9a4e1b7d4c2a9e8f6d5c4b3a2910' is a 'buckling' sweep, not a figure job (POST "
                   "/v1/plots/{kind}/job)"}}})


@router.get(
    "/{job_id}/figure", operation_id="get_job_figure", response_class=PlainResponse, response_model=None,
    summary="The image of a done figure job",
    description="For a job submitted with `POST /v1/plots/{kind}/job` that is `done`: its image, `image/png` or "
                "`image/svg+xml` as the body's `format` asked. A job not done yet (or failed, cancelled, interrupted): "
                "409 `job_not_done` with its status (and, when it failed, its message: the row with the `error` "
                "says the same); a sweep job: 422 `invalid_parameter` on `id`. Someone else's job (API keys "
                "configured) is 404.",
    responses={200: {"description": "The figure.", "content": {
        "image/png": {"schema": {"type": "string", "format": "binary"}},
        "image/svg+xml": {"schema": {"type": "string"}, "example": (
            '<?xml version="1.0" encoding="utf-8" standalone="no"?>\n<svg xmlns="http://www.w3.org/2000/svg" '
            'width="763pt" height="360pt" viewBox="0 0 763 360">...</svg>')}}},
               401: _401, 404: _404, 409: _FIGURE_409, 422: _FIGURE_422, 503: _503})
def get_job_figure(runner: Runner, owner: Owner, job_id: str) -> Any:
    job = _job(runner, job_id, owner)
    if job["analysis"] != FIGURE_ANALYSIS:
        raise ServiceError(422, "invalid_parameter", f"job {job_id!r} is a {job['analysis']!r} sweep, not a figure "
                           "job (POST /v1/plots/{kind}/job)", field="id")
    image = runner.figure(job_id) if job["status"] == "done" else None
    if image is None:
        details: dict[str, Any] = {"status": job["status"], "done": job["done"], "total": job["total"]}
        if job["message"] and job["status"] != "done":
            details["message"] = job["message"]
        raise ServiceError(409, "job_not_done", f"job {job_id!r} is {job['status']} ({job['done']} of {job['total']} "
                           "steps): its figure is served once the job is done", field="id", details=details)
    media, data = image
    kind, fmt = job["spec"].get("kind", "figure"), "svg" if media == "image/svg+xml" else "png"
    return PlainResponse(data, media_type=media,
                         headers={"Content-Disposition": f'inline; filename="{kind}.{fmt}"'})


@router.post(
    "/{job_id}/cancel", operation_id="cancel_job", response_model=js.JobSummary,
    summary="Cancel a queued or running job (its finished points are kept)",
    description="The job stops at once (the point in progress is abandoned once the native call in progress "
                "returns; in another server sharing the database: at that server's next lease renewal) and "
                "stays, `cancelled`, with its finished points: its results can still be read, and `DELETE` "
                "removes it. Cancelling a cancelled job answers it again; a job that ended otherwise (done, "
                "failed, interrupted): 409 `job_finished`. Someone else's job (API keys configured) is 404.",
    responses={200: {"description": "the cancelled job", "content": {"application/json": {"example": {
        **{k: v for k, v in js.JOB_EXAMPLE.items() if k not in ("spec", "columns", "results", "offset",
                                                                  "next_offset")},
        "status": "cancelled", "finished_at": "2025-01-01T12:00:01.000Z",
        "message": "cancelled by a request; finished points are kept"}}}},
        401: _401, 404: _404,
        409: _err(409, "The job already ended (`job_finished`, `details.status` says how).", {"job_finished": {
            "summary": "the job had ended", "value": {
                "code": "job_finished", "field": "id", "details": {"status": "done"},
                "message": "job '3f2a0c1e9b7d4e5f8a6b2c1d0e9f8a7b' already ended (done): nothing to cancel"}}}),
        422: _422_ID, 503: _503})
def cancel_job(runner: Runner, owner: Owner, job_id: str) -> Any:
    try:
        return summary(runner.cancel(job_id, owner))
    except JobNotFound:
        raise _not_found(job_id) from None
    except JobFinished as exc:
        raise ServiceError(409, "job_finished", f"job {job_id!r} already ended ({exc.status}): nothing to cancel",
                           field="id", details={"status": exc.status}) from None


@router.delete(
    "/{job_id}", operation_id="delete_job", status_code=204, response_class=PlainResponse, response_model=None,
    summary="Delete a job and all its rows (a queued or running one is cancelled first)",
    description="Removes the job and its rows: 204, no body; the id is then unknown (404). A queued or running "
                "job is cancelled first (to keep its finished points, `POST /v1/jobs/{id}/cancel` instead). "
                "Finished jobs are also deleted after `TENSEGRITY_JOBS_RETENTION_DAYS`. Someone else's job "
                "(API keys configured) is 404.",
    responses={204: {"description": "the job and its rows were deleted"},
               401: _401, 404: _404, 422: _422_ID, 503: _503})
def delete_job(runner: Runner, owner: Owner, job_id: str) -> Any:
    try:
        runner.delete(job_id, owner)
    except JobNotFound:
        raise _not_found(job_id) from None
    return PlainResponse(status_code=204)


def iso(ts: float | None) -> str | None:
    """An epoch time as ISO 8601 UTC with milliseconds (``...Z``)."""
    if ts is None:
        return None
    return datetime.fromtimestamp(ts, UTC).isoformat(timespec="milliseconds").replace("+00:00", "Z")


def summary(job: Mapping[str, Any]) -> dict[str, Any]:
    """The API's ``JobSummary`` of a stored job."""
    total = int(job["total"])
    return {"id": job["id"], "status": job["status"], "analysis": job["analysis"], "total": total,
            "done": job["done"], "failed": job["failed"], "progress": round(job["done"] / total, 6) if total else 1.0,
            "runs": job["runs"], "created_at": iso(job["created_at"]), "started_at": iso(job["started_at"]),
            "finished_at": iso(job["finished_at"]), "message": job["message"]}
