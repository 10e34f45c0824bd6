"""schemathesis against the committed openapi/openapi.json and a real server (bounded, fixed seed).

Zero server errors and zero responses violating the spec. The server runs with smaller limits
(as a deployment facing generated traffic would) so that no generated input runs into the solve
time limit; every endpoint and every schema branch is still exercised.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from servers import clean_env, free_port, running_server, serve_command

pytest.importorskip("httpx")
ROOT = Path(__file__).resolve().parents[1]


def schemathesis_command() -> list[str] | None:
    exe = shutil.which("schemathesis") or str(Path(sys.executable).with_name("schemathesis"))
    return [exe] if Path(exe).exists() else None


@pytest.mark.skipif(schemathesis_command() is None, reason="schemathesis is not installed (pip install '.[test]')")
def test_schemathesis_finds_no_server_error_and_no_spec_violation(tmp_path):
    env = clean_env(TENSEGRITY_MAX_SEGMENTS="24", TENSEGRITY_MAX_BATCH="50", TENSEGRITY_SOLVE_TIMEOUT="60",
                    TENSEGRITY_BATCH_TIMEOUT="30", TENSEGRITY_JOBS_DB=str(tmp_path / "jobs.sqlite3"),
                    TENSEGRITY_JOBS_MAX_POINTS="200", TENSEGRITY_HOMOTOPY_MAX_SEGMENTS="2")
    with running_server(serve_command(free_port()), env, ready="/readyz", stdout=subprocess.DEVNULL) as (_, base):
        run = subprocess.run(
            [*schemathesis_command(), "run", str(ROOT / "openapi" / "openapi.json"), "--url", base,
             "--max-examples", "20", "--seed", "1", "--checks", "not_a_server_error,response_schema_conformance",
             "--generation-database", "none", "--request-timeout", "120"],
            cwd=tmp_path, capture_output=True, text=True, timeout=900)
    assert run.returncode == 0, run.stdout[-6000:] + run.stderr[-2000:]
