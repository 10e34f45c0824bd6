"""Forward quasi-static simulation: the chain driven by sampled inputs, snapping where its branch ends.

:func:`simulate` takes time series of the inputs over steps ``k = 0 .. K-1`` -- the rest lengths
``(L1_0, L2_0)`` of every segment (the preloads, the control inputs of the paper), and either a dead tip
load (tip ``"free"``) or a tip deflection (tip ``"held"``) -- and answers what the arm does, in the
quasi-static limit (inputs slow against the dynamics, the dynamics overdamped):

* between two samples the inputs move linearly; the configuration follows the equilibrium branch it is
  on, continuously, by pseudo-arclength continuation in the fraction of the step
  (:func:`~tensegrity_opt.analyses.paths.branches.trace_branch` with a
  :meth:`~tensegrity_opt.analyses.paths.branches.Control.move`: preloads and load, or preloads and tip, in one
  parameter);
* where that branch loses stability -- a fold (located by the Moore-Spence system: the step fraction
  and the configuration at the fold to about ``1e-12``) or, for symmetric chains, a branch point -- the
  arm **snaps**: the new state is the equilibrium reached by *descent* from there, the gradient flow
  ``dq/dtau = -grad V(q)`` of the potential ``V = E - F . tip`` (free tip; the load held at its value at
  the fold) or of ``E`` on the tip constraint ``tip(q) = target`` (held tip; the projected flow), with
  the inputs frozen at the fold. The flow starts at the fold configuration moved by ``perturbation``
  (rad, largest joint) along the fold's null vector, on the side the branch continues to (the unstable
  side, where ``V`` decreases); it is integrated by scipy's BDF (tolerances ``1e-8`` relative, ``1e-10``
  absolute) until the point is a strict minimum's neighbour (the Hessian of ``V``, reduced to the
  constraint when held, positive definite there and Newton converging close by), then polished by
  Newton. This is the minimum whose basin the fold point drains into -- the state an overdamped arm
  with equal joint dampers reaches -- not the least-energy one. A branch point that loses stability is
  left the same way at ``BRANCH_POINT_OFFSET`` past it (at the branch point itself the flow leaves
  only algebraically slowly), on the side of the null vector where ``V`` is lower (``+`` on a tie:
  the mirror image is not chosen by the model);
* the simulation goes on from the landing state for the rest of the step; each snap is a
  :class:`SimulationEvent` (step, fraction, the fold and the landing configurations, the energy
  released, the inputs there).

It stops, keeping the steps done, where a joint reaches its range bound (on the followed branch or
during a snap: the model has no equilibrium beyond), where the held tip reaches the edge of its
workspace, or when the time limit runs out (:attr:`Simulation.status`). Every reported state is a
converged equilibrium inside the physical range, classified by its Morse index.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from ...errors import (
    InvalidParameterError,
    NoEquilibriumError,
    TensegrityError,
    TimeLimitError,
    UnreachableTargetError,
)
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...model.springs import SpringFields, Springs
from ...numerics import DENSE_MAX
from ...outcome import Outcome, freeze
from ...serialize import number, numbers
from ...timelimit import expired, time_limit
from ..equilibria.equilibrium import Equilibrium, check_q0
from .descent import ArmState
from .transition import (
    BRANCH_POINT_OFFSET,
    EVENT_KINDS,
    PERTURBATION,
    Move,
    SimulationEvent,
    chain_with,
    start_state,
)

__all__ = ["simulate", "Simulation", "SimulationEvent", "EVENT_KINDS", "PERTURBATION", "BRANCH_POINT_OFFSET"]


@dataclass(frozen=True)
class Simulation(Outcome, SpringFields):
    """The result of :func:`simulate`: the state at each step done, and the events.

    The arrays hold the ``k <= K`` steps done (``k = K`` when ``status == "complete"``); each row is a
    converged equilibrium inside the physical range at that step's inputs.

    Attributes
    ----------
    mode : str
        ``"free"`` (dead tip load) or ``"held"`` (tip deflection prescribed).
    preloads : ndarray (K, n, 2)
        The rest lengths at every sample (the input).
    loads : ndarray (K, 2) or None
        The dead tip loads (free).
    targets : ndarray (K, 2) or None
        The tip deflections ``(dx, dy)`` (held).
    q : ndarray (k, n)
    force : ndarray (k, 2)
        The load (free) or the holding force (held), ``grad E = J^T F``.
    tip : ndarray (k, 2)
    energy : ndarray (k,)
        Elastic energy.
    potential : ndarray (k,)
        ``E - F . tip`` (free) or ``E`` (held).
    stable : ndarray (k,) of bool
    morse_index : ndarray (k,) of int
    events : tuple of SimulationEvent
    status : str
        How it ended (:attr:`STATUSES`); only ``"complete"`` is a success (the steps done are kept).
    message : str
        The same in a sentence.
    straight_length : float
    spring_lengths, spring_stretches, spring_forces, spring_states : ndarray (k, n, 2)
        The springs at each step done, under its rest lengths (:class:`~tensegrity_opt.model.springs.SpringFields`).
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "complete": "every sample simulated",
        "joint_limit": "a joint reached its range bound (on the followed branch or during a snap): no equilibrium "
                       "beyond inside the physical range",
        "workspace_boundary": "the held tip reached the edge of its workspace",
        "force_bound": "the tip force grew beyond the continuation's bound",
        "time_limit": "the time limit ran out",
        "failed": "the followed branch or a snap could not be computed (message says where)",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"complete"})

    mode: str
    preloads: np.ndarray
    loads: np.ndarray | None
    targets: np.ndarray | None
    q: np.ndarray
    force: np.ndarray
    tip: np.ndarray
    energy: np.ndarray
    potential: np.ndarray
    stable: np.ndarray
    morse_index: np.ndarray
    events: list
    status: str
    message: str
    straight_length: float
    springs: Springs | None = field(default=None, repr=False, compare=False)

    def _spring_rest_lengths(self) -> np.ndarray:
        return self.preloads[:len(self)]

    def __post_init__(self) -> None:
        freeze(self)

    @property
    def steps(self) -> int:
        """The number of samples ``K`` asked for."""
        return int(self.preloads.shape[0])

    @property
    def snaps(self) -> list:
        """The snap and bifurcation events, in time order."""
        return [e for e in self.events if e.kind in ("snap", "bifurcation")]

    @property
    def deflection(self) -> np.ndarray:
        """``(dx, dy) = (2 sum b - x, y)`` of the tip at each step done."""
        return np.column_stack([self.straight_length - self.tip[:, 0], self.tip[:, 1]])

    def __len__(self) -> int:
        return int(self.q.shape[0])

    def to_dict(self) -> dict[str, Any]:
        """JSON form: ``mode, status, success, message, steps, done``; per step done ``q, force``
        ``{fx, fy}``, ``tip, deflection, energy, potential, stable, morse_index``; ``events``; the inputs
        ``preloads`` and ``loads`` or ``targets``; the spring state per step done (``spring_lengths``,
        ``spring_stretches``, ``spring_forces``, ``spring_states``: (k, n, 2))."""
        d = {**self.outcome(), **self.spring_dict(), "mode": self.mode, "steps": self.steps, "done": len(self),
             "q": [numbers(r) for r in self.q],
             "force": [{"fx": number(f[0]), "fy": number(f[1])} for f in self.force],
             "tip": [numbers(r) for r in self.tip], "deflection": [numbers(r) for r in self.deflection],
             "energy": numbers(self.energy), "potential": numbers(self.potential),
             "stable": [bool(v) for v in self.stable], "morse_index": [int(v) for v in self.morse_index],
             "events": [e.to_dict() for e in self.events],
             "preloads": [[numbers(r) for r in p] for p in self.preloads]}
        if self.loads is not None:
            d["loads"] = [numbers(r) for r in self.loads]
        if self.targets is not None:
            d["targets"] = [numbers(r) for r in self.targets]
        return d


# ---------------------------------------------------------------------------- inputs
def _series(v, name: str, shape_tail: tuple[int, ...]) -> np.ndarray:
    try:
        arr = np.asarray(v, dtype=float)
    except (TypeError, ValueError):
        raise InvalidParameterError(f"{name} must be an array of numbers", field=name) from None
    if arr.ndim != 1 + len(shape_tail) or arr.shape[1:] != shape_tail or arr.shape[0] < 1:
        want = "(K, " + ", ".join(str(s) for s in shape_tail) + ")"
        raise InvalidParameterError(f"{name} must have shape {want} with K >= 1, got {arr.shape}", field=name)
    if not np.all(np.isfinite(arr)):
        raise InvalidParameterError(f"{name} must be finite", field=name)
    return arr


def _inputs(m: Manipulator, preloads, loads, tip, targets):
    if tip not in ("free", "held"):
        raise InvalidParameterError(f"tip must be 'free' or 'held', got {tip!r}", field="tip")
    if m.n > DENSE_MAX:
        raise InvalidParameterError(f"the simulation handles chains of up to {DENSE_MAX} segments, got n = {m.n}",
                                    field="n")
    P = None if preloads is None else _series(preloads, "preloads", (m.n, 2))
    if P is not None and not np.all(P > 0.0):
        raise InvalidParameterError("preloads (rest lengths) must be > 0", field="preloads")
    if tip == "free":
        if targets is not None:
            raise InvalidParameterError("targets are for a held tip (tip='held'); a free tip takes loads",
                                        field="targets")
        L = None if loads is None else _series(loads, "loads", (2,))
        T = None
        if P is None and L is None:
            raise InvalidParameterError("give loads or preloads (a time series of K samples)", field="loads")
    else:
        if loads is not None:
            raise InvalidParameterError("loads are for a free tip (tip='free'); a held tip takes targets",
                                        field="loads")
        if targets is None:
            raise InvalidParameterError("a held tip needs targets (K, 2): the tip deflections (dx, dy)",
                                        field="targets")
        if m.n < 2:
            raise InvalidParameterError("a held tip needs n >= 2 segments (one segment's tip fixes its angle)",
                                        field="tip")
        T = _series(targets, "targets", (2,))
        L = None
        for i, (dx, dy) in enumerate(T):
            try:
                m.check_reachable(dx, dy)
            except UnreachableTargetError as exc:
                raise UnreachableTargetError(f"targets[{i}]: {exc.message}", field="targets") from None
    K = [a.shape[0] for a in (P, L, T) if a is not None]
    if len(set(K)) > 1:
        other = "targets" if T is not None else "loads"
        raise InvalidParameterError(f"preloads and {other} must have the same number of samples K, got "
                                    f"{P.shape[0]} and {K[-1]}", field=other)
    K = K[0]
    if P is None:
        P = np.repeat(np.column_stack([m.L1_0, m.L2_0])[None, :, :], K, axis=0)
    if tip == "free" and L is None:
        L = np.zeros((K, 2))
    return P, L, T


# ---------------------------------------------------------------------------- the start
def _start_state(m0: Manipulator, held: bool, F0, T0, start) -> ArmState:
    if start is None:
        if held:
            eq = _least_energy_held(m0, T0)
        elif not np.any(F0 != 0.0):
            from ..equilibria.rest import rest_configuration

            eq = rest_configuration(m0)
        elif not m0.linear_springs:
            # the tension-only law: the local minimum of E - F . tip that IPOPT reaches from the rest configuration
            # (the set of every equilibrium under a load is not available under this law)
            from ..equilibria.equilibrium import solve_equilibrium_under_force
            from ..equilibria.rest import rest_configuration

            eq = solve_equilibrium_under_force(m0, float(F0[0]), float(F0[1]), q0=rest_configuration(m0).q)
            if not eq.stable:
                raise NoEquilibriumError("no stable equilibrium under the first load near the rest configuration",
                                         status="no_start")
        else:
            from ..equilibria.rest import find_equilibria_under_force

            eqs = [e for e in find_equilibria_under_force(m0, float(F0[0]), float(F0[1]), stable_only=True)]
            if not eqs:
                raise NoEquilibriumError("no stable equilibrium under the first load", status="no_start")
            eq = min(eqs, key=lambda e: e.energy - float(F0 @ e.tip))
        q0 = eq.q
    else:
        q0 = start.q if isinstance(start, Equilibrium) else _start_q(m0, start)
        if q0.shape != (m0.n,):
            raise InvalidParameterError(f"start must hold {m0.n} joint angles", field="start")
    if held:
        F = start.force if isinstance(start, Equilibrium) and start.control == "displacement" else None
        return start_state(m0, q0, target=m0.target(*T0), force=F, moved=start is not None)
    return start_state(m0, q0, F0, moved=start is not None)


def _start_q(m: Manipulator, start) -> np.ndarray:
    try:
        q = check_q0(m, start, closed=not m.linear_springs)
    except InvalidParameterError as exc:
        raise InvalidParameterError(exc.message.replace("q0", "start"), field="start") from None
    if q is None:
        raise InvalidParameterError("start must be an Equilibrium or n joint angles", field="start")
    return q


def _least_energy_held(m0: Manipulator, T0) -> Equilibrium:
    from ..equilibria.least_energy import solve_equilibrium

    return solve_equilibrium(m0, float(T0[0]), float(T0[1]), stops=False)


# ---------------------------------------------------------------------------- the function
def simulate(m: Manipulator, preloads=None, loads=None, *, tip: str = "free", targets=None, start=None,
             perturbation: float = PERTURBATION, timeout: float | None = None,
             progress: Callable[[int, int], Any] | None = None) -> Simulation:
    """Quasi-static forward simulation of the chain under sampled inputs, with snap-through (module docstring).

    Parameters
    ----------
    m : Manipulator
        The chain (up to ``numerics.DENSE_MAX`` segments); its rest lengths are the default preloads.
    preloads : array_like (K, n, 2), optional
        The rest lengths ``(L1_0, L2_0)`` of every segment at each sample (> 0). Default: the chain's own,
        constant.
    loads : array_like (K, 2), optional
        The dead tip load ``(Fx, Fy)`` at each sample (tip ``"free"``; default zero). ``Fx < 0`` compresses.
    tip : {"free", "held"}
        ``"free"``: the tip is loaded by ``loads``. ``"held"``: the tip is held at ``targets``.
    targets : array_like (K, 2)
        The tip deflection ``(dx, dy)`` at each sample (tip ``"held"``; the tip at ``(2 sum b - dx, dy)``).
    start : Equilibrium or array_like (n,), optional
        The state at sample 0 (Newton puts it on the first inputs' equilibrium; it must be stable).
        Default: free, the least-energy rest configuration under the first preloads
        (:func:`~tensegrity_opt.analyses.equilibria.rest.rest_configuration`; under a non-zero first load the
        least-potential stable equilibrium); held, the least-energy stable equilibrium at the first target
        (:func:`~tensegrity_opt.analyses.equilibria.least_energy.solve_equilibrium`).
    perturbation : float
        The distance (rad, the largest joint) from the fold along its null vector where a snap's descent
        starts.
    timeout : float, optional
        Seconds; on expiry the steps done are kept, ``status="time_limit"``.
    progress : callable(done, total), optional
        Called with the samples done and their number ``K``, after the start and after each step.

    Returns
    -------
    Simulation
        The state at each sample done and the events (snaps, the joint-limit end). ``status`` is
        ``"complete"`` when every sample was reached.

    Raises
    ------
    InvalidParameterError
        (``ValueError``) naming the field: an array of the wrong shape or not finite, rest lengths not
        positive, ``tip`` not ``"free"``/``"held"``, loads with a held tip or targets with a free one,
        sample counts that differ, a start that is not a stable equilibrium under the first inputs,
        ``n > DENSE_MAX``.
    UnreachableTargetError
        (``ValueError``, ``field="targets"``) for a target beyond the chain's reach.
    NoEquilibriumError
        (``RuntimeError``) when the default start finds no stable equilibrium.

    Examples
    --------
    A load cycle along ``y`` on three bistable segments: two snaps at different loads (hysteresis).

    >>> import numpy as np, tensegrity_opt as to
    >>> m = to.Manipulator.uniform(3, a=0.5, b=1.0, k=1.0, L0=1.0)
    >>> up = np.linspace(0, 0.3, 31)
    >>> fy = np.concatenate([up, np.linspace(0.3, -0.3, 61)[1:], np.linspace(-0.3, 0, 31)[1:]])
    >>> sim = to.simulate(m, loads=np.column_stack([0 * fy, fy]))
    >>> sim.status, [(e.kind, e.step, round(float(e.load[1]), 6)) for e in sim.snaps]
    ('complete', [('snap', 15, 0.153111), ('snap', 69, -0.097754)])
    """
    unloaded_only(m, "simulate")
    held = tip == "held"
    P, L, T = _inputs(m, preloads, loads, tip, targets)
    if not (isinstance(perturbation, (int, float)) and math.isfinite(perturbation) and 0 < perturbation < 0.1):
        raise InvalidParameterError(f"perturbation must be in (0, 0.1) rad, got {perturbation!r}",
                                    field="perturbation")
    with time_limit(timeout):
        return _simulate(m, P, L, T, held, start, float(perturbation), progress)


def _simulate(m, P, L, T, held, start, eps, progress=None) -> Simulation:
    K, n = P.shape[0], m.n
    A = T if held else L
    events: list[SimulationEvent] = []
    rows: list[ArmState] = []
    status, message = "complete", ""
    tell = progress or (lambda done, total: None)
    try:
        state = _start_state(chain_with(m, P[0]), held, None if held else L[0], T[0] if held else None, start)
    except TimeLimitError:
        state, status, message = None, "time_limit", "the time limit ran out before the start was found"
    if state is not None:
        rows.append(state)
        tell(1, K)
        for k in range(K - 1):
            if expired():
                status, message = "time_limit", f"the time limit ran out after {len(rows)} of {K} samples"
                break
            move = Move(m, P[k], P[k + 1], A[k], A[k + 1], held, step=k, perturbation=eps)
            try:
                new, st, msg = move.run(state)
            except TimeLimitError:
                new, st, msg = None, "time_limit", "the time limit ran out"
            except TensegrityError as exc:
                new, st, msg = None, "failed", f"step {k}: {exc}"
            events.extend(move.events)
            if new is None:
                status, message = st, msg
                break
            state = new
            rows.append(state)
            tell(len(rows), K)
    if status == "complete":
        message = f"all {K} samples simulated, {len([e for e in events if e.kind != 'joint_limit'])} snap(s)"
    k = len(rows)
    q = np.array([s.q for s in rows]).reshape(k, n)
    force = np.array([s.force for s in rows]).reshape(k, 2)
    tips = np.array([s.tip for s in rows]).reshape(k, 2)
    return Simulation(springs=m.springs,
                      mode="held" if held else "free", preloads=P, loads=L, targets=T, q=q, force=force, tip=tips,
                      energy=np.array([s.energy for s in rows], float),
                      potential=np.array([s.potential(held) for s in rows], float),
                      stable=np.array([s.stable for s in rows], bool),
                      morse_index=np.array([s.morse for s in rows], int), events=events, status=status,
                      message=message, straight_length=m.straight_length)
