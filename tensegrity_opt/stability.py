"""Stability of an equilibrium: inertia of the (reduced) Hessian of the Lagrangian.

Under a prescribed tip displacement the configuration lives on the manifold
``tip(q) = target`` of dimension ``n - 2``; the equilibrium is classified by the
inertia of ``Z^T H Z`` with ``H = Hess E - Fx Hess x - Fy Hess y`` and ``Z`` a basis
of the null space of the tip Jacobian (conventions.md). Under a prescribed force
``Z = I``. The Morse index is the number of negative eigenvalues: 0 for a
minimum (stable), the full dimension for a maximum, anything between for a saddle.

The change ``q -> phi`` (absolute angles) is linear and invertible, so the
inertia is the same in either coordinate; it is computed in ``phi``, where
``H`` is tridiagonal.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla

from .manipulator import Manipulator
from .solvers import model

__all__ = ["Inertia", "classify"]


@dataclass(frozen=True)
class Inertia:
    """Eigenvalues of the reduced Hessian and the counts that classify the equilibrium."""

    eigenvalues: np.ndarray
    morse_index: int
    degenerate: bool

    @property
    def stable(self) -> bool:
        """A strict local minimum: Morse index 0 and no (near-)zero eigenvalue."""
        return self.morse_index == 0 and not self.degenerate


def reduced_hessian(m: Manipulator, q: np.ndarray, force: np.ndarray, *, constrained: bool) -> np.ndarray:
    """``Z^T H Z`` (``constrained``: tip held) or ``H`` (force prescribed), in absolute angles."""
    _, _, H, J, _ = model(m.n).evaluate(m.params, np.asarray(q, float), np.asarray(force, float))
    if not constrained:
        return H
    Z = sla.null_space(J)
    return Z.T @ H @ Z


def classify(m: Manipulator, q: np.ndarray, force: np.ndarray, *, constrained: bool,
             rel_tol: float = 1e-9) -> Inertia:
    """Inertia of the reduced Hessian at an equilibrium ``(q, force)``.

    Eigenvalues with ``|lambda| <= rel_tol * max(1, ||H||)`` count as zero (``degenerate``).
    """
    Hr = reduced_hessian(m, q, force, constrained=constrained)
    if Hr.size == 0:
        return Inertia(np.zeros(0), 0, False)
    w = sla.eigvalsh(Hr)
    tol = rel_tol * max(1.0, float(np.abs(w).max()))
    return Inertia(w, int(np.sum(w < -tol)), bool(np.any(np.abs(w) <= tol)))
