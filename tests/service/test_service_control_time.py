"""The time base and the start of a plan over HTTP and of the control stream's ``inverse`` mode.

* ``POST /v1/control/plan`` with ``times`` (or ``dt``), a rate limit per second and ``rest_lengths0`` answers the
  library's ``plan_preloads`` on the same inputs, ``times`` included;
* the stream's ``inverse`` mode: a step's ``time`` (seconds since the open) or ``dt`` (or the open's ``dt``) is
  the library controller's ``step(..., dt=)``; the open's ``rest_lengths0`` is the controller's;
* refusals name the field: a rate without a time base (``dt``), times that do not increase (``times``, ``time``),
  ``rest_lengths0`` of the wrong shape.

In process (a ``TestClient``: no solver processes, the plan in the solver threads); every plan here takes
milliseconds.
"""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("fastapi")
pytest.importorskip("httpx")

from service_helpers import app_client, body_of, check_error, post_ok, without_seconds

import tensegrity_opt as to
from tensegrity_opt.analyses.design.preload_control import PreloadController

PAPER = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}
M = to.Manipulator.uniform(4)
F = (-0.02, 0.01)
R0 = [[1.03, 0.98], [1.0, 1.02], [0.97, 1.0], [1.01, 0.99]]       # the arm's rest lengths, not the chain's own


@pytest.fixture(scope="module")
def client():
    with app_client(inline_processes=0, heavy_workers=0) as c:
        yield c


@pytest.fixture(scope="module")
def targets():
    ctl = PreloadController(M, rest_lengths0=R0, load=F)
    tip0 = ctl.manipulator().tip(ctl.q)
    return [(tip0 + np.array([-0.02, 0.05]) * k).tolist() for k in range(1, 5)]


def test_the_plan_body_is_the_library_plan_with_times_and_rest_lengths0(client, targets):
    times = [0.3, 0.45, 1.2, 1.3]
    body = {"manipulator": PAPER, "targets": targets, "loads": list(F), "times": times, "rate_limit": 0.2,
            "rest_lengths0": R0}
    got = post_ok(client, "/v1/control/plan", body)
    want = to.plan_preloads(M, targets, loads=F, times=times, rate_limit=0.2, rest_lengths0=R0)
    assert without_seconds(got) == without_seconds(body_of(want.to_dict()))
    assert got["times"] == times
    change = np.abs(np.diff(np.concatenate([[R0], got["commands"]]), axis=0)).reshape(4, -1).max(axis=1)
    assert np.all(change <= 0.2 * np.diff(times, prepend=0.0) + 1e-9)
    got = post_ok(client, "/v1/control/plan", {**{k: v for k, v in body.items() if k != "times"}, "dt": 0.25})
    want = to.plan_preloads(M, targets, loads=F, dt=0.25, rate_limit=0.2, rest_lengths0=R0)
    assert without_seconds(got) == without_seconds(body_of(want.to_dict()))
    assert got["times"] == pytest.approx([0.25, 0.5, 0.75, 1.0])


def test_plan_refusals_name_the_field(client):
    plan = {"manipulator": PAPER, "targets": [[7.9, 0.1], [7.8, 0.2]]}
    for body, code, field in [
        ({**plan, "rate_limit": 0.1}, "invalid_parameter", "dt"),
        ({**plan, "times": [0.5, 0.4]}, "invalid_parameter", "times"),
        ({**plan, "times": [0.5]}, "invalid_parameter", "times"),
        ({**plan, "times": [0.5, 1.0], "dt": 0.5}, "invalid_parameter", "times"),
        ({**plan, "times": [0.0, 1.0]}, "validation_error", "times[0]"),
        ({**plan, "dt": 0.0}, "validation_error", "dt"),
        ({**plan, "rest_lengths0": [[1.0, 1.0]] * 3}, "invalid_parameter", "rest_lengths0"),
        ({**plan, "rest_lengths0": [[1.0, 1.0, 1.0]] * 4}, "validation_error", "rest_lengths0[0]"),
        ({**plan, "rest_lengths0": [[1.0, 5.0]] * 4}, "invalid_parameter", "rest_lengths0"),     # beyond 4 b_max
    ]:
        check_error(client.post("/v1/control/plan", json=body), code, field)


def test_the_inverse_stream_takes_times_and_dts_as_the_controller_does(client, targets):
    ctl = PreloadController(M, rest_lengths0=R0, load=F, rate_limit=0.2)
    dts = [0.3, 0.15, 0.75, 0.1]
    want = [ctl.step(t, dt=h).to_dict() for t, h in zip(targets, dts)]
    assert any(w["feasible"] for w in want)
    with client.websocket_connect("/v1/control/stream") as ws:
        ws.send_json({"type": "open", "manipulator": PAPER, "mode": "inverse", "load": list(F), "rate_limit": 0.2,
                      "rest_lengths0": R0, "dt": 0.3})
        opened = ws.receive_json()
        assert opened["type"] == "opened" and opened["command"] == R0 and opened["time"] == 0.0
        steps = [{"target": targets[0]},                      # the open's dt
                 {"target": targets[1], "time": 0.45},         # 0.15 s after the last
                 {"target": targets[2], "dt": 0.75},
                 {"target": targets[3], "time": 1.3}]
        got = []
        for st in steps:
            ws.send_json({"type": "step", **st})
            got.append(ws.receive_json())
        for g, w, t in zip(got, want, [0.3, 0.45, 1.2, 1.3]):
            assert g["type"] == "result" and g["time"] == pytest.approx(t)
            assert {k: g[k] for k in w} == body_of(w)
        for msg, field in [({"target": targets[3], "time": 1.3}, "time"),        # not after the last step's
                           ({"target": targets[3], "time": 1.5, "dt": 0.2}, "dt"),
                           ({"target": targets[3], "dt": -1.0}, "dt")]:
            ws.send_json({"type": "step", **msg})
            e = ws.receive_json()
            assert e["type"] == "error" and e["field"] == field, e
    with client.websocket_connect("/v1/control/stream") as ws:          # a rate per second needs a time base
        ws.send_json({"type": "open", "manipulator": PAPER, "mode": "inverse", "rate_limit": 0.2})
        assert ws.receive_json()["type"] == "opened"
        ws.send_json({"type": "step", "target": targets[0]})
        e = ws.receive_json()
        assert (e["type"], e["code"], e["field"]) == ("error", "invalid_parameter", "dt") and "second" in e["message"]
    with client.websocket_connect("/v1/control/stream") as ws:
        ws.send_json({"type": "open", "manipulator": PAPER, "mode": "inverse", "rest_lengths0": [[1.0, 1.0]] * 3})
        e = ws.receive_json()
        assert (e["type"], e["field"]) == ("error", "rest_lengths0")
