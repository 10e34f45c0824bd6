"""Interval (Krawczyk, ball-arithmetic) certificates of equilibria (:mod:`tensegrity_opt.numerics.krawczyk`).

The equilibria proven here come from outside the code under test: the PHCpack oracle
(``tests/data/homotopy_oracle.json``: every real root of certified homotopies, classified by the independent
reference model) and the reference model's own Newton searches (``reference_model.py``, which does not import the
library) on fresh random chains of several families (fixed seeds). The proven Morse index is compared with the
reference model's floating-point one. The test is also shown to refuse what it must refuse: a point that is not an
equilibrium, a shifted box that misses the root, two boxes on one root, a singular (degenerate) equilibrium, an
equilibrium outside the joint range.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import reference_model as ref

import tensegrity_opt as to
from tensegrity_opt.numerics.krawczyk import IntervalCertificate, krawczyk_test, prove_equilibria, prove_root

ORACLE = Path(__file__).resolve().parents[2] / "tests" / "data" / "homotopy_oracle.json"
DATA = json.loads(ORACLE.read_text())["cases"]


def _chain(m: to.Manipulator) -> ref.Chain:
    return ref.Chain(m.a, m.b, m.k1, m.k2, m.L1_0, m.L2_0)


def _check_boxes(cert: IntervalCertificate, points: np.ndarray) -> None:
    """Every box holds its point, is thin, and no two boxes meet (checked here, not by the certificate)."""
    lo = np.array([b.lower for b in cert.boxes])
    hi = np.array([b.upper for b in cert.boxes])
    assert np.all(lo <= points) and np.all(points <= hi)
    assert np.all(hi - lo < 1e-5 * np.maximum(1.0, np.abs(points)))
    for i in range(len(lo)):
        for j in range(i + 1, len(lo)):
            assert np.any((hi[i] < lo[j]) | (hi[j] < lo[i])), (i, j)


def _reference_morse(c: ref.Chain, q, F, constrained: bool) -> int:
    w = c.reduced_eigs(np.asarray(q), np.asarray(F), constrained=constrained, fd=False)
    assert np.min(np.abs(w)) > 1e-7 * max(1.0, np.abs(w).max())      # the float index is well defined
    return int(np.sum(w < 0))


def _random_chain(rng: np.random.Generator, n: int, family: str) -> to.Manipulator:
    """``bistable`` (uniform, K < 0), ``heterogeneous`` (every segment its own geometry and springs, some
    bistable), ``asymmetric`` (k1 != k2, L1_0 != L2_0: pre-bent)."""
    segs = []
    a, b, k = rng.uniform(0.3, 0.7), rng.uniform(0.8, 1.3), rng.uniform(0.5, 2.0)
    for _ in range(n):
        if family == "bistable":
            K0 = 2.0 * (b * b - a * a) / b                    # L0 at K = 0; below it K < 0
            segs.append(to.Segment(a, b, k, K0 * rng.uniform(0.6, 0.9)) if not segs else segs[0])
        elif family == "heterogeneous":
            bj = rng.uniform(0.7, 1.4)
            aj = bj * rng.uniform(0.3, 0.7)
            K0 = 2.0 * (bj * bj - aj * aj) / bj
            segs.append(to.Segment(aj, bj, rng.uniform(0.5, 2.5), K0 * rng.uniform(0.6, 1.4)))
        else:
            K0 = 2.0 * (b * b - a * a) / b
            segs.append(to.Segment(a, b, (rng.uniform(0.5, 2.0), rng.uniform(0.5, 2.0)),
                                   (K0 * rng.uniform(0.7, 1.5), K0 * rng.uniform(0.7, 1.5))))
    return to.Manipulator(segs)


# ----------------------------------------------------------------------------- proofs on known roots
def test_every_oracle_equilibrium_is_proven_with_its_morse_index():
    """All 104 oracle chains (n = 2..5, four multistable families, dy != 0 in most): 545 equilibria."""
    total = 0
    for case in DATA:
        m = to.Manipulator.from_dict(case["manipulator"])
        eqs = case["equilibria"]
        X = np.array([e["q"] + e["force"] for e in eqs])
        cert = prove_equilibria(m, X[:, :m.n], X[:, m.n:], target=m.target(case["dx"], case["dy"]),
                                paths=case["paths"], float_morse=[e["morse_index"] for e in eqs])
        assert (cert.status, cert.success, cert.roots_proven, cert.morse_proven) == ("proven", True, True, True), \
            cert.message
        assert [b.morse_index for b in cert.boxes] == [e["morse_index"] for e in eqs]
        assert cert.paths == case["paths"] and cert.control == "displacement" and cert.method == "krawczyk (arb)"
        _check_boxes(cert, X)
        total += len(eqs)
    assert total == 545


@pytest.mark.parametrize("family,n,seed", [
    ("bistable", 3, 1), ("bistable", 4, 2), ("heterogeneous", 3, 1), ("heterogeneous", 4, 3), ("asymmetric", 3, 7),
    ("asymmetric", 5, 4), ("bistable", 6, 4)])
def test_random_chains_displacement(family, n, seed):
    """Fresh chains, deflections up to half the length and dy != 0; the equilibria of the library's search (the
    roots to prove: where they come from does not matter). Each box must hold the reference model's own Newton
    root from the box's centre, and the proven Morse index be the reference model's."""
    rng = np.random.default_rng(seed)
    m = _random_chain(rng, n, family)
    c = _chain(m)
    dx, dy = rng.uniform(0.1, 0.5) * m.straight_length, rng.uniform(-0.3, 0.3) * m.straight_length
    eqs = to.find_equilibria(m, dx, dy)
    assert len(eqs) >= 4
    Q, F = np.array([e.q for e in eqs]), np.array([e.force for e in eqs])
    target = m.target(dx, dy)
    cert = prove_equilibria(m, Q, F, target=target)
    assert cert.status == "proven", cert.message
    _check_boxes(cert, np.hstack([Q, F]))
    morse = []
    for box in cert.boxes:
        mid = 0.5 * (box.lower + box.upper)
        q, f, ok = c.newton_kkt(target, mid[:n], mid[n:])
        assert ok and box.contains(np.r_[q, f])
        morse.append(_reference_morse(c, q, f, True))
    assert [b.morse_index for b in cert.boxes] == morse
    assert len(set(morse)) >= 2                     # minima and saddles (or maxima)


@pytest.mark.parametrize("family,n,seed", [("bistable", 3, 11), ("heterogeneous", 3, 12), ("asymmetric", 3, 11)])
def test_random_chains_force_control(family, n, seed):
    """Under a dead load: the search's roots of grad E = J^T F proven, each box holding the reference model's
    Newton root from its centre, with the reference Hessian's index."""
    rng = np.random.default_rng(seed)
    m = _random_chain(rng, n, family)
    c = _chain(m)
    force = rng.uniform(-0.3, 0.3, 2) * m.torque_scale / float(m.b.sum())
    Q = np.array([e.q for e in to.find_equilibria_under_force(m, *force)])
    assert len(Q) >= 3
    cert = prove_equilibria(m, Q, np.tile(force, (len(Q), 1)), control="force")
    assert (cert.status, cert.control) == ("proven", "force"), cert.message
    _check_boxes(cert, Q)
    morse = []
    for box in cert.boxes:
        q, ok = c.newton_force(force, 0.5 * (box.lower + box.upper))
        assert ok and box.contains(q)
        morse.append(_reference_morse(c, q, force, False))
    assert [b.morse_index for b in cert.boxes] == morse
    assert len(set(morse)) >= 2


# ----------------------------------------------------------------------------- what it must refuse
CASE = next(c for c in DATA if len(c["equilibria"]) >= 4 and len(c["manipulator"]["segments"]) == 3)
M3 = to.Manipulator.from_dict(CASE["manipulator"])
T3 = M3.target(CASE["dx"], CASE["dy"])
X3 = np.array([e["q"] + e["force"] for e in CASE["equilibria"]])


def test_the_bare_test_fails_on_a_box_that_misses_the_root():
    root = X3[0]
    assert krawczyk_test(M3, root, 1e-9, target=T3)
    shifted = root + np.r_[1e-6, np.zeros(M3.n + 1)]
    assert not krawczyk_test(M3, shifted, 1e-9, target=T3)     # the root lies outside this box
    assert krawczyk_test(M3, shifted, 1e-5, target=T3)         # and inside this one
    assert not krawczyk_test(M3, root + 0.05, 1e-3, target=T3)  # no root there


def test_a_perturbed_root_or_a_non_root_is_not_proven():
    Q, F = X3[:, :M3.n].copy(), X3[:, M3.n:].copy()
    Q[1, 0] += 1e-4                         # beyond its box: Newton pulls it back farther than allowed
    cert = prove_equilibria(M3, Q, F, target=T3)
    assert cert.status == "not_proven" and not cert.success and not cert.roots_proven
    assert [b.proven for b in cert.boxes] == [i != 1 for i in range(len(Q))]
    assert cert.boxes[1].reason == "moved" and cert.boxes[1].morse_index is None
    assert "1 moved" in cert.message
    ok, *_, reason = prove_root(M3, np.r_[0.3, -0.2, 0.1, 0.0, 0.0], target=T3)
    assert not ok and reason in ("moved", "krawczyk", "singular")


def test_two_boxes_on_one_root_overlap():
    Q, F = X3[:, :M3.n], X3[:, M3.n:]
    Q2, F2 = np.vstack([Q, Q[2] + 1e-12]), np.vstack([F, F[2]])
    cert = prove_equilibria(M3, Q2, F2, target=T3)
    assert cert.status == "not_proven"
    assert [b.reason for b in cert.boxes] == ["" if i not in (2, len(Q)) else "overlap" for i in range(len(Q2))]


def test_a_degenerate_equilibrium_is_not_proven():
    """Segments at the pitchfork (K = 0: L0 = 2 (b^2 - a^2) / b exactly), unloaded, straight: a singular root."""
    m = to.Manipulator.uniform(2, a=0.5, b=1.0, k=1.0, L0=1.5)
    ok, _, _, morse, reason = prove_root(m, [0.0, 0.0], force=(0.0, 0.0))
    assert not ok and morse is None and reason in ("singular", "krawczyk")
    assert not krawczyk_test(m, [0.0, 0.0], 1e-9, force=(0.0, 0.0))
    # just off the pitchfork the root is regular, and proven in a box far smaller than its neighbours' distance
    m = to.Manipulator.uniform(2, a=0.5, b=1.0, k=1.0, L0=1.5 + 1e-6)
    ok, lo, hi, morse, _ = prove_root(m, [0.0, 0.0], force=(0.0, 0.0))
    assert ok and morse == 0 and np.all(hi - lo < 1e-6)


def test_an_equilibrium_outside_the_range_is_not_proven():
    """A zero of a segment's torque just beyond its joint limit (a spring length negative there)."""
    from scipy.optimize import brentq
    s = to.Segment(0.3, 1.0, 1.0, 0.5)
    q = brentq(lambda x: float(s.torque(x)), s.joint_limit, 3.0, xtol=1e-15)
    assert s.joint_limit < q < s.joint_limit + 0.05
    ok, *_, reason = prove_root(to.Manipulator([s]), [q], force=(0.0, 0.0))
    assert not ok and reason == "outside"
    assert krawczyk_test(to.Manipulator([s]), [q], 1e-9, force=(0.0, 0.0))   # a true root, out of range


def test_a_subset_is_restated_and_the_json_form():
    cert = prove_equilibria(M3, X3[:, :M3.n], X3[:, M3.n:], target=T3)
    sub = cert.select([0, 2])
    assert len(sub.boxes) == 2 and sub.boxes[1] is cert.boxes[2] and sub.status == "proven"
    assert "2 of 2" in sub.message
    d = cert.to_dict()
    assert list(d)[:3] == ["success", "status", "message"]
    assert len(d["boxes"]) == len(X3) and d["boxes"][0]["lower"] == cert.boxes[0].lower.tolist()
    json.dumps(d)
    with pytest.raises(ValueError):
        prove_equilibria(M3, X3[:, :M3.n], X3[:, M3.n:])               # displacement control needs the target
    with pytest.raises(ValueError):
        prove_root(M3, X3[0])                                          # neither target nor force


def test_the_equations_are_the_reference_models():
    """f and f' (float arithmetic of the same code the balls run) against the reference model's gradient, Hessian,
    tip and Jacobian at random points of a heterogeneous chain with asymmetric preloads."""
    from tensegrity_opt.numerics.krawczyk import _float_system

    rng = np.random.default_rng(7)
    m = to.Manipulator([to.Segment(0.5, 1.0, (1.2, 0.8), (1.0, 1.3)), to.Segment(0.7, 1.3, 2.0, 0.9),
                        to.Segment(0.3, 0.8, (0.6, 1.5), (0.7, 0.5)), to.Segment(0.6, 1.1, 1.0, 1.6)])
    c = _chain(m)
    target = m.target(0.7, -0.4)
    for _ in range(5):
        q, F = rng.uniform(-1.0, 1.0, m.n) * m.joint_limits, rng.uniform(-1.0, 1.0, 2)
        f, fp = _float_system(m, np.r_[q, F], target, None)
        J = c.jac(q)
        assert np.allclose(f, np.r_[c.lagrangian_grad(q, F), c.tip(q) - target], atol=1e-12)
        assert np.allclose(fp[:m.n, :m.n], c.lagrangian_hess(q, F), atol=1e-12)
        assert np.allclose(fp[:m.n, m.n:], -J.T, atol=1e-12) and np.allclose(fp[m.n:, :m.n], J, atol=1e-12)
        g, H = _float_system(m, q, None, F)
        assert np.allclose(g, c.lagrangian_grad(q, F), atol=1e-12) and np.allclose(H, fp[:m.n, :m.n])


def test_a_float_morse_index_the_proof_contradicts_is_reported():
    """A floating-point index set against the proof (here deliberately wrong for one equilibrium): that box is not
    Morse-proven, the certificate ``roots_proven`` (a success: the roots stand), its message says so."""
    true = [e["morse_index"] for e in CASE["equilibria"]]
    wrong = list(true)
    wrong[0] += 1
    cert = prove_equilibria(M3, X3[:, :M3.n], X3[:, M3.n:], target=T3, float_morse=wrong)
    assert (cert.status, cert.success, cert.roots_proven, cert.morse_proven) == ("roots_proven", True, True, False)
    assert cert.boxes[0].morse_index == true[0] and not cert.boxes[0].morse_proven
    assert "1 proven Morse indices differ from the floating-point ones" in cert.message
