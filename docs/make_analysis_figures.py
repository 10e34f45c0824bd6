"""The figures of the analysis pages (docs/analyses.md) that docs/figures.py does not draw.

Run from the repository root: ``python docs/make_analysis_figures.py`` (about half a minute). Writes
``docs/img/{equilibrium,buckling,stiffness,rest,limit_load,boundary,design,plan,simulation,force_estimate,
stiffness_design,load_capacity}.png`` at a low resolution (each well under 100 kB; they are committed).
Every figure is the library's numbers for the example of its section, drawn with
``tensegrity_opt.applications.plots`` where it has the figure, with plain matplotlib (its object API, no
pyplot, on ``plots.new_figure``) otherwise.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

import tensegrity_opt as to
from tensegrity_opt.applications import plots

OUT = Path(__file__).resolve().parent / "img"
DPI = 50
PAPER = to.Manipulator.uniform(4, a=1, b=1, k=1, L0=1)
BISTABLE = to.Manipulator.uniform(3, a=0.5, b=1, k=1, L0=1)


def _save(fig, name: str) -> None:
    path = plots.save(fig, OUT / f"{name}.png", dpi=DPI)
    print(f"wrote {path} ({path.stat().st_size} bytes)")


def _chain(ax, m: to.Manipulator, q, **kw) -> None:
    g = plots.chain_geometry(m, q)
    ax.plot(*g["centerline"].T, "-o", ms=3, **kw)


def equilibrium() -> None:
    eqs = [to.solve_equilibrium(PAPER, 0.1), to.solve_equilibrium(PAPER, 1.0, 0.5)]
    _save(plots.plot_shapes(eqs, PAPER, 0.1, ncols=2, panel_width=3.4), "equilibrium")


def buckling() -> None:
    bk = to.critical_force(PAPER)
    fig = plots.new_figure((6.4, 5.4))
    axes = fig.subplots(3, 1, sharex=True)
    for ax, md in zip(axes, bk.modes):
        _chain(ax, PAPER, 0.35 * md.q / np.abs(md.q).max(), color="tab:green" if md.stable else "tab:red")
        ax.set_title(f"{md.shape} {md.signs} ({'stable' if md.stable else 'unstable'}): P = {md.load:.6f}, "
                     f"mu_eq = {md.energy_factor:.6f}", fontsize=9)
        ax.set_ylim(-1.2, 1.2)
        ax.set_ylabel("y")
    axes[-1].set_xlabel("x")
    fig.suptitle("Buckling modes of the guided paper chain (amplitude arbitrary)", fontsize=10)
    _save(fig, "buckling")


def stiffness() -> None:
    dx = np.linspace(0.02, 1.5, 30)
    eqs = to.solve_equilibria_batch(PAPER, [(d, 0.0) for d in dx])
    K = np.array([to.cartesian_stiffness(PAPER, e) for e in eqs])
    fig = plots.new_figure((6.4, 3.6))
    ax = fig.subplots()
    for (i, j), name in zip([(0, 0), (0, 1), (1, 1)], ["Kxx", "Kxy", "Kyy"]):
        ax.plot(dx, K[:, i, j], label=name)
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.set_xlabel("dx")
    ax.set_ylabel("tangent stiffness dF/d(x, y)")
    ax.set_title("Cartesian stiffness along the U branch (paper chain)", fontsize=10)
    ax.legend()
    _save(fig, "stiffness")


def rest() -> None:
    wells = to.find_equilibria_under_force(BISTABLE, stable_only=True)
    _save(plots.plot_shapes(wells, BISTABLE, 0.0, ncols=4, panel_width=2.6), "rest")


def limit_load() -> None:
    bent = to.Manipulator([to.Segment(1, 1, 1, (1.0, 1.02))] + [to.Segment(1, 1, 1, 1.0)] * 3)
    ll = to.limit_load(bent, direction=(-1.0, 0.0), boundary="free", max_load=0.2)
    _save(plots.plot_limit_load(ll, bent), "limit_load")


def boundary() -> None:
    sb = to.stability_boundary(PAPER, "guided", "asymmetry", direction=(-1.0, 0.0), p_min=-0.1, p_max=0.1)
    _save(plots.plot_boundary(sb, PAPER, control="guided"), "boundary")


def design() -> None:
    d = to.maximize_critical_force(PAPER, vary=("k",), bounds={"k": (0.2, 5.0)}, budget={"k": 4.0})
    k0 = [s.k1 for s in PAPER.segments]
    k1 = [s.k1 for s in d.manipulator.segments]
    fig = plots.new_figure((6.0, 3.4))
    ax = fig.subplots()
    idx = np.arange(1, PAPER.n + 1)
    ax.bar(idx - 0.18, k0, 0.36, label=f"uniform: P = {-d.initial_critical_force:.4f}")
    ax.bar(idx + 0.18, k1, 0.36, label=f"optimal: P = {-d.critical_force:.4f}")
    ax.set_xticks(idx)
    ax.set_xlabel("segment (from the base)")
    ax.set_ylabel("spring stiffness k")
    ax.set_title("Strongest chain for a stiffness budget sum k = 4 (guided)", fontsize=10)
    ax.legend(fontsize=8)
    _save(fig, "design")


def plan() -> None:
    targets = [(7.6, 0.5), (7.5, 0.75), (7.4, 1.0), (7.3, 1.25)]
    p = to.plan_preloads(PAPER, targets, loads=(0.0, -0.02), margin=0.01)
    _save(plots.plot_preload_plan(p, PAPER, margin=0.01), "plan")


def simulation() -> None:
    fy = np.concatenate([np.linspace(0, 0.3, 31), np.linspace(0.3, -0.3, 61)[1:], np.linspace(-0.3, 0, 31)[1:]])
    sim = to.simulate(BISTABLE, loads=np.column_stack([0 * fy, fy]))
    _save(plots.plot_simulation(sim, BISTABLE), "simulation")


def force_estimate() -> None:
    eq = to.solve_equilibrium_under_force(PAPER, -0.1, 0.05)
    rng = np.random.default_rng(1)
    sigma = 1e-3
    est = [to.estimate_tip_force(PAPER, eq.q + sigma * rng.standard_normal(PAPER.n), sigma_q=sigma) for _ in range(200)]
    F = np.array([e.force for e in est])
    cov = est[0].covariance
    w, v = np.linalg.eigh(cov)
    t = np.linspace(0, 2 * np.pi, 200)
    ell = (v @ (np.sqrt(w)[:, None] * 2.0 * np.vstack([np.cos(t), np.sin(t)]))).T + [-0.1, 0.05]
    fig = plots.new_figure((5.2, 4.0))
    ax = fig.subplots()
    ax.plot(F[:, 0], F[:, 1], ".", ms=3, alpha=0.6, label="estimates, sigma_q = 1e-3 rad")
    ax.plot(*ell.T, "k-", lw=1, label="2 sigma ellipse (reported covariance)")
    ax.plot([-0.1], [0.05], "r+", ms=12, mew=2, label="true force (-0.1, 0.05)")
    ax.locator_params(nbins=5)
    ax.set_xlabel("fx")
    ax.set_ylabel("fy")
    ax.set_title("Tip force from joint angles (paper chain)", fontsize=10)
    ax.legend(fontsize=7)
    _save(fig, "force_estimate")


def stiffness_design() -> None:
    sd = to.preloads_for_stiffness(PAPER, (7.0, 1.0), eig_bounds=[0.04, 0.6])
    fig = plots.new_figure((8.4, 3.4))
    ax, bx = fig.subplots(1, 2)
    _chain(ax, sd.manipulator, sd.q, color="tab:green")
    ax.plot([7.0], [1.0], "kx", ms=8)
    ax.set_aspect("equal")
    ax.set_title("designed pose, tip at (7, 1)", fontsize=9)
    w, v = np.linalg.eigh(np.asarray(sd.K))
    t = np.linspace(0, 2 * np.pi, 200)
    for k, (lo, col) in enumerate([(0.04, "0.6"), (0.6, "0.6")]):
        bx.plot(lo * np.cos(t), lo * np.sin(t), ":", color=col)
    ell = (v @ (w[:, None] * np.vstack([np.cos(t), np.sin(t)]))).T
    bx.plot(*ell.T, "tab:blue", label=f"K: eigenvalues {w[0]:.3f}, {w[1]:.3f}")
    bx.set_aspect("equal")
    bx.set_title("tip stiffness (ellipse of K u); bounds dotted", fontsize=9)
    bx.legend(fontsize=7, loc="lower left")
    _save(fig, "stiffness_design")


def load_capacity() -> None:
    cap = to.load_capacity(BISTABLE, directions=24, max_load=1.0)
    fig = plots.new_figure((4.8, 4.8))
    ax = fig.add_subplot(projection="polar")
    lost = np.isfinite(cap.loads)
    ax.plot(cap.angles[lost], cap.loads[lost], "o-", ms=4, label="stability lost (fold)")
    ax.plot(cap.angles[~lost], np.full((~lost).sum(), 1.0), "x", color="0.5",
            label="none up to the joint limit or max_load = 1")
    ax.set_title("Load capacity of a bistable chain's rest pose, per direction", fontsize=9)
    ax.legend(fontsize=7, loc="lower left")
    _save(fig, "load_capacity")


FIGURES = {f.__name__: f for f in (equilibrium, buckling, stiffness, rest, limit_load, boundary, design, plan,
                                   simulation, force_estimate, stiffness_design, load_capacity)}


def main(names: list[str]) -> int:
    OUT.mkdir(exist_ok=True)
    for name in names or FIGURES:
        FIGURES[name]()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
