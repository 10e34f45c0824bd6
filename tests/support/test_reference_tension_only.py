"""Self-tests of tests/support/reference_tension_only.py (the independent tension-only / joint-stop reference).

The reference builds the springs from the vertex positions; here it is checked against the closed-form lengths
``2c cos(beta -+ q/2)``, its force-vector torques against central differences of its energy, its stiffness
against second differences, and its brute-force least energy against the figures quoted in the project's issue
(the paper chain, n = 4, a = b = k = L0 = 1: 4.86014 tension-only and 5.18323 linear at dx = 2), a seeded
multistart of SLSQP, and the envelope theorem for the stop's contact torque. ``tensegrity_opt`` is used only as
a container of parameters (:func:`reference_tension_only.segs_of`). Fast: about a second in all.
"""

from __future__ import annotations

import functools
import math

import numpy as np
import pytest
import reference_tension_only as RT  # noqa: E402
import scipy.optimize as so

LAWS = ("linear", "tension_only")


def seg(a=1.0, b=1.0, k1=1.0, k2=1.0, L10=1.0, L20=1.0, law="tension_only"):
    return dict(a=a, b=b, k1=k1, k2=k2, L10=L10, L20=L20, law=law)


def paper(law, n=4):
    return [seg(law=law)] * n


HETERO = [seg(0.8, 1.2, 2.5, 1.5, 1.7, 1.4, "tension_only"), seg(1.0, 1.0, 1.0, 1.0, 1.0, 1.0, "linear"),
          seg(1.1, 0.8, 0.7, 0.9, 1.2, 0.6, "tension_only")]


def random_q(segs, rng, frac=0.98):
    lim = RT.limits(segs)
    return rng.uniform(-frac, frac, len(segs)) * lim


def cos_lengths(segs, q):
    a = np.array([s["a"] for s in segs])
    b = np.array([s["b"] for s in segs])
    c, beta = np.hypot(a, b), np.arctan2(a, b)
    return np.column_stack([2 * c * np.cos(beta + q / 2), 2 * c * np.cos(beta - q / 2)])


@functools.lru_cache(maxsize=None)
def least(law, dx):
    return RT.least_energy(paper(law), dx, 0.0)


# ---------------------------------------------------------------------------- 1. the model from the vertices
@pytest.mark.parametrize("segs", [paper("linear"), HETERO], ids=["paper", "hetero"])
def test_lengths_are_the_cos_formulas(segs):
    rng = np.random.default_rng(1)
    for _ in range(50):
        q = random_q(segs, rng, 1.0)
        assert np.allclose(RT.lengths(segs, q), cos_lengths(segs, q), atol=1e-13, rtol=0)
    lim = RT.limits(segs)
    L = RT.lengths(segs, lim)                 # at the positive stop the first spring's length is 0
    assert np.allclose(L[:, 0], 0.0, atol=1e-12)
    assert np.allclose(RT.lengths(segs, -lim)[:, 1], 0.0, atol=1e-12)


@pytest.mark.parametrize("segs", [paper("linear"), paper("tension_only"), HETERO],
                         ids=["paper-linear", "paper-tension", "hetero"])
def test_torques_are_minus_the_energy_gradient(segs):
    rng = np.random.default_rng(2)
    h = 1e-6
    L0 = np.array([[s["L10"], s["L20"]] for s in segs])
    checked = 0
    while checked < 40:
        q = random_q(segs, rng)
        if np.min(np.abs(RT.lengths(segs, q) - L0)) < 1e-4:           # a tension-only kink: skip
            continue
        fd = np.empty(len(segs))
        for i in range(len(segs)):
            e = np.zeros(len(segs))
            e[i] = h
            fd[i] = (RT.energy(segs, q + e) - RT.energy(segs, q - e)) / (2 * h)
        assert np.allclose(RT.torques(segs, q), -fd, atol=1e-8, rtol=0), q
        checked += 1


def test_torques_at_the_stop_are_the_limit_from_inside():
    segs = HETERO
    lim = RT.limits(segs)
    for sgn in (1.0, -1.0):
        at = RT.torques(segs, sgn * lim)
        near = RT.torques(segs, sgn * (lim - 1e-9))
        assert np.allclose(at, near, atol=1e-7), (at, near)


def test_linear_energy_and_forces():
    segs = [dict(s, law="linear") for s in HETERO]
    rng = np.random.default_rng(3)
    k = np.array([[s["k1"], s["k2"]] for s in segs])
    L0 = np.array([[s["L10"], s["L20"]] for s in segs])
    for _ in range(20):
        q = random_q(segs, rng, 1.0)
        L = cos_lengths(segs, q)
        assert RT.energy(segs, q) == pytest.approx(0.5 * np.sum(k * (L - L0) ** 2), abs=1e-12)
        assert np.allclose(RT.forces(segs, q), k * (L - L0), atol=1e-12)
    # tension-only: the same where taut, nothing where slack
    q = np.array([1.3, 0.0, -1.2])
    T = RT.forces(HETERO, q)
    Lc = cos_lengths(HETERO, q)
    assert np.allclose(T, np.maximum(k * (Lc - L0), 0.0), atol=1e-12)
    assert (T == 0).any() and (T > 0).any()


def test_stiffness_is_the_second_difference_of_the_energy():
    segs = HETERO
    rng = np.random.default_rng(4)
    h = 1e-4
    L0 = np.array([[s["L10"], s["L20"]] for s in segs])
    for _ in range(10):
        q = random_q(segs, rng, 0.9)
        if np.min(np.abs(RT.lengths(segs, q) - L0)) < 1e-2:
            continue
        K = RT.stiffness(segs, q)
        for i in range(len(segs)):
            e = np.zeros(len(segs))
            e[i] = h
            d2 = (RT.energy(segs, q + e) - 2 * RT.energy(segs, q) + RT.energy(segs, q - e)) / h ** 2
            assert K[i] == pytest.approx(d2, abs=1e-5)
    # at the stop: one-sided into the range, agrees with a point just inside
    lim = RT.limits(segs)
    assert np.allclose(RT.stiffness(segs, lim), RT.stiffness(segs, lim - 1e-3), atol=1e-2)


def test_tip_and_mirror_symmetry():
    segs = paper("tension_only")
    assert np.allclose(RT.tip(segs, np.zeros(4)), RT.target(segs, 0.0))
    q = np.array([0.3, -0.2, 1.1, 0.4])
    t, tm = RT.tip(segs, q), RT.tip(segs, -q)
    assert np.allclose(tm, [t[0], -t[1]])
    assert RT.energy(segs, q) == pytest.approx(RT.energy(segs, -q), abs=1e-14)
    h = 1e-6
    J = np.column_stack([(RT.tip(segs, q + h * e) - RT.tip(segs, q - h * e)) / (2 * h) for e in np.eye(4)])
    assert np.allclose(RT.tip_jacobian(segs, q), J, atol=1e-8)


def test_segs_of_reads_a_manipulator():
    from tensegrity_opt import Manipulator, Segment  # a container of parameters only

    m = Manipulator([Segment(0.8, 1.2, (2.5, 1.5), (1.7, 1.4), spring="tension_only"), Segment(1.0, 1.0)])
    assert RT.segs_of(m) == [HETERO[0], dict(HETERO[1])]
    assert RT.segs_of(Manipulator.uniform(4, spring="tension_only")) == paper("tension_only")


# ---------------------------------------------------------------------------- 2. least energy
def test_paper_chain_tension_only_at_dx_2():
    r = least("tension_only", 2.0)
    assert r.energy == pytest.approx(4.86014, abs=1e-4)
    assert np.allclose(RT.tip(paper("tension_only"), r.q), RT.target(paper("tension_only"), 2.0), atol=1e-9)
    assert r.at_stop.sum() == 1 and r.at_stop[2]                   # |q_3| = pi/2 (or its mirror image)
    assert abs(r.q[2]) == pytest.approx(math.pi / 2, abs=1e-7)
    assert np.all(np.abs(r.q) <= RT.limits(paper("tension_only")))
    assert RT.energy(paper("tension_only"), -r.q) == pytest.approx(r.energy, abs=1e-12)
    # KKT: the free joints balance one tip force; the stop pushes the joint back into the range
    assert r.free_residual < 1e-7
    assert r.contact_torques[2] > 0.1 and np.all(r.contact_torques[~r.at_stop] == 0)
    assert -np.sign(r.q[2]) * r.stop_signs[2] > 0


def test_paper_chain_linear_at_dx_2():
    r = least("linear", 2.0)
    assert r.energy == pytest.approx(5.18323, abs=1e-4)
    assert not r.at_stop.any() and r.free_residual < 1e-7


@pytest.mark.parametrize("law", LAWS)
def test_least_energy_beats_a_multistart(law):
    """A seeded multistart of SLSQP from random points of the range finds nothing lower."""
    segs = paper(law)
    tgt = RT.target(segs, 2.0)
    lim = RT.limits(segs)
    r = least(law, 2.0)
    rng = np.random.default_rng(5)
    cons = {"type": "eq", "fun": lambda q: RT.tip(segs, q) - tgt}
    for _ in range(15):
        s = so.minimize(lambda q: RT.energy(segs, q), rng.uniform(-lim, lim), method="SLSQP",
                        bounds=list(zip(-lim, lim)), constraints=[cons], options={"ftol": 1e-12, "maxiter": 500})
        if s.success and np.max(np.abs(RT.tip(segs, s.x) - tgt)) < 1e-8:
            assert s.fun >= r.energy - 1e-8


def test_contact_torque_is_the_envelope_slope():
    """Holding the stop joint a little inside its stop, the least energy grows at the contact torque's rate."""
    segs = paper("tension_only")
    r = least("tension_only", 2.0)
    tgt = RT.target(segs, 2.0)
    lim = RT.limits(segs)
    i = int(np.flatnonzero(r.at_stop)[0])
    free = [j for j in range(4) if j != i]

    def held(d):
        def full(x):
            q = np.empty(4)
            q[free] = x
            q[i] = r.q[i] - np.sign(r.q[i]) * d
            return q
        s = so.minimize(lambda x: RT.energy(segs, full(x)), r.q[free], method="SLSQP",
                        bounds=list(zip(-lim[free], lim[free])),
                        constraints=[{"type": "eq", "fun": lambda x: RT.tip(segs, full(x)) - tgt}],
                        options={"ftol": 1e-15, "maxiter": 500})
        assert np.max(np.abs(RT.tip(segs, full(s.x)) - tgt)) < 1e-9
        return s.fun

    d = 1e-3
    slope = (4 * held(d) - 3 * held(0.0) - held(2 * d)) / (2 * d)          # second-order one-sided
    assert slope == pytest.approx(r.contact_torques[i], rel=1e-3)


@pytest.mark.parametrize("law, dx, E", [("tension_only", 1.5, 4.7827541), ("tension_only", 3.0, 5.2937640),
                                        ("linear", 1.5, 4.8810009), ("linear", 3.0, 5.7954015)])
def test_paper_chain_other_deflections_independent_of_the_grid(law, dx, E):
    coarse = RT.least_energy(paper(law), dx, grid=41)
    assert coarse.energy == pytest.approx(least(law, dx).energy, abs=1e-8)
    assert least(law, dx).energy == pytest.approx(E, abs=1e-6)


def test_n2_and_n3_and_unreachable():
    segs = paper("tension_only", 2)
    r = RT.least_energy(segs, 0.5)
    assert np.allclose(RT.tip(segs, r.q), RT.target(segs, 0.5), atol=1e-9)
    q2 = math.acos((2.5 ** 2 - 2 ** 2 - 1) / (2 * 2 * 1))          # law of cosines: |joint 1 -> target| = 2.5
    q_ik = np.array([-math.atan2(math.sin(q2), 2 + math.cos(q2)), q2])
    assert r.energy == pytest.approx(RT.energy(segs, q_ik), abs=1e-12)
    assert np.allclose(np.abs(r.q), np.abs(q_ik), atol=1e-9)
    r3 = RT.least_energy(HETERO, 0.8, 0.3)
    assert np.allclose(RT.tip(HETERO, r3.q), RT.target(HETERO, 0.8, 0.3), atol=1e-9)
    assert np.all(np.abs(r3.q) <= RT.limits(HETERO))
    with pytest.raises(ValueError):
        RT.least_energy(paper("linear", 3), -1.0)                   # beyond the straight chain's reach
    with pytest.raises(ValueError):
        RT.least_energy(paper("linear", 5), 1.0)
