"""Load shedding by the expected wait: a call that cannot finish (or not even start) before its deadline is
refused at once.

A bounded queue alone refuses too late: with 32 clients and a queue of 64 every call is queued, and when the calls
ahead take longer than the time limit the last ones wait the whole limit for a 504. An executor therefore keeps
running estimates of its calls' service time (:class:`ServiceTimes`: exponentially weighted means of the durations
of the calls that ended, per kind of call and per class, light and heavy) and, when a call has to wait, estimates
that wait (:func:`expected_wait`: the running calls' remaining time and the estimates of the calls queued ahead of
it, each on the worker free first). A call whose expected wait plus its own estimate, times :data:`MARGIN`, reaches
its time limit is
refused with :class:`~service.execution.executor.Saturated` (503 with ``Retry-After``: the seconds by which it
would miss the limit, at least the server's setting), the same refusal as a full queue. A call that finds a free
worker is never refused by an estimate; until calls have ended the estimates are 0 and only the queue's length
refuses."""

from __future__ import annotations

import heapq
import math
import threading
import time
from collections.abc import Callable, Hashable, Iterable

from .executor import Saturated

__all__ = ["ServiceTimes", "expected_wait", "remaining", "refusal", "WEIGHT", "MARGIN"]

#: Weight of the last call in the running estimate (the mean of about the last ``1 / WEIGHT`` calls).
WEIGHT = 0.2
#: Factor on the estimated wait and solve before they are compared with the time limit: the waits of a loaded
#: server came out up to ~30 % longer than estimated (benchmarks/overload_check.py), and a call admitted with less
#: slack than that mostly ended in a 504.
MARGIN = 1.25


class ServiceTimes:
    """Running estimates of a call's service time (seconds), per kind of call (a task's name) and per class
    (``heavy`` or light: the estimate of a kind not seen yet).

    Parameters
    ----------
    weight : float
        Weight of the newest duration (:data:`WEIGHT`).
    clock : callable
        The clock the executor measures its calls with (``time.monotonic``; tests give a stand-in).
    """

    #: Most kinds kept (the service's tasks are a few dozen; beyond, the class's estimate answers).
    MAX_KINDS = 256

    def __init__(self, weight: float = WEIGHT, clock: Callable[[], float] = time.monotonic) -> None:
        self.weight = weight
        self.clock = clock
        self._lock = threading.Lock()
        self._mean: dict[Hashable, float] = {}

    def _update(self, key: Hashable, seconds: float) -> None:
        old = self._mean.get(key)
        if old is not None:
            self._mean[key] = old + self.weight * (seconds - old)
        elif len(self._mean) < self.MAX_KINDS or isinstance(key, bool):
            self._mean[key] = seconds

    def record(self, heavy: bool, seconds: float, kind: Hashable = None) -> None:
        """A call of the class ``heavy`` (and of ``kind``, when given) took ``seconds``."""
        seconds = max(float(seconds), 0.0)
        with self._lock:
            self._update(bool(heavy), seconds)
            if kind is not None:
                self._update(("kind", kind), seconds)

    def set(self, heavy: bool, seconds: float, kind: Hashable = None) -> None:
        """Put an estimate in place (of ``kind``, else of the class): a stand-in's duration in tests."""
        with self._lock:
            self._mean[("kind", kind) if kind is not None else bool(heavy)] = max(float(seconds), 0.0)

    def estimate(self, heavy: bool, kind: Hashable = None) -> float:
        """The estimate of ``kind``, else of the class (0 until a call of it has ended)."""
        mean = self._mean
        if kind is not None:
            value = mean.get(("kind", kind))
            if value is not None:
                return value
        return mean.get(bool(heavy), 0.0)


def expected_wait(busy: Iterable[float], queued: Iterable[float], servers: int) -> float:
    """Seconds until a new call may start on one of ``servers``: ``busy`` holds the remaining work (seconds) of
    each busy server, ``queued`` the estimates of the calls ahead of it in the order they start; each goes to the
    server free first (list scheduling), and the new call gets the first one free after them."""
    free = sorted(max(b, 0.0) for b in busy)[:max(servers, 1)]
    free += [0.0] * (max(servers, 1) - len(free))
    heapq.heapify(free)
    for estimate in queued:
        heapq.heapreplace(free, free[0] + estimate)
    return free[0]


def remaining(started: float, estimate: float, now: float) -> float:
    """A running call's remaining work by its class's estimate: what it has not run of it yet (at least 0)."""
    return max(started + estimate - now, 0.0)


def refusal(what: str, wait: float, own: float, timeout: float) -> Saturated:
    """The refusal of a call that would wait ``wait`` seconds and then run ``own`` (estimates) under the time limit
    ``timeout``."""
    exc = Saturated(f"{what} are busy: the expected wait ({wait:.3g} s) and solve ({own:.3g} s) exceed the "
                    f"request's time limit ({timeout:g} s)")
    exc.retry_after = math.ceil(max(MARGIN * (wait + own) - timeout, 1.0))
    return exc
