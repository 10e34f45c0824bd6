"""The real server process: ``tensegrity-opt serve`` on a free loopback port, called over HTTP."""

from __future__ import annotations

import os
import shutil
import signal
import socket
import subprocess
import sys
import time

import pytest

import tensegrity_opt as to

httpx = pytest.importorskip("httpx")
pytest.importorskip("uvicorn")


def free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def serve_command(port: int) -> list[str]:
    exe = shutil.which("tensegrity-opt")
    base = [exe] if exe else [sys.executable, "-m", "tensegrity_opt.cli"]
    return [*base, "serve", "--host", "127.0.0.1", "--port", str(port), "--no-access-log", "--log-level", "warning"]


def test_serve_over_http():
    port = free_port()
    env = {k: v for k, v in os.environ.items() if not k.startswith("TENSEGRITY_")}
    env.update({"TENSEGRITY_WORKERS": "1", "TENSEGRITY_MAX_SEGMENTS": "50"})
    proc = subprocess.Popen(serve_command(port), env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    base = f"http://127.0.0.1:{port}"
    try:
        deadline = time.monotonic() + 60
        with httpx.Client(base_url=base, timeout=30) as client:
            while True:
                assert proc.poll() is None, proc.stdout.read().decode(errors="replace")
                try:
                    if client.get("/healthz").status_code == 200:
                        break
                except httpx.TransportError:
                    pass
                assert time.monotonic() < deadline, "server did not come up"
                time.sleep(0.1)
            r = client.post("/v1/equilibrium", json={"manipulator": {"n": 4, "a": 1, "b": 1, "k": 1, "L0": 1},
                                                     "dx": 0.1, "dy": 0.0})
            assert r.status_code == 200, r.text
            eq = to.solve_equilibrium(to.Manipulator.uniform(4), 0.1, 0.0)
            assert r.json()["q"] == pytest.approx(eq.q.tolist(), rel=1e-9, abs=1e-12)
            assert r.json()["force"]["fx"] == pytest.approx(eq.fx, rel=1e-9)
            assert client.get("/version").json()["limits"]["max_segments"] == 50    # settings from the environment
            r = client.post("/v1/equilibrium", json={"manipulator": {"n": 51}, "dx": 0.1})
            assert r.status_code == 422 and r.json()["code"] == "too_many_segments"
            assert "tensegrity_http_requests_total" in client.get("/metrics").text
    finally:
        proc.send_signal(signal.SIGINT)
        try:
            proc.wait(15)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait(5)
    assert proc.returncode is not None
