"""The committed OpenAPI document is exactly what ``tensegrity-opt openapi`` prints, and it is complete."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("fastapi")

from service.main import openapi_json

ROOT = Path(__file__).resolve().parents[2]
SPEC = ROOT / "openapi" / "openapi.json"
REGENERATE = "regenerate it with: tensegrity-opt openapi > openapi/openapi.json"


def test_committed_spec_is_current():
    assert SPEC.exists(), REGENERATE
    assert SPEC.read_text(encoding="utf-8") == openapi_json(), f"openapi/openapi.json is stale; {REGENERATE}"


@pytest.mark.slow
def test_cli_prints_the_spec(monkeypatch):
    env = {k: v for k, v in os.environ.items() if not k.startswith("TENSEGRITY_")}
    env["TENSEGRITY_MAX_SEGMENTS"] = "7"          # settings never change the document
    env["TENSEGRITY_API_KEYS"] = "x"
    out = subprocess.run([sys.executable, "-m", "service", "openapi"], capture_output=True, text=True,
                         env=env, cwd=ROOT, timeout=120, check=True).stdout
    assert out == SPEC.read_text(encoding="utf-8")


FIGURE_KINDS = ("curve", "landscape", "shapes", "modes", "holding", "torque", "map", "branch", "limit-load",
                "imperfection", "boundary", "atlas", "plan", "simulation")


def test_every_operation_is_documented():
    doc = json.loads(SPEC.read_text(encoding="utf-8"))
    ops = {(path, method): op for path, item in doc["paths"].items() for method, op in item.items()}
    expected = {("/v1/equilibrium", "post"), ("/v1/equilibrium/force", "post"), ("/v1/equilibria", "post"),
                ("/v1/buckling", "post"), ("/v1/force-deflection", "post"), ("/v1/stiffness", "post"),
                ("/v1/modes", "post"),
                ("/v1/segment/torque", "post"), ("/v1/energy-landscape", "post"), ("/v1/batch/equilibrium", "post"),
                ("/healthz", "get"), ("/readyz", "get"), ("/version", "get"), ("/metrics", "get"),
                ("/v1/design/critical-force", "post"), ("/v1/design/preloads", "post"),
                ("/v1/design/holding", "post"), ("/v1/control/weight-capacity", "post"),
                ("/v1/design/preloads-for-load", "post"),
                ("/v1/rest-configurations", "post"), ("/v1/branch", "post"), ("/v1/bifurcation-diagram", "post"),
                ("/v1/limit-load", "post"), ("/v1/imperfection-sensitivity", "post"),
                ("/v1/stability-boundary", "post"),
                ("/v1/atlas", "post"),
                ("/v1/control/plan", "post"), ("/v1/control/simulate", "post"), ("/v1/control/force-estimate", "post"),
                ("/v1/control/stiffness", "post"), ("/v1/control/load-capacity", "post"),
                *((f"/v1/plots/{kind}", "post") for kind in FIGURE_KINDS),
                ("/v1/jobs", "post"), ("/v1/jobs", "get"), ("/v1/jobs/{job_id}", "get"),
                ("/v1/jobs/{job_id}", "delete"), ("/v1/jobs/{job_id}/cancel", "post"),
                ("/v1/jobs/{job_id}/results", "get"), ("/v1/jobs/{job_id}/atlas", "get"),
                ("/v1/jobs/{job_id}/figure", "get"),
                *((f"/v1/plots/{kind}/job", "post") for kind in FIGURE_KINDS)}
    assert set(ops) == expected
    ids = [op["operationId"] for op in ops.values()]
    assert len(ids) == len(set(ids))
    error_ref = "#/components/schemas/ErrorOut"
    for (path, method), op in ops.items():
        assert op.get("summary"), path
        if path.startswith("/v1/jobs"):      # no solve: 202 on submit, 404 for ids, 503 = job store
            ok = op["responses"]["202" if (path, method) == ("/v1/jobs", "post") else "200"] if method != "delete" \
                else None
            assert ok is None or any("example" in m or "examples" in m for m in ok["content"].values()), path
            if method == "delete":
                assert "content" not in op["responses"]["204"], path          # no body
            assert op.get("security") == [{"ApiKey": []}, {}]     # optional: only servers with keys
            for status in ("401", "422", "503") + (("404",) if "{job_id}" in path else ()) + \
                    (("413",) if (path, method) == ("/v1/jobs", "post") else ()):
                c = op["responses"][status]["content"]["application/json"]
                assert c["schema"]["$ref"] == error_ref and c.get("examples"), (path, status)
            if (path, method) == ("/v1/jobs", "post"):
                assert op["requestBody"]["content"]["application/json"].get("examples")
            continue
        if path.endswith("/job"):            # a figure as a job: 202 with the job, the figure's refusals, the store's
            assert op["responses"]["202"]["content"]["application/json"].get("example"), path
            assert op["requestBody"]["content"]["application/json"].get("examples"), path
            assert op.get("security") == [{"ApiKey": []}, {}]
            for status in ("401", "413", "422", "503"):
                c = op["responses"][status]["content"]["application/json"]
                assert c["schema"]["$ref"] == error_ref and c.get("examples"), (path, status)
            continue
        ok = op["responses"]["200"]["content"]
        assert any("example" in media or "examples" in media for media in ok.values()), path
        if path.startswith("/v1/"):
            media = op["requestBody"]["content"]["application/json"]
            assert media.get("examples"), path
            assert op.get("security") == [{"ApiKey": []}, {}]     # optional: only servers with keys
            for status in ("401", "413", "422", "503", "504"):
                resp = op["responses"][status]
                assert resp["description"]
                content = resp["content"]["application/json"]
                assert content["schema"]["$ref"] == error_ref, (path, status)
                assert content.get("examples"), (path, status)
            assert "Retry-After" in op["responses"]["503"]["headers"]
    err = doc["components"]["schemas"]["ErrorOut"]
    assert set(err["required"]) == {"code", "message"}
    assert {"code", "message", "field", "status", "errors"} <= set(err["properties"])
