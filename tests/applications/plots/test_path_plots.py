"""Figures of the loading paths: branch diagrams, limit loads, stability boundaries.

Artists are found by their ``gid`` and their data compared with the library's numbers; every
figure renders to PNG and SVG (not compared pixel by pixel).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from types import SimpleNamespace

import numpy as np
import pytest

pytest.importorskip("matplotlib")

import tensegrity_opt as to
from tensegrity_opt.applications import plots
from tensegrity_opt.errors import InvalidParameterError

PAPER = to.Manipulator.uniform(4, a=1.0, b=1.0, k=1.0, L0=1.0)
GUIDED_LOADS = (0.572793, 1.362906, 1.921444)           # conventions.md


def gid(fig, name):
    found = fig.findobj(lambda a: a.get_gid() == name)
    assert len(found) == 1, (name, len(found))
    return found[0]


def gids(fig, prefix):
    return sorted({a.get_gid() for a in fig.findobj(lambda a: str(a.get_gid() or "").startswith(prefix))})


def check_renders(fig, tmp_path, name):
    png = plots.save(fig, tmp_path / f"{name}.png", dpi=50)
    svg = plots.save(fig, tmp_path / f"{name}.svg")
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert ET.fromstring(svg.read_bytes()).tag == "{http://www.w3.org/2000/svg}svg"


def legend_clear_of_axes(fig):
    """The legend is the figure's, beside the axes: its box does not meet the axes' box."""
    ax = fig.axes[0]
    assert ax.get_legend() is None and len(fig.legends) == 1
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    lb, ab = fig.legends[0].get_window_extent(r), ax.get_window_extent(r)
    assert lb.x0 >= ab.x1 - 1e-6, (lb, ab)
    return [t.get_text() for t in fig.legends[0].get_texts()]


@pytest.fixture(scope="module")
def guided():
    return to.trace_branch(PAPER, np.zeros(4), "guided", t_max=2.0)


def test_branch_diagram_pieces_by_morse_index_and_branch_points(guided, tmp_path):
    fig = plots.plot_branches(guided, x="t", y="fy")
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
    texts = legend_clear_of_axes(fig)
    assert "stable (Morse index 0)" in texts and "unstable, Morse index 3" in texts
    assert "branch point (bifurcation) (3)" in texts
    check_renders(fig, tmp_path, "branch")


def test_bifurcation_diagram_marks_each_event_kind_distinctly(tmp_path):
    bs = to.bifurcation_diagram(PAPER, np.zeros(4), "guided", t_max=2.0, t_min=-0.2, depth=1, max_points=120)
    fig = plots.plot_branches(bs, x="q1", y="t")
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
    legend_clear_of_axes(fig)
    check_renders(fig, tmp_path, "diagram")


def test_branch_quantities_and_refusals(guided):
    for name in ("fx", "dx", "dy", "x", "y", "u", "energy", "s", "q4"):
        fig = plots.plot_branches(guided, x=name, y="t")
        assert gids(fig, "branch-0-")
    fig = plots.plot_branches([guided], x="u", y="fx")
    xy = np.vstack([gid(fig, p).get_xydata() for p in gids(fig, "branch-0-")])
    u = (guided.tip - guided.tip[0]) @ guided.control.direction
    assert np.allclose(np.sort(np.unique(xy[:, 0])).min(), u.min()) and np.isclose(xy[:, 0].max(), u.max())
    disp = to.trace_branch(PAPER, to.solve_equilibrium(PAPER, 0.1), "displacement", t_max=0.3, max_points=40)
    assert "length" in plots.plot_branches(disp, x="t", y="energy").axes[0].get_xlabel()
    for kw, field in (({"x": "q5"}, "x"), ({"y": "nope"}, "y"), ({"x": 3}, "x")):
        with pytest.raises(InvalidParameterError) as e:
            plots.plot_branches(guided, **kw)
        assert e.value.field == field
    with pytest.raises(InvalidParameterError) as e:
        plots.plot_branches([])
    assert e.value.field == "branches"
    with pytest.raises(InvalidParameterError) as e:
        plots.plot_branches([guided, "x"])
    assert e.value.field == "branches[1]"


def test_limit_load_marks_the_bifurcation_of_the_straight_chain(tmp_path):
    res = to.limit_load(PAPER, (-1.0, 0.0), "guided", start=np.zeros(4))
    fig = plots.plot_limit_load(res)
    pt = gid(fig, "limit-point").get_xydata()
    assert pt[0, 1] == pytest.approx(GUIDED_LOADS[0], abs=1e-6) and pt[0, 0] == pytest.approx(0.0, abs=1e-9)
    assert gid(fig, "path-morse0-0").get_xydata()[-1] == pytest.approx(pt[0])
    ax = fig.axes[0]
    assert "(length)" in ax.get_xlabel() and "stiffness × length" in ax.get_ylabel()
    assert "bifurcation at P = 0.572793" in ax.get_title() and "n = 4" in ax.get_title()
    assert any("limit load P = 0.572793" in t for t in legend_clear_of_axes(fig))
    check_renders(fig, tmp_path, "limit")


def test_limit_load_of_a_pre_bent_chain_marks_the_quasi_buckling_load(tmp_path):
    m = to.Manipulator([to.Segment(1.0, 1.0, 1.0, (1.0, 1.02))] + [to.Segment(1.0, 1.0, 1.0, 1.0)] * 3)
    rest = to.solve_equilibrium_under_force(m, 0.0, 0.0)
    res = to.limit_load(m, (-1.0, 0.0), "free", max_load=0.2, start=rest.q)
    assert res.kind == "none" and res.quasi_buckling_load is not None
    fig = plots.plot_limit_load(res)
    assert gid(fig, "quasi-buckling").get_xydata()[0, 1] == pytest.approx(res.quasi_buckling_load)
    assert gid(fig, "quasi-buckling-level").get_ydata()[0] == pytest.approx(res.quasi_buckling_load)
    end = gid(fig, "path-end").get_xydata()[0]
    assert end[1] == pytest.approx(res.branch.t[-1])
    assert "L0 = 1..1.02" in fig.axes[0].get_title()
    check_renders(fig, tmp_path, "quasi")
    with pytest.raises(InvalidParameterError):
        plots.plot_limit_load(res.branch)


def fake_boundary():
    p = np.linspace(-0.1, 0.1, 21)
    t = GUIDED_LOADS[0] - 2.0 * np.abs(p) ** (2 / 3)
    cusp = SimpleNamespace(p=0.0, t=GUIDED_LOADS[0], q=np.zeros(4))
    return SimpleNamespace(kind="fold", parameter="asymmetry", p=p, t=t, q=np.zeros((p.size, 4)),
                           force=np.zeros((p.size, 2)), cusps=[cusp], status="p_max", success=True)


def test_boundary_plots_t_against_p_with_the_cusps(tmp_path):
    b = fake_boundary()
    fig = plots.plot_boundary(b, m=PAPER, control="guided")
    assert np.allclose(gid(fig, "boundary").get_xydata(), np.column_stack([b.p, b.t]))
    assert np.allclose(gid(fig, "cusps").get_xydata(), [[0.0, GUIDED_LOADS[0]]])
    ax = fig.axes[0]
    assert "asymmetry" in ax.get_xlabel() and "stiffness × length" in ax.get_ylabel()
    assert "fold" in ax.get_title() and "n = 4" in ax.get_title()
    assert "cusp (1)" in legend_clear_of_axes(fig)
    check_renders(fig, tmp_path, "boundary")
    b.success, b.status = False, "time_limit"
    assert "incomplete: time_limit" in plots.plot_boundary(b).axes[0].get_title()
    with pytest.raises(InvalidParameterError):
        plots.plot_boundary(SimpleNamespace(kind="fold"))


def test_boundary_plot_of_the_library_boundary(tmp_path):
    """Runs once analyses/boundaries.py is merged (skipped before)."""
    boundaries = pytest.importorskip("tensegrity_opt.analyses.paths.boundaries")
    pytest.importorskip("tensegrity_opt.analyses.equilibria.rest")
    b = boundaries.stability_boundary(PAPER, "guided", "asymmetry", p_min=-0.02, p_max=0.02, max_points=60)
    fig = plots.plot_boundary(b, m=PAPER, control="guided")
    ok = np.isfinite(np.asarray(b.p, float)) & np.isfinite(np.asarray(b.t, float))
    assert np.allclose(gid(fig, "boundary").get_xydata()[ok], np.column_stack([b.p, b.t])[ok])
    check_renders(fig, tmp_path, "library_boundary")
