"""Every equilibrium of a chain under dead loads against PHCpack (``tests/support/phc_oracle_loads.py``).

The oracle writes the equilibrium conditions of a linear-law chain with its weights, payload and joint forces as a
polynomial system in the half angles of the link angles and the tip force, solves it with PHCpack's blackbox solver
(``phc -b``, a subprocess; polyhedral homotopy: every isolated complex root), keeps the real roots inside the open
range and classifies them by their own Hessian; each run is checked complete (the generic number of finite
roots, 8 at n = 2, 96 at n = 3). It never imports the library; the library is imported here only
to be compared with it. n = 2 and 3 (n = 4 takes PHCpack about two minutes: 2816 paths).

Compared: ``find_equilibria(m, dx, dy, stops=False)`` (the library's search) member by member (q to 1e-7, the Morse
index), and ``solve_equilibrium(m, dx, dy, stops=False)`` with the oracle's least-potential stable root.
"""

from __future__ import annotations

import math
import shutil
import time

import numpy as np
import phc_oracle_loads as O
import pytest

import tensegrity_opt as to

pytestmark = pytest.mark.skipif(shutil.which("phc") is None, reason="PHCpack's phc is not installed")

FAMILIES = ("monotonic", "bistable", "heterogeneous", "asymmetric", "dy")
Q_TOL = 1e-7


# ------------------------------------------------------------------------------------------- random loaded chains
def _geometry(family: str, rng: np.random.Generator, n: int):
    """One family's segments (dicts of ``Segment`` keywords) and a deflection ``(dx, dy)``, ``dy != 0``."""
    u = lambda lo, hi: float(rng.uniform(lo, hi))  # noqa: E731
    if family == "monotonic":
        geo = [dict(a=u(0.8, 1.2), b=1.0, k=u(0.5, 2.0), L0=u(0.8, 1.2))] * n
    elif family == "bistable":                       # K < 0: L0 < 2b (1 - (a/b)^2) = 1.28
        geo = [dict(a=0.6, b=1.0, k=u(0.5, 2.0), L0=u(1.2, 1.27))] * n
    elif family == "heterogeneous":
        geo = [dict(a=u(0.6, 1.4), b=u(0.6, 1.4), k=u(0.5, 2.0), L0=u(0.7, 1.3)) for _ in range(n)]
    elif family == "asymmetric":
        geo = [dict(a=u(0.8, 1.2), b=1.0, k=(u(0.8, 1.2), u(1.2, 1.8)), L0=(u(0.9, 1.1), u(0.7, 0.95)))
               for _ in range(n)]
    elif family == "dy":
        geo = [dict(a=1.0, b=1.0, k=u(0.5, 2.0), L0=1.0)] * n
    else:
        raise AssertionError(family)
    sb = sum(g["b"] for g in geo)
    dx = u(0.05, 0.25) * 2.0 * sb
    dy = u(0.05, 0.3) * sb * (1 if rng.random() < 0.5 else -1)
    return geo, dx, dy


def _kc2(geo) -> float:
    return max(max(np.atleast_1d(g["k"])) * (g["a"] ** 2 + g["b"] ** 2) for g in geo)


def _loaded(family: str, seed: int, n: int):
    """A random linear-law chain of one family with masses, a payload, gravity in a random direction
    (``|g| m_total sum b`` a random 0.1-1 of ``k c^2``) and one joint force (``0.05-0.3 k c^2 / sum b``)."""
    rng = np.random.default_rng(seed)
    geo, dx, dy = _geometry(family, rng, n)
    masses = rng.uniform(0.05, 1.0, n)
    payload = float(rng.uniform(0.0, 0.5))
    kc2, sb = _kc2(geo), sum(g["b"] for g in geo)
    g = float(rng.uniform(0.1, 1.0)) * kc2 / ((masses.sum() + payload) * sb)
    ang = float(rng.uniform(0.0, 2.0 * math.pi))
    j = int(rng.integers(2, n + 1))              # joint 1 is fixed: a force there does no work
    force = tuple(float(x) for x in rng.uniform(-1.0, 1.0, 2) * rng.uniform(0.05, 0.3) * kc2 / sb)
    segs = [to.Segment(**gi, mass=float(mi)) for gi, mi in zip(geo, masses)]
    m = to.Manipulator(segs, payload=payload, gravity=(g * math.cos(ang), g * math.sin(ang)),
                       joint_forces=[(j, force)])
    return m, dx, dy


def _describe(m, dx, dy) -> str:
    segs = [dict(a=s.a, b=s.b, k=(s.k1, s.k2), L0=(s.L1_0, s.L2_0), mass=s.mass) for s in m.segments]
    return (f"segments={segs}, payload={m.payload!r}, gravity={m.gravity!r}, joint_forces={m.joint_forces!r}, "
            f"dx={dx!r}, dy={dy!r}")


# ------------------------------------------------------------------------------------------- comparison
def _match(oracle, lib_q, lib_morse, context: str):
    """Pair the oracle's roots with the library's members: same count, q within Q_TOL, same Morse index."""
    oq = [r.q for r in oracle.roots]
    missing = [q for q in oq if not any(np.abs(q - p).max() < Q_TOL for p in lib_q)]
    extra = [p for p in lib_q if not any(np.abs(q - p).max() < Q_TOL for q in oq)]
    assert not missing and not extra and len(oq) == len(lib_q), (
        f"{context}: oracle {len(oq)}, library {len(lib_q)}; missing from the library {missing}, "
        f"not in the oracle {extra}")
    for r in oracle.roots:
        k = int(np.argmin([np.abs(r.q - p).max() for p in lib_q]))
        assert r.morse_index == lib_morse[k], f"{context}: q {r.q}: Morse index {lib_morse[k]} != oracle's " \
                                              f"{r.morse_index} (eigenvalues {r.eigenvalues})"


def _check_oracle(ch, oracle, dx, dy):
    """PHCpack reached every finite root (the generic count), and every root satisfies the polynomial system and the
    trigonometric equations."""
    assert oracle.n_finite == O.GENERIC_ROOTS[ch.n], f"PHCpack: {oracle.n_finite} finite roots ({oracle.flags})"
    tgt = ch.target(dx, dy)
    eqs = O.system(ch, dx, dy)
    for r in oracle.roots:
        assert r.residual < 1e-9
        assert max(abs(p(O.unknowns(r.q, r.F))) for p in eqs) < 1e-9 * ch.scale
        assert np.abs(O.residual(ch, r.q, r.F, tgt)).max() < 1e-10 * ch.scale
        assert np.all(np.abs(r.q) < ch.limits)


def _compare(m, dx, dy):
    ctx = _describe(m, dx, dy)
    ch = O.chain_of(m)
    oracle = O.equilibria(ch, dx, dy)
    _check_oracle(ch, oracle, dx, dy)
    assert all(r.morse_index >= 0 for r in oracle.roots), f"{ctx}: a singular root"
    found = to.find_equilibria(m, dx, dy, stops=False)
    inside = [e for e in found.equilibria if not np.any(e.at_stop)]
    _match(oracle, [np.asarray(e.q) for e in inside], [e.morse_index for e in inside], ctx)
    # the potentials: the library's energy is E + V with V's constant, as the oracle's
    for e in inside:
        r = min(oracle.roots, key=lambda r: np.abs(r.q - e.q).max())
        assert e.energy == pytest.approx(r.potential, rel=1e-9, abs=1e-9 * ch.scale), ctx
    best = O.least_stable(oracle)
    if best is not None:
        eq = to.solve_equilibrium(m, dx, dy, stops=False)
        assert eq.energy == pytest.approx(best.potential, rel=1e-9, abs=1e-9 * ch.scale), \
            f"{ctx}: solve_equilibrium q {eq.q} energy {eq.energy}, oracle's least stable q {best.q} " \
            f"potential {best.potential}"
        if all(abs(r.potential - best.potential) > 1e-7 * ch.scale for r in oracle.roots
               if r.morse_index == 0 and r is not best):
            np.testing.assert_allclose(eq.q, best.q, atol=Q_TOL, err_msg=ctx)
    return oracle, found


# ------------------------------------------------------------------------------------------- the oracle itself
def test_the_oracle_derivatives_and_polynomials_are_its_potential():
    """The oracle's gradient and Hessian equal five-point differences of its potential, the polynomial system equals
    the trigonometric equations at random points, and the load vectors G_j give V = V_0 - sum G_j . u_j."""
    m, dx, dy = _loaded("heterogeneous", 3, 4)
    ch = O.chain_of(m)
    rng = np.random.default_rng(1)
    W, _ = ch.points
    for _ in range(4):
        q = rng.uniform(-0.9, 0.9, ch.n) * ch.limits
        F = rng.uniform(-1.0, 1.0, 2)
        np.testing.assert_allclose(O.gradient(ch, q), O.gradient_fd(ch, q), atol=1e-8 * ch.scale)
        np.testing.assert_allclose(O.hessian(ch, q, F), O.hessian_fd(ch, q, F), atol=1e-7 * ch.scale)
        poly = np.array([p(O.unknowns(q, F)) for p in O.system(ch, dx, dy)])
        trig = np.concatenate([np.zeros(ch.n), O.residual(ch, q, F, ch.target(dx, dy))])
        np.testing.assert_allclose(poly, trig, atol=1e-12 * ch.scale)
        psi = np.cumsum(q)
        L1, L2 = O.spring_lengths(ch, q)
        E = 0.5 * (ch.k1 * (L1 - ch.L10) ** 2 + ch.k2 * (L2 - ch.L20) ** 2).sum()
        V = -W[:, 0].sum() * ch.b[0] - ch.G[:, 0] @ np.cos(psi) - ch.G[:, 1] @ np.sin(psi)
        assert O.potential(ch, q) == pytest.approx(E + V, rel=1e-13)
    # the library's link loads are the oracle's (a check of the shared convention, not of the equilibria)
    np.testing.assert_allclose(m.link_loads, ch.G, atol=1e-14)
    assert m.load_offset == pytest.approx(-W[:, 0].sum() * ch.b[0], abs=1e-14)


@pytest.mark.parametrize("n, dx, dy", [(2, 0.4, 0.3),
                                       pytest.param(3, 0.8, 0.2, marks=pytest.mark.slow),
                                       pytest.param(3, 1.2, -0.4, marks=pytest.mark.slow)])
def test_the_oracle_is_the_certified_homotopy_without_loads(n, dx, dy):
    """Unloaded (masses, no gravity): the oracle's set is ``find_equilibria(method="homotopy")``'s."""
    segs = [to.Segment(0.6, 1.0, k=1.0, L0=1.25, mass=0.3), to.Segment(1.0, 1.0, k=(1.0, 1.5), L0=(1.0, 0.9)),
            to.Segment(0.8, 1.1, k=1.2, L0=1.05, mass=0.2)][:n]
    m = to.Manipulator(segs, payload=0.4)
    ch = O.chain_of(m)
    oracle = O.equilibria(ch, dx, dy)
    _check_oracle(ch, oracle, dx, dy)
    h = to.find_equilibria(m, dx, dy, method="homotopy")
    assert h.certified
    inside = [e for e in h.equilibria if not np.any(e.at_stop)]
    _match(oracle, [np.asarray(e.q) for e in inside], [e.morse_index for e in inside], _describe(m, dx, dy))
    assert len(oracle) >= 1


# ------------------------------------------------------------------------------------------- loaded chains
@pytest.mark.slow_cases(keep=5)
@pytest.mark.parametrize("family", FAMILIES)
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_two_segments_under_loads_every_equilibrium_is_the_oracle(family, seed):
    m, dx, dy = _loaded(family, 1000 * seed + FAMILIES.index(family), 2)
    _compare(m, dx, dy)


@pytest.mark.slow
@pytest.mark.parametrize("family", FAMILIES)
@pytest.mark.parametrize("seed", [0, 1])
def test_three_segments_under_loads_every_equilibrium_is_the_oracle(family, seed):
    m, dx, dy = _loaded(family, 500 + 1000 * seed + FAMILIES.index(family), 3)
    t0 = time.perf_counter()
    oracle, found = _compare(m, dx, dy)
    print(f"n=3 {family} seed {seed}: {len(oracle)} equilibria "
          f"(indices {sorted(r.morse_index for r in oracle.roots)}), PHCpack {oracle.n_solutions} roots "
          f"{oracle.seconds:.1f} s, total {time.perf_counter() - t0:.1f} s")
