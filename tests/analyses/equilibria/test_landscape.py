"""The paper's energy method (Figs. 4-5): landscape and its stationary points."""

import numpy as np
import pytest
from scipy.optimize import minimize

from tensegrity_opt import InvalidParameterError, Manipulator, UnsupportedError, energy_landscape, find_equilibria
from tensegrity_opt.analyses.equilibria.landscape import complete_configuration

PAPER = Manipulator.uniform(4)


@pytest.mark.parametrize("pair", [(0, 3), (0, 1), (1, 2), (0, 2)])
def test_every_equilibrium_is_a_stationary_point(pair):
    dx = 0.3
    target = PAPER.target(dx, 0)
    for e in find_equilibria(PAPER, dx):
        i, j = pair
        hits = []
        for elbow in (1, -1):
            q = complete_configuration(PAPER, target, pair, e.q[i], e.q[j], elbow)
            if np.all(np.isfinite(q)) and np.allclose(q, e.q, atol=1e-8):
                hits.append(elbow)
        assert len(hits) == 1
        elbow = hits[0]

        def f(x):
            return PAPER.energy(complete_configuration(PAPER, target, pair, x[0], x[1], elbow))

        h = 1e-6
        x0 = np.array([e.q[i], e.q[j]])
        grad = [(f(x0 + h * d) - f(x0 - h * d)) / (2 * h) for d in np.eye(2)]
        assert np.allclose(grad, 0, atol=1e-7)


def test_landscape_minima_are_the_stable_equilibria():
    dx = 0.3
    L = energy_landscape(PAPER, dx, 0.0, pair=(0, 3), grid=61)
    assert L.energy.shape == (2, 61, 61)
    stable = [e for e in find_equilibria(PAPER, dx) if e.stable]
    target = PAPER.target(dx, 0)
    found = []
    for b in range(2):
        E = L.energy[b]
        k = np.nanargmin(E)
        i, j = np.unravel_index(k, E.shape)
        elbow = (1, -1)[b]

        def f(x):
            q = complete_configuration(PAPER, target, (0, 3), x[0], x[1], elbow)
            return PAPER.energy(q) if np.all(np.isfinite(q)) and PAPER.in_range(q) else 1e9

        r = minimize(f, [L.qi[i], L.qj[j]], method="Nelder-Mead",
                     options={"xatol": 1e-11, "fatol": 1e-14, "maxiter": 5000})
        found.append(r.fun)
    for e in stable:
        assert min(abs(fv - e.energy) for fv in found) < 1e-9


def test_grid_values_and_nan_outside():
    L = energy_landscape(PAPER, 0.3, 0.1, pair=(0, 3), grid=(np.array([0.1, 0.2, 1.5]), np.array([-0.1, 0.0])))
    assert L.energy.shape == (2, 3, 2)
    q = L.q[0, 0, 0]
    assert np.allclose(PAPER.tip(q), PAPER.target(0.3, 0.1), atol=1e-12)
    assert L.energy[0, 0, 0] == pytest.approx(PAPER.energy(q), rel=1e-12)
    assert np.isnan(L.energy[:, 2, :]).all()      # q1 = 1.5 cannot reach the target


def test_errors():
    with pytest.raises(UnsupportedError):
        energy_landscape(Manipulator.uniform(5), 0.1)
    with pytest.raises(InvalidParameterError):
        energy_landscape(PAPER, 0.1, pair=(1, 1))
    with pytest.raises(ValueError):
        energy_landscape(PAPER, -0.1)


def test_landscape_span_covers_the_reachable_region():
    from tensegrity_opt.analyses.equilibria.landscape import landscape_span

    span = landscape_span(PAPER, 0.1, 0.0, (0, 3))
    full = energy_landscape(PAPER, 0.1, 0.0, pair=(0, 3), grid=201)
    QI, QJ = np.meshgrid(full.qi, full.qj, indexing="ij")
    ok = np.isfinite(full.energy).any(axis=0)
    assert span < 0.5 * full.qi.max()                     # a small patch around the origin at dx = 0.1
    assert np.all(np.abs(QI[ok]) <= span) and np.all(np.abs(QJ[ok]) <= span)
    assert landscape_span(PAPER, 4.0, 0.0, (0, 3)) <= full.qi.max()        # never beyond the default axes
