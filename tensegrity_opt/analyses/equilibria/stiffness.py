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
from ...model.springs import linear_only
from ...numerics import chain_solver
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
        equilibrium whose energy is convex in the tip position.

    Raises
    ------
    InvalidParameterError
        (``ValueError``) when the KKT system is singular there (e.g. the fully
        extended chain, where the tip Jacobian loses rank), or ``eq`` has the wrong size.
    """
    linear_only(m, "cartesian_stiffness")
    q = np.asarray(eq.q, dtype=float)
    if q.shape != (m.n,):
        raise InvalidParameterError(f"eq has {q.size} joint angles, the manipulator {m.n}", field="eq")
    try:
        K = chain_solver(m).tangent_stiffness(q, np.asarray(eq.force, float))
    except (np.linalg.LinAlgError, ValueError):
        K = None
    if K is None or not np.all(np.isfinite(K)):
        raise InvalidParameterError(
            "the tangent stiffness is undefined at this equilibrium: the KKT system is singular "
            "(fully extended chain or a bifurcation point)", field="eq")
    return K
