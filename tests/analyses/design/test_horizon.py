"""The horizon planner (``plan_preloads(..., horizon=N | "all")``, analyses/design/horizon.py) against independent
routes.

* every step of a plan is re-solved forward with the reference model (tests/support/reference_model.py: its own
  energy, scipy's minimiser of E - F . tip from the previous step's configuration) and must land on the reported
  pose, stable with the margin by the reference Hessian's eigenvalues; the rates hold between consecutive commands
  and from the given current rest lengths, the bounds hold;
* the anticipation case (a compressive payload arriving at a known step, a slow actuator and a margin): the
  step-by-step plan goes infeasible at the payload and never recovers, the horizon plan stiffens the arm ahead of it
  and stays on every target;
* the whole-trajectory plan and the receding one agree on an easy trajectory (both on target);
* an unreachable jump: with ``on_infeasible="approach"`` the plan moves toward it at the full rate and catches up;
  with ``"hold"`` the off-target steps hold the last command, their proposal nearer the target.
"""

from __future__ import annotations

import numpy as np
import pytest
from reference_control import forward, ref_chain

import tensegrity_opt as to
from tensegrity_opt.analyses.design.preload_control import PreloadController, plan_preloads
from tensegrity_opt.errors import InvalidParameterError

PREBENT = to.Manipulator.uniform(4, 1.0, 1.0, 1.0, (1.04, 0.96))
HETERO = to.Manipulator([to.Segment(0.9, 1.0, 1.2, (1.05, 0.97)), to.Segment(1.1, 0.9, 0.8, 1.0),
                         to.Segment(1.0, 1.1, 1.0, (0.98, 1.02))])
MARGIN, RATE, PAYLOAD, ARRIVES, K = 0.05, 0.04, 0.08, 7, 14


def step_by_step(m, targets, loads, rate, margin):
    """The step-by-step controller's plan of the same trajectory, its rate a length per step."""
    return plan_preloads(m, targets, loads=loads, rate_limit=rate, dt=1.0, margin=margin)


def check_forward(m, plan, loads, q0, rest0, rate, margin):
    """Every step re-solved forward by the reference model: on the reported pose, stable with the margin; rates
    and bounds held."""
    q_prev = q0
    lo, hi = 0.1 * float(m.b.min()), 4.0 * float(m.b.max())
    prev = np.asarray(rest0, float)
    for k in range(len(plan.targets)):
        cmd = plan.commands[k]
        ch = ref_chain(m, cmd)
        q = forward(ch, loads[k], q_prev)
        np.testing.assert_allclose(q, plan.q[k], atol=1e-7)
        np.testing.assert_allclose(ch.tip(q), plan.tip[k], atol=1e-7)
        w = np.linalg.eigvalsh(ch.lagrangian_hess(q, np.asarray(loads[k], float)))
        assert w[0] >= margin - 1e-7
        assert np.abs(cmd - prev).max() <= rate + 1e-9           # the rate box, from rest_lengths0 first
        assert cmd.min() >= lo and cmd.max() <= hi
        q_prev, prev = q, cmd


@pytest.fixture(scope="module")
def payload():
    """The anticipation case: a pre-bent chain, the tip moving up, a compressive payload arriving at step 7."""
    m = PREBENT
    q0 = PreloadController(m).q
    tip0 = m.tip(q0)
    targets = np.array([tip0 + np.array([-0.1, 0.2]) * min(k, 5) / 5 for k in range(K)])
    loads = np.zeros((K, 2))
    loads[ARRIVES:, 0] = -PAYLOAD
    hz = plan_preloads(m, targets, loads=loads, rate_limit=RATE, dt=1.0, margin=MARGIN, horizon=10)
    sbs = step_by_step(m, targets, loads, RATE, MARGIN)
    return m, q0, targets, loads, hz, sbs


def test_the_horizon_plan_anticipates_the_payload_where_the_step_by_step_plan_goes_infeasible(payload):
    m, q0, targets, loads, hz, sbs = payload
    assert not sbs.feasible[ARRIVES:].any() and sbs.feasible[:ARRIVES].all()      # infeasible at the payload, on
    assert hz.status == "complete" and hz.success and hz.horizon == 10
    assert hz.method == ("horizon",) * K and hz.verified.all() and hz.feasible.all()
    assert np.linalg.norm(hz.tip - targets, axis=1).max() <= 1e-6
    assert all(s.solver.status == "Solve_Succeeded" for s in hz.steps)
    # it starts moving before the payload: the rest lengths change while the tip target stands still (steps 5, 6)
    assert np.abs(hz.commands[ARRIVES - 1] - hz.commands[ARRIVES - 3]).max() > 0.5 * RATE
    assert hz.margin[ARRIVES:].min() >= MARGIN - 1e-7


def test_every_step_of_the_horizon_plan_lands_forward_in_the_reference_model(payload):
    m, q0, targets, loads, hz, _ = payload
    check_forward(m, hz, loads, q0, np.column_stack([m.L1_0, m.L2_0]), RATE, MARGIN)


def test_whole_trajectory_and_receding_agree_on_an_easy_trajectory():
    m, F = HETERO, np.array([0.01, -0.01])
    q0 = PreloadController(m, load=F).q
    tip0 = m.tip(q0)
    targets = np.array([tip0 + np.array([-0.1, 0.2]) * np.sin(np.pi * k / 7) for k in range(8)])
    rest0 = np.column_stack([m.L1_0, m.L2_0]) + 0.01                    # the arm's own rest lengths, not m's
    eq0 = to.solve_equilibrium_under_force(to.Manipulator(s.replace(L0=tuple(r)) for s, r in zip(m.segments, rest0)),
                                           *F, q0=q0)
    plans = [plan_preloads(m, targets, loads=F, rate_limit=0.1, dt=1.0, margin=1e-3, rest_lengths0=rest0, start=eq0,
                           horizon=h) for h in (3, "all")]
    for p in plans:
        assert p.status == "complete" and p.feasible.all() and p.verified.all()
        check_forward(m, p, np.tile(F, (8, 1)), eq0.q, rest0, 0.1, 1e-3)
    np.testing.assert_allclose(plans[0].tip, plans[1].tip, atol=1e-6)


def test_an_unreachable_jump_approach_catches_up_at_the_full_rate_hold_stays():
    m = HETERO
    q0 = PreloadController(m).q
    tip0 = m.tip(q0)
    targets = np.array([tip0] + [tip0 + np.array([-0.1, 0.4])] * 5)
    rate = 0.03
    near = plan_preloads(m, targets, rate_limit=rate, dt=1.0, horizon=2, on_infeasible="approach")
    # step 0 (the start pose) is kept on target by the step-by-step answer (the window would leave it a little off
    # to be nearer the jump): a step that step by step reaches stays on target
    assert near.method == ("newton",) + ("horizon",) * 5 and near.tip_error[0] <= 1e-9
    assert near.verified.all() and not near.feasible[1] and near.feasible[-1]
    assert near.status == "infeasible_steps" and not near.success
    moves = np.abs(np.diff(near.commands, axis=0)).max(axis=(1, 2))
    assert moves[0] == pytest.approx(rate, rel=1e-6)                      # as fast as allowed
    assert np.all(np.diff(near.tip_error[1:][~near.feasible[1:]]) < 0)    # the error falls until on target
    check_forward(m, near, np.zeros((6, 2)), q0, np.column_stack([m.L1_0, m.L2_0]), rate, 1e-3)
    held = plan_preloads(m, targets, rate_limit=rate, dt=1.0, horizon=2, on_infeasible="hold")
    assert held.method[1] == "none" and not held.feasible[1:].any()
    np.testing.assert_allclose(held.commands[1:], np.broadcast_to(held.commands[0], held.commands[1:].shape))
    assert held.steps[1].solver.status != "Solve_Succeeded"              # the pose of step 1 cannot be met
    assert np.abs(held.proposals[1] - held.commands[0]).max() == pytest.approx(rate, rel=1e-6)   # what approach sends
    assert np.linalg.norm(held.steps[1].proposal_tip - targets[1]) < held.tip_error[1] - 0.01
    assert held.tip_error[-1] > 0.3 and near.tip_error[-1] <= 1e-6


@pytest.mark.parametrize("horizon", [0, -1, "some", 2.5, True])
def test_the_horizon_vocabulary(horizon):
    with pytest.raises(InvalidParameterError) as exc:
        plan_preloads(HETERO, [[5.0, 0.1]], horizon=horizon)
    assert exc.value.field == "horizon"
    with pytest.raises(InvalidParameterError) as exc:
        plan_preloads(HETERO, [[5.0, 0.1]], horizon=3, objective="margin")
    assert exc.value.field == "objective"


def test_approach_settles_on_the_nearest_pose_as_the_step_by_step_plan():
    """A target out of reach that stays there: every horizon ends as near to it as the step-by-step controller's
    nearest admissible pose (the distance the results report; a norm taken component by component settles
    elsewhere: 0.1979 here against 0.1740)."""
    m = to.Manipulator([to.Segment(0.8514, 0.9997, (1.0812, 0.623), (0.9648, 1.0428)),
                        to.Segment(0.8282, 0.8519, (1.3587, 1.0975), (0.9869, 1.0011))])
    tip0 = m.tip(PreloadController(m).q)
    targets = [tip0 + np.array([-0.3, 0.5])] * 8
    kw = dict(rate_limit=0.06, dt=1.0, margin=0.01, on_infeasible="approach")
    near = plan_preloads(m, targets, **kw).tip_error[-1]
    assert 0.1 < near < 0.3
    for h in (3, "all"):
        p = plan_preloads(m, targets, horizon=h, **kw)
        assert p.verified.all() and p.tip_error[-1] <= near + 1e-6


def test_a_horizon_longer_than_the_trajectory_is_the_whole_trajectory():
    m = HETERO
    tip0 = m.tip(PreloadController(m).q)
    targets = [tip0 + np.array([-0.02, 0.05]) * k for k in range(3)]
    whole = plan_preloads(m, targets, horizon="all")
    for h in (3, 2000):
        p = plan_preloads(m, targets, horizon=h)
        assert p.status == "complete" and p.horizon == h
        np.testing.assert_allclose(p.commands, whole.commands, atol=1e-7)
