"""An atlas sweep's rows as a :class:`~tensegrity_opt.analyses.paths.atlas.StabilityAtlas`.

A sweep (or a job) with ``"analysis": "atlas"`` over a grid in ``dx`` and ``dy`` computes the expensive part,
every equilibrium of every target, point by point (serially, on Dask, resumable in the service's jobs);
:func:`atlas_from_rows` rebuilds the targets from the rows (each stable equilibrium re-solved by Newton from
its stored angles, so the atlas's crossings start from exact points) and analyses the grid's edges
(:func:`tensegrity_opt.analyses.paths.atlas.assemble_atlas`).
"""

from __future__ import annotations

import time
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from ...analyses.equilibria.equilibrium import make_equilibrium
from ...analyses.paths.atlas import AtlasTarget, StabilityAtlas, assemble_atlas
from ...errors import InvalidParameterError
from ...numerics import chain_solver
from ...timelimit import expired, time_limit
from .evaluate import _manipulator
from .spec import validate_spec

__all__ = ["atlas_from_rows"]


def atlas_from_rows(spec: Any, rows: Sequence[Mapping[str, Any]], *, edges: bool = True,
                    timeout: float | None = None) -> StabilityAtlas:
    """The atlas of an ``"atlas"`` sweep over a grid in ``dx`` and ``dy`` (the chain fixed) from its rows.

    Raises
    ------
    InvalidParameterError
        When the spec is not an atlas sweep over ``grid.dx`` x ``grid.dy`` alone, or rows are missing.
    """
    norm = validate_spec(spec)
    if norm["analysis"] != "atlas":
        raise InvalidParameterError(f"not an atlas sweep (analysis {norm['analysis']!r})", field="analysis")
    grid = norm.get("grid")
    if grid is None or set(grid) != {"dx", "dy"}:
        raise InvalidParameterError("an atlas is a grid over exactly dx and dy", field="grid")
    m = _manipulator(norm, {})
    want = len(grid["dx"]) * len(grid["dy"])
    if len(rows) != want:
        raise InvalidParameterError(f"{len(rows)} rows for a grid of {want} targets", field="rows")
    method = norm["options"].get("method", "search")
    t0 = time.perf_counter()
    with time_limit(timeout):
        targets = []
        for r in rows:
            if expired():       # the rest kept as failed targets: the atlas says time_limit
                t = AtlasTarget(float(r["dx"]), float(r["dy"]), method=method,
                                error="time_limit: not re-solved before the time limit")
            else:
                t = _target(m, r, method)
            targets.append(t)
    left = None if timeout is None else max(timeout - (time.perf_counter() - t0), 1e-3)
    return assemble_atlas(m, targets, edges=edges, timeout=left)     # a target not re-solved in time: time_limit


def _target(m, row: Mapping[str, Any], method: str) -> AtlasTarget:
    dx, dy = float(row["dx"]), float(row["dy"])
    if row.get("error"):
        return AtlasTarget(dx, dy, method=method, error=str(row["error"]))
    stored = {"reachable": bool(row["reachable"]), "count": int(row["count"]), "n_stable": int(row["n_stable"]),
              "n_saddle": int(row["n_saddle"]), "n_maximum": int(row["n_maximum"]),
              "least_energy": row["least_energy"], "least_signs": row["least_signs"], "tie": bool(row["tie"]),
              "certified": bool(row["certified"]), "method": str(row["method"])}
    Q = np.asarray(row["stable_q"] or [], dtype=float).reshape(-1, m.n)
    target = m.target(dx, dy)
    mdl = chain_solver(m)
    stable = []
    for q in Q:
        res = mdl.newton_kkt(target, q)
        if not res.success:
            return AtlasTarget(dx, dy, **stored, error=f"solver_failed: stored equilibrium "
                               f"{np.round(q, 6).tolist()} did not re-solve ({res.status})")
        stable.append(make_equilibrium(m, res, constrained=True))
    return AtlasTarget(dx, dy, **stored, stable=tuple(stable))
