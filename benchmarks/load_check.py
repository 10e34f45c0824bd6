#!/usr/bin/env python3
"""Load check of the HTTP service (not a timed test).

Drives ``--clients`` concurrent keep-alive clients (default 32) at ``POST /v1/equilibrium``
(the paper's chain, n = 4) on loopback for ``--duration`` seconds (default 10), then the same at
``GET /healthz`` for comparison, and prints requests/s, p50/p99/max latency and error counts.
While the solve phase runs, one extra probe measures ``/healthz`` latency under load (how
responsive the event loop stays while the solver threads work).

By default it starts its own server (``tensegrity-opt serve`` on a free loopback port, settings
from the environment, e.g. ``TENSEGRITY_WORKERS``) and stops it afterwards; ``--url`` targets a
running one instead.

    python benchmarks/load_check.py                     # own server, 32 clients, 10 s per phase
    python benchmarks/load_check.py --url http://127.0.0.1:8000 --duration 5
"""

from __future__ import annotations

import argparse
import asyncio
import collections
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import time
from contextlib import contextmanager

import httpx

PAPER = {"manipulator": {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}, "dx": 0.1, "dy": 0.0}


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@contextmanager
def own_server(workers: int | None):
    port = _free_port()
    exe = shutil.which("tensegrity-opt")
    cmd = [exe] if exe else [sys.executable, "-m", "tensegrity_opt.cli"]
    cmd += ["serve", "--host", "127.0.0.1", "--port", str(port), "--no-access-log", "--log-level", "warning"]
    env = dict(os.environ)
    if workers is not None:
        env["TENSEGRITY_WORKERS"] = str(workers)
    proc = subprocess.Popen(cmd, env=env)
    url = f"http://127.0.0.1:{port}"
    try:
        deadline = time.monotonic() + 60
        while True:
            if proc.poll() is not None:
                raise SystemExit(f"server exited with status {proc.returncode}")
            try:
                if httpx.get(f"{url}/readyz", timeout=2).status_code == 200:
                    break
            except httpx.TransportError:
                pass
            if time.monotonic() > deadline:
                raise SystemExit("server did not become ready within 60 s")
            time.sleep(0.1)
        yield url
    finally:
        proc.send_signal(signal.SIGINT)
        try:
            proc.wait(15)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait(5)


class Stats:
    def __init__(self) -> None:
        self.latencies: list[float] = []
        self.statuses: collections.Counter[str] = collections.Counter()

    def add(self, seconds: float, status: str) -> None:
        self.latencies.append(seconds)
        self.statuses[status] += 1

    def line(self, label: str, elapsed: float) -> str:
        lat = sorted(self.latencies)
        n = len(lat)

        def pct(p: float) -> float:
            return lat[min(n - 1, int(round(p / 100 * (n - 1))))] * 1000 if n else float("nan")

        ok = self.statuses.get("200", 0)
        errors = {k: v for k, v in sorted(self.statuses.items()) if k != "200"}
        return (f"{label:<28} {n:>7} req  {n / elapsed:>8.1f} req/s  p50 {pct(50):>7.2f} ms  p99 {pct(99):>7.2f} ms  "
                f"max {(lat[-1] * 1000 if n else float('nan')):>8.2f} ms  ok {ok}  errors {sum(errors.values())}"
                + (f" {dict(errors)}" if errors else ""))


class Connection:
    """A minimal HTTP/1.1 keep-alive client on asyncio streams.

    The load generator must cost much less than the server per request: httpx's async pool
    tops out at a few hundred requests/s on one core, which would measure the client.
    """

    def __init__(self, host: str, port: int) -> None:
        self.host, self.port = host, port
        self.reader: asyncio.StreamReader | None = None
        self.writer: asyncio.StreamWriter | None = None

    async def request(self, method: str, path: str, body: bytes | None) -> int:
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
            if name.lower() == "content-length":
                length = int(value)
            elif name.lower() == "connection" and value.strip().lower() == "close":
                close = True
        await self.reader.readexactly(length)
        if close:
            self.close()
        return status

    def close(self) -> None:
        if self.writer is not None:
            self.writer.close()
        self.reader = self.writer = None


async def _client(host: str, port: int, method: str, path: str, body: bytes | None, stop: float,
                  stats: Stats, every: float = 0.0) -> None:
    conn = Connection(host, port)
    try:
        while time.perf_counter() < stop:
            t0 = time.perf_counter()
            try:
                status = str(await conn.request(method, path, body))
            except (OSError, asyncio.IncompleteReadError, ValueError, IndexError) as exc:
                status = type(exc).__name__
                conn.close()
            stats.add(time.perf_counter() - t0, status)
            if every:
                await asyncio.sleep(every)
    finally:
        conn.close()


async def phase(url: str, method: str, path: str, body: dict | None, clients: int, duration: float,
                probe: bool) -> tuple[Stats, Stats | None, float]:
    parts = httpx.URL(url)
    host, port = parts.host, parts.port or 80
    payload = json.dumps(body).encode() if body is not None else None
    # warm-up: one request per client
    await asyncio.gather(*[_client(host, port, method, path, payload, 0.0, Stats()) for _ in range(1)])
    stats = Stats()
    probe_stats = Stats() if probe else None
    start = time.perf_counter()
    stop = start + duration
    tasks = [_client(host, port, method, path, payload, stop, stats) for _ in range(clients)]
    if probe_stats is not None:
        tasks.append(_client(host, port, "GET", "/healthz", None, stop, probe_stats, every=0.02))
    await asyncio.gather(*tasks)
    return stats, probe_stats, time.perf_counter() - start


def run(url: str, clients: int, duration: float) -> None:
    info = httpx.get(f"{url}/version", timeout=10).json()
    lim = info.get("limits", {})
    print(f"tensegrity-opt service {info.get('version')} at {url}: workers={lim.get('workers')} "
          f"queue={lim.get('queue_size')}; {clients} concurrent keep-alive clients, {duration:g} s per phase")
    eq, probe, el = asyncio.run(phase(url, "POST", "/v1/equilibrium", PAPER, clients, duration, probe=True))
    print(eq.line("POST /v1/equilibrium (n=4)", el))
    if probe is not None:
        print(probe.line("  GET /healthz during solves", el))
    hz, _, el = asyncio.run(phase(url, "GET", "/healthz", None, clients, duration, probe=False))
    print(hz.line("GET /healthz", el))


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--url", help="a running server (default: start one on a free loopback port)")
    p.add_argument("--clients", type=int, default=32)
    p.add_argument("--duration", type=float, default=10.0, help="seconds per phase (default 10)")
    p.add_argument("--workers", type=int, default=None, help="TENSEGRITY_WORKERS for the server it starts")
    args = p.parse_args(argv)
    if args.url:
        run(args.url.rstrip("/"), args.clients, args.duration)
    else:
        with own_server(args.workers) as url:
            run(url, args.clients, args.duration)
    return 0


if __name__ == "__main__":
    sys.exit(main())
