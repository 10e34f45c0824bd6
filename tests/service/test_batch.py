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


def test_the_iterations_of_a_continued_point_are_counted_or_null_never_minus_one():
    """Issue 18: batch points showed ``"iterations": -1``. A point of the compiled continuation (kernels,
    n <= 8) reports the Newton iterations it took - the count of the Python damped Newton method from the
    previous point, a second implementation of the same step - and a chain solved by CasADi's rootfinder
    (n > 8), which does not count them, reports ``None`` (JSON null), as the schema says."""
    from service.schemas.common import SolverInfo
    from tensegrity_opt.numerics import chain_solver

    tr = [(0.1 + 0.05 * i, 0.02 * i) for i in range(8)]
    res = to.solve_equilibria_batch(PAPER, tr)
    mdl = chain_solver(PAPER)
    for i in range(1, len(tr)):
        ref = mdl.newton_kkt(PAPER.target(*tr[i]), res[i - 1].q, res[i - 1].force)
        assert ref.success and np.allclose(ref.q, res[i].q, atol=1e-12)
        assert res[i].solver.iterations == ref.iterations >= 1          # the target moved: at least one step
        assert res[i].to_dict()["solver"]["iterations"] == ref.iterations
    long = to.Manipulator.uniform(12)
    res = to.solve_equilibria_batch(long, [(0.1 + 0.01 * i, 0.0) for i in range(4)])
    assert all(isinstance(r, to.Equilibrium) for r in res)
    assert all(r.solver.iterations is None or r.solver.iterations >= 0 for r in res)
    continued = [r for r in res[1:] if r.solver.iterations is None]
    assert continued, "n = 12 continues by the rootfinder"
    body = continued[0].to_dict()["solver"]
    assert body["iterations"] is None and SolverInfo(**body).iterations is None
    assert "null: not counted" in SolverInfo.model_fields["iterations"].description
