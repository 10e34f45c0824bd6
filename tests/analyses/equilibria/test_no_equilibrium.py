"""Targets with no equilibrium inside the physical joint range: ``find_equilibria`` answers an empty set when the
target is reachable inside the range (every solution of the equations lies outside it), refuses a target outside
the range's workspace, and keeps a solver breakdown an error.

The chains (as ``(a, b, k, L0)``, symmetric springs) were drawn at random with targets near the edge of the
range's workspace; on each target the certified homotopy (96 or 832 paths, none failed) finds no root inside the range,
and 2000 least-squares starts of the reference model (``kkt_least_squares``) converge only to solutions outside
it.
"""

import numpy as np
import pytest
from reference_model import Chain, kkt_least_squares

import tensegrity_opt.analyses.equilibria.all_equilibria as all_equilibria
from tensegrity_opt import Manipulator, Segment, find_equilibria, solve_equilibrium
from tensegrity_opt.errors import NoEquilibriumError, SolverError, UnreachableTargetError
from tensegrity_opt.numerics.homotopy import homotopy_available
from tensegrity_opt.numerics.results import LocalResult

needs_phc = pytest.mark.skipif(not homotopy_available(),
                               reason="PHCpack's phc is not installed (apt-get install phcpack)")

#: (segments, dx, dy): reachable inside the range, no equilibrium inside it
NONE_INSIDE = [
    ([(0.4244907, 1.1061139, 2.7977215, 2.0757221), (1.2855203, 1.0943198, 1.1138807, 1.9328666),
      (0.6116747, 1.2481474, 0.6567948, 2.0724451)], 8.356180218401274, -0.07981382020185246),
    ([(1.3715984, 0.7569187, 2.3705449, 1.1348328), (0.609281, 1.3145023, 0.5420682, 0.7935969),
      (1.3990259, 0.7359321, 2.6226113, 1.5339237)], 3.3734821351943287, 0.959030611535475),
    ([(1.2054486, 0.7404724, 1.2079276, 2.0699813), (1.1459484, 0.6141333, 2.5158723, 2.0865652),
      (0.5778258, 1.0642532, 0.9918591, 0.6465571)], 2.0497525030193544, 0.3363304093936288),
    ([(1.3470062, 1.0839657, 1.9624156, 0.2099818), (0.4521763, 0.6902586, 0.8445569, 2.4601873),
      (0.4027471, 0.8292592, 0.6460561, 1.6180259)], 4.762199617596034, -1.2132366039758693),
]
#: the same with four segments (832 homotopy paths, seconds each)
NONE_INSIDE_4 = [
    ([(0.7269723, 1.3885492, 1.2967771, 1.9819449), (1.2698965, 0.8519763, 1.5947047, 0.9632348),
      (0.5069536, 0.9310689, 1.1033804, 0.6800059), (0.5847316, 0.6744781, 2.5345692, 1.0863113)],
     8.790364323492653, -0.19115672088319668),
    ([(0.7713871, 0.7561586, 0.5419551, 0.4948071), (0.7946686, 0.8539796, 2.0418199, 1.158053),
      (1.0073307, 0.700754, 0.8349678, 0.856759), (0.4961084, 0.8292559, 1.6504483, 1.8115222)],
     6.696641695638417, 3.19415615437031),
]
ALL = NONE_INSIDE + [pytest.param(*c, marks=pytest.mark.slow) for c in NONE_INSIDE_4]
ALL_IDS = [f"n{len(c[0])}-dx{c[1]:.3f}-dy{c[2]:+.3f}" for c in NONE_INSIDE + NONE_INSIDE_4]
#: within the chain's length, outside the workspace of the range: no configuration inside the range reaches it
OUTSIDE_WORKSPACE = ([(0.6406598, 0.8237603, 0.7910227, 0.265325), (1.3813072, 0.8151609, 1.6729369, 1.7244185)],
                     3.777579300549713, 1.7907393228447095)


def _chain(segs) -> Manipulator:
    return Manipulator([Segment(*s) for s in segs])


def _ids(cases):
    return [f"n{len(c[0])}-dx{c[1]:.3f}-dy{c[2]:+.3f}" for c in cases]


@pytest.mark.parametrize("segs, dx, dy", NONE_INSIDE[:2], ids=_ids(NONE_INSIDE[:2]))
def test_no_equilibrium_inside_the_range_is_an_empty_set(segs, dx, dy):
    m = _chain(segs)
    eqs = find_equilibria(m, dx, dy)
    assert len(eqs) == 0 and eqs.success and eqs.status == "searched" and eqs.method == "search"
    assert not eqs.certified
    assert eqs.message.startswith("no equilibrium inside the physical joint range")
    assert "press a joint against its range limit" in eqs.message
    body = eqs.to_dict()
    assert body["success"] is True and body["equilibria"] == []
    # the least-energy configuration of the closed range rests on a stop (the issue "the arm as built"): the
    # least-energy solve returns it, with its contact torque, equal to an independent brute force
    import reference_tension_only as ref

    eq = solve_equilibrium(m, dx, dy)
    best = ref.least_energy(ref.segs_of(m), dx, dy)
    assert eq.at_stop.any() and eq.at_stop.tolist() == best.at_stop.tolist() and eq.stable
    assert eq.energy == pytest.approx(best.energy, rel=1e-8)
    np.testing.assert_allclose(eq.contact_torques, best.contact_torques, rtol=1e-4, atol=1e-8)


@needs_phc
@pytest.mark.parametrize("segs, dx, dy", ALL, ids=ALL_IDS)
def test_the_certified_homotopy_agrees_that_the_set_is_empty(segs, dx, dy):
    m = _chain(segs)
    cert = find_equilibria(m, dx, dy, method="homotopy")
    assert cert.status == "certified" and len(cert) == 0 and cert.failed_paths == 0
    assert cert.message.startswith("no equilibrium inside the physical joint range")
    assert len(find_equilibria(m, dx, dy)) == 0


#: the brute force (2000 starts, 20-40 s a target) on one target per chain length; the certified homotopy checks
#: every target above
BRUTE_FORCE = [NONE_INSIDE[0], NONE_INSIDE_4[0]]


@pytest.mark.slow
@pytest.mark.parametrize("segs, dx, dy", BRUTE_FORCE, ids=_ids(BRUTE_FORCE))
def test_a_brute_force_multistart_finds_no_equilibrium_inside_the_range(segs, dx, dy):
    inside, outside = kkt_least_squares(Chain.from_segments(segs), dx, dy, n_starts=2000)
    assert inside == [] and outside > 100          # the equations' solutions exist, all outside the range
    assert len(find_equilibria(_chain(segs), dx, dy)) == 0


def test_a_target_outside_the_range_workspace_is_unreachable():
    segs, dx, dy = OUTSIDE_WORKSPACE
    m = _chain(segs)
    with pytest.raises(UnreachableTargetError, match="outside the workspace of the physical joint range"):
        find_equilibria(m, dx, dy)
    with pytest.raises(UnreachableTargetError):
        solve_equilibrium(m, dx, dy)


def test_no_configuration_inside_the_range_reaches_the_outside_target():
    """The reference: bounded least squares on ``tip(q) = target`` from 300 starts stays far from the target."""
    import scipy.optimize as so

    segs, dx, dy = OUTSIDE_WORKSPACE
    ch = Chain.from_segments(segs)
    target = ch.target(dx, dy)
    rng = np.random.default_rng(0)
    gap = min(np.max(np.abs(so.least_squares(lambda q: ch.tip(q) - target, rng.uniform(-1, 1, ch.n) * ch.limits,
                                             jac=ch.jac, bounds=(-ch.limits, ch.limits)).fun))
              for _ in range(300))
    assert gap > 0.05


def test_a_solver_breakdown_stays_an_error(monkeypatch):
    """The same target when every local solve stops at its iteration limit: nothing tells whether an equilibrium
    exists, so no empty set is claimed."""
    segs, dx, dy = NONE_INSIDE[0]
    m = _chain(segs)

    def broken(m, target, q0, F0=None, *, minimize=False):
        return LocalResult(q=np.full(m.n, np.nan), force=np.full(2, np.nan), success=False,
                           status="Maximum_Iterations_Exceeded", iterations=3000, on_bound=False)

    monkeypatch.setattr(all_equilibria, "local_equilibrium", broken)
    with pytest.raises(SolverError, match="no Newton start converged") as exc:
        find_equilibria(m, dx, dy)
    assert not isinstance(exc.value, NoEquilibriumError)
    assert "IPOPT Maximum_Iterations_Exceeded" in exc.value.status
