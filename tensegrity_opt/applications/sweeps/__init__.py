"""Design-space sweeps: one analysis over a grid or a list of points, serially or on Dask.

A sweep spec (JSON-friendly dict)::

    {"analysis": "buckling",                       # buckling | equilibrium | equilibria_count
                                                   # | stiffness | design
     "manipulator": {"n": 4, "a": 1, "b": 1, "k": 1, "L0": 1},   # uniform base chain (defaults shown)
     "grid": {"n": [3, 4, 5], "k": [0.5, 1, 2]},   # cartesian product, first key varies slowest
     # or "points": [{"n": 4, "dx": 0.1}, {"n": 5, "dx": 0.2}],   # an explicit list
     "options": {"boundary": "guided"}}            # see below

Parameters a point may set (``grid`` lists or ``points`` entries):

=========  ===========================  ===================================================
name       value                        used by
=========  ===========================  ===================================================
``n``      integer >= 1                 every analysis (segments of the uniform chain)
``a``      number > 0                   every analysis (triangle half-height)
``b``      number > 0                   every analysis (triangle half-length)
``k``      number > 0                   every analysis (both springs' stiffness)
``L0``     number > 0                   every analysis (both springs' rest length)
``dx``     number (default 0)           equilibrium, stiffness, equilibria_count
``dy``     number (default 0)           equilibrium, stiffness, equilibria_count
``load``   ``[fx, fy]``                 equilibrium, stiffness (tip force instead of dx/dy)
=========  ===========================  ===================================================

A constant is a one-value list (``"dx": [0.1]``). A point gives either a tip deflection
(``dx``/``dy``) or a tip force (``load``), never both. Parameters the analysis does not use
are refused. ``options``: ``boundary`` (``"guided"`` | ``"free"``; buckling and design),
and for ``design`` the arguments of :func:`tensegrity_opt.maximize_critical_force`:
``vary`` (default ``["k"]``), ``bounds`` (``{name: [lo, hi]}``), ``budget``
(``{name: total}``), ``total_length``, ``tension`` (``[T_min, T_max]``), ``K_min``.

Every row: ``index`` (position in :func:`expand`), the swept parameters (effective value:
a parameter a point leaves out takes the base chain's value, ``dx``/``dy`` 0 or ``None``
under a tip force), the analysis's result columns (:data:`RESULT_COLUMNS`; ``None`` where
the point failed or a value does not exist) and ``error`` (``None`` or ``"code: message"``).
A failing point never stops the sweep.

Execution: ``scheduler=None``/``"serial"`` solves in the calling thread (the library caches
its CasADi solvers per thread); ``"local"`` starts a ``dask.distributed.LocalCluster``
(one single-threaded worker process per core), ``"tcp://host:port"`` uses a running Dask
scheduler (a :class:`distributed.Client` is accepted too). Each Dask task solves a chunk
of points with :func:`solve_chunk` (module level, so it pickles); a worker thread builds
its solvers once and reuses them for every later chunk. Chunks stream back with
``as_completed``; ``on_result(index, row)`` runs in the calling process as each point
(Dask: each chunk) arrives.
"""

from __future__ import annotations

import csv
import io
import itertools
import json
import math
import os
import sys
import time
import uuid
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ...analyses.all_equilibria import find_equilibria
from ...analyses.buckling import critical_force
from ...analyses.design import maximize_critical_force
from ...analyses.equilibrium import solve_equilibrium, solve_equilibrium_under_force
from ...analyses.stiffness import cartesian_stiffness
from ...errors import InvalidParameterError, TensegrityError
from ...model.manipulator import Manipulator

__all__ = ["ANALYSES", "PARAMETERS", "RESULT_COLUMNS", "MAX_POINTS", "SweepResult", "validate_spec", "expand",
           "count_points", "columns", "column_types", "evaluate_point", "solve_chunk", "sweep", "format_error",
           "read_results", "write_csv", "plan", "error_row"]

ANALYSES = ("buckling", "equilibrium", "equilibria_count", "stiffness", "design")
MANIPULATOR_PARAMETERS = ("n", "a", "b", "k", "L0")
PARAMETERS = (*MANIPULATOR_PARAMETERS, "dx", "dy", "load")
DEFAULT_MANIPULATOR: dict[str, Any] = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}
DESIGN_VARIABLES = ("a", "b", "k", "L0")
#: Largest sweep :func:`expand` accepts.
MAX_POINTS = 1_000_000

#: Parameters each analysis uses.
USES: dict[str, tuple[str, ...]] = {
    "buckling": MANIPULATOR_PARAMETERS,
    "design": MANIPULATOR_PARAMETERS,
    "equilibrium": PARAMETERS,
    "stiffness": PARAMETERS,
    "equilibria_count": (*MANIPULATOR_PARAMETERS, "dx", "dy"),
}
#: Options and the analyses that use them.
OPTIONS: dict[str, tuple[str, ...]] = {
    "boundary": ("buckling", "design"),
    "vary": ("design",), "bounds": ("design",), "budget": ("design",),
    "total_length": ("design",), "tension": ("design",), "K_min": ("design",),
}

#: Column types: ``int``, ``float``, ``bool``, ``str``, ``floats`` (list of numbers), ``strs``.
PARAMETER_TYPES = {"n": "int", "a": "float", "b": "float", "k": "float", "L0": "float", "dx": "float",
                   "dy": "float", "load": "floats"}

#: Result columns per analysis (``design`` adds ``<name>_opt`` per varied variable: the optimised
#: per-segment values).
RESULT_COLUMNS: dict[str, dict[str, str]] = {
    "buckling": {"critical_force": "float", "load2": "float", "loads": "floats", "mode_shape": "str",
                 "mode_signs": "str", "mode_q": "floats"},
    "equilibrium": {"energy": "float", "fx": "float", "fy": "float", "stable": "bool", "morse_index": "int",
                    "kind": "str", "shape": "str", "signs": "str", "q": "floats", "tip_x": "float",
                    "tip_y": "float", "status": "str", "iterations": "int"},
    "equilibria_count": {"count": "int", "n_stable": "int", "n_saddle": "int", "n_maximum": "int",
                         "min_energy": "float"},
    "stiffness": {"kxx": "float", "kxy": "float", "kyy": "float", "fx": "float", "fy": "float",
                  "energy": "float", "stable": "bool", "shape": "str"},
    "design": {"critical_force": "float", "multiplicity": "int", "initial_critical_force": "float",
               "loads": "floats", "active": "strs", "status": "str", "success": "bool", "iterations": "int"},
}

_BASE_TYPES = {"index": "int", "error": "str", **PARAMETER_TYPES}
_TOP_KEYS = ("analysis", "manipulator", "grid", "points", "options")


# =========================================================================== validation
def _fail(fld: str, msg: str) -> None:
    raise InvalidParameterError(f"{fld}: {msg}", field=fld)


def _is_number(v: Any) -> bool:
    return isinstance(v, (int, float, np.integer, np.floating)) and not isinstance(v, (bool, np.bool_))


def _finite(v: Any, fld: str) -> float:
    if not _is_number(v) or not math.isfinite(float(v)):
        _fail(fld, f"must be a finite number, got {v!r}")
    return float(v)


def _value(name: str, v: Any, fld: str) -> Any:
    """One parameter value, normalised (``n`` an int, lengths floats, ``load`` ``[fx, fy]``)."""
    if name == "n":
        if _is_number(v) and math.isfinite(float(v)) and float(v) == int(v) and int(v) >= 1:
            return int(v)
        _fail(fld, f"must be an integer >= 1, got {v!r}")
    if name in ("a", "b", "k", "L0"):
        x = _finite(v, fld)
        if x <= 0.0:
            _fail(fld, f"must be > 0, got {v!r}")
        return x
    if name in ("dx", "dy"):
        return _finite(v, fld)
    if name == "load":
        if not isinstance(v, (list, tuple)) or len(v) != 2:
            _fail(fld, f"must be a tip force [fx, fy], got {v!r}")
        return [_finite(v[0], f"{fld}[0]"), _finite(v[1], f"{fld}[1]")]
    _fail(fld, f"unknown parameter; expected one of {', '.join(PARAMETERS)}")  # pragma: no cover


def _check_name(name: Any, analysis: str, fld: str) -> None:
    if name not in PARAMETERS:
        _fail(fld, f"unknown parameter {name!r}; a sweep varies {', '.join(PARAMETERS)}")
    if name not in USES[analysis]:
        _fail(fld, f"{name!r} is not used by analysis {analysis!r} (it uses {', '.join(USES[analysis])})")


def _check_control(keys: Iterable[str], fld: str) -> None:
    keys = set(keys)
    if "load" in keys and keys & {"dx", "dy"}:
        _fail(fld, "a point gives either a tip deflection (dx, dy) or a tip force (load), not both")


def _options(analysis: str, raw: Any) -> dict[str, Any]:
    if raw is None:
        raw = {}
    if not isinstance(raw, Mapping):
        _fail("options", "must be an object")
    out: dict[str, Any] = {}
    for key in raw:
        if key not in OPTIONS:
            _fail(f"options.{key}", f"unknown option; expected one of {', '.join(OPTIONS)}")
        if analysis not in OPTIONS[key]:
            _fail(f"options.{key}", f"not used by analysis {analysis!r} (only by {', '.join(OPTIONS[key])})")
    if analysis in ("buckling", "design"):
        boundary = raw.get("boundary", "guided")
        if boundary not in ("guided", "free"):
            _fail("options.boundary", f"must be 'guided' or 'free', got {boundary!r}")
        out["boundary"] = boundary
    if analysis != "design":
        return out
    vary = raw.get("vary", ["k"])
    if isinstance(vary, str):
        vary = [vary]
    if not isinstance(vary, (list, tuple)) or not vary:
        _fail("options.vary", "must be a non-empty list of design variables")
    for i, v in enumerate(vary):
        if v not in DESIGN_VARIABLES:
            _fail(f"options.vary[{i}]", f"unknown design variable {v!r}; expected one of {', '.join(DESIGN_VARIABLES)}")
    if len(set(vary)) != len(vary):
        _fail("options.vary", "names a variable twice")
    out["vary"] = list(vary)
    if "bounds" in raw:
        bounds = raw["bounds"]
        if not isinstance(bounds, Mapping):
            _fail("options.bounds", "must be an object {name: [lo, hi]}")
        nb: dict[str, list[Any]] = {}
        for name, pair in bounds.items():
            fld = f"options.bounds.{name}"
            if name not in DESIGN_VARIABLES:
                _fail(fld, f"unknown design variable; expected one of {', '.join(DESIGN_VARIABLES)}")
            if not isinstance(pair, (list, tuple)) or len(pair) != 2:
                _fail(fld, "must be [lo, hi]")
            side = []
            for j, s in enumerate(pair):
                if isinstance(s, (list, tuple)):
                    side.append([_finite(x, f"{fld}[{j}][{i}]") for i, x in enumerate(s)])
                else:
                    side.append(_finite(s, f"{fld}[{j}]"))
            nb[name] = side
        out["bounds"] = nb
    if "budget" in raw:
        budget = raw["budget"]
        if not isinstance(budget, Mapping):
            _fail("options.budget", "must be an object {name: total}")
        for name in budget:
            if name not in DESIGN_VARIABLES:
                _fail(f"options.budget.{name}",
                      f"unknown design variable; expected one of {', '.join(DESIGN_VARIABLES)}")
        out["budget"] = {name: _finite(v, f"options.budget.{name}") for name, v in budget.items()}
    if "total_length" in raw:
        tl = raw["total_length"]
        out["total_length"] = True if tl is True else _finite(tl, "options.total_length")
    if "tension" in raw:
        t = raw["tension"]
        if not isinstance(t, (list, tuple)) or len(t) != 2:
            _fail("options.tension", "must be [T_min, T_max]")
        out["tension"] = [_finite(t[0], "options.tension[0]"), _finite(t[1], "options.tension[1]")]
    if "K_min" in raw:
        out["K_min"] = _finite(raw["K_min"], "options.K_min")
    return out


def _header(spec: Any) -> dict[str, Any]:
    """The validated analysis, base manipulator and options (everything but the points)."""
    if not isinstance(spec, Mapping):
        _fail("spec", f"a sweep spec is a JSON object, got {type(spec).__name__}")
    for key in spec:
        if key not in _TOP_KEYS:
            _fail(str(key), f"unknown key; a sweep spec has {', '.join(_TOP_KEYS)}")
    analysis = spec.get("analysis")
    if analysis is None:
        _fail("analysis", f"missing; one of {', '.join(ANALYSES)}")
    if analysis not in ANALYSES:
        _fail("analysis", f"unknown analysis {analysis!r}; one of {', '.join(ANALYSES)}")
    raw_m = spec.get("manipulator")
    raw_m = {} if raw_m is None else raw_m
    if not isinstance(raw_m, Mapping):
        _fail("manipulator", "must be an object {n, a, b, k, L0}")
    base = dict(DEFAULT_MANIPULATOR)
    for key, v in raw_m.items():
        if key not in MANIPULATOR_PARAMETERS:
            _fail(f"manipulator.{key}", "unknown key; the base chain is uniform: {n, a, b, k, L0}")
        base[key] = _value(key, v, f"manipulator.{key}")
    return {"analysis": analysis, "manipulator": base, "options": _options(analysis, spec.get("options"))}


def _shape(spec: Mapping[str, Any], analysis: str) -> tuple[str, Any]:
    has_grid, has_points = spec.get("grid") is not None, spec.get("points") is not None
    if has_grid == has_points:
        _fail("grid" if has_grid else "points", "give exactly one of 'grid' (cartesian product) or 'points' (a list)")
    if has_grid:
        grid = spec["grid"]
        if not isinstance(grid, Mapping) or not grid:
            _fail("grid", "must be a non-empty object {parameter: [values, ...]}")
        for name, values in grid.items():
            _check_name(name, analysis, f"grid.{name}")
            if not isinstance(values, (list, tuple)) or not values:
                _fail(f"grid.{name}", "must be a non-empty list of values")
        _check_control(grid, "grid.load")
        return "grid", grid
    points = spec["points"]
    if not isinstance(points, (list, tuple)) or not points:
        _fail("points", "must be a non-empty list of objects {parameter: value}")
    return "points", points


def count_points(spec: Mapping[str, Any]) -> int:
    """Number of points of ``spec`` without expanding it (validates its shape, not its values)."""
    head = _header(spec)
    kind, body = _shape(spec, head["analysis"])
    if kind == "grid":
        return math.prod(len(v) for v in body.values())
    return len(body)


def validate_spec(spec: Any) -> dict[str, Any]:
    """The normalised spec (defaults filled in, numbers typed); raises ``InvalidParameterError``.

    The error's ``field`` is the path of the culprit (``"grid.dx[2]"``, ``"points[3].load"``,
    ``"options.vary[0]"``, ``"manipulator.n"``...) and its message starts with that path.
    Idempotent: a normalised spec validates to itself.
    """
    head = _header(spec)
    analysis = head["analysis"]
    kind, body = _shape(spec, analysis)
    total = math.prod(len(v) for v in body.values()) if kind == "grid" else len(body)
    if total > MAX_POINTS:
        _fail(kind, f"{total} points; a sweep has at most {MAX_POINTS}")
    out: dict[str, Any] = {"analysis": analysis, "manipulator": head["manipulator"]}
    if kind == "grid":
        out["grid"] = {name: [_value(name, v, f"grid.{name}[{i}]") for i, v in enumerate(values)]
                       for name, values in body.items()}
    else:
        out["points"] = [_point(p, analysis, f"points[{i}]") for i, p in enumerate(body)]
    out["options"] = head["options"]
    return out


def _point(p: Any, analysis: str, fld: str) -> dict[str, Any]:
    if not isinstance(p, Mapping):
        _fail(fld, "must be an object {parameter: value}")
    for name in p:
        _check_name(name, analysis, f"{fld}.{name}")
    _check_control(p, f"{fld}.load")
    return {name: _value(name, v, f"{fld}.{name}") for name, v in p.items()}


def expand(spec: Any) -> list[dict[str, Any]]:
    """The points of ``spec`` in order: the grid's cartesian product (first key slowest), or ``points``."""
    norm = validate_spec(spec)
    if "grid" in norm:
        names = list(norm["grid"])
        return [dict(zip(names, combo)) for combo in itertools.product(*norm["grid"].values())]
    return [dict(p) for p in norm["points"]]


def _parameter_columns(norm: Mapping[str, Any]) -> list[str]:
    if "grid" in norm:
        return list(norm["grid"])
    seen = {name for p in norm["points"] for name in p}
    return [name for name in PARAMETERS if name in seen]


def _result_types(header: Mapping[str, Any]) -> dict[str, str]:
    out = dict(RESULT_COLUMNS[header["analysis"]])
    if header["analysis"] == "design":
        out.update({f"{v}_opt": "floats" for v in header["options"]["vary"]})
    return out


def columns(spec: Any) -> list[str]:
    """Column order of the rows: ``index``, swept parameters, result columns, ``error``."""
    norm = validate_spec(spec)
    return ["index", *_parameter_columns(norm), *_result_types(norm), "error"]


def column_types(spec: Any) -> dict[str, str]:
    """``{column: type}`` in column order (types as in :data:`PARAMETER_TYPES`)."""
    norm = validate_spec(spec)
    return {"index": "int", **{c: PARAMETER_TYPES[c] for c in _parameter_columns(norm)},
            **_result_types(norm), "error": "str"}


# =========================================================================== evaluation
def _num(x: Any) -> float | None:
    x = float(x)
    return x if math.isfinite(x) else None


def _floats(a: Any) -> list[float | None]:
    return [_num(x) for x in np.asarray(a, dtype=float).ravel()]


def _manipulator(header: Mapping[str, Any], point: Mapping[str, Any]) -> Manipulator:
    p = {**header["manipulator"], **{k: v for k, v in point.items() if k in MANIPULATOR_PARAMETERS}}
    return Manipulator.uniform(p["n"], p["a"], p["b"], p["k"], p["L0"])


def _equilibrium(m: Manipulator, point: Mapping[str, Any]):
    if point.get("load") is not None:
        fx, fy = point["load"]
        return solve_equilibrium_under_force(m, fx, fy)
    return solve_equilibrium(m, point.get("dx", 0.0), point.get("dy", 0.0))


def _evaluate(header: Mapping[str, Any], point: Mapping[str, Any]) -> dict[str, Any]:
    analysis, opts = header["analysis"], header["options"]
    m = _manipulator(header, point)
    if analysis == "buckling":
        bk = critical_force(m, opts["boundary"])
        first = bk.modes[0] if bk.modes else None
        return {"critical_force": _num(bk.force), "load2": _num(bk.loads[1]) if bk.loads.size > 1 else None,
                "loads": _floats(bk.loads), "mode_shape": first.shape if first else None,
                "mode_signs": first.signs if first else None, "mode_q": _floats(first.q) if first else None}
    if analysis == "equilibrium":
        eq = _equilibrium(m, point)
        return {"energy": _num(eq.energy), "fx": _num(eq.fx), "fy": _num(eq.fy), "stable": bool(eq.stable),
                "morse_index": int(eq.morse_index), "kind": eq.kind, "shape": eq.shape, "signs": eq.signs,
                "q": _floats(eq.q), "tip_x": _num(eq.tip[0]), "tip_y": _num(eq.tip[1]), "status": str(eq.status),
                "iterations": int(eq.iterations)}
    if analysis == "stiffness":
        eq = _equilibrium(m, point)
        K = cartesian_stiffness(m, eq)
        return {"kxx": _num(K[0, 0]), "kxy": _num(K[0, 1]), "kyy": _num(K[1, 1]), "fx": _num(eq.fx),
                "fy": _num(eq.fy), "energy": _num(eq.energy), "stable": bool(eq.stable), "shape": eq.shape}
    if analysis == "equilibria_count":
        eqs = find_equilibria(m, point.get("dx", 0.0), point.get("dy", 0.0))
        kinds = [e.kind for e in eqs]
        return {"count": len(eqs), "n_stable": sum(bool(e.stable) for e in eqs), "n_saddle": kinds.count("saddle"),
                "n_maximum": kinds.count("maximum"), "min_energy": _num(min(e.energy for e in eqs)) if eqs else None}
    if analysis == "design":
        kw = {k: v for k, v in opts.items() if k in ("total_length", "K_min")}
        if "tension" in opts:
            kw["tension"] = tuple(opts["tension"])
        bounds = {k: tuple(np.asarray(s, dtype=float) if isinstance(s, list) else s for s in v)
                  for k, v in opts.get("bounds", {}).items()} or None
        d = maximize_critical_force(m, vary=tuple(opts["vary"]), bounds=bounds, budget=opts.get("budget"),
                                    boundary=opts["boundary"], **kw)
        dm = d.manipulator
        values = {"a": dm.a, "b": dm.b, "k": dm.k1, "L0": dm.L1_0}
        out = {"critical_force": _num(d.critical_force), "multiplicity": int(d.multiplicity),
               "initial_critical_force": _num(d.initial_critical_force), "loads": _floats(d.loads),
               "active": [str(a) for a in d.active], "status": str(d.status), "success": bool(d.success),
               "iterations": int(d.iterations)}
        out.update({f"{v}_opt": _floats(values[v]) for v in opts["vary"]})
        return out
    raise AssertionError(analysis)  # pragma: no cover - validated


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
        code = exc.code if type(exc) is not TensegrityError else "no_equilibrium"
        return f"{code}: {exc.message}"
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


def plan(spec: Any) -> tuple[dict[str, Any], list[str], list[str], list[dict[str, Any]]]:
    """``(header, param_cols, result_cols, points)`` of ``spec``: what :func:`solve_chunk` takes, for
    callers that run the points themselves (the service's job runner, with a time limit per point)."""
    norm = validate_spec(spec)
    header = {k: norm[k] for k in ("analysis", "manipulator", "options")}
    return header, _parameter_columns(norm), list(_result_types(header)), expand(norm)


def error_row(header: Mapping[str, Any], param_cols: Sequence[str], result_cols: Sequence[str], index: int,
              point: Mapping[str, Any], error: str) -> dict[str, Any]:
    """The row of a point that did not produce a result: its parameters, empty results, ``error``."""
    return _row_error(header, param_cols, result_cols, index, point, error)


# =========================================================================== results
def _cell_csv(v: Any, kind: str) -> str:
    if v is None:
        return ""
    if kind in ("floats", "strs"):
        return json.dumps(v, allow_nan=False)
    if kind == "bool":
        return "true" if v else "false"
    if kind == "float":
        return repr(float(v))
    return str(v)


def _cell_parse(text: str, kind: str) -> Any:
    if text == "":
        return None
    if kind == "int":
        return int(text)
    if kind == "float":
        return float(text)
    if kind == "bool":
        return text.lower() in ("true", "1", "yes")
    if kind in ("floats", "strs"):
        return json.loads(text)
    return text


def _type_of(col: str) -> str:
    if col in _BASE_TYPES:
        return _BASE_TYPES[col]
    for cols in RESULT_COLUMNS.values():
        if col in cols:
            return cols[col]
    if col.endswith("_opt"):
        return "floats"
    return "str"


@dataclass
class SweepResult:
    """Rows of a sweep (sorted by ``index``; skipped points are absent) and how it ran."""

    spec: dict[str, Any] | None
    columns: list[str]
    rows: list[dict[str, Any]]
    total: int = 0
    skipped: int = 0
    cancelled: bool = False
    elapsed: float = 0.0
    scheduler: str = "serial"
    types: dict[str, str] = field(default_factory=dict, repr=False)

    def __post_init__(self) -> None:
        if not self.types:
            self.types = {c: _type_of(c) for c in self.columns}

    def __len__(self) -> int:
        return len(self.rows)

    @property
    def errors(self) -> list[dict[str, Any]]:
        """The rows whose point failed."""
        return [r for r in self.rows if r.get("error")]

    def column(self, name: str) -> list[Any]:
        return [r.get(name) for r in self.rows]

    # -------------------------------------------------------------- writers
    def csv_text(self) -> str:
        buf = io.StringIO()
        write_csv(buf, self.columns, self.rows, self.types)
        return buf.getvalue()

    def to_csv(self, path: str | os.PathLike[str]) -> Path:
        """CSV with a header; lists as JSON text, booleans ``true``/``false``, missing values empty."""
        path = Path(path)
        with open(path, "w", encoding="utf-8", newline="") as fh:
            write_csv(fh, self.columns, self.rows, self.types)
        return path

    def to_json(self, path: str | os.PathLike[str]) -> Path:
        """``{"format", "spec", "columns", "rows": [{column: value}, ...]}`` (no NaN: missing is ``null``)."""
        path = Path(path)
        doc = {"format": "tensegrity-sweep/1", "spec": self.spec, "columns": self.columns,
               "rows": [{c: r.get(c) for c in self.columns} for r in self.rows]}
        with open(path, "w", encoding="utf-8") as fh:
            json.dump(doc, fh, allow_nan=False, indent=1)
            fh.write("\n")
        return path

    def to_parquet(self, path: str | os.PathLike[str]) -> Path:
        """Parquet (pyarrow) with typed columns; lists as list columns; the spec in the schema metadata."""
        import pyarrow as pa
        import pyarrow.parquet as pq

        arrow = {"int": pa.int64(), "float": pa.float64(), "bool": pa.bool_(), "str": pa.string(),
                 "floats": pa.list_(pa.float64()), "strs": pa.list_(pa.string())}
        schema = pa.schema([pa.field(c, arrow[self.types.get(c, "str")]) for c in self.columns],
                           metadata={"tensegrity_sweep_spec": json.dumps(self.spec)})
        table = pa.Table.from_pylist([{c: r.get(c) for c in self.columns} for r in self.rows], schema=schema)
        path = Path(path)
        pq.write_table(table, path)
        return path

    def save(self, path: str | os.PathLike[str]) -> Path:
        """Write by suffix: ``.csv``, ``.json``, ``.parquet`` / ``.pq``."""
        suffix = Path(path).suffix.lower()
        if suffix == ".csv":
            return self.to_csv(path)
        if suffix == ".json":
            return self.to_json(path)
        if suffix in (".parquet", ".pq"):
            return self.to_parquet(path)
        raise InvalidParameterError(f"output: unknown file type {suffix or '(none)'!r}; use .csv, .json or .parquet",
                                    field="output")

    # -------------------------------------------------------------- reader
    @classmethod
    def read(cls, path: str | os.PathLike[str]) -> SweepResult:
        """Read a file written by :meth:`save` back (same rows, same types)."""
        path = Path(path)
        suffix = path.suffix.lower()
        if suffix == ".json":
            with open(path, encoding="utf-8") as fh:
                doc = json.load(fh)
            return cls(doc.get("spec"), list(doc["columns"]), list(doc["rows"]), total=len(doc["rows"]))
        if suffix in (".parquet", ".pq"):
            import pyarrow.parquet as pq

            table = pq.read_table(path)
            meta = table.schema.metadata or {}
            raw = meta.get(b"tensegrity_sweep_spec")
            spec = json.loads(raw) if raw else None
            rows = table.to_pylist()
            return cls(spec, list(table.column_names), rows, total=len(rows))
        if suffix == ".csv":
            with open(path, encoding="utf-8", newline="") as fh:
                reader = csv.reader(fh)
                header = next(reader)
                types = [_type_of(c) for c in header]
                rows = [{c: _cell_parse(v, t) for c, v, t in zip(header, line, types)} for line in reader]
            return cls(None, header, rows, total=len(rows))
        raise InvalidParameterError(f"unknown file type {suffix or '(none)'!r}; use .csv, .json or .parquet",
                                    field="path")


def write_csv(fh: Any, cols: Sequence[str], rows: Iterable[Mapping[str, Any]],
              types: Mapping[str, str] | None = None, header: bool = True) -> None:
    """Write ``rows`` as CSV to the text file ``fh`` (the format of :meth:`SweepResult.to_csv`);
    ``header=False``: without the header line (a later batch of a streamed file)."""
    types = dict(types or {})
    kinds = [types.get(c) or _type_of(c) for c in cols]
    w = csv.writer(fh, lineterminator="\n")
    if header:
        w.writerow(cols)
    for r in rows:
        w.writerow([_cell_csv(r.get(c), k) for c, k in zip(cols, kinds)])


def read_results(path: str | os.PathLike[str]) -> SweepResult:
    """Shorthand for :meth:`SweepResult.read`."""
    return SweepResult.read(path)


# =========================================================================== running
def _tty(stream: Any) -> bool:
    try:
        return bool(stream.isatty())
    except Exception:
        return False


class _Progress:
    def __init__(self, enabled: bool, total: int) -> None:
        self.bar = None
        if enabled and _tty(sys.stderr):
            try:
                from tqdm import tqdm
            except ImportError:  # pragma: no cover - tqdm missing: no bar
                return
            self.bar = tqdm(total=total, unit="pt", file=sys.stderr, dynamic_ncols=True, smoothing=0.1)

    def update(self, k: int, errors: int) -> None:
        if self.bar is not None:
            self.bar.update(k)
            if errors:
                self.bar.set_postfix(errors=errors, refresh=False)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()


def sweep(spec: Any, *, scheduler: Any = None, progress: bool = False,
          on_result: Callable[[int, dict[str, Any]], Any] | None = None, skip: Iterable[int] = (),
          should_stop: Callable[[], bool] | None = None, chunk_size: int | None = None,
          workers: int | None = None) -> SweepResult:
    """Run ``spec`` (see the module docstring) and return its rows.

    Parameters
    ----------
    scheduler : None | "serial" | "local" | "tcp://host:port" | distributed.Client
        ``None``/``"serial"``: in the calling thread. ``"local"``: a new ``LocalCluster``
        (``workers`` single-threaded processes, default one per core), closed at the end.
        An address: the Dask scheduler there (its workers need ``tensegrity_opt`` installed).
    progress : bool
        Show a tqdm bar on stderr, only when stderr is a terminal.
    on_result : callable(index, row), optional
        Called in the calling thread as each point's row arrives (completion order). An
        exception it raises stops the sweep and propagates.
    skip : iterable of int
        Indices already done (resume): not solved, not in the result.
    should_stop : callable() -> bool, optional
        Polled between points (Dask: between chunks); when true, the sweep stops early,
        pending Dask tasks are cancelled and ``SweepResult.cancelled`` is set.
    chunk_size : int, optional
        Points per Dask task (default: about four chunks per worker thread, at most 64).
    """
    norm = validate_spec(spec)
    header = {k: norm[k] for k in ("analysis", "manipulator", "options")}
    param_cols = _parameter_columns(norm)
    result_cols = list(_result_types(header))
    cols = ["index", *param_cols, *result_cols, "error"]
    points = expand(norm)
    skip_set = {int(i) for i in skip}
    todo = [(i, p) for i, p in enumerate(points) if i not in skip_set]
    stop = should_stop or (lambda: False)
    rows: dict[int, dict[str, Any]] = {}
    t0 = time.perf_counter()
    bar = _Progress(progress, len(todo))
    n_err = 0
    cancelled = False

    def deliver(i: int, row: dict[str, Any]) -> None:
        nonlocal n_err
        rows[i] = row
        if row.get("error"):
            n_err += 1
        if on_result is not None:
            on_result(i, row)

    label = "serial"
    try:
        if scheduler is None or scheduler == "serial":
            for i, p in todo:
                if stop():
                    cancelled = True
                    break
                deliver(i, _row(header, param_cols, result_cols, i, p))
                bar.update(1, n_err)
        else:
            label, cancelled = _run_dask(scheduler, header, param_cols, result_cols, todo, deliver, bar,
                                         lambda: n_err, stop, chunk_size, workers)
    finally:
        bar.close()
    types = column_types(norm)
    return SweepResult(norm, cols, [rows[i] for i in sorted(rows)], total=len(points), skipped=len(points) - len(todo),
                       cancelled=cancelled, elapsed=time.perf_counter() - t0, scheduler=label, types=types)


def _run_dask(scheduler: Any, header, param_cols, result_cols, todo, deliver, bar, n_err, stop, chunk_size,
              workers) -> tuple[str, bool]:
    try:
        from distributed import Client, LocalCluster, as_completed
    except ImportError as exc:  # pragma: no cover - optional dependency
        raise InvalidParameterError("scheduler: Dask is not installed (pip install 'dask[distributed]')",
                                    field="scheduler") from exc
    cluster = None
    own_client = True
    if isinstance(scheduler, Client):
        client, own_client, label = scheduler, False, f"dask:{scheduler.scheduler.address}"
    elif scheduler == "local":
        cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1, processes=True,
                               dashboard_address=None)
        client, label = Client(cluster), "local"
    elif isinstance(scheduler, str) and "://" in scheduler:
        client, label = Client(scheduler, timeout="30s"), scheduler
    else:
        raise InvalidParameterError(f"scheduler: expected 'serial', 'local' or a Dask address like "
                                    f"tcp://host:8786, got {scheduler!r}", field="scheduler")
    cancelled = False
    try:
        if not todo:
            return label, False
        threads = max(1, sum(client.nthreads().values()))
        size = chunk_size or max(1, min(64, math.ceil(len(todo) / (4 * threads))))
        chunks = [todo[j:j + size] for j in range(0, len(todo), size)]
        tag = uuid.uuid4().hex[:12]
        max_in_flight = 2 * threads + 2
        pending = iter(enumerate(chunks))
        owner: dict[str, list[tuple[int, Any]]] = {}

        def submit_next() -> Any:
            nxt = next(pending, None)
            if nxt is None:
                return None
            k, chunk = nxt
            fut = client.submit(solve_chunk, header, param_cols, result_cols, chunk, key=f"tensegrity-sweep-{tag}-{k}",
                                pure=False, retries=1)
            owner[fut.key] = chunk
            return fut

        first = [f for f in (submit_next() for _ in range(max_in_flight)) if f is not None]
        ac = as_completed(first)
        for fut in ac:
            chunk = owner.pop(fut.key)
            if fut.status == "error":
                # The task itself failed (worker died, ...): every point of the chunk gets the error.
                err = f"worker_failed: {type(fut.exception()).__name__}: {fut.exception()}"
                results = [(i, _row_error(header, param_cols, result_cols, i, p, err)) for i, p in chunk]
            else:
                results = fut.result()
            fut.release()
            for i, row in results:
                deliver(i, row)
            bar.update(len(results), n_err())
            if stop():
                cancelled = True
                rest = list(ac.futures) if hasattr(ac, "futures") else []
                client.cancel(rest)
                break
            nf = submit_next()
            if nf is not None:
                ac.add(nf)
        return label, cancelled
    finally:
        if own_client:
            client.close()
        if cluster is not None:
            cluster.close()


def _row_error(header, param_cols, result_cols, index, point, err) -> dict[str, Any]:
    row = _parameters(header, param_cols, index, point)
    row.update({c: None for c in result_cols})
    row["error"] = err
    return row
