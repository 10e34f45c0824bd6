"""Stability boundaries (``stability_boundary``) against other routes.

The expected numbers come from other solvers of the library that share nothing with the path system but the model
(the straight chain's eigenproblem in ``critical_force``), and from ``tests/support/reference_model.py`` (the
independent numpy model): a branch-point boundary is the critical load of the changed chain, a fold boundary passes
through the cusp of the unfolded pitchfork.
"""

from __future__ import annotations

import numpy as np
import pytest
import reference_model as ref
from branch_checks import chain_of

import tensegrity_opt as to
from tensegrity_opt.analyses.paths.boundaries import _chain_at, parameter_direction, stability_boundary

PAPER = to.Manipulator.uniform(4)
PREBENT = to.Manipulator([to.Segment(1.0, 1.0, 1.0, (1.02, 0.98))] * 4)


@pytest.mark.slow
@pytest.mark.parametrize("parameter, boundary", [("L0", "guided"), ("a", "free")])
def test_branch_point_boundary_is_the_critical_load_of_the_changed_chain(parameter, boundary):
    ctl = "guided" if boundary == "guided" else "load"
    B = stability_boundary(PAPER, ctl, parameter, start=np.zeros(4), p_min=-0.1, p_max=0.1, max_points=5)
    assert B.kind == "branch_point" and B.success
    assert B.p.min() == pytest.approx(-0.1) and B.p.max() == pytest.approx(0.1)
    for p, t in zip(B.p, B.t):
        mp = _chain_at(PAPER, B.parameter_direction, p)
        assert t == pytest.approx(ref.critical_loads_guided(chain_of(mp))[0] if boundary == "guided"
                                  else ref.critical_loads_free(chain_of(mp))[0], rel=1e-6)


#: (a, b, k1, k2, L1_0, L2_0) per segment: symmetric segments that differ (the straight chain buckles at a branch point)
HETERO = [(1.0, 1.0, 1.0, 1.0, 1.0, 1.0), (0.9, 1.3, 2.0, 2.0, 1.5, 1.5), (1.1, 0.8, 0.7, 0.7, 0.9, 0.9)]


def test_a_direction_is_read_in_the_order_of_the_chains_parameters():
    """A direction moving ONE segment's springs (segment 2's ``k1`` and ``k2``) as 6n numbers in the order of
    ``Manipulator.params`` (every ``a``, then every ``b``, ``k1``, ``k2``, ``L1_0``, ``L2_0``) or as the ``(6, n)``
    array of those rows: the boundary is the critical load of the chain changed by hand (segment 2's springs
    ``k + p``), from the independent model. Read a row per segment, the same numbers would move segment 2's ``b``
    and ``L1_0``. A ``(n, 6)`` array (a row per segment) is refused."""
    n = len(HETERO)
    m = to.Manipulator([to.Segment(a, b, (k1, k2), (l1, l2)) for a, b, k1, k2, l1, l2 in HETERO])
    rows = np.zeros((6, n))
    rows[2, 1] = rows[3, 1] = 1.0                  # k1 and k2 of segment 2
    flat = np.zeros(6 * n)
    flat[[2 * n + 1, 3 * n + 1]] = 1.0
    assert np.array_equal(parameter_direction(m, rows)[1], flat)
    assert np.array_equal(parameter_direction(m, flat)[1], flat)
    B = stability_boundary(m, "guided", flat, start=np.zeros(n), p_min=-0.3, p_max=0.3, max_points=3)
    assert B.kind == "branch_point" and B.success and B.parameter == "direction" and B.p.size == 3
    np.testing.assert_array_equal(B.parameter_direction, flat)
    for p, t in zip(B.p, B.t):
        by_hand = [seg if i != 1 else (*seg[:2], seg[2] + p, seg[3] + p, *seg[4:]) for i, seg in enumerate(HETERO)]
        assert t == pytest.approx(ref.critical_loads_guided(ref.Chain.from_segments(by_hand))[0], rel=1e-6)
    assert np.ptp(B.t) > 1e-2                      # the load moves with segment 2's springs
    with pytest.raises(to.InvalidParameterError, match=r"order of Manipulator.params.*got shape \(3, 6\)"):
        parameter_direction(m, rows.T)
    with pytest.raises(to.InvalidParameterError, match="order of Manipulator.params"):
        parameter_direction(m, flat[:-1])


def test_fold_boundary_through_the_cusp_of_the_unfolded_pitchfork():
    """A preload asymmetry unfolds the straight chain's pitchfork: the fold curve passes through the
    branch point (a cusp at p = 0, t = the critical load). Each point is checked on the independent model
    (an equilibrium of the pre-bent chain with the guide at y = 0, a zero eigenvalue of the Hessian reduced
    to dy = 0), and near the cusp the fold load grows like |p|^(2/3) (the imperfect pitchfork)."""
    B = stability_boundary(PAPER, "guided", "asymmetry", start=np.zeros(4), p_min=-0.03, p_max=0.03)
    assert B.kind == "fold" and B.p.min() < -0.03 and B.p.max() > 0.03
    crit = -to.critical_force(PAPER, "guided").force
    cusp0 = [c for c in B.cusps if abs(c.p) < 1e-9]
    assert cusp0 and cusp0[0].t == pytest.approx(crit, rel=1e-9)
    _, d = parameter_direction(PAPER, "asymmetry")
    for i in range(0, len(B.p), 7):
        ch = chain_of(_chain_at(PAPER, d, float(B.p[i])))
        q, F = B.q[i], B.force[i]
        assert F[0] == pytest.approx(-B.t[i], abs=1e-12)
        assert np.abs(ch.grad(q) - ch.jac(q).T @ F).max() < 1e-9 and abs(ch.tip(q)[1]) < 1e-10
        H = ch.lagrangian_hess(q, F)
        Q, _ = np.linalg.qr(ch.jac(q)[1:].T, mode="complete")
        w = np.linalg.eigvalsh(Q[:, 1:].T @ H @ Q[:, 1:])
        assert np.abs(w).min() < 1e-7 * np.abs(w).max()
    # the imperfect pitchfork: t - t_cr ~ C |p|^(2/3) on each side
    for side in (1, -1):
        sel = np.flatnonzero((side * B.p > 1e-4) & (side * B.p < 3e-3))
        assert sel.size >= 3
        slope = np.polyfit(np.log(np.abs(B.p[sel])), np.log(B.t[sel] - crit), 1)[0]
        assert slope == pytest.approx(2.0 / 3.0, abs=0.05)
