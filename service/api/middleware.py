"""Pure ASGI middleware: the request body size limit (413); HEAD and OPTIONS on every path."""

from __future__ import annotations

import json
from collections.abc import Iterable, Iterator
from typing import Any

from starlette._utils import get_route_path
from starlette.types import ASGIApp, Message, Receive, Scope, Send

__all__ = ["BodyLimitMiddleware", "MethodsMiddleware", "allowed_methods"]


def _flat(routes: Iterable[Any]) -> Iterator[Any]:
    """The routes, with those of included routers (FastAPI's ``effective_candidates``) in place."""
    for route in routes:
        nested = getattr(route, "effective_candidates", None)
        if callable(nested):
            yield from _flat(nested())
        else:
            yield route


def allowed_methods(routes: Iterable[Any], scope: Scope) -> list[str]:
    """Every method some route answers at ``scope``'s path (HEAD with GET, OPTIONS with any), sorted;
    empty when no route has this path. Routing itself only knows the first route of a path, so its
    405 would list one method (``OPTIONS /v1/jobs`` -> ``Allow: POST``)."""
    methods: set[str] = set()
    path = get_route_path(scope)
    for route in _flat(routes):
        own = getattr(route, "methods", None)
        regex = getattr(route, "path_regex", None)
        if own and regex is not None and regex.match(path):
            methods |= set(own)
    if "GET" in methods:
        methods.add("HEAD")
    if methods:
        methods.add("OPTIONS")
    return sorted(methods)


class MethodsMiddleware:
    """``HEAD`` answers what ``GET`` would, without the body; ``OPTIONS`` answers 204 with ``Allow``.

    ``routes()`` gives the application's routes (read when needed: the app may add routes after
    this middleware is built). Nothing is computed for other methods (the common path costs a
    string comparison); a CORS preflight is answered by the CORS middleware outside this one.
    """

    def __init__(self, app: ASGIApp, routes: Any) -> None:
        self.app = app
        self.routes = routes

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        method = scope["method"]
        if method == "HEAD":
            async def send_head(message: Message) -> None:
                if message["type"] == "http.response.body":
                    if message.get("more_body", False):
                        return
                    message = {"type": "http.response.body", "body": b"", "more_body": False}
                await send(message)

            await self.app({**scope, "method": "GET"}, receive, send_head)
            return
        if method == "OPTIONS":
            allow = allowed_methods(self.routes(), scope)
            if allow:
                await send({"type": "http.response.start", "status": 204,
                            "headers": [(b"allow", ", ".join(allow).encode())]})
                await send({"type": "http.response.body", "body": b""})
                return
        await self.app(scope, receive, send)


class BodyLimitMiddleware:
    """Refuse request bodies over ``max_bytes`` with 413 before the app reads them.

    A ``Content-Length`` over the limit is refused at once; otherwise the body is read (at most
    ``max_bytes`` plus one chunk) and replayed to the app, so chunked uploads are bounded too.
    """

    def __init__(self, app: ASGIApp, max_bytes: int) -> None:
        self.app = app
        self.max_bytes = max_bytes

    async def _refuse(self, send: Send, size: int | None) -> None:
        what = f"{size} bytes" if size is not None else "more"
        body = json.dumps({"code": "body_too_large",
                           "message": f"request body of {what} exceeds the limit of {self.max_bytes} bytes",
                           "details": {"max_body_bytes": self.max_bytes}}).encode()
        await send({"type": "http.response.start", "status": 413,
                    "headers": [(b"content-type", b"application/json"), (b"content-length", str(len(body)).encode()),
                                (b"connection", b"close")]})
        await send({"type": "http.response.body", "body": body})

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        length = None
        for name, value in scope.get("headers", ()):
            if name == b"content-length":
                try:
                    length = int(value)
                except ValueError:
                    length = None
                break
        if length is not None and length > self.max_bytes:
            await self._refuse(send, length)
            return
        chunks: list[bytes] = []
        size = 0
        more = True
        first: Message | None = None
        while more:
            message = await receive()
            if message["type"] != "http.request":
                first = message         # disconnect: hand it on
                break
            chunk = message.get("body", b"")
            size += len(chunk)
            if size > self.max_bytes:
                await self._refuse(send, None if length is None else size)
                return
            chunks.append(chunk)
            more = bool(message.get("more_body", False))
        body = b"".join(chunks)
        replayed = False

        async def replay() -> Message:
            nonlocal replayed
            if not replayed:
                replayed = True
                if first is not None:
                    return first
                return {"type": "http.request", "body": body, "more_body": False}
            return await receive()

        await self.app(scope, replay, send)
