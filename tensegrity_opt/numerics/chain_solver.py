"""The chain solver: every CasADi function and solver for one chain length, behind one interface.

What is solved lives in the analyses (``equilibrium``, ``all_equilibria``, ``curves`` ...); this
module says *how*: the symbolic model of :mod:`.expressions` in absolute link angles ``phi`` (energy
Hessian tridiagonal, constraint Hessians diagonal, so cost grows about linearly in ``n``), IPOPT for
minimisation (:mod:`.ipopt`), a damped Newton method on the KKT system for every stationary point and
for warm-started local corrections (:mod:`.newton`) — for chains of up to ``kernels.KERNEL_MAX``
segments run as generated C (:mod:`.kernels`) — compiled continuation and batched derivatives, and
the derivatives for stiffness and sensitivities.

Use
---
``chain_solver(m)`` returns this thread's :class:`ChainSolver` for the manipulator ``m``, whose methods
take targets, forces and configurations only::

    s = chain_solver(m)
    res = s.newton_kkt(m.target(dx, dy), q0)         # a LocalResult

The CasADi side, :class:`ChainFunctions`, is built once per chain length ``n`` with all numbers
(geometry, stiffness, preloads, loads) as parameters, and cached per thread (:mod:`.per_thread`); a
:class:`ChainSolver` is those functions with one chain's parameter vector, cheap to make. The functions'
*kind* says how the chain is represented: ``"dense"`` (``n <= DENSE_MAX``: one SX graph, dense KKT
matrices, LAPACK; the compiled kernels for ``2 <= n <= KERNEL_MAX`` on top) or ``"banded"`` (longer
chains: MX whole-vector graphs, tridiagonal Hessians, O(n) solves). ``n`` alone chooses the kind, so the
cache is keyed by ``n``; another kind for the same ``n`` is built on request (``ChainFunctions(n, kind)``,
uncached: for comparing the two).

Thread safety
-------------
A CasADi ``Function``/``nlpsol`` instance must never be called by two threads at once (it evaluates
in one shared memory slot). The functions are cached *per thread*: each thread builds and owns its
own, so every public function of the library may be called from several threads at once. Parts needed
only by some calls (IPOPT, sensitivities, kernels) are built on first use (:class:`_built`); no lock is
needed since an instance never leaves its thread.
"""

from __future__ import annotations

import math
from functools import lru_cache
from typing import NamedTuple

import casadi as ca
import numpy as np
import scipy.linalg as sla

from . import ipopt as _ipopt
from . import kernels as _kernels
from ._fast import Fast
from .expressions import banded_functions, kkt_graph
from .newton import damped_newton, one_blas_thread
from .per_thread import per_thread
from .results import Continuation, LocalResult, SeedResults, seed_results, set_row
from .units import (
    rescaled,
    torque_scale,
    unscale_continuation,
    unscale_result,
    unscale_seeds,
)

__all__ = ["ChainSolver", "ChainFunctions", "chain_solver", "chain_functions", "DENSE_MAX", "BATCH", "SAMPLE_ROUNDS"]

#: Chains up to this many segments use dense linear algebra; longer ones sparse (O(n)) paths.
DENSE_MAX = 64
#: Points per compiled batch (continuation and batched derivatives).
BATCH = 128
#: Further batched calls of the seeds kernel for the starts of a large sample not converged in the
#: first (``newton_kkt_seeds(python_fallback=False)``); each call is ``kernels.SEED_ITER`` iterations.
SAMPLE_ROUNDS = 5
KINDS = ("dense", "banded")
_UNBUILT = object()


class _built:
    """A part of a solver built on first access, then a plain attribute of the instance.

    ``functools.cached_property`` without its lock (Python < 3.12 holds one lock per property for
    all instances, which would make threads wait for each other's builds): a solver never leaves
    the thread that owns it.
    """

    def __init__(self, build) -> None:
        self.build = build
        self.name = build.__name__
        self.__doc__ = build.__doc__

    def __set_name__(self, owner, name: str) -> None:
        self.name = name

    def __get__(self, obj, owner=None):
        if obj is None:
            return self
        value = obj.__dict__[self.name] = self.build(obj)
        return value


class _KernelSet(NamedTuple):
    """The compiled Newton kernels of one solver, with :class:`Fast` wrappers of their Functions."""

    kernels: _kernels.Kernels
    newton: Fast
    seeds: Fast
    continuation: Fast


class ChainFunctions:
    """Every CasADi function and solver for chains of ``n`` segments of one ``kind`` (one thread's).

    Obtain it through :func:`chain_functions` (this thread's, cached); a :class:`ChainSolver` evaluates it
    for one chain's parameters. ``"dense"`` (default for ``n <= DENSE_MAX``): one SX graph in absolute
    angles gives the KKT residual and its dense Jacobian, the Hessian and the IPOPT problems. ``"banded"``
    (longer chains): the functions used by Newton and the classification are the MX graphs of
    :func:`.expressions.banded_functions`, returning the tridiagonal Hessian as two diagonals; the SX graph
    (IPOPT fallback, parameter sensitivities) is built only when first needed.
    """

    def __init__(self, n: int, kind: str | None = None) -> None:
        if kind is None:
            kind = "dense" if n <= DENSE_MAX else "banded"
        if kind not in KINDS:
            raise ValueError(f"kind must be one of {KINDS}, got {kind!r}")
        self.n = n
        self.kind = kind
        self.dense = kind == "dense"
        self.last: ChainSolver | None = None        # chain_solver's last solver (reused for the same m)
        self._kernel: _KernelSet | None | object = _UNBUILT
        if self.dense:
            D = ca.densify
            phi, p, F, q, E, tip, res, z, tgt, gradE, J, H = self._sym
            self.force_res = ca.Function("force_res", [phi, p, F], [gradE - J.T @ F, D(H)])
            self.derivs = ca.Function("derivs", [phi, p, F], [E, gradE, D(H), D(J), tip])
            self.fast_kkt = Fast(self.kkt)
            self.fast_force = Fast(self.force_res)
            self.fast_derivs = Fast(self.derivs)
        else:
            f = banded_functions(n)
            self.kkt_banded, self.kkt_res_banded = f["kkt_banded"], f["kkt_res_banded"]
            self.force_res_banded, self.force_banded = f["force_res_banded"], f["force_banded"]
            self.derivs_banded = f["derivs_banded"]
            self.fast_kkt = Fast(self.kkt_banded)
            self.fast_force = Fast(self.force_banded)
            self.fast_kkt_res = Fast(self.kkt_res_banded)
            self.fast_force_res = Fast(self.force_res_banded)
            self.fast_derivs = Fast(self.derivs_banded)

    # ---------------------------------------------------------------- parts built on first use
    @_built
    def _sym(self):
        """The SX graph: (phi, p, F, q, E, tip, KKT residual, z, target, grad E, J, H)."""
        return kkt_graph(self.n)

    @property
    def kernel(self) -> _KernelSet | None:
        """The compiled Newton kernels (:mod:`.kernels`) with fast wrappers, for
        ``2 <= n <= kernels.KERNEL_MAX`` (dense solvers); else ``None``. Built on first use; kernels running in
        the virtual machine while they compile in the background are replaced by the compiled ones when ready."""
        k = self._kernel
        if k is _UNBUILT or (k is not None and k.kernels.pending and not _kernels.pending(self.n)):
            k = self._kernel = self._build_kernel()
        return k

    def _build_kernel(self) -> _KernelSet | None:
        if self.dense and 2 <= self.n <= _kernels.KERNEL_MAX:
            k = _kernels.build(self.n)
            return _KernelSet(k, Fast(k.newton), Fast(k.seeds), Fast(k.continuation))
        return None

    @_built
    def kkt(self):
        """KKT residual and Jacobian ``(z, p, target) -> (r, [[H, -J^T], [J, 0]])`` (SX); dense for dense
        solvers, else sparse (built on first use)."""
        phi, p, F, q, E, tip, res, z, tgt, gradE, J, H = self._sym
        kkt_jac = ca.blockcat([[H, -J.T], [J, ca.SX(2, 2)]])
        return ca.Function("kkt", [z, p, tgt], [res, ca.densify(kkt_jac) if self.dense else kkt_jac])

    @_built
    def kkt_dp(self):
        """d(KKT residual)/d(parameters), for sensitivities."""
        phi, p, F, q, E, tip, res, z, tgt, *_ = self._sym
        return ca.Function("kkt_dp", [z, p, tgt], [ca.jacobian(res, p)])

    @_built
    def nlp_disp(self):
        """IPOPT: min E s.t. [tip; q] within bounds."""
        return _ipopt.displacement_nlp(self._sym)

    @_built
    def nlp_force(self):
        """IPOPT: min E - F.tip s.t. q within bounds."""
        return _ipopt.force_nlp(self._sym)

    @_built
    def batch(self):
        """CasADi's ``rootfinder`` under ``mapaccum`` (continuation without kernels) and the derivatives
        mapped over ``BATCH`` points (dense solvers)."""
        n, N = self.n, BATCH
        phi, p, F, q, E, tip, res, z, tgt, *_ = self._sym
        resf = ca.Function("kkt_res", [z, ca.vertcat(p, tgt)], [res])
        rf = ca.rootfinder("kkt_rf", "newton", resf,
                           {"error_on_fail": False, "abstol": 1e-12, "max_iter": 30})
        zp, pm, tm = ca.MX.sym("z", n + 2), ca.MX.sym("p", 6 * n), ca.MX.sym("t", 2)
        zn = rf(zp, ca.vertcat(pm, tm))
        step = ca.Function("step", [zp, tm, pm], [zn, ca.norm_inf(resf(zn, ca.vertcat(pm, tm)))])
        return step.mapaccum("continuation", N), self.derivs.map(N)


@per_thread
def chain_functions(n: int) -> ChainFunctions:
    """This thread's :class:`ChainFunctions` for ``n`` segments (built on first use: :mod:`.per_thread`)."""
    return ChainFunctions(n)


class ChainSolver:
    """The numerics of one chain: its :class:`ChainFunctions` evaluated at its parameters.

    Every method reads the chain's parameters and joint limits itself; angles are relative joint angles
    ``q`` (rad) unless a method says ``phi`` (absolute), targets are tip positions (``m.target(dx, dy)``),
    forces tip forces ``[Fx, Fy]``. Results are numpy only (:class:`LocalResult`, :class:`SeedResults`,
    :class:`Continuation`, arrays). Owned by the thread that made it, like its functions; cheap to make
    (:func:`chain_solver` keeps the last one per thread and chain length).

    Parameters
    ----------
    functions : ChainFunctions
    m : Manipulator
        The chain (``m.n == functions.n``).
    params : ndarray, optional
        The chain's parameters already in the units the Newton methods work in (:func:`.units.rescaled`; the
        solver then solves in them as they are); default ``m.params``, rescaled where needed.
    """

    __slots__ = ("functions", "manipulator", "params", "limits", "_scaled", "_scale")

    def __init__(self, functions: ChainFunctions, m, *, params: np.ndarray | None = None) -> None:
        self.functions = functions
        self.manipulator = m
        self.params = m.params if params is None else params
        self.limits = m.joint_limits
        self._scaled = None if params is None else (1.0, 1.0, self)
        self._scale = None

    @property
    def n(self) -> int:
        return self.functions.n

    @property
    def kind(self) -> str:
        """``"dense"`` or ``"banded"`` (:class:`ChainFunctions`)."""
        return self.functions.kind

    @property
    def dense(self) -> bool:
        """Dense linear algebra (``n <= DENSE_MAX``): compiled continuation and batched derivatives exist."""
        return self.functions.dense

    @property
    def kernel_mode(self) -> str | None:
        """How the compiled kernels run: ``"compiled"``, ``"virtual machine"``, or ``None`` (no kernels
        for this ``n``). Builds them on first use."""
        k = self.functions.kernel
        return None if k is None else k.kernels.mode

    # ---------------------------------------------------------------- units and tolerances
    def _units(self) -> tuple[float, float, ChainSolver]:
        """``(lam, kap, solver)``: the units the Newton methods work in (:func:`.units.rescaled`) and this
        chain's solver in them (itself when no rescaling is needed)."""
        if self._scaled is None:
            lam, kap, scaled = rescaled(self.params, self.n)
            self._scaled = (1.0, 1.0, self) if scaled is self.params else \
                (lam, kap, ChainSolver(self.functions, self.manipulator, params=scaled))
        return self._scaled

    @property
    def scale(self) -> float:
        """The torque scale of the stopping tests: residuals are torques, so the test is scaled by ``k c^2``
        of the stiffest segment; the test is on the 2-norm of ``n + 2`` entries, whose roundoff floor grows as
        ``sqrt(n)``: beyond ``DENSE_MAX`` segments it is scaled by ``sqrt(n / DENSE_MAX)``, the same accuracy
        per entry as at 64."""
        if self._scale is None:
            n = self.n
            self._scale = max(1.0, torque_scale(self.params, n)) * max(1.0, math.sqrt(n / DENSE_MAX))
        return self._scale

    # ---------------------------------------------------------------- local solves
    def newton_kkt(self, target: np.ndarray, q0: np.ndarray, F0: np.ndarray | None = None, *, tol: float = 1e-12,
                   max_iter: int = 50, max_step: float = 0.5) -> LocalResult:
        """Damped Newton on the KKT system of the displacement problem (any stationary point).

        Converged when the residual's 2-norm is at most ``tol`` times the torque scale ``k c^2`` of the
        stiffest segment (times ``sqrt(n / DENSE_MAX)`` for longer chains: the norm's roundoff floor
        grows as ``sqrt(n)``), in the solver's units (:mod:`.units`). ``F0`` defaults to the
        least-squares force of eq. (8) at ``q0``. Chains with compiled kernels (:mod:`.kernels`) run the
        method there first (same step rule), and in Python only when it did not converge.
        """
        lam, kap, s = self._units()
        if s is not self:
            res = s.newton_kkt(lam * np.asarray(target, float), q0,
                               None if F0 is None else kap * lam * np.asarray(F0, float), tol=tol, max_iter=max_iter,
                               max_step=max_step)
            return unscale_result(res, lam, kap)
        f, params = self.functions, self.params
        if max_step == _kernels.MAX_STEP and f.kernel is not None:
            res = self._kernel_newton(target, q0, F0, tol * self.scale, max_iter)
            if res is not None:
                return res
        phi = np.cumsum(np.asarray(q0, dtype=float))
        if F0 is None:
            # eq. (8): F = (J J^T)^-1 J grad E, a 2 x 2 system solved by hand (a start only)
            out = f.fast_derivs(phi, params, np.zeros(2))
            g, J = out[1], f.fast_derivs.dense(3 if f.dense else 4)
            A = J @ J.T
            bvec = J @ g
            det = A[0, 0] * A[1, 1] - A[0, 1] * A[1, 0]
            if abs(det) > 1e-14 * max(1.0, A[0, 0] * A[1, 1]):
                F0 = np.array([A[1, 1] * bvec[0] - A[0, 1] * bvec[1], A[0, 0] * bvec[1] - A[1, 0] * bvec[0]]) / det
            else:
                F0 = np.array([0.0, bvec[1] / A[1, 1] if A[1, 1] > 0 else 0.0])
        z = np.concatenate([phi, np.asarray(F0, dtype=float)])
        return self._newton(f.fast_kkt, None if f.dense else f.fast_kkt_res, (params, target), z, tol, max_iter,
                            max_step, None)

    def _kernel_newton(self, target, q0, F0, thresh, max_iter) -> LocalResult | None:
        """The compiled damped Newton method from ``(q0, F0)``; ``None`` when it did not converge."""
        fast = self.functions.kernel.newton
        n, params = self.n, self.params
        use = F0 is not None
        out = fast(q0, F0 if use else _ZERO2, 1.0 if use else 0.0, params, target, thresh)
        its, calls = int(out[2][0]), 1
        while not out[1][0] <= thresh:
            if not np.isfinite(out[1][0]) or calls * _kernels.ITER >= max_iter:
                return None
            out = fast(out[6], out[0][n:], 1.0, params, target, thresh)     # inputs are copied first
            its, calls = its + int(out[2][0]), calls + 1
        m = n - 2
        # R is Z^T H Z (symmetric): its column-major nonzeros read row-major give the same matrix
        return LocalResult(out[6].copy(), out[0][n:].copy(), True, "Newton_Converged", its, bool(out[7][0] >= 0.0),
                           float(out[3][0]), out[4].copy(), out[5].reshape(m, m).copy())

    def newton_kkt_seeds(self, target: np.ndarray, starts: np.ndarray | list[np.ndarray], same: float = 0.0, *,
                         python_fallback: bool = True) -> SeedResults:
        """:meth:`newton_kkt` from each start (force from eq. (8)); the seeds of a global search.

        With kernels, up to ``kernels.seed_columns(n)`` starts per compiled call (``kernels.SEED_ITER``
        iterations); a start not converged there goes on from its iterate with the ``newton`` kernel and,
        if that fails too, is run again from the start by :meth:`newton_kkt` (down to the Python method).
        ``same`` > 0 (rad): the result's ``distinct`` marks the distinct converged rows inside the range (the
        rule of :mod:`.distinct` with tolerance ``same``), when one kernel call settled every start (else
        ``distinct`` is ``None``: compare the rows yourself). ``python_fallback=False`` (large samples
        of starts, where a few failures cost nothing): the starts not converged in the first call go on
        from their iterates in up to ``SAMPLE_ROUNDS`` more batched calls of the same kernel (instead of one
        ``newton`` kernel call each), and what is still not converged is left so (no Python method).
        """
        lam, kap, s = self._units()
        if s is not self:
            out = s.newton_kkt_seeds(lam * np.asarray(target, float), starts, same, python_fallback=python_fallback)
            return unscale_seeds(out, lam, kap)
        n, m, params, limits = self.n, self.n - 2, self.params, self.limits
        Q0 = np.asarray(starts, dtype=float).reshape(-1, n)
        k_all = Q0.shape[0]
        kern = self.functions.kernel
        if kern is None or k_all == 0:
            return seed_results([self.newton_kkt(target, q) for q in Q0], n)
        thresh = 1e-12 * self.scale
        fast, S, layout = kern.seeds, _kernels.seed_columns(n), _kernels.seed_layout(n)

        def call(Q: np.ndarray) -> tuple[dict[str, np.ndarray], int]:
            k = Q.shape[0]
            chunks = -(-k // S)
            src = np.zeros((chunks * S, n))
            src[:k] = Q
            # a start's outputs are one column of the kernel's, one row here (copied: the buffer is reused)
            parts = [fast(src[c * S:(c + 1) * S].ravel(), _active(S, min(S, k - c * S)), params, target, thresh,
                          same)[0].reshape(S, -1).copy() for c in range(chunks)]
            return layout.unpack((parts[0] if chunks == 1 else np.vstack(parts))[:k]), chunks

        Y, chunks = call(Q0)
        # R is Z^T H Z (symmetric): the kernel's column-major nonzeros, transposed back
        out_b = SeedResults(Y["q"], Y["F"], Y["norm"] <= thresh, Y["margin"] >= 0.0, Y["iters"].astype(int),
                            ["Newton_Converged"] * k_all, Y["E"], Y["tip"],
                            Y["R"].reshape(k_all, m, m).transpose(0, 2, 1),
                            Y["distinct"] > 0.5 if chunks == 1 and same > 0.0 else None)
        if not python_fallback:
            rows = np.flatnonzero(~out_b.success)
            if rows.size:
                out_b.distinct = None
            for _ in range(SAMPLE_ROUNDS):
                Qr = out_b.q[rows]
                rows = rows[np.all(np.isfinite(Qr), axis=1) & np.all(np.abs(Qr) < limits, axis=1)]
                if rows.size == 0:
                    break
                Yr, _ = call(out_b.q[rows])
                out_b.q[rows], out_b.force[rows] = Yr["q"], Yr["F"]
                out_b.success[rows], out_b.on_bound[rows] = Yr["norm"] <= thresh, Yr["margin"] >= 0.0
                out_b.iterations[rows] += Yr["iters"].astype(int)
                out_b.energy[rows], out_b.tip[rows] = Yr["E"], Yr["tip"]
                out_b.reduced_hessian[rows] = Yr["R"].reshape(rows.size, m, m).transpose(0, 2, 1)
                rows = rows[~out_b.success[rows]]
            for j in np.flatnonzero(~out_b.success).tolist():
                out_b.status[j] = "Newton_Max_Iterations"
            return out_b
        for j in np.flatnonzero(~out_b.success).tolist():
            # go on from the iterate; failing that, everything again from the start
            out_b.distinct = None             # the kernel's comparison did not see this row's final point
            r = None
            if np.all(np.isfinite(Y["q"][j])) and np.all(np.isfinite(Y["F"][j])):
                r = self._kernel_newton(target, out_b.q[j], out_b.force[j], thresh, 50 - _kernels.SEED_ITER)
                if r is not None:
                    r.iterations += _kernels.SEED_ITER
            set_row(out_b, j, r if r is not None else self.newton_kkt(target, Q0[j]))
        return out_b

    def newton_force(self, force: np.ndarray, q0: np.ndarray, *, tol: float = 1e-12, max_iter: int = 50,
                     max_step: float = 0.5) -> LocalResult:
        """Damped Newton on ``grad E = J^T F`` for a prescribed tip force (any stationary point)."""
        lam, kap, s = self._units()
        if s is not self:
            res = s.newton_force(kap * lam * np.asarray(force, float), q0, tol=tol, max_iter=max_iter,
                                 max_step=max_step)
            return unscale_result(res, lam, kap)
        f = self.functions
        force = np.asarray(force, dtype=float)
        z = np.cumsum(np.asarray(q0, dtype=float))
        return self._newton(f.fast_force, None if f.dense else f.fast_force_res, (self.params, force), z, tol,
                            max_iter, max_step, force)

    def _newton(self, full: Fast, resid: Fast | None, args: tuple, z, tol, max_iter, max_step,
                force_fixed) -> LocalResult:
        """:func:`.newton.damped_newton` with ``full`` (residual and Jacobian) at this solver's tolerance
        (``tol`` times :attr:`scale`); long chains add the residual-only ``resid`` for the line search and
        hold BLAS to one thread."""
        def call(zz):
            return full(zz, *args)

        f = self.functions
        if resid is None:
            return damped_newton(call, full, z, self.limits, tol * self.scale, max_iter, max_step, force_fixed,
                                 n=f.n, dense=f.dense)
        with one_blas_thread():
            return damped_newton(call, full, z, self.limits, tol * self.scale, max_iter, max_step, force_fixed,
                                 n=f.n, dense=f.dense, residual_only=lambda zz: resid(zz, *args))

    def minimize_displacement(self, target: np.ndarray, q0: np.ndarray) -> LocalResult:
        """IPOPT: ``min E(q)`` s.t. ``tip(q) = target``, ``|q| < limits``, from ``q0``."""
        return _ipopt.minimize_displacement(self.functions.nlp_disp, self.params, self.limits, target, q0)

    def minimize_force(self, force: np.ndarray, q0: np.ndarray) -> LocalResult:
        """IPOPT: ``min E(q) - F.tip(q)`` s.t. ``|q| < limits``, from ``q0``."""
        return _ipopt.minimize_force(self.functions.nlp_force, self.params, self.limits, force, q0)

    # ---------------------------------------------------------------- continuation (dense solvers)
    def batch_continue(self, targets: np.ndarray, z0: np.ndarray) -> Continuation:
        """Newton continuation along ``targets`` (N x 2 tip positions) from ``z0 = (phi, F)``
        (:func:`.layout.equilibrium_unknowns`), in compiled code.

        Each point starts from the previous point's solution. Chains with kernels
        (``n <= kernels.KERNEL_MAX``) run ``kernels.CONT_ITER`` damped Newton iterations per point
        and also return the energy, tip and reduced Hessian there; longer dense chains run CasADi's
        undamped ``rootfinder``. Dense solvers only (``n <= DENSE_MAX``).
        """
        lam, kap, s = self._units()
        if s is not self:
            z0 = np.array(z0, dtype=float)
            z0[self.n:] *= kap * lam
            c = s.batch_continue(lam * np.asarray(targets, float), z0)
            return unscale_continuation(c, self.n, lam, kap)
        params = self.params
        kern = self.functions.kernel
        N, n = targets.shape[0], self.n
        Z = np.empty((N, n + 2))
        R = np.empty(N)
        z = np.asarray(z0, dtype=float)
        if kern is None:
            cont, _ = self.functions.batch
            P = np.repeat(params[:, None], BATCH, axis=1)
            for s in range(0, N, BATCH):
                chunk = targets[s:s + BATCH]
                pad = np.vstack([chunk, np.repeat(chunk[-1:], BATCH - chunk.shape[0], axis=0)])
                Zc, Rc = cont(z, pad.T, P)
                Zc, Rc = np.asarray(Zc).T, np.asarray(Rc).ravel()
                k = chunk.shape[0]
                Z[s:s + k], R[s:s + k] = Zc[:k], Rc[:k]
                z = Zc[k - 1]
            return Continuation(Z, R, torque_scale=torque_scale(params, n))
        fast, B, m, layout = kern.continuation, _kernels.BATCH, n - 2, _kernels.point_layout(n)
        Y = np.empty((N, layout.size))
        for s in range(0, N, B):
            chunk = targets[s:s + B]
            k = chunk.shape[0]
            pad = np.vstack([chunk, np.repeat(chunk[-1:], B - k, axis=0)]) if k < B else chunk
            out = fast(z, pad.ravel(), params, 1e-12 * self.scale)
            Z[s:s + k] = out[0].reshape(B, n + 2)[:k]
            Y[s:s + k] = out[1].reshape(B, layout.size)[:k]
            z = Z[s + k - 1]
        y = layout.unpack(Y)
        return Continuation(Z, y["norm"], y["E"], y["tip"], y["R"].reshape(N, m, m).transpose(0, 2, 1),
                            torque_scale(params, n), iterations=np.rint(y["iters"]).astype(int))

    def batch_derivs(self, Q: np.ndarray, Fs: np.ndarray):
        """Energy (N,), Lagrangian Hessian (N, n, n), tip Jacobian (N, 2, n), tip (N, 2) in phi, at the
        configurations ``Q`` (N, n) under the forces ``Fs`` (N, 2). Dense solvers only."""
        _, derivs = self.functions.batch
        n, N = self.n, Q.shape[0]
        E, H, J, T = np.empty(N), np.empty((N, n, n)), np.empty((N, 2, n)), np.empty((N, 2))
        P = np.repeat(self.params[:, None], BATCH, axis=1)
        for s in range(0, N, BATCH):
            k = min(BATCH, N - s)
            phi = np.zeros((n, BATCH))
            Fm = np.zeros((2, BATCH))
            phi[:, :k] = np.cumsum(Q[s:s + k], axis=1).T
            Fm[:, :k] = Fs[s:s + k].T
            e, _, h, j, t = derivs(phi, P, Fm)
            E[s:s + k] = np.asarray(e).ravel()[:k]
            H[s:s + k] = np.asarray(h).reshape(n, BATCH, n).transpose(1, 0, 2)[:k]
            J[s:s + k] = np.asarray(j).reshape(2, BATCH, n).transpose(1, 0, 2)[:k]
            T[s:s + k] = np.asarray(t).T[:k]
        return E, H, J, T

    # ---------------------------------------------------------------- derivatives
    def evaluate(self, q: np.ndarray, force: np.ndarray):
        """Energy, gradient, Lagrangian Hessian ``Hess(E - F.tip)``, tip Jacobian, tip (all in phi).

        The Hessian is dense for dense solvers, else a scipy CSC matrix (tridiagonal).
        """
        fast = self.functions.fast_derivs
        if self.functions.dense:
            out = fast(np.cumsum(q), self.params, force)
            return float(out[0][0]), out[1].copy(), fast.dense(2).copy(), fast.dense(3).copy(), out[4].copy()
        import scipy.sparse as sp_  # long chains only (not imported with the library)

        E, g, hd, ho, J, tip = fast(np.cumsum(q), self.params, force)
        H = sp_.diags([ho, hd, ho], [-1, 0, 1], format="csc")
        return float(E[0]), g.copy(), H, fast.dense(4).copy(), tip.copy()

    def tangent_stiffness(self, q: np.ndarray, force: np.ndarray) -> np.ndarray:
        """``dF/d(tip)`` by implicit differentiation of the KKT system: ``(J H^-1 J^T)^-1``.

        Dense solvers solve the whole KKT system (valid even where ``H`` is singular); banded ones
        use one banded solve. Raises ``numpy.linalg.LinAlgError`` when singular. Computed in the
        solver's units (:mod:`.units`): the KKT matrix mixes torque and length rows, so its condition
        number, tested here, grows as ``k^2`` in the caller's.
        """
        lam, kap, s = self._units()
        if s is not self:                  # dF/d(tip) scales as kap (force / length)
            return s.tangent_stiffness(q, kap * lam * np.asarray(force, float)) / kap
        n, f = self.n, self.functions
        if f.dense:
            fast = f.fast_kkt
            fast(np.concatenate([np.cumsum(q), force]), self.params, np.zeros(2))
            Jz = fast.dense(1)
            if np.linalg.cond(Jz) > 1e13:
                raise np.linalg.LinAlgError("singular KKT matrix")
            rhs = np.zeros((n + 2, 2))
            rhs[n:] = np.eye(2)
            return np.linalg.solve(Jz, rhs)[n:]
        fast = f.fast_derivs
        _, _, hd, ho, _, _ = fast(np.cumsum(q), self.params, force)
        J = fast.dense(4)
        ab = np.zeros((3, n))
        ab[0, 1:] = ho
        ab[1] = hd
        ab[2, :-1] = ho
        S = J @ sla.solve_banded((1, 1), ab, J.T)
        if not np.all(np.isfinite(S)) or np.linalg.cond(S) > 1e13:
            raise np.linalg.LinAlgError("singular KKT matrix")
        return np.linalg.inv(S)

    def kkt(self, z: np.ndarray, target: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The KKT residual (n+2,) and its Jacobian (n+2, n+2, dense) at ``z = (phi, F)``."""
        r, Jz = self.functions.kkt(z, self.params, target)
        return np.asarray(r).ravel(), np.asarray(ca.densify(Jz))

    def kkt_parameter_jacobian(self, q: np.ndarray, force: np.ndarray,
                               target: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """KKT Jacobian w.r.t. ``(phi, F)`` (:func:`.layout.equilibrium_unknowns`) and w.r.t. the parameters
        (``m.params`` order, :func:`.layout.chain_parameters`), at a solution."""
        f = self.functions
        z = np.concatenate([np.cumsum(q), force])
        _, Jz = f.kkt(z, self.params, target)
        Jp = f.kkt_dp(z, self.params, target)
        return np.asarray(ca.densify(Jz)), np.asarray(ca.densify(Jp))


_ZERO2 = np.zeros(2)


@lru_cache(maxsize=None)
def _active(columns: int, k: int) -> np.ndarray:
    """The ``seeds`` kernel's column flags for ``k`` starts (read only: passed without a copy)."""
    a = (np.arange(columns) < k).astype(float)
    a.setflags(write=False)
    return a


def chain_solver(m) -> ChainSolver:
    """This thread's :class:`ChainSolver` for the manipulator ``m`` (its :class:`ChainFunctions` built on
    first use, cached per thread).

    On the hot paths (a control step is tens of microseconds) this is one dictionary look-up: the
    functions keep the last solver made and return it again for the same manipulator object.
    """
    f = chain_functions(m.n)
    s = f.last
    if s is None or s.manipulator is not m:
        s = f.last = ChainSolver(f, m)
    return s
