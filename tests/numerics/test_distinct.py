"""When two configurations are the same equilibrium (tensegrity_opt.numerics.distinct) and the compiled kernel's
comparison: both against a plain double loop written here, on random rows near the tolerance."""

import numpy as np
import pytest

import tensegrity_opt as to
from tensegrity_opt.numerics import SAME_Q, chain_solver, distinct, distinct_indices, distinct_rows, kernels, same
from tensegrity_opt.numerics.results import LocalResult


def by_hand(Q, good, tol):
    """Rows kept by a double loop: good, and not within ``tol`` in every angle of an earlier kept row."""
    keep = []
    for i in range(len(Q)):
        keep.append(bool(good[i]) and not any(keep[j] and max(abs(a - b) for a, b in zip(Q[i], Q[j])) < tol
                                              for j in range(i)))
    return np.array(keep, dtype=bool)


def near_rows(rng, k, n, tol, groups):
    """``k`` rows in ``groups`` clusters, each row its cluster's centre plus noise up to 1.5 tol per angle: pairs
    on both sides of the tolerance, and chains (a ~ b, b ~ c, a !~ c)."""
    base = rng.uniform(-1.0, 1.0, (groups, n))
    return base[rng.integers(0, groups, k)] + rng.uniform(-0.75, 0.75, (k, n)) * tol


def test_same_is_strict_at_the_tolerance():
    q = np.array([0.3, -0.2, 0.1])
    assert same(q, q + 0.5 * SAME_Q) and not same(q, q + np.array([0.0, 2 * SAME_Q, 0.0]))
    assert not same(np.array([0.0]), np.array([0.25]), 0.25)       # exactly the tolerance apart: different
    assert same(np.array([0.0]), np.array([0.25]), 0.2500001)


@pytest.mark.parametrize("seed", range(6))
def test_distinct_rows_match_the_double_loop(seed):
    rng = np.random.default_rng(seed)
    for k, groups in [(12, 3), (40, 6), (64, 5)]:
        Q = near_rows(rng, k, 4, SAME_Q, groups)
        expected = by_hand(Q.tolist(), [True] * k, SAME_Q)
        np.testing.assert_array_equal(distinct_rows(Q), expected)
        assert expected.sum() < k                                  # duplicates were there
    Q = near_rows(rng, 30, 3, 1e-3, 4)                             # another tolerance
    np.testing.assert_array_equal(distinct_rows(Q, 1e-3), by_hand(Q.tolist(), [True] * 30, 1e-3))


def test_large_samples_keep_exactly_the_rows_of_the_double_loop():
    """Beyond 64 rows each row is compared with the kept rows near its first angle only: the same rows kept."""
    rng = np.random.default_rng(11)
    Q = near_rows(rng, 1500, 5, SAME_Q, 100)
    idx = sorted(rng.choice(1500, 700, replace=False).tolist())
    good = np.zeros(1500, dtype=bool)
    good[idx] = True
    expected = np.flatnonzero(by_hand(Q.tolist(), good, SAME_Q)).tolist()
    assert distinct_indices(Q, idx) == expected
    np.testing.assert_array_equal(distinct_rows(Q), by_hand(Q.tolist(), [True] * 1500, SAME_Q))


def test_distinct_results_keep_the_first_of_each_group_in_order():
    rng = np.random.default_rng(5)
    Q = near_rows(rng, 25, 3, 1e-6, 4)
    results = [LocalResult(q, np.zeros(2), True, "Newton_Converged", 0) for q in Q]
    kept = distinct(results, 1e-6)
    assert [r.q.tolist() for r in kept] == [q for q, k in zip(Q.tolist(), by_hand(Q.tolist(), [True] * 25, 1e-6))
                                            if k]
    assert distinct(results[:1]) == results[:1] and distinct([]) == []


@pytest.mark.parametrize("n", [3, 4, 6])
def test_kernel_comparison_agrees_with_numpy_on_random_rows_near_the_tolerance(n):
    """The ``distinct`` function compiled into the seeds kernel, fed rows by hand: the numpy rule's answer."""
    k = chain_solver(to.Manipulator.uniform(n)).functions.kernel.kernels
    cols, layout = kernels.seed_columns(n), kernels.seed_layout(n)
    rng = np.random.default_rng(n)
    thresh = 1e-12
    checked = 0
    for _ in range(40):
        rows = np.zeros((cols, layout.size - 1))
        Q = near_rows(rng, cols, n, SAME_Q, int(rng.integers(2, 6)))
        rows[:, layout["q"]] = Q
        rows[:, layout["norm"]] = np.where(rng.random(cols) < 0.85, 0.5 * thresh, 10 * thresh)   # converged or not
        rows[:, layout["margin"]] = np.where(rng.random(cols) < 0.9, -0.1, 0.0)                  # inside or on a bound
        active = (np.arange(cols) < int(rng.integers(cols // 2, cols + 1))).astype(float)
        got = np.asarray(k.distinct(rows.T, active, thresh, SAME_Q)).ravel() > 0.5
        good = (active > 0) & (rows[:, layout["norm"]] <= thresh) & (rows[:, layout["margin"]] < 0)
        expected = np.zeros(cols, dtype=bool)
        expected[distinct_indices(Q, np.flatnonzero(good).tolist())] = True
        np.testing.assert_array_equal(got, expected)
        np.testing.assert_array_equal(got, by_hand(Q.tolist(), good, SAME_Q))
        checked += int(good.sum() - got.sum())
    assert checked > 40                                            # many near-duplicates were dropped
