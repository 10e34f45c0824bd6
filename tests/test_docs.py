"""The examples in the package's docstrings run and print what they say."""

import doctest

import pytest

import tensegrity_opt
import tensegrity_opt.analyses.continuation
import tensegrity_opt.analyses.force_sensor
import tensegrity_opt.analyses.simulation
import tensegrity_opt.analyses.stiffness_design


@pytest.mark.parametrize("module", [tensegrity_opt, tensegrity_opt.analyses.continuation,
                                    tensegrity_opt.analyses.simulation, tensegrity_opt.analyses.force_sensor,
                                    tensegrity_opt.analyses.stiffness_design])
def test_docstring_examples(module):
    result = doctest.testmod(module, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert result.attempted > 0 and result.failed == 0
