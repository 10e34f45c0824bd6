"""The one interface for running a task away from the event loop, and its refusals.

An :class:`Executor` runs ``fn(*args)`` somewhere else (a thread, a killable process) under a time limit and
hands back the result or the exception, as ``await executor.run(fn, *args, timeout=...)``. Two implementations:
:class:`service.execution.threads.ThreadExecutor` (solver threads, each with its own CasADi instances) and
:class:`service.execution.processes.ProcessExecutor` (child processes over one socket protocol, killed when
they cannot stop). Every refusal of an executor is one of the exceptions below, mapped to HTTP in one place
(:mod:`service.api.errors`).
"""

from __future__ import annotations

import abc
from collections.abc import Callable
from typing import Any

__all__ = ["Executor", "Saturated", "Unavailable", "SolveTimeout"]


class Saturated(Exception):
    """Every worker is busy and the queue is full, or the call's expected wait reaches its time limit (503
    ``overloaded``; ``retry_after``: the seconds after which the executor expects room, when it knows)."""

    retry_after: float | None = None


class Unavailable(Saturated):
    """The executor cannot take or finish this call: not started (or it could not start), or its process
    stopped during the call. A caller with a fallback runs the call elsewhere; otherwise it is a 503."""


class SolveTimeout(Exception):
    """The call did not finish within its time limit (504 ``timeout``)."""

    def __init__(self, timeout: float) -> None:
        super().__init__(f"the solve did not finish within {timeout:g} s")
        self.timeout = timeout

    def __reduce__(self) -> tuple[Any, ...]:
        return type(self), (self.timeout,)


class Executor(abc.ABC):
    """Runs calls away from the event loop: at most ``workers`` at once, a bounded number waiting.

    ``fn`` runs under the library time limit of ``timeout`` (:func:`tensegrity_opt.time_limit`: the library
    stops by itself at the deadline where it can); a call still running at the deadline is stopped by the
    executor (interrupted in its thread, or its process killed after a grace). :meth:`run` raises
    :class:`SolveTimeout` at the deadline, :class:`Saturated` when full, and ``fn``'s own exception when it
    raised.
    """

    workers: int

    @abc.abstractmethod
    def start(self) -> None:
        """Start the workers (idempotent; a first :meth:`run` starts them too)."""

    @abc.abstractmethod
    async def run(self, fn: Callable[..., Any], *args: Any, timeout: float, heavy: bool = False,
                  kind: Any = None) -> Any:
        """``fn(*args)`` on a worker; ``heavy`` marks a long request class (a thread executor caps how many
        of its threads those hold); ``kind`` names what the call is (a task), for the running estimate of its
        service time by which a call that could not finish in time is refused at once
        (:mod:`service.execution.shedding`)."""

    @abc.abstractmethod
    def shutdown(self, timeout: float = 0.5) -> None:
        """Stop: queued calls are dropped, running ones stopped; wait at most ``timeout`` seconds."""

    @property
    @abc.abstractmethod
    def in_flight(self) -> int:
        """Calls queued or running."""
