"""CasADi problem formulations and local solvers (the only module that touches CasADi).

What is solved lives in the public modules (``equilibrium``, ``equilibria``,
``curves`` ...); this module says *how*: symbolic model in absolute link angles
``phi`` (energy Hessian tridiagonal, constraint Hessians diagonal, so cost grows
about linearly in ``n``), IPOPT for minimisation, a damped Newton method on the
KKT system for every stationary point and for warm-started local corrections.

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

import threading
from dataclasses import dataclass

import casadi as ca
import numpy as np
import scipy.linalg as sla
import scipy.sparse.linalg as spla

__all__ = ["LocalResult", "model", "IPOPT_OPTIONS"]

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
        The solver's return status (IPOPT's ``return_status`` or the Newton status).
    iterations : int
    on_bound : bool
        A joint sits on its range bound (not an equilibrium of the mechanism).
    """

    q: np.ndarray
    force: np.ndarray
    success: bool
    status: str
    iterations: int
    on_bound: bool = False


def _q_of_phi(phi):
    return phi - ca.vertcat(0, phi[:-1])


class _Model:
    """All CasADi functions and solvers for one chain length ``n`` (one thread)."""

    def __init__(self, n: int) -> None:
        self.n = n
        phi = ca.SX.sym("phi", n)
        p = ca.SX.sym("p", 6 * n)
        F = ca.SX.sym("F", 2)
        a, b, k1, k2, L10, L20 = (p[i * n:(i + 1) * n] for i in range(6))
        q = _q_of_phi(phi)
        c = ca.sqrt(a * a + b * b)
        beta = ca.atan2(a, b)
        L1 = 2 * c * ca.cos(beta + q / 2)
        L2 = 2 * c * ca.cos(beta - q / 2)
        E = 0.5 * ca.sum1(k1 * (L1 - L10) ** 2 + k2 * (L2 - L20) ** 2)
        links = b + ca.vertcat(b[1:], 0) if n > 1 else b
        tip = ca.vertcat(b[0] + ca.dot(links, ca.cos(phi)), ca.dot(links, ca.sin(phi)))
        J = ca.jacobian(tip, phi)
        gradE = ca.gradient(E, phi)
        lag = E - ca.dot(F, tip)
        H = ca.hessian(lag, phi)[0]
        tgt = ca.SX.sym("target", 2)

        # KKT of min E s.t. tip = target:  grad E - J^T F = 0, tip - target = 0.
        # Its Jacobian [[H, -J^T], [J, 0]] is assembled from blocks: asking CasADi for
        # jacobian(res, z) colours a matrix with a dense row and a dense column and costs O(n^2).
        res = ca.vertcat(gradE - J.T @ F, tip - tgt)
        z = ca.vertcat(phi, F)
        kkt_jac = ca.blockcat([[H, -J.T], [J, ca.SX(2, 2)]])
        self.kkt = ca.Function("kkt", [z, p, tgt], [res, kkt_jac])
        # Force control: grad (E - F.tip) = 0 in phi, Jacobian H.
        resf = gradE - J.T @ F
        self.force_res = ca.Function("force_res", [phi, p, F], [resf, H])
        self.derivs = ca.Function("derivs", [phi, p, F], [E, gradE, H, J, tip])
        # d(KKT residual)/d(parameters): for sensitivities of equilibria.
        self.kkt_dp = ca.Function("kkt_dp", [z, p, tgt], [ca.jacobian(res, p)])

        g = ca.vertcat(tip, q)
        self.nlp_disp = ca.nlpsol("eq_disp", "ipopt", {"x": phi, "p": p, "f": E, "g": g}, IPOPT_OPTIONS)
        pf = ca.vertcat(p, F)
        self.nlp_force = ca.nlpsol("eq_force", "ipopt",
                                   {"x": phi, "p": pf, "f": E - ca.dot(F, tip), "g": q}, IPOPT_OPTIONS)

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
        lim = limits * (1.0 - RANGE_SHRINK)
        q0 = np.clip(q0, -lim * 0.999, lim * 0.999)
        sol = self.nlp_force(x0=self.phi(q0), p=np.concatenate([params, force]), lbg=-lim, ubg=lim)
        st = self.nlp_force.stats()
        q = self.q(np.asarray(sol["x"]).ravel())
        return LocalResult(q, np.asarray(force, dtype=float).copy(), bool(st["success"]),
                           str(st["return_status"]), int(st.get("iter_count", -1)), self._on_bound(q, limits))

    # ---------------------------------------------------------------- Newton
    def _set_scale(self, params: np.ndarray) -> None:
        # Residuals are torques: scale the stopping test by k * c^2 of the stiffest segment.
        n = self.n
        a, b, k1, k2 = (params[i * n:(i + 1) * n] for i in range(4))
        self._scale = max(1.0, float(np.max(np.maximum(k1, k2) * (a * a + b * b))))

    def newton_kkt(self, params: np.ndarray, limits: np.ndarray, target: np.ndarray, q0: np.ndarray,
                   F0: np.ndarray | None = None, *, tol: float = 1e-12, max_iter: int = 50,
                   max_step: float = 0.5) -> LocalResult:
        """Damped Newton on the KKT system of the displacement problem (any stationary point).

        ``F0`` defaults to the least-squares force of eq. (8) at ``q0``.
        """
        self._set_scale(params)
        phi = self.phi(np.asarray(q0, dtype=float))
        if F0 is None:
            _, g, _, J, _ = self.derivs(phi, params, np.zeros(2))
            F0 = np.linalg.lstsq(np.asarray(J).T, np.asarray(g).ravel(), rcond=None)[0]
        z = np.concatenate([phi, np.asarray(F0, dtype=float)])
        return self._newton(lambda zz: self.kkt(zz, params, target), z, self.n, limits, tol, max_iter,
                            max_step, force_fixed=None)

    def newton_force(self, params: np.ndarray, limits: np.ndarray, force: np.ndarray, q0: np.ndarray, *,
                     tol: float = 1e-12, max_iter: int = 50, max_step: float = 0.5) -> LocalResult:
        """Damped Newton on ``grad E = J^T F`` for a prescribed force (any stationary point)."""
        self._set_scale(params)
        force = np.asarray(force, dtype=float)
        z = self.phi(np.asarray(q0, dtype=float))
        return self._newton(lambda zz: self.force_res(zz, params, force), z, self.n, limits, tol, max_iter,
                            max_step, force_fixed=force)

    def _newton(self, fun, z, n, limits, tol, max_iter, max_step, force_fixed) -> LocalResult:
        def residual(zz):
            r, Jr = fun(zz)
            return np.asarray(r).ravel(), Jr

        r, Jr = residual(z)
        norm = float(np.linalg.norm(r))
        status = "max_iter"
        it = 0
        scale = self._scale
        for it in range(1, max_iter + 1):
            if not np.isfinite(norm):
                status = "nonfinite"
                break
            if norm <= tol * scale:
                status = "converged"
                it -= 1
                break
            try:
                if n > 64:
                    step = spla.spsolve(Jr.sparse().tocsc(), -r)
                else:
                    step = sla.solve(np.asarray(Jr), -r, check_finite=True)
            except (sla.LinAlgError, ValueError, RuntimeError):
                status = "singular_jacobian"
                break
            if not np.all(np.isfinite(step)):
                status = "singular_jacobian"
                break
            dphi = np.abs(step[:n]).max()
            alpha = min(1.0, max_step / dphi) if dphi > 0 else 1.0
            accepted = False
            while alpha > 1e-6:
                z_new = z + alpha * step
                r_new, J_new = residual(z_new)
                n_new = float(np.linalg.norm(r_new))
                if np.isfinite(n_new) and n_new <= (1.0 - 1e-4 * alpha) * norm:
                    accepted = True
                    break
                alpha *= 0.5
            if not accepted:
                # Accept a full step once residual is tiny (roundoff floor).
                if norm <= 1e3 * tol * scale:
                    status = "converged"
                else:
                    status = "line_search_failed"
                break
            z, r, Jr, norm = z_new, r_new, J_new, n_new
        else:
            if norm <= tol * scale:
                status = "converged"
        q = self.q(z[:n])
        F = z[n:n + 2].copy() if force_fixed is None else force_fixed.copy()
        ok = status == "converged"
        return LocalResult(q, F, ok, status, it, bool(np.any(np.abs(q) >= limits)))

    # ---------------------------------------------------------------- derivatives
    def evaluate(self, params: np.ndarray, q: np.ndarray, force: np.ndarray):
        """Energy, gradient, Lagrangian Hessian ``Hess(E - F.tip)``, tip Jacobian, tip (all in phi)."""
        E, g, H, J, tip = self.derivs(self.phi(q), params, force)
        return (float(E), np.asarray(g).ravel(), np.asarray(H), np.asarray(J), np.asarray(tip).ravel())

    def kkt_parameter_jacobian(self, params: np.ndarray, q: np.ndarray, force: np.ndarray,
                               target: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """KKT Jacobian w.r.t. ``(phi, F)`` and w.r.t. the parameters, at a solution."""
        z = np.concatenate([self.phi(q), force])
        _, Jz = self.kkt(z, params, target)
        Jp = self.kkt_dp(z, params, target)
        return np.asarray(Jz), np.asarray(Jp)


_local = threading.local()


def model(n: int) -> _Model:
    """The cached CasADi model for ``n`` segments, owned by the calling thread."""
    cache = getattr(_local, "cache", None)
    if cache is None:
        cache = _local.cache = {}
    m = cache.get(n)
    if m is None:
        m = cache[n] = _Model(n)
    return m
