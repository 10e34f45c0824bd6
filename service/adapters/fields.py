"""Library field names as request paths.

A library refusal names the input it refuses in the library's words (``"dx"``, ``"q0"``, ``"segments[2].L0"``,
``"n"``); the answer names it in the request's (``"manipulator.segments[2].L0"``, ``"manipulator.n"``,
``"targets[3].dx"``, ``"start.q"``). :class:`FieldContext` says how for one request; the alias tables below are
the requests whose inputs the library names differently.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

__all__ = ["FieldContext", "request_field", "BRANCH_ALIASES", "LIMIT_LOAD_ALIASES", "JOB_ATLAS_ALIASES",
           "PLAN_ALIASES", "SIMULATION_ALIASES", "LOAD_CAPACITY_ALIASES", "STREAM_ALIASES"]


@dataclass(frozen=True)
class FieldContext:
    """How library field names map onto the request.

    ``manipulator``: ``"uniform"`` or ``"segments"`` (the request's form), or ``None``;
    ``segment``: the request has one ``segment`` (the torque endpoint);
    ``index``: position of the target in a batch;
    ``aliases``: ``(library field, request path)`` pairs of a request whose inputs the library names
    differently (the path endpoints: ``"q0"`` is ``"start.q"``, a control's ``"direction"`` is
    ``"control.direction"``).
    """

    manipulator: str | None = None
    segment: bool = False
    index: int | None = None
    aliases: tuple[tuple[str, str], ...] = ()


#: The branch requests (``/v1/branch``, ``/v1/bifurcation-diagram``, ``/v1/stability-boundary``, their figures).
BRANCH_ALIASES = (("q0", "start.q"), ("dx", "start.dx"), ("dy", "start.dy"), ("direction", "control.direction"),
                  ("base", "control.base"), ("normal", "control.normal"), ("load", "control.load"),
                  ("tip", "control.tip"))
#: The limit-load requests.
LIMIT_LOAD_ALIASES = (("q0", "start.q"),)
#: The atlas of a job (the inputs are the job's stored spec and rows).
JOB_ATLAS_ALIASES = (("analysis", "spec.analysis"), ("grid", "spec.grid"), ("dx", "spec.grid.dx"),
                     ("dy", "spec.grid.dy"), ("targets", "spec.grid"), ("rows", "id"),
                     ("method", "spec.options.method"))
#: Rest-length plans and simulations: the start is given as ``{"q": [...]}``.
PLAN_ALIASES = (("start", "start.q"), ("q0", "start.q"))
SIMULATION_ALIASES = PLAN_ALIASES
#: The load capacity of a pose: the pose is the start.
LOAD_CAPACITY_ALIASES = (("pose", "start.q"), *PLAN_ALIASES)
#: The control stream (the preloads mode's load is one [fx, fy]; the start is the library's q0).
STREAM_ALIASES = (("fx", "load"), ("fy", "load"), ("q0", "start"))

_SEG = re.compile(r"^segments\[(\d+)\](.*)$")
_PARAMS = ("a", "b", "k", "L0")


def request_field(field: str | None, ctx: FieldContext) -> str | None:
    """The request path of a library ``field``."""
    if not field:
        return None
    if field == "eq":
        return None
    for name, path in ctx.aliases:
        if field == name:
            return path
    if ctx.segment and field.split("[")[0] in _PARAMS:
        return f"segment.{field}"
    if field == "n":
        return "manipulator.n" if ctx.manipulator != "segments" else "manipulator.segments"
    if field == "segments" or _SEG.match(field):
        if ctx.manipulator == "uniform":
            m = _SEG.match(field)
            rest = m.group(2) if m else ""
            return "manipulator" + rest if rest else "manipulator"
        return f"manipulator.{field}"
    if field.split("[")[0] in _PARAMS:
        return f"manipulator.{field}"
    if ctx.index is not None and field in ("dx", "dy"):
        return f"targets[{ctx.index}].{field}"
    return field
