"""The time base and the start of preload control (analyses/design/preload_control.py).

* a rate limit is a length per second: with non-uniform ``times`` every change (the first from ``rest_lengths0``)
  stays within ``rate * (t_k - t_{k-1})``;
* where the limit must bind it does, exactly: an independent least max-norm change to reach the target (SLSQP on
  the numpy reference model, tests/support/reference_model.py) decides whether a step is reachable in ``dt``
  seconds, and a reachable step changes its most-moved rest length by ``rate * dt``;
* the start's rest lengths are ``rest_lengths0``: the start configuration is an equilibrium with them (by the
  reference model) and the first step is measured from them;
* refusals name their field.
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


def changes(ell0, rest_lengths) -> np.ndarray:
    """The largest change of a rest length at each step, the first from ``ell0``."""
    R = np.concatenate([np.reshape(ell0, (1, -1)), np.reshape(rest_lengths, (len(rest_lengths), -1))])
    return np.abs(np.diff(R, axis=0)).max(axis=1)


def least_max_change(m, ell_prev, q_prev, target, F, ell_guess) -> float:
    """min s subject to |l - l_prev| <= s, the equilibrium under F and the tip at target (SLSQP, reference model)."""
    n, F = m.n, np.asarray(F, float)

    def eq(x):
        ch = ref_chain(m, x[n:3 * n])
        return np.concatenate([ch.lagrangian_grad(x[:n], F), ch.tip(x[:n]) - target])

    def box(x):
        d = x[n:3 * n] - ell_prev
        return np.concatenate([x[-1] - d, x[-1] + d])

    x0 = np.concatenate([q_prev, ell_guess, [np.abs(ell_guess - ell_prev).max()]])
    res = so.minimize(lambda x: x[-1], x0, method="SLSQP", constraints=[{"type": "eq", "fun": eq},
                                                                        {"type": "ineq", "fun": box}],
                      options={"ftol": 1e-14, "maxiter": 1000})
    assert res.success, res.message
    return float(res.x[-1])


def test_the_rate_is_per_second_with_non_uniform_times():
    m, F = BISTABLE, (0.0, 0.02)
    ctl = PreloadController(m, load=F)
    tip0, ell0 = m.tip(ctl.q), ctl.ell.copy()
    T = np.array([tip0 + np.array([-0.05, 0.1]) * k for k in range(1, 5)])
    free = plan_preloads(m, T, loads=F)
    need = changes(ell0, free.commands)                 # each step's change without a rate limit
    times = np.array([0.4, 0.5, 1.1, 1.25])                  # 0.4, 0.1, 0.6, 0.15 s apart
    rate = 0.8 * need.min() / 0.1                            # length / s: the 0.1 s step cannot make its free change
    plan = plan_preloads(m, T, loads=F, times=times, rate_limit=rate)
    np.testing.assert_array_equal(plan.times, times)
    assert plan.to_dict()["times"] == times.tolist()
    allowed = rate * np.array([0.4, 0.1, 0.6, 0.15])         # by hand: rate * (t_k - t_{k-1}), t_{-1} = 0
    got = changes(ell0, plan.commands)
    assert np.all(got <= allowed + 1e-9)
    assert plan.feasible.all() and plan.verified.all()
    assert got[1] == pytest.approx(allowed[1], rel=1e-5)     # the short step moves as fast as allowed
    # a per-step reading of the same number would allow `rate` at every step: the 0.1 s step is held to a tenth
    assert need[1] > allowed[1] and allowed[1] < 0.2 * rate
    # a fixed step dt is the times (k + 1) dt
    fixed = plan_preloads(m, T, loads=F, dt=0.25, rate_limit=rate)
    np.testing.assert_allclose(fixed.times, [0.25, 0.5, 0.75, 1.0])
    same = plan_preloads(m, T, loads=F, times=[0.25, 0.5, 0.75, 1.0], rate_limit=rate)
    np.testing.assert_allclose(fixed.commands, same.commands, atol=1e-12)
    assert np.all(changes(ell0, fixed.commands) <= rate * 0.25 + 1e-9)
    # no time base, no rate: the times are unknown (null in JSON)
    assert np.isnan(free.times).all() and free.to_dict()["times"] == [None] * 4


@pytest.mark.parametrize("name,m,F", CHAINS, ids=[c[0] for c in CHAINS])
def test_the_limit_binds_exactly_where_the_least_max_change_says(name, m, F):
    ctl = PreloadController(m, load=F)
    tip0, ell0, q0 = m.tip(ctl.q), ctl.ell.copy(), ctl.q.copy()
    target = tip0 + np.array([-0.05, 0.1])
    free = PreloadController(m, load=F).step(target)
    s = least_max_change(m, ell0, q0, target, F, free.command.ravel())
    assert s < np.abs(free.command.ravel() - ell0).max() - 1e-3    # the least-change step moves more
    rate = 0.1                                                            # length / s
    slow = PreloadController(m, load=F, rate_limit=rate).step(target, dt=0.95 * s / rate)
    assert not slow.feasible                                              # not reachable in that time
    fast_ctl = PreloadController(m, load=F, rate_limit=rate, dt=1.05 * s / rate)    # the controller's own dt
    fast = fast_ctl.step(target)
    assert fast.feasible
    assert np.abs(fast.command.ravel() - ell0).max() == pytest.approx(1.05 * s, rel=1e-6)   # it binds
    ch = ref_chain(m, fast.command)
    q = forward(ch, F, q0)                                                # the forward solve lands on the target
    assert np.allclose(ch.tip(q), target, atol=1e-6)
    assert np.linalg.eigvalsh(ch.lagrangian_hess(q, np.asarray(F, float)))[0] > 0


def test_the_start_and_the_first_step_use_rest_lengths0():
    m, F = HETERO, (0.01, -0.01)
    r0 = np.array([[1.0, 1.04], [0.97, 1.02], [1.03, 0.99]])          # the arm's rest lengths, not m's
    own = np.column_stack([m.L1_0, m.L2_0])
    ctl = PreloadController(m, rest_lengths0=r0, load=F)
    np.testing.assert_array_equal(ctl.ell, r0.ravel())
    Fa = np.asarray(F, float)
    assert np.abs(ref_chain(m, r0).lagrangian_grad(ctl.q, Fa)).max() < 1e-9            # an equilibrium with r0
    assert np.abs(ref_chain(m, own).lagrangian_grad(ctl.q, Fa)).max() > 1e-3            # not with m's own
    assert np.linalg.eigvalsh(ref_chain(m, r0).lagrangian_hess(ctl.q, Fa))[0] > 0
    tip0 = ref_chain(m, r0).tip(ctl.q)
    T = np.array([tip0 + [-0.01, 0.02], tip0 + [-0.02, 0.04]])
    rate, dt = 0.1, 0.5
    plan = plan_preloads(m, T, loads=F, rest_lengths0=r0, dt=dt, rate_limit=rate)
    assert plan.feasible.all() and plan.verified.all()
    got = changes(r0, plan.commands)
    assert np.all(got <= rate * dt + 1e-9)
    assert np.abs(plan.commands[0] - own).max() > rate * dt       # measured from m's own it would not fit
    ch = ref_chain(m, plan.commands[0])
    q = forward(ch, Fa, ctl.q)                                        # from the start with r0
    assert np.allclose(ch.tip(q), T[0], atol=1e-6) and np.allclose(q, plan.q[0], atol=1e-7)
    # a start configuration given explicitly is read with r0 too
    again = plan_preloads(m, T, loads=F, rest_lengths0=r0, dt=dt, rate_limit=rate, start=ctl.q)
    np.testing.assert_allclose(again.commands, plan.commands, atol=1e-12)


def test_refusals_name_the_field():
    T = [[7.6, 0.5], [7.5, 0.7]]
    cases = [
        ({"rate_limit": 0.1}, "dt"),                                       # a rate per second needs a time base
        ({"rate_limit": 0.1, "times": [0.5]}, "times"),                    # one per target
        ({"times": [0.5, 0.5]}, "times"),                                  # strictly increasing
        ({"times": [0.0, 0.5]}, "times"),                                  # the start is time 0
        ({"times": [0.5, np.nan]}, "times"),
        ({"times": [0.5, 1.0], "dt": 0.5}, "times"),                       # not both
        ({"dt": 0.0}, "dt"), ({"dt": np.inf}, "dt"),
        ({"rest_lengths0": np.ones(8)}, "rest_lengths0"),                  # (n, 2)
        ({"rest_lengths0": np.ones((3, 2))}, "rest_lengths0"),
        ({"rest_lengths0": [[1.0, np.nan]] * 4}, "rest_lengths0"),
        ({"rest_lengths0": [[1.0, 1.0]] * 3 + [[1.0, 2.5]], "bounds": (0.5, 2.0)}, "rest_lengths0"),
    ]
    for kw, fld in cases:
        with pytest.raises(to.InvalidParameterError) as e:
            plan_preloads(PAPER, T, **kw)
        assert e.value.field == fld, kw
    ctl = PreloadController(PAPER, rate_limit=0.1)                        # the time may come with each step
    with pytest.raises(to.InvalidParameterError) as e:
        ctl.step([7.6, 0.5])
    assert e.value.field == "dt" and "per second" in e.value.message
    with pytest.raises(to.InvalidParameterError) as e:
        ctl.step([7.6, 0.5], dt=-1.0)
    assert e.value.field == "dt"
    with pytest.raises(to.InvalidParameterError) as e:
        PreloadController(PAPER, dt=0.0)
    assert e.value.field == "dt"


@pytest.mark.parametrize("dt", [-1.0, 0.0, float("nan"), "abc"])
def test_a_step_s_dt_is_checked_with_or_without_a_rate_limit(dt):
    for ctl in (PreloadController(PAPER), PreloadController(PAPER, rate_limit=0.1, dt=1.0)):
        tip = PAPER.tip(ctl.q)
        with pytest.raises(to.InvalidParameterError) as exc:
            ctl.step(tip, dt=dt)
        assert exc.value.field == "dt"
