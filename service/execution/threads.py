"""Solver threads: the :class:`~service.execution.executor.Executor` whose workers are threads.

Why threads, and how a call is stopped
--------------------------------------
* Solves are CPU-bound and never run on the event loop: a handler awaits :meth:`ThreadExecutor.run`, which
  hands the call to a worker thread; a thread of the process (the job runner) waits with :meth:`ThreadExecutor.wait`.
* The library caches its CasADi solver objects per thread (``threading.local``), so a CasADi instance built by
  one worker is only ever called by that worker, one call at a time: no instance is shared between threads.
* Concurrency is bounded: ``workers`` threads and at most ``queue_size`` waiting calls; beyond that
  :meth:`ThreadExecutor.submit` raises :class:`Saturated` (503 + Retry-After) at once instead of letting a
  backlog grow.
* The time limit: a call runs under the library's own limit (:func:`tensegrity_opt.time_limit`, the caller's
  budget: checked before every IPOPT solve, between curve points, every IPOPT iteration of a design solve), so
  it normally stops by itself. At the deadline the caller gets :class:`SolveTimeout` (504); a call still queued
  is dropped, a call still running is interrupted: :class:`Interrupted` is raised asynchronously in its thread
  (``PyThreadState_SetAsyncExc``). Python delivers it at the thread's next bytecode, i.e. after the current
  CasADi/IPOPT call returns (CasADi calls are never cut in half). It is sent again every ``REFIRE_SECONDS``
  while the call runs (an exception that lands in a finaliser run by the garbage collector is swallowed
  there). ``Interrupted`` derives from ``BaseException`` so the library's ``except Exception`` handlers let it
  through. What cannot be cut (one long native call that is not an IPOPT iteration) runs in a killable
  process instead (:mod:`service.execution.processes`).
* An interrupt is sent only while the call runs (under the executor's lock); after the call returns, the worker
  takes the same lock, marks the call done and clears any exception still pending for its thread, so an
  interrupt never hits the next call.

Load shedding: a call that must wait for a thread and could not finish within its time limit (its expected wait,
from the running calls' remaining time and the calls queued ahead of it, plus its own service time, by running
estimates per kind of call: :mod:`.shedding`) is refused at once with :class:`Saturated` (503 + ``Retry-After``)
instead of waiting for its 504.

Fairness: calls submitted with ``heavy=True`` (long request classes) run on at most ``heavy_limit`` threads at
once (default ``workers - 1``, at least 1); a free thread takes the oldest queued call it may run, so with two
or more workers a light call never waits for heavy ones.
"""

from __future__ import annotations

import asyncio
import collections
import concurrent.futures
import ctypes
import threading
import time
from collections.abc import Callable
from typing import Any

from tensegrity_opt.timelimit import time_limit

from .executor import Executor, Saturated, SolveTimeout
from .shedding import MARGIN, ServiceTimes, expected_wait, refusal, remaining

__all__ = ["ThreadExecutor", "Call", "Interrupted", "REFIRE_SECONDS"]

#: Seconds between repeats of an interrupt while the interrupted call still runs.
REFIRE_SECONDS = 0.25


class Interrupted(BaseException):
    """Raised inside a worker thread to abandon a call whose caller gave up (time limit, cancel)."""


def _raise_in(thread_id: int, exc: type[BaseException] | None) -> int:
    """Raise ``exc`` asynchronously in the thread ``thread_id`` (``None``: clear a pending one)."""
    try:
        return int(ctypes.pythonapi.PyThreadState_SetAsyncExc(
            ctypes.c_ulong(thread_id), ctypes.py_object(exc) if exc is not None else None))
    except Exception:  # pragma: no cover - not CPython
        return 0


_QUEUED, _RUNNING, _DONE = 0, 1, 2


class Call:
    """One submitted call: its future (the result or the exception) and where it is."""

    __slots__ = ("fn", "args", "future", "state", "thread_id", "cancel_sent", "abandoned", "deadline", "heavy",
                 "kind", "estimate", "started")

    def __init__(self, fn: Callable[..., Any], args: tuple[Any, ...], heavy: bool, timeout: float | None,
                 kind: Any = None, estimate: float = 0.0) -> None:
        self.fn = fn
        self.args = args
        self.heavy = heavy
        self.kind = kind            # what the call is, for the estimate of its service time
        self.estimate = estimate    # that estimate when it was submitted (seconds)
        self.future: concurrent.futures.Future[Any] = concurrent.futures.Future()
        self.state = _QUEUED
        self.thread_id = 0
        self.cancel_sent = False
        self.abandoned = False
        self.started = 0.0          # on the executor's clock (its ServiceTimes'), once running
        # time.monotonic(): the library time limit of the call, set before any worker can see the call
        self.deadline: float | None = None if timeout is None else time.monotonic() + timeout


class ThreadExecutor(Executor):
    """``workers`` solver threads fed by a queue of at most ``queue_size`` waiting calls.

    Parameters
    ----------
    workers, queue_size : int
        Threads, and calls that may wait for one (:class:`Saturated` beyond).
    name : str
        The threads' name prefix (``name-0``, ``name-1`` ...).
    heavy_limit : int, optional
        Threads the ``heavy`` calls may hold at once (default ``workers - 1``, at least 1).
    service_times : ServiceTimes, optional
        The running estimate of the calls' service time that load shedding uses (default: a new one).
    """

    def __init__(self, workers: int, queue_size: int, name: str = "solver", heavy_limit: int | None = None,
                 service_times: ServiceTimes | None = None) -> None:
        if workers < 1 or queue_size < 0:
            raise ValueError("workers must be >= 1 and queue_size >= 0")
        self.heavy_limit = max(1, workers - 1) if heavy_limit is None else max(1, min(heavy_limit, workers))
        self.workers = workers
        self.queue_size = queue_size
        self.name = name
        self._lock = threading.Lock()
        self._cond = threading.Condition(self._lock)
        self._queue: collections.deque[Call] = collections.deque()
        self._threads: list[threading.Thread] = []
        self._pending = 0           # submitted calls not finished yet (queued + running)
        self._running = 0
        self._running_heavy = 0
        self._active: set[Call] = set()
        self._stopping = False
        self._refiring = False
        self.cancelled_running = 0  # calls interrupted in a worker (statistics)
        self.service_times = service_times if service_times is not None else ServiceTimes()
        self.shed = 0               # calls refused by their expected wait (statistics)

    # ------------------------------------------------------------------ lifecycle
    def start(self) -> None:
        with self._lock:
            if self._threads or self._stopping:
                return
            for i in range(self.workers):
                t = threading.Thread(target=self._worker, name=f"{self.name}-{i}", daemon=True)
                self._threads.append(t)
                t.start()

    @property
    def started(self) -> bool:
        return bool(self._threads) and not self._stopping

    def shutdown(self, timeout: float = 0.5, wait: bool = True) -> None:
        """Stop the workers: queued calls are cancelled, running ones are interrupted."""
        with self._cond:
            self._stopping = True
            dropped = list(self._queue)
            self._queue.clear()
            self._cond.notify_all()
        for call in dropped:
            call.future.cancel()
            self._finished()
        with self._lock:
            running = [c for c in self._active if c.state == _RUNNING]
        for call in running:
            self._interrupt(call)
        if wait:
            deadline = time.monotonic() + timeout
            for t in self._threads:
                t.join(max(0.0, deadline - time.monotonic()))

    # ------------------------------------------------------------------ statistics
    @property
    def in_flight(self) -> int:
        """Calls queued or running."""
        return self._pending

    @property
    def running(self) -> int:
        return self._running

    @property
    def queued(self) -> int:
        return len(self._queue)

    @property
    def capacity(self) -> int:
        return self.workers + self.queue_size

    def expected_wait(self, heavy: bool = False) -> float:
        """Seconds a new call of the class ``heavy`` would wait for a thread, by the running estimates
        (:mod:`.shedding`); 0 while a thread is free for it."""
        with self._lock:
            return self._expected_wait(heavy)

    def _expected_wait(self, heavy: bool) -> float:
        # under the lock
        if self._pending < self.workers and (not heavy or self._running_heavy < self.heavy_limit):
            return 0.0
        now = self.service_times.clock()
        running = [c for c in self._active if c.state == _RUNNING]
        busy = [remaining(c.started, c.estimate, now) for c in running]
        if heavy:       # a thread, and one of the heavy share
            return max(expected_wait(busy, [c.estimate for c in self._queue], self.workers),
                       expected_wait([remaining(c.started, c.estimate, now) for c in running if c.heavy],
                                     [c.estimate for c in self._queue if c.heavy], self.heavy_limit))
        # a light call passes the heavy calls that wait for the heavy share of the threads
        room = max(self.heavy_limit - self._running_heavy, 0)
        ahead = []
        for c in self._queue:
            if c.heavy:
                if room == 0:
                    continue
                room -= 1
            ahead.append(c.estimate)
        return expected_wait(busy, ahead, self.workers)

    # ------------------------------------------------------------------ calls
    def submit(self, fn: Callable[..., Any], *args: Any, heavy: bool = False, timeout: float | None = None,
               kind: Any = None) -> Call:
        """Queue ``fn(*args)`` (under the library time limit ``timeout``, if given); raise :class:`Saturated`
        when ``workers + queue_size`` calls are pending, or when the call would wait and could not finish within
        ``timeout`` by the estimates of its ``kind`` and of the calls ahead (:mod:`.shedding`)."""
        call = Call(fn, args, heavy, timeout, kind, self.service_times.estimate(heavy, kind))
        with self._cond:
            if self._stopping:
                raise Saturated("the solver pool is shutting down")
            if self._pending >= self.capacity:
                raise Saturated(f"all {self.workers} solver workers are busy and {self.queue_size} requests are queued")
            if timeout is not None:
                wait = self._expected_wait(heavy)
                if wait > 0.0 and MARGIN * (wait + call.estimate) >= timeout:
                    self.shed += 1
                    raise refusal(f"all {self.workers} solver workers", wait, call.estimate, timeout)
            self._pending += 1
            self._queue.append(call)
            self._cond.notify()
        if not self._threads:
            self.start()
        return call

    async def run(self, fn: Callable[..., Any], *args: Any, timeout: float, heavy: bool = False,
                  kind: Any = None) -> Any:
        """Run ``fn(*args)`` in a worker; raise :class:`SolveTimeout` after ``timeout`` seconds."""
        call = self.submit(fn, *args, heavy=heavy, timeout=timeout, kind=kind)
        try:
            return await asyncio.wait_for(asyncio.wrap_future(call.future), timeout)
        except (asyncio.TimeoutError, TimeoutError):
            self.cancel(call)
            raise SolveTimeout(timeout) from None
        except asyncio.CancelledError:
            # The request itself was cancelled (client gone, shutdown): free the worker too.
            self.cancel(call)
            raise

    def wait(self, call: Call, timeout: float) -> Any:
        """Block until ``call`` ends (a thread's way to :meth:`run`): its result, or its exception; at
        ``timeout`` seconds it is cancelled and awaited (it ends at its next bytecode): :class:`SolveTimeout`
        unless it finished meanwhile. A call cancelled by someone else ends with ``SolveTimeout`` too."""
        try:
            return call.future.result(timeout)
        except concurrent.futures.TimeoutError:
            self.cancel(call)
        except concurrent.futures.CancelledError:
            raise SolveTimeout(timeout) from None
        try:
            return call.future.result()
        except concurrent.futures.CancelledError:
            raise SolveTimeout(timeout) from None

    def cancel(self, call: Call) -> None:
        """Give up ``call``: drop it if still queued, interrupt it if running."""
        if call.future.cancel():
            # Still queued: the worker will skip it; count it as finished now.
            with self._cond:
                try:
                    self._queue.remove(call)
                except ValueError:
                    return
            self._finished()
            return
        self._interrupt(call)

    def _interrupt(self, call: Call) -> None:
        with self._lock:
            if call.state != _RUNNING:
                call.abandoned = True    # between dequeue and start: the worker will skip it
                return
            if call.cancel_sent:
                return
            call.cancel_sent = True
            self.cancelled_running += 1
            _raise_in(call.thread_id, Interrupted)
            if not self._refiring:
                self._refiring = True
                threading.Thread(target=self._refire, name=f"{self.name}-interrupts", daemon=True).start()

    def _refire(self) -> None:
        """Send the interrupt again to the interrupted calls that still run, until none is left."""
        while True:
            time.sleep(REFIRE_SECONDS)
            with self._lock:
                late = [c for c in self._active if c.state == _RUNNING and c.cancel_sent]
                if not late:
                    self._refiring = False
                    return
                for c in late:
                    _raise_in(c.thread_id, Interrupted)

    def _finished(self) -> None:
        with self._lock:
            self._pending -= 1

    # ------------------------------------------------------------------ worker
    def _next(self) -> Call | None:
        with self._cond:
            while True:
                if self._stopping:
                    return None
                q = self._queue
                if q and (not q[0].heavy or self._running_heavy < self.heavy_limit):
                    call = q.popleft()
                else:       # the oldest call this thread may run: a light one while heavy ones wait
                    call = next((c for c in q if not c.heavy), None)
                    if call is not None:
                        q.remove(call)
                if call is not None:
                    if call.heavy:
                        self._running_heavy += 1
                    return call
                self._cond.wait()

    def _heavy_done(self) -> None:
        with self._cond:
            self._running_heavy -= 1
            self._cond.notify()

    def _worker(self) -> None:
        tid = threading.get_ident()
        while True:
            try:
                call = self._next()
            except Interrupted:  # pragma: no cover - a stray interrupt cannot reach here (see _execute)
                continue
            if call is None:
                return
            if not call.future.set_running_or_notify_cancel():
                if call.heavy:
                    self._heavy_done()
                self._finished()
                continue
            ok, value = self._execute(call, tid)
            if call.heavy:
                self._heavy_done()
            # Free the slot before the caller can see the result (a client that got its answer
            # may immediately submit again and must find the capacity).
            self._finished()
            if ok:
                call.future.set_result(value)
            else:
                call.future.set_exception(value)

    def _execute(self, call: Call, tid: int) -> tuple[bool, Any]:
        outcome: tuple[bool, Any]
        try:
            with self._lock:
                if call.abandoned:
                    return False, SolveTimeout(0.0)
                call.thread_id = tid
                call.started = self.service_times.clock()
                call.state = _RUNNING
                self._running += 1
                self._active.add(call)
            if call.deadline is None:
                outcome = (True, call.fn(*call.args))
            else:
                with time_limit(max(call.deadline - time.monotonic(), 1e-6)):
                    outcome = (True, call.fn(*call.args))
        except Interrupted:
            outcome = (False, SolveTimeout(0.0))
        except BaseException as exc:  # noqa: BLE001 - handed to the caller
            outcome = (False, exc)
        self.service_times.record(call.heavy, self.service_times.clock() - call.started, call.kind)
        # Disarm: after this no interrupt can be sent for this call and none is pending.
        while True:
            try:
                with self._lock:
                    if call.state == _RUNNING:
                        call.state = _DONE
                        self._running -= 1
                        self._active.discard(call)
                    if call.cancel_sent:
                        _raise_in(tid, None)
                break
            except Interrupted:
                continue
        return outcome
