"""No wrong answer labelled converged, on extreme but valid geometry.

Every equilibrium the library or the service returns is checked here against the independent
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

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, note, settings
from hypothesis import strategies as st

import tensegrity_opt as to
from tensegrity_opt.errors import (NoEquilibriumError, SolverError, StraightNotEquilibriumError,
                                   UnreachableTargetError)

from reference_model import Chain

REFUSALS = (UnreachableTargetError, NoEquilibriumError, SolverError, StraightNotEquilibriumError)
#: the accuracy every returned equilibrium must have (the library's own bar is 1e-9)
TOL = 1e-8


def _log(lo: float, hi: float):
    return st.floats(math.log10(lo), math.log10(hi)).map(lambda e: 10.0 ** e)


@st.composite
def chains(draw, n_max: int = 8):
    """A chain of 2..n_max segments: one geometry scaled to an extreme unit, then varied per segment."""
    n = draw(st.integers(2, n_max))
    length = draw(_log(1e-5, 1e5))                 # the unit of length
    stiff = draw(_log(1e-5, 1e8))                  # the unit of stiffness
    slender = draw(st.sampled_from([1.0, 1.0, 1e-3, 1e3, 1e6, 1e-6]))   # a / b
    hetero = draw(st.booleans())
    segs = []
    for i in range(n):
        jit = (lambda: draw(st.floats(0.5, 2.0))) if hetero or i == 0 else (lambda: 1.0)
        b = length * jit()
        a = min(max(b * slender * jit(), 1e-6), 1e6)
        b = min(max(b, 1e-6), 1e6)
        k1 = min(max(stiff * jit(), 1e-6), 1e9)
        k2 = k1 * (draw(st.floats(0.5, 2.0)) if draw(st.booleans()) else 1.0)
        # rest lengths around the straight spring length 2b: shorter (monotonic) or longer (bistable)
        L10 = min(max(2 * b * draw(st.floats(0.3, 1.6)), 1e-6), 1e6)
        L20 = L10 * (draw(st.floats(0.8, 1.25)) if draw(st.booleans()) else 1.0)
        segs.append(to.Segment(a=a, b=b, k=(k1, min(max(k2, 1e-6), 1e9)), L0=(L10, min(max(L20, 1e-6), 1e6))))
    return to.Manipulator(segs)


def _reference(m: to.Manipulator) -> Chain:
    return Chain(m.a.copy(), m.b.copy(), m.k1.copy(), m.k2.copy(), m.L1_0.copy(), m.L2_0.copy())


def check(m: to.Manipulator, eq, target=None, *, stable: bool | None = None) -> None:
    """``eq`` (an Equilibrium or the service's JSON) is an equilibrium of ``m`` by the reference model."""
    if isinstance(eq, dict):
        q, F, tip, energy = (np.array(eq["q"], float), np.array([eq["force"]["fx"], eq["force"]["fy"]], float),
                             np.array(eq["tip"], float), eq["energy"])
        is_stable = eq["stable"]
    else:
        q, F, tip, energy, is_stable = eq.q, eq.force, eq.tip, eq.energy, eq.stable
    ref = _reference(m)
    assert np.all(np.abs(q) < ref.limits), f"outside the physical range: {q} vs {ref.limits}"
    T = float(np.max(np.maximum(ref.k1, ref.k2) * ref.c ** 2))
    L = float(np.sum(ref.b))
    r = float(np.abs(ref.grad(q) - ref.jac(q).T @ F).max()) / T
    assert r <= TOL, f"grad E - J^T F = {r:.3g} (relative to k c^2 = {T:.3g})"
    assert float(np.abs(ref.tip(q) - tip).max()) <= TOL * L, "reported tip is not the tip of q"
    if target is not None:
        off = float(np.abs(ref.tip(q) - np.asarray(target, float)).max())
        assert off <= TOL * L, f"tip {ref.tip(q)} is {off:.3g} away from its target {target} (length {L:.3g})"
    assert abs(ref.energy(q) - energy) <= 1e-9 * max(T, abs(energy)), "reported energy is not E(q)"
    if stable is not None:
        assert is_stable == stable
    J = ref.jac(q)
    if target is not None and np.linalg.matrix_rank(J, tol=1e-12 * L) < 2:
        return                  # full extension: the straight chain is the only feasible point
    w = ref.reduced_eigs(q, F, constrained=target is not None, fd=False)
    if w.size:
        scale = max(T, float(np.abs(w).max()))
        if is_stable:
            assert w.min() > -1e-7 * scale, f"labelled stable with reduced eigenvalues {w}"
        elif np.all(w > 1e-6 * scale):
            pytest.fail(f"labelled not stable with a positive definite reduced Hessian {w}")


def _deflection(m, frac_x, frac_y):
    L = float(m.b.sum())
    return 2 * L * frac_x, 2 * L * frac_y


FAST = settings(max_examples=30, deadline=None, derandomize=True, database=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])


@FAST
@given(m=chains(), fx=st.floats(0.0, 0.5), fy=st.floats(-0.3, 0.3))
def test_least_energy_equilibrium_is_an_equilibrium(m, fx, fy):
    dx, dy = _deflection(m, fx, fy)
    note(f"chain {m.to_dict()}, dx={dx!r}, dy={dy!r}")
    try:
        eq = to.solve_equilibrium(m, dx, dy)
    except REFUSALS:
        return
    check(m, eq, m.target(dx, dy), stable=True)


@settings(max_examples=15, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(m=chains(n_max=5), fx=st.floats(0.0, 0.5), fy=st.floats(-0.3, 0.3))
def test_every_equilibrium_and_the_force_problem(m, fx, fy):
    dx, dy = _deflection(m, fx, fy)
    try:
        found = to.find_equilibria(m, dx, dy)
    except REFUSALS:
        return
    target = m.target(dx, dy)
    for eq in found:
        check(m, eq, target)
    if found:
        # the same configuration under its own force as a dead load (no tip constraint)
        eq = found[0]
        try:
            f_eq = to.solve_equilibrium_under_force(m, float(eq.force[0]), float(eq.force[1]), q0=eq.q)
        except REFUSALS:
            return
        check(m, f_eq)
        assert float(np.abs(f_eq.force - eq.force).max()) <= 1e-12 * max(1.0, float(np.abs(eq.force).max()))


@settings(max_examples=8, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(m=chains(n_max=5), fx=st.floats(0.01, 0.4), fy=st.floats(-0.2, 0.2))
def test_trajectories_and_the_tracker(m, fx, fy):
    # the compiled continuation (batch) and the stateful tracker: every point they return checks out
    _check_path(m, [_deflection(m, fx * s, fy * s) for s in (0.25, 0.5, 0.75, 1.0)])


def _check_path(m, pts) -> None:
    """Every point the compiled continuation (batch) and the stateful tracker return along ``pts``."""
    for res, (dx, dy) in zip(to.solve_equilibria_batch(m, pts), pts):
        if isinstance(res, Exception):
            assert isinstance(res, REFUSALS), repr(res)
            continue
        check(m, res, m.target(dx, dy), stable=True)
    tr = to.Tracker(m)
    for dx, dy in pts:
        try:
            check(m, tr.solve(dx, dy), m.target(dx, dy))
        except REFUSALS:
            break


@pytest.mark.parametrize("n, a, b, k, L0, dx", [
    (4, 1e6, 1.0, 1.0, 1.0, 0.1),          # the request: tip left at 8 instead of 7.9
    (2, 2e4, 1.0, 1.0, 1.0, 0.05),
    (12, 1e5, 1.0, 1.0, 1.0, 0.3),
    (2, 1.0, 1.0, 1e9, 1.0, 0.05),          # stiff springs: tips 0.02 off were accepted
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
        check(m, eq, m.target(dx, dy), stable=True)
    _check_path(m, [(dx * s, dy * s) for s in (0.5, 1.0)])      # from the straight chain


@pytest.mark.parametrize("n", [4, 8])
def test_tiny_chains_are_solved(n):
    # a = b = L0 = 1e-6, k = 1: torque scale 2e-12; every minimum was classified degenerate before
    m = to.Manipulator.uniform(n, a=1e-6, b=1e-6, k=1.0, L0=1e-6)
    dx = 0.05 * 2 * n * 1e-6
    eq = to.solve_equilibrium(m, dx, 0.3 * dx)
    check(m, eq, m.target(dx, 0.3 * dx), stable=True)


def test_bistable_two_segment_chain_does_not_crash():
    # n = 2 multistable chains take the projected random sample (reduced Hessian 0 x 0): a reshape crashed
    m = to.Manipulator.uniform(2, a=1.0, b=1000.0, k=1.0, L0=1000.0)
    assert not m.monotonic
    eq = to.solve_equilibrium(m, 50.0, 15.0)
    check(m, eq, m.target(50.0, 15.0), stable=True)


# ------------------------------------------------------------------------------------------ service
@pytest.fixture(scope="module")
def client():
    from fastapi.testclient import TestClient

    from service.config import Settings
    from service.main import create_app

    with TestClient(create_app(Settings(warmup=False, inline_processes=0))) as c:
        yield c


def _body(m: to.Manipulator) -> dict:
    return {"segments": [{"a": float(a), "b": float(b), "k": [float(k1), float(k2)], "L0": [float(l1), float(l2)]}
                         for a, b, k1, k2, l1, l2 in zip(m.a, m.b, m.k1, m.k2, m.L1_0, m.L2_0)]}


@settings(max_examples=15, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(m=chains(n_max=6), fx=st.floats(0.0, 0.5), fy=st.floats(-0.3, 0.3))
def test_service_equilibrium_and_batch(client, m, fx, fy):
    dx, dy = _deflection(m, fx, fy)
    r = client.post("/v1/equilibrium", json={"manipulator": _body(m), "dx": dx, "dy": dy})
    if r.status_code == 200:
        check(m, r.json(), m.target(dx, dy), stable=True)
    else:
        assert r.status_code == 422 and r.json()["code"] in ("unreachable_target", "no_equilibrium",
                                                             "solver_failed", "straight_not_equilibrium"), r.text
    targets = [{"dx": dx * s, "dy": dy * s} for s in (0.5, 1.0)]
    r = client.post("/v1/batch/equilibrium", json={"manipulator": _body(m), "targets": targets})
    assert r.status_code == 200, r.text
    for item, t in zip(r.json()["results"], targets):
        if item["equilibrium"] is not None:
            check(m, item["equilibrium"], m.target(t["dx"], t["dy"]), stable=True)


def test_service_reported_request(client):
    # POST /v1/equilibrium {"manipulator":{"n":4,"a":1e6},"dx":0.1} answered 200 with the tip at 8
    r = client.post("/v1/equilibrium", json={"manipulator": {"n": 4, "a": 1e6}, "dx": 0.1})
    assert r.status_code == 422 and r.json()["code"] == "unreachable_target", r.text


@pytest.mark.parametrize("k", [1e7, 1e9])
def test_stiffness_of_stiff_chains_scales_with_k(k):
    # K / k is the same for every k; the KKT matrix's condition number grew as k^2 in the caller's units
    # and the tangent stiffness was refused as singular from k ~ 1e7 on
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
        check(m, to.Equilibrium(q=c.q[j], energy=float(c.energy[j]), force=np.array([c.fx[j], c.fy[j]]),
                                morse_index=0, stable=bool(c.stable[j]), solver=to.outcome.SolverInfo("", 0), tip=m.tip(c.q[j])),
              m.target(c.dx[j], 0.0))
