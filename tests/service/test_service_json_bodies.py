"""JSON bodies and stream messages: a key given twice in one object is refused (422 naming it), on every operation.

``{"n": 4, "n": 200}`` read last-wins is n = 200, while anything keeping the first key (a proxy, a log, a cache)
sees n = 4. Every operation with a JSON body is checked (its example from the OpenAPI document with its first key
given twice), the key's path is the error's field (in a nested object, in a list), and a stream message the same.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from fastapi.routing import APIRoute
from fastapi.testclient import TestClient
from service_helpers import service_settings

from service.api.json_bodies import DuplicateKey, JSONBodyRoute, loads
from service.main import create_app

DOCUMENT = Path(__file__).resolve().parents[2] / "openapi" / "openapi.json"
PAPER = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}


@pytest.fixture(scope="module")
def app(tmp_path_factory):
    return create_app(service_settings(inline_processes=0, heavy_workers=0,
                                       jobs_db=str(tmp_path_factory.mktemp("jobs") / "jobs.sqlite3")))


@pytest.fixture(scope="module")
def client(app):
    with TestClient(app, raise_server_exceptions=False) as c:
        yield c


def _post(client: TestClient, path: str, text: str):
    return client.post(path, content=text.encode(), headers={"Content-Type": "application/json"})


def _duplicate(r, field: str, key: str) -> None:
    assert r.status_code == 422, r.text
    body = r.json()
    assert body["code"] == "validation_error" and body["field"] == field, body
    assert body["errors"][0]["type"] == "duplicate_key" and repr(key) in body["message"], body


def test_the_issue_body_is_refused_naming_the_key(client):
    _duplicate(_post(client, "/v1/equilibrium", '{"manipulator": {"n": 4, "n": 200}, "dx": 0.1}'), "manipulator.n", "n")
    _duplicate(_post(client, "/v1/equilibrium", '{"manipulator": {"n": 4}, "dx": 0.1, "dx": 0.2}'), "dx", "dx")
    segments = '{"manipulator": {"segments": [{"a": 1, "b": 1}, {"a": 1, "b": 1, "a": 2}]}, "dx": 0.1}'
    _duplicate(_post(client, "/v1/equilibrium", segments), "manipulator.segments[1].a", "a")
    # the same body without the duplicate is answered, and text that is not JSON keeps its own refusal
    assert _post(client, "/v1/equilibrium", '{"manipulator": {"n": 4}, "dx": 0.1}').status_code == 200
    bad = _post(client, "/v1/equilibrium", '{"manipulator": ')
    assert bad.status_code == 422 and bad.json()["errors"][0]["type"] == "json_invalid", bad.text


def test_a_job_with_a_duplicate_key_is_refused_and_not_stored(client):
    text = '{"analysis": "buckling", "analysis": "equilibrium", "manipulator": {"n": 4}, "points": [{"dx": 0.1}]}'
    _duplicate(_post(client, "/v1/jobs", text), "analysis", "analysis")
    assert client.get("/v1/jobs").json()["jobs"] == []


def _operations_with_bodies() -> list[tuple[str, dict[str, Any]]]:
    doc = json.loads(DOCUMENT.read_text())
    out = []
    for path, ops in doc["paths"].items():
        for method, op in ops.items():
            content = op.get("requestBody", {}).get("content", {}).get("application/json")
            if content is None:
                continue
            assert method == "post", path
            examples = content.get("examples") or {}
            example = next(iter(examples.values()))["value"] if examples else content.get("example")
            assert isinstance(example, dict) and example, f"{path}: no example body"
            out.append((path, example))
    return out


@pytest.mark.parametrize(("path", "example"), _operations_with_bodies(), ids=lambda v: v if isinstance(v, str) else "")
def test_every_operation_refuses_a_duplicate_key(client, path, example):
    key = next(iter(example))
    text = json.dumps(example)
    doubled = "{" + json.dumps(key) + ": " + json.dumps(example[key]) + ", " + text[1:]
    _duplicate(_post(client, path, doubled), key, key)


def _routes(routes):
    """The app's routes, those of its included routers in place (FastAPI's effective candidates)."""
    for r in routes:
        nested = getattr(r, "effective_candidates", None)
        if callable(nested):
            yield from _routes(nested())
        else:
            yield getattr(r, "original_route", r)


def test_every_route_with_a_body_decodes_it_in_one_place(app):
    with_body = [r for r in _routes(app.routes) if isinstance(r, APIRoute) and r.body_field is not None]
    assert len(with_body) >= 30 and all(isinstance(r, JSONBodyRoute) for r in with_body), \
        [r.path for r in with_body if not isinstance(r, JSONBodyRoute)]


def test_loads_gives_the_path_of_the_first_duplicate():
    assert loads('{"a": [1, {"b": 2}], "c": {"d": 3}}') == {"a": [1, {"b": 2}], "c": {"d": 3}}
    with pytest.raises(DuplicateKey) as e:
        loads('{"a": [1, {"b": 2, "b": 3}], "c": 1}')
    assert e.value.key == "b" and e.value.path == ("a", 1)
    with pytest.raises(DuplicateKey) as e:
        loads('{"x": {}, "x": {}}')
    assert e.value.key == "x" and e.value.path == ()


def test_a_stream_message_with_a_duplicate_key_is_refused(client):
    with client.websocket_connect("/v1/control/stream") as ws:
        ws.send_text('{"type": "open", "mode": "track", "manipulator": {"n": 4, "n": 200}}')
        e = ws.receive_json()
        assert e["type"] == "error" and e["code"] == "validation_error" and e["field"] == "manipulator.n", e
    with client.websocket_connect("/v1/control/stream") as ws:
        ws.send_json({"type": "open", "manipulator": PAPER, "mode": "track"})
        assert ws.receive_json()["type"] == "opened"
        ws.send_text('{"type": "step", "dx": 0.1, "dx": 0.2}')
        e = ws.receive_json()
        assert e["type"] == "error" and e["code"] == "validation_error" and e["field"] == "dx", e
        ws.send_json({"type": "step", "dx": 0.1})             # the stream goes on
        assert ws.receive_json()["type"] == "result"
