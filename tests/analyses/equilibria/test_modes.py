"""Masses and vibration modes (issue "weights and loads anywhere", item 4).

Expected numbers come from the independent reference ``tests/support/reference_dynamics.py`` (the bodies'
centroids and orientations from the triangles' vertices, the mass matrix and the stiffness by differences of
positions and of the reference torques, ``scipy.linalg.eigh``), or from a closed form (one segment), never from
the code under test.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import reference_dynamics as rd
import reference_tension_only as ref

import tensegrity_opt as to
from tensegrity_opt.errors import InvalidParameterError

FAMILIES = ("monotonic", "bistable", "heterogeneous", "asymmetric", "dy", "large")


def _chain(family: str, rng: np.random.Generator, spring: str = "linear", n: int = 4):
    """A random chain of one family with random masses, inertias and payload, and a deflection (dx, dy != 0)."""
    u = lambda lo, hi: float(rng.uniform(lo, hi))  # noqa: E731
    if family == "monotonic":
        geo = [dict(a=u(0.8, 1.2), b=1.0, k=u(0.5, 2.0), L0=u(0.8, 1.2))] * n
        dx = u(0.05, 0.6) * n / 4
    elif family == "bistable":
        geo = [dict(a=0.5, b=1.0, k=u(0.5, 2.0), L0=u(0.4, 0.6))] * n
        dx = u(0.1, 0.6) * n / 4
    elif family == "heterogeneous":
        geo = [dict(a=u(0.6, 1.4), b=u(0.6, 1.4), k=u(0.5, 2.0), L0=u(0.7, 1.3)) for _ in range(n)]
        dx = u(0.05, 0.3) * 0.5 * sum(g["b"] for g in geo)
    elif family == "asymmetric":
        geo = [dict(a=1.0, b=1.0, k=(u(0.8, 1.2), u(1.2, 1.8)), L0=(u(0.9, 1.1), u(0.7, 0.95)))] * n
        dx = u(0.1, 0.5) * n / 4
    elif family == "dy":
        geo = [dict(a=1.0, b=1.0, k=u(0.5, 2.0), L0=1.0)] * n
        dx = u(0.1, 0.5) * n / 4
    else:                                                  # large deflections
        geo = [dict(a=u(0.8, 1.2), b=1.0, k=u(0.5, 2.0), L0=u(0.8, 1.4))] * n
        dx = u(0.25, 0.4) * 2.0 * n
    segs = [to.Segment(**g, spring=spring, mass=u(0.05, 1.0), inertia=u(0.0, 0.05)) for g in geo]
    return to.Manipulator(segs, payload=u(0.0, 0.5)), dx, u(-0.3, 0.3) * n / 4


def _segs(m):
    return [dict(d, mass=s.mass, inertia=s.inertia) for d, s in zip(ref.segs_of(m), m.segments)]


def _check(m, eq, md, held):
    """The modes equal the reference's: frequencies to 1e-10, shapes in the allowed motions, mass-normalised,
    each an eigenvector of the reference's pencil."""
    w, Z, M, K = rd.frequencies(_segs(m), m.payload, eq.q, held=held, stops=eq.at_stop)
    assert md.eigenvalues.size == w.size
    if md.status == "solved":
        np.testing.assert_allclose(md.frequencies, np.sqrt(w), rtol=1e-10)
    else:
        np.testing.assert_allclose(md.eigenvalues, w, rtol=1e-9, atol=1e-10 * np.abs(w).max())
    if w.size == 0:
        return
    scale = float(np.abs(w).max())
    for lam, s in zip(md.eigenvalues, md.shapes):
        assert s @ M @ s == pytest.approx(1.0, rel=1e-9)
        np.testing.assert_allclose(Z @ (Z.T @ s), s, atol=1e-9)                   # an allowed motion
        np.testing.assert_allclose(Z.T @ (K - lam * M) @ s, 0.0, atol=1e-8 * scale)


@pytest.mark.slow_cases(keep=3)
@pytest.mark.parametrize("family", FAMILIES)
@pytest.mark.parametrize("seed", [0, 1])
def test_the_modes_with_the_tip_held_are_the_reference(family, seed):
    m, dx, dy = _chain(family, np.random.default_rng(4100 + seed))
    eq = to.solve_equilibrium(m, dx, dy)
    md = to.modes(m, eq)
    assert md.tip == "held" and md.eigenvalues.size == m.n - 2 and md.status == "solved" and md.success
    assert np.all(np.diff(md.frequencies) >= 0)
    _check(m, eq, md, held=True)


@pytest.mark.slow_cases(keep=2)
@pytest.mark.parametrize("family", FAMILIES)
def test_the_modes_with_the_tip_loaded_are_the_reference(family):
    """The pose of a tip displacement, its tip force then a dead load: every joint moves (n modes; unstable where
    the held tip was what kept it)."""
    m, dx, dy = _chain(family, np.random.default_rng(4200))
    eq = to.solve_equilibrium(m, dx, dy)
    md = to.modes(m, eq, tip="loaded")
    assert md.tip == "loaded" and md.eigenvalues.size == m.n
    _check(m, eq, md, held=False)


def test_an_equilibrium_under_a_tip_force_has_the_tip_loaded_by_default():
    m, _, _ = _chain("monotonic", np.random.default_rng(4250))
    eq = to.solve_equilibrium_under_force(m, -0.02, 0.03)
    md = to.modes(m, eq)
    assert md.tip == "loaded" and md.status == "solved" and md.eigenvalues.size == m.n
    _check(m, eq, md, held=False)


def test_the_modes_of_a_saddle_say_unstable_with_the_reference_eigenvalues():
    m = to.Manipulator.uniform(4, a=0.5, b=1.0, k=1.0, L0=0.5, mass=0.3, payload=0.1)
    eqs = to.find_equilibria(m, 0.6, 0.1)
    saddle = next(e for e in eqs if e.morse_index == 1)
    md = to.modes(m, saddle)
    assert md.status == "unstable" and not md.success
    assert np.isnan(md.frequencies[0]) and np.all(np.isfinite(md.frequencies[1:]))
    _check(m, saddle, md, held=True)
    body = md.to_dict()
    assert body["frequencies"][0] is None and body["success"] is False
    json.dumps(body)


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("family", ["monotonic", "large"])
def test_a_joint_on_its_stop_stays_there_in_the_modes(family):
    """Tension-only chains deflected far rest on a stop: that joint does not move in any mode."""
    rng = np.random.default_rng(4300)
    for _ in range(20):
        m, dx, dy = _chain(family, rng, spring="tension_only")
        eq = to.solve_equilibrium(m, 1.5 * dx + 1.0, dy)
        if eq.at_stop.any():
            break
    assert eq.at_stop.any()
    md = to.modes(m, eq)
    assert md.held_joints.tolist() == eq.at_stop.tolist()
    np.testing.assert_allclose(md.shapes[:, eq.at_stop], 0.0, atol=1e-12)
    _check(m, eq, md, held=True)


def test_one_segment_swings_at_its_closed_form_frequency():
    """One segment under a dead tip load: ``w^2 = V''(q) / J`` with ``V = E - F . tip``, ``J = m/2 (2b/3)^2 +
    I + payload b^2`` (the upper triangle and the payload turn about the joint; the lower one is the base)."""
    a, b, k, L0, mass, inertia, payload = 1.1, 1.0, 2.0, 1.2, 0.8, 0.03, 0.25
    m = to.Manipulator([to.Segment(a, b, k, L0, mass=mass, inertia=inertia)], payload=payload)
    fx, fy = 0.05, 0.1
    eq = to.solve_equilibrium_under_force(m, fx, fy)
    q = float(eq.q[0])
    c, beta = math.hypot(a, b), math.atan2(a, b)
    # E = k/2 sum (L - L0)^2, L1 = 2c cos(beta + q/2), L2 = 2c cos(beta - q/2); tip = (b + b cos q, b sin q)
    d2E = sum(k * ((c * math.sin(beta + s * q / 2)) ** 2 - (2 * c * math.cos(beta + s * q / 2) - L0)
                   * 0.5 * c * math.cos(beta + s * q / 2)) for s in (1, -1))
    d2V = d2E - (fx * (-b * math.cos(q)) + fy * (-b * math.sin(q)))
    J = 0.5 * mass * (2 * b / 3) ** 2 + inertia + payload * b * b
    md = to.modes(m, eq)
    assert md.frequencies[0] == pytest.approx(math.sqrt(d2V / J), rel=1e-12)


def test_modes_refuse_what_they_cannot_answer():
    m = to.Manipulator.uniform(4)
    eq = to.solve_equilibrium(m, 1.0)
    with pytest.raises(InvalidParameterError) as e:
        to.modes(m, eq)                                     # no mass at all
    assert e.value.field == "mass"
    lop = to.Manipulator([to.Segment(1, 1, mass=1.0)] + [to.Segment(1, 1)] * 3)   # links 2-4 carry nothing
    with pytest.raises(InvalidParameterError) as e:
        to.modes(lop, to.solve_equilibrium(lop, 1.0))
    assert e.value.field == "mass"
    with pytest.raises(InvalidParameterError) as e:
        to.modes(m.__class__.uniform(4, mass=1.0), eq, tip="pinned")
    assert e.value.field == "tip"
    with pytest.raises(InvalidParameterError) as e:
        to.modes(to.Manipulator.uniform(3, mass=1.0), eq)
    assert e.value.field == "equilibrium"


def test_masses_change_no_equilibrium_and_round_trip():
    """Without gravity the masses change no equilibrium (the same answer to the last bit); the chain's JSON form
    carries them only where set; bad values name their field."""
    m0 = to.Manipulator.uniform(4)
    m1 = to.Manipulator.uniform(4, mass=0.4, inertia=0.01, payload=0.2)
    e0, e1 = to.solve_equilibrium(m0, 1.3, 0.2), to.solve_equilibrium(m1, 1.3, 0.2)
    assert e0.q.tolist() == e1.q.tolist() and e0.energy == e1.energy
    assert "mass" not in json.dumps(m0.to_dict()) and "payload" not in m0.to_dict()
    d = m1.to_dict()
    assert d["payload"] == 0.2 and d["segments"][0]["mass"] == 0.4 and d["segments"][0]["inertia"] == 0.01
    assert to.Manipulator.from_dict(d) == m1 and to.Manipulator.from_dict(d) != m0
    assert m1.with_spring("tension_only").payload == 0.2 and m1.mirrored().segments[0].mass == 0.4
    for bad, field in ((dict(mass=-1.0), "mass"), (dict(inertia=float("nan")), "inertia")):
        with pytest.raises(InvalidParameterError) as e:
            to.Segment(1, 1, **bad)
        assert e.value.field == field
    with pytest.raises(InvalidParameterError) as e:
        to.Manipulator.uniform(3, payload=-0.1)
    assert e.value.field == "payload"
    with pytest.raises(InvalidParameterError) as e:
        to.Manipulator.from_dict({"segments": [{"a": 1, "b": 1, "mas": 1}]})
    assert "mass" in str(e.value)


def test_a_sweep_spec_carries_the_masses_and_its_rows_are_the_massless_chains():
    """One name and one form: the sweep spec's chain takes mass, inertia (per segment) and payload as the library
    and REST do; without gravity its rows are the massless chain's; a bad mass names its field."""
    pts = [{"dx": 0.5}, {"dx": 0.8, "dy": 0.1}]
    heavy = to.sweep({"analysis": "equilibrium", "manipulator": {"n": 3, "mass": 0.2, "inertia": 0.01,
                                                                 "payload": 0.1}, "points": pts})
    seg = to.sweep({"analysis": "equilibrium", "points": pts, "manipulator": {
        "segments": [{"a": 1, "b": 1, "mass": 0.2, "inertia": 0.01}] * 3, "payload": 0.1}})
    light = to.sweep({"analysis": "equilibrium", "manipulator": {"n": 3}, "points": pts})
    assert [r["q"] for r in heavy.rows] == [r["q"] for r in light.rows] == [r["q"] for r in seg.rows]
    for bad, field in (({"n": 3, "mass": -1}, "manipulator.mass"),
                       ({"segments": [{"a": 1, "b": 1, "inertia": "x"}]}, "manipulator.segments[0].inertia"),
                       ({"segments": [{"a": 1, "b": 1}], "payload": float("inf")}, "manipulator.payload")):
        with pytest.raises(InvalidParameterError) as e:
            to.sweep({"analysis": "equilibrium", "manipulator": bad, "points": pts})
        assert e.value.field == field


def test_modes_refuse_or_flag_the_review_cases():
    """A review's reproducers: a payload that cannot move with the tip held (the reduced mass matrix is rounding
    noise), a chain marginal in every direction (K = 1e-16: every w^2 ~ 0), the fully extended chain with its tip
    held (the tip constraint is singular: the held arm cannot move), masses too small to resolve."""
    m = to.Manipulator.uniform(4, payload=1.0)
    with pytest.raises(InvalidParameterError) as e:
        to.modes(m, to.solve_equilibrium(m, 0.5))
    assert e.value.field == "mass"
    flat = to.Manipulator.uniform(4, a=0.5, L0=1.5, mass=1.0)
    assert abs(flat.segments[0].stiffness) < 1e-12
    md = to.modes(flat, to.solve_equilibrium_under_force(flat, 0.0, 0.0))
    assert md.status == "degenerate" and not md.success and np.isnan(md.frequencies).all()
    straight = to.Manipulator.uniform(4, mass=1.0)
    eq = to.solve_equilibrium(straight, 0.0)
    with pytest.raises(InvalidParameterError) as e:
        to.modes(straight, eq)
    assert e.value.field == "tip"
    assert to.modes(straight, eq, tip="loaded").eigenvalues.size == 4
    tiny = to.Manipulator.uniform(4, mass=1e-310)
    with pytest.raises(InvalidParameterError) as e:
        to.modes(tiny, to.solve_equilibrium(tiny, 0.5))
    assert e.value.field == "mass"


def test_a_design_keeps_what_the_arm_carries():
    """A design changes the geometry or the springs, not the masses: the designed chain of every design verb keeps
    each segment's mass and inertia and the payload (a review found them dropped)."""
    m = to.Manipulator.uniform(4, mass=0.2, inertia=0.01, payload=0.5)
    designs = [to.preloads_for_critical_force(m, 0.6).manipulator,
               to.preloads_for_pose(m, m.tip(np.array([0.1, -0.1, 0.05, 0.0]))).manipulator,
               to.maximize_critical_force(m).manipulator]
    for d in designs:
        assert d.payload == 0.5 and all(s.mass == 0.2 and s.inertia == 0.01 for s in d.segments)
