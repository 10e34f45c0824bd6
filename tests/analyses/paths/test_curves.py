"""Force-deflection curves (``analyses/paths/curves.py``, Fig. 6): the stable branch, every branch, the jumps and
their kinds, partial curves (the stable branch ends), curves measured from the rest configuration.

Expected values are independent of the library: the paper's numbers (``docs/model.md``), the end of a curve and the
energies and forces at its points from the reference model (``tests/support/reference_model.py``: its own many-start
SLSQP descent and random-start Newton search), the joint stiffness from the closed form
``K = k (b L0 - 2 (b^2 - a^2))``, and whether a branch survives a grid step from the reference model's own Newton
continuation of it in small steps.
"""

from __future__ import annotations

import numpy as np
import pytest
import reference_model as ref
import reference_tension_only as ref_closed
from reference_paths import rest_configuration as ref_rest

import tensegrity_opt as to
from tensegrity_opt import InvalidParameterError, Manipulator, UnreachableTargetError, force_deflection
from tensegrity_opt.analyses.equilibria.equilibrium import straight_equilibrium
from tensegrity_opt.model.segment import Segment

PAPER = Manipulator.uniform(4)
FX0 = -0.572793               # docs/model.md: the guided critical force of the paper's chain
MODE1_FY_COEFF = 0.075044 / np.sqrt(0.868000)     # eq. 26 from the mode (alpha_5, mu_x)


def test_fig6_stable_branch():
    dx = np.linspace(0.0, 2.0, 41)
    c = force_deflection(PAPER, dx)
    assert c.fx[0] == 0.0 and c.fy[0] == 0.0 and c.shape[0] == "I"
    assert c.stable.all()
    assert set(c.shape[1:]) == {"U"}
    # quasi-linear Fx starting at the critical force
    assert c.fx[1] == pytest.approx(FX0, abs=2e-3)
    slope = np.polyfit(c.dx[1:], c.fx[1:], 1)
    resid = c.fx[1:] - np.polyval(slope, c.dx[1:])
    assert np.abs(resid).max() < 0.01 * abs(FX0)
    # Fy follows sqrt(dx): eq. 26 coefficient as dx -> 0
    ratio = np.abs(c.fy[1:]) / np.sqrt(c.dx[1:])
    assert ratio[0] == pytest.approx(MODE1_FY_COEFF, rel=1e-2)
    # one branch throughout, so the only jump is the buckling one at dx -> 0+
    assert len(c.jumps) == 1
    j = c.jumps[0]
    assert j.kind == "buckling" and j.dx_before == 0.0
    assert np.allclose(j.force_before, 0) and j.force_after[0] == pytest.approx(FX0, rel=1e-5)


def test_fy_coefficient_limit():
    dx = np.array([1e-6, 4e-6, 1e-5])
    c = force_deflection(PAPER, dx)
    assert np.allclose(np.abs(c.fy) / np.sqrt(dx), MODE1_FY_COEFF, rtol=1e-3)
    assert np.allclose(c.fx, FX0, rtol=1e-4)


def test_points_match_pointwise_global_solves():
    from tensegrity_opt import solve_equilibrium
    dx = np.linspace(0.05, 1.0, 8)
    c = force_deflection(PAPER, dx, 0.2)
    for i, d in enumerate(dx):
        e = solve_equilibrium(PAPER, d, 0.2)
        assert c.energy[i] == pytest.approx(e.energy, rel=1e-10)
        assert c.fx[i] == pytest.approx(e.fx, rel=1e-7)


def test_all_branches():
    dx = np.linspace(1e-4, 0.5, 11)
    c = force_deflection(PAPER, dx, branch="all")
    assert len(c.branches) == 6
    first = sorted(b.fx[0] for b in c.branches)
    assert np.allclose(first, np.repeat([-1.921444, -1.362906, -0.572793], 2), rtol=1e-3)
    for b in c.branches:
        ok = np.isfinite(b.fx)
        assert ok[0]
        assert len(set(b.morse_index[ok])) == 1          # each branch keeps its stability here


def test_switch_to_the_mirror_branch_is_reported():
    """Sweeping dy from one side to the other: the selected U branch has to flip to its mirror."""
    dy = np.linspace(-0.6, 0.6, 25)
    c = force_deflection(PAPER, np.full(dy.size, 0.3), dy)
    assert c.stable.all()
    assert [j.kind for j in c.jumps] == ["switch"]     # the first U stays stable past dy = 0: an exchange
    j = c.jumps[0]
    # the mirror images tie at dy = 0; past it the other U is lower: switch between dy = 0 and 0.05
    assert j.dy_before == pytest.approx(0.0, abs=1e-12) and j.dy_after == pytest.approx(0.05)
    assert np.sign(j.force_before[1]) != np.sign(j.force_after[1])
    i = int(np.argmin(np.abs(dy - 0.05)))
    assert np.sign(c.q[i, 0]) != np.sign(c.q[0, 0])
    # the selected point is the least-energy stable one everywhere (independent global solves)
    from tensegrity_opt import solve_equilibrium
    for k in (0, 6, 12, 18, 24):
        assert c.energy[k] == pytest.approx(solve_equilibrium(PAPER, 0.3, dy[k]).energy, rel=1e-10)


def test_errors():
    with pytest.raises(InvalidParameterError) as ei:
        force_deflection(PAPER, [0.1], branch="unstable")
    assert ei.value.field == "branch"
    with pytest.raises(UnreachableTargetError):
        force_deflection(PAPER, [0.1, -0.2])
    with pytest.raises(InvalidParameterError):
        force_deflection(PAPER, [])
    with pytest.raises(InvalidParameterError):
        force_deflection(PAPER, [0.1, 0.2], dy=[0.0, 0.1, 0.2])


def test_jump_when_the_straight_chain_is_unstable():
    """K < 0 (condition (4) fails): no critical load exists, but leaving the straight chain is still a
    force discontinuity, from 0 to the force on the first deflected point: not a buckling."""
    m = Manipulator.uniform(4, a=0.5, b=1.5, k=1.0, L0=1.0)
    assert m.stiffness[0] < 0
    c = force_deflection(m, np.linspace(0.0, 1.0, 5))
    assert len(c.jumps) == 1 and c.jumps[0].kind == "leave_straight"
    assert np.allclose(c.jumps[0].force_after, [c.fx[1], c.fy[1]])
    assert abs(c.fx[1]) > 1.0


def test_every_return_to_straight_is_a_jump():
    """Leaving the straight chain and coming back to it are both the buckling discontinuity, each between
    the two consecutive points where it happens (the return from F_x0 back to 0)."""
    c = force_deflection(PAPER, [0.0, 0.5, 0.0, 0.6])
    kinds = [(j.kind, j.dx_before, j.dx_after) for j in c.jumps]
    assert kinds == [("buckling", 0.0, 0.5), ("buckling", 0.5, 0.0), ("buckling", 0.0, 0.6)]
    back = c.jumps[1]
    assert back.force_before[0] == pytest.approx(FX0, rel=1e-5) and np.all(back.force_after == 0.0)
    assert (back.branch_before, back.branch_after) == (c.branch[1], -1)


# -------------------------------------------------------------------------------- partial curves and jump kinds
PRE_BENT = to.Manipulator([Segment(1.0, 1.0, 1.0, (1.05, 0.95))] * 2 + [Segment(1.0, 1.0, 1.0, 1.0)] * 2)
PAPER_REF = ref.Chain.uniform(4, 1.0, 1.0, 1.0, 1.0)
#: Past dx ~ 3.12 joint 3 rests on its stop (the open range has no stable equilibrium from dx = 3.15 on); from dx = 6
#: on the target is out of the closed range's reach (only the rigid fold with every joint on a stop meets dx = 6).
FAILING = np.linspace(0.0, 6.2, 63)


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
@pytest.mark.slow
def test_partial_curve_ends_where_the_reference_model_finds_no_stable_equilibrium():
    c = to.force_deflection(PAPER, FAILING)
    assert not c.success and c.status == "no_stable_equilibrium" and c.requested == 63 and c.dx.size == 60
    e = c.ended_at
    assert e.status == "no_stable_equilibrium" and not e.success and e.dx == FAILING[60] and e.dy == 0.0
    assert "dx = 6" in e.message
    assert c.message == ("The stable branch ends between dx = 5.9 and dx = 6 (dy = 0): no stable equilibrium at "
                      "dx = 6; 60 of 63 points computed.")
    np.testing.assert_array_equal(c.dx, FAILING[:60])
    for arr in (c.dy, c.fx, c.fy, c.energy, c.stable, c.morse_index, c.branch):
        assert arr.shape == (60,)
    assert c.q.shape == (60, 4) and len(c.shape) == len(c.point_status) == len(c.solver) == 60
    assert c.stable.all() and c.point_status[0] == "straight" and set(c.point_status[1:]) == {"converged"}
    assert c.solver[0].status == "straight"
    # inside the open range (dx <= 3.1): the reference model's many-start least-energy stable equilibrium
    k = int(np.flatnonzero(np.isclose(c.dx, 3.1))[0])
    E_ref, _, F_ref = PAPER_REF.global_min(c.dx[k], 0.0, n_random=60)
    assert c.energy[k] == pytest.approx(E_ref, rel=1e-9)
    np.testing.assert_allclose([c.fx[k], c.fy[k]], F_ref, atol=1e-7)
    # from dx = 3.15 the open range has none (the reference's descent and Newton search), and the curve goes on with
    # joint 3 on its stop: the closed range's brute-force least energy, up to the last point
    with pytest.raises(RuntimeError, match="found nothing"):
        PAPER_REF.global_min(3.15, 0.0, n_random=60)
    assert _stable_reference_equilibria(PAPER_REF, 3.15, 0.0) == []
    segs = ref_closed.segs_of(PAPER)
    for j in (k + 1, c.dx.size - 1):
        assert np.abs(c.q[j]).max() == pytest.approx(PAPER.joint_limits.max(), abs=1e-9)
        assert c.energy[j] == pytest.approx(ref_closed.least_energy(segs, c.dx[j], 0.0).energy, rel=1e-9)
    # the jumps lie on the returned part: only the buckling one (the arm reaches the stop continuously)
    assert [j.kind for j in c.jumps] == ["buckling"]


def test_a_complete_curve_says_so():
    c = to.force_deflection(PAPER, FAILING[:32])
    assert c.success and c.status == "complete" and c.ended_at is None and c.requested == 32 == c.dx.size
    assert c.message == "all 32 requested points computed"
    d = c.to_dict()
    assert list(d)[:3] == ["success", "status", "message"] and "complete" not in d and "note" not in d
    assert d["success"] is True and d["status"] == "complete" and d["ended_at"] is None and d["requested"] == 32


def test_points_after_the_end_are_dropped():
    """The curve stops at the first point without a stable equilibrium, even when later points have one (7.9: outside
    the workspace of the closed joint range; past dx ~ 3.12 the arm rests on joint 3's stop, and the curve goes on)."""
    c = to.force_deflection(PAPER, [0.5, 1.0, 7.9, 1.0, 0.5])
    assert c.dx.tolist() == [0.5, 1.0] and c.requested == 5
    assert (c.ended_at.dx, c.ended_at.dy) == (7.9, 0.0)
    assert c.message.endswith("2 of 5 points computed.")


@pytest.mark.slow
def test_a_curve_without_any_stable_point_is_empty():
    c = to.force_deflection(PAPER, [7.9, 7.95])
    assert c.dx.size == 0 and c.q.shape == (0, 4) and c.jumps == () and c.requested == 2
    assert c.ended_at.dx == 7.9
    assert c.message == ("The stable branch ends at the first point, dx = 7.9 (dy = 0): no stable equilibrium at "
                      "dx = 7.9; 0 of 2 points computed.")
    assert c.to_dict()["points"] == []


def test_partial_curve_with_every_branch_is_truncated_too():
    dxs = np.linspace(0.05, 3.3, 14)         # 3.05 has a stable equilibrium, 3.3 none (reference model above)
    c = to.force_deflection(PAPER, dxs, branch="all")
    assert not c.success and c.ended_at.dx == dxs[13] and c.dx.size == 13
    assert c.branches and all(b.dx.size == 13 and b.q.shape == (13, 4) for b in c.branches)
    d = c.to_dict()
    assert all(len(b["points"]) == 13 for b in d["branches"])


@pytest.mark.slow
def test_partial_curve_from_the_rest_configuration_speaks_of_the_callers_deflections():
    m = to.Manipulator([to.Segment(1.0, 1.0, 1.0, (1.05, 0.95))] * 2 + [to.Segment(1.0, 1.0, 1.0, 1.0)] * 2)
    rel = np.linspace(0.0, 13.0, 131)           # the closed range's reach ends between 11.7 and 11.8
    c = to.force_deflection(m, rel, 0.0, reference="rest")
    assert c.reference == "rest" and np.max(np.abs(c.origin)) > 0.1
    k = c.dx.size
    assert not c.success and 0 < k < 131
    np.testing.assert_allclose(c.dx, rel[:k], atol=1e-12)
    assert c.ended_at.dx == pytest.approx(rel[k], abs=1e-12) and c.ended_at.dy == pytest.approx(0.0, abs=1e-12)
    assert f"dx = {rel[k]:g}, dy = 0:" in c.ended_at.message
    # the same end, measured from straight (the reference model: nothing stable there, something at the last point)
    ch = ref.Chain.from_segments([(1.0, 1.0, 1.0, 1.0, 1.05, 0.95)] * 2 + [(1.0, 1.0, 1.0, 1.0)] * 2)
    x, y = rel[k] + c.origin[0], c.origin[1]
    with pytest.raises(RuntimeError, match="found nothing"):
        ch.global_min(x, y, n_random=60)
    E_ref = ref_closed.least_energy(ref_closed.segs_of(m), c.dx[-1] + c.origin[0], y).energy   # on its stops
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


@pytest.mark.slow
def test_leaving_an_unstable_straight_chain_is_no_buckling_and_tensile():
    a, b, k, L0 = 0.5, 1.0, 1.0, 0.5
    m = to.Manipulator.uniform(4, a, b, k, L0)
    K = k * (b * L0 - 2 * (b * b - a * a))           # docs/model.md: -1
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


@pytest.mark.slow
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


# a chain of bistable segments (K = -0.28): the least-energy branch changes once near dx = 1.3, while the first
# branch is still stable (a switch), and the stable branches end near dx = 3.8
SWITCH_CHAIN = (3, 0.6, 1.0, 1.0, 1.0)
# K = -1: the selected branch ends near dx = 2.5 (a snap)
SNAP_CHAIN = (3, 0.5, 1.0, 1.0, 0.5)
GRID = np.linspace(0.02, 5.4, 60)


def _the_inner_jump(params, kind: str):
    """The curve of the uniform chain ``params`` over ``GRID``, the reference chain, its one jump between two
    stable branches (of ``kind``) and the index of the point before it."""
    n, a, b, k, L0 = params
    c = to.force_deflection(to.Manipulator.uniform(n, a, b, k, L0), GRID)
    inner = [j for j in c.jumps if j.kind in ("snap", "switch")]
    assert [j.kind for j in inner] == [kind]
    return c, ref.Chain.uniform(n, a, b, k, L0), inner[0], int(np.flatnonzero(c.dx == inner[0].dx_before)[0])


def test_a_snap_where_the_selected_branch_ends():
    c, chain, j, i = _the_inner_jump(SNAP_CHAIN, "snap")
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


@pytest.mark.slow
def test_a_switch_where_the_least_energy_branch_is_exchanged():
    c, chain, j, i = _the_inner_jump(SWITCH_CHAIN, "switch")
    # both branches are stable over the whole step (reference continuation both ways) and exchange order
    ok, q_before, _ = _branch_survives(chain, c.q[i], [c.fx[i], c.fy[i]], j.dx_before, j.dx_after)
    assert ok and chain.energy(q_before) > c.energy[i + 1] + 1e-6
    ok, q_after, _ = _branch_survives(chain, c.q[i + 1], [c.fx[i + 1], c.fy[i + 1]], j.dx_after, j.dx_before)
    assert ok and chain.energy(q_after) > c.energy[i] + 1e-6
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


# -------------------------------------------------- measured from the rest configuration (reference="rest")
@pytest.mark.slow
def test_curve_from_rest_of_pre_bent_heterogeneous_chain():
    m = to.Manipulator([Segment(0.9, 1.0, 1.2, (1.08, 0.96)), Segment(1.1, 0.8, 0.9, (0.97, 1.01)),
                        Segment(1.0, 1.1, 1.0, 1.0)])
    ch = ref.Chain.from_segments([(s.a, s.b, s.k1, s.k2, s.L1_0, s.L2_0) for s in m.segments])
    q_rest = ref_rest(ch)                       # the unloaded joint minima near 0 (separable energy)
    tip_rest = ch.tip(q_rest)
    c = to.force_deflection(m, np.linspace(0.0, 0.24, 3), 0.03, reference="rest")
    assert c.reference == "rest"
    np.testing.assert_allclose(c.origin, [m.straight_length - tip_rest[0], tip_rest[1]], atol=1e-10)
    assert np.max(np.abs(c.origin)) > 0.05     # really pre-bent: the rest tip is off the straight one
    for i in range(c.dx.size):
        target = tip_rest + np.array([-c.dx[i], c.dy[i]])
        np.testing.assert_allclose(ch.tip(c.q[i]), target, atol=1e-9)
        # the reference model's many-start least-energy held-tip equilibrium at the same target
        E_ref, q_ref, F_ref = ch.global_min(c.dx[i] + c.origin[0], c.dy[i] + c.origin[1], n_random=40)
        assert c.energy[i] == pytest.approx(E_ref, rel=1e-9, abs=1e-10)
        np.testing.assert_allclose([c.fx[i], c.fy[i]], F_ref, atol=1e-7)
    d = c.to_dict()
    assert d["reference"] == "rest" and d["points"][0]["dx"] == pytest.approx(0.0)


def test_curve_from_rest_is_zero_force_at_rest_and_straight_for_symmetric_chain():
    c = to.force_deflection(PRE_BENT, [0.0, 0.05], 0.0, reference="rest")
    assert abs(c.fx[0]) < 1e-10 and abs(c.fy[0]) < 1e-10
    sym = to.Manipulator.uniform(4)
    a = to.force_deflection(sym, [0.0, 0.1], reference="rest")
    b = to.force_deflection(sym, [0.0, 0.1])
    np.testing.assert_array_equal(a.origin, [0.0, 0.0])
    np.testing.assert_allclose(a.fx, b.fx, atol=1e-14)
    with pytest.raises(to.InvalidParameterError) as e:
        to.force_deflection(sym, [0.1], reference="bent")
    assert e.value.field == "reference"


# ---------------------------------------------------------------------------- the first point is the least-energy one
#: a mixed chain (bistable and monotonic segments, L1_0 = L2_0 and k1 = k2 per segment) as (a, b, k, L0), and the
#: first point of its curve (a line of dx at constant dy, as `tensegrity-opt curve` and `/v1/force-deflection` draw)
MIXED = [(0.8051575, 1.3535103, 2.2901407, 1.4806089), (0.5435207, 1.3909166, 1.4299473, 2.2654741),
         (0.5031050, 1.1143596, 1.6877755, 1.7085544), (0.8356613, 0.6158667, 2.4110712, 0.4628743),
         (1.0735836, 1.0579341, 1.4235177, 0.2253548), (0.5138389, 0.6912436, 2.7236217, 0.5262346)]
MIXED_FIRST = (0.1244766, 0.5201387)


def test_the_first_point_is_the_least_energy_stable_equilibrium():
    """Newton from the global seeds and the wells finds a stable point 1.5e-2 above the least-energy one here; the
    curve starts at :func:`solve_equilibrium`'s (the same search) and stays on the least-energy branch."""
    m = Manipulator([Segment(*s) for s in MIXED])
    dx, dy = MIXED_FIRST
    c = force_deflection(m, np.linspace(dx, 0.3, 3), dy)
    for j in range(2):
        best = to.solve_equilibrium(m, c.dx[j], dy)
        assert c.stable[j] and abs(c.energy[j] - best.energy) <= 1e-9 * abs(best.energy)
    # the independent check of that energy: the reference model's multistart below (slow)
    assert not [j for j in c.jumps if j.dx_before < 0.3]          # no exchange of minima at the start


@pytest.mark.slow
def test_no_lower_stable_point_at_the_first_point_by_brute_force():
    """The reference model's SLSQP descent from 1000 random starts (plus 60 near straight) inside the range
    finds no stable point below the curve's first one."""
    dx, dy = MIXED_FIRST
    c = force_deflection(Manipulator([Segment(*s) for s in MIXED]), [dx], dy)
    e_ref, _, _ = ref.Chain.from_segments(MIXED).global_min(dx, dy, n_random=1000, seed=7)
    assert c.energy[0] <= e_ref + 1e-9 * abs(e_ref)


def _family(rng, family: str, n: int) -> list[tuple]:
    """Random segments (a, b, k1, k2, L1_0, L2_0) of one family."""
    segs = []
    for _ in range(n):
        a, b = rng.uniform(0.5, 1.3), rng.uniform(0.6, 1.3)
        k = rng.uniform(0.5, 3.0)
        K0 = 2.0 * (b * b - a * a)                       # K = k (b L0 - K0) for symmetric springs
        if family == "bistable":
            L0 = max(0.05, (K0 - rng.uniform(0.1, 0.6)) / b) if K0 > 0.2 else None
            if L0 is None:
                a, L0 = 0.5 * b, max(0.05, (2.0 * 0.75 * b * b - 0.3) / b)
            segs.append((a, b, k, k, L0, L0))
        elif family == "asymmetric":
            L0 = (K0 + rng.uniform(0.3, 1.5)) / b
            segs.append((a, b, k * rng.uniform(0.7, 1.3), k, L0 * rng.uniform(0.85, 1.15), L0))
        else:                                            # heterogeneous monotonic
            segs.append((a, b, k, k, (K0 + rng.uniform(0.2, 2.0)) / b, (K0 + rng.uniform(0.2, 2.0)) / b))
    if family == "heterogeneous":
        segs = [(a, b, k1, k1, L0, L0) for a, b, k1, _, L0, _ in segs]
    return segs


@pytest.mark.slow
@pytest.mark.parametrize("family, n, seed", [("bistable", 4, 1), ("bistable", 5, 2), ("heterogeneous", 4, 3),
                                             ("asymmetric", 4, 4), ("asymmetric", 5, 5), ("heterogeneous", 6, 6)])
def test_the_first_point_against_a_multistart_on_random_chains(family, n, seed):
    """Random chains of other families, the first point off the axis (dy != 0): the curve's first point is
    :func:`solve_equilibrium`'s energy, stable, and no stable point of the reference model's multistart lies
    below it."""
    rng = np.random.default_rng(1000 + seed)
    segs = _family(rng, family, n)
    m = Manipulator([Segment(a, b, (k1, k2), (L1, L2)) for a, b, k1, k2, L1, L2 in segs])
    dx, dy = float(rng.uniform(0.1, 0.8)), float(rng.choice([-1.0, 1.0]) * rng.uniform(0.1, 0.6))
    c = force_deflection(m, np.linspace(dx, dx + 0.2, 3), dy)
    best = to.solve_equilibrium(m, dx, dy)
    assert c.stable[0] and abs(c.energy[0] - best.energy) <= 1e-9 * max(1.0, abs(best.energy))
    e_ref, _, _ = ref.Chain.from_segments(segs).global_min(dx, dy, n_random=300, seed=seed)
    assert c.energy[0] <= e_ref + 1e-9 * max(1.0, abs(e_ref))
