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

from ...analyses.paths.atlas import AtlasTarget, StabilityAtlas, assemble_atlas
from ...analyses.equilibria.equilibrium import make_equilibrium
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
    at = assemble_atlas(m, targets, edges=edges, timeout=left)
    if any(t.error and t.error.startswith("time_limit") for t in targets):
        at.status = "time_limit"
    return at


def _target(m, row: Mapping[str, Any], method: str) -> AtlasTarget:
    t = AtlasTarget(float(row["dx"]), float(row["dy"]), method=method)
    if row.get("error"):
        t.error = str(row["error"])
        return t
    t.reachable = bool(row["reachable"])
    t.count, t.n_stable = int(row["count"]), int(row["n_stable"])
    t.n_saddle, t.n_maximum = int(row["n_saddle"]), int(row["n_maximum"])
    t.least_energy, t.least_signs, t.tie = row["least_energy"], row["least_signs"], bool(row["tie"])
    t.certified, t.method = bool(row["certified"]), str(row["method"])
    Q = np.asarray(row["stable_q"] or [], dtype=float).reshape(-1, m.n)
    target = m.target(t.dx, t.dy)
    mdl = chain_solver(m)
    for q in Q:
        res = mdl.newton_kkt(target, q)
        if not res.success:
            t.error = f"solver_failed: stored equilibrium {np.round(q, 6).tolist()} did not re-solve ({res.status})"
            t.stable = []
            return t
        t.stable.append(make_equilibrium(m, res, constrained=True))
    return t
