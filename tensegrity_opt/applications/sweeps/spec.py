"""What a sweep spec may say, and its validation: one analysis, a uniform base chain, a grid or
a list of points, options; the parameters each analysis uses and the columns of its rows.

This is the one place of the rules. The service's ``service/schemas/jobs.JobSpec`` repeats the
type and range checks (for its OpenAPI document and early 422 answers, plus its own size caps)
and hands the spec here; what depends on the analysis (which parameters and options it uses,
a deflection and a tip force never together) is checked only here.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from typing import Any

import numpy as np

from ...bounds import bound_pair
from ...errors import InvalidParameterError, unknown_name

__all__ = ["ANALYSES", "PARAMETERS", "MANIPULATOR_PARAMETERS", "DEFAULT_MANIPULATOR", "DESIGN_VARIABLES",
           "MAX_POINTS", "USES", "OPTIONS", "PARAMETER_TYPES", "RESULT_COLUMNS", "count_points", "validate_spec"]

ANALYSES = ("buckling", "equilibrium", "equilibria_count", "stiffness", "design", "atlas")
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
    "atlas": (*MANIPULATOR_PARAMETERS, "dx", "dy"),
}
#: Options and the analyses that use them.
OPTIONS: dict[str, tuple[str, ...]] = {
    "boundary": ("buckling", "design"),
    "vary": ("design",), "bounds": ("design",), "budget": ("design",),
    "total_length": ("design",), "tension": ("design",), "K_min": ("design",),
    "method": ("atlas",),
}

#: Column types: ``int``, ``float``, ``bool``, ``str``, ``floats`` (list of numbers), ``strs``, ``floats2``
#: and ``strs2`` (lists of such lists: one per segment, e.g. ``[spring 1, spring 2]``).
PARAMETER_TYPES = {"n": "int", "a": "float", "b": "float", "k": "float", "L0": "float", "dx": "float",
                   "dy": "float", "load": "floats"}

#: Result columns per analysis (``design`` adds ``<name>_opt`` per varied variable: the optimised
#: per-segment values).
RESULT_COLUMNS: dict[str, dict[str, str]] = {
    "buckling": {"critical_force": "float", "load2": "float", "loads": "floats", "mode_shape": "str",
                 "mode_signs": "str", "mode_q": "floats"},
    "equilibrium": {"energy": "float", "fx": "float", "fy": "float", "stable": "bool", "morse_index": "int",
                    "kind": "str", "shape": "str", "signs": "str", "q": "floats", "tip_x": "float",
                    "tip_y": "float", "status": "str", "solver_status": "str", "iterations": "int",
                    "spring_forces": "floats2", "spring_states": "strs2", "contact_torques": "floats"},
    "equilibria_count": {"count": "int", "n_stable": "int", "n_saddle": "int", "n_maximum": "int",
                         "min_energy": "float"},
    "stiffness": {"kxx": "float", "kxy": "float", "kyy": "float", "fx": "float", "fy": "float",
                  "energy": "float", "stable": "bool", "shape": "str"},
    "atlas": {"reachable": "bool", "count": "int", "n_stable": "int", "n_saddle": "int", "n_maximum": "int",
              "least_energy": "float", "least_signs": "str", "tie": "bool", "stable_energy": "floats",
              "stable_q": "floats", "certified": "bool", "method": "str"},
    "design": {"critical_force": "float", "multiplicity": "int", "initial_critical_force": "float",
               "loads": "floats", "active": "strs", "status": "str", "success": "bool", "solver_status": "str",
               "iterations": "int"},
}

_BASE_TYPES = {"index": "int", "error": "str", **PARAMETER_TYPES}
_TOP_KEYS = ("analysis", "manipulator", "grid", "points", "options")

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


def _spring_pair(name: str, v: Any, fld: str) -> list[float]:
    """``k`` or ``L0`` of the base chain as the pair of its two springs ``[spring 1, spring 2]``."""
    if len(v) != 2:
        _fail(fld, "must be a number or the pair of the two springs")
    return [_value(name, x, f"{fld}[{j}]") for j, x in enumerate(v)]


def _check_name(name: Any, analysis: str, fld: str) -> None:
    if name not in PARAMETERS:
        _fail(fld, unknown_name(name, PARAMETERS, "parameter") + f" (a sweep varies {', '.join(PARAMETERS)})")
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
            _fail(f"options.{key}", unknown_name(key, OPTIONS, "option"))
        if analysis not in OPTIONS[key]:
            _fail(f"options.{key}", f"not used by analysis {analysis!r} (only by {', '.join(OPTIONS[key])})")
    if analysis in ("buckling", "design"):
        boundary = raw.get("boundary", "guided")
        if boundary not in ("guided", "free"):
            _fail("options.boundary", f"must be 'guided' or 'free', got {boundary!r}")
        out["boundary"] = boundary
    if analysis == "atlas":
        method = raw.get("method", "search")
        if method not in ("search", "homotopy"):
            _fail("options.method", f"must be 'search' or 'homotopy', got {method!r}")
        out["method"] = method
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
            _fail("options.bounds", "must be an object {name: [lo, hi] or {lo, hi}}")
        nb: dict[str, list[Any]] = {}
        for name, given in bounds.items():
            fld = f"options.bounds.{name}"
            if name not in DESIGN_VARIABLES:
                _fail(fld, f"unknown design variable; expected one of {', '.join(DESIGN_VARIABLES)}")
            pair = bound_pair(given, fld)
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
        if tl is not False:
            out["total_length"] = True if tl is True else _finite(tl, "options.total_length")
    if "tension" in raw:
        t = bound_pair(raw["tension"], "options.tension")
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
            _fail(str(key), unknown_name(key, _TOP_KEYS, "key") + f" (a sweep spec has {', '.join(_TOP_KEYS)})")
    analysis = spec.get("analysis")
    if analysis is None:
        _fail("analysis", f"missing; one of {', '.join(ANALYSES)}")
    if analysis not in ANALYSES:
        _fail("analysis", f"unknown analysis {analysis!r}; one of {', '.join(ANALYSES)}")
    raw_m = spec.get("manipulator")
    raw_m = {} if raw_m is None else raw_m
    if not isinstance(raw_m, Mapping):
        _fail("manipulator", "must be an object {n, a, b, k, L0} or {segments: [...]}")
    if "segments" in raw_m:
        base = _segments(raw_m)
    else:
        base = dict(DEFAULT_MANIPULATOR)
        for key, v in raw_m.items():
            if key == "spring":
                base[key] = _law(v, "manipulator.spring")
                continue
            if key in _MASSES:
                if _mass(v, f"manipulator.{key}"):            # the normal form omits a zero (as to_dict does)
                    base[key] = float(v)
                continue
            if key in _LOADS:
                base.update(_loads({key: v}))
                continue
            if key not in MANIPULATOR_PARAMETERS:
                _fail(f"manipulator.{key}", unknown_name(key, (*MANIPULATOR_PARAMETERS, "spring", *_MASSES, *_LOADS,
                                                               "segments"), "key")
                      + " (the base chain is {n, a, b, k, L0, spring, mass, inertia, payload, gravity, joint_forces} "
                        "(uniform) or {segments: [{a, b, k, L0, spring, mass, inertia}, ...], payload, gravity, "
                        "joint_forces})")
            if key in ("k", "L0") and isinstance(v, (list, tuple)):
                base[key] = _spring_pair(key, v, f"manipulator.{key}")
            else:
                base[key] = _value(key, v, f"manipulator.{key}")
    return {"analysis": analysis, "manipulator": base, "options": _options(analysis, spec.get("options"))}


def _segments(raw_m: Mapping[str, Any]) -> dict[str, Any]:
    """A base chain given segment by segment (pre-bent, heterogeneous): ``{"segments": [{a, b, k, L0}]}``, ``k`` and
    ``L0`` a number or the pair of the two springs. Its segments are fixed: no point varies n, a, b, k, L0."""
    from ...model.segment import Segment

    extra = [k for k in raw_m if k not in ("segments", "payload", *_LOADS)]
    if extra:
        _fail(f"manipulator.{extra[0]}", "a chain given by its segments takes no other key but payload, gravity and "
                                         "joint_forces")
    segs = raw_m["segments"]
    if not isinstance(segs, (list, tuple)) or not segs:
        _fail("manipulator.segments", "must be a non-empty list of {a, b, k, L0}")
    out = []
    for i, sd in enumerate(segs):
        fld = f"manipulator.segments[{i}]"
        if not isinstance(sd, Mapping):
            _fail(fld, "must be an object {a, b, k, L0}")
        for key in sd:
            if key not in _SEGMENT_KEYS:
                _fail(f"{fld}.{key}", unknown_name(key, _SEGMENT_KEYS, "key")
                      + " (a segment has a, b, k, L0, spring, mass, inertia)")
        norm: dict[str, Any] = {}
        for key in ("a", "b", "k", "L0"):
            v, name = sd.get(key, 1.0), "a" if key != "k" else "k"
            if isinstance(v, (list, tuple)):
                norm[key] = _spring_pair(name, v, f"{fld}.{key}")
            else:
                norm[key] = _value(name, v, f"{fld}.{key}")
        if "spring" in sd:
            norm["spring"] = _law(sd["spring"], f"{fld}.spring")
        for key in ("mass", "inertia"):
            if key in sd and _mass(sd[key], f"{fld}.{key}"):
                norm[key] = float(sd[key])
        try:
            Segment(norm["a"], norm["b"], tuple(norm["k"]) if isinstance(norm["k"], list) else norm["k"],
                    tuple(norm["L0"]) if isinstance(norm["L0"], list) else norm["L0"], norm.get("spring", "linear"))
        except InvalidParameterError as exc:
            _fail(f"{fld}.{exc.field}" if exc.field else fld, exc.message)
        out.append(norm)
    chain: dict[str, Any] = {"segments": out}
    if "payload" in raw_m and _mass(raw_m["payload"], "manipulator.payload"):
        chain["payload"] = float(raw_m["payload"])
    chain.update(_loads(raw_m))
    return chain


#: The chain's dead loads besides its masses (``docs/model.md``, "Weights and loads").
_LOADS = ("gravity", "joint_forces")


def _loads(raw_m: Mapping[str, Any]) -> dict[str, Any]:
    """``gravity`` ``[gx, gy]`` and ``joint_forces`` ``[{joint, force}]`` in their JSON form, those set only (the
    library's readers check them; a joint beyond a point's ``n`` is that point's error)."""
    from ...model.loads import check_gravity, check_joint_forces

    out: dict[str, Any] = {}
    try:
        if raw_m.get("gravity") is not None:
            out["gravity"] = list(check_gravity(raw_m["gravity"]))
        forces = check_joint_forces(raw_m.get("joint_forces"), 1 << 30)
    except InvalidParameterError as exc:
        _fail(f"manipulator.{exc.field}", exc.message)
    if forces:
        out["joint_forces"] = [{"joint": j, "force": list(f)} for j, f in forces]
    return out


#: The masses a chain may carry (``docs/model.md``, "Masses and modes"): a segment's ``mass`` and ``inertia``, the
#: chain's ``payload``.
_MASSES = ("mass", "inertia", "payload")
_SEGMENT_KEYS = ("a", "b", "k", "L0", "spring", "mass", "inertia")


def _mass(v: Any, fld: str) -> float:
    """A mass or inertia (finite, >= 0), or the spec's refusal naming ``fld``."""
    if not _is_number(v) or not math.isfinite(float(v)) or float(v) < 0.0:
        _fail(fld, f"must be a finite number >= 0, got {v!r}")
    return float(v)


def _law(v: Any, fld: str) -> str:
    """A spring law (``"linear"`` or ``"tension_only"``), or the spec's refusal naming ``fld``."""
    from ...model.springs import spring_law

    return spring_law(v, fld)


def _fixed_chain(head: Mapping[str, Any], names: Iterable[str], fld: str) -> None:
    if "segments" in head["manipulator"]:
        for name in names:
            if name in MANIPULATOR_PARAMETERS:
                _fail(f"{fld}.{name}", "the base chain is given by its segments: a point cannot vary n, a, b, k, L0")


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
        _fixed_chain(head, body, "grid")
    else:
        for i, p in enumerate(body):
            if isinstance(p, Mapping):
                _fixed_chain(head, p, f"points[{i}]")
    if kind == "grid":
        out["grid"] = {name: [_value(name, v, f"grid.{name}[{i}]") for i, v in enumerate(values)]
                       for name, values in body.items()}
    else:
        out["points"] = [_point(p, analysis, f"points[{i}]") for i, p in enumerate(body)]
    out["options"] = head["options"]
    if analysis == "atlas":
        _atlas_chains(out)
    return out


def _atlas_chains(norm: Mapping[str, Any]) -> None:
    """The atlas's edges follow branches by the dense path system: 2 <= n <= DENSE_MAX."""
    from ...numerics import DENSE_MAX

    base = norm["manipulator"]
    found = [("manipulator.segments", len(base["segments"])) if "segments" in base else ("manipulator.n", base["n"])]
    if "grid" in norm:
        found += [(f"grid.n[{i}]", n) for i, n in enumerate(norm["grid"].get("n", []))]
    else:
        found += [(f"points[{i}].n", p["n"]) for i, p in enumerate(norm["points"]) if "n" in p]
    for fld, n in found:
        if not 2 <= int(n) <= DENSE_MAX:
            _fail(fld, f"the atlas needs 2 <= n <= {DENSE_MAX} segments, got {n}")


def _point(p: Any, analysis: str, fld: str) -> dict[str, Any]:
    if not isinstance(p, Mapping):
        _fail(fld, "must be an object {parameter: value}")
    for name in p:
        _check_name(name, analysis, f"{fld}.{name}")
    _check_control(p, f"{fld}.load")
    return {name: _value(name, v, f"{fld}.{name}") for name, v in p.items()}


