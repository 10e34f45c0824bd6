"""JSON request bodies and stream messages: decoded once, a key given twice in one object refused.

JSON leaves duplicate keys to the reader and Python's ``json`` (like pydantic's parser) keeps the last:
``{"n": 4, "n": 200}`` would be read as ``n = 200`` while a proxy, a log or a cache that keeps the first saw
``n = 4``. Every JSON body of the API is decoded here instead (:class:`JSONBodyRoute`, the route class of every
router): a key twice in one object is a 422 ``validation_error`` whose field is the key's path
(``manipulator.n``), type ``duplicate_key``. The decoded body is handed on to FastAPI, which does not decode it
again. Stream messages are checked by :func:`duplicate_key_error` before their validation.
"""

from __future__ import annotations

import json
from collections import deque
from collections.abc import Callable, Coroutine
from typing import Any

from fastapi.exceptions import RequestValidationError
from fastapi.routing import APIRoute
from starlette.requests import Request
from starlette.responses import Response

__all__ = ["DuplicateKey", "loads", "duplicate_key_error", "JSONBodyRoute", "is_json"]


class DuplicateKey(ValueError):
    """A key given twice in one JSON object: ``path`` (keys and list indices) leads to the object."""

    def __init__(self, key: str, path: tuple[str | int, ...] = ()) -> None:
        super().__init__(f"duplicate key {key!r}")
        self.key = key
        self.path = path

    def error(self) -> dict[str, Any]:
        """The error in pydantic's form (``loc`` under ``body``), as the validation handlers read it."""
        return {"type": "duplicate_key", "loc": ("body", *self.path, self.key), "input": None,
                "msg": f"the key {self.key!r} is given more than once in one object; give each key once"}


def _unique(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    out = dict(pairs)
    if len(out) != len(pairs):
        seen: set[str] = set()
        for key, _ in pairs:
            if key in seen:
                raise DuplicateKey(key)
            seen.add(key)
    return out


class _Pairs(list):
    """An object's pairs as given (duplicates kept): only to find where a duplicate is."""


def _where(text: str | bytes) -> DuplicateKey:
    """The first duplicate key of ``text`` with its path (decoded again, only when one was found)."""
    todo: deque[tuple[tuple[str | int, ...], Any]] = deque([((), json.loads(text, object_pairs_hook=_Pairs))])
    while todo:
        path, value = todo.popleft()
        if isinstance(value, _Pairs):
            seen: set[str] = set()
            for key, item in value:
                if key in seen:
                    return DuplicateKey(key, path)
                seen.add(key)
            todo.extend((path + (key,), item) for key, item in value)
        elif isinstance(value, list):
            todo.extend((path + (i,), item) for i, item in enumerate(value))
    return DuplicateKey("?")  # pragma: no cover - only called when the strict decoding found one


def loads(text: str | bytes) -> Any:
    """``json.loads`` refusing a key given twice in one object (:class:`DuplicateKey`, with its path)."""
    try:
        return json.loads(text, object_pairs_hook=_unique)
    except DuplicateKey:
        raise _where(text) from None


def duplicate_key_error(text: str | bytes) -> dict[str, Any] | None:
    """The error of a stream message with a key twice in one object (pydantic's form), else ``None`` (also for
    a message that is not JSON: its validation says so)."""
    try:
        loads(text)
    except DuplicateKey as exc:
        return exc.error()
    except (ValueError, RecursionError):
        return None
    return None


def is_json(content_type: str | None) -> bool:
    """The media types FastAPI decodes as JSON: ``application/json`` or ``application/*+json`` (a body without a
    ``Content-Type`` is not decoded: FastAPI's strict content type refuses it)."""
    if not content_type:
        return False
    media = content_type.split(";", 1)[0].strip().lower()
    return media == "application/json" or (media.startswith("application/") and media.endswith("+json"))


class JSONBodyRoute(APIRoute):
    """A route whose JSON body is decoded by :func:`loads` (a duplicate key: 422 naming it) before FastAPI reads
    it. A body that is not JSON is left to FastAPI's own refusal."""

    def get_route_handler(self) -> Callable[[Request], Coroutine[Any, Any, Response]]:
        handler = super().get_route_handler()
        if self.body_field is None:
            return handler

        async def decode_then_handle(request: Request) -> Response:
            if is_json(request.headers.get("content-type")):
                body = await request.body()
                if body:
                    try:
                        request._json = loads(body)     # Request.json() returns it: no second decoding
                    except DuplicateKey as exc:
                        raise RequestValidationError([exc.error()], body=None) from None
                    except (ValueError, RecursionError):
                        pass                            # not JSON: FastAPI's own refusal says so
            return await handler(request)

        return decode_then_handle
