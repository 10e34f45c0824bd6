"""Independent reference of a chain whose springs may be *tension-only* (cables), with the joint stops.

Imports numpy and scipy only -- it does NOT import ``tensegrity_opt`` (:func:`segs_of` reads a ``Manipulator``'s
attributes duck-typed, without importing the package).

The model (``docs/model.md``), rebuilt here from the vertex positions rather than from the length formulas:

* segment i: ``a, b > 0``, stiffnesses ``k1, k2``, rest lengths ``L10, L20``, a spring law ``"linear"`` or
  ``"tension_only"``; joint angle ``q_i`` (relative, rad); ``c = hypot(a, b)``, ``beta = atan2(a, b)``;
* relative to the joint, the lower triangle's far vertices are ``w1 = (-b, +a)``, ``w2 = (-b, -a)``, the upper
  triangle's ``v1 = R(q) (b, +a)``, ``v2 = R(q) (b, -a)`` (``R`` the counter-clockwise rotation); the springs are
  ``L1 = |v1 - w1|``, ``L2 = |v2 - w2|`` (equal to ``2c cos(beta + q/2)``, ``2c cos(beta - q/2)`` -- checked by
  the self-tests, not used here);
* the closed range is ``|q_i| <= pi - 2 beta_i`` (the joint stop: a spring's length reaches 0 there);
* tension ``T = k (L - L0)`` (linear) or ``k max(0, L - L0)`` (tension-only); energy ``k/2 (L - L0)^2`` or
  ``k/2 max(0, L - L0)^2``;
* base fixed, straight along +x; ``phi_j = q_1 + ... + q_j``; tip ``x = b_1 + sum l_j cos phi_j``,
  ``y = sum l_j sin phi_j``, ``l_j = b_j + b_{j+1}`` (j < n), ``l_n = b_n``; a deflection ``(dx, dy)`` puts the
  tip at ``target = (2 sum b - dx, dy)``.

:func:`torques` are the moments ``r x F`` about the joint of the spring forces on the upper triangle's vertices
(``M_i = -dE/dq_i``), not a differentiated formula. :func:`least_energy` is a brute force over the closed range
(a grid of the first ``n - 2`` joints, the last two by closed-form two-link inverse kinematics, then SLSQP polish
of the best distinct candidates) for ``n <= 4``.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np
import scipy.optimize as so

LAWS = ("linear", "tension_only")
#: A joint is at its stop when ``|q_i| >= limit_i - AT_STOP_TOL``.
AT_STOP_TOL = 1e-7
#: Default grid points per swept joint (``n = 3``: one swept joint, ``n = 4``: two).
DEFAULT_GRID = {3: 721, 4: 181}


# ---------------------------------------------------------------------------- parameters
def segs_of(m) -> list[dict]:
    """The segments of a ``tensegrity_opt.Manipulator`` as dicts, read duck-typed (attribute access only).

    Parameters
    ----------
    m : object
        Anything with ``m.segments[i].a, .b, .k1, .k2, .L1_0, .L2_0, .spring``.

    Returns
    -------
    list of dict
        ``{a, b, k1, k2, L10, L20, law}`` per segment, base first.
    """
    return [dict(a=float(s.a), b=float(s.b), k1=float(s.k1), k2=float(s.k2), L10=float(s.L1_0),
                 L20=float(s.L2_0), law=str(s.spring)) for s in m.segments]


@dataclass(frozen=True)
class _P:
    a: np.ndarray
    b: np.ndarray
    k: np.ndarray          # (n, 2): k1, k2
    L0: np.ndarray         # (n, 2): L10, L20
    slack: np.ndarray      # (n,) bool: tension-only
    limits: np.ndarray     # pi - 2 beta
    links: np.ndarray

    @property
    def n(self) -> int:
        return int(self.a.size)


def _params(segs) -> _P:
    if len(segs) < 1:
        raise ValueError("a chain needs at least one segment")
    for s in segs:
        if s["law"] not in LAWS:
            raise ValueError(f"unknown spring law {s['law']!r}")
        if not (s["a"] > 0 and s["b"] > 0):
            raise ValueError("a and b must be > 0")
    a = np.array([s["a"] for s in segs], float)
    b = np.array([s["b"] for s in segs], float)
    links = b.copy()
    links[:-1] = b[:-1] + b[1:]
    return _P(a=a, b=b, k=np.array([[s["k1"], s["k2"]] for s in segs], float),
              L0=np.array([[s["L10"], s["L20"]] for s in segs], float),
              slack=np.array([s["law"] == "tension_only" for s in segs]),
              limits=math.pi - 2.0 * np.arctan2(a, b), links=links)


def limits(segs) -> np.ndarray:
    """The closed range's half-widths ``pi - 2 beta_i`` (n,)."""
    return _params(segs).limits


# ---------------------------------------------------------------------------- vertices, lengths, forces
def _vertices(P: _P, q):
    """Vertices relative to the joint: ``v`` (..., n, 2 springs, 2 coords) upper, ``w`` (n, 2, 2) lower."""
    q = np.asarray(q, float)
    up = np.stack([np.stack([P.b, P.a], -1), np.stack([P.b, -P.a], -1)], -2)        # (n, 2, 2) at q = 0
    w = np.stack([np.stack([-P.b, P.a], -1), np.stack([-P.b, -P.a], -1)], -2)
    cq, sq = np.cos(q)[..., None], np.sin(q)[..., None]
    v = np.stack([cq * up[..., 0] - sq * up[..., 1], sq * up[..., 0] + cq * up[..., 1]], -1)
    return v, w


def _lengths(P: _P, q):
    v, w = _vertices(P, q)
    return np.linalg.norm(v - w, axis=-1)


def _tension(P: _P, L):
    T = P.k * (L - P.L0)
    return np.where(P.slack[:, None], np.maximum(T, 0.0), T)


def _energy(P: _P, q):
    """Vectorised over leading axes of ``q``."""
    L = _lengths(P, q)
    e = L - P.L0
    e = np.where(P.slack[:, None], np.maximum(e, 0.0), e)
    return 0.5 * np.sum(P.k * e * e, axis=(-2, -1))


def _torques(P: _P, q):
    q = np.asarray(q, float)
    v, w = _vertices(P, q)
    d = v - w
    L = np.linalg.norm(d, axis=-1)
    T = _tension(P, L)
    # the unit vector w -> v; at a stop (L = 0, v = w) its limit from inside the range: v - w ~ (q - q*) dv/dq
    # with dv/dq = perp(v), so u -> -sign(q) perp(v) / |v|
    perp = np.stack([-v[..., 1], v[..., 0]], -1)
    lim_u = -np.sign(q)[..., None, None] * perp / np.linalg.norm(v, axis=-1, keepdims=True)
    tiny = L < 1e-12 * np.hypot(P.a, P.b)[:, None]
    u = np.where(tiny[..., None], lim_u, d / np.where(tiny, 1.0, L)[..., None])
    F = -T[..., None] * u                      # the spring pulls the upper vertex towards the lower one
    F = np.where((T == 0.0)[..., None], 0.0, F)
    moment = v[..., 0] * F[..., 1] - v[..., 1] * F[..., 0]      # r x F about the joint, r = v
    return moment.sum(-1)


def lengths(segs, q) -> np.ndarray:
    """Spring lengths from the vertex positions.

    Parameters
    ----------
    segs : list of dict
        ``{a, b, k1, k2, L10, L20, law}`` per segment.
    q : array_like (n,)
        Relative joint angles (rad).

    Returns
    -------
    ndarray (n, 2)
        ``L1 = |v1 - w1|``, ``L2 = |v2 - w2|`` per segment.
    """
    return _lengths(_params(segs), q)


def forces(segs, q) -> np.ndarray:
    """Spring tensions (tension positive), ``(n, 2)``: ``k (L - L0)``, or ``k max(0, L - L0)`` when slack-able."""
    P = _params(segs)
    return _tension(P, _lengths(P, q))


def energy(segs, q) -> float:
    """Stored energy ``sum k/2 (L - L0)^2`` (linear) / ``k/2 max(0, L - L0)^2`` (tension-only)."""
    return float(_energy(_params(segs), q))


def torques(segs, q) -> np.ndarray:
    """Joint torques ``M_i = -dE/dq_i`` (n,), from the spring force vectors.

    The force of spring j on the upper triangle's vertex ``v_j`` is ``-T_j (v_j - w_j) / L_j``; ``M_i`` is the sum
    of its moments ``v_j x F_j`` about joint i. At a stop (``L_j = 0``) the direction is its limit from inside the
    range.
    """
    return _torques(_params(segs), q)


def stiffness(segs, q, h=1e-6) -> np.ndarray:
    """Joint stiffnesses ``d2E/dq_i2`` (n,) by differences of :func:`torques` (``E`` is a sum of one-joint terms,
    so the Hessian is diagonal).

    Central, ``-(M(q + h) - M(q - h)) / 2h``, when both points are inside the closed range; at (within ``h`` of)
    a stop one-sided into the range, second order: ``-(-3 M(q) + 4 M(q + s h) - M(q + 2 s h)) / (2 s h)``, ``s``
    pointing inwards. At a tension-only kink (``L = L0``) the central difference averages the two sides.
    """
    P = _params(segs)
    q = np.asarray(q, float)
    out = np.empty(P.n)
    for i in range(P.n):
        e = np.zeros(P.n)
        e[i] = h
        if abs(q[i]) + h <= P.limits[i]:
            out[i] = -(_torques(P, q + e)[i] - _torques(P, q - e)[i]) / (2 * h)
        else:
            s = -1.0 if q[i] > 0 else 1.0
            m0, m1, m2 = (_torques(P, q + j * s * e)[i] for j in range(3))
            out[i] = -(-3 * m0 + 4 * m1 - m2) / (2 * s * h)
    return out


# ---------------------------------------------------------------------------- kinematics
def _tip(P: _P, q):
    phi = np.cumsum(np.asarray(q, float), axis=-1)
    return np.stack([P.b[0] + np.sum(P.links * np.cos(phi), -1), np.sum(P.links * np.sin(phi), -1)], -1)


def _jac(P: _P, q):
    phi = np.cumsum(np.asarray(q, float))
    cx = -np.cumsum((P.links * np.sin(phi))[::-1])[::-1]
    cy = np.cumsum((P.links * np.cos(phi))[::-1])[::-1]
    return np.stack([cx, cy])


def tip(segs, q) -> np.ndarray:
    """Tip position ``(x, y)``: ``x = b_1 + sum l_j cos phi_j``, ``y = sum l_j sin phi_j``."""
    return _tip(_params(segs), q)


def tip_jacobian(segs, q) -> np.ndarray:
    """``d tip / d q`` (2, n)."""
    return _jac(_params(segs), q)


def target(segs, dx, dy=0.0) -> np.ndarray:
    """The tip target of a deflection: ``(2 sum b - dx, dy)``."""
    return np.array([2.0 * sum(s["b"] for s in segs) - dx, dy], float)


# ---------------------------------------------------------------------------- least energy
@dataclass
class LeastEnergy:
    q: np.ndarray                # the minimiser (n,)
    energy: float
    at_stop: np.ndarray          # bool (n,): |q_i| >= limit_i - AT_STOP_TOL
    contact_torques: np.ndarray  # (n,) >= 0: the torque magnitude each stop supplies (0 for free joints)
    force: np.ndarray            # the tip force F (2,): grad E = J^T F on the free joints (least squares)
    stop_signs: np.ndarray       # (n,) the signed residual dE/dq_i - (J^T F)_i (KKT: <= 0 at +stop, >= 0 at -stop)
    free_residual: float         # max |dE/dq_i - (J^T F)_i| over the free joints (a KKT check)
    grid_energy: float           # the best grid value before polishing
    candidates: int              # the distinct candidates polished


def _wrap(x):
    return (x + math.pi) % (2.0 * math.pi) - math.pi


def _grid_solutions(P: _P, tgt, grid):
    """All configurations meeting the target exactly: the first n - 2 joints on the grid, the last two by IK."""
    n = P.n
    if n == 2:
        Q = np.zeros((1, 0))
    else:
        axes = [np.linspace(-P.limits[i], P.limits[i], grid) for i in range(n - 2)]
        Q = np.array(list(itertools.product(*axes))) if n > 3 else axes[0][:, None]
    phi = np.cumsum(Q, axis=1)
    # joint n-1's position: (b_1, 0) + sum_{j < n-1} l_j (cos phi_j, sin phi_j)
    px = P.b[0] + np.sum(P.links[:n - 2] * np.cos(phi), 1)
    py = np.sum(P.links[:n - 2] * np.sin(phi), 1)
    phi0 = phi[:, -1] if n > 2 else np.zeros(Q.shape[0])
    ex, ey = tgt[0] - px, tgt[1] - py
    l1, l2 = P.links[n - 2], P.links[n - 1]
    cos_qn = (ex * ex + ey * ey - l1 * l1 - l2 * l2) / (2.0 * l1 * l2)
    ok = np.abs(cos_qn) <= 1.0
    qn = np.arccos(np.clip(cos_qn, -1.0, 1.0))
    out = []
    for sgn in (1.0, -1.0):
        qlast = sgn * qn
        phi1 = np.arctan2(ey, ex) - np.arctan2(l2 * np.sin(qlast), l1 + l2 * np.cos(qlast))
        qprev = _wrap(phi1 - phi0)
        out.append(np.column_stack([Q, qprev, qlast])[ok])
    S = np.concatenate(out)
    inside = np.all(np.abs(S) <= P.limits, axis=1)
    return S[inside]


def _distinct(S, E, m, sep):
    order = np.argsort(E, kind="stable")
    keep: list[int] = []
    for j in order:
        if all(np.max(np.abs(S[j] - S[i])) > sep for i in keep):
            keep.append(int(j))
            if len(keep) == m:
                break
    return keep


def _polish(P: _P, q0, tgt):
    bounds = list(zip(-P.limits, P.limits))
    cons = {"type": "eq", "fun": lambda q: _tip(P, q) - tgt, "jac": lambda q: _jac(P, q)}
    q = np.clip(q0, -P.limits, P.limits)
    for _ in range(2):               # a restart from SLSQP's own end point settles the active set
        r = so.minimize(lambda x: float(_energy(P, x)), q, jac=lambda x: -_torques(P, x), method="SLSQP",
                        bounds=bounds, constraints=[cons], options={"ftol": 1e-15, "maxiter": 1000})
        q = np.clip(r.x, -P.limits, P.limits)
    return q


def least_energy(segs, dx, dy=0.0, *, grid=None, candidates=20, seed=0) -> LeastEnergy:
    """The least energy over the configurations with ``tip(q) = target(dx, dy)`` in the CLOSED range.

    Brute force for ``2 <= n <= 4``: the first ``n - 2`` joints swept over ``grid`` points each of
    ``[-limit_i, limit_i]`` (endpoints included; default 721 for n = 3, 181 per axis for n = 4, i.e. a spacing of
    about 0.0044 and 0.017 rad on the paper chain), the last two joints solved in closed form (two-link inverse
    kinematics, both elbows), solutions outside the closed range dropped; for n = 2 the IK alone. The best
    ``candidates`` distinct grid solutions (greedy, pairwise more than two grid spacings apart in max-norm) are
    polished by SLSQP (energy with the analytic gradient ``-torques``, equality ``tip = target``, bounds the
    closed range, ``ftol`` 1e-15, run twice). The result is the least polished energy whose tip misses the target
    by < 1e-9 (the best grid point if none does). Deterministic: ``seed`` is accepted for interface
    compatibility and unused (no randomness).

    Contact torques (KKT): ``F`` solves ``dE/dq_i = (J^T F)_i`` over the free joints in least squares
    (minimum norm when fewer than two are free); a joint at its stop gets ``|dE/dq_i - (J^T F)_i|``, a free joint
    0. Raises ValueError when no configuration in the closed range reaches the target, or n is outside 2..4.
    """
    del seed
    P = _params(segs)
    n = P.n
    if not 2 <= n <= 4:
        raise ValueError("least_energy brute-forces 2 <= n <= 4 segments")
    g = int(grid) if grid is not None else DEFAULT_GRID.get(n, 1)
    tgt = np.array([2.0 * P.b.sum() - dx, dy], float)
    S = _grid_solutions(P, tgt, g)
    if S.shape[0] == 0:
        raise ValueError("the target is not reachable in the closed range (at this grid)")
    E = _energy(P, S)
    spacing = 2.0 * float(np.max(P.limits)) / max(g - 1, 1)
    keep = _distinct(S, E, candidates, 2.0 * spacing)
    best_q, best_e = S[keep[0]].copy(), float(E[keep[0]])
    grid_e = best_e
    scale = float(np.max(P.links)) * n
    for j in keep:
        q = _polish(P, S[j], tgt)
        if np.max(np.abs(_tip(P, q) - tgt)) < 1e-9 * scale:
            e = float(_energy(P, q))
            if e < best_e:
                best_q, best_e = q, e
    at_stop = np.abs(best_q) >= P.limits - AT_STOP_TOL
    grad = -_torques(P, best_q)
    J = _jac(P, best_q)
    free = ~at_stop
    if free.any():
        F = np.linalg.lstsq(J[:, free].T, grad[free], rcond=None)[0]
    else:
        F = np.zeros(2)
    res = grad - J.T @ F
    contact = np.where(at_stop, np.abs(res), 0.0)
    return LeastEnergy(q=best_q, energy=best_e, at_stop=at_stop, contact_torques=contact, force=F,
                       stop_signs=np.where(at_stop, res, 0.0),
                       free_residual=float(np.max(np.abs(res[free]))) if free.any() else 0.0,
                       grid_energy=grid_e, candidates=len(keep))
