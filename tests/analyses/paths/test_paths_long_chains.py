"""Curves and batches of chains longer than numpy's 32 array dimensions (two spring constants per segment: one
well each: their configurations never pass through an array of n dimensions)."""

from __future__ import annotations

import pytest

import tensegrity_opt as to


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("n", [33, 64, 200])
def test_curve_and_batch(n):
    m = to.Manipulator.uniform(n, k=(1.0, 2.0))
    curve = to.force_deflection(m, [0.0, 0.05, 0.1])
    assert curve.success and len(curve.dx) == 3 and curve.q.shape == (3, n)
    batch = to.solve_equilibria_batch(m, [(0.05, 0.0), (0.1, 0.01)])
    assert len(batch) == 2 and all(r.success for r in batch)
    assert all(r.q.shape == (n,) for r in batch)
