"""HTTP service: every endpoint against the library, and every refusal path.

The expected numbers are computed here with the library directly for the same input; the
service must return the same numbers (it calls the same functions, in a worker thread).
"""

from __future__ import annotations

import json
import math
import os
import re
import threading
import time
import warnings

import numpy as np
import pytest

pytest.importorskip("fastapi")
pytest.importorskip("httpx")

with warnings.catch_warnings():
    warnings.simplefilter("ignore")
    from fastapi.testclient import TestClient

from service_helpers import app_client

import tensegrity_opt as to
from service import schemas
from service.config import Settings
from service.main import create_app
from tensegrity_opt.numerics.homotopy import homotopy_available

PAPER = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}
REL = 1e-9


def approx(x):
    return pytest.approx(x, rel=REL, abs=1e-12)


@pytest.fixture(scope="module")
def client():
    with app_client() as c:
        yield c


def make_client(**overrides) -> TestClient:
    """The app with the tests' settings (generous time limits, ``tests/support/service_helpers.py``) and
    ``overrides``."""
    return app_client(**overrides)


def check_equilibrium(got: dict, eq: to.Equilibrium) -> None:
    assert got["q"] == approx(eq.q.tolist())
    assert got["energy"] == approx(eq.energy)
    assert got["force"] == {"fx": approx(eq.fx), "fy": approx(eq.fy)}
    assert got["morse_index"] == eq.morse_index
    assert got["stable"] is bool(eq.stable)
    assert got["kind"] == eq.kind
    assert got["shape"] == eq.shape
    assert got["signs"] == eq.signs
    assert got["tip"] == approx(eq.tip.tolist())
    assert got["solver"] == {"status": eq.solver.status, "iterations": eq.solver.iterations}


def check_error(r, status: int, code: str, field: str | None = None) -> dict:
    assert r.status_code == status, r.text
    body = r.json()
    assert body["code"] == code, body
    assert isinstance(body["message"], str) and body["message"]
    if field is not None:
        assert body.get("field") == field, body
    return body


# ---------------------------------------------------------------------------- endpoints vs library
def test_equilibrium_uniform(client):
    r = client.post("/v1/equilibrium", json={"manipulator": PAPER, "dx": 0.1, "dy": 0.0})
    assert r.status_code == 200, r.text
    check_equilibrium(r.json(), to.solve_equilibrium(to.Manipulator.uniform(4, 1, 1, 1, 1), 0.1, 0.0))
    assert r.json()["shape"] == "U" and r.json()["stable"] is True


@pytest.mark.slow
def test_equilibrium_segments_and_q0(client):
    segs = [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}, {"a": 0.8, "b": 1.2, "k": [1.0, 1.5], "L0": [1.1, 1.0]},
            {"a": 1.0, "b": 0.9, "k": 2.0, "L0": 1.2}]
    m = to.Manipulator([to.Segment(1, 1, 1, 1), to.Segment(0.8, 1.2, (1.0, 1.5), (1.1, 1.0)),
                        to.Segment(1, 0.9, 2, 1.2)])
    q0 = [0.1, -0.05, -0.1]
    r = client.post("/v1/equilibrium", json={"manipulator": {"segments": segs}, "dx": 0.2, "dy": 0.05, "q0": q0})
    assert r.status_code == 200, r.text
    check_equilibrium(r.json(), to.solve_equilibrium(m, 0.2, 0.05, q0=np.array(q0)))


def test_equilibrium_certify(client):
    """certify: the answer carries the rigorous lower bound (the library's certificate, same numbers); without it
    the body has no certificate."""
    body = {"manipulator": {"n": 3, "a": 0.6, "b": 1.0, "k": 1.0, "L0": 1.2}, "dx": 0.6, "dy": 0.2}
    r = client.post("/v1/equilibrium", json={**body, "certify": True})
    assert r.status_code == 200, r.text
    got = r.json()
    lib = to.solve_equilibrium(to.Manipulator.uniform(3, 0.6, 1.0, 1.0, 1.2), 0.6, 0.2, certify=True)
    assert got["status"] == lib.status == "certified"
    cert = got["certificate"]
    assert cert["certified"] is True and cert["success"] is True
    assert cert["bound"] == pytest.approx(lib.certificate.bound, rel=1e-12)
    assert cert["bound"] <= got["energy"] and cert["gap"] <= cert["tolerance"]
    # the default search of a short multistable chain takes its short way: the bound proves its candidate here too
    plain = client.post("/v1/equilibrium", json=body).json()
    assert plain["status"] == "certified" and plain["certificate"]["certified"] is True
    assert plain["energy"] == pytest.approx(got["energy"], abs=1e-9)
    # a monotonic chain's default search carries no certificate
    mono = client.post("/v1/equilibrium", json={"manipulator": PAPER, "dx": 0.3}).json()
    assert mono["status"] == "converged" and mono.get("certificate") is None


def test_equilibrium_straight(client):
    r = client.post("/v1/equilibrium", json={"manipulator": PAPER, "dx": 0.0})
    assert r.status_code == 200
    check_equilibrium(r.json(), to.solve_equilibrium(to.Manipulator.uniform(4), 0.0, 0.0))
    assert r.json()["shape"] == "I"


def test_equilibrium_under_force(client):
    r = client.post("/v1/equilibrium/force", json={"manipulator": PAPER, "fx": -0.3, "fy": 0.01})
    assert r.status_code == 200, r.text
    check_equilibrium(r.json(), to.solve_equilibrium_under_force(to.Manipulator.uniform(4), -0.3, 0.01))


@pytest.mark.slow
def test_equilibria(client):
    r = client.post("/v1/equilibria", json={"manipulator": PAPER, "dx": 0.1})
    assert r.status_code == 200, r.text
    expected = to.find_equilibria(to.Manipulator.uniform(4), 0.1, 0.0)
    got = r.json()["equilibria"]
    assert len(got) == len(expected) == 6
    for g, e in zip(got, expected):
        check_equilibrium(g, e)
    energies = [g["energy"] for g in got]
    # sorted by energy; mirror images tie (equal to roundoff), so compare with a tolerance
    assert all(b >= a - 1e-12 * abs(a) for a, b in zip(energies, energies[1:]))
    assert [g["kind"] for g in got] == ["minimum", "minimum", "saddle", "saddle", "maximum", "maximum"]
    assert r.json()["method"] == "search" and r.json()["certified"] is False and r.json()["certificate"] is None
    assert list(r.json())[:3] == ["success", "status", "message"]
    assert (r.json()["success"], r.json()["status"]) == (True, "searched") and r.json()["message"] == expected.message


@pytest.mark.slow
@pytest.mark.skipif(not homotopy_available() and os.environ.get("TENSEGRITY_REQUIRE_PHC") != "1",
                    reason="PHCpack's phc is not installed")
def test_equilibria_homotopy_is_certified(client):
    r = client.post("/v1/equilibria", json={"manipulator": {"n": 3, "a": 0.6, "L0": 0.8}, "dx": 0.5, "dy": 0.2,
                                            "method": "homotopy"})
    assert r.status_code == 200, r.text
    body = r.json()
    assert body["method"] == "homotopy" and body["certified"] is True and body["failed_paths"] == 0
    assert (body["success"], body["status"]) == (True, "certified") and body["message"].startswith("phc (")
    assert body["paths"] == 96
    cert = body["certificate"]           # the interval proofs: one box per equilibrium, holding it
    assert (cert["status"], cert["roots_proven"], cert["method"]) == ("proven", True, "krawczyk (arb)")
    assert cert["paths"] == 96
    assert len(cert["boxes"]) == len(body["equilibria"])
    for g, box in zip(body["equilibria"], cert["boxes"]):
        x = np.array(g["q"] + [g["force"]["fx"], g["force"]["fy"]])
        assert box["proven"] and np.all(np.array(box["lower"]) <= x) and np.all(x <= np.array(box["upper"]))
        assert box["morse_index"] == g["morse_index"]
    search = to.find_equilibria(to.Manipulator.uniform(3, a=0.6, L0=0.8), 0.5, 0.2)
    assert len(body["equilibria"]) == len(search) > 0
    for g in body["equilibria"]:
        assert min(np.max(np.abs(np.array(g["q"]) - e.q)) for e in search) < 1e-8


def test_equilibria_homotopy_refusals(client, monkeypatch):
    r = client.post("/v1/equilibria", json={"manipulator": {"n": 6}, "dx": 0.5, "method": "homotopy"})
    assert r.status_code == 422 and r.json()["code"] == "too_many_segments" and r.json()["field"] == "method"
    monkeypatch.setenv("TENSEGRITY_PHC", "/nonexistent/phc")
    r = client.post("/v1/equilibria", json={"manipulator": {"n": 3}, "dx": 0.5, "method": "homotopy"})
    assert r.status_code == 503 and r.json()["code"] == "homotopy_unavailable", r.text
    assert "phcpack" in r.json()["message"]


def test_equilibria_none_inside_the_range_is_an_empty_answer(client):
    """A target reachable inside the range whose equilibria all lie outside it: 200, an empty set, a success that
    says so (not 422 ``solver_failed``); the library's body."""
    segs = [(0.4244907, 1.1061139, 2.7977215, 2.0757221), (1.2855203, 1.0943198, 1.1138807, 1.9328666),
            (0.6116747, 1.2481474, 0.6567948, 2.0724451)]
    dx, dy = 8.356180218401274, -0.07981382020185246
    r = client.post("/v1/equilibria", json={"manipulator": {"segments": [{"a": a, "b": b, "k": k, "L0": L0}
                                                                        for a, b, k, L0 in segs]},
                                            "dx": dx, "dy": dy})
    assert r.status_code == 200, r.text
    body = r.json()
    assert (body["success"], body["status"], body["equilibria"]) == (True, "searched", [])
    assert body["message"].startswith("no equilibrium inside the physical joint range")
    expected = to.find_equilibria(to.Manipulator([to.Segment(*s) for s in segs]), dx, dy)
    assert body["message"] == expected.message


@pytest.mark.parametrize("boundary", ["guided", "free"])
def test_buckling(client, boundary):
    r = client.post("/v1/buckling", json={"manipulator": PAPER, "boundary": boundary})
    assert r.status_code == 200, r.text
    bk = to.critical_force(to.Manipulator.uniform(4), boundary)
    got = r.json()
    assert list(got)[:3] == ["success", "status", "message"] and (got["success"], got["status"]) == (True, "solved")
    assert got["message"] == bk.message
    assert got["boundary"] == boundary
    assert got["critical_force"] == approx(bk.force)
    assert got["loads"] == approx(bk.loads.tolist())
    assert len(got["modes"]) == len(bk.modes)
    for g, md in zip(got["modes"], bk.modes):
        assert g["load"] == approx(md.load)
        assert g["q"] == approx(md.q.tolist())
        for name in ("fy", "energy_factor", "mu_x", "fy_coefficient"):
            assert g[name] == approx(getattr(md, name)), name
        assert (g["shape"], g["signs"], g["stable"]) == (md.shape, md.signs, md.stable)
    if boundary == "guided":
        assert got["critical_force"] == pytest.approx(-0.572793, abs=1e-6)


def _check_curve_points(points, c):
    assert len(points) == c.dx.size
    for i, p in enumerate(points):
        assert p["dx"] == approx(c.dx[i]) and p["dy"] == approx(c.dy[i])
        assert p["fx"] == approx(c.fx[i]) and p["fy"] == approx(c.fy[i])
        assert p["energy"] == approx(c.energy[i])
        assert p["q"] == approx(c.q[i].tolist())
        assert p["stable"] is bool(c.stable[i])
        assert p["morse_index"] == int(c.morse_index[i])
        assert p["shape"] == c.shape[i]
        assert p["branch"] == int(c.branch[i])


def test_force_deflection_range(client):
    r = client.post("/v1/force-deflection", json={"manipulator": PAPER, "dx": {"start": 0.0, "stop": 0.3, "num": 4}})
    assert r.status_code == 200, r.text
    c = to.force_deflection(to.Manipulator.uniform(4), np.linspace(0.0, 0.3, 4), 0.0, branch="stable")
    got = r.json()
    _check_curve_points(got["points"], c)
    assert len(got["jumps"]) == len(c.jumps) >= 1
    j, gj = c.jumps[0], got["jumps"][0]
    assert gj["kind"] == j.kind == "buckling"
    assert gj["dx_before"] == approx(j.dx_before) and gj["dx_after"] == approx(j.dx_after)
    assert gj["force_after"] == {"fx": approx(j.force_after[0]), "fy": approx(j.force_after[1])}
    assert gj["force_before"] == {"fx": approx(j.force_before[0]), "fy": approx(j.force_before[1])}
    assert got["branches"] == []


def test_force_deflection_list_all_branches(client):
    dx = [0.05, 0.1, 0.2]
    r = client.post("/v1/force-deflection", json={"manipulator": PAPER, "dx": dx, "dy": 0.0, "branch": "all"})
    assert r.status_code == 200, r.text
    c = to.force_deflection(to.Manipulator.uniform(4), np.array(dx), 0.0, branch="all")
    got = r.json()
    _check_curve_points(got["points"], c)
    assert len(got["branches"]) == len(c.branches) >= 2
    for gb, br in zip(got["branches"], c.branches):
        for i, p in enumerate(gb["points"]):
            exists = bool(np.isfinite(br.energy[i]))
            assert p["exists"] is exists
            if exists:
                assert p["energy"] == approx(br.energy[i]) and p["fx"] == approx(br.fx[i])
                assert p["q"] == approx(br.q[i].tolist())
            else:
                assert p["energy"] is None and p["fx"] is None and all(v is None for v in p["q"])


@pytest.mark.slow
def test_force_deflection_answers_a_partial_curve_with_200(client):
    """The paper's chain has no stable equilibrium from dx = 6 on, out of the closed range's reach (past dx ~ 3.12 it
    rests on joint 3's stop; ``tests/analyses/paths/test_curves.py``): the points before, with the end and the buckling
    jump at the guided critical force, as the library's curve."""
    body = {"manipulator": PAPER, "dx": {"start": 0.0, "stop": 6.2, "num": 63}, "dy": 0.0}
    r = client.post("/v1/force-deflection", json=body)
    assert r.status_code == 200, r.text
    got = r.json()
    schemas.ForceDeflectionOut.model_validate(got)
    assert got["success"] is False and got["status"] == "no_stable_equilibrium"
    assert got["requested"] == 63 and len(got["points"]) == 60
    assert got["ended_at"]["dx"] == pytest.approx(6.0) and got["ended_at"]["dy"] == 0.0
    assert got["ended_at"]["status"] == "no_stable_equilibrium" and got["ended_at"]["message"]
    assert got["ended_at"]["success"] is False
    assert got["message"].endswith("60 of 63 points computed.")
    assert got["points"][0]["status"] == "straight" and got["points"][-1]["status"] == "converged"
    assert got["points"][31]["solver"]["status"] == "Newton_Converged"           # dx = 3.1, inside the range
    assert [j["kind"] for j in got["jumps"]] == ["buckling"]
    jd = got["jumps"][0]
    assert jd["delta"]["fx"] == pytest.approx(-0.572793, abs=1e-6) and jd["label"].startswith("buckling")
    assert got == to.force_deflection(to.Manipulator.uniform(4), np.linspace(0.0, 6.2, 63)).to_dict()


def test_stiffness(client):
    r = client.post("/v1/stiffness", json={"manipulator": PAPER, "dx": 0.1, "dy": 0.01})
    assert r.status_code == 200, r.text
    m = to.Manipulator.uniform(4)
    eq = to.solve_equilibrium(m, 0.1, 0.01)
    K = to.cartesian_stiffness(m, eq)
    got = r.json()
    assert np.array(got["matrix"]) == approx(K)
    assert np.array(got["matrix"]).shape == (2, 2)
    check_equilibrium(got["equilibrium"], eq)


def test_stiffness_undefined_when_straight(client):
    r = client.post("/v1/stiffness", json={"manipulator": PAPER, "dx": 0.0})
    check_error(r, 422, "invalid_parameter")


@pytest.mark.parametrize("q", [[-0.5, 0.0, 0.5, 1.2], {"start": -1.0, "stop": 1.0, "num": 9}])
def test_segment_torque(client, q):
    seg = {"a": 0.9, "b": 1.1, "k": [1.0, 2.0], "L0": [1.0, 1.3]}
    r = client.post("/v1/segment/torque", json={"segment": seg, "q": q})
    assert r.status_code == 200, r.text
    s = to.Segment(0.9, 1.1, (1.0, 2.0), (1.0, 1.3))
    qs = np.linspace(q["start"], q["stop"], q["num"]) if isinstance(q, dict) else np.array(q)
    got = r.json()
    assert got["q"] == approx(qs.tolist())
    assert got["torque"] == approx(s.torque(qs).tolist())
    assert got["dtorque"] == approx(s.dtorque(qs).tolist())
    assert got["energy"] == approx(s.energy(qs).tolist())
    assert got["stiffness"] == approx(s.stiffness)
    assert got["monotonic"] is s.monotonic()
    assert got["joint_limit"] == approx(s.joint_limit)


def test_energy_landscape(client):
    body = {"manipulator": PAPER, "dx": 0.1, "dy": 0.0, "pair": [0, 3], "grid": 15}
    r = client.post("/v1/energy-landscape", json=body)
    assert r.status_code == 200, r.text
    land = to.energy_landscape(to.Manipulator.uniform(4), 0.1, 0.0, pair=(0, 3), grid=15)
    got = r.json()
    assert (got["success"], got["status"], got["message"]) == (True, "evaluated", land.message)
    assert got["pair"] == [0, 3]
    assert got["qi"] == approx(land.qi.tolist()) and got["qj"] == approx(land.qj.tolist())
    E = np.array([[[np.nan if v is None else v for v in row] for row in plane] for plane in got["energy"]])
    assert E.shape == land.energy.shape == (2, 15, 15)
    assert np.array_equal(np.isnan(E), np.isnan(land.energy))
    assert np.any(np.isnan(E)) and np.any(np.isfinite(E))        # nulls where unreachable
    fin = np.isfinite(land.energy)
    assert E[fin] == approx(land.energy[fin])


def test_energy_landscape_span_and_pair(client):
    body = {"manipulator": PAPER, "dx": 0.2, "dy": 0.1, "pair": [1, 2], "grid": 5, "span": 0.5}
    r = client.post("/v1/energy-landscape", json=body)
    assert r.status_code == 200, r.text
    land = to.energy_landscape(to.Manipulator.uniform(4), 0.2, 0.1, pair=(1, 2), grid=5, span=0.5)
    assert r.json()["qi"] == approx(land.qi.tolist())


def test_energy_landscape_needs_four_segments(client):
    r = client.post("/v1/energy-landscape", json={"manipulator": {"n": 5}, "dx": 0.1})
    check_error(r, 422, "unsupported", "manipulator.n")


def test_batch_continuation(client):
    targets = [{"dx": 0.05, "dy": 0.0}, {"dx": 0.1, "dy": 0.01}, {"dx": 20.0, "dy": 0.0}, {"dx": 0.15, "dy": 0.0}]
    r = client.post("/v1/batch/equilibrium", json={"manipulator": PAPER, "targets": targets, "continuation": True})
    assert r.status_code == 200, r.text
    got = r.json()
    assert got["succeeded"] == 3 and got["failed"] == 1
    m = to.Manipulator.uniform(4)
    expected = to.solve_equilibria_batch(m, [(t["dx"], t["dy"]) for t in targets])
    for i, (t, item) in enumerate(zip(targets, got["results"])):
        assert item["index"] == i and item["dx"] == t["dx"] and item["dy"] == t["dy"]
        if i == 2:
            assert item["equilibrium"] is None
            assert item["error"]["code"] == "unreachable_target"
            assert item["error"]["field"] == "targets[2].dx"
            continue
        check_equilibrium(item["equilibrium"], expected[i])
        assert item["error"] is None


def test_batch_without_continuation(client):
    targets = [{"dx": 0.1}, {"dx": 0.2}]
    r = client.post("/v1/batch/equilibrium", json={"manipulator": PAPER, "targets": targets, "continuation": False})
    assert r.status_code == 200, r.text
    m = to.Manipulator.uniform(4)
    for t, item in zip(targets, r.json()["results"]):
        check_equilibrium(item["equilibrium"], to.solve_equilibrium(m, t["dx"], 0.0))


# ---------------------------------------------------------------------------- ops endpoints
def test_health_ready_version(client):
    assert client.get("/healthz").json() == {"status": "ok"}
    r = client.get("/readyz")
    assert r.status_code == 200 and r.json()["status"] == "ready"
    v = client.get("/version").json()
    assert v["version"] == to.__version__ and v["library_version"] == to.__version__
    from tensegrity_opt.numerics import kernels
    from tensegrity_opt.numerics.build import compiler_name
    assert v["limits"]["inline_max_segments"] == 8
    client.post("/v1/equilibrium", json={"manipulator": PAPER, "dx": 0.1})      # loads the n = 4 kernels
    k = client.get("/version").json()["kernels"]
    assert k["compiler"] == compiler_name() and k["max_segments"] == kernels.KERNEL_MAX
    assert 4 in (k["compiled"] if kernels.compiler() else k["virtual_machine"])
    assert v["limits"]["max_segments"] == 200 and v["limits"]["max_batch"] == 1000
    assert v["auth"] is False


def test_version_names_the_compiler_not_where_it_is(client, monkeypatch):
    # a compiler installed under a private path: /version gives its name (and version), never the path
    from tensegrity_opt.numerics import build, kernels
    private = "/opt/private-toolchain/secret/bin/cc"
    monkeypatch.setattr(build, "compiler", lambda: private)
    monkeypatch.setattr(kernels, "compiler", lambda: private)
    r = client.get("/version")
    assert r.status_code == 200
    assert "private-toolchain" not in r.text and "/bin/" not in r.text, r.text
    assert r.json()["kernels"]["compiler"].split()[0] == "cc"


def test_readyz_before_startup():
    app = create_app(Settings(warmup=False))
    c = TestClient(app)               # no context manager: lifespan not run, workers not started
    r = c.get("/readyz")
    assert r.status_code == 503 and r.json()["status"] == "starting"


@pytest.mark.slow
def test_warmup_then_ready():
    with make_client(warmup=True, workers=1) as c:
        assert c.get("/readyz").json()["status"] == "ready"


def test_metrics(client):
    client.post("/v1/equilibrium", json={"manipulator": PAPER, "dx": 0.1})
    client.post("/v1/equilibrium/force", json={"manipulator": PAPER, "fx": -0.6})   # a solver failure
    r = client.get("/metrics")
    assert r.status_code == 200
    assert r.headers["content-type"].startswith("text/plain")
    text = r.text
    assert 'tensegrity_http_requests_total{method="POST",route="/v1/equilibrium",status="200"}' in text
    assert 'tensegrity_http_request_duration_seconds_bucket{le="0.1",method="POST",route="/v1/equilibrium"}' in text
    assert 'tensegrity_solver_failures_total{code="no_equilibrium"}' in text
    assert "tensegrity_solver_pool_in_flight" in text


@pytest.mark.slow
def test_docs_offline(client):
    r = client.get("/docs")
    assert r.status_code == 200
    html = r.text
    assert "/static/docs/swagger-ui-bundle.js" in html and "/static/docs/swagger-ui.css" in html
    assert "cdn" not in html.lower() and "https://" not in html
    for asset in ("swagger-ui-bundle.js", "swagger-ui.css"):
        a = client.get(f"/static/docs/{asset}")
        assert a.status_code == 200 and len(a.content) > 10000
    assert client.get("/openapi.json").json()["info"]["title"] == "tensegrity-opt service"
    r = client.get("/redoc")
    assert r.status_code == 200 and "/static/docs/redoc.standalone.js" in r.text and "https://" not in r.text


# ---------------------------------------------------------------------------- 422: schema violations
@pytest.mark.parametrize("body, field", [
    ({"manipulator": {"n": 4, "a": -1.0}, "dx": 0.1}, "manipulator.a"),
    ({"manipulator": {"n": 0}, "dx": 0.1}, "manipulator.n"),
    ({"manipulator": {"n": 4}, "dx": "0.1"}, "dx"),                       # strings are not numbers
    ({"manipulator": {"n": 4}, "dx": True}, "dx"),                        # nor booleans
    ({"manipulator": {"n": 4}}, "dx"),                                     # missing
    ({"manipulator": {"n": 4}, "dx": 0.1, "dz": 1}, "dz"),                 # unknown field
    ({"manipulator": {"segments": [{"a": 1, "b": 1}, {"a": 1, "b": 0}]}, "dx": 0.1}, "manipulator.segments[1].b"),
    ({"manipulator": {"segments": [{"a": 1, "b": 1, "k": [1, -2]}]}, "dx": 0.1}, "manipulator.segments[0].k[1]"),
    ({"manipulator": {"segments": [{"a": 1, "b": 1, "L0": [1, 2, 3]}]}, "dx": 0.1}, "manipulator.segments[0].L0"),
    ({"manipulator": {"segments": []}, "dx": 0.1}, "manipulator.segments"),
    ({"manipulator": {"n": 4}, "dx": 0.1, "q0": [0.0, 10.0, 0.0, 0.0]}, "q0[1]"),
])
def test_schema_violation_names_the_field(client, body, field):
    r = client.post("/v1/equilibrium", json=body)
    out = check_error(r, 422, "validation_error", field)
    assert out["errors"][0]["field"] == field
    assert out["errors"][0]["type"]


def test_schema_violation_nan_and_bad_json(client):
    r = client.post("/v1/equilibrium", content=b'{"manipulator": {"n": 4}, "dx": NaN}',
                    headers={"content-type": "application/json"})
    check_error(r, 422, "validation_error", "dx")
    r = client.post("/v1/equilibrium", content=b"{not json", headers={"content-type": "application/json"})
    check_error(r, 422, "validation_error", "body")


def test_schema_limits(client):
    r = client.post("/v1/force-deflection", json={"manipulator": PAPER, "dx": {"start": 0, "stop": 1, "num": 502}})
    check_error(r, 422, "validation_error", "dx.num")
    r = client.post("/v1/energy-landscape", json={"manipulator": PAPER, "dx": 0.1, "grid": 500})
    check_error(r, 422, "validation_error", "grid")
    r = client.post("/v1/buckling", json={"manipulator": PAPER, "boundary": "clamped"})
    check_error(r, 422, "validation_error", "boundary")


# ---------------------------------------------------------------------------- 422: domain errors
def test_unreachable_target(client):
    r = client.post("/v1/equilibrium", json={"manipulator": PAPER, "dx": 20.0})
    body = check_error(r, 422, "unreachable_target", "dx")
    assert body["details"]["reach"] == pytest.approx(7.0)
    r = client.post("/v1/equilibria", json={"manipulator": PAPER, "dx": -0.5})
    check_error(r, 422, "unreachable_target", "dx")


def test_straight_not_equilibrium(client):
    segs = [{"a": 1.0, "b": 1.0, "k": [1.0, 2.0], "L0": 1.0}] + [{"a": 1.0, "b": 1.0}] * 3
    r = client.post("/v1/buckling", json={"manipulator": {"segments": segs}})
    check_error(r, 422, "straight_not_equilibrium", "manipulator.segments[0]")


def test_straight_unstable(client):
    assert to.Segment(0.5, 1.0, 1.0, 0.5).stiffness < 0          # K = b L0 - 2 (b^2 - a^2) = -1
    r = client.post("/v1/buckling", json={"manipulator": {"n": 4, "a": 0.5, "b": 1.0, "k": 1.0, "L0": 0.5}})
    check_error(r, 422, "straight_unstable", "manipulator.L0")
    segs = [{"a": 1.0, "b": 1.0}, {"a": 0.5, "b": 1.0, "L0": 0.5}]
    r = client.post("/v1/buckling", json={"manipulator": {"segments": segs}})
    check_error(r, 422, "straight_unstable", "manipulator.segments[1].L0")


@pytest.mark.slow
def test_too_many_segments(client):
    # The schema's cap is the default limit (200): above it the document itself refuses the body.
    r = client.post("/v1/equilibrium", json={"manipulator": {"n": 201}, "dx": 0.1})
    check_error(r, 422, "validation_error", "manipulator.n")
    with make_client(max_segments=150) as c:
        r = c.post("/v1/equilibrium", json={"manipulator": {"n": 151}, "dx": 0.1})
        body = check_error(r, 422, "too_many_segments", "manipulator.n")
        assert body["details"] == {"n": 151, "max_segments": 150}
    with make_client(max_segments=3) as c:
        r = c.post("/v1/buckling", json={"manipulator": {"segments": [{"a": 1, "b": 1}] * 4}})
        check_error(r, 422, "too_many_segments", "manipulator.segments")
        r = c.post("/v1/buckling", json={"manipulator": {"segments": [{"a": 1, "b": 1}] * 3}})
        assert r.status_code == 200


@pytest.mark.slow
@pytest.mark.parametrize("n", [150, 500, 10**9, 1e9])
def test_too_many_segments_names_the_real_limit_for_every_n(n):
    """On a server set below the schema's cap (TENSEGRITY_MAX_SEGMENTS=100) every length over the setting (150,
    500, 1e9: over the schema's "<= 200" too) is the server's own ``too_many_segments``, naming its limit, not the
    schema's refusal; a job's n values too."""
    with make_client(max_segments=100) as c:
        r = c.post("/v1/equilibrium", json={"manipulator": {"n": n}, "dx": 0.1})
        body = check_error(r, 422, "too_many_segments", "manipulator.n")
        assert body["message"] == f"the chain has {int(n)} segments; this server accepts at most 100"
        assert body["details"] == {"n": int(n), "max_segments": 100}
        r = c.post("/v1/jobs", json={"analysis": "buckling", "grid": {"n": [4, n]}})
        body = check_error(r, 422, "too_many_segments", "grid.n[1]")
        assert body["message"].endswith("this server accepts at most 100") and body["details"]["n"] == int(n)
        # a body with another error stays a validation_error; the design endpoints' own cap (60) is lower
        r = c.post("/v1/equilibrium", json={"manipulator": {"n": n}, "dx": "far"})
        check_error(r, 422, "validation_error")
        r = c.post("/v1/design/critical-force", json={"manipulator": {"n": n}})
        assert "less than or equal to 60" in check_error(r, 422, "validation_error", "manipulator.n")["message"]
    segs = [{"a": 1, "b": 1}] * 300
    with make_client(max_segments=100) as c:
        body = check_error(c.post("/v1/buckling", json={"manipulator": {"segments": segs}}), 422,
                           "too_many_segments", "manipulator.segments")
        assert body["details"] == {"n": 300, "max_segments": 100}
    with make_client() as c:                  # the default setting is the cap: the schema names it
        r = c.post("/v1/equilibrium", json={"manipulator": {"n": n}, "dx": 0.1})
        if n > 200:
            assert "less than or equal to 200" in check_error(r, 422, "validation_error", "manipulator.n")["message"]


def test_batch_too_large():
    with make_client(max_batch=2) as c:
        r = c.post("/v1/batch/equilibrium", json={"manipulator": PAPER, "targets": [{"dx": 0.1}] * 3})
        check_error(r, 422, "batch_too_large", "targets")


@pytest.mark.slow
def test_solver_failure_carries_status(client):
    # folded back that far, the tip is outside the closed range's workspace (the independent brute force agrees):
    # the library's refusal and its solver status reach the answer unchanged
    m = to.Manipulator.uniform(4)
    with pytest.raises(to.TensegrityError) as info:
        to.solve_equilibrium(m, 7.9, 0.0)
    r = client.post("/v1/equilibrium", json={"manipulator": PAPER, "dx": 7.9})
    body = check_error(r, 422, info.value.code)
    if isinstance(info.value, to.SolverError):
        assert body["status"] == info.value.status and body["status"]
    else:                                       # a refusal of the target (unreachable_target): its words unchanged
        assert body["message"] == info.value.message and body["field"] == info.value.field


def test_no_equilibrium_under_force(client):
    with pytest.raises(to.NoEquilibriumError) as info:
        to.solve_equilibrium_under_force(to.Manipulator.uniform(4), -0.6, 0.0)
    r = client.post("/v1/equilibrium/force", json={"manipulator": PAPER, "fx": -0.6})
    body = check_error(r, 422, "no_equilibrium")
    assert body["status"] == info.value.status


def test_q0_of_wrong_length(client):
    r = client.post("/v1/equilibrium", json={"manipulator": PAPER, "dx": 0.1, "q0": [0.0, 0.0]})
    check_error(r, 422, "invalid_parameter", "q0")


# ---------------------------------------------------------------------------- 504, 503, 413, 401, CORS, 404
def _works_for_ten_minutes(req, *args, **kwargs):
    """A stand-in for a search that runs far beyond any limit: pure Python (interruptible between bytecodes)."""
    end = time.monotonic() + 600.0
    while time.monotonic() < end:
        pass


@pytest.mark.slow
def test_timeout_504_and_recovery(monkeypatch):
    from service.api.routes import equilibrium as routes

    monkeypatch.setattr(routes, "equilibria_task", _works_for_ten_minutes)
    with make_client(solve_timeout=0.5, workers=1) as c:
        r = c.post("/v1/equilibria", json={"manipulator": {"n": 4}, "dx": 0.1})
        check_error(r, 504, "timeout")
        pool = c.app.state.executors.threads
        deadline = time.monotonic() + 300          # far less than the stand-in's ten minutes
        while pool.in_flight and time.monotonic() < deadline:
            time.sleep(0.01)
        assert pool.in_flight == 0            # the abandoned solve was interrupted, the worker is free
        assert 'tensegrity_solver_failures_total{code="timeout"} 1.0' in c.get("/metrics").text
        assert c.post("/v1/segment/torque", json={"segment": {"a": 1, "b": 1}, "q": [0.0]}).status_code == 200


def test_saturated_pool_503():
    with make_client(workers=1, queue_size=0, retry_after=3, inline_max_segments=0) as c:
        pool = c.app.state.executors.threads
        gate = threading.Event()
        job = pool.submit(gate.wait, 10)      # occupies the only worker
        try:
            r = c.post("/v1/equilibrium", json={"manipulator": PAPER, "dx": 0.1})
            check_error(r, 503, "overloaded")
            assert r.headers["retry-after"] == "3"
        finally:
            gate.set()
            job.future.result(5)
        r = c.post("/v1/equilibrium", json={"manipulator": PAPER, "dx": 0.1})
        assert r.status_code == 200


def test_body_too_large_413():
    with make_client(max_body_bytes=2000) as c:
        big = {"manipulator": {"segments": [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}] * 100}, "dx": 0.1}
        r = c.post("/v1/equilibrium", json=big)
        check_error(r, 413, "body_too_large")
        payload = json.dumps(big).encode()

        def chunks():                          # no Content-Length: counted while reading
            for i in range(0, len(payload), 500):
                yield payload[i:i + 500]

        r = c.post("/v1/equilibrium", content=chunks(), headers={"content-type": "application/json"})
        check_error(r, 413, "body_too_large")
        r = c.post("/v1/equilibrium", json={"manipulator": PAPER, "dx": 0.1})
        assert r.status_code == 200


def test_api_key_401():
    with make_client(api_keys=["s3cret", "other"]) as c:
        r = c.post("/v1/equilibrium", json={"manipulator": PAPER, "dx": 0.1})
        check_error(r, 401, "unauthorized", "X-API-Key")
        assert r.headers["www-authenticate"] == "ApiKey"
        r = c.post("/v1/equilibrium", json={"manipulator": PAPER, "dx": 0.1}, headers={"X-API-Key": "wrong"})
        check_error(r, 401, "unauthorized")
        r = c.post("/v1/buckling", json={"manipulator": PAPER}, headers={"X-API-Key": "s3cret"})
        assert r.status_code == 200
        assert c.get("/healthz").status_code == 200          # the health routes stay open
        assert c.get("/version", headers={"X-API-Key": "other"}).json()["auth"] is True


@pytest.mark.parametrize("path", ["/openapi.json", "/version", "/metrics"])
def test_the_documents_need_a_key_when_the_server_has_keys(path):
    """With keys: the OpenAPI document, the version and the metrics are the API's (401 without a key); the health
    routes, the page and the docs pages stay open. Without keys every one is open."""
    with make_client(api_keys=["s3cret"]) as c:
        r = c.get(path)
        assert r.status_code == 401 and r.json()["code"] == "unauthorized", r.text[:200]
        assert r.headers["www-authenticate"] == "ApiKey"
        assert c.get(path, headers={"X-API-Key": "wrong"}).status_code == 401
        assert c.get(path, headers={"X-API-Key": "s3cret"}).status_code == 200
        for open_path in ("/healthz", "/readyz", "/", "/docs", "/redoc"):
            assert c.get(open_path).status_code == 200, open_path
    with make_client() as c:
        assert c.get(path).status_code == 200


def test_static_documents_are_built_once(monkeypatch):
    """``/openapi.json`` is encoded once however often it is asked for; ``/version``'s body is built once, and again
    only when the kernels loaded in the process change."""
    from tensegrity_opt.numerics import kernels

    encoded: list[int] = []
    dumps = json.dumps

    def counting_dumps(obj, *args, **kwargs):
        out = dumps(obj, *args, **kwargs)
        if len(out) > 100_000:                  # the document (~390 KB); nothing else these requests encode
            encoded.append(len(out))
        return out

    built: list[int] = []
    status = kernels.status

    def counting_status():
        built.append(1)
        return status()

    monkeypatch.setattr(json, "dumps", counting_dumps)
    monkeypatch.setattr(kernels, "status", counting_status)
    with make_client() as c:
        docs = {c.get("/openapi.json").content for _ in range(30)}
        assert len(docs) == 1 and len(encoded) == 1
        assert json.loads(docs.pop())["info"]["title"] == "tensegrity-opt service"
        versions = {c.get("/version").content for _ in range(30)}
        assert len(versions) == 1 and len(built) == 1
        loaded = kernels.libraries()
        monkeypatch.setattr(kernels, "libraries", lambda: {**loaded, "another_kernel": ""})
        again = {c.get("/version").content for _ in range(10)}
        assert len(built) == 2 and len(again) == 1


def test_api_keys_from_environment(monkeypatch):
    monkeypatch.setenv("TENSEGRITY_API_KEYS", "k1, k2")
    monkeypatch.setenv("TENSEGRITY_MAX_SEGMENTS", "12")
    st = Settings()
    assert st.api_keys == ["k1", "k2"] and st.max_segments == 12
    monkeypatch.setenv("TENSEGRITY_API_KEYS", '["a,b"]')
    assert Settings().api_keys == ["a,b"]


def test_cors_off_by_default_and_on_when_configured(client):
    pre = {"Origin": "http://example.org", "Access-Control-Request-Method": "POST"}
    r = client.options("/v1/equilibrium", headers=pre)
    assert "access-control-allow-origin" not in r.headers
    with make_client(cors_origins=["http://example.org"]) as c:
        r = c.options("/v1/equilibrium", headers=pre)
        assert r.status_code == 200
        assert r.headers["access-control-allow-origin"] == "http://example.org"


def test_unknown_path_and_method(client):
    check_error(client.get("/v1/nothing"), 404, "not_found")
    check_error(client.get("/v1/equilibrium"), 405, "method_not_allowed")


# ---------------------------------------------------------------------------- response size
def test_response_size_limit_is_estimated_before_solving():
    with make_client(max_response_bytes=20000) as c:
        body = {"manipulator": PAPER, "dx": {"start": 0.0, "stop": 0.5, "num": 301}}
        r = c.post("/v1/force-deflection", json=body)
        err = check_error(r, 422, "response_too_large", "dx")
        assert err["details"]["max_response_bytes"] == 20000 and err["details"]["estimated_bytes"] > 20000
        assert "20000" in err["message"] and "TENSEGRITY_MAX_RESPONSE_BYTES" in err["message"]
        r = c.post("/v1/force-deflection", json={**body, "dx": {"start": 0.0, "stop": 0.5, "num": 5}})
        assert r.status_code == 200, r.text
        assert c.get("/version").json()["limits"]["max_response_bytes"] == 20000


def test_response_size_limit_is_counted_while_rendering():
    with make_client(max_response_bytes=4096, inline_max_segments=0) as c:
        targets = [{"dx": 0.01 * (i + 1)} for i in range(30)]          # ~30 x 400 bytes
        r = c.post("/v1/batch/equilibrium", json={"manipulator": PAPER, "targets": targets})
        err = check_error(r, 422, "response_too_large", "targets")
        assert err["details"] == {"max_response_bytes": 4096}
        r = c.post("/v1/batch/equilibrium", json={"manipulator": PAPER, "targets": targets[:2]})
        assert r.status_code == 200 and r.json()["succeeded"] == 2


def test_json_answers_are_rendered_in_the_solver_thread(monkeypatch):
    import service.responses as deps  # render_task, the renderer the dispatcher hands to the threads

    threads = []
    real = deps.render_json_bounded

    def spy(*args, **kwargs):
        threads.append(threading.current_thread().name)
        return real(*args, **kwargs)

    monkeypatch.setattr(deps, "render_json_bounded", spy)
    with make_client(inline_max_segments=0) as c:
        r = c.post("/v1/force-deflection", json={"manipulator": PAPER, "dx": [0.05, 0.1], "branch": "all"})
        assert r.status_code == 200 and r.headers["content-type"] == "application/json"
        assert len(r.json()["points"]) == 2
    assert threads and all(name.startswith("solver-") for name in threads)


def test_bounded_rendering_gives_the_same_bytes():
    from service.responses import ResponseTooLarge, render_json, render_json_bounded

    x = {"points": [{"q": [0.1 * j for j in range(50)], "e": float("nan"), "s": "é"} for _ in range(40)],
         "branches": [{"id": 1, "points": [{"q": [1.0] * 40}] * 40}], "n": np.int64(3), "a": np.arange(3.0)}
    body = render_json(x)
    assert render_json_bounded(x, len(body)) == body
    assert json.loads(body)["points"][0]["e"] is None and json.loads(body)["n"] == 3
    with pytest.raises(ResponseTooLarge) as info:
        render_json_bounded(x, len(body) - 1, "dx")
    assert isinstance(info.value, ValueError) and info.value.field == "dx"


# ---------------------------------------------------------------------------- the contract
def test_integral_floats_are_the_integers_the_schema_allows(client):
    # JSON Schema's "integer" is any number with a zero fractional part: 4.0 and 5.0 are valid
    r = client.post("/v1/equilibrium", json={"manipulator": {"n": 4.0}, "dx": 0.1})
    assert r.status_code == 200, r.text
    assert r.json() == client.post("/v1/equilibrium", json={"manipulator": {"n": 4}, "dx": 0.1}).json()
    r = client.post("/v1/force-deflection", json={"manipulator": PAPER, "dx": {"start": 0.0, "stop": 0.1, "num": 3.0}})
    assert r.status_code == 200 and len(r.json()["points"]) == 3
    for bad in (4.5, "4", True):            # still strict otherwise
        r = client.post("/v1/equilibrium", json={"manipulator": {"n": bad}, "dx": 0.1})
        check_error(r, 422, "validation_error", "manipulator.n")


def test_schema_caps_are_the_default_limits():
    from service import schemas as s
    from service.config import HARD_MAX_BATCH, HARD_MAX_SEGMENTS

    st = Settings()
    assert (HARD_MAX_SEGMENTS, HARD_MAX_BATCH) == (st.max_segments, st.max_batch) == (200, 1000)
    doc = create_app(Settings(warmup=False)).openapi()["components"]["schemas"]
    assert doc["UniformManipulatorIn"]["properties"]["n"]["maximum"] == 200
    assert doc["SegmentedManipulatorIn"]["properties"]["segments"]["maxItems"] == 200
    assert doc["BatchEquilibriumRequest"]["properties"]["targets"]["maxItems"] == 1000
    assert doc["DesignUniformManipulatorIn"]["properties"]["n"]["maximum"] == s.MAX_DESIGN_SEGMENTS
    # integers inside Annotated keep real JSON Schema bounds (not pydantic's "ge"/"le" keywords)
    assert doc["PlotTorqueRequest"]["properties"]["dpi"]["minimum"] == 30
    assert doc["EnergyLandscapeRequest"]["properties"]["pair"]["items"]["maximum"] == 3
    text = json.dumps(doc)
    assert '"ge":' not in text and '"le":' not in text
    with pytest.raises(ValueError):
        Settings(max_segments=201)


def test_design_limit_is_in_the_schema(client):
    r = client.post("/v1/design/preloads-for-load", json={"manipulator": {"n": 61}, "required": 1.0})
    check_error(r, 422, "validation_error", "manipulator.n")
    r = client.post("/v1/design/preloads-for-load", json={"manipulator": {"segments": [{"a": 1, "b": 1}] * 61},
                                                           "required": 1.0})
    check_error(r, 422, "validation_error", "manipulator.segments")


def test_api_key_is_optional_in_the_document():
    doc = create_app(Settings(warmup=False)).openapi()
    ops = [op for item in doc["paths"].values() for op in item.values() if op.get("security")]
    assert ops and all(op["security"] == [{"ApiKey": []}, {}] for op in ops)


def test_allow_lists_every_method_of_the_path(client):
    r = client.options("/v1/jobs")
    assert r.status_code == 204 and r.headers["allow"] == "GET, HEAD, OPTIONS, POST"
    r = client.put("/v1/jobs")
    check_error(r, 405, "method_not_allowed")
    assert r.headers["allow"] == "GET, HEAD, OPTIONS, POST"
    r = client.request("PATCH", "/v1/jobs/abc")
    assert r.status_code == 405 and r.headers["allow"] == "DELETE, GET, HEAD, OPTIONS"
    r = client.get("/v1/equilibrium")
    assert r.headers["allow"] == "OPTIONS, POST"
    check_error(client.options("/v1/nothing"), 404, "not_found")


@pytest.mark.parametrize("path", ["/healthz", "/readyz", "/version", "/metrics"])
def test_head_on_the_get_routes(client, path):
    get, head = client.get(path), client.head(path)
    assert head.status_code == get.status_code and head.content == b""
    assert head.headers["content-type"] == get.headers["content-type"]


def test_no_trailing_slash_redirect_from_the_host_header(client):
    r = client.get("/healthz/", headers={"Host": "evil.example"}, follow_redirects=False)
    check_error(r, 404, "not_found")
    assert "location" not in r.headers


def test_cors_allows_delete_and_head():
    with make_client(cors_origins=["http://example.org"]) as c:
        for method in ("DELETE", "HEAD", "GET", "POST"):
            r = c.options("/v1/jobs/abc", headers={"Origin": "http://example.org",
                                                   "Access-Control-Request-Method": method})
            assert r.status_code == 200, (method, r.text)
            assert method in r.headers["access-control-allow-methods"]


def test_concurrent_requests_agree(client):
    """Several threads at once: every answer equals the library's (no CasADi instance is shared)."""
    m = to.Manipulator.uniform(4)
    dxs = [0.05, 0.1, 0.15, 0.2, 0.25, 0.3]
    expected = {dx: to.solve_equilibrium(m, dx) for dx in dxs}
    results: dict[float, dict] = {}

    def call(dx):
        results[dx] = client.post("/v1/equilibrium", json={"manipulator": PAPER, "dx": dx}).json()

    threads = [threading.Thread(target=call, args=(dx,)) for dx in dxs]
    for t in threads:
        t.start()
    for t in threads:
        t.join(30)
    for dx in dxs:
        check_equilibrium(results[dx], expected[dx])


def test_responses_are_valid_json_without_nan(client):
    r = client.post("/v1/energy-landscape", json={"manipulator": PAPER, "dx": 0.1, "grid": 4})
    assert "NaN" not in r.text and "Infinity" not in r.text
    assert not any(isinstance(v, float) and math.isnan(v) for v in json.loads(r.text)["qi"])


def test_batch_bad_q0_refuses_the_request(client):
    r = client.post("/v1/batch/equilibrium", json={"manipulator": PAPER, "targets": [{"dx": 0.1}], "q0": [0.0]})
    check_error(r, 422, "invalid_parameter", "q0")
    r = client.post("/v1/batch/equilibrium", json={"manipulator": PAPER, "targets": [{"dx": 0.1}],
                                                   "q0": [3.0, 0.0, 0.0, 0.0]})     # outside |q| < pi/2
    check_error(r, 422, "invalid_parameter", "q0")


def test_batch_time_limit_marks_remaining_targets():
    with make_client(batch_timeout=0.001) as c:           # the first target alone takes longer
        targets = [{"dx": 0.05 * (i + 1)} for i in range(5)]
        r = c.post("/v1/batch/equilibrium", json={"manipulator": PAPER, "targets": targets})
        assert r.status_code == 200, r.text
        codes = [item["error"]["code"] if item["error"] else None for item in r.json()["results"]]
        assert codes[-1] == "timeout"
        assert r.json()["failed"] == codes.count("timeout") >= 1


def test_metrics_method_label_is_bounded(client):
    client.request("BREW", "/v1/equilibrium")
    assert 'method="BREW"' not in client.get("/metrics").text


@pytest.mark.parametrize("content, ctype", [
    (b'{"manipulator": {"n": 4}, "dx": 0.1}', "text/plain"),
    (b"", "application/json"),
    (b"[]", "application/json"),
    (b"[" * 100000 + b"]" * 100000, "application/json"),              # nesting too deep for the parser
    (b'{"manipulator": {"n": 4}, "dx": ' + b"1" * 5000 + b"}", "application/json"),   # integer too long
])
def test_malformed_bodies_are_422(client, content, ctype):
    r = client.post("/v1/equilibrium", content=content, headers={"content-type": ctype})
    check_error(r, 422, "validation_error", "body")


@pytest.mark.slow
def test_inline_fast_path_answers_like_the_workers():
    """Short monotonic chains are solved in the solver process; the answer equals the worker path's, and
    what the fast path does not settle (bistable segments) goes to the workers."""
    bistable = {"n": 4, "a": 0.6, "b": 1.0, "k": 1.0, "L0": 1.2}
    bodies = [{"manipulator": PAPER, "dx": 0.1}, {"manipulator": PAPER, "dx": 0.7, "dy": -0.3},
              {"manipulator": {"n": 6, "a": 0.8, "b": 1.2, "k": 2.5, "L0": 1.7}, "dx": 1.1, "dy": 0.2},
              {"manipulator": PAPER, "dx": 0.2, "dy": 0.05, "q0": [0.17, -0.07, -0.24, -0.13]},
              {"manipulator": bistable, "dx": 0.3, "dy": 0.1}]
    with make_client() as fast, make_client(inline_max_segments=0) as workers:
        assert fast.portal.call(fast.app.state.executors.fast.wait_ready, 120.0)   # else the workers solve all
        submitted = []
        pool = fast.app.state.executors.threads
        original = pool.submit

        def counting(fn, *args, **kwargs):        # kwargs: heavy=
            submitted.append(args[1][0])        # render_task(task, (chain key, dx, dy, q0, local), limit, field)
            return original(fn, *args, **kwargs)

        pool.submit = counting
        for body in bodies:
            a, b = fast.post("/v1/equilibrium", json=body), workers.post("/v1/equilibrium", json=body)
            assert a.status_code == b.status_code == 200, (a.text, b.text)
            # the fast path renders the body itself (no response-model pass): the same bytes
            assert a.content == b.content and a.headers["content-type"] == b.headers["content-type"]
        assert [key[3] for key in submitted] == [0.6]      # only the bistable chain (a = 0.6) used a worker


def test_local_equilibrium_follows_the_branch_through_q0(client):
    q0 = to.solve_equilibrium(to.Manipulator.uniform(4), 0.1).q.tolist()
    body = {"manipulator": PAPER, "dx": 0.101, "dy": 0.002, "q0": q0, "local": True}
    r = client.post("/v1/equilibrium", json=body)
    assert r.status_code == 200, r.text
    check_equilibrium(r.json(), to.solve_equilibrium(to.Manipulator.uniform(4), 0.101, 0.002, q0=q0, local=True))
    with make_client(inline_max_segments=0) as workers:              # the worker path answers the same
        assert workers.post("/v1/equilibrium", json=body).json() == r.json()
    # from a saddle the local solve stays on the saddle's branch (unstable), unlike the global search
    saddle = next(e for e in to.find_equilibria(to.Manipulator.uniform(4), 0.2) if e.kind == "saddle")
    r = client.post("/v1/equilibrium", json={"manipulator": PAPER, "dx": 0.201, "q0": saddle.q.tolist(),
                                             "local": True})
    assert r.status_code == 200 and r.json()["kind"] == "saddle" and r.json()["stable"] is False
    check_error(client.post("/v1/equilibrium", json={"manipulator": PAPER, "dx": 0.1, "local": True}),
                422, "invalid_parameter", "q0")


def test_service_maps_time_limit_to_504_with_status():
    from service.api.errors import error_body, status_for

    exc = to.TimeLimitError("stopped", status="User_Requested_Stop")
    assert status_for(exc) == 504
    body = error_body(exc)
    assert body["code"] == "timeout" and body["status"] == "User_Requested_Stop"


def test_config_docstring_lists_every_setting():
    from service import config

    documented = set(re.findall(r"``TENSEGRITY_([A-Z_]+)``", config.__doc__))
    fields = {name.upper() for name in config.Settings.model_fields}
    assert fields <= documented, f"undocumented settings: {sorted(fields - documented)}"


@pytest.mark.slow
def test_the_iterations_of_a_point_the_rootfinder_continued_are_null():
    """``iterations`` is ``None`` (JSON null) where the solver did not count them (the rootfinder's continuation
    of a chain of more than 8 segments), and the schema says so; never -1."""
    from service.schemas.common import SolverInfo

    res = to.solve_equilibria_batch(to.Manipulator.uniform(12), [(0.1 + 0.01 * i, 0.0) for i in range(4)])
    body = next(r.to_dict()["solver"] for r in res[1:] if r.solver.iterations is None)
    assert body["iterations"] is None and SolverInfo(**body).iterations is None
    assert "null: not counted" in SolverInfo.model_fields["iterations"].description
