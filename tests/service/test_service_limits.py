"""Real server processes: a 504 frees its capacity, heavy requests do not starve light ones, and slow
clients (half-sent requests) neither hold sockets for ever nor lock out new clients."""

from __future__ import annotations

import json
import socket
import sys
import threading
import time

import pytest
from servers import clean_env, free_port, running_server, serve_command

httpx = pytest.importorskip("httpx")
pytest.importorskip("uvicorn")

# n = 60 with every variable: the first solve builds a CasADi problem for 20-40 s (one uncuttable call)
HEAVY = {"manipulator": {"n": 60}, "vary": ["a", "b", "k", "L0"]}


def _readyz_in_flight(base: str) -> int:
    return httpx.get(base + "/readyz", timeout=5).json()["in_flight"]


def test_timed_out_design_requests_free_capacity_and_do_not_block_light_ones():
    env = clean_env(TENSEGRITY_SOLVE_TIMEOUT="2", TENSEGRITY_WORKERS="2", TENSEGRITY_WARMUP="false",
                    TENSEGRITY_HEAVY_GRACE="0.5", TENSEGRITY_INLINE_PROCESSES="0")
    with running_server(serve_command(free_port()), env) as (_, base):
        # the design process has started (it imports the library) before the clock starts
        httpx.post(base + "/v1/design/critical-force", json={"manipulator": {"n": 3}, "vary": ["k"]}, timeout=30)
        answers: dict[int, httpx.Response] = {}

        def heavy(i: int) -> None:
            answers[i] = httpx.post(base + "/v1/design/critical-force", json=HEAVY, timeout=30)

        threads = [threading.Thread(target=heavy, args=(i,)) for i in range(2)]
        t0 = time.monotonic()
        for t in threads:
            t.start()
        time.sleep(0.3)
        light = httpx.post(base + "/v1/buckling", json={"manipulator": {"n": 5}}, timeout=30)
        light_time = time.monotonic() - t0
        for t in threads:
            t.join()
        answered = time.monotonic() - t0
        assert light.status_code == 200, light.text
        assert light_time < 2.0                 # answered while both heavy requests were pending
        for r in answers.values():
            assert r.status_code == 504, r.text
            assert r.json()["code"] == "timeout"
        assert answered < 3.5
        # capacity comes back promptly: the stuck design process is killed after the grace period
        while _readyz_in_flight(base) and time.monotonic() - t0 < 30:
            time.sleep(0.05)
        freed = time.monotonic() - t0
        assert _readyz_in_flight(base) == 0
        assert freed - answered < 2.0, f"capacity freed {freed - answered:.1f} s after the 504s"
        # and the replacement process (a fresh interpreter: it imports the library first) answers
        for _ in range(5):
            r = httpx.post(base + "/v1/design/critical-force", json={"manipulator": {"n": 3}, "vary": ["k"]},
                           timeout=30)
            if r.status_code != 504:
                break
        assert r.status_code == 200, r.text


def _limited(cmd: list[str], nofile: int) -> list[str]:
    """``cmd`` run with a descriptor limit of ``nofile``."""
    code = ("import os, resource, sys; resource.setrlimit(resource.RLIMIT_NOFILE, (%d, %d)); "
            "os.execvp(sys.argv[1], sys.argv[1:])" % (nofile, nofile))
    return [sys.executable, "-c", code, *cmd]


def test_half_sent_requests_are_closed_and_do_not_lock_out_new_clients():
    # 128 descriptors: the default connection cap is 64; 150 half-sent requests would exhaust them
    env = clean_env(TENSEGRITY_WORKERS="1", TENSEGRITY_WARMUP="false", TENSEGRITY_INLINE_PROCESSES="0",
                    TENSEGRITY_HEAVY_WORKERS="0", TENSEGRITY_REQUEST_TIMEOUT="1.5")
    port = free_port()
    with running_server(_limited(serve_command(port), 128), env) as (_, base):
        socks = []
        for _ in range(150):
            s = socket.create_connection(("127.0.0.1", port), timeout=5)
            s.sendall(b"POST /v1/equilibrium HTTP/1.1\r\nHost: x\r\nContent-Length: 100\r\n")   # never finished
            socks.append(s)
        time.sleep(0.2)
        t0 = time.monotonic()
        for _ in range(3):
            assert httpx.get(base + "/healthz", timeout=5).status_code == 200
        assert time.monotonic() - t0 < 1.0
        # every half-sent request is closed by the request timeout (or made room for a new client)
        deadline = time.monotonic() + 5.0
        closed = 0
        for s in socks:
            s.settimeout(max(deadline - time.monotonic(), 0.01))
            try:
                data = b""
                while chunk := s.recv(4096):
                    data += chunk
                assert data in (b"",) or data.startswith(b"HTTP/1.1 408")
                closed += 1
            except (TimeoutError, socket.timeout):
                pass
            except ConnectionResetError:
                closed += 1
            finally:
                s.close()
        assert closed == len(socks)
        # a slow but complete request within the timeout is served
        with socket.create_connection(("127.0.0.1", port), timeout=5) as s:
            s.sendall(b"GET /healthz HTTP/1.1\r\n")
            time.sleep(0.5)
            s.sendall(b"Host: x\r\nConnection: close\r\n\r\n")
            assert s.recv(4096).startswith(b"HTTP/1.1 200")
        # malformed HTTP (refused by the parser, before the app): the JSON error shape, not plain text
        for raw in (b"GARBAGE\r\n\r\n", b"GET /healthz HTTP/1.1\r\nHost x\r\n\r\n",
                    b"POST /v1/equilibrium HTTP/1.1\r\nHost: x\r\nContent-Length: -5\r\n\r\n"):
            with socket.create_connection(("127.0.0.1", port), timeout=5) as s:
                s.sendall(raw)
                data = b""
                while chunk := s.recv(4096):
                    data += chunk
            head, _, body = data.partition(b"\r\n\r\n")
            assert head.startswith(b"HTTP/1.1 400") and b"content-type: application/json" in head.lower(), data
            assert json.loads(body)["code"] == "bad_request", data


def test_a_design_solve_stops_itself_at_the_deadline_and_keeps_its_process():
    from fastapi.testclient import TestClient

    from service.config import Settings
    from service.main import create_app

    # n = 16 with every variable: the build takes ~0.2 s, the IPOPT solve ~3 s (cut at 1 s by the
    # library limit inside IPOPT): the process answers by itself, nothing is killed
    with TestClient(create_app(Settings(warmup=False, solve_timeout=1.0, heavy_grace=2.0))) as c:
        heavy = c.app.state.executors.killable
        # the process has started (imported the library: it may take longer than 1 s) before the clock starts
        for _ in range(10):
            if c.post("/v1/design/critical-force", json={"manipulator": {"n": 3}, "vary": ["k"]}).status_code == 200:
                break
        r = c.post("/v1/design/critical-force", json={"manipulator": {"n": 16}, "vary": ["a", "b", "k", "L0"]})
        assert r.status_code == 504 and r.json()["code"] == "timeout"
        t0 = time.monotonic()
        while heavy.in_flight and time.monotonic() - t0 < 5:
            time.sleep(0.02)
        assert heavy.in_flight == 0 and time.monotonic() - t0 < 1.0
        assert heavy.killed == 0
        assert "tensegrity_design_processes_killed 0.0" in c.get("/metrics").text
