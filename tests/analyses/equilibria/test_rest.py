"""Rest configurations and every equilibrium under a dead tip load.

Independent routes only: the reference model (``reference_model.py``, which does not import the
library) finds each segment's unloaded critical points by a grid and bisection on its own gradient,
builds the unloaded equilibria as their product, classifies by its own Hessian, searches the loaded
equilibria by plain Newton from random starts and the least-energy well by L-BFGS-B from random starts;
PHCpack's homotopy (where ``phc`` is installed; required in CI, ``TENSEGRITY_REQUIRE_PHC=1``) checks the
search. Small chains (n = 2..4) to stay within the CI budget.
"""

from __future__ import annotations

import json
import os

import numpy as np
import pytest
import reference_model as ref
import scipy.optimize as so

import tensegrity_opt as to
from tensegrity_opt.analyses.equilibria import rest
from tensegrity_opt.numerics.homotopy import homotopy_available

SAME = 1e-6

needs_phc = pytest.mark.skipif(not homotopy_available() and os.environ.get("TENSEGRITY_REQUIRE_PHC") != "1",
                               reason="PHCpack's phc is not installed (apt-get install phcpack)")


# ----------------------------------------------------------------------------- the chains
def _random_chain(seed: int, n: int, family: str) -> to.Manipulator:
    """A random chain of one family (fixed seed): ``monotonic`` (symmetric, K > 0), ``asymmetric``
    (monotonic, asymmetric preloads: pre-bent), ``bistable`` (symmetric, K < 0) or ``heterogeneous``
    (a mix of the three with different geometry)."""
    rng = np.random.default_rng(seed)
    segs = []
    for j in range(n):
        fam = family if family != "heterogeneous" else ("monotonic", "asymmetric", "bistable")[j % 3]
        a, b, k = rng.uniform(0.3, 0.6), rng.uniform(0.9, 1.3), rng.uniform(0.5, 2.0)
        kc = 2.0 * (b * b - a * a) / b                     # K = k (b L0 - 2 (b^2 - a^2)) = 0 here
        if fam == "monotonic":
            segs.append(to.Segment(a, b, k, kc + rng.uniform(0.2, 1.0)))
        elif fam == "bistable":
            segs.append(to.Segment(a, b, k, rng.uniform(0.3, 0.85) * kc))
        else:
            L0 = kc + rng.uniform(0.3, 1.0)
            segs.append(to.Segment(a, b, (k, k * rng.uniform(0.7, 1.4)), (L0, L0 * rng.uniform(0.8, 1.2))))
    return to.Manipulator(segs)


def _chain(m: to.Manipulator) -> ref.Chain:
    return ref.Chain(m.a.copy(), m.b.copy(), m.k1.copy(), m.k2.copy(), m.L1_0.copy(), m.L2_0.copy())


def _segment(chain: ref.Chain, j: int) -> ref.Chain:
    return ref.Chain(*(np.array([v[j]]) for v in (chain.a, chain.b, chain.k1, chain.k2, chain.L10, chain.L20)))


def _ref_critical(chain: ref.Chain) -> list[np.ndarray]:
    """Each segment's unloaded critical angles: sign changes of the reference gradient on a fine grid (no
    grid point at 0), refined by brentq, near-duplicates merged."""
    out = []
    for j in range(chain.n):
        one = _segment(chain, j)
        lim = one.limits[0]
        qs = np.linspace(-lim, lim, 20002)[1:-1]
        g = one.grad(qs)                                  # elementwise: one segment
        roots: list[float] = []
        for i in np.flatnonzero(np.sign(g[:-1]) != np.sign(g[1:])):
            r = so.brentq(lambda x, one=one: float(one.grad(np.array([x]))[0]), qs[i], qs[i + 1], xtol=1e-15,
                          rtol=1e-15)
            if not roots or r - roots[-1] > 1e-9:
                roots.append(r)
        out.append(np.array(roots))
    return out


def _product(pts: list[np.ndarray]) -> np.ndarray:
    return np.stack([g.ravel() for g in np.meshgrid(*pts, indexing="ij")], axis=1)


def _ref_morse(chain: ref.Chain, q, F) -> int:
    """Negative eigenvalues of the reference Hessian of E - F.tip (relative angles, analytic)."""
    w = np.linalg.eigvalsh(chain.lagrangian_hess(np.asarray(q, float), np.asarray(F, float)))
    assert np.min(np.abs(w)) > 1e-7 * np.max(np.abs(w))            # no degenerate point in these tests
    return int(np.sum(w < 0))


def _ref_phi_eigenvalues(chain: ref.Chain, q, F) -> np.ndarray:
    """Eigenvalues of the reference Hessian of E - F.tip in absolute angles (q = D phi, D the difference
    matrix), the coordinates ``Equilibrium.hessian_eigenvalues`` is documented in."""
    D = np.eye(chain.n) - np.eye(chain.n, k=-1)
    return np.linalg.eigvalsh(D.T @ chain.lagrangian_hess(np.asarray(q, float), np.asarray(F, float)) @ D)


def _ref_force_set(chain: ref.Chain, F) -> list[np.ndarray]:
    """Every equilibrium under the dead load F the reference model finds: plain Newton from random starts
    and from every unloaded critical point of its own."""
    sols = ref.all_force_equilibria(chain, F, n_starts=300, seed=3)
    for q0 in _product(_ref_critical(chain)):
        q, ok = chain.newton_force(np.asarray(F, float), q0)
        if ok and np.all(np.isfinite(q)) and chain.in_range(q) and not any(np.max(np.abs(q - s)) < SAME for s in sols):
            sols.append(q)
    return sols


def _same_sets(got, expected: list[np.ndarray]) -> None:
    assert len(got) == len(expected), (len(got), len(expected))
    for q in expected:
        assert min(np.max(np.abs(e.q - q)) for e in got) < SAME, f"missed q = {q}"


# ----------------------------------------------------------------------------- F = 0: the exact set
@pytest.mark.parametrize("n,seed", [(2, 1), (3, 2), (4, 3)])
def test_monotonic_symmetric_chain_rests_straight(n, seed):
    m = _random_chain(seed, n, "monotonic")
    chain = _chain(m)
    assert np.all(chain.symmetric_K() > 0)
    assert all(p.size == 1 for p in _ref_critical(chain))          # one critical point per segment
    eqs = to.find_equilibria_under_force(m)
    assert eqs.method == "exact" and eqs.certified and len(eqs) == 1
    e = eqs[0]
    assert np.all(e.q == 0.0) and e.stable and e.kind == "minimum" and e.control == "force"
    assert np.all(e.force == 0.0) and e.energy == pytest.approx(chain.energy(np.zeros(n)), rel=1e-12)
    best = to.rest_configuration(m)
    assert np.all(best.q == 0.0) and best.stable


@pytest.mark.parametrize("n,seed", [(2, 4), (3, 5)])
def test_asymmetric_preloads_bend_the_rest_configuration(n, seed):
    m = _random_chain(seed, n, "asymmetric")
    chain = _chain(m)
    expected = _product(_ref_critical(chain))
    assert expected.shape[0] == 1                                  # monotonic: one rest configuration
    eqs = to.find_equilibria_under_force(m)
    assert len(eqs) == 1 and eqs.certified
    q = eqs[0].q
    assert np.max(np.abs(q)) > 0.05                                # pre-bent: not straight
    assert np.max(np.abs(q - expected[0])) < 1e-9
    assert np.max(np.abs(chain.grad(q))) < 1e-12 * np.max(chain.k1 * chain.c ** 2)   # grad E = 0
    assert np.all(chain.hess_diag(q) > 0) and eqs[0].stable
    best = to.rest_configuration(m)
    assert np.array_equal(best.q, q) and best.stable and best.energy == pytest.approx(chain.energy(q), rel=1e-12)


def test_bistable_chain_has_3_to_the_n_equilibria_and_2_to_the_n_wells():
    # a = 0.5, b = 1, L0 = 1: K = k (b L0 - 2 (b^2 - a^2)) = 1 - 1.5 < 0
    m = to.Manipulator([to.Segment(0.5, 1.0, 1.0, 1.0), to.Segment(0.45, 1.1, 1.3, 1.2),
                        to.Segment(0.5, 0.95, 0.8, 0.9)])
    chain = _chain(m)
    assert np.all(chain.symmetric_K() < 0)
    crit = _ref_critical(chain)
    assert [p.size for p in crit] == [3, 3, 3]
    eqs = to.find_equilibria_under_force(m)
    assert eqs.method == "exact" and eqs.certified and len(eqs) == 27
    _same_sets(eqs, list(_product(crit)))
    for e in eqs:
        assert e.morse_index == _ref_morse(chain, e.q, (0.0, 0.0))
        assert e.stable == (e.morse_index == 0)
        assert e.energy == pytest.approx(chain.energy(e.q), rel=1e-12)
        assert np.allclose(e.hessian_eigenvalues, _ref_phi_eigenvalues(chain, e.q, (0.0, 0.0)), atol=1e-10)
        assert np.allclose(e.tip, chain.tip(e.q), atol=1e-12)
    assert sorted(e.morse_index for e in eqs) == sorted([0] * 8 + [1] * 12 + [2] * 6 + [3])
    energies = np.array([e.energy for e in eqs])
    assert np.all(np.diff(energies) >= -1e-12)
    wells = to.find_equilibria_under_force(m, stable_only=True)
    assert len(wells) == 8 and all(e.stable for e in wells)
    _same_sets(wells, [e.q for e in eqs if e.stable])
    assert json.loads(json.dumps(wells.to_dict()))["method"] == "exact"


@pytest.mark.parametrize("n,seed", [(3, 6), (4, 7)])
def test_heterogeneous_unloaded_equilibria_match_the_reference(n, seed):
    m = _random_chain(seed, n, "heterogeneous")
    chain = _chain(m)
    crit = _ref_critical(chain)
    assert max(p.size for p in crit) == 3 and min(p.size for p in crit) == 1
    eqs = to.find_equilibria_under_force(m)
    _same_sets(eqs, list(_product(crit)))
    for e in eqs:
        assert e.morse_index == _ref_morse(chain, e.q, (0.0, 0.0))
        # the product rule: a minimum iff every factor is one
        assert e.stable == bool(np.all(chain.hess_diag(e.q) > 0))


def test_product_cap_and_stable_only():
    m = to.Manipulator.uniform(11, a=0.5, b=1.0, k=1.0, L0=1.0)        # 3^11 = 177147 critical points
    with pytest.raises(to.InvalidParameterError, match="stable_only=True") as err:
        to.find_equilibria_under_force(m)
    assert err.value.field == "n"
    wells = to.find_equilibria_under_force(m, stable_only=True)
    assert len(wells) == 2 ** 11 and all(e.stable and e.morse_index == 0 for e in wells)
    assert len({tuple(np.sign(e.q)) for e in wells}) == 2 ** 11
    big = to.Manipulator.uniform(17, a=0.5, b=1.0, k=1.0, L0=1.0)      # 2^17 wells: too many even so
    with pytest.raises(to.InvalidParameterError) as err:
        to.find_equilibria_under_force(big, stable_only=True)
    assert err.value.field == "n"
    assert to.rest_configuration(big).stable                           # but the least-energy one is fine


def test_a_segment_without_a_well_has_no_rest_configuration():
    # a > b and spring 1 far too long: the torque of joint 1 never vanishes inside its range
    m = to.Manipulator([to.Segment(1.4, 0.6, (3.0, 2.5), (4.0, 0.3)), to.Segment(1.0, 1.0, 1.0, 1.0)])
    assert _ref_critical(_chain(m))[0].size == 0
    eqs = to.find_equilibria_under_force(m)
    assert len(eqs) == 0 and eqs.certified and eqs.method == "exact"
    with pytest.raises(to.NoEquilibriumError):
        to.rest_configuration(m)


# ----------------------------------------------------------------------------- F != 0
LOADED = [
    ("monotonic", 3, 11, (-0.15, 0.06)),
    ("asymmetric", 3, 12, (0.2, -0.1)),
    ("bistable", 2, 13, (-0.05, 0.03)),
    ("heterogeneous", 3, 14, (-0.1, 0.05)),
    ("bistable", 3, 15, (0.08, 0.12)),
]


def _loaded_id(c) -> str:
    return f"{c[0]}-n{c[1]}"


@pytest.mark.slow
@pytest.mark.parametrize("case", LOADED, ids=_loaded_id)
def test_search_under_force_matches_the_reference(case):
    family, n, seed, F = case
    m = _random_chain(seed, n, family)
    chain = _chain(m)
    eqs = to.find_equilibria_under_force(m, *F)
    assert eqs.method == "search" and not eqs.certified and len(eqs) >= 1
    _same_sets(eqs, _ref_force_set(chain, F))
    V = []
    for e in eqs:
        assert e.control == "force" and np.array_equal(e.force, F)
        assert np.max(np.abs(chain.lagrangian_grad(e.q, F))) < 1e-9 * np.max(chain.k1 * chain.c ** 2)
        assert e.morse_index == _ref_morse(chain, e.q, F) and e.stable == (e.morse_index == 0)
        assert np.allclose(e.hessian_eigenvalues, _ref_phi_eigenvalues(chain, e.q, F), atol=1e-9)
        V.append(chain.energy(e.q) - np.dot(F, chain.tip(e.q)))
    assert np.all(np.diff(V) >= -1e-12)                   # sorted by the total potential E - F.tip
    stable = to.find_equilibria_under_force(m, *F, stable_only=True)
    assert [e.q.tolist() for e in stable] == [e.q.tolist() for e in eqs if e.stable]


@pytest.mark.slow
def test_search_under_force_on_a_mirror_symmetric_chain_gives_mirror_pairs():
    m = to.Manipulator.uniform(3, a=0.5, b=1.0, k=1.0, L0=1.0)
    eqs = to.find_equilibria_under_force(m, -0.05, 0.0)
    assert len(eqs) >= 2
    for e in eqs:                                        # fy = 0: -q is an equilibrium whenever q is
        assert min(np.max(np.abs(f.q + e.q)) for f in eqs) < 1e-9
    up = to.find_equilibria_under_force(m, -0.05, 0.02)
    down = to.find_equilibria_under_force(m, -0.05, -0.02)
    _same_sets(down, [-e.q for e in up])                  # (fx, fy) -> (fx, -fy) mirrors the set


@pytest.mark.slow_cases(keep=1)
@needs_phc
@pytest.mark.parametrize("case", LOADED + [("bistable", 4, 16, (-0.04, 0.05))], ids=_loaded_id)
def test_homotopy_under_force_agrees_with_the_search(case):
    family, n, seed, F = case
    m = _random_chain(seed, n, family)
    hom = to.find_equilibria_under_force(m, *F, method="homotopy")
    assert hom.method == "homotopy" and hom.certified and hom.failed_paths == 0 and hom.paths > 0
    search = to.find_equilibria_under_force(m, *F)
    _same_sets(hom, [e.q for e in search])
    for a, b in zip(hom, search):                        # the same order and classification
        assert np.max(np.abs(a.q - b.q)) < 1e-9 and a.morse_index == b.morse_index


def test_homotopy_at_zero_force_is_the_exact_set_even_without_phc(monkeypatch):
    monkeypatch.setenv("TENSEGRITY_PHC", "/nonexistent/phc")
    m = _random_chain(6, 3, "heterogeneous")
    eqs = to.find_equilibria_under_force(m, 0.0, 0.0, method="homotopy")
    assert eqs.method == "exact" and eqs.certified
    with pytest.raises(to.HomotopyUnavailableError):
        to.find_equilibria_under_force(m, 0.1, 0.0, method="homotopy")


# ----------------------------------------------------------------------------- the least-energy rest configuration
def _ref_least_energy(chain: ref.Chain, starts: int = 60, seed: int = 9) -> tuple[float, np.ndarray]:
    """Least energy of L-BFGS-B (reference energy and gradient) from random starts in the range, each end
    polished by Newton on the reference gradient: the minima of E, whatever the structure of the chain."""
    rng = np.random.default_rng(seed)
    lim = chain.limits * (1 - 1e-6)
    best = (np.inf, None)
    for _ in range(starts):
        r = so.minimize(chain.energy, rng.uniform(-0.95, 0.95, chain.n) * chain.limits, jac=chain.grad,
                        method="L-BFGS-B", bounds=list(zip(-lim, lim)))
        q = r.x
        for _ in range(8):                                # E is separable: its Hessian is diagonal
            q = q - chain.grad(q) / chain.hess_diag(q)
        if chain.in_range(q) and np.all(chain.hess_diag(q) > 0) and np.max(np.abs(q - r.x)) < 1e-3:
            e = chain.energy(q)
            if e < best[0]:
                best = (e, q)
    return best


@pytest.mark.slow
@pytest.mark.parametrize("n,seed", [(2, 21), (3, 22), (4, 23)])
def test_rest_configuration_is_the_least_energy_well(n, seed):
    rng = np.random.default_rng(seed)
    segs = []
    for _ in range(n):                                    # asymmetric bistable: wells of unequal energy
        a, b = rng.uniform(0.35, 0.55), rng.uniform(0.9, 1.2)
        L0 = rng.uniform(0.4, 0.8) * 2.0 * (b * b - a * a) / b
        segs.append(to.Segment(a, b, (1.0, rng.uniform(0.8, 1.25)), (L0, L0 * rng.uniform(0.9, 1.1))))
    m = to.Manipulator(segs)
    chain = _chain(m)
    e_ref, q_ref = _ref_least_energy(chain)
    best = to.rest_configuration(m)
    assert best.stable and best.control == "force" and np.all(best.force == 0.0)
    assert best.energy == pytest.approx(e_ref, abs=1e-12)
    assert np.max(np.abs(best.q - q_ref)) < 1e-9
    assert np.max(np.abs(chain.grad(best.q))) < 1e-12 and np.all(chain.hess_diag(best.q) > 0)
    wells = to.find_equilibria_under_force(m, stable_only=True)
    assert np.array_equal(wells[0].q, best.q)


def _ref_tie_pick(chain: ref.Chain) -> np.ndarray:
    """The tie rule applied by brute force to every well of the chain (reference critical points)."""
    wells = []
    for j, p in enumerate(_ref_critical(chain)):
        one = _segment(chain, j)
        wells.append(np.array([q for q in p if one.hess_diag(np.array([q]))[0] > 0]))
    W = _product(wells)
    E = np.array([chain.energy(q) for q in W])
    tied = W[E <= E.min() + 1e-9 * np.max(np.maximum(chain.k1, chain.k2) * chain.c ** 2)]
    size = np.round(np.abs(tied).max(axis=1), 7)
    tied = tied[size == size.min()]
    for i in range(chain.n):                              # then larger q_1, then larger q_2, ...
        col = np.round(tied[:, i], 7)
        tied = tied[col == col.max()]
    assert tied.shape[0] == 1
    return tied[0]


def test_tie_rule_on_a_mirror_symmetric_bistable_chain():
    m = to.Manipulator([to.Segment(0.5, 1.0, 1.0, 1.0), to.Segment(0.4, 1.1, 1.2, 1.3), to.Segment(0.5, 1.0, 1.0, 1.0)])
    assert m == m.mirrored() and not m.monotonic
    chain = _chain(m)
    wells = to.find_equilibria_under_force(m, stable_only=True)
    assert len(wells) == 8 and len({round(e.energy, 9) for e in wells}) == 1        # 8 equal wells
    best = to.rest_configuration(m)
    assert np.all(best.q > 0)                             # all wells equally far from straight: larger q first
    assert np.max(np.abs(best.q - _ref_tie_pick(chain))) < 1e-9
    assert np.array_equal(wells[0].q, best.q)
    # the whole tie group is ordered by the rule: signs (+++), (++-), (+-+), ...
    assert [tuple(np.sign(e.q).astype(int)) for e in wells] == [
        (1, 1, 1), (1, 1, -1), (1, -1, 1), (1, -1, -1), (-1, 1, 1), (-1, 1, -1), (-1, -1, 1), (-1, -1, -1)]


# A segment tuned (L0 = (1 + D, 1 - D), k = (1, 1.6)) so that its two wells, at q = -1.41333 and
# q = +2.01033, have equal energies (the reference model's energies agree to 1e-15 at this D).
TUNED_D = -0.07518381359193049


def _tuned() -> to.Segment:
    return to.Segment(0.5, 1.0, (1.0, 1.6), (1.0 + TUNED_D, 1.0 - TUNED_D))


@pytest.mark.parametrize("other,expected_sign", [(to.Segment(0.3, 1.0, 1.0, 0.6), 1.0),
                                                 (to.Segment(0.5, 1.0, 1.0, 1.4), -1.0)])
def test_tie_rule_is_global_not_per_segment(other, expected_sign):
    """The tuned segment's wells tie. Next to a segment with deeper wells (+-2.47) max|q| is fixed by that
    segment, so the tuned one takes its larger well (+2.01) although -1.41 is nearer straight ("each segment
    its nearest well" would say -1.41); next to shallow wells (+-0.73) its nearer well (-1.41) sets max|q|."""
    m = to.Manipulator([_tuned(), other])
    chain = _chain(m)
    one = _segment(chain, 0)
    wells = [q for q in _ref_critical(one)[0] if one.hess_diag(np.array([q]))[0] > 0]
    assert len(wells) == 2 and abs(one.energy(np.array([wells[0]])) - one.energy(np.array([wells[1]]))) < 1e-13
    assert abs(wells[0]) < abs(wells[1]) and wells[0] < 0 < wells[1]
    expected = _ref_tie_pick(chain)
    assert np.sign(expected[0]) == expected_sign
    best = to.rest_configuration(m)
    assert np.max(np.abs(best.q - expected)) < 1e-9
    assert np.array_equal(to.find_equilibria_under_force(m, stable_only=True)[0].q, best.q)


def test_near_ties_adding_up_past_the_tolerance():
    """Two copies of the tuned segment detuned so that the larger well lies 0.6 tolerance above the other:
    each alone ties, both together do not. Next to deep wells (max|q| fixed by them) the rule wants the
    larger wells, but only one segment may take its larger one: (+2.01, -1.41, +2.47), not (+, +, +) (what
    taking every segment's tied wells as a product would give)."""
    near = to.Segment(0.5, 1.0, (1.0, 1.6), (1.0 + TUNED_D + 3.3e-10, 1.0 - TUNED_D - 3.3e-10))
    m = to.Manipulator([near, near, to.Segment(0.3, 1.0, 1.0, 0.6)])
    chain = _chain(m)
    tol = rest.ENERGY_TIE * m.torque_scale
    one = _segment(chain, 0)
    w = [q for q in _ref_critical(one)[0] if one.hess_diag(np.array([q]))[0] > 0]
    excess = one.energy(np.array([w[1]])) - one.energy(np.array([w[0]]))
    assert 0.5 * tol < excess < 0.75 * tol                      # the premise, by the reference model
    expected = _ref_tie_pick(chain)
    assert np.sign(expected).tolist() == [1.0, -1.0, 1.0]
    best = to.rest_configuration(m)
    assert np.max(np.abs(best.q - expected)) < 1e-9
    assert np.array_equal(to.find_equilibria_under_force(m, stable_only=True)[0].q, best.q)


# ----------------------------------------------------------------------------- validation and exports
@pytest.mark.parametrize("kwargs,field", [({"fx": float("nan")}, "fx"), ({"fy": float("inf")}, "fy"),
                                          ({"fx": "x"}, "fx"), ({"method": "newton"}, "method"),
                                          ({"dedupe_tol": 0.0}, "dedupe_tol"), ({"n_random": -1}, "n_random"),
                                          ({"timeout": 0.0}, "timeout"), ({"stable_only": "yes"}, "stable_only")])
def test_invalid_arguments_name_their_field(kwargs, field):
    m = to.Manipulator.uniform(2)
    with pytest.raises(to.InvalidParameterError) as err:
        to.find_equilibria_under_force(m, **kwargs)
    assert err.value.field == field


def test_homotopy_refuses_long_chains_and_rest_configuration_unknown_rules():
    with pytest.raises(to.InvalidParameterError) as err:
        to.find_equilibria_under_force(to.Manipulator.uniform(7), 0.1, 0.1, method="homotopy")
    assert err.value.field == "method"
    with pytest.raises(to.InvalidParameterError) as err:
        to.rest_configuration(to.Manipulator.uniform(2), which="nearest")
    assert err.value.field == "which"


def test_exported():
    assert {"find_equilibria_under_force", "rest_configuration"} <= set(to.__all__)
    assert to.find_equilibria_under_force is rest.find_equilibria_under_force
    assert to.rest_configuration is rest.rest_configuration
