"""JSON bodies: the one renderer of every JSON answer, and the response class that uses it.

Solver results are rendered where they were computed, in the solver thread or the solver process,
by :func:`render_task` (:func:`render_json_bounded`; never on the event loop): piece by piece, so the GIL
changes hands between pieces and the loop keeps answering (one ``json.dumps`` of a 40 MB body holds it
~0.5 s), and counted as it goes, so a body over the server's ``max_response_bytes`` is refused
(:class:`ResponseTooLarge`) as soon as the limit is crossed instead of after the whole body is built.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from typing import Any

import numpy as np
from starlette.responses import JSONResponse

__all__ = ["render_json", "render_json_bounded", "render_task", "json_ready", "JSONBody", "json_safe",
           "SafeJSONResponse", "ResponseTooLarge"]


class ResponseTooLarge(ValueError):
    """The answer would exceed the server's response size limit (``max_response_bytes``)."""

    def __init__(self, limit: int, field: str | None = None, estimate: int | None = None) -> None:
        what = f"would be about {estimate} bytes, over" if estimate is not None else "exceeds"
        super().__init__(f"the answer {what} this server's response size limit of {limit} bytes "
                         "(TENSEGRITY_MAX_RESPONSE_BYTES)" + (f": ask for less ({field})" if field else ""))
        self.limit = limit
        self.field = field
        self.estimate = estimate


def _default(x: Any) -> Any:
    """numpy scalars and arrays as the JSON numbers and lists they are."""
    if isinstance(x, np.generic):
        return x.item()
    if isinstance(x, np.ndarray):
        return x.tolist()
    raise TypeError(f"{type(x).__name__} is not JSON serializable")


def json_safe(x: Any) -> Any:
    """``x`` with every NaN or infinite float (in nested dicts, lists, tuples) replaced by ``None``."""
    if isinstance(x, float):
        return x if math.isfinite(x) else None
    if isinstance(x, dict):
        return {k: json_safe(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [json_safe(v) for v in x]
    return x


_ENCODER = json.JSONEncoder(ensure_ascii=False, allow_nan=False, separators=(",", ":"), default=_default)


def render_json(content: Any) -> bytes:
    """Compact UTF-8 JSON that is always valid: a NaN or infinity that slipped through becomes ``null``."""
    try:
        return _ENCODER.encode(content).encode("utf-8")
    except ValueError:
        return _ENCODER.encode(json_safe(content)).encode("utf-8")


#: Containers longer than this (lists) are rendered item by item, down to ``_SPLIT_DEPTH`` levels.
_SPLIT_LEN = 32
_SPLIT_DEPTH = 3


def _big(x: Any) -> bool:
    if isinstance(x, list):
        return len(x) > _SPLIT_LEN
    if isinstance(x, dict):
        return any(isinstance(v, (list, dict)) and _big(v) for v in x.values())
    return False


def _pieces(x: Any, depth: int, out: list[bytes], budget: list[int], limit: int, field: str | None) -> None:
    if depth < _SPLIT_DEPTH and _big(x):
        if isinstance(x, list):
            out.append(b"[")
            for i, v in enumerate(x):
                if i:
                    out.append(b",")
                _pieces(v, depth + 1, out, budget, limit, field)
            out.append(b"]")
        else:
            out.append(b"{")
            for i, (k, v) in enumerate(x.items()):
                out.append((b"," if i else b"") + render_json(str(k)) + b":")
                _pieces(v, depth + 1, out, budget, limit, field)
            out.append(b"}")
        return
    piece = render_json(x)
    budget[0] += len(piece)
    if budget[0] > limit:
        raise ResponseTooLarge(limit, field)
    out.append(piece)


def render_json_bounded(content: Any, limit: int, field: str | None = None) -> bytes:
    """:func:`render_json` of ``content`` (the same bytes), rendered piece by piece; raises
    :class:`ResponseTooLarge` (naming ``field``, the input that sets the size) once the body
    would exceed ``limit`` bytes."""
    if not _big(content):
        body = render_json(content)
        if len(body) > limit:
            raise ResponseTooLarge(limit, field)
        return body
    out: list[bytes] = []
    budget = [0]
    _pieces(content, 0, out, budget, limit, field)
    body = b"".join(out)
    if len(body) > limit:
        raise ResponseTooLarge(limit, field)
    return body


class JSONBody(bytes):
    """A rendered JSON answer (as opposed to the bytes of a figure, which a task returns as they are)."""

    __slots__ = ()


def render_task(fn: Callable[..., Any], args: tuple[Any, ...], limit: int, field: str | None = None) -> Any:
    """``fn(*args)`` (a task of :mod:`service.tasks` or a figure), its result rendered here within ``limit``
    bytes (:func:`render_json_bounded`: :class:`ResponseTooLarge` naming ``field`` over it) as a
    :class:`JSONBody`: a library result by its own ``to_dict()`` (the one serialiser per result type), a dict
    as it is. The one way a task's result becomes a body, wherever the task runs (a solver thread, a solver
    process). ``None`` (a bounded first try that did not settle the request) and bytes (a figure) are returned
    as they are."""
    result = fn(*args)
    if result is None or isinstance(result, bytes):
        return result
    return JSONBody(render_json_bounded(json_ready(result), limit, field))


def json_ready(result: Any) -> Any:
    """A task's result as the body's content: a library result by its ``to_dict()``, a dict as it is."""
    return result if isinstance(result, dict) else result.to_dict()


class SafeJSONResponse(JSONResponse):
    """The application's default response class (:func:`render_json`)."""

    def render(self, content: Any) -> bytes:
        return render_json(content)
