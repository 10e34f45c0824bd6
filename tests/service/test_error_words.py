"""A misspelt field leads the refusal, with the nearest valid name (one error mapping for every body)."""

from __future__ import annotations

import time

import pytest

pytest.importorskip("fastapi")

from fastapi.testclient import TestClient  # noqa: E402
from service_helpers import WAIT_SECONDS, service_settings  # noqa: E402

from service.api.errors import field_names, validation_body  # noqa: E402
from service.main import create_app  # noqa: E402


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    db = tmp_path_factory.mktemp("words") / "jobs.sqlite3"
    with TestClient(create_app(service_settings(inline_processes=0, jobs_db=str(db)))) as c:
        yield c


@pytest.mark.parametrize(("path", "body", "field", "guess"), [
    ("/v1/equilibrium", {"manipulator": {"n": 4}, "dX": 0.1}, "dX", "dx"),
    ("/v1/equilibrium", {"manipulator": {"n": 4, "l0": 1.0}, "dx": 0.1}, "manipulator.l0", "L0"),
    ("/v1/buckling", {"manipulator": {"segments": [{"a": 1, "b": 1, "kk": 1}]}}, "manipulator.segments[0].kk", "k"),
    ("/v1/design/critical-force", {"manipulator": {"n": 3}, "bounds": {"k": {"lo": 1, "high": 2}}}, "bounds.k.high",
     "hi"),
    ("/v1/jobs", {"analysis": "design", "grid": {"n": [3]}, "options": {"bonds": {"k": [1, 2]}}}, "options.bonds",
     "bounds"),
    ("/v1/jobs", {"analysis": "buckling", "grid": {"N": [3]}}, "grid.N", "n"),
])
def test_a_misspelt_field_leads_with_the_nearest_name(client, path, body, field, guess):
    r = client.post(path, json=body)
    assert r.status_code == 422, r.text
    err = r.json()
    assert err["code"] == "validation_error" and err["field"] == field, err
    assert err["message"].startswith(f"{field}: unknown field; did you mean {guess}?"), err
    assert err["errors"][0] == {"field": field, "message": f"unknown field; did you mean {guess}?",
                                "type": "extra_forbidden"}


def test_a_name_far_from_every_field_lists_them(client):
    err = client.post("/v1/equilibrium", json={"manipulator": {"n": 4}, "dx": 0.1, "zzzz": 1}).json()
    assert err["message"] == "zzzz: unknown field; expected one of manipulator, dx, dy, q0, local, certify", err


def test_without_the_schema_the_unknown_field_still_leads():
    errors = [{"type": "missing", "loc": ("body", "dx"), "msg": "Field required"},
              {"type": "extra_forbidden", "loc": ("body", "dX"), "msg": "Extra inputs are not permitted"}]
    body = validation_body(errors)
    assert body["field"] == "dX" and body["message"] == "dX: unknown field (and 1 more)"


def test_field_names_follow_refs_unions_lists_and_maps():
    defs = {"S": {"type": "object", "properties": {"a": {}, "L0": {}}},
            "B": {"type": "object", "properties": {"lo": {}, "hi": {}}}}
    schema = {"type": "object", "properties": {
        "manipulator": {"oneOf": [{"type": "object", "properties": {"n": {}}},
                                  {"type": "object", "properties": {"segments": {
                                      "type": "array", "items": {"$ref": "#/components/schemas/S"}}}}]},
        "bounds": {"type": "object", "additionalProperties": {"anyOf": [{"type": "array"},
                                                                       {"$ref": "#/components/schemas/B"}]}}}}
    assert field_names(schema, defs, ("body",)) == ["manipulator", "bounds"]
    assert field_names(schema, defs, ("body", "manipulator", "segments", 2)) == ["a", "L0"]
    assert field_names(schema, defs, ("body", "bounds", "k", "<object>")) == ["lo", "hi"]


def test_a_design_row_says_the_input_chain_is_invalid(client):
    # a = 0.5, L0 = 1: the straight chain is unstable for every k; the row blames the input, not the optimiser
    r = client.post("/v1/jobs", json={"analysis": "design", "manipulator": {"n": 3, "a": 0.5}, "grid": {"n": [3]}})
    assert r.status_code in (200, 201, 202), r.text
    job_id, deadline = r.json()["id"], time.monotonic() + WAIT_SECONDS
    while (job := client.get(f"/v1/jobs/{job_id}").json())["status"] in ("queued", "running"):
        assert time.monotonic() < deadline, job
        time.sleep(0.05)
    (row,) = job["results"]
    assert row["error"].startswith("design_infeasible: the input chain is not a valid chain"), row
    assert "optimiser's design" not in row["error"]
