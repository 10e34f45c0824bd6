"""The typed client (``clients/python/``, package ``tensegrity_opt_client``) against a real server
process: equilibrium, buckling, a refusal, and the README's client example run as written."""

from __future__ import annotations

import contextlib
import io
import re
import sys
from pathlib import Path

import numpy as np
import pytest
from servers import GENEROUS_ENV, WAIT_SECONDS, clean_env, free_port, running_server, serve_command

import tensegrity_opt as to
from tensegrity_opt.model.manipulator import Manipulator

REPO = Path(__file__).resolve().parents[2]
# the client is its own project (pip install ./clients/python); the tests use the checkout's copy
sys.path.insert(0, str(REPO / "clients" / "python"))

httpx = pytest.importorskip("httpx")
pytest.importorskip("uvicorn")

from tensegrity_opt_client import Client  # noqa: E402
from tensegrity_opt_client.api.buckling import critical_force  # noqa: E402
from tensegrity_opt_client.api.equilibrium import solve_equilibrium  # noqa: E402
from tensegrity_opt_client.models import (  # noqa: E402
    BucklingOut,
    BucklingRequest,
    BucklingRequestBoundary,
    EquilibriumOut,
    EquilibriumRequest,
    ErrorOut,
    UniformManipulatorIn,
)

README_BASE = "http://127.0.0.1:8000"


@pytest.fixture(scope="module")
def base():
    env = clean_env(TENSEGRITY_WORKERS="1", **GENEROUS_ENV)
    with running_server(serve_command(free_port()), env, timeout=WAIT_SECONDS) as (_, url):
        yield url


@pytest.fixture()
def api(base):
    with Client(base_url=base, timeout=httpx.Timeout(WAIT_SECONDS), raise_on_unexpected_status=True) as client:
        yield client


@pytest.mark.slow
def test_equilibrium(api):
    body = EquilibriumRequest(manipulator=UniformManipulatorIn(n=4, a=1, b=1, k=1, L0=1), dx=0.1, dy=0.0)
    r = solve_equilibrium.sync_detailed(client=api, body=body)
    assert r.status_code == 200, r.content
    eq = r.parsed
    assert isinstance(eq, EquilibriumOut)
    # the library's own answer, in-process
    lib = to.solve_equilibrium(to.Manipulator.uniform(4), 0.1, 0.0)
    assert eq.q == pytest.approx(lib.q.tolist(), rel=1e-9, abs=1e-12)
    assert (eq.force.fx, eq.force.fy) == pytest.approx((lib.fx, lib.fy), rel=1e-9, abs=1e-12)
    # independently: the returned angles put the tip on its target (2 sum(b) - dx, dy) = (7.9, 0) ...
    assert Manipulator.uniform(4).tip(np.array(eq.q)) == pytest.approx([7.9, 0.0], abs=1e-9)
    assert eq.tip == pytest.approx([7.9, 0.0], abs=1e-9)
    # ... on the U branch, whose |Fy| at dx = 0.1 is 0.02579 (``docs/model.md``, eq. 26's branch)
    assert eq.stable and eq.shape == "U" and eq.morse_index == 0
    assert abs(eq.force.fy) == pytest.approx(0.02579, abs=1e-5)


def test_buckling_matches_the_paper(api):
    body = BucklingRequest(manipulator=UniformManipulatorIn(n=4), boundary=BucklingRequestBoundary.GUIDED)
    b = critical_force.sync(client=api, body=body)
    assert isinstance(b, BucklingOut)
    # the paper's Table 1 (eq. 19): eigenvalues of B^-1 A -1.746, -0.734, -0.520; loads P = -1/lambda and
    # the signed (compressive) critical force Fx0 = -1/1.746, to the paper's three decimals (half a
    # unit of the last digit, relative)
    paper = [1 / 1.746, 1 / 0.734, 1 / 0.520]
    assert b.critical_force == pytest.approx(-1 / 1.746, rel=0.0005 / 1.746)
    assert b.loads[:3] == pytest.approx(paper, rel=0.0005 / 0.520)


def test_refusal_is_a_typed_error(api):
    body = EquilibriumRequest(manipulator=UniformManipulatorIn(n=0), dx=0.1)
    r = solve_equilibrium.sync_detailed(client=api, body=body)
    assert r.status_code == 422
    err = r.parsed
    assert isinstance(err, ErrorOut)
    assert err.code == "validation_error"
    assert err.field == "manipulator.n"        # the path of the bad input
    assert err.message
    assert err.errors and any(e.field == err.field for e in err.errors)
    # sync() gives the same ErrorOut (the body), without the status
    again = solve_equilibrium.sync(client=api, body=body)
    assert isinstance(again, ErrorOut) and again.code == "validation_error" and again.field == err.field


def readme_client_block() -> str:
    """The README's Python block that uses the typed client (exactly one)."""
    text = (REPO / "README.md").read_text(encoding="utf-8")
    blocks = [b for b in re.findall(r"```python\n(.*?)```", text, flags=re.S) if "tensegrity_opt_client" in b]
    assert len(blocks) == 1, f"{len(blocks)} README blocks use tensegrity_opt_client"
    return blocks[0]


def test_readme_client_example_runs(base):
    code = readme_client_block()
    assert README_BASE in code
    out = io.StringIO()
    scope: dict = {}
    with contextlib.redirect_stdout(out):
        exec(compile(code.replace(README_BASE, base), "README.md", "exec"), scope)
    eq = scope["eq"]
    assert isinstance(eq, EquilibriumOut), out.getvalue()
    lib = to.solve_equilibrium(to.Manipulator.uniform(4), 0.1, 0.0)
    assert eq.q == pytest.approx(lib.q.tolist(), rel=1e-9, abs=1e-12)
    assert out.getvalue().startswith(str(eq.q)), out.getvalue()


def test_docs_client_example_runs(base):
    """docs/client.md's first example (equilibrium and buckling) runs as written."""
    text = (REPO / "docs" / "client.md").read_text(encoding="utf-8")
    code = re.findall(r"```python\n(.*?)```", text, flags=re.S)[0]
    assert README_BASE in code
    scope: dict = {}
    with contextlib.redirect_stdout(io.StringIO()):
        exec(compile(code.replace(README_BASE, base), "docs/client.md", "exec"), scope)
    assert isinstance(scope["eq"], EquilibriumOut) and scope["eq"].stable
    assert isinstance(scope["b"], BucklingOut)
    assert scope["b"].critical_force == pytest.approx(-1 / 1.746, rel=0.0005 / 1.746)    # the paper's Table 1
