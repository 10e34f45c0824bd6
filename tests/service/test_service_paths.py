"""HTTP service, the loading-path endpoints: rest configurations, branches, bifurcation diagrams, limit loads,
stability boundaries and their figures.

Every body is the library's ``to_dict()`` for the same input, rendered by the service's one renderer (the
service calls the same functions in a solver thread); the refusals are 422 with the field named, never a
500.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

pytest.importorskip("fastapi")
pytest.importorskip("httpx")

from clocks import tick_clock
from service_helpers import app_client, body_of, check_error, post_ok

import tensegrity_opt as to
from service import schemas as s

PAPER = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}
M = to.Manipulator.uniform(4, 1.0, 1.0, 1.0, 1.0)
STRAIGHT = {"q": [0.0, 0.0, 0.0, 0.0]}
GUIDED = {"kind": "guided", "direction": [-1.0, 0.0]}
GUIDED_LOADS = (0.572793, 1.362906, 1.921444)           # docs/model.md
PRE_BENT = {"segments": [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": [1.0, 1.02]}] + [{"a": 1.0, "b": 1.0, "k": 1.0,
                                                                                  "L0": 1.0}] * 3}
M_PRE_BENT = to.Manipulator.from_dict(PRE_BENT)


@pytest.fixture(scope="module")
def client():
    with app_client() as c:
        yield c


# ---------------------------------------------------------------------------- bodies = the library's
def test_branch_of_the_paper_chain_guided_has_the_critical_loads_as_branch_points(client):
    got = post_ok(client, "/v1/branch", {"manipulator": PAPER, "start": STRAIGHT, "control": GUIDED, "t_max": 2.0})
    want = to.trace_branch(M, np.zeros(4), to.Control.guided((-1.0, 0.0)), t_max=2.0)
    assert got == body_of(want.to_dict())
    s.TracedBranchOut.model_validate(got)
    bps = [e for e in got["events"] if e["kind"] == "branch_point"]
    assert [e["t"] for e in bps] == pytest.approx(GUIDED_LOADS, abs=1e-6)
    assert bps[0]["stability"] == "lost" and got["status"] == "t_max" and got["success"] is True


def test_branch_from_a_deflection_under_a_displacement_control(client):
    body = {"manipulator": PAPER, "start": {"dx": 0.1, "dy": 0.0},
            "control": {"kind": "displacement", "direction": [1.0, 0.0]}, "t_max": 0.4, "max_points": 50}
    got = post_ok(client, "/v1/branch", body)
    want = to.trace_branch(M, to.solve_equilibrium(M, 0.1, 0.0), to.Control.displacement((1.0, 0.0)), t_max=0.4,
                           max_points=50)
    assert got == body_of(want.to_dict())
    assert got["deflection"][0] == pytest.approx([0.1, 0.0], abs=1e-12)


def test_branch_under_a_preload_and_backwards_to_the_first_event(client):
    d = [1.0, -1.0] + [0.0] * 6
    body = {"manipulator": PAPER, "start": STRAIGHT, "control": {"kind": "preload", "direction": d},
            "t_max": 0.2, "max_points": 40}
    got = post_ok(client, "/v1/branch", body)
    want = to.trace_branch(M, np.zeros(4), to.Control.preload(d), t_max=0.2, max_points=40)
    assert got == body_of(want.to_dict()) and len(got["rest_lengths"]) == got["points"]
    s.TracedBranchOut.model_validate(got)
    body = {"manipulator": PAPER, "start": STRAIGHT, "control": {"kind": "load", "direction": [1.0, 0.0]},
            "orientation": -1, "stop_at": "event", "max_points": 300}
    got = post_ok(client, "/v1/branch", body)
    want = to.trace_branch(M, np.zeros(4), to.Control.load((1.0, 0.0)), orientation=-1, stop_at="event",
                           max_points=300)
    assert got == body_of(want.to_dict())
    assert got["status"] == "event" and got["events"][0]["t"] == pytest.approx(-0.0761205, rel=1e-5)


def test_bifurcation_diagram_is_the_library_diagram(client):
    body = {"manipulator": PAPER, "start": STRAIGHT, "control": GUIDED, "t_max": 2.0, "t_min": -0.2, "depth": 1,
            "max_points": 150}
    got = post_ok(client, "/v1/bifurcation-diagram", body)
    want = to.bifurcation_diagram(M, np.zeros(4), to.Control.guided((-1.0, 0.0)), depth=1, t_max=2.0, t_min=-0.2,
                                  max_points=150)
    assert got == body_of({"branches": [b.to_dict() for b in want]})
    s.BifurcationDiagramOut.model_validate(got)
    assert len(got["branches"]) == len(want) > 2


def test_limit_load_bodies(client):
    got = post_ok(client, "/v1/limit-load", {"manipulator": PAPER, "boundary": "guided", "start": STRAIGHT})
    want = to.limit_load(M, (-1.0, 0.0), "guided", start=np.zeros(4))
    assert got == body_of(want.to_dict())
    assert got["kind"] == "bifurcation" and got["load"] == pytest.approx(GUIDED_LOADS[0], abs=1e-6)
    s.LimitLoadOut.model_validate(got)
    q0 = to.solve_equilibrium_under_force(M_PRE_BENT, 0.0, 0.0).q
    got = post_ok(client, "/v1/limit-load", {"manipulator": PRE_BENT, "max_load": 0.2, "start": {"q": q0.tolist()},
                                             "include_branch": True})
    want = to.limit_load(M_PRE_BENT, (-1.0, 0.0), "free", 0.2, q0)
    assert got == body_of(want.to_dict(include_branch=True))
    assert got["kind"] == "none" and got["load"] is None and got["quasi_buckling_load"] is not None
    assert 0.0 < got["quasi_buckling_stiffness"] == pytest.approx(want.quasi_buckling_stiffness)
    s.LimitLoadOut.model_validate(got)


def test_rest_configurations_and_the_rest_start(client):
    from tensegrity_opt.analyses.equilibria.rest import find_equilibria_under_force

    got = post_ok(client, "/v1/rest-configurations", {"manipulator": PAPER})
    assert got == body_of(find_equilibria_under_force(M).to_dict())
    assert [e["q"] for e in got["equilibria"]] == [[0.0, 0.0, 0.0, 0.0]]
    assert (got["success"], got["status"], got["method"]) == (True, "exact", "exact")
    assert got["equilibria"][0]["status"] == "exact"
    s.EquilibriaOut.model_validate(got)
    got = post_ok(client, "/v1/rest-configurations", {"manipulator": PAPER, "fx": -0.3, "stable_only": True})
    assert got == body_of(find_equilibria_under_force(M, -0.3, 0.0, stable_only=True).to_dict())
    got = post_ok(client, "/v1/branch", {"manipulator": PAPER, "start": None, "control": GUIDED, "t_max": 1.0})
    assert got == body_of(to.trace_branch(M, None, to.Control.guided((-1.0, 0.0)), t_max=1.0).to_dict())
    got = post_ok(client, "/v1/limit-load", {"manipulator": PAPER, "boundary": "guided"})
    assert got == body_of(to.limit_load(M, (-1.0, 0.0), "guided").to_dict())


def test_stability_boundary_is_the_library_boundary(client):
    from tensegrity_opt.analyses.paths.boundaries import stability_boundary

    body = {"manipulator": PAPER, "control": GUIDED, "parameter": "asymmetry", "p_min": -0.02, "p_max": 0.02,
            "max_points": 60}
    got = post_ok(client, "/v1/stability-boundary", body)
    want = stability_boundary(M, "guided", "asymmetry", p_min=-0.02, p_max=0.02, max_points=60,
                              direction=[-1.0, 0.0], base=[0.0, 0.0])
    assert got == body_of(want.to_dict())
    s.StabilityBoundaryOut.model_validate(got)
    r = client.post("/v1/plots/boundary", json={**body, "format": "svg"})
    assert r.status_code == 200 and r.headers["content-type"] == "image/svg+xml"





# ---------------------------------------------------------------------------- refusals: 422, the field named
def _raw(client, path, text):
    return client.post(path, content=text, headers={"content-type": "application/json"})


def test_schema_refusals_name_the_field(client):
    base = {"manipulator": PAPER, "start": STRAIGHT, "control": GUIDED}
    check_error(_raw(client, "/v1/branch", json.dumps(base)[:-1] + ', "t_max": NaN}'), "validation_error", "t_max")
    check_error(_raw(client, "/v1/limit-load", '{"manipulator": {"n": 4}, "direction": [NaN, 0]}'),
                "validation_error", "direction[0]")
    for path, extra, field in [
        ("/v1/branch", {"max_points": 10 ** 9}, "max_points"),
        ("/v1/branch", {"max_points": 1}, "max_points"),
        ("/v1/branch", {"control": {"kind": "guided", "direction": [-1.0, 0.0, 0.0]}}, "control.direction"),
        ("/v1/branch", {"control": {"kind": "twist"}}, "control"),
        ("/v1/branch", {"control": {"kind": "load", "normal": [0.0, 1.0]}}, "control.normal"),
        ("/v1/branch", {"start": {"q": [0.0] * 4, "dx": 0.1}}, "start.dx"),
        ("/v1/branch", {"direction": 0}, "direction"),
        ("/v1/bifurcation-diagram", {"depth": 99}, "depth"),
        ("/v1/limit-load", {"direction": [1.0]}, "direction"),
        ("/v1/limit-load", {"max_load": -1.0}, "max_load"),
        ("/v1/rest-configurations", {"method": "magic"}, "method"),
        ("/v1/stability-boundary", {"parameter": "a b"}, "parameter"),
        ("/v1/plots/branch", {"x": "speed"}, "x"),
    ]:
        body = {**base, **extra}
        if path in ("/v1/limit-load", "/v1/rest-configurations", "/v1/stability-boundary"):
            body = {"manipulator": PAPER, **extra}
        if path == "/v1/bifurcation-diagram":
            body = {**base, **extra}
        check_error(client.post(path, json=body), "validation_error", field)


@pytest.mark.slow
def test_domain_refusals_name_the_field(client):
    base = {"manipulator": PAPER, "start": STRAIGHT, "control": GUIDED}
    long = {"manipulator": {"n": 100}, "start": {"q": [0.0] * 100}, "control": GUIDED}
    for path, body, code, field in [
        ("/v1/branch", long, "invalid_parameter", "manipulator.n"),
        ("/v1/bifurcation-diagram", long, "invalid_parameter", "manipulator.n"),
        ("/v1/limit-load", {"manipulator": {"n": 65}, "start": {"q": [0.0] * 65}}, "invalid_parameter",
         "manipulator.n"),
        ("/v1/plots/branch", long, "invalid_parameter", "manipulator.n"),
        ("/v1/branch", {**base, "start": {"q": [2.0, 0.0, 0.0, 0.0]}}, "invalid_parameter", "start.q"),
        ("/v1/branch", {**base, "start": {"q": [0.0, 0.0, 0.0]}}, "invalid_parameter", "start.q"),
        ("/v1/limit-load", {"manipulator": PAPER, "start": {"q": [0.0, 0.0, 0.0, 3.0]}}, "invalid_parameter",
         "start.q"),
        ("/v1/limit-load", {"manipulator": PAPER, "start": {"q": [0.3, 0.0, 0.0, 0.0]}}, "invalid_parameter",
         "start"),
        ("/v1/branch", {**base, "start": {"dx": 0.1}}, "invalid_parameter", "start"),
        ("/v1/branch", {**base, "start": {"dx": 50.0}, "control": {"kind": "displacement"}}, "unreachable_target",
         "start.dx"),
        ("/v1/branch", {**base, "control": {"kind": "guided", "direction": [0.0, 1.0]}}, "invalid_parameter",
         "control.direction"),
        ("/v1/branch", {**base, "control": {"kind": "load", "direction": [0.0, 0.0]}}, "invalid_parameter",
         "control.direction"),
        ("/v1/branch", {**base, "control": {"kind": "load", "direction": [1e-300, 0.0]}}, "invalid_parameter",
         "control.direction"),
        ("/v1/branch", {**base, "control": {"kind": "wall", "normal": [1.0, 0.0], "direction": [1.0, 0.0]}},
         "invalid_parameter", "control.direction"),
        ("/v1/branch", {**base, "control": {"kind": "preload", "direction": [1.0, 0.0]}}, "invalid_parameter",
         "control.direction"),
        ("/v1/branch", {**base, "control": {"kind": "preload", "direction": [0.0] * 8}}, "invalid_parameter",
         "control.direction"),
        ("/v1/plots/branch", {**base, "depth": 1, "stop_at": "event"}, "invalid_parameter", "stop_at"),
        ("/v1/plots/branch", {**base, "y": "q9"}, "invalid_parameter", "y"),
    ]:
        check_error(client.post(path, json=body), code, field)


@pytest.mark.slow
def test_odd_inputs_are_answers_not_server_errors(client):
    base = {"manipulator": PAPER, "start": STRAIGHT, "control": GUIDED, "max_points": 60}
    for extra in [{"t_max": 0.0}, {"t_max": -1.0}, {"t_min": 1.0, "t_max": 0.5}, {"orientation": -1},
                  {"control": {"kind": "load", "base": [1e12, -1e12]}}, {"t_max": 1e12},
                  {"control": {"kind": "wall", "normal": [1e12, 1.0]}},
                  {"manipulator": {"n": 1}, "start": {"q": [0.0]}},
                  {"manipulator": {"n": 4, "a": 1e-6, "b": 1e6}},
                  {"manipulator": {"n": 4, "a": 0.5, "L0": 0.2}, "start": {"q": [0.5, 0.5, 0.5, 0.5]}}]:
        r = client.post("/v1/branch", json={**base, **extra})
        assert r.status_code in (200, 422), (extra, r.status_code, r.text)
        if r.status_code == 200:
            s.TracedBranchOut.model_validate(r.json())
    for body in [{"manipulator": PAPER, "direction": [1.0, 0.0], "start": STRAIGHT, "max_points": 60},
                 {"manipulator": PAPER, "direction": [0.0, 1.0], "boundary": "guided", "start": STRAIGHT},
                 {"manipulator": PAPER, "max_load": 1e-9, "start": STRAIGHT}]:
        r = client.post("/v1/limit-load", json=body)
        assert r.status_code in (200, 422), (body, r.text)


@pytest.mark.slow
def test_the_server_limits(client):
    limits = client.get("/version").json()["limits"]
    assert limits["max_path_points"] == 5000
    with app_client(max_path_points=100) as c:
        b = check_error(c.post("/v1/branch", json={"manipulator": PAPER, "start": STRAIGHT, "control": GUIDED,
                                                   "max_points": 101}), "too_many_points", "max_points")
        assert b["details"] == {"max_points": 101, "max_path_points": 100}
        check_error(c.post("/v1/plots/limit-load", json={"manipulator": PAPER}), "too_many_points", "max_points")
        assert c.get("/version").json()["limits"]["max_path_points"] == 100
    with app_client(max_response_bytes=4096) as c:
        check_error(c.post("/v1/branch", json={"manipulator": PAPER, "start": STRAIGHT, "control": GUIDED,
                                               "t_max": 2.0}), "response_too_large", "max_points")


@pytest.mark.slow
def test_the_time_limit_answers_the_points_so_far(monkeypatch):
    """A branch longer than the time limit allows: 200 with the points computed and status time_limit, not 504.
    The library's clock moves on 1 s at every reading, once a point (tests/support/clocks.py): the soft deadline
    (270 s of the 300 s limit) runs out some 270 points in, of 5000, on any machine."""
    tick_clock(monkeypatch, step=1.0)
    with app_client() as c:
        body = {"manipulator": {"n": 20}, "start": {"q": [0.0] * 20}, "control": GUIDED, "max_points": 5000}
        got = post_ok(c, "/v1/branch", body)
        assert got["status"] == "time_limit" and got["success"] is False and 2 <= got["points"] < 5000
        s.TracedBranchOut.model_validate(got)
        got = post_ok(c, "/v1/bifurcation-diagram", {**body, "depth": 3, "max_points": 5000})
        assert any(b["status"] == "time_limit" for b in got["branches"])


# ---------------------------------------------------------------------------- figures
@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("path,body", [
    ("/v1/plots/branch", {"manipulator": PAPER, "start": STRAIGHT, "control": GUIDED, "t_max": 2.0, "y": "fy"}),
    ("/v1/plots/branch", {"manipulator": PAPER, "start": STRAIGHT, "control": GUIDED, "t_max": 2.0, "depth": 1,
                          "max_points": 100, "x": "q1", "y": "t"}),
    ("/v1/plots/limit-load", {"manipulator": PAPER, "boundary": "guided", "start": STRAIGHT}),
    ("/v1/plots/imperfection", {"manipulator": {"n": 2, "a": 1.5}, "amplitudes": [0.0, 3e-4, 1e-3, 3e-3]}),
])
def test_path_figures_answer_png_and_svg(client, path, body):
    r = client.post(path, json=body)
    assert r.status_code == 200 and r.headers["content-type"] == "image/png" and r.content[:4] == b"\x89PNG"
    r = client.post(path, json={**body, "format": "svg"})
    assert r.status_code == 200 and r.headers["content-type"] == "image/svg+xml" and b"<svg" in r.content[:500]


def test_the_new_operations_are_documented(client):
    doc = client.get("/openapi.json").json()
    for path in ("/v1/rest-configurations", "/v1/branch", "/v1/bifurcation-diagram", "/v1/limit-load",
                 "/v1/imperfection-sensitivity", "/v1/stability-boundary"):
        op = doc["paths"][path]["post"]
        assert op["tags"] == ["paths"] and op["requestBody"]["content"]["application/json"]["examples"]
        assert op["responses"]["200"]["content"]["application/json"]["example"]
    for kind in ("branch", "limit-load", "imperfection", "boundary"):
        assert doc["paths"][f"/v1/plots/{kind}"]["post"]["tags"] == ["plots"]


def test_imperfection_sensitivity_is_the_library_curve(client):
    """The paper chain guided at the two amplitudes of the stability boundary's comparison: the folds of the
    imperfect arms (0.52743, 0.42470), not the fixed-guide fold curve (0.615908, 0.6424)."""
    body = {"manipulator": PAPER, "amplitudes": [0.0, 0.02851, 0.061]}
    got = post_ok(client, "/v1/imperfection-sensitivity", body)
    want = to.imperfection_sensitivity(M, [0.0, 0.02851, 0.061])
    assert got == body_of(want.to_dict())
    s.ImperfectionSensitivityOut.model_validate(got)
    assert got["kinds"] == ["bifurcation", "fold", "fold"] and got["bifurcation"] == "stable_symmetric"
    assert got["loads"] == pytest.approx([GUIDED_LOADS[0], 0.52743, 0.42470], abs=1e-5)
    got = post_ok(client, "/v1/imperfection-sensitivity", {**body, "boundary": "free", "max_load": 0.2,
                                                             "include_limit_loads": True})
    want = to.imperfection_sensitivity(M, [0.0, 0.02851, 0.061], boundary="free", max_load=0.2)
    assert got == body_of(want.to_dict(include_limit_loads=True))
    assert got["loads"][1:] == [None, None] and got["kinds"][1:] == ["none", "none"]
    s.ImperfectionSensitivityOut.model_validate(got)
    for extra, field in (({"amplitudes": []}, "amplitudes"), ({"amplitudes": [0.1] * 65}, "amplitudes"),
                         ({"imperfection": "bend"}, "imperfection"), ({"boundary": "wall"}, "boundary")):
        check_error(client.post("/v1/imperfection-sensitivity", json={**body, **extra}), "validation_error", field)
    r = client.post("/v1/imperfection-sensitivity", json={**body, "amplitudes": [2.0]})
    assert check_error(r, "invalid_parameter", "amplitudes")
