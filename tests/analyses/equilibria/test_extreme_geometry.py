"""No wrong answer labelled converged, on extreme but valid geometry.

Every equilibrium the library returns is checked here against the independent
reference model (``tests/support/reference_model.py``, which does not import the library): the equilibrium
equations ``grad E = J^T F`` relative to the torque scale ``k c^2``, the tip on its target relative
to the chain's length, the angles inside the physical range, the reported tip and energy, and the
stability label against the reference reduced Hessian. Chains are drawn by hypothesis over the
request schema's whole range (lengths 1e-6..1e6, stiffnesses 1e-6..1e9): slender (a >> b), stubby,
very stiff, very soft, tiny and huge, heterogeneous, with asymmetric preloads, bistable ones. A
refusal (unreachable target, no equilibrium) is an allowed answer; anything else is not.

What the checks catch: without the rescaling of ``numerics.units.UNIT_RATIO``, ``a = 1e6`` would return the
unmoved straight chain as ``Newton_Converged`` 0.1 away from its target, ``k = 1e9`` would accept tips 0.02 off,
and tiny chains (``a = b = L0 = 1e-6``) would classify every minimum as degenerate.
"""

from __future__ import annotations

import numpy as np
import pytest
from extreme_chains import chains, check_equilibrium, deflection
from hypothesis import HealthCheck, given, note, settings
from hypothesis import strategies as st

import tensegrity_opt as to
from tensegrity_opt.errors import NoEquilibriumError, SolverError, StraightNotEquilibriumError, UnreachableTargetError

REFUSALS = (UnreachableTargetError, NoEquilibriumError, SolverError, StraightNotEquilibriumError)


FAST = settings(max_examples=30, deadline=None, derandomize=True, database=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])


@pytest.mark.slow
@FAST
@given(m=chains(), fx=st.floats(0.0, 0.5), fy=st.floats(-0.3, 0.3))
def test_least_energy_equilibrium_is_an_equilibrium(m, fx, fy):
    dx, dy = deflection(m, fx, fy)
    note(f"chain {m.to_dict()}, dx={dx!r}, dy={dy!r}")
    try:
        eq = to.solve_equilibrium(m, dx, dy)
    except REFUSALS:
        return
    check_equilibrium(m, eq, m.target(dx, dy), stable=True)


@pytest.mark.slow
@settings(max_examples=15, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(m=chains(n_max=5), fx=st.floats(0.0, 0.5), fy=st.floats(-0.3, 0.3))
def test_every_equilibrium_and_the_force_problem(m, fx, fy):
    dx, dy = deflection(m, fx, fy)
    try:
        found = to.find_equilibria(m, dx, dy)
    except REFUSALS:
        return
    target = m.target(dx, dy)
    for eq in found:
        check_equilibrium(m, eq, target)
    if found:
        # the same configuration under its own force as a dead load (no tip constraint)
        eq = found[0]
        try:
            f_eq = to.solve_equilibrium_under_force(m, float(eq.force[0]), float(eq.force[1]), q0=eq.q)
        except REFUSALS:
            return
        check_equilibrium(m, f_eq)
        assert float(np.abs(f_eq.force - eq.force).max()) <= 1e-12 * max(1.0, float(np.abs(eq.force).max()))


@pytest.mark.slow
@settings(max_examples=8, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(m=chains(n_max=5), fx=st.floats(0.01, 0.4), fy=st.floats(-0.2, 0.2))
def test_trajectories_and_the_tracker(m, fx, fy):
    # the compiled continuation (batch) and the stateful tracker: every point they return checks out
    _check_path(m, [deflection(m, fx * s, fy * s) for s in (0.25, 0.5, 0.75, 1.0)])


def _check_path(m, pts) -> None:
    """Every point the compiled continuation (batch) and the stateful tracker return along ``pts``."""
    for res, (dx, dy) in zip(to.solve_equilibria_batch(m, pts), pts):
        if isinstance(res, Exception):
            assert isinstance(res, REFUSALS), repr(res)
            continue
        check_equilibrium(m, res, m.target(dx, dy), stable=True)
    tr = to.Tracker(m)
    for dx, dy in pts:
        try:
            check_equilibrium(m, tr.solve(dx, dy), m.target(dx, dy))
        except REFUSALS:
            break


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("n, a, b, k, L0, dx", [
    (4, 1e6, 1.0, 1.0, 1.0, 0.1),          # slender: the unmoved tip (8) is no answer for 7.9
    (2, 2e4, 1.0, 1.0, 1.0, 0.05),
    (12, 1e5, 1.0, 1.0, 1.0, 0.3),
    (2, 1.0, 1.0, 1e9, 1.0, 0.05),          # stiff springs: a tip 0.02 off is no answer
    (8, 1.0, 1.0, 1e9, 1.0, 3.2),
])
@pytest.mark.parametrize("dy_per_dx", [0.0, 0.3])
def test_the_reported_cases_are_refused_or_right(n, a, b, k, L0, dx, dy_per_dx):
    m = to.Manipulator.uniform(n, a=a, b=b, k=k, L0=L0)
    dy = dy_per_dx * dx
    for method in ("auto", "newton"):
        try:
            eq = to.solve_equilibrium(m, dx, dy, method=method)
        except REFUSALS:         # method='newton' cannot tell an unreachable target: NoEquilibriumError
            continue
        check_equilibrium(m, eq, m.target(dx, dy), stable=True)
    _check_path(m, [(dx * s, dy * s) for s in (0.5, 1.0)])      # from the straight chain


@pytest.mark.parametrize("n", [4, 8])
def test_tiny_chains_are_solved(n):
    # a = b = L0 = 1e-6, k = 1: torque scale 2e-12; unscaled, every minimum would be classified degenerate
    m = to.Manipulator.uniform(n, a=1e-6, b=1e-6, k=1.0, L0=1e-6)
    dx = 0.05 * 2 * n * 1e-6
    eq = to.solve_equilibrium(m, dx, 0.3 * dx)
    check_equilibrium(m, eq, m.target(dx, 0.3 * dx), stable=True)


def test_bistable_two_segment_chain_does_not_crash():
    # n = 2 multistable chains take the projected random sample (reduced Hessian 0 x 0): a reshape crashed
    m = to.Manipulator.uniform(2, a=1.0, b=1000.0, k=1.0, L0=1000.0)
    assert not m.monotonic
    eq = to.solve_equilibrium(m, 50.0, 15.0)
    check_equilibrium(m, eq, m.target(50.0, 15.0), stable=True)


# ------------------------------------------------------------------------------------------ service


@pytest.mark.parametrize("k", [1e7, 1e9])
def test_stiffness_of_stiff_chains_scales_with_k(k):
    # K / k is the same for every k; in the caller's units the KKT matrix's condition number grows as k^2 and an
    # unscaled tangent stiffness would be refused as singular from k ~ 1e7 on
    m1, mk = to.Manipulator.uniform(4), to.Manipulator.uniform(4, k=k)
    K1 = to.cartesian_stiffness(m1, to.solve_equilibrium(m1, 0.5))
    Kk = to.cartesian_stiffness(mk, to.solve_equilibrium(mk, 0.5))
    np.testing.assert_allclose(np.asarray(Kk) / k, np.asarray(K1), rtol=1e-7, atol=1e-9 * np.abs(K1).max())


def test_a_curve_from_dx_0_on_a_pre_bent_chain_marks_the_straight_point():
    # the straight chain at dx = dy = 0 is no equilibrium with asymmetric preloads: not a stable point
    m = to.Manipulator([to.Segment(a=1.0, b=1.0, k=1.0, L0=(1.0, 1.3))] * 4)
    c = to.force_deflection(m, [0.0, 0.1, 0.2])
    assert c.point_status[0] == "straight_not_equilibrium" and not c.stable[0]
    for j in (1, 2):
        eq = to.Equilibrium(q=c.q[j], energy=float(c.energy[j]), force=np.array([c.fx[j], c.fy[j]]), morse_index=0,
                            stable=bool(c.stable[j]), solver=to.outcome.SolverInfo("", 0), tip=m.tip(c.q[j]))
        check_equilibrium(m, eq, m.target(c.dx[j], 0.0))
