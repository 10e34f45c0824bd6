"""Dead loads: weights under gravity, a payload, forces at the joints (issue "weights and loads anywhere").

Expected numbers come from the independent reference ``tests/support/reference_loads.py`` (the load points built
from the triangles' vertices and by chaining the links, ``V = -sum w . x``, its derivatives from the rigid motions
and by five-point differences; the least potential by dense grids of the constraint manifold, or of the closed box
for a free tip, polished by SLSQP and Newton; every equilibrium by sign changes on dense charts and Newton on the
KKT system; the modes by ``scipy.linalg.eigh`` of the reference's Hessian and mass matrix), never from the code
under test. Random chains of every family, both spring laws, random masses, payloads, joint forces and gravity
directions scaled so that the weights matter (``|g| m_total sum b ~ 0.1-1 k c^2``).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import reference_dynamics as rd
import reference_loads as rl
import reference_tension_only as ref

import tensegrity_opt as to
from tensegrity_opt.numerics.slack_nlp import slack_nlp

FAMILIES = ("monotonic", "bistable", "heterogeneous", "asymmetric", "dy", "large")
LAWS = ("linear", "tension_only")


# ------------------------------------------------------------------------------------------- random loaded chains
def _geometry(family: str, rng: np.random.Generator, n: int):
    """One family's segment geometry and preloads (``tests/model/test_spring_law.py``'s families) and a deflection."""
    u = lambda lo, hi: float(rng.uniform(lo, hi))  # noqa: E731
    if family == "monotonic":
        return [dict(a=u(0.8, 1.2), b=1.0, k=u(0.5, 2.0), L0=u(0.8, 1.2))] * n, u(0.05, 0.6) * n / 4, 0.0
    if family == "bistable":
        return [dict(a=0.5, b=1.0, k=u(0.5, 2.0), L0=u(0.4, 0.6))] * n, u(0.1, 0.6) * n / 4, 0.0
    if family == "heterogeneous":
        geo = [dict(a=u(0.6, 1.4), b=u(0.6, 1.4), k=u(0.5, 2.0), L0=u(0.7, 1.3)) for _ in range(n)]
        return geo, u(0.05, 0.3) * 0.5 * sum(g["b"] for g in geo), 0.0
    if family == "asymmetric":
        return [dict(a=1.0, b=1.0, k=(u(0.8, 1.2), u(1.2, 1.8)), L0=(u(0.9, 1.1), u(0.7, 0.95)))] * n, \
            u(0.1, 0.5) * n / 4, 0.0
    if family == "dy":
        return [dict(a=1.0, b=1.0, k=u(0.5, 2.0), L0=1.0)] * n, u(0.1, 0.5) * n / 4, u(-0.4, 0.4) * n / 4
    if family == "large":
        return [dict(a=u(0.8, 1.2), b=1.0, k=u(0.5, 2.0), L0=u(0.8, 1.4))] * n, u(0.25, 0.4) * 2.0 * n, \
            u(-0.3, 0.3)
    raise AssertionError(family)


def _kc2(geo) -> float:
    return max(max(np.atleast_1d(g["k"])) * (g["a"] ** 2 + g["b"] ** 2) for g in geo)


def _loaded(family: str, seed: int, spring: str = "linear", n: int = 3, *, joint_forces: bool = True,
            strength: tuple[float, float] = (0.1, 1.0)):
    """A random loaded chain of one family: masses, inertias, a payload, gravity in any direction (``|g| m_total
    sum b`` a random ``strength`` of ``k c^2``), up to two joint forces (``0.05-0.3 k c^2 / sum b``); and a
    deflection (dx, dy)."""
    rng = np.random.default_rng(seed)
    geo, dx, dy = _geometry(family, rng, n)
    masses = rng.uniform(0.05, 1.0, n)
    segs = [to.Segment(**g, spring=spring, mass=float(mi), inertia=float(rng.uniform(0.0, 0.05)))
            for g, mi in zip(geo, masses)]
    payload = float(rng.uniform(0.0, 0.5))
    kc2, sb = _kc2(geo), sum(g["b"] for g in geo)
    g = float(rng.uniform(*strength)) * kc2 / ((masses.sum() + payload) * sb)
    ang = float(rng.uniform(0.0, 2.0 * math.pi))
    forces = ()
    if joint_forces:
        count = int(rng.integers(0, 3))
        joints = rng.choice(np.arange(1, n + 1), size=min(count, n), replace=False)
        forces = tuple((int(j), tuple(rng.uniform(-1.0, 1.0, 2) * rng.uniform(0.05, 0.3) * kc2 / sb))
                       for j in joints)
    m = to.Manipulator(segs, payload=payload, gravity=(g * math.cos(ang), g * math.sin(ang)), joint_forces=forces)
    return m, dx, dy


def _ref(m):
    return rl.segs_of(m), rl.loads_of(m)


def _inside(m, rng, spread=0.95):
    """A random configuration of the open range whose tension-only springs are off their kinks."""
    L0 = np.array([[s.L1_0, s.L2_0] for s in m.segments])
    while True:
        q = rng.uniform(-spread, spread, m.n) * m.joint_limits
        if np.all(np.abs(ref.lengths(ref.segs_of(m), q) - L0) > 1e-3):
            return q


def _solve_reference(m, dx, dy, factors=(1.0, 0.75, 0.5)):
    """The brute-force least potential at the largest of ``factors`` x (dx, dy) the closed range reaches."""
    segs, loads = _ref(m)
    for f in factors:
        try:
            return rl.least_potential(segs, loads, dx * f, dy * f), dx * f, dy * f
        except ValueError:
            continue
    pytest.skip("no deflection of the family reachable in the closed range")


# ------------------------------------------------------------------------------------------- the reference itself
@pytest.mark.parametrize("family", FAMILIES[:3])
def test_the_reference_load_points_are_the_bodies_and_its_derivatives_its_differences(family):
    """Self-check of the reference: its vectorised centroids are reference_dynamics' bodies (the mean of each
    triangle's vertices), its joints lie on the links, and the analytic gradient and Hessian of ``E + V - F . tip``
    equal five-point differences of the potential."""
    m, _, _ = _loaded(family, 11, "linear", n=4)
    segs, loads = _ref(m)
    rng = np.random.default_rng(12)
    for _ in range(3):
        q = _inside(m, rng)
        W, X, kinds = rl.load_points(segs, loads, q)
        bodies = rd._bodies(segs, loads["payload"], q)
        np.testing.assert_allclose(X[:len(bodies)], [b[2] for b in bodies], atol=1e-14)
        np.testing.assert_allclose([w for w, k in zip(W, kinds) if k[0] != "joint"],
                                   [np.multiply(b[0], m.gravity) for b in bodies], atol=1e-15)
        P = rl.joints(segs, q)
        np.testing.assert_allclose(P[0], (m.b[0], 0.0), atol=0)
        np.testing.assert_allclose(np.linalg.norm(np.diff(P, axis=0), axis=1), m.link_lengths[:-1], rtol=1e-14)
        np.testing.assert_allclose(rl.gradient(segs, loads, q), rl.gradient_fd(segs, loads, q), rtol=1e-8,
                                   atol=1e-9 * m.torque_scale)
        F = rng.uniform(-0.3, 0.3, 2)
        np.testing.assert_allclose(rl.hessian(segs, loads, q, F), rl.hessian_fd(segs, loads, q, F), rtol=1e-7,
                                   atol=1e-8 * m.torque_scale)


# ------------------------------------------------------------------------------------------- the potential
@pytest.mark.parametrize("spring", LAWS)
@pytest.mark.parametrize("family", FAMILIES)
def test_the_potential_its_gradient_and_the_loads_hessian_are_the_reference(family, spring):
    m, _, _ = _loaded(family, 100 + FAMILIES.index(family), spring, n=4)
    assert m.loaded
    segs, loads = _ref(m)
    rng = np.random.default_rng(7)
    for _ in range(5):
        q = _inside(m, rng)
        scale = m.torque_scale
        assert m.potential_energy(q) == pytest.approx(rl.potential(segs, loads, q), rel=1e-12, abs=1e-12 * scale)
        np.testing.assert_allclose(m.potential_gradient(q), rl.gradient(segs, loads, q), rtol=1e-9,
                                   atol=1e-11 * scale)
        np.testing.assert_allclose(m.load_hessian(q), rl.load_hessian(segs, loads, q), rtol=1e-9,
                                   atol=1e-12 * scale)
        np.testing.assert_allclose(m.load_gradient(q), rl.load_gradient(segs, loads, q), rtol=1e-9,
                                   atol=1e-12 * scale)
        # V = V_0 - sum_j G_j . u_j with the chain's link loads
        psi = np.cumsum(q)
        V = m.load_offset - float(m.link_loads[:, 0] @ np.cos(psi) + m.link_loads[:, 1] @ np.sin(psi))
        assert V == pytest.approx(rl.load_potential(segs, loads, q), rel=1e-12, abs=1e-12 * scale)
        assert m.potential_energy(q) - m.energy(q) == pytest.approx(V, rel=1e-12, abs=1e-12 * scale)


@pytest.mark.parametrize("spring", LAWS)
@pytest.mark.parametrize("family", ("monotonic", "heterogeneous", "asymmetric", "large"))
def test_the_slack_problems_derivatives_are_the_reference(family, spring):
    """``slack_nlp(n, True).derivatives``: the springs' energy E (no loads), grad (E + V),
    Hess (E + V - F . tip), the tip and its Jacobian."""
    m, _, _ = _loaded(family, 200 + FAMILIES.index(family), spring, n=4)
    segs, loads = _ref(m)
    rng = np.random.default_rng(8)
    try:
        nlp = slack_nlp(m.n, m.loaded)                  # the loaded variant carries the loads' terms
    except TypeError:                                   # an earlier signature: one problem for every chain
        nlp = slack_nlp(m.n)
    for _ in range(4):
        q = _inside(m, rng)
        F = rng.uniform(-0.5, 0.5, 2) * m.torque_scale / m.b.sum()
        E, g, H, tip, J = nlp.derivatives(m, q, F)
        scale = m.torque_scale
        assert E == pytest.approx(ref.energy(segs, q), rel=1e-12, abs=1e-13 * scale)
        np.testing.assert_allclose(g, rl.gradient(segs, loads, q), rtol=1e-9, atol=1e-11 * scale)
        np.testing.assert_allclose(H, rl.hessian(segs, loads, q, F), rtol=1e-9, atol=1e-11 * scale)
        np.testing.assert_allclose(tip, ref.tip(segs, q), rtol=0, atol=1e-13)
        np.testing.assert_allclose(J, ref.tip_jacobian(segs, q), rtol=0, atol=1e-13)


def test_the_loaded_slack_problem_is_asked_for_as_its_refusal_says():
    """The unloaded problem refuses a loaded chain naming ``slack_nlp(n, True)``: that call works."""
    m, _, _ = _loaded("monotonic", 210, "linear", n=3)
    with pytest.raises(ValueError, match=r"slack_nlp\(n, True\)"):
        slack_nlp(3).derivatives(m, np.zeros(3), np.zeros(2))
    assert slack_nlp(3, True).loaded


def test_the_loads_of_a_chain_are_its_link_loads_and_say_loaded():
    """One weight and one joint force by hand: the potential of a payload ``mp`` under ``g`` at the tip and of a
    force ``f`` at joint 3 of the straight chain of three unit segments (tip at x = 6, joint 3 at x = 5)."""
    mp, g, f = 0.7, (0.3, -2.0), (0.25, 0.4)
    m = to.Manipulator.uniform(3, payload=mp, gravity=g, joint_forces=((3, f),))
    q = np.zeros(3)
    assert m.loaded
    assert m.potential_energy(q) == pytest.approx(m.energy(q) - (mp * g[0] * 6.0 + f[0] * 5.0), rel=1e-14)
    for quiet in (to.Manipulator.uniform(3, mass=1.0, payload=1.0),
                  to.Manipulator.uniform(3, gravity=(0.0, -9.81)),
                  to.Manipulator.uniform(3, mass=1.0, gravity=(0.0, 0.0), joint_forces=((2, (0.0, 0.0)),))):
        assert not quiet.loaded and np.all(quiet.link_loads == 0.0)


def test_a_force_at_the_fixed_joint_does_no_work_but_keeps_its_constant():
    """Joint 1 is fixed at (b_1, 0): a force there moves nothing (the same gradient and equilibria), and its potential
    ``-f . (b_1, 0)`` is a constant of ``V`` like every load's (``potential_energy`` is ``E + V``, V with its
    constant)."""
    m1 = to.Manipulator.uniform(3, joint_forces=((1, (2.0, 3.0)),))
    q = np.array([0.3, -0.2, 0.1])
    np.testing.assert_array_equal(m1.potential_gradient(q), m1.gradient(q))
    assert m1.load_offset == -2.0
    assert m1.potential_energy(q) == pytest.approx(rl.potential(*_ref(m1), q), rel=1e-14)
    assert m1.potential_energy(q) == pytest.approx(m1.energy(q) - 2.0, rel=1e-14)


@pytest.mark.parametrize("family", FAMILIES)
def test_the_equilibrium_residual_counts_the_loads(family):
    """At the reference's equilibria the library's residual (grad (E + V) = J^T F, tip = target) vanishes; with the
    spring torques alone it does not."""
    m, dx, dy = _loaded(family, 300 + FAMILIES.index(family), "linear", n=3)
    segs, loads = _ref(m)
    best, dx, dy = _solve_reference(m, dx, dy)
    free = ~best.at_stop
    if free.all():
        assert m.equilibrium_residual(best.q, best.force, m.target(dx, dy)) < 1e-9
        assert m.equilibrium_residuals(best.q[None], best.force[None], m.target(dx, dy))[0] < 1e-9
        r_springs = np.abs(m.gradient(best.q) - m.jacobian(best.q).T @ best.force).max() / m.torque_scale
        assert r_springs > 1e-6


# ------------------------------------------------------------------------------------------- the least potential
def _check_least(m, dx, dy, best, rel=1e-8):
    segs, loads = _ref(m)
    eq = to.solve_equilibrium(m, dx, dy)
    scale = max(abs(best.energy), m.torque_scale)
    assert eq.energy == pytest.approx(best.energy, abs=rel * scale), (eq.energy, best.energy, eq.q, best.q)
    assert eq.energy == pytest.approx(rl.potential(segs, loads, eq.q), rel=1e-12, abs=1e-12 * scale)
    assert eq.stable and eq.morse_index == 0
    np.testing.assert_allclose(eq.tip, m.target(dx, dy), atol=1e-9)
    assert np.all(np.abs(eq.q) <= m.joint_limits) and np.all(eq.contact_torques >= 0)
    # the reference's balance at the free joints: grad (E + V) = J^T F
    r = rl.gradient(segs, loads, eq.q) - ref.tip_jacobian(segs, eq.q).T @ eq.force
    assert np.abs(r[~eq.at_stop]).max() < 1e-8 * m.torque_scale
    if best.runner_up_gap > 1e-6 * scale:          # a unique least potential: the same configuration
        np.testing.assert_allclose(eq.q, best.q, atol=1e-6)
        assert eq.at_stop.tolist() == best.at_stop.tolist()
        np.testing.assert_allclose(eq.force, best.force, rtol=1e-6, atol=1e-8 * m.torque_scale / m.b.sum())
        np.testing.assert_allclose(eq.contact_torques, best.contact_torques, rtol=1e-5, atol=1e-8 * m.torque_scale)
    return eq


@pytest.mark.slow_cases(keep=6)
@pytest.mark.parametrize("n", [2, 3])
@pytest.mark.parametrize("spring", LAWS)
@pytest.mark.parametrize("family", FAMILIES)
def test_the_least_potential_equilibrium_is_the_brute_force(family, spring, n):
    m, dx, dy = _loaded(family, 400 + 10 * n + FAMILIES.index(family), spring, n=n)
    best, dx, dy = _solve_reference(m, dx, dy)
    _check_least(m, dx, dy, best)


@pytest.mark.slow_cases(keep=4)
@pytest.mark.parametrize("spring", LAWS)
@pytest.mark.parametrize("family", FAMILIES)
def test_the_least_potential_under_heavy_loads_is_the_brute_force(family, spring):
    """Weights up to 3 k c^2 (joints pressed on their stops; the sagged chain far from its unloaded shape)."""
    m, dx, dy = _loaded(family, 500 + FAMILIES.index(family), spring, n=3, strength=(1.0, 3.0))
    best, dx, dy = _solve_reference(m, dx, dy)
    _check_least(m, dx, dy, best)


@pytest.mark.slow
@pytest.mark.parametrize("spring", LAWS)
@pytest.mark.parametrize("family", FAMILIES)
def test_the_least_potential_of_four_segments_is_the_brute_force(family, spring):
    m, dx, dy = _loaded(family, 600 + FAMILIES.index(family), spring, n=4)
    best, dx, dy = _solve_reference(m, dx, dy)
    _check_least(m, dx, dy, best)


# ------------------------------------------------------------------------------------------- on a stop
#: (seed, n, law) of large deflections under heavy weights whose least potential rests a joint on its stop
ON_STOP = [(1403, 3, "tension_only"), (1421, 3, "linear"), (1505, 3, "linear"), (1427, 4, "tension_only"),
           (1421, 4, "linear"), (1451, 4, "tension_only")]


@pytest.mark.slow_cases(keep=3)
@pytest.mark.parametrize("seed,n,spring", ON_STOP)
def test_a_least_potential_resting_on_a_stop_is_the_brute_force_and_so_are_its_modes(seed, n, spring):
    """The brute force's minimiser rests a joint on its stop (a contact torque > 0): the same stop, contact torque
    and tip force; the modes with the tip and that joint held (n = 4: one mode) are the reference's."""
    m, dx, dy = _loaded("large", seed, spring, n=n, strength=(1.0, 3.0))
    best, dx, dy = _solve_reference(m, dx, dy, factors=(1.0,))
    assert best.at_stop.any() and best.contact_torques[best.at_stop].min() > 1e-3 * m.torque_scale
    eq = _check_least(m, dx, dy, best)
    assert eq.at_stop.tolist() == best.at_stop.tolist()
    if n - 2 - int(eq.at_stop.sum()) > 0:
        md = to.modes(m, eq)
        w = rl.modes(*_ref(m), eq.q, held=True, stops=eq.at_stop)[0]
        assert md.eigenvalues.size == w.size == n - 2 - int(eq.at_stop.sum())
        np.testing.assert_allclose(md.eigenvalues, w, rtol=1e-8, atol=1e-10 * np.abs(w).max())


# ------------------------------------------------------------------------------------------- every equilibrium
def _same_sets(m, dx, dy):
    """find_equilibria (stops included) against the reference enumeration: the same equilibria, Morse indices,
    stops, contact torques and potentials. Configurations with more than n - 2 joints on stops are not looked for
    by either."""
    segs, loads = _ref(m)
    want = rl.equilibria(segs, loads, dx, dy)
    got = to.find_equilibria(m, dx, dy, stops=True)
    report = (len(got), len(want), [(e.q.round(5).tolist(), e.morse_index) for e in got],
              [(r.q.round(5).tolist(), r.morse_index) for r in want])
    assert len(got) == len(want), report
    scale = m.torque_scale
    for e in got:
        d = [float(np.abs(e.q - r.q).max()) for r in want]
        r = want[int(np.argmin(d))]
        assert min(d) < 1e-7 and e.morse_index == r.morse_index, report
        assert e.at_stop.tolist() == (r.stops != 0).tolist()
        np.testing.assert_allclose(e.contact_torques, r.contact_torques, rtol=1e-5, atol=1e-8 * scale)
        np.testing.assert_allclose(e.force, r.F, rtol=1e-6, atol=1e-8 * scale / m.b.sum())
        assert e.energy == pytest.approx(r.energy, rel=1e-10, abs=1e-10 * scale)
    return got, want


@pytest.mark.slow_cases(keep=2)
@pytest.mark.parametrize("spring,family,seed", [
    ("linear", "bistable", 0), ("tension_only", "monotonic", 0), ("linear", "dy", 0), ("tension_only", "large", 0),
    ("linear", "monotonic", 1), ("linear", "heterogeneous", 1), ("linear", "asymmetric", 1), ("linear", "large", 1),
    ("tension_only", "bistable", 1), ("tension_only", "heterogeneous", 1), ("tension_only", "asymmetric", 1),
    ("tension_only", "dy", 1), ("linear", "bistable", 2), ("tension_only", "bistable", 2)])
def test_every_equilibrium_of_three_loaded_segments_is_the_reference(spring, family, seed):
    m, dx, dy = _loaded(family, 700 + 10 * seed + FAMILIES.index(family), spring, n=3)
    try:
        _, dx, dy = _solve_reference(m, dx, dy)
    except ValueError:
        pytest.skip("unreachable")
    got, want = _same_sets(m, dx, dy)
    assert len(want) >= 1


@pytest.mark.slow
@pytest.mark.xfail(strict=True, reason="a known miss of the closed-range search (measured, not certified): a stable "
                                       "equilibrium on one stop 1.7e-3 rad from a second is not reached from its "
                                       "starts, nor from the unloaded chain's set; strict: passes once it is found")
def test_a_stable_equilibrium_on_a_stop_beside_a_second_stop_is_in_the_set():
    """Four tension-only segments, light weights, a large deflection: the reference enumeration (44 equilibria) has a
    stable one with joint 4 on its stop and joint 2 1.7e-3 rad from its own (contact torque 0.30); the search's set
    (43) left it out. The record is rebuilt here by the reference's Newton from its rounded angles."""
    seg = dict(a=0.8353809955980198, b=1.0, k=0.9189654314584862, L0=0.8189919473723692, spring="tension_only")
    masses = [0.6593694971435904, 0.31284885700177956, 0.8839541435949437, 0.14131020204443395]
    m = to.Manipulator([to.Segment(**seg, mass=mi) for mi in masses], payload=0.08016881667982623,
                       gravity=(0.026909418636062693, -0.0011165755393725372))
    dx, dy = 2.5997513366882807, -0.10585941670987992
    M = rl.model(*_ref(m))
    tgt = rl.target(M.segs, dx, dy)
    q0 = np.array([-1.18483, 1.74801, -0.72415, m.joint_limits[3]])
    q, F, ok = rl._newton(M, q0, np.array([0, 1, 2]), tgt)
    assert ok
    r = rl._record(M, q, F, np.array([0, 0, 0, 1]), tgt)
    assert r is not None and r.morse_index == 0 and not r.degenerate and r.contact_torques[3] > 0.3
    got = to.find_equilibria(m, dx, dy)
    assert min(float(np.abs(e.q - r.q).max()) for e in got) < 1e-7, (len(got), r.q)


@pytest.mark.slow
@pytest.mark.parametrize("spring,family", [("linear", "bistable"), ("tension_only", "monotonic"),
                                           ("linear", "dy"), ("tension_only", "asymmetric")])
def test_every_equilibrium_of_four_loaded_segments_is_the_reference(spring, family):
    m, dx, dy = _loaded(family, 800 + FAMILIES.index(family), spring, n=4)
    _, dx, dy = _solve_reference(m, dx, dy)
    _same_sets(m, dx, dy)


def test_the_open_range_set_and_the_default_set_of_a_loaded_linear_chain():
    """A loaded linear chain (three segments, weights and a joint force) with an equilibrium resting on a stop:
    ``stops=False`` gives the reference's members of the open range, the default every member of the closed range
    (as for a tension-only chain)."""
    m = to.Manipulator.uniform(3, mass=0.3, payload=0.2, gravity=(0.0, -1.0), joint_forces=((2, (0.1, 0.05)),))
    want = rl.equilibria(*_ref(m), 0.8, 0.1)
    assert any(r.at_stop.any() for r in want) and not all(r.at_stop.any() for r in want)
    for kw, expect in (({"stops": False}, [r for r in want if not r.at_stop.any()]), ({}, want)):
        got = to.find_equilibria(m, 0.8, 0.1, **kw)
        assert len(got) == len(expect), kw
        for e in got:
            d = [float(np.abs(e.q - r.q).max()) for r in expect]
            r = expect[int(np.argmin(d))]
            assert min(d) < 1e-7 and e.morse_index == r.morse_index and e.at_stop.tolist() == r.at_stop.tolist()


@pytest.mark.parametrize("spring", LAWS)
def test_full_extension_under_a_transverse_load_has_no_equilibrium_by_either_route(spring):
    """dx = dy = 0: only the straight chain reaches the tip, and a transverse weight's torques are not proportional to
    the lever arms, so no tip force balances them (grad (E + V) = J^T F has no solution: the x row of J vanishes).
    find_equilibria says so (an empty set); solve_equilibrium must agree (refuse), not report a configuration off
    straight with an unbounded tip force."""
    m = to.Manipulator.uniform(3, mass=0.5, payload=0.2, gravity=(0.0, -1.0), spring=spring)
    assert len(to.find_equilibria(m, 0.0, 0.0)) == 0
    with pytest.raises((to.StraightNotEquilibriumError, to.NoEquilibriumError)):
        to.solve_equilibrium(m, 0.0, 0.0)


# ------------------------------------------------------------------------------------------- the rest shape
@pytest.mark.slow_cases(keep=3)
@pytest.mark.parametrize("n,spring,family", [
    (2, "linear", "monotonic"), (3, "linear", "bistable"), (3, "tension_only", "asymmetric"),
    (2, "tension_only", "large"), (3, "linear", "heterogeneous"), (3, "tension_only", "monotonic"),
    (3, "linear", "dy"), (3, "tension_only", "bistable")])
def test_the_rest_configuration_is_the_free_tip_brute_force(n, spring, family):
    """The sagged shape: the least E + V over the closed range with a free tip (no tip force)."""
    m, _, _ = _loaded(family, 900 + FAMILIES.index(family), spring, n=n)
    segs, loads = _ref(m)
    best = rl.least_potential_free(segs, loads)
    rest = to.rest_configuration(m)
    scale = max(abs(best.energy), m.torque_scale)
    assert rest.energy == pytest.approx(best.energy, abs=1e-8 * scale), (rest.q, best.q)
    np.testing.assert_array_equal(rest.force, 0.0)
    assert rest.stable
    if best.runner_up_gap > 1e-6 * scale:
        np.testing.assert_allclose(rest.q, best.q, atol=1e-6)
        assert rest.at_stop.tolist() == best.at_stop.tolist()
        np.testing.assert_allclose(rest.contact_torques, best.contact_torques, rtol=1e-5,
                                   atol=1e-8 * m.torque_scale)


@pytest.mark.slow_cases(keep=2)
@pytest.mark.parametrize("seed,n,family,spring", [
    (1603, 3, "bistable", "tension_only"), (1610, 3, "heterogeneous", "linear"),
    (1627, 3, "bistable", "tension_only"), (1640, 2, "heterogeneous", "tension_only"),
    (1620, 3, "monotonic", "linear")])
def test_a_chain_sagging_onto_its_stops_rests_where_the_brute_force_does(seed, n, family, spring):
    """Weights of 2-5 k c^2 press joints onto their stops in the rest shape (a contact torque > 0 each)."""
    m, _, _ = _loaded(family, seed, spring, n=n, strength=(2.0, 5.0))
    best = rl.least_potential_free(*_ref(m))
    assert best.at_stop.any()
    rest = to.rest_configuration(m)
    scale = max(abs(best.energy), m.torque_scale)
    assert rest.energy == pytest.approx(best.energy, abs=1e-8 * scale), (rest.q, best.q)
    assert rest.at_stop.tolist() == best.at_stop.tolist()
    np.testing.assert_allclose(rest.q, best.q, atol=1e-6)
    np.testing.assert_allclose(rest.contact_torques, best.contact_torques, rtol=1e-5, atol=1e-8 * m.torque_scale)


# ------------------------------------------------------------------------------------------- modes
@pytest.mark.slow_cases(keep=4)
@pytest.mark.parametrize("spring", LAWS)
@pytest.mark.parametrize("family", FAMILIES)
def test_the_modes_under_gravity_are_the_reference(family, spring):
    """The modes of the least-potential equilibrium (tip held; a joint on its stop held too): K the Hessian of
    E + V - F . tip on the allowed motions, M the reference's mass matrix."""
    m, dx, dy = _loaded(family, 1000 + FAMILIES.index(family), spring, n=4)
    eq = to.solve_equilibrium(m, dx, dy)
    md = to.modes(m, eq)
    segs, loads = _ref(m)
    w, Z, M, K = rl.modes(segs, loads, eq.q, held=True, stops=eq.at_stop)
    assert md.eigenvalues.size == w.size
    np.testing.assert_allclose(md.eigenvalues, w, rtol=1e-8, atol=1e-10 * np.abs(w).max(initial=1.0))
    if md.status == "solved":
        np.testing.assert_allclose(md.frequencies, np.sqrt(w), rtol=1e-8)
    # the loads change the stiffness: the unloaded Hessian would not give these
    w0 = rd.frequencies(segs, loads["payload"], eq.q, held=True, stops=eq.at_stop)[0]
    assert not np.allclose(w0, w, rtol=1e-6)


@pytest.mark.parametrize("family", ("monotonic", "heterogeneous", "asymmetric"))
def test_the_modes_of_a_loaded_tip_under_gravity_are_the_reference(family):
    """Posed by a tip force: every free joint moves, K the full Hessian of E + V - F . tip; the equilibrium balances
    the reference's torques and loads (contact torques >= 0 at the stops)."""
    m, _, _ = _loaded(family, 1100 + FAMILIES.index(family), "linear", n=3, strength=(0.05, 0.2))
    eq = to.solve_equilibrium_under_force(m, -0.01 * m.torque_scale, 0.02 * m.torque_scale)
    segs, loads = _ref(m)
    r = rl.gradient(segs, loads, eq.q) - ref.tip_jacobian(segs, eq.q).T @ eq.force
    assert np.abs(r[~eq.at_stop]).max(initial=0.0) < 1e-8 * m.torque_scale
    side = np.sign(eq.q) * eq.at_stop
    assert np.all(-side * r >= -1e-8 * m.torque_scale)
    md = to.modes(m, eq)
    w, _, _, _ = rl.modes(segs, loads, eq.q, held=False, stops=eq.at_stop, F=eq.force)
    assert md.tip == "loaded" and w.size == (~eq.at_stop).sum() > 0
    np.testing.assert_allclose(md.eigenvalues, w, rtol=1e-8, atol=1e-10 * np.abs(w).max())


# ------------------------------------------------------------------------------------------- no load, no change
@pytest.mark.slow_cases(keep=3)
@pytest.mark.parametrize("spring", LAWS)
@pytest.mark.parametrize("family", ("monotonic", "bistable", "dy", "large"))
def test_masses_without_gravity_or_gravity_without_masses_change_nothing(family, spring):
    """A chain with masses but no gravity, with gravity but no mass, with zero joint forces: the unloaded chain's
    numbers to the last bit."""
    rng = np.random.default_rng(1200 + FAMILIES.index(family))
    geo, dx, dy = _geometry(family, rng, 3)
    bare = to.Manipulator([to.Segment(**g, spring=spring) for g in geo])
    massive = to.Manipulator([to.Segment(**g, spring=spring, mass=0.7, inertia=0.02) for g in geo], payload=0.3)
    variants = (massive, to.Manipulator(bare.segments, gravity=(0.3, -9.81)),
                to.Manipulator(massive.segments, payload=0.3, gravity=(0.0, 0.0), joint_forces=((2, (0.0, 0.0)),)))
    try:
        base = to.solve_equilibrium(bare, dx, dy)
    except to.UnreachableTargetError:
        pytest.skip("unreachable")
    q = base.q
    for m in variants:
        assert not m.loaded
        assert m.potential_energy(q) == bare.energy(q)
        np.testing.assert_array_equal(m.potential_gradient(q), bare.gradient(q))
        eq = to.solve_equilibrium(m, dx, dy)
        np.testing.assert_array_equal(eq.q, base.q)
        assert eq.energy == base.energy
        np.testing.assert_array_equal(eq.force, base.force)
        np.testing.assert_array_equal(eq.at_stop, base.at_stop)


def test_a_tiny_load_changes_the_answer_a_little():
    """Continuity: gravity 1e-9 moves the least-potential equilibrium by ~1e-9 (the loaded route agrees with the
    unloaded one as the load vanishes)."""
    m0 = to.Manipulator.uniform(3, mass=0.5)
    m1 = to.Manipulator(m0.segments, gravity=(0.0, -1e-9))
    e0, e1 = to.solve_equilibrium(m0, 0.6, 0.1), to.solve_equilibrium(m1, 0.6, 0.1)
    np.testing.assert_allclose(e1.q, e0.q, atol=1e-7)
    assert e1.energy == pytest.approx(e0.energy + rl.load_potential(*_ref(m1), e0.q), rel=1e-9)


def test_the_mirror_image_under_reflected_loads_is_the_reflected_answer():
    """``mirrored()`` reflects the loads in the x axis: its least-potential equilibrium at ``-dy`` is ``-q``."""
    m, dx, dy = _loaded("asymmetric", 1300, "linear", n=3)
    eq, mir = to.solve_equilibrium(m, dx, dy), to.solve_equilibrium(m.mirrored(), dx, -dy)
    np.testing.assert_allclose(mir.q, -eq.q, atol=1e-8)
    assert mir.energy == pytest.approx(eq.energy, rel=1e-10)
    np.testing.assert_allclose(mir.force, eq.force * (1, -1), atol=1e-8)
