"""Regenerate the typed Python client ``clients/python/`` from the committed ``openapi/openapi.json``.

Run from anywhere, after ``openapi/openapi.json`` has changed (``tensegrity-opt openapi``)::

    python clients/regenerate.py

with the test extra installed (``pip install '.[test]'``: it pins openapi-python-client and ruff,
whose versions decide the generated text). ``tests/test_client_generated.py`` runs the same
generation into a temporary directory and fails when ``clients/python/`` differs from it.

The generator is given the committed document with one change: an operation whose security
requirements include the empty one (``[{"ApiKey": []}, {}]``: a key only when the server has keys)
is given without them. openapi-python-client treats any security requirement as mandatory
(openapi-generators/openapi-python-client#1372) and would type such operations as taking an
``AuthenticatedClient`` only; without it they take ``Client | AuthenticatedClient``. Operations that
require a key keep their requirement.

The generated models then keep the JSON names of their fields (``L0``, ``K_min``, ``bounds_K``; the
generator would write ``l0``, ``k_min``, ``bounds_k``): :func:`keep_json_names`.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import tomllib
from importlib import metadata
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
SPEC = REPO / "openapi" / "openapi.json"
CONFIG = REPO / "clients" / "openapi-python-client.yaml"
TARGET = REPO / "clients" / "python"
META = "pdm"                        # a PEP 621 pyproject.toml built by pdm-backend
TOOLS = ("openapi-python-client", "ruff")
COMMAND = "python clients/regenerate.py"


def pinned_versions() -> dict[str, str]:
    """The versions of :data:`TOOLS` pinned (``==``) in the project's ``test`` extra.

    Returns
    -------
    dict of str to str
        Distribution name to version.

    Raises
    ------
    LookupError
        If a tool is not pinned with ``==`` in ``[project.optional-dependencies] test``.
    """
    with open(REPO / "pyproject.toml", "rb") as f:
        test = tomllib.load(f)["project"]["optional-dependencies"]["test"]
    pins = {}
    for tool in TOOLS:
        found = [m.group(1) for req in test if (m := re.fullmatch(rf"{re.escape(tool)}==([^;\s]+)", req.strip()))]
        if len(found) != 1:
            raise LookupError(f"pyproject.toml: the test extra must pin {tool} with '=='")
        pins[tool] = found[0]
    return pins


def tool_environment() -> dict[str, str]:
    """The environment for the generator: this interpreter's scripts first on ``PATH`` (the
    generator's post hooks call ``ruff``), after checking the installed versions against the pins.

    Returns
    -------
    dict of str to str
        ``os.environ`` with ``PATH`` extended.

    Raises
    ------
    RuntimeError
        If openapi-python-client or ruff is missing or not at its pinned version: another version
        generates other text.
    """
    pins = pinned_versions()
    env = dict(os.environ)
    env["PATH"] = os.pathsep.join([str(Path(sys.executable).parent), env.get("PATH", "")])
    try:
        have = metadata.version("openapi-python-client")
    except metadata.PackageNotFoundError:
        have = None
    ruff = shutil.which("ruff", path=env["PATH"])
    ruff_have = None
    if ruff is not None:
        out = subprocess.run([ruff, "--version"], capture_output=True, text=True, check=False).stdout.split()
        ruff_have = out[1] if len(out) > 1 else None
    wrong = [f"{tool} {found or 'missing'} (pinned {pins[tool]})"
             for tool, found in (("openapi-python-client", have), ("ruff", ruff_have)) if found != pins[tool]]
    if wrong:
        raise RuntimeError("the client's generator needs the test extra's tools (pip install '.[test]'): "
                           + ", ".join(wrong))
    return env


def generator_document(spec: dict) -> dict:
    """The committed document as given to the generator: anonymous-or-key operations without their
    security requirements (see the module's docstring).

    Parameters
    ----------
    spec : dict
        The OpenAPI document.

    Returns
    -------
    dict
        A copy, changed only in the ``security`` of those operations.
    """
    spec = json.loads(json.dumps(spec))
    for operations in spec.get("paths", {}).values():
        for operation in operations.values():
            if isinstance(operation, dict) and {} in (operation.get("security") or []):
                del operation["security"]
    return spec


def generate(output: Path, spec: Path = SPEC) -> None:
    """Generate the client project from ``spec`` into ``output`` (which must not exist).

    Parameters
    ----------
    output : Path
        The directory to create: the project (``pyproject.toml``, ``tensegrity_opt_client/``).
    spec : Path
        The OpenAPI document (default: the committed ``openapi/openapi.json``).

    Raises
    ------
    RuntimeError
        If the tools are not the pinned ones, or the generator fails or warns (a warning means a
        part of the API missing from the client).
    """
    env = tool_environment()
    output = Path(output)
    with tempfile.TemporaryDirectory() as tmp:
        document = Path(tmp) / "openapi.json"
        document.write_text(json.dumps(generator_document(json.loads(spec.read_text(encoding="utf-8")))),
                            encoding="utf-8")
        run = subprocess.run([sys.executable, "-m", "openapi_python_client", "generate", "--path", str(document),
                              "--config", str(CONFIG), "--meta", META, "--output-path", str(output),
                              "--fail-on-warning"], cwd=tmp, env=env, capture_output=True, text=True, check=False)
    if run.returncode != 0 or not (output / "pyproject.toml").is_file():
        raise RuntimeError(f"openapi-python-client failed ({run.returncode}):\n{run.stdout}\n{run.stderr}")
    keep_json_names(output / "tensegrity_opt_client" / "models")


#: A model's ``field_dict["L0"] = l0``: the JSON name and the attribute the generator gave it.
_FIELD = re.compile(r'field_dict\["(\w+)"\] = (\w+)$', re.MULTILINE)


def keep_json_names(models: Path) -> list[tuple[str, str]]:
    """Give every model attribute its JSON name where the generator changed only its case (``l0`` -> ``L0``,
    ``k_min`` -> ``K_min``, ``bounds_k`` -> ``bounds_K``): one name for a parameter in the JSON, the library
    and the client.

    openapi-python-client (0.29) writes every property as ``snake_case(name)`` (its ``PythonIdentifier``);
    its configuration renames classes and modules (``class_overrides``), never a field, and the schema has no
    keyword it reads for one. So the generated modules are rewritten here: the attribute, its keyword argument,
    its local variable and its docstring line (the word ``l0`` alone; ``_parse_l0`` and the like stay).

    Parameters
    ----------
    models : Path
        The generated ``models`` package.

    Returns
    -------
    list of (str, str)
        ``(generated, JSON name)`` pairs renamed, sorted.
    """
    renamed = set()
    for path in sorted(models.glob("*.py")):
        text = path.read_text(encoding="utf-8")
        pairs = {(attr, name) for name, attr in _FIELD.findall(text) if name != attr and name.lower() == attr}
        for attr, name in sorted(pairs):
            text = re.sub(rf"\b{re.escape(attr)}\b", name, text)
            renamed.add((attr, name))
        if pairs:
            path.write_text(text, encoding="utf-8")
    return sorted(renamed)


def main() -> int:
    """Regenerate ``clients/python/`` in place (generated aside, then swapped in)."""
    with tempfile.TemporaryDirectory() as tmp:
        fresh = Path(tmp) / "python"
        generate(fresh)
        shutil.rmtree(TARGET, ignore_errors=True)
        shutil.copytree(fresh, TARGET)
    print(f"regenerated {TARGET.relative_to(REPO)} from {SPEC.relative_to(REPO)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
