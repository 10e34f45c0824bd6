"""Bounds ``[lo, hi]`` or ``{"lo": lo, "hi": hi}``: one reading (:func:`tensegrity_opt.bounds.bound_pair`)."""

from __future__ import annotations

import numpy as np
import pytest

from tensegrity_opt.bounds import bound_pair
from tensegrity_opt.errors import InvalidParameterError


@pytest.mark.parametrize("value", [[0.2, 5.0], (0.2, 5.0), np.array([0.2, 5.0]), {"lo": 0.2, "hi": 5.0},
                                   {"hi": 5.0, "lo": 0.2}])
def test_both_forms_read_alike(value):
    assert tuple(float(x) for x in bound_pair(value)) == (0.2, 5.0)


def test_sides_pass_unchanged():
    assert bound_pair({"lo": [0.1, 0.2], "hi": None}) == ([0.1, 0.2], None)


@pytest.mark.parametrize(("value", "words"), [({"lo": 1.0}, "missing 'hi'"), ({"lo": 1, "hi": 2, "mid": 3},
                                                                               "unknown key 'mid'"),
                                              ([1.0], "bounds are [lo, hi]"), ("lo", "bounds are"), (3.0, "bounds")])
def test_other_shapes_are_refused_naming_the_field(value, words):
    with pytest.raises(InvalidParameterError, match="^options.bounds.k: ") as info:
        bound_pair(value, "options.bounds.k")
    assert words in str(info.value) and info.value.field == "options.bounds.k"


def test_the_library_takes_both_forms():
    import tensegrity_opt as to

    m = to.Manipulator.uniform(2)
    a = to.maximize_critical_force(m, ["k"], {"k": [0.5, 2.0]}, {"k": 2.4})
    b = to.maximize_critical_force(m, ["k"], {"k": {"lo": 0.5, "hi": 2.0}}, {"k": 2.4}, tension={"lo": -5, "hi": 5})
    assert a.critical_force == pytest.approx(b.critical_force, rel=1e-9)
