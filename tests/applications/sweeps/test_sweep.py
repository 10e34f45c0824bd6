"""Sweeps (``tensegrity_opt.applications.sweeps``): expansion, validation, each analysis against direct library
calls, file round-trips, failing points, skip/resume, cancellation, Dask and the CLI command.

These are integration tests of the sweep machinery: the expected numbers come from the library's
own functions for the same point (the physics is tested elsewhere).
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import math

import numpy as np
import pytest

import tensegrity_opt as to
from tensegrity_opt.applications import sweeps as S
from tensegrity_opt.applications.cli.sweep import add_sweep_parser
from tensegrity_opt.errors import InvalidParameterError
from tensegrity_opt.outcome import Outcome
from tensegrity_opt.serialize import nullable

EXACT = {"rel": 1e-12, "abs": 1e-12}


# --------------------------------------------------------------------------- expansion
def test_grid_expands_as_a_cartesian_product_first_key_slowest():
    spec = {"analysis": "equilibrium", "grid": {"n": [3, 4], "dx": [0.1, 0.2, 0.3]}}
    pts = S.expand(spec)
    assert pts == [{"n": n, "dx": dx} for n in (3, 4) for dx in (0.1, 0.2, 0.3)]
    assert S.count_points(spec) == 6
    assert S.columns(spec)[:3] == ["index", "n", "dx"] and S.columns(spec)[-1] == "error"
    # key order decides the nesting
    assert S.expand({"analysis": "equilibrium", "grid": {"dx": [0.1, 0.2], "n": [3, 4]}})[:2] == [
        {"dx": 0.1, "n": 3}, {"dx": 0.1, "n": 4}]


def test_points_expand_in_order_and_values_are_normalised():
    spec = {"analysis": "equilibrium", "points": [{"dx": 1}, {"n": 5.0, "dy": 0.1}, {"load": [0, 1]}]}
    assert S.expand(spec) == [{"dx": 1.0}, {"n": 5, "dy": 0.1}, {"load": [0.0, 1.0]}]
    assert isinstance(S.expand(spec)[1]["n"], int)
    norm = S.validate_spec(spec)
    assert norm["manipulator"] == {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}
    assert S.validate_spec(norm) == norm                                     # idempotent
    assert S.columns(spec)[:5] == ["index", "n", "dx", "dy", "load"]         # canonical order for points


@pytest.mark.parametrize("spec, field", [
    ([1, 2], "spec"),
    ({"grid": {"n": [4]}}, "analysis"),
    ({"analysis": "bucklin", "grid": {"n": [4]}}, "analysis"),
    ({"analysis": "buckling", "grid": {"n": [4]}, "extra": 1}, "extra"),
    ({"analysis": "buckling"}, "points"),
    ({"analysis": "buckling", "grid": {"n": [4]}, "points": [{}]}, "grid"),
    ({"analysis": "buckling", "grid": {}}, "grid"),
    ({"analysis": "buckling", "grid": {"n": []}}, "grid.n"),
    ({"analysis": "buckling", "grid": {"n": [4, 2.5]}}, "grid.n[1]"),
    ({"analysis": "buckling", "grid": {"n": [4, True]}}, "grid.n[1]"),
    ({"analysis": "buckling", "grid": {"k": [1, -1]}}, "grid.k[1]"),
    ({"analysis": "buckling", "grid": {"a": [float("nan")]}}, "grid.a[0]"),
    ({"analysis": "buckling", "grid": {"dx": [0.1]}}, "grid.dx"),
    ({"analysis": "buckling", "grid": {"m": [1]}}, "grid.m"),
    ({"analysis": "equilibria_count", "grid": {"load": [[0, 1]]}}, "grid.load"),
    ({"analysis": "equilibrium", "grid": {"dx": [0.1], "load": [[0, 1]]}}, "grid.load"),
    ({"analysis": "equilibrium", "grid": {"load": [[0, 1, 2]]}}, "grid.load[0]"),
    ({"analysis": "equilibrium", "grid": {"load": [[0, "x"]]}}, "grid.load[0][1]"),
    ({"analysis": "equilibrium", "points": []}, "points"),
    ({"analysis": "equilibrium", "points": [{"dx": 0.1}, 3]}, "points[1]"),
    ({"analysis": "equilibrium", "points": [{"dx": 0.1}, {"dy": "a"}]}, "points[1].dy"),
    ({"analysis": "equilibrium", "points": [{"dx": 0.1, "load": [1, 2]}]}, "points[0].load"),
    ({"analysis": "equilibrium", "manipulator": {"n": 0}, "points": [{}]}, "manipulator.n"),
    ({"analysis": "equilibrium", "manipulator": {"segments": []}, "points": [{}]}, "manipulator.segments"),
    ({"analysis": "equilibrium", "manipulator": [], "points": [{}]}, "manipulator"),
    ({"analysis": "equilibrium", "points": [{}], "options": {"boundary": "free"}}, "options.boundary"),
    ({"analysis": "buckling", "points": [{}], "options": {"boundary": "fixed"}}, "options.boundary"),
    ({"analysis": "buckling", "points": [{}], "options": {"vary": ["k"]}}, "options.vary"),
    ({"analysis": "buckling", "points": [{}], "options": {"bogus": 1}}, "options.bogus"),
    ({"analysis": "design", "points": [{}], "options": {"vary": ["k", "q"]}}, "options.vary[1]"),
    ({"analysis": "design", "points": [{}], "options": {"vary": []}}, "options.vary"),
    ({"analysis": "design", "points": [{}], "options": {"bounds": {"k": [1]}}}, "options.bounds.k"),
    ({"analysis": "design", "points": [{}], "options": {"budget": {"k": "x"}}}, "options.budget.k"),
])
def test_invalid_specs_name_the_field(spec, field):
    with pytest.raises(InvalidParameterError) as err:
        S.validate_spec(spec)
    assert isinstance(err.value, ValueError)
    assert err.value.field == field
    assert str(err.value).startswith(f"{field}:")


def test_too_many_points_is_refused_before_expanding():
    spec = {"analysis": "buckling", "grid": {"a": [1.0] * 1001, "b": [1.0] * 1001}}
    with pytest.raises(InvalidParameterError) as err:
        S.expand(spec)
    assert err.value.field == "grid"


# --------------------------------------------------------------------------- each analysis = the library
def test_buckling_columns_equal_critical_force():
    spec = {"analysis": "buckling", "manipulator": {"a": 1.0}, "grid": {"n": [2, 4], "k": [0.5, 2.0]},
            "options": {"boundary": "free"}}
    res = S.sweep(spec)
    assert [r["index"] for r in res.rows] == [0, 1, 2, 3] and not res.errors
    for r in res.rows:
        bk = to.critical_force(to.Manipulator.uniform(r["n"], 1.0, 1.0, r["k"], 1.0), "free")
        assert r["critical_force"] == pytest.approx(bk.force, **EXACT)
        assert r["loads"] == pytest.approx(bk.loads.tolist(), **EXACT)
        assert r["load2"] == (pytest.approx(bk.loads[1], **EXACT) if bk.loads.size > 1 else None)
        assert r["mode_shape"] == bk.modes[0].shape and r["mode_signs"] == bk.modes[0].signs
        assert r["mode_q"] == pytest.approx(bk.modes[0].q.tolist(), **EXACT)
    assert S.evaluate_point(spec, {"n": 4, "k": 2.0}) == {k: v for k, v in res.rows[3].items()
                                                            if k in S.RESULT_COLUMNS["buckling"]}


def res_header(spec):
    from tensegrity_opt.applications.sweeps.spec import _header

    return _header(spec)


def test_a_sweep_of_a_chain_with_loads_is_the_library_under_them():
    """The base chain's gravity and joint forces reach every point (the normal form keeps them); a point's own ``n``
    keeps them too; an analysis that does not honour them is that point's error, named."""
    loads = {"gravity": [0.0, -9.81], "joint_forces": [{"joint": 2, "force": [0.0, 0.1]}]}
    spec = {"analysis": "equilibrium", "manipulator": {"n": 3, "mass": 0.05, **loads},
            "points": [{"dx": 0.4, "dy": 0.2}, {"n": 4, "dx": 0.4}]}
    assert res_header(spec)["manipulator"]["gravity"] == [0.0, -9.81]
    res = S.sweep(spec)
    assert not res.errors
    for r, n, dy in zip(res.rows, (3, 4), (0.2, 0.0)):
        m = to.Manipulator.uniform(n, mass=0.05, gravity=(0.0, -9.81), joint_forces=[(2, (0.0, 0.1))])
        eq = to.solve_equilibrium(m, 0.4, dy)
        assert r["q"] == pytest.approx(eq.q.tolist(), **EXACT) and r["energy"] == pytest.approx(eq.energy, **EXACT)
    bad = S.sweep({**spec, "analysis": "buckling", "points": [{"n": 3}]})
    assert bad.errors and "gravity" in json.dumps(bad.rows[0])


def test_equilibrium_columns_equal_solve_equilibrium_and_force_control():
    spec = {"analysis": "equilibrium", "manipulator": {"n": 4},
            "points": [{"dx": 0.1}, {"n": 5, "dx": 0.2, "dy": 0.05}, {"load": [0.2, 0.1]}]}
    res = S.sweep(spec)
    assert not res.errors
    m4, m5 = to.Manipulator.uniform(4), to.Manipulator.uniform(5)
    for r, eq in zip(res.rows, [to.solve_equilibrium(m4, 0.1), to.solve_equilibrium(m5, 0.2, 0.05),
                                to.solve_equilibrium_under_force(m4, 0.2, 0.1)]):
        assert r["q"] == pytest.approx(eq.q.tolist(), **EXACT)
        assert (r["energy"], r["fx"], r["fy"]) == pytest.approx((eq.energy, eq.fx, eq.fy), **EXACT)
        assert (r["stable"], r["morse_index"], r["kind"], r["shape"], r["signs"]) == \
               (eq.stable, eq.morse_index, eq.kind, eq.shape, eq.signs)
        # the row's status is the result's (its closed vocabulary), the solver's own word beside it
        assert (r["status"], r["solver_status"]) == (eq.status, eq.solver.status)
        assert r["status"] in type(eq).STATUSES
        assert (r["tip_x"], r["tip_y"]) == pytest.approx(tuple(eq.tip), **EXACT)
    # effective parameters: missing n from the base chain, dx/dy None under a tip force
    assert [(r["n"], r["dx"], r["dy"], r["load"]) for r in res.rows] == [
        (4, 0.1, 0.0, None), (5, 0.2, 0.05, None), (4, None, None, [0.2, 0.1])]


def test_stiffness_columns_equal_cartesian_stiffness():
    spec = {"analysis": "stiffness", "grid": {"dx": [0.1, 0.3], "dy": [0.0, 0.05]}}
    res = S.sweep(spec)
    assert not res.errors
    m = to.Manipulator.uniform(4)
    for r in res.rows:
        eq = to.solve_equilibrium(m, r["dx"], r["dy"])
        K = to.cartesian_stiffness(m, eq)
        assert (r["kxx"], r["kxy"], r["kyy"]) == pytest.approx((K[0, 0], K[0, 1], K[1, 1]), **EXACT)
        assert (r["fx"], r["fy"], r["energy"]) == pytest.approx((eq.fx, eq.fy, eq.energy), **EXACT)
    loaded = S.sweep({"analysis": "stiffness", "points": [{"load": [0.2, 0.1]}]}).rows[0]
    eq = to.solve_equilibrium_under_force(m, 0.2, 0.1)
    assert loaded["kxy"] == pytest.approx(to.cartesian_stiffness(m, eq)[0, 1], **EXACT)


def test_equilibria_count_columns_equal_find_equilibria():
    spec = {"analysis": "equilibria_count", "grid": {"n": [3, 4], "dx": [0.0, 0.1]}}
    res = S.sweep(spec)
    assert not res.errors
    for r in res.rows:
        eqs = to.find_equilibria(to.Manipulator.uniform(r["n"]), r["dx"])
        assert r["count"] == len(eqs)
        assert r["n_stable"] == sum(e.stable for e in eqs)
        assert r["n_saddle"] == sum(e.kind == "saddle" for e in eqs)
        assert r["n_maximum"] == sum(e.kind == "maximum" for e in eqs)
        assert r["min_energy"] == pytest.approx(min(e.energy for e in eqs), **EXACT)
    assert res.rows[3]["count"] == 6 and res.rows[3]["n_stable"] == 2     # the paper's chain at dx = 0.1


def test_design_columns_equal_maximize_critical_force():
    opts = {"vary": ["k"], "bounds": {"k": [0.2, 5.0]}, "budget": {"k": 4.0}}
    res = S.sweep({"analysis": "design", "grid": {"n": [3, 4]}, "options": opts})
    assert not res.errors
    assert res.columns[-2:] == ("k_opt", "error")
    for r in res.rows:
        d = to.maximize_critical_force(to.Manipulator.uniform(r["n"]), vary=("k",), bounds={"k": (0.2, 5.0)},
                                       budget={"k": 4.0})
        assert r["critical_force"] == pytest.approx(d.critical_force, **EXACT)
        assert r["multiplicity"] == d.multiplicity and r["active"] == list(d.active)
        assert (r["status"], r["success"], r["solver_status"]) == (d.status, d.success, d.solver.status)
        assert r["status"] in type(d).STATUSES
        assert r["k_opt"] == pytest.approx(d.manipulator.k1.tolist(), **EXACT)
        assert r["initial_critical_force"] == pytest.approx(d.initial_critical_force, **EXACT)


# --------------------------------------------------------------------------- failures, skip, stop
MIXED = {"analysis": "equilibrium", "grid": {"n": [3, 4], "dx": [0.1, 30.0, 0.2]}}


def test_a_failing_point_gets_an_error_and_the_others_succeed():
    res = S.sweep(MIXED)
    assert len(res.rows) == 6
    bad = [r for r in res.rows if r["dx"] == 30.0]
    assert len(bad) == 2 and len(res.errors) == 2
    assert (res.status, res.success) == ("point_errors", True)       # every point ran: the sweep worked
    assert res.message == "6 of 6 points solved, 2 failed"
    for r in bad:
        assert r["error"].startswith("unreachable_target: ")
        assert all(r[c] is None for c in S.RESULT_COLUMNS["equilibrium"])
    for r in res.rows:
        if r["dx"] != 30.0:
            assert r["error"] is None and r["stable"] is True
    with pytest.raises(to.UnreachableTargetError):
        S.evaluate_point(MIXED, {"dx": 30.0})


def test_skip_resumes_and_on_result_streams_every_point():
    full = S.sweep(MIXED)
    seen: list[int] = []
    part = S.sweep(MIXED, skip=[0, 2, 5], on_result=lambda i, row: seen.append(i))
    assert seen == [1, 3, 4] and [r["index"] for r in part.rows] == [1, 3, 4]
    assert (part.total, part.skipped) == (6, 3)
    rest = S.sweep(MIXED, skip=[1, 3, 4])
    assert tuple(sorted(part.rows + rest.rows, key=lambda r: r["index"])) == full.rows
    # points 1 and 4 (dx = 30) fail, and both are in the part
    assert (full.status, part.status, rest.status) == ("point_errors", "point_errors", "complete")
    assert part.message == "3 of 6 points solved, 2 failed, 3 skipped (done before)"


def test_should_stop_stops_between_points():
    calls = []
    res = S.sweep(MIXED, on_result=lambda i, row: calls.append(i), should_stop=lambda: len(calls) >= 2)
    assert res.cancelled and calls == [0, 1] and len(res.rows) == 2
    assert (res.status, res.success) == ("cancelled", False)
    assert res.message == "stopped early: 2 of 6 points solved, 1 failed"          # point 1: dx = 30


def test_progress_bar_only_on_a_terminal(capsys):
    S.sweep({"analysis": "buckling", "grid": {"n": [3, 4]}}, progress=True)
    assert capsys.readouterr().err == ""          # pytest's stderr is not a terminal


# --------------------------------------------------------------------------- files
@pytest.mark.parametrize("suffix", [".csv", ".json", ".parquet"])
def test_files_round_trip(tmp_path, suffix):
    if suffix == ".parquet":
        pytest.importorskip("pyarrow")
    spec = {"analysis": "equilibrium", "points": [{"dx": 0.1}, {"dx": 30.0}, {"load": [0.2, 0.1]}, {"n": 3, "dy": 0.1}]}
    res = S.sweep(spec)
    path = res.save(tmp_path / f"out{suffix}")
    back = S.read_results(path)
    assert back.columns == res.columns
    assert back.rows == res.rows                 # same values and types, None and lists included
    if suffix != ".csv":
        assert back.spec == res.spec
    if suffix == ".json":
        doc = json.loads(path.read_text())
        assert doc["rows"][1]["error"].startswith("unreachable_target")
        assert list(doc)[:4] == ["success", "status", "message", "format"]
        assert (doc["success"], doc["status"]) == (True, "point_errors")
    if suffix == ".csv":
        lines = path.read_text().splitlines()
        assert lines[0] == ",".join(res.columns) and len(lines) == 5
    with pytest.raises(InvalidParameterError):
        res.save(tmp_path / "out.txt")


# --------------------------------------------------------------------------- Dask
@pytest.mark.slow
def test_dask_local_cluster_equals_serial():
    """Two single-threaded worker *processes*: the realistic set-up (chunks and specs are pickled to
    other interpreters, each builds its own solvers, no shared GIL); it starts in ~2 s here."""
    distributed = pytest.importorskip("distributed")
    spec = {"analysis": "equilibrium", "grid": {"n": [3, 4, 5], "dx": [0.05, 0.1, 30.0, 0.2], "dy": [0.0, 0.02]}}
    serial = S.sweep(spec)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cl, \
            distributed.Client(cl) as client:
        arrived: list[int] = []
        res = S.sweep(spec, scheduler=client, chunk_size=5, on_result=lambda i, row: arrived.append(i))
        assert sorted(arrived) == list(range(24))
        assert res.rows == serial.rows
        workers = client.run(lambda: __import__("os").getpid())
        assert len(set(workers.values())) == 2
        by_address = S.sweep(spec, scheduler=cl.scheduler_address, skip=range(10))   # "tcp://..." form
        assert by_address.rows == serial.rows[10:]


# --------------------------------------------------------------------------- CLI
def _cli(argv):
    p = argparse.ArgumentParser(prog="tensegrity-opt")
    add_sweep_parser(p.add_subparsers(dest="command", required=True))
    args = p.parse_args(argv)
    return args.run(args)


def test_cli_sweep_writes_files_and_csv_to_stdout(tmp_path, capsys):
    spec_file = tmp_path / "spec.json"
    spec_file.write_text(json.dumps(MIXED))
    out = tmp_path / "out.json"
    assert _cli(["sweep", str(spec_file), "-o", str(out), "--scheduler", "serial", "--no-progress"]) == 0
    assert "6 points" in capsys.readouterr().err
    assert S.read_results(out).rows == S.sweep(MIXED).rows
    assert _cli(["sweep", str(spec_file), "--scheduler", "serial"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0].startswith("index,n,dx,energy") and len(lines) == 7


def test_cli_sweep_errors_exit_2(tmp_path, capsys):
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps({"analysis": "buckling", "grid": {"dx": [0.1]}}))
    assert _cli(["sweep", str(bad), "--scheduler", "serial"]) == 2
    assert "grid.dx" in capsys.readouterr().err
    assert _cli(["sweep", str(tmp_path / "missing.json"), "--scheduler", "serial"]) == 2
    assert _cli(["sweep", str(bad), "-o", "x.xlsx"]) == 2
    assert _cli(["sweep", str(bad), "--scheduler", "nowhere"]) == 2
    assert "error" in capsys.readouterr().err


def test_non_finite_values_become_none():
    # the sweep's cells follow the policy for nullable fields (tensegrity_opt.serialize)
    assert nullable(float("nan")) is None and nullable(math.inf) is None and nullable(np.float64(1.5)) == 1.5


# --------------------------------------------------------------------------- the default scheduler
def _readme_spec() -> dict:
    """The sweep spec the README shows (its first JSON block with an ``analysis``)."""
    import re
    from pathlib import Path

    text = (Path(__file__).resolve().parents[3] / "README.md").read_text(encoding="utf-8")
    return next(json.loads(b) for b in re.findall(r"```json\n(.*?)```", text, re.S) if '"analysis"' in b)


README_SPEC = _readme_spec()


def test_auto_runs_the_readme_spec_serially_without_a_cluster(monkeypatch, tmp_path, capsys):
    """The README's 9-point spec took 3.0 s on the local cluster against 0.43 s serially: ``auto`` (the CLI's
    default) solves it in this process and never starts Dask."""
    from tensegrity_opt.applications.sweeps import scheduler as sch

    def no_dask(*a, **k):
        raise AssertionError("auto started Dask for a 9-point sweep")

    monkeypatch.setattr(sch, "_run_dask", no_dask)
    assert S.count_points(README_SPEC) == 9 and sch.auto_scheduler(9) == "serial"
    res = S.sweep(README_SPEC, scheduler="auto")
    assert res.scheduler == "serial" and res.rows == S.sweep(README_SPEC).rows
    spec_file = tmp_path / "spec.json"
    spec_file.write_text(json.dumps(README_SPEC))
    assert _cli(["sweep", str(spec_file), "--no-progress"]) == 0         # no --scheduler: auto
    assert "9 points (buckling, serial)" in capsys.readouterr().err


def test_auto_decides_by_size_then_by_the_measured_time_per_point():
    from tensegrity_opt.applications.sweeps.scheduler import AUTO_CLUSTER_SECONDS, AUTO_SERIAL_POINTS, auto_scheduler

    assert auto_scheduler(1) == auto_scheduler(AUTO_SERIAL_POINTS) == "serial"
    assert auto_scheduler(AUTO_SERIAL_POINTS + 1) == "probe"
    assert auto_scheduler(1000, 0.001) == "serial"                      # 1000 buckling points: ~1 s serially
    assert auto_scheduler(1000, 1.01 * AUTO_CLUSTER_SECONDS / 1000) == "local"
    assert auto_scheduler(1000, 0.99 * AUTO_CLUSTER_SECONDS / 1000) == "serial"


def test_auto_hands_the_rest_after_its_probe_to_the_cluster_every_point_once(monkeypatch):
    """When the probe says the rest is long, the points after it go to the local cluster (here a stand-in
    solving the chunk in this process): every point delivered exactly once, rows as serial."""
    from tensegrity_opt.applications.sweeps import scheduler as sch

    spec = {"analysis": "buckling", "grid": {"n": [3, 4], "k": [float(v) for v in np.linspace(0.5, 2.0, 20)]}}
    handed: list[list[int]] = []

    def fake_dask(scheduler, header, pcols, rcols, todo, deliver, bar, n_err, stop, chunk_size, workers):
        assert scheduler == "local"
        handed.append([i for i, _ in todo])
        for i, row in sch.solve_chunk(header, pcols, rcols, todo):
            deliver(i, row)
        return "local", False

    monkeypatch.setattr(sch, "_run_dask", fake_dask)
    monkeypatch.setattr(sch, "AUTO_CLUSTER_SECONDS", 0.0)               # any rest counts as long
    monkeypatch.setattr(sch, "AUTO_PROBE_SECONDS", 1e9)                 # the probe ends by its count alone
    arrived: list[int] = []
    res = S.sweep(spec, scheduler="auto", on_result=lambda i, row: arrived.append(i))
    assert res.scheduler == "serial+local"
    assert len(handed) == 1 and handed[0] == list(range(sch.AUTO_PROBE_POINTS, 40))
    assert sorted(arrived) == list(range(40)) and res.rows == S.sweep(spec).rows


def test_threads_equal_serial():
    spec = {"analysis": "equilibrium", "grid": {"n": [3, 4], "dx": [0.05, 0.1, 30.0, 0.2]}}
    res = S.sweep(spec, scheduler="threads", workers=2, chunk_size=3)
    assert res.scheduler == "threads" and res.rows == S.sweep(spec).rows
    assert res.rows[2]["error"].startswith("unreachable_target")


# --------------------------------------------------------------------------- the result contract
def test_a_sweep_result_follows_the_contract_and_is_immutable(tmp_path):
    res = S.sweep({"analysis": "buckling", "grid": {"n": [3, 4]}})
    assert isinstance(res, Outcome) and set(S.SweepResult.STATUSES) == {"complete", "point_errors", "cancelled"}
    assert (res.success, res.status, res.message) == (True, "complete", "2 of 2 points solved, 0 failed")
    assert list(res.to_dict())[:3] == ["success", "status", "message"]
    assert isinstance(res.rows, tuple) and isinstance(res.columns, tuple)
    assert res.to_dict()["columns"] == list(res.columns)
    with pytest.raises(dataclasses.FrozenInstanceError):
        res.cancelled = True
    stopped = S.SweepResult(res.spec, list(res.columns), [res.rows[0]], total=2, cancelled=True)
    assert (stopped.status, stopped.success) == ("cancelled", False)
    back = S.read_results(stopped.save(tmp_path / "stopped.json"))
    assert back.status == "cancelled" and back.rows == stopped.rows


@pytest.mark.parametrize(("spec", "words"), [
    ({"analysis": "buckling", "grid": {"N": [3]}}, "grid.N: unknown parameter; did you mean n?"),
    ({"analysis": "design", "grid": {"n": [3]}, "options": {"bonds": {}}}, "options.bonds: unknown option; did you "
                                                                           "mean bounds?"),
    ({"analysis": "buckling", "gird": {"n": [3]}}, "gird: unknown key; did you mean grid?"),
    ({"analysis": "buckling", "manipulator": {"l0": 1.0}, "grid": {"n": [3]}}, "manipulator.l0: unknown key; did you "
                                                                               "mean L0?")])
def test_a_misspelt_name_is_refused_naming_the_nearest(spec, words):
    with pytest.raises(to.InvalidParameterError) as info:
        S.validate_spec(spec)
    assert str(info.value).startswith(words)


@pytest.mark.parametrize("argv, first, second", [
    (["--scheduler", "serial", "--workers", "2"], "--workers", "--scheduler serial"),
    (["--scheduler", "serial", "--chunk-size", "4"], "--chunk-size", "--scheduler serial"),
    (["--scheduler", "tcp://127.0.0.1:8786", "--workers", "2"], "--workers", "--scheduler tcp://127.0.0.1:8786"),
])
def test_cli_sweep_refuses_options_its_scheduler_ignores(argv, first, second, tmp_path, capsys):
    from cli_checks import refuses_together

    from tensegrity_opt.applications.cli import main

    spec_file = tmp_path / "spec.json"
    spec_file.write_text(json.dumps(MIXED))
    refuses_together(main, ["sweep", str(spec_file), *argv], first, second, capsys)
