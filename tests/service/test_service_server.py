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


def test_sigterm_is_prompt_with_a_heavy_request_in_flight(tmp_path):
    """SIGTERM used to take 4-15 s: uvicorn waited for the request's solve, the solver process was
    killed only after a 2 s wait (its socket closed late), the pool waited 5 s for its threads."""
    import signal
    import threading
    import time

    env = clean_env(TENSEGRITY_JOBS_DB=str(tmp_path / "jobs.sqlite3"))
    with running_server(serve_command(free_port()), env, ready="/readyz") as (proc, base):
        heavy = {"manipulator": {"n": 60}, "vary": ["a", "b", "k", "L0"]}      # ~10 s and more of IPOPT

        def post():
            try:
                httpx.post(base + "/v1/design/critical-force", json=heavy, timeout=60)
            except httpx.HTTPError:
                pass

        threading.Thread(target=post, daemon=True).start()
        deadline = time.monotonic() + 10
        while httpx.get(base + "/readyz").json()["in_flight"] == 0 and time.monotonic() < deadline:
            time.sleep(0.05)
        time.sleep(0.5)
        start = time.monotonic()
        proc.send_signal(signal.SIGTERM)
        proc.wait(30)
        took = time.monotonic() - start
    assert took < 3.0, f"SIGTERM took {took:.2f} s"
