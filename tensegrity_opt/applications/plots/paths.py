"""Figures of loading paths: branch diagrams, the load path of a limit load, the imperfection-sensitivity curve,
stability boundaries and the workspace stability atlas of the held tip."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from ...analyses.paths.atlas import StabilityAtlas
from ...analyses.paths.boundaries import StabilityBoundary
from ...analyses.paths.branches import Branch, BranchEvent, Control
from ...analyses.paths.events import SINGULAR_KINDS
from ...analyses.paths.imperfection import ImperfectionSensitivity
from ...analyses.paths.limit_load import LimitLoad
from ...errors import InvalidParameterError
from ...model.manipulator import Manipulator
from .style import ENERGY_UNIT, FORCE_UNIT, chain_label, legend_beside, new_figure, number_text

__all__ = ["plot_branches", "plot_limit_load", "plot_imperfection", "plot_boundary", "plot_atlas",
           "branch_quantity_label", "boundary_parameter_label", "morse_color", "BRANCH_QUANTITIES", "BRANCH_DEFAULT_X",
           "BRANCH_DEFAULT_Y", "BRANCH_CROP", "LIMIT_ARMS_X", "BOUNDARY_PARAMETER_LABELS", "MORSE_COLORS",
           "EVENT_STYLES", "ATLAS_STYLES", "IMPERFECTION_STYLES"]


# ---------------------------------------------------------------------------- loading paths
#: Quantities :func:`plot_branches` puts on an axis (and ``"q<i>"``, the 1-based joint angle ``q_i``).
BRANCH_QUANTITIES = ("t", "fx", "fy", "dx", "dy", "x", "y", "u", "phi", "energy", "s")
#: The default axes of :func:`plot_branches`: the end angle ``phi_n`` (a response under every control, zero on the
#: straight chain, of opposite signs on the two mirror branches of a pitchfork) against the control parameter.
BRANCH_DEFAULT_X = "t"
BRANCH_DEFAULT_Y = "phi"
#: The default crop of :func:`plot_branches`: the axis of ``t`` shows the events and the branches' starts with this
#: fraction of their span added either side.
BRANCH_CROP = 0.25
#: The response :func:`plot_limit_load` draws the load against when it draws the buckled arms.
LIMIT_ARMS_X = "phi"

#: Colour of a branch piece by its Morse index (index 0, stable: solid; the others dashed); beyond: the last.
MORSE_COLORS = ("tab:blue", "tab:orange", "tab:red", "tab:purple", "tab:brown", "tab:pink", "tab:gray")

#: Marker style of each kind of branch event.
EVENT_STYLES = {
    "fold": {"marker": "D", "ms": 6.5, "mfc": "tab:red", "mec": "black", "label": "fold (limit point)"},
    "branch_point": {"marker": "o", "ms": 7.0, "mfc": "white", "mec": "black", "mew": 1.4,
                     "label": "branch point (bifurcation)"},
    "joint_limit": {"marker": "X", "ms": 7.5, "mfc": "0.35", "mec": "black", "label": "joint limit (end)"},
}


def morse_color(index: int) -> str:
    """:data:`MORSE_COLORS` entry of a Morse index."""
    return MORSE_COLORS[min(max(int(index), 0), len(MORSE_COLORS) - 1)]


def _control_text(control: Control | str) -> str:
    """A control (a :class:`~tensegrity_opt.Control` or its kind) in words, for a title."""
    kind = control if isinstance(control, str) else getattr(control, "kind", str(control))
    d = getattr(control, "direction", None)
    vec = "" if d is None or np.size(d) != 2 else f" along ({float(d[0]):.3g}, {float(d[1]):.3g})"
    if kind == "displacement":
        return f"tip displacement{vec}"
    if kind == "load":
        return f"dead tip load{vec}"
    if kind == "guided":
        return f"guided tip (y held), load{vec}"
    if kind == "wall":
        nu = getattr(control, "normal", None)
        where = "" if nu is None else f" of normal ({float(nu[0]):.3g}, {float(nu[1]):.3g})"
        return f"tip on a wall{where}, load{vec}"
    if kind == "preload":
        return f"rest lengths moved (tip {getattr(control, 'tip', 'free')})"
    return str(kind)


def _t_label(control: Control | str | None) -> str:
    kind = control if isinstance(control, str) else getattr(control, "kind", None)
    if kind == "displacement":
        return "t: tip displacement along the control direction (length)"
    if kind == "preload":
        return "t: rest-length change along the preload direction (length)"
    if kind in ("load", "guided", "wall"):
        return f"t: load magnitude (force, {FORCE_UNIT})"
    return "t: control parameter (a force for a load control, a length for a displacement)"


def branch_quantity_label(name: str, control: Control | str | None = None) -> str:
    """The axis label (quantity and unit) of a :data:`BRANCH_QUANTITIES` name or ``"q<i>"``."""
    guided = getattr(control, "kind", None) in ("guided", "wall")
    labels = {
        "t": _t_label(control),
        "fx": f"tip force $F_x$ ({FORCE_UNIT})",
        "fy": f"tip force $F_y${' (reaction of the guide)' if guided else ''} ({FORCE_UNIT})",
        "dx": "tip deflection $\\delta_x$ (length)",
        "dy": "tip deflection $\\delta_y$ (length)",
        "x": "tip $x$ (length)",
        "y": "tip $y$ (length)",
        "u": "tip displacement along the control direction $u$ (length)",
        "phi": "end angle $\\varphi_n = q_1 + \\dots + q_n$ (rad)",
        "energy": f"elastic energy $E$ ({ENERGY_UNIT})",
        "s": "arclength $s$ (normalised: rad, $F / (k c^2 / 2b)$, length / $2b$)",
    }
    if name in labels:
        return labels[name]
    return f"joint angle $q_{{{name[1:]}}}$ (rad)"


def _check_quantity(name: Any, n: int, field: str) -> str:
    if isinstance(name, str) and name in BRANCH_QUANTITIES:
        return name
    if isinstance(name, str) and name.startswith("q") and name[1:].isdigit() and 1 <= int(name[1:]) <= n:
        return name
    raise InvalidParameterError(f"{field} must be one of {', '.join(BRANCH_QUANTITIES)} or q1..q{n}, got {name!r}",
                                field=field)


def _direction_of_u(control: Control) -> tuple[np.ndarray, bool]:
    """The unit vector ``u`` is measured along, and whether it is in deflection ``(dx, dy)`` space."""
    kind = getattr(control, "kind", None)
    if kind == "displacement":
        return np.asarray(control.direction, float), True
    if kind in ("load", "guided", "wall"):
        return np.asarray(control.direction, float), False
    if kind == "preload":
        load = np.asarray(control.base, float)
        nrm = float(np.linalg.norm(load))
        if nrm > 0.0:
            return load / nrm, False
    raise InvalidParameterError("u (the tip displacement along the control direction) needs a displacement or load "
                                "control, or a preload control under a tip load", field="x")


def _quantity(name: str, br: Branch, t: np.ndarray, q: np.ndarray, force: np.ndarray, tip: np.ndarray,
              energy: np.ndarray, s: np.ndarray) -> np.ndarray:
    """``name`` at the points ``(t, q, force, tip, energy, s)`` of branch ``br`` (arrays over points)."""
    L = float(br.straight_length)
    if name == "t":
        return t
    if name == "fx":
        return force[:, 0]
    if name == "fy":
        return force[:, 1]
    if name == "dx":
        return L - tip[:, 0]
    if name == "dy":
        return tip[:, 1]
    if name == "x":
        return tip[:, 0]
    if name == "y":
        return tip[:, 1]
    if name == "phi":
        return q.sum(axis=1)
    if name == "energy":
        return energy
    if name == "s":
        return s
    if name == "u":
        d, deflection = _direction_of_u(br.control)
        tip0 = br.tip[0]
        if deflection:
            return (np.column_stack([L - tip[:, 0], tip[:, 1]]) - np.array([L - tip0[0], tip0[1]])) @ d
        return (tip - tip0) @ d
    return q[:, int(name[1:]) - 1]


def _branch_xy(br: Branch, name: str) -> np.ndarray:
    return _quantity(name, br, br.t, br.q, br.force, br.tip, br.energy, br.s)


def _event_xy(br: Branch, e: BranchEvent, name: str) -> float:
    if name == "s":
        i = min(int(e.index), len(br) - 1)
        j = min(i + 1, len(br) - 1)
        da, db = float(np.linalg.norm(e.q - br.q[i])), float(np.linalg.norm(br.q[j] - e.q))
        frac = da / (da + db) if da + db > 0 else 0.0
        return float(br.s[i] + frac * (br.s[j] - br.s[i]))
    return float(_quantity(name, br, np.array([e.t]), e.q[None, :], np.asarray(e.force)[None, :],
                           np.asarray(e.tip)[None, :], np.array([e.energy]), np.array([np.nan]))[0])


def _morse_runs(br: Branch, xname: str, yname: str) -> list[tuple[int, np.ndarray, np.ndarray]]:
    """The pieces of constant Morse index of a branch: ``(index, x, y)``. Neighbouring pieces meet at the
    event located between them (or, where none was located, at the next piece's first point)."""
    X, Y = _branch_xy(br, xname), _branch_xy(br, yname)
    idx = np.asarray(br.morse_index, dtype=int)
    P = idx.size
    if P == 0:
        return []
    starts = [0, *(np.flatnonzero(idx[1:] != idx[:-1]) + 1).tolist()]
    ends = [s - 1 for s in starts[1:]] + [P - 1]
    located = [e for e in br.events if e.kind in SINGULAR_KINDS]
    out = []
    for a, b in zip(starts, ends):
        xs, ys = list(X[a:b + 1]), list(Y[a:b + 1])
        before = [e for e in located if e.index == a - 1 and e.morse_after == idx[a]]
        if before:
            xs.insert(0, _event_xy(br, before[-1], xname))
            ys.insert(0, _event_xy(br, before[-1], yname))
        if b + 1 < P:
            after = [e for e in located if e.index == b and e.morse_before == idx[b]]
            if after:
                xs.append(_event_xy(br, after[0], xname))
                ys.append(_event_xy(br, after[0], yname))
            else:
                xs.append(float(X[b + 1]))
                ys.append(float(Y[b + 1]))
        out.append((int(idx[a]), np.asarray(xs, float), np.asarray(ys, float)))
    return out


def _as_branches(branches: Branch | Sequence[Branch]) -> list[Branch]:
    items = [branches] if isinstance(branches, Branch) else list(branches)
    if not items:
        raise InvalidParameterError("plot_branches needs at least one branch", field="branches")
    for i, b in enumerate(items):
        if not isinstance(b, Branch):
            raise InvalidParameterError(f"branches[{i}] must be a Branch, got {type(b).__name__}",
                                        field=f"branches[{i}]")
    return items


def _draw_runs(ax: Any, runs: list, gid: str, zorder: float = 3.0) -> set[int]:
    seen: set[int] = set()
    for j, (k, xs, ys) in enumerate(runs):
        line, = ax.plot(xs, ys, color=morse_color(k), lw=1.8 if k == 0 else 1.4, ls="-" if k == 0 else "--",
                        zorder=zorder)
        line.set_gid(f"{gid}-morse{k}-{j}")
        seen.add(k)
    return seen


def _morse_handles(indices: set[int]) -> tuple[list, list]:
    from matplotlib.lines import Line2D

    hs, ls = [], []
    for k in sorted(indices):
        hs.append(Line2D([], [], color=morse_color(k), lw=1.8 if k == 0 else 1.4, ls="-" if k == 0 else "--"))
        ls.append("stable (Morse index 0)" if k == 0 else f"unstable, Morse index {k}")
    return hs, ls


def _crop_window(items: list[Branch], crop: float) -> tuple[float, float] | None:
    """The range of ``t`` that holds every event and every branch's start with ``crop`` times their span either
    side, within the branches' range of ``t``; ``None`` when no branch has an event or the window holds every
    point."""
    marks = [float(e.t) for br in items for e in br.events]
    if not marks:
        return None
    marks += [float(br.t[0]) for br in items if len(br)]
    marks = [v for v in marks if math.isfinite(v)]
    data = np.concatenate([np.asarray(br.t, float) for br in items])
    data = data[np.isfinite(data)]
    if not marks or not data.size:
        return None
    lo, hi = min(marks), max(marks)
    dlo, dhi = float(data.min()), float(data.max())
    span = hi - lo if hi > lo else max(abs(hi), 1e-3 * (dhi - dlo), 1e-12)
    lo, hi = max(lo - crop * span, dlo), min(hi + crop * span, dhi)
    if lo <= dlo and hi >= dhi:
        return None
    return lo, hi


def _shown_range(lines: list[tuple[np.ndarray, np.ndarray]], lo: float, hi: float) -> tuple[float, float] | None:
    """The range of the values ``v`` of the polylines ``(v, t)`` where ``lo <= t <= hi``, a piece crossing a bound
    cut there."""
    vals: list[float] = []
    for v, t in lines:
        inside = (t >= lo) & (t <= hi)
        vals += v[inside].tolist()
        for i in range(t.size - 1):
            for edge in (lo, hi):
                if (t[i] - edge) * (t[i + 1] - edge) < 0:
                    f = (edge - t[i]) / (t[i + 1] - t[i])
                    vals.append(float(v[i] + f * (v[i + 1] - v[i])))
    vals = [x for x in vals if math.isfinite(x)]
    return (min(vals), max(vals)) if vals else None


def _padded(lo: float, hi: float, frac: float = 0.05) -> tuple[float, float]:
    pad = frac * (hi - lo) if hi > lo else max(abs(hi) * frac, 0.05)
    return lo - pad, hi + pad


def plot_branches(branches: Branch | Sequence[Branch], m: Manipulator, *, x: str = BRANCH_DEFAULT_X,
                  y: str = BRANCH_DEFAULT_Y, crop: float | None = BRANCH_CROP, title: str | None = None,
                  figsize: tuple[float, float] = (8.4, 4.8)) -> Any:
    """Branch diagram of :func:`~tensegrity_opt.trace_branch` / :func:`~tensegrity_opt.bifurcation_diagram`.

    Each branch is drawn ``y`` against ``x`` in pieces of constant Morse index: stable (index 0) solid
    blue, unstable dashed and coloured by the index (:data:`MORSE_COLORS`); neighbouring pieces meet at
    the event located between them. Events are marked on top: folds (filled diamonds), branch points
    (open circles), joint limits (crosses). The legend sits beside the axes (it never covers data);
    the axes say the quantity and its unit in the caller's units (forces ``stiffness x length``,
    lengths, energies ``stiffness x length^2``, angles rad; nothing is normalised but the arclength
    ``s``); the title names the control and the chain's parameters.

    By default the diagram is the end angle ``phi_n = q_1 + ... + q_n`` against the control parameter ``t``,
    a bifurcation diagram: the straight chain lies on ``phi_n = 0``, each pitchfork's two mirror branches
    (``q -> -q``) leave it with opposite signs, and ``phi_n`` is a response under every control (a tip
    force or deflection is ``t`` itself, or its negative, under a load or a displacement along it). The
    diagram shows the points whose ``t`` lies within ``crop`` times the events' span (from the branches'
    starts to the last event) of them, whatever the axes: a branch traced to ``t ~ 70`` would squeeze its
    events into a corner. A branch along which the drawn quantity does not change says so in the axes.

    Parameters
    ----------
    branches : Branch or iterable of Branch
    m : Manipulator
        The branches' chain (for the title).
    x, y : str
        :data:`BRANCH_QUANTITIES` (``t`` the control parameter, ``fx``/``fy`` the tip force, ``dx``/``dy``
        the deflection, ``x``/``y`` the tip, ``u`` the tip displacement along the control direction
        from the start, ``phi`` the end angle, ``energy``, ``s``) or ``"q<i>"`` (joint ``i``, 1-based).
        Default: ``phi`` against ``t``.
    crop : float or None
        Margin in ``t`` past the events, as a fraction of their span (default :data:`BRANCH_CROP`); ``None``
        shows every point. Only the axes' limits change: the artists hold every point.

    Notes
    -----
    Artists (``gid``): ``"branch-<b>-morse<k>-<j>"`` (branch ``b``, its ``j``-th piece, Morse index
    ``k``), ``"events-fold"``, ``"events-branch_point"``, ``"events-joint_limit"`` (every event of that
    kind over all branches, in order), ``"constant-note"`` (the note of a quantity that does not change).
    """
    items = _as_branches(branches)
    n = items[0].q.shape[1]
    x = _check_quantity(x, n, "x")
    y = _check_quantity(y, n, "y")
    if crop is not None and not (isinstance(crop, (int, float)) and math.isfinite(crop) and crop >= 0):
        raise InvalidParameterError(f"crop must be a number >= 0 or None, got {crop!r}", field="crop")
    from matplotlib.lines import Line2D

    fig = new_figure(figsize)
    ax = fig.subplots()
    if y in ("t", "fx", "fy", "energy", "phi") or x in ("fx", "fy"):
        ax.axhline(0.0, color="0.85", lw=0.8, zorder=0)
    indices: set[int] = set()
    for b, br in enumerate(items):
        indices |= _draw_runs(ax, _morse_runs(br, x, y), f"branch-{b}")
    handles, labels = _morse_handles(indices)
    counts = {}
    for kind, style in EVENT_STYLES.items():
        pts = [(_event_xy(br, e, x), _event_xy(br, e, y)) for br in items for e in br.events if e.kind == kind]
        counts[kind] = len(pts)
        if not pts:
            continue
        arr = np.array(pts, dtype=float)
        kw = {k: v for k, v in style.items() if k != "label"}
        line, = ax.plot(arr[:, 0], arr[:, 1], ls="none", zorder=6, **kw)
        line.set_gid(f"events-{kind}")
        handles.append(Line2D([], [], ls="none", **kw))
        labels.append(f"{style['label']} ({len(pts)})")
    window = None if crop is None else _crop_window(items, float(crop))
    if window is not None:                  # each axis: what the branches show for t in the window
        for name, set_lim in ((x, ax.set_xlim), (y, ax.set_ylim)):
            if name == "t":
                set_lim(*_padded(*window, frac=0.02))
                continue
            lines = [(v, t) for br in items for _, v, t in _morse_runs(br, name, "t")]
            lines += [(np.array([_event_xy(br, e, name)]), np.array([e.t])) for br in items for e in br.events]
            shown = _shown_range(lines, *window)
            if shown is not None:
                set_lim(*_padded(*shown))
    for name in {x, y} - {"t", "s"}:
        vals = np.concatenate([_branch_xy(br, name) for br in items])
        vals = vals[np.isfinite(vals)]
        if vals.size and float(np.ptp(vals)) <= 1e-12 * max(1.0, float(np.abs(vals).max())):
            what = branch_quantity_label(name, items[0].control).rsplit(" (", 1)[0]
            note = ax.annotate(f"{what} = {number_text(float(vals[0]))} all along "
                               f"{'every' if len(items) > 1 else 'this'} branch;\nthe events mark where other "
                               "branches leave it (a bifurcation diagram, depth 1, draws them)", (0.02, 0.96),
                               xycoords="axes fraction", va="top", fontsize=8, color="0.3")
            note.set_gid("constant-note")
            break
    ax.set_xlabel(branch_quantity_label(x, items[0].control))
    ax.set_ylabel(branch_quantity_label(y, items[0].control))
    ax.grid(True, lw=0.4, alpha=0.5)
    legend_beside(ax, handles, labels)
    if title is None:
        what = f"{len(items)} branches" if len(items) > 1 else "Equilibrium branch"
        title = f"{what}: {_control_text(items[0].control)}\n{chain_label(m)}"
    ax.set_title(title, fontsize=9)
    return fig


def _as_arms(arms: Branch | Sequence[Branch] | None) -> list[Branch]:
    items = [] if arms is None else [arms] if isinstance(arms, Branch) else list(arms)
    for i, b in enumerate(items):
        if not isinstance(b, Branch):
            raise InvalidParameterError(f"arms[{i}] must be a Branch, got {type(b).__name__}", field=f"arms[{i}]")
    return items


def plot_limit_load(result: LimitLoad, m: Manipulator, *, arms: Branch | Sequence[Branch] | None = None,
                    figsize: tuple[float, float] = (8.4, 4.8)) -> Any:
    """The load path of :func:`~tensegrity_opt.limit_load`, and at a bifurcation the buckled arms leaving it
    (:func:`~tensegrity_opt.limit_arms`).

    The load ``t`` is drawn against a response, in pieces of constant Morse index as :func:`plot_branches`,
    with the limit point marked (a fold: snap-through; a bifurcation: the branch point) and the
    quasi-buckling load (the least tangent stiffness along the load) as a dotted level with its point; a
    path that ends without a limit marks its end (a joint limit, ``max_load``).

    Without ``arms`` the response is the tip displacement along the load ``u = d . (tip - tip_0)`` (guided:
    ``y`` is held, so ``u = d_x (x - x_0)``): a fold's path moves along the load. With ``arms`` it is the end
    angle ``phi_n = q_1 + ... + q_n`` (:data:`LIMIT_ARMS_X`, the branch diagram's default response): zero on
    the straight chain's path, which does not move before it buckles, and of opposite signs on the two mirror
    arms (``u`` is the same on both, they would overlap); each arm's end (its first fold or joint limit) is
    marked as :data:`EVENT_STYLES`.

    Artists (``gid``): ``"path-morse<k>-<j>"``, ``"arm-<a>-morse<k>-<j>"`` (arm ``a``, its ``j``-th piece of
    Morse index ``k``), ``"arm-ends-<kind>"``, ``"limit-point"``, ``"quasi-buckling"`` (the point),
    ``"quasi-buckling-level"`` (the horizontal line), ``"path-end"``, ``"no-displacement-note"``.
    """
    if not isinstance(result, LimitLoad):
        raise InvalidParameterError(f"plot_limit_load needs a LimitLoad, got {type(result).__name__}", field="result")
    arm_list = _as_arms(arms)
    br = result.branch
    xq = LIMIT_ARMS_X if arm_list else "u"
    d = np.asarray(result.direction, float)
    fig = new_figure(figsize)
    ax = fig.subplots()
    ax.axhline(0.0, color="0.85", lw=0.8, zorder=0)
    U, T = _branch_xy(br, xq), br.t
    lost = next((e for e in br.events if e.stability == "lost"), None)
    runs = _morse_runs(br, xq, "t")
    indices = _draw_runs(ax, [r for r in runs if r[1].size], "path")
    for a, arm in enumerate(arm_list):
        indices |= _draw_runs(ax, [r for r in _morse_runs(arm, xq, "t") if r[1].size], f"arm-{a}")
    from matplotlib.lines import Line2D

    handles, labels = _morse_handles(indices)
    if result.kind != "none" and result.load is not None:
        ue = _event_xy(br, lost, xq) if lost is not None else float(U[-1])
        style = EVENT_STYLES["fold" if result.kind == "fold" else "branch_point"]
        kw = {k: v for k, v in style.items() if k != "label"}
        pt, = ax.plot([ue], [result.load], ls="none", zorder=7, **kw)
        pt.set_gid("limit-point")
        handles.append(Line2D([], [], ls="none", **kw))
        what = "fold: snap-through" if result.kind == "fold" else "bifurcation"
        labels.append(f"limit load P = {result.load:.6g} ({what})")
    else:
        pt, = ax.plot([float(U[-1])], [float(T[-1])], ls="none", marker="s", ms=6, mfc="white", mec="black", zorder=7)
        pt.set_gid("path-end")
        handles.append(Line2D([], [], ls="none", marker="s", ms=6, mfc="white", mec="black"))
        labels.append(f"end of the path ({result.status})")
    for kind, style in EVENT_STYLES.items():          # where each arm ends: its first fold or joint limit
        ends = [e for arm in arm_list for e in arm.events[:1] if e.kind == kind]
        if not ends:
            continue
        kw = {k: v for k, v in style.items() if k != "label"}
        arm_of = [arm for arm in arm_list for e in arm.events[:1] if e.kind == kind]
        xs = [_event_xy(arm, e, xq) for arm, e in zip(arm_of, ends)]
        pt, = ax.plot(xs, [e.t for e in ends], ls="none", zorder=7, **kw)
        pt.set_gid(f"arm-ends-{kind}")
        handles.append(Line2D([], [], ls="none", **kw))
        loads = ", ".join(dict.fromkeys(f"{e.t:.4g}" for e in ends))
        labels.append(f"arm's end: {style['label'].split(' (')[0]} at t = {loads}")
    if result.quasi_buckling_load is not None:
        qb = float(result.quasi_buckling_load)
        lev = ax.axhline(qb, color="tab:green", ls=":", lw=1.2, zorder=1)
        lev.set_gid("quasi-buckling-level")
        stable = np.asarray(br.stable, bool)
        ok = stable & np.isfinite(U) & np.isfinite(T)
        order = np.argsort(T[ok])
        uq = float(np.interp(qb, T[ok][order], U[ok][order])) if ok.sum() >= 2 else float("nan")
        pt, = ax.plot([uq], [qb], ls="none", marker="*", ms=11, mfc="tab:green", mec="black", zorder=7)
        pt.set_gid("quasi-buckling")
        handles.append(Line2D([], [], ls=":", color="tab:green", marker="*", ms=9, mfc="tab:green", mec="black"))
        labels.append(f"quasi-buckling load {qb:.6g} (least tangent stiffness)")
    shown = np.concatenate([U, *(_branch_xy(arm, xq) for arm in arm_list)])
    finite_u = shown[np.isfinite(shown)]
    if finite_u.size and float(np.ptp(finite_u)) <= 1e-9 * max(1.0, float(br.straight_length)):
        # e.g. the straight chain under a guided load: it does not move until the limit point
        what = ("the end angle does not change\non this path ($\\varphi_n$ = 0)" if arm_list else
                "the tip does not move\nalong the load on this\npath ($u$ = 0)")
        note = ax.annotate(what, (0.5, 0.5),
                           xycoords="axes fraction", textcoords="offset points", xytext=(8, 0), ha="left",
                           fontsize=8, color="0.3")
        note.set_gid("no-displacement-note")
    if arm_list:
        ax.set_xlabel(branch_quantity_label(xq, br.control))
    else:
        ax.set_xlabel("tip displacement along the load $u = d \\cdot (\\mathrm{tip} - \\mathrm{tip}_0)$ (length)")
    ax.set_ylabel(f"load $t = |F|$ along $d$ (force, {FORCE_UNIT})")
    ax.grid(True, lw=0.4, alpha=0.5)
    legend_beside(ax, handles, labels)
    head = (f"Limit load: {result.kind}" + (f" at P = {result.load:.6g}" if result.load is not None else
                                             f" ({result.status})")
            + f"; {result.boundary} tip, load along ({d[0]:.3g}, {d[1]:.3g})")
    if arm_list:
        head += f"\nthe path and the buckled arm{'s' if len(arm_list) > 1 else ''} leaving the branch point"
    ax.set_title(f"{head}\n{chain_label(m)}", fontsize=9)
    return fig


#: Marker style of each kind of limit on the imperfection-sensitivity curve (``"none"`` and ``"unknown"`` have no
#: load: they are marked on the axis, at the bottom).
IMPERFECTION_STYLES = {
    "fold": {"marker": "D", "ms": 6.0, "mfc": "tab:red", "mec": "black", "label": "fold (snap-through)"},
    "bifurcation": {"marker": "o", "ms": 7.0, "mfc": "white", "mec": "black", "mew": 1.4, "label": "bifurcation"},
    "joint_limit": {"marker": "X", "ms": 7.5, "mfc": "0.35", "mec": "black",
                    "label": "joint limit (stable to it)"},
    "none": {"marker": "^", "ms": 7.0, "mfc": "tab:green", "mec": "black", "label": "no limit up to max_load"},
    "unknown": {"marker": "s", "ms": 6.0, "mfc": "white", "mec": "0.5", "label": "unknown (path cut)"},
}


def plot_imperfection(result: ImperfectionSensitivity, m: Manipulator | None = None, *,
                      figsize: tuple[float, float] = (8.4, 4.8)) -> Any:
    """The imperfection-sensitivity curve of :func:`~tensegrity_opt.imperfection_sensitivity`: the limit load
    against the amplitude, a marker per kind (:data:`IMPERFECTION_STYLES`; amplitudes without a load at the
    bottom of the axes), the perfect chain's limit load as a horizontal line, and where a small-imperfection law
    applies the fitted ``P_c - C |p|^e`` dashed over the amplitudes' range.

    Artists (``gid``): ``"curve"`` (the loads joined in amplitude order), ``"kind-<kind>"``, ``"perfect-load"``,
    ``"law"``.
    """
    if not isinstance(result, ImperfectionSensitivity):
        raise InvalidParameterError(f"plot_imperfection needs an ImperfectionSensitivity, got "
                                    f"{type(result).__name__}", field="result")
    from matplotlib.lines import Line2D

    p = np.asarray(result.amplitudes, float)
    loads = np.asarray(result.loads, float)
    kinds = np.asarray(result.kinds)
    order = np.argsort(p, kind="stable")
    fig = new_figure(figsize)
    ax = fig.subplots()
    handles, labels = [], []
    has = np.isfinite(loads[order])
    line, = ax.plot(p[order][has], loads[order][has], color="0.55", lw=1.0, zorder=2)
    line.set_gid("curve")
    pc = result.perfect_load
    if pc is not None:
        lev = ax.axhline(float(pc), color="tab:blue", ls="-", lw=1.0, alpha=0.7, zorder=1)
        lev.set_gid("perfect-load")
        handles.append(Line2D([], [], color="tab:blue", lw=1.0))
        labels.append(f"perfect chain: {result.perfect_kind} at P = {float(pc):.6g}")
    finite = loads[np.isfinite(loads)]
    bottom = float(min(finite.min(), pc if pc is not None else finite.min())) if finite.size else 0.0
    for kind, style in IMPERFECTION_STYLES.items():
        sel = kinds == kind
        if not sel.any():
            continue
        kw = {k: v for k, v in style.items() if k != "label"}
        y = np.where(np.isfinite(loads[sel]), loads[sel], bottom)
        pt, = ax.plot(p[sel], y, ls="none", zorder=6, clip_on=False, **kw)
        pt.set_gid(f"kind-{kind}")
        handles.append(Line2D([], [], ls="none", **kw))
        labels.append(f"{style['label']} ({int(sel.sum())})")
    if result.law_exponent is not None and pc is not None:
        e, c = float(result.law_exponent), float(result.law_coefficient)
        side = np.sign(result.law_amplitudes[0])
        on = p[np.sign(p) == side]
        a = np.linspace(0.0, float(np.max(np.abs(on))), 200)
        law, = ax.plot(side * a, float(pc) - c * a ** e, color="tab:purple", ls="--", lw=1.2, zorder=3)
        law.set_gid("law")
        handles.append(Line2D([], [], color="tab:purple", ls="--", lw=1.2))
        what = (result.bifurcation or "").replace("_", "-")
        labels.append(f"{what} law: $P_c - {c:.3g}\\,|p|^{{{e:.3f}}}$ (expected {result.law_expected:.3g})")
    ax.set_xlabel(boundary_parameter_label(str(result.imperfection)).replace("parameter", "amplitude", 1)
                  if result.imperfection != "asymmetry" else
                  "imperfection amplitude $p$: $L_{1,0} + p$, $L_{2,0} - p$ on every segment (length)")
    ax.set_ylabel(f"limit load $P$ (force, {FORCE_UNIT})")
    ax.grid(True, lw=0.4, alpha=0.5)
    legend_beside(ax, handles, labels)
    d = np.asarray(result.direction, float)
    incomplete = "" if result.success else f" (incomplete: {result.status})"
    head = (f"Imperfection sensitivity{incomplete}: the imperfect arm's limit load\n"
            f"{result.boundary} tip, load along ({d[0]:.3g}, {d[1]:.3g})")
    ax.set_title(head + (f"\n{chain_label(m)}" if m is not None else ""), fontsize=9)
    return fig


#: The second parameter of a stability boundary in words, with its unit (:data:`~tensegrity_opt.analyses.paths.
#: boundaries.PARAMETERS`; every segment moves by ``p``).
BOUNDARY_PARAMETER_LABELS = {
    "asymmetry": "preload asymmetry $p$: $L_{1,0} = L_0 + p$, $L_{2,0} = L_0 - p$ (length)",
    "L0": "rest-length change $p$: both $L_{i,0} + p$ (length)",
    "a": "triangle half-height change $p$: $a + p$ (length)",
    "b": "triangle half-length change $p$: $b + p$ (length)",
    "k": "stiffness change $p$: both $k_i + p$ (stiffness)",
    "direction": "parameter $p$ along the given direction (the unit of its entries per unit $p$)",
}


def boundary_parameter_label(parameter: str) -> str:
    """The axis label (quantity and unit) of a stability boundary's second parameter."""
    return BOUNDARY_PARAMETER_LABELS.get(parameter, f"second parameter $p$: {parameter} (its unit)")


def plot_boundary(boundary: StabilityBoundary, m: Manipulator | None = None, *,
                  control: Control | str | None = None, figsize: tuple[float, float] = (8.4, 4.8)) -> Any:
    """A stability boundary (:func:`~tensegrity_opt.stability_boundary`): the critical ``t`` (a fold or a branch
    point of the one-parameter branches) against the second parameter ``p``, with the cusps marked; an
    unsuccessful boundary says so in the title, with its status. ``m`` (the chain) and ``control`` (a
    :class:`~tensegrity_opt.Control` or its kind: the unit of ``t``; default the boundary's own control) are for
    the labels; without ``m`` the title has no chain line. The horizontal axis names the parameter and its unit
    (:func:`boundary_parameter_label`: the preload asymmetry and the geometric parameters are lengths).

    Artists (``gid``): ``"boundary"`` (the curve ``(p, t)``), ``"cusps"`` (the cusp points).
    """
    if not isinstance(boundary, StabilityBoundary):
        raise InvalidParameterError(f"plot_boundary needs a StabilityBoundary, got {type(boundary).__name__}",
                                    field="boundary")
    p = np.asarray(boundary.p, dtype=float).ravel()
    t = np.asarray(boundary.t, dtype=float).ravel()
    if p.shape != t.shape:
        raise InvalidParameterError("the boundary's p and t differ in length", field="boundary")
    kind = str(boundary.kind)
    own = boundary.control
    if control is None or (isinstance(control, str) and control == getattr(own, "kind", None)):
        control = own                        # the boundary's own control: its direction in the title
    from matplotlib.lines import Line2D

    fig = new_figure(figsize)
    ax = fig.subplots()
    color = "tab:red" if kind == "fold" else "tab:purple"
    line, = ax.plot(p, t, color=color, lw=1.8, marker="o", ms=2.0, zorder=3)
    line.set_gid("boundary")
    handles = [Line2D([], [], color=color, lw=1.8)]
    labels = ["fold curve (limit points)" if kind == "fold" else "branch-point curve (bifurcations)"]
    cusps = list(boundary.cusps or [])
    if cusps:
        cp = np.array([[float(c.p), float(c.t)] for c in cusps], dtype=float)
        pt, = ax.plot(cp[:, 0], cp[:, 1], ls="none", marker="^", ms=9, mfc="gold", mec="black", zorder=6)
        pt.set_gid("cusps")
        handles.append(Line2D([], [], ls="none", marker="^", ms=9, mfc="gold", mec="black"))
        labels.append(f"cusp ({len(cusps)})")
    ax.set_xlabel(boundary_parameter_label(str(boundary.parameter)))
    ax.set_ylabel("critical " + _t_label(control))
    ax.grid(True, lw=0.4, alpha=0.5)
    legend_beside(ax, handles, labels)
    incomplete = "" if boundary.success else f" (incomplete: {boundary.status})"
    head = f"Stability boundary ({kind}) over {boundary.parameter}" + (
        f", {_control_text(control)}" if control is not None else "") + incomplete
    ax.set_title(head + (f"\n{chain_label(m)}" if m is not None else ""), fontsize=9)
    return fig


# ---------------------------------------------------------------------------- stability atlas
#: Styles of the atlas's crossing curves and points (:func:`plot_atlas`).
ATLAS_STYLES = {
    "switch": {"color": "black", "lw": 2.2, "ls": "-", "marker": "o", "ms": 5.0, "mfc": "white", "mec": "black",
               "label": "least-energy branch switches (equal energy)"},
    "branch_end": {"color": "tab:red", "lw": 1.8, "ls": "--", "marker": "D", "ms": 4.5, "mfc": "tab:red",
                   "mec": "black", "label": "stable branch ends (fold: the arm snaps)"},
}
#: Fill of the cells without a count: beyond the chain's reach, and failed (an error or the time limit).
ATLAS_UNREACHABLE = {"facecolor": "0.93", "edgecolor": "0.65", "hatch": "////"}
ATLAS_FAILED = {"facecolor": "0.2", "edgecolor": "white", "hatch": "xx"}


def _cell_edges(v: np.ndarray, other: np.ndarray) -> np.ndarray:
    """Edges of the cells centred on the grid values ``v`` (midpoints; the outer cells as wide as their
    neighbour); one value: a cell as wide as the other axis's step (or 0.1)."""
    v = np.asarray(v, dtype=float)
    if v.size == 1:
        step = float(np.min(np.diff(other))) if other.size > 1 else 0.1
        return np.array([v[0] - step / 2, v[0] + step / 2])
    mid = (v[1:] + v[:-1]) / 2
    return np.concatenate([[v[0] - (mid[0] - v[0])], mid, [v[-1] + (v[-1] - mid[-1])]])


def plot_atlas(atlas: StabilityAtlas, m: Manipulator | None = None, *, title: str | None = None,
               figsize: tuple[float, float] = (7.6, 6.4)) -> Any:
    """The workspace stability atlas of :func:`~tensegrity_opt.stability_atlas` (or
    :func:`~tensegrity_opt.applications.sweeps.atlas_from_rows`): the number of stable equilibria of the held
    tip as a map over the deflection ``(dx, dy)``, one cell centred on each target, one colour per count (a
    discrete colour bar with integer ticks); the targets beyond the chain's reach hatched light grey and the
    failed ones (an error, or not computed within the time limit) dark and cross-hatched. On top: the curves
    where the least-energy branch switches (``atlas.curves("switch")``, solid) and where stable branches end
    (``atlas.curves("branch_end")``, dashed), each crossing located on a grid edge marked. The legend sits
    below the axes (it never covers data); the axes are the deflections in the caller's length unit; the title
    names the method, the grid, the status when incomplete and (``m``) the chain's parameters.

    Artists (``gid``): ``"n_stable"`` (QuadMesh, masked array ``n_stable[j, i]``, masked where unreachable or
    failed), ``"unreachable"``, ``"failed"`` (the cells, patch collections), ``"switch"``, ``"branch_end"`` (line
    collections of the curves' segments), ``"switch-points"``, ``"branch_end-points"`` (the crossings).
    """
    if not isinstance(atlas, StabilityAtlas):
        raise InvalidParameterError(f"plot_atlas needs a StabilityAtlas, got {type(atlas).__name__}", field="atlas")
    import matplotlib
    from matplotlib import patheffects
    from matplotlib.collections import LineCollection, PatchCollection
    from matplotlib.colors import BoundaryNorm, ListedColormap
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch, Rectangle

    X, Y = np.asarray(atlas.dx, float), np.asarray(atlas.dy, float)
    ns = atlas.n_stable
    ok = np.array([[t.success for t in row] for row in atlas.targets], dtype=bool).reshape(ns.shape)
    reach = np.array([[t.reachable for t in row] for row in atlas.targets], dtype=bool).reshape(ns.shape)
    good = ok & reach & (ns >= 0)
    kmax = int(ns[good].max()) if good.any() else 0
    base = matplotlib.colormaps["viridis"]
    colors = base(np.linspace(0.0, 1.0, kmax + 1)) if kmax > 0 else base([0.55])
    cmap = ListedColormap(colors).with_extremes(bad=(1.0, 1.0, 1.0, 0.0))
    norm = BoundaryNorm(np.arange(-0.5, kmax + 1.5), cmap.N)
    xe, ye = _cell_edges(X, Y), _cell_edges(Y, X)

    fig = new_figure(figsize)
    ax = fig.subplots()
    mesh = ax.pcolormesh(xe, ye, np.ma.masked_array(ns, mask=~good), cmap=cmap, norm=norm, shading="flat")
    mesh.set_gid("n_stable")
    step = max(1, math.ceil((kmax + 1) / 12))
    fig.colorbar(mesh, ax=ax, ticks=list(range(0, kmax + 1, step)),
                 label="stable equilibria (minima) with the tip held there")
    handles: list = []
    labels: list = []
    for name, style, mask, what in (("unreachable", ATLAS_UNREACHABLE, ok & ~reach, "beyond the chain's reach"),
                                    ("failed", ATLAS_FAILED, ~ok, "failed (an error, or the time limit)")):
        cells = [Rectangle((xe[i], ye[j]), xe[i + 1] - xe[i], ye[j + 1] - ye[j]) for j, i in np.argwhere(mask)]
        coll = PatchCollection(cells, lw=0.4, **style)
        coll.set_gid(name)
        ax.add_collection(coll)
        if cells:
            handles.append(Patch(**style, lw=0.4))
            labels.append(f"{what} ({len(cells)})")
    halo = [patheffects.withStroke(linewidth=4.0, foreground="white")]
    for kind, style in ATLAS_STYLES.items():
        segs = [np.asarray(s, float) for s in atlas.curves(kind)]
        lc = LineCollection(segs, colors=style["color"], linewidths=style["lw"], linestyles=style["ls"], zorder=4)
        lc.set_path_effects(halo)
        lc.set_gid(kind)
        ax.add_collection(lc)
        pts = np.array([[c.dx, c.dy] for c in atlas.crossings if c.kind == kind], dtype=float).reshape(-1, 2)
        line, = ax.plot(pts[:, 0], pts[:, 1], ls="none", marker=style["marker"], ms=style["ms"], mfc=style["mfc"],
                        mec=style["mec"], zorder=5)
        line.set_gid(f"{kind}-points")
        handles.append(Line2D([], [], color=style["color"], lw=style["lw"], ls=style["ls"], marker=style["marker"],
                              ms=style["ms"], mfc=style["mfc"], mec=style["mec"]))
        labels.append(f"{style['label']}: {len(segs)} segments, {len(pts)} crossings")
    ax.set_xlim(float(xe[0]), float(xe[-1]))
    ax.set_ylim(float(ye[0]), float(ye[-1]))
    ax.set_xlabel(branch_quantity_label("dx") + ", > 0 shortens the chain")
    ax.set_ylabel(branch_quantity_label("dy"))
    if handles:                     # below the map (beside it, the long entries squeeze the map)
        fig.legend(handles, labels, fontsize=7, loc="outside lower center", ncols=2 if len(handles) > 2 else 1,
                   frameon=False)
    if title is None:
        certified = bool(np.all(atlas.certified[good])) and good.any()
        title = (f"Stability atlas of the held tip: {X.size} x {Y.size} targets, method {atlas.method}"
                 + (" (certified counts)" if certified else "")
                 + ("" if atlas.status == "complete" else f" - {atlas.status}")
                 + (f"\n{chain_label(m)}" if m is not None else ""))
    ax.set_title(title, fontsize=9)
    return fig


