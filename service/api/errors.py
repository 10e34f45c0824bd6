"""The one place where failures become HTTP answers.

Every refusal has the body of :class:`service.schemas.ErrorOut`
(``{"code", "message", "field", ...}``):

=====================================================  ======  ==========================================
failure                                                status  code
=====================================================  ======  ==========================================
request body violates the schema                       422     ``validation_error`` (+ ``errors`` list; a key given
                                                               twice in one object too: ``duplicate_key``)
ragged list of lists (what JSON Schema cannot say)     422     ``invalid_parameter`` naming the field
library ``ValueError`` family (bad input, ill-posed)   422     the exception's ``code``: ``invalid_parameter``,
                                                               ``unreachable_target``, ``straight_not_equilibrium``,
                                                               ``straight_unstable``, ``unsupported``
library ``SolverError`` / ``NoEquilibriumError``       422     ``solver_failed`` / ``no_equilibrium``, ``status``
                                                               holds the solver (IPOPT) status
numerical failure outside the library's own checks     500     ``numerical_failure`` (a server bug: logged with
                                                               the traceback; the library validates its
                                                               inputs first, so none is known)
chain or batch over the configured limit               422     ``too_many_segments`` / ``batch_too_large``
branch longer than the configured limit                422     ``too_many_points`` (``field``: ``max_points``)
control trajectory over ``max_trajectory_steps``       422     ``too_many_steps`` (``field``: ``targets``, ``loads``,
                                                               ``end_angles`` or ``preloads``)
inline atlas over ``max_atlas_targets`` targets        422     ``atlas_too_large`` (``field``: ``dx``; a job then)
atlas of a job that is not done                        409     ``job_not_done`` (``details.status``)
answer over ``max_response_bytes`` (estimated before   422     ``response_too_large`` (``field``: the input
solving where possible, else counted while rendering)          setting the size, ``details.max_response_bytes``)
missing or wrong ``X-API-Key`` (auth configured)       401     ``unauthorized``
control stream handshake from another web origin      403     ``forbidden_origin`` (``field``: ``Origin``;
                                                               before the upgrade)
request body over ``max_body_bytes``                   413     ``body_too_large``
solver pool saturated                                  503     ``overloaded`` (+ ``Retry-After``)
``method: homotopy`` without PHCpack on the server     503     ``homotopy_unavailable``
job store unusable (damaged, read-only, deleted ...)   503     ``jobs_unavailable`` (+ ``Retry-After``)
request line and headers over ``max_header_bytes`` /  431     ``headers_too_large`` (``tensegrity-opt serve``:
more than ``max_headers`` header fields                        :mod:`service.api.connections`, before the app)
request cut by the server's shutdown (still running    503     ``shutting_down`` (+ ``Retry-After``;
``TENSEGRITY_SHUTDOWN_TIMEOUT`` s after SIGTERM)               :class:`ShutdownAnswerMiddleware`)
solve time limit exceeded (also the library's          504     ``timeout``, ``status`` when the library
``TimeLimitError``: IPOPT's ``max_wall_time``)                 stopped (``User_Requested_Stop``, ...)
unknown path / method                                  404/405 ``not_found`` / ``method_not_allowed``
=====================================================  ======  ==========================================

Library fields (``"dx"``, ``"q0"``, ``"segments[2].L0"``, ``"n"`` ...) are rewritten into paths
of the request (``"manipulator.segments[2].L0"``, ``"manipulator.n"``, ``"targets[3].dx"``) by the adapters
(:mod:`service.adapters.fields`), with the field context the route gave its task
(:func:`service.api.dispatch.run_task` maps a task's failure before it leaves the dispatcher).
"""

from __future__ import annotations

import asyncio
import json
import logging
import re
from typing import Any

import numpy as np
from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from starlette.exceptions import HTTPException as StarletteHTTPException
from starlette.responses import JSONResponse
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from tensegrity_opt.errors import HomotopyUnavailableError, TensegrityError, TimeLimitError, unknown_name

from ..adapters.fields import FieldContext
from ..adapters.refusals import refusal_body
from ..execution.executor import Saturated, SolveTimeout
from ..jobs.store import JobsUnavailable
from ..responses import ResponseTooLarge
from .middleware import allowed_methods

log = logging.getLogger("service.errors")

__all__ = ["ApiError", "ServiceError", "error_body", "to_api_error", "status_for", "install", "error_response",
           "validation_body", "field_names", "ShutdownAnswerMiddleware", "SHUTTING_DOWN", "raw_error_response"]


class ServiceError(Exception):
    """A refusal decided by the service itself (limits, auth, body size, pool, time)."""

    def __init__(self, status_code: int, code: str, message: str, *, field: str | None = None,
                 headers: dict[str, str] | None = None, details: dict[str, Any] | None = None) -> None:
        super().__init__(message)
        self.status_code = status_code
        self.code = code
        self.message = message
        self.field = field
        self.headers = headers
        self.details = details


def status_for(exc: BaseException) -> int:
    if isinstance(exc, ServiceError):
        return exc.status_code
    if isinstance(exc, (Saturated, JobsUnavailable)):
        return 503
    if isinstance(exc, (SolveTimeout, TimeLimitError)):
        return 504
    if isinstance(exc, HomotopyUnavailableError):
        return 503
    return 422


def error_body(exc: BaseException, ctx: FieldContext = FieldContext()) -> dict[str, Any] | None:
    """``ErrorOut`` for an exception a solve may raise, or ``None`` when it is a server bug.

    The service's own refusals here; the library's (their ``code``, the field as the request names it) and
    numerical exceptions from numpy/scipy/CasADi (``numerical_failure``, answered with 500: see
    :func:`to_api_error`) by :func:`service.adapters.refusals.refusal_body`.
    """
    if isinstance(exc, ServiceError):
        out: dict[str, Any] = {"code": exc.code, "message": exc.message}
        if exc.field:
            out["field"] = exc.field
        if exc.details:
            out["details"] = exc.details
        return out
    if isinstance(exc, ResponseTooLarge):
        out = {"code": "response_too_large", "message": str(exc),
               "details": {"max_response_bytes": exc.limit,
                           **({"estimated_bytes": exc.estimate} if exc.estimate is not None else {})}}
        if exc.field:
            out["field"] = exc.field
        return out
    if isinstance(exc, SolveTimeout):
        return {"code": "timeout", "message": str(exc)}
    if isinstance(exc, Saturated):
        return {"code": "overloaded", "message": str(exc)}
    if isinstance(exc, JobsUnavailable):
        return {"code": "jobs_unavailable", "message": str(exc)}
    return refusal_body(exc, ctx)


def error_response(status_code: int, body: dict[str, Any], headers: dict[str, str] | None = None) -> JSONResponse:
    return JSONResponse(status_code=status_code, content=body, headers=headers)


def raw_error_response(status_code: int, body: dict[str, Any]) -> bytes:
    """A whole HTTP/1.1 answer (``Connection: close``) with the error ``body``, for what the HTTP protocol refuses
    before the application sees a request (:mod:`service.api.connections`: malformed or oversized heads, requests
    not received in time)."""
    content = json.dumps(body, separators=(",", ":")).encode()
    reason = {400: b"Bad Request", 408: b"Request Timeout", 431: b"Request Header Fields Too Large"}
    return (b"HTTP/1.1 %d %s\r\ncontent-type: application/json\r\nconnection: close\r\ncontent-length: %d\r\n\r\n"
            % (status_code, reason.get(status_code, b""), len(content)) + content)


def _loc_path(loc: tuple[Any, ...] | list[Any]) -> str:
    parts = [p for p in loc if not (isinstance(p, str) and p.startswith("<") and p.endswith(">"))]
    if parts and parts[0] == "body":
        parts = parts[1:]
    out = ""
    for p in parts:
        if isinstance(p, int):
            out += f"[{p}]"
        else:
            out += ("." if out else "") + str(p)
    return out or "body"


#: The request fields giving a chain's length (a uniform chain's ``n``, a segment list, a job's ``n`` values).
_CHAIN_LENGTH_FIELD = re.compile(r"(^|\.)manipulator\.(n|segments)$|^grid\.n\[\d+\]$|^points\[\d+\]\.n$")


def segments_over_limit(errors: list[dict[str, Any]], max_segments: int | None) -> dict[str, Any] | None:
    """``too_many_segments`` for a chain longer than the server accepts, whatever its length.

    The schema caps a chain at its own maximum (``HARD_MAX_SEGMENTS``, 60 for the design endpoints);
    a server set lower (``TENSEGRITY_MAX_SEGMENTS``) refuses the lengths between its setting and that
    cap itself, naming its setting. Above the cap the schema's refusal named the cap, not the real
    limit (n = 150 on a server set to 100: "at most 100"; n = 500: "<= 200"). When every schema error
    is a chain length over a cap above ``max_segments``, the answer is the server's own
    (``too_many_segments``, ``details: {n, max_segments}``); else ``None`` (the schema's error names
    the limit that applies).
    """
    if not errors or max_segments is None:
        return None
    first = None
    for e in errors:
        field = _loc_path(e.get("loc", ()))
        ctx = e.get("ctx") or {}
        kind = e.get("type")
        cap = ctx.get("le") if kind == "less_than_equal" else ctx.get("max_length") if kind == "too_long" else None
        if cap is None or not _CHAIN_LENGTH_FIELD.search(field) or not float(cap) > max_segments:
            return None
        if first is None:
            value = ctx.get("actual_length") if kind == "too_long" else e.get("input")
            first = (field, value)
    field, value = first
    try:
        n: Any = int(value) if float(value) == int(float(value)) else value
    except (TypeError, ValueError, OverflowError):
        n = value
    # the words of the server's own check (deps.check_manipulator; a job's: prefixed by its field)
    where = "" if field.startswith("manipulator.") else f"{field}: "
    return {"code": "too_many_segments", "field": field,
            "message": f"{where}the chain has {n} segments; this server accepts at most {max_segments}",
            "details": {"n": n, "max_segments": max_segments}}


#: The request models' checks of what JSON Schema cannot state (nested lists of one length:
#: :func:`service.schemas.common.same_lengths`): a body the document calls valid, so refused with the domain code of
#: what the library refuses for the same reason, ``invalid_parameter`` on the field, not as a schema violation.
UNSTATED = frozenset({"ragged"})


def _resolve(schema: dict[str, Any], defs: dict[str, Any]) -> dict[str, Any]:
    while isinstance(schema, dict) and "$ref" in schema:
        schema = defs.get(schema["$ref"].rsplit("/", 1)[-1], {})
    return schema if isinstance(schema, dict) else {}


def _forms(schema: dict[str, Any], defs: dict[str, Any]) -> list[dict[str, Any]]:
    schema = _resolve(schema, defs)
    alts = [a for key in ("anyOf", "oneOf", "allOf") for a in schema.get(key, ())]
    return [f for a in alts for f in _forms(a, defs)] if alts else [schema]


def field_names(schema: dict[str, Any], defs: dict[str, Any], loc: tuple[Any, ...] | list[Any]) -> list[str]:
    """The names the object at ``loc`` (a validation error's location, ``body`` first) may have, by the JSON
    schema ``schema`` of the body (``$ref``s into ``defs``; every alternative of a union), in schema order."""
    parts = [p for p in loc if not (isinstance(p, str) and p.startswith("<") and p.endswith(">"))]
    if parts and parts[0] == "body":
        parts = parts[1:]
    level = [schema]
    for part in parts:
        nxt = []
        for form in (f for s in level for f in _forms(s, defs)):
            if isinstance(part, int) and isinstance(form.get("items"), dict):
                nxt.append(form["items"])
            elif part in form.get("properties", {}):
                nxt.append(form["properties"][part])
            elif isinstance(form.get("additionalProperties"), dict):
                nxt.append(form["additionalProperties"])
        level = nxt
    names: dict[str, None] = {}
    for form in (f for s in level for f in _forms(s, defs)):
        names.update(dict.fromkeys(form.get("properties", {})))
    return list(names)


def _unknown_first(items: list[dict[str, Any]], errors: list[dict[str, Any]], names: Any) -> list[dict[str, Any]]:
    """The errors with a misspelt field (``extra_forbidden``) first, each saying so and naming the nearest valid
    name (``dX: unknown field; did you mean dx?``); the others after, in their order."""
    unknown, rest = [], []
    for item, e in zip(items, errors, strict=True):
        if item["type"] != "extra_forbidden":
            rest.append(item)
            continue
        loc = tuple(e.get("loc", ()))
        choices = names(loc[:-1]) if names is not None else []
        unknown.append({**item, "message": unknown_name(str(loc[-1]) if loc else item["field"], choices)})
    if unknown:
        # a required field missing beside a misspelt one is the same mistake: the misspelling leads
        return unknown + rest
    return items


def validation_body(errors: list[dict[str, Any]], names: Any = None) -> dict[str, Any]:
    """The ``validation_error`` body of pydantic's ``errors``; ``names(loc)``: the valid names of the object at
    ``loc`` (:func:`field_names`), for the nearest name to an unknown one."""
    items = []
    for e in errors:
        kind = str(e.get("type", "value_error"))
        if kind == "json_invalid":
            reason = (e.get("ctx") or {}).get("error", "")
            items.append({"field": "body", "message": f"invalid JSON: {reason}".rstrip(": "), "type": kind})
            continue
        items.append({"field": _loc_path(e.get("loc", ())), "message": str(e.get("msg", "invalid")), "type": kind})
    if len(items) == len(errors):
        items = _unknown_first(items, errors, names)
    if not items:
        items = [{"field": "body", "message": "invalid request", "type": "value_error"}]
    first = items[0]
    if all(item["type"] in UNSTATED for item in items):
        # valid by the document, refused as the library refuses what JSON Schema cannot say
        return {"code": "invalid_parameter", "message": f"{first['field']}: {first['message']}",
                "field": first["field"]}
    more = f" (and {len(items) - 1} more)" if len(items) > 1 else ""
    return {"code": "validation_error", "message": f"{first['field']}: {first['message']}{more}",
            "field": first["field"], "errors": items}


class ApiError(Exception):
    """A fully decided HTTP refusal: status, ``ErrorOut`` body and headers."""

    def __init__(self, status_code: int, body: dict[str, Any], headers: dict[str, str] | None = None) -> None:
        super().__init__(body.get("message", ""))
        self.status_code = status_code
        self.body = body
        self.headers = headers


def to_api_error(exc: BaseException, ctx: FieldContext = FieldContext(), *, retry_after: int = 1,
                 timeout_hint: str | None = None) -> ApiError | None:
    """The HTTP refusal for ``exc``, or ``None`` when it is a server bug (a 500). ``timeout_hint``: a sentence added
    to a 504's message (what to do instead, e.g. a figure's job form)."""
    if isinstance(exc, ApiError):
        return exc
    body = error_body(exc, ctx)
    if body is None:
        return None
    # numpy/scipy/CasADi failed where the library did not refuse first: a bug to fix (500), not an answer
    status = 500 if body["code"] == "numerical_failure" else status_for(exc)
    if status == 504 and timeout_hint:
        body["message"] = f"{body['message']}; {timeout_hint}"
    headers = None
    if isinstance(exc, ServiceError) and exc.headers:
        headers = exc.headers
    if status == 503:
        # an executor that refused by its expected wait says when it expects room (at least the setting)
        wait = getattr(exc, "retry_after", None)
        headers = {**(headers or {}), "Retry-After": str(max(retry_after, int(wait)) if wait else retry_after)}
    return ApiError(status, body, headers)


def _record_failure(request: Request, code: str) -> None:
    metrics = getattr(request.app.state, "metrics", None)
    if metrics is not None:
        metrics.failure(code)


#: Exceptions a solve may raise that are answers, not server bugs.
ANSWERED = (ApiError, ServiceError, Saturated, SolveTimeout, JobsUnavailable, TensegrityError, ArithmeticError,
            np.linalg.LinAlgError, ValueError, RuntimeError)


def _body_names(request: Request) -> Any:
    """``names(loc)`` of the request's route: the valid field names at ``loc`` by the OpenAPI document's body."""
    route = request.scope.get("route")
    if route is None or not hasattr(request.app, "openapi"):
        return None
    try:
        doc = request.app.openapi()
        body = doc["paths"][route.path][request.method.lower()]["requestBody"]["content"]["application/json"]["schema"]
    except (KeyError, TypeError, AttributeError):
        return None
    defs = doc.get("components", {}).get("schemas", {})
    return lambda loc: field_names(body, defs, loc)


def install(app: FastAPI) -> None:
    """Register the exception handlers on ``app``."""

    async def _validation(request: Request, exc: Exception) -> JSONResponse:
        assert isinstance(exc, RequestValidationError)
        errors = list(exc.errors())
        settings = getattr(request.app.state, "settings", None)
        over = segments_over_limit(errors, getattr(settings, "max_segments", None))
        if over is not None:
            _record_failure(request, "too_many_segments")
            return error_response(422, over)
        body = validation_body(errors, _body_names(request))
        _record_failure(request, "validation_error")
        ctype = request.headers.get("content-type", "")
        if body["field"] == "body" and "json" not in ctype.lower():
            body["message"] += " (send the body as JSON with Content-Type: application/json)"
        return error_response(422, body)

    async def _answered(request: Request, exc: Exception) -> JSONResponse:
        # a task's failure comes mapped already (an ApiError from service.api.dispatch, with the request's
        # field names); what a route raised itself needs no field context
        settings = getattr(request.app.state, "settings", None)
        err = to_api_error(exc, retry_after=getattr(settings, "retry_after", 1))
        if err is None:  # pragma: no cover - ANSWERED types always map
            return await _other(request, exc)
        _record_failure(request, err.body["code"])
        if err.body["code"] == "numerical_failure":
            # Not a library refusal: a bug (the input and the exception are in the log).
            cause = exc.__cause__ if isinstance(exc, ApiError) and exc.__cause__ is not None else exc
            log.error("numerical failure on %s %s: %s: %s", request.method, request.url.path,
                      type(cause).__name__, cause, exc_info=cause)
        return error_response(err.status_code, err.body, err.headers)

    async def _http(request: Request, exc: Exception) -> JSONResponse:
        assert isinstance(exc, StarletteHTTPException)
        if exc.status_code == 400:
            # FastAPI's "error parsing the body" (nesting too deep, integer too long...): a schema violation.
            return error_response(422, {"code": "validation_error", "message": f"body: {exc.detail}",
                                        "field": "body",
                                        "errors": [{"field": "body", "message": str(exc.detail),
                                                    "type": "body_parse_error"}]})
        codes = {404: "not_found", 405: "method_not_allowed", 401: "unauthorized", 413: "body_too_large"}
        code = codes.get(exc.status_code, "http_error")
        headers = dict(exc.headers) if exc.headers else None
        if exc.status_code == 405:
            # Every method of the path, not just those of the first route routing found.
            allow = allowed_methods(request.app.router.routes, request.scope)
            headers = {**(headers or {}), "Allow": ", ".join(allow)}
        return error_response(exc.status_code, {"code": code, "message": str(exc.detail)}, headers)

    async def _other(request: Request, exc: Exception) -> JSONResponse:
        log.error("unexpected error on %s %s", request.method, request.url.path, exc_info=exc)
        _record_failure(request, "internal_error")
        return error_response(500, {"code": "internal_error",
                                    "message": f"unexpected server error ({type(exc).__name__})"})

    app.add_exception_handler(RequestValidationError, _validation)
    for cls in ANSWERED:
        app.add_exception_handler(cls, _answered)
    app.add_exception_handler(StarletteHTTPException, _http)
    app.add_exception_handler(Exception, _other)


#: The body of a request the server's shutdown cut.
SHUTTING_DOWN = {"code": "shutting_down",
                 "message": "the server is shutting down and stopped this request before it was answered; send it "
                            "again (to this server once it is back, or to another)"}


class ShutdownAnswerMiddleware:
    """Pure ASGI middleware: a request cut by the server's shutdown is answered 503 ``shutting_down`` with
    ``Retry-After``, in the service's error shape.

    At SIGTERM uvicorn gives the requests in flight ``TENSEGRITY_SHUTDOWN_TIMEOUT`` seconds, then cancels their
    tasks (which interrupts their solves). A cancelled request that has not started its answer gets this one
    instead of uvicorn's plain-text 500; the connection is closed after it. One started already is cut as before.
    """

    def __init__(self, app: ASGIApp, retry_after: int = 1) -> None:
        self.app = app
        self.retry_after = retry_after

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        started = False

        async def send_wrapper(message: Message) -> None:
            nonlocal started
            if message["type"] == "http.response.start":
                started = True
            await send(message)

        try:
            await self.app(scope, receive, send_wrapper)
        except asyncio.CancelledError:
            if started:
                raise
            log.warning("%s %s stopped by the server's shutdown: answered 503 shutting_down", scope.get("method"),
                        scope.get("path"))
            app = scope.get("app")
            metrics = getattr(getattr(app, "state", None), "metrics", None)
            if metrics is not None:
                metrics.failure(SHUTTING_DOWN["code"])
            response = error_response(503, dict(SHUTTING_DOWN), {"Retry-After": str(self.retry_after),
                                                                  "Connection": "close"})
            # answered, not re-raised: the task ends with this answer sent (uvicorn is closing the connection)
            await response(scope, receive, send)
