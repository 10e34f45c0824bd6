"""Verification of tensegrity_opt against an independent reference model.

Every expected number comes from ``tests/support/reference_model.py`` (plain numpy/scipy in
relative joint angles, written from the model's conventions, ``docs/model.md``, no import of the
library): SLSQP multistart for the least-energy equilibria, a bordered determinant with
brentq for the critical loads (finite-difference K, G, S0), finite differences of the
re-solved reference for the Cartesian stiffness, finite-difference Hessians for the Morse
index, and a hand-written two-link inverse kinematics for the n = 4 energy landscape.
The library is only called to produce the values under test.
"""

from __future__ import annotations

import functools

import numpy as np
import pytest
import reference_model as R  # noqa: E402
import scipy.optimize as so

import tensegrity_opt as to  # noqa: E402

# --------------------------------------------------------------------------- geometries
# (a, b, k, L0) per segment, symmetric springs.
GEOMETRIES = {
    "paper": [(1.0, 1.0, 1.0, 1.0)] * 4,
    "G1": [(0.8, 1.2, 2.5, 1.7)] * 5,
    "G2": [(1.0, 1.0, 1.0, 1.0), (0.9, 1.3, 2.0, 1.5), (1.1, 0.8, 0.7, 0.9), (1.0, 1.1, 1.5, 1.2)],
}
EXTRA = ("G1", "G2")
ALL = ("paper", "G1", "G2")
TARGETS = [(0.05, 0.0), (0.05, 0.2), (0.4, 0.0), (0.4, 0.2)]


@functools.lru_cache(maxsize=None)
def chain(name) -> R.Chain:
    return R.Chain.from_segments(GEOMETRIES[name])


@functools.lru_cache(maxsize=None)
def lib(name) -> to.Manipulator:
    return to.Manipulator([to.Segment(a, b, k, L0) for a, b, k, L0 in GEOMETRIES[name]])


@functools.lru_cache(maxsize=None)
def ref_min(name, dx, dy, n_random=200):
    """Reference least-energy stable equilibrium: (E, q, F)."""
    return chain(name).global_min(dx, dy, n_random=n_random)


@functools.lru_cache(maxsize=None)
def ref_loads(name):
    return R.critical_loads_guided(chain(name)), R.critical_loads_free(chain(name))


@functools.lru_cache(maxsize=None)
def lib_equilibria(name, dx, dy):
    return tuple(to.find_equilibria(lib(name), dx, dy))


def morse(w, scale):
    tol = 1e-8 * max(1.0, scale)
    assert np.all(np.abs(w) > tol), f"reference reduced Hessian is (nearly) singular: {w}"
    return int(np.sum(w < 0))


# --------------------------------------------------------------------------- the reference itself
@pytest.mark.parametrize("name", ALL)
def test_reference_model_self_consistency(name):
    """The reference's analytic derivatives agree with its own finite differences, and the
    closed-form joint stiffness K = k (b L0 - 2 (b^2 - a^2)) is positive (condition 4)."""
    c = chain(name)
    K = c.symmetric_K()
    assert np.all(K > 0)
    Kfd, G, S0 = R.fd_second_derivs(c)
    np.testing.assert_allclose(Kfd, K, rtol=1e-7)
    np.testing.assert_allclose(c.hess_diag(np.zeros(c.n)), K, rtol=1e-12)
    np.testing.assert_allclose(c.tip(np.zeros(c.n)), [2 * c.b.sum(), 0.0], atol=1e-14)
    rng = np.random.default_rng(3)
    for _ in range(3):
        q = rng.uniform(-0.6, 0.6, c.n) * c.limits
        F = rng.standard_normal(2)
        h = 1e-6
        gfd = np.array([(c.energy(q + h * e) - c.energy(q - h * e)) / (2 * h) for e in np.eye(c.n)])
        np.testing.assert_allclose(c.grad(q), gfd, atol=1e-7)
        Jfd = np.array([(c.tip(q + h * e) - c.tip(q - h * e)) / (2 * h) for e in np.eye(c.n)]).T
        np.testing.assert_allclose(c.jac(q), Jfd, atol=1e-7)
        np.testing.assert_allclose(c.lagrangian_hess(q, F), c.lagrangian_hess_fd(q, F), atol=1e-7)


# --------------------------------------------------------------------------- 1a least-energy equilibrium
CASES_A = [(g, dx, dy) for g in EXTRA for dx, dy in TARGETS] + [("paper", 0.1, 0.0)]


@pytest.mark.slow
@pytest.mark.parametrize("name,dx,dy", CASES_A)
def test_least_energy_equilibrium_matches_multistart_reference(name, dx, dy):
    E_ref, q_ref, F_ref = ref_min(name, dx, dy)
    c = chain(name)
    eq = to.solve_equilibrium(lib(name), dx, dy)
    assert eq.stable and eq.morse_index == 0
    np.testing.assert_allclose(eq.energy, E_ref, rtol=1e-7)
    if dy == 0.0:
        # mirror tie: the library reports q_1 > 0, as does the reference's tie-break
        assert eq.q[0] > 0 and q_ref[0] > 0
    np.testing.assert_allclose(eq.q, q_ref, atol=1e-5)
    # eq. 8 force at the reference configuration
    np.testing.assert_allclose(eq.force, c.force_eq8(q_ref), rtol=1e-6, atol=1e-9)
    # and the library's own point, judged by the reference: on target, balanced, stable
    np.testing.assert_allclose(c.tip(eq.q), c.target(dx, dy), atol=1e-9)
    np.testing.assert_allclose(eq.energy, c.energy(eq.q), rtol=1e-12)
    assert np.max(np.abs(c.lagrangian_grad(eq.q, eq.force))) < 1e-8
    assert np.min(c.reduced_eigs(eq.q, eq.force)) > 0


# --------------------------------------------------------------------------- 1b critical loads
@pytest.mark.slow
@pytest.mark.parametrize("name", ALL)
def test_guided_critical_loads_bordered_determinant(name):
    guided, _ = ref_loads(name)
    n = chain(name).n
    assert guided.size == n - 1
    bk = to.critical_force(lib(name))
    np.testing.assert_allclose(bk.loads, guided, rtol=1e-6)
    np.testing.assert_allclose(bk.force, -guided[0], rtol=1e-6)
    assert bk.force < 0
    np.testing.assert_allclose(to.critical_force(lib(name), method="paper").loads, guided, rtol=1e-6)
    # each mode solves the reference's linearised guided problem (K - P G) alpha = Fy S0, S0.alpha = 0
    K, G, S0 = R.fd_second_derivs(chain(name))
    for md in bk.modes:
        a = md.q
        assert abs(S0 @ a) < 1e-8 * np.linalg.norm(S0)
        r = K * a - md.load * (G @ a) - md.fy * S0
        assert np.max(np.abs(r)) < 1e-6 * np.abs(K).max()


@pytest.mark.parametrize("name", ALL)
def test_free_tip_critical_load_determinant(name):
    _, free = ref_loads(name)
    assert free.size == chain(name).n
    bk = to.critical_force(lib(name), "free")
    np.testing.assert_allclose(bk.loads[0], free[0], rtol=1e-6)
    np.testing.assert_allclose(bk.loads, free, rtol=1e-6)
    # the cantilever buckles at a much lower load than the guided chain
    assert free[0] < ref_loads(name)[0][0]


def test_paper_critical_loads_match_spec_table():
    guided, free = ref_loads("paper")
    np.testing.assert_allclose(guided, [0.572793, 1.362906, 1.921444], atol=2e-6)
    np.testing.assert_allclose(free[0], 0.0761205, atol=1e-6)


@pytest.mark.slow
@pytest.mark.parametrize("name", ALL)
def test_critical_load_is_limit_of_reference_branch_force(name):
    """Second route: Fx of the reference least-energy equilibrium at dx = 1e-4 -> -P1."""
    guided, _ = ref_loads(name)
    _, q, F = ref_min(name, 1e-4, 0.0, n_random=40)
    assert abs(F[0] + guided[0]) < 1e-3 * guided[0]
    assert abs(to.critical_force(lib(name)).force - F[0]) < 1e-3 * guided[0]


# --------------------------------------------------------------------------- 1c branch limits
def near_straight(eqs, tol=0.2):
    return [e for e in eqs if np.max(np.abs(e.q)) < tol]


@pytest.mark.parametrize("name", ALL)
def test_branch_forces_tend_to_each_critical_load(name):
    guided, _ = ref_loads(name)
    c = chain(name)
    eqs = near_straight(lib_equilibria(name, 1e-4, 0.0))
    assert len(eqs) == 2 * guided.size, [e.shape for e in eqs]
    energies = np.array([e.energy for e in eqs])
    assert np.all(np.diff(energies) >= -1e-12 * energies.max())
    for k, P in enumerate(guided):
        pair = eqs[2 * k: 2 * k + 2]
        np.testing.assert_allclose(pair[0].q, -pair[1].q, atol=1e-8)   # mirror images
        for e in pair:
            np.testing.assert_allclose(-e.fx, P, rtol=1e-3)
            np.testing.assert_allclose(e.force, c.force_eq8(e.q), rtol=1e-6, atol=1e-10)
            # branch k is born with Morse index k (only the lowest one is stable)
            assert morse(c.reduced_eigs(e.q, e.force), 1.0) == k
            assert e.morse_index == k


# --------------------------------------------------------------------------- 1d Cartesian stiffness
def ref_stiffness(c: R.Chain, dx, dy, q, F):
    return R.tip_stiffness_fd(c, c.target(dx, dy), q, F, h=1e-5, max_move=1e-3)


@pytest.mark.slow
@pytest.mark.parametrize("name,dx,dy", [(g, 0.05, 0.0) for g in EXTRA] + [(g, 0.4, 0.2) for g in EXTRA]
                         + [("paper", 0.1, 0.0)])
def test_cartesian_stiffness_finite_differences_of_reference(name, dx, dy):
    c = chain(name)
    E, q, F = ref_min(name, dx, dy)
    Kref = ref_stiffness(c, dx, dy, q, F)
    np.testing.assert_allclose(Kref, Kref.T, atol=1e-6 * np.abs(Kref).max())
    # hand the library the reference's equilibrium (not its own solve)
    eq = to.Equilibrium(q=q.copy(), energy=E, force=F.copy(), morse_index=0, stable=True,
                        solver=to.outcome.SolverInfo("reference", 0), tip=c.tip(q))
    Klib = to.cartesian_stiffness(lib(name), eq)
    assert Klib.shape == (2, 2)
    np.testing.assert_allclose(Klib, Klib.T, atol=1e-9 * np.abs(Klib).max())
    np.testing.assert_allclose(Klib, Kref, rtol=1e-4, atol=1e-4 * np.abs(Kref).max())


# --------------------------------------------------------------------------- 1e Morse index
@pytest.mark.slow
@pytest.mark.parametrize("name,dx,dy", [(g, dx, dy) for g in EXTRA for dx, dy in [(0.05, 0.0), (0.4, 0.2)]]
                         + [("paper", 0.1, 0.0)])
def test_morse_index_of_every_equilibrium(name, dx, dy):
    c = chain(name)
    eqs = lib_equilibria(name, dx, dy)
    assert len(eqs) >= 2
    target = c.target(dx, dy)
    n_stable = 0
    for e in eqs:
        assert c.in_range(e.q)
        np.testing.assert_allclose(c.tip(e.q), target, atol=1e-9)
        F = c.force_eq8(e.q)
        np.testing.assert_allclose(e.force, F, rtol=1e-6, atol=1e-9)
        assert np.max(np.abs(c.lagrangian_grad(e.q, F))) < 1e-8
        w = c.reduced_eigs(e.q, F)            # FD Hessian of E - F.tip, projected on null(J)
        idx = morse(w, np.abs(w).max())
        assert e.morse_index == idx, (e.q, w, e.hessian_eigenvalues)
        assert e.stable == (idx == 0)
        n_stable += idx == 0
    assert n_stable >= 1
    # the least-energy stable one is the reference global minimum
    stable = [e for e in eqs if e.stable]
    np.testing.assert_allclose(min(e.energy for e in stable), ref_min(name, dx, dy)[0], rtol=1e-7)


@pytest.mark.slow
@pytest.mark.parametrize("name,dx,dy", [("G2", 0.4, 0.2), ("paper", 1.0, 0.3)])
def test_find_equilibria_is_complete_against_random_newton(name, dx, dy):
    """Every KKT point the reference finds by Newton from 400 random starts is listed, and
    nothing else is."""
    c = chain(name)
    mine = R.all_equilibria(c, dx, dy, n_starts=400)
    eqs = lib_equilibria(name, dx, dy)
    assert len(mine) == len(eqs)
    for q, F in mine:
        match = [e for e in eqs if np.max(np.abs(e.q - q)) < 1e-6]
        assert len(match) == 1, q
        np.testing.assert_allclose(match[0].force, F, rtol=1e-6, atol=1e-9)
        np.testing.assert_allclose(match[0].energy, c.energy(q), rtol=1e-10)
        w = c.reduced_eigs(q, F)
        assert match[0].morse_index == morse(w, np.abs(w).max())


# --------------------------------------------------------------------------- 2 force control
def force_cases():
    out = []
    for g in ALL:
        out += [(g, -0.5, 0.0), (g, -0.5, 0.05), (g, None, 0.2), (g, None, -0.3), (g, -1.5, 0.0)]
    return out


@pytest.mark.parametrize("name,fx_rel,fy", force_cases())
def test_force_control_balance_and_stability(name, fx_rel, fy):
    """fx_rel: multiple of the reference free critical load (None: fx = +0.3 tension if fy < 0,
    else fx = -0.01)."""
    c = chain(name)
    Pfree = ref_loads(name)[1][0]
    if fx_rel is None:
        fx = 0.3 if fy < 0 else -0.01
    else:
        fx = fx_rel * Pfree
    F = np.array([fx, fy])
    eq = to.solve_equilibrium_under_force(lib(name), fx, fy)
    assert eq.control == "force"
    np.testing.assert_allclose(eq.force, F, atol=1e-12)
    assert c.in_range(eq.q)
    resid = c.grad(eq.q) - c.jac(eq.q).T @ F
    assert np.max(np.abs(resid)) < 1e-8
    np.testing.assert_allclose(eq.tip, c.tip(eq.q), atol=1e-12)
    w = c.reduced_eigs(eq.q, F, constrained=False)
    assert (w.min() > 0) == eq.stable, w
    if fx_rel == -0.5 and fy == 0.0:
        # below the free critical load straight is the stable equilibrium
        np.testing.assert_allclose(eq.q, 0.0, atol=1e-8)
        assert eq.stable
    if fx_rel == -1.5:
        # beyond it the straight configuration is unstable (reference) and the library bends
        assert c.reduced_eigs(np.zeros(c.n), F, constrained=False).min() < 0
        assert np.max(np.abs(eq.q)) > 1e-3
        assert eq.stable


@pytest.mark.slow
@pytest.mark.parametrize("name", ["paper", "G2"])
def test_force_control_without_stable_equilibrium_raises(name):
    """Dead load 0.9 x guided critical load, Fy = 0: the reference finds no stable equilibrium
    inside the range (straight is unstable above the free critical load and every buckled state
    runs into a joint limit), so the library must not report one."""
    c = chain(name)
    F = np.array([-0.9 * ref_loads(name)[0][0], 0.0])
    sols = R.all_force_equilibria(c, F, n_starts=500)
    assert not [q for q in sols if c.reduced_eigs(q, F, constrained=False).min() > 0]
    with pytest.raises((to.NoEquilibriumError, to.SolverError)):
        to.solve_equilibrium_under_force(lib(name), F[0], F[1])


# --------------------------------------------------------------------------- 3 energy landscape (n = 4)
def reduced_fun(c, target, elbow):
    def f(x):
        E, _ = R.ik_energy(c, target, x[0], x[1], elbow)
        return 1e6 if not np.isfinite(E) else E
    return f


def test_landscape_minima_are_stable_equilibria():
    c = chain("paper")
    dx, dy = 0.1, 0.0
    target = c.target(dx, dy)
    lim = min(c.limits[0], c.limits[3]) * 0.999
    starts = np.linspace(-0.9 * lim, 0.9 * lim, 7)
    minima = []
    for elbow in (1, -1):
        f = reduced_fun(c, target, elbow)
        for s1 in starts:
            for s4 in starts:
                if f([s1, s4]) >= 1e6:
                    continue
                r = so.minimize(f, [s1, s4], method="Nelder-Mead",
                                options={"xatol": 1e-11, "fatol": 1e-15, "maxiter": 4000, "maxfev": 8000})
                E, q = R.ik_energy(c, target, r.x[0], r.x[1], elbow)
                if not np.isfinite(E) or not c.in_range(q, 1e-6):
                    continue
                # a minimum against the reachability edge is not a critical point: drop it
                F = c.force_eq8(q)
                if np.max(np.abs(c.lagrangian_grad(q, F))) > 1e-5:
                    continue
                if not any(np.max(np.abs(q - m[1])) < 1e-4 for m in minima):
                    minima.append((E, q))
    assert len(minima) >= 2
    eqs = lib_equilibria("paper", dx, dy)
    stable = [e for e in eqs if e.stable]
    assert len(stable) == 2                      # the two U shapes
    for E, q in minima:
        match = [e for e in stable if np.max(np.abs(e.q - q)) < 1e-4]
        assert match, (E, q)
        np.testing.assert_allclose(match[0].energy, E, rtol=1e-8)
    for e in stable:
        assert any(np.max(np.abs(e.q - q)) < 1e-4 for _, q in minima)


@pytest.mark.parametrize("dx,dy", [(0.1, 0.0), (3.0, 0.5)])
def test_energy_landscape_grid_matches_own_inverse_kinematics(dx, dy):
    c = chain("paper")
    target = c.target(dx, dy)
    grid = 41
    L = to.energy_landscape(lib("paper"), dx, dy, pair=(0, 3), grid=grid)
    s = min(c.limits[0], c.limits[3]) * 0.999
    axis = np.linspace(-s, s, grid)
    np.testing.assert_allclose(L.qi, axis, atol=1e-14)
    np.testing.assert_allclose(L.qj, axis, atol=1e-14)
    assert L.energy.shape == (2, grid, grid)
    for b, elbow in enumerate((1, -1)):
        mine = np.array([[R.ik_energy(c, target, q1, q4, elbow)[0] for q4 in axis] for q1 in axis])
        both = np.isfinite(mine) & np.isfinite(L.energy[b])
        assert both.sum() > 50
        np.testing.assert_allclose(L.energy[b][both], mine[both], rtol=1e-10)
        qs = np.array([[R.ik_q14(c, target, q1, q4, elbow) if np.isfinite(mine[i, j]) else np.full(4, np.nan)
                        for j, q4 in enumerate(axis)] for i, q1 in enumerate(axis)])
        np.testing.assert_allclose(L.q[b][both], qs[both], atol=1e-10)
        mismatch = np.isfinite(mine) ^ np.isfinite(L.energy[b])
        assert mismatch.sum() <= 4, np.argwhere(mismatch)
