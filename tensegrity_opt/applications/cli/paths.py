"""Command line loading paths and the stability atlas: ``tensegrity-opt rest|branch|limit-load|imperfection|boundary|
atlas ...``.

:func:`add_path_parsers` adds the six commands to the ``tensegrity-opt`` parser; each sets
``func(args, m) -> (data, text)`` like the other analysis commands (a table, or with ``--json`` the
result's ``to_dict()``: the body of ``/v1/rest-configurations``, ``/v1/branch`` (``/v1/bifurcation-diagram``
with ``--depth``), ``/v1/limit-load``, ``/v1/imperfection-sensitivity``, ``/v1/stability-boundary``,
``/v1/atlas``). The control, start, imperfection and atlas options (:func:`add_control_options`,
:func:`add_start_options`, :func:`add_imperfection_options`, :func:`add_atlas_options`) are shared with
``plot branch|limit-load|imperfection|boundary|atlas`` (:mod:`.plot`).

Examples::

    tensegrity-opt rest --fx -0.3 --stable-only
    tensegrity-opt branch --control guided --t-max 2 --start-q 0 0 0 0
    tensegrity-opt branch --control guided --t-max 2 --t-min -0.2 --start-q 0 0 0 0 --depth 1 --json
    tensegrity-opt limit-load --boundary free --direction -1 0
    tensegrity-opt imperfection --amplitudes 0 0.01 0.02851 0.061
    tensegrity-opt imperfection --n 2 --a 1.5 --amplitudes 3e-4 1e-3 3e-3 --json
    tensegrity-opt boundary --parameter asymmetry --p-min -0.05 --p-max 0.05
    tensegrity-opt atlas --n 3 --a 0.5 --dx 0.2 1.4 7 --dy -0.6 0.6 7
    tensegrity-opt atlas --n 3 --a 0.5 --dx 0.2 1.4 3 --dy 0 0.6 3 --method homotopy --no-edges --json
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from typing import Any

import numpy as np

from ...analyses.equilibria.least_energy import solve_equilibrium
from ...analyses.equilibria.rest import find_equilibria_under_force
from ...analyses.paths.atlas import AtlasTarget, StabilityAtlas, stability_atlas
from ...analyses.paths.boundaries import PARAMETERS, stability_boundary
from ...analyses.paths.branches import Branch, trace_branch
from ...analyses.paths.control import Control
from ...analyses.paths.diagram import bifurcation_diagram
from ...analyses.paths.imperfection import imperfection_sensitivity
from ...analyses.paths.limit_load import limit_load
from ...errors import InvalidParameterError
from ...model.manipulator import Manipulator
from .common import (
    add_command,
    add_progress_option,
    at_least_two,
    eq_table,
    finite_float,
    fmt_q,
    non_negative_int,
    only_with,
    positive_float,
    positive_int,
)
from .progress import Progress, equilibria_summary

__all__ = ["add_path_parsers", "add_control_options", "add_start_options", "add_limit_load_options",
           "add_boundary_options", "control_from_args", "start_from_args", "branches_from_args", "limit_load_from_args",
           "boundary_from_args", "add_imperfection_options", "imperfection_from_args", "add_atlas_options",
           "atlas_from_args", "CONTROL_KINDS"]

CONTROL_KINDS = ("displacement", "load", "guided", "wall", "preload")


# ---------------------------------------------------------------------------- shared options
def add_control_options(sp: argparse.ArgumentParser, default: str = "guided") -> None:
    g = sp.add_argument_group("control (what the continuation parameter t moves)")
    g.add_argument("--control", choices=CONTROL_KINDS, default=default,
                   help="displacement: the tip along --direction in (dx, dy), t a length; load: a dead tip load "
                        "base + t d, t a force; guided: the tip's y held, Fx = base_x + t d_x (the paper's case); "
                        "wall: the tip on a frictionless wall of --normal; preload: the rest lengths along "
                        "--direction (2n numbers), t a length")
    g.add_argument("--direction", type=finite_float, nargs="+", default=None, metavar="D",
                   help="the control's direction, normalised: 2 numbers (dx, dy) or a load's (Fx, Fy), 2n for "
                        "preload (L1_0, L2_0 per segment); default: (1, 0) for displacement, (-1, 0) for loads")
    g.add_argument("--base", type=finite_float, nargs=2, default=[0.0, 0.0], metavar=("FX", "FY"),
                   help="load at t = 0 (force) for load, guided, wall")
    g.add_argument("--normal", type=finite_float, nargs=2, default=[0.0, 1.0], metavar=("NX", "NY"),
                   help="the wall's normal (wall only)")
    g.add_argument("--tip", choices=("free", "held"), default="free",
                   help="preload only: the tip free under --load, or held where the start has it")
    g.add_argument("--load", type=finite_float, nargs=2, default=[0.0, 0.0], metavar=("FX", "FY"),
                   help="preload only: the fixed tip load (force)")
    only_with(sp, ["--base"], "--control", ("load", "guided", "wall"))
    only_with(sp, ["--normal"], "--control", ("wall",))
    only_with(sp, ["--tip", "--load"], "--control", ("preload",))


def add_start_options(sp: argparse.ArgumentParser, deflection: bool = True) -> None:
    g = sp.add_argument_group("start (default: the least-energy rest configuration)")
    g.add_argument("--start-q", type=finite_float, nargs="+", default=None, metavar="Q",
                   help="start from these joint angles (rad, n of them)")
    if deflection:
        g.add_argument("--start-dx", type=finite_float, default=None,
                       help="start from the least-energy equilibrium with the tip held at this deflection (length; "
                            "displacement and held-tip preload controls)")
        g.add_argument("--start-dy", type=finite_float, default=0.0, help="sideways deflection of that start (length)")
        only_with(sp, ["--start-dy"], "--start-dx")


def add_branch_options(sp: argparse.ArgumentParser) -> None:
    add_control_options(sp)
    add_start_options(sp)
    g = sp.add_argument_group("continuation")
    g.add_argument("--t-max", type=finite_float, default=None, help="stop where t reaches this (the control's unit)")
    g.add_argument("--t-min", type=finite_float, default=None, help="stop where t falls to this (the control's unit)")
    g.add_argument("--max-points", type=at_least_two, default=1000, help="at most this many points per branch")
    g.add_argument("--stop-at", choices=("stability_loss", "event"), default=None,
                   help="stop after the first event where stability is lost, or after any event (one branch)")
    g.add_argument("--backward", action="store_true", help="leave the start with t decreasing (one branch)")
    g.add_argument("--depth", type=non_negative_int, default=None,
                   help="the bifurcation diagram to this many branch switches instead of one branch")
    g.add_argument("--max-branches", type=positive_int, default=24, help="with --depth: at most this many branches")
    only_with(sp, ["--max-branches"], "--depth")
    g.add_argument("--timeout", type=positive_float, default=None,
                   help="seconds; then the points computed so far (status time_limit)")


def add_limit_load_options(sp: argparse.ArgumentParser) -> None:
    sp.add_argument("--boundary", choices=("free", "guided"), default="free",
                    help="free: the tip free under F = t d; guided: the tip's y held, Fx = t d_x")
    sp.add_argument("--direction", type=finite_float, nargs=2, default=[-1.0, 0.0], metavar=("DX", "DY"),
                    help="the load's direction (normalised; -1 0 compresses)")
    sp.add_argument("--max-load", type=positive_float, default=None,
                    help="stop at this load (force); default 100 k c^2 / (2b)")
    add_start_options(sp, deflection=False)
    sp.add_argument("--max-points", type=at_least_two, default=4000, help="at most this many points on the path")
    sp.add_argument("--timeout", type=positive_float, default=None,
                    help="seconds; then the path so far (reason time_limit)")


def add_imperfection_options(sp: argparse.ArgumentParser) -> None:
    sp.add_argument("--amplitudes", type=finite_float, nargs="+", required=True, metavar="P",
                    help="the imperfection's amplitudes p, computed in this order (0: the given chain)")
    sp.add_argument("--imperfection", choices=PARAMETERS, default="asymmetry",
                    help="what p moves: asymmetry (every segment's rest lengths L1_0 + p, L2_0 - p: a pre-bend), "
                         "L0, a, b, k")
    sp.add_argument("--boundary", choices=("free", "guided"), default="guided",
                    help="guided: y held at each imperfect chain's rest tip, Fx = t d_x; free: F = t d")
    sp.add_argument("--direction", type=finite_float, nargs=2, default=[-1.0, 0.0], metavar=("DX", "DY"),
                    help="the load's direction (normalised; -1 0 compresses)")
    sp.add_argument("--max-load", type=positive_float, default=None,
                    help="stop each path at this load (force); default 100 k c^2 / (2b)")
    sp.add_argument("--max-points", type=at_least_two, default=4000, help="at most this many points per path")
    sp.add_argument("--timeout", type=positive_float, default=None,
                    help="seconds for the whole curve; then the amplitudes done (status time_limit)")


def add_boundary_options(sp: argparse.ArgumentParser) -> None:
    add_control_options(sp)
    sp.add_argument("--parameter", default="asymmetry",
                    help="the second parameter p the boundary is followed in (the library's names)")
    sp.add_argument("--p-min", type=finite_float, default=-0.1, help="lower end of p (the parameter's unit)")
    sp.add_argument("--p-max", type=finite_float, default=0.1, help="upper end of p (the parameter's unit)")
    sp.add_argument("--max-points", type=at_least_two, default=400, help="at most this many points on the boundary")
    sp.add_argument("--timeout", type=positive_float, default=None, help="seconds; then the boundary so far")


def add_atlas_options(sp: argparse.ArgumentParser) -> None:
    g = sp.add_argument_group("atlas (the grid of tip targets)")
    g.add_argument("--dx", type=finite_float, nargs=3, default=[0.1, 1.3, 5], metavar=("START", "STOP", "NUM"),
                   help="the dx values (length; > 0 shortens the chain): NUM evenly spaced from START to STOP")
    g.add_argument("--dy", type=finite_float, nargs=3, default=[-0.6, 0.6, 5], metavar=("START", "STOP", "NUM"),
                   help="the dy values (sideways, length): NUM evenly spaced from START to STOP")
    g.add_argument("--method", choices=("search", "homotopy"), default="search",
                   help="each target's equilibria: multi-start Newton, or PHCpack's certified homotopy (n <= 6)")
    g.add_argument("--no-edges", action="store_true",
                   help="the counts only: do not locate the switches and branch ends on the grid edges")
    g.add_argument("--timeout", type=positive_float, default=None,
                   help="seconds; then the targets and edges done so far (status time_limit)")


def _grid_axis(spec: list[float], name: str) -> np.ndarray:
    start, stop, num = spec
    if num != int(num) or num < 1:
        raise InvalidParameterError(f"--{name} START STOP NUM: NUM must be an integer >= 1, got {num:g}", field=name)
    return np.linspace(start, stop, int(num))


def atlas_from_args(args: argparse.Namespace, m: Manipulator,
                    progress: Callable[[AtlasTarget], Any] | None = None) -> StabilityAtlas:
    return stability_atlas(m, _grid_axis(args.dx, "dx"), _grid_axis(args.dy, "dy"), method=args.method,
                           edges=not args.no_edges, timeout=args.timeout, progress=progress)


def _control_kw(args: argparse.Namespace) -> dict[str, Any]:
    kw: dict[str, Any] = {}
    if args.direction is not None:
        kw["direction"] = list(args.direction)
    if args.control in ("load", "guided", "wall"):
        kw["base"] = list(args.base)
    if args.control == "wall":
        kw["normal"] = list(args.normal)
    if args.control == "preload":
        if args.direction is None:
            raise InvalidParameterError("a preload control needs --direction with 2n numbers", field="direction")
        kw["tip"], kw["load"] = args.tip, list(args.load)
    return kw


def control_from_args(args: argparse.Namespace) -> Control:
    kw = _control_kw(args)
    if args.control != "preload" and "direction" in kw and len(kw["direction"]) != 2:
        raise InvalidParameterError(f"--direction takes 2 numbers for a {args.control} control, got "
                                    f"{len(kw['direction'])}", field="direction")
    return getattr(Control, args.control)(**kw)


def start_from_args(m: Manipulator, args: argparse.Namespace) -> Any:
    if getattr(args, "start_q", None) is not None:
        if getattr(args, "start_dx", None) is not None:
            raise InvalidParameterError("give --start-q or --start-dx, not both", field="start")
        return np.asarray(args.start_q, dtype=float)
    if getattr(args, "start_dx", None) is not None:
        if not (args.control == "displacement" or (args.control == "preload" and args.tip == "held")):
            raise InvalidParameterError("--start-dx needs a control that holds the tip (displacement, or preload "
                                        "with --tip held)", field="start")
        return solve_equilibrium(m, args.start_dx, args.start_dy, stops=False)
    return None


def branches_from_args(args: argparse.Namespace, m: Manipulator) -> Branch | list[Branch]:
    ctl = control_from_args(args)
    start = start_from_args(m, args)
    if args.depth is None:
        return trace_branch(m, start, ctl, t_max=args.t_max, t_min=args.t_min, max_points=args.max_points,
                            stop_at=args.stop_at, orientation=-1 if args.backward else 1, timeout=args.timeout)
    if args.stop_at is not None or args.backward:
        raise InvalidParameterError("--stop-at and --backward belong to one branch: --depth follows every branch "
                                    "both ways", field="depth")
    return bifurcation_diagram(m, start, ctl, depth=args.depth, max_branches=args.max_branches,
                               timeout=args.timeout, t_max=args.t_max, t_min=args.t_min, max_points=args.max_points)


def limit_load_from_args(args: argparse.Namespace, m: Manipulator) -> Any:
    start = None if args.start_q is None else np.asarray(args.start_q, dtype=float)
    return limit_load(m, args.direction, args.boundary, args.max_load, start, max_points=args.max_points,
                      timeout=args.timeout)


def imperfection_from_args(args: argparse.Namespace, m: Manipulator) -> Any:
    return imperfection_sensitivity(m, args.amplitudes, imperfection=args.imperfection, direction=args.direction,
                                    boundary=args.boundary, max_load=args.max_load, max_points=args.max_points,
                                    timeout=args.timeout)


def boundary_from_args(args: argparse.Namespace, m: Manipulator) -> Any:
    fn = stability_boundary
    kw = _control_kw(args)
    kw.setdefault("direction", [1.0, 0.0] if args.control == "displacement" else [-1.0, 0.0])
    return fn(m, args.control, args.parameter, p_min=args.p_min, p_max=args.p_max, max_points=args.max_points,
              timeout=args.timeout, **kw)


# ---------------------------------------------------------------------------- the commands
def _cmd_rest(args: argparse.Namespace, m: Manipulator) -> tuple[Any, str]:
    with Progress("rest", enabled=args.progress) as bar:
        eqs = find_equilibria_under_force(m, args.fx, args.fy, method=args.method, stable_only=args.stable_only)
        bar.close(equilibria_summary(eqs, bar.seconds))
    head = ("Rest configurations (F = 0)" if args.fx == 0.0 and args.fy == 0.0 else
            f"Equilibria under the dead tip load ({args.fx:g}, {args.fy:g})")
    how = f"method {eqs.method}, " + ("certified complete" if eqs.certified else "not certified")
    return eqs.to_dict, "\n".join([f"{head}: {len(eqs)} ({how})", *eq_table(list(eqs))])


def _event_lines(br: Branch) -> list[str]:
    if not br.events:
        return ["events: none"]
    out = [f"events ({len(br.events)}):",
           f"  {'kind':<13} {'between':>9} {'t':>12} {'Fx':>11} {'Fy':>11} {'morse':>6} {'stability':>9}  "
           "method / mode"]
    for e in br.events:
        mode = e.method + ("" if e.null_vector is None else f", mode {fmt_q(e.null_vector)}")
        if e.kind == "joint_limit":
            mode += f", joint {e.joint + 1}"
        out.append(f"  {e.kind:<13} {e.index:>4}-{e.index + 1:<4} {e.t:>12.7f} {e.force[0]:>11.6f} {e.force[1]:>11.6f} "
                   f"{e.morse_before:>2}->{e.morse_after:<2} {e.stability:>9}  {mode}")
    return out


def _branch_head(br: Branch, k: int | None = None) -> str:
    which = "" if k is None else f"branch {k}: "
    return (f"{which}{len(br)} points, t from {br.t[0]:.6g} to {br.t[-1]:.6g}, status {br.status}"
            + ("" if br.success else " (incomplete)") + f": {br.message}")


def _points_table(br: Branch) -> list[str]:
    d = br.deflection
    lines = [f"{'#':>4} {'t':>12} {'Fx':>11} {'Fy':>11} {'dx':>10} {'dy':>10} {'energy':>11} {'morse':>5}  q (rad)"]
    for i in range(len(br)):
        lines.append(f"{i:>4} {br.t[i]:>12.7f} {br.force[i, 0]:>11.6f} {br.force[i, 1]:>11.6f} {d[i, 0]:>10.5f} "
                     f"{d[i, 1]:>10.5f} {br.energy[i]:>11.6f} {int(br.morse_index[i]):>5}  {fmt_q(br.q[i])}")
    return lines


def _cmd_branch(args: argparse.Namespace, m: Manipulator) -> tuple[Any, str]:
    res = branches_from_args(args, m)
    if isinstance(res, Branch):
        text = [f"Equilibrium branch, {args.control} control {fmt_q(res.control.direction)}, n = {m.n}",
                _branch_head(res), *_points_table(res), *_event_lines(res)]
        return res.to_dict, "\n".join(text)
    text = [f"Bifurcation diagram, {args.control} control, n = {m.n}: {len(res)} branches (depth {args.depth})"]
    for k, br in enumerate(res):
        text += [_branch_head(br, k), *("  " + line for line in _event_lines(br))]
    return (lambda: {"branches": [b.to_dict() for b in res]}), "\n".join(text)


def _cmd_limit_load(args: argparse.Namespace, m: Manipulator) -> tuple[Any, str]:
    r = limit_load_from_args(args, m)
    lines = [f"Limit load, {r.boundary} tip, load along {fmt_q(r.direction)}, n = {m.n}"]
    if r.kind != "none":
        lines += [f"{r.kind} at load P = {r.load:.7f} (force), F = {fmt_q(r.force)}",
                  f"configuration q = {fmt_q(r.q)}", f"mode {fmt_q(r.null_vector)}"]
    else:
        lines.append(f"no limit point: the path stays stable to its end ({r.status}) at load {r.end_load:.7f}")
    lines.append("quasi-buckling load (least tangent stiffness): "
                 + ("none" if r.quasi_buckling_load is None else
                    f"{r.quasi_buckling_load:.7f}, stiffness along the load {r.quasi_buckling_stiffness:.7g}"))
    lines.append(f"start q = {fmt_q(r.start.q)}; path: {len(r.branch)} points, status {r.branch.status}")
    return (lambda: r.to_dict(include_branch=args.include_branch)), "\n".join(lines)


def _cmd_imperfection(args: argparse.Namespace, m: Manipulator) -> tuple[Any, str]:
    r = imperfection_from_args(args, m)
    lines = [f"Imperfection sensitivity ({r.imperfection}), {r.boundary} tip, load along {fmt_q(r.direction)}, "
             f"n = {m.n}: status {r.status}" + ("" if r.success else " (incomplete)"),
             "perfect chain: " + (f"{r.perfect_kind} at P = {r.perfect_load:.7f}" if r.perfect_load is not None
                                  else r.perfect_kind)
             + ("" if r.bifurcation is None else f" ({r.bifurcation.replace('_', '-')})"),
             f"{'#':>4} {'p':>12} {'load':>12} {'kind':<12} status"]
    for i, (p, load, kind, st) in enumerate(zip(r.amplitudes, r.loads, r.kinds, r.statuses)):
        lines.append(f"{i:>4} {p:>12.7g} {'-' if np.isnan(load) else f'{load:.7f}':>12} {kind:<12} {st}")
    if r.law_exponent is not None:
        lines.append(f"small-imperfection law: P_c - P = {r.law_coefficient:.5g} |p|^{r.law_exponent:.4f} "
                     f"(expected exponent {r.law_expected:.4g})")
    return (lambda: r.to_dict(include_limit_loads=args.include_limit_loads)), "\n".join(lines)


def _cmd_boundary(args: argparse.Namespace, m: Manipulator) -> tuple[Any, str]:
    b = boundary_from_args(args, m)
    p, t = np.asarray(b.p, float), np.asarray(b.t, float)
    F = np.asarray(b.force, float).reshape(-1, 2) if np.size(b.force) else np.full((p.size, 2), np.nan)
    lines = [f"Stability boundary ({b.kind}) over {b.parameter}, {args.control} control, n = {m.n}: {p.size} points, "
             f"status {b.status}" + ("" if b.success else " (incomplete)"),
             f"{'#':>4} {'p':>12} {'t':>12} {'Fx':>11} {'Fy':>11}"]
    lines += [f"{i:>4} {p[i]:>12.7f} {t[i]:>12.7f} {F[i, 0]:>11.6f} {F[i, 1]:>11.6f}" for i in range(p.size)]
    cusps = list(b.cusps or [])
    lines.append(f"cusps ({len(cusps)}): " + (", ".join(f"p = {c.p:.7g}, t = {c.t:.7g}" for c in cusps) or "none"))
    return b.to_dict, "\n".join(lines)


def _cmd_atlas(args: argparse.Namespace, m: Manipulator) -> tuple[Any, str]:
    total = int(args.dx[2]) * int(args.dy[2])
    seen = {"done": 0, "failed": 0}

    def target_done(t: AtlasTarget) -> None:
        seen["done"] += 1
        seen["failed"] += not t.success
        bar(seen["done"], total, seen["failed"])
        if seen["done"] == total and not args.no_edges:
            bar.stage("grid edges")

    with Progress("atlas", total, unit="target", enabled=args.progress) as bar:
        at = atlas_from_args(args, m, progress=target_done)
        bar.close(f"{at.dx.size * at.dy.size} targets in {bar.seconds:.1f} s, {len(at.switches)} switches, "
                  f"{len(at.branch_ends)} branch ends, status {at.status}")
    ns = at.n_stable
    lines = [f"Stability atlas of the held tip, n = {m.n}, method {at.method}: {at.dx.size} x {at.dy.size} targets, "
             f"status {at.status} ({at.seconds:.1f} s)",
             "stable equilibria per target (rows dy from the top down, columns dx; '-' beyond reach, '!' failed):",
             f"{'dy / dx':>10} " + " ".join(f"{x:>7.3g}" for x in at.dx)]
    for j in range(at.dy.size - 1, -1, -1):
        cells = []
        for i in range(at.dx.size):
            t = at.targets[j][i]
            cells.append("!" if not t.success else "-" if not t.reachable else str(int(ns[j, i])))
        lines.append(f"{at.dy[j]:>10.4g} " + " ".join(f"{c:>7}" for c in cells))
    lines.append(f"crossings: {len(at.switches)} switches, {len(at.branch_ends)} branch ends"
                 + (f"; {len(at.unresolved)} edges unresolved" if at.unresolved else ""))
    if at.crossings:
        lines.append(f"  {'kind':<10} {'dx':>10} {'dy':>10} {'energy':>11} {'event':<12} method")
        lines += [f"  {c.kind:<10} {c.dx:>10.6f} {c.dy:>10.6f} {c.energy:>11.6f} {c.event:<12} {c.method}"
                  for c in at.crossings]
    for (a, b), reason in at.unresolved:
        lines.append(f"  unresolved edge {list(a)}-{list(b)}: {reason}")
    return at.to_dict, "\n".join(lines)


def add_path_parsers(subparsers: Any) -> None:
    """Add ``rest``, ``branch``, ``limit-load``, ``imperfection``, ``boundary`` and ``atlas`` to ``subparsers``
    (``add_subparsers()``'s result)."""

    sp = add_command(subparsers, "rest", _cmd_rest, "rest configurations, or every equilibrium under a dead tip load")
    sp.add_argument("--fx", type=finite_float, default=0.0, help="dead tip load along x (force; < 0 compresses)")
    sp.add_argument("--fy", type=finite_float, default=0.0, help="dead tip load along y (force)")
    sp.add_argument("--method", choices=("search", "homotopy"), default="search",
                    help="for a nonzero load: multi-start Newton, or PHCpack's certified homotopy (n <= 6); "
                         "F = 0 is exact either way")
    sp.add_argument("--stable-only", action="store_true", help="only the stable equilibria")
    add_progress_option(sp)

    sp = add_command(subparsers, "branch", _cmd_branch,
                     "an equilibrium branch by arclength continuation (or --depth: the bifurcation diagram), with "
                     "its folds, branch points and joint limits")
    add_branch_options(sp)

    sp = add_command(subparsers, "limit-load", _cmd_limit_load,
                     "the dead load at which the path from a rest configuration loses stability")
    add_limit_load_options(sp)
    sp.add_argument("--include-branch", action="store_true", help="with --json: also the traced path")
    only_with(sp, ["--include-branch"], "--json")

    sp = add_command(subparsers, "imperfection", _cmd_imperfection,
                     "the imperfection-sensitivity curve: the limit load of the imperfect chain from its rest shape "
                     "against the imperfection's amplitude")
    add_imperfection_options(sp)
    sp.add_argument("--include-limit-loads", action="store_true", help="with --json: also each amplitude's limit load")
    only_with(sp, ["--include-limit-loads"], "--json")

    sp = add_command(subparsers, "boundary", _cmd_boundary,
                     "a stability boundary: the folds or branch points over a second parameter")
    add_boundary_options(sp)

    sp = add_command(subparsers, "atlas", _cmd_atlas,
                     "the stability atlas of the held tip: stable equilibria over a grid of deflections, the "
                     "least-energy switches and the branch ends")
    add_atlas_options(sp)
    add_progress_option(sp)
