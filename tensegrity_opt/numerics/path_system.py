"""The equilibrium path system ``R(z, t) = 0`` of every control, as CasADi functions (one per ``n``).

An equilibrium branch in one control parameter ``t`` is the solution curve of ``n + 2`` equations in
``z = (q, F)`` (relative joint angles and the tip force)::

    R1 = grad E(q; p(t)) - J(q)^T F                                  (n: stationarity)
    R2 = A_tip (tip(q) - tip_ref) + A_F (F - F_ref) - t c            (2: the control)

with ``p(t) = p + t dp + s dp2`` (the 6n chain parameters ``a, b, k1, k2, L1_0, L2_0`` moved along
``dp`` by the control parameter — a preload control — and along ``dp2`` by a second parameter ``s``,
for two-parameter continuation). The two control rows say what is prescribed: ``A_tip = I`` holds the
tip (a displacement control, ``c`` its direction), ``A_F = I`` prescribes the force (a dead load ``c``),
one row of each is a guide or a frictionless wall (the tip held along the wall's normal, the load
prescribed along it). The analyses (:mod:`tensegrity_opt.analyses.paths.branches`) set these matrices;
this module only evaluates.

Functions (inputs ``x = (q, F, t, s)``, ``p``, ``dp``, ``dp2``, ``ctl`` — the 14 numbers
``A_tip, A_F`` (row-major), ``c, tip_ref, F_ref``):

* ``path(x, p, dp, dp2, ctl) -> (R, R_x, H, J, E, tip)``: the residual, its Jacobian in all of ``x``
  (``(n + 2) x (n + 4)``: the ``t`` and ``s`` columns are ``dR/dt``, ``dR/ds``), the Hessian of the
  potential ``E - F . tip`` in ``q``, the tip Jacobian, the elastic energy and the tip;
* ``second(x, v, p, dp, dp2, ctl) -> (R_z v, d(R_z v)/dx, (R_zz v) v)``: directional second
  derivatives for the extended systems (Moore-Spence fold system, the cusp test);
* ``curvature(x, v, p, dp, dp2, ctl) -> (R_xx[v, v], tip_xx[v, v])``: the second derivatives of the residual and
  of the tip along a direction ``v`` in all of ``x``: with ``v`` the path's tangent ``dx/dt`` they give its
  second derivative ``d^2x/dt^2`` and the tip's (the rate of the tangent stiffness along a load, the
  quasi-buckling load of :mod:`tensegrity_opt.analyses.paths.limit_load`).

Relative angles throughout (the joint range is a box in them); dense, so built for
``n <= DENSE_MAX`` only. Per thread (:mod:`.per_thread`), like every CasADi function here. For
``n <= KERNEL_MAX`` the functions are generated to C and compiled once per machine like the Newton kernels
(:func:`.build.load`; without a compiler they run in CasADi's virtual machine, about ten times slower, same
results).
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
from .layout import Layout, chain_parameters
from .per_thread import per_thread

__all__ = ["PathSystem", "PathLayouts", "path_system", "layouts", "CONTROL"]

#: The numbers describing a control: ``A_tip`` (4, row-major), ``A_F`` (4), ``c`` (2), ``tip_ref`` (2), ``F_ref`` (2).
CONTROL = Layout(A_tip=4, A_F=4, c=2, tip_ref=2, F_ref=2)
#: Newton iterations of the compiled corrector step (the Python corrector takes over when they do not
#: converge).
STEP_ITER = 5


class PathLayouts(NamedTuple):
    """The blocks of the path system's vectors for ``n`` segments (:func:`layouts`)."""

    #: the functions' point ``x = (q, F, t, s)`` (the control parameter ``t``, the second parameter ``s``)
    point: Layout
    #: a point of a branch ``(q, F, t)``: the functions' point without ``s`` (each block in the same place); also
    #: the blocks of a branch's tangent and of the columns of ``R_x`` in ``(z, t)``
    branch_point: Layout
    #: the unknowns ``z = (q, F)`` of ``R``, and the blocks of a null vector of ``R_z``
    z: Layout
    #: the residual ``R``: the stationarity rows ``grad`` (n) and the two ``control`` rows
    rows: Layout
    #: the chain's parameters ``p`` and the directions ``dp``, ``dp2`` (:func:`.layout.chain_parameters`)
    parameters: Layout
    #: the fold (Moore-Spence) system's unknowns: a branch point ``(q, F, t)`` and the null vector ``phi`` of
    #: ``R_z`` (n + 2)
    fold: Layout
    #: the same continued in the second parameter: ``(q, F, t, phi, p)``
    fold_curve: Layout
    #: the fold system's rows: ``R`` (n + 2), ``Rz_phi`` (``R_z phi``, n + 2) and ``norm`` (``l . phi - 1``)
    fold_rows: Layout


@lru_cache(maxsize=None)
def layouts(n: int) -> PathLayouts:
    """The layouts of the path system's vectors for ``n`` segments."""
    return PathLayouts(point=Layout(q=n, F=2, t=(), s=()), branch_point=Layout(q=n, F=2, t=()), z=Layout(q=n, F=2),
                       rows=Layout(grad=n, control=2), parameters=chain_parameters(n),
                       fold=Layout(q=n, F=2, t=(), phi=n + 2), fold_curve=Layout(q=n, F=2, t=(), phi=n + 2, p=()),
                       fold_rows=Layout(R=n + 2, Rz_phi=n + 2, norm=()))


@lru_cache(maxsize=None)
def _graphs(n: int, tension: tuple[bool, ...] = ()):
    at = layouts(n)
    x = ca.SX.sym("x", at.point.size)
    q, F, t, s = (x[at.point[k]] for k in ("q", "F", "t", "s"))
    size = at.parameters.size
    p, dp, dp2 = ca.SX.sym("p", size), ca.SX.sym("dp", size), ca.SX.sym("dp2", size)
    ctl = ca.SX.sym("ctl", CONTROL.size)
    pe = p + t * dp + s * dp2
    a, b, k1, k2, L10, L20 = (pe[at.parameters[k]] for k in ("a", "b", "k1", "k2", "L10", "L20"))
    _, _, E = segment_energy(q, a, b, k1, k2, L10, L20, tension=tension or None)
    phi = ca.cumsum(q)
    tip = tip_expression(phi, b)
    J = ca.jacobian(tip, q)
    A_tip = ca.reshape(ctl[CONTROL["A_tip"]], 2, 2).T
    A_F = ca.reshape(ctl[CONTROL["A_F"]], 2, 2).T
    c, tip_ref, F_ref = (ctl[CONTROL[k]] for k in ("c", "tip_ref", "F_ref"))
    R = ca.vertcat(ca.gradient(E, q) - J.T @ F, A_tip @ (tip - tip_ref) + A_F @ (F - F_ref) - t * c)
    Rx = ca.jacobian(R, x)
    H = ca.hessian(E - ca.dot(F, tip), q)[0]
    path = ca.Function("path", [x, p, dp, dp2, ctl], [R, ca.densify(Rx), ca.densify(H), ca.densify(J), E, tip])
    v = ca.SX.sym("v", n + 2)
    z = x[at.point.span("q", "F")]
    Rzv = ca.jtimes(R, z, v)
    second = ca.Function("second", [x, v, p, dp, dp2, ctl],
                         [Rzv, ca.densify(ca.jacobian(Rzv, x)), ca.jtimes(Rzv, z, v)])
    u = ca.SX.sym("u", at.point.size)
    curvature = ca.Function("curvature", [x, u, p, dp, dp2, ctl],
                            [ca.densify(ca.jtimes(ca.jtimes(R, x, u), x, u)),
                             ca.densify(ca.jtimes(ca.jtimes(tip, x, u), x, u))])
    return path, second, _step(n, path), curvature


def _step(n: int, path: ca.Function) -> ca.Function:
    """One whole predictor-corrector step (module docstring of :mod:`tensegrity_opt.analyses.paths.branches`):
    ``(x_a, tau, h, w, rs, tol, p, dp, dp2, ctl) -> (x, res, iterations, tau_b, R, R_x, H, J, E, tip)``.

    From ``x_a`` and its unit tangent ``tau`` (scaled coordinates ``w x``), the predictor
    ``x_a + h tau / w``, then ``STEP_ITER`` Newton iterations on ``[R(x); (w tau) . x - b] = 0``
    (``b = tau . (w x_a) + h``), each kept once the scaled residual ``max |rs R|`` and the arclength
    condition are below ``tol`` (the iterate then stays); at the last iterate its residual, the number of
    iterations that moved (the caller checks the arclength condition), the tangent there
    (``[R_x / w; tau] v = e``, normalised) and the path outputs.
    The caller checks ``res`` and falls back to the Python corrector."""
    N = n + 2
    xa, tau, w = ca.SX.sym("xa", N + 1), ca.SX.sym("tau", N + 1), ca.SX.sym("w", N + 1)
    h, tol, rs = ca.SX.sym("h"), ca.SX.sym("tol"), ca.SX.sym("rs", N)
    size = layouts(n).parameters.size
    p, dp, dp2 = ca.SX.sym("p", size), ca.SX.sym("dp", size), ca.SX.sym("dp2", size)
    ctl = ca.SX.sym("ctl", CONTROL.size)
    aw = tau * w
    b = ca.dot(tau, w * xa) + h
    x = xa + h * tau / w
    moved = 0
    for _ in range(STEP_ITER):
        R, Rx = path(ca.vertcat(x, 0), p, dp, dp2, ctl)[:2]
        g = ca.dot(aw, x) - b
        done = ca.logic_and(ca.mmax(ca.fabs(R * rs)) <= tol, ca.fabs(g) <= 1e-12 * ca.fmax(1, ca.fabs(b)))
        d = ca.solve(ca.vertcat(Rx[:, :N + 1], aw.T), -ca.vertcat(R, g))
        x = ca.if_else(done, x, x + d)
        moved = moved + ca.if_else(done, 0, 1)
    R, Rx, H, J, E, tip = path(ca.vertcat(x, 0), p, dp, dp2, ctl)
    res = ca.mmax(ca.fabs(R * rs))
    e = ca.DM.zeros(N + 1)
    e[N] = 1.0
    A = Rx[:, :N + 1] / ca.repmat(w.T, N, 1)
    v = ca.solve(ca.vertcat(A, tau.T), e)
    v = v / ca.norm_2(v)
    return ca.Function("step", [xa, tau, h, w, rs, tol, p, dp, dp2, ctl],
                       [x, res, moved, v, R, Rx, H, J, E, tip])


def _library(n: int) -> str:
    return f"tensegrity_paths_n{n}"


#: The Functions of the path system, in the order :func:`_graphs` builds them.
_NAMES = ("path", "second", "step", "curvature")


def _functions(n: int, tension: tuple[bool, ...] = ()) -> tuple[tuple[ca.Function, ...], str, bool]:
    """This thread's ``path``, ``second``, ``step`` and ``curvature`` Functions, how they run (``"compiled"`` /
    ``"virtual machine"``) and whether they are compiled in the background meanwhile (:func:`.build.load`).
    ``tension`` (one bool per segment, any true): the tension-only segments' variant, in the virtual machine (one
    graph per pattern of laws: not compiled)."""
    if any(tension):
        return _graphs(n, tuple(bool(t) for t in tension)), VIRTUAL_MACHINE, False
    if 2 <= n <= KERNEL_MAX:
        loaded = load(_library(n), "the path functions", lambda: dict(zip(_NAMES, _graphs(n))))
        return tuple(loaded.functions[k] for k in _NAMES), loaded.mode, loaded.pending
    return _graphs(n), VIRTUAL_MACHINE, False


class PathSystem:
    """This thread's evaluators of the path system for chains of ``n`` segments."""

    def __init__(self, n: int, tension: tuple[bool, ...] = ()) -> None:
        self.n = n
        #: which segments' springs are tension-only (empty: every one linear)
        self.tension = tuple(tension)
        #: the blocks of the functions' vectors (:class:`PathLayouts`)
        self.layouts = layouts(n)
        #: the point ``x = (q, F, t, s)`` of the functions (the control parameter ``t``, the second one ``s``)
        self.point = self.layouts.point
        (path, second, step, curvature), self.mode, self.pending = _functions(n, self.tension)
        self._path = Fast(path)
        self._second = Fast(second)
        self._step = Fast(step)
        self._curvature = Fast(curvature)

    def evaluate(self, x, p, dp, dp2, ctl):
        """``(R, R_x, H, J, E, tip)`` at ``x = (q, F, t, s)`` (copies: safe to keep)."""
        f = self._path
        out = f(x, p, dp, dp2, ctl)
        return (out[0].copy(), f.dense(1).copy(), f.dense(2).copy(), f.dense(3).copy(), float(out[4][0]),
                out[5].copy())

    def step(self, xa, tau, h, w, rs, tol, p, dp, dp2, ctl):
        """The compiled predictor-corrector step (:func:`_step`): ``(x, res, iterations, tau_b, path outputs)``,
        the path outputs as :meth:`evaluate` gives them. Copies."""
        f = self._step
        out = f(xa, tau, h, w, rs, tol, p, dp, dp2, ctl)
        return (out[0].copy(), float(out[1][0]), int(out[2][0]), out[3].copy(),
                (out[4].copy(), f.dense(5).copy(), f.dense(6).copy(), f.dense(7).copy(), float(out[8][0]),
                 out[9].copy()))

    def residual(self, x, p, dp, dp2, ctl):
        """``(R, R_x)`` only (copies)."""
        f = self._path
        out = f(x, p, dp, dp2, ctl)
        return out[0].copy(), f.dense(1).copy()

    def second(self, x, v, p, dp, dp2, ctl):
        """``(R_z v, d(R_z v)/dx, (R_zz v) v)`` at ``x`` for the direction ``v`` in ``z = (q, F)``."""
        f = self._second
        out = f(x, v, p, dp, dp2, ctl)
        return out[0].copy(), f.dense(1).copy(), out[2].copy()

    def curvature(self, x, u, p, dp, dp2, ctl):
        """``(R_xx[u, u], tip_xx[u, u])`` at ``x`` for the direction ``u`` in all of ``x = (q, F, t, s)``."""
        f = self._curvature
        out = f(x, u, p, dp, dp2, ctl)
        return out[0].copy(), out[1].copy()


def _compiled_meanwhile(ps: PathSystem) -> bool:
    return ps.pending and not ps.tension and not pending(_library(ps.n))


@per_thread(stale=_compiled_meanwhile)
def path_system(n: int, tension: tuple[bool, ...] = ()) -> PathSystem:
    """This thread's :class:`PathSystem` for ``n`` segments (:func:`.per_thread.per_thread`); ``tension``: which
    segments' springs are tension-only (empty or all false: the linear law's compiled functions)."""
    return PathSystem(n, tuple(bool(t) for t in tension) if any(tension) else ())


def control_vector(A_tip, A_F, c, tip_ref, F_ref) -> np.ndarray:
    """The 14 control numbers in the order the functions read them (:data:`CONTROL`)."""
    return CONTROL.pack(A_tip=np.asarray(A_tip, float).ravel(), A_F=np.asarray(A_F, float).ravel(), c=c,
                        tip_ref=tip_ref, F_ref=F_ref)
