"""Preload trajectories (analyses/design/preload_control.py) against independent routes.

* every planned step is re-solved forward by the numpy reference model (tests/support/reference_control.py: a
  local minimiser of its own energy under the dead load from the previous step's configuration, polished by
  Newton) and must land on the target, stable by its own Hessian;
* the least-change step equals scipy SLSQP on the same problem written with the reference model;
* bounds, rate limits and the margin hold; a margin larger than the least-change solution's keeps the
  plan on its branch (IPOPT takes those steps) where the unconstrained step would lose it.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.optimize as so
from reference_control import forward, ref_chain

import tensegrity_opt as to
from tensegrity_opt.analyses.design.preload_control import PreloadController, plan_preloads

PAPER = to.Manipulator.uniform(4)
BISTABLE = to.Manipulator.uniform(4, 0.5, 1.0, 1.0, 1.0)
HETERO = to.Manipulator([to.Segment(0.9, 1.0, 1.2, (1.05, 0.97)), to.Segment(1.1, 0.9, 0.8, 1.0),
                         to.Segment(1.0, 1.1, 1.0, (0.98, 1.02))])
CHAINS = [("paper", PAPER, (-0.02, 0.01)), ("bistable", BISTABLE, (0.0, 0.02)), ("hetero", HETERO, (0.01, -0.01))]


def arc(m, F, K=30, amp=(-0.15, 0.3)):
    ctl = PreloadController(m, load=F)
    tip0 = m.tip(ctl.q)
    return np.array([tip0 + np.array(amp) * np.sin(np.pi * k / (K - 1)) for k in range(K)])


@pytest.mark.parametrize("name,m,F", CHAINS, ids=[c[0] for c in CHAINS])
def test_every_step_lands_on_its_target_stable_in_the_reference_model(name, m, F):
    traj = arc(m, F)
    plan = plan_preloads(m, traj, loads=F, rate_limit=0.1, dt=1.0)
    assert plan.status == "complete" and plan.feasible.all() and plan.verified.all()
    q_prev = PreloadController(m, load=F).q
    for k in range(len(traj)):
        ch = ref_chain(m, plan.commands[k])
        q = forward(ch, F, q_prev)                                    # the forward quasi-static solve
        np.testing.assert_allclose(ch.tip(q), traj[k], atol=1e-6)
        np.testing.assert_allclose(q, plan.q[k], atol=1e-7)           # the same branch, not another well
        w = np.linalg.eigvalsh(ch.lagrangian_hess(q, np.asarray(F, float)))
        assert w[0] > 0 and w[0] == pytest.approx(plan.margin[k], rel=1e-6, abs=1e-9)
        q_prev = q
    assert np.abs(np.diff(plan.commands, axis=0)).max() <= 0.1 + 1e-12


def _slsqp_step(m, ell_prev, q_prev, target, F, angle=None):
    """min 1/2 |l - l_prev|^2 (+ 1e-8/2 |q - q_prev|^2) s.t. the equilibrium and the pose, by SLSQP on the
    reference model."""
    n = m.n
    F = np.asarray(F, float)

    def parts(x):
        return x[:n], x[n:]

    def f(x):
        q, ell = parts(x)
        return 0.5 * np.sum((ell - ell_prev) ** 2) + 0.5e-8 * np.sum((q - q_prev) ** 2)

    def g(x):
        q, ell = parts(x)
        ch = ref_chain(m, ell)
        out = [ch.lagrangian_grad(q, F), ch.tip(q) - target]
        if angle is not None:
            out.append([np.sum(q) - angle])
        return np.concatenate(out)

    res = so.minimize(f, np.concatenate([q_prev, ell_prev]), method="SLSQP",
                      constraints=[{"type": "eq", "fun": g}], options={"ftol": 1e-14, "maxiter": 500})
    assert res.success, res.message
    return parts(res.x)


@pytest.mark.parametrize("name,m,F", CHAINS, ids=[c[0] for c in CHAINS])
def test_a_least_change_step_is_the_slsqp_optimum(name, m, F):
    ctl = PreloadController(m, load=F)
    tip0 = m.tip(ctl.q)
    ell0, q0 = ctl.ell.copy(), ctl.q.copy()
    target = tip0 + np.array([-0.03, 0.05])
    st = ctl.step(target)
    # Newton, or IPOPT where Newton's KKT point is not a local minimum (the n = 3 chain: a saddle)
    assert st.feasible and st.method == ("ipopt" if name == "hetero" else "newton")
    q_ref, ell_ref = _slsqp_step(m, ell0, q0, target, F)
    np.testing.assert_allclose(st.command.ravel(), ell_ref, atol=2e-6)
    np.testing.assert_allclose(st.q, q_ref, atol=2e-6)
    # with the last link's angle prescribed too
    ctl2 = PreloadController(m, load=F)
    angle = float(np.sum(q0)) + 0.02
    st2 = ctl2.step(target, end_angle=angle)
    assert st2.feasible and st2.end_angle == pytest.approx(angle, abs=1e-10)
    q_ref, ell_ref = _slsqp_step(m, ell0, q0, target, F, angle)
    np.testing.assert_allclose(st2.command.ravel(), ell_ref, atol=2e-6)


def test_bounds_rate_and_margin_hold_and_the_margin_keeps_the_branch():
    m, F = PAPER, (-0.02, 0.01)
    traj = arc(m, F, K=25, amp=(-0.4, 0.8))
    free = plan_preloads(m, traj, loads=F)
    need = float(np.percentile(free.margin, 60))          # above the least-change solution's margin somewhere
    plan = plan_preloads(m, traj, loads=F, margin=need, rate_limit=0.08, dt=1.0, bounds=(0.5, 1.6))
    assert plan.feasible.all() and plan.verified.all()
    assert "ipopt" in plan.method                          # where the least-change step was not stable enough
    assert all(st.to_dict()["residual"] is None for st in plan.steps if st.method == "ipopt")     # no residual
    assert np.all(plan.margin >= need - 1e-7)
    assert np.all(plan.commands >= 0.5 - 1e-9) and np.all(plan.commands <= 1.6 + 1e-9)
    assert np.abs(np.diff(plan.commands, axis=0)).max() <= 0.08 + 1e-9
    # one branch: consecutive configurations stay close (no snap to another well between steps)
    assert np.abs(np.diff(plan.q, axis=0)).max() < 0.2


def test_an_unreachable_step_is_reported_with_the_best_pose_and_the_plan_goes_on():
    m, F = PAPER, (0.0, 0.0)
    ctl = PreloadController(m)
    tip0 = m.tip(ctl.q)
    traj = np.array([tip0 + [-0.05, 0.1], [10.0, 0.0], tip0 + [-0.1, 0.2]])
    plan = plan_preloads(m, traj, loads=F)
    assert plan.status == "infeasible_steps"
    assert plan.feasible.tolist() == [True, False, True] and plan.verified.tolist() == [True, True, True]
    assert plan.method[1] == "none" and "reach" in plan.steps[1].message
    assert plan.steps[1].status == "infeasible" and not plan.steps[1].success and plan.steps[0].success
    assert not plan.success and "2 feasible" in plan.message
    np.testing.assert_allclose(plan.tip[1], plan.tip[0], atol=1e-9)      # stayed at the last feasible pose
    np.testing.assert_array_equal(plan.commands[1], plan.commands[0])     # held
    d = plan.to_dict()
    assert d["feasible"] == [True, False, True] and d["margin"][1] == d["margin"][0]
    s = plan.steps[1].to_dict()             # one infeasible step (the control stream sends it): the held state
    assert s["feasible"] is False and s["margin"] == d["margin"][0] and s["command"] == d["commands"][0]


def test_validation_names_the_field():
    for kw, fld in (({"load": (1.0,)}, "load"), ({"margin": -1.0}, "margin"), ({"objective": "fast"}, "objective"),
                    ({"bounds": (1.0, 0.5)}, "bounds"), ({"rate_limit": 0.0}, "rate_limit"),
                    ({"weights": np.ones(3)}, "weights"), ({"start": [0.0, 0.1]}, "start")):
        with pytest.raises(to.InvalidParameterError) as e:
            PreloadController(PAPER, **kw)
        assert e.value.field == fld
    with pytest.raises(to.InvalidParameterError) as e:
        plan_preloads(PAPER, [[1.0, np.nan]])
    assert e.value.field == "targets"
    with pytest.raises(to.InvalidParameterError) as e:
        plan_preloads(PAPER, [[7.0, 0.5]], loads=[[0.0, 0.0], [1.0, 0.0]])
    assert e.value.field == "loads"
    with pytest.raises(to.InvalidParameterError) as e:
        PreloadController(PAPER).step([7.0, 0.5], end_angle=float("inf"))
    assert e.value.field == "end_angle"


@pytest.mark.slow
def test_where_the_least_change_rule_would_snap_the_plan_stays_stable_on_its_branch():
    """A bistable chain's tip pushed along a line: the least-change rest lengths (SLSQP on the reference model,
    step after step) lose stability on the way (the arm would snap); the plan keeps the margin, stable by the
    reference Hessian at every step, on one continuous branch."""
    m, F = BISTABLE, np.zeros(2)
    ctl = PreloadController(m)
    tip0 = m.tip(ctl.q)
    K = 40
    traj = np.array([tip0 + np.array([-1.0, 2.0]) * k / (K - 1) for k in range(K)])
    q, ell, worst = ctl.q.copy(), ctl.ell.copy(), np.inf
    for k in range(1, K):
        q, ell = _slsqp_step(m, ell, q, traj[k], F)
        worst = min(worst, float(np.linalg.eigvalsh(ref_chain(m, ell).lagrangian_hess(q, F))[0]))
    assert worst < -0.05                                  # the least-change path loses stability
    need = 0.05
    plan = plan_preloads(m, traj, loads=F, margin=need)
    assert plan.feasible.all() and plan.verified.all() and "ipopt" in plan.method
    for k in range(K):
        w = np.linalg.eigvalsh(ref_chain(m, plan.commands[k]).lagrangian_hess(plan.q[k], F))
        assert w[0] >= need - 1e-6
    assert np.abs(np.diff(plan.q, axis=0)).max() < 0.2   # continuous: no jump to another well between steps


def test_a_plan_and_its_steps_follow_the_result_contract():
    """The plan's status from its steps; the solver's own status in the step's solver detail; frozen."""
    F = (-0.02, 0.01)
    tip0 = PAPER.tip(PreloadController(PAPER, load=F).q)
    plan = plan_preloads(PAPER, [tip0 + [-0.03, 0.05], [10.0, 0.0]], loads=F)
    assert (plan.status, plan.success) == ("infeasible_steps", False)
    ok, bad = plan.steps
    assert (ok.status, ok.success, ok.method) == ("feasible", True, "newton")
    assert ok.solver.status == "Newton_Converged" and ok.solver.iterations >= 1
    assert (bad.status, bad.success, bad.solver.iterations) == ("infeasible", False, 0)
    d = plan.to_dict()
    assert list(d)[:3] == ["success", "status", "message"] and d["steps"][0]["solver"]["status"] == "Newton_Converged"
    assert list(d["steps"][1])[:3] == ["success", "status", "message"] and d["steps"][1]["success"] is False
    with pytest.raises(AttributeError):
        plan.status = "complete"
    with pytest.raises(ValueError):
        plan.q[0, 0] = 1.0
    with pytest.raises(ValueError):
        ok.command[0, 0] = 1.0
    assert isinstance(plan.steps, tuple) and isinstance(plan.method, tuple)
