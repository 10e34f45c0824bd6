#!/usr/bin/env python3
"""Overload check of the HTTP service (not a timed test): the share of 503 against 504 answers.

``--clients`` closed-loop keep-alive clients (default 32) send light requests on the paper's chain (n = 4) for
``--duration`` seconds: single equilibria at random targets, every equilibrium by the search, stiffness and
force-deflection curves of 150-450 points, in turn. More clients than the solver threads can serve within the time
limit: the server must refuse early (503 + ``Retry-After``) what it cannot start in time, instead of answering
504 at the limit. Prints the answers by status, each status's share and median latency.

    python benchmarks/overload_check.py                  # own server, 32 clients, 40 s
    python benchmarks/overload_check.py --solve-timeout 2     # a limit the queue's wait reaches here
    python benchmarks/overload_check.py --url http://127.0.0.1:8000 --duration 20
"""

from __future__ import annotations

import argparse
import collections
import random
import statistics
import time

try:
    from benchmarks.http_load import _client, _host_port, _run, json_body, own_server
except ImportError:                 # run as a script: benchmarks/ is on sys.path
    from http_load import _client, _host_port, _run, json_body, own_server

PAPER = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}


def request(idx: int, k: int) -> tuple[str, str, bytes]:
    rnd = random.Random(idx * 100_003 + k)
    dx, dy = rnd.uniform(0.1, 1.5), rnd.uniform(-0.3, 0.3)
    kind = (idx + k) % 4
    if kind == 0:
        return "POST", "/v1/equilibrium", json_body({"manipulator": PAPER, "dx": dx, "dy": dy})
    if kind == 1:
        return "POST", "/v1/equilibria", json_body({"manipulator": PAPER, "dx": dx, "dy": dy})
    if kind == 2:
        return "POST", "/v1/stiffness", json_body({"manipulator": PAPER, "dx": dx, "dy": dy})
    return "POST", "/v1/force-deflection", json_body(
        {"manipulator": PAPER, "dx": {"start": 0.05, "stop": dx, "num": rnd.randint(150, 450)}, "dy": 0.0})


class Stats:
    def __init__(self) -> None:
        self.latencies: list[float] = []
        self.statuses: collections.Counter[str] = collections.Counter()


async def _phase(host: str, port: int, clients: int, duration: float):
    import asyncio

    stats = Stats()
    stop = time.perf_counter() + duration
    await asyncio.gather(*[_client(host, port, i, request, stop, stats) for i in range(clients)])
    return stats


def report(stats: Stats, label: str) -> None:
    total = sum(stats.statuses.values())
    print(f"{label}: {total} answers")
    for status, count in sorted(stats.statuses.items()):
        print(f"  {status:>6} {count:>6}  {100.0 * count / total:6.2f} %")
    if stats.latencies:
        print(f"  latency p50 {statistics.median(stats.latencies) * 1000:.0f} ms, "
              f"max {max(stats.latencies) * 1000:.0f} ms")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--url", help="a running server (default: start one)")
    ap.add_argument("--clients", type=int, default=32)
    ap.add_argument("--duration", type=float, default=40.0)
    ap.add_argument("--solve-timeout", type=float, default=None,
                    help="the own server's TENSEGRITY_SOLVE_TIMEOUT (default 10 s): a shorter limit stands for a "
                         "slower machine (what matters is the queue's wait against the limit)")
    args = ap.parse_args(argv)

    def run(url: str) -> None:
        host, port = _host_port(url)
        stats = _run(_phase(host, port, args.clients, args.duration))
        limit = f", solve timeout {args.solve_timeout:g} s" if args.solve_timeout else ""
        report(stats, f"{args.clients} clients, {args.duration:g} s, light n = 4 requests{limit}")

    if args.url:
        run(args.url)
    else:
        env = {"TENSEGRITY_SOLVE_TIMEOUT": str(args.solve_timeout)} if args.solve_timeout else None
        with own_server(env=env) as url:
            run(url)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
