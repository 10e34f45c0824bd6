"""Displacement- and force-controlled equilibria (the paper's main problem)."""

import threading

import numpy as np
import pytest

from tensegrity_opt import (
    InvalidParameterError,
    Manipulator,
    NoEquilibriumError,
    Segment,
    UnreachableTargetError,
    critical_force,
    solve_equilibrium,
    solve_equilibrium_under_force,
)
from tensegrity_opt.analyses.equilibria.landscape import complete_configuration

PAPER = Manipulator.uniform(4)


def landscape_minimum(m, dx, dy, starts=25):
    """Independent route: the paper's energy method (n = 4): minimise E(q1, q4) with q2, q3 by IK."""
    from scipy.optimize import minimize
    target = m.target(dx, dy)
    best = None
    rng = np.random.default_rng(1)
    for _ in range(starts):
        x0 = rng.uniform(-0.8, 0.8, 2)
        for elbow in (1, -1):
            def f(x):
                q = complete_configuration(m, target, (0, 3), x[0], x[1], elbow)
                if not np.all(np.isfinite(q)) or not m.in_range(q):
                    return 1e6
                return m.energy(q)
            r = minimize(f, x0, method="Nelder-Mead", options={"xatol": 1e-10, "fatol": 1e-13, "maxiter": 4000})
            if r.fun < 1e5 and (best is None or r.fun < best[0]):
                best = (r.fun, complete_configuration(m, target, (0, 3), r.x[0], r.x[1], elbow))
    return best


@pytest.mark.parametrize("dx,fy_abs", [(0.01, 0.00806), (0.1, 0.02579)])
def test_conventions_figures_on_U_branch(dx, fy_abs):
    eq = solve_equilibrium(PAPER, dx)
    assert eq.stable and eq.morse_index == 0 and eq.shape == "U"
    assert abs(eq.fy) == pytest.approx(fy_abs, rel=2e-3)      # printed to 3-4 digits
    assert eq.q[0] > 0                                         # documented tie-break
    assert np.allclose(eq.tip, PAPER.target(dx, 0.0), atol=1e-9)
    assert eq.status == "converged" and eq.solver.status in ("Newton_Converged", "Solve_Succeeded")
    assert eq.solver.iterations >= 0


@pytest.mark.parametrize("dx,dy", [(0.05, 0.0), (0.5, 0.0), (0.3, 0.4), (1.5, -0.7)])
def test_force_from_multipliers_matches_eq8(dx, dy):
    eq = solve_equilibrium(PAPER, dx, dy)
    assert np.allclose(eq.force, PAPER.force_from_torques(eq.q), rtol=1e-8, atol=1e-10)


@pytest.mark.slow
@pytest.mark.parametrize("dx,dy", [(0.1, 0.0), (0.8, 0.3), (2.0, 0.0)])
def test_global_minimum_matches_energy_method(dx, dy):
    eq = solve_equilibrium(PAPER, dx, dy)
    ref_e, ref_q = landscape_minimum(PAPER, dx, dy)
    assert eq.energy == pytest.approx(ref_e, rel=1e-9)
    assert eq.energy <= ref_e + 1e-9


def test_q0_selects_the_nearer_mirror_image():
    eq = solve_equilibrium(PAPER, 0.2)
    other = solve_equilibrium(PAPER, 0.2, q0=-eq.q)
    assert np.allclose(other.q, -eq.q, atol=1e-8)
    assert other.energy == pytest.approx(eq.energy, rel=1e-12)


def test_straight_and_errors():
    eq = solve_equilibrium(PAPER, 0.0, 0.0)
    assert np.all(eq.q == 0) and eq.stable and np.allclose(eq.force, 0)
    assert eq.energy == pytest.approx(4 * 1.0)   # four segments, both springs stretched by 2b - L0 = 1
    with pytest.raises(UnreachableTargetError) as ei:
        solve_equilibrium(PAPER, -0.01)
    assert isinstance(ei.value, ValueError)
    with pytest.raises(UnreachableTargetError):
        solve_equilibrium(PAPER, 0.0, 0.1)
    with pytest.raises(InvalidParameterError) as ei:
        solve_equilibrium(PAPER, 0.1, q0=[0.1, 0.2])
    assert ei.value.field == "q0"
    with pytest.raises(InvalidParameterError):
        solve_equilibrium(PAPER, 0.1, q0=[3.0, 0, 0, 0])


def test_targets_outside_the_joint_range_workspace():
    # within the chain's length, but folding back that far needs |q| beyond pi - 2 beta
    m = Manipulator.uniform(2)
    with pytest.raises(UnreachableTargetError) as ei:
        solve_equilibrium(m, 5.9, n_random=2)
    assert "Infeasible_Problem_Detected" in ei.value.status
    # reachable, but every minimiser presses a joint against its limit: no equilibrium inside the open range
    # (stops=False), the arm resting on a stop by default (its contact torque positive)
    with pytest.raises(NoEquilibriumError) as ei:
        solve_equilibrium(PAPER, 5.0, 0.0, stops=False)
    assert isinstance(ei.value, RuntimeError) and "joint limit" in ei.value.status
    eq = solve_equilibrium(PAPER, 5.0, 0.0)
    assert eq.at_stop.any() and np.all(eq.contact_torques[eq.at_stop] > 0) and eq.stable
    assert np.allclose(np.abs(eq.q[eq.at_stop]), PAPER.joint_limits[eq.at_stop], rtol=0, atol=0)


@pytest.mark.slow
def test_nonuniform_chain_energy_method():
    m = Manipulator([Segment(1.0, 1.0, 1.0, 1.0), Segment(0.9, 1.3, 2.0, 1.5),
                     Segment(1.1, 0.8, 0.7, 0.9), Segment(1.0, 1.1, 1.5, (1.2, 1.3))])
    eq = solve_equilibrium(m, 0.3, 0.2)
    ref_e, _ = landscape_minimum(m, 0.3, 0.2)
    assert eq.energy == pytest.approx(ref_e, rel=1e-9)
    assert np.allclose(eq.force, m.force_from_torques(eq.q), rtol=1e-8)


def test_force_control_below_and_above_free_critical_load():
    free = critical_force(PAPER, "free").loads[0]
    eq = solve_equilibrium_under_force(PAPER, -0.5 * free, 0.0)
    assert np.allclose(eq.q, 0, atol=1e-9) and eq.stable and eq.control == "force"
    eq = solve_equilibrium_under_force(PAPER, -1.2 * free, 0.0)
    assert eq.stable and np.abs(eq.q).max() > 0.05
    assert np.allclose(PAPER.gradient(eq.q), PAPER.jacobian(eq.q).T @ eq.force, atol=1e-9)


def test_force_control_round_trip_with_displacement_control():
    """Prescribe a force, read the tip, prescribe that tip: same configuration, same force."""
    for fx, fy in [(0.3, 0.2), (-0.04, 0.1), (0.0, -0.15)]:
        feq = solve_equilibrium_under_force(PAPER, fx, fy)
        assert feq.stable
        dx, dy = PAPER.straight_length - feq.tip[0], feq.tip[1]
        deq = solve_equilibrium(PAPER, dx, dy, q0=feq.q)
        assert np.allclose(deq.q, feq.q, atol=1e-7)
        assert np.allclose(deq.force, [fx, fy], atol=1e-8)


def test_displacement_stable_can_be_dead_load_unstable():
    """Under a prescribed tip the post-buckled U shape is stable; under the same dead load it is
    not (its Hessian without the tip constraint has a negative eigenvalue), so IPOPT leaves it."""
    from tensegrity_opt.analyses.equilibria.stability import classify
    deq = solve_equilibrium(PAPER, 0.3, 0.5)
    assert classify(PAPER, deq.q, deq.force, constrained=True).morse_index == 0
    assert classify(PAPER, deq.q, deq.force, constrained=False).morse_index == 1


def test_force_control_errors():
    with pytest.raises(InvalidParameterError) as ei:
        solve_equilibrium_under_force(PAPER, float("nan"), 0.0)
    assert ei.value.field == "fx"
    with pytest.raises(NoEquilibriumError) as ei:
        solve_equilibrium_under_force(PAPER, -3.0, 0.0)     # folds onto the joint limits
    assert isinstance(ei.value, RuntimeError) and ei.value.status


def test_threads_share_nothing():
    """Several threads solving at once (per-thread CasADi instances) give the serial answers."""
    dxs = [0.05, 0.2, 0.4, 0.8]
    serial = [solve_equilibrium(PAPER, d, 0.1).q for d in dxs]
    out = [None] * len(dxs)

    def work(i):
        for _ in range(3):
            out[i] = solve_equilibrium(PAPER, dxs[i], 0.1).q

    threads = [threading.Thread(target=work, args=(i,)) for i in range(len(dxs))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for a, b in zip(out, serial):
        assert np.allclose(a, b, atol=1e-10)


@pytest.mark.slow
@pytest.mark.parametrize("m", [PAPER, Manipulator([Segment(1.0, 1.0, 1.0, 1.0), Segment(0.9, 1.3, 2.0, 1.5),
                                                   Segment(1.1, 0.8, 0.7, 0.9), Segment(1.0, 1.1, 1.5, 1.2),
                                                   Segment(0.8, 0.9, 1.2, 1.1)])])
def test_newton_seeded_search_agrees_with_ipopt_from_every_seed(m):
    """Two methods, one answer: the fast Newton-seeded global search and IPOPT from every seed."""
    L = m.straight_length
    for dx in np.linspace(0.02, 0.8 * L, 6):
        for dy in np.linspace(-0.5 * L, 0.5 * L, 5):
            outcomes = []
            for method in ("auto", "ipopt"):
                try:
                    outcomes.append(solve_equilibrium(m, dx, dy, method=method))
                except (ValueError, RuntimeError) as exc:
                    outcomes.append(type(exc))
            a, b = outcomes
            if isinstance(a, type) or isinstance(b, type):
                assert a is b, (dx, dy, a, b)
            else:
                assert a.energy == pytest.approx(b.energy, rel=1e-10), (dx, dy)
                assert a.stable and b.stable


@pytest.mark.slow
def test_bistable_segments_use_ipopt_descent_too():
    """With K < 0 (condition (4) fails) each segment is bistable and Newton from the seeds often
    lands on saddles only: "auto" must still be at least as good as IPOPT from every seed."""
    m = Manipulator.uniform(6, a=0.6, b=1.0, k=1.0, L0=1.2)
    assert not m.monotonic and m.stiffness[0] < 0
    L = m.straight_length
    checked = 0
    for dx in np.linspace(1.5, 0.6 * L, 4):
        for dy in (-0.3 * L, 0.0, 0.25 * L):
            try:
                ref = solve_equilibrium(m, dx, dy, method="ipopt").energy
            except (RuntimeError, ValueError):
                continue
            checked += 1
            got = solve_equilibrium(m, dx, dy)
            assert got.stable and got.energy <= ref + 1e-9 * max(1.0, abs(ref))
    assert checked >= 6


@pytest.mark.parametrize("m", [PAPER, Manipulator([Segment(1.0, 1.0, 1.0, 1.0), Segment(0.9, 1.3, 2.0, 1.5),
                                                   Segment(1.1, 0.8, 0.7, 0.9), Segment(1.0, 1.1, 1.5, 1.2)])])
def test_least_energy_search_keeps_what_the_full_search_would_pick(m):
    """search_stable(least=True) classifies in order of energy and stops after the least stable energy;
    what it returns is exactly the full search's stable set cut to the ties of its least energy
    (the same objects' numbers, in the same order), and the unstable count is never larger."""
    from tensegrity_opt.analyses.equilibria.least_energy import search_stable
    from tensegrity_opt.analyses.equilibria.seeds import seed_starts

    L = m.straight_length
    for dx in np.linspace(0.02, 0.6 * L, 5):
        for dy in (0.0, 0.13 * L, -0.2 * L):
            target = m.target(dx, dy)
            starts = seed_starts(m, dx, dy)
            full, n_full = search_stable(m, target, starts, {}, minimize=False)
            least, n_least = search_stable(m, target, starts, {}, minimize=False, least=True)
            if not full:
                assert not least and n_least == n_full
                continue
            e_min = min(e.energy for e in full)
            ties = [e for e in full if e.energy <= e_min + 1e-9 * max(1.0, abs(e_min))]
            assert [(e.q.tolist(), e.energy, e.solver.iterations) for e in least] == \
                   [(e.q.tolist(), e.energy, e.solver.iterations) for e in ties], (dx, dy)
            assert n_least <= n_full


# Two asymmetric monotonic chains found by a random search (see the seeds module): under these large
# deflections the least-energy equilibrium is a C curled near the joint limits, which the mode and
# random seeds missed (the search returned the U branch, 6.6698 instead of 4.5947, or nothing).
_LARGE_DEFLECTION = [
    ([(0.8781699912119716, 1.1007219190227988, 0.9442662571352722, 1.2010074179123316, 1.789508866961235,
       0.8422162502868251),
      (0.774675927682128, 0.9953847179431407, 1.7772532449605976, 0.9050497919310372, 1.7876892852443016,
       1.0934533318608768),
      (0.7818905679212979, 1.021527236483717, 1.4808578047012813, 1.8201049907114861, 1.855360483930753,
       1.1001941001946451),
      (1.0473613002323532, 1.0539972085218925, 1.0792152993625055, 1.6640627982184304, 1.8770232466757157,
       1.3750334880871655),
      (1.1496632069781527, 0.8510483023874074, 0.7492860315892221, 1.6463016251761382, 1.1666620232766234,
       1.5024390202238975),
      (0.8982426640703778, 0.8583141758122244, 1.6313504903080203, 1.6121488113197824, 0.9742441063870553,
       1.1117259699828208)], 7.5566286290524225),
    ([(1.0623083889208083, 0.8226832541181018, 1.5992392100791228, 1.7261449035473186, 1.3342322878979198,
       0.8749446954330838),
      (1.0097479532673295, 0.898465463852469, 1.4650359933833297, 1.0649337636012561, 1.564596224465474,
       1.1097618560931757),
      (0.8859222135447771, 1.009869895613795, 1.4465197736461919, 0.8047517623628078, 1.954461290242989,
       1.1469656908920278),
      (0.783612079060488, 0.9025249532640583, 0.6012143908521406, 1.1343843693522557, 1.726203573580058,
       1.651480324021818),
      (0.7173434718241897, 0.8547727610133331, 0.9821419106023555, 1.652382730085109, 1.3856937630226704,
       1.9078210189288232),
      (0.993830259556162, 1.0483627122448536, 1.6515366890709833, 1.625387371539444, 1.2126057500172722,
       1.1084100820732161),
      (0.8625728338354093, 0.9956988723085247, 0.7125841556358787, 1.1619982925651684, 1.567787907057995,
       0.9628574059801757)], 10.056600070360153),
]


@pytest.mark.slow
@pytest.mark.parametrize("rows, dx", _LARGE_DEFLECTION, ids=["n6", "n7"])
def test_large_deflection_c_shape_is_found(rows, dx):
    """The least energy of the independent reference model (SLSQP from 260 starts) is what the global
    search returns, by every method, and the shape is the C near the limits the arc seeds reach."""
    from reference_model import Chain

    m = Manipulator([Segment(a, b, (k1, k2), (L1, L2)) for a, b, k1, k2, L1, L2 in rows])
    assert m.monotonic
    e_ref, q_ref, _ = Chain.from_segments(rows).global_min(dx, 0.0)
    for method in ("auto", "newton", "ipopt"):
        eq = solve_equilibrium(m, dx, 0.0, method=method)
        assert eq.stable and eq.energy == pytest.approx(e_ref, rel=1e-9), method
        assert eq.shape == "C"
        np.testing.assert_allclose(np.abs(eq.q), np.abs(q_ref), atol=1e-6)


def _bistable_chains():
    """Multistable chains of three families (uniform, heterogeneous, asymmetric preloads), fixed seed."""
    rng = np.random.default_rng(2929)
    segs = []
    for _ in range(5):
        a, b, k = rng.uniform(0.45, 0.75), rng.uniform(0.85, 1.15), rng.uniform(0.6, 1.8)
        segs.append(Segment(a, b, k, rng.uniform(0.4, 0.85) * 2.0 * (b * b - a * a) / b))
    asym = [Segment(s.a, s.b, (s.k1, 1.3 * s.k1), (s.L1_0, 0.9 * s.L1_0)) for s in segs[:4]]
    return [Manipulator.uniform(6, a=0.6, b=1.0, k=1.0, L0=1.2), Manipulator(segs), Manipulator(asym)]


@pytest.mark.parametrize("m", _bistable_chains(), ids=["uniform6", "heterogeneous5", "asymmetric4"])
def test_least_energy_search_on_a_large_sample_keeps_the_full_search_pick(m):
    """With thousands of starts (several kernel calls: the rows are compared in Python) search_stable(least=True)
    deduplicates only the points it classifies, in order of energy; its answer is exactly the full search's
    (every converged start deduplicated first, every distinct point classified) cut to the ties of the least
    energy (the same rows' numbers, in the same order), and it never counts more unstable points."""
    from tensegrity_opt.analyses.equilibria.least_energy import search_stable
    from tensegrity_opt.analyses.equilibria.seeds import projected_sample, well_seeds

    L = m.straight_length
    for dx, dy in ((0.25 * L, 0.0), (0.4 * L, 0.12 * L), (0.15 * L, -0.2 * L)):
        target = m.target(dx, dy)
        starts = np.vstack([well_seeds(m, dx, dy, hilltops=False), projected_sample(m, target, 150 * m.n, 5)])
        assert starts.shape[0] > 64
        full, n_full = search_stable(m, target, starts, {}, minimize=False)
        least, n_least = search_stable(m, target, starts, {}, minimize=False, least=True)
        assert full, (dx, dy)
        e_min = min(e.energy for e in full)
        ties = [e for e in full if e.energy <= e_min + 1e-9 * max(1.0, abs(e_min))]
        assert [(e.q.tolist(), e.energy, e.solver.iterations) for e in least] == \
               [(e.q.tolist(), e.energy, e.solver.iterations) for e in ties], (dx, dy)
        assert n_least <= n_full


@pytest.mark.parametrize("fx, fy", [(0.0, 0.01), (0.3, -0.2), (-0.2, 0.15)])
def test_one_segment_under_a_tip_force_balances_it(fx, fy):
    """A regression: with one joint the CasADi model counted the segment twice (``phi[:-1]`` of a 1 x 1 symbol is
    1 x 0, and the relative angles broadcast into two entries), so the force solve stopped at half the angle. The
    answer balances ``E'(q) = b (-fx sin q + fy cos q)`` (the segment's torque in closed form)."""
    import math

    import tensegrity_opt as to

    a, b, k, L0 = 1.1, 1.0, 2.0, 1.2
    m = to.Manipulator([to.Segment(a, b, k, L0)])
    q = float(to.solve_equilibrium_under_force(m, fx, fy).q[0])
    c, beta = math.hypot(a, b), math.atan2(a, b)
    dE = sum(k * (2 * c * math.cos(beta + s * q / 2) - L0) * (-s * c * math.sin(beta + s * q / 2)) for s in (1, -1))
    assert dE == pytest.approx(b * (-fx * math.sin(q) + fy * math.cos(q)), abs=1e-10)
