"""The control commands: ``plan``, ``simulate``, ``force-estimate`` and ``plot plan|simulation``.

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
from tensegrity_opt.analyses.design.preload_control import PreloadController
from tensegrity_opt.applications.cli import build_parser, main
from tensegrity_opt.applications.cli.control import load_cycle

M = to.Manipulator.uniform(4)
M3 = to.Manipulator.uniform(3, a=0.5)
BISTABLE = ["--n", "3", "--a", "0.5"]
EQ_Q = [0.742754, 0.522806, 0.297158, 0.0953]


def run_json(capsys, argv):
    assert main([*argv, "--json"]) == 0, capsys.readouterr().err
    return json.loads(capsys.readouterr().out)


def same(a: dict, b: dict, skip=("seconds",)) -> bool:
    return {k: v for k, v in a.items() if k not in skip} == {k: v for k, v in b.items() if k not in skip}


def test_plan_from_a_line_a_csv_and_a_json_file(capsys, tmp_path):
    argv = ["plan", "--line", "7.9", "0.2", "7.3", "1.4", "7", "--margin", "0.05"]
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert "7 steps, 7 feasible, 7 verified, status complete" in out and "newton" in out
    got = run_json(capsys, argv)
    T = np.column_stack([np.linspace(7.9, 7.3, 7), np.linspace(0.2, 1.4, 7)])
    assert same(got, json.loads(json.dumps(to.plan_preloads(M, T, margin=0.05).to_dict())))

    csv = tmp_path / "path.csv"
    csv.write_text("x,y,fx,fy\n7.9,0.2,0,-0.01\n7.8,0.4,0,-0.01\n7.7,0.6,0,-0.02\n", encoding="utf-8")
    got = run_json(capsys, ["plan", "--targets", str(csv), "--rate-limit", "0.2", "--dt", "1", "--bounds", "0.5", "2"])
    want = to.plan_preloads(M, [[7.9, 0.2], [7.8, 0.4], [7.7, 0.6]],
                                      loads=[[0, -0.01], [0, -0.01], [0, -0.02]], rate_limit=0.2, dt=1.0,
                                      bounds=(0.5, 2.0))
    assert same(got, json.loads(json.dumps(want.to_dict())))
    js = tmp_path / "path.json"
    js.write_text(json.dumps({"targets": [[7.8, 0.3], [7.8, 0.6]], "end_angles": [0.0, None]}), encoding="utf-8")
    got = run_json(capsys, ["plan", "--targets", str(js), "--objective", "change", "--no-verify"])
    want = to.plan_preloads(M, [[7.8, 0.3], [7.8, 0.6]], end_angles=[0.0, np.nan], verify=False)
    assert same(got, json.loads(json.dumps(want.to_dict())))


def test_plan_of_a_tension_only_chain_keeps_its_springs_taut(capsys):
    argv = ["plan", "--n", "3", "--spring", "tension_only", "--line", "5.5", "0.3", "5.4", "0.6", "2"]
    got = run_json(capsys, [*argv, "--taut"])
    want = to.plan_preloads(to.Manipulator.uniform(3, spring="tension_only"), [[5.5, 0.3], [5.4, 0.6]], taut=True)
    assert same(got, json.loads(json.dumps(want.to_dict())))
    assert main(argv) == 2 and "taut" in capsys.readouterr().err


@pytest.mark.slow
def test_plan_with_a_horizon_is_the_library_plan(capsys):
    tip0 = M.tip(to.PreloadController(M).q)
    line = ["--line", *(repr(float(v)) for v in (tip0[0], tip0[1], tip0[0] - 0.1, tip0[1] + 0.3)), "3",
            "--rate-limit", "0.05", "--dt", "1"]
    got = run_json(capsys, ["plan", *line, "--horizon", "2", "--on-infeasible", "approach"])
    want = to.plan_preloads(M, np.linspace(tip0, tip0 + [-0.1, 0.3], 3), rate_limit=0.05, dt=1.0, horizon=2,
                            on_infeasible="approach")
    assert same(got, json.loads(json.dumps(want.to_dict())))
    # the window's steps, or (where one is not safe or is worse) the step-by-step answer from the same state
    assert got["horizon"] == 2 and "horizon" in got["method"]
    assert main(["plan", *line, "--horizon", "all"]) == 0
    assert "horizon all" in capsys.readouterr().out
    for bad in ("0", "some"):
        with pytest.raises(SystemExit) as exc:
            main(["plan", *line, "--horizon", bad])
        assert exc.value.code == 2
        assert "--horizon" in capsys.readouterr().err


def test_plan_on_infeasible_approach_commands_the_nearest_pose(capsys):
    """A target beyond the rate limit: approach moves toward it (the table's tip error and command columns, the
    JSON body the library's); hold keeps the command."""
    tip0 = M.tip(to.PreloadController(M).q)
    x1, y1 = tip0 + [-0.4, 0.8]
    line = ["--line", *(repr(float(v)) for v in (tip0[0], tip0[1], x1, y1)), "3", "--rate-limit", "0.05", "--dt", "1"]
    assert main(["plan", *line, "--on-infeasible", "approach"]) == 0
    out = capsys.readouterr().out
    assert "on infeasible steps approach" in out and "tip err." in out and "command [L1_0, L2_0]" in out
    assert "nearest" in out
    got = run_json(capsys, ["plan", *line, "--on-infeasible", "approach"])
    want = to.plan_preloads(M, np.linspace(tip0, [x1, y1], 3), rate_limit=0.05, dt=1.0,
                            on_infeasible="approach")
    assert same(got, json.loads(json.dumps(want.to_dict())))
    assert got["on_infeasible"] == "approach" and got["method"][1] == "nearest"
    assert got["commands"][1] != got["commands"][0]
    assert 0 < got["tip_error"][1] < float(np.hypot(*(np.array([x1, y1]) - tip0))) / 2
    held = run_json(capsys, ["plan", *line])
    assert held["on_infeasible"] == "hold" and held["commands"][1] == held["commands"][0]
    assert held["tip_error"][2] > got["tip_error"][2]


@pytest.mark.slow
def test_simulate_a_load_cycle_preloads_and_a_held_tip(capsys, tmp_path):
    argv = ["simulate", *BISTABLE, "--load-cycle", "0.3", "--steps", "25"]
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert "25 of 25 samples, status complete" in out and out.count("  snap ") == 2 and "0.15311" in out
    got = run_json(capsys, argv)
    assert got == json.loads(json.dumps(to.simulate(M3, loads=load_cycle(0.3, 25)).to_dict()))
    assert load_cycle(0.3, 5).tolist() == [[0.0, 0.0], [0.0, 0.3], [0.0, 0.0], [0.0, -0.3], [0.0, 0.0]]

    P = [[[1.0 + d, 1.0 - d], [1.0, 1.0], [1.0, 1.0]] for d in (0.0, 0.2, 0.4)]
    js = tmp_path / "pre.json"
    js.write_text(json.dumps(P), encoding="utf-8")
    csv = tmp_path / "pre.csv"
    csv.write_text("\n".join(",".join(str(v) for pair in p for v in pair) for p in P) + "\n", encoding="utf-8")
    want = json.loads(json.dumps(to.simulate(M3, P).to_dict()))
    assert run_json(capsys, ["simulate", *BISTABLE, "--preloads", str(js)]) == want
    assert run_json(capsys, ["simulate", *BISTABLE, "--preloads", str(csv)]) == want

    tg = tmp_path / "targets.csv"
    tg.write_text("dx,dy\n0.1,0\n0.3,0\n0.5,0\n", encoding="utf-8")
    got = run_json(capsys, ["simulate", "--tip", "held", "--targets", str(tg)])
    assert got == json.loads(json.dumps(to.simulate(M, tip="held", targets=[[0.1, 0], [0.3, 0], [0.5, 0]]).to_dict()))


def test_force_estimate(capsys):
    argv = ["force-estimate", "--q", *map(str, EQ_Q), "--sigma", "1e-3"]
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert "F = (-0.0999999" in out and "chi2 = " in out and "2 degrees of freedom" in out
    assert run_json(capsys, argv) == json.loads(json.dumps(to.estimate_tip_force(M, EQ_Q, sigma_q=1e-3).to_dict()))
    q3 = [EQ_Q[i] for i in (0, 1, 3)]
    got = run_json(capsys, ["force-estimate", "--q", *map(str, q3), "--measured", "0", "1", "3", "--sigma", "1e-3",
                            "1e-3", "2e-3"])
    want = to.estimate_tip_force(M, q3, sigma_q=np.array([1e-3, 1e-3, 2e-3]), measured=[0, 1, 3])
    assert got == json.loads(json.dumps(want.to_dict())) and got["hidden_covariance"]
    cov = ["1e-6", "0", "0", "0", "1e-6", "0", "0", "0", "4e-6"]           # 3 x 3, row by row
    got = run_json(capsys, ["force-estimate", "--q", str(EQ_Q[0]), "nan", *map(str, EQ_Q[2:]), "--measured", "0",
                            "2", "3", "--sigma", *cov])
    want = to.estimate_tip_force(M, [EQ_Q[0], np.nan, *EQ_Q[2:]], sigma_q=np.array(cov, float).reshape(3, 3),
                                 measured=[0, 2, 3])
    assert got == json.loads(json.dumps(want.to_dict()))
    assert run_json(capsys, ["force-estimate", "--q", *map(str, EQ_Q)])["chi2"] is None


@pytest.mark.slow
def test_plot_plan_and_simulation_write_png_and_svg(tmp_path, capsys):
    writes_png_and_svg(main, [["plot", "plan", "--line", "7.9", "0.2", "7.3", "1.4", "5"],
                              ["plot", "simulation", *BISTABLE, "--load-cycle", "0.3", "--steps", "13"]],
                       tmp_path, capsys)
    info = run_json(capsys, ["plot", "simulation", *BISTABLE, "--load-cycle", "0.3", "--steps", "13", "-o",
                             str(tmp_path / "s.png")])
    assert info["snaps"] == 2 and info["status"] == "complete"


def test_errors_are_one_line_and_exit_2(capsys, tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("x,y\n7.9,0.2\n7.8,oops\n", encoding="utf-8")
    three = tmp_path / "three.csv"
    three.write_text("7.9,0.2,1\n", encoding="utf-8")
    for argv, text in [
        (["plan", "--targets", str(bad)], "line 3 is not a row of numbers"),
        (["plan", "--targets", str(three)], "expected rows x, y"),
        (["plan", "--targets", str(tmp_path / "missing.csv")], "No such file"),
        (["plan", "--line", "7.9", "0.2", "7.3", "1.4", "2.5"], "NUM must be an integer"),
        (["plan", "--n", "1", "--line", "1.9", "0.1", "1.8", "0.2", "2"], "n >= 2"),
        (["plan", "--line", "7.9", "0.2", "7.3", "1.4", "3", "--bounds", "2", "1"], "0 < lo < hi"),
        (["plan", "--line", "7.9", "0.2", "7.3", "1.4", "3", "--start-q", "0", "0"], "start must hold 4"),
        (["simulate"], "give --load-cycle, --preloads"),
        (["simulate", "--steps", "5"], "--steps is the length of a --load-cycle"),
        (["simulate", "--tip", "held", "--load-cycle", "0.1"], "a held tip takes --targets"),
        (["simulate", "--tip", "held"], "(with --tip held) --targets"),
        (["simulate", "--n", "65", "--load-cycle", "0.1", "--steps", "3"], "up to 64 segments"),
        (["simulate", "--load-cycle", "0.1", "--load-direction", "0", "0"], "nonzero vector"),
        (["force-estimate", "--q", "0", "0", "0", "0"], "do not determine the tip force"),
        (["force-estimate", "--q", "0.1", "0.2", "0.3", "0.4", "--sigma", "1", "2", "3"], "--sigma takes 1, 4"),
        (["force-estimate", "--q", "0.1", "0.2", "0.3", "0.4", "--measured", "7"], "must lie in 0..3"),
        (["plot", "plan", "--line", "7.9", "0.2", "7.3", "1.4", "3", "--start-q", "9", "0", "0", "0", "-o", "x.png"],
         "outside the physical joint range"),
    ]:
        assert main(argv) == 2, argv
        err = capsys.readouterr().err
        assert err.startswith("tensegrity-opt: error:") and text in err and "Traceback" not in err, (argv, err)
        assert err.count("\n") == 1, err
    for argv in (["plan"], ["plan", "--line", "1", "2"], ["plan", "--line", "7", "0", "7", "1", "3", "--margin", "-1"],
                 ["simulate", "--steps", "1"], ["force-estimate"], ["force-estimate", "--q", "inf"],
                 ["force-estimate", "--q", "0.1", "--measured", "-1"]):
        with pytest.raises(SystemExit) as exc:
            main(argv)
        assert exc.value.code == 2
        assert "error" in capsys.readouterr().err


def test_every_option_of_the_control_commands_has_help_and_its_default(capsys):
    sub = next(a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction))
    plot = next(a for a in sub.choices["plot"]._actions if isinstance(a, argparse._SubParsersAction))
    parsers = {cmd: sub.choices[cmd] for cmd in ("plan", "simulate", "force-estimate", "stiffness-design",
                                                 "load-capacity")}
    parsers.update({f"plot {k}": plot.choices[k] for k in ("plan", "simulation")})
    for name, p in parsers.items():
        opts = [a for a in p._actions if a.option_strings and a.dest != "help"]
        assert [a.dest for a in opts if not a.help] == [], name
        text = p.format_help()
        assert isinstance(p.formatter_class, type) and "(default:" in text, name
    with pytest.raises(SystemExit):
        main(["plan", "--help"])
    out = " ".join(capsys.readouterr().out.split())
    assert "(default: change)" in out and "(default: 0.001)" in out and "(length" in out and "(force" in out
    with pytest.raises(SystemExit):
        main(["simulate", "--help"])
    out = " ".join(capsys.readouterr().out.split())
    assert "(default: free)" in out and "(default: [0.0, 1.0])" in out and "(default: 0.0001)" in out


def test_stiffness_design_and_load_capacity(capsys):
    got = run_json(capsys, ["stiffness-design", "--target", "7", "1", "--eig-bounds", "0.04", "0.6"])
    want = to.preloads_for_stiffness(M, (7.0, 1.0), eig_bounds=(0.04, 0.6))
    np.testing.assert_allclose(got["rest_lengths"], want.rest_lengths, atol=1e-9)
    got = run_json(capsys, ["load-capacity", "--directions", "4", "--max-load", "2"])
    assert got["kinds"] == ["none", "none", "bifurcation", "none"]
    assert got["loads"][2] == pytest.approx(abs(to.critical_force(M, "free").force), rel=1e-9)
    with pytest.raises(SystemExit) as e:
        main(["load-capacity", "--directions", "0"])
    assert e.value.code == 2 and "--directions" in capsys.readouterr().err


@pytest.mark.parametrize("argv, first, second", [
    (["simulate", "--preloads", "p.json", "--load-direction", "1", "0"], "--load-direction", "--load-cycle"),
    (["plot", "simulation", "--tip", "held", "--targets", "t.csv", "--load-direction", "1", "0", "-o", "x.png"],
     "--load-direction", "--load-cycle"),
    (["plan", "--line", "7.9", "0.2", "7.3", "1.4", "3", "--manipulator", "m.json", "--a", "0.5"],
     "--manipulator", "--a"),
    (["plan", "--line", "7.9", "0.2", "7.3", "1.4", "3", "--targets", "t.csv"], "--line", "--targets"),
])
def test_control_options_that_exclude_each_other_are_refused(argv, first, second, capsys):
    refuses_together(main, argv, first, second, capsys)


def test_stiffness_design_names_the_active_bounds(capsys):
    assert main(["stiffness-design", "--target", "7.5", "1.0", "--eig-bounds", "0.05", "0.5"]) == 0
    line = next(x for x in capsys.readouterr().out.splitlines() if x.startswith("active bounds"))
    assert "L1_0[3] = 0.104853 (lower bound 0.1)" in line and "L1_0[1] = 4 (upper bound 4)" in line


def test_plan_times_from_a_csv_column_times_or_dt_and_the_arm_s_rest_lengths(capsys, tmp_path):
    r0 = [[1.03, 0.98], [1.0, 1.02], [0.97, 1.0], [1.01, 0.99]]
    flat = [str(v) for pair in r0 for v in pair]
    ctl = PreloadController(M, rest_lengths0=r0)
    tip0 = ctl.manipulator().tip(ctl.q)
    T = [(tip0 + [-0.01 * k, 0.03 * k]).tolist() for k in (1, 2, 3)]
    times = [0.3, 0.4, 1.0]
    csv = tmp_path / "timed.csv"                  # named columns, any order
    csv.write_text("y,t,x\n" + "".join(f"{y!r},{t!r},{x!r}\n" for (x, y), t in zip(T, times)), encoding="utf-8")
    js = tmp_path / "targets.json"
    js.write_text(json.dumps(T), encoding="utf-8")
    want = to.plan_preloads(M, T, times=times, rate_limit=0.1, rest_lengths0=r0)
    assert want.feasible.any()
    want = json.loads(json.dumps(want.to_dict()))
    got = run_json(capsys, ["plan", "--targets", str(csv), "--rate-limit", "0.1", "--rest-lengths0", *flat])
    assert same(got, want) and got["times"] == times
    plan = ["plan", "--targets", str(js), "--rate-limit", "0.1"]
    assert same(run_json(capsys, [*plan, "--rest-lengths0", *flat, "--times", *map(str, times)]), want)
    got = run_json(capsys, [*plan, "--rest-lengths0", *flat, "--dt", "0.5"])
    assert same(got, json.loads(json.dumps(to.plan_preloads(M, T, dt=0.5, rate_limit=0.1,
                                                            rest_lengths0=r0).to_dict())))
    assert main(plan) == 2                                                  # a rate per second needs a time base
    assert "per second" in capsys.readouterr().err
    assert main(["plan", "--targets", str(csv), "--times", "1", "2", "3"]) == 2
    assert "--times" in capsys.readouterr().err
    assert main([*plan, "--times", "0.5", "0.4", "1"]) == 2                 # not increasing
    assert "times" in capsys.readouterr().err
    assert main([*plan, "--dt", "1", "--rest-lengths0", "1", "1", "1"]) == 2
    assert "rest_lengths0" in capsys.readouterr().err
