"""Models of the stability atlas: ``POST /v1/atlas`` (a small grid inline), ``GET /v1/jobs/{id}/atlas`` (the
atlas of a finished atlas job) and the figure ``POST /v1/plots/atlas``.

The atlas (``tensegrity_opt.stability_atlas``) holds the tip at every target of a grid of deflections
``dx x dy`` and counts its equilibria (minima, saddles, maxima), then finds on the grid edges where the
least-energy branch switches and where stable branches end. The answer is ``StabilityAtlas.to_dict()``
(:class:`AtlasOut`). Same conventions as :mod:`service.schemas` (strict, no NaN, unknown fields refused);
a grid that is not strictly increasing is refused by the library (422 ``invalid_parameter`` on ``dx`` /
``dy``), a grid of more targets than the server's ``TENSEGRITY_MAX_ATLAS_TARGETS`` with 422
``atlas_too_large`` (JSON Schema cannot bound the product of two lengths; each axis is bounded here).
"""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field

import tensegrity_opt as to
from tensegrity_opt.analyses.paths.atlas import CROSSING_KINDS, AtlasTarget

from ..config import HARD_MAX_ATLAS_TARGETS
from .common import Deflection, Int, ManipulatorIn, RangeIn, list_or_range, outcome_model

__all__ = ["AtlasRange", "AtlasValues", "AtlasRequest", "AtlasOut", "AtlasTargetOut", "AtlasCrossingOut",
           "AtlasCurvesOut", "AtlasUnresolvedOut", "ATLAS_REQUEST_EXAMPLE"]

#: A bistable chain (a = 0.5: every segment has two wells), 3 x 3 targets: the example of every atlas request.
ATLAS_CHAIN = {"n": 3, "a": 0.5, "b": 1.0, "k": 1.0, "L0": 1.0}
ATLAS_REQUEST_EXAMPLE = {"manipulator": ATLAS_CHAIN, "dx": {"start": 0.2, "stop": 1.4, "num": 3},
                         "dy": {"start": -0.6, "stop": 0.6, "num": 3}, "method": "search", "edges": True}


class AtlasRange(RangeIn):
    """`num` evenly spaced deflections from `start` to `stop` inclusive (`start < stop` unless `num` is 1)."""

    start: Deflection
    stop: Deflection
    num: Int = Field(ge=1, le=HARD_MAX_ATLAS_TARGETS,
                     description=f"number of values (1..{HARD_MAX_ATLAS_TARGETS}; the grid's targets, num_dx x "
                                 "num_dy, at most the server's TENSEGRITY_MAX_ATLAS_TARGETS)")


def _axis(name: str) -> Any:
    return list_or_range(Deflection, AtlasRange, 1, HARD_MAX_ATLAS_TARGETS,
                         f"the grid's {name} values (tip deflection, length units), strictly increasing: a list or "
                         f"{{start, stop, num}} (1..{HARD_MAX_ATLAS_TARGETS} values)")


AtlasValues = _axis("dx")
DxValues = _axis("dx (along the chain; dx > 0 shortens it)")
DyValues = _axis("dy (sideways)")


class _AtlasFields(BaseModel):
    model_config = ConfigDict(strict=True, extra="forbid")

    manipulator: ManipulatorIn
    dx: DxValues
    dy: DyValues
    method: Literal["search", "homotopy"] = Field(
        "search", description="how each target's equilibria are found: `search` (multi-start Newton, complete in "
                              "practice, measured) or `homotopy` (PHCpack, certified counts; chains up to the "
                              "server's `homotopy_max_segments`)")
    edges: bool = Field(True, description="locate the switches and branch ends on the grid edges (false: the "
                                          "counts only)")


class AtlasRequest(_AtlasFields):
    """The stability atlas of the held tip over the grid `dx x dy` (`tensegrity_opt.stability_atlas`)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={"examples": [ATLAS_REQUEST_EXAMPLE]})


# ---------------------------------------------------------------------------- answers
class AtlasTargetOut(outcome_model(AtlasTarget)):
    """The equilibria with the tip held at one target (`AtlasTarget.to_dict()`)."""

    dx: float
    dy: float
    reachable: bool = Field(description="false beyond the chain's reach (every count 0)")
    count: int = Field(description="equilibria inside the physical range (-1: the solve failed, see error)")
    n_stable: int = Field(description="minima (-1: failed)")
    n_saddle: int
    n_maximum: int
    least_energy: float | None = Field(description="energy of the least-energy stable equilibrium (force x length)")
    least_signs: str | None = Field(description="its sign string (+/- per joint)")
    tie: bool = Field(description="two stable equilibria share the least energy (e.g. mirror images on dy = 0)")
    stable_q: list[list[float]] = Field(description="joint angles (rad) of each stable equilibrium, least energy "
                                                    "first")
    stable_energy: list[float]
    certified: bool = Field(description="the set is proven complete (homotopy, or a trivial case)")
    method: str
    error: str | None = Field(description="`code: message` where the target failed (counts -1), e.g. time_limit")


class AtlasCrossingOut(BaseModel):
    """A point on a grid edge where the least-energy branch switches or a stable branch ends."""

    kind: Literal[CROSSING_KINDS] = Field(description="switch (the least-energy branch changes: the Maxwell point "
                                                      "of the held tip) or branch_end (a stable branch loses "
                                                      "stability: the arm snaps)")
    dx: float
    dy: float
    edge: list[list[int]] = Field(description="grid indices [[i, j], [i, j]] (dx index, dy index) of the edge's "
                                              "ends (the same twice: a tie at a target)")
    fraction: float = Field(description="position along the edge from its first end (0) to its second (1)")
    energy: float
    q: list[float] = Field(description="the configuration there (rad)")
    force: list[float] = Field(description="the tip force there [fx, fy]")
    event: str = Field(description="branch_end: fold, branch_point or joint_limit; switch: maxwell")
    method: str = Field(description="moore_spence / test_function / limit (the event's), equal_energy, branch_end "
                                    "or tie")
    q_other: list[float] | None = Field(description="switch: the equilibrium on the other side (same energy)")
    force_other: list[float] | None
    null_vector: list[float] | None = Field(description="the mode of a fold or branch point")


class AtlasCurvesOut(BaseModel):
    """Segments `[[dx0, dy0], [dx1, dy1]]` joining the crossings of one kind inside each grid cell."""

    switch: list[list[list[float]]]
    branch_end: list[list[list[float]]]


class AtlasUnresolvedOut(BaseModel):
    edge: list[list[int]]
    reason: str


class AtlasOut(outcome_model(to.StabilityAtlas)):
    """`StabilityAtlas.to_dict()`: the per-target arrays are `[dy index][dx index]`, `null` where absent."""

    dx: list[float]
    dy: list[float]
    method: str
    seconds: float
    count: list[list[int]] = Field(description="equilibria per target (-1: failed)")
    n_stable: list[list[int]] = Field(description="stable equilibria per target (-1: failed)")
    n_saddle: list[list[int]]
    n_maximum: list[list[int]]
    least_energy: list[list[float | None]]
    least_signs: list[list[str | None]]
    certified: list[list[bool]]
    targets: list[list[AtlasTargetOut]]
    crossings: list[AtlasCrossingOut]
    curves: AtlasCurvesOut
    unresolved: list[AtlasUnresolvedOut] = Field(description="edges whose analysis failed, with the reason")
