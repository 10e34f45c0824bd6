"""The drawing geometry of a chain: its joints, triangles and springs at given joint angles (numpy only)."""

from __future__ import annotations

from typing import Any

import numpy as np

from ...errors import InvalidParameterError
from ...model.manipulator import Manipulator

__all__ = ["chain_geometry"]


def chain_geometry(m: Manipulator, q: Any) -> dict[str, np.ndarray]:
    """Drawing geometry of the chain at the joint angles ``q`` (docs/model.md).

    The base half-link of length ``b_1`` runs from the origin along +x to joint 1; the link
    after joint ``j`` has the absolute angle ``phi_j = q_1 + ... + q_j`` and length
    ``b_j + b_{j+1}`` (the last one ``b_n``). Segment ``i`` has its joint at ``joints[i]``, a
    proximal triangle on the link before the joint and a distal one on the link after it: apex
    at the joint, base perpendicular to the link at distance ``b_i`` from the joint, base
    corners ``a_i`` either side. Spring 1 joins the two corners on the left (+ normal) side,
    spring 2 those on the right side, so that ``|spring 1| = 2c cos(beta + q/2)`` and
    ``|spring 2| = 2c cos(beta - q/2)`` (:meth:`Manipulator.spring_lengths`).

    Returns
    -------
    dict of ndarray
        ``"base"`` (2,) the origin; ``"joints"`` (n, 2); ``"tip"`` (2,) = :meth:`Manipulator.tip`;
        ``"centerline"`` (n + 2, 2): origin, joints, tip; ``"link_angles"`` (n + 1,): ``phi_0 = 0``
        (base link) then ``phi_1..phi_n``; ``"triangles"`` (n, 2, 3, 2): segment, proximal/distal,
        vertices (joint, left corner, right corner); ``"springs"`` (n, 2, 2, 2): segment, spring
        1/2, endpoints (proximal corner, distal corner).
    """
    q = np.asarray(q, dtype=float)
    if q.shape != (m.n,):
        raise InvalidParameterError(f"q must have {m.n} joint angles, got shape {q.shape}", field="q")
    a, b = m.a, m.b
    phi = np.concatenate([[0.0], np.cumsum(q)])
    u = np.column_stack([np.cos(phi), np.sin(phi)])            # link directions (n + 1, 2)
    nrm = np.column_stack([-np.sin(phi), np.cos(phi)])         # left normals
    links = m.link_lengths
    joints = np.empty((m.n, 2))
    joints[0] = (m.base_length, 0.0)
    for j in range(1, m.n):
        joints[j] = joints[j - 1] + links[j - 1] * u[j]
    tip = joints[-1] + links[-1] * u[m.n]
    A, B = a[:, None], b[:, None]
    prox_l = joints - B * u[:-1] + A * nrm[:-1]
    prox_r = joints - B * u[:-1] - A * nrm[:-1]
    dist_l = joints + B * u[1:] + A * nrm[1:]
    dist_r = joints + B * u[1:] - A * nrm[1:]
    triangles = np.stack([np.stack([joints, prox_l, prox_r], axis=1),
                          np.stack([joints, dist_l, dist_r], axis=1)], axis=1)
    springs = np.stack([np.stack([prox_l, dist_l], axis=1), np.stack([prox_r, dist_r], axis=1)], axis=1)
    centerline = np.vstack([[0.0, 0.0], joints, tip])
    return {"base": np.zeros(2), "joints": joints, "tip": tip, "centerline": centerline, "link_angles": phi,
            "triangles": triangles, "springs": springs}

