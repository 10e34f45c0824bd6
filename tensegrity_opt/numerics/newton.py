"""The damped Newton method of the Python path (dense LAPACK or banded O(n) steps), and BLAS control.

The compiled kernels (:mod:`.kernels`) run the same step rule in C; this loop drives CasADi
functions evaluated through :class:`._fast.Fast` buffers.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla
from scipy.linalg.lapack import dgesv as _dgesv

from .results import LocalResult

__all__ = ["damped_newton", "banded_step", "one_blas_thread"]


def damped_newton(call, fast, z, limits, thresh, max_iter, max_step, force_fixed, *, n: int, dense: bool,
                  residual_only=None) -> LocalResult:
    """Damped Newton with a backtracking line search on ``|r|``, converged at ``|r| <= thresh``.

    ``call(z)`` evaluates the residual and its Jacobian into ``fast``'s buffers (dense chains: the
    Jacobian as output 1; long chains: the tridiagonal Hessian and ``J``, see
    :func:`.expressions.banded_functions`); ``residual_only(z)`` (long chains) the residual alone, for
    the trial points of the line search; the Jacobian is then evaluated once at each accepted point.
    ``force_fixed``: the prescribed force (force control: ``z`` is ``phi``), or ``None`` (``z = (phi, F)``).
    """
    trial = residual_only or call
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
            if dense:
                # LAPACK's dgesv directly: the same LU solve as numpy.linalg.solve with less Python
                # overhead, which dominates for these small systems
                _, _, step, info = _dgesv(fast.dense(1), -r)
                if info != 0:
                    raise np.linalg.LinAlgError("singular KKT matrix")
            else:
                step = banded_step(fast.outs, r, n, force_fixed is None)
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
    q = np.diff(np.concatenate([[0.0], z[:n]]))
    F = z[n:n + 2].copy() if force_fixed is None else force_fixed.copy()
    return LocalResult(q, F, status == "Newton_Converged", status, it, bool(np.any(np.abs(q) >= limits)))


def banded_step(outs: list[np.ndarray], r: np.ndarray, n: int, kkt: bool) -> np.ndarray:
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


_blas = None


def one_blas_thread():
    """BLAS limited to one thread (threadpoolctl) for the O(n) loops of long chains.

    Their vectors are long enough for OpenBLAS to start helper threads on dot products and
    matrix-vector products that take microseconds; the helpers then spin and cost more time
    than they save (benchmarks/RESULTS.md, "Measurement notes").
    """
    global _blas
    if _blas is None:
        from threadpoolctl import ThreadpoolController

        _blas = ThreadpoolController()
    return _blas.limit(limits=1, user_api="blas")
