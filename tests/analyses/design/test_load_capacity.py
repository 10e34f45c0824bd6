"""Load capacity (analyses/design/load_capacity.py) against ``reference_paths.limit_load_reference`` (a
natural-parameter path with bisection and the extended system, scipy; written from ``docs/model.md``)."""

import json

import numpy as np
import pytest
import reference_model as R  # noqa: E402
import reference_paths as RP  # noqa: E402
from clocks import tick_clock

import tensegrity_opt as to
from tensegrity_opt import InvalidParameterError

PAPER = to.Manipulator.uniform(4)


# ----------------------------------------------------------------------------- reference helpers
def ref_chain(m: to.Manipulator, rest_lengths=None) -> R.Chain:
    """The reference chain of ``m``'s geometry and stiffness, with ``rest_lengths`` (n, 2) if given."""
    L = np.column_stack([m.L1_0, m.L2_0]) if rest_lengths is None else np.asarray(rest_lengths, float)
    return R.Chain(m.a.copy(), m.b.copy(), m.k1.copy(), m.k2.copy(), L[:, 0].copy(), L[:, 1].copy())


# ----------------------------------------------------------------------------- 2. load capacity
SEGS = [(1.0, 1.0, 1.0, 1.2), (0.9, 1.1, 1.5, 1.3), (1.1, 0.9, 0.8, 1.0)]


CHAINS = {
    "monotonic": (to.Manipulator([to.Segment(*s) for s in SEGS]), R.Chain.from_segments(SEGS)),
    "bistable": (to.Manipulator.uniform(2, a=0.5, b=1, k=1, L0=1), RP.bistable_chain(2)),
    "pre-bent": (to.Manipulator.uniform(3, L0=(1.05, 0.95)),
                 R.Chain.from_segments([(1.0, 1.0, 1.0, 1.0, 1.05, 0.95)] * 3)),
}


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("name, boundary, angles, base", [
    ("monotonic", "free", [np.pi, 0.75 * np.pi], (0.0, 0.0)),
    ("monotonic", "guided", [np.pi, 0.0], (0.0, 0.0)),
    ("monotonic", "free", [np.pi, 0.5 * np.pi], (0.0, 0.03)),
    ("bistable", "free", [0.0, 0.25 * np.pi, 0.5 * np.pi, -0.25 * np.pi, np.pi], (0.0, 0.0)),
    ("bistable", "guided", [0.0, np.pi], (0.0, 0.0)),
    ("bistable", "free", [0.0, -0.5 * np.pi], (0.03, 0.02)),
    ("pre-bent", "guided", [np.pi], (0.0, 0.0)),
    ("pre-bent", "guided", [np.pi], (-0.02, 0.0)),
    ("pre-bent", "free", [np.pi, 0.75 * np.pi, 0.5 * np.pi], (0.0, 0.03)),
])
def test_load_capacity_equals_the_reference_limit_load(name, boundary, angles, base):
    m, chain = CHAINS[name]
    cap = to.load_capacity(m, base=base, directions=angles, boundary=boundary, max_load=3.0)
    assert cap.success and cap.status == "complete"
    for i, a in enumerate(angles):
        d = np.array([np.cos(a), np.sin(a)])
        assert np.allclose(cap.directions[i], d, atol=1e-15)
        ref = RP.limit_load_reference(chain, cap.start.q, d, boundary, max_load=3.0, base=base)
        if ref.kind == "none":
            assert cap.kinds[i] == "none" and cap.reasons[i] == ref.reason
            assert np.isnan(cap.loads[i]) and np.all(np.isnan(cap.forces[i]))
            if ref.reason == "joint_limit":     # the library stops 1e-6 of the range short of the bound
                assert cap.end_loads[i] == pytest.approx(ref.t, rel=1e-4)
            else:
                assert cap.end_loads[i] == pytest.approx(3.0)
        else:
            assert cap.kinds[i] in ("fold", "bifurcation")
            if name == "monotonic":
                # symmetric segments: the chain stays straight under compression and buckles at a branch point
                # (R_t = -J^T d = 0 there: J_x = 0 at straight). The reference's extended system is singular at
                # a symmetric branch point and its classification drifts with its iterate, so it is not compared.
                assert cap.kinds[i] == "bifurcation" and np.abs(cap.q[i]).max() < 1e-9
            else:
                assert cap.kinds[i] == ref.kind
            assert cap.loads[i] == pytest.approx(ref.t, abs=1e-6)
            assert np.allclose(cap.forces[i], ref.force, atol=1e-6)
    # the pose is the reference's equilibrium under the base load, stable
    q, ok = chain.newton_force(np.asarray(base, float), cap.start.q)
    assert ok and np.abs(q - cap.start.q).max() < 1e-9


def test_straight_symmetric_chain_capacity_is_the_free_critical_load():
    cap = to.load_capacity(PAPER, directions=[np.pi, 0.5 * np.pi], max_load=1.0)
    crit = abs(to.critical_force(PAPER, "free").force)
    assert crit == pytest.approx(0.0761205, abs=1e-7)                       # docs/model.md
    assert cap.kinds[0] == "bifurcation"
    assert cap.loads[0] == pytest.approx(crit, rel=1e-9)
    assert cap.kinds[1] == "none"
    assert cap.weakest == (pytest.approx(np.pi), pytest.approx(crit, rel=1e-9))
    # the reference free critical load of the straight chain agrees
    assert cap.loads[0] == pytest.approx(R.critical_loads_free(ref_chain(PAPER))[0], rel=1e-6)


@pytest.mark.slow
def test_load_capacity_of_a_designed_pose_and_of_given_rest_lengths():
    """A design result as the pose: its chain, its configuration and its load (the base); (n, 2) rest lengths."""
    load = (0.02, -0.01)
    p = to.preloads_for_pose(PAPER, (7.0, 1.5), load=load, margin=0.05)
    cap = to.load_capacity(PAPER, p, directions=4, max_load=2.0)
    assert np.allclose(cap.base, load) and np.allclose(cap.start.q, p.q, atol=1e-9)
    chain = ref_chain(PAPER, p.preloads)
    for i, d in enumerate(cap.directions):
        ref = RP.limit_load_reference(chain, p.q, d, "free", max_load=2.0, base=load)
        assert cap.kinds[i] == ref.kind
        if ref.kind != "none":
            assert cap.loads[i] == pytest.approx(ref.t, abs=1e-6)
    # rest lengths as the pose: the rest configuration of m with them
    rest = [[1.05, 0.95]] * 3
    cap2 = to.load_capacity(to.Manipulator.uniform(3), rest, directions=[np.pi], boundary="guided", max_load=3.0)
    ref = RP.limit_load_reference(CHAINS["pre-bent"][1], cap2.start.q, (-1.0, 0.0), "guided", max_load=3.0)
    assert cap2.kinds[0] == ref.kind == "fold" and cap2.loads[0] == pytest.approx(ref.t, abs=1e-6)
    assert np.allclose(cap2.manipulator.L1_0, 1.05)
    out = json.loads(json.dumps(cap.to_dict(), allow_nan=False))
    assert len(out["loads"]) == 4 and out["base"] == list(load)


def test_load_capacity_validation():
    m = CHAINS["bistable"][0]
    for kw, field in [(dict(directions=0), "directions"), (dict(directions=[[0.0, 0.0]]), "directions"),
                      (dict(directions=[[1, 2, 3]]), "directions"), (dict(directions="x"), "directions"),
                      (dict(directions=[0.5 * np.pi], boundary="guided"), "directions"),
                      (dict(boundary="held"), "boundary"), (dict(base=(1.0,)), "base"),
                      (dict(max_load=-1.0), "max_load"), (dict(pose=[0.1, 0.2, 0.3]), "pose"),
                      (dict(pose=[5.0, 0.0]), "pose"), (dict(pose=[[1.0, -1.0], [1.0, 1.0]]), "pose")]:
        with pytest.raises(InvalidParameterError) as ei:
            to.load_capacity(m, **kw)
        assert ei.value.field == field, (kw, ei.value.field)
    # an unstable pose: the bistable chain's straight configuration (a maximum of each segment's energy)
    with pytest.raises(InvalidParameterError) as ei:
        to.load_capacity(m, [0.0, 0.0], directions=[np.pi])
    assert ei.value.field == "pose"


def test_time_limit(monkeypatch):
    # the library's clock moves on 1 s at every reading (tests/support/clocks.py): the 36 directions read it some
    # 27000 times, a limit of 2000 s runs out among the first directions on any machine
    tick_clock(monkeypatch, step=1.0)
    cap = to.load_capacity(PAPER, directions=36, timeout=2000.0)
    assert "time_limit" in cap.reasons and not cap.success and cap.status == "time_limit"
