"""The horizon NLP (numerics/horizon_nlp.py): built once per (n, N, angles), and its rows and objective against the
independent reference model (tests/support/reference_model.py: energy, gradient and Hessian in the joint angles,
written from docs/model.md)."""

from __future__ import annotations

import numpy as np
import pytest
from reference_model import Chain

from tensegrity_opt.numerics.design_nlp import tril_vector
from tensegrity_opt.numerics.horizon_nlp import NORM_SMOOTHING, HorizonNLP, horizon_nlp


def test_built_once_per_shape_and_reused():
    h = horizon_nlp(3, 4)
    assert horizon_nlp(3, 4) is h                     # the second call reuses the built problem
    assert horizon_nlp(3, 4, True) is not h and horizon_nlp(3, 5) is not h
    assert isinstance(h, HorizonNLP) and (h.n, h.N, h.angles, h.pose_size) == (3, 4, False, 2)
    assert h.variables.size == 4 * (3 * 3 + 6 + 2 + 1)
    assert horizon_nlp(3, 4, True).pose_size == 3


def test_rows_and_objective_match_the_reference_model():
    rng = np.random.default_rng(7)
    n, N = 3, 2
    h = horizon_nlp(n, N, True)
    a, b = rng.uniform(0.7, 1.2, n), rng.uniform(0.8, 1.2, n)
    k1, k2 = rng.uniform(0.5, 1.5, n), rng.uniform(0.5, 1.5, n)
    ell0 = rng.uniform(0.9, 1.1, 2 * n)                          # L10 then L20
    Ell = ell0 + rng.uniform(-0.05, 0.05, (N, 2 * n))
    Q = rng.uniform(-0.3, 0.3, (N, n))
    F = rng.uniform(-0.1, 0.1, (N, 2))
    v = rng.uniform(0.5, 2.0, 2 * n)
    w, s, margin = np.array([3.0, 5.0, 2.0]), float(b.max()), 0.01
    E = rng.uniform(-0.1, 0.1, (N, 3))
    Tt = np.linalg.norm(E, axis=1) + 0.2
    Ls = []
    chains = [Chain(a, b, k1, k2, Ell[k, :n], Ell[k, n:]) for k in range(N)]
    for k, ch in enumerate(chains):
        Hq = ch.lagrangian_hess(Q[k], F[k])
        Ls.append(tril_vector(np.linalg.cholesky(Hq - margin * np.eye(n))))
    x = h.variables.pack(phi=np.cumsum(Q, axis=1).ravel(), L10=Ell[:, :n].ravel(), L20=Ell[:, n:].ravel(),
                         L=np.concatenate(Ls), e=E.ravel(), t=Tt.ravel())
    p = h.parameters.pack(a=a, b=b, k1=k1, k2=k2, F=F.ravel(), ell0=ell0, v=v, w=w, scale=s, margin=margin)
    g, f = h.evaluate(x, p)
    rows = h.constraints.unpack(g)
    Tm = np.tril(np.ones((n, n)))
    for k, ch in enumerate(chains):
        # grad E - J^T F in the absolute angles: T^-T times the gradient in the joint angles
        np.testing.assert_allclose(Tm.T @ rows["grad"].reshape(N, n)[k], ch.lagrangian_grad(Q[k], F[k]), atol=1e-12)
        np.testing.assert_allclose(rows["psd"].reshape(N, -1)[k], 0.0, atol=1e-12)      # the factor is exact
        np.testing.assert_allclose(rows["q"].reshape(N, n)[k], Q[k], atol=1e-14)
        L1, L2 = ch.lengths(Q[k])
        np.testing.assert_allclose(rows["stretch1"].reshape(N, n)[k], L1 - Ell[k, :n], atol=1e-13)
        np.testing.assert_allclose(rows["stretch2"].reshape(N, n)[k], L2 - Ell[k, n:], atol=1e-13)
        pose = np.append(ch.tip(Q[k]), s * np.sum(Q[k]))
        np.testing.assert_allclose(rows["pose"].reshape(N, 3)[k], pose - E[k], atol=1e-13)
    np.testing.assert_allclose(rows["rate"].reshape(N, 2 * n), np.diff(np.vstack([ell0, Ell]), axis=0), atol=1e-14)
    d = NORM_SMOOTHING * s
    np.testing.assert_allclose(rows["norm"], Tt - (np.sqrt(np.sum(E ** 2, axis=1) + d * d) - d), atol=1e-15)
    dl = np.diff(np.vstack([ell0, Ell]), axis=0)
    expect = w[0] * np.sum(E ** 2) / s ** 2 + w[1] * np.sum(Tt) / s + w[2] * np.sum(v * dl ** 2) / s ** 2
    assert abs(f - expect) <= 1e-12 * max(1.0, abs(expect))


@pytest.mark.slow
def test_a_prebuilt_problem_warm_solves_in_compiled_code_to_the_same_answer(tmp_path, monkeypatch):
    """prebuild compiles the problem once (into TENSEGRITY_CACHE_DIR); a warm solve then evaluates the compiled
    library and lands where the virtual machine does (the same code, generated); a cold process finds it without
    compiling (compiled_path)."""
    import tensegrity_opt as to
    from tensegrity_opt.analyses.design import horizon as H
    from tensegrity_opt.analyses.design.preload_control import PreloadController
    from tensegrity_opt.numerics import build
    from tensegrity_opt.numerics import horizon_nlp as HN

    monkeypatch.setenv("TENSEGRITY_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.delenv("TENSEGRITY_COMPILE", raising=False)
    if build.compiler() is None:
        pytest.skip("no C compiler")
    n, N = 3, 2
    assert HN.compiled_path(n, N) is None                     # nothing in this cache yet: never compiles
    path = HN.prebuild(n, N)
    assert path and path.startswith(str(tmp_path / "cache"))
    assert HN.compiled_path(n, N) == path

    m = to.Manipulator.uniform(n)
    ctl = PreloadController(m, load=(0.0, -0.01), rate_limit=0.05, dt=1.0)
    tip0 = m.tip(ctl.q)
    T = np.array([tip0 + [-0.02 * k, 0.04 * k] for k in range(1, 5)])
    block = lambda v: np.asarray(v, float).reshape(n, 2).T.ravel()          # noqa: E731
    answers = {}
    for mode in ("compiled", "virtual machine"):
        nlp = HN.HorizonNLP(n, N, False)                      # a fresh problem: its own warm solver
        if mode == "virtual machine":
            nlp._warm, nlp._warm_deadline = HN._nlpsol("vm", nlp._nlp, **{"ipopt.max_iter": 1000,
                                                                           **HN.WARM_OPTIONS})
        c = PreloadController(m, load=(0.0, -0.01), rate_limit=0.05, dt=1.0)
        pl = H._Planner(c, T, np.tile([0.0, -0.01], (4, 1)), None, np.outer(np.ones(4), block(c.rate)), np.ones(4),
                        block(c.w), block(c.lo), block(c.hi), nlp, [], False, None)
        res = pl._solve(0, pl._cold(pl._index(0)))
        warm = pl._shifted(res)
        again = pl._solve(1, warm[0], lam=warm[1])
        assert again.success and nlp.mode == ("compiled" if mode == "compiled" else "virtual machine")
        answers[mode] = again.x
    np.testing.assert_allclose(answers["compiled"], answers["virtual machine"], atol=1e-8)
