"""The ``plot`` command: every kind writes PNG and SVG by the output's suffix and prints what it drew; its refusals
are one line on stderr and exit status 2."""

from __future__ import annotations

import argparse
import json

import numpy as np
import pytest

pytest.importorskip("matplotlib")

from figures import check_png, check_svg  # noqa: E402


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


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("argv", [
    ["plot", "curve", "--start", "0", "--stop", "0.5", "--num", "6"],
    ["plot", "landscape", "--dx", "0.1", "--grid", "31"],
    ["plot", "shapes", "--dx", "0.1", "--n", "3"],
    ["plot", "modes", "--dx", "0.5", "--n", "3", "--mass", "0.2"],
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

    assert cli.main(["plot", "torque", "-o", str(tmp_path / "w.png")]) == 0       # the plot command of the CLI
    check_png((tmp_path / "w.png").read_bytes())


def test_default_limit_load_figure_draws_the_buckled_arms(tmp_path, monkeypatch):
    from figures import gid, gids

    from tensegrity_opt.applications import plots

    drawn = []
    save = plots.save
    monkeypatch.setattr(plots, "save", lambda fig, *a, **kw: (drawn.append(fig), save(fig, *a, **kw))[1])
    data, _ = _run(["plot", "limit-load", "--dpi", "50", "-o", str(tmp_path / "l.png")])
    assert data["limit"] == "bifurcation" and data["load"] == pytest.approx(0.0761205, abs=1e-6)
    assert [a["end"] for a in data["arms"]] == ["joint_limit"] * 2
    fig = drawn[-1]
    arms = [gid(fig, g).get_xydata() for g in gids(fig, "arm-") if g.startswith("arm-0-") or g.startswith("arm-1-")]
    assert len(arms) == 2 and all(np.ptp(a[:, 0]) > 1.0 for a in arms)        # the end angle moves on the arms
    assert arms[1][:, 0] == pytest.approx(-arms[0][:, 0], abs=1e-9)            # mirror images
    assert arms[0][0] == pytest.approx([0.0, data["load"]], abs=1e-6)
    data, _ = _run(["plot", "limit-load", "--no-arms", "--dpi", "50", "-o", str(tmp_path / "p.png")])
    assert data["arms"] == [] and not gids(drawn[-1], "arm-") and gids(drawn[-1], "path-")
