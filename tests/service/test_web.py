"""The web page (``service/routes/web.py``, ``service/web/``): served offline, only local assets, no traversal.

The browser test that drives the page is ``test_web_e2e.py``.
"""

from __future__ import annotations

import asyncio
import fnmatch
import json
import re
import tomllib
from html.parser import HTMLParser
from importlib import resources
from pathlib import Path

import pytest

pytest.importorskip("httpx")
from fastapi.testclient import TestClient  # noqa: E402
from service_helpers import service_settings  # noqa: E402
from starlette.exceptions import HTTPException  # noqa: E402
from starlette.routing import NoMatchFound  # noqa: E402

from service.api.routes import web  # noqa: E402
from service.main import create_app, openapi_document  # noqa: E402


def _has_page(app) -> bool:
    try:
        app.url_path_for("web_page")
    except NoMatchFound:
        return False
    return True


def _app(include: bool = True):
    """The service's app (``service.main`` registers the page's router)."""
    app = create_app(service_settings())
    assert _has_page(app)
    return app


@pytest.fixture(scope="module")
def client():
    with TestClient(_app()) as c:
        yield c


class _Refs(HTMLParser):
    """Every URL-valued attribute of the page."""

    def __init__(self) -> None:
        super().__init__()
        self.refs: list[tuple[str, str, str]] = []
        self.ids: set[str] = set()

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if name in ("src", "href", "action", "xlink:href", "poster", "srcset", "data") and value is not None:
                self.refs.append((tag, name, value))
            if name == "id" and value:
                self.ids.add(value)


def _page_refs(html: str) -> _Refs:
    p = _Refs()
    p.feed(html)
    return p


EXTERNAL = re.compile(r"(?i)\b(?:https?|wss?|ftp):|(?<![\w:])//[\w.-]+\.[a-z]{2,}")


def test_page_is_html_with_local_assets_only(client):
    r = client.get("/")
    assert r.status_code == 200
    assert r.headers["content-type"].startswith("text/html")
    html = r.text
    assert html == resources.files("service.web").joinpath("index.html").read_text("utf-8")
    refs = _page_refs(html).refs
    urls = {value for _, _, value in refs}
    assert "web/app.js" in urls and "web/app.css" in urls
    for tag, name, value in refs:
        # Relative to this server (or an inline data: URL): no scheme, no host.
        assert value.startswith("data:") or not re.match(r"(?i)^([a-z][a-z0-9+.-]*:|//)", value), (tag, name, value)
    # The page may only talk to this server.
    csp = r.headers["content-security-policy"]
    assert "connect-src 'self'" in csp and "script-src 'self'" in csp and "default-src 'none'" in csp


@pytest.mark.parametrize("name", sorted(web.ASSETS))
def test_no_external_urls_in_assets(client, name):
    text = client.get(f"/web/{name}").text
    assert not EXTERNAL.search(text), EXTERNAL.search(text)
    assert "@import" not in text and "fonts." not in text.lower()
    if name.endswith(".css"):
        for url in re.findall(r"url\(\s*['\"]?([^'\")]+)", text):
            assert url.startswith("data:") or not re.match(r"(?i)^([a-z][a-z0-9+.-]*:|//)", url), url


@pytest.mark.parametrize("name,ctype", [("app.js", "text/javascript"), ("app.css", "text/css"),
                                        ("index.html", "text/html")])
def test_assets_have_their_content_types(client, name, ctype):
    r = client.get(f"/web/{name}")
    assert r.status_code == 200
    assert r.headers["content-type"].split(";")[0].strip() == ctype
    assert "charset=utf-8" in r.headers["content-type"]
    assert r.headers["x-content-type-options"] == "nosniff"
    assert r.content == resources.files("service.web").joinpath(name).read_bytes()   # shipped in the package


@pytest.mark.parametrize("path", [
    "/web/nope.js", "/web/__init__.py", "/web/app.JS", "/web/app.js.map", "/web/", "/web/app.js/x",
    "/web/../main.py", "/web/..%2Fmain.py", "/web/%2e%2e%2fmain.py", "/web/%2E%2E/main.py", "/web/..%5Cmain.py",
    "/web/..%2F..%2Fservice%2Fmain.py", "/web/%2Fetc%2Fpasswd", "/web/....//main.py", "/web/.%2e/routes/web.py",
])
def test_unknown_assets_are_404(client, path):
    r = client.get(path)
    assert r.status_code == 404, (path, r.status_code)
    assert r.headers["content-type"].startswith("application/json")
    assert r.json()["code"] == "not_found"
    assert "create_app" not in r.text and "root:" not in r.text


@pytest.mark.parametrize("asset", ["../main.py", "..\\main.py", "/etc/passwd", "../routes/web.py", "", "."])
def test_asset_route_refuses_paths_even_unnormalised(asset):
    # The URL a client sends may be normalised on the way; the handler itself must refuse too.
    with pytest.raises(HTTPException) as exc:
        asyncio.run(web.web_asset(asset))
    assert exc.value.status_code == 404


@pytest.mark.slow
def test_page_routes_are_not_in_the_openapi_document():
    doc = _app(True).openapi()
    assert "/" not in doc["paths"] and not any(p.startswith("/web") for p in doc["paths"])
    # The document is the service's own, page or no page (the committed openapi/openapi.json is that output).
    assert json.dumps(doc, sort_keys=True) == json.dumps(openapi_document(), sort_keys=True)


def test_script_uses_only_elements_of_the_page():
    html = resources.files("service.web").joinpath("index.html").read_text("utf-8")
    js = resources.files("service.web").joinpath("app.js").read_text("utf-8")
    ids = _page_refs(html).ids
    used = set(re.findall(r"\$\(\"([\w-]+)\"\)", js))
    assert used and used <= ids, used - ids
    # The API paths the page calls exist in the service, relative to the page.
    paths = set(re.findall(r"api\(\"(v1/[\w/-]+)\"", js))
    assert paths == {"v1/equilibrium", "v1/force-deflection", "v1/equilibria", "v1/buckling"}
    assert {"/" + p for p in paths} <= set(_app(True).openapi()["paths"])


def test_assets_are_package_data():
    """``pip install .`` ships the assets: pyproject's package-data for ``service.web`` matches every file."""
    pyproject = Path(__file__).resolve().parents[2] / "pyproject.toml"
    if not pyproject.is_file():
        pytest.skip("no pyproject.toml beside the tests (installed package)")
    conf = tomllib.loads(pyproject.read_text("utf-8")).get("tool", {}).get("setuptools", {})
    globs = conf.get("package-data", {}).get("service.web", [])
    missing = [name for name in web.ASSETS if not any(fnmatch.fnmatch(name, g) for g in globs)]
    assert not missing, f"add to pyproject.toml [tool.setuptools.package-data] \"service.web\": {missing}"


def _asset(name: str) -> str:
    return resources.files("service.web").joinpath(name).read_text("utf-8")


def test_assets_are_ascii_and_css_content_has_no_glyphs():
    """Characters a system font may lack (a busy glyph such as U+23F3 renders as a box in Debian's Chromium) are
    kept out: every asset is ASCII (HTML entities and JS escapes for punctuation), and a CSS ``content`` is
    plain text without escapes; the busy indicator is a CSS animation."""
    for name in web.ASSETS:
        text = _asset(name)
        bad = sorted({c for c in text if ord(c) > 127})
        assert not bad, (name, bad)
    css = _asset("app.css")
    for value in re.findall(r"content:\s*([^;}]+)", css):
        assert "\\" not in value and re.fullmatch(r'"[ -~]*"', value.strip()), value
    spinner = re.search(r'body\[data-state="busy"\] \.spinner \{([^}]*)\}', css)
    assert spinner and "animation: spin" in spinner.group(1) and "@keyframes spin" in css


def test_no_inline_style_attributes():
    """The page's CSP (``style-src 'self'``) blocks style attributes: the script sets styles through the CSSOM
    (``el.style.x = ...``) and the HTML has none."""
    assert "style-src 'self'" in web.CSP and "unsafe-inline" not in web.CSP
    assert not re.search(r"setAttribute\(\s*[\"']style[\"']", _asset("app.js"))
    assert not re.search(r"<[^>]+\sstyle=", _asset("index.html"))


def _js_set(js: str, name: str) -> set[str]:
    m = re.search(r"const " + name + r" = new Set\(\[([^\]]*)\]\)", js)
    assert m, name
    return set(re.findall(r'"(\w+)"', m.group(1)))


def test_error_codes_the_page_classifies_are_the_services():
    """The codes the page shows as physical answers (results) and as refusals are codes the service documents
    (service/errors.py's table, the OpenAPI examples); a physical answer is never also a refusal."""
    from service import examples as ex

    documented = {v["value"]["code"] for d in ex.ERRORS.values() for v in d.values() if "code" in v["value"]}
    errors_py = (Path(__file__).resolve().parents[2] / "service" / "api" / "errors.py")
    documented |= set(re.findall(r"``(\w+)``", errors_py.read_text("utf-8")))
    js = _asset("app.js")
    physical, refusals = _js_set(js, "PHYSICAL"), _js_set(js, "REFUSALS")
    assert physical == {"straight_unstable", "straight_not_equilibrium", "no_equilibrium"}
    assert physical <= documented and refusals <= documented, (physical | refusals) - documented
    assert not physical & refusals
    # Failures of the service (not the input's fault, not physics) stay errors.
    assert not {"solver_failed", "timeout", "overloaded", "numerical_failure"} & (physical | refusals)


def test_figure_downloads_name_figures_of_the_page():
    html = _asset("index.html")
    figures = re.findall(r'data-figure="([\w-]+)"\s+data-format="(svg|png)"', html)
    assert {f for f, _ in figures} == {"chain", "curve", "equilibria-shapes"}
    assert {(f, fmt) for f, fmt in figures} == {(f, fmt) for f, _ in figures for fmt in ("svg", "png")}
    for f, _ in figures:
        assert re.search(r'<svg id="' + f + r'"', html), f
    assert 'id="dl-json"' in html and 'id="boundary-note"' in html
