#!/usr/bin/env python3
"""The job store under thread churn: descriptors, SQLite connections and RSS of a real server (not a test).

Starts ``tensegrity-opt serve`` (default settings, its own job database in a temporary directory), stores one
small job, then sends ``--bursts`` bursts (default 40) of ``--concurrency`` (default 30) concurrent
``GET /v1/jobs?limit=1``, ``--spacing`` seconds apart (default 12). The server answers these in the thread pool
of its event loop (AnyIO's worker threads), whose idle threads exit after 10 s: each burst runs on fresh threads.
``--idle S`` makes those threads exit after ``S`` seconds instead (then a shorter ``--spacing`` churns the same
way, faster). The server runs in the temporary directory, on the installed ``service`` (or ``PYTHONPATH``'s).
Prints, before the first burst and after the last one: the open connections to the database
(descriptors of the server on the database file itself), all descriptors (``/proc/<pid>/fd``), threads and RSS.

    python benchmarks/jobs_store_churn.py                       # the real idle time: ~8 minutes
    python benchmarks/jobs_store_churn.py --idle 0.2 --spacing 0.5
"""

from __future__ import annotations

import argparse
import http.client
import json
import os
import socket
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

import httpx


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def server_command(port: int, idle: float | None) -> list[str]:
    """``tensegrity-opt serve`` (its own code, :mod:`service.cli`), with AnyIO's idle time set to ``idle``."""
    code = "import sys\n"
    if idle is not None:
        code += f"import anyio._backends._asyncio as a\na.WorkerThread.MAX_IDLE_TIME = {idle!r}\n"
    code += "from service.cli import main\nsys.exit(main(sys.argv[1:]))\n"
    return [sys.executable, "-c", code, "serve", "--host", "127.0.0.1", "--port", str(port), "--no-access-log",
            "--log-level", "warning"]


def figures(pid: int, db: Path) -> dict[str, int]:
    """Connections to ``db`` (descriptors on the file itself), descriptors, threads, RSS (MB) of ``pid``."""
    fds = os.listdir(f"/proc/{pid}/fd")
    conns = 0
    for fd in fds:
        try:
            if os.readlink(f"/proc/{pid}/fd/{fd}") == str(db):
                conns += 1
        except OSError:
            pass
    status = Path(f"/proc/{pid}/status").read_text().splitlines()
    field = dict(ln.split(":", 1) for ln in status if ":" in ln)
    return {"connections": conns, "descriptors": len(fds), "threads": int(field["Threads"].split()[0]),
            "rss_mb": round(int(field["VmRSS"].split()[0]) / 1024)}


def burst(base: str, concurrency: int) -> list[int]:
    """``concurrency`` concurrent ``GET /v1/jobs?limit=1``, each on its own connection; their statuses."""
    statuses: list[int] = []
    gate = threading.Barrier(concurrency)
    host, port = base.rsplit("/", 1)[1].split(":")

    def one() -> None:
        gate.wait()
        con = http.client.HTTPConnection(host, port, timeout=120)
        try:
            con.request("GET", "/v1/jobs?limit=1")
            statuses.append(con.getresponse().status)
        except OSError:
            statuses.append(0)
        finally:
            con.close()

    threads = [threading.Thread(target=one) for _ in range(concurrency)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return statuses


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--bursts", type=int, default=40)
    p.add_argument("--concurrency", type=int, default=30)
    p.add_argument("--spacing", type=float, default=12.0, help="seconds between two bursts (default 12)")
    p.add_argument("--idle", type=float, default=None, help="seconds an idle worker thread lives (default: AnyIO's)")
    args = p.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        db = Path(tmp) / "jobs.sqlite3"
        port = _free_port()
        env = {k: v for k, v in os.environ.items() if not k.startswith("TENSEGRITY_")}
        env["TENSEGRITY_JOBS_DB"] = str(db)
        log = open(Path(tmp) / "server.log", "wb")
        proc = subprocess.Popen(server_command(port, args.idle), env=env, cwd=tmp, stdout=log,
                                stderr=subprocess.STDOUT)
        base = f"http://127.0.0.1:{port}"
        try:
            deadline = time.monotonic() + 600
            while True:
                try:
                    if httpx.get(base + "/readyz", timeout=10).status_code == 200:
                        break
                except httpx.TransportError:
                    pass
                if proc.poll() is not None or time.monotonic() > deadline:
                    raise SystemExit("the server did not start: " + (Path(tmp) / "server.log").read_text())
                time.sleep(0.2)
            job = httpx.post(base + "/v1/jobs", json={"analysis": "buckling", "grid": {"n": [3]}}, timeout=120).json()
            while httpx.get(f"{base}/v1/jobs/{job['id']}", params={"limit": 0}, timeout=60).json()["status"] \
                    not in ("done", "failed"):
                time.sleep(0.2)
            start = figures(proc.pid, db)
            statuses: dict[int, int] = {}
            for k in range(args.bursts):
                if k:
                    time.sleep(args.spacing)
                for s in burst(base, args.concurrency):
                    statuses[s] = statuses.get(s, 0) + 1
            end = figures(proc.pid, db)
        finally:
            proc.terminate()
            proc.wait(30)
            log.close()
    print(json.dumps({"bursts": args.bursts, "concurrency": args.concurrency, "spacing": args.spacing,
                      "idle": args.idle, "statuses": statuses, "start": start, "end": end}, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
