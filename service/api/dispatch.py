"""Where a request's task runs: the one dispatcher between the routes and the executors.

A route validates its request, applies the server's limits and hands its task to :func:`run_task` with the
request's :class:`~service.adapters.fields.FieldContext` and a :class:`Placement`; the dispatcher picks the
executor (:class:`service.execution.Executors`, in ``app.state.executors``), runs the task there under the time
limit with its result rendered where it ran (:func:`service.responses.render_task`, within
``max_response_bytes``), and returns the body; a failure leaves as an :class:`~service.api.errors.ApiError`
already mapped with the request's field names. Nothing is solved on the event loop.

=================  =========================================================================================
placement          executor
=================  =========================================================================================
``LIGHT``          a solver thread
``HEAVY``          a solver thread, at most ``heavy_threads`` of them for this class (batches, branches, the
                   homotopy, long chains, figures of those)
``KILLABLE``       a killable solver process (design NLPs, plans, stiffness shaping); the solver threads as
                   ``HEAVY`` on a server without them (``TENSEGRITY_HEAVY_WORKERS=0``)
=================  =========================================================================================

``bounded=True`` (a short request the bounded search may settle): the task first runs as ``fn(*args, True)``
in a fast solver process when one is ready, so the event loop goes on with HTTP meanwhile (a thread hand-off
costs ~0.1-0.2 ms, as much as a whole short-chain solve). Its answer is sent as it is; when it does not settle
the request (``None``) or the process cannot answer (not running, restarting, saturated, died, or the call
raised there), the task runs where its placement says with the time left, which raises that error again with
its full type. Only a time limit ends the request there (504).
"""

from __future__ import annotations

import enum
import time
from collections.abc import Callable
from typing import Any

from fastapi import Request
from starlette.responses import Response

from ..adapters.fields import FieldContext
from ..execution.executor import SolveTimeout
from ..responses import JSONBody, render_task
from .errors import to_api_error

__all__ = ["Placement", "run_task", "MIN_TIME_LEFT"]

#: Seconds the threads get at least after a fast process's miss (the request's time limit goes on).
MIN_TIME_LEFT = 0.001
JSON = "application/json"


class Placement(enum.Enum):
    """Where a task runs (see the table above)."""

    LIGHT = "light"
    HEAVY = "heavy"
    KILLABLE = "killable"


async def run_task(request: Request, fn: Callable[..., Any], *args: Any, fields: FieldContext = FieldContext(),
                   placement: Placement = Placement.LIGHT, size_field: str | None = None,
                   timeout: float | None = None, bounded: bool = False, timeout_hint: str | None = None) -> Any:
    """``fn(*args)`` for ``request``: the rendered JSON answer (a ``Response``), or a figure's bytes.

    ``size_field`` names the input that sets the answer's size (``response_too_large`` over
    ``max_response_bytes``); ``timeout`` replaces the server's solve time limit; ``bounded`` tries the bounded
    first run in a fast process (above); ``timeout_hint`` is added to a 504's message (what to do instead). A
    failure raises :class:`~service.api.errors.ApiError` (with the field
    names of ``fields``), or the exception itself when it is a server bug.
    """
    state = request.app.state
    settings = state.settings
    executors = state.executors
    limit = settings.max_response_bytes
    timeout = timeout or settings.solve_timeout
    try:
        if bounded and executors.fast is not None:
            start = time.monotonic()
            try:
                body = await executors.fast.run(render_task, fn, (*args, True), limit, size_field, timeout=timeout)
            except SolveTimeout:
                raise
            except Exception:  # noqa: BLE001 - a miss or failure of the fast process: the threads decide
                body = None
            if body is not None:
                return Response(body, media_type=JSON)
            timeout = max(timeout - (time.monotonic() - start), MIN_TIME_LEFT)
        if placement is Placement.KILLABLE and executors.killable is not None:
            executor = executors.killable
        else:
            executor = executors.threads
        body = await executor.run(render_task, fn, args, limit, size_field, timeout=timeout,
                                  heavy=placement is not Placement.LIGHT, kind=getattr(fn, "__qualname__", None))
    except Exception as exc:
        err = to_api_error(exc, fields, retry_after=settings.retry_after, timeout_hint=timeout_hint)
        if err is None:
            raise
        raise err from exc
    if isinstance(body, JSONBody):
        return Response(body, media_type=JSON)
    return body             # a figure's bytes (the route adds its media type)
