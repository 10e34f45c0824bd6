"""What every figure shares: the Agg figure, writing it (PNG, SVG with reproducible bytes), the units and
colours, the chain's label for a title, number formats, contour levels and the legend beside the axes.

Matplotlib is imported lazily (inside the functions), so that this module, like ``import tensegrity_opt``,
works without it. Nothing here touches ``pyplot`` or the global ``rcParams`` (but for the SVG hash salt, set
under a lock while an SVG is written): figures may be drawn from several threads at once, one per thread.
"""

from __future__ import annotations

import threading
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from ...errors import InvalidParameterError
from ...model.manipulator import Manipulator

__all__ = ["FORMATS", "DPI", "STABILITY_COLORS", "MAP_PARAMS", "FORCE_UNIT", "ENERGY_UNIT", "SVG_HASHSALT",
           "new_figure", "save", "render", "chain_label", "param_text", "number_text", "contour_levels",
           "legend_beside"]

#: File suffix / format name -> MIME type.
FORMATS = {"png": "image/png", "svg": "image/svg+xml"}

#: Resolution of a PNG (dots per inch) unless the caller gives one: :func:`save`, :func:`render`, the command
#: line's ``--dpi`` and the HTTP figures' ``dpi`` (also as jobs) all default to it. An 8.4 x 4.8 in figure is
#: 1008 x 576 pixels.
DPI = 120

#: Colour of an equilibrium by its ``kind``.
STABILITY_COLORS = {"minimum": "tab:green", "saddle": "tab:orange", "maximum": "tab:red",
                    "degenerate": "tab:gray"}

#: The design parameters of a segment that labels name (:func:`chain_label`) and a critical-load map varies.
MAP_PARAMS = ("a", "b", "k", "L0")

#: Axis label units. The model has no units of its own: lengths are in the unit the caller gives ``a``, ``b``,
#: ``L0`` in (the paper: ``b = 1``), stiffnesses in that of ``k``; forces are then stiffness x length, energies
#: and torques stiffness x length^2, angles rad.
FORCE_UNIT = "stiffness × length"
ENERGY_UNIT = "stiffness × length²"


# ---------------------------------------------------------------------------- the figure and its file
def new_figure(figsize: tuple[float, float]) -> Any:
    """A :class:`matplotlib.figure.Figure` with constrained layout on its own Agg canvas (no pyplot, no global
    state)."""
    try:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise ImportError("tensegrity_opt.applications.plots needs matplotlib: "
                          "python3 -m pip install matplotlib") from exc
    fig = Figure(figsize=figsize, layout="constrained")
    FigureCanvasAgg(fig)
    return fig


def _format_of(path: str | Path) -> str:
    fmt = Path(path).suffix.lower().lstrip(".")
    if fmt not in FORMATS:
        raise InvalidParameterError(f"the figure file must end in .png or .svg, got {str(path)!r}", field="path")
    return fmt


def _savefig_kwargs(fmt: str, dpi: float | None) -> dict[str, Any]:
    kw: dict[str, Any] = {"format": fmt, "dpi": float(DPI if dpi is None else dpi)}
    if fmt == "svg":
        kw["metadata"] = {"Date": None}          # reproducible files
    return kw


#: ``svg.hashsalt`` while an SVG is written: matplotlib otherwise salts the ids of clip paths and
#: markers with a random UUID, and the same figure would give different bytes every time.
SVG_HASHSALT = "tensegrity-opt"
_SVG_LOCK = threading.Lock()     # rcParams are process-wide: one SVG save at a time under the salt


def _savefig(fig: Any, target: Any, fmt: str, dpi: float | None) -> None:
    """``fig.savefig`` with reproducible bytes: SVG under a fixed hash salt and no date (PNG is already)."""
    if fmt != "svg":
        fig.savefig(target, **_savefig_kwargs(fmt, dpi))
        return
    import matplotlib

    with _SVG_LOCK, matplotlib.rc_context({"svg.hashsalt": SVG_HASHSALT}):
        fig.savefig(target, **_savefig_kwargs(fmt, dpi))


def save(fig: Any, path: str | Path, *, dpi: float | None = None) -> Path:
    """Write ``fig`` to ``path`` as PNG or SVG, chosen by the suffix (``.png`` / ``.svg``); a PNG at ``dpi``
    (default :data:`DPI`).

    Raises :class:`InvalidParameterError` (``field="path"``) for any other suffix.
    """
    path = Path(path)
    fmt = _format_of(path)
    _savefig(fig, path, fmt, dpi)
    return path


def render(fig: Any, fmt: str = "png", *, dpi: float | None = None) -> bytes:
    """The bytes of ``fig`` as ``"png"`` or ``"svg"`` (a PNG at ``dpi``, default :data:`DPI`)."""
    import io

    if fmt not in FORMATS:
        raise InvalidParameterError(f"format must be 'png' or 'svg', got {fmt!r}", field="format")
    buf = io.BytesIO()
    _savefig(fig, buf, fmt, dpi)
    return buf.getvalue()


# ---------------------------------------------------------------------------- labels and numbers
def param_text(v: float | tuple[float, float]) -> str:
    """A segment parameter in a label: ``"1.5"``, or a spring pair ``"(1, 2)"``."""
    return f"{v:g}" if not isinstance(v, tuple) else f"({v[0]:g}, {v[1]:g})"


def number_text(v: float, other: float = 0.0, digits: int = 3) -> str:
    """``v`` in a label: ``"0"`` when it is zero to rounding relative to the scale ``max(|v|, |other|)``."""
    scale = max(abs(v), abs(other))
    if v == 0.0 or abs(v) <= 1e-9 * scale:
        return "0"
    return f"{v:.{digits}g}"


def chain_label(m: Manipulator, exclude: Sequence[str] = ()) -> str:
    """``"n = 4, a = 1, b = 1, k = 1, L0 = 1"``: the chain's parameters for a title; a chain whose segments
    differ is ``"heterogeneous, n = 5, ..."`` with each parameter that differs given as its range
    (``"k = 0.5..2"``). ``exclude``: parameters left out (e.g. the axes of a map)."""
    parts = [f"n = {m.n}"]
    mixed = False
    for p in MAP_PARAMS:
        vals = [getattr(s, p) for s in m.segments]
        if p in exclude:
            continue
        if all(v == vals[0] for v in vals):
            parts.append(f"{p} = {param_text(vals[0])}")
        else:
            mixed = True
            flat = [float(x) for v in vals for x in (v if isinstance(v, tuple) else (v,))]
            parts.append(f"{p} = {min(flat):g}..{max(flat):g}")
    return ("heterogeneous, " if mixed else "") + ", ".join(parts)


def contour_levels(values: np.ndarray, num: int) -> np.ndarray:
    """About ``num`` evenly spaced contour levels at round values over the finite ``values``
    (:class:`matplotlib.ticker.MaxNLocator`), kept within their range."""
    from matplotlib.ticker import MaxNLocator

    finite = values[np.isfinite(values)]
    if finite.size == 0:
        return np.array([])
    lo, hi = float(finite.min()), float(finite.max())
    if not hi > lo:
        return np.array([lo])
    lv = MaxNLocator(nbins=max(int(num), 2), steps=[1, 2, 2.5, 5, 10]).tick_values(lo, hi)
    step = float(lv[1] - lv[0])
    lv = lv[(lv >= lo - 1e-9 * step) & (lv <= hi + 1e-9 * step)]
    # whole multiples of the step (no rounding noise: np.diff is constant)
    return np.round(lv / step) * step


def legend_beside(ax: Any, handles: list, labels: list) -> None:
    """The figure's legend beside the axes (right, outside: constrained layout makes room), so that it
    never covers the data."""
    if handles:
        ax.figure.legend(handles, labels, fontsize=7, loc="outside right upper", frameon=False)
