"""The arm as a force sensor: :func:`tensegrity_opt.estimate_tip_force`.

Every expected number comes from the independent numpy model ``tests/support/reference_model.py`` (analytic
gradient, tip Jacobian and Hessian in relative angles; no ``tensegrity_opt``), never from the code
under test: the equilibria are found by the library's own solvers (IPOPT / the displacement search, a
code path the estimator does not use) and then re-polished by the reference's Newton method, the
covariances are the Cramer-Rao bound of the linearised model written from the reference's
derivatives (``F -> q(F)`` by implicit differentiation, observed with the angle noise), and the
extra-torque equilibria are solved by the reference alone.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import reference_model as R  # noqa: E402
from scipy.stats import chi2 as chi2_dist

import tensegrity_opt as to  # noqa: E402
from tensegrity_opt import InvalidParameterError, Manipulator, Segment  # noqa: E402

PAPER5 = Manipulator.uniform(5)
HETERO = Manipulator([Segment(1.0, 1.0, 1.0, 1.0), Segment(0.9, 1.3, 2.0, 1.5), Segment(1.1, 0.8, 0.7, 0.9),
                      Segment(1.0, 1.1, 1.5, 1.2), Segment(0.7, 0.6, 1.0, 1.0)])


def ref_chain(m: Manipulator) -> R.Chain:
    """The reference model of the same chain (its parameters only)."""
    return R.Chain(m.a.copy(), m.b.copy(), m.k1.copy(), m.k2.copy(), m.L1_0.copy(), m.L2_0.copy())


def equilibrium_under(m: Manipulator, F) -> np.ndarray:
    """An equilibrium under the dead tip load ``F``: the library's IPOPT start, polished by the
    reference Newton method, checked in the reference model."""
    ch = ref_chain(m)
    F = np.asarray(F, float)
    q, ok = ch.newton_force(F, to.solve_equilibrium_under_force(m, *F).q)
    assert ok and ch.in_range(q, 1e-6)
    assert np.abs(ch.lagrangian_grad(q, F)).max() < 1e-12
    return q


def reference_cov(m: Manipulator, q, F, Sigma, measured=None):
    """Cramer-Rao bound of (F, hidden angles): the equilibrium ``q(F)`` (``A dq = J^T dF``, ``A`` the
    reference Hessian of ``E - F.tip``) observed at the measured joints with covariance ``Sigma``."""
    ch = ref_chain(m)
    n = m.n
    idx = np.arange(n) if measured is None else np.asarray(measured)
    hid = np.setdiff1d(np.arange(n), idx)
    G = np.linalg.solve(ch.lagrangian_hess(q, F), ch.jac(q).T)        # dq/dF (n x 2)
    CF = np.linalg.inv(G[idx].T @ np.linalg.solve(Sigma, G[idx]))
    return CF, G[hid] @ CF @ G[hid].T


def random_chain(family: str, rng) -> Manipulator:
    n = int(rng.integers(4, 7))
    if family == "monotonic":
        a, k = rng.uniform(0.6, 1.0), rng.uniform(0.5, 2.0)
        L0 = 2.0 * (1.0 - a * a) + rng.uniform(0.1, 0.8)      # condition (4), b = 1: K > 0
        return Manipulator.uniform(n, a=a, b=1.0, k=k, L0=L0)
    if family == "bistable":                                    # K = k (b L0 - 2 (b^2 - a^2)) < 0
        return Manipulator.uniform(n, a=rng.uniform(0.45, 0.55), b=1.0, k=1.0, L0=rng.uniform(0.9, 1.1))
    if family == "heterogeneous":
        return Manipulator([Segment(rng.uniform(0.7, 1.2), rng.uniform(0.7, 1.3), rng.uniform(0.5, 2.0),
                                    rng.uniform(1.0, 1.6)) for _ in range(n)])
    if family == "asymmetric":                                  # pre-bent: unequal preloads
        return Manipulator.uniform(n, L0=(1.05, 0.95))
    raise AssertionError(family)


# ------------------------------------------------------------------------------------------- exactness
CASES = [(fam, seed) for fam in ("monotonic", "bistable", "heterogeneous", "asymmetric") for seed in range(3)]


@pytest.mark.parametrize("family,seed", CASES)
def test_exact_angles_give_the_force_exactly(family, seed):
    rng = np.random.default_rng(100 + seed + 10 * CASES.index((family, seed)))
    m = random_chain(family, rng)
    ch = ref_chain(m)
    theta = rng.uniform(0.0, 2.0 * math.pi)
    scale = 0.2 * float(np.abs(m.stiffness).max()) / m.b.sum()
    for t in (1.0, 0.5, 0.25, 0.1):                  # the largest load with an equilibrium in range
        F = t * scale * np.array([math.cos(theta), math.sin(theta)])
        try:
            q = equilibrium_under(m, F)
            break
        except (to.TensegrityError, AssertionError):
            continue
    else:
        pytest.fail("no equilibrium found for this chain")
    _check_exact(m, ch, q, F)


def _check_exact(m, ch, q, F):
    ts = m.torque_scale
    plain = to.estimate_tip_force(m, q)
    assert plain.success and plain.status == "least_squares"
    assert np.abs(plain.force - F).max() <= 1e-9 * max(1.0, np.abs(F).max())
    assert plain.residual_norm <= 1e-10 * ts
    assert plain.covariance is None and plain.chi2 is None and plain.p_value is None and plain.joint_chi2 is None
    assert plain.dof == m.n - 2 and np.array_equal(plain.q, q)
    sigma = 1e-3
    est = to.estimate_tip_force(m, q, sigma_q=sigma)
    assert est.success and est.status == "generalized_least_squares"
    assert np.abs(est.force - F).max() <= 1e-9 * max(1.0, np.abs(F).max())
    assert np.abs(est.residual_torque).max() <= 1e-10 * ts
    assert est.p_value > 0.5
    CF, _ = reference_cov(m, q, F, sigma ** 2 * np.eye(m.n))
    assert np.allclose(est.covariance, CF, rtol=1e-6, atol=1e-12 * np.abs(CF).max())
    # the brief's form of the same matrix: (J W J^T)^-1, W = (A Sigma A^T)^-1
    A, J = ch.lagrangian_hess(q, F), ch.jac(q)
    W = np.linalg.inv(sigma ** 2 * A @ A.T)
    assert np.allclose(est.covariance, np.linalg.inv(J @ W @ J.T), rtol=1e-6)
    json.dumps(est.to_dict(), allow_nan=False)
    json.dumps(plain.to_dict(), allow_nan=False)


def test_the_rest_configuration_of_a_pre_bent_chain_reads_zero_force():
    m = Manipulator.uniform(4, L0=(1.05, 0.95))
    ch = ref_chain(m)
    q, ok = ch.newton_force(np.zeros(2), to.rest_configuration(m).q)
    assert ok and np.all(np.abs(q) > 0.05)              # bent by its preloads
    est = to.estimate_tip_force(m, q, sigma_q=1e-3)
    assert np.abs(est.force).max() < 1e-12 and est.p_value > 0.5


@pytest.mark.parametrize("dx,dy,kind", [(2.5, -2.0, "minimum"), (1.5, 3.0, "minimum"), (0.2, 0.1, "saddle")])
def test_large_deflections_and_unstable_equilibria(dx, dy, kind):
    """Displacement control (the least-energy search, or every equilibrium for the saddle), re-solved
    by the reference KKT Newton: the estimator needs an equilibrium, not a stable one."""
    m = Manipulator.uniform(4)
    ch = ref_chain(m)
    if kind == "minimum":
        eq = to.solve_equilibrium(m, dx, dy)
    else:
        eq = next(e for e in to.find_equilibria(m, dx, dy) if e.kind == "saddle")
    q, F, ok = ch.newton_kkt(ch.target(dx, dy), eq.q, eq.force)
    assert ok and ch.in_range(q)
    _check_exact(m, ch, q, F)


# ------------------------------------------------------------------------------------------- coverage
def _draws(m, q, F, Sigma, N, seed, measured=None):
    rng = np.random.default_rng(seed)
    L = np.linalg.cholesky(Sigma)
    idx = np.arange(m.n) if measured is None else np.asarray(measured)
    k = idx.size
    crit = chi2_dist.ppf(0.95, 2)
    Fs, H, chis, ps, cover = [], [], [], [], 0
    for _ in range(N):
        qm = q[idx] + L @ rng.standard_normal(k)
        e = to.estimate_tip_force(m, qm, sigma_q=Sigma, measured=measured)
        assert e.success
        d = e.force - F
        cover += float(d @ np.linalg.solve(e.covariance, d)) <= crit
        Fs.append(e.force)
        H.append(e.q[np.setdiff1d(np.arange(m.n), idx)])
        chis.append(e.chi2)
        ps.append(e.p_value if e.p_value is not None else 1.0)
    return np.array(Fs), np.array(H), np.array(chis), np.array(ps), cover / N


def _close_cov(emp, C, tol=0.1):
    s = np.sqrt(np.diag(C))
    return bool(np.all(np.abs(emp - C) <= tol * np.outer(s, s)))


@pytest.mark.slow
def test_coverage_of_the_stated_covariance_and_the_chi2_null_distribution():
    m, F = PAPER5, np.array([-0.15, 0.25])
    q = equilibrium_under(m, F)
    sigma = 2e-4
    Sigma = sigma ** 2 * np.eye(5)
    CF, _ = reference_cov(m, q, F, Sigma)
    Fs, _, chis, ps, cover = _draws(m, q, F, Sigma, 2000, seed=1)
    assert _close_cov(np.cov(Fs.T), CF)                        # measured: within 4.7 % per entry
    assert 0.93 <= cover <= 0.97                               # measured: 0.9525
    assert abs(chis.mean() - 3.0) < 0.25                       # chi2(n - 2): mean 3; measured 3.03
    assert 0.035 <= np.mean(ps < 0.05) <= 0.065                # measured: 0.0535
    assert np.all(np.abs(Fs.mean(axis=0) - F) < 0.1 * np.sqrt(np.diag(CF)))   # bias << noise


@pytest.mark.slow
def test_coverage_with_per_joint_and_correlated_noise():
    m, F = HETERO, np.array([0.1, -0.2])
    q = equilibrium_under(m, F)
    s = np.array([1e-4, 3e-4, 2e-4, 1e-4, 4e-4])
    corr = 0.6 ** np.abs(np.subtract.outer(np.arange(5), np.arange(5)))
    for Sigma, sigma_q in ((np.diag(s ** 2), s), (corr * np.outer(s, s), corr * np.outer(s, s))):
        CF, _ = reference_cov(m, q, F, Sigma)
        est = to.estimate_tip_force(m, q, sigma_q=sigma_q)
        assert np.allclose(est.covariance, CF, rtol=1e-6)
        Fs, _, chis, _, cover = _draws(m, q, F, Sigma, 1000, seed=2)
        assert _close_cov(np.cov(Fs.T), CF)
        assert 0.93 <= cover <= 0.97
        assert abs(chis.mean() - 3.0) < 0.3


@pytest.mark.slow
def test_coverage_with_a_hidden_joint():
    m, F = PAPER5, np.array([-0.15, 0.25])
    q = equilibrium_under(m, F)
    sigma, meas = 2e-4, [0, 1, 3, 4]
    Sigma = sigma ** 2 * np.eye(4)
    CF, CH = reference_cov(m, q, F, Sigma, meas)
    est = to.estimate_tip_force(m, q[meas], sigma_q=sigma, measured=meas)
    assert np.allclose(est.covariance, CF, rtol=1e-6) and np.allclose(est.hidden_covariance, CH, rtol=1e-6)
    Fs, H, chis, _, cover = _draws(m, q, F, Sigma, 1000, seed=3, measured=meas)
    assert _close_cov(np.cov(Fs.T), CF)
    assert abs(H[:, 0].var() / CH[0, 0] - 1.0) < 0.1
    assert 0.93 <= cover <= 0.97
    assert abs(chis.mean() - 2.0) < 0.25                       # n - 2 - 1 degrees of freedom


# ------------------------------------------------------------------------------------------- a load elsewhere
def _with_extra_torque(ch, q, F, tau_ext):
    """The reference equilibrium ``grad E = J^T F + tau_ext`` (Newton from the tip-force-only one)."""
    for _ in range(60):
        r = ch.lagrangian_grad(q, F) - tau_ext
        if np.abs(r).max() < 1e-14:
            break
        q = q - np.linalg.solve(ch.lagrangian_hess(q, F), r)
    assert np.abs(ch.lagrangian_grad(q, F) - tau_ext).max() < 1e-13 and ch.in_range(q)
    return q


@pytest.mark.parametrize("j", range(5))
def test_a_torque_at_one_joint_is_detected_and_located(j):
    m, F = PAPER5, np.array([-0.15, 0.25])
    ch = ref_chain(m)
    q0 = equilibrium_under(m, F)
    ext = np.zeros(5)
    ext[j] = 0.01
    q = _with_extra_torque(ch, q0, F, ext)
    # exact angles, no noise model: F_hat and the residual are the least-squares projections of ext
    J = ch.jac(q)
    plain = to.estimate_tip_force(m, q)
    assert np.allclose(plain.force, F + np.linalg.solve(J @ J.T, J @ ext), rtol=0, atol=1e-12)
    assert np.allclose(plain.residual_torque, ext - J.T @ np.linalg.solve(J @ J.T, J @ ext), rtol=0, atol=1e-12)
    # noisy angles: the test rejects, and the per-joint statistic points at joint j
    sigma = 1e-4
    qn = q + sigma * np.random.default_rng(10 + j).standard_normal(5)
    est = to.estimate_tip_force(m, qn, sigma_q=sigma)
    assert est.p_value < 1e-12
    assert int(np.argmax(est.joint_chi2)) == j
    assert est.joint_chi2[j] > 0.9 * est.chi2                 # one torque at j explains almost all of chi2
    # ... and the same angles without the extra torque pass
    null = to.estimate_tip_force(m, q0 + (qn - q), sigma_q=sigma)
    assert null.p_value > 1e-3


def test_a_contact_force_along_the_arm_is_detected():
    """A force at joint 3 (not at the tip) loads joints 1-3 only: no tip force explains that."""
    m, F = PAPER5, np.array([-0.15, 0.25])
    ch = ref_chain(m)
    q0 = equilibrium_under(m, F)
    Fc = np.array([0.0, -0.02])

    def joint3(qq):                                # position of joint 3 (after links 1 and 2)
        phi = np.cumsum(qq)
        lk = ch.links
        return np.array([ch.b[0] + lk[0] * np.cos(phi[0]) + lk[1] * np.cos(phi[1]),
                         lk[0] * np.sin(phi[0]) + lk[1] * np.sin(phi[1])])

    q = q0.copy()
    for _ in range(60):                            # grad E = J^T F + J3^T Fc; J3 by central differences
        h = 1e-6
        J3 = np.column_stack([(joint3(q + h * e) - joint3(q - h * e)) / (2 * h) for e in np.eye(5)])
        q = q - np.linalg.solve(ch.lagrangian_hess(q, F), ch.lagrangian_grad(q, F) - J3.T @ Fc)
    sigma = 1e-4
    qn = q + sigma * np.random.default_rng(7).standard_normal(5)
    est = to.estimate_tip_force(m, qn, sigma_q=sigma)
    assert est.p_value < 1e-12
    assert int(np.argmax(est.joint_chi2)) <= 2                # somewhere at joints 1-3


# ------------------------------------------------------------------------------------------- partial measurement
@pytest.mark.parametrize("m,F", [(PAPER5, (-0.15, 0.25)), (HETERO, (0.1, -0.2)), (PAPER5, (0.05, 0.6))])
@pytest.mark.parametrize("hidden", [[2], [0], [4], [1, 3], [0, 4], [1, 2, 3]])
def test_hidden_joints_are_recovered_from_exact_data(m, F, hidden):
    F = np.asarray(F, float)
    q = equilibrium_under(m, F)
    meas = [i for i in range(5) if i not in hidden]
    for form in ("values", "full", "mask"):
        if form == "values":
            e = to.estimate_tip_force(m, q[meas], measured=meas)
        elif form == "full":
            qs = q.copy()
            qs[hidden] = np.nan                       # start at 0
            e = to.estimate_tip_force(m, qs, measured=meas)
        else:
            e = to.estimate_tip_force(m, q, measured=np.isin(np.arange(5), meas), sigma_q=1e-3)
        assert e.success
        assert np.abs(e.force - F).max() < 1e-8
        assert np.abs(e.q - q).max() < 1e-8
        assert m.in_range(e.q) and e.measured == tuple(meas)
        assert e.dof == 5 - 2 - len(hidden)
        assert np.array_equal(e.q[meas], q[meas])      # measured angles reported as given
    if len(hidden) < 3:
        assert e.p_value > 0.5
    else:
        assert e.p_value is None and e.chi2 < 1e-12      # square system: nothing to test


@pytest.mark.parametrize("n,meas", [(5, [0]), (5, []), (4, [1]), (3, [0]), (2, [1])])
def test_fewer_equations_than_unknowns_is_refused(n, meas):
    m = Manipulator.uniform(n)
    q = np.full(n, 0.2)
    with pytest.raises(InvalidParameterError) as e:
        to.estimate_tip_force(m, q, measured=meas)
    assert e.value.field == "measured"


@pytest.mark.parametrize("measured", [None, [0, 1, 2, 3], [1, 2, 4]])
def test_angles_of_no_equilibrium_are_rejected_and_never_leave_the_range(measured):
    """Random angles (no tip force holds them): an answer keeps every angle inside the physical range and
    fails the test; a refusal is a SolverError (no configuration in the range explains them)."""
    m = Manipulator.uniform(5, a=0.8)
    rng = np.random.default_rng(11)
    idx = list(range(5)) if measured is None else measured
    answered = 0
    for _ in range(20):
        q = rng.uniform(-0.9, 0.9, 5) * m.joint_limits
        try:
            e = to.estimate_tip_force(m, q[idx], sigma_q=1e-3, measured=measured)
        except to.SolverError:
            assert measured is not None               # every joint measured: always an answer
            continue
        answered += 1
        assert m.in_range(e.q) and np.array_equal(e.q[idx], q[idx])
        assert e.p_value < 1e-6
        assert e.success or e.status == "reweighting_not_converged"
        json.dumps(e.to_dict(), allow_nan=False)
    assert answered >= 10


# ------------------------------------------------------------------------------------------- validation
GOOD = np.array([0.3, 0.2, 0.1, 0.05, 0.02])


@pytest.mark.parametrize("kwargs,field", [
    ({"q_measured": GOOD[:4]}, "q_measured"),
    ({"q_measured": np.r_[GOOD[:4], np.nan]}, "q_measured"),
    ({"q_measured": np.r_[GOOD[:4], np.inf]}, "q_measured"),
    ({"q_measured": np.r_[GOOD[:4], math.pi / 2]}, "q_measured"),          # on the limit pi - 2 beta
    ({"q_measured": np.r_[-1.6, GOOD[1:]]}, "q_measured"),                  # beyond it
    ({"q_measured": np.r_[GOOD[:4], 2.0], "measured": [0, 1, 2, 3]}, "q_measured"),   # the hidden start
    ({"q_measured": "abc"}, "q_measured"),
    ({"q_measured": np.zeros(5)}, "q_measured"),                            # straight: Fx makes no torque
    ({"q_measured": np.r_[0.4, 0.0, 0.0, 0.0, 0.0]}, "q_measured"),         # collinear links
    ({"sigma_q": 0.0}, "sigma_q"),
    ({"sigma_q": -1e-3}, "sigma_q"),
    ({"sigma_q": np.nan}, "sigma_q"),
    ({"sigma_q": [1e-3] * 4}, "sigma_q"),
    ({"sigma_q": [1e-3, 1e-3, 0.0, 1e-3, 1e-3]}, "sigma_q"),
    ({"sigma_q": np.ones((4, 4))}, "sigma_q"),
    ({"sigma_q": np.triu(np.ones((5, 5)))}, "sigma_q"),                     # not symmetric
    ({"sigma_q": -np.eye(5)}, "sigma_q"),
    ({"sigma_q": np.diag([1, 1, 1, 1, 0.0])}, "sigma_q"),
    ({"sigma_q": np.ones((5, 2))}, "sigma_q"),
    ({"sigma_q": np.eye(5) - 0.6 * np.ones((5, 5)) + 0.6 * np.eye(5)}, "sigma_q"),   # indefinite
    ({"sigma_q": np.ones((5, 5, 1))}, "sigma_q"),
    ({"measured": [True, False]}, "measured"),
    ({"measured": [0, 5]}, "measured"),
    ({"measured": [-1, 0, 1]}, "measured"),
    ({"measured": [0, 1, 1, 2]}, "measured"),
    ({"measured": [0.0, 1.0, 2.0]}, "measured"),
    ({"measured": [[0, 1, 2]]}, "measured"),
])
def test_bad_inputs_name_the_field(kwargs, field):
    args = {"q_measured": GOOD, **kwargs}
    with pytest.raises(InvalidParameterError) as e:
        to.estimate_tip_force(PAPER5, args.pop("q_measured"), **args)
    assert e.value.field == field
    assert isinstance(e.value, ValueError)


def test_a_chain_of_one_joint_and_a_non_manipulator_are_refused():
    with pytest.raises(InvalidParameterError) as e:
        to.estimate_tip_force(Manipulator.uniform(1), [0.2])
    assert e.value.field == "n"
    with pytest.raises(InvalidParameterError) as e:
        to.estimate_tip_force({"n": 4}, GOOD[:4])
    assert e.value.field == "m"


def test_two_joints_determine_the_force_with_nothing_to_test():
    m = Manipulator.uniform(2)
    F = np.array([0.1, 0.2])
    q = equilibrium_under(m, F)
    e = to.estimate_tip_force(m, q, sigma_q=1e-3)
    assert np.abs(e.force - F).max() < 1e-12 and e.dof == 0 and e.p_value is None
    CF, _ = reference_cov(m, q, F, 1e-6 * np.eye(2))
    assert np.allclose(e.covariance, CF, rtol=1e-6)


def test_to_dict_is_json():
    q = equilibrium_under(PAPER5, (-0.15, 0.25))
    d = to.estimate_tip_force(PAPER5, q[[0, 1, 3, 4]], sigma_q=1e-3, measured=[0, 1, 3, 4]).to_dict()
    json.dumps(d, allow_nan=False)
    assert list(d)[:3] == ["success", "status", "message"]
    assert set(d) == {"force", "covariance", "residual_torque", "residual_norm", "chi2", "dof", "p_value",
                      "joint_chi2", "q", "measured", "hidden_covariance", "success", "status", "message",
                      "iterations", "spring_lengths", "spring_stretches", "spring_forces", "spring_states"}
    assert d["measured"] == [0, 1, 3, 4] and len(d["q"]) == 5 and len(d["hidden_covariance"]) == 1
    assert d["status"] == "weighted_gauss_newton" and d["dof"] == 2
