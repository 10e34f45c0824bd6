"""Figures (matplotlib, Agg canvas): curves, landscapes, shapes, torque curves, critical-load maps, the
loading paths (branch diagrams, limit loads, stability boundaries), the workspace stability atlas, and the
control layer (rest-length plans, simulations).

Every ``plot_*`` function computes its data with the library and returns a
:class:`matplotlib.figure.Figure` on an Agg canvas; :func:`save` writes it as PNG or SVG
(from the file suffix) and :func:`render` returns the bytes. Matplotlib is imported
lazily: ``import tensegrity_opt`` (and even ``import tensegrity_opt.applications.plots`` with
:func:`chain_geometry`) works without it. No function touches ``pyplot`` or the global
``rcParams``, so figures may be drawn from several threads at once (one figure per thread).

========================  ===================================================================
function                  figure
========================  ===================================================================
:func:`plot_curve`        ``Fx`` above ``Fy`` against the deflection (Fig. 6) with the jumps of
                          :func:`~tensegrity_opt.force_deflection` by kind, a partial curve's end;
                          ``branch="all"``: every branch, unstable parts dashed
:func:`plot_landscape`    energy contours (even levels) of :func:`~tensegrity_opt.energy_landscape` on both
                          elbow branches, cut at the exact edge of the reachable set, every equilibrium of
                          :func:`~tensegrity_opt.find_equilibria` marked and labelled (Figs. 4-5, n = 4)
:func:`plot_shapes`       the chain in each equilibrium: triangles, joints, both springs, coloured
                          by stability, titled with Table 2's label
:func:`plot_torque`       torque-angle curves ``M(q)`` of segments over the physical range (Fig. 2), their
                          equilibria marked, ``K`` and the curve's kind in the legend
:func:`plot_map`          critical load ``P = -Fx0`` over two design parameters (blank where
                          :func:`~tensegrity_opt.critical_force` raises)
:func:`plot_branches`     branch diagrams of :func:`~tensegrity_opt.trace_branch` /
                          :func:`~tensegrity_opt.bifurcation_diagram`: pieces coloured by Morse index
                          (stable solid, unstable dashed), folds / branch points / joint limits marked
:func:`plot_limit_load`   the load path of :func:`~tensegrity_opt.limit_load` (load against the tip
                          displacement along it), the limit point and the quasi-buckling load marked
:func:`plot_boundary`     a stability boundary (critical ``t`` against the second parameter ``p``),
                          cusps marked
:func:`plot_atlas`        the stability atlas of :func:`~tensegrity_opt.stability_atlas`: the number of
                          stable equilibria over ``(dx, dy)`` (discrete colours), the switch and
                          branch-end curves with their crossings
:func:`plot_preload_plan` a rest-length plan of :func:`~tensegrity_opt.preloads_for_trajectory`: the rest lengths of
                          every spring and the margin per step, the tip path with the targets,
                          infeasible steps shaded
:func:`plot_simulation`   the hysteresis loop of :func:`~tensegrity_opt.simulate`: the driving input
                          against the tip's response, each snap an arrow from its fold to its landing
========================  ===================================================================

Every figure is drawn in the caller's units (the model has none of its own: lengths in the unit of
``a``, ``b``, ``L0``, the paper's ``b = 1``; forces ``stiffness x length``, energies and torques
``stiffness x length^2``, angles in rad), and every axis says its quantity and unit; every figure puts
the chain's parameters in its title (:func:`chain_label`; a chain whose segments differ is
"heterogeneous, n = ..." with ranges) and its legend outside the axes (a figure legend beside or
below them: it never covers the data). Contour levels are evenly spaced round values.

The plotted data are the library's numbers, unchanged. Artists carry stable ``gid`` values so
that they can be found again (tests read the data back from them):

* curve: ``"fx"``, ``"fy"`` (the selected least-energy stable curve, NaN-separated at every
  jump), ``"jump-<k>-<kind>-fx"`` / ``"-fy"`` (the ``k``-th entry of ``Curve.jumps``, ``kind`` as
  :func:`jump_kind`; a buckling jump is the vertical segment at the abscissa 0 from 0 to the critical
  force), ``"jump-<k>-number-fx"`` (its number), a partial curve's ``"end-marker-fx"`` / ``"-fy"`` (its last
  point), ``"curve-end-fx"`` / ``"-fy"`` (the vertical at ``ended_at``), ``"curve-end-text"``,
  ``"branch-<id>-fx-stable"`` / ``"-unstable"`` (``branch="all"``; NaN where the branch does not
  exist or has the other stability);
* landscape: ``"energy-elbow+1"`` / ``"energy-elbow-1"`` (QuadMesh, array = ``energy[e].T``, not drawn),
  ``"energy-fill-elbow..."`` (filled contours, clipped to the region), ``"contour-elbow..."`` (contour lines),
  ``"boundary-elbow..."`` (the region's outline), ``"equilibria-elbow..."`` (scatter of ``(q_i, q_j)``);
* shapes: per panel ``"triangle-<i>-<0|1>"`` (proximal/distal triangle of segment ``i``),
  ``"spring-<i>-<1|2>"``, ``"joints"`` (scatter), ``"centerline"``, ``"tip"``;
  the axes' gid is ``"equilibrium-<k>"``;
* torque: ``"torque-<k>"``; map: ``"critical-load"`` (QuadMesh, array ``P[iy, ix]``), ``"critical-load-contours"``,
  ``"condition4"`` (the line ``K = 0``), ``"design"``;
* branches: ``"branch-<b>-morse<k>-<j>"`` (branch ``b``'s ``j``-th piece, of Morse index ``k``),
  ``"events-fold"``, ``"events-branch_point"``, ``"events-joint_limit"``; limit load:
  ``"path-morse<k>-<j>"``, ``"limit-point"``, ``"quasi-buckling"``, ``"quasi-buckling-level"``,
  ``"path-end"``; boundary: ``"boundary"``, ``"cusps"``;
* atlas: ``"n_stable"`` (QuadMesh, masked ``n_stable[j, i]``), ``"unreachable"``, ``"failed"`` (cells),
  ``"switch"``, ``"branch_end"`` (line collections of the curves), ``"switch-points"``,
  ``"branch_end-points"`` (the crossings);
* preload plan: ``"rest-length-<i>-<1|2>"``, ``"margin"``, ``"margin-required"``, ``"unverified"``,
  ``"infeasible-rest"``, ``"infeasible-margin"``, ``"targets"``, ``"tip-path"``, ``"infeasible-tips"``;
* simulation: ``"path"``, ``"samples"``, ``"start"``, ``"end"``, ``"snap-<j>"`` (arrows), ``"snap-folds"``,
  ``"snap-landings"``, ``"joint-limit"``.
"""

from __future__ import annotations

import math
import threading
from collections import Counter
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from ..analyses.equilibria.all_equilibria import find_equilibria
from ..analyses.equilibria.buckling import critical_force
from ..analyses.paths.curves import Curve, force_deflection
from ..analyses.equilibria.equilibrium import Equilibrium
from ..analyses.equilibria.landscape import complete_configuration, energy_landscape
from ..errors import InvalidParameterError, TensegrityError
from ..model.manipulator import Manipulator
from ..model.segment import Segment

__all__ = ["chain_geometry", "plot_curve", "plot_landscape", "plot_shapes", "plot_torque", "plot_map", "save",
           "render", "landscape_span", "critical_load_grid", "curve_breaks", "physical_range",
           "segment_label", "FORMATS", "STABILITY_COLORS", "MAP_PARAMS", "plot_branches", "plot_limit_load",
           "plot_boundary", "chain_label", "branch_quantity_label", "morse_color", "BRANCH_QUANTITIES",
           "MORSE_COLORS", "EVENT_STYLES", "plot_atlas", "ATLAS_STYLES", "plot_preload_plan", "plot_simulation",
           "CONTROL_STYLES", "jump_kind", "jump_label", "JUMP_STYLES", "landscape_region", "stiffness_text", "torque_zeros",
           "PARAM_LABELS", "FORCE_UNIT", "ENERGY_UNIT"]

#: File suffix / format name -> MIME type.
FORMATS = {"png": "image/png", "svg": "image/svg+xml"}

#: Colour of an equilibrium by its ``kind``.
STABILITY_COLORS = {"minimum": "tab:green", "saddle": "tab:orange", "maximum": "tab:red",
                    "degenerate": "tab:gray"}

#: Design parameters :func:`plot_map` can vary (applied to every segment with ``Segment.replace``).
MAP_PARAMS = ("a", "b", "k", "L0")

#: Axis label units. The model has no units of its own: lengths are in the unit the caller gives ``a``, ``b``,
#: ``L0`` in (the paper: ``b = 1``), stiffnesses in that of ``k``; forces are then stiffness x length, energies
#: and torques stiffness x length^2, angles rad.
FORCE_UNIT = "stiffness × length"
ENERGY_UNIT = "stiffness × length²"

_KIND_TEXT = {"minimum": "stable", "saddle": "saddle", "maximum": "maximum", "degenerate": "degenerate"}


# ---------------------------------------------------------------------------- matplotlib plumbing
def _new_figure(figsize: tuple[float, float]) -> Any:
    """A Figure on its own Agg canvas (no pyplot, no global state)."""
    try:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise ImportError("tensegrity_opt.applications.plots needs matplotlib: python3 -m pip install matplotlib") from exc
    fig = Figure(figsize=figsize, layout="constrained")
    FigureCanvasAgg(fig)
    return fig


def _format_of(path: str | Path) -> str:
    fmt = Path(path).suffix.lower().lstrip(".")
    if fmt not in FORMATS:
        raise InvalidParameterError(f"the figure file must end in .png or .svg, got {str(path)!r}", field="path")
    return fmt


def _savefig_kwargs(fmt: str, dpi: float | None) -> dict[str, Any]:
    kw: dict[str, Any] = {"format": fmt}
    if dpi is not None:
        kw["dpi"] = float(dpi)
    if fmt == "svg":
        kw["metadata"] = {"Date": None}          # reproducible files
    return kw


#: ``svg.hashsalt`` while an SVG is written: matplotlib otherwise salts the ids of clip paths and
#: markers with a random UUID, so the same figure gave different bytes every time.
SVG_HASHSALT = "tensegrity-opt"
_SVG_LOCK = threading.Lock()     # rcParams are process-wide: one SVG save at a time under the salt


def _savefig(fig: Any, target: Any, fmt: str, dpi: float | None) -> None:
    """``fig.savefig`` with reproducible bytes: SVG under a fixed hash salt and no date (PNG is already)."""
    if fmt != "svg":
        fig.savefig(target, **_savefig_kwargs(fmt, dpi))
        return
    import matplotlib

    with _SVG_LOCK, matplotlib.rc_context({"svg.hashsalt": SVG_HASHSALT}):
        fig.savefig(target, **_savefig_kwargs(fmt, dpi))


def save(fig: Any, path: str | Path, *, dpi: float | None = None) -> Path:
    """Write ``fig`` to ``path`` as PNG or SVG, chosen by the suffix (``.png`` / ``.svg``).

    Raises :class:`InvalidParameterError` (``field="path"``) for any other suffix.
    """
    path = Path(path)
    fmt = _format_of(path)
    _savefig(fig, path, fmt, dpi)
    return path


def render(fig: Any, fmt: str = "png", *, dpi: float | None = None) -> bytes:
    """The bytes of ``fig`` as ``"png"`` or ``"svg"``."""
    import io

    if fmt not in FORMATS:
        raise InvalidParameterError(f"format must be 'png' or 'svg', got {fmt!r}", field="format")
    buf = io.BytesIO()
    _savefig(fig, buf, fmt, dpi)
    return buf.getvalue()


# ---------------------------------------------------------------------------- geometry
def chain_geometry(m: Manipulator, q: Any) -> dict[str, np.ndarray]:
    """Drawing geometry of the chain at the joint angles ``q`` (conventions.md).

    The base half-link of length ``b_1`` runs from the origin along +x to joint 1; the link
    after joint ``j`` has the absolute angle ``phi_j = q_1 + ... + q_j`` and length
    ``b_j + b_{j+1}`` (the last one ``b_n``). Segment ``i`` has its joint at ``joints[i]``, a
    proximal triangle on the link before the joint and a distal one on the link after it: apex
    at the joint, base perpendicular to the link at distance ``b_i`` from the joint, base
    corners ``a_i`` either side. Spring 1 joins the two corners on the left (+ normal) side,
    spring 2 those on the right side, so that ``|spring 1| = 2c cos(beta + q/2)`` and
    ``|spring 2| = 2c cos(beta - q/2)`` (:meth:`Manipulator.spring_lengths`).

    Returns
    -------
    dict of ndarray
        ``"base"`` (2,) the origin; ``"joints"`` (n, 2); ``"tip"`` (2,) = :meth:`Manipulator.tip`;
        ``"centerline"`` (n + 2, 2): origin, joints, tip; ``"link_angles"`` (n + 1,): ``phi_0 = 0``
        (base link) then ``phi_1..phi_n``; ``"triangles"`` (n, 2, 3, 2): segment, proximal/distal,
        vertices (joint, left corner, right corner); ``"springs"`` (n, 2, 2, 2): segment, spring
        1/2, endpoints (proximal corner, distal corner).
    """
    q = np.asarray(q, dtype=float)
    if q.shape != (m.n,):
        raise InvalidParameterError(f"q must have {m.n} joint angles, got shape {q.shape}", field="q")
    a, b = m.a, m.b
    phi = np.concatenate([[0.0], np.cumsum(q)])
    u = np.column_stack([np.cos(phi), np.sin(phi)])            # link directions (n + 1, 2)
    nrm = np.column_stack([-np.sin(phi), np.cos(phi)])         # left normals
    links = m.link_lengths
    joints = np.empty((m.n, 2))
    joints[0] = (m.base_length, 0.0)
    for j in range(1, m.n):
        joints[j] = joints[j - 1] + links[j - 1] * u[j]
    tip = joints[-1] + links[-1] * u[m.n]
    A, B = a[:, None], b[:, None]
    prox_l = joints - B * u[:-1] + A * nrm[:-1]
    prox_r = joints - B * u[:-1] - A * nrm[:-1]
    dist_l = joints + B * u[1:] + A * nrm[1:]
    dist_r = joints + B * u[1:] - A * nrm[1:]
    triangles = np.stack([np.stack([joints, prox_l, prox_r], axis=1),
                          np.stack([joints, dist_l, dist_r], axis=1)], axis=1)
    springs = np.stack([np.stack([prox_l, dist_l], axis=1), np.stack([prox_r, dist_r], axis=1)], axis=1)
    centerline = np.vstack([[0.0, 0.0], joints, tip])
    return {"base": np.zeros(2), "joints": joints, "tip": tip, "centerline": centerline, "link_angles": phi,
            "triangles": triangles, "springs": springs}


# ---------------------------------------------------------------------------- force-deflection
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
    matching :class:`~tensegrity_opt.Jump` changes that component (a change without a recorded
    jump also breaks). ``Fy`` stays continuous through the buckling jump (it is 0 on both sides)."""
    out = []
    for j in np.flatnonzero(c.branch[1:] != c.branch[:-1]) + 1:
        jump = next((jp for jp in c.jumps if jp.dx_before == c.dx[j - 1] and jp.dx_after == c.dx[j]
                     and jp.dy_before == c.dy[j - 1] and jp.dy_after == c.dy[j]), None)
        if jump is None or jump.force_before[component] != jump.force_after[component]:
            out.append(int(j))
    return np.array(out, dtype=int)


#: How :func:`plot_curve` draws each kind of jump (``Jump.kind``; the old ``"branch_switch"`` is drawn as a snap).
JUMP_STYLES = {
    "buckling": {"color": "tab:red", "ls": "--", "marker": None, "name": "buckling of the straight chain"},
    "leave_straight": {"color": "tab:orange", "ls": "--", "marker": None, "name": "leaves the straight chain"},
    "snap": {"color": "tab:red", "ls": ":", "marker": "D", "name": "snap: the stable branch ends"},
    "switch": {"color": "tab:purple", "ls": ":", "marker": "s", "name": "switch of the least-energy branch"},
}
#: Jumps listed one by one in the legend of :func:`plot_curve` (the others are counted).
_MAX_JUMP_LEGEND = 6


def jump_kind(j: Any) -> str:
    """The kind :func:`plot_curve` draws a jump as: ``Jump.kind``, with the library's former ``"branch_switch"``
    as ``"snap"``, and a ``"buckling"`` whose force after the jump is not compressive (``F_x >= 0``) as
    ``"leave_straight"``: a tensile jump is never called buckling."""
    kind = str(j.kind)
    if kind == "branch_switch":
        return "snap"
    if kind == "buckling" and not float(j.force_after[0]) < 0.0:
        return "leave_straight"
    return kind if kind in JUMP_STYLES else "snap"


def _sense(fx: float) -> str:
    return "tensile" if fx > 0 else ("compressive" if fx < 0 else "zero")


def jump_label(j: Any) -> str:
    """``Jump.label`` when the library gives one, else a sentence of the same form naming the jump with its
    sign and size, e.g. ``"buckling of the straight chain: F_x 0 -> -0.573 (compressive)"``."""
    kind = jump_kind(j)
    try:
        label = getattr(j, "label", None) if j.kind in JUMP_STYLES else None   # not for the former kind
    except (KeyError, ValueError, TypeError):
        label = None
    if isinstance(label, str) and label and not (kind != "buckling" and label.startswith("buckling")):
        return label
    f0, f1 = float(j.force_before[0]), float(j.force_after[0])
    g0, g1 = float(j.force_before[1]), float(j.force_after[1])
    if kind in ("buckling", "leave_straight"):
        what = JUMP_STYLES[kind]["name"]
        return f"{what}: F_x {_num(f0, f1)} -> {_num(f1, f0)} ({_sense(f1)})"
    d = f1 - f0 if f1 != f0 else g1 - g0
    comp = "x" if f1 != f0 else "y"
    what = "snap to another stable branch" if kind == "snap" else "switch of the least-energy stable branch"
    return f"{what}: dF_{comp} = {d:+.3g}" + (f" ({_sense(f1)})" if comp == "x" else "")


def _num(v: float, other: float = 0.0, digits: int = 3) -> str:
    """``v`` in a label: ``"0"`` when it is zero to rounding relative to the scale ``max(|v|, |other|)``."""
    scale = max(abs(v), abs(other))
    if v == 0.0 or abs(v) <= 1e-9 * scale:
        return "0"
    return f"{v:.{digits}g}"


def _curve_end(c: Curve, xname: str) -> tuple[float, str] | None:
    """Where a partial curve (``Curve.ended_at``, the curves contract) ends on the abscissa, and why."""
    end = c.ended_at
    if end is None:
        return None
    return float(end.dx if xname == "dx" else end.dy), end.status


def plot_curve(m: Manipulator, dx: Any, dy: Any = 0.0, branch: str = "stable", *, curve: Curve | None = None,
               figsize: tuple[float, float] = (8.0, 7.0)) -> Any:
    """Force-deflection curves ``Fx`` and ``Fy`` (Fig. 6) from :func:`~tensegrity_opt.force_deflection`.

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
    ``branch="all"`` also draws every branch followed (``Curve.branches``): solid where stable, dashed where
    unstable. The axes are in the caller's units (lengths, forces ``stiffness x length``); the title gives
    the chain's parameters.

    Parameters
    ----------
    m : Manipulator
    dx, dy, branch
        As :func:`~tensegrity_opt.force_deflection`.
    curve : Curve, optional
        A curve already computed (then ``dx``, ``dy``, ``branch`` are ignored).
    """
    c = curve if curve is not None else force_deflection(m, dx, dy, branch=branch)
    x, xname = _abscissa(c)
    from matplotlib.lines import Line2D

    fig = _new_figure(figsize)
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
    import textwrap

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


# ---------------------------------------------------------------------------- landscape
def _elbow_of(m: Manipulator, target: np.ndarray, pair: tuple[int, int], q: np.ndarray) -> int:
    """Index (0: elbow +1, 1: elbow -1) of the landscape branch through ``q``."""
    errs = []
    for elbow in (1, -1):
        full = complete_configuration(m, target, pair, q[pair[0]], q[pair[1]], elbow)
        err = float(np.max(np.abs(full - q)))
        errs.append(err if math.isfinite(err) else math.inf)
    return int(np.argmin(errs))


def landscape_span(m: Manipulator, dx: float, dy: float = 0.0, pair: tuple[int, int] = (0, 3),
                   probe: int = 201) -> float:
    """Half-width of the square ``[-s, s]^2`` holding every finite point of the landscape.

    A ``probe`` x ``probe`` landscape over the default axes (the physical range) locates the
    reachable region; the answer adds two probe cells and never exceeds the default span.
    For small deflections the region is a small patch around the origin, so plotting over it
    instead of the whole physical range resolves the equilibria.
    """
    full = energy_landscape(m, dx, dy, pair=pair, grid=probe)
    finite = np.isfinite(full.energy).any(axis=0)
    default = float(np.max(np.abs(full.qi)))
    if not finite.any():
        return default
    cell = 2.0 * default / (probe - 1)
    ext = max(float(np.max(np.abs(full.qi[finite.any(axis=1)]))), float(np.max(np.abs(full.qj[finite.any(axis=0)]))))
    return float(min(default, ext + 2.0 * cell))


def _levels(values: np.ndarray, num: int) -> np.ndarray:
    """About ``num`` evenly spaced contour levels at round values over the finite ``values``
    (:class:`matplotlib.ticker.MaxNLocator`), kept within their range."""
    from matplotlib.ticker import MaxNLocator

    finite = values[np.isfinite(values)]
    if finite.size == 0:
        return np.array([])
    lo, hi = float(finite.min()), float(finite.max())
    if not hi > lo:
        return np.array([lo])
    lv = MaxNLocator(nbins=max(int(num), 2), steps=[1, 2, 2.5, 5, 10]).tick_values(lo, hi)
    step = float(lv[1] - lv[0])
    lv = lv[(lv >= lo - 1e-9 * step) & (lv <= hi + 1e-9 * step)]
    # whole multiples of the step (no rounding noise: np.diff is constant)
    return np.round(lv / step) * step


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

    from ..analyses.equilibria.landscape import landscape_margin

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


def plot_landscape(m: Manipulator, dx: float, dy: float = 0.0, pair: tuple[int, int] = (0, 3),
                   grid: Any = 101, *, span: float | str | None = "auto",
                   equilibria: list[Equilibrium] | None = None, levels: int = 24,
                   figsize: tuple[float, float] = (10.6, 5.0)) -> Any:
    """Energy landscape ``E(q_i, q_j)`` (Figs. 4-5, n = 4) with every equilibrium marked.

    One panel per elbow branch of :func:`~tensegrity_opt.energy_landscape`: the energy (the other two joints
    solved for the tip target) as filled contours at evenly spaced levels (:class:`~matplotlib.ticker.MaxNLocator`,
    about ``levels`` of them) with contour lines, a colour bar with the quantity and unit. The drawn region
    is the reachable set inside the physical range, cut at its exact boundary (:func:`landscape_region`: the
    zero contour of a continuous margin, drawn as a black line), not at the grid's cells. Every equilibrium
    of :func:`~tensegrity_opt.find_equilibria` (or ``equilibria``) is marked at its ``(q_i, q_j)`` on the
    branch it lies on, coloured by stability and labelled with its shape; each lies inside the drawn region
    (an equilibrium is reachable and in range). The legend sits below the panels; the title gives the
    chain's parameters, the deflection and the count.

    ``grid``, ``span`` go to :func:`~tensegrity_opt.energy_landscape`; ``span="auto"`` (default)
    uses :func:`landscape_span` (the reachable region), ``None`` the library's default (the
    physical range).

    Artists (``gid``): ``"energy-elbow+1"`` / ``"-1"`` (the grid's values, a QuadMesh with the array
    ``energy[e].T``, not drawn: the filled contours show them), ``"energy-fill-elbow..."`` (filled contour set,
    clipped to the region), ``"contour-elbow..."`` (contour lines), ``"boundary-elbow..."`` (the region's
    outline, a PathPatch whose path is :func:`landscape_region`), ``"equilibria-elbow..."`` (scatter).

    Raises
    ------
    UnsupportedError
        (``ValueError``) unless ``m.n == 4``; ``UnreachableTargetError`` beyond reach.
    """
    if isinstance(span, str):
        if span != "auto":
            raise InvalidParameterError(f"span must be a number, None or 'auto', got {span!r}", field="span")
        span = landscape_span(m, dx, dy, pair) if isinstance(grid, (int, np.integer)) else None
    land = energy_landscape(m, dx, dy, pair=pair, grid=grid, span=span)
    eqs = find_equilibria(m, dx, dy) if equilibria is None else list(equilibria)
    pair = land.pair
    target = m.target(dx, dy)
    import matplotlib
    from matplotlib.lines import Line2D
    from matplotlib.patches import PathPatch
    from matplotlib.ticker import MaxNLocator

    from ..analyses.equilibria.landscape import landscape_margin

    cmap = matplotlib.colormaps["viridis"].with_extremes(bad=(1.0, 1.0, 1.0, 0.0))
    lv = _levels(land.energy, levels)
    fig = _new_figure(figsize)
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
def plot_shapes(m: Manipulator, dx: float, dy: float = 0.0, *, equilibria: list[Equilibrium] | None = None,
                max_panels: int = 24, ncols: int | None = None, panel_width: float = 3.8) -> Any:
    """The chain in every equilibrium of :func:`~tensegrity_opt.find_equilibria`, one panel each.

    Each panel draws, for every segment, both triangles (polygons), the joint (dot) and both
    springs (lines between the triangles' base corners), coloured by stability (stable green,
    saddle orange, maximum red), with the link centre line and the tip; the title is Table 2's
    shape label, the kind, the energy and the tip force. At most ``max_panels`` equilibria (the
    lowest energies) are drawn.
    """
    eqs = find_equilibria(m, dx, dy) if equilibria is None else list(equilibria)
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
    fig = _new_figure((width * cols, (width * aspect + 0.9) * rows + 0.4))
    axes = np.atleast_1d(fig.subplots(rows, cols, squeeze=False)).ravel()
    from matplotlib.patches import Polygon

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
                line, = ax.plot(p[:, 0], p[:, 1], color=col, lw=1.4, ls="-" if s == 0 else "--", zorder=3)
                line.set_gid(f"spring-{i}-{s + 1}")
        sc = ax.scatter(g["joints"][:, 0], g["joints"][:, 1], s=14, color="black", zorder=4)
        sc.set_gid("joints")
        line, = ax.plot([g["tip"][0]], [g["tip"][1]], marker="x", color="black", ms=6, zorder=5)
        line.set_gid("tip")
        ax.set_title(f"{e.shape} ({e.signs}): {_KIND_TEXT.get(e.kind, e.kind)}\n"
                     f"E = {e.energy:.4g}, F = ({_num(e.fx, e.fy)}, {_num(e.fy, e.fx)})", fontsize=8, color=col)
        ax.set_xlim(lo[0], hi[0])
        ax.set_ylim(lo[1], hi[1])
        ax.set_aspect("equal", adjustable="box")
        ax.tick_params(labelsize=7)
        if idx % cols == 0:
            ax.set_ylabel("$y$ (length)", fontsize=8)
        if idx + cols >= k:
            ax.set_xlabel("$x$ (length)", fontsize=8)
    for ax in axes[k:]:
        ax.set_visible(False)
    more = f" (the {k} lowest of {len(eqs)})" if len(eqs) > k else ""
    fig.suptitle(f"Equilibria with the tip held at $\\delta_x$ = {dx:g}, $\\delta_y$ = {dy:g}: {len(eqs)}{more}\n"
                 f"{chain_label(m)}; spring 1 solid, spring 2 dashed; energy $E$ in {ENERGY_UNIT}, "
                 f"tip force $F$ in {FORCE_UNIT}", fontsize=9)
    return fig


# ---------------------------------------------------------------------------- torque
def _segments(segments: Segment | Manipulator | Iterable[Segment]) -> list[Segment]:
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


def _fmt(v: float | tuple[float, float]) -> str:
    return f"{v:g}" if not isinstance(v, tuple) else f"({v[0]:g}, {v[1]:g})"


def segment_label(seg: Segment, others: Sequence[Segment] = ()) -> str:
    """``"a=1, b=1, k=1, L0=1.2"``, restricted to the parameters that differ among ``others`` if any."""
    names = [p for p in MAP_PARAMS if len({getattr(s, p) for s in others}) > 1] or list(MAP_PARAMS)
    return ", ".join(f"{p}={_fmt(getattr(seg, p))}" for p in names)


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
    return ", ".join(f"{p} = {_fmt(getattr(segs[0], p))}" for p in same)


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
    segs = _segments(segments)
    if labels is not None and len(labels) != len(segs):
        raise InvalidParameterError(f"labels must have {len(segs)} entries", field="labels")
    fig = _new_figure(figsize)
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


# ---------------------------------------------------------------------------- critical-load map
def _axis_values(values: Any, field: str) -> np.ndarray:
    v = np.asarray(values, dtype=float).ravel()
    if v.size < 2:
        raise InvalidParameterError(f"{field} needs at least 2 values", field=field)
    if not np.all(np.isfinite(v)) or np.any(v <= 0.0):
        raise InvalidParameterError(f"{field} must be finite and > 0", field=field)
    d = np.diff(v)
    if not (np.all(d > 0) or np.all(d < 0)):
        raise InvalidParameterError(f"{field} must be strictly increasing or strictly decreasing", field=field)
    return v


def critical_load_grid(m: Manipulator, param_x: str, values_x: Any, param_y: str, values_y: Any,
                       boundary: str = "guided") -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(xs, ys, P)`` with ``P[iy, ix] = -critical_force(m').force``, ``m'`` = every segment with
    ``param_x = xs[ix]`` and ``param_y = ys[iy]``; NaN where ``critical_force`` raises for ``m'``
    (straight unstable, not an equilibrium, a failed eigen-solve)."""
    for f, p in (("param_x", param_x), ("param_y", param_y)):
        if p not in MAP_PARAMS:
            raise InvalidParameterError(f"{f} must be one of {', '.join(MAP_PARAMS)}, got {p!r}", field=f)
    if param_x == param_y:
        raise InvalidParameterError("param_x and param_y must differ", field="param_y")
    if boundary not in ("guided", "free"):
        raise InvalidParameterError(f"boundary must be 'guided' or 'free', got {boundary!r}", field="boundary")
    if boundary == "guided" and m.n < 2:
        raise InvalidParameterError("a guided tip needs n >= 2 segments", field="n")
    xs = _axis_values(values_x, "values_x")
    ys = _axis_values(values_y, "values_y")
    P = np.full((ys.size, xs.size), np.nan)
    for iy, y in enumerate(ys):
        for ix, x in enumerate(xs):
            mm = Manipulator([s.replace(**{param_x: float(x), param_y: float(y)}) for s in m.segments])
            try:
                P[iy, ix] = -critical_force(mm, boundary).force
            except (TensegrityError, ArithmeticError, np.linalg.LinAlgError):
                pass
    return xs, ys, P


#: Axis labels of the design parameters (:func:`plot_map`).
PARAM_LABELS = {"a": "triangle half-base $a$ (length)", "b": "triangle height $b$ (length)",
                "k": "spring stiffness $k$ (stiffness)", "L0": "spring rest length $L_0$ (length)"}


def plot_map(m: Manipulator, param_x: str, values_x: Any, param_y: str, values_y: Any, boundary: str = "guided",
             *, levels: int = 8, figsize: tuple[float, float] = (6.8, 5.4)) -> Any:
    """Critical load ``P = -Fx0`` of :func:`~tensegrity_opt.critical_force` over two design parameters.

    ``param_x``, ``param_y``: two of ``a``, ``b``, ``k``, ``L0``, set to the same value in every
    segment (``Segment.replace``; ``k``/``L0`` set both springs). Cells where ``critical_force``
    raises (the straight chain is unstable or not an equilibrium) are blank. Contour lines at about
    ``levels`` evenly spaced round values (:class:`~matplotlib.ticker.MaxNLocator`), labelled; a colour bar
    with the quantity and unit; the other parameters in the title. The manipulator's own design is starred
    (and labelled "design") when it is uniform in both parameters.
    """
    xs, ys, P = critical_load_grid(m, param_x, values_x, param_y, values_y, boundary)
    import matplotlib

    cmap = matplotlib.colormaps["viridis"].with_extremes(bad=(1.0, 1.0, 1.0, 0.0))
    fig = _new_figure(figsize)
    ax = fig.subplots()
    Pm = np.ma.masked_invalid(P)
    mesh = ax.pcolormesh(xs, ys, Pm, shading="nearest", cmap=cmap)
    mesh.set_gid("critical-load")
    lv = _levels(P, levels)
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
    blank = int(np.count_nonzero(~np.isfinite(P)))
    fixed = chain_label(m, exclude=(param_x, param_y))
    ax.set_title(f"Critical buckling load over {param_x} and {param_y}; {fixed}"
                 + (f"\nblank: {blank} designs where the straight chain is not a stable equilibrium" if blank else ""),
                 fontsize=9)
    return fig


# ---------------------------------------------------------------------------- loading paths
#: Quantities :func:`plot_branches` puts on an axis (and ``"q<i>"``, the 1-based joint angle ``q_i``).
BRANCH_QUANTITIES = ("t", "fx", "fy", "dx", "dy", "x", "y", "u", "energy", "s")

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


def chain_label(m: Manipulator, exclude: Sequence[str] = ()) -> str:
    """``"n = 4, a = 1, b = 1, k = 1, L0 = 1"``: the chain's parameters for a title; a chain whose segments
    differ is ``"heterogeneous, n = 5, ..."`` with each parameter that differs given as its range
    (``"k = 0.5..2"``). ``exclude``: parameters left out (e.g. the axes of a map)."""
    parts = [f"n = {m.n}"]
    mixed = False
    for p in MAP_PARAMS:
        vals = [getattr(s, p) for s in m.segments]
        if p in exclude:
            continue
        if all(v == vals[0] for v in vals):
            parts.append(f"{p} = {_fmt(vals[0])}")
        else:
            mixed = True
            flat = [float(x) for v in vals for x in (v if isinstance(v, tuple) else (v,))]
            parts.append(f"{p} = {min(flat):g}..{max(flat):g}")
    return ("heterogeneous, " if mixed else "") + ", ".join(parts)


def _control_text(control: Any) -> str:
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


def _t_label(control: Any) -> str:
    kind = control if isinstance(control, str) else getattr(control, "kind", None)
    if kind == "displacement":
        return "t: tip displacement along the control direction (length)"
    if kind == "preload":
        return "t: rest-length change along the preload direction (length)"
    if kind in ("load", "guided", "wall"):
        return f"t: load magnitude (force, {FORCE_UNIT})"
    return "t: control parameter (a force for a load control, a length for a displacement)"


def branch_quantity_label(name: str, control: Any = None) -> str:
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


def _direction_of_u(control: Any) -> tuple[np.ndarray, bool]:
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


def _quantity(name: str, br: Any, t: np.ndarray, q: np.ndarray, force: np.ndarray, tip: np.ndarray,
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


def _branch_xy(br: Any, name: str) -> np.ndarray:
    return _quantity(name, br, br.t, br.q, br.force, br.tip, br.energy, br.s)


def _event_xy(br: Any, e: Any, name: str) -> float:
    if name == "s":
        i = min(int(e.index), len(br) - 1)
        j = min(i + 1, len(br) - 1)
        da, db = float(np.linalg.norm(e.q - br.q[i])), float(np.linalg.norm(br.q[j] - e.q))
        frac = da / (da + db) if da + db > 0 else 0.0
        return float(br.s[i] + frac * (br.s[j] - br.s[i]))
    return float(_quantity(name, br, np.array([e.t]), e.q[None, :], np.asarray(e.force)[None, :],
                           np.asarray(e.tip)[None, :], np.array([e.energy]), np.array([np.nan]))[0])


def _morse_runs(br: Any, xname: str, yname: str) -> list[tuple[int, np.ndarray, np.ndarray]]:
    """The pieces of constant Morse index of a branch: ``(index, x, y)``. Neighbouring pieces meet at the
    event located between them (or, where none was located, at the next piece's first point)."""
    X, Y = _branch_xy(br, xname), _branch_xy(br, yname)
    idx = np.asarray(br.morse_index, dtype=int)
    P = idx.size
    if P == 0:
        return []
    starts = [0, *(np.flatnonzero(idx[1:] != idx[:-1]) + 1).tolist()]
    ends = [s - 1 for s in starts[1:]] + [P - 1]
    located = [e for e in br.events if e.kind != "joint_limit"]
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


def _as_branches(branches: Any) -> list:
    from ..analyses.paths.branches import Branch

    items = [branches] if isinstance(branches, Branch) else list(branches)
    if not items:
        raise InvalidParameterError("plot_branches needs at least one branch", field="branches")
    for i, b in enumerate(items):
        if not isinstance(b, Branch):
            raise InvalidParameterError(f"branches[{i}] must be a Branch, got {type(b).__name__}",
                                        field=f"branches[{i}]")
    return items


def _manipulator_of(obj: Any) -> Manipulator | None:
    prob = getattr(obj, "_problem", None)
    m = getattr(prob, "m", None)
    if isinstance(m, Manipulator):
        return m
    for name in ("manipulator", "m"):
        m = getattr(obj, name, None)
        if isinstance(m, Manipulator):
            return m
    return None


def _outside_legend(ax: Any, handles: list, labels: list) -> None:
    """The figure's legend beside the axes (right, outside: constrained layout makes room), so that it
    never covers the data."""
    if handles:
        ax.figure.legend(handles, labels, fontsize=7, loc="outside right upper", frameon=False)


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


def plot_branches(branches: Any, *, x: str = "t", y: str = "fx", m: Manipulator | None = None,
                  title: str | None = None, figsize: tuple[float, float] = (8.4, 4.8)) -> Any:
    """Branch diagram of :func:`~tensegrity_opt.trace_branch` / :func:`~tensegrity_opt.bifurcation_diagram`.

    Each branch is drawn ``y`` against ``x`` in pieces of constant Morse index: stable (index 0) solid
    blue, unstable dashed and coloured by the index (:data:`MORSE_COLORS`); neighbouring pieces meet at
    the event located between them. Events are marked on top: folds (filled diamonds), branch points
    (open circles), joint limits (crosses). The legend sits beside the axes (it never covers data);
    the axes say the quantity and its unit in the caller's units (forces ``stiffness x length``,
    lengths, energies ``stiffness x length^2``, angles rad; nothing is normalised but the arclength
    ``s``); the title names the control and the chain's parameters.

    Parameters
    ----------
    branches : Branch or iterable of Branch
    x, y : str
        :data:`BRANCH_QUANTITIES` (``t`` the control parameter, ``fx``/``fy`` the tip force, ``dx``/``dy``
        the deflection, ``x``/``y`` the tip, ``u`` the tip displacement along the control direction
        from the start, ``energy``, ``s``) or ``"q<i>"`` (joint ``i``, 1-based).
    m : Manipulator, optional
        For the title; default the branches' own chain.

    Notes
    -----
    Artists (``gid``): ``"branch-<b>-morse<k>-<j>"`` (branch ``b``, its ``j``-th piece, Morse index
    ``k``), ``"events-fold"``, ``"events-branch_point"``, ``"events-joint_limit"`` (every event of that
    kind over all branches, in order).
    """
    items = _as_branches(branches)
    n = items[0].q.shape[1]
    x = _check_quantity(x, n, "x")
    y = _check_quantity(y, n, "y")
    m = m if m is not None else _manipulator_of(items[0])
    from matplotlib.lines import Line2D

    fig = _new_figure(figsize)
    ax = fig.subplots()
    if y in ("t", "fx", "fy", "energy") or x in ("fx", "fy"):
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
    ax.set_xlabel(branch_quantity_label(x, items[0].control))
    ax.set_ylabel(branch_quantity_label(y, items[0].control))
    ax.grid(True, lw=0.4, alpha=0.5)
    _outside_legend(ax, handles, labels)
    if title is None:
        what = f"{len(items)} branches" if len(items) > 1 else "Equilibrium branch"
        title = f"{what}: {_control_text(items[0].control)}" + (f"\n{chain_label(m)}" if m is not None else "")
    ax.set_title(title, fontsize=9)
    return fig


def plot_limit_load(result: Any, *, m: Manipulator | None = None, figsize: tuple[float, float] = (8.4, 4.8)) -> Any:
    """The load path of :func:`~tensegrity_opt.limit_load`: the load ``t`` against the tip displacement along
    the load ``u = d . (tip - tip_0)`` (guided: ``y`` is held, so ``u = d_x (x - x_0)``), in pieces of constant Morse
    index as :func:`plot_branches`, with the limit point marked (a fold: snap-through; a bifurcation: the
    branch point) and the quasi-buckling load (the least tangent stiffness along the load) as a dotted
    level with its point; a path that ends without a limit marks its end (a joint limit, ``max_load``).

    Artists (``gid``): ``"path-morse<k>-<j>"``, ``"limit-point"``, ``"quasi-buckling"`` (the point),
    ``"quasi-buckling-level"`` (the horizontal line), ``"path-end"``.
    """
    from ..analyses.paths.limit_load import LimitLoad

    if not isinstance(result, LimitLoad):
        raise InvalidParameterError(f"plot_limit_load needs a LimitLoad, got {type(result).__name__}", field="result")
    br = result.branch
    m = m if m is not None else _manipulator_of(br)
    d = np.asarray(result.direction, float)
    fig = _new_figure(figsize)
    ax = fig.subplots()
    ax.axhline(0.0, color="0.85", lw=0.8, zorder=0)
    U, T = _branch_xy(br, "u"), br.t
    lost = next((e for e in br.events if e.stability == "lost"), None)
    runs = _morse_runs(br, "u", "t")
    indices = _draw_runs(ax, [r for r in runs if r[1].size], "path")
    from matplotlib.lines import Line2D

    handles, labels = _morse_handles(indices)
    if result.kind != "none" and result.load is not None:
        ue = _event_xy(br, lost, "u") if lost is not None else float(U[-1])
        style = EVENT_STYLES["fold" if result.kind == "fold" else "branch_point"]
        kw = {k: v for k, v in style.items() if k != "label"}
        pt, = ax.plot([ue], [result.load], ls="none", zorder=7, **kw)
        pt.set_gid("limit-point")
        handles.append(Line2D([], [], ls="none", **kw))
        labels.append(f"limit load P = {result.load:.6g} ({'fold: snap-through' if result.kind == 'fold' else 'bifurcation'})")
    else:
        pt, = ax.plot([float(U[-1])], [float(T[-1])], ls="none", marker="s", ms=6, mfc="white", mec="black", zorder=7)
        pt.set_gid("path-end")
        handles.append(Line2D([], [], ls="none", marker="s", ms=6, mfc="white", mec="black"))
        labels.append(f"end of the path ({result.status})")
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
    finite_u = U[np.isfinite(U)]
    if finite_u.size and float(np.ptp(finite_u)) <= 1e-9 * max(1.0, float(br.straight_length)):
        # e.g. the straight chain under a guided load: it does not move until the limit point
        note = ax.annotate("the tip does not move\nalong the load on this\npath ($u$ = 0)", (0.5, 0.5),
                           xycoords="axes fraction", textcoords="offset points", xytext=(8, 0), ha="left",
                           fontsize=8, color="0.3")
        note.set_gid("no-displacement-note")
    ax.set_xlabel("tip displacement along the load $u = d \\cdot (\\mathrm{tip} - \\mathrm{tip}_0)$ (length)")
    ax.set_ylabel(f"load $t = |F|$ along $d$ (force, {FORCE_UNIT})")
    ax.grid(True, lw=0.4, alpha=0.5)
    _outside_legend(ax, handles, labels)
    head = (f"Limit load: {result.kind}" + (f" at P = {result.load:.6g}" if result.load is not None else
                                             f" ({result.status})")
            + f"; {result.boundary} tip, load along ({d[0]:.3g}, {d[1]:.3g})")
    ax.set_title(head + (f"\n{chain_label(m)}" if m is not None else ""), fontsize=9)
    return fig


def plot_boundary(boundary: Any, *, m: Manipulator | None = None, control: Any = None,
                  figsize: tuple[float, float] = (8.4, 4.8)) -> Any:
    """A stability boundary (:func:`tensegrity_opt.analyses.paths.boundaries.stability_boundary`): the critical ``t``
    (a fold or a branch point of the one-parameter branches) against the second parameter ``p``, with the
    cusps marked. Takes any object with the attributes ``kind``, ``parameter``, ``p``, ``t`` and ``cusps``
    (each with ``.p``, ``.t``), ``status``, ``success``. ``m`` (the chain) and ``control`` (a
    :class:`~tensegrity_opt.Control` or its kind: the unit of ``t``) are for the labels; by default the
    boundary's own ``manipulator`` / ``control`` attributes when it has them.

    Artists (``gid``): ``"boundary"`` (the curve ``(p, t)``), ``"cusps"`` (the cusp points).
    """
    for name in ("kind", "parameter", "p", "t", "cusps"):
        if not hasattr(boundary, name):
            raise InvalidParameterError(f"plot_boundary needs a stability boundary (no attribute {name!r})",
                                        field="boundary")
    m = m if m is not None else _manipulator_of(boundary)
    p = np.asarray(boundary.p, dtype=float).ravel()
    t = np.asarray(boundary.t, dtype=float).ravel()
    if p.shape != t.shape:
        raise InvalidParameterError("the boundary's p and t differ in length", field="boundary")
    kind = str(boundary.kind)
    control = control if control is not None else getattr(boundary, "control", None)
    from matplotlib.lines import Line2D

    fig = _new_figure(figsize)
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
    ax.set_xlabel(f"second parameter $p$: {boundary.parameter}")
    ax.set_ylabel("critical " + _t_label(control))
    ax.grid(True, lw=0.4, alpha=0.5)
    _outside_legend(ax, handles, labels)
    status = getattr(boundary, "status", None)
    incomplete = "" if getattr(boundary, "success", True) else f" (incomplete: {status})"
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


def plot_atlas(atlas: Any, *, m: Manipulator | None = None, title: str | None = None,
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
    from ..analyses.paths.atlas import StabilityAtlas

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

    fig = _new_figure(figsize)
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


def plot_preload_plan(plan: Any, m: Manipulator | None = None, *, margin: float | None = None,
                      title: str | None = None, figsize: tuple[float, float] = (11.0, 6.4)) -> Any:
    """A rest-length plan of :func:`~tensegrity_opt.preloads_for_trajectory`, per step ``k``: the rest lengths of every
    spring (left, top; spring 1 ``L1_0`` solid, spring 2 ``L2_0`` dashed, one colour per segment), the stability
    margin (left, bottom; ``margin``: the required one as a dotted level), and the tip path with the targets
    (right, equal axes; each step's tip joined to the next, the targets as crosses). Infeasible steps (no
    admissible rest lengths: the controller stayed) are shaded in both step panels and their best reachable
    tips marked; feasible steps the forward solve did not verify are marked on the margin. The legend sits
    below the panels (outside the data); the axes are in the caller's units; the title gives the counts, the status and (``m``) the
    chain's parameters.

    Artists (``gid``): ``"rest-length-<i>-<1|2>"`` (segment ``i``, 0-based: its spring's rest length per step),
    ``"margin"``, ``"margin-required"``, ``"unverified"`` (margins of the feasible steps not verified),
    ``"infeasible-rest"``, ``"infeasible-margin"`` (the bands), ``"targets"``, ``"tip-path"``,
    ``"infeasible-tips"``.
    """
    from ..analyses.design.preload_control import PreloadPlan

    if not isinstance(plan, PreloadPlan):
        raise InvalidParameterError(f"plot_preload_plan needs a PreloadPlan, got {type(plan).__name__}", field="plan")
    if margin is not None and not (isinstance(margin, (int, float)) and math.isfinite(margin)):
        raise InvalidParameterError(f"margin must be a finite number, got {margin!r}", field="margin")
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    R = np.asarray(plan.rest_lengths, float)
    K = R.shape[0]
    n = R.shape[1] if R.ndim == 3 else (m.n if m is not None else 0)
    steps = np.arange(K)
    feasible = np.asarray(plan.feasible, bool).reshape(K)
    verified = np.asarray(plan.verified, bool).reshape(K)
    bad = steps[~feasible]
    fig = _new_figure(figsize)
    axd = fig.subplot_mosaic([["rest", "tip"], ["margin", "tip"]], width_ratios=[1.35, 1.0])
    ax_r, ax_m, ax_t = axd["rest"], axd["margin"], axd["tip"]
    ax_m.sharex(ax_r)
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
    line, = ax_m.plot(steps, M, color="tab:blue", lw=1.6, marker=marker, ms=3.5, zorder=3)
    line.set_gid("margin")
    handles.append(Line2D([], [], color="tab:blue", lw=1.6))
    labels.append("stability margin (smallest eigenvalue of the Hessian of $E - F \\cdot$ tip)")
    if margin is not None:
        lev = ax_m.axhline(float(margin), color="tab:orange", ls=":", lw=1.3, zorder=2)
        lev.set_gid("margin-required")
        handles.append(Line2D([], [], color="tab:orange", ls=":", lw=1.3))
        labels.append(f"required margin {float(margin):.3g}")
    unv = steps[feasible & ~verified]
    pt, = ax_m.plot(unv, M[unv], ls="none", marker="o", ms=7.0, mfc="none", mec="tab:purple", mew=1.4, zorder=5)
    pt.set_gid("unverified")
    if unv.size:
        handles.append(Line2D([], [], ls="none", marker="o", ms=7.0, mfc="none", mec="tab:purple", mew=1.4))
        labels.append(f"feasible, not verified by the forward solve ({unv.size})")
    _step_spans(ax_r, bad, "infeasible-rest")
    _step_spans(ax_m, bad, "infeasible-margin")
    if bad.size:
        handles.append(Patch(**CONTROL_STYLES["infeasible"]))
        labels.append(f"infeasible step: the controller stays ({bad.size})")
    # the tip path and the targets
    T = np.asarray(plan.targets, float).reshape(K, 2)
    tips = np.asarray(plan.tip, float).reshape(K, 2)
    tg, = ax_t.plot(T[:, 0], T[:, 1], ls=":", lw=0.9, color="0.45", marker="x", ms=6.0, mec="black", zorder=4)
    tg.set_gid("targets")
    path, = ax_t.plot(tips[:, 0], tips[:, 1], color="tab:blue", lw=1.6, marker=".", ms=4.0, zorder=3)
    path.set_gid("tip-path")
    inf, = ax_t.plot(tips[bad, 0], tips[bad, 1], ls="none", marker="s", ms=6.5, mfc="tab:red", mec="black",
                     zorder=5)
    inf.set_gid("infeasible-tips")
    handles += [Line2D([], [], ls=":", lw=0.9, color="0.45", marker="x", ms=6.0, mec="black"),
                Line2D([], [], color="tab:blue", lw=1.6, marker=".", ms=4.0)]
    labels += ["targets (in order)", "tip per step"]
    if bad.size:
        handles.append(Line2D([], [], ls="none", marker="s", ms=6.5, mfc="tab:red", mec="black"))
        labels.append("best reachable tip of an infeasible step")
    if K:
        ax_t.annotate("first", T[0], textcoords="offset points", xytext=(6, 6), fontsize=7)
    ax_t.set_aspect("equal", adjustable="datalim")
    ax_r.set_ylabel("rest length (length)")
    ax_m.set_ylabel(f"margin ({MARGIN_UNIT})")
    ax_m.set_xlabel("step $k$")
    from matplotlib.ticker import MaxNLocator

    ax_m.xaxis.set_major_locator(MaxNLocator(integer=True))
    ax_r.tick_params(labelbottom=False)
    ax_t.set_xlabel("tip $x$ (length)")
    ax_t.set_ylabel("tip $y$ (length)")
    for ax in (ax_r, ax_m, ax_t):
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


def _simulation_axes(sim: Any, component: int | None) -> dict[str, Any]:
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


def plot_simulation(sim: Any, m: Manipulator | None = None, *, component: int | None = None,
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
    done), ``"start"``, ``"end"`` (the last sample done), ``"snap-<j>"`` (the ``j``-th snap's arrow, a ``FancyArrowPatch``), ``"snap-folds"``,
    ``"snap-landings"`` (the points of every snap with a landing, in time order), ``"joint-limit"``.
    """
    from ..analyses.paths.simulation import Simulation

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

    def at_event(e: Any, after: bool) -> tuple[float, float]:
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
    fig = _new_figure(figsize)
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
    _outside_legend(ax, handles, labels)
    if title is None:
        title = (f"Quasi-static simulation, {sim.mode} tip: {spec['what']}\n{k} of {sim.steps} samples, "
                 f"{len(snaps)} snap(s), status {sim.status}" + spec.get("note", "")
                 + (f"\n{chain_label(m)}" if m is not None else ""))
    ax.set_title(title, fontsize=9)
    return fig
