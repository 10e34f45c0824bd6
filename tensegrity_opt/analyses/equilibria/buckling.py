"""Buckling of the straight configuration: critical loads and modes (eq. 9-26).

Linearised about ``q = 0`` (symmetric segments), the equilibrium condition
``grad E = J^T F`` reads ``K q = P G q + Fy S0`` with ``Fx = -P``, where
``K = diag(E_i''(0))`` (joint stiffness), ``G = -Hess x = T^T diag(links) T``
(``T`` lower-triangular ones) and ``S0 = dy/dq = T^T links``.

* ``boundary="guided"`` (the paper's case): ``dy = 0`` is held, ``S0^T q = 0``,
  ``Fy`` is a reaction. Critical loads are the generalised eigenvalues of
  ``Z^T K Z v = P Z^T G Z v`` on the null space ``Z`` of ``S0^T`` (``method="reduced"``,
  symmetric, via ``scipy.linalg.eigh``) or, identically, ``P = -1/lambda`` over
  the nonzero eigenvalues of the paper's ``B^-1 A`` (eq. 17-20, ``method="paper"``).
* ``boundary="free"``: a cantilever, ``Fy = 0`` and ``y`` free:
  ``K v = P G v`` on the whole space (paper form ``B = K``, ``A = -G``).

Mode normalisation follows Table 1: the paper's vector ``v = [alpha; alpha_{n+1}]``
has unit norm and ``alpha_1 > 0``. The paper's ``alpha_{n+1}`` carries the
opposite sign convention for the force; ``Mode.fy`` is the physical ``Fy`` per
unit amplitude in this project's convention (``Fy = -alpha_{n+1} t``), so on the
branch ``q ~ t alpha`` (``t > 0``) the tip force is
``(Fx, Fy) ~ (-load, fy_coefficient * sqrt(dx))`` (eq. 26).

``mu_x`` is eq. 23 generalised: ``dx = mu_x * b * t^2`` with
``mu_x = alpha^T G alpha / (2 b)`` and ``b`` the mean half-length (the paper's
``b`` for equal segments); ``energy_factor`` is eq. 25, ``sum(alpha^2) / mu_x``,
so for equal segments ``E ~ energy_factor * K * dx / (2 b)`` (eq. 24).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, ClassVar, Literal

import numpy as np
import scipy.linalg as sla

from ...errors import (
    InvalidParameterError,
    StraightNotEquilibriumError,
    UnstableStraightError,
    UnsupportedError,
)
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...model.shapes import shape_label, sign_string
from ...model.springs import SHORT_TOL
from ...outcome import Outcome
from ...serialize import number, numbers

__all__ = ["Mode", "Buckling", "critical_force", "straight_matrices"]

Boundary = Literal["guided", "free"]


@dataclass(frozen=True)
class Mode:
    """One buckling mode: a record of :class:`Buckling` (no outcome of its own), immutable (arrays read-only).

    Attributes
    ----------
    load : float
        Critical compressive load ``P`` (force units, > 0); ``Fx = -load``.
    q : ndarray (n,)
        Mode shape ``alpha`` (joint angles per unit amplitude ``t``), Table 1 normalisation.
    fy : float
        Physical ``Fy`` per unit ``t`` (guided only; 0 for ``free``) = ``-alpha_{n+1}``.
    vector : ndarray
        The paper's eigenvector ``[alpha; alpha_{n+1}]`` (guided) or ``alpha`` (free).
    mu_x : float
        Eq. 23: ``dx = mu_x * b * t^2``.
    energy_factor : float
        Eq. 25: ``mu_eq = sum(alpha^2) / mu_x``.
    fy_coefficient : float
        Eq. 26: ``Fy ~ fy_coefficient * sqrt(dx)`` on the branch ``t > 0`` (force / sqrt(length)).
    shape, signs : str
        Label and sign string (:mod:`tensegrity_opt.model.shapes`).
    stable : bool
        The branch born from this mode is stable under displacement control (only the
        lowest mode: branch ``m`` has Morse index ``m - 1`` near the straight configuration).
    """

    load: float
    q: np.ndarray
    fy: float
    vector: np.ndarray
    mu_x: float
    energy_factor: float
    fy_coefficient: float
    shape: str
    signs: str
    stable: bool

    def __post_init__(self) -> None:
        # critical_force builds the arrays for it: read-only in place (as freeze(copy=False), without its loop)
        self.q.setflags(write=False)
        self.vector.setflags(write=False)

    def to_dict(self) -> dict[str, Any]:
        """JSON form (an item of ``modes`` in ``POST /v1/buckling``): ``load``, ``q``, ``fy``,
        ``energy_factor``, ``mu_x``, ``fy_coefficient``, ``shape``, ``signs``, ``stable``."""
        return {"load": number(self.load), "q": numbers(self.q), "fy": number(self.fy),
                "energy_factor": number(self.energy_factor), "mu_x": number(self.mu_x),
                "fy_coefficient": number(self.fy_coefficient), "shape": self.shape, "signs": self.signs,
                "stable": bool(self.stable)}


@dataclass(frozen=True)
class Buckling(Outcome):
    """Result of :func:`critical_force`: the critical loads and modes of the straight chain.

    Attributes
    ----------
    force : float
        Signed critical ``Fx0 = -min(loads)`` (negative: compressive).
    loads : ndarray
        All critical compressive loads, ascending.
    modes : tuple of Mode
        One per load, same order.
    boundary : str
        ``"guided"`` or ``"free"``.
    method : str
        ``"reduced"``, ``"paper"`` or ``"sparse"``.
    status : str
        ``"solved"`` (:attr:`STATUSES`): the eigenproblem is solved or :func:`critical_force` raises.
    message : str
        The same in a sentence: how many loads, of which problem.
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "solved": "the linearised eigenproblem of the straight chain was solved: every critical load asked for "
                  "(all of them, or the lowest n_modes) with its mode",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset(STATUSES)

    force: float
    loads: np.ndarray
    modes: tuple[Mode, ...] = field(repr=False)
    boundary: str = "guided"
    method: str = "reduced"
    status: str = "solved"
    message: str = ""

    def __post_init__(self) -> None:
        # critical_force builds the arrays for it: read-only in place (as freeze(copy=False), without its loop)
        self.loads.setflags(write=False)
        if not isinstance(self.modes, tuple):
            object.__setattr__(self, "modes", tuple(self.modes))
        if self.status not in self.STATUSES:
            self._check_outcome()

    def to_dict(self) -> dict[str, Any]:
        """JSON form (the body of ``POST /v1/buckling``): ``success``, ``status``, ``message``, ``boundary``,
        ``critical_force``, ``loads``, ``modes`` (each :meth:`Mode.to_dict`)."""
        return {**self.outcome(), "boundary": self.boundary, "critical_force": number(self.force),
                "loads": numbers(self.loads), "modes": [md.to_dict() for md in self.modes]}


def straight_matrices(m: Manipulator) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(K, G, S0)`` at the straight configuration (``K`` as a vector of joint stiffnesses)."""
    n = m.n
    T = np.tril(np.ones((n, n)))
    links = m.link_lengths
    G = T.T @ (links[:, None] * T)
    S0 = T.T @ links
    return m.stiffness.copy(), G, S0


def tip_slope(m: Manipulator) -> np.ndarray:
    """``S0 = dy/dq`` at the straight configuration: reverse cumulative sums of the links (O(n))."""
    return np.cumsum(m.link_lengths[::-1])[::-1]


def quad_G(m: Manipulator, q: np.ndarray) -> float:
    """``q^T G q = sum_j links_j (q_1 + ... + q_j)^2`` without forming ``G`` (O(n))."""
    return float(m.link_lengths @ np.cumsum(q) ** 2)


def check_straight(m: Manipulator) -> None:
    """Raise unless the straight configuration is a stable equilibrium of the unloaded chain."""
    grad = m.gradient(np.zeros(m.n))
    scale = np.maximum(m.k1, m.k2) * (m.a ** 2 + m.b ** 2)
    bad = np.flatnonzero(np.abs(grad) > 1e-12 * np.maximum(scale, 1e-300))
    if bad.size:
        i = int(bad[0])
        raise StraightNotEquilibriumError(
            f"the straight configuration is not an equilibrium: segment {i} is asymmetric "
            f"(k1={m.k1[i]:g}, k2={m.k2[i]:g}, L1_0={m.L1_0[i]:g}, L2_0={m.L2_0[i]:g}) and exerts "
            f"a torque {-grad[i]:.6g} at q = 0", field=f"segments[{i}]")
    K = m.stiffness
    bad = np.flatnonzero(K <= 0.0)
    if bad.size:
        i = int(bad[0])
        raise UnstableStraightError(
            f"the straight configuration is not stable unloaded: segment {i} has joint stiffness "
            f"K = k (b L0 - 2 (b^2 - a^2)) = {K[i]:.6g} <= 0 (condition (4) fails); raise L0 above "
            f"{2 * (m.b[i] ** 2 - m.a[i] ** 2) / m.b[i]:.6g}", field=f"segments[{i}].L0")


#: Above this many segments ``method="auto"`` uses the sparse solver and the lowest modes only.
SPARSE_ABOVE = 200


def _taut_when_straight(m: Manipulator) -> None:
    """Buckling linearises at the straight chain: a tension-only spring taut there (``2 b > L0``) is a linear one
    for it; one slack or at its rest length there is refused by name (its stiffness is zero or one-sided)."""
    if m.linear_springs:
        return
    sp = m.springs
    short = sp.stretches(np.zeros(m.n)) <= SHORT_TOL * sp.L0
    for i, j in zip(*np.nonzero(short & sp.tension_only[:, None])):
        raise UnsupportedError(
            f"critical_force linearises at the straight chain, where spring {j + 1} of segment {i} is slack or at its "
            f"rest length (L0 = {sp.L0[i, j]:.6g} >= 2b = {2 * m.b[i]:.6g}) under the tension-only law: its stiffness "
            "there is zero or one-sided (the linear law's answer would be wrong)", field=f"segments[{i}].spring",
            spring="tension_only")


def critical_force(m: Manipulator, boundary: Boundary = "guided", *,
                   method: Literal["auto", "reduced", "paper", "sparse"] = "auto",
                   n_modes: int | None = None) -> Buckling:
    """Critical loads and buckling modes of the straight configuration.

    Parameters
    ----------
    m : Manipulator
        Symmetric segments (straight must be an equilibrium) with ``K_i > 0``.
    boundary : {"guided", "free"}
        ``"guided"``: tip held at ``dy = 0`` (the paper); ``"free"``: cantilever.
    method : {"auto", "reduced", "paper", "sparse"}
        Symmetric reduced generalised eigenproblem (dense), the paper's ``B^-1 A`` form
        (dense), or the sparse form for long chains: in absolute angles ``phi`` the stiffness
        ``D^T K D`` is tridiagonal, ``G`` is ``diag(links)`` and the guided constraint is
        ``links^T phi = 0``; shift-invert Lanczos (``scipy.sparse.linalg.eigsh``) with a
        bordered sparse LU finds the lowest loads in O(n) each. ``"auto"``: ``"reduced"`` up
        to ``SPARSE_ABOVE`` segments, ``"sparse"`` beyond.
    n_modes : int, optional
        How many of the lowest loads to compute: all by default for the dense methods,
        ``min(6, all)`` for ``"sparse"``.

    Returns
    -------
    Buckling

    Raises
    ------
    StraightNotEquilibriumError, UnstableStraightError
        (``ValueError``) when straight is not an equilibrium / not stable unloaded.
    InvalidParameterError
        For an unknown ``boundary``/``method``, or ``boundary="guided"`` with ``n = 1``
        (a single guided segment cannot deflect).
    """
    unloaded_only(m, "critical_force")
    if boundary not in ("guided", "free"):
        raise InvalidParameterError(f"boundary must be 'guided' or 'free', got {boundary!r}", field="boundary")
    _taut_when_straight(m)
    if method not in ("auto", "reduced", "paper", "sparse"):
        raise InvalidParameterError(f"method must be 'auto', 'reduced', 'paper' or 'sparse', got {method!r}",
                                    field="method")
    if method == "auto":
        method = "reduced" if m.n <= SPARSE_ABOVE else "sparse"
    if n_modes is not None and (isinstance(n_modes, bool) or int(n_modes) < 1):
        raise InvalidParameterError("n_modes must be a positive integer", field="n_modes")
    if boundary == "guided" and m.n < 2:
        raise InvalidParameterError("a guided tip (dy = 0 held) needs n >= 2 segments: one segment cannot "
                                    "move its tip along x", field="n")
    check_straight(m)
    guided = boundary == "guided"
    total = m.n - 1 if guided else m.n
    if method == "sparse":
        k = min(total, int(n_modes) if n_modes is not None else 6)
        loads, alphas = _sparse(m, guided, k)
    else:
        K, G, S0 = straight_matrices(m)
        loads, alphas = (_reduced if method == "reduced" else _paper)(K, G, S0, guided)
        if n_modes is not None:
            loads, alphas = loads[:int(n_modes)], alphas[:, :int(n_modes)]
    K = m.stiffness
    S0 = tip_slope(m)
    b_mean = float(m.b.mean())
    modes = []
    for j, (P, alpha) in enumerate(zip(loads, alphas.T)):
        if guided:
            # Fy from the q rows of K q = P G q + Fy S0 (least squares: exact up to roundoff).
            fy_phys = float(S0 @ (K * alpha - P * _G_times(m, alpha)) / (S0 @ S0))
            vec = np.concatenate([alpha, [-fy_phys]])
        else:
            fy_phys = 0.0
            vec = alpha.copy()
        norm = np.linalg.norm(vec)
        sgn = 1.0 if vec[0] > 0 or (vec[0] == 0 and _first_nonzero(vec) > 0) else -1.0
        vec = vec * (sgn / norm)
        alpha = vec[: m.n]
        fy = -vec[m.n] if guided else 0.0
        mu_x = quad_G(m, alpha) / (2.0 * b_mean)
        modes.append(Mode(load=float(P), q=alpha, fy=float(fy), vector=vec, mu_x=mu_x,
                          energy_factor=float(alpha @ alpha) / mu_x,
                          fy_coefficient=float(fy) / np.sqrt(b_mean * mu_x),
                          shape=shape_label(alpha), signs=sign_string(alpha), stable=(j == 0)))
    which = f"all {len(modes)}" if len(modes) == total else f"the lowest {len(modes)} of {total}"
    return Buckling(force=-float(loads[0]), loads=np.asarray(loads, float), modes=tuple(modes),
                    boundary=boundary, method=method,
                    message=f"{which} critical loads of the straight chain, tip {boundary} ({method} eigenproblem)")


def _G_times(m: Manipulator, q: np.ndarray) -> np.ndarray:
    """``G q = T^T (links * (T q))`` in O(n)."""
    w = m.link_lengths * np.cumsum(q)
    return np.cumsum(w[::-1])[::-1]


def _sparse(m: Manipulator, guided: bool, k: int) -> tuple[np.ndarray, np.ndarray]:
    """Lowest ``k`` loads by shift-invert Lanczos in absolute angles (all sparse, O(n) per solve)."""
    import scipy.sparse as sp
    import scipy.sparse.linalg as spla

    n = m.n
    K = m.stiffness
    links = m.link_lengths
    # D^T diag(K) D with D the difference matrix (q = D phi): tridiagonal
    main = K + np.concatenate([K[1:], [0.0]])
    off = -K[1:]
    A = sp.diags([off, main, off], [-1, 0, 1], format="csc")
    M = sp.diags(links, format="csc")
    lu = spla.splu(A)              # tridiagonal, positive definite (all K_i > 0): no fill-in
    if guided:
        # the bordered system [[A, l], [l^T, 0]] [u; f] = [x; 0] by its Schur complement: a
        # direct LU of the arrow matrix pivots on the zero corner and fills in (O(n^2))
        w = lu.solve(links)
        lw = float(links @ w)

        def solve(x):
            y = lu.solve(np.ravel(x))
            return y - (float(links @ y) / lw) * w
    else:
        def solve(x):
            return lu.solve(np.ravel(x))
    if n <= 3 or k >= (n - 1 if guided else n) - 1:
        # ARPACK needs k < dimension - 1: the dense route for tiny problems
        Kd, G, S0 = straight_matrices(m)
        loads, alphas = _reduced(Kd, G, S0, guided)
        return loads[:k], alphas[:, :k]
    op = spla.LinearOperator((n, n), matvec=solve, dtype=float)
    vals, vecs = spla.eigsh(A, k=k, M=M, sigma=0.0, which="LM", OPinv=op, tol=1e-12)
    order = np.argsort(vals)
    vals, U = vals[order], vecs[:, order]
    Q = np.diff(np.vstack([np.zeros((1, k)), U]), axis=0)    # q = D phi
    return vals, Q


def _first_nonzero(v: np.ndarray) -> float:
    nz = v[np.abs(v) > 1e-12 * np.abs(v).max()]
    return float(nz[0]) if nz.size else 1.0


def _reduced(K, G, S0, guided):
    if guided:
        Z = sla.null_space(S0[None, :])
        P, V = sla.eigh(Z.T @ (K[:, None] * Z), Z.T @ G @ Z)
        return P, Z @ V
    return sla.eigh(np.diag(K), G)


def _paper(K, G, S0, guided):
    n = K.size
    if guided:
        B = np.zeros((n + 1, n + 1))
        B[:n, :n] = np.diag(K)
        B[:n, n] = S0
        B[n, :n] = S0
        A = np.zeros((n + 1, n + 1))
        A[:n, :n] = -G
    else:
        B, A = np.diag(K), -G
    lam, V = sla.eig(np.linalg.solve(B, A))
    lam = lam.real
    V = V.real
    scale = np.abs(lam).max()
    keep = np.flatnonzero(np.abs(lam) > 1e-10 * scale)
    loads = -1.0 / lam[keep]
    order = np.argsort(loads)
    alphas = V[:n, keep[order]]
    return loads[order], alphas
