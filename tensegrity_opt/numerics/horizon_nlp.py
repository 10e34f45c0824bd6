"""The horizon problem: the springs' rest lengths for ``N`` consecutive steps of a trajectory as one CasADi NLP.

The shape of do-mpc's and rockit's optimal-control problems, for quasi-static steps: the problem (this module)
is built once per ``(n, N, angles)`` and cached per thread (:mod:`.per_thread`); every number that varies
between calls (the geometry, the loads, the current rest lengths, the per-spring weights of the motion, the
objective's weights, the length scale, the required margin) enters through the parameter vector ``p``, and
the targets, the rates, the actuator bounds and the joint range through the bounds. The method that calls it
(receding or whole-trajectory) is :mod:`tensegrity_opt.analyses.design.horizon`.

Variables, per step ``k = 1..N`` (each block holds the ``N`` steps one after the other):
``phi`` (absolute angles, n), ``L10``, ``L20`` (rest lengths, n each), ``L`` (the lower-triangular factor
of ``H_q - margin I = L L^T``, as :class:`~.design_nlp.PreloadNLP`: ``H_q`` the Hessian of ``E - F_k . tip``
in the joint angles, ``diag(L) >= 0``: the stability margin in Cholesky form), ``e`` (the pose error:
the tip's two coordinates, and with ``angles`` the last link's angle times the length scale) and ``t`` (one per
step: ``t >= |e|``, the Euclidean norm, smoothed: ``sqrt(|e|^2 + d^2) - d``, ``d = NORM_SMOOTHING s``).

Rows, per step: ``grad`` (``grad E - J^T F_k = 0``), ``psd`` (the factorisation, ``= 0``), ``q`` (the joint
angles, inside the range), ``stretch1``, ``stretch2`` (``L_i - L_i0``: ``>= 0`` for taut springs), ``pose``
(``pose_k - e_k``, bounded by the target: the pose is the target plus the error), ``norm``
(``t_k - (sqrt(|e_k|^2 + d^2) - d) >= 0``) and ``rate`` (``l_k - l_{k-1}``, ``l_0`` the current rest lengths ``ell0``,
bounded by the step's rate box ``+- r_k``).

Objective (``s`` the length scale, ``w`` the weights ``(w_2, w_1, w_move)``, ``v`` the per-spring weights)::

    w_2 sum_k |e_k|^2 / s^2 + w_1 sum_k t_k / s + w_move sum_k sum_j v_j (l_kj - l_{k-1,j})^2 / s^2

The pose error is soft: an out-of-reach stretch of the trajectory still has a solution, which moves toward
the targets as fast as the rates allow. Its first-power part makes the penalty exact (a step whose target
is reachable is met once ``w_1`` exceeds the multiplier of the pose row: to within ``d`` times that multiplier
over ``w_1``, the smoothing's price), its square part spreads a shortfall over the steps; both are functions of
the Euclidean distance, so a target out of reach is approached along the distance the results report (a norm
taken component by component would settle on another pose). Bounding ``e`` (and ``t``) to zero turns it into
exact tracking.
"""

from __future__ import annotations

import casadi as ca
import numpy as np

from .build import COMPILED, VIRTUAL_MACHINE, cached_library, libraries, load
from .design_nlp import NLPResult, _factor_floor, _lower, _nlpsol, _problem, _run, _tril, tril_size
from .expressions import chain_expressions
from .layout import Layout

__all__ = ["HorizonNLP", "horizon_nlp", "prebuild", "compiled_path", "WARM_OPTIONS"]

#: The Functions of an NLP that IPOPT evaluates, by the names ``nlpsol`` gives them (and loads from a library).
NLP_FUNCTIONS = ("nlp", "nlp_f", "nlp_g", "nlp_grad", "nlp_grad_f", "nlp_jac_g", "nlp_hess_l")
#: Windows of at most this many steps look for their compiled problem in the cache (finding a library means
#: generating its code, ~0.2 s at N = 10: worth it for a receding loop, not for one whole-trajectory solve).
PREBUILD_MAX_N = 32
#: IPOPT iterations of one horizon solve at most (a receding step is warm: tens).
HORIZON_MAX_ITER = 1000
#: IPOPT's warm start from a nearby solution and its multipliers (a receding step): the barrier parameter starts
#: small and the point and multipliers are not pushed away from their bounds.
WARM_OPTIONS = {"ipopt.warm_start_init_point": "yes", "ipopt.mu_init": 1e-8, "ipopt.mu_strategy": "monotone",
                "ipopt.warm_start_bound_push": 1e-9, "ipopt.warm_start_bound_frac": 1e-9,
                "ipopt.warm_start_slack_bound_push": 1e-9, "ipopt.warm_start_slack_bound_frac": 1e-9,
                "ipopt.warm_start_mult_bound_push": 1e-9}
#: The smoothing ``d`` of the pose error's norm, times the length scale: ``sqrt(|e|^2 + d^2) - d``.
NORM_SMOOTHING = 1e-6


class HorizonNLP:
    """Rest lengths, configurations and margins of ``N`` quasi-static steps (module docstring).

    Parameters
    ----------
    n : int
        Segments (``>= 2``).
    N : int
        Steps of the horizon (``>= 1``).
    angles : bool
        The pose includes the last link's absolute angle (times the length scale ``s``).

    Attributes
    ----------
    variables, constraints, parameters : Layout
        The named blocks of ``x``, ``g`` and ``p``; a block of per-step values holds the ``N`` steps one after
        the other (``unpack(x)["phi"].reshape(N, n)``).
    pose_size : int
        2, or 3 with ``angles``.
    factor_floor : ndarray
        The lower bounds of one step's factor block (``diag(L) >= 0``).
    """

    def __init__(self, n: int, N: int, angles: bool) -> None:
        if n < 2 or N < 1:
            raise ValueError(f"a horizon problem needs n >= 2 segments and N >= 1 steps, got n={n}, N={N}")
        self.n, self.N, self.angles = n, N, bool(angles)
        d = self.pose_size = 3 if angles else 2
        nt = tril_size(n)
        a, b, k1, k2 = (ca.SX.sym(s, n) for s in ("a", "b", "k1", "k2"))
        F = ca.SX.sym("F", 2 * N)
        ell0 = ca.SX.sym("ell0", 2 * n)                # the current rest lengths: L10 then L20
        v = ca.SX.sym("v", 2 * n)                      # per-spring weights of the motion
        w = ca.SX.sym("w", 3)                          # w_2, w_1, w_move
        s = ca.SX.sym("scale")
        margin = ca.SX.sym("margin")
        phi, L10, L20 = (ca.SX.sym(nm, n * N) for nm in ("phi", "L10", "L20"))
        lv = ca.SX.sym("L", nt * N)
        e, t = ca.SX.sym("e", d * N), ca.SX.sym("t", N)
        dn = NORM_SMOOTHING * s
        T = ca.DM(np.tril(np.ones((n, n))))            # dphi/dq
        rows: dict[str, list] = {k: [] for k in ("grad", "psd", "q", "stretch1", "stretch2", "pose", "norm", "rate")}
        diag = None
        f = 0
        prev = ell0
        for k in range(N):
            ph = phi[k * n:(k + 1) * n]
            l1, l2 = L10[k * n:(k + 1) * n], L20[k * n:(k + 1) * n]
            Fk = F[2 * k:2 * k + 2]
            q, S1, S2, E, tip = chain_expressions(ph, a, b, k1, k2, l1, l2)
            J = ca.jacobian(tip, ph)
            Hq = T.T @ ca.hessian(E - ca.dot(Fk, tip), ph)[0] @ T
            Lc, diag = _tril(lv[k * nt:(k + 1) * nt], n)
            ek, tk = e[k * d:(k + 1) * d], t[k]
            pose = ca.vertcat(tip, s * ph[n - 1]) if angles else tip
            ell = ca.vertcat(l1, l2)
            rows["grad"].append(ca.gradient(E, ph) - J.T @ Fk)
            rows["psd"].append(_lower(Hq - margin * ca.SX.eye(n) - Lc @ Lc.T, n))
            rows["q"].append(q)
            rows["stretch1"].append(S1 - l1)
            rows["stretch2"].append(S2 - l2)
            rows["pose"].append(pose - ek)
            rows["norm"].append(tk - (ca.sqrt(ca.sumsqr(ek) + dn * dn) - dn))
            rows["rate"].append(ell - prev)
            f += w[0] * ca.sumsqr(ek) / (s * s) + w[1] * tk / s \
                + w[2] * ca.sum1(v * (ell - prev) ** 2) / (s * s)
            prev = ell
        g = ca.vertcat(*(ca.vertcat(*r) for r in rows.values()))
        x = ca.vertcat(phi, L10, L20, lv, e, t)
        p = ca.vertcat(a, b, k1, k2, F, ell0, v, w, s, margin)
        #: ``phi``, ``L10``, ``L20`` (n per step), ``L`` (``tril(n)`` per step), ``e`` (``pose_size`` per step), ``t``
        #: (one per step)
        self.variables = Layout(phi=n * N, L10=n * N, L20=n * N, L=nt * N, e=d * N, t=N)
        #: per step: ``grad`` (n), ``psd`` (tril(n)), ``q`` (n), ``stretch1``, ``stretch2`` (n), ``pose``
        #: (``pose_size``), ``norm`` (1), ``rate`` (2n: the L10 then the L20 changes)
        self.constraints = Layout(grad=n * N, psd=nt * N, q=n * N, stretch1=n * N, stretch2=n * N, pose=d * N,
                                  norm=N, rate=2 * n * N)
        #: geometry ``a, b, k1, k2``; the loads ``F`` (2 per step); ``ell0`` the current rest lengths (L10 then
        #: L20); ``v`` the per-spring weights of the motion; ``w = (w_2, w_1, w_move)``; the length ``scale``;
        #: the required ``margin``
        self.parameters = Layout(a=n, b=n, k1=n, k2=n, F=2 * N, ell0=2 * n, v=2 * n, w=3, scale=(), margin=())
        self.factor_floor = _factor_floor(n, diag)
        self._nlp = {"x": x, "p": p, "f": f, "g": g}
        self.solver, self._deadline = _nlpsol(f"horizon_{n}_{N}", self._nlp, **{"ipopt.max_iter": HORIZON_MAX_ITER})
        self._warm = None
        #: how the warm solves evaluate the problem: CasADi's virtual machine, or compiled (:func:`prebuild`)
        self.mode = VIRTUAL_MACHINE
        self._eval = ca.Function("horizon_eval", [x, p], [g, f])

    def solve(self, x0, lbx, ubx, lbg, ubg, p, lam_x0=None, lam_g0=None) -> NLPResult:
        """IPOPT from ``x0`` (:class:`~.design_nlp.NLPResult`; out of time: ``TimeLimitError``); with the
        multipliers ``lam_x0``, ``lam_g0`` of a nearby solution (a receding step's shifted one), IPOPT's warm start
        (:data:`WARM_OPTIONS`: the barrier starts small, the point is not pushed into the interior), on the
        problem's compiled code where :func:`prebuild` put it in the cache."""
        if lam_x0 is None or lam_g0 is None:
            return _run(self.solver, x0, lbx, ubx, lbg, ubg, p)
        if self._warm is None:
            path = compiled_path(self.n, self.N, self.angles) if self.N <= PREBUILD_MAX_N else None
            options = {"ipopt.max_iter": HORIZON_MAX_ITER, **WARM_OPTIONS}
            name = f"horizon_{self.n}_{self.N}_warm"
            if path:
                try:
                    self._warm, self._warm_deadline = _nlpsol(name, self._nlp, source=path, **options)
                    self.mode = COMPILED
                except RuntimeError:                # an unloadable library: the virtual machine
                    path = None
            if not path:
                self._warm, self._warm_deadline = _nlpsol(name, self._nlp, **options)
        return _run(self._warm, x0, lbx, ubx, lbg, ubg, p, lam_x0, lam_g0)

    def functions(self) -> dict[str, ca.Function]:
        """The NLP's Functions IPOPT evaluates (objective, rows, their derivatives), named as ``nlpsol`` loads them
        from a library: what :func:`prebuild` compiles."""
        nlp = self._nlp
        oracle = ca.Function("nlp", [nlp["x"], nlp["p"]], [nlp["f"], nlp["g"]], ["x", "p"], ["f", "g"])
        return {"nlp": oracle, **{k: self.solver.get_function(k) for k in NLP_FUNCTIONS if k != "nlp"}}

    def evaluate(self, x: np.ndarray, p: np.ndarray) -> tuple[np.ndarray, float]:
        """The rows ``g(x)`` and the objective at ``x`` (numpy)."""
        g, f = self._eval(x, p)
        return np.asarray(g).ravel(), float(f)


def _library(n: int, N: int, angles: bool) -> str:
    return f"tensegrity_horizon_n{int(n)}_N{int(N)}{'_angles' if angles else ''}"


def compiled_path(n: int, N: int, angles: bool = False) -> str | None:
    """The compiled library of the ``(n, N, angles)`` horizon problem when :func:`prebuild` put it in the cache
    (``TENSEGRITY_CACHE_DIR``), else None. Never compiles."""
    if cached_library(_library(n, N, angles), lambda: horizon_nlp(n, N, angles).functions()):
        return libraries()[_library(n, N, angles)] or None
    return None


def prebuild(n: int, N: int, angles: bool = False) -> str | None:
    """Compile the ``(n, N, angles)`` horizon problem's Functions into the cache, once per machine (~15 s for
    n = 4, N = 10 with gcc): later receding windows of that size (their warm solves) evaluate compiled code,
    ~4 ms instead of ~5.5 ms a window at n = 4, N = 10. The library's path, or None (no compiler, or
    ``TENSEGRITY_COMPILE=0``: the virtual machine, with the one warning of :mod:`.build`)."""
    name = _library(n, N, angles)
    loaded = load(name, "the horizon problem", lambda: horizon_nlp(n, N, angles).functions())
    return libraries().get(name) or None if loaded.mode == COMPILED else None


def horizon_nlp(n: int, N: int, angles: bool = False) -> HorizonNLP:
    """This thread's :class:`HorizonNLP` for ``n`` segments and ``N`` steps (``angles``: the pose includes the last
    link's angle), built on the first call and reused (:mod:`.per_thread`)."""
    return _problem(HorizonNLP, int(n), int(N), bool(angles))
