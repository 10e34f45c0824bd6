"""Bounded pool of solver threads: the only place where solves run.

Why threads, and why this pool
------------------------------
* Solves are CPU-bound and must never run on the event loop: handlers ``await``
  :meth:`SolverPool.run`, which hands the call to a worker thread.
* The library caches its CasADi solver objects per thread (``threading.local``), so a
  CasADi instance built by one worker is only ever called by that worker, one call at a
  time: no instance is shared between threads.
* Concurrency is bounded: ``workers`` threads and at most ``queue_size`` waiting calls.
  Beyond that :meth:`SolverPool.submit` raises :class:`PoolSaturated` (503 + Retry-After)
  at once instead of letting a backlog grow.
* The time limit is ``asyncio.wait_for`` around the call's future (504). A call still
  queued at its deadline is dropped; a call already running is interrupted: the pool
  raises :class:`SolveCancelled` asynchronously in its worker thread
  (``PyThreadState_SetAsyncExc``). Python delivers it at the thread's next bytecode, i.e.
  after the current CasADi/IPOPT call returns (CasADi calls are never cut in half), so the
  worker is free again shortly after the deadline instead of finishing a solve nobody waits
  for. ``SolveCancelled`` derives from ``BaseException`` so the library's ``except
  Exception``-style handlers do not swallow it.

Before that, the call runs under the library's own time limit (:func:`tensegrity_opt.time_limit`,
the caller's remaining budget): the library checks it before every IPOPT solve, between curve
points and every IPOPT iteration of a design solve, and raises ``TimeLimitError`` (504), so a call
normally stops by itself at its deadline, even inside a long IPOPT solve. What neither can cut is
one long call into compiled code that is not an IPOPT iteration (the first build of a large design
problem): the design endpoints therefore run in killable processes (:mod:`service.heavy`).

A cancel request is sent at most once per call and only while the call runs (under the
pool lock); after the call returns, the worker takes the same lock, marks the call done and
clears any exception still pending for its thread, so a cancel can never hit the next call.
"""

from __future__ import annotations

import asyncio
import collections
import concurrent.futures
import ctypes
import logging
import threading
import time
from collections.abc import Callable
from typing import Any

from tensegrity_opt.timelimit import time_limit

log = logging.getLogger("service.pool")

__all__ = ["SolverPool", "PoolSaturated", "SolveTimeout", "SolveCancelled"]


class PoolSaturated(Exception):
    """Every worker is busy and the queue is full."""


class SolveTimeout(Exception):
    """The call did not finish within its time limit."""

    def __init__(self, timeout: float) -> None:
        super().__init__(f"the solve did not finish within {timeout:g} s")
        self.timeout = timeout


class SolveCancelled(BaseException):
    """Raised inside a worker thread to abandon a call whose caller gave up (time limit)."""


_QUEUED, _RUNNING, _DONE = 0, 1, 2


def _set_async_exc(thread_id: int, exc: type[BaseException] | None) -> int:
    try:
        return int(ctypes.pythonapi.PyThreadState_SetAsyncExc(
            ctypes.c_ulong(thread_id), ctypes.py_object(exc) if exc is not None else None))
    except Exception:  # pragma: no cover - not CPython
        return 0


class _Task:
    __slots__ = ("fn", "args", "future", "state", "thread_id", "cancel_sent", "abandoned", "submitted", "deadline",
                 "heavy")

    def __init__(self, fn: Callable[..., Any], args: tuple[Any, ...], heavy: bool = False,
                 timeout: float | None = None) -> None:
        self.heavy = heavy
        self.fn = fn
        self.args = args
        self.future: concurrent.futures.Future[Any] = concurrent.futures.Future()
        self.state = _QUEUED
        self.thread_id = 0
        self.cancel_sent = False
        self.abandoned = False
        self.submitted = time.monotonic()
        # time.monotonic(): the library time limit of the call, set before any worker can see the task
        self.deadline: float | None = None if timeout is None else self.submitted + timeout


class SolverPool:
    """``workers`` solver threads fed by a queue of at most ``queue_size`` waiting calls.

    Fairness: calls submitted with ``heavy=True`` (long request classes) run on at most
    ``heavy_limit`` threads at once (default ``workers - 1``, at least 1); a free thread takes the
    oldest queued call it may run, so with two or more workers a light call never waits for heavy ones.
    """

    def __init__(self, workers: int, queue_size: int, name: str = "solver", heavy_limit: int | None = None) -> None:
        if workers < 1 or queue_size < 0:
            raise ValueError("workers must be >= 1 and queue_size >= 0")
        self.heavy_limit = max(1, workers - 1) if heavy_limit is None else max(1, min(heavy_limit, workers))
        self._running_heavy = 0
        self.workers = workers
        self.queue_size = queue_size
        self.name = name
        self._lock = threading.Lock()
        self._cond = threading.Condition(self._lock)
        self._queue: collections.deque[_Task] = collections.deque()
        self._threads: list[threading.Thread] = []
        self._pending = 0           # submitted calls not finished yet (queued + running)
        self._running = 0
        self._active: set[_Task] = set()
        self._stopping = False
        self.cancelled_running = 0  # calls interrupted in a worker (statistics)

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

    def shutdown(self, wait: bool = True, timeout: float = 5.0) -> None:
        """Stop the workers: queued calls are cancelled, running ones are interrupted."""
        with self._cond:
            self._stopping = True
            dropped = list(self._queue)
            self._queue.clear()
            self._cond.notify_all()
        for task in dropped:
            task.future.cancel()
            self._finished()
        with self._lock:
            running = [j for j in self._active_tasks() if j.state == _RUNNING]
        for task in running:
            self._cancel_running(task)
        if wait:
            deadline = time.monotonic() + timeout
            for t in self._threads:
                t.join(max(0.0, deadline - time.monotonic()))

    def _active_tasks(self) -> list[_Task]:
        return list(self._active)

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

    # ------------------------------------------------------------------ submission
    def submit(self, fn: Callable[..., Any], *args: Any, heavy: bool = False, timeout: float | None = None) -> _Task:
        """Queue ``fn(*args)`` (under the library time limit ``timeout``, if given); raise
        :class:`PoolSaturated` when ``workers + queue_size`` calls are pending."""
        task = _Task(fn, args, heavy, timeout)
        with self._cond:
            if self._stopping:
                raise PoolSaturated("the solver pool is shutting down")
            if self._pending >= self.capacity:
                raise PoolSaturated(
                    f"all {self.workers} solver workers are busy and {self.queue_size} requests are queued")
            self._pending += 1
            self._queue.append(task)
            self._cond.notify()
        if not self._threads:
            self.start()
        return task

    async def run(self, fn: Callable[..., Any], *args: Any, timeout: float, heavy: bool = False) -> Any:
        """Run ``fn(*args)`` in a worker; raise :class:`SolveTimeout` after ``timeout`` seconds."""
        task = self.submit(fn, *args, heavy=heavy, timeout=timeout)
        fut = asyncio.wrap_future(task.future)
        try:
            return await asyncio.wait_for(fut, timeout)
        except (asyncio.TimeoutError, TimeoutError):
            self.cancel(task)
            raise SolveTimeout(timeout) from None
        except asyncio.CancelledError:
            # The request itself was cancelled (client gone, shutdown): free the worker too.
            self.cancel(task)
            raise

    def cancel(self, task: _Task) -> None:
        """Give up ``task``: drop it if still queued, interrupt it if running."""
        if task.future.cancel():
            # Still queued: the worker will skip it; count it as finished now.
            with self._cond:
                try:
                    self._queue.remove(task)
                except ValueError:
                    return
            self._finished()
            return
        self._cancel_running(task)

    def _cancel_running(self, task: _Task) -> None:
        with self._lock:
            if task.state != _RUNNING:
                task.abandoned = True    # between dequeue and start: the worker will skip it
                return
            if task.cancel_sent:
                return
            task.cancel_sent = True
            self.cancelled_running += 1
            _set_async_exc(task.thread_id, SolveCancelled)

    def _finished(self) -> None:
        with self._lock:
            self._pending -= 1

    # ------------------------------------------------------------------ worker
    def _next(self) -> _Task | None:
        with self._cond:
            while True:
                if self._stopping:
                    return None
                q = self._queue
                if q and (not q[0].heavy or self._running_heavy < self.heavy_limit):
                    task = q.popleft()
                else:       # the oldest call this thread may run: a light one while heavy ones wait
                    task = next((j for j in q if not j.heavy), None)
                    if task is not None:
                        q.remove(task)
                if task is not None:
                    if task.heavy:
                        self._running_heavy += 1
                    return task
                self._cond.wait()

    def _heavy_done(self) -> None:
        with self._cond:
            self._running_heavy -= 1
            self._cond.notify()

    def _worker(self) -> None:
        tid = threading.get_ident()
        while True:
            try:
                task = self._next()
            except SolveCancelled:  # pragma: no cover - a stray cancel cannot reach here (see _finish)
                continue
            if task is None:
                return
            if not task.future.set_running_or_notify_cancel():
                if task.heavy:
                    self._heavy_done()
                self._finished()
                continue
            ok, value = self._execute(task, tid)
            if task.heavy:
                self._heavy_done()
            # Free the slot before the caller can see the result (a client that got its answer
            # may immediately submit again and must find the capacity).
            self._finished()
            if ok:
                task.future.set_result(value)
            else:
                task.future.set_exception(value)

    def _execute(self, task: _Task, tid: int) -> tuple[bool, Any]:
        outcome: tuple[bool, Any]
        try:
            with self._lock:
                if task.abandoned:
                    return False, SolveTimeout(0.0)
                task.thread_id = tid
                task.state = _RUNNING
                self._running += 1
                self._active.add(task)
            if task.deadline is None:
                outcome = (True, task.fn(*task.args))
            else:
                with time_limit(max(task.deadline - time.monotonic(), 1e-6)):
                    outcome = (True, task.fn(*task.args))
        except SolveCancelled:
            outcome = (False, SolveTimeout(0.0))
        except BaseException as exc:  # noqa: BLE001 - handed to the awaiting request
            outcome = (False, exc)
        # Disarm: after this no cancel can be sent for this task and none is pending.
        while True:
            try:
                with self._lock:
                    if task.state == _RUNNING:
                        task.state = _DONE
                        self._running -= 1
                        self._active.discard(task)
                    if task.cancel_sent:
                        _set_async_exc(tid, None)
                break
            except SolveCancelled:
                continue
        return outcome
