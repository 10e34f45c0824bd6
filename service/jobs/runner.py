"""The job runner: the threads that run the stored sweep jobs, point by point.

Execution and scheduling
------------------------
``TENSEGRITY_JOBS_MAX_RUNNING`` runner threads (default 2), never the event loop, each run one job at a time.
Fair scheduling: a thread that has run its job for ``TENSEGRITY_JOBS_SLICE_SECONDS`` checks, between two
points, whether another job waits; if so its job goes back to ``queued`` and the thread claims the job that
waited longest (``turn_at``: its creation, then the end of its last turn), i.e. round-robin in order of
arrival. A job alone keeps its thread.

With ``TENSEGRITY_JOBS_SCHEDULER`` unset each point runs on the runner's own
:class:`~service.execution.threads.ThreadExecutor` (one thread per runner thread: the library caches its
CasADi solvers per thread; the requests' threads are never taken), under ``TENSEGRITY_JOBS_POINT_TIMEOUT``: a
late point is interrupted (it stops at its thread's next bytecode, once the CasADi/IPOPT call in progress
returns), its row becomes the error ``timeout: ...`` and the job goes on. In-process rather than a killable
subprocess per point: no process start-up and solver rebuild per point, rows identical to
``tensegrity_opt.applications.sweeps``'s; the price is that one native call longer than the limit runs to its
end (the library bounds each IPOPT call itself: ``ipopt.max_wall_time`` 20 s, 60 s for a design NLP, so a late
point ends at most that long after its deadline). ``local`` or ``tcp://host:port`` sends the points to Dask
(:func:`tensegrity_opt.applications.sweeps.sweep`; no per-point limit there).

Leases, resume, cancel
----------------------
The runner claims jobs from the store (:mod:`service.jobs.store`) under a lease of
``TENSEGRITY_JOBS_LEASE_SECONDS``; a heartbeat thread renews it every third of that, and when the renewal finds
the job no longer ``running`` under this runner's lease (cancelled through another server, deleted, or taken
over after this server stalled) the runner abandons the point in progress. At start the runner takes the jobs a
previous process left ``running`` or ``queued`` and resumes them (only the indices not stored yet are solved);
with ``TENSEGRITY_JOBS_RESUME=false`` a job left ``running`` is marked ``interrupted`` (its points are kept). A
graceful shutdown stops the running jobs between two points and puts them back to ``queued``.
``POST /v1/jobs/{id}/cancel`` stops a job at once (its point in progress is abandoned and stores nothing;
finished points are kept); ``DELETE`` removes a job with its rows (cancelling it first). Finished jobs older than
``TENSEGRITY_JOBS_RETENTION_DAYS`` (0: never) are deleted at start-up and hourly.

Figure jobs
-----------
A figure (``POST /v1/plots/<kind>/job``, analysis ``figure``) runs as one call on the same points' thread, under
``TENSEGRITY_JOBS_POINT_TIMEOUT`` (a continuation's soft deadline at 90 % of it: it draws what it has by then);
each step it reports is a row (``index``, ``stage``, ``error``: the targets of an atlas, the drawing), then the image
is stored (:meth:`JobStore.put_figure`) with the last row and the job is ``done``. A failure is a row with its
``error`` (``code: message``, ``timeout: ...`` past the limit) and the job ``failed`` with the same message. A
resumed figure job starts its figure again (the rows of its steps are stored once).

Every SQLite or OS error of an API call raises :class:`~service.jobs.store.JobsUnavailable` (503
``jobs_unavailable``, saying what failed, not where on disk). The database file is created on the first
submitted job, so a server that never gets a job leaves no file behind.

Storage faults clear
--------------------
No fault is final (but a file deleted or replaced while the server runs): every API call tries the store again,
and while the store fails (:meth:`JobRunner.health`, shown by ``/readyz``) a watcher thread retries it every
``TENSEGRITY_JOBS_RETRY_SECONDS``: it opens the file when it could not be opened, then probes it
(:meth:`JobStore.probe <service.jobs.store.JobStore.probe>`: free space, a small write). Once a probe succeeds the
store is healthy again, the runner threads take up the queue, and the jobs a storage fault cut off in this
server go back to ``queued`` at once (rather than after their lease).
"""

from __future__ import annotations

import functools
import logging
import os
import socket
import sqlite3
import threading
import time
import uuid
from collections.abc import Callable, Iterator, Mapping
from pathlib import Path
from typing import Any

# Names, not the module: ``tensegrity_opt.applications.sweeps`` may be re-exported as the function.
from tensegrity_opt.applications.sweeps import columns as sweep_columns
from tensegrity_opt.applications.sweeps import count_points, error_row, format_error, solve_chunk, validate_spec
from tensegrity_opt.applications.sweeps import plan as plan_sweep
from tensegrity_opt.applications.sweeps import sweep as run_sweep
from tensegrity_opt.errors import InvalidParameterError

from ..config import Settings
from ..execution.executor import SolveTimeout
from ..execution.threads import Call, ThreadExecutor
from ..tasks.plots import FIGURE_ANALYSIS, figure_job_task
from .store import NAME, JobFinished, JobNotFound, JobStore, JobsUnavailable, fault_text

log = logging.getLogger("service.jobs")

__all__ = ["JobRunner", "FIGURE_COLUMNS", "FIGURE_MEDIA"]

#: The rows of a figure job: one per step.
FIGURE_COLUMNS = ["index", "stage", "error"]
#: A figure job's image format -> media type.
FIGURE_MEDIA = {"png": "image/png", "svg": "image/svg+xml"}
#: The share of ``TENSEGRITY_JOBS_POINT_TIMEOUT`` a figure job's continuation may use (then it draws what it has).
FIGURE_DEADLINE_SHARE = 0.9

def _setting(settings: Any, name: str, fallback: Any) -> Any:
    value = getattr(settings, name, None) if settings is not None else None
    return fallback if value is None else value


class _Slot:
    """One runner thread: the job it holds and the point it runs."""

    def __init__(self, k: int) -> None:
        self.k = k
        self.job_id: str | None = None
        self.stop = threading.Event()     # the job was cancelled, or the lease was lost
        self.renewed = 0.0                # monotonic time of the last successful renewal
        self.call: Call | None = None     # the point in progress
        self.abandoned = False            # that point was given up (cancel, lease lost, shutdown): no row


def _storage_guard(fn: Callable[..., Any]) -> Callable[..., Any]:
    """Every storage fault of an API call becomes :class:`JobsUnavailable` (503 ``jobs_unavailable``)."""

    @functools.wraps(fn)
    def wrapper(self: JobRunner, *args: Any, **kwargs: Any) -> Any:
        try:
            return fn(self, *args, **kwargs)
        except (sqlite3.Error, OSError) as exc:
            raise JobsUnavailable(self._fault_message(exc)) from exc

    return wrapper


class JobRunner:
    """Accepts jobs, stores them, and runs at most ``jobs_max_running`` of them at a time.

    ``JobRunner(settings)``: the service's :class:`service.config.Settings` (its ``jobs_*`` fields;
    ``max_segments`` limits the chains of a job); without it the settings are read from the
    environment. Keyword arguments win.
    """

    def __init__(self, settings: Any = None, *, db_path: str | os.PathLike[str] | None = None,
                 scheduler: str | None = None, resume: bool | None = None, max_points: int | None = None,
                 synchronous: str | None = None, chunk_size: int | None = None, point_timeout: float | None = None,
                 max_running: int | None = None, slice_seconds: float | None = None,
                 retention_days: float | None = None, lease_seconds: float | None = None,
                 retry_seconds: float | None = None) -> None:
        self.config_error: str | None = None
        try:
            js = settings if settings is not None else Settings()
        except ValueError as exc:  # reported by start(); building the app (e.g. for OpenAPI) still works
            js = Settings.model_construct()
            self.config_error = f"invalid TENSEGRITY_JOBS_* or other TENSEGRITY_* setting: {exc}"

        def pick(given: Any, name: str) -> Any:
            return given if given is not None else _setting(settings, name, getattr(js, name))

        self.db_path = Path(pick(db_path, "jobs_db"))
        self.scheduler = pick(scheduler, "jobs_scheduler")
        if self.scheduler == "serial":
            self.scheduler = None
        self.resume = bool(pick(resume, "jobs_resume"))
        self.max_points = int(pick(max_points, "jobs_max_points"))
        self.chunk_size = pick(chunk_size, "jobs_chunk_size")
        self.point_timeout = float(pick(point_timeout, "jobs_point_timeout"))
        self.max_running = int(pick(max_running, "jobs_max_running"))
        self.slice_seconds = float(pick(slice_seconds, "jobs_slice_seconds"))
        self.retention_days = float(pick(retention_days, "jobs_retention_days"))
        self.lease_seconds = float(pick(lease_seconds, "jobs_lease_seconds"))
        self.retry_seconds = float(pick(retry_seconds, "jobs_retry_seconds"))
        self.results_max_limit = int(_setting(settings, "jobs_results_max_limit", js.jobs_results_max_limit))
        self.max_segments = _setting(settings, "max_segments", None)
        self.homotopy_max_segments = _setting(settings, "homotopy_max_segments", None)
        self.store = JobStore(self.db_path, synchronous or _setting(settings, "jobs_synchronous", js.jobs_synchronous))
        #: This runner's identity in the leases (one per server process).
        self.host = socket.gethostname()
        self.id = f"{self.host}:{os.getpid()}-{uuid.uuid4().hex[:12]}"
        self.points_computed = 0          # points this runner solved (tests, statistics)
        self._ready = False
        self._lock = threading.Lock()          # slots / opening the store
        self._wake = threading.Condition(threading.Lock())
        self._stopping = threading.Event()
        self._threads: list[threading.Thread] = []
        self._slots = [_Slot(k) for k in range(self.max_running)]
        self._point_lock = threading.Lock()    # a slot's point in progress (taken inside ``_lock`` too)
        #: where the points run: one thread per runner thread (the library's solvers are cached per thread)
        self.points = ThreadExecutor(self.max_running, 0, name="sweep-points")
        self._purged = 0.0
        self._fault_logged = -1e9
        self._stranded: set[str] = set()       # jobs a storage fault cut off here (released once it clears)

    # -------------------------------------------------------------- lifecycle
    def start(self) -> JobRunner:
        """Open an existing database (purging expired jobs, resuming unfinished ones) and start the
        runner threads, their point threads and the lease heartbeat.

        Raises ``RuntimeError`` for an invalid ``TENSEGRITY_JOBS_*`` setting. A database that cannot
        be opened does not stop the service: the jobs API answers 503 ``jobs_unavailable``.
        """
        if self._threads:
            return self
        if self.config_error:
            raise RuntimeError(self.config_error)
        self._stopping.clear()
        if self.store.exists():
            try:
                self._open()
            except Exception as exc:  # the rest of the service keeps working; the watcher retries
                log.error("cannot open the job store %s (retried every %g s): %r", self.db_path, self.retry_seconds,
                          exc)
        targets = [(f"sweep-jobs-{s.k}", functools.partial(self._loop, s)) for s in self._slots]
        targets += [("sweep-jobs-lease", self._heartbeat), ("sweep-jobs-watch", self._watch)]
        self.points = ThreadExecutor(self.max_running, 0, name="sweep-points")
        self.points.start()
        for name, target in targets:
            t = threading.Thread(target=target, name=name, daemon=True)
            self._threads.append(t)
            t.start()
        return self

    def stop(self, timeout: float = 30.0) -> None:
        """Stop: the points in progress are abandoned (computed again on resume) and the jobs go back to
        ``queued``; close the database."""
        self._stopping.set()
        for slot in self._slots:      # the points in progress are dropped (computed again on resume)
            self._abandon(slot)
        with self._wake:
            self._wake.notify_all()
        deadline = time.monotonic() + timeout
        for t in self._threads:
            t.join(max(0.0, deadline - time.monotonic()))
            if t.is_alive():  # pragma: no cover - a point longer than the timeout
                log.warning("the job runner did not stop within %g s", timeout)
                return
        self._threads = []
        self.points.shutdown(max(0.0, deadline - time.monotonic()))
        with self._lock:
            self._ready = False
        self.store.close()

    def _open(self) -> None:
        """Open the store once (creating it when missing): free the leases of dead runners of this host, resume
        or interrupt the jobs a previous process left running, purge expired jobs. Raises (and stays closed, to
        be tried again) when any of it fails."""
        with self._lock:
            if not self._ready:
                self.store.open()
                self.store.free_dead_leases(self.host)
                n = self.store.recover(self.resume)
                if n:
                    log.warning("%d job(s) left running by a previous process marked interrupted", n)
                self._purge()
                self._ready = True

    def _fault_message(self, exc: BaseException) -> str:
        """What failed (the store's health, else the exception), never where on disk."""
        return self.store.health()["message"] or f"{NAME} cannot be used: {fault_text(exc)}"

    def health(self) -> dict[str, Any]:
        """The job store's health: ``status`` ``ok`` or ``failing``, ``message`` (what fails, no path) and
        ``since`` (epoch seconds). Reads no file (for ``/readyz``)."""
        return self.store.health()

    def _store(self) -> JobStore:
        if not self._ready:
            if not self.store.exists():
                raise JobNotFound("")
            self._open()
        self.store.check_file()
        return self.store

    # -------------------------------------------------------------- API
    def validate(self, spec: Any) -> tuple[dict[str, Any], int, list[str]]:
        """The normalised spec, its number of points and its columns; ``InvalidParameterError`` otherwise."""
        total = count_points(spec)
        if total > self.max_points:
            kind = "grid" if spec.get("grid") is not None else "points"
            raise _TooLarge(f"{kind}: the sweep has {total} points; this server runs at most {self.max_points} "
                            f"per job", field=kind, total=total, max_points=self.max_points)
        norm = validate_spec(spec)
        if self.max_segments is not None:
            for fld, n in _segment_counts(norm):
                if n > self.max_segments:
                    raise _TooManySegments(f"{fld}: the chain has {n} segments; this server accepts at most "
                                           f"{self.max_segments}", field=fld, n=n, max_segments=self.max_segments)
        if norm["options"].get("method") == "homotopy" and self.homotopy_max_segments is not None:
            # the server's limit of the homotopy (as /v1/equilibria's): its path count grows ~8x a segment
            for fld, n in _segment_counts(norm):
                if n > self.homotopy_max_segments:
                    raise _TooManySegments(f"options.method: method 'homotopy' is accepted for chains of up to "
                                           f"{self.homotopy_max_segments} segments; {fld} has {n}: use 'search'",
                                           field="options.method", n=n,
                                           homotopy_max_segments=self.homotopy_max_segments)
        return norm, total, sweep_columns(norm)

    @_storage_guard
    def submit(self, spec: Any, owner: str | None = None) -> dict[str, Any]:
        """Validate and store a new ``queued`` job (of ``owner``: an API key's hash); a runner thread picks it up."""
        norm, total, cols = self.validate(spec)
        return self._create(norm, total, cols, owner)

    @_storage_guard
    def submit_figure(self, kind: str, fmt: str, request: Mapping[str, Any], total: int,
                      owner: str | None = None) -> dict[str, Any]:
        """Store a new ``queued`` figure job: the figure ``kind`` of ``request`` (its JSON form, checked by the route
        against the server's limits) as ``fmt``, in ``total`` steps (:func:`service.tasks.plots.figure_steps`)."""
        spec = {"analysis": FIGURE_ANALYSIS, "kind": kind, "format": fmt, "request": dict(request)}
        return self._create(spec, int(total), list(FIGURE_COLUMNS), owner)

    def _create(self, spec: dict[str, Any], total: int, cols: list[str], owner: str | None) -> dict[str, Any]:
        try:
            self._open()
        except Exception as exc:
            self._log_fault("cannot open the job store %s: %r", self.db_path, exc)
            raise
        self.store.check_file()
        job = self.store.create(spec, total, cols, owner)
        with self._wake:
            self._wake.notify()
        return job

    @_storage_guard
    def figure(self, job_id: str) -> tuple[str, bytes] | None:
        """The media type and bytes of a figure job's image (``None`` before it is stored)."""
        return self._store().figure(job_id)

    @_storage_guard
    def get(self, job_id: str, owner: str | None = None) -> dict[str, Any]:
        try:
            return self._store().get(job_id, owner)
        except JobNotFound:
            raise JobNotFound(job_id) from None

    @_storage_guard
    def rows(self, job_id: str, offset: int = 0, limit: int | None = None) -> list[dict[str, Any]]:
        return self._store().rows(job_id, offset, limit)

    def row_batches(self, job_id: str, offset: int = 0, limit: int | None = None,
                    batch: int = 1000) -> Iterator[list[dict[str, Any]]]:
        """:meth:`JobStore.row_batches`; storage faults as :class:`JobsUnavailable`."""
        it = self._store().row_batches(job_id, offset, limit, batch)
        while True:
            try:
                b = next(it)
            except StopIteration:
                return
            except (sqlite3.Error, OSError) as exc:
                raise JobsUnavailable(self._fault_message(exc)) from exc
            yield b

    @_storage_guard
    def list(self, limit: int = 50, status: str | None = None, owner: str | None = None) -> list[dict[str, Any]]:
        if not self._ready and not self.store.exists():
            return []
        return self._store().list(limit, status, owner)

    @_storage_guard
    def cancel(self, job_id: str, owner: str | None = None) -> dict[str, Any]:
        """Cancel a queued or running job (its finished points are kept). ``JobFinished`` when it ended.

        A job running here stops at once (its point in progress is abandoned); one running in another
        server sharing the file stops at that server's next lease renewal (a third of
        ``TENSEGRITY_JOBS_LEASE_SECONDS``).
        """
        store = self._store()
        store.get(job_id, owner)                      # JobNotFound for someone else's job
        with self._lock:
            updated = store.update(job_id, status="cancelled", when=("queued", "running"), finished_at=time.time(),
                                   lease_until=None, message="cancelled by a request; finished points are kept")
            if updated:
                for slot in self._slots:
                    if slot.job_id == job_id:
                        slot.stop.set()
                        self._abandon(slot)
        job = self.get(job_id, owner)
        if not updated and job["status"] != "cancelled":
            raise JobFinished(job["status"])
        return job

    @_storage_guard
    def delete(self, job_id: str, owner: str | None = None) -> None:
        """``DELETE /v1/jobs/{id}``: remove the job and all its rows; a queued or running one is cancelled
        first (it stops here at once, in another server sharing the file at its next lease renewal, and
        stores nothing more: rows are stored only under a held lease of an existing job).
        ``JobNotFound`` when there is no such job (of this owner)."""
        store = self._store()
        if store.delete(job_id, owner):
            return
        try:
            self.cancel(job_id, owner)
        except JobFinished:        # it finished between the two statements
            pass
        if not store.delete(job_id, owner):
            raise JobNotFound(job_id)

    def wait_idle(self, timeout: float = 10.0) -> bool:
        """True once no job is running here (tests)."""
        deadline = time.monotonic() + timeout
        while any(s.job_id for s in self._slots):
            if time.monotonic() > deadline:
                return False
            time.sleep(0.02)
        return True

    def running_here(self) -> list[str]:
        """Ids of the jobs this runner's threads hold now."""
        return [s.job_id for s in self._slots if s.job_id]

    # -------------------------------------------------------------- threads
    def _poll(self) -> float:
        return min(1.0, self.lease_seconds / 4)

    def _loop(self, slot: _Slot) -> None:
        while not self._stopping.is_set():
            job = None
            if self._ready:
                try:
                    self.store.check_file()
                    self.store.free_dead_leases(self.host)
                    if not self.resume:
                        self.store.recover(False)
                    with self._lock:
                        held = [s.job_id for s in self._slots if s.job_id]
                    job = self.store.claim(self.id, self.lease_seconds, exclude=held)
                except Exception as exc:  # database trouble: retry later (logged once a minute)
                    self._log_fault("job runner: cannot read the job queue of %s: %r", self.db_path, exc)
            if job is None:
                with self._wake:
                    if not self._stopping.is_set():
                        self._wake.wait(self._poll())
                continue
            with self._lock:
                slot.job_id = job["id"]
                slot.stop = threading.Event()
                slot.renewed = time.monotonic()
            try:
                self._run(slot, job)
            except (sqlite3.Error, JobsUnavailable) as exc:  # released as soon as the store works again
                with self._lock:
                    self._stranded.add(job["id"])
                self._log_fault("job %s: stopped by a fault of the job store %s: %r", job["id"], self.db_path, exc)
            except Exception:  # never let the runner die (the lease expires; the job is taken up again)
                log.exception("job %s: unexpected runner error", job["id"])
            finally:
                with self._lock:
                    slot.job_id = None

    def _run(self, slot: _Slot, job: dict[str, Any]) -> None:
        """Run ``job`` until it is done, cancelled, its lease lost, its slice over or the server stops."""
        job_id = job["id"]
        if job["analysis"] == FIGURE_ANALYSIS:
            self._run_figure(slot, job)
            return
        done = self.store.done_indices(job_id)
        log.info("job %s: running (%d of %d points already stored)", job_id, len(done), job["total"])
        slice_end = time.monotonic() + self.slice_seconds
        yielded = False

        def should_stop() -> bool:
            nonlocal slice_end, yielded
            if slot.stop.is_set() or self._stopping.is_set():
                return True
            if time.monotonic() >= slice_end:
                with self._lock:
                    held = [s.job_id for s in self._slots if s.job_id]
                if self.store.waiting(exclude=held):
                    yielded = True
                    return True
                slice_end = time.monotonic() + self.slice_seconds
            return False

        t0 = time.perf_counter()
        try:
            if self.scheduler is None:
                header, pcols, rcols, points = plan_sweep(job["spec"])
                for i, p in enumerate(points):
                    if i in done:
                        continue
                    if should_stop():
                        break
                    row = self._timed_row(slot, header, pcols, rcols, i, p)
                    if row is None:      # abandoned: cancelled, lease lost, or the server stops
                        break
                    self.points_computed += 1
                    self.store.add_point(job_id, i, row, self.id)
            else:
                run_sweep(job["spec"], scheduler=self.scheduler, skip=done, should_stop=should_stop,
                          on_result=lambda i, row: self.store.add_point(job_id, i, row, self.id),
                          chunk_size=self.chunk_size)
        except Exception as exc:
            if isinstance(exc, (sqlite3.Error, JobsUnavailable)):
                raise
            detail = exc.strerror if isinstance(exc, OSError) and exc.filename else exc   # the job names no file
            msg = format_error(exc) if not isinstance(exc, (OSError, TimeoutError)) else \
                f"scheduler_unreachable: {type(exc).__name__}: {detail}"
            log.warning("job %s failed: %s (%r)", job_id, msg, exc)
            self.store.release(job_id, self.id, status="failed", message=msg[:2000], finished=True)
            return
        if slot.stop.is_set():
            return  # cancelled (a cancel or DELETE set "cancelled"), or another server holds the job now
        stored = self.store.count(job_id)
        if stored >= job["total"]:
            self.store.release(job_id, self.id, status="done", finished=True)
            log.info("job %s: done (%d points, %.1f s in this run)", job_id, job["total"], time.perf_counter() - t0)
        elif self._stopping.is_set():
            self._stopped(job_id)
        elif yielded:
            self.store.release(job_id, self.id, status="queued",
                               message=f"waiting for its next turn ({stored} of {job['total']} points done; "
                                       f"jobs take turns of {self.slice_seconds:g} s)")
        else:  # pragma: no cover - defensive
            self.store.release(job_id, self.id, status="failed", finished=True,
                               message=f"internal_error: {stored} of {job['total']} points stored")

    def _stopped(self, job_id: str) -> None:
        """A server shutdown stopped ``job_id``: back to ``queued`` (resumed at the next start), or interrupted."""
        if self.resume:
            self.store.release(job_id, self.id, status="queued",
                               message="stopped by a server shutdown; resumes when the server starts again")
        else:
            self.store.release(job_id, self.id, status="interrupted", finished=True,
                               message="stopped by a server shutdown; finished points are kept")

    def _run_figure(self, slot: _Slot, job: dict[str, Any]) -> None:
        """Draw a figure job on the points' thread (module docstring: Figure jobs)."""
        job_id, spec, total = job["id"], job["spec"], int(job["total"])
        last = total - 1                       # the last row is the stored image's
        step = [0]
        log.info("job %s: drawing the figure %s", job_id, spec.get("kind"))

        def row(stage: str, error: str | None = None) -> None:
            i = min(step[0], last)
            step[0] += 1
            self.store.add_point(job_id, i, {"index": i, "stage": stage, "error": error}, self.id)

        def progress(stage: str) -> None:      # on the points' thread
            if step[0] < last:
                row(stage)

        data: bytes | None = None
        error: str | None = None
        with self._point_lock:
            if not (slot.stop.is_set() or self._stopping.is_set()):
                slot.abandoned = False
                deadline = time.monotonic() + FIGURE_DEADLINE_SHARE * self.point_timeout
                slot.call = self.points.submit(figure_job_task, spec, deadline, progress, timeout=self.point_timeout)
            call = slot.call
        try:
            if call is not None:
                data = self.points.wait(call, self.point_timeout)
        except SolveTimeout:
            if not slot.abandoned:
                error = (f"timeout: the figure did not finish within {self.point_timeout:g} s "
                         "(TENSEGRITY_JOBS_POINT_TIMEOUT)")
        except Exception as exc:  # the figure's own failure: a row, and the job failed
            error = format_error(exc)
        finally:
            with self._point_lock:
                slot.call = None
        if slot.stop.is_set():
            return                      # cancelled, or another server holds the job now
        if error is not None:
            log.warning("job %s failed: %s", job_id, error)
            row("failed", error)
            self.store.release(job_id, self.id, status="failed", message=error[:2000], finished=True)
            return
        if data is None:                # abandoned by a shutdown
            self._stopped(job_id)
            return
        fmt = spec["format"]
        self.store.put_figure(job_id, FIGURE_MEDIA[fmt], data, self.id)
        self.store.add_point(job_id, last, {"index": last, "stage": f"stored: {fmt}, {len(data)} bytes",
                                            "error": None}, self.id)
        self.store.release(job_id, self.id, status="done", finished=True)
        log.info("job %s: figure done (%d bytes)", job_id, len(data))

    def _timed_row(self, slot: _Slot, header: Mapping[str, Any], pcols: list[str], rcols: list[str], i: int,
                   p: Mapping[str, Any]) -> dict[str, Any] | None:
        """One point on the points' thread under ``point_timeout`` (past it, the point is interrupted at its next
        bytecode, after the CasADi/IPOPT call in progress returns, and its row is the error ``timeout: ...``).
        ``None`` when the point was abandoned (:meth:`_abandon`: the job was cancelled, its lease lost, or the
        server stops); nothing is stored for it then, and a resumed job computes it again."""
        with self._point_lock:
            if slot.stop.is_set() or self._stopping.is_set():
                return None
            slot.abandoned = False
            slot.call = self.points.submit(solve_chunk, header, pcols, rcols, [(i, p)])
        try:
            return self.points.wait(slot.call, self.point_timeout)[0][1]
        except SolveTimeout:
            if slot.abandoned:
                return None
            log.warning("point %d of a job exceeded %g s (TENSEGRITY_JOBS_POINT_TIMEOUT)", i, self.point_timeout)
            return error_row(header, pcols, rcols, i, p, f"timeout: the point did not finish within "
                                                          f"{self.point_timeout:g} s (TENSEGRITY_JOBS_POINT_TIMEOUT)")
        finally:
            with self._point_lock:
                slot.call = None

    def _abandon(self, slot: _Slot) -> None:
        """Interrupt the point in progress in ``slot`` now (its job was cancelled, or its lease lost, or the
        server stops): the thread is free after the CasADi call in progress instead of after the point."""
        with self._point_lock:
            call = slot.call
            if call is None:
                return
            slot.abandoned = True
        self.points.cancel(call)

    def _heartbeat(self) -> None:
        """Renew the leases of the jobs held here; stop those cancelled or taken over elsewhere; purge."""
        interval = self.lease_seconds / 3
        while not self._stopping.wait(interval):
            with self._lock:
                held = [(s, s.job_id) for s in self._slots if s.job_id]
            for slot, job_id in held:
                try:
                    ok = self.store.renew(job_id, self.id, self.lease_seconds)
                except Exception as exc:  # database trouble: stop once the lease may have expired
                    ok = time.monotonic() - slot.renewed < self.lease_seconds * 0.9
                    log.warning("job %s: cannot renew the lease: %r", job_id, exc)
                else:
                    if ok:
                        slot.renewed = time.monotonic()
                if not ok:
                    with self._lock:        # the slot may have moved on to another job meanwhile
                        if slot.job_id != job_id or slot.stop.is_set():
                            continue
                        slot.stop.set()
                        self._abandon(slot)
                    log.warning("job %s: cancelled elsewhere or lease lost; this server stops running it", job_id)
            if self._ready and time.monotonic() - self._purged > 3600:
                try:
                    self._purge()
                except Exception as exc:
                    log.warning("cannot purge expired jobs: %r", exc)

    def _log_fault(self, msg: str, *args: Any) -> None:
        """Log a storage fault, at most once a minute (a failing store is retried often)."""
        if time.monotonic() - self._fault_logged > 60:
            self._fault_logged = time.monotonic()
            log.error(msg, *args)

    def _watch(self) -> None:
        """While the store fails, retry it every ``retry_seconds`` (:meth:`recover_store`)."""
        while not self._stopping.wait(self.retry_seconds):
            if self.store.health()["status"] != "ok":
                self.recover_store()

    def recover_store(self) -> bool:
        """One retry of a failing store: open it if it is not open, probe it, then put back to ``queued`` the
        jobs a storage fault cut off here and wake the runner threads. True when the store works."""
        try:
            self._open()
            self.store.probe()
            with self._lock:
                stranded = sorted(self._stranded)
            for job_id in stranded:
                self.store.release(job_id, self.id, status="queued",
                                   message="waiting for its next turn after a fault of the job store")
                with self._lock:
                    self._stranded.discard(job_id)
        except Exception as exc:
            self._log_fault("the job store %s still fails: %r", self.db_path, exc)
            return False
        log.warning("the job store %s works again", self.db_path)
        with self._wake:
            self._wake.notify_all()
        return True

    def _purge(self) -> int:
        self._purged = time.monotonic()
        if self.retention_days <= 0:
            return 0
        n = self.store.purge(time.time() - self.retention_days * 86400.0)
        if n:
            log.info("deleted %d finished job(s) older than %g days (TENSEGRITY_JOBS_RETENTION_DAYS)", n,
                     self.retention_days)
        return n


class _TooLarge(InvalidParameterError):
    code = "sweep_too_large"


class _TooManySegments(InvalidParameterError):
    code = "too_many_segments"


def _segment_counts(norm: Mapping[str, Any]) -> list[tuple[str, int]]:
    base = norm["manipulator"]
    out = [("manipulator.segments", len(base["segments"])) if "segments" in base else ("manipulator.n", int(base["n"]))]
    if "grid" in norm:
        out += [(f"grid.n[{i}]", int(n)) for i, n in enumerate(norm["grid"].get("n", []))]
    else:
        out += [(f"points[{i}].n", int(p["n"])) for i, p in enumerate(norm["points"]) if "n" in p]
    return out
