"""The batched path tracker (:mod:`tensegrity_opt.numerics.homotopy_tracker`).

Expected end points come from formulas (roots of univariate polynomials, ``numpy.roots``) and from PHCpack's
``phc -p`` on the same homotopy, path by path: never from the tracker itself.
"""

from __future__ import annotations

import time
import zlib

import numpy as np
import pytest

import tensegrity_opt as to
from tensegrity_opt.numerics import homotopy_tracker as ht
from tensegrity_opt.numerics import parameter_homotopy as ph
from tensegrity_opt.numerics.homotopy import _force_laurent_terms, _laurent_terms, homotopy_available, phc_path

needs_phc = pytest.mark.skipif(not homotopy_available(), reason="PHCpack's phc is not installed")


def _univariate(coefs) -> list[dict]:
    """``sum_k c_k x^k`` as a one-equation Laurent system."""
    return [{(k,): complex(c) for k, c in enumerate(coefs) if c != 0}]


def _roots(coefs) -> np.ndarray:
    return np.roots(np.asarray(coefs, complex)[::-1])


def test_univariate_paths_end_on_the_formula_roots():
    """A generic cubic to ``x^3 - 6 x^2 + 11 x - 6 = (x - 1)(x - 2)(x - 3)``: the three paths end on 1, 2, 3."""
    rng = np.random.default_rng(0)
    start = rng.normal(size=4) + 1j * rng.normal(size=4)
    start[3] = 1.0
    target = [-6.0, 11.0, -6.0, 1.0]
    out = ht.track_batch(_univariate(start), _univariate(target), np.exp(0.7j), _roots(start)[:, None])
    assert (out.state == ht.FINITE).all() and out.regular.all()
    assert np.allclose(np.sort(out.roots[:, 0].real), [1.0, 2.0, 3.0], atol=1e-12)
    assert np.abs(out.roots.imag).max() < 1e-12


def test_two_unknowns_end_on_every_root():
    """``x^2 = a``, ``x y = b`` (two roots: ``x = +-sqrt(a)``, ``y = b / x``): from a generic instance to ``a = 4``,
    ``b = 6``."""
    def system(a, b):
        return [{(2, 0): 1.0, (0, 0): -a}, {(1, 1): 1.0, (0, 0): -b}]

    a0, b0 = 0.3 + 1.1j, -0.8 + 0.4j
    x0 = np.sqrt(a0) * np.array([1.0, -1.0])
    starts = np.stack([x0, b0 / x0], axis=1)
    out = ht.track_batch(system(a0, b0), system(4.0, 6.0), np.exp(2.1j), starts)
    assert (out.state == ht.FINITE).all()
    got = sorted(map(tuple, np.round(out.roots.real, 10)))
    assert got == [(-2.0, -3.0), (2.0, 3.0)] and np.abs(out.roots.imag).max() < 1e-12


def test_a_double_root_is_left_to_phc_and_paths_leaving_the_torus_are_diverged():
    """``(x - 1)^2`` (a double root, singular): both paths come back FAILED, for PHCpack's end games. ``x - 1`` with
    the ``x^2`` coefficient zero: one path ends on 1, the other goes to infinity (valuation -1); ``x^2 - x`` with
    the constant zero: one ends on 1, the other goes to 0 (valuation +1, out of the torus of a Laurent system):
    the end game calls both INFINITE."""
    rng = np.random.default_rng(3)
    start = np.concatenate([rng.normal(size=2) + 1j * rng.normal(size=2), [1.0]])
    x0 = _roots(start)[:, None]
    double = ht.track_batch(_univariate(start), _univariate([1.0, -2.0, 1.0]), np.exp(1.3j), x0)
    assert (double.state == ht.FAILED).all()
    for target in ([-1.0, 1.0, 0.0], [0.0, -1.0, 1.0]):
        out = ht.track_batch(_univariate(start), _univariate(target), np.exp(1.3j), x0)
        assert sorted(out.state.tolist()) == [ht.FINITE, ht.INFINITE], target
        assert abs(out.roots[out.state == ht.FINITE, 0][0] - 1.0) < 1e-12
        assert np.isnan(out.roots[out.state == ht.INFINITE]).all()


def test_a_small_finite_unknown_is_followed_to_its_end_unless_watched():
    """``z^2 = a``, ``g = b z`` from a generic instance to ``a = 1``, ``b = 1e-9``: the roots ``(+-1, +-1e-9)``.
    On the way ``g`` shrinks like a power of ``s`` (valuation ~1) until ``s`` is far below 1e-9. Watching only ``z``
    (a joint's half-angle, of modulus 1 at real points) both paths end on their roots; watching ``g`` too, the end
    game calls them diverged (which is why only the joints' unknowns are watched)."""
    def system(a, b):
        return [{(2, 0): 1.0, (0, 0): -a}, {(0, 1): 1.0, (1, 0): -b}]

    a0, b0 = 0.4 - 0.9j, 0.7 + 0.3j
    z0 = np.sqrt(a0) * np.array([1.0, -1.0])
    starts = np.stack([z0, b0 * z0], axis=1)
    out = ht.track_batch(system(a0, b0), system(1.0, 1e-9), np.exp(0.9j), starts, angles=1)
    assert (out.state == ht.FINITE).all()
    got = out.roots[np.argsort(out.roots[:, 0].real)]
    assert np.allclose(got[:, 0], [-1.0, 1.0], atol=1e-12) and np.allclose(got[:, 1], [-1e-9, 1e-9], rtol=1e-9)
    watched = ht.track_batch(system(a0, b0), system(1.0, 1e-9), np.exp(0.9j), starts, angles=2)
    assert (watched.state == ht.INFINITE).all()


def test_a_past_deadline_ends_nothing_and_returns():
    start = [2.0 + 1j, 0.5, 1.0]
    out = ht.track_batch(_univariate(start), _univariate([-2.0, 1.0, 1.0]), 1j, _roots(start)[:, None],
                         deadline=time.monotonic() - 1.0)
    assert (out.state == ht.FAILED).all() and np.isnan(out.roots).all()


def _chain(family: str, n: int, rng) -> to.Manipulator:
    segs = []
    for j in range(n):
        a, b = rng.uniform(0.5, 1.0), rng.uniform(0.6, 1.2)
        if family == "bistable":
            segs.append({"a": 0.6, "b": 0.9, "k": [2.0, 2.0], "L0": [1.6, 1.6]})
        elif family == "asymmetric":
            segs.append({"a": a, "b": b, "k": [rng.uniform(1, 3), rng.uniform(1, 3)],
                         "L0": [rng.uniform(0.3, 1.0), rng.uniform(1.4, 2.2)]})
        else:
            segs.append({"a": a, "b": b, "k": [rng.uniform(1, 3), rng.uniform(1, 3)],
                         "L0": [rng.uniform(0.3, 2.2), rng.uniform(0.3, 2.2)]})
    return to.Manipulator.from_dict({"segments": segs})


@needs_phc
@pytest.mark.parametrize("kind", ["displacement", "force"])
@pytest.mark.parametrize("family", ["heterogeneous", "asymmetric", "bistable"])
def test_every_path_ends_where_phc_p_ends_it(kind, family):
    """Path by path, on one homotopy (same start roots, same gamma): the batch's end points are phc -p's (careful
    settings) wherever both ended one, dy != 0 and a tip load off the axes."""
    rng = np.random.default_rng(zlib.crc32(f"{kind}-{family}".encode()))
    n = 3
    m = _chain(family, n, rng)
    if kind == "displacement":
        target = _laurent_terms(m, m.target(0.3 * m.straight_length, -0.15 * m.straight_length))
    else:
        target = _force_laurent_terms(m, (-0.5, 0.3))
    start = ph.load_start(kind, n, ph.structure_of(m))
    gamma = complex(np.exp(2j * np.pi * rng.random()))
    out = ht.track_batch(ph._family(kind)(n, start.parameters), target, gamma, start.roots)
    names = ph._unknowns(kind, n)
    state, roots, _, ok = ph._run_slices(phc_path(), ph._system_text(target, names), start, np.arange(start.count),
                                         1, gamma, ph.CAREFUL, None)
    both = (out.state == ht.FINITE) & (state == ht.FINITE)
    assert ok and both.sum() >= 0.95 * start.count
    scale = 1.0 + np.abs(roots[both]).max(axis=1)
    assert (np.abs(out.roots[both] - roots[both]).max(axis=1) <= 1e-8 * scale).all()
    # no path the batch ended is one phc -p says diverged or failed
    assert not ((out.state == ht.FINITE) & (state != ht.FINITE)).any()
