"""The control stream: ``/v1/control/stream``, a WebSocket for control loops (``docs/stream.md``).

One connection is one chain in one mode: the client's first message ``open``s it (``track``,
``preloads`` or ``inverse``), every later message is a ``step`` answered in order by a ``result``
(the library's answer, computed from the state the previous step left) or an ``error`` (the REST API's
codes and fields: ``validation_error`` with the field paths, the library's refusals, ``timeout``). A
bad message never closes the connection; a refused ``open`` does (1008), as do a server without a
free stream slot (1013), a missing or wrong API key (4401) and silence (1001). A handshake from a web page of another
origin (its ``Origin`` neither the server's own nor one of ``TENSEGRITY_CORS_ORIGINS``) is refused before the upgrade:
HTTP 403 ``forbidden_origin``.

Each stream holds one solver thread for its lifetime (:class:`service.execution.slots.StreamSlots`): its
steps run there under the server's solve time limit, never on the event loop, so one slow stream
never holds up another or the REST requests.
"""

from __future__ import annotations

import asyncio
import logging
from typing import Any

from fastapi import APIRouter, WebSocket
from pydantic import ValidationError
from starlette.responses import JSONResponse
from starlette.websockets import WebSocketDisconnect

from ... import schemas as s
from ...adapters.fields import STREAM_ALIASES, FieldContext
from ...config import Settings
from ...execution.threads import ThreadExecutor
from ...responses import render_json
from ...sessions import Session, open_session, step_task
from ..deps import api_key_valid, check_manipulator, origin_allowed
from ..errors import ServiceError, error_body, error_response, validation_body
from ..json_bodies import duplicate_key_error

__all__ = ["router", "CLOSE_NORMAL", "CLOSE_IDLE", "CLOSE_POLICY", "CLOSE_TRY_LATER", "CLOSE_UNAUTHORIZED",
           "PATH"]

log = logging.getLogger("service.stream")

router = APIRouter(prefix="/v1", tags=["stream"])

PATH = "/v1/control/stream"
#: Close codes (RFC 6455; 4401 is this application's: the WebSocket form of HTTP 401).
CLOSE_NORMAL = 1000         # the server is done (the client closes normally)
CLOSE_IDLE = 1001           # "going away": nothing received for stream_idle_timeout seconds
CLOSE_POLICY = 1008         # "policy violation": the open was refused (schema, limits, the library)
CLOSE_TRY_LATER = 1013      # "try again later": every stream slot is taken, or the open ran out of time
CLOSE_UNAUTHORIZED = 4401   # missing or wrong API key (servers with API keys only)

#: Error codes that close a refused open with CLOSE_TRY_LATER (capacity or time, not the message).
_LATER = frozenset({"timeout", "overloaded"})


class _Stream:
    """One connection's protocol state: the message count, the session once open."""

    __slots__ = ("ws", "settings", "slot", "metrics", "seq", "session", "step_model", "ctx")

    def __init__(self, ws: WebSocket, settings: Settings, slot: ThreadExecutor | None, metrics: Any) -> None:
        self.ws = ws
        self.settings = settings
        self.slot = slot
        self.metrics = metrics
        self.seq = -1                      # the open is message 0
        self.session: Session | None = None
        self.step_model: Any = None
        self.ctx = FieldContext()

    # ------------------------------------------------------------------ answers
    async def send_error(self, body: dict[str, Any], seq: int | None) -> None:
        if self.metrics is not None:
            self.metrics.failure(body["code"])
        code, message, field = body.pop("code"), body.pop("message"), body.pop("field", None)
        await self.ws.send_text(render_json({"type": "error", "seq": seq, "code": code, "message": message,
                                             "field": field, **body}).decode())

    async def send_exception(self, exc: BaseException, seq: int | None) -> str:
        """The error message of an exception (the REST mapping; a server bug: ``internal_error``); its code."""
        body = error_body(exc, self.ctx)
        if body is None or body["code"] == "numerical_failure":
            log.error("stream %s: %s: %s", "step" if self.session is not None else "open", type(exc).__name__, exc,
                      exc_info=exc)
            if body is None:
                body = {"code": "internal_error", "message": f"unexpected server error ({type(exc).__name__})"}
        code = body["code"]
        await self.send_error(body, seq)
        return code

    async def send_protocol_error(self, code: str, message: str, seq: int | None, field: str | None = None) -> None:
        await self.send_error({"code": code, "message": message, "field": field}, seq)

    # ------------------------------------------------------------------ messages
    async def handle(self, data: str | bytes) -> tuple[int, str] | None:
        """Answer one client message; the close code and reason when the connection must end."""
        self.seq += 1
        seq = self.seq
        duplicate = duplicate_key_error(data)
        if duplicate is not None:               # a key twice: refused as in a REST body (an open: closed)
            await self.send_error(validation_body([duplicate]), seq)
            return None if self.session is not None else (CLOSE_POLICY, "open refused: validation_error")
        if self.session is not None:
            try:
                msg = self.step_model.model_validate_json(data)
            except ValidationError as exc:
                await self._refused_step(data, exc, seq)
                return None
            try:
                assert self.slot is not None
                text = await self.slot.run(step_task, self.session, msg, seq, timeout=self.settings.solve_timeout)
            except Exception as exc:    # noqa: BLE001 - every failure is answered; the stream goes on
                await self.send_exception(exc, seq)
                return None
            await self.ws.send_text(text.decode())
            return None
        try:
            env = s.Envelope.model_validate_json(data)
        except ValidationError as exc:
            await self.send_error(validation_body(list(exc.errors())), seq)
            return None
        if env.type == "step":
            await self.send_protocol_error("not_open", "the first message must be an open: "
                                           '{"type": "open", "manipulator": {...}, "mode": "track" | "preloads" | '
                                           '"inverse", ...}', seq, "type")
            return None
        return await self._open(data, seq)

    async def _refused_step(self, data: str | bytes, exc: ValidationError, seq: int) -> None:
        """A message the step model refused: not JSON or no known type (the envelope says), a second
        open, or a bad step (its own errors)."""
        try:
            env = s.Envelope.model_validate_json(data)
        except ValidationError as env_exc:
            await self.send_error(validation_body(list(env_exc.errors())), seq)
            return
        if env.type == "open":
            await self.send_protocol_error(
                "already_open", f"this stream is open (mode {self.session.mode if self.session else '?'}); "
                "open another connection for another chain or mode", seq, "type")
            return
        await self.send_error(validation_body(list(exc.errors())), seq)

    async def _open(self, data: str | bytes, seq: int) -> tuple[int, str] | None:
        try:
            mode = s.OpenEnvelope.model_validate_json(data).mode
            req = s.OPEN_MODELS[mode].model_validate_json(data)
        except ValidationError as exc:
            await self.send_error(validation_body(list(exc.errors())), seq)
            return CLOSE_POLICY, "open refused: validation_error"
        try:
            self.ctx = check_manipulator(req.manipulator, self.settings)
            self.ctx = FieldContext(manipulator=self.ctx.manipulator, aliases=STREAM_ALIASES)
            assert self.slot is not None
            session, fields = await self.slot.run(open_session, req, timeout=self.settings.solve_timeout)
        except Exception as exc:        # noqa: BLE001 - answered, then the connection is closed
            code = await self.send_exception(exc, seq)
            return (CLOSE_TRY_LATER if code in _LATER else CLOSE_POLICY), f"open refused: {code}"[:120]
        self.session = session
        self.step_model = s.STEP_MODELS[mode]
        await self.ws.send_text(render_json({
            "type": "opened", "seq": seq, "mode": mode, **fields,
            "step_timeout": self.settings.solve_timeout,
            "idle_timeout": self.settings.stream_idle_timeout}).decode())
        return None


def _api_key(ws: WebSocket) -> str | None:
    return ws.headers.get("x-api-key") or ws.query_params.get("api_key")


async def _close(ws: WebSocket, code: int, reason: str) -> None:
    try:
        await ws.close(code, reason)
    except (WebSocketDisconnect, RuntimeError, OSError):
        pass                                # the client is gone already


async def _refuse_origin(ws: WebSocket, origin: str, metrics: Any) -> None:
    """Refuse the handshake before the upgrade: 403 ``forbidden_origin`` (an HTTP answer, in the error shape)."""
    exc = ServiceError(403, "forbidden_origin",
                       f"a control stream from the origin {origin[:200]!r} is refused: this server accepts its own "
                       "origin, those of TENSEGRITY_CORS_ORIGINS and clients that send no Origin", field="Origin")
    if metrics is not None:
        metrics.failure(exc.code)
    body = error_body(exc)
    assert body is not None
    try:
        await ws.send_denial_response(error_response(exc.status_code, body))
    except RuntimeError:                    # a server without the denial extension: its own 403
        await ws.close(CLOSE_POLICY)


@router.websocket(PATH.removeprefix("/v1"), name="control_stream")
async def control_stream(websocket: WebSocket) -> None:
    app = websocket.app
    settings: Settings = app.state.settings
    metrics = getattr(app.state, "metrics", None)
    origin = websocket.headers.get("origin")
    if not origin_allowed(origin, websocket.headers.get("host"), settings):
        assert origin is not None
        await _refuse_origin(websocket, origin, metrics)
        return
    await websocket.accept()
    # the connection as one stream: auth, a slot, then messages until the client closes or goes silent
    refusal = _Stream(websocket, settings, None, metrics)     # answers only (no slot)
    try:
        if settings.api_keys and not api_key_valid(_api_key(websocket), settings):
            key = _api_key(websocket)
            await refusal.send_protocol_error(
                "unauthorized", "missing API key: send the X-API-Key header or the api_key query parameter"
                if not key else "invalid API key", None, "X-API-Key")
            await _close(websocket, CLOSE_UNAUTHORIZED, "unauthorized")
            return
        slots = app.state.executors.streams
        slot = slots.acquire()
        if slot is None:
            await refusal.send_protocol_error(
                "overloaded", f"this server has {slots.size} control streams open (TENSEGRITY_MAX_STREAM_CONNECTIONS); "
                "try again later", None)
            await _close(websocket, CLOSE_TRY_LATER, "too many streams: try again later")
            return
    except WebSocketDisconnect:
        return
    try:
        await _serve(_Stream(websocket, settings, slot, metrics))
    except WebSocketDisconnect:
        pass                                # the client went away (closed, or its socket did)
    finally:
        slots.release(slot)


async def _serve(st: _Stream) -> None:
    ws, idle = st.ws, st.settings.stream_idle_timeout
    while True:
        try:
            async with asyncio.timeout(idle):
                message = await ws.receive()
        except TimeoutError:
            await st.send_protocol_error("idle_timeout", f"nothing received for {idle:g} s "
                                         "(TENSEGRITY_STREAM_IDLE_TIMEOUT): closing", None)
            await _close(ws, CLOSE_IDLE, f"idle for {idle:g} s")
            return
        if message["type"] == "websocket.disconnect":
            return
        data = message.get("text")
        if data is None:
            data = message.get("bytes") or b""
        close = await st.handle(data)
        if close is not None:
            await _close(ws, *close)
            return


@router.get(PATH.removeprefix("/v1"), include_in_schema=False)
async def control_stream_http() -> JSONResponse:
    """A plain HTTP request to the stream's path: 426, with how to connect."""
    return JSONResponse(status_code=426, headers={"Upgrade": "websocket"}, content={
        "code": "upgrade_required", "message": f"{PATH} is a WebSocket: connect with ws:// (or wss://) and "
                                               "send an open message (docs/stream.md)"})
