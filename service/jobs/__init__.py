"""Persistent sweep jobs: the SQLite store (:mod:`.store`: jobs, points, leases, owners) and the runner
(:mod:`.runner`: the threads that run the jobs point by point, fairly, under a per-point time limit).

Wiring: :func:`service.main.create_app` builds the runner (``JobRunner(settings)``, reading ``TENSEGRITY_JOBS_*``),
keeps it in ``app.state.jobs``, and in its lifespan starts it after the executors and stops it at shutdown; the
routes of ``/v1/jobs`` (:mod:`service.api.routes.jobs`) call it. This package imports neither of them.
"""

from .runner import JobRunner
from .store import TERMINAL, JobFinished, JobNotFound, JobStore, JobsUnavailable, owner_hash

__all__ = ["JobRunner", "JobStore", "JobNotFound", "JobFinished", "JobsUnavailable", "TERMINAL", "owner_hash"]
