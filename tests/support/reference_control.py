"""The reference of the preload-control tests: the arm with commanded rest lengths, and its forward solve.

Built on the numpy reference model (``reference_model.py``) only; it does NOT import ``tensegrity_opt`` (a
``Manipulator`` is read through its ``n`` and its segments' ``a``, ``b``, ``k1``, ``k2``).

* :func:`ref_chain` -- the reference ``Chain`` of a manipulator's geometry and stiffnesses with the rest lengths
  ``ell`` (shape ``(n, 2)`` or ``(2n,)``, segment-major) in place of its own;
* :func:`forward` -- the forward quasi-static solve under the dead load ``F`` from the previous configuration:
  a local minimiser of ``E - F . tip`` (scipy's trust-exact on the reference's own gradient and Hessian),
  polished by Newton; it asserts the result is an equilibrium (gradient ~0) in the joints' range;
* :func:`equilibrium` -- the same solve for a search (a multi-start reference): None where it finds no
  equilibrium in the range.
"""

from __future__ import annotations

import numpy as np
import scipy.optimize as so
from reference_model import Chain

#: The largest |gradient of E - F . tip| a forward solve's result may have.
GRADIENT_TOL = 1e-11


def ref_chain(m, ell) -> Chain:
    """The reference chain of manipulator ``m`` with rest lengths ``ell`` (``(n, 2)`` or ``(2n,)``)."""
    ell = np.asarray(ell, float).reshape(m.n, 2)
    return Chain.from_segments([(s.a, s.b, s.k1, s.k2, l1, l2) for s, (l1, l2) in zip(m.segments, ell)])


def _solve(ch: Chain, F, q_prev):
    F = np.asarray(F, float)
    res = so.minimize(lambda q: ch.energy(q) - F @ ch.tip(q), np.asarray(q_prev, float),
                      jac=lambda q: ch.lagrangian_grad(q, F), hess=lambda q: ch.lagrangian_hess(q, F),
                      method="trust-exact", options={"gtol": 1e-12})
    q = res.x
    for _ in range(4):                          # polished by Newton on the reference's own derivatives
        g = ch.lagrangian_grad(q, F)
        if np.abs(g).max() < 1e-3 * GRADIENT_TOL:
            break
        q = q - np.linalg.solve(ch.lagrangian_hess(q, F), g)
    return q, res


def forward(ch: Chain, F, q_prev) -> np.ndarray:
    """The equilibrium of ``ch`` under the dead load ``F`` reached from ``q_prev`` (asserted: gradient below
    :data:`GRADIENT_TOL`, in the joints' range)."""
    q, res = _solve(ch, F, q_prev)
    assert np.abs(ch.lagrangian_grad(q, np.asarray(F, float))).max() < GRADIENT_TOL, res.message
    assert ch.in_range(q), q
    return q


def equilibrium(ch: Chain, F, q_prev) -> np.ndarray | None:
    """:func:`forward` for a search: the equilibrium, or None where the solve ends off one or out of range."""
    try:
        q, _ = _solve(ch, F, q_prev)
    except np.linalg.LinAlgError:
        return None
    if not np.all(np.isfinite(q)) or np.abs(ch.lagrangian_grad(q, np.asarray(F, float))).max() >= GRADIENT_TOL:
        return None
    return q if ch.in_range(q) else None
