"""Force-deflection curves (Fig. 6) and their jumps."""

import numpy as np
import pytest

from tensegrity_opt import InvalidParameterError, Manipulator, UnreachableTargetError, force_deflection

PAPER = Manipulator.uniform(4)
FX0 = -0.572793               # conventions.md
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
    assert [j.kind for j in c.jumps] == ["switch"]     # the old U stays stable past dy = 0: an exchange
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
