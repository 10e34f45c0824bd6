"""Stiffness shaping (analyses/design/stiffness_shaping.py), each result checked by an independent computation.

Every expected number comes from ``tests/support/reference_model.py`` / ``reference_paths.py`` (numpy and scipy
only, written from ``docs/model.md``), never from the library:

* a stiffness is re-measured as the finite difference of the tip force holding the chain against the tip
  position (the reference KKT Newton at ``tip +- h e_j`` from the design's configuration);
* a reachable stiffness is made by the reference model itself: rest lengths of our choosing, their
  equilibrium under a dead load (reference Newton), the tip there as the target, the finite-difference
  stiffness there as ``K_desired``;
* a pose is checked as an equilibrium and stable (the reference Hessian of ``E - F . tip``) with the tip on
  the target.
"""

import json

import numpy as np
import pytest
import reference_model as R  # noqa: E402
import reference_paths as RP  # noqa: E402

import tensegrity_opt as to
from tensegrity_opt import InfeasibleDesignError, InvalidParameterError

PAPER = to.Manipulator.uniform(4)


TARGET = (7.0, 1.0)


# ----------------------------------------------------------------------------- reference helpers
def ref_chain(m: to.Manipulator, rest_lengths=None) -> R.Chain:
    """The reference chain of ``m``'s geometry and stiffness, with ``rest_lengths`` (n, 2) if given."""
    L = np.column_stack([m.L1_0, m.L2_0]) if rest_lengths is None else np.asarray(rest_lengths, float)
    return R.Chain(m.a.copy(), m.b.copy(), m.k1.copy(), m.k2.copy(), L[:, 0].copy(), L[:, 1].copy())


def fd_stiffness(chain: R.Chain, q, F) -> np.ndarray:
    """``dF/d(tip)`` by central differences: the force holding the tip at ``tip +- h e_j`` (reference Newton)."""
    return R.tip_stiffness_fd(chain, chain.tip(q), q, F, h=1e-4, max_move=0.01)


def check_pose(m: to.Manipulator, d, target, load):
    """The design is a stable equilibrium at the target under the load, on the reference model; returns the
    reference chain with its rest lengths and the reference-polished configuration."""
    chain = ref_chain(m, d.rest_lengths)
    q, ok = chain.newton_force(np.asarray(load, float), d.q)
    assert ok and np.abs(q - d.q).max() < 1e-8
    assert np.abs(chain.tip(q) - np.asarray(target)).max() < 1e-6
    H = RP.lagrangian_hess(chain, q, np.asarray(load, float))
    assert np.linalg.eigvalsh(H)[0] > 0
    return chain, q


def reachable(m, rest_lengths, load, q0):
    """A (target, K) pair reachable by construction: the reference equilibrium of ``m`` with ``rest_lengths``
    under ``load`` from ``q0``, its tip and its finite-difference stiffness."""
    chain = ref_chain(m, rest_lengths)
    q, ok = chain.newton_force(np.asarray(load, float), q0)
    assert ok and chain.in_range(q)
    assert np.linalg.eigvalsh(RP.lagrangian_hess(chain, q, np.asarray(load, float)))[0] > 1e-3
    K = fd_stiffness(chain, q, np.asarray(load, float))
    return chain.tip(q), 0.5 * (K + K.T)


# ----------------------------------------------------------------------------- 1. stiffness shaping
@pytest.mark.parametrize("rest, load, q0", [
    ([[0.8, 1.3], [1.2, 0.9], [0.7, 1.1], [1.0, 1.2]], (0.0, 0.0), np.zeros(4)),
    ([[1.1, 0.8], [0.9, 1.2], [1.3, 0.7], [0.9, 1.0]], (-0.04, 0.03), np.zeros(4)),
])
def test_a_reachable_stiffness_is_met_exactly(rest, load, q0):
    """K_desired built by the reference model (other rest lengths, the same target and load): the design meets
    it exactly, and the stiffness re-measured by finite differences on the reference model equals it."""
    target, K_ref = reachable(PAPER, rest, load, q0)
    d = to.preloads_for_stiffness(PAPER, target, K_desired=K_ref, load=load)
    assert d.exact and d.success and d.status == "exact" and "reached" in d.message
    assert d.residual < 1e-7
    chain, q = check_pose(PAPER, d, target, load)
    K_fd = fd_stiffness(chain, q, np.asarray(load, float))
    assert np.linalg.norm(K_fd - K_ref) / np.linalg.norm(K_ref) < 1e-6
    assert np.linalg.norm(d.K - K_fd) / np.linalg.norm(K_fd) < 1e-6       # the reported K is the measured one
    assert d.margin >= 1e-3 * (1 - 1e-6)


def test_bounds_on_entries_hold_on_the_verified_result():
    bk = {"kxx": [None, 0.25], "kyy": [0.06, None], "kyx": [-1.0, 1.0]}
    d = to.preloads_for_stiffness(PAPER, TARGET, bounds_K=bk)
    chain, q = check_pose(PAPER, d, TARGET, (0.0, 0.0))
    K = fd_stiffness(chain, q, np.zeros(2))
    tol = 1e-6
    assert K[0, 0] <= 0.25 + tol and K[1, 1] >= 0.06 - tol and -1 - tol <= K[0, 1] <= 1 + tol
    # the pose chosen without a stiffness requirement violates both (so the bounds did work): its stiffness
    # measured on the reference model
    p = to.preloads_for_pose(PAPER, TARGET)
    K_p = fd_stiffness(ref_chain(PAPER, p.preloads), p.q, np.zeros(2))
    assert K_p[0, 0] > 0.25 and K_p[1, 1] < 0.06
    assert d.residual == 0.0 and d.exact and d.status == "within_bounds" and d.success
    assert set(d.bounds_K) == {"kxx", "kxy", "kyy"}


def test_eigenvalue_bounds_hold_on_the_verified_result():
    d = to.preloads_for_stiffness(PAPER, TARGET, eig_bounds=[0.04, 0.6], load=(0.02, -0.01))
    chain, q = check_pose(PAPER, d, TARGET, (0.02, -0.01))
    w = np.linalg.eigvalsh(fd_stiffness(chain, q, np.array([0.02, -0.01])))
    assert w[0] >= 0.04 - 1e-6 and w[1] <= 0.6 + 1e-6
    assert np.allclose(d.eigenvalues, w, rtol=1e-6, atol=1e-8)


def test_an_unreachable_stiffness_reports_its_residual():
    """K = 5 I is far stiffer than the springs allow at this pose: the least-squares fit, exact=False, its
    residual the relative misfit of the re-measured stiffness; the pose itself is still valid."""
    Kd = 5.0 * np.eye(2)
    d = to.preloads_for_stiffness(PAPER, TARGET, K_desired=Kd)
    assert not d.exact and d.status == "closest" and not d.success and d.to_dict()["success"] is False
    chain, q = check_pose(PAPER, d, TARGET, (0.0, 0.0))
    K = fd_stiffness(chain, q, np.zeros(2))
    misfit = np.linalg.norm(K - Kd) / np.linalg.norm(Kd)
    assert d.residual == pytest.approx(misfit, rel=1e-5)
    assert misfit > 0.5
    # a two-segment chain has 2 free rest lengths for 3 entries: a generic K is out of reach
    m2 = to.Manipulator.uniform(2)
    target, K_ref = reachable(m2, [[0.9, 1.1], [1.05, 0.95]], (0.0, 0.0), np.zeros(2))
    d2 = to.preloads_for_stiffness(m2, target, K_desired=K_ref + np.diag([0.0, 0.3 * K_ref[1, 1]]))
    assert not d2.exact and d2.residual > 1e-4


def test_unreachable_bounds_raise_naming_why_with_the_least_violation():
    with pytest.raises(InfeasibleDesignError) as ei:
        to.preloads_for_stiffness(PAPER, TARGET, bounds_K={"kxx": [None, 0.1], "kyy": [0.08, None]})
    err = ei.value
    assert "kxx" in err.message and "kyy" in err.message and "least violation" in err.message
    best = err.best
    s = best["least_violation"]
    assert s > 0 and best["violations"]
    # the best point is a stable equilibrium at the target whose (reference) stiffness misses the bounds by s
    chain = ref_chain(PAPER, best["rest_lengths"])
    q, ok = chain.newton_force(np.zeros(2), np.array(best["q"]))
    assert ok and np.abs(chain.tip(q) - np.array(TARGET)).max() < 1e-6
    K = fd_stiffness(chain, q, np.zeros(2))
    assert max(K[0, 0] - 0.1, 0.08 - K[1, 1]) == pytest.approx(s, rel=1e-4)


def test_input_validation_names_the_field():
    cases = [
        (dict(), "K_desired"),
        (dict(K_desired=[[1, 0, 0], [0, 1, 0]]), "K_desired"),
        (dict(K_desired=[[1, 0.2], [0.1, 1]]), "K_desired"),
        (dict(K_desired=[[np.nan, 0], [0, 1]]), "K_desired"),
        (dict(bounds_K={"kzz": [0, 1]}), "bounds_K"),
        (dict(bounds_K={"kxx": [1, 0]}), "bounds_K.kxx"),
        (dict(bounds_K={"kxx": 3}), "bounds_K.kxx"),
        (dict(bounds_K={"kxy": [0, 1], "kyx": [2, 3]}), "bounds_K.kyx"),
        (dict(eig_bounds=[0.1, -0.1]), "eig_bounds"),
        (dict(eig_bounds=[None, 0.0]), "eig_bounds"),
        (dict(eig_bounds=[0.1, 0.2], load=(0, np.inf)), "load"),
        (dict(eig_bounds=[0.1, 0.2], margin=-1), "margin"),
        (dict(eig_bounds=[0.1, 0.2], bounds=(2, 1)), "bounds"),
        (dict(eig_bounds=[0.1, 0.2], max_starts=0), "max_starts"),
        (dict(eig_bounds=[0.1, 0.2], start=[0, 0]), "start"),
    ]
    for kw, field in cases:
        with pytest.raises(InvalidParameterError) as ei:
            to.preloads_for_stiffness(PAPER, TARGET, **kw)
        assert ei.value.field == field, (kw, ei.value.field)
    with pytest.raises(InvalidParameterError) as ei:
        to.preloads_for_stiffness(PAPER, (np.nan, 1.0), eig_bounds=[0.1, 0.2])
    assert ei.value.field == "target"
    with pytest.raises(to.UnreachableTargetError) as ei:
        to.preloads_for_stiffness(PAPER, (9.0, 0.0), eig_bounds=[0.1, 0.2])
    assert ei.value.field == "target"


def test_stiffness_design_to_dict_is_json():
    d = to.preloads_for_stiffness(PAPER, TARGET, eig_bounds=[0.03, None])
    out = json.loads(json.dumps(d.to_dict(), allow_nan=False))
    assert out["eig_bounds"] == [0.03, None] and out["exact"] is True
    assert np.allclose(out["K"], d.K) and len(out["rest_lengths"]) == 4


def test_time_limit():
    with pytest.raises(to.TimeLimitError):
        to.preloads_for_stiffness(PAPER, TARGET, eig_bounds=[0.04, 0.6], timeout=1e-4)


# ---------------------------------------------------------------------------- the bounds the design presses against
def test_active_bounds_name_the_rest_lengths_at_or_near_a_bound():
    """The paper's chain at (7.5, 1) with eigenvalues in [0.05, 0.5]: L2_0 of segment 0 and both springs of
    segment 1 on the upper bound 4 (= 4 b), L1_0 of segment 3 at 0.105, within 1 % of the interval of its lower
    bound 0.1 (= 0.1 b); the others (3.94 ...) are free."""
    d = to.preloads_for_stiffness(PAPER, (7.5, 1.0), eig_bounds=(0.05, 0.5))
    got = [(b.segment, b.variable, b.side, b.bound) for b in d.active_bounds]
    assert got == [(0, "L2_0", "upper", 4.0), (1, "L1_0", "upper", 4.0), (1, "L2_0", "upper", 4.0),
                   (3, "L1_0", "lower", pytest.approx(0.1))]
    for b in d.active_bounds:
        assert b.value == d.rest_lengths[b.segment, int(b.variable[1]) - 1]
    assert d.to_dict()["active_bounds"][3] == {"segment": 3, "variable": "L1_0", "side": "lower",
                                               "value": d.rest_lengths[3, 0], "bound": pytest.approx(0.1)}


def test_active_bounds_helper():
    from tensegrity_opt.analyses.design.active_bounds import ACTIVE_TOL, ActiveBound, active_bounds

    x = {"L1_0": [0.1, 0.5, 3.99, 2.0], "k": [1.0, 5.0]}
    lo = {"L1_0": 0.1, "k": [0.2, 0.2]}
    hi = {"L1_0": [4.0, 4.0, 4.0, 4.0], "k": float("inf")}
    got = active_bounds(x, lo, hi)
    assert got == (ActiveBound(0, "L1_0", "lower", 0.1, 0.1), ActiveBound(2, "L1_0", "upper", 3.99, 4.0))
    assert active_bounds({"k": [0.2 + 0.5 * ACTIVE_TOL]}, {"k": 0.2}, {"k": float("inf")})[0].side == "lower"
    assert active_bounds({"k": [0.2 + 2 * ACTIVE_TOL]}, {"k": 0.2}, {"k": float("inf")}) == ()
    assert got[0].describe() == "L1_0[0] = 0.1 (lower bound 0.1)"
