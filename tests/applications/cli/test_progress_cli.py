"""Progress on long work (:mod:`tensegrity_opt.applications.cli.progress`): on a terminal a bar and a one-line
summary on stderr; with ``--no-progress`` or a pipe no bar, and stdout byte-identical either way.

The terminal is a pseudo-terminal (:func:`pty.openpty`) opened without a size, as ``script`` or a CI runner
opens one: tqdm reads it as -1 lines and hid every bar there. Small inputs, no timing asserts.
"""

from __future__ import annotations

import os
import pty
import re
import subprocess
import sys

import pytest

from tensegrity_opt.applications.cli.progress import Progress
from tensegrity_opt.numerics.homotopy import homotopy_available

SPEC = '{"analysis": "buckling", "grid": {"n": [3, 4], "k": [0.5, 1, 2]}}'
COMMANDS = {
    "sweep": ["sweep", "SPEC", "--scheduler", "serial"],
    "atlas": ["atlas", "--n", "3", "--a", "0.5", "--dx", "0.2", "1.4", "2", "--dy", "-0.3", "0.3", "2", "--no-edges"],
    "simulate": ["simulate", "--n", "3", "--a", "0.5", "--load-cycle", "0.3", "--steps", "9"],
    "plan": ["plan", "--line", "7.9", "0.2", "7.6", "0.8", "3"],
    "equilibria": ["equilibria", "--n", "3", "--method", "homotopy"],
}
SUMMARY = {"sweep": "sweep: 6 points", "atlas": "atlas: 4 targets in", "simulate": "simulate: 9 of 9 samples in",
           "plan": "plan: 3 steps in", "equilibria": "equilibria in"}


def _untimed(out: bytes) -> bytes:
    return re.sub(rb"\(\d+\.\d+ s\)", b"(T s)", out)


def _run(argv: list[str], tmp_path, *, tty: bool) -> tuple[bytes, str]:
    """Run the command line with ``argv``; stdout a pipe, stderr a pseudo-terminal (``tty``) or a pipe:
    ``(stdout, stderr)``."""
    spec = tmp_path / "spec.json"
    spec.write_text(SPEC)
    argv = [str(spec) if a == "SPEC" else a for a in argv]
    cmd = [sys.executable, "-m", "tensegrity_opt.applications.cli", *argv]
    env = {**os.environ, "COLUMNS": "", "LINES": ""}
    if not tty:
        r = subprocess.run(cmd, capture_output=True, timeout=600, env=env, stdin=subprocess.DEVNULL)
        assert r.returncode == 0, r.stderr.decode()
        return r.stdout, r.stderr.decode()
    master, slave = pty.openpty()
    try:
        proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=slave, stdin=subprocess.DEVNULL, env=env)
        os.close(slave)
        err = bytearray()
        while True:
            try:
                chunk = os.read(master, 65536)
            except OSError:            # the terminal's other side closed (Linux: EIO)
                break
            if not chunk:
                break
            err += chunk
        out = proc.stdout.read()
        assert proc.wait(timeout=600) == 0, err.decode(errors="replace")
    finally:
        os.close(master)
    return out, err.decode(errors="replace")


@pytest.mark.slow
@pytest.mark.parametrize("name", list(COMMANDS))
def test_a_terminal_shows_a_bar_and_a_summary_a_pipe_neither(name, tmp_path):
    if name == "equilibria" and not homotopy_available():
        pytest.skip("PHCpack's phc is not installed")
    argv = COMMANDS[name]
    out_tty, err_tty = _run(argv, tmp_path, tty=True)
    assert "%|" in err_tty or "[00:" in err_tty, err_tty          # the bar (a count, or a spinner's elapsed time)
    assert SUMMARY[name] in err_tty, err_tty
    out_off, err_off = _run([*argv, "--no-progress"], tmp_path, tty=True)
    out_pipe, err_pipe = _run(argv, tmp_path, tty=False)
    for err in (err_off, err_pipe):
        assert "%|" not in err and "[00:" not in err and "\r" not in err.replace("\r\n", "\n"), err
    # stdout byte-identical, bar or not (but the run's own time that the plan's and the atlas' tables state)
    assert _untimed(out_tty) == _untimed(out_off) == _untimed(out_pipe)
    if name != "sweep":                                       # the sweep's own summary line stays (where it wrote)
        assert SUMMARY[name] not in err_pipe and err_pipe == ""


@pytest.mark.slow
def test_the_sweep_shows_a_bar_on_a_terminal_without_a_size(tmp_path):
    """The fast one of the above: the sweep's bar on a pseudo-terminal of no size, not with --no-progress."""
    out_tty, err_tty = _run(COMMANDS["sweep"], tmp_path, tty=True)
    assert "sweep:   0%|" in err_tty and "0/6" in err_tty, err_tty
    assert "sweep: 6 points (buckling, serial), 0 failed" in err_tty
    out_off, err_off = _run([*COMMANDS["sweep"], "--no-progress"], tmp_path, tty=True)
    assert "%|" not in err_off and out_off == out_tty
    assert "sweep: 6 points" in err_off


def test_progress_is_a_callback_and_silent_off_a_terminal(capsys):
    """Off a terminal (pytest's stderr) by default nothing is shown, not even the summary; the library's
    callbacks ``(done, total, errors)`` land on it."""
    bar = Progress("atlas", 4, unit="target")
    assert not bar.enabled and bar.bar is None
    for k in range(1, 5):
        bar(k, 4, errors=k // 4)
    bar.stage("grid edges")
    bar.close("4 targets")
    assert capsys.readouterr() == ("", "")


def test_progress_forced_on_writes_the_bar_and_the_summary_to_its_stream(tmp_path):
    with open(tmp_path / "err.txt", "w", encoding="utf-8") as fh:
        bar = Progress("plan", unit="step", enabled=True, stream=fh)
        bar(0, 3)
        bar(3, 3)
        bar.close("3 steps in 0.0 s")
    text = (tmp_path / "err.txt").read_text(encoding="utf-8")
    assert "0/3" in text and text.endswith("plan: 3 steps in 0.0 s\n")
