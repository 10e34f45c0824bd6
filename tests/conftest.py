"""Test-wide settings and the suite's markers.

The folders mirror the code (``tests/model``, ``tests/numerics``, ``tests/analyses/<package>``,
``tests/applications/<package>``, ``tests/service``) plus ``tests/browser`` (the page in Chromium),
``tests/docs`` (the documentation site and the notebook) and ``tests/client`` (the generated typed client).
Markers, set here by folder (``service``, ``browser``, ``docs``) or on the test (``slow``):

* ``slow`` - longer than the fast lane affords (``python -m pytest -m "not slow"``, the developer's check
  after every change);
* ``service`` - needs the ``service`` extra (FastAPI, uvicorn ...): everything under ``tests/service``,
  ``tests/browser`` and ``tests/client``;
* ``browser`` - drives Chromium;
* ``docs`` - builds the documentation site or runs the notebook.

The service's job store never touches the working directory.
"""

from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent

#: Markers of every test below a folder (relative to ``tests/``).
FOLDER_MARKERS = {
    "service": ("service",),
    "browser": ("browser", "service", "slow"),
    "client": ("service",),
    "docs": ("docs", "slow"),
}


def pytest_collection_modifyitems(config, items):
    for item in items:
        try:
            top = Path(str(item.fspath)).resolve().relative_to(HERE).parts[0]
        except ValueError:
            continue
        for name in FOLDER_MARKERS.get(top, ()):
            item.add_marker(getattr(pytest.mark, name))


@pytest.fixture(autouse=True)
def _jobs_db_in_tmp(tmp_path, monkeypatch):
    monkeypatch.setenv("TENSEGRITY_JOBS_DB", str(tmp_path / "jobs.sqlite3"))
