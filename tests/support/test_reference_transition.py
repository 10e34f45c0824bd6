"""Self-tests of tests/support/reference_transition.py (the independent transition reference).

No import of ``tensegrity_opt``: the reference is checked against what can be derived without it -- the fold of
one tilted segment in closed form (the equilibrium curve ``d(q)`` of a segment under the tilt ``(1 + d, 1 - d)``
is explicit; its extremum is the fold), an extended (Moore-Spence) system solved by scipy, plain Newton at the end
point, a brute-force grid of margins, and the load-path references of ``reference_paths`` (``limit_load_reference``,
``segment_wells``). Fast: well under two seconds in all.
"""

from __future__ import annotations

import functools
import math

import numpy as np
import pytest
import reference_paths as RP  # noqa: E402
import reference_transition as RT  # noqa: E402
import scipy.optimize as so

BI = (0.5, 1.0, 1.0, 1.0)           # (a, b, k, L0): K = k (b L0 - 2 (b^2 - a^2)) = -0.5, bistable
WELL = RP.segment_wells(0.5, 1.0, 1.0, 1.0, 1.0, 1.0)[1]     # its positive well, 1.682137


# ---------------------------------------------------------------------------- closed forms
def tilt_of_angle(q, a=0.5, b=1.0):
    """One symmetric segment (k = 1, L0 = 1) with the tilted rest lengths (1 + d, 1 - d), no load: E'(q; d) = 0 is
    linear in d, so the equilibrium curve is explicit, d(q) = ((L1 - 1) L1' + (L2 - 1) L2') / (L1' - L2')."""
    c, beta = math.hypot(a, b), math.atan2(a, b)
    L1, L2 = 2 * c * np.cos(beta + q / 2), 2 * c * np.cos(beta - q / 2)
    d1, d2 = -c * np.sin(beta + q / 2), c * np.sin(beta - q / 2)
    return ((L1 - 1) * d1 + (L2 - 1) * d2) / (d1 - d2)


@functools.lru_cache(maxsize=None)
def tilt_fold():
    """(q*, d*): the largest tilt the positive well survives, the maximum of d(q) on (0.3, well)."""
    r = so.minimize_scalar(lambda q: -tilt_of_angle(q), bounds=(0.3, WELL), method="bounded",
                           options={"xatol": 1e-12})
    return float(r.x), float(-r.fun)


def extended_fold(chain_at, ell0, ell1, F0, F1, q, s):
    """Moore-Spence: R(q, s) = 0, H(q, s) phi = 0, phi . phi = 1 (unknowns q, s, phi), scipy root (hybr, its own
    finite-difference Jacobian) from the reference's fold, with the reference model's gradient and Hessian."""
    ell0, ell1, F0, F1 = (np.asarray(x, float) for x in (ell0, ell1, F0, F1))
    n = q.size

    def parts(s):
        return chain_at(ell0 + s * (ell1 - ell0)), F0 + s * (F1 - F0)

    def G(x):
        qq, ss, phi = x[:n], x[n], x[n + 1:]
        c, F = parts(ss)
        return np.concatenate([c.lagrangian_grad(qq, F), c.lagrangian_hess(qq, F) @ phi, [phi @ phi - 1.0]])

    c, F = parts(s)
    phi0 = np.linalg.eigh(c.lagrangian_hess(q, F))[1][:, 0]
    sol = so.root(G, np.concatenate([q, [s], phi0]), method="hybr", options={"xtol": 1e-14})
    assert np.abs(G(sol.x)).max() < 1e-12, (sol.message, G(sol.x))      # ("xtol too small" is fine)
    return sol.x[:n], float(sol.x[n])


def potential(chain_at, ell, F, q):
    c = chain_at(np.asarray(ell, float))
    return c.energy(q) - float(np.asarray(F, float) @ c.tip(q))


# ---------------------------------------------------------------------------- 1. a tilted bistable segment snaps
@functools.lru_cache(maxsize=None)
def tilt_case():
    chain_at = RT.chain_factory([0.5, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 1.0])   # bistable + monotonic
    ell0, ell1 = np.ones((2, 2)), np.array([[1.4, 0.6], [1.0, 1.0]])
    return chain_at, ell0, ell1, RT.transition(chain_at, [WELL, 0.0], ell0, ell1, (0, 0), (0, 0))


def test_tilt_snaps_at_the_closed_form_fold():
    chain_at, ell0, ell1, r = tilt_case()
    q_fold, d_fold = tilt_fold()
    assert 0.3 < d_fold < 0.4 and d_fold == pytest.approx(0.345820762, abs=1e-9)
    assert r.status == "snapped" and len(r.snaps) == 1 and r.limit_at is None
    s_star, q_before, q_after = r.snaps[0]
    assert r.fold_at == s_star
    assert s_star == pytest.approx(d_fold / 0.4, abs=1e-9)            # 0.8645519045
    # the last stable point sits at the fold: ~sqrt(1e-10) away in q, margin ~0
    assert q_before[0] == pytest.approx(q_fold, abs=1e-4) and q_before[1] == 0.0
    assert 0.0 < r.min_margin < 1e-5 and r.min_margin_at == pytest.approx(s_star, abs=1e-9)
    # the extended system from the reference's fold lands on the same fold
    qe, se = extended_fold(chain_at, ell0, ell1, (0, 0), (0, 0), q_before, s_star)
    assert se == pytest.approx(s_star, abs=1e-9) and np.abs(qe - q_before).max() < 1e-4
    # the landing: the other well of the tilted segment (the second joint untouched), a stable minimum, lower V
    ell_star = ell0 + s_star * (ell1 - ell0)
    other = RP.segment_wells(0.5, 1.0, 1.0, 1.0, *ell_star[0]).min()
    assert other < 0 and q_after[0] == pytest.approx(other, abs=1e-9) and abs(q_after[1]) < 1e-12
    c = chain_at(ell_star)
    assert np.abs(c.lagrangian_grad(q_after, (0, 0))).max() < 1e-11
    assert np.linalg.eigvalsh(c.lagrangian_hess(q_after, (0, 0)))[0] > 0.1
    assert potential(chain_at, ell_star, (0, 0), q_after) < potential(chain_at, ell_star, (0, 0), q_before) - 0.1
    # the end: the negative well at the full tilt
    assert r.q_end[0] == pytest.approx(RP.segment_wells(0.5, 1.0, 1.0, 1.0, 1.4, 0.6).min(), abs=1e-10)
    assert np.allclose(r.tip_end, chain_at(ell1).tip(r.q_end), atol=1e-14)


def test_two_snaps_in_one_transition():
    """Two bistable segments tilted at different rates (d = 0.6 s, 0.4 s), no load: the energy is separable, so
    each snaps at its own closed-form fold, d* / 0.6 first, then d* / 0.4."""
    chain_at = RT.chain_factory(0.5, 1.0, 1.0, 1.0)
    ell1 = np.array([[1.6, 0.4], [1.4, 0.6]])
    r = RT.transition(chain_at, [WELL, WELL], np.ones((2, 2)), ell1, (0, 0), (0, 0))
    _, d_fold = tilt_fold()
    assert r.status == "snapped" and len(r.snaps) == 2
    (s1, b1, a1), (s2, b2, a2) = r.snaps
    assert s1 == pytest.approx(d_fold / 0.6, abs=1e-9) and s2 == pytest.approx(d_fold / 0.4, abs=1e-9)
    assert r.fold_at == s1 and r.stretch_end < s1
    assert a1[0] < 0 < a1[1] and b2[0] < 0 < b2[1] and a2[1] < 0          # first joint 1 snaps, then joint 2
    wells_end = [RP.segment_wells(0.5, 1.0, 1.0, 1.0, *e).min() for e in ell1]
    assert np.allclose(r.q_end, wells_end, atol=1e-10)


# ---------------------------------------------------------------------------- 2. a smooth transition
PAPER = RT.chain_factory(np.ones(4), np.ones(4), np.ones(4), np.ones(4))
SMOOTH = dict(ell0=np.ones((4, 2)), ell1=np.array([[1.03, 0.98], [1.0, 1.02], [0.99, 1.0], [1.01, 0.97]]),
              F0=(0.0, 0.0), F1=(0.0, 0.05))


def test_smooth_transition_follows_to_the_newton_end():
    r = RT.transition(PAPER, np.zeros(4), **SMOOTH)
    assert r.status == "followed" and r.snaps == [] and r.fold_at is None and r.limit_at is None
    c1 = PAPER(SMOOTH["ell1"])
    q_newton, ok = c1.newton_force(np.array(SMOOTH["F1"]), np.zeros(4))
    assert ok and np.abs(r.q_end - q_newton).max() < 1e-10
    # the least margin against a brute-force grid of 2001 fractions (each solved by Newton from the previous)
    S = np.linspace(0.0, 1.0, 2001)
    q, M = np.zeros(4), []
    for s in S:
        c = PAPER(SMOOTH["ell0"] + s * (SMOOTH["ell1"] - SMOOTH["ell0"]))
        F = s * np.array(SMOOTH["F1"])
        q, ok = c.newton_force(F, q)
        assert ok
        M.append(np.linalg.eigvalsh(c.lagrangian_hess(q, F))[0])
    i = int(np.argmin(M))
    assert 0 < i < S.size - 1                        # an interior minimum (0.998942 at s = 0.229)
    assert r.min_margin <= M[i] + 1e-12 and M[i] - r.min_margin < 1e-8
    assert r.min_margin_at == pytest.approx(S[i], abs=1e-3)


def test_required_margin_and_its_loss():
    r = RT.transition(PAPER, np.zeros(4), **SMOOTH, margin=0.999)
    assert r.margin_ok is False and 0.0 < r.margin_lost_at < r.min_margin_at
    s = r.margin_lost_at
    c = PAPER(SMOOTH["ell0"] + s * (SMOOTH["ell1"] - SMOOTH["ell0"]))
    q, ok = c.newton_force(s * np.array(SMOOTH["F1"]), np.zeros(4))
    assert ok and np.linalg.eigvalsh(c.lagrangian_hess(q, s * np.array(SMOOTH["F1"])))[0] == pytest.approx(0.999,
                                                                                                        abs=1e-9)
    r2 = RT.transition(PAPER, np.zeros(4), **SMOOTH, margin=0.99)
    assert r2.margin_ok is True and r2.margin_lost_at is None


def test_dR_ds_is_exact():
    P = RT._Problem(PAPER, SMOOTH["ell0"], SMOOTH["ell1"], SMOOTH["F0"], SMOOTH["F1"])
    q, s, h = np.array([0.3, -0.2, 0.1, 0.05]), 0.4, 1e-5
    fd = (P.residual(q, s + h) - P.residual(q, s - h)) / (2 * h)
    assert np.abs(P.dR_ds(q) - fd).max() < 1e-9


# ---------------------------------------------------------------------------- 3. a joint limit
def test_compression_runs_into_a_joint_limit():
    """A pre-bent paper chain (every L1_0 = 0.9) under F: 0 -> (-5, 0): smooth quasi-buckling up to the joint
    range (reference_paths: no fold), the joint limit at the load limit_load_reference finds (t = 0.300086)."""
    ell = np.tile([0.9, 1.0], (4, 1))
    c = PAPER(ell)
    q_rest = RP.rest_configuration(c)
    r = RT.transition(PAPER, q_rest, ell, ell, (0, 0), (-5, 0))
    assert r.status == "joint_limit" and r.fold_at is None and r.snaps == []
    assert RT.joint_ratio(c, r.q_end) == pytest.approx(1.0, abs=2e-6)
    F = r.limit_at * np.array([-5.0, 0.0])
    assert np.abs(c.lagrangian_grad(r.q_end, F)).max() < 1e-11
    lr = RP.limit_load_reference(c, q_rest, (-1.0, 0.0), "free", 5.0)
    assert lr.reason == "joint_limit"
    assert 5.0 * r.limit_at == pytest.approx(lr.t, rel=1e-5)          # |q| = limit vs (1 - 1e-6) limit
    assert r.stretch_end == r.limit_at
    # the least margin: interior (0.484322 at s = 0.0103), below every accepted sample, above 0
    assert 0.0 < r.min_margin <= min(p[2] for p in r.points) and 0.0 < r.min_margin_at < r.limit_at


def test_snap_that_runs_into_a_joint_limit():
    """One bistable segment in its negative well, tilted towards positive angles (rest lengths (1, 1) -> (0.2,
    1.8)) under a growing compression (0, 0) -> (-0.4, 0): its well vanishes at a fold and the flow runs to the
    positive joint limit. For n = 1 the fold solves V'(q) = V''(q) = 0 in (q, s) (scipy root, a route of its own)
    and V is decreasing all the way from the fold to the limit (no well to land in)."""
    chain_at = RT.chain_factory(0.5, 1.0, 1.0, 1.0)
    ell0, ell1, F1 = np.ones((1, 2)), np.array([[0.2, 1.8]]), np.array([-0.4, 0.0])
    r = RT.transition(chain_at, [-WELL], ell0, ell1, (0, 0), F1)
    assert r.status == "joint_limit" and r.snaps == [] and r.fold_at == r.limit_at
    c_lim = chain_at(ell0 + r.limit_at * (ell1 - ell0))
    assert r.q_end[0] > 0 and RT.joint_ratio(c_lim, r.q_end) == pytest.approx(1.0, abs=2e-6)

    def G(x):
        q, s = x[:1], x[1]
        c, F = chain_at(ell0 + s * (ell1 - ell0)), s * F1
        return [c.lagrangian_grad(q, F)[0], c.lagrangian_hess(q, F)[0, 0]]
    sol = so.root(G, [r.points[-1][1][0], r.fold_at], method="hybr", options={"xtol": 1e-14})
    assert np.abs(G(sol.x)).max() < 1e-12
    assert r.fold_at == pytest.approx(sol.x[1], abs=1e-9)                # 0.9409534711
    F_star = r.fold_at * F1
    qs = np.linspace(sol.x[0] + 1e-3, c_lim.limits[0], 2000)
    assert np.all(np.array([c_lim.lagrangian_grad(np.array([q]), F_star)[0] for q in qs]) < 0)


def test_supercritical_branch_point_is_refused():
    """The straight paper chain under growing compression: a supercritical pitchfork at P = 0.0761205 (free
    tip), no snap -- out of scope, refused once the flow settles next to the lost point."""
    ell = np.ones((4, 2))
    with pytest.raises(RT.BranchPointError, match="s\\* = 0.01522409"):
        RT.transition(PAPER, np.zeros(4), ell, ell, (0, 0), (-5, 0))


# ---------------------------------------------------------------------------- 4. a bistable chain under a y-load
def test_bistable_chain_snaps_at_the_documented_load():
    chain_at = RT.chain_factory(0.5, 1.0, 1.0, 1.0)
    ell = np.ones((3, 2))
    q0 = np.full(3, WELL)
    r = RT.transition(chain_at, q0, ell, ell, (0, 0), (0, 0.3))
    assert r.status == "snapped" and len(r.snaps) == 1
    s_star, q_before, q_after = r.snaps[0]
    assert 0.3 * s_star == pytest.approx(0.153110661, abs=1e-9)
    lr = RP.limit_load_reference(chain_at(ell), q0, (0.0, 1.0), "free", 0.3)   # bisection + extended system
    assert lr.kind == "fold" and 0.3 * s_star == pytest.approx(lr.t, abs=1e-9)
    assert np.abs(q_before - lr.q).max() < 1e-4
    c = chain_at(ell)
    F = np.array([0.0, 0.3 * s_star])
    assert np.linalg.eigvalsh(c.lagrangian_hess(q_after, F))[0] > 0.0
    assert potential(chain_at, ell, F, q_after) < potential(chain_at, ell, F, q_before) - 0.1
    assert q_after[1] < 0 < q_before[1]                                   # the middle joint changed well
    assert np.abs(c.lagrangian_grad(r.q_end, (0.0, 0.3))).max() < 1e-11
    # docs/design.md's load cycle 0 -> 0.3 -> -0.3 -> 0 as three transitions: the energy released per snap
    # (0.284993 up, 0.525489 down at Fy = -0.0977542) and the rest state reached, (-, -, +)
    assert potential(chain_at, ell, F, q_before) - potential(chain_at, ell, F, q_after) == pytest.approx(
        0.284993, abs=1e-6)
    down = RT.transition(chain_at, r.q_end, ell, ell, (0, 0.3), (0, -0.3))
    assert down.status == "snapped" and len(down.snaps) == 1
    s_down, b_down, a_down = down.snaps[0]
    F_down = np.array([0.0, 0.3 - 0.6 * s_down])
    assert F_down[1] == pytest.approx(-0.0977542, abs=1e-7)
    assert potential(chain_at, ell, F_down, b_down) - potential(chain_at, ell, F_down, a_down) == pytest.approx(
        0.525489, abs=1e-6)
    back = RT.transition(chain_at, down.q_end, ell, ell, (0, -0.3), (0, 0))
    assert back.status == "followed" and np.allclose(back.q_end, [-WELL, -WELL, WELL], atol=1e-10)


# ---------------------------------------------------------------------------- the start
def test_start_must_be_a_stable_equilibrium():
    chain_at = RT.chain_factory(0.5, 1.0, 1.0, 1.0)
    ell = np.ones((2, 2))
    with pytest.raises(ValueError, match="not a stable"):
        RT.transition(chain_at, [0.0, 0.0], ell, ell, (0, 0), (0, 0.1))      # the straight bistable: a maximum
    with pytest.raises(ValueError, match="not an equilibrium"):
        RT.transition(chain_at, [0.8, WELL], ell, ell, (0, 0), (0, 0.1))
    r = RT.transition(chain_at, [WELL + 1e-5, WELL], ell, ell, (0, 0), (0, 0))   # polished, nothing moves
    assert r.status == "followed" and np.abs(r.q_end - WELL).max() < 1e-12
