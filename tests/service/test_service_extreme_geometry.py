"""The service on extreme but valid geometry: no wrong answer labelled converged.

The chains and the check are those of the library's test (``tests/analyses/equilibria/test_extreme_geometry.py``,
``tests/support/extreme_chains.py``): every equilibrium ``POST /v1/equilibrium`` and ``/v1/batch/equilibrium``
return is an equilibrium of the independent reference model on its target; a refusal (unreachable target, no
equilibrium) is an allowed answer, anything else is not.
"""

from __future__ import annotations

import pytest

pytest.importorskip("fastapi")

from extreme_chains import chains, check_equilibrium, deflection
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from service_helpers import app_client

import tensegrity_opt as to


@pytest.fixture(scope="module")
def client():
    with app_client(inline_processes=0) as c:
        yield c


def _body(m: to.Manipulator) -> dict:
    return {"segments": [{"a": float(a), "b": float(b), "k": [float(k1), float(k2)], "L0": [float(l1), float(l2)]}
                         for a, b, k1, k2, l1, l2 in zip(m.a, m.b, m.k1, m.k2, m.L1_0, m.L2_0)]}


@pytest.mark.slow
@settings(max_examples=15, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(m=chains(n_max=6), fx=st.floats(0.0, 0.5), fy=st.floats(-0.3, 0.3))
def test_equilibrium_and_batch_on_extreme_chains(client, m, fx, fy):
    dx, dy = deflection(m, fx, fy)
    r = client.post("/v1/equilibrium", json={"manipulator": _body(m), "dx": dx, "dy": dy})
    if r.status_code == 200:
        check_equilibrium(m, r.json(), m.target(dx, dy), stable=True)
    else:
        assert r.status_code == 422 and r.json()["code"] in ("unreachable_target", "no_equilibrium",
                                                             "solver_failed", "straight_not_equilibrium"), r.text
    targets = [{"dx": dx * s, "dy": dy * s} for s in (0.5, 1.0)]
    r = client.post("/v1/batch/equilibrium", json={"manipulator": _body(m), "targets": targets})
    assert r.status_code == 200, r.text
    for item, t in zip(r.json()["results"], targets):
        if item["equilibrium"] is not None:
            check_equilibrium(m, item["equilibrium"], m.target(t["dx"], t["dy"]), stable=True)


def test_a_target_a_slender_chain_cannot_reach_is_refused(client):
    # a = 1e6: the unmoved straight chain (its tip at 8) is no answer for dx = 0.1
    r = client.post("/v1/equilibrium", json={"manipulator": {"n": 4, "a": 1e6}, "dx": 0.1})
    assert r.status_code == 422 and r.json()["code"] == "unreachable_target", r.text
