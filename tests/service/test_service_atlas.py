"""HTTP service, the stability atlas: a job with ``analysis: atlas`` and ``GET /v1/jobs/{id}/atlas``, the inline
``POST /v1/atlas`` and the figure ``POST /v1/plots/atlas``.

The atlas of a job (assembled from its rows by ``sweeps.atlas_from_rows``) and the inline one are compared
with ``tensegrity_opt.stability_atlas`` called directly on the same grid: the same counts and the same
crossings. Small grids (3 x 3 and less, n = 3): the whole file runs in a few seconds.
"""

from __future__ import annotations

import json
import time

import numpy as np
import pytest

pytest.importorskip("fastapi")
pytest.importorskip("httpx")

from clocks import tick_clock
from service_helpers import WAIT_SECONDS, app_client

import tensegrity_opt as to
from service import schemas as s

#: Bistable segments (a = 0.5): 2 to 4 stable equilibria over the grid, switches and folds on its edges.
CHAIN = {"n": 3, "a": 0.5, "b": 1.0, "k": 1.0, "L0": 1.0}
M = to.Manipulator.uniform(3, 0.5, 1.0, 1.0, 1.0)
DX, DY = [0.2, 0.8, 1.4], [-0.6, 0.0, 0.6]
#: Pre-bent: two segments with the rest lengths [1.05, 0.95].
PRE_BENT = {"segments": [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": [1.05, 0.95]}] * 2
            + [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}]}
M_PRE_BENT = to.Manipulator.from_dict(PRE_BENT)
GIDS = ("n_stable", "switch", "branch_end")


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    db = tmp_path_factory.mktemp("atlas") / "jobs.sqlite3"
    with app_client(inline_processes=0, jobs_db=str(db)) as c:
        yield c


@pytest.fixture(scope="module")
def direct():
    """``stability_atlas`` on the grid, called directly."""
    return to.stability_atlas(M, DX, DY).to_dict()


def test_targets_beyond_reach_are_in_the_answer_with_zero_counts(client):
    r = client.post("/v1/atlas", json={"manipulator": CHAIN, "dx": [0.2], "dy": [0.0, 5.0], "edges": False})
    assert r.status_code == 200, r.text
    got = r.json()
    s.AtlasOut.model_validate(got)
    far = got["targets"][1][0]
    assert far["reachable"] is False and far["count"] == 0 and far["least_energy"] is None
    assert got["least_energy"][1] == [None] and got["n_stable"] == [[2], [0]] and got["status"] == "complete"



def test_an_atlas_through_the_straight_chain_is_complete(client):
    """The paper's chain held straight at dx = dy = 0 (where it buckles) is one target of the grid like any other."""
    r = client.post("/v1/atlas", json={"manipulator": {"n": 4, "a": 1, "b": 1, "k": 1, "L0": 1},
                                       "dx": {"start": 0, "stop": 1, "num": 3}, "dy": [0.0, 0.1, 0.2]})
    assert r.status_code == 200, r.text
    got = r.json()
    assert got["status"] == "complete" and got["unresolved"] == [] and got["n_stable"][0] == [1, 2, 2], got["message"]

def wait_done(client, job_id, timeout=WAIT_SECONDS):
    deadline = time.monotonic() + timeout
    while True:
        job = client.get(f"/v1/jobs/{job_id}", params={"limit": 0}).json()
        if job["status"] not in ("queued", "running"):
            return job
        assert time.monotonic() < deadline, job
        time.sleep(0.05)


def submit(client, spec) -> str:
    r = client.post("/v1/jobs", json=spec)
    assert r.status_code == 202, r.text
    return r.json()["id"]


@pytest.fixture(scope="module")
def atlas_job(client):
    job_id = submit(client, {"analysis": "atlas", "manipulator": CHAIN, "grid": {"dx": DX, "dy": DY},
                             "options": {"method": "search"}})
    assert wait_done(client, job_id)["status"] == "done"
    return job_id


def same_atlas(got: dict, want: dict) -> None:
    """The same targets (counts, least energies) and the same crossings (kinds, edges, points)."""
    s.AtlasOut.model_validate(got)
    assert got["dx"] == want["dx"] and got["dy"] == want["dy"]
    for key in ("count", "n_stable", "n_saddle", "n_maximum", "least_signs", "certified"):
        assert got[key] == want[key], key
    assert np.allclose(np.array(got["least_energy"], float), np.array(want["least_energy"], float), atol=1e-9)
    kinds = [(c["kind"], c["edge"], c["event"]) for c in got["crossings"]]
    assert sorted(kinds) == sorted((c["kind"], c["edge"], c["event"]) for c in want["crossings"])

    def points(b):      # in one order (rounded keys: the two computations agree to ~1e-15, not bit for bit)
        key = sorted((c["kind"] == "switch", round(c["dx"], 9), round(c["dy"], 9), c["dx"], c["dy"])
                     for c in b["crossings"])
        return np.array([k[3:] for k in key], float)

    assert np.allclose(points(got), points(want), atol=1e-7)
    assert len(got["curves"]["switch"]) == len(want["curves"]["switch"])
    assert len(got["curves"]["branch_end"]) == len(want["curves"]["branch_end"])


# ---------------------------------------------------------------------------- jobs
@pytest.mark.slow
def test_an_atlas_job_gives_the_atlas_of_stability_atlas(client, atlas_job, direct):
    job = client.get(f"/v1/jobs/{atlas_job}").json()
    assert job["analysis"] == "atlas" and job["total"] == 9 and job["spec"]["options"] == {"method": "search"}
    r = client.get(f"/v1/jobs/{atlas_job}/atlas")
    assert r.status_code == 200, r.text
    got = r.json()
    same_atlas(got, direct)
    assert got["status"] == "complete" and got["method"] == "search"
    assert got["n_stable"] == [[2, 3, 4], [2, 4, 4], [2, 3, 4]]
    assert {c["kind"] for c in got["crossings"]} == {"switch", "branch_end"}
    counts = client.get(f"/v1/jobs/{atlas_job}/atlas", params={"edges": False}).json()
    assert counts["n_stable"] == got["n_stable"] and counts["crossings"] == []


def test_a_job_on_a_pre_bent_chain_given_by_its_segments(client):
    spec = {"analysis": "atlas", "manipulator": PRE_BENT, "grid": {"dx": [0.2, 0.8], "dy": [0.0, 0.4]}}
    job_id = submit(client, spec)
    job = wait_done(client, job_id)
    assert job["status"] == "done"
    stored = client.get(f"/v1/jobs/{job_id}").json()["spec"]["manipulator"]
    assert stored == {"segments": [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": [1.05, 0.95]}] * 2
                      + [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}]}         # the segments only, no n, a, b ...
    got = client.get(f"/v1/jobs/{job_id}/atlas").json()
    same_atlas(got, to.stability_atlas(M_PRE_BENT, [0.2, 0.8], [0.0, 0.4]).to_dict())
    # either the segments or the uniform keys
    r = client.post("/v1/jobs", json={**spec, "manipulator": {**PRE_BENT, "n": 3}})
    assert r.status_code == 422 and r.json()["code"] == "validation_error" and r.json()["field"] == "manipulator.n"
    r = client.post("/v1/jobs", json={**spec, "grid": {"dx": [0.2], "k": [1.0, 2.0]}})
    assert r.status_code == 422 and r.json()["field"] == "grid.k"          # a fixed chain: points vary dx, dy only


def test_the_atlas_of_a_job_not_done_or_not_an_atlas_is_refused(client):
    job_id = submit(client, {"analysis": "atlas", "manipulator": CHAIN,
                             "grid": {"dx": [0.1 * i for i in range(1, 9)], "dy": [-0.3, 0.0, 0.3]}})
    r = client.get(f"/v1/jobs/{job_id}/atlas")
    assert r.status_code == 409, r.text
    body = r.json()
    assert body["code"] == "job_not_done" and body["field"] == "id" and body["details"]["status"] in ("queued",
                                                                                                        "running")
    assert client.post(f"/v1/jobs/{job_id}/cancel").status_code == 200
    r = client.get(f"/v1/jobs/{job_id}/atlas")
    assert r.status_code == 409 and r.json()["details"]["status"] == "cancelled"
    r = client.post("/v1/plots/atlas", json={"job": job_id})
    assert r.status_code == 409 and r.json()["code"] == "job_not_done" and r.json()["field"] == "job"
    assert client.delete(f"/v1/jobs/{job_id}").status_code == 204

    buckling = submit(client, {"analysis": "buckling", "grid": {"n": [3]}})
    r = client.get(f"/v1/jobs/{buckling}/atlas")
    assert r.status_code == 422 and r.json()["code"] == "invalid_parameter" and r.json()["field"] == "spec.analysis"
    line = submit(client, {"analysis": "atlas", "manipulator": CHAIN, "grid": {"dx": [0.2, 0.4]}})
    r = client.get(f"/v1/jobs/{line}/atlas")
    assert r.status_code == 422 and r.json()["field"] == "spec.grid"
    r = client.get("/v1/jobs/0123456789abcdef0123456789abcdef/atlas")
    assert r.status_code == 404 and r.json()["code"] == "not_found"
    r = client.post("/v1/jobs", json={"analysis": "buckling", "grid": {"n": [3]}, "options": {"method": "search"}})
    assert r.status_code == 422 and r.json()["field"] == "options.method"      # atlas only
    r = client.post("/v1/jobs", json={"analysis": "atlas", "manipulator": {"n": 6}, "grid": {"dx": [0.1], "dy": [0.0]},
                                      "options": {"method": "homotopy"}})
    assert r.status_code == 422 and r.json()["code"] == "too_many_segments" and r.json()["field"] == "options.method"


# ---------------------------------------------------------------------------- inline
@pytest.mark.slow
def test_the_inline_atlas_is_stability_atlas(client, direct):
    r = client.post("/v1/atlas", json={"manipulator": CHAIN, "dx": {"start": 0.2, "stop": 1.4, "num": 3},
                                       "dy": DY, "method": "search", "edges": True})
    assert r.status_code == 200, r.text
    same_atlas(r.json(), direct)


@pytest.mark.parametrize("body, code, field", [
    ({"dx": [0.8, 0.2]}, "invalid_parameter", "dx"),                      # not increasing
    ({"dy": {"start": 0.5, "stop": 0.0, "num": 3}}, "invalid_parameter", "dy"),
    ({"dx": []}, "validation_error", "dx"),
    ({"dx": {"start": 0.0, "stop": 1.0, "num": 0}}, "validation_error", "dx.num"),
    ({"dx": [0.1, float("nan")]}, "validation_error", "dx[1]"),
    ({"dx": {"start": 0.0, "stop": 1.0, "num": 21}, "dy": {"start": 0.0, "stop": 1.0, "num": 20}},
     "atlas_too_large", "dx"),
    ({"manipulator": {**PRE_BENT, "n": 3}}, "validation_error", "manipulator.n"),   # segments and n together
    ({"manipulator": {**CHAIN, "n": 1}}, "invalid_parameter", "manipulator.n"),
    ({"manipulator": {**CHAIN, "n": 6}, "method": "homotopy"}, "too_many_segments", "method"),
    ({"method": "newton"}, "validation_error", "method"),
    ({"edges": 1}, "validation_error", "edges"),
])
def test_inline_atlas_refusals_name_the_field(client, body, code, field):
    full = {"manipulator": CHAIN, "dx": [0.2, 0.8], "dy": [0.0], **body}
    r = client.post("/v1/atlas", content=json.dumps(full), headers={"Content-Type": "application/json"})
    assert r.status_code == 422, r.text
    b = r.json()
    assert (b["code"], b["field"]) == (code, field), b
    if code == "atlas_too_large":
        assert "/v1/jobs" in b["message"] and "atlas" in b["message"]
        assert b["details"] == {"targets": 420, "nx": 21, "ny": 20, "max_atlas_targets": 400}


@pytest.mark.slow
def test_the_target_bound_is_a_setting_and_the_time_limit_answers_a_partial_atlas(monkeypatch):
    with app_client(inline_processes=0, max_atlas_targets=25) as c:
        assert c.get("/version").json()["limits"]["max_atlas_targets"] == 25
        seven = {"start": 0.2, "stop": 1.4, "num": 7}
        r = c.post("/v1/atlas", json={"manipulator": CHAIN, "dx": seven, "dy": [-0.6, -0.3, 0.0, 0.3]})
        assert r.status_code == 422 and r.json()["code"] == "atlas_too_large"
        assert r.json()["details"] == {"targets": 28, "nx": 7, "ny": 4, "max_atlas_targets": 25}
        r = c.post("/v1/plots/atlas", json={"manipulator": CHAIN, "dx": seven, "dy": [-0.6, -0.3, 0.0, 0.3]})
        assert r.status_code == 422 and r.json()["code"] == "atlas_too_large"
        # 25 targets with their edges read the library's clock some 1000 times; it moves on 1 s at every reading
        # (tests/support/clocks.py), so the soft deadline (270 s of the 300 s limit) runs out a quarter of the way,
        # on any machine: 200 with what was done by then, not a 504
        tick_clock(monkeypatch, step=1.0)
        five = {"start": 0.2, "stop": 1.4, "num": 5}
        r = c.post("/v1/atlas", json={"manipulator": CHAIN, "dx": five, "dy": {"start": -0.6, "stop": 0.6, "num": 5}})
        assert r.status_code == 200, r.text
        got = r.json()
        s.AtlasOut.model_validate(got)
        assert got["status"] == "time_limit" and got["success"] is False
        assert any(t["success"] for row in got["targets"] for t in row)             # what was done is answered
        errors = [t["error"] for row in got["targets"] for t in row if t["error"]]
        assert all(e.startswith("time_limit") for e in errors)      # targets not reached, if any


# ---------------------------------------------------------------------------- figure
@pytest.mark.slow
def test_the_figure_is_a_png_or_an_svg_with_its_gids(client, atlas_job):
    grid = {"manipulator": CHAIN, "dx": [0.2, 0.8], "dy": [0.0, 0.6, 5.0], "dpi": 40}      # 5.0: beyond reach
    r = client.post("/v1/plots/atlas", json=grid)
    assert r.status_code == 200, r.text
    assert r.headers["content-type"] == "image/png" and r.content[:8] == b"\x89PNG\r\n\x1a\n"
    r = client.post("/v1/plots/atlas", json={**grid, "format": "svg"})
    assert r.status_code == 200 and r.headers["content-type"].startswith("image/svg+xml")
    svg = r.text
    assert svg.lstrip().startswith("<?xml") and "<svg" in svg[:400]
    for gid in GIDS:
        assert f'id="{gid}"' in svg, gid
    r = client.post("/v1/plots/atlas", json={"job": atlas_job}, headers={"Accept": "image/svg+xml"})
    assert r.status_code == 200 and r.headers["content-type"].startswith("image/svg+xml")
    for gid in GIDS:
        assert f'id="{gid}"' in r.text, gid
    r = client.post("/v1/plots/atlas", json={"job": "0123456789abcdef0123456789abcdef"})
    assert r.status_code == 404 and r.json()["field"] == "job"
    r = client.post("/v1/plots/atlas", json={"job": atlas_job, "dx": [0.1]})
    assert r.status_code == 422 and r.json()["code"] == "validation_error"      # a job or a grid, not both
