"""Time limits: ``with time_limit(seconds):`` bounds every computation of the library inside it.

A limit is a deadline (``time.monotonic()``) held in a context variable, so it belongs to the
thread (or asyncio task) that set it; nested limits keep the earliest deadline. The library checks
it

* before every IPOPT solve (equilibrium searches and design problems), between the points of a
  force-deflection curve and after building a design problem, raising
  :class:`~tensegrity_opt.errors.TimeLimitError`;
* inside the long IPOPT solves of the design problems (:mod:`.numerics.design_nlp`), once per IPOPT
  iteration through CasADi's ``iteration_callback``: IPOPT stops with ``User_Requested_Stop``,
  which the library raises as :class:`~tensegrity_opt.errors.TimeLimitError` (never as a result).

An IPOPT solve that hits its own ``max_wall_time`` / ``max_cpu_time`` is likewise reported as a
:class:`~tensegrity_opt.errors.TimeLimitError` with that ``status``, not as an answer.

What a limit does not cut: the Newton-only stretches of a search between those checks (bounded:
milliseconds, seconds for long chains), and one call into compiled code that is not an IPOPT
iteration. The one that matters is the *first* design solve for a chain length, which builds the
CasADi problem (``nlpsol``: ~2 s for n = 30, 20-40 s for n = 60); the limit is checked right after
it returns. (``solve_equilibria_batch`` has its own ``deadline`` argument.)
The HTTP service runs those requests in a separate process that it kills at the deadline.

Example::

    with to.time_limit(5.0):
        d = to.maximize_critical_force(m, vary=("k",))   # TimeLimitError after ~5 s
"""

from __future__ import annotations

import contextvars
import math
import time
from collections.abc import Iterator
from contextlib import contextmanager

from .errors import InvalidParameterError, TimeLimitError

__all__ = ["time_limit", "deadline", "remaining", "check_time", "expired", "TIMEOUT_STATUSES"]

_deadline: contextvars.ContextVar[float | None] = contextvars.ContextVar("tensegrity_deadline", default=None)

#: IPOPT return statuses that mean "out of time", reported as :class:`TimeLimitError`.
TIMEOUT_STATUSES = frozenset({"Maximum_WallTime_Exceeded", "Maximum_CpuTime_Exceeded", "User_Requested_Stop"})


@contextmanager
def time_limit(seconds: float | None) -> Iterator[None]:
    """Bound the computations inside the block to ``seconds`` (``None``: no new limit).

    Raises :class:`~tensegrity_opt.errors.InvalidParameterError` (``field="time_limit"``) for a
    limit that is not a positive number; :class:`~tensegrity_opt.errors.TimeLimitError` from inside
    the block once the limit is reached.
    """
    if seconds is None:
        yield
        return
    try:
        s = float(seconds)
    except (TypeError, ValueError):
        raise InvalidParameterError(f"time_limit must be a number of seconds, got {seconds!r}",
                                    field="time_limit") from None
    if not s > 0 or math.isnan(s):
        raise InvalidParameterError(f"time_limit must be positive, got {seconds!r}", field="time_limit")
    new = time.monotonic() + s
    old = _deadline.get()
    token = _deadline.set(new if old is None else min(old, new))
    try:
        yield
    finally:
        _deadline.reset(token)


def deadline() -> float | None:
    """The current deadline (``time.monotonic()`` seconds), ``None`` without a limit."""
    return _deadline.get()


def remaining() -> float | None:
    """Seconds left before the current deadline (may be negative), ``None`` without a limit."""
    d = _deadline.get()
    return None if d is None else d - time.monotonic()


def expired() -> bool:
    """``True`` when a limit is set and reached."""
    d = _deadline.get()
    return d is not None and time.monotonic() >= d


def check_time(what: str = "the computation") -> None:
    """Raise :class:`~tensegrity_opt.errors.TimeLimitError` when the current limit is reached."""
    d = _deadline.get()
    if d is not None and time.monotonic() >= d:
        raise TimeLimitError(f"the time limit was reached before {what} finished", status="time_limit")
