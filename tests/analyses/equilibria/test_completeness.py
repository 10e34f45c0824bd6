"""Completeness of the global searches on multistable chains, against the homotopy.

The reference sets in ``tests/data/homotopy_oracle.json`` were written by
``python -m benchmarks.homotopy_oracle``: PHCpack's polyhedral homotopy on the polynomial KKT
system (every isolated complex root; only certified solves kept), each real root inside the range
polished and classified by the *independent* reference model (``reference_model.py``, which does not
import the library). Random chains of every multistable family (bistable, heterogeneous, mixed,
asymmetric preloads), n = 2..5, targets over the workspace, dy != 0 in most. The search under test
must find every one of those equilibria with the same Morse index, and ``solve_equilibrium`` the
least-energy stable one.

The live homotopy tests need PHCpack's ``phc`` (Debian package ``phcpack``); they are skipped
without it, except in CI (``TENSEGRITY_REQUIRE_PHC=1``, set by ``.ci/run``, which installs it).
"""

from __future__ import annotations

import json
import os
import stat
from pathlib import Path

import numpy as np
import pytest
import reference_model as ref

import tensegrity_opt as to
from tensegrity_opt.numerics.homotopy import homotopy_available

ORACLE = Path(__file__).resolve().parents[3] / "tests" / "data" / "homotopy_oracle.json"
DATA = json.loads(ORACLE.read_text())["cases"]
SAME = 1e-6

needs_phc = pytest.mark.skipif(not homotopy_available() and os.environ.get("TENSEGRITY_REQUIRE_PHC") != "1",
                               reason="PHCpack's phc is not installed (apt-get install phcpack)")


def _case_id(c) -> str:
    return f"n{len(c['manipulator']['segments'])}-{c['family']}-dx{c['dx']:.3f}-dy{c['dy']:+.3f}"


def _chain(m: to.Manipulator) -> ref.Chain:
    return ref.Chain(m.a, m.b, m.k1, m.k2, m.L1_0, m.L2_0)


def _well(a, b, k, L0) -> float:
    """The positive unloaded well of a bistable symmetric segment, from the reference model's gradient."""
    one = ref.Chain.uniform(1, a, b, k, L0)
    qs = np.linspace(1e-6, 0.999 * one.limits[0], 20001)
    g = np.array([one.grad(np.array([q]))[0] for q in qs])
    i = int(np.flatnonzero((g[:-1] < 0) & (g[1:] >= 0))[0])
    return float(qs[i])


def _least_descent(chain: ref.Chain, target, starts) -> float:
    """Least energy of the reference model's SLSQP minima from ``starts``."""
    best = np.inf
    for q0 in starts:
        r = chain.local_min(target, q0)
        if r is not None:
            best = min(best, chain.energy(r[0]))
    return best


def test_oracle_covers_the_families():
    ns = [len(c["manipulator"]["segments"]) for c in DATA]
    assert len(DATA) >= 95 and set(ns) >= {2, 3, 4}
    assert {c["family"] for c in DATA} == {"bistable", "heterogeneous", "mixed", "asymmetric"}
    assert sum(c["dy"] != 0.0 for c in DATA) > len(DATA) / 2
    for c in DATA:                               # every chain is multistable
        assert not to.Manipulator.from_dict(c["manipulator"]).monotonic


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("case", DATA, ids=_case_id)
def test_search_finds_every_equilibrium_the_homotopy_finds(case):
    m = to.Manipulator.from_dict(case["manipulator"])
    got = to.find_equilibria(m, case["dx"], case["dy"])
    assert got.method == "search" and not got.certified
    for e in case["equilibria"]:
        match = [g for g in got if np.max(np.abs(g.q - np.array(e["q"]))) < SAME]
        assert match, f"missed an equilibrium of Morse index {e['morse_index']}: q = {e['q']}"
        assert match[0].morse_index == e["morse_index"]
        assert match[0].energy == pytest.approx(e["energy"], rel=1e-10, abs=1e-12)
    # and nothing else: every extra point must be a genuine equilibrium the homotopy also has
    assert len(got) == len(case["equilibria"])


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("case", [c for c in DATA if any(e["morse_index"] == 0 for e in c["equilibria"])],
                         ids=_case_id)
def test_solve_equilibrium_is_the_least_energy_stable_one(case):
    m = to.Manipulator.from_dict(case["manipulator"])
    e_min = min(e["energy"] for e in case["equilibria"] if e["morse_index"] == 0)
    eq = to.solve_equilibrium(m, case["dx"], case["dy"])
    assert eq.stable
    assert eq.energy == pytest.approx(e_min, rel=1e-9, abs=1e-12)


# ----------------------------------------------------------------------------- chains where a search fell short
def test_bistable_n8_least_energy():
    """The least-energy stable equilibrium has E = 5.04003 (independent brute force), not a higher one (5.04349)."""
    m = to.Manipulator.uniform(8, a=0.6, b=1, k=1, L0=1.2)
    eq = to.solve_equilibrium(m, 2.0, 0.0)
    assert eq.energy == pytest.approx(5.04003, abs=6e-6)
    chain = _chain(m)                            # the point is a clearly stable equilibrium of the reference model
    target = chain.target(2.0, 0.0)
    q, F, ok = chain.newton_kkt(target, eq.q, eq.force)
    assert ok and np.max(np.abs(q - eq.q)) < 1e-8
    assert np.min(chain.reduced_eigs(q, F, fd=False)) > 1e-6


@pytest.mark.slow
def test_bistable_n8_least_energy_vs_reference_descent():
    """The reference model's SLSQP from every combination of the segments' wells finds nothing lower."""
    m = to.Manipulator.uniform(8, a=0.6, b=1, k=1, L0=1.2)
    chain = _chain(m)
    eq = to.solve_equilibrium(m, 2.0, 0.0)
    rng = np.random.default_rng(5)
    starts = _well(0.6, 1, 1, 1.2) * rng.choice([-1.0, 1.0], (60, m.n))
    best = _least_descent(chain, chain.target(2.0, 0.0), starts)
    assert np.isfinite(best) and eq.energy <= best + 1e-9


def _verified_morse(chain: ref.Chain, target, e) -> int:
    """The reference model confirms ``e`` as an equilibrium in range and returns its Morse index."""
    q, F, ok = chain.newton_kkt(target, e.q, e.force)
    assert ok and chain.in_range(q) and np.max(np.abs(q - e.q)) < 1e-8
    return int(np.sum(chain.reduced_eigs(q, F, fd=False) < 0))


def test_bistable_n5_every_equilibrium():
    """At least 52 equilibria exist (a short search finds 22). A Morse-3 maximum an independent brute force (4000
    reference-model starts) found at q = [0.147852, 0.355537, -0.960061, 0.309796, 0.061975] is among them."""
    m = to.Manipulator.uniform(5, 0.6, 1, 1, 1.2)
    eqs = to.find_equilibria(m, 0.5)
    assert len(eqs) >= 52
    chain = _chain(m)
    target = chain.target(0.5)
    q = np.array([0.147852, 0.355537, -0.960061, 0.309796, 0.061975])
    for sign in (1.0, -1.0):                     # and its mirror image
        e = min(eqs, key=lambda e: np.max(np.abs(e.q - sign * q)))
        assert np.max(np.abs(e.q - sign * q)) < 1e-5
        assert e.morse_index == _verified_morse(chain, target, e) == 3
    assert len({round(e.energy, 8) for e in eqs}) >= 26                 # mirror pairs share an energy


def test_monotonic_n6_maxima_are_found():
    """A Morse-4 maximum and its mirror on a monotonic chain (easily missed) are found."""
    m = to.Manipulator.uniform(6, a=0.7, b=1.25, k=2.2, L0=2.1)
    eqs = to.find_equilibria(m, 0.5)
    chain = _chain(m)
    top = [e for e in eqs if e.morse_index == 4]
    assert len(top) == 2 and np.max(np.abs(top[0].q + top[1].q)) < 1e-8
    for e in top:
        assert _verified_morse(chain, chain.target(0.5), e) == 4



def _monotonic_chain(rng, n):
    """A random chain of monotonic segments (condition (4) with margin; asymmetric preloads in half of them)."""
    segs = []
    for _ in range(n):
        a, b = rng.uniform(0.4, 0.8), rng.uniform(0.8, 1.2)
        base = max(2.0 * (b * b - a * a) / b, 0.0)
        if rng.random() < 0.5:
            segs.append(to.Segment(a, b, (rng.uniform(0.5, 2), rng.uniform(0.5, 2)),
                                   (base + rng.uniform(0.05, 1.2), base + rng.uniform(0.05, 1.2))))
        else:
            segs.append(to.Segment(a, b, rng.uniform(0.5, 2), base + rng.uniform(0.05, 1.2)))
    return to.Manipulator(segs)


@needs_phc
@pytest.mark.parametrize("seed, n", [(0, 3), (2, 2)])
def test_search_equals_homotopy_on_monotonic_chains(seed, n):
    """Short monotonic chains (whose search skips IPOPT's descents when Newton finds equilibria:
    ``MONOTONIC_NO_DESCENT_MAX_N``) at large deflections, dy != 0: the search's set is the certified homotopy's,
    with the same Morse indices."""
    rng = np.random.default_rng(700 + seed)
    while True:
        m = _monotonic_chain(rng, n)
        L = m.straight_length
        dx, dy = rng.uniform(0.3, 0.7) * L, rng.uniform(-0.3, 0.3) * L
        if not m.monotonic:
            continue
        try:
            m.check_reachable(dx, dy)
        except ValueError:
            continue
        hom = to.find_equilibria(m, dx, dy, method="homotopy")
        if len(hom):
            break
    assert hom.certified
    search = to.find_equilibria(m, dx, dy)
    assert len(search) == len(hom)
    for e in hom:
        f = min(search, key=lambda f: np.max(np.abs(e.q - f.q)))
        assert np.max(np.abs(e.q - f.q)) < 1e-8 and f.morse_index == e.morse_index

@pytest.mark.slow
@needs_phc
def test_bistable_n4_least_energy_vs_homotopy():
    """The least-energy stable equilibrium has E = 3.21362, not a higher stable one (3.21975)."""
    m = to.Manipulator.uniform(4, a=0.55, b=1, k=1.5, L0=1.25)
    hom = to.find_equilibria(m, 1.0, 0.3, method="homotopy")
    assert hom.certified
    e_min = min(e.energy for e in hom if e.stable)
    assert e_min == pytest.approx(3.21362, abs=6e-6)
    assert to.solve_equilibrium(m, 1.0, 0.3).energy == pytest.approx(e_min, rel=1e-10)
    cert = to.solve_equilibrium(m, 1.0, 0.3, method="homotopy")
    assert cert.status == "certified" and cert.solver.status == "homotopy (certified)"
    assert cert.energy == pytest.approx(e_min, rel=1e-12)


@pytest.mark.slow
def test_bistable_curve_stays_on_the_least_energy_branch():
    """The curve stays on the least-energy branch (not on a higher one, as 24 points could). At every point the
    curve's energy equals the least stable energy of the reference model's descent from all well patterns."""
    m = to.Manipulator.uniform(5, 0.6, 1, 1, 1.2)
    dxs = np.linspace(0.02, 4, 40)
    c = to.force_deflection(m, dxs)
    switches = [j for j in c.jumps if j.kind in ("snap", "switch")]
    assert len(switches) == 5 and len(c.jumps) == 5 and c.success
    assert switches[0].dx_before > 0.6 and switches[-1].dx_after < 2.3     # "5 times between 0.63 and 2.27"
    chain = _chain(m)
    w = _well(0.6, 1, 1, 1.2)
    patterns = np.array(np.meshgrid(*[[-w, w]] * m.n, indexing="ij")).reshape(m.n, -1).T
    for i in (5, 16, 18, 20, 30):
        best = _least_descent(chain, chain.target(dxs[i]), patterns)
        assert c.energy[i] <= best + 1e-8 * max(1.0, abs(best)), dxs[i]


# ----------------------------------------------------------------------------- the homotopy itself
@pytest.mark.slow
@needs_phc
def test_homotopy_paper_chain_six_equilibria_certified():
    m = to.Manipulator.uniform(4)
    eqs = to.find_equilibria(m, 0.1, method="homotopy")
    assert eqs.method == "homotopy" and eqs.certified and eqs.failed_paths == 0 and eqs.status == "certified"
    assert eqs.paths == 456                    # mixed volume of the Laurent system for a = b
    assert [e.kind for e in eqs] == ["minimum", "minimum", "saddle", "saddle", "maximum", "maximum"]
    assert [e.shape for e in eqs] == ["U", "U", "ZU", "ZU", "Z", "Z"]
    assert abs(eqs[0].fy) == pytest.approx(0.02579, abs=1e-5)          # docs/model.md
    search = to.find_equilibria(m, 0.1)
    assert len(search) == 6
    for e in eqs:
        assert min(np.max(np.abs(e.q - s.q)) for s in search) < 1e-9


@pytest.mark.slow
@needs_phc
@pytest.mark.parametrize("seed", range(6))
def test_homotopy_matches_independent_brute_force(seed):
    """Random multistable n = 3 chains: the homotopy's set equals the reference model's Newton from 600
    random starts (independent code), with the same Morse indices."""
    rng = np.random.default_rng(300 + seed)
    while True:
        segs = [to.Segment(rng.uniform(0.4, 0.8), rng.uniform(0.8, 1.2), (rng.uniform(0.5, 2), rng.uniform(0.5, 2)),
                           (rng.uniform(0.3, 0.9), rng.uniform(0.3, 0.9))) for _ in range(3)]
        m = to.Manipulator(segs)
        dx, dy = rng.uniform(0.1, 0.4) * m.straight_length, rng.uniform(-0.2, 0.2) * m.straight_length
        if m.monotonic:
            continue
        try:
            m.check_reachable(dx, dy)
        except ValueError:
            continue
        hom = to.find_equilibria(m, dx, dy, method="homotopy")
        if len(hom):
            break
    assert hom.certified
    chain = _chain(m)
    brute = ref.all_equilibria(chain, dx, dy, n_starts=600, seed=seed)
    assert len(brute) == len(hom)
    for q, F in brute:
        e = min(hom, key=lambda e: np.max(np.abs(e.q - q)))
        assert np.max(np.abs(e.q - q)) < 1e-8
        assert e.morse_index == int(np.sum(chain.reduced_eigs(q, F, fd=False) < 0))


@needs_phc
def test_homotopy_two_segments_closed_form():
    """n = 2: the tip fixes both joints (elbow up / down), so exactly those two configurations."""
    m = to.Manipulator([to.Segment(0.5, 1.0, 1.0, 0.6), to.Segment(0.7, 1.1, (1.0, 1.5), (0.8, 0.7))])
    dx, dy = 0.6, 0.4
    eqs = to.find_equilibria(m, dx, dy, method="homotopy")
    assert eqs.certified and eqs.paths == 8
    x, y = m.target(dx, dy) - np.array([m.base_length, 0.0])
    l1, l2 = m.link_lengths
    c2 = (x * x + y * y - l1 * l1 - l2 * l2) / (2 * l1 * l2)
    expected = []
    for s in (1.0, -1.0):
        q2 = s * np.arccos(c2)
        q1 = np.arctan2(y, x) - np.arctan2(l2 * np.sin(q2), l1 + l2 * np.cos(q2))
        if abs(q1) < m.joint_limits[0] and abs(q2) < m.joint_limits[1]:
            expected.append(np.array([q1, q2]))
    assert len(eqs) == len(expected) >= 1
    for q in expected:
        assert min(np.max(np.abs(e.q - q)) for e in eqs) < 1e-10


def _fake_phc(tmp_path, report: str) -> str:
    """A stand-in ``phc`` that writes ``report`` as its output file (the last argument)."""
    out = tmp_path / "report.txt"
    out.write_text(report)
    exe = tmp_path / "phc"
    exe.write_text(f"#!/bin/sh\nfor last; do :; done\ncp '{out}' \"$last\"\n")
    exe.chmod(exe.stat().st_mode | stat.S_IEXEC)
    return str(exe)


_ROOT = """solution {k} :    start residual :  1.0E-15   #iterations : 1   success
t :  1.00000000000000E+00   0.00000000000000E+00
m : 1
the solution for t :
 z1 :  {z1r}   {z1i}
 z2 :  {z2r}   {z2i}
 g :  {gr}   {gi}
 h :  {hr}   {hi}
== err :  1.0E-16 = rco :  1.0E-01 = res :  1.0E-15 = real regular ==
"""


def _report(m, dx, dy, failures: int) -> str:
    """A phc report holding the two true roots of an n = 2 chain (computed here in closed form) and the
    given number of failed paths."""
    target = m.target(dx, dy)
    eqs = [e for e in to.find_equilibria(m, dx, dy)]
    body = ""
    for k, e in enumerate(eqs, 1):
        z = np.exp(0.5j * e.q)
        g, h = complex(e.fx, e.fy), complex(e.fx, -e.fy)
        body += _ROOT.format(k=k, z1r=f"{z[0].real:.14E}", z1i=f"{z[0].imag:.14E}", z2r=f"{z[1].real:.14E}",
                             z2i=f"{z[1].imag:.14E}", gr=f"{g.real:.14E}", gi=f"{g.imag:.14E}",
                             hr=f"{h.real:.14E}", hi=f"{h.imag:.14E}")
    assert target is not None
    return (f"mixed volume : {len(eqs) + failures}\nTHE SOLUTIONS :\n\n{len(eqs)} 4\n" + "=" * 20 + "\n" + body
            + f"Number of regular solutions     : {len(eqs)}.\nNumber of singular solutions    : 0.\n"
              f"Number of solutions at infinity : 0.\nNumber of failures              : {failures}.\n")


def test_failed_paths_make_the_result_uncertified(tmp_path, monkeypatch):
    m = to.Manipulator([to.Segment(0.5, 1.0, 1.0, 0.6), to.Segment(0.7, 1.1, 1.0, 0.8)])
    monkeypatch.setenv("TENSEGRITY_HOMOTOPY_ENGINE", "polyhedral")     # a fake phc -b report
    monkeypatch.setenv("TENSEGRITY_PHC", _fake_phc(tmp_path, _report(m, 0.5, 0.2, failures=3)))
    eqs = to.find_equilibria(m, 0.5, 0.2, method="homotopy")
    assert eqs.failed_paths == 3 and not eqs.certified and (eqs.status, eqs.success) == ("uncertified", False)
    assert "3 failed" in eqs.message
    assert len(eqs) == len(to.find_equilibria(m, 0.5, 0.2))       # the roots found are still reported
    monkeypatch.setenv("TENSEGRITY_PHC", _fake_phc(tmp_path, _report(m, 0.5, 0.2, failures=0)))
    assert to.find_equilibria(m, 0.5, 0.2, method="homotopy").certified


def test_a_run_with_failed_paths_is_repeated(tmp_path, monkeypatch):
    """PHCpack draws new random constants per run: the first run fails 2 paths, the second none."""
    m = to.Manipulator([to.Segment(0.5, 1.0, 1.0, 0.6), to.Segment(0.7, 1.1, 1.0, 0.8)])
    bad, good = tmp_path / "bad.txt", tmp_path / "good.txt"
    bad.write_text(_report(m, 0.5, 0.2, failures=2))
    good.write_text(_report(m, 0.5, 0.2, failures=0))
    count = tmp_path / "count"
    exe = tmp_path / "phc"
    exe.write_text(f"#!/bin/sh\nfor last; do :; done\nif [ -e '{count}' ]; then cp '{good}' \"$last\"; "
                   f"else touch '{count}'; cp '{bad}' \"$last\"; fi\n")
    exe.chmod(exe.stat().st_mode | stat.S_IEXEC)
    monkeypatch.setenv("TENSEGRITY_HOMOTOPY_ENGINE", "polyhedral")     # fake phc -b reports
    monkeypatch.setenv("TENSEGRITY_PHC", str(exe))
    eqs = to.find_equilibria(m, 0.5, 0.2, method="homotopy")
    assert eqs.certified and eqs.failed_paths == 0 and "2 runs" in eqs.message and eqs.status == "certified"


@pytest.mark.parametrize("defect", ["clustered", "short", "no_solution"])
def test_report_defects_make_the_result_uncertified(tmp_path, monkeypatch, defect):
    """A clustered end point (path jumping), a path short of t = 1 or a failed path's last point listed as
    a block: the set is not certified, and such a point is never reported as a root."""
    m = to.Manipulator([to.Segment(0.5, 1.0, 1.0, 0.6), to.Segment(0.7, 1.1, 1.0, 0.8)])
    rep = _report(m, 0.5, 0.2, failures=0)
    first = rep.index("solution 1 :")
    block = rep[first:rep.index("solution 2 :")] if "solution 2 :" in rep else rep[first:rep.index("Number of")]
    if defect == "clustered":
        bad = block.replace("real regular", "real clustered : 2")
    elif defect == "short":
        bad = block.replace("t :  1.00000000000000E+00", "t :  9.00000000000000E-01")
    else:
        bad = block.replace("real regular", "no solution")
    rep = rep.replace(block, bad)
    monkeypatch.setenv("TENSEGRITY_HOMOTOPY_ENGINE", "polyhedral")     # a fake phc -b report
    monkeypatch.setenv("TENSEGRITY_PHC", _fake_phc(tmp_path, rep))
    eqs = to.find_equilibria(m, 0.5, 0.2, method="homotopy")
    assert not eqs.certified
    assert len(eqs) == len(to.find_equilibria(m, 0.5, 0.2)) - 1


@needs_phc
def test_homotopy_includes_a_rest_configuration_at_the_target():
    """F = 0 roots (g = h = 0) lie outside the torus the mixed volume counts: a target exactly at the
    tip of a pre-bent chain's rest configuration must still list it (force 0)."""
    from scipy.optimize import brentq

    segs = [to.Segment(0.6, 1.0, (1.0, 1.3), (1.0, 1.2)), to.Segment(0.5, 1.0, (1.2, 1.0), (0.9, 1.0)),
            to.Segment(0.55, 1.0, 1.0, 1.6)]
    m = to.Manipulator(segs)
    chain = _chain(m)
    q_rest = []
    for s in segs:                               # each segment's own rest angle, by the reference model
        one = ref.Chain.from_segments([(s.a, s.b, s.k1, s.k2, s.L1_0, s.L2_0)])
        g = lambda q: one.grad(np.array([q]))[0]                                  # noqa: E731
        q_rest.append(brentq(g, -0.5, 0.5))
    q_rest = np.array(q_rest)
    assert np.max(np.abs(chain.grad(q_rest))) < 1e-12
    x, y = chain.tip(q_rest)
    eqs = to.find_equilibria(m, m.straight_length - x, y, method="homotopy")
    assert eqs.certified
    hit = [e for e in eqs if np.max(np.abs(e.q - q_rest)) < 1e-9]
    assert len(hit) == 1 and np.max(np.abs(hit[0].force)) < 1e-9


def test_missing_engine_names_the_package(monkeypatch):
    monkeypatch.setenv("TENSEGRITY_PHC", "/nonexistent/phc")
    with pytest.raises(to.HomotopyUnavailableError, match="phcpack") as info:
        to.find_equilibria(to.Manipulator.uniform(3, 0.6, 1, 1, 1.0), 0.3, method="homotopy")
    assert isinstance(info.value, RuntimeError) and info.value.field == "method"


def test_homotopy_refuses_long_chains_and_unknown_methods():
    with pytest.raises(to.InvalidParameterError, match="up to 6"):
        to.find_equilibria(to.Manipulator.uniform(7, 0.6, 1, 1, 1.0), 0.3, method="homotopy")
    with pytest.raises(to.InvalidParameterError) as info:
        to.find_equilibria(to.Manipulator.uniform(3), 0.3, method="brute")
    assert info.value.field == "method"


def test_polynomial_system_vanishes_at_a_true_equilibrium():
    """The Laurent system evaluated (numpy) at an equilibrium found by the independent reference model."""
    from tensegrity_opt.numerics.homotopy import residuals

    m = to.Manipulator([to.Segment(0.6, 1.0, (1.0, 1.4), (0.7, 0.9)), to.Segment(0.5, 0.9, 1.2, 0.5),
                        to.Segment(0.7, 1.1, 0.8, 1.6)])
    chain = _chain(m)
    target = chain.target(0.7, 0.3)
    q, F, ok = chain.newton_kkt(target, np.array([0.3, -0.4, 0.2]))
    assert ok
    root = np.concatenate([np.exp(0.5j * q), [complex(F[0], F[1]), complex(F[0], -F[1])]])
    assert residuals(m, target, root[None, :])[0] < 1e-13
    wrong = root.copy()
    wrong[1] *= np.exp(0.01j)
    assert residuals(m, target, wrong[None, :])[0] > 1e-4


@pytest.mark.slow
@needs_phc
def test_all_branches_include_those_born_inside_the_range():
    """branch="all" on a bistable chain: at sampled points every equilibrium of the certified homotopy
    lies on one of the curve's branches (branches are born at folds inside the range)."""
    m = to.Manipulator.uniform(3, 0.6, 1, 1, 1.0)
    dxs = np.linspace(0.02, 0.45 * m.straight_length, 25)
    c = to.force_deflection(m, dxs, 0.3, branch="all")
    for i in range(0, 25, 3):           # following only the first point's branches left 4 of 44 off
        hom = to.find_equilibria(m, dxs[i], 0.3, method="homotopy")
        assert hom.certified and len(hom) > 0
        on = [b.q[i] for b in c.branches if np.all(np.isfinite(b.q[i]))]
        for e in hom:
            assert min(np.max(np.abs(e.q - q)) for q in on) < 1e-6, (dxs[i], e.q)


N6_HETEROGENEOUS = {"segments": [
    {"a": 0.4263025952879175, "b": 0.8663799784270281, "k": 1.7456221771942766, "L0": 0.4750229568654612},
    {"a": 0.6123631225988109, "b": 0.8362876101510781, "k": 1.9348281278528057, "L0": 0.3502067536913262},
    {"a": 0.5564082133759133, "b": 0.8354429701784982, "k": 1.4155519932792542, "L0": 0.7363720974916305},
    {"a": 0.6297094817270428, "b": 0.8269469625252251, "k": 0.5698798337210292, "L0": 0.2467069121951338},
    {"a": 0.4353250118667673, "b": 0.9813255152833682, "k": 1.997748471625542, "L0": 0.9194587045390243},
    {"a": 0.6284709858731725, "b": 0.821441974754111, "k": 1.9461697391139923, "L0": 0.31052524505580104}]}


def test_heterogeneous_n6_every_equilibrium_of_the_homotopy_run():
    """n = 6: a homotopy run (43648 paths, ~12 min; 1 path failed, so not certified) found 9 equilibria,
    each polished by the reference model. The search finds 9 (with 100 n projected starts it found 8),
    each confirmed as an equilibrium by the reference model, which also classifies them."""
    m = to.Manipulator.from_dict(N6_HETEROGENEOUS)
    dx, dy = 4.649225215244688, 1.3921729654405548
    eqs = to.find_equilibria(m, dx, dy)
    chain = _chain(m)
    target = chain.target(dx, dy)
    assert len(eqs) == 9
    assert sorted(_verified_morse(chain, target, e) for e in eqs) == [2, 2, 2, 2, 2, 3, 3, 3, 3]


def test_heterogeneous_n7_least_energy_near_the_joint_limit():
    """benchmarks/search_check.py (independent brute force: SLSQP from 200 random and 64 well starts): the
    least-energy minimum 7.91557851405 has one joint at 99.8 % of its range (the next minimum: 7.92389775903)."""
    segs = ((0.6305225993492213, 0.8119186559439603, 0.6118243720533708, 0.5414890527716383),
            (0.6527489530287989, 0.8704110024684791, 1.4277223921299376, 0.6004115568782297),
            (0.7302857171199216, 1.0589459409469888, 0.7118134680567862, 0.9076064103095218),
            (0.6687157648658772, 1.1297690904499342, 1.2112522987878689, 1.2148522347117834),
            (0.7210317581503769, 0.9321972104818673, 0.7305728820220942, 0.5178603973818379),
            (0.48238112005896316, 0.9378592931794086, 0.8408351734182713, 0.779751202718825),
            (0.5411360810138364, 1.0802961154308768, 1.4113451433910613, 0.7184024612155265))
    m = to.Manipulator(to.Segment(*s) for s in segs)
    eq = to.solve_equilibrium(m, 4.54894089144433)
    assert eq.energy == pytest.approx(7.91557851405, abs=1e-9)
    chain = _chain(m)
    assert _verified_morse(chain, chain.target(4.54894089144433), eq) == 0


def test_sampled_starts_rows_are_true_equilibria():
    """newton_kkt_seeds(python_fallback=False) continues unconverged rows in batched kernel calls: every
    row it marks converged is an equilibrium in numpy (residual, range), whatever round settled it."""
    from tensegrity_opt.analyses.equilibria.seeds import project_to_target
    from tensegrity_opt.numerics import chain_solver

    m = to.Manipulator.uniform(6, 0.6, 1, 1, 1.2)
    target = m.target(1.5, 0.4)
    rng = np.random.default_rng(3)
    Q = project_to_target(m, rng.uniform(-0.95, 0.95, (600, 6)) * m.joint_limits, target)
    b = chain_solver(m).newton_kkt_seeds(target, Q, python_fallback=False)
    ok = np.flatnonzero(b.success & ~b.on_bound)
    assert ok.size > 300 and np.any(b.iterations[ok] > 8)          # some were settled in a later round
    for j in ok:
        assert m.in_range(b.q[j]) and m.equilibrium_residual(b.q[j], b.force[j], target) < 1e-9
        assert b.energy[j] == pytest.approx(m.energy(b.q[j]), rel=1e-12)
