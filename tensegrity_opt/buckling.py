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
from typing import Literal

import numpy as np
import scipy.linalg as sla

from .errors import InvalidParameterError, StraightNotEquilibriumError, UnstableStraightError
from .manipulator import Manipulator
from .shapes import shape_label, sign_string

__all__ = ["Mode", "Buckling", "critical_force", "straight_matrices"]

Boundary = Literal["guided", "free"]


@dataclass(frozen=True)
class Mode:
    """One buckling mode.

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
        Label and sign string (:mod:`tensegrity_opt.shapes`).
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


@dataclass(frozen=True)
class Buckling:
    """Result of :func:`critical_force`.

    Attributes
    ----------
    force : float
        Signed critical ``Fx0 = -min(loads)`` (negative: compressive).
    loads : ndarray
        All critical compressive loads, ascending.
    modes : list of Mode
        One per load, same order.
    boundary : str
        ``"guided"`` or ``"free"``.
    method : str
        ``"reduced"`` or ``"paper"``.
    """

    force: float
    loads: np.ndarray
    modes: list[Mode] = field(repr=False)
    boundary: str = "guided"
    method: str = "reduced"


def straight_matrices(m: Manipulator) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(K, G, S0)`` at the straight configuration (``K`` as a vector of joint stiffnesses)."""
    n = m.n
    T = np.tril(np.ones((n, n)))
    links = m.link_lengths
    G = T.T @ (links[:, None] * T)
    S0 = T.T @ links
    return m.stiffness.copy(), G, S0


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


def critical_force(m: Manipulator, boundary: Boundary = "guided", *,
                   method: Literal["reduced", "paper"] = "reduced") -> Buckling:
    """Critical loads and buckling modes of the straight configuration.

    Parameters
    ----------
    m : Manipulator
        Symmetric segments (straight must be an equilibrium) with ``K_i > 0``.
    boundary : {"guided", "free"}
        ``"guided"``: tip held at ``dy = 0`` (the paper); ``"free"``: cantilever.
    method : {"reduced", "paper"}
        Symmetric reduced generalised eigenproblem or the paper's ``B^-1 A`` form.

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
    if boundary not in ("guided", "free"):
        raise InvalidParameterError(f"boundary must be 'guided' or 'free', got {boundary!r}", field="boundary")
    if method not in ("reduced", "paper"):
        raise InvalidParameterError(f"method must be 'reduced' or 'paper', got {method!r}", field="method")
    if boundary == "guided" and m.n < 2:
        raise InvalidParameterError("a guided tip (dy = 0 held) needs n >= 2 segments: one segment cannot "
                                    "move its tip along x", field="n")
    check_straight(m)
    K, G, S0 = straight_matrices(m)
    guided = boundary == "guided"
    if method == "reduced":
        loads, alphas = _reduced(K, G, S0, guided)
    else:
        loads, alphas = _paper(K, G, S0, guided)
    b_mean = float(m.b.mean())
    modes = []
    for j, (P, alpha) in enumerate(zip(loads, alphas.T)):
        if guided:
            # Fy from the q rows of K q = P G q + Fy S0 (least squares: exact up to roundoff).
            fy_phys = float(S0 @ (K * alpha - P * (G @ alpha)) / (S0 @ S0))
            vec = np.concatenate([alpha, [-fy_phys]])
        else:
            fy_phys = 0.0
            vec = alpha.copy()
        norm = np.linalg.norm(vec)
        sgn = 1.0 if vec[0] > 0 or (vec[0] == 0 and _first_nonzero(vec) > 0) else -1.0
        vec = vec * (sgn / norm)
        alpha = vec[: m.n]
        fy = -vec[m.n] if guided else 0.0
        mu_x = float(alpha @ G @ alpha) / (2.0 * b_mean)
        modes.append(Mode(load=float(P), q=alpha, fy=float(fy), vector=vec, mu_x=mu_x,
                          energy_factor=float(alpha @ alpha) / mu_x,
                          fy_coefficient=float(fy) / np.sqrt(b_mean * mu_x),
                          shape=shape_label(alpha), signs=sign_string(alpha), stable=(j == 0)))
    return Buckling(force=-float(loads[0]), loads=np.asarray(loads, float), modes=modes,
                    boundary=boundary, method=method)


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
