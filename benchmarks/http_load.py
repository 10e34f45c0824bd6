"""Closed-loop HTTP load on loopback: ``clients`` concurrent keep-alive connections.

Each client sends a request, waits for the whole response, records the latency and sends the
next one, until the phase ends. The client is a minimal HTTP/1.1 implementation on asyncio
streams: httpx's ``AsyncClient`` tops out at ~200 requests/s on this 2-core machine even for
``GET /healthz`` (measured: p99 > 600 ms for the trivial endpoint), so it would measure itself,
not the server, and make the ``/v1/equilibrium`` vs ``/healthz`` ratio meaningless. This client
sustains several thousand requests/s, so the ratio reflects the server. It runs on uvloop when
installed: it shares the cores with the server, and its CPU per request is interference.

Also: a server started for the run (``own_server``) and a single timed request (``timed_post``).
"""

from __future__ import annotations

import asyncio
import collections
import gc
import json
import os
import signal
import socket
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field

__all__ = ["PhaseStats", "load_phase", "alternating_phases", "load_phase_with_probe", "own_server", "free_port",
           "ServerStartError"]


class ServerStartError(RuntimeError):
    pass


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@contextmanager
def own_server(timeout: float = 60.0, env: dict[str, str] | None = None) -> Iterator[str]:
    """``tensegrity-opt serve`` on a free loopback port; yields its URL once ``/healthz`` answers 200."""
    import httpx

    port = free_port()
    # ``python -m service`` is the console script's code (service.cli), whatever the installed script points at
    cmd = [sys.executable, "-m", "service", "serve", "--host", "127.0.0.1", "--port", str(port), "--no-access-log",
           "--log-level", "warning"]
    log = tempfile.NamedTemporaryFile("w+", prefix="tensegrity-bench-server-", suffix=".log", delete=False)
    proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, env={**os.environ, **(env or {})})
    url = f"http://127.0.0.1:{port}"
    try:
        deadline = time.monotonic() + timeout
        while True:
            if proc.poll() is not None:
                log.flush()
                log.seek(0)
                tail = log.read()[-2000:]
                raise ServerStartError(f"server exited with status {proc.returncode}: {tail.strip()}")
            try:
                if httpx.get(f"{url}/healthz", timeout=2).status_code == 200:
                    break
            except httpx.TransportError:
                pass
            if time.monotonic() > deadline:
                raise ServerStartError(f"server did not answer /healthz within {timeout:g} s")
            time.sleep(0.1)
        yield url
    finally:
        if proc.poll() is None:
            proc.send_signal(signal.SIGINT)
            try:
                proc.wait(15)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait(5)
        log.close()
        try:
            os.unlink(log.name)
        except OSError:
            pass


class _Connection:
    """HTTP/1.1 keep-alive connection on asyncio streams (Content-Length bodies only)."""

    def __init__(self, host: str, port: int) -> None:
        self.host, self.port = host, port
        self.reader: asyncio.StreamReader | None = None
        self.writer: asyncio.StreamWriter | None = None

    async def request(self, method: str, path: str, body: bytes | None) -> tuple[int, bytes]:
        if self.writer is None:
            self.reader, self.writer = await asyncio.open_connection(self.host, self.port)
        head = f"{method} {path} HTTP/1.1\r\nHost: {self.host}:{self.port}\r\n"
        if body is not None:
            head += f"Content-Type: application/json\r\nContent-Length: {len(body)}\r\n"
        self.writer.write(head.encode() + b"\r\n" + (body or b""))
        await self.writer.drain()
        assert self.reader is not None
        raw = await self.reader.readuntil(b"\r\n\r\n")
        lines = raw.decode("latin-1").split("\r\n")
        status = int(lines[0].split()[1])
        length = 0
        close = False
        for line in lines[1:]:
            name, _, value = line.partition(":")
            name = name.strip().lower()
            if name == "content-length":
                length = int(value)
            elif name == "connection" and value.strip().lower() == "close":
                close = True
        payload = await self.reader.readexactly(length)
        if close:
            self.close()
        return status, payload

    def close(self) -> None:
        if self.writer is not None:
            self.writer.close()
        self.reader = self.writer = None


@dataclass
class PhaseStats:
    latencies: list[float] = field(default_factory=list)
    statuses: collections.Counter = field(default_factory=collections.Counter)
    elapsed: float = 0.0

    @property
    def count(self) -> int:
        return len(self.latencies)

    @property
    def throughput(self) -> float:
        return self.count / self.elapsed if self.elapsed > 0 else float("nan")

    def percentile(self, p: float) -> float:
        """Nearest-rank percentile of the latencies (seconds)."""
        lat = sorted(self.latencies)
        if not lat:
            return float("nan")
        return lat[min(len(lat) - 1, max(0, int(-(-p / 100.0 * len(lat) // 1)) - 1))]

    @property
    def errors(self) -> int:
        return sum(v for k, v in self.statuses.items() if k != "200")

    def summary(self) -> dict:
        return {"requests": self.count, "elapsed_s": self.elapsed, "throughput_rps": self.throughput,
                "p50_ms": self.percentile(50) * 1e3, "p90_ms": self.percentile(90) * 1e3,
                "p99_ms": self.percentile(99) * 1e3,
                "max_ms": (max(self.latencies) * 1e3 if self.latencies else float("nan")),
                "errors": self.errors, "statuses": dict(self.statuses)}


RequestFactory = Callable[[int, int], tuple[str, str, bytes | None]]


async def _client(host: str, port: int, idx: int, make: RequestFactory, stop: float, stats: PhaseStats | None,
                  count: int | None = None, every: float = 0.0) -> None:
    """One closed-loop client; ``every`` > 0 paces it (a probe) with that pause between requests."""
    conn = _Connection(host, port)
    k = 0
    try:
        while (time.perf_counter() < stop) if count is None else (k < count):
            method, path, body = make(idx, k)
            k += 1
            t0 = time.perf_counter()
            try:
                status, _ = await conn.request(method, path, body)
                key = str(status)
            except (OSError, asyncio.IncompleteReadError, asyncio.LimitOverrunError, ValueError, IndexError) as exc:
                key = type(exc).__name__
                conn.close()
            if stats is not None:
                stats.latencies.append(time.perf_counter() - t0)
                stats.statuses[key] += 1
            if every:
                await asyncio.sleep(every)
    finally:
        conn.close()


async def _phase(host: str, port: int, make: RequestFactory, clients: int, duration: float,
                 warmup_requests: int) -> PhaseStats:
    if warmup_requests:
        await asyncio.gather(*[_client(host, port, i, make, 0.0, None, count=warmup_requests)
                               for i in range(clients)])
    stats = PhaseStats()
    start = time.perf_counter()
    stop = start + duration
    await asyncio.gather(*[_client(host, port, i, make, stop, stats) for i in range(clients)])
    stats.elapsed = time.perf_counter() - start
    return stats


def load_phase(url: str, make: RequestFactory, clients: int = 32, duration: float = 10.0,
               warmup_requests: int = 2) -> PhaseStats:
    """Run ``clients`` closed-loop keep-alive clients for ``duration`` seconds (after a warm-up)."""
    host, port = _host_port(url)
    return _run(_phase(host, port, make, clients, duration, warmup_requests))


def alternating_phases(url: str, makers: dict[str, RequestFactory], clients: int = 32, duration: float = 10.0,
                       rounds: int = 4) -> dict[str, PhaseStats]:
    """``duration`` seconds of load per request kind, in ``rounds`` alternating phases, merged per kind.

    On a shared machine whose speed drifts over minutes, back-to-back phases of each kind in turn
    expose both kinds to the same conditions, so their throughput ratio does not depend on which
    kind happened to run in a fast minute.
    """
    merged = {name: PhaseStats() for name in makers}
    for _ in range(rounds):
        for name, make in makers.items():
            st = load_phase(url, make, clients, duration / rounds)
            out = merged[name]
            out.latencies.extend(st.latencies)
            out.statuses.update(st.statuses)
            out.elapsed += st.elapsed
    return merged


def load_phase_with_probe(url: str, make: RequestFactory, probe: RequestFactory, clients: int = 32,
                          duration: float = 10.0, every: float = 0.02) -> tuple[PhaseStats, PhaseStats]:
    """Like :func:`load_phase`, plus one paced client (``probe``) measuring latency under that load."""
    host, port = _host_port(url)

    async def both() -> tuple[PhaseStats, PhaseStats]:
        await asyncio.gather(*[_client(host, port, i, make, 0.0, None, count=2) for i in range(clients)])
        stats, probe_stats = PhaseStats(), PhaseStats()
        start = time.perf_counter()
        stop = start + duration
        await asyncio.gather(*[_client(host, port, i, make, stop, stats) for i in range(clients)],
                             _client(host, port, 0, probe, stop, probe_stats, every=every))
        stats.elapsed = probe_stats.elapsed = time.perf_counter() - start
        return stats, probe_stats

    return _run(both())


def _run(coro):
    """Run the load on uvloop when it is installed (the service depends on it), else asyncio's loop,
    with the garbage collector paused.

    The load generator shares the machine's cores with the server under test, so its own CPU per
    request is interference with the measurement; uvloop's event loop is C, asyncio's mostly Python.
    A full collection in this process (the benchmark suite holds large heaps) took 20-30 ms, which
    the clients waiting on it would have counted as server latency; the requests' own garbage is
    freed by reference counting.
    """
    try:
        import uvloop
        run = uvloop.run
    except ImportError:
        run = asyncio.run
    enabled = gc.isenabled()
    gc.disable()
    try:
        return run(coro)
    finally:
        if enabled:
            gc.enable()


def _host_port(url: str) -> tuple[str, int]:
    host_port = url.split("://", 1)[-1].rstrip("/")
    host, _, port = host_port.partition(":")
    return host, int(port or 80)


def json_body(obj) -> bytes:
    return json.dumps(obj, separators=(",", ":")).encode()
