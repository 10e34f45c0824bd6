"""The preload follower: commanded rest lengths in, the equilibrium the arm settles into out.

The forward problem of control in actuation space (:mod:`.preload_control` is the inverse one): the springs' rest
lengths ``(L1_0, L2_0)`` are commanded step by step, with a dead tip load, and the arm answers each command the way
a plan's step is verified: its **transition** (:mod:`tensegrity_opt.analyses.paths.transition`), the previous
command and load moving linearly to the new ones while the arm follows its equilibrium branch by continuation.
Where that branch loses stability on the way (a fold, a branch point: the well the arm sat in has vanished) the arm
**snaps**: it lands, by descent, in another well, and the move goes on from there; each snap is an event
(:class:`~tensegrity_opt.analyses.paths.transition.SimulationEvent`: where in the move, from which configuration,
to which, the energy released). A large but continuous motion on one branch is not a snap.

:class:`PreloadFollower` keeps the state between commands; each :meth:`PreloadFollower.step` returns a
:class:`FollowerStep`. This is the ``preloads`` mode of the control stream (``docs/stream.md``).

Example (a bistable segment in front of a straight one: tilting its double well ends the well it sits in, and it
snaps into the other one)::

    >>> import tensegrity_opt as to
    >>> m = to.Manipulator([to.Segment(0.5, 1.0, 1.0, 1.0), to.Segment(1.0, 1.0, 1.0, 1.0)])
    >>> f = to.PreloadFollower(m)
    >>> steps = [f.step([[1 + d, 1 - d], [1.0, 1.0]]) for d in (0.1, 0.2, 0.3, 0.4)]
    >>> [s.snap is not None for s in steps], steps[-1].snap.kind, steps[-1].status
    ([False, False, False, True], 'snap', 'converged')
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from ...errors import InvalidParameterError, NoEquilibriumError, SolverError
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...numerics import chain_solver
from ...outcome import Outcome, freeze
from ...serialize import numbers
from ..equilibria.equilibrium import Equilibrium, is_equilibrium, make_equilibrium, solve_equilibrium_under_force
from ..paths.control import checked_vector
from ..paths.descent import ArmState
from ..paths.transition import follow, start_state

__all__ = ["PreloadFollower", "FollowerStep", "loaded_rest"]


@dataclass(frozen=True)
class FollowerStep(Outcome):
    """One command of :class:`PreloadFollower`: the equilibrium reached, what was commanded, and the snaps.

    Its outcome is the equilibrium's (:attr:`STATUSES` are :attr:`Equilibrium.STATUSES`): a command the arm finds
    no equilibrium for (a joint reaches its stop on the way) raises instead (the follower then stays where it was).

    Attributes
    ----------
    equilibrium : Equilibrium
        The equilibrium under ``load`` with ``rest_lengths`` at the end of the command's transition (tip free,
        ``control == "force"``).
    rest_lengths : ndarray (n, 2)
        The commanded ``(L1_0, L2_0)`` per segment.
    load : ndarray (2,)
        The dead tip load of the step.
    events : tuple of SimulationEvent
        The snaps of the transition (``kind`` ``"snap"`` or ``"bifurcation"``; ``step`` the command's index since
        the follower's start, ``fraction`` where in the move), none when the arm followed its branch.
    status, message : str
        The equilibrium's.
    """

    STATUSES: ClassVar[dict[str, str]] = Equilibrium.STATUSES
    SUCCESS: ClassVar[frozenset[str]] = Equilibrium.SUCCESS

    equilibrium: Equilibrium
    rest_lengths: np.ndarray
    load: np.ndarray
    events: tuple = ()

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

    @property
    def snap(self):
        """The first snap of the step (a :class:`~tensegrity_opt.analyses.paths.transition.SimulationEvent`), or
        None when the arm followed its branch."""
        return next((e for e in self.events if e.kind in ("snap", "bifurcation")), None)

    def to_dict(self) -> dict[str, Any]:
        """JSON form (a ``result`` of the stream's ``preloads`` mode): the equilibrium's
        (:meth:`Equilibrium.to_dict`), then ``rest_lengths``, ``load`` and ``events`` (each
        :meth:`~tensegrity_opt.analyses.paths.transition.SimulationEvent.to_dict`)."""
        return {**self.outcome(), **self.equilibrium.to_dict(), "rest_lengths": [numbers(p) for p in self.rest_lengths],
                "load": numbers(self.load), "events": [e.to_dict() for e in self.events]}


def _settled(m: Manipulator, F: np.ndarray, q: np.ndarray) -> Equilibrium:
    """The end of a move, ``q``, polished into an :class:`Equilibrium` under the dead load ``F``: Newton (the linear
    law) or the local minimiser under each spring's law (a chain with tension-only springs), which must stay there."""
    if m.linear_springs:
        res = chain_solver(m).newton_force(F, q)
        if not is_equilibrium(m, res):
            raise SolverError("the end of the move is not a converged equilibrium", status="not_converged")
        return make_equilibrium(m, res, constrained=False)
    eq = solve_equilibrium_under_force(m, float(F[0]), float(F[1]), q0=q)
    if float(np.abs(eq.q - q).max()) > 1e-6:
        raise SolverError("the end of the move is not a converged equilibrium", status="not_converged")
    return eq


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
        Geometry and stiffness (kept); its rest lengths are the ones before the first command.
    start : Equilibrium or array_like (n,), optional
        The configuration the first command starts from: a stable equilibrium with ``m``'s rest lengths under
        ``load`` (Newton polishes it); default the equilibrium under ``load`` reached from the least-energy rest
        configuration of ``m`` (:func:`loaded_rest`).
    load : (fx, fy)
        The dead tip load (a command may give its own).

    Attributes
    ----------
    q : ndarray (n,)
        The current configuration (moves with every step).
    load : ndarray (2,)
        The default load.
    """

    def __init__(self, m: Manipulator, start=None, *, load=(0.0, 0.0)) -> None:
        unloaded_only(m, "PreloadFollower")
        if not isinstance(m, Manipulator):
            raise InvalidParameterError("m must be a Manipulator", field="m")
        self.m = m
        self.load = checked_vector(load, 2, "load")
        if isinstance(start, Equilibrium):
            start = start.q
        if start is None:
            q0 = loaded_rest(m, self.load).q.copy()
        else:
            if len(start) != m.n:
                raise InvalidParameterError(f"start must be {m.n} joint angles, got {len(start)}", field="start")
            q0 = checked_vector(start, m.n, "start")
        self._state = start_state(m, q0, self.load)
        self.q = self._state.q.copy()
        self.rest = np.column_stack([m.L1_0, m.L2_0])       # the command the state is an equilibrium with
        self.index = 0

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
        return self.m.with_segments(segments)

    def step(self, rest_lengths, load=None) -> FollowerStep:
        """The equilibrium the arm reaches along the transition from the current state to the commanded
        ``rest_lengths`` (``n`` pairs ``[L1_0, L2_0]``) and ``load`` (default the follower's); the state moves there.

        Raises
        ------
        InvalidParameterError
            Bad rest lengths (``field="rest_lengths"`` or ``"rest_lengths[i]"``) or load.
        NoEquilibriumError
            A joint reaches its stop during the transition: no equilibrium inside the physical range
            (``field="rest_lengths"``); the state stays where it was.
        SolverError
            The transition could not be followed; the state stays where it was.
        """
        m1 = self.manipulator(rest_lengths)
        F = self.load if load is None else checked_vector(load, 2, "load")
        P1 = np.column_stack([m1.L1_0, m1.L2_0])
        tr = follow(self.m, self._state, self.rest, P1, self._state.force, F, step=self.index)
        if tr.status == "joint_limit":
            raise NoEquilibriumError(f"a joint reaches its stop at {tr.fraction:.4g} of the move to this command: no "
                                     "equilibrium inside the physical range (the state stays where it was)",
                                     field="rest_lengths", status="joint_limit")
        if tr.status not in ("followed", "snapped"):
            raise SolverError(f"the move to this command could not be followed: {tr.message}", status=tr.status)
        eq = _settled(m1, np.asarray(F, float), tr.q)
        self._state = ArmState(eq.q.copy(), np.array(F, dtype=float), eq.tip.copy(), float(eq.energy), 0, True)
        self.q, self.rest = eq.q.copy(), P1
        self.index += 1
        return FollowerStep(equilibrium=eq, rest_lengths=P1.copy(), load=np.array(F, dtype=float), events=tr.events)
