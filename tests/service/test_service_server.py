"""The real server process: ``tensegrity-opt serve`` on a free loopback port, called over HTTP."""

from __future__ import annotations

import pytest
from servers import clean_env, free_port, running_server, serve_command
from service_helpers import GENEROUS_ENV, WAIT_SECONDS

import tensegrity_opt as to

httpx = pytest.importorskip("httpx")
pytest.importorskip("uvicorn")


@pytest.mark.slow
def test_serve_over_http():
    env = clean_env(TENSEGRITY_WORKERS="1", TENSEGRITY_MAX_SEGMENTS="50", **GENEROUS_ENV)
    with running_server(serve_command(free_port()), env, timeout=WAIT_SECONDS) as (proc, base):
        with httpx.Client(base_url=base, timeout=WAIT_SECONDS) as client:
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


@pytest.mark.slow
def test_sigterm_is_prompt_with_a_heavy_request_in_flight(tmp_path):
    """SIGTERM with a design request in flight (building its problem alone takes 20-40 s, then minutes of IPOPT)
    ends the server within the shutdown time limit (1 s) and the kill of the solver process: in well under 10 s,
    however loaded the machine, where waiting for the request would take minutes."""
    import signal
    import threading
    import time

    env = clean_env(TENSEGRITY_JOBS_DB=str(tmp_path / "jobs.sqlite3"))
    with running_server(serve_command(free_port()), env, ready="/readyz", timeout=WAIT_SECONDS) as (proc, base):
        heavy = {"manipulator": {"n": 60}, "vary": ["a", "b", "k", "L0"]}      # ~10 s and more of IPOPT

        def post():
            try:
                httpx.post(base + "/v1/design/critical-force", json=heavy, timeout=WAIT_SECONDS)
            except httpx.HTTPError:
                pass

        threading.Thread(target=post, daemon=True).start()
        deadline = time.monotonic() + WAIT_SECONDS
        while httpx.get(base + "/readyz", timeout=WAIT_SECONDS).json()["in_flight"] == 0:
            assert time.monotonic() < deadline
            time.sleep(0.05)
        time.sleep(0.5)
        start = time.monotonic()
        proc.send_signal(signal.SIGTERM)
        proc.wait(WAIT_SECONDS)
        took = time.monotonic() - start
    assert took < 10.0, f"SIGTERM took {took:.2f} s"
