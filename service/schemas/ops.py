"""Models of the operational endpoints: ``/healthz``, ``/readyz``, ``/version`` (its limits and kernels)."""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, Field


class Health(BaseModel):
    status: Literal["ok"]


class JobsHealth(BaseModel):
    status: Literal["ok", "failing"] = Field(description="failing: the job store cannot be used now (the jobs "
                                                         "API answers 503 jobs_unavailable); it is retried")
    message: str | None = Field(None, description="what fails (never where on disk)")
    since: float | None = Field(None, description="epoch seconds of the first failure")


class ProcessesState(BaseModel):
    """Solver processes of one kind and where they stand."""

    state: Literal["up", "starting", "restarting", "down"] = Field(
        description="up: every process ready; starting: warming up; restarting: processes were lost and are "
                    "replaced (after a delay growing with each loss in a row, at most 30 s); down: stopped, or "
                    "this platform cannot start them")
    ready: int = Field(description="processes ready")
    workers: int = Field(description="processes configured")
    restarts: int = Field(description="processes started to replace lost ones since the server started")


class Ready(BaseModel):
    status: Literal["ready", "starting", "degraded"] = Field(
        description="ready (200); starting (503); degraded (503): the solvers answer but the job store fails "
                    "(see jobs)")
    workers: int
    queue_size: int
    in_flight: int
    jobs: JobsHealth
    processes: dict[Literal["fast", "design"], ProcessesState] = Field(
        default_factory=dict,
        description="the solver processes: fast (the short chains' bounded first try; while it is not up the solver "
                    "threads answer those requests, slower) and design (/v1/design/*, plans, stiffness shaping); "
                    "absent when the server has none")
    degraded: list[Literal["fast_path", "design_processes", "job_store"]] = Field(
        default_factory=list,
        description="what works degraded while the server answers: fast_path (the fast solver process is not up), "
                    "design_processes (the design processes are restarting or down: those requests get 503), "
                    "job_store (the job store fails: status degraded, the jobs API answers 503)")


class Limits(BaseModel):
    max_segments: int
    max_batch: int
    solve_timeout: float
    batch_timeout: float
    workers: int
    queue_size: int
    inline_max_segments: int
    inline_processes: int = Field(description="solver processes running the short chains' bounded search "
                                              "(service.execution); 0: the solver threads run it")
    max_body_bytes: int
    max_response_bytes: int = Field(description="largest JSON answer (422 response_too_large above)")
    max_curve_points: int
    max_path_points: int = Field(description="most points per branch of the path endpoints (422 too_many_points)")
    max_atlas_targets: int = Field(description="most targets of one /v1/atlas or /v1/plots/atlas (422 "
                                               "atlas_too_large; larger grids: a job with analysis atlas)")
    max_trajectory_steps: int = Field(description="most steps of one /v1/control/plan or /v1/control/simulate "
                                                  "trajectory (422 too_many_steps)")
    max_grid: int
    max_torque_points: int
    max_stream_connections: int = Field(description="control streams (WebSocket /v1/control/stream) open at once; "
                                                    "beyond, closed with 1013")
    stream_idle_timeout: float = Field(description="seconds a control stream may send nothing before it is "
                                                   "closed with 1001")


class KernelsOut(BaseModel):
    """How the compiled Newton kernels run in this server process (`tensegrity_opt.numerics.kernels`)."""

    compiler: str | None = Field(description="the C compiler used, by name and version (e.g. cc 12.2.0); null: "
                                             "none (kernels run in CasADi's VM)")
    max_segments: int = Field(description="chains up to this long have kernels")
    compiled: list[int] = Field(description="chain lengths loaded as compiled code so far")
    virtual_machine: list[int] = Field(description="chain lengths running in CasADi's virtual machine "
                                                   "(no compiler, or compiling failed: about 4x slower)")
    building: list[int] = Field(default_factory=list,
                                description="chain lengths whose kernels compile in the background; their requests "
                                            "are answered in the virtual machine meanwhile")


class VersionOut(BaseModel):
    service: str
    version: str
    library_version: str
    api: str
    auth: bool
    limits: Limits
    kernels: KernelsOut
