"""The preload follower (analyses/design/follower.py) against independent references.

Each command is answered along its transition: the previous command and load moving linearly to the new ones, the
arm following its branch by continuation and snapping where it folds. The expected configurations and snaps come
from ``tests/support/reference_transition.py`` (numpy/scipy on the reference model, its own continuation, folds by
bisection, landings by an LSODA gradient flow); the monotonic chain's answers are also the reference model's Newton
solve from the previous configuration (one well: nothing to snap into).
"""

import json

import numpy as np
import pytest
import reference_transition as RT
from reference_model import Chain

import tensegrity_opt as to
from tensegrity_opt.analyses.design.follower import FollowerStep, PreloadFollower
from tensegrity_opt.analyses.paths.transition import SimulationEvent

#: A bistable segment in front of a straight one: tilting its double well (1 + d, 1 - d) ends the well it
#: sits in, and the arm snaps into the other one.
BISTABLE_SEGMENTS = [(0.5, 1.0, 1.0, 1.0), (1.0, 1.0, 1.0, 1.0)]
#: Monotonic segments (a = b): one well, no snap.
MONOTONIC_SEGMENTS = [(1.0, 1.0, 1.0, 1.0), (0.9, 1.1, 1.5, 1.3), (1.1, 0.9, 0.8, 1.0)]


def manipulator(segments) -> to.Manipulator:
    return to.Manipulator([to.Segment(*s) for s in segments])


def reference(segments, rest_lengths) -> Chain:
    return Chain.from_segments([(a, b, k, k, l1, l2) for (a, b, k, _), (l1, l2) in zip(segments, rest_lengths)])


def reference_answers(segments, commands, loads, q_start, F0=(0.0, 0.0)):
    """Per command: the reference transition from the previous state (its end and its snaps)."""
    chain_at = lambda ell: reference(segments, ell)                  # noqa: E731
    q, ell, F, out = np.asarray(q_start, float), np.array([[s[3], s[3]] for s in segments]), np.asarray(F0), []
    for rl, F1 in zip(commands, loads):
        r = RT.transition(chain_at, q, ell, np.asarray(rl, float), F, np.asarray(F1, float))
        out.append(r)
        q, ell, F = r.q_end, np.asarray(rl, float), np.asarray(F1, float)
    return out


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("name, segments, commands, loads", [
    ("bistable", BISTABLE_SEGMENTS, [[[1 + d, 1 - d], [1.0, 1.0]] for d in np.linspace(0.0, 0.5, 26)],
     [(0.0, 0.0)] * 25 + [(0.0, 0.01)]),
    ("monotonic", MONOTONIC_SEGMENTS,
     [[[1.0 + d, 1.0 - d], [1.3 - d, 1.3 + 0.5 * d], [1.0, 1.0 + d]] for d in np.linspace(0.0, 0.3, 16)],
     [(-0.02, 0.01 * k) for k in range(16)]),
])
def test_each_command_lands_where_the_overdamped_arm_settles(name, segments, commands, loads):
    m = manipulator(segments)
    f = PreloadFollower(m, load=(0.0, 0.0))
    start = f.q.copy()
    # the default start: the rest configuration, an equilibrium of the reference (either well)
    assert np.abs(reference(segments, [(s[3], s[3]) for s in segments]).lagrangian_grad(start, np.zeros(2))).max() \
        < 1e-10
    want = reference_answers(segments, commands, loads, start)
    got = [f.step(rl, load=F) for rl, F in zip(commands, loads)]
    for i, (st, ref) in enumerate(zip(got, want)):
        assert isinstance(st, FollowerStep) and st.success and st.status == "converged", i
        np.testing.assert_allclose(st.q, ref.q_end, atol=1e-7, err_msg=str(i))
        assert (st.snap is not None) == (ref.status == "snapped"), i
        if st.snap:
            assert st.snap.fraction == pytest.approx(ref.snaps[0][0], abs=1e-7)
            np.testing.assert_allclose(st.snap.q_after, ref.snaps[0][2], atol=1e-7)
            assert st.snap.step == i
        np.testing.assert_array_equal(st.load, loads[i])
        np.testing.assert_array_equal(st.rest_lengths, commands[i])
    snaps = [i for i, w in enumerate(want) if w.status == "snapped"]
    assert snaps == ([18] if name == "bistable" else [])     # one snap into the other well; none on one well
    np.testing.assert_allclose(f.q, got[-1].q, atol=0)
    if name == "monotonic":                                   # one well: the reference's Newton from the last state
        q = start
        for st, rl, F in zip(got, commands, loads):
            q, ok = reference(segments, rl).newton_force(np.asarray(F, float), q)
            assert ok and np.abs(q - st.q).max() < 1e-9


def test_a_large_smooth_move_on_one_branch_is_not_a_snap():
    """The follower follows the branch before it calls anything a snap: one command moving the arm by more than
    0.2 rad along its branch (the former distance rule's threshold) is a continuous move, as the reference says."""
    segments = MONOTONIC_SEGMENTS
    m = manipulator(segments)
    f = PreloadFollower(m)
    start = f.q.copy()
    cmd = [[1.3, 0.7], [1.6, 1.0], [1.0, 1.4]]
    st = f.step(cmd)
    ref = reference_answers(segments, [cmd], [(0.0, 0.0)], start)[0]
    assert ref.status == "followed" and float(np.abs(ref.q_end - start).max()) > 0.2
    assert st.snap is None and st.events == () and np.abs(st.q - ref.q_end).max() < 1e-8


def test_the_answer_is_the_equilibrium_with_the_command_and_its_event():
    m = manipulator(BISTABLE_SEGMENTS)
    f = PreloadFollower(m)
    st = f.step([[1.4, 0.6], [1.0, 1.0]], load=[0.0, 0.01])
    d = st.to_dict()
    eq = st.equilibrium.to_dict()
    assert list(d) == [*eq, "rest_lengths", "load", "events"]
    assert {k: d[k] for k in eq} == eq and d["rest_lengths"] == [[1.4, 0.6], [1.0, 1.0]] and d["load"] == [0.0, 0.01]
    assert d["events"] == [st.snap.to_dict()] and d["events"][0]["kind"] == "snap"     # the well vanished
    json.dumps(d, allow_nan=False)
    assert st.equilibrium.control == "force" and np.allclose(st.equilibrium.force, [0.0, 0.01])
    with pytest.raises(AttributeError):
        st.events = ()
    with pytest.raises(ValueError):
        st.rest_lengths[0, 0] = 2.0
    assert isinstance(st.snap, SimulationEvent) and st.snap.status == "landed"


def test_a_start_and_a_refused_command_leave_the_state_alone():
    m = manipulator(MONOTONIC_SEGMENTS)
    eq = to.solve_equilibrium_under_force(m, -0.02, 0.03)
    f = PreloadFollower(m, eq, load=(-0.02, 0.03))
    np.testing.assert_array_equal(f.q, eq.q)
    before = f.q.copy()
    with pytest.raises(to.InvalidParameterError) as ei:
        f.step([[1.0, 1.0]] * 2)
    assert ei.value.field == "rest_lengths"
    with pytest.raises(to.InvalidParameterError) as ei:
        f.step([[1.0, 1.0], [1.0, -1.0], [1.0, 1.0]])
    assert ei.value.field == "rest_lengths[1]"
    with pytest.raises(to.InvalidParameterError) as ei:
        f.step([[1.0, 1.0]] * 3, load=[0.0, np.nan])
    assert ei.value.field == "load"
    np.testing.assert_array_equal(f.q, before)
    for kw, field in (({"start": [0.0, 0.1]}, "start"), ({"load": (1.0,)}, "load")):
        with pytest.raises(to.InvalidParameterError) as ei:
            PreloadFollower(m, **kw)
        assert ei.value.field == field
