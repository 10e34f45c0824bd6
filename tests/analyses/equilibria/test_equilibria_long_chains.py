"""Chains longer than numpy's 32 array dimensions: the analyses build their configurations row by row.

A chain of two spring constants per segment (``k = (1, 2)``) has one well per segment; a configuration built from
one critical point per segment through a ``numpy.meshgrid`` of ``n`` dimensions is refused by numpy beyond 32.
"""

from __future__ import annotations

import numpy as np
import pytest

import tensegrity_opt as to
from tensegrity_opt.analyses.equilibria.seeds import well_seeds
from tensegrity_opt.numerics.homotopy import rest_points_at

LENGTHS = [33, 64, 200]


def two_springs(n: int) -> to.Manipulator:
    return to.Manipulator.uniform(n, k=(1.0, 2.0))


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("n", LENGTHS)
def test_equilibrium_and_stiffness(n):
    m = two_springs(n)
    eq = to.solve_equilibrium(m, 0.1)
    assert eq.success and eq.stable and eq.q.shape == (n,)
    assert m.equilibrium_residual(eq.q, eq.force, m.target(0.1)) < 1e-8
    K = to.cartesian_stiffness(m, eq)
    assert np.asarray(K).shape == (2, 2) and np.all(np.isfinite(K))


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("n", LENGTHS)
def test_every_equilibrium(n):
    found = to.find_equilibria(two_springs(n), 0.1)
    assert found.success and len(found.equilibria) >= 1
    assert all(e.q.shape == (n,) for e in found.equilibria)


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("n", LENGTHS)
def test_well_seeds_and_rest_points(n):
    m = two_springs(n)
    Q = well_seeds(m, 0.1, 0.0)
    assert Q.ndim == 2 and Q.shape[1] == n
    rest = to.rest_configuration(m)
    assert rest.q.shape == (n,)
    at = rest_points_at(m, m.tip(rest.q))
    assert at.shape == (1, n) and np.allclose(at[0], rest.q)
