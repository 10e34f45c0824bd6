"""Vibration modes of an equilibrium: natural frequencies and mode shapes (``docs/model.md``, "Masses and modes").

The linearised motion about an equilibrium ``q*`` is ``M dq'' + K dq = 0`` on the motions the equilibrium allows:

* ``M`` the chain's mass matrix (:func:`~tensegrity_opt.model.inertia.mass_matrix`: the triangles' centroids and the
  payload as point masses, plus each triangle's rotational inertia);
* ``K`` the Hessian of the potential ``E(q) + V(q) - F . tip(q)`` in the joint angles: ``diag(E_i''(q_i))`` plus
  the dead loads' ``sum_{l >= max(j, k)} G_l . u_l`` (:mod:`~tensegrity_opt.model.loads`) plus ``F . r_max(j, k)``
  (``r_j`` the vector from joint ``j`` to the tip; ``F`` the tip force, under a held tip the
  constraint's multiplier: the same Lagrangian Hessian). Under the tension-only law ``E_i''`` is the one of the
  springs' states at ``q*``;
* the motions: with the tip held (the equilibrium was posed by a tip displacement) those tangent to the tip
  constraint; with the tip loaded (posed by a tip force) every joint; a joint resting on its stop stays there.

On a basis ``Z`` of those motions the modes solve ``(Z^T K Z) v = w^2 (Z^T M Z) v`` (:func:`scipy.linalg.eigh`);
the shapes ``Z v`` are mass-normalised (``shape^T M shape = 1``).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np
import scipy.linalg as sla

from ...errors import InvalidParameterError
from ...model.inertia import mass_matrix, total_mass
from ...model.loads import loads_json
from ...model.manipulator import Manipulator
from ...outcome import Outcome, freeze
from ...serialize import nullables, numbers
from .equilibrium import Equilibrium

__all__ = ["Modes", "modes", "TIPS"]

#: How the tip is held in the modes: ``"held"`` (prescribed: the motions tangent to it) or ``"loaded"`` (a dead load).
TIPS = ("held", "loaded")
#: An eigenvalue ``w^2`` within this much of zero, relative to the largest, is zero (a marginal direction).
ZERO_TOL = 1e-9


@dataclass(frozen=True)
class Modes(Outcome):
    """Result of :func:`modes`: the vibration modes of an equilibrium.

    Attributes
    ----------
    frequencies : ndarray (d,)
        The natural frequencies ``w`` (rad/s when masses are in kg, stiffnesses in N/m and lengths in m),
        ascending; NaN for a direction that does not vibrate (``eigenvalues <= 0``: status ``unstable`` or
        ``degenerate``).
    eigenvalues : ndarray (d,)
        ``w^2``, ascending (negative: a direction the equilibrium is unstable in, growing as ``e^{sqrt(-w^2) t}``).
    shapes : ndarray (d, n)
        Mode ``k``'s joint angles (row ``k``), mass-normalised: ``shapes[k] @ M @ shapes[k] = 1``.
    mass_matrix : ndarray (n, n)
        ``M(q*)`` in the joint angles.
    stiffness_matrix : ndarray (n, n)
        ``K`` in the joint angles (before the tip's and the stops' constraints).
    tip : str
        ``"held"`` or ``"loaded"`` (:data:`TIPS`).
    held_joints : ndarray (n,) of bool
        The joints held on their stop.
    total_mass : float
        The segments' masses and the payload.
    equilibrium : Equilibrium
        The equilibrium the modes are of.
    status : str
        :attr:`STATUSES`.
    message : str
        The same in a sentence, with the lowest frequency.
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "solved": "the equilibrium is stable on its allowed motions: every mode vibrates (all w^2 > 0)",
        "unstable": "some w^2 < 0: the equilibrium is unstable in those directions (no vibration; frequencies NaN "
                    "there)",
        "degenerate": "some w^2 is zero up to rounding: a marginal direction (a fold or a branch point); its "
                      "frequency is NaN",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"solved"})

    frequencies: np.ndarray
    eigenvalues: np.ndarray
    shapes: np.ndarray
    mass_matrix: np.ndarray = field(repr=False)
    stiffness_matrix: np.ndarray = field(repr=False)
    tip: str
    held_joints: np.ndarray = field(repr=False)
    total_mass: float
    equilibrium: Equilibrium = field(repr=False)
    status: str

    def __post_init__(self) -> None:
        freeze(self)

    @property
    def message(self) -> str:
        d = self.eigenvalues.size
        where = "with the tip held" if self.tip == "held" else "with the tip loaded"
        held = int(self.held_joints.sum())
        stops = f", {held} joint(s) held on their stop" if held else ""
        if d == 0:
            return f"no motion is left {where}{stops}: the arm is held rigid"
        if self.status == "solved":
            return (f"{d} modes {where}{stops}; lowest frequency {self.frequencies[0]:.6g} rad/s "
                    f"({self.frequencies[0] / (2 * np.pi):.6g} Hz)")
        neg = int(np.sum(~np.isfinite(self.frequencies)))
        word = "unstable" if self.status == "unstable" else "marginal"
        return f"{d} directions {where}{stops}: {neg} {word} (w^2 <= 0, no vibration there)"

    def to_dict(self) -> dict[str, Any]:
        """JSON form: ``success``, ``status``, ``message``, ``frequencies`` (null where a direction does not
        vibrate), ``eigenvalues``, ``shapes`` (mode-major, joint angles), ``tip``, ``held_joints``,
        ``total_mass``, ``loads`` (the equilibrium's dead loads, null where none)."""
        return {**self.outcome(), "frequencies": nullables(self.frequencies), "eigenvalues": numbers(self.eigenvalues),
                "shapes": numbers(self.shapes), "tip": self.tip, "held_joints": [bool(v) for v in self.held_joints],
                "total_mass": float(self.total_mass), "loads": loads_json(self.equilibrium.loads)}


def stiffness_matrix(m: Manipulator, q: np.ndarray, force: np.ndarray) -> np.ndarray:
    """``K`` (n, n): the Hessian of ``E(q) + V(q) - F . tip(q)`` in the joint angles (module docstring; ``V`` the
    chain's dead loads, :mod:`~tensegrity_opt.model.loads`)."""
    q = np.asarray(q, dtype=float)
    force = np.asarray(force, dtype=float)
    psi = np.cumsum(q)
    links = m.link_lengths * np.exp(1j * psi)
    r = np.cumsum(links[::-1])[::-1]                                   # joint j to the tip
    rF = r.real * force[0] + r.imag * force[1]
    n = m.n
    K = rF[np.maximum.outer(np.arange(n), np.arange(n))]
    K[np.diag_indices(n)] += np.array([-float(s.dtorque(v)) for s, v in zip(m.segments, q)])
    if m.loaded:                                # the dead loads' potential (weights, joint forces)
        K += m.load_hessian(q)
    return K


def modes(m: Manipulator, equilibrium: Equilibrium, *, tip: str | None = None) -> Modes:
    """The vibration modes of ``equilibrium`` of ``m`` (module docstring).

    Parameters
    ----------
    m : Manipulator
        The chain, with its masses (``Segment(..., mass=, inertia=)``, ``Manipulator(..., payload=)``).
    equilibrium : Equilibrium
        An equilibrium of ``m`` (``solve_equilibrium``, ``solve_equilibrium_under_force``, a set's member ...).
    tip : {"held", "loaded"}, optional
        ``"held"``: the tip stays where it is (the motions tangent to the tip constraint); ``"loaded"``: a dead
        load, the tip free. Default: as the equilibrium was posed (``held`` for a tip displacement,
        ``loaded`` for a tip force).

    Returns
    -------
    Modes
        ``success`` when the equilibrium is stable on its motions; ``frequencies`` ascending.

    Raises
    ------
    InvalidParameterError
        (a ``ValueError``) ``field="mass"`` when the chain has no mass, none that moves on some allowed motion, or
        masses too small or large against the stiffnesses to resolve in double precision; ``field="equilibrium"``
        when its ``q`` does not fit ``m``; ``field="tip"`` for an unknown ``tip``, or a held tip where its
        constraint is singular (the fully extended chain: the held arm cannot move).

    Examples
    --------
    >>> import tensegrity_opt as to
    >>> m = to.Manipulator.uniform(4, mass=0.1)
    >>> md = to.modes(m, to.solve_equilibrium(m, 1.0))
    >>> md.status, md.frequencies.size
    ('solved', 2)
    """
    if tip is None:
        tip = "held" if equilibrium.control == "displacement" else "loaded"
    if tip not in TIPS:
        raise InvalidParameterError(f"tip must be one of {TIPS}, got {tip!r}", field="tip")
    q = np.asarray(equilibrium.q, dtype=float)
    if q.shape != (m.n,):
        raise InvalidParameterError(f"the equilibrium has {q.size} joint angles, the chain {m.n} joints",
                                    field="equilibrium")
    if total_mass(m) <= 0.0:
        raise InvalidParameterError("the chain has no mass: give its segments a mass (Segment(..., mass=)) or the "
                                    "tip a payload (Manipulator(..., payload=))", field="mass")
    M = mass_matrix(m, q)
    K = stiffness_matrix(m, q, equilibrium.force)
    held = np.asarray(equilibrium.at_stop, dtype=bool)
    rows = [np.eye(m.n)[held]]
    if tip == "held":
        J = m.jacobian(q)
        s = np.linalg.svd(J, compute_uv=False)
        if s[-1] <= 1e-9 * max(float(s[0]), float(m.link_lengths.sum())):
            raise InvalidParameterError(
                "the tip is held where its constraint is singular (the chain's joints in line with the tip, e.g. "
                "fully extended): the held arm cannot move there, so it has no modes; ask for tip='loaded'",
                field="tip")
        rows.append(J)
    C = np.vstack(rows)
    if C.shape[0]:
        Q, R = np.linalg.qr(C.T, mode="complete")
        rank = int(np.sum(np.abs(np.diag(R)) > 1e-12 * max(1.0, float(np.abs(R).max())))) if R.size else 0
        Z = Q[:, rank:]
    else:
        Z = np.eye(m.n)
    Kr, Mr = Z.T @ K @ Z, Z.T @ M @ Z
    mw = np.zeros(1)
    if Z.shape[1] == 0:
        w, V = np.zeros(0), np.zeros((0, 0))
    else:
        mw = np.linalg.eigvalsh(Mr)
        if not mw[0] > 1e-12 * float(np.abs(M).max()):          # relative to the whole chain's (NaN: refused too)
            raise InvalidParameterError(
                "the mass matrix is singular on the arm's allowed motions: some link carries no mass that moves "
                "(give each segment a mass, or the tip a payload)", field="mass")
        w, V = sla.eigh(Kr, Mr)
        if not (np.all(np.isfinite(w)) and np.all(np.isfinite(V))):
            raise InvalidParameterError("the masses are too small or too large against the stiffnesses for the modes "
                                        "to be resolved in double precision", field="mass")
    shapes = (Z @ V).T
    # zero relative to the stiffness scale (torque / rad) over the largest reduced mass, not only to the largest w^2:
    # a chain marginal in every direction has every w^2 ~ 0
    scale = m.torque_scale / float(mw[-1]) if Z.shape[1] else 1.0
    tol = ZERO_TOL * max(float(np.abs(w).max(initial=0.0)), scale)
    status = "unstable" if np.any(w < -tol) else "degenerate" if np.any(np.abs(w) <= tol) else "solved"
    freq = np.where(w > tol, np.sqrt(np.maximum(w, 0.0)), np.nan)
    return Modes(freq, w, shapes, M, K, tip, held, total_mass(m), equilibrium, status)
