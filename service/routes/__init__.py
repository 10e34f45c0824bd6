"""One router per area; every route has a summary, a stable ``operation_id``, examples and error docs."""

from __future__ import annotations

from typing import Any

from ..examples import ERRORS
from ..schemas import ErrorOut

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
