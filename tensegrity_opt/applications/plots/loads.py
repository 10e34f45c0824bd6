"""Figures of a chain under its weight: its sagged shape as its base turns, and the least design holding it."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ...analyses.design.holding import HoldingMap
from ...model.manipulator import Manipulator
from .geometry import chain_geometry
from .style import chain_label, new_figure

__all__ = ["plot_holding", "elevations"]


def elevations(hmap: HoldingMap) -> np.ndarray:
    """The chain's base direction above the horizontal (deg) of each orientation of ``hmap``, gravity pointing
    down: ``90`` pointing up, ``0`` held out sideways, ``-90`` hanging down."""
    e = np.degrees(-np.pi / 2 - hmap.angles)
    return (e + 180.0) % 360.0 - 180.0


def plot_holding(hmap: HoldingMap, m: Manipulator, *, figsize: tuple[float, float] = (11.0, 5.0)) -> Any:
    """The result of :func:`~tensegrity_opt.analyses.design.holding.holding_map` of the chain ``m`` (its geometry
    draws the shapes): left, the chain resting under its
    weight in each orientation, drawn with gravity pointing down (its base turned; colour by the base's elevation,
    the tip a dot; a joint resting on its stop at the range's end); right, the least total stiffness (``vary k``)
    or preload tension (``vary L0``) of :func:`~tensegrity_opt.preloads_for_holding` against the base's elevation
    (log scale; a cross where no design holds it, an open marker where the design is only metastable), with the
    rest configuration's sag on a second axis.

    Artists (``gid``): ``"sag-<i>"`` (the chain of orientation ``i``), ``"tips"``, ``"design"``, ``"infeasible"``,
    ``"metastable"``, ``"sag"``; the axes ``"shapes"`` and ``"holding"``.
    """
    import matplotlib

    fig = new_figure(figsize)
    ax, bx = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1.0, 1.2]})
    ax.set_gid("shapes")
    bx.set_gid("holding")
    el = elevations(hmap)
    cmap = matplotlib.colormaps["twilight_shifted"]
    tips = []
    for i, (angle, q) in enumerate(zip(hmap.angles, hmap.q)):
        if not np.all(np.isfinite(q)):
            continue
        rot = -np.pi / 2 - angle                        # turn the base so that gravity points down
        c, s = math.cos(rot), math.sin(rot)
        R = np.array([[c, -s], [s, c]])
        line = chain_geometry(m, q)["centerline"] @ R.T
        col = cmap((el[i] + 180.0) / 360.0)
        ln, = ax.plot(line[:, 0], line[:, 1], color=col, lw=1.6, marker="o", ms=2.5)
        ln.set_gid(f"sag-{i}")
        tips.append(line[-1])
    if tips:
        tp = np.array(tips)
        sc = ax.scatter(tp[:, 0], tp[:, 1], s=14, color="black", zorder=4)
        sc.set_gid("tips")
    ax.plot([0.0], [0.0], marker="s", color="0.3", ms=7)
    ax.annotate("$g$", xy=(0.06, 0.08), xytext=(0.06, 0.22), xycoords="axes fraction", textcoords="axes fraction",
                ha="center", fontsize=9, arrowprops={"arrowstyle": "->", "color": "0.3"})
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("$x$ (length), gravity down", fontsize=9)
    ax.set_ylabel("$y$ (length)", fontsize=9)
    ax.set_title("sagged shape as the base turns", fontsize=9)
    value = hmap.stiffness if hmap.vary == "k" else hmap.tension
    order = np.argsort(el)
    ok = np.array([o in ("optimal", "metastable") for o in hmap.outcomes])
    y = np.where(ok & np.isfinite(value) & (value > 0), value, np.nan)
    ln, = bx.plot(el[order], y[order], color="tab:blue", marker="o", ms=4,
                  label="least total stiffness" if hmap.vary == "k" else "least preload tension")
    ln.set_gid("design")
    meta = np.array([o == "metastable" for o in hmap.outcomes])
    if meta.any():
        mk, = bx.plot(el[meta], y[meta], ls="none", marker="o", mfc="white", mec="tab:blue", ms=7,
                      label="metastable")
        mk.set_gid("metastable")
    bad = np.array([o == "infeasible" for o in hmap.outcomes])
    if np.any(np.isfinite(y)):
        bx.set_yscale("log")
    if bad.any():
        base = np.nanmin(y) if np.any(np.isfinite(y)) else 1.0
        xs, = bx.plot(el[bad], np.full(int(bad.sum()), base), ls="none", marker="x", color="tab:red", ms=8,
                      label="no design holds it")
        xs.set_gid("infeasible")
    bx.set_xlabel("base elevation (deg): 90 up, 0 sideways, -90 down", fontsize=9)
    bx.set_ylabel("force / length" if hmap.vary == "k" else "force", fontsize=9)
    sx = bx.twinx()
    sg, = sx.plot(el[order], hmap.sag[order], color="tab:orange", ls="--", lw=1.2, label="sag without a design")
    sg.set_gid("sag")
    sx.set_ylabel("largest joint angle at rest (rad)", fontsize=9, color="tab:orange")
    handles = [h for h in (*bx.get_lines(), sg) if not h.get_label().startswith("_")]
    bx.legend(handles=handles, fontsize=7, loc="upper left")
    held = "within %.3g rad" % hmap.max_angle if hmap.max_angle is not None else "anywhere in range"
    bx.set_title(f"holding it {held}, margin {hmap.margin:g} ({hmap.status})", fontsize=9)
    fig.suptitle(f"The chain under its weight: {chain_label(m)}", fontsize=10)
    return fig
