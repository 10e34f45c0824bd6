"""Long chains: the sparse/banded routes against the dense ones on the same problems."""

import numpy as np
import pytest

import tensegrity_opt as to
from tensegrity_opt.analyses.equilibria.stability import inertia_of
from tensegrity_opt.numerics import ChainFunctions, ChainSolver, chain_solver


def wavy_chain(n):
    return to.Manipulator([to.Segment(0.9 + 0.1 * np.sin(i), 1 + 0.2 * np.cos(i), 1 + 0.5 * np.sin(2 * i) ** 2, 1.4)
                           for i in range(n)])


@pytest.mark.parametrize("boundary", ["guided", "free"])
def test_sparse_critical_loads_match_dense(boundary):
    m = wavy_chain(150)
    dense = to.critical_force(m, boundary, method="reduced")
    sparse = to.critical_force(m, boundary, method="sparse", n_modes=6)
    assert np.allclose(sparse.loads, dense.loads[:6], rtol=1e-9)
    for a, b in zip(dense.modes[:6], sparse.modes):
        assert np.allclose(a.vector, b.vector, atol=1e-8)
        assert a.fy == pytest.approx(b.fy, rel=1e-7, abs=1e-12)
        assert a.mu_x == pytest.approx(b.mu_x, rel=1e-9)


def test_uniform_chain_loads_scale_like_a_column():
    """A long uniform guided chain is a discrete column: P_1 n^2 tends to a constant."""
    p = [to.critical_force(to.Manipulator.uniform(n)).loads[0] * n * n for n in (250, 500, 1000)]
    assert p[2] == pytest.approx(p[1], rel=2e-3) and p[1] == pytest.approx(p[0], rel=1e-2)


@pytest.fixture
def both_models():
    n = 80
    m = wavy_chain(n)
    dense_model = ChainSolver(ChainFunctions(n, "dense"), m)     # the dense route beyond DENSE_MAX, for comparison
    banded_model = ChainSolver(ChainFunctions(n), m)
    assert dense_model.dense and not banded_model.dense
    return m, dense_model, banded_model


def test_banded_newton_classification_and_stiffness_match_dense(both_models):
    m, dm, bm = both_models
    eq = to.solve_equilibrium(m, 3.0, 2.0)          # uses the banded model (n = 80 > 64)
    target = eq.tip
    q0 = eq.q * 1.05
    rd = dm.newton_kkt(target, q0)
    rb = bm.newton_kkt(target, q0)
    assert rd.success and rb.success
    assert np.allclose(rd.q, rb.q, atol=1e-10) and np.allclose(rd.force, rb.force, atol=1e-12)
    for F in (eq.force, np.array([-0.3, 0.2])):
        Ed, gd, Hd, Jd, td = dm.evaluate(eq.q, F)
        Eb, gb, Hb, Jb, tb = bm.evaluate(eq.q, F)
        assert Ed == pytest.approx(Eb, rel=1e-13)
        assert np.allclose(gd, gb, atol=1e-12) and np.allclose(Hd, Hb.toarray(), atol=1e-12)
        assert np.allclose(Jd, Jb, atol=1e-13) and np.allclose(td, tb, atol=1e-12)
        for constrained in (True, False):
            a = inertia_of(Hd, Jd, constrained, 1e-9, m.n - 2 if constrained else m.n)
            b = inertia_of(Hb, Jb, constrained, 1e-9, m.n - 2 if constrained else m.n)
            assert a.morse_index == b.morse_index and a.stable == b.stable
    assert np.allclose(dm.tangent_stiffness(eq.q, eq.force),
                       bm.tangent_stiffness(eq.q, eq.force), rtol=1e-8)


def test_unstable_equilibria_are_classified_alike(both_models):
    m, dm, bm = both_models
    eqs = to.find_equilibria(m, 0.5, n_random=0, max_modes=3, amplitudes=(1.0,))
    assert sorted(e.morse_index for e in eqs)[:6] == [0, 0, 1, 1, 2, 2]
    for e in eqs:
        _, _, Hd, Jd, _ = dm.evaluate(e.q, e.force)
        assert inertia_of(Hd, Jd, True, 1e-9, m.n - 2).morse_index == e.morse_index


@pytest.mark.slow
def test_long_chain_force_control_and_curve():
    m = to.Manipulator.uniform(200)
    free = to.critical_force(m, "free", n_modes=1).loads[0]
    eq = to.solve_equilibrium_under_force(m, -1.5 * free, 0.0)
    assert eq.stable and np.abs(eq.q).max() > 1e-3
    assert m.equilibrium_residual(eq.q, eq.force) < 1e-9
    c = to.force_deflection(m, np.linspace(0.0, 4.0, 9))
    assert c.stable.all() and c.fx[1] == pytest.approx(-to.critical_force(m).loads[0], rel=2e-2)


def test_seed_results_of_a_long_chain_hold_no_dense_reduced_hessians():
    """Without kernels (n > 8) the seed results carry no reduced Hessians: for n = 10000 a (k, n-2, n-2)
    array would be 800 MB a start (it once was, and the n = 10000 solve took 1.8 s instead of 0.2 s)."""
    from tensegrity_opt.analyses.equilibria.seeds import seed_starts

    m = to.Manipulator.uniform(300)
    dx = 0.05 * m.straight_length
    b = chain_solver(m).newton_kkt_seeds(m.target(dx, 0.0),
                                         seed_starts(m, dx, 0.0, max_modes=2, n_random=0, arcs=False))
    assert b.reduced_hessian is None and b.q.shape == (4, 300) and b.success.any()
    assert all(b.result(j).reduced_hessian is None for j in range(4))
