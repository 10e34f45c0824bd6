"""Quasi-static simulation with snap-through against independent references.

Every expected number comes from ``tests/support/reference_paths.py`` / ``tests/support/reference_model.py``
(numpy + scipy, no import of the library) or from the small scipy routines below: the folds from
``limit_load_reference`` / ``fold_in_displacement`` (natural paths and the extended system), the landing
states from a gradient flow of the reference potential integrated by scipy's LSODA from the reference fold
(perturbed along its null vector to the side where the potential is lower), the global minima from the
reference's Newton from random starts. The library only produces the values under test.

Chains: ``bistable3`` (three segments a = 0.5, b = 1, k = 1, L0 = 1: K = -0.5, unloaded wells +-1.682137, 8
rest configurations), a two-segment chain with one bistable segment (preload control), a monotonic
``a = 0.9`` chain (held tip), the paper chain (the free buckling of the straight chain).
"""

from __future__ import annotations

import functools
import json

import numpy as np
import pytest
import reference_model as R  # noqa: E402
import reference_paths as RP  # noqa: E402
import scipy.optimize as so
from clocks import tick_clock
from scipy.integrate import solve_ivp

import tensegrity_opt as to  # noqa: E402
from tensegrity_opt import simulate  # noqa: E402

BISTABLE = (0.5, 1.0, 1.0, 1.0)


def lib_bistable3() -> to.Manipulator:
    return to.Manipulator.uniform(3, *BISTABLE)


def ref_bistable3() -> R.Chain:
    return R.Chain.uniform(3, *BISTABLE)


def bistable_well() -> float:
    return float(RP.segment_wells(0.5, 1.0, 1.0, 1.0, 1.0, 1.0)[1])


def _chain_with(c: R.Chain, P) -> R.Chain:
    P = np.asarray(P, float)
    return R.Chain(c.a.copy(), c.b.copy(), c.k1.copy(), c.k2.copy(), P[:, 0].copy(), P[:, 1].copy())


# --------------------------------------------------------------------------- reference descent
def ref_descent_free(c: R.Chain, q_fold, phi, F, eps=1e-3, T=4000.0):
    """The gradient flow dq/dtau = -grad(E - F . tip) from the fold moved by eps along +-phi (the side of
    lower potential), LSODA, then a Newton polish. Returns (q, status): "landed" or "joint_limit"."""
    F = np.asarray(F, float)
    phi = np.asarray(phi, float) / np.abs(phi).max()

    def V(q):
        return c.energy(q) - F @ c.tip(q)

    q0 = min((q_fold + s * eps * phi for s in (1, -1)), key=V)
    return _flow(c, lambda q: c.grad(q) - c.jac(q).T @ F, q0, T,
                 lambda q: c.newton_force(F, q))


def ref_descent_held(c: R.Chain, q_fold, phi, target, eps=1e-3, T=4000.0):
    """The projected gradient flow of E on tip(q) = target (with a pull back onto the constraint) from the
    fold moved by eps along +-phi (the side of lower E after projection), then a Newton KKT polish."""
    target = np.asarray(target, float)
    phi = np.asarray(phi, float) / np.abs(phi).max()

    def onto(q):
        for _ in range(12):
            q = q - np.linalg.lstsq(c.jac(q), c.tip(q) - target, rcond=None)[0]
        return q

    q0 = min((onto(q_fold + s * eps * phi) for s in (1, -1)), key=c.energy)

    def field(q):
        J, g = c.jac(q), c.grad(q)
        lam = np.linalg.lstsq(J.T, g, rcond=None)[0]
        return (g - J.T @ lam) + np.linalg.lstsq(J, c.tip(q) - target, rcond=None)[0]

    def polish(q):
        qq, F, ok = c.newton_kkt(target, q)
        return qq, ok
    return _flow(c, field, q0, T, polish)


def _flow(c, minus_field, q0, T, polish):
    def at_limit(_t, q):
        return float(np.max(np.abs(q) / c.limits)) - (1 - 1e-6)
    at_limit.terminal = True
    sol = solve_ivp(lambda _t, q: -minus_field(q), (0.0, T), q0, method="LSODA", rtol=1e-10, atol=1e-12,
                    events=at_limit)
    if sol.status == 1:
        return sol.y[:, -1], "joint_limit"
    q, ok = polish(sol.y[:, -1])
    assert ok and np.abs(q - sol.y[:, -1]).max() < 1e-5, "the reference flow did not converge"
    return q, "landed"


def free_min_eig(c: R.Chain, q, F) -> float:
    return float(np.linalg.eigvalsh(RP.lagrangian_hess(c, np.asarray(q, float), np.asarray(F, float)))[0])


def check_rows(sim, c_of_step, *, held=False):
    """Every row: inside the physical range, an equilibrium of the reference chain at that step's preloads
    (under the load, or with the tip at the target), and stable by the reference Hessian."""
    assert len(sim) >= 1
    for k in range(len(sim)):
        c = c_of_step(k)
        q, F = sim.q[k], sim.force[k]
        assert np.all(np.abs(q) < c.limits)
        assert RP.equilibrium_residual(c, q, F) < 1e-9
        if held:
            np.testing.assert_allclose(c.tip(q), c.target(*sim.targets[k]), atol=1e-9)
            assert RP.smallest_eigenvalue(c, q, F, "displacement") > 0
        else:
            np.testing.assert_allclose(F, sim.loads[k], atol=1e-14)
            assert free_min_eig(c, q, F) > 0
        assert sim.stable[k] and sim.morse_index[k] == 0
    json.dumps(sim.to_dict(), allow_nan=False)


# --------------------------------------------------------------------------- hysteresis (free tip, load in y)
AMPLITUDE = 0.3


@functools.lru_cache(maxsize=None)
def load_cycle():
    up = np.linspace(0.0, AMPLITUDE, 31)
    t = np.concatenate([up, np.linspace(AMPLITUDE, -AMPLITUDE, 61)[1:], np.linspace(-AMPLITUDE, 0.0, 31)[1:]])
    loads = np.column_stack([np.zeros_like(t), t])
    return loads, simulate(lib_bistable3(), loads=loads, start=np.full(3, bistable_well()))


@functools.lru_cache(maxsize=None)
def reference_cycle():
    """The two folds of the cycle and the landings, by the reference: the fold of the path from (+, +, +)
    under F = (0, t); the landing by the reference flow; the fold of the path from that landing as the load
    comes back down (F = (0, t1 - t)); its landing."""
    c = ref_bistable3()
    r1 = RP.limit_load_reference(c, np.full(3, bistable_well()), (0.0, 1.0), "free", max_load=1.0)
    F1 = np.array([0.0, r1.t])
    q1, st1 = ref_descent_free(c, r1.q, r1.phi, F1)
    r2 = RP.limit_load_reference(c, q1, (0.0, -1.0), "free", base=F1, max_load=1.0)
    F2 = np.array([0.0, r1.t - r2.t])
    q2, st2 = ref_descent_free(c, r2.q, r2.phi, F2)
    assert r1.kind == r2.kind == "fold" and st1 == st2 == "landed"
    return (r1, F1, q1), (r2, F2, q2)


@pytest.mark.slow
def test_load_cycle_snaps_at_the_two_reference_folds():
    """Fy up to 0.3, down to -0.3, back to 0 on bistable3 from (+, +, +): two snaps, on the way up at
    Fy = 0.153111 and on the way down at Fy = -0.097754 (a hysteresis loop), each at the reference fold of
    the branch it follows (to 1e-9), each landing where the reference gradient flow from that fold lands."""
    loads, sim = load_cycle()
    assert sim.success and sim.status == "complete" and len(sim) == loads.shape[0]
    c = ref_bistable3()
    check_rows(sim, lambda k: c)
    snaps = sim.snaps
    assert [e.kind for e in sim.events] == ["snap", "snap"]
    for e, (r, F, q_land) in zip(snaps, reference_cycle()):
        load = loads[e.step] + e.fraction * (loads[e.step + 1] - loads[e.step])
        np.testing.assert_allclose(e.load, load, atol=1e-15)
        assert e.load[1] == pytest.approx(F[1], abs=1e-9)
        np.testing.assert_allclose(e.q_before, r.q, atol=1e-6)
        np.testing.assert_allclose(e.q_after, q_land, atol=1e-7)
        assert RP.equilibrium_residual(c, e.q_after, F) < 1e-9 and free_min_eig(c, e.q_after, F) > 1e-6
        # the energy released is the drop of the potential E - F . tip between the fold and the landing
        V = lambda q: c.energy(q) - F @ c.tip(q)  # noqa: E731
        assert e.energy_released > 0.1
        assert e.energy_released == pytest.approx(V(e.q_before) - V(e.q_after), abs=1e-9)
        assert e.potential_before - e.potential_after == pytest.approx(e.energy_released, abs=1e-12)
    up, down = snaps
    assert up.load[1] > 0 > down.load[1] and up.load[1] != pytest.approx(-down.load[1], abs=1e-2)
    assert up.step < 30 < down.step < 91
    # the snaps show in the steps: the configuration jumps across the event's step
    for e in snaps:
        assert np.abs(sim.q[e.step + 1] - sim.q[e.step]).max() > 0.5


@pytest.mark.slow
def test_the_landing_is_the_descent_not_the_global_minimum():
    """At the down fold (Fy = -0.097754) the flow from the fold lands in (-1.480, -1.449, 1.648), potential
    1.706565; the least-potential stable equilibrium at that load is another well, (-1.798, 1.475, -1.636)
    at 1.679928 (the reference's Newton from 300 random starts). The simulation lands where the flow does."""
    _, (r2, F2, q2) = reference_cycle()
    e = load_cycle()[1].snaps[1]
    c = ref_bistable3()
    V = lambda q: c.energy(q) - F2 @ c.tip(q)  # noqa: E731
    stable = [q for q in R.all_force_equilibria(c, F2, n_starts=300) if free_min_eig(c, q, F2) > 1e-9]
    best = min(stable, key=V)
    assert np.abs(best - q2).max() > 1.0 and V(best) < V(q2) - 0.02
    np.testing.assert_allclose(e.q_after, q2, atol=1e-7)
    assert np.abs(e.q_after - best).max() > 1.0
    # and the flow is not the first minimiser one might call: the landing is a minimum of the potential
    res = so.minimize(V, e.q_after + 1e-3, method="BFGS", options={"gtol": 1e-10})
    np.testing.assert_allclose(res.x, e.q_after, atol=1e-5)


def test_compression_snaps_at_the_free_fold_then_ends_at_a_joint_limit():
    """bistable3 from (+, +, +) compressed along -x: the free fold at t = 0.4274008426 (reference), a snap
    landing where the reference flow does, then the branch reaches a joint's range bound (status
    "joint_limit", the steps before it kept, the end an event inside the range)."""
    c = ref_bistable3()
    q0 = np.full(3, bistable_well())
    t = np.linspace(0.0, 0.6, 31)
    loads = np.column_stack([-t, np.zeros_like(t)])
    sim = simulate(lib_bistable3(), loads=loads, start=q0)
    r = RP.limit_load_reference(c, q0, (-1.0, 0.0), "free", max_load=1.0)
    assert r.kind == "fold" and r.t == pytest.approx(0.4274008426, abs=1e-9)
    assert sim.status == "joint_limit" and not sim.success
    snap, end = sim.events
    assert snap.kind == "snap" and -snap.load[0] == pytest.approx(r.t, abs=1e-9)
    q_land, st = ref_descent_free(c, r.q, r.phi, np.array([-r.t, 0.0]))
    assert st == "landed"
    np.testing.assert_allclose(snap.q_after, q_land, atol=1e-7)
    assert end.kind == "joint_limit" and end.q_after is None
    assert np.max(np.abs(end.q_before) / c.limits) == pytest.approx(1 - 1e-6, abs=1e-9)
    assert len(sim) == end.step + 1 and end.time > snap.time
    check_rows(sim, lambda k: c)


# --------------------------------------------------------------------------- preload control
def test_a_preload_trajectory_drives_a_bistable_segment_through_its_fold():
    """No load, tip free; segment 1 (bistable) of a two-segment chain gets its rest lengths
    (1 + d, 1 - d), d = 0 .. 0.5. Its + well meets the unstable one at a fold (the reference: E' = E'' = 0 in
    (q, d), scipy fsolve); the arm snaps once, there, into the other well of segment 1 (segment_wells at that
    d), segment 2 straight throughout; the energy released is the drop of E."""
    a, b, k, L0 = BISTABLE
    m = to.Manipulator([to.Segment(a, b, k, L0), to.Segment(1.0, 1.0, 1.0, 1.0)])
    ds = np.linspace(0.0, 0.5, 51)
    P = np.array([[[1 + d, 1 - d], [1.0, 1.0]] for d in ds])
    sim = simulate(m, preloads=P)
    c0 = R.Chain.from_segments([BISTABLE, (1.0, 1.0, 1.0, 1.0)])
    check_rows(sim, lambda i: _chain_with(c0, P[i]))
    assert sim.success and [e.kind for e in sim.events] == ["snap"]
    e = sim.events[0]

    def seg(d):
        return R.Chain.from_segments([(a, b, k, k, 1 + d, 1 - d)])

    def fold(x):
        q, d = x
        s = seg(d)
        return [s.grad(np.array([q]))[0], s.hess_diag(np.array([q]))[0]]
    q0 = sim.q[0, 0]
    assert q0 == pytest.approx(bistable_well(), abs=1e-9) or q0 == pytest.approx(-bistable_well(), abs=1e-9)
    # the well the arm starts in (the default rest configuration) is the one the asymmetry flattens
    qf, df = so.fsolve(fold, [0.6 * np.sign(q0), 0.4], xtol=1e-12)
    assert np.abs(fold([qf, df])).max() < 1e-12 and 0 < df < 0.5
    np.testing.assert_allclose(e.preloads, [[1 + df, 1 - df], [1.0, 1.0]], atol=1e-9)
    assert e.q_before[0] == pytest.approx(qf, abs=1e-5) and abs(e.q_before[1]) < 1e-9
    other = [w for w in RP.segment_wells(a, b, k, k, 1 + df, 1 - df) if np.sign(w) != np.sign(qf)]
    assert len(other) == 1
    np.testing.assert_allclose(e.q_after, [other[0], 0.0], atol=1e-7)
    cf = _chain_with(c0, e.preloads)
    assert e.energy_released > 0
    assert e.energy_released == pytest.approx(cf.energy(e.q_before) - cf.energy(e.q_after), abs=1e-9)
    np.testing.assert_allclose(sim.q[:, 1], 0.0, atol=1e-9)
    assert np.all(np.sign(sim.q[:e.step + 1, 0]) == np.sign(qf))
    assert np.all(np.sign(sim.q[e.step + 1:, 0]) != np.sign(qf))


# --------------------------------------------------------------------------- held tip
def test_held_tip_with_changing_preloads_follows_the_reference_branch():
    """A monotonic chain, the tip moved and two rest lengths changed together: no event; every step is the
    reference's Newton KKT solution continued from the previous step on the changed chain, and the
    least-energy stable equilibrium of the library's global search on that chain (what a Tracker answers)."""
    m = to.Manipulator.uniform(3, a=0.9, b=1.0, k=1.0, L0=1.0)
    c0 = R.Chain.uniform(3, 0.9, 1.0, 1.0, 1.0)
    K = 21
    s = np.linspace(0.0, 1.0, K)
    T = np.column_stack([0.4 + 0.2 * s, 0.1 + 0.3 * s])
    P = np.ones((K, 3, 2))
    P[:, 0, 0] += 0.2 * s
    P[:, 2, 1] -= 0.1 * s
    sim = simulate(m, P, tip="held", targets=T)
    assert sim.success and sim.events == ()
    check_rows(sim, lambda k: _chain_with(c0, P[k]), held=True)
    q, F = sim.q[0], sim.force[0]
    for k in range(K):
        ck = _chain_with(c0, P[k])
        q, F, ok = ck.newton_kkt(ck.target(*T[k]), q, F)
        assert ok
        np.testing.assert_allclose(sim.q[k], q, atol=1e-8)
        np.testing.assert_allclose(sim.force[k], F, atol=1e-8)
    for k in (0, K // 2, K - 1):
        mk = to.Manipulator(to.Segment(0.9, 1.0, 1.0, tuple(P[k, i])) for i in range(3))
        eq = to.solve_equilibrium(mk, *T[k])
        np.testing.assert_allclose(sim.q[k], eq.q, atol=1e-7)
    # constant preloads: the Tracker along the same targets (its semantics, no fold met)
    sim2 = simulate(m, tip="held", targets=T)
    tr = to.Tracker(m)
    for k in range(K):
        np.testing.assert_allclose(sim2.q[k], tr.solve(*T[k]).q, atol=1e-8)
    assert tr.jumps == 0


@pytest.mark.slow
def test_held_tip_snaps_at_the_displacement_fold():
    """bistable3 from (+, +, +), the tip moved along (1, 1)/sqrt 2 in (dx, dy): the held-tip branch folds at
    t = 2.490914 (reference fold_in_displacement); the arm snaps there, landing where the reference projected
    gradient flow of E on the tip constraint lands; E drops; the holding force jumps."""
    c = ref_bistable3()
    q0 = np.full(3, bistable_well())
    tip0 = c.tip(q0)
    d0 = np.array([6.0 - tip0[0], tip0[1]])
    u = np.array([1.0, 1.0]) / np.sqrt(2.0)
    s = np.linspace(0.0, 2.6, 27)
    T = d0[None, :] + s[:, None] * u[None, :]
    sim = simulate(lib_bistable3(), tip="held", targets=T, start=q0)
    r = RP.fold_in_displacement(c, q0, u, t_max=3.0)
    assert r.kind == "fold" and r.t_coordinate == pytest.approx(r.t, abs=1e-9)
    assert sim.success and [e.kind for e in sim.events] == ["snap"]
    e = sim.events[0]
    np.testing.assert_allclose(e.target, d0 + r.t * u, atol=1e-9)
    np.testing.assert_allclose(e.q_before, r.q, atol=1e-6)
    target = c.target(*e.target)
    q_land, st = ref_descent_held(c, r.q, r.phi[:3], target)
    assert st == "landed"
    np.testing.assert_allclose(e.q_after, q_land, atol=1e-7)
    np.testing.assert_allclose(c.tip(e.q_after), target, atol=1e-10)
    assert RP.smallest_eigenvalue(c, e.q_after, e.force_after, "displacement") > 1e-6
    assert e.energy_released > 0.1
    assert e.energy_released == pytest.approx(c.energy(e.q_before) - c.energy(e.q_after), abs=1e-9)
    assert np.abs(e.force_after - e.force_before).max() > 0.05
    check_rows(sim, lambda k: c, held=True)


def test_a_snap_into_a_joint_bound_ends_the_simulation():
    """Held tip moved along +dx from (+, +, +): the fold at dx = 1.973177 (reference), and the reference flow
    from it runs into joint 1's range bound; the simulation ends there ("joint_limit"), keeping the steps
    before, the snap recorded without a landing."""
    c = ref_bistable3()
    q0 = np.full(3, bistable_well())
    tip0 = c.tip(q0)
    d0 = np.array([6.0 - tip0[0], tip0[1]])
    s = np.linspace(0.0, 2.2, 23)
    T = d0[None, :] + s[:, None] * np.array([1.0, 0.0])[None, :]
    sim = simulate(lib_bistable3(), tip="held", targets=T, start=q0)
    r = RP.fold_in_displacement(c, q0, (1.0, 0.0), t_max=3.0)
    _, st = ref_descent_held(c, r.q, r.phi[:3], c.tip(q0) + r.t * np.array([-1.0, 0.0]))
    assert st == "joint_limit"
    assert sim.status == "joint_limit" and not sim.success
    (e,) = sim.events
    assert e.kind == "snap" and e.q_after is None and e.energy_released is None
    assert e.target[0] - d0[0] == pytest.approx(r.t, abs=1e-9)
    assert len(sim) == e.step + 1
    check_rows(sim, lambda k: c, held=True)


# --------------------------------------------------------------------------- buckling of the straight chain
def test_straight_chain_buckles_continuously_at_the_free_critical_load():
    """The paper chain compressed along -x: the straight branch loses stability at a branch point, the free
    critical load P1 = (K / b)(1 - cos(pi / 8)) = 0.0761205 (reference eigenproblem); the pitchfork is
    supercritical, so the arm moves onto the stable bent branch with (almost) no energy released."""
    c = R.Chain.uniform(4, 1.0, 1.0, 1.0, 1.0)
    P1 = RP.buckling_modes(c, "free")[0][0]
    t = np.linspace(0.0, 0.2, 11)
    loads = np.column_stack([-t, np.zeros_like(t)])
    sim = simulate(to.Manipulator.uniform(4), loads=loads, start=np.zeros(4))
    assert sim.success and [e.kind for e in sim.events] == ["bifurcation"]
    e = sim.events[0]
    assert -e.load[0] == pytest.approx(P1, abs=1e-4) and -e.load[0] >= P1
    assert 0 <= e.energy_released < 1e-6
    check_rows(sim, lambda k: c)
    assert np.abs(sim.q[-1]).max() > 0.5                 # bent well past the critical load


# --------------------------------------------------------------------------- inputs, limits, JSON
def test_bad_inputs_name_the_field():
    m = lib_bistable3()
    K = 4
    cases = [
        (dict(loads=np.zeros((K, 3))), "loads"),
        (dict(loads=np.full((K, 2), np.nan)), "loads"),
        (dict(loads=np.zeros((0, 2))), "loads"),
        (dict(preloads=np.ones((K, 2, 2))), "preloads"),
        (dict(preloads=np.ones((K, 3))), "preloads"),
        (dict(preloads=np.zeros((K, 3, 2))), "preloads"),
        (dict(preloads=np.full((K, 3, 2), np.inf)), "preloads"),
        (dict(preloads=np.ones((K, 3, 2)), loads=np.zeros((K + 1, 2))), "loads"),
        (dict(loads=np.zeros((K, 2)), tip="clamped"), "tip"),
        (dict(loads=np.zeros((K, 2)), tip="held"), "loads"),
        (dict(tip="held"), "targets"),
        (dict(targets=np.zeros((K, 2))), "targets"),
        (dict(tip="held", targets=np.zeros((K, 3))), "targets"),
        (dict(tip="held", targets=[[0.1, 0.0], [0.1, float("inf")]]), "targets"),
        (dict(), "loads"),
        (dict(loads=np.zeros((K, 2)), start=np.zeros(2)), "start"),
        (dict(loads=np.zeros((K, 2)), start=np.full(3, 3.0)), "start"),
        (dict(loads=np.zeros((K, 2)), start=np.zeros(3)), "start"),       # the straight chain is unstable here
        (dict(loads=np.zeros((K, 2)), perturbation=0.0), "perturbation"),
    ]
    for kw, name in cases:
        with pytest.raises(to.InvalidParameterError) as exc:
            simulate(m, **kw)
        assert exc.value.field == name, (kw, exc.value.field, exc.value.message)
        assert isinstance(exc.value, ValueError)
    with pytest.raises(to.UnreachableTargetError) as exc:
        simulate(m, tip="held", targets=[[0.1, 0.0], [-1.0, 0.0]])
    assert exc.value.field == "targets"


def test_time_limit_keeps_the_steps_done_and_constant_inputs_stay_put(monkeypatch):
    m = lib_bistable3()
    t = np.linspace(0.0, 0.14, 20001)
    # the library's clock moves on 1 s at every reading, about twice a step (tests/support/clocks.py): a limit of
    # 100 s runs out after some 50 of the 20001 steps on any machine
    with monkeypatch.context() as patched:
        tick_clock(patched, step=1.0)
        sim = simulate(m, loads=np.column_stack([np.zeros_like(t), t]), timeout=100.0)
    assert sim.status == "time_limit" and not sim.success and 10 < len(sim) < 200
    check_rows(sim, lambda k: ref_bistable3())
    q0 = np.full(3, bistable_well())
    sim = simulate(m, loads=np.zeros((3, 2)), start=q0)
    assert sim.success and len(sim) == 3 and sim.events == ()
    np.testing.assert_allclose(sim.q, np.repeat(q0[None, :], 3, 0), atol=1e-9)
    one = simulate(m, loads=np.zeros((1, 2)))
    assert one.success and len(one) == 1 and one.steps == 1
    d = one.to_dict()
    assert d["status"] == "complete" and d["done"] == 1 and d["mode"] == "free"
