"""Independent reference of a chain under DEAD LOADS: weights under gravity, a payload, forces at the joints.

Imports numpy, scipy and the sibling references -- never ``tensegrity_opt`` (:func:`segs_of` and :func:`loads_of`
read a ``Manipulator`` duck-typed):

* :mod:`reference_tension_only` (``RT``): the triangles' vertices, the spring energy from the vertex distances,
  the joint torques from the spring force vectors, the tip, the two-link inverse kinematics of its brute force;
* :mod:`reference_dynamics` (``RD``): the moving bodies (the triangles' centroids as the mean of their vertices, the
  payload at the tip) and the mass matrix;
* :mod:`reference_equilibria_tension` (``RE``): the closed-form one-joint energy derivatives and the chart inverse
  kinematics (both self-tested there against the vertex model).

The chain: ``segs`` a list of dicts ``{a, b, k1, k2, L10, L20, law, mass, inertia}`` (base first), ``loads`` a dict
``{payload, gravity (gx, gy) or None, joint_forces ((j, (fx, fy)), ...)}`` (joints 1-based, joint 1 at ``(b_1, 0)``).

The load points, built from the geometry (not from lever formulas):

* each moving triangle's centroid (the mean of its apex -- the joint -- and its two far vertices): the lower
  triangle of segment ``i`` in the frame of the link before joint ``i``, the upper one turned by ``q_i`` too; weight
  ``m_i / 2 * g``; the lower triangle of segment 1 belongs to the fixed base and is not a load point (as in
  ``RD._bodies``);
* the payload at the tip, weight ``payload * g``;
* joint ``j`` at ``p_j`` (``p_1 = (b_1, 0)``, ``p_{j+1} = p_j + l_j (cos phi_j, sin phi_j)``), force ``f_j``.

The potential of the loads ``V(q) = -sum_points w . x(q)`` (with its constant: positions are absolute); the chain's
potential ``E(q) + V(q)``, ``E`` the springs' energy under each spring's law. Derivatives, from the rigid motions:
a point ``x`` carried by joint ``j`` (the joint turns everything after it) moves with ``dx/dq_j = perp(x - p_j)``,
``d2x/dq_j dq_k = -(x - p_{max(j, k)})``; so ``dV/dq_j = -sum w . perp(x - p_j)``, ``d2V/dq_j dq_k =
sum w . (x - p_{max(j,k)})`` over the points both joints carry (the tip likewise: ``Hess(-F . tip)``). The
functions ``*_fd`` give the same by five-point differences (``RD._diff``), for the self-checks.

Solvers (``n <= 4``):

* :func:`least_potential`: the least ``E + V`` with the tip on a target over the CLOSED range: every chart of the
  constraint manifold (``n - 2`` joints on a grid over their closed range, the other two by inverse kinematics, both
  elbows; n = 2 the two elbows alone), the best distinct grid points polished by SLSQP (bounds: the stops) and then
  by Newton on the KKT system with the joints that SLSQP left on a stop held there;
* :func:`least_potential_free`: the least ``E + V`` with a free tip (no tip force; the sagged rest shape): a dense
  grid over the closed box, the best distinct points polished by SLSQP with bounds, then Newton;
* :func:`equilibria`: every equilibrium with the tip on the target (interior and on every admissible stop set), by
  sign changes of the manifold gradient on dense charts (1-D: Brent; 2-D: cells and small-gradient minima), Newton
  on the KKT system, dedupe; the Morse index on the tangent space (``RE``'s method, the gradient ``dE`` replaced by
  ``d(E + V)``, the Hessian by the full one);
* :func:`modes`: ``K`` the Hessian of ``E + V - F . tip`` reduced to the motions tangent to the held tip and the
  held stops, ``M`` from ``RD.mass_matrix``, ``scipy.linalg.eigh``.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field

import numpy as np
import reference_dynamics as RD
import reference_equilibria_tension as RE
import reference_tension_only as RT
import scipy.linalg as sla
import scipy.optimize as so

#: a joint within this of its stop is at the stop
AT_STOP_TOL = 1e-7
#: KKT residual accepted by Newton (relative to max k c^2 and sum b)
KKT_TOL = 1e-11
#: contact torques below -CONTACT_TOL (relative) are not equilibria
CONTACT_TOL = 1e-8
#: reduced-Hessian eigenvalues this small (relative) are singular
EIG_TOL = 1e-8
#: dedupe in q (max-norm)
DEDUP = 1e-7


# ---------------------------------------------------------------------------- the chain
def segs_of(m) -> list[dict]:
    """``RT.segs_of`` plus each segment's ``mass`` and ``inertia`` (duck-typed)."""
    return [dict(d, mass=float(getattr(s, "mass", 0.0)), inertia=float(getattr(s, "inertia", 0.0)))
            for d, s in zip(RT.segs_of(m), m.segments)]


def loads_of(m) -> dict:
    """``{payload, gravity, joint_forces}`` of a ``Manipulator`` (duck-typed)."""
    g = getattr(m, "gravity", None)
    return dict(payload=float(getattr(m, "payload", 0.0)), gravity=None if g is None else tuple(map(float, g)),
                joint_forces=tuple((int(j), tuple(map(float, f))) for j, f in getattr(m, "joint_forces", ())))


@dataclass
class _Model:
    segs: list
    loads: dict
    P: object                 # RT._P
    ch: object                # RE._Chain
    W: np.ndarray             # (npts, 2) the dead forces
    moved: np.ndarray         # (npts,) the point is carried by joints 0..moved-1 (0-based)
    kinds: list = field(default_factory=list)   # ("lower", i) / ("upper", i) / ("joint", j) / ("tip",)

    @property
    def n(self) -> int:
        return self.P.n

    @property
    def lim(self) -> np.ndarray:
        return self.P.limits

    @property
    def scale_e(self) -> float:
        return self.ch.scale_e

    @property
    def scale_x(self) -> float:
        return self.ch.scale_x


def model(segs, loads=None) -> _Model:
    loads = dict(payload=0.0, gravity=None, joint_forces=()) | dict(loads or {})
    P = RT._params(segs)
    ch = RE._chain(segs)
    n = P.n
    g = np.zeros(2) if loads["gravity"] is None else np.asarray(loads["gravity"], float)
    W, moved, kinds = [], [], []
    for i, s in enumerate(segs):
        if i > 0:
            W.append(0.5 * s.get("mass", 0.0) * g), moved.append(i), kinds.append(("lower", i))
        W.append(0.5 * s.get("mass", 0.0) * g), moved.append(i + 1), kinds.append(("upper", i))
    W.append(float(loads["payload"]) * g), moved.append(n), kinds.append(("tip",))
    for j, f in loads["joint_forces"]:
        if not 1 <= int(j) <= n:
            raise ValueError(f"joint {j} is not a joint of a chain of {n}")
        W.append(np.asarray(f, float)), moved.append(int(j) - 1), kinds.append(("joint", int(j)))
    return _Model(segs=list(segs), loads=loads, P=P, ch=ch, W=np.array(W, float).reshape(-1, 2),
                  moved=np.array(moved, int), kinds=kinds)


def _M(segs, loads) -> _Model:
    return segs if isinstance(segs, _Model) else model(segs, loads)


# ---------------------------------------------------------------------------- the points
def _local_points(M: _Model):
    """Each load point as ``(joint index, angle index, local vector)``: the point is ``p_joint + R(phi_angle) local``
    (``phi_i = q_1 + ... + q_i``, ``phi_0 = 0`` the base). The triangles' centroids are the means of their three
    vertices (``RT._vertices`` at ``q = 0``: the upper triangle turns with its joint, ``R(phi_i) R(q_i) =
    R(phi_{i+1})``)."""
    cached = getattr(M, "_local", None)
    if cached is not None:
        return cached
    v, w = RT._vertices(M.P, np.zeros(M.n))
    n = M.n
    jp, ap, lp = [], [], []
    for kind in M.kinds:
        if kind[0] == "lower":
            i = kind[1]
            jp.append(i), ap.append(i), lp.append((np.zeros(2) + w[i, 0] + w[i, 1]) / 3.0)
        elif kind[0] == "upper":
            i = kind[1]
            jp.append(i), ap.append(i + 1), lp.append((np.zeros(2) + v[i, 0] + v[i, 1]) / 3.0)
        elif kind[0] == "tip":
            jp.append(n - 1), ap.append(n), lp.append(np.array([M.P.links[n - 1], 0.0]))
        else:
            jp.append(kind[1] - 1), ap.append(0), lp.append(np.zeros(2))
    M._local = (np.array(jp, int), np.array(ap, int), np.array(lp, float).reshape(-1, 2))
    return M._local


def _geometry(M: _Model, Q):
    """``X (N, npts, 2)`` the load points, ``Pj (N, n, 2)`` the joints, ``tip (N, 2)`` of the rows of ``Q``."""
    Q = np.atleast_2d(np.asarray(Q, float))
    N, n = Q.shape
    P = M.P
    phi = np.concatenate([np.zeros((N, 1)), np.cumsum(Q, 1)], 1)  # phi[:, i]: the link before joint i
    c, s = np.cos(phi), np.sin(phi)
    Pj = np.empty((N, n, 2))
    Pj[:, 0, 0], Pj[:, 0, 1] = P.b[0], 0.0
    Pj[:, 1:, 0] = P.b[0] + np.cumsum(P.links[:-1] * c[:, 1:n], 1)
    Pj[:, 1:, 1] = np.cumsum(P.links[:-1] * s[:, 1:n], 1)
    tip = Pj[:, n - 1] + P.links[n - 1] * np.stack([c[:, n], s[:, n]], -1)
    jp, ap, lp = _local_points(M)
    X = np.empty((N, jp.size, 2))
    X[..., 0] = Pj[:, jp, 0] + c[:, ap] * lp[:, 0] - s[:, ap] * lp[:, 1]
    X[..., 1] = Pj[:, jp, 1] + s[:, ap] * lp[:, 0] + c[:, ap] * lp[:, 1]
    return X, Pj, tip


def load_points(segs, loads, q):
    """``(W (npts, 2), X (npts, 2), kinds)``: every dead force and its point at ``q``."""
    M = _M(segs, loads)
    X, _, _ = _geometry(M, q)
    return M.W.copy(), X[0], list(M.kinds)


def joints(segs, q) -> np.ndarray:
    """The joints' positions (n, 2) at ``q``."""
    return _geometry(model(segs), q)[1][0]


# ---------------------------------------------------------------------------- potentials and derivatives
def _V(M: _Model, Q):
    X, _, _ = _geometry(M, Q)
    return -np.einsum("npk,pk->n", X, M.W)


def _dV(M: _Model, Q):
    """``dV/dq`` (N, n): ``-sum_p [moved_p > j] (x_p - p_j) x w_p`` (``a x b = a_x b_y - a_y b_x``)."""
    X, Pj, _ = _geometry(M, Q)
    n = M.n
    out = np.zeros((X.shape[0], n))
    for j in range(n):
        sel = M.moved > j
        d = X[:, sel] - Pj[:, j, None]
        out[:, j] = -np.sum(d[..., 0] * M.W[sel, 1] - d[..., 1] * M.W[sel, 0], 1)
    return out


def _d2V(M: _Model, q):
    """``d2V/dq2`` (n, n) at one ``q``: ``sum_p [moved_p > max(j, k)] w_p . (x_p - p_max)``."""
    X, Pj, _ = _geometry(M, q)
    n = M.n
    H = np.zeros((n, n))
    for j, k in itertools.product(range(n), repeat=2):
        mx = max(j, k)
        sel = M.moved > mx
        H[j, k] = float(np.sum((X[0, sel] - Pj[0, mx]) * M.W[sel]))
    return H


def _tip_hess_dot(M: _Model, q, F):
    """``Hess(-F . tip)`` (n, n) at ``q``: ``F . (tip - p_max(j,k))``."""
    _, Pj, tip = _geometry(M, q)
    n = M.n
    idx = np.maximum.outer(np.arange(n), np.arange(n))
    return np.einsum("jkd,d->jk", tip[0][None, None] - Pj[0][idx], np.asarray(F, float))


def load_potential(segs, loads, q) -> float:
    """``V(q) = -sum w . x`` (with its constant)."""
    return float(_V(_M(segs, loads), q)[0])


def load_gradient(segs, loads, q) -> np.ndarray:
    return _dV(_M(segs, loads), q)[0]


def load_hessian(segs, loads, q) -> np.ndarray:
    return _d2V(_M(segs, loads), q)


def potential(segs, loads, q) -> float:
    """``E + V``: the springs' energy from the vertex distances (``RT.energy``) plus :func:`load_potential`."""
    M = _M(segs, loads)
    return float(RT._energy(M.P, np.asarray(q, float)) + _V(M, q)[0])


def _potential_many(M: _Model, Q):
    """``E + V`` of the rows of ``Q``, ``E`` by ``RE``'s closed form (fast; :func:`potential` builds it from the
    vertices)."""
    Q = np.atleast_2d(np.asarray(Q, float))
    return RE._energy_derivs(M.ch, Q, second=False)[0] + _V(M, Q)


def gradient(segs, loads, q) -> np.ndarray:
    """``d(E + V)/dq``: ``-RT.torques`` (the spring force vectors' moments) plus :func:`load_gradient`."""
    M = _M(segs, loads)
    return -RT._torques(M.P, np.asarray(q, float)) + _dV(M, q)[0]


def _grad_many(M: _Model, Q):
    Q = np.atleast_2d(np.asarray(Q, float))
    return RE._energy_derivs(M.ch, Q, second=False)[1] + _dV(M, Q)


def hessian(segs, loads, q, F=None) -> np.ndarray:
    """Hessian of ``E + V - F . tip`` (``F`` default 0): ``RE``'s closed-form ``E''`` (diagonal; the taut side only
    where ``L > L0`` strictly) plus :func:`load_hessian` plus ``Hess(-F . tip)``."""
    M = _M(segs, loads)
    q = np.asarray(q, float)
    _, _, d2E = RE._energy_derivs(M.ch, q)
    H = np.diag(d2E) + _d2V(M, q)
    if F is not None:
        H = H + _tip_hess_dot(M, q, F)
    return H


def gradient_fd(segs, loads, q) -> np.ndarray:
    """Five-point differences of :func:`potential`."""
    M = _M(segs, loads)
    return RD._diff(lambda x: np.array(potential(M, None, x)), q)


def hessian_fd(segs, loads, q, F=None) -> np.ndarray:
    """Five-point differences of :func:`gradient` (and of ``-J^T F``)."""
    M = _M(segs, loads)
    F = np.zeros(2) if F is None else np.asarray(F, float)
    H = RD._diff(lambda x: gradient(M, None, x) - RT._jac(M.P, x).T @ F, q)
    return 0.5 * (H + H.T)


def tip(segs, q) -> np.ndarray:
    return RT.tip(segs, q)


def tip_jacobian(segs, q) -> np.ndarray:
    return RT.tip_jacobian(segs, q)


def target(segs, dx, dy=0.0) -> np.ndarray:
    return RT.target(segs, dx, dy)


# ---------------------------------------------------------------------------- KKT helpers
def _kin(M: _Model, q):
    q = np.asarray(q, float)
    return RT._tip(M.P, q), RT._jac(M.P, q)


def _force(M: _Model, q, free):
    """``F`` balancing ``d(E+V) = J^T F`` on the free joints (least squares; zeros when < 2 free)."""
    g = _grad_many(M, q)[0]
    _, J = _kin(M, q)
    free = np.asarray(free, bool)
    if free.sum() == 0:
        return np.zeros(2), g, J
    return np.linalg.lstsq(J[:, free].T, g[free], rcond=None)[0], g, J


def _newton(M: _Model, q0, free, tgt, F0=None, iters=80):
    """Damped Newton on ``d(E+V)_f - J_f^T F = 0``, ``tip = tgt`` in ``(q_f, F)``; ``tgt`` None: a free tip
    (``F = 0``, ``d(E+V)_f = 0``). Returns ``(q, F, ok)``."""
    free = np.flatnonzero(np.asarray(free, bool)) if np.asarray(free).dtype == bool else np.asarray(free, int)
    nf = free.size
    q = np.array(q0, float)
    held = tgt is not None
    if held:
        F = _force(M, q, np.isin(np.arange(M.n), free))[0] if F0 is None else np.array(F0, float)
    else:
        F = np.zeros(2)

    def resid(q, F):
        g = _grad_many(M, q)[0]
        t, J = _kin(M, q)
        r = g[free] - (J[:, free].T @ F if held else 0.0)
        if held:
            return np.concatenate([r, t - tgt]), J
        return r, J

    def norm(r):
        a = float(np.max(np.abs(r[:nf]), initial=0.0)) / M.scale_e
        return max(a, float(np.max(np.abs(r[nf:]), initial=0.0)) / M.scale_x)

    r, J = resid(q, F)
    nr = norm(r)
    for _ in range(iters):
        if nr < 1e-15:
            break
        H = hessian(M, None, q, F if held else None)[np.ix_(free, free)]
        if held:
            Jf = J[:, free]
            K = np.block([[H, -Jf.T], [Jf, np.zeros((2, 2))]])
        else:
            K = H
        try:
            step = np.linalg.solve(K, -r)
        except np.linalg.LinAlgError:
            step = np.linalg.lstsq(K, -r, rcond=None)[0]
        dq = step[:nf]
        big = float(np.max(np.abs(dq), initial=0.0))
        t = 1.0 if big < 0.5 else 0.5 / big
        improved = False
        for _ in range(30):
            qt = q.copy()
            qt[free] += t * dq
            Ft = F + t * step[nf:] if held else F
            rt, Jt = resid(qt, Ft)
            nt = norm(rt)
            if nt < nr or nt < 1e-15:
                improved = True
                break
            t *= 0.5
        if not improved:
            break
        q, F, r, J, nr = qt, Ft, rt, Jt, nt
    return q, F, nr < KKT_TOL


@dataclass
class Result:
    q: np.ndarray
    energy: float                  # E + V
    force: np.ndarray              # the tip force (zeros for a free tip)
    at_stop: np.ndarray            # (n,) bool
    contact_torques: np.ndarray    # (n,) >= 0 up to CONTACT_TOL: -s_i (d(E+V)_i - (J^T F)_i)
    morse_index: int               # on the motions tangent to the tip (held) and the stops
    eigenvalues: np.ndarray
    residual: float                # max |KKT| over the free rows and the tip rows (absolute)
    minima: list = field(default_factory=list)    # (energy, q) of the distinct polished local minima, ascending
    grid_energy: float = math.nan

    @property
    def stable(self) -> bool:
        return self.morse_index == 0

    @property
    def runner_up_gap(self) -> float:
        """The energy gap to the next distinct polished minimum (inf when none)."""
        return self.minima[1][0] - self.minima[0][0] if len(self.minima) > 1 else math.inf


def _classify(M: _Model, q, tgt, stops=None) -> Result:
    q = np.asarray(q, float)
    if stops is None:
        stops = np.where(np.abs(q) >= M.lim - AT_STOP_TOL, np.sign(q), 0.0).astype(int)
    stops = np.asarray(stops, int)
    q = np.where(stops != 0, stops * M.lim, q)
    free = stops == 0
    held = tgt is not None
    if held:
        F, g, J = _force(M, q, free)
    else:
        F, g, J = np.zeros(2), _grad_many(M, q)[0], _kin(M, q)[1]
    res = g - J.T @ F
    contact = np.where(stops != 0, -stops * res, 0.0)
    t, _ = _kin(M, q)
    residual = max(float(np.max(np.abs(res[free]), initial=0.0)), float(np.max(np.abs(t - tgt))) if held else 0.0)
    rows = [np.eye(M.n)[~free]] + ([J] if held else [])
    C = np.vstack(rows)
    Z = sla.null_space(C) if C.shape[0] else np.eye(M.n)
    H = hessian(M, None, q, F if held else None)
    eig = np.linalg.eigvalsh(Z.T @ H @ Z) if Z.shape[1] else np.zeros(0)
    return Result(q=q, energy=float(_potential_many(M, q)[0]), force=F, at_stop=~free,
                  contact_torques=contact, morse_index=int(np.sum(eig < -EIG_TOL * M.scale_e)), eigenvalues=eig,
                  residual=residual)


def _distinct(S, E, m, sep):
    order = np.argsort(E, kind="stable")
    keep: list[int] = []
    for j in order:
        if all(np.max(np.abs(S[j] - S[i])) > sep for i in keep):
            keep.append(int(j))
            if len(keep) == m:
                break
    return keep


def _refine(M: _Model, q, tgt):
    """Newton with the joints on a stop held there; the Newton point when it converges in the closed range with a
    potential no higher (to rounding) than ``q``'s, else ``q``."""
    q = np.clip(np.asarray(q, float), -M.lim, M.lim)
    stops = np.where(np.abs(q) >= M.lim - AT_STOP_TOL, np.sign(q), 0.0)
    qs = np.where(stops != 0, stops * M.lim, q)
    qn, _, ok = _newton(M, qs, stops == 0, tgt)
    e0 = float(_potential_many(M, q)[0])
    if ok and np.all(np.abs(qn) <= M.lim + 1e-12):
        qn = np.clip(qn, -M.lim, M.lim)
        if float(_potential_many(M, qn)[0]) <= e0 + 1e-10 * M.scale_e:
            return qn
    return q


# ---------------------------------------------------------------------------- least potential, tip held
def manifold_grid(segs, loads, dx, dy=0.0, grid=None):
    """Points of ``tip = target`` in the closed range: every chart (``n - 2`` joints on ``grid`` points each, the
    other two by inverse kinematics, both elbows). Returns ``(S (N, n), spacing)``."""
    M = _M(segs, loads)
    n = M.n
    tgt = RT.target(M.segs, dx, dy)
    g = int(grid) if grid is not None else {2: 1, 3: 2001, 4: 151}[n]
    out = []
    for pair in itertools.combinations(range(n), 2):
        params = [p for p in range(n) if p not in pair]
        axes = [np.linspace(-M.lim[p], M.lim[p], g) for p in params]
        Q = np.zeros((g ** len(params), n)) if params else np.zeros((1, n))
        if params:
            mesh = np.meshgrid(*axes, indexing="ij")
            for p, X in zip(params, mesh):
                Q[:, p] = X.ravel()
        for sigma in (1.0, -1.0):
            Qs, ok = RE._ik(M.ch, Q, pair[0], pair[1], sigma, tgt)
            Qs = Qs[ok]
            tip_ok = np.max(np.abs(RT._tip(M.P, Qs) - tgt), axis=1) < 1e-9 * M.scale_x
            Qs = Qs[tip_ok & np.all(np.abs(Qs) <= M.lim, axis=1)]
            out.append(Qs)
    S = np.concatenate(out) if out else np.zeros((0, n))
    spacing = 2.0 * float(np.max(M.lim)) / max(g - 1, 1)
    return S, spacing


def _polish_held(M: _Model, q0, tgt):
    bounds = list(zip(-M.lim, M.lim))
    cons = {"type": "eq", "fun": lambda q: RT._tip(M.P, q) - tgt, "jac": lambda q: RT._jac(M.P, q)}
    q = np.clip(q0, -M.lim, M.lim)
    r = so.minimize(lambda x: float(_potential_many(M, x)[0]), q, jac=lambda x: _grad_many(M, x)[0],
                    method="SLSQP", bounds=bounds, constraints=[cons], options={"ftol": 1e-14, "maxiter": 500})
    return np.clip(r.x, -M.lim, M.lim)


def least_potential(segs, loads, dx, dy=0.0, *, grid=None, candidates=12) -> Result:
    """The least ``E + V`` with ``tip = target(dx, dy)`` over the closed range (``2 <= n <= 4``; module docstring).
    ``minima`` lists the distinct polished local minima (energy, q), ascending."""
    M = _M(segs, loads)
    if not 2 <= M.n <= 4:
        raise ValueError("least_potential brute-forces 2 <= n <= 4 segments")
    tgt = RT.target(M.segs, dx, dy)
    S, spacing = manifold_grid(M, None, dx, dy, grid)
    if S.shape[0] == 0:
        raise ValueError("the target is not reachable in the closed range")
    E = _potential_many(M, S)
    keep = _distinct(S, E, candidates, 2.0 * spacing)
    found = []
    for j in keep:
        q = _polish_held(M, S[j], tgt)
        if np.max(np.abs(RT._tip(M.P, q) - tgt)) < 1e-9 * M.scale_x:
            found.append(_refine(M, q, tgt))
    if not found:
        raise ValueError("no polished candidate meets the target")
    Ef = _potential_many(M, np.array(found))
    minima = []
    for j in np.argsort(Ef, kind="stable"):
        if all(np.max(np.abs(found[j] - q)) > 1e-5 for _, q in minima):
            minima.append((float(Ef[j]), found[j]))
    r = _classify(M, minima[0][1], tgt)
    r.minima, r.grid_energy = minima, float(E[keep[0]])
    return r


# ---------------------------------------------------------------------------- least potential, tip free
def least_potential_free(segs, loads, *, grid=None, candidates=10, chunk=200_000) -> Result:
    """The least ``E + V`` over the closed box (no tip force: the rest shape under the loads); ``2 <= n <= 4``."""
    M = _M(segs, loads)
    n = M.n
    g = int(grid) if grid is not None else {1: 2001, 2: 201, 3: 61, 4: 31}[n]
    axes = [np.linspace(-M.lim[i], M.lim[i], g) for i in range(n)]
    total = g ** n
    bestE, bestQ = [], []
    for start in range(0, total, chunk):
        idx = np.arange(start, min(total, start + chunk))
        sub = np.unravel_index(idx, (g,) * n)
        Q = np.column_stack([axes[i][sub[i]] for i in range(n)])
        E = _potential_many(M, Q)
        take = np.argsort(E)[:20 * candidates]
        bestE.append(E[take]), bestQ.append(Q[take])
    E, S = np.concatenate(bestE), np.concatenate(bestQ)
    spacing = 2.0 * float(np.max(M.lim)) / (g - 1)
    keep = _distinct(S, E, candidates, 2.0 * spacing)
    bounds = list(zip(-M.lim, M.lim))
    found = []
    for j in keep:
        r = so.minimize(lambda x: float(_potential_many(M, x)[0]), S[j], jac=lambda x: _grad_many(M, x)[0],
                        method="SLSQP", bounds=bounds, options={"ftol": 1e-14, "maxiter": 500})
        found.append(_refine(M, np.clip(r.x, -M.lim, M.lim), None))
    Ef = _potential_many(M, np.array(found))
    minima = []
    for j in np.argsort(Ef, kind="stable"):
        if all(np.max(np.abs(found[j] - q)) > 1e-5 for _, q in minima):
            minima.append((float(Ef[j]), found[j]))
    r = _classify(M, minima[0][1], None)
    r.minima, r.grid_energy = minima, float(E[keep[0]])
    return r


# ---------------------------------------------------------------------------- every equilibrium, tip held
def _g_scaled(M: _Model, Q, i, j, params):
    """``(dP_p - J_p^T F) det J_r`` with ``F = J_r^{-T} dP_r`` (``P = E + V``), and ``det J_r``, ``J``."""
    dP = _grad_many(M, Q)
    _, J, _, _ = RE._kin(M.ch, Q)
    Jx, Jy = J[:, 0], J[:, 1]
    det = Jx[:, i] * Jy[:, j] - Jy[:, i] * Jx[:, j]
    gi, gj = dP[:, i], dP[:, j]
    Fdx = Jy[:, j] * gi - Jy[:, i] * gj
    Fdy = -Jx[:, j] * gi + Jx[:, i] * gj
    G = np.stack([dP[:, p] * det - (Jx[:, p] * Fdx + Jy[:, p] * Fdy) for p in params], -1) if params else \
        np.zeros((Q.shape[0], 0))
    return G, det, J


def _in_ext(M, Q, margin):
    return np.all(np.abs(Q) <= M.lim + margin, axis=-1)


def _seeds_rigid(M, tgt, base, free):
    i, j = free
    out = []
    for sigma in (1.0, -1.0):
        Q, ok = RE._ik(M.ch, base[None], i, j, sigma, tgt)
        if ok[0]:
            out.append(Q[0])
    return out


def _seeds_curve(M, tgt, base, free, grid, margin):
    """One free parameter: every chart (parameter ``p``, the other two free joints by IK), both elbows; Brent on
    the sign changes of ``g det J_r``; plus the grid's local minima of ``|g det J_r|`` (a tangency)."""
    out = []
    for p in free:
        i, j = sorted(set(free) - {p})
        xs = np.linspace(-M.lim[p], M.lim[p], grid)
        Q = np.tile(base, (grid, 1))
        Q[:, p] = xs
        for sigma in (1.0, -1.0):
            Qs, ok = RE._ik(M.ch, Q, i, j, sigma, tgt)
            ok &= _in_ext(M, Qs, margin)
            G = _g_scaled(M, Qs, i, j, [p])[0][:, 0]
            br = np.flatnonzero(ok[:-1] & ok[1:] & (G[:-1] * G[1:] <= 0))

            def f(x, i=i, j=j, p=p, sigma=sigma):
                row = base.copy()
                row[p] = x
                Qx, okx = RE._ik(M.ch, row[None], i, j, sigma, tgt)
                if not okx[0]:
                    raise ValueError("left the branch")
                return float(_g_scaled(M, Qx, i, j, [p])[0][0, 0])

            for kk in br:
                try:
                    x = so.brentq(f, xs[kk], xs[kk + 1], xtol=1e-14, rtol=4 * np.finfo(float).eps, maxiter=200)
                except ValueError:
                    x = 0.5 * (xs[kk] + xs[kk + 1])
                row = base.copy()
                row[p] = x
                Qx, okx = RE._ik(M.ch, row[None], i, j, sigma, tgt)
                out.append(Qx[0] if okx[0] else Qs[kk])
            a = np.where(ok, np.abs(G), np.inf)
            loc = np.flatnonzero((a[1:-1] <= a[:-2]) & (a[1:-1] <= a[2:]) & np.isfinite(a[1:-1])) + 1
            scale = np.percentile(a[np.isfinite(a)], 90) if np.isfinite(a).any() else 1.0
            out.extend(Qs[loc[a[loc] < 0.02 * max(scale, 1e-300)]])
    return out


def _best_minor(J, free):
    Jx, Jy = J[:, 0], J[:, 1]
    return np.max([np.abs(Jx[:, a] * Jy[:, b] - Jy[:, a] * Jx[:, b]) for a, b in itertools.combinations(free, 2)],
                  axis=0)


def _seeds_surface(M, tgt, base, free, grid, margin, minima=200, responsible=0.3, small=0.05):
    """Two free parameters (n = 4 interior): every chart, both elbows; cells with a sign change of both components
    (seeded at the cell's linearised zero) and the grid's small-gradient local minima."""
    out = []
    for i, j in itertools.combinations(free, 2):
        p1, p2 = sorted(set(free) - {i, j})
        x1 = np.linspace(-M.lim[p1], M.lim[p1], grid)
        x2 = np.linspace(-M.lim[p2], M.lim[p2], grid)
        h1, h2 = x1[1] - x1[0], x2[1] - x2[0]
        X1, X2 = np.meshgrid(x1, x2, indexing="ij")
        Q = np.tile(base, (grid * grid, 1))
        Q[:, p1], Q[:, p2] = X1.ravel(), X2.ravel()
        for sigma in (1.0, -1.0):
            Qs, ok = RE._ik(M.ch, Q, i, j, sigma, tgt)
            ok &= _in_ext(M, Qs, margin)
            G, det, J = _g_scaled(M, Qs, i, j, [p1, p2])
            G = np.where(ok[:, None], G, np.nan).reshape(grid, grid, 2)
            okg = ok.reshape(grid, grid)
            resp = (ok & (np.abs(det) >= responsible * _best_minor(J, free))).reshape(grid, grid)
            V = okg[:-1, :-1] & okg[1:, :-1] & okg[:-1, 1:] & okg[1:, 1:]
            V &= resp[:-1, :-1] | resp[1:, :-1] | resp[:-1, 1:] | resp[1:, 1:]
            corners = np.stack([G[:-1, :-1], G[1:, :-1], G[:-1, 1:], G[1:, 1:]])
            with np.errstate(invalid="ignore"):
                mn = np.nanmin(np.where(V[None, ..., None], corners, 0), 0)
                mx = np.nanmax(np.where(V[None, ..., None], corners, 0), 0)
            cand = V & (mn[..., 0] <= 0) & (mx[..., 0] >= 0) & (mn[..., 1] <= 0) & (mx[..., 1] >= 0)
            a_idx, b_idx = np.nonzero(cand)
            pts = []
            if a_idx.size:
                g00 = G[a_idx, b_idx]
                d1 = (G[a_idx + 1, b_idx] - g00) / h1
                d2 = (G[a_idx, b_idx + 1] - g00) / h2
                A = np.stack([d1, d2], -1)
                dlin = A[:, 0, 0] * A[:, 1, 1] - A[:, 0, 1] * A[:, 1, 0]
                with np.errstate(divide="ignore", invalid="ignore"):
                    s1 = -(A[:, 1, 1] * g00[:, 0] - A[:, 0, 1] * g00[:, 1]) / dlin
                    s2 = -(-A[:, 1, 0] * g00[:, 0] + A[:, 0, 0] * g00[:, 1]) / dlin
                s1 = np.where(np.isfinite(s1), np.clip(s1, -h1, 2 * h1), 0.5 * h1)
                s2 = np.where(np.isfinite(s2), np.clip(s2, -h2, 2 * h2), 0.5 * h2)
                pts.append(np.column_stack([x1[a_idx] + s1, x2[b_idx] + s2]))
            scale = np.nanpercentile(np.abs(G[okg]), 90, axis=0) if okg.any() else np.ones(2)
            scale = np.where(scale > 0, scale, 1.0)
            rho = np.where(okg & resp, np.abs(G[..., 0]) / scale[0] + np.abs(G[..., 1]) / scale[1], np.inf)
            inner = rho[1:-1, 1:-1]
            is_min = np.isfinite(inner)
            for da in (-1, 0, 1):
                for db in (-1, 0, 1):
                    if da or db:
                        is_min &= inner <= rho[1 + da:grid - 1 + da, 1 + db:grid - 1 + db]
            ma, mb = np.nonzero(is_min & (inner < small))
            if ma.size:
                order = np.argsort(inner[ma, mb])[:minima]
                pts.append(np.column_stack([x1[ma[order] + 1], x2[mb[order] + 1]]))
            if not pts:
                continue
            Pp = np.concatenate(pts)
            Qp = np.tile(base, (Pp.shape[0], 1))
            Qp[:, p1], Qp[:, p2] = Pp[:, 0], Pp[:, 1]
            Qp, okp = RE._ik(M.ch, Qp, i, j, sigma, tgt)
            out.extend(Qp[okp])
    return out


@dataclass
class Record:
    q: np.ndarray
    F: np.ndarray
    energy: float                  # E + V
    morse_index: int
    stops: np.ndarray              # (n,) -1 / 0 / +1
    contact_torques: np.ndarray
    eigenvalues: np.ndarray
    degenerate: bool
    reasons: tuple = ()

    @property
    def at_stop(self) -> np.ndarray:
        return self.stops != 0


def _record(M: _Model, q, F, stops, tgt):
    stops = np.array(stops, int)
    reasons = []
    near = (stops == 0) & (np.abs(q) >= M.lim - 1e-9)
    if near.any():
        reasons.append("free joint at its stop")
        stops = np.where(near, np.sign(q).astype(int), stops)
    q = np.where(stops != 0, stops * M.lim, q)
    free = stops == 0
    g = _grad_many(M, q)[0]
    _, J = _kin(M, q)
    if np.linalg.matrix_rank(J[:, free], tol=1e-10 * M.scale_x) < 2:
        return None                # not generic (the free rows do not fix F): not looked for
    res = g - J.T @ F
    contact = np.where(stops != 0, -stops * res, 0.0)
    if np.any(contact < -CONTACT_TOL * M.scale_e):
        return None
    if np.any((stops != 0) & (np.abs(contact) <= CONTACT_TOL * M.scale_e)):
        reasons.append("contact torque ~ 0")
    Jf = J[:, free]
    Z = sla.null_space(Jf) if free.sum() > 2 else np.zeros((free.sum(), 0))
    if Z.shape[1]:
        H = hessian(M, None, q, F)[np.ix_(free, free)]
        eig = np.linalg.eigvalsh(Z.T @ H @ Z)
    else:
        eig = np.zeros(0)
    if np.any(np.abs(eig) <= EIG_TOL * M.scale_e):
        reasons.append("singular reduced Hessian")
    L, _, _ = RE._springs(M.ch, q)
    if np.any(M.ch.slack[:, None] & (np.abs(L - M.ch.L0) <= 1e-9 * M.scale_x)):
        reasons.append("tension-only spring at its rest length")
    return Record(q=q, F=np.array(F, float), energy=float(_potential_many(M, q)[0]),
                  morse_index=int(np.sum(eig < -EIG_TOL * M.scale_e)), stops=stops,
                  contact_torques=np.maximum(contact, 0.0) * (stops != 0), eigenvalues=eig,
                  degenerate=bool(reasons), reasons=tuple(reasons))


def _stop_sets(n):
    for size in range(0, n - 1):
        for S in itertools.combinations(range(n), size):
            for signs in itertools.product((-1, 1), repeat=size):
                yield S, signs


def equilibria(segs, loads, dx, dy=0.0, *, grid1=20001, grid2=401) -> list[Record]:
    """Every equilibrium (``2 <= n <= 4``) with the tip on ``target(dx, dy)`` in the closed range, the stops
    included (at most ``n - 2`` joints on a stop), sorted by potential. Module docstring."""
    M = _M(segs, loads)
    n = M.n
    if not 2 <= n <= 4:
        raise ValueError("equilibria enumerates 2 <= n <= 4 segments")
    tgt = RT.target(M.segs, dx, dy)
    margin = float(min(0.05, 0.5 * np.min(math.pi - M.lim)))
    recs: list[Record] = []
    for S, signs in _stop_sets(n):
        base = np.zeros(n)
        for i, s in zip(S, signs):
            base[i] = s * M.lim[i]
        free = [i for i in range(n) if i not in S]
        m = len(free) - 2
        if m == 0:
            seeds = _seeds_rigid(M, tgt, base, free)
        elif m == 1:
            seeds = _seeds_curve(M, tgt, base, free, grid1, margin)
        else:
            seeds = _seeds_surface(M, tgt, base, free, grid2, margin)
        stops = np.zeros(n, int)
        stops[list(S)] = signs
        for s in seeds:
            q, F, ok = _newton(M, s, np.array(free), tgt)
            if ok and np.all(np.abs(q) <= M.lim + 1e-9):
                r = _record(M, np.clip(q, -M.lim, M.lim), F, stops, tgt)
                if r is not None:
                    recs.append(r)
    out: list[Record] = []
    for r in recs:
        twin = next((o for o in out if np.max(np.abs(o.q - r.q)) < DEDUP), None)
        if twin is None:
            out.append(r)
        elif r.degenerate and not twin.degenerate:
            twin.degenerate, twin.reasons = True, tuple(set(twin.reasons) | set(r.reasons))
    return sorted(out, key=lambda r: (r.energy, tuple(r.q)))


# ---------------------------------------------------------------------------- modes
def modes(segs, loads, q, *, held=True, stops=None, F=None):
    """``(w^2 ascending, Z, M, K)``: ``K`` the Hessian of ``E + V - F . tip`` (``F`` balancing the free joints, least
    squares, unless given; zero for a free tip without ``F``), ``M`` = ``RD.mass_matrix``, on the motions tangent to
    the held tip and to the joints on their stop (``stops``, default: those at ``|q| >= lim - AT_STOP_TOL``)."""
    Mo = _M(segs, loads)
    q = np.asarray(q, float)
    stops = np.abs(q) >= Mo.lim - AT_STOP_TOL if stops is None else np.asarray(stops, bool)
    if F is None:
        F = _force(Mo, q, ~stops)[0] if held else np.zeros(2)
    K = hessian(Mo, None, q, F)
    K = 0.5 * (K + K.T)
    Mm = RD.mass_matrix(Mo.segs, Mo.loads["payload"], q)
    rows = [np.eye(q.size)[stops]]
    if held:
        rows.append(RT._jac(Mo.P, q))
    C = np.vstack(rows)
    Z = sla.null_space(C) if C.shape[0] else np.eye(q.size)
    w = sla.eigh(Z.T @ K @ Z, Z.T @ Mm @ Z, eigvals_only=True) if Z.shape[1] else np.zeros(0)
    return w, Z, Mm, K
