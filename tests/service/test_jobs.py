"""Sweep jobs: the ``/v1/jobs`` API (TestClient), the SQLite store, resuming, and a real server
process killed with SIGKILL mid-job and restarted on the same database.

The expected rows are ``tensegrity_opt.applications.sweeps.sweep`` run directly on the same spec.
"""

from __future__ import annotations

import csv
import io
import json
import signal
import sqlite3
import subprocess
import threading
import time
import warnings
from pathlib import Path

import pytest

pytest.importorskip("fastapi")
httpx = pytest.importorskip("httpx")

with warnings.catch_warnings():
    warnings.simplefilter("ignore")
    from fastapi.testclient import TestClient

from servers import clean_env, free_port, stop, uvicorn_factory_command, wait_ready
from service_helpers import GENEROUS_ENV, WAIT_SECONDS, service_settings

from service import jobs
from service.jobs import runner as jobs_runner
from service.jobs import store as jobs_store
from service.main import create_app
from tensegrity_opt.applications import sweeps as S

ROOT = Path(__file__).resolve().parents[2]

#: ~50 ms a point (every equilibrium of an 8-segment chain): long enough to act while it runs.
def slow_spec(points: int) -> dict:
    return {"analysis": "equilibria_count", "manipulator": {"n": 8},
            "grid": {"dx": [round(0.005 * (i + 1), 6) for i in range(points)]}}


def quick_spec(points: int) -> dict:
    """Every equilibrium of a 3-segment chain: a few ms to ~0.1 s a point."""
    return {"analysis": "equilibria_count", "manipulator": {"n": 3},
            "grid": {"dx": [round(0.004 * (i + 1), 6) for i in range(points)]}}


MIXED = {"analysis": "equilibrium", "grid": {"dx": [0.1, 30.0, 0.2], "n": [3, 4]}}


@pytest.fixture()
def api(tmp_path, monkeypatch, request):
    """A TestClient on a fresh database; ``indirect`` parametrisation passes more settings."""
    db = tmp_path / "jobs.sqlite3"
    app = create_app(service_settings(max_segments=50, inline_processes=0, jobs_db=str(db),
                                      **getattr(request, "param", {})))
    with TestClient(app) as client:
        client.db = db
        yield client


def wait_for(client, job_id, pred, timeout=WAIT_SECONDS):
    deadline = time.monotonic() + timeout
    while True:
        job = client.get(f"/v1/jobs/{job_id}", params={"limit": 0}).json()
        if pred(job):
            return job
        assert time.monotonic() < deadline, job
        time.sleep(0.05)


def done(job):
    return job["status"] in jobs.TERMINAL


# --------------------------------------------------------------------------- API
def test_submit_poll_and_results_as_json_and_csv(api):
    r = api.post("/v1/jobs", json=MIXED)
    assert r.status_code == 202, r.text
    body = r.json()
    assert body["status"] == "queued" and body["total"] == 6 and len(body["id"]) == 32
    assert r.headers["location"] == f"/v1/jobs/{body['id']}"
    job = wait_for(api, body["id"], done)
    assert (job["status"], job["done"], job["failed"], job["progress"], job["runs"]) == ("done", 6, 2, 1.0, 1)

    expected = S.sweep(MIXED)
    full = api.get(f"/v1/jobs/{body['id']}").json()
    assert full["columns"] == list(expected.columns) and full["columns"][1:3] == ["dx", "n"]     # grid order kept
    assert full["results"] == list(expected.rows) and full["next_offset"] is None
    assert full["spec"] == S.validate_spec(MIXED)
    page = api.get(f"/v1/jobs/{body['id']}", params={"offset": 2, "limit": 3}).json()
    assert [r["index"] for r in page["results"]] == [2, 3, 4] and page["next_offset"] == 5

    res = api.get(f"/v1/jobs/{body['id']}/results").json()
    assert res["complete"] and res["rows"] == list(expected.rows) and res["columns"] == list(expected.columns)
    assert res["rows"][2]["error"].startswith("unreachable_target: ")

    as_csv = api.get(f"/v1/jobs/{body['id']}/results", params={"format": "csv"})
    assert as_csv.headers["content-type"].startswith("text/csv")
    assert as_csv.text == expected.csv_text()
    by_accept = api.get(f"/v1/jobs/{body['id']}/results", headers={"Accept": "text/csv"})
    assert by_accept.text == as_csv.text
    parsed = list(csv.DictReader(io.StringIO(as_csv.text)))
    assert [int(p["index"]) for p in parsed] == list(range(6))

    listed = api.get("/v1/jobs").json()["jobs"]
    assert [j["id"] for j in listed] == [body["id"]]


def test_unknown_job_is_404_with_the_error_body(api):
    for method, path in (("GET", "/v1/jobs/nope"), ("GET", "/v1/jobs/nope/results"), ("DELETE", "/v1/jobs/nope")):
        r = api.request(method, path)
        assert r.status_code == 404, (method, path)
        assert r.json() == {"code": "not_found", "message": "no job with id 'nope'", "field": "id"}


@pytest.mark.parametrize("spec, code, field", [
    ({"analysis": "buckling", "grid": {"n": [0]}}, "validation_error", "grid.n[0]"),
    ({"analysis": "buckling", "grid": {"n": [4]}, "bogus": 1}, "validation_error", "bogus"),
    ({"analysis": "stiff", "grid": {"n": [4]}}, "validation_error", "analysis"),
    ({"analysis": "equilibrium", "points": [{"dx": "0.1"}]}, "validation_error", "points[0].dx"),
    ({"analysis": "buckling", "grid": {"dx": [0.1]}}, "invalid_parameter", "grid.dx"),
    ({"analysis": "buckling", "grid": {"n": [4]}, "points": [{}]}, "invalid_parameter", "grid"),
    ({"analysis": "equilibrium", "points": [{}, {"dx": 0.1, "load": [1, 0]}]}, "invalid_parameter",
     "points[1].load"),
    ({"analysis": "buckling", "grid": {"n": [4, 60]}}, "too_many_segments", "grid.n[1]"),
    ({"analysis": "buckling", "grid": {"a": [1.0] * 400, "b": [1.0] * 400}}, "sweep_too_large", "grid"),
])
def test_bad_spec_is_422_naming_the_field(api, spec, code, field):
    r = api.post("/v1/jobs", json=spec)
    assert r.status_code == 422, r.text
    assert (r.json()["code"], r.json()["field"]) == (code, field)
    assert api.get("/v1/jobs").json()["jobs"] == []
    assert api.get("/v1/jobs/x", params={"limit": -1}).status_code == 422


@pytest.mark.slow
@pytest.mark.parametrize("api", [{"jobs_max_running": 1}], indirect=True)
def test_cancel_keeps_finished_points_and_the_runner_goes_on(api):
    long_id = api.post("/v1/jobs", json=slow_spec(200)).json()["id"]
    next_id = api.post("/v1/jobs", json=MIXED).json()["id"]
    queued_id = api.post("/v1/jobs", json=MIXED).json()["id"]
    wait_for(api, long_id, lambda j: j["done"] >= 3)

    r = api.post(f"/v1/jobs/{queued_id}/cancel")                  # queued: cancelled at once
    assert r.status_code == 200 and r.json()["status"] == "cancelled" and r.json()["done"] == 0
    r = api.post(f"/v1/jobs/{long_id}/cancel")                    # running: after its current point
    assert r.status_code == 200 and r.json()["status"] == "cancelled"
    r = api.post(f"/v1/jobs/{long_id}/cancel")                    # again: the same answer (idempotent)
    assert r.status_code == 200 and r.json()["status"] == "cancelled", r.text
    wait_for(api, next_id, done)
    assert api.get(f"/v1/jobs/{next_id}").json()["status"] == "done"
    r = api.post(f"/v1/jobs/{next_id}/cancel")                    # it has ended: nothing to cancel
    assert r.status_code == 409 and r.json()["code"] == "job_finished" and r.json()["details"] == {"status": "done"}
    cancelled = api.get(f"/v1/jobs/{long_id}/results").json()
    assert cancelled["status"] == "cancelled" and not cancelled["complete"]
    assert 3 <= cancelled["done"] < 200
    assert [row["index"] for row in cancelled["rows"]] == list(range(cancelled["done"]))
    assert cancelled["rows"][0] == S.sweep(slow_spec(200), should_stop=lambda: False, skip=range(1, 200)).rows[0]
    time.sleep(0.2)
    assert api.get(f"/v1/jobs/{long_id}").json()["done"] == cancelled["done"]     # nothing after the cancel
    assert api.get(f"/v1/jobs/{queued_id}").json()["done"] == 0


def test_an_unusable_database_is_503_and_the_rest_of_the_service_runs(tmp_path, monkeypatch):
    bad = tmp_path / "a-directory"
    bad.mkdir()
    app = create_app(service_settings(jobs_db=str(bad)))
    with TestClient(app) as client:
        r = client.post("/v1/jobs", json=MIXED)
        assert r.status_code == 503 and r.json()["code"] == "jobs_unavailable"
        assert client.get("/v1/jobs/x").status_code == 503
        assert client.post("/v1/buckling", json={"manipulator": {"n": 4}}).status_code == 200


def test_an_invalid_jobs_setting_fails_the_start_not_the_construction(monkeypatch):
    monkeypatch.setenv("TENSEGRITY_JOBS_SCHEDULER", "nowhere")
    runner = jobs.JobRunner()
    with pytest.raises(RuntimeError, match="TENSEGRITY_JOBS_"):
        runner.start()


# --------------------------------------------------------------------------- store and runner, in process
def _left_running(db: Path, spec: dict, stored: dict[int, dict]) -> str:
    """A job as a killed process leaves it: status running, some points stored."""
    runner = jobs.JobRunner(db_path=db)
    norm, total, cols = runner.validate(spec)
    store = jobs.JobStore(db)
    store.open()
    job = store.create(norm, total, cols)
    assert store.start_run(job["id"])
    for i, row in stored.items():
        store.add_point(job["id"], i, row)
    store.close()
    return job["id"]


def test_restart_resumes_a_running_job_without_touching_stored_points(tmp_path):
    db = tmp_path / "jobs.sqlite3"
    expected = S.sweep(MIXED).rows
    marker = {**expected[0], "energy": 123.0}              # proves row 0 is never recomputed or rewritten
    job_id = _left_running(db, MIXED, {0: marker, 3: expected[3]})
    runner = jobs.JobRunner(db_path=db, resume=True).start()
    try:
        deadline = time.monotonic() + WAIT_SECONDS
        while runner.get(job_id)["status"] != "done":
            assert time.monotonic() < deadline
            time.sleep(0.05)
        job = runner.get(job_id)
        assert (job["done"], job["runs"]) == (6, 2)
        assert runner.rows(job_id) == [marker, *expected[1:]]
    finally:
        runner.stop()


def test_restart_without_resume_marks_the_job_interrupted(tmp_path):
    db = tmp_path / "jobs.sqlite3"
    job_id = _left_running(db, MIXED, {1: S.sweep(MIXED).rows[1]})
    runner = jobs.JobRunner(db_path=db, resume=False).start()
    try:
        job = runner.get(job_id)
        assert job["status"] == "interrupted" and job["done"] == 1 and "kept" in job["message"]
        time.sleep(0.3)
        assert runner.get(job_id)["done"] == 1
    finally:
        runner.stop()


@pytest.mark.slow
def test_graceful_stop_requeues_and_the_next_start_finishes(tmp_path):
    db = tmp_path / "jobs.sqlite3"
    runner = jobs.JobRunner(db_path=db).start()
    job_id = runner.submit(slow_spec(40))["id"]
    deadline = time.monotonic() + WAIT_SECONDS
    while runner.get(job_id)["done"] < 2:
        assert time.monotonic() < deadline
        time.sleep(0.02)
    runner.stop()
    store = jobs.JobStore(db)
    job = store.get(job_id)
    store.close()
    assert job["status"] == "queued" and 2 <= job["done"] < 40 and "resumes" in job["message"]
    runner = jobs.JobRunner(db_path=db).start()
    try:
        deadline = time.monotonic() + WAIT_SECONDS
        while runner.get(job_id)["status"] != "done":
            assert time.monotonic() < deadline
            time.sleep(0.05)
        assert [r["index"] for r in runner.rows(job_id)] == list(range(40))
        assert runner.get(job_id)["runs"] == 2
    finally:
        runner.stop()


def test_no_database_file_until_the_first_job(tmp_path):
    db = tmp_path / "sub" / "jobs.sqlite3"
    runner = jobs.JobRunner(db_path=db).start()
    try:
        assert runner.list() == [] and not db.exists()
        with pytest.raises(jobs.JobNotFound):
            runner.get("x")
        runner.submit({"analysis": "buckling", "grid": {"n": [3]}})
        assert db.exists()
        with sqlite3.connect(db) as con:
            assert con.execute("PRAGMA journal_mode").fetchone()[0] == "wal"
    finally:
        runner.stop()


@pytest.mark.slow
def test_a_job_on_a_dask_cluster_stores_the_serial_rows(tmp_path):
    """TENSEGRITY_JOBS_SCHEDULER=tcp://...: points solved by Dask worker processes, rows stored by the runner."""
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cl:
        runner = jobs.JobRunner(db_path=tmp_path / "jobs.sqlite3", scheduler=cl.scheduler_address, chunk_size=2).start()
        try:
            job_id = runner.submit(MIXED)["id"]
            deadline = time.monotonic() + WAIT_SECONDS
            while runner.get(job_id)["status"] not in jobs.TERMINAL:
                assert time.monotonic() < deadline
                time.sleep(0.05)
            assert runner.get(job_id)["status"] == "done"
            assert runner.rows(job_id) == list(S.sweep(MIXED).rows)
        finally:
            runner.stop()


# --------------------------------------------------------------------------- a real server, killed
def start_server(db: Path, log: Path) -> tuple[subprocess.Popen, str]:
    port = free_port()
    env = clean_env(TENSEGRITY_JOBS_DB=str(db), TENSEGRITY_WARMUP="false", TENSEGRITY_WORKERS="1", **GENEROUS_ENV)
    cmd = uvicorn_factory_command("service.main:create_app", port)
    with open(log, "ab") as out:      # the child keeps its own copy of the descriptor
        proc = subprocess.Popen(cmd, env=env, cwd=ROOT, stdout=out, stderr=subprocess.STDOUT)
    base = f"http://127.0.0.1:{port}"
    wait_ready(proc, base, "/healthz", WAIT_SECONDS, log=lambda: log.read_text(errors="replace"))
    return proc, base


def stored_points(db: Path, job_id: str) -> dict[int, str]:
    with sqlite3.connect(db) as con:
        return dict(con.execute("SELECT idx, row FROM points WHERE job_id = ?", (job_id,)).fetchall())


@pytest.mark.slow
def test_sigkill_mid_job_loses_no_point_and_the_restart_resumes(tmp_path):
    db, log = tmp_path / "jobs.sqlite3", tmp_path / "server.log"
    total = 160
    spec = slow_spec(total)
    proc, base = start_server(db, log)
    try:
        job_id = httpx.post(base + "/v1/jobs", json=spec, timeout=WAIT_SECONDS).json()["id"]
        deadline = time.monotonic() + WAIT_SECONDS
        while True:
            seen = httpx.get(f"{base}/v1/jobs/{job_id}/results", timeout=WAIT_SECONDS).json()
            if seen["done"] >= 15:
                break
            assert time.monotonic() < deadline, seen
            time.sleep(0.05)
        proc.send_signal(signal.SIGKILL)
        proc.wait(WAIT_SECONDS)
    finally:
        if proc.poll() is None:
            proc.kill()
    assert proc.returncode == -signal.SIGKILL

    before = stored_points(db, job_id)
    assert 15 <= len(before) < total, len(before)
    for row in seen["rows"]:                          # every point the server reported is in the file, unchanged
        assert json.loads(before[row["index"]]) == row
    with sqlite3.connect(db) as con:
        assert con.execute("SELECT status FROM jobs WHERE id = ?", (job_id,)).fetchone()[0] == "running"

    proc, base = start_server(db, log)
    try:
        deadline = time.monotonic() + WAIT_SECONDS     # ~150 points of ~0.4 s, many times that on a loaded machine
        while True:
            job = httpx.get(f"{base}/v1/jobs/{job_id}", params={"limit": 0}, timeout=WAIT_SECONDS).json()
            if job["status"] in jobs.TERMINAL:
                break
            assert time.monotonic() < deadline, job
            time.sleep(0.1)
        assert (job["status"], job["done"], job["runs"]) == ("done", total, 2)
        rows = httpx.get(f"{base}/v1/jobs/{job_id}/results", timeout=WAIT_SECONDS).json()["rows"]
    finally:
        stop(proc, grace=20)

    assert [r["index"] for r in rows] == list(range(total))            # all points, no duplicates
    after = stored_points(db, job_id)
    assert len(after) == total
    with sqlite3.connect(db) as con:
        assert con.execute("SELECT COUNT(*), COUNT(DISTINCT idx) FROM points WHERE job_id = ?",
                           (job_id,)).fetchone() == (total, total)
    assert all(after[i] == text for i, text in before.items())          # stored before the kill: byte-identical
    assert not any(r["error"] for r in rows)
    for i in (0, len(before), total - 1):               # before and after the kill: the library's numbers
        point = {"dx": spec["grid"]["dx"][i]}
        assert {k: rows[i][k] for k in S.RESULT_COLUMNS["equilibria_count"]} == S.evaluate_point(spec, point)


# --------------------------------------------------------------------------- scheduling, limits, owners
def _wait(pred, timeout=WAIT_SECONDS, what=""):
    deadline = time.monotonic() + timeout
    while not pred():
        assert time.monotonic() < deadline, what
        time.sleep(0.02)


def _settled(count, quiet: float, timeout: float = WAIT_SECONDS) -> int:
    """The value of ``count()`` once it has not changed for ``quiet`` seconds."""
    deadline = time.monotonic() + timeout
    last, since = count(), time.monotonic()
    while time.monotonic() - since < quiet:
        assert time.monotonic() < deadline, "still changing"
        time.sleep(0.05)
        now = count()
        if now != last:
            last, since = now, time.monotonic()
    return last


def _runner(db, **kw):
    kw.setdefault("lease_seconds", 0.6)
    return jobs.JobRunner(db_path=db, **kw).start()


@pytest.mark.slow
def test_a_point_over_the_time_limit_is_a_timeout_row_and_the_job_goes_on(tmp_path, monkeypatch):
    """Point 1 would run forever (a Python loop inside the solve): it is interrupted at the limit, its row
    is the error ``timeout: ...`` and points 0 and 2 are computed as usual (well within the limit: a point of a
    4-segment chain takes milliseconds, its first one builds the thread's solvers in a fraction of a second)."""
    spec = {"analysis": "equilibrium", "grid": {"dx": [0.1, 0.2, 0.3]}}
    real = jobs_runner.solve_chunk
    stuck = []

    def solve(header, pcols, rcols, items):
        if items[0][0] == 1:
            stuck.append(time.monotonic())
            while True:               # never returns by itself
                time.sleep(0.005)
        return real(header, pcols, rcols, items)

    monkeypatch.setattr(jobs_runner, "solve_chunk", solve)
    runner = _runner(tmp_path / "jobs.sqlite3", point_timeout=10.0)
    try:
        job_id = runner.submit(spec)["id"]
        _wait(lambda: runner.get(job_id)["status"] in jobs.TERMINAL)
        job = runner.get(job_id)
        assert (job["status"], job["done"], job["failed"]) == ("done", 3, 1)
        rows = runner.rows(job_id)
        assert rows[1]["error"].startswith("timeout: the point did not finish within 10 s")
        assert rows[1]["dx"] == 0.2 and rows[1]["energy"] is None and rows[1]["q"] is None
        assert [rows[0], rows[2]] == [r for r in S.sweep(spec).rows if r["index"] != 1]
        assert len(stuck) == 1
    finally:
        runner.stop()


def test_a_real_long_point_times_out(tmp_path):
    """The limit also cuts a library computation (a multi-start equilibrium search on a long chain)."""
    runner = _runner(tmp_path / "jobs.sqlite3", point_timeout=0.02)
    try:
        job_id = runner.submit({"analysis": "equilibria_count", "manipulator": {"n": 60},
                                "points": [{"dx": 0.3}]})["id"]
        _wait(lambda: runner.get(job_id)["status"] in jobs.TERMINAL)
        assert runner.rows(job_id)[0]["error"].startswith("timeout: ")
        assert runner.get(job_id)["status"] == "done"
    finally:
        runner.stop()


def test_at_most_max_running_jobs_and_a_huge_job_does_not_hold_a_small_one(tmp_path):
    """Two runner threads: two big jobs run at once (never three), and a small job submitted after them
    finishes while they still run, because jobs take turns of ``slice_seconds``."""
    runner = _runner(tmp_path / "jobs.sqlite3", max_running=2, slice_seconds=0.2)
    big = {"analysis": "equilibria_count", "manipulator": {"n": 3},
           "grid": {"dx": [round(0.002 * (i + 1), 6) for i in range(300)]}}
    try:
        a, b = runner.submit(big)["id"], runner.submit(big)["id"]
        _wait(lambda: len(runner.running_here()) == 2, what="two jobs running")
        small = runner.submit(MIXED)["id"]
        most = 0

        def small_done():
            nonlocal most
            most = max(most, len(runner.running_here()))
            return runner.get(small)["status"] == "done"

        _wait(small_done, what="the small job finishes")
        assert most <= 2
        progress = []
        for j in (a, b):                  # neither is near its end (a thread's first point builds its solvers)
            job = runner.get(j)
            assert job["status"] in ("queued", "running") and job["done"] < 300
            progress.append(job["done"])
            runner.cancel(j)
        assert max(progress) > 0
        assert runner.rows(small) == list(S.sweep(MIXED).rows)
        assert runner.get(small)["runs"] == 1
    finally:
        runner.stop()


@pytest.mark.parametrize("api", [{"api_keys": ["key-one", "key-two"]}], indirect=True)
def test_jobs_belong_to_the_api_key_that_submitted_them(api):
    one, two = {"X-API-Key": "key-one"}, {"X-API-Key": "key-two"}
    job_id = api.post("/v1/jobs", json=MIXED, headers=one).json()["id"]
    other = api.post("/v1/jobs", json={"analysis": "buckling", "grid": {"n": [3]}}, headers=two).json()["id"]
    assert api.get("/v1/jobs", headers=one).status_code == 200
    assert [j["id"] for j in api.get("/v1/jobs", headers=one).json()["jobs"]] == [job_id]
    assert [j["id"] for j in api.get("/v1/jobs", headers=two).json()["jobs"]] == [other]
    for method, path in (("GET", f"/v1/jobs/{job_id}"), ("GET", f"/v1/jobs/{job_id}/results"),
                         ("GET", f"/v1/jobs/{job_id}/results?format=csv"), ("DELETE", f"/v1/jobs/{job_id}")):
        r = api.request(method, path, headers=two)
        assert r.status_code == 404, (method, path)
        assert r.json() == {"code": "not_found", "message": f"no job with id {job_id!r}", "field": "id"}
    assert api.get(f"/v1/jobs/{job_id}").status_code == 401
    _wait(lambda: api.get(f"/v1/jobs/{job_id}", headers=one).json()["status"] == "done")
    assert api.get(f"/v1/jobs/{job_id}/results", headers=one).json()["rows"] == list(S.sweep(MIXED).rows)
    with sqlite3.connect(api.db) as con:
        owners = dict(con.execute("SELECT id, owner FROM jobs"))
    assert owners == {job_id: jobs.owner_hash("key-one"), other: jobs.owner_hash("key-two")}
    raw = b"".join(p.read_bytes() for p in api.db.parent.glob("jobs.sqlite3*"))
    assert b"key-one" not in raw and b"key-two" not in raw
    assert api.delete(f"/v1/jobs/{job_id}", headers=one).status_code == 204


@pytest.mark.slow
def test_delete_removes_a_finished_job_and_a_running_one(api):
    done_id = api.post("/v1/jobs", json=MIXED).json()["id"]
    wait_for(api, done_id, done)
    r = api.delete(f"/v1/jobs/{done_id}")
    assert r.status_code == 204 and r.content == b""
    assert api.get(f"/v1/jobs/{done_id}").status_code == 404
    assert api.delete(f"/v1/jobs/{done_id}").status_code == 404
    with sqlite3.connect(api.db) as con:
        assert con.execute("SELECT COUNT(*) FROM points WHERE job_id = ?", (done_id,)).fetchone() == (0,)

    long_id = api.post("/v1/jobs", json=slow_spec(100)).json()["id"]
    wait_for(api, long_id, lambda j: j["done"] >= 1)
    r = api.delete(f"/v1/jobs/{long_id}")                                 # running: cancelled, then removed
    assert r.status_code == 204 and r.content == b""
    assert api.get(f"/v1/jobs/{long_id}").status_code == 404
    assert api.delete(f"/v1/jobs/{long_id}").status_code == 404
    time.sleep(0.3)                       # the point in progress when cancelled stores nothing
    with sqlite3.connect(api.db) as con:
        assert con.execute("SELECT COUNT(*) FROM points WHERE job_id = ?", (long_id,)).fetchone() == (0,)


def test_retention_deletes_old_finished_jobs_at_start(tmp_path):
    db = tmp_path / "jobs.sqlite3"
    runner = _runner(db)
    ids = [runner.submit({"analysis": "buckling", "grid": {"n": [3]}})["id"] for _ in range(3)]
    running = runner.submit(slow_spec(200))["id"]
    _wait(lambda: all(runner.get(i)["status"] == "done" for i in ids))
    runner.stop()
    old, recent, _ = ids
    with sqlite3.connect(db) as con:
        con.execute("UPDATE jobs SET finished_at = ? WHERE id = ?", (time.time() - 8 * 86400, old))
        con.execute("UPDATE jobs SET finished_at = ? WHERE id = ?", (time.time() - 6 * 86400, recent))
        con.execute("UPDATE jobs SET created_at = ? WHERE id = ?", (time.time() - 30 * 86400, running))
    keep = jobs.JobRunner(db_path=db, retention_days=0).start()    # 0: kept forever
    try:
        assert {j["id"] for j in keep.list()} == {*ids, running}
    finally:
        keep.stop()
    runner = jobs.JobRunner(db_path=db, retention_days=7).start()
    try:
        assert {j["id"] for j in runner.list()} == {recent, ids[2], running}
        with sqlite3.connect(db) as con:
            assert con.execute("SELECT COUNT(*) FROM points WHERE job_id = ?", (old,)).fetchone() == (0,)
        runner.cancel(running)
    finally:
        runner.stop()


@pytest.mark.slow
def test_two_runners_on_one_file_one_runs_a_job_cancel_and_takeover_cross(tmp_path, monkeypatch):
    """Two runners (as two servers) share the file: a job runs in one at a time; a cancel through the other
    stops it; a runner that stops renewing loses the job to the other, which finishes it, and the first
    stops once it sees the lost lease (storing nothing meanwhile). From its third point on, the second job waits
    for the test's word (however fast the machine computes, the job cannot end before the takeover is seen)."""
    db = tmp_path / "jobs.sqlite3"
    gate = threading.Event()
    real = jobs_runner.solve_chunk

    def solve(header, pcols, rcols, items):
        if items[0][0] >= 2:                  # patched once the first job has stopped: the second job's points
            gate.wait(WAIT_SECONDS)
        return real(header, pcols, rcols, items)

    a = _runner(db)
    b = _runner(db)
    try:
        job_id = a.submit(quick_spec(200))["id"]
        _wait(lambda: a.get(job_id)["done"] >= 2)
        assert a.running_here() == [job_id] and b.running_here() == [] and b.points_computed == 0
        assert b.cancel(job_id)["status"] == "cancelled"
        assert a.wait_idle(WAIT_SECONDS)                      # at its next lease renewal (0.2 s) and point
        n = a.get(job_id)["done"]
        time.sleep(0.3)
        assert a.get(job_id)["done"] == n and b.points_computed == 0

        spec = quick_spec(20)
        monkeypatch.setattr(jobs_runner, "solve_chunk", solve)
        job_id = a.submit(spec)["id"]
        _wait(lambda: job_id in a.running_here() + b.running_here() and a.get(job_id)["done"] >= 2)
        first, second = (a, b) if a.running_here() == [job_id] else (b, a)
        assert second.running_here() == []
        renew = first.store.renew
        first.store.renew = lambda *args: True                # a hung server: no renewal
        _wait(lambda: second.running_here() == [job_id], what="the other runner takes the job over")
        gate.set()
        first.store.renew = renew
        _wait(lambda: first.running_here() == [], what="the first runner stops")
        _wait(lambda: b.get(job_id)["status"] == "done")
        job = b.get(job_id)
        assert (job["done"], job["runs"]) == (20, 2) and job["lease_owner"] == second.id
        assert [r["index"] for r in b.rows(job_id)] == list(range(20))
    finally:
        a.stop()
        b.stop()


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("fault", ["garbage", "deleted", "read-only"])
def test_every_storage_fault_is_503_jobs_unavailable(api, monkeypatch, fault):
    job_id = api.post("/v1/jobs", json=MIXED).json()["id"]
    wait_for(api, job_id, done)
    runner = api.app.state.jobs
    db = api.db
    if fault == "garbage":
        runner.store.close()                  # a fresh connection reads the damaged file (no page cache)
        runner.store._closed = False
        with sqlite3.connect(db) as con:
            con.execute("PRAGMA wal_checkpoint(TRUNCATE)")
        size = db.stat().st_size
        with open(db, "r+b") as fh:
            fh.write(bytes(range(256)) * (size // 256 + 1))
    elif fault == "deleted":
        for p in db.parent.glob("jobs.sqlite3*"):
            p.unlink()
    else:
        runner.store.close()
        runner.store._closed = False
        monkeypatch.setattr(jobs_store, "_connect", lambda path: sqlite3.connect(
            f"file:{path}?mode=ro", uri=True, timeout=1.0, isolation_level=None, check_same_thread=False))
    calls = [("POST", "/v1/jobs", MIXED), ("DELETE", f"/v1/jobs/{job_id}", None)]
    if fault != "read-only":                  # reading a read-only file works
        calls += [("GET", "/v1/jobs", None), ("GET", f"/v1/jobs/{job_id}", None),
                  ("GET", f"/v1/jobs/{job_id}/results", None), ("GET", f"/v1/jobs/{job_id}/results?format=csv", None)]
    for method, path, body in calls:
        r = api.request(method, path, json=body)
        assert r.status_code == 503, (method, path, r.text)
        assert r.json()["code"] == "jobs_unavailable" and r.headers["retry-after"], r.text
        assert str(db.parent) not in r.text, r.text                      # what failed, not where on disk
    ready = api.get("/readyz")
    assert ready.status_code == 503 and ready.json()["jobs"]["status"] == "failing", ready.text
    assert str(db.parent) not in ready.text, ready.text
    if fault == "deleted":
        assert "deleted" in r.json()["message"] and not db.exists()       # nothing silently recreated
    assert api.post("/v1/buckling", json={"manipulator": {"n": 4}}).status_code == 200


@pytest.mark.parametrize("api", [{"jobs_results_max_limit": 4}], indirect=True)
def test_results_are_paged_and_csv_is_streamed_in_batches(api, monkeypatch):
    from service.api.routes import jobs as routes
    job_id = api.post("/v1/jobs", json=MIXED).json()["id"]
    wait_for(api, job_id, done)
    expected = S.sweep(MIXED)
    first = api.get(f"/v1/jobs/{job_id}/results").json()          # default limit: min(1000, the maximum)
    assert (first["offset"], first["limit"], first["next_offset"], first["done"]) == (0, 4, 4, 6)
    assert first["rows"] == list(expected.rows[:4])
    last = api.get(f"/v1/jobs/{job_id}/results", params={"offset": first["next_offset"]}).json()
    assert last["rows"] == list(expected.rows[4:]) and last["next_offset"] is None
    page = api.get(f"/v1/jobs/{job_id}/results", params={"offset": 1, "limit": 2}).json()
    assert [r["index"] for r in page["rows"]] == [1, 2] and page["next_offset"] == 3
    cut = api.get(f"/v1/jobs/{job_id}/results", params={"limit": 10_000, "offset": 1}).json()   # to the maximum
    assert (cut["limit"], cut["next_offset"], len(cut["rows"])) == (4, 5, 4)

    batches = []
    real = jobs.JobStore.row_batches

    def counted(self, *args, **kwargs):
        for b in real(self, *args, **kwargs):
            batches.append(len(b))
            yield b

    monkeypatch.setattr(routes, "CSV_BATCH", 2)
    monkeypatch.setattr(jobs.JobStore, "row_batches", counted)
    full = api.get(f"/v1/jobs/{job_id}/results", params={"format": "csv"})      # all rows: no JSON maximum
    assert full.text == expected.csv_text() and batches == [2, 2, 2]
    assert full.headers["x-total-rows"] == "6" and "x-next-offset" not in full.headers
    part = api.get(f"/v1/jobs/{job_id}/results", params={"offset": 1, "limit": 3}, headers={"Accept": "text/csv"})
    lines = expected.csv_text().splitlines(keepends=True)
    assert part.text == "".join([lines[0], *lines[2:5]]) and part.headers["x-next-offset"] == "4"


def _lease_owner_pid(db: Path, job_id: str) -> int | None:
    with sqlite3.connect(db) as con:
        r = con.execute("SELECT lease_owner FROM jobs WHERE id = ? AND status = 'running'", (job_id,)).fetchone()
    return int(r[0].rpartition(":")[2].split("-")[0]) if r and r[0] else None


@pytest.mark.slow
def test_two_real_servers_share_one_file_cancel_crosses_and_a_killed_servers_job_moves(tmp_path):
    """Two server processes on one database (lease 1 s): a job runs in one of them only; a cancel through
    the other stops it; SIGKILL of the server running a job hands the job to the other after its lease,
    which finishes it with every point once."""
    db = tmp_path / "jobs.sqlite3"
    extra = {"TENSEGRITY_JOBS_LEASE_SECONDS": "1", "TENSEGRITY_INLINE_PROCESSES": "0"}
    procs, bases = [], []
    try:
        for k in range(2):
            port = free_port()
            env = clean_env(TENSEGRITY_JOBS_DB=str(db), TENSEGRITY_WARMUP="false", TENSEGRITY_WORKERS="1", **extra,
                            **GENEROUS_ENV)
            log = tmp_path / f"server{k}.log"
            with open(log, "ab") as out:
                procs.append(subprocess.Popen(uvicorn_factory_command("service.main:create_app", port),
                                              env=env, cwd=ROOT, stdout=out, stderr=subprocess.STDOUT))
            bases.append(f"http://127.0.0.1:{port}")
        for proc, base, k in zip(procs, bases, range(2)):
            wait_ready(proc, base, "/healthz", WAIT_SECONDS,
                       log=lambda k=k: (tmp_path / f"server{k}.log").read_text())
        pids = [p.pid for p in procs]

        job_id = httpx.post(bases[0] + "/v1/jobs", json=quick_spec(200), timeout=WAIT_SECONDS).json()["id"]
        _wait(lambda: httpx.get(f"{bases[1]}/v1/jobs/{job_id}", params={"limit": 0}).json()["done"] >= 3)
        holder = _lease_owner_pid(db, job_id)
        assert holder in pids
        other = bases[1 - pids.index(holder)]
        r = httpx.post(f"{other}/v1/jobs/{job_id}/cancel", timeout=WAIT_SECONDS)
        assert r.status_code == 200 and r.json()["status"] == "cancelled"
        # the holder stops at its next lease renewal (1/3 s) and point: the stored points stop growing, short of
        # the 200 a holder that went on would store (a few ms to 0.1 s a point)
        n = _settled(lambda: len(stored_points(db, job_id)), quiet=3.0)
        assert n < 200

        total = 16
        spec = quick_spec(total)
        job_id = httpx.post(bases[1] + "/v1/jobs", json=spec, timeout=WAIT_SECONDS).json()["id"]
        _wait(lambda: len(stored_points(db, job_id)) >= 3 and _lease_owner_pid(db, job_id) is not None)
        victim = pids.index(_lease_owner_pid(db, job_id))
        procs[victim].send_signal(signal.SIGKILL)
        procs[victim].wait(WAIT_SECONDS)
        survivor = bases[1 - victim]
        _wait(lambda: httpx.get(f"{survivor}/v1/jobs/{job_id}", params={"limit": 0}).json()["status"] == "done")
        job = httpx.get(f"{survivor}/v1/jobs/{job_id}", params={"limit": 0}).json()
        assert (job["done"], job["runs"]) == (total, 2)
        with sqlite3.connect(db) as con:
            assert con.execute("SELECT COUNT(*), COUNT(DISTINCT idx) FROM points WHERE job_id = ?",
                               (job_id,)).fetchone() == (total, total)
    finally:
        for proc in procs:
            stop(proc, grace=20)


def test_a_cancel_or_a_shutdown_frees_the_thread_of_a_long_point_at_once(tmp_path, monkeypatch):
    """A point that would run for minutes is abandoned by a cancel (nothing stored for it) and by a
    shutdown (the job goes back to queued and computes that point again on resume)."""
    stuck = threading.Event()
    real = jobs_runner.solve_chunk

    def solve(header, pcols, rcols, items):
        if items[0][0] == 1:
            stuck.set()
            while True:
                time.sleep(0.005)
        return real(header, pcols, rcols, items)

    monkeypatch.setattr(jobs_runner, "solve_chunk", solve)
    db = tmp_path / "jobs.sqlite3"
    runner = _runner(db, point_timeout=120, max_running=1)
    spec = {"analysis": "equilibrium", "grid": {"dx": [0.1, 0.2, 0.3]}}
    try:
        job_id = runner.submit(spec)["id"]
        assert stuck.wait(WAIT_SECONDS)
        runner.cancel(job_id)
        assert runner.wait_idle(WAIT_SECONDS)
        assert [r["index"] for r in runner.rows(job_id)] == [0]
        stuck.clear()
        job_id = runner.submit(spec)["id"]
        assert stuck.wait(WAIT_SECONDS)
    finally:
        t0 = time.monotonic()
        runner.stop()               # its default timeout, 30 s, is what a point it waited for would take
    assert time.monotonic() - t0 < 20.0
    store = jobs.JobStore(db)
    job = store.get(job_id)
    store.close()
    assert (job["status"], job["done"]) == ("queued", 1)


@pytest.mark.parametrize("api", [{"max_response_bytes": 1500}], indirect=True)
def test_result_pages_are_bounded_and_limit_0_has_no_next_page(api):
    # pages are rendered in the thread pool within max_response_bytes (422 naming `limit`), like every
    # other answer; limit = 0 gives the counts only, not a next_offset equal to offset (a client loop)
    job_id = api.post("/v1/jobs", json=MIXED).json()["id"]
    wait_for(api, job_id, done)
    for path in (f"/v1/jobs/{job_id}", f"/v1/jobs/{job_id}/results"):
        r = api.get(path, params={"limit": 0})
        assert r.status_code == 200 and r.json()["next_offset"] is None, r.text
        r = api.get(path, params={"limit": 1})
        assert r.status_code == 200 and r.json()["next_offset"] == 1, r.text
        r = api.get(path, params={"limit": 6})
        assert r.status_code == 422 and r.json()["code"] == "response_too_large", r.text
        assert r.json()["field"] == "limit"
