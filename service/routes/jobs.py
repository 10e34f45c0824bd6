"""Sweep jobs: submit a sweep spec, follow it, fetch its rows (JSON or CSV), cancel it.

Handlers are plain functions (FastAPI runs them in its thread pool): they only touch the
SQLite job store; the sweeps themselves run in the job runner's background thread
(:mod:`service.jobs`).
"""

from __future__ import annotations

import io
from typing import Annotated, Any, Literal

from fastapi import APIRouter, Body, Depends, Query, Request, Response
from starlette.responses import Response as PlainResponse

from tensegrity_opt.errors import InvalidParameterError
from tensegrity_opt.sweep import write_csv

from .. import job_schemas as js
from ..errors import ServiceError
from ..examples import ERRORS
from ..jobs import JobFinished, JobNotFound, JobRunner, JobsUnavailable, summary
from ..schemas import ErrorOut

router = APIRouter(prefix="/v1/jobs", tags=["jobs"])

_NOT_FOUND = {"code": "not_found", "message": "no job with id '0123456789abcdef0123456789abcdef'", "field": "id"}
_FINISHED = {"code": "job_finished", "message": "the job is already done; only queued or running jobs can be "
                                                "cancelled", "field": "id", "details": {"status": "done"}}
_UNAVAILABLE = {"code": "jobs_unavailable",
                "message": "cannot open the job store tensegrity_jobs.sqlite3: unable to open database file"}
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
_503 = _err(503, "The job store cannot be used (its SQLite file could not be opened).",
            {"jobs_unavailable": {"summary": "job store unavailable", "value": _UNAVAILABLE}})


async def get_runner(request: Request) -> JobRunner:
    runner = getattr(request.app.state, "jobs", None)
    if runner is None:  # pragma: no cover - the router is only included together with a runner
        raise ServiceError(503, "jobs_unavailable", "this server has no job runner")
    return runner


Runner = Annotated[JobRunner, Depends(get_runner)]


def _not_found(job_id: str) -> ServiceError:
    return ServiceError(404, "not_found", f"no job with id {job_id!r}", field="id")


def _job(runner: JobRunner, job_id: str) -> dict[str, Any]:
    try:
        return runner.get(job_id)
    except JobNotFound:
        raise _not_found(job_id) from None
    except JobsUnavailable as exc:
        raise ServiceError(503, "jobs_unavailable", str(exc)) from None


@router.post(
    "", operation_id="submit_job", status_code=202, response_model=js.JobCreated,
    summary="Submit a sweep as a background job",
    description="Body: a sweep spec (`analysis`, `manipulator`, `grid` | `points`, `options`; see "
                "`tensegrity_opt.sweep`). Answers 202 at once with the job `id` and its number of points; the "
                "points are solved one job at a time in a background thread and every finished point is "
                "stored in SQLite, so a server restart resumes the job where it stopped. Follow it with "
                "`GET /v1/jobs/{id}`.",
    responses={
        202: {"description": "Job accepted (queued)", "headers": {"Location": {
            "description": "the job's URL", "schema": {"type": "string"}}},
              "content": {"application/json": {"example": {"id": js.JOB_EXAMPLE["id"], "status": "queued",
                                                           "total": 9, "analysis": "buckling"}}}},
        401: _401,
        413: _err(413, "Request body larger than the server's limit (`TENSEGRITY_MAX_BODY_BYTES`).", ERRORS[413]),
        422: _err(422, "Invalid spec: a schema violation (`validation_error`) or a spec that does not fit its "
                       "analysis (`invalid_parameter`), more points than the server runs (`sweep_too_large`), "
                       "a chain over the server's limit (`too_many_segments`); `field` names the culprit.",
                  _INVALID),
        503: _503,
    })
def submit_job(
    runner: Runner, response: Response,
    spec: Annotated[js.JobSpec, Body(openapi_examples=js.SPEC_EXAMPLES)],
) -> Any:
    try:
        job = runner.submit(spec.to_spec())
    except InvalidParameterError as exc:
        details = {k: v for k, v in exc.details.items() if v is not None} or None
        raise ServiceError(422, exc.code, exc.message, field=exc.field, details=details) from None
    except JobsUnavailable as exc:
        raise ServiceError(503, "jobs_unavailable", str(exc)) from None
    response.headers["Location"] = f"/v1/jobs/{job['id']}"
    return {"id": job["id"], "status": job["status"], "total": job["total"], "analysis": job["analysis"]}


@router.get(
    "", operation_id="list_jobs", response_model=js.JobList, summary="List jobs, newest first",
    responses={200: {"description": "jobs (no rows)", "content": {"application/json": {"example": {"jobs": [
        {k: v for k, v in js.JOB_EXAMPLE.items() if k not in ("spec", "columns", "results", "offset", "next_offset")}
    ]}}}}, 401: _401, 422: _422_ID, 503: _503})
def list_jobs(
    runner: Runner,
    limit: Annotated[int, Query(ge=1, le=1000, description="most jobs listed")] = 50,
    status: Annotated[js.JobStatus | None, Query(description="only jobs with this status")] = None,
) -> Any:
    try:
        return {"jobs": [summary(j) for j in runner.list(limit, status)]}
    except JobsUnavailable as exc:
        raise ServiceError(503, "jobs_unavailable", str(exc)) from None


@router.get(
    "/{job_id}", operation_id="get_job", response_model=js.JobOut,
    summary="Status, progress and the rows finished so far",
    description="`status`: queued | running | done | failed | cancelled | interrupted; `done` / `total` points "
                "(`progress`); `results`: a page of the finished rows by index (`offset`, `limit`; "
                "`next_offset` when there are more). All rows: `GET /v1/jobs/{id}/results`.",
    responses={200: {"description": "the job", "content": {"application/json": {"example": js.JOB_EXAMPLE}}},
               401: _401, 404: _404, 422: _422_ID, 503: _503})
def get_job(
    runner: Runner, job_id: str,
    offset: Annotated[int, Query(ge=0, le=10_000_000, description="rows to skip")] = 0,
    limit: Annotated[int, Query(ge=0, le=10_000, description="most rows returned")] = 100,
) -> Any:
    job = _job(runner, job_id)
    rows = runner.rows(job_id, offset, limit + 1)
    more = len(rows) > limit
    return {**summary(job), "spec": job["spec"], "columns": job["columns"], "results": rows[:limit],
            "offset": offset, "next_offset": offset + limit if more else None}


@router.get(
    "/{job_id}/results", operation_id="get_job_results", response_model=js.JobResults,
    summary="Every finished row (JSON, or CSV with ?format=csv or Accept: text/csv)",
    description="One row per finished point, by index: `index`, the swept parameters, the analysis's columns and "
                "`error` (`null`, or `code: message` for a point that failed). While the job runs these are the "
                "partial results (`complete`: false). CSV: header = `columns`, lists as JSON text, missing "
                "values empty.",
    responses={200: {"description": "the rows", "content": {
        "application/json": {"example": js.RESULTS_EXAMPLE},
        "text/csv": {"schema": {"type": "string"}, "example": js.CSV_EXAMPLE}}},
        401: _401, 404: _404, 422: _422_ID, 503: _503})
def get_job_results(
    request: Request, runner: Runner, job_id: str,
    format: Annotated[Literal["json", "csv"] | None, Query(
        description="json or csv (default: from the Accept header, else json)")] = None,
) -> Any:
    job = _job(runner, job_id)
    rows = runner.rows(job_id)
    fmt = format or ("csv" if "text/csv" in request.headers.get("accept", "").lower() else "json")
    if fmt == "csv":
        buf = io.StringIO()
        write_csv(buf, job["columns"], rows)
        return PlainResponse(buf.getvalue(), media_type="text/csv; charset=utf-8",
                             headers={"Content-Disposition": f'attachment; filename="job-{job_id}.csv"'})
    return {"id": job_id, "status": job["status"], "complete": job["status"] == "done", "total": job["total"],
            "done": job["done"], "columns": job["columns"], "rows": rows}


@router.delete(
    "/{job_id}", operation_id="cancel_job", response_model=js.JobSummary,
    summary="Cancel a queued or running job (finished points are kept)",
    description="A queued job is cancelled at once, a running one after its current point. Cancelling a "
                "cancelled job again answers it as it is; a job that already ended otherwise is 409 "
                "`job_finished`.",
    responses={200: {"description": "the cancelled job", "content": {"application/json": {"example": {
        **{k: v for k, v in js.JOB_EXAMPLE.items() if k not in ("spec", "columns", "results", "offset",
                                                                  "next_offset")},
        "status": "cancelled", "finished_at": "2025-01-01T12:00:01.000Z",
        "message": "cancelled by a request; finished points are kept"}}}},
        401: _401, 404: _404, 422: _422_ID,
        409: _err(409, "The job already ended (done, failed or interrupted).",
                  {"job_finished": {"summary": "job already finished", "value": _FINISHED}}),
        503: _503})
def cancel_job(runner: Runner, job_id: str) -> Any:
    try:
        job = runner.cancel(job_id)
    except JobNotFound:
        raise _not_found(job_id) from None
    except JobFinished as exc:
        raise ServiceError(409, "job_finished", f"the job is already {exc.status}; only queued or running jobs can "
                                                f"be cancelled", field="id", details={"status": exc.status}) from None
    except JobsUnavailable as exc:
        raise ServiceError(503, "jobs_unavailable", str(exc)) from None
    return summary(job)
