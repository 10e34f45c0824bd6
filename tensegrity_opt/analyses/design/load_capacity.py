"""Load capacity: how much more dead tip load a stable pose carries, per direction, before it loses stability.

:func:`load_capacity` follows, for each of a set of directions, the dead-load path ``F = base + t d`` from the
pose (:func:`~tensegrity_opt.analyses.paths.limit_load.limit_load` with its ``base``) to its first fold or
bifurcation: a polar curve of the pose's capacity (:class:`LoadCapacity`). Formulations and measured numbers:
``docs/design.md``, "Stiffness shaping and load capacity".

Example (the straight paper chain under compression: its capacity is its free critical load)::

    >>> import tensegrity_opt as to
    >>> cap = to.load_capacity(to.Manipulator.uniform(4), directions=[3.141592653589793], max_load=1.0)
    >>> cap.status, cap.kinds, round(float(cap.loads[0]), 6)
    ('complete', ('bifurcation',), 0.07612)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from ...errors import InvalidParameterError, TensegrityError, TimeLimitError
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...model.springs import linear_only
from ...outcome import Outcome, freeze
from ...serialize import nullables, number, numbers
from ...timelimit import time_limit as _time_limit
from ..equilibria.equilibrium import Equilibrium, check_q0, solve_equilibrium_under_force
from ..paths.limit_load import DEFAULT_MAX_LOAD, check_max_load, limit_load
from ..paths.loaded_path import loaded_limit, weight_limit

__all__ = ["LoadCapacity", "load_capacity", "WeightCapacity", "weight_capacity"]


@dataclass(frozen=True)
class LoadCapacity(Outcome):
    """Result of :func:`load_capacity`: per direction ``d_i`` (``K`` of them), the largest additional dead tip
    load ``t_i`` along ``d_i`` the pose carries before its equilibrium loses stability.

    Attributes
    ----------
    angles : ndarray (K,)
        The directions' angles ``atan2(d_y, d_x)`` (rad).
    directions : ndarray (K, 2)
        The unit directions.
    loads : ndarray (K,)
        The limit load ``t_i`` (force units; the magnitude of the load added to ``base``), NaN where the path
        does not lose stability (``kinds[i] == "none"``).
    forces : ndarray (K, 2)
        The total tip force at the limit, ``base + t_i d_i`` (guided: ``Fy`` the guide's reaction); NaN rows for
        ``"none"``.
    kinds : tuple of str
        ``"fold"`` (snap-through), ``"bifurcation"`` (a branch point: buckling) or ``"none"``.
    reasons : tuple of (str or None)
        For ``"none"``: ``"joint_limit"`` (a joint reaches its range bound on the stable path), ``"max_load"``
        (stable up to ``max_load``), or why the path could not be followed (``"time_limit"``, the branch's
        status, an error code); None otherwise.
    end_loads : ndarray (K,)
        The last load reached on the stable path (``loads`` where there is a limit).
    q : ndarray (K, n)
        The configuration at the limit (NaN rows for ``"none"``).
    base : ndarray (2,)
        The load the pose is in equilibrium under (``F = base + t d``).
    boundary : str
    max_load : float
        The largest ``t`` followed.
    start : Equilibrium
        The pose (under ``base``).
    manipulator : Manipulator
        The chain (with the pose's rest lengths).
    results : tuple of LimitLoad
        The per-direction results of :func:`~tensegrity_opt.analyses.paths.limit_load.limit_load` (None where it
        failed).
    status : str
        :attr:`STATUSES`, from ``reasons``: ``"complete"``, ``"time_limit"`` or ``"path_failed"``.
    message : str
        The same in a sentence: how many directions end in a fold, a bifurcation, or no limit.
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "complete": "every direction was followed to its first loss of stability, a joint's range bound or "
                    "max_load",
        "time_limit": "the time limit ran out before every direction was followed (reasons: time_limit)",
        "path_failed": "the path of some direction could not be followed (reasons: the branch's status or the "
                       "error's code)",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"complete"})

    angles: np.ndarray
    directions: np.ndarray
    loads: np.ndarray
    forces: np.ndarray
    kinds: tuple[str, ...]
    reasons: tuple[str | None, ...]
    end_loads: np.ndarray
    q: np.ndarray
    base: np.ndarray
    boundary: str
    max_load: float
    start: Equilibrium
    manipulator: Manipulator
    results: tuple = field(repr=False, default=())

    def __post_init__(self) -> None:
        freeze(self)

    @property
    def unfinished(self) -> list[str]:
        """The reasons of the directions not followed to a limit, a joint's range bound or ``max_load``."""
        return [str(r) for k, r in zip(self.kinds, self.reasons)
                if k == "none" and r not in ("joint_limit", "max_load")]

    @property
    def status(self) -> str:
        """``"complete"``, ``"time_limit"`` or ``"path_failed"`` (:attr:`STATUSES`)."""
        failed = self.unfinished
        if not failed:
            return "complete"
        return "time_limit" if "time_limit" in failed else "path_failed"

    @property
    def message(self) -> str:
        """A sentence: what the directions end in."""
        count = {k: sum(1 for x in self.kinds if x == k) for k in ("fold", "bifurcation", "none")}
        text = (f"{len(self.kinds)} directions: {count['fold']} fold(s), {count['bifurcation']} bifurcation(s), "
                f"{count['none']} without a limit")
        failed = self.unfinished
        if failed:
            text += f"; {len(failed)} not followed to the end ({', '.join(sorted(set(failed)))})"
        return text

    @property
    def weakest(self) -> tuple[float, float] | None:
        """``(angle, load)`` of the smallest limit load over the directions (None when no direction has one)."""
        ok = np.isfinite(self.loads)
        if not ok.any():
            return None
        i = int(np.nanargmin(np.where(ok, self.loads, np.nan)))
        return float(self.angles[i]), float(self.loads[i])

    def to_dict(self) -> dict[str, Any]:
        """JSON form: ``success``, ``status``, ``message``, ``angles``, ``directions``, ``loads`` and ``forces``
        (null where ``kind`` is none), ``kinds``, ``reasons``, ``end_loads``, ``base``, ``boundary``, ``max_load``,
        ``weakest`` (``{angle, load}`` or null), ``start``, ``manipulator``."""
        wk = self.weakest
        return {**self.outcome(), "angles": numbers(self.angles), "directions": numbers(self.directions),
                "loads": nullables(self.loads), "forces": nullables(self.forces), "kinds": list(self.kinds),
                "reasons": list(self.reasons), "end_loads": numbers(self.end_loads), "base": numbers(self.base),
                "boundary": self.boundary, "max_load": number(self.max_load),
                "weakest": None if wk is None else {"angle": wk[0], "load": wk[1]},
                "start": self.start.to_dict(), "manipulator": self.manipulator.to_dict()}


def _directions(directions, boundary: str) -> np.ndarray:
    if isinstance(directions, (int, np.integer)) and not isinstance(directions, bool):
        if directions < 1:
            raise InvalidParameterError(f"directions must be >= 1, got {directions}", field="directions")
        ang = 2.0 * math.pi * np.arange(int(directions)) / int(directions)
        D = np.column_stack([np.cos(ang), np.sin(ang)])
        D[np.abs(D) < 1e-15] = 0.0                  # cos(pi / 2) is 6e-17: make the axes exact
    else:
        try:
            arr = np.asarray(directions, dtype=float)
        except (TypeError, ValueError):
            raise InvalidParameterError("directions must be a count, a list of angles (rad) or of (dx, dy) vectors",
                                        field="directions") from None
        if arr.ndim == 1 and arr.size >= 1:
            D = np.column_stack([np.cos(arr), np.sin(arr)])
        elif arr.ndim == 2 and arr.shape[1] == 2 and arr.shape[0] >= 1:
            D = arr.copy()
        else:
            raise InvalidParameterError(f"directions must be a count, a list of angles (rad) or a (K, 2) array of "
                                        f"vectors, got shape {arr.shape}", field="directions")
        if not np.all(np.isfinite(D)):
            raise InvalidParameterError("directions must be finite", field="directions")
        nrm = np.linalg.norm(D, axis=1)
        if np.any(nrm == 0.0):
            raise InvalidParameterError("a direction vector is zero", field="directions")
        D = D / nrm[:, None]
    if boundary == "guided":
        bad = np.flatnonzero(np.abs(D[:, 0]) < 1e-12)
        if bad.size:
            raise InvalidParameterError(f"a guided tip takes loads with an x component (the guide takes y); direction "
                                        f"{int(bad[0])} is {D[bad[0]].tolist()}", field="directions")
    return D


def _pose(m: Manipulator, pose, base):
    """``(chain, start q or None, base)`` from :func:`load_capacity`'s ``pose``."""
    if pose is None:
        return m, None, base
    if isinstance(pose, Equilibrium):
        return m, pose.q, (pose.force.copy() if base is None else base)
    if hasattr(pose, "manipulator") and isinstance(getattr(pose, "equilibrium", None), Equilibrium):
        mm = pose.manipulator
        if not isinstance(mm, Manipulator) or mm.n != m.n:
            raise InvalidParameterError("pose's manipulator does not match m", field="pose")
        return mm, pose.equilibrium.q, (pose.equilibrium.force.copy() if base is None else base)
    try:
        arr = np.asarray(pose, dtype=float)
    except (TypeError, ValueError):
        raise InvalidParameterError("pose must be None, an Equilibrium, a design result, n joint angles or (n, 2) "
                                    "rest lengths", field="pose") from None
    if arr.shape == (m.n, 2):
        if not np.all(np.isfinite(arr)) or np.any(arr <= 0):
            raise InvalidParameterError("rest lengths must be finite and > 0", field="pose")
        mm = m.with_segments(s.replace(L0=(float(l1), float(l2))) for s, (l1, l2) in zip(m.segments, arr))
        return mm, None, base
    if arr.shape == (m.n,):
        try:
            q = check_q0(m, arr)
        except InvalidParameterError as exc:
            raise InvalidParameterError(exc.message, field="pose") from None
        return m, q, base
    raise InvalidParameterError(f"pose must be None, an Equilibrium, a design result, {m.n} joint angles or "
                                f"({m.n}, 2) rest lengths; got shape {arr.shape}", field="pose")


def load_capacity(m: Manipulator, pose=None, *, base=None, directions=36, boundary: str = "free",
                  max_load: float | None = None, max_points: int = 4000,
                  timeout: float | None = None) -> LoadCapacity:
    """The largest additional dead tip load, in each direction, that a stable pose carries before it loses
    stability: a polar curve of the pose's load capacity.

    For each unit direction ``d`` the dead-load path ``F = base + t d`` (``t >= 0``) is followed from the pose by
    arclength continuation until the equilibrium first loses stability — a fold (the arm snaps through) or a
    bifurcation (it buckles) — with :func:`~tensegrity_opt.analyses.paths.limit_load.limit_load` (``start`` the pose,
    ``base`` its load). Where the path stays stable up to a joint's range bound or ``max_load``, there is no
    limit (``kind "none"``, ``loads`` NaN, ``reasons`` says which).

    A chain with dead loads (``gravity`` on its masses, ``joint_forces``) is followed from its sagged pose (the
    least-potential rest configuration under the loads by default) by :func:`~..paths.loaded_path.loaded_limit`
    (Newton along the load under the loads; ``results`` None): the extra tip load along the gravity direction it
    carries is the payload it carries, ``loads / |g|`` (free tip only).

    Parameters
    ----------
    m : Manipulator
    pose : optional
        The stable pose: None (the least-energy rest configuration of ``m``; with a non-zero ``base`` the
        equilibrium under it), an :class:`Equilibrium` (its ``q``; ``base`` defaults to its force), a design result
        with ``manipulator`` and ``equilibrium``
        (:class:`~tensegrity_opt.analyses.design.stiffness_shaping.StiffnessDesign`,
        :class:`~tensegrity_opt.analyses.design.preloads.PreloadDesign`: that chain, that pose, its load), ``n``
        joint angles (put on the equilibrium under ``base`` by Newton), or ``(n, 2)`` rest lengths (``m`` with
        them, at its least-energy rest configuration or the equilibrium under ``base``).
    base : (float, float), optional
        The dead tip load the pose is in equilibrium under (default: the pose's own load, else zero).
    directions : int or sequence
        ``K``: the angles ``2 pi i / K``; or a list of angles (rad); or a ``(K, 2)`` array of vectors.
    boundary : {"free", "guided"}
        As :func:`~tensegrity_opt.analyses.paths.limit_load.limit_load` (guided: only directions with an x component).
    max_load : float, optional
        Follow ``t`` at most this far (default ``DEFAULT_MAX_LOAD`` force units ``k c^2 / (2 b)``).
    max_points : int
        Continuation points per direction at most.
    timeout : float, optional
        Seconds for the whole call; directions not finished in time have ``reasons "time_limit"``.

    Returns
    -------
    LoadCapacity

    Raises
    ------
    InvalidParameterError
        (``ValueError``) bad arguments (``field`` names one), or a pose that is not a stable equilibrium under
        ``base`` (``field="pose"``).
    """
    linear_only(m, "load_capacity")
    if boundary not in ("free", "guided"):
        raise InvalidParameterError(f"boundary must be 'free' or 'guided', got {boundary!r}", field="boundary")
    if m.loaded and boundary != "free":
        unloaded_only(m, "load_capacity (boundary='guided')")
    D = _directions(directions, boundary)
    if base is not None:
        try:
            base = np.asarray(base, dtype=float)
        except (TypeError, ValueError):
            raise InvalidParameterError("base must be two finite numbers (fx, fy)", field="base") from None
        if base.shape != (2,) or not np.all(np.isfinite(base)):
            raise InvalidParameterError("base must be two finite numbers (fx, fy)", field="base")
    mm, q0, base = _pose(m, pose, base)
    base = np.zeros(2) if base is None else np.asarray(base, dtype=float)
    max_load = check_max_load(max_load)
    if max_load is None:
        max_load = DEFAULT_MAX_LOAD * mm.torque_scale / (mm.straight_length / mm.n)
    with _time_limit(timeout):
        start = _start_equilibrium(mm, q0, base)
        K = D.shape[0]
        loads, end_loads = np.full(K, np.nan), np.zeros(K)
        forces, qs = np.full((K, 2), np.nan), np.full((K, mm.n), np.nan)
        kinds, reasons, results = [], [], []
        for i, d in enumerate(D):
            if mm.loaded:                       # from the sagged pose, Newton under the loads (loaded_path)
                try:
                    lim = loaded_limit(mm, start, base, d, max_load)
                except TimeLimitError:
                    kinds.append("none")
                    reasons.append("time_limit")
                    results.append(None)
                    continue
                kinds.append(lim.kind)
                reasons.append(lim.reason)
                results.append(None)
                end_loads[i] = lim.end_load
                if lim.kind != "none":
                    loads[i], forces[i], qs[i] = lim.load, base + lim.load * d, lim.q
                continue
            try:
                r = limit_load(mm, d, boundary, max_load, start, base=base, max_points=max_points)
            except TimeLimitError:
                r = None
                kinds.append("none")
                reasons.append("time_limit")
            except InvalidParameterError as exc:
                if exc.field == "start":             # the same pose for every direction: refuse it
                    raise InvalidParameterError(exc.message, field="pose") from None
                raise
            except TensegrityError as exc:
                r = None
                kinds.append("none")
                reasons.append(exc.code)
            results.append(r)
            if r is None:
                continue
            kinds.append(r.kind)
            reasons.append(None if r.kind != "none" else r.status)
            end_loads[i] = r.end_load
            if r.kind != "none":
                loads[i] = r.load
                forces[i] = r.force
                qs[i] = r.q
    return LoadCapacity(angles=np.arctan2(D[:, 1], D[:, 0]), directions=D, loads=loads, forces=forces,
                        kinds=kinds, reasons=reasons, end_loads=end_loads, q=qs, base=base.copy(),
                        boundary=boundary, max_load=float(max_load), start=start, manipulator=mm, results=results)


def _start_equilibrium(m: Manipulator, q0, base: np.ndarray) -> Equilibrium:
    """The pose as an equilibrium under ``base``: from ``q0`` (it must be one: Newton moves it by < 1e-3 rad),
    else the least-energy rest configuration (zero ``base``) or the equilibrium under ``base``."""
    if q0 is None:
        if not np.any(base != 0.0):
            from ..equilibria.rest import rest_configuration

            return rest_configuration(m)
        return solve_equilibrium_under_force(m, base[0], base[1])
    eq = solve_equilibrium_under_force(m, base[0], base[1], q0=q0)
    moved = float(np.abs(eq.q - q0).max())
    if moved > 1e-3:
        raise InvalidParameterError(f"pose is not (near) an equilibrium under the base load {base.tolist()}: Newton "
                                    f"moved it by {moved:.3g} rad", field="pose")
    return eq


# ---------------------------------------------------------------------------- how much heavier
@dataclass(frozen=True)
class WeightCapacity(Outcome):
    """Result of :func:`weight_capacity`: by how much the chain's weights may grow before its rest pose loses
    stability.

    Attributes
    ----------
    factor : float
        The multiple of ``gravity`` (the segments' and the payload's weights together) at which the pose first loses
        stability (NaN for ``kind`` none).
    kind : str
        ``"fold"`` (the arm snaps), ``"bifurcation"`` (it buckles) or ``"none"``.
    reason : str or None
        For none: ``"joint_limit"`` (a joint reaches its range bound on the stable path) or ``"max_factor"``.
    end_factor : float
        The last multiple on the stable path (``factor`` where there is a limit).
    q : ndarray (n,)
        The configuration there.
    max_factor : float
    start : Equilibrium
        The pose (the rest configuration under the chain's loads, or the given one).
    status : str
        ``"complete"``: the path was followed to its first loss of stability, a joint's range bound or ``max_factor``.
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "complete": "the path of growing weights was followed to its first loss of stability, a joint's range bound "
                    "or max_factor",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset(STATUSES)

    factor: float
    kind: str
    reason: str | None
    end_factor: float
    q: np.ndarray
    max_factor: float
    start: Equilibrium
    status: str = "complete"

    def __post_init__(self) -> None:
        freeze(self)

    @property
    def message(self) -> str:
        if self.kind == "none":
            why = "a joint reaches its range bound" if self.reason == "joint_limit" else "max_factor"
            return f"no loss of stability up to {self.end_factor:.6g} times the weights ({why})"
        what = "snaps (a fold)" if self.kind == "fold" else "buckles (a bifurcation)"
        return f"the rest pose {what} when the weights are {self.factor:.6g} times theirs"

    def to_dict(self) -> dict[str, Any]:
        """JSON form: ``success``, ``status``, ``message``, ``factor`` (null for none), ``kind``, ``reason``,
        ``end_factor``, ``q``, ``max_factor``, ``start``."""
        return {**self.outcome(), "factor": nullables(np.array([self.factor]))[0], "kind": self.kind,
                "reason": self.reason, "end_factor": number(self.end_factor), "q": numbers(self.q),
                "max_factor": number(self.max_factor), "start": self.start.to_dict()}


def weight_capacity(m: Manipulator, pose=None, *, max_factor: float = 10.0,
                    timeout: float | None = None) -> WeightCapacity:
    """By how much the chain's weights (``gravity`` on its masses and payload, the joint forces held) may grow
    before its rest pose loses stability: the rest configuration followed as gravity is scaled from 1 to
    ``max_factor`` (:func:`~..paths.loaded_path.weight_limit`: tangent predictor, Newton corrector under the loads,
    a fold or a bifurcation located to 1e-9 of the range).

    Parameters
    ----------
    m : Manipulator
        A chain with ``gravity`` and some mass.
    pose : optional
        The stable pose: None (the least-potential rest configuration), an :class:`Equilibrium` or ``n`` joint angles
        (the equilibrium with the tip free reached from them).
    max_factor : float
        Follow up to this multiple of gravity (> 1).
    timeout : float, optional
        Seconds.

    Raises
    ------
    InvalidParameterError
        ``field="gravity"`` when the chain carries no weight; ``max_factor`` not > 1; a pose that is not a stable
        equilibrium (``field="pose"``).
    UnsupportedError
        A tension-only chain (``field="segments[i].spring"``).
    """
    linear_only(m, "weight_capacity")
    if m.gravity is None or not np.any(Manipulator(m.segments, m.payload, m.gravity).link_loads != 0.0):
        raise InvalidParameterError("the chain carries no weight: give it gravity and a mass (Segment(..., mass=)) "
                                    "or a payload", field="gravity")
    try:
        top = float(max_factor)
    except (TypeError, ValueError):
        raise InvalidParameterError(f"max_factor must be a number > 1, got {max_factor!r}",
                                    field="max_factor") from None
    if not (math.isfinite(top) and top > 1.0):
        raise InvalidParameterError(f"max_factor must be a finite number > 1, got {max_factor!r}", field="max_factor")
    with _time_limit(timeout):
        if pose is None:
            from ..equilibria.rest import rest_configuration

            start = rest_configuration(m)
        else:
            q0 = pose.q if isinstance(pose, Equilibrium) else check_q0(m, pose, closed=True)
            start = solve_equilibrium_under_force(m, 0.0, 0.0, q0=q0)
            if not start.stable or float(np.abs(start.q - np.asarray(q0, float)).max()) > 1e-3:
                raise InvalidParameterError("the pose is not a stable equilibrium of the chain under its loads",
                                            field="pose")
        lim = weight_limit(m, start, np.zeros(2), top)
    reason = None if lim.kind != "none" else ("max_factor" if lim.reason == "max_load" else lim.reason)
    return WeightCapacity(factor=1.0 + lim.load if lim.kind != "none" else float("nan"), kind=lim.kind,
                          reason=reason, end_factor=1.0 + lim.end_load, q=np.asarray(lim.q, float).copy(),
                          max_factor=top, start=start)
