"""The API's documents: the OpenAPI document and the interactive docs that work offline, served from bytes built once.

``/openapi.json`` is the application's document (:func:`service.main.openapi_document`), encoded the first time it
is asked for (per ``root_path``, which FastAPI adds to ``servers``) and then answered from those bytes: encoding the
~390 KB document takes 10-30 ms of the event loop, and per request 100 connections pipelining it keep ``/healthz``
waiting for tens of seconds. With API keys configured it needs a key like the API (``install(app, dependencies)``).

``/docs`` (Swagger UI) and ``/redoc`` load their JavaScript and CSS from this server,
``/static/docs/...``, which serves the files shipped inside the ``fastapi-offline`` package
(Swagger UI 5, which renders OpenAPI 3.1): no CDN is contacted. Their pages are built once per ``root_path`` too.
"""

from __future__ import annotations

import importlib.util
import json
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

from fastapi import FastAPI, Request
from fastapi.openapi.docs import get_redoc_html, get_swagger_ui_html, get_swagger_ui_oauth2_redirect_html
from fastapi.params import Depends
from fastapi.staticfiles import StaticFiles
from starlette.responses import Response

STATIC_URL = "/static/docs"
OPENAPI_URL = "/openapi.json"
#: Distinct ``root_path`` values whose bytes are kept (the server's own, set by its launcher: one in practice).
MAX_ROOT_PATHS = 8

__all__ = ["assets_dir", "install", "encode_document", "STATIC_URL", "OPENAPI_URL"]


def assets_dir() -> Path:
    """Directory holding ``swagger-ui-bundle.js``, ``swagger-ui.css``, ``redoc.standalone.js``, ``favicon.png``."""
    spec = importlib.util.find_spec("fastapi_offline")
    if spec is None or not spec.submodule_search_locations:
        raise RuntimeError("the fastapi-offline package (Swagger UI assets) is not installed")
    return Path(list(spec.submodule_search_locations)[0]) / "static"


def encode_document(doc: dict[str, Any]) -> bytes:
    """The document as served (what Starlette's ``JSONResponse`` would send)."""
    return json.dumps(doc, ensure_ascii=False, allow_nan=False, indent=None, separators=(",", ":")).encode("utf-8")


class _Built:
    """Bytes built once per ``root_path`` by ``build(root_path)`` (at most :data:`MAX_ROOT_PATHS` kept)."""

    def __init__(self, build: Callable[[str], bytes]) -> None:
        self.build = build
        self.by_root: dict[str, bytes] = {}

    def __call__(self, request: Request) -> bytes:
        root = request.scope.get("root_path", "").rstrip("/")
        body = self.by_root.get(root)
        if body is None:
            body = self.build(root)
            if len(self.by_root) < MAX_ROOT_PATHS:
                self.by_root[root] = body
        return body


def install(app: FastAPI, dependencies: Sequence[Depends] = ()) -> None:
    """Mount the assets and add ``/openapi.json`` (with ``dependencies``: the API key when the server has keys),
    ``/docs``, ``/docs/oauth2-redirect`` and ``/redoc`` (none of them in the document). The app must be built
    with ``openapi_url=None`` (FastAPI's own route encodes the document per request)."""
    app.mount(STATIC_URL, StaticFiles(directory=str(assets_dir())), name="docs-static")
    oauth2_url = app.swagger_ui_oauth2_redirect_url or "/docs/oauth2-redirect"

    def document(root: str) -> bytes:
        doc = app.openapi()
        if root and app.root_path_in_servers and root not in {s.get("url") for s in doc.get("servers", [])}:
            doc = {**doc, "servers": [{"url": root}, *doc.get("servers", [])]}
        return encode_document(doc)

    def swagger(root: str) -> bytes:
        return bytes(get_swagger_ui_html(
            openapi_url=f"{root}{OPENAPI_URL}", title=f"{app.title} - Swagger UI",
            oauth2_redirect_url=f"{root}{oauth2_url}",
            swagger_js_url=f"{root}{STATIC_URL}/swagger-ui-bundle.js",
            swagger_css_url=f"{root}{STATIC_URL}/swagger-ui.css",
            swagger_favicon_url=f"{root}{STATIC_URL}/favicon.png").body)

    def redoc(root: str) -> bytes:
        return bytes(get_redoc_html(openapi_url=f"{root}{OPENAPI_URL}", title=f"{app.title} - ReDoc",
                                    redoc_js_url=f"{root}{STATIC_URL}/redoc.standalone.js",
                                    redoc_favicon_url=f"{root}{STATIC_URL}/favicon.png",
                                    with_google_fonts=False).body)

    document_bytes, swagger_bytes, redoc_bytes = _Built(document), _Built(swagger), _Built(redoc)
    redirect_bytes = bytes(get_swagger_ui_oauth2_redirect_html().body)
    html = "text/html; charset=utf-8"

    @app.get(OPENAPI_URL, include_in_schema=False, dependencies=list(dependencies))
    async def openapi_document(request: Request) -> Response:
        return Response(document_bytes(request), media_type="application/json")

    @app.get("/docs", include_in_schema=False)
    async def swagger_ui(request: Request) -> Response:
        return Response(swagger_bytes(request), media_type=html)

    @app.get(oauth2_url, include_in_schema=False)
    async def swagger_ui_redirect() -> Response:
        return Response(redirect_bytes, media_type=html)

    @app.get("/redoc", include_in_schema=False)
    async def redoc_ui(request: Request) -> Response:
        return Response(redoc_bytes(request), media_type=html)
