"""The critical-load map: the buckling analysis swept over a grid of two design parameters of a chain.

:func:`critical_load_map` sets two of a segment's parameters (``a``, ``b``, ``k``, ``L0``) to every pair of
grid values in every segment of the chain, computes the critical load ``P = -Fx0`` of each design
(:func:`~tensegrity_opt.critical_force`), and returns the grid as a :class:`CriticalLoadMap`, the result the
figure :func:`~tensegrity_opt.applications.plots.plot_map` draws. Unlike :func:`~.scheduler.sweep` (rows of a
uniform base chain, serial or on Dask), it keeps any chain's other parameters (a heterogeneous or pre-bent chain
included) and answers a typed grid.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from ...analyses.equilibria.buckling import critical_force
from ...errors import InvalidParameterError, TensegrityError
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...outcome import Outcome, freeze
from ...serialize import nullables, numbers
from .spec import DESIGN_VARIABLES

__all__ = ["CriticalLoadMap", "critical_load_map"]


@dataclass(frozen=True)
class CriticalLoadMap(Outcome):
    """The critical load of a chain over a grid of two design parameters.

    Attributes
    ----------
    param_x, param_y : str
        The two parameters varied (two of ``a``, ``b``, ``k``, ``L0``; ``k`` and ``L0`` set both springs).
    values_x, values_y : ndarray
        Their values (strictly monotonic, > 0).
    load : ndarray (len(values_y), len(values_x))
        ``load[iy, ix] = -critical_force(m').force`` for the chain ``m'`` whose every segment has
        ``param_x = values_x[ix]`` and ``param_y = values_y[iy]``; NaN where ``critical_force`` refused the
        design (the straight chain unstable or not an equilibrium there, or its eigen-solve failed).
    boundary : str
        ``"guided"`` or ``"free"``: the tip condition of the buckling analysis.
    status : str
        :attr:`STATUSES` (derived from :attr:`load`).
    message : str
        The same in a sentence, with the counts.
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "complete": "every design of the grid has its critical load",
        "partial": "some designs have no critical load (blank: the straight chain is unstable or not an "
                   "equilibrium there)",
        "empty": "no design of the grid has a critical load",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"complete", "partial"})

    param_x: str
    values_x: np.ndarray
    param_y: str
    values_y: np.ndarray
    load: np.ndarray
    boundary: str

    def __post_init__(self) -> None:
        freeze(self)

    @property
    def blank(self) -> int:
        """How many designs have no critical load."""
        return int(np.count_nonzero(~np.isfinite(self.load)))

    @property
    def status(self) -> str:
        """``"complete"``, ``"partial"`` or ``"empty"`` (:attr:`STATUSES`)."""
        if self.blank == 0:
            return "complete"
        return "empty" if self.blank == self.load.size else "partial"

    @property
    def message(self) -> str:
        """A sentence: how many designs have a critical load."""
        total = int(self.load.size)
        if self.status == "complete":
            return f"critical loads of all {total} designs ({self.boundary} tip)"
        why = "the straight chain is unstable or not an equilibrium there"
        if self.status == "empty":
            return f"none of the {total} designs has a critical load ({why})"
        return f"critical loads of {total - self.blank} of {total} designs; {self.blank} blank ({why})"

    def to_dict(self) -> dict[str, Any]:
        """JSON form: ``success``, ``status``, ``message``, ``param_x``, ``values_x``, ``param_y``, ``values_y``,
        ``boundary`` and ``load`` (``[iy][ix]``, ``null`` where a design has no critical load)."""
        return {**self.outcome(), "param_x": self.param_x, "values_x": numbers(self.values_x),
                "param_y": self.param_y, "values_y": numbers(self.values_y), "boundary": self.boundary,
                "load": nullables(self.load)}


def _axis_values(values: Any, field: str) -> np.ndarray:
    v = np.asarray(values, dtype=float).ravel()
    if v.size < 2:
        raise InvalidParameterError(f"{field} needs at least 2 values", field=field)
    if not np.all(np.isfinite(v)) or np.any(v <= 0.0):
        raise InvalidParameterError(f"{field} must be finite and > 0", field=field)
    d = np.diff(v)
    if not (np.all(d > 0) or np.all(d < 0)):
        raise InvalidParameterError(f"{field} must be strictly increasing or strictly decreasing", field=field)
    return v


def critical_load_map(m: Manipulator, param_x: str, values_x: Any, param_y: str, values_y: Any,
                      boundary: str = "guided") -> CriticalLoadMap:
    """The critical load ``P = -Fx0`` of ``m`` with two design parameters swept over a grid.

    Parameters
    ----------
    m : Manipulator
        The chain; its segments keep their other parameters.
    param_x, param_y : str
        Two different parameters of ``a``, ``b``, ``k``, ``L0``, set to the same value in every segment
        (``Segment.replace``; ``k`` and ``L0`` set both springs).
    values_x, values_y : array_like
        At least two values each, finite, > 0, strictly increasing or strictly decreasing.
    boundary : str
        ``"guided"`` (the paper's case, ``n >= 2``) or ``"free"``, as :func:`~tensegrity_opt.critical_force`.

    Returns
    -------
    CriticalLoadMap
        NaN where :func:`~tensegrity_opt.critical_force` raises for a design (a library refusal, an arithmetic
        or linear-algebra failure); any other exception propagates.

    Raises
    ------
    InvalidParameterError
        For a parameter, values or boundary outside the above (``field`` names the argument).
    """
    unloaded_only(m, "critical_load_map")
    for f, p in (("param_x", param_x), ("param_y", param_y)):
        if p not in DESIGN_VARIABLES:
            raise InvalidParameterError(f"{f} must be one of {', '.join(DESIGN_VARIABLES)}, got {p!r}", field=f)
    if param_x == param_y:
        raise InvalidParameterError("param_x and param_y must differ", field="param_y")
    if boundary not in ("guided", "free"):
        raise InvalidParameterError(f"boundary must be 'guided' or 'free', got {boundary!r}", field="boundary")
    if boundary == "guided" and m.n < 2:
        raise InvalidParameterError("a guided tip needs n >= 2 segments", field="n")
    xs = _axis_values(values_x, "values_x")
    ys = _axis_values(values_y, "values_y")
    P = np.full((ys.size, xs.size), np.nan)
    for iy, y in enumerate(ys):
        for ix, x in enumerate(xs):
            mm = m.with_segments([s.replace(**{param_x: float(x), param_y: float(y)}) for s in m.segments])
            try:
                P[iy, ix] = -critical_force(mm, boundary).force
            except (TensegrityError, ArithmeticError, np.linalg.LinAlgError):
                pass
    return CriticalLoadMap(param_x=param_x, values_x=xs, param_y=param_y, values_y=ys, load=P, boundary=boundary)
