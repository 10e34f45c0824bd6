"""One serialiser per result: each ``to_dict()`` equals the dict the independent, hand-written serialiser builds
for the same object (``tests/support/reference_serialisers.py``), the service's body is that dict, each passes
``json.dumps(allow_nan=False)``, and follows the one NaN policy (:mod:`tensegrity_opt.serialize`); the CLI's
``--json`` is the API's body.
"""

from __future__ import annotations

import json
import math
import warnings

import numpy as np
import pytest

import tensegrity_opt as to
from tensegrity_opt.errors import NonFiniteResult, TensegrityError
from tensegrity_opt.serialize import nullable, nullables, number, numbers

pytest.importorskip("fastapi")

import reference_serialisers as refs  # noqa: E402  (the pre-to_dict serialisers: the reference)

from service import schemas as s  # noqa: E402
from service.responses import json_ready  # noqa: E402  (a task's result as its body's content)
from service.tasks import control as control_tasks  # noqa: E402  (the service's tasks: the same bodies)
from service.tasks import equilibria as compute  # noqa: E402


def _family(name: str, rng: np.random.Generator) -> tuple[to.Manipulator, float, float]:
    """A random chain of one family and a deflection for it."""
    u = lambda lo, hi: float(rng.uniform(lo, hi))  # noqa: E731
    if name == "monotonic":
        n = int(rng.integers(2, 5))
        return to.Manipulator.uniform(n, a=u(0.8, 1.2), b=1.0, k=u(0.5, 2.0), L0=1.0), u(0.05, 0.6), 0.0
    if name == "bistable":
        return to.Manipulator.uniform(int(rng.integers(2, 4)), a=0.5, b=1.0, k=u(0.5, 2.0), L0=0.5), u(0.1, 0.5), 0.0
    if name == "heterogeneous":
        segs = [to.Segment(u(0.6, 1.4), u(0.6, 1.4), u(0.5, 2.0), u(0.7, 1.2)) for _ in range(int(rng.integers(3, 5)))]
        return to.Manipulator(segs), u(0.05, 0.4), 0.0
    if name == "asymmetric":
        n = int(rng.integers(2, 5))
        return to.Manipulator.uniform(n, a=1.0, b=1.0, k=(1.0, 1.5), L0=(1.0, 0.9)), u(0.1, 0.5), 0.0
    if name == "dy":
        n = int(rng.integers(2, 5))
        return to.Manipulator.uniform(n, a=1.0, b=1.0, k=u(0.5, 2.0), L0=1.0), u(0.1, 0.5), u(-0.3, 0.3)
    raise AssertionError(name)


FAMILIES = ("monotonic", "bistable", "heterogeneous", "asymmetric", "dy")
CASES = [(f, seed) for f in FAMILIES for seed in (0, 1)]


def _same(mine: dict, reference: dict) -> None:
    """Equal as dicts, with the same key order at every level, the same Python types, JSON-safe."""
    assert mine == reference
    assert json.dumps(mine, allow_nan=False) == json.dumps(reference, allow_nan=False)
    _same_types(mine, reference)


def _same_types(a, b) -> None:
    assert type(a) is type(b), (a, b)
    if isinstance(a, dict):
        assert list(a) == list(b)
        for k in a:
            _same_types(a[k], b[k])
    elif isinstance(a, list):
        for x, y in zip(a, b, strict=True):
            _same_types(x, y)


def _req(model, m: to.Manipulator, **fields):
    return model.model_validate({"manipulator": m.to_dict(), **fields})


def _body(task, *args):
    """The content of the service's body for ``task(*args)`` (what :func:`service.responses.render_task` renders)."""
    return json_ready(task(*args))


def _or_error(f):
    try:
        return f()
    except (TensegrityError, ArithmeticError) as exc:
        return type(exc)


@pytest.mark.slow_cases(keep=1)
@pytest.mark.parametrize("family,seed", CASES)
def test_to_dict_equals_the_service_serialiser(family, seed):
    rng = np.random.default_rng(seed)
    m, dx, dy = _family(family, rng)

    # Manipulator: the {"segments": [...]} form, k / L0 a number when equal, else a pair
    assert m.to_dict() == refs.manipulator_out(m)
    _same(m.to_dict(), refs.manipulator_out(m))
    assert to.Manipulator.from_dict(m.to_dict()) == m

    eq = to.solve_equilibrium(m, dx, dy)
    _same(eq.to_dict(), refs.equilibrium_out(eq))
    feq = _or_error(lambda: to.solve_equilibrium_under_force(m, -0.2 * abs(eq.fx), eq.fy))
    if isinstance(feq, to.Equilibrium):
        _same(feq.to_dict(), refs.equilibrium_out(feq))

    eqs = to.find_equilibria(m, dx, dy)
    _same(eqs.to_dict(), refs.equilibria_out(eqs))
    _same(eqs.to_dict(), _body(compute.equilibria_task, _req(s.EquilibriaRequest, m, dx=dx, dy=dy)))

    K = to.cartesian_stiffness(m, eq)
    _same({"matrix": numbers(K), "equilibrium": eq.to_dict()},
          _body(compute.stiffness_task, _req(s.StiffnessRequest, m, dx=dx, dy=dy)))

    for boundary in ("guided", "free"):
        bk = _or_error(lambda b=boundary: to.critical_force(m, b))
        ref = _or_error(lambda b=boundary: _body(compute.buckling_task, _req(s.BucklingRequest, m, boundary=b)))
        if isinstance(bk, type):
            assert ref is bk        # the same refusal (asymmetric preloads: straight is not an equilibrium)
            continue
        _same(bk.to_dict(), ref)
        _same(bk.to_dict(), refs.buckling_out(bk))
        for md, ref_md in zip(bk.modes, ref["modes"], strict=True):
            _same(md.to_dict(), ref_md)

    grid = np.linspace(0.0 if dy == 0 else dx, 2 * dx, 5)      # dx = 0 is out of reach when dy != 0
    for branch in ("stable", "all"):
        c = to.force_deflection(m, grid, dy, branch=branch)
        ref = _body(compute.force_deflection_task,
                    _req(s.ForceDeflectionRequest, m, dx=grid.tolist(), dy=dy, branch=branch))
        _same(c.to_dict(), ref)
        _same(c.to_dict(), refs.curve_out(c))
        for j, ref_j in zip(c.jumps, ref["jumps"], strict=True):
            _same(j.to_dict(), ref_j)


@pytest.mark.parametrize("family", FAMILIES)
def test_landscape_to_dict_equals_the_service_serialiser(family):
    m, dx, dy = _family(family, np.random.default_rng(3))
    m = to.Manipulator((list(m.segments) * 4)[:4])      # the landscape needs n = 4
    land = to.energy_landscape(m, dx, dy, pair=(0, 3), grid=9)
    ref = _body(compute.energy_landscape_task, _req(s.EnergyLandscapeRequest, m, dx=dx, dy=dy, pair=[0, 3], grid=9))
    _same(land.to_dict(), ref)
    _same(land.to_dict(), refs.landscape_out(land))
    assert any(v is None for plane in ref["energy"] for row in plane for v in row)   # cells outside: null


def test_design_to_dict_equals_the_service_serialiser():
    m = to.Manipulator.uniform(4)
    d = to.maximize_critical_force(m, vary=("k",), bounds={"k": (0.5, 2.0)}, budget={"k": 4.0})
    _same(d.to_dict(), refs.design_out(d))
    _same(d.to_dict(), _body(control_tasks.design_critical_force_task, _req(
        s.DesignCriticalForceRequest, m, vary=["k"], bounds={"k": {"lo": 0.5, "hi": 2.0}}, budget={"k": 4.0})))
    pl = to.preloads_for_critical_force(m, 0.8)
    _same(pl.to_dict(), _body(control_tasks.preloads_for_load_task, _req(s.PreloadsForLoadRequest, m, required=0.8)))
    p = to.preloads_for_pose(m, (7.5, 0.5), load=(0.0, 0.0), objective="energy")
    _same(p.to_dict(), refs.preload_design_out(p))
    _same(p.to_dict(), _body(control_tasks.preloads_task, _req(s.PreloadsRequest, m, target=[7.5, 0.5],
                                                 objective="energy")))
    # nullable: a starting design without a critical force
    import dataclasses

    nan_start = dataclasses.replace(d, initial_critical_force=math.nan)
    assert nan_start.to_dict()["initial_critical_force"] is None
    _same(nan_start.to_dict(), refs.design_out(nan_start))


# --------------------------------------------------------------------------- the NaN policy
def test_nan_policy():
    assert NonFiniteResult.__mro__[1] is ArithmeticError and not issubclass(NonFiniteResult, TensegrityError)
    for bad in (math.nan, math.inf, -math.inf, np.float64("nan")):
        with pytest.raises(NonFiniteResult):
            number(bad)
        with pytest.raises(NonFiniteResult):
            numbers([1.0, bad])
        assert nullable(bad) is None
    assert number(np.float64(1.5)) == 1.5 and type(number(np.float64(1.5))) is float
    assert numbers(np.eye(2)) == [[1.0, 0.0], [0.0, 1.0]]
    assert nullables(np.array([[1.0, math.nan]])) == [[1.0, None]]
    assert nullables(np.array([math.inf, 2.0])) == [None, 2.0]

    eq = to.solve_equilibrium(to.Manipulator.uniform(3), 0.1)
    import dataclasses

    broken = dataclasses.replace(eq, energy=math.nan)
    with pytest.raises(NonFiniteResult):
        broken.to_dict()
    with pytest.raises(ArithmeticError):
        refs.equilibrium_out(broken)       # the service's serialiser agrees (its own class, for now)


def test_a_non_finite_result_is_a_500_numerical_failure():
    from service.api.errors import to_api_error

    err = to_api_error(NonFiniteResult("x"))
    assert err is not None and err.status_code == 500 and err.body["code"] == "numerical_failure"


# --------------------------------------------------------------------------- CLI --json == API body
@pytest.fixture(scope="module")
def client():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        from fastapi.testclient import TestClient
    from service.main import create_app

    with TestClient(create_app()) as c:
        yield c


def _cli_json(argv, capsys) -> dict | str:
    """The CLI's ``--json`` output, or its error line (exit status 2) or answer line (status 1: a physical
    answer such as the straight chain unstable unloaded)."""
    from tensegrity_opt.applications.cli import main

    capsys.readouterr()
    status = main([*argv, "--json"])
    out = capsys.readouterr()
    if status in (1, 2):
        return out.err
    assert status == 0
    return json.loads(out.out)


CHAINS = {
    "paper": (["--n", "4"], {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}),
    "bistable": (["--n", "3", "--a", "0.5", "--L0", "0.5"], {"n": 3, "a": 0.5, "b": 1.0, "k": 1.0, "L0": 0.5}),
}


@pytest.mark.slow
@pytest.mark.parametrize("chain", list(CHAINS))
def test_cli_json_is_the_api_body(chain, client, capsys, tmp_path):
    opts, man = CHAINS[chain]
    cases = [
        (["equilibrium", "--dx", "0.3", "--dy", "0.05"], "/v1/equilibrium", {"dx": 0.3, "dy": 0.05}),
        (["equilibria", "--dx", "0.2"], "/v1/equilibria", {"dx": 0.2}),
        (["equilibria", "--dx", "0.9", "--dy", "0.3", "--stops"], "/v1/equilibria", {"dx": 0.9, "dy": 0.3,
                                                                                     "stops": True}),
        (["buckling"], "/v1/buckling", {}),
        (["buckling", "--boundary", "free"], "/v1/buckling", {"boundary": "free"}),
        (["curve", "--start", "0", "--stop", "0.6", "--num", "4", "--dy", "0.0"], "/v1/force-deflection",
         {"dx": {"start": 0.0, "stop": 0.6, "num": 4}, "dy": 0.0, "branch": "stable"}),
    ]
    for argv, path, body in cases:
        r = client.post(path, json={"manipulator": man, **body})
        got = _cli_json([*argv, *opts], capsys)
        if r.status_code == 200:
            assert got == r.json(), argv
        else:               # the same refusal (bistable segments: the straight chain is unstable)
            word = "answer" if r.json()["code"] in ("straight_unstable", "straight_not_equilibrium") else "error"
            assert r.status_code == 422 and got == f"tensegrity-opt: {word}: {r.json()['message']}\n", argv


def test_cli_json_of_a_segments_file_is_the_api_body(client, capsys, tmp_path):
    m = to.Manipulator([to.Segment(1.0, 1.1, 1.2, 0.9), to.Segment(0.8, 1.0, (1.0, 1.0), 1.0),
                        to.Segment(1.1, 0.9, 0.7, 1.1)])
    f = tmp_path / "m.json"
    f.write_text(json.dumps(m.to_dict()))
    r = client.post("/v1/equilibrium", json={"manipulator": m.to_dict(), "dx": 0.2})
    assert r.status_code == 200
    assert _cli_json(["equilibrium", "--dx", "0.2", "--manipulator", str(f)], capsys) == r.json()


def test_the_other_service_bodies_are_to_dict_too():
    m = to.Manipulator.uniform(4)
    # the uniform request form builds the same chain as Manipulator.from_dict of it
    assert to.Manipulator.from_dict({"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}) == m
    feq = to.solve_equilibrium_under_force(m, -0.3, 0.02)
    _same(feq.to_dict(), _body(compute.force_equilibrium_task, _req(s.ForceEquilibriumRequest, m, fx=-0.3, fy=0.02)))
    targets = [{"dx": 0.1 * i, "dy": 0.0} for i in range(4)]
    batch = compute.batch_task(_req(s.BatchEquilibriumRequest, m, targets=targets), math.inf, "segments")
    solved = to.solve_equilibria_batch(m, [(0.1 * i, 0.0) for i in range(4)])
    for item, eq in zip(batch["results"], solved, strict=True):
        _same(eq.to_dict(), item["equilibrium"])


# --------------------------------------------------------------------------- sweep rows: the same values
def test_sweep_rows_hold_the_values_of_the_result_dicts():
    from tensegrity_opt.applications import sweeps as S

    res = S.sweep({"analysis": "equilibrium", "points": [{"dx": 0.1}, {"dx": 0.3, "dy": 0.05}, {"load": [-0.3, 0.02]}]})
    json.dumps(res.to_dict(), allow_nan=False)
    assert res.to_dict()["rows"] == [{c: r[c] for c in res.columns} for r in res.rows]
    m = to.Manipulator.uniform(4)
    eqs = [to.solve_equilibrium(m, 0.1), to.solve_equilibrium(m, 0.3, 0.05),
           to.solve_equilibrium_under_force(m, -0.3, 0.02)]
    for row, eq in zip(res.rows, eqs, strict=True):
        d = eq.to_dict()
        assert row["error"] is None
        assert {k: row[k] for k in ("energy", "stable", "morse_index", "kind", "shape", "signs", "q")} == {
            k: d[k] for k in ("energy", "stable", "morse_index", "kind", "shape", "signs", "q")}
        assert (row["fx"], row["fy"]) == (d["force"]["fx"], d["force"]["fy"])
        assert [row["tip_x"], row["tip_y"]] == d["tip"]
        assert (row["status"], row["solver_status"], row["iterations"]) == (
            d["status"], d["solver"]["status"], d["solver"]["iterations"])

    res = S.sweep({"analysis": "buckling", "grid": {"n": [3, 4]}})
    for row, n in zip(res.rows, (3, 4), strict=True):
        d = to.critical_force(to.Manipulator.uniform(n)).to_dict()
        assert (row["critical_force"], row["loads"], row["load2"]) == (d["critical_force"], d["loads"], d["loads"][1])
        assert (row["mode_shape"], row["mode_signs"], row["mode_q"]) == (
            d["modes"][0]["shape"], d["modes"][0]["signs"], d["modes"][0]["q"])
