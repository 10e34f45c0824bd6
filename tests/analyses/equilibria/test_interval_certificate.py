"""The homotopy's sets carry interval proofs (``EquilibriumSet.certificate``) and are certified only with them.

The phc run is replaced by a stand-in reporting known roots (as in ``test_equilibria_results.py``) where the point
is the wiring; the live runs (PHCpack; required in CI) check the proofs on a real homotopy's output against the
reference model's Morse index and Newton roots.
"""

from __future__ import annotations

import os

import numpy as np
import pytest
import reference_model as ref

import tensegrity_opt as to
from tensegrity_opt.analyses.equilibria import all_equilibria
from tensegrity_opt.numerics import homotopy, krawczyk
from tensegrity_opt.numerics.homotopy import HomotopySolve, homotopy_available

#: Two heterogeneous segments: two equilibria at (dx, dy) = (0.5, 0.2) (8 homotopy paths).
PAIR = to.Manipulator([to.Segment(0.5, 1.0, 1.0, 0.6), to.Segment(0.7, 1.1, 1.0, 0.8)])
#: A bistable chain of three (K < 0) with asymmetric last segment.
TRIPLE = to.Manipulator([to.Segment(0.5, 1.0, 1.0, 0.9), to.Segment(0.5, 1.0, 1.0, 0.9),
                         to.Segment(0.45, 1.1, (1.2, 0.8), (1.0, 1.1))])

needs_phc = pytest.mark.skipif(not homotopy_available() and os.environ.get("TENSEGRITY_REQUIRE_PHC") != "1",
                               reason="PHCpack's phc is not installed (apt-get install phcpack)")


def _stand_in(roots: np.ndarray):
    def solve(*args, **kwargs) -> HomotopySolve:
        return HomotopySolve(roots=roots, regular=np.ones(len(roots), dtype=bool), paths=len(roots), failures=0,
                             at_infinity=0, singular=0, seconds=0.0)
    return solve


def _pair_set(monkeypatch) -> to.EquilibriumSet:
    search = to.find_equilibria(PAIR, 0.5, 0.2)
    roots = np.array([np.concatenate([np.exp(0.5j * e.q), [complex(e.fx, e.fy), complex(e.fx, -e.fy)]])
                      for e in search])
    monkeypatch.setattr(homotopy, "solve_homotopy", _stand_in(roots))
    return to.find_equilibria(PAIR, 0.5, 0.2, method="homotopy")


def _check(eqs: to.EquilibriumSet, m: to.Manipulator, target=None) -> None:
    """One proven box per equilibrium, in the set's order, holding it; the proven Morse indices the reference
    model's; the reference model's Newton from each box's centre stays in the box."""
    c = ref.Chain(m.a, m.b, m.k1, m.k2, m.L1_0, m.L2_0)
    cert = eqs.certificate
    assert cert.status == "proven" and cert.roots_proven and cert.morse_proven and cert.paths == eqs.paths
    assert len(cert.boxes) == len(eqs) > 0
    for e, box in zip(eqs, cert.boxes):
        mid = 0.5 * (box.lower + box.upper)
        if target is not None:
            assert box.contains(np.r_[e.q, e.force])
            q, F, ok = c.newton_kkt(target, mid[:m.n], mid[m.n:])
            assert ok and box.contains(np.r_[q, F])
            w = c.reduced_eigs(q, F, fd=False)
        else:
            assert box.contains(e.q)
            q, ok = c.newton_force(e.force, mid)
            assert ok and box.contains(q)
            w = c.reduced_eigs(q, e.force, constrained=False, fd=False)
        assert box.morse_index == e.morse_index == int(np.sum(w < 0))


def test_a_homotopy_set_carries_its_proofs(monkeypatch):
    eqs = _pair_set(monkeypatch)
    assert (eqs.status, eqs.certified) == ("certified", True)
    _check(eqs, PAIR, PAIR.target(0.5, 0.2))
    assert "Krawczyk's test in ball arithmetic proved 2 of 2 equilibria" in eqs.message
    d = eqs.to_dict()
    assert d["certificate"]["status"] == "proven" and len(d["certificate"]["boxes"]) == 2
    assert to.find_equilibria(PAIR, 0.5, 0.2).certificate is None
    assert to.find_equilibria(PAIR, 0.5, 0.2).to_dict()["certificate"] is None


def test_a_failed_interval_proof_uncertifies_the_set(monkeypatch):
    """The proofs are made on a point shifted off the equilibrium (a stand-in for a root the test cannot prove):
    the set is listed, but not certified, and says why."""
    real = krawczyk.prove_equilibria

    def shifted(m, q, force, **kw):
        q = np.array(q, dtype=float)
        q[0, 0] += 1e-4
        return real(m, q, force, **kw)

    monkeypatch.setattr(all_equilibria, "prove_equilibria", shifted)
    eqs = _pair_set(monkeypatch)
    assert (eqs.status, eqs.success, eqs.certified) == ("uncertified", False, False) and len(eqs) == 2
    assert eqs.certificate.status == "not_proven" and not eqs.certificate.boxes[0].proven
    assert "not certified: Krawczyk's test in ball arithmetic proved 1 of 2" in eqs.message
    best = to.solve_equilibrium(PAIR, 0.5, 0.2, method="homotopy")
    assert best.status == "converged" and "NOT certified" in best.solver.status


@needs_phc
def test_live_homotopy_sets_are_proven():
    """A live run of each control: every equilibrium proven (boxes against the reference model); every root the
    homotopy classes non-real proven non-real (complex Krawczyk, a box off the real set), the real ones never; the
    real roots inside the range are exactly the set's equilibria."""
    target = TRIPLE.target(0.8, 0.3)
    eqs = to.find_equilibria(TRIPLE, 0.8, 0.3, method="homotopy")
    assert eqs.certified and len(eqs) >= 4
    _check(eqs, TRIPLE, target)
    sol = homotopy.solve_homotopy(TRIPLE, target)
    X = krawczyk.homotopy_unknowns(TRIPLE, sol.roots)
    real = np.max(np.abs(X.imag), axis=1) < 1e-9
    assert 0 < real.sum() < len(X)
    assert [krawczyk.prove_nonreal(TRIPLE, x, target=target) for x in X] == (~real).tolist()
    inside = [x.real for x in X[real] if TRIPLE.in_range(x.real[:TRIPLE.n])]
    assert len(inside) == len(eqs)
    for e in eqs:
        assert min(np.max(np.abs(x[:TRIPLE.n] - e.q)) for x in inside) < 1e-8

    loaded = to.find_equilibria_under_force(TRIPLE, -0.1, 0.05, method="homotopy")
    assert loaded.certified and loaded.certificate.control == "force" and len(loaded) >= 4
    _check(loaded, TRIPLE)
    cert = loaded.certificate          # two real roots lie just beyond the range: proven beyond it
    assert cert.outside_checked == cert.outside_proven == 2 and cert.nonreal_checked == cert.nonreal_proven
    assert "2 of 2 real roots just beyond the joint range (within 0.1) proven beyond it" in loaded.message
    stable = to.find_equilibria_under_force(TRIPLE, -0.1, 0.05, method="homotopy", stable_only=True)
    assert 0 < len(stable) < len(loaded) and len(stable.certificate.boxes) == len(stable)
    _check(stable, TRIPLE)


def test_a_single_segments_roots_are_real_and_not_proven_non_real():
    """n = 1 under a load: the quartic's four roots lie on the unit circle (real angles): none is proven non-real,
    the three inside the range are proven equilibria, the fourth lies beyond the range."""
    m = to.Manipulator([to.Segment(0.5, 1.0, 1.0, 0.9)])
    F = (-0.1, 0.05)
    P = homotopy._force_laurent_terms(m, F)[0]
    z = np.roots([P.get((p,), 0.0) for p in (2, 1, 0, -1, -2)])
    X = krawczyk.homotopy_unknowns(m, z[:, None], displacement=False)
    assert not any(krawczyk.prove_nonreal(m, x, force=F) for x in X)
    proofs = [krawczyk.prove_root(m, x.real, force=F) for x in X]
    assert sorted(p[4] for p in proofs) == ["", "", "", "outside"]
