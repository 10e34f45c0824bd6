"""The job store: every sweep job and every finished point in one SQLite file.

Durability
----------
* Jobs and points live in one SQLite file (``TENSEGRITY_JOBS_DB``, default ``tensegrity_jobs.sqlite3`` in the
  working directory) in WAL mode. A point's row is written as soon as the sweep delivers it, in its own
  committed transaction, so killing the server (even SIGKILL) loses no finished point.
  ``TENSEGRITY_JOBS_SYNCHRONOUS`` (``NORMAL`` by default) is SQLite's ``synchronous``: ``NORMAL`` survives a
  killed process, ``FULL`` also a power cut (an fsync per point).
* Points are keyed by ``(job, index)`` and inserted with ``INSERT OR IGNORE``: a point is stored once and never
  rewritten; with a runner's id it is stored only while that runner holds the job's lease.

Leases: several servers on one file
-----------------------------------
A runner (one per server process, ``host:pid-token``) takes a job with one atomic ``UPDATE ... WHERE``
(``queued``, or ``running`` with an expired lease) ``RETURNING id``, with a lease it renews
(:meth:`JobStore.claim`, :meth:`JobStore.renew`); the job that waited longest for its turn goes first
(``turn_at``: its creation, then the end of its last slice). The leases of a runner of this host whose process
is gone are freed at once (:meth:`JobStore.free_dead_leases`).

Owners
------
With API keys configured a job belongs to the key that submitted it: the store keeps :func:`owner_hash`, the
SHA-256 of the key, never the key. ``owner`` arguments: ``None`` sees every job (auth off); a hash sees only the
jobs it created.

Figure jobs
-----------
A figure computed as a job (analysis ``figure``) stores its steps as rows (``index``, ``stage``, ``error``) and its
image, once, in the table ``figures`` (:meth:`JobStore.put_figure`, :meth:`JobStore.figure`); deleting the job
deletes its image.

Connections
-----------
The store keeps at most ``max_connections`` SQLite connections (default 8), shared by every thread: a call
borrows one for its statement or transaction and gives it back (:meth:`JobStore.connection`). A thread that
exits leaves nothing open behind, however many threads come and go (the server's request threads exit after a
few seconds idle); a thread finding every connection in use waits for one. A connection that met a storage
fault is closed rather than reused.

Storage faults and health
-------------------------
Every storage fault (an SQLite or OS error: a full disk, a read-only or damaged file, a file that cannot be
opened) is remembered as the store's health (:meth:`JobStore.health`: what failed, never where on disk) until a
write succeeds again: a write that changed the file, or :meth:`JobStore.probe` (a small write plus a check of
the free space of the file's device). Nothing is given up for good: the next call tries again.

A database file deleted or replaced while the server runs (its device and inode are checked,
:meth:`JobStore.check_file`) raises :class:`JobsUnavailable` (503 ``jobs_unavailable``) until the server is
restarted; a deleted file is not recreated (that would silently start an empty store beside servers still
writing into the old one).
"""

from __future__ import annotations

import hashlib
import json
import logging
import os
import sqlite3
import threading
import time
import uuid
from collections.abc import Iterable, Iterator, Mapping
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from ..responses import json_safe

log = logging.getLogger("service.jobs")

__all__ = ["JobStore", "JobNotFound", "JobFinished", "JobsUnavailable", "TERMINAL", "owner_hash", "fault_text"]

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
    replaced while the server runs (503 ``jobs_unavailable``, mapped in :mod:`service.api.errors`)."""


def _dumps(x: Any) -> str:
    return json.dumps(json_safe(x), allow_nan=False, separators=(",", ":"))

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
CREATE TABLE IF NOT EXISTS probe (
    id  INTEGER PRIMARY KEY CHECK (id = 1),
    at  REAL NOT NULL
);
CREATE TABLE IF NOT EXISTS points (
    job_id  TEXT NOT NULL,
    idx     INTEGER NOT NULL,
    failed  INTEGER NOT NULL,
    row     TEXT NOT NULL,
    PRIMARY KEY (job_id, idx)
) WITHOUT ROWID;
CREATE TABLE IF NOT EXISTS figures (
    job_id      TEXT PRIMARY KEY,
    media_type  TEXT NOT NULL,
    data        BLOB NOT NULL
);
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


#: The store's own name in messages: what failed, never where on disk (the logs have the path).
NAME = "the job store (TENSEGRITY_JOBS_DB)"
#: Faults of the storage (remembered as the store's health; the connection that met one is closed). A
#: constraint or a misuse of the API is not one.
_FAULTS = (sqlite3.OperationalError, sqlite3.InternalError, sqlite3.NotSupportedError, OSError)
#: Free space below this on the file's device fails :meth:`JobStore.probe` (a full disk).
PROBE_MIN_FREE_BYTES = 64 * 1024


def _is_fault(exc: BaseException) -> bool:
    return isinstance(exc, _FAULTS) or type(exc) is sqlite3.DatabaseError   # "file is not a database"


def fault_text(exc: BaseException) -> str:
    """What went wrong, without a path: SQLite's message, or the OS error's text without its file name."""
    if isinstance(exc, JobsUnavailable):
        return str(exc)
    if isinstance(exc, OSError):
        return exc.strerror or type(exc).__name__
    return str(exc) or type(exc).__name__


def owner_hash(key: str) -> str:
    """What the store keeps of an API key: its SHA-256 (hex), never the key."""
    return hashlib.sha256(key.encode("utf-8", "surrogateescape")).hexdigest()


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


class JobStore:
    """Jobs and their points in one SQLite file (WAL; a bounded set of shared connections, autocommit).

    ``owner`` arguments: ``None`` sees every job (auth off); a hash sees only the jobs it created.
    """

    def __init__(self, path: str | os.PathLike[str], synchronous: str = "NORMAL", max_connections: int = 8) -> None:
        if max_connections < 1:
            raise ValueError("max_connections must be at least 1")
        self.path = Path(path)
        self.synchronous = synchronous
        self.max_connections = max_connections
        self._idle: list[sqlite3.Connection] = []    # open and free (the last returned is lent first)
        self._open_count = 0                         # open connections: idle + lent
        self._free = threading.Condition(threading.Lock())
        self._closed = False
        self._identity: tuple[int, int] | None = None
        self._health_lock = threading.Lock()
        self._fault: str | None = None               # what failed last (None: healthy)
        self._fault_since: float | None = None       # epoch seconds of the first failure of this fault
        self._gone: str | None = None                # the file was deleted or replaced: until a restart

    # -------------------------------------------------------------- connections
    def exists(self) -> bool:
        return self.path.exists()

    def open(self) -> None:
        """Create the file and the tables when missing (idempotent); remember the file's identity."""
        self._closed = False
        try:
            if self.path.parent and not self.path.parent.exists():
                self.path.parent.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            self._failed(f"{NAME} cannot be opened: {fault_text(exc)}")
            raise
        with self.connection(write=True, doing="opened") as con:
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
        if self._gone:
            raise JobsUnavailable(self._gone)
        try:
            st = os.stat(self.path)
        except FileNotFoundError:
            self._failed(f"the file of {NAME} was deleted while the server runs; jobs are unavailable until the "
                         f"server is restarted", gone=True)
            log.error("the job store %s was deleted while the server runs", self.path)
            raise JobsUnavailable(self._gone) from None
        except OSError as exc:
            self._failed(f"{NAME} cannot be used: {fault_text(exc)}")
            raise JobsUnavailable(self._fault) from None
        if (st.st_dev, st.st_ino) != self._identity:
            self._failed(f"the file of {NAME} was replaced by another file while the server runs; jobs are "
                         f"unavailable until the server is restarted", gone=True)
            log.error("the job store %s was replaced by another file while the server runs", self.path)
            raise JobsUnavailable(self._gone)

    @contextmanager
    def connection(self, write: bool = False, doing: str | None = None) -> Iterator[sqlite3.Connection]:
        """Borrow a connection for one statement or transaction (waiting while all ``max_connections`` are
        lent). A storage fault inside is remembered as the store's health and closes the connection; a
        ``write`` that changed the file clears the health."""
        con = self._borrow()
        before = con.total_changes
        try:
            yield con
        except BaseException as exc:
            fault = _is_fault(exc)
            if fault:
                self._failed(f"{NAME} cannot be {doing or ('written' if write else 'read')}: {fault_text(exc)}")
            self._give_back(con, discard=fault)
            raise
        if write and con.total_changes != before:
            self._healthy()
        self._give_back(con)

    def _borrow(self) -> sqlite3.Connection:
        with self._free:
            while True:
                if self._closed:
                    raise JobsUnavailable(f"{NAME} is closed")
                if self._idle:
                    return self._idle.pop()
                if self._open_count < self.max_connections:
                    self._open_count += 1
                    break
                if not self._free.wait(30.0):
                    raise JobsUnavailable(f"all {self.max_connections} connections of {NAME} stayed in use for 30 s")
        try:
            con = _connect(self.path)
            try:
                con.execute("PRAGMA busy_timeout=30000")
                con.execute(f"PRAGMA synchronous={self.synchronous}")
            except BaseException:
                con.close()
                raise
        except BaseException as exc:
            with self._free:
                self._open_count -= 1
                self._free.notify()
            if _is_fault(exc):
                self._failed(f"{NAME} cannot be opened: {fault_text(exc)}")
            raise
        return con

    def _give_back(self, con: sqlite3.Connection, discard: bool = False) -> None:
        if con.in_transaction and not discard:
            try:
                con.execute("ROLLBACK")
            except sqlite3.Error:
                discard = True
        with self._free:
            keep = not (discard or self._closed)
            if keep:
                self._idle.append(con)
            else:
                self._open_count -= 1
            self._free.notify()
        if not keep:
            try:
                con.close()
            except Exception:  # pragma: no cover
                pass

    @property
    def open_connections(self) -> int:
        """SQLite connections open now (idle and lent; at most ``max_connections``)."""
        with self._free:
            return self._open_count

    def close(self) -> None:
        """Close the idle connections now and the lent ones when they come back."""
        with self._free:
            self._closed = True
            idle, self._idle = self._idle, []
            self._open_count -= len(idle)
            self._free.notify_all()
        for con in idle:
            try:
                con.close()
            except Exception:  # pragma: no cover
                pass

    # -------------------------------------------------------------- health
    def _failed(self, message: str, gone: bool = False) -> None:
        with self._health_lock:
            if gone and self._gone is None:
                self._gone = message
            if self._fault != message:
                self._fault_since = self._fault_since if self._fault else time.time()
                self._fault = message

    def _healthy(self) -> None:
        with self._health_lock:
            if self._gone is None:
                self._fault = self._fault_since = None

    def health(self) -> dict[str, Any]:
        """``{"status": "ok"}``, or ``{"status": "failing", "message": what failed, "since": epoch seconds}``
        (the message names no path). Reads no file."""
        with self._health_lock:
            fault = self._gone or self._fault
            if fault is None:
                return {"status": "ok", "message": None, "since": None}
            return {"status": "failing", "message": fault, "since": self._fault_since}

    def probe(self) -> None:
        """Check that the store can be written now: the file is still the one opened, its device has at least
        :data:`PROBE_MIN_FREE_BYTES` free, and a small write commits. Clears the health on success; raises the
        fault otherwise (remembered as the health)."""
        self.check_file()
        try:
            st = os.statvfs(self.path.parent if str(self.path.parent) else ".")
        except OSError as exc:
            self._failed(f"{NAME} cannot be used: {fault_text(exc)}")
            raise
        if st.f_bavail * st.f_frsize < PROBE_MIN_FREE_BYTES:
            self._failed(f"{NAME} cannot be written: no space left on its device")
            raise JobsUnavailable(self._fault)
        with self.connection(write=True) as con:
            con.execute("INSERT INTO probe (id, at) VALUES (1, ?) ON CONFLICT (id) DO UPDATE SET at = excluded.at",
                        (time.time(),))

    @contextmanager
    def _tx(self) -> Iterator[sqlite3.Connection]:
        """A write transaction (``BEGIN IMMEDIATE`` ... ``COMMIT``, rolled back on error) on a borrowed connection."""
        with self.connection(write=True) as con:
            con.execute("BEGIN IMMEDIATE")
            try:
                yield con
            except BaseException:
                if con.in_transaction:
                    con.execute("ROLLBACK")
                raise
            con.execute("COMMIT")

    def _write(self, sql: str, args: Any = ()) -> int:
        """One write statement on a borrowed connection; its row count."""
        with self.connection(write=True) as con:
            return con.execute(sql, args).rowcount

    def _read(self, sql: str, args: Any = ()) -> list[tuple[Any, ...]]:
        """One query on a borrowed connection; its rows."""
        with self.connection() as con:
            return con.execute(sql, args).fetchall()

    # -------------------------------------------------------------- jobs
    def create(self, spec: Mapping[str, Any], total: int, columns: list[str],
               owner: str | None = None) -> dict[str, Any]:
        job_id = uuid.uuid4().hex
        now = time.time()
        self._write("INSERT INTO jobs (id, status, analysis, total, spec, columns, created_at, owner, turn_at) "
                    "VALUES (?, 'queued', ?, ?, ?, ?, ?, ?, ?)",
                    (job_id, spec["analysis"], total, _dumps(spec), _dumps(columns), now, owner, now))
        return self.get(job_id)

    def get(self, job_id: str, owner: str | None = None) -> dict[str, Any]:
        with self.connection() as con:
            return self._get(con, job_id, owner)

    @staticmethod
    def _get(con: sqlite3.Connection, job_id: str, owner: str | None = None) -> dict[str, Any]:
        q = ("SELECT id, status, analysis, total, spec, columns, created_at, started_at, finished_at, message, runs, "
             "lease_owner FROM jobs WHERE id = ?")
        args: tuple[Any, ...] = (job_id,)
        if owner is not None:
            q += " AND owner = ?"
            args += (owner,)
        r = con.execute(q, args).fetchone()
        if r is None:
            raise JobNotFound(job_id)
        done, failed = con.execute(
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
        with self.connection() as con:
            ids = [r[0] for r in con.execute(q, (*args, int(limit))).fetchall()]
            out = []
            for i in ids:
                try:
                    out.append(self._get(con, i))
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
        return self._write(q, args) > 0

    def start_run(self, job_id: str) -> bool:
        """``queued``/``running`` -> ``running`` without a lease, counting the run (what a process that was
        killed before it took leases leaves behind; the runner itself uses :meth:`claim`)."""
        now = time.time()
        return self._write(
            "UPDATE jobs SET status = 'running', runs = runs + 1, started_at = COALESCE(started_at, ?), message = "
            "CASE WHEN runs > 0 THEN 'resumed after a restart' ELSE NULL END "
            "WHERE id = ? AND status IN ('queued', 'running')", (now, job_id)) > 0

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
        with self.connection(write=True) as con:
            r = con.execute(
                "UPDATE jobs SET status = 'running', lease_owner = :me, lease_until = :until, "
                "runs = runs + (lease_owner IS NOT :me), started_at = COALESCE(started_at, :now), "
                "message = CASE WHEN runs > 0 AND lease_owner IS NOT :me THEN 'resumed after a restart' ELSE NULL END "
                f"WHERE id = (SELECT id FROM jobs WHERE {_CLAIMABLE}{not_in} "
                "ORDER BY COALESCE(turn_at, created_at), rowid LIMIT 1) "
                f"AND {_CLAIMABLE} RETURNING id", params).fetchall()
            return self._get(con, r[0][0]) if r else None

    def renew(self, job_id: str, runner_id: str, lease: float) -> bool:
        """Extend the lease; False when the job is no longer ``running`` under this runner's lease."""
        return self._write("UPDATE jobs SET lease_until = ? WHERE id = ? AND lease_owner = ? AND status = 'running'",
                           (time.time() + lease, job_id, runner_id)) > 0

    def waiting(self, exclude: Iterable[str] = ()) -> bool:
        """Is any job waiting for a runner?"""
        ex = list(exclude)
        q = f"SELECT 1 FROM jobs WHERE {_CLAIMABLE}"
        params: dict[str, Any] = {"now": time.time()}
        if ex:
            q += f" AND id NOT IN ({', '.join(f':x{k}' for k in range(len(ex)))})"
            params.update({f"x{k}": v for k, v in enumerate(ex)})
        return bool(self._read(q + " LIMIT 1", params))

    def release(self, job_id: str, runner_id: str, *, status: str = "queued", message: str | None = None,
                finished: bool = False) -> bool:
        """End this runner's lease on a running job: back to ``queued`` (its turn is over), or finished."""
        now = time.time()
        return self._write(
            "UPDATE jobs SET status = ?, message = ?, lease_until = NULL, turn_at = ?, "
            "finished_at = CASE WHEN ? THEN ? ELSE finished_at END "
            "WHERE id = ? AND lease_owner = ? AND status = 'running'",
            (status, message, now, 1 if finished else 0, now, job_id, runner_id)) > 0

    def recover(self, resume: bool) -> int:
        """Jobs left ``running`` by a server that died (lease expired, or none): resumed by :meth:`claim`,
        or, with resuming off, marked ``interrupted``."""
        if resume:
            return 0
        now = time.time()
        return self._write(
            "UPDATE jobs SET status = 'interrupted', finished_at = :now, lease_until = NULL, message = 'the server "
            "stopped while the job ran; its finished points are kept (resuming is off: TENSEGRITY_JOBS_RESUME=false)' "
            "WHERE status = 'running' AND COALESCE(lease_until, 0) < :now", {"now": now})

    def free_dead_leases(self, host: str) -> int:
        """Free the leases held by runners of this host whose process is gone (a killed server restarted
        on the same machine resumes its jobs at once instead of after the lease). A live process with a
        reused pid only delays the take-over until the lease expires."""
        now = time.time()
        dead = []
        for job_id, owner in self._read(
                "SELECT id, lease_owner FROM jobs WHERE status = 'running' AND lease_until >= ?", (now,)):
            pid = _lease_pid(owner, host)
            if pid is not None and not _alive(pid):
                dead.append((job_id, owner))
        n = 0
        for job_id, owner in dead:
            n += self._write("UPDATE jobs SET lease_until = NULL WHERE id = ? AND lease_owner = ? AND "
                             "status = 'running'", (job_id, owner))
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
            con.execute("DELETE FROM figures WHERE job_id = ?", (job_id,))
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
                con.execute("DELETE FROM figures WHERE job_id = ?", (i,))
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
            return self._write("INSERT OR IGNORE INTO points (job_id, idx, failed, row) VALUES (?, ?, ?, ?)", args) > 0
        return self._write(
            "INSERT OR IGNORE INTO points (job_id, idx, failed, row) SELECT ?, ?, ?, ? WHERE EXISTS "
            "(SELECT 1 FROM jobs WHERE id = ? AND status = 'running' AND lease_owner = ?)",
            (*args, job_id, runner_id)) > 0

    def put_figure(self, job_id: str, media_type: str, data: bytes, runner_id: str) -> bool:
        """Store the image of a figure job, while ``runner_id`` holds its lease (as :meth:`add_point`). True when
        stored."""
        return self._write(
            "INSERT OR REPLACE INTO figures (job_id, media_type, data) SELECT ?, ?, ? WHERE EXISTS "
            "(SELECT 1 FROM jobs WHERE id = ? AND status = 'running' AND lease_owner = ?)",
            (job_id, media_type, sqlite3.Binary(data), job_id, runner_id)) > 0

    def figure(self, job_id: str) -> tuple[str, bytes] | None:
        """The media type and bytes of a figure job's image; ``None`` before it is stored."""
        rows = self._read("SELECT media_type, data FROM figures WHERE job_id = ?", (job_id,))
        return None if not rows else (str(rows[0][0]), bytes(rows[0][1]))

    def done_indices(self, job_id: str) -> set[int]:
        return {r[0] for r in self._read("SELECT idx FROM points WHERE job_id = ?", (job_id,))}

    def count(self, job_id: str) -> int:
        return int(self._read("SELECT COUNT(*) FROM points WHERE job_id = ?", (job_id,))[0][0])

    def rows(self, job_id: str, offset: int = 0, limit: int | None = None) -> list[dict[str, Any]]:
        q = "SELECT row FROM points WHERE job_id = ? ORDER BY idx LIMIT ? OFFSET ?"
        return [json.loads(r[0]) for r in self._read(q, (job_id, -1 if limit is None else int(limit), int(offset)))]

    def row_batches(self, job_id: str, offset: int = 0, limit: int | None = None,
                    batch: int = 1000) -> Iterator[list[dict[str, Any]]]:
        """The rows from ``offset`` (at most ``limit``) in batches of ``batch``, by index (keyset paging:
        each batch is one short query, so a long download holds no transaction open)."""
        left = -1 if limit is None else int(limit)
        first = self._read("SELECT idx FROM points WHERE job_id = ? ORDER BY idx LIMIT 1 OFFSET ?",
                           (job_id, int(offset)))
        if not first or left == 0:
            return
        last, op = first[0][0], ">="
        while left != 0:
            n = batch if left < 0 else min(batch, left)
            got = self._read(f"SELECT idx, row FROM points WHERE job_id = ? AND idx {op} ? ORDER BY idx LIMIT ?",
                             (job_id, last, n))
            if not got:
                return
            yield [json.loads(r[1]) for r in got]
            last, op = got[-1][0], ">"
            if left > 0:
                left -= len(got)
            if len(got) < n:
                return
