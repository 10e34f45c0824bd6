"""The result contract on the paths package: every result says whether it worked the same way.

Each result class (and each sub-record with an outcome of its own) derives from ``Outcome``: a closed, documented
vocabulary of snake_case statuses, ``success`` derived from ``status``, a sentence in ``message``, ``to_dict()``
starting with the three, immutable once returned (frozen, arrays read-only, sequences tuples). The events of a
path (``BranchEvent``, ``Jump``, ``BoundaryPoint``, ``AtlasCrossing``) are facts, not outcomes: immutable too.
"""

from __future__ import annotations

import dataclasses
import re

import numpy as np
import pytest
from clocks import tick_clock

import tensegrity_opt as to
from tensegrity_opt.analyses.paths.atlas import AtlasTarget, atlas_target
from tensegrity_opt.analyses.paths.curves import POINT_STATUSES, CurveEnd
from tensegrity_opt.outcome import Outcome

PAPER = to.Manipulator.uniform(4, a=1.0, b=1.0, k=1.0, L0=1.0)
BISTABLE = to.Manipulator.uniform(3, a=0.5, b=1.0, k=1.0, L0=1.0)
RESULTS = (to.Curve, CurveEnd, to.Branch, to.LimitLoad, to.StabilityBoundary, to.StabilityAtlas, AtlasTarget,
           to.Simulation, to.results.SimulationEvent)
EVENTS = (to.results.BranchEvent, to.results.Jump)


@pytest.mark.parametrize("cls", RESULTS, ids=lambda c: c.__name__)
def test_each_result_declares_a_closed_documented_vocabulary(cls):
    assert issubclass(cls, Outcome)
    assert cls.STATUSES and set(cls.SUCCESS) <= set(cls.STATUSES)
    for status, meaning in cls.STATUSES.items():
        assert re.fullmatch(r"[a-z][a-z_]*", status), status               # a word, no prose, no solver string
        assert isinstance(meaning, str) and len(meaning) > 10, status       # documented
    assert dataclasses.is_dataclass(cls) and cls.__dataclass_params__.frozen


@pytest.mark.parametrize("cls", EVENTS, ids=lambda c: c.__name__)
def test_events_are_facts_not_outcomes(cls):
    assert not issubclass(cls, Outcome) and cls.__dataclass_params__.frozen


def _check(result: Outcome) -> None:
    """The contract on one returned result, all the way down."""
    assert result.status in type(result).STATUSES
    assert result.success == (result.status in type(result).SUCCESS)
    assert isinstance(result.message, str) and result.message
    d = result.to_dict()
    assert list(d)[:3] == ["success", "status", "message"]
    assert (d["success"], d["status"], d["message"]) == (result.success, result.status, result.message)
    with pytest.raises(dataclasses.FrozenInstanceError):
        result.status = "changed"                                          # type: ignore[misc]
    for f in dataclasses.fields(result):
        v = getattr(result, f.name)
        assert not isinstance(v, list), f.name
        if isinstance(v, np.ndarray):
            assert not v.flags.writeable, f.name
            with pytest.raises(ValueError):
                v[...] = 0
    for f in dataclasses.fields(result):
        v = getattr(result, f.name)
        for item in (v if isinstance(v, tuple) else (v,)):
            for sub in (item if isinstance(item, tuple) else (item,)):
                if isinstance(sub, to.Curve):               # a followed branch: NaN where it does not reach
                    assert sub.success and isinstance(sub.point_status, tuple)
                elif isinstance(sub, Outcome) and not isinstance(sub, to.Equilibrium):
                    _check(sub)
                elif dataclasses.is_dataclass(sub) and not isinstance(sub, type):
                    for g in dataclasses.fields(sub):
                        w = getattr(sub, g.name)
                        assert not isinstance(w, np.ndarray) or not w.flags.writeable, (type(sub), g.name)


def test_a_complete_curve_and_its_points():
    c = to.force_deflection(PAPER, np.linspace(0.0, 0.5, 6), branch="all")
    _check(c)
    assert c.success and c.status == "complete" and c.ended_at is None
    assert c.point_status[0] == "straight" and set(c.point_status[1:]) == {"converged"}
    assert set(c.point_status) <= set(POINT_STATUSES)
    assert c.solver[0].status == "straight" and all(s.status == "Newton_Converged" for s in c.solver[1:])
    d = c.to_dict()
    assert [p["status"] for p in d["points"]] == list(c.point_status)
    assert all(set(p["solver"]) == {"status", "iterations"} for p in d["points"])
    assert "complete" not in d and "note" not in d
    for b in c.branches:                                                   # a followed branch: absent where gone
        assert set(b.point_status) <= {"converged", "absent"}
        assert all((s is None) == (p == "absent") for s, p in zip(b.solver, b.point_status))


def test_a_partial_curve_is_no_success_and_says_where():
    c = to.force_deflection(PAPER, [0.5, 1.0, 7.9])      # 7.9: outside the closed range's workspace
    _check(c)
    assert not c.success and c.status == c.ended_at.status == "no_stable_equilibrium"
    assert not c.ended_at.success and "1 and dx = 7.9" in c.message
    assert c.to_dict()["ended_at"] == {"success": False, "status": "no_stable_equilibrium",
                                       "message": c.ended_at.message, "dx": 7.9, "dy": 0.0}


def test_branches_and_their_events(monkeypatch):
    br = to.trace_branch(PAPER, np.zeros(4), "guided", t_max=1.0)
    _check(br)
    assert br.success and br.status == "t_max" and br.branch_points and br.manipulator is PAPER
    with monkeypatch.context() as patched:              # one reading of the library's clock a point: 20 points
        tick_clock(patched, step=1.0)
        cut = to.trace_branch(to.Manipulator.uniform(20), np.zeros(20), "guided", max_points=5000, timeout=20.0)
    _check(cut)
    assert cut.status == "time_limit" and not cut.success and 1 <= len(cut) < 100
    for ev in br.events:
        assert not ev.q.flags.writeable
        with pytest.raises(dataclasses.FrozenInstanceError):
            ev.t = 0.0                                                      # type: ignore[misc]


def test_limit_loads_say_how_the_path_ended():
    found = to.limit_load(PAPER, boundary="guided", start=np.zeros(4))
    _check(found)
    assert found.status == "stability_lost" and found.kind == "bifurcation" and found.success
    smooth = to.limit_load(to.Manipulator([to.Segment(1, 1, 1, (1.02, 0.98))] * 4), max_load=0.01)
    _check(smooth)
    assert smooth.status == "max_load" and smooth.kind == "none" and smooth.success
    d = found.to_dict(include_branch=True)
    assert "reason" not in d and d["branch_status"] == found.branch.status and d["branch"]["success"]


def test_a_stability_boundary():
    b = to.stability_boundary(PAPER, p_min=-0.02, p_max=0.02, max_points=20)
    _check(b)
    assert b.success and b.kind == "fold"


def test_an_atlas_and_its_targets():
    at = to.stability_atlas(BISTABLE, [0.2, 0.8], [0.3])
    _check(at)
    assert at.status == "complete" and all(t.status == "solved" for row in at.targets for t in row)
    assert isinstance(at.targets, tuple) and all(isinstance(row, tuple) for row in at.targets)
    far = atlas_target(BISTABLE, 100.0, 0.0)
    _check(far)
    assert far.status == "unreachable" and far.success and far.count == 0
    late = AtlasTarget(0.2, 0.3, error="time_limit: not computed")
    assert late.status == "time_limit" and not late.success and late.message == late.error
    failed = AtlasTarget(0.2, 0.3, error="solver_failed: stored equilibrium did not re-solve")
    assert failed.status == "failed" and not failed.success


def test_a_simulation_and_its_snaps():
    fy = np.concatenate([np.linspace(0.0, 0.3, 7), np.linspace(0.3, 0.0, 7)[1:]])
    sim = to.simulate(BISTABLE, loads=np.column_stack([0 * fy, fy]))
    _check(sim)
    assert sim.status == "complete" and sim.snaps
    assert all(e.status == "landed" and e.success and e.q_after is not None for e in sim.snaps)


def test_the_batch_stays_a_list_of_outcomes():
    """Each target already carries its own outcome (an Equilibrium, or the exception saying why not): the batch
    as a whole has none of its own."""
    out = to.solve_equilibria_batch(PAPER, [(0.05, 0.0), (20.0, 0.0), (0.1, 0.0)])
    assert isinstance(out, list) and len(out) == 3
    assert isinstance(out[0], to.Equilibrium) and out[0].success and isinstance(out[2], to.Equilibrium)
    assert isinstance(out[1], to.UnreachableTargetError)


