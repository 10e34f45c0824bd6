"""The checks of a branch (``trace_branch``, ``switch_branch``, ``bifurcation_diagram``, ``limit_load``) against
the independent references, and the chains they are run on.

Every expected number comes from ``tests/support/reference_paths.py`` / ``tests/support/reference_model.py``
(numpy + scipy, relative joint angles, no import of the library) or from a closed form. Conventions
(``docs/model.md``): ``grad E = J^T F`` with ``F`` the tip force holding the chain; the deflection ``(dx, dy)``
puts the tip at ``(2 sum b - dx, dy)``; the joint range is ``|q_i| < pi - 2 beta_i``. Branches and references are
cached: each is computed once per process.
"""

from __future__ import annotations

import functools
import json

import numpy as np
import pytest
import reference_model as R
import reference_paths as RP

import tensegrity_opt as to
from tensegrity_opt import Control, trace_branch


# (a, b, k1, k2, L1_0, L2_0) per segment
def _sym(a, b, k, L0):
    return (a, b, k, k, L0, L0)


CHAINS = {
    "paper4": [_sym(1.0, 1.0, 1.0, 1.0)] * 4,
    "paper2": [_sym(1.0, 1.0, 1.0, 1.0)] * 2,
    "G1x3": [_sym(0.8, 1.2, 2.5, 1.7)] * 3,
    "hetero3": [_sym(1.0, 1.0, 1.0, 1.0), _sym(0.9, 1.3, 2.0, 1.5), _sym(1.1, 0.8, 0.7, 0.9)],
    # every segment's first spring 0.1 shorter: a pre-bent arm (rest q_i = 0.105166)
    "pre_bent3": [(1.0, 1.0, 1.0, 1.0, 0.9, 1.0)] * 3,
    # bistable segments, K = k (b L0 - 2 (b^2 - a^2)) = -0.5, wells +-1.682137
    "bistable3": [_sym(0.5, 1.0, 1.0, 1.0)] * 3,
    # one bistable segment with wells +-1.348261 inside +-pi/2 (a y force acts as a torque)
    "one_seg": [_sym(0.6, 1.0, 1.0, 1.0)],
}
STRAIGHT = ("paper4", "G1x3", "hetero3")
RES_TOL = 1e-8          # equilibrium residual, relative to max k c^2
RANK_TOL = 1e-6         # reference eigenvalues closer to 0 than this: Morse index not compared


@functools.lru_cache(maxsize=None)
def ref(name) -> R.Chain:
    return R.Chain.from_segments(CHAINS[name])


@functools.lru_cache(maxsize=None)
def lib(name) -> to.Manipulator:
    return to.Manipulator([to.Segment(a, b, k=(k1, k2), L0=(l1, l2)) for a, b, k1, k2, l1, l2 in CHAINS[name]])


def chain_of(m: to.Manipulator) -> R.Chain:
    """The reference model's chain of a library ``Manipulator``."""
    return R.Chain(m.a, m.b, m.k1, m.k2, m.L1_0, m.L2_0)


def wells(name):
    a, b, k1, k2, l1, l2 = CHAINS[name][0]
    return RP.segment_wells(a, b, k1, k2, l1, l2)


def bistable_rest():
    """The (+, +, +) rest configuration of the bistable chain."""
    return np.full(3, wells("bistable3")[1])


def _expected_stability(before, after):
    if before == 0 and after > 0:
        return "lost"
    if before > 0 and after == 0:
        return "gained"
    return "unchanged"


def _reduction(boundary):
    """Which reduced Hessian decides stability: free / guided / displacement (tip held)."""
    return {"load": "free", "guided": "guided", "displacement": "displacement",
            "preload_free": "free", "preload_held": "displacement"}[boundary]


def check_branch(c: R.Chain, br, control, *, direction=None, base=(0.0, 0.0), tip0=None, preload=None,
                 from_start=True):
    """Every point of ``br`` is a configuration (strictly inside the joint range) and an
    equilibrium of the reference model under the control; the records are consistent.

    ``control``: "load", "guided", "displacement", "preload_free", "preload_held";
    ``tip0`` the tip at t = 0 (guided / displacement / held); ``preload`` the (2n,) unit
    direction of the rest lengths (the chain at a point has L0 = L0_start + t preload)."""
    n = c.n
    P = br.t.shape[0]
    assert P >= 2, f"a branch of {P} point(s): status {br.status!r}"
    for name, shape in (("t", (P,)), ("q", (P, n)), ("force", (P, 2)), ("tip", (P, 2)),
                        ("deflection", (P, 2)), ("energy", (P,)), ("morse_index", (P,)),
                        ("stable", (P,)), ("s", (P,))):
        arr = np.asarray(getattr(br, name))
        assert arr.shape == shape, f"{name}: shape {arr.shape}, expected {shape}"
    for name in ("t", "q", "force", "tip", "deflection", "energy", "s"):
        assert np.all(np.isfinite(np.asarray(getattr(br, name), float))), name
    assert isinstance(br.status, str) and isinstance(br.success, (bool, np.bool_))
    json.dumps(br.to_dict())

    q = np.asarray(br.q, float)
    t = np.asarray(br.t, float)
    F = np.asarray(br.force, float)
    # inside the physical range, strictly
    assert np.all(np.abs(q) < c.limits), "a point outside the joint range |q_i| < pi - 2 beta_i"
    if from_start:
        assert t[0] == pytest.approx(0.0, abs=1e-12) and t[1] > t[0]
    s = np.asarray(br.s, float)
    assert s[0] == pytest.approx(0.0, abs=1e-12) and np.all(np.diff(s) > 0)

    d = None if direction is None else RP.unit(direction)
    base = np.asarray(base, float)
    chains = []
    for i in range(P):
        ci = c
        if preload is not None:
            L0 = np.column_stack([c.L10, c.L20]).ravel() + t[i] * np.asarray(preload, float)
            ci = R.Chain(c.a.copy(), c.b.copy(), c.k1.copy(), c.k2.copy(), L0[0::2].copy(), L0[1::2].copy())
        chains.append(ci)
        tip = ci.tip(q[i])
        np.testing.assert_allclose(br.tip[i], tip, atol=1e-9)
        np.testing.assert_allclose(br.deflection[i], [2.0 * c.b.sum() - tip[0], tip[1]], atol=1e-9)
        res = RP.equilibrium_residual(ci, q[i], F[i])
        assert res < RES_TOL, f"point {i}: reference equilibrium residual {res:.2e}"
        # the control
        if control == "load":
            np.testing.assert_allclose(F[i], base + t[i] * d, atol=1e-9)
        elif control == "guided":
            assert F[i, 0] == pytest.approx(base[0] + t[i] * d[0], abs=1e-9)
            assert tip[1] == pytest.approx(tip0[1], abs=1e-9)
        elif control == "displacement":
            defl0 = np.array([2.0 * c.b.sum() - tip0[0], tip0[1]])
            np.testing.assert_allclose(br.deflection[i], defl0 + t[i] * d, atol=1e-9)
            assert br.energy[i] == pytest.approx(ci.energy(q[i]), rel=1e-9, abs=1e-12)
        elif control == "preload_held":
            np.testing.assert_allclose(tip, tip0, atol=1e-9)
            assert br.energy[i] == pytest.approx(ci.energy(q[i]), rel=1e-9, abs=1e-12)
        # stability: the reference's inertia where it is not degenerate
        red = _reduction(control)
        w = _reduced_eigs(ci, q[i], F[i], red)
        if w.size == 0 or np.min(np.abs(w)) > RANK_TOL:
            m_ref = int(np.sum(w < 0))
            assert int(br.morse_index[i]) == m_ref, f"point {i}: Morse index {br.morse_index[i]}, reference {m_ref}"
            assert bool(br.stable[i]) == (m_ref == 0)

    for e in br.events:
        check_event(c if preload is None else None, br, e, control)
    return chains


def _reduced_eigs(c, q, F, red):
    H = RP.lagrangian_hess(c, q, F)
    if red == "free":
        return np.linalg.eigvalsh(H)
    import scipy.linalg as sla
    J = c.jac(q)
    Z = sla.null_space(J[1][None, :]) if red == "guided" else sla.null_space(J)
    return np.linalg.eigvalsh(Z.T @ H @ Z) if Z.shape[1] else np.zeros(0)


def check_event(c, br, e, control):
    P = br.t.shape[0]
    assert e.kind in {"fold", "branch_point", "joint_limit"}
    assert 0 <= e.index <= P - 1
    assert e.stability in {"lost", "gained", "unchanged"}
    assert e.stability == _expected_stability(e.morse_before, e.morse_after)
    if e.index + 1 < P and e.kind != "joint_limit":
        assert e.morse_before == int(br.morse_index[e.index])
        assert e.morse_after == int(br.morse_index[e.index + 1])
    if c is None:
        return
    q = np.asarray(e.q, float)
    assert np.all(np.abs(q) <= c.limits + 1e-12)
    np.testing.assert_allclose(e.tip, c.tip(q), atol=1e-8)
    assert np.isfinite(e.energy)
    if control in ("displacement", "preload_held"):
        assert e.energy == pytest.approx(c.energy(q), rel=1e-8, abs=1e-12)
    assert RP.equilibrium_residual(c, q, e.force) < RES_TOL
    if e.kind in ("fold", "branch_point"):
        assert np.all(np.abs(q) < c.limits)
        # singular there: the reference's smallest |eigenvalue| is ~ 0
        w = _reduced_eigs(c, q, np.asarray(e.force, float), _reduction(control))
        assert np.min(np.abs(w)) < 1e-4 * max(1.0, np.max(np.abs(w))), f"{e.kind} at t={e.t}: eigenvalues {w}"


def check_turning_point(br, e, window=6):
    """A fold is a turning point of t along the branch: e.t is the extremum of t over the
    points around it (a maximum when t grew before it, a minimum when it decreased)."""
    t = np.asarray(br.t, float)
    i = e.index
    lo, hi = max(0, i - window), min(t.size, i + window + 2)
    before = t[i] - t[max(0, i - 1)] if i > 0 else t[min(i + 1, t.size - 1)] - t[i]
    tol = 1e-10 * max(1.0, abs(e.t))
    if before > 0:
        assert e.t >= t[lo:hi].max() - tol, f"fold at t={e.t} below the branch's nearby maximum {t[lo:hi].max()}"
    else:
        assert e.t <= t[lo:hi].min() + tol, f"fold at t={e.t} above the branch's nearby minimum {t[lo:hi].min()}"
    # and the branch really turns there: t[i] and t[i+1] on the same side of e.t
    if i + 1 < t.size:
        assert (t[i] - e.t) * (t[i + 1] - e.t) >= -tol ** 2


def events_of(br, kind):
    return [e for e in br.events if e.kind == kind]


@functools.lru_cache(maxsize=None)
def modes(name, boundary):
    return RP.buckling_modes(ref(name), boundary)


@functools.lru_cache(maxsize=None)
def ref_limit(name, boundary, direction=(-1.0, 0.0), max_load=2.0):
    c = ref(name)
    if name == "bistable3":
        q0 = bistable_rest()
    elif name == "one_seg":
        q0 = np.array([wells("one_seg")[0]])
    else:
        q0 = RP.rest_configuration(c)
    return RP.limit_load_reference(c, q0, direction, boundary, max_load)


def load_control(boundary, direction=(-1.0, 0.0)):
    return Control.load(direction=direction, base=(0.0, 0.0)) if boundary == "free" else \
        Control.guided(direction=direction, base=(0.0, 0.0))


def check_name(boundary):
    return "load" if boundary == "free" else "guided"


def t_max_two_branch_points(P):
    return 0.5 * (P[1] + P[2]) if P.size > 2 else 1.25 * P[1]


@functools.lru_cache(maxsize=None)
def straight_branch(name, boundary):
    P, _ = modes(name, boundary)
    return trace_branch(lib(name), None, load_control(boundary), t_max=float(t_max_two_branch_points(P)),
                        max_points=400)
