#!/usr/bin/env python3
"""The server's edges under a hostile client (not a timed test): shutdown, headers, pipelining, WebSocket origins.

Each reproducer starts its own server (``python -m service serve`` on a free loopback port, from the code on
``sys.path``: run it with ``PYTHONPATH=<a checkout>`` to measure another tree) and prints what it saw:

* ``shutdown``: an n = 200 force-deflection curve (500 points) and an n = 150 ``/v1/equilibria`` in flight,
  SIGTERM after 1.5 s: the status, content type and ``Retry-After`` of each answer, and the time to exit.
* ``headers``: one request with an 8 MB header (its status), then 20 connections each sending 16 MB of headers
  that never end: the server's RSS before and after (``/proc/<pid>/status``).
* ``pipelining``: 100 connections each pipelining 20 ``GET /openapi.json`` (read to the end), while a probe
  times ``GET /healthz`` (10 s timeout per probe): the probes' count, timeouts, median and maximum latency.
* ``origin``: a WebSocket upgrade of ``/v1/control/stream`` with ``Origin: http://evil.example``: the answer.

    python benchmarks/server_edges.py shutdown headers pipelining origin
    PYTHONPATH=/tmp/main-checkout python benchmarks/server_edges.py pipelining
"""

from __future__ import annotations

import argparse
import os
import selectors
import signal
import socket
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager

import httpx


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@contextmanager
def server(**env: str) -> Iterator[tuple[subprocess.Popen, int]]:
    """``python -m service serve`` on a free port with ``env`` (its jobs database in a temporary folder)."""
    port = _free_port()
    tmp = tempfile.mkdtemp(prefix="tensegrity-edges-")
    full = {k: v for k, v in os.environ.items() if not k.startswith("TENSEGRITY_")}
    full.update({"TENSEGRITY_JOBS_DB": os.path.join(tmp, "jobs.sqlite3"), **env})
    log = open(os.path.join(tmp, "server.log"), "w+")
    proc = subprocess.Popen([sys.executable, "-m", "service", "serve", "--port", str(port), "--no-access-log",
                             "--log-level", "warning"], env=full, stdout=log, stderr=subprocess.STDOUT, cwd=tmp)
    try:
        deadline = time.monotonic() + 600
        while True:
            if proc.poll() is not None:
                log.seek(0)
                raise RuntimeError(f"server exited: {log.read()[-2000:]}")
            try:
                if httpx.get(f"http://127.0.0.1:{port}/readyz", timeout=5).status_code == 200:
                    break
            except httpx.TransportError:
                pass
            if time.monotonic() > deadline:
                raise RuntimeError("server not ready in 600 s")
            time.sleep(0.1)
        yield proc, port
    finally:
        if proc.poll() is None:
            proc.send_signal(signal.SIGINT)
            try:
                proc.wait(15)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()
        log.close()


def rss_mb(pid: int) -> float:
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024
    return float("nan")


# ------------------------------------------------------------------------------------------------ shutdown
def shutdown() -> None:
    requests = {"curve n=200": ("/v1/force-deflection", {"manipulator": {"n": 200},
                                                         "dx": {"start": 0.0, "stop": 50.0, "num": 500}}),
                "equilibria n=150": ("/v1/equilibria", {"manipulator": {"n": 150}, "dx": 5.0})}
    with server() as (proc, port):
        answers: dict[str, str] = {}

        def post(name: str, path: str, body: dict) -> None:
            try:
                r = httpx.post(f"http://127.0.0.1:{port}{path}", json=body, timeout=120)
                answers[name] = (f"{r.status_code} {r.headers.get('content-type')} retry-after="
                                 f"{r.headers.get('retry-after')} {r.text[:90]!r}")
            except httpx.HTTPError as exc:
                answers[name] = f"{type(exc).__name__}: {exc}"

        threads = [threading.Thread(target=post, args=(k, *v)) for k, v in requests.items()]
        for t in threads:
            t.start()
        time.sleep(1.5)
        start = time.monotonic()
        proc.send_signal(signal.SIGTERM)
        proc.wait(60)
        took = time.monotonic() - start
        for t in threads:
            t.join()
    print(f"shutdown: exit {proc.returncode} after {took:.2f} s")
    for k, v in answers.items():
        print(f"  {k}: {v}")


# ------------------------------------------------------------------------------------------------ headers
def _head_status(port: int, header_bytes: int) -> str:
    with socket.create_connection(("127.0.0.1", port)) as s:
        s.settimeout(60)
        try:
            s.sendall(b"GET /healthz HTTP/1.1\r\nHost: x\r\nX-Big: " + b"a" * header_bytes + b"\r\n\r\n")
        except OSError as exc:
            return f"send failed: {exc}"
        try:
            data = s.recv(4096)
        except OSError as exc:
            return f"recv failed: {exc}"
        return data.split(b"\r\n", 1)[0].decode(errors="replace") or "(closed)"


def headers() -> None:
    with server() as (proc, port):
        print(f"headers: 8 MB header -> {_head_status(port, 8 << 20)}")
        before = rss_mb(proc.pid)
        socks = []
        chunk = b"b" * (1 << 20)
        cut = 0
        for _ in range(20):
            s = socket.create_connection(("127.0.0.1", port))
            s.settimeout(30)
            socks.append(s)
            try:
                s.sendall(b"GET /healthz HTTP/1.1\r\nHost: x\r\nX-Big: ")
                for _ in range(16):
                    s.sendall(chunk)
            except OSError:
                cut += 1                        # the server closed it
        time.sleep(1.0)
        after = rss_mb(proc.pid)
        alive = httpx.get(f"http://127.0.0.1:{port}/healthz", timeout=30).status_code
        for s in socks:
            s.close()
    print(f"headers: 20 x 16 MB unfinished headers: RSS {before:.0f} -> {after:.0f} MB (+{after - before:.0f}), "
          f"{cut} of 20 connections cut by the server, /healthz {alive}")


# ------------------------------------------------------------------------------------------------ pipelining
def _attack(port: int, connections: int, depth: int, path: str, done: threading.Event) -> tuple[int, float]:
    """``connections`` sockets each pipelining ``depth`` GETs of ``path`` (the last with Connection: close),
    read to the end; (bytes read, seconds)."""
    sel = selectors.DefaultSelector()
    req = f"GET {path} HTTP/1.1\r\nHost: x\r\n\r\n".encode()
    last = f"GET {path} HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n".encode()
    start = time.monotonic()
    for _ in range(connections):
        s = socket.create_connection(("127.0.0.1", port))
        s.sendall(req * (depth - 1) + last)
        s.setblocking(False)
        sel.register(s, selectors.EVENT_READ)
    total, open_ = 0, connections
    while open_:
        for key, _ in sel.select(timeout=120):
            try:
                data = key.fileobj.recv(1 << 20)
            except (BlockingIOError, InterruptedError):
                continue
            except OSError:
                data = b""
            if not data:
                sel.unregister(key.fileobj)
                key.fileobj.close()
                open_ -= 1
            total += len(data)
    done.set()
    return total, time.monotonic() - start


def pipelining(path: str = "/openapi.json") -> None:
    with server() as (_, port):
        done = threading.Event()
        lat: list[float] = []
        timeouts = 0

        def probe() -> None:
            nonlocal timeouts
            with httpx.Client(timeout=10) as c:
                while not done.is_set():
                    t = time.monotonic()
                    try:
                        c.get(f"http://127.0.0.1:{port}/healthz")
                        lat.append(time.monotonic() - t)
                    except httpx.HTTPError:
                        timeouts += 1
                    time.sleep(0.05)

        p = threading.Thread(target=probe)
        p.start()
        total, took = _attack(port, 100, 20, path, done)
        p.join()
    med = statistics.median(lat) * 1e3 if lat else float("nan")
    print(f"pipelining {path}: 100 x 20 requests, {total / 1e6:.0f} MB in {took:.1f} s; /healthz probes "
          f"{len(lat)} answered, {timeouts} timed out (10 s), median {med:.1f} ms, max "
          f"{max(lat, default=float('nan')) * 1e3:.0f} ms")


# ------------------------------------------------------------------------------------------------ origin
def origin() -> None:
    with server() as (_, port):
        with socket.create_connection(("127.0.0.1", port)) as s:
            s.settimeout(30)
            s.sendall(b"GET /v1/control/stream HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nUpgrade: websocket\r\n"
                      b"Connection: Upgrade\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n"
                      b"Sec-WebSocket-Version: 13\r\nOrigin: http://evil.example\r\n\r\n" % port)
            data = s.recv(4096)
    status = data.split(b"\r\n", 1)[0].decode()
    print(f"origin: ws upgrade from http://evil.example -> {status}")


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("what", nargs="+", choices=("shutdown", "headers", "pipelining", "version", "origin"))
    args = p.parse_args(argv)
    import service
    print(f"service from {os.path.dirname(service.__file__)}")
    for what in args.what:
        if what == "version":
            pipelining("/version")
        else:
            globals()[what]()
    return 0


if __name__ == "__main__":
    sys.exit(main())
