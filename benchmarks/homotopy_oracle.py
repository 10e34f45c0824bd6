"""Reference equilibria of random multistable chains by the certified homotopy, for the tests.

``python -m benchmarks.homotopy_oracle [--out tests/data/homotopy_oracle.json]`` draws random chains
of every multistable family (bistable uniform, heterogeneous bistable, monotonic and bistable
segments mixed, asymmetric preloads; ``n = 2..5``; targets over the workspace, ``dy != 0`` in most),
solves each target's polynomial KKT system with PHCpack (:mod:`tensegrity_opt.numerics.homotopy`), keeps the
real roots inside the physical range, polishes each with the *independent* reference model
(``tests/support/reference_model.py``: its own Newton, its own Hessians; it does not import the library) and
records ``q``, ``F``, the energy and the Morse index from the reference model's reduced Hessian.
Only certified solves (every path ended) whose roots all polish are written. The library's search
is then tested against this file (``tests/analyses/equilibria/test_completeness.py``). Which equilibria exist comes from
a different method than the search (the homotopy, whose polynomial system is library code: it is
checked independently by the n = 3 brute-force tests and the residual test there); every number
(``q``, ``F``, energy, Morse index) comes from the reference model.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

import tensegrity_opt as to
from tensegrity_opt.numerics.homotopy import real_configurations, solve_homotopy

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "support"))
import reference_model as ref  # noqa: E402

FAMILIES = ("bistable", "heterogeneous", "mixed", "asymmetric")


def _bistable_L0(rng, a, b):
    """A rest length with K = k (b L0 - 2 (b^2 - a^2)) < 0 (needs a < b)."""
    return rng.uniform(0.35, 0.9) * 2.0 * (b * b - a * a) / b


def random_chain(rng, n: int, family: str) -> to.Manipulator:
    segs = []
    for i in range(n):
        if family == "bistable":
            if i == 0:
                a, b, k = rng.uniform(0.4, 0.8), 1.0, rng.uniform(0.5, 2.0)
                L0 = _bistable_L0(rng, a, b)
            segs.append(to.Segment(a, b, k, L0))
            continue
        a, b = rng.uniform(0.4, 0.8), rng.uniform(0.8, 1.2)
        k = rng.uniform(0.5, 2.0)
        bist = family != "mixed" or rng.random() < 0.5
        L0 = _bistable_L0(rng, a, b) if bist else 2.0 * (b * b - a * a) / b + rng.uniform(0.2, 1.0)
        if family == "asymmetric":
            k = (k, k * rng.uniform(0.6, 1.6))
            L0 = (L0, L0 * rng.uniform(0.8, 1.2))
        segs.append(to.Segment(a, b, k, L0))
    return to.Manipulator(segs)


def cases(n: int, seed: int):
    """Endless random (family, chain, dx, dy) of ``n`` segments, families in turn."""
    rng = np.random.default_rng(seed + 1000 * n)
    made = 0
    while True:
        fam = FAMILIES[made % len(FAMILIES)]
        m = random_chain(rng, n, fam)
        if m.monotonic:
            continue
        L = m.straight_length
        dx = float(rng.uniform(0.02, 0.5) * L)
        dy = float(rng.uniform(-0.3, 0.3) * L) if made % 3 else 0.0
        try:
            m.check_reachable(dx, dy)
        except ValueError:
            continue
        made += 1
        yield fam, m, dx, dy


def reference_set(m: to.Manipulator, dx: float, dy: float, timeout: float | None = None):
    target = m.target(dx, dy)
    sol = solve_homotopy(m, target, timeout=timeout)
    q, F, inside, _ = real_configurations(m, sol)
    chain = ref.Chain(m.a, m.b, m.k1, m.k2, m.L1_0, m.L2_0)
    out = []
    ok = sol.complete
    for qi, Fi in zip(q[inside], F[inside]):
        qp, Fp, conv = chain.newton_kkt(target, qi, Fi)
        if not (conv and chain.in_range(qp) and np.max(np.abs(qp - qi)) < 1e-6):
            ok = False
            continue
        if any(np.max(np.abs(qp - np.array(e["q"]))) < 1e-7 for e in out):
            continue
        eig = chain.reduced_eigs(qp, Fp, constrained=True, fd=False)
        scale = max(1.0, float(np.abs(eig).max())) if eig.size else 1.0
        smallest = float(np.abs(eig).min() / scale) if eig.size else 1.0
        out.append({"q": qp.tolist(), "force": Fp.tolist(), "energy": float(chain.energy(qp)),
                    "morse_index": int(np.sum(eig < 0)), "min_abs_eig": smallest})
    out.sort(key=lambda e: e["energy"])
    return out, sol, ok


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=str(ROOT / "tests" / "data" / "homotopy_oracle.json"))
    ap.add_argument("--seed", type=int, default=2026)
    ap.add_argument("--counts", default="2:24,3:36,4:36,5:12", help="n:count,...")
    args = ap.parse_args(argv)
    counts = {int(k): int(v) for k, v in (p.split(":") for p in args.counts.split(","))}
    rows = []
    for n, count in counts.items():
        kept = 0
        for fam, m, dx, dy in cases(n, args.seed):
            if kept >= count:
                break
            if _one(rows, fam, m, dx, dy):
                kept += 1
                _write(args.out, args.seed, rows)           # a long run keeps what it has
    _write(args.out, args.seed, rows)
    print(f"{len(rows)} certified cases -> {args.out}")
    return 0


def _write(out, seed, rows) -> None:
    Path(out).write_text(json.dumps({"generator": "benchmarks/homotopy_oracle.py", "seed": seed,
                                    "cases": rows}, indent=1))


def _one(rows, fam, m, dx, dy) -> int:
    """Solve one case, append it to ``rows`` when certified with at least one equilibrium; 1 if kept."""
    t0 = time.perf_counter()
    eqs, sol, ok = reference_set(m, dx, dy)
    print(f"n={m.n} {fam:13s} dx={dx:.4f} dy={dy:+.4f}: {len(eqs)} equilibria "
          f"({sum(e['morse_index'] == 0 for e in eqs)} stable), {sol.paths} paths, {sol.failures} failed, "
          f"{time.perf_counter() - t0:.1f} s{'' if ok else '  NOT CERTIFIED: skipped'}", flush=True)
    if not ok or not eqs:
        return 0                    # uncertified, or a target outside the joint-range workspace
    rows.append({"family": fam, "manipulator": m.to_dict(), "dx": dx, "dy": dy, "paths": sol.paths,
                 "seconds": round(sol.seconds, 3), "equilibria": eqs})
    return 1


if __name__ == "__main__":
    raise SystemExit(main())
