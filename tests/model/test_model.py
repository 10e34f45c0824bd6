"""Segment and Manipulator: validation, springs, torque (eq. 1-3), kinematics (eq. 5, 7)."""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from tensegrity_opt import InvalidParameterError, Manipulator, Segment, UnreachableTargetError


def eq2_torque(a, b, k, L0, q):
    """The paper's eq. (2) for a symmetric segment (independent of the general form)."""
    c, beta = math.hypot(a, b), math.atan2(a, b)
    return 2 * c * k * (c * math.cos(2 * beta) * math.sin(q) - L0 * math.cos(beta) * math.sin(q / 2))


def eq3_dtorque(a, b, k, L0, q):
    c, beta = math.hypot(a, b), math.atan2(a, b)
    return c * k * (2 * c * math.cos(2 * beta) * math.cos(q) - L0 * math.cos(beta) * math.cos(q / 2))


@pytest.mark.parametrize("a,b,k,L0", [(1, 1, 1, 1), (0.6, 1.3, 2.5, 1.9), (1.4, 0.7, 0.3, 0.5)])
@pytest.mark.parametrize("frac", [-0.9, -0.2, 0.0, 0.35, 0.95])
def test_torque_matches_eq2_and_eq3(a, b, k, L0, frac):
    s = Segment(a, b, k, L0)
    q = frac * s.joint_limit
    assert s.torque(q) == pytest.approx(eq2_torque(a, b, k, L0, q), rel=1e-12, abs=1e-14)
    assert s.dtorque(q) == pytest.approx(eq3_dtorque(a, b, k, L0, q), rel=1e-12, abs=1e-14)


def test_eq1_general_form_for_asymmetric_segment():
    s = Segment(0.8, 1.1, (1.5, 0.7), (1.2, 1.9))
    c, beta = s.c, s.beta
    for q in (-0.5, 0.2, 0.9):
        t1, t2 = 2 * beta + q, 2 * beta - q
        L1 = math.sqrt(2 * c * c + 2 * c * c * math.cos(t1))
        L2 = math.sqrt(2 * c * c + 2 * c * c * math.cos(t2))
        M1 = 1.5 * (1 - 1.2 / L1) * c * c * math.sin(t1)
        M2 = -0.7 * (1 - 1.9 / L2) * c * c * math.sin(t2)
        assert s.torque(q) == pytest.approx(M1 + M2, rel=1e-12)
        h = 1e-6
        assert s.torque(q) == pytest.approx(-(s.energy(q + h) - s.energy(q - h)) / (2 * h), rel=1e-7)
        assert s.dtorque(q) == pytest.approx((s.torque(q + h) - s.torque(q - h)) / (2 * h), rel=1e-6)


def test_spring_lengths_and_forces():
    s = Segment(1, 1, 2.0, 1.5)
    L1, L2 = s.spring_lengths(0.0)
    assert L1 == pytest.approx(2.0) and L2 == pytest.approx(2.0)
    F1, F2 = s.spring_forces(0.0)
    assert F1 == pytest.approx(2.0 * 0.5) and F2 == pytest.approx(1.0)
    # at the range bound one spring length reaches zero
    L1, _ = s.spring_lengths(s.joint_limit)
    assert L1 == pytest.approx(0.0, abs=1e-12)


@pytest.mark.parametrize("a,b,L0", [(1, 1, 1), (0.5, 1, 1.6), (0.5, 1, 1.4), (0.2, 2, 0.5)])
def test_joint_stiffness_and_condition4(a, b, L0):
    s = Segment(a, b, 3.0, L0)
    assert s.stiffness == pytest.approx(3.0 * (b * L0 - 2 * (b * b - a * a)), rel=1e-12, abs=1e-12)
    assert s.condition4 == (L0 > 2 * b * (1 - (a / b) ** 2))


def test_paper_segment_is_monotonic():
    assert Segment(1, 1, 1, 1).monotonic()
    assert not Segment(0.5, 1, 1, 0.5).monotonic()


@pytest.mark.parametrize("kwargs,field", [
    (dict(a=0, b=1), "a"), (dict(a=1, b=-1), "b"), (dict(a=1, b=float("nan")), "b"),
    (dict(a=1, b=1, k=float("inf")), "k"), (dict(a=1, b=1, k=(1, 0)), "k[1]"),
    (dict(a=1, b=1, L0=(1, 2, 3)), "L0"), (dict(a="x", b=1), "a"),
])
def test_segment_validation_names_field(kwargs, field):
    with pytest.raises(InvalidParameterError) as ei:
        Segment(**kwargs)
    assert isinstance(ei.value, ValueError)
    assert ei.value.field == field


@pytest.mark.parametrize("n", [0, -1, 2.5, True])
def test_uniform_validation(n):
    with pytest.raises(ValueError) as ei:
        Manipulator.uniform(n)
    assert ei.value.field == "n"


def test_manipulator_validation():
    with pytest.raises(InvalidParameterError) as ei:
        Manipulator([])
    assert ei.value.field == "segments"
    with pytest.raises(InvalidParameterError) as ei:
        Manipulator([Segment(1, 1), "nope"])
    assert ei.value.field == "segments[1]"


def test_tip_equals_eq5_for_equal_b():
    m = Manipulator.uniform(4, a=0.7, b=1.3)
    q = np.array([0.2, -0.1, 0.3, -0.25])
    b = 1.3
    ph = np.cumsum(q)
    x = b + 2 * b * np.cos(ph[:3]).sum() + b * np.cos(ph[3])
    y = 2 * b * np.sin(ph[:3]).sum() + b * np.sin(ph[3])
    assert np.allclose(m.tip(q), [x, y], rtol=1e-14)
    assert m.tip(np.zeros(4)) == pytest.approx([8 * 1.3, 0.0])


def test_tip_with_different_b_and_jacobian_by_finite_differences():
    m = Manipulator([Segment(1, 0.5), Segment(1, 1.5), Segment(0.3, 0.9)])
    assert m.straight_length == pytest.approx(2 * (0.5 + 1.5 + 0.9))
    # joint positions by walking the links explicitly
    q = np.array([0.3, -0.4, 0.2])
    p = np.array([0.5, 0.0])
    ang = 0.0
    lengths = [0.5 + 1.5, 1.5 + 0.9, 0.9]
    for qi, L in zip(q, lengths):
        ang += qi
        p = p + L * np.array([math.cos(ang), math.sin(ang)])
    assert np.allclose(m.tip(q), p, rtol=1e-14)
    J = m.jacobian(q)
    h = 1e-6
    for i in range(3):
        e = np.zeros(3)
        e[i] = h
        assert np.allclose(J[:, i], (m.tip(q + e) - m.tip(q - e)) / (2 * h), atol=1e-8)


def test_batched_tip_kinematics_is_the_walk_and_finite_differences_row_by_row():
    """``tip_kinematics`` on many rows (large angles, different b): each row's tip is the explicit walk of the links
    and its Jacobian the central differences of that walk."""
    m = Manipulator([Segment(1, 0.5), Segment(0.7, 1.5), Segment(0.3, 0.9), Segment(0.6, 1.1)])
    lengths = np.array([0.5 + 1.5, 1.5 + 0.9, 0.9 + 1.1, 1.1])

    def walk(q):
        ang = np.cumsum(q)
        return np.array([0.5 + lengths @ np.cos(ang), lengths @ np.sin(ang)])

    Q = np.random.default_rng(4).uniform(-0.95, 0.95, (7, 4)) * m.joint_limits
    k = m.tip_kinematics(Q)
    h = 1e-6
    for r, q in enumerate(Q):
        assert np.allclose(k.tip[r], walk(q), rtol=1e-14, atol=1e-14)
        assert np.allclose(k.cos[r], np.cos(np.cumsum(q))) and np.allclose(k.sin[r], np.sin(np.cumsum(q)))
        for i in range(4):
            e = np.zeros(4)
            e[i] = h
            fd = (walk(q + e) - walk(q - e)) / (2 * h)
            assert abs(k.Jx[r, i] - fd[0]) < 1e-8 and abs(k.Jy[r, i] - fd[1]) < 1e-8


def test_paper_jacobian_eq12_at_small_angles():
    # eq. (12): J^T = b [[-7q1-5q2-3q3-q4, 7], [-5q1-5q2-3q3-q4, 5], ...] (linearised)
    m = Manipulator.uniform(4)
    q = 1e-5 * np.array([1.0, -2.0, 0.5, 3.0])
    S1 = -np.array([[7, 5, 3, 1], [5, 5, 3, 1], [3, 3, 3, 1], [1, 1, 1, 1]], float)
    J = m.jacobian(q)
    assert np.allclose(J[0], S1 @ q, rtol=1e-8, atol=1e-14)
    assert np.allclose(J[1], [7, 5, 3, 1], rtol=1e-8)


def test_reachability():
    m = Manipulator.uniform(4)
    with pytest.raises(UnreachableTargetError) as ei:
        m.check_reachable(-0.1)
    assert isinstance(ei.value, ValueError) and ei.value.field == "dx"
    with pytest.raises(UnreachableTargetError) as ei:
        m.check_reachable(0.0, 0.5)
    assert ei.value.field == "dy"
    with pytest.raises(InvalidParameterError):
        m.check_reachable(float("nan"))
    assert m.check_reachable(0.5, 0.5) == pytest.approx([7.5, 0.5])


def test_physical_range():
    m = Manipulator.uniform(2, a=1, b=1)
    assert m.joint_limits == pytest.approx([math.pi / 2] * 2)
    assert m.in_range([1.5, -1.5]) and not m.in_range([math.pi / 2, 0.0])


def test_roundtrip_dict():
    m = Manipulator([Segment(1, 1, (1, 2), 1.0), Segment(0.5, 2.0, 3.0, (1.0, 1.5))])
    assert Manipulator.from_dict(m.to_dict()) == m
    assert Manipulator.from_dict({"n": 3, "a": 1, "b": 2, "k": 1, "L0": 3}) == Manipulator.uniform(3, 1, 2, 1, 3)


# ----------------------------------------------------------------------------- unloaded critical angles
def _critical_by_grid(seg, num=400001):
    """Wells and hilltops of the unloaded segment by an independent route: the torque on a fine grid (shifted
    off q = 0), each sign change refined by scipy's brentq to the last bits; + to - is a well (M = -E')."""
    lim = seg.joint_limit
    qs = np.linspace(-lim, lim, num)[1:-1] + 0.37 * (2 * lim / (num - 1))
    qs = qs[np.abs(qs) < lim]
    M = seg.torque(qs)
    wells, tops = [], []
    for i in np.flatnonzero(np.sign(M[:-1]) != np.sign(M[1:])):
        root = brentq(lambda q: float(seg.torque(q)), float(qs[i]), float(qs[i + 1]), xtol=1e-15, rtol=1e-15)
        (wells if M[i] > 0 else tops).append(root)
    return np.array(wells), np.array(tops)


def _random_segment(rng, family):
    if family == "monotonic":
        a, b, k = rng.uniform(0.3, 1.2), rng.uniform(0.8, 1.5), rng.uniform(0.3, 3.0)
        K = k * rng.uniform(0.2, 2.0)
        return Segment(a, b, k, (2 * (b * b - a * a) + K / k) / b)
    if family == "bistable":
        a, b, k = rng.uniform(0.3, 0.6), rng.uniform(0.9, 1.4), rng.uniform(0.3, 3.0)
        K = -k * rng.uniform(0.05, 0.8) * (b * b - a * a)
        return Segment(a, b, k, (2 * (b * b - a * a) + K / k) / b)
    if family == "asymmetric":
        a, b = rng.uniform(0.3, 0.8), rng.uniform(0.9, 1.4)
        L = 2 * (b * b - a * a) / b
        return Segment(a, b, tuple(rng.uniform(0.3, 3.0, 2)), tuple(L * rng.uniform(0.6, 1.5, 2)))
    if family == "a > b":
        a, b = rng.uniform(1.1, 1.6), rng.uniform(0.5, 1.0)
        return Segment(a, b, rng.uniform(0.3, 3.0), rng.uniform(0.2, 3.0))
    if family == "K ~ 0":
        a, b, k = rng.uniform(0.3, 0.6), rng.uniform(0.9, 1.4), rng.uniform(0.3, 3.0)
        K = k * rng.choice([-1.0, 1.0]) * rng.uniform(1e-7, 1e-5) * (a * a + b * b)
        return Segment(a, b, k, (2 * (b * b - a * a) + K / k) / b)
    raise ValueError(family)


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("family", ["monotonic", "bistable", "asymmetric", "a > b", "K ~ 0"])
def test_critical_angles_match_an_independent_grid_and_bisection(family):
    rng = np.random.default_rng(sum(map(ord, family)))
    kinds = set()
    for _ in range(25):
        seg = _random_segment(rng, family)
        wells, tops = seg.critical_angles()
        ref_wells, ref_tops = _critical_by_grid(seg)
        assert wells.shape == ref_wells.shape and tops.shape == ref_tops.shape, (seg, wells, ref_wells, tops, ref_tops)
        np.testing.assert_allclose(wells, ref_wells, rtol=0, atol=1e-9)
        np.testing.assert_allclose(tops, ref_tops, rtol=0, atol=1e-9)
        np.testing.assert_array_equal(seg.critical_points(), np.sort(np.concatenate([wells, tops])))
        assert np.all(np.abs(seg.critical_points()) < seg.joint_limit)
        assert np.all(np.abs(seg.torque(seg.critical_points())) <= 1e-12 * max(seg.k1, seg.k2) * seg.c ** 2)
        if seg.symmetric:
            np.testing.assert_array_equal(seg.critical_points(), -seg.critical_points()[::-1])
        kinds.add((wells.size, tops.size))
    if family in ("bistable", "K ~ 0"):
        assert (2, 1) in kinds                          # both wells and the hilltop between them
    if family == "monotonic":
        assert kinds == {(1, 0)}


def test_torque_polynomial_is_the_torque_on_the_unit_circle():
    seg = Segment(0.7, 1.1, (1.3, 0.6), (1.4, 0.9))
    coef = seg.torque_polynomial()
    for q in (-1.2, -0.3, 0.0, 0.5, 1.4):
        z = np.exp(0.5j * q)
        assert sum(c * z ** p for p, c in coef.items()) == pytest.approx(-float(seg.torque(q)), abs=1e-13)


def test_equilibrium_residuals_of_rows_equal_the_residual_of_each_row():
    """The vectorised residual of a global search's batch is the one-row residual, row by row (NaN stays NaN)."""
    rng = np.random.default_rng(7)
    for m in (Manipulator.uniform(4), Manipulator.uniform(3, 0.5, 1.0, 1.0, 1.0),
              Manipulator([Segment(1.0, 1.2, (1.0, 2.0), (1.05, 0.95)), Segment(0.8, 1.0, 1.5, 1.0)])):
        Q = rng.uniform(-1.0, 1.0, size=(40, m.n)) * m.joint_limits
        F = rng.normal(size=(40, 2))
        target = m.target(0.3, 0.1)
        got = m.equilibrium_residuals(Q, F, target)
        want = [m.equilibrium_residual(q, f, target) for q, f in zip(Q, F)]
        np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-15)
        Q[3, 0] = np.nan
        assert np.isnan(m.equilibrium_residuals(Q, F, target)[3])


@pytest.mark.parametrize(("d", "words"), [
    ({"segments": [{"a": 1, "b": 1, "k": 1, "l0": 1}]}, "segments[0].l0: unknown key; did you mean L0?"),
    ({"n": 3, "A": 1.0}, "A: unknown key; did you mean a?"),
    ({"segments": [], "segs": 1}, "segs: unknown key; did you mean segments?")])
def test_from_dict_names_a_misspelt_key_and_its_nearest_name(d, words):
    with pytest.raises(InvalidParameterError) as info:
        Manipulator.from_dict(d)
    assert str(info.value) == words and info.value.field == words.split(":")[0]
