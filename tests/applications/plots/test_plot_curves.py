"""The force-deflection figure: it draws the curve's numbers, its jumps by kind, a partial curve's end, and every
branch of a curve computed with ``branch="all"``."""

from __future__ import annotations

import dataclasses
from collections import Counter

import numpy as np
import pytest

pytest.importorskip("matplotlib")

from figures import check_renders, gid, legend_texts, maybe_gid, nan_equal, rows  # noqa: E402

import tensegrity_opt as to  # noqa: E402
from tensegrity_opt.analyses.paths.curves import CurveEnd, Jump  # noqa: E402
from tensegrity_opt.applications import plots  # noqa: E402

PAPER = to.Manipulator.uniform(4, a=1.0, b=1.0, k=1.0, L0=1.0)
PAPER_LABEL = "n = 4, a = 1, b = 1, k = 1, L0 = 1"


def test_curve_plots_the_force_deflection_numbers(tmp_path):
    dx = np.linspace(0.0, 1.0, 11)
    c = to.force_deflection(PAPER, dx)
    fig = plots.plot_curve(c, PAPER)
    fx, fy = gid(fig, "fx"), gid(fig, "fy")
    assert np.array_equal(rows(fx), np.column_stack([c.dx, c.fx]))
    assert np.array_equal(rows(fy), np.column_stack([c.dx, c.fy]))
    # Fx is broken at the buckling jump (after the straight point), Fy is continuous there
    assert np.isnan(fx.get_xydata()[1]).all() and fx.get_xydata().shape[0] == dx.size + 1
    assert fy.get_xydata().shape[0] == dx.size
    # the buckling jump: vertical dashed segment at dx = 0 from 0 to the critical force
    crit = to.critical_force(PAPER).force
    jump = gid(fig, "jump-0-buckling-fx")
    assert np.allclose(jump.get_xydata(), [[0.0, 0.0], [0.0, crit]], atol=1e-12)
    assert jump.get_linestyle() == "--"
    assert maybe_gid(fig, "jump-0-buckling-fy") is None        # Fy is 0 on both sides
    assert c.fx[1] == pytest.approx(crit, rel=0.02)
    check_renders(fig, tmp_path, "curve")


def test_curve_marks_a_branch_switch_against_dy():
    dy = np.linspace(-0.6, 0.6, 13)
    dx = np.full(dy.size, 0.3)
    c = to.force_deflection(PAPER, dx, dy)
    fig = plots.plot_curve(c, PAPER)
    switches = [(k, j) for k, j in enumerate(c.jumps) if j.kind in ("snap", "switch")]
    assert len(switches) == 1
    k, j = switches[0]
    kind = plots.jump_kind(j)
    assert kind == j.kind
    # abscissa is dy (dx is constant)
    assert np.array_equal(rows(gid(fig, "fx")), np.column_stack([c.dy, c.fx]))
    assert np.array_equal(rows(gid(fig, "fy")), np.column_stack([c.dy, c.fy]))
    seg = gid(fig, f"jump-{k}-{kind}-fy")
    assert np.allclose(seg.get_xydata(), [[j.dy_before, j.force_before[1]], [j.dy_after, j.force_after[1]]])
    assert np.sign(j.force_before[1]) != np.sign(j.force_after[1])
    # the line is broken exactly where Fy jumps
    xy = gid(fig, "fy").get_xydata()
    gap = int(np.flatnonzero(np.isnan(xy[:, 0]))[0])
    assert xy[gap - 1, 0] == j.dy_before and xy[gap + 1, 0] == j.dy_after


def test_curve_all_branches_unstable_dashed(tmp_path):
    dx = np.linspace(0.0, 0.5, 6)
    c = to.force_deflection(PAPER, dx, branch="all")
    fig = plots.plot_curve(c, PAPER)
    assert len(c.branches) == 6
    kinds = Counter()
    for br in c.branches:
        bid = int(br.branch[0])
        for name in ("fx", "fy"):
            v = getattr(br, name)
            ok = np.isfinite(v)
            stable = gid(fig, f"branch-{bid}-{name}-stable")
            unstable = gid(fig, f"branch-{bid}-{name}-unstable")
            assert np.array_equal(stable.get_xdata(), c.dx)
            assert nan_equal(stable.get_ydata(), np.where(ok & br.stable, v, np.nan))
            assert nan_equal(unstable.get_ydata(), np.where(ok & ~br.stable, v, np.nan))
            assert stable.get_linestyle() == "-" and unstable.get_linestyle() == "--"
        kinds[bool(br.stable[1])] += 1
    assert kinds == {True: 2, False: 4}          # two stable U branches, four unstable (ZU, Z)
    assert "(all branches)" in fig._suptitle.get_text()
    check_renders(fig, tmp_path, "curve_all")


def test_curve_axes_say_quantity_and_unit_and_the_title_the_chain():
    fig = plots.plot_curve(to.force_deflection(PAPER, np.linspace(0.0, 0.5, 6)), PAPER)
    top, bottom = fig.axes[:2]
    assert "$F_x$" in top.get_ylabel() and "(stiffness × length)" in top.get_ylabel()
    assert "$F_y$" in bottom.get_ylabel() and "(stiffness × length)" in bottom.get_ylabel()
    assert "deflection $\\delta_x$ (length)" in bottom.get_xlabel()
    assert PAPER_LABEL in fig._suptitle.get_text()
    # Fx and Fy on two stacked panels sharing the abscissa, each on its own scale
    assert top.get_shared_x_axes().joined(top, bottom)
    assert top.get_position().y0 > bottom.get_position().y1 - 1e-9
    m = to.Manipulator([to.Segment(1.0, 1.0, k, 1.0) for k in (0.5, 1.0, 2.0, 1.0, 1.5)])
    fig = plots.plot_curve(to.force_deflection(m, np.linspace(0.0, 0.2, 3)), m)
    assert "heterogeneous, n = 5" in fig._suptitle.get_text() and "k = 0.5..2" in fig._suptitle.get_text()


@pytest.mark.parametrize("branch", ["stable", "all"])
def test_curve_legend_does_not_cover_the_data(branch):
    assert legend_texts(plots.plot_curve(to.force_deflection(PAPER, np.linspace(0.0, 0.5, 6), branch=branch),
                                         PAPER))


def _partial(c, k: int):
    """``c`` cut after ``k`` points, ended at point ``k`` (``Curve.ended_at``)."""
    fields = {f.name: getattr(c, f.name) for f in dataclasses.fields(c)}
    for nm in ("dx", "dy", "q", "fx", "fy", "energy", "stable", "morse_index", "branch", "shape", "point_status",
               "solver"):
        fields[nm] = fields[nm][:k]
    fields["ended_at"] = CurveEnd(float(c.dx[k]), float(c.dy[k]), "no_stable_equilibrium",
                                  f"no stable equilibrium at dx = {float(c.dx[k]):g}")
    fields["requested"] = int(c.dx.size)
    return type(c)(**fields)


def test_a_partial_curve_draws_its_end():
    dx = np.linspace(0.0, 1.0, 11)
    c = _partial(to.force_deflection(PAPER, dx), 7)
    fig = plots.plot_curve(c, PAPER)
    assert np.array_equal(rows(gid(fig, "fx")), np.column_stack([c.dx, c.fx]))     # only the points returned
    for name, v in (("fx", c.fx), ("fy", c.fy)):
        assert np.allclose(gid(fig, f"end-marker-{name}").get_xydata(), [[c.dx[-1], v[-1]]])
        assert np.allclose(gid(fig, f"curve-end-{name}").get_xdata(), [dx[7], dx[7]])
    text = gid(fig, "curve-end-text").get_text()
    assert text == "stable branch ends at $\\delta_x$ = 0.7"
    done = plots.plot_curve(to.force_deflection(PAPER, dx), PAPER)
    assert maybe_gid(done, "end-marker-fx") is None and maybe_gid(done, "curve-end-text") is None


@pytest.mark.slow
def test_a_partial_curve_of_the_library_draws_its_end():
    m = to.Manipulator.uniform(3, a=0.5)
    dx = np.linspace(0.0, 5.5, 23)
    c = to.force_deflection(m, dx)
    assert c.ended_at is not None and c.dx.size < dx.size          # K = -0.5: the stable branch ends
    fig = plots.plot_curve(c, m)
    assert np.array_equal(rows(gid(fig, "fx")), np.column_stack([c.dx, c.fx]))
    assert np.allclose(gid(fig, "end-marker-fx").get_xydata(), [[c.dx[-1], c.fx[-1]]])
    assert gid(fig, "curve-end-text").get_text() == f"stable branch ends at $\\delta_x$ = {c.ended_at.dx:.4g}"
    kinds = [plots.jump_kind(j) for j in c.jumps]
    assert kinds[0] == "leave_straight" and "buckling" not in kinds          # K = -0.5: nothing buckles
    assert legend_texts(fig)


def test_a_tensile_jump_off_the_straight_chain_is_not_called_buckling():
    bistable = to.Manipulator.uniform(4, a=0.5, L0=1.0)          # K = 1 - 1.5 < 0: straight is unstable
    assert bistable.segments[0].stiffness < 0
    c = to.force_deflection(bistable, np.linspace(0.0, 0.6, 7))
    first = c.jumps[0]
    assert first.force_before[0] == 0.0 and first.force_after[0] > 0.0          # tensile
    assert plots.jump_kind(first) == "leave_straight"
    assert "buckling" not in plots.jump_label(first)
    fig = plots.plot_curve(c, bistable)
    assert maybe_gid(fig, "jump-0-buckling-fx") is None
    assert gid(fig, "jump-0-leave_straight-fx") is not None
    texts = legend_texts(fig)
    entry = next(t for t in texts if t.startswith("jump 1:"))
    assert "buckling" not in entry and "straight" in entry
    # the paper's chain buckles: compressive, and called so
    p = to.force_deflection(PAPER, np.linspace(0.0, 0.2, 3))
    assert plots.jump_kind(p.jumps[0]) == "buckling"
    assert plots.jump_label(p.jumps[0]).startswith("buckling") and "compressive" in plots.jump_label(p.jumps[0])


def test_a_jump_of_a_kind_the_figure_does_not_know_is_drawn_as_a_snap():
    j = Jump("branch_switch", 0.3, 0.35, np.array([-0.5, 0.1]), np.array([-0.4, -0.1]), 0, 1)
    assert plots.jump_kind(j) == "snap" and plots.jump_label(j).startswith("snap to another stable branch")
    assert "dF_x = +0.1" in plots.jump_label(j)
