"""The compiled Newton kernels (tensegrity_opt.numerics.kernels) against independent computations.

Expected values come from the numpy model of ``Manipulator`` (energy, tip, equilibrium residual),
the library's QR route for the reduced Hessian (``stability.reduced_hessian``), the Python Newton
method, the independent reference model of ``tests/support/reference_model.py`` — never from the kernels.
"""

import concurrent.futures
import json
import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest
from reference_model import Chain

import tensegrity_opt as to
from tensegrity_opt.analyses.equilibria.seeds import seed_starts, seeds
from tensegrity_opt.analyses.equilibria.stability import inertia_of_reduced, reduced_hessian
from tensegrity_opt.numerics import SAME_Q, build, chain_solver, kernels

CHAINS = {
    "paper": to.Manipulator.uniform(4),
    "n2": to.Manipulator.uniform(2, a=0.8, b=1.2, k=2.0, L0=1.5),
    "n3": to.Manipulator.uniform(3),
    "n6 non-uniform": to.Manipulator([to.Segment(1.0, 0.9 + 0.05 * i, (1.0 + 0.2 * i, 1.1), 1.0) for i in range(6)]),
    "n8": to.Manipulator.uniform(8, a=0.8, b=1.2, k=2.5, L0=1.7),
}


def _python_newton(m, target, q0, F0=None):
    """The damped Newton method in Python (the kernels' step rule, driven from numpy/LAPACK)."""
    mdl = chain_solver(m)
    phi = np.cumsum(q0)
    if F0 is None:
        F0 = m.force_from_torques(q0)
    z = np.concatenate([phi, F0])
    return mdl._newton(mdl.functions.fast_kkt, None, (m.params, target), z, 1e-12, 50, kernels.MAX_STEP, None)


@pytest.mark.parametrize("name", CHAINS)
def test_kernel_solutions_are_equilibria_with_their_energy_tip_and_reduced_hessian(name):
    m = CHAINS[name]
    mdl = chain_solver(m)
    assert mdl.kernel_mode is not None
    assert mdl.kernel_mode == ("compiled" if build.compiler() else "virtual machine")
    checked = 0
    for dx, dy in [(0.05, 0.0), (0.4, 0.2), (1.2, -0.5)]:
        target = m.target(dx, dy)
        for s in seeds(m, dx, dy):
            res = mdl.newton_kkt(target, s.q)
            if not res.success or res.reduced_hessian is None:
                continue
            checked += 1
            assert m.equilibrium_residual(res.q, res.force, target) < 1e-10
            assert res.energy == pytest.approx(m.energy(res.q), rel=1e-12, abs=1e-12)
            np.testing.assert_allclose(res.tip, m.tip(res.q), atol=1e-12)
            R_qr = reduced_hessian(m, res.q, res.force, constrained=True)
            assert res.reduced_hessian.shape == R_qr.shape == (m.n - 2, m.n - 2)
            if m.n > 2:
                np.testing.assert_allclose(np.linalg.eigvalsh(res.reduced_hessian), np.linalg.eigvalsh(R_qr),
                                           atol=1e-9 * max(1.0, np.abs(R_qr).max()))
    assert checked >= 6


@pytest.mark.parametrize("name", ["paper", "n6 non-uniform"])
def test_kernel_newton_equals_python_newton_from_nearby_starts(name):
    """Started near an equilibrium (a warm start), both methods converge to it. (From far seeds the
    damped methods may settle on different stationary points: their line searches differ.)"""
    m = CHAINS[name]
    mdl = chain_solver(m)
    rng = np.random.default_rng(7)
    agree = 0
    for dx, dy in [(0.1, 0.0), (0.7, 0.3)]:
        target = m.target(dx, dy)
        for s in seeds(m, dx, dy, arcs=False):     # the starts this comparison was written for
            p0 = _python_newton(m, target, s.q)
            if not p0.success:
                continue
            q0 = p0.q + 0.02 * rng.standard_normal(m.n)
            k = mdl.newton_kkt(target, q0)
            p = _python_newton(m, target, q0)
            assert k.success and p.success and k.reduced_hessian is not None
            np.testing.assert_allclose(k.q, p.q, atol=1e-9)
            np.testing.assert_allclose(k.force, p.force, atol=1e-9)
            np.testing.assert_allclose(k.q, p0.q, atol=1e-8)
            agree += 1
    assert agree >= 10


def test_seed_batch_equals_single_starts():
    m = CHAINS["paper"]
    mdl = chain_solver(m)
    target = m.target(0.6, 0.1)
    starts = [s.q for s in seeds(m, 0.6, 0.1)]
    batch = mdl.newton_kkt_seeds(target, starts)
    many = [batch.result(j) for j in range(len(batch.status))]
    assert len(many) == len(starts)
    from_kernels = 0
    for q0, r in zip(starts, many):
        one = mdl.newton_kkt(target, q0)
        assert r.success == one.success
        if r.success:
            np.testing.assert_allclose(r.q, one.q, atol=1e-9)
            np.testing.assert_allclose(r.force, one.force, atol=1e-9)
            if r.energy is not None:        # None: a start the kernels left to the Python method
                assert r.energy == pytest.approx(m.energy(r.q), rel=1e-12)
                from_kernels += 1
    assert from_kernels >= len(starts) - 2


def _distinct_by_hand(q, good, same):
    """Rows kept by a plain double loop: good, and no earlier kept row within ``same`` in every angle."""
    keep = []
    for i in range(len(q)):
        keep.append(bool(good[i]) and not any(keep[j] and max(abs(a - b) for a, b in zip(q[i], q[j])) < same
                                              for j in range(i)))
    return np.array(keep)


@pytest.mark.parametrize("name", ["paper", "n3", "n6 non-uniform", "n8"])
def test_seed_call_marks_the_distinct_converged_rows(name):
    # the kernel's marks against a double loop over the rows it returned (many starts coincide: each
    # search below has duplicates), whether or not every start converged in the call
    m = CHAINS[name]
    mdl = chain_solver(m)
    thresh = 1e-12 * mdl.scale
    fast, cols, at = mdl.functions.kernel.seeds, kernels.seed_columns(m.n), kernels.seed_layout(m.n)
    reach = 2 * float(np.sum(m.b))
    dup = 0
    for dx, dy in [(0.02 * reach, 0.0), (0.1 * reach, 0.03 * reach), (0.3 * reach, 0.0)]:
        starts = seed_starts(m, dx, dy)
        k = starts.shape[0]
        src = np.zeros((cols, m.n))
        src[:k] = starts
        src[k] = starts[0]                      # one start twice: the same point, never distinct the second time
        active = (np.arange(cols) <= k).astype(float)
        Y = at.unpack(fast(src.ravel(), active, m.params, m.target(dx, dy), thresh, SAME_Q)[0].reshape(cols, -1))
        good = (active > 0) & (Y["norm"] <= thresh) & (Y["margin"] < 0)
        expected = _distinct_by_hand(Y["q"].tolist(), good.tolist(), SAME_Q)
        np.testing.assert_array_equal(Y["distinct"] > 0.5, expected)
        assert not expected[k]
        dup += int(good.sum() - expected.sum())
    assert dup > 3


def test_search_rows_carry_the_distinct_marks_only_when_one_call_settled_every_start():
    m = CHAINS["paper"]
    mdl = chain_solver(m)
    target = m.target(0.1, 0.0)
    starts = seed_starts(m, 0.1, 0.0)
    b = mdl.newton_kkt_seeds(target, starts, SAME_Q)
    assert b.distinct is not None and bool(b.success.all())
    good = b.success & ~b.on_bound
    np.testing.assert_array_equal(b.distinct, _distinct_by_hand(b.q.tolist(), good.tolist(), SAME_Q))
    assert mdl.newton_kkt_seeds(target, starts).distinct is None     # not asked for


def test_more_starts_than_one_call_takes_leave_the_comparison_to_the_caller():
    m = CHAINS["paper"]
    mdl = chain_solver(m)
    starts = np.vstack([seed_starts(m, 0.4, 0.0)] * 2)
    assert starts.shape[0] > kernels.seed_columns(4)
    b = mdl.newton_kkt_seeds(m.target(0.4, 0.0), starts, SAME_Q)
    assert b.distinct is None
    half = starts.shape[0] // 2
    np.testing.assert_array_equal(b.q[:half], b.q[half:])       # the same starts give the same points


def test_continuation_kernel_matches_pointwise_solves_and_reference_model():
    m = CHAINS["paper"]
    ref = Chain.uniform(4, 1.0, 1.0, 1.0, 1.0)
    eq = to.solve_equilibrium(m, 0.3)
    dxs = np.linspace(0.3, 0.8, 200)
    targets = np.column_stack([m.straight_length - dxs, 0.1 * np.sin(dxs)])
    c = chain_solver(m).batch_continue(targets, np.concatenate([np.cumsum(eq.q), eq.force]))
    assert c.reduced_hessian is not None and np.all(c.residual < 1e-10)
    Q = np.diff(np.hstack([np.zeros((len(dxs), 1)), c.Z[:, :4]]), axis=1)
    for i in (0, 57, 199):
        qr, Fr, ok = ref.newton_kkt(targets[i], Q[i], c.Z[i, 4:])
        assert ok
        np.testing.assert_allclose(Q[i], qr, atol=1e-9)
        np.testing.assert_allclose(c.Z[i, 4:], Fr, atol=1e-9)
        assert c.energy[i] == pytest.approx(ref.energy(Q[i]), rel=1e-12)


def test_inertia_of_reduced_closed_form_matches_eigvalsh():
    rng = np.random.default_rng(3)
    cases = [rng.standard_normal((2, 2)) for _ in range(200)]
    cases += [np.diag([1e8, 1e-8]), np.diag([1e-12, -3.0]), np.array([[1.0, 1.0], [1.0, 1.0]]), np.zeros((2, 2))]
    for A in cases:
        R = (A + A.T) / 2
        w = np.linalg.eigvalsh(R)
        got = inertia_of_reduced(R)
        np.testing.assert_allclose(got.eigenvalues, w, atol=1e-12 * max(1.0, np.abs(w).max()), rtol=1e-10)
        tol = 1e-9 * max(1.0, np.abs(w).max())
        assert got.morse_index == int(np.sum(w < -tol))
        assert got.degenerate == bool(np.any(np.abs(w) <= tol))


_CHILD = textwrap.dedent("""
    import json, sys, warnings
    import numpy as np
    warnings.simplefilter("always")
    with warnings.catch_warnings(record=True) as caught:
        import tensegrity_opt as to
        from tensegrity_opt.numerics import chain_solver
        m = to.Manipulator.uniform(4)
        out = [to.solve_equilibrium(m, dx, dy).q.tolist() for dx, dy in [(0.1, 0.0), (0.9, 0.4)]]
        mode = chain_solver(m).kernel_mode
    print(json.dumps({"q": out, "mode": mode, "warnings": [str(w.message) for w in caught]}))
""")


def _child(tmp_path, **env):
    e = {**os.environ, "TENSEGRITY_CACHE_DIR": str(tmp_path / "cache"), **env}
    r = subprocess.run([sys.executable, "-c", _CHILD], env=e, capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout.strip().splitlines()[-1])


@pytest.mark.slow
@pytest.mark.skipif(build.compiler() is None, reason="no C compiler on this machine (or TENSEGRITY_COMPILE=0)")
def test_compiled_cached_and_virtual_machine_give_the_same_answers(tmp_path):
    first = _child(tmp_path)
    assert first["mode"] == "compiled" and not first["warnings"]
    libs = sorted((tmp_path / "cache").glob("*.so"))
    assert len(libs) == 1
    stamp = libs[0].stat().st_mtime_ns
    second = _child(tmp_path)                            # loads the cached library, compiles nothing
    assert second["mode"] == "compiled"
    assert sorted((tmp_path / "cache").glob("*")) == libs and libs[0].stat().st_mtime_ns == stamp
    vm = _child(tmp_path, TENSEGRITY_COMPILE="0")
    # one warning, naming the variable
    assert vm["mode"] == "virtual machine"
    assert [w for w in vm["warnings"] if "TENSEGRITY_COMPILE=0" in w and "virtual machine" in w] == vm["warnings"]
    assert len(vm["warnings"]) == 1
    np.testing.assert_allclose(np.array(vm["q"]), np.array(first["q"]), atol=1e-10)
    np.testing.assert_allclose(np.array(second["q"]), np.array(first["q"]), atol=0)


def test_a_failing_compiler_warns_and_falls_back_to_the_virtual_machine(tmp_path):
    broken = _child(tmp_path, CC="false", TENSEGRITY_COMPILE="1")
    assert broken["mode"] == "virtual machine"
    assert any("compiling the Newton kernels" in w for w in broken["warnings"])
    assert not (tmp_path / "cache").exists() or not list((tmp_path / "cache").glob("*.so"))
    reference = [to.solve_equilibrium(CHAINS["paper"], dx, dy).q for dx, dy in [(0.1, 0.0), (0.9, 0.4)]]
    np.testing.assert_allclose(np.array(broken["q"]), np.array(reference), atol=1e-10)


def test_no_compiler_on_the_path_warns_once_and_falls_back_to_the_virtual_machine(tmp_path):
    """No ``CC`` and no cc/gcc/clang on the ``PATH``: one warning naming what is missing, same answers."""
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    os.symlink(sys.executable, bin_dir / "python3")
    env = {k: v for k, v in os.environ.items() if k != "CC"}
    e = {**env, "PATH": str(bin_dir), "TENSEGRITY_CACHE_DIR": str(tmp_path / "cache"), "TENSEGRITY_COMPILE": "1"}
    r = subprocess.run([sys.executable, "-c", _CHILD], env=e, capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    got = json.loads(r.stdout.strip().splitlines()[-1])
    assert got["mode"] == "virtual machine"
    assert len(got["warnings"]) == 1 and "no C compiler was found" in got["warnings"][0], got["warnings"]
    reference = [to.solve_equilibrium(CHAINS["paper"], dx, dy).q for dx, dy in [(0.1, 0.0), (0.9, 0.4)]]
    np.testing.assert_allclose(np.array(got["q"]), np.array(reference), atol=1e-10)


def test_kernels_exist_only_for_short_chains():
    assert chain_solver(to.Manipulator.uniform(kernels.KERNEL_MAX + 1)).kernel_mode is None
    with pytest.raises(ValueError):
        kernels.build(1)


@pytest.mark.slow
@pytest.mark.skipif(build.compiler() is None, reason="no C compiler on this machine (or TENSEGRITY_COMPILE=0)")
def test_a_corrupt_cached_library_warns_and_falls_back(tmp_path):
    _child(tmp_path)
    (lib,) = (tmp_path / "cache").glob("*.so")
    lib.write_bytes(b"not a shared library")
    again = _child(tmp_path)
    assert again["mode"] == "virtual machine"
    assert any("loading" in w and "failed" in w for w in again["warnings"])
    reference = [to.solve_equilibrium(CHAINS["paper"], dx, dy).q for dx, dy in [(0.1, 0.0), (0.9, 0.4)]]
    np.testing.assert_allclose(np.array(again["q"]), np.array(reference), atol=1e-10)


@pytest.mark.skipif(build.compiler() is None, reason="no C compiler on this machine (or TENSEGRITY_COMPILE=0)")
def test_an_unwritable_cache_directory_warns_and_falls_back(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("a file where the cache directory should be")
    got = _child(tmp_path, TENSEGRITY_CACHE_DIR=str(blocker / "cache"), TENSEGRITY_COMPILE="1")
    assert got["mode"] == "virtual machine"
    assert any("compiling the Newton kernels" in w for w in got["warnings"])


# ----------------------------------------------------------------------------- background builds
@pytest.fixture
def fresh_builds(tmp_path, monkeypatch):
    """This process's build tables empty, background mode on, an empty cache directory, and a stand-in compiler
    (``CC``) that waits until the test creates the file ``release`` and then runs ``then`` (the real compiler, or
    ``false``: a compiler that fails) with its arguments."""
    monkeypatch.setattr(build, "_libraries", {})
    monkeypatch.setattr(build, "_names", {})
    monkeypatch.setattr(build, "_name_locks", {})
    monkeypatch.setattr(build, "_pending", set())
    monkeypatch.setattr(build, "_warned", True)
    monkeypatch.setattr(build, "_background", True)
    monkeypatch.setenv("TENSEGRITY_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.delenv("TENSEGRITY_COMPILE", raising=False)
    release = tmp_path / "release"

    def held_compiler(then: str) -> None:
        cc = tmp_path / "held-cc"
        cc.write_text(f'#!/bin/sh\nwhile [ ! -e "{release}" ]; do sleep 0.01; done\nexec {then} "$@"\n')
        cc.chmod(0o755)
        monkeypatch.setenv("CC", str(cc))

    yield held_compiler, release
    release.touch()                                    # nothing left waiting for the stand-in
    for name in list(build._pending):
        assert build.wait_built(name, 600.0)


def in_thread(fn, *args):
    """``fn(*args)`` in a new thread (its own per-thread solvers), its result."""
    with concurrent.futures.ThreadPoolExecutor(1) as pool:
        return pool.submit(fn, *args).result(600.0)


def test_in_background_mode_nobody_waits_for_the_compiler(fresh_builds):
    """The compiler is held (it would wait forever): a fresh chain length is solved in the virtual machine at once,
    its kernels queued; a compiler that then fails leaves them in the virtual machine, with the same answers."""
    held_compiler, release = fresh_builds
    held_compiler("false")
    m = to.Manipulator.uniform(5)
    res = in_thread(to.solve_equilibrium, m, 0.3, 0.1)
    assert res.success
    assert in_thread(lambda: chain_solver(m).kernel_mode) == build.VIRTUAL_MACHINE
    assert kernels.pending(5) and kernels.status()["building"] == [5]
    release.touch()
    assert build.wait_built(kernels.library(5), 600.0)
    assert not kernels.pending(5) and kernels.status()["virtual_machine"] == [5]
    np.testing.assert_allclose(in_thread(to.solve_equilibrium, m, 0.3, 0.1).q, res.q, atol=1e-10)


@pytest.mark.slow
@pytest.mark.skipif(build.compiler() is None, reason="no C compiler on this machine (or TENSEGRITY_COMPILE=0)")
def test_in_background_mode_the_kernels_are_used_once_built_and_rebuilt_after_a_cache_wipe(fresh_builds, tmp_path):
    held_compiler, release = fresh_builds
    held_compiler(build.compiler())
    m = to.Manipulator.uniform(6)
    with concurrent.futures.ThreadPoolExecutor(1) as worker:           # one thread, its solvers kept
        first = worker.submit(to.solve_equilibrium, m, 0.4, 0.2).result(600.0)
        assert worker.submit(lambda: chain_solver(m).kernel_mode).result(600.0) == build.VIRTUAL_MACHINE
        assert kernels.prebuild() == [4, 2, 3, 5, 7, 8]                   # 6 is queued already
        release.touch()
        for n in range(2, kernels.KERNEL_MAX + 1):
            assert build.wait_built(kernels.library(n), 600.0)
        assert kernels.status()["compiled"] == list(range(2, kernels.KERNEL_MAX + 1))
        # the same thread's solver loads the compiled kernels at its next use
        assert worker.submit(lambda: chain_solver(m).kernel_mode).result(600.0) == build.COMPILED
        again = worker.submit(to.solve_equilibrium, m, 0.4, 0.2).result(600.0)
        np.testing.assert_allclose(again.q, first.q, atol=1e-10)
    release.unlink()                                   # held again
    for lib in (tmp_path / "cache").glob("*.so"):      # the cache wiped under a running process
        lib.unlink()
    assert in_thread(lambda: chain_solver(m).kernel_mode) == build.VIRTUAL_MACHINE
    assert kernels.pending(6)
    release.touch()
    assert build.wait_built(kernels.library(6), 600.0)
    assert in_thread(lambda: chain_solver(m).kernel_mode) == build.COMPILED
