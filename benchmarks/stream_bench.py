"""Round trip per control step over loopback: the WebSocket control stream against REST.

One client, one step at a time (a control loop: send, wait for the answer, send the next), against a
``tensegrity-opt serve`` started for the run at its default settings:

* ``stream track``: ``/v1/control/stream`` in mode ``track``, one ``{"type": "step", "dx", "dy"}`` per step
  (``Tracker.solve`` in the stream's solver thread);
* ``stream inverse``: mode ``inverse``, one ``{"type": "step", "target"}`` per step under a dead load
  (``PreloadController.step``: the compiled least-change Newton step);
* ``REST local``: ``POST /v1/equilibrium`` with ``q0`` = the previous answer and ``"local": true`` per step,
  the REST API's control step (the solver process of ``service/execution/processes.py``), on the same trajectory as
  ``stream track``, over one keep-alive connection (the minimal HTTP client of :mod:`benchmarks.http_load`);
* ``library``: the same calls in this process (no transport): what the answer itself costs.

Run: ``python -m benchmarks.stream_bench [--steps 2000] [--n 4] [--json]``. The goal: p99 <= 1 ms for
n = 4 in track mode. Every stream answer is checked to be a result (and the REST ones 200).
"""

from __future__ import annotations

import argparse
import asyncio
import gc
import json
import math
import sys
import time
from typing import Any

import numpy as np

import tensegrity_opt as to
from tensegrity_opt.analyses.design.preload_control import PreloadController
from tensegrity_opt.analyses.paths.continuation import Tracker

from .http_load import _Connection, _host_port, json_body, own_server

__all__ = ["track_path", "inverse_path", "stream_steps", "rest_local_steps", "library_steps", "run", "table", "main"]

#: Dead tip load of the inverse mode (the paper's chain, as in tests/analyses/design/test_preload_control.py).
LOAD = (-0.02, 0.01)
#: Steps before the timed ones (first builds, caches).
WARMUP = 50


def track_path(steps: int, n: int) -> list[tuple[float, float]]:
    """A smooth closed loop of tip deflections (length units; the chain is 2 n long)."""
    s = np.arange(steps) / max(steps, 1)
    scale = n / 4.0
    return [(float(scale * (0.4 + 0.3 * math.sin(2 * math.pi * t))), float(scale * 0.3 * math.sin(4 * math.pi * t)))
            for t in s]


def inverse_path(steps: int, n: int) -> list[list[float]]:
    """Tip poses from the start pose under ``LOAD`` out along an arc and back (every step a Newton step for
    n = 4; the trajectory of tests/analyses/design/test_preload_control.py, finer)."""
    m = to.Manipulator.uniform(n)
    tip0 = m.tip(PreloadController(m, load=LOAD).q)
    s = np.arange(steps) / max(steps, 1)
    return [(tip0 + np.array([-0.15, 0.3]) * math.sin(math.pi * t)).tolist() for t in s]


def _stats(ts: list[float]) -> dict[str, float]:
    a = np.asarray(ts) * 1e3
    return {"steps": len(ts), "p50_ms": float(np.percentile(a, 50)), "p99_ms": float(np.percentile(a, 99)),
            "mean_ms": float(a.mean()), "max_ms": float(a.max())}


async def stream_steps(url: str, open_msg: dict[str, Any], steps: list[dict[str, Any]]) -> list[float]:
    """Seconds per step (send to answer) over one stream; the first ``WARMUP`` are not returned."""
    import websockets

    ws_url = url.replace("http://", "ws://") + "/v1/control/stream"
    out: list[float] = []
    async with websockets.connect(ws_url, compression=None, max_size=None) as ws:
        await ws.send(json.dumps(open_msg))
        opened = json.loads(await ws.recv())
        if opened["type"] != "opened":
            raise RuntimeError(f"the stream was not opened: {opened}")
        texts = [json.dumps(st, separators=(",", ":")) for st in steps]
        for i, text in enumerate(texts):
            t0 = time.perf_counter()
            await ws.send(text)
            ans = await ws.recv()
            dt = time.perf_counter() - t0
            if not ans.startswith('{"type":"result"'):
                raise RuntimeError(f"step {i}: {ans[:300]}")
            if i >= WARMUP:
                out.append(dt)
    return out


async def rest_local_steps(url: str, n: int, path: list[tuple[float, float]]) -> list[float]:
    """Seconds per ``POST /v1/equilibrium`` (``q0`` the previous answer, ``local: true``)."""
    host, port = _host_port(url)
    conn = _Connection(host, port)
    chain = {"n": n, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}
    out: list[float] = []
    q0 = None
    try:
        for i, (dx, dy) in enumerate(path):
            body: dict[str, Any] = {"manipulator": chain, "dx": dx, "dy": dy}
            if q0 is not None:
                body.update(q0=q0, local=True)
            raw = json_body(body)
            t0 = time.perf_counter()
            status, payload = await conn.request("POST", "/v1/equilibrium", raw)
            dt = time.perf_counter() - t0
            if status != 200:
                raise RuntimeError(f"step {i}: {status} {payload[:300]!r}")
            q0 = json.loads(payload)["q"]
            if i >= WARMUP:
                out.append(dt)
    finally:
        conn.close()
    return out


def library_steps(n: int, track: list[tuple[float, float]], targets: list[list[float]]) -> dict[str, list[float]]:
    """Seconds per ``Tracker.solve`` and per ``PreloadController.step`` in this process."""
    m = to.Manipulator.uniform(n)
    tr = Tracker(m)
    out: dict[str, list[float]] = {"track": [], "inverse": []}
    for i, (dx, dy) in enumerate(track):
        t0 = time.perf_counter()
        tr.solve(dx, dy)
        if i >= WARMUP:
            out["track"].append(time.perf_counter() - t0)
    ctl = PreloadController(m, load=LOAD)
    for i, tgt in enumerate(targets):
        t0 = time.perf_counter()
        ctl.step(tgt)
        if i >= WARMUP:
            out["inverse"].append(time.perf_counter() - t0)
    return out


def run(steps: int = 2000, n: int = 4, url: str | None = None) -> list[dict[str, Any]]:
    """The table's rows (a server is started unless ``url`` is given)."""
    track = track_path(steps + WARMUP, n)
    targets = inverse_path(steps + WARMUP, n)
    chain = {"n": n, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}
    enabled = gc.isenabled()
    gc.disable()
    try:
        lib = library_steps(n, track, targets)
    finally:
        if enabled:
            gc.enable()

    async def measure(base: str) -> dict[str, list[float]]:
        return {
            "stream track": await stream_steps(base, {"type": "open", "manipulator": chain, "mode": "track"},
                                               [{"type": "step", "dx": dx, "dy": dy} for dx, dy in track]),
            "stream inverse": await stream_steps(base, {"type": "open", "manipulator": chain, "mode": "inverse",
                                                        "load": list(LOAD)},
                                                 [{"type": "step", "target": t} for t in targets]),
            "REST local (POST /v1/equilibrium)": await rest_local_steps(base, n, track),
        }

    def go(base: str) -> dict[str, list[float]]:
        try:
            import uvloop
            runner = uvloop.run
        except ImportError:
            runner = asyncio.run
        enabled = gc.isenabled()
        gc.disable()            # a collection in the client would count as server latency
        try:
            return runner(measure(base))
        finally:
            if enabled:
                gc.enable()

    if url is None:
        with own_server() as base:
            got = go(base)
    else:
        got = go(url)
    rows = [{"what": k, "n": n, **_stats(v)} for k, v in got.items()]
    rows += [{"what": f"library {k} (in process)", "n": n, **_stats(v)} for k, v in lib.items()]
    return rows


def table(rows: list[dict[str, Any]]) -> str:
    head = "| what | n | steps | p50 ms | p99 ms | mean ms | max ms |\n|---|---|---|---|---|---|---|\n"
    return head + "".join(f"| {r['what']} | {r['n']} | {r['steps']} | {r['p50_ms']:.3f} | {r['p99_ms']:.3f} | "
                          f"{r['mean_ms']:.3f} | {r['max_ms']:.3f} |\n" for r in rows)


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--steps", type=int, default=2000, help="timed steps per mode (default 2000)")
    p.add_argument("--n", type=int, default=4, help="segments (default 4)")
    p.add_argument("--url", default=None, help="a running server (default: start one)")
    p.add_argument("--json", action="store_true", help="print the rows as JSON")
    args = p.parse_args(argv)
    rows = run(args.steps, args.n, args.url)
    print(json.dumps(rows, indent=2) if args.json else table(rows), end="" if not args.json else "\n")
    track = next(r for r in rows if r["what"] == "stream track")
    print(f"\ngoal p99 <= 1 ms for stream track: {'met' if track['p99_ms'] <= 1.0 else 'NOT met'} "
          f"({track['p99_ms']:.3f} ms)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
