"""JSON bodies: the one renderer of every JSON answer, and the response class that uses it."""

from __future__ import annotations

import json
import math
from typing import Any

from starlette.responses import JSONResponse

__all__ = ["render_json", "json_safe", "SafeJSONResponse"]


def json_safe(x: Any) -> Any:
    """``x`` with every NaN or infinite float (in nested dicts, lists, tuples) replaced by ``None``."""
    if isinstance(x, float):
        return x if math.isfinite(x) else None
    if isinstance(x, dict):
        return {k: json_safe(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [json_safe(v) for v in x]
    return x


def render_json(content: Any) -> bytes:
    """Compact UTF-8 JSON that is always valid: a NaN or infinity that slipped through becomes ``null``."""
    try:
        return json.dumps(content, ensure_ascii=False, allow_nan=False, separators=(",", ":")).encode("utf-8")
    except ValueError:
        return json.dumps(json_safe(content), ensure_ascii=False, allow_nan=False,
                          separators=(",", ":")).encode("utf-8")


class SafeJSONResponse(JSONResponse):
    """The application's default response class (:func:`render_json`)."""

    def render(self, content: Any) -> bytes:
        return render_json(content)
