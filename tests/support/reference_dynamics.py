"""Independent reference of a chain's vibration modes (issue "weights and loads anywhere", item 4).

Imports numpy, scipy and the sibling reference :mod:`reference_tension_only` (its vertices, torques and tip) --
never ``tensegrity_opt``. The model, rebuilt from the triangles' vertices:

* segment ``i`` is two triangles, each with its apex at joint ``i``: the lower one's far vertices ``(-b, +-a)`` in
  the frame of the link before the joint, the upper one's ``R(q_i) (b, +-a)``; each has mass ``m_i / 2`` at its
  centroid (the mean of its three vertices) and the rotational inertia ``I_i`` about it; the lower triangle of
  segment 1 belongs to the fixed base; a payload is a point mass at the tip;
* the kinetic energy ``1/2 q'^T M q'``: ``M = sum m J_c^T J_c + sum I J_t^T J_t`` with the Jacobians of every
  centroid's position and every triangle's orientation (the angle of its apex-to-far-edge vector) taken by
  five-point central differences of those positions and angles (error ~h^4);
* the stiffness: ``K`` the Jacobian of ``-torques(q) - J(q)^T F`` (the reference's torques from the spring force
  vectors, its analytic tip Jacobian), five-point differences; ``F`` the tip force that balances the torques
  (least squares over the free joints);
* the motions: tangent to the tip (held) and to each stop a joint rests on; ``scipy.linalg.eigh(K_r, M_r)``.
"""

from __future__ import annotations

import numpy as np
import reference_tension_only as ref
import scipy.linalg as sla

H = 1e-3
_STENCIL = ((-2, 1.0 / 12.0), (-1, -8.0 / 12.0), (1, 8.0 / 12.0), (2, -1.0 / 12.0))


def _bodies(segs, payload, q):
    """Every moving body's (mass, inertia, position (2,), orientation) at ``q``."""
    P = ref._params(segs)
    q = np.asarray(q, float)
    v, w = ref._vertices(P, q)                                   # relative to each joint, in the lower link's frame
    phi = np.concatenate([[0.0], np.cumsum(q)])                  # phi[i]: the link before joint i (0: the base)
    joint = np.zeros((P.n, 2))
    joint[0] = (P.b[0], 0.0)
    for i in range(1, P.n):
        joint[i] = joint[i - 1] + P.links[i - 1] * np.array([np.cos(phi[i]), np.sin(phi[i])])
    out = []
    for i, s in enumerate(segs):
        c, sn = np.cos(phi[i]), np.sin(phi[i])
        Rl = np.array([[c, -sn], [sn, c]])                       # the frame of the link before joint i
        for far, lower in ((w[i], True), (v[i], False)):
            if lower and i == 0:
                continue
            verts = np.vstack([np.zeros(2), far])                # apex at the joint, the two far vertices
            centroid = joint[i] + Rl @ verts.mean(axis=0)
            axis = Rl @ (0.5 * (far[0] + far[1]))                 # apex to the far edge's midpoint
            angle = np.arctan2(axis[1], axis[0]) + (np.pi if lower else 0.0)
            out.append((0.5 * s.get("mass", 0.0), s.get("inertia", 0.0), centroid, angle))
    out.append((payload, 0.0, ref._tip(P, q), 0.0))
    return out


def _diff(f, q):
    """Five-point central differences of ``f`` (array-valued) at ``q``: ``(..., n)``."""
    q = np.asarray(q, float)
    cols = []
    for j in range(q.size):
        acc = 0.0
        for k, c in _STENCIL:
            e = np.zeros(q.size)
            e[j] = k * H
            acc = acc + c * np.asarray(f(q + e), float)
        cols.append(acc / H)
    return np.stack(cols, axis=-1)


def mass_matrix(segs, payload, q) -> np.ndarray:
    """``M(q)`` (n, n) from the bodies' centroids and orientations (module docstring)."""
    bodies = _bodies(segs, payload, q)
    pos = _diff(lambda x: np.array([b[2] for b in _bodies(segs, payload, x)]), q)          # (bodies, 2, n)
    ang = _diff(lambda x: np.unwrap(np.array([b[3] for b in _bodies(segs, payload, x)])), q)  # (bodies, n)
    M = np.zeros((len(q), len(q)))
    for (mass, inertia, _, _), Jp, Jt in zip(bodies, pos, ang):
        M += mass * Jp.T @ Jp + inertia * np.outer(Jt, Jt)
    return M


def tip_force(segs, q, stops) -> np.ndarray:
    """The tip force balancing the torques on the free joints: ``-torques = J^T F`` (least squares)."""
    free = ~np.asarray(stops, bool)
    J = ref.tip_jacobian(segs, q)
    return np.linalg.lstsq(J[:, free].T, -ref.torques(segs, q)[free], rcond=None)[0]


def stiffness_matrix(segs, q, F) -> np.ndarray:
    """``K`` (n, n): the Jacobian of ``-torques(q) - J(q)^T F`` (symmetrised)."""
    K = _diff(lambda x: -ref.torques(segs, x) - ref.tip_jacobian(segs, x).T @ F, q)
    return 0.5 * (K + K.T)


def frequencies(segs, payload, q, *, held: bool, stops=None):
    """``(w^2 ascending, Z, M, K)`` of the equilibrium ``q`` with the tip ``held`` or loaded, ``stops`` the joints
    resting on their stop."""
    q = np.asarray(q, float)
    stops = np.zeros(q.size, bool) if stops is None else np.asarray(stops, bool)
    F = tip_force(segs, q, stops)
    K = stiffness_matrix(segs, q, F)
    M = mass_matrix(segs, payload, q)
    rows = [np.eye(q.size)[stops]]
    if held:
        rows.append(ref.tip_jacobian(segs, q))
    C = np.vstack(rows)
    Z = sla.null_space(C) if C.shape[0] else np.eye(q.size)
    w = sla.eigh(Z.T @ K @ Z, Z.T @ M @ Z, eigvals_only=True)
    return w, Z, M, K
