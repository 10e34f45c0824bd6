"""The workspace stability atlas (``analyses/paths/atlas.py``): targets, switches and branch ends, unreachable and
failed targets, the time limit, the certified counts.

Independent numbers: tests/support/reference_model.py (numpy: the energy, the held-tip Newton and a many-start
global minimum); the brute-force atlas comparison (counts, Maxwell points, folds on the edges) is
tests/analyses/paths/test_atlas_reference.py, the atlas as a sweep tests/applications/sweeps/test_sweep_atlas.py.
"""

from __future__ import annotations

import shutil

import numpy as np
import pytest
from clocks import tick_clock
from reference_model import Chain

import tensegrity_opt as to
from tensegrity_opt.analyses.paths.atlas import assemble_atlas, atlas_target, stability_atlas
from tensegrity_opt.model.segment import Segment

BISTABLE = to.Manipulator.uniform(3, 0.5, 1.0, 1.0, 1.0)
PRE_BENT = to.Manipulator([Segment(1.0, 1.0, 1.0, (1.05, 0.95))] * 2 + [Segment(1.0, 1.0, 1.0, 1.0)] * 2)


def ref_chain(m: to.Manipulator) -> Chain:
    return Chain.from_segments([(s.a, s.b, s.k1, s.k2, s.L1_0, s.L2_0) for s in m.segments])


# ------------------------------------------------------------------------------------------ reference="rest"


# ------------------------------------------------------------------------------------------ the atlas
@pytest.mark.slow
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


@pytest.mark.slow
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


def test_progress_sees_each_target_once_in_grid_order_before_the_edges():
    seen = []
    at = stability_atlas(BISTABLE, [0.2, 1.4], [-0.3, 0.3], edges=False, progress=seen.append)
    assert [(t.dx, t.dy) for t in seen] == [(0.2, -0.3), (1.4, -0.3), (0.2, 0.3), (1.4, 0.3)]
    assert seen == [t for row in at.targets for t in row]


def test_atlas_time_limit_keeps_what_is_done_and_validates_input(monkeypatch):
    # the library's clock moves on 1 s at every reading (tests/support/clocks.py): a target takes about 4 readings,
    # so a limit of 30 s runs out after some 7 of the 144 targets, on any machine
    tick_clock(monkeypatch, step=1.0)
    at = stability_atlas(BISTABLE, np.linspace(0.2, 1.2, 12), np.linspace(-0.5, 0.5, 12), timeout=30.0)
    assert at.status == "time_limit" and not at.success
    done = [t for row in at.targets for t in row if t.success]
    assert 2 <= len(done) <= 20
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


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("phc") is None, reason="PHCpack (phc) not installed")
def test_certified_counts_agree_with_the_search():
    h = stability_atlas(BISTABLE, [0.3, 1.1], [0.1, 0.5], method="homotopy", edges=False)
    s = stability_atlas(BISTABLE, [0.3, 1.1], [0.1, 0.5], edges=False)
    assert h.certified.all() and not s.certified.any()
    np.testing.assert_array_equal(h.count, s.count)
    np.testing.assert_array_equal(h.n_stable, s.n_stable)
    np.testing.assert_allclose(h.least_energy, s.least_energy, rtol=1e-10)


# ------------------------------------------------------------------------------ the straight chain in the grid
#: The paper's chain and a grid through the straight chain (dx = 0, dy = 0: held at full reach, where it buckles).
PAPER = to.Manipulator.uniform(4, 1.0, 1.0, 1.0, 1.0)
STRAIGHT_DX, STRAIGHT_DY = [0.0, 0.5, 1.0], [0.0, 0.1, 0.2]
#: Words of the continuation engine that mean nothing to the atlas's user.
INTERNAL_WORDS = ("increasing t", "start nearby", "min_step", "corrector", "singular point of the branch")


def reference_minima(chain: Chain, dx: float, dy: float, n_starts: int) -> list[np.ndarray]:
    """The distinct strict constrained local minima (scipy SLSQP from many starts, the reference model)."""
    rng = np.random.default_rng(7)
    target = chain.target(dx, dy)
    found: list[np.ndarray] = []
    for _ in range(n_starts):
        r = chain.local_min(target, rng.uniform(-0.9, 0.9, chain.n) * chain.limits)
        if r is not None and not any(np.max(np.abs(r[0] - q)) < 1e-6 for q in found):
            found.append(r[0])
    return found


def same_configurations(got, want) -> bool:
    return len(got) == len(want) and all(any(np.max(np.abs(g - w)) < 1e-6 for w in want) for g in got)


def check_straight_column(at) -> None:
    """dx = 0: the straight chain alone at dy = 0 (the only shape reaching that far), beyond reach above it."""
    t00 = at.targets[0][0]
    assert t00.status == "solved" and t00.n_stable == 1 and np.allclose(t00.stable[0].q, 0.0, atol=1e-12)
    assert t00.stable[0].energy == pytest.approx(ref_chain(PAPER).energy(np.zeros(4)), rel=1e-12)
    assert all(not row[0].reachable and row[0].status == "unreachable" for row in at.targets[1:])


def test_an_atlas_through_the_straight_chain_is_complete_and_says_nothing_internal():
    at = stability_atlas(PAPER, STRAIGHT_DX, STRAIGHT_DY)
    assert at.status == "complete" and at.unresolved == () and at.success, at.message
    text = str(at.to_dict())
    assert not [w for w in INTERNAL_WORDS if w in text]
    assert at.n_stable.tolist() == [[1, 2, 2], [0, 2, 2], [0, 2, 2]]
    check_straight_column(at)
    # the straight chain continues into both mirror-image buckled shapes at dx = 0.5: no switch on that edge,
    # the tie at (0.5, 0) is the switch (the symmetry line)
    assert not [c for c in at.crossings if c.edge == ((0, 0), (1, 0))]
    assert any(c.edge == ((1, 0), (1, 0)) and c.method == "tie" for c in at.switches)
    chain = ref_chain(PAPER)
    t = at.targets[0][1]                                  # (0.5, 0): the two mirror-image buckled shapes
    assert same_configurations([e.q for e in t.stable], reference_minima(chain, 0.5, 0.0, 40))


@pytest.mark.slow
def test_every_target_of_the_atlas_through_the_straight_chain_has_the_reference_minima():
    at = stability_atlas(PAPER, STRAIGHT_DX, STRAIGHT_DY)
    check_straight_column(at)
    chain = ref_chain(PAPER)
    for row in at.targets:
        for t in row[1:]:
            want = reference_minima(chain, t.dx, t.dy, 150)
            assert same_configurations([e.q for e in t.stable], want), (t.dx, t.dy)
            eqs = to.find_equilibria(PAPER, t.dx, t.dy)
            assert same_configurations([e.q for e in t.stable], [e.q for e in eqs if e.stable])


def test_an_edge_whose_continuation_fails_is_unresolved_in_the_atlas_words_and_the_rest_is_kept(monkeypatch):
    import tensegrity_opt.analyses.paths.atlas as atlas_module
    from tensegrity_opt.errors import SingularStartError

    def singular(*args, **kwargs):
        raise SingularStartError("start is a singular point of its path", field="start")

    monkeypatch.setattr(atlas_module, "branches_from", singular)
    at = stability_atlas(PAPER, [0.5, 1.0], [0.0, 0.1])
    assert at.status == "partial" and len(at.unresolved) == 4
    assert at.n_stable.tolist() == [[2, 2], [2, 2]] and len(at.switches) == 2      # the targets and the ties
    for _, reason in at.unresolved:
        assert reason.startswith("the stable equilibrium ") and "fold or a branch point" in reason, reason
    assert "4 edge(s) unresolved" in at.message
