"""The workspace stability atlas (analyses/atlas.py), its sweep form, and curves measured from the rest shape.

Independent numbers: tests/support/reference_model.py (numpy: the energy, the held-tip Newton and a many-start
global minimum) and the exact rest configurations of tests/support/reference_paths.py; the brute-force atlas
comparison (counts, Maxwell points, folds on the edges) is tests/analyses/paths/test_atlas_reference.py.
"""

from __future__ import annotations

import shutil

import numpy as np
import pytest

import tensegrity_opt as to
from tensegrity_opt.analyses.paths.atlas import assemble_atlas, atlas_target, stability_atlas
from tensegrity_opt.applications import sweeps
from tensegrity_opt.model.segment import Segment

from reference_model import Chain
from reference_paths import rest_configuration as ref_rest

BISTABLE = to.Manipulator.uniform(3, 0.5, 1.0, 1.0, 1.0)
PRE_BENT = to.Manipulator([Segment(1.0, 1.0, 1.0, (1.05, 0.95))] * 2 + [Segment(1.0, 1.0, 1.0, 1.0)] * 2)


def ref_chain(m: to.Manipulator) -> Chain:
    return Chain.from_segments([(s.a, s.b, s.k1, s.k2, s.L1_0, s.L2_0) for s in m.segments])


# ------------------------------------------------------------------------------------------ reference="rest"
def test_curve_from_rest_of_pre_bent_heterogeneous_chain():
    m = to.Manipulator([Segment(0.9, 1.0, 1.2, (1.08, 0.96)), Segment(1.1, 0.8, 0.9, (0.97, 1.01)),
                        Segment(1.0, 1.1, 1.0, 1.0)])
    ch = ref_chain(m)
    q_rest = ref_rest(ch)                       # the unloaded joint minima near 0 (separable energy)
    tip_rest = ch.tip(q_rest)
    c = to.force_deflection(m, np.linspace(0.0, 0.24, 3), 0.03, reference="rest")
    assert c.reference == "rest"
    np.testing.assert_allclose(c.origin, [m.straight_length - tip_rest[0], tip_rest[1]], atol=1e-10)
    assert np.max(np.abs(c.origin)) > 0.05     # really pre-bent: the rest tip is off the straight one
    for i in range(c.dx.size):
        target = tip_rest + np.array([-c.dx[i], c.dy[i]])
        np.testing.assert_allclose(ch.tip(c.q[i]), target, atol=1e-9)
        # the reference model's many-start least-energy held-tip equilibrium at the same target
        E_ref, q_ref, F_ref = ch.global_min(c.dx[i] + c.origin[0], c.dy[i] + c.origin[1], n_random=40)
        assert c.energy[i] == pytest.approx(E_ref, rel=1e-9, abs=1e-10)
        np.testing.assert_allclose([c.fx[i], c.fy[i]], F_ref, atol=1e-7)
    d = c.to_dict()
    assert d["reference"] == "rest" and d["points"][0]["dx"] == pytest.approx(0.0)


def test_curve_from_rest_is_zero_force_at_rest_and_straight_for_symmetric_chain():
    c = to.force_deflection(PRE_BENT, [0.0, 0.05], 0.0, reference="rest")
    assert abs(c.fx[0]) < 1e-10 and abs(c.fy[0]) < 1e-10
    sym = to.Manipulator.uniform(4)
    a = to.force_deflection(sym, [0.0, 0.1], reference="rest")
    b = to.force_deflection(sym, [0.0, 0.1])
    np.testing.assert_array_equal(a.origin, [0.0, 0.0])
    np.testing.assert_allclose(a.fx, b.fx, atol=1e-14)
    with pytest.raises(to.InvalidParameterError) as e:
        to.force_deflection(sym, [0.1], reference="bent")
    assert e.value.field == "reference"


# ------------------------------------------------------------------------------------------ the atlas
def test_atlas_targets_against_reference_model():
    at = stability_atlas(PRE_BENT, [0.2, 0.6], [-0.6, 0.2], edges=False)
    ch = ref_chain(PRE_BENT)
    assert at.status == "complete"
    for j, dy in enumerate(at.dy):
        for i, dx in enumerate(at.dx):
            E_ref = ch.global_min(dx, dy, n_random=40)[0]
            assert at.least_energy[j, i] == pytest.approx(E_ref, rel=1e-9)


def test_switch_off_the_symmetry_line_on_a_pre_bent_chain():
    at = stability_atlas(PRE_BENT, [0.2, 0.7], np.linspace(-0.6, 0.6, 4))
    ch = ref_chain(PRE_BENT)
    sw = at.switches
    assert len(sw) == 2 and all(c.method == "equal_energy" for c in sw)
    for c in sw:
        assert -0.45 < c.dy < -0.3                    # the pre-bend moves the Maxwell line off dy = 0
        target = ch.target(c.dx, c.dy)
        for q in (c.q, c.q_other):
            np.testing.assert_allclose(ch.tip(q), target, atol=1e-9)
        assert ch.energy(c.q) == pytest.approx(ch.energy(c.q_other), rel=1e-10)
        assert np.max(np.abs(c.q - c.q_other)) > 0.1  # two different shapes
        for q, F in ((c.q, c.force), (c.q_other, c.force_other)):
            assert np.all(ch.reduced_eigs(q, F) > 0)  # both stable
    segs = at.curves("switch")
    assert len(segs) == 1 and segs[0][0, 1] == pytest.approx(sw[0].dy)


def test_mirror_chain_ties_on_the_axis_and_folds_are_branch_ends():
    at = stability_atlas(BISTABLE, [0.4, 0.9], [-0.3, 0.0, 0.3])
    ties = [c for c in at.switches if c.method == "tie"]
    assert {(c.dx, c.dy) for c in ties} == {(0.4, 0.0), (0.9, 0.0)}
    assert [s[:, 1].tolist() for s in at.curves("switch")] == [[0.0, 0.0]]
    ch = ref_chain(BISTABLE)
    n_stable = at.n_stable
    ends = at.branch_ends
    assert ends, "the bistable chain gains stable equilibria between dx = 0.4 and 0.9"
    for c in ends:
        (ia, ja), (ib, jb) = c.edge
        assert n_stable[ja, ia] != n_stable[jb, ib]
        assert c.event == "fold" and c.method == "moore_spence"
        # at a fold of the held tip the reduced Hessian is singular (reference model)
        ev = ch.reduced_eigs(c.q, c.force, fd=False)
        assert np.min(np.abs(ev)) < 1e-8 * np.max(np.abs(ch.lagrangian_hess(c.q, c.force)))


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


def test_unreachable_targets_and_failed_targets_are_kept():
    at = stability_atlas(BISTABLE, [-0.5, 0.5], [0.0, 0.2])     # dx = -0.5 stretches beyond reach
    assert not at.targets[0][0].reachable and at.n_stable[0, 0] == 0 and at.count[0, 0] == 0
    assert at.n_stable[0, 1] > 0
    # the stable branches from dx = 0.5 followed towards the unreachable target end on the edge, inside it
    to_far = [c for c in at.crossings if c.edge[0] == (0, 0)]
    # (the straight chain, dx = 0, is the edge of the workspace: the branches end there, no stability event)
    assert all(c.kind == "branch_end" and 0.0 < c.dx < 0.5 for c in to_far)
    assert atlas_target(BISTABLE, -1.0, 0.0).reachable is False
    d = at.to_dict()                            # targets without a stable equilibrium: nulls, not a TypeError
    assert d["targets"][0][0]["least_energy"] is None and d["least_energy"][0][0] is None


def test_atlas_time_limit_keeps_what_is_done_and_validates_input():
    at = stability_atlas(BISTABLE, np.linspace(0.2, 1.2, 12), np.linspace(-0.5, 0.5, 12), timeout=0.3)
    assert at.status == "time_limit" and not at.success
    done = [t for row in at.targets for t in row if t.success]
    assert 0 < len(done) < 144
    assert all(t.error.startswith("time_limit") for row in at.targets for t in row if not t.success)
    for kw, fld in (({"dx": [0.2, 0.1], "dy": [0.0]}, "dx"), ({"dx": [0.1], "dy": [np.nan]}, "dy"),
                    ({"dx": np.zeros(101) + np.arange(101), "dy": np.arange(101.0)}, "dx"),
                    ({"dx": [0.1], "dy": [0.0], "method": "exact"}, "method")):
        with pytest.raises(to.InvalidParameterError) as e:
            stability_atlas(BISTABLE, **kw)
        assert e.value.field == fld
    with pytest.raises(to.InvalidParameterError) as e:
        stability_atlas(to.Manipulator.uniform(1), [0.1], [0.0])
    assert e.value.field == "n"
    with pytest.raises(to.InvalidParameterError):
        assemble_atlas(BISTABLE, [atlas_target(BISTABLE, 0.2, 0.0)] * 2)


@pytest.mark.skipif(shutil.which("phc") is None, reason="PHCpack (phc) not installed")
def test_certified_counts_agree_with_the_search():
    h = stability_atlas(BISTABLE, [0.3, 1.1], [0.1, 0.5], method="homotopy", edges=False)
    s = stability_atlas(BISTABLE, [0.3, 1.1], [0.1, 0.5], edges=False)
    assert h.certified.all() and not s.certified.any()
    np.testing.assert_array_equal(h.count, s.count)
    np.testing.assert_array_equal(h.n_stable, s.n_stable)
    np.testing.assert_allclose(h.least_energy, s.least_energy, rtol=1e-10)
