"""The loading-path commands: ``rest``, ``branch``, ``limit-load``, ``imperfection``, ``boundary`` and
``plot branch|limit-load|imperfection|boundary``.

``--json`` prints the library's ``to_dict()`` (the body of the HTTP API for the same request); errors are one
line on stderr and exit status 2; every option has its help with the default.
"""

from __future__ import annotations

import argparse
import json

import numpy as np
import pytest
from cli_checks import refuses_together, writes_png_and_svg

import tensegrity_opt as to
from tensegrity_opt.applications.cli import build_parser, main

M = to.Manipulator.uniform(4)
STRAIGHT = ["--start-q", "0", "0", "0", "0"]
GUIDED_LOADS = (0.572793, 1.362906, 1.921444)


def run_json(capsys, argv):
    assert main([*argv, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_branch_table_and_json(capsys):
    assert main(["branch", "--control", "guided", "--t-max", "2", *STRAIGHT]) == 0
    out = capsys.readouterr().out
    assert "status t_max" in out and "events (3):" in out
    assert out.count("branch_point") == 3 and "0.5727928" in out and "1.3629065" in out and "1.9214436" in out
    got = run_json(capsys, ["branch", "--control", "guided", "--t-max", "2", *STRAIGHT])
    want = to.trace_branch(M, np.zeros(4), to.Control.guided(), t_max=2.0)
    assert got == json.loads(json.dumps(want.to_dict()))
    got = run_json(capsys, ["branch", "--control", "load", "--direction", "1", "0", "--backward", "--stop-at", "event",
                            "--max-points", "300", *STRAIGHT])
    assert got["status"] == "event" and got["events"][0]["t"] == pytest.approx(-0.0761205, rel=1e-5)


def test_bifurcation_diagram_json_is_the_api_body(capsys):
    argv = ["branch", "--control", "guided", "--t-max", "2", "--t-min", "-0.2", "--depth", "1", "--max-points", "120",
            *STRAIGHT]
    got = run_json(capsys, argv)
    want = to.bifurcation_diagram(M, np.zeros(4), to.Control.guided(), depth=1, t_max=2.0, t_min=-0.2, max_points=120)
    assert got == json.loads(json.dumps({"branches": [b.to_dict() for b in want]}))
    assert main(argv) == 0
    assert f"{len(want)} branches (depth 1)" in capsys.readouterr().out


def test_limit_load_table_and_json(capsys):
    argv = ["limit-load", "--boundary", "guided", "--direction", "-1", "0", *STRAIGHT]
    assert main(argv) == 0
    assert "bifurcation at load P = 0.5727928" in capsys.readouterr().out
    got = run_json(capsys, [*argv, "--include-branch"])
    want = to.limit_load(M, (-1.0, 0.0), "guided", start=np.zeros(4))
    assert got == json.loads(json.dumps(want.to_dict(include_branch=True)))


def test_limit_load_prints_the_quasi_buckling_load_and_stiffness(tmp_path, capsys):
    path = tmp_path / "pre_bent.json"
    path.write_text(json.dumps({"segments": [{"a": 1, "b": 1, "k": 1, "L0": [1.02, 0.98]}] * 4}))
    assert main(["limit-load", "--manipulator", str(path)]) == 0
    want = to.limit_load(to.Manipulator([to.Segment(1, 1, 1, (1.02, 0.98))] * 4), (-1.0, 0.0), "free")
    assert (f"quasi-buckling load (least tangent stiffness): {want.quasi_buckling_load:.7f}, stiffness along the "
            f"load {want.quasi_buckling_stiffness:.7g}") in capsys.readouterr().out


def test_imperfection_table_json_and_figure(capsys, tmp_path):
    argv = ["imperfection", "--amplitudes", "0", "0.02851", "0.061"]
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert "bifurcation at P = 0.5727928 (stable-symmetric)" in out and "0.5274290" in out and "0.4247007" in out
    got = run_json(capsys, [*argv, "--include-limit-loads"])
    want = to.imperfection_sensitivity(M, [0.0, 0.02851, 0.061])
    assert got == json.loads(json.dumps(want.to_dict(include_limit_loads=True)))
    info = run_json(capsys, ["plot", "imperfection", "--n", "2", "--a", "1.5", "--amplitudes", "3e-4", "1e-3", "3e-3",
                             "-o", str(tmp_path / "i.png")])
    assert info["bifurcation"] == "unstable_symmetric" and info["law_exponent"] == pytest.approx(2 / 3, abs=0.02)
    assert (tmp_path / "i.png").read_bytes()[:4] == b"\x89PNG"


@pytest.mark.slow
def test_plot_kinds_write_png_and_svg(tmp_path, capsys):
    writes_png_and_svg(main, [["plot", "branch", "--control", "guided", "--t-max", "2", *STRAIGHT, "--y", "fy"],
                              ["plot", "branch", "--control", "guided", "--t-max", "2", *STRAIGHT, "--depth", "1",
                               "--max-points", "80", "--x", "q1", "--y", "t"],
                              ["plot", "limit-load", "--boundary", "guided", *STRAIGHT]], tmp_path, capsys)
    info = run_json(capsys, ["plot", "limit-load", "--boundary", "guided", *STRAIGHT, "-o", str(tmp_path / "l.png")])
    assert info["limit"] == "bifurcation" and info["load"] == pytest.approx(GUIDED_LOADS[0], abs=1e-6)


def test_errors_are_one_line_and_exit_2(capsys):
    for argv, text in [
        (["branch", "--control", "guided", "--start-q", "0", "0", "0"], "q0 must hold 4"),
        (["branch", "--control", "guided", "--start-q", "3", "0", "0", "0"], "outside the physical joint range"),
        (["branch", "--control", "guided", "--direction", "0", "1", *STRAIGHT], "needs an x component"),
        (["branch", "--control", "guided", "--direction", "1", "0", "0", *STRAIGHT], "takes 2 numbers"),
        (["branch", "--control", "preload", *STRAIGHT], "needs --direction with 2n"),
        (["branch", "--control", "guided", "--start-dx", "0.1"], "--start-dx needs a control that holds the tip"),
        (["branch", "--n", "65", "--control", "guided", "--start-q", *["0"] * 65], "up to 64 segments"),
        (["branch", "--depth", "1", "--backward", *STRAIGHT], "belong to one branch"),
        (["plot", "branch", *STRAIGHT, "--y", "q9", "-o", "x.png"], "q1..q4"),
    ]:
        assert main(argv) == 2, argv
        err = capsys.readouterr().err
        assert err.startswith("tensegrity-opt: error:") and text in err and "Traceback" not in err, (argv, err)
    for argv in (["branch", "--max-points", "1"], ["branch", "--t-max", "nan"], ["limit-load", "--max-load", "0"],
                 ["branch", "--depth", "-1"]):
        with pytest.raises(SystemExit) as exc:
            main(argv)
        assert exc.value.code == 2
        assert "expected" in capsys.readouterr().err





def test_rest_and_the_default_start(capsys):
    from tensegrity_opt.analyses.equilibria.rest import find_equilibria_under_force

    got = run_json(capsys, ["rest"])
    assert got == json.loads(json.dumps(find_equilibria_under_force(M).to_dict()))
    assert main(["rest", "--fx", "-0.3", "--stable-only"]) == 0
    assert "dead tip load (-0.3, 0)" in capsys.readouterr().out
    got = run_json(capsys, ["branch", "--control", "guided", "--t-max", "1"])
    assert got == json.loads(json.dumps(to.trace_branch(M, None, to.Control.guided(), t_max=1.0).to_dict()))


def test_boundary_command(capsys, tmp_path):
    argv = ["boundary", "--parameter", "asymmetry", "--p-min", "-0.02", "--p-max", "0.02", "--max-points", "40"]
    assert main(argv) == 0
    assert "Stability boundary" in capsys.readouterr().out
    assert run_json(capsys, argv)["parameter"] == "asymmetry"
    assert main(["plot", *argv, "-o", str(tmp_path / "b.png")]) == 0


def test_every_option_of_the_path_commands_has_help_and_its_default(capsys):
    sub = next(a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction))
    plot = next(a for a in sub.choices["plot"]._actions if isinstance(a, argparse._SubParsersAction))
    parsers = {cmd: sub.choices[cmd] for cmd in ("rest", "branch", "limit-load", "imperfection", "boundary")}
    parsers.update({f"plot {k}": plot.choices[k] for k in ("branch", "limit-load", "imperfection", "boundary")})
    for name, p in parsers.items():
        opts = [a for a in p._actions if a.option_strings and a.dest != "help"]
        assert [a.dest for a in opts if not a.help] == [], name
        assert isinstance(p.formatter_class, type) and "(default:" in p.format_help(), name
    with pytest.raises(SystemExit):
        main(["branch", "--help"])
    out = capsys.readouterr().out
    assert "(default: guided)" in out and "(default: 1000)" in out and "(length)" in out and "(force)" in out


@pytest.mark.parametrize("argv, first, second", [
    (["branch", "--control", "displacement", "--base", "1", "0"], "--base", "--control load, guided or wall"),
    (["branch", "--normal", "0", "1"], "--normal", "--control wall"),
    (["boundary", "--control", "load", "--normal", "0", "1"], "--normal", "--control wall"),
    (["branch", "--load", "0", "0.1"], "--load", "--control preload"),
    (["branch", "--control", "guided", "--tip", "held"], "--tip", "--control preload"),
    (["branch", *STRAIGHT, "--start-dy", "0.1"], "--start-dy", "--start-dx"),
    (["branch", *STRAIGHT, "--max-branches", "3"], "--max-branches", "--depth"),
    (["limit-load", "--include-branch"], "--include-branch", "--json"),
    (["imperfection", "--amplitudes", "0.01", "--include-limit-loads"], "--include-limit-loads", "--json"),
    (["plot", "branch", "--normal", "0", "1", "-o", "x.png"], "--normal", "--control wall"),
])
def test_options_for_another_mode_are_refused(argv, first, second, capsys):
    """An option that belongs to another control, another start or another mode (it was ignored without a
    word): one line naming it and what it needs, exit status 2."""
    refuses_together(main, argv, first, second, capsys)
