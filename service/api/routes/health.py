"""Health: liveness and readiness, always open (no API key, whatever the server's keys: orchestrators and load
balancers probe them without one)."""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter, Request
from starlette.responses import JSONResponse

from ... import schemas as s

router = APIRouter(tags=["ops"])


@router.get("/healthz", operation_id="healthz", response_model=s.Health, summary="Liveness: the process answers",
            responses={200: {"description": "alive", "content": {"application/json": {"example": {"status": "ok"}}}}})
async def healthz() -> Any:
    return {"status": "ok"}


@router.get(
    "/readyz", operation_id="readyz", response_model=s.Ready,
    summary="Readiness: the solver workers are started (and warmed up) and the job store works",
    description="503 while the server starts (`starting`) and while its job store fails (`status: degraded`: a "
                "full disk, an unreadable file ...; `jobs.message` says what fails). A failing store is retried "
                "every `TENSEGRITY_JOBS_RETRY_SECONDS`; the answer is 200 again once a retry succeeds. While a "
                "solver process is lost and restarted the answer stays 200 (the solver threads answer) and "
                "`degraded` names what runs slower or refuses (`processes` says where each kind stands).",
    responses={
        200: {"description": "ready", "content": {"application/json": {"example": {
            "status": "ready", "workers": 2, "queue_size": 64, "in_flight": 0,
            "jobs": {"status": "ok", "message": None, "since": None},
            "processes": {"fast": {"state": "restarting", "ready": 0, "workers": 1, "restarts": 2},
                          "design": {"state": "up", "ready": 1, "workers": 1, "restarts": 0}},
            "degraded": ["fast_path"]}}}},
        503: {"model": s.Ready, "description": "still starting, or the job store fails", "content": {
            "application/json": {"examples": {
                "starting": {"summary": "still starting", "value": {
                    "status": "starting", "workers": 2, "queue_size": 64, "in_flight": 0,
                    "jobs": {"status": "ok", "message": None, "since": None}}},
                "degraded": {"summary": "the job store fails", "value": {
                    "status": "degraded", "workers": 2, "queue_size": 64, "in_flight": 0,
                    "jobs": {"status": "failing", "since": 1767225600.0,
                             "message": "the job store (TENSEGRITY_JOBS_DB) cannot be written: database or disk "
                                        "is full"}}}}}}}})
async def readyz(request: Request) -> Any:
    executors = request.app.state.executors
    pool, heavy = executors.threads, executors.killable
    ready = bool(getattr(request.app.state, "ready", False)) and pool.started
    jobs = request.app.state.jobs.health()
    status = "starting" if not ready else "ready" if jobs["status"] == "ok" else "degraded"
    processes = {name: {"state": ex.state, "ready": ex.ready_count, "workers": ex.workers, "restarts": ex.restarts}
                 for name, ex in (("fast", executors.fast), ("design", heavy)) if ex is not None}
    degraded = []
    if ready and "fast" in processes and processes["fast"]["state"] != "up":
        degraded.append("fast_path")            # the solver threads answer its requests meanwhile
    if "design" in processes and processes["design"]["state"] in ("restarting", "down"):
        degraded.append("design_processes")
    if jobs["status"] != "ok":
        degraded.append("job_store")
    body = {"status": status, "workers": pool.workers, "queue_size": pool.queue_size,
            "in_flight": pool.in_flight + (heavy.in_flight if heavy is not None else 0), "jobs": jobs,
            "processes": processes, "degraded": degraded}
    return body if status == "ready" else JSONResponse(status_code=503, content=body)
