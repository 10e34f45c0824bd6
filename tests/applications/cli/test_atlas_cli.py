"""The stability atlas on the command line: ``tensegrity-opt atlas`` and ``tensegrity-opt plot atlas``.

``--json`` prints the library's ``StabilityAtlas.to_dict()`` (the body of ``/v1/atlas`` for the same grid);
errors are one line on stderr and exit status 2, as for the other commands. Small grids (n = 3).
"""

from __future__ import annotations

import argparse
import json

import pytest

import tensegrity_opt as to
from tensegrity_opt.applications.cli import build_parser, main

CHAIN = ["--n", "3", "--a", "0.5"]
M = to.Manipulator.uniform(3, 0.5)
GRID = ["--dx", "0.2", "0.8", "2", "--dy", "0", "0.6", "2"]


def run_json(capsys, argv):
    assert main([*argv, "--json"]) == 0, capsys.readouterr().err
    return json.loads(capsys.readouterr().out)


def without_seconds(d: dict) -> dict:
    return {k: v for k, v in d.items() if k != "seconds"}


@pytest.mark.slow
def test_atlas_json_is_the_library_body_and_the_table_reads_it(capsys):
    got = run_json(capsys, ["atlas", *CHAIN, *GRID])
    want = json.loads(json.dumps(to.stability_atlas(M, [0.2, 0.8], [0.0, 0.6]).to_dict()))
    assert without_seconds(got) == without_seconds(want)
    assert got["n_stable"] == [[2, 4], [2, 3]] and got["status"] == "complete"
    assert main(["atlas", *CHAIN, *GRID, "--no-edges", "--dy", "0", "5", "2"]) == 0
    out = capsys.readouterr().out
    assert "Stability atlas of the held tip, n = 3, method search: 2 x 2 targets, status complete" in out
    assert "crossings: 0 switches, 0 branch ends" in out
    rows = [line.split() for line in out.splitlines()[3:5]]
    assert rows == [["5", "-", "-"], ["0", "2", "4"]]          # dy from the top down; '-': beyond reach
    got = run_json(capsys, ["atlas", *CHAIN, "--dx", "0.2", "0.2", "1", "--dy", "5", "5", "1", "--no-edges"])
    assert got["targets"][0][0]["reachable"] is False and got["least_energy"] == [[None]]


@pytest.mark.slow
def test_plot_atlas_writes_png_and_svg_with_the_gids(tmp_path, capsys):
    for suffix in ("png", "svg"):
        out = tmp_path / f"atlas.{suffix}"
        assert main(["plot", "atlas", *CHAIN, *GRID, "-o", str(out), "--dpi", "40"]) == 0, capsys.readouterr().err
        assert f"wrote {out} (atlas, {suffix.upper()}" in capsys.readouterr().out
        data = out.read_bytes()
        if suffix == "png":
            assert data[:8] == b"\x89PNG\r\n\x1a\n"
        else:
            assert b"<svg" in data[:400]
            for gid in ("n_stable", "switch", "branch_end"):
                assert f'id="{gid}"'.encode() in data, gid
    info = run_json(capsys, ["plot", "atlas", *CHAIN, *GRID, "--no-edges", "-o", str(tmp_path / "a.png")])
    assert info["kind"] == "atlas" and info["targets"] == 4 and info["max_stable"] == 4 and info["switches"] == 0


def test_errors_are_one_line_and_exit_2(capsys):
    for argv, text in [
        (["atlas", *CHAIN, "--dx", "0", "1", "2.5"], "NUM must be an integer >= 1"),
        (["atlas", *CHAIN, "--dx", "0.8", "0.2", "2"], "dx must be strictly increasing"),
        (["atlas", "--n", "1", *GRID], "2 <= n"),
        (["atlas", "--n", "8", *GRID, "--method", "homotopy"], "homotopy takes n <= 6"),
        (["plot", "atlas", *CHAIN, "--dx", "0", "1", "0", "-o", "x.png"], "NUM must be an integer >= 1"),
    ]:
        assert main(argv) == 2, argv
        err = capsys.readouterr().err
        assert err.startswith("tensegrity-opt: error:") and text in err and "Traceback" not in err, (argv, err)
        assert err.count("\n") == 1, err
    for argv, text in ((["atlas", "--dx", "0", "1", "x"], "expected a number"),
                       (["atlas", "--dx", "0", "1"], "expected 3 arguments"),
                       (["atlas", "--method", "newton"], "invalid choice"),
                       (["atlas", "--timeout", "0"], "expected a number > 0"),
                       (["plot", "atlas", *GRID], "-o/--output")):
        with pytest.raises(SystemExit) as exc:
            main(argv)
        assert exc.value.code == 2, argv
        assert text in capsys.readouterr().err, argv


def test_every_atlas_option_has_help_and_its_default(capsys):
    sub = next(a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction))
    plot = next(a for a in sub.choices["plot"]._actions if isinstance(a, argparse._SubParsersAction))
    for name, p in (("atlas", sub.choices["atlas"]), ("plot atlas", plot.choices["atlas"])):
        opts = [a for a in p._actions if a.option_strings and a.dest != "help"]
        assert [a.dest for a in opts if not a.help] == [], name
        assert "(default:" in p.format_help(), name
    with pytest.raises(SystemExit):
        main(["atlas", "--help"])
    out = " ".join(capsys.readouterr().out.split())
    assert "--dx START STOP NUM" in out and "(default: search)" in out and "--no-edges" in out
    assert "(default: [0.1, 1.3, 5])" in out and "(length" in out


def test_an_atlas_grid_through_the_straight_chain_runs_to_the_end(capsys):
    """The paper's chain (the default) on a grid whose corner holds it straight at full reach (a branch point)."""
    assert main(["atlas", "--dx", "0", "1", "3", "--dy", "0", "0.2", "3"]) == 0, capsys.readouterr().err
    out = capsys.readouterr().out
    assert "status complete" in out and "increasing t" not in out and "start nearby" not in out
