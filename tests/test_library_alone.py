"""The library's tests need no service extra: with the service's packages made unimportable, every test of
``tests/model``, ``tests/numerics``, ``tests/analyses`` and ``tests/applications`` collects (every module and
the helpers it imports load), and the fast lane of a representative part passes (:data:`FAST_LANE_SAMPLE`: the
model, a numerics file, a results file of each analyses package and one computing design file, the CLI with
its figure commands, the plot style and a sweep) -- the whole fast lane runs in the ordinary run of the suite.

The packages of the ``service`` extra (and the service itself) are blocked in a fresh interpreter by a meta-path
finder that raises ``ImportError`` for them, installed by a ``sitecustomize`` module put first on its
``PYTHONPATH``: pytest then runs as it would where only the library and its test tools are installed. A static
check adds the imports collection does not reach (inside test functions, ``pytest.importorskip``), and a control
shows that the finder stops a test that does import the service, so neither check can pass vacuously.
"""

from __future__ import annotations

import ast
import os
import re
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
TESTS = ROOT / "tests"
#: The folders of the library's tests (relative to the repository).
LIBRARY_TESTS = ("tests/model", "tests/numerics", "tests/analyses", "tests/applications")
#: The part of the library's tests whose fast lane is run without the service: each analyses package's results,
#: the numerics, the CLI and its figures, the plots and the sweeps (~15 s; the rest is collected only).
FAST_LANE_SAMPLE = ("tests/model", "tests/numerics/test_building_blocks.py",
                    "tests/analyses/equilibria/test_equilibria_results.py",
                    "tests/analyses/paths/test_paths_results.py", "tests/analyses/design/test_design_results.py",
                    "tests/analyses/design/test_preloads.py", "tests/applications/cli/test_cli.py",
                    "tests/applications/cli/test_plot_cli.py", "tests/applications/plots/test_plot_style.py",
                    "tests/applications/sweeps/test_sweep.py")
#: The service and the packages of its extra.
BLOCKED = ("service", "fastapi", "starlette", "uvicorn", "pydantic_settings", "prometheus_client", "httpx")

SITECUSTOMIZE = textwrap.dedent(f"""\
    import sys

    BLOCKED = {BLOCKED!r}


    class BlockTheService:
        def find_spec(self, name, path=None, target=None):
            if name.split(".")[0] in BLOCKED:
                raise ImportError(f"{{name}} is blocked: the library's tests must not need the service extra")
            return None


    sys.meta_path.insert(0, BlockTheService())
    """)


def _pytest_without_the_service(tmp_path: Path, *args: str, timeout: float = 900) -> subprocess.CompletedProcess:
    """``python -m pytest ARGS`` in a fresh interpreter in which the service's packages cannot be imported."""
    site = tmp_path / "block"
    site.mkdir(exist_ok=True)
    (site / "sitecustomize.py").write_text(SITECUSTOMIZE, encoding="utf-8")
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(p for p in (str(site), os.environ.get("PYTHONPATH")) if p)}
    return subprocess.run([sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-n", "0", *args], cwd=ROOT,
                          env=env, capture_output=True, text=True, timeout=timeout)


def _library_test_files() -> set[str]:
    return {p.relative_to(ROOT).as_posix() for d in LIBRARY_TESTS for p in (ROOT / d).rglob("test_*.py")}


def _summary(out: str) -> str:
    lines = [ln for ln in out.strip().splitlines() if ln.strip()]
    return lines[-1] if lines else ""


@pytest.mark.slow
def test_the_library_tests_collect_without_the_service_packages(tmp_path):
    r = _pytest_without_the_service(tmp_path, "--collect-only", "-q", *LIBRARY_TESTS)
    assert r.returncode == 0, r.stdout[-4000:] + r.stderr[-2000:]
    summary = _summary(r.stdout)
    assert re.fullmatch(r"\d+ tests collected in [\d.]+s", summary), summary      # no error, no module skipped
    collected = {line.split("::")[0] for line in r.stdout.splitlines() if "::" in line}
    assert collected == _library_test_files()                                       # every file, each with tests


@pytest.mark.slow
def test_the_blocker_stops_a_test_that_imports_the_service(tmp_path):
    """The control: the same finder makes a test module that imports the service fail to collect."""
    for name, line in (("test_uses_the_service.py", "from service.config import Settings"),
                       ("test_uses_fastapi.py", "import fastapi")):
        (tmp_path / name).write_text(f"{line}\n\n\ndef test_nothing():\n    pass\n", encoding="utf-8")
        r = _pytest_without_the_service(tmp_path, "--collect-only", "-q", str(tmp_path / name))
        assert r.returncode != 0 and "is blocked" in r.stdout, r.stdout[-2000:]


def _imports(path: Path) -> set[str]:
    """Every module ``path`` imports, at any depth, and every module named to ``pytest.importorskip``."""
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found |= {a.name for a in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            found.add(node.module)
        elif (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr == "importorskip"
              and node.args and isinstance(node.args[0], ast.Constant)):
            found.add(str(node.args[0].value))
    return found


def test_no_library_test_and_no_helper_it_uses_imports_the_service():
    """What collection does not reach: imports inside the tests' functions and ``importorskip`` (a module skipped
    for want of the service would pass unnoticed); the helpers in ``tests/support`` they import; the test-wide
    ``tests/conftest.py``."""
    support = {p.stem: p for p in (TESTS / "support").glob("*.py")}
    todo = [ROOT / f for f in sorted(_library_test_files())] + [TESTS / "conftest.py"]
    seen: set[Path] = set()
    bad = []
    while todo:
        path = todo.pop()
        if path in seen:
            continue
        seen.add(path)
        for module in _imports(path):
            top = module.split(".")[0]
            if top in BLOCKED:
                bad.append(f"{path.relative_to(ROOT)}: {module}")
            elif top in support:
                todo.append(support[top])
    assert not bad, bad
    assert len(seen) > 40                    # the walk reached the library's tests and their helpers


@pytest.mark.slow
def test_the_library_fast_lane_passes_without_the_service_packages(tmp_path):
    """The fast lane of :data:`FAST_LANE_SAMPLE`, every part of it a library test."""
    library = _library_test_files()
    for part in FAST_LANE_SAMPLE:
        assert part in library or any(f.startswith(part + "/") for f in library), part
    r = _pytest_without_the_service(tmp_path, "-q", "-m", "not slow", *FAST_LANE_SAMPLE, timeout=900)
    assert r.returncode == 0, r.stdout[-6000:] + r.stderr[-2000:]
    summary = _summary(r.stdout)
    assert " passed" in summary and "failed" not in summary and "error" not in summary, summary
