"""Preloads for a pose and for a critical load (analyses/design/preloads.py), checked by independent
computations: the forward equilibrium, numpy finite differences, the paper's critical load."""

import numpy as np
import pytest

import tensegrity_opt as to
from tensegrity_opt.analyses.design.preloads import preloads_for_critical_force, preloads_for_pose
from tensegrity_opt.errors import InfeasibleDesignError

PAPER = to.Manipulator.uniform(4)
P_UNIT = 0.572793          # docs/model.md: critical load of the paper's chain with K = 1


def test_preloads_for_required_load():
    d = preloads_for_critical_force(PAPER, 0.7)
    assert d.feasible
    assert -to.critical_force(d.manipulator).force >= 0.7 * (1 - 1e-6)
    change = np.linalg.norm(d.manipulator.L1_0 - 1.0)
    # uniform scaling of K by 0.7/0.5728 (K = b L0 - 2(b^2 - a^2) = L0 here) is feasible, so the
    # minimal change cannot exceed it
    uniform_change = np.linalg.norm(np.full(4, 0.7 / P_UNIT - 1.0))
    assert change <= uniform_change + 1e-8
    assert d.status == "optimal" and d.success
    infeasible = preloads_for_critical_force(PAPER, 10.0)
    assert not infeasible.feasible and infeasible.status == "below_required" and not infeasible.success
    # best achievable with L0 <= 2b: K = 2 a^2 = 2, P = 2 * 0.572793
    assert infeasible.load == pytest.approx(2 * P_UNIT, rel=1e-5)


@pytest.mark.parametrize("objective", ["change", "margin", "energy"])
def test_preloads_for_a_pose_verified_independently(objective):
    target, load = np.array([7.0, 1.5]), np.array([0.05, -0.02])
    r = preloads_for_pose(PAPER, target, load=load, objective=objective, margin=0.05)
    assert r.success and r.status == "optimal" and r.solver.status in ("Solve_Succeeded", "Solved_To_Acceptable_Level")
    m = r.manipulator
    eq = to.solve_equilibrium_under_force(m, *load, q0=r.q)
    assert np.allclose(eq.tip, target, atol=1e-6) and eq.morse_index == 0
    # numpy check of the equilibrium and of the margin (Hessian by finite differences of torques)
    assert np.allclose(m.gradient(r.q), m.jacobian(r.q).T @ load, atol=1e-8)
    h = 1e-6
    H = np.column_stack([((m.gradient(r.q + h * e) - m.jacobian(r.q + h * e).T @ load)
                          - (m.gradient(r.q - h * e) - m.jacobian(r.q - h * e).T @ load)) / (2 * h)
                         for e in np.eye(4)])
    assert np.linalg.eigvalsh((H + H.T) / 2)[0] == pytest.approx(r.margin, abs=1e-5)
    assert r.margin >= 0.05 - 1e-6


def test_the_objectives_do_what_they_say():
    target, load = (7.0, 1.5), (0.05, -0.02)
    nominal = preloads_for_pose(PAPER, target, load=load, objective="change", margin=0.05)
    margin = preloads_for_pose(PAPER, target, load=load, objective="margin", margin=0.05)
    energy = preloads_for_pose(PAPER, target, load=load, objective="energy", margin=0.05)
    assert margin.margin > nominal.margin
    assert energy.energy <= nominal.energy + 1e-9
    change = lambda r: np.linalg.norm(r.preloads - 1.0)       # noqa: E731
    assert change(nominal) <= change(margin) and change(nominal) <= change(energy)


def test_taut_springs_and_an_end_angle():
    r = preloads_for_pose(PAPER, (6.5, 2.0), taut=True, end_angle=0.6, margin=0.01)
    L1, L2 = r.manipulator.spring_lengths(r.q)
    assert np.all(L1 >= r.preloads[:, 0] - 1e-7) and np.all(L2 >= r.preloads[:, 1] - 1e-7)
    assert r.q.sum() == pytest.approx(0.6, abs=1e-7)
    assert np.allclose(r.manipulator.tip(r.q), [6.5, 2.0], atol=1e-6)


def test_a_start_keeps_the_family_of_shapes():
    """From a start in the mirrored shape, the pose is sought there: the verified configuration stays near it
    (an independent check: the forward equilibrium from that start with the found rest lengths)."""
    default = preloads_for_pose(PAPER, (7.6, 0.0), margin=0.01)
    start = -default.q
    mirrored = preloads_for_pose(PAPER, (7.6, 0.0), margin=0.01, start=start)
    eq = to.solve_equilibrium_under_force(mirrored.manipulator, 0.0, 0.0, q0=start)
    assert np.allclose(eq.q, mirrored.q, atol=1e-6) and np.allclose(eq.tip, (7.6, 0.0), atol=1e-6)
    assert np.sign(mirrored.q[0]) == np.sign(start[0])


def test_errors_name_the_field():
    with pytest.raises(to.InvalidParameterError) as ei:
        preloads_for_pose(PAPER, (7.0, 0.5), objective="nominal")
    assert ei.value.field == "objective"
    with pytest.raises(to.InvalidParameterError) as ei:
        preloads_for_pose(PAPER, (7.0, 0.5), start=[0.0, 0.1])
    assert ei.value.field == "start" and "start" in ei.value.message
    with pytest.raises(to.InvalidParameterError) as ei:
        preloads_for_pose(to.Manipulator.uniform(1), (1.5, 0.5))
    assert ei.value.field == "n"
    with pytest.raises(to.UnreachableTargetError):
        preloads_for_pose(PAPER, (9.0, 0.0))
    with pytest.raises(to.TimeLimitError):
        preloads_for_pose(PAPER, (7.0, 1.0), timeout=1e-6)
    with pytest.raises(InfeasibleDesignError) as ei:       # impossible margin within the bounds
        preloads_for_pose(PAPER, (7.0, 1.0), margin=1e3)
    assert isinstance(ei.value, RuntimeError) and ei.value.status and ei.value.best is not None
