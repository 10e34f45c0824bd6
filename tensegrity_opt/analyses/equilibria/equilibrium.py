"""One equilibrium: the :class:`Equilibrium` result, and what every analysis builds it from.

* :class:`Equilibrium` - ``q``, energy, the tip force holding it, its Morse index (stability) and the
  solver status; ``to_dict()`` is its JSON form (the API's body);
* building and checking one from a local solve (:func:`make_equilibrium`, :func:`is_equilibrium`),
  the exact special cases (the straight chain, one segment) and the local solve from a start
  (:func:`local_equilibrium`: Newton on the KKT system, IPOPT as the fallback);
* :func:`solve_equilibrium_under_force`: a local minimiser of ``E(q) - F . tip(q)`` for a dead tip
  load (IPOPT, polished by Newton).

The *least-energy stable* equilibrium for a tip displacement (the global search) is
:func:`tensegrity_opt.analyses.equilibria.least_energy.solve_equilibrium`; every equilibrium is
:func:`tensegrity_opt.analyses.equilibria.all_equilibria.find_equilibria`. Both build on this module, which
imports neither. Thread-safe (solvers are cached per thread, :mod:`tensegrity_opt.numerics`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any, ClassVar

import numpy as np

from ...errors import (
    InvalidParameterError,
    NoEquilibriumError,
    SolverError,
    StraightNotEquilibriumError,
    TensegrityError,
    UnreachableTargetError,
    UnsupportedError,
)
from ...model.loads import describe, load_potential, loads_json, loads_key
from ...model.manipulator import Manipulator
from ...model.shapes import shape_label, sign_string
from ...model.springs import SpringFields, Springs
from ...numerics import LocalResult, chain_solver
from ...numerics.slack_nlp import slack_nlp
from ...outcome import Outcome, SolverInfo
from ...serialize import number, numbers
from ...timelimit import check_time
from .buckling import critical_force, tip_slope
from .lower_bound import EnergyBound
from .stability import analyse, inertia_of_reduced

__all__ = ["settle_under_force", "Equilibrium", "solve_equilibrium_under_force", "make_equilibrium",
           "local_equilibrium", "is_equilibrium", "check_q0", "classify_result", "equilibrium_from",
           "straight_equilibrium", "one_segment_equilibrium", "RESIDUAL_TOL", "TipForce"]


class TipForce:
    """``fx`` and ``fy``: the components of a result's tip force ``force`` (``[Fx, Fy]``)."""

    @property
    def fx(self) -> float:
        """``Fx``, the tip force along ``x``."""
        return float(self.force[0])

    @property
    def fy(self) -> float:
        """``Fy``, the tip force along ``y``."""
        return float(self.force[1])


@dataclass(frozen=True)
class Equilibrium(Outcome, TipForce, SpringFields):
    """An equilibrium configuration of the chain.

    Attributes
    ----------
    q : ndarray (n,)
        Relative joint angles (rad), inside the physical range.
    energy : float
        The chain's potential energy (force x length): its springs' elastic energy, plus the potential of its dead
        loads where it carries some (weights under gravity, joint forces: ``Manipulator.potential_energy``); not
        the tip force's work.
    force : ndarray (2,)
        Tip force ``[Fx, Fy]`` holding the equilibrium (``grad E = J^T F``); for the
        displacement problem it comes from the constraint multipliers.
    morse_index : int
        Number of negative eigenvalues of the reduced Hessian (0: stable).
    stable : bool
        Strict local minimum (Morse index 0, non-degenerate).
    solver : SolverInfo
        The solver's own status (IPOPT ``return_status``, the Newton status, ``"straight"``,
        ``"closed_form"``, ``"exact"``) and its iterations of the final solve (0: none needed, e.g. the
        straight chain; ``None``: not counted - a point of the compiled continuation of a chain longer than
        ``kernels.KERNEL_MAX`` segments, solved by CasADi's ``rootfinder``, which does not report it).
    tip : ndarray (2,)
        Tip position.
    control : str
        ``"displacement"`` or ``"force"``.
    hessian_eigenvalues : ndarray
        Eigenvalues of the reduced Hessian (absolute-angle coordinates).
    spring_lengths, spring_stretches, spring_forces, spring_states : ndarray (n, 2)
        Each spring's length, ``L - L0``, force (tension positive, under its segment's law) and state
        (``"taut"``, ``"slack"``, ``"pushing"``) at ``q`` (:class:`~tensegrity_opt.model.springs.SpringFields`;
        from ``springs``, the chain's springs).
    at_stop : ndarray (n,) of bool
        The joints resting on their mechanical stop ``|q_i| = pi - 2 beta_i`` (where springs go slack, or a large
        deflection presses a joint there); all False for an equilibrium inside the open range.
    contact_torques : ndarray (n,)
        The torque each stop supplies (>= 0; 0 where a joint is not at its stop). Both are read from ``stops``:
        ``None`` inside the open range, else the pair ``(at_stop, contact_torques)``.
    certificate : EnergyBound or None
        With ``solve_equilibrium(..., certify=True)``: the rigorous lower bound on the energy of every
        configuration meeting the tip constraint in the closed joint range, and the gap
        (:class:`~.lower_bound.EnergyBound`); ``status`` is ``"certified"`` when the gap is within its tolerance.
    status : str
        How it was obtained (:attr:`STATUSES`); every status is a success: an unconverged solve is never
        returned as an equilibrium.
    message : str
        The same in a sentence.
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "converged": "a numerical solve converged to it (Newton on the KKT system, IPOPT, a continuation step; "
                     "the solver's own status is in solver) and the equilibrium equations hold",
        "exact": "known in closed form: the straight chain, a single segment, or an unloaded chain (a product of "
                 "its segments' critical points)",
        "certified": "the least-energy stable member of a set of equilibria proven complete by the polynomial "
                     "homotopy (method='homotopy'), or the least-energy one proven by a rigorous lower bound on "
                     "the energy of every configuration meeting the tip constraint (certify=True; certificate)",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset(STATUSES)

    q: np.ndarray
    energy: float
    force: np.ndarray
    morse_index: int
    stable: bool
    solver: SolverInfo
    tip: np.ndarray
    control: str = "displacement"
    hessian_eigenvalues: np.ndarray = field(default_factory=lambda: np.zeros(0), repr=False)
    status: str = "converged"
    certificate: EnergyBound | None = field(default=None, repr=False)
    springs: Springs | None = field(default=None, repr=False, compare=False)
    stops: tuple | None = field(default=None, repr=False)
    loads: tuple | None = field(default=None, repr=False)

    def __post_init__(self) -> None:
        # the builders pass arrays they own: read-only in place (this is on the control loop's path)
        if self.stops is not None:
            for a in self.stops:
                a.setflags(write=False)
        self.q.setflags(write=False)
        self.force.setflags(write=False)
        self.tip.setflags(write=False)
        self.hessian_eigenvalues.setflags(write=False)
        if self.status not in self.STATUSES:
            self._check_outcome()

    @property
    def at_stop(self) -> np.ndarray:
        """The joints resting on their stop (n,): all False inside the open range."""
        return _NO_STOP[self.q.size] if self.stops is None else self.stops[0]

    @property
    def contact_torques(self) -> np.ndarray:
        """The torque each stop supplies (n,), >= 0: all 0 inside the open range."""
        return _ZERO_TORQUE[self.q.size] if self.stops is None else self.stops[1]

    @property
    def message(self) -> str:
        """A sentence: how the equilibrium was obtained."""
        if self.status == "exact":
            return "exact: " + _EXACT.get(self.solver.status, self.solver.status.replace("_", " "))
        if self.status == "certified" and self.certificate is not None:
            return f"the least-energy stable equilibrium, {self.certificate.message}"
        if self.status == "certified":
            return ("the least-energy stable equilibrium of the complete set certified by the homotopy "
                    f"({self.solver.status})")
        its = "iterations not counted" if self.solver.iterations is None else f"{self.solver.iterations} iterations"
        return f"converged ({self.solver.status}, {its})" + (f", under {describe(self.loads)}" if self.loads else "")

    @cached_property
    def shape(self) -> str:
        """Shape label of ``q`` (:func:`tensegrity_opt.model.shapes.shape_label`)."""
        return shape_label(self.q)

    @cached_property
    def signs(self) -> str:
        """Sign string of ``q`` (:func:`tensegrity_opt.model.shapes.sign_string`)."""
        return sign_string(self.q)

    @property
    def kind(self) -> str:
        """``"minimum"``, ``"maximum"`` or ``"saddle"`` (``"degenerate"`` on a zero eigenvalue)."""
        dim = self.q.size - 2 if self.control == "displacement" else self.q.size
        if self.stable:
            return "minimum"
        if self.morse_index == 0:
            return "degenerate"
        return "maximum" if self.morse_index == dim else "saddle"

    def to_dict(self) -> dict[str, Any]:
        """JSON form (the body of ``POST /v1/equilibrium``): ``success``, ``status``, ``message``, ``q``,
        ``energy``, ``force`` ``{fx, fy}``, ``morse_index``, ``stable``, ``kind``, ``shape``, ``signs``, ``tip``,
        ``solver`` ``{status, iterations}`` (``iterations`` ``null`` when not counted), ``certificate``
        (:meth:`EnergyBound.to_dict`: with ``certify=True``, or where the search's short way proved its answer;
        else ``null``), the spring state ``spring_lengths``, ``spring_stretches``, ``spring_forces``,
        ``spring_states`` ((n, 2) each), ``at_stop`` and ``contact_torques`` (per joint), ``loads`` (the dead loads it
        was computed under, :func:`~tensegrity_opt.model.loads.loads_json`; ``null`` where the chain carries none);
        every number finite (:mod:`tensegrity_opt.serialize`)."""
        extra = {"certificate": None if self.certificate is None else self.certificate.to_dict()}
        return {**self.outcome(), **self.spring_dict(), "q": numbers(self.q), "energy": number(self.energy),
                "force": {"fx": number(self.fx), "fy": number(self.fy)},
                "morse_index": int(self.morse_index), "stable": bool(self.stable), "kind": self.kind,
                "shape": self.shape, "signs": self.signs, "tip": numbers(self.tip),
                "solver": self.solver.to_dict(), **extra, "at_stop": [bool(v) for v in self.at_stop],
                "contact_torques": numbers(self.contact_torques), "loads": loads_json(self.loads)}


class _Zeros(dict):
    """Read-only zero vectors by length, made once (shared by every equilibrium inside the open range)."""

    def __init__(self, dtype: type) -> None:
        super().__init__()
        self.dtype = dtype

    def __missing__(self, n: int) -> np.ndarray:
        z = np.zeros(n, dtype=self.dtype)
        z.setflags(write=False)
        self[n] = z
        return z


_NO_STOP = _Zeros(bool)
_ZERO_TORQUE = _Zeros(float)


#: What each exact case is (the sentence of :attr:`Equilibrium.message`), by its ``solver.status``.
_EXACT = {"straight": "the straight chain, the only configuration at full extension",
          "closed_form": "a single segment, its angle fixed by the target",
          "exact": "the unloaded chain, a product of its segments' critical points"}


def make_equilibrium(m: Manipulator, res: LocalResult, *, constrained: bool, status: str = "converged") -> Equilibrium:
    """Classify a converged local solution into an :class:`Equilibrium` (``status``: how it was obtained,
    :attr:`Equilibrium.STATUSES`)."""
    return equilibrium_from(res, *classify_result(m, res, constrained), constrained, status=status,
                            springs=m.springs)


def classify_result(m: Manipulator, res: LocalResult, constrained: bool):
    """``(inertia, energy, tip)`` of a converged local solution: from the compiled kernels' reduced
    Hessian when it came with one, else evaluated from the model (:func:`.stability.analyse`)."""
    if constrained and res.reduced_hessian is not None:        # the compiled kernels' outputs
        return inertia_of_reduced(res.reduced_hessian, scale=m.torque_scale), res.energy, res.tip
    return analyse(m, res.q, res.force, constrained=constrained)


def equilibrium_from(res: LocalResult, inertia, energy, tip, constrained: bool, *,
                     status: str = "converged", springs: Springs | None = None) -> Equilibrium:
    """The :class:`Equilibrium` of a local solution and its classification (:func:`classify_result`)."""
    return Equilibrium(q=res.q.copy(), energy=energy, force=np.asarray(res.force, float).copy(),
                       morse_index=inertia.morse_index, stable=inertia.stable,
                       solver=SolverInfo(res.status, res.iterations),
                       tip=np.array(tip, dtype=float), control="displacement" if constrained else "force",
                       hessian_eigenvalues=inertia.eigenvalues, status=status, springs=springs)


#: Largest accepted scaled residual of the equilibrium equations (checked in numpy, independently
#: of the solver that produced the point).
RESIDUAL_TOL = 1e-9
#: Chains whose springs may go slack (the closed range, joint stops; :mod:`.tension_only` shares these): a joint
#: within this distance of its bound (rad) rests on its stop.
STOP_TOL = 1e-6
#: ... or within this one where the free joints do not balance otherwise (IPOPT's interior point may end that far
#: inside a stop it presses on).
HELD_TOL = 1e-4
#: Newton iterations of the polish at most.
POLISH_ITER = 30
#: Reduced-Hessian eigenvalues below this (times k c^2) are zero: not a strict minimum.
EIG_TOL = 1e-9


def is_equilibrium(m: Manipulator, res: LocalResult, target: np.ndarray | None = None, *,
           check_residual: bool = True) -> bool:
    """A converged solve inside the open physical range that really is an equilibrium.

    ``check_residual`` re-evaluates the equilibrium equations in numpy (independently of
    CasADi); Newton results, whose convergence test *is* the residual, may skip it.
    """
    if res.energy is not None and not check_residual:
        return res.success and not res.on_bound     # a converged kernel result: finite, range checked
    if not (res.success and not res.on_bound and math.isfinite(float(res.force.sum()))
            and m.in_range(res.q)):         # in_range is False for a NaN angle
        return False
    return not check_residual or m.equilibrium_residual(res.q, res.force, target) <= RESIDUAL_TOL


def check_q0(m: Manipulator, q0, *, closed: bool = False) -> np.ndarray | None:
    """``q0`` as an array of ``n`` angles inside the open physical range (``closed``: the closed one, where a joint
    may rest on its stop: the tension-only solves), or None; else :class:`InvalidParameterError` (``field="q0"``)."""
    if q0 is None:
        return None
    q0 = np.asarray(q0, dtype=float)
    if q0.shape == (m.n,) and m.in_range(q0):          # the common case first (NaN is not in range)
        return q0
    if q0.shape != (m.n,) or not np.all(np.isfinite(q0)):
        raise InvalidParameterError(f"q0 must hold {m.n} finite joint angles, got shape {q0.shape}", field="q0")
    if closed and np.all(np.abs(q0) <= m.joint_limits):
        return q0
    if closed:
        raise InvalidParameterError("q0 lies outside the closed joint range |q_i| <= pi - 2 beta_i", field="q0")
    raise InvalidParameterError("q0 lies outside the physical joint range |q_i| < pi - 2 beta_i", field="q0")


def straight_equilibrium(m: Manipulator, *, check: bool = True) -> Equilibrium:
    """The fully extended chain (the only configuration reaching ``dx = dy = 0``).

    It is an equilibrium only when its spring torques are balanced by a tip force, which at full
    extension can only be ``Fy`` times each joint's lever arm: always so for symmetric segments
    (no torque), in general not with asymmetric preloads (a pre-bent chain pulled straight needs an
    unbounded tension). Then :class:`StraightNotEquilibriumError` (``check=False``: the straight
    chain with the least-squares force, for callers that mark the point themselves).
    """
    q = np.zeros(m.n)
    S0 = tip_slope(m)
    s2 = float(S0 @ S0)
    fy = float(S0 @ m.potential_gradient(q) / s2) if s2 > 0.0 else 0.0
    if check:
        r = m.equilibrium_residual(q, (0.0, fy))
        if r > RESIDUAL_TOL:
            raise StraightNotEquilibriumError(
                f"dx = dy = 0 holds the tip at full extension, which only the straight chain reaches, and the "
                f"straight chain is not an equilibrium of this chain under any finite tip force (its spring "
                f"torques are not proportional to the lever arms: residual {r:.3g} of k c^2; asymmetric "
                f"preloads bend it); choose dx > 0", field="dx")
    return Equilibrium(q=q, energy=m.potential_energy(q), force=np.array([0.0, fy]), morse_index=0, stable=True,
                       solver=SolverInfo("straight", 0), tip=m.tip(q), control="displacement", status="exact",
                       springs=m.springs, loads=loads_key(m))


def one_segment_equilibrium(m: Manipulator, target: np.ndarray) -> Equilibrium:
    """A single segment: the target fixes the joint angle; the force is the least-norm one.

    With one joint the tip constraint leaves no freedom (the configuration manifold is a
    point) and the force along the link is not determined by equilibrium: eq. (8) gives the
    component normal to the link, the least-norm force.
    """
    q = np.array([math.atan2(target[1], target[0] - m.base_length)])
    if not m.in_range(q):
        raise UnreachableTargetError(
            f"reaching the target needs q = {q[0]:.6g}, outside the joint range |q| < {m.joint_limits[0]:.6g}",
            field="dx")
    J = m.jacobian(q)
    force = J[:, 0] * (m.potential_gradient(q)[0] / float(J[:, 0] @ J[:, 0]))
    return Equilibrium(q=q, energy=m.potential_energy(q), force=force, morse_index=0, stable=True,
                       solver=SolverInfo("closed_form", 0), tip=m.tip(q), control="displacement", status="exact",
                       springs=m.springs, loads=loads_key(m))


def local_equilibrium(m: Manipulator, target: np.ndarray, q0: np.ndarray, F0: np.ndarray | None = None,
                      *, minimize: bool = False) -> LocalResult:
    """One local solve for the displacement problem: Newton on the KKT system from ``(q0, F0)``,
    or IPOPT (``minimize=True``) followed by a Newton polish. Returns the raw result."""
    mdl = chain_solver(m)
    if not minimize:
        return mdl.newton_kkt(target, q0, F0)
    res = mdl.minimize_displacement(target, q0)
    if not res.on_bound and np.all(np.isfinite(res.q)):
        # Newton polish to machine precision; IPOPT's status is kept (its solve is the result).
        pol = mdl.newton_kkt(target, res.q, res.force)
        if pol.success and np.max(np.abs(pol.q - res.q)) < 1e-4:
            pol.status = res.status
            pol.iterations = res.iterations
            pol.success = res.success or res.status == "Solved_To_Acceptable_Level"
            return pol
        if res.status == "Solved_To_Acceptable_Level":
            res.success = False
    return res


def settle_under_force(m: Manipulator, force, q0) -> Equilibrium | None:
    """The stable equilibrium under the dead tip load ``force`` that Newton reaches from ``q0`` (the forward
    quasi-static solve from a nearby state), or None when Newton does not converge inside the range onto a
    stable point (the caller then descends, e.g. :func:`solve_equilibrium_under_force`)."""
    res = chain_solver(m).newton_force(np.asarray(force, dtype=float), np.asarray(q0, dtype=float))
    if not is_equilibrium(m, res):
        return None
    eq = make_equilibrium(m, res, constrained=False)
    return eq if eq.stable else None


def _under_force_slack(m: Manipulator, force: np.ndarray, q0) -> Equilibrium:
    """:func:`solve_equilibrium_under_force` of a chain with tension-only springs (the closed range, stops held:
    :func:`_equilibrium_under_force_slack`); the default start is straight, nudged along the first free
    buckling mode under a load beyond the first critical one (or a small bend where the straight chain's springs are
    not all taut)."""
    q0 = check_q0(m, q0, closed=True)
    if q0 is None and m.loaded:                 # from the sagged shape (the least potential with the tip free)
        try:
            q0 = least_energy_free(m).q
        except TensegrityError:
            q0 = 0.02 * np.cos(np.arange(m.n)) * float(np.min(m.joint_limits))
    if q0 is None:
        q0 = np.zeros(m.n)
        try:
            first = critical_force(m, "free", n_modes=1).modes[0]
            if -force[0] >= first.load:
                q0 = 0.05 * first.q / np.abs(first.q).max() * float(np.min(m.joint_limits))
        except TensegrityError:                 # not taut when straight, or straight no equilibrium
            q0 = 0.02 * np.cos(np.arange(m.n)) * float(np.min(m.joint_limits))
    return _equilibrium_under_force_slack(m, force, q0)


def solve_equilibrium_under_force(m: Manipulator, fx: float, fy: float, *, q0=None) -> Equilibrium:
    """A local minimiser of ``E(q) - F . tip(q)`` for the tip force ``F = (fx, fy)`` (dead load).

    Parameters
    ----------
    fx, fy : float
        Tip force (force units); ``fx < 0`` compresses.
    q0 : array_like (n,), optional
        Start. Default: straight, perturbed along the first free buckling mode when
        straight is unstable under this load (``K + fx G`` not positive definite).

    Returns
    -------
    Equilibrium
        ``control == "force"``, classified with ``Z = I``; may be unstable only when
        IPOPT stops at a degenerate point, which ``stable`` reports.

    Raises
    ------
    NoEquilibriumError, SolverError
        (``RuntimeError``) when IPOPT does not converge or only finds a point on a joint limit.
    """
    for name, v in (("fx", fx), ("fy", fy)):
        if not math.isfinite(float(v)):
            raise InvalidParameterError(f"{name} must be finite, got {v!r}", field=name)
    force = np.array([float(fx), float(fy)])
    if not m.paper_model:
        return _under_force_slack(m, force, q0)
    q0 = check_q0(m, q0)
    if q0 is None:
        q0 = np.zeros(m.n)
        try:
            # straight is unstable under a compressive load beyond the first free-tip critical load
            first = critical_force(m, "free", n_modes=1).modes[0]
            if -force[0] >= first.load:
                q0 = 0.05 * first.q / np.abs(first.q).max() * float(np.min(m.joint_limits))
        except TensegrityError:
            pass                    # straight is not an equilibrium: IPOPT leaves it anyway
    mdl = chain_solver(m)
    res = mdl.minimize_force(force, q0)
    if res.success and not res.on_bound:
        pol = mdl.newton_force(force, res.q)
        if pol.success and np.max(np.abs(pol.q - res.q)) < 1e-4:
            pol.status, pol.iterations = res.status, res.iterations
            res = pol
    if not res.success:
        raise SolverError(f"IPOPT did not converge for the tip force ({fx:g}, {fy:g})", status=res.status)
    if not is_equilibrium(m, res):
        raise NoEquilibriumError(
            f"no equilibrium inside the physical range for the tip force ({fx:g}, {fy:g}): the minimiser "
            "presses a joint against its limit", status=res.status)
    return make_equilibrium(m, res, constrained=False)


def free_residual(m: Manipulator, q: np.ndarray, F: np.ndarray, free: np.ndarray) -> float:
    """The free joints' equilibrium residual in numpy (scaled by k c^2), under each spring's law and the dead loads."""
    r = m.potential_gradient(q) - m.jacobian(q).T @ F
    return float(np.abs(r[free]).max(initial=0.0)) / m.torque_scale if math.isfinite(float(r.sum())) else math.inf


# ----------------------------------------------------------------------------- force control
def _equilibrium_under_force_slack(m: Manipulator, force: np.ndarray, q0: np.ndarray) -> Equilibrium:
    """A local minimiser of ``E(q) - F . tip(q)`` under each spring's law in the closed joint range, from ``q0``
    (force control: the tip free, the dead load ``F``): IPOPT on the slack problem with the tip rows unbounded, the
    joints at a stop read from its solution and held, Newton on the free joints' rows ``dE/dq - J^T F = 0``, the
    residual re-checked in numpy, each stop's contact torque ``-sign(q_i)(dE/dq_i - (J^T F)_i) >= 0``, and the
    stability of the Hessian of ``E - F . tip`` on the free joints (the stops held).

    Raises :class:`NoEquilibriumError` (``RuntimeError``) where IPOPT does not converge or its point does not check
    out, :class:`UnsupportedError` (``field="segments[i]"``, status ``free_joint``) where a segment's two springs are
    slack and nothing holds its joint (its angle undetermined)."""
    nlp = slack_nlp(m.n, m.loaded)
    force = np.asarray(force, dtype=float)
    lim = m.joint_limits
    res = nlp.solve(nlp.start(m, np.clip(q0, -lim, lim)), nlp.parameters(m, np.zeros(2), force),
                    nlp.bounds(m, free_tip=True))
    if not res.success:
        raise NoEquilibriumError(f"IPOPT did not converge for the tip force ({force[0]:g}, {force[1]:g}) under the "
                                 f"springs' laws ({res.status})", status=res.status)
    q_ip = np.array(nlp.x.unpack(res.x)["q"], dtype=float)
    scale = m.torque_scale
    for tol in (STOP_TOL, HELD_TOL):            # IPOPT may end a little inside a stop it presses on: then held
        side = np.where(q_ip >= lim - tol, 1.0, np.where(q_ip <= -lim + tol, -1.0, 0.0))
        q = np.where(side != 0.0, side * lim, q_ip)
        free = side == 0.0
        idx = np.flatnonzero(free)
        for _ in range(POLISH_ITER):            # Newton on the free joints' rows (F given)
            _, g, H, _, J = nlp.derivatives(m, q, force)
            r = (g - J.T @ force)[idx]
            if float(np.abs(r).max(initial=0.0)) <= 1e-13 * scale:
                break
            try:
                d = np.linalg.solve(H[np.ix_(idx, idx)], -r)
            except np.linalg.LinAlgError:
                break
            q = q.copy()
            q[idx] += d
            if np.any(np.abs(q) > lim) or float(np.abs(d).max(initial=0.0)) < 1e-15:
                break
        if not np.any(np.abs(q) > lim) and free_residual(m, q, force, free) <= RESIDUAL_TOL:
            break
    if np.any(np.abs(q) > lim) or free_residual(m, q, force, free) > RESIDUAL_TOL:
        raise NoEquilibriumError(f"the solve for the tip force ({force[0]:g}, {force[1]:g}) did not end on an "
                                 "equilibrium under the springs' laws", status="not_an_equilibrium")
    E, g, H, tip, J = nlp.derivatives(m, q, force)
    contact = np.where(free, 0.0, -side * (g - J.T @ force))
    if np.any(contact < -1e-9 * scale):
        raise NoEquilibriumError(f"the solve for the tip force ({force[0]:g}, {force[1]:g}) ended against a stop that "
                                 "pulls (a negative contact torque): not an equilibrium", status="not_an_equilibrium")
    w = np.linalg.eigvalsh(H[np.ix_(idx, idx)]) if idx.size else np.zeros(0)
    morse = int(np.sum(w < -EIG_TOL * scale))
    stable = morse == 0 and bool(np.all(w > EIG_TOL * scale))
    if morse == 0 and not stable:
        loose = [i for i in idx if np.all(m.springs.states(q)[i] == "slack")]
        if loose:
            i = int(loose[0])
            raise UnsupportedError(f"both springs of segment {i} are slack under the tip force ({force[0]:g}, "
                                   f"{force[1]:g}) and its joint is left undetermined (a free joint: no stiffness and "
                                   "nothing holds it)", field=f"segments[{i}]", status="free_joint")
    return Equilibrium(q=q.copy(), energy=float(m.potential_energy(q)), force=force.copy(), morse_index=morse,
                       stable=stable,
                       solver=SolverInfo(res.status, res.iterations), tip=m.tip(q), control="force",
                       hessian_eigenvalues=w, springs=m.springs, stops=(side != 0.0, np.maximum(contact, 0.0)),
                       loads=loads_key(m))


# ----------------------------------------------------------------------------- the free tip under dead loads
#: The free-tip search under dead loads (:func:`least_energy_free`): random configurations per joint ranked, local
#: solves from the lowest ``FREE_STARTS`` distinct ones (besides straight); two starts closer than ``FREE_DISTINCT``
#: (rad) are one, two equilibria closer than ``FREE_SAME`` are one.
FREE_SAMPLE_PER_JOINT = 256
FREE_STARTS = 6
FREE_DISTINCT = 0.15
FREE_SAME = 1e-4


def least_energy_free(m: Manipulator, force=(0.0, 0.0)) -> Equilibrium:
    """The least-potential stable equilibrium of ``m`` with its tip free under the dead tip load ``force`` (default
    none: the rest configuration), in the closed joint range: the local solve of
    :func:`~.equilibrium._equilibrium_under_force_slack` (IPOPT on the slack problem with the tip rows free, Newton,
    the checks in numpy) from straight and from the ``FREE_STARTS`` lowest-potential distinct configurations of
    ``FREE_SAMPLE_PER_JOINT * n`` seeded random ones of the closed range (a quarter with one joint on a stop), ranked
    by ``E + V - F . tip`` (numpy, all at once). A measured global search, not a certified one (``status``
    ``"converged"``)."""
    F = np.asarray(force, dtype=float)
    found, failures, refused = free_stable(m, F, free_starts(m, F, FREE_STARTS))
    if not found:
        if refused is not None:
            raise refused
        why = ", ".join(sorted(set(failures))) or "all unstable"
        raise NoEquilibriumError(f"no stable equilibrium with the tip free under the force ({F[0]:g}, {F[1]:g}) found "
                                 f"from {FREE_STARTS + 1} starts ({why})", status="no_stable_equilibrium")
    key = [e.energy - float(F @ e.tip) for e in found]
    e0 = min(key)
    tied = [e for e, v in zip(found, key) if v <= e0 + 1e-10 * max(1.0, abs(e0))]
    best = max(tied, key=lambda e: (next((float(np.sign(v)) for v in e.q if abs(v) > 1e-9), 0.0),
                                    -float(np.abs(e.q).max())))
    if F[1] == 0.0 and m == m.mirrored() and next((v for v in best.q if abs(v) > 1e-9), 0.0) < 0.0:
        twin, _, _ = free_stable(m, F, [-best.q])   # its mirror image ties: the one with q_1 > 0 (as elsewhere)
        if twin and abs(twin[0].energy - best.energy) <= 1e-10 * max(1.0, abs(best.energy)):
            best = twin[0]
    return best


def free_starts(m: Manipulator, F: np.ndarray, count: int) -> list[np.ndarray]:
    """Straight and the ``count`` lowest-potential distinct configurations of a seeded random sample of the closed
    range (a quarter with one joint on a stop), ranked by ``E + V - F . tip``."""
    n, lim = m.n, m.joint_limits
    rng = np.random.default_rng(20261209 + n)
    Q = rng.uniform(-0.98, 0.98, size=(FREE_SAMPLE_PER_JOINT * n, n)) * lim
    k = Q.shape[0] // 4
    j = rng.integers(0, n, size=k)
    Q[np.arange(k), j] = rng.choice([-1.0, 1.0], size=k) * lim[j]
    tip = m.tip_kinematics(Q).tip
    E = m.springs.energy(Q) + (load_potential(m, Q) if m.loaded else 0.0) - tip @ F
    starts = [np.zeros(n)]
    for i in np.argsort(E, kind="stable"):
        if all(float(np.abs(Q[i] - s).max()) > FREE_DISTINCT for s in starts):
            starts.append(Q[i])
        if len(starts) > count:
            break
    return starts


def free_stable(m: Manipulator, F: np.ndarray, starts) -> tuple[list[Equilibrium], list[str], Any]:
    """The distinct stable equilibria reached from ``starts`` (tip free under ``F``), the failures' statuses and the
    last refusal (a free joint left undetermined)."""
    found: list[Equilibrium] = []
    refused: UnsupportedError | None = None
    failures: list[str] = []
    for qs in starts:
        check_time("the free-tip search")
        try:
            eq = _equilibrium_under_force_slack(m, F, qs)
        except UnsupportedError as exc:
            refused = exc
            continue
        except NoEquilibriumError as exc:
            failures.append(str(exc.details.get("status") or "failed"))
            continue
        if eq.stable and not any(float(np.abs(eq.q - e.q).max()) < FREE_SAME for e in found):
            found.append(eq)
    return found, failures, refused


