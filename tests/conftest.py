"""Test-wide settings: the service's job store never touches the working directory."""

import pytest


@pytest.fixture(autouse=True)
def _jobs_db_in_tmp(tmp_path, monkeypatch):
    monkeypatch.setenv("TENSEGRITY_JOBS_DB", str(tmp_path / "jobs.sqlite3"))
