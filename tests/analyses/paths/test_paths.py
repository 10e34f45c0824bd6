"""Acceptance tests of equilibrium paths and limit points against independent
references.

Every expected number comes from ``tests/support/reference_paths.py`` / ``tests/support/reference_model.py``
(numpy + scipy, relative joint angles, no import of the library) or from a closed form; the
library is only called to produce the values under test.

API under test (``tensegrity_opt``): ``Control.load / guided / displacement / preload``,
``trace_branch``, ``switch_branch``, ``bifurcation_diagram``, ``limit_load``, the ``Branch``
and ``BranchEvent`` records. Conventions (shared/spec/conventions.md): ``grad E = J^T F`` with
``F`` the tip force holding the chain; the deflection ``(dx, dy)`` puts the tip at
``(2 sum b - dx, dy)``; the joint range is ``|q_i| < pi - 2 beta_i``.

Kept small (n <= 4, one trace per case, cached) so that the file runs in well under a minute.
"""

from __future__ import annotations

import functools
import json
import math

import numpy as np
import pytest

import reference_model as R  # noqa: E402
import reference_paths as RP  # noqa: E402

import tensegrity_opt as to  # noqa: E402
from tensegrity_opt import Control, bifurcation_diagram, limit_load, switch_branch, trace_branch  # noqa: E402

# --------------------------------------------------------------------------- chains
# (a, b, k1, k2, L1_0, L2_0) per segment
def _sym(a, b, k, L0):
    return (a, b, k, k, L0, L0)


CHAINS = {
    "paper4": [_sym(1.0, 1.0, 1.0, 1.0)] * 4,
    "paper2": [_sym(1.0, 1.0, 1.0, 1.0)] * 2,
    "G1x3": [_sym(0.8, 1.2, 2.5, 1.7)] * 3,
    "hetero3": [_sym(1.0, 1.0, 1.0, 1.0), _sym(0.9, 1.3, 2.0, 1.5), _sym(1.1, 0.8, 0.7, 0.9)],
    # every segment's first spring 0.1 shorter: a pre-bent arm (rest q_i = 0.105166)
    "pre_bent3": [(1.0, 1.0, 1.0, 1.0, 0.9, 1.0)] * 3,
    # bistable segments, K = k (b L0 - 2 (b^2 - a^2)) = -0.5, wells +-1.682137
    "bistable3": [_sym(0.5, 1.0, 1.0, 1.0)] * 3,
    # one bistable segment with wells +-1.348261 inside +-pi/2 (a y force acts as a torque)
    "one_seg": [_sym(0.6, 1.0, 1.0, 1.0)],
}
STRAIGHT = ("paper4", "G1x3", "hetero3")

RES_TOL = 1e-8          # equilibrium residual, relative to max k c^2
RANK_TOL = 1e-6         # reference eigenvalues closer to 0 than this: Morse index not compared


@functools.lru_cache(maxsize=None)
def ref(name) -> R.Chain:
    return R.Chain.from_segments(CHAINS[name])


@functools.lru_cache(maxsize=None)
def lib(name) -> to.Manipulator:
    return to.Manipulator([to.Segment(a, b, k=(k1, k2), L0=(l1, l2)) for a, b, k1, k2, l1, l2 in CHAINS[name]])


def wells(name):
    a, b, k1, k2, l1, l2 = CHAINS[name][0]
    return RP.segment_wells(a, b, k1, k2, l1, l2)


def bistable_rest():
    """The (+, +, +) rest configuration of the bistable chain."""
    return np.full(3, wells("bistable3")[1])


# --------------------------------------------------------------------------- generic checks
def _expected_stability(before, after):
    if before == 0 and after > 0:
        return "lost"
    if before > 0 and after == 0:
        return "gained"
    return "unchanged"


def _reduction(boundary):
    """Which reduced Hessian decides stability: free / guided / displacement (tip held)."""
    return {"load": "free", "guided": "guided", "displacement": "displacement",
            "preload_free": "free", "preload_held": "displacement"}[boundary]


def check_branch(c: R.Chain, br, control, *, direction=None, base=(0.0, 0.0), tip0=None, preload=None,
                 from_start=True):
    """Every point of ``br`` is a configuration (strictly inside the joint range) and an
    equilibrium of the reference model under the control; the records are consistent.

    ``control``: "load", "guided", "displacement", "preload_free", "preload_held";
    ``tip0`` the tip at t = 0 (guided / displacement / held); ``preload`` the (2n,) unit
    direction of the rest lengths (the chain at a point has L0 = L0_start + t preload)."""
    n = c.n
    P = br.t.shape[0]
    assert P >= 2, f"a branch of {P} point(s): status {br.status!r}"
    for name, shape in (("t", (P,)), ("q", (P, n)), ("force", (P, 2)), ("tip", (P, 2)),
                        ("deflection", (P, 2)), ("energy", (P,)), ("morse_index", (P,)),
                        ("stable", (P,)), ("s", (P,))):
        arr = np.asarray(getattr(br, name))
        assert arr.shape == shape, f"{name}: shape {arr.shape}, expected {shape}"
    for name in ("t", "q", "force", "tip", "deflection", "energy", "s"):
        assert np.all(np.isfinite(np.asarray(getattr(br, name), float))), name
    assert isinstance(br.status, str) and isinstance(br.success, (bool, np.bool_))
    json.dumps(br.to_dict())

    q = np.asarray(br.q, float)
    t = np.asarray(br.t, float)
    F = np.asarray(br.force, float)
    # inside the physical range, strictly
    assert np.all(np.abs(q) < c.limits), "a point outside the joint range |q_i| < pi - 2 beta_i"
    if from_start:
        assert t[0] == pytest.approx(0.0, abs=1e-12) and t[1] > t[0]
    s = np.asarray(br.s, float)
    assert s[0] == pytest.approx(0.0, abs=1e-12) and np.all(np.diff(s) > 0)

    d = None if direction is None else RP.unit(direction)
    base = np.asarray(base, float)
    chains = []
    for i in range(P):
        ci = c
        if preload is not None:
            L0 = np.column_stack([c.L10, c.L20]).ravel() + t[i] * np.asarray(preload, float)
            ci = R.Chain(c.a.copy(), c.b.copy(), c.k1.copy(), c.k2.copy(), L0[0::2].copy(), L0[1::2].copy())
        chains.append(ci)
        tip = ci.tip(q[i])
        np.testing.assert_allclose(br.tip[i], tip, atol=1e-9)
        np.testing.assert_allclose(br.deflection[i], [2.0 * c.b.sum() - tip[0], tip[1]], atol=1e-9)
        res = RP.equilibrium_residual(ci, q[i], F[i])
        assert res < RES_TOL, f"point {i}: reference equilibrium residual {res:.2e}"
        # the control
        if control == "load":
            np.testing.assert_allclose(F[i], base + t[i] * d, atol=1e-9)
        elif control == "guided":
            assert F[i, 0] == pytest.approx(base[0] + t[i] * d[0], abs=1e-9)
            assert tip[1] == pytest.approx(tip0[1], abs=1e-9)
        elif control == "displacement":
            defl0 = np.array([2.0 * c.b.sum() - tip0[0], tip0[1]])
            np.testing.assert_allclose(br.deflection[i], defl0 + t[i] * d, atol=1e-9)
            assert br.energy[i] == pytest.approx(ci.energy(q[i]), rel=1e-9, abs=1e-12)
        elif control == "preload_held":
            np.testing.assert_allclose(tip, tip0, atol=1e-9)
            assert br.energy[i] == pytest.approx(ci.energy(q[i]), rel=1e-9, abs=1e-12)
        # stability: the reference's inertia where it is not degenerate
        red = _reduction(control)
        w = _reduced_eigs(ci, q[i], F[i], red)
        if w.size == 0 or np.min(np.abs(w)) > RANK_TOL:
            m_ref = int(np.sum(w < 0))
            assert int(br.morse_index[i]) == m_ref, f"point {i}: Morse index {br.morse_index[i]}, reference {m_ref}"
            assert bool(br.stable[i]) == (m_ref == 0)

    for e in br.events:
        check_event(c if preload is None else None, br, e, control)
    return chains


def _reduced_eigs(c, q, F, red):
    H = RP.lagrangian_hess(c, q, F)
    if red == "free":
        return np.linalg.eigvalsh(H)
    import scipy.linalg as sla
    J = c.jac(q)
    Z = sla.null_space(J[1][None, :]) if red == "guided" else sla.null_space(J)
    return np.linalg.eigvalsh(Z.T @ H @ Z) if Z.shape[1] else np.zeros(0)


def check_event(c, br, e, control):
    P = br.t.shape[0]
    assert e.kind in {"fold", "branch_point", "joint_limit"}
    assert 0 <= e.index <= P - 1
    assert e.stability in {"lost", "gained", "unchanged"}
    assert e.stability == _expected_stability(e.morse_before, e.morse_after)
    if e.index + 1 < P and e.kind != "joint_limit":
        assert e.morse_before == int(br.morse_index[e.index])
        assert e.morse_after == int(br.morse_index[e.index + 1])
    if c is None:
        return
    q = np.asarray(e.q, float)
    assert np.all(np.abs(q) <= c.limits + 1e-12)
    np.testing.assert_allclose(e.tip, c.tip(q), atol=1e-8)
    assert np.isfinite(e.energy)
    if control in ("displacement", "preload_held"):
        assert e.energy == pytest.approx(c.energy(q), rel=1e-8, abs=1e-12)
    assert RP.equilibrium_residual(c, q, e.force) < RES_TOL
    if e.kind in ("fold", "branch_point"):
        assert np.all(np.abs(q) < c.limits)
        # singular there: the reference's smallest |eigenvalue| is ~ 0
        w = _reduced_eigs(c, q, np.asarray(e.force, float), _reduction(control))
        assert np.min(np.abs(w)) < 1e-4 * max(1.0, np.max(np.abs(w))), f"{e.kind} at t={e.t}: eigenvalues {w}"


def check_turning_point(br, e, window=6):
    """A fold is a turning point of t along the branch: e.t is the extremum of t over the
    points around it (a maximum when t grew before it, a minimum when it decreased)."""
    t = np.asarray(br.t, float)
    i = e.index
    lo, hi = max(0, i - window), min(t.size, i + window + 2)
    before = t[i] - t[max(0, i - 1)] if i > 0 else t[min(i + 1, t.size - 1)] - t[i]
    tol = 1e-10 * max(1.0, abs(e.t))
    if before > 0:
        assert e.t >= t[lo:hi].max() - tol, f"fold at t={e.t} below the branch's nearby maximum {t[lo:hi].max()}"
    else:
        assert e.t <= t[lo:hi].min() + tol, f"fold at t={e.t} above the branch's nearby minimum {t[lo:hi].min()}"
    # and the branch really turns there: t[i] and t[i+1] on the same side of e.t
    if i + 1 < t.size:
        assert (t[i] - e.t) * (t[i + 1] - e.t) >= -tol ** 2


def _events(br, kind):
    return [e for e in br.events if e.kind == kind]


# --------------------------------------------------------------------------- reference values (cached)
@functools.lru_cache(maxsize=None)
def modes(name, boundary):
    return RP.buckling_modes(ref(name), boundary)


@functools.lru_cache(maxsize=None)
def ref_limit(name, boundary, direction=(-1.0, 0.0), max_load=2.0):
    c = ref(name)
    if name == "bistable3":
        q0 = bistable_rest()
    elif name == "one_seg":
        q0 = np.array([wells("one_seg")[0]])
    else:
        q0 = RP.rest_configuration(c)
    return RP.limit_load_reference(c, q0, direction, boundary, max_load)


def _control(boundary, direction=(-1.0, 0.0)):
    return Control.load(direction=direction, base=(0.0, 0.0)) if boundary == "free" else \
        Control.guided(direction=direction, base=(0.0, 0.0))


def _check_control(boundary):
    return "load" if boundary == "free" else "guided"


# --------------------------------------------------------------------------- straight chains
def _t_max_two_branch_points(P):
    return 0.5 * (P[1] + P[2]) if P.size > 2 else 1.25 * P[1]


@functools.lru_cache(maxsize=None)
def straight_branch(name, boundary):
    P, _ = modes(name, boundary)
    return trace_branch(lib(name), None, _control(boundary), t_max=float(_t_max_two_branch_points(P)),
                        max_points=400)


@pytest.mark.parametrize("name", STRAIGHT)
@pytest.mark.parametrize("boundary", ["free", "guided"])
def test_straight_chain_branch_points_are_the_critical_loads(name, boundary):
    """On the straight chain under compression the trivial path meets a branch point at each
    critical load (free: K v = P G v; guided: the same on dy = 0); the null vectors are the
    buckling modes; stability is lost at the first and the Morse index grows by one at each."""
    c = ref(name)
    P, V = modes(name, boundary)
    br = straight_branch(name, boundary)
    check_branch(c, br, _check_control(boundary), direction=(-1.0, 0.0), tip0=c.tip(np.zeros(c.n)))
    np.testing.assert_allclose(br.q, 0.0, atol=1e-8)
    t_max = _t_max_two_branch_points(P)
    bps = _events(br, "branch_point")
    expected = P[P < t_max]
    assert [e.t for e in bps] == pytest.approx(list(expected), rel=1e-6)
    assert not _events(br, "fold")
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
    first is 0.0761205 (conventions.md) and its guided one 0.572793."""
    br = straight_branch("paper4", "free")
    j = np.arange(1, 3)
    closed = 1.0 - np.cos((2 * j - 1) * math.pi / 8)
    assert [e.t for e in _events(br, "branch_point")] == pytest.approx(list(closed), rel=1e-6)
    assert closed[0] == pytest.approx(0.0761205, abs=1e-7)
    assert _events(straight_branch("paper4", "guided"), "branch_point")[0].t == pytest.approx(0.572793, abs=1e-6)


@pytest.mark.parametrize("name", ["paper4", "hetero3"])
@pytest.mark.parametrize("boundary", ["free", "guided"])
def test_limit_load_of_straight_chain_is_a_bifurcation(name, boundary):
    P, _ = modes(name, boundary)
    lim = limit_load(lib(name), direction=(-1.0, 0.0), boundary=boundary)
    assert lim.kind == "bifurcation" and lim.status == "stability_lost" and lim.success
    assert lim.load == pytest.approx(P[0], rel=1e-6)
    np.testing.assert_allclose(lim.force, [-P[0], 0.0], atol=1e-6 * P[0])
    np.testing.assert_allclose(lim.q, 0.0, atol=1e-8)
    check_branch(ref(name), lim.branch, _check_control(boundary), direction=(-1.0, 0.0),
                 tip0=ref(name).tip(np.zeros(ref(name).n)))


@pytest.mark.parametrize("boundary, side", [("guided", +1), ("free", -1)])
def test_switch_branch_at_the_first_branch_point(boundary, side):
    """The bifurcating branch of the paper chain: bent along the first buckling mode,
    supercritical (the load grows past P as it bends) and stable near the branch point."""
    c = ref("paper4")
    P, V = modes("paper4", boundary)
    br = straight_branch("paper4", boundary)
    e = _events(br, "branch_point")[0]
    sb = switch_branch(br, e, side=side)
    check_branch(c, sb, _check_control(boundary), direction=(-1.0, 0.0), tip0=c.tip(np.zeros(4)),
                 from_start=False)
    q = np.asarray(sb.q, float)
    amp = np.linalg.norm(q, axis=1)
    assert amp.max() > 1e-2, "the switched branch never leaves the straight configuration"
    # the reference's post-buckling shapes stay within cos > 0.9999 of the first mode up to
    # |q| = 0.4 (guided and free)
    near = (amp > 1e-4) & (amp < 0.4)
    assert near.any()
    cos = np.abs(q[near] @ V[:, 0]) / amp[near]
    assert np.all(cos > 0.999), "the switched branch does not leave along the buckling mode"
    small = amp < 0.2
    assert np.all(np.asarray(sb.t)[small] >= P[0] - 1e-7), "subcritical? the reference pitchfork is supercritical"
    assert np.all(np.asarray(sb.morse_index)[small & (amp > 1e-3)] == 0)


def test_bifurcation_diagram_two_segment_guided():
    """n = 2, guided: one branch point at P = 5/3; the diagram holds the trivial branch and
    the branch(es) bifurcating there, every point a reference equilibrium."""
    c = ref("paper2")
    P, _ = modes("paper2", "guided")
    assert P[0] == pytest.approx(5.0 / 3.0, rel=1e-12)
    branches = bifurcation_diagram(lib("paper2"), None, _control("guided"), depth=2, t_max=2.0)
    assert isinstance(branches, list) and len(branches) >= 2
    primary = branches[0]
    bps = _events(primary, "branch_point")
    assert [e.t for e in bps] == pytest.approx([P[0]], rel=1e-6)
    bent = 0
    for k, br in enumerate(branches):
        check_branch(c, br, "guided", direction=(-1.0, 0.0), tip0=c.tip(np.zeros(2)), from_start=(k == 0))
        if np.max(np.abs(br.q)) > 1e-2:
            bent += 1
            assert br.t[0] == pytest.approx(P[0], abs=0.05) and np.max(np.abs(br.q[0])) < 0.1
    assert bent >= 1


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
    folds = _events(br, "fold")
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


def test_pre_bent_guided_path_folds_at_the_reference_fold():
    """The pre-bent arm, tip guided: the load path turns at a fold, t = 0.825957 (extended
    system solved by scipy; the joint-angle parametrisation gives the same), where the reduced
    Hessian is singular; the library's fold is the turning point of its own branch."""
    c = ref("pre_bent3")
    r = ref_limit("pre_bent3", "guided")
    assert r.kind == "fold"
    br = pre_bent_guided_branch()
    check_branch(c, br, "guided", direction=(-1.0, 0.0), tip0=c.tip(RP.rest_configuration(c)))
    folds = _events(br, "fold")
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


def test_limit_load_pre_bent_chain():
    """Free: the path is smooth up to the joint range (no fold, quasi-buckling); the
    smallest eigenvalue stays positive through the straight chain's critical load. Guided: a
    fold at t = 0.825957."""
    c = ref("pre_bent3")
    m = lib("pre_bent3")
    r_free = ref_limit("pre_bent3", "free")
    assert r_free.kind == "none" and r_free.reason == "joint_limit"
    lim = limit_load(m, direction=(-1.0, 0.0), boundary="free")
    assert lim.kind == "none" and lim.status == "joint_limit"
    assert lim.load is None or lim.load == pytest.approx(r_free.t, rel=1e-3)
    assert lim.quasi_buckling_load is None or 0.0 < lim.quasi_buckling_load <= r_free.t + 1e-9
    check_branch(c, lim.branch, "load", direction=(-1.0, 0.0))
    assert np.all(np.asarray(lim.branch.morse_index) == 0)
    P_straight = RP.buckling_modes(R.Chain.uniform(3, 1.0, 1.0, 1.0, 1.0), "free")[0][0]
    assert np.max(lim.branch.t) > P_straight

    lim = limit_load(m, direction=(-1.0, 0.0), boundary="free", max_load=0.2)
    assert lim.kind == "none" and lim.status == "max_load"

    r = ref_limit("pre_bent3", "guided")
    lim = limit_load(m, direction=(-1.0, 0.0), boundary="guided")
    assert lim.kind == "fold" and lim.status == "stability_lost"
    assert lim.load == pytest.approx(r.t, rel=1e-6)
    np.testing.assert_allclose(lim.force, r.force, atol=1e-5)
    np.testing.assert_allclose(lim.q, r.q, atol=1e-4)


@pytest.mark.parametrize("boundary", ["free", "guided"])
def test_limit_load_bistable_chain(boundary):
    """Three bistable segments from the (+, +, +) rest, compressed: a fold (snap-through), free
    t = 0.427401, guided t = 0.432200."""
    r = ref_limit("bistable3", boundary)
    assert r.kind == "fold"
    lim = limit_load(lib("bistable3"), direction=(-1.0, 0.0), boundary=boundary, start=bistable_rest())
    assert lim.kind == "fold" and lim.status == "stability_lost"
    assert lim.load == pytest.approx(r.t, rel=1e-6)
    np.testing.assert_allclose(lim.force, r.force, atol=1e-5)
    np.testing.assert_allclose(lim.q, r.q, atol=1e-4)
    c = ref("bistable3")
    check_branch(c, lim.branch, _check_control(boundary), direction=(-1.0, 0.0), tip0=c.tip(bistable_rest()))


def test_limit_load_single_segment_fold():
    c = ref("one_seg")
    (q1, t1), _ = RP.single_segment_folds(c, (0.0, 1.0), -1.5, 1.5)
    lim = limit_load(lib("one_seg"), direction=(0.0, 1.0), boundary="free", start=np.array([wells("one_seg")[0]]))
    assert lim.kind == "fold" and lim.load == pytest.approx(t1, rel=1e-6)
    assert lim.q[0] == pytest.approx(q1, abs=1e-4)


# --------------------------------------------------------------------------- displacement control
@functools.lru_cache(maxsize=None)
def displacement_branch():
    return trace_branch(lib("bistable3"), bistable_rest(), Control.displacement(direction=(1.0, 0.0)),
                        t_max=2.5, max_points=800)


def test_displacement_branch_fold_and_joint_limit():
    """Displacement control (dx grows) of the bistable chain: a turning point in dx at
    dx = 1.973177 (stability lost); the unstable branch then runs back to dx = 0.660098 where
    joint 2 reaches its bound."""
    c = ref("bistable3")
    br = displacement_branch()
    check_branch(c, br, "displacement", direction=(1.0, 0.0), tip0=c.tip(bistable_rest()))
    r = RP.fold_in_displacement(c, bistable_rest(), (1.0, 0.0), t_max=3.0)
    assert r.kind == "fold" and r.t_coordinate == pytest.approx(r.t, abs=1e-10)
    folds = _events(br, "fold")
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
    jl = _events(br, "joint_limit")
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
