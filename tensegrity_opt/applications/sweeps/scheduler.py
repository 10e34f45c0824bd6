"""Running a sweep: serially in the calling thread, in a pool of threads of this process, or in chunks
on Dask (a local cluster or a scheduler's address), with progress, resume (``skip``) and cancellation
(``should_stop``); ``"auto"`` chooses between serial and a local cluster by the sweep's size and the
measured time of its first points (:data:`AUTO_SERIAL_POINTS`, :data:`AUTO_CLUSTER_SECONDS`)."""

from __future__ import annotations

import concurrent.futures
import math
import os
import statistics
import time
import uuid
from collections.abc import Callable, Iterable
from typing import Any

from ...errors import InvalidParameterError
from .evaluate import _row, _row_error, solve_chunk
from .plan import _parameter_columns, _result_types, column_types, expand
from .results import SweepResult
from .spec import validate_spec

__all__ = ["sweep", "auto_scheduler", "AUTO_SERIAL_POINTS", "AUTO_PROBE_POINTS", "AUTO_PROBE_SECONDS",
           "AUTO_CLUSTER_SECONDS", "SCHEDULERS"]

#: The scheduler names :func:`sweep` takes (besides a ``tcp://host:port`` address or a ``distributed.Client``).
SCHEDULERS = ("auto", "serial", "threads", "local")
#: ``"auto"``: a sweep of at most this many points runs serially (benchmarks/RESULTS.md, "Sweep scheduler
#: default": a local cluster's start, ~5 s on 2 cores, costs more than such a sweep's points).
AUTO_SERIAL_POINTS = 16
#: ``"auto"``, a larger sweep: its first points are solved serially, to time the analysis (the median time
#: per point: a chain length's first point also builds its solvers), until this many are done or, after
#: three at least, :data:`AUTO_PROBE_SECONDS` have passed.
AUTO_PROBE_POINTS = 16
AUTO_PROBE_SECONDS = 5.0
#: ``"auto"``: the rest goes to a local cluster only when, at the probe's time per point, it would take
#: longer than this serially (seconds). Measured on the project's shared 2-core machine, the cluster
#: never won: 5-8 s to start, then at best a tie (270 points of 44 s serially) and 1.5x slower at 540
#: points (82 s); so only sweeps of minutes, where more cores pay, go to it.
AUTO_CLUSTER_SECONDS = 120.0


def _progress(progress: Any) -> tuple[Callable[[int, int, int], Any] | None, Callable[[], Any]]:
    """``(report, close)`` for :func:`sweep`'s ``progress``: a callable is the report itself; True the command
    line's bar (:class:`tensegrity_opt.applications.cli.progress.Progress`, shown when stderr is a terminal)."""
    if callable(progress):
        return progress, lambda: None
    if not progress:
        return None, lambda: None
    from ..cli.progress import Progress

    bar = Progress("sweep", unit="pt")
    return bar, bar.close


def sweep(spec: Any, *, scheduler: Any = None, progress: bool | Callable[[int, int, int], Any] = False,
          on_result: Callable[[int, dict[str, Any]], Any] | None = None, skip: Iterable[int] = (),
          should_stop: Callable[[], bool] | None = None, chunk_size: int | None = None,
          workers: int | None = None) -> SweepResult:
    """Run ``spec`` (see the module docstring) and return its rows.

    Parameters
    ----------
    scheduler : None | "serial" | "threads" | "local" | "auto" | "tcp://host:port" | distributed.Client
        ``None``/``"serial"``: in the calling thread. ``"threads"``: chunks in a pool of ``workers``
        threads of this process (default one per core; no consistent gain over serial measured on 2
        cores: benchmarks/RESULTS.md, "Sweep scheduler default"). ``"local"``: a new ``LocalCluster``
        (``workers`` single-threaded processes, default one per core), closed at the end.
        ``"auto"``: serially when the sweep has at most :data:`AUTO_SERIAL_POINTS` points to solve;
        else its first points serially (:data:`AUTO_PROBE_POINTS`, at most :data:`AUTO_PROBE_SECONDS`),
        and the rest on a local cluster only when, at the measured time per point, it would take
        more than :data:`AUTO_CLUSTER_SECONDS` serially (:func:`auto_scheduler`;
        ``SweepResult.scheduler`` says what ran: ``"serial"`` or ``"serial+local"``).
        An address: the Dask scheduler there (its workers need ``tensegrity_opt`` installed).
    progress : bool or callable(done, total, errors)
        A callable is called in the calling thread as the points arrive (``done`` of ``total`` to solve,
        ``errors`` of them failed; first with ``done = 0``). True: a tqdm bar on stderr, shown only when
        stderr is a terminal (the command line's, :mod:`tensegrity_opt.applications.cli.progress`).
    on_result : callable(index, row), optional
        Called in the calling thread as each point's row arrives (completion order). An
        exception it raises stops the sweep and propagates.
    skip : iterable of int
        Indices already done (resume): not solved, not in the result.
    should_stop : callable() -> bool, optional
        Polled between points (Dask: between chunks); when true, the sweep stops early,
        pending Dask tasks are cancelled and ``SweepResult.cancelled`` is set.
    chunk_size : int, optional
        Points per Dask task (default: about four chunks per worker thread, at most 64).
    """
    norm = validate_spec(spec)
    header = {k: norm[k] for k in ("analysis", "manipulator", "options")}
    param_cols = _parameter_columns(norm)
    result_cols = list(_result_types(header))
    cols = ["index", *param_cols, *result_cols, "error"]
    points = expand(norm)
    skip_set = {int(i) for i in skip}
    todo = [(i, p) for i, p in enumerate(points) if i not in skip_set]
    stop = should_stop or (lambda: False)
    rows: dict[int, dict[str, Any]] = {}
    t0 = time.perf_counter()
    report, close_report = _progress(progress)
    n_err = 0
    cancelled = False
    n_done = 0

    class _Bar:
        """The scheduler's view of ``report``: ``update(k, errors)`` after ``k`` more points."""

        @staticmethod
        def update(k: int, errors: int) -> None:
            nonlocal n_done
            n_done += k
            if report is not None:
                report(n_done, len(todo), errors)

    bar = _Bar()
    bar.update(0, 0)

    def deliver(i: int, row: dict[str, Any]) -> None:
        nonlocal n_err
        rows[i] = row
        if row.get("error"):
            n_err += 1
        if on_result is not None:
            on_result(i, row)

    def serial(items, seconds: float | None = None, times: list[float] | None = None) -> tuple[bool, int]:
        """Solve ``items`` in order (with ``seconds``: until they have passed, at least three points), each
        point's time appended to ``times``: ``(cancelled, how many were solved)``."""
        t_start = time.perf_counter()
        for k, (i, p) in enumerate(items):
            if stop():
                return True, k
            if seconds is not None and k >= 3 and time.perf_counter() - t_start > seconds:
                return False, k
            t_point = time.perf_counter()
            deliver(i, _row(header, param_cols, result_cols, i, p))
            if times is not None:
                times.append(time.perf_counter() - t_point)
            bar.update(1, n_err)
        return False, len(items)

    label = "serial"
    try:
        if scheduler is None or scheduler == "serial":
            cancelled = serial(todo)[0]
        elif scheduler == "auto":
            if auto_scheduler(len(todo)) == "serial":
                cancelled = serial(todo)[0]
            else:
                # the median, not the mean: a chain length's first point also builds its solvers (seconds)
                times: list[float] = []
                cancelled, done = serial(todo[:AUTO_PROBE_POINTS], AUTO_PROBE_SECONDS, times)
                per_point = float(statistics.median(times)) if times else 0.0
                rest = todo[done:]
                if not cancelled and rest:
                    if auto_scheduler(len(rest), per_point) == "serial":
                        cancelled = serial(rest)[0]
                    else:
                        _, cancelled = _run_dask("local", header, param_cols, result_cols, rest, deliver, bar,
                                                 lambda: n_err, stop, chunk_size, workers)
                        label = "serial+local"
        elif scheduler == "threads":
            label, cancelled = "threads", _run_threads(header, param_cols, result_cols, todo, deliver, bar,
                                                       lambda: n_err, stop, chunk_size, workers)
        else:
            label, cancelled = _run_dask(scheduler, header, param_cols, result_cols, todo, deliver, bar,
                                         lambda: n_err, stop, chunk_size, workers)
    finally:
        close_report()
    types = column_types(norm)
    return SweepResult(norm, cols, [rows[i] for i in sorted(rows)], total=len(points), skipped=len(points) - len(todo),
                       cancelled=cancelled, elapsed=time.perf_counter() - t0, scheduler=label, types=types)


def auto_scheduler(points: int, seconds_per_point: float | None = None) -> str:
    """What ``scheduler="auto"`` does with ``points`` points to solve.

    Without ``seconds_per_point``: ``"serial"`` up to :data:`AUTO_SERIAL_POINTS` points, else ``"probe"``
    (solve the first points serially and time them). With the measured ``seconds_per_point``, for the
    ``points`` left after the probe: ``"local"`` (a local Dask cluster) when they would take more than
    :data:`AUTO_CLUSTER_SECONDS` serially, else ``"serial"``.
    """
    if seconds_per_point is None:
        return "serial" if points <= AUTO_SERIAL_POINTS else "probe"
    return "local" if points * seconds_per_point > AUTO_CLUSTER_SECONDS else "serial"


def _chunk_size(chunk_size: int | None, points: int, threads: int) -> int:
    return chunk_size or max(1, min(64, math.ceil(points / (4 * threads))))


def _run_threads(header, param_cols, result_cols, todo, deliver, bar, n_err, stop, chunk_size, workers) -> bool:
    """Chunks of ``todo`` on a pool of ``workers`` threads of this process (each builds its solvers once:
    the library caches them per thread); rows delivered in the calling thread. Returns ``cancelled``."""
    if not todo:
        return False
    threads = workers or os.cpu_count() or 1
    size = _chunk_size(chunk_size, len(todo), threads)
    chunks = [todo[j:j + size] for j in range(0, len(todo), size)]
    with concurrent.futures.ThreadPoolExecutor(max_workers=threads, thread_name_prefix="tensegrity-sweep") as pool:
        futures = [pool.submit(solve_chunk, header, param_cols, result_cols, c) for c in chunks]
        try:
            for fut in concurrent.futures.as_completed(futures):
                results = fut.result()
                for i, row in results:
                    deliver(i, row)
                bar.update(len(results), n_err())
                if stop():
                    return True
        finally:
            for f in futures:
                f.cancel()
    return False


def _run_dask(scheduler: Any, header, param_cols, result_cols, todo, deliver, bar, n_err, stop, chunk_size,
              workers) -> tuple[str, bool]:
    try:
        from distributed import Client, LocalCluster, as_completed
    except ImportError as exc:  # pragma: no cover - optional dependency
        raise InvalidParameterError("scheduler: Dask is not installed (pip install 'dask[distributed]')",
                                    field="scheduler") from exc
    cluster = None
    own_client = True
    if isinstance(scheduler, Client):
        client, own_client, label = scheduler, False, f"dask:{scheduler.scheduler.address}"
    elif scheduler == "local":
        cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1, processes=True,
                               dashboard_address=None)
        client, label = Client(cluster), "local"
    elif isinstance(scheduler, str) and "://" in scheduler:
        client, label = Client(scheduler, timeout="30s"), scheduler
    else:
        raise InvalidParameterError(f"scheduler: expected 'auto', 'serial', 'threads', 'local' or a Dask address like "
                                    f"tcp://host:8786, got {scheduler!r}", field="scheduler")
    cancelled = False
    try:
        if not todo:
            return label, False
        threads = max(1, sum(client.nthreads().values()))
        size = _chunk_size(chunk_size, len(todo), threads)
        chunks = [todo[j:j + size] for j in range(0, len(todo), size)]
        tag = uuid.uuid4().hex[:12]
        max_in_flight = 2 * threads + 2
        pending = iter(enumerate(chunks))
        owner: dict[str, list[tuple[int, Any]]] = {}

        def submit_next() -> Any:
            nxt = next(pending, None)
            if nxt is None:
                return None
            k, chunk = nxt
            fut = client.submit(solve_chunk, header, param_cols, result_cols, chunk, key=f"tensegrity-sweep-{tag}-{k}",
                                pure=False, retries=1)
            owner[fut.key] = chunk
            return fut

        first = [f for f in (submit_next() for _ in range(max_in_flight)) if f is not None]
        ac = as_completed(first)
        for fut in ac:
            chunk = owner.pop(fut.key)
            if fut.status == "error":
                # The task itself failed (worker died, ...): every point of the chunk gets the error.
                err = f"worker_failed: {type(fut.exception()).__name__}: {fut.exception()}"
                results = [(i, _row_error(header, param_cols, result_cols, i, p, err)) for i, p in chunk]
            else:
                results = fut.result()
            fut.release()
            for i, row in results:
                deliver(i, row)
            bar.update(len(results), n_err())
            if stop():
                cancelled = True
                rest = list(ac.futures) if hasattr(ac, "futures") else []
                client.cancel(rest)
                break
            nf = submit_next()
            if nf is not None:
                ac.add(nf)
        return label, cancelled
    finally:
        if own_client:
            client.close()
        if cluster is not None:
            cluster.close()


