"""Partial force-deflection curves (the stable branch ends) and the kinds of their jumps.

Expected values are independent of the library: the end of a curve and the energies and forces at its
points come from the reference model (``tests/support/reference_model.py``: its own many-start SLSQP descent and
random-start Newton search), the critical force from conventions.md's table, the joint stiffness from
the closed form ``K = k (b L0 - 2 (b^2 - a^2))``, and whether a branch survives a grid step from the
reference model's own Newton continuation of it in small steps.
"""

from __future__ import annotations

import numpy as np
import pytest
import reference_model as ref
from fastapi.testclient import TestClient

import tensegrity_opt as to
from service import schemas as s
from service.config import Settings
from service.main import create_app
from tensegrity_opt.analyses.equilibria.equilibrium import straight_equilibrium

PAPER = to.Manipulator.uniform(4)
PAPER_REF = ref.Chain.uniform(4, 1.0, 1.0, 1.0, 1.0)
FX0 = -0.572793                         # conventions.md: the guided critical force of the paper's chain
FAILING = np.linspace(0.0, 4.0, 81)     # "no stable equilibrium at dx=3.15" (the old NoEquilibriumError)


def _stable_reference_equilibria(chain: ref.Chain, dx: float, dy: float, n_starts: int = 200) -> list:
    """The stable equilibria (reduced Hessian positive definite) among every KKT point the reference
    model's random-start Newton search finds inside the physical range."""
    out = []
    for q, F in ref.all_equilibria(chain, dx, dy, n_starts=n_starts):
        w = chain.reduced_eigs(q, F, fd=False)
        if w.size == 0 or w.min() > 1e-9 * max(1.0, np.abs(w).max()):
            out.append((q, F))
    return out


def _branch_survives(chain: ref.Chain, q, F, d0: float, d1: float, dy: float = 0.0, steps: int = 200):
    """Continue the reference model's equilibrium ``(q, F)`` at ``dx = d0`` to ``d1`` by its Newton method in
    ``steps`` small steps. Returns ``(True, q, F)`` at ``d1`` when the branch stays converged, continuous,
    inside the range and stable all the way, else ``(False, dx where it was lost, None)``."""
    q, F = np.asarray(q, float), np.asarray(F, float)
    for t in np.linspace(d0, d1, steps + 1)[1:]:
        q1, F1, ok = chain.newton_kkt(chain.target(t, dy), q, F)
        if not ok or not chain.in_range(q1) or np.max(np.abs(q1 - q)) > 0.05:
            return False, t, None
        w = chain.reduced_eigs(q1, F1, fd=False)
        if w.size and w.min() <= 0.0:
            return False, t, None
        q, F = q1, F1
    return True, q, F


# ------------------------------------------------------------------------------------------ partial curves
def test_partial_curve_ends_where_the_reference_model_finds_no_stable_equilibrium():
    c = to.force_deflection(PAPER, FAILING)
    assert not c.success and c.status == "no_stable_equilibrium" and c.requested == 81 and c.dx.size == 63
    e = c.ended_at
    assert e.status == "no_stable_equilibrium" and not e.success and e.dx == FAILING[63] and e.dy == 0.0
    assert "dx = 3.15" in e.message
    assert c.message == ("The stable branch ends between dx = 3.1 and dx = 3.15 (dy = 0): no stable equilibrium at "
                      "dx = 3.15; 63 of 81 points computed.")
    np.testing.assert_array_equal(c.dx, FAILING[:63])
    for arr in (c.dy, c.fx, c.fy, c.energy, c.stable, c.morse_index, c.branch):
        assert arr.shape == (63,)
    assert c.q.shape == (63, 4) and len(c.shape) == len(c.point_status) == len(c.solver) == 63
    assert c.stable.all() and c.point_status[0] == "straight" and set(c.point_status[1:]) == {"converged"}
    assert c.solver[0].status == "straight" and {v.status for v in c.solver[1:]} == {"Newton_Converged"}
    # the last point: the reference model's many-start least-energy stable equilibrium, same energy and force
    E_ref, _, F_ref = PAPER_REF.global_min(c.dx[-1], 0.0, n_random=60)
    assert c.energy[-1] == pytest.approx(E_ref, rel=1e-9)
    np.testing.assert_allclose([c.fx[-1], c.fy[-1]], F_ref, atol=1e-7)
    # the end: neither the reference descent nor its random-start Newton search finds a stable equilibrium
    with pytest.raises(RuntimeError, match="found nothing"):
        PAPER_REF.global_min(e.dx, e.dy, n_random=60)
    assert _stable_reference_equilibria(PAPER_REF, e.dx, e.dy) == []
    # the jumps lie on the returned part: only the buckling one
    assert [j.kind for j in c.jumps] == ["buckling"]


def test_a_complete_curve_says_so():
    c = to.force_deflection(PAPER, FAILING[:63])
    assert c.success and c.status == "complete" and c.ended_at is None and c.requested == 63 == c.dx.size
    assert c.message == "all 63 requested points computed"
    d = c.to_dict()
    assert list(d)[:3] == ["success", "status", "message"] and "complete" not in d and "note" not in d
    assert d["success"] is True and d["status"] == "complete" and d["ended_at"] is None and d["requested"] == 63


def test_points_after_the_end_are_dropped():
    """The curve stops at the first point without a stable equilibrium, even when later points have one."""
    c = to.force_deflection(PAPER, [0.5, 1.0, 3.15, 1.0, 0.5])
    assert c.dx.tolist() == [0.5, 1.0] and c.requested == 5
    assert (c.ended_at.dx, c.ended_at.dy) == (3.15, 0.0)
    assert c.message.endswith("2 of 5 points computed.")


def test_a_curve_without_any_stable_point_is_empty():
    c = to.force_deflection(PAPER, [3.15, 3.2])
    assert c.dx.size == 0 and c.q.shape == (0, 4) and c.jumps == () and c.requested == 2
    assert c.ended_at.dx == 3.15
    assert c.message == ("The stable branch ends at the first point, dx = 3.15 (dy = 0): no stable equilibrium at "
                      "dx = 3.15; 0 of 2 points computed.")
    assert c.to_dict()["points"] == []


def test_partial_curve_with_every_branch_is_truncated_too():
    dxs = np.linspace(0.05, 3.3, 14)         # 3.05 has a stable equilibrium, 3.3 none (reference model above)
    c = to.force_deflection(PAPER, dxs, branch="all")
    assert not c.success and c.ended_at.dx == dxs[13] and c.dx.size == 13
    assert c.branches and all(b.dx.size == 13 and b.q.shape == (13, 4) for b in c.branches)
    d = c.to_dict()
    assert all(len(b["points"]) == 13 for b in d["branches"])


def test_partial_curve_from_the_rest_configuration_speaks_of_the_callers_deflections():
    m = to.Manipulator([to.Segment(1.0, 1.0, 1.0, (1.05, 0.95))] * 2 + [to.Segment(1.0, 1.0, 1.0, 1.0)] * 2)
    rel = np.linspace(0.0, 6.0, 61)
    c = to.force_deflection(m, rel, 0.0, reference="rest")
    assert c.reference == "rest" and np.max(np.abs(c.origin)) > 0.1
    k = c.dx.size
    assert not c.success and 0 < k < 61
    np.testing.assert_allclose(c.dx, rel[:k], atol=1e-12)
    assert c.ended_at.dx == pytest.approx(rel[k], abs=1e-12) and c.ended_at.dy == pytest.approx(0.0, abs=1e-12)
    assert f"dx = {rel[k]:g}, dy = 0:" in c.ended_at.message
    # the same end, measured from straight (the reference model: nothing stable there, something at the last point)
    ch = ref.Chain.from_segments([(1.0, 1.0, 1.0, 1.0, 1.05, 0.95)] * 2 + [(1.0, 1.0, 1.0, 1.0)] * 2)
    x, y = rel[k] + c.origin[0], c.origin[1]
    with pytest.raises(RuntimeError, match="found nothing"):
        ch.global_min(x, y, n_random=60)
    E_ref = ch.global_min(c.dx[-1] + c.origin[0], y, n_random=60)[0]
    assert c.energy[-1] == pytest.approx(E_ref, rel=1e-9)


def test_the_time_limit_still_raises():
    with to.time_limit(1e-9), pytest.raises(to.TimeLimitError):
        to.force_deflection(PAPER, np.linspace(0.05, 1.0, 20))


# ------------------------------------------------------------------------------------------ jump kinds
def test_buckling_of_the_paper_chain():
    c = to.force_deflection(PAPER, np.linspace(0.0, 1.0, 11))
    assert [j.kind for j in c.jumps] == ["buckling"]
    j = c.jumps[0]
    assert (j.dx_before, j.dx_after, j.branch_before) == (0.0, 0.1, -1)
    np.testing.assert_allclose(j.force_after, [FX0, 0.0], atol=1e-6)
    np.testing.assert_allclose(j.delta, [FX0, 0.0], atol=1e-6)
    assert j.label == "buckling of the straight chain: F_x 0 -> -0.573 (compressive)"
    d = j.to_dict()
    assert d["delta"]["fx"] == pytest.approx(FX0, abs=1e-6) and d["delta"]["fy"] == 0.0
    assert d["label"] == j.label and d["kind"] == "buckling"


def test_leaving_an_unstable_straight_chain_is_no_buckling_and_tensile():
    a, b, k, L0 = 0.5, 1.0, 1.0, 0.5
    m = to.Manipulator.uniform(4, a, b, k, L0)
    K = k * (b * L0 - 2 * (b * b - a * a))           # conventions.md: -1
    assert K == -1.0 and m.segments[0].stiffness == pytest.approx(K, abs=1e-12)
    with pytest.raises(to.UnstableStraightError):
        to.critical_force(m)
    c = to.force_deflection(m, [0.0, 0.1, 0.2])
    assert [j.kind for j in c.jumps] == ["leave_straight"]
    j = c.jumps[0]
    # the force after is the first deflected point's, from the reference model: tensile (the bent wells pull in)
    E_ref, _, F_ref = ref.Chain.uniform(4, a, b, k, L0).global_min(0.1, 0.0, n_random=40)
    assert c.energy[1] == pytest.approx(E_ref, rel=1e-9)
    np.testing.assert_allclose(j.force_after, F_ref, atol=1e-7)
    assert F_ref[0] > 0.5
    assert j.delta[0] == pytest.approx(F_ref[0], abs=1e-7)
    assert j.label.startswith("leaving the straight chain (unstable unloaded: K <= 0): F_x 0 -> ")
    assert "(tensile)" in j.label


def test_leaving_the_straight_chain_off_the_axis_is_no_buckling():
    c = to.force_deflection(PAPER, [0.0, 0.2], [0.0, 0.3])
    assert [j.kind for j in c.jumps] == ["leave_straight"]
    _, _, F_ref = PAPER_REF.global_min(0.2, 0.3, n_random=40)
    np.testing.assert_allclose(c.jumps[0].force_after, F_ref, atol=1e-7)
    assert "dy = 0.3" in c.jumps[0].label


def test_no_jump_when_the_straight_chain_is_no_equilibrium():
    m = to.Manipulator([to.Segment(a=1.0, b=1.0, k=1.0, L0=(1.0, 1.3))] * 4)
    with pytest.raises(to.StraightNotEquilibriumError):
        straight_equilibrium(m)
    c = to.force_deflection(m, [0.0, 0.1, 0.2, 0.0, 0.3])
    assert c.success and c.jumps == ()
    assert c.point_status[0] == c.point_status[3] == "straight_not_equilibrium"


def test_a_descending_grid_reports_its_jump_between_the_last_two_points():
    """The bug: dx from 2 down to 0 reported the buckling jump at dx_after = 2 (the first point) from a
    point 0 that does not precede it. It lies between dx = 0.05 and the straight point, from F_x0 to 0."""
    dxs = np.linspace(2.0, 0.0, 41)
    c = to.force_deflection(PAPER, dxs)
    assert [j.kind for j in c.jumps] == ["buckling"]
    j = c.jumps[0]
    assert (j.dx_before, j.dx_after) == (dxs[-2], 0.0) and (j.branch_before, j.branch_after) == (c.branch[-2], -1)
    np.testing.assert_allclose(j.force_before, [FX0, 0.0], atol=1e-6)
    assert np.all(j.force_after == 0.0)
    assert j.label == "return to the straight chain (buckling reversed): F_x -0.573 -> 0"
    # a curve that does not contain the straight point has no jump from it
    assert to.force_deflection(PAPER, dxs[:-1]).jumps == ()
    assert to.force_deflection(PAPER, dxs[::-1][1:]).jumps == ()


# a chain of bistable segments (K = -0.28): the least-energy branch changes once near dx = 1.3, while the old
# branch is still stable (a switch), and the stable branches end near dx = 3.8
SWITCH_CHAIN = (3, 0.6, 1.0, 1.0, 1.0)
# K = -1: the selected branch ends near dx = 2.5 (a snap)
SNAP_CHAIN = (3, 0.5, 1.0, 1.0, 0.5)
GRID = np.linspace(0.02, 5.4, 60)


def _jump_index(c: to.Curve, j: to.results.Jump) -> int:
    return int(np.flatnonzero(c.dx == j.dx_before)[0])


def test_a_snap_where_the_selected_branch_ends():
    n, a, b, k, L0 = SNAP_CHAIN
    c = to.force_deflection(to.Manipulator.uniform(n, a, b, k, L0), GRID)
    chain = ref.Chain.uniform(n, a, b, k, L0)
    inner = [j for j in c.jumps if j.kind in ("snap", "switch")]
    assert [j.kind for j in inner] == ["snap"]
    j = inner[0]
    i = _jump_index(c, j)
    assert (j.dx_before, j.dx_after) == (GRID[i], GRID[i + 1]) and j.branch_before != j.branch_after
    # the reference model's continuation of the branch before loses it inside the step ...
    ok, where, _ = _branch_survives(chain, c.q[i], [c.fx[i], c.fy[i]], j.dx_before, j.dx_after)
    assert not ok and j.dx_before < where <= j.dx_after
    # ... and the point after is its least-energy stable equilibrium
    E_ref, _, F_ref = chain.global_min(j.dx_after, 0.0, n_random=40)
    assert c.energy[i + 1] == pytest.approx(E_ref, rel=1e-9)
    np.testing.assert_allclose(j.force_after, F_ref, atol=1e-7)
    np.testing.assert_allclose(j.delta, np.array(F_ref) - [c.fx[i], c.fy[i]], atol=1e-7)
    assert j.label.startswith(f"snap to another stable branch: dF_x = {j.delta[0]:+.3g} (tensile)")


def test_a_switch_where_the_least_energy_branch_is_exchanged():
    n, a, b, k, L0 = SWITCH_CHAIN
    c = to.force_deflection(to.Manipulator.uniform(n, a, b, k, L0), GRID)
    chain = ref.Chain.uniform(n, a, b, k, L0)
    inner = [j for j in c.jumps if j.kind in ("snap", "switch")]
    assert [j.kind for j in inner] == ["switch"]
    j = inner[0]
    i = _jump_index(c, j)
    # both branches are stable over the whole step (reference continuation both ways) and exchange order
    ok, q_old, _ = _branch_survives(chain, c.q[i], [c.fx[i], c.fy[i]], j.dx_before, j.dx_after)
    assert ok and chain.energy(q_old) > c.energy[i + 1] + 1e-6
    ok, q_new, _ = _branch_survives(chain, c.q[i + 1], [c.fx[i + 1], c.fy[i + 1]], j.dx_after, j.dx_before)
    assert ok and chain.energy(q_new) > c.energy[i] + 1e-6
    for p in (i, i + 1):
        assert c.energy[p] == pytest.approx(chain.global_min(GRID[p], 0.0, n_random=40)[0], rel=1e-9)
    assert j.label.startswith("switch of the least-energy stable branch")


def test_a_descending_grid_finds_the_same_switch_reversed():
    n, a, b, k, L0 = SWITCH_CHAIN
    m = to.Manipulator.uniform(n, a, b, k, L0)
    up = to.force_deflection(m, GRID[:35])
    down = to.force_deflection(m, GRID[:35][::-1])
    assert up.success and down.success
    assert [(j.kind, j.dx_before, j.dx_after) for j in down.jumps] == \
        [(j.kind, j.dx_after, j.dx_before) for j in reversed(up.jumps)]
    for ju, jd in zip(reversed(up.jumps), down.jumps):
        np.testing.assert_allclose(jd.force_before, ju.force_after, atol=1e-9)
        np.testing.assert_allclose(jd.delta, -ju.delta, atol=1e-9)
    np.testing.assert_allclose(down.energy[::-1], up.energy, rtol=1e-10)


# ------------------------------------------------------------------------------------------ HTTP
@pytest.fixture(scope="module")
def client():
    app = create_app(Settings(warmup=False))
    with TestClient(app) as cl:
        yield cl


def test_force_deflection_answers_a_partial_curve_with_200(client):
    body = {"manipulator": {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0},
            "dx": {"start": 0.0, "stop": 4.0, "num": 81}, "dy": 0.0}
    r = client.post("/v1/force-deflection", json=body)
    assert r.status_code == 200, r.text
    got = r.json()
    s.ForceDeflectionOut.model_validate(got)
    assert got["success"] is False and got["status"] == "no_stable_equilibrium"
    assert got["requested"] == 81 and len(got["points"]) == 63
    assert got["ended_at"]["dx"] == pytest.approx(3.15) and got["ended_at"]["dy"] == 0.0
    assert got["ended_at"]["status"] == "no_stable_equilibrium" and got["ended_at"]["message"]
    assert got["ended_at"]["success"] is False
    assert got["message"].endswith("63 of 81 points computed.")
    assert got["points"][0]["status"] == "straight" and got["points"][-1]["status"] == "converged"
    assert got["points"][-1]["solver"]["status"] == "Newton_Converged"
    assert [j["kind"] for j in got["jumps"]] == ["buckling"]
    jd = got["jumps"][0]
    assert jd["delta"]["fx"] == pytest.approx(FX0, abs=1e-6) and jd["label"].startswith("buckling")
    assert got == to.force_deflection(PAPER, FAILING).to_dict()
