"""The paper notebook (docs/notebooks/paper.ipynb) runs: every table cell of Tables 1-2 and the figures'
checks are ``assert`` statements in it, so executing it fails when the library drifts from the paper.

The kernel is ipykernel's ``python3`` kernel of this interpreter (a kernel spec of that name on
``JUPYTER_PATH`` for the test, so that a ``python3`` spec of another Python in the user's Jupyter
directories is not the one started), with the environment of the test process and with ``PYTHONPATH`` led by
the directory of the ``tensegrity_opt`` the test imports, so that the notebook checks that library: the worktree's
source or the installed package alike.
"""

import json
import os
import sys
from pathlib import Path

import nbclient
import nbformat

import tensegrity_opt

NOTEBOOK = Path(__file__).resolve().parents[2] / "docs" / "notebooks" / "paper.ipynb"


def test_committed_without_outputs():
    nb = nbformat.read(NOTEBOOK, as_version=4)
    code = [c for c in nb.cells if c.cell_type == "code"]
    assert code
    assert all(not c.outputs and c.execution_count is None for c in code)


def test_notebook_runs_and_its_checks_pass(tmp_path, monkeypatch):
    spec = tmp_path / "kernels" / "python3"
    spec.mkdir(parents=True)
    (spec / "kernel.json").write_text(json.dumps({
        "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
        "display_name": "Python 3", "language": "python"}))
    monkeypatch.setenv("JUPYTER_PATH", str(tmp_path))
    nb = nbformat.read(NOTEBOOK, as_version=4)
    lib = str(Path(tensegrity_opt.__file__).resolve().parents[1])
    env = dict(os.environ, MPLBACKEND="Agg",
               PYTHONPATH=os.pathsep.join([lib] + [p for p in [os.environ.get("PYTHONPATH")] if p]))
    client = nbclient.NotebookClient(nb, kernel_name="python3", timeout=300,
                                     resources={"metadata": {"path": str(NOTEBOOK.parent)}})
    client.execute(env=env)          # raises CellExecutionError (with the failing assert) on any error
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    images = [o for o in outputs if o.output_type == "display_data" and "image/png" in o.get("data", {})]
    assert len(images) >= 7                    # Fig. 2, the shapes, Fig. 4 (two pairs), Fig. 5 (two), Fig. 6
    text = "".join(o.get("text", "") for o in outputs if o.output_type == "stream")
    assert "critical force Fx0 = -0.572793" in text
    # the kernel ran the library this test imported
    assert f"from {tensegrity_opt.__file__}" in text
