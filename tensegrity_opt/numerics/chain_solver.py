"""CasADi problem formulations and local solvers (with :mod:`.kernels` and :mod:`.design_solvers`,
the only modules that touch CasADi).

What is solved lives in the public modules (``equilibrium``, ``equilibria``,
``curves`` ...); this module says *how*: symbolic model in absolute link angles
``phi`` (energy Hessian tridiagonal, constraint Hessians diagonal, so cost grows
about linearly in ``n``), IPOPT for minimisation, a damped Newton method on the
KKT system for every stationary point and for warm-started local corrections — for
chains of up to ``kernels.KERNEL_MAX`` segments run as generated C (:mod:`.kernels`).

Every CasADi object is built once per ``(n, problem kind)`` with all numbers
(geometry, stiffness, preloads, loads) passed as parameters, then cached.

Thread safety
-------------
A CasADi ``Function``/``nlpsol`` instance must never be called by two threads at
once (it evaluates in one shared memory slot). The cache here is *per thread*
(``threading.local``): each thread builds and owns its instances, so every
public function of the library may be called from several threads at once.
"""

from __future__ import annotations

import math
import threading
from collections import OrderedDict
from dataclasses import dataclass
from functools import lru_cache

import casadi as ca
import numpy as np
import scipy.linalg as sla
from scipy.linalg.lapack import dgesv as _dgesv

from ..timelimit import check_time
from . import kernels as _kernels
from .expressions import kkt_graph

__all__ = ["LocalResult", "SeedResults", "Continuation", "model", "IPOPT_OPTIONS"]

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


@dataclass
class LocalResult:
    """Outcome of one local solve (numpy only).

    Attributes
    ----------
    q : ndarray (n,)
        Relative joint angles (rad).
    force : ndarray (2,)
        Tip force ``[Fx, Fy]`` holding the equilibrium (force units).
    success : bool
        The solver reports convergence.
    status : str
        The solver's return status: IPOPT's ``return_status`` (``"Solve_Succeeded"``, ...) or
        the damped Newton method's (``"Newton_Converged"``, ``"Newton_Max_Iterations"``,
        ``"Newton_Singular_Jacobian"``, ``"Newton_Line_Search_Failed"``, ``"Newton_Nonfinite"``).
    iterations : int
    on_bound : bool
        A joint sits on its range bound (not an equilibrium of the mechanism).
    energy, tip, reduced_hessian : float, ndarray (2,), ndarray (n-2, n-2) or None
        Filled by the compiled kernels (:mod:`.kernels`) at the returned point: the energy, the
        tip and ``Z^T H Z`` (absolute angles, orthonormal ``Z``), so that classifying the
        point needs no further model evaluation. ``None`` from the other solvers.
    """

    q: np.ndarray
    force: np.ndarray
    success: bool
    status: str
    iterations: int
    on_bound: bool = False
    energy: float | None = None
    tip: np.ndarray | None = None
    reduced_hessian: np.ndarray | None = None


@dataclass
class Continuation:
    """Points of a compiled continuation (:meth:`_Model.batch_continue`), N of them.

    ``Z`` (N, n+2) the iterates ``(phi, F)``, ``residual`` (N,) the KKT residual norm there (large
    where Newton failed); from the kernels also ``energy`` (N,), ``tip`` (N, 2) and
    ``reduced_hessian`` (N, n-2, n-2), else ``None``; ``residual`` is in the solver's units, whose
    torque scale is ``torque_scale``.
    """

    Z: np.ndarray
    residual: np.ndarray
    energy: np.ndarray | None = None
    tip: np.ndarray | None = None
    reduced_hessian: np.ndarray | None = None
    #: ``max k c^2`` in the units ``residual`` is measured in (the solver's, see :meth:`_Model._units`)
    torque_scale: float = 1.0


@dataclass
class SeedResults:
    """Local solves from k starts as arrays (:meth:`_Model.newton_kkt_seeds`; numpy only).

    ``q`` (k, n), ``force`` (k, 2), ``success``/``on_bound`` (k,) bool, ``iterations`` (k,),
    ``status`` (k statuses), and the kernels' ``energy`` (k,), ``tip`` (k, 2) and
    ``reduced_hessian`` (k, n-2, n-2) at each point: NaN in the rows that came from the Python
    Newton method (classify those from the model); ``reduced_hessian`` is ``None`` when no row has
    one (chains without kernels). ``distinct`` (k,) bool when the kernel compared the rows
    (:meth:`_Model.newton_kkt_seeds`), else ``None``.
    """

    q: np.ndarray
    force: np.ndarray
    success: np.ndarray
    on_bound: np.ndarray
    iterations: np.ndarray
    status: list[str]
    energy: np.ndarray
    tip: np.ndarray
    reduced_hessian: np.ndarray | None
    distinct: np.ndarray | None = None

    def result(self, j: int) -> LocalResult:
        """Row ``j`` as a :class:`LocalResult`."""
        known = not np.isnan(self.energy[j])
        return LocalResult(self.q[j], self.force[j], bool(self.success[j]), self.status[j], int(self.iterations[j]),
                           bool(self.on_bound[j]), float(self.energy[j]) if known else None,
                           self.tip[j] if known else None, self.reduced_hessian[j] if known else None)


#: Chains up to this many segments use dense linear algebra; longer ones sparse (O(n)) paths.
DENSE_MAX = 64

#: The Newton methods test one norm of the KKT residual, whose rows are torques (``grad E - J^T F``) and
#: lengths (``tip - target``), against ``1e-12`` times the torque scale ``max(1, k c^2)``. That bounds each
#: part relative to its own scale only while the torque scale ``T`` and the length scale ``L = sum b`` are
#: comparable: a chain with ``max(1, T) / min(L, T)`` above this ratio (slender segments ``a >> b``, very
#: stiff or very soft springs, tiny or huge lengths) is solved in units where both are about 1 (exact
#: powers of two; results are returned in the caller's units). Without it, ``a = 1e6`` accepted the
#: unmoved straight chain as converged 0.1 away from its target (torque scale 1e12, threshold 1).
UNIT_RATIO = 1e3
#: Points per compiled batch (continuation and batched derivatives).
BATCH = 128
#: Further batched calls of the seeds kernel for the starts of a large sample not converged in the
#: first (``newton_kkt_seeds(python_fallback=False)``); each call is ``kernels.SEED_ITER`` iterations.
SAMPLE_ROUNDS = 5


class _Fast:
    """Low-overhead evaluation of a CasADi ``Function`` through ``Function.buffer()``.

    Inputs are copied into preallocated arrays, outputs land in preallocated arrays (their
    nonzeros, column-major); one call costs about a microsecond instead of tens. The
    returned arrays are overwritten by the next call: copy what you keep. Not thread-safe
    (nor is the Function): owned by one thread's model.
    """

    def __init__(self, f: ca.Function) -> None:
        self.f = f
        self.buf, self.trigger = f.buffer()
        self.ins = [np.zeros(f.nnz_in(i)) for i in range(f.n_in())]
        self.outs = [np.zeros(f.nnz_out(i)) for i in range(f.n_out())]
        self._held: list[object] = [None] * f.n_in()
        self.sparsity = [f.sparsity_out(i) for i in range(f.n_out())]
        self.shapes = [(sp.size1(), sp.size2()) for sp in self.sparsity]
        for i, a in enumerate(self.ins):
            self.buf.set_arg(i, memoryview(a))
        for i, a in enumerate(self.outs):
            self.buf.set_res(i, memoryview(a))

    def __call__(self, *args) -> list[np.ndarray]:
        held, ins = self._held, self.ins
        for i in range(len(args)):
            src = args[i]
            if src is held[i]:
                continue                # the same read-only array as last time: already in place
            ins[i][:] = src
            held[i] = src if type(src) is np.ndarray and not src.flags.writeable else None
        self.trigger()
        return self.outs

    def dense(self, i: int) -> np.ndarray:
        """Output ``i`` as a dense 2-D array (it must have been densified)."""
        return self.outs[i].reshape(self.shapes[i], order="F")

    def csc(self, i: int):
        """Output ``i`` as a scipy CSC matrix (a copy)."""
        import scipy.sparse as sp_

        s = self.sparsity[i]
        return sp_.csc_matrix((self.outs[i].copy(), np.asarray(s.row()), np.asarray(s.colind())),
                              shape=(s.size1(), s.size2()))


class _Model:
    """All CasADi functions and solvers for one chain length ``n`` (one thread).

    Short chains (``n <= DENSE_MAX``): one SX graph in absolute angles gives the KKT residual
    and its dense Jacobian, the Hessian and the IPOPT problems. Long chains: the functions
    used by Newton and the classification are MX graphs of whole-vector operations (a few
    dozen nodes whatever ``n``), returning the tridiagonal Hessian as two diagonals; the SX
    graph (IPOPT fallback, parameter sensitivities) is built only when first needed.
    """

    def __init__(self, n: int) -> None:
        self.n = n
        self.dense = n <= DENSE_MAX
        self._sx = None
        self._nlp_disp = None
        self._nlp_force = None
        self._kkt_dp = None
        self._batch = None
        self._kern = None
        if self.dense:
            D = ca.densify
            phi, p, F, q, E, tip, res, z, tgt, gradE, J, H = self._sym
            kkt_jac = ca.blockcat([[H, -J.T], [J, ca.SX(2, 2)]])
            self._kkt_sx = ca.Function("kkt", [z, p, tgt], [res, D(kkt_jac)])
            self.force_res = ca.Function("force_res", [phi, p, F], [gradE - J.T @ F, D(H)])
            self.derivs = ca.Function("derivs", [phi, p, F], [E, gradE, D(H), D(J), tip])
            self._fast_kkt = _Fast(self._kkt_sx)
            self._fast_force = _Fast(self.force_res)
            self._fast_derivs = _Fast(self.derivs)
        else:
            self._build_banded()

    @property
    def _sym(self):
        """The SX graph: (phi, p, F, q, E, tip, KKT residual, z, target, grad E, J, H)."""
        if self._sx is None:
            self._sx = kkt_graph(self.n)
        return self._sx

    @property
    def kernel(self) -> tuple | None:
        """The compiled Newton kernels (:mod:`.kernels`) as ``(Kernels, newton, seeds, continuation)``
        fast wrappers, for ``2 <= n <= kernels.KERNEL_MAX``; else ``None``. Built on first use."""
        if self._kern is None:
            if 2 <= self.n <= _kernels.KERNEL_MAX:
                k = _kernels.build(self.n)
                self._kern = (k, _Fast(k.newton), _Fast(k.seeds), _Fast(k.continuation))
            else:
                self._kern = False
        return self._kern or None

    def _build_banded(self) -> None:
        """MX whole-vector functions for long chains (Newton, classification, stiffness)."""
        n = self.n
        phi, p, F, tgt = ca.MX.sym("phi", n), ca.MX.sym("p", 6 * n), ca.MX.sym("F", 2), ca.MX.sym("t", 2)
        a, b, k1, k2, L10, L20 = (p[i * n:(i + 1) * n] for i in range(6))
        qs = ca.MX.sym("q", n)
        c = ca.sqrt(a * a + b * b)
        beta = ca.atan2(a, b)
        L1 = 2 * c * ca.cos(beta + qs / 2)
        L2 = 2 * c * ca.cos(beta - qs / 2)
        Es = 0.5 * ca.sum1(k1 * (L1 - L10) ** 2 + k2 * (L2 - L20) ** 2)
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
        self.kkt_banded = ca.Function("kkt_banded", [z, p, tgt], [r, hdz, hoz, Jz])
        self.kkt_res_banded = ca.Function("kkt_res_banded", [z, p, tgt], [r])
        self.force_res_banded = ca.Function("force_res_banded", [phi, p, F], [r1])
        self.force_banded = ca.Function("force_banded", [phi, p, F], [r1, hd, ho])
        self.derivs_banded = ca.Function("derivs_banded", [phi, p, F], [E, g, hd, ho, J, tip])
        self._fast_kkt_b = _Fast(self.kkt_banded)
        self._fast_force_b = _Fast(self.force_banded)
        self._fast_kkt_rb = _Fast(self.kkt_res_banded)
        self._fast_force_rb = _Fast(self.force_res_banded)
        self._fast_derivs_b = _Fast(self.derivs_banded)

    @property
    def kkt(self):
        """KKT residual and Jacobian (SX); for long chains built on first use (sparse Jacobian)."""
        if "_kkt_sx" not in self.__dict__:
            phi, p, F, q, E, tip, res, z, tgt, gradE, J, H = self._sym
            self._kkt_sx = ca.Function("kkt", [z, p, tgt], [res, ca.blockcat([[H, -J.T], [J, ca.SX(2, 2)]])])
        return self._kkt_sx

    @property
    def nlp_disp(self):
        """IPOPT: min E s.t. [tip; q] within bounds (built on first use)."""
        if self._nlp_disp is None:
            phi, p, F, q, E, tip, *_ = self._sym
            self._nlp_disp = ca.nlpsol("eq_disp", "ipopt", {"x": phi, "p": p, "f": E, "g": ca.vertcat(tip, q)},
                                       IPOPT_OPTIONS)
        return self._nlp_disp

    @property
    def nlp_force(self):
        """IPOPT: min E - F.tip s.t. q within bounds (built on first use)."""
        if self._nlp_force is None:
            phi, p, F, q, E, tip, *_ = self._sym
            self._nlp_force = ca.nlpsol("eq_force", "ipopt", {"x": phi, "p": ca.vertcat(p, F),
                                                              "f": E - ca.dot(F, tip), "g": q}, IPOPT_OPTIONS)
        return self._nlp_force

    # ---------------------------------------------------------------- batches (short chains)
    def _batch_functions(self):
        if getattr(self, "_batch", None) is None:
            n, N = self.n, BATCH
            phi, p, F, q, E, tip, res, z, tgt, *_ = self._sym
            resf = ca.Function("kkt_res", [z, ca.vertcat(p, tgt)], [res])
            rf = ca.rootfinder("kkt_rf", "newton", resf,
                               {"error_on_fail": False, "abstol": 1e-12, "max_iter": 30})
            zp, pm, tm = ca.MX.sym("z", n + 2), ca.MX.sym("p", 6 * n), ca.MX.sym("t", 2)
            zn = rf(zp, ca.vertcat(pm, tm))
            step = ca.Function("step", [zp, tm, pm], [zn, ca.norm_inf(resf(zn, ca.vertcat(pm, tm)))])
            self._batch = (step.mapaccum("continuation", N), self.derivs.map(N))
        return self._batch

    def batch_continue(self, params: np.ndarray, targets: np.ndarray, z0: np.ndarray) -> "Continuation":
        """Newton continuation along ``targets`` (N x 2 tip positions) from ``z0 = (phi, F)``, in compiled code.

        Each point starts from the previous point's solution. Chains with kernels
        (``n <= kernels.KERNEL_MAX``) run ``kernels.CONT_ITER`` damped Newton iterations per point
        and also return the energy, tip and reduced Hessian there; longer short chains run CasADi's
        undamped ``rootfinder``. Short chains only (``n <= DENSE_MAX``).
        """
        lam, kap, scaled = self._units(params)
        if scaled is not params:
            z0 = np.array(z0, dtype=float)
            z0[self.n:] *= kap * lam
            c = self.batch_continue(scaled, lam * np.asarray(targets, float), z0)
            c.Z[:, self.n:] /= kap * lam
            return Continuation(c.Z, c.residual, None if c.energy is None else c.energy / (kap * lam * lam),
                                None if c.tip is None else c.tip / lam,
                                None if c.reduced_hessian is None else c.reduced_hessian / (kap * lam * lam),
                                c.torque_scale)
        kern = self.kernel
        N, n = targets.shape[0], self.n
        Z = np.empty((N, n + 2))
        R = np.empty(N)
        z = np.asarray(z0, dtype=float)
        if kern is None:
            cont, _ = self._batch_functions()
            P = np.repeat(params[:, None], BATCH, axis=1)
            for s in range(0, N, BATCH):
                chunk = targets[s:s + BATCH]
                pad = np.vstack([chunk, np.repeat(chunk[-1:], BATCH - chunk.shape[0], axis=0)])
                Zc, Rc = cont(z, pad.T, P)
                Zc, Rc = np.asarray(Zc).T, np.asarray(Rc).ravel()
                k = chunk.shape[0]
                Z[s:s + k], R[s:s + k] = Zc[:k], Rc[:k]
                z = Zc[k - 1]
            return Continuation(Z, R, torque_scale=_torque_scale(params, n))
        self._set_scale(params)
        fast, B, m = kern[3], _kernels.BATCH, n - 2
        Y = np.empty((N, 5 + m * m))
        for s in range(0, N, B):
            chunk = targets[s:s + B]
            k = chunk.shape[0]
            pad = np.vstack([chunk, np.repeat(chunk[-1:], B - k, axis=0)]) if k < B else chunk
            out = fast(z, pad.ravel(), params, 1e-12 * self._scale)
            Z[s:s + k] = out[0].reshape(B, n + 2)[:k]
            Y[s:s + k] = out[1].reshape(B, 5 + m * m)[:k]
            z = Z[s + k - 1]
        return Continuation(Z, Y[:, 0], Y[:, 2], Y[:, 3:5], Y[:, 5:].reshape(N, m, m).transpose(0, 2, 1),
                            _torque_scale(params, n))

    def batch_derivs(self, params: np.ndarray, Q: np.ndarray, Fs: np.ndarray):
        """Energy (N,), Lagrangian Hessian (N, n, n), tip Jacobian (N, 2, n), tip (N, 2) in phi."""
        _, derivs = self._batch_functions()
        n, N = self.n, Q.shape[0]
        E, H, J, T = np.empty(N), np.empty((N, n, n)), np.empty((N, 2, n)), np.empty((N, 2))
        P = np.repeat(params[:, None], BATCH, axis=1)
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

    @property
    def kkt_dp(self):
        """d(KKT residual)/d(parameters), for sensitivities (built on first use)."""
        if self._kkt_dp is None:
            phi, p, F, q, E, tip, res, z, tgt, *_ = self._sym
            self._kkt_dp = ca.Function("kkt_dp", [z, p, tgt], [ca.jacobian(res, p)])
        return self._kkt_dp

    # ---------------------------------------------------------------- helpers
    @staticmethod
    def phi(q: np.ndarray) -> np.ndarray:
        return np.cumsum(q)

    @staticmethod
    def q(phi: np.ndarray) -> np.ndarray:
        return np.diff(np.concatenate([[0.0], phi]))

    def _on_bound(self, q: np.ndarray, limits: np.ndarray) -> bool:
        return bool(np.any(np.abs(q) >= limits * (1.0 - 2.0 * RANGE_SHRINK)))

    # ---------------------------------------------------------------- IPOPT
    def minimize_displacement(self, params: np.ndarray, limits: np.ndarray, target: np.ndarray,
                              q0: np.ndarray) -> LocalResult:
        """IPOPT: ``min E(q)`` s.t. ``tip(q) = target``, ``|q| < limits``, from ``q0``."""
        check_time("the equilibrium search")
        lim = limits * (1.0 - RANGE_SHRINK)
        q0 = np.clip(q0, -lim * 0.999, lim * 0.999)
        sol = self.nlp_disp(x0=self.phi(q0), p=params,
                            lbg=np.concatenate([target, -lim]), ubg=np.concatenate([target, lim]))
        st = self.nlp_disp.stats()
        phi = np.asarray(sol["x"]).ravel()
        q = self.q(phi)
        F = -np.asarray(sol["lam_g"]).ravel()[:2]   # CasADi's lam_g is -F for this form
        return LocalResult(q, F, bool(st["success"]), str(st["return_status"]),
                           int(st.get("iter_count", -1)), self._on_bound(q, limits))

    def minimize_force(self, params: np.ndarray, limits: np.ndarray, force: np.ndarray,
                       q0: np.ndarray) -> LocalResult:
        """IPOPT: ``min E(q) - F.tip(q)`` s.t. ``|q| < limits``, from ``q0``."""
        check_time("the equilibrium search")
        lim = limits * (1.0 - RANGE_SHRINK)
        q0 = np.clip(q0, -lim * 0.999, lim * 0.999)
        sol = self.nlp_force(x0=self.phi(q0), p=np.concatenate([params, force]), lbg=-lim, ubg=lim)
        st = self.nlp_force.stats()
        q = self.q(np.asarray(sol["x"]).ravel())
        return LocalResult(q, np.asarray(force, dtype=float).copy(), bool(st["success"]),
                           str(st["return_status"]), int(st.get("iter_count", -1)), self._on_bound(q, limits))

    # ---------------------------------------------------------------- Newton
    def _units(self, params: np.ndarray) -> tuple[float, float, np.ndarray]:
        """``(lam, kap, params')``: the units the Newton methods work in (see :data:`UNIT_RATIO`).

        Lengths are multiplied by ``lam`` and stiffnesses by ``kap`` (powers of two, so the change is exact),
        chosen so that both the length scale ``sum b`` and the torque scale ``k c^2`` are about 1. Identity
        (``1, 1, params``) when ``max(1, T) / min(L, T) <= UNIT_RATIO`` (torque scale ``T``, length
        scale ``L``): in particular for every chain with ``T >= 1`` and ``T <= UNIT_RATIO L``; long light
        chains (``L >> T >= 1``) are not rescaled (their tip rows meet a threshold above roundoff).
        """
        if params is getattr(self, "_units_params", None):
            return self._units_val
        if params is getattr(self, "_units_scaled", None):     # the rescaled vector itself (nested calls)
            return 1.0, 1.0, params
        n = self.n
        torque = _torque_scale(params, n)
        length = float(np.sum(params[n:2 * n]))
        if max(1.0, torque) / min(length, torque) <= UNIT_RATIO:
            val = (1.0, 1.0, params)
        else:
            lam = 2.0 ** -round(math.log2(length))
            kap = 2.0 ** -round(math.log2(torque * lam * lam))
            scaled = np.array(params, dtype=float)
            scaled[:2 * n] *= lam
            scaled[2 * n:4 * n] *= kap
            scaled[4 * n:6 * n] *= lam
            scaled.setflags(write=False)
            val = (lam, kap, scaled)
            self._units_scaled = scaled
        self._units_params, self._units_val = params, val
        return val

    def _set_scale(self, params: np.ndarray) -> None:
        # Residuals are torques: scale the stopping test by k * c^2 of the stiffest segment. The test is
        # on the 2-norm of n + 2 entries, whose roundoff floor grows as sqrt(n): beyond DENSE_MAX
        # segments it is scaled by sqrt(n / DENSE_MAX), the same accuracy per entry as at 64. (Measured
        # at n = 10000: Newton reached 6e-11 in 4 iterations, then spent 4 more crawling to the
        # unscaled 2e-12 at the roundoff floor, about half the solve's time.)
        if params is getattr(self, "_scale_params", None):
            return
        self._scale_params = params
        n = self.n
        self._scale = max(1.0, _torque_scale(params, n)) * max(1.0, math.sqrt(n / DENSE_MAX))

    def newton_kkt(self, params: np.ndarray, limits: np.ndarray, target: np.ndarray, q0: np.ndarray,
                   F0: np.ndarray | None = None, *, tol: float = 1e-12, max_iter: int = 50,
                   max_step: float = 0.5) -> LocalResult:
        """Damped Newton on the KKT system of the displacement problem (any stationary point).

        Converged when the residual's 2-norm is at most ``tol`` times the torque scale ``k c^2`` of the
        stiffest segment (times ``sqrt(n / DENSE_MAX)`` for longer chains: the norm's roundoff floor
        grows as ``sqrt(n)``). ``F0`` defaults to the least-squares force of eq. (8) at ``q0``.
        Chains with compiled kernels (:mod:`.kernels`) run the method there first (same step rule),
        and here only when it did not converge.
        """
        lam, kap, scaled = self._units(params)
        if scaled is not params:
            res = self.newton_kkt(scaled, limits, lam * np.asarray(target, float), q0,
                                  None if F0 is None else kap * lam * np.asarray(F0, float), tol=tol,
                                  max_iter=max_iter, max_step=max_step)
            return _unscale_result(res, lam, kap)
        self._set_scale(params)
        if max_step == _kernels.MAX_STEP and self.kernel is not None:
            res = self._kernel_newton(params, limits, target, q0, F0, tol * self._scale, max_iter)
            if res is not None:
                return res
        phi = self.phi(np.asarray(q0, dtype=float))
        if F0 is None:
            # eq. (8): F = (J J^T)^-1 J grad E, a 2 x 2 system solved by hand (a start only)
            if self.dense:
                out = self._fast_derivs(phi, params, np.zeros(2))
                g, J = out[1], self._fast_derivs.dense(3)
            else:
                out = self._fast_derivs_b(phi, params, np.zeros(2))
                g, J = out[1], self._fast_derivs_b.dense(4)
            A = J @ J.T
            bvec = J @ g
            det = A[0, 0] * A[1, 1] - A[0, 1] * A[1, 0]
            if abs(det) > 1e-14 * max(1.0, A[0, 0] * A[1, 1]):
                F0 = np.array([A[1, 1] * bvec[0] - A[0, 1] * bvec[1], A[0, 0] * bvec[1] - A[1, 0] * bvec[0]]) / det
            else:
                F0 = np.array([0.0, bvec[1] / A[1, 1] if A[1, 1] > 0 else 0.0])
        z = np.concatenate([phi, np.asarray(F0, dtype=float)])
        return self._dispatch(self._fast_kkt if self.dense else self._fast_kkt_b,
                              None if self.dense else self._fast_kkt_rb, (params, target), z, limits, tol,
                              max_iter, max_step, None)

    def _kernel_newton(self, params, limits, target, q0, F0, thresh, max_iter) -> LocalResult | None:
        """The compiled damped Newton method from ``(q0, F0)``; ``None`` when it did not converge."""
        fast = self.kernel[1]
        n = self.n
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

    def newton_kkt_many(self, params: np.ndarray, limits: np.ndarray, target: np.ndarray,
                        starts: list[np.ndarray]) -> list[LocalResult]:
        """:meth:`newton_kkt` from each start (force from eq. (8)); :meth:`newton_kkt_seeds` as objects."""
        batch = self.newton_kkt_seeds(params, limits, target, starts)
        return [batch.result(j) for j in range(len(batch.status))]

    def newton_kkt_seeds(self, params: np.ndarray, limits: np.ndarray, target: np.ndarray,
                         starts: np.ndarray | list[np.ndarray], same: float = 0.0, *,
                         python_fallback: bool = True) -> SeedResults:
        """:meth:`newton_kkt` from each start (force from eq. (8)); the seeds of a global search.

        With kernels, up to ``kernels.seed_columns(n)`` starts per compiled call (``kernels.SEED_ITER``
        iterations); a start not converged there goes on from its iterate with the ``newton`` kernel and,
        if that fails too, is run again from the start by :meth:`newton_kkt` (down to the Python method).
        ``same`` > 0 (rad): the result's ``distinct`` marks the converged rows inside the range whose angles
        differ by at least ``same`` from every earlier such row's, when one kernel call settled every start
        (else ``distinct`` is ``None``: compare the rows yourself). ``python_fallback=False`` (large samples
        of starts, where a few failures cost nothing): the starts not converged in the first call go on
        from their iterates in up to ``SAMPLE_ROUNDS`` more batched calls of the same kernel (instead of one
        ``newton`` kernel call each), and what is still not converged is left so (no Python method).
        """
        lam, kap, scaled = self._units(params)
        if scaled is not params:
            out = self.newton_kkt_seeds(scaled, limits, lam * np.asarray(target, float), starts, same,
                                        python_fallback=python_fallback)
            return _unscale_seeds(out, lam, kap)
        n, m = self.n, self.n - 2
        Q0 = np.asarray(starts, dtype=float).reshape(-1, n)
        k_all = Q0.shape[0]
        kern = self.kernel
        if kern is None or k_all == 0:
            return _seed_results([self.newton_kkt(params, limits, target, q) for q in Q0], n)
        self._set_scale(params)
        thresh = 1e-12 * self._scale
        fast, S, at = kern[2], _kernels.seed_columns(n), _kernels.seed_row(n)

        def call(Q: np.ndarray) -> tuple[np.ndarray, int]:
            k = Q.shape[0]
            chunks = -(-k // S)
            src = np.zeros((chunks * S, n))
            src[:k] = Q
            # a start's outputs are one column of the kernel's, one row here (copied: the buffer is reused)
            parts = [fast(src[c * S:(c + 1) * S].ravel(), _active(S, min(S, k - c * S)), params, target, thresh,
                          same)[0].reshape(S, -1).copy() for c in range(chunks)]
            return (parts[0] if chunks == 1 else np.vstack(parts))[:k], chunks

        Y, chunks = call(Q0)
        # R is Z^T H Z (symmetric): the kernel's column-major nonzeros, transposed back
        out_b = SeedResults(Y[:, at["q"]], Y[:, at["F"]], Y[:, at["norm"]] <= thresh, Y[:, at["margin"]] >= 0.0,
                            Y[:, at["iters"]].astype(int), ["Newton_Converged"] * k_all, Y[:, at["E"]],
                            Y[:, at["tip"]], Y[:, at["R"]].reshape(k_all, m, m).transpose(0, 2, 1),
                            Y[:, at["distinct"]] > 0.5 if chunks == 1 and same > 0.0 else None)
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
                out_b.q[rows], out_b.force[rows] = Yr[:, at["q"]], Yr[:, at["F"]]
                out_b.success[rows], out_b.on_bound[rows] = Yr[:, at["norm"]] <= thresh, Yr[:, at["margin"]] >= 0.0
                out_b.iterations[rows] += Yr[:, at["iters"]].astype(int)
                out_b.energy[rows], out_b.tip[rows] = Yr[:, at["E"]], Yr[:, at["tip"]]
                out_b.reduced_hessian[rows] = Yr[:, at["R"]].reshape(rows.size, m, m).transpose(0, 2, 1)
                rows = rows[~out_b.success[rows]]
            for j in np.flatnonzero(~out_b.success).tolist():
                out_b.status[j] = "Newton_Max_Iterations"
            return out_b
        for j in np.flatnonzero(~out_b.success).tolist():
            # go on from the iterate; failing that, everything again from the start
            out_b.distinct = None             # the kernel's comparison did not see this row's final point
            r = None
            if np.all(np.isfinite(Y[j, :n + 2])):
                r = self._kernel_newton(params, limits, target, out_b.q[j], out_b.force[j], thresh,
                                        50 - _kernels.SEED_ITER)
                if r is not None:
                    r.iterations += _kernels.SEED_ITER
            _set_row(out_b, j, r if r is not None else self.newton_kkt(params, limits, target, Q0[j]))
        return out_b

    def newton_force(self, params: np.ndarray, limits: np.ndarray, force: np.ndarray, q0: np.ndarray, *,
                     tol: float = 1e-12, max_iter: int = 50, max_step: float = 0.5) -> LocalResult:
        """Damped Newton on ``grad E = J^T F`` for a prescribed force (any stationary point)."""
        lam, kap, scaled = self._units(params)
        if scaled is not params:
            res = self.newton_force(scaled, limits, kap * lam * np.asarray(force, float), q0, tol=tol,
                                    max_iter=max_iter, max_step=max_step)
            return _unscale_result(res, lam, kap)
        self._set_scale(params)
        force = np.asarray(force, dtype=float)
        z = self.phi(np.asarray(q0, dtype=float))
        return self._dispatch(self._fast_force if self.dense else self._fast_force_b,
                              None if self.dense else self._fast_force_rb, (params, force), z, limits, tol,
                              max_iter, max_step, force)

    def _dispatch(self, full: _Fast, resid: _Fast | None, args: tuple, z, limits, tol, max_iter, max_step,
                  force_fixed) -> LocalResult:
        """Newton with ``full`` (residual and Jacobian); long chains add the residual-only ``resid`` for
        the line search and hold BLAS to one thread."""
        def call(zz):
            return full(zz, *args)

        if resid is None:
            return self._newton(call, full, z, limits, tol, max_iter, max_step, force_fixed)
        with _one_blas_thread():
            return self._newton(call, full, z, limits, tol, max_iter, max_step, force_fixed,
                                residual_only=lambda zz: resid(zz, *args))

    def _newton(self, call, fast: _Fast, z, limits, tol, max_iter, max_step, force_fixed,
                residual_only=None) -> LocalResult:
        """Damped Newton with a backtracking line search on ``|r|``.

        ``call(z)`` evaluates the residual and its Jacobian into ``fast``'s buffers;
        ``residual_only(z)`` (long chains) the residual alone, for the trial points of the
        line search; the Jacobian is then evaluated once at each accepted point.
        """
        trial = residual_only or call
        n = self.n
        thresh = tol * self._scale
        r = call(z)[0].copy()
        norm = float(np.sqrt(r @ r))
        status = "Newton_Max_Iterations"
        it = 0
        while True:
            if not np.isfinite(norm):
                status = "Newton_Nonfinite"
                break
            if norm <= thresh:
                status = "Newton_Converged"
                break
            if it >= max_iter:
                break
            it += 1
            try:
                if self.dense:
                    # LAPACK's dgesv directly: the same LU solve as numpy.linalg.solve at a fifth of
                    # the Python overhead, which dominates for these 6 x 6 systems
                    _, _, step, info = _dgesv(fast.dense(1), -r)
                    if info != 0:
                        raise np.linalg.LinAlgError("singular KKT matrix")
                else:
                    step = _banded_step(fast.outs, r, n, force_fixed is None)
            except (np.linalg.LinAlgError, ValueError, RuntimeError):
                status = "Newton_Singular_Jacobian"
                break
            if not np.all(np.isfinite(step)):
                status = "Newton_Singular_Jacobian"
                break
            dphi = float(np.abs(step[:n]).max())
            alpha = min(1.0, max_step / dphi) if dphi > 0 else 1.0
            accepted = False
            while alpha > 1e-6:
                z_new = z + alpha * step
                r_new = trial(z_new)[0]
                n_new = float(np.sqrt(r_new @ r_new))
                if np.isfinite(n_new) and n_new <= (1.0 - 1e-4 * alpha) * norm:
                    accepted = True
                    break
                alpha *= 0.5
            if not accepted:
                # at the roundoff floor no step decreases the residual any more
                status = "Newton_Converged" if norm <= 1e3 * thresh else "Newton_Line_Search_Failed"
                break
            z, r, norm = z_new, r_new.copy(), n_new
            if residual_only is not None:
                call(z)            # the Jacobian at the accepted point, for the next step
        q = self.q(z[:n])
        F = z[n:n + 2].copy() if force_fixed is None else force_fixed.copy()
        return LocalResult(q, F, status == "Newton_Converged", status, it, bool(np.any(np.abs(q) >= limits)))

    # ---------------------------------------------------------------- derivatives
    def evaluate(self, params: np.ndarray, q: np.ndarray, force: np.ndarray):
        """Energy, gradient, Lagrangian Hessian ``Hess(E - F.tip)``, tip Jacobian, tip (all in phi).

        The Hessian is dense for ``n <= DENSE_MAX``, else a scipy CSC matrix (tridiagonal).
        """
        if self.dense:
            fast = self._fast_derivs
            out = fast(self.phi(q), params, force)
            return float(out[0][0]), out[1].copy(), fast.dense(2).copy(), fast.dense(3).copy(), out[4].copy()
        import scipy.sparse as sp_

        fast = self._fast_derivs_b
        E, g, hd, ho, J, tip = fast(self.phi(q), params, force)
        H = sp_.diags([ho, hd, ho], [-1, 0, 1], format="csc")
        return float(E[0]), g.copy(), H, fast.dense(4).copy(), tip.copy()

    def tangent_stiffness(self, params: np.ndarray, q: np.ndarray, force: np.ndarray) -> np.ndarray:
        """``dF/d(tip)`` by implicit differentiation of the KKT system: ``(J H^-1 J^T)^-1``.

        Dense chains solve the whole KKT system (valid even where ``H`` is singular);
        long chains use one banded solve. Raises ``numpy.linalg.LinAlgError`` when singular.
        Computed in the solver's units (:meth:`_units`): the KKT matrix mixes torque and length rows,
        so its condition number, tested here, grows as ``k^2`` in the caller's.
        """
        lam, kap, scaled = self._units(params)
        if scaled is not params:           # dF/d(tip) scales as kap (force / length)
            return self.tangent_stiffness(scaled, q, kap * lam * np.asarray(force, float)) / kap
        n = self.n
        if self.dense:
            fast = self._fast_kkt
            fast(np.concatenate([self.phi(q), force]), params, np.zeros(2))
            Jz = fast.dense(1)
            if np.linalg.cond(Jz) > 1e13:
                raise np.linalg.LinAlgError("singular KKT matrix")
            rhs = np.zeros((n + 2, 2))
            rhs[n:] = np.eye(2)
            return np.linalg.solve(Jz, rhs)[n:]
        fast = self._fast_derivs_b
        _, _, hd, ho, _, _ = fast(self.phi(q), params, force)
        J = fast.dense(4)
        ab = np.zeros((3, n))
        ab[0, 1:] = ho
        ab[1] = hd
        ab[2, :-1] = ho
        S = J @ sla.solve_banded((1, 1), ab, J.T)
        if not np.all(np.isfinite(S)) or np.linalg.cond(S) > 1e13:
            raise np.linalg.LinAlgError("singular KKT matrix")
        return np.linalg.inv(S)

    def kkt_parameter_jacobian(self, params: np.ndarray, q: np.ndarray, force: np.ndarray,
                               target: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """KKT Jacobian w.r.t. ``(phi, F)`` and w.r.t. the parameters, at a solution."""
        z = np.concatenate([self.phi(q), force])
        _, Jz = self.kkt(z, params, target)
        Jp = self.kkt_dp(z, params, target)
        return np.asarray(ca.densify(Jz)), np.asarray(ca.densify(Jp))


_ZERO2 = np.zeros(2)


@lru_cache(maxsize=None)
def _active(columns: int, k: int) -> np.ndarray:
    """The ``seeds`` kernel's column flags for ``k`` starts (read only: passed without a copy)."""
    a = (np.arange(columns) < k).astype(float)
    a.setflags(write=False)
    return a


def _torque_scale(params: np.ndarray, n: int) -> float:
    """``max k c^2`` of the parameter vector ``[a, b, k1, k2, ...]`` (``Manipulator.torque_scale``)."""
    a, b, k1, k2 = (params[i * n:(i + 1) * n] for i in range(4))
    return float(np.max(np.maximum(k1, k2) * (a * a + b * b)))


def _unscale_result(r: LocalResult, lam: float, kap: float) -> LocalResult:
    """A result of the rescaled problem (:meth:`_Model._units`) in the caller's units."""
    e = kap * lam * lam
    return LocalResult(r.q, r.force / (kap * lam), r.success, r.status, r.iterations, r.on_bound,
                       None if r.energy is None else r.energy / e, None if r.tip is None else r.tip / lam,
                       None if r.reduced_hessian is None else r.reduced_hessian / e)


def _unscale_seeds(out: SeedResults, lam: float, kap: float) -> SeedResults:
    e = kap * lam * lam
    out.force /= kap * lam
    out.energy /= e
    out.tip /= lam
    if out.reduced_hessian is not None:
        out.reduced_hessian /= e
    return out


def _seed_results(results: list[LocalResult], n: int) -> SeedResults:
    """Single results as :class:`SeedResults`; ``reduced_hessian`` only when some result has one (a long
    chain's would be (k, n-2, n-2): never allocated for it)."""
    k, m = len(results), n - 2
    with_r = any(r.reduced_hessian is not None for r in results)
    out = SeedResults(np.empty((k, n)), np.empty((k, 2)), np.zeros(k, bool), np.zeros(k, bool), np.zeros(k, int),
                      [""] * k, np.empty(k), np.empty((k, 2)), np.empty((k, m, m)) if with_r else None)
    for j, r in enumerate(results):
        _set_row(out, j, r)
    return out


def _set_row(out: SeedResults, j: int, r: LocalResult) -> None:
    out.q[j], out.force[j] = r.q, r.force
    out.success[j], out.on_bound[j], out.iterations[j], out.status[j] = r.success, r.on_bound, r.iterations, r.status
    if r.energy is None or out.reduced_hessian is None:
        out.energy[j], out.tip[j] = np.nan, np.nan
        if out.reduced_hessian is not None:
            out.reduced_hessian[j] = np.nan
    else:
        out.energy[j], out.tip[j], out.reduced_hessian[j] = r.energy, r.tip, r.reduced_hessian


_blas = None


def _one_blas_thread():
    """BLAS limited to one thread (threadpoolctl) for the O(n) loops of long chains.

    Their vectors are long enough for OpenBLAS to start helper threads on dot products and
    matrix-vector products that take microseconds; the helpers then spin, doubling the CPU
    time and the wall time at n = 10000 (measured: 383 ms -> 222 ms for one solve).
    """
    global _blas
    if _blas is None:
        from threadpoolctl import ThreadpoolController

        _blas = ThreadpoolController()
    return _blas.limit(limits=1, user_api="blas")


def _banded_step(outs: list[np.ndarray], r: np.ndarray, n: int, kkt: bool) -> np.ndarray:
    """Newton step from a tridiagonal ``H`` (+ the 2 x n ``J`` of the KKT system), O(n)."""
    hd, ho = outs[1], outs[2]
    ab = np.zeros((3, n))
    ab[0, 1:] = ho
    ab[1] = hd
    ab[2, :-1] = ho
    if not kkt:
        return sla.solve_banded((1, 1), ab, -r, check_finite=False)
    J = outs[3].reshape((2, n), order="F")
    X = sla.solve_banded((1, 1), ab, np.column_stack([-r[:n], J.T]), check_finite=False)
    a, W = X[:, 0], X[:, 1:]
    dF = np.linalg.solve(J @ W, -r[n:] - J @ a)
    return np.concatenate([a + W @ dF, dF])


_local = threading.local()

#: Models kept per thread (least recently used evicted): each costs ~1-2 MB for short chains.
CACHE_SIZE = 16


def model(n: int) -> _Model:
    """The cached CasADi model for ``n`` segments, owned by the calling thread (LRU, ``CACHE_SIZE``)."""
    cache = getattr(_local, "cache", None)
    if cache is None:
        cache = _local.cache = OrderedDict()
    m = cache.get(n)
    if m is None:
        m = cache[n] = _Model(n)
        while len(cache) > CACHE_SIZE:
            cache.popitem(last=False)
    else:
        cache.move_to_end(n)
    return m
