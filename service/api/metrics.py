"""Prometheus metrics (one registry per app) and the ASGI middleware that records requests.

Exposed at ``GET /metrics`` in the Prometheus text format:

* ``tensegrity_http_requests_total{method, route, status}``
* ``tensegrity_http_request_duration_seconds{method, route}`` (histogram)
* ``tensegrity_errors_total{code}``: every refusal by its ``code`` (413 and 404/405 are only in
  the request counts)
* ``tensegrity_solver_failures_total{code}``: solves that failed (``solver_failed``,
  ``no_equilibrium``, ``numerical_failure``, ``timeout``, ``overloaded``)
* ``tensegrity_solver_pool_in_flight``, ``tensegrity_solver_pool_running``,
  ``tensegrity_solver_pool_capacity`` (gauges)
* ``tensegrity_design_processes_in_flight`` (gauge: design requests queued or running in the
  killable processes of :mod:`service.execution.processes`), ``tensegrity_design_processes_killed`` (gauge:
  processes killed because they could not stop at a deadline)
* ``tensegrity_solver_pool_shed`` (gauge: calls refused at once because they could not finish within their time
  limit by the expected wait, :mod:`service.execution.shedding`), ``tensegrity_solver_pool_expected_wait_seconds``
  (gauge: that wait for a new light call)
* ``tensegrity_solver_processes_state{pool, state}`` (gauge: 1 for the current state of the ``fast`` and ``design``
  solver processes: ``up``, ``starting``, ``restarting``, ``down``), ``tensegrity_solver_processes_ready{pool}``,
  ``tensegrity_solver_processes_restarts{pool}`` (processes started to replace lost ones)
* ``tensegrity_stream_connections`` (gauge: control streams open, ``/v1/control/stream``); the
  streams' refusals count in ``tensegrity_errors_total`` too

``route`` is the route template (``/v1/equilibrium``), never the raw path, so the label set
stays bounded; unmatched paths are ``route="<unmatched>"``.
"""

from __future__ import annotations

import time
from typing import Any

from prometheus_client import (
    CONTENT_TYPE_LATEST,
    CollectorRegistry,
    Counter,
    Gauge,
    Histogram,
    disable_created_metrics,
    generate_latest,
)
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from ..execution.processes import STATES

# No ``*_created`` series: they double the output and carry nothing a scraper needs.
disable_created_metrics()

SOLVER_FAILURE_CODES = frozenset({"solver_failed", "no_equilibrium", "numerical_failure", "timeout", "overloaded"})

__all__ = ["Metrics", "MetricsMiddleware", "CONTENT_TYPE_LATEST"]

_METHODS = frozenset({"GET", "HEAD", "POST", "PUT", "PATCH", "DELETE", "OPTIONS"})


class Metrics:
    """The registry of one app; its gauges read the app's executors (``service.execution.Executors``)."""

    def __init__(self, executors: Any = None) -> None:
        pool = getattr(executors, "threads", None)
        heavy = getattr(executors, "killable", None)
        streams = getattr(executors, "streams", None)
        self.registry = CollectorRegistry(auto_describe=True)
        self.requests = Counter("tensegrity_http_requests", "HTTP requests answered",
                                ["method", "route", "status"], registry=self.registry)
        self.latency = Histogram("tensegrity_http_request_duration_seconds", "HTTP request latency",
                                 ["method", "route"], registry=self.registry,
                                 buckets=(0.001, 0.0025, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 0.5, 1.0, 2.5,
                                          5.0, 10.0, 30.0, 60.0))
        self.errors = Counter("tensegrity_errors", "Refusals by error code", ["code"], registry=self.registry)
        self.solver_failures = Counter("tensegrity_solver_failures", "Solves that failed, by error code",
                                       ["code"], registry=self.registry)
        if pool is not None:
            g = Gauge("tensegrity_solver_pool_in_flight", "Solver calls queued or running", registry=self.registry)
            g.set_function(lambda: pool.in_flight)
            g = Gauge("tensegrity_solver_pool_running", "Solver calls running", registry=self.registry)
            g.set_function(lambda: pool.running)
            g = Gauge("tensegrity_solver_pool_capacity", "Solver workers + queue slots", registry=self.registry)
            g.set_function(lambda: pool.capacity)
        if pool is not None and hasattr(pool, "shed"):
            g = Gauge("tensegrity_solver_pool_shed", "Solver calls refused at once because they could not finish "
                      "within their time limit by the expected wait", registry=self.registry)
            g.set_function(lambda: pool.shed)
            g = Gauge("tensegrity_solver_pool_expected_wait_seconds", "Expected wait of a new light call for a "
                      "solver thread", registry=self.registry)
            g.set_function(lambda: pool.expected_wait())
        kinds = [(name, ex) for name, ex in (("fast", getattr(executors, "fast", None)), ("design", heavy))
                 if ex is not None and hasattr(ex, "state")]
        if kinds:
            state = Gauge("tensegrity_solver_processes_state", "Solver processes by kind (pool): 1 for the "
                          "current state (up, starting, restarting, down)", ["pool", "state"], registry=self.registry)
            ready = Gauge("tensegrity_solver_processes_ready", "Solver processes ready, by kind", ["pool"],
                          registry=self.registry)
            restarts = Gauge("tensegrity_solver_processes_restarts", "Solver processes started to replace lost "
                             "ones, by kind", ["pool"], registry=self.registry)
            for name, ex in kinds:
                for st in STATES:
                    state.labels(name, st).set_function(lambda ex=ex, st=st: 1.0 if ex.state == st else 0.0)
                ready.labels(name).set_function(lambda ex=ex: ex.ready_count)
                restarts.labels(name).set_function(lambda ex=ex: ex.restarts)
        if heavy is not None:
            g = Gauge("tensegrity_design_processes_in_flight", "Design requests queued or running in the design "
                      "processes", registry=self.registry)
            g.set_function(lambda: heavy.in_flight)
            g = Gauge("tensegrity_design_processes_killed", "Design processes killed at a deadline",
                      registry=self.registry)
            g.set_function(lambda: heavy.killed)
        if streams is not None:
            g = Gauge("tensegrity_stream_connections", "Control streams (/v1/control/stream) open",
                      registry=self.registry)
            g.set_function(lambda: streams.in_use)

    def failure(self, code: str) -> None:
        self.errors.labels(code).inc()
        if code in SOLVER_FAILURE_CODES:
            self.solver_failures.labels(code).inc()

    def render(self) -> bytes:
        return generate_latest(self.registry)


class MetricsMiddleware:
    """Pure ASGI middleware: counts and times every HTTP request by route template."""

    def __init__(self, app: ASGIApp, metrics: Metrics) -> None:
        self.app = app
        self.metrics = metrics

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        start = time.perf_counter()
        status = 500

        async def send_wrapper(message: Message) -> None:
            nonlocal status
            if message["type"] == "http.response.start":
                status = int(message["status"])
            await send(message)

        try:
            await self.app(scope, receive, send_wrapper)
        finally:
            route = scope.get("route")
            label = getattr(route, "path", None) or "<unmatched>"
            method = scope.get("method", "")
            if method not in _METHODS:
                method = "OTHER"    # arbitrary method tokens must not grow the label set
            self.metrics.requests.labels(method, label, str(status)).inc()
            self.metrics.latency.labels(method, label).observe(time.perf_counter() - start)
