"""The strongest chain (analyses/design/strongest.py), each design checked by an independent computation: the
paper's numbers, closed forms, the reference model's critical loads, SLSQP on the same problem."""

import numpy as np
import pytest
import reference_model as R  # noqa: E402
import scipy.linalg as sla
import scipy.optimize as so

import tensegrity_opt as to
from tensegrity_opt.analyses.design.strongest import K_FLOOR_REL, maximize_critical_force
from tensegrity_opt.errors import InfeasibleDesignError

PAPER = to.Manipulator.uniform(4)
P_UNIT = 0.572793          # docs/model.md: critical load of the paper's chain with K = 1


def test_uniform_preload_optimum_is_analytic():
    """Uniform chain, vary L0 in [0.5, 1.5]: K = k (b L0 - 2 (b^2 - a^2)) grows with L0, and the
    load scales with K: the optimum is L0 = 1.5 everywhere, P = 1.5 * 0.572793."""
    d = maximize_critical_force(PAPER, vary=("L0",), bounds={"L0": (0.5, 1.5)})
    assert np.allclose(d.manipulator.L1_0, 1.5, atol=1e-7)
    assert d.load == pytest.approx(1.5 * P_UNIT, rel=1e-5)
    assert -to.critical_force(d.manipulator).force == pytest.approx(1.5 * P_UNIT, rel=1e-5)
    assert d.multiplicity == 1 and d.success and d.status == "optimal" and d.feasible
    assert sorted(d.active) == sorted(f"L0[{i}] <= 1.5" for i in range(4))


def test_two_segment_stiffness_allocation_is_a_linear_program():
    """n = 2 guided: Z = (1, -3), Z^T G Z = 6 b, so P = (K1 + 9 K2) / (6 b) with K_i = k_i here.
    Budget k1 + k2 <= 2, k >= 0.1: all the spare stiffness goes to segment 2, P = (0.1 + 9*1.9)/6."""
    m = to.Manipulator.uniform(2)
    d = maximize_critical_force(m, vary=("k",), bounds={"k": (0.1, 10.0)}, budget={"k": 2.0})
    assert np.allclose(d.manipulator.k1, [0.1, 1.9], atol=1e-6)
    assert d.load == pytest.approx((0.1 + 9 * 1.9) / 6, rel=1e-6)
    assert "sum(k) <= 2" in d.active and "k[0] >= 0.1" in d.active


def test_reference_nonuniform_optimum_beats_the_best_uniform_chain():
    """n = 6, vary the half-lengths b with the total length 2 sum(b) = 12 fixed: the only uniform
    chain is b = 1; the optimum is non-uniform, ~10.9 % stronger, with a double critical load."""
    m = to.Manipulator.uniform(6)
    uniform = -to.critical_force(m).force
    d = maximize_critical_force(m, vary=("b",), bounds={"b": (0.3, 3.0)}, total_length=True)
    # the design reports the reduced form's loads; check them by the paper's B^-1 A form
    recomputed = to.critical_force(d.manipulator, method="paper")
    assert d.manipulator.straight_length == pytest.approx(12.0, abs=1e-8)
    assert -recomputed.force == pytest.approx(d.load, rel=1e-9)
    assert -recomputed.force > 1.10 * uniform
    assert d.multiplicity == 2
    assert recomputed.loads[1] == pytest.approx(recomputed.loads[0], rel=1e-4)
    # the stiffness budget case: 20 % stronger than the uniform chain with the same sum(k)
    d = maximize_critical_force(PAPER, vary=("k",), bounds={"k": (0.2, 5.0)}, budget={"k": 4.0})
    assert d.manipulator.k1.sum() == pytest.approx(4.0, abs=1e-7)
    assert -to.critical_force(d.manipulator).force > 1.2 * P_UNIT


def test_constraints_tension_and_joint_stiffness():
    d = maximize_critical_force(PAPER, vary=("k", "L0"), bounds={"k": (0.5, 2.0), "L0": (0.5, 1.9)},
                                budget={"k": 4.0}, tension=(0.2, 1.0), K_min=0.8)
    m = d.manipulator
    tension = m.k1 * (2 * m.b - m.L1_0)
    assert np.all(tension >= 0.2 - 1e-7) and np.all(tension <= 1.0 + 1e-7)
    assert np.all(m.stiffness >= 0.8 - 1e-7)
    assert m.k1.sum() <= 4.0 + 1e-7
    assert -to.critical_force(m, method="paper").force == pytest.approx(d.load, rel=1e-9)


# An optimum at K_i -> 0+. a = 0.8, b = 1: K = k (L0 - 0.72). With both budgets binding, the strongest
# guided chain takes the stiffness and the preload off segment 1 (k_1 to its bound 0.2, L0_1 to 0.72,
# K_1 = 0: a guided chain keeps a positive load with one K_i = 0) and gives them to the others. Without
# a K floor the optimiser would stop at K_1 = -1e-10, not a valid chain.
K0_CHAIN = to.Manipulator.uniform(5, a=0.8, b=1.0, k=1.0, L0=1.0)
K0_CALL = dict(vary=("k", "L0"), budget={"k": 5.0, "L0": 5.0}, bounds={"k": (0.2, 5.0), "L0": (0.2, 2.0)})
K0_LOAD = 0.1702862        # this case's optimum (the SLSQP scan below finds it independently)


def _reference_load(m):
    """Guided critical load of a chain from the reference model only: K, G, S0 by finite differences
    of its energy and tip, then the smallest P of Z^T K Z v = P Z^T G Z v on Z = null(S0^T)."""
    chain = R.Chain.from_segments([(s.a, s.b, s.k1, s.L1_0) for s in m.segments])
    K, G, S0 = R.fd_second_derivs(chain)
    Z = sla.null_space(S0[None, :])
    return float(sla.eigh(Z.T @ np.diag(K) @ Z, Z.T @ G @ Z, eigvals_only=True)[0])


def _slsqp_optimum(a, b, n, k_bounds, L0_bounds, k_budget, L0_budget, K_lower, starts, seed=0):
    """max over (k, L0) of the guided critical load (closed-form K, the pencil in plain numpy) subject to
    the same bounds and budgets and K_i >= K_lower, by SLSQP from random starts. Returns (load, k, L0)."""
    links = np.array([2 * b] * (n - 1) + [b])
    T = np.tril(np.ones((n, n)))
    G = T.T @ np.diag(links) @ T
    Z = sla.null_space((T.T @ links)[None, :])
    ZGZ = Z.T @ G @ Z
    c = 2 * (b * b - a * a)

    def Kof(x):
        return x[:n] * (b * x[n:] - c)

    def neg_load(x):
        w, V = sla.eigh(Z.T @ np.diag(Kof(x)) @ Z, ZGZ)
        zv2 = (Z @ V[:, 0]) ** 2                       # dP/dK_i, V normalised by ZGZ
        return -w[0], -np.concatenate([zv2 * (b * x[n:] - c), zv2 * x[:n] * b])

    cons = [{"type": "ineq", "fun": lambda x: k_budget - x[:n].sum(),
             "jac": lambda x: np.concatenate([-np.ones(n), np.zeros(n)])},
            {"type": "ineq", "fun": lambda x: L0_budget - x[n:].sum(),
             "jac": lambda x: np.concatenate([np.zeros(n), -np.ones(n)])},
            {"type": "ineq", "fun": lambda x: Kof(x) - K_lower,
             "jac": lambda x: np.hstack([np.diag(b * x[n:] - c), np.diag(x[:n] * b)])}]
    bnds = [k_bounds] * n + [L0_bounds] * n
    lo, hi = np.array(bnds).T
    rng = np.random.default_rng(seed)
    best = None
    for _ in range(starts):
        x0 = np.concatenate([rng.uniform(0.5, 1.0, n) * k_budget / n, rng.uniform(0.9, 1.0, n) * L0_budget / n])
        r = so.minimize(neg_load, np.clip(x0, lo, hi), jac=True, method="SLSQP", bounds=bnds, constraints=cons,
                        options={"ftol": 1e-14, "maxiter": 500})
        x = r.x
        ok = (np.all(Kof(x) >= K_lower - 1e-9) and x[:n].sum() <= k_budget + 1e-9
              and x[n:].sum() <= L0_budget + 1e-9)
        if ok and (best is None or -r.fun > best[0]):
            best = (-r.fun, x[:n], x[n:])
    return best


def test_optimum_at_zero_joint_stiffness_is_returned():
    d = maximize_critical_force(K0_CHAIN, **K0_CALL)
    m = d.manipulator
    assert d.success and d.status == "optimal" and d.solver.status == "Solve_Succeeded"
    assert "critical load" in d.message and d.to_dict()["solver"] == d.solver.to_dict()
    # the default floor on K (condition (4) as a constraint), recorded in the result
    assert d.K_min == pytest.approx(K_FLOOR_REL * 1.0 * (0.8 ** 2 + 1.0 ** 2), rel=1e-12)
    K = m.stiffness
    assert np.all(K >= d.K_min)                     # exactly: IPOPT's K_1 ~ K_min - 1e-9 is lifted
    assert K[1] == pytest.approx(d.K_min, rel=1e-6)  # the sacrificed segment sits on the floor
    assert f"K[1] >= {d.K_min:.6g}" in d.active
    assert m.k1[1] == pytest.approx(0.2, abs=1e-8) and m.L1_0[1] == pytest.approx(0.72, abs=1e-7)
    assert m.k1.sum() <= 5.0 + 1e-7 and m.L1_0.sum() <= 5.0 + 1e-7
    assert np.all(m.L1_0 >= 0.2) and np.all(m.L1_0 <= 2.0) and np.all(m.k1 >= 0.2) and np.all(m.k1 <= 5.0)
    # the reported load is the returned chain's, recomputed independently
    assert _reference_load(m) == pytest.approx(d.load, rel=1e-7)
    assert -to.critical_force(m).force == pytest.approx(d.load, rel=1e-12)
    assert d.load == pytest.approx(K0_LOAD, rel=1e-6)
    # ... and it is the optimum over the same variables and constraints (K_i >= 0, its closure):
    # SLSQP from random starts reaches it, never beats it, and also puts segment 1 on K = 0
    best, k, L0 = _slsqp_optimum(0.8, 1.0, 5, (0.2, 5.0), (0.2, 2.0), 5.0, 5.0, 0.0, starts=8)
    assert best <= d.load * (1 + 1e-7)
    assert best == pytest.approx(d.load, rel=1e-5)
    assert k[1] * (L0[1] - 0.72) < 1e-6
    # an explicit K_min below the floor is raised to it: the same design
    d0 = maximize_critical_force(K0_CHAIN, **K0_CALL, K_min=0.0)
    assert d0.K_min == d.K_min and d0.load == pytest.approx(d.load, rel=1e-9)


def test_explicit_joint_stiffness_floor_is_respected():
    d = maximize_critical_force(K0_CHAIN, **K0_CALL, K_min=0.05)
    m = d.manipulator
    assert d.K_min == 0.05
    assert np.all(m.stiffness >= 0.05)
    assert m.stiffness[1] == pytest.approx(0.05, rel=1e-7) and "K[1] >= 0.05" in d.active
    assert _reference_load(m) == pytest.approx(d.load, rel=1e-7)
    assert d.load < K0_LOAD                         # the floor costs load
    best, _, _ = _slsqp_optimum(0.8, 1.0, 5, (0.2, 5.0), (0.2, 2.0), 5.0, 5.0, 0.05, starts=4)
    assert best <= d.load * (1 + 1e-7) and best == pytest.approx(d.load, rel=1e-5)


def test_free_boundary_design():
    d = maximize_critical_force(PAPER, vary=("k",), bounds={"k": (0.3, 5.0)}, budget={"k": 4.0}, boundary="free")
    assert -to.critical_force(d.manipulator, "free", method="paper").force == pytest.approx(d.load, rel=1e-9)
    assert d.load > to.critical_force(PAPER, "free").loads[0]
    # a cantilever wants its stiffness near the base
    assert d.manipulator.k1[0] > d.manipulator.k1[-1]


def test_design_errors():
    with pytest.raises(to.InvalidParameterError) as ei:
        maximize_critical_force(PAPER, vary=("c",))
    assert ei.value.field == "vary"
    with pytest.raises(to.InvalidParameterError):
        maximize_critical_force(PAPER, vary=("k",), colour="red")
    with pytest.raises(to.StraightNotEquilibriumError):
        maximize_critical_force(to.Manipulator.uniform(3, k=(1, 2)), vary=("k",))
    with pytest.raises(InfeasibleDesignError) as ei:          # K_min beyond what the bounds allow
        maximize_critical_force(PAPER, vary=("k",), bounds={"k": (0.5, 1.0)}, K_min=5.0)
    assert ei.value.status                                    # IPOPT's status: the error body's
    best = ei.value.best
    assert best.status == "infeasible" and not best.success and best.solver.status == ei.value.status
    with pytest.raises(to.TimeLimitError):
        maximize_critical_force(PAPER, vary=("k",), timeout=1e-6)


def test_a_design_is_immutable():
    d = maximize_critical_force(PAPER, vary=("k",), bounds={"k": (0.5, 2.0)})
    with pytest.raises(AttributeError):
        d.status = "infeasible"
    with pytest.raises(ValueError):
        d.loads[0] = 0.0
    assert isinstance(d.active, tuple)


def test_an_invalid_input_chain_is_named_as_the_input():
    # a = 0.5, L0 = 1: K = k (b L0 - 2 (b^2 - a^2)) < 0 for every k, so varying k cannot make the chain valid
    with pytest.raises(InfeasibleDesignError, match="^the input chain is not a valid chain, and varying k") as info:
        maximize_critical_force(to.Manipulator.uniform(3, 0.5), ["k"])
    assert info.value.field == "segments[0].L0"
    assert "optimiser" not in str(info.value)


def test_an_invalid_design_of_a_valid_chain_is_the_optimisers():
    from tensegrity_opt.analyses.design.strongest import _invalid_design
    from tensegrity_opt.errors import UnstableStraightError

    err = _invalid_design(to.Manipulator.uniform(3), "guided", ["k"], UnstableStraightError("K_1 < 0"), "Solve")
    assert str(err) == "the optimiser's design is not a valid chain (the input chain is): K_1 < 0"
    assert err.field is None
