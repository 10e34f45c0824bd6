"""The chain's model as CasADi expressions: the one symbolic definition every solver builds on.

Kept apart from :mod:`.solvers` (IPOPT, Newton) and :mod:`.kernels` (compiled Newton), which both
build their graphs from it.
"""

from __future__ import annotations

import casadi as ca

__all__ = ["chain_expressions", "kkt_graph"]


def _q_of_phi(phi):
    return phi - ca.vertcat(0, phi[:-1])


def chain_expressions(phi, a, b, k1, k2, L10, L20, *, beta=None, c=None):
    """The chain's model in absolute angles as CasADi expressions (SX or MX).

    Returns ``(q, L1, L2, E, tip)``: relative angles, spring lengths, elastic energy and tip
    position (conventions.md); every argument is a column of length ``n``. ``beta = atan2(a, b)``
    and ``c = sqrt(a^2 + b^2)`` may be given (symbols computed once elsewhere) instead of being part
    of every evaluation.
    """
    q = _q_of_phi(phi)
    c = ca.sqrt(a * a + b * b) if c is None else c
    beta = ca.atan2(a, b) if beta is None else beta
    L1 = 2 * c * ca.cos(beta + q / 2)
    L2 = 2 * c * ca.cos(beta - q / 2)
    E = 0.5 * ca.sum1(k1 * (L1 - L10) ** 2 + k2 * (L2 - L20) ** 2)
    links = b + ca.vertcat(b[1:], 0) if phi.shape[0] > 1 else b
    tip = ca.vertcat(b[0] + ca.dot(links, ca.cos(phi)), ca.dot(links, ca.sin(phi)))
    return q, L1, L2, E, tip


def kkt_graph(n: int, *, extended: bool = False):
    """The displacement problem's SX graph in absolute angles:
    ``(phi, p, F, q, E, tip, KKT residual, z, target, grad E, J, H)``.

    ``p`` holds ``a, b, k1, k2, L10, L20`` per segment (6n), followed with ``extended`` by each
    segment's ``beta`` and ``c`` (8n: computed once by the caller, not in every evaluation). The KKT
    system of ``min E`` s.t. ``tip = target`` is ``grad E - J^T F = 0, tip - target = 0``; its Jacobian
    ``[[H, -J^T], [J, 0]]`` is assembled from blocks by the users of this graph: asking CasADi for
    ``jacobian(res, z)`` colours a matrix with a dense row and column, O(n^2).
    """
    phi, F, tgt = ca.SX.sym("phi", n), ca.SX.sym("F", 2), ca.SX.sym("target", 2)
    p = ca.SX.sym("p", (8 if extended else 6) * n)
    part = [p[i * n:(i + 1) * n] for i in range(8 if extended else 6)]
    q, _, _, E, tip = chain_expressions(phi, *part[:6], beta=part[6] if extended else None,
                                        c=part[7] if extended else None)
    J = ca.jacobian(tip, phi)
    gradE = ca.gradient(E, phi)
    H = ca.hessian(E - ca.dot(F, tip), phi)[0]
    res = ca.vertcat(gradE - J.T @ F, tip - tgt)
    return phi, p, F, q, E, tip, res, ca.vertcat(phi, F), tgt, gradE, J, H
