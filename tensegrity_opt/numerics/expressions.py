"""The chain's model as CasADi expressions: the one symbolic definition every solver builds on.

One segment's energy (:func:`segment_energy`) and the tip (:func:`chain_expressions`) are written
here once. Two graphs are built from them:

* :func:`kkt_graph` — one SX graph in absolute angles (short chains: IPOPT, the dense Newton method,
  parameter sensitivities; and the compiled kernels of :mod:`.kernels`);
* :func:`banded_functions` — MX graphs of whole-vector operations for long chains, whose size does
  not grow with ``n``: the energy is separable in the relative angles, so its gradient and
  (tridiagonal) Hessian in absolute angles are assembled from the per-segment derivatives of
  :func:`segment_energy` instead of asking CasADi for an ``n x n`` Hessian.

The solvers (:mod:`.chain_solver`, :mod:`.kernels`, :mod:`.design_nlp`) only assemble these.
"""

from __future__ import annotations

import casadi as ca

__all__ = ["segment_energy", "tip_expression", "chain_expressions", "kkt_graph", "banded_functions"]


def _q_of_phi(phi):
    # one joint: phi[:-1] is 1 x 0 and the vertcat a 2 x 1 that would broadcast phi into two segments
    return phi if phi.shape[0] == 1 else phi - ca.vertcat(0, phi[:-1])


def segment_energy(q, a, b, k1, k2, L10, L20, *, beta=None, c=None, tension=None):
    """Spring lengths and elastic energy of the segments at relative angles ``q`` (SX or MX columns).

    Returns ``(L1, L2, E)`` (``docs/model.md``): ``L1,2 = 2 c cos(beta +- q/2)`` per segment and
    ``E = 1/2 sum(k1 (L1 - L10)^2 + k2 (L2 - L20)^2)``. ``beta = atan2(a, b)`` and
    ``c = sqrt(a^2 + b^2)`` may be given (symbols computed once elsewhere) instead of being part
    of every evaluation. ``tension`` (a sequence of bools, one per segment): the segments whose springs follow the
    tension-only law, each stretch clipped at 0 (``fmax(L - L0, 0)``: C^1, its second derivative the taut side's
    where ``L > L0`` and 0 elsewhere).
    """
    c = ca.sqrt(a * a + b * b) if c is None else c
    beta = ca.atan2(a, b) if beta is None else beta
    L1 = 2 * c * ca.cos(beta + q / 2)
    L2 = 2 * c * ca.cos(beta - q / 2)
    r1, r2 = L1 - L10, L2 - L20
    if tension is not None and any(tension):
        w = ca.DM([1.0 if t else 0.0 for t in tension])
        r1 = w * ca.fmax(r1, 0) + (1 - w) * r1
        r2 = w * ca.fmax(r2, 0) + (1 - w) * r2
    E = 0.5 * ca.sum1(k1 * r1 ** 2 + k2 * r2 ** 2)
    return L1, L2, E


def tip_expression(phi, b):
    """Tip position at absolute link angles ``phi`` (eq. 5 with per-segment ``b``): the base half-link
    ``b_1`` along +x, then links ``b_j + b_{j+1}`` and the last ``b_n``."""
    links = b + ca.vertcat(b[1:], 0) if phi.shape[0] > 1 else b
    return ca.vertcat(b[0] + ca.dot(links, ca.cos(phi)), ca.dot(links, ca.sin(phi)))


def chain_expressions(phi, a, b, k1, k2, L10, L20, *, beta=None, c=None):
    """The chain's model in absolute angles as CasADi expressions (SX or MX).

    Returns ``(q, L1, L2, E, tip)``: relative angles, spring lengths, elastic energy and tip
    position (``docs/model.md``); every argument is a column of length ``n``. ``beta`` and ``c``
    as in :func:`segment_energy`.
    """
    q = _q_of_phi(phi)
    L1, L2, E = segment_energy(q, a, b, k1, k2, L10, L20, beta=beta, c=c)
    return q, L1, L2, E, tip_expression(phi, b)


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


def banded_functions(n: int) -> dict[str, ca.Function]:
    """The long-chain functions (MX, whole-vector operations: a few dozen nodes whatever ``n``).

    With ``e1 = dE_i/dq_i`` and ``e2 = d2E_i/dq_i2`` (the energy is separable in ``q = D phi``), the
    gradient in absolute angles is ``D^T e1`` and the Lagrangian Hessian ``Hess(E - F.tip)`` is
    tridiagonal: diagonal ``hd = e2_i + e2_{i+1} + F.(links_i (cos, sin) phi_i)``, off-diagonal
    ``ho = -e2_{i+1}``. Returns, by name (inputs ``z = (phi, F)`` or ``phi, p, F``; ``p`` the 6n
    parameters, ``t`` the target):

    ``kkt_banded (z, p, t) -> (r, hd, ho, J)``, ``kkt_res_banded (z, p, t) -> r`` (KKT residual
    ``r = (grad E - J^T F, tip - t)``), ``force_banded (phi, p, F) -> (r1, hd, ho)``,
    ``force_res_banded (phi, p, F) -> r1`` (``r1 = grad E - J^T F``) and
    ``derivs_banded (phi, p, F) -> (E, grad E, hd, ho, J, tip)``.
    """
    phi, p, F, tgt = ca.MX.sym("phi", n), ca.MX.sym("p", 6 * n), ca.MX.sym("F", 2), ca.MX.sym("t", 2)
    a, b, k1, k2, L10, L20 = (p[i * n:(i + 1) * n] for i in range(6))
    qs = ca.MX.sym("q", n)
    _, _, Es = segment_energy(qs, a, b, k1, k2, L10, L20)
    e1 = ca.gradient(Es, qs)                       # dE_i/dq_i (E is separable in q)
    e2 = ca.jtimes(e1, qs, ca.DM.ones(n))          # d2E_i/dq_i2: the diagonal Hessian times 1
    seg = ca.Function("segments", [qs, p], [Es, e1, e2])
    E, d1, d2 = seg(phi - ca.vertcat(0, phi[:-1]), p)
    zero = ca.MX.zeros(1)
    g = d1 - ca.vertcat(d1[1:], zero)             # D^T e1
    links = b + ca.vertcat(b[1:], zero)
    sn, cs = ca.sin(phi), ca.cos(phi)
    Jx, Jy = -links * sn, links * cs
    tip = ca.vertcat(b[0] + ca.dot(links, cs), ca.dot(links, sn))
    hd = d2 + ca.vertcat(d2[1:], zero) + F[0] * links * cs + F[1] * links * sn
    ho = -d2[1:]
    J = ca.horzcat(Jx, Jy).T
    r1 = g - (F[0] * Jx + F[1] * Jy)
    z = ca.vertcat(phi, F)
    zphi, zF = z[:n], z[n:]
    kkt = ca.Function("kkt_banded_", [phi, F, p, tgt], [ca.vertcat(r1, tip - tgt), hd, ho, J])
    r, hdz, hoz, Jz = kkt(zphi, zF, p, tgt)
    return {"kkt_banded": ca.Function("kkt_banded", [z, p, tgt], [r, hdz, hoz, Jz]),
            "kkt_res_banded": ca.Function("kkt_res_banded", [z, p, tgt], [r]),
            "force_res_banded": ca.Function("force_res_banded", [phi, p, F], [r1]),
            "force_banded": ca.Function("force_banded", [phi, p, F], [r1, hd, ho]),
            "derivs_banded": ca.Function("derivs_banded", [phi, p, F], [E, g, hd, ho, J, tip])}
