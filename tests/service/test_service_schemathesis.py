"""schemathesis against the committed openapi/openapi.json and a real server at its default limits.

Every check of correctness (server errors, status codes, content types, headers and bodies against the document,
positive data accepted, negative data refused, Allow headers, auth, use after free ...: :data:`CHECKS`) and every
phase (examples, coverage, fuzzing, stateful), bounded (``--max-examples``) with a fixed seed (hypothesis' health
checks, about generation speed, are off). Not checked: how fast the server answers (schemathesis'
``max_response_time``), which says nothing about the document and everything about how busy the machine is. The
server runs at its *default* limits on what it accepts (only the job store is moved to a temporary file): the
document says exactly what it accepts. Its time limits (``solve_timeout``, ``batch_timeout``) are raised: at the
default 10 s a loaded machine answers 504, which ``not_a_server_error`` counts. ``schemathesis_hooks`` bounds the cost
of the generated requests within the valid range (see there) and adds a check that a request the
document calls valid is never refused as a schema violation or over an undocumented limit.

A second run goes without the hooks (:data:`CONFIG_WITHOUT_HOOKS`): the requests as schemathesis generates them, at
every cost the document allows, under short time limits; its 503/504 answers (the documented refusals of what the
machine cannot do in time) are expected, any other 5xx is a failure.

``positive_data_acceptance`` also accepts 422: a valid request may still be refused for a domain
reason the schema cannot say (an unreachable target, an unstable straight chain, ...), answered as
a documented ``ErrorOut`` with its code; the added check makes sure that is never ``validation_error``.
"""

from __future__ import annotations

import copy
import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path
from types import SimpleNamespace

import pytest
from servers import GENEROUS_ENV, WAIT_SECONDS, clean_env, free_port, running_server, serve_command

pytest.importorskip("httpx")
ROOT = Path(__file__).resolve().parents[2]
HERE = ROOT / "tests" / "support"   # schemathesis_hooks.py

#: schemathesis' checks of correctness: every built-in check but ``max_response_time``, and the hooks' own.
CHECKS = ("not_a_server_error", "status_code_conformance", "content_type_conformance", "response_headers_conformance",
          "response_schema_conformance", "negative_data_rejection", "positive_data_acceptance",
          "missing_required_header", "unsupported_method", "allow_header_conformance", "use_after_free",
          "ensure_resource_availability", "ignored_auth", "object_level_authorization",
          "positive_data_is_accepted_by_the_schema")

CONFIG = """\
[checks.positive_data_acceptance]
expected-statuses = ["2xx", "401", "403", "404", "409", "422", "429"]

# Figures and design NLPs are the expensive operations (matplotlib, IPOPT): fewer examples there, fewest for the
# figures, whose bodies are their JSON operations' (run with 16 examples: the CI budget) plus format and dpi.
[[operations]]
include-path-regex = "^/v1/design/"
generation.max-examples = 10

# The imperfection curve is a limit-load path per amplitude and the perfect chain's buckled arms: as the designs.
[[operations]]
include-path-regex = "^/v1/imperfection-sensitivity"
generation.max-examples = 10

# A figure's body is its JSON operation's (plus format and dpi), whose boundary cases the coverage phase runs
# there: the figures keep the examples, fuzzing and stateful phases (the figures' coverage cases were ~40% of
# the run, ~150 s of the CI budget).
[[operations]]
include-path-regex = "^/v1/plots/"
generation.max-examples = 6
phases.coverage.enabled = false
"""


def schemathesis_command() -> list[str] | None:
    exe = shutil.which("schemathesis") or str(Path(sys.executable).with_name("schemathesis"))
    return [exe] if Path(exe).exists() else None


@pytest.mark.skipif(schemathesis_command() is None, reason="schemathesis is not installed (pip install '.[test]')")
def test_the_checks_are_every_check_of_schemathesis_but_the_response_time():
    """:data:`CHECKS` names every built-in check the installed schemathesis offers (its ``--exclude-checks``
    choices, which leave out ``max_response_time``), so that a check a new version adds is run too."""
    run = subprocess.run([*schemathesis_command(), "run", "--help"], capture_output=True, text=True,
                         timeout=WAIT_SECONDS, check=True)
    text = " ".join(run.stdout.split())
    offered = re.search(r"--exclude-checks .*?\[possible values: ([^\]]*)\]", text).group(1)
    builtin = {name.strip() for name in offered.split(",")} - {"all"}
    assert "max_response_time" not in builtin and builtin == set(CHECKS) - {"positive_data_is_accepted_by_the_schema"}


def _mapped(hooks, path: str, body: dict, negative: bool = False) -> dict:
    """``body`` as the hooks map a generated case of ``POST path`` (positive, or negative)."""
    mode = SimpleNamespace(is_negative=negative)
    case = SimpleNamespace(body=copy.deepcopy(body), operation=SimpleNamespace(path=path),
                           meta=SimpleNamespace(generation=SimpleNamespace(mode=mode)))
    return hooks.map_case(None, case).body


def test_the_hooks_bound_the_imperfection_curve_and_the_plan_and_their_figure_jobs():
    """A positive case of the imperfection-sensitivity curve keeps 3 amplitudes of at most 400 points; a plan keeps
    4 steps of its per-step lists (``times`` with its targets) and a horizon of at most 4; a figure job's body is
    bounded as its figure's; a negative case keeps its values."""
    pytest.importorskip("schemathesis")
    import schemathesis_hooks as hooks

    chain = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}
    curve = {"manipulator": chain, "amplitudes": [0.01 * i for i in range(10)], "max_points": 4000}
    for path in ("/v1/imperfection-sensitivity", "/v1/plots/imperfection", "/v1/plots/imperfection/job"):
        got = _mapped(hooks, path, curve)
        assert got["amplitudes"] == [0.0, 0.01, 0.02] and got["max_points"] == 400, path
        assert _mapped(hooks, path, curve, negative=True)["amplitudes"] == curve["amplitudes"], path
    assert _mapped(hooks, "/v1/imperfection-sensitivity", {**curve, "max_points": 50})["max_points"] == 50
    targets = [[7.6 - 0.1 * i, 0.25 * i] for i in range(8)]
    plan = {"manipulator": chain, "targets": targets, "times": [0.5 * (i + 1) for i in range(8)],
            "rate_limit": 0.1, "horizon": 7}
    for path in ("/v1/control/plan", "/v1/plots/plan", "/v1/plots/plan/job"):
        got = _mapped(hooks, path, plan)
        assert got["targets"] == targets[:4] and got["times"] == [0.5, 1.0, 1.5, 2.0] and got["horizon"] == 4, path
        assert _mapped(hooks, path, {**plan, "horizon": "all"})["horizon"] == "all", path
        assert _mapped(hooks, path, {**plan, "horizon": 2})["horizon"] == 2, path
        negative = _mapped(hooks, path, plan, negative=True)
        assert negative["times"] == plan["times"] and negative["horizon"] == 7, path


@pytest.mark.slow
@pytest.mark.skipif(schemathesis_command() is None, reason="schemathesis is not installed (pip install '.[test]')")
def test_schemathesis_every_correctness_check_and_phase_at_the_default_limits(tmp_path):
    env = clean_env(TENSEGRITY_JOBS_DB=str(tmp_path / "jobs.sqlite3"), **GENEROUS_ENV)
    config = tmp_path / "schemathesis.toml"
    config.write_text(CONFIG, encoding="utf-8")
    hooks_env = {**env, "SCHEMATHESIS_HOOKS": "schemathesis_hooks",
                 "PYTHONPATH": os.pathsep.join([str(HERE), env.get("PYTHONPATH", "")]).rstrip(os.pathsep)}
    with running_server(serve_command(free_port()), env, ready="/readyz", stdout=subprocess.DEVNULL,
                        timeout=WAIT_SECONDS) as (_, base):
        start = time.monotonic()
        run = subprocess.run(
            [*schemathesis_command(), "--config-file", str(config), "run", str(ROOT / "openapi" / "openapi.json"),
             "--url", base, "--checks", ",".join(CHECKS),
             "--phases", "examples,coverage,fuzzing,stateful", "--suppress-health-check", "all",
             "--max-examples", "16", "--seed", "1", "--generation-database", "none", "--request-timeout", "600"],
            cwd=tmp_path, env=hooks_env, capture_output=True, text=True, timeout=3600)
        took = time.monotonic() - start
    print(f"schemathesis: {took:.0f} s")
    (tmp_path / "schemathesis.out").write_text(run.stdout + run.stderr, encoding="utf-8")
    assert run.returncode == 0, run.stdout[:3000] + "\n...\n" + run.stdout[-9000:] + run.stderr[-2000:]
    for phase in ("Examples", "Coverage", "Fuzzing", "Stateful"):     # each ran and passed (not skipped)
        assert f"✅ {phase}" in run.stdout, run.stdout[-3000:]


#: Without the cost hooks: what schemathesis generates as it is (chains of 200 segments, curves of 501 points, jobs
#: of 100 000 points ...). A time limit or a full queue is the server's documented answer to a request too costly
#: for the machine (504 ``timeout``, 503 ``overloaded``), not a server error: those two are expected, every other
#: 5xx is counted.
CONFIG_WITHOUT_HOOKS = """\
[checks.positive_data_acceptance]
expected-statuses = ["2xx", "401", "403", "404", "409", "422", "429", "503", "504"]

[checks.not_a_server_error]
expected-statuses = ["2xx", "3xx", "4xx", "503", "504"]

# A negative case can be a body over the server's size limit (a list over its maxItems of pairs): 413 refuses it.
[checks.negative_data_rejection]
expected-statuses = ["400", "401", "403", "404", "405", "406", "409", "413", "415", "422", "428", "429", "5xx"]

# A figure's body is its JSON operation's (plus format and dpi), whose boundary cases the coverage phase runs there.
[[operations]]
include-path-regex = "^/v1/plots/"
phases.coverage.enabled = false
"""
#: Short time limits keep the run within minutes whatever the generated costs (the answers then are 504s).
SHORT_LIMITS = {"TENSEGRITY_SOLVE_TIMEOUT": "3", "TENSEGRITY_BATCH_TIMEOUT": "3", "TENSEGRITY_JOBS_POINT_TIMEOUT": "3"}


@pytest.mark.slow
@pytest.mark.skipif(schemathesis_command() is None, reason="schemathesis is not installed (pip install '.[test]')")
def test_schemathesis_without_the_cost_hooks_finds_no_server_error(tmp_path):
    """The fuzzing phase without the cost hooks, seeded (half a minute). The coverage phase without hooks takes
    about 3 minutes more and runs in the with-hooks test above (its boundary values, costs bounded); a full
    unhooked pass (coverage and fuzzing, 10 examples, ~12,000 requests, ~15 minutes) is run by hand with the same
    configuration: ``CONFIG_WITHOUT_HOOKS``."""
    env = clean_env(TENSEGRITY_JOBS_DB=str(tmp_path / "jobs.sqlite3"), **SHORT_LIMITS)
    config = tmp_path / "schemathesis.toml"
    config.write_text(CONFIG_WITHOUT_HOOKS, encoding="utf-8")
    checks = [c for c in CHECKS if c != "positive_data_is_accepted_by_the_schema"]       # the hooks' own check
    with running_server(serve_command(free_port()), env, ready="/readyz", stdout=subprocess.DEVNULL,
                        timeout=WAIT_SECONDS) as (_, base):
        run = subprocess.run(
            [*schemathesis_command(), "--config-file", str(config), "run", str(ROOT / "openapi" / "openapi.json"),
             "--url", base, "--checks", ",".join(checks), "--phases", "fuzzing",
             "--suppress-health-check", "all", "--max-examples", "5", "--seed", "2", "--generation-database", "none",
             "--request-timeout", "600"],
            cwd=tmp_path, env={k: v for k, v in env.items() if k != "SCHEMATHESIS_HOOKS"}, capture_output=True,
            text=True, timeout=3600)
    (tmp_path / "schemathesis.out").write_text(run.stdout + run.stderr, encoding="utf-8")
    assert run.returncode == 0, run.stdout[:3000] + "\n...\n" + run.stdout[-9000:] + run.stderr[-2000:]
    for phase in ("Fuzzing",):
        assert f"✅ {phase}" in run.stdout, run.stdout[-3000:]
