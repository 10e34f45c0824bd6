"""The four plans of issue 39 that hid what the arm does inside a step, each checked along its transitions.

Every step of each plan is checked by ``check_plan`` (``test_plan_transitions.py``): the independent reference
transition (``tests/support/reference_transition.py``) from the state the previous step reports confirms each
``verified`` step (no snap, the margin held, the end on the step's pose), each reported snap (where it lands) and
each step without equilibrium (a joint reaches its stop).
"""

from __future__ import annotations

import numpy as np
import pytest
import reference_control as RC  # noqa: E402
from test_plan_transitions import _segment, check_plan

import tensegrity_opt as to
from tensegrity_opt.analyses.paths.descent import ArmState
from tensegrity_opt.analyses.paths.transition import follow


def _transition_of(m, q, ell, F0, command, F1):
    """The library's transition of one step (for the comparison with the unverified plan)."""
    mk = to.Manipulator(s.replace(L0=tuple(r)) for s, r in zip(m.segments, ell))
    state = ArmState(np.asarray(q, float), np.asarray(F0, float), mk.tip(q), float(mk.energy(q)), 0, True)
    return follow(m, state, np.asarray(ell, float), np.asarray(command, float), np.asarray(F0, float),
                  np.asarray(F1, float))


def five_random_segments(seed: int = 39) -> to.Manipulator:
    """Five random segments (mixed families), the kind of chain of the issue's first example."""
    rng = np.random.default_rng(seed)
    fam = rng.choice(["monotonic", "bistable", "asymmetric"], size=5)
    return to.Manipulator(_segment(rng, f) for f in fam)


@pytest.mark.slow          # ~12 s a seed: the fast lane's budget (issue 39's other examples stay in it)
@pytest.mark.parametrize("seed", [39, 2])
def test_a_horizon_step_that_hid_a_snap_is_not_sent(seed):
    """Targets moving, then (100, 100) three times, then back; approach, horizon 5, rate 0.1, dt 0.5, margin 0.01:
    unverified, a step of the plan snaps inside its move (the arm would land elsewhere); verified, every step's
    transition follows its branch (the reference agrees), and the plan is as good as step by step."""
    m = five_random_segments(seed)
    F = (0.0, -0.01)
    tip0 = m.tip(to.PreloadController(m, load=F).q)
    T = np.array([tip0 + 1.175 * np.array([-0.1, 0.1]) * k / 2 for k in range(3)] + [[100.0, 100.0]] * 3
                 + [tip0 + 1.175 * np.array([-0.1, 0.1])] * 4)
    kw = dict(loads=F, rate_limit=0.1, dt=0.5, margin=0.01, on_infeasible="approach", horizon=5)
    blind = to.plan_preloads(m, T, verify=False, **kw)
    q, ell, snapped = blind.start, np.column_stack([m.L1_0, m.L2_0]), False
    for st in blind.steps:                      # the unverified plan hides a snap (or a joint stop) in a step
        tr = _transition_of(m, q, ell, F, st.command, F)
        if tr.status != "followed" or np.abs(tr.q - st.q).max() > 1e-6:
            snapped = True
            break
        q, ell = st.q, st.command
    assert snapped
    plan = to.plan_preloads(m, T, **kw)
    counts = check_plan(m, plan, np.tile(F, (len(T), 1)))
    assert counts["verified"] == len(T) and plan.verified.all()
    own = to.plan_preloads(m, T, **{**kw, "horizon": None})
    assert plan.feasible.sum() >= own.feasible.sum()
    assert plan.tip_error.sum() <= own.tip_error.sum() * (1 + 1e-9) + 1e-9


@pytest.mark.slow
def test_a_held_arm_under_a_load_jump_reports_where_it_goes():
    """``uniform(3, a=0.5)``, rate 0.04/s, dt 1, margin 0.01, hold; the load jumps at step 6 from (0, -0.01) to
    (0.9797, 0): the held arm does not stay where the hold says; the step reports where its transition takes it
    (a joint's stop here), the reference agrees, and the next steps start from there."""
    m = to.Manipulator.uniform(3, a=0.5)
    ctl = to.PreloadController(m, load=(0.0, -0.01))
    tip0 = m.tip(ctl.q)
    K = 10
    T = np.tile(tip0, (K, 1)) + np.outer(np.arange(1, K + 1), [-0.01, 0.02])
    L = np.tile([0.0, -0.01], (K, 1))
    L[6:] = (0.9797, 0.0)
    plan = to.plan_preloads(m, T, loads=L, rate_limit=0.04, dt=1.0, margin=0.01, on_infeasible="hold")
    counts = check_plan(m, plan, L)
    st = plan.steps[6]
    assert st.status in ("snap", "no_equilibrium") and not st.verified and st.method == "none"
    assert counts["verified"] == 6 and plan.verified[:6].all()
    assert plan.status in ("snapped", "no_equilibrium") and not plan.success
    assert "step(s) 6" in plan.message
    if st.status == "no_equilibrium":
        ratio = np.abs(st.q) / m.joint_limits
        assert ratio.max() > 1 - 1e-5 and np.isnan(st.margin) and "stop" in st.message
    stopped = to.plan_preloads(m, T, loads=L, rate_limit=0.04, dt=1.0, margin=0.01, on_infeasible="hold",
                               on_snap="stop")
    assert len(stopped.steps) == 7 and stopped.status == plan.status and "on_snap='stop'" in stopped.message


def test_a_held_step_below_the_margin_is_not_verified():
    """The paper chain under (-0.06, 0) with margin 0.3 required: its start has margin 0.2118 (the reference's
    Hessian), a target out of reach is held; the held step is not verified (its margin is below the requirement)
    and says so; the same chain reaching a target that restores the margin is verified (its move never drops below
    where it started)."""
    m = to.Manipulator.uniform(4)
    F = (-0.06, 0.0)
    ctl = to.PreloadController(m, load=F, margin=0.3)
    ch = RC.ref_chain(m, np.column_stack([m.L1_0, m.L2_0]))
    mu0 = np.linalg.eigvalsh(ch.lagrangian_hess(ctl.q, np.array(F)))[0]
    assert mu0 == pytest.approx(0.21177572892735, abs=1e-9)
    tip0 = m.tip(ctl.q)
    held = to.plan_preloads(m, [tip0 + [-3.0, 3.0]], loads=F, margin=0.3, rate_limit=0.01, dt=1.0)
    st = held.steps[0]
    assert st.method == "none" and st.status == "infeasible" and not st.verified
    assert st.margin == pytest.approx(mu0, abs=1e-9) and "below the required 0.3" in st.message
    reach = to.plan_preloads(m, [tip0 + [-0.3, 0.5]], loads=F, margin=0.3)
    counts = check_plan(m, reach, np.tile(F, (1, 1)))
    assert reach.verified.all() and counts["verified"] == 1 and reach.margin[0] >= 0.3 - 1e-7


@pytest.mark.slow_cases(keep=1)            # the horizon case (~7 s) in the slow lane: the fast one's budget
@pytest.mark.parametrize("horizon", [None, "all"])
def test_a_step_without_equilibrium_is_a_state_and_the_plan_goes_on_from_it(horizon):
    """The paper chain, 8 targets moving (-0.02, 0.04) a step, a load (-5, 0) at step 5 only: no equilibrium at
    step 5 (a joint reaches its stop: the reference agrees), the step says so and reports the configuration at the
    stop; step 6 starts from there (released, not verified); the horizon plan is as good as step by step."""
    m = to.Manipulator.uniform(4)
    tip0 = m.tip(np.zeros(4))
    T = np.array([tip0 + (k + 1) * np.array([-0.02, 0.04]) for k in range(8)])
    L = np.zeros((8, 2))
    L[5] = (-5.0, 0.0)
    plan = to.plan_preloads(m, T, loads=L, horizon=horizon)
    counts = check_plan(m, plan, L)
    st = plan.steps[5]
    assert st.status == "no_equilibrium" and not st.verified and not st.feasible
    assert (np.abs(st.q) / m.joint_limits).max() > 1 - 1e-5 and np.isnan(st.margin) and np.isnan(st.energy)
    assert st.events and st.events[-1].status == "joint_limit"
    assert "no equilibrium" in st.message and plan.status == "no_equilibrium"
    assert not plan.steps[6].verified and counts["no_equilibrium"] == 1 and counts["release"] == 1
    assert plan.feasible[[0, 1, 2, 3, 4, 6, 7]].all() and plan.verified[[0, 1, 2, 3, 4, 7]].all()
    own = to.plan_preloads(m, T, loads=L)
    assert plan.feasible.sum() >= own.feasible.sum()
    d = plan.to_dict()
    assert d["steps"][5]["status"] == "no_equilibrium" and d["steps"][5]["margin"] is None
    assert d["steps"][5]["events"][-1]["status"] == "joint_limit"


@pytest.mark.slow          # ~13 s: the fast lane keeps its budget (issue 39's other examples stay in it)
def test_step_by_step_and_the_horizon_start_from_the_same_state_and_shape():
    """The straight paper chain under compression (a symmetric start: both mirror-image shapes reach a target off
    the axis): both planners start from the same configuration and take the same shape, whatever the horizon."""
    m = to.Manipulator.uniform(4)
    F = np.array([-0.05, 0.0])
    tip0 = m.tip(to.PreloadController(m, load=F).q)
    T = np.array([tip0 + np.array([-0.3, 0.6]) * np.sin(np.pi * k / 11) for k in range(12)])
    own = to.plan_preloads(m, T, loads=F, rate_limit=0.05, dt=1.0)
    hz = to.plan_preloads(m, T, loads=F, rate_limit=0.05, dt=1.0, horizon=10)
    np.testing.assert_array_equal(own.start, hz.start)
    assert np.all(np.sign(own.q[1]) == np.sign(hz.q[1])) and np.abs(own.q - hz.q).max() < 0.05
    assert hz.verified.all() and own.verified.all()


def test_a_whole_trajectory_too_long_for_the_time_limit_still_gets_its_steps(monkeypatch):
    """horizon='all' on a long trajectory with a time limit its one NLP cannot meet: the window's share of the time
    runs out (a deterministic stand-in: the solve raises the time limit at once) and the steps are planned step by
    step, all of them, each saying why."""
    from tensegrity_opt.analyses.design import horizon as H
    from tensegrity_opt.errors import TimeLimitError

    def slow(self, *a, **k):
        raise TimeLimitError("the window's share of the time ran out")

    monkeypatch.setattr(H._Planner, "_solve", slow)
    m = to.Manipulator.uniform(4)
    tip0 = m.tip(np.zeros(4))
    T = np.array([tip0 + np.array([-0.3, 0.6]) * np.sin(np.pi * k / 29) for k in range(30)])
    p = to.plan_preloads(m, T, horizon="all", timeout=600)
    assert p.status == "complete" and len(p.steps) == 30 and p.verified.all()
    assert all("time_budget" in s.message for s in p.steps)
