"""Chains of extreme but valid geometry, drawn by hypothesis, and the check that an answer on them is right.

``chains`` draws over the request schema's whole range (lengths 1e-6..1e6, stiffnesses 1e-6..1e9): slender
(a >> b), stubby, very stiff, very soft, tiny and huge, heterogeneous, with asymmetric preloads, bistable ones.
``check_equilibrium`` checks an equilibrium (the library's or the service's JSON) against the independent reference
model (``tests/support/reference_model.py``, which does not import the library): the equilibrium equations
``grad E = J^T F`` relative to the torque scale ``k c^2``, the tip on its target relative to the chain's length, the
angles inside the physical range, the reported tip and energy, and the stability label against the reference
reduced Hessian.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import strategies as st
from reference_model import Chain

import tensegrity_opt as to

#: the accuracy every returned equilibrium must have (the library's own bar is 1e-9)
TOL = 1e-8


def _log(lo: float, hi: float):
    return st.floats(math.log10(lo), math.log10(hi)).map(lambda e: 10.0 ** e)


@st.composite
def chains(draw, n_max: int = 8):
    """A chain of 2..n_max segments: one geometry scaled to an extreme unit, then varied per segment."""
    n = draw(st.integers(2, n_max))
    length = draw(_log(1e-5, 1e5))                 # the unit of length
    stiff = draw(_log(1e-5, 1e8))                  # the unit of stiffness
    slender = draw(st.sampled_from([1.0, 1.0, 1e-3, 1e3, 1e6, 1e-6]))   # a / b
    hetero = draw(st.booleans())
    segs = []
    for i in range(n):
        jit = (lambda: draw(st.floats(0.5, 2.0))) if hetero or i == 0 else (lambda: 1.0)
        b = length * jit()
        a = min(max(b * slender * jit(), 1e-6), 1e6)
        b = min(max(b, 1e-6), 1e6)
        k1 = min(max(stiff * jit(), 1e-6), 1e9)
        k2 = k1 * (draw(st.floats(0.5, 2.0)) if draw(st.booleans()) else 1.0)
        # rest lengths around the straight spring length 2b: shorter (monotonic) or longer (bistable)
        L10 = min(max(2 * b * draw(st.floats(0.3, 1.6)), 1e-6), 1e6)
        L20 = L10 * (draw(st.floats(0.8, 1.25)) if draw(st.booleans()) else 1.0)
        segs.append(to.Segment(a=a, b=b, k=(k1, min(max(k2, 1e-6), 1e9)), L0=(L10, min(max(L20, 1e-6), 1e6))))
    return to.Manipulator(segs)


def reference_chain(m: to.Manipulator) -> Chain:
    return Chain(m.a.copy(), m.b.copy(), m.k1.copy(), m.k2.copy(), m.L1_0.copy(), m.L2_0.copy())


def check_equilibrium(m: to.Manipulator, eq, target=None, *, stable: bool | None = None) -> None:
    """``eq`` (an Equilibrium or the service's JSON) is an equilibrium of ``m`` by the reference model."""
    if isinstance(eq, dict):
        q, F, tip, energy = (np.array(eq["q"], float), np.array([eq["force"]["fx"], eq["force"]["fy"]], float),
                             np.array(eq["tip"], float), eq["energy"])
        is_stable = eq["stable"]
        at_stop, contact = np.array(eq["at_stop"], bool), np.array(eq["contact_torques"], float)
    else:
        q, F, tip, energy, is_stable = eq.q, eq.force, eq.tip, eq.energy, eq.stable
        at_stop, contact = np.asarray(eq.at_stop, bool), np.asarray(eq.contact_torques, float)
    ref = reference_chain(m)
    T = float(np.max(np.maximum(ref.k1, ref.k2) * ref.c ** 2))
    L = float(np.sum(ref.b))
    if at_stop.any():
        # an equilibrium resting on joint stops (issue 40): those joints exactly at their bound, the others inside;
        # the free joints balanced, each stop pushing back with the reported contact torque (>= 0)
        assert np.allclose(np.abs(q[at_stop]), ref.limits[at_stop], rtol=1e-12, atol=0), \
            f"not on its stop: {q} vs {ref.limits}"
        assert np.all(np.abs(q[~at_stop]) < ref.limits[~at_stop]), f"outside the physical range: {q}"
        res = ref.grad(q) - ref.jac(q).T @ F
        assert float(np.abs(res[~at_stop]).max(initial=0.0)) / T <= TOL, "the free joints are not balanced"
        c = -np.sign(q[at_stop]) * res[at_stop]
        assert np.all(c >= -TOL * T) and np.allclose(c, contact[at_stop], rtol=1e-6, atol=TOL * T)
        off = float(np.abs(ref.tip(q) - (tip if target is None else np.asarray(target, float))).max())
        assert off <= TOL * L and abs(ref.energy(q) - energy) <= 1e-9 * max(T, abs(energy))
        return
    assert not np.any(contact), "contact torques without a joint on its stop"
    assert np.all(np.abs(q) < ref.limits), f"outside the physical range: {q} vs {ref.limits}"
    r = float(np.abs(ref.grad(q) - ref.jac(q).T @ F).max()) / T
    assert r <= TOL, f"grad E - J^T F = {r:.3g} (relative to k c^2 = {T:.3g})"
    assert float(np.abs(ref.tip(q) - tip).max()) <= TOL * L, "reported tip is not the tip of q"
    if target is not None:
        off = float(np.abs(ref.tip(q) - np.asarray(target, float)).max())
        assert off <= TOL * L, f"tip {ref.tip(q)} is {off:.3g} away from its target {target} (length {L:.3g})"
    assert abs(ref.energy(q) - energy) <= 1e-9 * max(T, abs(energy)), "reported energy is not E(q)"
    if stable is not None:
        assert is_stable == stable
    J = ref.jac(q)
    if target is not None and np.linalg.matrix_rank(J, tol=1e-12 * L) < 2:
        return                  # full extension: the straight chain is the only feasible point
    w = ref.reduced_eigs(q, F, constrained=target is not None, fd=False)
    if w.size:
        scale = max(T, float(np.abs(w).max()))
        if is_stable:
            assert w.min() > -1e-7 * scale, f"labelled stable with reduced eigenvalues {w}"
        elif np.all(w > 1e-6 * scale):
            pytest.fail(f"labelled not stable with a positive definite reduced Hessian {w}")


def deflection(m, frac_x, frac_y):
    L = float(m.b.sum())
    return 2 * L * frac_x, 2 * L * frac_y
