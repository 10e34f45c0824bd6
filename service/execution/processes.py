"""Solver processes: the :class:`~service.execution.executor.Executor` whose workers are child processes.

Why processes
-------------
Two kinds of work leave the server's process, as two instances of :class:`ProcessExecutor`:

* **the fast lane** (short, bounded calls: the Newton-only equilibrium search of a short chain, ~0.3-0.5 ms):
  a hand-off to a solver thread costs as much as the solve, and the solve would then hold the GIL the event
  loop needs; a child process solves on the other core while the loop parses, validates and answers the next
  requests. Many calls may be outstanding in one child (``depth``); it answers them in order.
* **the killable processes** (``/v1/design/*``, rest-length plans, stiffness shaping): the first solve for a
  chain length builds its CasADi problem in one call into compiled code (~2 s for n = 30, 20-40 s for n = 60)
  that nothing inside a process can interrupt. In a child, a call runs under the library time limit of its
  deadline, so it normally stops by itself (IPOPT checks it every iteration) and the child keeps its warm
  caches; one call at a time per child (``depth`` 1), at most ``queue_size`` waiting (503 beyond).

How a call is stopped
---------------------
At its deadline the caller gets :class:`SolveTimeout` (504) at once. A child that has not answered that call
``grace`` seconds later (stuck in a build, or sleeping) is killed (SIGKILL) and replaced at once: its capacity is
free again within ``grace`` plus a process start, whatever it was doing. Its other calls fail with
:class:`Unavailable`.

Children
--------
A child is ``python -m service.execution.child FD`` (a fresh interpreter, no fork of a threaded server) on one
end of a socketpair, speaking :mod:`service.execution.ipc`; the loop's end is an asyncio protocol (no thread,
no blocking read). Its first call is the warm-up (``warmup``: building the solvers, or importing the
library); it takes calls once that is answered.

Restarts
--------
A child killed by the executor (stuck past a deadline) is replaced at once. A child lost otherwise (it died, was
killed from outside, failed its warm-up, or exited before it was ready) is replaced after a delay that grows with
each loss in a row: ``RESTART_BASE`` seconds, doubled each time,
at most ``RESTART_MAX`` (bounded: a child that can never start is tried again every ``RESTART_MAX`` seconds, with
one log line each time); the count of losses in a row starts over once a child has been ready for
``HEALTHY_SECONDS``. Meanwhile :meth:`ProcessExecutor.run` answers :class:`Unavailable` (the fast path's caller
falls back to the solver threads). :attr:`ProcessExecutor.state` says where it stands (``up``, ``starting``,
``restarting``, ``down``); ``/readyz`` and ``/metrics`` show it. Only a platform that cannot start a child at all
(no ``pass_fds``) leaves it ``down``.
"""

from __future__ import annotations

import asyncio
import collections
import logging
import os
import pickle
import socket
import subprocess
import sys
import time
from collections.abc import Callable
from typing import Any

from .executor import Executor, Saturated, SolveTimeout, Unavailable
from .ipc import FRAME, WARMUP, UnreadableReply, encode, ready
from .shedding import MARGIN, ServiceTimes, expected_wait, refusal, remaining

log = logging.getLogger("service.execution")

__all__ = ["ProcessExecutor", "RESTART_BASE", "RESTART_MAX", "HEALTHY_SECONDS", "STATES", "restart_delay"]

#: Seconds before the replacement of the first child lost after a healthy period; doubled with each loss in a row.
RESTART_BASE = 0.5
#: The longest delay before a replacement (seconds).
RESTART_MAX = 30.0
#: Seconds a child must have been ready for the next loss to count as the first in a row again.
HEALTHY_SECONDS = 60.0
#: The executor's states (:attr:`ProcessExecutor.state`).
STATES = ("up", "starting", "restarting", "down")


def restart_delay(losses: int) -> float:
    """Seconds before a replacement after ``losses`` children lost in a row (``losses`` >= 1)."""
    return min(RESTART_BASE * 2.0 ** max(losses - 1, 0), RESTART_MAX)


def _expire(fut: asyncio.Future[Any]) -> None:
    """A call's time limit: its caller gets ``TimeoutError`` (unless the answer came first)."""
    if not fut.done():
        fut.set_exception(asyncio.TimeoutError())


class _Child(asyncio.Protocol):
    """One child process and the loop's end of its socket: frames in, the calls' futures resolved."""

    def __init__(self, owner: ProcessExecutor, proc: subprocess.Popen[bytes], sock: socket.socket) -> None:
        self.owner = owner
        self.proc = proc
        self.sock = sock
        self.transport: asyncio.Transport | None = None
        self.buffer = bytearray()
        self.calls: dict[int, asyncio.Future[Any]] = {}   # sent, not answered (timed-out ones included)
        self.sent: dict[int, float] = {}                   # when each was sent (the executor's clock)
        self.kinds: dict[int, Any] = {}                    # what each is (for the estimates of service time)
        self.reserved = 0                                  # handed to a waiter that has not sent yet
        self.ready = False
        self.ready_at = 0.0                                # time.monotonic() at the end of its warm-up
        self.killed = False                                # by the executor (past the grace of a deadline)
        self.started = time.monotonic()
        self.done: asyncio.Future[bool] = asyncio.get_running_loop().create_future()   # ready, or never

    @property
    def load(self) -> int:
        return len(self.calls) + self.reserved

    def connection_made(self, transport: asyncio.BaseTransport) -> None:
        self.transport = transport  # type: ignore[assignment]

    def data_received(self, data: bytes) -> None:
        buf = self.buffer
        buf += data
        start, end = 0, len(buf)
        while end - start >= FRAME.size:
            size, call_id = FRAME.unpack_from(buf, start)
            if end - start - FRAME.size < size:
                break
            body = buf[start + FRAME.size:start + FRAME.size + size]
            start += FRAME.size + size
            try:
                ok, value = pickle.loads(body)
            except Exception as exc:  # noqa: BLE001 - a reply this process cannot unpickle: a server bug
                ok, value = False, UnreadableReply(f"the {self.owner.label} sent an unreadable reply: {exc!r}")
            self.owner._reply(self, call_id, ok, value)
        if start:
            del buf[:start]

    def connection_lost(self, exc: Exception | None) -> None:
        self.owner._lost(self)


class ProcessExecutor(Executor):
    """``workers`` child processes, each answering up to ``depth`` calls in order; at most ``queue_size`` calls
    wait for room (:class:`Saturated` beyond; with no queue, a call that finds no ready child with room is
    refused at once: :class:`Unavailable`, for a caller that has a fallback).

    Parameters
    ----------
    workers : int
        Child processes.
    depth : int
        Calls one child may hold at once (sent, not answered).
    queue_size : int
        Calls that may wait for room.
    grace : float
        Seconds after a call's deadline before its child, still busy with it, is killed.
    warmup : callable, optional
        A child's first call (importable by name); it takes calls once that is answered.
    label : str
        What the children are, for messages and logs (``"design solver process"``).
    env : dict, optional
        Extra environment of the children (the server's is inherited).
    """

    def __init__(self, workers: int, *, depth: int = 1, queue_size: int = 0, grace: float = 0.5,
                 warmup: Callable[[], Any] | None = None, label: str = "solver process",
                 env: dict[str, str] | None = None) -> None:
        self.workers = workers
        self.depth = depth
        self.queue_size = queue_size
        self.grace = grace
        self.warmup = warmup if warmup is not None else ready
        self.label = label
        self.env = env
        self._children: list[_Child] = []
        self._waiters: collections.deque[asyncio.Future[_Child]] = collections.deque()
        self._waiting: dict[asyncio.Future[_Child], Any] = {}     # each waiter's kind of call
        self._tasks: set[asyncio.Task[None]] = set()
        self._next_id = 0
        self._closing = False
        self._broken = False        # this platform cannot start a child: none is started again
        self._restart: asyncio.TimerHandle | None = None    # a replacement waiting for its delay
        self.losses = 0             # children lost in a row (reset by a healthy period)
        self.service_times = ServiceTimes()   # the calls' service time, for load shedding (:mod:`.shedding`)
        self.shed = 0               # calls refused by their expected wait
        self.completed = 0          # calls answered (statistics, tests)
        self.restarts = 0           # children started to replace a lost one
        self.killed = 0             # children killed past the grace of a deadline

    # ------------------------------------------------------------------ lifecycle
    def start(self) -> None:
        """Start the children (returns at once; :meth:`wait_ready` waits for their warm-up); nothing while a
        replacement waits for its delay."""
        while (len(self._children) < self.workers and not self._closing and not self._broken
               and self._restart is None):
            if not self._spawn():
                return

    def _spawn(self) -> bool:
        parent, child = socket.socketpair()
        try:
            proc = subprocess.Popen([sys.executable, "-m", "service.execution.child", str(child.fileno())],
                                    pass_fds=(child.fileno(),), stdin=subprocess.DEVNULL,
                                    env={**os.environ, **self.env} if self.env else None)
        except (OSError, ValueError) as exc:             # ValueError: no pass_fds on this platform
            parent.close()
            log.warning("could not start a %s: %r", self.label, exc)
            if isinstance(exc, ValueError):
                self._broken = True
            else:                                        # out of processes or descriptors: try again later
                self.losses += 1
                self._schedule_restart()
            return False
        finally:
            child.close()
        c = _Child(self, proc, parent)
        self._children.append(c)
        task = asyncio.get_running_loop().create_task(self._connect(c))
        self._tasks.add(task)
        task.add_done_callback(self._tasks.discard)
        return True

    async def _connect(self, c: _Child) -> None:
        loop = asyncio.get_running_loop()
        try:
            await loop.create_unix_connection(lambda: c, sock=c.sock)
        except OSError as exc:  # pragma: no cover - a fresh socketpair
            log.warning("cannot connect to a %s: %r", self.label, exc)
            c.proc.kill()
            self._lost(c)
            return
        assert c.transport is not None
        if self._closing:                               # shut down while connecting
            c.transport.close()
            return
        c.transport.write(encode(WARMUP, (self.warmup, (), None)))

    async def wait_ready(self, timeout: float) -> bool:
        """Wait up to ``timeout`` seconds for the children's warm-up; ``True`` when every child is ready."""
        children = list(self._children)
        if not children:
            return False
        try:
            await asyncio.wait_for(asyncio.gather(*[asyncio.shield(c.done) for c in children]), timeout)
        except (asyncio.TimeoutError, TimeoutError):
            return False
        return all(c.ready for c in children)

    def shutdown(self, timeout: float = 0.5) -> None:
        """Stop the children (their sockets close; they exit) and fail the calls still outstanding."""
        self._closing = True
        if self._restart is not None:
            self._restart.cancel()
            self._restart = None
        while self._waiters:
            w = self._waiters.popleft()
            if not w.done():
                w.set_exception(Saturated(f"the {self.label}es are shutting down"))
        children, self._children = self._children, []
        for c in children:
            # the transport closes its socket only at the loop's next iteration, and the wait below blocks
            # the loop: without the shutdown a child would see no end of file and be killed after the wait
            try:
                c.sock.shutdown(socket.SHUT_RDWR)
            except OSError:
                pass
            if c.transport is not None:
                c.transport.close()
            self._fail(c, f"the {self.label} stopped")
        deadline = time.monotonic() + timeout
        for c in children:
            try:
                c.proc.wait(max(deadline - time.monotonic(), 0.0))
            except subprocess.TimeoutExpired:       # busy with a call: nothing of it is kept
                c.proc.kill()
                c.proc.wait(2.0)

    # ------------------------------------------------------------------ statistics
    @property
    def ready(self) -> bool:
        """A child has finished its warm-up and runs."""
        return any(c.ready for c in self._children)

    @property
    def ready_count(self) -> int:
        """Children that have finished their warm-up and run."""
        return sum(1 for c in self._children if c.ready)

    @property
    def state(self) -> str:
        """``up`` (every child ready), ``starting`` (not yet, and none lost so far), ``restarting`` (children were
        lost: replacements wait for their delay or warm up), ``down`` (stopped, or no child can start here)."""
        if self._closing or self._broken:
            return "down"
        if self.ready_count >= self.workers:
            return "up"
        return "restarting" if self.restarts or self.losses else "starting"

    @property
    def pids(self) -> list[int]:
        return [c.proc.pid for c in self._children]

    @property
    def in_flight(self) -> int:
        """Calls waiting for room plus calls in the children (those past their deadline included)."""
        return len(self._waiters) + sum(len(c.calls) for c in self._children)

    def expected_wait(self) -> float:
        """Seconds a new call would wait for room, by the running estimate of the service time (:mod:`.shedding`):
        the calls in the children (in order in each) and those waiting, shared by the children."""
        times = self.service_times
        now = times.clock()
        busy = [sum(remaining(sent, times.estimate(False, c.kinds.get(i)), now) for i, sent in c.sent.items())
                for c in self._children]
        return expected_wait(busy, [times.estimate(False, kind) for kind in self._waiting.values()],
                             len(self._children) or self.workers)

    # ------------------------------------------------------------------ calls
    async def run(self, fn: Callable[..., Any], *args: Any, timeout: float, heavy: bool = False,
                  kind: Any = None) -> Any:
        """``fn(*args)`` in a child (``fn`` importable by name, the arguments and the answer picklable)."""
        if self._closing:
            raise Saturated(f"the {self.label}es are shutting down")
        child = self._pick()
        if child is None:
            if not self._children:
                self.start()
            if not self._children:
                raise Unavailable(f"the {self.label} is {'restarting' if self.state == 'restarting' else 'down'}")
            if len(self._waiters) >= self.queue_size:
                if self.queue_size == 0:
                    raise Unavailable(f"no {self.label} is ready with room for the call")
                raise Saturated(f"all {self.workers} {self.label}es are busy and {self.queue_size} requests are "
                                "queued")
            wait, own = self.expected_wait(), self.service_times.estimate(False, kind)
            if wait > 0.0 and MARGIN * (wait + own) >= timeout:
                self.shed += 1
                raise refusal(f"all {self.workers} {self.label}es", wait, own, timeout)
        deadline = time.monotonic() + timeout
        call_id = self._next_id
        self._next_id += 1
        frame = encode(call_id, (fn, args, deadline))     # not picklable: raised here, nothing sent
        loop = asyncio.get_running_loop()
        left = timeout
        if child is None:
            child = await self._acquire(loop, deadline, timeout, kind)
            child.reserved -= 1
            if child not in self._children:             # it stopped between the hand-over and now
                raise Unavailable(f"the {self.label} stopped")
            left = max(deadline - time.monotonic(), 0.0)
        fut: asyncio.Future[Any] = loop.create_future()
        child.calls[call_id] = fut
        child.sent[call_id] = self.service_times.clock()
        child.kinds[call_id] = kind
        assert child.transport is not None
        child.transport.write(frame)
        # one timer instead of asyncio.wait_for (which costs ~20 us of loop time per call)
        timer = loop.call_later(left, _expire, fut)
        try:
            return await fut
        except (asyncio.TimeoutError, TimeoutError):
            self._overdue(loop, child, call_id)
            raise SolveTimeout(timeout) from None
        except asyncio.CancelledError:                   # the request itself went away
            self._overdue(loop, child, call_id)
            raise
        finally:
            timer.cancel()

    def _pick(self) -> _Child | None:
        """The ready child with the fewest calls that has room, or ``None``."""
        if len(self._children) == 1:                    # the common case, on every call: no search
            c = self._children[0]
            return c if c.ready and len(c.calls) + c.reserved < self.depth else None
        best = None
        for c in self._children:
            if c.ready and c.load < self.depth and (best is None or c.load < best.load):
                best = c
        return best

    async def _acquire(self, loop: asyncio.AbstractEventLoop, deadline: float, timeout: float, kind: Any) -> _Child:
        """Wait for room in a child (until ``deadline``); the child comes with one call reserved."""
        w: asyncio.Future[_Child] = loop.create_future()
        self._waiters.append(w)
        self._waiting[w] = kind
        try:
            return await asyncio.wait_for(w, max(deadline - time.monotonic(), 0.0))
        except BaseException as exc:                    # timed out, or the request went away
            if w.done() and not w.cancelled() and w.exception() is None:
                w.result().reserved -= 1                # handed over at the last moment: pass it on
                self._wake()
            if isinstance(exc, (asyncio.TimeoutError, TimeoutError)):
                raise SolveTimeout(timeout) from None
            raise
        finally:
            self._waiting.pop(w, None)
            try:
                self._waiters.remove(w)
            except ValueError:
                pass

    def _wake(self) -> None:
        """Room in a child: to the waiters, oldest first."""
        while self._waiters:
            child = self._pick()
            if child is None:
                return
            w = self._waiters.popleft()
            if not w.done():
                child.reserved += 1
                w.set_result(child)

    def _overdue(self, loop: asyncio.AbstractEventLoop, child: _Child, call_id: int) -> None:
        """A call past its deadline (or whose caller went away): its child gets ``grace`` seconds to answer it."""
        if call_id in child.calls:
            loop.call_later(self.grace, self._reap, child, call_id)

    def _reap(self, child: _Child, call_id: int) -> None:
        if call_id in child.calls and child in self._children and child.proc.poll() is None:
            child.killed = True
            self.killed += 1
            log.warning("%s %s did not stop within %.1f s of a deadline; killing it", self.label, child.proc.pid,
                        self.grace)
            child.proc.kill()

    # ------------------------------------------------------------------ replies
    def _reply(self, child: _Child, call_id: int, ok: bool, value: Any) -> None:
        if call_id == WARMUP:
            if ok:
                child.ready = True
                child.ready_at = time.monotonic()
                if not child.done.done():
                    child.done.set_result(True)
                self._wake()
            else:                                        # lost (and replaced after its delay)
                log.warning("a %s failed its warm-up (%s)", self.label, value)
                child.proc.kill()
            return
        fut = child.calls.pop(call_id, None)
        sent, kind = child.sent.pop(call_id, None), child.kinds.pop(call_id, None)
        if sent is not None:
            self.service_times.record(False, self.service_times.clock() - sent, kind)
        self.completed += 1
        if fut is not None and not fut.done():
            if ok:
                fut.set_result(value)
            else:
                fut.set_exception(value)
        if self._waiters:
            self._wake()

    def _fail(self, child: _Child, why: str) -> None:
        calls, child.calls = child.calls, {}
        for fut in calls.values():
            if not fut.done():
                fut.set_exception(Unavailable(why))
        if not child.done.done():
            child.done.set_result(False)

    def _lost(self, child: _Child) -> None:
        """The child's socket closed (it exited, or was killed): fail its calls, replace it."""
        if child not in self._children:
            return                                      # shut down, or already handled
        self._children.remove(child)
        self._fail(child, f"the {self.label} stopped")
        proc = child.proc
        try:
            code = proc.wait(1.0)
        except subprocess.TimeoutExpired:
            proc.kill()
            code = proc.wait(1.0)
        if self._closing:
            return
        if child.killed:                                # stuck in a call: its replacement starts at once
            if self._restart is None:
                self._replace()
            return
        if child.ready and time.monotonic() - child.ready_at >= HEALTHY_SECONDS:
            self.losses = 0                             # after a healthy period: the first loss in a row again
        self.losses += 1
        log.warning("%s %s exited (status %s)%s; it is replaced in %.1f s", self.label, proc.pid, code,
                    "" if child.ready else " before it was ready", restart_delay(self.losses))
        if not child.ready and not self._children:
            while self._waiters:                        # nothing will answer them before a replacement is ready
                w = self._waiters.popleft()
                if not w.done():
                    w.set_exception(Unavailable(f"the {self.label} could not start; it is being restarted"))
        self._schedule_restart()

    def _schedule_restart(self) -> None:
        """Replace the lost children after the delay of the losses in a row (one timer for all of them)."""
        if self._closing or self._broken or self._restart is not None:
            return
        self._restart = asyncio.get_running_loop().call_later(restart_delay(max(self.losses, 1)), self._replace)

    def _replace(self) -> None:
        self._restart = None
        if self._closing or self._broken:
            return
        while len(self._children) < self.workers and self._restart is None:
            self.restarts += 1
            if not self._spawn():
                return
