"""Tracker (the control-loop API): follows the branch like a manipulator driven along a path."""

import numpy as np
import pytest

import tensegrity_opt as to
from tensegrity_opt import find_equilibria, solve_equilibrium

from reference_model import Chain

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
