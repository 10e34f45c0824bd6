"""Cartesian stiffness by implicit differentiation vs central finite differences along the branch."""

import numpy as np
import pytest

from tensegrity_opt import (
    InvalidParameterError,
    Manipulator,
    Segment,
    cartesian_stiffness,
    find_equilibria,
    solve_equilibrium,
    solve_equilibrium_under_force,
)

PAPER = Manipulator.uniform(4)
NONUNIFORM = Manipulator([Segment(1.0, 1.0, 1.0, 1.0), Segment(0.9, 1.3, 2.0, 1.5),
                          Segment(1.1, 0.8, 0.7, 0.9), Segment(1.0, 1.1, 1.5, 1.2), Segment(0.7, 0.6, 1.0, 1.0)])


def fd_stiffness(m, eq, h=1e-5):
    """Central differences of the force, re-solving locally on the same branch."""
    dx0 = m.straight_length - eq.tip[0]
    dy0 = eq.tip[1]
    K = np.zeros((2, 2))
    for j, (ex, ey) in enumerate([(h, 0.0), (0.0, h)]):
        # tip x = L - dx, so moving the tip by +h in x is dx - h
        fp = solve_equilibrium(m, dx0 - ex, dy0 + ey, q0=eq.q, local=True).force
        fm = solve_equilibrium(m, dx0 + ex, dy0 - ey, q0=eq.q, local=True).force
        K[:, j] = (fp - fm) / (2 * h)
    return K


@pytest.mark.parametrize("m,dx,dy", [(PAPER, 0.3, 0.0), (PAPER, 0.5, 0.4), (PAPER, 2.0, -1.0),
                                     (NONUNIFORM, 0.4, 0.3)])
def test_stable_equilibrium_stiffness(m, dx, dy):
    eq = solve_equilibrium(m, dx, dy)
    K = cartesian_stiffness(m, eq)
    assert K.shape == (2, 2)
    assert np.allclose(K, K.T, rtol=1e-8, atol=1e-10)
    assert np.allclose(K, fd_stiffness(m, eq), rtol=1e-5, atol=1e-7)


def test_saddle_stiffness_on_its_own_branch():
    eqs = find_equilibria(PAPER, 0.2, 0.1)
    saddle = next(e for e in eqs if e.morse_index == 1)
    K = cartesian_stiffness(PAPER, saddle)
    assert np.allclose(K, fd_stiffness(PAPER, saddle), rtol=1e-5, atol=1e-7)


def test_force_controlled_equilibrium_stiffness():
    eq = solve_equilibrium_under_force(PAPER, 0.2, 0.1)
    K = cartesian_stiffness(PAPER, eq)
    assert np.allclose(K, fd_stiffness(PAPER, eq), rtol=1e-5, atol=1e-7)
    # stable under a dead load => the Cartesian stiffness is positive definite
    assert np.all(np.linalg.eigvalsh(K) > 0)


def test_straight_configuration_has_no_stiffness():
    with pytest.raises(InvalidParameterError):
        cartesian_stiffness(PAPER, solve_equilibrium(PAPER, 0.0))
