"""The figures of ``docs/figures.md``: our versions of the paper's Figs. 2, 4, 5 and 6, a few beyond it, and every
figure kind's default as its command draws it.

Run from the repository root::

    python docs/figures.py            # writes docs/img/<name>.png (plots.DPI, a 256-colour palette, each <= 150 kB)
    python docs/figures.py fig6_curve map     # only these
    python docs/figures.py default_branch     # one default: `tensegrity-opt plot branch -o ...`, as DEFAULTS says

Every figure's result is computed by the library (``tensegrity_opt``) and drawn by
``tensegrity_opt.applications.plots``; the parameters are the paper's (n = 4, a/b = 1, L0/b = 1,
k = 1, lengths in units of b) unless a figure says otherwise in its title.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

import tensegrity_opt as to  # noqa: E402
from tensegrity_opt.analyses.equilibria.landscape import landscape_span  # noqa: E402
from tensegrity_opt.applications import cli, plots  # noqa: E402
from tensegrity_opt.applications.sweeps import critical_load_map  # noqa: E402

OUT = ROOT / "docs" / "img"
DPI = plots.DPI
MAX_BYTES = 150_000
PAPER = to.Manipulator.uniform(4, a=1.0, b=1.0, k=1.0, L0=1.0)


def fig2_torque():
    """Fig. 2: torque-angle curves, monotonic and two-mode. a/b = 0.5, so condition (4) reads L0 > 1.5 b:
    K = k (b L0 - 2 (b^2 - a^2)) = -0.5, 0, +0.5 for L0 = 1, 1.5, 2 (L0 = 1: stable wells at q = +-1.682)."""
    segs = [to.Segment(0.5, 1.0, 1.0, L0) for L0 in (1.0, 1.5, 2.0)]
    return plots.plot_torque(segs)


def _landscape(dx: float, dy: float, pair: tuple[int, int]):
    """The landscape of the paper's chain over its reachable region (121 x 121) with every equilibrium."""
    land = to.energy_landscape(PAPER, dx, dy, pair=pair, grid=121, span=landscape_span(PAPER, dx, dy, pair))
    return plots.plot_landscape(land, to.find_equilibria(PAPER, dx, dy), PAPER, dx, dy)


def fig4_landscape():
    """Fig. 4: the energy E(q1, q4) of the paper's chain, q2, q3 solved, at dx = 0.1 (dy = 0): six equilibria."""
    return _landscape(0.1, 0.0, (0, 3))


def fig4_landscape_q1q2():
    """Fig. 4, its second landscape: E(q1, q2), q3, q4 solved, same chain and deflection."""
    return _landscape(0.1, 0.0, (0, 1))


def fig5_landscape():
    """Fig. 5: contours of E(q1, q4) for another configuration: the tip also moved sideways (dx = 0.3,
    dy = 0.2); the symmetry of Fig. 4 is broken."""
    return _landscape(0.3, 0.2, (0, 3))


def fig6_curve():
    """Fig. 6: the force-deflection curves Fx(dx, 0), Fy(dx, 0) of the paper's chain, with the paper's
    asymptotes after buckling (eq. 26, dotted): Fx ~ Fx0, Fy ~ alpha_5 / sqrt(b mu_x) sqrt(dx)."""
    fig = plots.plot_curve(to.force_deflection(PAPER, np.linspace(0.0, 1.0, 41)), PAPER)
    b = to.critical_force(PAPER)
    coef = float(b.modes[0].fy_coefficient)
    ax_fx, ax_fy = fig.axes[:2]
    fine = np.linspace(0.0, 1.0, 201)
    ax_fx.axhline(b.force, color="tab:green", ls=":", lw=1.4, zorder=2)
    ax_fx.annotate(f"eq. (20): $F_x^0$ = {b.force:.4f}", (1.0, b.force), textcoords="offset points", xytext=(-4, 6),
                   ha="right", fontsize=8, color="tab:green")
    ax_fy.plot(fine, coef * np.sqrt(fine), color="tab:green", ls=":", lw=1.4, zorder=2)
    ax_fy.annotate(f"eq. (26): $F_y \\approx {coef:.4f}\\sqrt{{\\delta_x}}$", (0.55, coef * np.sqrt(0.55)),
                   textcoords="offset points", xytext=(6, -14), fontsize=8, color="tab:green")
    return fig


def shapes():
    """Table 2: the chain in each of the six equilibria at dx = 0.1."""
    return plots.plot_shapes(to.find_equilibria(PAPER, 0.1), PAPER, 0.1)


def branch():
    """The guided straight chain under compression and the branches born at its critical loads."""
    brs = to.bifurcation_diagram(PAPER, np.zeros(4), "guided", depth=1, t_max=2.2, t_min=-0.2, max_points=400)
    return plots.plot_branches(brs, PAPER, x="t", y="q1")


def atlas():
    """The number of stable equilibria of the held tip over (dx, dy), n = 3, a = 0.5 (bistable segments)."""
    m = to.Manipulator.uniform(3, a=0.5)
    at = to.stability_atlas(m, np.linspace(0.2, 1.4, 13), np.linspace(-0.6, 0.6, 13))
    return plots.plot_atlas(at, m)


def map():  # noqa: A001 - the figure's name
    """The critical load over a and L0 (guided tip), the edge K = 0 of condition (4) drawn from the formula."""
    return plots.plot_map(critical_load_map(PAPER, "a", np.linspace(0.3, 1.5, 25), "L0", np.linspace(0.2, 2.5, 24)),
                          PAPER)


def _least_energy_path(m, dxs):
    """The least-energy equilibrium at each deflection (warm-started from the last)."""
    out, q = [], None
    for dx in dxs:
        e = to.solve_equilibrium(m, float(dx), q0=q)
        out.append(e)
        q = e.q if not e.at_stop.any() else None
    return out


def spring_laws():
    """The paper's chain past dx ~ 1.1 under both spring laws: the least energy, the tip force, the most compressed
    spring's stretch; where a spring first goes short of its rest length and where a joint first rests on its
    stop."""
    dxs = np.linspace(0.05, 4.0, 80)
    fig = plots.new_figure((11.0, 3.6))
    axes = fig.subplots(1, 3)
    for law, color in (("linear", "tab:blue"), ("tension_only", "tab:red")):
        eqs = _least_energy_path(PAPER.with_spring(law), dxs)
        stretch = np.array([e.spring_stretches.min() for e in eqs])
        label = {"linear": "linear (pushes)", "tension_only": "tension-only (goes slack)"}[law]
        axes[0].plot(dxs, [e.energy for e in eqs], color=color, label=label)
        axes[1].plot(dxs, [e.fx for e in eqs], color=color, label=label)
        axes[2].plot(dxs, stretch, color=color, label=label)
        stop = next((dx for dx, e in zip(dxs, eqs) if e.at_stop.any()), None)
        if stop is not None:
            for ax in axes:
                ax.axvline(stop, color=color, ls=":", lw=0.9)
    first = next(dx for dx, e in zip(dxs, _least_energy_path(PAPER, dxs)) if e.spring_stretches.min() < 0)
    for ax, ylabel in zip(axes, ("least energy $E$ (stiffness × length²)", "tip force $F_x$ (force)",
                                 "least stretch $L - L_0$ (length)")):
        ax.axvline(first, color="0.4", ls="--", lw=0.8)
        ax.set_xlabel("$\\delta_x$ (length)")
        ax.set_ylabel(ylabel, fontsize=9)
    axes[2].axhline(0.0, color="0.6", lw=0.6)
    axes[0].legend(fontsize=8)
    fig.suptitle("The paper's chain (n = 4, a = b = k = L0 = 1) under both spring laws: dashed, a spring first "
                 "shorter than its rest length;\ndotted, a joint first on its stop (the least-energy equilibrium at "
                 "each deflection)", fontsize=9)
    return fig


def spring_laws_shapes():
    """The least-energy equilibrium at dx = 2 under the linear law (left: spring 3.2 pushes) and the tension-only
    law (right: spring 3.2 slack, joint 3 on its stop)."""
    eqs = [to.solve_equilibrium(PAPER.with_spring(law), 2.0) for law in ("linear", "tension_only")]
    return plots.plot_shapes(eqs, PAPER, 2.0)


FIGURES = {f.__name__: f for f in (fig2_torque, fig4_landscape, fig4_landscape_q1q2, fig5_landscape, fig6_curve,
                                    shapes, branch, atlas, map, spring_laws, spring_laws_shapes)}

#: Every figure kind's default (``tensegrity-opt plot --help``), drawn by its command: ``default_<name>.png`` is
#: ``tensegrity-opt plot <these arguments> -o default_<name>.png``, at the command's own resolution. ``modes`` needs
#: a mass (the paper's chain with 0.1 per segment), ``holding`` a chain with weight (the 6-segment arm of
#: ``docs/model.md``, "Weights and loads"). ``map``,
#: ``imperfection``, ``plan`` and ``simulation`` need their inputs (the examples of ``tensegrity-opt plot KIND
#: --help``); the branch diagram also with ``--depth 2`` and on the axes of the paper's Fig. 6.
DEFAULTS = {
    "curve": ["curve"],
    "landscape": ["landscape"],
    "shapes": ["shapes"],
    "modes": ["modes", "--mass", "0.1", "--dx", "1"],
    "holding": ["holding", "--n", "6", "--a", "0.04", "--b", "0.05", "--k", "3000", "--L0", "0.05", "--mass", "0.05",
                "--payload", "0.1", "--max-angle", "0.05", "--directions", "16"],
    "torque": ["torque"],
    "map": ["map", "--x", "k", "0.5", "2", "16", "--y", "L0", "0.5", "2.5", "21"],
    "branch": ["branch"],
    "branch_depth2": ["branch", "--depth", "2"],
    "branch_fig6": ["branch", "--depth", "2", "--x", "dx", "--y", "fx"],
    "limit_load": ["limit-load"],
    "imperfection": ["imperfection", "--amplitudes", "0", "0.005", "0.01", "0.02", "0.03", "0.04", "0.061"],
    "boundary": ["boundary"],
    "atlas": ["atlas"],
    "plan": ["plan", "--line", "7.9", "0.2", "7.3", "1.4", "13", "--margin", "0.05"],
    "simulation": ["simulation", "--n", "3", "--a", "0.5", "--load-cycle", "0.3", "--steps", "121"],
}


def default_command(name: str) -> str:
    """The command line that draws ``default_<name>.png``."""
    return " ".join(["tensegrity-opt", "plot", *DEFAULTS[name], "-o", f"default_{name}.png"])


def _draw(name: str) -> Path:
    """Write ``docs/img/<name>.png``: a figure of :data:`FIGURES`, or (``default_<kind>``) the command's own."""
    path = OUT / f"{name}.png"
    if name in FIGURES:
        return plots.save(FIGURES[name](), path, dpi=DPI)
    kind = name.removeprefix("default_")
    if cli.main(["plot", *DEFAULTS[kind], "-o", str(path)]) != 0:
        raise SystemExit(f"{default_command(kind)} failed")
    return path


NAMES = [*FIGURES, *(f"default_{k}" for k in DEFAULTS)]


def _palette(path: Path) -> None:
    """Rewrite the PNG with a 256-colour palette (a third of the bytes; the figures have few colours)."""
    from PIL import Image

    with Image.open(path) as im:
        rgb = im.convert("RGB")
    rgb.quantize(colors=256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE).save(path, optimize=True)


def main(names: list[str]) -> int:
    OUT.mkdir(parents=True, exist_ok=True)
    for name in names or NAMES:
        if name not in NAMES:
            print(f"unknown figure {name!r}; one of {', '.join(NAMES)}", file=sys.stderr)
            return 2
        path = _draw(name)
        _palette(path)
        size = path.stat().st_size
        print(f"wrote {path.relative_to(ROOT)} ({size} bytes)")
        if size > MAX_BYTES:
            print(f"  {name}.png is larger than {MAX_BYTES} bytes", file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
