"""Limit loads (``limit_load``) against the independent references: the straight chain's limit is its first critical
load (a bifurcation), a pre-bent or bistable chain's the reference fold (``reference_paths.limit_load_reference``:
a natural-parameter path with bisection and the extended system)."""

from __future__ import annotations

import numpy as np
import pytest
import reference_model as R
import reference_paths as RP
from branch_checks import bistable_rest, check_branch, check_name, lib, modes, ref, ref_limit, wells

from tensegrity_opt import limit_load


@pytest.mark.parametrize("name", ["paper4", "hetero3"])
@pytest.mark.parametrize("boundary", ["free", "guided"])
def test_limit_load_of_straight_chain_is_a_bifurcation(name, boundary):
    P, _ = modes(name, boundary)
    lim = limit_load(lib(name), direction=(-1.0, 0.0), boundary=boundary)
    assert lim.kind == "bifurcation" and lim.status == "stability_lost" and lim.success
    assert lim.load == pytest.approx(P[0], rel=1e-6)
    np.testing.assert_allclose(lim.force, [-P[0], 0.0], atol=1e-6 * P[0])
    np.testing.assert_allclose(lim.q, 0.0, atol=1e-8)
    check_branch(ref(name), lim.branch, check_name(boundary), direction=(-1.0, 0.0),
                 tip0=ref(name).tip(np.zeros(ref(name).n)))


def test_limit_load_pre_bent_chain():
    """Free: the path is smooth up to the joint range (no fold, quasi-buckling); the
    smallest eigenvalue stays positive through the straight chain's critical load. Guided: a
    fold at t = 0.825957."""
    c = ref("pre_bent3")
    m = lib("pre_bent3")
    r_free = ref_limit("pre_bent3", "free")
    assert r_free.kind == "none" and r_free.reason == "joint_limit"
    lim = limit_load(m, direction=(-1.0, 0.0), boundary="free")
    assert lim.kind == "none" and lim.status == "joint_limit"
    assert lim.load is None or lim.load == pytest.approx(r_free.t, rel=1e-3)
    assert lim.quasi_buckling_load is None or 0.0 < lim.quasi_buckling_load <= r_free.t + 1e-9
    check_branch(c, lim.branch, "load", direction=(-1.0, 0.0))
    assert np.all(np.asarray(lim.branch.morse_index) == 0)
    P_straight = RP.buckling_modes(R.Chain.uniform(3, 1.0, 1.0, 1.0, 1.0), "free")[0][0]
    assert np.max(lim.branch.t) > P_straight

    lim = limit_load(m, direction=(-1.0, 0.0), boundary="free", max_load=0.2)
    assert lim.kind == "none" and lim.status == "max_load"

    r = ref_limit("pre_bent3", "guided")
    lim = limit_load(m, direction=(-1.0, 0.0), boundary="guided")
    assert lim.kind == "fold" and lim.status == "stability_lost"
    assert lim.load == pytest.approx(r.t, rel=1e-6)
    np.testing.assert_allclose(lim.force, r.force, atol=1e-5)
    np.testing.assert_allclose(lim.q, r.q, atol=1e-4)


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("boundary", ["free", "guided"])
def test_limit_load_bistable_chain(boundary):
    """Three bistable segments from the (+, +, +) rest, compressed: a fold (snap-through), free
    t = 0.427401, guided t = 0.432200."""
    r = ref_limit("bistable3", boundary)
    assert r.kind == "fold"
    lim = limit_load(lib("bistable3"), direction=(-1.0, 0.0), boundary=boundary, start=bistable_rest())
    assert lim.kind == "fold" and lim.status == "stability_lost"
    assert lim.load == pytest.approx(r.t, rel=1e-6)
    np.testing.assert_allclose(lim.force, r.force, atol=1e-5)
    np.testing.assert_allclose(lim.q, r.q, atol=1e-4)
    c = ref("bistable3")
    check_branch(c, lim.branch, check_name(boundary), direction=(-1.0, 0.0), tip0=c.tip(bistable_rest()))


def test_limit_load_single_segment_fold():
    c = ref("one_seg")
    (q1, t1), _ = RP.single_segment_folds(c, (0.0, 1.0), -1.5, 1.5)
    lim = limit_load(lib("one_seg"), direction=(0.0, 1.0), boundary="free", start=np.array([wells("one_seg")[0]]))
    assert lim.kind == "fold" and lim.load == pytest.approx(t1, rel=1e-6)
    assert lim.q[0] == pytest.approx(q1, abs=1e-4)
