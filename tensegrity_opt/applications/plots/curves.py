"""The force-deflection figure of a :class:`~tensegrity_opt.Curve`: ``Fx`` above ``Fy`` against the deflection
(Fig. 6), the jumps drawn by kind, a partial curve's end marked, and every branch with ``branch="all"``."""

from __future__ import annotations

import math
import textwrap
from collections import Counter
from typing import Any

import numpy as np

from ...analyses.paths.curves import Curve, Jump
from ...model.manipulator import Manipulator
from .style import FORCE_UNIT, chain_label, new_figure, number_text

__all__ = ["plot_curve", "curve_breaks", "jump_kind", "jump_label", "JUMP_STYLES"]


def _abscissa(c: Curve) -> tuple[np.ndarray, str]:
    """The deflection that varies along the curve: ``dx``, or ``dy`` when only ``dy`` varies."""
    if c.dx.size > 1 and np.ptp(c.dx) == 0.0 and np.ptp(c.dy) > 0.0:
        return c.dy, "dy"
    return c.dx, "dx"


def _broken(x: np.ndarray, y: np.ndarray, breaks: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``x, y`` with a NaN inserted before every index in ``breaks`` (matplotlib breaks the line)."""
    return np.insert(x.astype(float), breaks, np.nan), np.insert(y.astype(float), breaks, np.nan)


def curve_breaks(c: Curve, component: int) -> np.ndarray:
    """Indices ``j`` where the plotted component (0: ``Fx``, 1: ``Fy``) of the selected curve is
    discontinuous between points ``j - 1`` and ``j``: the selected branch changes there and the
    matching :class:`~tensegrity_opt.results.Jump` changes that component (a change without a recorded
    jump also breaks). ``Fy`` stays continuous through the buckling jump (it is 0 on both sides)."""
    out = []
    for j in np.flatnonzero(c.branch[1:] != c.branch[:-1]) + 1:
        jump = next((jp for jp in c.jumps if jp.dx_before == c.dx[j - 1] and jp.dx_after == c.dx[j]
                     and jp.dy_before == c.dy[j - 1] and jp.dy_after == c.dy[j]), None)
        if jump is None or jump.force_before[component] != jump.force_after[component]:
            out.append(int(j))
    return np.array(out, dtype=int)


#: How :func:`plot_curve` draws each kind of jump (``Jump.kind``; a kind not listed here is drawn as a snap).
JUMP_STYLES = {
    "buckling": {"color": "tab:red", "ls": "--", "marker": None, "name": "buckling of the straight chain"},
    "leave_straight": {"color": "tab:orange", "ls": "--", "marker": None, "name": "leaves the straight chain"},
    "snap": {"color": "tab:red", "ls": ":", "marker": "D", "name": "snap: the stable branch ends"},
    "switch": {"color": "tab:purple", "ls": ":", "marker": "s", "name": "switch of the least-energy branch"},
}
#: Jumps listed one by one in the legend of :func:`plot_curve` (the others are counted).
_MAX_JUMP_LEGEND = 6


def jump_kind(j: Jump) -> str:
    """The kind :func:`plot_curve` draws a jump as: ``Jump.kind``, a kind :data:`JUMP_STYLES` does not list (such
    as ``"branch_switch"``) as ``"snap"``, and a ``"buckling"`` whose force after the jump is not compressive
    (``F_x >= 0``) as ``"leave_straight"``: a tensile jump is never called buckling."""
    kind = str(j.kind)
    if kind == "buckling" and not float(j.force_after[0]) < 0.0:
        return "leave_straight"
    return kind if kind in JUMP_STYLES else "snap"


def _sense(fx: float) -> str:
    return "tensile" if fx > 0 else ("compressive" if fx < 0 else "zero")


def jump_label(j: Jump) -> str:
    """``Jump.label`` when the library gives one, else a sentence of the same form naming the jump with its
    sign and size, e.g. ``"buckling of the straight chain: F_x 0 -> -0.573 (compressive)"``."""
    kind = jump_kind(j)
    try:
        label = getattr(j, "label", None) if j.kind in JUMP_STYLES else None   # not for a kind drawn as another
    except (KeyError, ValueError, TypeError):
        label = None
    if isinstance(label, str) and label and not (kind != "buckling" and label.startswith("buckling")):
        return label
    f0, f1 = float(j.force_before[0]), float(j.force_after[0])
    g0, g1 = float(j.force_before[1]), float(j.force_after[1])
    if kind in ("buckling", "leave_straight"):
        what = JUMP_STYLES[kind]["name"]
        return f"{what}: F_x {number_text(f0, f1)} -> {number_text(f1, f0)} ({_sense(f1)})"
    d = f1 - f0 if f1 != f0 else g1 - g0
    comp = "x" if f1 != f0 else "y"
    what = "snap to another stable branch" if kind == "snap" else "switch of the least-energy stable branch"
    return f"{what}: dF_{comp} = {d:+.3g}" + (f" ({_sense(f1)})" if comp == "x" else "")


def _curve_end(c: Curve, xname: str) -> tuple[float, str] | None:
    """Where a partial curve (``Curve.ended_at``, the curves contract) ends on the abscissa, and why."""
    end = c.ended_at
    if end is None:
        return None
    return float(end.dx if xname == "dx" else end.dy), end.status


def plot_curve(curve: Curve, m: Manipulator, *, figsize: tuple[float, float] = (8.0, 7.0)) -> Any:
    """Force-deflection curves ``Fx`` and ``Fy`` (Fig. 6) of a :class:`~tensegrity_opt.Curve`
    (:func:`~tensegrity_opt.force_deflection`).

    Two stacked panels sharing the abscissa, ``Fx`` above and ``Fy`` below (each on its own scale, so that
    the shape of ``Fy``, e.g. ``~ sqrt(dx)`` after buckling, is visible), against ``dx`` (against ``dy`` when
    only ``dy`` varies). The selected least-energy stable curve is drawn solid and broken at every jump. Each
    jump (``Curve.jumps``) is drawn by its kind (:func:`jump_kind`, :data:`JUMP_STYLES`): the buckling of the
    stable straight chain (vertical dashed, from 0 to the critical force), leaving an unstable straight chain,
    a snap (the followed stable branch ends), a switch of the least-energy branch (dotted, between the forces
    before and after); jumps are numbered on the ``Fx`` panel and listed with their label
    (:func:`jump_label`) in the legend, which sits below the panels (never over the data). A partial curve
    (``Curve.ended_at`` set: no stable equilibrium from some point on) is drawn as far as it goes, its last
    point marked and the end drawn as a dotted vertical with the text "stable branch ends at dx = ...".
    A curve computed with ``branch="all"`` also has every branch followed drawn (``Curve.branches``): solid
    where stable, dashed where unstable. The axes are in the caller's units (lengths, forces
    ``stiffness x length``); the title gives the chain's parameters.

    Artists (``gid``): ``"fx"``, ``"fy"`` (the selected curve, NaN-separated at every jump),
    ``"jump-<k>-<kind>-fx"`` / ``"-fy"``, ``"jump-<k>-number-fx"``, a partial curve's ``"end-marker-fx"`` /
    ``"-fy"``, ``"curve-end-fx"`` / ``"-fy"``, ``"curve-end-text"``, ``"branch-<id>-fx-stable"`` /
    ``"-unstable"`` (the package's docstring says what each holds).

    Parameters
    ----------
    curve : Curve
        The curve to draw.
    m : Manipulator
        Its chain (for the title).
    figsize : (float, float)
        The figure's size (inches).
    """
    c = curve
    x, xname = _abscissa(c)
    from matplotlib.lines import Line2D

    fig = new_figure(figsize)
    axes = fig.subplots(2, 1, sharex=True)
    comps = (("fx", c.fx, "$F_x$"), ("fy", c.fy, "$F_y$"))
    colors = ["tab:blue", "tab:purple", "tab:brown", "tab:pink", "tab:olive", "tab:cyan", "tab:gray"]
    handles: dict[str, Any] = {}
    end = _curve_end(c, xname)
    sym = "\\delta_x" if xname == "dx" else "\\delta_y"
    for comp, (ax, (name, vals, tex)) in enumerate(zip(axes, comps)):
        breaks = curve_breaks(c, comp)
        ax.axhline(0.0, color="0.75", lw=0.8, zorder=0)
        if c.branches:
            ax.plot(*_broken(x, vals, breaks), color="0.8", lw=5.0, solid_capstyle="round", zorder=1)
            handles.setdefault("least-energy stable (selected)",
                               Line2D([], [], color="0.8", lw=5.0, solid_capstyle="round"))
            for k, br in enumerate(c.branches):
                bid = int(br.branch[0]) if br.branch.size else k
                v = getattr(br, name)
                ok = np.isfinite(v)
                shape = next((s for s, good in zip(br.shape, ok) if good and s), "")
                col = colors[k % len(colors)]
                bx = br.dx if xname == "dx" else br.dy
                line, = ax.plot(bx, np.where(ok & br.stable, v, np.nan), color=col, lw=1.5, zorder=3)
                line.set_gid(f"branch-{bid}-{name}-stable")
                line, = ax.plot(bx, np.where(ok & ~br.stable, v, np.nan), color=col, lw=1.2, ls="--", zorder=2)
                line.set_gid(f"branch-{bid}-{name}-unstable")
                handles.setdefault(f"branch {bid} {shape}".rstrip(), Line2D([], [], color=col, lw=1.5))
            handles.setdefault("unstable part (dashed)", Line2D([], [], color="0.4", lw=1.2, ls="--"))
        line, = ax.plot(*_broken(x, vals, breaks), color="black" if c.branches else "tab:blue",
                        lw=1.0 if c.branches else 1.8, marker="o", ms=2.5, zorder=4)
        line.set_gid(name)
        if not c.branches:
            handles.setdefault("least-energy stable equilibrium", Line2D([], [], color="tab:blue", lw=1.8,
                                                                         marker="o", ms=2.5))
        for k, j in enumerate(c.jumps):
            f0, f1 = float(j.force_before[comp]), float(j.force_after[comp])
            if f0 == f1:
                continue                        # this component is continuous there
            kind = jump_kind(j)
            st = JUMP_STYLES[kind]
            xa = float(j.dx_before if xname == "dx" else j.dy_before)
            xb = float(j.dx_after if xname == "dx" else j.dy_after)
            if kind == "buckling":
                xb = xa                          # vertical: from 0 to the critical force at dx -> 0+
            seg, = ax.plot([xa, xb], [f0, f1], color=st["color"], ls=st["ls"], lw=1.5, marker=st["marker"], ms=4,
                           zorder=5)
            seg.set_gid(f"jump-{k}-{kind}-{name}")
            ax.plot([xb], [f1], marker="o", mfc="white", mec=st["color"], ls="none", zorder=6)
            if comp == 0 or float(j.force_before[0]) == float(j.force_after[0]):
                # beside a vertical jump, above (alternately below) a slanted one: clear of its end markers
                side = 1 if k % 2 == 0 else -1
                off, ha, va = (((8 * side, 0), "left" if side > 0 else "right", "center") if xa == xb else
                               ((0, 10 * side), "center", "bottom" if side > 0 else "top"))
                anchor = ((xa + xb) / 2, (max(f0, f1) if side > 0 else min(f0, f1)) if xa != xb else (f0 + f1) / 2)
                num = ax.annotate(f"{k + 1}", anchor, textcoords="offset points", xytext=off, ha=ha, va=va,
                                  fontsize=7, color=st["color"], fontweight="bold",
                                  bbox={"boxstyle": "circle,pad=0.15", "fc": "white", "ec": st["color"], "lw": 0.6})
                num.set_gid(f"jump-{k}-number-{name}")
        if end is not None and math.isfinite(end[0]):
            xe = end[0]
            vline = ax.axvline(xe, color="0.35", ls=":", lw=1.2, zorder=2)
            vline.set_gid(f"curve-end-{name}")
            ok = np.isfinite(vals)
            if ok.any():
                last = int(np.flatnonzero(ok)[-1])
                mk, = ax.plot([x[last]], [vals[last]], ls="none", marker="X", ms=8, mfc="tab:red", mec="black",
                              zorder=7)
                mk.set_gid(f"end-marker-{name}")
            if comp == 0:
                what = "stable branch ends" if end[1] in ("", "no_stable_equilibrium") else f"curve stops ({end[1]})"
                txt = ax.annotate(f"{what} at ${sym}$ = {xe:.4g}", (xe, 1.0), xycoords=("data", "axes fraction"),
                                  textcoords="offset points", xytext=(-4, -4), ha="right", va="top", fontsize=8,
                                  color="0.2", bbox={"boxstyle": "round,pad=0.2", "fc": "white", "ec": "0.6",
                                                     "alpha": 0.9})
                txt.set_gid("curve-end-text")
        ax.set_ylabel(f"tip force {tex} ({FORCE_UNIT})")
        ax.grid(True, lw=0.4, alpha=0.5)
    if end is not None:
        handles.setdefault("last point computed (the stable branch ends after it)",
                           Line2D([], [], ls="none", marker="X", ms=8, mfc="tab:red", mec="black"))
    for k, j in enumerate(c.jumps[:_MAX_JUMP_LEGEND]):
        st = JUMP_STYLES[jump_kind(j)]
        handles[f"jump {k + 1}: {jump_label(j)}"] = Line2D([], [], color=st["color"], ls=st["ls"], lw=1.5,
                                                           marker=st["marker"], ms=4)
    if len(c.jumps) > _MAX_JUMP_LEGEND:
        rest = Counter(jump_kind(j) for j in c.jumps[_MAX_JUMP_LEGEND:])
        handles["... and " + ", ".join(f"{v} {k}" for k, v in sorted(rest.items()))] = Line2D([], [], ls="none")
    xs = [float(v) for v in x if math.isfinite(float(v))] + ([end[0]] if end is not None and math.isfinite(end[0])
                                                              else [])
    if xs and max(xs) > min(xs):
        pad = 0.03 * (max(xs) - min(xs))                # a jump at the first abscissa stays off the spine
        axes[1].set_xlim(min(xs) - pad, max(xs) + pad)
    axes[1].set_xlabel(f"tip deflection ${sym}$ (length)" + (", > 0 shortens the chain" if xname == "dx" else ""))
    axes[0].tick_params(labelbottom=False)
    width = max(40, int(figsize[0] * 14))          # characters of a 7-point line across the figure
    long = any(len(t) > width // 2 - 4 for t in handles)
    fig.legend(list(handles.values()), [textwrap.fill(t, width, subsequent_indent="    ") for t in handles],
               fontsize=7, loc="outside lower center", ncols=1 if long or len(handles) > 4 else 2, frameon=False)
    other = f"$\\delta_y$ = {float(c.dy[0]):g}" if xname == "dx" and c.dy.size and np.ptp(c.dy) == 0 else (
        f"$\\delta_x$ = {float(c.dx[0]):g}" if xname == "dy" and c.dx.size else "")
    ref = " (from the rest configuration)" if c.reference == "rest" else ""
    head = ("Force-deflection curves" + (" (all branches)" if c.branches else " (least-energy stable)")
            + (f", {other}" if other else "") + ref + "; $F_x$ < 0 compressive")
    note = "" if c.success else c.message
    note = textwrap.fill(note, max(40, int(figsize[0] * 12))) if note else ""
    fig.suptitle(head + f"\n{chain_label(m)}" + (f"\n{note}" if note else ""), fontsize=9)
    return fig


