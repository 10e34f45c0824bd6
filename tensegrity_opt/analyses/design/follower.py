"""The preload follower: commanded rest lengths in, the equilibrium the arm settles into out.

The forward problem of control in actuation space (:mod:`.preload_control` is the inverse one): the springs' rest
lengths ``(L1_0, L2_0)`` are commanded step by step, with a dead tip load, and the arm answers each command with
the equilibrium it reaches quasi-statically from where it was: a local minimiser of ``E - F . tip`` for the new
rest lengths, found from the previous configuration
(:func:`~tensegrity_opt.analyses.equilibria.equilibrium.solve_equilibrium_under_force` with ``q0`` the last
state). Where the well the arm sat in has vanished the minimiser lands in another one: the arm **snaps**. A step is
reported as a snap (:class:`Snap`) when its configuration moves by more than ``snap_distance`` (rad, the largest
joint) from the last one, or when the equilibrium reached is not stable.

:class:`PreloadFollower` keeps the state between commands; each :meth:`PreloadFollower.step` returns a
:class:`FollowerStep`. This is the ``preloads`` mode of the control stream (``docs/stream.md``).

Example (a bistable segment in front of a straight one: tilting its double well ends the well it sits in, and it
snaps into the other one)::

    >>> import tensegrity_opt as to
    >>> m = to.Manipulator([to.Segment(0.5, 1.0, 1.0, 1.0), to.Segment(1.0, 1.0, 1.0, 1.0)])
    >>> f = to.PreloadFollower(m)
    >>> steps = [f.step([[1 + d, 1 - d], [1.0, 1.0]]) for d in (0.1, 0.2, 0.3, 0.4)]
    >>> [s.snap is not None for s in steps], steps[-1].snap.cause, steps[-1].status
    ([False, False, False, True], 'distance', 'converged')
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from ...errors import InvalidParameterError
from ...model.manipulator import Manipulator
from ...outcome import Outcome, freeze
from ...serialize import number, numbers
from ..equilibria.equilibrium import Equilibrium, solve_equilibrium_under_force
from ..paths.control import checked_vector

__all__ = ["PreloadFollower", "FollowerStep", "Snap", "SNAP_DISTANCE", "loaded_rest"]

#: Default largest joint motion (rad) of a step that is not reported as a snap.
SNAP_DISTANCE = 0.2


@dataclass(frozen=True)
class Snap:
    """The arm jumped during a step (:meth:`PreloadFollower.step`).

    Attributes
    ----------
    cause : str
        ``"unstable"`` (the equilibrium reached is not stable) or ``"distance"`` (the configuration moved by more
        than ``snap_distance``).
    distance : float
        The largest joint motion of the step (rad).
    q_before : ndarray (n,)
        The configuration before the step.
    """

    cause: str
    distance: float
    q_before: np.ndarray

    def __post_init__(self) -> None:
        freeze(self)

    def to_dict(self) -> dict[str, Any]:
        """JSON form, an event of the control stream: ``kind`` (``"snap"``), ``cause``, ``distance``,
        ``q_before``."""
        return {"kind": "snap", "cause": self.cause, "distance": number(self.distance),
                "q_before": numbers(self.q_before)}


@dataclass(frozen=True)
class FollowerStep(Outcome):
    """One command of :class:`PreloadFollower`: the equilibrium reached, what was commanded, and the snap.

    Its outcome is the equilibrium's (:attr:`STATUSES` are :attr:`Equilibrium.STATUSES`): a command the arm finds
    no equilibrium for raises instead (the follower then stays where it was).

    Attributes
    ----------
    equilibrium : Equilibrium
        The equilibrium under ``load`` with ``rest_lengths``, reached from the previous configuration (tip free,
        ``control == "force"``).
    rest_lengths : ndarray (n, 2)
        The commanded ``(L1_0, L2_0)`` per segment.
    load : ndarray (2,)
        The dead tip load of the step.
    snap : Snap or None
        The snap of the step, None when the arm moved continuously and stayed stable.
    status, message : str
        The equilibrium's.
    """

    STATUSES: ClassVar[dict[str, str]] = Equilibrium.STATUSES
    SUCCESS: ClassVar[frozenset[str]] = Equilibrium.SUCCESS

    equilibrium: Equilibrium
    rest_lengths: np.ndarray
    load: np.ndarray
    snap: Snap | None = field(default=None)

    def __post_init__(self) -> None:
        freeze(self)

    @property
    def status(self) -> str:
        return self.equilibrium.status

    @property
    def message(self) -> str:
        return self.equilibrium.message

    @property
    def q(self) -> np.ndarray:
        """The configuration reached (``equilibrium.q``)."""
        return self.equilibrium.q

    def to_dict(self) -> dict[str, Any]:
        """JSON form (a ``result`` of the stream's ``preloads`` mode): the equilibrium's
        (:meth:`Equilibrium.to_dict`), then ``rest_lengths``, ``load`` and ``events`` (the snap's
        :meth:`Snap.to_dict`, or none)."""
        return {**self.outcome(), **self.equilibrium.to_dict(), "rest_lengths": [numbers(p) for p in self.rest_lengths],
                "load": numbers(self.load), "events": [] if self.snap is None else [self.snap.to_dict()]}


def loaded_rest(m: Manipulator, load) -> Equilibrium:
    """The default start of the control modes: the least-energy rest configuration of ``m``, and under a
    non-zero dead tip ``load`` the equilibrium reached from it (which may be unstable; the caller decides)."""
    from ..equilibria.rest import rest_configuration

    rest = rest_configuration(m)
    if not np.any(load):
        return rest
    return solve_equilibrium_under_force(m, *load, q0=rest.q)


class PreloadFollower:
    """The arm under commanded rest lengths, step by step (module docstring).

    Parameters
    ----------
    m : Manipulator
        Geometry and stiffness (kept; each command replaces the rest lengths).
    start : Equilibrium or array_like (n,), optional
        The configuration the first command starts from; default the equilibrium under ``load`` reached from
        the least-energy rest configuration of ``m`` (:func:`loaded_rest`).
    load : (fx, fy)
        The dead tip load (a command may give its own).
    snap_distance : float
        A step whose joint angles move by more than this (rad, the largest joint) is a snap (``SNAP_DISTANCE``).

    Attributes
    ----------
    q : ndarray (n,)
        The current configuration (moves with every step).
    load : ndarray (2,)
        The default load.
    """

    def __init__(self, m: Manipulator, start=None, *, load=(0.0, 0.0), snap_distance: float = SNAP_DISTANCE) -> None:
        if not isinstance(m, Manipulator):
            raise InvalidParameterError("m must be a Manipulator", field="m")
        self.m = m
        self.load = checked_vector(load, 2, "load")
        if not snap_distance > 0:
            raise InvalidParameterError(f"snap_distance must be > 0, got {snap_distance!r}", field="snap_distance")
        self.snap_distance = float(snap_distance)
        if isinstance(start, Equilibrium):
            start = start.q
        if start is None:
            self.q = loaded_rest(m, self.load).q.copy()
        else:
            if len(start) != m.n:
                raise InvalidParameterError(f"start must be {m.n} joint angles, got {len(start)}", field="start")
            self.q = np.asarray(start, dtype=float)

    def manipulator(self, rest_lengths) -> Manipulator:
        """The chain with the commanded rest lengths (``[L1_0, L2_0]`` per segment, ``field="rest_lengths"``)."""
        n = self.m.n
        if len(rest_lengths) != n:
            raise InvalidParameterError(f"rest_lengths must be {n} pairs [L1_0, L2_0], got {len(rest_lengths)}",
                                        field="rest_lengths")
        segments = []
        for i, (seg, (l1, l2)) in enumerate(zip(self.m.segments, rest_lengths)):
            try:
                segments.append(seg.replace(L0=(float(l1), float(l2))))
            except InvalidParameterError as exc:
                raise InvalidParameterError(exc.message, field=f"rest_lengths[{i}]") from None
        return Manipulator(segments)

    def step(self, rest_lengths, load=None) -> FollowerStep:
        """The equilibrium the arm reaches from the current configuration under the commanded ``rest_lengths``
        (``n`` pairs ``[L1_0, L2_0]``) and ``load`` (default the follower's); the state moves there.

        Raises
        ------
        InvalidParameterError
            Bad rest lengths (``field="rest_lengths"`` or ``"rest_lengths[i]"``) or load.
        NoEquilibriumError, SolverError
            No equilibrium reached inside the physical range; the state stays where it was.
        """
        m = self.manipulator(rest_lengths)
        F = self.load if load is None else checked_vector(load, 2, "load")
        eq = solve_equilibrium_under_force(m, float(F[0]), float(F[1]), q0=self.q)
        distance = float(np.max(np.abs(eq.q - self.q)))
        snap = None
        if distance > self.snap_distance or not eq.stable:
            snap = Snap(cause="unstable" if not eq.stable else "distance", distance=distance, q_before=self.q)
        self.q = eq.q.copy()
        return FollowerStep(equilibrium=eq, rest_lengths=np.array([[float(a), float(b)] for a, b in rest_lengths]),
                            load=np.array(F, dtype=float), snap=snap)
