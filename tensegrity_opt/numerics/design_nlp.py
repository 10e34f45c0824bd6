"""CasADi formulations of the design and control problems (the only design module touching CasADi).

Three problem kinds, each built once per ``(n, boundary)`` / ``n`` and cached per thread
(:mod:`.per_thread`); every number that varies between calls (fixed parameters, bounds, budgets,
nominal values, loads, targets, objective weights) enters through the parameter vector or the
bounds. Each problem names the blocks of its variables, rows and parameters (:class:`.layout.Layout`:
``variables``, ``constraints``, ``parameters``): callers pack and unpack them by name.

``BucklingDesignNLP`` — variables ``a, b, k, L0`` (per segment, symmetric springs), the load
``P`` and a lower-triangular ``L``; constraint ``Z^T (K - P G) Z = L L^T`` with
``diag(L) >= 0`` (positive semidefinite, smooth even where the smallest eigenvalue is
repeated), plus budget, total-length, preload-tension and joint-stiffness rows. Objective
``-w_P P + w_c sum((L0 - L0_nom)^2) / sum(L0_nom^2)``.

``PreloadNLP`` — variables absolute angles ``phi``, rest lengths ``L1_0, L2_0``, a margin
``mu`` and a lower-triangular ``L``; constraints ``grad E = J^T F``, ``tip = target``,
optional last-link angle, ``H_q - mu I = L L^T`` (``H_q``: Hessian of ``E - F.tip`` in joint
angles), spring lengths ``L_i - L_i0`` (for tautness) and joint angles (physical range).
Objective ``w_nom |L0 - L0_nom|^2 / |L0_nom|^2 - w_mu mu + w_E E + w_tip |tip - aim_xy|^2
+ w_ang (phi_n - aim_angle)^2``: with the tip rows left free, the distance terms make it the nearest
admissible pose to an aim.

``StiffnessNLP`` — the variables of ``PreloadNLP`` and the compliance columns ``Y = H^-1 J^T``
(``H`` the Hessian of ``E - F.tip`` in the absolute angles, ``n x 2``, scaled); the rows of
``PreloadNLP`` and ``H Y = J^T``, so that ``C = J Y = J H^-1 J^T`` (the free tip's compliance) and
``K = C^-1`` (its Cartesian tangent stiffness, the 2 x 2 inverse written out) are smooth functions of
the variables; rows ``K`` (its three entries, for bounds or equalities) and, for eigenvalue bounds
``lo <= eig(K) <= hi``, the trace and determinant of ``K - lo I`` and of ``hi I - K`` (a 2 x 2
symmetric matrix is positive semidefinite iff both are >= 0). Objective
``w_K |K - K_d|_F^2 + w_nom |L0 - L0_nom|^2 / |L0_nom|^2``.
"""

from __future__ import annotations

from dataclasses import dataclass

import casadi as ca
import numpy as np

from ..errors import TimeLimitError
from ..timelimit import TIMEOUT_STATUSES, check_time, expired
from .expressions import chain_expressions
from .ipopt import IPOPT_OPTIONS
from .layout import Layout
from .per_thread import per_thread

__all__ = ["NLPResult", "buckling_design_nlp", "preload_nlp", "stiffness_nlp", "tril_size", "tril_vector"]

#: IPOPT iterations of one stiffness-shaping solve at most.
STIFFNESS_MAX_ITER = 400

_DESIGN_OPTIONS = {**IPOPT_OPTIONS, "ipopt.max_iter": 3000, "ipopt.tol": 1e-9, "ipopt.constr_viol_tol": 1e-9,
                   "ipopt.max_wall_time": 60.0}


@dataclass
class NLPResult:
    x: np.ndarray
    lam_g: np.ndarray
    lam_x: np.ndarray
    success: bool
    status: str
    iterations: int


def tril_size(d: int) -> int:
    """Entries of a ``d x d`` lower-triangular matrix."""
    return d * (d + 1) // 2


def tril_vector(L: np.ndarray) -> np.ndarray:
    """The lower triangle of the square matrix ``L``, row by row (the order of a factor's block)."""
    d = L.shape[0]
    return np.array([L[i, j] for i in range(d) for j in range(i + 1)])


def _factor_floor(d: int, diag: list[int]) -> np.ndarray:
    """Lower bounds of a factor's block: ``0`` on its diagonal (``diag(L) >= 0``), ``-inf`` elsewhere."""
    lo = np.full(tril_size(d), -np.inf)
    lo[diag] = 0.0
    lo.setflags(write=False)
    return lo


def _tril(v, d):
    """Lower-triangular SX matrix from a vector (row by row), and the indices of its diagonal."""
    L = ca.SX(d, d)
    diag = []
    k = 0
    for i in range(d):
        for j in range(i + 1):
            L[i, j] = v[k]
            if i == j:
                diag.append(k)
            k += 1
    return L, diag


def _lower(M, d):
    return ca.vertcat(*[M[i, j] for i in range(d) for j in range(i + 1)])


def _chain_matrices(b):
    """G = -Hess x (joint angles, straight) and S0 = dy/dq for half-lengths ``b`` (SX)."""
    n = b.shape[0]
    links = b + ca.vertcat(b[1:], 0) if n > 1 else b
    T = ca.DM(np.tril(np.ones((n, n))))
    G = T.T @ ca.diag(links) @ T
    S0 = T.T @ links
    return G, S0


class _DeadlineCallback(ca.Callback):
    """IPOPT's ``iteration_callback``: asks IPOPT to stop (``User_Requested_Stop``) once the calling
    thread's :func:`~tensegrity_opt.time_limit` is reached. One per solver instance (per thread)."""

    def __init__(self, name: str, nx: int, ng: int, np_: int) -> None:
        ca.Callback.__init__(self)
        self._sizes = {"x": nx, "lam_x": nx, "g": ng, "lam_g": ng, "p": np_, "lam_p": np_, "f": 1}
        self.construct(name, {})

    def get_n_in(self) -> int:
        return ca.nlpsol_n_out()

    def get_n_out(self) -> int:
        return 1

    def get_name_in(self, i: int) -> str:
        return ca.nlpsol_out(i)

    def get_name_out(self, i: int) -> str:
        return "stop"

    def get_sparsity_in(self, i: int) -> ca.Sparsity:
        return ca.Sparsity.dense(self._sizes.get(ca.nlpsol_out(i), 0), 1)

    def eval(self, arg):
        return [1 if expired() else 0]


def _nlpsol(name: str, nlp: dict, source: str | None = None, **options) -> tuple[ca.Function, _DeadlineCallback]:
    """``nlpsol`` with the design options (``options`` override them) and a deadline callback (kept alive by
    the caller); ``source``: a compiled library of the problem's Functions (``nlp_f``, ``nlp_g``, ...) to
    evaluate instead of CasADi's virtual machine."""
    cb = _DeadlineCallback(f"{name}_deadline", nlp["x"].numel(), nlp["g"].numel(), nlp["p"].numel())
    return ca.nlpsol(name, "ipopt", nlp if source is None else source,
                     {**_DESIGN_OPTIONS, **options, "iteration_callback": cb}), cb


def _run(solver, x0, lbx, ubx, lbg, ubg, p, lam_x0=None, lam_g0=None) -> NLPResult:
    check_time("the design solve")
    warm = {} if lam_x0 is None else {"lam_x0": lam_x0, "lam_g0": lam_g0}
    sol = solver(x0=x0, lbx=lbx, ubx=ubx, lbg=lbg, ubg=ubg, p=p, **warm)
    st = solver.stats()
    status = str(st["return_status"])
    if status in TIMEOUT_STATUSES:
        # Out of time (the caller's limit, or IPOPT's own max_wall_time): never a result.
        raise TimeLimitError(f"the design solve stopped at its time limit after {int(st.get('iter_count', -1))} "
                             f"IPOPT iterations ({status})", status=status)
    return NLPResult(np.asarray(sol["x"]).ravel(), np.asarray(sol["lam_g"]).ravel(),
                     np.asarray(sol["lam_x"]).ravel(), bool(st["success"]), str(st["return_status"]),
                     int(st.get("iter_count", -1)))


class BucklingDesignNLP:
    """max P  s.t.  Z^T (K(a,b,k,L0) - P G(b)) Z = L L^T, diag(L) >= 0, and design rows."""

    def __init__(self, n: int, guided: bool) -> None:
        self.n = n
        self.d = d = n - 1 if guided else n
        a, b, k, L0 = (ca.SX.sym(s, n) for s in ("a", "b", "k", "L0"))
        P = ca.SX.sym("P")
        lv = ca.SX.sym("L", tril_size(d))
        L, self.diag = _tril(lv, d)
        K = k * (b * L0 - 2 * (b * b - a * a))
        G, S0 = _chain_matrices(b)
        if guided:
            Z = ca.vertcat(ca.SX.eye(n - 1), -S0[: n - 1].T / S0[n - 1])
        else:
            Z = ca.SX.eye(n)
        M = Z.T @ (ca.diag(K) - P * G) @ Z
        psd = _lower(M - L @ L.T, d)
        # parameters: nominal L0 (n), weights (w_P, w_change)
        L0nom = ca.SX.sym("L0nom", n)
        w = ca.SX.sym("w", 2)
        f = -w[0] * P + w[1] * ca.sumsqr(L0 - L0nom) / ca.sumsqr(L0nom)
        rows = ca.vertcat(psd,                                   # = 0
                          ca.sum1(a), ca.sum1(b), ca.sum1(k), ca.sum1(L0),   # budgets
                          2 * ca.sum1(b),                        # total length
                          k * (2 * b - L0),                      # preload tension at straight (n)
                          K)                                     # joint stiffness (n)
        x = ca.vertcat(a, b, k, L0, P, lv)
        self.n_psd = tril_size(d)
        #: ``a, b, k, L0`` (n each), the load ``P``, the factor ``L`` (row by row)
        self.variables = Layout(a=n, b=n, k=n, L0=n, P=(), L=self.n_psd)
        #: ``psd`` (= 0), the budgets of ``a, b, k, L0``, the total ``length``, ``tension`` and joint stiffness ``K``
        self.constraints = Layout(psd=self.n_psd, budget_a=(), budget_b=(), budget_k=(), budget_L0=(), length=(),
                                  tension=n, K=n)
        self.parameters = Layout(L0nom=n, w=2)
        #: lower bounds of the factor's block (``diag(L) >= 0``)
        self.factor_floor = _factor_floor(d, self.diag)
        self.solver, self._deadline = _nlpsol("design_buckling",
                                              {"x": x, "p": ca.vertcat(L0nom, w), "f": f, "g": rows})
        self._rows = ca.Function("rows", [x], [rows])

    def solve(self, x0, lbx, ubx, lbg, ubg, p) -> NLPResult:
        return _run(self.solver, x0, lbx, ubx, lbg, ubg, p)

    def rows(self, x: np.ndarray) -> np.ndarray:
        """The constraint rows ``g(x)`` at the variables ``x`` (numpy)."""
        return np.asarray(self._rows(x)).ravel()


class _Pose:
    """What :class:`PreloadNLP` and :class:`StiffnessNLP` share: a stable equilibrium at a target under a tip load.

    The variables ``x = (phi, L10, L20, mu, L)`` (absolute angles, rest lengths, the margin and the factor of
    ``H_q - mu I = L L^T``), the parameters ``p = (a, b, k1, k2, F, L0nom)``, the model there and the rows
    ``(grad E - J^T F, tip, phi_n, psd)``.
    """

    def __init__(self, n: int) -> None:
        phi = self.phi = ca.SX.sym("phi", n)
        L10 = self.L10 = ca.SX.sym("L10", n)
        L20 = self.L20 = ca.SX.sym("L20", n)
        mu = self.mu = ca.SX.sym("mu")
        lv = ca.SX.sym("L", tril_size(n))
        Lc, self.diag = _tril(lv, n)
        a, b, k1, k2 = (ca.SX.sym(s, n) for s in ("a", "b", "k1", "k2"))
        F = ca.SX.sym("F", 2)
        self.L0nom = ca.SX.sym("L0nom", 2 * n)
        self.x = (phi, L10, L20, mu, lv)
        self.p = ca.vertcat(a, b, k1, k2, F, self.L0nom)
        self.q, self.L1, self.L2, self.E, tip = chain_expressions(phi, a, b, k1, k2, L10, L20)
        self.tip = tip
        J = self.J = ca.jacobian(tip, phi)
        grad = ca.gradient(self.E, phi) - J.T @ F
        Hphi = self.Hphi = ca.hessian(self.E - ca.dot(F, tip), phi)[0]
        T = ca.DM(np.tril(np.ones((n, n))))          # dphi/dq
        Hq = T.T @ Hphi @ T
        psd = _lower(Hq - mu * ca.SX.eye(n) - Lc @ Lc.T, n)
        self.rows = ca.vertcat(grad, tip, phi[n - 1], psd)
        self.L0 = ca.vertcat(L10, L20)
        # the blocks of x, p and the rows, for the problems' layouts
        self.x_blocks = {"phi": n, "L10": n, "L20": n, "mu": (), "L": tril_size(n)}
        self.p_blocks = {"a": n, "b": n, "k1": n, "k2": n, "F": 2, "L0nom": 2 * n}
        self.row_blocks = {"grad": n, "tip": 2, "angle": (), "psd": tril_size(n)}
        self.factor_floor = _factor_floor(n, self.diag)


class PreloadNLP:
    """Rest lengths and configuration for a stable equilibrium at a target under a tip load."""

    def __init__(self, n: int) -> None:
        self.n = n
        pose = _Pose(n)
        self.diag = pose.diag
        w = ca.SX.sym("w", 5)
        aim = ca.SX.sym("aim", 3)                # the tip and last-link angle the distance terms measure from
        f = (w[0] * ca.sumsqr(pose.L0 - pose.L0nom) / ca.sumsqr(pose.L0nom) - w[1] * pose.mu + w[2] * pose.E
             + w[3] * ca.sumsqr(pose.tip - aim[:2]) + w[4] * (pose.phi[n - 1] - aim[2]) ** 2)
        rows = ca.vertcat(pose.rows, pose.L1 - pose.L10, pose.L2 - pose.L20, pose.q)
        x = ca.vertcat(*pose.x)
        #: absolute angles ``phi``, rest lengths ``L10, L20``, margin ``mu``, the factor ``L`` (row by row)
        self.variables = Layout(**pose.x_blocks)
        #: ``grad E - J^T F``, ``tip``, the last link's ``angle``, ``psd`` (= 0), the springs' ``stretch1``,
        #: ``stretch2`` (``L_i - L_i0``), the joint angles ``q``
        self.constraints = Layout(**pose.row_blocks, stretch1=n, stretch2=n, q=n)
        #: the chain, the load, the nominal rest lengths, the objective's weights ``w`` (change, margin, energy,
        #: tip distance, angle distance) and the ``aim`` ``(x, y, angle)`` of the distance terms
        self.parameters = Layout(**pose.p_blocks, w=5, aim=3)
        self.factor_floor = pose.factor_floor
        self.solver, self._deadline = _nlpsol("design_preload",
                                              {"x": x, "p": ca.vertcat(pose.p, w, aim), "f": f, "g": rows})

    def solve(self, x0, lbx, ubx, lbg, ubg, p) -> NLPResult:
        return _run(self.solver, x0, lbx, ubx, lbg, ubg, p)


class StiffnessNLP:
    """Rest lengths and configuration for a stable equilibrium at a target under a tip load with a
    prescribed (or bounded) Cartesian tangent stiffness of the free tip.

    Variables ``x = (phi, L10, L20, mu, L, Y, s)`` (:attr:`variables`): ``phi`` absolute angles (n), the rest
    lengths (2n),
    the margin ``mu`` and the lower-triangular ``L`` of ``H_q - mu I = L L^T`` (as :class:`PreloadNLP`),
    ``Yhat`` (2n, column by column) with ``Y = Yhat Ls / Ts`` the compliance columns ``H^-1 J^T``
    (``Ts`` the torque scale, ``Ls`` the length scale: ``Yhat`` and ``Khat = K Ls^2 / Ts`` are O(1)), and
    the slack ``s`` of the elastic mode (fixed at 0 otherwise): every stiffness bound relaxed by ``s``.
    Parameters ``p = (a, b, k1, k2, F, L0nom, Kd (3), w (3), eig (2), scales (2))`` (:attr:`parameters`); objective
    ``w0 |Khat - Kd|_F^2 + w1 |L0 - L0nom|^2 / |L0nom|^2 + w2 s``.

    Rows ``g`` (:attr:`constraints`): ``grad E - J^T F`` (n), ``tip`` (2), ``phi_n`` (1), the margin's factorisation
    (``tril(n)``), ``H Yhat / Ts - J^T / Ls`` (2n), ``q`` (n), ``Khat + s`` and ``Khat - s`` (3 each:
    ``kxx, kxy, kyy``, for lower and upper bounds), ``tr, det`` of ``Khat - (lo - s) I`` and of
    ``(hi + s) I - Khat`` (4; ``lo, hi`` scaled, in ``p``).
    """

    def __init__(self, n: int) -> None:
        self.n = n
        pose = _Pose(n)
        self.diag = pose.diag
        yv = ca.SX.sym("Y", 2 * n)
        slack = ca.SX.sym("s")                   # elastic mode: the stiffness bounds relaxed by s >= 0
        Kd = ca.SX.sym("Kd", 3)
        w = ca.SX.sym("w", 3)
        eig = ca.SX.sym("eig", 2)
        sc = ca.SX.sym("scales", 2)              # torque scale Ts, length scale Ls
        Hphi, J = pose.Hphi, pose.J
        Y = ca.horzcat(yv[:n], yv[n:])
        comp = ca.vec(Hphi @ Y / sc[0] - J.T / sc[1])
        C = J @ Y / sc[1]                        # C Ts / Ls^2: the scaled compliance
        c11, c22, c12 = C[0, 0], C[1, 1], 0.5 * (C[0, 1] + C[1, 0])
        det = c11 * c22 - c12 * c12
        K = ca.vertcat(c22 / det, -c12 / det, c11 / det)       # kxx, kxy, kyy (scaled)
        lo, hi = eig[0] - slack, eig[1] + slack
        eig_rows = ca.vertcat(K[0] + K[2] - 2 * lo, (K[0] - lo) * (K[2] - lo) - K[1] * K[1],
                              2 * hi - K[0] - K[2], (hi - K[0]) * (hi - K[2]) - K[1] * K[1])
        dK = K - Kd
        fit = dK[0] * dK[0] + 2 * dK[1] * dK[1] + dK[2] * dK[2]          # |K - Kd|_F^2 (kxy twice)
        f = w[0] * fit + w[1] * ca.sumsqr(pose.L0 - pose.L0nom) / ca.sumsqr(pose.L0nom) + w[2] * slack
        rows = ca.vertcat(pose.rows, comp, pose.q, K + slack, K - slack, eig_rows)
        x = ca.vertcat(*pose.x, yv, slack)
        self.variables = Layout(**pose.x_blocks, Y=2 * n, s=())
        self.constraints = Layout(**pose.row_blocks, compliance=2 * n, q=n, K_lo=3, K_hi=3, eig=4)
        self.parameters = Layout(**pose.p_blocks, Kd=3, w=3, eig=2, scales=2)
        self.factor_floor = pose.factor_floor
        p = ca.vertcat(pose.p, Kd, w, eig, sc)
        # a solve that has not converged in STIFFNESS_MAX_ITER iterations is not going to (the caller tries
        # another start or formulation instead of waiting for the design problems' 3000)
        self.solver, self._deadline = _nlpsol("design_stiffness", {"x": x, "p": p, "f": f, "g": rows},
                                              **{"ipopt.max_iter": STIFFNESS_MAX_ITER})
        self._rows = ca.Function("stiffness_rows", [x, p], [rows])

    def solve(self, x0, lbx, ubx, lbg, ubg, p) -> NLPResult:
        return _run(self.solver, x0, lbx, ubx, lbg, ubg, p)

    def rows(self, x: np.ndarray, p: np.ndarray) -> np.ndarray:
        """The constraint rows ``g(x)`` (numpy), for the report of an infeasible point."""
        return np.asarray(self._rows(x, p)).ravel()


def _deadline_after_build(problem) -> None:
    check_time("building the design problem")     # the build (nlpsol) itself cannot be cut


@per_thread(built=_deadline_after_build)
def _problem(kind: type, *args):
    """This thread's problem of ``kind`` for ``args`` (:mod:`.per_thread`)."""
    return kind(*args)


def buckling_design_nlp(n: int, guided: bool) -> BucklingDesignNLP:
    """This thread's :class:`BucklingDesignNLP` for ``n`` segments (``guided``: the guided tip)."""
    return _problem(BucklingDesignNLP, n, bool(guided))


def preload_nlp(n: int) -> PreloadNLP:
    """This thread's :class:`PreloadNLP` for ``n`` segments."""
    return _problem(PreloadNLP, n)


def stiffness_nlp(n: int) -> StiffnessNLP:
    """This thread's :class:`StiffnessNLP` for ``n`` segments."""
    return _problem(StiffnessNLP, n)
