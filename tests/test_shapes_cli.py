"""Shape labels and the command line."""

import json
import subprocess
import sys
from pathlib import Path

import pytest

from tensegrity_opt import shape_label, sign_string
from tensegrity_opt.applications.cli import main


@pytest.mark.parametrize("q,label,signs", [
    ([-1, 2, 3, 4], "U", "-+++"), ([1, -2, -3, -4], "U", "+---"),
    ([-1, 2, -3, 4], "Z", "-+-+"), ([1, -2, 3, -4], "Z", "+-+-"),
    ([-1, 2, -3, -4], "ZU", "-+--"), ([1, -2, 3, 4], "ZU", "+-++"),
    ([0, 0, 0, 0], "I", "0000"), ([1, 2, 3, 1e-9], "C", "+++0"),
    ([1, -1, 1, -1, 1], "W4", "+-+-+"),
])
def test_table2_labels(q, label, signs):
    assert shape_label(q) == label
    assert sign_string(q) == signs


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
    assert main(["buckling", "--L0", "0.1", "--a", "0.5"]) == 2
    bad = tmp_path / "m.json"
    bad.write_text('{"segments": [{"a": 1, "b": -1}]}')
    assert main(["buckling", "--manipulator", str(bad)]) == 2
    assert "b must be finite and > 0" in capsys.readouterr().err


def test_console_script_runs():
    r = subprocess.run([sys.executable, "-m", "tensegrity_opt.applications.cli", "buckling"], capture_output=True, text=True,
                       check=True)
    assert "critical force Fx0 = -0.572793" in r.stdout


def test_vectorised_shape_labels_equal_the_row_by_row_labels():
    import numpy as np

    from tensegrity_opt.model.shapes import shape_label, shape_labels

    rng = np.random.default_rng(0)
    Q = rng.standard_normal((3000, 7)) * (rng.random((3000, 7)) > 0.3)
    Q[::11] = 0.0
    Q[5] = [0.0, 0.0, 1e-9, 0.0, 2.0, -1.0, 0.0]          # a tiny angle counts as zero
    assert shape_labels(Q) == [shape_label(q) for q in Q]
    assert shape_labels(np.zeros((0, 4))) == []


# ---------------------------------------------------------------------------- usage errors, help, pipes
@pytest.mark.parametrize("argv", [["curve", "--num", "-1"], ["curve", "--num", "0"], ["equilibrium", "--dx", "nan"],
                                  ["buckling", "--n", "0"], ["plot", "curve", "--num", "-3", "-o", "x.png"]])
def test_a_bad_option_is_one_usage_line_and_exit_2(argv, capsys):
    """A count must be >= 1 and a number finite: argparse's usage error, never a traceback (was a
    numpy ValueError traceback for --num -1)."""
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


def test_a_closed_pipe_is_not_an_error():
    """``tensegrity-opt buckling | head -1``: the reader leaves early; no BrokenPipeError traceback."""
    p = subprocess.Popen([sys.executable, "-m", "tensegrity_opt.applications.cli", "buckling"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=str(Path(__file__).resolve().parents[1]))
    p.stdout.close()                      # nobody reads: the first write fails with EPIPE
    err = p.stderr.read().decode()
    assert p.wait(timeout=120) == 0
    assert "Traceback" not in err and "BrokenPipe" not in err
