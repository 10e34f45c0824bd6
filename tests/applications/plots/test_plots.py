"""Figures: every figure renders to PNG and SVG, and the plotted data are the library's numbers.

The data are read back from the matplotlib artists (lines, polygons, scatter offsets, meshes,
contour levels) and compared with the library's outputs computed here independently. Then the
``plot`` command (argparse) and the ``/v1/plots/*`` routes (TestClient).
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import warnings
import xml.etree.ElementTree as ET
from collections import Counter
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("matplotlib")

from matplotlib.colors import to_rgba

import tensegrity_opt as to
from tensegrity_opt.applications import plots
from tensegrity_opt.errors import InvalidParameterError, UnreachableTargetError, UnsupportedError
from tensegrity_opt.analyses.equilibria.landscape import complete_configuration

ROOT = Path(__file__).resolve().parents[3]
PAPER = to.Manipulator.uniform(4, a=1.0, b=1.0, k=1.0, L0=1.0)
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
SVG_TAG = "{http://www.w3.org/2000/svg}svg"


# ---------------------------------------------------------------------------- helpers
def check_png(data: bytes) -> None:
    assert data[:8] == PNG_MAGIC


def check_svg(data: bytes) -> None:
    assert ET.fromstring(data).tag == SVG_TAG


def check_renders(fig, tmp_path: Path, name: str) -> None:
    """``save`` writes a PNG and an SVG by suffix; ``render`` gives the same kinds of bytes."""
    png = plots.save(fig, tmp_path / f"{name}.png", dpi=60)
    svg = plots.save(fig, tmp_path / f"{name}.svg")
    check_png(png.read_bytes())
    check_svg(svg.read_bytes())
    check_png(plots.render(fig, "png", dpi=40))


def gid(fig, name: str):
    found = fig.findobj(lambda a: a.get_gid() == name)
    assert len(found) == 1, (name, len(found))
    return found[0]


def maybe_gid(container, name: str):
    found = container.findobj(lambda a: a.get_gid() == name)
    return found[0] if found else None


def rows(line) -> np.ndarray:
    """The (x, y) rows of a Line2D without its NaN separators."""
    xy = np.asarray(line.get_xydata(), dtype=float)
    return xy[np.all(np.isfinite(xy), axis=1)]


def nan_equal(a, b, rtol=0.0, atol=0.0) -> bool:
    a = np.ma.filled(np.ma.asarray(a, dtype=float), np.nan)
    b = np.asarray(b, dtype=float)
    return a.shape == b.shape and np.allclose(a, b, rtol=rtol, atol=atol, equal_nan=True) and bool(
        np.all(np.isnan(a) == np.isnan(b)))


@pytest.fixture(scope="module")
def equilibria():
    return to.find_equilibria(PAPER, 0.1, 0.0)


# ---------------------------------------------------------------------------- geometry
def test_chain_geometry_reproduces_spring_lengths_and_tip():
    rng = np.random.default_rng(3)
    m = to.Manipulator([to.Segment(0.6, 1.0, 1.0, 1.5), to.Segment(1.2, 0.7, (1.0, 2.0), (1.0, 1.3)),
                        to.Segment(0.9, 1.4, 2.0, 2.5), to.Segment(0.5, 0.5, 1.0, 1.0), to.Segment(1.0, 1.0)])
    for q in [np.zeros(m.n), *(rng.uniform(-0.95, 0.95, m.n) * m.joint_limits for _ in range(20))]:
        g = plots.chain_geometry(m, q)
        L1, L2 = m.spring_lengths(q)
        d = np.linalg.norm(g["springs"][:, :, 1] - g["springs"][:, :, 0], axis=-1)
        assert np.allclose(d[:, 0], L1, rtol=1e-12, atol=1e-12)
        assert np.allclose(d[:, 1], L2, rtol=1e-12, atol=1e-12)
        assert np.allclose(g["centerline"][-1], m.tip(q), atol=1e-12)
        assert np.allclose(g["tip"], m.tip(q), atol=1e-12)
        assert np.allclose(g["joints"][0], [m.base_length, 0.0])
        assert np.allclose(np.linalg.norm(np.diff(g["joints"], axis=0), axis=1), m.link_lengths[:-1])
        # each triangle: apex at the joint, base corners at distance c = hypot(a, b), base length 2a
        tri = g["triangles"]
        assert np.allclose(tri[:, :, 0], g["joints"][:, None, :])
        c = np.hypot(m.a, m.b)
        for corner in (1, 2):
            assert np.allclose(np.linalg.norm(tri[:, :, corner] - tri[:, :, 0], axis=-1), c[:, None])
        assert np.allclose(np.linalg.norm(tri[:, :, 1] - tri[:, :, 2], axis=-1), 2 * m.a[:, None])
        # springs join the triangles' corners (spring 1: left corners, spring 2: right corners)
        assert np.allclose(g["springs"][:, 0, 0], tri[:, 0, 1]) and np.allclose(g["springs"][:, 0, 1], tri[:, 1, 1])
        assert np.allclose(g["springs"][:, 1, 0], tri[:, 0, 2]) and np.allclose(g["springs"][:, 1, 1], tri[:, 1, 2])
    straight = plots.chain_geometry(m, np.zeros(m.n))
    assert np.allclose(straight["tip"], [m.straight_length, 0.0])
    with pytest.raises(InvalidParameterError):
        plots.chain_geometry(m, np.zeros(3))


# ---------------------------------------------------------------------------- force-deflection
def test_curve_plots_the_force_deflection_numbers(tmp_path):
    dx = np.linspace(0.0, 1.0, 11)
    fig = plots.plot_curve(PAPER, dx)
    c = to.force_deflection(PAPER, dx)
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
    fig = plots.plot_curve(PAPER, dx, dy)
    c = to.force_deflection(PAPER, dx, dy)
    switches = [(k, j) for k, j in enumerate(c.jumps) if j.kind in ("branch_switch", "snap", "switch")]
    assert len(switches) == 1
    k, j = switches[0]
    kind = plots.jump_kind(j)
    assert kind in ("snap", "switch")              # the former "branch_switch" is drawn as a snap
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
    fig = plots.plot_curve(PAPER, dx, branch="all")
    c = to.force_deflection(PAPER, dx, branch="all")
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
    check_renders(fig, tmp_path, "curve_all")


# ---------------------------------------------------------------------------- landscape
def test_landscape_energy_and_equilibria(tmp_path, equilibria):
    fig = plots.plot_landscape(PAPER, 0.1, 0.0, pair=(0, 3), grid=41, span=None)
    land = to.energy_landscape(PAPER, 0.1, 0.0, pair=(0, 3), grid=41)
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
    check_renders(fig, tmp_path, "landscape")


def test_landscape_auto_span_covers_the_reachable_region():
    span = plots.landscape_span(PAPER, 0.1, 0.0, (0, 3))
    fig = plots.plot_landscape(PAPER, 0.1, 0.0, grid=31)          # span="auto"
    land = to.energy_landscape(PAPER, 0.1, 0.0, pair=(0, 3), grid=31, span=span)
    assert nan_equal(gid(fig, "energy-elbow+1").get_array(), land.energy[0].T)
    assert nan_equal(gid(fig, "energy-elbow-1").get_array(), land.energy[1].T)
    full = to.energy_landscape(PAPER, 0.1, 0.0, pair=(0, 3), grid=201)
    QI, QJ = np.meshgrid(full.qi, full.qj, indexing="ij")
    ok = np.isfinite(full.energy).any(axis=0)
    assert span < 0.5 * full.qi.max()
    assert np.all(np.abs(QI[ok]) <= span) and np.all(np.abs(QJ[ok]) <= span)


def test_landscape_refusals():
    with pytest.raises(UnsupportedError):
        plots.plot_landscape(to.Manipulator.uniform(5), 0.1)
    with pytest.raises(UnreachableTargetError):
        plots.plot_landscape(PAPER, 20.0)


# ---------------------------------------------------------------------------- shapes
def test_shapes_draw_every_equilibrium(tmp_path, equilibria):
    fig = plots.plot_shapes(PAPER, 0.1, 0.0)
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
    check_renders(fig, tmp_path, "shapes")


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


# ---------------------------------------------------------------------------- critical-load map
def test_map_is_the_critical_load_blank_where_it_raises(tmp_path):
    xs, ys = [0.4, 0.7, 1.0, 1.3], [0.5, 1.0, 1.5, 2.0, 2.5]
    fig = plots.plot_map(PAPER, "a", xs, "L0", ys)
    expected = np.full((len(ys), len(xs)), np.nan)
    for iy, L0 in enumerate(ys):
        for ix, a in enumerate(xs):
            try:
                expected[iy, ix] = -to.critical_force(to.Manipulator.uniform(4, a=a, b=1.0, k=1.0, L0=L0)).force
            except to.TensegrityError:
                pass
    assert np.isnan(expected).sum() >= 2 and np.isfinite(expected).sum() >= 10
    mesh = gid(fig, "critical-load")
    assert nan_equal(mesh.get_array(), expected, rtol=1e-13)
    assert expected[1, 2] == pytest.approx(0.572793, abs=1e-6)      # the paper's chain
    # mesh cells are centred on the grid values
    coords = mesh.get_coordinates()
    centres = 0.25 * (coords[:-1, :-1] + coords[1:, :-1] + coords[:-1, 1:] + coords[1:, 1:])
    assert np.allclose(centres[0, :, 0], xs) and np.allclose(centres[:, 0, 1], ys)
    assert np.allclose(gid(fig, "design").get_xydata(), [[1.0, 1.0]])
    fig2 = plots.plot_map(PAPER, "k", [0.5, 2.0], "b", [1.0, 0.8], boundary="free")
    got = np.ma.filled(gid(fig2, "critical-load").get_array(), np.nan)
    assert got[1, 1] == pytest.approx(-to.critical_force(to.Manipulator.uniform(4, b=0.8, k=2.0), "free").force,
                                      rel=1e-13)
    check_renders(fig, tmp_path, "map")
    with pytest.raises(InvalidParameterError, match="differ"):
        plots.plot_map(PAPER, "a", xs, "a", ys)
    with pytest.raises(InvalidParameterError) as ei:
        plots.plot_map(PAPER, "a", [1.0, 0.5, 2.0], "L0", ys)
    assert ei.value.field == "values_x"
    with pytest.raises(InvalidParameterError):
        plots.plot_map(PAPER, "c", xs, "L0", ys)


def test_save_chooses_the_format_by_suffix(tmp_path):
    fig = plots.plot_torque(to.Segment(1.0, 1.0), num=11)
    with pytest.raises(InvalidParameterError):
        plots.save(fig, tmp_path / "fig.pdf")
    with pytest.raises(InvalidParameterError):
        plots.render(fig, "jpg")
    check_png(plots.save(fig, tmp_path / "FIG.PNG").read_bytes())


def test_library_imports_without_matplotlib(tmp_path):
    code = ("import sys; sys.modules['matplotlib'] = None\n"
            "import numpy as np, tensegrity_opt as to, tensegrity_opt.applications.plots as p, tensegrity_opt.applications.cli.plot\n"
            "m = to.Manipulator.uniform(4)\n"
            "assert np.allclose(p.chain_geometry(m, np.zeros(4))['tip'], [8, 0])\n"
            "try:\n    p.plot_torque(to.Segment(1, 1))\nexcept ImportError as e:\n    print('ImportError', e)\n"
            "assert tensegrity_opt.applications.cli.plot.main(['torque', '-o', 'x.png']) == 2\n")
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")])}
    out = subprocess.run([sys.executable, "-c", code], check=False, capture_output=True, text=True, cwd=tmp_path,
                         env=env, timeout=120)
    assert out.returncode == 0, out.stderr
    assert "ImportError" in out.stdout and "matplotlib" in out.stdout
    assert "figures need matplotlib" in out.stderr


# ---------------------------------------------------------------------------- command line
def _parser() -> argparse.ArgumentParser:
    from tensegrity_opt.applications.cli.plot import add_plot_parser

    p = argparse.ArgumentParser(prog="tensegrity-opt")
    sub = p.add_subparsers(dest="command", required=True)
    add_plot_parser(sub)
    return p


def _run(argv: list[str]):
    from tensegrity_opt.applications.cli.common import _manipulator

    args = _parser().parse_args(argv)
    return args.func(args, _manipulator(args))


@pytest.mark.parametrize("argv", [
    ["plot", "curve", "--start", "0", "--stop", "0.5", "--num", "6"],
    ["plot", "landscape", "--dx", "0.1", "--grid", "31"],
    ["plot", "shapes", "--dx", "0.1", "--n", "3"],
    ["plot", "torque", "--vary", "L0", "--values", "0.5", "1", "1.5", "--num", "51"],
    ["plot", "map", "--x", "a", "0.5", "1.5", "5", "--y", "L0", "0.5", "2", "4"],
], ids=lambda argv: argv[1])
def test_cli_writes_png_and_svg(tmp_path, argv):
    kind = argv[1]
    for fmt, check in (("png", check_png), ("svg", check_svg)):
        out = tmp_path / f"{kind}.{fmt}"
        data, text = _run([*argv, "-o", str(out), "--dpi", "50"])
        check(out.read_bytes())
        assert data["kind"] == kind and data["format"] == fmt and data["output"] == str(out)
        assert text.startswith(f"wrote {out}")
        json.dumps(data)


def test_cli_options_and_errors(tmp_path, capsys):
    from tensegrity_opt.applications.cli import plot as plot_cli

    data, _ = _run(["plot", "curve", "--num", "3", "--stop", "0.2", "--branch", "all", "-o", str(tmp_path / "c.png")])
    assert data["branches"] == 6 and data["jumps"] == ["buckling"]
    data, _ = _run(["plot", "map", "--x", "k", "0.5", "2", "3", "--y", "b", "0.8", "1.2", "3", "--boundary", "free",
                    "-o", str(tmp_path / "m.svg")])
    assert data["x"] == {"param": "k", "values": [0.5, 1.25, 2.0]} and data["boundary"] == "free"
    with pytest.raises(SystemExit):                                 # the suffix is checked by argparse
        _parser().parse_args(["plot", "curve", "-o", str(tmp_path / "c.pdf")])
    assert plot_cli.main(["landscape", "--n", "5", "-o", str(tmp_path / "l.png")]) == 2
    assert "n = 4" in capsys.readouterr().err
    assert plot_cli.main(["shapes", "--dx", "20", "-o", str(tmp_path / "s.png")]) == 2
    assert "beyond the chain's reach" in capsys.readouterr().err
    assert plot_cli.main(["map", "--x", "q", "1", "2", "3", "--y", "L0", "1", "2", "3", "-o",
                          str(tmp_path / "m.png")]) == 2
    assert plot_cli.main(["torque", "--json", "-o", str(tmp_path / "t.svg")]) == 0
    assert json.loads(capsys.readouterr().out)["segments"] == [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}]
    from tensegrity_opt.applications import cli

    if "plot" in cli.build_parser()._subparsers._group_actions[0].choices:     # once wired into cli.py
        assert cli.main(["plot", "torque", "-o", str(tmp_path / "w.png")]) == 0
        check_png((tmp_path / "w.png").read_bytes())


# ---------------------------------------------------------------------------- HTTP
@pytest.fixture(scope="module")
def client():
    pytest.importorskip("fastapi")
    pytest.importorskip("httpx")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        from fastapi.testclient import TestClient
    from service.config import Settings
    from service.main import create_app

    app = create_app(Settings(warmup=False))        # service.main registers the plot routes
    assert app.url_path_for("plot_curve") == "/v1/plots/curve"
    with TestClient(app) as c:
        yield c


M4 = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}
BODIES = {
    "curve": {"manipulator": M4, "dx": {"start": 0.0, "stop": 0.5, "num": 6}},
    "landscape": {"manipulator": M4, "dx": 0.1, "grid": 31},
    "shapes": {"manipulator": {"n": 3}, "dx": 0.1},
    "torque": {"segments": [{"a": 1.0, "b": 1.0, "L0": 0.5}, {"a": 1.0, "b": 1.0, "k": [1.0, 2.0]}], "num": 51},
    "map": {"manipulator": M4, "param_x": "k", "values_x": {"start": 0.5, "stop": 2.0, "num": 4},
            "param_y": "L0", "values_y": [0.5, 1.0, 1.5]},
}


@pytest.mark.parametrize("kind", list(BODIES))
def test_api_answers_png_and_svg(client, kind):
    r = client.post(f"/v1/plots/{kind}", json={**BODIES[kind], "dpi": 40})
    assert r.status_code == 200, r.text
    assert r.headers["content-type"] == "image/png"
    check_png(r.content)
    r = client.post(f"/v1/plots/{kind}", json={**BODIES[kind], "format": "svg"})
    assert r.status_code == 200 and r.headers["content-type"].startswith("image/svg+xml")
    check_svg(r.content)


@pytest.mark.parametrize("kind", ["curve", "torque"])
def test_api_svg_is_byte_identical_between_identical_requests(client, kind):
    # matplotlib salts clip-path ids with a random UUID unless svg.hashsalt is set (issue 14 item 7)
    body = {**BODIES[kind], "format": "svg"}
    first, second = client.post(f"/v1/plots/{kind}", json=body), client.post(f"/v1/plots/{kind}", json=body)
    assert first.status_code == second.status_code == 200
    assert b"clip-path" in first.content or b"<use " in first.content
    assert first.content == second.content


def test_api_content_negotiation(client):
    body = BODIES["torque"]
    r = client.post("/v1/plots/torque", json=body, headers={"Accept": "image/svg+xml"})
    assert r.headers["content-type"].startswith("image/svg+xml")
    check_svg(r.content)
    r = client.post("/v1/plots/torque", json=body, headers={"Accept": "image/png;q=0.5, image/svg+xml;q=0.9"})
    assert r.headers["content-type"].startswith("image/svg+xml")
    r = client.post("/v1/plots/torque", json=body, headers={"Accept": "image/svg+xml;q=0.2, image/png"})
    assert r.headers["content-type"] == "image/png"
    r = client.post("/v1/plots/torque", json={**body, "format": "png"}, headers={"Accept": "image/svg+xml"})
    assert r.headers["content-type"] == "image/png"                 # the body's format wins
    r = client.post("/v1/plots/torque", json=body, headers={"Accept": "*/*"})
    assert r.headers["content-type"] == "image/png"


def test_api_refusals(client):
    r = client.post("/v1/plots/landscape", json={"manipulator": {"n": 5}, "dx": 0.1})
    assert r.status_code == 422 and r.json()["code"] == "unsupported" and r.json()["field"] == "manipulator.n"
    for kind in ("landscape", "shapes"):
        r = client.post(f"/v1/plots/{kind}", json={"manipulator": M4, "dx": 20.0})
        assert r.status_code == 422 and r.json()["code"] == "unreachable_target", kind
    r = client.post("/v1/plots/curve", json={"manipulator": M4, "dx": [0.1, -2.0]})
    assert r.status_code == 422 and r.json()["code"] == "unreachable_target"
    r = client.post("/v1/plots/curve", json={**BODIES["curve"], "format": "gif"})
    assert r.status_code == 422 and r.json()["code"] == "validation_error" and r.json()["field"] == "format"
    r = client.post("/v1/plots/map", json={**BODIES["map"], "param_y": "k"})
    assert r.status_code == 422 and r.json()["code"] == "invalid_parameter" and r.json()["field"] == "param_y"
    r = client.post("/v1/plots/map", json={**BODIES["map"], "values_y": [1.0, 0.5, 2.0]})
    assert r.status_code == 422 and r.json()["field"] == "values_y"
    r = client.post("/v1/plots/shapes", json={"manipulator": {"n": 5000}, "dx": 0.1})
    assert r.status_code == 422 and r.json()["code"] == "validation_error"
    r = client.post("/v1/plots/shapes", json={"manipulator": {"n": 300}, "dx": 0.1})
    assert r.status_code == 422 and r.json()["code"] == "validation_error"      # above the default limit: schema


def test_api_is_documented(client):
    doc = client.app.openapi()
    ids = {}
    for kind in BODIES:
        op = doc["paths"][f"/v1/plots/{kind}"]["post"]
        ids[kind] = op["operationId"]
        assert op["tags"] == ["plots"] and op["summary"]
        ok = op["responses"]["200"]["content"]
        assert set(ok) == {"image/png", "image/svg+xml"}
        assert op["requestBody"]["content"]["application/json"].get("examples")
        assert op.get("security") == [{"ApiKey": []}, {}]
        for status in ("401", "413", "422", "503", "504"):
            content = op["responses"][status]["content"]["application/json"]
            assert content["schema"]["$ref"] == "#/components/schemas/ErrorOut" and content.get("examples")
    assert ids == {k: f"plot_{k}" for k in BODIES}
    assert "unsupported" in doc["paths"]["/v1/plots/landscape"]["post"]["responses"]["422"]["content"][
        "application/json"]["examples"]


# ---------------------------------------------------------------------------- what a reviewer checks (issue 18)
def fig_texts(fig) -> str:
    """Every title, suptitle, axis label, colour-bar label and legend entry of ``fig``, one string."""
    out = [fig._suptitle.get_text() if fig._suptitle is not None else ""]
    for ax in fig.axes:
        out += [ax.get_title(), ax.get_xlabel(), ax.get_ylabel()]
        if ax.get_legend() is not None:
            out += [t.get_text() for t in ax.get_legend().get_texts()]
    for leg in fig.legends:
        out += [t.get_text() for t in leg.get_texts()]
    return "\n".join(out)


def legend_boxes_clear(fig) -> list[str]:
    """Every legend of ``fig`` is a figure legend whose box meets no data axes' box; returns its texts."""
    assert fig.legends and all(ax.get_legend() is None for ax in fig.axes if ax.get_label() != "<colorbar>")
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    texts = []
    for leg in fig.legends:
        lb = leg.get_window_extent(r)
        for ax in fig.axes:
            ab = ax.get_window_extent(r)
            assert not lb.overlaps(ab), (lb, ab, ax.get_label())
        texts += [t.get_text() for t in leg.get_texts()]
    return texts


PAPER_LABEL = "n = 4, a = 1, b = 1, k = 1, L0 = 1"


def test_axes_say_quantity_and_unit_and_titles_the_parameters():
    fig = plots.plot_curve(PAPER, np.linspace(0.0, 0.5, 6))
    top, bottom = fig.axes[:2]
    assert "$F_x$" in top.get_ylabel() and "(stiffness × length)" in top.get_ylabel()
    assert "$F_y$" in bottom.get_ylabel() and "(stiffness × length)" in bottom.get_ylabel()
    assert "deflection $\\delta_x$ (length)" in bottom.get_xlabel()
    assert PAPER_LABEL in fig._suptitle.get_text()
    # Fx and Fy on two stacked panels sharing the abscissa, each on its own scale
    assert top.get_shared_x_axes().joined(top, bottom)
    assert top.get_position().y0 > bottom.get_position().y1 - 1e-9
    fig = plots.plot_landscape(PAPER, 0.1, grid=41)
    for ax in fig.axes[:2]:
        assert "(rad)" in ax.get_xlabel()
    assert "(rad)" in fig.axes[0].get_ylabel()
    cbar = [ax for ax in fig.axes if ax.get_label() == "<colorbar>"]
    assert len(cbar) == 1 and "energy $E$ (stiffness × length²)" in cbar[0].get_ylabel()
    assert PAPER_LABEL in fig._suptitle.get_text()
    fig = plots.plot_shapes(PAPER, 0.1)
    assert PAPER_LABEL in fig._suptitle.get_text() and "stiffness × length" in fig._suptitle.get_text()
    assert "(length)" in fig.axes[0].get_ylabel() and any("(length)" in ax.get_xlabel() for ax in fig.axes)
    segs = [to.Segment(0.5, 1.0, 1.0, L0) for L0 in (0.5, 2.5)]
    fig = plots.plot_torque(segs)
    ax = fig.axes[0]
    assert "(rad)" in ax.get_xlabel() and "(stiffness × length²)" in ax.get_ylabel()
    assert "a = 0.5, b = 1, k = 1" in ax.get_title()             # shared; L0 differs: in each legend entry
    fig = plots.plot_map(PAPER, "k", [0.5, 1.0, 2.0], "L0", [0.5, 1.0, 2.0])
    ax = fig.axes[0]
    assert "$k$ (stiffness)" in ax.get_xlabel() and "$L_0$ (length)" in ax.get_ylabel()
    assert "n = 4, a = 1, b = 1" in ax.get_title() and "L0 =" not in ax.get_title()
    assert "(stiffness × length)" in fig.axes[1].get_ylabel()      # the colour bar


def test_chain_label_of_a_heterogeneous_chain():
    m = to.Manipulator([to.Segment(1.0, 1.0, k, 1.0) for k in (0.5, 1.0, 2.0, 1.0, 1.5)])
    assert plots.chain_label(m) == "heterogeneous, n = 5, a = 1, b = 1, k = 0.5..2, L0 = 1"
    assert plots.chain_label(PAPER) == PAPER_LABEL
    fig = plots.plot_curve(m, np.linspace(0.0, 0.2, 3))
    assert "heterogeneous, n = 5" in fig._suptitle.get_text() and "k = 0.5..2" in fig._suptitle.get_text()


def test_contour_levels_are_evenly_spaced():
    fig = plots.plot_landscape(PAPER, 0.1, pair=(0, 1), grid=41)
    land = to.energy_landscape(PAPER, 0.1, pair=(0, 1), grid=41, span=plots.landscape_span(PAPER, 0.1, 0.0, (0, 1)))
    finite = land.energy[np.isfinite(land.energy)]
    for elbow in ("+1", "-1"):
        for name in (f"contour-elbow{elbow}", f"energy-fill-elbow{elbow}"):
            lv = np.asarray(gid(fig, name).levels, float)
            d = np.diff(lv)
            assert lv.size >= 8 and np.allclose(d, d[0], rtol=1e-9, atol=0), (name, lv)
            assert finite.min() <= lv[0] and lv[-1] <= finite.max()
    # percentile levels (the former _levels) were not evenly spaced on this landscape
    pct = np.unique(np.percentile(finite, np.linspace(0.0, 100.0, 25)))
    assert not np.allclose(np.diff(pct), np.diff(pct)[0], rtol=1e-3)
    fig = plots.plot_map(PAPER, "a", np.linspace(0.4, 1.4, 6), "L0", np.linspace(0.5, 2.5, 5))
    lv = np.asarray(gid(fig, "critical-load-contours").levels, float)
    assert lv.size >= 3 and np.allclose(np.diff(lv), np.diff(lv)[0], rtol=1e-9, atol=0)


@pytest.mark.parametrize("pair", [(0, 1), (0, 3)])
def test_landscape_region_is_the_exact_boundary_and_holds_every_equilibrium(pair, equilibria):
    from tensegrity_opt.analyses.equilibria.landscape import landscape_margin

    fig = plots.plot_landscape(PAPER, 0.1, 0.0, pair=pair, grid=41, equilibria=equilibria)
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
        land = to.energy_landscape(PAPER, 0.1, 0.0, pair=pair, grid=41,
                                   span=plots.landscape_span(PAPER, 0.1, 0.0, pair))
        QI, QJ = np.meshgrid(land.qi, land.qj, indexing="ij")
        grid_mg, _ = landscape_margin(PAPER, target, pair, QI, QJ, 1 if b == 0 else -1)
        inside = np.isfinite(land.energy[b])
        # the margin is positive exactly on the landscape's finite cells (brute force: the library's NaN)
        assert np.array_equal(inside, grid_mg > 0)
        # cells next to the boundary have margins up to ~1e-2; the outline's vertices are 100 x closer
        step = np.max(np.abs(np.diff(grid_mg, axis=0))[np.isfinite(np.diff(grid_mg, axis=0))])
        assert np.max(np.abs(mg)) < 0.02 * step, (np.max(np.abs(mg)), step)
    assert marked == len(equilibria) == 6


def test_torque_label_prints_zero_for_a_zero_stiffness():
    seg = to.Segment(0.5, 1.0, 1.0, 1.5)           # K = k (b L0 - 2 (b^2 - a^2)) = 1.5 - 1.5 = 0
    assert seg.stiffness != 0.0 and abs(seg.stiffness) < 1e-12     # rounding noise in the library's K
    assert plots.stiffness_text(seg) == "K = 0: degenerate"
    segs = [to.Segment(0.5, 1.0, 1.0, L0) for L0 in (0.5, 1.5, 2.5)]
    texts = legend_boxes_clear(plots.plot_torque(segs))
    assert "L0=0.5 (K = -1: two-mode)" in texts                   # K = 0.5 - 1.5
    assert "L0=1.5 (K = 0: degenerate)" in texts
    assert "L0=2.5 (K = 1: monotonic)" in texts
    assert not any("e-" in t for t in texts)


def _partial(c, k: int):
    """``c`` cut after ``k`` points, ended at point ``k`` (``Curve.ended_at``)."""
    import dataclasses

    from tensegrity_opt.analyses.paths.curves import CurveEnd

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
    fig = plots.plot_curve(PAPER, dx, curve=c)
    assert np.array_equal(rows(gid(fig, "fx")), np.column_stack([c.dx, c.fx]))     # only the points returned
    for name, v in (("fx", c.fx), ("fy", c.fy)):
        assert np.allclose(gid(fig, f"end-marker-{name}").get_xydata(), [[c.dx[-1], v[-1]]])
        assert np.allclose(gid(fig, f"curve-end-{name}").get_xdata(), [dx[7], dx[7]])
    text = gid(fig, "curve-end-text").get_text()
    assert text == "stable branch ends at $\\delta_x$ = 0.7"
    done = plots.plot_curve(PAPER, dx)
    assert maybe_gid(done, "end-marker-fx") is None and maybe_gid(done, "curve-end-text") is None


def test_a_tensile_jump_off_the_straight_chain_is_not_called_buckling():
    bistable = to.Manipulator.uniform(4, a=0.5, L0=1.0)          # K = 1 - 1.5 < 0: straight is unstable
    assert bistable.segments[0].stiffness < 0
    c = to.force_deflection(bistable, np.linspace(0.0, 0.6, 7))
    first = c.jumps[0]
    assert first.force_before[0] == 0.0 and first.force_after[0] > 0.0          # tensile
    assert plots.jump_kind(first) == "leave_straight"
    assert "buckling" not in plots.jump_label(first)
    if not hasattr(first, "label"):                # the figure's own sentence (the library's once it has one)
        assert plots.jump_label(first) == f"leaves the straight chain: F_x 0 -> {first.force_after[0]:.3g} (tensile)"
    fig = plots.plot_curve(bistable, None, curve=c)
    assert maybe_gid(fig, "jump-0-buckling-fx") is None
    assert gid(fig, "jump-0-leave_straight-fx") is not None
    texts = legend_boxes_clear(fig)
    entry = next(t for t in texts if t.startswith("jump 1:"))
    assert "buckling" not in entry and "straight" in entry
    # the paper's chain buckles: compressive, and called so
    p = to.force_deflection(PAPER, np.linspace(0.0, 0.2, 3))
    assert plots.jump_kind(p.jumps[0]) == "buckling"
    assert plots.jump_label(p.jumps[0]).startswith("buckling") and "compressive" in plots.jump_label(p.jumps[0])


def test_former_branch_switch_is_a_snap():
    from tensegrity_opt.analyses.paths.curves import Jump

    j = Jump("branch_switch", 0.3, 0.35, np.array([-0.5, 0.1]), np.array([-0.4, -0.1]), 0, 1)
    assert plots.jump_kind(j) == "snap" and plots.jump_label(j).startswith("snap to another stable branch")
    assert "dF_x = +0.1" in plots.jump_label(j)


@pytest.mark.parametrize("make", ["curve", "curve-all", "landscape", "torque", "shapes"])
def test_legends_do_not_cover_the_data(make):
    if make == "curve":
        fig = plots.plot_curve(PAPER, np.linspace(0.0, 0.5, 6))
    elif make == "curve-all":
        fig = plots.plot_curve(PAPER, np.linspace(0.0, 0.5, 6), branch="all")
    elif make == "landscape":
        fig = plots.plot_landscape(PAPER, 0.1, grid=31)
    elif make == "torque":
        fig = plots.plot_torque([to.Segment(1.0, 1.0, 1.0, L0) for L0 in (0.5, 1.0)])
    else:
        fig = plots.plot_shapes(PAPER, 0.1)
        assert not fig.legends                    # no legend at all: the colours are in each panel's title
        return
    assert legend_boxes_clear(fig)


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
    assert np.allclose(gid(fig, "torque-1-stable").get_xdata(), [0.0]) and gid(fig, "torque-1-unstable").get_xdata().size == 0


def test_docs_figures_are_committed_small_and_referenced():
    names = ["fig2_torque", "fig4_landscape", "fig5_landscape", "fig6_curve", "shapes", "branch", "atlas", "map"]
    text = (ROOT / "docs" / "figures.md").read_text()
    import importlib.util

    spec = importlib.util.spec_from_file_location("docs_figures", ROOT / "docs" / "figures.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)                  # importing draws nothing
    for name in names:
        png = ROOT / "docs" / "img" / f"{name}.png"
        check_png(png.read_bytes())
        assert png.stat().st_size <= 150_000, name
        assert f"img/{name}.png" in text and name in mod.FIGURES, name


def test_a_partial_curve_of_the_library_draws_its_end():
    m = to.Manipulator.uniform(3, a=0.5)
    dx = np.linspace(0.0, 5.5, 23)
    c = to.force_deflection(m, dx)
    assert c.ended_at is not None and c.dx.size < dx.size          # K = -0.5: the stable branch ends
    fig = plots.plot_curve(m, dx, curve=c)
    assert np.array_equal(rows(gid(fig, "fx")), np.column_stack([c.dx, c.fx]))
    assert np.allclose(gid(fig, "end-marker-fx").get_xydata(), [[c.dx[-1], c.fx[-1]]])
    assert gid(fig, "curve-end-text").get_text() == f"stable branch ends at $\\delta_x$ = {c.ended_at.dx:.4g}"
    kinds = [plots.jump_kind(j) for j in c.jumps]
    assert kinds[0] == "leave_straight" and "buckling" not in kinds          # K = -0.5: nothing buckles
    assert legend_boxes_clear(fig)
