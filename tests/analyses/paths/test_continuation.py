"""Natural-parameter continuation (``analyses/paths/continuation.py``): the ``Tracker`` (the control-loop API),
which follows the branch like a manipulator driven along a path, and ``solve_equilibria_batch`` (trajectories of
targets in one call)."""

import numpy as np
import pytest
from reference_model import Chain

import tensegrity_opt as to
from tensegrity_opt import find_equilibria, solve_equilibrium

PAPER = to.Manipulator.uniform(4)


def test_tracker_follows_the_branch_of_the_reference_model():
    """Each step equals the independent reference model's Newton solve from the previous step."""
    ref = Chain.uniform(4, 1.0, 1.0, 1.0, 1.0)
    tr = to.Tracker(PAPER)
    s = np.linspace(0.0, 1.0, 120)
    path = np.column_stack([0.1 + 0.7 * s, 0.2 * np.sin(3 * s)])
    first = tr.solve(*path[0])
    assert first == tr.current and first.stable
    np.testing.assert_allclose(first.q, solve_equilibrium(PAPER, *path[0]).q, atol=1e-12)
    prev = first
    for dx, dy in path[1:]:
        eq = tr.solve(dx, dy)
        qr, Fr, ok = ref.newton_kkt(ref.target(dx, dy), prev.q, prev.force)
        assert ok
        np.testing.assert_allclose(eq.q, qr, atol=1e-9)
        np.testing.assert_allclose(eq.force, Fr, atol=1e-9)
        assert eq.stable and eq.solver.status == "Newton_Converged" and eq.solver.iterations <= 4
        prev = eq
    assert tr.jumps == 0


def test_tracker_agrees_with_batch_continuation():
    s = np.linspace(0.0, 1.0, 300)
    path = np.column_stack([0.05 + 1.5 * s, 0.3 * np.sin(2 * np.pi * s)])
    batch = to.solve_equilibria_batch(PAPER, path)
    tr = to.Tracker(PAPER)
    for (dx, dy), b in zip(path, batch):
        eq = tr.solve(dx, dy)
        np.testing.assert_allclose(eq.q, b.q, atol=1e-8)
        assert eq.morse_index == b.morse_index


def test_tracker_leaves_an_unstable_branch_unless_told_to_stay():
    eqs = find_equilibria(PAPER, 0.2, 0.0)
    saddle = next(e for e in eqs if e.kind == "saddle")
    stay = to.Tracker(PAPER, saddle, jump=False).solve(0.201, 0.0)
    local = solve_equilibrium(PAPER, 0.201, 0.0, q0=saddle.q, local=True)
    assert not stay.stable and stay.morse_index == saddle.morse_index == local.morse_index
    np.testing.assert_allclose(stay.q, local.q, atol=1e-9)

    tr = to.Tracker(PAPER, saddle)
    jumped = tr.solve(0.201, 0.0)
    glob = solve_equilibrium(PAPER, 0.201, 0.0, q0=saddle.q)
    assert tr.jumps == 1 and jumped.stable
    np.testing.assert_allclose(jumped.q, glob.q, atol=1e-9)
    assert jumped.energy < stay.energy


def test_tracker_errors_keep_the_state():
    tr = to.Tracker(PAPER)
    eq = tr.solve(0.3, 0.1)
    with pytest.raises(to.UnreachableTargetError):
        tr.solve(-1.0, 0.0)
    assert tr.current is eq
    with pytest.raises(ValueError):
        to.Tracker(PAPER, to.solve_equilibrium(to.Manipulator.uniform(3), 0.1))
    tr.reset()
    assert tr.current is None and tr.q is None


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("m", [PAPER, to.Manipulator([to.Segment(1.0, 0.9 + 0.1 * i, (1.0 + 0.3 * i, 1.2), 1.0)
                                                      for i in range(5)])])
def test_method_newton_finds_the_least_energy_of_ipopt(m):
    """The bounded Newton-only search against IPOPT from the same seeds (monotonic chains)."""
    rng = np.random.default_rng(11)
    done = 0
    while done < 8:
        dx, dy = rng.uniform(0.05, 2.5), rng.uniform(-0.8, 0.8)
        try:
            ip = solve_equilibrium(m, dx, dy, method="ipopt")
        except to.TensegrityError:
            continue
        nw = solve_equilibrium(m, dx, dy, method="newton")
        assert nw.stable and nw.energy == pytest.approx(ip.energy, rel=1e-9, abs=1e-12)
        done += 1
    with pytest.raises(to.InvalidParameterError, match="'newton'"):
        solve_equilibrium(m, 0.1, method="slsqp")


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
    """A point of the compiled continuation (kernels, n <= 8) reports the Newton iterations it took - the count of
    the Python damped Newton method from the previous point, a second implementation of the same step - and a chain
    solved by CasADi's rootfinder (n > 8), which does not count them, reports ``None`` (JSON null); never -1."""
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
    assert continued[0].to_dict()["solver"]["iterations"] is None
