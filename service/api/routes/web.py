"""The web page: ``GET /`` and its static assets ``GET /web/{asset}``.

Plain HTML, JavaScript and CSS shipped inside the ``service.web`` package (no build step, no CDN,
no external fonts): the page works without internet. It calls the JSON API with ``fetch()``
(``/v1/equilibrium``, ``/v1/force-deflection``, ``/v1/equilibria``, ``/v1/buckling``) using URLs relative
to the page, so it also works behind a path prefix. Neither route is part of the OpenAPI document.
Its downloads (the results as JSON, the figures as SVG or PNG) are made in the browser from what it
already has (no further request). Styles are set through the CSSOM, never as style attributes, which
the policy below (``style-src 'self'``) blocks.

Only the files listed in :data:`ASSETS` are served (a fixed table, never a path built from the
request), so no other file can be reached: ``/web/../main.py`` and the like answer 404.
"""

from __future__ import annotations

from functools import lru_cache
from importlib import resources

from fastapi import APIRouter
from starlette.exceptions import HTTPException
from starlette.responses import Response

__all__ = ["router", "ASSETS", "asset_bytes"]

#: Every file the page needs: name -> content type.
ASSETS: dict[str, str] = {
    "index.html": "text/html; charset=utf-8",
    "app.js": "text/javascript; charset=utf-8",
    "app.css": "text/css; charset=utf-8",
}

#: The page talks to this server only (and uses ``data:`` for its empty favicon).
CSP = ("default-src 'none'; script-src 'self'; style-src 'self'; img-src 'self' data:; connect-src 'self'; "
       "base-uri 'none'; form-action 'none'; frame-ancestors 'self'")

router = APIRouter(tags=["web"])


@lru_cache(maxsize=None)
def asset_bytes(name: str) -> bytes:
    """The content of one shipped asset (``name`` must be a key of :data:`ASSETS`)."""
    if name not in ASSETS:
        raise KeyError(name)
    return resources.files("service.web").joinpath(name).read_bytes()


def _response(name: str) -> Response:
    headers = {"Cache-Control": "no-cache", "X-Content-Type-Options": "nosniff"}
    if name.endswith(".html"):
        headers["Content-Security-Policy"] = CSP
    return Response(content=asset_bytes(name), media_type=ASSETS[name], headers=headers)


@router.get("/", include_in_schema=False)
async def web_page() -> Response:
    """The page (``text/html``)."""
    return _response("index.html")


@router.get("/web/{asset}", include_in_schema=False)
async def web_asset(asset: str) -> Response:
    """One of the page's static files; 404 for anything else."""
    if asset not in ASSETS:
        raise HTTPException(status_code=404, detail=f"no such asset: {asset[:100]}")
    return _response(asset)
