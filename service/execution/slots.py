"""Stream slots: one solver thread per open control stream (``/v1/control/stream``).

Each stream holds one slot for its lifetime: a one-thread :class:`~service.execution.threads.ThreadExecutor`
(the time limit, the interrupt of a call past it), so a stream's steps run in order on one thread whose CasADi
instances stay warm, and one slow stream never delays another (nor the REST requests, which have their own
threads). At most ``size`` streams hold a slot at once.
"""

from __future__ import annotations

from .threads import ThreadExecutor

__all__ = ["StreamSlots"]


class StreamSlots:
    """At most ``size`` slots. Threads are made on demand and kept (their CasADi instances stay built); a free
    slot is reused most-recent first. Used from the event loop only."""

    def __init__(self, size: int) -> None:
        self.size = size
        self._all: list[ThreadExecutor] = []
        self._free: list[ThreadExecutor] = []

    @property
    def in_use(self) -> int:
        return len(self._all) - len(self._free)

    def acquire(self) -> ThreadExecutor | None:
        """A slot, or ``None`` when ``size`` streams hold one. An idle thread first: a stream that closed
        after a step past its time limit may have left its thread still finishing that call (a CasADi call
        is not cut), and a new stream must not wait behind it."""
        for i in range(len(self._free) - 1, -1, -1):
            if self._free[i].in_flight == 0:
                return self._free.pop(i)
        if len(self._all) >= self.size:
            return self._free.pop() if self._free else None
        # one worker, one queued call: a call past its time limit may still be finishing when the next
        # step arrives; that step waits behind it on the same thread (a stream's state is never used by
        # two threads at once)
        slot = ThreadExecutor(1, 1, name=f"stream-{len(self._all)}")
        slot.start()
        self._all.append(slot)
        return slot

    def release(self, slot: ThreadExecutor) -> None:
        self._free.append(slot)

    def shutdown(self, timeout: float = 0.5) -> None:
        for slot in self._all:
            slot.shutdown(wait=False)
        for slot in self._all:
            slot.shutdown(timeout / max(len(self._all), 1))
