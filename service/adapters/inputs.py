"""Requests as library arguments: chains, segments, grids, controls, starts.

Every function takes validated request models (``service.schemas``; read only) or their plain parts and
returns what the library takes. A chain description becomes a hashable key of plain numbers
(:func:`manipulator_key`: cheap to send to a solver process) and the key its cached, immutable
:class:`tensegrity_opt.Manipulator` (:func:`manipulator`).
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any

import numpy as np

import tensegrity_opt as to

from .. import schemas as s

__all__ = ["pair", "segment_count", "manipulator_form", "build_segment", "manipulator_key", "manipulator",
           "build_manipulator", "optional_array", "number_or_array", "values", "build_control", "control_kwargs",
           "branch_start", "equilibrium_args", "bounded_search_may_settle", "modes_pose", "PRELOAD_OBJECTIVES"]

#: A preloads request's ``objective`` -> the library's (``"nominal"``: the least change from the chain's own rest
#: lengths, the library's ``"change"``).
PRELOAD_OBJECTIVES = {"nominal": "change", "margin": "margin", "energy": "energy"}


def pair(v: float | list[float]) -> float | tuple[float, float]:
    """A per-spring value: one number, or the two springs' pair."""
    return (float(v[0]), float(v[1])) if isinstance(v, list) else float(v)


def segment_count(m: s.UniformManipulatorIn | s.SegmentedManipulatorIn) -> int:
    return m.n if isinstance(m, s.UniformManipulatorIn) else len(m.segments)


def manipulator_form(m: Any) -> str:
    """``"uniform"`` (``{n, a, b, k, L0}``) or ``"segments"`` (the segments listed)."""
    return "uniform" if isinstance(m, s.UniformManipulatorIn) else "segments"


def build_segment(seg: s.SegmentIn) -> to.Segment:
    return to.Segment(seg.a, seg.b, pair(seg.k), pair(seg.L0), seg.spring, seg.mass, seg.inertia)


def manipulator_key(m: s.UniformManipulatorIn | s.SegmentedManipulatorIn) -> tuple[Any, ...]:
    """A chain description as a hashable tuple of plain numbers (cache key; cheap to send to a process)."""
    loads = (m.payload, None if m.gravity is None else tuple(m.gravity),
             tuple((f.joint, tuple(f.force)) for f in m.joint_forces))
    if isinstance(m, s.UniformManipulatorIn):
        return ("uniform", loads, m.n, m.a, m.b, pair(m.k), pair(m.L0), m.spring, m.mass, m.inertia)
    return ("segments", loads) + tuple((seg.a, seg.b, pair(seg.k), pair(seg.L0), seg.spring, seg.mass,
                                        seg.inertia) for seg in m.segments)


@lru_cache(maxsize=256)
def manipulator(key: tuple[Any, ...]) -> to.Manipulator:
    """The chain of a key, by the library's own reader of the two JSON forms (:meth:`Manipulator.from_dict`);
    the same description gives the same (cached, immutable) object, so its derived arrays, buckling modes and
    seed directions are computed once, not per request."""
    payload, gravity, forces = key[1]
    loads = {"payload": payload, "gravity": gravity, "joint_forces": forces}
    if key[0] == "uniform":
        return to.Manipulator.from_dict({**dict(zip(("n", "a", "b", "k", "L0", "spring", "mass", "inertia"),
                                                     key[2:])), **loads})
    return to.Manipulator.from_dict({"segments": [dict(zip(("a", "b", "k", "L0", "spring", "mass", "inertia"), seg))
                                                  for seg in key[2:]], **loads})


def build_manipulator(m: s.UniformManipulatorIn | s.SegmentedManipulatorIn) -> to.Manipulator:
    """The chain of a request (:func:`manipulator` of its key)."""
    return manipulator(manipulator_key(m))


def modes_pose(req: Any) -> str:
    """How a modes request poses its equilibrium: ``"deflection"`` (dx, dy) or ``"force"`` (fx, fy); one of them,
    not both (``InvalidParameterError`` naming the field)."""
    deflected = req.dx is not None or req.dy is not None
    loaded = req.fx is not None or req.fy is not None
    if deflected and loaded:
        raise to.InvalidParameterError("give a tip deflection (dx, dy) or a tip force (fx, fy), not both",
                                       field="fx" if req.fx is not None else "fy")
    if not deflected and not loaded:
        raise to.InvalidParameterError("give a tip deflection (dx, dy) or a tip force (fx, fy)", field="dx")
    return "deflection" if deflected else "force"


def optional_array(v: Any) -> np.ndarray | None:
    """A list of numbers as an array; ``None`` stays ``None``."""
    return None if v is None else np.asarray(v, dtype=float)


def number_or_array(v: Any) -> Any:
    """One number (a float), or a list of numbers (an array, e.g. one per spring or per joint); ``None`` stays."""
    return None if v is None else (np.asarray(v, dtype=float) if isinstance(v, list) else float(v))


def values(v: Any) -> np.ndarray:
    """The values of a list, or of a range ``{start, stop, num}`` (``numpy.linspace``): deflections, angles,
    grid axes."""
    if isinstance(v, (list, tuple)):
        return np.asarray(v, dtype=float)
    return np.linspace(v.start, v.stop, v.num)


def build_control(c: Any) -> to.Control:
    """The :class:`tensegrity_opt.Control` of a control request (``schemas.ControlIn``)."""
    if c.kind == "displacement":
        return to.Control.displacement(c.direction)
    if c.kind == "load":
        return to.Control.load(c.direction, c.base)
    if c.kind == "guided":
        return to.Control.guided(c.direction, c.base)
    if c.kind == "wall":
        return to.Control.wall(c.normal, c.direction, c.base)
    return to.Control.preload(c.direction, tip=c.tip, load=c.load)


def control_kwargs(c: Any) -> tuple[str, dict[str, Any]]:
    """A control request as the kind and the constructor keywords (the ``control, **control_kw`` of the analyses)."""
    return c.kind, c.model_dump(exclude={"kind"})


def branch_start(m: to.Manipulator, start: Any, control: Any) -> Any:
    """The library's ``start`` of a start request (``schemas.StartIn`` or None: the rest configuration)."""
    if start is None:
        return None
    if isinstance(start, s.StartQ):
        return np.asarray(start.q, dtype=float)
    if not (control.kind == "displacement" or (control.kind == "preload" and control.tip == "held")):
        raise to.InvalidParameterError(
            "a start {dx, dy} (the least-energy equilibrium with the tip held there) needs a control that holds the "
            f"tip (displacement, or preload with tip 'held'); the {control.kind} control starts from joint angles "
            "{q} or the rest configuration (null)", field="start")
    return to.solve_equilibrium(m, start.dx, start.dy)


def equilibrium_args(req: s.EquilibriumRequest) -> tuple[Any, ...]:
    """An equilibrium request as plain numbers (chain key, dx, dy, q0, local, certify): cheap to send to a process."""
    return (manipulator_key(req.manipulator), req.dx, req.dy, None if req.q0 is None else tuple(req.q0), req.local,
            req.certify)


def bounded_search_may_settle(key: tuple[Any, ...], max_segments: int) -> bool:
    """Whether the bounded Newton-only search may settle an equilibrium request of the chain ``key``
    (:func:`manipulator_key`): at most ``max_segments`` segments (decided from the key, the chain is not built)
    and every segment monotonic (bistable ones often give Newton saddles only). Decided by the caller, so
    another request goes straight to the full search instead of a round trip answering "not settled"."""
    if (key[2] if key[0] == "uniform" else len(key) - 2) > max_segments:
        return False
    m = manipulator(key)                    # the chain is cached: the solve reuses it
    return m.monotonic and m.paper_model    # the closed-range search (tension-only, loads) is not a bounded Newton one
