"""Figures of the loading paths: branch diagrams, limit loads, stability boundaries (the atlas figure is tested
with its command, ``tests/applications/cli/test_atlas_cli.py``).

Artists are found by their ``gid`` and their data compared with the library's numbers; every
figure renders to PNG and SVG (not compared pixel by pixel).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

pytest.importorskip("matplotlib")

from figures import check_renders, gid, gids, legend_texts, rows  # noqa: E402

import tensegrity_opt as to  # noqa: E402
from tensegrity_opt.analyses.paths.boundaries import BoundaryPoint, stability_boundary  # noqa: E402
from tensegrity_opt.applications import plots  # noqa: E402
from tensegrity_opt.errors import InvalidParameterError  # noqa: E402

PAPER = to.Manipulator.uniform(4, a=1.0, b=1.0, k=1.0, L0=1.0)
GUIDED_LOADS = (0.572793, 1.362906, 1.921444)           # docs/model.md


@pytest.fixture(scope="module")
def guided():
    return to.trace_branch(PAPER, np.zeros(4), "guided", t_max=2.0)


def test_branch_diagram_pieces_by_morse_index_and_branch_points(guided, tmp_path):
    fig = plots.plot_branches(guided, PAPER, x="t", y="fy")
    pieces = gids(fig, "branch-0-")
    assert pieces == [f"branch-0-morse{k}-{k}" for k in range(4)]
    for k in range(4):
        line = gid(fig, f"branch-0-morse{k}-{k}")
        assert line.get_linestyle() == ("-" if k == 0 else "--")
        assert line.get_color() == plots.MORSE_COLORS[k]
    # the pieces hold the branch's own points, and meet at the branch points
    xy = np.vstack([gid(fig, p).get_xydata() for p in pieces])
    for t, fy in zip(guided.t, guided.force[:, 1]):
        assert np.any(np.all(np.isclose(xy, [t, fy], rtol=0, atol=1e-15), axis=1))
    bp = gid(fig, "events-branch_point").get_xydata()
    assert bp[:, 0] == pytest.approx(GUIDED_LOADS, abs=1e-6)
    assert np.allclose(gid(fig, "branch-0-morse0-0").get_xydata()[-1], bp[0])
    assert np.allclose(gid(fig, "branch-0-morse1-1").get_xydata()[0], bp[0])
    ax = fig.axes[0]
    assert "stiffness × length" in ax.get_xlabel() and "load" in ax.get_xlabel()
    assert "$F_y$" in ax.get_ylabel() and "guide" in ax.get_ylabel()
    assert "n = 4, a = 1, b = 1, k = 1, L0 = 1" in ax.get_title() and "guided" in ax.get_title()
    texts = legend_texts(fig, beside=True, count=1)
    assert "stable (Morse index 0)" in texts and "unstable, Morse index 3" in texts
    assert "branch point (bifurcation) (3)" in texts
    check_renders(fig, tmp_path, "branch")


@pytest.mark.slow
def test_bifurcation_diagram_marks_each_event_kind_distinctly(tmp_path):
    bs = to.bifurcation_diagram(PAPER, np.zeros(4), "guided", t_max=2.0, t_min=-0.2, depth=1, max_points=120)
    fig = plots.plot_branches(bs, PAPER, x="q1", y="t")
    markers = {}
    for kind in ("fold", "branch_point", "joint_limit"):
        line = gid(fig, f"events-{kind}")
        want = [(e.q[0], e.t) for b in bs for e in b.events if e.kind == kind]
        assert len(want) > 0 and np.allclose(line.get_xydata(), want)
        markers[kind] = line.get_marker()
    assert len(set(markers.values())) == 3
    assert len({g.split("-morse")[0] for g in gids(fig, "branch-")}) == len(bs)
    ax = fig.axes[0]
    assert ax.get_xlabel() == "joint angle $q_{1}$ (rad)"
    assert f"{len(bs)} branches" in ax.get_title()
    legend_texts(fig, beside=True, count=1)
    check_renders(fig, tmp_path, "diagram")


@pytest.fixture(scope="module")
def diagram():
    """The guided straight chain's bifurcation diagram, traced far past its events (t to about 14)."""
    return to.bifurcation_diagram(PAPER, np.zeros(4), "guided", depth=1, max_points=200)


def _event_ts(branches) -> list[float]:
    return [e.t for b in branches for e in b.events]


def test_default_branch_figure_is_a_response_against_the_load_cut_past_the_events(diagram, tmp_path):
    fig = plots.plot_branches(diagram, PAPER)
    ax = fig.axes[0]
    xy = np.vstack([rows(gid(fig, g)) for g in gids(fig, "branch-")])
    # the end angle q1 + ... + qn against t: not an affine function of t (Fx = -t is, under this load)
    assert max(float(b.t.max()) for b in diagram) > 10.0
    fit = np.polyfit(xy[:, 0], xy[:, 1], 1)
    assert np.abs(xy[:, 1] - np.polyval(fit, xy[:, 0])).max() > 0.5
    drawn = np.vstack([rows(gid(fig, g)) for g in gids(fig, "branch-2-")])
    for t, phi in zip(diagram[2].t, diagram[2].q.sum(axis=1)):             # the library's numbers, unchanged
        assert np.any(np.all(np.isclose(drawn, [t, phi], rtol=0, atol=1e-15), axis=1))
    # the axis of t: the start and every event, a margin past them, not the whole trace
    last = max(_event_ts(diagram))                     # the span: from the start, t = 0, to the last event
    lo, hi = ax.get_xlim()
    assert last < hi <= last + 0.5 * last
    assert -0.5 * last <= lo < 0.0
    ylo, yhi = ax.get_ylim()
    ev = np.vstack([gid(fig, f"events-{k}").get_xydata() for k in ("fold", "branch_point", "joint_limit")])
    assert ylo < ev[:, 1].min() and ev[:, 1].max() < yhi and yhi - ylo < 4.0
    assert "end angle" in ax.get_ylabel() and ax.get_ylabel().endswith("(rad)")
    assert ax.get_xlabel().endswith("(force, stiffness × length)")
    # whatever the axes, the window in t: Fx against dx (Fig. 6's axes) shows Fx down to about -1.25 last, not -14
    f6 = plots.plot_branches(diagram, PAPER, x="dx", y="fx").axes[0]
    assert -1.5 * last <= f6.get_ylim()[0] < -last and f6.get_xlim()[1] > 3.0
    # the full trace is one keyword away, and every quantity still an option
    full = plots.plot_branches(diagram, PAPER, y="fx", crop=None).axes[0]
    assert full.get_xlim()[1] > 10.0
    check_renders(fig, tmp_path, "default")


def test_one_trivial_branch_says_its_response_is_constant():
    br = to.trace_branch(PAPER, np.zeros(4), "guided", max_points=200)
    assert br.t[-1] > 10.0
    fig = plots.plot_branches(br, PAPER)
    lo, hi = fig.axes[0].get_xlim()
    last = max(_event_ts([br]))
    assert last < hi <= 1.5 * last and lo <= 0.0
    assert "= 0 all along this branch" in gid(fig, "constant-note").get_text()
    assert "depth 1" in gid(fig, "constant-note").get_text()           # and how to draw the branches leaving it
    with pytest.raises(InvalidParameterError) as e:
        plots.plot_branches(br, PAPER, crop=-1.0)
    assert e.value.field == "crop"


def test_branch_quantities_and_refusals(guided):
    for name in ("fx", "dx", "dy", "x", "y", "u", "phi", "energy", "s", "q4"):
        fig = plots.plot_branches(guided, PAPER, x=name, y="t")
        assert gids(fig, "branch-0-")
    fig = plots.plot_branches([guided], PAPER, x="u", y="fx")
    xy = np.vstack([gid(fig, p).get_xydata() for p in gids(fig, "branch-0-")])
    u = (guided.tip - guided.tip[0]) @ guided.control.direction
    assert np.allclose(np.sort(np.unique(xy[:, 0])).min(), u.min()) and np.isclose(xy[:, 0].max(), u.max())
    disp = to.trace_branch(PAPER, to.solve_equilibrium(PAPER, 0.1), "displacement", t_max=0.3, max_points=40)
    assert "length" in plots.plot_branches(disp, PAPER, x="t", y="energy").axes[0].get_xlabel()
    for kw, field in (({"x": "q5"}, "x"), ({"y": "nope"}, "y"), ({"x": 3}, "x")):
        with pytest.raises(InvalidParameterError) as e:
            plots.plot_branches(guided, PAPER, **kw)
        assert e.value.field == field
    with pytest.raises(InvalidParameterError) as e:
        plots.plot_branches([], PAPER)
    assert e.value.field == "branches"
    with pytest.raises(InvalidParameterError) as e:
        plots.plot_branches([guided, "x"], PAPER)
    assert e.value.field == "branches[1]"


@pytest.mark.slow
def test_limit_load_marks_the_bifurcation_of_the_straight_chain(tmp_path):
    res = to.limit_load(PAPER, (-1.0, 0.0), "guided", start=np.zeros(4))
    fig = plots.plot_limit_load(res, PAPER)
    pt = gid(fig, "limit-point").get_xydata()
    assert pt[0, 1] == pytest.approx(GUIDED_LOADS[0], abs=1e-6) and pt[0, 0] == pytest.approx(0.0, abs=1e-9)
    assert gid(fig, "path-morse0-0").get_xydata()[-1] == pytest.approx(pt[0])
    ax = fig.axes[0]
    assert "(length)" in ax.get_xlabel() and "stiffness × length" in ax.get_ylabel()
    assert "bifurcation at P = 0.572793" in ax.get_title() and "n = 4" in ax.get_title()
    assert any("limit load P = 0.572793" in t for t in legend_texts(fig, beside=True, count=1))
    check_renders(fig, tmp_path, "limit")


def test_limit_load_of_a_pre_bent_chain_marks_the_quasi_buckling_load(tmp_path):
    m = to.Manipulator([to.Segment(1.0, 1.0, 1.0, (1.0, 1.02))] + [to.Segment(1.0, 1.0, 1.0, 1.0)] * 3)
    rest = to.solve_equilibrium_under_force(m, 0.0, 0.0)
    res = to.limit_load(m, (-1.0, 0.0), "free", max_load=0.2, start=rest.q)
    assert res.kind == "none" and res.quasi_buckling_load is not None
    fig = plots.plot_limit_load(res, m)
    assert gid(fig, "quasi-buckling").get_xydata()[0, 1] == pytest.approx(res.quasi_buckling_load)
    assert gid(fig, "quasi-buckling-level").get_ydata()[0] == pytest.approx(res.quasi_buckling_load)
    end = gid(fig, "path-end").get_xydata()[0]
    assert end[1] == pytest.approx(res.branch.t[-1])
    assert "L0 = 1..1.02" in fig.axes[0].get_title()
    check_renders(fig, tmp_path, "quasi")
    with pytest.raises(InvalidParameterError):
        plots.plot_limit_load(res.branch, m)


FREE_LOAD = 0.0761205                                   # the paper's chain, free tip: conventions.md


def _xt(fig, prefix):
    """The ``(x, t)`` points of the pieces whose gid starts with ``prefix``, in drawing order."""
    return np.vstack([gid(fig, g).get_xydata() for g in gids(fig, prefix)])


@pytest.fixture(scope="module")
def free_limit():
    res = to.limit_load(PAPER)
    return res, to.limit_arms(res)


def test_limit_load_draws_the_buckled_arms_leaving_the_bifurcation(free_limit, tmp_path):
    res, arms = free_limit
    assert res.kind == "bifurcation" and res.load == pytest.approx(FREE_LOAD, abs=1e-6)
    assert len(arms) == 2 and all(a.events and a.events[0].kind == "joint_limit" for a in arms)
    assert (arms[0].q[1] - arms[0].q[0]) @ res.null_vector > 0            # the arm along the mode first
    fig = plots.plot_limit_load(res, PAPER, arms=arms)
    a0, a1 = _xt(fig, "arm-0-"), _xt(fig, "arm-1-")
    for a in (a0, a1):
        assert np.ptp(a[:, 0]) > 1.0                    # the response moves on the arms (phi_n, rad)
        assert a[0] == pytest.approx([0.0, FREE_LOAD], abs=1e-6)       # each starts at the limit point
        assert a[:, 1].max() > 2 * FREE_LOAD            # supercritical: the arms carry more load as they bend
    assert a1[:, 0] == pytest.approx(-a0[:, 0], abs=1e-9) and a1[:, 1] == pytest.approx(a0[:, 1], abs=1e-9)
    assert np.sign(a0[-1, 0]) == -np.sign(a1[-1, 0])
    assert gid(fig, "limit-point").get_xydata()[0] == pytest.approx([0.0, FREE_LOAD], abs=1e-6)
    ends = gid(fig, "arm-ends-joint_limit").get_xydata()
    assert sorted(ends[:, 0]) == pytest.approx(sorted([a0[-1, 0], a1[-1, 0]]))
    ax = fig.axes[0]
    assert ax.get_xlabel() == plots.branch_quantity_label(plots.LIMIT_ARMS_X)
    assert "no-displacement-note" not in gids(fig, "no-")
    assert "buckled arms" in ax.get_title()
    end = f"{arms[0].events[0].t:.4g}"                 # the arm's end the label names (both arms: mirror images)
    assert arms[1].events[0].t == pytest.approx(arms[0].events[0].t, rel=1e-9)
    assert any(t.startswith(f"arm's end: joint limit at t = {end}") for t in legend_texts(fig, beside=True, count=1))
    check_renders(fig, tmp_path, "arms")


def test_a_buckled_arm_is_in_equilibrium_by_finite_differences(free_limit):
    import reference_model as R

    arm = free_limit[1][0]
    i = len(arm) // 2
    q, F = arm.q[i], arm.force[i]
    assert F == pytest.approx([-arm.t[i], 0.0], abs=1e-12) and abs(q.sum()) > 0.3
    chain = R.Chain.uniform(4, 1.0, 1.0, 1.0, 1.0)

    def work(x):                                        # energy minus the dead load's work
        return chain.energy(x) - F @ chain.tip(x)

    h = 1e-6
    grad = np.array([(work(q + h * e) - work(q - h * e)) / (2 * h) for e in np.eye(4)])
    assert np.abs(grad).max() < 1e-7
    assert free_limit[1][1].q[i] == pytest.approx(-q, abs=1e-9)      # its mirror image


def test_limit_load_without_arms_draws_the_path_only(free_limit):
    res, _ = free_limit
    fig = plots.plot_limit_load(res, PAPER)
    assert not gids(fig, "arm-") and gids(fig, "path-")
    assert "tip displacement along the load" in fig.axes[0].get_xlabel()
    assert gid(fig, "no-displacement-note")            # the straight path: u = 0 all along
    assert "buckled" not in fig.axes[0].get_title()


def test_limit_load_of_a_fold_has_no_arms_and_keeps_its_figure():
    m = to.Manipulator([to.Segment(1, 1, 1, (1.02, 0.98))] * 4)         # pre-bent
    res = to.limit_load(m, (-1.0, 0.0), "guided")
    assert res.kind == "fold" and res.load == pytest.approx(0.553664, abs=1e-6)     # docs/paths.md
    assert to.limit_arms(res) == []
    fig, plain = plots.plot_limit_load(res, m, arms=to.limit_arms(res)), plots.plot_limit_load(res, m)
    drawn = [g for p in ("path-", "limit-", "quasi-", "no-", "arm-") for g in gids(fig, p)]
    assert drawn == [g for p in ("path-", "limit-", "quasi-", "no-", "arm-") for g in gids(plain, p)]
    assert "limit-point" in drawn and not gids(fig, "arm-")
    path = _xt(fig, "path-")
    assert path == pytest.approx(_xt(plain, "path-")) and np.ptp(path[:, 0]) > 1e-3     # the path itself moves
    assert fig.axes[0].get_xlabel() == plain.axes[0].get_xlabel()
    assert "tip displacement along the load" in fig.axes[0].get_xlabel()
    with pytest.raises(InvalidParameterError) as e:
        plots.plot_limit_load(res, m, arms=[res.branch, "x"])
    assert e.value.field == "arms[1]"


@pytest.fixture(scope="module")
def boundary():
    return stability_boundary(PAPER, "guided", "asymmetry", p_min=-0.02, p_max=0.02, max_points=60)


def test_boundary_plots_t_against_p_with_the_cusps(boundary, tmp_path):
    cusp = BoundaryPoint("cusp", float(boundary.p[3]), float(boundary.t[3]), boundary.q[3], boundary.force[3])
    b = dataclasses.replace(boundary, cusps=[cusp])
    fig = plots.plot_boundary(b, PAPER, control="guided")
    ok = np.isfinite(np.asarray(b.p, float)) & np.isfinite(np.asarray(b.t, float))
    assert ok.sum() >= 10
    assert np.allclose(gid(fig, "boundary").get_xydata()[ok], np.column_stack([b.p, b.t])[ok])
    assert np.allclose(gid(fig, "cusps").get_xydata(), [[b.p[3], b.t[3]]])
    ax = fig.axes[0]
    assert "asymmetry" in ax.get_xlabel() and "stiffness × length" in ax.get_ylabel()
    assert str(b.kind) in ax.get_title() and "n = 4" in ax.get_title() and "incomplete" not in ax.get_title()
    assert "cusp (1)" in legend_texts(fig, beside=True, count=1)
    check_renders(fig, tmp_path, "boundary")
    assert "n = 4" not in plots.plot_boundary(boundary).axes[0].get_title()      # without the chain
    with pytest.raises(InvalidParameterError) as e:
        plots.plot_boundary(boundary.to_dict(), PAPER)
    assert e.value.field == "boundary"


def _inside_figure(fig, artist) -> bool:
    box = artist.get_window_extent(fig.canvas.get_renderer())
    return fig.bbox.x0 <= box.x0 and box.x1 <= fig.bbox.x1 and fig.bbox.y0 <= box.y0 and box.y1 <= fig.bbox.y1


@pytest.mark.parametrize("control", [None, "guided"])
def test_boundary_title_is_whole_and_every_axis_has_a_unit(boundary, control):
    fig = plots.plot_boundary(boundary, PAPER, control=control)
    fig.canvas.draw()
    ax = fig.axes[0]
    assert "guided tip (y held), load along (-1, 0)" in ax.get_title()
    assert _inside_figure(fig, ax.title)
    assert all(_inside_figure(fig, t) for t in fig.legends[0].get_texts())
    assert ax.get_xlabel().startswith("preload asymmetry $p$") and ax.get_xlabel().endswith("(length)")
    assert ax.get_ylabel().endswith("(force, stiffness × length)")
    assert plots.boundary_parameter_label("k").endswith("(stiffness)")


def test_an_incomplete_boundary_says_so(boundary):
    b = dataclasses.replace(boundary, status="time_limit")
    assert not b.success
    assert "incomplete: time_limit" in plots.plot_boundary(b, PAPER).axes[0].get_title()


def test_imperfection_curve_marks_each_kind_the_perfect_load_and_the_law(tmp_path):
    """Two segments a = 1.5 under the guided load: the perfect chain's bifurcation at 35/6 as the line, the folds
    of the imperfect chains as markers on their loads, the fitted 2/3-power law dashed through them."""
    m = to.Manipulator.uniform(2, a=1.5, b=1.0, k=1.0, L0=1.0)
    res = to.imperfection_sensitivity(m, [0.0, 3e-4, 1e-3, 3e-3, -1e-3])
    fig = plots.plot_imperfection(res, m)
    assert gid(fig, "perfect-load").get_ydata()[0] == pytest.approx(35.0 / 6.0, rel=1e-9)
    folds = gid(fig, "kind-fold").get_xydata()
    assert sorted(map(tuple, folds)) == sorted(zip(res.amplitudes[1:], res.loads[1:]))
    assert gid(fig, "kind-bifurcation").get_xydata()[0] == pytest.approx([0.0, 35.0 / 6.0])
    law = gid(fig, "law")
    assert law.get_linestyle() == "--"
    x, y = law.get_xdata(), law.get_ydata()
    assert np.all(x >= 0) and y[0] == pytest.approx(35.0 / 6.0)
    assert np.interp(3e-3, x, y) == pytest.approx(res.loads[3], rel=2e-3)        # the law through the folds
    assert "unstable-symmetric" in " ".join(legend_texts(fig, beside=True, count=1))
    free = to.imperfection_sensitivity(PAPER, [0.0, 0.01], boundary="free", max_load=0.2)
    fig2 = plots.plot_imperfection(free, PAPER)
    assert "law" not in gids(fig2, "law") and gid(fig2, "kind-none").get_xydata()[0, 0] == pytest.approx(0.01)
    check_renders(fig, tmp_path, "imperfection")
    with pytest.raises(InvalidParameterError):
        plots.plot_imperfection(to.limit_load(m, (-1.0, 0.0), "guided"), m)
