"""The real server process: ``tensegrity-opt serve`` on a free loopback port, called over HTTP; its shutdown."""

from __future__ import annotations

import asyncio
import json
import signal
import threading
import time

import pytest
from servers import clean_env, free_port, running_server, serve_command, uvicorn_factory_command
from service_helpers import GENEROUS_ENV, WAIT_SECONDS
from stand_ins import NEVER_ENDING_SEGMENTS, server_env

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


def test_a_cancelled_request_is_answered_503_shutting_down():
    """The shutdown's answer without a server: a request whose task is cancelled before its answer started gets the
    JSON 503 with Retry-After; one cancelled after its answer started is cut (the cancellation goes on)."""
    from service.api.errors import ShutdownAnswerMiddleware

    async def never_answers(scope, receive, send):
        raise asyncio.CancelledError

    async def half_answers(scope, receive, send):
        await send({"type": "http.response.start", "status": 200, "headers": []})
        raise asyncio.CancelledError

    async def call(app) -> list[dict]:
        sent: list[dict] = []

        async def receive():
            return {"type": "http.request", "body": b"", "more_body": False}

        async def send(message):
            sent.append(message)

        await ShutdownAnswerMiddleware(app, retry_after=3)({"type": "http", "method": "POST", "path": "/v1/x",
                                                             "headers": []}, receive, send)
        return sent

    start, body = asyncio.run(call(never_answers))
    assert start["status"] == 503
    headers = {k.decode(): v.decode() for k, v in start["headers"]}
    assert headers["retry-after"] == "3" and headers["content-type"] == "application/json"
    assert json.loads(body["body"])["code"] == "shutting_down"
    with pytest.raises(asyncio.CancelledError):
        asyncio.run(call(half_answers))


@pytest.mark.slow
def test_sigterm_answers_a_request_in_flight_503_shutting_down(tmp_path):
    """SIGTERM with a request that never ends by itself (the stand-in design request): after the shutdown time limit
    (1 s) the request gets the service's JSON 503 ``shutting_down`` with Retry-After, and the server exits."""
    env = server_env(clean_env(TENSEGRITY_JOBS_DB=str(tmp_path / "jobs.sqlite3"), TENSEGRITY_WARMUP="false",
                               TENSEGRITY_INLINE_PROCESSES="0", TENSEGRITY_RETRY_AFTER="7",
                               TENSEGRITY_SOLVE_TIMEOUT=str(WAIT_SECONDS)))
    cmd = uvicorn_factory_command("stand_ins:app_with_designs_that_never_end", free_port(),
                                  "--timeout-graceful-shutdown", "1")
    heavy = {"manipulator": {"n": NEVER_ENDING_SEGMENTS}, "vary": ["a", "b", "k", "L0"]}
    with running_server(cmd, env, ready="/readyz", timeout=WAIT_SECONDS) as (proc, base):
        answers: list = []

        def post() -> None:
            try:
                answers.append(httpx.post(base + "/v1/design/critical-force", json=heavy, timeout=WAIT_SECONDS))
            except httpx.HTTPError as exc:
                answers.append(exc)

        thread = threading.Thread(target=post, daemon=True)
        thread.start()
        deadline = time.monotonic() + WAIT_SECONDS
        while httpx.get(base + "/readyz", timeout=WAIT_SECONDS).json()["in_flight"] == 0:
            assert time.monotonic() < deadline and thread.is_alive(), answers
            time.sleep(0.05)
        proc.send_signal(signal.SIGTERM)
        proc.wait(WAIT_SECONDS)
        thread.join(WAIT_SECONDS)
    (r,) = answers
    assert isinstance(r, httpx.Response), r
    assert r.status_code == 503, r.text
    assert r.headers["content-type"] == "application/json" and r.headers["retry-after"] == "7"
    body = r.json()
    assert body["code"] == "shutting_down" and body["message"]


@pytest.mark.slow
@pytest.mark.skipif(to.numerics.build.compiler() is None, reason="no C compiler on this machine")
def test_the_first_request_for_a_fresh_chain_length_does_not_wait_for_the_compiler(tmp_path):
    """A real server with an empty kernel cache and a stand-in compiler held until the test releases it: the server
    gets ready and answers the first requests (a fresh n = 6 too) in CasADi's virtual machine; once released, the
    kernels compile in the background and /version reports them compiled."""
    import time

    release = tmp_path / "release"
    cc = tmp_path / "held-cc"
    real = to.numerics.build.compiler()
    cc.write_text(f'#!/bin/sh\nwhile [ ! -e "{release}" ]; do sleep 0.01; done\nexec {real} "$@"\n')
    cc.chmod(0o755)
    env = clean_env(**GENEROUS_ENV, TENSEGRITY_CACHE_DIR=str(tmp_path / "cache"), CC=str(cc),
                    TENSEGRITY_JOBS_DB=str(tmp_path / "jobs.sqlite3"))
    body = {"manipulator": {"n": 6, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}, "dx": 0.3, "dy": 0.1}
    try:
        with running_server(serve_command(free_port()), env, ready="/readyz") as (_, base):
            kernels = httpx.get(base + "/version", timeout=60).json()["kernels"]
            assert 6 in kernels["building"] and kernels["compiled"] == []
            first = httpx.post(base + "/v1/equilibrium", json=body, timeout=120)
            assert first.status_code == 200 and first.json()["success"]
            assert not list((tmp_path / "cache").glob("*.so"))               # nothing compiled yet
            release.touch()
            deadline = time.monotonic() + WAIT_SECONDS
            while time.monotonic() < deadline:
                kernels = httpx.get(base + "/version", timeout=60).json()["kernels"]
                if not kernels["building"]:
                    break
                time.sleep(0.1)
            assert kernels["building"] == [] and 6 in kernels["compiled"]
            again = httpx.post(base + "/v1/equilibrium", json=body, timeout=120)
            assert again.status_code == 200 and again.json()["q"] == pytest.approx(first.json()["q"], abs=1e-9)
    finally:
        release.touch()
