"""What every command of the command line shares: the manipulator options, the chain they
describe, and running a parsed command (table or ``--json``, one-line errors, exit status 2).

Below both :mod:`tensegrity_opt.applications.cli` (the parser of every command) and its command
modules (:mod:`.plot`, :mod:`.sweep`), so neither imports the other back.
"""

from __future__ import annotations

import argparse
import json
import sys

from ...errors import NonFiniteResult, TensegrityError
from ...model.manipulator import Manipulator

__all__ = ["add_manipulator_options", "run_command"]


def add_manipulator_options(sp: argparse.ArgumentParser) -> None:
    """The manipulator options every analysis command takes (uniform chain or a JSON file)."""
    g = sp.add_argument_group("manipulator (default: the paper's chain n=4, a=b=k=L0=1)")
    g.add_argument("--n", type=int, default=4, help="number of segments")
    g.add_argument("--a", type=float, default=1.0)
    g.add_argument("--b", type=float, default=1.0)
    g.add_argument("--k", type=float, default=1.0)
    g.add_argument("--L0", type=float, default=1.0)
    g.add_argument("--manipulator", metavar="FILE", help='JSON file {"segments": [{"a","b","k","L0"}, ...]}')



def _manipulator(args: argparse.Namespace) -> Manipulator:
    if args.manipulator:
        with open(args.manipulator, encoding="utf-8") as fh:
            return Manipulator.from_dict(json.load(fh))
    return Manipulator.uniform(args.n, args.a, args.b, args.k, args.L0)


def run_command(parser: argparse.ArgumentParser, argv: list[str] | None) -> int:
    """Parse ``argv`` with ``parser`` and run the command; the exit status.

    A command either handles its own arguments (``run=callable(args) -> status``) or is an analysis
    (``func=callable(args, manipulator) -> (data, text)``) printing ``text``, or with ``--json`` the
    result's ``to_dict()`` (``data``, called only then) - the body the HTTP API answers."""
    args = parser.parse_args(argv)
    if getattr(args, "run", None) is not None:
        return args.run(args)
    try:
        m = _manipulator(args)
        data, text = args.func(args, m)
        if args.json:
            text = json.dumps(data() if callable(data) else data, indent=2)
    except (TensegrityError, NonFiniteResult, OSError, json.JSONDecodeError, TypeError) as exc:
        print(f"tensegrity-opt: error: {exc}", file=sys.stderr)
        return 2
    print(text)
    return 0
