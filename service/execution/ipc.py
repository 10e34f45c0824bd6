"""The one protocol between the server and its solver processes: frames over a socketpair.

A frame is a header, the payload's length and the call's id (big-endian ``>Iq``, 12 bytes), then the payload,
a pickle. A call's payload is ``(fn, args, deadline)``: ``fn`` importable by name, ``deadline`` the absolute
``time.monotonic()`` deadline (one clock for every process of the machine) or ``None``; the reply's payload
is ``(ok, value)``: the result, or the exception the call raised (its type and fields survive the trip). The
id is outside the pickle so that a call the child cannot unpickle is still answered (``ok`` false). The first
call of a child (id :data:`WARMUP`) is its warm-up: its reply says the child is ready.

Why this framing: measured against ``multiprocessing.connection`` (the same length prefix, read with
``add_reader`` and a blocking ``recv`` per frame), the frames parsed by an asyncio protocol cost the event
loop ~40 us per small call against ~70 us one call at a time, ~15 us against ~41 us with 32 calls
outstanding (uvloop, 2 cores; ``docs/architecture.md``), and they never block the loop on a large frame.

The child (:func:`serve`, started as ``python -m service.execution.child FD``: a fresh interpreter, no fork
of a threaded server) reads calls in order, runs each under the library time limit of its deadline
(:func:`tensegrity_opt.time_limit`) and writes the reply; it exits when the socket closes.
"""

from __future__ import annotations

import gc
import pickle
import socket
import struct
import time
from typing import Any

from tensegrity_opt.timelimit import time_limit

__all__ = ["FRAME", "WARMUP", "UnreadableReply", "encode", "serve", "ready"]

FRAME = struct.Struct(">Iq")
#: The id of a child's first call, its warm-up.
WARMUP = -1


class UnreadableReply(Exception):
    """A reply that could not be pickled there or unpickled here (a server bug: answered as a 500)."""


def encode(call_id: int, obj: Any) -> bytes:
    """One frame: the header and the pickle of ``obj`` (pickling errors propagate: nothing is sent)."""
    payload = pickle.dumps(obj, protocol=pickle.HIGHEST_PROTOCOL)
    return FRAME.pack(len(payload), call_id) + payload


def _run(body: bytes) -> tuple[bool, Any]:
    try:
        fn, args, deadline = pickle.loads(body)
        if deadline is None:
            return True, fn(*args)
        # the time a call waited in the socket (behind other calls, or while the child started) counts
        with time_limit(max(deadline - time.monotonic(), 1e-6)):
            return True, fn(*args)
    except Exception as exc:  # noqa: BLE001 - handed to the parent with its type
        return False, exc


def serve(fd: int) -> None:
    """The child: answer calls in order until the socket closes."""
    sock = socket.socket(fileno=fd)
    # buffered: when calls queue up (many clients), one read system call takes several of them
    calls = sock.makefile("rb", buffering=1 << 16)
    while True:
        head = calls.read(FRAME.size)
        if len(head) < FRAME.size:
            return
        size, call_id = FRAME.unpack(head)
        body = calls.read(size)
        if len(body) < size:
            return
        reply = _run(body)
        try:
            frame = encode(call_id, reply)
        except Exception as exc:  # noqa: BLE001 - an unpicklable result or exception
            frame = encode(call_id, (False, UnreadableReply(f"unpicklable reply: {type(exc).__name__}: {exc}")))
        try:
            sock.sendall(frame)
        except OSError:                 # the server closed the socket (it stops): nobody waits for the answer
            return
        if call_id == WARMUP and reply[0]:
            # as the server does after its warm-up: full collections skip what start-up built
            gc.collect()
            gc.freeze()


def ready() -> None:
    """The default warm-up: nothing (the child has imported what unpickling the call needed)."""
