"""The imperfection-sensitivity curve (``imperfection_sensitivity``) against the independent references.

At every amplitude ``p`` the curve is the limit load of the dead-load path from the rest shape of the imperfect chain
(every segment's rest lengths ``L1_0 + p``, ``L2_0 - p``): here each one is traced again by
``reference_paths.limit_load_reference`` (a natural-parameter path with eigenvalue monitoring, bisection and the
extended system) from the reference model's own imperfect chain and rest shape. Koiter's small-imperfection law is
checked on a chain whose straight configuration buckles at an unstable-symmetric bifurcation (two segments
``a = 1.5``, guided: both buckled arms carry less load), where the drop ``P_c - P_s(p)`` goes as ``p^(2/3)``.
"""

from __future__ import annotations

import dataclasses
import json
import math

import numpy as np
import pytest
import reference_model as R
import reference_paths as RP
from clocks import tick_clock

import tensegrity_opt as to
from tensegrity_opt.analyses.paths import imperfection as imp
from tensegrity_opt.analyses.paths.boundaries import chain_at

# (a, b, k1, k2, L1_0, L2_0) per segment
PAPER = [(1.0, 1.0, 1.0, 1.0, 1.0, 1.0)] * 4
#: Three random heterogeneous monotonic segments (numpy's default_rng(7): a, b, k, L0 uniform).
HETERO = [(1.0500381866418667, 1.2588855203878302, 1.7083913973187517, 1.7083913973187517, 1.0576450329934144,
           1.0576450329934144),
          (0.9200665139644901, 1.2494213781585048, 0.7068448959352471, 0.7068448959352471, 1.4748598928679364,
           1.4748598928679364),
          (1.1188277715008184, 1.0871739811374883, 1.0939421548651076, 1.0939421548651076, 1.0948979284705413,
           1.0948979284705413)]
#: Two segments a = 1.5 > b: under the guided load the straight chain buckles at P_c = 35/6 and its arms fall.
SUBCRITICAL = [(1.5, 1.0, 1.0, 1.0, 1.0, 1.0)] * 2
AMPLITUDES = (0.0, 5e-4, 1e-3, 2e-3, 5e-3, 0.01, 0.02, 0.02851, 0.04, 0.061, -0.01)


def lib(segs) -> to.Manipulator:
    return to.Manipulator([to.Segment(a, b, k=(k1, k2), L0=(l1, l2)) for a, b, k1, k2, l1, l2 in segs])


def reference_limit(segs, p, boundary):
    """The reference limit load of the imperfect chain, from its own rest shape: ``(kind, load)`` with the kinds
    of the curve (a joint limit reached on the stable path: its load; stable to the end: NaN)."""
    chain = R.Chain.from_segments([(a, b, k1, k2, l1 + p, l2 - p) for a, b, k1, k2, l1, l2 in segs])
    r = RP.limit_load_reference(chain, RP.rest_configuration(chain), (-1.0, 0.0), boundary)
    if r.kind in ("fold", "bifurcation"):
        return r.kind, r.t
    return ("joint_limit", r.t) if r.reason == "joint_limit" else ("none", math.nan)


@pytest.fixture(scope="module")
def subcritical():
    return to.imperfection_sensitivity(lib(SUBCRITICAL), [1e-5, 3e-5, 1e-4, 3e-4, 0.0, -3e-5])


def test_curve_equals_limit_load_of_each_imperfect_chain(subcritical):
    m = lib(SUBCRITICAL)
    r = subcritical
    assert r.success and r.status == "complete"
    assert len(r.kinds) == len(r.loads) == len(r.statuses) == len(r.limit_loads) == r.amplitudes.size == 6
    for p, load, kind, lim in zip(r.amplitudes, r.loads, r.kinds, r.limit_loads):
        direct = to.limit_load(chain_at(m, "asymmetry", p), (-1.0, 0.0), "guided")
        assert (lim.kind, lim.status) == (direct.kind, direct.status)
        assert load == direct.load and kind == direct.kind           # the same computation, to the last bit
        np.testing.assert_array_equal(lim.q, direct.q)
    assert r.kinds[4] == "bifurcation" and r.loads[4] == pytest.approx(35.0 / 6.0, rel=1e-9)   # the perfect chain
    assert r.perfect_load == pytest.approx(35.0 / 6.0, rel=1e-9)
    assert r.loads[5] == pytest.approx(r.loads[1], rel=1e-9)         # -p: the mirror image
    for (a, b, k1, k2, l1, l2), s in zip(SUBCRITICAL, chain_at(m, "asymmetry", 0.01).segments):
        assert s.L0 == pytest.approx((l1 + 0.01, l2 - 0.01), rel=1e-15)


def test_unstable_symmetric_bifurcation_drops_as_two_thirds_power(subcritical):
    r = subcritical
    assert r.bifurcation == "unstable_symmetric" and r.law_expected == pytest.approx(2.0 / 3.0)
    small = [i for i in range(r.amplitudes.size) if r.amplitudes[i] > 0]
    assert all(r.kinds[i] == "fold" for i in small)
    p, drop = r.amplitudes[small], 35.0 / 6.0 - r.loads[small]
    assert np.all(drop > 0)
    slope = np.polyfit(np.log(p), np.log(drop), 1)[0]
    assert slope == pytest.approx(2.0 / 3.0, abs=0.03)               # Koiter: P_c - P_s ~ C p^(2/3)
    assert r.law_exponent == pytest.approx(2.0 / 3.0, abs=0.03)
    # pairwise too: every amplitude's fold on the law, down to p = 1e-5 (a fold sharper than a continuation step)
    assert np.all(np.abs(np.diff(np.log(drop)) / np.diff(np.log(p)) - 2.0 / 3.0) < 0.03)
    # the reference continuation at the smallest and largest amplitude: the same folds
    for i in (small[0], small[-1]):
        kind, load = reference_limit(SUBCRITICAL, float(r.amplitudes[i]), "guided")
        assert kind == "fold" and r.loads[i] == pytest.approx(load, rel=1e-7)


def test_kinds_vocabulary_and_json(subcritical):
    free = to.imperfection_sensitivity(lib(PAPER), [0.0, 0.01], boundary="free", max_load=0.2)
    assert free.kinds == ("bifurcation", "none") and math.isnan(free.loads[1])       # stable to max_load
    assert free.statuses == ("stability_lost", "max_load") and free.success
    assert free.bifurcation == "stable_symmetric" and free.law_exponent is None
    joint = to.imperfection_sensitivity(lib(PAPER), [0.01], boundary="free")
    assert joint.kinds == ("joint_limit",) and joint.loads[0] == joint.limit_loads[0].end_load
    assert joint.limit_loads[0].status == "joint_limit"
    for r in (subcritical, free, joint):
        assert set(r.kinds) <= set(imp.KINDS)
        d = json.loads(json.dumps(r.to_dict(include_limit_loads=True)))
        assert list(d)[:3] == ["success", "status", "message"]
        assert d["kinds"] == list(r.kinds) and len(d["limit_loads"]) == r.amplitudes.size
        assert "limit_loads" not in r.to_dict()
        with pytest.raises(dataclasses.FrozenInstanceError):
            r.status = "changed"                                        # type: ignore[misc]
    assert json.loads(json.dumps(free.to_dict()))["loads"][1] is None


def test_bad_arguments_are_refused():
    m = lib(PAPER)
    for kw, field in (({"amplitudes": []}, "amplitudes"), ({"amplitudes": [0.1, float("nan")]}, "amplitudes"),
                      ({"amplitudes": [2.0]}, "amplitudes"), ({"amplitudes": [0.1], "imperfection": "bend"},
                                                              "imperfection"),
                      ({"amplitudes": [0.1], "boundary": "wall"}, "boundary"),
                      ({"amplitudes": [0.1], "max_load": -1.0}, "max_load")):
        with pytest.raises(to.InvalidParameterError) as e:
            to.imperfection_sensitivity(m, **kw)
        assert e.value.field == field


def test_time_limit_keeps_the_amplitudes_done(monkeypatch):
    """An injected expiry after the perfect chain and two amplitudes: those are kept, the rest not computed."""
    checks = {"n": 0}

    def expires_after_three():
        checks["n"] += 1
        return checks["n"] > 3

    monkeypatch.setattr(imp, "expired", expires_after_three)
    m = lib(SUBCRITICAL)
    r = to.imperfection_sensitivity(m, [1e-3, 2e-3, 3e-3, 4e-3], timeout=3600.0)
    assert r.status == "time_limit" and not r.success
    assert r.statuses[2:] == ("not_computed", "not_computed") and r.kinds[2:] == ("unknown", "unknown")
    assert r.limit_loads[2:] == (None, None) and np.all(np.isnan(r.loads[2:]))
    for p, load in zip((1e-3, 2e-3), r.loads[:2]):
        assert load == to.limit_load(chain_at(m, "asymmetry", p), (-1.0, 0.0), "guided").load
    assert "2 of 4" in r.message


def test_time_limit_on_the_library_clock(monkeypatch):
    """The library's own clock (a stand-in that ticks per reading): a limit far beyond a few paths' readings
    cuts a long list of amplitudes part way, and what was done is kept."""
    clock = tick_clock(monkeypatch, step=1.0)
    m = lib(SUBCRITICAL)
    r = to.imperfection_sensitivity(m, np.linspace(1e-3, 0.03, 200), timeout=400.0)
    assert clock.readings > 0
    assert r.status == "time_limit"
    done = [i for i, s in enumerate(r.statuses) if s == "stability_lost"]
    assert done and done == list(range(len(done))) and len(done) < 200
    assert all(k == "unknown" for k in r.kinds[len(done) + 1:])


@pytest.mark.slow
@pytest.mark.parametrize("segs,boundary", [(PAPER, "guided"), (PAPER, "free"), (HETERO, "guided")],
                         ids=["paper-guided", "paper-free", "hetero-guided"])
def test_curve_against_reference_continuation(segs, boundary):
    """>= 10 amplitudes per chain: kind and load against the reference traced from the imperfect rest shape
    (folds and bifurcations to 1e-9; a joint limit, located by the library 1e-6 inside the range, to 1e-5)."""
    r = to.imperfection_sensitivity(lib(segs), AMPLITUDES, boundary=boundary)
    assert r.status == "complete" and r.amplitudes.size >= 10
    for p, kind, load in zip(AMPLITUDES, r.kinds, r.loads):
        ref_kind, ref_load = reference_limit(segs, p, boundary)
        assert kind == ref_kind, p
        if kind in ("fold", "bifurcation"):
            assert load == pytest.approx(ref_load, rel=1e-9), p
        elif kind == "joint_limit":
            assert load == pytest.approx(ref_load, rel=1e-5), p
    # the perfect chain's arms: both carry more (supercritical), no small-imperfection law
    assert r.bifurcation == "stable_symmetric" and r.law_exponent is None


def test_stability_boundary_says_which_curve_it_is():
    """The fold curve of ``stability_boundary`` is documented as that curve, pointing to the imperfect arm's."""
    doc = to.stability_boundary.__doc__
    assert "imperfection_sensitivity" in doc and "imperfection sensitivity of a column" not in doc
    assert "imperfection_sensitivity" in to.StabilityBoundary.__doc__


def test_the_sharp_folds_of_tiny_imperfections_are_folds(subcritical):
    """The smallest pre-bends of the subcritical chain fold in a corner far shorter than a continuation step: each
    is located as a fold (the continuation refuses a step whose stability changes with no event between its
    points), its path stable up to it; none is "unknown" or "none"."""
    r = subcritical
    assert r.status == "complete" and r.kinds == ("fold",) * 4 + ("bifurcation", "fold")
    for lim in r.limit_loads:
        ev = next(e for e in lim.branch.events if e.stability == "lost")
        assert np.all(lim.branch.morse_index[:ev.index + 1] == 0)


def test_law_side_is_the_one_that_drops(monkeypatch):
    """The law is fitted on the side of ``p`` whose folds fall below ``P_c``, whichever sign the smallest amplitude
    has. The subcritical chain (symmetric: both sides drop) with its smallest amplitude listed first on the side
    with a single point: the other side's three folds give the 2/3 law. Then that smallest amplitude's path is
    cut (an injected failure, kind ``"unknown"``): the law still comes from the side that folds below ``P_c``."""
    m = lib(SUBCRITICAL)
    amplitudes = [-1e-5, 3e-5, 1e-4, 3e-4]
    r = to.imperfection_sensitivity(m, amplitudes)
    assert r.bifurcation == "unstable_symmetric" and r.kinds == ("fold",) * 4
    assert np.all(r.loads < 35.0 / 6.0)
    np.testing.assert_array_equal(r.law_amplitudes, [3e-5, 1e-4, 3e-4])
    assert r.law_exponent == pytest.approx(2.0 / 3.0, abs=0.03)     # Koiter: P_c - P_s ~ C p^(2/3)

    real = imp.limit_load

    def cut_negative_side(chain, *args, **kwargs):
        if chain.segments[0].L1_0 < SUBCRITICAL[0][4]:
            raise to.TensegrityError("injected: this path was cut")
        return real(chain, *args, **kwargs)

    monkeypatch.setattr(imp, "limit_load", cut_negative_side)
    cut = to.imperfection_sensitivity(m, amplitudes)
    assert cut.kinds[0] == "unknown" and cut.statuses[0] == "failed" and cut.kinds[1:] == ("fold",) * 3
    np.testing.assert_array_equal(cut.law_amplitudes, [3e-5, 1e-4, 3e-4])
    assert cut.law_exponent == pytest.approx(2.0 / 3.0, abs=0.03)


def test_law_on_the_dropping_side_of_an_asymmetric_bifurcation():
    """Transcritical (asymmetric) data: the smallest amplitudes on one side fold above ``P_c`` or not at all, the
    other side drops as ``|p|^(1/2)``; the law is the dropping side's, and no side gives none."""
    pc = 2.0
    perfect = type("Perfect", (), {"load": pc})()
    amps = np.array([1e-4, 4e-4, -4e-4, 1e-3, -1e-3, -4e-3, 4e-3])
    drops = 0.3 * np.sqrt(np.abs(amps))
    loads = np.where(amps < 0, pc - drops, pc + drops)
    kinds = ["fold" if p < 0 else k for p, k in zip(amps, ("fold", "none", "", "fold", "", "", "joint_limit"))]
    e, c, used = imp._law(amps, loads, kinds, perfect, "asymmetric")
    np.testing.assert_array_equal(used, [-4e-4, -1e-3, -4e-3])
    assert e == pytest.approx(0.5, rel=1e-9) and c == pytest.approx(0.3, rel=1e-9)
    none = imp._law(amps, np.full(amps.size, pc + 0.1), ["fold"] * amps.size, perfect, "asymmetric")
    assert none[0] is None and none[2].size == 0
