"""The critical-load map figure: it draws the map's loads cell by cell (blank where there is none), the chain's own
design, the edge K = 0 of condition (4), contour levels evenly spaced, axes with quantity and unit."""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("matplotlib")

from figures import check_renders, gid, maybe_gid, nan_equal  # noqa: E402

import tensegrity_opt as to  # noqa: E402
from tensegrity_opt.applications import plots  # noqa: E402
from tensegrity_opt.applications.sweeps import critical_load_map  # noqa: E402
from tensegrity_opt.errors import InvalidParameterError  # noqa: E402

PAPER = to.Manipulator.uniform(4, a=1.0, b=1.0, k=1.0, L0=1.0)


def test_map_draws_the_critical_loads_blank_where_there_is_none(tmp_path):
    xs, ys = [0.4, 0.7, 1.0, 1.3], [0.5, 1.0, 1.5, 2.0, 2.5]
    cm = critical_load_map(PAPER, "a", xs, "L0", ys)
    assert np.isnan(cm.load).sum() >= 2
    fig = plots.plot_map(cm, PAPER)
    mesh = gid(fig, "critical-load")
    assert nan_equal(mesh.get_array(), cm.load)
    # mesh cells are centred on the grid values
    coords = mesh.get_coordinates()
    centres = 0.25 * (coords[:-1, :-1] + coords[1:, :-1] + coords[:-1, 1:] + coords[1:, 1:])
    assert np.allclose(centres[0, :, 0], xs) and np.allclose(centres[:, 0, 1], ys)
    assert np.allclose(gid(fig, "design").get_xydata(), [[1.0, 1.0]])
    assert gid(fig, "condition4") is not None                      # K = 0 crosses this grid
    ax = fig.axes[0]
    assert f"blank: {cm.blank} designs where the straight chain is not a stable equilibrium" in ax.get_title()
    assert "guided tip" in fig.axes[1].get_ylabel()
    free = critical_load_map(PAPER, "k", [0.5, 2.0], "b", [1.0, 0.8], boundary="free")
    fig2 = plots.plot_map(free, PAPER)
    assert nan_equal(gid(fig2, "critical-load").get_array(), free.load)
    assert "free tip" in fig2.axes[1].get_ylabel() and "blank" not in fig2.axes[0].get_title()
    check_renders(fig, tmp_path, "map")
    with pytest.raises(InvalidParameterError) as e:
        plots.plot_map(cm.to_dict(), PAPER)
    assert e.value.field == "critical_map"


def test_the_design_is_starred_only_when_uniform_in_both_parameters():
    m = to.Manipulator([to.Segment(1.0, 1.0, k, 1.0) for k in (0.5, 1.0, 2.0, 1.0)])
    fig = plots.plot_map(critical_load_map(m, "a", [0.8, 1.0, 1.2], "k", [0.5, 1.0, 2.0]), m)
    assert maybe_gid(fig, "design") is None
    assert "heterogeneous" not in fig.axes[0].get_title()             # k is an axis: the rest is uniform


def test_map_axes_say_quantity_and_unit():
    fig = plots.plot_map(critical_load_map(PAPER, "k", [0.5, 1.0, 2.0], "L0", [0.5, 1.0, 2.0]), PAPER)
    ax = fig.axes[0]
    assert "$k$ (stiffness)" in ax.get_xlabel() and "$L_0$ (length)" in ax.get_ylabel()
    assert "n = 4, a = 1, b = 1" in ax.get_title() and "L0 =" not in ax.get_title()
    assert "(stiffness × length)" in fig.axes[1].get_ylabel()      # the colour bar


def test_map_contour_levels_are_evenly_spaced():
    fig = plots.plot_map(critical_load_map(PAPER, "a", np.linspace(0.4, 1.4, 6), "L0", np.linspace(0.5, 2.5, 5)),
                         PAPER)
    lv = np.asarray(gid(fig, "critical-load-contours").levels, float)
    assert lv.size >= 3 and np.allclose(np.diff(lv), np.diff(lv)[0], rtol=1e-9, atol=0)
