"""A stand-in for the library's clock, so that a test of a time limit does not depend on the machine's speed.

Every time limit of the library (``to.time_limit``, the ``timeout=`` arguments, the service's soft deadline passed
on as a ``timeout``) is read from one clock, ``time.monotonic()`` in :mod:`tensegrity_opt.timelimit`.
:func:`tick_clock` replaces that clock by a :class:`TickClock`, which ignores the wall time and moves on by a
fixed ``step`` at every reading: a limit of ``T`` seconds then runs out after about ``T / step`` readings of the
clock (the library reads it once per check: before each IPOPT solve, each target, each point, each step), the same
number on a fast machine and on a loaded one. A test of a limit chooses ``T / step`` well above the readings its
first unit of work takes and well below those of the whole computation, and asserts that the answer is cut in
between: partial, with what was done before the limit.
"""

from __future__ import annotations

import threading

import pytest

from tensegrity_opt import timelimit


class TickClock:
    """``monotonic()`` moves on by ``step`` seconds at every call; ``readings`` counts the calls."""

    def __init__(self, step: float = 1.0, start: float = 1000.0):
        self.step = float(step)
        self.now = float(start)
        self.readings = 0
        self._lock = threading.Lock()

    def monotonic(self) -> float:
        with self._lock:
            self.readings += 1
            self.now += self.step
            return self.now


def tick_clock(monkeypatch: pytest.MonkeyPatch, step: float = 1.0) -> TickClock:
    """Put a :class:`TickClock` in place of the library's clock for the rest of the test."""
    clock = TickClock(step)
    assert hasattr(timelimit, "time") and callable(timelimit.time.monotonic), \
        "tensegrity_opt.timelimit reads its clock elsewhere: update tests/support/clocks.py"
    monkeypatch.setattr(timelimit, "time", clock)
    return clock
