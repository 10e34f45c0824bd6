"""Command line control: ``tensegrity-opt plan|simulate|force-estimate ...``.

:func:`add_control_parsers` adds the three commands to the ``tensegrity-opt`` parser; each sets
``func(args, m) -> (data, text)`` like the other analysis commands (a table, or with ``--json`` the result's
``to_dict()``: the body of ``/v1/control/plan``, ``/v1/control/simulate``, ``/v1/control/force-estimate``). The
plan and simulation options (:func:`add_plan_options`, :func:`add_simulate_options`) are shared with
``plot plan|simulation`` (:mod:`.plot`).

Files: ``--targets`` (plan) is JSON, a list ``[[x, y], ...]`` or an object ``{"targets": [...], "loads": [...],
"end_angles": [...], "times": [...]}`` (the per-step series of ``/v1/control/plan``), or CSV with the columns
``x, y`` (then optionally ``fx, fy`` and ``end_angle``, ``nan`` for free), or CSV whose header row names its
columns among ``t`` (or ``time``: the step's instant, seconds), ``x``, ``y``, ``fx``, ``fy``, ``end_angle`` in any
order (another header row is skipped). ``--preloads`` (simulate) is
JSON ``(K, n, 2)`` (or ``{"preloads": ...}``) or CSV, one row of ``2n`` rest lengths per sample (``L1_0, L2_0`` of
segment 1, then of segment 2, ...); ``--targets`` (simulate, held tip) JSON ``(K, 2)`` or CSV ``dx, dy``.

Examples::

    tensegrity-opt plan --line 7.9 0.2 7.3 1.4 13 --margin 0.05
    tensegrity-opt plan --targets path.csv --load 0 -0.02 --rate-limit 0.05 --dt 0.5 --json
    tensegrity-opt simulate --n 3 --a 0.5 --load-cycle 0.3 --steps 121
    tensegrity-opt simulate --n 2 --preloads preloads.json
    tensegrity-opt simulate --tip held --targets targets.csv
    tensegrity-opt force-estimate --q 0.742754 0.522806 0.297158 0.0953 --sigma 1e-3
    tensegrity-opt force-estimate --q 0.742754 0.522806 0.0953 --measured 0 1 3 --sigma 1e-3
"""

from __future__ import annotations

import argparse
import csv
import json
import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from ...analyses.design.force_sensor import estimate_tip_force
from ...analyses.design.holding import preloads_for_holding
from ...analyses.design.load_capacity import load_capacity, weight_capacity
from ...analyses.design.preload_control import ON_INFEASIBLE, ON_SNAP, PreloadPlan, plan_preloads
from ...analyses.design.preloads import OBJECTIVES
from ...analyses.design.stiffness_shaping import preloads_for_stiffness
from ...analyses.paths.simulation import Simulation, simulate
from ...errors import InvalidParameterError
from ...model.manipulator import Manipulator
from .common import (
    add_command,
    add_progress_option,
    at_least_two,
    finite_float,
    fmt_q,
    joint_index,
    non_negative_float,
    only_with,
    positive_float,
    positive_int,
)
from .progress import Progress

__all__ = ["add_control_parsers", "add_plan_options", "add_simulate_options", "plan_from_args",
           "simulation_from_args", "load_cycle", "read_rows", "read_table", "PLAN_COLUMNS"]


def _angle_or_nan(text: str) -> float:
    """A joint angle, or ``nan`` (an unmeasured joint: only the solver's start)."""
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number (or nan), got {text!r}") from None
    if math.isinf(v):
        raise argparse.ArgumentTypeError(f"expected a finite number (or nan), got {text!r}")
    return v


# ---------------------------------------------------------------------------- files
def read_rows(path: str, field: str) -> Any:
    """The numbers of a JSON file (any nesting, or an object) or the rows of a CSV file (a header row skipped)."""
    return read_table(path, field)[1]


def read_table(path: str, field: str) -> tuple[list[str] | None, Any]:
    """``(header, numbers)``: a JSON file's numbers (any nesting, or an object; no header), or a CSV file's rows and
    its header row (the names lower-cased; None without one)."""
    p = Path(path)
    text = p.read_text(encoding="utf-8")
    if p.suffix.lower() == ".json" or text.lstrip()[:1] in ("[", "{"):
        try:
            return None, json.loads(text)
        except json.JSONDecodeError as exc:
            raise InvalidParameterError(f"--{field}: {path} is not valid JSON ({exc})", field=field) from None
    rows = []
    header = None
    for i, row in enumerate(csv.reader(text.splitlines())):
        cells = [c.strip() for c in row if c.strip()]
        if not cells or cells[0].startswith("#"):
            continue
        try:
            rows.append([float(c) for c in cells])
        except ValueError:
            if i == 0 and not rows:
                header = [c.lower() for c in cells]
                continue                        # a header
            raise InvalidParameterError(f"--{field}: {path} line {i + 1} is not a row of numbers: {row!r}",
                                        field=field) from None
    if not rows:
        raise InvalidParameterError(f"--{field}: {path} holds no rows of numbers", field=field)
    if len({len(r) for r in rows}) != 1:
        raise InvalidParameterError(f"--{field}: the rows of {path} differ in length", field=field)
    return header, rows


def _array(v: Any, field: str) -> np.ndarray:
    try:
        return np.asarray(v, dtype=float)
    except (TypeError, ValueError):
        raise InvalidParameterError(f"--{field}: expected arrays of numbers", field=field) from None


#: The names of a plan's CSV columns (a header row naming each column; any order).
PLAN_COLUMNS = {"x": "x", "y": "y", "fx": "fx", "fy": "fy", "end_angle": "end_angle", "t": "time", "time": "time",
                "times": "time"}


def _named_columns(header: list[str], A: np.ndarray) -> dict[str, np.ndarray] | None:
    """The columns of a CSV whose header names every column (:data:`PLAN_COLUMNS`) by name; None otherwise (the
    header is only skipped)."""
    names = [PLAN_COLUMNS.get(h) for h in header]
    if len(header) != A.shape[1] or None in names or len(set(names)) != len(names):
        return None
    cols = dict(zip(names, A.T))
    if "x" not in cols or "y" not in cols or ("fx" in cols) != ("fy" in cols):
        raise InvalidParameterError(f"--targets: the columns {header} need x and y (and fx with fy)", field="targets")
    return cols


def _plan_inputs(args: argparse.Namespace) -> tuple[np.ndarray, Any, Any, Any]:
    """``(targets, loads, end_angles, times)`` from ``--targets FILE`` or ``--line``, ``--load``, ``--end-angle``
    and ``--times``."""
    loads: Any = None
    angles: Any = None
    times: Any = None
    if args.line is not None:
        x0, y0, x1, y1, num = args.line
        if num != int(num) or num < 1:
            raise InvalidParameterError(f"--line X0 Y0 X1 Y1 NUM: NUM must be an integer >= 1, got {num:g}",
                                        field="line")
        T = np.column_stack([np.linspace(x0, x1, int(num)), np.linspace(y0, y1, int(num))])
    else:
        header, data = read_table(args.targets, "targets")
        named = None
        if isinstance(data, dict):
            unknown = set(data) - {"targets", "loads", "end_angles", "times"}
            if unknown or "targets" not in data:
                raise InvalidParameterError(f"--targets: a JSON object holds 'targets' (and optionally 'loads', "
                                            f"'end_angles', 'times'), got {sorted(data)}", field="targets")
            T = _array(data["targets"], "targets")
            loads = data.get("loads")
            angles = data.get("end_angles")
            angles = None if angles is None else [math.nan if a is None else a for a in angles]
            times = data.get("times")
        elif header is not None and (named := _named_columns(header, _array(data, "targets"))) is not None:
            T = np.column_stack([named["x"], named["y"]])
            loads = np.column_stack([named["fx"], named["fy"]]) if "fx" in named else None
            angles = named.get("end_angle")
            times = named.get("time")
        else:
            A = _array(data, "targets")
            if A.ndim != 2 or A.shape[1] not in (2, 4, 5):
                raise InvalidParameterError(f"--targets: expected rows x, y [, fx, fy [, end_angle]], got shape "
                                            f"{A.shape}", field="targets")
            T = A[:, :2]
            if A.shape[1] >= 4:
                loads = A[:, 2:4]
            if A.shape[1] == 5:
                angles = A[:, 4]
    if args.load is not None:
        if loads is not None:
            raise InvalidParameterError("give the load by --load or in the --targets file, not both", field="load")
        loads = list(args.load)
    if args.end_angle is not None:
        if angles is not None:
            raise InvalidParameterError("give the end angle by --end-angle or in the --targets file, not both",
                                        field="end_angle")
        angles = np.full(len(T), args.end_angle)
    if args.times is not None:
        if times is not None:
            raise InvalidParameterError("give the steps' times by --times or in the --targets file, not both",
                                        field="times")
        times = list(args.times)
    return T, loads, angles, times


def _horizon(text: str) -> int | str:
    """``--horizon``: a positive int or ``all``."""
    if text == "all":
        return text
    try:
        n = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"a positive int or 'all', got {text!r}") from None
    if n < 1:
        raise argparse.ArgumentTypeError(f"a positive int or 'all', got {text!r}")
    return n


def _rest_lengths0(values: list[float] | None) -> np.ndarray | None:
    """``--rest-lengths0``: 2n numbers, ``L1_0, L2_0`` of segment 1, then of segment 2, ... as (n, 2)."""
    if values is None:
        return None
    a = np.asarray(values, dtype=float)
    return a.reshape(-1, 2) if a.size % 2 == 0 else a


def plan_from_args(args: argparse.Namespace, m: Manipulator,
                   progress: Callable[[int, int], Any] | None = None) -> PreloadPlan:
    T, loads, angles, times = _plan_inputs(args)
    return plan_preloads(m, T, loads=loads, end_angles=angles, times=times, dt=args.dt,
                         rest_lengths0=_rest_lengths0(args.rest_lengths0),
                         bounds=None if args.bounds is None else tuple(args.bounds),
                         rate_limit=args.rate_limit, margin=args.margin, objective=args.objective,
                         start=None if args.start_q is None else np.asarray(args.start_q, dtype=float),
                         on_infeasible=args.on_infeasible, horizon=args.horizon, verify=not args.no_verify,
                         on_snap=args.on_snap, taut=args.taut, timeout=args.timeout, progress=progress)


def load_cycle(amplitude: float, steps: int, direction: Any = (0.0, 1.0)) -> np.ndarray:
    """``steps`` loads ``f d`` with ``f`` from 0 up to ``amplitude``, down to ``-amplitude`` and back to 0 (piecewise
    linear in the sample index), ``d`` the unit ``direction``."""
    d = np.asarray(direction, dtype=float)
    nrm = float(np.linalg.norm(d))
    if not nrm > 0.0 or not math.isfinite(nrm):
        raise InvalidParameterError("--load-direction must be a nonzero vector", field="load_direction")
    t = np.linspace(0.0, 4.0, steps)
    f = amplitude * np.interp(t, [0.0, 1.0, 3.0, 4.0], [0.0, 1.0, -1.0, 0.0])
    return np.outer(f, d / nrm)


def _preloads(path: str, m: Manipulator) -> np.ndarray:
    data = read_rows(path, "preloads")
    if isinstance(data, dict):
        if set(data) != {"preloads"}:
            raise InvalidParameterError(f"--preloads: a JSON object holds 'preloads' only, got {sorted(data)}",
                                        field="preloads")
        data = data["preloads"]
    P = _array(data, "preloads")
    if P.ndim == 2 and P.shape[1] == 2 * m.n:            # CSV: one row of 2n numbers per sample
        P = P.reshape(P.shape[0], m.n, 2)
    return P


def simulation_from_args(args: argparse.Namespace, m: Manipulator,
                         progress: Callable[[int, int], Any] | None = None) -> Simulation:
    P = None if args.preloads is None else _preloads(args.preloads, m)
    loads = None
    if args.load_cycle is not None:
        if args.tip == "held":
            raise InvalidParameterError("--load-cycle loads a free tip; a held tip takes --targets", field="load_cycle")
        steps = args.steps if args.steps is not None else (P.shape[0] if P is not None and P.ndim == 3 else 121)
        loads = load_cycle(args.load_cycle, steps, args.load_direction)
    elif args.steps is not None:
        raise InvalidParameterError("--steps is the length of a --load-cycle", field="steps")
    targets = None if args.targets is None else _array(read_rows(args.targets, "targets"), "targets")
    if args.tip == "free" and targets is not None:
        raise InvalidParameterError("--targets are for a held tip (--tip held)", field="targets")
    if P is None and loads is None and targets is None:
        raise InvalidParameterError("give --load-cycle, --preloads or (with --tip held) --targets", field="load_cycle")
    return simulate(m, P, loads, tip=args.tip, targets=targets,
                    start=None if args.start_q is None else np.asarray(args.start_q, dtype=float),
                    perturbation=args.perturbation, timeout=args.timeout, progress=progress)


# ---------------------------------------------------------------------------- shared options
def add_plan_options(sp: argparse.ArgumentParser) -> None:
    g = sp.add_argument_group("targets (one of)")
    one = g.add_mutually_exclusive_group(required=True)
    one.add_argument("--targets", metavar="FILE", default=None,
                     help="tip positions per step: JSON [[x, y], ...] or {\"targets\", \"loads\", \"end_angles\", "
                          "\"times\"}, or CSV rows x, y [, fx, fy [, end_angle]] (length, force, rad), or CSV with a "
                          "header naming its columns among t (or time; seconds), x, y, fx, fy, end_angle")
    one.add_argument("--line", type=finite_float, nargs=5, default=None, metavar=("X0", "Y0", "X1", "Y1", "NUM"),
                     help="NUM tip positions evenly spaced from (X0, Y0) to (X1, Y1) (length)")
    g = sp.add_argument_group("the plan")
    g.add_argument("--load", type=finite_float, nargs=2, default=None, metavar=("FX", "FY"),
                   help="the dead tip load of every step (force; None: none, or the file's)")
    g.add_argument("--end-angle", type=finite_float, default=None,
                   help="the last link's absolute angle at every step (rad; None: free)")
    g.add_argument("--bounds", type=positive_float, nargs=2, default=None, metavar=("LO", "HI"),
                   help="actuator bounds on every rest length (length; None: 0.1 b_min, 4 b_max)")
    g.add_argument("--rate-limit", type=positive_float, default=None,
                   help="largest speed of each rest length (length per second; None: no limit): step k changes each "
                        "by at most RATE_LIMIT * (t_k - t_{k-1}); needs --dt, --times or a time column")
    g.add_argument("--dt", type=positive_float, default=None, metavar="SECONDS",
                   help="a fixed time between steps: t_k = (k + 1) DT (the start is the state at time 0)")
    g.add_argument("--times", type=positive_float, nargs="+", default=None, metavar="T",
                   help="the steps' instants (seconds, one per target, increasing from a first one > 0; the start "
                        "is the state at time 0)")
    g.add_argument("--rest-lengths0", type=positive_float, nargs="+", default=None, metavar="L",
                   help="the arm's current rest lengths, 2n numbers (L1_0, L2_0 of segment 1, then of segment 2, "
                        "...; length): the start is an equilibrium with them and the first step's change is "
                        "measured from them; None: the chain's own")
    g.add_argument("--margin", type=non_negative_float, default=1e-3,
                   help="required stability margin: the smallest eigenvalue of the Hessian of E - F . tip, "
                        "absolute, torque / rad (times the chain's torque scale max k c^2 for a relative one)")
    g.add_argument("--objective", choices=OBJECTIVES, default="change",
                   help="change: least change from the previous step (Newton, IPOPT where a bound is active); "
                        "margin: largest margin; energy: least spring energy (IPOPT)")
    g.add_argument("--start-q", type=finite_float, nargs="+", default=None, metavar="Q",
                   help="the start configuration (rad, n angles) with the start's rest lengths (--rest-lengths0) "
                        "under the first load; None: reached from the least-energy rest configuration")
    g.add_argument("--on-infeasible", choices=ON_INFEASIBLE, default="hold",
                   help="what an infeasible step commands: hold the previous command, or approach: the rest "
                        "lengths of the admissible pose nearest to the target (within the bounds, the rate limit "
                        "and the margin)")
    g.add_argument("--horizon", type=_horizon, default=None, metavar="N|all",
                   help="plan N steps at a time as one IPOPT problem (receding horizon: the first applied), or all "
                        "the trajectory at once; default step by step")
    g.add_argument("--no-verify", action="store_true",
                   help="do not follow each step's transition (the previous command and load moving linearly to the "
                        "step's): the end pose only, nothing verified")
    g.add_argument("--on-snap", choices=ON_SNAP, default="continue",
                   help="when the arm snaps during a step (nothing admissible avoids it) or has no equilibrium (a "
                        "joint reaches its stop): continue from where it went, or stop the plan after that step")
    g.add_argument("--taut", action="store_true",
                   help="keep every spring in tension at every planned pose (required for --spring tension_only)")
    g.add_argument("--timeout", type=positive_float, default=None,
                   help="seconds; then the steps done so far (status time_limit)")


def add_simulate_options(sp: argparse.ArgumentParser) -> None:
    g = sp.add_argument_group("inputs (a load cycle, preloads from a file, or the targets of a held tip)")
    g.add_argument("--load-cycle", type=finite_float, default=None, metavar="F_MAX",
                   help="a dead tip load along --load-direction from 0 up to F_MAX, down to -F_MAX and back to 0 "
                        "(force; tip free)")
    g.add_argument("--steps", type=at_least_two, default=None,
                   help="samples of the load cycle (None: 121, or the preloads' count)")
    g.add_argument("--load-direction", type=finite_float, nargs=2, default=[0.0, 1.0], metavar=("DX", "DY"),
                   help="direction of the load cycle (normalised)")
    g.add_argument("--preloads", metavar="FILE", default=None,
                   help="rest lengths per sample: JSON (K, n, 2) or CSV rows of 2n numbers (L1_0, L2_0 per segment; "
                        "length); None: the chain's own")
    g.add_argument("--tip", choices=("free", "held"), default="free",
                   help="free: loaded by the load cycle (or unloaded); held: at --targets")
    g.add_argument("--targets", metavar="FILE", default=None,
                   help="held tip: the deflections per sample, JSON (K, 2) or CSV rows dx, dy (length)")
    g.add_argument("--start-q", type=finite_float, nargs="+", default=None, metavar="Q",
                   help="the state at sample 0 (rad, n angles; a stable equilibrium under the first inputs); "
                        "None: the least-energy one")
    only_with(sp, ["--load-direction"], "--load-cycle")
    g.add_argument("--perturbation", type=positive_float, default=1e-4,
                   help="a snap's descent starts this far from the fold along its null vector (rad, < 0.1)")
    g.add_argument("--timeout", type=positive_float, default=None,
                   help="seconds; then the samples done so far (status time_limit)")


# ---------------------------------------------------------------------------- the commands
def _cmd_plan(args: argparse.Namespace, m: Manipulator) -> tuple[Any, str]:
    with Progress("plan", unit="step", enabled=args.progress) as bar:
        p = plan_from_args(args, m, progress=bar)
        K = len(p.method)
        bar.close(f"{K} steps in {bar.seconds:.1f} s, {int(np.sum(p.feasible))} feasible, "
                  f"{int(np.sum(p.verified))} verified, status {p.status}")
    timed = bool(np.all(np.isfinite(p.times)))
    how = "step by step" if p.horizon is None else f"horizon {p.horizon}"
    lines = [f"Preload plan, n = {m.n}, {how}, objective {args.objective}, on infeasible steps {p.on_infeasible}: "
             f"{K} steps, "
             f"{int(np.sum(p.feasible))} feasible, {int(np.sum(p.verified))} verified, status {p.status} "
             f"({p.seconds:.2f} s)",
             f"{'#':>4} " + (f"{'t (s)':>9} " if timed else "") + f"{'target x':>9} {'target y':>9} {'tip x':>9} "
             f"{'tip y':>9} {'tip err.':>9} {'margin':>9} {'on move':>9} {'status':>14} {'verif.':>6} {'method':>7}  "
             "command [L1_0, L2_0] per segment"]
    for k in range(K):
        mg = "-" if not math.isfinite(p.margin[k]) else f"{p.margin[k]:.5f}"
        mv = "-" if not math.isfinite(p.transition_margin[k]) else f"{p.transition_margin[k]:.5f}"
        rl = " ".join(f"[{a:.4f}, {b:.4f}]" for a, b in p.commands[k])
        lines.append(f"{k:>4} " + (f"{p.times[k]:>9.4g} " if timed else "")
                     + f"{p.targets[k, 0]:>9.5f} {p.targets[k, 1]:>9.5f} {p.tip[k, 0]:>9.5f} {p.tip[k, 1]:>9.5f} "
                     f"{p.tip_error[k]:>9.2e} {mg:>9} {mv:>9} {p.steps[k].status:>14} "
                     f"{'yes' if p.verified[k] else 'no':>6} {p.method[k]:>7}  {rl}")
    for k, st in enumerate(p.steps):
        for e in st.events:
            if e.q_after is not None:
                lines.append(f"step {k}: the arm snaps at {e.fraction:.4g} of its move (largest joint motion "
                             f"{e.distance:.3g} rad) and lands with the tip at ({e.tip_after[0]:.6g}, "
                             f"{e.tip_after[1]:.6g})")
            else:
                lines.append(f"step {k}: a joint reaches its stop at {e.fraction:.4g} of its move: no equilibrium")
    lines.append(p.message)
    return p.to_dict, "\n".join(lines)


def _cmd_simulate(args: argparse.Namespace, m: Manipulator) -> tuple[Any, str]:
    with Progress("simulate", unit="sample", enabled=args.progress) as bar:
        sim = simulation_from_args(args, m, progress=bar)
        bar.close(f"{len(sim)} of {sim.steps} samples in {bar.seconds:.1f} s, {len(sim.snaps)} snap(s), "
                  f"status {sim.status}")
    held = sim.mode == "held"
    D = sim.deflection
    lines = [f"Quasi-static simulation, {sim.mode} tip, n = {m.n}: {len(sim)} of {sim.steps} samples, "
             f"status {sim.status}: {sim.message}",
             f"{'#':>4} {'Fx':>10} {'Fy':>10} {'dx':>10} {'dy':>10} {'energy':>11} {'morse':>5}  q (rad)"
             + ("   (F: the holding force)" if held else "")]
    for i in range(len(sim)):
        lines.append(f"{i:>4} {sim.force[i, 0]:>10.6f} {sim.force[i, 1]:>10.6f} {D[i, 0]:>10.5f} {D[i, 1]:>10.5f} "
                     f"{sim.energy[i]:>11.6f} {int(sim.morse_index[i]):>5}  {fmt_q(sim.q[i])}")
    if not sim.events:
        lines.append("events: none")
    else:
        lines.append(f"events ({len(sim.events)}):")
        for e in sim.events:
            where = e.target if held else e.load
            rel = "" if e.energy_released is None else f", energy released {e.energy_released:.6g}"
            lines.append(f"  {e.kind:<11} at {e.time:.6f} (step {e.step} + {e.fraction:.6f}), "
                         f"{'target' if held else 'load'} {fmt_q(where)}{rel}"
                         + ("" if e.q_after is None else f": {fmt_q(e.q_before)} -> {fmt_q(e.q_after)}")
                         + (f" ({e.message})" if e.message else ""))
    return sim.to_dict, "\n".join(lines)


def _fmt_g(v: Any) -> str:
    """``[1.2e-07, -3.4e-07]``: small numbers (torques, chi-square parts) for a table."""
    return "[" + ", ".join(f"{x:.4g}" for x in np.asarray(v, float).ravel()) + "]"


def _sigma(values: list[float] | None, n: int, k: int) -> Any:
    """``--sigma``: one number, one per joint (n or k), or a covariance (n x n or k x k, row by row)."""
    if values is None:
        return None
    if len(values) == 1:
        return values[0]
    if len(values) in (n, k):
        return np.asarray(values)
    for size in (k, n):
        if len(values) == size * size:
            return np.asarray(values).reshape(size, size)
    raise InvalidParameterError(f"--sigma takes 1, {k if k != n else n}{f' or {n}' if k != n else ''} standard "
                                f"deviations or a covariance of {k * k}{f' or {n * n}' if k != n else ''} numbers, "
                                f"got {len(values)}", field="sigma_q")


def _cmd_force_estimate(args: argparse.Namespace, m: Manipulator) -> tuple[Any, str]:
    k = m.n if args.measured is None else len(args.measured)
    est = estimate_tip_force(m, np.asarray(args.q, dtype=float), sigma_q=_sigma(args.sigma, m.n, k),
                             measured=None if args.measured is None else np.asarray(args.measured, dtype=int))
    lines = [f"Tip force from the joint angles, n = {m.n}, joints measured {list(est.measured)}: "
             f"F = ({est.fx:.9g}, {est.fy:.9g}) ({est.status}, {est.iterations} iterations"
             + ("" if est.success else ", NOT settled") + ")"]
    if est.covariance is not None:
        sd = est.std
        rho = est.covariance[0, 1] / (sd[0] * sd[1]) if sd[0] > 0 and sd[1] > 0 else float("nan")
        lines.append(f"std (Fx, Fy) = ({sd[0]:.4g}, {sd[1]:.4g}), correlation {rho:.3f}")
        pv = "-" if est.p_value is None else f"{est.p_value:.4g}"
        lines.append(f"chi2 = {est.chi2:.6g} on {est.dof} degrees of freedom, p = {pv}")
        lines.append(f"joint chi2 (an extra torque at each joint) {_fmt_g(est.joint_chi2)}")
    lines.append(f"residual torque {_fmt_g(est.residual_torque)} (norm {est.residual_norm:.4g})")
    lines.append(f"configuration q = {fmt_q(est.q)}")
    if est.hidden_covariance is not None and est.hidden_covariance.size:
        lines.append(f"std of the unmeasured angles {_fmt_g(np.sqrt(np.diag(est.hidden_covariance)))}")
    return est.to_dict, "\n".join(lines)


def _cmd_stiffness(args: argparse.Namespace, m: Manipulator) -> tuple[Any, str]:
    K = None if args.K is None else np.array([[args.K[0], args.K[1]], [args.K[1], args.K[2]]])
    d = preloads_for_stiffness(m, tuple(args.target), K_desired=K,
                               eig_bounds=None if args.eig_bounds is None else tuple(args.eig_bounds),
                               load=tuple(args.load), margin=args.margin)
    lines = [f"Rest lengths for the tip at ({args.target[0]:g}, {args.target[1]:g}) under {tuple(args.load)}, "
             f"n = {m.n}: "
             f"{d.solver.status}" + ("" if d.exact or K is None else f", not exact (residual {d.residual:.3g})"),
             f"K = [[{d.K[0, 0]:.6g}, {d.K[0, 1]:.6g}], [{d.K[1, 0]:.6g}, {d.K[1, 1]:.6g}]] (force / length), "
             f"eigenvalues {_fmt_g(d.eigenvalues)}, margin {d.margin:.4g}",
             "rest lengths (L1_0, L2_0) per segment: " + "; ".join(f"{a:.6g}, {b:.6g}" for a, b in d.rest_lengths),
             "active bounds (segments 0-based; wider bounds may change the design): "
             + ("; ".join(b.describe() for b in d.active_bounds) or "none"),
             f"configuration q = {fmt_q(d.q)}"]
    return d.to_dict, "\n".join(lines)


def _cmd_holding(args: argparse.Namespace, m: Manipulator) -> tuple[Any, str]:
    d = preloads_for_holding(m, vary=args.vary, margin=args.margin, max_angle=args.max_angle)
    what = "rest-length changes (both springs; > 0: less preload)" if d.vary == "L0" else "stiffness scales"
    lines = [f"Holding design (n = {m.n}): {d.status}: {d.message}",
             f"{what} per segment: " + ", ".join(f"{v:.6g}" for v in d.change),
             f"total tension when straight {d.tension:.6g}, total stiffness {d.stiffness:.6g}",
             f"rest configuration q = {fmt_q(d.q)}"]
    return d.to_dict, "\n".join(lines)


def _cmd_weight_capacity(args: argparse.Namespace, m: Manipulator) -> tuple[Any, str]:
    w = weight_capacity(m, None, max_factor=args.max_factor)
    lines = [f"Weight capacity of the rest pose (n = {m.n}): {w.message}",
             f"rest configuration q = {fmt_q(w.start.q)}",
             f"at the {'limit' if w.kind != 'none' else 'end'} (x{w.end_factor:.6g}): q = {fmt_q(w.q)}"]
    return w.to_dict, "\n".join(lines)


def _cmd_load_capacity(args: argparse.Namespace, m: Manipulator) -> tuple[Any, str]:
    cap = load_capacity(m, None, base=tuple(args.base), directions=args.directions, boundary=args.boundary,
                        max_load=args.max_load)
    lines = [f"Load capacity of the rest pose (n = {m.n}, {args.boundary} tip, base load {tuple(args.base)}), "
             f"up to {args.max_load:g} more:", "  angle (deg)    load        kind          why"]
    for a, ld, k, r in zip(cap.angles, cap.loads, cap.kinds, cap.reasons):
        load = "-" if not math.isfinite(ld) else f"{ld:.6g}"
        lines.append(f"  {math.degrees(a):9.2f}   {load:>10}  {k:12}  {r or ''}")
    return cap.to_dict, "\n".join(lines)


def add_control_parsers(subparsers: Any) -> None:
    """Add ``plan``, ``simulate``, ``force-estimate``, ``stiffness-design``, ``holding-design``, ``weight-capacity`` and
    ``load-capacity`` to ``subparsers``
    (``add_subparsers()``'s result)."""

    sp = add_command(subparsers, "plan", _cmd_plan,
                     "rest lengths for a trajectory of tip positions, on one stable branch")
    add_plan_options(sp)
    add_progress_option(sp)

    sp = add_command(subparsers, "simulate", _cmd_simulate,
                     "quasi-static simulation under a load cycle, preloads or held-tip targets, with the snaps at "
                     "folds")
    add_simulate_options(sp)
    add_progress_option(sp)

    sp = add_command(subparsers, "force-estimate", _cmd_force_estimate,
                     "the tip force from measured joint angles (the arm as a force sensor)")
    sp.add_argument("--q", type=_angle_or_nan, nargs="+", required=True, metavar="Q",
                    help="joint angles (rad): all n (nan at an unmeasured joint: start at 0), or the measured ones "
                         "in joint order")
    sp.add_argument("--sigma", type=finite_float, nargs="+", default=None, metavar="S",
                    help="angle noise: one standard deviation (rad), one per joint, or a covariance matrix row by "
                         "row (rad^2); None: no noise model, no statistics")
    sp.add_argument("--measured", type=joint_index, nargs="+", default=None, metavar="J",
                    help="the measured joints (0-based); None: all")

    sp = add_command(subparsers, "stiffness-design", _cmd_stiffness,
                     "rest lengths for a stable pose with a shaped tip stiffness")
    sp.add_argument("--target", type=finite_float, nargs=2, required=True, metavar=("X", "Y"),
                    help="tip position (length)")
    sp.add_argument("--K", type=finite_float, nargs=3, default=None, metavar=("KXX", "KXY", "KYY"),
                    help="the wanted stiffness (force / length); None: only --eig-bounds")
    sp.add_argument("--eig-bounds", type=finite_float, nargs=2, default=None, metavar=("LO", "HI"),
                    help="bounds on both stiffness eigenvalues (force / length)")
    sp.add_argument("--load", type=finite_float, nargs=2, default=[0.0, 0.0], metavar=("FX", "FY"),
                    help="dead tip load (force)")
    sp.add_argument("--margin", type=non_negative_float, default=1e-3,
                    help="required stability margin: the smallest eigenvalue of the Hessian of E - F . tip, "
                         "absolute, torque / rad (times the chain's torque scale max k c^2 for a relative one)")

    sp = add_command(subparsers, "holding-design", _cmd_holding,
                     "the least preload (or stiffness) holding the chain up under its weight (--gravity)")
    sp.add_argument("--vary", choices=("L0", "k"), default="L0",
                    help="design the rest lengths (the preload) or the stiffnesses, per segment")
    sp.add_argument("--margin", type=non_negative_float, default=1e-3,
                    help="required stability margin: the smallest eigenvalue of the potential's Hessian (torque / "
                         "rad)")
    sp.add_argument("--max-angle", type=positive_float, default=None,
                    help="the sag allowed: every joint within this of straight (rad); default anywhere in range")

    sp = add_command(subparsers, "weight-capacity", _cmd_weight_capacity,
                     "how much heavier the chain may get (gravity scaled) before its rest pose snaps or buckles")
    sp.add_argument("--max-factor", type=positive_float, default=10.0,
                    help="follow the weights up to this multiple of gravity (> 1)")

    sp = add_command(subparsers, "load-capacity", _cmd_load_capacity,
                     "how much more tip load the rest pose carries, per direction")
    sp.add_argument("--directions", type=positive_int, default=8, help="evenly spaced directions")
    sp.add_argument("--base", type=finite_float, nargs=2, default=[0.0, 0.0], metavar=("FX", "FY"),
                    help="the load the pose already carries (force)")
    sp.add_argument("--boundary", choices=("free", "guided"), default="free", help="tip boundary condition")
    sp.add_argument("--max-load", type=positive_float, default=10.0, help="follow each path up to this extra load")
