"""``/v1/modes`` and the chain's masses on the REST interface (issue "weights and loads anywhere", item 4)."""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("fastapi")
pytest.importorskip("httpx")

from service_helpers import app_client, check_error, post_ok  # noqa: E402

import tensegrity_opt as to  # noqa: E402


@pytest.fixture(scope="module")
def client():
    with app_client() as c:
        yield c


def test_the_modes_are_the_librarys_for_both_chain_forms(client):
    segs = [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.1, "mass": 0.2 + 0.1 * i, "inertia": 0.01} for i in range(4)]
    body = post_ok(client, "/v1/modes", {"manipulator": {"segments": segs, "payload": 0.3}, "dx": 1.2, "dy": 0.2})
    m = to.Manipulator([to.Segment(1, 1, 1, 1.1, mass=0.2 + 0.1 * i, inertia=0.01) for i in range(4)], payload=0.3)
    md = to.modes(m, to.solve_equilibrium(m, 1.2, 0.2))
    assert body["success"] and body["status"] == "solved" and body["tip"] == "held"
    np.testing.assert_allclose(body["frequencies"], md.frequencies, rtol=1e-12)
    np.testing.assert_allclose(body["shapes"], md.shapes, rtol=1e-9, atol=1e-12)
    assert body["total_mass"] == pytest.approx(1.7) and body["equilibrium"]["q"] == pytest.approx(md.equilibrium.q)
    uni = post_ok(client, "/v1/modes", {"manipulator": {"n": 4, "mass": 0.1}, "fx": -0.05, "fy": 0.02})
    mu = to.Manipulator.uniform(4, mass=0.1)
    want = to.modes(mu, to.solve_equilibrium_under_force(mu, -0.05, 0.02))
    assert uni["tip"] == "loaded" and len(uni["frequencies"]) == 4
    np.testing.assert_allclose(uni["frequencies"], want.frequencies, rtol=1e-12)


def test_modes_refuse_by_field(client):
    check_error(client.post("/v1/modes", json={"manipulator": {"n": 4}, "dx": 1.0}), "invalid_parameter", "mass")
    check_error(client.post("/v1/modes", json={"manipulator": {"n": 4, "mass": 1}, "dx": 1.0, "fx": 0.1}),
                "invalid_parameter", "fx")
    check_error(client.post("/v1/modes", json={"manipulator": {"n": 4, "mass": 1}}), "invalid_parameter", "dx")
    check_error(client.post("/v1/plots/modes/job", json={"manipulator": {"n": 4, "mass": 1}}), "invalid_parameter",
                "dx")                                          # refused before a job is stored
    r = client.post("/v1/modes", json={"manipulator": {"n": 4, "mass": -1}, "dx": 1.0})
    assert r.status_code == 422 and "mass" in r.text


def test_masses_do_not_change_an_equilibrium_answer(client):
    """Without gravity the masses change no equilibrium: the same body as the massless chain's."""
    a = post_ok(client, "/v1/equilibrium", {"manipulator": {"n": 4}, "dx": 1.0, "dy": 0.1})
    b = post_ok(client, "/v1/equilibrium", {"manipulator": {"n": 4, "mass": 0.5, "payload": 0.2}, "dx": 1.0,
                                            "dy": 0.1})
    a.pop("seconds", None), b.pop("seconds", None)
    assert a["q"] == b["q"] and a["energy"] == b["energy"]
