"""Request and response models of the jobs API (``/v1/jobs``): a sweep spec in, job status and rows out.

The request mirrors :mod:`tensegrity_opt.applications.sweeps`'s spec (``analysis``, ``manipulator``, ``grid`` |
``points``, ``options``). The schema checks types and ranges; the library then checks what
depends on the analysis (which parameters it uses, dx/dy and load never together, ...) and the
server its limits. Every refusal names the field (``grid.dx[2]``, ``points[3].load``, ...).
The order of the ``grid`` keys is kept: it is the nesting order of the cartesian product
(first key slowest). The base chain is uniform (``{n, a, b, k, L0}``, which the points may vary) or given
segment by segment (``{"segments": [...]}``, pre-bent or heterogeneous; the points then vary only ``dx``,
``dy``, ``load``), never both.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal, Union

from pydantic import (
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Discriminator,
    Field,
    PrivateAttr,
    RootModel,
    Tag,
    model_validator,
)

from ..config import HARD_MAX_SEGMENTS
from .common import (
    INERTIA_DOC,
    MASS_DOC,
    Deflection,
    Finite,
    ForceValue,
    Length,
    LengthPair,
    Mass,
    SegmentIn,
    SpringLaw,
    Stiff,
    StiffPair,
    TotalLength,
    _ChainLoads,
    bounds_of,
    integral,
)

__all__ = ["HARD_MAX_JOB_POINTS", "MAX_GRID_VALUES", "JobSpec", "SweepManipulator", "SweepUniformManipulator",
           "SweepSegmentedManipulator", "JobCreated", "JobSummary", "JobOut", "JobResults",
           "JobList", "JobStatus", "JobAnalysis", "SPEC_EXAMPLES", "JOB_EXAMPLE", "RESULTS_EXAMPLE", "CSV_EXAMPLE"]

#: Schema caps (the server's ``TENSEGRITY_JOBS_MAX_POINTS`` can only be tighter).
HARD_MAX_JOB_POINTS = 100_000
MAX_GRID_VALUES = 10_000

_STRICT = ConfigDict(strict=True, extra="forbid")

Analysis = Literal["buckling", "equilibrium", "equilibria_count", "stiffness", "design", "atlas"]
#: What a job computes: a sweep's analysis, or ``figure`` (a figure as a job, ``POST /v1/plots/{kind}/job``).
JobAnalysis = Literal[Analysis, "figure"]
JobStatus = Literal["queued", "running", "done", "failed", "cancelled", "interrupted"]
DesignVariable = Literal["a", "b", "k", "L0"]
Segments = Annotated[int, Field(ge=1, le=HARD_MAX_SEGMENTS), BeforeValidator(integral)]
Load = Annotated[list[ForceValue], Field(min_length=2, max_length=2, description="tip force [fx, fy]")]


#: The analyses that use a grid's tip deflections, and its tip forces.
_DEFLECTED = "(equilibrium, stiffness, equilibria_count, atlas)"
_LOADED = "(equilibrium, stiffness; not with dx/dy)"


def _values(item: Any, what: str) -> Any:
    return Annotated[list[item], Field(min_length=1, max_length=MAX_GRID_VALUES, description=what)]


class SweepUniformManipulator(_ChainLoads):
    """The uniform base chain; a point's own n, a, b, k, L0 replace these."""

    model_config = _STRICT

    n: Segments = Field(4, description="number of segments")
    a: Length = Field(1.0, description="triangle half-height")
    b: Length = Field(1.0, description="triangle half-length")
    k: StiffPair = 1.0
    L0: LengthPair = 1.0
    spring: SpringLaw = "linear"
    mass: Mass = Field(0.0, description=MASS_DOC)
    inertia: Mass = Field(0.0, description=INERTIA_DOC)


class SweepSegmentedManipulator(_ChainLoads):
    """The base chain segment by segment, base to tip (pre-bent: `L0` the pair `[L1_0, L2_0]`; heterogeneous):
    fixed, so the points vary only dx, dy, load."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={"examples": [{"segments": [
        {"a": 1.0, "b": 1.0, "k": 1.0, "L0": [1.05, 0.95]}, {"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}]}]})

    segments: list[SegmentIn] = Field(min_length=1, max_length=HARD_MAX_SEGMENTS,
                                      description="segments from base to tip ({a, b, k, L0, spring}; k and L0 a "
                                                  "number or the pair of the two springs)")


def _sweep_manipulator_kind(v: Any) -> str:
    if isinstance(v, SweepSegmentedManipulator) or (isinstance(v, dict) and "segments" in v):
        return "<segments>"
    return "<uniform>"


class SweepManipulator(RootModel[Annotated[
        Union[Annotated[SweepUniformManipulator, Tag("<uniform>")],
              Annotated[SweepSegmentedManipulator, Tag("<segments>")]],
        Discriminator(_sweep_manipulator_kind)]]):
    """The base chain: `{n, a, b, k, L0}` (uniform; the points may vary these) or `{"segments": [...]}` (given
    segment by segment; the points vary only dx, dy, load), not both."""

    model_config = ConfigDict(strict=True)

    def to_spec(self) -> dict[str, Any]:
        """The library's ``manipulator`` of the spec: the five uniform keys, or ``{"segments": [...]}`` only;
        ``spring`` only where it is not the default ``"linear"`` (as :meth:`tensegrity_opt.Manipulator.to_dict`)."""
        d = self.root.model_dump()
        for part in d.get("segments", [d]):
            if part.get("spring") == "linear":
                del part["spring"]
        return d


class SweepGrid(BaseModel):
    """``{parameter: [values]}``: the cartesian product, in the order the keys are given (first slowest)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={"minProperties": 1})

    n: _values(Segments, "segment counts") = None  # type: ignore[assignment]
    a: _values(Length, "triangle half-heights") = None  # type: ignore[assignment]
    b: _values(Length, "triangle half-lengths") = None  # type: ignore[assignment]
    k: _values(Stiff, "spring stiffnesses") = None  # type: ignore[assignment]
    L0: _values(Length, "spring rest lengths") = None  # type: ignore[assignment]
    dx: _values(Deflection, f"tip deflections along x {_DEFLECTED}") = None  # type: ignore[assignment]
    dy: _values(Deflection, f"tip deflections along y {_DEFLECTED}") = None  # type: ignore[assignment]
    load: _values(Load, f"tip forces [fx, fy] {_LOADED}") = None  # type: ignore[assignment]

    _order: list[str] = PrivateAttr(default_factory=list)

    @model_validator(mode="wrap")
    @classmethod
    def _keep_order(cls, data: Any, handler: Any) -> Any:
        model = handler(data)
        if isinstance(data, dict):
            model._order = [k for k in data if k in cls.model_fields]
        return model

    def ordered(self) -> dict[str, list[Any]]:
        """The given parameters in the order of the request."""
        order = self._order or [k for k in type(self).model_fields if k in self.model_fields_set]
        return {k: getattr(self, k) for k in order if getattr(self, k) is not None}


class SweepPoint(BaseModel):
    """One point: any of the parameters (the rest from the base chain; dx = dy = 0)."""

    model_config = _STRICT

    n: Segments = None  # type: ignore[assignment]
    a: Length = None  # type: ignore[assignment]
    b: Length = None  # type: ignore[assignment]
    k: Stiff = None  # type: ignore[assignment]
    L0: Length = None  # type: ignore[assignment]
    dx: Deflection = None  # type: ignore[assignment]
    dy: Deflection = None  # type: ignore[assignment]
    load: Load = None  # type: ignore[assignment]


BoundValue = Union[Finite, Annotated[list[Finite], Field(min_length=1, max_length=HARD_MAX_SEGMENTS)]]
BoundPair = bounds_of(BoundValue, "SweepBoundsIn", "bounds (each side a number, or one per segment)",
                      object_doc="Bounds {lo, hi}, each a number or one per segment (the object form of [lo, hi]).")
TensionPair = bounds_of(Finite, "SweepTensionIn", "[T_min, T_max] on the spring preloads at straight")


class SweepOptions(BaseModel):
    """``boundary`` for buckling and design; ``method`` for atlas; the rest are ``maximize_critical_force``'s
    (design only)."""

    model_config = _STRICT

    boundary: Literal["guided", "free"] = Field(  # type: ignore[assignment]
        None, description="tip boundary condition (default guided)")
    method: Literal["search", "homotopy"] = Field(  # type: ignore[assignment]
        None, description="atlas only: how each target's equilibria are found, search (default) or homotopy "
                          "(certified counts; chains up to the server's homotopy_max_segments)")
    vary: list[DesignVariable] = Field(None, min_length=1, max_length=4,  # type: ignore[assignment]
                                       description="design: per-segment variables to optimise (default [k])")
    bounds: dict[DesignVariable, BoundPair] = Field(  # type: ignore[assignment]
        None, description="design: {name: [lo, hi] or {lo, hi}}, numbers or per-segment lists")
    budget: dict[DesignVariable, Finite] = Field(  # type: ignore[assignment]
        None, description="design: {name: total}, sum over the segments <= total")
    total_length: TotalLength = Field(  # type: ignore[assignment]
        None, description="design: total length 2 sum(b) (true: keep the initial one)")
    tension: TensionPair = Field(  # type: ignore[assignment]
        None, description="design: [T_min, T_max] (or {lo, hi}) on the spring preloads at straight")
    K_min: Finite = Field(  # type: ignore[assignment]
        None, description="design: lower bound on every joint stiffness")


class JobSpec(BaseModel):
    """A sweep spec: one analysis over a grid or a list of points (exactly one of them)."""

    model_config = _STRICT

    analysis: Analysis = Field(description="what to compute at each point")
    manipulator: SweepManipulator = Field(
        default_factory=lambda: SweepManipulator(SweepUniformManipulator()),
        description="the base chain: uniform {n, a, b, k, L0} or {segments: [...]}")
    grid: SweepGrid = Field(None, description="cartesian product {parameter: [values]}")  # type: ignore[assignment]
    points: list[SweepPoint] = Field(  # type: ignore[assignment]
        None, min_length=1, max_length=HARD_MAX_JOB_POINTS, description="explicit list of points")
    options: SweepOptions = Field(None, description="analysis options")  # type: ignore[assignment]

    def to_spec(self) -> dict[str, Any]:
        """The library's spec (``tensegrity_opt.applications.sweeps``), grid order kept."""
        out: dict[str, Any] = {"analysis": self.analysis, "manipulator": self.manipulator.to_spec()}
        if self.grid is not None:
            out["grid"] = self.grid.ordered()
        if self.points is not None:
            out["points"] = [p.model_dump(exclude_none=True) for p in self.points]
        if self.options is not None:
            out["options"] = self.options.model_dump(exclude_none=True)
        return out


# ---------------------------------------------------------------------------- answers
class JobCreated(BaseModel):
    id: str = Field(description="job id (use it in /v1/jobs/{id})")
    status: JobStatus
    total: int = Field(description="number of points (a figure job: its steps)")
    analysis: JobAnalysis


class JobSummary(BaseModel):
    id: str
    status: JobStatus = Field(description="queued | running | done | failed | cancelled | interrupted")
    analysis: JobAnalysis = Field(description="the sweep's analysis, or figure (a figure as a job)")
    total: int = Field(description="points in the sweep (a figure job: its steps)")
    done: int = Field(description="points finished and stored (failed points included)")
    failed: int = Field(description="finished points whose row has an error")
    progress: float = Field(description="done / total")
    runs: int = Field(description="times the job was started (> 1: resumed after a server restart)")
    created_at: str = Field(description="ISO 8601, UTC")
    started_at: str | None = None
    finished_at: str | None = None
    message: str | None = Field(None, description="why the job failed, was cancelled or interrupted")


class JobOut(JobSummary):
    spec: dict[str, Any] = Field(description="the normalised sweep spec (a figure job: analysis, kind, format and "
                                             "the figure's request)")
    columns: list[str] = Field(description="column order of the rows")
    results: list[dict[str, Any]] = Field(description="finished rows so far, by index (a page: offset, limit)")
    offset: int
    next_offset: int | None = Field(None, description="offset of the next page of rows, when there is one")


class JobResults(BaseModel):
    id: str
    status: JobStatus
    complete: bool = Field(description="every point is done")
    total: int
    done: int = Field(description="rows there are (finished points, failed ones included)")
    columns: list[str]
    offset: int = Field(description="index in the rows of the first row of this page")
    limit: int = Field(description="most rows in this page (the one asked for, cut to the server's maximum)")
    next_offset: int | None = Field(None, description="offset of the next page; null on the last one")
    rows: list[dict[str, Any]] = Field(description="a page of rows, by index: index, the swept "
                                                   "parameters, the analysis's columns, error")


class JobList(BaseModel):
    jobs: list[JobSummary]


# ---------------------------------------------------------------------------- examples
SPEC_EXAMPLES = {
    "buckling_map": {"summary": "critical force over n x k (grid)", "value": {
        "analysis": "buckling", "manipulator": {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0},
        "grid": {"n": [3, 4, 5], "k": [0.5, 1.0, 2.0]}, "options": {"boundary": "guided"}}},
    "equilibrium_points": {"summary": "equilibria at listed deflections and a tip force (points)", "value": {
        "analysis": "equilibrium", "manipulator": {"n": 4},
        "points": [{"dx": 0.1}, {"dx": 0.2, "dy": 0.05}, {"load": [0.2, 0.1]}]}},
    "design": {"summary": "strongest chain per n (design)", "value": {
        "analysis": "design", "grid": {"n": [3, 4]},
        "options": {"vary": ["k"], "bounds": {"k": [0.2, 5.0]}, "budget": {"k": 4.0}}}},
    "atlas": {"summary": "stability atlas of a bistable chain over dx x dy (then GET /v1/jobs/{id}/atlas)", "value": {
        "analysis": "atlas", "manipulator": {"n": 3, "a": 0.5, "b": 1.0, "k": 1.0, "L0": 1.0},
        "grid": {"dx": [0.2, 0.8, 1.4], "dy": [-0.6, 0.0, 0.6]}, "options": {"method": "search"}}},
    "atlas_pre_bent": {"summary": "atlas of a pre-bent chain given by its segments", "value": {
        "analysis": "atlas", "manipulator": {"segments": [
            {"a": 1.0, "b": 1.0, "k": 1.0, "L0": [1.05, 0.95]}, {"a": 1.0, "b": 1.0, "k": 1.0, "L0": [1.05, 0.95]},
            {"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}]},
        "grid": {"dx": [0.2, 0.8], "dy": [0.0, 0.4]}}},
}

_ROW = {"index": 0, "n": 3, "k": 0.5, "critical_force": -0.470871, "load2": 0.929129, "loads": [0.470871, 0.929129],
        "mode_shape": "U", "mode_signs": "+--", "mode_q": [0.501331, -0.643451, -0.576303], "error": None}
_COLUMNS = ["index", "n", "k", "critical_force", "load2", "loads", "mode_shape", "mode_signs", "mode_q", "error"]

JOB_EXAMPLE = {
    "id": "3f0c9a4e1b7d4c2a9e8f6d5c4b3a2910", "status": "running", "analysis": "buckling", "total": 9, "done": 1,
    "failed": 0, "progress": 0.111111, "runs": 1, "created_at": "2025-01-01T12:00:00.000Z",
    "started_at": "2025-01-01T12:00:00.010Z", "finished_at": None, "message": None,
    "spec": {**SPEC_EXAMPLES["buckling_map"]["value"]}, "columns": _COLUMNS, "results": [_ROW], "offset": 0,
    "next_offset": None,
}
RESULTS_EXAMPLE = {"id": JOB_EXAMPLE["id"], "status": "done", "complete": True, "total": 9, "done": 9,
                   "columns": _COLUMNS, "offset": 0, "limit": 1, "next_offset": 1, "rows": [_ROW]}
CSV_EXAMPLE = ("index,n,k,critical_force,load2,loads,mode_shape,mode_signs,mode_q,error\n"
               '0,3,0.5,-0.470871,0.929129,"[0.470871, 0.929129]",U,+--,"[0.501331, -0.643451, -0.576303]",\n')
