"""The chain's masses: where they sit and its mass matrix (``docs/model.md``, "Masses and modes").

Segment ``i`` has two equal triangles of mass ``m_i / 2``; their centroids lie on the chain's axis ``2 b_i / 3``
from joint ``i``, the lower one on the link before the joint, the upper one on the link after it (the lower
triangle of segment 1 is fixed to the base and does no work). Each triangle may have a rotational inertia
``I_i`` about its centroid (``Segment.inertia``). A payload is a point mass at the tip (``Manipulator.payload``).

In the absolute link angles ``psi_j = q_1 + ... + q_j`` a mass point on link ``L`` at ``z = p_i + d e^{i psi_L}``
(``p_i`` joint ``i``) moves with ``dz / dpsi_j = i c_j e^{i psi_j}``, ``c_j`` a constant lever length (``l_j`` for
the links before joint ``i``, plus ``d`` on link ``L``). So the kinetic energy ``1/2 psi'^T M_psi psi'`` has
``M_psi[j, k] = W[j, k] cos(psi_j - psi_k) + diag(I)``, ``W = sum_points m c c^T`` constant, and in the joint
angles ``M = A^T M_psi A`` (``A`` the lower-triangular ones: ``psi = A q``).

The functions take a :class:`~.manipulator.Manipulator` (typed ``Any``: ``manipulator`` imports this module, and no
import goes back).
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["mass_points", "mass_matrix", "total_mass"]


def mass_points(m: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The moving mass points: ``(mass, joint, link, offset)`` per point: the point sits at joint ``joint``'s
    position plus ``offset`` along link ``link`` (0-based links; ``link = -1`` is the fixed base). The triangles'
    centroids of every segment, then the payload at the tip."""
    mass, joint, link, offset = [], [], [], []
    for i, s in enumerate(m.segments):
        if i > 0:                                   # the lower triangle of segment 1 is part of the base
            mass.append(0.5 * s.mass), joint.append(i), link.append(i - 1), offset.append(-2.0 * s.b / 3.0)
        mass.append(0.5 * s.mass), joint.append(i), link.append(i), offset.append(2.0 * s.b / 3.0)
    mass.append(m.payload), joint.append(m.n - 1), link.append(m.n - 1), offset.append(float(m.b[-1]))
    return np.array(mass), np.array(joint), np.array(link), np.array(offset)


def _levers(m: Any) -> tuple[np.ndarray, np.ndarray]:
    """``(W, I)``: the constant matrix ``W = sum m c c^T`` (n, n) and the links' rotational inertias (n,)."""
    mass, joint, link, offset = mass_points(m)
    n = m.n
    l = m.link_lengths
    C = np.where(np.arange(n)[None, :] < joint[:, None], l[None, :], 0.0)     # the links before the point's joint
    C[np.arange(C.shape[0]), link] += offset
    W = (C * mass[:, None]).T @ C
    inertia = np.zeros(n)
    for i, s in enumerate(m.segments):
        inertia[i] += s.inertia                     # the upper triangle turns with link i
        if i > 0:
            inertia[i - 1] += s.inertia             # the lower one with link i - 1
    return W, inertia


def mass_matrix(m: Any, q) -> np.ndarray:
    """The mass matrix ``M(q)`` (n, n) in the joint angles: kinetic energy ``1/2 q'^T M q'``."""
    q = np.asarray(q, dtype=float)
    W, inertia = _levers(m)
    psi = np.cumsum(q)
    Mpsi = W * np.cos(psi[:, None] - psi[None, :]) + np.diag(inertia)
    # A^T X A with (A x)_j = sum_{l <= j} x_l: reverse cumulative sums over both axes
    return np.cumsum(np.cumsum(Mpsi[::-1, ::-1], axis=0), axis=1)[::-1, ::-1]


def total_mass(m: Any) -> float:
    """The segments' masses and the payload."""
    return float(sum(s.mass for s in m.segments) + m.payload)
