"""A validated spec as points and columns: the grid's cartesian product or the list, in order."""

from __future__ import annotations

import itertools
from collections.abc import Mapping
from typing import Any

from .spec import PARAMETER_TYPES, PARAMETERS, RESULT_COLUMNS, validate_spec

__all__ = ["expand", "columns", "column_types", "plan"]

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


def plan(spec: Any) -> tuple[dict[str, Any], list[str], list[str], list[dict[str, Any]]]:
    """``(header, param_cols, result_cols, points)`` of ``spec``: what :func:`solve_chunk` takes, for
    callers that run the points themselves (the service's job runner, with a time limit per point)."""
    norm = validate_spec(spec)
    header = {k: norm[k] for k in ("analysis", "manipulator", "options")}
    return header, _parameter_columns(norm), list(_result_types(header)), expand(norm)

