"""Imperfection sensitivity: the limit load an imperfect arm reaches, against the imperfection's amplitude.

:func:`imperfection_sensitivity` moves the chain by an amplitude ``p`` along an imperfection (by default
``"asymmetry"``: every segment's rest lengths ``L1_0 + p`` and ``L2_0 - p``, a pre-bend; the chain of
:func:`~.boundaries.chain_at`, the same words as the parameter axis of
:func:`~.boundaries.stability_boundary`) and, at every amplitude, takes the limit load of the dead-load path
from that imperfect chain's own rest shape, :func:`~.limit_load.limit_load` with the same direction and boundary
(guided: the guide through the imperfect chain's rest tip). This is Koiter's picture: the load an imperfect
arm actually carries before it snaps, buckles or reaches a joint limit, with amplitude 0 the given (perfect)
chain. The limit loads are not re-computed here: each one *is* ``limit_load`` of its chain.

Where the perfect chain loses stability at a bifurcation, the classical small-imperfection laws say how the
limit load of the imperfect chain approaches the critical load ``P_c``:

* **unstable-symmetric** (subcritical pitchfork: the buckled arms carry less): the imperfect path folds at
  ``P_s(p) = P_c - C |p|^(2/3)``. Example: two segments ``Segment(1.5, 1, 1, 1)`` under the guided load
  (``P_c = 35/6``, the drop's log-log slope 0.667 for ``p`` from 1e-5 to 3e-3);
* **asymmetric** (transcritical): ``P_c - C |p|^(1/2)`` on the side of ``p`` that drops;
* **stable-symmetric** (supercritical: the buckled arms carry more) the imperfect path has no limit near
  ``P_c``: it bends smoothly (``kind`` ``"none"`` or ``"joint_limit"``; the free paper chain), or, where the
  buckled arm itself folds further on (the paper chain guided: ``P_c = 0.5728``, its arms fold at 0.6143), it
  folds near that arm's fold, whose load the limit load tends to (linearly in ``p``) as ``p -> 0``.

:attr:`ImperfectionSensitivity.bifurcation` says which case the perfect chain is (from its buckled arms,
:func:`~.limit_load.limit_arms`: both carry less, one does, both carry more), and ``law_exponent`` and
``law_coefficient`` are the law fitted at the smallest amplitudes where one applies (an unstable-symmetric or
asymmetric bifurcation, the imperfect chains at folds below ``P_c``) on the side of ``p`` whose folds fall below
``P_c`` (both signs are tried; where both drop, the side with more such amplitudes, the positive one on a tie);
compare the exponent with ``law_expected`` (2/3 or 1/2).

:func:`~.boundaries.stability_boundary` with ``parameter="asymmetry"`` is another curve: the fold (or branch
point) of a branch continued in ``p`` with its references fixed, which is not the load an imperfect arm reaches.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from ...checks import real_array
from ...errors import InvalidParameterError, TensegrityError, TimeLimitError
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...model.springs import linear_only
from ...outcome import Outcome, freeze
from ...serialize import nullable, nullables, number, numbers
from ...timelimit import expired, time_limit
from .boundaries import PARAMETERS, chain_at, parameter_direction
from .limit_load import LimitLoad, check_max_load, limit_arms, limit_load

__all__ = ["ImperfectionSensitivity", "imperfection_sensitivity", "KINDS", "BIFURCATIONS", "AMPLITUDE_STATUSES",
           "LAW_POINTS"]

#: The kind of each amplitude's limit.
KINDS = ("fold", "bifurcation", "joint_limit", "none", "unknown")
#: The perfect chain's bifurcation by its buckled arms (:func:`~.limit_load.limit_arms`), and the exponent of
#: the classical small-imperfection law where one applies.
BIFURCATIONS = {"unstable_symmetric": 2.0 / 3.0, "asymmetric": 0.5, "stable_symmetric": None}
#: The small-imperfection law is fitted at (up to) this many of the smallest amplitudes where it applies.
LAW_POINTS = 4
#: An amplitude's status beyond :attr:`LimitLoad.STATUSES`.
_NOT_COMPUTED, _FAILED = "not_computed", "failed"
#: Every status an amplitude may have (:attr:`ImperfectionSensitivity.statuses`).
AMPLITUDE_STATUSES = (*LimitLoad.STATUSES, _FAILED, _NOT_COMPUTED)


@dataclass(frozen=True)
class ImperfectionSensitivity(Outcome):
    """The result of :func:`imperfection_sensitivity`.

    Attributes
    ----------
    status : str
        :attr:`STATUSES`: ``"complete"`` when every amplitude's path reached its end; ``"partial"`` when some
        path was cut, some imperfect chain could not be followed, or a path without a limit point has unstable
        points (stability lost where no event was located); those amplitudes' ``kinds`` are ``"unknown"``;
        ``"time_limit"`` when the time limit ran out first (the amplitudes done are kept).
    message : str
    amplitudes : ndarray (A,)
        The amplitudes, in the order given.
    loads : ndarray (A,)
        The limit load at each amplitude: the load of the fold or bifurcation; for ``"joint_limit"`` the load
        at which a joint reaches its range bound on the still stable path (:attr:`LimitLoad.end_load`); NaN for
        ``"none"`` (stable up to ``max_load``) and ``"unknown"``.
    kinds : tuple of str
        Per amplitude (:data:`KINDS`): ``"fold"``, ``"bifurcation"``, ``"joint_limit"``, ``"none"``, or
        ``"unknown"`` where the path was cut, the chain could not be followed, the time ran out first, or the
        path reports no limit point but has unstable points.
    statuses : tuple of str
        Per amplitude the :class:`LimitLoad` status, ``"failed"`` (the imperfect chain could not be followed:
        ``messages`` says why) or ``"not_computed"`` (the time limit ran out before it).
    messages : tuple of str
        Per amplitude, in words.
    limit_loads : tuple of (LimitLoad or None)
        Per amplitude the result of ``limit_load`` of the imperfect chain (None where not computed).
    perfect : LimitLoad or None
        The limit load of the given chain (amplitude 0).
    law_exponent, law_coefficient : float or None
        The small-imperfection law ``perfect.load - load = C |p|^e`` fitted (least squares in log-log) at the
        amplitudes ``law_amplitudes``; None where it does not apply (module docstring).
    law_amplitudes : ndarray
    bifurcation : str or None
        The perfect chain's bifurcation (:data:`BIFURCATIONS`): ``"unstable_symmetric"`` (both buckled arms
        carry less load), ``"asymmetric"`` (one does), ``"stable_symmetric"`` (both carry more); None where its
        limit is not a bifurcation (or its arms could not be followed).
    imperfection : str
        Its name (:data:`~.boundaries.PARAMETERS`) or ``"direction"``; ``imperfection_direction`` the 6n
        direction the amplitude moves the chain along.
    imperfection_direction : ndarray (6n,)
    direction : ndarray (2,)
    boundary : str
    max_load : float or None
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "complete": "every amplitude's path was followed to its limit point or its end",
        "partial": "some amplitude's path was cut, could not be followed or lost stability at no located limit "
                   "point (kind unknown)",
        "time_limit": "the time limit ran out before every amplitude was computed (those computed are kept)",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"complete"})

    status: str
    message: str
    amplitudes: np.ndarray
    loads: np.ndarray
    kinds: tuple
    statuses: tuple
    messages: tuple
    limit_loads: tuple
    perfect: LimitLoad | None
    law_exponent: float | None
    law_coefficient: float | None
    law_amplitudes: np.ndarray
    bifurcation: str | None
    imperfection: str
    imperfection_direction: np.ndarray
    direction: np.ndarray
    boundary: str
    max_load: float | None

    def __post_init__(self) -> None:
        freeze(self)

    @property
    def perfect_load(self) -> float | None:
        """The perfect chain's limit load (its critical load at a bifurcation), None without one."""
        return None if self.perfect is None else self.perfect.load

    @property
    def law_expected(self) -> float | None:
        """The exponent of the classical law for :attr:`bifurcation` (2/3, 1/2), None where none applies."""
        return None if self.bifurcation is None else BIFURCATIONS[self.bifurcation]

    @property
    def perfect_kind(self) -> str:
        """The perfect chain's kind of limit (as :attr:`kinds`)."""
        return "unknown" if self.perfect is None else _kind(self.perfect)

    def to_dict(self, *, include_limit_loads: bool = False) -> dict[str, Any]:
        """JSON form (the body of ``POST /v1/imperfection-sensitivity``): ``success``, ``status``,
        ``message``, ``imperfection``, ``direction``, ``boundary``, ``max_load``, ``amplitudes``, ``loads`` (null
        for NaN), ``kinds``, ``statuses``, ``messages``, ``perfect_load``, ``perfect_kind``, ``law`` (``exponent``,
        ``coefficient``, ``amplitudes``; null where it does not apply) and with ``include_limit_loads`` the
        ``limit_loads`` (:meth:`LimitLoad.to_dict` or null) and ``perfect``."""
        law = None if self.law_exponent is None else {
            "exponent": number(self.law_exponent), "expected": number(self.law_expected),
            "coefficient": number(self.law_coefficient), "amplitudes": numbers(self.law_amplitudes)}
        d = {**self.outcome(), "imperfection": self.imperfection, "direction": numbers(self.direction),
             "boundary": self.boundary, "max_load": None if self.max_load is None else number(self.max_load),
             "amplitudes": numbers(self.amplitudes), "loads": nullables(self.loads), "kinds": list(self.kinds),
             "statuses": list(self.statuses), "messages": list(self.messages),
             "perfect_load": None if self.perfect_load is None else nullable(self.perfect_load),
             "perfect_kind": self.perfect_kind, "bifurcation": self.bifurcation, "law": law}
        if include_limit_loads:
            d["limit_loads"] = [None if r is None else r.to_dict() for r in self.limit_loads]
            d["perfect"] = None if self.perfect is None else self.perfect.to_dict()
        return d


def _unlocated_loss(r: LimitLoad) -> bool:
    """The path has no limit point, yet unstable points: it lost stability where no event was located."""
    return r.kind == "none" and not bool(np.all(r.branch.stable))


def _kind(r: LimitLoad) -> str:
    if r.kind in ("fold", "bifurcation"):
        return r.kind
    if _unlocated_loss(r):
        return "unknown"
    return {"joint_limit": "joint_limit", "max_load": "none"}.get(r.status, "unknown")


def _load(r: LimitLoad) -> float:
    kind = _kind(r)
    if kind in ("fold", "bifurcation"):
        return float(r.load)
    return float(r.end_load) if kind == "joint_limit" else math.nan


def _check_amplitudes(amplitudes) -> np.ndarray:
    a = real_array(amplitudes, "amplitudes")
    if a.ndim == 0:
        a = a.reshape(1)
    if a.ndim != 1 or a.size == 0 or not np.all(np.isfinite(a)):
        raise InvalidParameterError("amplitudes must be a non-empty list of finite numbers", field="amplitudes")
    return a


def _bifurcation(perfect: LimitLoad | None) -> str | None:
    """The perfect chain's bifurcation by the load along its buckled arms just past the branch point."""
    if perfect is None or perfect.kind != "bifurcation" or perfect.load is None:
        return None
    try:
        arms = limit_arms(perfect, max_points=8)
    except TensegrityError:
        return None
    pc = float(perfect.load)
    sides = {int(np.sign(a.t[1] - pc)) for a in arms if len(a) > 1 and a.t[1] != pc}
    if len(arms) < 2 or len(sides) == 0:
        return None
    if sides == {-1}:
        return "unstable_symmetric"
    return "stable_symmetric" if sides == {1} else "asymmetric"


def _law_side(amplitudes: np.ndarray, loads: np.ndarray, kinds, pc: float, side: float) -> list[int]:
    """The amplitudes of one sign, from the smallest on, while the limit is a fold below ``pc`` (up to
    :data:`LAW_POINTS`, increasing in size)."""
    order = [i for i in np.argsort(np.abs(amplitudes), kind="stable") if np.sign(amplitudes[i]) == side]
    used: list[int] = []
    for i in order:
        if kinds[i] != "fold" or not pc - loads[i] > 0.0:
            break
        if not used or abs(amplitudes[i]) > abs(amplitudes[used[-1]]):
            used.append(i)
        if len(used) == LAW_POINTS:
            break
    return used


def _law(amplitudes: np.ndarray, loads: np.ndarray, kinds, perfect: LimitLoad | None, bifurcation: str | None):
    """``(exponent, coefficient, amplitudes)`` of ``P_c - P = C |p|^e`` at the smallest amplitudes, or Nones.

    Both signs of ``p`` are tried: the law is fitted on the side whose smallest amplitudes fold below ``P_c`` (the
    side that drops); where both do (a symmetric bifurcation), on the side with more such amplitudes, the positive
    one on a tie."""
    none = (None, None, np.zeros(0))
    if bifurcation not in ("unstable_symmetric", "asymmetric"):
        return none
    pc = float(perfect.load)
    used = max((_law_side(amplitudes, loads, kinds, pc, side) for side in (1.0, -1.0)), key=len)
    if len(used) < 2:
        return none
    x, y = np.log(np.abs(amplitudes[used])), np.log(pc - loads[used])
    e, c = np.polyfit(x, y, 1)
    return float(e), float(math.exp(c)), amplitudes[used].copy()


def imperfection_sensitivity(m: Manipulator, amplitudes, *, imperfection="asymmetry", direction=(-1.0, 0.0),
                             boundary: str = "guided", max_load: float | None = None, max_points: int = 4000,
                             timeout: float | None = None) -> ImperfectionSensitivity:
    """The limit load of the dead-load path from the rest shape of the imperfect chain, against the amplitude.

    Parameters
    ----------
    m : Manipulator
        The perfect chain (amplitude 0).
    amplitudes : array_like (A,)
        The amplitudes ``p`` (the imperfection's units: a length for ``"asymmetry"``), computed in this order.
    imperfection : str or array_like (6n,)
        What the amplitude moves (:func:`~.boundaries.chain_at`): ``"asymmetry"`` (``L1_0 + p``, ``L2_0 - p`` on
        every segment: a pre-bend), another name of :data:`~.boundaries.PARAMETERS` or a direction in the
        chain's parameters, as the parameter of :func:`~.boundaries.stability_boundary`.
    direction, boundary, max_load, max_points
        As :func:`~.limit_load.limit_load` (default the guided compression ``(-1, 0)``); each imperfect chain's
        path starts at its own least-energy rest configuration, guided: the guide through its rest tip.
    timeout : float, optional
        Seconds for the whole curve: the amplitudes computed before it runs out are kept
        (``status="time_limit"``, the others ``kinds`` ``"unknown"``, ``statuses`` ``"not_computed"``).

    Returns
    -------
    ImperfectionSensitivity
        At every amplitude ``limit_loads[i]`` is ``limit_load(chain_at(m, imperfection, p), direction,
        boundary, max_load)`` and ``loads[i]``, ``kinds[i]`` its load and kind (``"joint_limit"``: the load
        where the still stable path reaches a joint's range bound).

    Raises
    ------
    InvalidParameterError
        (``ValueError``) for bad amplitudes (also an amplitude giving an invalid chain, e.g. a rest length
        <= 0), imperfection, direction, boundary or ``max_load``.
    """
    unloaded_only(m, "imperfection_sensitivity")
    linear_only(m, "imperfection_sensitivity")
    amps = _check_amplitudes(amplitudes)
    if isinstance(imperfection, str) and imperfection not in PARAMETERS:
        raise InvalidParameterError(f"imperfection must be one of {PARAMETERS} or a vector of 6n numbers, got "
                                    f"{imperfection!r}", field="imperfection")
    try:
        name, dp = parameter_direction(m, imperfection)
    except InvalidParameterError as exc:
        raise InvalidParameterError(str(exc), field="imperfection") from None
    if boundary not in ("free", "guided"):
        raise InvalidParameterError(f"boundary must be 'free' or 'guided', got {boundary!r}", field="boundary")
    max_load = check_max_load(max_load)
    chains = []
    for p in amps:
        try:
            chains.append(m if p == 0.0 else chain_at(m, dp, float(p)))
        except InvalidParameterError as exc:
            raise InvalidParameterError(f"amplitude {p:g} gives no valid chain: {exc}", field="amplitudes") from None
    A = amps.size
    results: list[LimitLoad | None] = [None] * A
    statuses, messages = [_NOT_COMPUTED] * A, ["the time limit ran out before this amplitude"] * A
    perfect, d = None, None
    timed_out = False
    with time_limit(timeout):
        for i in [-1, *range(A)]:          # the perfect chain first (amplitude 0, reused where it is asked)
            if i >= 0 and amps[i] == 0.0 and perfect is not None:
                results[i], statuses[i], messages[i] = perfect, perfect.status, perfect.message
                continue
            if expired():
                timed_out = True
                break
            try:
                r = limit_load(m if i < 0 else chains[i], direction, boundary, max_load, max_points=max_points)
            except TimeLimitError:
                timed_out = True
                break
            except InvalidParameterError:
                if i < 0:
                    raise                # a bad direction: the caller's
                statuses[i], messages[i] = _FAILED, "the imperfect chain's path could not be started"
                continue
            except TensegrityError as exc:
                if i < 0:
                    continue             # the curve stands without the perfect chain's limit
                statuses[i], messages[i] = _FAILED, str(exc)
                continue
            d = r.direction
            if i < 0:
                perfect = r
                continue
            results[i], statuses[i], messages[i] = r, r.status, r.message
            if _unlocated_loss(r):
                messages[i] = (f"{r.message}; but the path has unstable points: stability was lost where no limit "
                               "point was located (kind unknown)")
            if r.status == "time_limit":
                timed_out = True
                break
    kinds = tuple(_kind(r) if r is not None else "unknown" for r in results)
    loads = np.array([_load(r) if r is not None else math.nan for r in results])
    if d is None:
        v = np.asarray(direction, dtype=float)
        d = v / np.linalg.norm(v) if v.shape == (2,) and np.linalg.norm(v) > 0 else np.array([-1.0, 0.0])
    bifurcation = None if timed_out else _bifurcation(perfect)
    e, c, used = _law(amps, loads, kinds, perfect, bifurcation)
    done = sum(r is not None for r in results)
    cut = [i for i in range(A) if statuses[i] != _NOT_COMPUTED and (results[i] is None or not results[i].success
                                                                     or kinds[i] == "unknown")]
    if timed_out and done < A or any(s == "time_limit" for s in statuses):
        status = "time_limit"
        message = f"the time limit ran out: {done} of {A} amplitudes computed"
    elif cut:
        status = "partial"
        message = (f"{len(cut)} of {A} amplitudes of unknown kind: their paths were cut, could not be followed or "
                   f"lost stability at no located limit point (amplitudes {', '.join(f'{amps[i]:g}' for i in cut)})")
    else:
        status = "complete"
        counts = {k: kinds.count(k) for k in KINDS if k in kinds}
        message = f"{A} amplitudes: " + ", ".join(f"{v} {k}" for k, v in counts.items())
    if e is not None:
        message += f"; small-imperfection law ({bifurcation.replace('_', '-')}): drop ~ {c:.4g} |p|^{e:.3f}"
    return ImperfectionSensitivity(status, message, amps, loads, kinds, tuple(statuses), tuple(messages),
                                   tuple(results), perfect, e, c, used, bifurcation, name, dp, d, boundary,
                                   max_load)
