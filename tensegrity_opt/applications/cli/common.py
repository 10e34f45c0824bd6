"""What every command of the command line shares: the manipulator options, the chain they
describe, and running a parsed command (table or ``--json``, one-line errors, exit status 2).

Below both :mod:`tensegrity_opt.applications.cli` (the parser of every command) and its command
modules (:mod:`.plot`, :mod:`.sweep`), so neither imports the other back.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
from collections.abc import Callable, Sequence
from typing import Any

from ...errors import (
    InvalidParameterError,
    NonFiniteResult,
    StraightNotEquilibriumError,
    TensegrityError,
    UnstableStraightError,
)
from ...model.loads import describe, loads_key
from ...model.manipulator import Manipulator
from ...model.springs import SPRING_LAWS

__all__ = ["add_manipulator_options", "add_analysis_options", "add_command", "add_deflection_options",
           "add_curve_options", "run_command", "positive_int", "non_negative_int",
           "at_least_two", "joint_index", "finite_float", "positive_float", "non_negative_float", "HELP_FORMAT",
           "fmt_q", "eq_table", "Parser", "error", "note", "exclusive", "only_with", "add_rule", "add_progress_option",
           "GIVEN"]

#: Every command's help shows each option's default.
HELP_FORMAT = argparse.ArgumentDefaultsHelpFormatter


#: The namespace attribute holding the option strings given on the command line (:class:`Parser`).
GIVEN = "given_options"


class Parser(argparse.ArgumentParser):
    """An ``ArgumentParser`` whose usage errors are one line on stderr, ``PROG: error: MESSAGE (see PROG
    --help)``, and exit status 2 (argparse's status; its usage block is left out: for the commands with
    many options it buries the one line that matters). Subparsers inherit the class, and every
    parser shows each option's default (:data:`HELP_FORMAT`) unless given another formatter.

    It also refuses options that exclude each other (:func:`exclusive`, :func:`only_with`): argparse's
    mutually exclusive groups take single options only and cannot see an option given at its default value,
    so the parser notes every option given (the namespace's :data:`GIVEN`, a set of option strings) and checks
    its rules after parsing, with argparse's own message: ``argument --fx: not allowed with argument --dx``."""

    def __init__(self, *args, **kwargs) -> None:
        kwargs.setdefault("formatter_class", HELP_FORMAT)
        super().__init__(*args, **kwargs)
        self.rules: list[Callable[[argparse.Namespace, frozenset[str]], str | None]] = []
        self._given: set[str] = set()

    def _get_values(self, action, arg_strings):  # noqa: D102  (argparse's hook for every option it parses)
        self._given.update(action.option_strings)
        return super()._get_values(action, arg_strings)

    def parse_known_args(self, args=None, namespace=None):  # noqa: D102
        self._given = set()
        ns, rest = super().parse_known_args(args, namespace)
        given = frozenset(self._given | set(getattr(ns, GIVEN, ())))      # a subcommand's options included
        setattr(ns, GIVEN, given)
        for rule in self.rules:
            message = rule(ns, given)
            if message:
                self.error(message)
        return ns, rest

    def error(self, message: str):  # noqa: D102  (argparse's hook)
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


def add_rule(sp: argparse.ArgumentParser, rule: Callable[[argparse.Namespace, frozenset[str]], str | None]) -> None:
    """Check ``rule(namespace, given) -> message | None`` after parsing (a message: the usage error) on ``sp``, a
    :class:`Parser` (on a plain ``ArgumentParser``, which does not note the options given, nothing)."""
    if isinstance(sp, Parser):
        sp.rules.append(rule)


def exclusive(sp: argparse.ArgumentParser, first: Sequence[str], second: Sequence[str], why: str = "") -> None:
    """Refuse an option of ``second`` given with one of ``first`` (option strings; given at any value, its
    default included): ``argument --fx: not allowed with argument --dx (WHY)``, exit status 2. ``sp`` is a
    :class:`Parser` (a subcommand's parser: subparsers inherit the class); a plain ``ArgumentParser`` cannot
    tell which options were given and checks nothing."""
    suffix = f" ({why})" if why else ""

    def rule(ns: argparse.Namespace, given: frozenset[str]) -> str | None:
        a = next((o for o in first if o in given), None)
        b = next((o for o in second if o in given), None)
        return None if a is None or b is None else f"argument {b}: not allowed with argument {a}{suffix}"

    add_rule(sp, rule)


def only_with(sp: argparse.ArgumentParser, options: Sequence[str], other: str, values: Sequence[Any] | None = None,
              why: str = "") -> None:
    """Refuse the ``options`` (option strings) unless ``other`` is given too (``values`` None) or holds one of
    ``values`` (its default counts): ``argument --normal: only with --control wall``, exit status 2."""
    dest = other.lstrip("-").replace("-", "_")
    names = [str(v) for v in values or ()]
    want = other if values is None else f"{other} " + (names[0] if len(names) == 1 else
                                                       f"{', '.join(names[:-1])} or {names[-1]}")
    suffix = f" ({why})" if why else ""

    def rule(ns: argparse.Namespace, given: frozenset[str]) -> str | None:
        if (other in given) if values is None else (getattr(ns, dest, None) in values):
            return None
        a = next((o for o in options if o in given), None)
        return None if a is None else f"argument {a}: only with {want}{suffix}"

    add_rule(sp, rule)


def add_progress_option(sp: argparse.ArgumentParser) -> None:
    """``--progress/--no-progress``: a progress bar and a closing summary on stderr (None: when stderr is a
    terminal; :mod:`.progress`)."""
    sp.add_argument("--progress", action=argparse.BooleanOptionalAction, default=None,
                    help="show a progress bar and a one-line summary on stderr; None: only when stderr is a terminal")


def answer(exc: Exception) -> int:
    """A physical answer that leaves nothing to print (``buckling`` of a chain whose straight shape is unstable
    unloaded, or no equilibrium at all): one line ``tensegrity-opt: answer: ...`` on stderr, exit status 1 -
    a fact about the chain, not a bad input (2). The HTTP API answers the same with 422 and its ``code``."""
    text = " ".join(str(exc).split()) or type(exc).__name__
    print(f"tensegrity-opt: answer: {text}", file=sys.stderr)
    return 1


def error(message: object) -> int:
    """Print ``tensegrity-opt: error: MESSAGE`` (one line) on stderr; the exit status of a bad input, 2."""
    text = " ".join(str(message).split()) or type(message).__name__
    print(f"tensegrity-opt: error: {text}", file=sys.stderr)
    return 2


def note(message: object) -> None:
    """Print ``tensegrity-opt: note: MESSAGE`` on stderr: something the result's reader must know (a partial
    curve) that is not an error (the exit status stays 0)."""
    print(f"tensegrity-opt: note: {message}", file=sys.stderr)


def _integer(text: str, least: int, expected: str) -> int:
    """``text`` as an integer ``>= least``, else a usage error ``expected EXPECTED, got ...`` (exit 2)."""
    try:
        v = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected {expected}, got {text!r}") from None
    if v < least:
        raise argparse.ArgumentTypeError(f"expected {expected}, got {v}")
    return v


def positive_int(text: str) -> int:
    """An argparse type: an integer >= 1 (a count: points, segments, panels), else a usage error (exit 2)."""
    return _integer(text, 1, "an integer >= 1")


def non_negative_int(text: str) -> int:
    """An argparse type: an integer >= 0 (a depth), else a usage error (exit 2)."""
    return _integer(text, 0, "an integer >= 0")


def joint_index(text: str) -> int:
    """An argparse type: a joint's index, 0-based, else a usage error (exit 2)."""
    return _integer(text, 0, "a joint index (an integer >= 0)")


def at_least_two(text: str) -> int:
    """An argparse type: an integer >= 2 (a branch's points, the start included; samples), else a usage error."""
    v = positive_int(text)
    if v < 2:
        raise argparse.ArgumentTypeError(f"expected an integer >= 2, got {v}")
    return v


#: Longest uniform chain the command line builds (``--n``): beyond it the dense solvers' n x n matrices alone
#: take gigabytes and a command would run for hours or exhaust memory instead of answering.
MAX_SEGMENTS = 10_000


def segment_count(text: str) -> int:
    """An argparse type: a number of segments, 1 ..  :data:`MAX_SEGMENTS`, else a usage error (exit 2)."""
    v = positive_int(text)
    if v > MAX_SEGMENTS:
        raise argparse.ArgumentTypeError(f"expected at most {MAX_SEGMENTS} segments (the command line's limit: "
                                         f"the solvers' n x n matrices), got {v}")
    return v


def finite_float(text: str) -> float:
    """An argparse type: a finite number, else a usage error (exit 2)."""
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, got {text!r}") from None
    if not math.isfinite(v):
        raise argparse.ArgumentTypeError(f"expected a finite number, got {text!r}")
    return v


def positive_float(text: str) -> float:
    """An argparse type: a finite number > 0 (a bound, a rate, seconds), else a usage error (exit 2)."""
    v = finite_float(text)
    if v <= 0:
        raise argparse.ArgumentTypeError(f"expected a number > 0, got {text!r}")
    return v


def non_negative_float(text: str) -> float:
    """An argparse type: a finite number >= 0 (a margin), else a usage error (exit 2)."""
    v = finite_float(text)
    if v < 0:
        raise argparse.ArgumentTypeError(f"expected a number >= 0, got {text!r}")
    return v


def fmt_q(q) -> str:
    """``[+0.10000, -0.20000]``: angles (or any short vector) for a table."""
    return "[" + ", ".join(f"{v:+.5f}" for v in q) + "]"


def springs_text(result) -> str:
    """The springs of a result that are not taut, ``"spring 3.2 pushes 0.469; spring 1.1 slack"`` (segment.spring,
    counted from 1), or ``""`` when every spring is taut (or the state is unknown)."""
    sp = result._spring_model() if hasattr(result, "_spring_model") else None
    return "" if sp is None else "; ".join(sp.summary(result.q))


def stops_text(eq) -> str:
    """The joints of an equilibrium resting on their stops, ``"joint 3 on its stop (contact 0.21)"`` (counted from
    1), or ``""``."""
    at = getattr(eq, "at_stop", None)
    if at is None:
        return ""
    return "; ".join(f"joint {j + 1} on its stop (contact {eq.contact_torques[j]:.3g})"
                     for j, on in enumerate(at) if on)


def eq_table(eqs) -> list[str]:
    """The table of equilibria (energy, force, Morse index, stability, shape, q, the joints on a stop and the springs
    that are not taut) the commands print."""
    lines = [f"{'#':>2} {'energy':>12} {'Fx':>10} {'Fy':>10} {'morse':>5} {'stable':>6} {'shape':>5}  q (rad)"
             "  stops, springs not taut"]
    for i, e in enumerate(eqs, 1):
        notes = "; ".join(t for t in (stops_text(e), springs_text(e)) if t)
        lines.append(f"{i:>2} {e.energy:>12.6f} {e.fx:>10.6f} {e.fy:>10.6f} {e.morse_index:>5} "
                     f"{'yes' if e.stable else 'no':>6} {e.shape:>5}  {fmt_q(e.q)}  {notes or '-'}")
    return lines


def add_manipulator_options(sp: argparse.ArgumentParser) -> None:
    """The manipulator options every analysis command takes (uniform chain or a JSON file)."""
    g = sp.add_argument_group("manipulator (default: the paper's chain n=4, a=b=k=L0=1)")
    g.add_argument("--n", type=segment_count, default=4, help=f"number of identical segments (1 to {MAX_SEGMENTS})")
    g.add_argument("--a", type=finite_float, default=1.0, help="triangle half-height a (length)")
    g.add_argument("--b", type=finite_float, default=1.0,
                   help="triangle half-length b (length; a segment is 2 b long straight)")
    g.add_argument("--k", type=finite_float, default=1.0, help="spring stiffness (force / length)")
    g.add_argument("--L0", type=finite_float, default=1.0, help="spring rest length (length)")
    g.add_argument("--spring", choices=tuple(SPRING_LAWS), default="linear",
                   help="the springs' law: linear (the paper's: a spring shorter than its rest length pushes) or "
                        "tension_only (it goes slack)")
    g.add_argument("--mass", type=finite_float, default=0.0,
                   help="each segment's mass (two triangles, centroids 2b/3 from the joint; no effect on equilibria "
                        "without gravity; sets the vibration modes)")
    g.add_argument("--inertia", type=finite_float, default=0.0,
                   help="each triangle's rotational inertia about its centroid (mass x length^2)")
    g.add_argument("--payload", type=finite_float, default=0.0, help="a point mass at the tip")
    g.add_argument("--gravity", type=finite_float, nargs=2, metavar=("GX", "GY"), default=None,
                   help="the gravity vector in the chain's plane (e.g. 0 -9.81: the chain along +x in a vertical "
                        "plane); the masses and the payload then weigh on it")
    g.add_argument("--joint-force", dest="joint_forces", type=finite_float, nargs=3, action="append",
                   metavar=("J", "FX", "FY"), default=None,
                   help="a dead force (FX, FY) at joint J (counted from 1 at the base); repeat for several joints")
    g.add_argument("--manipulator", metavar="FILE",
                   help='JSON file {"segments": [{"a","b","k","L0","spring","mass","inertia"}, ...], "payload", '
                        '"gravity", "joint_forces"}, instead of the uniform chain\'s options')
    exclusive(sp, ["--manipulator"], ["--n", "--a", "--b", "--k", "--L0", "--spring", "--mass", "--inertia",
                                      "--payload", "--gravity", "--joint-force"],
              "the chain comes from the file or from the uniform chain's options")



def add_deflection_options(sp: argparse.ArgumentParser, number=finite_float) -> None:
    """``--dx``, ``--dy``: one tip deflection (``number`` parses each)."""
    sp.add_argument("--dx", type=number, default=0.1, help="tip deflection along the chain (length)")
    sp.add_argument("--dy", type=number, default=0.0, help="sideways tip deflection (length)")


def add_curve_options(sp: argparse.ArgumentParser, num: int, number=finite_float) -> None:
    """``--start``, ``--stop``, ``--num`` (default ``num``), ``--dy``: the deflections of a force-deflection curve
    (``number`` parses each)."""
    sp.add_argument("--start", type=number, default=0.0, help="first tip deflection dx (length)")
    sp.add_argument("--stop", type=number, default=1.0, help="last tip deflection dx (length)")
    sp.add_argument("--num", type=positive_int, default=num, help="number of deflections, evenly spaced")
    sp.add_argument("--dy", type=number, default=0.0, help="sideways tip deflection (length)")


def add_analysis_options(sp: argparse.ArgumentParser,
                         json_help: str = "print the API body (JSON) instead of a table") -> None:
    """An analysis command's options: the manipulator's (:func:`add_manipulator_options`) and ``--json``."""
    add_manipulator_options(sp)
    sp.add_argument("--json", action="store_true", help=json_help)


def add_command(subparsers, name: str, func, help: str,
                json_help: str = "print the API body (JSON) instead of a table") -> argparse.ArgumentParser:
    """An analysis command ``name`` (``help`` its line in the list of commands) in ``subparsers``
    (``add_subparsers()``'s result) running ``func(args, m) -> (data, text)`` (:func:`run_command`), with its
    analysis options (:func:`add_analysis_options`); returns its parser for the command's own options."""
    sp = subparsers.add_parser(name, formatter_class=HELP_FORMAT, help=help)
    add_analysis_options(sp, json_help)
    sp.set_defaults(func=func)
    return sp


def _manipulator(args: argparse.Namespace) -> Manipulator:
    if args.manipulator:
        with open(args.manipulator, encoding="utf-8") as fh:
            data = json.load(fh)
        if not isinstance(data, dict) or not isinstance(data.get("segments"), list):
            raise InvalidParameterError(f"--manipulator {args.manipulator}: expected a JSON object "
                                        '{"segments": [{"a", "b", "k", "L0"}, ...]}', field="manipulator")
        return Manipulator.from_dict(data)
    forces = []
    for j, fx, fy in args.joint_forces or ():
        if j != int(j):
            raise InvalidParameterError(f"--joint-force: the joint must be an integer, got {j:g}",
                                        field="joint_forces")
        forces.append((int(j), (fx, fy)))
    return Manipulator.uniform(args.n, args.a, args.b, args.k, args.L0, args.spring, args.mass, args.inertia,
                               args.payload, args.gravity, forces)


def run_command(parser: argparse.ArgumentParser, argv: list[str] | None) -> int:
    """Parse ``argv`` with ``parser`` and run the command; the exit status.

    A command either handles its own arguments (``run=callable(args) -> status``) or is an analysis
    (``func=callable(args, manipulator) -> (data, text)``) printing ``text``, or with ``--json`` the
    result's ``to_dict()`` (``data``, called only then) - the body the HTTP API answers.

    Every bad input is one line ``tensegrity-opt: error: ...`` on stderr and exit status 2: argparse's
    usage errors (:class:`Parser`), and what the command raises for its input - a domain error
    (:class:`~tensegrity_opt.errors.TensegrityError`, a ``ValueError`` or ``RuntimeError`` naming the field),
    any other ``ValueError``/``TypeError``, an unreadable file (``OSError``, bad JSON) - never a traceback."""
    args = parser.parse_args(argv)
    if getattr(args, "run", None) is not None:
        return args.run(args)
    try:
        m = _manipulator(args)
        data, text = args.func(args, m)
        if args.json:
            text = json.dumps(data() if callable(data) else data, indent=2)
        elif m.loaded:                          # every answer says the loads it was computed under
            text = f"{text}\nunder the chain's dead loads: {describe(loads_key(m))}"
    except (StraightNotEquilibriumError, UnstableStraightError) as exc:
        return answer(exc)
    except (TensegrityError, NonFiniteResult, OSError, ValueError, TypeError) as exc:
        return error(exc)
    try:
        print(text)
        sys.stdout.flush()
    except BrokenPipeError:           # the reader went away (``| head``): not an error of the command
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    return 0
