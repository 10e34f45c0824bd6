"""``tensegrity-opt sweep spec.json [-o out.csv|out.json|out.parquet] [--scheduler ...] [--[no-]progress]``.

Wired into :mod:`tensegrity_opt.applications.cli` by :func:`add_sweep_parser` (the command handles
its own arguments, so it registers as a ``run`` command returning the exit status).
Without ``-o`` the rows go to stdout as CSV. The scheduler defaults to ``auto``: serially in this
process for a small sweep, a local Dask cluster only where its start pays off (measured:
benchmarks/RESULTS.md, "Sweep scheduler default"; :func:`tensegrity_opt.applications.sweeps.scheduler.auto_scheduler`);
``serial`` solves in this process, ``threads`` in a pool of threads of this process, ``local`` on a
``dask.distributed.LocalCluster`` (one single-threaded worker process per core) and ``tcp://host:port``
on a running Dask scheduler.
A progress bar goes to stderr while it runs (by default when stderr is a terminal: ``--progress/--no-progress``,
:mod:`.progress`), and a one-line summary at the end (always). Errors (bad spec, unreadable file, unknown output type,
unreachable scheduler) print one line to stderr and exit with status 2; points that fail
are rows with an ``error`` and do not change the exit status.
"""

from __future__ import annotations

import argparse
import json
import logging
import os
import sys
from pathlib import Path
from typing import Any

from ...errors import TensegrityError
from ..sweeps.scheduler import AUTO_CLUSTER_SECONDS, AUTO_SERIAL_POINTS, SCHEDULERS
from .common import add_progress_option, add_rule
from .progress import Progress

__all__ = ["add_sweep_parser", "cmd_sweep"]

_SUFFIXES = (".csv", ".json", ".parquet", ".pq")


def add_sweep_parser(subparsers: Any) -> argparse.ArgumentParser:
    """Add the ``sweep`` subcommand to ``subparsers`` (from ``ArgumentParser.add_subparsers``)."""
    sp = subparsers.add_parser(
        "sweep", help="run one analysis over a grid or a list of design points (serial, threads or Dask)",
        description="Run a sweep spec (JSON: analysis, manipulator, grid | points, options; see "
                    "tensegrity_opt.applications.sweeps) and write one row per point.")
    sp.add_argument("spec", help="sweep spec, a JSON file ('-' reads stdin)")
    sp.add_argument("-o", "--output", metavar="FILE",
                    help="out.csv | out.json | out.parquet; None: CSV on stdout")
    sp.add_argument("--scheduler", default="auto", metavar="auto|serial|threads|local|tcp://HOST:PORT",
                    help=f"where to solve. auto: serially up to {AUTO_SERIAL_POINTS} points, else the first "
                         f"points serially, timed, and the rest on a local Dask cluster only if it would take "
                         f"more than {AUTO_CLUSTER_SECONDS:g} s serially (a cluster costs 5-8 s to start: the "
                         "README's 9-point buckling sweep took 5.3 s on it against 0.007 s serially; "
                         "benchmarks/RESULTS.md, 'Sweep scheduler default'); serial: this process; threads: a "
                         "pool of threads of this process (no consistent gain measured); local: a local Dask "
                         "cluster; tcp://HOST:PORT: a running Dask scheduler")
    sp.add_argument("--workers", type=int, default=None, metavar="N",
                    help="threads (threads) or worker processes (local, auto) of this machine; None: one per core")
    sp.add_argument("--chunk-size", type=int, default=None, metavar="N",
                    help="points per task (threads, Dask); None: about four tasks per worker, at most 64")
    add_progress_option(sp)
    add_rule(sp, _scheduler_rule)
    sp.set_defaults(run=cmd_sweep)
    return sp


def _scheduler_rule(ns: argparse.Namespace, given: frozenset[str]) -> str | None:
    """``--workers`` and ``--chunk-size`` are for the schedulers that use them: refused with ``serial`` (one point
    after the other in this process), ``--workers`` with a running Dask scheduler's address (its workers)."""
    if ns.scheduler == "serial":
        bad = next((o for o in ("--workers", "--chunk-size") if o in given), None)
        if bad:
            return f"argument {bad}: not allowed with --scheduler serial (one point after the other in this process)"
    elif "://" in ns.scheduler and "--workers" in given:
        return (f"argument --workers: not allowed with --scheduler {ns.scheduler} (the running Dask scheduler's "
                "workers solve)")
    return None


def _load_spec(path: str) -> Any:
    if path == "-":
        return json.load(sys.stdin)
    with open(path, encoding="utf-8") as fh:
        return json.load(fh)


def cmd_sweep(args: argparse.Namespace) -> int:
    from ..sweeps import sweep, validate_spec

    def fail(msg: object) -> int:
        print(f"tensegrity-opt: error: {msg}", file=sys.stderr)
        return 2

    scheduler = args.scheduler
    if scheduler not in SCHEDULERS and "://" not in scheduler:
        return fail(f"--scheduler: expected {', '.join(SCHEDULERS)} or tcp://host:port, got {scheduler!r}")
    if args.output and Path(args.output).suffix.lower() not in _SUFFIXES:
        return fail(f"--output: unknown file type {Path(args.output).suffix or '(none)'!r}; "
                    "use .csv, .json or .parquet")
    for name in ("workers", "chunk_size"):
        value = getattr(args, name)
        if value is not None and value < 1:
            return fail(f"--{name.replace('_', '-')} must be >= 1, got {value}")
    try:
        spec = validate_spec(_load_spec(args.spec))
    except (TensegrityError, OSError, json.JSONDecodeError) as exc:
        return fail(exc)
    if scheduler not in ("serial", "threads"):
        # Dask's INFO lines (cluster start and stop) would drown the summary.
        logging.getLogger("distributed").setLevel(logging.WARNING)
    bar = Progress("sweep", unit="pt", enabled=args.progress)
    try:
        result = sweep(spec, scheduler=scheduler, progress=bar, chunk_size=args.chunk_size, workers=args.workers)
    except TensegrityError as exc:
        return fail(exc)
    except (OSError, TimeoutError) as exc:
        return fail(f"cannot reach the Dask scheduler {scheduler!r}: {exc}")
    finally:
        bar.close()
    try:
        if args.output:
            out = result.save(args.output)
            where = f"written to {os.fspath(out)}"
        else:
            sys.stdout.write(result.csv_text())
            sys.stdout.flush()
            where = "written to stdout"
    except (TensegrityError, OSError, ImportError) as exc:
        return fail(exc)
    n_err = len(result.errors)
    print(f"sweep: {len(result.rows)} points ({spec['analysis']}, {result.scheduler}), {n_err} failed, "
          f"{result.elapsed:.1f} s; {where}", file=sys.stderr)
    return 0
