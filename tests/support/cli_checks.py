"""What the command lines' tests share: the usage errors both parsers (the library's ``tensegrity_opt.applications.cli``
and the console script's ``service.cli``) answer with one line and status 2, and the check of that line."""

#: ``(argv, what the error line names)``: a bad option of each kind, through either parser.
USAGE_ERRORS = [
    (["curve", "--num", "-1"], "--num"), (["curve", "--num", "0"], "--num"), (["curve", "--n", "0"], "--n"),
    (["buckling", "--n", "-2"], "--n"), (["plot", "torque", "--num", "0", "-o", "t.png"], "--num"),
    (["sweep", "spec.json", "--workers", "x"], "--workers"), (["curve", "--frobnicate"], "frobnicate"),
    ([], "COMMAND"), (["plot"], "KIND"), (["serve", "--port", "-5"], "--port"),
    # a chain too long to build answers at once instead of hanging (it allocated n x n matrices for n = 1e9)
    (["buckling", "--n", "1000000000"], "at most 10000 segments"), (["curve", "--n", "10001"], "at most"),
]


def one_error_line(err: str) -> str:
    """The one line of ``err``: ``tensegrity-opt ... error: ...``, no traceback."""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err, err
    assert lines[0].startswith("tensegrity-opt") and "error: " in lines[0], err
    return lines[0]


def writes_png_and_svg(main, argvs, tmp_path, capsys) -> None:
    """Each command of ``argvs`` (run by ``main``) writes a PNG and an SVG, by the output's suffix, and says so."""
    for argv in argvs:
        for suffix in ("png", "svg"):
            out = tmp_path / f"fig.{suffix}"
            assert main([*argv, "-o", str(out), "--dpi", "40"]) == 0, capsys.readouterr().err
            assert f"wrote {out}" in capsys.readouterr().out
            data = out.read_bytes()
            assert data[:4] == b"\x89PNG" if suffix == "png" else b"<svg" in data[:400]


def refuses_together(main, argv: list[str], first: str, second: str, capsys) -> None:
    """``main(argv)``, which gives the options ``first`` and ``second`` that exclude each other, is refused
    at parse time: one line ``... error: ...`` on stderr naming both, nothing on stdout, exit status 2."""
    import pytest

    with pytest.raises(SystemExit) as exc:
        main(argv)
    assert exc.value.code == 2
    out, err = capsys.readouterr()
    line = one_error_line(err)
    assert first in line and second in line and out == "", (argv, err)
