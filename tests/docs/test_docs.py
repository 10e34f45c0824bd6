"""The examples in the package's docstrings run and print what they say."""

import doctest

import pytest

import tensegrity_opt
import tensegrity_opt.analyses.design.follower
import tensegrity_opt.analyses.design.force_sensor
import tensegrity_opt.analyses.design.load_capacity
import tensegrity_opt.analyses.design.stiffness_shaping
import tensegrity_opt.analyses.equilibria.modes
import tensegrity_opt.analyses.paths.continuation
import tensegrity_opt.analyses.paths.simulation


@pytest.mark.parametrize("module", [tensegrity_opt, tensegrity_opt.analyses.paths.continuation,
                                    tensegrity_opt.analyses.paths.simulation,
                                    tensegrity_opt.analyses.design.force_sensor,
                                    tensegrity_opt.analyses.design.stiffness_shaping,
                                    tensegrity_opt.analyses.design.load_capacity,
                                    tensegrity_opt.analyses.design.follower,
                                    tensegrity_opt.analyses.equilibria.modes])
def test_docstring_examples(module):
    result = doctest.testmod(module, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert result.attempted > 0 and result.failed == 0


# ---------------------------------------------------------------------------- the README
import json  # noqa: E402
import re  # noqa: E402
from pathlib import Path  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
README = (ROOT / "README.md").read_text(encoding="utf-8")


def _table_rows(text: str) -> list[str]:
    return [ln.strip() for ln in text.splitlines() if ln.startswith("| ") and not ln.startswith("|---")]


def test_the_readme_benchmark_table_is_rows_of_results_md():
    """The README's table had fallen behind benchmarks/RESULTS.md: every row it shows must be a row there."""
    block = re.search(r"<!-- benchmark-table[^>]*-->(.*?)<!-- /benchmark-table -->", README, re.S)
    assert block, "the README's benchmark table markers"
    rows = _table_rows(block.group(1))
    results = set(_table_rows((ROOT / "benchmarks" / "RESULTS.md").read_text(encoding="utf-8")))
    assert len(rows) > 10
    assert [r for r in rows if r not in results] == []
    date = re.search(r"`python -m benchmarks` on (\d{4}-\d\d-\d\d)T(\d\d:\d\d)",
                     (ROOT / "benchmarks" / "RESULTS.md").read_text(encoding="utf-8"))
    assert date and f"{date.group(1)} {date.group(2)} UTC" in README          # and says which run


def test_the_readme_set_up_names_the_prerequisites():
    setup = README.split("## Set-up on a fresh machine", 1)[1].split("\n## ", 1)[0]
    assert "python3 -m venv .venv && . .venv/bin/activate" in setup
    assert setup.index("python3 -m venv") < setup.index("pip install '.[service]'")      # before installing
    assert "gcc" in setup and "virtual machine" in setup                              # the compiler, and without it
    assert "apt-get install chromium chromium-driver" in setup
    assert "minutes on 2 cores" in setup and "second terminal" in setup and "serve &" in setup


def test_the_readme_figure_examples_are_valid_bodies():
    """The ``curl`` bodies for ``POST /v1/plots/curve`` (PNG, SVG) validate against the figure's schema."""
    pytest.importorskip("fastapi")
    from service.schemas.plots import PlotCurveRequest

    bodies = re.findall(r"/v1/plots/curve -H 'Content-Type: application/json' \\\s*-d '([^']*)' -o (\S+)", README)
    assert len(bodies) >= 2
    formats = set()
    for body, out in bodies:
        req = PlotCurveRequest.model_validate_json(body)
        fmt = req.format or "png"
        assert out.endswith("." + fmt)
        formats.add(fmt)
        json.loads(body)
    assert formats == {"png", "svg"}


def test_getting_started_code_lines_fit_the_page():
    """The first page a user reads: its commands and examples fit a code block's width without wrapping."""
    page = (ROOT / "docs" / "getting-started.md").read_text(encoding="utf-8")
    long = [line for block in re.findall(r"```[a-z]*\n(.*?)```", page, re.S) for line in block.splitlines()
            if len(line) > 88]
    assert not long, long
