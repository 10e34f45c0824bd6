"""Killable solver processes for the heavy request classes (``/v1/design/*``, ``/v1/control/plan``).

Why processes for these
-----------------------
* A design request runs one long IPOPT solve, and the first one for a chain length first builds
  its CasADi problem: one call into compiled code (``nlpsol``: ~2 s for n = 30, 20-40 s for
  n = 60) that nothing inside the process can interrupt. In a solver thread such a request held
  the thread long after its 504 (the thread was busy ~38 s for a 10 s limit).
* Here each call runs in a child process with the library time limit
  (:func:`tensegrity_opt.time_limit`) set to the request's remaining budget, so a solve normally
  stops by itself at the deadline (IPOPT checks it every iteration) and the child keeps its warm
  problem cache. At the deadline the request gets its 504 at once; a child that has not answered
  ``grace`` seconds later (stuck in a build) is killed (SIGKILL) and replaced: its capacity is
  free again within ``grace`` + a process start, whatever it was doing.
* Fairness: these requests never occupy the solver threads of :mod:`service.pool`, so light
  requests (``/v1/buckling``, ``/v1/equilibrium`` ...) always find a thread; heavy requests share
  ``workers`` processes and at most ``queue_size`` wait (503 ``overloaded`` beyond).

A child is ``python -m service.heavy FD`` (a fresh interpreter, as :mod:`service.lane`); a call
is ``(fn, args, deadline)`` over a socket, the reply ``(ok, value)`` with the exception itself when
the call raised (its type and fields survive: it is mapped to HTTP like any other). A child that
dies during a call answers 503 ``overloaded`` (retry) and is replaced.
"""

from __future__ import annotations

import asyncio
import logging
import os
import socket
import subprocess
import sys
import time
from collections.abc import Callable
from multiprocessing.connection import Connection
from typing import Any

from .pool import PoolSaturated, SolveTimeout

log = logging.getLogger("service.heavy")

__all__ = ["ProcessLane"]


def _child_main(conn: Any) -> None:
    """The child: answer calls in order, each under the library time limit it was sent with."""
    import tensegrity_opt  # noqa: F401 - import (CasADi) before the first call, not during it
    from tensegrity_opt.timelimit import time_limit

    from . import compute  # noqa: F401 - what the calls run

    conn.send("ready")          # a call is sent only to a child that has imported (~1-3 s)
    while True:
        try:
            fn, args, deadline = conn.recv()
        except (EOFError, OSError):
            return
        try:
            # the deadline is absolute (CLOCK_MONOTONIC is one clock for every process of the machine):
            # the time a call waited in the pipe (a child still importing) counts
            with time_limit(max(deadline - time.monotonic(), 1e-6)):
                reply: tuple[bool, Any] = (True, fn(*args))
        except Exception as exc:  # noqa: BLE001 - handed to the parent, which maps it
            reply = (False, exc)
        try:
            conn.send(reply)
        except Exception as exc:  # noqa: BLE001 - an unpicklable result or exception
            conn.send((False, UnreadableReply(f"unpicklable reply: {type(exc).__name__}: {exc}")))


def _blocking(conn: Connection, op: Callable[..., Any], *args: Any) -> Any:
    """``op(*args)`` (``conn.send`` / ``conn.recv``) with the descriptor in blocking mode. uvloop's ``add_reader``
    (``tensegrity-opt serve`` runs on uvloop) makes it non-blocking, and ``Connection`` reads and writes whole frames:
    a call or a reply over the socket buffer (a plan's targets, a figure) raised ``BlockingIOError`` half-way. The
    child reads a call (sends its reply) in one go, so the wait here is the copy."""
    fd = conn.fileno()
    was = os.get_blocking(fd)
    if not was:
        os.set_blocking(fd, True)
    try:
        return op(*args)
    finally:
        if not was:
            os.set_blocking(fd, False)


class UnreadableReply(Exception):
    """The child's reply could not be unpickled here (a server bug: answered as a 500)."""


class _Child:
    """``python -m service.heavy FD``: a fresh interpreter (no fork of a threaded server, no re-import
    of the parent's main script) talking ``multiprocessing.connection`` frames over a socketpair."""

    def __init__(self) -> None:
        parent, child = socket.socketpair()
        try:
            self.proc = subprocess.Popen([sys.executable, "-m", "service.heavy", str(child.fileno())],
                                         pass_fds=(child.fileno(),), stdin=subprocess.DEVNULL)
        except BaseException:
            parent.close()
            raise
        finally:
            child.close()
        self.conn = Connection(parent.detach())
        self.future: asyncio.Future[tuple[bool, Any]] | None = None
        self.reading = False
        self.ready = False      # its "ready" frame came: it has imported the library

    def kill(self) -> None:
        try:
            self.proc.kill()
            self.proc.wait(2.0)
        except (OSError, subprocess.TimeoutExpired):  # pragma: no cover - already gone / unkillable
            pass
        self.conn.close()


class ProcessLane:
    """``workers`` killable solver processes, at most ``queue_size`` calls waiting for one."""

    def __init__(self, workers: int, queue_size: int, grace: float = 0.5) -> None:
        self.workers = workers
        self.queue_size = queue_size
        self.grace = grace
        self._idle: list[_Child] = []
        self._all: set[_Child] = set()
        self._waiters: list[asyncio.Future[_Child]] = []
        self._queued = 0
        self._closing = False
        self.killed = 0             # children killed at a deadline (statistics, tests)

    # ------------------------------------------------------------------ lifecycle
    def start(self) -> None:
        while len(self._all) < self.workers and not self._closing:
            self._add()

    def _add(self) -> None:
        c = _Child()
        self._all.add(c)
        self._start_reading(asyncio.get_running_loop(), c)     # its "ready" frame makes it available

    def close(self) -> None:
        self._closing = True
        for c in list(self._all):
            self._stop_reading(c)
            c.kill()
        self._all.clear()
        self._idle.clear()
        for w in self._waiters:
            if not w.done():
                w.set_exception(PoolSaturated("the solver processes are shutting down"))

    # ------------------------------------------------------------------ statistics
    @property
    def busy(self) -> int:
        """Children running a call (or finishing one whose caller timed out); not the ones starting."""
        return sum(1 for c in self._all if c.ready) - len(self._idle)

    @property
    def in_flight(self) -> int:
        """Calls waiting for a child plus children busy."""
        return self._queued + self.busy

    # ------------------------------------------------------------------ calls
    async def run(self, fn: Callable[..., Any], *args: Any, timeout: float) -> Any:
        """``fn(*args)`` in a child; :class:`SolveTimeout` after ``timeout`` s, :class:`PoolSaturated` when full."""
        if self._closing:
            raise PoolSaturated("the solver processes are shutting down")
        if not self._all:
            self.start()
        if not self._idle and self._queued >= self.queue_size:
            raise PoolSaturated(f"all {self.workers} design solver processes are busy and {self.queue_size} "
                                f"requests are queued")
        loop = asyncio.get_running_loop()
        deadline = time.monotonic() + timeout
        child = await self._acquire(loop, timeout)
        fut: asyncio.Future[tuple[bool, Any]] = loop.create_future()
        child.future = fut
        try:
            self._start_reading(loop, child)
            _blocking(child.conn, child.conn.send, (fn, args, deadline))
        except (OSError, ValueError) as exc:            # the child is gone: replace it
            self._replace(child)
            raise PoolSaturated(f"the design solver process stopped ({exc})") from None
        except BaseException:                           # not picklable (nothing was sent): child unused
            child.future = None
            self._give(child)
            raise
        try:
            ok, value = await asyncio.wait_for(asyncio.shield(fut), max(deadline - time.monotonic(), 0.0))
        except (asyncio.TimeoutError, TimeoutError):
            loop.create_task(self._reap(child, fut))
            raise SolveTimeout(timeout) from None
        except asyncio.CancelledError:                  # the request itself went away
            loop.create_task(self._reap(child, fut))
            raise
        except PoolSaturated:
            self._replace(child)
            raise
        except UnreadableReply:
            child.future = None
            self._give(child)
            raise
        child.future = None
        self._give(child)
        if ok:
            return value
        raise value

    async def _acquire(self, loop: asyncio.AbstractEventLoop, timeout: float) -> _Child:
        if self._idle:
            return self._idle.pop()
        w: asyncio.Future[_Child] = loop.create_future()
        self._waiters.append(w)
        self._queued += 1
        try:
            return await asyncio.wait_for(w, timeout)
        except BaseException as exc:                    # timed out, or the request went away
            if w.done() and not w.cancelled() and w.exception() is None:
                self._give(w.result())                  # handed over at the last moment: pass it on
            if isinstance(exc, (asyncio.TimeoutError, TimeoutError)):
                raise SolveTimeout(timeout) from None
            raise
        finally:
            self._queued -= 1
            if w in self._waiters:
                self._waiters.remove(w)

    def _give(self, child: _Child) -> None:
        """``child`` is free: to the first waiter, else idle."""
        while self._waiters:
            w = self._waiters.pop(0)
            if not w.done():
                w.set_result(child)
                return
        self._idle.append(child)

    async def _reap(self, child: _Child, fut: asyncio.Future[tuple[bool, Any]]) -> None:
        """After a deadline: let the child answer within ``grace`` (its own time limit), else kill it."""
        try:
            await asyncio.wait_for(asyncio.shield(fut), self.grace)
        except (asyncio.TimeoutError, TimeoutError, PoolSaturated):
            self.killed += 1
            log.info("design solver process %s did not stop within %.1f s of the deadline; killing it",
                     child.proc.pid, self.grace)
            self._replace(child)
            return
        except BaseException:  # noqa: BLE001 - the call failed there; the child itself is fine
            pass
        child.future = None
        if child in self._all:
            self._give(child)

    def _replace(self, child: _Child) -> None:
        self._stop_reading(child)
        if child in self._idle:
            self._idle.remove(child)
        if child in self._all:
            self._all.discard(child)
            child.kill()
        if not self._closing:
            self._add()

    # ------------------------------------------------------------------ replies
    def _start_reading(self, loop: asyncio.AbstractEventLoop, child: _Child) -> None:
        if not child.reading:
            loop.add_reader(child.conn.fileno(), self._readable, child)
            child.reading = True

    def _stop_reading(self, child: _Child) -> None:
        if child.reading:
            try:
                asyncio.get_running_loop().remove_reader(child.conn.fileno())
            except (RuntimeError, ValueError, OSError):  # pragma: no cover - no loop / closed
                pass
            child.reading = False

    def _readable(self, child: _Child) -> None:
        fut = child.future
        try:
            reply = _blocking(child.conn, child.conn.recv)
        except (EOFError, OSError) as exc:
            self._stop_reading(child)
            if not child.ready:                 # died while starting (cannot import?): not retried in a loop
                log.warning("a design solver process exited while starting (status %s)", child.proc.poll())
                self._all.discard(child)
                child.kill()
                for w in self._waiters:
                    if not w.done() and not self._all:
                        w.set_exception(PoolSaturated("the design solver process could not start"))
                return
            if fut is not None and not fut.done():
                fut.set_exception(PoolSaturated(f"the design solver process stopped ({type(exc).__name__})"))
            elif child in self._all:
                self._replace(child)
            return
        except Exception as exc:  # noqa: BLE001 - a reply this process cannot unpickle: a server bug (500)
            if fut is not None and not fut.done():
                fut.set_exception(UnreadableReply(f"the design solver process sent an unreadable reply: {exc!r}"))
            return
        if not child.ready:
            child.ready = True
            if child in self._all:
                self._give(child)
            return
        if fut is not None and not fut.done():
            fut.set_result(reply)


if __name__ == "__main__":
    _child_main(Connection(int(sys.argv[1])))
