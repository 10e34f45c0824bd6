"""The CasADi model (absolute angles) against the numpy model and finite differences."""

import numpy as np
import pytest

from tensegrity_opt import Manipulator, Segment
from tensegrity_opt.numerics import chain_solver

CHAINS = [Manipulator.uniform(4),
          Manipulator([Segment(1.0, 1.0, 1.0, 1.0), Segment(0.9, 1.3, 2.0, 1.5), Segment(1.1, 0.8, (0.7, 1.1),
                                                                                         (0.9, 1.2))])]


@pytest.mark.parametrize("m", CHAINS)
def test_energy_gradient_hessian_by_finite_differences(m):
    rng = np.random.default_rng(3)
    q = rng.uniform(-0.5, 0.5, m.n)
    F = np.array([-0.4, 0.3])
    E, g, H, J, tip = chain_solver(m).evaluate(q, F)
    assert E == pytest.approx(m.energy(q), rel=1e-13)
    assert np.allclose(tip, m.tip(q), rtol=1e-13)

    def lag_phi(phi):
        qq = np.diff(np.concatenate([[0.0], phi]))
        return m.energy(qq) - F @ m.tip(qq)

    D = np.eye(m.n) - np.eye(m.n, k=-1)          # dq/dphi

    def grad_phi(phi):
        """Analytic numpy gradient (Segment.torque, Manipulator.jacobian) mapped to phi."""
        qq = D @ phi
        return D.T @ (m.gradient(qq) - m.jacobian(qq).T @ F)

    phi = np.cumsum(q)
    # gradient of E alone (F = 0 part) and Lagrangian Hessian
    gE = g
    qJ = m.jacobian(q)
    h = 1e-6
    assert np.allclose(gE - J.T @ F, [(lag_phi(phi + h * e) - lag_phi(phi - h * e)) / (2 * h)
                                      for e in np.eye(m.n)], atol=1e-8)
    assert np.allclose(gE - J.T @ F, grad_phi(phi), atol=1e-12)
    Hfd = np.array([(grad_phi(phi + h * e) - grad_phi(phi - h * e)) / (2 * h) for e in np.eye(m.n)])
    assert np.allclose(H, Hfd, atol=1e-8)
    # H is tridiagonal in absolute angles
    assert np.allclose(np.triu(H, 2), 0) and np.allclose(np.tril(H, -2), 0)
    # Jacobians agree through the chain rule dq/dphi
    T = np.tril(np.ones((m.n, m.n)))
    assert np.allclose(J @ T, qJ, atol=1e-12)


def test_kkt_jacobian_by_finite_differences():
    m = CHAINS[1]
    mdl = chain_solver(m)
    z = np.concatenate([np.cumsum([0.2, -0.1, 0.3]), [-0.5, 0.2]])
    tgt = np.array([5.0, 0.4])
    r, Jr = mdl.kkt(z, tgt)
    Jr = np.asarray(Jr)
    h = 1e-6
    fd = np.column_stack([(np.asarray(mdl.kkt(z + h * e, tgt)[0]).ravel()
                           - np.asarray(mdl.kkt(z - h * e, tgt)[0]).ravel()) / (2 * h)
                          for e in np.eye(z.size)])
    assert np.allclose(Jr, fd, atol=1e-7)
