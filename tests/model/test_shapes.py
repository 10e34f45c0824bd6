"""Shape labels (``model/shapes.py``): the paper's Table 2 names of the equilibria by the signs of their joint
angles, and the vectorised labels equal the row-by-row ones."""

import numpy as np
import pytest

from tensegrity_opt import shape_label, sign_string
from tensegrity_opt.model.shapes import shape_labels


@pytest.mark.parametrize("q,label,signs", [
    ([-1, 2, 3, 4], "U", "-+++"), ([1, -2, -3, -4], "U", "+---"),
    ([-1, 2, -3, 4], "Z", "-+-+"), ([1, -2, 3, -4], "Z", "+-+-"),
    ([-1, 2, -3, -4], "ZU", "-+--"), ([1, -2, 3, 4], "ZU", "+-++"),
    ([0, 0, 0, 0], "I", "0000"), ([1, 2, 3, 1e-9], "C", "+++0"),
    ([1, -1, 1, -1, 1], "W4", "+-+-+"),
])
def test_table2_labels(q, label, signs):
    assert shape_label(q) == label
    assert sign_string(q) == signs


def test_vectorised_shape_labels_equal_the_row_by_row_labels():
    rng = np.random.default_rng(0)
    Q = rng.standard_normal((3000, 7)) * (rng.random((3000, 7)) > 0.3)
    Q[::11] = 0.0
    Q[5] = [0.0, 0.0, 1e-9, 0.0, 2.0, -1.0, 0.0]          # a tiny angle counts as zero
    assert shape_labels(Q) == [shape_label(q) for q in Q]
    assert shape_labels(np.zeros((0, 4))) == []
