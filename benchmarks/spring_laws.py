"""The least-energy equilibrium under the tension-only spring law (issue 40), against what a user would write.

``python -m benchmarks.spring_laws [--quick]`` prints a markdown table: for chains of every family (n = 2..4, and
the paper's chain at dx = 2 and 3), deflected so that springs go slack or a joint rests on its stop,

* ours: ``solve_equilibrium`` of the tension-only chain (IPOPT on the smooth slack problem from the linear law's
  answer, the stops and 24 random starts; Newton with the stops held), median time;
* the baseline a user would pick: scipy's SLSQP on the tension-only energy with the tip constraint and the closed
  joint range as bounds, from 16 and from 64 random starts (the best of them), median time;
* the same chain under the linear law (``solve_equilibrium``, the default search), for the cost of the law;
* the energies found: ours, SLSQP's best and the independent brute force's (``tests/support/reference_tension_only``:
  a dense grid over the closed range, polished), and whether ours is the least (within 1e-9 relative).

A second table: every equilibrium (``find_equilibria``) of tension-only chains n = 3, 4, by the search (not
certified) and by the patterns' homotopy (``method="homotopy"``: certified), beside the linear law's search and
certified homotopy on the same chain and target. A third: the linear law's every-equilibrium set with the equilibria
resting on a stop (``stops=True``) beside its default (the open range).
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np
import scipy.optimize as so

import tensegrity_opt as to

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "support"))
import reference_tension_only as ref  # noqa: E402  (the independent brute force)


def _cases(rng: np.random.Generator):
    """(label, chain, dx, dy): the paper's chain and random chains of every family, tension-only."""
    yield "paper chain, dx = 2", to.Manipulator.uniform(4, spring="tension_only"), 2.0, 0.0
    yield "paper chain, dx = 3", to.Manipulator.uniform(4, spring="tension_only"), 3.0, 0.0
    for n in (2, 3, 4):
        u = lambda lo, hi: float(rng.uniform(lo, hi))  # noqa: E731
        yield f"monotonic n={n}", to.Manipulator.uniform(n, a=u(0.8, 1.2), k=u(0.5, 2), L0=u(0.8, 1.2),
                                                         spring="tension_only"), 0.45 * n, 0.0
        yield f"bistable n={n}", to.Manipulator.uniform(n, a=0.5, k=u(0.5, 2), L0=u(0.4, 0.6),
                                                        spring="tension_only"), 0.4 * n, 0.1
        segs = [to.Segment(u(0.6, 1.4), u(0.8, 1.2), (u(0.5, 2), u(0.5, 2)), (u(0.8, 1.3), u(0.8, 1.3)),
                           "tension_only") for _ in range(n)]
        yield f"heterogeneous n={n}", to.Manipulator(segs), 0.4 * n, -0.2


def _slsqp(m: to.Manipulator, dx: float, dy: float, starts: int, seed: int = 0) -> float:
    """The best energy of SLSQP from ``starts`` random configurations (tension-only energy, tip equality, the closed
    range as bounds): what a user would write with scipy."""
    segs = ref.segs_of(m)
    T = ref.target(segs, dx, dy)
    lim = ref.limits(segs)
    cons = {"type": "eq", "fun": lambda q: ref.tip(segs, q) - T, "jac": lambda q: ref.tip_jacobian(segs, q)}
    rng = np.random.default_rng(seed)
    best = np.inf
    for q0 in rng.uniform(-0.9, 0.9, size=(starts, m.n)) * lim:
        r = so.minimize(lambda q: ref.energy(segs, q), q0, jac=lambda q: -ref.torques(segs, q), method="SLSQP",
                        constraints=[cons], bounds=list(zip(-lim, lim)), options={"maxiter": 300, "ftol": 1e-12})
        if r.success and np.abs(ref.tip(segs, r.x) - T).max() < 1e-8:
            best = min(best, float(r.fun))
    return best


def _median_time(f, reps: int) -> tuple[float, object]:
    out, times = None, []
    for _ in range(reps):
        t = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t)
    return float(np.median(times)), out


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m benchmarks.spring_laws", description=__doc__.splitlines()[0])
    p.add_argument("--quick", action="store_true", help="one repetition, 16 SLSQP starts")
    args = p.parse_args(argv)
    reps, starts = (1, 16) if args.quick else (3, 64)
    print("| case | n | ours (median) | SLSQP, 16 starts | ratio | SLSQP, %d starts | ratio | linear law (median) | "
          "E ours | E SLSQP best | E brute force | ours least? | slack springs | joints on a stop |" % starts)
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    rng = np.random.default_rng(20261207)
    for label, m, dx, dy in _cases(rng):
        try:
            best = ref.least_energy(ref.segs_of(m), dx, dy)
        except ValueError:
            continue
        to.solve_equilibrium(m, dx, dy)                  # warm-up (the NLP built once per n)
        t_ours, eq = _median_time(lambda: to.solve_equilibrium(m, dx, dy), reps)
        t_few, e_few = _median_time(lambda: _slsqp(m, dx, dy, 16), 1 if args.quick else 2)
        t_slsqp, e_slsqp = _median_time(lambda: _slsqp(m, dx, dy, starts), 1 if args.quick else 2)
        e_slsqp = min(e_few, e_slsqp)
        lin = m.with_spring("linear")
        to.solve_equilibrium(lin, dx, dy)
        t_lin, _ = _median_time(lambda: to.solve_equilibrium(lin, dx, dy), reps)
        least = eq.energy <= best.energy * (1 + 1e-9) + 1e-12 and eq.energy <= e_slsqp * (1 + 1e-9) + 1e-12
        print(f"| {label} | {m.n} | {t_ours * 1e3:.1f} ms | {t_few * 1e3:.0f} ms | {t_few / t_ours:.2f}x | "
              f"{t_slsqp * 1e3:.0f} ms | {t_slsqp / t_ours:.2f}x | "
              f"{t_lin * 1e3:.2f} ms | {eq.energy:.9f} | {e_slsqp:.9f} | {best.energy:.9f} | "
              f"{'yes' if least else 'NO'} | {int((eq.spring_states == 'slack').sum())} | "
              f"{int(eq.at_stop.sum())} |")
    print()
    print("| every equilibrium | n | dx, dy | tension-only search (median) | count (on a stop) | tension-only "
          "homotopy | count | status | patterns solved / all | linear search (median) | count | linear homotopy | "
          "count | status |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    rng = np.random.default_rng(40)
    cases = [("paper's segments", to.Manipulator.uniform(n, spring="tension_only"), dx, dy)
             for n, dx, dy in ((3, 1.0, 0.5), (3, 2.0, 0.3), (4, 1.0, 0.4), (4, 3.0, 0.3))]
    for n in (3, 4):
        segs = [to.Segment(float(rng.uniform(0.6, 1.4)), float(rng.uniform(0.8, 1.2)),
                           (float(rng.uniform(0.5, 2)), float(rng.uniform(0.5, 2))),
                           (float(rng.uniform(0.8, 1.3)), float(rng.uniform(0.8, 1.3))), "tension_only")
                 for _ in range(n)]
        cases.append(("heterogeneous", to.Manipulator(segs), 0.45 * n, 0.2))
    for label, m, dx, dy in cases:
        lin = m.with_spring("linear")
        t_to, eqs = _median_time(lambda: to.find_equilibria(m, dx, dy), reps)
        t_lin, leqs = _median_time(lambda: to.find_equilibria(lin, dx, dy), reps)
        try:
            t_th, theqs = _median_time(lambda: to.find_equilibria(m, dx, dy, method="homotopy"), 1)
            pats = theqs.message.split(" from ")[1].split(" taut")[0] + " / " + \
                theqs.message.split("patterns of ")[1].split(" ")[0]
            th = f"{t_th * 1e3:.0f} ms | {len(theqs)} | {theqs.status} | {pats}"
            t_hom, heqs = _median_time(lambda: to.find_equilibria(lin, dx, dy, method="homotopy"), 1)
            hom = f"{t_hom * 1e3:.0f} ms | {len(heqs)} | {heqs.status}"
        except to.HomotopyUnavailableError:
            th, hom = "(no PHCpack) | - | - | -", "(no PHCpack) | - | -"
        on = sum(bool(e.at_stop.any()) for e in eqs)
        print(f"| {label} | {m.n} | {dx:g}, {dy:g} | {t_to * 1e3:.0f} ms | {len(eqs)} ({on}) | {th} | "
              f"{t_lin * 1e3:.1f} ms | {len(leqs)} | {hom} |")
    print()
    _linear_stops(reps)
    return 0


def _linear_stops(reps: int) -> None:
    """A third table: the linear law's every-equilibrium set with the equilibria resting on a stop
    (``find_equilibria(stops=True)``), beside its default (the open range), by the search and by the homotopy."""
    print("| linear law, every equilibrium | n | dx, dy | default search (median) | count | stops=True search | "
          "count (on a stop) | default homotopy | count | stops=True homotopy | count (on a stop) | status |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for label, m, dx, dy in (("paper's chain", to.Manipulator.uniform(4), 1.0, 0.1),
                             ("paper's chain", to.Manipulator.uniform(4), 3.3, 0.1),
                             ("paper's segments", to.Manipulator.uniform(3), 0.9, 0.3)):
        t_d, d = _median_time(lambda: to.find_equilibria(m, dx, dy), reps)
        t_s, s = _median_time(lambda: to.find_equilibria(m, dx, dy, stops=True), reps)
        try:
            t_hd, hd = _median_time(lambda: to.find_equilibria(m, dx, dy, method="homotopy"), 1)
            t_hs, hs = _median_time(lambda: to.find_equilibria(m, dx, dy, method="homotopy", stops=True), 1)
            hom = (f"{t_hd * 1e3:.0f} ms | {len(hd)} | {t_hs * 1e3:.0f} ms | {len(hs)} "
                   f"({sum(bool(e.at_stop.any()) for e in hs)}) | {hs.status}")
        except to.HomotopyUnavailableError:
            hom = "(no PHCpack) | - | - | - | -"
        print(f"| {label} | {m.n} | {dx:g}, {dy:g} | {t_d * 1e3:.1f} ms | {len(d)} | {t_s * 1e3:.0f} ms | {len(s)} "
              f"({sum(bool(e.at_stop.any()) for e in s)}) | {hom} |")


if __name__ == "__main__":
    raise SystemExit(main())
