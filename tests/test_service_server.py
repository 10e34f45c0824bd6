"""The real server process: ``tensegrity-opt serve`` on a free loopback port, called over HTTP."""

from __future__ import annotations

import pytest

import tensegrity_opt as to
from servers import clean_env, free_port, running_server, serve_command

httpx = pytest.importorskip("httpx")
pytest.importorskip("uvicorn")


def test_serve_over_http():
    env = clean_env(TENSEGRITY_WORKERS="1", TENSEGRITY_MAX_SEGMENTS="50")
    with running_server(serve_command(free_port()), env) as (proc, base):
        with httpx.Client(base_url=base, timeout=30) as client:
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
    assert proc.returncode is not None
