"""One point of a sweep: the library call of its analysis and its row (parameters, results, error).

The result columns are read from the analysis's result object (:class:`Buckling`,
:class:`Equilibrium`, :class:`EquilibriumSet`, :class:`Design`); they are table cells that
may be empty (``None`` where a value does not exist), so a non-finite value becomes ``None``
(:func:`tensegrity_opt.serialize.nullable`, the policy's rule for nullable fields) rather than
an error. A point that raises gets an error row and never stops the sweep.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from ...analyses.design.strongest import maximize_critical_force
from ...analyses.equilibria.all_equilibria import find_equilibria
from ...analyses.equilibria.buckling import critical_force
from ...analyses.equilibria.equilibrium import solve_equilibrium_under_force
from ...analyses.equilibria.least_energy import solve_equilibrium
from ...analyses.equilibria.stiffness import cartesian_stiffness
from ...analyses.paths.atlas import atlas_target
from ...errors import TensegrityError
from ...model.manipulator import Manipulator
from ...serialize import nullable, nullables
from .spec import MANIPULATOR_PARAMETERS, _header, _point

__all__ = ["evaluate_point", "format_error", "solve_chunk", "error_row"]

def _manipulator(header: Mapping[str, Any], point: Mapping[str, Any]) -> Manipulator:
    if "segments" in header["manipulator"]:
        return _chain_of(header["manipulator"])
    p = {**header["manipulator"], **{k: v for k, v in point.items() if k in MANIPULATOR_PARAMETERS}}
    k, L0 = (tuple(p[x]) if isinstance(p[x], list) else p[x] for x in ("k", "L0"))
    return Manipulator.uniform(p["n"], p["a"], p["b"], k, L0, p.get("spring", "linear"), p.get("mass", 0.0),
                               p.get("inertia", 0.0), p.get("payload", 0.0), p.get("gravity"),
                               p.get("joint_forces", ()))


def _chain_of(base: Mapping[str, Any]) -> Manipulator:
    from ...model.segment import Segment

    def pair(v):
        return tuple(v) if isinstance(v, list) else v

    return Manipulator((Segment(s["a"], s["b"], pair(s["k"]), pair(s["L0"]), s.get("spring", "linear"),
                                s.get("mass", 0.0), s.get("inertia", 0.0)) for s in base["segments"]),
                       base.get("payload", 0.0), base.get("gravity"), base.get("joint_forces", ()))


def _equilibrium(m: Manipulator, point: Mapping[str, Any]):
    if point.get("load") is not None:
        fx, fy = point["load"]
        return solve_equilibrium_under_force(m, fx, fy)
    return solve_equilibrium(m, point.get("dx", 0.0), point.get("dy", 0.0))


def _buckling(m: Manipulator, point: Mapping[str, Any], opts: Mapping[str, Any]) -> dict[str, Any]:
    bk = critical_force(m, opts["boundary"])
    first = bk.modes[0] if bk.modes else None
    return {"critical_force": nullable(bk.force), "load2": nullable(bk.loads[1]) if bk.loads.size > 1 else None,
            "loads": nullables(bk.loads), "mode_shape": first.shape if first else None,
            "mode_signs": first.signs if first else None, "mode_q": nullables(first.q) if first else None}


def _equilibrium_row(m: Manipulator, point: Mapping[str, Any], opts: Mapping[str, Any]) -> dict[str, Any]:
    eq = _equilibrium(m, point)
    return {"energy": nullable(eq.energy), "fx": nullable(eq.fx), "fy": nullable(eq.fy), "stable": bool(eq.stable),
            "morse_index": int(eq.morse_index), "kind": eq.kind, "shape": eq.shape, "signs": eq.signs,
            "q": nullables(eq.q), "tip_x": nullable(eq.tip[0]), "tip_y": nullable(eq.tip[1]),
            "status": eq.status, "solver_status": str(eq.solver.status), "iterations": int(eq.solver.iterations),
            "spring_forces": eq.spring_forces.tolist(), "spring_states": eq.spring_states.tolist(),
            "contact_torques": nullables(eq.contact_torques)}


def _stiffness(m: Manipulator, point: Mapping[str, Any], opts: Mapping[str, Any]) -> dict[str, Any]:
    eq = _equilibrium(m, point)
    K = cartesian_stiffness(m, eq)
    return {"kxx": nullable(K[0, 0]), "kxy": nullable(K[0, 1]), "kyy": nullable(K[1, 1]), "fx": nullable(eq.fx),
            "fy": nullable(eq.fy), "energy": nullable(eq.energy), "stable": bool(eq.stable), "shape": eq.shape}


def _equilibria_count(m: Manipulator, point: Mapping[str, Any], opts: Mapping[str, Any]) -> dict[str, Any]:
    eqs = find_equilibria(m, point.get("dx", 0.0), point.get("dy", 0.0))
    kinds = [e.kind for e in eqs]
    return {"count": len(eqs), "n_stable": sum(bool(e.stable) for e in eqs), "n_saddle": kinds.count("saddle"),
            "n_maximum": kinds.count("maximum"),
            "min_energy": nullable(min(e.energy for e in eqs)) if eqs else None}


def _atlas(m: Manipulator, point: Mapping[str, Any], opts: Mapping[str, Any]) -> dict[str, Any]:
    t = atlas_target(m, point.get("dx", 0.0), point.get("dy", 0.0), method=opts.get("method", "search"),
                     strict=True)
    return {"reachable": t.reachable, "count": t.count, "n_stable": t.n_stable, "n_saddle": t.n_saddle,
            "n_maximum": t.n_maximum, "least_energy": None if t.least_energy is None else nullable(t.least_energy),
            "least_signs": t.least_signs,
            "tie": t.tie, "stable_energy": nullables([e.energy for e in t.stable]),
            "stable_q": nullables(np.concatenate([e.q for e in t.stable])) if t.stable else [],
            "certified": t.certified, "method": t.method}


def _design(m: Manipulator, point: Mapping[str, Any], opts: Mapping[str, Any]) -> dict[str, Any]:
    kw = {k: v for k, v in opts.items() if k in ("total_length", "K_min")}
    if "tension" in opts:
        kw["tension"] = tuple(opts["tension"])
    bounds = {k: tuple(np.asarray(s, dtype=float) if isinstance(s, list) else s for s in v)
              for k, v in opts.get("bounds", {}).items()} or None
    d = maximize_critical_force(m, vary=tuple(opts["vary"]), bounds=bounds, budget=opts.get("budget"),
                                boundary=opts["boundary"], **kw)
    dm = d.manipulator
    values = {"a": dm.a, "b": dm.b, "k": dm.k1, "L0": dm.L1_0}
    out = {"critical_force": nullable(d.critical_force), "multiplicity": int(d.multiplicity),
           "initial_critical_force": nullable(d.initial_critical_force), "loads": nullables(d.loads),
           "active": [str(a) for a in d.active], "status": d.status, "success": bool(d.success),
           "solver_status": str(d.solver.status), "iterations": int(d.solver.iterations)}
    out.update({f"{v}_opt": nullables(values[v]) for v in opts["vary"]})
    return out


#: The result columns of a point, per analysis (the keys of :data:`.spec.RESULT_COLUMNS`).
EVALUATORS = {"buckling": _buckling, "equilibrium": _equilibrium_row, "stiffness": _stiffness,
              "equilibria_count": _equilibria_count, "design": _design, "atlas": _atlas}


def _evaluate(header: Mapping[str, Any], point: Mapping[str, Any]) -> dict[str, Any]:
    return EVALUATORS[header["analysis"]](_manipulator(header, point), point, header["options"])


def evaluate_point(spec: Any, point: Mapping[str, Any]) -> dict[str, Any]:
    """The result columns of one point of ``spec`` (raises the library's exception when it fails).

    ``point`` is ``{parameter: value}`` over the parameters the analysis uses (what it leaves
    out comes from the spec's base chain; dx = dy = 0 by default). Only the spec's analysis,
    manipulator and options matter here, not its grid/points.
    """
    header = _header(spec)
    return _evaluate(header, _point(point, header["analysis"], "point"))


def format_error(exc: BaseException) -> str:
    """``"code: message"`` of a failed point (the service's codes)."""
    if isinstance(exc, TensegrityError):
        return f"{exc.code}: {exc.message}"
    if isinstance(exc, (ArithmeticError, np.linalg.LinAlgError, ValueError, RuntimeError)):
        return f"numerical_failure: {type(exc).__name__}: {exc}"
    return f"internal_error: {type(exc).__name__}: {exc}"


def _parameters(header: Mapping[str, Any], param_cols: Sequence[str], index: int,
                point: Mapping[str, Any]) -> dict[str, Any]:
    """``index`` and the effective value of every swept parameter of ``point``."""
    row: dict[str, Any] = {"index": index}
    force = point.get("load") is not None
    for c in param_cols:
        if c in point:
            row[c] = point[c]
        elif c in MANIPULATOR_PARAMETERS:
            row[c] = header["manipulator"][c]
        elif c in ("dx", "dy"):
            row[c] = None if force else 0.0
        else:
            row[c] = None
    return row


def _row(header: Mapping[str, Any], param_cols: Sequence[str], result_cols: Sequence[str], index: int,
         point: Mapping[str, Any]) -> dict[str, Any]:
    row = _parameters(header, param_cols, index, point)
    try:
        res = _evaluate(header, point)
        err = None
    except Exception as exc:  # a failing point never stops the sweep
        res, err = {}, format_error(exc)
    for c in result_cols:
        row[c] = res.get(c)
    row["error"] = err
    return row


def solve_chunk(header: Mapping[str, Any], param_cols: Sequence[str], result_cols: Sequence[str],
                items: Sequence[tuple[int, Mapping[str, Any]]]) -> list[tuple[int, dict[str, Any]]]:
    """Solve a chunk of ``(index, point)`` (a Dask task; module level so it pickles).

    The library caches its CasADi solvers per thread, so a worker thread builds them on its
    first chunk and reuses them for every later one.
    """
    return [(int(i), _row(header, param_cols, result_cols, int(i), p)) for i, p in items]


def error_row(header: Mapping[str, Any], param_cols: Sequence[str], result_cols: Sequence[str], index: int,
              point: Mapping[str, Any], error: str) -> dict[str, Any]:
    """The row of a point that did not produce a result: its parameters, empty results, ``error``."""
    return _row_error(header, param_cols, result_cols, index, point, error)

def _row_error(header, param_cols, result_cols, index, point, err) -> dict[str, Any]:
    row = _parameters(header, param_cols, index, point)
    row.update({c: None for c in result_cols})
    row["error"] = err
    return row
