"""The library's command line (``tensegrity_opt.applications.cli``): the analysis commands' tables and JSON, their
usage and domain errors (one line, status 2), help with every default, partial curves, a closed pipe."""

import json
import subprocess
import sys
from pathlib import Path

import pytest
from cli_checks import USAGE_ERRORS, one_error_line, refuses_together

import tensegrity_opt as to
from tensegrity_opt.applications.cli import main


def test_cli_buckling_table(capsys):
    assert main(["buckling"]) == 0
    out = capsys.readouterr().out
    assert "-0.572793" in out and "1.145586" in out and "2.725813" in out and "3.842887" in out


def test_cli_json_outputs(capsys):
    assert main(["buckling", "--json", "--boundary", "free"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["critical_force"] == pytest.approx(-0.0761205, rel=1e-4)
    assert main(["equilibria", "--dx", "0.05", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert [e["shape"] for e in data["equilibria"]] == ["U", "U", "ZU", "ZU", "Z", "Z"]
    assert main(["equilibrium", "--dx", "0.1", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert abs(data["force"]["fy"]) == pytest.approx(0.02579, rel=1e-3)
    assert main(["curve", "--start", "0", "--stop", "0.5", "--num", "3", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert len(data["points"]) == 3 and data["jumps"][0]["kind"] == "buckling"


def test_cli_errors(capsys, tmp_path):
    assert main(["equilibrium", "--dx", "-1"]) == 2
    assert "beyond the chain's reach" in capsys.readouterr().err
    assert main(["buckling", "--L0", "0.1", "--a", "0.5"]) == 1    # an unstable straight chain: an answer
    bad = tmp_path / "m.json"
    bad.write_text('{"segments": [{"a": 1, "b": -1}]}')
    assert main(["buckling", "--manipulator", str(bad)]) == 2
    assert "b must be finite and > 0" in capsys.readouterr().err


def test_cli_equilibria_with_stops_names_the_joint_on_its_stop(capsys):
    """``--stops`` adds the equilibria resting on a stop (the library's ``stops=True``), and the table says which
    joint rests there with its contact torque; the default leaves them out."""
    argv = ["equilibria", "--n", "3", "--a", "0.9", "--dx", "0.9", "--dy", "0.3"]
    assert main([*argv, "--stops"]) == 0
    out = capsys.readouterr().out
    want = to.find_equilibria(to.Manipulator.uniform(3, a=0.9), 0.9, 0.3, stops=True)
    on = [e for e in want if e.at_stop.any()]
    assert on and out.count("on its stop (contact") == len(on) and f": {len(want)} (" in out
    assert main(argv) == 0 and "on its stop" not in capsys.readouterr().out


def test_cli_equilibria_none_inside_the_range(capsys, tmp_path):
    """A target reachable inside the range whose equilibria all lie outside it: exit 0, zero equilibria and the
    reason (table), an empty set that is a success (JSON)."""
    chain = tmp_path / "m.json"
    chain.write_text(json.dumps({"segments": [
        {"a": 0.4244907, "b": 1.1061139, "k": 2.7977215, "L0": 2.0757221},
        {"a": 1.2855203, "b": 1.0943198, "k": 1.1138807, "L0": 1.9328666},
        {"a": 0.6116747, "b": 1.2481474, "k": 0.6567948, "L0": 2.0724451}]}))
    argv = ["equilibria", "--manipulator", str(chain), "--dx", "8.356180218401274", "--dy", "-0.07981382020185246"]
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert ": 0 (method search, not certified)" in out and "no equilibrium inside the physical joint range" in out
    assert main([*argv, "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert (data["success"], data["status"], data["equilibria"]) == (True, "searched", [])


@pytest.mark.slow
def test_console_script_runs():
    r = subprocess.run([sys.executable, "-m", "tensegrity_opt.applications.cli", "buckling"], capture_output=True,
                       text=True, check=True)
    assert "critical force Fx0 = -0.572793" in r.stdout


# ---------------------------------------------------------------------------- usage errors, help, pipes
@pytest.mark.parametrize("argv", [["curve", "--num", "-1"], ["curve", "--num", "0"], ["equilibrium", "--dx", "nan"],
                                  ["buckling", "--n", "0"], ["plot", "curve", "--num", "-3", "-o", "x.png"]])
def test_a_bad_option_is_one_usage_line_and_exit_2(argv, capsys):
    """A count must be >= 1 and a number finite: argparse's usage error, never a traceback (numpy's ValueError
    for --num -1, say)."""
    with pytest.raises(SystemExit) as exc:
        main(argv)
    assert exc.value.code == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err and err.strip().splitlines()[-1].startswith("tensegrity-opt")
    assert "expected" in err.strip().splitlines()[-1]


def test_every_option_of_the_analysis_commands_has_help_and_its_default(capsys):
    import argparse

    from tensegrity_opt.applications.cli import build_parser

    sub = next(a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction))
    for cmd in ("buckling", "equilibrium", "equilibria", "curve"):
        opts = [a for a in sub.choices[cmd]._actions if a.option_strings and a.dest != "help"]
        assert opts, cmd
        assert [a.dest for a in opts if not a.help] == [], cmd        # every option says what it is
        with pytest.raises(SystemExit):
            main([cmd, "--help"])
        out = capsys.readouterr().out
        assert "(default: 0" in out or "(default: guided)" in out, cmd    # and its default


@pytest.mark.slow
def test_a_closed_pipe_is_not_an_error():
    """``tensegrity-opt buckling | head -1``: the reader leaves early; no BrokenPipeError traceback."""
    p = subprocess.Popen([sys.executable, "-m", "tensegrity_opt.applications.cli", "buckling"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=str(Path(__file__).resolve().parents[3]))
    p.stdout.close()                      # nobody reads: the first write fails with EPIPE
    err = p.stderr.read().decode()
    assert p.wait(timeout=120) == 0
    assert "Traceback" not in err and "BrokenPipe" not in err


# ---------------------------------------------------------------------------- help, errors, partial curves




@pytest.mark.parametrize("argv,says", [(argv, says) for argv, says in USAGE_ERRORS if argv[:1] != ["serve"]])
def test_a_usage_error_is_one_line_and_exit_2(argv, says, capsys):
    """Every bad option is one line ``error: ...`` on stderr (argparse's usage block left out) and status 2 (the
    console script's parser, with ``serve``: ``tests/service/test_service_cli.py``)."""
    with pytest.raises(SystemExit) as exc:
        main(argv)
    assert exc.value.code == 2
    line = one_error_line(capsys.readouterr().err)
    assert says in line and "--help" in line


@pytest.mark.parametrize("argv,says", [
    (["curve", "--k", "-1"], "k must be finite and > 0"), (["curve", "--a", "0"], "a must be"),
    (["equilibrium", "--L0", "-0.5"], "L0"), (["curve", "--start", "0", "--stop", "50", "--num", "3"], "reach"),
    (["plot", "map", "--x", "k", "0.5", "2", "-1", "--y", "L0", "0.5", "2.5", "3", "-o", "m.png"], "-1"),
    (["plot", "map", "--x", "q", "0.5", "2", "3", "--y", "L0", "0.5", "2.5", "3", "-o", "m.png"], "--x"),
])
def test_a_domain_error_inside_a_command_is_one_line_and_exit_2(argv, says, capsys, tmp_path, monkeypatch):
    """A negative stiffness, a zero size, an unreachable deflection, a negative count that only the library
    checks (numpy's ``linspace`` raised a ``ValueError`` traceback for ``plot map ... -1``): one line, 2."""
    monkeypatch.chdir(tmp_path)
    assert main(argv) == 2
    assert says in one_error_line(capsys.readouterr().err)


@pytest.mark.parametrize("text,says", [("[1, 2]", "expected a JSON object"), ('{"segments": []}', "n >= 1"),
                                       ("{not json", "Expecting"), ('{"segments": [{"a": 1, "b": -1}]}', "b must")])
def test_a_bad_manipulator_file_is_one_line_and_exit_2(text, says, capsys, tmp_path):
    """n = 0 by file (no segments), a JSON list, broken JSON: one line each, no traceback."""
    f = tmp_path / "m.json"
    f.write_text(text)
    assert main(["curve", "--manipulator", str(f), "--num", "3"]) == 2
    assert says in one_error_line(capsys.readouterr().err)


class _Partial:
    """A curve as the curves contract returns it when the stable branch ends early (``success`` False,
    ``message`` the sentence), around the real curve of the points before the end."""

    success = False
    status = "no_stable_equilibrium"
    message = "The stable branch ends between dx = 0.25 and dx = 0.5 (dy = 0): test; 2 of 5 points computed."

    def __init__(self, curve):
        self._curve = curve

    def __getattr__(self, name):
        return getattr(self._curve, name)

    def to_dict(self):
        return {**self._curve.to_dict(), "success": False, "status": self.status, "message": self.message}


def test_a_partial_curve_prints_its_points_and_the_note_and_exits_0(capsys, monkeypatch):
    """The contract: a Curve with ``success`` False is a result (its points are real equilibria): the
    table (or JSON) on stdout, ``curve.message`` on stderr, status 0; a complete curve prints no note."""
    import tensegrity_opt.applications.cli as cli
    from tensegrity_opt.analyses.paths.curves import force_deflection

    def partial(m, dx, dy=0.0, **kw):
        return _Partial(force_deflection(m, dx[:2], dy, **kw))

    assert main(["curve", "--start", "0", "--stop", "1", "--num", "5"]) == 0
    assert "note" not in capsys.readouterr().err
    monkeypatch.setattr(cli, "force_deflection", partial)
    assert main(["curve", "--start", "0", "--stop", "1", "--num", "5"]) == 0
    out, err = capsys.readouterr()
    rows = [ln for ln in out.splitlines() if ln.strip()[:1].isdigit()]
    assert len(rows) == 2 and rows[1].split()[0] == "0.25000"
    assert err.strip() == f"tensegrity-opt: note: {_Partial.message}"
    assert main(["curve", "--start", "0", "--stop", "1", "--num", "5", "--json"]) == 0
    out, err = capsys.readouterr()
    data = json.loads(out)
    assert len(data["points"]) == 2 and data["success"] is False and _Partial.message in err


def test_plot_curve_of_a_partial_curve_writes_the_figure_and_prints_the_note(capsys, monkeypatch, tmp_path):
    import tensegrity_opt.applications.cli.plot as plot_cli

    real = plot_cli.force_deflection

    def partial(m, dx, dy=0.0, **kw):
        return _Partial(real(m, dx[:3], dy, **kw))

    monkeypatch.setattr(plot_cli, "force_deflection", partial)       # the curve the command computes
    out_file = tmp_path / "c.png"
    assert main(["plot", "curve", "--start", "0", "--stop", "1", "--num", "5", "-o", str(out_file), "--json"]) == 0
    out, err = capsys.readouterr()
    data = json.loads(out)
    assert out_file.stat().st_size > 1000 and out_file.read_bytes()[:4] == b"\x89PNG"
    assert data["points"] == 3 and data["complete"] is False and data["note"] == _Partial.message
    assert err.strip() == f"tensegrity-opt: note: {_Partial.message}"


@pytest.mark.parametrize("argv", [["buckling", "--a", "0.5", "--L0", "0.5"],
                                  ["buckling", "--a", "0.5", "--L0", "0.5", "--json"]])
def test_a_physical_answer_is_no_usage_error(argv, capsys):
    """The straight chain being unstable unloaded (K = k (b L0 - 2 (b^2 - a^2)) = 0.5 - 1.5 = -1 here,
    by hand) is a fact about the chain: one line ``answer:`` naming K, status 1, not the usage error's 2."""
    assert main(argv) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("tensegrity-opt: answer: ")
    assert "K = " in err[0] and "= -1 <= 0" in err[0]


# ---------------------------------------------------------------------------- options that exclude each other
@pytest.mark.parametrize("argv, first, second", [
    (["equilibrium", "--dx", "0.1", "--fx", "1"], "--dx", "--fx"),
    (["equilibrium", "--dy", "0.1", "--fy", "1"], "--dy", "--fy"),
    (["equilibrium", "--fx", "-0.05", "--dy", "0.2"], "--dy", "--fx"),
    (["buckling", "--manipulator", "m.json", "--n", "3"], "--manipulator", "--n"),
    (["curve", "--k", "2", "--manipulator", "m.json"], "--manipulator", "--k"),
    (["equilibria", "--manipulator", "m.json", "--L0", "0.9"], "--manipulator", "--L0"),
])
def test_options_that_exclude_each_other_are_refused(argv, first, second, capsys):
    """A deflection and a force (the force won silently), a chain file and the uniform chain's options (the
    file won silently): one line naming both, exit status 2, before anything is read or solved."""
    refuses_together(main, argv, first, second, capsys)


def test_cli_homotopy_precompute_lists_the_start_solutions(capsys, tmp_path, monkeypatch):
    """n = 2 start roots of both kinds and structures: the packaged ones are found (nothing computed), their
    counts are the mixed volumes (8 and 24 general, 8 and 16 symmetric)."""
    monkeypatch.setenv("TENSEGRITY_CACHE_DIR", str(tmp_path))
    assert main(["homotopy-precompute", "--max-segments", "2"]) == 0
    lines = capsys.readouterr().out.strip().splitlines()
    assert len(lines) == 4 and all("(packaged" in line for line in lines)
    assert [int(line.split(":")[1].split()[0]) for line in lines] == [8, 8, 24, 16]
    assert not (tmp_path / "homotopy").exists()
    with pytest.raises(SystemExit):                                         # n = 2..6 only
        main(["homotopy-precompute", "--max-segments", "7"])


def test_cli_equilibrium_certify(capsys):
    """--certify: the library's certify=True answer (a bistable chain near its wells: certified), its bound no
    more than the energy; refused with a tip force."""
    argv = ["equilibrium", "--n", "3", "--a", "0.6", "--b", "1", "--k", "1", "--L0", "1.2",
            "--dx", "0.6", "--dy", "0.2"]
    assert main([*argv, "--certify", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    lib = to.solve_equilibrium(to.Manipulator.uniform(3, 0.6, 1.0, 1.0, 1.2), 0.6, 0.2, certify=True)
    assert data["status"] == lib.status == "certified" and data["energy"] == pytest.approx(lib.energy, abs=1e-12)
    cert = data["certificate"]
    assert cert["bound"] <= data["energy"] <= cert["bound"] + cert["tolerance"]
    assert main([*argv, "--certify"]) == 0
    assert "least energy certified" in capsys.readouterr().out
    with pytest.raises(SystemExit) as exc:
        main(["equilibrium", "--fx", "-0.1", "--certify"])
    assert exc.value.code == 2 and "not allowed with argument --certify" in capsys.readouterr().err


def test_modes_prints_the_librarys_frequencies_and_its_json_is_the_api_body(capsys, tmp_path):
    assert main(["modes", "--mass", "0.2", "--payload", "0.1", "--dx", "1.1", "--dy", "0.2"]) == 0
    out = capsys.readouterr().out
    m = to.Manipulator.uniform(4, mass=0.2, payload=0.1)
    md = to.modes(m, to.solve_equilibrium(m, 1.1, 0.2))
    assert md.message in out and f"{md.frequencies[0]:.6g}" in out
    path = tmp_path / "chain.json"
    path.write_text(json.dumps(m.to_dict()))
    assert main(["modes", "--manipulator", str(path), "--dx", "1.1", "--dy", "0.2", "--json"]) == 0
    body = json.loads(capsys.readouterr().out)
    assert body["frequencies"] == pytest.approx(md.frequencies.tolist(), rel=1e-12)
    assert body["equilibrium"]["q"] == pytest.approx(md.equilibrium.q.tolist())
    assert main(["modes", "--dx", "1"]) == 2                  # no mass: one line naming it
    assert "no mass" in one_error_line(capsys.readouterr().err)
    refuses_together(main, ["modes", "--mass", "1", "--dx", "1", "--fx", "0.1"], "--dx", "--fx", capsys)


def test_the_chain_options_take_gravity_and_joint_forces(capsys, tmp_path):
    assert main(["equilibrium", "--n", "3", "--mass", "0.05", "--payload", "0.02", "--gravity", "0", "-9.81",
                 "--joint-force", "2", "0.1", "0.3", "--dx", "0.8", "--dy", "-0.2", "--json"]) == 0
    body = json.loads(capsys.readouterr().out)
    m = to.Manipulator.uniform(3, mass=0.05, payload=0.02, gravity=(0.0, -9.81), joint_forces=[(2, (0.1, 0.3))])
    eq = to.solve_equilibrium(m, 0.8, -0.2)
    assert body["q"] == pytest.approx(eq.q.tolist(), rel=1e-12, abs=1e-14)
    assert body["loads"] == {"gravity": [0.0, -9.81], "payload": 0.02,
                             "joint_forces": [{"joint": 2, "force": [0.1, 0.3]}]}
    assert main(["equilibrium", "--n", "3", "--mass", "0.05", "--gravity", "0", "-9.81", "--dx", "0.8"]) == 0
    assert "under the chain's dead loads: gravity (0, -9.81)" in capsys.readouterr().out
    assert main(["buckling", "--mass", "0.1", "--gravity", "0", "-9.81"]) == 2
    assert "gravity is set" in one_error_line(capsys.readouterr().err)
    assert main(["equilibrium", "--joint-force", "2.5", "0", "1"]) == 2
    assert "joint must be an integer" in one_error_line(capsys.readouterr().err)
    # the file form takes them too
    path = tmp_path / "chain.json"
    path.write_text(json.dumps({"segments": [{"a": 1, "b": 1, "mass": 0.05}] * 3, "gravity": [0, -9.81]}))
    assert main(["rest", "--manipulator", str(path), "--stable-only", "--json"]) == 0
    sets = json.loads(capsys.readouterr().out)
    assert sets["equilibria"][0]["loads"]["gravity"] == [0.0, -9.81]


def test_weight_capacity_prints_the_librarys_factor(capsys):
    args = ["--n", "6", "--a", "0.04", "--b", "0.05", "--k", "5000", "--L0", "0.05", "--mass", "0.05", "--payload",
            "0.1", "--gravity", "-9.81", "0"]
    assert main(["weight-capacity", *args, "--json"]) == 0
    body = json.loads(capsys.readouterr().out)
    m = to.Manipulator.uniform(6, a=0.04, b=0.05, k=5000.0, L0=0.05, mass=0.05, payload=0.1, gravity=(-9.81, 0.0))
    assert body["factor"] == pytest.approx(to.weight_capacity(m).factor, rel=1e-12)
    assert main(["weight-capacity", "--n", "3"]) == 2
    assert "no weight" in one_error_line(capsys.readouterr().err)
