#!/usr/bin/env python3
"""Time to the first answer for a chain length whose kernels are not compiled yet (not a timed test).

Starts ``tensegrity-opt serve`` with an empty kernel cache (``TENSEGRITY_CACHE_DIR`` a new directory), waits
for ``/readyz``, then sends ``POST /v1/equilibrium`` for each ``--n`` in turn (each a chain length the server
has not solved yet) and prints the time to each answer; then the same requests again, and the kernels' state
(``/version``) after ``--settle`` seconds. With background builds the first answers do not wait for the C
compiler (CasADi's virtual machine answers them); compiling on the request's path, they wait for it.

    python benchmarks/first_answer.py                 # n = 6 and 8
    python benchmarks/first_answer.py --n 5 7
"""

from __future__ import annotations

import argparse
import tempfile
import time

import httpx

try:
    from benchmarks.http_load import own_server
except ImportError:                 # run as a script: benchmarks/ is on sys.path
    from http_load import own_server


def body(n: int) -> dict:
    return {"manipulator": {"n": n, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}, "dx": 0.3, "dy": 0.1}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, nargs="+", default=[6, 8])
    ap.add_argument("--settle", type=float, default=20.0, help="seconds before the kernels' state is read")
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory(prefix="tensegrity-kernels-") as cache:
        t0 = time.perf_counter()
        env = {"TENSEGRITY_CACHE_DIR": cache, "TENSEGRITY_SOLVE_TIMEOUT": "300"}
        with own_server(timeout=600, env=env) as url, httpx.Client(base_url=url, timeout=600) as client:
            while client.get("/readyz").status_code != 200:
                time.sleep(0.05)
            print(f"server ready after {time.perf_counter() - t0:.2f} s (empty kernel cache)")
            for rnd in ("first", "second"):
                for n in args.n:
                    t = time.perf_counter()
                    r = client.post("/v1/equilibrium", json=body(n))
                    print(f"{rnd:>6} answer, n = {n}: {r.status_code} after {time.perf_counter() - t:.3f} s")
            time.sleep(args.settle)
            print("kernels:", client.get("/version").json()["kernels"])
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
