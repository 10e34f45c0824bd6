"""Library time limits: ``to.time_limit`` / ``timeout=`` stop a computation with ``TimeLimitError``,
never with a result, and IPOPT's own wall-time stop is reported the same way."""

from __future__ import annotations

import time

import numpy as np
import pytest
from clocks import tick_clock

import tensegrity_opt as to
from tensegrity_opt.numerics import design_nlp as design_solvers
from tensegrity_opt.timelimit import check_time, remaining

ALL = ("a", "b", "k", "L0")


def test_time_limit_nests_and_validates():
    assert remaining() is None
    with to.time_limit(10):
        outer = remaining()
        with to.time_limit(100):                   # the earlier deadline wins
            assert remaining() <= outer
        with to.time_limit(0.01):
            time.sleep(0.02)
            with pytest.raises(to.TimeLimitError) as err:
                check_time("this block")
            assert err.value.code == "timeout" and isinstance(err.value, RuntimeError)
        check_time()                               # the outer limit again
    assert remaining() is None
    for bad in (0, -1, float("nan"), "soon"):
        with pytest.raises(to.InvalidParameterError) as err, to.time_limit(bad):
            pass
        assert err.value.field == "time_limit"


def test_design_solve_stops_inside_ipopt_at_the_limit(monkeypatch):
    # unlimited, this solve runs ~3 s of IPOPT iterations (and ends infeasible); the library's clock moves on 1 s at
    # every reading, once an IPOPT iteration (tests/support/clocks.py): a limit of 20 s stops it after some 20
    # iterations on any machine
    m = to.Manipulator.uniform(16)
    design_solvers.buckling_design_nlp(16, True)   # build first: the build itself is not cut
    with monkeypatch.context() as patched:
        clock = tick_clock(patched, step=1.0)
        with pytest.raises(to.TimeLimitError) as err:
            to.maximize_critical_force(m, vary=ALL, timeout=20.0)
    assert err.value.status == "User_Requested_Stop"          # stopped by the callback inside IPOPT
    assert 5 < clock.readings < 100
    # the same solve without a limit is a verified design (the limit left nothing behind)
    d = to.maximize_critical_force(to.Manipulator.uniform(4), vary=("k",), bounds={"k": (0.2, 5.0)},
                                   budget={"k": 4.0}, timeout=30)
    assert d.success and d.critical_force == pytest.approx(to.critical_force(d.manipulator).force)


def test_ipopt_wall_time_status_is_a_time_limit_error_not_a_result():
    class Stopped:
        def __call__(self, **kw):
            return {"x": np.zeros(3), "lam_g": np.zeros(1), "lam_x": np.zeros(3)}

        def stats(self):
            return {"success": False, "return_status": "Maximum_WallTime_Exceeded", "iter_count": 7}

    with pytest.raises(to.TimeLimitError) as err:
        design_solvers._run(Stopped(), None, None, None, None, None, None)
    assert err.value.status == "Maximum_WallTime_Exceeded"


