"""``clients/python/`` is what openapi-python-client generates from the committed
``openapi/openapi.json``: regenerated here, compared byte for byte."""

from __future__ import annotations

import importlib.util
import shutil
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
COMMITTED = REPO / "clients" / "python"
# what a checkout may hold beside the generated files: caches and build output (none is generated)
IGNORED_DIRS = {"__pycache__", ".pytest_cache", ".mypy_cache", ".ruff_cache", "build", "dist"}


def _regenerate_module():
    spec = importlib.util.spec_from_file_location("clients_regenerate", REPO / "clients" / "regenerate.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


regenerate = _regenerate_module()


def tree(root: Path) -> dict[str, bytes]:
    """Every file under ``root`` (relative POSIX path to its bytes), without caches and build output."""
    files = {}
    for path in sorted(root.rglob("*")):
        rel = path.relative_to(root)
        if any(part in IGNORED_DIRS or part.endswith(".egg-info") for part in rel.parts):
            continue
        if path.is_file():
            files[rel.as_posix()] = path.read_bytes()
    return files


def differences(committed: dict[str, bytes], fresh: dict[str, bytes]) -> list[str]:
    """The files that differ, each as ``path (what)``, sorted."""
    out = [f"{p} (not generated any more)" for p in committed.keys() - fresh.keys()]
    out += [f"{p} (missing)" for p in fresh.keys() - committed.keys()]
    out += [f"{p} (differs)" for p in committed.keys() & fresh.keys() if committed[p] != fresh[p]]
    return sorted(out)


@pytest.fixture(scope="module")
def fresh(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("client") / "python"
    regenerate.generate(out)
    return out


@pytest.mark.slow
def test_committed_client_is_up_to_date(fresh):
    fresh_files = tree(fresh)
    assert "tensegrity_opt_client/api/equilibrium/solve_equilibrium.py" in fresh_files
    diff = differences(tree(COMMITTED), fresh_files)
    assert not diff, (f"clients/python/ is stale against openapi/openapi.json: {len(diff)} file(s) differ:\n  "
                      + "\n  ".join(diff[:50]) + f"\nregenerate it: {regenerate.COMMAND}")


def test_the_comparison_sees_every_kind_of_change(fresh, tmp_path):
    """A changed, a removed and an extra file are each reported (and caches are not)."""
    copy = tmp_path / "python"
    shutil.copytree(fresh, copy)
    assert differences(tree(copy), tree(fresh)) == []
    (copy / "README.md").write_bytes((copy / "README.md").read_bytes() + b"\n")
    (copy / "tensegrity_opt_client" / "py.typed").unlink()
    (copy / "tensegrity_opt_client" / "stale.py").write_text("")
    (copy / "tensegrity_opt_client" / "__pycache__").mkdir()
    (copy / "tensegrity_opt_client" / "__pycache__" / "client.cpython-311.pyc").write_bytes(b"\0")
    assert differences(tree(copy), tree(fresh)) == [
        "README.md (differs)", "tensegrity_opt_client/py.typed (missing)",
        "tensegrity_opt_client/stale.py (not generated any more)"]


def test_anonymous_operations_take_a_plain_client():
    """Operations that accept no key (``{}`` among their requirements) reach the generator without
    security, so their functions take ``Client | AuthenticatedClient``; key-only ones keep it."""
    spec = {"paths": {"/a": {"post": {"security": [{"ApiKey": []}, {}]}},
                      "/b": {"get": {"security": [{"ApiKey": []}]}, "parameters": []},
                      "/c": {"get": {}}}}
    out = regenerate.generator_document(spec)
    assert "security" not in out["paths"]["/a"]["post"]
    assert out["paths"]["/b"]["get"]["security"] == [{"ApiKey": []}]
    assert out["paths"]["/c"]["get"] == {} and spec["paths"]["/a"]["post"]["security"] == [{"ApiKey": []}, {}]
    code = (COMMITTED / "tensegrity_opt_client" / "api" / "equilibrium" / "solve_equilibrium.py").read_text()
    assert "client: AuthenticatedClient | Client," in code and "client: AuthenticatedClient,\n" not in code


def test_the_pins_are_the_test_extras():
    pins = regenerate.pinned_versions()
    assert set(pins) == {"openapi-python-client", "ruff"}
    assert all(v[0].isdigit() for v in pins.values())
