"""The stability atlas (``tensegrity_opt.analyses.paths.atlas``) against independent references.

The references (``tests/support/reference_atlas.py``, on ``reference_model`` / ``reference_paths``; no
``tensegrity_opt``) are: a brute-force set of the stable equilibria at every grid target (several hundred
starts run downhill on the tip constraint, SLSQP with the tip equality, Newton polish, reduced Hessian);
every stable branch at either end of every grid edge followed along it by natural-parameter steps (scipy
root on the KKT system), its stability loss bracketed by bisection and located by the extended system; the
Maxwell point of the least branches by brentq on their energy difference.

Chains: a uniform bistable chain (n = 3, K < 0; switches on dy = 0 and folds), the paper's monotonic chain
(n = 4), a heterogeneous bistable chain (a, b, k, L0 per segment), a pre-bent monotonic chain and a pre-bent
bistable chain (asymmetric rest lengths, different per segment: the Maxwell line is off dy = 0 and moves
with dx; switches and folds both present).

Three more small grids at large deflections (``LIMIT_CHAINS``), where stable branches end at joint limits
(located by the reference at ``|q_k| = (1 - 1e-6)(pi - 2 beta_k)``, the documented margin of
``trace_branch``), one with a target inside the links' reach but with no equilibrium inside the range.

Checked per chain, on a small grid (edges = every pair of neighbouring targets):

* targets -- the atlas's n_stable equals the brute-force count, the least energy agrees (1e-8 relative),
  and every stable configuration the atlas lists is one of the brute force's (1e-5 rad, 1e-9 in energy);
* switches -- every atlas "switch" sits on an edge where the brute-force least branch does not continue,
  at the reference Maxwell point (1e-7 in (dx, dy)), with q / q_other the reference's two least branches
  there, at equal reference-model energy, tip on the point (a switch "at a branch end": at the reference's
  end of the least branch, 1e-6); every edge where the least branch does not continue has exactly one
  switch (none missed); a tie crossing at a grid target iff the brute force has a tie there; and (a third
  route) the brute force at the reference Maxwell point itself finds the tie;
* branch ends -- the atlas's "branch_end" crossings of each edge and the reference's stability losses of
  the stable branches from both ends are the same set (1e-6 in position, 1e-5 rad in q, 1e-8 in energy,
  same event): none spurious, none missed; an edge whose ends' brute-force stable counts differ has branch
  ends;
* sensitivity -- the checkers do flag a moved switch, a dropped / moved / invented branch end and a wrong
  count (planted in copies of a real atlas), so agreement above is not vacuous.
"""

from __future__ import annotations

import dataclasses
import functools

import numpy as np
import pytest
import reference_atlas as RA

from tensegrity_opt import Manipulator, Segment

try:
    from tensegrity_opt import stability_atlas
except ImportError:                              # not exported at top level yet
    from tensegrity_opt.analyses.paths.atlas import stability_atlas

# (a, b, k1, k2, L1_0, L2_0) per segment; the grid (dx values, dy values)
CHAINS = {
    # K = k (b L0 - 2 (b^2 - a^2)) = -0.5: bistable segments (wells at +-1.68 rad)
    "bistable3": ([(0.5, 1.0, 1.0, 1.0, 1.0, 1.0)] * 3,
                  [0.2, 0.5, 0.8, 1.1], [-0.6, -0.2, 0.2, 0.6]),
    # the paper's chain (K = 1)
    "paper4": ([(1.0, 1.0, 1.0, 1.0, 1.0, 1.0)] * 4,
               [0.2, 0.6, 1.0, 1.4], [-0.45, -0.1, 0.3]),
    # heterogeneous: a, b, k, L0 all differ per segment (all three bistable)
    "hetero3": ([(0.5, 1.0, 1.0, 1.0, 1.0, 1.0), (0.8, 1.2, 1.5, 1.5, 1.3, 1.3), (0.55, 0.9, 0.8, 0.8, 0.95, 0.95)],
                [0.3, 0.6, 0.9, 1.2], [-0.5, -0.15, 0.25]),
    # pre-bent monotonic: asymmetric rest lengths, different per segment -> Maxwell line at dy ~ +0.03
    "pre_bent3": ([(1.0, 1.0, 1.0, 1.0, 0.99, 1.0), (1.0, 1.0, 1.0, 1.0, 1.0, 1.006), (1.0, 1.0, 1.0, 1.0, 1.004, 1.0)],
                  [0.3, 0.75, 1.2], [-0.5, -0.1667, 0.1667, 0.5]),
    # pre-bent bistable: Maxwell line at dy = 0.07 .. 0.16 (moving with dx), folds on the dx edges
    "pre_bent_bistable3": ([(0.5, 1.0, 1.0, 1.0, 0.97, 1.0), (0.5, 1.0, 1.0, 1.0, 1.0, 1.01),
                            (0.5, 1.0, 1.0, 1.0, 1.0, 0.99)],
                           [0.3, 0.6, 0.9, 1.2], [-0.5, -0.1667, 0.1667, 0.5]),
}
NAMES = sorted(CHAINS)
# Large deflections, where stable branches end at joint limits (one edge or two each):
LIMIT_CHAINS = {
    # a joint limit just past the edge's far end (dx = 2.3115 > 2.3, and 2.9162 > 2.9): the atlas's edge
    # continuation runs past t_max into the event (see the report of these tests)
    "bistable3_limit_past_end": (CHAINS["bistable3"][0], [1.7, 2.3, 2.9], [0.0]),
    "pre_bent3_limit_past_end": (CHAINS["pre_bent3"][0], [2.3, 2.9], [-2.0]),
    # (2.9, 0) is within the links' reach but has no equilibrium inside the physical range (the homotopy
    # certifies 0): the stable branches from (2.3, 0) end at joint limits on the edge
    "pre_bent3_empty_target": (CHAINS["pre_bent3"][0], [2.3, 2.9], [0.0]),
}
CHAINS.update(LIMIT_CHAINS)
LIMIT_NAMES = sorted(LIMIT_CHAINS)

# tolerances (deflections are O(1); energies O(1..5))
POS_SWITCH = 1e-7
POS_FOLD = 1e-6
Q_TOL = 1e-5
E_REL = 1e-8
#: A joint-limit branch end is where ``|q_i| = (1 - 1e-6)(pi - 2 beta_i)``: ``branches.LIMIT_MARGIN``, documented
#: in ``trace_branch``; the reference follows its branches in the range narrowed by the same margin.
LIMIT_MARGIN = 1e-6


# --------------------------------------------------------------------------- cached computations
@functools.cache
def manipulator(name) -> Manipulator:
    return Manipulator([Segment(a, b, (k1, k2), (l1, l2)) for a, b, k1, k2, l1, l2 in CHAINS[name][0]])


@functools.cache
def ref_chain(name) -> RA.Chain:
    return RA.Chain.from_segments(CHAINS[name][0])


@functools.cache
def atlas(name):
    _, dx, dy = CHAINS[name]
    return stability_atlas(manipulator(name), dx, dy)


@functools.cache
def brute(name) -> dict:
    """(i, j) -> the brute-force stable equilibria at (dx[i], dy[j])."""
    _, dx, dy = CHAINS[name]
    c = ref_chain(name)
    return {(i, j): RA.stable_equilibria(c, x, y) for i, x in enumerate(dx) for j, y in enumerate(dy)}


def grid_edges(name):
    _, dx, dy = CHAINS[name]
    for j in range(len(dy)):
        for i in range(len(dx)):
            for (i2, j2) in ((i + 1, j), (i, j + 1)):
                if i2 < len(dx) and j2 < len(dy):
                    yield (i, j), (i2, j2)


@functools.cache
def edge_refs(name) -> dict:
    """((iA, jA), (iB, jB)) -> RA.EdgeReference."""
    _, dx, dy = CHAINS[name]
    c, S = ref_chain(name), brute(name)
    out = {}
    for (i, j), (i2, j2) in grid_edges(name):
        out[(i, j), (i2, j2)] = RA.edge_reference(c, (dx[i], dy[j]), (dx[i2], dy[j2]), S[i, j], S[i2, j2],
                                                  limit_margin=LIMIT_MARGIN)
    return out


# --------------------------------------------------------------------------- the checkers
def check_targets(at, chain, S):
    """Problems (strings) and the largest errors of the per-target counts / least energies."""
    problems, err = [], {"least_energy_rel": 0.0, "stable_q": 0.0}
    for (i, j), ref in S.items():
        t = at.targets[j][i]
        where = f"target (i={i}, j={j}) = (dx={t.dx}, dy={t.dy})"
        if not t.success:
            problems.append(f"{where}: atlas error {t.error}")
            continue
        if at.n_stable[j, i] != len(ref):
            problems.append(f"{where}: atlas n_stable {at.n_stable[j, i]} != brute force {len(ref)} "
                            f"(brute-force energies {[e.energy for e in ref]}, atlas {[e.energy for e in t.stable]})")
            continue
        if not ref:
            if np.isfinite(at.least_energy[j, i]):
                problems.append(f"{where}: atlas least energy without a stable equilibrium")
            continue
        rel = abs(at.least_energy[j, i] - ref[0].energy) / max(1.0, abs(ref[0].energy))
        err["least_energy_rel"] = max(err["least_energy_rel"], rel)
        if rel > E_REL:
            problems.append(f"{where}: least energy atlas {at.least_energy[j, i]!r} vs brute force {ref[0].energy!r}")
        for e in t.stable:                       # each atlas stable configuration is a brute-force one
            d = [np.max(np.abs(np.asarray(e.q) - r.q)) for r in ref]
            k = int(np.argmin(d))
            err["stable_q"] = max(err["stable_q"], d[k])
            if d[k] > Q_TOL or abs(chain.energy(e.q) - ref[k].energy) > 1e-9 * max(1.0, ref[k].energy):
                problems.append(f"{where}: atlas stable q {np.asarray(e.q)} is no brute-force equilibrium "
                                f"(nearest {ref[k].q}, {d[k]:.2e} rad)")
    return problems, err


def _point(at, ij):
    i, j = ij
    return np.array([at.dx[i], at.dy[j]])


def check_switches(at, chain, S, E):
    """Every atlas switch at the reference Maxwell point of its edge; none missed."""
    problems, err = [], {"switch_pos": 0.0, "switch_energy_rel": 0.0, "switch_gap_rel": 0.0, "switch_q": 0.0}
    by_edge = {}
    for c in at.switches:
        by_edge.setdefault(tuple(map(tuple, c.edge)), []).append(c)
    for edge, cs in by_edge.items():
        A, B = edge
        if A == B:                                   # a tie at a grid point
            ref = S[A]
            scale = float(np.max(chain.k1) * (np.sum(chain.L10) + np.sum(chain.L20)) ** 2)
            if len(ref) < 2 or ref[1].energy - ref[0].energy > 1e-9 * scale:
                problems.append(f"tie switch at target {A}: the brute force has no tie "
                                f"({[e.energy for e in ref]})")
            continue
        ref = E.get(edge)
        if ref is None:
            problems.append(f"switch on {edge}: not a grid edge")
            continue
        if len(cs) != 1:
            problems.append(f"edge {edge}: {len(cs)} switch crossings")
        c = cs[0]
        if ref.least_continues or ref.tie:
            gap = ("" if c.q_other is None else
                   f", energy gap of its two configurations {chain.energy(c.q) - chain.energy(c.q_other):.1e}, "
                   f"max |q - q_other| {np.max(np.abs(np.asarray(c.q) - np.asarray(c.q_other))):.1e} rad")
            problems.append(f"switch on {edge} at ({c.dx}, {c.dy}), fraction {c.fraction:.6f}, method {c.method}{gap}: "
                            f"the reference least branch continues from {A} to {B} (tie at an end: {ref.tie}); "
                            f"spurious")
            continue
        if ref.switch_method is None:
            problems.append(f"switch on {edge} at ({c.dx}, {c.dy}) method {c.method}: the reference least branch "
                            f"does not continue but the reference finds no switch point")
            continue
        if c.method != ref.switch_method:
            problems.append(f"switch on {edge} at ({c.dx}, {c.dy}): method {c.method} vs reference "
                            f"{ref.switch_method} at {tuple(ref.switch_point)}")
            continue
        if c.method == "branch_end":             # at a branch end: compare with that reference fold
            pos = float(np.max(np.abs(np.array([c.dx, c.dy]) - ref.switch_point)))
            err["switch_pos"] = max(err["switch_pos"], pos)
            if pos > POS_FOLD:
                problems.append(f"switch (at a branch end) on {edge}: atlas ({c.dx!r}, {c.dy!r}) vs reference "
                                f"{tuple(ref.switch_point)} ({pos:.2e})")
            continue
        mw = ref.maxwell
        pos = float(np.max(np.abs(np.array([c.dx, c.dy]) - mw.point)))
        err["switch_pos"] = max(err["switch_pos"], pos)
        if pos > POS_SWITCH:
            problems.append(f"switch on {edge}: atlas ({c.dx!r}, {c.dy!r}) fraction {c.fraction!r} vs reference "
                            f"{tuple(mw.point)} fraction {mw.fraction!r} ({pos:.2e})")
        erel = abs(c.energy - mw.energy) / max(1.0, abs(mw.energy))
        err["switch_energy_rel"] = max(err["switch_energy_rel"], erel)
        if erel > E_REL:
            problems.append(f"switch on {edge}: energy atlas {c.energy!r} vs reference {mw.energy!r}")
        if c.q_other is None:
            problems.append(f"switch on {edge}: no q_other")
            continue
        eA, eB = chain.energy(c.q), chain.energy(c.q_other)      # the reference model's energies
        gap = abs(eA - eB) / max(1.0, abs(eA))
        err["switch_gap_rel"] = max(err["switch_gap_rel"], gap)
        if gap > E_REL:
            problems.append(f"switch on {edge}: the atlas's two configurations differ in energy by {eA - eB:.3e}")
        target = chain.target(c.dx, c.dy)
        for q in (c.q, c.q_other):
            if np.max(np.abs(chain.tip(q) - target)) > 1e-8:
                problems.append(f"switch on {edge}: a configuration's tip {chain.tip(q)} is not at {target}")
        dq = max(np.max(np.abs(np.asarray(c.q) - mw.qA)), np.max(np.abs(np.asarray(c.q_other) - mw.qB)))
        err["switch_q"] = max(err["switch_q"], dq)
        if dq > Q_TOL:
            problems.append(f"switch on {edge}: configurations differ from the reference's least branches by "
                            f"{dq:.2e} rad (atlas {c.q}, {c.q_other}; reference {mw.qA}, {mw.qB})")
    scale = float(np.max(chain.k1) * (np.sum(chain.L10) + np.sum(chain.L20)) ** 2)
    for ij, ref in S.items():                    # a brute-force tie for the least energy: a tie crossing there
        if len(ref) > 1 and ref[1].energy - ref[0].energy <= 1e-9 * scale and (ij, ij) not in by_edge:
            problems.append(f"target {ij}: the brute force has a tie for the least energy "
                            f"({ref[0].energy!r}, {ref[1].energy!r}) but the atlas no tie switch there")
    for edge, ref in E.items():                  # none missed
        if not ref.least_continues and not ref.tie and edge not in by_edge:
            where = ref.switch_point
            problems.append(f"edge {edge}: the reference least branch switches (Maxwell point {where}) but the "
                            f"atlas has no switch there")
    return problems, err


def check_branch_ends(at, chain, S, E):
    """The atlas's branch ends of each edge == the reference's stability losses (both directions)."""
    problems, err = [], {"fold_pos": 0.0, "fold_q": 0.0, "fold_energy_rel": 0.0}
    by_edge = {}
    for c in at.branch_ends:
        by_edge.setdefault(tuple(map(tuple, c.edge)), []).append(c)
    for edge in set(by_edge) | set(E):
        ref = E.get(edge)
        if ref is None:
            problems.append(f"branch ends on {edge}: not a grid edge")
            continue
        mine = list(by_edge.get(edge, []))
        theirs = list(ref.folds)
        for f in list(theirs):
            if f.kind == "reach":                      # the target leaves the workspace: not a branch end
                theirs.remove(f)
                continue
            # the same event: near in position and in q (mirror images on dy = 0 share the position)
            cand = [(float(np.max(np.abs(np.array([c.dx, c.dy]) - f.point))),
                     float(np.max(np.abs(np.asarray(c.q) - f.q))), k) for k, c in enumerate(mine)]
            cand = [x for x in cand if x[0] < 1e-3 and x[1] < 1e-2]
            if not cand:
                continue
            pos, dq, k = min(cand, key=lambda x: x[0] + x[1])
            c = mine.pop(k)
            theirs.remove(f)
            err["fold_pos"] = max(err["fold_pos"], pos)
            err["fold_q"] = max(err["fold_q"], dq)
            erel = abs(c.energy - f.energy) / max(1.0, abs(f.energy))
            err["fold_energy_rel"] = max(err["fold_energy_rel"], erel)
            kind_ref = {"bifurcation": "branch_point"}.get(f.kind, f.kind)
            if pos > POS_FOLD or dq > Q_TOL or erel > E_REL or c.event != kind_ref:
                problems.append(f"branch end on {edge}: atlas ({c.dx!r}, {c.dy!r}) {c.event} vs reference "
                                f"{tuple(f.point)} {f.kind} (position {pos:.2e}, q {dq:.2e} rad, energy {erel:.1e})")
        for c in mine:
            problems.append(f"branch end on {edge} at ({c.dx}, {c.dy}), fraction {c.fraction:.6f} ({c.event}, "
                            f"q={c.q}): no reference branch loses stability on this edge there (brute-force "
                            f"n_stable {len(ref.stable_A)} -> {len(ref.stable_B)}); spurious")
        for f in theirs:
            problems.append(f"edge {edge}: the reference branch from {f.side} (q={f.q_start}) loses stability at "
                            f"{tuple(f.point)} ({f.kind}); the atlas has no branch end there (missed)")
        nA, nB = len(ref.stable_A), len(ref.stable_B)
        if nA != nB and nA and nB and not by_edge.get(edge):
            problems.append(f"edge {edge}: brute-force n_stable {nA} -> {nB} but no atlas branch end")
        if nA != nB and not [f for f in ref.folds if f.kind != "reach"] and nA and nB:
            problems.append(f"edge {edge}: brute-force n_stable {nA} -> {nB} but no reference fold (reference bug)")
    return problems, err


def all_checks(name, at=None):
    at = atlas(name) if at is None else at
    c, S, E = ref_chain(name), brute(name), edge_refs(name)
    out, errs = [], {}
    for f in (check_targets,):
        p, e = f(at, c, S)
        out += p
        errs.update(e)
    for f in (check_switches, check_branch_ends):
        p, e = f(at, c, S, E)
        out += p
        errs.update(e)
    return out, errs


# --------------------------------------------------------------------------- the tests
@pytest.mark.slow
@pytest.mark.parametrize("name", NAMES + LIMIT_NAMES)
def test_atlas_complete(name):
    at = atlas(name)
    assert at.status == "complete", (at.status, at.unresolved, [t.error for row in at.targets for t in row])


@pytest.mark.slow
@pytest.mark.parametrize("name", NAMES + LIMIT_NAMES)
def test_counts_and_least_energy_match_brute_force(name):
    problems, _ = check_targets(atlas(name), ref_chain(name), brute(name))
    assert not problems, "\n".join(problems)


@pytest.mark.slow
@pytest.mark.parametrize("name", NAMES + LIMIT_NAMES)
def test_switches_match_reference_maxwell_points(name):
    problems, _ = check_switches(atlas(name), ref_chain(name), brute(name), edge_refs(name))
    assert not problems, "\n".join(problems)


@pytest.mark.slow
@pytest.mark.parametrize("name", NAMES + LIMIT_NAMES)
def test_branch_ends_match_reference_folds(name):
    problems, _ = check_branch_ends(atlas(name), ref_chain(name), brute(name), edge_refs(name))
    assert not problems, "\n".join(problems)


@pytest.mark.slow
def test_the_grids_exercise_switches_and_folds():
    """The chosen grids are not vacuous: switches everywhere, folds on the multistable chains, a switch
    line off dy = 0 on the pre-bent chains, and one chain with both a switch and a fold."""
    n_sw = {n: sum(not r.least_continues and not r.tie for r in edge_refs(n).values()) for n in NAMES}
    n_fold = {n: sum(len(r.folds) for r in edge_refs(n).values()) for n in NAMES}
    assert all(v >= 2 for v in n_sw.values()), n_sw
    assert n_fold["bistable3"] >= 6 and n_fold["hetero3"] >= 2 and n_fold["pre_bent_bistable3"] >= 6, n_fold
    for n in ("pre_bent3", "pre_bent_bistable3"):
        ys = [r.maxwell.point[1] for r in edge_refs(n).values() if r.maxwell is not None]
        assert ys and min(abs(y) for y in ys) > 0.02, (n, ys)


@pytest.mark.slow
def test_brute_force_sees_the_tie_at_reference_maxwell_points():
    """Third route to a switch: at the reference Maxwell point the brute force itself finds two stable
    equilibria of equal least energy -- the two branches' configurations."""
    for name in ("pre_bent_bistable3", "hetero3"):
        c = ref_chain(name)
        refs = [r for r in edge_refs(name).values() if r.maxwell is not None][:1]
        assert refs
        for r in refs:
            mw = r.maxwell
            S = RA.stable_equilibria(c, *mw.point)
            assert len(S) >= 2
            assert S[1].energy - S[0].energy < 1e-10 * max(1.0, S[0].energy)
            assert S[0].energy == pytest.approx(mw.energy, rel=1e-10)
            got = sorted(min(np.max(np.abs(e.q - q)) for e in S[:2]) for q in (mw.qA, mw.qB))
            assert got[-1] < 1e-6


@pytest.mark.slow
def test_reference_fold_routes_agree():
    """The reference folds by two routes: the bracket + extended system used above, and
    reference_paths.fold_in_displacement (its own natural path, bisection to 1e-12, extended system and the
    joint-angle parametrisation)."""
    name = "pre_bent_bistable3"
    c = ref_chain(name)
    folds = [f for r in edge_refs(name).values() for f in r.folds][:2]
    assert folds
    for f in folds:
        assert f.kind == "fold" and f.converged and abs(f.lam_min) < 1e-9
        r = next(r for r in edge_refs(name).values() if any(g is f for g in r.folds))
        g = RA.edge_fold(c, f.q_start, r.a, r.b, f.side, route="fold_in_displacement")
        assert g is not None and g.kind == "fold"
        assert np.max(np.abs(g.point - f.point)) < 1e-9
        assert g.u_coordinate == pytest.approx(f.u, abs=1e-7)


@pytest.mark.slow
def test_checkers_flag_planted_errors():
    """The comparison is sensitive: on copies of a real atlas (the pre-bent bistable chain, switches and
    folds both present) a switch moved by 1e-6 of its edge, a branch end dropped, one moved by 1e-5, one
    invented, a switch dropped, and a count changed are each reported."""
    name = "pre_bent_bistable3"
    at = atlas(name)
    assert all_checks(name, at)[0] == []
    assert at.switches and at.branch_ends

    def mutated(fn):
        return all_checks(name, fn(at))[0]

    def with_crossing(a2, c, new):
        """``a2`` with the crossing ``c`` replaced by ``new`` (None: dropped); results are immutable."""
        k = next(i for i, x in enumerate(a2.crossings) if x is c)
        rest = a2.crossings[:k] + a2.crossings[k + 1:]
        return dataclasses.replace(a2, crossings=rest if new is None else rest[:k] + (new,) + rest[k:])

    def move_switch(a2):
        c = a2.switches[0]
        (ia, ja), (ib, jb) = c.edge
        step = 1e-6 * (_point(a2, (ib, jb)) - _point(a2, (ia, ja)))
        return with_crossing(a2, c, dataclasses.replace(c, dx=c.dx + step[0], dy=c.dy + step[1]))

    def drop(kind):
        def f(a2):
            return with_crossing(a2, next(c for c in a2.crossings if c.kind == kind), None)
        return f

    def move_fold(a2):
        c = a2.branch_ends[0]
        return with_crossing(a2, c, dataclasses.replace(c, dx=c.dx + 1e-5))

    def invent_fold(a2):
        c = a2.branch_ends[0]
        edge = ((0, 0), (1, 0)) if tuple(map(tuple, c.edge)) != ((0, 0), (1, 0)) else ((0, 0), (0, 1))
        return dataclasses.replace(a2, crossings=a2.crossings + (dataclasses.replace(c, edge=edge),))

    def change_count(a2):
        t = a2.targets[1][2]
        row = a2.targets[1][:2] + (dataclasses.replace(t, n_stable=t.n_stable + 1),) + a2.targets[1][3:]
        return dataclasses.replace(a2, targets=a2.targets[:1] + (row,) + a2.targets[2:])

    for fn in (move_switch, drop("switch"), drop("branch_end"), move_fold, invent_fold, change_count):
        assert mutated(fn), fn
