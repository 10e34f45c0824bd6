"""Self-tests of tests/support/reference_paths.py (the independent path / limit-point references).

No import of ``tensegrity_opt``: these check the references against closed forms, against
reference_model (bordered determinant with brentq for the critical loads) and against each
other (natural path + bisection + extended system vs the joint-angle parametrisation).
Fast: a few seconds in all.
"""

from __future__ import annotations

import functools

import numpy as np
import pytest
import reference_model as R  # noqa: E402
import reference_paths as RP  # noqa: E402

# (a, b, k, L0) per segment, symmetric springs
STRAIGHT = {
    "paper4": [(1.0, 1.0, 1.0, 1.0)] * 4,
    "G1x3": [(0.8, 1.2, 2.5, 1.7)] * 3,
    "hetero3": [(1.0, 1.0, 1.0, 1.0), (0.9, 1.3, 2.0, 1.5), (1.1, 0.8, 0.7, 0.9)],
}
# pre-bent: every segment's first spring 0.1 shorter
PRE_BENT = [(1.0, 1.0, 1.0, 1.0, 0.9, 1.0)] * 3
# bistable: K = k (b L0 - 2 (b^2 - a^2)) = -0.5, wells at +-1.682137 rad
BISTABLE = [(0.5, 1.0, 1.0, 1.0)] * 3
# one bistable segment with wells inside +-pi/2 (a tip force along y acts like a torque)
ONE_SEG = [(0.6, 1.0, 1.0, 1.0)]


@functools.lru_cache(maxsize=None)
def chain(name):
    table = {**STRAIGHT, "pre_bent": PRE_BENT, "bistable": BISTABLE, "one_seg": ONE_SEG}
    return R.Chain.from_segments(table[name])


def bistable_rest():
    w = RP.segment_wells(0.5, 1.0, 1.0, 1.0, 1.0, 1.0)
    return np.full(3, w[1])


@functools.lru_cache(maxsize=None)
def limit(name, boundary, max_load):
    c = chain(name)
    q0 = bistable_rest() if name == "bistable" else RP.rest_configuration(c)
    return RP.limit_load_reference(c, q0, (-1.0, 0.0), boundary, max_load)


# --------------------------------------------------------------------------- building blocks
def test_fast_hessian_matches_reference_model():
    rng = np.random.default_rng(0)
    for n in (1, 3, 5):
        c = R.Chain.from_segments([(0.8 + 0.1 * i, 1.0 + 0.1 * i, 1.0, 1.2) for i in range(n)])
        q = rng.uniform(-1.0, 1.0, n)
        F = rng.normal(size=2)
        np.testing.assert_allclose(RP.lagrangian_hess(c, q, F), c.lagrangian_hess(q, F), atol=1e-13)
        np.testing.assert_allclose(RP.lagrangian_hess(c, q, F), c.lagrangian_hess_fd(q, F), atol=1e-7)


@pytest.mark.parametrize("boundary", ["free", "guided", "displacement"])
def test_path_system_jacobians_by_finite_differences(boundary):
    c = chain("bistable")
    system = RP.PathSystem(c, bistable_rest() * 0.7, (-0.6, 0.8), boundary)
    rng = np.random.default_rng(1)
    z = np.concatenate([bistable_rest() * 0.7 + 0.1 * rng.normal(size=3), rng.normal(size=system.m - 3)])
    t, h = 0.3, 1e-6
    Jz = np.column_stack([(system.residual(z + h * e, t) - system.residual(z - h * e, t)) / (2 * h)
                          for e in np.eye(system.m)])
    np.testing.assert_allclose(system.jac_z(z, t), Jz, atol=1e-8)
    Jt = (system.residual(z, t + h) - system.residual(z, t - h)) / (2 * h)
    np.testing.assert_allclose(system.jac_t(z, t), Jt, atol=1e-8)


# --------------------------------------------------------------------------- straight chains
def test_paper_chain_critical_loads():
    """``docs/model.md``: guided 0.572793 (1.362906, 1.921444), free 0.0761205."""
    c = chain("paper4")
    Pg, _ = RP.buckling_modes(c, "guided")
    Pf, _ = RP.buckling_modes(c, "free")
    np.testing.assert_allclose(Pg, [0.572793, 1.362906, 1.921444], atol=1e-6)
    assert Pf[0] == pytest.approx(0.0761205, abs=1e-7)
    # the other route (finite-difference K, G, S0 and a bordered determinant)
    np.testing.assert_allclose(Pg, R.critical_loads_guided(c), rtol=1e-8)
    np.testing.assert_allclose(Pf, R.critical_loads_free(c), rtol=1e-8)


@pytest.mark.parametrize("n", [2, 3, 4, 5])
@pytest.mark.parametrize("geom", [(1.0, 1.0, 1.0, 1.0), (0.8, 1.2, 2.5, 1.7)])
def test_free_critical_loads_closed_form(n, geom):
    """A uniform free-tip chain (links 2b, ..., 2b, b): P_j = (K / b) (1 - cos((2j - 1) pi / (2n)))
    (found here, checked against the eigenproblem to rounding)."""
    c = R.Chain.uniform(n, *geom)
    K = c.symmetric_K()[0]
    j = np.arange(1, n + 1)
    closed = K / geom[1] * (1.0 - np.cos((2 * j - 1) * np.pi / (2 * n)))
    np.testing.assert_allclose(RP.buckling_modes(c, "free")[0], closed, rtol=1e-12)


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("name", sorted(STRAIGHT))
@pytest.mark.parametrize("boundary", ["free", "guided"])
def test_limit_load_of_straight_chain_is_its_critical_load(name, boundary):
    c = chain(name)
    P, V = RP.buckling_modes(c, boundary)
    res = limit(name, boundary, float(1.5 * P[0]))
    t, q, force, kind = res
    assert kind == "bifurcation" and res.reason is None
    assert t == pytest.approx(P[0], rel=1e-9)
    np.testing.assert_allclose(q, 0.0, atol=1e-9)
    np.testing.assert_allclose(force[0], -P[0], rtol=1e-9)
    assert abs(res.lam_min) < 1e-8
    # the null vector of R_z is the buckling mode
    v = res.phi[:c.n] / np.linalg.norm(res.phi[:c.n])
    assert abs(v @ V[:, 0]) == pytest.approx(1.0, abs=1e-8)
    # the natural path: straight and stable below P, the eigenvalue crossing at P
    assert np.all(res.path.lam_min > 0) and res.path.t[-1] == pytest.approx(P[0], rel=1e-10)


@pytest.mark.parametrize("boundary", ["free", "guided"])
def test_paper_chain_pitchfork_is_supercritical(boundary):
    """The branch born at the first critical load carries more load as it bends and is stable."""
    P = RP.buckling_modes(chain("paper4"), boundary)[0][0]
    t, lam, _ = RP.post_buckling(chain("paper4"), boundary)
    assert np.all(t > P) and np.all(np.diff(t) > 0)
    assert np.all(lam > 0)
    # t - P ~ c amp^2
    ratio = (t - P) / np.array([1e-3, 1e-2, 0.05, 0.1]) ** 2
    assert ratio[1] == pytest.approx(ratio[0], rel=0.05)


def test_load_path_straight_chain():
    c = chain("paper4")
    ts = np.linspace(0.0, 1.0, 21)
    p = RP.load_path(c, np.zeros(4), (-1.0, 0.0), "guided", ts)
    assert p.status == "done" and p.t.size == ts.size
    np.testing.assert_allclose(p.q, 0.0, atol=1e-12)
    P = RP.buckling_modes(c, "guided")[0][0]
    assert np.all((p.lam_min > 0) == (p.t < P))
    for q, F in zip(p.q, p.force):
        assert RP.equilibrium_residual(c, q, F) < 1e-12


# --------------------------------------------------------------------------- pre-bent chain
def test_pre_bent_free_path_is_smooth_to_the_joint_limit():
    """Free compression of the pre-bent arm: no fold, no branch point (quasi-buckling); the
    smallest eigenvalue stays positive through the straight chain's critical load and the
    path ends on the joint range (q_1 -> pi - 2 beta) at t = 0.324031."""
    c = chain("pre_bent")
    P_straight = RP.buckling_modes(R.Chain.uniform(3, 1.0, 1.0, 1.0, 1.0), "free")[0][0]
    res = limit("pre_bent", "free", 2.0)
    assert res.kind == "none" and res.reason == "joint_limit"
    assert res.t == pytest.approx(0.324031, abs=1e-5)
    assert res.q[0] == pytest.approx(c.limits[0], abs=1e-6)
    p = res.path
    assert p.t[0] < P_straight < p.t[-1]
    assert np.all(p.lam_min > 0.3)
    for q, F in zip(p.q, p.force):
        assert RP.equilibrium_residual(c, q, F) < 1e-10


def test_pre_bent_guided_path_folds():
    """Guided (tip y held), the same arm snaps: a fold at t = 0.825957 (load maximum)."""
    c = chain("pre_bent")
    res = limit("pre_bent", "guided", 2.0)
    assert res.kind == "fold" and res.extended_converged
    assert res.t == pytest.approx(0.8259571826, abs=1e-9)
    np.testing.assert_allclose(res.q, [-0.6989828234, 1.3732507903, 1.1159102153], atol=1e-6)
    assert res.force[1] == pytest.approx(-0.5282683382, abs=1e-8)
    assert res.u_dot_rt > 0.1 and abs(res.lam_min) < 1e-10
    assert RP.equilibrium_residual(c, res.q, res.force) < 1e-12
    # route 2: the joint-angle parametrisation, t maximised along it
    system = RP.PathSystem(c, RP.rest_configuration(c), (-1.0, 0.0), "guided")
    t2, z2 = RP.fold_by_coordinate(system, res.z, res.t)
    assert t2 == pytest.approx(res.t, abs=1e-10)
    np.testing.assert_allclose(z2[:3], res.q, atol=1e-5)
    # the load is a maximum: just below, two equilibria (stable and unstable) are near
    assert res.path.t[-1] <= res.t + 1e-12


# --------------------------------------------------------------------------- bistable chains
@pytest.mark.parametrize("boundary, t_ref", [("free", 0.42740084255), ("guided", 0.43219959466)])
def test_bistable_chain_folds(boundary, t_ref):
    c = chain("bistable")
    res = limit("bistable", boundary, 2.0)
    assert res.kind == "fold" and res.extended_converged
    assert res.t == pytest.approx(t_ref, abs=1e-9)
    assert res.u_dot_rt > 0.1 and abs(res.lam_min) < 1e-10
    system = RP.PathSystem(c, bistable_rest(), (-1.0, 0.0), boundary)
    t2, _ = RP.fold_by_coordinate(system, res.z, res.t)
    assert t2 == pytest.approx(res.t, abs=1e-10)


def test_single_bistable_segment_fold_closed_form():
    """n = 1 under a tip force along +y (a torque t b cos q): the curve t(q) = E'(q) / (b cos q)
    has a maximum (fold, stability lost) at q = -0.997415, t = 0.218830 and by symmetry a
    minimum at q = +0.997415, t = -0.218830 (stability regained)."""
    c = chain("one_seg")
    folds = RP.single_segment_folds(c, (0.0, 1.0), -1.5, 1.5)
    assert len(folds) == 2
    (q1, t1), (q2, t2) = folds
    assert q1 == pytest.approx(-0.99741498512, abs=1e-9) and t1 == pytest.approx(0.21882968297, abs=1e-10)
    assert q2 == pytest.approx(-q1, abs=1e-12) and t2 == pytest.approx(-t1, abs=1e-12)
    w = RP.segment_wells(0.6, 1.0, 1.0, 1.0, 1.0, 1.0)
    res = RP.limit_load_reference(c, [w[0]], (0.0, 1.0), "free", 1.0)
    assert res.kind == "fold" and res.t == pytest.approx(t1, abs=1e-10)
    assert res.q[0] == pytest.approx(q1, abs=1e-6)


def test_fold_in_displacement_bistable():
    """Displacement control (dx grows, dy = 0) of the 3-segment bistable chain from its
    (+, +, +) rest: a turning point in dx at dx = 1.973177, by two routes."""
    c = chain("bistable")
    res = RP.fold_in_displacement(c, bistable_rest(), (1.0, 0.0), t_max=3.0)
    assert res.kind == "fold" and res.extended_converged
    assert res.t == pytest.approx(1.97317671982, abs=1e-9)
    assert res.t_coordinate == pytest.approx(res.t, abs=1e-10)
    np.testing.assert_allclose(res.force, [-0.414126, -0.066291], atol=2e-6)
    assert abs(res.lam_min) < 1e-10


def test_energy_integral_on_a_reference_displacement_path():
    """The refinement integral of F . dtip reproduces E(end) - E(start) on a coarse path."""
    c = chain("bistable")
    p = RP.displacement_path(c, bistable_rest(), (1.0, 0.0), np.linspace(0.0, 1.5, 16))
    assert p.status == "done"
    exact = c.energy(p.q[-1]) - c.energy(p.q[0])
    integral, trap = RP.energy_integral(c, p.q, p.force, w=(-1.0, 0.0))
    assert integral == pytest.approx(exact, rel=1e-10)
    assert trap == pytest.approx(exact, rel=1e-2)       # the plain trapezoid is O(h^2) only
    assert abs(trap - exact) > 1e-5 * abs(exact)
    # very coarse points (0.5 rad steps) are split and still integrate exactly
    sub = slice(0, None, 5)
    integral2, _ = RP.energy_integral(c, p.q[sub], p.force[sub], w=(-1.0, 0.0))
    assert integral2 == pytest.approx(exact, rel=1e-10)


def test_displacement_to_straight_sub_arm_is_not_a_fold():
    """A path that straightens the arm beyond a joint (J loses rank, F diverges) is reported
    as a kinematic singularity, not as a fold."""
    c = R.Chain.from_segments([(1.0, 1.0, 1.0, 1.0), (0.6, 1.0, 1.0, 1.0), (1.0, 1.0, 1.0, 1.0)])
    w = RP.segment_wells(0.6, 1.0, 1.0, 1.0, 1.0, 1.0)
    res = RP.fold_in_displacement(c, np.array([0.0, w[0], 0.0]), (0.0, -1.0), t_max=3.0)
    assert res.kind == "none" and res.reason == "kinematic_singularity"


def test_first_segment_bent_guided_has_a_branch_point():
    """Only segment 1 pre-bent, guided: (q1*, 0, 0, 0) with the force along the arm
    (Fy = Fx tan q1*) is an exact equilibrium for every load, and it loses stability at a
    branch point (u . R_t = 0) -- not at a fold. The guide is not perpendicular to the arm, so
    the branch point is not a symmetric pitchfork; numerically it is fragile (a round-off
    imperfection makes a natural path slide onto the crossing branch), so it is located here
    on the exact trivial solution."""
    import scipy.optimize as so

    c = R.Chain.from_segments([(1.0, 1.0, 1.0, 1.0, 0.9, 1.0)] + [(1.0, 1.0, 1.0, 1.0)] * 3)
    q_r = RP.rest_configuration(c)
    assert np.all(q_r[1:] == 0.0)
    system = RP.PathSystem(c, q_r, (-1.0, 0.0), "guided")

    def z_of(t):
        return np.concatenate([q_r, [-t * np.tan(q_r[0])]])
    for t in (0.1, 0.5, 0.9):
        assert np.max(np.abs(system.residual(z_of(t), t))) < 1e-12
    t_c = so.brentq(lambda t: system.lam_min(z_of(t), t), 0.3, 0.8, xtol=1e-14)
    assert t_c == pytest.approx(0.56184376, abs=1e-7)
    kind, _, _ = RP.classify_singular_point(system, z_of(t_c), t_c)
    assert kind == "bifurcation"
