"""The dead-load path of a chain with dead loads (``loaded_path``): the limit of a sagged pose, and the payload a
design carries before it snaps (``load_capacity`` under gravity)."""

from __future__ import annotations

import numpy as np
import pytest

import tensegrity_opt as to
from tensegrity_opt.analyses.paths.loaded_path import loaded_limit

G = 9.81


def _random_chain(rng):
    n = int(rng.integers(2, 5))
    return to.Manipulator([to.Segment(float(rng.uniform(0.5, 1.2)), 1.0,
                                      (float(rng.uniform(0.5, 2)), float(rng.uniform(0.5, 2))),
                                      (float(rng.uniform(0.8, 1.6)), float(rng.uniform(0.8, 1.6)))) for _ in range(n)])


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("seed", [3, 5])
def test_without_loads_the_path_is_the_arclength_limit_load(seed):
    """A second method: the arclength continuation of ``limit_load`` (its own predictor, events and fold location)
    on pre-bent random chains: the same kind of limit and the same load (measured on 100 chains: all equal)."""
    rng = np.random.default_rng(seed)
    seen = set()
    for _ in range(12):
        m = _random_chain(rng)
        try:
            start = to.rest_configuration(m)
        except to.TensegrityError:
            continue
        ang = rng.uniform(0, 2 * np.pi)
        d = np.array([np.cos(ang), np.sin(ang)])
        mine = loaded_limit(m, start, np.zeros(2), d, 2 * m.torque_scale)
        ref = to.limit_load(m, d, "free", 2 * m.torque_scale, start)
        assert mine.kind == ref.kind
        if mine.kind != "none":
            assert mine.load == pytest.approx(ref.load, rel=1e-6)
        seen.add(mine.kind)
    assert "fold" in seen


def test_the_paper_chains_free_buckling_load_is_a_bifurcation():
    m = to.Manipulator.uniform(4)
    r = loaded_limit(m, to.rest_configuration(m), np.zeros(2), np.array([-1.0, 0.0]), 1.0)
    assert r.kind == "bifurcation" and r.load == pytest.approx(-to.critical_force(m, "free").force, rel=1e-7)


def _arm(gravity, payload=0.1):
    return to.Manipulator.uniform(6, a=0.04, b=0.05, k=3000.0, L0=0.05, mass=0.05, inertia=2e-5, payload=payload,
                                  gravity=gravity)


def test_the_payload_an_upright_arm_carries_before_it_snaps():
    """Pointing up (gravity along -x) a leaning arm pushed sideways folds: ``load_capacity`` finds the fold from the
    sagged pose; forward solves confirm it (a stable equilibrium near the path just below, none near just above), and
    the extra load along gravity is a payload: the same chain with that much more payload mass snaps there too."""
    m = _arm((-G, 0.0))
    rest = to.rest_configuration(m)
    lean = -np.sign(rest.tip[1]) * np.pi / 2              # pushed back across the way it leans
    cap = to.load_capacity(m, directions=[lean], max_load=50.0)
    assert cap.kinds == ("fold",) and cap.status == "complete"
    t, d = float(cap.loads[0]), cap.directions[0]
    q = cap.q[0]
    below = to.solve_equilibrium_under_force(m, *(0.999 * t * d), q0=q)
    assert below.stable and float(np.abs(below.q - q).max()) < 0.05
    above = to.solve_equilibrium_under_force(m, *(1.001 * t * d), q0=q)
    assert float(np.abs(above.q - q).max()) > 0.1           # it snapped away
    # along gravity the extra tip load is a payload: the chain with its payload grown by 5 / g rests where the path
    # from the sagged pose under 5 more along gravity ends (it carries that much: no limit up to max_load)
    cap_g = to.load_capacity(m, directions=[np.pi], max_load=5.0)
    assert cap_g.kinds == ("none",) and cap_g.reasons == ("max_load",)
    heavier = _arm((-G, 0.0), payload=0.1 + 5.0 / G)
    eq = to.solve_equilibrium_under_force(heavier, 0.0, 0.0, q0=rest.q)
    path_end = to.solve_equilibrium_under_force(m, -5.0, 0.0, q0=rest.q)
    assert eq.stable and path_end.stable
    np.testing.assert_allclose(eq.q, path_end.q, atol=1e-8)


def test_a_loaded_chain_refuses_the_guided_boundary_by_name():
    with pytest.raises(to.UnsupportedError) as e:
        to.load_capacity(_arm((0.0, -G)), boundary="guided")
    assert e.value.field == "gravity"


def test_the_weight_an_upright_arm_carries_before_it_buckles_is_where_its_straight_hessian_turns_singular():
    """Standing straight up (gravity along -x), the arm's rest pose is straight and stays so as its weights grow,
    until the straight pose's Hessian (the springs' ``K_i`` against the weights' destabilising term, linear in the
    factor) turns singular: an independent bisection on its smallest eigenvalue gives the factor."""
    m = to.Manipulator.uniform(6, a=0.04, b=0.05, k=5000.0, L0=0.05, mass=0.05, inertia=2e-5, payload=0.1,
                               gravity=(-G, 0.0))
    w = to.weight_capacity(m)
    assert w.success and w.kind == "bifurcation" and w.reason is None
    K = np.diag([-float(s.dtorque(0.0)) for s in m.segments])
    Hg = m.load_hessian(np.zeros(6))                    # the weights' Hessian at the straight pose, factor 1
    lo, hi = 0.0, 10.0
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if np.linalg.eigvalsh(K + mid * Hg)[0] > 0 else (lo, mid)
    assert w.factor == pytest.approx(lo, rel=1e-8)
    body = w.to_dict()
    assert body["kind"] == "bifurcation" and body["start"]["loads"]["gravity"] == [-G, 0.0]


def test_growing_weights_lean_an_arm_onto_its_range_bound_as_forward_solves_say():
    m = to.Manipulator.uniform(4, a=0.04, b=0.05, k=800.0, L0=0.05, mass=0.05, payload=0.1, gravity=(-G, 0.5))
    w = to.weight_capacity(m, max_factor=20.0)
    assert (w.kind, w.reason) == ("none", "joint_limit") and 1.0 < w.end_factor < 20.0
    assert np.all(np.abs(w.q) <= m.joint_limits)        # never past the range (a predictor there is refused)
    # the chain with its weights at 0.99 of the end factor rests, stably, near the path's last configuration
    g = 0.99 * w.end_factor
    heavier = to.Manipulator(m.segments, m.payload, (-G * g, 0.5 * g))
    eq = to.solve_equilibrium_under_force(heavier, 0.0, 0.0, q0=w.q)
    assert eq.stable and float(np.abs(eq.q - w.q).max()) < 0.2
    assert float(np.max(np.abs(w.q) / m.joint_limits)) > 0.99         # a joint at its bound at the end


def test_a_chain_without_weight_has_no_weight_capacity():
    with pytest.raises(to.InvalidParameterError) as e:
        to.weight_capacity(to.Manipulator.uniform(3, mass=0.1))
    assert e.value.field == "gravity"
    with pytest.raises(to.InvalidParameterError) as e:
        to.weight_capacity(_arm((0.0, -G)), max_factor=1.0)
    assert e.value.field == "max_factor"
