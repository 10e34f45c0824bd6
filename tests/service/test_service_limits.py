"""Real server processes: a 504 frees its capacity, heavy requests do not starve light ones, and slow
clients (half-sent requests) neither hold sockets for ever nor lock out new clients.

No verdict here depends on the machine's speed: the heavy design requests are a stand-in that never ends by itself
(``tests/support/stand_ins.py``), the light ones must be answered while the heavy ones are still pending (an order,
not a duration), and every wait ends as soon as what it waits for happens.
"""

from __future__ import annotations

import asyncio
import json
import socket
import sys
import threading
import time

import pytest
from servers import clean_env, free_port, running_server, serve_command, uvicorn_factory_command
from service_helpers import GENEROUS_ENV, WAIT_SECONDS
from stand_ins import NEVER_ENDING_SEGMENTS, server_env

httpx = pytest.importorskip("httpx")
pytest.importorskip("uvicorn")

#: A design request the stand-in never finishes.
HEAVY = {"manipulator": {"n": NEVER_ENDING_SEGMENTS}, "vary": ["a", "b", "k", "L0"]}
#: The time limit of the heavy requests' server: the light request has that long to be answered while they wait.
LIMIT = 10.0


def _readyz_in_flight(base: str) -> int:
    return httpx.get(base + "/readyz", timeout=WAIT_SECONDS).json()["in_flight"]


@pytest.mark.slow
def test_timed_out_design_requests_free_capacity_and_do_not_block_light_ones():
    env = server_env(clean_env(TENSEGRITY_SOLVE_TIMEOUT=str(LIMIT), TENSEGRITY_WORKERS="2",
                               TENSEGRITY_WARMUP="false", TENSEGRITY_HEAVY_GRACE="0.5",
                               TENSEGRITY_INLINE_PROCESSES="0"))
    cmd = uvicorn_factory_command("stand_ins:app_with_designs_that_never_end", free_port())
    with running_server(cmd, env, timeout=WAIT_SECONDS) as (_, base):
        # the design process has started (it imports the library) before the heavy requests
        r = httpx.post(base + "/v1/design/critical-force", json={"manipulator": {"n": 3}, "vary": ["k"]},
                       timeout=WAIT_SECONDS)
        assert r.status_code == 200, r.text
        answers: dict[int, httpx.Response] = {}

        def heavy(i: int) -> None:
            answers[i] = httpx.post(base + "/v1/design/critical-force", json=HEAVY, timeout=WAIT_SECONDS)

        threads = [threading.Thread(target=heavy, args=(i,)) for i in range(2)]
        for t in threads:
            t.start()
        deadline = time.monotonic() + WAIT_SECONDS
        while _readyz_in_flight(base) < 2:                  # both heavy requests are in
            assert time.monotonic() < deadline
            time.sleep(0.02)
        light = httpx.post(base + "/v1/buckling", json={"manipulator": {"n": 5}}, timeout=WAIT_SECONDS)
        assert light.status_code == 200, light.text
        assert not answers                      # answered while both heavy requests were pending
        for t in threads:
            t.join()
        for r in answers.values():
            assert r.status_code == 504, r.text
            assert r.json()["code"] == "timeout"
        # capacity comes back: the stuck design process (it sleeps an hour) is killed after the grace period
        deadline = time.monotonic() + WAIT_SECONDS
        while _readyz_in_flight(base):
            assert time.monotonic() < deadline, "the capacity of the timed-out requests was not freed"
            time.sleep(0.05)
        # and the replacement process (a fresh interpreter: it imports the library first) answers
        r = httpx.post(base + "/v1/design/critical-force", json={"manipulator": {"n": 3}, "vary": ["k"]},
                       timeout=WAIT_SECONDS)
        assert r.status_code == 200, r.text


def _limited(cmd: list[str], nofile: int) -> list[str]:
    """``cmd`` run with a descriptor limit of ``nofile``."""
    code = ("import os, resource, sys; resource.setrlimit(resource.RLIMIT_NOFILE, (%d, %d)); "
            "os.execvp(sys.argv[1], sys.argv[1:])" % (nofile, nofile))
    return [sys.executable, "-c", code, *cmd]


def _closed(sock: socket.socket) -> bool | None:
    """Whether the server closed ``sock`` (EOF, a 408 then EOF, a reset); ``None`` while it is open."""
    try:
        data = sock.recv(4096)
    except BlockingIOError:
        return None
    except ConnectionResetError:
        return True
    assert data == b"" or data.startswith(b"HTTP/1.1 408"), data
    return True


def _count_closed(socks: list[socket.socket], want: int) -> int:
    """Wait until ``want`` of ``socks`` are closed by the server; how many are."""
    for s in socks:
        s.setblocking(False)
    closed: set[int] = set()
    deadline = time.monotonic() + WAIT_SECONDS
    while len(closed) < want and time.monotonic() < deadline:
        closed |= {i for i, s in enumerate(socks) if i not in closed and _closed(s)}
        time.sleep(0.05)
    return len(closed)


def _half_sent(port: int) -> socket.socket:
    s = socket.create_connection(("127.0.0.1", port), timeout=WAIT_SECONDS)
    s.sendall(b"POST /v1/equilibrium HTTP/1.1\r\nHost: x\r\nContent-Length: 100\r\n")   # never finished
    return s


@pytest.mark.slow
def test_half_sent_requests_do_not_lock_out_new_clients():
    """A request timeout far away (600 s): the connection cap alone makes room for new clients, by closing the
    oldest half-sent requests; slow but complete requests are served; malformed HTTP gets the JSON error shape."""
    # 128 descriptors: the connection cap is 128 - 64 = 64; 150 half-sent requests would exhaust them
    env = clean_env(TENSEGRITY_WORKERS="1", TENSEGRITY_WARMUP="false", TENSEGRITY_INLINE_PROCESSES="0",
                    TENSEGRITY_HEAVY_WORKERS="0", TENSEGRITY_REQUEST_TIMEOUT="600", **GENEROUS_ENV)
    port = free_port()
    with running_server(_limited(serve_command(port), 128), env, timeout=WAIT_SECONDS) as (_, base):
        socks = [_half_sent(port) for _ in range(150)]
        try:
            for _ in range(3):          # long before the request timeout: room was made, nobody is locked out
                assert httpx.get(base + "/healthz", timeout=60).status_code == 200
            assert _count_closed(socks, 150 - 64) >= 150 - 64      # the oldest, for the newer clients
        finally:
            for s in socks:
                s.close()
        # a slow but complete request is served
        with socket.create_connection(("127.0.0.1", port), timeout=WAIT_SECONDS) as s:
            s.sendall(b"GET /healthz HTTP/1.1\r\n")
            time.sleep(0.5)
            s.sendall(b"Host: x\r\nConnection: close\r\n\r\n")
            assert s.recv(4096).startswith(b"HTTP/1.1 200")
        # malformed HTTP (refused by the parser, before the app): the JSON error shape, not plain text
        for raw in (b"GARBAGE\r\n\r\n", b"GET /healthz HTTP/1.1\r\nHost x\r\n\r\n",
                    b"POST /v1/equilibrium HTTP/1.1\r\nHost: x\r\nContent-Length: -5\r\n\r\n"):
            with socket.create_connection(("127.0.0.1", port), timeout=WAIT_SECONDS) as s:
                s.sendall(raw)
                data = b""
                while chunk := s.recv(4096):
                    data += chunk
            head, _, body = data.partition(b"\r\n\r\n")
            assert head.startswith(b"HTTP/1.1 400") and b"content-type: application/json" in head.lower(), data
            assert json.loads(body)["code"] == "bad_request", data


@pytest.mark.slow
def test_half_sent_requests_are_closed_by_the_request_timeout():
    env = clean_env(TENSEGRITY_WORKERS="1", TENSEGRITY_WARMUP="false", TENSEGRITY_INLINE_PROCESSES="0",
                    TENSEGRITY_HEAVY_WORKERS="0", TENSEGRITY_REQUEST_TIMEOUT="1.5", **GENEROUS_ENV)
    port = free_port()
    with running_server(serve_command(port), env, timeout=WAIT_SECONDS) as (_, base):
        socks = [_half_sent(port) for _ in range(5)]          # under the cap: only the timeout closes them
        try:
            assert _count_closed(socks, len(socks)) == len(socks)
        finally:
            for s in socks:
                s.close()
        assert httpx.get(base + "/healthz", timeout=60).status_code == 200


@pytest.mark.slow
def test_a_design_solve_stops_itself_at_the_deadline_and_keeps_its_process():
    from fastapi.testclient import TestClient
    from service_helpers import service_settings

    from service.main import create_app

    # n = 16 with every variable: the build takes ~0.2 s, the IPOPT solve ~3 s (cut at 1 s by the library limit
    # inside IPOPT, checked at every iteration): the process answers by itself, long before its grace (60 s) runs
    # out, and nothing is killed
    with TestClient(create_app(service_settings(solve_timeout=1.0, heavy_grace=60.0))) as c:
        heavy = c.app.state.executors.killable
        # the process has started (imported the library: it may take longer than 1 s) before the clock starts
        deadline = time.monotonic() + WAIT_SECONDS
        while c.post("/v1/design/critical-force", json={"manipulator": {"n": 3}, "vary": ["k"]}).status_code != 200:
            assert time.monotonic() < deadline
        r = c.post("/v1/design/critical-force", json={"manipulator": {"n": 16}, "vary": ["a", "b", "k", "L0"]})
        assert r.status_code == 504 and r.json()["code"] == "timeout"
        deadline = time.monotonic() + WAIT_SECONDS
        while heavy.in_flight:
            assert time.monotonic() < deadline
            time.sleep(0.02)
        assert heavy.killed == 0
        assert "tensegrity_design_processes_killed 0.0" in c.get("/metrics").text


# ------------------------------------------------------------------------------------------------ request heads
#: The head bounds of the servers below (lower than the defaults, so the tests send little).
HEAD_BYTES, HEAD_FIELDS = 8192, 20


def _exchange(port: int, *parts: bytes) -> bytes:
    """Send ``parts`` on a new connection; everything the server sends until it closes the connection."""
    with socket.create_connection(("127.0.0.1", port), timeout=WAIT_SECONDS) as s:
        try:
            for part in parts:
                s.sendall(part)
        except OSError:
            pass                            # refused before everything was sent: the answer is in the socket
        data = b""
        try:
            while chunk := s.recv(65536):
                data += chunk
        except ConnectionResetError:
            pass
    return data


def _get(*headers: bytes) -> bytes:
    return b"GET /healthz HTTP/1.1\r\nHost: x\r\n" + b"".join(h + b"\r\n" for h in headers)


class _Transport:
    """Enough of an asyncio transport for uvicorn's protocol: what it writes, whether it closed."""

    def __init__(self) -> None:
        self.out, self.closed, self.eof, self.protocol = b"", False, False, None

    def get_extra_info(self, name, default=None):
        return {"sockname": ("127.0.0.1", 8000), "peername": ("127.0.0.1", 50000)}.get(name, default)

    def write(self, data):
        self.out += data

    def write_eof(self):
        self.eof = True

    def close(self):
        self.closed = True

    def is_closing(self):
        return self.closed

    def get_protocol(self):
        return self.protocol

    def set_protocol(self, protocol):
        self.protocol = protocol

    def pause_reading(self):
        pass

    def resume_reading(self):
        pass


def test_a_head_over_the_bound_is_refused_while_it_arrives():
    """The protocol of ``tensegrity-opt serve`` alone: a head that never ends is answered 431 once it passes the bound
    (the application never called), the connection ends; a head of too many fields likewise; one within the bounds
    reaches the application."""
    from uvicorn.config import Config
    from uvicorn.server import ServerState

    from service.api.connections import protocol_class

    called: list[str] = []

    async def app(scope, receive, send):
        called.append(scope["path"])
        await send({"type": "http.response.start", "status": 200, "headers": [(b"content-length", b"0")]})
        await send({"type": "http.response.body", "body": b""})

    async def feed(*chunks: bytes) -> _Transport:
        config = Config(app=app, lifespan="off")
        config.load()
        cls = protocol_class(600.0, 100, HEAD_BYTES, HEAD_FIELDS)
        proto = cls(config=config, server_state=ServerState(), app_state={})
        transport = _Transport()
        transport.set_protocol(proto)
        proto.connection_made(transport)
        for chunk in chunks:
            proto.data_received(chunk)
        for _ in range(10):
            await asyncio.sleep(0)          # the application's task, if one started
        proto.connection_lost(None)
        return transport

    def status(t: _Transport) -> tuple[bytes, dict]:
        head, _, body = t.out.partition(b"\r\n\r\n")
        return head.split(b"\r\n", 1)[0], (json.loads(body) if body else {})

    unfinished = [_get(b"X-Big: ")] + [b"a" * 1000] * 20         # never ends
    t = asyncio.run(feed(*unfinished))
    line, body = status(t)
    assert line == b"HTTP/1.1 431 Request Header Fields Too Large", t.out
    assert body["code"] == "headers_too_large" and body["details"] == {"max_header_bytes": HEAD_BYTES,
                                                                       "max_headers": HEAD_FIELDS}
    assert t.eof and not called
    t = asyncio.run(feed(_get(*(b"X-%d: 1" % i for i in range(HEAD_FIELDS + 1))) + b"\r\n"))
    assert status(t)[0].startswith(b"HTTP/1.1 431") and not called
    t = asyncio.run(feed(_get(b"X-Big: " + b"a" * (HEAD_BYTES // 2), *(b"X-%d: 1" % i for i in range(10))) + b"\r\n"))
    assert status(t)[0] == b"HTTP/1.1 200 OK" and called == ["/healthz"]


@pytest.mark.slow
def test_request_heads_are_bounded_on_a_real_server():
    """Raw sockets against ``tensegrity-opt serve`` with the head bounds lowered: a header over the bound, too many
    fields, a head that never ends, and the second request of a kept-alive connection over the bound are answered 431
    ``headers_too_large`` in the JSON error shape; heads within the bounds are served."""
    env = clean_env(TENSEGRITY_WORKERS="1", TENSEGRITY_WARMUP="false", TENSEGRITY_INLINE_PROCESSES="0",
                    TENSEGRITY_HEAVY_WORKERS="0", TENSEGRITY_REQUEST_TIMEOUT="600",
                    TENSEGRITY_MAX_HEADER_BYTES=str(HEAD_BYTES), TENSEGRITY_MAX_HEADERS=str(HEAD_FIELDS),
                    **GENEROUS_ENV)
    port = free_port()
    with running_server(serve_command(port), env, timeout=WAIT_SECONDS) as (_, base):
        ok = _get(b"X-Big: " + b"a" * (HEAD_BYTES // 2), *(b"X-%d: 1" % i for i in range(HEAD_FIELDS - 3)),
                  b"Connection: close") + b"\r\n"
        assert _exchange(port, ok).startswith(b"HTTP/1.1 200 OK")
        refused = {
            "one header over the bound": [_get(b"X-Big: " + b"a" * (1 << 20)) + b"\r\n"],
            "too many fields": [_get(*(b"X-%d: 1" % i for i in range(HEAD_FIELDS + 1))) + b"\r\n"],
            "a target over the bound": [b"GET /healthz?" + b"q" * (2 * HEAD_BYTES) + b" HTTP/1.1\r\nHost: x\r\n\r\n"],
            # never ends: refused while it arrives, 600 s before the request timeout
            "a head that never ends": [_get(b"X-Big: ")] + [b"a" * 4096] * (4 * HEAD_BYTES // 4096),
            "the second request of a connection": [_get() + b"\r\n" + _get(b"X-Big: " + b"a" * (2 * HEAD_BYTES))
                                                   + b"\r\n"],
        }
        for case, parts in refused.items():
            data = _exchange(port, *parts)
            if case == "the second request of a connection":
                assert data.startswith(b"HTTP/1.1 200"), data
                data = data[data.find(b"HTTP/1.1 4"):]
            line, _, rest = data.partition(b"\r\n")
            assert line == b"HTTP/1.1 431 Request Header Fields Too Large", (case, data[:300])
            head, _, body = rest.partition(b"\r\n\r\n")
            assert b"content-type: application/json" in head.lower(), (case, data[:300])
            assert json.loads(body)["code"] == "headers_too_large", (case, body)
        assert httpx.get(base + "/healthz", timeout=60).status_code == 200
