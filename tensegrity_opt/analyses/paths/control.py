"""What the continuation parameter moves: :class:`Control`.

A control turns the equilibrium equations of the chain into a one-parameter family ``R(z, t) = 0``
(:mod:`tensegrity_opt.numerics.path_system`): the tip moved along a line (:meth:`Control.displacement`), a
dead tip load ``base + t d`` (:meth:`Control.load`), the paper's guided tip (``y`` held, the load along ``x``,
``Fy`` the reaction: :meth:`Control.guided`), a frictionless wall (:meth:`Control.wall`), rest lengths along
a direction in preload space with the tip free under a load or held (:meth:`Control.preload`,
:meth:`Control.spring`), or rest lengths and the load (or the held tip) together along a segment, ``t`` its
fraction (:meth:`Control.move`). :func:`as_control` builds one from a kind name and keywords.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ...checks import real_array
from ...errors import InvalidParameterError
from ...model.manipulator import Manipulator
from ...serialize import numbers

__all__ = ["Control", "as_control", "checked_vector", "KINDS"]

#: The kinds of :class:`Control` (the names of its constructors).
KINDS = ("displacement", "load", "guided", "wall", "preload", "move")


def _unit(v, field: str, size: int | None = None) -> np.ndarray:
    try:
        d = np.asarray(v, dtype=float).ravel()
    except (TypeError, ValueError):
        raise InvalidParameterError(f"{field} must be a vector of numbers, got {v!r}", field=field) from None
    if size is not None and d.size != size:
        raise InvalidParameterError(f"{field} must have {size} components, got {d.size}", field=field)
    if not np.all(np.isfinite(d)):
        raise InvalidParameterError(f"{field} must be finite, got {v!r}", field=field)
    norm = float(np.linalg.norm(d))
    if norm == 0.0:
        raise InvalidParameterError(f"{field} must not be zero", field=field)
    return d / norm


def checked_vector(v, size: int, name: str) -> np.ndarray:
    """``size`` finite numbers (a target, a load, a direction), flattened, checked (``field=name``)."""
    a = real_array(v, name).ravel()
    if a.size != size or not np.all(np.isfinite(a)):
        raise InvalidParameterError(f"{name} must be {size} finite numbers, got {v!r}", field=name)
    return a


@dataclass(frozen=True)
class Control:
    """What the continuation parameter ``t`` moves (``t = 0`` at the start point).

    Build it with a constructor: :meth:`displacement`, :meth:`load`, :meth:`guided`, :meth:`wall`,
    :meth:`preload`, :meth:`move`. Directions are normalised: ``t`` is the distance moved (length units
    for the tip and the rest lengths, force units for a load); for :meth:`move` (rest lengths and the
    load or the held tip together) ``t`` is the fraction of the move.
    """

    kind: str
    direction: np.ndarray
    base: np.ndarray = field(default_factory=lambda: np.zeros(2))
    normal: np.ndarray | None = None
    tip: str = "free"

    def __post_init__(self) -> None:
        for name in ("direction", "base", "normal"):         # read-only arrays (a private copy of the caller's)
            v = getattr(self, name)
            if v is not None and v.flags.writeable:
                v = v.copy()
                v.setflags(write=False)
                object.__setattr__(self, name, v)

    @classmethod
    def displacement(cls, direction=(1.0, 0.0)) -> "Control":
        """The tip moved along a line: the deflection ``(dx, dy)`` is the start's plus ``t`` times the
        unit ``direction`` (``dx > 0`` shortens the chain); ``F`` is the force holding it."""
        return cls("displacement", _unit(direction, "direction", 2))

    @classmethod
    def load(cls, direction=(-1.0, 0.0), base=(0.0, 0.0)) -> "Control":
        """A dead tip load ``F = base + t d`` (``d`` the unit ``direction``; ``(-1, 0)`` compresses),
        the tip free."""
        return cls("load", _unit(direction, "direction", 2), checked_vector(base, 2, "base"))

    @classmethod
    def guided(cls, direction=(-1.0, 0.0), base=(0.0, 0.0)) -> "Control":
        """The paper's guided tip: ``y`` held at the start's value, ``Fx = base_x + t d_x`` (``d`` the unit
        ``direction``), ``Fy`` the reaction of the guide. A wall of normal ``(0, 1)``."""
        d = _unit(direction, "direction", 2)
        if abs(d[0]) < 1e-12:
            raise InvalidParameterError("a guided load needs an x component (the guide takes y)", field="direction")
        return cls("guided", d, checked_vector(base, 2, "base"), np.array([0.0, 1.0]))

    @classmethod
    def wall(cls, normal=(0.0, 1.0), direction=(-1.0, 0.0), base=(0.0, 0.0)) -> "Control":
        """A frictionless wall through the start's tip: the tip slides along it (held along the unit
        ``normal``), the load along the wall is ``tau . (base + t d)`` (``tau`` the wall's tangent), the
        wall's reaction along the normal is part of ``F``."""
        nu = _unit(normal, "normal", 2)
        d = _unit(direction, "direction", 2)
        if abs(nu[1] * d[0] - nu[0] * d[1]) < 1e-12:
            raise InvalidParameterError("the load must have a component along the wall", field="direction")
        return cls("wall", d, checked_vector(base, 2, "base"), nu)

    @classmethod
    def preload(cls, direction, tip: str = "free", load=(0.0, 0.0)) -> "Control":
        """Rest lengths moved along a unit ``direction`` of ``2n`` numbers (``L1_0, L2_0`` of segment 1,
        then of segment 2, ...): ``t`` is the distance in rest-length space. ``tip="free"``: under the
        fixed tip ``load``; ``"held"``: the tip held where the start has it (``F`` the holding force)."""
        if tip not in ("free", "held"):
            raise InvalidParameterError(f"tip must be 'free' or 'held', got {tip!r}", field="tip")
        return cls("preload", _unit(direction, "direction"), checked_vector(load, 2, "load"), None, tip)

    @classmethod
    def move(cls, n: int, *, preload=None, load=None, displacement=None, tip: str = "free",
             base=(0.0, 0.0)) -> "Control":
        """Every input moved at once along a straight segment, ``t`` the fraction of the move (0 at the
        start, 1 at its end; not normalised, unlike the other controls).

        ``preload`` (``(n, 2)`` or ``2n`` numbers, default none): the change of the rest lengths
        ``(L1_0, L2_0)`` of each segment over the whole move. ``tip="free"``: the dead tip load is
        ``F = base + t load`` (``load`` its change, default none). ``tip="held"``: the tip deflection
        ``(dx, dy)`` is the start's plus ``t displacement`` (``dx > 0`` shortens), ``F`` the holding force.
        A combined preload and load (or tip) move in one parameter, as the quasi-static simulation
        (:func:`~tensegrity_opt.analyses.paths.simulation.simulate`) needs between two samples of its inputs.
        """
        if tip not in ("free", "held"):
            raise InvalidParameterError(f"tip must be 'free' or 'held', got {tip!r}", field="tip")
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 1:
            raise InvalidParameterError(f"n must be an integer >= 1, got {n!r}", field="n")
        dl = np.zeros(2 * int(n)) if preload is None else checked_vector(preload, 2 * int(n), "preload")
        if tip == "free":
            if displacement is not None:
                raise InvalidParameterError("a free tip takes a load change, not a displacement",
                                            field="displacement")
            last = np.zeros(2) if load is None else checked_vector(load, 2, "load")
        else:
            if load is not None:
                raise InvalidParameterError("a held tip takes a displacement, not a load change", field="load")
            last = np.zeros(2) if displacement is None else checked_vector(displacement, 2, "displacement")
        d = np.concatenate([dl, last])
        if not np.any(d != 0.0):
            raise InvalidParameterError("the move must change at least one input", field="preload")
        return cls("move", d, checked_vector(base, 2, "base") if tip == "free" else np.zeros(2), None, tip)

    @classmethod
    def spring(cls, n: int, segment: int, spring: int = 1, *, tip: str = "free", load=(0.0, 0.0)) -> "Control":
        """One spring's rest length (``segment`` 0-based, ``spring`` 1 or 2) as the parameter."""
        if not (0 <= int(segment) < n):
            raise InvalidParameterError(f"segment must be in 0..{n - 1}, got {segment!r}", field="segment")
        if spring not in (1, 2):
            raise InvalidParameterError(f"spring must be 1 or 2, got {spring!r}", field="spring")
        d = np.zeros(2 * n)
        d[2 * int(segment) + spring - 1] = 1.0
        return cls.preload(d, tip=tip, load=load)

    @property
    def preload_direction(self) -> np.ndarray | None:
        """The rest lengths' change per unit ``t``, ``(n, 2)`` (``L1_0, L2_0`` per segment): a preload's
        direction, a move's preload part; None for the other kinds."""
        if self.kind == "preload":
            return self.direction.reshape(-1, 2)
        if self.kind == "move":
            return self.direction[:-2].reshape(-1, 2)
        return None

    @property
    def tip_direction(self) -> np.ndarray | None:
        """What ``t`` moves at the tip per unit ``t`` (2 numbers): the displacement's or the load's direction, a
        move's load change (free tip) or displacement (held tip); None for a preload control."""
        if self.kind == "preload":
            return None
        return self.direction[-2:] if self.kind == "move" else self.direction

    def to_dict(self) -> dict[str, Any]:
        """JSON form (a branch's ``control``): ``kind`` and the constructor's arguments."""
        if self.kind == "move":
            d = {"kind": "move", "tip": self.tip, "preload": [numbers(r) for r in self.preload_direction]}
            if self.tip == "free":
                d["load"], d["base"] = numbers(self.tip_direction), numbers(self.base)
            else:
                d["displacement"] = numbers(self.tip_direction)
            return d
        d = {"kind": self.kind, "direction": numbers(self.direction)}
        if self.kind != "displacement":
            d["load" if self.kind == "preload" else "base"] = numbers(self.base)
        if self.normal is not None and self.kind == "wall":
            d["normal"] = numbers(self.normal)
        if self.kind == "preload":
            d["tip"] = self.tip
        return d

    @property
    def held(self) -> tuple[bool, bool]:
        """Which of the two control rows hold the tip (the rest prescribe a force)."""
        if self.kind == "displacement" or (self.kind in ("preload", "move") and self.tip == "held"):
            return (True, True)
        if self.kind in ("guided", "wall"):
            return (True, False)
        return (False, False)


def as_control(m: Manipulator, control, kw: dict) -> Control:
    """A :class:`Control` from itself or a kind name with the constructor's keywords."""
    if isinstance(control, Control):
        if kw:
            raise InvalidParameterError(f"unexpected keyword(s) {sorted(kw)} with a Control object",
                                        field=sorted(kw)[0])
        if control.kind == "preload" and control.direction.size != 2 * m.n:
            raise InvalidParameterError(f"a preload direction has 2n = {2 * m.n} components, got "
                                        f"{control.direction.size}", field="direction")
        if control.kind == "move" and control.direction.size != 2 * m.n + 2:
            raise InvalidParameterError(f"a move has 2n + 2 = {2 * m.n + 2} components, got "
                                        f"{control.direction.size}", field="preload")
        return control
    if control not in KINDS:
        raise InvalidParameterError(f"control must be a Control or one of {KINDS}, got {control!r}", field="control")
    if control == "move":
        kw = {"n": m.n, **kw}
    try:
        c = getattr(Control, control)(**kw)
    except TypeError as e:
        raise InvalidParameterError(f"bad arguments for the {control} control: {e}", field="control") from None
    return as_control(m, c, {})

