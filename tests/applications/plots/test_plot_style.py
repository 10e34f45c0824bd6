"""What every figure shares: PNG and SVG by the file's suffix, reproducible SVG bytes, the chain's label, the
package importable without matplotlib, and the documentation's figures committed and referenced."""

from __future__ import annotations

import importlib
import inspect
import os
import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("matplotlib")

from figures import check_png, check_svg, png_size  # noqa: E402

import tensegrity_opt as to  # noqa: E402
from tensegrity_opt.applications import plots  # noqa: E402
from tensegrity_opt.errors import InvalidParameterError  # noqa: E402

ROOT = Path(__file__).resolve().parents[3]
PAPER = to.Manipulator.uniform(4, a=1.0, b=1.0, k=1.0, L0=1.0)


def test_save_chooses_the_format_by_suffix(tmp_path):
    fig = plots.plot_torque(to.Segment(1.0, 1.0), num=11)
    with pytest.raises(InvalidParameterError) as e:
        plots.save(fig, tmp_path / "fig.pdf")
    assert e.value.field == "path"
    with pytest.raises(InvalidParameterError) as e:
        plots.render(fig, "jpg")
    assert e.value.field == "format"
    check_png(plots.save(fig, tmp_path / "FIG.PNG").read_bytes())
    check_svg(plots.save(fig, tmp_path / "fig.svg").read_bytes())


def test_png_resolution_defaults_to_one_constant(tmp_path):
    fig = plots.plot_torque(to.Segment(1.0, 1.0), num=11)
    w, h = fig.get_size_inches()
    want = (round(w * plots.DPI), round(h * plots.DPI))
    assert png_size(plots.render(fig, "png")) == want
    assert png_size(plots.save(fig, tmp_path / "t.png").read_bytes()) == want
    assert png_size(plots.render(fig, "png", dpi=50)) == (round(w * 50), round(h * 50))


def test_svg_bytes_are_reproducible():
    first = plots.render(plots.plot_torque(to.Segment(1.0, 1.0), num=11), "svg")
    second = plots.render(plots.plot_torque(to.Segment(1.0, 1.0), num=11), "svg")
    assert b"clip-path" in first and first == second
    assert plots.new_figure((3.0, 2.0)).get_size_inches().tolist() == [3.0, 2.0]


def test_chain_label():
    m = to.Manipulator([to.Segment(1.0, 1.0, k, 1.0) for k in (0.5, 1.0, 2.0, 1.0, 1.5)])
    assert plots.chain_label(m) == "heterogeneous, n = 5, a = 1, b = 1, k = 0.5..2, L0 = 1"
    assert plots.chain_label(PAPER) == "n = 4, a = 1, b = 1, k = 1, L0 = 1"
    assert plots.chain_label(PAPER, exclude=("a", "k")) == "n = 4, b = 1, L0 = 1"
    pair = to.Manipulator([to.Segment(1.0, 1.0, (1.0, 2.0), 1.0)] * 2)
    assert plots.chain_label(pair) == "n = 2, a = 1, b = 1, k = (1, 2), L0 = 1"


@pytest.mark.slow
def test_library_imports_without_matplotlib(tmp_path):
    code = ("import sys; sys.modules['matplotlib'] = None\n"
            "import numpy as np, tensegrity_opt as to, tensegrity_opt.applications.plots as p\n"
            "import tensegrity_opt.applications.cli.plot\n"
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
    # every figure kind's default: its PNG, made by the command the page shows
    from tensegrity_opt.applications.cli.plot import KINDS

    assert {k.replace("-", "_") for k in KINDS} <= set(mod.DEFAULTS)
    for kind in mod.DEFAULTS:
        png = ROOT / "docs" / "img" / f"default_{kind}.png"
        check_png(png.read_bytes())
        assert png.stat().st_size <= 150_000, kind
        assert f"img/default_{kind}.png" in text and mod.default_command(kind) in text, kind


#: The library functions a figure may call: closed-form geometry that draws (the landscape's reachable region
#: and the elbow branch an equilibrium lies on), no solve.
DRAWING_GEOMETRY = {"complete_configuration", "landscape_margin"}


@pytest.mark.parametrize("family", ["style", "geometry", "curves", "equilibria", "maps", "paths", "control"])
def test_figures_draw_results_and_call_no_analysis(family):
    mod = importlib.import_module(f"tensegrity_opt.applications.plots.{family}")
    for name, obj in vars(mod).items():
        origin = getattr(obj, "__module__", "") or ""
        if origin.startswith(("tensegrity_opt.analyses", "tensegrity_opt.applications.sweeps",
                              "tensegrity_opt.numerics")):
            assert inspect.isclass(obj) or name in DRAWING_GEOMETRY, (family, name)
