"""Cartesian (tangent) stiffness at an equilibrium: ``dF/d(tip)`` along the equilibrium family.

The KKT system ``r(phi, F; target) = [grad E - J^T F; tip - target] = 0`` defines
``(phi, F)`` as functions of the target; implicit differentiation gives
``dr/dz dz/dtarget = [0; I]``, and the last two rows of ``dz/dtarget`` are the
2 x 2 tangent stiffness. It includes the load (geometric) term ``-F . Hess tip``
through the KKT Jacobian, and is symmetric (it is the Hessian of the
equilibrium energy as a function of the tip position).
"""

from __future__ import annotations

import numpy as np

from ...errors import InvalidParameterError
from ...model.manipulator import Manipulator
from ...numerics import chain_solver
from ...numerics.slack_nlp import slack_nlp
from .equilibrium import Equilibrium

__all__ = ["cartesian_stiffness"]


def cartesian_stiffness(m: Manipulator, eq: Equilibrium) -> np.ndarray:
    """Tangent stiffness ``K_c = dF/d(x, y)`` at the equilibrium ``eq`` (force / length).

    Parameters
    ----------
    m : Manipulator
        The chain ``eq`` belongs to.
    eq : Equilibrium
        Any equilibrium (displacement- or force-controlled, stable or not).

    Returns
    -------
    ndarray (2, 2)
        ``K_c[i, j] = dF_i / d tip_j``; symmetric. Positive definite at a stable
        equilibrium whose energy is convex in the tip position. Under each segment's spring law (a slack spring
        adds no stiffness), the joints resting on a stop (``eq.at_stop``) held there.

    Raises
    ------
    InvalidParameterError
        (``ValueError``) when the KKT system is singular there (e.g. the fully
        extended chain, where the tip Jacobian loses rank), or ``eq`` has the wrong size.
    """
    q = np.asarray(eq.q, dtype=float)
    if q.shape != (m.n,):
        raise InvalidParameterError(f"eq has {q.size} joint angles, the manipulator {m.n}", field="eq")
    try:
        if m.paper_model and not eq.at_stop.any():
            K = chain_solver(m).tangent_stiffness(q, np.asarray(eq.force, float))
        else:
            K = _held_stiffness(m, q, np.asarray(eq.force, float), np.asarray(eq.at_stop, bool))
    except (np.linalg.LinAlgError, ValueError):
        K = None
    if K is None or not np.all(np.isfinite(K)):
        raise InvalidParameterError(
            "the tangent stiffness is undefined at this equilibrium: the KKT system is singular "
            "(fully extended chain or a bifurcation point)", field="eq")
    return K


def _held_stiffness(m: Manipulator, q: np.ndarray, force: np.ndarray, at_stop: np.ndarray) -> np.ndarray:
    """``dF/d(tip)`` of an equilibrium under each spring's law, the joints on a stop held there (a stop with a
    positive contact torque is rigid for a small change of the tip): the KKT system of the free joints,
    ``[[H_ff, -J_f^T], [J_f, 0]] [dq_f; dF] = [0; I]`` with ``H = Hess(E - F . tip)`` (a slack spring adds nothing; at
    a spring exactly at its rest length, its taut side)."""
    _, _, H, _, J = slack_nlp(m.n, m.loaded).derivatives(m, q, force)
    idx = np.flatnonzero(~at_stop)
    k = idx.size
    scale, length = m.torque_scale, float(m.b.sum())
    K = np.zeros((k + 2, k + 2))
    K[:k, :k] = H[np.ix_(idx, idx)] / scale
    K[:k, k:] = -J[:, idx].T / scale
    K[k:, :k] = J[:, idx] / length
    if np.linalg.cond(K) > 1e13:
        raise np.linalg.LinAlgError("singular KKT matrix")
    rhs = np.zeros((k + 2, 2))
    rhs[k:] = np.eye(2) / length
    return np.linalg.solve(K, rhs)[k:]
