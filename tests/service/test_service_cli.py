"""The library never imports the service; ``tensegrity-opt`` (service.cli) runs the library's commands and
the service's ``serve`` / ``openapi``; without the service extra those name it and exit with 2."""

from __future__ import annotations

import subprocess
import sys
import tomllib
from pathlib import Path

import pytest
from cli_checks import USAGE_ERRORS, one_error_line

ROOT = Path(__file__).resolve().parents[2]
SERVICE_PACKAGES = ("fastapi", "uvicorn", "starlette", "pydantic_settings", "prometheus_client", "service")


def _python(code: str, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True, cwd=ROOT,
                          timeout=300)


@pytest.mark.slow
def test_the_library_and_its_applications_do_not_import_the_service():
    code = ("import sys\n"
            "import tensegrity_opt, tensegrity_opt.applications.cli, tensegrity_opt.applications.cli.plot\n"
            "import tensegrity_opt.applications.cli.sweep, tensegrity_opt.applications.plots\n"
            "import tensegrity_opt.applications.sweeps\n"
            "tensegrity_opt.applications.cli.build_parser()\n"
            f"print(sorted(m for m in {SERVICE_PACKAGES!r} if m in sys.modules))\n")
    r = _python(code)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "[]"


@pytest.mark.slow
def test_the_console_script_runs_the_library_commands_with_the_same_output():
    lib = subprocess.run([sys.executable, "-m", "tensegrity_opt.applications.cli", "buckling", "--json"],
                         capture_output=True, text=True, cwd=ROOT, timeout=300, check=True).stdout
    svc = subprocess.run([sys.executable, "-m", "service", "buckling", "--json"],
                         capture_output=True, text=True, cwd=ROOT, timeout=300, check=True).stdout
    assert svc == lib and '"critical_force": -0.5727' in svc


@pytest.mark.slow
def test_a_library_command_does_not_import_the_service_packages():
    code = ("import sys\nfrom service.cli import main\n"
            "assert main(['equilibrium', '--dx', '0.1']) == 0\n"
            f"print(sorted(m for m in {SERVICE_PACKAGES[:-1]!r} if m in sys.modules))\n")
    r = _python(code)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip().splitlines()[-1] == "[]"


@pytest.mark.slow
def test_serve_and_openapi_without_the_service_extra_name_it():
    for cmd in ("serve", "openapi"):
        code = ("import sys\n"
                "for name in ('fastapi', 'uvicorn', 'starlette', 'pydantic_settings'):\n"
                "    sys.modules[name] = None        # not installed\n"
                "from service.cli import main\n"
                f"sys.exit(main([{cmd!r}]))\n")
        r = _python(code)
        assert r.returncode == 2, (cmd, r.stdout, r.stderr)
        lines = r.stderr.strip().splitlines()
        assert len(lines) == 1 and "pip install 'tensegrity-opt[service]'" in lines[0], (cmd, r.stderr)


def test_the_library_cli_points_to_the_service_for_its_commands(capsys):
    from tensegrity_opt.applications.cli import build_parser, main

    assert main(["serve", "--port", "1"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "tensegrity-opt serve" in err
    assert "serve" not in build_parser().format_help() and "openapi" not in build_parser().format_help()


def test_the_service_packages_are_an_extra():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    names = lambda reqs: {r.split(";")[0].split(">")[0].split("=")[0].split("[")[0].strip() for r in reqs}  # noqa: E731
    service = names(project["optional-dependencies"]["service"])
    assert {"fastapi", "uvicorn", "pydantic-settings", "prometheus-client", "fastapi-offline"} <= service
    assert not service & names(project["dependencies"])
    assert service <= names(project["optional-dependencies"]["test"])
    assert project["scripts"]["tensegrity-opt"] == "service.cli:main"


def test_nothing_but_the_entry_points_imports_service_main():
    """``service.main`` wires everything; only the entry point imports it (no cycle through it: the
    whole project's import graph is checked for cycles in ``tests/test_architecture.py``)."""
    import grimp

    sys.path.insert(0, str(ROOT))
    try:
        graph = grimp.build_graph("service", "tensegrity_opt", cache_dir=None)
    finally:
        sys.path.remove(str(ROOT))
    importers = graph.find_modules_that_directly_import("service.main")
    assert importers == {"service.cli"}


# ---------------------------------------------------------------------------- the console script's help and errors
def _parsers(parser, path=("tensegrity-opt",)):
    """Every parser of ``parser``'s tree (the top one, each command, each ``plot`` kind), with its path."""
    import argparse

    yield path, parser
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                yield from _parsers(sub, (*path, name))


def test_every_option_of_every_command_has_help_and_shows_its_default():
    """``tensegrity-opt --help`` and each ``COMMAND --help``: no option without a help text (every ``plot``
    kind, ``serve --log-level`` included), and every help shows the defaults (argparse's
    ``ArgumentDefaultsHelpFormatter`` or ``%(default)s``); walked over the parser, not a snapshot."""
    import argparse

    from service.cli import build_parser

    seen = 0
    for path, p in _parsers(build_parser()):
        shows_defaults = issubclass(p.formatter_class, argparse.ArgumentDefaultsHelpFormatter)
        for a in p._actions:
            if not a.option_strings or a.dest == "help":
                continue
            seen += 1
            assert a.help and a.help.strip(), (" ".join(path), a.option_strings)
            has_default = a.default not in (None, argparse.SUPPRESS) and a.nargs != 0
            if has_default:
                assert shows_defaults or "%(default)" in a.help, (" ".join(path), a.option_strings)
                text = p.format_help()
                assert "(default: " in text, " ".join(path)
    assert seen > 150          # the walk reached the commands and the plot kinds


def test_the_top_help_lists_every_command_group():
    from service.cli import build_parser

    top = build_parser()
    text = " ".join(top.format_help().split())
    for word in ("plot", "sweep", "serve", "openapi", "buckling", "curve", "branch", "atlas", "plan", "simulate",
                 "load-capacity", "figures", "parameter sweeps"):
        assert word in text.split("positional arguments")[0], word     # in the description itself
    sub = next(iter(p for path, p in _parsers(top) if path[1:] == ("plot",)))
    assert "shapes" in sub.format_help() and "torque" in sub.format_help()


@pytest.mark.parametrize("argv,says", USAGE_ERRORS)
def test_a_usage_error_of_the_console_script_is_one_line_and_exit_2(argv, says, capsys):
    """Every bad option of ``tensegrity-opt`` (the console script's parser, ``serve`` included) is one line
    ``error: ...`` on stderr (argparse's usage block left out) and status 2."""
    from service.cli import main as console

    with pytest.raises(SystemExit) as exc:
        console(argv)
    assert exc.value.code == 2
    line = one_error_line(capsys.readouterr().err)
    assert says in line and "--help" in line
