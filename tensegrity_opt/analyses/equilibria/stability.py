"""Stability of an equilibrium: inertia of the (reduced) Hessian of the Lagrangian.

Under a prescribed tip displacement the configuration lives on the manifold
``tip(q) = target`` of dimension ``n - 2``; the equilibrium is classified by the
inertia of ``Z^T H Z`` with ``H = Hess E - Fx Hess x - Fy Hess y`` and ``Z`` a basis
of the null space of the tip Jacobian (``docs/model.md``). Under a prescribed force
``Z = I``. The Morse index is the number of negative eigenvalues: 0 for a
minimum (stable), the full dimension for a maximum, anything between for a saddle.

The change ``q -> phi`` (absolute angles) is linear and invertible, so the
inertia is the same in either coordinate; it is computed in ``phi``, where
``H`` is tridiagonal.

Short chains (``n <= numerics.DENSE_MAX``): the eigenvalues of ``Z^T H Z`` with ``Z`` from a
QR factorisation of ``J^T``. Long chains: no dense step. The inertia of the KKT matrix
``[[H, J^T], [J, 0]]`` is that of ``Z^T H Z`` plus two positive and two negative
eigenvalues, and by Haynsworth it is the inertia of ``H`` (the signs of the pivots of
its tridiagonal LDL^T factorisation) plus that of the 2 x 2 Schur complement
``-J H^-1 J^T`` (one banded solve): O(n) in all. Only the count is returned then, not
the eigenvalues.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla

from ...model.manipulator import Manipulator
from ...numerics import chain_solver

__all__ = ["Inertia", "classify", "analyse", "classify_batch", "classify_reduced", "reduced_hessian",
           "inertia_of_reduced"]


@dataclass(frozen=True)
class Inertia:
    """Classification of an equilibrium.

    ``eigenvalues`` of the reduced Hessian (absolute-angle coordinates) for short chains,
    empty for long ones; ``dim`` the dimension of the reduced space.
    """

    eigenvalues: np.ndarray
    morse_index: int
    degenerate: bool
    dim: int

    @property
    def stable(self) -> bool:
        """A strict local minimum: Morse index 0 and no (near-)zero eigenvalue."""
        return self.morse_index == 0 and not self.degenerate


def reduced_hessian(m: Manipulator, q: np.ndarray, force: np.ndarray, *, constrained: bool) -> np.ndarray:
    """``Z^T H Z`` (``constrained``: tip held) or ``H`` (force prescribed), dense, in absolute angles."""
    _, _, H, J, _ = chain_solver(m).evaluate(np.asarray(q, float), np.asarray(force, float))
    H = H if isinstance(H, np.ndarray) else H.toarray()
    if not constrained:
        return H
    Q, _ = np.linalg.qr(J.T, mode="complete")
    Z = Q[:, 2:]
    return Z.T @ H @ Z


def classify(m: Manipulator, q: np.ndarray, force: np.ndarray, *, constrained: bool,
             rel_tol: float = 1e-9) -> Inertia:
    """Inertia of the reduced Hessian at an equilibrium ``(q, force)``.

    Eigenvalues (or pivots) with ``|lambda| <= rel_tol * max(k c^2, |lambda|_max)`` count as zero
    (``degenerate``): relative to the chain's torque scale ``m.torque_scale``, whatever its units.
    """
    return analyse(m, q, force, constrained=constrained, rel_tol=rel_tol)[0]


def analyse(m: Manipulator, q: np.ndarray, force: np.ndarray, *, constrained: bool,
            rel_tol: float = 1e-9) -> tuple[Inertia, float, np.ndarray]:
    """``(inertia, energy, tip)`` at ``(q, force)`` from one evaluation of the model."""
    n = m.n
    dim = n - 2 if constrained else n
    E, _, H, J, tip = chain_solver(m).evaluate(np.asarray(q, float), np.asarray(force, float))
    return inertia_of(H, J, constrained, rel_tol, dim, m.torque_scale), E, tip


def inertia_of(H, J, constrained: bool, rel_tol: float, dim: int, scale: float = 1.0) -> Inertia:
    """Inertia of ``H`` (reduced on the null space of ``J`` when ``constrained``); ``scale`` is the
    torque scale below which an eigenvalue's size is judged against it rather than against the largest."""
    if dim <= 0:
        return Inertia(np.zeros(0), 0, False, 0)
    if isinstance(H, np.ndarray):
        if constrained:
            Q, _ = np.linalg.qr(J.T, mode="complete")
            Z = Q[:, 2:]
            H = Z.T @ H @ Z
        return _inertia_of_eigenvalues(np.linalg.eigvalsh(H), rel_tol, dim, scale)
    return _sparse_inertia(H, J if constrained else None, rel_tol, dim, scale)


def _inertia_of_eigenvalues(w: np.ndarray, rel_tol: float, dim: int, scale: float = 1.0) -> Inertia:
    tol = rel_tol * max(scale, float(np.abs(w).max()))
    return Inertia(w, int(np.sum(w < -tol)), bool(np.any(np.abs(w) <= tol)), dim)


def inertia_of_reduced(R: np.ndarray, rel_tol: float = 1e-9, scale: float = 1.0) -> Inertia:
    """Inertia of a displacement-controlled equilibrium from its reduced Hessian ``Z^T H Z`` (m x m).

    As :func:`inertia_of`, for a reduced Hessian computed elsewhere (the compiled kernels);
    a 2 x 2 one (``n = 4``) by the closed form, its small eigenvalue as ``det / large`` (no
    cancellation). ``scale``: the chain's torque scale ``k c^2`` (see :func:`classify`).
    """
    dim = R.shape[0]
    if dim == 0:
        return Inertia(np.zeros(0), 0, False, 0)
    if dim == 1:
        return _inertia_of_eigenvalues(R[0].copy(), rel_tol, 1, scale)
    if dim == 2:
        (a, b), (_, d) = R.tolist()
        mean, rad = 0.5 * (a + d), math.hypot(0.5 * (a - d), b)
        big = mean + rad if mean >= 0 else mean - rad
        small = (a * d - b * b) / big if big != 0.0 else 0.0
        lo, hi = (small, big) if small <= big else (big, small)
        tol = rel_tol * max(scale, -lo, hi)
        return Inertia(np.array((lo, hi)), (lo < -tol) + (hi < -tol), -tol <= lo <= tol or -tol <= hi <= tol, 2)
    return _inertia_of_eigenvalues(np.linalg.eigvalsh(R), rel_tol, dim, scale)


def classify_batch(H: np.ndarray, J: np.ndarray, rel_tol: float = 1e-9, scale: float = 1.0
                   ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Classify many displacement-controlled equilibria at once (short chains).

    ``H`` (N, n, n) Lagrangian Hessians and ``J`` (N, 2, n) tip Jacobians, absolute angles.
    Returns ``(morse_index (N,), stable (N,), eigenvalues (N, n-2))``.
    """
    N, n = H.shape[0], H.shape[1]
    if n <= 2:
        return np.zeros(N, dtype=int), np.ones(N, dtype=bool), np.zeros((N, 0))
    Q, _ = np.linalg.qr(np.transpose(J, (0, 2, 1)), mode="complete")
    Z = Q[:, :, 2:]
    return classify_reduced(np.transpose(Z, (0, 2, 1)) @ H @ Z, rel_tol, scale)


def classify_reduced(R: np.ndarray, rel_tol: float = 1e-9, scale: float = 1.0
                     ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """:func:`classify_batch` from the reduced Hessians ``R`` (N, m, m) themselves."""
    N, m = R.shape[0], R.shape[1]
    if m == 0:
        return np.zeros(N, dtype=int), np.ones(N, dtype=bool), np.zeros((N, 0))
    w = np.linalg.eigvalsh(R)
    tol = rel_tol * np.maximum(scale, np.abs(w).max(axis=1))
    morse = np.sum(w < -tol[:, None], axis=1)
    stable = (morse == 0) & ~np.any(np.abs(w) <= tol[:, None], axis=1)
    return morse, stable, w


def _sparse_inertia(H, J, rel_tol: float, dim: int, scale: float = 1.0) -> Inertia:
    diag = H.diagonal().copy()
    off = H.diagonal(1).copy()
    tiny = rel_tol * max(scale, float(np.abs(diag).max()), float(np.abs(off).max(initial=0.0)))
    neg = 0
    degenerate = False
    d_prev = 1.0
    e2 = [0.0] + (off * off).tolist()
    for a, e in zip(diag.tolist(), e2):   # LDL^T pivots of a tridiagonal matrix (Sylvester), plain floats
        d = a - e / d_prev
        if -tiny <= d <= tiny:
            degenerate = True
            d = -tiny if d < 0 else tiny
        if d < 0:
            neg += 1
        d_prev = d
    if J is None:
        return Inertia(np.zeros(0), neg, degenerate, dim)
    ab = np.zeros((3, diag.size))
    ab[0, 1:] = off
    ab[1] = diag
    ab[2, :-1] = off
    try:
        X = sla.solve_banded((1, 1), ab, J.T)
    except (np.linalg.LinAlgError, ValueError):
        return Inertia(np.zeros(0), neg, True, dim)
    S = -(J @ X)
    w = np.linalg.eigvalsh((S + S.T) / 2)
    s_tol = rel_tol * max(scale, float(np.abs(w).max()))
    degenerate = degenerate or bool(np.any(np.abs(w) <= s_tol))
    morse = neg + int(np.sum(w < 0)) - 2
    return Inertia(np.zeros(0), max(morse, 0), degenerate, dim)
