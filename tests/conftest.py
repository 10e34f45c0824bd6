"""Test-wide settings and the suite's markers.

The folders mirror the code (``tests/model``, ``tests/numerics``, ``tests/analyses/<package>``,
``tests/applications/<package>``, ``tests/service``) plus ``tests/browser`` (the page in Chromium),
``tests/docs`` (the documentation site and the notebook), ``tests/client`` (the generated typed client) and
``tests/support`` (the shared helpers, the independent reference models and their own tests).
Markers, set here by folder (``service``, ``browser``, ``docs``) or on the test (``slow``, ``slow_cases``):

* ``slow`` - longer than the fast lane affords (``python -m pytest -m "not slow"``, the developer's check
  after every change; every test file keeps tests in it, so that the lane fails when any module breaks);
* ``slow_cases(keep=k)`` - on a parametrized test: its first ``k`` cases stay in the fast lane, the others are
  ``slow``;
* ``service`` - needs the ``service`` extra (FastAPI, uvicorn ...): everything under ``tests/service``,
  ``tests/browser`` and ``tests/client`` (the client's tests are ``slow`` too: a real server, the generator);
* ``browser`` - drives Chromium;
* ``docs`` - builds the documentation site or runs the notebook.

The service's job store never touches the working directory. This file imports no part of the service: the
library's tests run without the service extra (``tests/test_library_alone.py``).
"""

from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent

#: Markers of every test below a folder (relative to ``tests/``).
FOLDER_MARKERS = {
    "service": ("service",),
    "browser": ("browser", "service", "slow"),
    "client": ("service", "slow"),
    "docs": ("docs", "slow"),
}


@pytest.hookimpl(tryfirst=True)       # before pytest deselects by marker (-m)
def pytest_collection_modifyitems(config, items):
    seen: dict[tuple[str, str], int] = {}
    for item in items:
        try:
            top = Path(str(item.fspath)).resolve().relative_to(HERE).parts[0]
        except ValueError:
            top = None
        for name in FOLDER_MARKERS.get(top, ()):
            item.add_marker(getattr(pytest.mark, name))
        cases = item.get_closest_marker("slow_cases")
        if cases is not None:
            key = (str(item.fspath), item.originalname)
            seen[key] = seen.get(key, 0) + 1
            if seen[key] > cases.kwargs.get("keep", 1):
                item.add_marker(pytest.mark.slow)


@pytest.fixture(autouse=True)
def _jobs_db_in_tmp(tmp_path, monkeypatch):
    monkeypatch.setenv("TENSEGRITY_JOBS_DB", str(tmp_path / "jobs.sqlite3"))
