"""Sweep schedulers against each other: ``python -m benchmarks.sweep_scheduler [ANALYSIS] [SIZES] [SCHEDULERS]``.

Each run is a fresh process (solvers built in it, as for ``tensegrity-opt sweep``) timing
``sweep(spec, scheduler=...)`` alone (the imports, ~1-2 s, are printed apart). The specs are the README's
(``buckling`` over ``n`` in 3, 4, 5 and ``k``; 9 points: ``k`` in 0.5, 1, 2) with more ``k`` values for
the larger sizes; ``equilibrium`` and ``equilibria_count`` at ``dx = 0.1``. One JSON line per run,
with the scheduler that ran (``auto``: ``serial`` or ``serial+local``) and the load average.
Results: benchmarks/RESULTS.md, "Sweep scheduler default".
"""

from __future__ import annotations

import json
import os
import subprocess
import sys

import numpy as np

CHILD = r'''
import json, sys, time
t0 = time.perf_counter()
from tensegrity_opt.applications.sweeps import sweep
spec = json.loads(sys.argv[1]); sched = sys.argv[2]
t1 = time.perf_counter()
r = sweep(spec, scheduler=sched)
t2 = time.perf_counter()
print(json.dumps({"ran": r.scheduler, "import": t1 - t0, "sweep": t2 - t1, "rows": len(r.rows),
                  "errors": len(r.errors)}))
'''


def spec(points: int, analysis: str = "buckling") -> dict:
    """The README's spec (9 points) or the same grid with ``points // 3`` values of ``k``."""
    k = [0.5, 1, 2] if points == 9 else [float(v) for v in np.linspace(0.5, 2, points // 3)]
    s = {"analysis": analysis, "manipulator": {"n": 4, "a": 1, "b": 1, "k": 1, "L0": 1},
         "grid": {"n": [3, 4, 5], "k": k}, "options": {"boundary": "guided"}}
    if analysis in ("equilibrium", "equilibria_count"):
        s["grid"]["dx"] = [0.1]
        s.pop("options")
    return s


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    analysis = args[0] if args else "buckling"
    sizes = [int(a) for a in args[1].split(",")] if len(args) > 1 else [9, 90, 270, 1002]
    schedulers = args[2].split(",") if len(args) > 2 else ["serial", "threads", "local", "auto"]
    for points in sizes:
        for sched in schedulers:
            r = subprocess.run([sys.executable, "-c", CHILD, json.dumps(spec(points, analysis)), sched],
                               capture_output=True, text=True)
            if r.returncode:
                print(json.dumps({"points": points, "scheduler": sched, "failed": r.stderr[-300:]}), flush=True)
                continue
            d = json.loads(r.stdout.strip().splitlines()[-1])
            d.update(points=points, scheduler=sched, analysis=analysis, load=round(os.getloadavg()[0], 2))
            print(json.dumps(d), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
