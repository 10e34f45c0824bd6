"""The documentation site builds in strict mode (every warning an error) and has its pages.

``python -m mkdocs build --strict`` from the repository root (``mkdocs.yml``): the guides in ``docs/``, the
analysis pages, the API reference from the numpydoc docstrings (mkdocstrings-python) and the HTTP API
page that ``docs/hooks/openapi_page.py`` generates from the committed ``openapi/openapi.json``. Broken links,
anchors, images, docstrings griffe cannot parse and a hook error all fail the build.
"""

import html
import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
METHODS = ("get", "post", "put", "patch", "delete")


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    out = tmp_path_factory.mktemp("site")
    env = dict(os.environ, NO_MKDOCS_2_WARNING="1")
    proc = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "--site-dir", str(out)],
                          cwd=ROOT, env=env, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, f"mkdocs build --strict failed:\n{proc.stdout}\n{proc.stderr}"
    return out


def test_pages_exist(site):
    for page in ["index.html", "getting-started.html", "model.html", "analyses.html", "http-api.html",
                 "design.html", "paths.html", "stream.html", "architecture.html", "figures.html", "notebook.html",
                 "reference/index.html", "reference/buckling.html", "notebooks/paper.ipynb"]:
        assert (site / page).is_file(), page


def test_api_reference_renders_the_docstrings(site):
    text = (site / "reference" / "buckling.html").read_text(encoding="utf-8")
    assert 'id="tensegrity_opt.analyses.equilibria.buckling.critical_force"' in text
    assert 'id="tensegrity_opt.analyses.paths.curves.force_deflection"' in text
    # the numpydoc "Parameters" section of critical_force, rendered as a section, not as raw text
    assert "----------" not in text
    assert "boundary" in text and "Parameters" in text
    # Sphinx roles in the docstrings are shown as their targets (docs/hooks/sphinx_roles.py), not raw
    for page in (site / "reference").glob("*.html"):
        assert not re.search(r":(func|class|mod|meth|data|attr):`", page.read_text(encoding="utf-8")), page.name
    model = (site / "reference" / "model.html").read_text(encoding="utf-8")
    assert 'id="tensegrity_opt.model.manipulator.Manipulator"' in model


def test_http_api_page_has_every_operation(site):
    spec = json.loads((ROOT / "openapi" / "openapi.json").read_text(encoding="utf-8"))
    text = html.unescape((site / "http-api.html").read_text(encoding="utf-8"))
    plain = re.sub(r"<[^>]+>", "", text)
    ops = [(m, p, op) for p, item in spec["paths"].items() for m, op in item.items() if m in METHODS]
    assert len(ops) >= 40
    for method, path, op in ops:
        assert f"{method.upper()} {path}" in plain, (method, path)
        assert op["summary"] in plain, (method, path)
        body = op.get("requestBody", {}).get("content", {}).get("application/json", {}).get("schema", {})
        if "$ref" in body:
            assert body["$ref"].rsplit("/", 1)[-1] in plain, (method, path)
        for status in op["responses"]:
            assert f"{status}" in plain


def test_http_api_page_says_its_websocket_paragraph_once_with_the_guide_linked(site):
    page = (site / "http-api.html").read_text(encoding="utf-8")
    intro = page[page.index("<h1"):page.index('id="operations"')]          # the page's text before its table
    assert re.sub(r"<[^>]+>", "", html.unescape(intro)).count("/v1/control/stream") == 1
    assert 'href="stream.html"' in intro


def test_code_blocks_wrap_instead_of_scrolling_off_the_page(site):
    page = (site / "getting-started.html").read_text(encoding="utf-8")
    (css,) = re.findall(r'href="(stylesheets/[^"]+\.css)"', page)
    rules = (site / css).read_text(encoding="utf-8")
    assert re.search(r"pre\s*>\s*code\s*\{[^}]*white-space:\s*pre-wrap", rules)


def test_analysis_pages_show_the_spec_examples_and_figures(site):
    text = html.unescape(re.sub(r"<[^>]+>", "", (site / "analyses.html").read_text(encoding="utf-8")))
    assert "<!-- http:" not in text
    assert text.count("curl -s -X POST http://127.0.0.1:8000/v1/") >= 18
    assert '"boundary": "guided"' in text                  # the buckling example body, from openapi.json
    page = (site / "analyses.html").read_text(encoding="utf-8")
    for img in re.findall(r'<img [^>]*src="([^"]+)"', page):
        assert (site / img).is_file(), img


def test_offline_no_cdn(site):
    for page in ["index.html", "http-api.html", "reference/buckling.html"]:
        text = (site / page).read_text(encoding="utf-8")
        assert not re.search(r'<(script|link)[^>]+(src|href)="(https?:)?//', text), page


def test_the_docs_packages_are_extras():
    import tomllib
    extras = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]["optional-dependencies"]
    names = lambda reqs: {re.split(r"[<>=;\[ ]", r, maxsplit=1)[0] for r in reqs}  # noqa: E731
    assert {"mkdocs", "mkdocs-material", "mkdocstrings"} <= names(extras["docs"]) <= names(extras["test"])
    assert {"nbclient", "nbformat", "ipykernel"} <= names(extras["test"])
    assert any(r.startswith("mkdocstrings[python]") for r in extras["docs"])       # the Python handler
