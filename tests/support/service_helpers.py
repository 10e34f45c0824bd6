"""What the service's tests share: an app in a ``TestClient`` with the tests' settings, the library's JSON body as
the service renders it, and the checks of a 200 and of a 422.

The tests' settings raise the time limits (``solve_timeout``, ``batch_timeout``) to :data:`GENEROUS_SECONDS`: a test
that expects an answer gets it on a loaded machine too (at the default 10 s a loaded machine answers 504). A test of
a time limit sets its own, with a stand-in that runs out on any machine (``tests/support/clocks.py``, or a task
that blocks far beyond the limit).
"""

from __future__ import annotations

import json
import warnings

with warnings.catch_warnings():
    warnings.simplefilter("ignore")
    from fastapi.testclient import TestClient

from servers import GENEROUS_ENV, GENEROUS_SECONDS, WAIT_SECONDS  # noqa: F401 - the tests' one set of bounds

from service.config import Settings
from service.main import create_app
from service.responses import render_json


def service_settings(**overrides) -> Settings:
    """The service's settings for a test: no warm-up, generous time limits, then ``overrides``."""
    return Settings(**{"warmup": False, "solve_timeout": GENEROUS_SECONDS, "batch_timeout": GENEROUS_SECONDS,
                       **overrides})


def app_client(**overrides) -> TestClient:
    """A ``TestClient`` of the app with :func:`service_settings` (use it as a context manager)."""
    return TestClient(create_app(service_settings(**overrides)))


def body_of(result) -> dict:
    """The library's JSON form as the service renders it."""
    return json.loads(render_json(result))


def post_ok(client, path, body) -> dict:
    """POST ``body``; the answer must be 200; its JSON."""
    r = client.post(path, json=body)
    assert r.status_code == 200, r.text
    return r.json()


def check_error(r, code, field=None) -> dict:
    """The answer is a 422 with the error ``code`` (and ``field``); its JSON."""
    assert r.status_code == 422, r.text
    b = r.json()
    assert b["code"] == code, b
    if field is not None:
        assert b.get("field") == field, b
    return b


def without_seconds(d: dict) -> dict:
    """A body without its ``seconds`` (the time a computation took differs between two runs)."""
    return {k: v for k, v in d.items() if k != "seconds"}
