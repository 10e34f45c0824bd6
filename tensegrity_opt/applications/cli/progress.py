"""Progress of a long command on stderr: a tqdm bar while it runs, a one-line summary when it ends.

One helper for every long command (``sweep``, ``atlas``, ``equilibria``/``rest`` (the homotopy's path tracking),
``plan``, ``simulate``): :class:`Progress`. With a known total it is a bar of steps done (``13/25 targets``,
the rate, the time left); without one (a ``phc`` run, whose path count is known only at its end) a spinner with
the elapsed time. A thread refreshes it twice a second, so the elapsed time moves during a long step too. Shown
on stderr only, never on stdout (the table or ``--json`` stays clean), by default only when stderr is a
terminal (``--progress/--no-progress``: :func:`~.common.add_progress_option`).

The analyses report progress by callbacks (``stability_atlas(progress=...)``, ``plan_preloads``,
``simulate``, ``sweep``) and never print; a :class:`Progress` is such a callback:
``progress(done, total=None, errors=0)``.

A terminal that reports no size (a pseudo-terminal opened without one: ``script``, an editor's or a CI runner's
terminal, :func:`pty.openpty`) reads as 0 x 0, which tqdm takes for -1 lines and then hides every bar (as below
the screen's last line): such a terminal gets :data:`FALLBACK_SIZE`.
"""

from __future__ import annotations

import os
import sys
import threading
import time
from typing import Any, TextIO

__all__ = ["Progress", "is_terminal", "equilibria_summary", "FALLBACK_SIZE"]

#: The bar's terminal size (columns, lines) where the terminal reports none (0 x 0).
FALLBACK_SIZE = (80, 24)
#: Seconds between two refreshes of the bar by its thread (the spinner, the elapsed time).
TICK = 0.5
_SPINNER = "|/-\\"


def is_terminal(stream: Any) -> bool:
    """True when ``stream`` is a terminal (a pseudo-terminal included)."""
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError, OSError):
        return False


def _size(stream: Any) -> dict[str, Any]:
    """tqdm's size options for ``stream``: its own (following resizes) when the terminal reports a size, else
    :data:`FALLBACK_SIZE`."""
    try:
        size = os.get_terminal_size(stream.fileno())
    except (AttributeError, ValueError, OSError):
        size = os.terminal_size((0, 0))
    if size.columns > 0 and size.lines > 0:
        return {"dynamic_ncols": True}
    return {"ncols": FALLBACK_SIZE[0], "nrows": FALLBACK_SIZE[1]}


class Progress:
    """A progress bar on ``stream`` (stderr) for one long piece of work, and its summary line.

    Parameters
    ----------
    what : str
        The command (``"sweep"``, ``"atlas"``): the bar's label and the summary's first word.
    total : int, optional
        Steps to do; None: a spinner with the elapsed time (set later by a call with ``total``).
    unit : str
        What a step is (``"pt"``, ``"target"``, ``"step"``).
    enabled : bool, optional
        None (default): only when ``stream`` is a terminal. False: nothing is shown, not even the summary.
    stream : file, optional
        Default ``sys.stderr``.
    """

    def __init__(self, what: str, total: int | None = None, *, unit: str = "it", enabled: bool | None = None,
                 stream: TextIO | None = None) -> None:
        self.what = what
        self.stream = sys.stderr if stream is None else stream
        self.enabled = is_terminal(self.stream) if enabled is None else bool(enabled)
        self.t0 = time.perf_counter()
        self.bar: Any = None
        self._spin = 0
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        if not self.enabled:
            return
        try:
            from tqdm import tqdm
        except ImportError:  # pragma: no cover - tqdm is a core dependency
            return
        self.bar = tqdm(total=total, desc=what, unit=unit, file=self.stream, leave=False, smoothing=0.1,
                        mininterval=0.2, bar_format=None if total is not None else "{desc} [{elapsed}]{postfix}",
                        **_size(self.stream))
        self._thread = threading.Thread(target=self._tick, name=f"progress-{what}", daemon=True)
        self._thread.start()

    @property
    def seconds(self) -> float:
        """Seconds since the start."""
        return time.perf_counter() - self.t0

    def _tick(self) -> None:
        while not self._stop.wait(TICK):
            bar = self.bar
            if bar is None:
                return
            with bar.get_lock():
                self._spin += 1
                if bar.total is None:
                    bar.set_description_str(f"{self.what} {_SPINNER[self._spin % 4]}", refresh=False)
                bar.refresh()

    def __call__(self, done: int, total: int | None = None, errors: int = 0) -> None:
        """``done`` steps of ``total`` (None: unchanged) are done, ``errors`` of them failed: the callback the
        library's long functions take."""
        bar = self.bar
        if bar is None:
            return
        with bar.get_lock():
            if total is not None and bar.total != total:
                bar.total = total
                bar.bar_format = None
                bar.set_description_str(self.what, refresh=False)
                bar.refresh()
            if errors:
                bar.set_postfix_str(f"{errors} failed", refresh=False)
            bar.update(int(done) - bar.n)

    def stage(self, text: str) -> None:
        """What is being done now, after the counted steps (``"the grid edges"``): shown beside the bar."""
        if self.bar is not None:
            self.bar.set_postfix_str(text)

    def close(self, summary: str | None = None) -> None:
        """Remove the bar; with ``summary``, print ``WHAT: SUMMARY`` (one line, when shown at all)."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join()
            self._thread = None
        if self.bar is not None:
            self.bar.close()
            self.bar = None
        if summary is not None and self.enabled:
            print(f"{self.what}: {summary}", file=self.stream, flush=True)

    def __enter__(self) -> Progress:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def equilibria_summary(eqs: Any, seconds: float) -> str:
    """The summary of a search for every equilibrium (an ``EquilibriumSet``): how many, the time, the method and,
    for the homotopy, its paths."""
    paths = f": {eqs.paths} paths, {eqs.failed_paths} failed" if eqs.paths else ""
    return f"{len(eqs)} equilibria in {seconds:.1f} s ({eqs.method}{paths})"
