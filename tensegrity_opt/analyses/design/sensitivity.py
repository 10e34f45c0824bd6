"""Sensitivities: how a critical load and an equilibrium move with the chain's parameters."""

from __future__ import annotations

import numpy as np

from ...errors import InvalidParameterError
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...model.springs import linear_only
from ...numerics import chain_solver
from ...numerics.layout import chain_parameters, equilibrium_unknowns
from ..equilibria.buckling import critical_force, straight_matrices
from ..equilibria.equilibrium import Equilibrium

__all__ = ["critical_load_sensitivity", "equilibrium_sensitivity"]

#: The chain's parameters by their names in the result, with their blocks in the solvers' parameters.
_PARAMETERS = {"a": "a", "b": "b", "k1": "k1", "k2": "k2", "L1_0": "L10", "L2_0": "L20"}


def critical_load_sensitivity(m: Manipulator, boundary: str = "guided", mode: int = 0) -> dict[str, np.ndarray]:
    """``d(load)/d(parameter)`` of a critical load, per segment, for ``a``, ``b``, ``k``, ``L0``.

    Symmetric segments; ``k`` and ``L0`` change both springs together. From the bordered
    eigenproblem ``A(P) w = 0``, ``A = [[K - P G, S0], [S0^T, 0]]`` (guided) or
    ``A = K - P G`` (free): ``dP/dp = w^T (dA/dp) w / (q^T G q)``.

    Returns
    -------
    dict
        ``{"a", "b", "k", "L0"}`` -> ndarray (n,), and ``"load"`` the load itself.

    Raises
    ------
    InvalidParameterError
        When the load is repeated (not differentiable there; use the design NLP instead).
    """
    unloaded_only(m, "critical_load_sensitivity")
    linear_only(m, "critical_load_sensitivity")
    bk = critical_force(m, boundary)
    if mode < 0 or mode >= bk.loads.size:
        raise InvalidParameterError(f"mode must be in 0..{bk.loads.size - 1}", field="mode")
    P = bk.loads[mode]
    gaps = np.abs(np.delete(bk.loads, mode) - P)
    if gaps.size and gaps.min() < 1e-6 * P:
        raise InvalidParameterError("the critical load is repeated: it has no derivative there", field="mode")
    K, G, S0 = straight_matrices(m)
    qv = bk.modes[mode].q
    guided = boundary == "guided"
    f = -float(S0 @ ((K - 0) * qv - P * (G @ qv))) / float(S0 @ S0) if guided else 0.0
    denom = float(qv @ G @ qv)
    n = m.n
    a, b, k, L0 = m.a, m.b, m.k1, m.L1_0
    T = np.tril(np.ones((n, n)))
    dK = {"a": 4 * k * a, "b": k * (L0 - 4 * b), "k": b * L0 - 2 * (b * b - a * a), "L0": k * b}
    out = {name: dK[name] * qv ** 2 / denom for name in ("a", "k", "L0")}
    db = np.zeros(n)
    Tq = T @ qv
    for i in range(n):
        dl = np.zeros(n)
        dl[i] = 1.0
        if i > 0:
            dl[i - 1] = 1.0
        dG_qq = float(dl @ Tq ** 2)                 # q^T T^T diag(dl) T q
        dS0_q = float(dl @ Tq)                      # (T^T dl)^T q
        db[i] = (dK["b"][i] * qv[i] ** 2 - P * dG_qq + (2 * f * dS0_q if guided else 0.0)) / denom
    out["b"] = db
    out["load"] = np.array(P)
    return out


def equilibrium_sensitivity(m: Manipulator, eq: Equilibrium) -> dict[str, np.ndarray]:
    """``d(q, F)/d(parameters)`` at a displacement-controlled equilibrium (tip held fixed).

    Implicit differentiation of the KKT system with respect to the per-segment parameters
    ``a, b, k1, k2, L1_0, L2_0``.

    Returns
    -------
    dict
        ``"dq"``: ndarray (n, 6n) and ``"dF"``: ndarray (2, 6n), columns ordered as
        ``names`` (``"a[0]", ..., "L2_0[n-1]"``); and per-parameter blocks
        ``"dq/<name>"`` (n, n) and ``"dF/<name>"`` (2, n).
    """
    unloaded_only(m, "equilibrium_sensitivity")
    linear_only(m, "equilibrium_sensitivity")
    n = m.n
    Jz, Jp = chain_solver(m).kkt_parameter_jacobian(np.asarray(eq.q, float), np.asarray(eq.force, float),
                                                    np.asarray(eq.tip, float))
    try:
        dz = -np.linalg.solve(Jz, Jp)
    except np.linalg.LinAlgError:
        raise InvalidParameterError("the KKT system is singular at this equilibrium", field="eq") from None
    rows, cols = equilibrium_unknowns(n), chain_parameters(n)
    D = np.eye(n) - np.eye(n, k=-1)
    dq = D @ dz[rows["phi"]]
    dF = dz[rows["F"]]
    names = [f"{p}[{i}]" for p in _PARAMETERS for i in range(n)]
    out: dict[str, np.ndarray] = {"dq": dq, "dF": dF, "names": np.array(names)}
    for p, block in _PARAMETERS.items():
        out[f"dq/{p}"] = dq[:, cols[block]]
        out[f"dF/{p}"] = dF[:, cols[block]]
    return out
