"""The house's rules, checked on the code's own imports.

* the layers: ``model`` (numpy) <- ``numerics`` (the only package importing CasADi) <- ``analyses``
  <- ``applications``; the foundation (``errors``, ``timelimit``) below all of them;
* the library never imports the service (nor fastapi, uvicorn, starlette; that importing it loads
  none of them is checked in ``tests/service/test_service_cli.py``);
* no import cycle among the project's modules, an import inside a function included.

The import graph is grimp's (import-linter's engine: it reads every import statement, at any
depth); the contracts are import-linter's, configured in ``pyproject.toml`` (``[tool.importlinter]``);
cycles are the strongly connected components of that graph (scipy). Each check is shown to fail
on a small package that breaks it, so none of them can pass vacuously.
"""

from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

import grimp
import numpy as np
import pytest
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

ROOT = Path(__file__).resolve().parents[1]


def import_cycles(graph: grimp.ImportGraph, packages: tuple[str, ...]) -> list[list[str]]:
    """The import cycles among the modules of ``packages``: each strongly connected component of
    more than one module, and each module importing itself."""
    mods = sorted(m for m in graph.modules if m.split(".")[0] in packages)
    index = {m: i for i, m in enumerate(mods)}
    rows, cols, selfs = [], [], []
    for m in mods:
        for t in graph.find_modules_directly_imported_by(m):
            if t in index:
                if t == m:
                    selfs.append([m])
                rows.append(index[m])
                cols.append(index[t])
    adj = coo_matrix((np.ones(len(rows)), (rows, cols)), shape=(len(mods), len(mods)))
    _, labels = connected_components(adj, directed=True, connection="strong")
    groups: dict[int, list[str]] = {}
    for m, lab in zip(mods, labels):
        groups.setdefault(int(lab), []).append(m)
    return [g for g in groups.values() if len(g) > 1] + selfs


def _build(tmp_path: Path, files: dict[str, str], package: str) -> grimp.ImportGraph:
    for name, text in files.items():
        p = tmp_path / name
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text(textwrap.dedent(text))
    sys.path.insert(0, str(tmp_path))
    try:
        return grimp.build_graph(package, cache_dir=None)
    finally:
        sys.path.remove(str(tmp_path))


def test_no_import_cycle_among_the_project_modules():
    sys.path.insert(0, str(ROOT))
    try:
        graph = grimp.build_graph("tensegrity_opt", "service", cache_dir=None)
    finally:
        sys.path.remove(str(ROOT))
    assert len(graph.modules) > 40          # the graph really holds the project
    assert import_cycles(graph, ("tensegrity_opt", "service")) == []


def test_the_cycle_check_sees_a_cycle_through_a_function_level_import(tmp_path):
    graph = _build(tmp_path, {"cyc/__init__.py": "", "cyc/a.py": "def f():\n    from . import b\n",
                              "cyc/b.py": "from .a import f\n", "cyc/c.py": "from . import a\n"}, "cyc")
    assert import_cycles(graph, ("cyc",)) == [["cyc.a", "cyc.b"]]


def test_import_linter_contracts_hold():
    """``lint-imports`` with the project's contracts (layers, the CasADi fence, no service in the library)."""
    out = subprocess.run([sys.executable, "-c", "import sys; from importlinter.cli import lint_imports; "
                          "sys.exit(lint_imports(no_cache=True))"], cwd=ROOT, capture_output=True, text=True,
                         timeout=300)
    assert out.returncode == 0, out.stdout + out.stderr
    assert "0 broken" in out.stdout and "kept" in out.stdout


def test_the_contracts_catch_a_broken_layer_and_a_casadi_import(tmp_path):
    """The same contract types, on a small package that breaks each: import-linter reports both."""
    files = {"lay/__init__.py": "", "lay/model/__init__.py": "", "lay/numerics/__init__.py": "",
             "lay/model/m.py": "def f():\n    from ..numerics import n\n",       # an upward import
             "lay/numerics/n.py": "import json\n",
             "lay/model/k.py": "import casadi\n",                                # CasADi outside numerics
             "setup.cfg": textwrap.dedent("""\
                [importlinter]
                root_package = lay
                include_external_packages = True

                [importlinter:contract:layers]
                name = layers
                type = layers
                layers =
                    lay.numerics
                    lay.model

                [importlinter:contract:casadi]
                name = casadi fence
                type = forbidden
                source_modules = lay.model
                forbidden_modules = casadi
                """)}
    for name, text in files.items():
        p = tmp_path / name
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text(text)
    out = subprocess.run([sys.executable, "-c", f"import sys; sys.path.insert(0, {str(tmp_path)!r}); "
                          "from importlinter.cli import lint_imports; sys.exit(lint_imports(no_cache=True))"],
                         cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert out.returncode != 0
    assert "2 broken" in out.stdout, out.stdout + out.stderr


@pytest.mark.slow
def test_the_import_check_sees_the_service_when_it_is_loaded():
    """The control of ``test_service_cli``'s check that the library loads no web stack: the same
    ``sys.modules`` test sees fastapi once the service is imported."""
    code = ("import sys, service.main; bad = [m for m in sys.modules if m.split('.')[0] == 'fastapi']; "
            "sys.exit(1 if bad else 0)")
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert out.returncode == 1
