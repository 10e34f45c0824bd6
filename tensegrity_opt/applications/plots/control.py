"""Figures of the control layer: a rest-length plan (commands, margin, tip error and tip path per step) and the
hysteresis loop of a quasi-static simulation (the snaps as arrows from fold to landing)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ...analyses.design.preload_control import PreloadPlan
from ...analyses.paths.simulation import Simulation, SimulationEvent
from ...errors import InvalidParameterError
from ...model.manipulator import Manipulator
from .paths import EVENT_STYLES
from .style import FORCE_UNIT, chain_label, legend_beside, new_figure

__all__ = ["plot_preload_plan", "plot_simulation", "CONTROL_STYLES", "PLAN_STYLES", "MARGIN_UNIT"]


# ---------------------------------------------------------------------------- control: plans and simulations
#: Margin label unit (an eigenvalue of a Hessian of the energy in the joint angles).
MARGIN_UNIT = "stiffness × length² / rad²"
#: Colours of the control figures: infeasible steps, snaps (arrow, fold), landings, targets.
CONTROL_STYLES = {
    "infeasible": {"facecolor": "tab:red", "alpha": 0.16, "edgecolor": "none"},
    "snap": {"color": "tab:red", "lw": 1.6},
    "fold": {"marker": "D", "ms": 6.0, "mfc": "tab:red", "mec": "black"},
    "bifurcation": {"marker": "o", "ms": 6.5, "mfc": "white", "mec": "tab:red", "mew": 1.4},
    "landing": {"marker": "o", "ms": 6.0, "mfc": "tab:green", "mec": "black"},
    "joint_limit": EVENT_STYLES["joint_limit"],
}
#: The plan's own lines, in black and grey (the segments take the colours): the margin, the required margin, the
#: unverified steps' rings and the tip path (a wide grey band under the targets' black crosses).
PLAN_STYLES = {
    "margin": {"color": "black", "lw": 1.6, "ls": "-"},
    "margin-required": {"color": "black", "lw": 1.2, "ls": (0, (1.0, 2.0))},
    "unverified": {"marker": "o", "ms": 7.5, "mfc": "none", "mec": "black", "mew": 1.3},
    "tip-path": {"color": "0.62", "lw": 3.2, "ls": "-", "solid_capstyle": "round"},
    "tip-error": {"color": "black", "lw": 1.4, "ls": "-"},
}
#: Segments drawn with a legend entry each (longer chains: a colour bar of the segment index).
_MAX_SEGMENT_LEGEND = 10


def _segment_colors(n: int) -> list:
    import matplotlib

    if n <= _MAX_SEGMENT_LEGEND:
        return [matplotlib.colormaps["tab10"](i) for i in range(n)]
    cmap = matplotlib.colormaps["viridis"]
    return [cmap(i / max(n - 1, 1)) for i in range(n)]


def _step_spans(ax: Any, steps: np.ndarray, gid: str) -> Any:
    """One translucent band over each of ``steps`` (full height of ``ax``)."""
    from matplotlib.collections import PatchCollection
    from matplotlib.patches import Rectangle

    rects = [Rectangle((float(k) - 0.5, 0.0), 1.0, 1.0) for k in steps]
    coll = PatchCollection(rects, transform=ax.get_xaxis_transform(), zorder=0, **CONTROL_STYLES["infeasible"])
    coll.set_gid(gid)
    ax.add_collection(coll)
    return coll


def plot_preload_plan(plan: PreloadPlan, m: Manipulator | None = None, *, margin: float | None = None,
                      title: str | None = None, figsize: tuple[float, float] = (11.0, 7.4)) -> Any:
    """A rest-length plan of :func:`~tensegrity_opt.plan_preloads`, per step ``k``: the commanded rest lengths of
    every spring (left, top; spring 1 ``L1_0`` solid, spring 2 ``L2_0`` dashed, one colour per segment), the
    stability margin of the arm under the command (left, middle, black; ``margin``: the required one as a dotted
    black level: the plan's own lines are black, :data:`PLAN_STYLES`, so that no segment's colour is read as a
    margin), the tip error ``|tip - target|`` (left, bottom, black) and the tip path with the targets (right,
    equal axes; each step's tip joined to the next, the targets as crosses). Infeasible steps (the command held,
    or approaching the target: ``on_infeasible``) are shaded in the step panels and the arm's tips there
    marked; steps the forward solve did not verify are marked on the margin. The legend sits below the panels
    (outside the data); the axes are in the caller's units; the title gives the counts, the status and (``m``)
    the chain's parameters.

    Artists (``gid``): ``"rest-length-<i>-<1|2>"`` (segment ``i``, 0-based: its spring's commanded rest length
    per step), ``"margin"``, ``"margin-required"``, ``"unverified"`` (margins of the steps not verified),
    ``"tip-error"``, ``"infeasible-rest"``, ``"infeasible-margin"``, ``"infeasible-error"`` (the bands),
    ``"targets"``, ``"tip-path"``, ``"infeasible-tips"``.
    """
    if not isinstance(plan, PreloadPlan):
        raise InvalidParameterError(f"plot_preload_plan needs a PreloadPlan, got {type(plan).__name__}", field="plan")
    if margin is not None and not (isinstance(margin, (int, float)) and math.isfinite(margin)):
        raise InvalidParameterError(f"margin must be a finite number, got {margin!r}", field="margin")
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    R = np.asarray(plan.commands, float)
    K = R.shape[0]
    n = R.shape[1] if R.ndim == 3 else (m.n if m is not None else 0)
    steps = np.arange(K)
    feasible = np.asarray(plan.feasible, bool).reshape(K)
    verified = np.asarray(plan.verified, bool).reshape(K)
    bad = steps[~feasible]
    fig = new_figure(figsize)
    axd = fig.subplot_mosaic([["rest", "tip"], ["margin", "tip"], ["error", "tip"]], width_ratios=[1.35, 1.0],
                             height_ratios=[1.2, 1.0, 0.8])
    ax_r, ax_m, ax_e, ax_t = axd["rest"], axd["margin"], axd["error"], axd["tip"]
    ax_m.sharex(ax_r)
    ax_e.sharex(ax_r)
    colors = _segment_colors(n)
    marker = "." if K <= 60 else None
    for i in range(n):
        for s in range(2):
            line, = ax_r.plot(steps, R[:, i, s], color=colors[i], lw=1.4, ls="-" if s == 0 else "--", marker=marker,
                              ms=3.0, zorder=3)
            line.set_gid(f"rest-length-{i}-{s + 1}")
    handles: list = []
    labels: list = []
    if n <= _MAX_SEGMENT_LEGEND:
        for i in range(n):
            handles.append(Patch(facecolor=colors[i]))
            labels.append(f"segment {i + 1}")
    elif n:
        import matplotlib
        from matplotlib.cm import ScalarMappable
        from matplotlib.colors import Normalize

        sm = ScalarMappable(norm=Normalize(1, n), cmap=matplotlib.colormaps["viridis"])
        fig.colorbar(sm, ax=ax_r, label="segment", pad=0.01)
    handles += [Line2D([], [], color="0.3", lw=1.4, ls="-"), Line2D([], [], color="0.3", lw=1.4, ls="--")]
    labels += ["spring 1: rest length $L_{1,0}$", "spring 2: rest length $L_{2,0}$"]
    # the margin; NaN (infeasible steps) leaves gaps
    M = np.asarray(plan.margin, float).reshape(K)
    line, = ax_m.plot(steps, M, marker=marker, ms=3.5, zorder=3, **PLAN_STYLES["margin"])
    line.set_gid("margin")
    handles.append(Line2D([], [], **PLAN_STYLES["margin"]))
    labels.append("stability margin (smallest eigenvalue of the Hessian of $E - F \\cdot$ tip)")
    if margin is not None:
        lev = ax_m.axhline(float(margin), zorder=2, **PLAN_STYLES["margin-required"])
        lev.set_gid("margin-required")
        handles.append(Line2D([], [], **PLAN_STYLES["margin-required"]))
        labels.append(f"required margin {float(margin):.3g}")
    TM = np.asarray(getattr(plan, "transition_margin", np.full(K, np.nan)), float).reshape(K)
    if np.any(np.isfinite(TM)):
        line, = ax_m.plot(steps, TM, ls="none", marker="v", ms=3.5, color=PLAN_STYLES["margin"].get("color", "C0"),
                          alpha=0.7, zorder=4)
        line.set_gid("transition-margin")
        handles.append(Line2D([], [], ls="none", marker="v", ms=3.5, color=PLAN_STYLES["margin"].get("color", "C0"),
                              alpha=0.7))
        labels.append("least margin on the step's move (its transition)")
    unv = steps[~verified]
    pt, = ax_m.plot(unv, M[unv], ls="none", zorder=5, **PLAN_STYLES["unverified"])
    pt.set_gid("unverified")
    if unv.size:
        handles.append(Line2D([], [], ls="none", **PLAN_STYLES["unverified"]))
        labels.append(f"not verified along its transition ({unv.size})")
    E = np.asarray(plan.tip_error, float).reshape(K)
    line, = ax_e.plot(steps, E, marker=marker, ms=3.5, zorder=3, **PLAN_STYLES["tip-error"])
    line.set_gid("tip-error")
    # from zero; a floor a thousandth of the workspace's size keeps the roundoff of on-target steps flat at zero
    size = float(np.abs(np.asarray(plan.targets, float)).max(initial=0.0))
    top = float(np.nanmax(E)) if K and np.any(np.isfinite(E)) else 0.0
    ax_e.set_ylim(0.0, max(1.08 * top, 1e-3 * max(size, 1e-12)))
    handles.append(Line2D([], [], **PLAN_STYLES["tip-error"]))
    labels.append("tip error |tip - target|")
    _step_spans(ax_r, bad, "infeasible-rest")
    _step_spans(ax_m, bad, "infeasible-margin")
    _step_spans(ax_e, bad, "infeasible-error")
    if bad.size:
        handles.append(Patch(**CONTROL_STYLES["infeasible"]))
        action = "approaching the target" if plan.on_infeasible == "approach" else "the command held"
        labels.append(f"infeasible step: {action} ({bad.size})")
    # the tip path and the targets
    T = np.asarray(plan.targets, float).reshape(K, 2)
    tips = np.asarray(plan.tip, float).reshape(K, 2)
    tg, = ax_t.plot(T[:, 0], T[:, 1], ls=":", lw=0.9, color="0.45", marker="x", ms=6.0, mec="black", zorder=4)
    tg.set_gid("targets")
    path, = ax_t.plot(tips[:, 0], tips[:, 1], zorder=3, **PLAN_STYLES["tip-path"])
    path.set_gid("tip-path")
    inf, = ax_t.plot(tips[bad, 0], tips[bad, 1], ls="none", marker="s", ms=6.5, mfc="tab:red", mec="black",
                     zorder=5)
    inf.set_gid("infeasible-tips")
    handles += [Line2D([], [], ls=":", lw=0.9, color="0.45", marker="x", ms=6.0, mec="black"),
                Line2D([], [], **PLAN_STYLES["tip-path"])]
    labels += ["targets (in order)", "tip per step"]
    status = [getattr(st, "status", "") for st in getattr(plan, "steps", ())]
    lost = np.array([k for k, st in enumerate(status) if st in ("snap", "no_equilibrium")], dtype=int)
    if lost.size:
        sn, = ax_t.plot(tips[lost, 0], tips[lost, 1], ls="none", marker="*", ms=11.0, mfc="gold", mec="black",
                        zorder=6)
        sn.set_gid("snaps")
        handles.append(Line2D([], [], ls="none", marker="*", ms=11.0, mfc="gold", mec="black"))
        labels.append(f"the arm snapped or met a joint stop ({lost.size}): where it went")
    if bad.size:
        handles.append(Line2D([], [], ls="none", marker="s", ms=6.5, mfc="tab:red", mec="black"))
        labels.append("the tip on an infeasible step")
    if K:
        ax_t.annotate("first", T[0], textcoords="offset points", xytext=(6, 6), fontsize=7)
    ax_t.set_aspect("equal", adjustable="datalim")
    ax_r.set_ylabel("rest length (length)")
    ax_m.set_ylabel(f"margin ({MARGIN_UNIT})")
    ax_e.set_ylabel("tip error (length)")
    ax_e.set_xlabel("step $k$")
    from matplotlib.ticker import MaxNLocator

    ax_e.xaxis.set_major_locator(MaxNLocator(integer=True))
    ax_r.tick_params(labelbottom=False)
    ax_m.tick_params(labelbottom=False)
    ax_t.set_xlabel("tip $x$ (length)")
    ax_t.set_ylabel("tip $y$ (length)")
    for ax in (ax_r, ax_m, ax_e, ax_t):
        ax.grid(True, lw=0.4, alpha=0.5)
    if K:
        ax_r.set_xlim(-0.5, K - 0.5)
    # below the panels (three of them: beside would squeeze the tip path), never over the data
    fig.legend(handles, labels, fontsize=7, loc="outside lower center", ncols=3, frameon=False)
    if title is None:
        title = (f"Preload plan: {K} steps, {int(feasible.sum())} feasible, {int(verified.sum())} verified; "
                 f"status {plan.status}" + (f"\n{chain_label(m)}" if m is not None else ""))
    fig.suptitle(title, fontsize=9)
    return fig


def _simulation_axes(sim: Simulation, component: int | None) -> dict[str, Any]:
    """What a simulation figure plots: the driving input on the vertical axis, the response on the horizontal."""
    P = np.asarray(sim.preloads, float)
    L = float(sim.straight_length)
    if sim.mode == "held":
        T = np.asarray(sim.targets, float)
        c = int(np.argmax(np.ptp(T, axis=0))) if component is None else component
        xyz = "xy"[c]
        return {"kind": "held", "c": c,
                "xlabel": f"held tip deflection $\\delta_{xyz}$ (length)",
                "ylabel": f"holding force $F_{xyz}$ ({FORCE_UNIT})",
                "what": f"the tip moved in $\\delta_{xyz}$"}
    F = np.asarray(sim.loads, float)
    dF = np.ptp(F, axis=0)
    flat = P.reshape(P.shape[0], -1)
    dist = np.linalg.norm(flat - flat[0], axis=1)
    if float(dF.max()) > 0.0 or float(dist.max()) == 0.0:
        c = int(np.argmax(dF)) if component is None else component
        xyz = "xy"[c]
        return {"kind": "load", "c": c, "dc": c,
                "xlabel": f"tip deflection $\\delta_{xyz}$ (length)" + (", > 0 shortens the chain" if c == 0 else ""),
                "ylabel": f"dead tip load $F_{xyz}$ ({FORCE_UNIT})", "what": f"a dead tip load along {xyz}"}
    d = (flat[int(np.argmax(dist))] - flat[0]) / float(dist.max())
    D = np.column_stack([L - np.asarray(sim.tip, float)[:, 0], np.asarray(sim.tip, float)[:, 1]])
    dc = (int(np.argmax(np.ptp(D, axis=0))) if len(D) else 1) if component is None else component
    xyz = "xy"[dc]
    return {"kind": "preload", "d": d, "p0": flat[0], "dc": dc,
            "xlabel": f"tip deflection $\\delta_{xyz}$ (length)" + (", > 0 shortens the chain" if dc == 0 else ""),
            "ylabel": "preload parameter $p = d \\cdot (L_0 - L_0^{(0)})$ (length)",
            "what": "the rest lengths moved",
            "note": "" if d.size > 6 else "\nd = (" + ", ".join(f"{v:.2g}" for v in d) + ") (L1_0, L2_0 per segment)"}


def _simulation_xy(ax: dict[str, Any], L: float, tip: Any, force: Any, load: Any, target: Any, preloads: Any
                   ) -> tuple[float, float]:
    """The point of one state (a sample, a fold, a landing) in the figure's coordinates."""
    if ax["kind"] == "held":
        c = ax["c"]
        return float(np.asarray(target, float)[c]), float(np.asarray(force, float)[c])
    tip = np.asarray(tip, float)
    dfl = (L - tip[0], tip[1])[ax["dc"]]
    if ax["kind"] == "load":
        return float(dfl), float(np.asarray(load, float)[ax["c"]])
    return float(dfl), float((np.asarray(preloads, float).ravel() - ax["p0"]) @ ax["d"])


def plot_simulation(sim: Simulation, m: Manipulator | None = None, *, component: int | None = None,
                    title: str | None = None, figsize: tuple[float, float] = (8.8, 5.2)) -> Any:
    """The hysteresis loop of a quasi-static simulation (:func:`~tensegrity_opt.simulate`): the driving input
    against the tip's response, sample by sample, with every snap drawn as an arrow from its fold (where the
    followed branch ends) to its landing (the state the descent reaches, the inputs frozen there).

    What is on the axes follows the simulation: a free tip under varying loads, the load component that varies
    most (``component``: 0 for ``x``, 1 for ``y``) against the tip deflection along it (the snaps horizontal);
    a free tip with the preloads varying, the preload parameter ``p = d . (L0 - L0(0))`` (``d`` the unit direction
    to the sample farthest from the first, in rest-length space) against the tip deflection that varies most; a
    held tip, the holding force against the held deflection of the component that varies most (the snaps
    vertical). The path between two samples is drawn straight (the branch in between is not sampled), broken at
    each snap: sample, fold, (the arrow), landing, next sample. A joint-limit end is marked. The legend sits
    beside the axes; the axes are in the caller's units; the title gives the counts, the status and (``m``) the
    chain's parameters.

    Artists (``gid``): ``"path"`` (the line, NaN-broken at the snaps), ``"samples"`` (the states at the samples
    done), ``"start"``, ``"end"`` (the last sample done), ``"snap-<j>"`` (the ``j``-th snap's arrow, a
    ``FancyArrowPatch``), ``"snap-folds"``, ``"snap-landings"`` (the points of every snap with a landing, in time
    order), ``"joint-limit"``.
    """
    if not isinstance(sim, Simulation):
        raise InvalidParameterError(f"plot_simulation needs a Simulation, got {type(sim).__name__}", field="sim")
    if component not in (None, 0, 1):
        raise InvalidParameterError(f"component must be 0 (x), 1 (y) or None, got {component!r}", field="component")
    from matplotlib.lines import Line2D
    from matplotlib.patches import FancyArrowPatch

    L = float(sim.straight_length)
    k = len(sim)
    spec = _simulation_axes(sim, component)
    P = np.asarray(sim.preloads, float)
    loads = None if sim.loads is None else np.asarray(sim.loads, float)
    targets = None if sim.targets is None else np.asarray(sim.targets, float)

    def at_sample(i: int) -> tuple[float, float]:
        return _simulation_xy(spec, L, sim.tip[i], sim.force[i], None if loads is None else loads[i],
                              None if targets is None else targets[i], P[i])

    def at_event(e: SimulationEvent, after: bool) -> tuple[float, float]:
        return _simulation_xy(spec, L, e.tip_after if after else e.tip_before,
                              e.force_after if after else e.force_before, e.load, e.target, e.preloads)

    events = sorted(sim.events, key=lambda e: e.time)
    snaps = [e for e in events if e.kind in ("snap", "bifurcation") and e.q_after is not None]
    xs: list[float] = []
    ys: list[float] = []
    for i in range(k):
        if i:
            for e in (e for e in snaps if e.step == i - 1):
                for after in (False, True):
                    x, y = at_event(e, after)
                    xs.append(x)
                    ys.append(y)
                    if not after:
                        xs.append(float("nan"))
                        ys.append(float("nan"))
        x, y = at_sample(i)
        xs.append(x)
        ys.append(y)
    ends = [e for e in events if e.kind == "joint_limit" or (e.kind in ("snap", "bifurcation") and e.q_after is None)]
    for e in ends:                       # the path goes on to where it ended
        x, y = at_event(e, False)
        xs.append(x)
        ys.append(y)
    fig = new_figure(figsize)
    ax = fig.subplots()
    ax.axhline(0.0, color="0.85", lw=0.8, zorder=0)
    path, = ax.plot(xs, ys, color="tab:blue", lw=1.5, zorder=3)
    path.set_gid("path")
    S = np.array([at_sample(i) for i in range(k)], dtype=float).reshape(k, 2)
    dots, = ax.plot(S[:, 0], S[:, 1], ls="none", marker=".", ms=4.0 if k <= 200 else 2.0, color="tab:blue",
                    zorder=4)
    dots.set_gid("samples")
    st, = ax.plot(S[:1, 0], S[:1, 1], ls="none", marker="s", ms=9.0, mfc="none", mec="black", mew=1.3, zorder=7)
    st.set_gid("start")
    en, = ax.plot(S[-1:, 0], S[-1:, 1], ls="none", marker="s", ms=6.0, mfc="black", mec="black", zorder=6)
    en.set_gid("end")
    handles = [Line2D([], [], color="tab:blue", lw=1.5, marker=".", ms=4.0),
               Line2D([], [], ls="none", marker="s", ms=9.0, mfc="none", mec="black", mew=1.3),
               Line2D([], [], ls="none", marker="s", ms=6.0, mfc="black", mec="black")]
    labels = [f"quasi-static path ({k} of {sim.steps} samples)", "start (sample 0)", f"last sample done ({k - 1})"]
    fold_pts, land_pts = [], []
    for j, e in enumerate(snaps):
        a, b = at_event(e, False), at_event(e, True)
        fold_pts.append(a)
        land_pts.append(b)
        arr = FancyArrowPatch(a, b, arrowstyle="-|>", shrinkA=3.0, shrinkB=3.0, mutation_scale=14, zorder=5,
                              **CONTROL_STYLES["snap"])
        arr.set_gid(f"snap-{j}")
        ax.add_patch(arr)
    style_fold = {k_: v for k_, v in CONTROL_STYLES["fold"].items()}
    F = np.array(fold_pts, dtype=float).reshape(-1, 2)
    G = np.array(land_pts, dtype=float).reshape(-1, 2)
    fp, = ax.plot(F[:, 0], F[:, 1], ls="none", zorder=7, **style_fold)
    fp.set_gid("snap-folds")
    lp, = ax.plot(G[:, 0], G[:, 1], ls="none", zorder=7, **CONTROL_STYLES["landing"])
    lp.set_gid("snap-landings")
    if snaps:
        released = sorted(e.energy_released for e in snaps if e.energy_released is not None)
        lo_hi = sorted({f"{released[0]:.3g}", f"{released[-1]:.3g}"}, key=float) if released else []
        amount = "..".join(lo_hi)
        handles += [Line2D([], [], ls="none", **style_fold),
                    Line2D([], [], color=CONTROL_STYLES["snap"]["color"], lw=1.6, marker=">", ms=5.0),
                    Line2D([], [], ls="none", **CONTROL_STYLES["landing"])]
        labels += [f"fold: the branch ends, the arm snaps ({len(snaps)})",
                   "snap (descent, inputs frozen)" + (f": energy released {amount}" if amount else ""),
                   "landing (a stable equilibrium)"]
    jl = [at_event(e, False) for e in ends]
    J = np.array(jl, dtype=float).reshape(-1, 2)
    style = {k_: v for k_, v in CONTROL_STYLES["joint_limit"].items() if k_ != "label"}
    jp, = ax.plot(J[:, 0], J[:, 1], ls="none", zorder=7, **style)
    jp.set_gid("joint-limit")
    if ends:
        handles.append(Line2D([], [], ls="none", **style))
        labels.append("the end: a joint at its range bound" if any(e.kind == "joint_limit" for e in ends)
                      else "the end: a snap into a joint's bound")
    ax.set_xlabel(spec["xlabel"])
    ax.set_ylabel(spec["ylabel"])
    ax.grid(True, lw=0.4, alpha=0.5)
    legend_beside(ax, handles, labels)
    if title is None:
        title = (f"Quasi-static simulation, {sim.mode} tip: {spec['what']}\n{k} of {sim.steps} samples, "
                 f"{len(snaps)} snap(s), status {sim.status}" + spec.get("note", "")
                 + (f"\n{chain_label(m)}" if m is not None else ""))
    ax.set_title(title, fontsize=9)
    return fig

