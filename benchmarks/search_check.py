"""Completeness of the global search on random multistable chains against an independent brute force.

``python -m benchmarks.search_check [--cases 48] [--seed 13] [--n 6 7 8 10] [--starts 300] [--eq-starts 2000]``

The README's "measured" completeness claim for chains longer than the homotopy certifies in practical time
(``n >= 6``: the homotopy tracks 43648 paths at n = 6, ~12 min here). Random
chains that are *not* monotonic, the families in turn: ``bistable`` (uniform segments, ``K < 0``:
a in [0.4, 0.8], b = 1, k in [0.5, 2], L0 = u 2 (b^2 - a^2) / b with u in [0.35, 0.9]),
``heterogeneous`` (each segment its own a, b in [0.8, 1.2], k, bistable L0), ``mixed`` (half of the
segments, drawn at random, monotonic: L0 = 2 (b^2 - a^2) / b + [0.2, 1.0]) and ``asymmetric``
(heterogeneous bistable with k = (k, k [0.6, 1.6]), L0 = (L0, L0 [0.8, 1.2])); n cycles through
``--n``. Targets: dx = U(0.02, 0.5) of the straight length, dy = U(-0.3, 0.3) of it in 2/3 of the
cases, 0 otherwise; targets ``check_reachable`` rejects are redrawn.

The reference never calls the library's solvers: it is ``tests/support/reference_model.py`` (which does not
import ``tensegrity_opt``; only its O(n^2)-loop tip Hessian is replaced here by an equal vectorised
one, checked at start-up) with SciPy:

1. least-energy stable equilibrium: SLSQP (``min E`` s.t. ``tip = target`` inside the joint range)
   from ``--starts`` random starts uniform in 0.98 of the range plus up to 64 combinations of the
   segments' unloaded wells (each segment's own energy minima), every result polished by the
   reference Newton on the KKT system and kept only when it converged strictly inside the range and
   the reduced Hessian's eigenvalues are all > 1e-9 of their scale (clearly stable);
2. all equilibria: Newton on the KKT system from ``--eq-starts`` random starts projected onto
   ``tip = target`` (as ``reference_model.all_equilibria``), merged with the minima of 1 (dedupe
   1e-6), each classified by its Morse index from the reference reduced Hessian.

The library: ``solve_equilibrium(m, dx, dy)`` — its energy against the reference least stable
energy (the minimum over 1 and the stable points of 2): ``same`` within 1e-9 relative, ``higher``
(the library missed the least-energy stable equilibrium), ``lower`` (the reference missed it; the
library's point is re-checked with the reference model), ``fail`` (the library raised while the
reference found one), ``none`` (neither found a stable equilibrium: a target outside the
joint-range workspace); and ``find_equilibria(m, dx, dy)`` — reference equilibria it missed (match:
max-norm of ``q`` within 1e-6), split stable / unstable, and library equilibria the reference missed
(``extra``; ``bogus`` when the reference Newton does not confirm them as equilibria in range). Both
calls are timed (median ms per call, after an untimed warm-up per ``n``). Every ``higher``,
missed-stable, ``lower`` and ``bogus`` case is printed with ``dx``, ``dy`` and its segments as
``(a, b, k1, k2, L1_0, L2_0)`` tuples (``manipulator_from(segments)`` rebuilds the chain), then one
line per finding; per-case progress goes to stderr.

Neither side is complete for n >= 7 (the equilibria multiply with n; many library ``extra`` are
genuine): ``missed`` and ``extra`` are lower bounds, only found points are ever counted.

Cost: the reference dominates. ``--cases 24 --starts 200 --eq-starts 800`` took 337 s on one core
(8-22 s of reference per case; the library ~0.2-0.6 s per call); the defaults (48 cases, 300 / 2000
starts) cost roughly 4x that. That run (seed 13): solve
21 same, 1 higher (n = 7 heterogeneous), 0 lower, 2 none (n = 10); find missed 207 stable and 373
unstable of 1049 reference equilibria (no stable one missed at n = 6, some at every n >= 7), 844 extra,
0 bogus.
"""

from __future__ import annotations

import argparse
import collections
import itertools
import statistics
import sys
import time
import warnings
from pathlib import Path

import numpy as np
import scipy.optimize as so

import tensegrity_opt as to

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "support"))
import reference_model as ref  # noqa: E402  (independent of the library: never imports it)

FAMILIES = ("bistable", "heterogeneous", "mixed", "asymmetric")
DEDUPE = 1e-6           # max-norm of q: two equilibria closer than this are one
MATCH = 1e-6            # library vs reference equilibrium
STABLE_REL = 1e-9       # reduced-Hessian eigenvalues > this times their scale: clearly stable
ENERGY_REL = 1e-9       # "same" least energy


# ---------------------------------------------------------------------------------- random cases
def _bistable_L0(rng, a, b):
    """A rest length with K = k (b L0 - 2 (b^2 - a^2)) < 0 (a < b)."""
    return rng.uniform(0.35, 0.9) * 2.0 * (b * b - a * a) / b


def random_chain(rng, n: int, family: str) -> to.Manipulator:
    if family == "bistable":
        a, k = rng.uniform(0.4, 0.8), rng.uniform(0.5, 2.0)
        return to.Manipulator([to.Segment(a, 1.0, k, _bistable_L0(rng, a, 1.0))] * n)
    monotonic = set(rng.choice(n, n // 2, replace=False).tolist()) if family == "mixed" else set()
    segs = []
    for i in range(n):
        a, b, k = rng.uniform(0.4, 0.8), rng.uniform(0.8, 1.2), rng.uniform(0.5, 2.0)
        L0 = 2.0 * (b * b - a * a) / b + rng.uniform(0.2, 1.0) if i in monotonic else _bistable_L0(rng, a, b)
        if family == "asymmetric":
            k = (k, k * rng.uniform(0.6, 1.6))
            L0 = (L0, L0 * rng.uniform(0.8, 1.2))
        segs.append(to.Segment(a, b, k, L0))
    return to.Manipulator(segs)


def cases(count: int, seed: int, ns):
    """``count`` (family, manipulator, dx, dy): n cycles through ``ns``, the families per n in turn."""
    rng = np.random.default_rng(seed)
    for i in range(count):
        n = ns[i % len(ns)]
        fam = FAMILIES[(i // len(ns)) % len(FAMILIES)]
        while True:
            m = random_chain(rng, n, fam)
            if m.monotonic:
                continue
            L = m.straight_length
            for _ in range(20):
                dx = float(rng.uniform(0.02, 0.5) * L)
                dy = float(rng.uniform(-0.3, 0.3) * L) if rng.random() < 2.0 / 3.0 else 0.0
                try:
                    m.check_reachable(dx, dy)
                except ValueError:
                    continue
                break
            else:
                continue
            yield fam, m, dx, dy
            break


def segments_repr(m: to.Manipulator) -> str:
    """The segments as a Python expression of (a, b, k1, k2, L1_0, L2_0) tuples (uniform: ``(s,) * n``)."""
    rows = [(s.a, s.b, s.k1, s.k2, s.L1_0, s.L2_0) for s in m.segments]
    return f"({rows[0]!r},) * {m.n}" if all(r == rows[0] for r in rows) else repr(tuple(rows))


def manipulator_from(rows) -> to.Manipulator:
    """Rebuild a printed case: ``manipulator_from(segments)`` with the tuples printed by this check."""
    return to.Manipulator([to.Segment(a, b, (k1, k2), (l1, l2)) for a, b, k1, k2, l1, l2 in rows])


# ---------------------------------------------------------------------------------- reference
class RefChain(ref.Chain):
    """``reference_model.Chain`` with the same tip Hessians computed without Python loops."""

    def tip_hessians(self, q):
        phi = np.cumsum(np.asarray(q, float))
        l = self.links
        sx = np.cumsum((l * np.cos(phi))[::-1])[::-1]      # sum_{j >= m} l_j cos phi_j
        sy = np.cumsum((l * np.sin(phi))[::-1])[::-1]
        idx = np.maximum.outer(np.arange(self.n), np.arange(self.n))
        return -sx[idx], -sy[idx]


def ref_chain(m: to.Manipulator) -> RefChain:
    return RefChain(*(np.array(v, float) for v in (m.a, m.b, m.k1, m.k2, m.L1_0, m.L2_0)))


def _check_fast_hessians() -> None:
    rng = np.random.default_rng(0)
    segs = [(rng.uniform(0.4, 0.8), rng.uniform(0.8, 1.2), 1.0, 1.3, 1.1, 0.9) for _ in range(7)]
    fast = RefChain(*(np.array(c, float) for c in zip(*segs)))
    slow = ref.Chain(*(np.array(c, float) for c in zip(*segs)))
    q = rng.uniform(-0.9, 0.9, 7) * slow.limits
    for A, B in zip(fast.tip_hessians(q), slow.tip_hessians(q)):
        assert np.allclose(A, B, rtol=1e-13, atol=1e-13), "vectorised tip Hessian differs from the reference"


def classify(chain: ref.Chain, q, F):
    """(Morse index, clearly stable) from the reference reduced Hessian."""
    w = chain.reduced_eigs(q, F, constrained=True, fd=False)
    if w.size == 0:
        return 0, True
    tol = STABLE_REL * max(1.0, float(np.abs(w).max()))
    return int(np.sum(w < -tol)), bool(w.min() > tol)


def polish(chain: ref.Chain, target, q, F=None):
    """Reference Newton on the KKT system; (q, F) strictly inside the range, or None."""
    try:
        q, F, ok = chain.newton_kkt(target, q, F)
    except (np.linalg.LinAlgError, ValueError, FloatingPointError):
        return None
    if not ok or not np.all(np.isfinite(q)) or not chain.in_range(q):
        return None
    return q, F


def segment_wells(chain: ref.Chain, grid: int = 4001):
    """Each segment's unloaded energy minima inside its range (sign changes - to + of E_i')."""
    lim = chain.limits * (1.0 - 1e-9)
    t = np.linspace(-1.0, 1.0, grid)
    Q = t[:, None] * lim[None, :]
    G = chain.grad(Q)                       # separable: column i is E_i'(q_i)
    wells = []
    for i in range(chain.n):
        def g(x, i=i):
            z = np.zeros(chain.n)
            z[i] = x
            return chain.grad(z)[i]
        mins = [so.brentq(g, Q[j, i], Q[j + 1, i], xtol=1e-14)
                for j in range(grid - 1) if G[j, i] < 0.0 < G[j + 1, i]]
        wells.append(mins or [0.0])
    return wells


def well_starts(chain: ref.Chain, rng, sample: int = 64):
    wells = segment_wells(chain)
    total = int(np.prod([len(w) for w in wells]))
    if total <= sample:
        combos = list(itertools.product(*[range(len(w)) for w in wells]))
    else:
        seen: set = set()
        while len(seen) < sample:
            seen.add(tuple(int(rng.integers(len(w))) for w in wells))
        combos = sorted(seen)
    return [np.array([wells[i][c] for i, c in enumerate(combo)]) for combo in combos]


def add_unique(sols, q, F) -> bool:
    if any(np.max(np.abs(q - s)) < DEDUPE for s, _ in sols):
        return False
    sols.append((q, F))
    return True


def reference_minima(chain: ref.Chain, target, starts):
    """Clearly stable constrained minima by SLSQP + reference Newton polish, deduplicated."""
    lim = chain.limits * (1.0 - 1e-6)
    bounds = list(zip(-lim, lim))
    cons = [{"type": "eq", "fun": lambda q: chain.tip(q) - target, "jac": chain.jac}]
    sols: list = []
    for s in starts:
        try:
            res = so.minimize(chain.energy, s, jac=chain.grad, method="SLSQP", bounds=bounds, constraints=cons,
                              options={"maxiter": 300, "ftol": 1e-10})
        except (ValueError, np.linalg.LinAlgError):
            continue
        if not np.all(np.isfinite(res.x)) or np.max(np.abs(chain.tip(res.x) - target)) > 1e-4:
            continue
        p = polish(chain, target, res.x)
        if p is not None and classify(chain, *p)[1]:
            add_unique(sols, *p)
    return sols


def reference_equilibria(chain: ref.Chain, target, rng, n_starts: int):
    """``reference_model.all_equilibria``: random starts projected on tip = target (min-norm
    Gauss-Newton), then Newton on the KKT system; strictly inside the range, deduplicated."""
    sols: list = []
    for _ in range(n_starts):
        q = rng.uniform(-0.98, 0.98, chain.n) * chain.limits
        try:
            for _ in range(40):
                r = target - chain.tip(q)
                if np.max(np.abs(r)) < 1e-12:
                    break
                q = q + np.linalg.lstsq(chain.jac(q), r, rcond=None)[0]
        except (np.linalg.LinAlgError, ValueError):
            continue
        if not np.all(np.isfinite(q)):
            continue
        p = polish(chain, target, q)
        if p is not None:
            add_unique(sols, *p)
    return sols


# ---------------------------------------------------------------------------------- one case
def run_case(i, fam, m, dx, dy, args, warm: set):
    chain = ref_chain(m)
    target = chain.target(dx, dy)
    rng = np.random.default_rng([args.seed, i])
    t0 = time.perf_counter()
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore")
        starts = [rng.uniform(-0.98, 0.98, chain.n) * chain.limits for _ in range(args.starts)]
        starts += well_starts(chain, rng)
        minima = reference_minima(chain, target, starts)
        eqs = reference_equilibria(chain, target, rng, args.eq_starts)
    for q, F in minima:
        add_unique(eqs, q, F)
    ref_eqs = [(q, F, chain.energy(q), *classify(chain, q, F)) for q, F in eqs]
    stable_E = [e for _, _, e, _, st in ref_eqs if st]
    ref_E = min(stable_E) if stable_E else None
    t_ref = time.perf_counter() - t0

    if m.n not in warm:              # untimed warm-up: solver construction per chain length
        warm.add(m.n)
        for f in (to.solve_equilibrium, to.find_equilibria):
            try:
                f(m, dx, dy)
            except (ValueError, RuntimeError):
                pass
    t0 = time.perf_counter()
    try:
        got = to.solve_equilibrium(m, dx, dy)
    except (ValueError, RuntimeError):
        got = None
    t_solve = time.perf_counter() - t0
    t0 = time.perf_counter()
    try:
        found = list(to.find_equilibria(m, dx, dy))
    except (ValueError, RuntimeError):
        found = None
    t_find = time.perf_counter() - t0

    r = {"n": m.n, "fam": fam, "t_solve": t_solve, "t_find": t_find, "t_ref": t_ref, "ref_eqs": len(ref_eqs),
         "missed_stable": 0, "missed_unstable": 0, "extra": 0, "bogus": 0, "find_fail": found is None}
    notes = []
    if got is None:
        r["solve"] = "none" if ref_E is None else "fail"
    elif ref_E is None:
        r["solve"] = "lower"
    else:
        tol = ENERGY_REL * max(1.0, abs(ref_E))
        r["solve"] = "higher" if got.energy > ref_E + tol else ("lower" if got.energy < ref_E - tol else "same")
    if r["solve"] == "higher":
        notes.append(f"  HIGHER: library {got.energy:.12g} (q={np.round(got.q, 6).tolist()}) "
                     f"reference {ref_E:.12g}")
    elif r["solve"] == "lower":
        p = polish(chain, target, got.q, got.force)
        conf = ("confirmed stable by the reference" if p is not None and np.max(np.abs(p[0] - got.q)) < MATCH
                and classify(chain, *p)[1] else "NOT confirmed by the reference")
        notes.append(f"  LOWER: library {got.energy:.12g} reference "
                     f"{'none' if ref_E is None else format(ref_E, '.12g')} ({conf})")
    if found is not None:
        for q, F, e, idx, st in ref_eqs:
            if not any(np.max(np.abs(eq.q - q)) < MATCH for eq in found):
                r["missed_stable" if st else "missed_unstable"] += 1
                if st:
                    notes.append(f"  MISSED STABLE by find_equilibria: energy {e:.12g} q={np.round(q, 6).tolist()} "
                                 f"(reference least stable {ref_E:.12g})")
        for eq in found:
            if any(np.max(np.abs(eq.q - q)) < MATCH for q, *_ in ref_eqs):
                continue
            p = polish(chain, target, eq.q, eq.force)
            if p is not None and np.max(np.abs(p[0] - eq.q)) < MATCH:
                r["extra"] += 1
            else:
                r["bogus"] += 1
                notes.append(f"  BOGUS: library equilibrium energy {eq.energy:.12g} "
                             f"q={np.round(eq.q, 6).tolist()} not confirmed by the reference Newton")
    if notes:
        notes.insert(0, f"case {i + 1}/{args.cases}: n={m.n} {fam} dx={dx!r} dy={dy!r} segments={segments_repr(m)}")
    return r, notes


# ---------------------------------------------------------------------------------- summary
def _table(rows) -> list[str]:
    head = (f"{'n':>3} {'cases':>5} | {'same':>4} {'higher':>6} {'lower':>5} {'fail':>4} {'none':>4} | "
            f"{'ref eq':>6} {'miss st':>7} {'miss un':>7} {'extra':>5} {'bogus':>5} {'ffail':>5} | "
            f"{'solve ms':>8} {'find ms':>8} {'ref s':>6}")
    out = [head, "-" * len(head)]
    groups = collections.defaultdict(list)
    for r in rows:
        groups[r["n"]].append(r)
    for key in sorted(groups) + ["all"]:
        g = rows if key == "all" else groups[key]
        if not g:
            continue
        c = collections.Counter(r["solve"] for r in g)
        s = lambda f: sum(r[f] for r in g)  # noqa: E731
        med = lambda f: 1e3 * statistics.median(r[f] for r in g)  # noqa: E731
        out.append(f"{key!s:>3} {len(g):>5} | {c['same']:>4} {c['higher']:>6} {c['lower']:>5} {c['fail']:>4} "
                   f"{c['none']:>4} | {s('ref_eqs'):>6} {s('missed_stable'):>7} {s('missed_unstable'):>7} "
                   f"{s('extra'):>5} {s('bogus'):>5} {s('find_fail'):>5} | {med('t_solve'):>8.1f} "
                   f"{med('t_find'):>8.1f} {statistics.median(r['t_ref'] for r in g):>6.1f}")
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", type=int, default=48, help="number of random (chain, target) cases")
    ap.add_argument("--seed", type=int, default=13)
    ap.add_argument("--n", type=int, nargs="+", default=[6, 7, 8, 10], help="chain lengths, cycled")
    ap.add_argument("--starts", type=int, default=300, help="random SLSQP starts of the reference minimisation")
    ap.add_argument("--eq-starts", type=int, default=2000, help="random Newton starts of the reference equilibria")
    args = ap.parse_args(argv)
    _check_fast_hessians()
    t_all = time.perf_counter()
    rows, warm = [], set()
    for i, (fam, m, dx, dy) in enumerate(cases(args.cases, args.seed, args.n)):
        r, notes = run_case(i, fam, m, dx, dy, args, warm)
        rows.append(r)
        for line in notes:
            print(line, flush=True)
        print(f"[{i + 1}/{args.cases}] n={r['n']} {fam}: solve {r['solve']}, {r['ref_eqs']} reference equilibria, "
              f"missed {r['missed_stable']}/{r['missed_unstable']}, extra {r['extra']}, reference {r['t_ref']:.1f} s",
              file=sys.stderr, flush=True)
    print(f"search_check: {args.cases} cases, seed {args.seed}, n {args.n}, starts {args.starts}, "
          f"eq-starts {args.eq_starts}, {time.perf_counter() - t_all:.0f} s")
    print("solve: least stable energy vs the reference; find: reference equilibria, missed stable / unstable, "
          "library extras (confirmed) and bogus, find failures; median ms per library call; median reference s")
    print("\n".join(_table(rows)))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
