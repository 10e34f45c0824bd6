"""The fast solver process of the service (the ``fast`` :class:`~service.execution.ProcessExecutor`): same
answers, and nothing lost when it fails.

Expected answers come from a server without solver processes (``inline_processes=0``: the solver
threads solve), which the rest of the service tests check against the library; here the point is
that handing the call to another process changes nothing a client can see, and that every
failure of that process (killed, refusing, timing out, raising) still answers the request.
"""

from __future__ import annotations

import operator
import os
import pickle
import signal
import time
import warnings

import pytest

pytest.importorskip("fastapi")

with warnings.catch_warnings():
    warnings.simplefilter("ignore")
    from fastapi.testclient import TestClient

from service_helpers import WAIT_SECONDS, service_settings

from service.execution import ProcessExecutor, SolveTimeout, Unavailable
from service.execution import processes as processes_mod
from service.main import create_app

PAPER = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}
BODIES = [{"manipulator": PAPER, "dx": 0.1}, {"manipulator": PAPER, "dx": 0.7, "dy": -0.3},
          {"manipulator": {"n": 6, "a": 0.8, "b": 1.2, "k": 2.5, "L0": 1.7}, "dx": 1.1, "dy": 0.2},
          {"manipulator": PAPER, "dx": 0.2, "dy": 0.05, "q0": [0.17, -0.07, -0.24, -0.13]},
          {"manipulator": PAPER, "dx": 0.101, "q0": [0.178, -0.077, -0.245, -0.131], "local": True},
          {"manipulator": {"n": 4, "a": 0.6, "b": 1.0, "k": 1.0, "L0": 1.2}, "dx": 0.3, "dy": 0.1}]
UNREACHABLE = {"manipulator": PAPER, "dx": 0.1, "dy": 8.5}
BISTABLE = BODIES[5]                     # a bistable chain: not for the bounded search
LONG = {"manipulator": {"n": 12, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}, "dx": 0.4, "dy": 0.1}   # > 8 segments


def ready_client(**overrides) -> TestClient:
    return TestClient(create_app(service_settings(**overrides)))


def wait_ready(client: TestClient, timeout: float = WAIT_SECONDS) -> ProcessExecutor:
    lane = client.app.state.executors.fast
    assert client.portal.call(lane.wait_ready, timeout), "the solver process did not get ready"
    return lane


@pytest.fixture(scope="module")
def clients():
    with ready_client() as fast, ready_client(inline_processes=0) as plain:
        wait_ready(fast)
        assert plain.app.state.executors.fast is None
        yield fast, plain


@pytest.mark.slow
def test_the_solver_process_answers_like_the_solver_threads(clients):
    fast, plain = clients
    lane = fast.app.state.executors.fast
    before = lane.completed
    for body in BODIES:
        a, b = fast.post("/v1/equilibrium", json=body), plain.post("/v1/equilibrium", json=body)
        assert a.status_code == b.status_code == 200, (a.text, b.text)
        assert a.content == b.content
    # every body the bounded search may settle went through the process; the bistable chain did not
    # (the parent decides that: it goes straight to a solver thread, no round trip answering "not settled")
    assert lane.completed - before == len(BODIES) - 1
    assert lane.pids and os.getpid() not in lane.pids


def test_only_requests_the_bounded_search_may_settle_are_sent_to_the_solver_process(clients):
    fast, plain = clients
    lane = fast.app.state.executors.fast
    for body in (BISTABLE, LONG):
        before = lane.completed
        a, b = fast.post("/v1/equilibrium", json=body), plain.post("/v1/equilibrium", json=body)
        assert a.status_code == b.status_code == 200, (a.text, b.text)
        assert a.content == b.content
        assert lane.completed == before, body["manipulator"]


def _case(b: dict) -> str:
    how = "local" if b.get("local") else "q0" if "q0" in b else "search"
    return f"n{b['manipulator'].get('n')}-dx{b['dx']}-dy{b.get('dy', 0)}-{how}"


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("body", [*BODIES, BISTABLE, LONG], ids=_case)
def test_the_response_schema_is_the_contract_of_every_path(clients, body):
    """The body of the solver process (rendered there, no response-model pass) validates against
    ``EquilibriumOut`` and is byte for byte what the solver threads send for the same request,
    which is the model's own dump of it, rendered the way the threads render."""
    from service import schemas as s
    from service.responses import render_json

    fast, plain = clients
    a, b = fast.post("/v1/equilibrium", json=body), plain.post("/v1/equilibrium", json=body)
    assert a.status_code == b.status_code == 200, (a.text, b.text)
    assert a.headers["content-type"] == b.headers["content-type"] == "application/json"
    for r in (a, b):
        model = s.EquilibriumOut.model_validate_json(r.content)
        assert render_json(model.model_dump(mode="json")) == r.content
    assert a.content == b.content


def test_an_error_raised_in_the_solver_process_is_answered_as_without_it(clients):
    fast, plain = clients
    lane = fast.app.state.executors.fast
    before = lane.completed
    a, b = fast.post("/v1/equilibrium", json=UNREACHABLE), plain.post("/v1/equilibrium", json=UNREACHABLE)
    assert a.status_code == b.status_code == 422
    assert a.json() == b.json() and a.json()["code"] == "unreachable_target"
    assert lane.completed == before + 1          # the process answered "failed"; the pool re-raised it


@pytest.mark.slow
def test_a_killed_solver_process_loses_no_request_and_is_restarted(monkeypatch):
    monkeypatch.setattr(processes_mod, "RESTART_BASE", 0.0)
    with ready_client() as fast, ready_client(inline_processes=0) as plain:
        lane = wait_ready(fast)
        expected = plain.post("/v1/equilibrium", json=BODIES[1]).json()
        [old] = lane.pids
        os.kill(old, signal.SIGKILL)
        deadline = time.monotonic() + WAIT_SECONDS
        while lane.ready and time.monotonic() < deadline:     # the loop notices the closed socket
            time.sleep(0.01)
        assert not lane.ready
        r = fast.post("/v1/equilibrium", json=BODIES[1])      # answered by a solver thread; restart begins
        assert r.status_code == 200 and r.json() == expected
        wait_ready(fast)
        assert lane.pids and old not in lane.pids and lane.restarts == 1
        before = lane.completed
        r = fast.post("/v1/equilibrium", json=BODIES[1])
        assert r.status_code == 200 and r.json() == expected
        assert lane.completed == before + 1
        [pid] = lane.pids
    with pytest.raises(ProcessLookupError):     # the server's shutdown ended (and reaped) its child
        os.kill(pid, 0)


def test_a_saturated_solver_process_hands_the_call_back(clients):
    fast, plain = clients
    lane = fast.app.state.executors.fast
    before, limit = lane.completed, lane.depth
    lane.depth = 0
    try:
        r = fast.post("/v1/equilibrium", json=BODIES[0])
    finally:
        lane.depth = limit
    assert r.status_code == 200 and r.json() == plain.post("/v1/equilibrium", json=BODIES[0]).json()
    assert lane.completed == before


class _FailsToUnpickle:
    """Pickles fine here; unpickling it in the child raises ZeroDivisionError."""

    def __reduce__(self):
        return operator.truediv, (1, 0)


def test_the_solver_process_survives_calls_it_cannot_take(clients):
    fast, _ = clients
    lane = fast.app.state.executors.fast
    pids = lane.pids
    with pytest.raises((pickle.PicklingError, AttributeError, TypeError)):   # cannot be pickled: nothing sent
        fast.portal.call(lambda: lane.run(operator.add, lambda: 0, 1, timeout=120))
    with pytest.raises(ZeroDivisionError):               # cannot be unpickled there: its error comes back
        fast.portal.call(lambda: lane.run(operator.add, _FailsToUnpickle(), 1, timeout=120))
    with pytest.raises(ZeroDivisionError):               # raises there: the exception comes back with its type
        fast.portal.call(lambda: lane.run(operator.truediv, 1, 0, timeout=120))
    assert fast.portal.call(lambda: lane.run(operator.add, 2, 3, timeout=120)) == 5
    assert lane.ready and lane.pids == pids


@pytest.mark.slow
def test_a_stuck_solver_process_is_killed_and_restarted(monkeypatch):
    monkeypatch.setattr(processes_mod, "RESTART_BASE", 0.0)
    with ready_client() as fast:
        lane = wait_ready(fast)
        [old] = lane.pids
        with pytest.raises(SolveTimeout):                  # the child sleeps through the whole limit
            fast.portal.call(lambda: lane.run(time.sleep, 600.0, timeout=0.5))
        deadline = time.monotonic() + WAIT_SECONDS
        while lane.ready and time.monotonic() < deadline:
            time.sleep(0.01)
        assert not lane.ready and lane.killed == 1         # killed as stuck, after its grace
        r = fast.post("/v1/equilibrium", json=BODIES[0])   # answered by a solver thread; restart begins
        assert r.status_code == 200
        wait_ready(fast)
        assert old not in lane.pids and lane.restarts == 1


@pytest.mark.slow
def test_a_call_over_the_time_limit_is_a_504():
    with ready_client(solve_timeout=0.5) as fast:
        lane = wait_ready(fast)
        # the child sleeps ten minutes: the request queued behind it is over its 0.5 s limit on any machine
        busy = fast.portal.start_task_soon(lambda: lane.run(time.sleep, 600.0, timeout=900))
        r = fast.post("/v1/equilibrium", json=BODIES[0])
        assert r.status_code == 504 and r.json()["code"] == "timeout"
        with pytest.raises(Unavailable):                     # no answer within the grace: killed as stuck
            busy.result(WAIT_SECONDS)


def test_a_solver_process_that_cannot_start_is_tried_again_with_growing_delays(monkeypatch):
    """A child that dies before it is ready (here: a Python that cannot import the service) leaves the requests to
    the solver threads and is tried again after a delay that doubles with each loss in a row, up to a bound."""
    monkeypatch.setattr(processes_mod, "RESTART_BASE", 0.01)
    monkeypatch.setattr(processes_mod, "RESTART_MAX", 0.04)
    monkeypatch.setattr(processes_mod.sys, "executable", "/bin/false")
    assert [processes_mod.restart_delay(k) for k in (1, 2, 3, 4, 10)] == [0.01, 0.02, 0.04, 0.04, 0.04]
    with ready_client() as fast:
        lane = fast.app.state.executors.fast
        assert not fast.portal.call(lane.wait_ready, WAIT_SECONDS)        # returns at once: the child died
        for _ in range(3):
            r = fast.post("/v1/equilibrium", json=BODIES[0])
            assert r.status_code == 200
        deadline = time.monotonic() + WAIT_SECONDS
        while lane.restarts < 3 and time.monotonic() < deadline:
            time.sleep(0.01)
        assert lane.restarts >= 3 and lane.losses >= 3 and not lane.ready and lane.completed == 0
        body = fast.get("/readyz").json()
        assert body["processes"]["fast"]["state"] == "restarting" and body["degraded"] == ["fast_path"]


def test_version_reports_the_solver_processes(clients):
    fast, plain = clients
    assert fast.get("/version").json()["limits"]["inline_processes"] == 1
    assert plain.get("/version").json()["limits"]["inline_processes"] == 0


def solver_children(server_pid: int) -> set[int]:
    """The server's solver processes (``python -m service.execution.child``), from ``/proc``."""
    found = set()
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as f:
                ppid = int(f.read().rsplit(")", 1)[1].split()[1])
            with open(f"/proc/{entry}/cmdline", "rb") as f:
                cmdline = f.read()
        except (OSError, ValueError, IndexError):
            continue
        if ppid == server_pid and b"service.execution.child" in cmdline:
            found.add(int(entry))
    return found


def wait_for(what, predicate, timeout: float = WAIT_SECONDS):
    """Poll ``predicate()`` until it returns something true (returned); fail after ``timeout`` seconds."""
    deadline = time.monotonic() + timeout
    while True:
        value = predicate()
        if value:
            return value
        if time.monotonic() > deadline:
            raise AssertionError(f"{what}: not within {timeout:g} s")
        time.sleep(0.02)


@pytest.mark.slow
@pytest.mark.skipif(not os.path.isdir("/proc"), reason="finds the solver process in /proc")
def test_a_solver_process_killed_while_restarting_comes_back_and_its_state_shows(tmp_path):
    """A real server: its fast solver process is killed; the replacement is killed again before it is ready (its
    warm-up waits for a file the test creates); a third one comes up. Meanwhile /readyz answers 200 and names the
    degraded fast path, /metrics shows the state and the restarts, and requests are answered (by the threads)."""
    import httpx
    from servers import GENEROUS_ENV, clean_env, running_server, uvicorn_factory_command
    from stand_ins import WARMUP_GATE, server_env

    gate = tmp_path / "warm-up may finish"
    gate.touch()
    env = server_env(clean_env(**GENEROUS_ENV, TENSEGRITY_HEAVY_WORKERS="0", TENSEGRITY_JOBS_DB=str(tmp_path / "j.db"),
                               **{WARMUP_GATE: str(gate)}))
    cmd = uvicorn_factory_command("stand_ins:app_with_a_held_fast_process", free_port())
    with running_server(cmd, env, ready="/readyz") as (proc, base):
        def fast() -> dict:
            return httpx.get(base + "/readyz", timeout=30).json()["processes"]["fast"]

        def metric(name: str) -> float:
            text = httpx.get(base + "/metrics", timeout=30).text
            return float(next(line.rsplit(" ", 1)[1] for line in text.splitlines() if line.startswith(name)))

        wait_for("the fast process up", lambda: fast()["state"] == "up")
        [first] = solver_children(proc.pid)
        gate.unlink()                                       # the replacements' warm-ups wait from now on
        os.kill(first, signal.SIGKILL)
        second = wait_for("a replacement", lambda: solver_children(proc.pid) - {first})
        ready = httpx.get(base + "/readyz", timeout=30)
        assert ready.status_code == 200 and ready.json()["processes"]["fast"]["state"] == "restarting"
        assert ready.json()["degraded"] == ["fast_path"]
        assert metric('tensegrity_solver_processes_state{pool="fast",state="restarting"}') == 1.0
        r = httpx.post(base + "/v1/equilibrium", json=BODIES[0], timeout=60)
        assert r.status_code == 200 and r.json()["success"]
        [second] = second
        os.kill(second, signal.SIGKILL)                     # before it is ready: its warm-up waits for the gate
        third = wait_for("another replacement", lambda: solver_children(proc.pid) - {first, second})
        assert fast()["state"] == "restarting"
        gate.touch()
        wait_for("the fast process up again", lambda: fast()["state"] == "up")
        assert solver_children(proc.pid) == third
        state = fast()
        assert state["restarts"] == 2 and state["ready"] == 1
        assert httpx.get(base + "/readyz", timeout=30).json()["degraded"] == []
        assert metric('tensegrity_solver_processes_state{pool="fast",state="up"}') == 1.0
        assert metric('tensegrity_solver_processes_restarts{pool="fast"}') == 2.0
        r = httpx.post(base + "/v1/equilibrium", json=BODIES[0], timeout=60)
        assert r.status_code == 200 and r.json()["success"]


def free_port() -> int:
    from servers import free_port as port

    return port()
