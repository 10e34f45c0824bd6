"""The critical-load map: the buckling analysis over a grid of two design parameters, blank where it refuses a
design; its result contract; its refusals."""

from __future__ import annotations

import numpy as np
import pytest

import tensegrity_opt as to
from tensegrity_opt.applications.sweeps import CriticalLoadMap, critical_load_map
from tensegrity_opt.errors import InvalidParameterError

PAPER = to.Manipulator.uniform(4, a=1.0, b=1.0, k=1.0, L0=1.0)


def test_the_map_is_the_critical_load_blank_where_it_raises():
    xs, ys = [0.4, 0.7, 1.0, 1.3], [0.5, 1.0, 1.5, 2.0, 2.5]
    cm = critical_load_map(PAPER, "a", xs, "L0", ys)
    expected = np.full((len(ys), len(xs)), np.nan)
    for iy, L0 in enumerate(ys):
        for ix, a in enumerate(xs):
            try:
                expected[iy, ix] = -to.critical_force(to.Manipulator.uniform(4, a=a, b=1.0, k=1.0, L0=L0)).force
            except to.TensegrityError:
                pass
    assert np.isnan(expected).sum() >= 2 and np.isfinite(expected).sum() >= 10
    assert cm.load.shape == expected.shape
    assert np.allclose(cm.load, expected, rtol=1e-13, atol=0.0, equal_nan=True)
    assert np.array_equal(np.isnan(cm.load), np.isnan(expected))
    assert expected[1, 2] == pytest.approx(0.572793, abs=1e-6)      # the paper's chain
    assert (cm.param_x, cm.param_y, cm.boundary) == ("a", "L0", "guided")
    assert np.array_equal(cm.values_x, xs) and np.array_equal(cm.values_y, ys)
    free = critical_load_map(PAPER, "k", [0.5, 2.0], "b", [1.0, 0.8], boundary="free")
    assert free.load[1, 1] == pytest.approx(-to.critical_force(to.Manipulator.uniform(4, b=0.8, k=2.0), "free").force,
                                            rel=1e-13)


def test_a_heterogeneous_chain_keeps_its_other_parameters():
    m = to.Manipulator([to.Segment(1.0, 1.0, k, 1.0) for k in (0.5, 1.0, 2.0, 1.0)])
    cm = critical_load_map(m, "a", [0.8, 1.0], "L0", [1.0, 1.2])
    same = to.Manipulator([s.replace(a=1.0, L0=1.2) for s in m.segments])
    assert cm.load[1, 1] == pytest.approx(-to.critical_force(same).force, rel=1e-13)


def test_the_result_contract():
    cm = critical_load_map(PAPER, "a", [0.4, 1.0], "L0", [0.5, 1.0])
    assert 0 < cm.blank < cm.load.size
    assert (cm.status, cm.success) == ("partial", True)
    assert cm.message == f"critical loads of {4 - cm.blank} of 4 designs; {cm.blank} blank " \
                         "(the straight chain is unstable or not an equilibrium there)"
    d = cm.to_dict()
    assert list(d)[:3] == ["success", "status", "message"]
    assert sum(v is None for row in d["load"] for v in row) == cm.blank
    full = critical_load_map(PAPER, "k", [1.0, 2.0], "a", [1.0, 0.9])
    assert (full.status, full.success, full.blank) == ("complete", True, 0)
    assert full.message == "critical loads of all 4 designs (guided tip)"
    empty = critical_load_map(PAPER, "a", [0.3, 0.4], "L0", [0.2, 0.3])
    assert (empty.status, empty.success) == ("empty", False)
    assert set(CriticalLoadMap.STATUSES) == {"complete", "partial", "empty"}
    with pytest.raises(ValueError):                          # immutable
        cm.load[0, 0] = 1.0
    with pytest.raises(AttributeError):
        cm.boundary = "free"


@pytest.mark.parametrize("args, field", [
    (("a", [0.5, 1.0], "a", [1.0, 2.0]), "param_y"),         # "param_x and param_y must differ"
    (("a", [1.0, 0.5, 2.0], "L0", [1.0, 2.0]), "values_x"),
    (("a", [1.0], "L0", [1.0, 2.0]), "values_x"),
    (("a", [1.0, 2.0], "L0", [0.0, 2.0]), "values_y"),
    (("c", [1.0, 2.0], "L0", [1.0, 2.0]), "param_x"),
])
def test_refusals(args, field):
    with pytest.raises(InvalidParameterError) as e:
        critical_load_map(PAPER, *args)
    assert e.value.field == field
    with pytest.raises(InvalidParameterError) as e:
        critical_load_map(PAPER, "a", [1.0, 2.0], "L0", [1.0, 2.0], boundary="clamped")
    assert e.value.field == "boundary"
    with pytest.raises(InvalidParameterError) as e:
        critical_load_map(to.Manipulator.uniform(1), "a", [1.0, 2.0], "L0", [1.0, 2.0])
    assert e.value.field == "n"
