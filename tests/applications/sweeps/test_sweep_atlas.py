"""The atlas as a sweep (``applications/sweeps/atlas.py``): the rows of an ``analysis: atlas`` sweep assemble to the
atlas ``stability_atlas`` computes directly on the same grid; a chain given by its segments cannot vary."""

from __future__ import annotations

import numpy as np
import pytest

import tensegrity_opt as to
from tensegrity_opt.analyses.paths.atlas import stability_atlas
from tensegrity_opt.applications import sweeps
from tensegrity_opt.model.segment import Segment

PRE_BENT = to.Manipulator([Segment(1.0, 1.0, 1.0, (1.05, 0.95))] * 2 + [Segment(1.0, 1.0, 1.0, 1.0)] * 2)


def test_sweep_rows_assemble_to_the_same_atlas():
    spec = {"analysis": "atlas",
            "manipulator": {"segments": [{"a": 1, "b": 1, "k": 1, "L0": [1.05, 0.95]}] * 2
                            + [{"a": 1, "b": 1, "k": 1, "L0": 1}] * 2},
            "grid": {"dy": [-0.6, -0.2, 0.2], "dx": [0.2, 0.7]}}
    res = sweeps.sweep(spec)
    assert not res.errors
    from_rows = sweeps.atlas_from_rows(spec, res.rows)
    direct = stability_atlas(PRE_BENT, [0.2, 0.7], [-0.6, -0.2, 0.2])
    np.testing.assert_array_equal(from_rows.n_stable, direct.n_stable)
    assert len(from_rows.crossings) == len(direct.crossings) == 2
    for a, b in zip(from_rows.crossings, direct.crossings):
        assert (a.kind, a.edge) == (b.kind, b.edge)
        assert a.dy == pytest.approx(b.dy, abs=1e-10)
    d = from_rows.to_dict()
    assert d["n_stable"] == direct.n_stable.tolist() and len(d["curves"]["switch"]) == 1


def test_sweep_spec_with_segments_refuses_varying_the_chain():
    base = {"segments": [{"a": 1, "b": 1, "k": 1, "L0": [1.05, 0.95]}]}
    with pytest.raises(to.InvalidParameterError) as e:
        sweeps.validate_spec({"analysis": "atlas", "manipulator": base, "grid": {"dx": [0.1], "n": [3]}})
    assert e.value.field == "grid.n"
    with pytest.raises(to.InvalidParameterError) as e:
        sweeps.validate_spec({"analysis": "atlas", "manipulator": {"segments": [{"a": 1, "k": [1, -2]}]},
                              "grid": {"dx": [0.1]}})
    assert e.value.field == "manipulator.segments[0].k[1]"
    with pytest.raises(to.InvalidParameterError) as e:
        sweeps.validate_spec({"analysis": "atlas", "manipulator": {**base, "n": 3}, "grid": {"dx": [0.1]}})
    assert e.value.field == "manipulator.n"
    for spec, fld in (({"manipulator": {"n": 1}}, "manipulator.n"),
                      ({"grid": {"dx": [0.1], "n": [3, 65]}}, "grid.n[1]")):
        with pytest.raises(to.InvalidParameterError) as e:
            sweeps.validate_spec({"analysis": "atlas", "grid": {"dx": [0.1]}, **spec})
        assert e.value.field == fld
    with pytest.raises(to.InvalidParameterError) as e:
        sweeps.validate_spec({"analysis": "atlas", "grid": {"dx": [0.1]}, "options": {"method": "guess"}})
    assert e.value.field == "options.method"
    with pytest.raises(to.InvalidParameterError) as e:
        sweeps.atlas_from_rows({"analysis": "atlas", "grid": {"dx": [0.1], "k": [1.0]}}, [])
    assert e.value.field == "grid"


def test_an_atlas_sweep_through_the_straight_chain_keeps_the_targets_beyond_reach():
    """dx = 0 holds the paper's chain straight at dy = 0 and is beyond reach above it: every row is computed (the
    rows beyond reach have no least energy) and the rows assemble to the complete atlas."""
    spec = {"analysis": "atlas", "manipulator": {"n": 4, "a": 1, "b": 1, "k": 1, "L0": 1},
            "grid": {"dx": [0.0, 0.5], "dy": [0.0, 0.1]}}
    res = sweeps.sweep(spec)
    assert not res.errors
    at = sweeps.atlas_from_rows(spec, res.rows)
    assert at.status == "complete", at.message
    direct = stability_atlas(to.Manipulator.uniform(4, 1.0, 1.0, 1.0, 1.0), [0.0, 0.5], [0.0, 0.1])
    assert at.n_stable.tolist() == direct.n_stable.tolist() == [[1, 2], [0, 2]]
