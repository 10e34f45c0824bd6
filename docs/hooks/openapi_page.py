"""mkdocs hook: the HTTP API page, generated at build time from the committed ``openapi/openapi.json``.

``on_files`` adds ``http-api.md`` (not a file in ``docs/``): per operation the method, the path, the
summary and description, the path and query parameters, the request body's schema name with its
examples as ``curl`` calls, and every response (status, description, schema name per media type).
Nothing is fetched: the page is Markdown rendered by the theme, no Swagger UI, no CDN.

``on_page_markdown`` expands ``<!-- http: POST /v1/buckling paper -->`` in any page into the ``curl``
call of that operation's request example (``paper``), so the analysis pages show bodies the committed
spec holds; an unknown operation or example is an error (the strict build fails).
"""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

from mkdocs.exceptions import PluginError
from mkdocs.structure.files import File

PAGE = "http-api.md"
SPEC = Path("openapi") / "openapi.json"
METHODS = ("get", "post", "put", "patch", "delete")
HTTP_MARK = re.compile(r"<!--\s*http:\s*(GET|POST|PUT|PATCH|DELETE)\s+(\S+)\s+(\S+)\s*-->")
BASE = "http://127.0.0.1:8000"


def _spec(config: Any) -> dict[str, Any]:
    path = Path(config.config_file_path).parent / SPEC
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise PluginError(f"openapi_page: cannot read {path}: {exc}") from exc


def _ref_name(schema: dict[str, Any] | None) -> str:
    """The component name of a schema (``#/components/schemas/X`` -> ``X``), else its type."""
    if not schema:
        return "-"
    if "$ref" in schema:
        return schema["$ref"].rsplit("/", 1)[-1]
    for key in ("anyOf", "oneOf", "allOf"):
        if key in schema:
            return " | ".join(_ref_name(s) for s in schema[key])
    if schema.get("type") == "array":
        return f"array of {_ref_name(schema.get('items'))}"
    return str(schema.get("type", "object"))


def _cell(text: Any) -> str:
    """Text for a Markdown table cell: one line, pipes escaped."""
    return " ".join(str(text).split()).replace("|", "\\|")


def _anchor(method: str, path: str) -> str:
    return re.sub(r"[^a-z0-9]+", "-", f"{method} {path}".lower()).strip("-")


def _curl(method: str, path: str, body: Any) -> str:
    data = json.dumps(body, separators=(", ", ": "))
    return (f"```bash\ncurl -s -X {method.upper()} {BASE}{path} -H 'Content-Type: application/json' \\\n"
            f"     -d '{data}'\n```")


def _examples(op: dict[str, Any]) -> dict[str, Any]:
    content = op.get("requestBody", {}).get("content", {}).get("application/json", {})
    out = dict(content.get("examples", {}))
    if "example" in content:
        out.setdefault("example", {"value": content["example"]})
    return out


def _operation(method: str, path: str, op: dict[str, Any]) -> list[str]:
    lines = [f"### `{method.upper()} {path}` {{ #{_anchor(method, path)} }}", ""]
    if op.get("summary"):
        lines += [f"**{op['summary']}**", ""]
    if op.get("description"):
        lines += [op["description"].strip(), ""]
    params = op.get("parameters", [])
    if params:
        lines += ["| parameter | in | required | type | description |", "|---|---|---|---|---|"]
        for p in params:
            lines.append(f"| `{p['name']}` | {p['in']} | {'yes' if p.get('required') else 'no'} | "
                         f"{_cell(_ref_name(p.get('schema')))} | {_cell(p.get('description', ''))} |")
        lines.append("")
    body = op.get("requestBody")
    if body:
        for media, c in body.get("content", {}).items():
            lines += [f"Request body (`{media}`): `{_ref_name(c.get('schema'))}`"
                      + (" (required)" if body.get("required") else ""), ""]
    else:
        lines += ["Request body: none", ""]
    lines += ["| status | description | body |", "|---|---|---|"]
    for status, r in op.get("responses", {}).items():
        media = ", ".join(f"`{m}`: `{_ref_name(c.get('schema'))}`" for m, c in r.get("content", {}).items()) or "-"
        lines.append(f"| {status} | {_cell(r.get('description', ''))} | {_cell(media)} |")
    lines.append("")
    for name, ex in _examples(op).items():
        title = ex.get("summary", name)
        lines += [f"Example `{name}`: {title}", "", _curl(method, path, ex.get("value")), ""]
    return lines


def render(spec: dict[str, Any]) -> str:
    """The Markdown of the HTTP API page for an OpenAPI document."""
    info = spec.get("info", {})
    ops = [(m, p, op) for p, item in spec.get("paths", {}).items() for m, op in item.items() if m in METHODS]
    lines = ["# HTTP API", "",
             f"Generated at build time from the committed `openapi/openapi.json` ({info.get('title', '')} "
             f"{info.get('version', '')}, OpenAPI {spec.get('openapi', '')}; `tensegrity-opt openapi` prints it). "
             f"The running server serves the same document interactively at `/docs` (Swagger UI) and `/redoc`, "
             f"from installed packages.", "",
             # the description's own paragraph on the WebSocket, linked to its guide (said once)
             info.get("description", "").strip().replace("`docs/stream.md`", "[The control stream](stream.md)"),
             "",
             "## Operations", "", "| method | path | summary |", "|---|---|---|"]
    for m, p, op in ops:
        lines.append(f"| {m.upper()} | [`{p}`](#{_anchor(m, p)}) | {_cell(op.get('summary', ''))} |")
    lines.append("")
    tags: dict[str, list] = {}
    for m, p, op in ops:
        tags.setdefault((op.get("tags") or ["other"])[0], []).append((m, p, op))
    for tag, items in tags.items():
        lines += [f"## {tag}", ""]
        for m, p, op in items:
            lines += _operation(m, p, op)
    lines += ["## Schemas", "", "The request and response models named above (`components.schemas`):", "",
              "| schema | description |", "|---|---|"]
    for name, s in sorted(spec.get("components", {}).get("schemas", {}).items()):
        lines.append(f"| `{name}` | {_cell(s.get('description', s.get('title', '')))} |")
    lines.append("")
    return "\n".join(lines)


def on_files(files: Any, config: Any) -> Any:
    files.append(File.generated(config, PAGE, content=render(_spec(config))))
    return files


def on_page_markdown(markdown: str, page: Any, config: Any, files: Any) -> str:
    if "<!--" not in markdown:
        return markdown
    spec = _spec(config)

    def expand(mt: re.Match) -> str:
        method, path, name = mt.group(1).lower(), mt.group(2), mt.group(3)
        op = spec.get("paths", {}).get(path, {}).get(method)
        if op is None:
            raise PluginError(f"{page.file.src_uri}: no operation {method.upper()} {path} in {SPEC}")
        ex = _examples(op).get(name)
        if ex is None:
            raise PluginError(f"{page.file.src_uri}: {method.upper()} {path} has no request example {name!r} "
                              f"(it has {sorted(_examples(op))})")
        return _curl(method, path, ex.get("value"))

    return HTTP_MARK.sub(expand, markdown)
