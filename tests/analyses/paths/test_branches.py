"""Arclength continuation in every control, and stability boundaries, against other routes.

The expected numbers come from other solvers of the library that share nothing with the path system
but the model (IPOPT/Newton under force or displacement on a chain with changed preloads, the straight
chain's eigenproblem in ``critical_force``), from closed forms (``t`` at the end point), or from
tests/support/reference_model.py (independent numpy model). The acceptance tests of the paths (branch points =
critical loads, folds, limit loads vs a separate computation, the energy identity) are in test_paths.py.
"""

from __future__ import annotations


import numpy as np
import pytest

import tensegrity_opt as to
from tensegrity_opt.analyses.paths.boundaries import _chain_at, parameter_direction, stability_boundary
from tensegrity_opt.analyses.paths.branches import trace_branch
from tensegrity_opt.analyses.paths.control import Control

import reference_model as ref  # noqa: E402

PAPER = to.Manipulator.uniform(4)
PREBENT = to.Manipulator([to.Segment(1.0, 1.0, 1.0, (1.02, 0.98))] * 4)


def _chain(m: to.Manipulator) -> ref.Chain:
    return ref.Chain(m.a, m.b, m.k1, m.k2, m.L1_0, m.L2_0)


def _assert_on_branch(m: to.Manipulator, br, *, tol: float = 1e-8) -> None:
    """Every point inside the range and an equilibrium of the independent model."""
    ch = _chain(m)
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


def test_partial_results_on_max_points_and_time_limit():
    br = trace_branch(PAPER, np.zeros(4), "guided", max_points=5)
    assert len(br) == 5 and br.status == "max_points" and br.success
    br = trace_branch(PAPER, np.zeros(4), "guided", max_points=100000, step=1e-4, max_step=1e-4, timeout=0.05)
    assert br.status == "time_limit" and not br.success and len(br) > 1
    _assert_on_branch(PAPER, br)


@pytest.mark.parametrize("parameter, boundary", [("L0", "guided"), ("a", "free")])
def test_branch_point_boundary_is_the_critical_load_of_the_changed_chain(parameter, boundary):
    ctl = "guided" if boundary == "guided" else "load"
    B = stability_boundary(PAPER, ctl, parameter, start=np.zeros(4), p_min=-0.1, p_max=0.1, max_points=5)
    assert B.kind == "branch_point" and B.success
    assert B.p.min() == pytest.approx(-0.1) and B.p.max() == pytest.approx(0.1)
    for p, t in zip(B.p, B.t):
        mp = _chain_at(PAPER, B.parameter_direction, p)
        assert t == pytest.approx(ref.critical_loads_guided(_chain(mp))[0] if boundary == "guided"
                                  else ref.critical_loads_free(_chain(mp))[0], rel=1e-6)


def test_fold_boundary_through_the_cusp_of_the_unfolded_pitchfork():
    """A preload asymmetry unfolds the straight chain's pitchfork: the fold curve passes through the
    branch point (a cusp at p = 0, t = the critical load). Each point is checked on the independent model
    (an equilibrium of the pre-bent chain with the guide at y = 0, a zero eigenvalue of the Hessian reduced
    to dy = 0), and near the cusp the fold load grows like |p|^(2/3) (the imperfect pitchfork)."""
    B = stability_boundary(PAPER, "guided", "asymmetry", start=np.zeros(4), p_min=-0.03, p_max=0.03)
    assert B.kind == "fold" and B.p.min() < -0.03 and B.p.max() > 0.03
    crit = -to.critical_force(PAPER, "guided").force
    cusp0 = [c for c in B.cusps if abs(c.p) < 1e-9]
    assert cusp0 and cusp0[0].t == pytest.approx(crit, rel=1e-9)
    _, d = parameter_direction(PAPER, "asymmetry")
    for i in range(0, len(B.p), 7):
        ch = _chain(_chain_at(PAPER, d, float(B.p[i])))
        q, F = B.q[i], B.force[i]
        assert F[0] == pytest.approx(-B.t[i], abs=1e-12)
        assert np.abs(ch.grad(q) - ch.jac(q).T @ F).max() < 1e-9 and abs(ch.tip(q)[1]) < 1e-10
        H = ch.lagrangian_hess(q, F)
        Q, _ = np.linalg.qr(ch.jac(q)[1:].T, mode="complete")
        w = np.linalg.eigvalsh(Q[:, 1:].T @ H @ Q[:, 1:])
        assert np.abs(w).min() < 1e-7 * np.abs(w).max()
    # the imperfect pitchfork: t - t_cr ~ C |p|^(2/3) on each side
    for side in (1, -1):
        sel = np.flatnonzero((side * B.p > 1e-4) & (side * B.p < 3e-3))
        assert sel.size >= 3
        slope = np.polyfit(np.log(np.abs(B.p[sel])), np.log(B.t[sel] - crit), 1)[0]
        assert slope == pytest.approx(2.0 / 3.0, abs=0.05)
