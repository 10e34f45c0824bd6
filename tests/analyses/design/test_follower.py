"""The preload follower (analyses/design/follower.py) against the reference model.

The expected configurations come from ``tests/support/reference_model.py`` only (numpy and scipy, written from
``docs/model.md``): each command is answered by the overdamped arm, the gradient flow
``dq/dt = -(grad E - J^T F)`` of the chain with the commanded rest lengths integrated by scipy from the
previous configuration, polished by the reference's Newton method; a snap is where that flow travels more than
the snap distance (the well the arm sat in has vanished) or lands on an unstable point (the reference Hessian).
"""

import json

import numpy as np
import pytest
import scipy.integrate as si
from reference_model import Chain

import tensegrity_opt as to
from tensegrity_opt.analyses.design.follower import FollowerStep, PreloadFollower, Snap

#: A bistable segment in front of a straight one: tilting its double well (1 + d, 1 - d) ends the well it
#: sits in, and the arm snaps into the other one.
BISTABLE_SEGMENTS = [(0.5, 1.0, 1.0, 1.0), (1.0, 1.0, 1.0, 1.0)]
#: Monotonic segments (a = b): one well, no snap.
MONOTONIC_SEGMENTS = [(1.0, 1.0, 1.0, 1.0), (0.9, 1.1, 1.5, 1.3), (1.1, 0.9, 0.8, 1.0)]


def manipulator(segments) -> to.Manipulator:
    return to.Manipulator([to.Segment(*s) for s in segments])


def reference(segments, rest_lengths) -> Chain:
    return Chain.from_segments([(a, b, k, k, l1, l2) for (a, b, k, _), (l1, l2) in zip(segments, rest_lengths)])


def settle(chain: Chain, F: np.ndarray, q0: np.ndarray) -> np.ndarray:
    """Where the overdamped arm comes to rest from ``q0``: the gradient flow of ``E - F . tip``, then Newton."""
    def rhs(_t, q):
        return -chain.lagrangian_grad(q, F)

    def still(_t, q):
        return np.max(np.abs(chain.lagrangian_grad(q, F))) - 1e-9

    still.terminal = True
    sol = si.solve_ivp(rhs, (0.0, 1e5), np.asarray(q0, float), method="LSODA", rtol=1e-10, atol=1e-12,
                       events=still)
    q, ok = chain.newton_force(F, sol.y[:, -1])
    assert ok and chain.in_range(q)
    return q


def reference_answers(segments, commands, loads, q_start, snap_distance=0.2):
    """Per command: the reference configuration and whether it is a snap (and its cause)."""
    q, out = np.asarray(q_start, float), []
    for rl, F in zip(commands, loads):
        chain = reference(segments, rl)
        q_new = settle(chain, np.asarray(F, float), q)
        stable = np.linalg.eigvalsh(chain.lagrangian_hess(q_new, np.asarray(F, float)))[0] > 0
        distance = float(np.max(np.abs(q_new - q)))
        cause = "unstable" if not stable else "distance" if distance > snap_distance else None
        out.append((q_new, cause, distance))
        q = q_new
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
    # the default start: the rest configuration, by the reference flow from near straight (either well)
    rest = settle(reference(segments, [(s[3], s[3]) for s in segments]), np.zeros(2), start + 1e-3)
    assert np.allclose(start, rest, atol=1e-7)
    want = reference_answers(segments, commands, loads, start)
    got = [f.step(rl, load=F) for rl, F in zip(commands, loads)]
    for i, (st, (q_ref, cause, distance)) in enumerate(zip(got, want)):
        assert isinstance(st, FollowerStep) and st.success and st.status == "converged", i
        np.testing.assert_allclose(st.q, q_ref, atol=1e-7, err_msg=str(i))
        assert (st.snap.cause if st.snap else None) == cause, i
        if st.snap:
            assert st.snap.distance == pytest.approx(distance, abs=1e-7)
            np.testing.assert_allclose(st.snap.q_before, got[i - 1].q if i else start, atol=0)
        np.testing.assert_array_equal(st.load, loads[i])
        np.testing.assert_array_equal(st.rest_lengths, commands[i])
    snaps = [i for i, w in enumerate(want) if w[1]]
    assert snaps == ([18] if name == "bistable" else [])     # one snap into the other well; none on one well
    np.testing.assert_allclose(f.q, got[-1].q, atol=0)


def test_the_answer_is_the_equilibrium_with_the_command_and_its_event():
    m = manipulator(BISTABLE_SEGMENTS)
    f = PreloadFollower(m, snap_distance=0.1)
    st = f.step([[1.2, 0.8], [1.0, 1.0]], load=[0.0, 0.01])
    d = st.to_dict()
    eq = st.equilibrium.to_dict()
    assert list(d) == [*eq, "rest_lengths", "load", "events"]
    assert {k: d[k] for k in eq} == eq and d["rest_lengths"] == [[1.2, 0.8], [1.0, 1.0]] and d["load"] == [0.0, 0.01]
    assert d["events"] == [st.snap.to_dict()] and d["events"][0]["kind"] == "snap"     # moved more than 0.1 rad
    json.dumps(d, allow_nan=False)
    assert st.equilibrium.control == "force" and np.allclose(st.equilibrium.force, [0.0, 0.01])
    with pytest.raises(AttributeError):
        st.snap = None
    with pytest.raises(ValueError):
        st.rest_lengths[0, 0] = 2.0
    assert isinstance(st.snap, Snap)


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
    for kw, field in (({"start": [0.0, 0.1]}, "start"), ({"load": (1.0,)}, "load"),
                      ({"snap_distance": 0.0}, "snap_distance")):
        with pytest.raises(to.InvalidParameterError) as ei:
            PreloadFollower(m, **kw)
        assert ei.value.field == field
