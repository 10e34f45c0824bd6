"""IPOPT for the equilibrium problems: the options, the two NLPs and their calls.

``min E`` s.t. ``tip = target`` and the joint ranges (displacement control), and ``min E - F.tip``
s.t. the joint ranges (force control), built from :func:`.expressions.kkt_graph`'s symbols.
"""

from __future__ import annotations

import casadi as ca
import numpy as np

from ..timelimit import check_time
from .results import LocalResult

__all__ = ["IPOPT_OPTIONS", "RANGE_SHRINK", "displacement_nlp", "force_nlp", "minimize_displacement",
           "minimize_force"]

#: Options for every IPOPT instance: exact Hessian, MUMPS, silent, bounded.
IPOPT_OPTIONS: dict[str, object] = {
    "print_time": False,
    "ipopt.print_level": 0,
    "ipopt.sb": "yes",
    "ipopt.hessian_approximation": "exact",
    "ipopt.linear_solver": "mumps",
    "ipopt.max_iter": 300,
    "ipopt.max_wall_time": 20.0,
    "ipopt.tol": 1e-10,
    "ipopt.constr_viol_tol": 1e-10,
    "ipopt.mu_strategy": "adaptive",
}

# Joint-range constraints are imposed slightly inside the open physical range;
# a solution whose joint sits on this bound is not an equilibrium of the
# mechanism (it would need a stop to hold it) and is rejected by the callers.
RANGE_SHRINK = 1e-6


def displacement_nlp(sym) -> ca.Function:
    """IPOPT: min E s.t. [tip; q] within bounds (``sym``: :func:`.expressions.kkt_graph`'s tuple)."""
    phi, p, F, q, E, tip, *_ = sym
    return ca.nlpsol("eq_disp", "ipopt", {"x": phi, "p": p, "f": E, "g": ca.vertcat(tip, q)}, IPOPT_OPTIONS)


def force_nlp(sym) -> ca.Function:
    """IPOPT: min E - F.tip s.t. q within bounds."""
    phi, p, F, q, E, tip, *_ = sym
    return ca.nlpsol("eq_force", "ipopt", {"x": phi, "p": ca.vertcat(p, F), "f": E - ca.dot(F, tip), "g": q},
                     IPOPT_OPTIONS)


def _on_bound(q: np.ndarray, limits: np.ndarray) -> bool:
    return bool(np.any(np.abs(q) >= limits * (1.0 - 2.0 * RANGE_SHRINK)))


def minimize_displacement(nlp: ca.Function, params: np.ndarray, limits: np.ndarray, target: np.ndarray,
                          q0: np.ndarray) -> LocalResult:
    """IPOPT (``nlp`` from :func:`displacement_nlp`): ``min E(q)`` s.t. ``tip(q) = target``, ``|q| < limits``."""
    check_time("the equilibrium search")
    lim = limits * (1.0 - RANGE_SHRINK)
    q0 = np.clip(q0, -lim * 0.999, lim * 0.999)
    sol = nlp(x0=np.cumsum(q0), p=params, lbg=np.concatenate([target, -lim]), ubg=np.concatenate([target, lim]))
    st = nlp.stats()
    phi = np.asarray(sol["x"]).ravel()
    q = np.diff(np.concatenate([[0.0], phi]))
    F = -np.asarray(sol["lam_g"]).ravel()[:2]   # CasADi's lam_g is -F for this form
    return LocalResult(q, F, bool(st["success"]), str(st["return_status"]),
                       int(st.get("iter_count", -1)), _on_bound(q, limits))


def minimize_force(nlp: ca.Function, params: np.ndarray, limits: np.ndarray, force: np.ndarray,
                   q0: np.ndarray) -> LocalResult:
    """IPOPT (``nlp`` from :func:`force_nlp`): ``min E(q) - F.tip(q)`` s.t. ``|q| < limits``."""
    check_time("the equilibrium search")
    lim = limits * (1.0 - RANGE_SHRINK)
    q0 = np.clip(q0, -lim * 0.999, lim * 0.999)
    sol = nlp(x0=np.cumsum(q0), p=np.concatenate([params, force]), lbg=-lim, ubg=lim)
    st = nlp.stats()
    q = np.diff(np.concatenate([[0.0], np.asarray(sol["x"]).ravel()]))
    return LocalResult(q, np.asarray(force, dtype=float).copy(), bool(st["success"]),
                       str(st["return_status"]), int(st.get("iter_count", -1)), _on_bound(q, limits))
