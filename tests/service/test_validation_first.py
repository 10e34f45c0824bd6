"""Validate before solving; an internal failure is a bug answered with 500, never a 422.

Each case below is an input the library refuses before it reaches numpy, scipy or CasADi (whose own message,
as a 422 ``numerical_failure``, would name no field).
"""

from __future__ import annotations

import numpy as np
import pytest
from fastapi.testclient import TestClient
from service_helpers import service_settings

import tensegrity_opt as to
from service.main import create_app
from service.tasks import equilibria as compute
from tensegrity_opt.errors import InvalidParameterError, UnreachableTargetError

PAPER = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}


@pytest.fixture(scope="module")
def client():
    with TestClient(create_app(service_settings(inline_processes=0)), raise_server_exceptions=False) as c:
        yield c


@pytest.mark.slow
def test_preloads_for_one_segment_is_refused_before_the_nlp(client):
    # a reachable target; CasADi would stop at "Input 4 (lbg) has mismatching shape"
    x, y = 1 + np.cos(0.3), np.sin(0.3)
    with pytest.raises(InvalidParameterError) as e:
        to.preloads_for_pose(to.Manipulator.uniform(1), (x, y))
    assert e.value.field == "n"
    r = client.post("/v1/design/preloads", json={"manipulator": {"n": 1}, "target": [x, y]})
    assert r.status_code == 422 and r.json()["code"] == "invalid_parameter", r.text
    assert r.json()["field"] == "manipulator.n"


@pytest.mark.slow
def test_tension_bounds_in_the_wrong_order_name_the_field(client):
    # IPOPT would stop at its assertion "lb <= ub"
    with pytest.raises(InvalidParameterError) as e:
        to.maximize_critical_force(to.Manipulator.uniform(4), vary=("k",), tension=(5.0, 1.0))
    assert e.value.field == "tension"
    r = client.post("/v1/design/critical-force",
                    json={"manipulator": PAPER, "vary": ["k"], "tension": {"lo": 5, "hi": 1}})
    assert r.status_code == 422 and r.json()["code"] == "invalid_parameter" and r.json()["field"] == "tension", r.text


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("load", [[0.0, 1e12], [0.0, -1e12], [1e12, 1e12]])
def test_huge_loads_on_preloads_are_answered(client, load):
    # an absolute floor (1e-6) under entries of 1e12 would make numpy raise "Matrix is not positive definite"
    r = client.post("/v1/design/preloads", json={"manipulator": PAPER, "target": [7.0, 1.5], "load": load})
    assert r.status_code in (200, 422), r.text
    if r.status_code == 422:
        assert r.json()["code"] == "design_infeasible", r.text


def test_unreachable_preload_target_names_the_target(client):
    # the request has a tip position `target`, not a deflection `dx`
    with pytest.raises(UnreachableTargetError) as e:
        to.preloads_for_pose(to.Manipulator.uniform(4), (9.0, 1.5))
    assert e.value.field == "target"
    r = client.post("/v1/design/preloads", json={"manipulator": PAPER, "target": [9.0, 1.5]})
    assert r.status_code == 422 and r.json()["code"] == "unreachable_target", r.text
    assert r.json()["field"] == "target"


def test_an_internal_numerical_failure_is_a_500(client, monkeypatch):
    # what the library does not refuse is a bug: 500 with the JSON error shape, not a 422 answer
    def broken(req):
        raise np.linalg.LinAlgError("Matrix is not positive definite")

    monkeypatch.setattr("service.api.routes.buckling.buckling_task", broken)
    r = client.post("/v1/buckling", json={"manipulator": PAPER})
    assert r.status_code == 500 and r.json()["code"] == "numerical_failure", r.text
    assert compute.buckling_task is not broken


def test_a_500_says_what_failed_not_the_numerical_library_text(client, monkeypatch, caplog):
    # numpy's own words (shapes, dimensions) stay in the server's log; the body says what failed
    inside = ("setting an array element with a sequence. The requested array has an inhomogeneous shape after 1 "
              "dimensions. The detected shape was (4,) + inhomogeneous part.")

    def broken(req):
        raise ValueError(inside)

    monkeypatch.setattr("service.api.routes.buckling.buckling_task", broken)
    with caplog.at_level("ERROR", logger="service.errors"):
        r = client.post("/v1/buckling", json={"manipulator": PAPER})
    assert r.status_code == 500, r.text
    body = r.json()
    assert body["code"] == "numerical_failure" and "failed numerically" in body["message"], body
    assert "inhomogeneous" not in r.text and "ValueError" not in r.text, r.text
    assert set(body) <= {"code", "message", "field", "status", "errors", "details", "best"}
    assert any("inhomogeneous" in rec.getMessage() for rec in caplog.records), "the detail goes to the log"
