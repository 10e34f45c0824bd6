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
* **bounded heads** (``TENSEGRITY_MAX_HEADER_BYTES``, ``TENSEGRITY_MAX_HEADERS``): the request line and headers of a
  request may take at most ``max_header_bytes`` bytes and ``max_headers`` header fields; beyond, ``431``
  ``headers_too_large`` and the socket is closed. httptools sets no limit of its own and keeps an unfinished
  header in memory (20 connections sending 16 MB of unfinished headers: +340 MB), so the bytes of a head still
  open are counted as they arrive (to within one read of the socket, at most 256 KiB) and those of finished
  fields exactly.

uvicorn's own ``limit_concurrency`` (503 beyond ``TENSEGRITY_LIMIT_CONCURRENCY`` requests and
connections) and ``timeout_keep_alive`` (``TENSEGRITY_KEEP_ALIVE``) are set by ``tensegrity-opt serve``
too. A production deployment still puts a reverse proxy in front (see the README).
"""

from __future__ import annotations

import asyncio
from typing import Any

from .errors import raw_error_response

__all__ = ["protocol_class", "uvicorn_options", "HeadTooLarge"]

_TIMEOUT_RESPONSE = raw_error_response(408, {"code": "request_timeout",
                                             "message": "the request was not received in time"})


#: Seconds a connection whose head was refused (431) is still read (and what arrives dropped) before it is closed.
LINGER_SECONDS = 2.0


class HeadTooLarge(Exception):
    """A request's head over the server's limits (raised in a parser callback; answered 431)."""

    def __init__(self, message: str, details: dict[str, int]) -> None:
        super().__init__(message)
        self.message = message
        self.details = details


def protocol_class(request_timeout: float, max_connections: int, max_header_bytes: int = 65536,
                   max_headers: int = 100) -> type[asyncio.Protocol] | None:
    """uvicorn's httptools protocol with the request timeout, the connection cap and the bounds of a request's
    head (``None`` without httptools: uvicorn's default protocol, with ``limit_concurrency``, keep-alive and
    h11's own bound on a head, ``h11_max_incomplete_event_size``)."""
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

    def too_large(what: str) -> HeadTooLarge:
        return HeadTooLarge(f"the request's {what}: this server accepts at most {max_header_bytes} bytes of "
                            f"request line and headers and {max_headers} header fields",
                            {"max_header_bytes": max_header_bytes, "max_headers": max_headers})

    class BoundedHttpToolsProtocol(HttpToolsProtocol):
        #: bytes of the head in progress (None: no head in progress: a body, or an upgraded connection)
        _head: int | None = 0
        #: header fields of the head in progress
        _fields = 0
        #: why the head was refused (set by a parser callback; answered 431 instead of uvicorn's 400)
        _refused: HeadTooLarge | None = None
        #: refused: what the client still sends is dropped until the socket closes
        _lingering = False
        #: a refused head whose 431 waits for the answers to the requests before it on the connection
        _deferred: HeadTooLarge | None = None

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

        def data_received(self, data: bytes) -> None:
            if self._lingering:
                return                                  # refused: dropped until the socket closes
            head = self._head
            if head is None or head + len(data) <= max_header_bytes:
                if head is not None:
                    self._head = head + len(data)       # settled when the head ends (on_headers_complete)
                super().data_received(data)
                return
            # more than the head in progress may still take: feed what it may, then refuse it if still open
            room = max_header_bytes - head
            self._head = max_header_bytes
            super().data_received(data[:room])
            if self.transport.is_closing() or self.transport.get_protocol() is not self:
                return                                  # refused, closed or upgraded meanwhile
            if self._head == max_header_bytes:          # that head did not end (the next one would start at 0)
                self._refuse_head(too_large(f"head is over {max_header_bytes} bytes"))
                return
            self.data_received(data[room:])

        def on_message_begin(self) -> None:
            super().on_message_begin()
            self._fields = 0
            if self not in incomplete:
                self._begin()

        def on_url(self, url: bytes) -> None:
            super().on_url(url)
            if len(self.url) > max_header_bytes:
                self._refuse_in_parser(f"target is over {max_header_bytes} bytes")

        def on_header(self, name: bytes, value: bytes) -> None:
            self._fields += 1
            if self._fields > max_headers:
                self._refuse_in_parser(f"head has more than {max_headers} header fields")
            if len(name) + len(value) > max_header_bytes:
                self._refuse_in_parser(f"header field {name[:64].decode('latin-1')!r} is over {max_header_bytes} "
                                       "bytes")
            super().on_header(name, value)

        def on_headers_complete(self) -> None:
            self._head = None
            super().on_headers_complete()

        def on_message_complete(self) -> None:
            self._forget()
            self._head = 0                          # the next request's head may follow
            super().on_message_complete()

        def on_response_complete(self) -> None:
            super().on_response_complete()
            if self._deferred is not None:  # a refused head waits for the answers to the requests before it
                if not self.pipeline and not self.transport.is_closing():
                    refused, self._deferred = self._deferred, None
                    self._answer_431(refused)
                return
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
            # application sees it, in plain text: here in the service's JSON error shape; a head over the limits
            # (a parser callback raised HeadTooLarge) gets its 431
            if self._refused is not None:
                self._refuse_head(self._refused)
                return
            self.transport.write(raw_error_response(400, {"code": "bad_request",
                                                          "message": f"malformed HTTP request: {msg}"}))
            self.transport.close()

        def _refuse_in_parser(self, what: str) -> None:
            """Stop the parser (it raises its own error, which uvicorn answers with send_400_response): 431."""
            self._refused = too_large(what)
            raise self._refused

        def _refuse_head(self, exc: HeadTooLarge) -> None:
            """431 (after the answers of the requests before it on this connection, if any are still due)."""
            self._forget()
            self._head = None
            self._lingering = True
            if (self.cycle is not None and not self.cycle.response_complete) or self.pipeline:
                self._deferred = exc
                return
            self._answer_431(exc)

        def _answer_431(self, exc: HeadTooLarge) -> None:
            """431, then a lingering close: the answer is sent with the end of the server's side, what the client
            still sends is read and dropped for at most LINGER_SECONDS (closing a socket with unread data resets
            the connection, and the client would lose the answer), then the socket is closed."""
            self._forget()
            self.transport.write(raw_error_response(431, {"code": "headers_too_large", "message": exc.message,
                                                          "details": exc.details}))
            try:
                self.transport.write_eof()
            except (NotImplementedError, RuntimeError, OSError):
                self.transport.close()
                return
            self.loop.call_later(LINGER_SECONDS, self.transport.close)

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
                            "ws_max_size": settings.max_body_bytes, "ws_per_message_deflate": False,
                            # the bound of a head when uvicorn runs h11 (no httptools); the protocol below bounds
                            # it for httptools
                            "h11_max_incomplete_event_size": settings.max_header_bytes}
    proto = protocol_class(settings.request_timeout, settings.connection_cap, settings.max_header_bytes,
                           settings.max_headers)
    if proto is not None:
        opts["http"] = proto
    return opts
