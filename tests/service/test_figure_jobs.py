"""Figures as jobs: ``POST /v1/plots/{kind}/job`` runs to completion and ``GET /v1/jobs/{id}/figure`` serves the
image; the job's progress moves step by step; a failure is a row with its error; the 504 of a synchronous figure
names the job route (a stand-in task that never ends by itself, so the limit expires on any machine)."""

from __future__ import annotations

import json
import threading
import time
import warnings

import pytest

pytest.importorskip("matplotlib")
pytest.importorskip("fastapi")
pytest.importorskip("httpx")

with warnings.catch_warnings():
    warnings.simplefilter("ignore")
    from fastapi.testclient import TestClient

from figures import check_png, check_svg  # noqa: E402
from service_helpers import WAIT_SECONDS, service_settings  # noqa: E402

from service import jobs  # noqa: E402
from service.api.routes import plots as plot_routes  # noqa: E402
from service.jobs import runner as jobs_runner  # noqa: E402
from service.main import create_app  # noqa: E402
from service.schemas import plots as ps  # noqa: E402
from service.tasks import plots as plot_tasks  # noqa: E402

M4 = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}
#: A small figure: a landscape on a coarse grid (a fraction of a second).
SMALL = {"manipulator": M4, "dx": 0.1, "grid": 11, "dpi": 40}
#: A small atlas: 2 x 1 targets of a bistable chain, counts only.
SMALL_ATLAS = {"manipulator": {"n": 3, "a": 0.5}, "dx": [0.2, 1.4], "dy": [0.0], "edges": False, "dpi": 40}


@pytest.fixture()
def api(tmp_path):
    app = create_app(service_settings(inline_processes=0, jobs_db=str(tmp_path / "jobs.sqlite3")))
    with TestClient(app) as client:
        yield client


def wait_for(client, job_id, pred, timeout=WAIT_SECONDS):
    deadline = time.monotonic() + timeout
    while True:
        job = client.get(f"/v1/jobs/{job_id}").json()
        if pred(job):
            return job
        assert time.monotonic() < deadline, job
        time.sleep(0.05)


def ended(job):
    return job["status"] in jobs.TERMINAL


def submit(client, kind, body) -> dict:
    r = client.post(f"/v1/plots/{kind}/job", json=body)
    assert r.status_code == 202, r.text
    out = r.json()
    assert r.headers["location"] == f"/v1/jobs/{out['id']}"
    assert out["analysis"] == "figure" and out["status"] == "queued"
    return out


# --------------------------------------------------------------------------- to completion
def test_a_figure_job_runs_to_completion_and_serves_the_image(api):
    job = submit(api, "landscape", SMALL)
    assert job["total"] == 2                                  # the drawing, then the stored image
    done = wait_for(api, job["id"], ended)
    assert done["status"] == "done", done
    assert done["done"] == done["total"] == 2 and done["failed"] == 0 and done["progress"] == 1.0
    assert [r["stage"] for r in done["results"]][0] == "drawn"
    assert done["spec"]["kind"] == "landscape" and done["spec"]["request"]["grid"] == 11
    r = api.get(f"/v1/jobs/{job['id']}/figure")
    assert r.status_code == 200 and r.headers["content-type"] == "image/png"
    check_png(r.content)
    assert r.headers["content-disposition"] == 'inline; filename="landscape.png"'
    # the same figure as SVG: the body's format decides
    svg = submit(api, "landscape", {**SMALL, "format": "svg"})
    assert wait_for(api, svg["id"], ended)["status"] == "done"
    r = api.get(f"/v1/jobs/{svg['id']}/figure")
    assert r.status_code == 200 and r.headers["content-type"].startswith("image/svg+xml")
    check_svg(r.content)
    # deleting the job deletes its image
    assert api.delete(f"/v1/jobs/{svg['id']}").status_code == 204
    assert api.get(f"/v1/jobs/{svg['id']}/figure").status_code == 404
    assert api.app.state.jobs.store.figure(svg["id"]) is None


def test_the_atlas_job_counts_a_step_per_target(api):
    job = submit(api, "atlas", SMALL_ATLAS)
    assert job["total"] == 2 * 1 + 2
    done = wait_for(api, job["id"], ended)
    assert done["status"] == "done", done
    stages = [r["stage"] for r in done["results"]]
    assert stages[:2] == ["target dx = 0.2, dy = 0", "target dx = 1.4, dy = 0"] and stages[2] == "drawn"
    check_png(api.get(f"/v1/jobs/{job['id']}/figure").content)


# --------------------------------------------------------------------------- progress
def test_the_progress_of_a_figure_job_moves(api, monkeypatch):
    """The atlas job stops after its first target until the test lets it go on: the job is seen running with one
    step of four done, then done with all four."""
    gate, reached = threading.Event(), threading.Event()
    real = jobs_runner.figure_job_task

    def gated(spec, deadline, progress):
        def step(stage):
            progress(stage)
            if not gate.is_set():
                reached.set()
                gate.wait(WAIT_SECONDS)
        return real(spec, deadline, step)

    monkeypatch.setattr(jobs_runner, "figure_job_task", gated)
    job = submit(api, "atlas", SMALL_ATLAS)
    try:
        assert reached.wait(WAIT_SECONDS)
        mid = api.get(f"/v1/jobs/{job['id']}").json()
        assert mid["status"] == "running" and mid["done"] == 1 and mid["total"] == 4
        assert 0 < mid["progress"] < 1
        r = api.get(f"/v1/jobs/{job['id']}/figure")
        assert r.status_code == 409 and r.json()["code"] == "job_not_done"
        assert r.json()["details"] == {"status": "running", "done": 1, "total": 4}
    finally:
        gate.set()
    done = wait_for(api, job["id"], ended)
    assert done["status"] == "done" and done["done"] == 4 and done["progress"] == 1.0


def test_a_cancelled_figure_job_stops_and_serves_no_image(api, monkeypatch):
    gate, reached = threading.Event(), threading.Event()

    def never_ending(spec, deadline, progress):
        progress("started")
        reached.set()
        while not gate.is_set():               # interruptible: it ends at its thread's next bytecode
            time.sleep(0.01)
        return b""

    monkeypatch.setattr(jobs_runner, "figure_job_task", never_ending)
    job = submit(api, "landscape", SMALL)
    try:
        assert reached.wait(WAIT_SECONDS)
        assert api.post(f"/v1/jobs/{job['id']}/cancel").json()["status"] == "cancelled"
        assert api.app.state.jobs.wait_idle(WAIT_SECONDS)
    finally:
        gate.set()
    r = api.get(f"/v1/jobs/{job['id']}/figure")
    assert r.status_code == 409 and r.json()["details"]["status"] == "cancelled"


# --------------------------------------------------------------------------- errors
def test_a_failed_figure_job_has_its_error_in_the_rows(api):
    job = submit(api, "landscape", {**SMALL, "dx": 20.0})          # beyond the chain's reach
    failed = wait_for(api, job["id"], ended)
    assert failed["status"] == "failed", failed
    assert failed["message"].startswith("unreachable_target: ")
    assert failed["failed"] == 1
    (row,) = [r for r in failed["results"] if r["error"]]
    assert row["stage"] == "failed" and row["error"] == failed["message"]
    r = api.get(f"/v1/jobs/{job['id']}/figure")
    assert r.status_code == 409
    body = r.json()
    assert body["code"] == "job_not_done" and body["field"] == "id"
    assert body["details"]["status"] == "failed" and body["details"]["message"] == failed["message"]


def test_the_job_route_applies_the_figures_limits_and_refuses_bad_bodies(api):
    r = api.post("/v1/plots/landscape/job", json={**SMALL, "manipulator": {"n": 500}})
    assert r.status_code == 422 and r.json()["code"] in ("validation_error", "too_many_segments")
    r = api.post("/v1/plots/atlas/job", json={"job": "0123456789abcdef0123456789abcdef"})
    assert r.status_code == 422 and r.json()["code"] == "validation_error"     # the grid form only
    r = api.post("/v1/plots/atlas/job", json={**SMALL_ATLAS, "dx": {"start": 0.1, "stop": 1.0, "num": 100},
                                               "dy": {"start": -1.0, "stop": 1.0, "num": 100}})
    assert r.status_code == 422 and r.json()["code"] == "atlas_too_large"


def test_the_figure_of_a_sweep_or_an_unknown_job_is_refused(api):
    r = api.post("/v1/jobs", json={"analysis": "buckling", "grid": {"n": [3]}})
    assert r.status_code == 202
    r = api.get(f"/v1/jobs/{r.json()['id']}/figure")
    assert r.status_code == 422 and r.json()["code"] == "invalid_parameter" and r.json()["field"] == "id"
    r = api.get("/v1/jobs/0123456789abcdef0123456789abcdef/figure")
    assert r.status_code == 404 and r.json()["code"] == "not_found"


# --------------------------------------------------------------------------- the 504 names the job route
def _never(req, fmt, *args):
    while True:                                  # ends only when the solver thread is interrupted at the limit
        time.sleep(0.01)


def test_the_504_of_a_figure_names_its_job_route(tmp_path):
    fig = next(f for f in plot_routes.FIGURES if f.kind == "torque")
    real = fig.task
    object.__setattr__(fig, "task", _never)      # the table's entries are frozen: the route reads fig.task
    try:
        app = create_app(service_settings(inline_processes=0, solve_timeout=0.5,
                                          jobs_db=str(tmp_path / "jobs.sqlite3")))
        with TestClient(app) as client:
            r = client.post("/v1/plots/torque", json={"segments": [{"a": 1.0, "b": 1.0}]})
    finally:
        object.__setattr__(fig, "task", real)
    assert r.status_code == 504, r.text
    body = r.json()
    assert body["code"] == "timeout"
    assert "POST /v1/plots/torque/job" in body["message"] and "GET /v1/jobs/{id}/figure" in body["message"]


# --------------------------------------------------------------------------- the stored request
def test_every_figure_request_round_trips_through_the_job_store():
    """The job stores the request's JSON form; the runner reads back the same request (every example of every
    figure), and the job table's task is the figure route's."""
    for fig in plot_routes.FIGURES:
        model, task, continuation = plot_tasks.FIGURE_TASKS[fig.kind]
        assert task is fig.task and continuation == fig.continuation
        for name, example in fig.examples.items():
            if name == "job":
                continue
            req = model.model_validate_json(json.dumps(example["value"]))
            assert plot_tasks.figure_request(fig.kind, req.model_dump(mode="json")) == req, (fig.kind, name)


def test_the_landscape_figure_defaults_to_a_coarser_grid_and_keeps_an_explicit_one():
    req = ps.PlotLandscapeRequest.model_validate({"manipulator": M4, "dx": 0.1})
    assert req.grid == ps.LANDSCAPE_FIGURE_GRID == 61
    assert ps.PlotLandscapeRequest.model_validate({"manipulator": M4, "dx": 0.1, "grid": 101}).grid == 101
