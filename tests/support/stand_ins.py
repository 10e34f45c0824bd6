"""Stand-ins for long computations in a real server process, so that a test of a time limit expires on any machine.

A server started as ``uvicorn --factory stand_ins:app_with_designs_that_never_end`` (this folder on its
``PYTHONPATH``: :func:`server_env`) is the service with one change: ``POST /v1/design/critical-force`` on a chain
of :data:`NEVER_ENDING_SEGMENTS` segments or more never ends by itself (the killable solver process sleeps an
hour), every other request is the real one. The task is sent to the solver process by name, so the process imports
it from here too. ``stand_ins:app_with_short_lived_request_threads`` is the service whose request threads exit
after a fraction of a second idle (thread churn, fast).
"""

from __future__ import annotations

import os
import time
from pathlib import Path

#: Design requests on chains this long (or longer) never end by themselves.
NEVER_ENDING_SEGMENTS = 60
HERE = Path(__file__).resolve().parent


def design_critical_force_or_never(req):
    """The service's design task, except on long chains: those sleep an hour."""
    from service.adapters.inputs import segment_count
    from service.tasks.control import design_critical_force_task

    if segment_count(req.manipulator) >= NEVER_ENDING_SEGMENTS:
        time.sleep(3600.0)
    return design_critical_force_task(req)


def app_with_designs_that_never_end():
    """The service's app (settings from the environment) with :func:`design_critical_force_or_never`."""
    from service.api.routes import design
    from service.main import create_app

    design.design_critical_force_task = design_critical_force_or_never
    return create_app()


def server_env(env: dict[str, str]) -> dict[str, str]:
    """``env`` with this folder first on ``PYTHONPATH`` (the server and its solver processes import from here)."""
    return {**env, "PYTHONPATH": os.pathsep.join(p for p in (str(HERE), env.get("PYTHONPATH")) if p)}


#: Seconds an idle request thread lives in :func:`app_with_short_lived_request_threads` (AnyIO's default: 10).
REQUEST_THREAD_IDLE_SECONDS = 0.05


def app_with_short_lived_request_threads():
    """The service's app (settings from the environment) whose request threads (AnyIO's worker threads, which run
    the plain route functions) exit after :data:`REQUEST_THREAD_IDLE_SECONDS` idle instead of 10 s: bursts of
    requests a fraction of a second apart each run on fresh threads (thread churn without the wait)."""
    import anyio._backends._asyncio as anyio_asyncio

    from service.main import create_app

    anyio_asyncio.WorkerThread.MAX_IDLE_TIME = REQUEST_THREAD_IDLE_SECONDS
    return create_app()


#: The environment variable naming the file whose presence lets a fast solver process finish its warm-up
#: (:func:`app_with_a_held_fast_process`).
WARMUP_GATE = "STAND_IN_WARMUP_GATE"


def held_warmup() -> None:
    """The service's warm-up; in a solver process (its main thread) it first waits until the file named by
    ``STAND_IN_WARMUP_GATE`` exists, so that a test decides when a restarted process gets ready."""
    import threading

    from service.tasks.equilibria import warmup

    gate = os.environ.get(WARMUP_GATE)
    if gate and threading.current_thread() is threading.main_thread():
        while not os.path.exists(gate):
            time.sleep(0.01)
    warmup()


def app_with_a_held_fast_process():
    """The service's app (settings from the environment) whose solver processes warm up with
    :func:`held_warmup`."""
    from service import tasks
    from service.main import create_app

    tasks.equilibria.warmup = held_warmup
    return create_app()
