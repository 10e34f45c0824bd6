"""Vibration modes of an equilibrium (issue 41, item 4), against what a user would write.

``python -m benchmarks.modes [--quick]`` prints a markdown table: for the paper's chain with masses (n = 4) and longer
uniform chains (n = 10, 30, 100), each at its least-energy stable equilibrium with the tip held,

* ours: ``to.modes(m, eq)`` (the closed-form mass matrix, the Hessian of the potential in closed form, the tangent
  space of the tip by QR, ``scipy.linalg.eigh``), median time;
* the baseline a user would write: the mass matrix from the bodies' positions by central differences (every
  centroid and the payload, ``tests/support/reference_dynamics.py``'s geometry), the Hessian by central differences
  of the library's numpy gradient ``E'(q) - J^T F``, the null space of the tip Jacobian by ``scipy.linalg.null_space``,
  ``scipy.linalg.eigh``; median time;
* the largest relative difference of the frequencies (the two must agree to the differences' accuracy).
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np
import scipy.linalg as sla

import tensegrity_opt as to

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "support"))
import reference_dynamics as rd  # noqa: E402  (the bodies' geometry of the independent reference)
import reference_tension_only as ref  # noqa: E402


def _baseline(m: to.Manipulator, eq) -> np.ndarray:
    """Frequencies by differences: what a user without ``modes`` would write."""
    q, F = np.asarray(eq.q, float), np.asarray(eq.force, float)
    segs = [dict(d, mass=s.mass, inertia=s.inertia) for d, s in zip(ref.segs_of(m), m.segments)]
    h = 1e-5
    n = q.size
    K = np.empty((n, n))
    pos, ang = [], []
    for j in range(n):
        e = np.zeros(n)
        e[j] = h
        up, down = m.gradient(q + e) - m.jacobian(q + e).T @ F, m.gradient(q - e) - m.jacobian(q - e).T @ F
        K[:, j] = (up - down) / (2 * h)
        plus, minus = rd._bodies(segs, m.payload, q + e), rd._bodies(segs, m.payload, q - e)
        pos.append((np.array([b[2] for b in plus]) - np.array([b[2] for b in minus])) / (2 * h))
        ang.append((np.array([b[3] for b in plus]) - np.array([b[3] for b in minus])) / (2 * h))
    Jp, Jt = np.stack(pos, axis=-1), np.stack(ang, axis=-1)      # (bodies, 2, n), (bodies, n)
    bodies = rd._bodies(segs, m.payload, q)
    mass, inertia = np.array([b[0] for b in bodies]), np.array([b[1] for b in bodies])
    M = np.einsum("b,bin,bim->nm", mass, Jp, Jp) + np.einsum("b,bn,bm->nm", inertia, Jt, Jt)
    Z = sla.null_space(m.jacobian(q))
    w = sla.eigh(Z.T @ (0.5 * (K + K.T)) @ Z, Z.T @ M @ Z, eigvals_only=True)
    return np.sqrt(w)


def _median(f, reps: int) -> tuple[float, object]:
    times, out = [], None
    for _ in range(reps):
        t = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t)
    return float(np.median(times)), out


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m benchmarks.modes", description=__doc__.splitlines()[0])
    p.add_argument("--quick", action="store_true", help="fewer repetitions, no n = 100")
    args = p.parse_args(argv)
    reps = 5 if args.quick else 21
    cases = [("paper chain, mass 0.1", to.Manipulator.uniform(4, mass=0.1), 1.0, 0.0),
             ("uniform n = 10, mass 0.2, payload 0.5", to.Manipulator.uniform(10, mass=0.2, payload=0.5), 3.0, 1.0),
             ("uniform n = 30, mass 0.2", to.Manipulator.uniform(30, mass=0.2, inertia=0.01), 8.0, 2.0)]
    if not args.quick:
        cases.append(("uniform n = 100, mass 0.2", to.Manipulator.uniform(100, mass=0.2), 20.0, 5.0))
    print("| chain | n | dx, dy | ours `modes` (median) | differences + eigh (median) | ratio | lowest w (rad/s) | "
          "largest relative difference |")
    print("|---|---|---|---|---|---|---|---|")
    for label, m, dx, dy in cases:
        eq = to.solve_equilibrium(m, dx, dy)
        to.modes(m, eq)                                           # warm-up
        t_ours, md = _median(lambda: to.modes(m, eq), reps)
        t_base, w = _median(lambda: _baseline(m, eq), max(3, reps // 4))
        diff = float(np.max(np.abs(md.frequencies / w - 1.0)))
        print(f"| {label} | {m.n} | {dx:g}, {dy:g} | {t_ours * 1e3:.3f} ms | {t_base * 1e3:.1f} ms | "
              f"{t_base / t_ours:.0f}x | {md.frequencies[0]:.6g} | {diff:.1e} |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
