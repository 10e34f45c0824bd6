"""The executors of one server, as its settings say, started and stopped together.

* ``threads`` (:class:`ThreadExecutor`; ``TENSEGRITY_WORKERS``, ``QUEUE_SIZE``, ``HEAVY_THREADS``): every request
  that is not sent elsewhere; the ``heavy`` request classes hold at most ``heavy_threads`` of them;
* ``fast`` (:class:`ProcessExecutor`; ``TENSEGRITY_INLINE_PROCESSES``, ``INLINE_MAX_SEGMENTS``): the bounded first
  try of a short request (the Newton-only equilibrium search), many calls outstanding per child; a miss or a
  failure goes to ``threads``;
* ``killable`` (:class:`ProcessExecutor`; ``TENSEGRITY_HEAVY_WORKERS``, ``HEAVY_QUEUE_SIZE``, ``HEAVY_GRACE``): the
  requests whose first call may be an uncuttable build (design, plans, stiffness shaping), one call per child;
* ``streams`` (:class:`StreamSlots`; ``TENSEGRITY_MAX_STREAM_CONNECTIONS``): one thread per open control stream.

The job runner has threads of its own (:mod:`service.jobs.runner`), so sweeps never take the requests' capacity.
"""

from __future__ import annotations

import asyncio
import logging
import os
from collections.abc import Callable
from typing import Any

from ..config import Settings
from .processes import ProcessExecutor
from .slots import StreamSlots
from .threads import ThreadExecutor

log = logging.getLogger("service.execution")

__all__ = ["Executors", "FAST_GRACE", "WARMUP_TIMEOUT"]

#: Seconds a fast-lane call past its deadline may take before its process is killed as stuck.
FAST_GRACE = 1.0
#: Seconds the start-up waits for the solver processes' warm-up (then the threads answer until they are ready).
WARMUP_TIMEOUT = 60.0


def child_env(settings: Settings) -> dict[str, str] | None:
    """The solver processes' environment beyond the server's: with ``kernel_builds=background`` they compile in the
    background too (``TENSEGRITY_COMPILE=background``), unless compilation is switched off."""
    current = os.environ.get("TENSEGRITY_COMPILE", "1").strip().lower()
    if settings.kernel_builds == "background" and current not in ("0", "false", "no", "off"):
        return {"TENSEGRITY_COMPILE": "background"}
    return None


class Executors:
    """The server's executors (see the table above).

    Parameters
    ----------
    settings : Settings
        The server's settings.
    warmup : callable
        Builds a worker's solvers for the common case (run once per solver thread at start-up, and as the fast
        processes' warm-up); importable by name.
    loaded : callable
        The killable processes' warm-up: importing what their calls run; importable by name.
    """

    def __init__(self, settings: Settings, *, warmup: Callable[[], Any], loaded: Callable[[], Any]) -> None:
        self.settings = settings
        self.warmup = warmup
        self.threads = ThreadExecutor(settings.workers, settings.queue_size, heavy_limit=settings.heavy_threads)
        env = child_env(settings)
        self.fast = (ProcessExecutor(settings.inline_processes, depth=max(settings.queue_size, 1), grace=FAST_GRACE,
                                     warmup=warmup, label="solver process", env=env)
                     if settings.inline_processes and settings.inline_max_segments else None)
        self.killable = (ProcessExecutor(settings.heavy_workers, queue_size=settings.heavy_queue_size,
                                         grace=settings.heavy_grace, warmup=loaded, label="design solver process",
                                         env=env)
                         if settings.heavy_workers else None)
        self.streams = StreamSlots(settings.max_stream_connections)

    async def start(self) -> None:
        """Start every executor; with ``settings.warmup`` each solver thread builds its solvers and the start
        waits for the processes' warm-up (best effort: what is not ready is logged, the threads answer)."""
        settings = self.settings
        self.threads.start()
        if self.fast is not None:
            self.fast.start()           # the processes warm up while the threads do
        if self.killable is not None and settings.warmup:
            self.killable.start()       # they import the library meanwhile (without warm-up: on the first call)
        if not settings.warmup:
            return
        timeout = max(settings.solve_timeout, 30.0)
        warmups = [self.threads.run(self.warmup, timeout=timeout) for _ in range(self.threads.workers)]
        for res in await asyncio.gather(*warmups, return_exceptions=True):
            if isinstance(res, BaseException):
                log.warning("solver warm-up failed: %r", res)
        if self.fast is not None and not await self.fast.wait_ready(WARMUP_TIMEOUT):
            log.warning("a solver process is not ready after %g s; requests run in the solver threads",
                        WARMUP_TIMEOUT)

    def stop(self, timeout: float) -> None:
        """Stop every executor: the processes first (their sockets close), then the threads."""
        for ex in (self.fast, self.killable):
            if ex is not None:
                ex.shutdown()
        self.streams.shutdown(timeout)
        self.threads.shutdown(timeout)
