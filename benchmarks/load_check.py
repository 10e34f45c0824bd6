#!/usr/bin/env python3
"""Load check of the HTTP service (not a timed test).

Drives ``--clients`` concurrent keep-alive clients (default 32) at ``POST /v1/equilibrium``
(the paper's chain, n = 4) on loopback for ``--duration`` seconds (default 10), then the same at
``GET /healthz`` for comparison, and prints requests/s, p50/p99/max latency and error counts.
While the solve phase runs, one extra probe measures ``/healthz`` latency under load (how
responsive the event loop stays while the solver threads work).

By default it starts its own server (``tensegrity-opt serve`` on a free loopback port, settings
from the environment, e.g. ``TENSEGRITY_WORKERS``) and stops it afterwards; ``--url`` targets a
running one instead. The HTTP client is :mod:`benchmarks.http_load` (shared with the benchmark
suite).

    python benchmarks/load_check.py                     # own server, 32 clients, 10 s per phase
    python benchmarks/load_check.py --url http://127.0.0.1:8000 --duration 5
"""

from __future__ import annotations

import argparse
import sys

import httpx

try:
    from benchmarks.http_load import PhaseStats, json_body, load_phase, load_phase_with_probe, own_server
except ImportError:                 # run as a script: benchmarks/ is on sys.path
    from http_load import PhaseStats, json_body, load_phase, load_phase_with_probe, own_server

PAPER = {"manipulator": {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}, "dx": 0.1, "dy": 0.0}


def line(label: str, st: PhaseStats) -> str:
    s = st.summary()
    ok = st.statuses.get("200", 0)
    errors = {k: v for k, v in sorted(st.statuses.items()) if k != "200"}
    return (f"{label:<28} {s['requests']:>7} req  {s['throughput_rps']:>8.1f} req/s  p50 {s['p50_ms']:>7.2f} ms  "
            f"p99 {s['p99_ms']:>7.2f} ms  max {s['max_ms']:>8.2f} ms  ok {ok}  errors {sum(errors.values())}"
            + (f" {dict(errors)}" if errors else ""))


def run(url: str, clients: int, duration: float) -> None:
    info = httpx.get(f"{url}/version", timeout=10).json()
    lim = info.get("limits", {})
    print(f"tensegrity-opt service {info.get('version')} at {url}: workers={lim.get('workers')} "
          f"queue={lim.get('queue_size')}; {clients} concurrent keep-alive clients, {duration:g} s per phase")
    body = json_body(PAPER)
    eq, probe = load_phase_with_probe(url, lambda i, k: ("POST", "/v1/equilibrium", body),
                                      lambda i, k: ("GET", "/healthz", None), clients, duration)
    print(line("POST /v1/equilibrium (n=4)", eq))
    print(line("  GET /healthz during solves", probe))
    print(line("GET /healthz", load_phase(url, lambda i, k: ("GET", "/healthz", None), clients, duration)))


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--url", help="a running server (default: start one on a free loopback port)")
    p.add_argument("--clients", type=int, default=32)
    p.add_argument("--duration", type=float, default=10.0, help="seconds per phase (default 10)")
    p.add_argument("--workers", type=int, default=None, help="TENSEGRITY_WORKERS for the server it starts")
    args = p.parse_args(argv)
    if args.url:
        run(args.url.rstrip("/"), args.clients, args.duration)
    else:
        env = {} if args.workers is None else {"TENSEGRITY_WORKERS": str(args.workers)}
        with own_server(env=env) as url:
            run(url, args.clients, args.duration)
    return 0


if __name__ == "__main__":
    sys.exit(main())
