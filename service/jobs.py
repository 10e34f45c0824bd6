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
  resumes them: only the indices not stored yet are solved. With ``TENSEGRITY_JOBS_RESUME=false``
  a job left ``running`` (lease expired) is marked ``interrupted`` instead (its points are kept).
  A graceful shutdown stops the running jobs between two points and puts them back to
  ``queued``, so the next start resumes them.

Execution and scheduling
------------------------
``TENSEGRITY_JOBS_MAX_RUNNING`` runner threads (default 2), never the event loop, each run one
job at a time. Fair scheduling: a thread that has run its job for ``TENSEGRITY_JOBS_SLICE_SECONDS``
checks, between two points, whether another job waits; if so its job goes back to ``queued`` and
the thread claims the job that waited longest (``turn_at``: its creation, then the end of its last
turn), i.e. round-robin in order of arrival. A job alone keeps its thread.

With ``TENSEGRITY_JOBS_SCHEDULER`` unset the points are solved in the runner thread (the library
caches its CasADi solvers per thread), each under ``TENSEGRITY_JOBS_POINT_TIMEOUT``: a watchdog
thread raises :class:`PointTimeout` in a runner thread whose point is late
(``PyThreadState_SetAsyncExc``, the mechanism of :mod:`service.pool`); it lands at the thread's next
bytecode, i.e. once the CasADi/IPOPT call in progress returns, and the point's row becomes the
error ``timeout: ...``; the job goes on. In-process rather than a killable subprocess per point: no
process start-up and solver rebuild per point, rows identical to ``tensegrity_opt.applications.sweeps``'s; the
price is that one native call longer than the limit runs to its end (the library bounds each IPOPT
call itself: ``ipopt.max_wall_time`` 20 s, 60 s for a design NLP, so a late point ends at most that
long after its deadline). ``local`` or ``tcp://host:port``
sends the points to Dask (:func:`tensegrity_opt.applications.sweeps.sweep`; no per-point limit there).

Leases: several servers on one file
-----------------------------------
Each runner (one per server process, ``JobRunner.id``) claims a job with one atomic ``UPDATE ...
WHERE`` (``queued``, or ``running`` with an expired lease) ``RETURNING id``, taking a lease of
``TENSEGRITY_JOBS_LEASE_SECONDS``. A heartbeat thread renews it every third of that; when the
renewal finds the job no longer ``running`` under this runner's lease (cancelled through another
server, deleted, or taken over after this server stalled), the runner stops the job after the
current point. Rows are only stored while the runner holds the lease, and a point is stored once
(``INSERT OR IGNORE``). A job whose server died is taken over when its lease expires, or at once
by a runner on the same host (the owner is ``host:pid-token``) that finds that pid gone, e.g. the
same server restarted after a SIGKILL.

Owners, deletion, retention
---------------------------
With API keys configured a job belongs to the key that submitted it (the store keeps
:func:`owner_hash`, the SHA-256 of the key); every other key sees 404 for it. Jobs stored while
auth was off have no owner and are not visible to any key. ``POST /v1/jobs/{id}/cancel`` cancels a
queued or running job (a queued one at once; a running one at once too: its point in progress is
abandoned, like a late point, once the CasADi call in progress returns, and stores nothing; finished
points are kept); ``DELETE`` removes a job with its rows (cancelling it first). Finished jobs older than ``TENSEGRITY_JOBS_RETENTION_DAYS``
(0: never) are deleted at start-up and hourly.

Storage faults
--------------
Every SQLite or OS error of an API call, and a database file deleted or replaced while the server
runs (its device and inode are checked on every call), raise :class:`JobsUnavailable`: 503
``jobs_unavailable``. A deleted file is not recreated (that would silently start an empty store
beside servers still writing into the old one).

The database file is created on the first submitted job, so a server that never gets a job
leaves no file behind.

Wiring: :func:`service.main.create_app` builds the runner (``JobRunner(settings)``, reading
``TENSEGRITY_JOBS_*``), keeps it in ``app.state.jobs``, includes ``service.routes.jobs`` and, in its
lifespan, starts the runner after the solver pool and stops it at shutdown. This module imports
neither of them.
"""

from __future__ import annotations

import functools
import hashlib
import json
import logging
import os
import socket
import sqlite3
import threading
import time
import uuid
from collections.abc import Callable, Iterable, Iterator, Mapping
from contextlib import contextmanager
from datetime import UTC, datetime
from pathlib import Path
from typing import Any


from tensegrity_opt.errors import InvalidParameterError

from .config import Settings
from .pool import _set_async_exc
from .responses import json_safe

# Names, not the module: ``tensegrity_opt.applications.sweeps`` may be re-exported as the function.
from tensegrity_opt.applications.sweeps import count_points, format_error, validate_spec  # noqa: I001
from tensegrity_opt.applications.sweeps import columns as sweep_columns
from tensegrity_opt.applications.sweeps import error_row, solve_chunk
from tensegrity_opt.applications.sweeps import plan as plan_sweep
from tensegrity_opt.applications.sweeps import sweep as run_sweep

log = logging.getLogger("service.jobs")

__all__ = ["JobStore", "JobRunner", "JobNotFound", "JobFinished", "JobsUnavailable", "PointTimeout", "TERMINAL",
           "owner_hash"]

TERMINAL = frozenset({"done", "failed", "cancelled", "interrupted"})


class JobNotFound(KeyError):
    """No job with this id."""


class JobFinished(Exception):
    """The job already ended (done, failed, cancelled or interrupted)."""

    def __init__(self, status: str) -> None:
        super().__init__(status)
        self.status = status


class JobsUnavailable(RuntimeError):
    """The job store cannot be used: its file cannot be opened, is damaged, read-only, or was deleted or
    replaced while the server runs (503 ``jobs_unavailable``, mapped in :mod:`service.errors`)."""


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

#: Columns added after the first release (``ALTER TABLE`` on an older file).
_ADDED_COLUMNS = (
    ("owner", "TEXT"),            # sha256 of the API key that created the job (NULL: auth was off)
    ("lease_owner", "TEXT"),      # the runner (one per server process) that holds or last held the job
    ("lease_until", "REAL"),      # epoch seconds; the lease is free once this is past (or NULL)
    ("turn_at", "REAL"),          # round-robin key: created_at, then the end of the job's last slice
)

_CLAIMABLE = "(status = 'queued' OR (status = 'running' AND COALESCE(lease_until, 0) < :now))"


def _connect(path: Path) -> sqlite3.Connection:
    """A connection to the job store (module level: the tests open a read-only one in its place)."""
    return sqlite3.connect(path, timeout=30.0, isolation_level=None, check_same_thread=False)


def owner_hash(key: str) -> str:
    """What the store keeps of an API key: its SHA-256 (hex), never the key."""
    return hashlib.sha256(key.encode("utf-8", "surrogateescape")).hexdigest()


class JobStore:
    """Jobs and their points in one SQLite file (WAL; one connection per thread, autocommit).

    ``owner`` arguments: ``None`` sees every job (auth off); a hash sees only the jobs it created.
    """

    def __init__(self, path: str | os.PathLike[str], synchronous: str = "NORMAL") -> None:
        self.path = Path(path)
        self.synchronous = synchronous
        self._local = threading.local()
        self._conns: list[sqlite3.Connection] = []
        self._lock = threading.Lock()
        self._closed = False
        self._identity: tuple[int, int] | None = None

    # -------------------------------------------------------------- connections
    def exists(self) -> bool:
        return self.path.exists()

    def open(self) -> None:
        """Create the file and the tables when missing (idempotent); remember the file's identity."""
        self._closed = False
        if self.path.parent and not self.path.parent.exists():
            self.path.parent.mkdir(parents=True, exist_ok=True)
        con = self._conn()
        mode = con.execute("PRAGMA journal_mode=WAL").fetchone()[0]
        if str(mode).lower() != "wal":  # pragma: no cover - e.g. a file system without shared memory
            log.warning("SQLite journal mode is %s, not WAL, for %s", mode, self.path)
        con.executescript(_SCHEMA)
        have = {r[1] for r in con.execute("PRAGMA table_info(jobs)")}
        for name, kind in _ADDED_COLUMNS:
            if name not in have:
                try:
                    con.execute(f"ALTER TABLE jobs ADD COLUMN {name} {kind}")
                except sqlite3.OperationalError as exc:  # another server added it meanwhile
                    if "duplicate column" not in str(exc):
                        raise
        con.execute("CREATE INDEX IF NOT EXISTS jobs_owner ON jobs (owner)")
        st = os.stat(self.path)
        self._identity = (st.st_dev, st.st_ino)

    def check_file(self) -> None:
        """``JobsUnavailable`` when the file was deleted or replaced since :meth:`open` (the open
        connections would otherwise go on writing into a file nobody can see any more)."""
        if self._identity is None:
            return
        try:
            st = os.stat(self.path)
        except FileNotFoundError:
            raise JobsUnavailable(f"the job store {self.path} was deleted while the server runs; jobs are "
                                  f"unavailable until the server is restarted") from None
        except OSError as exc:
            raise JobsUnavailable(f"the job store {self.path} cannot be used: {exc}") from None
        if (st.st_dev, st.st_ino) != self._identity:
            raise JobsUnavailable(f"the job store {self.path} was replaced by another file while the server runs; "
                                  f"jobs are unavailable until the server is restarted")

    def _conn(self) -> sqlite3.Connection:
        con = getattr(self._local, "con", None)
        if con is None:
            if self._closed:
                raise JobsUnavailable("the job store is closed")
            con = _connect(self.path)
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

    @contextmanager
    def _tx(self) -> Iterator[sqlite3.Connection]:
        """A write transaction (``BEGIN IMMEDIATE`` ... ``COMMIT``, rolled back on error)."""
        con = self._conn()
        con.execute("BEGIN IMMEDIATE")
        try:
            yield con
        except BaseException:
            con.execute("ROLLBACK")
            raise
        con.execute("COMMIT")

    # -------------------------------------------------------------- jobs
    def create(self, spec: Mapping[str, Any], total: int, columns: list[str],
               owner: str | None = None) -> dict[str, Any]:
        job_id = uuid.uuid4().hex
        now = time.time()
        self._conn().execute(
            "INSERT INTO jobs (id, status, analysis, total, spec, columns, created_at, owner, turn_at) "
            "VALUES (?, 'queued', ?, ?, ?, ?, ?, ?, ?)",
            (job_id, spec["analysis"], total, _dumps(spec), _dumps(columns), now, owner, now))
        return self.get(job_id)

    def get(self, job_id: str, owner: str | None = None) -> dict[str, Any]:
        q = ("SELECT id, status, analysis, total, spec, columns, created_at, started_at, finished_at, message, runs, "
             "lease_owner FROM jobs WHERE id = ?")
        args: tuple[Any, ...] = (job_id,)
        if owner is not None:
            q += " AND owner = ?"
            args += (owner,)
        r = self._conn().execute(q, args).fetchone()
        if r is None:
            raise JobNotFound(job_id)
        done, failed = self._conn().execute(
            "SELECT COUNT(*), COALESCE(SUM(failed), 0) FROM points WHERE job_id = ?", (job_id,)).fetchone()
        return {"id": r[0], "status": r[1], "analysis": r[2], "total": r[3], "spec": json.loads(r[4]),
                "columns": json.loads(r[5]), "created_at": r[6], "started_at": r[7], "finished_at": r[8],
                "message": r[9], "runs": r[10], "lease_owner": r[11], "done": int(done), "failed": int(failed)}

    def list(self, limit: int = 50, status: str | None = None, owner: str | None = None) -> list[dict[str, Any]]:
        q = "SELECT id FROM jobs WHERE 1"
        args: tuple[Any, ...] = ()
        if status:
            q += " AND status = ?"
            args += (status,)
        if owner is not None:
            q += " AND owner = ?"
            args += (owner,)
        q += " ORDER BY created_at DESC, rowid DESC LIMIT ?"
        ids = [r[0] for r in self._conn().execute(q, (*args, int(limit)))]
        out = []
        for i in ids:
            try:
                out.append(self.get(i))
            except JobNotFound:  # deleted meanwhile
                pass
        return out

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
        """``queued``/``running`` -> ``running`` without a lease, counting the run (what a process that was
        killed before it took leases leaves behind; the runner itself uses :meth:`claim`)."""
        now = time.time()
        return self._conn().execute(
            "UPDATE jobs SET status = 'running', runs = runs + 1, started_at = COALESCE(started_at, ?), message = "
            "CASE WHEN runs > 0 THEN 'resumed after a restart' ELSE NULL END "
            "WHERE id = ? AND status IN ('queued', 'running')", (now, job_id)).rowcount > 0

    def claim(self, runner_id: str, lease: float, exclude: Iterable[str] = ()) -> dict[str, Any] | None:
        """Atomically take the next job: ``queued``, or ``running`` with an expired lease (its server died).

        The order is round-robin: the job that waited longest for its turn (``turn_at``: its creation,
        then the end of its last slice). A job taken over from another runner counts one more run.
        """
        now = time.time()
        ex = list(exclude)
        params: dict[str, Any] = {"me": runner_id, "now": now, "until": now + lease}
        params.update({f"x{k}": v for k, v in enumerate(ex)})
        not_in = f" AND id NOT IN ({', '.join(f':x{k}' for k in range(len(ex)))})" if ex else ""
        r = self._conn().execute(
            "UPDATE jobs SET status = 'running', lease_owner = :me, lease_until = :until, "
            "runs = runs + (lease_owner IS NOT :me), started_at = COALESCE(started_at, :now), "
            "message = CASE WHEN runs > 0 AND lease_owner IS NOT :me THEN 'resumed after a restart' ELSE NULL END "
            f"WHERE id = (SELECT id FROM jobs WHERE {_CLAIMABLE}{not_in} "
            "ORDER BY COALESCE(turn_at, created_at), rowid LIMIT 1) "
            f"AND {_CLAIMABLE} RETURNING id", params).fetchone()
        return self.get(r[0]) if r else None

    def renew(self, job_id: str, runner_id: str, lease: float) -> bool:
        """Extend the lease; False when the job is no longer ``running`` under this runner's lease."""
        return self._conn().execute(
            "UPDATE jobs SET lease_until = ? WHERE id = ? AND lease_owner = ? AND status = 'running'",
            (time.time() + lease, job_id, runner_id)).rowcount > 0

    def waiting(self, exclude: Iterable[str] = ()) -> bool:
        """Is any job waiting for a runner?"""
        ex = list(exclude)
        q = f"SELECT 1 FROM jobs WHERE {_CLAIMABLE}"
        params: dict[str, Any] = {"now": time.time()}
        if ex:
            q += f" AND id NOT IN ({', '.join(f':x{k}' for k in range(len(ex)))})"
            params.update({f"x{k}": v for k, v in enumerate(ex)})
        return self._conn().execute(q + " LIMIT 1", params).fetchone() is not None

    def release(self, job_id: str, runner_id: str, *, status: str = "queued", message: str | None = None,
                finished: bool = False) -> bool:
        """End this runner's lease on a running job: back to ``queued`` (its turn is over), or finished."""
        now = time.time()
        return self._conn().execute(
            "UPDATE jobs SET status = ?, message = ?, lease_until = NULL, turn_at = ?, "
            "finished_at = CASE WHEN ? THEN ? ELSE finished_at END "
            "WHERE id = ? AND lease_owner = ? AND status = 'running'",
            (status, message, now, 1 if finished else 0, now, job_id, runner_id)).rowcount > 0

    def recover(self, resume: bool) -> int:
        """Jobs left ``running`` by a server that died (lease expired, or none): resumed by :meth:`claim`,
        or, with resuming off, marked ``interrupted``."""
        if resume:
            return 0
        now = time.time()
        return self._conn().execute(
            "UPDATE jobs SET status = 'interrupted', finished_at = :now, lease_until = NULL, message = 'the server "
            "stopped while the job ran; its finished points are kept (resuming is off: TENSEGRITY_JOBS_RESUME=false)' "
            "WHERE status = 'running' AND COALESCE(lease_until, 0) < :now", {"now": now}).rowcount

    def free_dead_leases(self, host: str) -> int:
        """Free the leases held by runners of this host whose process is gone (a killed server restarted
        on the same machine resumes its jobs at once instead of after the lease). A live process with a
        reused pid only delays the take-over until the lease expires."""
        now = time.time()
        dead = []
        for job_id, owner in self._conn().execute(
                "SELECT id, lease_owner FROM jobs WHERE status = 'running' AND lease_until >= ?", (now,)):
            pid = _lease_pid(owner, host)
            if pid is not None and not _alive(pid):
                dead.append((job_id, owner))
        n = 0
        for job_id, owner in dead:
            n += self._conn().execute("UPDATE jobs SET lease_until = NULL WHERE id = ? AND lease_owner = ? AND "
                                      "status = 'running'", (job_id, owner)).rowcount
        return n

    def delete(self, job_id: str, owner: str | None = None) -> bool:
        """Remove a finished job and its rows. False when there is no such finished job."""
        with self._tx() as con:
            q = f"DELETE FROM jobs WHERE id = ? AND status IN ({', '.join(repr(t) for t in sorted(TERMINAL))})"
            args: tuple[Any, ...] = (job_id,)
            if owner is not None:
                q += " AND owner = ?"
                args += (owner,)
            if con.execute(q, args).rowcount == 0:
                return False
            con.execute("DELETE FROM points WHERE job_id = ?", (job_id,))
            return True

    def purge(self, older_than: float) -> int:
        """Delete the finished jobs (and their rows) that finished before ``older_than`` (epoch seconds)."""
        terminal = ", ".join(repr(t) for t in sorted(TERMINAL))
        with self._tx() as con:
            ids = [r[0] for r in con.execute(
                f"SELECT id FROM jobs WHERE status IN ({terminal}) AND COALESCE(finished_at, created_at) < ?",
                (older_than,))]
            for i in ids:
                con.execute("DELETE FROM points WHERE job_id = ?", (i,))
                con.execute("DELETE FROM jobs WHERE id = ?", (i,))
        return len(ids)

    # -------------------------------------------------------------- points
    def add_point(self, job_id: str, index: int, row: Mapping[str, Any], runner_id: str | None = None) -> bool:
        """Store one finished point (committed at once); a point already stored is kept as it is.

        With ``runner_id`` the row is stored only while that runner holds the job's lease (a runner
        that lost it, or a job cancelled or deleted meanwhile, stores nothing). True when stored.
        """
        args = (job_id, int(index), 1 if row.get("error") else 0, _dumps(row))
        if runner_id is None:
            return self._conn().execute("INSERT OR IGNORE INTO points (job_id, idx, failed, row) VALUES (?, ?, ?, ?)",
                                        args).rowcount > 0
        return self._conn().execute(
            "INSERT OR IGNORE INTO points (job_id, idx, failed, row) SELECT ?, ?, ?, ? WHERE EXISTS "
            "(SELECT 1 FROM jobs WHERE id = ? AND status = 'running' AND lease_owner = ?)",
            (*args, job_id, runner_id)).rowcount > 0

    def done_indices(self, job_id: str) -> set[int]:
        return {r[0] for r in self._conn().execute("SELECT idx FROM points WHERE job_id = ?", (job_id,))}

    def count(self, job_id: str) -> int:
        return int(self._conn().execute("SELECT COUNT(*) FROM points WHERE job_id = ?", (job_id,)).fetchone()[0])

    def rows(self, job_id: str, offset: int = 0, limit: int | None = None) -> list[dict[str, Any]]:
        q = "SELECT row FROM points WHERE job_id = ? ORDER BY idx LIMIT ? OFFSET ?"
        return [json.loads(r[0]) for r in self._conn().execute(q, (job_id, -1 if limit is None else int(limit),
                                                                    int(offset)))]

    def row_batches(self, job_id: str, offset: int = 0, limit: int | None = None,
                    batch: int = 1000) -> Iterator[list[dict[str, Any]]]:
        """The rows from ``offset`` (at most ``limit``) in batches of ``batch``, by index (keyset paging:
        each batch is one short query, so a long download holds no transaction open)."""
        left = -1 if limit is None else int(limit)
        first = self._conn().execute("SELECT idx FROM points WHERE job_id = ? ORDER BY idx LIMIT 1 OFFSET ?",
                                     (job_id, int(offset))).fetchone()
        if first is None or left == 0:
            return
        last, op = first[0], ">="
        while left != 0:
            n = batch if left < 0 else min(batch, left)
            got = self._conn().execute(f"SELECT idx, row FROM points WHERE job_id = ? AND idx {op} ? ORDER BY idx "
                                       "LIMIT ?", (job_id, last, n)).fetchall()
            if not got:
                return
            yield [json.loads(r[1]) for r in got]
            last, op = got[-1][0], ">"
            if left > 0:
                left -= len(got)
            if len(got) < n:
                return


# =========================================================================== runner
def _lease_pid(owner: str | None, host: str) -> int | None:
    """The pid in a lease owner ``host:pid-token`` when it is of ``host``."""
    if not owner or ":" not in owner:
        return None
    h, _, rest = owner.rpartition(":")
    if h != host:
        return None
    try:
        return int(rest.split("-", 1)[0])
    except ValueError:
        return None


def _alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:            # exists, not ours
        return True
    return True


def _setting(settings: Any, name: str, fallback: Any) -> Any:
    value = getattr(settings, name, None) if settings is not None else None
    return fallback if value is None else value


#: Seconds between repeats of a sent :class:`PointTimeout` while the point still runs.
REFIRE_SECONDS = 0.25


class PointTimeout(BaseException):
    """Raised asynchronously in a runner thread whose point exceeded ``TENSEGRITY_JOBS_POINT_TIMEOUT``
    (``BaseException``, as :class:`service.pool.SolveCancelled`, so the library's handlers let it through)."""


class _Slot:
    """One runner thread: the job it holds and the watchdog's view of its current point."""

    def __init__(self, k: int) -> None:
        self.k = k
        self.job_id: str | None = None
        self.stop = threading.Event()     # the job was cancelled, or the lease was lost
        self.renewed = 0.0                # monotonic time of the last successful renewal
        self.thread_id = 0
        self.deadline = 0.0
        self.armed = False
        self.fired = False
        self.fired_at = 0.0               # monotonic time the exception was last sent
        self.abandoned = False            # fired by _abandon, not by the deadline


def _storage_guard(fn: Callable[..., Any]) -> Callable[..., Any]:
    """Every storage fault of an API call becomes :class:`JobsUnavailable` (503 ``jobs_unavailable``)."""

    @functools.wraps(fn)
    def wrapper(self: JobRunner, *args: Any, **kwargs: Any) -> Any:
        try:
            return fn(self, *args, **kwargs)
        except (sqlite3.Error, OSError) as exc:
            raise JobsUnavailable(f"the job store {self.db_path} cannot be used: {type(exc).__name__}: {exc}") \
                from exc

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
                 retention_days: float | None = None, lease_seconds: float | None = None) -> None:
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
        self.results_max_limit = int(_setting(settings, "jobs_results_max_limit", js.jobs_results_max_limit))
        self.max_segments = _setting(settings, "max_segments", None)
        self.homotopy_max_segments = _setting(settings, "homotopy_max_segments", None)
        self.store = JobStore(self.db_path, synchronous or _setting(settings, "jobs_synchronous", js.jobs_synchronous))
        #: This runner's identity in the leases (one per server process).
        self.host = socket.gethostname()
        self.id = f"{self.host}:{os.getpid()}-{uuid.uuid4().hex[:12]}"
        self.error: str | None = None
        self.points_computed = 0          # points this runner solved (tests, statistics)
        self._ready = False
        self._lock = threading.Lock()          # slots / opening the store
        self._wake = threading.Condition(threading.Lock())
        self._stopping = threading.Event()
        self._threads: list[threading.Thread] = []
        self._slots = [_Slot(k) for k in range(self.max_running)]
        # the point watchdog's; ``_watch_lock`` is its lock, taken directly (a C-level ``with``) where a
        # PointTimeout may arrive: Condition.__enter__ is Python code, between whose acquire and return an
        # asynchronous exception would leave the lock held
        self._watch_lock = threading.Lock()
        self._watch = threading.Condition(self._watch_lock)
        self._purged = 0.0
        self._fault_logged = -1e9

    # -------------------------------------------------------------- lifecycle
    def start(self) -> JobRunner:
        """Open an existing database (purging expired jobs, resuming unfinished ones) and start the
        runner threads, the lease heartbeat and the point watchdog.

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
                self.store.free_dead_leases(self.host)
                n = self.store.recover(self.resume)
                if n:
                    log.warning("%d job(s) left running by a previous process marked interrupted", n)
                self._purge()
            except Exception as exc:  # the rest of the service keeps working
                self.error = f"cannot open the job store {self.db_path}: {exc}"
                log.error(self.error)
        targets = [(f"sweep-jobs-{s.k}", functools.partial(self._loop, s)) for s in self._slots]
        targets += [("sweep-jobs-lease", self._heartbeat), ("sweep-jobs-watchdog", self._watchdog)]
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
        with self._watch:
            self._watch.notify_all()
        deadline = time.monotonic() + timeout
        for t in self._threads:
            t.join(max(0.0, deadline - time.monotonic()))
            if t.is_alive():  # pragma: no cover - a point longer than the timeout
                log.warning("the job runner did not stop within %g s", timeout)
                return
        self._threads = []
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
        if self.error:
            raise JobsUnavailable(self.error)
        norm, total, cols = self.validate(spec)
        try:
            self._open()
        except Exception as exc:
            self.error = f"cannot open the job store {self.db_path}: {exc}"
            log.error(self.error)
            raise JobsUnavailable(self.error) from exc
        self.store.check_file()
        job = self.store.create(norm, total, cols, owner)
        with self._wake:
            self._wake.notify()
        return job

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
                raise JobsUnavailable(f"the job store {self.db_path} cannot be used: {exc}") from exc
            yield b

    @_storage_guard
    def list(self, limit: int = 50, status: str | None = None, owner: str | None = None) -> list[dict[str, Any]]:
        if not self._ready and not self.store.exists() and not self.error:
            return []
        return self._store().list(limit, status, owner)

    @_storage_guard
    def cancel(self, job_id: str, owner: str | None = None) -> dict[str, Any]:
        """Cancel a queued or running job (its finished points are kept). ``JobFinished`` when it ended.

        A job running here stops at once (its point in progress is abandoned); one running in another
        server sharing the file stops at that server's next lease renewal (a third of ``TENSEGRITY_JOBS_LEASE_SECONDS``).
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
        slot.thread_id = threading.get_ident()
        while not self._stopping.is_set():
            job = None
            if self._ready and not self.error:
                try:
                    self.store.check_file()
                    self.store.free_dead_leases(self.host)
                    if not self.resume:
                        self.store.recover(False)
                    with self._lock:
                        held = [s.job_id for s in self._slots if s.job_id]
                    job = self.store.claim(self.id, self.lease_seconds, exclude=held)
                except Exception as exc:  # database trouble: retry later (logged once a minute)
                    if time.monotonic() - self._fault_logged > 60:
                        self._fault_logged = time.monotonic()
                        log.error("job runner: cannot read the job queue of %s: %r", self.db_path, exc)
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
            except Exception:  # never let the runner die (the lease expires; the job is taken up again)
                log.exception("job %s: unexpected runner error", job["id"])
            finally:
                with self._lock:
                    slot.job_id = None

    def _run(self, slot: _Slot, job: dict[str, Any]) -> None:
        """Run ``job`` until it is done, cancelled, its lease lost, its slice over or the server stops."""
        job_id = job["id"]
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
            if isinstance(exc, sqlite3.Error):
                raise
            msg = format_error(exc) if not isinstance(exc, (OSError, TimeoutError)) else \
                f"scheduler_unreachable: {type(exc).__name__}: {exc}"
            log.warning("job %s failed: %s", job_id, msg)
            self.store.release(job_id, self.id, status="failed", message=msg[:2000], finished=True)
            return
        if slot.stop.is_set():
            return  # cancelled (a cancel or DELETE set "cancelled"), or another server holds the job now
        stored = self.store.count(job_id)
        if stored >= job["total"]:
            self.store.release(job_id, self.id, status="done", finished=True)
            log.info("job %s: done (%d points, %.1f s in this run)", job_id, job["total"], time.perf_counter() - t0)
        elif self._stopping.is_set():
            if self.resume:
                self.store.release(job_id, self.id, status="queued",
                                   message="stopped by a server shutdown; resumes when the server starts again")
            else:
                self.store.release(job_id, self.id, status="interrupted", finished=True,
                                   message="stopped by a server shutdown; finished points are kept")
        elif yielded:
            self.store.release(job_id, self.id, status="queued",
                               message=f"waiting for its next turn ({stored} of {job['total']} points done; "
                                       f"jobs take turns of {self.slice_seconds:g} s)")
        else:  # pragma: no cover - defensive
            self.store.release(job_id, self.id, status="failed", finished=True,
                               message=f"internal_error: {stored} of {job['total']} points stored")

    def _timed_row(self, slot: _Slot, header: Mapping[str, Any], pcols: list[str], rcols: list[str], i: int,
                   p: Mapping[str, Any]) -> dict[str, Any] | None:
        """One point under ``point_timeout``: the watchdog raises :class:`PointTimeout` in this thread at its
        next bytecode after the deadline (after the CasADi/IPOPT call in progress returns). ``None`` when the
        point was abandoned (:meth:`_abandon`: the job was cancelled, its lease lost, or the server stops);
        nothing is stored for it then, and a resumed job computes it again."""
        with self._watch:
            slot.deadline = time.monotonic() + self.point_timeout
            slot.fired = False
            slot.abandoned = False
            slot.armed = True
            self._watch.notify()
        try:
            try:
                return solve_chunk(header, pcols, rcols, [(i, p)])[0][1]
            finally:
                while True:              # a repeated PointTimeout may land here too: disarm regardless
                    try:
                        with self._watch_lock:
                            slot.armed = False
                            if slot.fired:       # sent but perhaps not delivered yet: never into the next point
                                _set_async_exc(slot.thread_id, None)
                        break
                    except PointTimeout:
                        continue
        except PointTimeout:
            if slot.abandoned:
                return None
            log.warning("point %d of a job exceeded %g s (TENSEGRITY_JOBS_POINT_TIMEOUT)", i, self.point_timeout)
            return error_row(header, pcols, rcols, i, p, f"timeout: the point did not finish within "
                                                          f"{self.point_timeout:g} s (TENSEGRITY_JOBS_POINT_TIMEOUT)")

    def _abandon(self, slot: _Slot) -> None:
        """Interrupt the point in progress in ``slot`` now (its job was cancelled, or its lease lost, or the
        server stops): the thread is free after the CasADi call in progress instead of after the point."""
        with self._watch:
            if slot.armed and not slot.fired:
                slot.fired, slot.fired_at = True, time.monotonic()
                slot.abandoned = True
                _set_async_exc(slot.thread_id, PointTimeout)
                self._watch.notify()            # the watchdog repeats it while the point runs

    def _watchdog(self) -> None:
        while not self._stopping.is_set():
            with self._watch:
                now = time.monotonic()
                nxt = None
                for s in self._slots:
                    if not s.armed:
                        continue
                    if s.fired:
                        # sent, and the point still runs: an exception that landed in a finaliser
                        # (a __del__ run by the garbage collector in that thread) was swallowed there
                        # ("Exception ignored in ..."): send it again until the point ends
                        if now - s.fired_at >= REFIRE_SECONDS:
                            s.fired_at = now
                            _set_async_exc(s.thread_id, PointTimeout)
                        nxt = s.fired_at + REFIRE_SECONDS if nxt is None else min(nxt, s.fired_at + REFIRE_SECONDS)
                    elif s.deadline <= now:
                        s.fired, s.fired_at = True, now
                        _set_async_exc(s.thread_id, PointTimeout)
                        nxt = now + REFIRE_SECONDS if nxt is None else min(nxt, now + REFIRE_SECONDS)
                    else:
                        nxt = s.deadline if nxt is None else min(nxt, s.deadline)
                self._watch.wait(1.0 if nxt is None else max(0.001, nxt - now))

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
            if self._ready and not self.error and time.monotonic() - self._purged > 3600:
                try:
                    self._purge()
                except Exception as exc:
                    log.warning("cannot purge expired jobs: %r", exc)

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


def summary(job: Mapping[str, Any]) -> dict[str, Any]:
    """The API's ``JobSummary`` of a stored job."""
    total = int(job["total"])
    return {"id": job["id"], "status": job["status"], "analysis": job["analysis"], "total": total,
            "done": job["done"], "failed": job["failed"], "progress": round(job["done"] / total, 6) if total else 1.0,
            "runs": job["runs"], "created_at": iso(job["created_at"]), "started_at": iso(job["started_at"]),
            "finished_at": iso(job["finished_at"]), "message": job["message"]}

