"""Persistent sweep jobs: a SQLite job store and the background runner that executes them.

Durability
----------
* Every job and every finished point live in one SQLite file (``TENSEGRITY_JOBS_DB``, default
  ``tensegrity_jobs.sqlite3`` in the working directory) in WAL mode. A point's row is written
  by the runner thread as soon as the sweep delivers it, in its own committed transaction, so
  killing the server (even SIGKILL) loses no finished point. ``TENSEGRITY_JOBS_SYNCHRONOUS``
  (``NORMAL`` by default) is SQLite's ``synchronous``: ``NORMAL`` survives a killed process,
  ``FULL`` also a power cut (an fsync per point).
* Points are keyed by ``(job, index)`` and inserted with ``INSERT OR IGNORE``: a point is stored
  once and never rewritten.
* At start the runner takes the jobs a previous process left ``running`` (or ``queued``) and
  resumes them: ``tensegrity_opt.sweep(spec, skip=<indices already stored>)``. With
  ``TENSEGRITY_JOBS_RESUME=false`` a job left ``running`` is marked ``interrupted`` instead
  (its points are kept). A graceful shutdown stops the running job between two points and
  puts it back to ``queued``, so the next start resumes it.
* One server process per database file (the runner assumes it owns the jobs it finds).

Execution
---------
One background thread runs one job at a time (FIFO), never on the event loop. With
``TENSEGRITY_JOBS_SCHEDULER`` unset the points are solved in that thread (the library caches its
CasADi solvers per thread); ``local`` or ``tcp://host:port`` sends them to Dask
(:func:`tensegrity_opt.sweep.sweep`), the rows still being stored by the runner thread.
``DELETE /v1/jobs/{id}`` cancels: a queued job at once, a running one after its current point
(Dask: chunk); finished points are kept.

The database file is created on the first submitted job, so a server that never gets a job
leaves no file behind.

Wiring (``service/main.py``)::

    runner = JobRunner(settings)          # reads TENSEGRITY_JOBS_* (service.config.Settings)
    app.state.jobs = runner
    app.include_router(routes.jobs.router)
    # lifespan: runner.start() after the pool starts; await asyncio.to_thread(runner.stop) at exit

Until then :func:`create_app_with_jobs` (``uvicorn --factory service.jobs:create_app_with_jobs``)
builds the service's app with the jobs API attached.
"""

from __future__ import annotations

import json
import logging
import os
import sqlite3
import threading
import time
import uuid
from collections.abc import AsyncIterator, Iterable, Mapping
from contextlib import asynccontextmanager
from datetime import UTC, datetime
from pathlib import Path
from typing import Any


from tensegrity_opt.errors import InvalidParameterError

from .config import Settings
from .responses import json_safe

# Names, not the module: ``tensegrity_opt.sweep`` may be re-exported as the function.
from tensegrity_opt.sweep import count_points, format_error, validate_spec  # noqa: I001
from tensegrity_opt.sweep import columns as sweep_columns
from tensegrity_opt.sweep import sweep as run_sweep

log = logging.getLogger("service.jobs")

__all__ = ["JobStore", "JobRunner", "JobNotFound", "JobFinished", "JobsUnavailable", "TERMINAL",
           "install", "create_app_with_jobs"]

STATUSES = ("queued", "running", "done", "failed", "cancelled", "interrupted")
TERMINAL = frozenset({"done", "failed", "cancelled", "interrupted"})


class JobNotFound(KeyError):
    """No job with this id."""


class JobFinished(Exception):
    """The job already ended (done, failed, cancelled or interrupted)."""

    def __init__(self, status: str) -> None:
        super().__init__(status)
        self.status = status


class JobsUnavailable(RuntimeError):
    """The job store cannot be used (its database could not be opened)."""


def iso(ts: float | None) -> str | None:
    if ts is None:
        return None
    return datetime.fromtimestamp(ts, UTC).isoformat(timespec="milliseconds").replace("+00:00", "Z")


def _dumps(x: Any) -> str:
    return json.dumps(json_safe(x), allow_nan=False, separators=(",", ":"))


# =========================================================================== store
_SCHEMA = """
CREATE TABLE IF NOT EXISTS jobs (
    id          TEXT PRIMARY KEY,
    status      TEXT NOT NULL,
    analysis    TEXT NOT NULL,
    total       INTEGER NOT NULL,
    spec        TEXT NOT NULL,
    columns     TEXT NOT NULL,
    created_at  REAL NOT NULL,
    started_at  REAL,
    finished_at REAL,
    message     TEXT,
    runs        INTEGER NOT NULL DEFAULT 0
);
CREATE INDEX IF NOT EXISTS jobs_status ON jobs (status);
CREATE TABLE IF NOT EXISTS points (
    job_id  TEXT NOT NULL,
    idx     INTEGER NOT NULL,
    failed  INTEGER NOT NULL,
    row     TEXT NOT NULL,
    PRIMARY KEY (job_id, idx)
) WITHOUT ROWID;
"""


class JobStore:
    """Jobs and their points in one SQLite file (WAL; one connection per thread, autocommit)."""

    def __init__(self, path: str | os.PathLike[str], synchronous: str = "NORMAL") -> None:
        self.path = Path(path)
        self.synchronous = synchronous
        self._local = threading.local()
        self._conns: list[sqlite3.Connection] = []
        self._lock = threading.Lock()
        self._closed = False

    # -------------------------------------------------------------- connections
    def exists(self) -> bool:
        return self.path.exists()

    def open(self) -> None:
        """Create the file and the tables when missing (idempotent)."""
        self._closed = False
        if self.path.parent and not self.path.parent.exists():
            self.path.parent.mkdir(parents=True, exist_ok=True)
        con = self._conn()
        mode = con.execute("PRAGMA journal_mode=WAL").fetchone()[0]
        if str(mode).lower() != "wal":  # pragma: no cover - e.g. a file system without shared memory
            log.warning("SQLite journal mode is %s, not WAL, for %s", mode, self.path)
        con.executescript(_SCHEMA)

    def _conn(self) -> sqlite3.Connection:
        con = getattr(self._local, "con", None)
        if con is None:
            if self._closed:
                raise JobsUnavailable("the job store is closed")
            con = sqlite3.connect(self.path, timeout=30.0, isolation_level=None, check_same_thread=False)
            con.execute("PRAGMA busy_timeout=30000")
            con.execute(f"PRAGMA synchronous={self.synchronous}")
            self._local.con = con
            with self._lock:
                self._conns.append(con)
        return con

    def close(self) -> None:
        with self._lock:
            self._closed = True
            conns, self._conns = self._conns, []
        for con in conns:
            try:
                con.close()
            except Exception:  # pragma: no cover
                pass
        self._local = threading.local()

    # -------------------------------------------------------------- jobs
    def create(self, spec: Mapping[str, Any], total: int, columns: list[str]) -> dict[str, Any]:
        job_id = uuid.uuid4().hex
        now = time.time()
        self._conn().execute(
            "INSERT INTO jobs (id, status, analysis, total, spec, columns, created_at) "
            "VALUES (?, 'queued', ?, ?, ?, ?, ?)",
            (job_id, spec["analysis"], total, _dumps(spec), _dumps(columns), now))
        return self.get(job_id)

    def get(self, job_id: str) -> dict[str, Any]:
        cur = self._conn().execute(
            "SELECT id, status, analysis, total, spec, columns, created_at, started_at, finished_at, message, runs "
            "FROM jobs WHERE id = ?", (job_id,))
        r = cur.fetchone()
        if r is None:
            raise JobNotFound(job_id)
        done, failed = self._conn().execute(
            "SELECT COUNT(*), COALESCE(SUM(failed), 0) FROM points WHERE job_id = ?", (job_id,)).fetchone()
        return {"id": r[0], "status": r[1], "analysis": r[2], "total": r[3], "spec": json.loads(r[4]),
                "columns": json.loads(r[5]), "created_at": r[6], "started_at": r[7], "finished_at": r[8],
                "message": r[9], "runs": r[10], "done": int(done), "failed": int(failed)}

    def list(self, limit: int = 50, status: str | None = None) -> list[dict[str, Any]]:
        q = "SELECT id FROM jobs"
        args: tuple[Any, ...] = ()
        if status:
            q += " WHERE status = ?"
            args = (status,)
        q += " ORDER BY created_at DESC, rowid DESC LIMIT ?"
        ids = [r[0] for r in self._conn().execute(q, (*args, int(limit)))]
        return [self.get(i) for i in ids]

    def next_job(self) -> dict[str, Any] | None:
        """The oldest job waiting to run (``running`` first: left by a previous process)."""
        r = self._conn().execute(
            "SELECT id FROM jobs WHERE status IN ('running', 'queued') "
            "ORDER BY status = 'running' DESC, created_at, rowid LIMIT 1").fetchone()
        return self.get(r[0]) if r else None

    def update(self, job_id: str, *, status: str, when: Iterable[str] | None = None, **fields: Any) -> bool:
        """Set ``status`` (and ``fields``); only while the job's status is in ``when``. True when updated."""
        sets = ["status = ?"] + [f"{k} = ?" for k in fields]
        args: list[Any] = [status, *fields.values(), job_id]
        q = f"UPDATE jobs SET {', '.join(sets)} WHERE id = ?"
        if when is not None:
            when = list(when)
            q += f" AND status IN ({', '.join('?' for _ in when)})"
            args += when
        return self._conn().execute(q, args).rowcount > 0

    def start_run(self, job_id: str) -> bool:
        """``queued``/``running`` -> ``running``, counting the run. False when the job was cancelled meanwhile."""
        now = time.time()
        return self._conn().execute(
            "UPDATE jobs SET status = 'running', runs = runs + 1, started_at = COALESCE(started_at, ?), message = "
            "CASE WHEN runs > 0 THEN 'resumed after a restart' ELSE NULL END "
            "WHERE id = ? AND status IN ('queued', 'running')", (now, job_id)).rowcount > 0

    def recover(self, resume: bool) -> int:
        """At start: jobs a previous process left ``running`` are resumed (or marked ``interrupted``)."""
        if resume:
            return 0  # next_job() takes them first
        return self._conn().execute(
            "UPDATE jobs SET status = 'interrupted', finished_at = ?, message = 'the server stopped while the job "
            "ran; its finished points are kept (resuming is off: TENSEGRITY_JOBS_RESUME=false)' "
            "WHERE status = 'running'", (time.time(),)).rowcount

    # -------------------------------------------------------------- points
    def add_point(self, job_id: str, index: int, row: Mapping[str, Any]) -> None:
        """Store one finished point (committed at once); a point already stored is kept as it is."""
        self._conn().execute("INSERT OR IGNORE INTO points (job_id, idx, failed, row) VALUES (?, ?, ?, ?)",
                             (job_id, int(index), 1 if row.get("error") else 0, _dumps(row)))

    def done_indices(self, job_id: str) -> set[int]:
        return {r[0] for r in self._conn().execute("SELECT idx FROM points WHERE job_id = ?", (job_id,))}

    def rows(self, job_id: str, offset: int = 0, limit: int | None = None) -> list[dict[str, Any]]:
        q = "SELECT row FROM points WHERE job_id = ? ORDER BY idx LIMIT ? OFFSET ?"
        return [json.loads(r[0]) for r in self._conn().execute(q, (job_id, -1 if limit is None else int(limit),
                                                                    int(offset)))]


# =========================================================================== runner
def _setting(settings: Any, name: str, fallback: Any) -> Any:
    value = getattr(settings, name, None) if settings is not None else None
    return fallback if value is None else value


class JobRunner:
    """Accepts jobs, stores them, and runs them one at a time in a background thread.

    ``JobRunner(settings)``: the service's :class:`service.config.Settings` (its ``jobs_*`` fields;
    ``max_segments`` limits the chains of a job); without it the settings are read from the
    environment. Keyword arguments win.
    """

    def __init__(self, settings: Any = None, *, db_path: str | os.PathLike[str] | None = None,
                 scheduler: str | None = None, resume: bool | None = None, max_points: int | None = None,
                 synchronous: str | None = None, chunk_size: int | None = None) -> None:
        self.config_error: str | None = None
        try:
            js = settings if settings is not None else Settings()
        except ValueError as exc:  # reported by start(); building the app (e.g. for OpenAPI) still works
            js = Settings.model_construct()
            self.config_error = f"invalid TENSEGRITY_JOBS_* or other TENSEGRITY_* setting: {exc}"
        self.db_path = Path(db_path if db_path is not None else _setting(settings, "jobs_db", js.jobs_db))
        self.scheduler = scheduler if scheduler is not None else _setting(settings, "jobs_scheduler", js.jobs_scheduler)
        if self.scheduler == "serial":
            self.scheduler = None
        self.resume = resume if resume is not None else bool(_setting(settings, "jobs_resume", js.jobs_resume))
        self.max_points = int(max_points or _setting(settings, "jobs_max_points", js.jobs_max_points))
        self.chunk_size = chunk_size or _setting(settings, "jobs_chunk_size", js.jobs_chunk_size)
        self.max_segments = _setting(settings, "max_segments", None)
        self.store = JobStore(self.db_path, synchronous or _setting(settings, "jobs_synchronous", js.jobs_synchronous))
        self.error: str | None = None
        self._ready = False
        self._lock = threading.Lock()          # current job / cancel event / opening the store
        self._wake = threading.Event()
        self._stopping = threading.Event()
        self._thread: threading.Thread | None = None
        self._current: str | None = None
        self._cancel = threading.Event()
        self._idle = threading.Event()
        self._idle.set()

    # -------------------------------------------------------------- lifecycle
    def start(self) -> JobRunner:
        """Open an existing database (resuming its unfinished jobs) and start the runner thread.

        Raises ``RuntimeError`` for an invalid ``TENSEGRITY_JOBS_*`` setting. A database that cannot
        be opened does not stop the service: the jobs API answers 503 ``jobs_unavailable``.
        """
        if self._thread is not None:
            return self
        if self.config_error:
            raise RuntimeError(self.config_error)
        self._stopping.clear()
        if self.store.exists():
            try:
                self._open()
                n = self.store.recover(self.resume)
                if n:
                    log.warning("%d job(s) left running by a previous process marked interrupted", n)
            except Exception as exc:  # the rest of the service keeps working
                self.error = f"cannot open the job store {self.db_path}: {exc}"
                log.error(self.error)
        self._thread = threading.Thread(target=self._loop, name="sweep-jobs", daemon=True)
        self._thread.start()
        return self

    def stop(self, timeout: float = 30.0) -> None:
        """Stop after the current point (the job goes back to ``queued``); close the database."""
        self._stopping.set()
        self._wake.set()
        t = self._thread
        if t is not None:
            t.join(timeout)
            if t.is_alive():  # pragma: no cover - a point longer than the timeout
                log.warning("the job runner did not stop within %g s", timeout)
                return
        self._thread = None
        with self._lock:
            self._ready = False
        self.store.close()

    def _open(self) -> None:
        with self._lock:
            if not self._ready:
                self.store.open()
                self._ready = True

    def _store(self) -> JobStore:
        if self.error:
            raise JobsUnavailable(self.error)
        if not self._ready:
            if not self.store.exists():
                raise JobNotFound("")
            self._open()
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
        return norm, total, sweep_columns(norm)

    def submit(self, spec: Any) -> dict[str, Any]:
        """Validate and store a new ``queued`` job; the runner thread picks it up."""
        if self.error:
            raise JobsUnavailable(self.error)
        norm, total, cols = self.validate(spec)
        try:
            self._open()
        except Exception as exc:
            self.error = f"cannot open the job store {self.db_path}: {exc}"
            log.error(self.error)
            raise JobsUnavailable(self.error) from exc
        job = self.store.create(norm, total, cols)
        self._wake.set()
        return job

    def get(self, job_id: str) -> dict[str, Any]:
        try:
            return self._store().get(job_id)
        except JobNotFound:
            raise JobNotFound(job_id) from None

    def rows(self, job_id: str, offset: int = 0, limit: int | None = None) -> list[dict[str, Any]]:
        return self._store().rows(job_id, offset, limit)

    def list(self, limit: int = 50, status: str | None = None) -> list[dict[str, Any]]:
        if not self._ready and not self.store.exists() and not self.error:
            return []
        return self._store().list(limit, status)

    def cancel(self, job_id: str) -> dict[str, Any]:
        """Cancel a queued or running job (its finished points are kept). ``JobFinished`` when it ended."""
        store = self._store()
        with self._lock:
            updated = store.update(job_id, status="cancelled", when=("queued", "running"), finished_at=time.time(),
                                   message="cancelled by a request; finished points are kept")
            if updated and self._current == job_id:
                self._cancel.set()
        job = self.get(job_id)
        if not updated and job["status"] != "cancelled":
            raise JobFinished(job["status"])
        return job

    def wait_idle(self, timeout: float = 10.0) -> bool:
        """True once no job is running (tests)."""
        return self._idle.wait(timeout)

    # -------------------------------------------------------------- thread
    def _loop(self) -> None:
        while not self._stopping.is_set():
            self._wake.clear()
            job = None
            if self._ready and not self.error:
                try:
                    job = self.store.next_job()
                except Exception:  # pragma: no cover - database trouble: retry later
                    log.exception("cannot read the job queue")
            if job is None:
                self._wake.wait(1.0)
                continue
            self._idle.clear()
            try:
                self._run(job)
            except Exception:  # pragma: no cover - never let the runner die
                log.exception("job %s: unexpected runner error", job["id"])
            finally:
                with self._lock:
                    self._current = None
                self._idle.set()

    def _run(self, job: dict[str, Any]) -> None:
        job_id = job["id"]
        with self._lock:
            self._current = job_id
            self._cancel = threading.Event()
            cancel = self._cancel
        if not self.store.start_run(job_id):
            return
        done = self.store.done_indices(job_id)
        log.info("job %s: running (%d of %d points already stored)", job_id, len(done), job["total"])

        def store_row(index: int, row: dict[str, Any]) -> None:
            self.store.add_point(job_id, index, row)

        try:
            result = run_sweep(job["spec"], scheduler=self.scheduler, on_result=store_row, skip=done,
                                     should_stop=lambda: cancel.is_set() or self._stopping.is_set(),
                                     chunk_size=self.chunk_size)
        except Exception as exc:
            msg = format_error(exc) if not isinstance(exc, (OSError, TimeoutError)) else \
                f"scheduler_unreachable: {type(exc).__name__}: {exc}"
            log.warning("job %s failed: %s", job_id, msg)
            self._finish(job_id, "failed", msg[:2000])
            return
        stored = len(self.store.done_indices(job_id))
        if cancel.is_set():
            return  # the DELETE already set "cancelled"
        if result.cancelled and stored < job["total"]:
            if self.resume:
                self.store.update(job_id, status="queued", when=("running",),
                                  message="stopped by a server shutdown; resumes when the server starts again")
            else:
                self._finish(job_id, "interrupted", "stopped by a server shutdown; finished points are kept")
            return
        if stored < job["total"]:  # pragma: no cover - defensive
            self._finish(job_id, "failed", f"internal_error: {stored} of {job['total']} points stored")
            return
        self._finish(job_id, "done", None)
        log.info("job %s: done (%d points, %.1f s)", job_id, job["total"], result.elapsed)

    def _finish(self, job_id: str, status: str, message: str | None) -> None:
        self.store.update(job_id, status=status, when=("running",), finished_at=time.time(), message=message)


class _TooLarge(InvalidParameterError):
    code = "sweep_too_large"


class _TooManySegments(InvalidParameterError):
    code = "too_many_segments"


def _segment_counts(norm: Mapping[str, Any]) -> list[tuple[str, int]]:
    out = [("manipulator.n", int(norm["manipulator"]["n"]))]
    if "grid" in norm:
        out += [(f"grid.n[{i}]", int(n)) for i, n in enumerate(norm["grid"].get("n", []))]
    else:
        out += [(f"points[{i}].n", int(p["n"])) for i, p in enumerate(norm["points"]) if "n" in p]
    return out


def summary(job: Mapping[str, Any]) -> dict[str, Any]:
    """The API's ``JobSummary`` of a stored job."""
    total = int(job["total"])
    return {"id": job["id"], "status": job["status"], "analysis": job["analysis"], "total": total,
            "done": job["done"], "failed": job["failed"], "progress": round(job["done"] / total, 6) if total else 1.0,
            "runs": job["runs"], "created_at": iso(job["created_at"]), "started_at": iso(job["started_at"]),
            "finished_at": iso(job["finished_at"]), "message": job["message"]}


# =========================================================================== app wiring
def install(app: Any, settings: Any = None, **runner_kwargs: Any) -> JobRunner:
    """Attach the jobs API to a service app built by ``service.main.create_app``.

    Adds the router, ``app.state.jobs`` and wraps the app's lifespan so that the runner starts
    after the app's own start-up and stops before its shutdown. Does nothing when the app has
    jobs already (``service/main.py`` wires them).
    """
    existing = getattr(app.state, "jobs", None)
    if existing is not None:
        return existing
    from .routes import jobs as jobs_routes

    runner = JobRunner(settings if settings is not None else getattr(app.state, "settings", None), **runner_kwargs)
    app.state.jobs = runner
    app.include_router(jobs_routes.router)
    inner = app.router.lifespan_context

    @asynccontextmanager
    async def lifespan(a: Any) -> AsyncIterator[Any]:
        import asyncio

        async with inner(a) as state:
            runner.start()
            try:
                yield state
            finally:
                await asyncio.to_thread(runner.stop)

    app.router.lifespan_context = lifespan
    return runner


def create_app_with_jobs() -> Any:
    """The service app (settings from the environment) with the jobs API; a uvicorn ``--factory``."""
    from .main import create_app

    settings = Settings()
    app = create_app(settings)
    install(app, settings)
    return app
