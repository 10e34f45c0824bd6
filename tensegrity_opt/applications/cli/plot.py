"""Command line figures: ``tensegrity-opt plot curve|landscape|shapes|torque|map|branch|limit-load|imperfection|
boundary|atlas|plan|simulation ... -o fig.png|fig.svg``.

:func:`add_plot_parser` adds the ``plot`` subcommand to the ``tensegrity-opt`` parser
(:func:`tensegrity_opt.applications.cli.build_parser`). Every kind takes the manipulator options of the
other commands (``--n --a --b --k --L0`` uniform, the paper's chain by default, or
``--manipulator FILE.json``), ``--json`` and ``-o/--output`` (the format follows the suffix);
its ``func(args, m)`` computes the result with the library, draws it with
:mod:`tensegrity_opt.applications.plots` and returns ``(data, text)`` as the other commands do, so
``cli.main`` prints one line (or JSON) and maps errors to one line on stderr and exit status 2.

``python -m tensegrity_opt.applications.cli.plot KIND ...`` runs the same command on its own.

Examples::

    tensegrity-opt plot curve --start 0 --stop 2 --num 41 -o curve.png
    tensegrity-opt plot curve --start 0 --stop 1 --num 21 --branch all -o branches.svg
    tensegrity-opt plot landscape --dx 0.1 --pair 0 3 -o landscape.png
    tensegrity-opt plot shapes --dx 0.1 -o shapes.svg
    tensegrity-opt plot torque --vary L0 --values 0.5 1 1.5 2 -o torque.png
    tensegrity-opt plot map --x k 0.5 2 16 --y L0 0.5 2.5 21 -o map.png
    tensegrity-opt plot branch --control guided --t-max 2 --start-q 0 0 0 0 --y fy -o branch.png
    tensegrity-opt plot branch --control guided --t-max 2 --start-q 0 0 0 0 --depth 1 --x q1 --y t -o diagram.svg
    tensegrity-opt plot limit-load --boundary guided --start-q 0 0 0 0 -o limit.png
    tensegrity-opt plot limit-load --no-arms -o path.png
    tensegrity-opt plot imperfection --amplitudes 0 0.005 0.01 0.02 0.04 0.061 -o imperfection.png
    tensegrity-opt plot boundary --parameter asymmetry -o boundary.png
    tensegrity-opt plot atlas --n 3 --a 0.5 --dx 0.2 1.4 7 --dy -0.6 0.6 7 -o atlas.png
    tensegrity-opt plot plan --line 7.9 0.2 7.3 1.4 13 --margin 0.05 -o plan.png
    tensegrity-opt plot simulation --n 3 --a 0.5 --load-cycle 0.3 --steps 121 -o loop.svg

The loading-path kinds take the options of the ``branch``, ``limit-load``, ``imperfection`` and ``boundary`` commands,
``atlas`` those of the ``atlas`` command (:mod:`.paths`), ``plan`` and ``simulation`` those of the ``plan`` and
``simulate`` commands (:mod:`.control`).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

import numpy as np

from ...analyses.equilibria.all_equilibria import find_equilibria
from ...analyses.equilibria.landscape import energy_landscape, landscape_span
from ...analyses.paths.curves import force_deflection
from ...analyses.paths.limit_load import limit_arms
from ...errors import InvalidParameterError, UnsupportedError
from ...model.manipulator import Manipulator
from ..plots.paths import BRANCH_DEFAULT_X, BRANCH_DEFAULT_Y  # no matplotlib: it is imported by each figure
from ..plots.style import DPI
from ..sweeps.critical_map import critical_load_map
from ..sweeps.spec import DESIGN_VARIABLES
from .common import (
    HELP_FORMAT,
    Parser,
    add_analysis_options,
    add_curve_options,
    add_deflection_options,
    note,
    positive_int,
    run_command,
)
from .control import add_plan_options, add_simulate_options, plan_from_args, simulation_from_args
from .paths import (
    add_atlas_options,
    add_boundary_options,
    add_branch_options,
    add_imperfection_options,
    add_limit_load_options,
    atlas_from_args,
    boundary_from_args,
    branches_from_args,
    imperfection_from_args,
    limit_load_from_args,
)

__all__ = ["add_plot_parser", "main", "KINDS"]

KINDS = ("curve", "landscape", "shapes", "modes", "holding", "torque", "map", "branch", "limit-load", "imperfection",
         "boundary",
         "atlas", "plan", "simulation")
#: Axis quantities of ``plot branch`` (``plots.BRANCH_QUANTITIES``; also ``q1``, ``q2``, ...).
_QUANTITY_HELP = ("t, fx, fy (tip force), dx, dy (deflection), x, y (tip), u (tip displacement along the control "
                  "direction), phi (end angle q1 + ... + qn), energy, s (arclength) or q1..qn (a joint angle)")


def _output(value: str) -> str:
    if Path(value).suffix.lower() not in (".png", ".svg"):
        raise argparse.ArgumentTypeError(f"the figure file must end in .png or .svg, got {value!r}")
    return value


def _common(sp: argparse.ArgumentParser) -> None:
    """The manipulator options of the other commands, plus the figure's output options."""
    add_analysis_options(sp, "print JSON instead of a line of text")
    sp.add_argument("-o", "--output", type=_output, required=True, metavar="FIG.png|FIG.svg",
                    help="figure file; PNG or SVG by its suffix")
    sp.add_argument("--dpi", type=float, default=float(DPI), help="resolution of a PNG (dots per inch)")


def _axis(spec: list[str], name: str) -> tuple[str, np.ndarray]:
    param = spec[0]
    if param not in DESIGN_VARIABLES:
        raise InvalidParameterError(f"--{name}: the parameter must be one of {', '.join(DESIGN_VARIABLES)}, "
                                    f"got {param!r}", field=name)
    try:
        start, stop, num = float(spec[1]), float(spec[2]), int(spec[3])
    except ValueError:
        raise InvalidParameterError(f"--{name} takes PARAM START STOP NUM, got {' '.join(spec)!r}",
                                    field=name) from None
    return param, np.linspace(start, stop, num)


def _render(args: argparse.Namespace, fig: Any, kind: str, extra: dict[str, Any]) -> tuple[dict[str, Any], str]:
    from .. import plots

    path = plots.save(fig, args.output, dpi=args.dpi)
    fmt = path.suffix.lower().lstrip(".")
    size = path.stat().st_size
    data = {"kind": kind, "output": str(path), "format": fmt, "bytes": size, **extra}
    return data, f"wrote {path} ({kind}, {fmt.upper()}, {size} bytes)"


def _plots():
    try:
        import matplotlib.figure  # noqa: F401  (fail here, not after a long solve, when it is missing)

        from .. import plots
    except ImportError as exc:
        raise UnsupportedError(f"figures need matplotlib ({exc}): python3 -m pip install matplotlib",
                               field="matplotlib") from None
    return plots


def _cmd_curve(args: argparse.Namespace, m: Manipulator) -> tuple[dict[str, Any], str]:
    plots = _plots()
    c = force_deflection(m, np.linspace(args.start, args.stop, args.num), args.dy, branch=args.branch)
    fig = plots.plot_curve(c, m)
    out = _render(args, fig, "curve", {"points": int(c.dx.size), "jumps": [j.kind for j in c.jumps],
                                       "branches": len(c.branches), "complete": c.success,
                                       "note": "" if c.success else c.message})
    if not c.success:    # the figure holds the points computed; the reader is told where and why it ends
        note(c.message)
    return out


def _cmd_landscape(args: argparse.Namespace, m: Manipulator) -> tuple[dict[str, Any], str]:
    plots = _plots()
    eqs = find_equilibria(m, args.dx, args.dy) if m.n == 4 else None      # n != 4: the landscape refuses it
    pair = tuple(args.pair)
    span = landscape_span(m, args.dx, args.dy, pair) if args.span is None else (None if args.span <= 0 else args.span)
    land = energy_landscape(m, args.dx, args.dy, pair=pair, grid=args.grid, span=span)
    fig = plots.plot_landscape(land, eqs, m, args.dx, args.dy)
    return _render(args, fig, "landscape", {"equilibria": [{"shape": e.shape, "kind": e.kind,
                                                            "q": e.q.tolist()} for e in eqs]})


def _cmd_shapes(args: argparse.Namespace, m: Manipulator) -> tuple[dict[str, Any], str]:
    plots = _plots()
    eqs = find_equilibria(m, args.dx, args.dy)
    fig = plots.plot_shapes(eqs, m, args.dx, args.dy, max_panels=args.max_panels, spring_colors=args.spring_colors)
    return _render(args, fig, "shapes", {"equilibria": [{"shape": e.shape, "kind": e.kind, "q": e.q.tolist()}
                                                        for e in eqs]})


def _cmd_modes(args: argparse.Namespace, m: Manipulator) -> tuple[dict[str, Any], str]:
    from ...analyses.equilibria.equilibrium import solve_equilibrium_under_force
    from ...analyses.equilibria.least_energy import solve_equilibrium
    from ...analyses.equilibria.modes import modes

    plots = _plots()
    if args.fx is not None or args.fy is not None:
        eq = solve_equilibrium_under_force(m, args.fx or 0.0, args.fy or 0.0)
    else:
        eq = solve_equilibrium(m, args.dx, args.dy)
    md = modes(m, eq, tip=args.tip)
    fig = plots.plot_modes(md, m, excursion=args.excursion, max_panels=args.max_panels)
    return _render(args, fig, "modes", {"frequencies": [v if v == v else None for v in md.frequencies.tolist()],
                                        "status": md.status})


def _cmd_holding(args: argparse.Namespace, m: Manipulator) -> tuple[dict[str, Any], str]:
    from ...analyses.design.holding import holding_map

    plots = _plots()
    hmap = holding_map(m, args.directions, vary=args.vary, margin=args.margin, max_angle=args.max_angle)
    fig = plots.plot_holding(hmap, m)
    return _render(args, fig, "holding", {"elevations": plots.elevations(hmap).tolist(),
                                          "outcomes": list(hmap.outcomes), "status": hmap.status})


def _cmd_torque(args: argparse.Namespace, m: Manipulator) -> tuple[dict[str, Any], str]:
    plots = _plots()
    if args.vary:
        if not args.values:
            raise InvalidParameterError("--vary needs --values V1 V2 ...", field="values")
        base = m.segments[0]
        segs = [base.replace(**{args.vary: v}) for v in args.values]
    else:
        segs = list(m.segments)
    q = None
    if args.qmin is not None or args.qmax is not None:
        lim = min(s.joint_limit for s in segs)
        q = np.linspace(-lim if args.qmin is None else args.qmin, lim if args.qmax is None else args.qmax, args.num)
    fig = plots.plot_torque(segs, q, num=args.num)
    return _render(args, fig, "torque", {"segments": [s.to_dict() for s in plots.distinct_segments(segs)]})


def _cmd_map(args: argparse.Namespace, m: Manipulator) -> tuple[dict[str, Any], str]:
    plots = _plots()
    px, xs = _axis(args.x, "x")
    py, ys = _axis(args.y, "y")
    fig = plots.plot_map(critical_load_map(m, px, xs, py, ys, args.boundary), m)
    return _render(args, fig, "map", {"x": {"param": px, "values": xs.tolist()},
                                      "y": {"param": py, "values": ys.tolist()}, "boundary": args.boundary})


def _cmd_branch(args: argparse.Namespace, m: Manipulator) -> tuple[dict[str, Any], str]:
    plots = _plots()
    res = branches_from_args(args, m)
    fig = plots.plot_branches(res, x=args.x, y=args.y, m=m)
    brs = [res] if not isinstance(res, list) else res
    return _render(args, fig, "branch", {"branches": len(brs), "points": [len(b) for b in brs],
                                         "status": [b.status for b in brs],
                                         "events": [[e.kind for e in b.events] for b in brs]})


def _cmd_limit_load(args: argparse.Namespace, m: Manipulator) -> tuple[dict[str, Any], str]:
    plots = _plots()
    r = limit_load_from_args(args, m)
    arms = limit_arms(r, timeout=args.timeout) if args.arms else []
    fig = plots.plot_limit_load(r, m=m, arms=arms)
    return _render(args, fig, "limit-load", {"limit": r.kind, "load": r.load,
                                             "reason": None if r.kind != "none" else r.status,
                                             "quasi_buckling_load": r.quasi_buckling_load,
                                             "quasi_buckling_stiffness": r.quasi_buckling_stiffness,
                                             "arms": [{"end": a.events[0].kind if a.events else a.status,
                                                       "t_end": float(a.t[-1])} for a in arms]})


def _cmd_imperfection(args: argparse.Namespace, m: Manipulator) -> tuple[dict[str, Any], str]:
    plots = _plots()
    r = imperfection_from_args(args, m)
    fig = plots.plot_imperfection(r, m)
    return _render(args, fig, "imperfection", {"amplitudes": int(r.amplitudes.size), "status": r.status,
                                               "kinds": list(r.kinds), "bifurcation": r.bifurcation,
                                               "law_exponent": r.law_exponent})


def _cmd_boundary(args: argparse.Namespace, m: Manipulator) -> tuple[dict[str, Any], str]:
    plots = _plots()
    b = boundary_from_args(args, m)
    fig = plots.plot_boundary(b, m=m)
    return _render(args, fig, "boundary", {"boundary": str(b.kind), "points": int(np.size(b.p)),
                                           "cusps": len(list(b.cusps or [])), "status": b.status})


def _cmd_atlas(args: argparse.Namespace, m: Manipulator) -> tuple[dict[str, Any], str]:
    plots = _plots()
    at = atlas_from_args(args, m)
    fig = plots.plot_atlas(at, m=m)
    return _render(args, fig, "atlas", {"targets": int(at.dx.size * at.dy.size), "status": at.status,
                                        "max_stable": int(at.n_stable.max()), "switches": len(at.switches),
                                        "branch_ends": len(at.branch_ends)})


def _cmd_plan(args: argparse.Namespace, m: Manipulator) -> tuple[dict[str, Any], str]:
    plots = _plots()
    p = plan_from_args(args, m)
    fig = plots.plot_preload_plan(p, m, margin=args.margin)
    return _render(args, fig, "plan", {"steps": len(p.method), "status": p.status,
                                       "feasible": int(np.sum(p.feasible)), "verified": int(np.sum(p.verified))})


def _cmd_simulation(args: argparse.Namespace, m: Manipulator) -> tuple[dict[str, Any], str]:
    plots = _plots()
    sim = simulation_from_args(args, m)
    fig = plots.plot_simulation(sim, m)
    return _render(args, fig, "simulation", {"samples": sim.steps, "done": len(sim), "status": sim.status,
                                             "snaps": len(sim.snaps), "events": [e.kind for e in sim.events]})


def _add_branch_plot_options(k: argparse.ArgumentParser) -> None:
    """The ``branch`` command's options and the diagram's axes."""
    add_branch_options(k)
    k.add_argument("--x", default=BRANCH_DEFAULT_X, help=f"horizontal axis: {_QUANTITY_HELP}")
    k.add_argument("--y", default=BRANCH_DEFAULT_Y, help="vertical axis, as --x (default: the end angle, a bifurcation "
                                                  "diagram; the axis of t shows a margin past the events)")


def _add_limit_load_plot_options(k: argparse.ArgumentParser) -> None:
    """The ``limit-load`` command's options and whether to draw the buckled arms."""
    add_limit_load_options(k)
    k.add_argument("--arms", action=argparse.BooleanOptionalAction, default=True,
                   help="at a bifurcation, also draw the buckled arms leaving it (to their first fold or joint "
                        "limit), against the end angle; --no-arms: the path only, against the tip displacement "
                        "along the load")


#: The kinds that draw the result of another command, with that command's options: ``(kind, help, options, func)``.
_RESULT_KINDS = (
    ("branch", "branch diagram: one branch (or --depth: the bifurcation diagram) by Morse index, events marked",
     _add_branch_plot_options, _cmd_branch),
    ("limit-load", "the load path of a limit load, the limit point and quasi-buckling load marked, at a "
     "bifurcation the buckled arms", _add_limit_load_plot_options, _cmd_limit_load),
    ("imperfection", "the imperfection-sensitivity curve: the limit load against the amplitude, a marker per kind, "
     "the fitted small-imperfection law", add_imperfection_options, _cmd_imperfection),
    ("boundary", "a stability boundary: critical t against the second parameter, cusps marked", add_boundary_options,
     _cmd_boundary),
    ("atlas", "the stability atlas: stable equilibria over (dx, dy), switch and branch-end curves", add_atlas_options,
     _cmd_atlas),
    ("plan", "a rest-length plan: rest lengths, margin and tip path per step, infeasible steps shaded",
     add_plan_options, _cmd_plan),
    ("simulation", "the hysteresis loop of a quasi-static simulation, the snaps as arrows", add_simulate_options,
     _cmd_simulation),
)


def add_plot_parser(subparsers: Any) -> argparse.ArgumentParser:
    """Add ``plot KIND`` (:data:`KINDS`) to ``subparsers`` (``add_subparsers()``'s result).

    Each kind sets ``func(args, m) -> (data, text)`` like the other commands of ``cli.py``.
    Returns the ``plot`` parser.
    """
    sp = subparsers.add_parser(
        "plot", help="figures (PNG/SVG): force-deflection curve, energy landscape, equilibrium shapes, "
                     "torque curves, critical-load map, loading paths, stability atlas, rest-length plan, simulation",
        description="Draw a figure with matplotlib and write it to -o FILE (.png or .svg).")
    kinds = sp.add_subparsers(dest="kind", required=True, metavar="KIND")

    k = kinds.add_parser("curve", help="force-deflection curves Fx, Fy with their jumps (Fig. 6)")
    _common(k)
    add_curve_options(k, num=41, number=float)
    k.add_argument("--branch", choices=("stable", "all"), default="stable",
                   help="'all': every branch, unstable parts dashed")
    k.set_defaults(func=_cmd_curve)

    k = kinds.add_parser("landscape", help="energy contours E(q_i, q_j) with every equilibrium (n = 4, Figs. 4-5)")
    _common(k)
    add_deflection_options(k, number=float)
    k.add_argument("--pair", type=int, nargs=2, default=[0, 3], metavar=("I", "J"),
                   help="the two grid joints, 0-based (0 3: the paper's q1, q4)")
    k.add_argument("--grid", type=positive_int, default=61,
                   help="points per axis (default 61; the region's boundary is drawn on a grid 4x finer)")
    k.add_argument("--span", type=float, default=None,
                   help="half-width of the axes (rad); None: the reachable region; 0: the physical range")
    k.set_defaults(func=_cmd_landscape)

    k = kinds.add_parser("shapes", help="the chain drawn in every equilibrium, coloured by stability")
    _common(k)
    add_deflection_options(k, number=float)
    k.add_argument("--max-panels", type=positive_int, default=24, help="draw at most this many (lowest energies)")
    k.add_argument("--spring-colors", choices=("state", "tension"), default="state",
                   help="state: taut solid, pushing red dashed, slack grey dotted; tension: coloured by force")
    k.set_defaults(func=_cmd_shapes)

    k = kinds.add_parser("modes", help="the vibration modes of an equilibrium (needs --mass or --payload)")
    _common(k)
    add_deflection_options(k, number=float)
    k.add_argument("--fx", type=float, default=None, help="a dead tip force instead of the deflection")
    k.add_argument("--fy", type=float, default=None, help="sideways dead tip force")
    k.add_argument("--tip", choices=("held", "loaded"), default=None,
                   help="the modes with the tip held or free under its load (default: as the equilibrium is posed)")
    k.add_argument("--excursion", type=float, default=0.3, help="largest joint excursion drawn (rad)")
    k.add_argument("--max-panels", type=positive_int, default=8, help="draw at most this many modes (the lowest)")
    k.set_defaults(func=_cmd_modes)

    k = kinds.add_parser("holding", help="the chain under its weight as its base turns: its sagged shapes and the "
                                         "least stiffness or preload holding it (needs --mass or --payload)")
    _common(k)
    k.add_argument("--directions", type=positive_int, default=12,
                   help="gravity directions (base orientations) over a full turn")
    k.add_argument("--vary", choices=("k", "L0"), default="k", help="design the stiffnesses or the rest lengths")
    k.add_argument("--margin", type=float, default=1e-3, help="required stability margin (torque / rad)")
    k.add_argument("--max-angle", type=float, default=None, help="the sag allowed (rad); default anywhere in range")
    k.set_defaults(func=_cmd_holding)

    k = kinds.add_parser("torque", help="torque-angle curves M(q) of the segments (Fig. 2)")
    _common(k)
    k.add_argument("--vary", choices=DESIGN_VARIABLES, help="one curve per value of this parameter (first segment)")
    k.add_argument("--values", type=float, nargs="+", metavar="V", help="the values for --vary")
    k.add_argument("--qmin", type=float, default=None,
                   help="first joint angle (rad); None: the lower end of the physical range")
    k.add_argument("--qmax", type=float, default=None,
                   help="last joint angle (rad); None: the upper end of the physical range")
    k.add_argument("--num", type=positive_int, default=401, help="number of angles, evenly spaced")
    k.set_defaults(func=_cmd_torque)

    k = kinds.add_parser("map", help="critical load over two design parameters (a, b, k, L0)")
    _common(k)
    k.add_argument("--x", nargs=4, required=True, metavar=("PARAM", "START", "STOP", "NUM"),
                   help="horizontal axis, e.g. --x k 0.5 2 16")
    k.add_argument("--y", nargs=4, required=True, metavar=("PARAM", "START", "STOP", "NUM"),
                   help="vertical axis, e.g. --y L0 0.5 2.5 21")
    k.add_argument("--boundary", choices=("guided", "free"), default="guided",
                   help="tip guided (y held, the paper's case) or free")
    k.set_defaults(func=_cmd_map)

    for name, help_, add_options, func in _RESULT_KINDS:
        k = kinds.add_parser(name, formatter_class=HELP_FORMAT, help=help_)
        _common(k)
        add_options(k)
        k.set_defaults(func=func)
    return sp


def main(argv: list[str] | None = None) -> int:
    """``python -m tensegrity_opt.applications.cli.plot KIND ...``: the ``plot`` command on its own."""
    p = Parser(prog="tensegrity-opt")
    add_plot_parser(p.add_subparsers(dest="command", required=True))
    return run_command(p, ["plot", *(sys.argv[1:] if argv is None else argv)])


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
