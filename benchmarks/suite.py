"""The benchmark suite: ``python -m benchmarks [--quick] [--json PATH] [--md PATH] [--no-service]``.

Prints one table (case | n | ours (median) | baseline | baseline (median) | ratio (baseline/ours) |
target | met?) with numbered notes, and writes the same data as JSON (default
``benchmarks/results.json``) and as markdown (default ``benchmarks/RESULTS.md``), both with the
machine information. Every time is a median over repeated runs after a warm-up
(``time.perf_counter``); every baseline is measured in the same run.

Cases (each with its target):

1. n = 4 local solve warm-started from the solution 0.001 away: <= 0.2 ms and >= 20x SLSQP.
2. n = 4 global solve, not warm-started (solver built): <= 5 ms; vs the paper's energy method
   and a 14-start SLSQP; ``find_equilibria`` (every equilibrium) on the same targets: <= 36 ms (its time before
   the projected starts were added).
3. n = 4 force-deflection curve, 1000 points: <= 0.1 s and >= 30x a warm-started SLSQP loop.
4. n = 1000, first call in a fresh process (build included): <= 2 s; cached: <= 50 ms; vs SLSQP.
5. n = 10000 cached: <= 1 s; exponent of the cached time over n = 1000..10000: <= 1.2.
6. critical load n = 10000: <= 0.5 s; dense reduced ``eigh`` at n = 2000 for the ratio.
7. service ``/v1/equilibrium`` under 32 clients: throughput >= 0.5x ``/healthz``, p99 <= 25 ms, 0 errors.
8. service ``/v1/batch/equilibrium`` with 1000 targets: median latency <= 0.3 s.
9. multistable (bistable, K < 0) chains: global solve n = 4 and n = 8 (goal <= 20 ms for n = 8) vs a
   64-start SLSQP; ``find_equilibria`` n = 4 and n = 8 (goal <= 1 s for n = 8); the certified homotopy
   (PHCpack) per n with its path count, vs the search on the same target.
10. paths: a 1000-point arclength branch of the paper's chain vs natural-parameter loops of the same points
   (the Tracker, the compiled batch); ``limit_load`` per call (branch point, smooth path, fold) vs force
   steps with bisection on stability; the stability atlas per target vs a ``find_equilibria`` loop, and
   per crossing vs bisecting the stable count along the edge.
11. control in actuation space: a warm preload step of ``PreloadController`` (the end pose only, goal <= 0.2 ms for
   n = 4) vs ``preloads_for_pose`` per step and scipy SLSQP on the same problem; the same step verified along its
   transition (the default); ``plan_preloads`` per step.
12. figures: every figure route's default request on a server of default settings (``benchmarks/figures.py``):
   seconds from the client (first answer, then the median) against the time limit; target: the median at most a
   third of it. Its own table in RESULTS.md ("Figures").
13. horizon planner: one warm receding-horizon window solve (n = 4, N = 10) beside the same NLP cold and the
    step-by-step controller's verified step, and a whole receding step of plan_preloads beside step by step, on
   the same trajectory, both timed in the same run (info).
14. interval certificates: Krawczyk's test in ball arithmetic (python-flint) on every equilibrium of a set, per
   set, n = 2..5 on the PHCpack oracle's sets (``tests/data/homotopy_oracle.json``), n = 6 on the search's sets of
   bistable chains; beside the Newton polish and float classification of the same equilibria (what the homotopy
   already does per root), same run (info).
"""

from __future__ import annotations

import argparse
import datetime as _dt
import json
import math
import os
import platform
import statistics
import subprocess
import sys
import textwrap
import time
import traceback
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

import numpy as np

import tensegrity_opt as to

from . import baselines as bl
from .http_load import ServerStartError

ROOT = Path(__file__).resolve().parents[1]
HERE = Path(__file__).resolve().parent
PAPER = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}


def log(msg: str) -> None:
    print(f"[bench {time.strftime('%H:%M:%S')}] {msg}", file=sys.stderr, flush=True)


# ============================================================================ configuration
@dataclass(frozen=True)
class Config:
    quick: bool
    service: bool
    # case 1
    c1_targets: int
    c1_reps: int
    c1_slsqp_reps: int
    c1_tc_reps: int
    # case 2
    c2_targets: int
    c2_reps: int
    c2_ms_targets: int
    # case 3
    c3_reps: int
    c3_base_reps: int
    # case 4
    c4_subprocs: int
    c4_slsqp_timeout: float
    # case 5
    c5_ns: tuple[int, ...]
    c5_reps: int
    # case 6
    c6_reps: int
    c6_dense_reps: int
    # case 7/8
    c7_duration: float
    c8_reps: int

    @classmethod
    def make(cls, quick: bool, service: bool) -> "Config":
        if quick:
            return cls(quick=True, service=service, c1_targets=5, c1_reps=15, c1_slsqp_reps=3, c1_tc_reps=1,
                       c2_targets=12, c2_reps=2, c2_ms_targets=4, c3_reps=3, c3_base_reps=1,
                       c4_subprocs=1, c4_slsqp_timeout=5.0, c5_ns=(1000, 2000, 4000, 8000, 10000), c5_reps=3,
                       c6_reps=3, c6_dense_reps=1, c7_duration=3.0, c8_reps=2)
        return cls(quick=False, service=service, c1_targets=10, c1_reps=50, c1_slsqp_reps=10, c1_tc_reps=3,
                   c2_targets=40, c2_reps=3, c2_ms_targets=12, c3_reps=7, c3_base_reps=3,
                   c4_subprocs=3, c4_slsqp_timeout=60.0, c5_ns=(1000, 2000, 4000, 8000, 10000), c5_reps=5,
                   c6_reps=5, c6_dense_reps=2, c7_duration=10.0, c8_reps=4)


# ============================================================================ results
@dataclass
class Row:
    case: str
    name: str
    n: int | str
    ours: float | None                 # value in `unit`
    unit: str                          # "ms", "req/s", "", "errors"
    baseline: str = "-"
    baseline_value: float | None = None
    baseline_display: str | None = None  # overrides the formatted value (e.g. ">60 s (stopped)")
    ratio: float | None = None           # baseline / ours
    ratio_display: str | None = None
    target: str = "-"
    met: bool | None = None
    notes: list[str] = field(default_factory=list)
    samples: list[float] | None = None
    baseline_samples: list[float] | None = None
    extra: dict[str, Any] = field(default_factory=dict)

    def to_json(self) -> dict[str, Any]:
        d = {k: getattr(self, k) for k in ("case", "name", "n", "unit", "baseline", "ratio", "target", "met",
                                             "notes")}
        d["ours"] = self.ours
        d["ours_display"] = fmt(self.ours, self.unit)
        d["baseline_value"] = self.baseline_value
        d["baseline_display"] = self.baseline_cell()
        d["ratio_display"] = self.ratio_cell()
        if self.samples is not None:
            d["samples_s"] = self.samples               # raw timings in seconds
        if self.baseline_samples is not None:
            d["baseline_samples_s"] = self.baseline_samples
        if self.extra:
            d["extra"] = self.extra
        return _jsonable(d)

    def baseline_cell(self) -> str:
        if self.baseline_display is not None:
            return self.baseline_display
        return fmt(self.baseline_value, self.unit) if self.baseline_value is not None else "-"

    def ratio_cell(self) -> str:
        if self.ratio_display is not None:
            return self.ratio_display
        if self.ratio is None or not math.isfinite(self.ratio):
            return "-"
        return f"{self.ratio:.3g}x" if self.ratio < 1000 else f"{self.ratio:.0f}x"


def fmt(v: float | None, unit: str) -> str:
    if v is None:
        return "-"
    if isinstance(v, float) and not math.isfinite(v):
        return str(v)
    if unit == "ms":
        if v < 1:
            return f"{v:.3f} ms"
        if v < 100:
            return f"{v:.2f} ms"
        return f"{v:.0f} ms"
    if unit == "req/s":
        return f"{v:.0f} req/s"
    if unit == "errors":
        return f"{int(v)} errors"
    return f"{v:.3g}" + (f" {unit}" if unit else "")


def _jsonable(x: Any) -> Any:
    if isinstance(x, dict):
        return {str(k): _jsonable(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_jsonable(v) for v in x]
    if isinstance(x, (np.floating,)):
        x = float(x)
    if isinstance(x, (np.integer,)):
        return int(x)
    if isinstance(x, (np.bool_,)):
        return bool(x)
    if isinstance(x, float) and not math.isfinite(x):
        return None
    if isinstance(x, np.ndarray):
        return _jsonable(x.tolist())
    return x


def median_ms(ts: list[float]) -> float:
    return float(statistics.median(ts) * 1e3)


def repeat(fn: Callable[[], Any], reps: int, warmup: int = 1) -> list[float]:
    """``reps`` timings (seconds) of ``fn()`` after ``warmup`` untimed calls."""
    for _ in range(warmup):
        fn()
    out = []
    for _ in range(reps):
        t0 = time.perf_counter()
        fn()
        out.append(time.perf_counter() - t0)
    return out


def rel(a: float, b: float) -> float:
    return abs(a - b) / max(abs(b), 1e-300)


def random_targets(m: to.Manipulator, count: int, seed: int, dx=(0.05, 3.0), dy=(-1.0, 1.0)):
    """Deflections the library solves (targets it rejects are skipped and counted)."""
    rng = np.random.default_rng(seed)
    out, skipped = [], 0
    while len(out) < count:
        t = (float(rng.uniform(*dx)), float(rng.uniform(*dy)))
        try:
            eq = to.solve_equilibrium(m, *t)
        except to.TensegrityError:
            skipped += 1
            if skipped > 10 * count:
                raise
            continue
        out.append((t, eq))
    return out, skipped


# ============================================================================ cases
def case1(cfg: Config) -> list[Row]:
    """n = 4 local solve warm-started from the solution at a target 0.001 away."""
    m = to.Manipulator.uniform(4)
    ch = bl.Chain(m)
    bases, skipped = random_targets(m, cfg.c1_targets, seed=101)
    rng = np.random.default_rng(102)
    ours, tracked, slsqp, tc = [], [], [], []
    e_slsqp, e_tc, ours_status, not_converged = [], [], set(), 0
    tr_diff = 0.0
    for (dx, dy), prev in bases:
        ang = rng.uniform(0, 2 * np.pi)
        dx2, dy2 = dx + 1e-3 * math.cos(ang), dy + 1e-3 * math.sin(ang)
        q0 = prev.q.copy()
        eq = to.solve_equilibrium(m, dx2, dy2, q0=q0, local=True)
        ours_status.add(eq.solver.status)
        ours += repeat(lambda: to.solve_equilibrium(m, dx2, dy2, q0=q0, local=True), cfg.c1_reps)
        tracker = to.Tracker(m, prev)

        def step():
            tracker.current = prev            # every repetition is the same step from prev
            return tracker.solve(dx2, dy2)

        tr_diff = max(tr_diff, float(np.abs(step().q - eq.q).max()))
        tracked += repeat(step, cfg.c1_reps)
        r = bl.slsqp_equilibrium(ch, dx2, dy2, q0)
        not_converged += not r.success
        e_slsqp.append(rel(r.energy, eq.energy))
        slsqp += repeat(lambda: bl.slsqp_equilibrium(ch, dx2, dy2, q0), cfg.c1_slsqp_reps)
        r = bl.trust_constr_equilibrium(ch, dx2, dy2, q0)
        not_converged += not r.success
        e_tc.append(rel(r.energy, eq.energy))
        tc += repeat(lambda: bl.trust_constr_equilibrium(ch, dx2, dy2, q0), cfg.c1_tc_reps, warmup=0)
    o = median_ms(ours)
    s = median_ms(slsqp)
    t = median_ms(tc)
    name = "warm-start local solve (0.001 away)"
    common = (f"{len(bases)} targets dx in [0.05,3], dy in [-1,1]; ours = solve_equilibrium(q0=prev.q, local=True), "
              f"status {sorted(ours_status)}")
    r1 = Row("1", name, 4, o, "ms", "SLSQP from same q0 (tol 1e-10)", s, ratio=s / o,
             target="<= 0.2 ms and >= 20x", met=(o <= 0.2 and s / o >= 20), samples=ours, baseline_samples=slsqp,
             notes=[common, f"SLSQP energy vs ours: max rel diff {max(e_slsqp):.1e}"])
    r2 = Row("1", name, 4, o, "ms", "trust-constr from same q0 (exact Hessians)", t, ratio=t / o,
             target="(info)", met=None, baseline_samples=tc,
             notes=[f"trust-constr energy vs ours: max rel diff {max(e_tc):.1e}; baselines not converged: "
                    f"{not_converged}"])
    tk = median_ms(tracked)
    r3 = Row("1", "warm-start step, Tracker.solve (control-loop API)", 4, tk, "ms", "SLSQP from same q0 (tol 1e-10)", s,
             ratio=s / tk, target="<= 0.2 ms and >= 20x", met=(tk <= 0.2 and s / tk >= 20), samples=tracked,
             baseline_samples=slsqp,
             notes=[f"Tracker(m, prev).solve(dx, dy): same answer as the local solve (max |dq| {tr_diff:.1e}), "
                    f"without re-validating q0; Newton kernels: {kernel_mode(4)}"])
    return [r1, r3, r2]


def case2(cfg: Config) -> list[Row]:
    """n = 4 global solve (no q0; solver already built)."""
    m = to.Manipulator.uniform(4)
    ch = bl.Chain(m)
    targets, skipped = random_targets(m, cfg.c2_targets, seed=202)
    ours: list[float] = []
    to.solve_equilibrium(m, 0.5, 0.1)            # warm-up
    for (dx, dy), _ in targets:
        ours += repeat(lambda: to.solve_equilibrium(m, dx, dy), cfg.c2_reps, warmup=0)
    o = median_ms(ours)
    # the paper's energy method
    bl.energy_method_n4(ch, 0.5, 0.1)           # warm-up
    em_t, em_cmp = [], []
    for (dx, dy), eq in targets:
        r, dt = bl.timed(bl.energy_method_n4, ch, dx, dy)
        em_t.append(dt)
        em_cmp.append((r.energy - eq.energy) / abs(eq.energy))
    em = median_ms(em_t)
    # SLSQP multistart, 14 random starts
    ms_t, ms_cmp = [], []
    for (dx, dy), eq in targets[:cfg.c2_ms_targets]:
        r, dt = bl.timed(bl.slsqp_multistart, ch, dx, dy, 14)
        ms_t.append(dt)
        ms_cmp.append((r.energy - eq.energy) / abs(eq.energy))
    ms = median_ms(ms_t)

    def agree(c):
        c = np.asarray(c)
        same = int(np.sum(np.abs(c) <= 1e-8))
        lower = int(np.sum(c < -1e-8))
        return f"same energy (1e-8) on {same}/{c.size}, baseline lower on {lower}, max |rel diff| {np.abs(c).max():.1e}"

    name = "global solve, not warm-started"
    note0 = (f"{len(targets)} random targets dx in [0.05,3], dy in [-1,1] ({skipped} rejected by the library), "
             f"{cfg.c2_reps} runs each")
    r1 = Row("2", name, 4, o, "ms", "energy method: 101x101 grid (q1,q4) + IK + Nelder-Mead", em, ratio=em / o,
             target="<= 5 ms", met=o <= 5.0, samples=ours, baseline_samples=em_t,
             notes=[note0, "energy method vs ours: " + agree(em_cmp)],
             extra={"energy_method_rel_diff": em_cmp})
    r2 = Row("2", name, 4, o, "ms", "SLSQP multistart, 14 random starts", ms, ratio=ms / o, target="(info)",
             met=None, baseline_samples=ms_t,
             notes=[f"SLSQP multistart on the first {len(ms_t)} targets vs ours: " + agree(ms_cmp)],
             extra={"multistart_rel_diff": ms_cmp})
    # every equilibrium of the paper's chain (monotonic segments) at the same targets
    fe_targets = [t for t, _ in targets[:cfg.c2_ms_targets]]
    to.find_equilibria(m, *fe_targets[0])       # warm-up
    fe_t: list[float] = []
    counts = []
    for dx, dy in fe_targets:
        fe_t += repeat(lambda: to.find_equilibria(m, dx, dy), max(2, cfg.c2_reps // 2), warmup=0)
        counts.append(len(to.find_equilibria(m, dx, dy)))
    fe = median_ms(fe_t)
    r3 = Row("2", "find_equilibria, every equilibrium (paper chain)", 4, fe, "ms", target="<= 36 ms (before the "
             "projected starts)", met=fe <= 36.0, samples=fe_t,
             notes=[f"find_equilibria on the paper's chain at the first {len(fe_targets)} targets: "
                    f"{min(counts)}-{max(counts)} equilibria per target (monotonic segments, n <= 4: IPOPT's "
                    "descents only where Newton finds nothing)"])
    return [r1, r2, r3]


def kernel_mode(n: int) -> str:
    """How the compiled Newton kernels run here ("compiled" with the cache directory, or the VM)."""
    from tensegrity_opt.numerics import chain_solver, kernels

    mode = chain_solver(to.Manipulator.uniform(n)).kernel_mode
    if mode is None:
        return "none for this n"
    return f"{mode} (C compiler {kernels.compiler()}, cache {kernels.cache_dir()})"


def case3(cfg: Config) -> list[Row]:
    m = to.Manipulator.uniform(4)
    ch = bl.Chain(m)
    dxs = np.linspace(0, 2, 1000)
    curve = to.force_deflection(m, dxs)
    ours = repeat(lambda: to.force_deflection(m, dxs), cfg.c3_reps)
    base = repeat(lambda: bl.slsqp_force_deflection(ch, dxs), cfg.c3_base_reps, warmup=0)
    res = bl.slsqp_force_deflection(ch, dxs)
    E = np.array([r.energy for r in res])
    d = (E - curve.energy) / np.maximum(np.abs(curve.energy), 1e-300)
    o, b = median_ms(ours), median_ms(base)
    note = (f"SLSQP curve vs ours: energies equal (1e-8) at {int(np.sum(np.abs(d) <= 1e-8))}/1000 points, "
            f"SLSQP lower at {int(np.sum(d < -1e-8))}, max |rel diff| {np.abs(d).max():.1e}; "
            f"{sum(not r.success for r in res)} SLSQP points not converged; ours: {len(curve.jumps)} jumps")
    return [Row("3", "force-deflection curve, 1000 points", 4, o, "ms", "SLSQP loop, warm-started from previous",
                b, ratio=b / o, target="<= 100 ms and >= 30x", met=(o <= 100 and b / o >= 30), samples=ours,
                baseline_samples=base, notes=[note])]


_FIRST_CALL = textwrap.dedent("""
    import json, sys, time
    import tensegrity_opt as to
    n, dx = int(sys.argv[1]), float(sys.argv[2])
    t0 = time.perf_counter()
    eq = to.solve_equilibrium(to.Manipulator.uniform(n), dx)
    t1 = time.perf_counter()
    eq2 = to.solve_equilibrium(to.Manipulator.uniform(n), dx * 1.001)
    t2 = time.perf_counter()
    print(json.dumps({"first_s": t1 - t0, "second_s": t2 - t1, "energy": eq.energy, "status": eq.solver.status}))
""")

_SLSQP_CHILD = textwrap.dedent("""
    import json, sys, time
    sys.path.insert(0, sys.argv[3])
    import tensegrity_opt as to
    from benchmarks import baselines as bl
    n, dx = int(sys.argv[1]), float(sys.argv[2])
    ch = bl.Chain(to.Manipulator.uniform(n))
    q0 = bl.mode_start(ch, dx)                  # the start is built first (not timed)
    print("ready", flush=True)
    t0 = time.perf_counter()
    r = bl.slsqp_equilibrium(ch, dx, 0.0, q0, maxiter=2000)
    t1 = time.perf_counter()
    print(json.dumps({"time_s": t1 - t0, "energy": r.energy, "success": r.success, "nit": r.nit,
                      "message": r.message, "tip_error": r.tip_error}), flush=True)
""")


_SWEEP_CHILD = textwrap.dedent("""
    import json, statistics, sys, time
    import numpy as np
    import tensegrity_opt as to
    ns, reps = [int(x) for x in sys.argv[1].split(",")], int(sys.argv[2])
    out = {}
    for n in ns:
        m = to.Manipulator.uniform(n)
        L = m.straight_length
        to.solve_equilibrium(m, 0.05 * L)
        ts = []
        for i in range(reps):
            t0 = time.perf_counter()
            to.solve_equilibrium(m, 0.05 * L * (1 + 1e-3 * (i + 1)))
            ts.append(time.perf_counter() - t0)
        out[n] = statistics.median(ts) * 1e3
    print(json.dumps(out))
""")


def _slsqp_subprocess(n: int, dx: float, timeout: float) -> dict[str, Any]:
    proc = subprocess.Popen([sys.executable, "-c", _SLSQP_CHILD, str(n), repr(dx), str(ROOT)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=str(ROOT))
    try:
        line = proc.stdout.readline()           # the start is built (not timed)
        if line.strip() != "ready":
            proc.wait(30)
            return {"error": f"child failed: {proc.stderr.read()[-800:]}"}
        t0 = time.perf_counter()
        try:
            out, err = proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.communicate()
            return {"stopped": True, "timeout_s": timeout, "elapsed_s": time.perf_counter() - t0}
        if proc.returncode != 0:
            return {"error": f"child exited {proc.returncode}: {err[-800:]}"}
        return json.loads(out.strip().splitlines()[-1])
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()


def case4_5(cfg: Config) -> list[Row]:
    """n = 1000 first call (fresh process) and cached; n = 10000 cached; scaling exponent."""
    rows: list[Row] = []
    n4 = 1000
    L = 2.0 * n4
    dx = 0.05 * L
    firsts, seconds, energies = [], [], []
    for _ in range(cfg.c4_subprocs):
        out = subprocess.run([sys.executable, "-c", _FIRST_CALL, str(n4), repr(dx)], capture_output=True, text=True,
                             cwd=str(ROOT), timeout=300)
        if out.returncode != 0:
            raise RuntimeError(f"first-call subprocess failed: {out.stderr[-800:]}")
        d = json.loads(out.stdout.strip().splitlines()[-1])
        firsts.append(d["first_s"])
        seconds.append(d["second_s"])
        energies.append(d["energy"])
    first = median_ms(firsts)
    # scaling sweep (main process): first call builds, then cached calls with slightly different dx
    sweep: dict[int, dict[str, Any]] = {}
    for n in cfg.c5_ns:
        m = to.Manipulator.uniform(n)
        Ln = m.straight_length
        t0 = time.perf_counter()
        eq = to.solve_equilibrium(m, 0.05 * Ln)
        build = time.perf_counter() - t0
        ts, cpu, its = [], [], []
        for i in range(cfg.c5_reps):
            c0 = time.process_time()
            t0 = time.perf_counter()
            e = to.solve_equilibrium(m, 0.05 * Ln * (1 + 1e-3 * (i + 1)))
            ts.append(time.perf_counter() - t0)
            cpu.append(time.process_time() - c0)
            its.append(e.solver.iterations)
        sweep[n] = {"first_in_process_s": build, "cached_s": ts, "cached_median_ms": median_ms(ts),
                    "cached_cpu_s": cpu, "cached_cpu_median_ms": median_ms(cpu), "final_newton_iterations": its,
                    "energy": eq.energy, "status": eq.solver.status}
        log(f"  n={n}: cached median {median_ms(ts):.1f} ms (cpu {median_ms(cpu):.1f} ms)")
    ns = np.array(cfg.c5_ns, float)
    tm = np.array([sweep[n]["cached_median_ms"] for n in cfg.c5_ns])
    slope = float(np.polyfit(np.log(ns), np.log(tm), 1)[0])
    local = [float(np.log(tm[i + 1] / tm[i]) / np.log(ns[i + 1] / ns[i])) for i in range(len(ns) - 1)]
    tc = np.array([sweep[n]["cached_cpu_median_ms"] for n in cfg.c5_ns])
    slope_cpu = float(np.polyfit(np.log(ns), np.log(tc), 1)[0])
    # SLSQP at n = 1000 from the mode-shaped start (subprocess with a time limit)
    log(f"  SLSQP n={n4} (limit {cfg.c4_slsqp_timeout:g} s)")
    sl = _slsqp_subprocess(n4, dx, cfg.c4_slsqp_timeout)
    e_ours = sweep[n4]["energy"] if n4 in sweep else energies[0]
    if "time_s" in sl:
        b_ms = sl["time_s"] * 1e3
        b_disp = None
        b_note = (f"SLSQP n=1000 from the first-mode start: {sl['nit']} iterations, success {sl['success']}, "
                  f"energy rel diff vs ours {rel(sl['energy'], e_ours):.1e}")
    elif sl.get("stopped"):
        b_ms = None
        b_disp = f">{cfg.c4_slsqp_timeout:g} s (stopped)"
        b_note = f"SLSQP n=1000 stopped after {cfg.c4_slsqp_timeout:g} s"
    else:
        b_ms = None
        b_disp = "failed"
        b_note = "SLSQP n=1000: " + sl.get("error", "?")

    def ratio_of(o_ms):
        if b_ms is not None:
            return b_ms / o_ms, None
        if sl.get("stopped"):
            return None, f">{cfg.c4_slsqp_timeout * 1e3 / o_ms:.0f}x"
        return None, "-"

    r, rd = ratio_of(first)
    rows.append(Row("4", "first call, fresh process (build incl.)", n4, first, "ms", "SLSQP n=1000, mode start",
                    b_ms, baseline_display=b_disp, ratio=r, ratio_display=rd, target="<= 2 s", met=first <= 2000,
                    samples=firsts,
                    notes=[f"dx = 0.05 * straight length = {dx:g}; {len(firsts)} fresh processes, timed from after "
                           f"the imports (Manipulator + solve); second call there: "
                           f"{median_ms(seconds):.1f} ms", b_note],
                    extra={"slsqp": sl}))
    cached = sweep[n4]["cached_median_ms"]
    r, rd = ratio_of(cached)
    rows.append(Row("4", "cached (2nd+ call, other dx)", n4, cached, "ms", "SLSQP n=1000, mode start", b_ms,
                    baseline_display=b_disp, ratio=r, ratio_display=rd, target="<= 50 ms", met=cached <= 50,
                    samples=sweep[n4]["cached_s"]))
    c10 = sweep[10000]["cached_median_ms"] if 10000 in sweep else float("nan")
    rows.append(Row("5", "cached, dx = 0.05 L", 10000, c10, "ms", target="<= 1 s", met=c10 <= 1000,
                    samples=sweep.get(10000, {}).get("cached_s"),
                    notes=["cached medians (ms): " + ", ".join(f"n={n}: {sweep[n]['cached_median_ms']:.1f}"
                                                               for n in cfg.c5_ns)]))
    # the same sweep with single-threaded BLAS (diagnostic: OpenBLAS threads vectors longer than 10000)
    env = {**os.environ, "OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"}
    out = subprocess.run([sys.executable, "-c", _SWEEP_CHILD, ",".join(map(str, cfg.c5_ns)), str(cfg.c5_reps)],
                         capture_output=True, text=True, cwd=str(ROOT), timeout=300, env=env)
    blas1 = {int(k): v for k, v in json.loads(out.stdout.strip().splitlines()[-1]).items()} \
        if out.returncode == 0 else {}
    rows.append(Row("5", "exponent of cached time vs n", "1e3..1e4", slope, "", target="<= 1.2", met=slope <= 1.2,
                    notes=["local exponents between consecutive n: " + ", ".join(f"{x:.2f}" for x in local)
                           + f"; exponent of the process CPU time instead of wall time: {slope_cpu:.2f}; "
                           "Newton iterations of the returned solve at n=10000 per run: "
                           + str(sweep.get(10000, {}).get("final_newton_iterations"))],
                    extra={"sweep": sweep, "local_exponents": local, "exponent_cpu_time": slope_cpu}))
    if blas1 and 10000 in blas1:
        t1 = np.array([blas1[n] for n in cfg.c5_ns])
        slope1 = float(np.polyfit(np.log(ns), np.log(t1), 1)[0])
        rows.append(Row("5", "cached, OPENBLAS_NUM_THREADS=1 (diagnostic)", 10000, blas1[10000], "ms",
                        target="(info)", met=None,
                        notes=["fresh process with single-threaded BLAS, same sweep: " + ", ".join(
                            f"n={n}: {blas1[n]:.1f} ms" for n in cfg.c5_ns) + f"; exponent {slope1:.2f}"],
                        extra={"sweep_ms": blas1, "exponent": slope1}))
    return rows


def case6(cfg: Config) -> list[Row]:
    m = to.Manipulator.uniform(10000)
    bk = to.critical_force(m)
    ours = repeat(lambda: to.critical_force(m), cfg.c6_reps)
    o = median_ms(ours)
    m2 = to.Manipulator.uniform(2000)
    bk2 = to.critical_force(m2)
    ours2 = repeat(lambda: to.critical_force(m2), cfg.c6_reps)
    o2 = median_ms(ours2)
    nm = len(bk2.loads)
    bl.dense_critical_loads(to.Manipulator.uniform(200), n_modes=nm)      # warm-up of LAPACK
    w, _ = bl.dense_critical_loads(m2, n_modes=nm)
    dense = repeat(lambda: bl.dense_critical_loads(m2, n_modes=nm), cfg.c6_dense_reps, warmup=0)
    d = median_ms(dense)
    return [
        Row("6", "critical load (guided)", 10000, o, "ms", target="<= 0.5 s", met=o <= 500, samples=ours,
            notes=[f"critical force n=10000: {bk.force:.6e} ({len(bk.loads)} loads)"]),
        Row("6", "critical load (guided) - baseline row is n=2000", 2000, o2, "ms",
            "dense reduced eigh (null_space + eigh subset), n=2000", d, ratio=d / o2, target="(info)", met=None,
            samples=ours2, baseline_samples=dense,
            notes=[f"n=2000, {nm} lowest loads; dense vs ours lowest load rel diff "
                   f"{rel(float(w[0]), float(bk2.loads[0])):.1e}"]),
    ]


def case7_8(cfg: Config) -> list[Row]:
    from . import http_load as hl

    rows: list[Row] = []
    with hl.own_server() as url:
        log(f"  server at {url}")
        bodies = [hl.json_body({"manipulator": PAPER, "dx": 0.1 + 1e-4 * j, "dy": 0.0}) for j in range(1000)]
        rounds = 2 if cfg.quick else 4
        phases = hl.alternating_phases(url, {
            "healthz": lambda i, k: ("GET", "/healthz", None),
            "equilibrium": lambda i, k: ("POST", "/v1/equilibrium", bodies[(i * 31 + k) % 1000])},
            32, cfg.c7_duration, rounds)
        H, E = phases["healthz"].summary(), phases["equilibrium"].summary()
        ratio = H["throughput_rps"] / E["throughput_rps"] if E["throughput_rps"] else float("inf")
        rel_tp = E["throughput_rps"] / H["throughput_rps"] if H["throughput_rps"] else float("nan")
        common = (f"32 keep-alive clients on loopback, {cfg.c7_duration:g} s per kind in {rounds} alternating phases; "
                  f"/v1/equilibrium n=4, "
                  f"dx in [0.1, 0.2); /v1/equilibrium p50 {E['p50_ms']:.1f} ms, p99 {E['p99_ms']:.1f} ms, "
                  f"{E['requests']} requests; /healthz p50 {H['p50_ms']:.2f} ms, {H['requests']} requests")
        rows.append(Row("7", "service /v1/equilibrium throughput", 4, E["throughput_rps"], "req/s",
                        "GET /healthz (same client, same run)", H["throughput_rps"], ratio=ratio,
                        target=">= 0.5x healthz (ratio <= 2)", met=rel_tp >= 0.5,
                        notes=[common, f"/v1/equilibrium = {rel_tp:.3f}x /healthz"],
                        extra={"equilibrium": E, "healthz": H}))
        rows.append(Row("7", "service /v1/equilibrium p99 latency", 4, E["p99_ms"], "ms", "GET /healthz p99",
                        H["p99_ms"], ratio=H["p99_ms"] / E["p99_ms"], target="<= 25 ms", met=E["p99_ms"] <= 25))
        rows.append(Row("7", "service /v1/equilibrium errors", 4, float(E["errors"]), "errors", "GET /healthz errors",
                        float(H["errors"]), target="0", met=E["errors"] == 0,
                        notes=[f"statuses: /v1/equilibrium {E['statuses']}, /healthz {H['statuses']}"]))
        # the control-loop request: local solve from the previous answer (information, not a target)
        q0 = to.solve_equilibrium(to.Manipulator.uniform(4), 0.1).q.tolist()
        local = [hl.json_body({"manipulator": PAPER, "dx": 0.1 + 1e-5 * j, "dy": 0.0, "q0": q0, "local": True})
                 for j in range(1000)]
        L = hl.load_phase(url, lambda i, k: ("POST", "/v1/equilibrium", local[(i * 31 + k) % 1000]), 32,
                          cfg.c7_duration).summary()
        rows.append(Row("7", "service /v1/equilibrium local=true (control step)", 4, L["throughput_rps"], "req/s",
                        "GET /healthz (same client, same run)", H["throughput_rps"],
                        ratio=H["throughput_rps"] / L["throughput_rps"] if L["throughput_rps"] else float("inf"),
                        target="(info)", met=None,
                        notes=[f"local=true with q0 = the solution at dx = 0.1, targets dx in [0.1, 0.11): p50 "
                               f"{L['p50_ms']:.1f} ms, p99 {L['p99_ms']:.1f} ms, {L['requests']} requests, "
                               f"statuses {L['statuses']}"], extra={"local": L}))
        # case 8: a 1000-target trajectory in one request
        s = np.linspace(0.0, 1.0, 1000)
        traj = np.column_stack([0.05 + 1.5 * s, 0.3 * np.sin(2 * np.pi * s)])
        body = {"manipulator": PAPER, "targets": [{"dx": float(a), "dy": float(b)} for a, b in traj],
                "continuation": True}
        import httpx

        lat: list[float] = []
        info: dict[str, Any] = {}
        with httpx.Client(base_url=url, timeout=300) as client:
            for i in range(cfg.c8_reps + (0 if cfg.quick else 1)):
                t0 = time.perf_counter()
                resp = client.post("/v1/batch/equilibrium", json=body)
                dt = time.perf_counter() - t0
                if resp.status_code != 200:
                    raise RuntimeError(f"/v1/batch/equilibrium answered {resp.status_code}: {resp.text[:300]}")
                if i > 0 or cfg.quick:
                    lat.append(dt)
                j = resp.json()
                info = {"succeeded": j.get("succeeded"), "failed": j.get("failed")}
        m = to.Manipulator.uniform(4)
        lib = repeat(lambda: to.solve_equilibria_batch(m, traj), 5)
        o = median_ms(lat)
        lb = median_ms(lib)
        rows.append(Row("8", "service /v1/batch/equilibrium, 1000 targets", 4, o, "ms",
                        "library solve_equilibria_batch in-process", lb, ratio=lb / o, target="<= 0.3 s",
                        met=o <= 300, samples=lat, baseline_samples=lib,
                        notes=[f"trajectory dx 0.05..1.55, dy = 0.3 sin(2 pi s), continuation; response: "
                               f"{info.get('succeeded')} succeeded, {info.get('failed')} failed; request "
                               f"{o / lb:.0f}x the library's own batch call"], extra=info))
    return rows


# ============================================================================ machine, output
def machine_info() -> dict[str, Any]:
    import casadi
    import scipy

    cpu = "?"
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as fh:
            for line in fh:
                if line.lower().startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    info = {
        "platform": platform.platform(), "python": platform.python_version(),
        "numpy": np.__version__, "scipy": scipy.__version__, "casadi": casadi.__version__,
        "tensegrity_opt": to.__version__, "cpu": cpu, "nproc": os.cpu_count(),
        "nproc_available": len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count(),
        "date": _dt.datetime.now(_dt.timezone.utc).astimezone().isoformat(timespec="seconds"),
        "loadavg_start": list(os.getloadavg()) if hasattr(os, "getloadavg") else None,
    }
    for mod in ("fastapi", "uvicorn", "httpx"):
        try:
            info[mod] = __import__(mod).__version__
        except Exception:  # noqa: BLE001
            info[mod] = None
    return info


HEAD = ["case", "n", "ours (median)", "baseline", "baseline (median)", "ratio (baseline/ours)", "target", "met?"]


def _cells(r: Row) -> list[str]:
    met = "-" if r.met is None else ("yes" if r.met else "NO")
    return [f"{r.case} {r.name}", str(r.n), fmt(r.ours, r.unit), r.baseline, r.baseline_cell(), r.ratio_cell(),
            r.target, met]


def table_text(rows: list[Row]) -> str:
    cells = [HEAD] + [_cells(r) for r in rows]
    w = [max(len(c[i]) for c in cells) for i in range(len(HEAD))]
    line = lambda c: " | ".join(x.ljust(w[i]) for i, x in enumerate(c))  # noqa: E731
    sep = "-+-".join("-" * x for x in w)
    return "\n".join([line(HEAD), sep] + [line(c) for c in cells[1:]])


def notes_text(rows: list[Row]) -> list[str]:
    out = []
    for r in rows:
        for nt in r.notes:
            out.append(f"[{r.case}] {nt}")
    return out


def markdown(rows: list[Row], machine: dict[str, Any], cfg: Config, total: float, skipped: list[str]) -> str:
    esc = lambda s: s.replace("|", "\\|")  # noqa: E731
    lines = ["# Benchmark results", "",
             f"`python -m benchmarks{' --quick' if cfg.quick else ''}{'' if cfg.service else ' --no-service'}` "
             f"on {machine['date']} ({total:.0f} s). Times are medians over repeated runs after a warm-up "
             "(`time.perf_counter`); every baseline was measured in the same run. ratio = baseline / ours.",
             "", f"Load average at start / end: {machine.get('loadavg_start')} / {machine.get('loadavg_end')} "
             f"(this machine has {machine.get('nproc')} cores: a load near {machine.get('nproc')} means other "
             "processes competed for the CPU during the run).", "",
             "| " + " | ".join(HEAD) + " |", "|" + "---|" * len(HEAD)]
    for r in rows:
        lines.append("| " + " | ".join(esc(c) for c in _cells(r)) + " |")
    figs = [r.extra["figure"] for r in rows if "figure" in r.extra]
    if figs:
        from .figures import table as figure_table

        lines += ["", "## Figures", "", "Every figure route's default request (its first OpenAPI example) on a server "
                  "of default settings, seconds from the client: the server's first answer, then the median.", ""]
        lines += figure_table(figs)
    lines += ["", "## Notes", ""]
    lines += [f"* {esc(n)}" for n in notes_text(rows)]
    lines += [f"* {s}" for s in skipped]
    lines += ["", "## Machine", ""]
    lines += [f"* {k}: {v}" for k, v in machine.items()]
    lines.append("")
    return "\n".join(lines)


#: The multistable chains of case 9: bistable segments (K = 1.2 - 2 (1 - 0.36) = -0.08 < 0).
BISTABLE = {"a": 0.6, "b": 1.0, "k": 1.0, "L0": 1.2}


def case9(cfg: Config) -> list[Row]:
    """Multistable chains: global solve, every equilibrium, and the certified homotopy."""
    from tensegrity_opt.numerics.homotopy import homotopy_available

    rows: list[Row] = []
    reps = 3 if cfg.quick else 7
    for n, targets in ((4, [(1.0, 0.3), (2.0, 0.0), (0.5, -0.4)]), (8, [(2.0, 0.0), (3.0, 1.0), (1.0, -0.5)])):
        m = to.Manipulator.uniform(n, **BISTABLE)
        to.solve_equilibrium(m, *targets[0])                # warm-up (kernels built)
        ours, base, agree, per = [], [], [], []
        for dx, dy in targets:
            t = repeat(lambda: to.solve_equilibrium(m, dx, dy), reps, warmup=0)
            ours += t
            per.append(f"({dx:g}, {dy:g}) {median_ms(t):.1f} ms {to.solve_equilibrium(m, dx, dy).status}")
            r, dt = bl.timed(bl.slsqp_multistart, bl.Chain(m), dx, dy, 64)
            base.append(dt)
            agree.append((r.energy - to.solve_equilibrium(m, dx, dy).energy) / abs(r.energy))
        o, b = median_ms(ours), median_ms(base)
        c = np.asarray(agree)
        rows.append(Row("9", "bistable global solve", n, o, "ms", "SLSQP multistart, 64 random starts", b,
                        ratio=b / o, target="<= 20 ms (goal)" if n == 8 else "(info)",
                        met=(o <= 20.0) if n == 8 else None, samples=ours, baseline_samples=base,
                        notes=[f"bistable n={n} ({BISTABLE}), targets {targets}: SLSQP energy vs ours: same (1e-8) on "
                               f"{int(np.sum(np.abs(c) <= 1e-8))}/{c.size}, SLSQP higher on {int(np.sum(c > 1e-8))}, "
                               f"lower on {int(np.sum(c < -1e-8))}",
                               "per target (median, status: certified = the short way's bound proved it, converged = "
                               "the whole search): " + "; ".join(per)]))
        fe = repeat(lambda: to.find_equilibria(m, *targets[0]), max(2, reps // 2), warmup=1)
        count = len(to.find_equilibria(m, *targets[0]))
        rows.append(Row("9", "bistable find_equilibria", n, median_ms(fe), "ms", target="<= 1 s (goal)" if n == 8
                        else "(info)", met=(median_ms(fe) <= 1000.0) if n == 8 else None, samples=fe,
                        notes=[f"find_equilibria n={n} at (dx, dy) = {targets[0]}: {count} equilibria"]))
    rows += _certified_least_rows(cfg)
    if not homotopy_available():
        rows.append(Row("9", "homotopy (PHCpack)", "-", None, "ms", notes=["phc not installed: homotopy rows skipped"]))
        return rows
    for n in ((2, 3, 4) if cfg.quick else (2, 3, 4, 5)):
        m = to.Manipulator([to.Segment(0.6, 1.0, 1.0, 1.2), to.Segment(0.55, 1.1, (1.2, 0.9), (1.0, 1.3)),
                            to.Segment(0.7, 0.9, 1.5, 0.6), to.Segment(0.5, 1.0, 0.8, 1.1),
                            to.Segment(0.65, 1.05, 1.0, 1.0)][:n])
        dx, dy = 0.25 * m.straight_length, 0.1 * m.straight_length
        t0 = time.perf_counter()
        h = to.find_equilibria(m, dx, dy, method="homotopy")
        th = (time.perf_counter() - t0) * 1e3
        ts = repeat(lambda: to.find_equilibria(m, dx, dy), 3, warmup=1)
        s = to.find_equilibria(m, dx, dy)
        same = len(s) == len(h) and all(min(np.max(np.abs(e.q - f.q)) for f in s) < 1e-6 for e in h)
        verdict = "the same set" if same else "DIFFERENT"
        rows.append(Row("9", "homotopy find_equilibria (certified)", n, th, "ms",
                        "search find_equilibria (same target)", median_ms(ts), ratio=median_ms(ts) / th,
                        target="n <= 4 required; <= 60 s (goal n <= 6)", met=h.certified and th <= 60000.0,
                        samples=[th / 1e3], baseline_samples=ts,
                        notes=[f"homotopy n={n}: {h.paths} paths, {h.failed_paths} failed, certified {h.certified}, "
                               f"{len(h)} equilibria; the search finds {len(s)} ({verdict})"]))
    rows += _parameter_homotopy_rows(cfg)
    return rows


#: Goals of the parameter homotopy (issue 29), seconds on 2 cores.
PARAMETER_GOALS = {4: 0.5, 5: 5.0, 6: 60.0}


def _parameter_homotopy_rows(cfg: Config) -> list[Row]:
    """The parameter homotopy (the batched tracker from the cached start roots, the default engine of
    method="homotopy") against the polyhedral solve (``phc -b``, ``TENSEGRITY_HOMOTOPY_ENGINE=polyhedral``), same
    chain and target, n = 2..6 (--quick: 2..4; the polyhedral n = 6, ~12-20 min, only in the full run); the notes
    add the parameter homotopy with ``phc -p`` for every path (``TENSEGRITY_HOMOTOPY_TRACKER=phc``)."""
    import os

    from tensegrity_opt.numerics import parameter_homotopy as ph

    rows: list[Row] = []
    segs = [to.Segment(0.6, 1.0, 1.0, 1.2), to.Segment(0.55, 1.1, (1.2, 0.9), (1.0, 1.3)),
            to.Segment(0.7, 0.9, 1.5, 0.6), to.Segment(0.5, 1.0, 0.8, 1.1), to.Segment(0.65, 1.05, 1.0, 1.0),
            to.Segment(0.45, 0.95, (0.9, 1.1), 0.9)]
    for n in ((2, 3, 4) if cfg.quick else (2, 3, 4, 5, 6)):
        m = to.Manipulator(segs[:n])
        dx, dy = 0.3 * m.straight_length, -0.1 * m.straight_length
        if ph.load_start("displacement", n) is None:
            log(f"  parameter homotopy n={n}: computing the start solutions first (once per machine)")
            ph.compute_start("displacement", n)
        par = []
        for _ in range(1 if n >= 6 else 3):
            t0 = time.perf_counter()
            h = to.find_equilibria(m, dx, dy, method="homotopy")
            par.append(time.perf_counter() - t0)
        os.environ["TENSEGRITY_HOMOTOPY_TRACKER"] = "phc"
        try:
            t0 = time.perf_counter()
            phcp = to.find_equilibria(m, dx, dy, method="homotopy")
            tq = time.perf_counter() - t0
        finally:
            del os.environ["TENSEGRITY_HOMOTOPY_TRACKER"]
        os.environ["TENSEGRITY_HOMOTOPY_ENGINE"] = "polyhedral"
        try:
            t0 = time.perf_counter()
            poly = to.find_equilibria(m, dx, dy, method="homotopy")
            tp = time.perf_counter() - t0
        finally:
            del os.environ["TENSEGRITY_HOMOTOPY_ENGINE"]

        def agree(a, b) -> bool:
            return len(a) == len(b) and all(min(np.max(np.abs(e.q - f.q)) for f in b) < 1e-6 for e in a)

        same = agree(h, poly) and agree(h, phcp)
        o = float(np.median(par)) * 1e3
        goal = PARAMETER_GOALS.get(n)
        rows.append(Row("9", "parameter homotopy find_equilibria (certified)", n, o, "ms",
                        "polyhedral homotopy (phc -b, same target)", tp * 1e3, ratio=tp * 1e3 / o,
                        target=f"<= {goal:g} s (goal)" if goal else "(info)",
                        met=(h.certified and same and o <= goal * 1e3) if goal else None,
                        samples=par, baseline_samples=[tp],
                        notes=[f"parameter homotopy n={n}: {h.paths} paths ({h.failed_paths} failed), certified "
                               f"{h.certified}, {len(h)} equilibria; with phc -p for every path {tq:.2f} s "
                               f"(certified {phcp.certified}); polyhedral: {poly.paths} paths, certified "
                               f"{poly.certified}; {'the same set' if same else 'DIFFERENT sets'}; {h.message}"]))
    return rows


#: The certified least-energy rows of case 9: bistable chains and targets near their wells (the least energy
#: within ~1e-4 of n x 0.63 among 2^n near-degenerate well patterns).
CERTIFIED_TARGETS = ((8, (2.0, 0.0)), (12, (3.5, 0.3)), (20, (4.84, 0.3)))


def _certified_least_rows(cfg: Config) -> list[Row]:
    """``solve_equilibrium(certify=True)`` (the search plus the rigorous lower bound) beside the default search."""
    rows: list[Row] = []
    reps = 1 if cfg.quick else 3
    for n, (dx, dy) in CERTIFIED_TARGETS:
        m = to.Manipulator.uniform(n, **BISTABLE)
        to.solve_equilibrium(m, dx, dy)                     # warm-up (kernels built)
        td = repeat(lambda: to.solve_equilibrium(m, dx, dy), reps, warmup=0)
        got: list = []
        full = repeat(lambda: got.append(to.solve_equilibrium(m, dx, dy, certify=True)), reps, warmup=0)
        e = got[-1]
        c = e.certificate
        o, b = median_ms(full), median_ms(td)
        rows.append(Row("9", "certified least energy (search + lower bound)", n, o, "ms",
                        "default search (no certificate)", b, ratio=b / o,
                        target="certified in seconds (goal n <= 20)", met=bool(c.certified and o < 10000.0),
                        samples=full, baseline_samples=td,
                        notes=[f"bistable n={n} at (dx, dy) = ({dx}, {dy}): energy {e.energy:.10g}, bound "
                               f"{c.bound:.10g}, gap {c.gap:.3g} (tolerance {c.tolerance:.3g}), status {e.status}; "
                               f"{c.patterns} pattern boxes, {c.boxes} boxes, {c.newton} Newton re-centrings; "
                               f"the bound alone {1e3 * float(np.median([g.certificate.seconds for g in got])):.0f} "
                               f"ms; the default's energy {to.solve_equilibrium(m, dx, dy).energy:.10g}"]))
    return rows


def _natural_limit_load(m, direction, t_step: float, tol: float = 1e-8):
    """What a user would write without continuation: dead-load steps from the rest configuration
    (``solve_equilibrium_under_force`` warm-started), then bisection on stability; a fold or branch
    point is met as the first unstable (or failed) step."""
    d = np.asarray(direction, float) / np.linalg.norm(direction)
    q, t, lo, hi = to.rest_configuration(m).q, 0.0, 0.0, None
    while t < 50.0:
        t += t_step
        try:
            eq = to.solve_equilibrium_under_force(m, *(t * d), q0=q)
        except to.TensegrityError:
            eq = None
        if eq is None or not eq.stable or np.abs(eq.q - q).max() > 0.5:
            hi = t
            break
        lo, q = t, eq.q
    if hi is None:
        return None
    qlo = q
    while hi - lo > tol:
        mid = 0.5 * (lo + hi)
        try:
            eq = to.solve_equilibrium_under_force(m, *(mid * d), q0=qlo)
            ok = eq.stable and np.abs(eq.q - qlo).max() < 0.5
        except to.TensegrityError:
            ok = False
        if ok:
            lo, qlo = mid, eq.q
        else:
            hi = mid
    return 0.5 * (lo + hi)


def case10(cfg: Config) -> list[Row]:
    """Paths: a 1000-point arclength branch vs natural-parameter loops of the same points; limit loads."""
    rows: list[Row] = []
    reps = 3 if cfg.quick else 7
    m = to.Manipulator.uniform(4, **{k: v for k, v in PAPER.items() if k != "n"})
    start = to.solve_equilibrium(m, 0.01)
    branch = lambda: to.trace_branch(m, start, "displacement", direction=(1.0, 0.0), max_points=1000,  # noqa: E731
                                     step=0.002, max_step=0.002, t_max=2.9)
    br = branch()
    ours = repeat(branch, reps)
    targets = br.deflection
    tr = to.Tracker(m, start, jump=False)

    def tracker_loop():
        tr.reset(start)
        return [tr.solve(dx, dy) for dx, dy in targets]

    track = repeat(tracker_loop, reps)
    batch = repeat(lambda: to.solve_equilibria_batch(m, targets, q0=start.q), reps)
    same = max(float(np.abs(e.q - q).max()) for e, q in zip(tracker_loop(), br.q))
    note = (f"paper chain n=4, U branch from dx=0.01: {len(br)} points to dx={targets[-1, 0]:.3f} (status {br.status}, "
            f"{len(br.events)} events); the natural-parameter loops solve the same {len(targets)} targets, largest "
            f"|q| difference {same:.1e} rad")
    o = median_ms(ours)
    rows.append(Row("10", "arclength branch, 1000 points", 4, o, "ms", "Tracker loop, same points", median_ms(track),
                    ratio=median_ms(track) / o, target="(info)", samples=ours, baseline_samples=track, notes=[note]))
    rows.append(Row("10", "arclength branch, 1000 points", 4, o, "ms", "solve_equilibria_batch (compiled kernel)",
                    median_ms(batch), ratio=median_ms(batch) / o, target="(info)", samples=ours,
                    baseline_samples=batch, notes=["the compiled natural-parameter kernel: no events, no folds"]))
    cases = (("straight, guided (branch point)", m, (-1.0, 0.0), "guided", 0.02),
             ("pre-bent, free (smooth)", to.Manipulator([to.Segment(1, 1, 1, (1.02, 0.98))] * 4), (-1.0, 0.0), "free",
              0.01),
             ("bistable, free (fold)", to.Manipulator.uniform(3, **BISTABLE), (0.0, 1.0), "free", 0.01))
    for name, mm, d, bd, dt in cases:
        res = to.limit_load(mm, d, bd)
        ts = repeat(lambda mm=mm, d=d, bd=bd: to.limit_load(mm, d, bd), reps)
        base_val, base_t = None, None
        if bd == "free":
            t0 = time.perf_counter()
            base_val = _natural_limit_load(mm, d, dt)
            base_t = [time.perf_counter() - t0]
        val = res.load if res.load is not None else res.end_load
        rows.append(Row("10", f"limit_load: {name}", mm.n, median_ms(ts), "ms",
                        "force steps + bisection (solve_equilibrium_under_force)" if base_t else "-",
                        median_ms(base_t) if base_t else None,
                        ratio=(median_ms(base_t) / median_ms(ts)) if base_t else None, target="(info)", samples=ts,
                        baseline_samples=base_t,
                        notes=[f"{name}: kind {res.kind}, load {val:.6g}"
                               + (f" ({res.status})" if res.kind == "none" else "")
                               + (f"; quasi-buckling load {res.quasi_buckling_load:.6g}"
                                  if res.quasi_buckling_load is not None else "")
                               + (f"; the step-and-bisect loop: {base_val:.6g}" if base_t and base_val is not None
                                  else "; the step-and-bisect loop finds no limit" if base_t else "")]))
    rows += _atlas_rows(cfg)
    return rows


def _bisect_count(m, a, b, n_a: int, tol: float):
    """What a user would do without the edge continuation: bisect the stable count along the edge with
    ``find_equilibria`` at each trial (to ``tol`` in length)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    lo, hi = 0.0, 1.0
    L = float(np.linalg.norm(b - a))
    while (hi - lo) * L > tol:
        mid = 0.5 * (lo + hi)
        p = a + mid * (b - a)
        k = sum(e.stable for e in to.find_equilibria(m, float(p[0]), float(p[1])))
        lo, hi = (mid, hi) if k == n_a else (lo, mid)
    return a + 0.5 * (lo + hi) * (b - a)


def _atlas_rows(cfg: Config) -> list[Row]:
    """The stability atlas: cost per target (every equilibrium + the edges) vs a find_equilibria loop over the
    same targets (the counts alone); cost per crossing vs bisecting the count along the edge."""
    rows: list[Row] = []
    size = 5 if cfg.quick else 8
    for name, m, X, Y in (
            ("bistable n=3", to.Manipulator.uniform(3, 0.5, 1.0, 1.0, 1.0), np.linspace(0.2, 1.4, size),
             np.linspace(-0.6, 0.6, size)),
            ("pre-bent n=4", to.Manipulator([to.Segment(1, 1, 1, (1.05, 0.95))] * 2 + [to.Segment(1, 1, 1, 1)] * 2),
             np.linspace(0.2, 1.4, size), np.linspace(-0.9, 0.9, size))):
        from tensegrity_opt.analyses.paths.atlas import assemble_atlas

        to.stability_atlas(m, X[:2], Y[:2])                             # warm-up (kernels built)
        t0 = time.perf_counter()
        bare = to.stability_atlas(m, X, Y, edges=False)                 # the targets (every equilibrium)
        counts = time.perf_counter() - t0
        t0 = time.perf_counter()
        at = assemble_atlas(m, [t for row in bare.targets for t in row])   # the edges of the same targets
        total = counts + time.perf_counter() - t0
        t0 = time.perf_counter()
        for y in Y:
            for x in X:
                to.find_equilibria(m, float(x), float(y))
        loop = time.perf_counter() - t0
        nt = X.size * Y.size
        o = total / nt * 1e3
        rows.append(Row("10", f"atlas per target: {name}", m.n, o, "ms", "find_equilibria loop (counts only)",
                        loop / nt * 1e3, ratio=loop / total, target="(info)", samples=[total / nt],
                        baseline_samples=[loop / nt],
                        notes=[f"atlas {name} on {X.size}x{Y.size} targets: {total:.2f} s in all, the counts "
                               f"{counts:.2f} s, the edges {total - counts:.2f} s; {len(at.switches)} switch and "
                               f"{len(at.branch_ends)} branch-end crossings, status {at.status}"]))
        ends = at.branch_ends
        if ends:
            c = ends[0]
            (ia, ja), (ib, jb) = c.edge
            a, b = (X[ia], Y[ja]), (X[ib], Y[jb])
            t0 = time.perf_counter()
            p = _bisect_count(m, a, b, int(at.n_stable[ja, ia]), 1e-6)
            tb = time.perf_counter() - t0
            per = (total - counts) / max(len(at.crossings), 1) * 1e3
            rows.append(Row("10", f"atlas crossing located: {name}", m.n, per, "ms",
                            "bisection of the stable count to 1e-6 (find_equilibria per trial)", tb * 1e3,
                            ratio=tb * 1e3 / per, target="(info)", samples=[per / 1e3], baseline_samples=[tb],
                            notes=[f"{name}: the fold on edge {c.edge} by the continuation at "
                                   f"({c.dx:.9f}, {c.dy:.9f}), "
                                   f"by bisection at ({p[0]:.9f}, {p[1]:.9f}); ours is the edge time per crossing "
                                   "(every crossing of the grid located by the edge continuation)"]))
    return rows


def case11(cfg: Config) -> list[Row]:
    """Control in actuation space: one warm preload step (the compiled least-change Newton step) vs
    ``preloads_for_pose`` per step and SLSQP on the same problem; ``plan_preloads`` per step with
    verification."""
    from tensegrity_opt.analyses.design.preload_control import PreloadController

    rows: list[Row] = []
    m = to.Manipulator.uniform(4, **{k: v for k, v in PAPER.items() if k != "n"})
    F = np.array([-0.02, 0.01])
    K = 200 if cfg.quick else 1000
    # the raw step (the end pose only, as the baselines): verify=False; the verified step is its own row below
    ctl = PreloadController(m, load=F, verify=False)
    tip0 = m.tip(ctl.q)
    traj = np.array([tip0 + np.array([-0.3, 0.6]) * np.sin(np.pi * k / (K - 1)) for k in range(K)])
    ctl.step(traj[0])                                          # warm-up (the kernel built)
    ts, methods = [], []
    for k in range(1, K):
        t0 = time.perf_counter()
        st = ctl.step(traj[k])
        ts.append(time.perf_counter() - t0)
        methods.append(st.method)
    # the alternatives on the same steps (a subset: they are slow), each from the controller's previous state
    ctl2 = PreloadController(m, load=F, verify=False)
    sub = list(range(1, K, max(1, K // 20)))
    base_c, base_s, agree = [], [], []
    for k in range(1, K):
        if k in sub:
            ell_prev, q_prev = ctl2.ell.copy(), ctl2.q.copy()
            t0 = time.perf_counter()
            d = to.preloads_for_pose(ctl2.manipulator(), traj[k], load=F, start=q_prev)
            base_c.append(time.perf_counter() - t0)
            t0 = time.perf_counter()
            r = bl.slsqp_preload_step(m, ell_prev, q_prev, traj[k], F)
            base_s.append(time.perf_counter() - t0)
        st = ctl2.step(traj[k])
        if k in sub:
            agree.append(max(float(np.abs(d.preloads.ravel() - st.command.ravel()).max()),
                             float(np.abs(r.x[m.n:] - st.command.ravel()).max())))
    o = median_ms(ts)
    note = (f"paper chain n=4 under F = {F.tolist()}, {K} tip poses on an arc (0.3 x 0.6): {methods.count('newton')} "
            f"steps by the compiled Newton step, {methods.count('ipopt')} by IPOPT, {methods.count('none')} "
            f"infeasible; p99 {float(np.percentile(ts, 99)) * 1e3:.3f} ms; on {len(sub)} sampled steps the three "
            f"methods' rest lengths agree to {max(agree):.1e}")
    rows.append(Row("11", "preload controller, warm step", 4, o, "ms", "preloads_for_pose per step (IPOPT)",
                    median_ms(base_c), ratio=median_ms(base_c) / o, target="<= 0.2 ms (goal)", met=o <= 0.2,
                    samples=ts, baseline_samples=base_c, notes=[note]))
    rows.append(Row("11", "preload controller, warm step", 4, o, "ms", "scipy SLSQP on the same problem (warm)",
                    median_ms(base_s), ratio=median_ms(base_s) / o, target="(info)", samples=ts,
                    baseline_samples=base_s))
    # the same steps verified along their transitions (the default): continuation of the move, the margin watched
    ctl3 = PreloadController(m, load=F)
    ctl3.step(traj[0])
    tv = []
    for k in range(1, K):
        t0 = time.perf_counter()
        ctl3.step(traj[k])
        tv.append(time.perf_counter() - t0)
    rows.append(Row("11", "preload controller, warm step verified along its transition", 4, median_ms(tv), "ms",
                    "the raw warm step (end pose only, verify=False)", o, ratio=o / median_ms(tv), target="(info)",
                    samples=tv, baseline_samples=ts,
                    notes=["the verified step: the least-change Newton step, then its transition followed by "
                           "arclength continuation (the rest lengths and the load ramping linearly), the margin "
                           "watched and its least located"]))
    t0 = time.perf_counter()
    plan = to.plan_preloads(m, traj[:200], loads=F)
    tp = (time.perf_counter() - t0) / 200
    rows.append(Row("11", "plan_preloads per step (verified along its transition)", 4, tp * 1e3, "ms",
                    target="(info)", samples=[tp],
                    notes=[f"plan_preloads over 200 steps: status {plan.status}, "
                           f"verified {int(plan.verified.sum())}/200"]))
    return rows


def case12(cfg: Config) -> list[Row]:
    """Every figure route's default request against the time limit (benchmarks/figures.py), on its own server."""
    from . import figures as fg
    from . import http_load as hl

    limit = float(os.environ.get("TENSEGRITY_SOLVE_TIMEOUT", "10"))
    with hl.own_server() as url:
        log(f"  server at {url}")
        measured = fg.measure(url, 1 if cfg.quick else 3, limit, explicit=not cfg.quick)
    rows = []
    for r in measured:
        rows.append(Row("12", f"figure {r['route']} ({r['example']}"
                        + (")" if r["default"] else ", explicit)"), r["request"].split(",")[0],
                        r["median_s"] * 1e3, "ms", target=f"<= {r['target_s']:g} s (limit / {fg.MARGIN:g})"
                        if r["default"] else "(info)", met=r["met"], samples=r["samples_s"],
                        notes=[f"{r['route']} {r['example']}: first answer {r['first_s']:.2f} s, HTTP {r['status']}, "
                               f"{r['bytes']} bytes"], extra={"figure": r}))
    return rows


def case13(cfg: Config) -> list[Row]:
    """The receding horizon (n = 4, N = 10): one window's solve warm-started from the shifted solution and its
    multipliers, beside the same NLP solved by IPOPT cold (from the current state) and beside the step-by-step
    controller's verified step; and a whole receding step of ``plan_preloads`` (the window, the step's transition,
    the never-worse checks) beside ``plan_preloads`` step by step."""
    from tensegrity_opt.analyses.design import horizon as H
    from tensegrity_opt.analyses.design.preload_control import PreloadController, plan_preloads
    from tensegrity_opt.numerics.horizon_nlp import horizon_nlp
    from tensegrity_opt.outcome import SolverInfo

    m = to.Manipulator.uniform(4, **{k: v for k, v in PAPER.items() if k != "n"})
    F = np.array([-0.02, 0.01])
    K = 20 if cfg.quick else 40
    N = 10
    tip0 = m.tip(PreloadController(m, load=F).q)
    traj = np.array([tip0 + np.array([-0.3, 0.6]) * np.sin(np.pi * k / (K - 1)) for k in range(K)])
    kw = dict(loads=F, rate_limit=0.05, dt=1.0)
    from tensegrity_opt.numerics import horizon_nlp as HN

    t0 = time.perf_counter()
    built = HN.prebuild(m.n, N)                                      # once per machine (cached)
    t_build = time.perf_counter() - t0
    plan_preloads(m, traj[:2], horizon=N, **kw)                      # warm-up (the NLPs built)
    plan_preloads(m, traj[:2], **kw)

    def receding(nlp):
        """One window solve at a time, on the receding loop a controller runs (the window's first step applied):
        the warm solves' and the cold solves' times and iterations."""
        ctl = PreloadController(m, load=F, rate_limit=0.05, dt=1.0)
        Ls, dts = np.tile(F, (K, 1)), np.ones(K)
        block = lambda v: np.asarray(v, float).reshape(m.n, 2).T.ravel()     # noqa: E731
        pl = H._Planner(ctl, traj, Ls, None, np.outer(dts, block(ctl.rate)), dts, block(ctl.w), block(ctl.lo),
                        block(ctl.hi), nlp, [], False, None)
        wt, ct, iw, ic, warm = [], [], [], [], None
        for j in range(K):
            cold_x = pl._cold(pl._index(j))
            t0 = time.perf_counter()
            cold = pl._solve(j, cold_x)
            ct.append(time.perf_counter() - t0)
            ic.append(cold.iterations)
            res = cold
            if warm is not None:
                t0 = time.perf_counter()
                res = pl._solve(j, warm[0], lam=warm[1])
                wt.append(time.perf_counter() - t0)
                iw.append(res.iterations)
            Q, Ell = pl._split(res.x)
            st = ctl.evaluate(pl._segment_major(Ell[0]), F, traj[j], method="horizon",
                              solver=SolverInfo(res.status, res.iterations))
            ctl.commit(st, F)
            warm = pl._shifted(res)
        return wt, ct, iw, ic

    nlp = horizon_nlp(m.n, N)
    warm_t, cold_t, its_w, its_c = receding(nlp)
    mode = nlp.mode
    vm = HN.HorizonNLP(m.n, N, False)                                # the same problem, warm in the VM
    vm._warm, vm._warm_deadline = HN._nlpsol("horizon_vm", vm._nlp, **{"ipopt.max_iter": 1000, **HN.WARM_OPTIONS})
    vm_t, _, _, _ = receding(vm)
    # the step-by-step controller's verified step on the same trajectory
    own = PreloadController(m, load=F, rate_limit=0.05, dt=1.0)
    sbs_t = []
    for j in range(K):
        t0 = time.perf_counter()
        own.step(traj[j])
        sbs_t.append(time.perf_counter() - t0)
    th, ts = [], []
    for _ in range(3 if cfg.quick else 5):
        t0 = time.perf_counter()
        hz = plan_preloads(m, traj, horizon=N, **kw)
        th.append((time.perf_counter() - t0) / K)
        t0 = time.perf_counter()
        sbs = plan_preloads(m, traj, **kw)
        ts.append((time.perf_counter() - t0) / K)
    w = median_ms(warm_t)
    how = ("no compiler" if not built else "the library found in the cache" if t_build < 1 else
           f"the library compiled in {t_build:.1f} s")
    note = (f"paper chain n=4 under F = {F.tolist()}, {K} tip poses on an arc (0.3 x 0.6), rate 0.05 per second, "
            f"a step a second, N = {N}: the window warm-started from the shifted solution and its multipliers "
            f"(IPOPT warm_start_init_point, mu_init 1e-8) takes a median {int(np.median(its_w))} iterations, cold "
            f"{int(np.median(its_c))}; the warm solves evaluate {mode} code (horizon_nlp.prebuild(4, 10): {how})")
    note2 = (f"a whole receding step of plan_preloads(horizon={N}): the window, the step's transition followed, the "
             f"never-worse checks, and the step-by-step plan it is compared with (status {hz.status}, "
             f"{sum(mm == 'horizon' for mm in hz.method)} of {K} steps the window's); step by step: status "
             f"{sbs.status}")
    return [Row("13", "receding-horizon window solve (N = 10, warm: shifted solution and multipliers)", 4, w, "ms",
                "the same NLP, IPOPT cold", median_ms(cold_t), ratio=median_ms(cold_t) / w, target="<= 5 ms (goal)",
                met=w <= 5.0, samples=warm_t, baseline_samples=cold_t, notes=[note]),
            Row("13", "receding-horizon window solve (N = 10, warm: shifted solution and multipliers)", 4, w, "ms",
                "the same warm solve in CasADi's virtual machine (no prebuild)", median_ms(vm_t),
                ratio=median_ms(vm_t) / w, target="(info)", samples=warm_t, baseline_samples=vm_t),
            Row("13", "receding-horizon window solve (N = 10, warm: shifted solution and multipliers)", 4, w, "ms",
                "the step-by-step controller's verified step", median_ms(sbs_t), ratio=median_ms(sbs_t) / w,
                target="(info)", samples=warm_t, baseline_samples=sbs_t),
            Row("13", "plan_preloads(horizon=10), per step", 4, median_ms(th), "ms",
                "plan_preloads step by step (per step)", median_ms(ts), ratio=median_ms(ts) / median_ms(th),
                target="(info)", samples=th, baseline_samples=ts, notes=[note2])]


def case14(cfg: Config) -> list[Row]:
    """Interval certificates (Krawczyk, Arb) of whole sets of equilibria, per n, beside the float polish."""
    from tensegrity_opt.analyses.equilibria.equilibrium import local_equilibrium, make_equilibrium
    from tensegrity_opt.numerics.krawczyk import prove_equilibria

    cases = json.loads((ROOT / "tests" / "data" / "homotopy_oracle.json").read_text())["cases"]
    sets: dict[int, list] = {}
    for c in cases:
        m = to.Manipulator.from_dict(c["manipulator"])
        Q = np.array([e["q"] for e in c["equilibria"]])
        F = np.array([e["force"] for e in c["equilibria"]])
        sets.setdefault(m.n, []).append((m, m.target(c["dx"], c["dy"]), Q, F, c["seconds"]))
    for seed in range(2 if cfg.quick else 4):
        m = to.Manipulator.uniform(6, **BISTABLE)
        rng = np.random.default_rng(seed)
        dx, dy = rng.uniform(0.1, 0.4) * m.straight_length, rng.uniform(-0.2, 0.2) * m.straight_length
        eqs = to.find_equilibria(m, dx, dy)
        sets.setdefault(6, []).append((m, m.target(dx, dy), np.array([e.q for e in eqs]),
                                       np.array([e.force for e in eqs]), None))
    rows = []
    for n in sorted(sets):
        ours, base, per, counts, proven, phc = [], [], [], [], 0, []
        for m, target, Q, F, sec in sets[n][: 6 if cfg.quick else None]:
            t = repeat(lambda: prove_equilibria(m, Q, F, target=target), 1 if cfg.quick else 3, warmup=0)
            cert = prove_equilibria(m, Q, F, target=target)
            proven += cert.status == "proven"
            ours.append(statistics.median(t))
            per.append(statistics.median(t) / max(1, len(Q)))
            counts.append(len(Q))

            def polish():
                for q, f in zip(Q, F):
                    make_equilibrium(m, local_equilibrium(m, target, q, f), constrained=True)
            base.append(statistics.median(repeat(polish, 1 if cfg.quick else 3, warmup=0)))
            if sec is not None:
                phc.append(sec)
        o, b = median_ms(ours), median_ms(base)
        src = "PHCpack oracle" if n <= 5 else f"search sets of bistable chains ({BISTABLE})"
        rows.append(Row("14", "interval certificate of a set (Krawczyk, arb)", n, o, "ms",
                        "Newton polish + float classification of the same equilibria", b, ratio=b / o,
                        target="(info)", samples=ours, baseline_samples=base,
                        notes=[f"n={n}: {len(ours)} sets ({src}), {min(counts)}-{max(counts)} equilibria a set, "
                               f"{proven}/{len(ours)} sets proven (every root and Morse index); "
                               f"{1e3 * statistics.median(per):.2f} ms an equilibrium"
                               + (f"; the oracle's phc solve took {statistics.median(phc):.2f} s (median, recorded)"
                                  if phc else "")]))
    return rows


CASES: list[tuple[str, Callable[[Config], list[Row]]]] = [
    ("1", case1), ("2", case2), ("3", case3), ("4-5", case4_5), ("6", case6), ("7-8", case7_8), ("9", case9),
    ("10", case10), ("11", case11), ("12", case12), ("13", case13), ("14", case14),
]


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m benchmarks", description=__doc__.splitlines()[0])
    p.add_argument("--quick", action="store_true", help="fewer repetitions, short service phases (< 1 min)")
    p.add_argument("--json", default=str(HERE / "results.json"), help="JSON output (default benchmarks/results.json)")
    p.add_argument("--md", default=str(HERE / "RESULTS.md"),
                   help="markdown output (default benchmarks/RESULTS.md; '' to skip)")
    p.add_argument("--no-service", action="store_true", help="skip the HTTP service cases (7, 8, 12)")
    p.add_argument("--only", default=None, help="comma-separated case ids to run (e.g. 1,3,7-8)")
    args = p.parse_args(argv)
    cfg = Config.make(args.quick, not args.no_service)
    machine = machine_info()
    t_start = time.perf_counter()
    rows: list[Row] = []
    skipped: list[str] = []
    only = None if args.only is None else set(args.only.split(","))
    for cid, fn in CASES:
        if only is not None and cid not in only:
            continue
        if cid in ("7-8", "12") and not cfg.service:
            skipped.append(f"cases {cid} (service) skipped: --no-service")
            continue
        log(f"case {cid} ...")
        t0 = time.perf_counter()
        try:
            rows += fn(cfg)
        except ServerStartError as exc:
            msg = f"cases {cid} (service) skipped: the server did not start: {str(exc)[:500]}"
            log(msg)
            skipped.append(msg)
        except Exception as exc:  # noqa: BLE001 - one failing case must not lose the others
            msg = f"cases {cid} failed: {type(exc).__name__}: {str(exc)[:500]}"
            log(msg + "\n" + traceback.format_exc())
            skipped.append(msg)
        log(f"case {cid} done in {time.perf_counter() - t0:.1f} s")
    total = time.perf_counter() - t_start
    machine["loadavg_end"] = list(os.getloadavg()) if hasattr(os, "getloadavg") else None
    machine["suite_seconds"] = round(total, 1)

    print(table_text(rows))
    print()
    for nt in notes_text(rows) + skipped:
        print(nt)
    print(f"\nmachine: {machine['cpu']}, nproc {machine['nproc']}, python {machine['python']}, numpy "
          f"{machine['numpy']}, scipy {machine['scipy']}, casadi {machine['casadi']}; load average "
          f"{machine['loadavg_start']} -> {machine['loadavg_end']}; {total:.0f} s")

    data = {"suite": "tensegrity_opt benchmarks", "mode": "quick" if cfg.quick else "full",
            "service": cfg.service, "machine": machine, "columns": HEAD,
            "rows": [r.to_json() for r in rows], "skipped": skipped,
            "targets_met": sum(1 for r in rows if r.met is True),
            "targets_missed": sum(1 for r in rows if r.met is False)}
    if args.json:
        Path(args.json).write_text(json.dumps(_jsonable(data), indent=2) + "\n", encoding="utf-8")
    if args.md:
        md = Path(args.md)
        # sections measured by other scripts (below KEEP_MARKER: e.g. "Sweep scheduler default",
        # benchmarks/sweep_scheduler.py) survive a new run of the suite
        old = md.read_text(encoding="utf-8") if md.exists() else ""
        kept = old[old.index(KEEP_MARKER):] if KEEP_MARKER in old else ""
        md.write_text(markdown(rows, machine, cfg, total, skipped) + ("\n" + kept if kept else ""), encoding="utf-8")
    return 0


#: What follows this line in RESULTS.md is kept when the suite rewrites the file.
KEEP_MARKER = "<!-- kept by benchmarks.suite: sections measured by other scripts -->"
