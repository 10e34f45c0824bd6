"""Solver processes for the short requests: the event loop hands them over and stays free for HTTP.

Why a process, and why this lane
--------------------------------
* A short chain's global search (n = 4: ~0.3-0.5 ms of Python and compiled Newton) is as long as
  the HTTP work around it, and a hand-off to a solver thread of :mod:`service.pool` costs
  ~0.1-0.2 ms more, with the search then holding the GIL the event loop needs (it is mostly
  Python). A child process solves on the other core while the loop parses, validates and answers
  the next requests.
* The lane carries only calls that are *bounded* and *deterministic*: the Newton-only search of
  :func:`service.compute.equilibrium_newton_task`, sent by :func:`service.deps.solve` (the one
  dispatcher) only for requests it may settle; it renders its answer there, as a solver thread
  would (:func:`service.responses.render_task`), or returns ``None`` when it finds nothing (the
  request then goes to the pool). Everything else goes to the pool directly.
* Nothing is lost: if the child is not running (starting, crashed, killed), is saturated, or the
  call raises there, :meth:`SolverLane.run` raises :class:`LaneUnavailable` and the caller hands
  the request to the pool (never to the event loop); an exception is thus raised again there with
  its full type and mapped to HTTP like any other. A dead child is restarted
  (at most once every ``RESTART_INTERVAL`` seconds); so is one that answers no call for a whole
  time limit (stuck).
* Protocol: one ``socketpair``. A call is its length and id (big-endian 4 + 8 bytes) and a pickle
  of ``(function, args, kwargs)``; a reply a 4-byte length and a pickle of ``(call id, ok, result)``. The
  child is ``python -m service.lane FD`` (a fresh interpreter, no fork of a threaded server); it
  builds its solvers (warm-up), answers calls in order and exits when the socket closes. A call
  it cannot unpickle or run is answered "failed" (the parent then hands the request to the pool).
"""

from __future__ import annotations

import asyncio
import gc
import logging
import os
import pickle
import socket
import struct
import subprocess
import sys
import time
from collections.abc import Callable
from typing import Any

log = logging.getLogger("service.lane")

__all__ = ["SolverLane", "LaneUnavailable"]

_HEADER = struct.Struct(">I")         # a reply: its length
_CALL = struct.Struct(">Iq")          # a call: its length and id (readable even if the call cannot be unpickled)
RESTART_INTERVAL = 5.0          # seconds between restarts of a child that died


class LaneUnavailable(Exception):
    """The lane cannot take or finish this call: the caller has it run elsewhere (the pool)."""


def _expire(fut: asyncio.Future[Any]) -> None:
    """A call's time limit: its caller gets ``TimeoutError`` (unless the answer came first)."""
    if not fut.done():
        fut.set_exception(asyncio.TimeoutError())


class _Protocol(asyncio.Protocol):
    """The loop's end of the socket: frames in, futures resolved."""

    def __init__(self, lane: SolverLane) -> None:
        self.lane = lane
        self.buffer = bytearray()
        self.transport: asyncio.Transport | None = None

    def connection_made(self, transport: asyncio.BaseTransport) -> None:
        self.transport = transport  # type: ignore[assignment]

    def data_received(self, data: bytes) -> None:
        buf = self.buffer
        buf += data
        start = 0
        end = len(buf)
        while end - start >= 4:
            (size,) = _HEADER.unpack_from(buf, start)
            if end - start - 4 < size:
                break
            call_id, ok, value = pickle.loads(buf[start + 4:start + 4 + size])
            start += 4 + size
            self.lane._resolve(call_id, ok, value)
        if start:
            del buf[:start]

    def connection_lost(self, exc: Exception | None) -> None:
        self.lane._lost(self)


class SolverLane:
    """One solver child process fed over a socket; at most ``max_in_flight`` calls outstanding.

    Parameters
    ----------
    max_in_flight : int
        Calls sent and not answered yet beyond which :meth:`run` refuses (the caller hands the request to the pool).
    env : dict, optional
        Extra environment of the child (the parent's is inherited).
    """

    def __init__(self, max_in_flight: int = 64, env: dict[str, str] | None = None) -> None:
        self.max_in_flight = max_in_flight
        self.env = env
        self._proc: subprocess.Popen[bytes] | None = None
        self._protocol: _Protocol | None = None
        self._sock: socket.socket | None = None     # the loop's end of the socket pair (close: shutdown)
        self._pending: dict[int, asyncio.Future[Any]] = {}
        self._next_id = 0
        self._ready: asyncio.Future[None] | None = None
        self._last_start = -1e9
        self._closing = False
        self._broken = False        # the child never got ready (failed warm-up or start): not restarted
        self.completed = 0          # calls answered by the child (statistics, tests)
        self.restarts = 0

    # ------------------------------------------------------------------ lifecycle
    @property
    def ready(self) -> bool:
        """The child is running and has finished its warm-up."""
        return self._ready is not None and self._ready.done() and not self._ready.cancelled() \
            and self._ready.exception() is None and self._protocol is not None

    async def start(self) -> None:
        """Start the child (returns at once; :meth:`wait_ready` waits for its warm-up)."""
        if self._closing or self._protocol is not None:
            return
        loop = asyncio.get_running_loop()
        self._last_start = time.monotonic()
        parent, child = socket.socketpair()
        try:
            self._proc = subprocess.Popen(
                [sys.executable, "-m", "service.lane", str(child.fileno())], pass_fds=(child.fileno(),),
                env={**os.environ, **(self.env or {})}, stdin=subprocess.DEVNULL)
        except (OSError, ValueError):
            parent.close()
            self._broken = True                 # cannot spawn here: not retried
            raise
        finally:
            child.close()
        self._ready = loop.create_future()
        # The child's first frame (id -1) says it has warmed up.
        self._pending[-1] = self._ready
        _, proto = await loop.create_unix_connection(lambda: _Protocol(self), sock=parent)
        self._protocol = proto
        self._sock = parent

    async def wait_ready(self, timeout: float) -> bool:
        """Wait up to ``timeout`` seconds for the child's warm-up; ``True`` when it is ready."""
        if self._ready is None:
            return False
        try:
            await asyncio.wait_for(asyncio.shield(self._ready), timeout)
        except (asyncio.TimeoutError, TimeoutError, LaneUnavailable):
            return False
        return self.ready

    def close(self) -> None:
        """Stop the child (its socket closes; it exits) and fail the calls still outstanding."""
        self._closing = True
        proto, self._protocol = self._protocol, None
        if proto is not None and proto.transport is not None:
            # The transport closes its socket only at the loop's next iteration, and the wait below
            # blocks the loop: without the shutdown the child saw no end of file and was killed after
            # the whole wait (2 s of every SIGTERM).
            sock = self._sock
            if sock is not None:
                try:
                    sock.shutdown(socket.SHUT_RDWR)    # on the socket, whoever holds a descriptor of it
                except OSError:
                    pass
            proto.transport.close()
        self._sock = None
        self._fail_pending()
        proc, self._proc = self._proc, None
        if proc is not None:
            try:
                proc.wait(0.5)
            except subprocess.TimeoutExpired:       # busy with a call: it is only a cache of solvers
                proc.kill()
                proc.wait(2.0)

    @property
    def pid(self) -> int | None:
        return None if self._proc is None else self._proc.pid

    @property
    def in_flight(self) -> int:
        return sum(1 for k in self._pending if k >= 0)

    # ------------------------------------------------------------------ calls
    async def run(self, fn: Callable[..., Any], *args: Any, timeout: float, **kwargs: Any) -> Any:
        """``fn(*args, **kwargs)`` in the child (``fn`` importable by name, arguments picklable).

        Raises :class:`LaneUnavailable` when the child is not ready, has too many calls, dies
        during the call, or the call raised there; ``asyncio.TimeoutError`` after ``timeout`` (and
        when the child answered no call at all meanwhile, it is killed as stuck and restarted).
        """
        if not self.ready:
            await self._maybe_restart()
            raise LaneUnavailable("the solver process is not ready")
        if len(self._pending) >= self.max_in_flight:
            raise LaneUnavailable("the solver process has too many calls")
        call_id = self._next_id
        self._next_id += 1
        try:
            payload = pickle.dumps((fn, args, kwargs), protocol=pickle.HIGHEST_PROTOCOL)
        except (pickle.PicklingError, TypeError, AttributeError) as exc:
            raise LaneUnavailable(f"the call cannot be sent to the solver process: {exc}") from None
        proto = self._protocol
        if proto is None or proto.transport is None:            # pragma: no cover - ready implies both
            raise LaneUnavailable("the solver process is not connected")
        loop = asyncio.get_running_loop()
        fut: asyncio.Future[Any] = loop.create_future()
        self._pending[call_id] = fut
        progress = self.completed
        proto.transport.write(_CALL.pack(len(payload), call_id) + payload)
        # one timer instead of asyncio.wait_for (which costs ~20 us of loop time per call here)
        timer = loop.call_later(timeout, _expire, fut)
        try:
            return await fut
        except (asyncio.TimeoutError, TimeoutError):
            if self.completed == progress:
                self._kill("answered no call within the time limit")     # stuck: restart it
            raise
        finally:
            timer.cancel()
            self._pending.pop(call_id, None)

    def _kill(self, why: str) -> None:
        """End a child that stopped answering; the closed socket then fails its calls (the callers
        go to the pool) and the next call restarts it."""
        proc = self._proc
        if proc is not None and proc.poll() is None:
            log.warning("solver process %s %s; killing it", proc.pid, why)
            proc.kill()

    def _resolve(self, call_id: int, ok: bool, value: Any) -> None:
        fut = self._pending.pop(call_id, None)
        if call_id >= 0:
            self.completed += 1
        if call_id < 0 and not ok:
            self._broken = True
            log.warning("the solver process failed its warm-up (%s); requests run in the solver threads", value)
        if fut is None or fut.done():
            return
        if ok:
            fut.set_result(value)
        else:
            fut.set_exception(LaneUnavailable(value))

    def _lost(self, proto: _Protocol) -> None:
        was_ready = self.ready
        if self._protocol is proto:
            self._protocol = None
        self._fail_pending()
        proc = self._proc
        if proc is not None and not self._closing:
            try:
                code = proc.wait(1.0)
            except subprocess.TimeoutExpired:
                proc.kill()
                code = proc.wait(1.0)
            if was_ready:
                log.warning("solver process %s exited (status %s); requests run in the solver threads until it "
                            "is restarted", proc.pid, code)
            else:               # it never got ready (cannot import the service, say): not restarted
                self._broken = True
                log.warning("solver process %s exited (status %s) before it was ready; requests run in the "
                            "solver threads", proc.pid, code)
            self._proc = None

    def _fail_pending(self) -> None:
        pending, self._pending = self._pending, {}
        for fut in pending.values():
            if not fut.done():
                fut.set_exception(LaneUnavailable("the solver process stopped"))

    async def _maybe_restart(self) -> None:
        if self._closing or self._broken or self._protocol is not None or self._proc is not None:
            return
        if time.monotonic() - self._last_start < RESTART_INTERVAL:
            return
        self.restarts += 1
        try:
            await self.start()
        except (OSError, ValueError) as exc:    # pragma: no cover - cannot spawn
            log.warning("could not restart the solver process: %r", exc)


# ---------------------------------------------------------------------------- the child
def _send(sock: socket.socket, obj: Any) -> None:
    payload = pickle.dumps(obj, protocol=pickle.HIGHEST_PROTOCOL)
    sock.sendall(_HEADER.pack(len(payload)) + payload)


def child_main(fd: int) -> None:
    """The child: warm up, then answer calls in order until the socket closes."""
    sock = socket.socket(fileno=fd)
    # buffered: when calls queue up (many clients), one read system call takes several of them
    calls = sock.makefile("rb", buffering=1 << 16)
    from .compute import warmup_task

    try:
        warmup_task()
        gc.collect()
        gc.freeze()             # as the server does: full collections skip what start-up built
        _send(sock, (-1, True, None))
    except Exception as exc:  # noqa: BLE001 - reported to the parent, which then uses the pool only
        _send(sock, (-1, False, repr(exc)))
        return
    while True:
        head = calls.read(_CALL.size)
        if len(head) < _CALL.size:
            return
        size, call_id = _CALL.unpack(head)
        body = calls.read(size)
        if len(body) < size:
            return
        try:
            fn, args, kwargs = pickle.loads(body)
            reply = (call_id, True, fn(*args, **kwargs))
        except Exception as exc:  # noqa: BLE001 - the parent has the pool run the request and map the error
            reply = (call_id, False, f"{type(exc).__name__}: {exc}")
        try:
            _send(sock, reply)
        except (pickle.PicklingError, TypeError, AttributeError) as exc:
            _send(sock, (call_id, False, f"unpicklable result: {exc!r}"))


if __name__ == "__main__":
    child_main(int(sys.argv[1]))
