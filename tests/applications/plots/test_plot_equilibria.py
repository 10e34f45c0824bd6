"""Figures of equilibria and segments: the energy landscape (its grid's values, the region's exact boundary, the
equilibria on their elbow branch), the chain in every equilibrium, the torque curves of segments."""

from __future__ import annotations

from collections import Counter

import numpy as np
import pytest

pytest.importorskip("matplotlib")

from figures import check_renders, gid, landscape_figure, legend_texts, nan_equal, rows  # noqa: E402
from matplotlib.colors import to_rgba  # noqa: E402

import tensegrity_opt as to  # noqa: E402
from tensegrity_opt.analyses.equilibria.landscape import complete_configuration, landscape_margin  # noqa: E402
from tensegrity_opt.applications import plots  # noqa: E402
from tensegrity_opt.errors import InvalidParameterError  # noqa: E402

PAPER = to.Manipulator.uniform(4, a=1.0, b=1.0, k=1.0, L0=1.0)
PAPER_LABEL = "n = 4, a = 1, b = 1, k = 1, L0 = 1"


@pytest.fixture(scope="module")
def equilibria():
    return to.find_equilibria(PAPER, 0.1, 0.0)


# ---------------------------------------------------------------------------- landscape
@pytest.mark.slow
def test_landscape_energy_and_equilibria(tmp_path, equilibria):
    fig, land = landscape_figure(PAPER, 0.1, 0.0, pair=(0, 3), grid=41, span=None, equilibria=equilibria)
    assert land.qi.max() == pytest.approx(0.999 * PAPER.joint_limits[0])          # the physical range
    target = PAPER.target(0.1, 0.0)
    points, colors, texts = [], [], []
    for b, elbow in enumerate(("+1", "-1")):
        mesh = gid(fig, f"energy-elbow{elbow}")
        assert nan_equal(mesh.get_array(), land.energy[b].T)
        cs = gid(fig, f"contour-elbow{elbow}")
        finite = land.energy[np.isfinite(land.energy)]
        assert np.all(np.diff(cs.levels) > 0) and finite.min() <= cs.levels[0] and cs.levels[-1] <= finite.max()
        sc = gid(fig, f"equilibria-elbow{elbow}")
        offs = np.asarray(sc.get_offsets(), dtype=float).reshape(-1, 2)
        fc = sc.get_facecolors()
        for i, (qi, qj) in enumerate(offs):
            full = complete_configuration(PAPER, target, (0, 3), qi, qj, 1 if elbow == "+1" else -1)
            match = [e for e in equilibria if np.allclose(full, e.q, atol=1e-8)]
            assert len(match) == 1, "each marker lies on the elbow branch of its equilibrium"
            colors.append((match[0].kind, tuple(fc[i if len(fc) > 1 else 0])))
        points.extend(map(tuple, offs))
        texts.extend(t.get_text() for t in sc.axes.texts)
    expected = sorted((e.q[0], e.q[3]) for e in equilibria)
    assert np.allclose(sorted(points), expected, atol=0)
    assert all(rgba == to_rgba(plots.STABILITY_COLORS[kind]) for kind, rgba in colors)
    assert Counter(texts) == Counter(e.shape for e in equilibria) == Counter({"U": 2, "ZU": 2, "Z": 2})
    assert "$\\delta_x$ = 0.1, $\\delta_y$ = 0: 6 equilibria" in fig._suptitle.get_text()
    check_renders(fig, tmp_path, "landscape")


def test_landscape_draws_the_landscape_it_is_given():
    fig, land = landscape_figure(PAPER, 0.1, 0.0, grid=31)            # over the reachable region
    assert nan_equal(gid(fig, "energy-elbow+1").get_array(), land.energy[0].T)
    assert nan_equal(gid(fig, "energy-elbow-1").get_array(), land.energy[1].T)
    ax = gid(fig, "energy-elbow+1").axes
    assert ax.get_xlim() == (land.qi.min(), land.qi.max()) and ax.get_ylim() == (land.qj.min(), land.qj.max())


@pytest.mark.parametrize("pair", [(0, 1), (0, 3)])
def test_landscape_region_is_the_exact_boundary_and_holds_every_equilibrium(pair, equilibria):
    fig, land = landscape_figure(PAPER, 0.1, 0.0, pair=pair, grid=41, equilibria=equilibria)
    target = PAPER.target(0.1, 0.0)
    marked = 0
    for b, elbow in enumerate(("+1", "-1")):
        edge = gid(fig, f"boundary-elbow{elbow}")
        path = edge.get_path()
        fill = gid(fig, f"energy-fill-elbow{elbow}")
        assert fill.get_clip_path() is not None                  # the fill is cut at the outline
        offs = np.asarray(gid(fig, f"equilibria-elbow{elbow}").get_offsets(), float).reshape(-1, 2)
        for qi, qj in offs:
            # inside the drawn region, and (independently) a configuration in the physical range
            assert path.contains_point((qi, qj)), (pair, elbow, qi, qj)
            full = complete_configuration(PAPER, target, pair, qi, qj, 1 if b == 0 else -1)
            assert np.all(np.isfinite(full)) and np.all(np.abs(full) < PAPER.joint_limits)
            marked += 1
        # the outline lies on the exact boundary (margin 0), not on the grid's cell edges
        verts = path.vertices[path.codes != path.CLOSEPOLY] if path.codes is not None else path.vertices
        mg, _ = landscape_margin(PAPER, target, pair, verts[:, 0], verts[:, 1], 1 if b == 0 else -1)
        QI, QJ = np.meshgrid(land.qi, land.qj, indexing="ij")
        grid_mg, _ = landscape_margin(PAPER, target, pair, QI, QJ, 1 if b == 0 else -1)
        inside = np.isfinite(land.energy[b])
        # the margin is positive exactly on the landscape's finite cells (brute force: the library's NaN)
        assert np.array_equal(inside, grid_mg > 0)
        # cells next to the boundary have margins up to ~1e-2; the outline's vertices are 100 x closer
        step = np.max(np.abs(np.diff(grid_mg, axis=0))[np.isfinite(np.diff(grid_mg, axis=0))])
        assert np.max(np.abs(mg)) < 0.02 * step, (np.max(np.abs(mg)), step)
    assert marked == len(equilibria) == 6


def test_landscape_contour_levels_are_evenly_spaced():
    fig, land = landscape_figure(PAPER, 0.1, pair=(0, 1), grid=41)
    finite = land.energy[np.isfinite(land.energy)]
    for elbow in ("+1", "-1"):
        for name in (f"contour-elbow{elbow}", f"energy-fill-elbow{elbow}"):
            lv = np.asarray(gid(fig, name).levels, float)
            d = np.diff(lv)
            assert lv.size >= 8 and np.allclose(d, d[0], rtol=1e-9, atol=0), (name, lv)
            assert finite.min() <= lv[0] and lv[-1] <= finite.max()
    # percentile levels would not be evenly spaced on this landscape
    pct = np.unique(np.percentile(finite, np.linspace(0.0, 100.0, 25)))
    assert not np.allclose(np.diff(pct), np.diff(pct)[0], rtol=1e-3)


def test_landscape_axes_and_legend():
    fig, _ = landscape_figure(PAPER, 0.1, grid=41)
    for ax in fig.axes[:2]:
        assert "(rad)" in ax.get_xlabel()
    assert "(rad)" in fig.axes[0].get_ylabel()
    cbar = [ax for ax in fig.axes if ax.get_label() == "<colorbar>"]
    assert len(cbar) == 1 and "energy $E$ (stiffness × length²)" in cbar[0].get_ylabel()
    assert PAPER_LABEL in fig._suptitle.get_text()
    assert legend_texts(landscape_figure(PAPER, 0.1, grid=31)[0])


# ---------------------------------------------------------------------------- shapes
@pytest.mark.slow
def test_shapes_draw_every_equilibrium(tmp_path, equilibria):
    fig = plots.plot_shapes(equilibria, PAPER, 0.1, 0.0)
    assert Counter((e.shape, e.kind) for e in equilibria) == Counter(
        {("U", "minimum"): 2, ("ZU", "saddle"): 2, ("Z", "maximum"): 2})       # Table 2
    for k, e in enumerate(equilibria):
        ax = gid(fig, f"equilibrium-{k}")
        assert ax.get_title().startswith(f"{e.shape} ({e.signs})")
        color = to_rgba(plots.STABILITY_COLORS[e.kind])
        L1, L2 = PAPER.spring_lengths(e.q)
        g = plots.chain_geometry(PAPER, e.q)
        for i in range(PAPER.n):
            for s, L in ((1, L1[i]), (2, L2[i])):
                xy = gid(ax, f"spring-{i}-{s}").get_xydata()
                assert np.linalg.norm(xy[1] - xy[0]) == pytest.approx(L, rel=1e-12)
                assert to_rgba(gid(ax, f"spring-{i}-{s}").get_color()) == color
            for t in range(2):
                poly = gid(ax, f"triangle-{i}-{t}")
                verts = poly.get_xy()[:3]
                assert np.allclose(verts, g["triangles"][i, t], atol=1e-12)
                assert poly.get_facecolor()[:3] == pytest.approx(color[:3])
        joints = np.asarray(gid(ax, "joints").get_offsets(), dtype=float)
        assert np.allclose(joints, g["joints"], atol=1e-12)
        assert np.allclose(gid(ax, "tip").get_xydata()[0], PAPER.tip(e.q), atol=1e-12)
        assert np.allclose(gid(ax, "tip").get_xydata()[0], PAPER.target(0.1, 0.0), atol=1e-9)
        assert np.allclose(rows(gid(ax, "centerline"))[-1], PAPER.tip(e.q), atol=1e-12)
    assert PAPER_LABEL in fig._suptitle.get_text() and "stiffness × length" in fig._suptitle.get_text()
    assert "(length)" in fig.axes[0].get_ylabel() and any("(length)" in ax.get_xlabel() for ax in fig.axes)
    assert not fig.legends                    # no legend at all: the colours are in each panel's title
    check_renders(fig, tmp_path, "shapes")


def test_shapes_draw_at_most_max_panels(equilibria):
    fig = plots.plot_shapes(equilibria, PAPER, 0.1, max_panels=4)
    assert [ax.get_gid() for ax in fig.axes if ax.get_visible()] == [f"equilibrium-{k}" for k in range(4)]
    assert "(the 4 lowest of 6)" in fig._suptitle.get_text()


# ---------------------------------------------------------------------------- torque
def test_torque_curves_are_segment_torque(tmp_path):
    segs = [to.Segment(1.0, 1.0, 1.0, L0) for L0 in (0.5, 1.0, 1.5)] + [to.Segment(0.7, 1.0, (1.0, 2.0), (1.0, 1.2))]
    fig = plots.plot_torque(segs, num=101)
    for k, seg in enumerate(segs):
        x, y = gid(fig, f"torque-{k}").get_data()
        lim = seg.joint_limit
        assert x.size == 101 and np.all(np.abs(x) < lim) and x[0] == pytest.approx(-lim, rel=0.05)
        assert np.array_equal(y, seg.torque(x))
        assert np.allclose(y, [seg.torque(v) for v in x], rtol=1e-14, atol=1e-14)
    q = np.linspace(-1.0, 1.0, 21)
    fig2 = plots.plot_torque(segs[3], q)
    x, y = gid(fig2, "torque-0").get_data()
    assert np.array_equal(x, q) and np.array_equal(y, segs[3].torque(q))
    check_renders(fig, tmp_path, "torque")


def test_torque_draws_the_distinct_segments_of_a_chain():
    m = to.Manipulator([to.Segment(1.0, 1.0), to.Segment(0.5, 1.0), to.Segment(1.0, 1.0)])
    assert plots.distinct_segments(m) == [to.Segment(1.0, 1.0), to.Segment(0.5, 1.0)]
    fig = plots.plot_torque(m, num=11)
    assert gid(fig, "torque-1") is not None and not fig.findobj(lambda a: a.get_gid() == "torque-2")
    with pytest.raises(InvalidParameterError) as e:
        plots.plot_torque([to.Segment(1.0, 1.0), "x"])
    assert e.value.field == "segments[1]"
    with pytest.raises(InvalidParameterError):
        plots.plot_torque([])


def test_torque_axes_and_labels():
    segs = [to.Segment(0.5, 1.0, 1.0, L0) for L0 in (0.5, 2.5)]
    ax = plots.plot_torque(segs).axes[0]
    assert "(rad)" in ax.get_xlabel() and "(stiffness × length²)" in ax.get_ylabel()
    assert "a = 0.5, b = 1, k = 1" in ax.get_title()             # shared; L0 differs: in each legend entry


def test_torque_label_prints_zero_for_a_zero_stiffness():
    seg = to.Segment(0.3, 1.0, 1.0, 2 * (1 - 0.3 ** 2))    # K = k (b L0 - 2 (b^2 - a^2)) = 0 up to rounding
    assert seg.stiffness != 0.0 and abs(seg.stiffness) < 1e-12     # rounding noise in the library's K
    assert plots.stiffness_text(seg) == "K = 0: degenerate"
    assert plots.stiffness_text(to.Segment(0.5, 1.0, 1.0, 1.5)) == "K = 0: degenerate"     # 1.5 - 1.5
    segs = [to.Segment(0.5, 1.0, 1.0, L0) for L0 in (0.5, 1.5, 2.5)]
    texts = legend_texts(plots.plot_torque(segs))
    assert "L0=0.5 (K = -1: two-mode)" in texts                   # K = 0.5 - 1.5
    assert "L0=1.5 (K = 0: degenerate)" in texts
    assert "L0=2.5 (K = 1: monotonic)" in texts
    assert not any("e-" in t for t in texts)


def test_torque_marks_the_equilibria_of_the_unloaded_segment():
    # two-mode (K = -0.5): wells where cos(q/2) = L0 cos(beta) / (2 c cos(2 beta)) (eq. 2 = 0), q = 0 unstable
    two, mono = to.Segment(0.5, 1.0, 1.0, 1.0), to.Segment(0.5, 1.0, 1.0, 2.0)
    c, beta = np.hypot(0.5, 1.0), np.arctan2(0.5, 1.0)
    well = 2.0 * np.arccos(1.0 * np.cos(beta) / (2.0 * c * np.cos(2.0 * beta)))
    assert well == pytest.approx(1.68214, abs=1e-5) and well < two.joint_limit
    fig = plots.plot_torque([two, mono], num=401)
    st = gid(fig, "torque-0-stable").get_xdata()
    un = gid(fig, "torque-0-unstable").get_xdata()
    assert np.allclose(np.sort(st), [-well, well], atol=1e-4) and np.allclose(un, [0.0], atol=1e-12)
    assert np.allclose(gid(fig, "torque-1-stable").get_xdata(), [0.0])
    assert gid(fig, "torque-1-unstable").get_xdata().size == 0


def test_shapes_draw_pushing_and_slack_springs_and_stops_distinctly():
    """dx = 2 on the paper's chain: under the linear law spring 3.2 pushes (red dashed), under the tension-only law
    it is slack (grey dotted) and joint 3 rests on its stop (ringed); with springs='tension' each spring's colour is
    its force on the shared scale (the colour bar's)."""
    from matplotlib.colors import to_rgba

    lin = to.solve_equilibrium(PAPER, 2.0)
    ten = to.solve_equilibrium(PAPER.with_spring("tension_only"), 2.0)
    fig = plots.plot_shapes([lin, ten], PAPER, 2.0)
    a0, a1 = gid(fig, "equilibrium-0"), gid(fig, "equilibrium-1")
    pushing, slack, taut = gid(a0, "spring-2-2"), gid(a1, "spring-2-2"), gid(a0, "spring-2-1")
    assert to_rgba(pushing.get_color()) == to_rgba("tab:red") and pushing.get_linestyle() == "--"
    assert slack.get_linestyle() == ":" and to_rgba(slack.get_color()) == to_rgba("0.55")
    assert taut.get_linestyle() == "-" and to_rgba(taut.get_color()) == to_rgba(plots.STABILITY_COLORS["minimum"])
    assert gid(a1, "stop-2") is not None
    assert not [a for a in a0.get_children() if str(a.get_gid()).startswith("stop-")]
    fig = plots.plot_shapes([lin, ten], PAPER, 2.0, spring_colors="tension")
    line = gid(gid(fig, "equilibrium-0"), "spring-2-2")
    mappable = [a for a in fig.axes if a.get_gid() == "spring-forces"]
    assert mappable and "tension" in mappable[0].get_ylabel()
    top = max(abs(lin.spring_forces).max(), abs(ten.spring_forces).max())
    import matplotlib
    from matplotlib.colors import TwoSlopeNorm

    want = matplotlib.colormaps["coolwarm"](TwoSlopeNorm(0.0, -top, top)(lin.spring_forces[2, 1]))
    assert to_rgba(line.get_color()) == pytest.approx(want)
    with pytest.raises(to.InvalidParameterError):
        plots.plot_shapes([lin], PAPER, 2.0, spring_colors="colour")


def test_modes_draw_each_mode_both_ways_about_the_held_tip(tmp_path):
    """``plot_modes``: per mode the equilibrium's centre line and the chain displaced along the mode both ways, the
    largest joint excursion ``excursion``; with the tip held both displaced tips stay at the target to second
    order in the amplitude (the mode is tangent to the tip constraint: checked on the reference kinematics); the
    masses are drawn where the triangles' centroids are (the mean of each triangle's vertices)."""
    import math

    import reference_tension_only as ref

    m = to.Manipulator.uniform(5, mass=0.1, payload=0.2)
    eq = to.solve_equilibrium(m, 1.5, 0.3)
    md = to.modes(m, eq)
    amp = 0.01
    fig = plots.plot_modes(md, m, excursion=amp)
    ids = check_renders(fig, tmp_path, "modes")
    assert {"mode-0", "mode-1", "mode-2"} <= ids
    segs = ref.segs_of(m)
    target = ref.tip(segs, eq.q)
    for k in range(3):
        ax = gid(fig, f"mode-{k}")
        base = rows(gid(ax, "equilibrium"))
        np.testing.assert_allclose(base[-1], target, atol=1e-12)
        for name, sign in (("mode-plus", 1.0), ("mode-minus", -1.0)):
            line = rows(gid(ax, name))
            s = md.shapes[k] * amp / np.abs(md.shapes[k]).max()
            np.testing.assert_allclose(line[-1], ref.tip(segs, eq.q + sign * s), atol=1e-12)
            assert np.linalg.norm(line[-1] - target) <= 10 * amp ** 2 * float(m.b.sum())
        w = md.frequencies[k]
        assert f"{w:.4g} rad/s" in ax.get_title() and f"{w / (2 * math.pi):.4g} Hz" in ax.get_title()
        masses = gid(ax, "masses").get_offsets()
        assert len(masses) == 2 * m.n - 1 + 1                # every moving triangle and the payload
    with pytest.raises(InvalidParameterError) as e:
        plots.plot_modes(md, m, excursion=-1.0)
    assert e.value.field == "excursion"


def test_shapes_of_a_chain_with_weight_draw_gravity_and_name_the_loads():
    m = to.Manipulator.uniform(4, mass=0.05, gravity=(0.0, -9.81))
    eqs = to.find_equilibria(m, 1.0, 0.5)
    fig = plots.plot_shapes(eqs, m, 1.0, 0.5, max_panels=2)
    for ax in fig.axes[:2]:
        assert "gravity" in {a.get_gid() for a in ax.get_children()}
    assert "under gravity (0, -9.81)" in fig._suptitle.get_text()
    bare = plots.plot_shapes(to.find_equilibria(to.Manipulator.uniform(4), 1.0, 0.5), to.Manipulator.uniform(4),
                             1.0, 0.5, max_panels=1)
    assert "gravity" not in {a.get_gid() for a in bare.axes[0].get_children()}
