"""Command line: ``tensegrity-opt buckling|equilibrium|equilibria|curve|rest|branch|limit-load|imperfection|boundary|
atlas|plan|simulate|force-estimate|plot|sweep|homotopy-precompute ...``.

Every command takes the manipulator as ``--n --a --b --k --L0`` (uniform; the
paper's chain by default) or ``--manipulator FILE.json`` (``{"segments": [...]}``),
prints a readable table, or JSON with ``--json``: the result's ``to_dict()``, the body the
HTTP API answers for the same request (one serialiser, one NaN policy: :mod:`tensegrity_opt.serialize`).
Errors print one line to stderr and exit with status 2; a physical answer that leaves nothing to print (the
straight chain unstable unloaded, or no equilibrium there: ``buckling`` of such a chain) prints one line
``tensegrity-opt: answer: ...`` and exits with status 1.

The library's commands only: the HTTP service's ``serve`` and ``openapi`` belong to the service
(:mod:`service.cli`, the ``tensegrity-opt`` console script, which hands every other command to
:func:`main` here). This package never imports the service; :func:`build_parser` takes the extra
commands of an application built on top (``add_commands``).
"""

from __future__ import annotations

import argparse
import math
import sys
from collections.abc import Callable
from typing import Any

import numpy as np

from ... import __version__
from ...analyses.equilibria.all_equilibria import find_equilibria
from ...analyses.equilibria.buckling import critical_force
from ...analyses.equilibria.equilibrium import solve_equilibrium_under_force
from ...analyses.equilibria.least_energy import solve_equilibrium
from ...analyses.equilibria.modes import modes
from ...analyses.paths.curves import force_deflection
from .common import (
    HELP_FORMAT,
    Parser,
    add_command,
    add_curve_options,
    add_deflection_options,
    add_manipulator_options,
    add_progress_option,
    eq_table,
    exclusive,
    finite_float,
    fmt_q,
    note,
    run_command,
)
from .control import add_control_parsers
from .paths import add_path_parsers
from .plot import add_plot_parser
from .progress import Progress, equilibria_summary
from .sweep import add_sweep_parser

__all__ = ["main", "build_parser", "add_manipulator_options", "SERVICE_COMMANDS"]

#: The service's commands (``service.cli``): named here only to point a caller of this module there.
SERVICE_COMMANDS = ("serve", "openapi")


def _cmd_buckling(args, m) -> tuple[Any, str]:
    bk = critical_force(m, args.boundary)
    data = bk.to_dict
    lines = [f"Buckling of the straight configuration (n = {m.n}, tip {bk.boundary})",
             f"critical force Fx0 = {bk.force:.6f}", "",
             f"{'#':>2} {'load P':>10} {'-1/P':>10} {'mu_eq':>9} {'mu_x':>9} {'Fy/sqrt(dx)':>12} {'shape':>5} "
             f"{'signs':>{max(5, m.n)}} {'stable':>6}  mode q"]
    for i, md in enumerate(bk.modes, 1):
        lines.append(f"{i:>2} {md.load:>10.6f} {-1 / md.load:>10.5f} {md.energy_factor:>9.6f} {md.mu_x:>9.6f} "
                     f"{md.fy_coefficient:>12.6f} {md.shape:>5} {md.signs:>{max(5, m.n)}} "
                     f"{'yes' if md.stable else 'no':>6}  {fmt_q(md.q)}")
    return data, "\n".join(lines)


def _cmd_equilibrium(args, m):
    if args.fx is not None or args.fy is not None:
        eq = solve_equilibrium_under_force(m, args.fx or 0.0, args.fy or 0.0)
        head = f"Equilibrium under the tip force ({args.fx or 0.0:g}, {args.fy or 0.0:g})"
    else:
        eq = solve_equilibrium(m, args.dx, args.dy, certify=args.certify)
        head = f"Least-energy stable equilibrium at dx = {args.dx:g}, dy = {args.dy:g}"
    its = "iterations not counted" if eq.solver.iterations is None else f"{eq.solver.iterations} iterations"
    cert = [] if eq.certificate is None else [f"least energy {eq.certificate.message}"]
    return eq.to_dict, "\n".join([head, *(eq_table([eq])), f"solver: {eq.solver.status}, {its}", *cert])


def _cmd_modes(args, m):
    if args.fx is not None or args.fy is not None:
        eq = solve_equilibrium_under_force(m, args.fx or 0.0, args.fy or 0.0)
        head = f"Vibration modes of the equilibrium under the tip force ({args.fx or 0.0:g}, {args.fy or 0.0:g})"
    else:
        eq = solve_equilibrium(m, args.dx, args.dy)
        head = f"Vibration modes of the least-energy stable equilibrium at dx = {args.dx:g}, dy = {args.dy:g}"
    md = modes(m, eq, tip=args.tip)
    lines = [head, md.message, f"{'mode':>4} {'w (rad/s)':>12} {'f (Hz)':>10} {'w^2':>12}  shape (joint angles, "
                                "mass-normalised)"]
    for i, (w, lam, s) in enumerate(zip(md.frequencies, md.eigenvalues, md.shapes), 1):
        ws = f"{w:>12.6g} {w / (2 * math.pi):>10.6g}" if math.isfinite(w) else f"{'-':>12} {'-':>10}"
        lines.append(f"{i:>4} {ws} {lam:>12.6g}  {fmt_q(s)}")

    def body():
        return {**md.to_dict(), "equilibrium": eq.to_dict()}
    return body, "\n".join(lines)


def _cmd_equilibria(args, m):
    with Progress("equilibria", enabled=args.progress) as bar:
        eqs = find_equilibria(m, args.dx, args.dy, method=args.method, stops=args.stops)
        bar.close(equilibria_summary(eqs, bar.seconds))
    how = f"method {eqs.method}, " + ("certified complete" if eqs.certified else "not certified")
    if eqs.paths:
        how += f" ({eqs.paths} homotopy paths, {eqs.failed_paths} failed)"
    if eqs.certificate is not None:
        c, k = eqs.certificate, len(eqs.certificate.boxes)
        how += (f"; interval proofs (Krawczyk, ball arithmetic): {sum(b.proven for b in c.boxes)}/{k} equilibria, "
                f"{sum(b.morse_proven for b in c.boxes)}/{k} Morse indices")
    return (eqs.to_dict,
            "\n".join([f"All equilibria at dx = {args.dx:g}, dy = {args.dy:g}: {len(eqs)} ({how})",
                       *(eq_table(eqs) if len(eqs) else [eqs.message])]))


def _cmd_curve(args, m):
    dx = np.linspace(args.start, args.stop, args.num)
    c = force_deflection(m, dx, args.dy, branch="stable", reference=args.reference)
    data = c.to_dict
    lines = [f"Force-deflection (stable branch), dy = {args.dy:g}",
             f"{'dx':>10} {'Fx':>10} {'Fy':>10} {'energy':>12} {'shape':>5}"]
    lines += [f"{c.dx[i]:>10.5f} {c.fx[i]:>10.6f} {c.fy[i]:>10.6f} {c.energy[i]:>12.6f} {c.shape[i]:>5}"
              for i in range(c.dx.size)]
    for j in c.jumps:
        lines.append(f"jump ({j.kind}) between dx = {j.dx_before:g} and {j.dx_after:g}: "
                     f"F {fmt_q(j.force_before)} -> {fmt_q(j.force_after)}")
    if not c.success:
        # A partial curve (the stable branch ends before --stop): its points are real equilibria, printed
        # (table or JSON, exit 0); what is missing and why goes to stderr.
        note(c.message)
    return data, "\n".join(lines)


def _cmd_homotopy_precompute(args) -> int:
    """``homotopy-precompute``: the start roots of the parameter homotopy, computed and cached ahead
    (:func:`tensegrity_opt.numerics.parameter_homotopy.precompute`)."""
    from ...errors import TensegrityError
    from ...numerics import parameter_homotopy as ph
    from .common import error

    kinds = ph.KINDS if args.kind == "both" else (args.kind,)

    def progress(kind, n, start) -> None:
        where = ph.start_file(kind, n, start.structure) if start.source != "packaged" else "the package's data"
        print(f"{kind:>12} n = {n} {start.structure:>9}: {start.count:>6} start solutions ({start.source}, {where})",
              flush=True)

    try:
        ph.precompute(args.max_segments, kinds, min_segments=args.min_segments, force=args.force,
                      progress=progress)
    except (TensegrityError, OSError) as exc:
        return error(exc)
    return 0


class _WholeNames(argparse.HelpFormatter):
    """The top help's formatter: its description lists the commands, so a line never breaks inside a hyphenated
    name (``load-capacity``)."""

    def _fill_text(self, text: str, width: int, indent: str) -> str:
        import textwrap

        return textwrap.fill(" ".join(text.split()), width, initial_indent=indent, subsequent_indent=indent,
                             break_on_hyphens=False)


def build_parser(add_commands: Callable[[Any], None] | None = None) -> argparse.ArgumentParser:
    """The parser of every library command; ``add_commands(subparsers)`` adds more (a command that
    handles its own arguments sets ``run=callable(args) -> exit status`` as its default)."""
    p = Parser(prog="tensegrity-opt", formatter_class=_WholeNames,
               epilog="Each command's options and their defaults: tensegrity-opt COMMAND --help (plot: tensegrity-opt "
                      "plot KIND --help).")
    p.add_argument("--version", action="version", version=f"tensegrity-opt {__version__}")
    sub = p.add_subparsers(dest="command", required=True, metavar="COMMAND")

    def command(name: str, func, help: str) -> argparse.ArgumentParser:
        return add_command(sub, name, func, help, json_help="print JSON instead of a table")

    sp = command("buckling", _cmd_buckling, "critical force and buckling modes (the paper's Table 1)")
    sp.add_argument("--boundary", choices=("guided", "free"), default="guided",
                    help="tip guided (y held, the paper's case) or free")

    sp = command("equilibrium", _cmd_equilibrium, "least-energy stable equilibrium for a tip deflection or force")
    sp.add_argument("--dx", type=finite_float, default=0.1,
                    help="tip deflection along the chain (length; > 0 shortens it): the tip is held at "
                         "(2 sum b - dx, dy)")
    sp.add_argument("--dy", type=finite_float, default=0.0, help="sideways tip deflection (length)")
    sp.add_argument("--fx", type=finite_float, default=None,
                    help="prescribe the tip force instead of the deflection --dx, --dy (force; < 0 compresses; "
                         "0 when only --fy is given)")
    sp.add_argument("--fy", type=finite_float, default=None,
                    help="sideways tip force (force; 0 when only --fx is given)")
    sp.add_argument("--certify", action="store_true",
                    help="prove the answer least: a rigorous lower bound on the energy of every configuration "
                         "meeting the tip constraint, and the gap (certified when within its tolerance)")
    exclusive(sp, ["--dx", "--dy", "--certify"], ["--fx", "--fy"], "a tip deflection or a tip force, not both")

    sp = command("modes", _cmd_modes, "natural frequencies and mode shapes of an equilibrium (needs --mass or "
                                      "--payload)")
    sp.add_argument("--dx", type=finite_float, default=0.1, help="tip deflection along the chain (the tip held)")
    sp.add_argument("--dy", type=finite_float, default=0.0, help="sideways tip deflection")
    sp.add_argument("--fx", type=finite_float, default=None, help="a dead tip force instead of the deflection")
    sp.add_argument("--fy", type=finite_float, default=None, help="sideways dead tip force")
    sp.add_argument("--tip", choices=("held", "loaded"), default=None,
                    help="the modes with the tip held or free under its load (default: as the equilibrium is posed)")
    exclusive(sp, ["--dx", "--dy"], ["--fx", "--fy"], "a tip deflection or a tip force, not both")

    sp = command("equilibria", _cmd_equilibria, "every equilibrium (minima, saddles, maxima) for a tip deflection")
    add_deflection_options(sp)
    sp.add_argument("--method", choices=("search", "homotopy"), default="search",
                    help="search: multi-start Newton (any n, not certified); homotopy: PHCpack, certified, "
                         "n <= 6 (default: %(default)s)")
    sp.add_argument("--stops", action=argparse.BooleanOptionalAction, default=None,
                    help="include (or leave out) the equilibria resting on a joint's stop; default: included for "
                         "tension-only springs, left out under the linear law")
    add_progress_option(sp)

    sp = command("curve", _cmd_curve, "force-deflection curve along the stable branch (Fig. 6)")
    add_curve_options(sp, num=11)
    sp.add_argument("--reference", choices=("straight", "rest"), default="straight",
                    help="measure dx, dy from the straight tip or from the rest configuration's tip (pre-bent arms)")
    sp = sub.add_parser("homotopy-precompute", formatter_class=HELP_FORMAT,
                        help="compute and cache the start solutions of the parameter homotopy (method=homotopy)")
    sp.add_argument("--max-segments", type=int, default=5, choices=range(2, 7), metavar="N",
                    help="up to this many segments, 2..6 (n = 6: ~10-20 min on 2 cores; default: %(default)s)")
    sp.add_argument("--min-segments", type=int, default=2, choices=range(2, 7), metavar="N",
                    help="from this many segments (default: %(default)s)")
    sp.add_argument("--kind", choices=("displacement", "force", "both"), default="both",
                    help="the tip-displacement system, the tip-force system or both (default: %(default)s)")
    sp.add_argument("--force", action="store_true", help="recompute those already cached or packaged")
    sp.set_defaults(run=_cmd_homotopy_precompute)
    add_path_parsers(sub)
    add_control_parsers(sub)
    add_plot_parser(sub)
    add_sweep_parser(sub)

    if add_commands is not None:
        add_commands(sub)
    p.description = describe(sub.choices)
    return p


#: The command groups of the top help, in order; a command in none of them is listed under "more".
GROUPS = (("equilibria", ("buckling", "equilibrium", "equilibria", "curve", "rest", "modes")),
          ("loading paths", ("branch", "limit-load", "imperfection", "boundary", "atlas")),
          ("control and design", ("plan", "simulate", "force-estimate", "stiffness-design", "load-capacity",
                                   "holding-design", "weight-capacity")),
          ("figures", ("plot",)), ("parameter sweeps", ("sweep",)), ("set-up", ("homotopy-precompute",)),
          ("HTTP service", SERVICE_COMMANDS))


def describe(commands) -> str:
    """The top help's description: every command, by group (:data:`GROUPS`), of the parser's ``commands``."""
    names = list(commands)
    parts, seen = [], set()
    for title, group in GROUPS:
        here = [c for c in group if c in names]
        seen.update(here)
        if here:
            parts.append(f"{title}: {', '.join(here)}")
    rest = [c for c in names if c not in seen]
    if rest:
        parts.append(f"more: {', '.join(rest)}")
    return ("The tensegrity manipulator's analyses from the command line - " + "; ".join(parts) + ". "
            "Tables by default, --json for the HTTP API's body; a bad input is one line 'error: ...' on "
            "stderr and exit status 2.")


def main(argv: list[str] | None = None, parser: argparse.ArgumentParser | None = None) -> int:
    """Run one command (``argv``: ``sys.argv[1:]`` by default) of ``parser`` (:func:`build_parser`
    by default); the exit status."""
    if parser is None:
        first = next((a for a in (sys.argv[1:] if argv is None else argv) if not a.startswith("-")), None)
        if first in SERVICE_COMMANDS:
            print(f"tensegrity-opt: error: '{first}' is a command of the HTTP service: run `tensegrity-opt {first}` "
                  f"(service.cli; needs pip install 'tensegrity-opt[service]')", file=sys.stderr)
            return 2
    return run_command(parser or build_parser(), argv)

