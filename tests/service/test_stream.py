"""The control stream (``/v1/control/stream``) over a real server process and a real WebSocket client.

* every mode's answers equal the library called directly on the same inputs, step by step: the
  ``Tracker`` (track), ``solve_equilibrium_under_force`` from the last configuration (preloads), the
  ``PreloadController`` (inverse), events included (a tracker jump, a preload snap);
* bad messages (not JSON, an unknown type, a bad field, a step before the open, a second open) get the
  REST API's errors and the stream goes on; a refused open is answered, then closed with 1008;
* the API key (header or query) on a server with keys: refused with 4401 without it;
* the Origin: a page of another origin is refused before the upgrade (403 ``forbidden_origin``), the server's own
  origin, the configured CORS origins and clients sending none are served;
* the idle timeout (1001), the per-step time limit (``timeout``, the stream goes on; in process, where a step
  that never ends by itself can stand in for a long one), the connection bound (1013), and a client killed
  mid-step: the server survives and its slot is free again.

The servers' solve time limit is generous (``tests/support/service_helpers.py``): every open and step of these
tests takes milliseconds (a fraction of a second for a stream's first, which builds its solvers).
"""

from __future__ import annotations

import asyncio
import json
import math
import socket
import time

import numpy as np
import pytest
from servers import clean_env, free_port, running_server, serve_command
from service_helpers import GENEROUS_ENV, GENEROUS_SECONDS, WAIT_SECONDS

import tensegrity_opt as to
from tensegrity_opt.analyses.design.preload_control import PreloadController
from tensegrity_opt.analyses.equilibria.rest import rest_configuration
from tensegrity_opt.analyses.paths.continuation import Tracker

websockets = pytest.importorskip("websockets")
httpx = pytest.importorskip("httpx")
pytest.importorskip("uvicorn")

KEY = "stream-test-key"
PAPER = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}
#: Lean servers: no warm-up, no solver processes (a stream has its own solver thread), generous time limits.
LEAN = dict(TENSEGRITY_WORKERS="1", TENSEGRITY_WARMUP="false", TENSEGRITY_INLINE_PROCESSES="0",
            TENSEGRITY_HEAVY_WORKERS="0", **GENEROUS_ENV)


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    """Keys, at most 2 streams, chains up to 50 segments."""
    env = clean_env(**LEAN, TENSEGRITY_API_KEYS=KEY, TENSEGRITY_MAX_STREAM_CONNECTIONS="2",
                    TENSEGRITY_MAX_SEGMENTS="50",
                    TENSEGRITY_JOBS_DB=str(tmp_path_factory.mktemp("jobs") / "jobs.sqlite3"))
    with running_server(serve_command(free_port()), env) as (proc, base):
        yield proc, base


@pytest.fixture(scope="module")
def quick(tmp_path_factory):
    """No keys, a short idle timeout."""
    env = clean_env(**LEAN, TENSEGRITY_STREAM_IDLE_TIMEOUT="0.5",
                    TENSEGRITY_JOBS_DB=str(tmp_path_factory.mktemp("jobs") / "jobs.sqlite3"))
    with running_server(serve_command(free_port()), env) as (proc, base):
        yield proc, base


def ws_url(base: str, query: str = "") -> str:
    return base.replace("http://", "ws://") + "/v1/control/stream" + query


def connect(base: str, key: str | None = KEY, query: str = ""):
    headers = {"X-API-Key": key} if key else {}
    return websockets.connect(ws_url(base, query), additional_headers=headers, compression=None,
                              open_timeout=WAIT_SECONDS)


async def ask(ws, msg) -> dict:
    await ws.send(msg if isinstance(msg, (str, bytes)) else json.dumps(msg))
    return json.loads(await asyncio.wait_for(ws.recv(), WAIT_SECONDS))


async def closed(ws) -> tuple[int, str]:
    """The close code and reason the server sent (after anything still queued)."""
    with pytest.raises(websockets.ConnectionClosed) as info:
        while True:
            await asyncio.wait_for(ws.recv(), WAIT_SECONDS)
    return info.value.rcvd.code, info.value.rcvd.reason


def run(coro):
    return asyncio.run(coro)


def assert_same(got, want, path="") -> None:
    """``got`` (decoded JSON) equals the library's ``to_dict()`` ``want``: numbers to 1e-9."""
    if isinstance(want, dict):
        assert set(want) <= set(got), (path, set(want) - set(got))
        for k, v in want.items():
            assert_same(got[k], v, f"{path}.{k}")
    elif isinstance(want, (list, tuple)):
        assert isinstance(got, list) and len(got) == len(want), path
        for i, (g, w) in enumerate(zip(got, want)):
            assert_same(g, w, f"{path}[{i}]")
    elif isinstance(want, float) and not isinstance(want, bool):
        assert got == pytest.approx(want, rel=1e-9, abs=1e-12), path
    else:
        assert got == want, path


# ---------------------------------------------------------------------------- the three modes
@pytest.mark.slow
def test_track_mode_is_the_tracker_with_its_jumps(server):
    _, base = server
    chain = {"n": 3, "a": 0.5, "b": 1.0, "k": 1.0, "L0": 1.0}          # bistable segments: a snap on the way
    m = to.Manipulator.uniform(3, 0.5, 1.0, 1.0, 1.0)
    path = [(dx, 0.0) for dx in np.linspace(0.02, 2.6, 40)] + [(1.0, 0.3), (1.0, -0.3)]
    tr = Tracker(m)
    want, jumps_at = [], []
    for i, (dx, dy) in enumerate(path):
        j = tr.jumps
        want.append(tr.solve(dx, dy).to_dict())
        if tr.jumps != j:
            jumps_at.append(i)
    assert jumps_at, "the path should make the tracker jump"

    async def go():
        async with connect(base) as ws:
            opened = await ask(ws, {"type": "open", "manipulator": chain, "mode": "track"})
            assert opened["type"] == "opened" and opened["seq"] == 0 and opened["mode"] == "track"
            assert opened["n"] == 3 and opened["step_timeout"] == GENEROUS_SECONDS and opened["idle_timeout"] == 60.0
            out = []
            for dx, dy in path:
                out.append(await ask(ws, {"type": "step", "dx": float(dx), "dy": float(dy)}))
            return out

    got = run(go())
    for i, (g, w) in enumerate(zip(got, want)):
        assert g["type"] == "result" and g["seq"] == i + 1 and g["mode"] == "track"
        assert_same(g, w)
        assert bool(g["events"]) == (i in jumps_at), i
    for i in jumps_at:
        (ev,) = got[i]["events"]
        assert ev["kind"] == "jump" and ev["q_before"] == got[i - 1]["q"]
        assert ev["distance"] == pytest.approx(np.max(np.abs(np.subtract(got[i]["q"], got[i - 1]["q"]))), rel=1e-12)
    assert got[-1]["jumps"] == tr.jumps == len(jumps_at)


@pytest.mark.slow
def test_preloads_mode_is_the_forward_solve_from_the_last_state_with_its_snap(server):
    _, base = server
    # a bistable segment in front of a straight one; tilting its double well (1 + d, 1 - d) ends its well:
    # one snap into the other
    chain = {"segments": [{"a": 0.5, "b": 1.0, "k": 1.0, "L0": 1.0}, {"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}]}
    m = to.Manipulator.from_dict(chain)
    ds = np.linspace(0.0, 0.5, 26)
    commands = [[[1 + d, 1 - d], [1.0, 1.0]] for d in ds]
    loads = [None] * len(ds)
    loads[-1] = [0.0, 0.01]                     # a step's own load
    start = rest_configuration(m).q.copy()
    follower = to.PreloadFollower(m)                # the library's answers: each command along its transition
    want = [follower.step(rl, load=F).to_dict() for rl, F in zip(commands, loads)]
    snaps = [i for i, w in enumerate(want) if w["events"]]
    assert len(snaps) == 1

    async def go():
        async with connect(base) as ws:
            opened = await ask(ws, {"type": "open", "manipulator": chain, "mode": "preloads"})
            assert opened["type"] == "opened" and opened["load"] == [0.0, 0.0]
            assert_same(opened["q"], start.tolist())
            out = []
            for rl, F in zip(commands, loads):
                out.append(await ask(ws, {"type": "step", "rest_lengths": rl, **({"load": F} if F else {})}))
            return out

    got = run(go())
    for i, (g, w) in enumerate(zip(got, want)):
        assert g["type"] == "result" and g["seq"] == i + 1 and g["mode"] == "preloads", g
        assert_same(g, w)
        assert g["rest_lengths"] == commands[i] and g["load"] == (loads[i] or [0.0, 0.0])
        assert bool(g["events"]) == (i in snaps)
    (ev,) = got[snaps[0]]["events"]
    assert ev["kind"] == "snap" and ev["status"] == "landed" and ev["step"] == snaps[0] and 0 < ev["fraction"] < 1
    assert max(abs(a - b) for a, b in zip(ev["q_after"], ev["q_before"])) > 1.0       # into the other well


@pytest.mark.slow
def test_inverse_mode_is_the_preload_controller(server):
    _, base = server
    F = (-0.02, 0.01)
    m = to.Manipulator.uniform(4)
    ctl = PreloadController(m, load=F, rate_limit=0.1, dt=1.0)
    tip0 = m.tip(ctl.q)
    steps = [{"target": (tip0 + np.array([-0.15, 0.3]) * math.sin(math.pi * k / 11)).tolist()} for k in range(12)]
    steps[5]["end_angle"] = 0.55                        # beyond the rate limit's Newton step: IPOPT
    steps[7]["load"] = [-0.03, 0.0]
    steps.insert(9, {"target": [10.0, 0.0]})            # out of reach: infeasible, the controller stays
    opened_want = {"q": ctl.q.tolist(), "command": ctl.ell.reshape(4, 2).tolist(), "load": list(F),
                   "on_infeasible": "hold"}
    want = [ctl.step(st["target"], load=st.get("load"), end_angle=st.get("end_angle")).to_dict() for st in steps]
    assert not want[9]["feasible"] and all(w["feasible"] for i, w in enumerate(want) if i != 9)
    assert want[5]["method"] == "ipopt" and want[5]["residual"] is None
    assert want[9]["method"] == "none" and want[9]["command"] == want[8]["command"]     # held

    async def go():
        async with connect(base) as ws:
            opened = await ask(ws, {"type": "open", "manipulator": PAPER, "mode": "inverse", "load": list(F),
                                    "rate_limit": 0.1, "dt": 1.0})
            assert opened["type"] == "opened" and opened["mode"] == "inverse"
            assert_same(opened, opened_want)
            return [await ask(ws, {"type": "step", **st}) for st in steps]

    got = run(go())
    for i, (g, w) in enumerate(zip(got, want)):
        assert g["type"] == "result" and g["seq"] == i + 1 and g["mode"] == "inverse", g
        assert_same(g, w)


# ---------------------------------------------------------------------------- refusals
@pytest.mark.slow
def test_bad_messages_are_answered_and_the_stream_goes_on(server):
    _, base = server

    async def go():
        async with connect(base) as ws:
            e = await ask(ws, "not json")
            assert e["type"] == "error" and e["seq"] == 0 and e["code"] == "validation_error"
            assert e["field"] == "body" and e["errors"][0]["type"] == "json_invalid"
            e = await ask(ws, {"type": "step", "dx": 0.1})
            assert (e["code"], e["field"], e["seq"]) == ("not_open", "type", 1)
            e = await ask(ws, {"type": "steer"})
            assert (e["code"], e["field"]) == ("validation_error", "type")
            e = await ask(ws, [1, 2])
            assert (e["code"], e["field"]) == ("validation_error", "body")
            assert (await ask(ws, {"type": "open", "manipulator": PAPER, "mode": "track"}))["type"] == "opened"
            ok = await ask(ws, {"type": "step", "dx": 0.1})
            assert ok["type"] == "result" and ok["seq"] == 5
            e = await ask(ws, {"type": "step", "dx": "0.1"})
            assert (e["code"], e["field"], e["seq"]) == ("validation_error", "dx", 6)
            e = await ask(ws, {"type": "step", "dx": 0.1, "dz": 1})
            assert (e["code"], e["field"]) == ("validation_error", "dz")
            e = await ask(ws, {"type": "step"})
            assert (e["code"], e["field"]) == ("validation_error", "dx")
            e = await ask(ws, '{"type": "step", "dx": NaN}')
            assert (e["code"], e["field"]) == ("validation_error", "dx")
            e = await ask(ws, {"type": "step", "dx": 50.0})            # the library's refusal
            assert (e["code"], e["field"]) == ("unreachable_target", "dx") and e["details"]["reach"] == 7.0
            e = await ask(ws, {"type": "open", "manipulator": PAPER, "mode": "track"})
            assert (e["code"], e["field"]) == ("already_open", "type")
            e = await ask(ws, "{")
            assert (e["code"], e["field"]) == ("validation_error", "body")
            ok2 = await ask(ws, json.dumps({"type": "step", "dx": 0.11}).encode())   # a binary frame
            assert ok2["type"] == "result" and ok2["seq"] == 13 and ok2["events"] == []
            # the stream still continues from the last good step: the Tracker's answer for 0.1 then 0.11
            tr = Tracker(to.Manipulator.uniform(4))
            tr.solve(0.1)
            assert_same(ok2, tr.solve(0.11).to_dict())
        # a preloads step with the wrong number of segments: the library's refusal names the message field
        async with connect(base) as ws:
            await ask(ws, {"type": "open", "manipulator": PAPER, "mode": "preloads"})
            e = await ask(ws, {"type": "step", "rest_lengths": [[1.0, 1.0]] * 3})
            assert (e["code"], e["field"]) == ("invalid_parameter", "rest_lengths")
            e = await ask(ws, {"type": "step", "rest_lengths": [[1.0, 1.0]] * 3 + [[1.0, -1.0]]})
            assert (e["code"], e["field"]) == ("validation_error", "rest_lengths[3][1]")
            assert (await ask(ws, {"type": "step", "rest_lengths": [[1.0, 1.0]] * 4}))["type"] == "result"
        r = httpx.get(base + "/v1/control/stream", headers={"X-API-Key": KEY})
        assert r.status_code == 426 and r.json()["code"] == "upgrade_required"

    run(go())


@pytest.mark.slow
@pytest.mark.parametrize("open_msg,code,field", [
    ({"type": "open", "manipulator": {"n": 0}, "mode": "track"}, "validation_error", "manipulator.n"),
    ({"type": "open", "manipulator": PAPER, "mode": "steer"}, "validation_error", "mode"),
    ({"type": "open", "manipulator": PAPER}, "validation_error", "mode"),
    ({"type": "open", "manipulator": PAPER, "mode": "track", "load": [0.0, 1.0]}, "validation_error", "load"),
    ({"type": "open", "manipulator": {"n": 51}, "mode": "track"}, "too_many_segments", "manipulator.n"),
    ({"type": "open", "manipulator": {"n": 1}, "mode": "inverse"}, "invalid_parameter", "manipulator.n"),
    ({"type": "open", "manipulator": {"n": 61}, "mode": "inverse"}, "validation_error", "manipulator.n"),
    ({"type": "open", "manipulator": PAPER, "mode": "inverse", "start": [0.0] * 3}, "invalid_parameter", "start"),
    # the chain's dead loads are taken and refused by name where the mode does not honour them
    ({"type": "open", "manipulator": {**PAPER, "mass": 0.1, "gravity": [0.0, -9.81]}, "mode": "track"},
     "unsupported", "gravity"),
    ({"type": "open", "manipulator": {**PAPER, "joint_forces": [{"joint": 2, "force": [0.0, 0.1]}]},
      "mode": "preloads"}, "unsupported", "joint_forces"),
])
def test_a_refused_open_is_answered_then_closed_with_1008(server, open_msg, code, field):
    _, base = server

    async def go():
        async with connect(base) as ws:
            e = await ask(ws, open_msg)
            assert (e["type"], e["seq"], e["code"], e["field"]) == ("error", 0, code, field), e
            assert (await closed(ws))[0] == 1008

    run(go())


@pytest.mark.slow
def test_the_api_key_in_the_header_or_the_query(server):
    _, base = server

    async def refused(key, query=""):
        async with connect(base, key, query) as ws:
            e = json.loads(await asyncio.wait_for(ws.recv(), 10))
            assert (e["type"], e["seq"], e["code"], e["field"]) == ("error", None, "unauthorized", "X-API-Key")
            assert (await closed(ws)) == (4401, "unauthorized")

    async def accepted(key, query=""):
        async with connect(base, key, query) as ws:
            assert (await ask(ws, {"type": "open", "manipulator": PAPER, "mode": "track"}))["type"] == "opened"

    async def go():
        await refused(None)
        await refused("wrong")
        await refused(None, "?api_key=wrong")
        await accepted(KEY)
        await accepted(None, f"?api_key={KEY}")

    run(go())
    assert httpx.get(base + "/version", headers={"X-API-Key": KEY}).json()["limits"]["max_stream_connections"] == 2


# ---------------------------------------------------------------------------- origins
#: Origin header -> accepted, on an app whose CORS origins are ["https://app.example.org"] (the TestClient connects
#: to the host "testserver").
ORIGINS = {
    None: True,                                     # a script: no Origin
    "http://testserver": True,                      # the server's own origin
    "https://testserver": True,                     # the same, behind TLS
    "https://app.example.org": True,                # a configured CORS origin
    "https://APP.example.org/": True,               # the same, written differently
    "http://evil.example": False,                   # any other page
    "http://testserver:8001": False,                # the same host, another port: another origin
    "http://testserver.evil.example": False,
    "null": False,                                  # a sandboxed frame, a file
    "ws://testserver": False,                       # not a web origin
}


@pytest.mark.parametrize("origin,accepted", ORIGINS.items(), ids=[str(o) for o in ORIGINS])
def test_a_stream_is_opened_only_from_the_servers_own_origin_the_cors_origins_or_no_origin(origin, accepted):
    """In process: a handshake from another origin is refused before the upgrade, HTTP 403 ``forbidden_origin`` in the
    error shape; the others are upgraded and served."""
    from service_helpers import app_client
    from starlette.testclient import WebSocketDenialResponse

    headers = {"origin": origin} if origin is not None else {}
    with app_client(cors_origins=["https://app.example.org"], inline_processes=0, heavy_workers=0) as client:
        if accepted:
            with client.websocket_connect("/v1/control/stream", headers=headers) as ws:
                ws.send_json({"type": "step", "dx": 0.1})
                assert ws.receive_json()["code"] == "not_open"
            return
        with pytest.raises(WebSocketDenialResponse) as info:
            with client.websocket_connect("/v1/control/stream", headers=headers):
                pass
        r = info.value
        assert r.status_code == 403 and r.headers["content-type"] == "application/json"
        body = r.json()
        assert (body["code"], body["field"]) == ("forbidden_origin", "Origin")
        assert 'tensegrity_errors_total{code="forbidden_origin"} 1.0' in client.get("/metrics").text


def test_without_cors_origins_only_the_servers_own_origin_is_accepted():
    from service.api.deps import origin_allowed
    from service.config import Settings

    plain, anything = Settings(), Settings(cors_origins=["*"])
    assert origin_allowed(None, "127.0.0.1:8000", plain)
    assert origin_allowed("http://127.0.0.1:8000", "127.0.0.1:8000", plain)
    assert origin_allowed("http://[::1]:8000", "[::1]:8000", plain)
    assert origin_allowed("http://example.org", "example.org:80", plain)
    assert not origin_allowed("http://localhost:8000", "127.0.0.1:8000", plain)     # another origin for a browser
    assert not origin_allowed("http://127.0.0.1:8000", None, plain)
    assert not origin_allowed("http://127.0.0.1:8000", "127.0.0.1:notaport", plain)
    assert not origin_allowed("https://app.example.org", "127.0.0.1:8000", plain)
    assert origin_allowed("https://app.example.org", "127.0.0.1:8000", anything)


@pytest.mark.slow
def test_a_page_of_another_origin_is_refused_before_the_upgrade(server):
    """A real server with keys: the origin is checked before the upgrade and before the key (403, not 4401); a
    client sending the server's own origin is served."""
    _, base = server
    port = int(base.rsplit(":", 1)[1])

    with socket.create_connection(("127.0.0.1", port), timeout=WAIT_SECONDS) as sock:
        sock.sendall(b"GET /v1/control/stream HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nUpgrade: websocket\r\n"
                     b"Connection: Upgrade\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n"
                     b"Sec-WebSocket-Version: 13\r\nOrigin: http://evil.example\r\nX-API-Key: %s\r\n\r\n"
                     % (port, KEY.encode()))
        data = b""
        while b"\r\n\r\n" not in data or not data.rstrip().endswith(b"}"):
            chunk = sock.recv(65536)
            if not chunk:
                break
            data += chunk
    head, _, body = data.partition(b"\r\n\r\n")
    assert head.startswith(b"HTTP/1.1 403"), data
    assert json.loads(body)["code"] == "forbidden_origin"

    async def own_origin():
        async with websockets.connect(ws_url(base), additional_headers={"X-API-Key": KEY}, compression=None,
                                      origin=f"http://127.0.0.1:{port}", open_timeout=WAIT_SECONDS) as ws:
            assert (await ask(ws, {"type": "open", "manipulator": PAPER, "mode": "track"}))["type"] == "opened"

    run(own_origin())


# ---------------------------------------------------------------------------- limits
@pytest.mark.slow
def test_an_idle_stream_is_closed_with_1001(quick):
    _, base = quick

    async def go():
        async with connect(base, None) as ws:
            opened = await ask(ws, {"type": "open", "manipulator": PAPER, "mode": "track"})
            assert opened["idle_timeout"] == 0.5
            t0 = time.monotonic()
            e = json.loads(await asyncio.wait_for(ws.recv(), WAIT_SECONDS))
            assert (e["type"], e["seq"], e["code"]) == ("error", None, "idle_timeout")
            code, reason = await closed(ws)
            assert code == 1001 and "idle" in reason
            assert time.monotonic() - t0 > 0.4           # not before the idle timeout
        async with connect(base, None) as ws:           # silent from the start
            e = json.loads(await asyncio.wait_for(ws.recv(), WAIT_SECONDS))
            assert e["code"] == "idle_timeout" and (await closed(ws))[0] == 1001

    run(go())


def _never_ends(session, msg, seq):
    """A step that never ends by itself (short sleeps: the stream's thread can interrupt it between them)."""
    end = time.monotonic() + 600.0
    while time.monotonic() < end:
        time.sleep(0.01)
    raise AssertionError("the step was not interrupted")


@pytest.mark.slow
def test_a_step_over_the_time_limit_is_a_timeout_and_the_stream_goes_on(monkeypatch):
    """In process (a ``TestClient`` WebSocket): the inverse mode's steps are a stand-in that never ends, answered
    ``timeout`` at the step time limit (10 s; the opens and the real steps take a fraction of a second); the stream
    answers its next message, and the server serves other streams."""
    from service_helpers import app_client

    from service.api.routes import stream as routes

    real = routes.step_task

    def step(session, msg, seq):
        return (_never_ends if session.mode == "inverse" else real)(session, msg, seq)

    monkeypatch.setattr(routes, "step_task", step)
    with app_client(solve_timeout=10.0, inline_processes=0, heavy_workers=0) as client:
        with client.websocket_connect("/v1/control/stream") as ws:
            ws.send_json({"type": "open", "manipulator": PAPER, "mode": "inverse"})
            assert ws.receive_json()["type"] == "opened"
            t0 = time.monotonic()
            ws.send_json({"type": "step", "target": [7.0, 1.0]})
            e = ws.receive_json()
            assert (e["type"], e["seq"], e["code"]) == ("error", 1, "timeout") and time.monotonic() - t0 >= 9.9
            ws.send_json({"type": "step", "target": "x"})
            e = ws.receive_json()
            assert (e["seq"], e["code"], e["field"]) == (2, "validation_error", "target")
        with client.websocket_connect("/v1/control/stream") as ws:      # and other streams are served meanwhile
            ws.send_json({"type": "open", "manipulator": PAPER, "mode": "track"})
            assert ws.receive_json()["type"] == "opened"
            ws.send_json({"type": "step", "dx": 0.1})
            r = ws.receive_json()
            assert r["type"] == "result", r


@pytest.mark.slow
def test_the_stream_bound_and_a_killed_client_frees_its_slot(server):
    proc, base = server
    opn = {"type": "open", "manipulator": PAPER, "mode": "track"}

    async def opened_stream():
        """A new open stream; retried while the slots of the previous tests' streams are being released."""
        deadline = time.monotonic() + WAIT_SECONDS
        while True:
            ws = await connect(base)
            try:
                ans = await ask(ws, opn)
            except websockets.ConnectionClosed:
                ans = None
            if ans is not None and ans["type"] == "opened":
                return ws
            await ws.close()
            assert time.monotonic() < deadline, ans
            await asyncio.sleep(0.05)

    async def go():
        a = await opened_stream()
        b = await opened_stream()
        async with connect(base) as c:                  # a third: refused (2 streams at most)
            e = json.loads(await asyncio.wait_for(c.recv(), WAIT_SECONDS))
            assert (e["type"], e["seq"], e["code"]) == ("error", None, "overloaded")
            assert (await closed(c))[0] == 1013
        await a.send(json.dumps({"type": "step", "dx": 0.2}))
        a.transport.abort()                             # killed mid-step: no close frame, the socket dropped
        deadline = time.monotonic() + WAIT_SECONDS
        while True:                                     # its slot is free again as soon as the server notices
            async with connect(base) as d:
                try:
                    ans = await ask(d, opn)
                except websockets.ConnectionClosed:
                    ans = {"type": "error", "code": "overloaded"}     # refused before the open was read
                if ans["type"] == "opened":
                    assert (await ask(d, {"type": "step", "dx": 0.1}))["type"] == "result"
                    break
                assert ans["code"] == "overloaded" and time.monotonic() < deadline
            await asyncio.sleep(0.05)
        assert (await ask(b, {"type": "step", "dx": 0.1}))["type"] == "result"      # b never noticed
        await b.close()

    run(go())
    assert proc.poll() is None
    assert httpx.get(base + "/healthz").status_code == 200
    metrics = httpx.get(base + "/metrics", headers={"X-API-Key": KEY}).text
    assert "tensegrity_stream_connections" in metrics


def test_inverse_mode_approaches_when_asked():
    """In process: ``on_infeasible: "approach"`` in the open; a target beyond the rate limit is approached (the
    command the nearest admissible pose's, within the rate limit), as the library's controller does."""
    from service_helpers import app_client

    F = (0.0, -0.01)
    m = to.Manipulator.uniform(4)
    ctl = PreloadController(m, load=F, rate_limit=0.05, dt=1.0, on_infeasible="approach")
    far = (m.tip(ctl.q) + [-0.5, 1.0]).tolist()
    want = [ctl.step(far).to_dict() for _ in range(2)]
    assert want[0]["method"] == "nearest" and want[1]["tip_error"] < want[0]["tip_error"]
    with app_client(inline_processes=0, heavy_workers=0) as client:
        with client.websocket_connect("/v1/control/stream") as ws:
            ws.send_json({"type": "open", "manipulator": PAPER, "mode": "inverse", "load": list(F),
                          "rate_limit": 0.05, "dt": 1.0, "on_infeasible": "approach"})
            opened = ws.receive_json()
            assert opened["type"] == "opened" and opened["on_infeasible"] == "approach"
            got = []
            for _ in range(2):
                ws.send_json({"type": "step", "target": far})
                got.append(ws.receive_json())
    for g, w in zip(got, want):
        assert g["type"] == "result"
        assert_same(g, w)
    assert np.abs(np.subtract(got[0]["command"], opened["command"])).max() <= 0.05 + 1e-12
