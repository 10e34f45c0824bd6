"""Every equilibrium: counts, classification (Table 2), branch-force limits."""

import numpy as np
import pytest

from tensegrity_opt import Manipulator, Segment, critical_force, find_equilibria, solve_equilibrium

PAPER = Manipulator.uniform(4)
LOADS = [0.572793, 1.362906, 1.921444]      # docs/model.md


@pytest.mark.parametrize("dx", [1e-3, 0.05, 0.3])
def test_paper_chain_has_six_equilibria(dx):
    eqs = find_equilibria(PAPER, dx)
    assert len(eqs) == 6
    assert [e.shape for e in eqs] == ["U", "U", "ZU", "ZU", "Z", "Z"]
    assert [e.morse_index for e in eqs] == [0, 0, 1, 1, 2, 2]
    assert [e.kind for e in eqs] == ["minimum"] * 2 + ["saddle"] * 2 + ["maximum"] * 2
    assert [e.stable for e in eqs] == [True, True, False, False, False, False]
    energies = np.array([e.energy for e in eqs])
    assert np.all(np.diff(energies) >= -1e-12)
    # mirror pairs: q and -q, same energy
    for a, b in zip(eqs[::2], eqs[1::2]):
        assert np.allclose(a.q, -b.q, atol=1e-8) and a.energy == pytest.approx(b.energy, rel=1e-12)
    # Table 2 sign patterns (both cases)
    signs = {e.signs for e in eqs}
    assert signs == {"-+++", "+---", "-+-+", "+-+-", "-+--", "+-++"}
    # every equilibrium satisfies eq. 6 with its force and holds the tip on target
    for e in eqs:
        assert np.allclose(PAPER.gradient(e.q), PAPER.jacobian(e.q).T @ e.force, atol=1e-9)
        assert np.allclose(e.tip, PAPER.target(dx, 0), atol=1e-9)
        assert PAPER.in_range(e.q)


def test_least_energy_stable_one_is_solve_equilibrium():
    eqs = find_equilibria(PAPER, 0.2)
    best = solve_equilibrium(PAPER, 0.2)
    assert np.allclose(eqs[0].q, best.q, atol=1e-8)


@pytest.mark.parametrize("dx", [1e-6, 1e-5])
def test_branch_forces_tend_to_critical_loads(dx):
    """docs/model.md: on branch m the force as dx -> 0+ tends to the m-th critical load."""
    eqs = find_equilibria(PAPER, dx)
    for j, P in enumerate(LOADS):
        for e in eqs[2 * j:2 * j + 2]:
            assert e.fx == pytest.approx(-P, rel=1e-4)
            assert e.morse_index == j          # branch m has Morse index m - 1


@pytest.mark.parametrize("n", [2, 3, 5, 6])
def test_uniform_chain_has_2_n_minus_1_equilibria_near_straight(n):
    m = Manipulator.uniform(n, a=0.9, b=1.1, k=1.3, L0=1.6)
    eqs = find_equilibria(m, 1e-5)
    assert len(eqs) == 2 * (n - 1)
    loads = critical_force(m).loads
    fx = np.array([e.fx for e in eqs])
    assert np.allclose(np.sort(-fx), np.repeat(loads, 2), rtol=1e-3)
    assert sorted(e.morse_index for e in eqs) == sorted(list(range(n - 1)) * 2)


def test_nonuniform_chain_branch_limits():
    m = Manipulator([Segment(1.0, 1.0, 1.0, 1.0), Segment(0.9, 1.3, 2.0, 1.5),
                     Segment(1.1, 0.8, 0.7, 0.9), Segment(1.0, 1.1, 1.5, 1.2)])
    eqs = find_equilibria(m, 1e-6)
    loads = critical_force(m).loads
    assert len(eqs) == 6
    assert np.allclose(np.sort([-e.fx for e in eqs]), np.repeat(loads, 2), rtol=1e-4)


def test_with_lateral_deflection_breaks_the_mirror_symmetry():
    eqs = find_equilibria(PAPER, 0.2, 0.3)
    assert len({round(e.energy, 8) for e in eqs}) == len(eqs)      # no ties any more
    assert sum(e.stable for e in eqs) >= 1
    assert np.allclose(eqs[0].q, solve_equilibrium(PAPER, 0.2, 0.3).q, atol=1e-8) or not eqs[0].stable


def test_straight_target():
    eqs = find_equilibria(PAPER, 0.0)
    assert len(eqs) == 1 and eqs[0].shape == "I"
