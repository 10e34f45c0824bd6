"""Figures (matplotlib, Agg canvas) of the library's results: curves, landscapes, shapes, torque curves,
critical-load maps, the loading paths (branch diagrams, limit loads, stability boundaries), the workspace
stability atlas, and the control layer (rest-length plans, simulations).

Every ``plot_*`` function draws a result the caller computed with the library (computing stays with the
caller: the command line, the service, the user's script; no figure function runs an analysis) and returns a
:class:`matplotlib.figure.Figure` on an Agg canvas; :func:`save` writes it as PNG or SVG (from the file
suffix; a PNG at :data:`DPI` dots per inch unless told otherwise) and :func:`render` returns the bytes. Each
takes the result first, then the chain ``m`` (for the title; where it is optional, a figure without it has no
chain line), then its options::

    c = to.force_deflection(m, np.linspace(0.0, 2.0, 41))
    plots.save(plots.plot_curve(c, m), "curve.png")

Matplotlib is imported lazily: ``import tensegrity_opt`` (and even ``import tensegrity_opt.applications.plots``
with :func:`chain_geometry`) works without it. No function touches ``pyplot`` or the global ``rcParams``, so
figures may be drawn from several threads at once (one figure per thread).

The package, by family: :mod:`.style` (the figure, its file, units, colours, labels), :mod:`.geometry` (the
chain's drawing geometry), :mod:`.curves`, :mod:`.equilibria` (landscape, shapes, torque), :mod:`.maps`,
:mod:`.paths` (branches, limit load, boundary, atlas) and :mod:`.control` (plan, simulation).

==========================  ===================================================================
function (result)           figure
==========================  ===================================================================
:func:`plot_curve`          ``Fx`` above ``Fy`` against the deflection (Fig. 6) with the jumps by kind, a
(``Curve``)                 partial curve's end; a curve of ``branch="all"``: every branch, unstable parts
                            dashed
:func:`plot_landscape`      energy contours (even levels) on both elbow branches, cut at the exact edge of
(``Landscape``,             the reachable set, every equilibrium marked and labelled (Figs. 4-5, n = 4)
equilibria)
:func:`plot_shapes`         the chain in each equilibrium: triangles, joints, both springs, coloured
(equilibria)                by stability, titled with Table 2's label
:func:`plot_modes`          the vibration modes of :func:`~tensegrity_opt.modes`: the chain displaced along
(``Modes``)                 each mode both ways over its equilibrium, the masses as dots, the frequency
:func:`plot_holding`        a chain under its weight as its base turns: its sagged shapes (gravity down), and
(``HoldingMap``)            the least stiffness or preload holding it against the base's elevation
:func:`plot_torque`         torque-angle curves ``M(q)`` of segments over the physical range (Fig. 2), their
(segments)                  equilibria marked, ``K`` and the curve's kind in the legend
:func:`plot_map`            critical load ``P = -Fx0`` over two design parameters (blank where
(``CriticalLoadMap``)       :func:`~tensegrity_opt.critical_force` refused the design)
:func:`plot_branches`       branch diagrams of :func:`~tensegrity_opt.trace_branch` /
(``Branch``, branches)      :func:`~tensegrity_opt.bifurcation_diagram`: by default the end angle against the
                            load parameter, cut a margin past the events; pieces coloured by Morse index
                            (stable solid, unstable dashed), folds / branch points / joint limits marked
:func:`plot_limit_load`     the load path of :func:`~tensegrity_opt.limit_load` (load against the tip
(``LimitLoad``)             displacement along it), the limit point and the quasi-buckling load marked
:func:`plot_imperfection`   the imperfection-sensitivity curve of :func:`~tensegrity_opt.imperfection_sensitivity`
(imperfection curve)        (limit load against the amplitude), a marker per kind, the perfect chain's limit
                            load as a line, the fitted small-imperfection law dashed
:func:`plot_boundary`       a stability boundary (critical ``t`` against the second parameter ``p``, in
(``StabilityBoundary``)     its unit), cusps marked
:func:`plot_atlas`          the stability atlas of :func:`~tensegrity_opt.stability_atlas`: the number of
(``StabilityAtlas``)        stable equilibria over ``(dx, dy)`` (discrete colours), the switch and
                            branch-end curves with their crossings
:func:`plot_preload_plan`   a rest-length plan of :func:`~tensegrity_opt.plan_preloads`: the rest lengths of
(``PreloadPlan``)           every spring and the margin per step, the tip path with the targets,
                            infeasible steps shaded
:func:`plot_simulation`     the hysteresis loop of :func:`~tensegrity_opt.simulate`: the driving input
(``Simulation``)            against the tip's response, each snap an arrow from its fold to its landing
==========================  ===================================================================

The critical-load map's result is computed by
:func:`tensegrity_opt.applications.sweeps.critical_load_map`, the landscape's axes over the reachable region
by :func:`tensegrity_opt.analyses.equilibria.landscape.landscape_span`.

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
  ``"branch-<id>-fx-stable"`` / ``"-unstable"`` (a curve of ``branch="all"``; NaN where the branch does not
  exist or has the other stability);
* landscape: ``"energy-elbow+1"`` / ``"energy-elbow-1"`` (QuadMesh, array = ``energy[e].T``, not drawn),
  ``"energy-fill-elbow..."`` (filled contours, clipped to the region), ``"contour-elbow..."`` (contour lines),
  ``"boundary-elbow..."`` (the region's outline), ``"equilibria-elbow..."`` (scatter of ``(q_i, q_j)``);
* shapes: per panel ``"triangle-<i>-<0|1>"`` (proximal/distal triangle of segment ``i``),
  ``"spring-<i>-<1|2>"``, ``"joints"`` (scatter), ``"centerline"``, ``"tip"``;
  the axes' gid is ``"equilibrium-<k>"``;
* torque: ``"torque-<k>"``, ``"torque-<k>-stable"`` / ``"-unstable"`` (the unloaded equilibria); map:
  ``"critical-load"`` (QuadMesh, array ``load[iy, ix]``), ``"critical-load-contours"``, ``"condition4"``
  (the line ``K = 0``), ``"design"``;
* branches: ``"branch-<b>-morse<k>-<j>"`` (branch ``b``'s ``j``-th piece, of Morse index ``k``),
  ``"events-fold"``, ``"events-branch_point"``, ``"events-joint_limit"``, ``"constant-note"``; limit load:
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

from .control import CONTROL_STYLES, MARGIN_UNIT, PLAN_STYLES, plot_preload_plan, plot_simulation
from .curves import JUMP_STYLES, curve_breaks, jump_kind, jump_label, plot_curve
from .equilibria import (
    distinct_segments,
    landscape_region,
    physical_range,
    plot_landscape,
    plot_modes,
    plot_shapes,
    plot_torque,
    segment_label,
    stiffness_text,
    torque_zeros,
)
from .geometry import chain_geometry
from .loads import elevations, plot_holding
from .maps import PARAM_LABELS, plot_map
from .paths import (
    ATLAS_STYLES,
    BOUNDARY_PARAMETER_LABELS,
    BRANCH_CROP,
    BRANCH_DEFAULT_X,
    BRANCH_DEFAULT_Y,
    BRANCH_QUANTITIES,
    EVENT_STYLES,
    LIMIT_ARMS_X,
    MORSE_COLORS,
    boundary_parameter_label,
    branch_quantity_label,
    morse_color,
    plot_atlas,
    plot_boundary,
    plot_branches,
    plot_imperfection,
    plot_limit_load,
)
from .style import (
    DPI,
    ENERGY_UNIT,
    FORCE_UNIT,
    FORMATS,
    MAP_PARAMS,
    STABILITY_COLORS,
    chain_label,
    new_figure,
    render,
    save,
)

__all__ = ["plot_curve", "plot_landscape", "plot_shapes", "plot_modes", "plot_holding", "elevations", "plot_torque",
           "plot_map", "plot_branches",
           "plot_limit_load",
           "plot_imperfection", "plot_boundary", "plot_atlas", "plot_preload_plan", "plot_simulation", "save", "render",
           "new_figure", "chain_geometry", "chain_label", "curve_breaks", "jump_kind", "jump_label", "landscape_region",
           "physical_range", "segment_label", "stiffness_text", "torque_zeros", "distinct_segments",
           "branch_quantity_label", "boundary_parameter_label", "morse_color", "FORMATS", "DPI", "STABILITY_COLORS",
           "MAP_PARAMS", "PARAM_LABELS", "FORCE_UNIT", "ENERGY_UNIT", "MARGIN_UNIT", "JUMP_STYLES", "BRANCH_QUANTITIES",
           "BRANCH_DEFAULT_X", "BRANCH_DEFAULT_Y", "BRANCH_CROP", "BOUNDARY_PARAMETER_LABELS", "LIMIT_ARMS_X",
           "MORSE_COLORS", "EVENT_STYLES", "ATLAS_STYLES", "CONTROL_STYLES", "PLAN_STYLES"]
