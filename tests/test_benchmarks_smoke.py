"""Smoke test of the benchmark baselines (benchmarks/baselines.py): each runs once on the paper's
chain (n = 4) and reaches the library's equilibrium. Correctness only, no timing asserts."""

from __future__ import annotations

import os
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import tensegrity_opt as to  # noqa: E402
from benchmarks import baselines as bl  # noqa: E402

REL = 1e-8


@pytest.fixture(scope="module")
def m():
    return to.Manipulator.uniform(4)


def test_model_matches_library(m):
    ch = bl.Chain(m)
    q = np.array([0.1, -0.2, 0.3, 0.05])
    assert ch.energy(q) == pytest.approx(m.energy(q), rel=1e-14)
    np.testing.assert_allclose(ch.gradient(q), m.gradient(q), atol=1e-14)
    np.testing.assert_allclose(ch.tip(q), m.tip(q), atol=1e-14)
    np.testing.assert_allclose(ch.jacobian(q), m.jacobian(q), atol=1e-14)


@pytest.mark.parametrize("dx, dy", [(0.1, 0.0), (0.8, 0.3)])
def test_constrained_baselines_reach_library_energy(m, dx, dy):
    eq = to.solve_equilibrium(m, dx, dy)
    prev = to.solve_equilibrium(m, dx - 1e-3, dy)          # the warm start of case 1
    r = bl.slsqp_equilibrium(m, dx, dy, prev.q)
    assert r.success and r.tip_error < 1e-8
    assert abs(r.energy - eq.energy) <= REL * abs(eq.energy)
    r = bl.trust_constr_equilibrium(m, dx, dy, prev.q)
    assert r.tip_error < 1e-8
    assert abs(r.energy - eq.energy) <= REL * abs(eq.energy)


def test_global_baselines_reach_library_energy(m):
    dx, dy = 1.2, -0.4
    eq = to.solve_equilibrium(m, dx, dy)
    r = bl.energy_method_n4(m, dx, dy)
    assert r.tip_error < 1e-8
    assert abs(r.energy - eq.energy) <= REL * abs(eq.energy)
    r = bl.slsqp_multistart(m, dx, dy, n_starts=14)
    assert r.success
    assert abs(r.energy - eq.energy) <= REL * abs(eq.energy)


def test_force_deflection_and_buckling_baselines(m):
    dxs = np.linspace(0.0, 2.0, 21)
    curve = to.force_deflection(m, dxs)
    res = bl.slsqp_force_deflection(m, dxs)
    E = np.array([r.energy for r in res])
    np.testing.assert_allclose(E, curve.energy, rtol=REL)
    loads, modes = bl.dense_critical_loads(m)
    np.testing.assert_allclose(loads, to.critical_force(m).loads, rtol=1e-10)
    q0 = bl.mode_start(m, 0.1, modes[:, 0])
    assert m.in_range(q0)


def test_the_modes_baseline_agrees_with_the_library():
    """benchmarks/modes.py's baseline (differences of positions, angles and the numpy gradient) gives the frequencies
    of ``to.modes`` (their accuracy: ~1e-10)."""
    from benchmarks import modes as bm

    m = to.Manipulator([to.Segment(1, 1, 1, 1.1, mass=0.3, inertia=0.02), to.Segment(0.9, 1.1, 1.2, 1.0, mass=0.2),
                        to.Segment(1.1, 0.9, 0.8, 0.9, mass=0.4, inertia=0.01)], payload=0.1)
    eq = to.solve_equilibrium(m, 0.6, 0.2)
    np.testing.assert_allclose(bm._baseline(m, eq), to.modes(m, eq).frequencies, rtol=1e-8)
