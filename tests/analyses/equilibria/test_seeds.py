"""The starting points of the global searches (tensegrity_opt/analyses/equilibria/seeds.py)."""

import numpy as np
import pytest

from tensegrity_opt import Manipulator, Segment
from tensegrity_opt.analyses.equilibria.seeds import project_to_target, projected_sample


def _gauss_newton_row(m, q, target, iters=30):
    """One row moved onto the tip constraint by a plain loop (the library's rule written again: minimum-norm
    Gauss-Newton steps of at most 0.5 rad, the model's tip and Jacobian), or None when it fails."""
    q = np.array(q, dtype=float)
    for _ in range(iters):
        r = target - m.tip(q)
        if np.max(np.abs(r)) < 1e-11 * float(m.b.sum()):
            break
        J = m.jacobian(q)
        A = J @ J.T
        if np.linalg.det(A) <= 1e-14 * A[0, 0] * A[1, 1]:
            return None
        step = J.T @ np.linalg.solve(A, r)
        step *= min(1.0, 0.5 / max(np.max(np.abs(step)), 1e-300))
        q = q + step
        if not np.all(np.isfinite(q)):
            return None
    ok = np.max(np.abs(target - m.tip(q))) < 1e-8 * float(m.b.sum()) and m.in_range(q)
    return q if ok else None


@pytest.mark.parametrize("m, dx, dy", [
    (Manipulator.uniform(5, a=0.6, b=1.0, k=1.0, L0=1.2), 2.0, 0.7),
    (Manipulator([Segment(0.7, 1.1, (1.0, 1.4), (0.9, 1.1)), Segment(0.5, 0.9, 2.0, 0.6),
                  Segment(0.8, 1.0, 0.7, 1.3), Segment(0.6, 1.2, 1.2, 1.0)]), 1.1, -0.9),
])
def test_project_to_target_matches_a_row_by_row_gauss_newton(m, dx, dy):
    """Every row kept lies on the tip constraint inside the range and is where a row-by-row Gauss-Newton loop
    (the model's own tip and Jacobian) takes it; the rows dropped are those the loop fails on."""
    target = m.target(dx, dy)
    rng = np.random.default_rng(11)
    Q0 = rng.uniform(-0.95, 0.95, (120, m.n)) * m.joint_limits
    got = project_to_target(m, Q0, target)
    ref = [r for r in (_gauss_newton_row(m, q, target) for q in Q0) if r is not None]
    assert got.shape == (len(ref), m.n) and len(ref) > 30
    np.testing.assert_allclose(got, np.array(ref), atol=1e-9)
    for q in got:
        assert np.max(np.abs(m.tip(q) - target)) < 1e-8 * float(m.b.sum()) and m.in_range(q)


def test_projected_sample_is_reproducible():
    m = Manipulator.uniform(4, a=0.6, b=1.0, k=1.0, L0=1.2)
    target = m.target(1.5, 0.3)
    a, b = projected_sample(m, target, 200, 3), projected_sample(m, target, 200, 3)
    assert a.shape[0] > 100 and np.array_equal(a, b)
