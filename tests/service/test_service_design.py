"""The /v1/design endpoints: numbers equal the library's, infeasible problems answer 422 with the best point."""

from __future__ import annotations

import numpy as np
import pytest
from fastapi.testclient import TestClient
from pytest import approx
from service_helpers import service_settings

import tensegrity_opt as to
from service.main import create_app

PAPER = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}


@pytest.fixture(scope="module")
def client():
    with TestClient(create_app(service_settings())) as c:
        yield c


@pytest.mark.slow
def test_critical_force_design_equals_library(client):
    body = {"manipulator": PAPER, "vary": ["k"], "bounds": {"k": {"lo": 0.2, "hi": 5.0}}, "budget": {"k": 4.0}}
    r = client.post("/v1/design/critical-force", json=body)
    assert r.status_code == 200, r.text
    got = r.json()
    d = to.maximize_critical_force(to.Manipulator.uniform(4), vary=("k",), bounds={"k": (0.2, 5.0)},
                                   budget={"k": 4.0})
    assert got["critical_force"] == approx(d.critical_force, rel=1e-9)
    assert got["loads"] == approx(d.loads.tolist(), rel=1e-9)
    assert got["multiplicity"] == d.multiplicity and got["active"] == list(d.active)
    assert [sg["k"] for sg in got["manipulator"]["segments"]] == approx(d.manipulator.k1.tolist(), rel=1e-9)
    assert got["solver"]["status"] == "Solve_Succeeded" and got["feasible"] is True
    assert (got["success"], got["status"], got["message"]) == (True, "optimal", d.message)
    # independent forward check of the returned design
    m = to.Manipulator.from_dict(got["manipulator"])
    assert to.critical_force(m).force == approx(got["critical_force"], rel=1e-9)


@pytest.mark.slow
def test_total_length_design(client):
    body = {"manipulator": {"n": 6}, "vary": ["b"], "bounds": {"b": {"lo": 0.3, "hi": 3.0}}, "total_length": True}
    got = client.post("/v1/design/critical-force", json=body).json()
    assert got["multiplicity"] == 2
    assert 2 * sum(sg["b"] for sg in got["manipulator"]["segments"]) == approx(12.0, abs=1e-7)


@pytest.mark.slow
def test_preloads_for_load(client):
    r = client.post("/v1/design/preloads-for-load", json={"manipulator": PAPER, "required": 0.7})
    assert r.status_code == 200, r.text
    got = r.json()
    d = to.preloads_for_critical_force(to.Manipulator.uniform(4), 0.7)
    assert [sg["L0"] for sg in got["manipulator"]["segments"]] == approx(d.manipulator.L1_0.tolist(), rel=1e-9)
    assert -got["critical_force"] >= 0.7 * (1 - 1e-6)


@pytest.mark.slow
def test_preloads_for_load_infeasible_answers_422_with_best(client):
    r = client.post("/v1/design/preloads-for-load", json={"manipulator": PAPER, "required": 10.0})
    assert r.status_code == 422
    got = r.json()
    assert got["code"] == "design_infeasible" and got["status"] == got["best"]["solver"]["status"]
    assert got["best"]["feasible"] is False
    assert (got["best"]["success"], got["best"]["status"]) == (False, "below_required")
    assert -got["best"]["critical_force"] == approx(2 * 0.5727928357, rel=1e-5)


def test_design_infeasible_constraints(client):
    body = {"manipulator": PAPER, "vary": ["k"], "bounds": {"k": {"lo": 0.5, "hi": 1.0}}, "K_min": 5.0}
    r = client.post("/v1/design/critical-force", json=body)
    assert r.status_code == 422 and r.json()["code"] == "design_infeasible"
    assert r.json()["status"]


def test_preloads_pose_equals_library_and_verifies(client):
    body = {"manipulator": PAPER, "target": [7.0, 1.5], "load": [0.05, -0.02],
            "objective": "nominal", "margin": 0.05}
    r = client.post("/v1/design/preloads", json=body)
    assert r.status_code == 200, r.text
    got = r.json()
    lib = to.preloads_for_pose(to.Manipulator.uniform(4), (7.0, 1.5), load=(0.05, -0.02), objective="change",
                               margin=0.05)
    assert np.allclose(got["preloads"], lib.preloads, rtol=1e-9)
    assert got["q"] == approx(lib.q.tolist(), abs=1e-9)
    assert got["margin"] == approx(lib.margin, rel=1e-9)
    m = to.Manipulator.from_dict(got["manipulator"])
    eq = to.solve_equilibrium_under_force(m, 0.05, -0.02, q0=np.array(got["q"]))
    assert np.allclose(eq.tip, [7.0, 1.5], atol=1e-6) and eq.morse_index == 0


@pytest.mark.parametrize("body,field", [
    ({"manipulator": PAPER, "vary": ["c"]}, "vary"),
    ({"manipulator": PAPER, "required": -1.0}, "required"),
    ({"manipulator": PAPER, "target": [7.0]}, "target"),
])
def test_design_schema_errors(client, body, field):
    path = {"vary": "/v1/design/critical-force", "required": "/v1/design/preloads-for-load",
            "target": "/v1/design/preloads"}[field]
    r = client.post(path, json=body)
    assert r.status_code == 422 and r.json()["code"] == "validation_error"
    assert any(e["field"].startswith(field) for e in r.json()["errors"])


def test_design_domain_errors(client):
    r = client.post("/v1/design/preloads", json={"manipulator": PAPER, "target": [9.0, 0.0]})
    assert r.status_code == 422 and r.json()["code"] == "unreachable_target"
    r = client.post("/v1/design/critical-force", json={"manipulator": {"n": 3, "k": [1.0, 2.0]}, "vary": ["k"]})
    assert r.status_code == 422 and r.json()["code"] == "straight_not_equilibrium"
    r = client.post("/v1/design/critical-force", json={"manipulator": {"n": 61}, "vary": ["k"]})
    assert r.status_code == 422 and r.json()["code"] == "validation_error"      # the schema says n <= 60 here
    assert r.json()["field"] == "manipulator.n"
