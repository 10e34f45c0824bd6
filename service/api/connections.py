"""Slow and idle clients: uvicorn's HTTP protocol with a request timeout and a connection cap.

uvicorn (0.54) times out only *idle keep-alive* connections, and only after a first response:
a client that opens a connection and sends half a request (or nothing, or a trickle of bytes)
holds its socket for ever (3000 such sockets: 3000 descriptors; with a 256-descriptor limit every
new ``/healthz`` fails). :func:`protocol_class` returns uvicorn's httptools protocol with

* **a request timeout** (``TENSEGRITY_REQUEST_TIMEOUT``): from the connection (or the first byte
  of the next request on a kept-alive connection) to the last byte of the request, headers and
  body. A request still incomplete then gets ``408`` (headers incomplete: nothing reached the app)
  or is cut (body incomplete: the app sees the client disconnect), and the socket is closed.
* **a connection cap** (``TENSEGRITY_MAX_CONNECTIONS``): when a new connection would exceed it,
  the oldest connection that has no request in progress (half-sent, or idle between requests) is
  closed to make room; when every connection has a request in progress the new one is closed.
  So half-open sockets cannot lock out new clients: ``/healthz`` still answers.

* **WebSockets** (``/v1/control/stream``): an upgraded connection leaves the request timeout and is
  never the one closed to make room (the stream has its own idle timeout and bound); it still counts
  towards the cap.
* **JSON 400s**: a request uvicorn cannot parse (request line, headers, ``Content-Length``) is
  refused in the service's error shape (``{"code": "bad_request", "message"}``), not uvicorn's
  plain text.

uvicorn's own ``limit_concurrency`` (503 beyond ``TENSEGRITY_LIMIT_CONCURRENCY`` requests and
connections) and ``timeout_keep_alive`` (``TENSEGRITY_KEEP_ALIVE``) are set by ``tensegrity-opt serve``
too. A production deployment still puts a reverse proxy in front (see the README).
"""

from __future__ import annotations

import asyncio
import json
from typing import Any

__all__ = ["protocol_class", "uvicorn_options"]

_TIMEOUT_BODY = b'{"code":"request_timeout","message":"the request was not received in time"}'
_TIMEOUT_RESPONSE = (b"HTTP/1.1 408 Request Timeout\r\ncontent-type: application/json\r\nconnection: close\r\n"
                     b"content-length: " + str(len(_TIMEOUT_BODY)).encode() + b"\r\n\r\n" + _TIMEOUT_BODY)


def protocol_class(request_timeout: float, max_connections: int) -> type[asyncio.Protocol] | None:
    """uvicorn's httptools protocol with the request timeout and the connection cap (``None``
    without httptools: uvicorn's default protocol, with ``limit_concurrency`` and keep-alive only)."""
    try:
        from uvicorn.protocols.http.httptools_impl import HttpToolsProtocol
    except ImportError:  # pragma: no cover - httptools is a dependency of uvicorn[standard]
        return None

    #: connections without a request in progress, oldest first (per server process)
    waiting: dict[Any, None] = {}
    #: connections whose request is incomplete -> loop time it began; oldest first (insertion order)
    incomplete: dict[Any, float] = {}
    sweeper: list[asyncio.TimerHandle | None] = [None]
    interval = max(0.05, min(0.5, request_timeout / 10))

    def sweep(loop: asyncio.AbstractEventLoop) -> None:
        # One timer per server instead of one per request (~5 us each): every ``interval`` the
        # connections whose request began more than ``request_timeout`` ago are timed out.
        limit = loop.time() - request_timeout
        while incomplete:
            proto, began = next(iter(incomplete.items()))
            if began > limit:
                break
            del incomplete[proto]
            proto._request_timed_out()
        sweeper[0] = loop.call_later(interval, sweep, loop) if incomplete else None

    class BoundedHttpToolsProtocol(HttpToolsProtocol):
        def connection_made(self, transport: asyncio.Transport) -> None:  # type: ignore[override]
            super().connection_made(transport)
            if len(self.connections) > max_connections:
                victim = next(iter(waiting), None)
                if victim is None:          # every connection has a request in progress
                    transport.close()
                    return
                victim._close_waiting()
            waiting[self] = None
            self._begin()                   # the first request must arrive within the timeout

        def connection_lost(self, exc: Exception | None) -> None:
            self._forget()
            super().connection_lost(exc)

        def handle_websocket_upgrade(self) -> None:
            # a WebSocket from here on (/v1/control/stream, which has its own idle timeout and connection
            # bound): no request timeout, and never closed to make room for a new connection
            self._forget()
            super().handle_websocket_upgrade()

        def on_message_begin(self) -> None:
            super().on_message_begin()
            if self not in incomplete:
                self._begin()

        def on_message_complete(self) -> None:
            self._forget()
            super().on_message_complete()

        def on_response_complete(self) -> None:
            super().on_response_complete()
            if not self.transport.is_closing():
                waiting[self] = None        # idle between requests: may make room (keep-alive timer runs)

        # -------------------------------------------------------------- helpers
        def _forget(self) -> None:
            """Out of both tables: its request is in the app's hands, or the connection is gone or upgraded."""
            waiting.pop(self, None)
            incomplete.pop(self, None)

        def _begin(self) -> None:
            incomplete[self] = self.loop.time()
            if sweeper[0] is None:
                sweeper[0] = self.loop.call_later(interval, sweep, self.loop)

        def _request_timed_out(self) -> None:
            if self.transport.is_closing():
                return
            if self.cycle is None or self.cycle.response_complete:
                self.transport.write(_TIMEOUT_RESPONSE)     # nothing reached the app: tell the client
            self.transport.close()

        def send_400_response(self, msg: str) -> None:
            # uvicorn answers an unparsable request line or header, or a bad Content-Length, before the
            # application sees it, in plain text: here in the service's JSON error shape
            body = json.dumps({"code": "bad_request", "message": f"malformed HTTP request: {msg}"}).encode()
            self.transport.write(b"HTTP/1.1 400 Bad Request\r\ncontent-type: application/json\r\n"
                                 b"connection: close\r\ncontent-length: " + str(len(body)).encode() + b"\r\n\r\n"
                                 + body)
            self.transport.close()

        def _close_waiting(self) -> None:
            self._forget()
            if not self.transport.is_closing():
                self.transport.close()

    return BoundedHttpToolsProtocol


def uvicorn_options(settings: Any) -> dict[str, Any]:
    """The keyword arguments of ``uvicorn.run`` for the connection limits of ``settings``."""
    opts: dict[str, Any] = {"timeout_keep_alive": settings.keep_alive, "backlog": settings.backlog,
                            "limit_concurrency": settings.concurrency_cap,
                            # WebSocket messages (the control stream): bounded like request bodies (a larger
                            # one closes the stream with 1009), and not compressed: a stream's messages are
                            # a few hundred bytes and its point is latency
                            "ws_max_size": settings.max_body_bytes, "ws_per_message_deflate": False}
    proto = protocol_class(settings.request_timeout, settings.connection_cap)
    if proto is not None:
        opts["http"] = proto
    return opts
