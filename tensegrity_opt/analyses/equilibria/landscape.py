"""The paper's "straightforward energy method" for n = 4 (Figs. 4-5).

Two joint angles ``(q_i, q_j)`` are chosen on a grid; the other two follow from
the tip constraint by two-link inverse kinematics (both elbow branches); the
energy ``E(q)`` is evaluated there. Points where the tip cannot be reached, or
the completed configuration leaves the physical range, are NaN. Stationary
points of this two-variable function are exactly the equilibria.

This route shares no code with the CasADi solvers (plain numpy trigonometry),
which makes it an independent check of them.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from ...errors import InvalidParameterError, UnsupportedError
from ...model.loads import load_potential, loads_json, loads_key
from ...model.manipulator import Manipulator
from ...outcome import Outcome, freeze
from ...serialize import nullables, numbers

__all__ = ["Landscape", "energy_landscape", "complete_configuration", "landscape_margin", "landscape_span"]


@dataclass(frozen=True)
class Landscape(Outcome):
    """Energy over a grid of two joint angles (immutable: arrays read-only).

    Attributes
    ----------
    pair : (int, int)
        The two free joints (0-based).
    qi, qj : ndarray
        Grid axes (rad).
    energy : ndarray (2, len(qi), len(qj))
        Energy on each elbow branch (``[0]``: elbow ``+1``, ``[1]``: elbow ``-1``), NaN where
        unreachable or outside the physical range.
    q : ndarray (2, len(qi), len(qj), 4)
        The completed configurations.
    status : str
        ``"evaluated"`` (:attr:`STATUSES`): the grid is evaluated or :func:`energy_landscape` raises; a grid
        with no point inside the range is an answer too.
    message : str
        The same in a sentence: the grid and how many of its points lie inside the range.
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "evaluated": "the energy was evaluated at every grid point on both elbow branches (NaN, null in JSON, "
                     "where the tip is out of the two arms' reach or the configuration leaves the physical range)",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset(STATUSES)

    pair: tuple[int, int]
    qi: np.ndarray
    qj: np.ndarray
    energy: np.ndarray
    q: np.ndarray
    status: str = "evaluated"
    loads: tuple | None = None

    def __post_init__(self) -> None:
        freeze(self)

    @property
    def message(self) -> str:
        """A sentence: the grid and how many of its points lie inside the range."""
        i, j = self.pair
        inside = int(np.count_nonzero(np.isfinite(self.energy)))
        return (f"the energy on a {self.qi.size} x {self.qj.size} grid of (q{i + 1}, q{j + 1}), both elbow "
                f"branches: {inside} of {self.energy.size} points inside the reach and the physical range")

    def to_dict(self) -> dict[str, Any]:
        """JSON form (the body of ``POST /v1/energy-landscape``): ``success``, ``status``, ``message``, ``pair``,
        ``qi``, ``qj`` and ``energy`` (``[elbow][i][j]``, ``null`` outside the reachable set or the physical
        range; the chain's potential under its dead loads where it carries some), ``loads`` (those loads, ``null``
        without)."""
        return {**self.outcome(), "pair": [int(p) for p in self.pair], "qi": numbers(self.qi),
                "qj": numbers(self.qj), "energy": nullables(self.energy), "loads": loads_json(self.loads)}


def complete_configuration(m: Manipulator, target, pair: tuple[int, int], qi, qj, elbow: int) -> np.ndarray:
    """Full ``q`` (shape ``(..., n)``) with ``q[pair] = (qi, qj)`` and the tip at ``target``.

    The two remaining joints ``u < v`` come from two-link IK: the links between joint ``u``
    and joint ``v`` form one rigid arm, those after joint ``v`` another. ``elbow`` is ``+1``
    or ``-1``. NaN where the target is out of reach for the two arms.
    """
    q, cos_g = _two_link(m, target, pair, qi, qj, elbow)
    u, v = [k for k in range(m.n) if k not in pair]
    ok = np.abs(cos_g) <= 1.0
    q[..., u] = np.where(ok, q[..., u], np.nan)
    q[..., v] = np.where(ok, q[..., v], np.nan)
    return q


def landscape_margin(m: Manipulator, target, pair: tuple[int, int], qi, qj, elbow: int) -> tuple[np.ndarray,
                                                                                                 np.ndarray]:
    """A continuous margin of the landscape's domain and the configuration extended beyond it.

    Returns ``(margin, q)``: ``margin`` is positive exactly where :func:`complete_configuration`
    gives a configuration inside the open physical range, zero on the boundary of that set and
    negative outside, and it is a smooth function of ``(qi, qj)`` across the boundary, so that its
    zero contour (linear interpolation on a grid) is the exact boundary up to the grid's second
    order, not the staircase of the grid cells. It is the least of ``1 - |cos gamma|`` (the two-link
    reach: ``gamma`` the angle at the arms' common joint, unclipped) and ``1 - |q_k| / q_max_k`` over
    the joints (the physical range). ``q`` is the configuration with ``cos gamma`` clipped to
    ``[-1, 1]``: equal to :func:`complete_configuration` inside the reach, the nearest reachable
    arm (both arms aligned) outside it, finite everywhere.
    """
    q, cos_g = _two_link(m, target, pair, qi, qj, elbow)
    lim = np.asarray(m.joint_limits, float)
    with np.errstate(invalid="ignore"):
        joint = np.min(1.0 - np.abs(q) / lim, axis=-1)
    return np.minimum(1.0 - np.abs(cos_g), joint), q


def _two_link(m: Manipulator, target, pair: tuple[int, int], qi, qj, elbow: int) -> tuple[np.ndarray, np.ndarray]:
    """The configuration of :func:`complete_configuration` with ``cos gamma`` clipped (finite everywhere),
    and the unclipped ``cos gamma`` (reachable where ``|cos gamma| <= 1``)."""
    n = m.n
    i, j = pair
    free = [k for k in range(n) if k not in (i, j)]
    if len(free) != 2:
        raise UnsupportedError("the landscape needs exactly two unknown joints (n = 4)", field="pair")
    u, v = free
    qi, qj = np.broadcast_arrays(np.asarray(qi, float), np.asarray(qj, float))
    shape = qi.shape
    q = np.zeros(shape + (n,))
    q[..., i] = qi
    q[..., j] = qj
    links = m.link_lengths
    base = np.array([m.base_length, 0.0])
    # Joint u position: links before u depend on known joints only (all joints < u are known).
    phi = np.cumsum(q, axis=-1)            # valid for indices < u
    pu = np.broadcast_to(base, shape + (2,)).copy()
    for k in range(u):
        pu = pu + links[k] * np.stack([np.cos(phi[..., k]), np.sin(phi[..., k])], axis=-1)
    phi_before_u = phi[..., u - 1] if u > 0 else np.zeros(shape)

    def arm(start, stop):
        """The links ``start`` to ``stop - 1`` as one vector in the frame of link ``start`` (its joint angle 0),
        and the last link's angle relative to link ``start`` (each accumulates the joints between)."""
        w = np.zeros(shape + (2,))
        rel = np.zeros(shape)
        for k in range(start, stop):
            if k > start:
                rel = rel + q[..., k]
            w = w + links[k] * np.stack([np.cos(rel), np.sin(rel)], axis=-1)
        return w, rel

    w1, last_rel1 = arm(u, v)               # arm 1, joint u to joint v: rotate by (phi_before_u + q_u)
    w2, _ = arm(v, n)                       # arm 2, joint v to the tip: rotate by the absolute angle of link v
    d = np.asarray(target, float) - pu
    r1 = np.hypot(w1[..., 0], w1[..., 1])
    r2 = np.hypot(w2[..., 0], w2[..., 1])
    D = np.hypot(d[..., 0], d[..., 1])
    with np.errstate(invalid="ignore", divide="ignore"):
        cos_g = (D * D + r1 * r1 - r2 * r2) / (2.0 * D * r1)
        gam = np.arccos(np.clip(cos_g, -1.0, 1.0))
        ang_d = np.arctan2(d[..., 1], d[..., 0])
        a1 = ang_d + elbow * gam            # direction of arm 1 (absolute)
        p_v = pu + r1[..., None] * np.stack([np.cos(a1), np.sin(a1)], axis=-1)
        e = np.asarray(target, float) - p_v
        a2 = np.arctan2(e[..., 1], e[..., 0])  # direction of arm 2 (absolute)
    th1 = np.arctan2(w1[..., 1], w1[..., 0])
    th2 = np.arctan2(w2[..., 1], w2[..., 0])
    abs_u = a1 - th1                        # absolute angle of link u
    abs_v = a2 - th2                        # absolute angle of link v
    # Relative angles as the signed angle between consecutive link directions (atan2 of
    # cross and dot products): IK yields directions, and in the physical range |q| < pi the
    # relative angle is the unique one in (-pi, pi]. No angle is reduced modulo 2 pi.
    qu = _angle_between(phi_before_u, abs_u)
    before_v = abs_u + last_rel1 if v - 1 >= u else abs_u
    qv = _angle_between(before_v, abs_v)
    q[..., u] = qu
    q[..., v] = qv
    return q, cos_g


def energy_landscape(m: Manipulator, dx: float, dy: float = 0.0, pair: tuple[int, int] = (0, 3),
                     grid: int | tuple[np.ndarray, np.ndarray] = 101, span: float | None = None) -> Landscape:
    """Energy ``E(q_i, q_j)`` with the other two joints from inverse kinematics (n = 4).

    Parameters
    ----------
    m : Manipulator
        Exactly 4 segments.
    dx, dy : float
        Tip deflection.
    pair : (int, int)
        The two grid joints, 0-based (the paper's ``(q1, q4)`` is ``(0, 3)``).
    grid : int or (array, array)
        Points per axis over ``[-span, span]``, or the two axes explicitly (rad).
    span : float, optional
        Half-width of the default axes; default the smaller physical joint limit of the pair.

    Returns
    -------
    Landscape
    """
    if m.n != 4:
        raise UnsupportedError(f"the energy landscape is defined for n = 4 segments, got n = {m.n}", field="n")
    pair = tuple(int(p) for p in pair)
    if len(pair) != 2 or pair[0] == pair[1] or not all(0 <= p < 4 for p in pair):
        raise InvalidParameterError(f"pair must be two different joints in 0..3, got {pair}", field="pair")
    target = m.check_reachable(dx, dy)
    if isinstance(grid, (int, np.integer)):
        if grid < 2:
            raise InvalidParameterError("grid needs at least 2 points per axis", field="grid")
        s = span if span is not None else float(min(m.joint_limits[list(pair)])) * 0.999
        qi = qj = np.linspace(-s, s, int(grid))
    else:
        qi, qj = (np.asarray(g, float) for g in grid)
    QI, QJ = np.meshgrid(qi, qj, indexing="ij")
    energies, configs = [], []
    lim = m.joint_limits
    for elbow in (1, -1):
        q = complete_configuration(m, target, pair, QI, QJ, elbow)
        L1, L2 = _lengths(m, q)
        if m.linear_springs:
            E = 0.5 * ((m.k1 * (L1 - m.L1_0) ** 2).sum(-1) + (m.k2 * (L2 - m.L2_0) ** 2).sum(-1))
        else:                                   # each spring's law (a slack spring holds nothing)
            E = m.springs.energy(q)
        if m.loaded:                            # the dead loads' potential (weights, joint forces)
            E = E + load_potential(m, q.reshape(-1, m.n)).reshape(E.shape)
        inside = np.all(np.abs(q) < lim, axis=-1)
        energies.append(np.where(inside, E, np.nan))
        configs.append(q)
    return Landscape(pair=pair, qi=qi, qj=qj, energy=np.stack(energies), q=np.stack(configs), loads=loads_key(m))



def landscape_span(m: Manipulator, dx: float, dy: float = 0.0, pair: tuple[int, int] = (0, 3),
                   probe: int = 201) -> float:
    """Half-width of the square ``[-s, s]^2`` holding every finite point of the landscape.

    A ``probe`` x ``probe`` landscape over the default axes (the physical range) locates the
    reachable region; the answer adds two probe cells and never exceeds the default span.
    For small deflections the region is a small patch around the origin, so a landscape over it
    (``energy_landscape(..., span=landscape_span(...))``) instead of the whole physical range resolves the
    equilibria.
    """
    full = energy_landscape(m, dx, dy, pair=pair, grid=probe)
    finite = np.isfinite(full.energy).any(axis=0)
    default = float(np.max(np.abs(full.qi)))
    if not finite.any():
        return default
    cell = 2.0 * default / (probe - 1)
    ext = max(float(np.max(np.abs(full.qi[finite.any(axis=1)]))), float(np.max(np.abs(full.qj[finite.any(axis=0)]))))
    return float(min(default, ext + 2.0 * cell))

def _angle_between(a, b):
    """Signed angle from direction ``a`` to direction ``b`` (rad, in (-pi, pi])."""
    return np.arctan2(np.sin(b) * np.cos(a) - np.cos(b) * np.sin(a), np.cos(b) * np.cos(a) + np.sin(b) * np.sin(a))


def _lengths(m: Manipulator, q: np.ndarray):
    c = np.hypot(m.a, m.b)
    beta = np.arctan2(m.a, m.b)
    return 2 * c * np.cos(beta + q / 2), 2 * c * np.cos(beta - q / 2)
