"""What the figure tests share: reading artists back by ``gid``, checking the rendered bytes and that legends stay
off the data, and drawing a landscape figure the way its callers do (compute, then draw)."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np

import tensegrity_opt as to
from tensegrity_opt.analyses.equilibria.landscape import landscape_span
from tensegrity_opt.applications import plots

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
SVG_TAG = "{http://www.w3.org/2000/svg}svg"


def check_png(data: bytes) -> None:
    assert data[:8] == PNG_MAGIC


def png_size(data: bytes) -> tuple[int, int]:
    """The width and height in pixels of a PNG (its IHDR chunk)."""
    check_png(data)
    return int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")


def check_svg(data: bytes) -> ET.Element:
    root = ET.fromstring(data)
    assert root.tag == SVG_TAG
    return root


def check_renders(fig, tmp_path: Path, name: str) -> set[str]:
    """``save`` writes a PNG and an SVG by suffix; ``render`` gives the same kinds of bytes. Returns the ids of
    the SVG's elements."""
    png = plots.save(fig, tmp_path / f"{name}.png", dpi=50)
    svg = plots.save(fig, tmp_path / f"{name}.svg")
    check_png(png.read_bytes())
    root = check_svg(svg.read_bytes())
    check_png(plots.render(fig, "png", dpi=40))
    return {el.get("id") for el in root.iter() if el.get("id")}


def gid(container, name: str):
    """The one artist of ``container`` whose gid is ``name``."""
    found = container.findobj(lambda a: a.get_gid() == name)
    assert len(found) == 1, (name, len(found))
    return found[0]


def maybe_gid(container, name: str):
    found = container.findobj(lambda a: a.get_gid() == name)
    return found[0] if found else None


def gids(fig, prefix: str) -> list[str]:
    """The gids of ``fig`` that start with ``prefix``, sorted."""
    return sorted({a.get_gid() for a in fig.findobj(lambda a: str(a.get_gid() or "").startswith(prefix))})


def rows(line) -> np.ndarray:
    """The (x, y) rows of a Line2D without its NaN separators."""
    xy = np.asarray(line.get_xydata(), dtype=float)
    return xy[np.all(np.isfinite(xy), axis=1)]


def nan_equal(a, b, rtol=0.0, atol=0.0) -> bool:
    a = np.ma.filled(np.ma.asarray(a, dtype=float), np.nan)
    b = np.asarray(b, dtype=float)
    return a.shape == b.shape and np.allclose(a, b, rtol=rtol, atol=atol, equal_nan=True) and bool(
        np.all(np.isnan(a) == np.isnan(b)))


def legend_texts(fig, *, beside: bool = False, count: int | None = None) -> list[str]:
    """Every legend of ``fig`` is a figure legend whose box meets no axes' box (``beside``: it lies right of
    every data axes; ``count``: there are that many); returns the legends' texts."""
    assert fig.legends and all(ax.get_legend() is None for ax in fig.axes if ax.get_label() != "<colorbar>")
    assert count is None or len(fig.legends) == count, len(fig.legends)
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    texts = []
    for leg in fig.legends:
        lb = leg.get_window_extent(r)
        for ax in fig.axes:
            ab = ax.get_window_extent(r)
            assert not lb.overlaps(ab), (lb, ab, ax.get_label())
            if beside and ax.get_label() != "<colorbar>":
                assert lb.x0 >= ab.x1 - 1e-6, (lb, ab)
        texts += [t.get_text() for t in leg.get_texts()]
    return texts


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


def landscape_figure(m, dx: float, dy: float = 0.0, pair=(0, 3), grid: int = 41, span="auto", equilibria=None):
    """``(figure, landscape)``: the landscape over the reachable region (``span="auto"``), a given half-width or
    the physical range (``None``), with ``equilibria`` (default: every equilibrium) marked."""
    span = landscape_span(m, dx, dy, pair) if span == "auto" else span
    land = to.energy_landscape(m, dx, dy, pair=pair, grid=grid, span=span)
    eqs = to.find_equilibria(m, dx, dy) if equilibria is None else equilibria
    return plots.plot_landscape(land, eqs, m, dx, dy), land
