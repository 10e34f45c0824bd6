"""Every plan step checked along its transition against an independent reference (issue 39).

A plan's step moves the command (the springs' rest lengths) and the tip load linearly from the previous step's to its
own; the arm follows quasi-statically. ``tests/support/reference_transition.py`` (numpy/scipy on the reference model,
no ``tensegrity_opt``) follows that move by its own natural-parameter continuation, locates folds by bisection, lands
snaps by an LSODA gradient flow and measures the least margin along the move. For each step of random plans of every
family (monotonic, bistable, heterogeneous, asymmetric preloads, load jumps; hold and approach; step by step, a
receding horizon and the whole trajectory) the test runs the reference from the state the previous step reports:

* a ``verified`` step: the reference follows its branch to the end (no snap, no joint limit), ends on the step's
  configuration, and its least margin along the move is not below the required margin (nor below the margin the arm
  started the move with, when that was already lower);
* a ``snap`` step: the reference snaps too and lands on the step's configuration;
* a ``no_equilibrium`` step: the reference reaches a joint limit;
* any other step (not verified): the reference confirms why (its margin falls short, or it snaps).

Chaining the checks step after step is the check that no step starts from a state the arm is not in.
"""

from __future__ import annotations

import numpy as np
import pytest
import reference_control as RC  # noqa: E402
import reference_transition as RT  # noqa: E402

import tensegrity_opt as to
from tensegrity_opt.analyses.design.preloads import stability_margin

#: Configurations (rad) within which the reference ends where the step says.
SAME_Q = 1e-5


def _segment(rng, family: str) -> to.Segment:
    b = rng.uniform(0.8, 1.2)
    a = rng.uniform(0.45, 0.75) * b
    k = rng.uniform(0.6, 1.6)
    thresh = 2 * b * (1 - (a / b) ** 2)                    # condition (4): monotonic where L0 > thresh
    if family == "bistable":
        L0 = thresh - rng.uniform(0.15, 0.4)
    else:
        L0 = thresh + rng.uniform(0.2, 0.8)
    if family == "asymmetric":
        d = rng.uniform(0.03, 0.12) * rng.choice([-1, 1])
        return to.Segment(a, b, (k, k * rng.uniform(0.8, 1.25)), (L0 + d, L0 - d))
    return to.Segment(a, b, k, L0)


def _chain(rng, family: str, n: int) -> to.Manipulator:
    if family == "heterogeneous":
        return to.Manipulator(_segment(rng, rng.choice(["monotonic", "bistable", "asymmetric"])) for _ in range(n))
    return to.Manipulator(_segment(rng, family) for _ in range(n))


def random_plan(seed: int):
    """A random chain and plan scenario of a family chosen by the seed: ``(m, targets, kwargs)``."""
    rng = np.random.default_rng(seed)
    family = ("monotonic", "bistable", "heterogeneous", "asymmetric")[seed % 4]
    n = int(rng.integers(2, 6))
    K = int(rng.integers(4, 8))
    F0 = rng.normal(scale=0.01, size=2)
    loads = np.tile(F0, (K, 1))
    if seed % 3 == 0:                                       # a load jump
        loads[K // 2:] += rng.normal(scale=0.3, size=2)
    elif seed % 3 == 1:                                     # a large one, for a step
        loads[K // 2] += rng.normal(scale=3.0, size=2)
    for _ in range(20):                                     # a chain with a stable start under the first load
        m = _chain(rng, family, n)
        try:
            ctl = to.PreloadController(m, load=loads[0])
        except (to.NoEquilibriumError, to.InvalidParameterError):
            continue
        break
    tip0 = m.tip(ctl.q)
    d = rng.normal(size=2)
    d /= np.linalg.norm(d)
    step = rng.uniform(0.05, 0.25) * float(np.mean(m.b))
    targets = np.array([tip0 + (k + 1) * step * d for k in range(K)])
    if seed % 5 == 1:                                       # out of reach for a while
        targets[K // 3: K // 3 + 2] += 50.0 * d
    kw = dict(loads=loads, rate_limit=float(rng.uniform(0.05, 0.3)), dt=1.0,
              margin=float(rng.uniform(1e-3, 0.05)) * m.torque_scale,
              on_infeasible=("hold", "approach")[seed % 2], horizon=(None, 3, "all")[seed % 3])
    return m, targets, kw


def check_plan(m, plan, loads) -> dict[str, int]:
    """Every step of ``plan`` against the reference transition from the previous step's state (module docstring);
    the counts of each kind of step checked."""
    counts = {"verified": 0, "snap": 0, "no_equilibrium": 0, "unverified": 0, "release": 0, "branch_point": 0}
    chain_at = lambda ell: RC.ref_chain(m, ell)                           # noqa: E731
    q_prev = plan.start
    ell_prev = np.column_stack([m.L1_0, m.L2_0])
    F_prev = np.asarray(loads[0], float)
    at_stop = False
    for k, st in enumerate(plan.steps):
        F = np.asarray(loads[k], float)
        ell = np.asarray(st.command, float)
        if at_stop:
            # the arm starts against a joint's stop: a release, not a followed path (never verified)
            assert not st.verified
            counts["release"] += 1
        else:
            try:
                ref = RT.transition(chain_at, q_prev, ell_prev, ell, F_prev, F)
            except RT.BranchPointError:
                counts["branch_point"] += 1
                ref = None
            if ref is not None:
                mu0 = stability_margin(m_with(m, ell_prev), q_prev, F_prev)
                floor = min(plan.margin_required, mu0)
                tol = 1e-7 * max(1.0, m.torque_scale)
                if st.verified:
                    assert ref.status == "followed", (k, ref.status, st.message)
                    assert np.abs(ref.q_end - st.q).max() < SAME_Q, (k, ref.q_end, st.q)
                    assert ref.min_margin >= floor - tol, (k, ref.min_margin, floor)
                    assert st.margin >= plan.margin_required - tol
                    assert st.transition_margin == pytest.approx(ref.min_margin, abs=1e-6 * max(1.0, ref.min_margin))
                    counts["verified"] += 1
                elif st.status == "snap":
                    assert ref.status == "snapped", (k, ref.status, st.message)
                    assert np.abs(ref.q_end - st.q).max() < SAME_Q, (k, ref.q_end, st.q)
                    assert st.snap.fraction == pytest.approx(ref.snaps[0][0], abs=1e-6)
                    counts["snap"] += 1
                elif st.status == "no_equilibrium":
                    assert ref.status == "joint_limit", (k, ref.status, st.message)
                    counts["no_equilibrium"] += 1
                else:
                    # not verified: the reference confirms why (a snap, or the margin short along or at the end)
                    end_margin = np.linalg.eigvalsh(chain_at(ell).lagrangian_hess(ref.q_end, F))[0] \
                        if ref.status == "followed" else -1.0
                    assert ref.status != "followed" or ref.min_margin < floor + tol \
                        or end_margin < plan.margin_required + tol or np.abs(ref.q_end - st.q).max() > SAME_Q, \
                        (k, st.status, st.message, ref.min_margin, end_margin)
                    counts["unverified"] += 1
        # the next step starts where the arm is: an equilibrium of this command (unless against a stop)
        at_stop = st.status == "no_equilibrium"
        if not at_stop:
            g = chain_at(ell).lagrangian_grad(st.q, F)
            assert np.abs(g).max() < 1e-8 * max(1.0, m.torque_scale), (k, st.status, g)
        q_prev, ell_prev, F_prev = np.asarray(st.q, float), ell, F
    return counts


def m_with(m, ell):
    ell = np.asarray(ell, float).reshape(m.n, 2)
    return to.Manipulator(s.replace(L0=(float(a), float(b))) for s, (a, b) in zip(m.segments, ell))


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("seed", range(36))
def test_every_step_of_a_random_plan_holds_along_its_transition(seed):
    m, targets, kw = random_plan(seed)
    plan = to.plan_preloads(m, targets, **kw)
    counts = check_plan(m, plan, kw["loads"])
    assert plan.verified.sum() == counts["verified"]


def test_a_snap_hidden_in_a_step_is_refused_or_reported():
    """A bistable chain whose least-change step tilts a well away: the command the controller sends is either one
    whose transition follows the branch (verified) or, where nothing avoids it, the snap is reported where the
    reference lands."""
    m = to.Manipulator([to.Segment(0.5, 1.0, 1.0, 1.0), to.Segment(1.0, 1.0, 1.0, 1.0)])
    ctl = to.PreloadController(m)
    tip0 = m.tip(ctl.q)
    targets = np.array([tip0 + [0.0, -0.15 * (k + 1)] for k in range(8)])
    plan = to.plan_preloads(m, targets, rate_limit=0.2, dt=1.0, margin=1e-3)
    counts = check_plan(m, plan, np.zeros((8, 2)))
    assert counts["verified"] >= 1
