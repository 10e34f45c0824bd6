"""Configurations of one value per joint: the Cartesian product as rows, for any number of joints."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from tensegrity_opt.model.combinations import combination_count, combination_indices, combinations


def test_rows_in_meshgrid_order():
    choices = [[0.1, 0.2], [1.0], [-1.0, 0.0, 1.0]]
    expected = np.array(list(itertools.product(*choices)))
    assert np.array_equal(combinations(choices), expected)
    grids = np.meshgrid(*choices, indexing="ij")
    assert np.array_equal(combinations(choices), np.stack([g.ravel() for g in grids], axis=1))
    assert combination_count(choices) == 6
    assert np.array_equal(combination_indices([2, 1, 3]), np.array(list(itertools.product(range(2), [0], range(3)))))


@pytest.mark.parametrize("n", [33, 64, 200])
def test_more_joints_than_numpy_has_dimensions(n):
    # numpy.meshgrid / broadcast stop at 32 dimensions ("only supports up to 32 dimensions but the array has 33")
    rows = combinations([[0.5 * j] for j in range(n)])
    assert rows.shape == (1, n) and np.array_equal(rows[0], 0.5 * np.arange(n))
    two = combinations([[0.0, 1.0] if j in (0, n - 1) else [2.0] for j in range(n)])
    assert two.shape == (4, n)
    assert two[:, 0].tolist() == [0.0, 0.0, 1.0, 1.0] and two[:, -1].tolist() == [0.0, 1.0, 0.0, 1.0]


def test_a_joint_without_a_choice_gives_no_row():
    assert combinations([[1.0, 2.0], [], [3.0]]).shape == (0, 3)
    assert combination_count([[1.0, 2.0], []]) == 0
