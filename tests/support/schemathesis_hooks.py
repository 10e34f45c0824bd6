"""schemathesis hooks for ``test_service_schemathesis.py`` (``SCHEMATHESIS_HOOKS=schemathesis_hooks``).

The server runs at its *default* limits, and the committed document says exactly what it accepts;
what these hooks bound is the *cost* of the generated requests, not what is valid:

* ``map_case`` shrinks sizes inside the valid range (chains to 6 segments, 2 for the homotopy,
  curves to 21 points, grids to 21 per axis, batches to 10 targets, job sweeps to 3 values per
  key and 3 points, inline atlases to 2 x 2 targets, the control trajectories -- plan targets, times, simulation
  preloads, loads and targets -- to 4 steps, a plan's horizon to 4 steps, an imperfection-sensitivity curve to 3
  amplitudes of at most 400 points each; a figure job's body as its figure's), so that the run stays short and
  no generated input keeps the job runner busy for the rest of the run. A positive
  case stays positive; a negative case keeps its violation (only values valid for every operation
  are shrunk there, and schemathesis revalidates a mapped case).
* ``positive_data_is_accepted_by_the_schema``: a check on top of schemathesis' own. A request the
  document calls valid may be refused for a domain reason (422 ``unreachable_target``, ...), but
  never as a schema violation or over a size limit the document does not state: ``validation_error``,
  ``too_many_segments`` (except on ``method`` / ``options.method``: the homotopy's own limit, documented
  there) and
  ``batch_too_large`` would mean that the document allows what the server refuses.
"""

from __future__ import annotations

from typing import Any

import schemathesis

MAX_N = 6
MAX_N_HOMOTOPY = 2
LIMITS = {"dx": 21, "q": 101, "targets": 10, "values_x": 6, "values_y": 6, "points": 3, "segments": MAX_N}
MAX_NUM = 21
MAX_GRID = 21
MAX_JOB_VALUES = 3
#: The inline atlas (~0.1 s a target, its edges as much again): 2 values per axis (3 x 3 took ~150 s of the run).
ATLAS_PATHS = ("/v1/atlas", "/v1/plots/atlas")
MAX_ATLAS_AXIS = 2
#: Figures: the PNG's resolution is most of a figure's cost (measured: the plot operations were ~60% of the run).
MAX_DPI = 30
#: The control trajectories (a plan step: ~1 ms by Newton, up to ~0.1 s by IPOPT; a simulation step up to ~0.5 s when
#: a wild load makes its branch long): 4 steps of each per-step list.
CONTROL_PATHS = ("/v1/control/plan", "/v1/control/simulate", "/v1/plots/plan", "/v1/plots/simulation")
#: A plan's ``times`` are cut with its targets (as many as targets: a cut plan stays consistent).
CONTROL_SERIES = ("targets", "loads", "preloads", "end_angles", "times")
MAX_CONTROL_STEPS = 4
#: Stiffness shaping (an IPOPT solve per arm shape tried), load capacity (a limit-load path per direction), a
#: plan's horizon (an IPOPT problem of N steps per step; ``"all"`` is the cut trajectory) and the
#: imperfection-sensitivity curve (a limit-load path per amplitude): a number over its cap is lowered to it, a list
#: cut to that many items.
_IMPERFECTION_CAPS = {"amplitudes": 3, "max_points": 400}
COST_CAPS = {"/v1/control/stiffness": {"max_starts": 1},
             "/v1/control/load-capacity": {"directions": 4, "max_load": 2.0},
             "/v1/control/plan": {"horizon": 4},
             "/v1/plots/plan": {"horizon": 4},
             "/v1/imperfection-sensitivity": _IMPERFECTION_CAPS,
             "/v1/plots/imperfection": _IMPERFECTION_CAPS}


def _small_n(v: Any, cap: int, positive: bool) -> Any:
    if isinstance(v, bool) or not isinstance(v, (int, float)) or v != int(v) or v <= cap:
        return v
    if positive or v <= 60:             # 60: valid on every operation (the design endpoints' cap)
        return type(v)(cap)
    return v


def _bound(x: Any, positive: bool, cap: int, parent: str | None = None) -> Any:
    if isinstance(x, list):
        return [_bound(v, positive, cap, parent) for v in x]
    if not isinstance(x, dict):
        return x
    if x.get("method") == "homotopy" or (isinstance(x.get("options"), dict)
                                         and x["options"].get("method") == "homotopy"):    # a job's atlas
        cap = MAX_N_HOMOTOPY
    out = {}
    for key, v in x.items():
        if key == "n":
            v = [_small_n(e, cap, positive) for e in v[:MAX_JOB_VALUES]] if isinstance(v, list) and positive \
                else _small_n(v, cap, positive)
        elif key == "segments" and isinstance(v, list) and len(v) > cap and (positive or len(v) <= 60):
            v = v[:cap]
        elif positive and key in LIMITS and isinstance(v, list) and len(v) > LIMITS[key]:
            v = v[:LIMITS[key]]
        elif positive and key == "num" and isinstance(v, int) and not isinstance(v, bool) and v > MAX_NUM:
            v = MAX_NUM
        elif positive and key == "grid" and isinstance(v, int) and not isinstance(v, bool) and v > MAX_GRID:
            v = MAX_GRID
        elif positive and parent == "grid" and isinstance(v, list):     # a job's grid: values per key
            v = v[:MAX_JOB_VALUES]
        out[key] = _bound(v, positive, cap, key)
    return out


def _operation(path: str) -> str:
    """The operation whose body ``path`` takes: a figure job's (``/v1/plots/x/job``) is its figure's."""
    return path.removesuffix("/job") if path.startswith("/v1/plots/") else path


@schemathesis.hook
def map_case(ctx, case):
    body = case.body
    if isinstance(body, dict):
        meta = case.meta
        positive = meta is None or not meta.generation.mode.is_negative
        path = _operation(case.operation.path)
        case.body = _bound(body, positive, MAX_N)
        dpi = case.body.get("dpi")
        if positive and case.operation.path.startswith("/v1/plots/") and isinstance(dpi, (int, float)) \
                and not isinstance(dpi, bool) and dpi > MAX_DPI:
            case.body["dpi"] = MAX_DPI
        if positive and case.operation.path.startswith("/v1/plots/") and "dpi" not in case.body:
            case.body["dpi"] = MAX_DPI
        if positive and path in ATLAS_PATHS:
            for key in ("dx", "dy"):
                v = case.body.get(key)
                if isinstance(v, list):
                    case.body[key] = v[:MAX_ATLAS_AXIS]
                elif isinstance(v, dict) and isinstance(v.get("num"), int) and v["num"] > MAX_ATLAS_AXIS:
                    case.body[key] = {**v, "num": MAX_ATLAS_AXIS}
        for key, cap in COST_CAPS.get(path, {}).items() if positive else ():
            v = case.body.get(key)
            if isinstance(v, (int, float)) and not isinstance(v, bool) and v > cap:
                case.body[key] = type(v)(cap)
            elif isinstance(v, list) and len(v) > cap:
                case.body[key] = v[:cap]
        if path in CONTROL_PATHS:
            # a sample's preloads: as many pairs as the (shrunk) chain has segments; valid either way (1..200), so
            # shrunk in negative cases too (a sample count over the cap then stays under the body size limit)
            v = case.body.get("preloads")
            if isinstance(v, list):
                case.body["preloads"] = [p[:MAX_N] if isinstance(p, list) and MAX_N < len(p) <= 200 else p for p in v]
            for key in CONTROL_SERIES if positive else ():
                v = case.body.get(key)
                if isinstance(v, list) and len(v) > MAX_CONTROL_STEPS and (key != "loads" or isinstance(v[0], list)):
                    case.body[key] = v[:MAX_CONTROL_STEPS]
    return case


SCHEMA_CODES = {"validation_error", "too_many_segments", "batch_too_large"}
_VALIDATORS: dict[tuple[str, str], Any] = {}


def _conforms(case) -> bool:
    """Whether the case's JSON body conforms to the document's request schema (JSON Schema 2020-12,
    checked here rather than trusting the case's generation mode: a case's mode does not say
    whether each of its values is valid)."""
    import jsonschema_rs

    op = case.operation
    key = (op.method.lower(), op.path)
    if key not in _VALIDATORS:
        raw = op.schema.raw_schema
        media = (raw["paths"][op.path][op.method.lower()].get("requestBody") or {}).get("content", {})
        schema = (media.get("application/json") or {}).get("schema")
        _VALIDATORS[key] = None if schema is None else jsonschema_rs.Draft202012Validator(
            {**schema, "components": raw.get("components", {})})
    validator = _VALIDATORS[key]
    return validator is not None and validator.is_valid(case.body)


@schemathesis.check
def positive_data_is_accepted_by_the_schema(ctx, response, case):
    if response.status_code != 422 or not isinstance(case.body, dict):
        return None
    sent = response.request.headers.get("content-type", "") if response.request is not None else ""
    if "json" not in sent.lower() or case.query or case.path_parameters:
        return None             # a body sent as text/plain, say, is refused whatever it holds
    try:
        body = response.json()
    except ValueError:
        return None
    code = body.get("code") if isinstance(body, dict) else None
    if code not in SCHEMA_CODES or (code == "too_many_segments" and body.get("field") in ("method", "options.method")):
        return None
    if _conforms(case):
        raise AssertionError(f"a request the document calls valid was refused as {code} on "
                             f"{body.get('field')}: {body.get('message')}")
    return None
