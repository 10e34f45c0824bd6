"""Trajectories of targets in one call."""

import numpy as np
import pytest

import tensegrity_opt as to

PAPER = to.Manipulator.uniform(4)


def trajectory(num=200):
    s = np.linspace(0.0, 1.0, num)
    return np.column_stack([0.3 + 0.5 * s, 0.8 * np.sin(6 * s)])


def test_continuation_follows_the_branch_point_by_point():
    tr = trajectory()
    res = to.solve_equilibria_batch(PAPER, tr)
    assert all(isinstance(r, to.Equilibrium) and r.stable for r in res)
    assert res[0].energy == pytest.approx(to.solve_equilibrium(PAPER, *tr[0]).energy, rel=1e-12)
    for k in range(1, len(tr), 17):
        local = to.solve_equilibrium(PAPER, *tr[k], q0=res[k - 1].q, local=True)
        assert np.allclose(local.q, res[k].q, atol=1e-9)
        assert np.allclose(res[k].tip, PAPER.target(*tr[k]), atol=1e-9)
        assert np.allclose(PAPER.gradient(res[k].q), PAPER.jacobian(res[k].q).T @ res[k].force, atol=1e-9)


def test_without_continuation_each_point_is_global():
    tr = trajectory(12)
    res = to.solve_equilibria_batch(PAPER, tr, continuation=False)
    for r, (dx, dy) in zip(res, tr):
        assert r.energy == pytest.approx(to.solve_equilibrium(PAPER, dx, dy).energy, rel=1e-12)


def test_errors_stay_in_place():
    res = to.solve_equilibria_batch(PAPER, [[0.1, 0], [-1, 0], [0.2, 0.1], [0, 0], [0.3, 0], [5.0, 0.0]])
    kinds = [type(r).__name__ for r in res]
    assert kinds[:5] == ["Equilibrium", "UnreachableTargetError", "Equilibrium", "Equilibrium", "Equilibrium"]
    assert isinstance(res[5], RuntimeError)           # every minimiser on a joint limit
    assert res[3].shape == "I"
    assert res[1].field == "dx"
    with pytest.raises(to.InvalidParameterError):
        to.solve_equilibria_batch(PAPER, [[0.1, 0.2, 0.3]])


def test_branch_loss_falls_back_to_a_global_solve():
    """Sweeping dy across 0 on the U branch: continuation stays on its branch while it is stable."""
    dy = np.linspace(-0.6, 0.6, 41)
    res = to.solve_equilibria_batch(PAPER, np.column_stack([np.full(dy.size, 0.3), dy]))
    assert all(r.stable for r in res)
    # continuation keeps the first branch (metastable beyond dy = 0), unlike the least-energy curve
    assert np.sign(res[-1].q[0]) == np.sign(res[0].q[0])
