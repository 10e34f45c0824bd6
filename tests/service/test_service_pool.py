"""The solver pool: bounded queue, time limit, interruption of abandoned calls, one thread per call."""

from __future__ import annotations

import asyncio
import threading
import time

import pytest

pytest.importorskip("fastapi")

import tensegrity_opt as to
from service.pool import PoolSaturated, SolverPool, SolveTimeout


def busy(seconds: float) -> str:
    """Pure-Python work (interruptible between bytecodes)."""
    end = time.perf_counter() + seconds
    while time.perf_counter() < end:
        pass
    return "done"


def wait_idle(pool: SolverPool, timeout: float = 5.0) -> None:
    deadline = time.monotonic() + timeout
    while pool.in_flight and time.monotonic() < deadline:
        time.sleep(0.005)
    assert pool.in_flight == 0


def test_run_result_and_exception():
    pool = SolverPool(2, 2)
    try:
        assert asyncio.run(pool.run(lambda x: x * 2, 21, timeout=5)) == 42
        with pytest.raises(ZeroDivisionError):
            asyncio.run(pool.run(lambda: 1 / 0, timeout=5))
        wait_idle(pool)
    finally:
        pool.shutdown()


def test_saturation_is_immediate():
    pool = SolverPool(1, 1)
    gate = threading.Event()
    try:
        a = pool.submit(gate.wait, 5)
        b = pool.submit(gate.wait, 5)          # queued
        with pytest.raises(PoolSaturated):
            pool.submit(gate.wait, 5)
        gate.set()
        a.future.result(5), b.future.result(5)
        wait_idle(pool)
        assert pool.submit(lambda: 1).future.result(5) == 1
    finally:
        gate.set()
        pool.shutdown()


def test_timeout_interrupts_running_call_and_frees_worker():
    pool = SolverPool(1, 0)
    try:
        t0 = time.perf_counter()
        with pytest.raises(SolveTimeout):
            asyncio.run(pool.run(busy, 30.0, timeout=0.05))
        wait_idle(pool, 2.0)
        assert time.perf_counter() - t0 < 2.0
        assert pool.cancelled_running == 1
        assert asyncio.run(pool.run(busy, 0.001, timeout=5)) == "done"
    finally:
        pool.shutdown()


def test_timeout_drops_queued_call():
    pool = SolverPool(1, 1)
    gate = threading.Event()
    ran = []
    try:
        blocker = pool.submit(gate.wait, 5)

        async def main():
            with pytest.raises(SolveTimeout):
                await pool.run(ran.append, 1, timeout=0.05)

        asyncio.run(main())
        assert pool.in_flight == 1            # only the blocker is left
        gate.set()
        blocker.future.result(5)
        wait_idle(pool)
        assert ran == []                      # the dropped call never ran
    finally:
        gate.set()
        pool.shutdown()


def test_no_stray_cancellation_hits_later_calls():
    """Timeouts racing with completion must never interrupt the next call of the worker."""
    pool = SolverPool(2, 1000)

    async def main():
        racing = [pool.run(busy, 0.0005 * (i % 7), timeout=0.0015) for i in range(300)]
        await asyncio.gather(*racing, return_exceptions=True)
        wait_idle(pool)
        normal = await asyncio.gather(*[pool.run(busy, 0.0005, timeout=30) for _ in range(100)])
        assert normal == ["done"] * 100

    try:
        asyncio.run(main())
    finally:
        pool.shutdown()


def test_each_call_runs_on_one_worker_thread_with_its_own_solvers():
    """Library calls in the pool agree with the main thread's; each worker owns its CasADi model."""
    from tensegrity_opt.numerics import chain_functions

    pool = SolverPool(2, 64)
    m = to.Manipulator.uniform(4)
    expected = to.solve_equilibrium(m, 0.1)
    seen: dict[int, int] = {}
    lock = threading.Lock()

    def job():
        mdl = chain_functions(4)
        with lock:
            seen.setdefault(threading.get_ident(), id(mdl))
            assert seen[threading.get_ident()] == id(mdl)
        return to.solve_equilibrium(m, 0.1)

    async def main():
        return await asyncio.gather(*[pool.run(job, timeout=60) for _ in range(12)])

    try:
        for eq in asyncio.run(main()):
            assert eq.q.tolist() == pytest.approx(expected.q.tolist(), rel=1e-9, abs=1e-12)
        assert len(set(seen.values())) == len(seen)      # one model object per thread, never shared
        assert id(chain_functions(4)) not in seen.values()
    finally:
        pool.shutdown()


def test_shutdown_cancels_queue():
    pool = SolverPool(1, 5)
    gate = threading.Event()
    a = pool.submit(gate.wait, 5)
    queued = [pool.submit(lambda: 1) for _ in range(3)]
    gate.set()
    pool.shutdown()
    assert a.future.done()
    for j in queued:
        assert j.future.done()
    with pytest.raises(PoolSaturated):
        pool.submit(lambda: 1)


def test_heavy_calls_hold_at_most_their_share_of_the_threads():
    pool = SolverPool(2, 8)                   # heavy_limit: workers - 1 = 1
    gate = threading.Event()
    try:
        heavy = [pool.submit(gate.wait, 5, heavy=True) for _ in range(3)]
        time.sleep(0.05)
        assert pool.running == 1              # one thread for the heavy calls, the other kept free
        t0 = time.perf_counter()
        assert pool.submit(lambda: "light").future.result(2) == "light"    # past the queued heavy calls
        assert time.perf_counter() - t0 < 0.5
        gate.set()
        assert [j.future.result(5) for j in heavy] == [True] * 3
        wait_idle(pool)
    finally:
        gate.set()
        pool.shutdown()

