"""The executors: the solver threads (bounded queue, time limit, interruption of abandoned calls, one thread per
call, the blocking wait of a thread) and the killable solver processes (the time limit inside the child, the
exception with its type, the bounded queue, a stuck child killed after the grace and replaced)."""

from __future__ import annotations

import asyncio
import threading
import time

import pytest

pytest.importorskip("fastapi")

import tensegrity_opt as to
from service.execution import ProcessExecutor, Saturated, SolveTimeout, ThreadExecutor
from service.execution.shedding import ServiceTimes


def busy(seconds: float) -> str:
    """Pure-Python work (interruptible between bytecodes)."""
    end = time.perf_counter() + seconds
    while time.perf_counter() < end:
        pass
    return "done"


#: How long a test waits for what must happen (an interrupted call to leave its worker, a child to start): the wait
#: ends as soon as it happens. The stand-ins it waits on run far longer (``busy(600)``, ``time.sleep(600)``).
WAIT = 120.0
#: Far beyond any wait: how long a stand-in call runs when nothing interrupts it.
LONG = 600.0


def wait_idle(pool: ThreadExecutor, timeout: float = WAIT) -> None:
    deadline = time.monotonic() + timeout
    while pool.in_flight and time.monotonic() < deadline:
        time.sleep(0.005)
    assert pool.in_flight == 0


def test_run_result_and_exception():
    pool = ThreadExecutor(2, 2)
    try:
        assert asyncio.run(pool.run(lambda x: x * 2, 21, timeout=WAIT)) == 42
        with pytest.raises(ZeroDivisionError):
            asyncio.run(pool.run(lambda: 1 / 0, timeout=WAIT))
        wait_idle(pool)
    finally:
        pool.shutdown()


def test_saturation_is_immediate():
    pool = ThreadExecutor(1, 1)
    gate = threading.Event()
    try:
        a = pool.submit(gate.wait, WAIT)
        b = pool.submit(gate.wait, WAIT)          # queued
        with pytest.raises(Saturated):
            pool.submit(gate.wait, WAIT)
        gate.set()
        a.future.result(WAIT), b.future.result(WAIT)
        wait_idle(pool)
        assert pool.submit(lambda: 1).future.result(WAIT) == 1
    finally:
        gate.set()
        pool.shutdown()


def test_timeout_interrupts_running_call_and_frees_worker():
    pool = ThreadExecutor(1, 0)
    try:
        with pytest.raises(SolveTimeout):
            asyncio.run(pool.run(busy, LONG, timeout=0.05))
        wait_idle(pool)                       # interrupted: long before the call's ten minutes
        assert pool.cancelled_running == 1
        assert asyncio.run(pool.run(busy, 0.001, timeout=WAIT)) == "done"
    finally:
        pool.shutdown()


def test_timeout_drops_queued_call():
    pool = ThreadExecutor(1, 1)
    gate = threading.Event()
    ran = []
    try:
        blocker = pool.submit(gate.wait, WAIT)

        async def main():
            with pytest.raises(SolveTimeout):
                await pool.run(ran.append, 1, timeout=0.05)

        asyncio.run(main())
        assert pool.in_flight == 1            # only the blocker is left
        gate.set()
        blocker.future.result(WAIT)
        wait_idle(pool)
        assert ran == []                      # the dropped call never ran
    finally:
        gate.set()
        pool.shutdown()


def test_no_stray_cancellation_hits_later_calls():
    """Timeouts racing with completion must never interrupt the next call of the worker."""
    pool = ThreadExecutor(2, 1000)

    async def main():
        racing = [pool.run(busy, 0.0005 * (i % 7), timeout=0.0015) for i in range(300)]
        await asyncio.gather(*racing, return_exceptions=True)
        wait_idle(pool)
        normal = await asyncio.gather(*[pool.run(busy, 0.0005, timeout=WAIT) for _ in range(100)])
        assert normal == ["done"] * 100

    try:
        asyncio.run(main())
    finally:
        pool.shutdown()


def test_each_call_runs_on_one_worker_thread_with_its_own_solvers():
    """Library calls in the pool agree with the main thread's; each worker owns its CasADi model."""
    from tensegrity_opt.numerics import chain_functions

    pool = ThreadExecutor(2, 64)
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
        return await asyncio.gather(*[pool.run(job, timeout=WAIT) for _ in range(12)])

    try:
        for eq in asyncio.run(main()):
            assert eq.q.tolist() == pytest.approx(expected.q.tolist(), rel=1e-9, abs=1e-12)
        assert len(set(seen.values())) == len(seen)      # one model object per thread, never shared
        assert id(chain_functions(4)) not in seen.values()
    finally:
        pool.shutdown()


def test_shutdown_cancels_queue():
    pool = ThreadExecutor(1, 5)
    gate = threading.Event()
    a = pool.submit(gate.wait, WAIT)
    queued = [pool.submit(lambda: 1) for _ in range(3)]
    gate.set()
    pool.shutdown()
    assert a.future.done()
    for j in queued:
        assert j.future.done()
    with pytest.raises(Saturated):
        pool.submit(lambda: 1)


def test_heavy_calls_hold_at_most_their_share_of_the_threads():
    pool = ThreadExecutor(2, 8)                   # heavy_limit: workers - 1 = 1
    gate = threading.Event()
    try:
        heavy = [pool.submit(gate.wait, WAIT, heavy=True) for _ in range(3)]
        deadline = time.monotonic() + WAIT
        while pool.running < 1 and time.monotonic() < deadline:
            time.sleep(0.005)
        assert pool.running == 1              # one thread for the heavy calls, the other kept free
        # past the queued heavy calls: answered while the gate holds them (it opens only after this answer)
        assert pool.submit(lambda: "light").future.result(WAIT) == "light"
        assert pool.running == 1 and not any(j.future.done() for j in heavy)
        gate.set()
        assert [j.future.result(WAIT) for j in heavy] == [True] * 3
        wait_idle(pool)
    finally:
        gate.set()
        pool.shutdown()



def test_a_thread_waits_for_its_call_and_a_late_call_is_interrupted():
    """``wait`` (a thread's way to run, the job runner's): the result; past the timeout the call is interrupted at
    its next bytecode (``SolveTimeout``) and the worker is free again."""
    pool = ThreadExecutor(1, 0)
    try:
        assert pool.wait(pool.submit(busy, 0.001), WAIT) == "done"
        call = pool.submit(busy, LONG)
        with pytest.raises(SolveTimeout):
            pool.wait(call, 0.05)
        wait_idle(pool)                       # interrupted: long before the call's ten minutes
        assert pool.wait(pool.submit(busy, 0.001), WAIT) == "done"
    finally:
        pool.shutdown()


def _stubborn() -> str:
    """Swallows the first interrupt (as a finaliser run by the garbage collector in that thread would), then
    works on."""
    try:
        busy(LONG)
    except BaseException:  # noqa: BLE001 - the point of the test
        pass
    return busy(LONG)


def test_an_interrupt_swallowed_once_is_sent_again():
    pool = ThreadExecutor(1, 0)
    try:
        with pytest.raises(SolveTimeout):
            pool.wait(pool.submit(_stubborn), 0.05)
        # the second busy(LONG) was interrupted too: by a repeat, REFIRE_SECONDS after the first interrupt
        wait_idle(pool)
    finally:
        pool.shutdown()


# ---------------------------------------------------------------------------- killable processes
@pytest.mark.slow
def test_a_process_call_runs_under_its_time_limit_and_raises_with_its_type():
    from tensegrity_opt.timelimit import remaining

    async def main():
        ex = ProcessExecutor(1, queue_size=2, grace=0.5)
        ex.start()
        try:
            assert await ex.wait_ready(WAIT)
            left = await ex.run(remaining, timeout=WAIT)        # the library's limit is set in the child
            assert 0.0 < left <= WAIT
            with pytest.raises(to.InvalidParameterError) as err:    # the library's exception, fields included
                await ex.run(to.Manipulator.uniform, 0, timeout=WAIT)
            assert err.value.field == "n"
            assert await ex.run(pow, 2, 10, timeout=WAIT) == 1024
            assert ex.killed == 0 and ex.in_flight == 0
        finally:
            ex.shutdown()

    asyncio.run(main())


@pytest.mark.slow
def test_a_stuck_process_is_killed_after_the_grace_and_its_queue_is_bounded():
    """One child, one call waiting at most: a third call is refused (503); the stuck call answers 504 at its
    deadline, its child is killed ``grace`` later and replaced, and the call that waited times out too (it never
    got the child); the replacement answers."""

    async def main():
        ex = ProcessExecutor(1, queue_size=1, grace=0.3)
        ex.start()
        try:
            assert await ex.wait_ready(WAIT)
            stuck = asyncio.ensure_future(ex.run(time.sleep, LONG, timeout=0.5))
            await asyncio.sleep(0.05)
            waiting = asyncio.ensure_future(ex.run(pow, 2, 3, timeout=0.5))
            await asyncio.sleep(0.05)
            with pytest.raises(Saturated):
                await ex.run(pow, 2, 4, timeout=WAIT)
            for fut in (stuck, waiting):
                with pytest.raises(SolveTimeout):
                    await fut
            [old] = ex.pids
            t0 = time.monotonic()
            while old in ex.pids and time.monotonic() - t0 < WAIT:
                await asyncio.sleep(0.02)
            assert old not in ex.pids and ex.killed == 1 and ex.restarts == 1 and ex.in_flight == 0
            assert await ex.run(pow, 2, 5, timeout=WAIT) == 32          # the replacement, once it has started
        finally:
            ex.shutdown()

    asyncio.run(main())


class StandInClock:
    """The executor's clock, moved by the test only."""

    def __init__(self) -> None:
        self.now = 1000.0

    def __call__(self) -> float:
        return self.now


def wait_running(pool: ThreadExecutor, count: int, timeout: float = WAIT) -> None:
    deadline = time.monotonic() + timeout
    while pool.running < count and time.monotonic() < deadline:
        time.sleep(0.005)
    assert pool.running == count


def test_a_call_that_could_not_finish_before_its_deadline_is_refused_at_once():
    """Calls of a kind whose service time is estimated at 4 s (put in place, on a clock that only the test moves):
    a call that would wait behind them is refused when wait plus its own time (times the margin) reaches its limit,
    accepted otherwise; the refusal says when to come back."""
    clock = StandInClock()
    times = ServiceTimes(clock=clock)
    times.set(False, 4.0, kind="solve")
    pool = ThreadExecutor(1, 8, service_times=times)
    gate = threading.Event()
    try:
        running = pool.submit(gate.wait, LONG, kind="solve", timeout=LONG)
        wait_running(pool, 1)
        assert pool.expected_wait() == 4.0                     # the running call's estimate, none of it run yet
        queued = pool.submit(gate.wait, LONG, kind="solve", timeout=LONG)
        assert pool.expected_wait() == 8.0                     # then the queued one's
        with pytest.raises(Saturated) as refused:              # 1.25 x (8 + 4) = 15 s >= 14 s
            pool.submit(gate.wait, LONG, kind="solve", timeout=14.0)
        assert refused.value.retry_after == 1 and "expected wait" in str(refused.value)
        assert pool.shed == 1 and pool.in_flight == 2
        with pytest.raises(Saturated) as refused:
            pool.submit(gate.wait, LONG, kind="solve", timeout=5.0)
        assert refused.value.retry_after == 10                 # 15 s - 5 s
        clock.now += 3.0                                       # the running call has 1 s left by its estimate
        assert pool.expected_wait() == 5.0
        third = pool.submit(gate.wait, LONG, kind="solve", timeout=14.0)    # 1.25 x (5 + 4) < 14
        assert pool.shed == 2 and pool.in_flight == 3
        gate.set()
        for call in (running, queued, third):
            call.future.result(WAIT)
        wait_idle(pool)
    finally:
        gate.set()
        pool.shutdown()


def test_a_call_that_finds_a_free_thread_is_never_refused_by_an_estimate():
    clock = StandInClock()
    times = ServiceTimes(clock=clock)
    times.set(False, 100.0, kind="solve")
    pool = ThreadExecutor(2, 0, service_times=times)
    gate = threading.Event()
    try:
        first = pool.submit(gate.wait, LONG, kind="solve", timeout=1.0)       # the estimate exceeds the limit
        second = pool.submit(gate.wait, LONG, kind="solve", timeout=1.0)
        assert pool.shed == 0 and pool.in_flight == 2
        gate.set()
        first.future.result(WAIT), second.future.result(WAIT)
    finally:
        gate.set()
        pool.shutdown()


def test_a_light_call_is_not_refused_for_heavy_calls_it_passes():
    """Two threads, one for heavy calls: heavy calls of 100 s queued behind a running one do not delay a light
    call (it takes the other thread when the light call there ends), so it is accepted; a heavy one is refused."""
    clock = StandInClock()
    times = ServiceTimes(clock=clock)
    times.set(True, 100.0, kind="heavy")
    times.set(False, 1.0, kind="light")
    pool = ThreadExecutor(2, 8, heavy_limit=1, service_times=times)
    gate = threading.Event()
    try:
        calls = [pool.submit(gate.wait, LONG, heavy=True, kind="heavy", timeout=LONG),
                 pool.submit(gate.wait, LONG, kind="light", timeout=LONG)]
        wait_running(pool, 2)
        calls += [pool.submit(gate.wait, LONG, heavy=True, kind="heavy", timeout=LONG) for _ in range(3)]
        assert pool.expected_wait(heavy=False) == 1.0
        assert pool.expected_wait(heavy=True) == 400.0
        calls.append(pool.submit(gate.wait, LONG, kind="light", timeout=10.0))
        with pytest.raises(Saturated):
            pool.submit(gate.wait, LONG, heavy=True, kind="heavy", timeout=300.0)
        gate.set()
        for call in calls:
            call.future.result(WAIT)
    finally:
        gate.set()
        pool.shutdown()


def test_the_estimates_follow_the_calls_per_kind_and_class():
    times = ServiceTimes(weight=0.5)
    assert times.estimate(False, "a") == 0.0                   # nothing seen: nothing refused by an estimate
    times.record(False, 2.0, "a")
    times.record(False, 4.0, "a")
    assert times.estimate(False, "a") == 3.0
    assert times.estimate(False, "b") == 3.0                   # a kind not seen yet: its class's estimate
    assert times.estimate(True, "b") == 0.0


def test_a_refusal_by_the_expected_wait_is_a_503_with_retry_after():
    from service.api.errors import to_api_error
    from service.execution.shedding import refusal

    err = to_api_error(refusal("all 2 solver workers", 12.0, 4.0, 10.0), retry_after=1)
    assert err.status_code == 503 and err.body["code"] == "overloaded"
    assert err.headers["Retry-After"] == "10"                  # 1.25 x 16 s - 10 s
    err = to_api_error(Saturated("full"), retry_after=3)
    assert err.headers["Retry-After"] == "3"


@pytest.mark.slow
def test_a_process_call_that_could_not_finish_before_its_deadline_is_refused_at_once():
    async def scenario() -> None:
        pool = ProcessExecutor(1, queue_size=4, grace=0.1)
        clock = StandInClock()
        pool.service_times = ServiceTimes(clock=clock)
        pool.service_times.set(False, 4.0, kind="sleep")
        pool.start()
        assert await pool.wait_ready(WAIT)
        try:
            busy = asyncio.ensure_future(pool.run(time.sleep, LONG, timeout=LONG, kind="sleep"))
            while not pool.expected_wait():
                await asyncio.sleep(0.005)
            assert pool.expected_wait() == 4.0
            with pytest.raises(Saturated):                       # 1.25 x (4 + 4) >= 9
                await pool.run(time.sleep, 0.0, timeout=9.0, kind="sleep")
            assert pool.shed == 1
            busy.cancel()
        finally:
            pool.shutdown()

    asyncio.run(scenario())


@pytest.mark.slow
def test_the_losses_in_a_row_start_over_after_a_healthy_period(monkeypatch):
    """Children killed from outside: each loss in a row counts (the delay grows with the count) until a child has
    been ready for the healthy period; then the next loss is the first again."""
    import os
    import signal

    from service.execution import processes

    monkeypatch.setattr(processes, "RESTART_BASE", 0.0)

    async def kill_and_wait(pool: ProcessExecutor, restarts: int) -> None:
        [pid] = pool.pids
        os.kill(pid, signal.SIGKILL)
        deadline = time.monotonic() + WAIT
        while not (pool.restarts == restarts and pool.ready) and time.monotonic() < deadline:
            await asyncio.sleep(0.01)
        assert pool.restarts == restarts and pool.ready and pool.state == "up"

    async def scenario() -> None:
        pool = ProcessExecutor(1)
        pool.start()
        assert await pool.wait_ready(WAIT) and pool.state == "up"
        try:
            monkeypatch.setattr(processes, "HEALTHY_SECONDS", 1e9)
            await kill_and_wait(pool, 1)
            assert pool.losses == 1
            await kill_and_wait(pool, 2)
            assert pool.losses == 2
            monkeypatch.setattr(processes, "HEALTHY_SECONDS", 0.0)    # every child ready so far was healthy
            await kill_and_wait(pool, 3)
            assert pool.losses == 1
        finally:
            pool.shutdown()
        assert pool.state == "down"

    asyncio.run(scenario())
