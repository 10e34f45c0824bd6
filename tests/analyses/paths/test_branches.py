"""Branches (``trace_branch``) in every control, against independent references and other routes.

Every expected number comes from ``tests/support/reference_paths.py`` / ``tests/support/reference_model.py``
(numpy + scipy, relative joint angles, no import of the library, through ``tests/support/branch_checks.py``), from
a closed form, or from other solvers of the library that share nothing with the path system but the model
(IPOPT/Newton under force or displacement on a chain with changed preloads, the natural-parameter solver).
The control's records (``Control.load / guided / displacement / preload``, ``Branch``, ``BranchEvent``) are checked
on every point. Conventions: ``docs/model.md``.
"""

from __future__ import annotations

import functools
import math

import numpy as np
import pytest
import reference_model as R
import reference_paths as RP
from branch_checks import (
    STRAIGHT,
    bistable_rest,
    chain_of,
    check_branch,
    check_name,
    check_turning_point,
    events_of,
    lib,
    modes,
    ref,
    ref_limit,
    straight_branch,
    t_max_two_branch_points,
    wells,
)
from clocks import tick_clock

import tensegrity_opt as to
from tensegrity_opt import Control, trace_branch

PAPER = to.Manipulator.uniform(4)

# --------------------------------------------------------------------------- chains


# --------------------------------------------------------------------------- generic checks


# --------------------------------------------------------------------------- straight chains


@pytest.mark.parametrize("name", STRAIGHT)
@pytest.mark.parametrize("boundary", ["free", "guided"])
def test_straight_chain_branch_points_are_the_critical_loads(name, boundary):
    """On the straight chain under compression the trivial path meets a branch point at each
    critical load (free: K v = P G v; guided: the same on dy = 0); the null vectors are the
    buckling modes; stability is lost at the first and the Morse index grows by one at each."""
    c = ref(name)
    P, V = modes(name, boundary)
    br = straight_branch(name, boundary)
    check_branch(c, br, check_name(boundary), direction=(-1.0, 0.0), tip0=c.tip(np.zeros(c.n)))
    np.testing.assert_allclose(br.q, 0.0, atol=1e-8)
    t_max = t_max_two_branch_points(P)
    bps = events_of(br, "branch_point")
    expected = P[P < t_max]
    assert [e.t for e in bps] == pytest.approx(list(expected), rel=1e-6)
    assert not events_of(br, "fold")
    for j, e in enumerate(bps):
        assert (e.morse_before, e.morse_after) == (j, j + 1)
        assert e.stability == ("lost" if j == 0 else "unchanged")
        np.testing.assert_allclose(e.force, [-P[j], 0.0], atol=1e-6 * P[j])
        np.testing.assert_allclose(e.q, 0.0, atol=1e-8)
        v = np.asarray(e.null_vector, float)
        assert v.shape == (c.n,)
        v = v / np.linalg.norm(v)
        sin = np.linalg.norm(v - (v @ V[:, j]) * V[:, j])
        assert sin < 1e-4, f"null vector {v} not parallel to the mode {V[:, j]} (sin {sin:.1e})"


def test_paper_chain_free_critical_loads_closed_form():
    """The free-tip uniform chain: P_j = (K / b) (1 - cos((2j - 1) pi / (2n))); the paper chain's
    first is 0.0761205 (``docs/model.md``) and its guided one 0.572793."""
    br = straight_branch("paper4", "free")
    j = np.arange(1, 3)
    closed = 1.0 - np.cos((2 * j - 1) * math.pi / 8)
    assert [e.t for e in events_of(br, "branch_point")] == pytest.approx(list(closed), rel=1e-6)
    assert closed[0] == pytest.approx(0.0761205, abs=1e-7)
    assert events_of(straight_branch("paper4", "guided"), "branch_point")[0].t == pytest.approx(0.572793, abs=1e-6)


# --------------------------------------------------------------------------- folds
@functools.lru_cache(maxsize=None)
def one_segment_branch():
    return trace_branch(lib("one_seg"), np.array([wells("one_seg")[0]]), Control.load(direction=(0.0, 1.0)),
                        t_max=0.3, t_min=-0.5, max_points=600)


def test_bistable_segment_snaps_through_and_returns_to_a_stable_branch():
    """One bistable segment under a tip force along +y (a torque t b cos q), from its lower
    well: t(q) = E'(q) / (b cos q) (closed form) has a maximum (fold, stability lost) at
    q = -0.997415, t = 0.218830 and a minimum (fold, stability regained) at q = +0.997415,
    t = -0.218830; continuation goes around both and ends stable beyond the upper well."""
    c = ref("one_seg")
    br = one_segment_branch()
    check_branch(c, br, "load", direction=(0.0, 1.0))
    (q1, t1), (q2, t2) = RP.single_segment_folds(c, (0.0, 1.0), -1.5, 1.5)
    r = ref_limit("one_seg", "free", direction=(0.0, 1.0), max_load=1.0)
    assert r.kind == "fold" and r.t == pytest.approx(t1, abs=1e-10)
    folds = events_of(br, "fold")
    assert len(folds) >= 2
    f1, f2 = folds[0], folds[1]
    assert f1.t == pytest.approx(t1, rel=1e-6) and f1.q[0] == pytest.approx(q1, abs=1e-4)
    assert f1.stability == "lost" and (f1.morse_before, f1.morse_after) == (0, 1)
    assert f2.t == pytest.approx(t2, rel=1e-6) and f2.q[0] == pytest.approx(q2, abs=1e-4)
    assert f2.stability == "gained" and (f2.morse_before, f2.morse_after) == (1, 0)
    for f in (f1, f2):
        check_turning_point(br, f)
        assert f.null_vector is None or abs(np.asarray(f.null_vector, float).ravel()[0]) > 0
    # stable again later on the same branch, beyond the upper well
    later = np.asarray(br.morse_index)[f2.index + 1:]
    assert later.size > 0 and np.all(later == 0)
    assert br.q[-1, 0] > wells("one_seg")[1] and br.t[-1] > 0.0


@functools.lru_cache(maxsize=None)
def pre_bent_guided_branch():
    return trace_branch(lib("pre_bent3"), None, Control.guided(direction=(-1.0, 0.0)), t_max=0.9, max_points=300)


@pytest.mark.slow
def test_pre_bent_guided_path_folds_at_the_reference_fold():
    """The pre-bent arm, tip guided: the load path turns at a fold, t = 0.825957 (extended
    system solved by scipy; the joint-angle parametrisation gives the same), where the reduced
    Hessian is singular; the library's fold is the turning point of its own branch."""
    c = ref("pre_bent3")
    r = ref_limit("pre_bent3", "guided")
    assert r.kind == "fold"
    br = pre_bent_guided_branch()
    check_branch(c, br, "guided", direction=(-1.0, 0.0), tip0=c.tip(RP.rest_configuration(c)))
    folds = events_of(br, "fold")
    assert folds, f"no fold on the branch (status {br.status!r})"
    f = folds[0]
    assert f.t == pytest.approx(r.t, rel=1e-6)
    np.testing.assert_allclose(f.q, r.q, atol=1e-4)
    np.testing.assert_allclose(f.force, r.force, atol=1e-5)
    assert f.stability == "lost"
    check_turning_point(br, f)
    # before the fold everything is stable, and no branch point comes first
    assert np.all(np.asarray(br.morse_index)[:f.index + 1] == 0)
    assert all(e.kind != "branch_point" for e in br.events if e.t < f.t and e.index <= f.index)


# --------------------------------------------------------------------------- displacement control
@functools.lru_cache(maxsize=None)
def displacement_branch():
    return trace_branch(lib("bistable3"), bistable_rest(), Control.displacement(direction=(1.0, 0.0)),
                        t_max=2.5, max_points=800)


@pytest.mark.slow
def test_displacement_branch_fold_and_joint_limit():
    """Displacement control (dx grows) of the bistable chain: a turning point in dx at
    dx = 1.973177 (stability lost); the unstable branch then runs back to dx = 0.660098 where
    joint 2 reaches its bound."""
    c = ref("bistable3")
    br = displacement_branch()
    check_branch(c, br, "displacement", direction=(1.0, 0.0), tip0=c.tip(bistable_rest()))
    r = RP.fold_in_displacement(c, bistable_rest(), (1.0, 0.0), t_max=3.0)
    assert r.kind == "fold" and r.t_coordinate == pytest.approx(r.t, abs=1e-10)
    folds = events_of(br, "fold")
    assert folds
    f = folds[0]
    assert f.t == pytest.approx(r.t, rel=1e-6)
    np.testing.assert_allclose(f.q, r.q, atol=1e-4)
    np.testing.assert_allclose(f.force, r.force, atol=1e-5)
    assert f.stability == "lost" and (f.morse_before, f.morse_after) == (0, 1)
    check_turning_point(br, f)
    assert np.all(np.asarray(br.morse_index)[:f.index + 1] == 0)
    assert np.all(np.asarray(br.morse_index)[f.index + 1:] == 1)
    # the end: the joint range (t decreasing after the fold, never below the reference bound)
    assert np.min(np.asarray(br.t)[f.index + 1:]) >= 0.660098 - 1e-6
    jl = events_of(br, "joint_limit")
    if jl:
        assert jl[-1].t == pytest.approx(0.6600981, abs=1e-3)
        assert np.max(np.abs(jl[-1].q) / c.limits) > 0.999


def test_energy_along_a_displacement_branch_integrates_the_force():
    """grad E = J^T F, so along a displacement path dE = F . d(tip) (tip = (2 sum b - dx, dy)):
    E(end) - E(start) equals int F . dtip over the branch (here through a fold). The integral is
    refined on the reference between the branch's points (Gauss nodes on each secant, so the
    step sizes do not matter); the plain trapezoid rule over the points agrees to its O(h^2)."""
    c = ref("bistable3")
    br = displacement_branch()
    E = np.asarray(br.energy, float)
    dE = E[-1] - E[0]
    assert dE == pytest.approx(c.energy(br.q[-1]) - c.energy(br.q[0]), rel=1e-9)
    integral, trap = RP.energy_integral(c, br.q, br.force, w=(-1.0, 0.0), nodes=4)
    assert integral == pytest.approx(dE, rel=1e-6)
    assert trap == pytest.approx(dE, rel=1e-3)
    # pointwise: the library's tip moves as -dx, and F . dtip has the sign of the energy change
    dtip = np.diff(np.asarray(br.tip, float), axis=0)
    Fm = 0.5 * (np.asarray(br.force)[1:] + np.asarray(br.force)[:-1])
    dEs = np.diff(E)
    big = np.abs(dEs) > 1e-3 * np.max(np.abs(dEs))
    assert np.all(np.sign(np.sum(Fm * dtip, axis=1)[big]) == np.sign(dEs[big]))


# --------------------------------------------------------------------------- preload control
def test_preload_free_tip_bends_one_segment():
    """Unloaded free tip, L1_0 of segment 1 grows: segment 1 bends alone (its own E'(q1) = 0
    with the new rest length), the others stay straight."""
    c = ref("paper2")
    d = np.array([1.0, 0.0, 0.0, 0.0])
    br = trace_branch(lib("paper2"), None, Control.preload(direction=tuple(d), tip="free", load=(0.0, 0.0)),
                      t_max=0.3, max_points=200)
    chains = check_branch(c, br, "preload_free", preload=d)
    np.testing.assert_allclose(br.force, 0.0, atol=1e-9)
    np.testing.assert_allclose(br.q[:, 1], 0.0, atol=1e-9)
    for ci, qi in zip(chains, br.q):
        seg = R.Chain.from_segments([(ci.a[0], ci.b[0], ci.k1[0], ci.k2[0], ci.L10[0], ci.L20[0])])
        q1, ok = seg.newton_force(np.zeros(2), np.array([qi[0]]))
        assert ok and qi[0] == pytest.approx(q1[0], abs=1e-8)
    assert np.max(br.t) >= 0.3 - 1e-6 and abs(br.q[-1, 0]) > 1e-3
    assert np.all(np.asarray(br.morse_index) == 0)


def test_preload_held_tip():
    """Tip held where the pre-bent arm rests, L1_0 of segment 2 grows: every point is an
    equilibrium of the re-preloaded reference chain with the tip in place, the force the
    reaction."""
    c = ref("pre_bent3")
    d = np.zeros(6)
    d[2] = 1.0
    q_r = RP.rest_configuration(c)
    br = trace_branch(lib("pre_bent3"), None, Control.preload(direction=tuple(d), tip="held", load=(0.0, 0.0)),
                      t_max=0.2, max_points=200)
    check_branch(c, br, "preload_held", preload=d, tip0=c.tip(q_r))
    np.testing.assert_allclose(br.q[0], q_r, atol=1e-8)
    assert np.max(np.abs(np.asarray(br.force)[-1])) > 1e-3


def _assert_on_branch(m: to.Manipulator, br, *, tol: float = 1e-8) -> None:
    """Every point inside the range and an equilibrium of the independent model."""
    ch = chain_of(m)
    assert np.all(np.abs(br.q) < m.joint_limits)
    for q, F in zip(br.q, br.force):
        r = np.abs(ch.grad(q) - ch.jac(q).T @ F).max() / m.torque_scale
        assert r < tol


@pytest.mark.parametrize("kind, kw", [("load", {"direction": (0.3, 1.0)}), ("guided", {"direction": (-1.0, 0.2)}),
                                      ("wall", {"normal": (0.4, 1.0), "direction": (-1.0, 0.0)})])
def test_every_load_control_is_on_the_independent_model(kind, kw):
    rng = np.random.default_rng(7)
    m = to.Manipulator([to.Segment(0.8 + 0.3 * rng.random(), 0.9 + 0.2 * rng.random(),
                                   (1 + rng.random(), 1 + rng.random()), (1.0 + 0.1 * rng.random(), 1.0))
                        for _ in range(3)])
    rest = to.solve_equilibrium_under_force(m, 0.0, 0.0)
    br = trace_branch(m, rest.q, kind, t_max=0.3, **kw)
    assert br.success and len(br) > 3
    _assert_on_branch(m, br)
    ctl = br.control
    if kind == "load":
        np.testing.assert_allclose(br.force, br.t[:, None] * ctl.direction[None, :], atol=1e-12)
    else:
        nu = ctl.normal
        tau = np.array([nu[1], -nu[0]])
        # held along the normal, the load prescribed along the wall
        np.testing.assert_allclose((br.tip - br.tip[0]) @ nu, 0.0, atol=1e-10)
        np.testing.assert_allclose(br.force @ tau, br.t * (tau @ ctl.direction), atol=1e-10)
    # a point of the branch is the local equilibrium the force solver finds from it (another method)
    i = len(br) // 2
    eq = to.solve_equilibrium_under_force(m, *br.force[i], q0=br.q[i])
    if kind == "load":
        np.testing.assert_allclose(eq.q, br.q[i], atol=1e-7)
    assert br.t[-1] == pytest.approx(0.3, abs=1e-12) and br.status == "t_max"


def test_preload_control_free_and_held_against_the_changed_chain():
    m = to.Manipulator.uniform(3, a=0.9, b=1.0, k=1.0, L0=1.0)
    # one spring's rest length moves: the rest shape is the rest configuration of the changed chain
    br = trace_branch(m, np.zeros(3), Control.spring(3, 0, 1), t_max=0.3)
    assert br.status == "t_max" and br.rest_lengths.shape == (len(br), 3, 2)
    m2 = to.Manipulator([to.Segment(0.9, 1.0, 1.0, (1.3, 1.0)), to.Segment(0.9, 1.0, 1.0, 1.0),
                         to.Segment(0.9, 1.0, 1.0, 1.0)])
    eq = to.solve_equilibrium_under_force(m2, 0.0, 0.0)
    np.testing.assert_allclose(br.q[-1], eq.q, atol=1e-8)
    np.testing.assert_allclose(br.rest_lengths[-1, 0], [1.3, 1.0], atol=1e-12)
    # tip held: the least-energy displacement solve on the changed chain at the same target
    start = to.solve_equilibrium(m, 0.4, 0.1)
    d = np.zeros(6)
    d[1], d[4] = 1.0, -0.5                         # L2_0 of segment 1 up, L1_0 of segment 3 down
    brh = trace_branch(m, start, Control.preload(d, tip="held"), t_max=0.2)
    np.testing.assert_allclose(brh.tip, np.repeat(start.tip[None, :], len(brh), 0), atol=1e-10)
    u = d / np.linalg.norm(d)
    L = np.array([[1.0, 1.0]] * 3) + 0.2 * u.reshape(3, 2)
    m3 = to.Manipulator(to.Segment(0.9, 1.0, 1.0, tuple(r)) for r in L)
    # the end point is one of every equilibrium of the changed chain at that target (the search)
    eqs = to.find_equilibria(m3, 0.4, 0.1)
    e3 = min(eqs, key=lambda e: np.abs(e.q - brh.q[-1]).max())
    np.testing.assert_allclose(brh.q[-1], e3.q, atol=1e-7)
    np.testing.assert_allclose(brh.force[-1], e3.force, atol=1e-7)
    assert e3.stable == bool(brh.stable[-1])


def test_displacement_branch_matches_the_natural_parameter_solver_and_ends_inside_the_range():
    start = to.solve_equilibrium(PAPER, 0.05)
    br = trace_branch(PAPER, start, "displacement", direction=(1.0, 0.0), t_max=10.0)
    assert br.status == "joint_limit" and br.events[-1].kind == "joint_limit"
    lim = br.events[-1]
    assert abs(lim.q[lim.joint]) == pytest.approx((1 - 1e-6) * PAPER.joint_limits[lim.joint], rel=1e-9)
    _assert_on_branch(PAPER, br)
    np.testing.assert_allclose(br.deflection[:, 1], 0.0, atol=1e-10)
    tr = to.Tracker(PAPER, start, jump=False)
    for i in range(0, len(br), 5):
        e = tr.solve(*br.deflection[i])
        np.testing.assert_allclose(e.q, br.q[i], atol=1e-7)
        assert e.stable == bool(br.stable[i])


def test_errors_name_the_field():
    with pytest.raises(to.InvalidParameterError) as e:
        trace_branch(PAPER, np.zeros(4), "load", direction=(0.0, 0.0))
    assert e.value.field == "direction"
    with pytest.raises(to.InvalidParameterError) as e:
        trace_branch(PAPER, np.zeros(4), "bogus")
    assert e.value.field == "control"
    with pytest.raises(to.InvalidParameterError) as e:
        trace_branch(PAPER, np.zeros(4), "guided", direction=(0.0, 1.0))
    assert e.value.field == "direction"
    with pytest.raises(to.InvalidParameterError) as e:
        trace_branch(PAPER, np.full(4, 3.0), "load")
    assert e.value.field == "q0"
    with pytest.raises(to.InvalidParameterError) as e:
        trace_branch(PAPER, np.zeros(4), Control.preload(np.ones(4)))
    assert e.value.field == "direction"
    with pytest.raises(to.InvalidParameterError) as e:
        trace_branch(PAPER, np.zeros(4), "load", max_points=1)
    assert e.value.field == "max_points"
    with pytest.raises(to.InvalidParameterError) as e:
        trace_branch(PAPER, np.zeros(4), "load", t_max=float("nan"))
    assert e.value.field == "t_max"


def test_partial_results_on_max_points_and_time_limit(monkeypatch):
    br = trace_branch(PAPER, np.zeros(4), "guided", max_points=5)
    assert len(br) == 5 and br.status == "max_points" and br.success
    # the library's clock moves on 1 s at every reading, once a point (tests/support/clocks.py): a limit of 50 s
    # runs out after some 50 points on any machine
    tick_clock(monkeypatch, step=1.0)
    br = trace_branch(PAPER, np.zeros(4), "guided", max_points=100000, step=1e-4, max_step=1e-4, timeout=50.0)
    assert br.status == "time_limit" and not br.success and 10 < len(br) < 100
    _assert_on_branch(PAPER, br)


# --------------------------------------------------------------------------- sharp folds: no unlocated stability change
def _imperfect_two(p: float) -> to.Manipulator:
    """Two segments a = 1.5 > b pre-bent by p (``L1_0 + p``, ``L2_0 - p``): guided, the path folds just below the
    straight chain's critical load 35/6 (Koiter), in a corner of size ~p^(1/3), far shorter than a step."""
    return to.Manipulator([to.Segment(1.5, 1.0, 1.0, (1.0 + p, 1.0 - p))] * 2)


def test_every_stability_change_of_a_branch_is_at_a_located_event():
    """p = 1e-5 past its fold: wherever the Morse index changes between two points, an event lies between them
    (a step over the sharp fold onto the neighbouring branch is refused and shortened)."""
    m = _imperfect_two(1e-5)
    br = trace_branch(m, None, "guided", direction=(-1.0, 0.0), t_max=6.5 * 1.625, max_points=200)
    changes = np.flatnonzero(np.diff(br.morse_index))
    assert changes.size >= 1 and br.morse_index[0] == 0
    for i in changes:
        located = [e for e in br.events if e.index == i and e.kind != "joint_limit"]
        assert len(located) == abs(int(br.morse_index[i + 1] - br.morse_index[i])), i
    fold = br.events[0]
    assert fold.kind == "fold" and fold.stability == "lost" and 5.8 < fold.t < 35.0 / 6.0
    assert np.all(br.morse_index[:fold.index + 1] == 0)


def test_a_stability_change_that_cannot_be_located_cuts_the_branch(monkeypatch):
    """With event location made to fail, the straight chain's stability loss at its branch point cannot be
    located: the branch ends at it, not a success, saying so; no unstable point is reported."""
    from tensegrity_opt.analyses.paths import branches

    monkeypatch.setattr(branches, "events_between", lambda *args, **kw: [])
    br = trace_branch(to.Manipulator.uniform(2, a=1.5), np.zeros(2), "guided", direction=(-1.0, 0.0),
                      t_max=7.0 * 1.625)
    assert br.status == "step_too_small" and not br.success
    assert "stability changes" in br.message and "no fold or branch point" in br.message
    # the last point is within min_step of the critical load: marginal at worst (Morse index 0)
    assert np.all(br.morse_index == 0) and np.all(br.stable[:-1])
    assert br.t[-1] == pytest.approx(35.0 / 6.0, rel=1e-6)
