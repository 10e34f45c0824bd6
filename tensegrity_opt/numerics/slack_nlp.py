"""The least-energy problem of a chain whose springs may go slack, with its joint stops: a smooth NLP.

A tension-only spring's energy ``k/2 max(0, L - L0)^2`` is only C^1 (its stiffness jumps where it goes slack).
Written with one extra variable per spring, the problem is smooth:

    min  1/2 sum k e^2 - sum_j G_j . u_j(q) - F . tip(q)   over  q (n), e (2n)
    s.t. tip(q) = target,   e - (L(q) - L0) >= 0,  e >= 0   (tension-only spring)
                            e - (L(q) - L0)  = 0,  e free   (linear spring)
         -(pi - 2 beta) <= q <= pi - 2 beta                 (the joint stops: the closed range)

``G_j`` the chain's dead loads on link ``j`` (its weights under gravity and its joint forces,
:mod:`tensegrity_opt.model.loads`; ``u_j = (cos psi_j, sin psi_j)``). Under a tip displacement ``F = 0`` and the
tip rows hold; under a dead tip load ``F`` (force control) the tip rows'
bounds are infinite (:meth:`SlackNLP.bounds` with ``free_tip``). At a solution ``e = max(0, L - L0)``
(tension-only) or ``L - L0`` (linear), so the objective is the chain's potential (less ``F . tip``) under each
spring's law; the multiplier of a spring's row is its force ``k e``, the multipliers of the tip rows are
``-F`` (CasADi's sign, ``docs/model.md``), and a joint's bound multiplier is the stop's contact torque. The law
of each spring enters only through the bounds, so one problem per chain length serves every chain (built once per
``n`` and thread, :mod:`.per_thread`).

:class:`SlackNLP` also evaluates the energy under the laws (``fmax``) with its gradient, Hessian, tip and tip
Jacobian in the relative angles (:meth:`SlackNLP.derivatives`): the stability of a solution (its Morse index on
the manifold left free by the tip and the stops).
"""

from __future__ import annotations

import casadi as ca
import numpy as np

from .design_nlp import NLPResult, _nlpsol, _run
from .expressions import segment_energy, tip_expression
from .layout import Layout
from .per_thread import per_thread

__all__ = ["SlackNLP", "slack_nlp"]

#: IPOPT options of the slack problem (on top of the design problems' own).
_OPTIONS = {"ipopt.max_iter": 300, "ipopt.tol": 1e-12, "ipopt.constr_viol_tol": 1e-11,
            "ipopt.acceptable_tol": 1e-9, "ipopt.bound_relax_factor": 0.0, "ipopt.max_wall_time": 5.0}


class SlackNLP:
    """The slack problem of a chain of ``n`` segments (module docstring).

    ``x``: variables ``q`` (n), ``e1``, ``e2`` (n each: springs 1 and 2 of each segment); ``g``: rows ``tip`` (2),
    ``s1``, ``s2`` (``e - (L - L0)``, n each); ``p``: ``a, b, k1, k2, L10, L20`` (n each, the chain's parameters)
    then ``target`` (2), the dead tip load ``force`` (2) and the links' dead loads ``Gx``, ``Gy`` (n each).
    """

    def __init__(self, n: int, loaded: bool = False) -> None:
        self.n = n
        self.loaded = loaded
        self.x = Layout(q=n, e1=n, e2=n)
        self.g = Layout(tip=2, s1=n, s2=n)
        self.p = Layout(a=n, b=n, k1=n, k2=n, L10=n, L20=n, target=2, force=2, Gx=n, Gy=n)
        q, e1, e2 = (ca.SX.sym(s, n) for s in ("q", "e1", "e2"))
        p = ca.SX.sym("p", self.p.size)
        a, b, k1, k2, L10, L20 = (p[i * n:(i + 1) * n] for i in range(6))
        tgt = p[self.p["target"]]
        load = p[self.p["force"]]
        psi = ca.cumsum(q)
        # the dead loads' terms only in the loaded variant: the unloaded chain's expressions (and their rounding)
        # stay those of the problem without loads
        V = -ca.dot(p[self.p["Gx"]], ca.cos(psi)) - ca.dot(p[self.p["Gy"]], ca.sin(psi)) if loaded else 0.0
        L1, L2, _ = segment_energy(q, a, b, k1, k2, L10, L20)
        tip = tip_expression(psi, b)
        f = 0.5 * ca.sum1(k1 * e1 ** 2 + k2 * e2 ** 2)
        f = (f + V if loaded else f) - ca.dot(load, tip)
        g = ca.vertcat(tip - tgt, e1 - (L1 - L10), e2 - (L2 - L20))
        name = f"slack_{n}" + ("_loaded" if loaded else "")
        self.solver, self._cb = _nlpsol(name, {"x": ca.vertcat(q, e1, e2), "p": p, "f": f, "g": g}, **_OPTIONS)
        # the energy under the laws (t = 1: tension-only) and its derivatives in q, for the classification
        t1, t2 = ca.SX.sym("t1", n), ca.SX.sym("t2", n)
        F = ca.SX.sym("F", 2)
        s1, s2 = L1 - L10, L2 - L20
        E = 0.5 * ca.sum1(k1 * (s1 - t1 * ca.fmin(s1, 0)) ** 2 + k2 * (s2 - t2 * ca.fmin(s2, 0)) ** 2)
        J = ca.jacobian(tip, q)
        EV = E + V if loaded else E
        H = ca.hessian(EV - ca.dot(F, tip), q)[0]
        self._derivs = ca.Function(f"slack_derivs_{n}" + ("_loaded" if loaded else ""), [q, p, t1, t2, F],
                                   [E, ca.gradient(EV, q), H, tip, J])

    def _check(self, m) -> None:
        if m.loaded and not self.loaded:
            raise ValueError("a chain with dead loads needs the loaded problem, slack_nlp(n, True)")

    def parameters(self, m, target, force=None) -> np.ndarray:
        """The parameter vector of the chain ``m`` (read attribute by attribute: its springs' laws are in the
        bounds, :meth:`bounds`; its dead loads ``m.link_loads``), the tip ``target`` and the dead tip load ``force``
        (default none)."""
        self._check(m)
        G = m.link_loads
        return self.p.pack(a=m.a, b=m.b, k1=m.k1, k2=m.k2, L10=m.L1_0, L20=m.L2_0, target=np.asarray(target, float),
                           force=np.zeros(2) if force is None else np.asarray(force, float), Gx=G[:, 0], Gy=G[:, 1])

    def bounds(self, m, free_tip: bool = False) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """``lbx, ubx, lbg, ubg`` of the chain ``m``: the closed joint range, each spring's law; ``free_tip``: the
        tip rows unbounded (force control)."""
        n, lim = self.n, m.joint_limits
        t = m.springs.tension_only
        e_lo = np.where(t, 0.0, -np.inf)
        lbx = self.x.pack(q=-lim, e1=e_lo, e2=e_lo)
        ubx = self.x.pack(q=lim, e1=np.inf, e2=np.inf)
        row_hi = np.where(t, np.inf, 0.0)
        tip = np.inf if free_tip else 0.0
        lbg = self.g.pack(tip=-tip, s1=np.zeros(n), s2=np.zeros(n))
        ubg = self.g.pack(tip=tip, s1=row_hi, s2=row_hi)
        return lbx, ubx, lbg, ubg

    def start(self, m, q0: np.ndarray) -> np.ndarray:
        """A start vector from the angles ``q0``: each ``e`` at its spring's value there."""
        f = m.springs.forces(q0) / m.springs.k
        return self.x.pack(q=q0, e1=f[:, 0], e2=f[:, 1])

    def solve(self, x0: np.ndarray, p: np.ndarray, bounds) -> NLPResult:
        """One IPOPT solve from ``x0`` (:meth:`start`)."""
        lbx, ubx, lbg, ubg = bounds
        return _run(self.solver, x0, lbx, ubx, lbg, ubg, p)

    def derivatives(self, m, q: np.ndarray, F: np.ndarray):
        """``(E, grad (E + V), Hess(E + V - F . tip), tip, J)`` at the relative angles ``q`` under each spring's law
        (a slack spring contributes nothing; where a spring is exactly at its rest length, its taut side): ``E`` the
        springs' energy, ``V`` the chain's dead loads' potential (less its constant, :mod:`~..model.loads`)."""
        self._check(m)
        t = m.springs.tension_only.astype(float)
        G = m.link_loads
        out = self._derivs(q, self.p.pack(a=m.a, b=m.b, k1=m.k1, k2=m.k2, L10=m.L1_0, L20=m.L2_0, target=0.0,
                                          force=0.0, Gx=G[:, 0], Gy=G[:, 1]), t, t, np.asarray(F, float))
        E, g, H, tip, J = (np.asarray(v, dtype=float) for v in out)
        return float(E.item()), g.ravel(), H, tip.ravel(), J


@per_thread
def slack_nlp(n: int, loaded: bool = False) -> SlackNLP:
    """This thread's :class:`SlackNLP` for chains of ``n`` segments, with the dead loads' terms where ``loaded`` (a
    chain's ``m.loaded``; built once each; positional arguments only: ``slack_nlp(n, m.loaded)``)."""
    return SlackNLP(n, bool(loaded))
