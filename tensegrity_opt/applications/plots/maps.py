"""The critical-load map: the critical buckling load over two design parameters, the stable designs' edge
(condition 4) and the chain's own design marked."""

from __future__ import annotations

from typing import Any

import numpy as np

from ...errors import InvalidParameterError
from ...model.manipulator import Manipulator
from ..sweeps.critical_map import CriticalLoadMap
from .style import FORCE_UNIT, chain_label, contour_levels, new_figure

__all__ = ["plot_map", "PARAM_LABELS"]


#: Axis labels of the design parameters (:func:`plot_map`).
PARAM_LABELS = {"a": "triangle half-base $a$ (length)", "b": "triangle height $b$ (length)",
                "k": "spring stiffness $k$ (stiffness)", "L0": "spring rest length $L_0$ (length)"}


def plot_map(critical_map: CriticalLoadMap, m: Manipulator, *, levels: int = 8,
             figsize: tuple[float, float] = (6.8, 5.4)) -> Any:
    """The critical load ``P = -Fx0`` over two design parameters: a
    :class:`~tensegrity_opt.applications.sweeps.CriticalLoadMap`
    (:func:`~tensegrity_opt.applications.sweeps.critical_load_map`) of the chain ``m``.

    The map's two parameters (two of ``a``, ``b``, ``k``, ``L0``, the same value in every segment) are the axes;
    the designs without a critical load (the straight chain is unstable or not an equilibrium there) are blank.
    Contour lines at about ``levels`` evenly spaced round values (:class:`~matplotlib.ticker.MaxNLocator`),
    labelled; a colour bar with the quantity and unit; the other parameters in the title. The manipulator's own
    design is starred (and labelled "design") when it is uniform in both parameters; condition (4), ``K = 0``,
    is drawn from its formula when the segments are symmetric and alike apart from the two parameters.

    Artists (``gid``): ``"critical-load"`` (QuadMesh, array ``load[iy, ix]``), ``"critical-load-contours"``,
    ``"condition4"`` (the line ``K = 0``), ``"design"``.
    """
    if not isinstance(critical_map, CriticalLoadMap):
        raise InvalidParameterError(f"plot_map needs a CriticalLoadMap, got {type(critical_map).__name__}",
                                    field="critical_map")
    param_x, param_y, boundary = critical_map.param_x, critical_map.param_y, critical_map.boundary
    xs, ys, P = np.asarray(critical_map.values_x), np.asarray(critical_map.values_y), np.asarray(critical_map.load)
    import matplotlib

    cmap = matplotlib.colormaps["viridis"].with_extremes(bad=(1.0, 1.0, 1.0, 0.0))
    fig = new_figure(figsize)
    ax = fig.subplots()
    Pm = np.ma.masked_invalid(P)
    mesh = ax.pcolormesh(xs, ys, Pm, shading="nearest", cmap=cmap)
    mesh.set_gid("critical-load")
    lv = contour_levels(P, levels)
    if Pm.count() >= 4 and xs.size >= 2 and ys.size >= 2 and lv.size >= 2:
        cs = ax.contour(xs, ys, Pm, levels=lv, colors="white", linewidths=0.6)
        cs.set_gid("critical-load-contours")
        ax.clabel(cs, fontsize=7, fmt="%.3g")
    fig.colorbar(mesh, ax=ax, label=f"critical load $P = -F_{{x0}}$ ({FORCE_UNIT}), {boundary} tip")
    # condition (4), K = k (b L0 - 2 (b^2 - a^2)) = 0, from the formula on a fine grid: the exact edge of the
    # stable designs (symmetric segments all alike apart from the two parameters)
    seg0 = m.segments[0]
    alike = all(s.replace(**{param_x: getattr(seg0, param_x), param_y: getattr(seg0, param_y)}) == seg0
                for s in m.segments)
    if alike and seg0.symmetric:
        fx_ = np.linspace(float(xs.min()), float(xs.max()), 201)
        fy_ = np.linspace(float(ys.min()), float(ys.max()), 201)
        FX, FY = np.meshgrid(fx_, fy_)
        par = {p: np.full(FX.shape, float(getattr(seg0, p))) for p in ("a", "b", "L0")}
        for p, V in ((param_x, FX), (param_y, FY)):
            if p in par:
                par[p] = V
        K4 = par["b"] * par["L0"] - 2.0 * (par["b"] ** 2 - par["a"] ** 2)
        if K4.min() < 0.0 < K4.max():
            c4 = ax.contour(fx_, fy_, K4, levels=[0.0], colors="black", linewidths=1.2, linestyles="--")
            c4.set_gid("condition4")
            from matplotlib.lines import Line2D

            ax.legend([Line2D([], [], color="black", lw=1.2, ls="--")],
                      ["$K = 0$: $b L_0 = 2(b^2 - a^2)$ (condition 4)"], fontsize=7, loc="upper center",
                      bbox_to_anchor=(0.5, -0.12), frameon=False)
    base_x = {getattr(s, param_x) for s in m.segments}
    base_y = {getattr(s, param_y) for s in m.segments}
    if len(base_x) == 1 and len(base_y) == 1:
        bx, by = next(iter(base_x)), next(iter(base_y))
        if not isinstance(bx, tuple) and not isinstance(by, tuple):
            star, = ax.plot([bx], [by], marker="*", ms=12, color="white", mec="black", ls="none")
            star.set_gid("design")
            ax.annotate("design", (bx, by), textcoords="offset points", xytext=(7, 5), fontsize=7,
                        bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "none", "alpha": 0.8})
    ax.set_xlabel(PARAM_LABELS[param_x])
    ax.set_ylabel(PARAM_LABELS[param_y])
    blank = critical_map.blank
    fixed = chain_label(m, exclude=(param_x, param_y))
    ax.set_title(f"Critical buckling load over {param_x} and {param_y}; {fixed}"
                 + (f"\nblank: {blank} designs where the straight chain is not a stable equilibrium" if blank else ""),
                 fontsize=9)
    return fig


