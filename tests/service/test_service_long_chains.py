"""Chains longer than numpy's 32 array dimensions on every route that takes a chain: answered, never a 500.

Two spring constants per segment (``"k": [1, 2]``) give each segment one well; the configurations built from one
critical point per segment must never pass through an array of ``n`` dimensions, which numpy refuses beyond 32 (a
500 ``numerical_failure`` on every route that searches). The table below has a body for every operation whose request
takes a chain (checked against the OpenAPI document); each is posted for n = 33, 64 and 200. The routes of the
equilibria must answer 200; the others 200 or a documented refusal (the schema's cap of 60 segments on the design
routes, the continuation's 64, a time limit), never a server error.
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from fastapi.testclient import TestClient
from service_helpers import service_settings

from service.main import create_app

DOCUMENT = Path(__file__).resolve().parents[2] / "openapi" / "openapi.json"

LENGTHS = [33, 64, 200]
#: The operations whose answer must be a solution for any n (the chain's own equilibria).
SOLVED = ("/v1/equilibrium", "/v1/equilibria", "/v1/stiffness", "/v1/batch/equilibrium", "/v1/force-deflection")


def _chain(n: int, form: str) -> dict[str, Any]:
    if form == "uniform":
        return {"n": n, "k": [1, 2]}
    return {"segments": [{"a": 1.0, "b": 1.0, "k": [1, 2]}] * n}


def _massive(m: dict[str, Any]) -> dict[str, Any]:
    """The chain ``m`` with a mass on every segment (either form)."""
    if "segments" in m:
        return {**m, "segments": [{**seg, "mass": 0.1} for seg in m["segments"]]}
    return {**m, "mass": 0.1}


def _bodies(n: int, m: dict[str, Any]) -> dict[str, dict[str, Any]]:
    """A valid body for every operation taking a chain ``m`` of ``n`` segments (``a = b = 1``)."""
    x = 2.0 * n - 0.3                            # near the straight chain's tip (2 b n)
    zeros = [0.0] * n
    guided = {"kind": "guided", "direction": [-1.0, 0.0]}
    load = {"kind": "load", "direction": [-1.0, 0.0]}
    return {
        "/v1/equilibrium": {"manipulator": m, "dx": 0.1},
        "/v1/equilibrium/force": {"manipulator": m, "fx": -0.01, "fy": 0.001},
        "/v1/equilibria": {"manipulator": m, "dx": 0.1},
        "/v1/buckling": {"manipulator": m, "boundary": "guided"},
        "/v1/force-deflection": {"manipulator": m, "dx": {"start": 0.0, "stop": 0.1, "num": 3}},
        "/v1/stiffness": {"manipulator": m, "dx": 0.1},
        "/v1/modes": {"manipulator": _massive(m), "dx": 0.1},
        "/v1/energy-landscape": {"manipulator": m, "dx": 0.1, "pair": [0, 3], "grid": 3},
        "/v1/batch/equilibrium": {"manipulator": m, "targets": [{"dx": 0.05}, {"dx": 0.1, "dy": 0.01}]},
        "/v1/design/critical-force": {"manipulator": m, "vary": ["k"], "bounds": {"k": {"lo": 0.2, "hi": 5.0}},
                                      "budget": {"k": 1.5 * n}},
        "/v1/design/preloads-for-load": {"manipulator": m, "required": 0.01},
        "/v1/design/preloads": {"manipulator": m, "target": [x, 0.5]},
        "/v1/design/holding": {"manipulator": {**_massive(m), "gravity": [0.0, -1e-3]}, "vary": ["k"]},
        "/v1/control/weight-capacity": {"manipulator": {**_massive(m), "gravity": [0.0, -1e-3]}, "max_factor": 1.5},
        "/v1/rest-configurations": {"manipulator": m},
        "/v1/branch": {"manipulator": m, "control": load, "stop_at": "event", "max_points": 50},
        "/v1/bifurcation-diagram": {"manipulator": m, "start": {"q": zeros}, "control": guided, "t_max": 0.1,
                                    "depth": 1, "max_points": 30},
        "/v1/limit-load": {"manipulator": m, "direction": [-1.0, 0.0], "boundary": "guided", "start": {"q": zeros}},
        "/v1/imperfection-sensitivity": {"manipulator": m, "amplitudes": [0.0, 0.01]},
        "/v1/stability-boundary": {"manipulator": m, "control": guided, "parameter": "asymmetry", "p_min": -0.01,
                                   "p_max": 0.01, "max_points": 20},
        "/v1/atlas": {"manipulator": m, "dx": [0.1], "dy": [0.0], "edges": False},
        "/v1/control/plan": {"manipulator": m, "targets": [[x, 0.2], [x, 0.3]]},
        "/v1/control/simulate": {"manipulator": m, "loads": [[0.0, 0.0], [0.0, 0.001]]},
        "/v1/control/force-estimate": {"manipulator": m, "q_measured": [0.001] * n, "sigma_q": 0.001},
        "/v1/control/stiffness": {"manipulator": m, "target": [x, 0.5], "eig_bounds": [0.001, 10.0]},
        "/v1/control/load-capacity": {"manipulator": m, "directions": 4, "max_load": 0.1},
        "/v1/plots/curve": {"manipulator": m, "dx": {"start": 0.0, "stop": 0.1, "num": 3}},
        "/v1/plots/landscape": {"manipulator": m, "dx": 0.1, "pair": [0, 3], "grid": 3},
        "/v1/plots/shapes": {"manipulator": m, "dx": 0.1},
        "/v1/plots/modes": {"manipulator": _massive(m), "dx": 0.1, "max_panels": 2},
        "/v1/plots/holding": {"manipulator": _massive(m), "directions": 1},
        "/v1/plots/map": {"manipulator": m, "param_x": "k", "values_x": [1.0, 2.0], "param_y": "L0",
                          "values_y": [1.0, 1.5]},
        "/v1/plots/branch": {"manipulator": m, "control": load, "stop_at": "event", "max_points": 50, "x": "t",
                             "y": "fx"},
        "/v1/plots/limit-load": {"manipulator": m, "direction": [-1.0, 0.0], "boundary": "guided"},
        "/v1/plots/imperfection": {"manipulator": m, "amplitudes": [0.0, 0.01]},
        "/v1/plots/boundary": {"manipulator": m, "control": guided, "parameter": "asymmetry", "p_min": -0.01,
                               "p_max": 0.01, "max_points": 20},
        "/v1/plots/atlas": {"manipulator": m, "dx": [0.1], "dy": [0.0], "edges": False},
        "/v1/plots/plan": {"manipulator": m, "targets": [[x, 0.2], [x, 0.3]]},
        "/v1/plots/simulation": {"manipulator": m, "loads": [[0.0, 0.0], [0.0, 0.001]]},
        "/v1/jobs": {"analysis": "equilibrium", "manipulator": m, "points": [{"dx": 0.1}, {"load": [-0.01, 0.0]}]},
    }


def _takes_chain(schema: dict[str, Any], components: dict[str, Any]) -> bool:
    """The request schema has a ``manipulator`` property (in any of its forms)."""
    todo, seen = [schema], set()
    while todo:
        s = todo.pop()
        if "$ref" in s:
            name = s["$ref"].rsplit("/", 1)[-1]
            if name not in seen:
                seen.add(name)
                todo.append(components[name])
            continue
        if "manipulator" in s.get("properties", {}):
            return True
        todo.extend(v for key in ("anyOf", "oneOf", "allOf") for v in s.get(key, []))
    return False


def test_the_table_has_every_operation_taking_a_chain():
    doc = json.loads(DOCUMENT.read_text())        # the committed document (checked equal to the app's elsewhere)
    components = doc["components"]["schemas"]
    taking = {path for path, ops in doc["paths"].items() for op in ops.values()
              if _takes_chain(op.get("requestBody", {}).get("content", {}).get("application/json", {})
                              .get("schema", {}), components)}
    # a figure's job form takes the figure's own body (tests/service/test_figure_jobs.py): the figure stands for it
    figures_as_jobs = {path for path in taking if path.startswith("/v1/plots/") and path.endswith("/job")}
    assert {path.removesuffix("/job") for path in figures_as_jobs} <= taking
    assert taking - figures_as_jobs == set(_bodies(4, {"n": 4})), \
        "add a body to _bodies for each new operation taking a chain"


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    # generous limits: these answers must be solutions
    settings = service_settings(inline_processes=0, heavy_workers=0,
                                jobs_db=str(tmp_path_factory.mktemp("jobs") / "jobs.sqlite3"))
    with TestClient(create_app(settings), raise_server_exceptions=False) as c:
        yield c


@pytest.fixture(scope="module")
def limited_client(tmp_path_factory):
    # every route: an answer or a refusal, a time limit included (the design and control solves of long chains)
    # (10 s: the design and control solves of n = 33 reach it, three of them; a 504 is an answer here)
    settings = service_settings(inline_processes=0, heavy_workers=0, solve_timeout=10.0, batch_timeout=10.0,
                                jobs_db=str(tmp_path_factory.mktemp("jobs") / "jobs.sqlite3"))
    with TestClient(create_app(settings), raise_server_exceptions=False) as c:
        yield c


def _answered(r, path: str) -> None:
    assert r.status_code != 500, f"{path}: {r.text[:500]}"
    if r.status_code >= 400:
        assert r.status_code in (422, 504) and r.json()["code"], f"{path}: {r.status_code} {r.text[:500]}"


#: The solved routes for every length and both forms of the chain, n = 33 first (the fast lane's cases).
SOLVED_CASES = [(path, n, form) for n in LENGTHS for form in ("uniform", "segments") for path in SOLVED]


@pytest.mark.slow_cases(keep=len(SOLVED))
@pytest.mark.parametrize(("path", "n", "form"), SOLVED_CASES)
def test_equilibria_of_long_chains_are_solved(client, path, n, form):
    r = client.post(path, json=_bodies(n, _chain(n, form))[path])
    assert r.status_code == 200, r.text[:500]


@pytest.mark.slow
@pytest.mark.parametrize("n", LENGTHS)
def test_every_route_answers_long_chains(limited_client, n):
    for path, body in _bodies(n, _chain(n, "uniform")).items():
        r = limited_client.post(path, json=body)
        _answered(r, path)
        if path == "/v1/jobs" and r.status_code == 202:
            _job_points_solved(limited_client, r.json()["id"])


def _job_points_solved(client: TestClient, job: str, wait: Callable[[float], None] = time.sleep) -> None:
    deadline = time.monotonic() + 600
    while (status := client.get(f"/v1/jobs/{job}").json()["status"]) in ("queued", "running"):
        assert time.monotonic() < deadline, "the job did not end"
        wait(0.2)
    assert status == "done", status
    rows = client.get(f"/v1/jobs/{job}/results").json()["rows"]
    assert rows and not any(row.get("error") for row in rows), rows
