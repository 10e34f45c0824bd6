"""The result contract of the equilibria package: ``EquilibriumSet``, ``Buckling``, ``Landscape`` and
``Equilibrium`` each declare a closed status vocabulary, every status is reached by a real call (the homotopy's
failures through a stand-in for the ``phc`` run), ``success`` follows ``status``, ``to_dict()`` starts with
``success``, ``status``, ``message``, and a returned result cannot be changed."""

from __future__ import annotations

import dataclasses
import os
import re

import numpy as np
import pytest

import tensegrity_opt as to
from tensegrity_opt.numerics import homotopy
from tensegrity_opt.numerics.homotopy import HomotopySolve, homotopy_available
from tensegrity_opt.outcome import Outcome

PAPER = to.Manipulator.uniform(4)
#: Two heterogeneous segments: two equilibria at (dx, dy) = (0.5, 0.2), a cheap homotopy (8 paths).
PAIR = to.Manipulator([to.Segment(0.5, 1.0, 1.0, 0.6), to.Segment(0.7, 1.1, 1.0, 0.8)])
#: A chain with a bistable segment: nine unloaded equilibria, four of them stable.
BISTABLE = to.Manipulator.uniform(2, a=0.6, b=1.0, L0=0.7)

needs_phc = pytest.mark.skipif(not homotopy_available() and os.environ.get("TENSEGRITY_REQUIRE_PHC") != "1",
                               reason="PHCpack's phc is not installed (apt-get install phcpack)")

RESULTS = (to.EquilibriumSet, to.Buckling, to.Landscape, to.Equilibrium)


# ----------------------------------------------------------------------------- a stand-in for the phc run
def _displacement_roots(eqs) -> np.ndarray:
    """The homotopy's unknowns ``z_j = exp(i q_j / 2)``, ``g = Fx + i Fy``, ``h = Fx - i Fy`` of each
    equilibrium (:mod:`tensegrity_opt.numerics.homotopy`)."""
    return np.array([np.concatenate([np.exp(0.5j * e.q), [complex(e.fx, e.fy), complex(e.fx, -e.fy)]])
                     for e in eqs])


def _stand_in(roots: np.ndarray, failures: int):
    """A ``solve_*homotopy`` that reports ``roots`` (all regular) and ``failures`` failed paths."""
    def solve(*args, **kwargs) -> HomotopySolve:
        return HomotopySolve(roots=roots, regular=np.ones(len(roots), dtype=bool), paths=len(roots) + failures,
                             failures=failures, at_infinity=0, singular=0, seconds=0.0)
    return solve


def _homotopy_set(monkeypatch, failures: int = 0, extra=()) -> to.EquilibriumSet:
    """``find_equilibria(PAIR, 0.5, 0.2, method="homotopy")`` with the phc run replaced by a report of the two
    true roots (from the search), ``failures`` failed paths and the ``extra`` configurations as more roots."""
    search = to.find_equilibria(PAIR, 0.5, 0.2)
    roots = _displacement_roots(search)
    if len(extra):
        bogus = np.array([np.concatenate([np.exp(0.5j * np.asarray(q)), [0.1 + 0.0j, 0.1 + 0.0j]]) for q in extra])
        roots = np.vstack([roots, bogus])
    monkeypatch.setenv("TENSEGRITY_HOMOTOPY_ENGINE", "polyhedral")     # the stand-in replaces the polyhedral solve
    monkeypatch.setattr(homotopy, "solve_homotopy", _stand_in(roots, failures))
    return to.find_equilibria(PAIR, 0.5, 0.2, method="homotopy")


# ----------------------------------------------------------------------------- the vocabularies
@pytest.mark.parametrize("cls", RESULTS, ids=lambda c: c.__name__)
def test_each_result_declares_a_closed_vocabulary(cls):
    assert issubclass(cls, Outcome)
    assert cls.STATUSES and set(cls.SUCCESS) <= set(cls.STATUSES)
    for status, meaning in cls.STATUSES.items():
        assert re.fullmatch(r"[a-z]+(_[a-z]+)*", status), status
        assert isinstance(meaning, str) and len(meaning) > 20
    fields = {f.name for f in dataclasses.fields(cls)}
    assert "success" not in fields                   # derived from status, never stored


def test_equilibrium_set_statuses():
    assert set(to.EquilibriumSet.STATUSES) == {"certified", "uncertified", "searched", "exact"}
    assert to.EquilibriumSet.SUCCESS == {"certified", "searched", "exact"}


# ----------------------------------------------------------------------------- every status reached
@pytest.mark.slow
def test_searched_sets():
    eqs = to.find_equilibria(PAPER, 0.1)
    assert (eqs.status, eqs.method, eqs.success, eqs.certified) == ("searched", "search", True, False)
    assert "Newton_Converged" in eqs.message and len(eqs) == 6
    loaded = to.find_equilibria_under_force(PAPER, -0.3, 0.0)
    assert (loaded.status, loaded.method, loaded.success, loaded.certified) == ("searched", "search", True, False)
    stable = to.find_equilibria_under_force(PAPER, -0.3, 0.0, stable_only=True)
    assert stable.status == "searched" and [e.q.tolist() for e in stable] == [e.q.tolist() for e in loaded
                                                                              if e.stable]


def test_exact_sets():
    straight = to.find_equilibria(PAPER, 0.0, 0.0)
    assert (straight.status, straight.method, straight.certified, len(straight)) == ("exact", "straight", True, 1)
    assert straight[0].status == "exact" and straight[0].solver.status == "straight"
    one = to.Manipulator.uniform(1)
    x, y = one.tip(np.array([0.3]))
    single = to.find_equilibria(one, one.straight_length - x, y)
    assert (single.status, single.method, single.certified) == ("exact", "closed_form", True)
    assert single[0].q[0] == pytest.approx(0.3, abs=1e-12)
    rest = to.find_equilibria_under_force(BISTABLE)
    assert (rest.status, rest.method, rest.certified, len(rest)) == ("exact", "exact", True, 9)
    assert rest.message.endswith(": 9 points") and all(e.status == "exact" for e in rest)
    wells = to.find_equilibria_under_force(BISTABLE, stable_only=True)
    assert wells.status == "exact" and len(wells) == 4 and wells.message.endswith(": 4 minima")


def test_an_empty_set_is_an_answer():
    """The straight chain of an asymmetrically preloaded chain is not an equilibrium: at full extension no
    equilibrium exists, which is an exact answer and a success."""
    bent = to.Manipulator.uniform(3, k=(1.0, 1.5), L0=(1.0, 0.9))
    none = to.find_equilibria(bent, 0.0, 0.0)
    assert len(none) == 0 and not none and list(none) == []
    assert (none.status, none.success, none.certified) == ("exact", True, True)
    assert "not an equilibrium" in none.message
    assert none.to_dict()["equilibria"] == [] and none.to_dict()["success"] is True


@pytest.mark.slow
def test_homotopy_certified_and_uncertified_through_a_stand_in(monkeypatch):
    cert = _homotopy_set(monkeypatch, failures=0)
    assert (cert.status, cert.success, cert.certified, cert.method) == ("certified", True, True, "homotopy")
    assert len(cert) == 2 and cert.paths == 2 and cert.failed_paths == 0
    failed = _homotopy_set(monkeypatch, failures=3)
    assert (failed.status, failed.success, failed.certified) == ("uncertified", False, False)
    assert failed.failed_paths == 3 and "3 failed" in failed.message and len(failed) == 2
    # a real root inside the range that does not polish onto an equilibrium: the message says so
    lost = _homotopy_set(monkeypatch, failures=0, extra=[[0.4, -0.3]])
    assert (lost.status, lost.success) == ("uncertified", False)
    assert "1 real roots did not polish" in lost.message and len(lost) == 2


def test_the_force_homotopy_uncertified_through_a_stand_in(monkeypatch):
    loaded = to.find_equilibria_under_force(PAIR, -0.2, 0.05)
    roots = np.array([np.exp(0.5j * e.q) for e in loaded])
    monkeypatch.setenv("TENSEGRITY_HOMOTOPY_ENGINE", "polyhedral")     # the stand-in replaces the polyhedral solve
    monkeypatch.setattr(homotopy, "solve_force_homotopy", _stand_in(roots, 1))
    eqs = to.find_equilibria_under_force(PAIR, -0.2, 0.05, method="homotopy")
    assert (eqs.status, eqs.success, eqs.method, eqs.failed_paths) == ("uncertified", False, "homotopy", 1)
    assert len(eqs) == len(loaded)
    monkeypatch.setattr(homotopy, "solve_force_homotopy", _stand_in(roots, 0))
    assert to.find_equilibria_under_force(PAIR, -0.2, 0.05, method="homotopy").status == "certified"


@needs_phc
def test_homotopy_certified_by_phc():
    eqs = to.find_equilibria(PAIR, 0.5, 0.2, method="homotopy")
    assert (eqs.status, eqs.success, eqs.certified) == ("certified", True, True)
    assert eqs.message.startswith("phc (") and eqs.paths == 8 and eqs.seconds > 0.0
    loaded = to.find_equilibria_under_force(PAIR, -0.2, 0.05, method="homotopy")
    assert loaded.status == "certified" and loaded.method == "homotopy"


def test_equilibrium_statuses(monkeypatch):
    assert to.solve_equilibrium(PAPER, 0.1).status == "converged"
    assert to.solve_equilibrium(PAPER, 0.0).status == "exact"
    rest = to.rest_configuration(BISTABLE)
    assert (rest.status, rest.solver.status) == ("exact", "exact") and "product" in rest.message
    _homotopy_set(monkeypatch)                          # installs the stand-in: two true roots, no failure
    best = to.solve_equilibrium(PAIR, 0.5, 0.2, method="homotopy")
    assert (best.status, best.solver.status) == ("certified", "homotopy (certified)")
    _homotopy_set(monkeypatch, failures=1)
    best = to.solve_equilibrium(PAIR, 0.5, 0.2, method="homotopy")
    assert best.status == "converged" and best.solver.status.startswith("homotopy (NOT certified: phc (")


def test_buckling_and_landscape_statuses():
    bk = to.critical_force(PAPER)
    assert (bk.status, bk.success) == ("solved", True) and bk.message.startswith("all 3 critical loads")
    sparse = to.critical_force(to.Manipulator.uniform(300), n_modes=2)
    assert sparse.status == "solved" and sparse.message.startswith("the lowest 2 of 299")
    land = to.energy_landscape(PAPER, 0.1, grid=9)
    inside = int(np.isfinite(land.energy).sum())
    assert (land.status, land.success) == ("evaluated", True) and f"{inside} of 162 points" in land.message


# ----------------------------------------------------------------------------- to_dict and immutability
@pytest.mark.parametrize("make", [
    lambda: to.find_equilibria(PAPER, 0.1),
    lambda: to.find_equilibria_under_force(BISTABLE),
    lambda: to.critical_force(PAPER, "free"),
    lambda: to.energy_landscape(PAPER, 0.1, grid=5),
    lambda: to.rest_configuration(BISTABLE),
], ids=["equilibria", "rest", "buckling", "landscape", "equilibrium"])
def test_to_dict_starts_with_the_outcome(make):
    r = make()
    d = r.to_dict()
    assert list(d)[:3] == ["success", "status", "message"]
    assert d["success"] is r.success is (r.status in r.SUCCESS)
    assert d["status"] == r.status and d["message"] == r.message and d["message"]


def test_an_equilibrium_set_is_a_read_only_sequence():
    eqs = to.find_equilibria(PAPER, 0.1)
    assert isinstance(eqs.equilibria, tuple) and len(eqs) == 6 and bool(eqs)
    assert list(eqs) == list(eqs.equilibria) and eqs[0] is eqs.equilibria[0] and eqs[-1] is eqs.equilibria[5]
    assert eqs[1:3] == eqs.equilibria[1:3] and isinstance(eqs[1:3], tuple)
    assert [e.kind for e in reversed(eqs)][0] == "maximum"
    for name, value in (("status", "certified"), ("method", "homotopy"), ("equilibria", ()), ("paths", 1)):
        with pytest.raises(dataclasses.FrozenInstanceError):
            setattr(eqs, name, value)
    with pytest.raises(TypeError):
        eqs[0] = eqs[1]
    assert not hasattr(eqs, "append") and not hasattr(eqs, "sort")
    with pytest.raises(ValueError):
        eqs[0].q[0] = 1.0
    with pytest.raises(ValueError, match="status"):
        to.EquilibriumSet([], method="search", status="phc: 8 paths", message="")


def test_buckling_and_its_modes_are_immutable():
    bk = to.critical_force(PAPER)
    assert isinstance(bk.modes, tuple)
    for a in (bk.loads, bk.modes[0].q, bk.modes[0].vector):
        assert not a.flags.writeable
        with pytest.raises(ValueError):
            a[0] = 0.0
    with pytest.raises(dataclasses.FrozenInstanceError):
        bk.force = 0.0
    with pytest.raises(dataclasses.FrozenInstanceError):
        bk.modes[0].load = 0.0
    assert not isinstance(bk.modes[0], Outcome)        # a record of the result, no outcome of its own


def test_landscape_is_immutable_and_leaves_the_callers_axes_alone():
    axis = np.linspace(-0.5, 0.5, 5)
    land = to.energy_landscape(PAPER, 0.1, grid=(axis, axis))
    for a in (land.qi, land.qj, land.energy, land.q):
        assert not a.flags.writeable
    assert axis.flags.writeable
    axis[0] = -0.4                                     # the caller's array stays the caller's
    assert land.qi[0] == -0.5
    with pytest.raises(dataclasses.FrozenInstanceError):
        land.pair = (1, 2)
