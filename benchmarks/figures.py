"""The figure routes against their time limit: ``python -m benchmarks.figures [--reps N] [--url URL]``.

Every route of ``service/api/routes/plots.py``'s ``FIGURES`` table gets its default request (the route's first
OpenAPI example: what the API page's "Try it out" sends) on a server of default settings (its own, started for
the run, unless ``--url``): the first answer of the server (matplotlib imported, the figure's solvers built)
and the median of ``--reps`` more, in seconds of wall time from the client, against the server's time limit
(``TENSEGRITY_SOLVE_TIMEOUT``, 10 s by default). The target is a margin of 3 (the median at most a third of the
limit) on a machine whose two cores other processes share. Also run by the suite (``python -m benchmarks``,
case 12: the figures table).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import sys
import time
from typing import Any

#: The margin of the target: a default figure takes at most ``limit / MARGIN`` (median).
MARGIN = 3.0


def default_requests() -> list[tuple[str, str, dict[str, Any]]]:
    """``(route, example name, body)`` of every figure route: its first OpenAPI example."""
    from service.api.routes.plots import FIGURES

    out = []
    for fig in FIGURES:
        name, example = next(iter(fig.examples.items()))
        out.append((f"/v1/plots/{fig.kind}", name, example["value"]))
    return out


#: Explicit requests measured beside the defaults: the larger figures users ask for (not defaults, no target).
EXPLICIT: list[tuple[str, str, dict[str, Any]]] = [
    ("/v1/plots/atlas", "5 x 5 targets", {"manipulator": {"n": 3, "a": 0.5, "b": 1.0, "k": 1.0, "L0": 1.0},
                                          "dx": {"start": 0.2, "stop": 1.4, "num": 5},
                                          "dy": {"start": -0.6, "stop": 0.6, "num": 5}}),
    ("/v1/plots/landscape", "grid 101", {"manipulator": {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0},
                                         "dx": 0.1, "dy": 0.0, "pair": [0, 3], "grid": 101}),
]


def describe(body: dict[str, Any]) -> str:
    """A short description of a request body (the chain and the fields that set the work)."""
    parts = []
    m = body.get("manipulator")
    if isinstance(m, dict) and "n" in m:
        parts.append(f"n={m['n']}" + ("" if m.get("a", 1.0) == 1.0 else f", a={m['a']}"))
    for key in ("dx", "dy", "values_x", "values_y", "grid", "targets", "loads", "segments", "t_max", "depth"):
        v = body.get(key)
        if isinstance(v, dict) and "num" in v:
            parts.append(f"{key}: {v['num']} values")
        elif isinstance(v, list) and key in ("targets", "loads", "segments") and v and isinstance(v[0], (list, dict)):
            parts.append(f"{key}: {len(v)}")
        elif isinstance(v, (int, float)) and key != "dy":
            parts.append(f"{key}={v:g}")
    return ", ".join(parts)


def measure(url: str, reps: int = 3, limit: float = 10.0, explicit: bool = True) -> list[dict[str, Any]]:
    """Time every figure route's default request on the server at ``url`` (``limit``: its time limit, s), then
    the :data:`EXPLICIT` requests (``default: False``, no target)."""
    import httpx

    rows = []
    todo = [(*r, True) for r in default_requests()] + ([(*r, False) for r in EXPLICIT] if explicit else [])
    with httpx.Client(base_url=url, timeout=max(120.0, 3 * limit)) as client:
        for route, name, body, default in todo:
            times, status, size = [], None, 0
            for _ in range(reps + 1):
                t0 = time.perf_counter()
                resp = client.post(route, json=body)
                times.append(time.perf_counter() - t0)
                status, size = resp.status_code, len(resp.content)
                if status != 200:
                    break
            warm = times[1:] or times
            med = statistics.median(warm)
            rows.append({"route": route, "example": name, "request": describe(body), "first_s": times[0],
                         "median_s": med, "samples_s": warm, "status": status, "bytes": size, "limit_s": limit,
                         "target_s": limit / MARGIN, "default": default,
                         "met": (status == 200 and med <= limit / MARGIN) if default else None})
    return rows


def table(rows: list[dict[str, Any]]) -> list[str]:
    """The figures table (markdown lines)."""
    out = ["| route | default request | seconds: first / median | the limit | status | within limit / "
           f"{MARGIN:g}? |", "|---|---|---|---|---|---|"]
    for r in rows:
        met = "-" if r["met"] is None else "yes" if r["met"] else "NO"
        what = f"{r['example']}: {r['request']}" + ("" if r["default"] else " (explicit, not a default)")
        out.append(f"| `POST {r['route']}` | {what} | {r['first_s']:.2f} / {r['median_s']:.2f} | {r['limit_s']:g} s "
                   f"| {r['status']} | {met} |")
    return out


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m benchmarks.figures", description=__doc__.splitlines()[0])
    p.add_argument("--reps", type=int, default=3, help="timed requests per route after the first (default 3)")
    p.add_argument("--url", default=None, help="a running server (default: start one with default settings)")
    p.add_argument("--json", default=None, help="write the rows as JSON here")
    args = p.parse_args(argv)
    limit = float(os.environ.get("TENSEGRITY_SOLVE_TIMEOUT", "10"))
    if args.url:
        rows = measure(args.url, args.reps, limit)
    else:
        from .http_load import own_server

        with own_server() as url:
            rows = measure(url, args.reps, limit)
    load = list(os.getloadavg()) if hasattr(os, "getloadavg") else None
    print("\n".join(table(rows)))
    print(f"\nload average {load}, {os.cpu_count()} cores")
    if args.json:
        with open(args.json, "w", encoding="utf-8") as fh:
            json.dump({"rows": rows, "loadavg": load}, fh, indent=2)
    return 0 if all(r["met"] is not False for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
