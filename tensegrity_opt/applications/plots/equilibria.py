"""Figures of equilibria and segments: the energy landscape with every equilibrium marked (Figs. 4-5), the chain
drawn in each equilibrium, and the torque-angle curves of segments (Fig. 2)."""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from typing import Any

import numpy as np

from ...analyses.equilibria.equilibrium import Equilibrium
from ...analyses.equilibria.landscape import Landscape, complete_configuration, landscape_margin
from ...analyses.equilibria.modes import Modes
from ...errors import InvalidParameterError
from ...model.inertia import mass_points
from ...model.loads import describe, loads_key
from ...model.manipulator import Manipulator
from ...model.segment import Segment
from .geometry import chain_geometry
from .style import (
    ENERGY_UNIT,
    FORCE_UNIT,
    MAP_PARAMS,
    STABILITY_COLORS,
    chain_label,
    contour_levels,
    new_figure,
    number_text,
    param_text,
)

__all__ = ["plot_landscape", "plot_shapes", "plot_modes", "plot_torque", "landscape_region", "segment_label",
           "physical_range",
           "stiffness_text", "torque_zeros", "distinct_segments"]

_KIND_TEXT = {"minimum": "stable", "saddle": "saddle", "maximum": "maximum", "degenerate": "degenerate"}


# ---------------------------------------------------------------------------- landscape
def _elbow_of(m: Manipulator, target: np.ndarray, pair: tuple[int, int], q: np.ndarray) -> int:
    """Index (0: elbow +1, 1: elbow -1) of the landscape branch through ``q``."""
    errs = []
    for elbow in (1, -1):
        full = complete_configuration(m, target, pair, q[pair[0]], q[pair[1]], elbow)
        err = float(np.max(np.abs(full - q)))
        errs.append(err if math.isfinite(err) else math.inf)
    return int(np.argmin(errs))


def _energy_of(m: Manipulator, q: np.ndarray) -> np.ndarray:
    """``E(q)`` over the last axis of ``q`` (any finite ``q``, also beyond the physical range)."""
    c = np.hypot(m.a, m.b)
    beta = np.arctan2(m.a, m.b)
    L1, L2 = 2 * c * np.cos(beta + q / 2), 2 * c * np.cos(beta - q / 2)
    return 0.5 * ((m.k1 * (L1 - m.L1_0) ** 2).sum(-1) + (m.k2 * (L2 - m.L2_0) ** 2).sum(-1))


def landscape_region(m: Manipulator, target: Any, pair: tuple[int, int], qi: np.ndarray, qj: np.ndarray,
                     elbow: int, refine: int = 4) -> Any:
    """The drawn region of one elbow branch of the landscape as a :class:`matplotlib.path.Path`: where
    :func:`~tensegrity_opt.analyses.equilibria.landscape.landscape_margin` is positive (reachable and inside the
    physical range) within the axes ``qi x qj``; its outline is the margin's zero contour on a grid
    ``refine`` times finer than the axes', i.e. the exact boundary (a smooth curve), not the grid's cells.
    ``None`` when the region is empty."""
    import contourpy
    from matplotlib.path import Path as MPath

    qi, qj = np.asarray(qi, float), np.asarray(qj, float)
    fi = np.linspace(qi[0], qi[-1], max(2, (qi.size - 1) * int(refine) + 1))
    fj = np.linspace(qj[0], qj[-1], max(2, (qj.size - 1) * int(refine) + 1))
    FI, FJ = np.meshgrid(fi, fj, indexing="xy")
    margin, _ = landscape_margin(m, target, pair, FI, FJ, elbow)
    # the axes' box as a second constraint, so that the region closes along the axes when it is cut there
    hx, hy = (fi[-1] - fi[0]) / 2, (fj[-1] - fj[0]) / 2
    box = np.minimum((hx - np.abs(FI - (fi[0] + hx))) / max(hx, 1e-300),
                     (hy - np.abs(FJ - (fj[0] + hy))) / max(hy, 1e-300))
    z = np.where(np.isfinite(margin), np.minimum(margin, box), -1.0)
    if not (z > 0).any():
        return None
    gen = contourpy.contour_generator(fi, fj, z, fill_type=contourpy.FillType.OuterCode)
    polys, codes = gen.filled(0.0, np.inf)
    if not polys:
        return None
    return MPath(np.vstack(polys), np.concatenate(codes))


def plot_landscape(landscape: Landscape, equilibria: Sequence[Equilibrium], m: Manipulator, dx: float,
                   dy: float = 0.0, *, levels: int = 24, figsize: tuple[float, float] = (10.6, 5.0)) -> Any:
    """The energy landscape ``E(q_i, q_j)`` (Figs. 4-5, n = 4) of a :class:`~tensegrity_opt.Landscape`
    (:func:`~tensegrity_opt.energy_landscape`) with the equilibria marked.

    One panel per elbow branch: the energy (the other two joints solved for the tip target) as filled contours
    at evenly spaced levels (:class:`~matplotlib.ticker.MaxNLocator`, about ``levels`` of them) with contour
    lines, a colour bar with the quantity and unit. The drawn region is the reachable set inside the physical
    range, cut at its exact boundary (:func:`landscape_region`: the zero contour of a continuous margin, drawn
    as a black line), not at the grid's cells. Every equilibrium of ``equilibria`` (those of
    :func:`~tensegrity_opt.find_equilibria` at the same deflection) is marked at its ``(q_i, q_j)`` on the
    branch it lies on, coloured by stability and labelled with its shape; each lies inside the drawn region
    (an equilibrium is reachable and in range). The legend sits below the panels; the title gives the
    chain's parameters, the deflection and the count.

    Artists (``gid``): ``"energy-elbow+1"`` / ``"-1"`` (the grid's values, a QuadMesh with the array
    ``energy[e].T``, not drawn: the filled contours show them), ``"energy-fill-elbow..."`` (filled contour set,
    clipped to the region), ``"contour-elbow..."`` (contour lines), ``"boundary-elbow..."`` (the region's
    outline, a PathPatch whose path is :func:`landscape_region`), ``"equilibria-elbow..."`` (scatter).

    Parameters
    ----------
    landscape : Landscape
        The energy over the grid (its axes are the figure's).
    equilibria : sequence of Equilibrium
        The equilibria to mark (an :class:`~tensegrity_opt.EquilibriumSet` or any sequence).
    m : Manipulator
        The chain of the landscape (4 segments).
    dx, dy : float
        The tip deflection the landscape was computed for.
    levels : int
        About how many contour levels.
    figsize : (float, float)
        The figure's size (inches).
    """
    land = landscape
    eqs = list(equilibria)
    pair = land.pair
    target = m.target(dx, dy)
    import matplotlib
    from matplotlib.lines import Line2D
    from matplotlib.patches import PathPatch
    from matplotlib.ticker import MaxNLocator

    cmap = matplotlib.colormaps["viridis"].with_extremes(bad=(1.0, 1.0, 1.0, 0.0))
    lv = contour_levels(land.energy, levels)
    fig = new_figure(figsize)
    axes = fig.subplots(1, 2, sharex=True, sharey=True)
    where = [_elbow_of(m, target, pair, e.q) for e in eqs]
    QI, QJ = np.meshgrid(land.qi, land.qj, indexing="xy")        # (len(qj), len(qi)): matplotlib's order
    fill = None
    for b, (ax, elbow) in enumerate(zip(axes, ("+1", "-1"))):
        E = np.ma.masked_invalid(land.energy[b].T)
        mesh = ax.pcolormesh(land.qi, land.qj, E, shading="nearest", cmap=cmap, rasterized=True, visible=False)
        mesh.set_gid(f"energy-elbow{elbow}")
        region = landscape_region(m, target, pair, land.qi, land.qj, 1 if b == 0 else -1)
        if region is not None and lv.size >= 2:
            margin, qext = landscape_margin(m, target, pair, QI, QJ, 1 if b == 0 else -1)
            Eext = _energy_of(m, qext)                           # continued beyond the boundary, then clipped
            fill = ax.contourf(land.qi, land.qj, Eext, levels=lv, cmap=cmap, extend="both")
            fill.set_gid(f"energy-fill-elbow{elbow}")
            fill.set_clip_path(region, ax.transData)
            cs = ax.contour(land.qi, land.qj, Eext, levels=lv, colors="k", linewidths=0.4, alpha=0.6)
            cs.set_gid(f"contour-elbow{elbow}")
            cs.set_clip_path(region, ax.transData)
        if region is not None:
            edge = PathPatch(region, facecolor="none", edgecolor="black", lw=1.0, zorder=4)
            edge.set_gid(f"boundary-elbow{elbow}")
            ax.add_patch(edge)
        mine = [e for e, w in zip(eqs, where) if w == b]
        pts = np.array([[e.q[pair[0]], e.q[pair[1]]] for e in mine]).reshape(-1, 2)
        sc = ax.scatter(pts[:, 0], pts[:, 1], c=[STABILITY_COLORS.get(e.kind, "k") for e in mine] or None,
                        s=60, edgecolors="black", linewidths=0.8, zorder=5)
        sc.set_gid(f"equilibria-elbow{elbow}")
        for e, (x, y) in zip(mine, pts):
            # the label on the side away from the panel's centre (inside the region's hull, not over the edge)
            cx = 0.5 * (land.qi[0] + land.qi[-1])
            right = x <= cx
            ax.annotate(f"{e.shape}", (x, y), textcoords="offset points", xytext=(7 if right else -7, 5),
                        ha="left" if right else "right", fontsize=8, fontweight="bold", color="black", zorder=6,
                        bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "none", "alpha": 0.8})
        u, v = (k + 1 for k in range(4) if k not in pair)
        ax.set_title(f"elbow {elbow} (of the two-link solution for $q_{u}, q_{v}$)", fontsize=9)
        ax.set_xlabel(f"joint angle $q_{pair[0] + 1}$ (rad)")
        ax.set_xlim(float(np.min(land.qi)), float(np.max(land.qi)))
        ax.set_ylim(float(np.min(land.qj)), float(np.max(land.qj)))
        ax.set_aspect("equal", adjustable="box")
        ax.xaxis.set_major_locator(MaxNLocator(nbins=5))
        ax.grid(True, lw=0.3, alpha=0.4)
    axes[0].set_ylabel(f"joint angle $q_{pair[1] + 1}$ (rad)")
    if fill is not None:
        fig.colorbar(fill, ax=list(axes), label=f"elastic energy $E$ ({ENERGY_UNIT})", shrink=0.9,
                     ticks=lv[::max(1, math.ceil(lv.size / 8))])
    kinds = [k for k in STABILITY_COLORS if any(e.kind == k for e in eqs)]
    hs = [Line2D([], [], ls="none", marker="o", ms=7, mfc=STABILITY_COLORS[k], mec="black") for k in kinds]
    ls = [f"{_KIND_TEXT[k]} equilibrium" for k in kinds]
    hs.append(Line2D([], [], color="black", lw=1.0))
    ls.append("boundary: tip unreachable or a joint at its range bound beyond")
    fig.legend(hs, ls, fontsize=7, loc="outside lower center", ncols=len(hs), frameon=False)
    others = [k + 1 for k in range(4) if k not in pair]
    fig.suptitle(f"Energy landscape $E(q_{pair[0] + 1}, q_{pair[1] + 1})$, $q_{others[0]}, q_{others[1]}$ solved "
                 f"for the tip at $\\delta_x$ = {dx:g}, $\\delta_y$ = {dy:g}: {len(eqs)} equilibria\n{chain_label(m)}",
                 fontsize=9)
    return fig



# ---------------------------------------------------------------------------- shapes
#: How a spring is drawn by its state (``springs="state"``): taut in the panel's stability colour, a linear-law spring
#: shorter than its rest length (pushing: a force a real tension spring cannot carry) red and dashed, a slack
#: tension-only spring grey and dotted.
SPRING_STYLES = {"pushing": {"color": "tab:red", "ls": "--", "lw": 1.6},
                 "slack": {"color": "0.55", "ls": ":", "lw": 1.1}}


def plot_shapes(equilibria: Sequence[Equilibrium], m: Manipulator, dx: float, dy: float = 0.0, *,
                max_panels: int = 24, ncols: int | None = None, panel_width: float = 3.8,
                spring_colors: str = "state") -> Any:
    """The chain drawn in each of ``equilibria`` (those of :func:`~tensegrity_opt.find_equilibria`, an
    :class:`~tensegrity_opt.EquilibriumSet` or any sequence of :class:`~tensegrity_opt.Equilibrium`), one panel
    each.

    Each panel draws, for every segment, both triangles (polygons), the joint (dot) and both
    springs (lines between the triangles' base corners), coloured by stability (stable green,
    saddle orange, maximum red), with the link centre line and the tip; the title is Table 2's
    shape label, the kind, the energy and the tip force. At most ``max_panels`` equilibria (the
    first ones: the lowest energies of a set) are drawn. ``m`` is their chain; ``dx``, ``dy`` the tip
    deflection named in the title.

    ``spring_colors``: ``"state"`` (default) draws a taut spring solid in the panel's colour, a pushing one (linear
    law, shorter than its rest length) red and dashed, a slack one (tension-only law) grey and dotted
    (:data:`SPRING_STYLES`); ``"tension"`` colours every spring by its force (tension positive) on one diverging
    scale shared by the panels, with a colour bar. A joint resting on its stop is ringed (``"stop-<i>"``).

    A chain with weight (``gravity``) has an arrow ``g`` in each panel and its loads in the title.

    Artists (``gid``): per panel ``"triangle-<i>-<0|1>"`` (proximal/distal triangle of segment ``i``),
    ``"spring-<i>-<1|2>"``, ``"joints"`` (scatter), ``"centerline"``, ``"tip"``, ``"stop-<i>"``, ``"gravity"``; the
    axes' gid is
    ``"equilibrium-<k>"``; with ``spring_colors="tension"`` the colour bar's axes ``"spring-forces"``.
    """
    if spring_colors not in ("state", "tension"):
        raise InvalidParameterError(f"spring_colors must be 'state' or 'tension', got {spring_colors!r}",
                                    field="spring_colors")
    eqs = list(equilibria)
    shown = eqs[:max(1, int(max_panels))]
    k = len(shown)
    cols = ncols or min(k, 3)
    rows = math.ceil(k / cols)
    geos = [chain_geometry(m, e.q) for e in shown]
    allpts = np.vstack([np.vstack([g["triangles"].reshape(-1, 2), g["centerline"]]) for g in geos])
    amax = float(np.max(m.a))
    lo = allpts.min(axis=0) - 0.15 * amax
    hi = allpts.max(axis=0) + 0.15 * amax
    aspect = float(np.clip((hi[1] - lo[1]) / max(hi[0] - lo[0], 1e-12), 0.15, 3.0))
    width = panel_width
    fig = new_figure((width * cols, (width * aspect + 0.9) * rows + 0.4))
    axes = np.atleast_1d(fig.subplots(rows, cols, squeeze=False)).ravel()
    from matplotlib.colors import TwoSlopeNorm
    from matplotlib.patches import Polygon

    forces = [m.springs.forces(e.q) if e.springs is None else e.spring_forces for e in shown]
    states = [m.springs.states(e.q) if e.springs is None else e.spring_states for e in shown]
    norm = cmap = None
    if spring_colors == "tension":
        import matplotlib

        top = max(float(np.abs(f).max()) for f in forces) or 1.0
        norm, cmap = TwoSlopeNorm(0.0, -top, top), matplotlib.colormaps["coolwarm"]
    for idx, (ax, e, g) in enumerate(zip(axes, shown, geos)):
        col = STABILITY_COLORS.get(e.kind, "k")
        ax.set_gid(f"equilibrium-{idx}")
        ax.plot([0.0, 0.0], [-1.4 * m.a[0], 1.4 * m.a[0]], color="0.3", lw=3.0, solid_capstyle="butt")
        line, = ax.plot(g["centerline"][:, 0], g["centerline"][:, 1], color="0.55", lw=0.8, zorder=1)
        line.set_gid("centerline")
        for i in range(m.n):
            for t in range(2):
                poly = Polygon(g["triangles"][i, t], closed=True, facecolor=col, alpha=0.35, edgecolor=col, lw=0.9,
                               zorder=2)
                poly.set_gid(f"triangle-{i}-{t}")
                ax.add_patch(poly)
            for s in range(2):
                p = g["springs"][i, s]
                style = {"color": col, "ls": "-", "lw": 1.4}
                if spring_colors == "tension":
                    style = {"color": cmap(norm(float(forces[idx][i, s]))), "ls": "-", "lw": 2.0}
                style.update(SPRING_STYLES.get(str(states[idx][i, s]), {}) if spring_colors == "state" else {})
                line, = ax.plot(p[:, 0], p[:, 1], zorder=3, **style)
                line.set_gid(f"spring-{i}-{s + 1}")
            if e.at_stop[i]:
                ring, = ax.plot([g["joints"][i, 0]], [g["joints"][i, 1]], marker="o", ms=9, mfc="none",
                                mec="black", mew=1.2, ls="none", zorder=5)
                ring.set_gid(f"stop-{i}")
        sc = ax.scatter(g["joints"][:, 0], g["joints"][:, 1], s=14, color="black", zorder=4)
        sc.set_gid("joints")
        line, = ax.plot([g["tip"][0]], [g["tip"][1]], marker="x", color="black", ms=6, zorder=5)
        line.set_gid("tip")
        ax.set_title(f"{e.shape} ({e.signs}): {_KIND_TEXT.get(e.kind, e.kind)}\n"
                     f"E = {e.energy:.4g}, F = ({number_text(e.fx, e.fy)}, {number_text(e.fy, e.fx)})",
                     fontsize=8, color=col)
        _chain_panel(ax, lo, hi, idx, cols, k)
        if m.loaded and m.gravity is not None:          # the weights' direction
            gx, gy = m.gravity
            norm_g = math.hypot(gx, gy) or 1.0
            arrow = ax.annotate("$g$", xy=(0.9 + 0.07 * gx / norm_g, 0.82 + 0.07 * gy / norm_g),
                                xytext=(0.9 - 0.07 * gx / norm_g, 0.82 - 0.07 * gy / norm_g),
                                xycoords="axes fraction", textcoords="axes fraction", ha="center", va="center",
                                fontsize=8, arrowprops={"arrowstyle": "->", "color": "0.3"})
            arrow.set_gid("gravity")
    for ax in axes[k:]:
        ax.set_visible(False)
    more = f" (the {k} lowest of {len(eqs)})" if len(eqs) > k else ""
    how = ("springs by force (tension > 0)" if spring_colors == "tension" else
           "springs: taut solid, pushing red dashed, slack grey dotted")
    loads = describe(loads_key(m))
    fig.suptitle(f"Equilibria with the tip held at $\\delta_x$ = {dx:g}, $\\delta_y$ = {dy:g}: {len(eqs)}{more}\n"
                 f"{chain_label(m)}" + (f"; under {loads}" if loads else "")
                 + ("; " if cols >= 3 and not loads else "\n") + f"{how}; stops ringed"
                 + ("; " if cols >= 3 else "\n") + f"energy $E$ in {ENERGY_UNIT}, tip force $F$ in {FORCE_UNIT}",
                 fontsize=9)
    if spring_colors == "tension":
        from matplotlib.cm import ScalarMappable

        cb = fig.colorbar(ScalarMappable(norm=norm, cmap=cmap), ax=list(axes[:k]), shrink=0.8)
        cb.set_label(f"spring force ({FORCE_UNIT}; tension > 0)", fontsize=8)
        cb.ax.set_gid("spring-forces")
    return fig



def _chain_panel(ax: Any, lo: np.ndarray, hi: np.ndarray, idx: int, cols: int, k: int) -> None:
    """One panel of a grid of ``k`` chain drawings (``cols`` a row): the common limits, equal axes, and the axis
    labels on the left column and the bottom row."""
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal", adjustable="box")
    ax.tick_params(labelsize=7)
    if idx % cols == 0:
        ax.set_ylabel("$y$ (length)", fontsize=8)
    if idx + cols >= k:
        ax.set_xlabel("$x$ (length)", fontsize=8)


# ---------------------------------------------------------------------------- modes
#: The two sides of a mode in :func:`plot_modes`: ``+`` and ``-`` its (scaled) shape.
MODE_COLORS = ("tab:blue", "tab:orange")


def plot_modes(modes: Modes, m: Manipulator, *, excursion: float = 0.3, max_panels: int = 8,
               panel_width: float = 3.8) -> Any:
    """The vibration modes of :func:`~tensegrity_opt.modes`, one panel per mode (the lowest ``max_panels``).

    Each panel draws the equilibrium's centre line (grey, its triangles' centroids and the payload as dots sized by
    their mass) and the chain displaced along the mode both ways, ``q* +- s shape`` (blue ``+``, orange ``-``),
    ``s`` scaling the largest joint excursion to ``excursion`` rad; a joint held on its stop is ringed. The title
    gives the mode's frequency (rad/s and Hz), or says that the direction does not vibrate (``w^2 <= 0``).

    Artists (``gid``): per panel ``"equilibrium"``, ``"mode-plus"``, ``"mode-minus"``, ``"masses"``, ``"stop-<i>"``;
    the axes' gid is ``"mode-<k>"``.
    """
    if not (isinstance(excursion, (int, float)) and math.isfinite(excursion) and excursion > 0):
        raise InvalidParameterError(f"excursion must be a finite number > 0, got {excursion!r}", field="excursion")
    q0 = np.asarray(modes.equilibrium.q, dtype=float)
    k = min(int(max_panels), modes.eigenvalues.size)
    if k < 1:
        raise InvalidParameterError("the equilibrium leaves no motion to draw (no mode)", field="modes")
    cols = min(k, 3)
    rows = math.ceil(k / cols)
    shapes = [modes.shapes[i] * (excursion / max(float(np.abs(modes.shapes[i]).max()), 1e-300)) for i in range(k)]
    lines = [[chain_geometry(m, q0 + sg * s)["centerline"] for sg in (1.0, -1.0)] for s in shapes]
    base = chain_geometry(m, q0)
    pts = np.vstack([base["centerline"], *[c for pair in lines for c in pair]])
    pad = 0.1 * float(np.max(m.b))
    lo, hi = pts.min(axis=0) - pad, pts.max(axis=0) + pad
    aspect = float(np.clip((hi[1] - lo[1]) / max(hi[0] - lo[0], 1e-12), 0.2, 3.0))
    fig = new_figure((panel_width * cols, (panel_width * aspect + 0.8) * rows + 0.5))
    axes = np.atleast_1d(fig.subplots(rows, cols, squeeze=False)).ravel()
    mass, joint, link, offset = mass_points(m)
    phi = base["link_angles"][1:]
    where = base["joints"][joint] + offset[:, None] * np.column_stack([np.cos(phi[link]), np.sin(phi[link])])
    size = 60.0 * mass / max(float(mass.max()), 1e-300)
    for idx in range(k):
        ax = axes[idx]
        ax.set_gid(f"mode-{idx}")
        eq_line, = ax.plot(base["centerline"][:, 0], base["centerline"][:, 1], color="0.5", lw=2.0, zorder=2)
        eq_line.set_gid("equilibrium")
        for side, (gid, col) in enumerate(zip(("mode-plus", "mode-minus"), MODE_COLORS)):
            ln, = ax.plot(lines[idx][side][:, 0], lines[idx][side][:, 1], color=col, lw=1.4, marker="o", ms=3,
                          zorder=3)
            ln.set_gid(gid)
        sc = ax.scatter(where[mass > 0, 0], where[mass > 0, 1], s=size[mass > 0], color="black", zorder=4)
        sc.set_gid("masses")
        for j in np.flatnonzero(modes.held_joints):
            ring, = ax.plot([base["joints"][j, 0]], [base["joints"][j, 1]], marker="o", ms=9, mfc="none",
                            mec="black", mew=1.2, ls="none", zorder=5)
            ring.set_gid(f"stop-{j}")
        w = float(modes.frequencies[idx])
        title = (f"mode {idx + 1}: $\\omega$ = {w:.4g} rad/s ({w / (2 * math.pi):.4g} Hz)" if math.isfinite(w)
                 else f"direction {idx + 1}: does not vibrate ($\\omega^2$ = {modes.eigenvalues[idx]:.3g})")
        ax.set_title(title, fontsize=8, color="black" if math.isfinite(w) else STABILITY_COLORS.get("saddle", "r"))
        _chain_panel(ax, lo, hi, idx, cols, k)
    for ax in axes[k:]:
        ax.set_visible(False)
    held = "the tip held" if modes.tip == "held" else "the tip loaded (free)"
    fig.suptitle(f"Vibration modes with {held}: {modes.eigenvalues.size} directions, {modes.status}\n"
                 f"{chain_label(m)}; total mass {modes.total_mass:.4g}; each mode drawn both ways, largest joint "
                 f"excursion {excursion:g} rad", fontsize=9)
    return fig


# ---------------------------------------------------------------------------- torque
def distinct_segments(segments: Segment | Manipulator | Iterable[Segment]) -> list[Segment]:
    """The segments a torque figure draws: ``segments`` itself, or the distinct ones of a chain or an iterable
    (in order; :class:`InvalidParameterError` for an item that is no segment, or none at all)."""
    if isinstance(segments, Segment):
        return [segments]
    if isinstance(segments, Manipulator):
        segs = list(segments.segments)
    else:
        segs = list(segments)
    out: list[Segment] = []
    for i, s in enumerate(segs):
        if not isinstance(s, Segment):
            raise InvalidParameterError(f"segments[{i}] must be a Segment, got {type(s).__name__}",
                                        field=f"segments[{i}]")
        if s not in out:
            out.append(s)
    if not out:
        raise InvalidParameterError("plot_torque needs at least one segment", field="segments")
    return out


def segment_label(seg: Segment, others: Sequence[Segment] = ()) -> str:
    """``"a=1, b=1, k=1, L0=1.2"``, restricted to the parameters that differ among ``others`` if any."""
    names = [p for p in MAP_PARAMS if len({getattr(s, p) for s in others}) > 1] or list(MAP_PARAMS)
    return ", ".join(f"{p}={param_text(getattr(seg, p))}" for p in names)


def physical_range(seg: Segment, num: int = 401) -> np.ndarray:
    """``num`` angles evenly spaced inside the open physical range ``|q| < pi - 2 beta``."""
    lim = seg.joint_limit
    return np.linspace(-lim, lim, int(num) + 2)[1:-1]


def _clean(v: float, scale: float, rel: float = 1e-9) -> float:
    """``v`` with rounding noise removed: ``0.0`` when ``|v| <= rel * scale`` (e.g. ``K = 1.1e-16`` for ``K = 0``)."""
    return 0.0 if abs(v) <= rel * abs(scale) else float(v)


def stiffness_text(seg: Segment) -> str:
    """``"K = -1: two-mode"``: the joint stiffness ``K = E''(0)`` of a segment, zero to rounding printed as 0
    (relative to the scale ``k (b L0 + 2 (a^2 + b^2))`` of its terms), and the shape of its torque curve
    (``monotonic``, ``two-mode`` when ``K < 0``, ``degenerate`` at ``K = 0``, else ``non-monotonic``)."""
    kmax = max(seg.k1, seg.k2)
    scale = kmax * (seg.b * max(seg.L1_0, seg.L2_0) + 2.0 * (seg.a ** 2 + seg.b ** 2))
    K = _clean(seg.stiffness, scale)
    if K == 0.0:
        kind = "degenerate"
    elif K < 0.0:
        kind = "two-mode"
    else:
        kind = "monotonic" if seg.monotonic() else "non-monotonic"
    return f"K = {K:.3g}: {kind}"


def torque_zeros(q: np.ndarray, M: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The equilibria of an unloaded segment on a sampled torque curve: the angles where ``M`` is zero or
    changes sign (linear interpolation between samples), and whether each is stable: ``M`` falls through
    zero (positive before, negative after, so a deflection is pushed back; also at ``K = 0`` when the curve
    is monotonic there)."""
    q, M = np.asarray(q, float), np.asarray(M, float)
    out_q, out_s = [], []
    for i in range(q.size - 1):
        a, b = M[i], M[i + 1]
        if a == 0.0 and 0 < i:
            out_q.append(q[i])
            out_s.append(bool(M[i - 1] > 0.0 > b))
        elif a * b < 0.0:
            out_q.append(q[i] - a * (q[i + 1] - q[i]) / (b - a))
            out_s.append(bool(a > 0.0))
    return np.array(out_q, float), np.array(out_s, bool)


def _common_label(segs: Sequence[Segment]) -> str:
    """The parameters every segment shares, ``"a = 0.5, b = 1, k = 1"`` (empty when none)."""
    same = [p for p in MAP_PARAMS if len({getattr(s, p) for s in segs}) == 1]
    return ", ".join(f"{p} = {param_text(getattr(segs[0], p))}" for p in same)


def plot_torque(segments: Segment | Manipulator | Iterable[Segment], q: Any = None, *, num: int = 401,
                labels: Sequence[str] | None = None, figsize: tuple[float, float] = (7.0, 5.4)) -> Any:
    """Torque-angle curves ``M(q)`` (Fig. 2) of one or several segments from :meth:`Segment.torque`.

    ``q``: the angles (rad) for every curve; default ``num`` angles across each segment's own
    open physical range ``|q| < pi - 2 beta`` (:func:`physical_range`), whose bounds are drawn
    as dotted verticals. A Manipulator contributes its distinct segments. Each curve's legend entry
    gives the parameters that differ between the segments and the joint stiffness
    (:func:`stiffness_text`: ``K > 0`` monotonic, ``K < 0`` two-mode, i.e. the straight joint unstable);
    the parameters they share are in the title. The legend sits below the axes (never over the data);
    the torque is in ``stiffness x length^2``, the angle in rad.
    """
    segs = distinct_segments(segments)
    if labels is not None and len(labels) != len(segs):
        raise InvalidParameterError(f"labels must have {len(segs)} entries", field="labels")
    fig = new_figure(figsize)
    ax = fig.subplots()
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.axvline(0.0, color="0.85", lw=0.8)
    limits: list[float] = []
    qs = None if q is None else np.asarray(q, dtype=float).ravel()
    for k, seg in enumerate(segs):
        x = physical_range(seg, num) if qs is None else qs
        y = seg.torque(x)
        lab = labels[k] if labels is not None else (segment_label(seg, segs) if len(segs) > 1 else "")
        lab = (f"{lab} ({stiffness_text(seg)})" if lab else stiffness_text(seg))
        line, = ax.plot(x, y, lw=1.6, label=lab)
        line.set_gid(f"torque-{k}")
        qz, stable = torque_zeros(x, y)
        for flag, gid_ in ((True, "stable"), (False, "unstable")):
            sel = stable == flag
            # unstable: a larger open ring on top, visible around the stable dots of other curves at q = 0
            pts, = ax.plot(qz[sel], np.zeros(int(sel.sum())), ls="none", marker="o", ms=6.0 if flag else 10.0,
                           zorder=5 if flag else 6, color=line.get_color(),
                           mfc=line.get_color() if flag else "none", mec=line.get_color(), mew=1.6)
            pts.set_gid(f"torque-{k}-{gid_}")
        lim = seg.joint_limit
        if not any(abs(lim - l) < 1e-12 for l in limits):
            limits.append(lim)
            for sgn in (-1, 1):
                ax.axvline(sgn * lim, color=line.get_color(), ls=":", lw=1.0)
    ax.set_xlabel("joint angle $q$ (rad)")
    ax.set_ylabel(f"spring torque $M(q) = -dE/dq$ ({ENERGY_UNIT})")
    ax.grid(True, lw=0.4, alpha=0.5)
    handles, labs = ax.get_legend_handles_labels()
    from matplotlib.lines import Line2D

    handles += [Line2D([], [], ls="none", marker="o", ms=6.0, mfc="0.3", mec="0.3"),
                Line2D([], [], ls="none", marker="o", ms=9.0, mfc="none", mec="0.3", mew=1.6)]
    labs += ["equilibrium of the unloaded segment, stable ($M$ falls through 0)", "equilibrium, unstable ($M$ rises)"]
    handles.append(_dotted_handle())
    labs.append("physical range $|q| < \\pi - 2\\beta$ (dotted)")
    fig.legend(handles, labs, fontsize=7, loc="outside lower center", ncols=1 if len(handles) > 3 else 2,
               frameon=False)
    common = _common_label(segs)
    ax.set_title("Torque-angle curves of a segment (Fig. 2)" + (f"\n{common}" if common else ""), fontsize=9)
    return fig


def _dotted_handle() -> Any:
    from matplotlib.lines import Line2D

    return Line2D([], [], color="0.4", ls=":", lw=1.0)


