"""Every result of the design package follows the result contract (``tensegrity_opt/outcome.py``)."""

import dataclasses
import re

import pytest

import tensegrity_opt as to
from tensegrity_opt.outcome import Outcome

RESULTS = [to.Design, to.PreloadDesign, to.StiffnessDesign, to.LoadCapacity, to.results.PreloadStep, to.PreloadPlan,
           to.results.FollowerStep, to.ForceEstimate]


@pytest.mark.parametrize("cls", RESULTS, ids=lambda c: c.__name__)
def test_a_closed_vocabulary_success_derived_and_frozen(cls):
    assert issubclass(cls, Outcome)
    assert cls.STATUSES and set(cls.SUCCESS) <= set(cls.STATUSES)
    for status, meaning in cls.STATUSES.items():
        assert re.fullmatch(r"[a-z][a-z_]*", status), status         # short snake_case words, no solver strings
        assert meaning                                                # each one documented
    assert dataclasses.is_dataclass(cls) and cls.__dataclass_params__.frozen
    names = {f.name for f in dataclasses.fields(cls)}
    assert "success" not in names                                    # derived from status, never stored
    assert "iterations" not in names or cls is to.ForceEstimate      # a solver's count lives in `solver`
