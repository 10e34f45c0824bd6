"""The chain's dead loads on the REST interface (issue "weights and loads anywhere", item 1): every chain body
takes ``gravity`` and ``joint_forces``; the answers are the library's under them and say so (``loads``); an
analysis that does not honour them refuses by name (422 ``unsupported``)."""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("fastapi")
pytest.importorskip("httpx")

from service_helpers import app_client, check_error, post_ok  # noqa: E402

import tensegrity_opt as to  # noqa: E402

SEGMENTS = [{"a": 1.0, "b": 1.0, "k": [1.0, 1.2], "L0": 1.1, "mass": 0.04 + 0.01 * i} for i in range(3)]
LOADS = {"gravity": [2.0, -9.81], "payload": 0.03, "joint_forces": [{"joint": 3, "force": [0.0, 0.2]}]}


@pytest.fixture(scope="module")
def client():
    with app_client() as c:
        yield c


def _chain() -> to.Manipulator:
    return to.Manipulator.from_dict({"segments": SEGMENTS, **LOADS})


def test_an_equilibrium_under_loads_is_the_librarys_and_names_them(client):
    body = post_ok(client, "/v1/equilibrium", {"manipulator": {"segments": SEGMENTS, **LOADS}, "dx": 0.8, "dy": -0.3})
    eq = to.solve_equilibrium(_chain(), 0.8, -0.3)
    np.testing.assert_allclose(body["q"], eq.q, rtol=1e-12, atol=1e-14)
    assert body["energy"] == pytest.approx(eq.energy, rel=1e-12)
    assert body["loads"] == {"gravity": [2.0, -9.81], "payload": 0.03,
                             "joint_forces": [{"joint": 3, "force": [0.0, 0.2]}]}
    assert "under gravity (2, -9.81), payload 0.03, a force (0, 0.2) at joint 3" in body["message"]
    plain = post_ok(client, "/v1/equilibrium", {"manipulator": {"segments": SEGMENTS}, "dx": 0.8, "dy": -0.3})
    assert plain["loads"] is None and plain["q"] != body["q"]


def test_the_uniform_form_takes_the_loads_and_the_rest_configuration_sags(client):
    chain = {"n": 4, "mass": 0.05, "gravity": [0.0, -9.81]}
    body = post_ok(client, "/v1/rest-configurations", {"manipulator": chain, "stable_only": True})
    m = to.Manipulator.uniform(4, mass=0.05, gravity=(0.0, -9.81))
    want = to.find_equilibria_under_force(m, stable_only=True)
    assert body["status"] == "searched" and len(body["equilibria"]) == len(want)
    np.testing.assert_allclose(body["equilibria"][0]["q"], want[0].q, rtol=1e-12, atol=1e-14)
    assert body["equilibria"][0]["tip"][1] < -1.0                 # the weight pulls the tip down


def test_an_analysis_that_does_not_honour_the_loads_refuses_them_by_name(client):
    check_error(client.post("/v1/buckling", json={"manipulator": {"n": 3, "mass": 0.1, "gravity": [0, -9.81]}}),
                "unsupported", "gravity")
    check_error(client.post("/v1/limit-load", json={"manipulator": {"segments": [{"a": 1, "b": 1}] * 3,
                                                                    "joint_forces": [{"joint": 2, "force": [0, 1]}]}}),
                "unsupported", "joint_forces")


def test_a_malformed_load_is_refused_naming_its_field(client):
    check_error(client.post("/v1/equilibrium", json={"manipulator": {"n": 3, "joint_forces": [
        {"joint": 4, "force": [0, 1]}]}, "dx": 0.5}), "invalid_parameter", "joint_forces[0].joint")
    b = check_error(client.post("/v1/equilibrium", json={"manipulator": {"n": 3, "gravity": [0.0]}, "dx": 0.5}),
                    "validation_error")
    assert b["field"] == "manipulator.gravity"
    check_error(client.post("/v1/equilibrium", json={"manipulator": {"n": 3, "joint_forces": [
        {"joint": 2, "force": [0, 1], "where": 1}]}, "dx": 0.5}), "validation_error")


def test_the_weight_capacity_is_the_librarys(client):
    arm = {"n": 6, "a": 0.04, "b": 0.05, "k": 5000.0, "L0": 0.05, "mass": 0.05, "payload": 0.1, "gravity": [-9.81, 0.0]}
    body = post_ok(client, "/v1/control/weight-capacity", {"manipulator": arm})
    want = to.weight_capacity(to.Manipulator.from_dict(arm))
    assert body["kind"] == "bifurcation" and body["factor"] == pytest.approx(want.factor, rel=1e-12)
    check_error(client.post("/v1/control/weight-capacity", json={"manipulator": {"n": 3}}), "invalid_parameter",
                "gravity")
