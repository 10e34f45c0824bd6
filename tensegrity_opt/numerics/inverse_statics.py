"""The inverse-statics problem (rest lengths for a tip pose under a load) as one compiled Newton step.

Unknowns ``y = (q, l, mu)``: relative joint angles ``q`` (n), the rest lengths ``l = (L1_0, L2_0)`` per
segment (2n, segment by segment: ``l[2i], l[2i+1]``) and the multipliers ``mu`` of the task rows. The
least-change problem of a control step::

    min  1/2 sum_j w_j (l_j - l_prev_j)^2 + 1/2 eps |q - q_prev|^2
    s.t. grad E(q; l) - J(q)^T F = 0          (n: the arm in equilibrium under the dead tip load F)
         tip(q) = target                       (2)
         sum(q) = end_angle                    (1, the variant with the last link's angle)

Its KKT system ``r(y) = [grad_q L; grad_l L; g] = 0`` (``L = f + mu . g``) is solved by Newton's method:
the compiled function gives ``r`` and its Jacobian, the linear solves are numpy's (an unrolled symbolic
solve compiles for tens of seconds); ``step`` iterates from a warm start and returns the
iterate, its residual, the iterations that moved, the Hessian of ``E - F . tip`` in ``q`` there (the
stability of the free arm: positive definite) and the KKT matrix (a strict local minimum of the
least-change problem has ``3 n`` positive and ``rows`` negative eigenvalues: Newton can also converge to
a saddle of it). Built once per ``(n, angle)`` and thread (:mod:`.per_thread`); generated to C and compiled
like the other kernels for ``n <= KERNEL_MAX`` (:func:`.build.load`), CasADi's virtual machine otherwise.
Bounds, rate limits and the stability margin are the caller's
(:mod:`tensegrity_opt.analyses.design.preload_control`): it checks them on the result and falls back to IPOPT
where one is active.
"""

from __future__ import annotations

from functools import lru_cache
from typing import NamedTuple

import casadi as ca
import numpy as np

from ._fast import Fast
from .build import VIRTUAL_MACHINE, load, pending
from .expressions import segment_energy, tip_expression
from .kernels import KERNEL_MAX
from .layout import Layout
from .per_thread import per_thread

__all__ = ["InverseStatics", "inverse_statics", "layouts", "StepLayouts", "ITER"]

#: Newton iterations of one step at most.
ITER = 25


class StepLayouts(NamedTuple):
    """The step's inputs by name (:func:`layouts`)."""

    #: the unknowns ``y``: joint angles ``q``, rest lengths ``ell`` (segment by segment), multipliers ``mu`` of
    #: the ``n + 2`` task rows (``n + 3`` with the angle row)
    unknowns: Layout
    #: the geometry ``geo``: ``a, b, k1, k2``
    geometry: Layout
    #: the ``target``: the ``tip`` and the last link's ``angle`` (read only with the angle row)
    target: Layout


@lru_cache(maxsize=None)
def layouts(n: int, angle: bool) -> StepLayouts:
    """The layouts of the step's inputs for ``n`` segments (``angle``: with the end-angle row)."""
    return StepLayouts(Layout(q=n, ell=2 * n, mu=n + 2 + (1 if angle else 0)), Layout(a=n, b=n, k1=n, k2=n),
                       Layout(tip=2, angle=()))


@lru_cache(maxsize=None)
def _graph(n: int, angle: bool) -> ca.Function:
    unknowns, geometry, target_at = layouts(n, angle)
    y = ca.SX.sym("y", unknowns.size)
    q, ell, mu = (y[unknowns[k]] for k in ("q", "ell", "mu"))
    geo = ca.SX.sym("geo", geometry.size)
    a, b, k1, k2 = (geo[geometry[k]] for k in ("a", "b", "k1", "k2"))
    F, target = ca.SX.sym("F", 2), ca.SX.sym("target", target_at.size)
    ell_prev, w, q_prev = ca.SX.sym("ell_prev", 2 * n), ca.SX.sym("w", 2 * n), ca.SX.sym("q_prev", n)
    eps = ca.SX.sym("eps")
    L10, L20 = ell[0::2], ell[1::2]
    _, _, E = segment_energy(q, a, b, k1, k2, L10, L20)
    tip = tip_expression(ca.cumsum(q), b)
    J = ca.jacobian(tip, q)
    g = [ca.gradient(E, q) - J.T @ F, tip - target[target_at["tip"]]]
    if angle:
        g.append(ca.sum1(q) - target[target_at["angle"]])
    g = ca.vertcat(*g)
    f = 0.5 * ca.sum1(w * (ell - ell_prev) ** 2) + 0.5 * eps * ca.sumsqr(q - q_prev)
    Lag = f + ca.dot(mu, g)
    r = ca.vertcat(ca.gradient(Lag, ca.vertcat(q, ell)), g)
    K = ca.jacobian(r, y)
    H = ca.hessian(E - ca.dot(F, tip), q)[0]
    return ca.Function("inverse_kkt", [y, geo, F, target, ell_prev, w, q_prev, eps],
                       [r, ca.densify(K), ca.densify(H), E, tip])


def _library(n: int, angle: bool) -> str:
    return f"tensegrity_inverse_n{n}{'a' if angle else ''}"


def _function(n: int, angle: bool) -> tuple[ca.Function, str, bool]:
    if 2 <= n <= KERNEL_MAX:
        loaded = load(_library(n, angle), "the inverse-statics step", lambda: {"inverse_kkt": _graph(n, angle)})
        return loaded.functions["inverse_kkt"], loaded.mode, loaded.pending
    return _graph(n, angle), VIRTUAL_MACHINE, False


class InverseStatics:
    """This thread's compiled inverse-statics step for ``n`` segments (``angle``: with the end-angle row)."""

    def __init__(self, n: int, angle: bool) -> None:
        self.n, self.angle = n, angle
        #: the unknowns ``y``: joint angles ``q``, rest lengths ``ell`` (segment by segment), multipliers ``mu``;
        #: the geometry ``geo`` (``a, b, k1, k2``); the ``target`` (``tip``, ``angle``) (:func:`layouts`)
        self.unknowns, self.geometry, self.target = layouts(n, angle)
        self.rows = n + 2 + (1 if angle else 0)
        f, self.mode, self.pending = _function(n, angle)
        self._f = Fast(f)

    def step(self, y0, geo, F, target, ell_prev, w, q_prev, eps, tol, max_iter: int = ITER):
        """Newton's method on the KKT system from ``y0``: ``(y, residual, iterations, H, E, tip, K)`` with ``K``
        the KKT matrix at ``y`` (its inertia says whether ``y`` is a strict local minimum; copies). Stops when
        ``max |r| <= tol`` or after ``max_iter`` iterations (or where the matrix is singular)."""
        f = self._f
        y = np.array(y0, dtype=float)
        it = 0
        while True:
            out = f(y, geo, F, target, ell_prev, w, q_prev, eps)
            r = out[0]
            res = float(np.max(np.abs(r)))
            if res <= tol or it >= max_iter or not np.isfinite(res):
                break
            try:
                y = y - np.linalg.solve(f.dense(1), r)
            except np.linalg.LinAlgError:
                break
            it += 1
        return y, res, it, f.dense(2).copy(), float(out[3][0]), out[4].copy(), f.dense(1).copy()


def inverse_statics(n: int, angle: bool = False) -> InverseStatics:
    """This thread's :class:`InverseStatics` (built once per thread, ``n`` and ``angle``: :mod:`.per_thread`)."""
    return _inverse_statics(n, bool(angle))


def _compiled_meanwhile(step: InverseStatics) -> bool:
    return step.pending and not pending(_library(step.n, step.angle))


_inverse_statics = per_thread(InverseStatics, stale=_compiled_meanwhile)
