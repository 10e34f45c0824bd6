"""What came out of a local solve: numpy-only result types of :class:`.ChainSolver`."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["LocalResult", "SeedResults", "Continuation"]


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
    """Points of a compiled continuation (:meth:`ChainSolver.batch_continue`), N of them.

    ``Z`` (N, n+2) the iterates ``(phi, F)``, ``residual`` (N,) the KKT residual norm there (large
    where Newton failed); from the kernels also ``energy`` (N,), ``tip`` (N, 2),
    ``reduced_hessian`` (N, n-2, n-2) and ``iterations`` (N,) (the Newton iterations each point took,
    0 for a point converged at its start), else ``None`` (CasADi's ``rootfinder`` of a longer chain
    does not report them); ``residual`` is in the solver's units, whose torque scale is ``torque_scale``.
    """

    Z: np.ndarray
    residual: np.ndarray
    energy: np.ndarray | None = None
    tip: np.ndarray | None = None
    reduced_hessian: np.ndarray | None = None
    #: ``max k c^2`` in the units ``residual`` is measured in (the solver's, see :mod:`.units`)
    torque_scale: float = 1.0
    iterations: np.ndarray | None = None

    @property
    def phi(self) -> np.ndarray:
        """The absolute angles of the iterates, (N, n) (a view of ``Z``)."""
        return self.Z[:, :-2]

    @property
    def force(self) -> np.ndarray:
        """The tip forces of the iterates, (N, 2) (a view of ``Z``)."""
        return self.Z[:, -2:]


@dataclass
class SeedResults:
    """Local solves from k starts as arrays (:meth:`ChainSolver.newton_kkt_seeds`; numpy only).

    ``q`` (k, n), ``force`` (k, 2), ``success``/``on_bound`` (k,) bool, ``iterations`` (k,),
    ``status`` (k statuses), and the kernels' ``energy`` (k,), ``tip`` (k, 2) and
    ``reduced_hessian`` (k, n-2, n-2) at each point: NaN in the rows that came from the Python
    Newton method (classify those from the model); ``reduced_hessian`` is ``None`` when no row has
    one (chains without kernels). ``distinct`` (k,) bool when the kernel compared the rows
    (:meth:`ChainSolver.newton_kkt_seeds`), else ``None``.
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


def seed_results(results: list[LocalResult], n: int) -> SeedResults:
    """Single results as :class:`SeedResults`; ``reduced_hessian`` only when some result has one (a long
    chain's would be (k, n-2, n-2): never allocated for it)."""
    k, m = len(results), n - 2
    with_r = any(r.reduced_hessian is not None for r in results)
    out = SeedResults(np.empty((k, n)), np.empty((k, 2)), np.zeros(k, bool), np.zeros(k, bool), np.zeros(k, int),
                      [""] * k, np.empty(k), np.empty((k, 2)), np.empty((k, m, m)) if with_r else None)
    for j, r in enumerate(results):
        set_row(out, j, r)
    return out


def set_row(out: SeedResults, j: int, r: LocalResult) -> None:
    """Row ``j`` of ``out`` from a single result."""
    out.q[j], out.force[j] = r.q, r.force
    out.success[j], out.on_bound[j], out.iterations[j], out.status[j] = r.success, r.on_bound, r.iterations, r.status
    if r.energy is None or out.reduced_hessian is None:
        out.energy[j], out.tip[j] = np.nan, np.nan
        if out.reduced_hessian is not None:
            out.reduced_hessian[j] = np.nan
    else:
        out.energy[j], out.tip[j], out.reduced_hessian[j] = r.energy, r.tip, r.reduced_hessian
