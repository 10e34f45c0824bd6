"""Nested lists of one length: a ragged one is a 422 naming its field, on every field where JSON Schema allows it.

``sigma_q: [[0.001, 0, 0, 0], [0, 0.001], ...]`` reached numpy as an "inhomogeneous shape" (a 500). Every request
field that is a list of lists whose inner lengths the document does not fix (a covariance matrix, the per-segment
rest lengths of every step, a job's per-segment bounds) is found by walking the OpenAPI document; each has a ragged
body below, refused by the shared type (``service.schemas.common.rectangular`` / ``OneLength``).
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from fastapi.testclient import TestClient
from service_helpers import service_settings

from service.main import create_app
from service.schemas.common import same_lengths

DOCUMENT = Path(__file__).resolve().parents[2] / "openapi" / "openapi.json"
CHAIN = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}
Q = [0.742754, 0.522806, 0.297158, 0.0953]

#: (operation, field as the document's walk names it): a ragged body and the field the refusal names.
RAGGED: dict[tuple[str, str], tuple[dict[str, Any], str]] = {
    ("/v1/control/force-estimate", "sigma_q"): (
        {"manipulator": CHAIN, "q_measured": Q,
         "sigma_q": [[0.001, 0, 0, 0], [0, 0.001], [0, 0, 0.001, 0], [0, 0, 0, 0.001]]}, "sigma_q"),
    ("/v1/control/simulate", "preloads"): (
        {"manipulator": CHAIN, "preloads": [[[1.0, 1.0]] * 4, [[1.1, 0.9]] * 3]}, "preloads"),
    ("/v1/plots/simulation", "preloads"): (
        {"manipulator": CHAIN, "preloads": [[[1.0, 1.0]] * 4, [[1.1, 0.9]] * 3]}, "preloads"),
    ("/v1/plots/simulation/job", "preloads"): (
        {"manipulator": CHAIN, "preloads": [[[1.0, 1.0]] * 4, [[1.1, 0.9]] * 3]}, "preloads"),
    **{(path, "bounds"): ({"manipulator": CHAIN, "targets": [[7.0, 1.0]], "bounds": [[0.5] * 8, [2.0] * 7]}, "bounds")
       for path in ("/v1/control/plan", "/v1/plots/plan", "/v1/plots/plan/job")},
    ("/v1/control/stiffness", "bounds"): (
        {"manipulator": CHAIN, "target": [7.0, 1.0], "eig_bounds": [0.04, 0.6], "bounds": [[0.5] * 8, [2.0] * 7]},
        "bounds"),
    ("/v1/design/preloads", "bounds"): (
        {"manipulator": CHAIN, "target": [7.0, 1.5], "bounds": [[0.5] * 8, [2.0] * 7]}, "bounds"),
    ("/v1/design/preloads-for-load", "bounds"): (
        {"manipulator": CHAIN, "required": 1.0, "bounds": [[0.2] * 4, [2.0] * 3]}, "bounds"),
    ("/v1/design/critical-force", "bounds.*"): (
        {"manipulator": CHAIN, "vary": ["k"], "bounds": {"k": [[0.2] * 4, [5.0] * 3]}}, "bounds.k"),
    ("/v1/jobs", "options.bounds.*"): (
        {"analysis": "design", "manipulator": CHAIN, "grid": {"k": [1.0]},
         "options": {"vary": ["k"], "bounds": {"k": [[0.2] * 4, [5.0] * 3]}}}, "options.bounds.k"),
}


def _variants(schema: dict[str, Any], components: dict[str, Any]):
    while "$ref" in schema:
        schema = components[schema["$ref"].rsplit("/", 1)[-1]]
    forms = [v for key in ("anyOf", "oneOf", "allOf") for v in schema.get(key, [])]
    if not forms:
        yield schema
    for v in forms:
        yield from _variants(v, components)


def _ragged_fields(schema: dict[str, Any], components: dict[str, Any], path: str = "") -> set[str]:
    """The fields under ``schema`` that are lists of lists of no fixed inner length."""
    out: set[str] = set()
    for v in _variants(schema, components):
        if v.get("type") == "object":
            for key, sub in v.get("properties", {}).items():
                out |= _ragged_fields(sub, components, f"{path}.{key}" if path else key)
            if isinstance(v.get("additionalProperties"), dict):
                out |= _ragged_fields(v["additionalProperties"], components, f"{path}.*")
        elif v.get("type") == "array":
            items = v.get("items", {})
            for iv in _variants(items, components):
                if iv.get("type") == "array" and not (iv.get("minItems") is not None
                                                       and iv.get("minItems") == iv.get("maxItems")):
                    out.add(path)
            out |= _ragged_fields(items, components, path)
    return out


def _document_fields() -> set[tuple[str, str]]:
    doc = json.loads(DOCUMENT.read_text())
    components = doc["components"]["schemas"]
    found = set()
    for path, ops in doc["paths"].items():
        for op in ops.values():
            schema = op.get("requestBody", {}).get("content", {}).get("application/json", {}).get("schema")
            if schema is not None:
                found |= {(path, field) for field in _ragged_fields(schema, components)}
    return found


def test_the_table_has_every_field_that_can_be_ragged():
    assert _document_fields() == set(RAGGED), "give each new list of lists a ragged case (and the shared type)"


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    settings = service_settings(inline_processes=0, heavy_workers=0,
                                jobs_db=str(tmp_path_factory.mktemp("jobs") / "jobs.sqlite3"))
    with TestClient(create_app(settings), raise_server_exceptions=False) as c:
        yield c


@pytest.mark.parametrize(("path", "field"), sorted(RAGGED))
def test_a_ragged_list_is_a_422_naming_its_field(client, path, field):
    body, named = RAGGED[path, field]
    r = client.post(path, json=body)
    assert r.status_code == 422, r.text
    err = r.json()
    # valid by the document (JSON Schema cannot say "rows of one length"): a domain refusal, as the library's own
    assert err["code"] == "invalid_parameter" and err["field"] == named, err
    assert "one length" in err["message"], err


def test_lists_of_one_length_pass():
    assert same_lengths([[1, 2], [3, 4]]) == [[1, 2], [3, 4]]
    assert same_lengths([0.2, [1, 2, 3], 5.0, [4, 5, 6]]) == [0.2, [1, 2, 3], 5.0, [4, 5, 6]]
    with pytest.raises(ValueError, match="item 0 has 2 entries, item 2 has 1"):
        same_lengths([[1, 2], 7.0, [3]])
