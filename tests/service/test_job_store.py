"""The job store's connections and faults.

* Connections stay bounded whatever the thread churn: in process (threads that each use the store and exit) and
  in a real server whose request threads exit between bursts of requests (``stand_ins``).
* A storage fault clears once its cause is gone, without a restart, and ``/readyz`` reports the store's health
  meanwhile (503 ``degraded``, what fails, no path): a stand-in full disk and a store whose directory appears
  later, in process; a real full disk (a 2 MB tmpfs) under a real server where this machine lets the tests mount
  one.
* The bodies name no path: what failed, not where on disk.
"""

from __future__ import annotations

import http.client
import os
import sqlite3
import subprocess
import threading
import time
import warnings
from contextlib import contextmanager
from pathlib import Path

import pytest

pytest.importorskip("fastapi")
httpx = pytest.importorskip("httpx")

with warnings.catch_warnings():
    warnings.simplefilter("ignore")
    from fastapi.testclient import TestClient

from servers import GENEROUS_ENV, WAIT_SECONDS, clean_env, free_port, stop, uvicorn_factory_command, wait_ready
from service_helpers import service_settings
from stand_ins import server_env

from service.jobs import JobStore
from service.jobs import store as jobs_store
from service.main import create_app

ROOT = Path(__file__).resolve().parents[2]
SPEC = {"analysis": "buckling", "grid": {"n": [3, 4]}}
#: The store's connections at its default size.
MAX_CONNECTIONS = 8
BURSTS, CONCURRENCY = 40, 30

needs_proc = pytest.mark.skipif(not Path("/proc/self/fd").is_dir(), reason="counts descriptors in /proc (Linux)")


def connections_to(db: Path, pid: int | str = "self") -> int:
    """Open SQLite connections of ``pid`` to ``db``: its descriptors on the database file itself."""
    n = 0
    for fd in os.listdir(f"/proc/{pid}/fd"):
        try:
            n += os.readlink(f"/proc/{pid}/fd/{fd}") == str(db)
        except OSError:             # closed meanwhile
            pass
    return n


def get_status(port: int, path: str) -> int:
    """``GET path`` on a fresh connection (the standard library's client: cheap to open 1200 times)."""
    con = http.client.HTTPConnection("127.0.0.1", port, timeout=WAIT_SECONDS)
    try:
        con.request("GET", path)
        return con.getresponse().status
    finally:
        con.close()


def descriptors(pid: int) -> int:
    return len(os.listdir(f"/proc/{pid}/fd"))


def wait_until(pred, what: str) -> None:
    deadline = time.monotonic() + WAIT_SECONDS
    while not pred():
        assert time.monotonic() < deadline, what
        time.sleep(0.05)


def in_threads(fn, n: int) -> list:
    """``fn()`` in ``n`` fresh threads released together; their results (or exceptions)."""
    gate = threading.Barrier(n, timeout=WAIT_SECONDS)
    out: list = []

    def one() -> None:
        try:
            gate.wait()
            out.append(fn())
        except Exception as exc:
            out.append(exc)

    threads = [threading.Thread(target=one) for _ in range(n)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return out


# --------------------------------------------------------------------------- connections
@needs_proc
def test_thread_churn_leaves_at_most_the_stores_connections_open(tmp_path):
    """40 bursts of 30 threads, each reading the store once and exiting: never more than the store's
    connections, all closed with the store."""
    db = tmp_path / "jobs.sqlite3"
    store = JobStore(db)
    store.open()
    store.create({"analysis": "buckling"}, 1, ["n"])
    try:
        for _ in range(BURSTS):
            got = in_threads(lambda: len(store.list(1)), CONCURRENCY)
            assert got == [1] * CONCURRENCY, [g for g in got if g != 1][:3]
        assert connections_to(db) <= MAX_CONNECTIONS
    finally:
        store.close()
    assert connections_to(db) == 0


def test_threads_wait_for_a_connection_when_all_are_lent(tmp_path):
    db = tmp_path / "jobs.sqlite3"
    store = JobStore(db, max_connections=2)
    store.open()
    job = store.create({"analysis": "buckling"}, 1, ["n"])
    with store.connection():                       # one lent for the whole burst: the others share one
        assert in_threads(lambda: store.get(job["id"])["id"], 20) == [job["id"]] * 20
        assert store.open_connections == 2
    store.close()
    assert store.open_connections == 0


@pytest.mark.slow
@needs_proc
def test_a_real_server_keeps_its_connections_bounded_over_thread_churn(tmp_path):
    """A real server whose request threads exit after 50 ms idle: 40 bursts of 30 concurrent
    ``GET /v1/jobs?limit=1``, each burst after the previous one's threads went idle; the server's connections
    to the database stay within the store's and its descriptors do not grow with the bursts."""
    db = tmp_path / "jobs.sqlite3"
    env = server_env(clean_env(TENSEGRITY_JOBS_DB=str(db), TENSEGRITY_WARMUP="false", TENSEGRITY_INLINE_PROCESSES="0",
                               **GENEROUS_ENV))
    port, log = free_port(), tmp_path / "server.log"
    with open(log, "ab") as out:
        proc = subprocess.Popen(uvicorn_factory_command("stand_ins:app_with_short_lived_request_threads", port),
                                env=env, cwd=ROOT, stdout=out, stderr=subprocess.STDOUT)
    base = f"http://127.0.0.1:{port}"
    try:
        wait_ready(proc, base, "/readyz", WAIT_SECONDS, log=log.read_text)
        job_id = httpx.post(base + "/v1/jobs", json=SPEC, timeout=WAIT_SECONDS).json()["id"]
        wait_until(lambda: httpx.get(f"{base}/v1/jobs/{job_id}", params={"limit": 0}, timeout=WAIT_SECONDS)
                   .json()["status"] == "done", "the job ends")
        start = descriptors(proc.pid)
        for _ in range(BURSTS):
            time.sleep(0.3)       # 6x the idle time: the next burst's first request retires the idle threads
            got = in_threads(lambda: get_status(port, "/v1/jobs?limit=1"), CONCURRENCY)
            assert got == [200] * CONCURRENCY, got
        conns, end = connections_to(db, proc.pid), descriptors(proc.pid)
        assert conns <= MAX_CONNECTIONS, (conns, start, end)
        assert end - start < 100, (conns, start, end)       # one connection per fresh thread: > 1000
    finally:
        stop(proc)


# --------------------------------------------------------------------------- faults clear
def _ready(client) -> dict:
    return client.get("/readyz").json()


def _job_done(client, r) -> None:
    assert r.status_code == 202, r.text
    job_id = r.json()["id"]
    wait_until(lambda: client.get(f"/v1/jobs/{job_id}", params={"limit": 0}).json()["status"] == "done",
               "the job ends")


def _check_failing(r, ready, where: Path, words: tuple[str, ...]) -> None:
    """A 503 ``jobs_unavailable`` and a 503 ``degraded`` readiness, both saying what fails and not where."""
    assert r.status_code == 503 and r.json()["code"] == "jobs_unavailable", r.text
    assert any(w in r.json()["message"] for w in words), r.text
    assert ready.status_code == 503, ready.text
    body = ready.json()
    assert body["status"] == "degraded" and body["jobs"]["status"] == "failing", body
    assert any(w in body["jobs"]["message"] for w in words), body
    for text in (r.text, ready.text):
        assert str(where) not in text and "/" not in r.json()["message"], text


def test_a_full_disk_fails_the_store_and_readiness_until_it_is_freed(tmp_path, monkeypatch):
    """A stand-in full disk (every write of SQLite fails with its own "database or disk is full") after a first
    job: 503 for a new job and 503 ``degraded`` readiness; once freed, readiness clears by itself (the store is
    retried, no jobs call needed) and new jobs run."""
    full = threading.Event()

    class FullDisk(sqlite3.Connection):
        def execute(self, sql, *args):
            if full.is_set() and sql.split(None, 1)[0].upper() in ("INSERT", "UPDATE", "DELETE", "BEGIN"):
                raise sqlite3.OperationalError("database or disk is full")
            return super().execute(sql, *args)

    monkeypatch.setattr(jobs_store, "_connect", lambda path: sqlite3.connect(
        path, timeout=30.0, isolation_level=None, check_same_thread=False, factory=FullDisk))
    monkeypatch.setenv("TENSEGRITY_JOBS_RETRY_SECONDS", "0.05")
    with TestClient(create_app(service_settings(jobs_db=str(tmp_path / "jobs.sqlite3")))) as client:
        _job_done(client, client.post("/v1/jobs", json=SPEC))
        assert _ready(client)["status"] == "ready"
        full.set()
        _check_failing(client.post("/v1/jobs", json=SPEC), client.get("/readyz"), tmp_path, ("full",))
        assert not client.app.state.jobs.recover_store()       # a retry while the disk is full fails
        assert client.get("/readyz").status_code == 503
        full.clear()
        wait_until(lambda: _ready(client)["status"] == "ready", "readiness clears once the disk is freed")
        assert _ready(client)["jobs"] == {"status": "ok", "message": None, "since": None}
        _job_done(client, client.post("/v1/jobs", json=SPEC))


def test_a_store_that_cannot_be_created_works_once_its_directory_exists(tmp_path, monkeypatch):
    """The database's directory is a plain file (the store cannot be created): 503 and ``degraded``; once the
    directory exists the store is created by the retry and jobs run (no restart)."""
    monkeypatch.setenv("TENSEGRITY_JOBS_RETRY_SECONDS", "0.05")
    where = tmp_path / "store"
    where.write_text("not a directory")
    with TestClient(create_app(service_settings(jobs_db=str(where / "jobs.sqlite3")))) as client:
        assert _ready(client)["status"] == "ready"            # no job yet: nothing fails
        _check_failing(client.post("/v1/jobs", json=SPEC), client.get("/readyz"), tmp_path, ("open",))
        assert client.get("/v1/jobs").json() == {"jobs": []}
        where.unlink()
        where.mkdir()
        wait_until(lambda: _ready(client)["status"] == "ready", "readiness clears once the directory exists")
        _job_done(client, client.post("/v1/jobs", json=SPEC))


@contextmanager
def small_tmpfs(path: Path, size: str = "2m"):
    """A ``size`` tmpfs mounted on ``path`` (skips the test where this machine does not allow it)."""
    path.mkdir()
    try:
        r = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", str(path)], capture_output=True,
                           text=True, timeout=60)
    except (OSError, subprocess.SubprocessError) as exc:
        pytest.skip(f"cannot mount a tmpfs here: {exc}")
    if r.returncode:
        pytest.skip(f"cannot mount a tmpfs here (mount -t tmpfs needs root or CAP_SYS_ADMIN): {r.stderr.strip()}")
    try:
        yield path
    finally:
        subprocess.run(["umount", "-l", str(path)], capture_output=True, timeout=60)


def fill(disk: Path) -> Path:
    """Fill ``disk`` with one file until it has no space left; the file."""
    filler = disk / "filler"
    fd = os.open(filler, os.O_WRONLY | os.O_CREAT, 0o600)
    try:
        while True:
            os.write(fd, bytes(65536))
    except OSError:
        pass
    finally:
        os.close(fd)
    return filler


@pytest.mark.slow
def test_a_real_full_disk_under_a_real_server_clears_once_freed(tmp_path):
    """A real server whose database lives on a 2 MB tmpfs. The disk full before the first job (the store cannot
    be created) and then full under a working store: each time 503 for a new job and 503 ``degraded`` readiness
    naming no path; each time, once the filler is deleted, readiness clears by itself and jobs run again."""
    with small_tmpfs(tmp_path / "disk") as disk:
        env = clean_env(TENSEGRITY_JOBS_DB=str(disk / "jobs.sqlite3"), TENSEGRITY_JOBS_RETRY_SECONDS="0.1",
                        TENSEGRITY_WARMUP="false", TENSEGRITY_INLINE_PROCESSES="0", **GENEROUS_ENV)
        port, log = free_port(), tmp_path / "server.log"
        with open(log, "ab") as out:
            proc = subprocess.Popen(uvicorn_factory_command("service.main:create_app", port), env=env, cwd=ROOT,
                                    stdout=out, stderr=subprocess.STDOUT)
        try:
            with httpx.Client(base_url=f"http://127.0.0.1:{port}", timeout=WAIT_SECONDS) as client:
                wait_ready(proc, str(client.base_url), "/readyz", WAIT_SECONDS, log=log.read_text)
                for _ in range(2):
                    filler = fill(disk)
                    _check_failing(client.post("/v1/jobs", json=SPEC), client.get("/readyz"), tmp_path,
                                   ("full", "space"))
                    filler.unlink()
                    wait_until(lambda: _ready(client)["status"] == "ready", "readiness clears once freed")
                    _job_done(client, client.post("/v1/jobs", json=SPEC))
        finally:
            stop(proc)


def test_a_job_failed_by_an_os_error_names_no_file(tmp_path, monkeypatch):
    """An OS error that ends a job (its message is in the job's body) says what failed, not which file."""
    from service.jobs import runner as jobs_runner

    secret = tmp_path / "somewhere" / "private"

    def plan_fails(spec):
        raise PermissionError(13, "Permission denied", str(secret))

    monkeypatch.setattr(jobs_runner, "plan_sweep", plan_fails)
    with TestClient(create_app(service_settings(jobs_db=str(tmp_path / "jobs.sqlite3")))) as client:
        job_id = client.post("/v1/jobs", json=SPEC).json()["id"]
        wait_until(lambda: client.get(f"/v1/jobs/{job_id}").json()["status"] == "failed", "the job fails")
        r = client.get(f"/v1/jobs/{job_id}")
        assert "Permission denied" in r.json()["message"] and str(tmp_path) not in r.text, r.text
