"""The paper notebook (docs/notebooks/paper.ipynb) runs as docs/notebook.md says: every table cell of Tables 1-2
and the figures' checks are ``assert`` statements in it, so executing it fails when the library drifts from the
paper; the ``notebook`` extra the page names installs what its commands need (``jupyter notebook``, ``jupyter
nbconvert``, the ``python3`` kernel), and the test suite's extra installs the same, so that these tests run the
page's own commands.

The kernel is ipykernel's ``python3`` kernel of this interpreter (a kernel spec of that name on
``JUPYTER_PATH`` for the test, so that a ``python3`` spec of another Python in the user's Jupyter
directories is not the one started), with the environment of the test process and with ``PYTHONPATH`` led by
the directory of the ``tensegrity_opt`` the test imports, so that the notebook checks that library: the worktree's
source or the installed package alike.
"""

import json
import os
import re
import shlex
import subprocess
import sys
import tomllib
from pathlib import Path

import nbformat
from packaging.requirements import Requirement

import tensegrity_opt

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOK = ROOT / "docs" / "notebooks" / "paper.ipynb"
PAGE = ROOT / "docs" / "notebook.md"


def _extras() -> dict[str, list[str]]:
    return tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["optional-dependencies"]


def _page_commands() -> list[list[str]]:
    """The shell commands of the page's bash block, as argument lists (comments dropped)."""
    block = re.search(r"```bash\n(.*?)```", PAGE.read_text(), re.S)
    assert block, "docs/notebook.md has no bash block with the commands"
    lines = block.group(1).replace("\\\n", " ").splitlines()           # continuation lines joined
    return [cmd for cmd in (shlex.split(line, comments=True) for line in lines) if cmd]


def test_committed_without_outputs():
    nb = nbformat.read(NOTEBOOK, as_version=4)
    code = [c for c in nb.cells if c.cell_type == "code"]
    assert code
    assert all(not c.outputs and c.execution_count is None for c in code)


def test_the_page_installs_the_notebook_extra_and_it_has_what_its_commands_run():
    extras = _extras()
    assert "notebook" in extras, "pyproject.toml has no `notebook` extra"
    names = {Requirement(r).name.lower() for r in extras["notebook"]}
    assert {"notebook", "nbconvert", "ipykernel"} <= names       # jupyter notebook, jupyter nbconvert, the kernel
    # the suite installs the same (it runs the page's commands below)
    assert names <= {Requirement(r).name.lower() for r in extras["test"]}
    commands = _page_commands()
    assert ["python3", "-m", "pip", "install", ".[notebook]"] in commands
    runs = [c[3] for c in commands if c[:3] == ["python3", "-m", "jupyter"]]
    assert {"notebook", "nbconvert"} <= set(runs)
    # README names the extra where it mentions the notebook
    assert "'.[notebook]'" in (ROOT / "README.md").read_text()


def test_jupyter_notebook_command_is_installed():
    """``jupyter notebook`` of the page resolves (without the extra: "Jupyter command `jupyter-notebook` not
    found"); ``--version`` checks it without starting a server."""
    out = subprocess.run([sys.executable, "-m", "jupyter", "notebook", "--version"], capture_output=True,
                         text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert re.match(r"\d+\.", out.stdout.strip())


def test_notebook_runs_with_the_pages_command_and_its_checks_pass(tmp_path):
    spec = tmp_path / "kernels" / "python3"
    spec.mkdir(parents=True)
    (spec / "kernel.json").write_text(json.dumps({
        "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
        "display_name": "Python 3", "language": "python"}))
    lib = str(Path(tensegrity_opt.__file__).resolve().parents[1])
    env = dict(os.environ, MPLBACKEND="Agg", JUPYTER_PATH=str(tmp_path),
               PYTHONPATH=os.pathsep.join([lib] + [p for p in [os.environ.get("PYTHONPATH")] if p]))
    (command,) = [c for c in _page_commands() if c[:4] == ["python3", "-m", "jupyter", "nbconvert"]]
    out_dir = tmp_path / "out"
    command = [sys.executable] + command[1:command.index("--output-dir") + 1] + [str(out_dir)]
    run = subprocess.run(command + ["--ExecutePreprocessor.timeout=300"], cwd=ROOT, env=env,
                         capture_output=True, text=True, timeout=900)
    assert run.returncode == 0, run.stderr[-4000:]        # an error in a cell (a failing assert) fails nbconvert
    nb = nbformat.read(out_dir / NOTEBOOK.name, as_version=4)
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    images = [o for o in outputs if o.output_type == "display_data" and "image/png" in o.get("data", {})]
    assert len(images) >= 7                    # Fig. 2, the shapes, Fig. 4 (two pairs), Fig. 5 (two), Fig. 6
    text = "".join(o.get("text", "") for o in outputs if o.output_type == "stream")
    assert "critical force Fx0 = -0.572793" in text
    # the kernel ran the library this test imported
    assert f"from {tensegrity_opt.__file__}" in text
