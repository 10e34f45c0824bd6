"""Infeasible control steps (analyses/design/preload_control.py): what they command, recovery, the nearest pose.

* an actuator that obeys the commands stays in step with the controller: consecutive commands never differ by
  more than the rate limit, and every command re-solved forward by the numpy reference model
  (tests/support/reference_control.py: a local minimiser of its own energy under the dead load from the previous
  state, polished by Newton) gives the step's reported configuration and tip, stable;
* ``on_infeasible="approach"`` catches up with a target that moved faster than the rate limit allows; ``"hold"``
  never moves;
* the nearest admissible pose against a multi-start reference: scipy SLSQP over the rest lengths in the box,
  the equilibrium of each by the reference model from the current configuration, the margin by its Hessian.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.optimize as so
from reference_control import equilibrium, forward, ref_chain

import tensegrity_opt as to
from tensegrity_opt.analyses.design.preload_control import PreloadController, plan_preloads

PAPER = to.Manipulator.uniform(4)
HETERO = to.Manipulator([to.Segment(0.9, 1.0, 1.2, (1.05, 0.97)), to.Segment(1.1, 0.9, 0.8, 1.0),
                         to.Segment(1.0, 1.1, 1.0, (0.98, 1.02))])
F0 = np.array([0.0, -0.01])


def solved(m, ell, F, q_prev, search=False):
    """The arm with rest lengths ``ell`` under ``F`` from ``q_prev`` by the reference forward solve
    (``reference_control``): its configuration, tip and smallest Hessian eigenvalue; with ``search`` None where it
    reaches no equilibrium (else that fails the test)."""
    ch = ref_chain(m, ell)
    q = equilibrium(ch, F, q_prev) if search else forward(ch, F, q_prev)
    if q is None:
        return None
    return q, ch.tip(q), float(np.linalg.eigvalsh(ch.lagrangian_hess(q, np.asarray(F, float)))[0])


def check_forward(m, plan, loads, q0):
    """Every command of ``plan`` re-solved forward from the previous state gives the step's q and tip, stable."""
    q_prev = q0
    for k in range(len(plan.targets)):
        q, tip, w = solved(m, plan.commands[k], loads[k], q_prev)
        np.testing.assert_allclose(q, plan.q[k], atol=1e-7)
        np.testing.assert_allclose(tip, plan.tip[k], atol=1e-7)
        assert w > 0 and w == pytest.approx(plan.margin[k], rel=1e-6, abs=1e-9)
        assert plan.tip_error[k] == pytest.approx(np.hypot(*(tip - plan.targets[k])), abs=1e-7)
        q_prev = q


def test_commands_stay_within_the_rate_and_re_solve_to_the_reported_state():
    """Feasible, infeasible (held: under a new load), feasible again: the commands an actuator obeys never jump by
    more than the rate limit; the held row commands the previous value, its proposal (the nearest admissible pose)
    is apart; the arm's state under every command is what the step reports."""
    m, rate = HETERO, 0.04
    q0 = PreloadController(m, load=F0).q
    tip0 = m.tip(q0)
    targets = np.array([tip0 + [-0.005, 0.01], tip0 + [-0.9, 1.4], tip0 + [-0.9, 1.4], tip0 + [-0.005, 0.015]])
    loads = np.array([F0, F0 + [0.004, 0.0], F0 + [0.004, 0.0], F0])
    plan = plan_preloads(m, targets, loads=loads, rate_limit=rate, dt=1.0)
    assert plan.feasible.tolist() == [True, False, False, True] and plan.verified.all()
    assert plan.method[1:3] == ("none", "none") and plan.on_infeasible == "hold"
    assert np.abs(np.diff(plan.commands, axis=0)).max() <= rate + 1e-12
    np.testing.assert_array_equal(plan.commands[1], plan.commands[0])           # held
    np.testing.assert_array_equal(plan.commands[2], plan.commands[0])
    assert np.abs(plan.proposals[1] - plan.commands[1]).max() > rate / 2        # the proposal moved, apart
    assert np.abs(plan.proposals[1] - plan.commands[1]).max() <= rate + 1e-12
    assert np.abs(plan.q[1] - plan.q[0]).max() > 1e-4                           # the new load moved the arm
    check_forward(m, plan, loads, q0)
    st = plan.steps[1]
    assert st.tip_error > np.hypot(*(st.proposal_tip - st.target)) + 0.05       # the proposal is nearer
    d = plan.to_dict()
    assert "rest_lengths" not in d and "rest_lengths" not in d["steps"][1]
    assert d["commands"][1] == d["commands"][0] and d["steps"][1]["command"] == d["commands"][0]
    assert d["steps"][1]["proposal"] == d["proposals"][1] and d["margin"][1] is not None
    assert d["tip_error"][3] < 1e-9 and d["on_infeasible"] == "hold"


def too_fast(m, rate, K=12, stop=5, move=(-0.6, 1.2)):
    ctl = PreloadController(m, load=F0, rate_limit=rate, dt=1.0)
    tip0 = m.tip(ctl.q)
    return ctl.q, np.array([tip0 + np.array(move) * min(k, stop) / stop for k in range(K)])


def test_approach_catches_up_with_a_target_moving_faster_than_the_rate_limit_and_hold_does_not():
    m, rate, stop = PAPER, 0.05, 5
    q0, traj = too_fast(m, rate, stop=stop)
    hold = plan_preloads(m, traj, loads=F0, rate_limit=rate, dt=1.0)
    assert not hold.feasible[1:].any() and set(hold.method[1:]) == {"none"}
    np.testing.assert_allclose(hold.commands, np.broadcast_to(hold.commands[0], hold.commands.shape))
    assert hold.tip_error[-1] == pytest.approx(np.hypot(*(traj[-1] - traj[0])), rel=1e-9)     # never moved
    plan = plan_preloads(m, traj, loads=F0, rate_limit=rate, dt=1.0, on_infeasible="approach")
    assert plan.status == "infeasible_steps" and plan.on_infeasible == "approach"
    assert plan.verified.all() and np.abs(np.diff(plan.commands, axis=0)).max() <= rate + 1e-12
    late = ~plan.feasible
    assert late[1] and set(np.asarray(plan.method)[late]) == {"nearest"}
    np.testing.assert_array_equal(plan.commands, plan.proposals)               # approach commands its proposal
    assert plan.feasible[-3:].all() and plan.tip_error[-1] < 1e-9               # caught up, on the target
    after = plan.tip_error[stop:]
    assert np.all(np.diff(after) <= 1e-9)                                       # the target stopped: closing in
    assert np.all(plan.tip_error <= hold.tip_error + 1e-9)
    check_forward(m, plan, [F0] * len(traj), q0)


def test_on_infeasible_is_checked():
    with pytest.raises(to.InvalidParameterError) as e:
        PreloadController(PAPER, on_infeasible="wait")
    assert e.value.field == "on_infeasible"
    with pytest.raises(to.InvalidParameterError) as e:
        plan_preloads(PAPER, [[7.0, 0.5]], on_infeasible="skip")
    assert e.value.field == "on_infeasible"


def reference_nearest(m, ell, q, F, target, lo, hi, margin, starts=30, seed=1):
    """The smallest tip distance to ``target`` over rest lengths in the box ``[lo, hi]`` (segment-major) whose
    equilibrium from ``q`` (:func:`solved`) has the margin: SLSQP from the current rest lengths and ``starts``
    uniform points of the box."""
    seen: dict[bytes, object] = {}

    def at(x):
        key = x.tobytes()
        if key not in seen:
            seen[key] = solved(m, x, F, q, search=True)
        return seen[key]

    def dist2(x):
        r = at(x)
        return 1e3 if r is None else float(np.sum((r[1] - target) ** 2))

    def stable(x):
        r = at(x)
        return -1.0 if r is None else r[2] - margin

    rng = np.random.default_rng(seed)
    best = dist2(ell)
    for x0 in [ell, *(lo + rng.uniform(size=(starts, lo.size)) * (hi - lo))]:
        res = so.minimize(dist2, x0, method="SLSQP", bounds=list(zip(lo, hi)),
                          constraints=[{"type": "ineq", "fun": stable}], options={"ftol": 1e-12, "maxiter": 200})
        x = np.clip(res.x, lo, hi)
        if stable(x) >= -1e-9:
            best = min(best, dist2(x))
    return float(np.sqrt(best))


@pytest.mark.slow
@pytest.mark.parametrize("kw,move", [({"rate_limit": 0.05, "dt": 1.0}, (-0.5, 1.0)),
                                     ({"bounds": (0.85, 1.15)}, (-1.5, 3.0)),
                                     ({"rate_limit": 0.2, "dt": 1.0, "bounds": (0.7, 1.3)}, (-2.0, 2.5))],
                         ids=["beyond-the-rate-box", "beyond-the-bounds", "both"])
def test_the_nearest_admissible_pose_is_as_near_as_a_multistart_reference(kw, move):
    m = PAPER
    ctl = PreloadController(m, load=F0, on_infeasible="approach", **kw)
    q0, ell0 = ctl.q.copy(), ctl.ell.copy()
    target = m.tip(q0) + move
    lo, hi = ctl.box()
    st = ctl.step(target)
    assert not st.feasible and st.method == "nearest"
    ref = reference_nearest(m, ell0, q0, F0, target, lo, hi, ctl.margin)
    assert ref < np.hypot(*move) - 0.1                                       # moving helps
    assert st.tip_error <= ref + 1e-6
    got = solved(m, st.command, F0, q0)                                      # the arm gets there from q0, stable
    np.testing.assert_allclose(got[0], st.q, atol=1e-7)
    assert got[2] >= ctl.margin - 1e-7 and st.margin == pytest.approx(got[2], rel=1e-6)
    assert np.all(st.command.ravel() >= lo - 1e-12) and np.all(st.command.ravel() <= hi + 1e-12)
