"""HTTP service, the control endpoints: ``/v1/control/plan``, ``/v1/control/simulate``, ``/v1/control/force-estimate``
and their figures ``/v1/plots/plan``, ``/v1/plots/simulation``.

Every body is the library's ``to_dict()`` for the same input, rendered by the service's one renderer (the plan
runs in a solver process, the others in the solver threads: the same functions); the refusals are 422 with the
field named, never a 500; a trajectory longer than the server's ``max_trajectory_steps`` is 422 ``too_many_steps``;
a plan or simulation cut by the time limit answers the steps done (200, ``status: "time_limit"``).
"""

from __future__ import annotations

import json

import numpy as np
import pytest

pytest.importorskip("fastapi")
pytest.importorskip("httpx")

from clocks import tick_clock
from service_helpers import app_client, body_of, check_error, post_ok, without_seconds

import tensegrity_opt as to
from service import schemas as s
from service.config import Settings

PAPER = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}
M = to.Manipulator.uniform(4)
BISTABLE = {"n": 3, "a": 0.5, "b": 1.0, "k": 1.0, "L0": 1.0}
M3 = to.Manipulator.uniform(3, a=0.5)
#: Tips of the paper's chain bent evenly (q_i = alpha), the third one moved off the arc (beyond a rate limit 0.05).
ARC = [[7.997, 0.2], [7.986, 0.4], [7.369, 1.399], [7.945, 0.797], [7.914, 0.994]]
EQ_Q = [0.742754, 0.522806, 0.297158, 0.0953]          # the paper's chain under (-0.1, 0.05), rounded


@pytest.fixture(scope="module")
def client():
    with app_client() as c:
        yield c


# ---------------------------------------------------------------------------- bodies = the library's
@pytest.mark.slow
def test_plan_is_the_library_plan(client):
    got = post_ok(client, "/v1/control/plan", s.PLAN_REQUEST_EXAMPLE)
    ex = s.PLAN_REQUEST_EXAMPLE
    want = to.plan_preloads(M, ex["targets"], loads=ex["loads"], margin=ex["margin"])
    assert without_seconds(got) == without_seconds(body_of(want.to_dict()))
    s.PlanOut.model_validate(got)
    assert got["status"] == "complete" and all(got["verified"]) and np.allclose(got["tip"], ex["targets"], atol=1e-9)

    body = {"manipulator": PAPER, "targets": ARC, "rate_limit": 0.05, "dt": 1.0, "margin": 0.3}
    got = post_ok(client, "/v1/control/plan", body)
    want = to.plan_preloads(M, ARC, rate_limit=0.05, dt=1.0, margin=0.3)
    assert without_seconds(got) == without_seconds(body_of(want.to_dict()))
    assert got["status"] == "infeasible_steps" and got["feasible"] == [True, True, False, True, True]
    assert got["method"][2] == "none" and got["commands"][2] == got["commands"][1]     # held

    body = {"manipulator": PAPER, "targets": [[7.8, 0.3], [7.8, 0.6]], "end_angles": [0.0, None],
            "bounds": {"lo": 0.5, "hi": [2.0] * 8}, "weights": [[1.0, 2.0]] * 4, "objective": "change",
            "loads": [[0.0, 0.0], [0.0, -0.01]], "start": {"q": [0.0] * 4}, "verify": False}
    got = post_ok(client, "/v1/control/plan", body)
    want = to.plan_preloads(M, body["targets"], loads=body["loads"], end_angles=[0.0, np.nan],
                                      bounds=(0.5, np.full(8, 2.0)), weights=body["weights"], start=np.zeros(4),
                                      verify=False)
    assert without_seconds(got) == without_seconds(body_of(want.to_dict()))
    assert got["end_angle"][0] == pytest.approx(0.0, abs=1e-9)
    assert got["verified"] == [False, False] and got["feasible"] == [True, True]   # verify: false checks nothing


@pytest.mark.slow
def test_a_plan_for_a_tension_only_chain_needs_taut_on_every_interface(client):
    """`taut` has one name on the library, REST and the CLI; without it a tension-only chain is refused naming it."""
    chain = {"n": 3, "spring": "tension_only"}
    body = {"manipulator": chain, "targets": [[5.5, 0.3], [5.4, 0.6]], "taut": True}
    got = post_ok(client, "/v1/control/plan", body)
    want = to.plan_preloads(to.Manipulator.uniform(3, spring="tension_only"), body["targets"], taut=True)
    assert without_seconds(got) == without_seconds(body_of(want.to_dict())) and all(got["verified"])
    check_error(client.post("/v1/control/plan", json={**body, "taut": False}), "unsupported", "taut")


def test_a_plan_that_approaches_is_the_library_plan(client):
    """on_infeasible: approach — the step beyond the rate limit commands the nearest admissible pose's rest lengths
    (within the rate limit of the previous command) and the body says so; hold keeps the command."""
    body = {"manipulator": PAPER, "targets": ARC[:3], "rate_limit": 0.05, "dt": 1.0, "margin": 0.3,
            "on_infeasible": "approach"}
    got = post_ok(client, "/v1/control/plan", body)
    want = to.plan_preloads(M, ARC[:3], rate_limit=0.05, dt=1.0, margin=0.3, on_infeasible="approach")
    assert without_seconds(got) == without_seconds(body_of(want.to_dict()))
    s.PlanOut.model_validate(got)
    assert got["on_infeasible"] == "approach" and got["method"][2] == "nearest" and not got["feasible"][2]
    assert np.abs(np.subtract(got["commands"][2], got["commands"][1])).max() <= 0.05 + 1e-12
    assert got["steps"][2]["proposal"] == got["steps"][2]["command"] and got["verified"] == [True] * 3
    held = post_ok(client, "/v1/control/plan", {**body, "on_infeasible": "hold"})
    assert held["commands"][2] == held["commands"][1] and 0 < got["tip_error"][2] < held["tip_error"][2]
    check_error(client.post("/v1/control/plan", json={**body, "on_infeasible": "wait"}), "validation_error",
                "on_infeasible")


def test_a_horizon_plan_is_the_library_plan(client):
    """horizon: N — the body is the library's horizon plan (its steps' method horizon, the horizon echoed); the
    vocabulary and the objective it needs are checked."""
    body = {"manipulator": PAPER, "targets": ARC[:2], "rate_limit": 0.05, "dt": 1.0, "margin": 0.3, "horizon": 3,
            "on_infeasible": "approach"}
    got = post_ok(client, "/v1/control/plan", body)
    want = to.plan_preloads(M, ARC[:2], rate_limit=0.05, dt=1.0, margin=0.3, horizon=3, on_infeasible="approach")
    assert without_seconds(got) == without_seconds(body_of(want.to_dict()))
    s.PlanOut.model_validate(got)
    assert got["horizon"] == 3 and set(got["method"]) <= {"horizon", "none"}
    assert post_ok(client, "/v1/control/plan", {**body, "horizon": "all"})["horizon"] == "all"
    for bad in (0, "some", 2.5):
        check_error(client.post("/v1/control/plan", json={**body, "horizon": bad}), "validation_error", "horizon")
    check_error(client.post("/v1/control/plan", json={**body, "objective": "margin"}), "invalid_parameter",
                "objective")


@pytest.mark.slow
def test_simulation_is_the_library_simulation(client):
    got = post_ok(client, "/v1/control/simulate", s.SIMULATION_REQUEST_EXAMPLE)
    want = to.simulate(M3, loads=s.SIMULATION_REQUEST_EXAMPLE["loads"])
    assert got == body_of(want.to_dict())
    s.SimulationOut.model_validate(got)
    snaps = [e for e in got["events"] if e["kind"] == "snap"]
    assert [e["load"][1] for e in snaps] == pytest.approx([0.1531106608, -0.0977541913], abs=1e-9)   # docs/paths.md
    held = {"manipulator": PAPER, "tip": "held", "targets": [[0.1, 0.0], [0.3, 0.0], [0.5, 0.0]]}
    got = post_ok(client, "/v1/control/simulate", held)
    assert got == body_of(to.simulate(M, tip="held", targets=held["targets"]).to_dict())
    assert got["mode"] == "held" and got["targets"] == held["targets"] and "loads" not in got
    P = [[[1.0 + d, 1.0 - d], [1.0, 1.0], [1.0, 1.0]] for d in (0.0, 0.2, 0.4)]
    got = post_ok(client, "/v1/control/simulate", {"manipulator": BISTABLE, "preloads": P, "perturbation": 2e-4})
    assert got == body_of(to.simulate(M3, P, perturbation=2e-4).to_dict())


def test_simulation_of_a_tension_only_chain_is_the_library_simulation(client):
    """The spring law travels in the segment body; a start on a stop is refused naming the start."""
    chain = {"n": 3, "spring": "tension_only"}
    m = to.Manipulator.uniform(3, spring="tension_only")
    held = {"manipulator": chain, "tip": "held", "targets": [[0.8, 0.0], [1.0, 0.0], [1.2, 0.0]]}
    got = post_ok(client, "/v1/control/simulate", held)
    assert got == body_of(to.simulate(m, tip="held", targets=held["targets"]).to_dict())
    assert any("slack" in seg for seg in got["spring_states"][-1])           # spring 2.2 goes slack on the way
    bistable = {"n": 3, "a": 0.5, "b": 1.0, "k": 1.0, "L0": 0.5, "spring": "tension_only"}
    check_error(client.post("/v1/control/simulate", json={"manipulator": bistable, "loads": [[0, 0], [0, 0.1]]}),
                "unsupported", "start.q")


def test_force_estimate_is_the_library_estimate(client):
    for body, kw in [({"q_measured": EQ_Q, "sigma_q": 1e-3}, {"sigma_q": 1e-3}),
                     ({"q_measured": EQ_Q}, {}),
                     ({"q_measured": [EQ_Q[i] for i in (0, 1, 3)], "sigma_q": [1e-3, 1e-3, 2e-3],
                       "measured": [0, 1, 3]},
                      {"sigma_q": np.array([1e-3, 1e-3, 2e-3]), "measured": [0, 1, 3]}),
                     ({"q_measured": [EQ_Q[0], None, EQ_Q[2], EQ_Q[3]], "measured": [True, False, True, True],
                       "sigma_q": [[1e-6, 0, 0], [0, 1e-6, 0], [0, 0, 4e-6]]},
                      {"measured": np.array([True, False, True, True]), "sigma_q": np.diag([1e-6, 1e-6, 4e-6])})]:
        got = post_ok(client, "/v1/control/force-estimate", {"manipulator": PAPER, **body})
        q = np.array([np.nan if v is None else v for v in body["q_measured"]])
        assert got == body_of(to.estimate_tip_force(M, q, **kw).to_dict()), body
        s.ForceEstimateOut.model_validate(got)
        assert got["force"]["fx"] == pytest.approx(-0.1, abs=1e-5)
        assert got["force"]["fy"] == pytest.approx(0.05, abs=1e-5)


# ---------------------------------------------------------------------------- refusals name the field
def test_schema_refusals_name_the_field(client):
    plan = {"manipulator": PAPER, "targets": [[7.9, 0.1]]}
    sim = {"manipulator": PAPER, "loads": [[0.0, 0.0], [0.0, 0.1]]}
    est = {"manipulator": PAPER, "q_measured": EQ_Q}
    for path, body, field in [
        ("/v1/control/plan", {**plan, "targets": []}, "targets"),
        ("/v1/control/plan", {**plan, "targets": [[7.9, 0.1, 0.0]]}, "targets[0]"),
        ("/v1/control/plan", {**plan, "targets": [[7.9, 0.1]] * 2001}, "targets"),
        ("/v1/control/plan", {**plan, "loads": [1.0]}, "loads"),
        ("/v1/control/plan", {**plan, "objective": "fast"}, "objective"),
        ("/v1/control/plan", {**plan, "margin": -1.0}, "margin"),
        ("/v1/control/plan", {**plan, "rate_limit": 0.0}, "rate_limit"),
        ("/v1/control/plan", {**plan, "bounds": {"lo": 0.5}}, "bounds.hi"),
        ("/v1/control/plan", {**plan, "weights": [[1.0, -1.0]] * 4}, "weights[0][1]"),
        ("/v1/control/plan", {**plan, "manipulator": {"n": 61}}, "manipulator.n"),
        ("/v1/control/plan", {**plan, "start": {"q": [0.0] * 4, "dx": 0.1}}, "start.dx"),
        ("/v1/control/simulate", {**sim, "tip": "loose"}, "tip"),
        ("/v1/control/simulate", {**sim, "perturbation": 0.2}, "perturbation"),
        ("/v1/control/simulate", {**sim, "preloads": [[[1.0, 0.0]] * 4] * 2}, "preloads[0][0][1]"),
        ("/v1/control/simulate", {**sim, "loads": [[0.0, float("inf")]]}, None),
        ("/v1/control/force-estimate", {**est, "sigma_q": -1.0}, "sigma_q"),
        ("/v1/control/force-estimate", {**est, "sigma_q": [1e-3, 0.0]}, "sigma_q[1]"),
        ("/v1/control/force-estimate", {**est, "measured": [1.5]}, "measured[0]"),
        ("/v1/control/force-estimate", {**est, "q_measured": []}, "q_measured"),
        ("/v1/plots/plan", {**plan, "format": "gif"}, "format"),
        ("/v1/plots/simulation", {**sim, "dpi": 1000}, "dpi"),
    ]:
        if field is None:                            # not JSON: refused as a body error
            r = client.post(path, content=json.dumps(body), headers={"content-type": "application/json"})
            assert r.status_code == 422 and r.json()["code"] == "validation_error", r.text
            continue
        check_error(client.post(path, json=body), "validation_error", field)


@pytest.mark.slow
def test_domain_refusals_name_the_field(client):
    plan = {"manipulator": PAPER, "targets": [[7.9, 0.1]]}
    sim = {"manipulator": PAPER, "loads": [[0.0, 0.0], [0.0, 0.1]]}
    est = {"manipulator": PAPER, "q_measured": [0.1, 0.2, 0.3, 0.4]}
    for path, body, code, field in [
        ("/v1/control/plan", {**plan, "bounds": {"lo": 2.0, "hi": 1.0}}, "invalid_parameter", "bounds"),
        ("/v1/control/plan", {**plan, "bounds": {"lo": [0.5] * 3, "hi": 2.0}}, "invalid_parameter", "bounds"),
        ("/v1/control/plan", {**plan, "weights": [[1.0, 1.0]]}, "invalid_parameter", "weights"),
        ("/v1/control/plan", {**plan, "rate_limit": [0.1] * 3, "dt": 1.0}, "invalid_parameter", "rate_limit"),
        ("/v1/control/plan", {**plan, "end_angles": [0.0, 0.0]}, "invalid_parameter", "end_angles"),
        ("/v1/control/plan", {**plan, "loads": [[0.0, 0.0]] * 2}, "invalid_parameter", "loads"),
        ("/v1/control/plan", {**plan, "manipulator": {"n": 1}}, "invalid_parameter", "manipulator.n"),
        ("/v1/control/plan", {**plan, "start": {"q": [0.0, 0.0]}}, "invalid_parameter", "start.q"),
        ("/v1/control/plan", {**plan, "start": {"q": [3.0, 0.0, 0.0, 0.0]}}, "invalid_parameter", "start.q"),
        ("/v1/plots/plan", {**plan, "weights": [[1.0, 1.0]]}, "invalid_parameter", "weights"),
        ("/v1/control/simulate", {"manipulator": PAPER}, "invalid_parameter", "loads"),
        ("/v1/control/simulate", {"manipulator": PAPER, "tip": "held"}, "invalid_parameter", "targets"),
        ("/v1/control/simulate", {**sim, "preloads": [[[1.0, 1.0]] * 4]}, "invalid_parameter", "loads"),
        ("/v1/control/simulate", {**sim, "preloads": [[[1.0, 1.0]] * 3] * 2}, "invalid_parameter", "preloads"),
        ("/v1/control/simulate", {**sim, "targets": [[0.1, 0.0]] * 2}, "invalid_parameter", "targets"),
        ("/v1/control/simulate", {"manipulator": PAPER, "tip": "held", "targets": [[0.1, 0.0], [100.0, 0.0]]},
         "unreachable_target", "targets"),
        ("/v1/control/simulate", {**sim, "manipulator": {"n": 65}}, "invalid_parameter", "manipulator.n"),
        ("/v1/control/simulate", {**sim, "start": {"q": [0.3, 0.0, 0.0, 0.0]}}, "invalid_parameter", "start.q"),
        ("/v1/plots/simulation", {**sim, "start": {"q": [3.0, 0.0, 0.0, 0.0]}}, "invalid_parameter", "start.q"),
        ("/v1/control/force-estimate", {**est, "q_measured": [0.0] * 4}, "invalid_parameter", "q_measured"),
        ("/v1/control/force-estimate", {**est, "q_measured": [3.0, 0.0, 0.0, 0.0]}, "invalid_parameter",
         "q_measured"),
        ("/v1/control/force-estimate", {**est, "sigma_q": [[1e-6, 0.0], [0.0, 1e-6]]}, "invalid_parameter",
         "sigma_q"),
        ("/v1/control/force-estimate", {**est, "sigma_q": [[1e-6, 0, 0, 0]] * 4}, "invalid_parameter", "sigma_q"),
        ("/v1/control/force-estimate", {**est, "measured": [9]}, "invalid_parameter", "measured"),
        ("/v1/control/force-estimate", {**est, "measured": [True]}, "invalid_parameter", "measured"),
        ("/v1/control/force-estimate", {**est, "measured": []}, "invalid_parameter", "measured"),
        ("/v1/control/force-estimate", {"manipulator": {"n": 1}, "q_measured": [0.1]}, "invalid_parameter",
         "manipulator.n"),
    ]:
        check_error(client.post(path, json=body), code, field)


@pytest.mark.slow
def test_odd_inputs_are_answers_not_server_errors(client):
    X = {"n": 4, "a": 1e-6, "b": 1e6}
    Y = {"n": 4, "a": 1e6, "b": 1e-6, "k": 1e9}
    for path, body in [
        ("/v1/control/plan", {"manipulator": PAPER, "targets": [[0.0, 0.0]]}),
        ("/v1/control/plan", {"manipulator": PAPER, "targets": [[-8.0, 0.0]]}),
        ("/v1/control/plan", {"manipulator": PAPER, "targets": [[7.9, 0.1]], "margin": 1e9}),
        ("/v1/control/plan", {"manipulator": PAPER, "targets": [[7.9, 0.1]], "loads": [0.0, 1e6]}),
        ("/v1/control/plan", {"manipulator": X, "targets": [[2e6, 1.0]]}),
        ("/v1/control/plan", {"manipulator": Y, "targets": [[8e-6, 1e-7]]}),
        ("/v1/control/plan", {"manipulator": PAPER, "targets": [[7.9, 0.1]], "objective": "energy",
                              "end_angles": [6.0]}),
        ("/v1/control/simulate", {"manipulator": PAPER, "loads": [[0.0, 0.0]]}),
        ("/v1/control/simulate", {"manipulator": PAPER, "loads": [[1e12, 0.0], [0.0, 1e12]]}),
        ("/v1/control/simulate", {"manipulator": PAPER, "tip": "held", "targets": [[0.0, 0.0], [0.0, 0.0]]}),
        ("/v1/control/simulate", {"manipulator": {"n": 1}, "loads": [[0.0, 0.0], [0.0, 0.1]]}),
        ("/v1/control/simulate", {"manipulator": X, "loads": [[0.0, 0.0], [0.0, 1e-6]]}),
        ("/v1/control/simulate", {"manipulator": Y, "loads": [[0.0, 0.0], [0.0, 1e3]]}),
        ("/v1/control/force-estimate", {"manipulator": X, "q_measured": [0.1, 0.2, 0.3, 0.4], "sigma_q": 1e-3}),
        ("/v1/control/force-estimate", {"manipulator": Y, "q_measured": [1e-6] * 4, "sigma_q": 6.0}),
        ("/v1/control/force-estimate", {"manipulator": PAPER, "q_measured": [1.5, -1.5, 1.5, -1.5], "sigma_q": 6.0}),
        ("/v1/control/force-estimate", {"manipulator": PAPER, "q_measured": [0.1, 1.5, 0.3], "measured": [0, 1, 3],
                                        "sigma_q": 1e-3}),
    ]:
        r = client.post(path, json=body)
        assert r.status_code in (200, 422), (path, body, r.status_code, r.text)
        if r.status_code == 200:
            {"/v1/control/plan": s.PlanOut, "/v1/control/simulate": s.SimulationOut,
             "/v1/control/force-estimate": s.ForceEstimateOut}[path].model_validate(r.json())


# ---------------------------------------------------------------------------- limits
@pytest.mark.slow
def test_the_step_bound_and_the_response_size():
    assert Settings().max_trajectory_steps == 2000
    # a one-step plan's body is ~3.2 kB (its spring state, per step and per plan, since issue 40), thirty steps ~80 kB
    with app_client(max_trajectory_steps=30, max_response_bytes=4096) as c:
        assert c.get("/version").json()["limits"]["max_trajectory_steps"] == 30
        many = [[8.0 - 0.001 * i, 0.01 * i] for i in range(31)]
        b = check_error(c.post("/v1/control/plan", json={"manipulator": PAPER, "targets": many}), "too_many_steps",
                        "targets")
        assert b["details"] == {"steps": 31, "max_trajectory_steps": 30}
        check_error(c.post("/v1/control/plan", json={"manipulator": PAPER, "targets": many[:30],
                                                     "loads": [[0.0, 0.0]] * 31}), "too_many_steps", "loads")
        check_error(c.post("/v1/control/plan", json={"manipulator": PAPER, "targets": many[:30],
                                                     "end_angles": [None] * 31}), "too_many_steps", "end_angles")
        check_error(c.post("/v1/plots/plan", json={"manipulator": PAPER, "targets": many}), "too_many_steps", "targets")
        loads = [[0.0, 0.01 * i] for i in range(31)]
        check_error(c.post("/v1/control/simulate", json={"manipulator": PAPER, "loads": loads}), "too_many_steps",
                    "loads")
        check_error(c.post("/v1/control/simulate", json={"manipulator": PAPER, "preloads": [[[1.0, 1.0]] * 4] * 31}),
                    "too_many_steps", "preloads")
        check_error(c.post("/v1/plots/simulation", json={"manipulator": PAPER, "tip": "held",
                                                         "targets": [[0.1, 0.0]] * 31}), "too_many_steps", "targets")
        # within the bound: the answer is rendered in the solver process, within the response size
        r = c.post("/v1/control/plan", json={"manipulator": PAPER, "targets": many[:1]})
        assert r.status_code == 200 and len(r.json()["method"]) == 1
        check_error(c.post("/v1/control/plan", json={"manipulator": PAPER, "targets": many[:30]}),
                    "response_too_large", "targets")
        check_error(c.post("/v1/control/simulate", json=s.SIMULATION_REQUEST_EXAMPLE), "response_too_large", "loads")


@pytest.mark.slow
def test_a_time_limited_plan_answers_partial(monkeypatch):
    """A plan (a simulation) longer than the time limit allows: 200 with the steps done and status time_limit, not
    504. The library's clock moves on 1 s at every reading (tests/support/clocks.py), about once a plan step and
    four times a simulation step: the soft deadline (270 s of the 300 s limit) runs out some 250 plan steps and
    some 70 simulation steps in, of 2000, on any machine."""
    M_ = to.Manipulator.uniform(4)
    arc = [M_.tip(np.full(4, a)).tolist() for a in np.linspace(0.0, 0.3, 2000)]
    fy = np.concatenate([np.linspace(0, 0.3, 500), np.linspace(0.3, -0.3, 1000)[1:], np.linspace(-0.3, 0, 500)[1:]])
    # heavy_workers = 0: the plan in the solver threads of this process, which reads the clock of the stand-in
    tick_clock(monkeypatch, step=1.0)
    with app_client(heavy_workers=0) as c:
        got = post_ok(c, "/v1/control/plan", {"manipulator": PAPER, "targets": arc})
        assert got["status"] == "time_limit" and got["success"] is False and 1 <= len(got["method"]) < 2000
        assert len(got["commands"]) == len(got["targets"]) == len(got["feasible"])
        s.PlanOut.model_validate(got)
        got = post_ok(c, "/v1/control/simulate", {"manipulator": BISTABLE,
                                                  "loads": np.column_stack([0 * fy, fy]).tolist()})
        assert got["status"] == "time_limit" and got["success"] is False and 1 <= got["done"] < got["steps"] == 1998
        s.SimulationOut.model_validate(got)


# ---------------------------------------------------------------------------- figures, documentation
@pytest.mark.slow
@pytest.mark.parametrize("path,body", [
    ("/v1/plots/plan", {"manipulator": PAPER, "targets": ARC, "rate_limit": 0.05, "dt": 1.0, "margin": 0.3,
                        "dpi": 40}),
    ("/v1/plots/simulation", {**s.SIMULATION_REQUEST_EXAMPLE, "dpi": 40}),
])
def test_control_figures_answer_png_and_svg(client, path, body):
    r = client.post(path, json=body)
    assert r.status_code == 200 and r.headers["content-type"] == "image/png" and r.content[:4] == b"\x89PNG", r.text
    r = client.post(path, json={**body, "format": "svg"})
    assert r.status_code == 200 and r.headers["content-type"] == "image/svg+xml" and b"<svg" in r.content[:500]


@pytest.mark.slow
def test_the_new_operations_are_documented(client):
    doc = client.get("/openapi.json").json()
    for path in ("/v1/control/plan", "/v1/control/simulate", "/v1/control/force-estimate"):
        op = doc["paths"][path]["post"]
        assert op["tags"] == ["control"] and op["requestBody"]["content"]["application/json"]["examples"]
        assert op["responses"]["200"]["content"]["application/json"]["example"]
    for path in ("/v1/control/plan", "/v1/control/simulate"):
        assert "too_many_steps" in doc["paths"][path]["post"]["responses"]["422"]["content"]["application/json"][
            "examples"]
    for kind in ("plan", "simulation"):
        assert doc["paths"][f"/v1/plots/{kind}"]["post"]["tags"] == ["plots"]
    # every request example of the control operations is answered 200
    for path in ("/v1/control/plan", "/v1/control/simulate", "/v1/control/force-estimate"):
        for name, ex in doc["paths"][path]["post"]["requestBody"]["content"]["application/json"]["examples"].items():
            assert client.post(path, json=ex["value"]).status_code == 200, (path, name)


@pytest.mark.slow
def test_the_plan_process_carries_large_calls_and_replies_on_uvloop():
    """``tensegrity-opt serve`` runs on uvloop, whose ``add_reader`` makes the solver process's pipe non-blocking: a
    plan of many targets (the call) or its figure (the reply) over the socket buffer once failed half-way
    (``BlockingIOError``: 503 ``overloaded``). Both ways, 3 MB."""
    uvloop = pytest.importorskip("uvloop")
    from service.execution import ProcessExecutor

    async def main():
        lane = ProcessExecutor(1, queue_size=2)
        lane.start()
        try:
            assert len(await lane.run(bytes, 3_000_000, timeout=60)) == 3_000_000
            assert await lane.run(len, b"x" * 3_000_000, timeout=60) == 3_000_000
        finally:
            lane.shutdown()

    uvloop.run(main())


# ---------------------------------------------------------------------------- stiffness shaping, load capacity
@pytest.mark.slow
def test_stiffness_and_load_capacity_are_the_library_calls(client):
    body = {"manipulator": PAPER, "target": [7.0, 1.0], "eig_bounds": [0.04, 0.6]}
    got = post_ok(client, "/v1/control/stiffness", body)
    want = to.preloads_for_stiffness(M, (7.0, 1.0), eig_bounds=(0.04, 0.6))
    np.testing.assert_allclose(got["rest_lengths"], want.rest_lengths, atol=1e-9)
    np.testing.assert_allclose(got["K"], want.K, atol=1e-9)
    assert min(got["eigenvalues"]) >= 0.04 - 1e-6 and max(got["eigenvalues"]) <= 0.6 + 1e-6
    assert got["active_bounds"] == [b.to_dict() for b in want.active_bounds]
    got = post_ok(client, "/v1/control/load-capacity", {"manipulator": PAPER, "directions": 4, "max_load": 2.0})
    # the straight chain compressed along -x buckles at the free critical load; the other directions have no limit
    assert got["kinds"] == ["none", "none", "bifurcation", "none"]
    assert got["loads"][2] == pytest.approx(abs(to.critical_force(M, "free").force), rel=1e-9)


@pytest.mark.slow
def test_stiffness_and_load_capacity_refusals_name_the_field(client):
    r = client.post("/v1/control/stiffness", json={"manipulator": PAPER, "target": [7.0, 1.0],
                                                   "bounds_K": {"kxx": [None, 0.1], "kyy": [0.08, None]}})
    assert r.status_code == 422 and r.json()["code"] == "design_infeasible"
    r = client.post("/v1/control/stiffness", json={"manipulator": PAPER, "target": [7.0, 1.0], "eig_bounds": [1.0]})
    assert r.status_code == 422 and r.json()["errors"][0]["field"] == "eig_bounds"
    r = client.post("/v1/control/load-capacity", json={"manipulator": PAPER, "start": {"q": [3.0, 0.0, 0.0, 0.0]}})
    assert r.status_code == 422 and r.json()["field"] == "start.q"
    r = client.post("/v1/control/load-capacity", json={"manipulator": PAPER, "directions": 0})
    assert r.status_code == 422 and r.json()["errors"][0]["field"] == "directions"


def test_the_stiffness_body_names_the_rest_lengths_at_their_bounds(client):
    """The design of the paper's chain at (7.5, 1) puts three rest lengths on their upper bound 4 and one near its
    lower bound 0.1: the body says which (0-based segment, variable, side, value, bound)."""
    got = post_ok(client, "/v1/control/stiffness", {"manipulator": PAPER, "target": [7.5, 1.0],
                                                      "eig_bounds": [0.05, 0.5]})
    sides = {(b["segment"], b["variable"], b["side"]) for b in got["active_bounds"]}
    assert (3, "L1_0", "lower") in sides and (1, "L1_0", "upper") in sides
    low = next(b for b in got["active_bounds"] if b["side"] == "lower")
    assert low["bound"] == pytest.approx(0.1) and 0.1 <= low["value"] < 0.11
