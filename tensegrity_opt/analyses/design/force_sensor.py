"""The arm as a force sensor: the tip force from measured joint angles.

At a static equilibrium under a tip force ``F`` and nothing else, the spring torques balance it
(eq. 6 / 8, ``docs/model.md``)::

    tau(q) = grad E(q) = J(q)^T F          (n equations, 2 unknowns)

so the joint angles measure the force: ``F`` by (generalised) least squares, and the ``n - 2``
redundant equations test the model. The part of ``tau`` that no tip force explains, the
*residual torque*, reveals a load elsewhere on the arm (a contact along a link, a torque at a
joint) or a model error; with the angle noise known it is a chi-square statistic.

:func:`estimate_tip_force` is the one public function; :class:`ForceEstimate` its result. The
derivatives (``grad E``, ``J``, ``Hess(E - F . tip)``) are the project's CasADi model through
:meth:`tensegrity_opt.numerics.ChainSolver.evaluate` (the compiled SX graph of
:mod:`tensegrity_opt.numerics.expressions`; long chains its banded form), transformed from absolute
to relative joint angles here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from ...errors import InvalidParameterError, NoEquilibriumError, SolverError
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...model.springs import SpringFields, Springs, linear_only
from ...numerics import chain_solver
from ...outcome import Outcome, freeze
from ...serialize import number, numbers
from ..equilibria.equilibrium import TipForce

__all__ = ["ForceEstimate", "estimate_tip_force"]

#: Convergence of the Gauss-Newton steps: the predicted change of the residual ``|B dx|_inf``, relative
#: to the torque scale ``k c^2`` of the stiffest segment.
STEP_TOL = 1e-13
#: With ``sigma_q`` the unweighted Gauss-Newton solve only provides the start of the weighted one: to this.
LOOSE_TOL = 1e-7
#: Numerical rank threshold: smallest / largest singular value of the column-normalised Jacobian
#: ``dr/d(F, hidden angles)`` below which the unknowns are not determined by the torques.
RANK_TOL = 1e-10
#: Iteration caps: the unweighted Gauss-Newton solve, then the re-weighting (the weight at the estimate).
MAX_ITER = 100
MAX_REWEIGHT = 100
#: The re-weighting has settled when its next step is below this fraction of every unknown's standard
#: deviation (or below ``STEP_TOL``): a change of the weight that moves the estimate by a millionth of its
#: uncertainty is immaterial. Under the null hypothesis it takes one or two steps; data far from any
#: equilibrium (a huge ``chi2``) converge linearly.
REWEIGHT_TOL = 1e-6
#: A hidden angle never steps more than this fraction of the way to its joint limit, nor more than
#: ``MAX_STEP`` rad, in one iteration.
TO_LIMIT = 0.9
MAX_STEP = 0.5


@dataclass(frozen=True)
class ForceEstimate(Outcome, TipForce, SpringFields):
    """The tip force estimated from joint angles (:func:`estimate_tip_force`).

    Attributes
    ----------
    force : ndarray (2,)
        The estimate ``[Fx, Fy]`` (force units; the tip force holding the equilibrium, ``docs/model.md``).
    covariance : ndarray (2, 2) or None
        Covariance of ``force`` propagated from the joint-angle noise (linearised; ``None`` without
        ``sigma_q``).
    residual_torque : ndarray (n,)
        ``grad E(q) - J(q)^T F`` at the estimate: the joint torques no tip force explains.
    residual_norm : float
        Its 2-norm (torque units).
    chi2 : float or None
        The test statistic ``r^T W r`` (see :func:`estimate_tip_force`); ``None`` without ``sigma_q``.
    dof : int
        Its degrees of freedom: equations minus unknowns, ``n - 2 - (number of unmeasured joints)``.
    p_value : float or None
        ``P(chi2_dof >= chi2)`` (``scipy.stats.chi2.sf``): small when the angles are not those of an
        equilibrium under a tip force only. ``None`` without ``sigma_q`` or when ``dof == 0``.
    joint_chi2 : ndarray (n,) or None
        Where is the load that is not at the tip? Entry ``j`` is the decrease of ``chi2`` when an unknown
        extra torque at joint ``j`` is admitted, ``(P r)_j^2 / P_jj`` (``P`` the residual weight, see
        :func:`estimate_tip_force`; Baarda's w-test squared, ``~ chi2(1)`` under the null). A single
        extra torque at joint ``j`` makes entry ``j`` the largest (and equal to ``chi2`` for exact data);
        0 where such a torque cannot be told from the unknowns. ``None`` without ``sigma_q``.
    q : ndarray (n,)
        The configuration used: the measured angles as given, the unmeasured ones as estimated;
        inside the physical range.
    measured : tuple of int
        The (0-based) indices of the measured joints.
    hidden_covariance : ndarray (u, u) or None
        Covariance of the estimated unmeasured angles (rad^2; ``(0, 0)`` when every joint is measured;
        ``None`` without ``sigma_q``).
    status : str
        How the estimate was obtained (:attr:`STATUSES`): ``"least_squares"``, ``"gauss_newton"`` (unmeasured
        joints), ``"generalized_least_squares"``, ``"weighted_gauss_newton"`` (with ``sigma_q``), or
        ``"reweighting_not_converged"``, the one status that is not a success: the re-weighting did not settle,
        which happens for angles far from any equilibrium under a tip force (``chi2`` far beyond ``dof``, the
        weight swinging with the estimate); the estimate is then the one-step one, generalised least squares
        with the weight at the unweighted estimate, its covariance and ``chi2`` at that point.
    iterations : int
        Gauss-Newton / re-weighting iterations made.
    spring_lengths, spring_stretches, spring_forces, spring_states : ndarray (n, 2)
        The springs at ``q`` (:class:`~tensegrity_opt.model.springs.SpringFields`).
    message : str
        The status in a sentence, with the residual (and ``chi2`` with ``sigma_q``).
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "least_squares": "every joint measured, no noise model: the least-squares force (eq. 8)",
        "gauss_newton": "unmeasured joints, no noise model: the force and the unmeasured angles by Gauss-Newton",
        "generalized_least_squares": "every joint measured, with sigma_q: generalised least squares with the "
                                     "residual's covariance at the estimate",
        "weighted_gauss_newton": "unmeasured joints, with sigma_q: the re-weighted Gauss-Newton estimate",
        "reweighting_not_converged": "the re-weighting did not settle (angles far from any equilibrium under a tip "
                                     "force): the one-step estimate",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset(set(STATUSES) - {"reweighting_not_converged"})

    force: np.ndarray
    covariance: np.ndarray | None
    residual_torque: np.ndarray
    residual_norm: float
    chi2: float | None
    dof: int
    p_value: float | None
    joint_chi2: np.ndarray | None
    q: np.ndarray
    measured: tuple[int, ...]
    hidden_covariance: np.ndarray | None
    status: str
    iterations: int
    springs: Springs | None = field(default=None, repr=False, compare=False)

    def __post_init__(self) -> None:
        freeze(self, copy=False)

    @property
    def message(self) -> str:
        """A sentence: how the force was estimated, and how well the angles fit."""
        how = {"least_squares": "least-squares estimate", "gauss_newton": "Gauss-Newton estimate",
               "generalized_least_squares": "generalised least-squares estimate",
               "weighted_gauss_newton": "weighted Gauss-Newton estimate",
               "reweighting_not_converged": "the re-weighting did not settle: one-step estimate"}[self.status]
        text = f"{how}, residual torque {self.residual_norm:.3g}"
        if self.chi2 is not None:
            text += f", chi2 {self.chi2:.3g} on {self.dof} degrees of freedom"
        return text

    @property
    def std(self) -> np.ndarray | None:
        """Standard deviations of ``Fx, Fy`` (the square roots of the covariance's diagonal), or ``None``."""
        return None if self.covariance is None else np.sqrt(np.diag(self.covariance))

    def to_dict(self) -> dict[str, Any]:
        """JSON form: ``success``, ``status``, ``message``, ``force`` ``{fx, fy}``, ``covariance`` (2 x 2 lists or
        null), ``residual_torque``, ``residual_norm``, ``chi2``, ``dof``, ``p_value``, ``joint_chi2``, ``q``,
        ``measured``, ``hidden_covariance``, ``iterations``, the spring state at ``q`` (``spring_lengths``,
        ``spring_stretches``, ``spring_forces``, ``spring_states``); every number finite
        (:mod:`tensegrity_opt.serialize`)."""
        return {**self.outcome(), **self.spring_dict(), "force": {"fx": number(self.fx), "fy": number(self.fy)},
                "covariance": None if self.covariance is None else numbers(self.covariance),
                "residual_torque": numbers(self.residual_torque), "residual_norm": number(self.residual_norm),
                "chi2": None if self.chi2 is None else number(self.chi2), "dof": int(self.dof),
                "p_value": None if self.p_value is None else number(self.p_value),
                "joint_chi2": None if self.joint_chi2 is None else numbers(self.joint_chi2),
                "q": numbers(self.q), "measured": [int(i) for i in self.measured],
                "hidden_covariance": None if self.hidden_covariance is None else numbers(self.hidden_covariance),
                "iterations": int(self.iterations)}


# ---------------------------------------------------------------------------------------------- inputs
def _measured_indices(m: Manipulator, measured) -> np.ndarray:
    n = m.n
    if measured is None:
        return np.arange(n)
    try:
        arr = np.asarray(measured)
    except (TypeError, ValueError):
        raise InvalidParameterError("measured must be a boolean mask or a list of joint indices",
                                    field="measured") from None
    if arr.ndim != 1:
        raise InvalidParameterError(f"measured must be one-dimensional, got shape {arr.shape}", field="measured")
    if arr.dtype == bool:
        if arr.shape != (n,):
            raise InvalidParameterError(f"a boolean mask measured must have {n} entries, got {arr.size}",
                                        field="measured")
        return np.flatnonzero(arr)
    if arr.size == 0:
        return np.zeros(0, dtype=int)
    if not np.issubdtype(arr.dtype, np.integer):
        raise InvalidParameterError(f"measured must be a boolean mask or integer joint indices, got dtype "
                                    f"{arr.dtype}", field="measured")
    if arr.min() < 0 or arr.max() >= n:
        raise InvalidParameterError(f"measured joint indices must lie in 0..{n - 1}, got {arr.tolist()}",
                                    field="measured")
    if np.unique(arr).size != arr.size:
        raise InvalidParameterError(f"measured lists a joint twice: {arr.tolist()}", field="measured")
    return np.sort(arr.astype(int))


def _angles(m: Manipulator, q_measured, idx: np.ndarray, hid: np.ndarray) -> np.ndarray:
    """The full start configuration: measured entries checked (finite, inside the range), hidden ones the
    given start (NaN, or not given: 0)."""
    n, k = m.n, idx.size
    try:
        qm = np.asarray(q_measured, dtype=float)
    except (TypeError, ValueError):
        raise InvalidParameterError("q_measured must be an array of joint angles", field="q_measured") from None
    if qm.shape == (n,):
        q = qm.copy()
    elif qm.shape == (k,):
        q = np.zeros(n)
        q[idx] = qm
    else:
        sizes = f"{n}" if k == n else f"{n} (all joints) or {k} (the measured ones)"
        raise InvalidParameterError(f"q_measured must hold {sizes} joint angles, got shape {qm.shape}",
                                    field="q_measured")
    lim = m.joint_limits
    if not np.all(np.isfinite(q[idx])):
        raise InvalidParameterError("q_measured holds a non-finite measured angle", field="q_measured")
    h = q[hid]
    h[~np.isfinite(h)] = 0.0
    q[hid] = h
    bad = np.flatnonzero(np.abs(q) >= lim)
    if bad.size:
        i = int(bad[0])
        raise InvalidParameterError(
            f"q_measured[{i}] = {q[i]:.6g} lies outside the physical range |q| < pi - 2 beta = {lim[i]:.6g}: "
            "not a configuration of the mechanism", field="q_measured")
    return q


def _noise(sigma_q, n: int, idx: np.ndarray) -> np.ndarray:
    """The covariance (k x k) of the measured angles from a std (scalar or vector) or a covariance."""
    k = idx.size
    try:
        s = np.asarray(sigma_q, dtype=float)
    except (TypeError, ValueError):
        raise InvalidParameterError("sigma_q must be a number, a vector of standard deviations or a covariance "
                                    "matrix", field="sigma_q") from None
    if not np.all(np.isfinite(s)):
        raise InvalidParameterError("sigma_q must be finite", field="sigma_q")
    if s.ndim <= 1:
        if s.ndim == 1:
            if s.shape == (n,):
                s = s[idx]
            elif s.shape != (k,):
                raise InvalidParameterError(f"sigma_q as standard deviations must have {n} entries"
                                            + ("" if k == n else f" (or {k}, the measured joints)")
                                            + f", got {s.size}", field="sigma_q")
        if np.any(s <= 0.0):
            raise InvalidParameterError("sigma_q (standard deviations, rad) must be > 0", field="sigma_q")
        return np.diag(np.broadcast_to(s * s, (k,)).astype(float))
    if s.ndim != 2 or s.shape[0] != s.shape[1] or s.shape[0] not in (n, k):
        raise InvalidParameterError(f"sigma_q as a covariance must be {n} x {n}"
                                    + ("" if k == n else f" (or {k} x {k}, the measured joints)")
                                    + f", got shape {s.shape}", field="sigma_q")
    if s.shape[0] != k:
        s = s[np.ix_(idx, idx)]
    scale = float(np.abs(s).max())
    if np.any(np.diag(s) <= 0.0):
        raise InvalidParameterError("sigma_q (covariance) must have positive variances on its diagonal",
                                    field="sigma_q")
    if np.abs(s - s.T).max() > 1e-12 * scale:
        raise InvalidParameterError("sigma_q (covariance) must be symmetric", field="sigma_q")
    s = 0.5 * (s + s.T)
    if np.linalg.eigvalsh(s).min() < -1e-12 * scale:
        raise InvalidParameterError("sigma_q (covariance) must be positive semidefinite", field="sigma_q")
    return s


# ---------------------------------------------------------------------------------------------- model
def _derivatives(m: Manipulator, q: np.ndarray, F: np.ndarray):
    """``(tau, J, A)`` in relative angles: ``grad E``, the tip Jacobian, ``Hess(E - F . tip)``.

    The numerics work in absolute angles ``phi = T q`` (``T`` lower-triangular ones): ``grad_q = T^T
    grad_phi``, ``J_q = J_phi T``, ``H_q = T^T H_phi T`` (reverse cumulative sums)."""
    _, g, H, J, _ = chain_solver(m).evaluate(q, F)
    if not isinstance(H, np.ndarray):
        H = H.toarray()
    tau = g[::-1].cumsum()[::-1]
    Jq = J[:, ::-1].cumsum(axis=1)[:, ::-1]
    A = H[::-1].cumsum(axis=0)[::-1]
    A = A[:, ::-1].cumsum(axis=1)[:, ::-1]
    return tau, Jq, 0.5 * (A + A.T)


def _rank_ok(B: np.ndarray) -> bool:
    norms = np.linalg.norm(B, axis=0)
    if np.any(norms == 0.0) or not np.all(np.isfinite(B)):
        return False
    s = np.linalg.svd(B / norms, compute_uv=False)
    return bool(s[-1] > RANK_TOL * s[0])


def _damped(m: Manipulator, q: np.ndarray, hid: np.ndarray, dq: np.ndarray) -> float:
    """The step length ``t <= 1`` keeping the hidden angles inside the range (at most ``TO_LIMIT`` of
    the way to a limit, at most ``MAX_STEP`` rad)."""
    if dq.size == 0:
        return 1.0
    t = 1.0
    big = float(np.abs(dq).max())
    if big > MAX_STEP:
        t = MAX_STEP / big
    lim = m.joint_limits[hid]
    qh = q[hid]
    for i in np.flatnonzero(dq):
        room = lim[i] - math.copysign(1.0, dq[i]) * qh[i]
        t = min(t, TO_LIMIT * room / abs(dq[i]))
    return t


def _bordered(S: np.ndarray, B: np.ndarray):
    """Pseudo-inverse of the scaled bordered matrix ``[[S/alpha, B D^-1], [(B D^-1)^T, 0]]`` with
    ``alpha = max|S|`` and ``D`` the column norms of ``B``; returns ``(Minv, alpha, D)``."""
    n, p = B.shape
    alpha = float(np.abs(S).max())
    D = np.linalg.norm(B, axis=0)
    M = np.zeros((n + p, n + p))
    M[:n, :n] = S / alpha
    M[:n, n:] = B / D
    M[n:, :n] = (B / D).T
    w, V = np.linalg.eigh(M)
    keep = np.abs(w) > 1e-13 * np.abs(w).max()
    Minv = (V[:, keep] / w[keep]) @ V[:, keep].T
    return Minv, alpha, D


# ---------------------------------------------------------------------------------------------- the estimate
def estimate_tip_force(m: Manipulator, q_measured, sigma_q=None, measured=None) -> ForceEstimate:
    """The tip force ``F`` from joint angles, by least squares on the equilibrium ``grad E = J^T F``.

    With ``r(q, F) = grad E(q) - J(q)^T F`` (the residual torque; ``tau = grad E`` is the torque the
    springs take from outside, ``-M`` of eq. 1, ``docs/model.md``) and every joint measured:

    * ``sigma_q=None``: ``F = argmin |r(q, F)|^2`` (eq. 8: ``F = (J J^T)^-1 J grad E``), the residual
      and its norm; no statistics.
    * with the angle noise ``Sigma_q`` (from ``sigma_q``): a noise ``dq`` moves the residual by
      ``A dq`` with ``A = dr/dq = Hess_q(E - F . tip)`` (the spring Hessian minus ``sum_k F_k Hess tip_k``),
      so ``r`` has the covariance ``S = A Sigma_q A^T``. ``F`` is the generalised least-squares estimate
      ``argmin r^T W r``, ``W = S^-1``, with ``S`` evaluated at the estimate (iterated: from the plain
      estimate, ``S`` at the current ``(q, F)``, one GLS step, repeat until the next step is below
      ``REWEIGHT_TOL`` = 1e-6 of every unknown's standard deviation or below ``STEP_TOL``; ``r`` is
      linear in ``F``, so each step is exact for its weight; one or two steps under the null
      hypothesis). When it does not settle in ``MAX_REWEIGHT`` steps (angles far from any equilibrium,
      the weight swinging with the estimate) the one-step estimate is returned with
      ``status="reweighting_not_converged"`` (``success=False``).
      Its covariance
      is ``(J W J^T)^-1`` (linearised: exact to first order in ``Sigma_q``) and
      ``chi2 = r^T W r`` has ``n - 2`` degrees of freedom under the null hypothesis (tip force only).

      Each step solves the bordered system ``[[S, B], [B^T, 0]] [lambda; dx] = [-r; 0]`` (``B = dr/dx``,
      here ``-J^T``); its lower-right block of the inverse is ``-Cov(x)`` and ``chi2 = -lambda^T r``.
      Where ``S`` is invertible this *is* ``(J W J^T)^-1`` and ``r^T W r``; where ``S`` is singular (a
      singular ``Sigma_q`` or ``A``, e.g. at a fold under force control) the combinations of ``r`` with
      no noise are imposed exactly instead of dropped (the pseudo-inverse ``W = S^+`` would drop them);
      where the bordered matrix itself is singular its pseudo-inverse is used. Its upper-left block
      ``P`` (``W - W J^T (J W J^T)^-1 J W`` where ``S`` is invertible) is the residual weight:
      ``lambda = -P r``, ``chi2 = r^T P r``, and ``joint_chi2[j] = (P r)_j^2 / P_jj`` is the part of
      ``chi2`` an unknown extra torque at joint ``j`` would explain (the residual itself need not peak
      at a loaded joint: the fitted force absorbs part of a torque near the base).

    With unmeasured joints (``measured``), their angles ``q_u`` are unknowns too: ``x = (F, q_u)``,
    ``2 + u`` unknowns from the ``n`` equations ``r = 0`` (``B = [-J^T, A[:, u]]``). They are found by
    Gauss-Newton on ``|r|^2`` (damped: a hidden angle stays inside its range, and backtracking; to
    ``STEP_TOL``, or only to ``LOOSE_TOL`` when the weighted steps follow), then, with ``sigma_q``,
    re-weighted as above with ``S = A_m Sigma_m A_m^T`` (``A_m`` the columns of the measured joints,
    ``Sigma_m`` their noise). ``n == 2 + u`` is a square system (Newton; ``dof = 0``, residual zero).
    The solution found is the one the iteration reaches from the start (the entries of ``q_measured``
    at the unmeasured joints, else 0): a nonlinear system may have others.

    Parameters
    ----------
    m : Manipulator
        The chain (``n >= 2``).
    q_measured : array_like (n,) or (k,)
        Joint angles (rad): all ``n`` (the entries at unmeasured joints are only the solver's start; NaN
        there means 0), or the ``k`` measured ones in joint order. Each inside the physical range
        ``|q_i| < pi - 2 beta_i`` (``m.joint_limits``).
    sigma_q : float, array_like (n,) or (k,), or (n, n) or (k, k), optional
        Angle noise: one standard deviation for every joint, one per joint (rad, > 0), or a covariance
        (rad^2; symmetric positive semidefinite with positive variances). Only the measured joints'
        entries are used.
    measured : array_like of bool (n,) or of int, optional
        Which joints are measured (a mask, or 0-based indices); default all.

    Returns
    -------
    ForceEstimate
        ``force``, its ``covariance``, ``residual_torque`` (n), ``chi2`` / ``dof`` / ``p_value``, the
        configuration ``q`` (measured angles as given, unmeasured as estimated), ``status``.

    Raises
    ------
    InvalidParameterError
        (``ValueError``) ``field="q_measured"``: wrong size, non-finite, outside the physical range, or a
        configuration where the torques do not determine the force (collinear links: the straight chain
        feels no torque from an axial force); ``field="sigma_q"``: not finite, not positive, wrong shape,
        not a covariance; ``field="measured"``: a bad mask or index list, fewer equations than unknowns
        (``n < 2 + u``), or unmeasured angles not determined by the torques; ``field="n"``: a chain of
        one joint (one equation).
    SolverError
        (``RuntimeError``) when Gauss-Newton for unmeasured angles does not converge (e.g. it runs into
        a joint limit: no configuration inside the range explains the measurement).

    Examples
    --------
    >>> import tensegrity_opt as to
    >>> m = to.Manipulator.uniform(4)
    >>> eq = to.solve_equilibrium_under_force(m, -0.1, 0.05)
    >>> est = to.estimate_tip_force(m, eq.q, sigma_q=1e-3)
    >>> round(est.fx, 9), round(est.fy, 9), est.dof, est.p_value > 0.5
    (-0.1, 0.05, 2, True)
    """
    unloaded_only(m, "estimate_tip_force")
    linear_only(m, "estimate_tip_force")
    if not isinstance(m, Manipulator):
        raise InvalidParameterError("m must be a Manipulator", field="m")
    n = m.n
    idx = _measured_indices(m, measured)
    hid = np.setdiff1d(np.arange(n), idx)
    u = hid.size
    if n < 2 + u:
        if u == 0:
            raise InvalidParameterError(f"a chain of n = {n} joint gives {n} equilibrium equation for the 2 "
                                        "force components: the tip force needs n >= 2 joints", field="n")
        raise InvalidParameterError(
            f"{n} equilibrium equations cannot determine {2 + u} unknowns (the tip force and the {u} unmeasured "
            f"angles): measure at least {u + 2 - n} more joint(s) (n >= 2 + unmeasured)", field="measured")
    q = _angles(m, q_measured, idx, hid)
    Sigma = None if sigma_q is None else _noise(sigma_q, n, idx)
    ts = m.torque_scale
    tol = STEP_TOL * ts

    # ---- unweighted (Gauss-)Newton on |r|^2; with every joint measured one exact linear step
    tau, J, A = _derivatives(m, q, np.zeros(2))
    if not _rank_ok(-J.T):
        raise InvalidParameterError(
            "the joint torques do not determine the tip force at this configuration: the tip Jacobian has rank "
            "< 2 (collinear links; a force along them makes no torque, as on the straight chain)",
            field="q_measured")
    F = np.linalg.lstsq(J.T, tau, rcond=None)[0]
    iterations = 0
    if u:
        converged = False
        # with sigma_q the weighted iterations below finish the solve: here only to LOOSE_TOL
        gn_tol = tol if Sigma is None else LOOSE_TOL * ts
        tau, J, A = _derivatives(m, q, F)
        r = tau - J.T @ F
        for iterations in range(1, MAX_ITER + 1):
            B = np.hstack([-J.T, A[:, hid]])
            D = np.linalg.norm(B, axis=0)
            D[D == 0.0] = 1.0
            dx = np.linalg.lstsq(B / D, -r, rcond=None)[0] / D
            if np.abs(B @ dx).max() <= gn_tol:
                converged = True
            t = _damped(m, q, hid, dx[2:])
            f0 = float(r @ r)
            pred = f0 - float(np.sum((r + B @ dx) ** 2))      # the decrease Gauss-Newton predicts
            slack = 1e-13 * math.sqrt(f0) * (float(np.linalg.norm(tau)) + ts)   # roundoff of |r|^2
            for _ in range(30):           # backtracking on |r|^2 (Armijo on the predicted decrease)
                qt = q.copy()
                qt[hid] += t * dx[2:]
                Ft = F + t * dx[:2]
                taut, Jt, At = _derivatives(m, qt, Ft)
                rt = taut - Jt.T @ Ft
                if converged or float(rt @ rt) <= f0 - 1e-4 * t * pred + slack:
                    break
                t *= 0.5
            else:
                converged = True            # no descent left: a stationary point of |r|^2 (to roundoff)
                break
            q, F, tau, J, A, r = qt, Ft, taut, Jt, At, rt
            if converged:
                break
        if not converged:
            near = hid[np.abs(q[hid]) > 0.99 * m.joint_limits[hid]]
            if near.size:
                raise NoEquilibriumError(
                    f"no configuration inside the physical range explains these angles: the unmeasured angle "
                    f"q[{int(near[0])}] runs into its joint limit (|r| = {np.linalg.norm(r):.3g})",
                    status="joint_limit")
            raise SolverError(f"Gauss-Newton for the {u} unmeasured angle(s) did not converge in {MAX_ITER} "
                              f"iterations (|r| = {np.linalg.norm(r):.3g}: these angles are far from any "
                              "equilibrium under a tip force)", status="max_iterations")
        if not m.in_range(q):
            raise NoEquilibriumError("the unmeasured angles left the physical range", status="out_of_range")
        if not _rank_ok(np.hstack([-J.T, A[:, hid]])):
            raise InvalidParameterError(
                "the unmeasured angles and the tip force are not determined by the joint torques at this "
                "configuration (the Jacobian of the equilibrium equations in them loses rank): measure more "
                "joints", field="measured")
        status = "gauss_newton"
    else:
        tau, J, A = _derivatives(m, q, F)
        status = "least_squares"
    r = tau - J.T @ F
    dof = n - 2 - u
    cov = hcov = chi2 = p_value = joint = None

    # ---- generalised least squares, the residual covariance at the estimate
    if Sigma is not None:
        s0 = float(np.abs(Sigma).max())
        Sig = Sigma / s0
        settled, first = False, None
        for it in range(MAX_REWEIGHT + 1):
            Am = A[:, idx]
            B = np.hstack([-J.T, A[:, hid]])
            Minv, alpha, D = _bordered(Am @ Sig @ Am.T, B)
            dx = -(Minv[n:, :n] @ r) / D
            sd = np.sqrt(np.maximum(-(s0 * alpha) * np.diag(Minv[n:, n:]), 0.0)) / D
            if np.abs(B @ dx).max() <= tol or np.all(np.abs(dx) <= REWEIGHT_TOL * sd):
                settled = True                   # the weight at the estimate reproduces the estimate
                break
            if it == MAX_REWEIGHT:
                break
            t = _damped(m, q, hid, dx[2:])
            q = q.copy()
            q[hid] += t * dx[2:]
            F = F + t * dx[:2]
            tau, J, A = _derivatives(m, q, F)
            r = tau - J.T @ F
            iterations += 1
            if first is None:
                first = (q, F, tau, J, A, r)
        if not settled:
            # no fixed point reached (data far from any equilibrium under a tip force: the weight swings
            # with the estimate): report the one-step estimate, the weight at the unweighted one
            q, F, tau, J, A, r = first
            Am = A[:, idx]
            Minv, alpha, D = _bordered(Am @ Sig @ Am.T, np.hstack([-J.T, A[:, hid]]))
        if not m.in_range(q):
            raise NoEquilibriumError("the unmeasured angles left the physical range", status="out_of_range")
        C = -(s0 * alpha) * Minv[n:, n:] / np.outer(D, D)
        C = 0.5 * (C + C.T)
        cov, hcov = C[:2, :2], C[2:, 2:]
        P = Minv[:n, :n] / (alpha * s0)              # the residual weight: lambda = -P r, chi2 = r^T P r
        Pr = P @ r
        chi2 = max(0.0, float(r @ Pr))
        d = np.diag(P)
        ok = d > 1e-12 * max(float(np.abs(d).max()), np.finfo(float).tiny)
        joint = np.zeros(n)
        joint[ok] = Pr[ok] ** 2 / d[ok]
        if dof > 0:
            from scipy.special import chdtrc  # = scipy.stats.chi2.sf (its implementation), 50x cheaper

            p_value = float(chdtrc(dof, chi2))
        status = "generalized_least_squares" if u == 0 else "weighted_gauss_newton"
        if not settled:
            status = "reweighting_not_converged"

    return ForceEstimate(force=np.asarray(F, float).copy(), covariance=cov, residual_torque=r.copy(),
                         residual_norm=float(np.linalg.norm(r)), chi2=chi2, dof=dof, p_value=p_value, joint_chi2=joint,
                         q=q.copy(), measured=tuple(int(i) for i in idx), hidden_covariance=hcov,
                         status=status, iterations=iterations, springs=m.springs)
