"""Limit loads (``limit_load``) against the independent references: the straight chain's limit is its first critical
load (a bifurcation), a pre-bent or bistable chain's the reference fold (``reference_paths.limit_load_reference``:
a natural-parameter path with bisection and the extended system); the quasi-buckling load the least tangent
stiffness along the reference's own natural path (Brent on its finite-difference rate)."""

from __future__ import annotations

import functools

import numpy as np
import pytest
import reference_model as R
import reference_paths as RP
import scipy.optimize as so
from branch_checks import bistable_rest, chain_of, check_branch, check_name, lib, modes, ref, ref_limit, wells

import tensegrity_opt as to
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


# ---------------------------------------------------------------------------------------------- quasi-buckling
#: (a, b, k1, k2, L1_0, L2_0) per segment, boundary: chains whose stiffness along (-1, 0) has an interior minimum
QUASI = {
    "pre_bent4": ([(1.0, 1.0, 1.0, 1.0, 1.02, 0.98)] * 4, "free"),
    "hetero_bent3": ([(1.0, 1.0, 1.0, 1.0, 1.03, 0.98), (0.9, 1.2, 1.6, 1.4, 1.0, 1.0),
                      (1.1, 0.85, 0.8, 0.9, 0.97, 1.01)], "free"),
    "hetero_bent2": ([(1.0, 1.0, 1.0, 1.2, 1.0, 1.0), (0.9, 1.2, 1.5, 1.3, 1.02, 1.0)], "guided"),
}


class _ReferenceStiffness:
    """The tangent stiffness ``k(t) = 1 / (d . dtip/dt)`` along the dead-load path of ``reference_paths`` (its own
    natural-parameter continuation and corrector, the analytic tangent ``dz/dt``), and its least value: the zero of
    ``dk/dt`` (a central difference, step ``H``) by Brent between the grid points about the grid's least ``k``."""

    H = 1e-6

    def __init__(self, chain: R.Chain, boundary: str, t_end: float, direction=(-1.0, 0.0)):
        self.chain = chain
        q0 = RP.rest_configuration(chain)
        self.system = RP.PathSystem(chain, q0, direction, boundary)
        self.path = RP.load_path(chain, q0, direction, boundary, np.linspace(0.0, t_end, 61))
        assert self.path.status == "done"
        self.k_grid = np.array([self.k_of(z, t) for z, t in zip(self.path.z, self.path.t)])
        i = int(np.argmin(self.k_grid))
        assert 0 < i < len(self.k_grid) - 1            # an interior minimum
        rate = lambda t: (self.k(t + self.H) - self.k(t - self.H)) / (2 * self.H)     # noqa: E731
        self.t_min = so.brentq(rate, self.path.t[i - 1], self.path.t[i + 1], xtol=1e-14)
        self.k_min = self.k(self.t_min)

    def k_of(self, z, t) -> float:
        """The stiffness at the equilibrium ``z`` of load ``t``."""
        s = self.system
        q, _ = s.split(z, t)
        return 1.0 / float(s.d @ self.chain.jac(q) @ s.tangent(z, t)[:self.chain.n])

    def k(self, t: float) -> float:
        """The stiffness on the path at load ``t`` (solved from the nearest grid point)."""
        z, ok = self.system.solve(self.path.z[int(np.argmin(np.abs(self.path.t - t)))], t)
        assert ok
        return self.k_of(z, t)


@functools.lru_cache(maxsize=None)
def _quasi(name):
    segs, boundary = QUASI[name]
    m = to.Manipulator([to.Segment(a, b, (k1, k2), (l1, l2)) for a, b, k1, k2, l1, l2 in segs])
    lim = limit_load(m, direction=(-1.0, 0.0), boundary=boundary)
    return m, lim, _ReferenceStiffness(chain_of(m), boundary, lim.end_load)


@pytest.mark.parametrize("name", list(QUASI))
def test_quasi_buckling_load_is_the_least_stiffness_of_the_path(name):
    """The quasi-buckling load and stiffness equal the reference's least stiffness along its own path (1e-6 in the
    load); the stiffness at the returned load is at most the stiffness at every point of both paths."""
    m, lim, ref_k = _quasi(name)
    assert lim.kind == "none" and lim.status == "joint_limit" and lim.success
    assert lim.quasi_buckling_load == pytest.approx(ref_k.t_min, rel=1e-6)
    assert lim.quasi_buckling_stiffness == pytest.approx(ref_k.k_min, rel=1e-9)
    t = lim.quasi_buckling_load
    if QUASI[name][1] == "free":
        np.testing.assert_allclose(lim.quasi_buckling_force, [-t, 0.0], atol=1e-12)
    else:
        assert lim.quasi_buckling_force[0] == pytest.approx(-t, abs=1e-12)
    k_at = ref_k.k(t)                                   # the reference's stiffness at the returned load
    assert k_at == pytest.approx(lim.quasi_buckling_stiffness, rel=1e-9)
    assert np.all(k_at <= ref_k.k_grid * (1 + 1e-12))
    br = lim.branch
    z = br.q if QUASI[name][1] == "free" else np.column_stack([br.q, br.force[:, 1]])
    k_branch = np.array([ref_k.k_of(zi, ti) for zi, ti in zip(z, br.t)])
    assert np.all(k_at <= k_branch * (1 + 1e-12))
    d = lim.to_dict()
    assert d["quasi_buckling_stiffness"] == pytest.approx(lim.quasi_buckling_stiffness)


# ---------------------------------------------------------------------------- sharp folds of tiny imperfections
#: Two segments a = 1.5 > b (guided: an unstable-symmetric bifurcation at P_c = 35/6) and the paper chain (guided: a
#: stable-symmetric one whose arms fold at 0.6143), pre-bent by p: the imperfect path's fold is a corner of size
#: ~p^(1/3), smaller than a continuation step at p = 1e-4.
SHARP = {"two": [(1.5, 1.0, 1.0, 1.0, 1.0, 1.0)] * 2, "paper": [(1.0, 1.0, 1.0, 1.0, 1.0, 1.0)] * 4}


def sharp_chains(name: str, p: float):
    """The imperfect chain (``L1_0 + p``, ``L2_0 - p``) in the library and in the reference model."""
    segs = [(a, b, k1, k2, l1 + p, l2 - p) for a, b, k1, k2, l1, l2 in SHARP[name]]
    m = to.Manipulator([to.Segment(a, b, k=(k1, k2), L0=(l1, l2)) for a, b, k1, k2, l1, l2 in segs])
    return m, R.Chain.from_segments(segs)


@pytest.mark.parametrize("name", ["two", "paper"])
def test_a_sharp_fold_of_a_tiny_imperfection_is_located(name):
    """p = 1e-4, guided: the path folds (never "stable to its end" past unstable points); the fold against the
    reference continuation, which rejects every unstable point and bisects to the loss, then solves the extended
    system."""
    m, c = sharp_chains(name, 1e-4)
    lim = limit_load(m, direction=(-1.0, 0.0), boundary="guided")
    ref_lim = RP.limit_load_reference(c, RP.rest_configuration(c), (-1.0, 0.0), "guided")
    assert ref_lim.kind == "fold" and ref_lim.extended_converged
    assert lim.success and lim.status == "stability_lost" and lim.kind == "fold"
    assert lim.load == pytest.approx(ref_lim.t, rel=1e-7)
    np.testing.assert_allclose(lim.q, ref_lim.q, atol=1e-5)
    br = lim.branch
    ev = br.events[0]
    assert ev.kind == "fold" and ev.stability == "lost"
    assert np.all(br.morse_index[:ev.index + 1] == 0)     # stable up to the fold, every change at an event
    if name == "two":
        # a brute check: the largest load along the path parametrised by q_2 (smooth through the fold)
        s = RP.PathSystem(c, RP.rest_configuration(c), (-1.0, 0.0), "guided")
        z0, ok = s.solve(s.start_z(t=0.0), 0.0)
        assert ok
        path = RP.coordinate_path(s, z0, 0.0, 1, np.linspace(z0[1], 1.5 * ref_lim.q[1], 400))
        i = int(np.argmax(path.t))
        assert 0 < i < path.t.size - 1                       # an interior maximum: the fold
        t_fold, _ = RP.fold_by_coordinate(s, path.z[i], path.t[i], k=1, half_width=2 * abs(path.q[1, 1] - path.q[0, 1]))
        assert lim.load == pytest.approx(t_fold, rel=1e-7)
