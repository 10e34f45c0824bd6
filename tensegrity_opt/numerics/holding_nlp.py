"""The holding problem: the least stiffness or preload with which a chain holds itself up under its dead loads.

    min  w . s                                 over  s (n, the design), q (n), L (the factor)
    s.t. d(E + V)/dq (q; s) = 0                (an equilibrium with the tip free under the dead loads)
         Hess(E + V)(q; s) - mu I = L L^T,  diag(L) >= 0     (stable with the margin mu, torque / rad; the
                                               lower triangle's rows: the matrix is symmetric)
         |q_i| <= q_max_i                      (the sag allowed, inside the joint range)
         L(q) - L0 >= 0                        (every spring taut: the linear law holds as a real spring's)
         s_lo <= s <= s_hi

``E`` the springs' energy (the linear law), ``V = -sum_j G_j . u_j`` the dead loads' potential
(:mod:`tensegrity_opt.model.loads`). The design ``s`` is, per segment, either

* ``vary="k"``: a stiffness scale, both springs ``k_i = s_i k_i^0`` (the objective weights ``w_i = k_i1^0 + k_i2^0``:
  the total stiffness), or
* ``vary="L0"``: a change of both rest lengths ``L_i0 = L_i0^0 + s_i`` (``s_i > 0`` lengthens: less preload; the
  objective ``-sum (k_i1 + k_i2) s_i``, i.e. the least total preload tension ``sum k (L(0) - L0)`` of the straight
  chain).

Built once per ``(n, vary)`` and thread; every number enters through ``p``: ``a, b, k1, k2, L10, L20`` (the chain's,
n each), ``Gx, Gy`` (the links' dead loads, n each), ``mu``, ``w`` (the objective's weights, n).
"""

from __future__ import annotations

import casadi as ca
import numpy as np

from .design_nlp import _factor_floor, _nlpsol, _run, _tril, tril_size
from .expressions import segment_energy
from .layout import Layout
from .per_thread import per_thread

__all__ = ["HoldingNLP", "holding_nlp", "VARY"]

#: What the holding problem designs (module docstring).
VARY = ("k", "L0")


class HoldingNLP:
    """The holding problem of a chain of ``n`` segments designing ``vary`` (module docstring)."""

    def __init__(self, n: int, vary: str) -> None:
        self.n, self.vary = n, vary
        self.x = Layout(s=n, q=n, L=tril_size(n))
        self.g = Layout(grad=n, factor=tril_size(n), stretch1=n, stretch2=n)
        self.p = Layout(a=n, b=n, k1=n, k2=n, L10=n, L20=n, Gx=n, Gy=n, mu=1, w=n)
        s, q, lv = ca.SX.sym("s", n), ca.SX.sym("q", n), ca.SX.sym("L", tril_size(n))
        p = ca.SX.sym("p", self.p.size)
        a, b, k1, k2, L10, L20, Gx, Gy = (p[self.p[name]] for name in ("a", "b", "k1", "k2", "L10", "L20", "Gx",
                                                                           "Gy"))
        if vary == "k":
            k1, k2 = s * k1, s * k2
        else:
            L10, L20 = L10 + s, L20 + s
        psi = ca.cumsum(q)
        L1, L2, E = segment_energy(q, a, b, k1, k2, L10, L20)
        U = E - ca.dot(Gx, ca.cos(psi)) - ca.dot(Gy, ca.sin(psi))
        H, grad = ca.hessian(U, q)
        L, self.diag = _tril(lv, n)
        R = H - p[self.p["mu"]] * ca.SX.eye(n) - L @ L.T
        f = ca.dot(p[self.p["w"]], s)
        g = ca.vertcat(grad, *[R[i, j] for i in range(n) for j in range(i + 1)],     # R is symmetric
                       L1 - L10, L2 - L20)
        self.solver, self._cb = _nlpsol(f"holding_{n}_{vary}", {"x": ca.vertcat(s, q, lv), "p": p, "f": f, "g": g})
        self.hessian = ca.Function(f"holding_hessian_{n}_{vary}", [s, q, p], [H, grad])
        self.factor_floor = _factor_floor(n, self.diag)

    def solve(self, x0, p, lbx, ubx):
        """One IPOPT solve: the equilibrium and factor rows equalities, every spring taut (``L - L0 >= 0``)."""
        lbg = np.zeros(self.g.size)
        ubg = np.zeros(self.g.size)
        ubg[self.g.span("stretch1", "stretch2")] = np.inf
        return _run(self.solver, x0, lbx, ubx, lbg, ubg, p)


@per_thread
def holding_nlp(n: int, vary: str) -> HoldingNLP:
    """This thread's :class:`HoldingNLP` for ``n`` segments designing ``vary`` (built once)."""
    return HoldingNLP(n, vary)
