"""The result contract across the library: every result type says whether it worked the same way.

Each package's tests reach every status of its results by real calls (``tests/analyses/*/test_*results.py``,
``tests/applications/sweeps``); here the contract's shape is checked for all of them at once: which classes
follow it, their vocabularies, their immutability, and that the top-level namespace exposes no result outside it.
"""

from __future__ import annotations

import dataclasses
import inspect
import re

import tensegrity_opt as to
from tensegrity_opt import results
from tensegrity_opt.outcome import Outcome, outcome_classes

#: Public classes of the top level that are not results (the model, the stateful steppers, the control spec).
NOT_RESULTS = {"Segment", "Manipulator", "Tracker", "Control", "PreloadController", "PreloadFollower"}
#: Records inside results that carry no outcome of their own (facts about a path or a solve).
PLAIN_RECORDS = {"Mode", "Jump", "BranchEvent", "BoundaryPoint", "AtlasCrossing", "SolverInfo", "Outcome",
                 "ActiveBound", "RootBox"}


def _public_classes(module, names):
    return {n: getattr(module, n) for n in names if inspect.isclass(getattr(module, n))}


def test_every_top_level_result_follows_the_contract():
    classes = _public_classes(to, to.__all__)
    res = {n: c for n, c in classes.items() if n not in NOT_RESULTS and not issubclass(c, Exception)}
    assert res, "no result classes found"
    missing = sorted(n for n, c in res.items() if not issubclass(c, Outcome))
    assert not missing, f"results outside the contract: {missing}"
    # the main results are the top level's; the results module holds them all
    assert set(res) <= set(results.__all__)


def test_every_result_record_either_follows_the_contract_or_is_a_plain_record():
    for name, cls in _public_classes(results, results.__all__).items():
        assert issubclass(cls, Outcome) or name in PLAIN_RECORDS, name


def test_vocabularies_are_closed_words_with_meanings():
    word = re.compile(r"^[a-z][a-z0-9_]*$")
    for cls in outcome_classes():
        assert cls.STATUSES, cls.__name__             # SUCCESS may be empty: a CurveEnd is never a success
        assert set(cls.SUCCESS) <= set(cls.STATUSES), cls.__name__
        for status, meaning in cls.STATUSES.items():
            assert word.match(status), (cls.__name__, status)           # a word, not prose or a solver string
            assert isinstance(meaning, str) and len(meaning) > 10, (cls.__name__, status)


def test_results_are_frozen_dataclasses():
    for cls in outcome_classes():
        if not cls.__module__.startswith("tensegrity_opt"):
            continue
        assert dataclasses.is_dataclass(cls), cls.__name__
        assert cls.__dataclass_params__.frozen, cls.__name__
        assert "success" not in {f.name for f in dataclasses.fields(cls)}, cls.__name__   # derived, never stored


def test_success_is_derived_from_status_for_every_vocabulary_word():
    class Probe(Outcome):
        STATUSES = {"done": "it is done, completely", "stopped": "it stopped before the end"}
        SUCCESS = frozenset({"done"})

        def __init__(self, status):
            self.status, self.message = status, f"probe {status}"

    assert Probe("done").success and not Probe("stopped").success
    assert list(Probe("stopped").outcome()) == ["success", "status", "message"]
    try:
        Probe("Solve_Succeeded")._check_outcome()
    except ValueError as exc:
        assert "Solve_Succeeded" in str(exc)
    else:
        raise AssertionError("a status outside the vocabulary was accepted")
