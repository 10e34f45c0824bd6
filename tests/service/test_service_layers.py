"""The service's house rules, checked on its own imports and files.

* the layers, each importing only those below it: the entry points (``cli``, ``main``: wiring), the HTTP layer
  (``api``), the stream sessions and the jobs, the tasks, the adapters (request names <-> library names), the
  executors and the renderer, the schemas and the examples, then the settings; nothing imports ``service.main``
  but the entry point;
* no module imports another one's private names (``from x import _y``, ``x._y``);
* no module over ~800 lines.

The import graph is grimp's (every import statement, at any depth, as ``tests/test_architecture.py``). The
private-name check is shown to fail on a small source that breaks it.
"""

from __future__ import annotations

import ast
import sys
from pathlib import Path

import grimp
import pytest

ROOT = Path(__file__).resolve().parents[2]
SERVICE = ROOT / "service"

#: Highest first; modules of one layer do not import each other.
LAYERS = (
    grimp.Layer("cli"),
    grimp.Layer("main"),
    grimp.Layer("api"),
    grimp.Layer("sessions", "jobs"),
    grimp.Layer("tasks"),
    grimp.Layer("adapters"),
    grimp.Layer("execution", "responses"),
    grimp.Layer("schemas", "examples"),
    grimp.Layer("config"),
)
#: The contract helpers' request and response models share private field sets between their modules.
PRIVATE_IMPORTS_ALLOWED_IN = ("service.schemas",)
MAX_LINES = 800


@pytest.fixture(scope="module")
def graph() -> grimp.ImportGraph:
    sys.path.insert(0, str(ROOT))
    try:
        return grimp.build_graph("service", cache_dir=None)
    finally:
        sys.path.remove(str(ROOT))


def test_the_layers_import_downwards_only(graph):
    assert {"service.api.dispatch", "service.execution.processes", "service.jobs.store"} <= set(graph.modules)
    illegal = graph.find_illegal_dependencies_for_layers(layers=LAYERS, containers={"service"})
    assert not illegal, sorted((d.importer, d.imported) for d in illegal)


def test_nothing_imports_main_but_the_entry_point(graph):
    assert graph.find_modules_that_directly_import("service.main") == {"service.cli"}


def _modules() -> list[tuple[str, Path]]:
    out = []
    for path in sorted(SERVICE.rglob("*.py")):
        parts = path.relative_to(ROOT).with_suffix("").parts
        name = ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
        out.append((name, path))
    return out


def private_imports(module: str, source: str, package: bool = False) -> list[str]:
    """``module``'s imports of another module's private names: ``from x import _y`` and ``x._y`` on a module
    bound by ``import x`` / ``from p import x`` (relative imports resolved against ``module``)."""
    base = module.split(".") if package else module.split(".")[:-1]
    found, modules = [], {}
    tree = ast.parse(source)
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            origin = ".".join(base[:len(base) - node.level + 1] + ([node.module] if node.module else [])) \
                if node.level else (node.module or "")
            for alias in node.names:
                if alias.name.startswith("_") and not alias.name.startswith("__") and origin != module:
                    found.append(f"from {origin} import {alias.name}")
                modules[alias.asname or alias.name] = f"{origin}.{alias.name}"
        elif isinstance(node, ast.Import):
            for alias in node.names:
                modules[alias.asname or alias.name.split(".")[0]] = alias.name
    for node in ast.walk(tree):
        if (isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id in modules
                and node.attr.startswith("_") and not node.attr.startswith("__")):
            found.append(f"{modules[node.value.id]}.{node.attr}")
    return found


def test_the_private_import_check_sees_both_forms():
    assert private_imports("service.a.b", "from ..pool import _set_async_exc\n") == \
        ["from service.pool import _set_async_exc"]
    assert private_imports("service.a.b", "from .. import pool\npool._set_async_exc(1, None)\n") == \
        ["service.pool._set_async_exc"]
    assert private_imports("service.a", "from .b import _x\n", package=True) == ["from service.a.b import _x"]
    assert private_imports("service.a.b", "from .c import public\nimport os\nos.getpid()\n") == []


def test_no_module_imports_another_ones_private_names():
    bad = {}
    for name, path in _modules():
        if name.startswith(PRIVATE_IMPORTS_ALLOWED_IN):
            continue
        found = private_imports(name, path.read_text("utf-8"), package=path.name == "__init__.py")
        if found:
            bad[name] = found
    assert not bad, bad


def test_no_module_is_over_800_lines():
    sizes = {name: len(path.read_text("utf-8").splitlines()) for name, path in _modules()}
    assert len(sizes) > 40
    assert {n: k for n, k in sizes.items() if k > MAX_LINES} == {}
