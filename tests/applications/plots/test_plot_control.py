"""Figures of the control layer: rest-length plans (``plot_preload_plan``) and simulations (``plot_simulation``).

Artists are found by their ``gid`` and their data compared with the library's numbers; every figure renders to
PNG and SVG (not compared pixel by pixel); the legend sits outside the data.
"""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("matplotlib")

from figures import check_renders, gid, legend_texts  # noqa: E402

import tensegrity_opt as to  # noqa: E402
from tensegrity_opt.applications import plots  # noqa: E402
from tensegrity_opt.errors import InvalidParameterError  # noqa: E402

PAPER = to.Manipulator.uniform(4)
M3 = to.Manipulator.uniform(3, a=0.5)


@pytest.fixture(scope="module")
def plan():
    """Tips of the paper's chain bent evenly (q_i = alpha), the third moved off the arc: beyond a rate limit 0.05."""
    T = np.array([PAPER.tip(np.full(4, a)) for a in np.linspace(0.0, 0.05, 6)])
    T[3] += [-0.6, 0.8]
    p = to.plan_preloads(PAPER, T, rate_limit=0.05, dt=1.0, margin=0.3)
    assert list(p.feasible) == [True, True, True, False, True, True]
    return p


def test_plan_figure_draws_the_library_plan(plan, tmp_path):
    fig = plots.plot_preload_plan(plan, PAPER, margin=0.3)
    K = len(plan.method)
    for i in range(4):
        for s in (1, 2):
            line = gid(fig, f"rest-length-{i}-{s}")
            assert np.array_equal(line.get_xdata(), np.arange(K))
            assert np.array_equal(line.get_ydata(), plan.commands[:, i, s - 1])
    m = gid(fig, "margin")
    assert np.array_equal(m.get_ydata(), plan.margin, equal_nan=True)
    assert np.array_equal(gid(fig, "tip-error").get_ydata(), plan.tip_error)
    assert plan.tip_error[3] > 0.5 and plan.tip_error[0] < 1e-9
    assert gid(fig, "margin-required").get_ydata()[0] == pytest.approx(0.3)
    assert np.array_equal(gid(fig, "targets").get_xydata(), plan.targets)
    assert np.array_equal(gid(fig, "tip-path").get_xydata(), plan.tip)
    assert np.array_equal(gid(fig, "infeasible-tips").get_xydata(), plan.tip[~plan.feasible])
    for name in ("infeasible-rest", "infeasible-margin", "infeasible-error"):
        bands = gid(fig, name).get_paths()
        assert len(bands) == 1 and bands[0].get_extents().x0 == pytest.approx(2.5)
    labels = legend_texts(fig, count=1)
    assert "segment 4" in labels and any("infeasible step" in t for t in labels)
    assert any("required margin 0.3" in t for t in labels)
    axes_labels = " ".join(ax.get_xlabel() + " " + ax.get_ylabel() for ax in fig.axes)
    assert "(length)" in axes_labels and "tip error" in axes_labels and "stiffness × length² / rad" in axes_labels
    assert "status infeasible_steps" in fig.get_suptitle() and "n = 4, a = 1" in fig.get_suptitle()
    ids = check_renders(fig, tmp_path, "plan")
    assert {"rest-length-0-1", "tip-path", "targets", "margin", "infeasible-rest"} <= ids


def test_plan_margin_lines_have_colours_of_their_own(plan):
    from matplotlib.colors import to_rgba

    fig = plots.plot_preload_plan(plan, PAPER, margin=0.3)
    segments = {to_rgba(gid(fig, f"rest-length-{i}-{s}").get_color()) for i in range(4) for s in (1, 2)}
    assert len(segments) == 4
    for name in ("margin", "margin-required", "tip-path"):
        assert to_rgba(gid(fig, name).get_color()) not in segments, name
    assert gid(fig, "margin").get_linestyle() != gid(fig, "margin-required").get_linestyle()


@pytest.mark.slow
def test_plan_figure_of_a_long_chain_and_of_no_step(tmp_path):
    m = to.Manipulator.uniform(12)
    p = to.plan_preloads(m, [[m.straight_length - 0.01, 0.3]])
    fig = plots.plot_preload_plan(p, m)
    assert len(fig.axes) == 5            # the four panels and a colour bar of the segments
    assert not any(t.startswith("segment") for t in legend_texts(fig, count=1))
    gid(fig, "rest-length-11-2")
    empty = to.plan_preloads(PAPER, [[7.9, 0.1]], timeout=1e-9)
    assert empty.status == "time_limit" and len(empty.method) == 0
    check_renders(plots.plot_preload_plan(empty), tmp_path, "empty")
    with pytest.raises(InvalidParameterError) as exc:
        plots.plot_preload_plan({"status": "complete"})
    assert exc.value.field == "plan"


def _points(fig, name):
    return gid(fig, name).get_xydata()


@pytest.mark.slow
def test_simulation_figure_is_the_hysteresis_loop(tmp_path):
    fy = np.concatenate([np.linspace(0, 0.3, 16), np.linspace(0.3, -0.3, 31)[1:], np.linspace(-0.3, 0, 16)[1:]])
    sim = to.simulate(M3, loads=np.column_stack([0 * fy, fy]))
    assert sim.status == "complete" and len(sim.snaps) == 2
    fig = plots.plot_simulation(sim, M3)
    ax = fig.axes[0]
    samples = _points(fig, "samples")
    assert np.allclose(samples[:, 0], sim.deflection[:, 1]) and np.allclose(samples[:, 1], sim.loads[:, 1])
    folds, lands = _points(fig, "snap-folds"), _points(fig, "snap-landings")
    for j, e in enumerate(sim.snaps):                 # horizontal: the load frozen during the snap
        assert folds[j].tolist() == pytest.approx([e.tip_before[1], e.load[1]])
        assert lands[j].tolist() == pytest.approx([e.tip_after[1], e.load[1]])
        fig.canvas.draw()
        box = gid(fig, f"snap-{j}").get_path().get_extents()     # the arrow as drawn (data coordinates)
        lo, hi = sorted((folds[j][0], lands[j][0]))
        assert lo - 1e-9 <= box.x0 and box.x1 <= hi + 1e-9 and box.width > 0.4 * (hi - lo)
        assert box.height < 0.05 * (ax.get_ylim()[1] - ax.get_ylim()[0])
    path = gid(fig, "path").get_xydata()
    assert np.isnan(path[:, 0]).sum() == 2           # broken once at each snap
    assert _points(fig, "start").tolist() == [samples[0].tolist()]
    assert _points(fig, "end").tolist() == [samples[-1].tolist()]
    assert _points(fig, "joint-limit").shape == (0, 2)
    assert "load $F_y$" in ax.get_ylabel() and "deflection $\\delta_y$ (length)" in ax.get_xlabel()
    assert "2 snap(s)" in ax.get_title() and "n = 3, a = 0.5" in ax.get_title()
    labels = legend_texts(fig, count=1)
    assert any(t.startswith("fold") for t in labels) and any("energy released" in t for t in labels)
    ids = check_renders(fig, tmp_path, "loop")
    assert {"path", "samples", "snap-0", "snap-1", "snap-folds", "snap-landings"} <= ids


@pytest.mark.slow
def test_simulation_figure_held_tip_preloads_and_the_joint_limit(tmp_path):
    from tensegrity_opt.analyses.equilibria.rest import rest_configuration

    r = rest_configuration(M3)
    d0 = np.array([M3.straight_length - r.tip[0], r.tip[1]])
    T = d0 + np.outer(np.linspace(0, 3.0, 16), [1.0, 1.0]) / np.sqrt(2)
    held = to.simulate(M3, tip="held", targets=T, start=r.q)
    assert held.status == "joint_limit" and len(held.snaps) == 1
    fig = plots.plot_simulation(held)
    e = held.snaps[0]
    c = int(np.argmax(np.ptp(T, axis=0)))
    assert _points(fig, "snap-folds")[0].tolist() == pytest.approx([e.target[c], e.force_before[c]])
    assert _points(fig, "snap-landings")[0].tolist() == pytest.approx([e.target[c], e.force_after[c]])   # vertical
    end = next(x for x in held.events if x.kind == "joint_limit")
    assert _points(fig, "joint-limit")[0].tolist() == pytest.approx([end.target[c], end.force_before[c]])
    assert "holding force" in fig.axes[0].get_ylabel()
    check_renders(fig, tmp_path, "held")

    m2 = to.Manipulator([to.Segment(0.5, 1.0, 1.0, 1.0), to.Segment(1.0, 1.0, 1.0, 1.0)])
    ds = np.concatenate([np.linspace(0, 0.45, 10), np.linspace(0.45, 0.0, 10)[1:]])
    P = np.array([[[1 + d, 1 - d], [1.0, 1.0]] for d in ds])
    pre = to.simulate(m2, preloads=P)
    assert len(pre.snaps) == 1
    fig = plots.plot_simulation(pre, m2)
    p = _points(fig, "samples")[:, 1]
    assert p == pytest.approx(np.sqrt(2) * ds)          # p = d . (L0 - L0(0)), d = (1, -1, 0, 0) / sqrt 2
    assert "preload parameter" in fig.axes[0].get_ylabel() and "d = (0.71, -0.71, 0, 0)" in fig.axes[0].get_title()
    check_renders(fig, tmp_path, "preloads")
    with pytest.raises(InvalidParameterError) as exc:
        plots.plot_simulation(pre, component=2)
    assert exc.value.field == "component"
    with pytest.raises(InvalidParameterError):
        plots.plot_simulation(held.to_dict())
