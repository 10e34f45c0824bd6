"""The spring law and the spring state (issue "the arm as built").

Expected numbers come from the independent reference ``tests/support/reference_tension_only.py`` (spring lengths
from the triangles' vertices, torques from the spring force vectors, the least energy by a dense brute force over
the closed joint range polished by SLSQP), never from the code under test; the paper's chain's figures at dx = 2
(4.86014 tension-only with joint 3 on its stop, 5.18323 linear) are the issue's own brute-force figures.
"""

from __future__ import annotations

import json
import math
import os

import numpy as np
import pytest
import reference_tension_only as ref

import tensegrity_opt as to
from tensegrity_opt.errors import InvalidParameterError, UnsupportedError
from tensegrity_opt.numerics.homotopy import homotopy_available


# ------------------------------------------------------------------------------------------- random chains
def _chain(family: str, rng: np.random.Generator, spring: str = "linear", n: int | None = None):
    """A random chain of one family and a deflection (dx, dy) for it."""
    u = lambda lo, hi: float(rng.uniform(lo, hi))  # noqa: E731
    n = int(rng.integers(2, 5)) if n is None else n
    if family == "monotonic":
        return to.Manipulator.uniform(n, a=u(0.8, 1.2), b=1.0, k=u(0.5, 2.0), L0=u(0.8, 1.2), spring=spring), \
            u(0.05, 0.6) * n / 4, 0.0
    if family == "bistable":
        return to.Manipulator.uniform(n, a=0.5, b=1.0, k=u(0.5, 2.0), L0=u(0.4, 0.6), spring=spring), \
            u(0.1, 0.6) * n / 4, 0.0
    if family == "heterogeneous":
        segs = [to.Segment(u(0.6, 1.4), u(0.6, 1.4), u(0.5, 2.0), u(0.7, 1.3), spring) for _ in range(n)]
        m = to.Manipulator(segs)
        return m, u(0.05, 0.3) * m.straight_length / 4, 0.0
    if family == "asymmetric":
        return to.Manipulator.uniform(n, a=1.0, b=1.0, k=(u(0.8, 1.2), u(1.2, 1.8)), L0=(u(0.9, 1.1), u(0.7, 0.95)),
                                      spring=spring), u(0.1, 0.5) * n / 4, 0.0
    if family == "dy":
        return to.Manipulator.uniform(n, a=1.0, b=1.0, k=u(0.5, 2.0), L0=1.0, spring=spring), u(0.1, 0.5) * n / 4, \
            u(-0.4, 0.4) * n / 4
    if family == "large":                      # large deflections: springs go slack or push
        return to.Manipulator.uniform(n, a=u(0.8, 1.2), b=1.0, k=u(0.5, 2.0), L0=u(0.8, 1.4), spring=spring), \
            u(0.25, 0.4) * 2.0 * n, u(-0.3, 0.3)
    raise AssertionError(family)


FAMILIES = ("monotonic", "bistable", "heterogeneous", "asymmetric", "dy", "large")


# ------------------------------------------------------------------------------------------- the spring state
@pytest.mark.parametrize("family", FAMILIES)
@pytest.mark.parametrize("seed", [0, 1])
def test_the_spring_state_of_an_equilibrium_is_the_reference_geometry(family, seed):
    """Linear law: lengths from the triangles' vertices, forces k (L - L0) (negative: pushing), the states."""
    m, dx, dy = _chain(family, np.random.default_rng(seed))
    eq = to.solve_equilibrium(m, dx, dy)
    segs = ref.segs_of(m)
    L = ref.lengths(segs, eq.q)
    L0 = np.array([[s.L1_0, s.L2_0] for s in m.segments])
    k = np.array([[s.k1, s.k2] for s in m.segments])
    np.testing.assert_allclose(eq.spring_lengths, L, rtol=0, atol=1e-12)
    np.testing.assert_allclose(eq.spring_stretches, L - L0, rtol=0, atol=1e-12)
    np.testing.assert_allclose(eq.spring_forces, k * (L - L0), rtol=0, atol=1e-12)
    np.testing.assert_array_equal(eq.spring_states, np.where(L - L0 < -1e-9 * L0, "pushing", "taut"))
    d = eq.to_dict()
    assert d["spring_forces"] == eq.spring_forces.tolist() and d["spring_states"] == eq.spring_states.tolist()
    json.dumps(d, allow_nan=False)


def test_the_paper_chain_past_its_first_rest_length_pushes_and_says_so():
    """The issue's figures: past dx ~ 1.097 a spring is shorter than its rest length (0.217, 0.469, 0.945 at
    dx = 1.5, 2, 3; two springs at dx = 3)."""
    m = to.Manipulator.uniform(4)
    short = {}
    for dx in (1.0, 1.5, 2.0, 3.0):
        eq = to.solve_equilibrium(m, dx)
        s = eq.spring_stretches
        short[dx] = sorted((-s[s < 0]).round(3).tolist(), reverse=True)
        assert (eq.spring_states == "pushing").sum() == (s < 0).sum()
    assert short[1.0] == [] and short[1.5] == [0.217] and short[2.0] == [0.469] and short[3.0][0] == 0.945
    assert len(short[3.0]) == 2


def test_series_results_carry_one_spring_state_per_point():
    m = to.Manipulator.uniform(3)
    c = to.force_deflection(m, np.linspace(0.2, 1.5, 4))
    segs = ref.segs_of(m)
    for i, pt in enumerate(c.to_dict()["points"]):
        np.testing.assert_allclose(pt["spring_lengths"], ref.lengths(segs, c.q[i]), atol=1e-12)
    br = to.trace_branch(m, to.solve_equilibrium(m, 0.2), to.Control.displacement(), t_max=0.6)
    assert br.spring_forces.shape == (len(br), 3, 2)
    np.testing.assert_allclose(br.spring_forces[-1], ref.forces(segs, br.q[-1]), atol=1e-12)
    # a preload move: each point under its own rest lengths
    P0 = np.column_stack([m.L1_0, m.L2_0])
    plan = to.plan_preloads(m, [[5.5, 0.3], [5.4, 0.6]])
    for s, cmd in zip(plan.steps, plan.commands):
        mk = to.Manipulator(sg.replace(L0=tuple(c)) for sg, c in zip(m.segments, cmd))
        np.testing.assert_allclose(s.spring_forces, ref.forces(ref.segs_of(mk), s.q), atol=1e-12)
    np.testing.assert_allclose(plan.spring_forces[0], plan.steps[0].spring_forces, atol=0)
    assert not np.allclose(plan.commands[-1], P0)


# ------------------------------------------------------------------------------------------- the law itself
def test_a_spring_law_is_named_once_and_refused_by_name():
    assert to.Segment(1, 1).spring == "linear"
    with pytest.raises(InvalidParameterError) as e:
        to.Segment(1, 1, spring="tension")
    assert e.value.field == "spring" and "tension_only" in str(e.value)
    with pytest.raises(InvalidParameterError):
        to.Manipulator.uniform(3, spring=1)
    m = to.Manipulator([to.Segment(1, 1), to.Segment(1, 1, spring="tension_only")])
    d = m.to_dict()
    assert "spring" not in d["segments"][0] and d["segments"][1]["spring"] == "tension_only"
    assert to.Manipulator.from_dict(d) == m
    assert to.Manipulator.from_dict({"n": 2, "spring": "tension_only"}).segments[1].spring == "tension_only"
    assert m.with_spring("linear").linear_springs and not m.linear_springs


@pytest.mark.parametrize("seed", range(4))
def test_the_tension_only_model_equals_the_reference(seed):
    """Energy, joint torques and joint stiffness of random tension-only chains at random angles (springs slack
    and taut), against the reference's vertex geometry, force vectors and finite differences."""
    rng = np.random.default_rng(seed)
    segs = [to.Segment(rng.uniform(0.5, 1.5), rng.uniform(0.5, 1.5), (rng.uniform(0.5, 2), rng.uniform(0.5, 2)),
                       (rng.uniform(0.6, 2.2), rng.uniform(0.6, 2.2)), "tension_only") for _ in range(4)]
    m = to.Manipulator(segs)
    rs = ref.segs_of(m)
    slack_seen = 0
    for _ in range(40):
        q = rng.uniform(-0.97, 0.97) * m.joint_limits
        L = ref.lengths(rs, q)
        L0 = np.array([[s.L1_0, s.L2_0] for s in segs])
        if np.any(np.abs(L - L0) < 1e-4):      # not on a kink (the finite differences)
            continue
        slack_seen += int(np.sum(L < L0))
        assert m.energy(q) == pytest.approx(ref.energy(rs, q), rel=1e-12, abs=1e-14)
        np.testing.assert_allclose(m.torques(q), ref.torques(rs, q), rtol=1e-10, atol=1e-12)
        np.testing.assert_allclose(m.springs.forces(q), ref.forces(rs, q), rtol=1e-12, atol=1e-14)
        stiff = np.array([-s.dtorque(qi) for s, qi in zip(segs, q)])
        np.testing.assert_allclose(stiff, ref.stiffness(rs, q), rtol=1e-5, atol=1e-6)
    assert slack_seen > 0


# ------------------------------------------------------------------------------------------- the least energy
def test_the_paper_chain_under_both_laws():
    """The issue's brute-force figures: tension-only 4.86014 at dx = 2 with joint 3 on its stop (q3 = -pi/2, its
    mirror +pi/2), linear 5.18323 (no answer of the linear law touches a stop)."""
    lin = to.solve_equilibrium(to.Manipulator.uniform(4), 2.0)
    assert lin.energy == pytest.approx(5.18323, abs=1e-5) and not lin.at_stop.any()
    assert lin.contact_torques.tolist() == [0.0] * 4
    eq = to.solve_equilibrium(to.Manipulator.uniform(4, spring="tension_only"), 2.0)
    assert eq.energy == pytest.approx(4.86014, abs=1e-5)
    assert eq.at_stop.tolist() == [False, False, True, False] and abs(eq.q[2]) == math.pi / 2
    assert eq.contact_torques[2] > 0.1 and eq.stable and eq.morse_index == 0
    assert (eq.spring_states == "slack").sum() == 1 and not (eq.spring_states == "pushing").any()
    d = eq.to_dict()
    assert d["at_stop"] == [False, False, True, False] and d["contact_torques"][2] == eq.contact_torques[2]


@pytest.mark.parametrize("dx", [3.3, 4.0])
def test_under_the_linear_law_too_the_arm_rests_on_a_stop_where_it_reaches_one(dx):
    """The paper's chain pressed past dx ~ 3.1: the least-energy configuration of the closed range rests joint 3 on
    its stop (the linear law's pushing spring is at zero length there), as the brute force finds."""
    m = to.Manipulator.uniform(4)
    eq, best = to.solve_equilibrium(m, dx), ref.least_energy(ref.segs_of(m), dx, 0.0)
    assert eq.at_stop.tolist() == best.at_stop.tolist() == [False, False, True, False]
    assert eq.energy == pytest.approx(best.energy, rel=1e-10)
    np.testing.assert_allclose(eq.contact_torques, best.contact_torques, rtol=1e-6, atol=1e-9)
    assert eq.spring_lengths[2].min() == pytest.approx(0.0, abs=1e-12)    # the spring at the stop has no length


@pytest.mark.parametrize("family", FAMILIES)
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_the_least_energy_of_a_tension_only_chain_equals_the_brute_force(family, seed):
    """Random tension-only chains of every family (n = 2, 3, 4), deflected far enough that springs go slack (the
    largest of 3x, 2x, 1.5x, 1x the family's deflection the closed range reaches)."""
    n = (3, 2, 4)[seed]
    m, dx0, dy0 = _chain(family, np.random.default_rng(100 + seed), "tension_only", n=n)
    segs = ref.segs_of(m)
    best = None
    for factor in (3.0, 2.0, 1.5, 1.0):
        dx, dy = dx0 * factor, dy0 * factor
        try:
            best = ref.least_energy(segs, dx, dy)
            break
        except ValueError:                     # out of reach in the closed range: a smaller deflection
            with pytest.raises(to.UnreachableTargetError):
                to.solve_equilibrium(m, dx, dy)
    if best is None:
        return                                 # every deflection out of reach: each refused as unreachable
    eq = to.solve_equilibrium(m, dx, dy)
    assert eq.energy == pytest.approx(best.energy, rel=1e-7, abs=1e-9)
    assert eq.stable and eq.energy == pytest.approx(ref.energy(segs, eq.q), rel=1e-12, abs=1e-12)
    np.testing.assert_allclose(eq.tip, m.target(dx, dy), atol=1e-9)
    assert np.all(np.abs(eq.q) <= m.joint_limits) and np.all(eq.contact_torques >= 0)
    if eq.at_stop.any() or best.at_stop.any():
        # the same stops, the same contact torques (the configuration is the brute force's up to its polish)
        assert eq.at_stop.tolist() == best.at_stop.tolist()
        np.testing.assert_allclose(eq.contact_torques, best.contact_torques, rtol=1e-4, atol=1e-6)
    # the forces balance at the free joints in the reference model
    r = ref.torques(segs, eq.q) + ref.tip_jacobian(segs, eq.q).T @ eq.force
    assert np.abs(r[~eq.at_stop]).max() < 1e-8 * m.torque_scale


# ------------------------------------------------------------------------------------------- refusals
def _calls(m, lin_eq, P):
    return {
        "find_equilibria_under_force": lambda: to.find_equilibria_under_force(m, -0.1, 0.0),
        "solve_equilibria_batch": lambda: to.solve_equilibria_batch(m, [0.1, 0.2]),
        "Tracker": lambda: to.Tracker(m),
        "force_deflection (branch all)": lambda: to.force_deflection(m, [0.1, 0.2], branch="all"),
        "force_deflection (from rest)": lambda: to.force_deflection(m, [0.1, 0.2], reference="rest"),
        "bifurcation_diagram": lambda: to.bifurcation_diagram(m, lin_eq, to.Control.displacement(), t_max=0.1),
        "imperfection_sensitivity": lambda: to.imperfection_sensitivity(m, [0.01, 0.02]),
        "stability_boundary": lambda: to.stability_boundary(m, "displacement", "k"),
        "maximize_critical_force": lambda: to.maximize_critical_force(m),
        "preloads_for_pose": lambda: to.preloads_for_pose(m, (5.5, 0.3)),
        "preloads_for_stiffness": lambda: to.preloads_for_stiffness(m, (5.5, 0.3), K_desired=np.eye(2)),
        "plan_preloads": lambda: to.plan_preloads(m, [[5.5, 0.3]]),
        "PreloadController": lambda: to.PreloadController(m),
        "load_capacity": lambda: to.load_capacity(m),
        "estimate_tip_force": lambda: to.estimate_tip_force(m, lin_eq.q),
        "critical_load_sensitivity": lambda: to.critical_load_sensitivity(m),
        "equilibrium_sensitivity": lambda: to.equilibrium_sensitivity(m, 0.3),
    }


def test_every_analysis_honours_the_tension_only_law_or_refuses_it_by_name():
    """No analysis answers for the linear law when a segment is tension-only: each one not yet honouring it
    refuses naming the first such segment's spring (the second segment here)."""
    m = to.Manipulator([to.Segment(1, 1), to.Segment(1, 1, spring="tension_only"), to.Segment(1, 1)])
    lin = m.with_spring("linear")
    lin_eq = to.solve_equilibrium(lin, 0.3)
    P = np.column_stack([lin.L1_0, lin.L2_0])
    for name, call in _calls(m, lin_eq, P).items():
        with pytest.raises(UnsupportedError) as e:
            call()
        want = {"preloads_for_pose": "taut", "plan_preloads": "taut", "PreloadController": "taut",
                "force_deflection (branch all)": "branch"}
        assert e.value.field == want.get(name, "segments[1].spring"), name
    # honoured: the least energy, buckling of springs taut when straight, the landscape, the spring state
    eq = to.solve_equilibrium(m, 0.3)
    assert eq.stable and eq.energy == pytest.approx(lin_eq.energy, rel=1e-9)   # every spring taut here
    assert to.critical_force(m).force == pytest.approx(to.critical_force(lin).force, rel=1e-12)
    m4 = to.Manipulator.uniform(4, spring="tension_only")
    land = to.energy_landscape(m4, 2.0, grid=5)
    finite = np.isfinite(land.energy)
    E = np.array([ref.energy(ref.segs_of(m4), q) for q in land.q[finite]])
    np.testing.assert_allclose(land.energy[finite], E, rtol=1e-12)


def test_buckling_refuses_a_spring_slack_at_the_straight_chain():
    m = to.Manipulator([to.Segment(1, 1, L0=1.0, spring="tension_only"), to.Segment(1, 1, L0=2.5,
                                                                                   spring="tension_only")])
    with pytest.raises(UnsupportedError) as e:
        to.critical_force(m, "free")
    assert e.value.field == "segments[1].spring"


def test_a_rigid_configuration_on_two_stops_is_found():
    """Two joints on their stops and the tip fixing the two others: the least energy (an independent brute force's)
    that random samples projected onto the tip seldom reach (a regression: the search returned 7.6118 here)."""
    m = to.Manipulator.uniform(4, a=0.9209530102308371, k=1.579145451463046, L0=1.135520437554391,
                               spring="tension_only")
    dx, dy = 7.843795235504559, 0.07794324677667466
    best = ref.least_energy(ref.segs_of(m), dx, dy)
    eq = to.solve_equilibrium(m, dx, dy)
    assert best.at_stop.tolist() == [False, True, True, False]
    assert eq.energy == pytest.approx(best.energy, rel=1e-9) and eq.at_stop.tolist() == best.at_stop.tolist()


@pytest.mark.slow
@pytest.mark.parametrize("seed", range(8))
def test_many_random_tension_only_chains_equal_the_brute_force(seed):
    """Large deflections (2x to 4x each family's), every family, n = 2..4: springs slack, joints on stops."""
    rng = np.random.default_rng(5000 + seed)
    for family in FAMILIES:
        m, dx0, dy0 = _chain(family, rng, "tension_only", n=int(rng.integers(2, 5)))
        f = float(rng.uniform(2.0, 4.0))
        try:
            best = ref.least_energy(ref.segs_of(m), dx0 * f, dy0 * f)
        except ValueError:
            with pytest.raises(to.UnreachableTargetError):
                to.solve_equilibrium(m, dx0 * f, dy0 * f)
            continue
        eq = to.solve_equilibrium(m, dx0 * f, dy0 * f)
        assert eq.energy == pytest.approx(best.energy, rel=1e-7, abs=1e-9), (family, m.n)


def test_the_cartesian_stiffness_of_a_tension_only_equilibrium_on_a_stop_is_the_brute_force_derivative():
    """dF/d(tip) at the paper's chain's tension-only equilibrium at (dx, dy) = (2, 0.2) (joint 3 on its stop, no mirror
    tie): central differences of the brute force's tip force (the reference, h = 1e-4) against the library's held
    KKT system."""
    m = to.Manipulator.uniform(4, spring="tension_only")
    eq = to.solve_equilibrium(m, 2.0, 0.2)
    assert eq.at_stop.any()
    K = to.cartesian_stiffness(m, eq)
    segs, h = ref.segs_of(m), 1e-4
    dFdx = (ref.least_energy(segs, 2.0 - h, 0.2).force - ref.least_energy(segs, 2.0 + h, 0.2).force) / (2 * h)
    dFdy = (ref.least_energy(segs, 2.0, 0.2 + h).force - ref.least_energy(segs, 2.0, 0.2 - h).force) / (2 * h)
    np.testing.assert_allclose(K, np.column_stack([dFdx, dFdy]), rtol=1e-4, atol=1e-6)
    lin = to.Manipulator.uniform(4)                  # the laws agree where every spring is taut: the same stiffness
    e = to.solve_equilibrium(lin, 0.5)
    np.testing.assert_allclose(to.cartesian_stiffness(lin.with_spring("tension_only"), e),
                               to.cartesian_stiffness(lin, e), rtol=1e-10, atol=1e-12)


# ------------------------------------------------------------------------------------------- every equilibrium
def _same_sets(m, dx, dy, method="search", status="searched", **kw):
    """find_equilibria of a tension-only chain against the independent enumeration (the constraint manifold on dense
    grids, every stop set, both elbows: ``tests/support/reference_equilibria_tension.py``): the same equilibria, the
    same Morse indices, the same stops. Configurations with more than n - 2 joints on stops (met only by coincidence;
    the tip force is not determined there) are not looked for by the library and left out."""
    import reference_equilibria_tension as reqs

    want = [r for r in reqs.equilibria(ref.segs_of(m), dx, dy) if np.abs(r.stops).sum() <= m.n - 2]
    got = to.find_equilibria(m, dx, dy, method=method, **kw)
    assert got.status == status and len(got) == len(want), (got.status, len(got), len(want), got.message)
    for e in got:
        d = [float(np.abs(e.q - r.q).max()) for r in want]
        r = want[int(np.argmin(d))]
        assert min(d) < 1e-7 and e.morse_index == r.morse_index
        assert e.at_stop.tolist() == (r.stops != 0).tolist()
        np.testing.assert_allclose(e.contact_torques, r.contact_torques, rtol=1e-5, atol=1e-8)
        assert e.energy == pytest.approx(r.energy, rel=1e-10)
    return got


@pytest.mark.parametrize("dx", [1.5, 2.0])
def test_every_equilibrium_of_a_tension_only_chain_of_three(dx):
    got = _same_sets(to.Manipulator.uniform(3, spring="tension_only"), dx, 0.0)
    assert any(e.at_stop.any() for e in got) and any(e.morse_index == 1 for e in got)


@pytest.mark.parametrize("family", FAMILIES)
def test_every_equilibrium_of_random_tension_only_chains_of_three(family):
    m, dx, dy = _chain(family, np.random.default_rng(7100), "tension_only", n=3)
    _same_sets(m, 2.0 * dx, 2.0 * dy)


@pytest.mark.slow
@pytest.mark.parametrize("dx", [1.0, 1.5, 2.0, 3.0])
def test_every_equilibrium_of_the_paper_chain_under_the_tension_only_law(dx):
    """Up to 34 equilibria (22 on a stop at dx = 2), each with its Morse index."""
    _same_sets(to.Manipulator.uniform(4, spring="tension_only"), dx, 0.0)


# ------------------------------------------------------------------------------------------- curves
def _curve_is_the_brute_force(m, dxs, dy):
    """Every point of the tension-only curve is the least energy of the independent brute force there (energy, tip
    force on the free joints, the stops), and the spring state is the reference geometry's."""
    c = to.force_deflection(m, dxs, dy)
    assert c.status == "complete" and len(c.dx) == len(dxs)
    segs = ref.segs_of(m)
    for j, dx in enumerate(dxs):
        if dx == 0.0 and dy == 0.0:
            continue
        best = ref.least_energy(segs, dx, dy)
        assert c.energy[j] == pytest.approx(best.energy, rel=1e-9, abs=1e-12), (dx, c.energy[j], best.energy)
        assert c.stable[j] and c.point_status[j] == "converged"
        if float(np.abs(c.q[j] - best.q).max()) < 1e-5:     # the same configuration (not a tie's mirror image)
            np.testing.assert_allclose([c.fx[j], c.fy[j]], best.force, rtol=1e-5, atol=1e-7 * m.torque_scale)
        np.testing.assert_allclose(c.spring_forces[j], ref.forces(segs, c.q[j]), rtol=0, atol=1e-10 * m.torque_scale)
    return c


def test_the_force_deflection_curve_of_the_paper_chain_under_the_tension_only_law():
    """The README's curve past dx ~ 1.1: the least energy at every point is the brute force's; the tip force
    softens where spring 3.2 goes slack, then the stop takes the load."""
    m = to.Manipulator.uniform(4, spring="tension_only")
    c = _curve_is_the_brute_force(m, np.array([0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0]), 0.0)
    lin = to.force_deflection(m.with_spring("linear"), c.dx)
    np.testing.assert_allclose(c.fx[:3], lin.fx[:3], rtol=1e-8)                  # every spring taut: the same
    assert abs(c.fx[4]) < 0.5 * abs(lin.fx[4])                                    # slack: much softer at dx = 2
    assert (c.spring_states[4] == "slack").sum() >= 1 and c.jumps[0].kind == "buckling"


@pytest.mark.slow          # ~1 s each (the brute force at every point), heterogeneous ~20 s
@pytest.mark.parametrize("family", FAMILIES)
def test_the_force_deflection_curves_of_random_tension_only_chains(family):
    m, dx, dy = _chain(family, np.random.default_rng(9100), "tension_only", n=3)
    top = 1.0 if family == "large" else 2.0          # "large" is deflected far already (springs slack, stops)
    _curve_is_the_brute_force(m, np.linspace(0.25, 1.0, 4) * top * dx, dy + 0.05)


# ------------------------------------------------------------------------------------------- force control
def _is_a_local_minimum_of_the_reference(m, eq):
    """``eq`` (force control) is a strict local minimum of the reference potential ``E - F . tip`` over the closed
    range: its free joints balance (reference torques), its stops push (contact >= 0), and SLSQP on the reference
    potential from nearby starts (bounds: the closed range) comes back to it."""
    import scipy.optimize as so

    segs = ref.segs_of(m)
    F = eq.force
    r = ref.torques(segs, eq.q) + ref.tip_jacobian(segs, eq.q).T @ F
    assert np.abs(r[~eq.at_stop]).max(initial=0.0) < 1e-8 * m.torque_scale
    side = np.sign(eq.q)
    assert np.all(side[eq.at_stop] * r[eq.at_stop] >= -1e-9 * m.torque_scale)        # the stop pushes back
    np.testing.assert_allclose(eq.contact_torques[eq.at_stop], (side * r)[eq.at_stop], rtol=1e-6, atol=1e-9)
    lim = ref.limits(segs)

    def V(q):
        return ref.energy(segs, q) - F @ ref.tip(segs, q)

    rng = np.random.default_rng(1)
    for _ in range(4):
        q0 = np.clip(eq.q + rng.normal(0.0, 0.02, m.n), -lim, lim)
        res = so.minimize(V, q0, method="L-BFGS-B", bounds=list(zip(-lim, lim)),
                          options={"ftol": 1e-15, "gtol": 1e-11, "maxiter": 2000})
        assert float(np.abs(res.x - eq.q).max()) < 1e-4, (res.x, eq.q)
        assert V(eq.q) <= res.fun + 1e-10 * m.torque_scale


@pytest.mark.parametrize("family", FAMILIES)
@pytest.mark.parametrize("load", [(-0.3, 0.0), (-0.8, 0.1), (0.4, -0.3)])
def test_force_control_of_tension_only_chains_is_a_local_minimum_of_the_reference(family, load):
    m, _, _ = _chain(family, np.random.default_rng(9500), "tension_only", n=3)
    fx, fy = (v * m.torque_scale / float(m.b.mean()) for v in load)
    try:
        eq = to.solve_equilibrium_under_force(m, fx, fy)
    except UnsupportedError as e:                 # a free joint left undetermined: said by name
        assert e.field.startswith("segments[") and e.status == "free_joint"
        return
    assert eq.control == "force" and eq.stable
    _is_a_local_minimum_of_the_reference(m, eq)


def test_force_control_of_the_paper_chain_rests_on_a_stop_where_the_linear_law_has_none():
    m = to.Manipulator.uniform(4, spring="tension_only")
    eq = to.solve_equilibrium_under_force(m, -0.6, 0.05)
    assert eq.at_stop[0] and eq.contact_torques[0] > 0 and (eq.spring_states == "slack").any()
    _is_a_local_minimum_of_the_reference(m, eq)
    with pytest.raises(to.NoEquilibriumError):
        to.solve_equilibrium_under_force(m.with_spring("linear"), -0.6, 0.05)


# ------------------------------------------------------------------------------------------- rest configuration
@pytest.mark.parametrize("family", FAMILIES)
def test_the_rest_configuration_of_a_tension_only_chain_is_each_segments_least_energy(family):
    """F = 0: E is a sum of one-joint energies, so the least rest energy is the sum of each segment's least energy
    over its closed range (the reference's, on a dense grid polished), each joint at a minimiser of its own energy,
    a joint on a stop pushed back by it."""
    m, _, _ = _chain(family, np.random.default_rng(9700), "tension_only", n=3)
    segs = ref.segs_of(m)
    try:
        r = to.rest_configuration(m)
    except UnsupportedError as e:           # a segment with both springs slack over part of its range: said by name
        assert e.status == "free_joint" and e.field.startswith("segments[")
        return
    import scipy.optimize as so

    mins = []
    for j in range(m.n):
        one = [segs[j]]
        lim = ref.limits(one)[0]
        g = np.linspace(-lim, lim, 2001)
        v = np.array([ref.energy(one, np.array([t])) for t in g])
        i = int(np.argmin(v))
        pol = so.minimize_scalar(lambda t: ref.energy(one, np.array([t])), method="bounded",
                                 bounds=(g[max(i - 1, 0)], g[min(i + 1, g.size - 1)]), options={"xatol": 1e-13})
        mins.append(min(v[i], pol.fun))
        assert ref.energy(one, np.array([r.q[j]])) <= mins[-1] + 1e-9 * m.torque_scale
    assert r.energy == pytest.approx(sum(mins), abs=1e-8 * m.torque_scale)
    assert r.status == "exact" and r.stable and r.control == "force" and np.all(r.force == 0.0)
    tq = ref.torques(segs, r.q)
    assert np.abs(tq[~r.at_stop]).max(initial=0.0) < 1e-8 * m.torque_scale
    np.testing.assert_allclose(r.contact_torques[r.at_stop], (np.sign(r.q) * tq)[r.at_stop], rtol=1e-8, atol=1e-12)
    assert np.all(r.contact_torques >= 0.0)


# ------------------------------------------------------------------------------------------- limit loads
def _reference_minimum_near(m, F, q0, spread=0.01, starts=4):
    """Where L-BFGS-B on the reference potential ``E - F . tip`` (the closed range as bounds) goes from near
    ``q0``: the farthest end point from ``q0`` over a few nearby starts."""
    import scipy.optimize as so

    segs = ref.segs_of(m)
    lim = ref.limits(segs)
    V = lambda q: ref.energy(segs, q) - F @ ref.tip(segs, q)  # noqa: E731
    rng = np.random.default_rng(2)
    far = 0.0
    for _ in range(starts):
        x0 = np.clip(q0 + rng.normal(0.0, spread, m.n), -lim, lim)
        r = so.minimize(V, x0, method="L-BFGS-B", bounds=list(zip(-lim, lim)),
                        options={"ftol": 1e-15, "gtol": 1e-11, "maxiter": 5000})
        far = max(far, float(np.abs(r.x - q0).max()))
    return far


@pytest.mark.parametrize("family", ["monotonic", "asymmetric", "dy", "large"])
def test_a_limit_load_at_a_kink_is_where_the_reference_arm_snaps(family):
    """Under a growing dead load the tension-only arm loses stability where a spring goes slack (the load turns
    back at the kink: a fold). Checked in the reference model: just below the limit load the path's configuration is
    a strict local minimum of the reference potential (L-BFGS-B from nearby comes back); just above, from the limit
    configuration, it runs away (the arm snaps)."""
    m, _, _ = _chain(family, np.random.default_rng(9900), "tension_only", n=3)
    r = to.limit_load(m, (-1, 0.2), "free")
    assert r.status == "stability_lost" and r.kind == "fold" and "goes slack" in r.message
    e = next(ev for ev in r.branch.events if ev.stability == "lost")
    assert e.kind == "spring_slack"
    d = np.array([-1.0, 0.2]) / math.hypot(1.0, 0.2)
    below = np.flatnonzero(r.branch.t[:e.index + 1] < (1 - 1e-3) * r.load)
    k = int(below[-1])                            # a path point below the limit load (before the kink)
    assert r.branch.stable[k]
    # its basin ends where the spring goes slack (a small step away): nearby starts only
    assert _reference_minimum_near(m, r.branch.t[k] * d, r.branch.q[k], spread=1e-7) < 1e-5
    assert _reference_minimum_near(m, r.load * (1 + 2e-3) * d, r.q, spread=1e-4) > 1e-2


def test_a_limit_load_from_a_rest_on_a_stop_is_refused_by_name():
    m, _, _ = _chain("bistable", np.random.default_rng(9900), "tension_only", n=3)
    assert to.rest_configuration(m).at_stop.any()
    with pytest.raises(UnsupportedError) as e:
        to.limit_load(m)
    assert e.value.field == "start" and e.value.status == "start_on_stop"


def test_the_paper_chains_limit_load_is_the_critical_load_under_both_laws():
    """Every spring is taut at the straight chain: the bifurcation at the first critical load is the linear law's."""
    m = to.Manipulator.uniform(4, spring="tension_only")
    r, lin = to.limit_load(m), to.limit_load(m.with_spring("linear"))
    assert r.kind == lin.kind == "bifurcation" and r.load == pytest.approx(lin.load, rel=1e-9)
    assert r.load == pytest.approx(to.critical_force(m.with_spring("linear"), "free").force * -1, rel=1e-6)


# ------------------------------------------------------------------------------------------- branches
def _branch_is_the_reference(m, br):
    """Every point balances in the reference model (torques from the spring force vectors) inside the closed range,
    and each spring event lies where the reference spring reaches its rest length, with the joint's one-sided
    stiffnesses of the reference torque (one-sided differences) before and after."""
    segs = ref.segs_of(m)
    for q, F in zip(br.q, br.force):
        r = ref.torques(segs, q) + ref.tip_jacobian(segs, q).T @ F
        assert np.abs(r).max() < 1e-8 * m.torque_scale
        assert np.all(np.abs(q) <= m.joint_limits)
    events = [e for e in br.events if e.kind in ("spring_slack", "spring_taut")]
    for e in events:
        j, i = e.joint, e.spring - 1
        L = ref.lengths(segs, e.q)[j, i]
        L0 = (m.segments[j].L1_0, m.segments[j].L2_0)[i]
        assert abs(L - L0) < 1e-9 * L0, (L, L0)
        h = 1e-6
        side = []
        for s in (1.0, -1.0):
            dq = np.zeros(m.n)
            dq[j] = s * h
            side.append(-(ref.torques(segs, e.q + dq)[j] - ref.torques(segs, e.q)[j]) / (s * h))
        assert sorted([e.stiffness_before, e.stiffness_after]) == pytest.approx(sorted(side), abs=1e-4 * m.torque_scale)
        assert e.stiffness_before != pytest.approx(e.stiffness_after)
        d = e.to_dict()
        assert d["kind"] == e.kind and d["spring"] == i + 1 and d["stiffness_after"] == e.stiffness_after
    # each change of a spring's state along the points is one located event, in order (a point on the kink itself,
    # |L - L0| ~ rounding, counts for neither side)
    L0 = np.array([[s.L1_0, s.L2_0] for s in m.segments])
    r = np.array([ref.lengths(segs, q) for q in br.q]) - L0
    for j in range(m.n):
        for i in range(2):
            if not m.segments[j].tension_only:
                continue
            keep = np.abs(r[:, j, i]) > 1e-9 * L0[j, i]
            st = r[keep, j, i] > 0.0
            idx = np.flatnonzero(keep)
            want = [int(idx[k]) for k in np.flatnonzero(st[1:] != st[:-1])]       # the last point before each change
            got = [e for e in events if (e.joint, e.spring - 1) == (j, i)]
            assert len(got) == len(want), (j, i, [e.index for e in got], want)
            for e, w in zip(got, want):
                assert w <= e.index <= w + 1
                assert e.kind == ("spring_slack" if r[w, j, i] > 0.0 else "spring_taut")
    return events


def test_a_branch_of_the_paper_chain_locates_where_spring_3_2_goes_slack():
    """Displacement control from dx = 0.5: spring 3.2 reaches its rest length at dx ~ 1.097 (the issue's figure), the
    joint's stiffness drops there, and the branch ends where joint 3 reaches its stop (dx ~ 1.74, the docs' figure:
    from ~1.75 the least-energy configuration rests on it)."""
    m = to.Manipulator.uniform(4, spring="tension_only")
    br = to.trace_branch(m, to.solve_equilibrium(m, 0.5), "displacement", t_max=2.5, max_points=400)
    ev = _branch_is_the_reference(m, br)
    assert [(e.kind, e.joint, e.spring) for e in ev] == [("spring_slack", 2, 2)]
    assert 0.5 + ev[0].t == pytest.approx(1.097, abs=1e-3) and ev[0].stiffness_after < ev[0].stiffness_before
    assert br.status == "joint_limit" and br.events[-1].joint == 2 and 0.5 + br.t[-1] == pytest.approx(1.74, abs=0.01)


@pytest.mark.parametrize("family", ["large", "asymmetric", "heterogeneous", "dy"])
@pytest.mark.parametrize("control", ["displacement", "load"])
def test_branches_of_random_tension_only_chains(family, control):
    m, dx, dy = _chain(family, np.random.default_rng(9300), "tension_only", n=3)
    eq = to.solve_equilibrium(m, 0.3 * dx, dy)
    if eq.at_stop.any():                         # a branch starts inside the range
        eq = to.solve_equilibrium(m, 0.05 * dx, dy)
    ctl = to.Control.displacement() if control == "displacement" else to.Control.load(base=eq.force)  # from eq
    br = to.trace_branch(m, eq, ctl, t_max=3.0 if control == "displacement" else 2.0, max_points=300)
    assert len(br.t) > 5
    _branch_is_the_reference(m, br)


# ------------------------------------------------------------------------------------------- certified sets
needs_phc = pytest.mark.skipif(not homotopy_available() and os.environ.get("TENSEGRITY_REQUIRE_PHC") != "1",
                               reason="PHCpack's phc is not installed")


@needs_phc
@pytest.mark.slow
@pytest.mark.parametrize("family", FAMILIES)
def test_the_certified_set_of_random_tension_only_chains_of_three_is_the_reference(family):
    """One homotopy per taut/slack/stop pattern: the same equilibria, Morse indices, stops and contact torques as
    the independent enumeration, certified (dy != 0: a mirror-symmetric chain at dy = 0 has double roots that the
    linear law's homotopy leaves uncertified too)."""
    m, dx, dy = _chain(family, np.random.default_rng(7100), "tension_only", n=3)
    got = _same_sets(m, 2.0 * dx, 2.0 * dy + 0.3, "homotopy", "certified")
    assert got.method == "homotopy" and got.certificate is None and "patterns" in got.message


@needs_phc
@pytest.mark.slow
def test_the_certified_set_of_the_paper_chain_of_three_rests_on_stops():
    got = _same_sets(to.Manipulator.uniform(3, spring="tension_only"), 1.0, 0.5, "homotopy", "certified")
    assert any(e.at_stop.any() for e in got) and any(e.morse_index >= 1 for e in got)


@needs_phc
def test_a_mixed_chain_is_certified_with_the_linear_segments_stops():
    """A linear segment between tension-only ones: one free option over its whole range, and its two stops."""
    m = to.Manipulator([to.Segment(1, 1, spring="tension_only"), to.Segment(0.9, 1.1, k=1.3),
                        to.Segment(1.1, 1.0, L0=1.2, spring="tension_only")])
    _same_sets(m, 2.2, 0.4, "homotopy", "certified")


def test_the_pattern_options_and_their_torque_bounds_agree_with_the_reference_model():
    """Each joint's options: the springs' states inside each interval are the reference model's, the intervals tile
    the closed range, and the pattern test's bounds of ``dE/dq`` over any piece of an interval hold every reference
    value there (sampled densely) and are tight (to the sampling's resolution)."""
    from tensegrity_opt.analyses.equilibria.tension_only_homotopy import _TorqueTables, joint_options

    rng = np.random.default_rng(3)
    for family in FAMILIES:
        m, _, _ = _chain(family, rng, "tension_only", n=2)
        segs = ref.segs_of(m)
        tables = _TorqueTables(m)
        for j, seg in enumerate(m.segments):
            opts = joint_options(seg)
            free = [o for o in opts if o.side == 0]
            iv = np.sort(np.vstack([o.intervals for o in free]), axis=0)
            lim = seg.joint_limit
            assert iv[0, 0] == pytest.approx(-lim) and iv[-1, 1] == pytest.approx(lim)
            assert np.allclose(iv[1:, 0], iv[:-1, 1])
            for o in free:
                for lo, hi in o.intervals:
                    for q in np.linspace(lo, hi, 7)[1:-1]:
                        qq = np.zeros(m.n)
                        qq[j] = q
                        L = ref.lengths(segs, qq)[j]
                        L0 = np.array([seg.L1_0, seg.L2_0])
                        assert tuple(L > L0) == o.taut
                    for _ in range(3):
                        a, b = np.sort(rng.uniform(lo, hi, 2))
                        Q = np.zeros((201, m.n))
                        Q[:, j] = np.linspace(a, b, 201)
                        dE = np.array([-ref.torques(segs, qq)[j] for qq in Q])
                        t = np.array([tables.index(j, o.taut)])
                        low, high = tables.bounds(t, np.array([a]), np.array([b]))
                        assert low[0] <= dE.min() + 1e-12 and high[0] >= dE.max() - 1e-12
                        slope = float(np.abs(np.diff(dE)).max()) + 1e-12
                        assert dE.min() - low[0] <= slope and high[0] - dE.max() <= slope


def test_the_force_test_is_a_linear_program():
    """``_force_exists`` (some F with every row a fx + b fy >= t) against scipy's linprog on random row sets,
    degenerate ones too (parallel rows, rows of zeros): never "no" where the LP finds an F with a margin (sound), and
    "no" wherever the LP's margin is clearly negative, except for two opposite parallel rows (rounding makes them
    meet far away: such a pair is dropped, a relaxation)."""
    from scipy.optimize import linprog

    from tensegrity_opt.analyses.equilibria.tension_only_homotopy import _force_exists

    rng = np.random.default_rng(11)
    checked = feasible = 0
    for trial in range(400):
        M = int(rng.integers(2, 11))
        A = rng.normal(size=(M, 2))
        t = rng.normal(size=M) * rng.choice([0.0, 0.3, 1.0, 3.0])
        if trial % 4 == 1:
            A[1] = -A[0] * rng.uniform(0.5, 2.0)          # parallel (a strip or nothing)
        if trial % 4 == 2:
            A[-1], t[-1] = 0.0, -abs(t[-1])               # an empty row
        # the largest margin s with A F >= t + s, |F| <= 1e3: > 0 feasible, < 0 not
        res = linprog([0.0, 0.0, -1.0], A_ub=np.hstack([-A, np.ones((M, 1))]), b_ub=-t,
                      bounds=[(-1e3, 1e3), (-1e3, 1e3), (None, 1.0)], method="highs")
        assert res.status == 0
        margin = res.x[2]
        if abs(margin) < 1e-6:
            continue
        got = bool(_force_exists(A[:, 0], A[:, 1], t))
        if margin > 0 or trial % 4 != 1:
            assert got == (margin > 0), (trial, margin)
        checked += 1
        feasible += margin > 0
    assert checked > 300 and 50 < feasible < checked - 50


def _patterns_of(m, q, stops):
    """The patterns (one option per joint) an equilibrium at ``q`` with ``stops`` lies in."""
    from tensegrity_opt.analyses.equilibria.tension_only_homotopy import joint_options

    per = []
    for j, seg in enumerate(m.segments):
        opts = joint_options(seg)
        if stops[j]:
            per.append([o for o in opts if o.side == stops[j]])
        else:
            per.append([o for o in opts if o.side == 0 and o.contains(q[j])])
    return [tuple(per[j][i] for j, i in enumerate(idx)) for idx in np.ndindex(*[len(p) for p in per])]


@pytest.mark.slow_cases(keep=2)
@pytest.mark.parametrize("family", FAMILIES)
@pytest.mark.parametrize("spring", ["tension_only", "linear"])
def test_a_box_around_an_equilibrium_passes_the_pattern_test(family, spring):
    """The pruning is sound: for every equilibrium of the independent enumeration (n = 3, the stops included), every
    pattern it lies in is kept by ``patterns``, and random boxes about it inside its pattern pass the box test."""
    import reference_equilibria_tension as reqs

    from tensegrity_opt.analyses.equilibria import tension_only_homotopy as th

    rng = np.random.default_rng(7500)
    want = []
    while not want:                              # a target the chain reaches
        m, dx, dy = _chain(family, rng, spring, n=3)
        dx, dy = 2.0 * dx, 2.0 * dy + 0.2
        want = [r for r in reqs.equilibria(ref.segs_of(m), dx, dy) if np.abs(r.stops).sum() <= m.n - 2]
    target = np.array([m.straight_length - dx, dy])
    kept = {th._name(p) for p in th.patterns(m, target)[0]}
    tables = th._TorqueTables(m)
    tol = 1e-9 * float(m.link_lengths.sum())
    slack = th.CONTACT_TOL * 1e3 * m.torque_scale
    lim = m.joint_limits
    for r in want:
        pats = _patterns_of(m, r.q, r.stops)
        assert pats
        for pat in pats:
            assert th._name(pat) in kept, (th._name(pat), r.q)
            lo, hi = np.tile(r.q, (20, 1)), np.tile(r.q, (20, 1))
            table = np.zeros((20, m.n), dtype=int)
            side = np.tile([float(o.side) for o in pat], (20, 1))
            held = np.tile([float(-m.segments[j].torque(o.side * lim[j])) if o.side else 0.0
                            for j, o in enumerate(pat)], (20, 1))
            for j, o in enumerate(pat):
                if o.side:
                    continue
                table[:, j] = tables.index(j, o.taut)
                iv = o.intervals[np.flatnonzero((o.intervals[:, 0] <= r.q[j] + 1e-8) &
                                                (r.q[j] - 1e-8 <= o.intervals[:, 1]))[0]]
                w = 10.0 ** rng.uniform(-6, 0, 20)
                lo[:, j] = np.maximum(iv[0], r.q[j] - w * rng.random(20))
                hi[:, j] = np.minimum(iv[1], r.q[j] + w * rng.random(20))
            assert th._boxes_pass(m, target, lo, hi, table, side, held, tables, tol, slack).all()


@needs_phc
@pytest.mark.slow
@pytest.mark.parametrize("family", FAMILIES)
def test_certify_proves_the_least_energy_of_a_tension_only_chain(family):
    """certify=True: the rigorous lower bound (each spring's curvature bounded on its taut and slack sides) or, where
    it stays open (n <= 4), the patterns' certified set; the energy is the independent brute force's and the bound
    never exceeds it."""
    m, dx, dy = _chain(family, np.random.default_rng(8100), "tension_only", n=3)
    dx, dy = 1.5 * dx, dy + 0.1
    best = ref.least_energy(ref.segs_of(m), dx, dy)
    eq = to.solve_equilibrium(m, dx, dy, certify=True)
    assert eq.status == "certified", eq.message
    assert eq.energy == pytest.approx(best.energy, rel=1e-9, abs=1e-12)
    b = to.energy_lower_bound(m, dx, dy, eq.q, force=eq.force)
    assert b.bound <= best.energy + 1e-12 * abs(best.energy)
    h = to.solve_equilibrium(m, dx, dy, method="homotopy")
    assert h.status == "certified" and h.energy == pytest.approx(best.energy, rel=1e-9, abs=1e-12)


@needs_phc
@pytest.mark.slow
def test_an_option_whose_two_intervals_have_opposite_moments_prunes_nothing():
    """A review's counterexample: with a / b < 0.41 a one-taut option can have two intervals on either side of its
    spring's turning angle, its moment of opposite signs there; read from one interval, the old sign test pruned a
    pattern holding a stable equilibrium while the set said certified (5 of the reference's 6). The pattern test
    bounds each interval on its own."""
    from tensegrity_opt.analyses.equilibria.tension_only_homotopy import joint_options

    seg = to.Segment(math.tan(0.2), 1.0, 1.0, (2 * math.hypot(math.tan(0.2), 1) * math.cos(1.2),
                                             2 * math.hypot(math.tan(0.2), 1) * math.cos(0.5)), "tension_only")
    two = [o for o in joint_options(seg) if o.side == 0 and len(o.intervals) == 2]
    assert two
    m = to.Manipulator([to.Segment(0.22204, 1.39045, 1.0, (0.88682, 0.75931), "tension_only"),
                        to.Segment(0.20271, 1.0, 1.0, (0.73946, 1.79086), "tension_only"),
                        to.Segment(0.17292, 0.66221, 1.0, (0.93656, 1.11136), "tension_only")])
    dx, dy = m.straight_length + 0.717058, -1.199148          # the target (-0.717058, -1.199148)
    got = _same_sets(m, dx, dy, "homotopy", "certified")
    assert any(float(np.abs(e.q - [2.80062, 1.67224, 1.19218]).max()) < 1e-4 and e.stable for e in got)


@needs_phc
@pytest.mark.slow
@pytest.mark.parametrize("dx, dy", [(3.0, 0.3)])
def test_the_certified_set_of_the_paper_chain_of_four(dx, dy):
    got = _same_sets(to.Manipulator.uniform(4, spring="tension_only"), dx, dy, "homotopy", "certified")
    assert len(got) >= 16


@needs_phc
@pytest.mark.slow
def test_the_pattern_test_leaves_only_the_four_free_patterns_that_hold_an_equilibrium():
    """The pruning's strength (issue 40, item 4: "prune patterns that cannot occur"): on the paper chain of four at
    (1, 0.4), of the 37 patterns with four free joints whose tip may reach the target, the kept ones are exactly the
    9 that hold an equilibrium of the independent enumeration; the set is that enumeration's, certified."""
    import reference_equilibria_tension as reqs

    from tensegrity_opt.analyses.equilibria import tension_only_homotopy as th

    m = to.Manipulator.uniform(4, spring="tension_only")
    want = [r for r in reqs.equilibria(ref.segs_of(m), 1.0, 0.4) if np.abs(r.stops).sum() <= m.n - 2]
    holding = {th._name(p) for r in want if not r.stops.any() for p in _patterns_of(m, r.q, r.stops)}
    kept = {th._name(p) for p in th.patterns(m, [m.straight_length - 1.0, 0.4])[0]
            if all(o.side == 0 for o in p)}
    assert kept == holding and len(holding) == 9
    got = to.find_equilibria(m, 1.0, 0.4, method="homotopy")
    assert got.status == "certified" and len(got) == len(want) == 16


@needs_phc
@pytest.mark.slow
@pytest.mark.parametrize("family", FAMILIES)
def test_the_certified_set_of_random_tension_only_chains_of_four(family):
    m, dx, dy = _chain(family, np.random.default_rng(7400), "tension_only", n=4)
    _same_sets(m, 2.0 * dx, 2.0 * dy + 0.2, "homotopy", "certified")


def test_preloads_for_a_pose_of_a_tension_only_chain_keep_every_spring_taut():
    """taut=True: the linear law's design with every spring taut is the arm's as built (the laws agree there); the
    reference model (its own geometry and force vectors) finds the designed pose in equilibrium and stable under
    no load, every spring in tension."""
    m = to.Manipulator.uniform(4, spring="tension_only")
    d = to.preloads_for_pose(m, (5.5, 1.5), taut=True)
    built = d.manipulator
    assert all(s.spring == "tension_only" for s in built.segments) and d.success
    segs = ref.segs_of(built)
    assert np.all(ref.lengths(segs, d.q) - np.array([[s.L1_0, s.L2_0] for s in built.segments]) >= -1e-9)
    assert np.abs(ref.torques(segs, d.q)).max() < 1e-8 * built.torque_scale        # no load: no torque
    np.testing.assert_allclose(ref.tip(segs, d.q), [5.5, 1.5], atol=1e-8)
    h = 1e-5
    H = np.array([(ref.torques(segs, d.q - h * e) - ref.torques(segs, d.q + h * e)) / (2 * h) for e in np.eye(4)])
    assert np.linalg.eigvalsh(0.5 * (H + H.T)).min() > 0.5 * d.margin
    assert (d.spring_states == "taut").all()


# ------------------------------------------------------------------------------------------- simulation, transitions
def _reference_flow(m, F, q0):
    """Where the reference gradient flow ``dq/dtau = -grad V`` of ``V = E - F . tip`` (the reference torques) goes
    from ``q0``: ``("bound", q)`` where a joint reaches its range bound, ``("rest", q)`` where it settles."""
    from scipy.integrate import solve_ivp

    segs = ref.segs_of(m)
    lim = ref.limits(segs)

    def bound(_t, q):
        return float(np.min(lim * (1.0 - 1e-6) - np.abs(q)))

    bound.terminal = True
    sol = solve_ivp(lambda _t, q: ref.torques(segs, q) + ref.tip_jacobian(segs, q).T @ F, (0.0, 1e4), q0,
                    method="LSODA", rtol=1e-10, atol=1e-12, events=bound)
    return ("bound" if sol.status == 1 else "rest"), sol.y[:, -1]


def _states_are_reference_minima(m, sim, rest_lengths):
    """Every state of a free-tip series is a strict local minimum of the reference potential under its own rest
    lengths (free joints balance; L-BFGS-B from nearby comes back), with the reference's spring states."""
    for k in range(len(sim)):
        mk = to.Manipulator(sg.replace(L0=tuple(c)) for sg, c in zip(m.segments, rest_lengths[k]))
        segs = ref.segs_of(mk)
        r = ref.torques(segs, sim.q[k]) + ref.tip_jacobian(segs, sim.q[k]).T @ sim.force[k]
        assert np.abs(r).max() < 1e-8 * m.torque_scale, k
        assert _reference_minimum_near(mk, sim.force[k], sim.q[k], spread=1e-5) < 1e-5, k
        L0 = np.asarray(rest_lengths[k], float)
        slack = ref.lengths(segs, sim.q[k]) - L0 < 0.0
        assert (sim.spring_states[k] == "slack").tolist() == slack.tolist(), k


@pytest.mark.parametrize("family", ["monotonic", "asymmetric", "dy", "large"])
def test_a_simulation_of_a_tension_only_chain_snaps_where_a_spring_goes_slack(family):
    """A growing compressive load: the arm follows its branch (every state a strict local minimum of the reference
    potential) until a spring goes slack and the branch turns back at the kink; there it snaps. The kink is where a
    reference spring reaches its rest length; just past the event's load the reference arm runs away from it; the
    reference gradient flow from where the descent starts goes where the simulation says (here into a joint's
    stop: the arm as built rests on it, which ends the simulation, status joint_limit)."""
    m, _, _ = _chain(family, np.random.default_rng(9900), "tension_only", n=3)
    F = np.array([-1.0, 0.15]) * np.linspace(0.0, 1.0, 41)[:, None] * 3.0 * m.torque_scale / m.straight_length
    sim = to.simulate(m, loads=F)
    P = np.repeat(np.column_stack([m.L1_0, m.L2_0])[None], len(F), 0)
    _states_are_reference_minima(m, sim, P)
    assert sim.snaps, sim.message
    e = sim.snaps[0]
    segs = ref.segs_of(m)
    stretch = ref.lengths(segs, e.q_before) - P[0]
    assert np.abs(stretch).min() < 1e-8                              # a kink: a spring at its rest length
    assert _reference_minimum_near(m, e.load * (1 + 2e-3), e.q_before, spread=1e-4) > 1e-2      # it snaps
    assert _reference_minimum_near(m, sim.force[e.step], sim.q[e.step], spread=1e-5) < 1e-5     # stable before
    q0 = e.q_before + e.direction * 1e-4 * e.null_vector
    V = lambda q: ref.energy(segs, q) - e.load @ ref.tip(segs, q)  # noqa: E731
    assert V(q0) < V(e.q_before)                                     # the descent starts downhill
    where, q = _reference_flow(m, e.load, q0)
    if e.status == "joint_limit":
        assert where == "bound" and sim.status == "joint_limit"
    else:
        assert where == "rest" and np.abs(q - e.q_after).max() < 1e-6


def test_a_held_tip_simulation_of_the_paper_chain_passes_its_springs_going_slack():
    """The tip held and moved: springs 2.2 then 1.1 go slack on the way (each state the reference's) and the arm
    follows, stable, until joint 1 reaches its stop. Each state is a strict local minimum of the reference energy
    on the tip constraint (SLSQP from nearby starts comes back)."""
    import scipy.optimize as so

    m = to.Manipulator.uniform(3, spring="tension_only")
    T = np.column_stack([np.linspace(0.5, 1.7, 25), np.zeros(25)])
    sim = to.simulate(m, tip="held", targets=T)
    assert sim.status == "joint_limit" and 17 <= len(sim) < 25
    segs = ref.segs_of(m)
    L0 = np.column_stack([m.L1_0, m.L2_0])
    rng = np.random.default_rng(3)
    for k in range(len(sim)):
        tgt = ref.target(segs, *T[k])
        assert np.abs(ref.tip(segs, sim.q[k]) - tgt).max() < 1e-10
        slack = ref.lengths(segs, sim.q[k]) - L0 < 0.0
        assert (sim.spring_states[k] == "slack").tolist() == slack.tolist()
        assert sim.stable[k]
        for _ in range(2):
            res = so.minimize(lambda q: ref.energy(segs, q), sim.q[k] + rng.normal(0.0, 1e-3, 3), method="SLSQP",
                              constraints={"type": "eq", "fun": lambda q, t=tgt: ref.tip(segs, q) - t},
                              options={"ftol": 1e-15, "maxiter": 500})
            assert np.abs(res.x - sim.q[k]).max() < 1e-5, k
    slack_at = [k for k in range(len(sim)) if (sim.spring_states[k] == "slack").any()]
    assert slack_at and (sim.spring_states[0] == "taut").all()
    assert sim.events[-1].kind == "joint_limit"


def test_a_preload_move_lets_a_tension_only_spring_go_slack_and_the_arm_follows():
    """Raising a rest length past the spring's length under a load: the spring goes slack during the move (a kink
    where the rest length moves, not the arm), the arm follows; its end is a strict local minimum of the reference
    potential under the final rest lengths."""
    from tensegrity_opt.analyses.paths.transition import transition

    m = to.Manipulator.uniform(3, spring="tension_only")
    P0 = np.column_stack([m.L1_0, m.L2_0])
    P1 = P0.copy()
    P1[1, 0] = 2.6
    F = np.array([0.0, 0.2])
    start = to.solve_equilibrium_under_force(m, *F, q0=to.rest_configuration(m).q)
    tr = transition(m, start, [P0, P1], loads=[F, F])
    assert tr.status == "followed" and tr.stable and tr.margin > 0
    assert tr.spring_states[1, 0] == "slack" and (start.spring_states == "taut").all()
    m1 = to.Manipulator(sg.replace(L0=tuple(c)) for sg, c in zip(m.segments, P1))
    segs = ref.segs_of(m1)
    r = ref.torques(segs, tr.q) + ref.tip_jacobian(segs, tr.q).T @ F
    assert np.abs(r).max() < 1e-8
    assert _reference_minimum_near(m1, F, tr.q, spread=1e-5) < 1e-5
    # the branch's spring event sits where the spring's length equals its (moving) rest length
    br = to.trace_branch(m, start, to.Control.move(3, preload=P1 - P0, load=np.zeros(2), base=F), t_max=1.0)
    ev = [e for e in br.events if e.kind == "spring_slack"]
    assert len(ev) == 1 and ev[0].joint == 1 and ev[0].spring == 1
    L0t = P0[1, 0] + ev[0].t * (P1[1, 0] - P0[1, 0])
    assert abs(ref.lengths(ref.segs_of(m), ev[0].q)[1, 0] - L0t) < 1e-9


def test_a_simulation_from_a_rest_on_a_stop_is_refused_by_name():
    m, _, _ = _chain("bistable", np.random.default_rng(9900), "tension_only", n=3)
    with pytest.raises(UnsupportedError) as e:
        to.simulate(m, loads=np.zeros((3, 2)))
    assert e.value.field == "start" and e.value.status == "start_on_stop"


def test_the_preload_follower_answers_a_tension_only_chain_with_reference_equilibria():
    """Rest lengths commanded step by step under a load: each answer is a strict local minimum of the reference
    potential under its command, with the reference's spring states (spring 2.1 goes slack on the last command);
    under another load the arm reaches a joint's stop on the way: refused naming the command, the state kept."""
    from tensegrity_opt.errors import NoEquilibriumError

    m = to.Manipulator.uniform(3, spring="tension_only")
    F = np.array([0.0, 0.2])
    f = to.PreloadFollower(m, load=F)
    for v in (1.4, 2.0, 2.6):
        P = np.column_stack([m.L1_0, m.L2_0])
        P[1, 0] = v
        st = f.step(P)
        mk = to.Manipulator(sg.replace(L0=tuple(c)) for sg, c in zip(m.segments, P))
        segs = ref.segs_of(mk)
        r = ref.torques(segs, st.q) + ref.tip_jacobian(segs, st.q).T @ F
        assert st.success and np.abs(r).max() < 1e-8
        assert _reference_minimum_near(mk, F, st.q, spread=1e-5) < 1e-5
        assert (st.equilibrium.spring_states == "slack").tolist() == (ref.lengths(segs, st.q) < P).tolist()
    assert st.equilibrium.spring_states[1, 0] == "slack"
    f = to.PreloadFollower(m, load=(-0.1, 0.05))
    P = np.column_stack([m.L1_0, m.L2_0])
    P[1, 0] = 2.6
    q = f.q.copy()
    with pytest.raises(NoEquilibriumError) as e:
        f.step(P)
    assert e.value.field == "rest_lengths" and np.array_equal(f.q, q)


# ------------------------------------------------------------------------------------------- plans
#: Chains, trajectories (an arc of radius r times the straight length, from angle ang0 to ang1, 6 steps), loads and
#: objectives where the linear law's plan (taut not asked) has springs shorter than their rest length (pushing).
PLAN_CASES = [
    dict(n=3, a=0.92, k=1.134, L0=1.025, ang0=-0.225, ang1=0.286, r=0.759, F=(0.136, 0.014), obj="energy"),
    dict(n=3, a=1.051, k=1.939, L0=1.332, ang0=0.032, ang1=0.313, r=0.839, F=(0.051, 0.064), obj="margin"),
    dict(n=4, a=1.198, k=0.974, L0=1.164, ang0=0.228, ang1=1.165, r=0.767, F=(0.092, -0.023), obj="energy"),
    dict(n=3, a=1.101, k=1.871, L0=1.429, ang0=0.218, ang1=0.823, r=0.618, F=(-0.033, -0.079), obj="change"),
]


def _reference_follows(m, q0, P0, P1, F0, F1, q1):
    """The reference arm (tension-only potential, L-BFGS-B over the closed range) moved quasi-statically from ``q0``
    while the rest lengths and the load move linearly from ``(P0, F0)`` to ``(P1, F1)``: each substep's minimum
    from the previous one, the substep halved where the arm moves by more than 0.02 rad. It follows continuously
    (a snap would jump however small the substep: down to 1e-4 of the move), never on a stop, and ends on ``q1``."""
    import scipy.optimize as so

    q = np.asarray(q0, float)
    lim = ref.limits(ref.segs_of(m))

    def settle(s, x0):
        P, F = P0 + s * (P1 - P0), F0 + s * (F1 - F0)
        segs = ref.segs_of(to.Manipulator(sg.replace(L0=tuple(c)) for sg, c in zip(m.segments, P)))
        return so.minimize(lambda x: ref.energy(segs, x) - F @ ref.tip(segs, x), x0, method="L-BFGS-B",
                           jac=lambda x: -(ref.torques(segs, x) + ref.tip_jacobian(segs, x).T @ F),
                           bounds=list(zip(-lim, lim)), options={"ftol": 1e-15, "gtol": 1e-12, "maxiter": 5000}).x

    s, h = 0.0, 0.05
    while s < 1.0:
        h = min(h, 1.0 - s)
        x = settle(s + h, q)
        if np.abs(x - q).max() > 0.02:
            assert h > 1e-4, (s, x, q)                                   # a jump that does not shrink: a snap
            h *= 0.5
            continue
        assert np.all(np.abs(x) < lim * (1 - 1e-6))                      # no joint on its stop
        s, q, h = s + h, x, 2.0 * h
    assert np.abs(q - q1).max() < 1e-5, (q, q1)


@pytest.mark.slow_cases(keep=1)         # the reference's quasi-static follow costs 2-15 s a plan
@pytest.mark.parametrize("case", [1, 3, 0, 2])
def test_a_plan_for_a_tension_only_chain_keeps_its_springs_taut_and_gets_there(case):
    """The linear law's plan of these trajectories lets springs push; under the tension-only law (taut=True) every
    planned pose has every reference spring in tension, each step's pose is an equilibrium of the reference under
    its command, and each verified step is followed by the reference arm from the previous state without a snap."""
    c = PLAN_CASES[case]
    lin = to.Manipulator.uniform(c["n"], a=c["a"], k=c["k"], L0=c["L0"])
    ang = np.linspace(c["ang0"], c["ang1"], 6)
    T = c["r"] * lin.straight_length * np.column_stack([np.cos(ang), np.sin(ang)])
    F = np.array(c["F"])
    plan_lin = to.plan_preloads(lin, T, loads=F, objective=c["obj"])
    assert any((st.spring_states == "pushing").any() for st in plan_lin.steps)
    m = lin.with_spring("tension_only")
    with pytest.raises(UnsupportedError) as e:
        to.plan_preloads(m, T, loads=F, objective=c["obj"])
    assert e.value.field == "taut"
    plan = to.plan_preloads(m, T, loads=F, objective=c["obj"], taut=True)
    assert plan.verified.sum() >= 4, plan.message
    q_prev, P_prev = plan.start, np.column_stack([m.L1_0, m.L2_0])
    for st in plan.steps:
        segs = ref.segs_of(to.Manipulator(sg.replace(L0=tuple(p)) for sg, p in zip(m.segments, st.command)))
        r = ref.torques(segs, st.q) + ref.tip_jacobian(segs, st.q).T @ F
        assert np.abs(r).max() < 1e-8 * m.torque_scale
        if st.method != "none":
            assert np.all(ref.lengths(segs, st.q) - st.command > 0.0)          # every spring in tension
            assert (st.spring_states == "taut").all()
        if st.verified:
            _reference_follows(m, q_prev, P_prev, st.command, F, F, st.q)
        q_prev, P_prev = st.q, st.command


def test_a_tension_only_plan_from_a_rest_on_a_stop_or_over_a_horizon_is_refused_by_name():
    m = to.Manipulator.uniform(3, a=0.5, b=1.0, k=1.0, L0=0.5, spring="tension_only")
    with pytest.raises(UnsupportedError) as e:
        to.plan_preloads(m, [[2.5, 0.5]], taut=True)
    assert e.value.field == "start" and e.value.status == "start_on_stop"
    with pytest.raises(UnsupportedError) as e:
        to.plan_preloads(to.Manipulator.uniform(3, spring="tension_only"), [[5.5, 0.3]], taut=True, horizon=2)
    assert e.value.field == "horizon"


# ------------------------------------------------------------------------------------------- the atlas
@pytest.mark.slow          # ~3 s: the reference enumeration at six targets
def test_the_stability_atlas_of_a_tension_only_chain():
    """Per target the counts are the reference enumeration's (stable ones on a stop included) with its least
    energy; every branch end on an edge balances in the reference model with the tip on the edge (where a spring
    goes slack there, it is at its rest length); every edge left unresolved starts from an equilibrium resting on a
    stop (the path engine works inside the range) and says so."""
    import reference_equilibria_tension as reqs

    m = to.Manipulator.uniform(3, a=0.5, L0=0.5, spring="tension_only")
    X, Y = np.array([1.1, 1.35, 1.6]), np.array([0.0, 0.4])
    at = to.stability_atlas(m, X, Y)
    segs = ref.segs_of(m)
    for row in at.targets:
        for t in row:
            want = [r for r in reqs.equilibria(segs, t.dx, t.dy) if np.abs(r.stops).sum() <= m.n - 2]
            stable = [r for r in want if r.stable]
            assert (t.count, t.n_stable) == (len(want), len(stable)), (t.dx, t.dy)
            assert t.least_energy == pytest.approx(min(r.energy for r in stable), rel=1e-9)
    ends = [c for c in at.crossings if c.kind == "branch_end"]
    assert ends
    for c in ends:
        r = ref.torques(segs, c.q) + ref.tip_jacobian(segs, c.q).T @ c.force
        assert np.abs(r).max() < 1e-8
        np.testing.assert_allclose(ref.tip(segs, c.q), ref.target(segs, c.dx, c.dy), atol=1e-9)
        if c.event in ("spring_slack", "spring_taut"):
            assert np.abs(ref.lengths(segs, c.q) - 0.5).min() < 1e-8
    assert at.status == "partial" and at.unresolved
    for (_, why) in at.unresolved:
        assert "stop" in why


# ------------------------------------------------------------------------------------------- preload design
def _reference_guided_critical_load(m, h=1e-5):
    """The straight chain's critical compressive load with the tip guided along x, from the reference model: the
    least ``P`` where ``Z^T (K + P G) Z`` turns singular (``K`` the reference energy's Hessian, ``G`` the tip x's,
    both by central differences at ``q = 0``; ``Z`` the null space of the tip y's gradient there)."""
    segs = ref.segs_of(m)
    n = m.n
    q0 = np.zeros(n)
    K = np.array([(ref.torques(segs, q0 - h * e) - ref.torques(segs, q0 + h * e)) / (2 * h) for e in np.eye(n)])
    G = np.array([(ref.tip_jacobian(segs, q0 + h * e)[0] - ref.tip_jacobian(segs, q0 - h * e)[0]) / (2 * h)
                  for e in np.eye(n)])
    Jy = ref.tip_jacobian(segs, q0)[1]
    Z = np.linalg.svd(Jy[None, :])[2][1:].T
    A, B = Z.T @ (0.5 * (K + K.T)) @ Z, -Z.T @ (0.5 * (G + G.T)) @ Z
    return float(np.min(np.linalg.eigvals(np.linalg.solve(B, A)).real))


def test_preloads_for_a_critical_load_of_a_tension_only_chain_keep_every_spring_taut_at_straight():
    """The designed rest lengths leave every reference spring taut at the straight chain, and the reference's
    critical load of the designed chain is the one reported; a requirement out of reach returns the strongest
    design, its rest lengths just below the springs' lengths at straight (taut by 1e-7: the reference's differences
    then take a step inside that, 1e-9 rad, since a larger one reaches the slack side)."""
    m = to.Manipulator.uniform(4, a=0.9, k=1.3, spring="tension_only")
    for required, status in ((0.5, "optimal"), (5.0, "below_required")):
        d = to.preloads_for_critical_force(m, required)
        assert d.status == status and all(s.spring == "tension_only" for s in d.manipulator.segments)
        segs = ref.segs_of(d.manipulator)
        L0 = np.array([[s.L1_0, s.L2_0] for s in d.manipulator.segments])
        assert np.all(ref.lengths(segs, np.zeros(4)) - L0 > 0.0)
        h, rel = (1e-5, 1e-6) if status == "optimal" else (1e-9, 1e-4)
        assert -d.critical_force == pytest.approx(_reference_guided_critical_load(d.manipulator, h), rel=rel)
        if status == "optimal":
            assert -d.critical_force >= required * (1 - 1e-7)
    with pytest.raises(InvalidParameterError) as e:
        to.preloads_for_critical_force(m, 0.5, bounds=(2.0, 3.0))
    assert e.value.field == "bounds"
    # springs slack at straight in the nominal chain: its starting critical load is undefined (not the linear twin's)
    slack = to.Manipulator.uniform(3, a=0.9, k=1.3, L0=2.3, spring="tension_only")
    d = to.preloads_for_critical_force(slack, 0.3)
    assert math.isnan(d.initial_critical_force) and d.to_dict()["initial_critical_force"] is None


# ------------------------------------------------------------------------------------------- stops, the linear law
#: Linear-law chains and targets with equilibria resting on a stop (the reference enumeration finds 1-4 of them).
LINEAR_STOP_CASES = [("heterogeneous", 300, 2.0), ("heterogeneous", 301, 2.0), ("asymmetric", 300, 3.0),
                     ("dy", 302, 3.0), ("large", 302, 2.0)]


def _linear_stop_case(family, seed, scale):
    rng = np.random.default_rng(seed)
    m, dx, dy = _chain(family, rng, "linear", n=int(rng.integers(3, 5)))
    return m, dx * scale, dy * scale + 0.1


@pytest.mark.slow_cases(keep=3)         # the n = 4 cases: the reference enumeration takes ~10 s each
@pytest.mark.parametrize("case", LINEAR_STOP_CASES)
def test_every_equilibrium_under_the_linear_law_with_stops_is_the_reference(case):
    """``stops=True`` under the linear law: the open range's set and the equilibria resting on a stop, equal to the
    reference enumeration (stops, Morse indices, contact torques); the default leaves the stop ones out."""
    m, dx, dy = _linear_stop_case(*case)
    got = _same_sets(m, dx, dy, stops=True)
    assert any(e.at_stop.any() for e in got)
    assert len(to.find_equilibria(m, dx, dy)) == sum(not e.at_stop.any() for e in got)


@needs_phc
@pytest.mark.slow_cases(keep=2)
@pytest.mark.parametrize("case", LINEAR_STOP_CASES)
def test_the_certified_set_under_the_linear_law_with_stops_is_the_reference(case):
    m, dx, dy = _linear_stop_case(*case)
    got = _same_sets(m, dx, dy, method="homotopy", status="certified", stops=True)
    assert any(e.at_stop.any() for e in got)


def test_stops_false_leaves_a_tension_only_chains_stop_equilibria_out():
    """The open range's members: the reference enumeration's equilibria with no joint on a stop."""
    import reference_equilibria_tension as reqs

    m = to.Manipulator.uniform(3, spring="tension_only")
    every, inside = to.find_equilibria(m, 2.0), to.find_equilibria(m, 2.0, stops=False)
    want = [r for r in reqs.equilibria(ref.segs_of(m), 2.0, 0.0) if not r.stops.any()]
    assert len(inside) == len(want) < len(every) and "stops=False" in inside.message
    for r in want:
        assert min(float(np.abs(e.q - r.q).max()) for e in inside) < 1e-7


def test_the_linear_laws_curve_goes_on_resting_on_a_stop():
    """Past dx ~ 3.12 the paper chain's least-energy configuration presses joint 3 on its stop (the issue's figure):
    the curve goes on there (it ended with no stable equilibrium), on the same branch (no jump: the arm reaches the
    stop continuously), each point the brute force's least energy over the closed range."""
    m = to.Manipulator.uniform(4)
    dxs = np.linspace(2.8, 3.6, 9)
    c = _curve_is_the_brute_force(m, dxs, 0.0)
    assert not c.jumps and len(set(c.branch.tolist())) == 1
    assert np.all(np.abs(c.q[-4:]).max(axis=1) >= m.joint_limits.max() * (1 - 1e-9))    # on the stop
    assert np.all(np.abs(c.q[:3]).max(axis=1) < m.joint_limits.max() * (1 - 1e-3))       # inside the range


#: Held-tip moves where the arm snaps at a spring's kink and lands inside the range (a review's random runs).
HELD_SNAPS = [
    (to.Manipulator.uniform(3, a=1.0, b=1.0, k=(0.8776101904028178, 1.434275348278633),
                            L0=(1.0595867772194043, 0.7951188426608309), spring="tension_only"), 0.6751068249918712),
    (to.Manipulator.uniform(3, a=0.807633384489745, b=1.0, k=0.6017360667834929, L0=1.1719713942108982,
                            spring="tension_only"), -1.433772427366471),
]


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("case", range(len(HELD_SNAPS)))
def test_a_held_tip_snap_at_a_kink_lands_where_the_reference_flow_goes(case):
    """The tip moved (held): the branch loses stability where a spring goes slack and the arm snaps, landing inside
    the range. The kink is where a reference spring is at its rest length; the reference projected gradient flow of
    the energy on the tip constraint (LSODA) from where the descent starts lands on the reported configuration; the
    descent starts downhill; the landing is a constrained minimum of the reference energy (SLSQP returns)."""
    import scipy.optimize as so
    from scipy.integrate import solve_ivp

    m, dy_end = HELD_SNAPS[case]
    lim_len = m.straight_length
    T = np.column_stack([np.linspace(0.05, 0.6, 25) * lim_len, np.linspace(0.0, 1.0, 25) * dy_end])
    sim = to.simulate(m, tip="held", targets=T)
    landed = [e for e in sim.events if e.kind == "snap" and e.status == "landed"]
    assert landed, sim.message
    segs = ref.segs_of(m)
    L0 = np.column_stack([m.L1_0, m.L2_0])
    for e in landed:
        assert np.abs(ref.lengths(segs, e.q_before) - L0).min() < 1e-8
        tgt = ref.tip(segs, e.q_before)
        q0 = e.q_before + e.direction * 1e-4 * e.null_vector
        for _ in range(20):                                         # onto the tip constraint
            q0 = q0 - np.linalg.lstsq(ref.tip_jacobian(segs, q0), ref.tip(segs, q0) - tgt, rcond=None)[0]
        assert ref.energy(segs, q0) < ref.energy(segs, e.q_before)

        def flow(_t, q):
            J = ref.tip_jacobian(segs, q)
            Jp = np.linalg.pinv(J)
            return (np.eye(m.n) - Jp @ J) @ ref.torques(segs, q) - 10.0 * Jp @ (ref.tip(segs, q) - tgt)

        q1 = solve_ivp(flow, (0.0, 2e3), q0, method="LSODA", rtol=1e-10, atol=1e-12).y[:, -1]
        assert np.abs(q1 - e.q_after).max() < 1e-6, (q1, e.q_after)
        res = so.minimize(lambda q: ref.energy(segs, q), e.q_after + 1e-3, method="SLSQP",
                          constraints={"type": "eq", "fun": lambda q: ref.tip(segs, q) - tgt},
                          options={"ftol": 1e-15, "maxiter": 500})
        assert np.abs(res.x - e.q_after).max() < 1e-5


def test_a_step_crossing_two_kinks_is_not_taken():
    """A held-tip move across which spring 3.2 goes slack while 4.2 stays taut (a review's reproducer): one step of
    the continuation crossed both kinks and landed on another, unstable branch, reported as a snap that came back
    (``failed``). Now the move is followed, stable, and its end is a constrained minimum of the reference energy."""
    import scipy.optimize as so

    seg = {"a": 1.0, "b": 1.0, "k": [0.8140236185598528, 1.653695828880264],
           "L0": [1.0788728971297559, 0.7363294735243248], "spring": "tension_only"}
    m = to.Manipulator.from_dict({"segments": [seg] * 4})
    T = np.array([[3.15, -2.29091362], [3.33333333, -2.44364119]])
    sim = to.simulate(m, tip="held", targets=T, start=np.array([0.37977371, -0.57175962, -1.03655164, -1.03934059]))
    assert sim.status == "complete" and sim.stable.all() and not sim.snaps
    assert sim.spring_states[-1, 2, 1] == "slack" and sim.spring_states[-1, 3, 1] == "taut"
    segs = ref.segs_of(m)
    tgt = ref.target(segs, *T[-1])
    res = so.minimize(lambda q: ref.energy(segs, q), sim.q[-1] + 1e-3, method="SLSQP",
                      constraints={"type": "eq", "fun": lambda q: ref.tip(segs, q) - tgt},
                      options={"ftol": 1e-15, "maxiter": 500})
    assert np.abs(res.x - sim.q[-1]).max() < 1e-5
