"""Sweep jobs: the ``/v1/jobs`` API (TestClient), the SQLite store, resuming, and a real server
process killed with SIGKILL mid-job and restarted on the same database.

The expected rows are ``tensegrity_opt.sweep.sweep`` run directly on the same spec.
"""

from __future__ import annotations

import csv
import importlib
import io
import json
import signal
import sqlite3
import subprocess
import time
import warnings
from pathlib import Path

import pytest

pytest.importorskip("fastapi")
httpx = pytest.importorskip("httpx")

with warnings.catch_warnings():
    warnings.simplefilter("ignore")
    from fastapi.testclient import TestClient

from service import jobs
from service.config import Settings
from service.main import create_app
from servers import clean_env, free_port, stop, uvicorn_factory_command, wait_ready

# the module (``tensegrity_opt.sweep`` itself may be re-exported as the function)
S = importlib.import_module("tensegrity_opt.sweep")

ROOT = Path(__file__).resolve().parents[1]

#: ~50 ms a point (every equilibrium of an 8-segment chain): long enough to act while it runs.
def slow_spec(points: int) -> dict:
    return {"analysis": "equilibria_count", "manipulator": {"n": 8},
            "grid": {"dx": [round(0.005 * (i + 1), 6) for i in range(points)]}}


MIXED = {"analysis": "equilibrium", "grid": {"dx": [0.1, 30.0, 0.2], "n": [3, 4]}}


@pytest.fixture()
def api(tmp_path, monkeypatch, request):
    """A TestClient on a fresh database; ``indirect`` parametrisation passes more settings."""
    db = tmp_path / "jobs.sqlite3"
    monkeypatch.setenv("TENSEGRITY_JOBS_DB", str(db))     # also when service/main.py wires the runner itself
    app = create_app(Settings(warmup=False, max_segments=50, **getattr(request, "param", {})))
    jobs.install(app, db_path=db)
    with TestClient(app) as client:
        client.db = db
        yield client


def wait_for(client, job_id, pred, timeout=60.0):
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
    assert full["columns"] == expected.columns and full["columns"][1:3] == ["dx", "n"]     # grid order kept
    assert full["results"] == expected.rows and full["next_offset"] is None
    assert full["spec"] == S.validate_spec(MIXED)
    page = api.get(f"/v1/jobs/{body['id']}", params={"offset": 2, "limit": 3}).json()
    assert [r["index"] for r in page["results"]] == [2, 3, 4] and page["next_offset"] == 5

    res = api.get(f"/v1/jobs/{body['id']}/results").json()
    assert res["complete"] and res["rows"] == expected.rows and res["columns"] == expected.columns
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


@pytest.mark.parametrize("api", [{"jobs_max_running": 1}], indirect=True)
def test_cancel_keeps_finished_points_and_the_runner_goes_on(api):
    long_id = api.post("/v1/jobs", json=slow_spec(200)).json()["id"]
    next_id = api.post("/v1/jobs", json=MIXED).json()["id"]
    queued_id = api.post("/v1/jobs", json=MIXED).json()["id"]
    wait_for(api, long_id, lambda j: j["done"] >= 3)

    r = api.delete(f"/v1/jobs/{queued_id}")                       # queued: cancelled at once
    assert r.status_code == 200 and r.json()["status"] == "cancelled" and r.json()["done"] == 0
    r = api.delete(f"/v1/jobs/{long_id}")                         # running: after its current point
    assert r.status_code == 200 and r.json()["status"] == "cancelled"
    wait_for(api, next_id, done)
    assert api.get(f"/v1/jobs/{next_id}").json()["status"] == "done"
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
    monkeypatch.setenv("TENSEGRITY_JOBS_DB", str(bad))
    app = create_app(Settings(warmup=False))
    jobs.install(app, db_path=bad)
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
        deadline = time.monotonic() + 30
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


def test_graceful_stop_requeues_and_the_next_start_finishes(tmp_path):
    db = tmp_path / "jobs.sqlite3"
    runner = jobs.JobRunner(db_path=db).start()
    job_id = runner.submit(slow_spec(40))["id"]
    deadline = time.monotonic() + 30
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
        while runner.get(job_id)["status"] != "done":
            assert time.monotonic() < deadline + 30
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


def test_a_job_on_a_dask_cluster_stores_the_serial_rows(tmp_path):
    """TENSEGRITY_JOBS_SCHEDULER=tcp://...: points solved by Dask worker processes, rows stored by the runner."""
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cl:
        runner = jobs.JobRunner(db_path=tmp_path / "jobs.sqlite3", scheduler=cl.scheduler_address, chunk_size=2).start()
        try:
            job_id = runner.submit(MIXED)["id"]
            deadline = time.monotonic() + 60
            while runner.get(job_id)["status"] not in jobs.TERMINAL:
                assert time.monotonic() < deadline
                time.sleep(0.05)
            assert runner.get(job_id)["status"] == "done"
            assert runner.rows(job_id) == S.sweep(MIXED).rows
        finally:
            runner.stop()


# --------------------------------------------------------------------------- a real server, killed
def start_server(db: Path, log: Path) -> tuple[subprocess.Popen, str]:
    port = free_port()
    env = clean_env(TENSEGRITY_JOBS_DB=str(db), TENSEGRITY_WARMUP="false", TENSEGRITY_WORKERS="1")
    cmd = uvicorn_factory_command("service.jobs:create_app_with_jobs", port)
    with open(log, "ab") as out:      # the child keeps its own copy of the descriptor
        proc = subprocess.Popen(cmd, env=env, cwd=ROOT, stdout=out, stderr=subprocess.STDOUT)
    base = f"http://127.0.0.1:{port}"
    wait_ready(proc, base, "/healthz", 60, log=lambda: log.read_text(errors="replace"))
    return proc, base


def stored_points(db: Path, job_id: str) -> dict[int, str]:
    with sqlite3.connect(db) as con:
        return dict(con.execute("SELECT idx, row FROM points WHERE job_id = ?", (job_id,)).fetchall())


def test_sigkill_mid_job_loses_no_point_and_the_restart_resumes(tmp_path):
    db, log = tmp_path / "jobs.sqlite3", tmp_path / "server.log"
    total = 160
    spec = slow_spec(total)
    proc, base = start_server(db, log)
    try:
        job_id = httpx.post(base + "/v1/jobs", json=spec, timeout=30).json()["id"]
        deadline = time.monotonic() + 60
        while True:
            seen = httpx.get(f"{base}/v1/jobs/{job_id}/results", timeout=30).json()
            if seen["done"] >= 15:
                break
            assert time.monotonic() < deadline, seen
            time.sleep(0.05)
        proc.send_signal(signal.SIGKILL)
        proc.wait(10)
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
        deadline = time.monotonic() + 90
        while True:
            job = httpx.get(f"{base}/v1/jobs/{job_id}", params={"limit": 0}, timeout=30).json()
            if job["status"] in jobs.TERMINAL:
                break
            assert time.monotonic() < deadline, job
            time.sleep(0.1)
        assert (job["status"], job["done"], job["runs"]) == ("done", total, 2)
        rows = httpx.get(f"{base}/v1/jobs/{job_id}/results", timeout=30).json()["rows"]
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
