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
    summary="Readiness: the solver workers are started (and warmed up)",
    responses={
        200: {"description": "ready", "content": {"application/json": {"example": {
            "status": "ready", "workers": 2, "queue_size": 64, "in_flight": 0}}}},
        503: {"model": s.Ready, "description": "still starting", "content": {"application/json": {"example": {
            "status": "starting", "workers": 2, "queue_size": 64, "in_flight": 0}}}}})
async def readyz(request: Request) -> Any:
    executors = request.app.state.executors
    pool, heavy = executors.threads, executors.killable
    ready = bool(getattr(request.app.state, "ready", False)) and pool.started
    body = {"status": "ready" if ready else "starting", "workers": pool.workers, "queue_size": pool.queue_size,
            "in_flight": pool.in_flight + (heavy.in_flight if heavy is not None else 0)}
    return body if ready else JSONResponse(status_code=503, content=body)
