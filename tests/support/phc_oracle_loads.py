"""An independent oracle of every equilibrium of a loaded chain of LINEAR-law segments: PHCpack's blackbox solver.

Imports numpy and scipy only (never ``tensegrity_opt``) and runs PHCpack's ``phc`` executable in a subprocess
(``phc -b input output``). The chain and its dead loads are plain numbers (:func:`chain`; :func:`chain_of` reads a
``Manipulator`` duck-typed, attribute by attribute).

The model (``docs/model.md``): segment ``i`` (1-based) has ``c = hypot(a, b)``, ``beta = atan2(a, b)`` and springs
``L1 = 2 c cos(beta + q/2) = 2 (b C - a S)``, ``L2 = 2 c cos(beta - q/2) = 2 (b C + a S)`` with ``C = cos(q/2)``,
``S = sin(q/2)``; ``E_i = k1/2 (L1 - L10)^2 + k2/2 (L2 - L20)^2``, so

    dE_i/dq_i = k1 (L1 - L10) L1' + k2 (L2 - L20) L2',     L1' = -(a C + b S),   L2' = a C - b S

(``dC/dq = -S/2``, ``dS/dq = C/2``). The links: ``u_j = (cos psi_j, sin psi_j)``, ``psi_j = q_1 + ... + q_j``, link
``j`` of length ``l_j = b_j + b_{j+1}`` (``l_n = b_n``); joint ``j`` at ``p_j = (b_1, 0) + sum_{k<j} l_k u_k``; the tip
``p_n + l_n u_n``. The load points: segment ``i``'s upper triangle (mass ``m_i / 2``) at ``p_i + (2 b_i / 3) u_i``, its
lower one (``i >= 2``; segment 1's belongs to the base) at ``p_i - (2 b_i / 3) u_{i-1}``, the payload at the tip, each
joint force at its joint. Each point is ``(b_1, 0) + sum_j lever_j u_j``, so with ``G_j = sum_points w lever_j``

    V(q) = -sum_points w . x = -(b_1, 0) . sum w - sum_j G_j . u_j,
    dV/dq_i = -sum_{j >= i} u_j x G_j,      d(F . tip)/dq_i = sum_{j >= i} l_j u_j x F

(``du_j/dq_i = perp(u_j)`` for ``j >= i``; ``perp(u) . G = u x G``). The equilibria with the tip held on the target
``(2 sum b - dx, dy)``: ``grad (E + V) = J^T F`` and ``tip(q) = target``.

The polynomial system, unknowns the half angles of the ABSOLUTE link angles ``X_j = cos(psi_j / 2)``, ``Y_j =
sin(psi_j / 2)`` (``j = 1..n``; ``X_0 = 1, Y_0 = 0``) and ``Fx, Fy`` (``2n + 2`` of them), with the joints' half angles
``C_i + i S_i = (X_i + i Y_i)(X_{i-1} - i Y_{i-1})`` (a bijection with the relative ``C_i, S_i``: ``X_j + i Y_j =
prod_{i <= j} (C_i + i S_i)``) and ``u_j = (X_j^2 - Y_j^2, 2 X_j Y_j)``:

* ``X_j^2 + Y_j^2 - 1 = 0``;
* ``dE_i/dq_i (C_i, S_i) - sum_{j >= i} u_j x (G_j + l_j F) = 0`` (degree 4);
* ``b_1 + sum_j l_j u_j,x - target_x = 0``, ``sum_j l_j u_j,y - target_y = 0``.

(The relative unknowns ``C_i, S_i`` give degree ``2n + 1``: PHCpack's blackbox did not finish that one in 10 minutes
at n = 3; this one takes 4-25 s at n = 3, about 2 minutes at n = 4: 2816 paths.) A generic chain has 8 finite
complex roots at n = 2 and 96 at n = 3 (:data:`GENERIC_ROOTS`; the roots with some ``C_i < 0`` -- the springs'
lengths negative -- included): a run reporting fewer lost one.

It is expanded exactly by a small monomial-dictionary arithmetic (:class:`_Poly`) and written in PHCpack's input
format. Every finite root that PHCpack reports is taken; the real ones (imaginary parts small) are polished by
Newton's method on the trigonometric equations in ``(q, F)`` (numpy, real), kept when ``C_i > 0`` (``q/2`` in
``(-pi/2, pi/2)``) and ``|q_i| < pi - 2 beta_i`` (the open range), checked against the polynomial system (residual
``<= 1e-9`` relative) and deduplicated. Each is classified by the inertia of the Hessian of ``E + V - F . tip`` on
the null space of the tip Jacobian (the Morse index), analytic and self-checked by :func:`hessian_fd`.
"""

from __future__ import annotations

import math
import os
import re
import shutil
import subprocess
import tempfile
import time
from dataclasses import dataclass, field

import numpy as np
import scipy.linalg as sla

PHC = shutil.which("phc")
#: the finite complex roots of the system of a generic chain (measured: every n = 2 and n = 3 chain tried, loaded
#: or not, symmetric segments too; PHCpack's other paths diverge, "no solution" / "at infinity"). A run that reports
#: fewer lost a root.
GENERIC_ROOTS = {2: 8, 3: 96}
#: a root whose imaginary parts are all below this (relative to its size) is real
IMAG_TOL = 1e-6
#: dedupe in q (max-norm)
DEDUP = 1e-8
#: reduced-Hessian eigenvalues this small (relative to the torque scale) are singular
EIG_TOL = 1e-9


# ------------------------------------------------------------------------------------------------ the chain
@dataclass
class Chain:
    a: np.ndarray
    b: np.ndarray
    k1: np.ndarray
    k2: np.ndarray
    L10: np.ndarray
    L20: np.ndarray
    mass: np.ndarray
    payload: float = 0.0
    gravity: tuple = (0.0, 0.0)
    joint_forces: tuple = ()
    _cache: dict = field(default_factory=dict, repr=False)

    @property
    def n(self) -> int:
        return int(self.a.size)

    @property
    def links(self) -> np.ndarray:
        return np.append(self.b[:-1] + self.b[1:], self.b[-1])

    @property
    def limits(self) -> np.ndarray:
        return math.pi - 2.0 * np.arctan2(self.a, self.b)

    @property
    def scale(self) -> float:
        """A torque scale: ``max k c^2`` plus the loads' ``|G|``."""
        kc2 = float(np.max(np.maximum(self.k1, self.k2) * (self.a ** 2 + self.b ** 2)))
        return kc2 + float(np.abs(self.G).max(initial=0.0))

    def target(self, dx, dy=0.0) -> np.ndarray:
        return np.array([2.0 * self.b.sum() - dx, dy])

    # the load points: (force w, lever row) -------------------------------------------------
    @property
    def points(self):
        if "points" not in self._cache:
            n, l, b = self.n, self.links, self.b
            g = np.asarray(self.gravity, float)
            W, lever = [], []
            for i in range(n):                                # 0-based segment i, joint i
                before = np.where(np.arange(n) < i, l, 0.0)
                if i > 0:                                     # lower triangle: on link i-1 (0-based), behind joint i
                    row = before.copy()
                    row[i - 1] -= 2.0 * b[i] / 3.0
                    W.append(0.5 * self.mass[i] * g), lever.append(row)
                row = before.copy()                           # upper triangle: on link i, ahead of joint i
                row[i] += 2.0 * b[i] / 3.0
                W.append(0.5 * self.mass[i] * g), lever.append(row)
            W.append(self.payload * g), lever.append(l.copy())     # payload at the tip
            for j, f in self.joint_forces:                    # joint j (1-based): after links 1..j-1
                W.append(np.asarray(f, float)), lever.append(np.where(np.arange(n) < int(j) - 1, l, 0.0))
            self._cache["points"] = (np.array(W, float).reshape(-1, 2), np.array(lever, float).reshape(-1, n))
        return self._cache["points"]

    @property
    def G(self) -> np.ndarray:
        W, lever = self.points
        return lever.T @ W


def chain(segs, payload=0.0, gravity=None, joint_forces=()) -> Chain:
    """``segs``: dicts ``{a, b, k (k1, k2 or one), L0 (L10, L20 or one), mass}``, base first."""
    def pair(v):
        v = np.atleast_1d(np.asarray(v, float))
        return (float(v[0]), float(v[-1]))
    k = [pair(s.get("k", 1.0)) for s in segs]
    L0 = [pair(s.get("L0", 1.0)) for s in segs]
    return Chain(a=np.array([s["a"] for s in segs], float), b=np.array([s["b"] for s in segs], float),
                 k1=np.array([x[0] for x in k]), k2=np.array([x[1] for x in k]),
                 L10=np.array([x[0] for x in L0]), L20=np.array([x[1] for x in L0]),
                 mass=np.array([float(s.get("mass", 0.0)) for s in segs]), payload=float(payload),
                 gravity=(0.0, 0.0) if gravity is None else tuple(map(float, gravity)),
                 joint_forces=tuple((int(j), tuple(map(float, f))) for j, f in joint_forces))


def chain_of(m) -> Chain:
    """The oracle's chain of a ``Manipulator`` (duck-typed: its segments' ``a, b, k1, k2, L1_0, L2_0, mass, spring``,
    its ``payload, gravity, joint_forces``); linear-law segments only."""
    segs = []
    for s in m.segments:
        if getattr(s, "spring", "linear") != "linear":
            raise ValueError("the PHCpack oracle models linear-law segments only")
        segs.append(dict(a=s.a, b=s.b, k=(s.k1, s.k2), L0=(s.L1_0, s.L2_0), mass=getattr(s, "mass", 0.0)))
    g = getattr(m, "gravity", None)
    return chain(segs, getattr(m, "payload", 0.0), g, getattr(m, "joint_forces", ()))


# ------------------------------------------------------------------------------------------------ numerics in q
def _dirs(q):
    psi = np.cumsum(q)
    return np.cos(psi), np.sin(psi)


def positions(ch: Chain, q):
    """``(joints (n, 2), tip (2,), load points (P, 2))`` built by chaining the links."""
    q = np.asarray(q, float)
    n, l, b = ch.n, ch.links, ch.b
    c, s = _dirs(q)
    u = np.stack([c, s], 1)
    p = np.zeros((n, 2))
    p[0] = (b[0], 0.0)
    for j in range(1, n):
        p[j] = p[j - 1] + l[j - 1] * u[j - 1]
    tip = p[n - 1] + l[n - 1] * u[n - 1]
    X = []
    for i in range(n):
        if i > 0:
            X.append(p[i] - 2.0 * b[i] / 3.0 * u[i - 1])
        X.append(p[i] + 2.0 * b[i] / 3.0 * u[i])
    X.append(tip)
    for j, _ in ch.joint_forces:
        X.append(p[int(j) - 1])
    return p, tip, np.array(X)


def spring_lengths(ch: Chain, q):
    C, S = np.cos(np.asarray(q) / 2), np.sin(np.asarray(q) / 2)
    return 2 * (ch.b * C - ch.a * S), 2 * (ch.b * C + ch.a * S)


def potential(ch: Chain, q) -> float:
    """``E + V`` with ``V = -sum w . x`` (absolute positions: with its constant)."""
    L1, L2 = spring_lengths(ch, q)
    E = 0.5 * (ch.k1 * (L1 - ch.L10) ** 2 + ch.k2 * (L2 - ch.L20) ** 2).sum()
    W, _ = ch.points
    _, _, X = positions(ch, q)
    return float(E - np.einsum("pk,pk->", W, X))


def tip(ch: Chain, q):
    return positions(ch, q)[1]


def _dE(ch: Chain, q):
    q = np.asarray(q, float)
    C, S = np.cos(q / 2), np.sin(q / 2)
    L1, L2 = spring_lengths(ch, q)
    d1, d2 = -(ch.a * C + ch.b * S), ch.a * C - ch.b * S
    dd1, dd2 = -L1 / 4.0, -L2 / 4.0                  # L'' = -L/4
    g = ch.k1 * (L1 - ch.L10) * d1 + ch.k2 * (L2 - ch.L20) * d2
    h = ch.k1 * (d1 ** 2 + (L1 - ch.L10) * dd1) + ch.k2 * (d2 ** 2 + (L2 - ch.L20) * dd2)
    return g, h


def jacobian(ch: Chain, q):
    c, s = _dirs(q)
    l = ch.links
    rc, rs = np.cumsum((l * c)[::-1])[::-1], np.cumsum((l * s)[::-1])[::-1]   # sum_{j >= i}
    return np.stack([-rs, rc])


def gradient(ch: Chain, q):
    """``grad (E + V)``."""
    c, s = _dirs(q)
    G = ch.G
    cross = c * G[:, 1] - s * G[:, 0]                 # u_j x G_j
    return _dE(ch, q)[0] - np.cumsum(cross[::-1])[::-1]


def hessian(ch: Chain, q, F=(0.0, 0.0)):
    """Hessian of ``E + V - F . tip``: ``d2V/dq_i dq_k = sum_{j >= max} G_j . u_j``, ``d2 tip/dq_i dq_k =
    -sum_{j >= max} l_j u_j``."""
    c, s = _dirs(q)
    H_lin = ch.G[:, 0] * c + ch.G[:, 1] * s + ch.links * (F[0] * c + F[1] * s)
    tail = np.cumsum(H_lin[::-1])[::-1]
    n = ch.n
    idx = np.maximum.outer(np.arange(n), np.arange(n))
    return tail[idx] + np.diag(_dE(ch, q)[1])


def gradient_fd(ch: Chain, q, h=1e-5):
    q = np.asarray(q, float)
    out = np.empty(q.size)
    for i in range(q.size):
        e = np.zeros(q.size)
        e[i] = h
        f = [potential(ch, q + t * e) for t in (-2, -1, 1, 2)]
        out[i] = (f[0] - 8 * f[1] + 8 * f[2] - f[3]) / (12 * h)
    return out


def hessian_fd(ch: Chain, q, F=(0.0, 0.0), h=1e-5):
    """Five-point differences of ``gradient - J^T F``."""
    q = np.asarray(q, float)
    F = np.asarray(F, float)
    g = lambda x: gradient(ch, x) - jacobian(ch, x).T @ F  # noqa: E731
    H = np.empty((q.size, q.size))
    for i in range(q.size):
        e = np.zeros(q.size)
        e[i] = h
        H[:, i] = (g(q - 2 * e) - 8 * g(q - e) + 8 * g(q + e) - g(q + 2 * e)) / (12 * h)
    return 0.5 * (H + H.T)


def residual(ch: Chain, q, F, tgt):
    return np.concatenate([gradient(ch, q) - jacobian(ch, q).T @ np.asarray(F, float), tip(ch, q) - tgt])


def _newton(ch: Chain, q, F, tgt, iters=30):
    x = np.concatenate([q, F]).astype(float)
    n = ch.n
    for _ in range(iters):
        r = residual(ch, x[:n], x[n:], tgt)
        J = np.zeros((n + 2, n + 2))
        Jt = jacobian(ch, x[:n])
        J[:n, :n] = hessian(ch, x[:n], x[n:])
        J[:n, n:] = -Jt.T
        J[n:, :n] = Jt
        try:
            dx = np.linalg.solve(J, -r)
        except np.linalg.LinAlgError:
            break
        x += dx
        if np.abs(dx).max() < 1e-15 * (1 + np.abs(x).max()):
            break
    return x[:n], x[n:]


def morse(ch: Chain, q, F):
    """``(Morse index, reduced eigenvalues)``: the inertia of ``Z^T H Z``, ``Z`` the null space of the tip
    Jacobian."""
    Z = sla.null_space(jacobian(ch, q))
    ev = np.linalg.eigvalsh(Z.T @ hessian(ch, q, F) @ Z) if Z.size else np.zeros(0)
    return int((ev < 0).sum()), ev


# ------------------------------------------------------------------------------------------------ polynomials
class _Poly:
    """A real polynomial as ``{exponent tuple: coefficient}``."""

    __slots__ = ("t", "nv")

    def __init__(self, nv, terms=None):
        self.nv = nv
        self.t = dict(terms or {})

    @classmethod
    def const(cls, nv, c):
        return cls(nv, {(0,) * nv: float(c)} if c != 0 else {})

    @classmethod
    def var(cls, nv, k):
        e = [0] * nv
        e[k] = 1
        return cls(nv, {tuple(e): 1.0})

    def _lift(self, o):
        return o if isinstance(o, _Poly) else _Poly.const(self.nv, o)

    def __add__(self, o):
        o = self._lift(o)
        t = dict(self.t)
        for e, c in o.t.items():
            t[e] = t.get(e, 0.0) + c
        return _Poly(self.nv, t)

    __radd__ = __add__

    def __neg__(self):
        return _Poly(self.nv, {e: -c for e, c in self.t.items()})

    def __sub__(self, o):
        return self + (-self._lift(o))

    def __rsub__(self, o):
        return self._lift(o) - self

    def __mul__(self, o):
        if not isinstance(o, _Poly):
            return _Poly(self.nv, {e: c * float(o) for e, c in self.t.items()})
        t = {}
        for e1, c1 in self.t.items():
            for e2, c2 in o.t.items():
                e = tuple(x + y for x, y in zip(e1, e2))
                t[e] = t.get(e, 0.0) + c1 * c2
        return _Poly(self.nv, t)

    __rmul__ = __mul__

    def __call__(self, x):
        x = np.asarray(x)
        return sum(c * np.prod(x ** np.array(e)) for e, c in self.t.items())

    def phc(self, names) -> str:
        out = []
        for e, c in sorted(self.t.items(), reverse=True):
            if c == 0.0:
                continue
            mon = "*".join(nm if p == 1 else f"{nm}^{p}" for nm, p in zip(names, e) if p)
            out.append(f"{c:+.17e}" + (f"*{mon}" if mon else ""))
        return " ".join(out) if out else "0"


def names(n):
    return [f"X{j + 1}" for j in range(n)] + [f"Y{j + 1}" for j in range(n)] + ["Fx", "Fy"]


def system(ch: Chain, dx, dy=0.0) -> list[_Poly]:
    """The ``2n + 2`` polynomials (module docstring) in the half angles of the ABSOLUTE link angles,
    ``X_j = cos(psi_j / 2)``, ``Y_j = sin(psi_j / 2)``
    (``j = 1..n``; ``X_0 = 1``, ``Y_0 = 0`` the base), and ``Fx, Fy``.

    ``C_i + i S_i = (X_i + i Y_i) (X_{i-1} - i Y_{i-1})`` (``q_i / 2 = psi_i / 2 - psi_{i-1} / 2``): a bijection with
    the relative half angles ``(C, S)`` (``X_j + i Y_j = prod_{i <= j} (C_i + i S_i)``), so the two systems have the
    same roots; this one is of degree 4 at most (``u_j = (X_j^2 - Y_j^2, 2 X_j Y_j)``), the relative one of degree
    ``2n + 1``, which PHCpack's blackbox did not finish in 10 minutes at n = 3."""
    n = ch.n
    nv = 2 * n + 2
    V = lambda k: _Poly.var(nv, k)  # noqa: E731
    X = [_Poly.const(nv, 1.0)] + [V(j) for j in range(n)]
    Y = [_Poly.const(nv, 0.0)] + [V(n + j) for j in range(n)]
    Fx, Fy = V(2 * n), V(2 * n + 1)
    l, G = ch.links, ch.G
    tgt = ch.target(dx, dy)
    ux = [X[j + 1] * X[j + 1] - Y[j + 1] * Y[j + 1] for j in range(n)]
    uy = [2.0 * X[j + 1] * Y[j + 1] for j in range(n)]
    eqs = [X[j + 1] * X[j + 1] + Y[j + 1] * Y[j + 1] - 1.0 for j in range(n)]
    for i in range(n):
        a, b = ch.a[i], ch.b[i]
        C = X[i + 1] * X[i] + Y[i + 1] * Y[i]
        S = Y[i + 1] * X[i] - X[i + 1] * Y[i]
        L1, L2 = 2.0 * (b * C - a * S), 2.0 * (b * C + a * S)
        d1, d2 = -(a * C + b * S), a * C - b * S
        dE = ch.k1[i] * (L1 - ch.L10[i]) * d1 + ch.k2[i] * (L2 - ch.L20[i]) * d2
        tq = _Poly.const(nv, 0.0)
        for j in range(i, n):
            Hx, Hy = G[j, 0] + l[j] * Fx, G[j, 1] + l[j] * Fy
            tq = tq + ux[j] * Hy - uy[j] * Hx
        eqs.append(dE - tq)
    eqs.append(sum((l[j] * ux[j] for j in range(n)), _Poly.const(nv, ch.b[0] - tgt[0])))
    eqs.append(sum((l[j] * uy[j] for j in range(n)), _Poly.const(nv, -tgt[1])))
    return eqs


def unknowns(q, F) -> np.ndarray:
    """The system's unknowns at ``(q, F)``."""
    h = np.cumsum(np.asarray(q, float)) / 2.0
    return np.concatenate([np.cos(h), np.sin(h), np.asarray(F, float)])


def relative_half_angles(x, n):
    """``(C, S)`` of the unknowns ``x``."""
    X, Y = np.concatenate([[1.0], x[:n]]), np.concatenate([[0.0], x[n:2 * n]])
    return X[1:] * X[:-1] + Y[1:] * Y[:-1], Y[1:] * X[:-1] - X[1:] * Y[:-1]


def phc_input(eqs, n) -> str:
    nm = names(n)
    return f"{len(eqs)}\n" + "".join(f" {p.phc(nm)};\n" for p in eqs)


_NUM = r"[-+]?\d+\.\d+E[-+]\d+"


def _parse(text: str, nm):
    """Every solution of the last ``THE SOLUTIONS`` section: ``(values (complex, in nm's order), m, flag)``."""
    part = text[text.rfind("THE SOLUTIONS"):]
    sols = []
    for blk in part.split("the solution for t :")[1:]:
        vals = dict((k, complex(float(x), float(y)))
                    for k, x, y in re.findall(rf"^\s*(\w+)\s*:\s*({_NUM})\s+({_NUM})\s*$", blk.split("==")[0], re.M))
        tail = re.search(r"res :\s*\S+\s*=\s*([^=\n]*?)\s*==", blk)
        sols.append(([vals[k] for k in nm], tail.group(1) if tail else ""))
    return sols


def run_phc(text: str, timeout=600.0, seed=None) -> tuple[str, float]:
    """Run ``phc -b`` on an input text; ``(output text, seconds)``."""
    if PHC is None:
        raise RuntimeError("phc not found")
    with tempfile.TemporaryDirectory(prefix="phc_oracle_") as d:
        inp, out = os.path.join(d, "input"), os.path.join(d, "output")
        with open(inp, "w") as f:
            f.write(text)
        cmd = [PHC] + ([f"-{seed}"] if seed is not None else []) + ["-b", inp, out]
        t0 = time.perf_counter()
        subprocess.run(cmd, cwd=d, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                       timeout=timeout, check=True)
        with open(out) as f:
            return f.read(), time.perf_counter() - t0


# ------------------------------------------------------------------------------------------------ the oracle
@dataclass
class Root:
    q: np.ndarray
    F: np.ndarray
    morse_index: int
    potential: float
    eigenvalues: np.ndarray
    residual: float          # the polynomial system at the root (max abs, relative to the torque scale)


@dataclass
class Result:
    roots: list              # the equilibria inside the open range, sorted by q
    n_solutions: int         # the solutions PHCpack reported (one per path)
    n_finite: int            # of them finite (not "no solution", not "at infinity")
    n_real: int              # of them real
    n_valid: int             # of them with C > 0 (q in (-pi, pi)) before the range filter
    seconds: float
    flags: list              # PHCpack's labels of its solutions ("real regular", ...)

    def __iter__(self):
        return iter([(r.q, r.F, r.morse_index, r.potential) for r in self.roots])

    def __len__(self):
        return len(self.roots)


def equilibria(ch: Chain, dx, dy=0.0, *, timeout=600.0, seed=None) -> Result:
    """Every equilibrium of the chain with its tip on the target, inside the open range (module docstring)."""
    n = ch.n
    eqs = system(ch, dx, dy)
    text, secs = run_phc(phc_input(eqs, n), timeout=timeout, seed=seed)
    sols = _parse(text, names(n))
    tgt = ch.target(dx, dy)
    scale = ch.scale
    roots, n_real, n_valid = [], 0, 0
    for vals, flag in sols:
        if flag in ("no solution", "at infinity"):
            continue
        z = np.array(vals)
        if not np.all(np.isfinite(z)):
            continue
        if np.abs(z.imag).max() > IMAG_TOL * (1.0 + np.abs(z.real).max()):
            continue
        n_real += 1
        x = z.real
        (Cs, Ss), F0 = relative_half_angles(x, n), x[2 * n:]
        if np.any(Cs <= 0.0):
            continue
        n_valid += 1
        q0 = 2.0 * np.arctan2(Ss, Cs)
        q, F = _newton(ch, q0, F0, tgt)
        if np.abs(q - q0).max() > 1e-6 or np.abs(residual(ch, q, F, tgt)).max() > 1e-9 * scale:
            raise AssertionError(f"a PHCpack root does not polish: q0 {q0}, q {q}, flag {flag!r}")
        if np.any(np.abs(q) >= ch.limits):
            continue
        y = unknowns(q, F)
        res = max(abs(p(y)) for p in eqs) / scale
        idx, ev = morse(ch, q, F)
        if ev.size and np.abs(ev).min() < EIG_TOL * scale:
            idx = -1                                    # singular: undetermined
        roots.append(Root(q=q, F=F, morse_index=idx, potential=potential(ch, q), eigenvalues=ev, residual=res))
    out = []
    for r in sorted(roots, key=lambda r: tuple(r.q)):
        if not any(np.abs(r.q - o.q).max() < DEDUP for o in out):
            out.append(r)
    n_finite = sum(1 for v, f in sols if f not in ("no solution", "at infinity") and np.all(np.isfinite(v))
                   and np.abs(np.array(v)).max() < 1e8)
    return Result(roots=out, n_solutions=len(sols), n_finite=n_finite, n_real=n_real, n_valid=n_valid, seconds=secs,
                  flags=[f for _, f in sols])


def least_stable(res: Result):
    """The stable root of least potential (``None`` without one)."""
    st = [r for r in res.roots if r.morse_index == 0]
    return min(st, key=lambda r: r.potential) if st else None
