"""Completeness check of the global search on random chains (not a timing): ``python -m benchmarks.search_check``.

Random monotonic chains (n 3..8, asymmetric springs: a 0.6-1.2, b 0.8-1.2, k 0.5-2, L0 0.8-2) at
random targets (dx up to 0.8 of the reach, half of them with dy): ``solve_equilibrium`` (the
Newton-seeded search, method "auto") against IPOPT from the same mode seeds plus 24 random starts.
Prints the counts and every case where "auto" returned a higher energy, with its chain, so a miss
can be reproduced. Last run (2026-11-22, 300 cases, seed 99): 206 same, 93 unsolvable by both
(targets outside the joint-range workspace), 1 higher (n = 8, a W4 minimum only IPOPT's descent
reaches; see the issue notes).
"""

from __future__ import annotations

import argparse
import collections

import numpy as np

import tensegrity_opt as to


def cases(count: int, seed: int):
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < count:
        n = int(rng.integers(3, 9))
        segs = [to.Segment(rng.uniform(0.6, 1.2), rng.uniform(0.8, 1.2), (rng.uniform(0.5, 2), rng.uniform(0.5, 2)),
                           (rng.uniform(0.8, 2.0), rng.uniform(0.8, 2.0))) for _ in range(n)]
        try:
            m = to.Manipulator(segs)
        except ValueError:
            continue
        if not m.monotonic:
            continue
        reach = m.straight_length
        dx = rng.uniform(0.01, 0.8) * reach
        dy = rng.uniform(-0.3, 0.3) * reach if len(out) % 2 else 0.0
        try:
            m.check_reachable(dx, dy)
        except ValueError:
            continue
        out.append((m, dx, dy))
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", type=int, default=300)
    ap.add_argument("--seed", type=int, default=99)
    args = ap.parse_args(argv)
    counts: collections.Counter[str] = collections.Counter()
    for m, dx, dy in cases(args.cases, args.seed):
        try:
            ref = to.solve_equilibrium(m, dx, dy, method="ipopt", n_random=24).energy
        except (ValueError, RuntimeError):
            ref = None
        try:
            got = to.solve_equilibrium(m, dx, dy).energy
        except (ValueError, RuntimeError):
            got = None
        if ref is None or got is None:
            counts["both fail" if ref is None and got is None else
                   ("auto fails" if got is None else "ipopt fails")] += 1
            continue
        tol = 1e-9 * max(1.0, abs(ref))
        if got > ref + tol:
            counts["auto higher"] += 1
            print(f"auto higher: dx={dx!r} dy={dy!r} auto {got:.10g} ipopt {ref:.10g} segments="
                  f"{[(s.a, s.b, s.k1, s.k2, s.L1_0, s.L2_0) for s in m.segments]}")
        else:
            counts["same" if got >= ref - tol else "auto lower"] += 1
    print(dict(counts))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
