"""Real server processes for the tests: start on a free loopback port, wait until ready, stop."""

from __future__ import annotations

import os
import signal
import socket
import subprocess
import sys
import time
from collections.abc import Iterator, Sequence
from contextlib import contextmanager

#: How long a test waits for what must happen (a server ready, an answer): the wait ends as soon as it happens, so
#: only a machine many times slower than a quiet one comes near it.
WAIT_SECONDS = 600.0
#: The time limits of a server that is expected to answer: far beyond what any request of the tests takes quiet (a
#: few seconds), so that a loaded machine answers too (at the default 10 s it answers 504).
GENEROUS_SECONDS = 300.0
GENEROUS_ENV = {"TENSEGRITY_SOLVE_TIMEOUT": str(GENEROUS_SECONDS), "TENSEGRITY_BATCH_TIMEOUT": str(GENEROUS_SECONDS)}


def free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def serve_command(port: int) -> list[str]:
    """``tensegrity-opt serve`` on ``port``, as ``python -m service serve`` (the console script's own
    code, :mod:`service.cli`, whatever the installed script points at)."""
    return [sys.executable, "-m", "service", "serve", "--host", "127.0.0.1", "--port", str(port), "--no-access-log",
            "--log-level", "warning"]


def uvicorn_factory_command(factory: str, port: int, *extra: str) -> list[str]:
    """``uvicorn --factory FACTORY`` on ``port`` (apps the console script does not build)."""
    return [sys.executable, "-m", "uvicorn", "--factory", *extra, factory, "--host", "127.0.0.1", "--port",
            str(port), "--log-level", "warning", "--no-access-log"]


def clean_env(**settings: str) -> dict[str, str]:
    """The environment without any ``TENSEGRITY_*`` variable, plus ``settings``."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("TENSEGRITY_")}
    env.update(settings)
    return env


def wait_ready(proc: subprocess.Popen, base: str, path: str = "/healthz", timeout: float = WAIT_SECONDS,
               log=None) -> None:
    """Poll ``base + path`` until it answers 200; fail with the server's output if it exits."""
    import httpx

    deadline = time.monotonic() + timeout
    while True:
        if proc.poll() is not None:
            out = log() if callable(log) else (proc.stdout.read().decode(errors="replace") if proc.stdout else "")
            raise AssertionError(f"server exited with {proc.returncode}: {out}")
        try:
            if httpx.get(base + path, timeout=10).status_code == 200:
                return
        except httpx.TransportError:
            pass
        if time.monotonic() > deadline:
            raise AssertionError(f"server did not answer {path} within {timeout:g} s")
        time.sleep(0.1)


def stop(proc: subprocess.Popen, grace: float = 15.0) -> None:
    """SIGINT (uvicorn's graceful shutdown), then SIGKILL after ``grace`` seconds."""
    if proc.poll() is None:
        proc.send_signal(signal.SIGINT)
        try:
            proc.wait(grace)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait(5)


@contextmanager
def running_server(cmd: Sequence[str], env: dict[str, str], *, ready: str = "/healthz", timeout: float = WAIT_SECONDS,
                   cwd=None, stdout=subprocess.PIPE) -> Iterator[tuple[subprocess.Popen, str]]:
    """Start ``cmd`` (its ``--port`` is the last port argument), wait until ready, stop it on exit."""
    port = cmd[list(cmd).index("--port") + 1]
    proc = subprocess.Popen(list(cmd), env=env, cwd=cwd, stdout=stdout, stderr=subprocess.STDOUT)
    base = f"http://127.0.0.1:{port}"
    try:
        wait_ready(proc, base, ready, timeout)
        yield proc, base
    finally:
        stop(proc)
