"""A serial chain of dual-triangle segments: kinematics and elastostatics in numpy.

The base is fixed, the chain is straight along +x. Joint ``j`` (1-based) has the
relative angle ``q_j``; absolute link angles are ``phi_j = q_1 + ... + q_j``.
The base half-link has length ``b_1``, the link after joint ``j < n`` has length
``b_j + b_{j+1}`` and the last one ``b_n`` (eq. 5 for equal ``b``), so the
straight length is ``2 sum(b)``. A deflection ``(dx, dy)`` puts the tip at
``(2 sum(b) - dx, dy)``.

Everything here is plain numpy on relative angles ``q`` (the paper's variables);
the solvers work on absolute angles internally.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass
from functools import cached_property
from typing import Any, NamedTuple

import numpy as np

from ..errors import InvalidParameterError, UnreachableTargetError, unknown_name
from . import loads as _loads
from .segment import Segment, _nonnegative
from .springs import Springs, linear_only

__all__ = ["Manipulator", "TipKinematics"]


class TipKinematics(NamedTuple):
    """The tip of many configurations at once (:meth:`Manipulator.tip_kinematics`), rows as the rows of ``Q``."""

    #: ``cos phi_j``, ``sin phi_j`` of the absolute link angles ``phi_j = q_1 + ... + q_j``, (M, n).
    cos: np.ndarray
    sin: np.ndarray
    #: Tip positions, (M, 2).
    tip: np.ndarray
    #: The tip Jacobian's rows ``d x_tip / dq`` and ``d y_tip / dq``, (M, n) each.
    Jx: np.ndarray
    Jy: np.ndarray


_SEGMENT_KEYS = ("a", "b", "k", "L0", "spring", "mass", "inertia")


def _known_keys(d: dict[str, Any], keys: tuple[str, ...], prefix: str) -> None:
    for key in d:
        if key not in keys:
            raise InvalidParameterError(f"{prefix}{key}: {unknown_name(key, keys, 'key')}", field=f"{prefix}{key}")


@dataclass(frozen=True)
class Manipulator:
    """A chain of ``n >= 1`` segments (base first).

    Parameters
    ----------
    segments : sequence of Segment
        The segments from base to tip; they may differ in every parameter.
    payload : float
        A point mass at the tip (>= 0, default 0): like the segments' masses it changes no equilibrium without
        gravity and sets the vibration modes (:func:`~tensegrity_opt.modes`).
    gravity : (gx, gy) or None
        The gravity vector in the plane of the chain (default None: no weight); ``(0, -9.81)`` for a chain pointing
        along +x in a vertical plane, any direction (a tilted base). The weights of the segments' triangles and of
        the payload then load the chain in every analysis that honours the loads (:mod:`~.loads`).
    joint_forces : sequence of (joint, (fx, fy))
        Dead point forces at joints (fixed in direction), joints counted from 1 at the base (joint 1 is fixed: a
        force there does no work); beside the tip force of each analysis. Also ``{joint: (fx, fy)}``.

    Raises
    ------
    InvalidParameterError
        (a ``ValueError``, ``field="segments"``) when the sequence is empty or
        holds something other than :class:`Segment`; ``field="payload"`` when it is negative or not finite;
        ``field="gravity"`` / ``"joint_forces[i]..."`` for a malformed load.
    """

    segments: tuple[Segment, ...]
    payload: float = 0.0
    gravity: tuple[float, float] | None = None
    joint_forces: tuple[tuple[int, tuple[float, float]], ...] = ()

    def __init__(self, segments: Iterable[Segment], payload: float = 0.0, gravity: Any = None,
                 joint_forces: Any = ()) -> None:
        if isinstance(segments, Segment):
            segments = (segments,)
        try:
            segs = tuple(segments)
        except TypeError:
            raise InvalidParameterError("segments must be a sequence of Segment", field="segments") from None
        if len(segs) < 1:
            raise InvalidParameterError("a manipulator needs n >= 1 segments", field="segments")
        for i, s in enumerate(segs):
            if not isinstance(s, Segment):
                raise InvalidParameterError(
                    f"segments[{i}] must be a Segment, got {type(s).__name__}", field=f"segments[{i}]")
        object.__setattr__(self, "segments", segs)
        object.__setattr__(self, "payload", _nonnegative(payload, "payload"))
        object.__setattr__(self, "gravity", _loads.check_gravity(gravity))
        object.__setattr__(self, "joint_forces", _loads.check_joint_forces(joint_forces, len(segs)))

    def __hash__(self) -> int:
        # computed once: hashing 10^4 segments costs milliseconds, and the caches keyed by the chain
        # (buckling modes, seed directions) look it up on every solve
        h = self.__dict__.get("_hash")
        if h is None:
            extra = (self.payload, self.gravity, self.joint_forces)
            h = hash(self.segments) if extra == (0.0, None, ()) else hash((self.segments, extra))
            object.__setattr__(self, "_hash", h)
        return h

    @classmethod
    def uniform(cls, n: int, a: float = 1.0, b: float = 1.0, k: float | tuple[float, float] = 1.0,
                L0: float | tuple[float, float] = 1.0, spring: str = "linear", mass: float = 0.0,
                inertia: float = 0.0, payload: float = 0.0, gravity: Any = None,
                joint_forces: Any = ()) -> "Manipulator":
        """``n`` identical segments ``Segment(a, b, k, L0, spring, mass, inertia)``, a ``payload`` at the tip, the
        chain's ``gravity`` and ``joint_forces``."""
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 1:
            raise InvalidParameterError(f"n must be an integer >= 1, got {n!r}", field="n")
        seg = Segment(a, b, k, L0, spring, mass, inertia)
        return cls((seg,) * int(n), payload, gravity, joint_forces)

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> "Manipulator":
        """From ``{"n", "a", "b", "k", "L0", "spring", "mass", "inertia", "payload", "gravity", "joint_forces"}``
        (uniform) or ``{"segments": [...], "payload", "gravity", "joint_forces"}`` (``joint_forces`` as
        ``[{"joint": j, "force": [fx, fy]}, ...]``); a key it does not know is refused naming the nearest valid one
        (``segments[0].l0: unknown key; did you mean L0?``)."""
        chain = ("payload", "gravity", "joint_forces")
        loads = (d.get("payload", 0.0), d.get("gravity"), d.get("joint_forces", ()))
        if "segments" in d:
            _known_keys(d, ("segments", *chain), "")
            for i, s in enumerate(d["segments"]):
                if isinstance(s, dict):
                    _known_keys(s, _SEGMENT_KEYS, f"segments[{i}].")
            return cls((Segment(**s) for s in d["segments"]), *loads)
        _known_keys(d, ("n", *_SEGMENT_KEYS, *chain), "")
        return cls.uniform(d.get("n", 4), d.get("a", 1.0), d.get("b", 1.0), d.get("k", 1.0), d.get("L0", 1.0),
                           d.get("spring", "linear"), d.get("mass", 0.0), d.get("inertia", 0.0), *loads)

    def to_dict(self) -> dict[str, Any]:
        """JSON form ``{"segments": [{"a", "b", "k", "L0"}, ...]}`` (``k`` / ``L0`` one number when both
        springs agree, else the pair; ``spring``, ``mass``, ``inertia`` where they are not their defaults;
        ``payload``, ``gravity``, ``joint_forces`` where they are set): what the API returns for a chain, accepted by
        :meth:`from_dict`."""
        out: dict[str, Any] = {"segments": [s.to_dict() for s in self.segments]}
        out.update(self.loads_dict())
        return out

    def loads_dict(self) -> dict[str, Any]:
        """The chain's own loads as JSON, those set only: ``payload``, ``gravity`` ``[gx, gy]``, ``joint_forces``
        ``[{"joint", "force": [fx, fy]}]``."""
        out: dict[str, Any] = {}
        if self.payload:
            out["payload"] = self.payload
        if self.gravity is not None:
            out["gravity"] = list(self.gravity)
        if self.joint_forces:
            out["joint_forces"] = [{"joint": j, "force": list(f)} for j, f in self.joint_forces]
        return out

    # ------------------------------------------------------------------ arrays
    def __len__(self) -> int:
        return len(self.segments)

    @property
    def n(self) -> int:
        """Number of segments (= joints)."""
        return len(self.segments)

    def _col(self, name: str) -> np.ndarray:
        return np.array([getattr(s, name) for s in self.segments], dtype=float)

    @cached_property
    def a(self) -> np.ndarray:
        return self._col("a")

    @cached_property
    def b(self) -> np.ndarray:
        return self._col("b")

    @cached_property
    def k1(self) -> np.ndarray:
        return self._col("k1")

    @cached_property
    def k2(self) -> np.ndarray:
        return self._col("k2")

    @cached_property
    def L1_0(self) -> np.ndarray:
        return self._col("L1_0")

    @cached_property
    def L2_0(self) -> np.ndarray:
        return self._col("L2_0")

    @cached_property
    def springs(self) -> Springs:
        """The chain's springs as arrays: their law and their state at any configuration
        (:class:`~tensegrity_opt.model.springs.Springs`)."""
        return Springs(c=np.hypot(self.a, self.b), beta=np.arctan2(self.a, self.b),
                       k=np.column_stack([self.k1, self.k2]), L0=np.column_stack([self.L1_0, self.L2_0]),
                       tension_only=np.array([s.tension_only for s in self.segments]))

    @cached_property
    def linear_springs(self) -> bool:
        """Every spring follows the linear law (the paper's model)."""
        return self.springs.linear

    @cached_property
    def params(self) -> np.ndarray:
        """Flat parameter vector ``[a, b, k1, k2, L1_0, L2_0]`` (each of length n) for the solvers.

        The solvers built on it (CasADi: Newton, IPOPT, continuation, the design NLPs) model the linear spring
        law: a chain with a tension-only segment is refused here (:func:`~.springs.linear_only`), so no analysis
        silently answers for the linear law."""
        linear_only(self, "this analysis (its solvers model the linear spring law)")
        _loads.unloaded_only(self, "this analysis (its solvers model the unloaded chain)")
        p = np.concatenate([self.a, self.b, self.k1, self.k2, self.L1_0, self.L2_0])
        p.setflags(write=False)           # shared by every solve of this chain: never modified
        return p

    @cached_property
    def link_loads(self) -> np.ndarray:
        """The dead loads per link ``G`` (n, 2): weights under ``gravity`` and ``joint_forces``, the loads'
        potential ``V = V_0 - sum_j G_j . (cos psi_j, sin psi_j)`` (:mod:`~.loads`). Read-only."""
        G = _loads.link_loads(self)
        G.setflags(write=False)
        return G

    @cached_property
    def load_offset(self) -> float:
        """``V_0``: the loads' potential no joint angle changes (:func:`~.loads.load_offset`)."""
        return _loads.load_offset(self)

    @cached_property
    def loaded(self) -> bool:
        """The chain carries dead loads: a weight under gravity (a mass or a payload) or a nonzero joint force (one
        at the fixed joint 1 too: it does no work, but its constant is part of the potential)."""
        return bool(np.any(self.link_loads != 0.0)) or self.load_offset != 0.0

    @property
    def paper_model(self) -> bool:
        """The paper's model: every spring linear, no dead load (the CasADi kernels, the homotopy and the designs
        solve it; the other chains go through the closed-range route of :mod:`~.tension_only`)."""
        return self.linear_springs and not self.loaded

    @cached_property
    def link_lengths(self) -> np.ndarray:
        """Lengths of the moving links: ``b_j + b_{j+1}`` for ``j < n``, then ``b_n``."""
        b = self.b
        return np.concatenate([b[:-1] + b[1:], b[-1:]])

    @cached_property
    def base_length(self) -> float:
        """The fixed base half-link ``b_1``: joint 1 sits at ``(b_1, 0)``."""
        return float(self.b[0])

    @cached_property
    def straight_length(self) -> float:
        """Tip abscissa of the straight chain, ``2 sum(b)``."""
        return float(2.0 * self.b.sum())

    @cached_property
    def _reach(self) -> tuple[float, float]:
        """``(inner, outer)`` distances from joint 1 between which the tip can be."""
        reach = float(self.link_lengths.sum())
        return max(0.0, 2.0 * float(self.link_lengths.max()) - reach), reach

    @cached_property
    def _limits_list(self) -> list[float]:
        return [float(v) for v in self.joint_limits]

    @cached_property
    def joint_limits(self) -> np.ndarray:
        """Physical range bounds ``pi - 2 beta_i``: a configuration has ``|q_i| <`` this."""
        return np.array([s.joint_limit for s in self.segments])

    @cached_property
    def stiffness(self) -> np.ndarray:
        """Joint stiffnesses ``K_i = E_i''(0)`` at the straight configuration."""
        return np.array([s.stiffness for s in self.segments])

    @property
    def symmetric(self) -> bool:
        """True when every segment is symmetric (straight is then an equilibrium)."""
        return all(s.symmetric for s in self.segments)

    @property
    def condition4(self) -> bool:
        """Condition (4) for every segment: all ``K_i > 0``."""
        return bool(np.all(self.stiffness > 0.0))

    @cached_property
    def monotonic(self) -> bool:
        """Every segment's torque ``M(q)`` decreases over its whole range (one equilibrium per torque).

        For a symmetric segment this is condition (4), ``K > 0`` (the paper's simplification,
        checked here on random geometries); an asymmetric one is sampled (:meth:`Segment.monotonic`).
        """
        return all(s.stiffness > 0.0 if s.symmetric else s.monotonic() for s in self.segments)

    # ------------------------------------------------------------------ kinematics
    def _q(self, q: Any, field: str = "q") -> np.ndarray:
        q = np.asarray(q, dtype=float)
        if q.shape != (self.n,):
            raise InvalidParameterError(f"{field} must have {self.n} joint angles, got shape {q.shape}", field=field)
        return q

    def in_range(self, q: Any, margin: float = 0.0) -> bool:
        """True when every ``|q_i| < (pi - 2 beta_i) - margin``."""
        q = self._q(q)
        if margin == 0.0 and q.size <= 16:     # plain floats: several times faster than numpy for a few joints
            return all(abs(v) < lim for v, lim in zip(q.tolist(), self._limits_list))
        return bool(np.all(np.abs(q) < self.joint_limits - margin))

    def tip(self, q: Any) -> np.ndarray:
        """Tip position ``(x, y)`` (eq. 5 generalised to per-segment ``b``)."""
        phi = np.cumsum(self._q(q))
        l = self.link_lengths
        return np.array([self.base_length + l @ np.cos(phi), l @ np.sin(phi)])

    def jacobian(self, q: Any) -> np.ndarray:
        """Tip Jacobian ``d(x, y)/dq``, shape ``(2, n)`` (eq. 7)."""
        phi = np.cumsum(self._q(q))
        l = self.link_lengths
        # d tip / d phi_j, then d phi_j / d q_i = 1 for j >= i: reverse cumulative sums.
        dx = -l * np.sin(phi)
        dy = l * np.cos(phi)
        return np.vstack([np.cumsum(dx[::-1])[::-1], np.cumsum(dy[::-1])[::-1]])

    def tip_kinematics(self, Q: np.ndarray) -> TipKinematics:
        """:meth:`tip` and :meth:`jacobian` of every row of ``Q`` (M, n) at once, with the links' absolute angles'
        cosines and sines (no validation: the batched searches' inner loops)."""
        phi = np.cumsum(Q, axis=1)
        c, s = np.cos(phi), np.sin(phi)
        lc, ls = self.link_lengths * c, self.link_lengths * s
        tip = np.stack([self.base_length + lc.sum(axis=1), ls.sum(axis=1)], axis=1)
        Jx = -np.cumsum(ls[:, ::-1], axis=1)[:, ::-1]
        Jy = np.cumsum(lc[:, ::-1], axis=1)[:, ::-1]
        return TipKinematics(c, s, tip, Jx, Jy)

    def target(self, dx: float, dy: float = 0.0) -> np.ndarray:
        """Tip position ``(2 sum(b) - dx, dy)`` for a deflection ``(dx, dy)``."""
        return np.array([self.straight_length - float(dx), float(dy)])

    def check_reachable(self, dx: float, dy: float = 0.0) -> np.ndarray:
        """Return the target for ``(dx, dy)`` or raise :class:`UnreachableTargetError`.

        The tip stays between ``max(0, 2 max(links) - sum(links))`` and ``sum(links)`` from joint 1
        at ``(b_1, 0)`` (a single segment: exactly on the circle of radius ``b_1``). The joint
        range restricts it further; that is found by the solvers.
        """
        for name, v in (("dx", dx), ("dy", dy)):
            if not math.isfinite(float(v)):
                raise InvalidParameterError(f"{name} must be finite, got {v!r}", field=name)
        target = self.target(dx, dy)
        inner, reach = self._reach
        dist = math.hypot(self.straight_length - float(dx) - self.base_length, float(dy))
        if self.n == 1 and abs(dist - reach) > 1e-9 * reach:
            raise UnreachableTargetError(
                f"a single segment's tip moves on a circle of radius {reach:.6g} about its joint; the target "
                f"for dx={dx:.6g}, dy={dy:.6g} is at distance {dist:.6g}", field="dx", distance=dist, reach=reach)
        if dist < inner * (1.0 - 1e-12):
            raise UnreachableTargetError(
                f"the target for dx={dx:.6g}, dy={dy:.6g} is closer to joint 1 ({dist:.6g}) than the chain can fold "
                f"({inner:.6g})", field="dx", distance=dist, reach=reach)
        if dist > reach * (1.0 + 1e-12):
            raise UnreachableTargetError(
                f"target ({target[0]:.6g}, {target[1]:.6g}) for dx={dx:.6g}, dy={dy:.6g} is beyond the "
                f"chain's reach: distance {dist:.6g} from joint 1 exceeds the total link length {reach:.6g}"
                + (" (dx < 0 stretches the chain past its straight length)" if dx < 0 else ""),
                field="dx" if dx < 0 or dy == 0 else "dy", distance=dist, reach=reach)
        return target

    # ------------------------------------------------------------------ elastostatics
    def _springs(self, q: np.ndarray):
        c = np.hypot(self.a, self.b)
        beta = np.arctan2(self.a, self.b)
        L1 = 2.0 * c * np.cos(beta + q / 2.0)
        L2 = 2.0 * c * np.cos(beta - q / 2.0)
        return c, beta, L1, L2

    def spring_lengths(self, q: Any) -> tuple[np.ndarray, np.ndarray]:
        """Per-segment spring lengths ``(L1, L2)``."""
        _, _, L1, L2 = self._springs(self._q(q))
        return L1, L2

    def spring_forces(self, q: Any) -> tuple[np.ndarray, np.ndarray]:
        """Per-segment spring tensions ``k_i (L_i - L_i0)`` (``k_i max(0, L_i - L_i0)`` under the tension-only law)."""
        if not self.linear_springs:
            f = self.springs.forces(self._q(q))
            return f[:, 0], f[:, 1]
        L1, L2 = self.spring_lengths(q)
        return self.k1 * (L1 - self.L1_0), self.k2 * (L2 - self.L2_0)

    def energy(self, q: Any) -> float:
        """Total elastic energy ``sum_i E_i(q_i)`` (under each segment's spring law)."""
        if not self.linear_springs:
            return float(self.springs.energy(self._q(q)))
        L1, L2 = self.spring_lengths(q)
        return float(0.5 * (self.k1 @ (L1 - self.L1_0) ** 2 + self.k2 @ (L2 - self.L2_0) ** 2))

    def torques(self, q: Any) -> np.ndarray:
        """Joint torques ``M_i(q_i) = -dE/dq_i`` (eq. 1, general form)."""
        q = self._q(q)
        c, beta, L1, L2 = self._springs(q)
        if self.linear_springs:
            F1, F2 = self.k1 * (L1 - self.L1_0), self.k2 * (L2 - self.L2_0)
        else:
            F1, F2 = self.spring_forces(q)
        return c * (F1 * np.sin(beta + q / 2.0) - F2 * np.sin(beta - q / 2.0))

    def gradient(self, q: Any) -> np.ndarray:
        """``dE/dq = -M(q)``."""
        return -self.torques(q)

    def potential_energy(self, q: Any) -> float:
        """The chain's potential ``E(q) + V(q)``: its springs' energy and its dead loads' potential (weights under
        ``gravity``, ``joint_forces``; :mod:`~.loads`). Equal to :meth:`energy` for a chain without loads."""
        E = self.energy(q)
        return E + _loads.load_potential(self, self._q(q)) if self.loaded else E

    def load_gradient(self, q: Any) -> np.ndarray:
        """``dV/dq`` of the dead loads' potential (zeros without loads)."""
        return _loads.load_gradient(self, self._q(q))

    def load_hessian(self, q: Any) -> np.ndarray:
        """``d^2 V / dq^2`` (n, n) of the dead loads' potential."""
        return _loads.load_hessian(self, self._q(q))

    def potential_gradient(self, q: Any) -> np.ndarray:
        """``d(E + V)/dq``: the joint torques of the springs and of the dead loads, with the sign of a gradient."""
        g = self.gradient(q)
        return g + _loads.load_gradient(self, self._q(q)) if self.loaded else g

    def force_from_torques(self, q: Any) -> np.ndarray:
        """Eq. (8): ``F = -(J^T)^+ M``, the least-squares (least-norm where ``J`` loses rank) tip force
        balancing the torques; ``-(J J^T)^-1 J M`` when ``J`` has full rank."""
        J = self.jacobian(q)
        return np.linalg.lstsq(J.T, -self.torques(q), rcond=None)[0]

    @cached_property
    def torque_scale(self) -> float:
        """``max k c^2`` over the segments: the scale of joint torques, for residual tolerances."""
        return float(np.max(np.maximum(self.k1, self.k2) * (self.a ** 2 + self.b ** 2)))

    def equilibrium_residual(self, q: Any, force: Any, target: Any | None = None) -> float:
        """Largest violation of ``grad E = J^T F`` (scaled by ``k c^2``) and of ``tip = target`` (by ``sum b``)."""
        q = self._q(q)
        r = float(np.abs(self.potential_gradient(q) - self.jacobian(q).T @ np.asarray(force, float)).max()) \
            / self.torque_scale
        if target is not None:
            r = max(r, float(np.abs(self.tip(q) - np.asarray(target, float)).max()) / float(self.b.sum()))
        return r

    def equilibrium_residuals(self, Q: Any, F: Any, target: Any) -> np.ndarray:
        """:meth:`equilibrium_residual` of every row of ``Q`` (k, n) with the forces ``F`` (k, 2) and the tip at
        ``target``, at once (numpy over the rows: the thousands of solves of a global search). NaN rows give NaN."""
        Q = np.asarray(Q, dtype=float).reshape(-1, self.n)
        F = np.asarray(F, dtype=float).reshape(-1, 2)
        c, beta = np.hypot(self.a, self.b), np.arctan2(self.a, self.b)
        L1, L2 = 2.0 * c * np.cos(beta + Q / 2.0), 2.0 * c * np.cos(beta - Q / 2.0)
        if self.linear_springs:
            F1, F2 = self.k1 * (L1 - self.L1_0), self.k2 * (L2 - self.L2_0)
        else:
            f = self.springs.forces(Q)
            F1, F2 = f[..., 0], f[..., 1]
        torques = c * (F1 * np.sin(beta + Q / 2.0) - F2 * np.sin(beta - Q / 2.0))
        phi = np.cumsum(Q, axis=1)
        l = self.link_lengths
        # (J^T F)_i = sum over the links j >= i of d tip_j / d phi_j . F
        work = -l * np.sin(phi) * F[:, :1] + l * np.cos(phi) * F[:, 1:]
        jtf = np.cumsum(work[:, ::-1], axis=1)[:, ::-1]
        grad = -torques + _loads.load_gradient(self, Q) if self.loaded else -torques
        r = np.abs(grad - jtf).max(axis=1) / self.torque_scale
        tip = np.stack([self.base_length + np.cos(phi) @ l, np.sin(phi) @ l], axis=1)
        return np.maximum(r, np.abs(tip - np.asarray(target, float)).max(axis=1) / float(self.b.sum()))

    def mirrored(self) -> "Manipulator":
        """The mirror image (springs 1 and 2 swapped, the loads reflected in the x axis): ``q`` solves it iff ``-q``
        solves this one (with the tip target and force reflected too)."""
        gravity = None if self.gravity is None else (self.gravity[0], -self.gravity[1])
        return Manipulator((s.replace(k=(s.k2, s.k1), L0=(s.L2_0, s.L1_0)) for s in self.segments), self.payload,
                           gravity, tuple((j, (f[0], -f[1])) for j, f in self.joint_forces))

    def with_segments(self, segments: Iterable[Segment]) -> "Manipulator":
        """The same chain's loads (``payload``, ``gravity``, ``joint_forces``) on new ``segments``: what a design or a
        preload change returns."""
        return Manipulator(segments, self.payload, self.gravity, self.joint_forces)

    def with_spring(self, spring: str) -> "Manipulator":
        """The same chain with every segment's spring law set to ``spring``."""
        return self.with_segments(s.replace(spring=spring) for s in self.segments)
