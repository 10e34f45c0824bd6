"""The horizon planner against step by step on a set of scenarios (issue 39, item 3), and the receding step's time.

``python -m benchmarks.plan_scenarios [--quick]`` prints one row per scenario: the summed tip error and the feasible
(and verified) steps of ``plan_preloads`` step by step, with ``horizon=5`` and with ``horizon="all"``, and whether
the horizon plans are never worse (summed error <= step by step's, feasible steps >= step by step's). The scenarios:
``[step-by-step plan]`` marks where ``plan_preloads`` returned the step-by-step plan because the horizon's own was
worse (its message says so); the summed tip error counts the steps off their targets (farther than the landing
tolerance ``LAND_TOL max b``);
chains n = 3..5 of every family (monotonic, bistable, heterogeneous, asymmetric preloads), each with moving targets,
a stationary target, an out-of-reach stretch and a payload change (a load jump), rate-limited (the horizon's reason
to exist: an actuator too slow for a step alone).
"""

from __future__ import annotations

import argparse
import json
import time

import numpy as np

import tensegrity_opt as to
from tensegrity_opt.analyses.design.preloads import LAND_TOL

FAMILIES = ("monotonic", "bistable", "heterogeneous", "asymmetric")
KINDS = ("moving", "stationary", "out_of_reach", "payload")


def _segment(rng, family: str) -> to.Segment:
    b = rng.uniform(0.8, 1.2)
    a = rng.uniform(0.45, 0.75) * b
    k = rng.uniform(0.6, 1.6)
    thresh = 2 * b * (1 - (a / b) ** 2)
    L0 = thresh - rng.uniform(0.15, 0.4) if family == "bistable" else thresh + rng.uniform(0.2, 0.8)
    if family == "asymmetric":
        d = rng.uniform(0.03, 0.12) * rng.choice([-1, 1])
        return to.Segment(a, b, (k, k * rng.uniform(0.8, 1.25)), (L0 + d, L0 - d))
    return to.Segment(a, b, k, L0)


def scenario(seed: int, family: str, kind: str, n: int, K: int = 10):
    """``(m, targets, kwargs)`` of one scenario."""
    rng = np.random.default_rng(seed)
    for _ in range(50):
        fam = [rng.choice(["monotonic", "bistable", "asymmetric"]) if family == "heterogeneous" else family
               for _ in range(n)]
        m = to.Manipulator(_segment(rng, f) for f in fam)
        loads = np.tile([0.0, -0.01], (K, 1))
        if kind == "payload":
            loads[K // 2:] = [0.0, -0.01 - rng.uniform(0.05, 0.2) * m.torque_scale / m.straight_length * 4]
        try:
            q0 = to.PreloadController(m, load=loads[0]).q
        except (to.NoEquilibriumError, to.InvalidParameterError):
            continue
        break
    tip0 = m.tip(q0)
    d = rng.normal(size=2)
    d /= np.linalg.norm(d)
    step = 0.05 * float(np.mean(m.b))
    if kind == "stationary":
        targets = np.tile(tip0 + 4 * step * d, (K, 1))
    else:
        targets = np.array([tip0 + (k + 1) * step * d for k in range(K)])
    if kind == "out_of_reach":
        targets[K // 3: K // 3 + 3] = tip0 + 20.0 * m.straight_length / n * d
    kw = dict(loads=loads, rate_limit=0.1 * float(np.mean(m.b)), dt=1.0, margin=1e-3 * m.torque_scale,
              on_infeasible="approach")
    return m, targets, kw


def run(quick: bool) -> list[dict]:
    rows = []
    ns = (3, 4) if quick else (3, 4, 5)
    seed = 0
    for n in ns:
        for family in FAMILIES:
            for kind in KINDS:
                seed += 1
                m, T, kw = scenario(seed, family, kind, n)
                row = {"n": n, "family": family, "kind": kind}
                for name, hz in (("step", None), ("h5", 5), ("all", "all")):
                    t0 = time.perf_counter()
                    p = to.plan_preloads(m, T, horizon=hz, **kw)
                    off = p.tip_error > LAND_TOL * float(np.max(m.b))      # on target: within the landing tolerance
                    row[name] = {"error": float(np.sum(p.tip_error[off])), "feasible": int(np.sum(p.feasible)),
                                 "verified": int(np.sum(p.verified)), "status": p.status,
                                 "seconds": time.perf_counter() - t0,
                                 "fallback": "step-by-step plan is returned" in p.message}
                for h in ("h5", "all"):
                    row[f"{h}_ok"] = (row[h]["error"] <= row["step"]["error"] * (1 + 1e-6) + 1e-9
                                      and row[h]["feasible"] >= row["step"]["feasible"])
                rows.append(row)
                print(json.dumps(row), flush=True)
    return rows


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args(argv)
    rows = run(args.quick)
    print("\n| n | family | scenario | step by step: error, feasible | horizon 5 | all | never worse (5, all) |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        cell = lambda d: (f"{d['error']:.4g}, {d['feasible']} ({d['seconds']:.2f} s)"    # noqa: E731
                          + (" [step-by-step plan]" if d.get("fallback") else ""))
        print(f"| {r['n']} | {r['family']} | {r['kind']} | {cell(r['step'])} | {cell(r['h5'])} | {cell(r['all'])} | "
              f"{'yes' if r['h5_ok'] else 'NO'}, {'yes' if r['all_ok'] else 'NO'} |")
    bad = [r for r in rows if not (r["h5_ok"] and r["all_ok"])]
    print(f"\n{len(rows) - len(bad)} of {len(rows)} scenarios: the horizon never worse than step by step")
    for h in ("h5", "all"):
        fb = sum(r[h]["fallback"] for r in rows)
        better = sum(r[h]["feasible"] > r["step"]["feasible"] or (r[h]["feasible"] == r["step"]["feasible"] and
                                                                  r[h]["error"] < r["step"]["error"] * (1 - 1e-6))
                     for r in rows)
        print(f"{h}: strictly better than step by step on {better}; the step-by-step plan returned (the horizon's "
              f"own plan worse) on {fb}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
