"""Request models of the figure endpoints (``POST /v1/plots/<kind>``), same conventions as :mod:`service.schemas`.

Requests are strict (JSON numbers only, no NaN/Infinity, unknown fields refused). Every request
may carry ``format`` (``"png"`` or ``"svg"``; when absent the ``Accept`` header decides, PNG by
default) and ``dpi`` (PNG resolution, default ``tensegrity_opt.applications.plots.DPI``, the command line's
too). The answers are images, not JSON.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal, Union

from pydantic import BaseModel, BeforeValidator, ConfigDict, Discriminator, Field, Tag

from tensegrity_opt.applications.plots.paths import BRANCH_DEFAULT_X, BRANCH_DEFAULT_Y, BRANCH_QUANTITIES
from tensegrity_opt.applications.plots.style import DPI

from . import common as s
from .atlas import ATLAS_REQUEST_EXAMPLE, _AtlasFields
from .control import PLAN_REQUEST_EXAMPLE, SIMULATION_REQUEST_EXAMPLE, _PlanFields, _SimulationFields
from .curves import CurveDeflections
from .design import DesignManipulatorIn
from .modes import MASSIVE_CHAIN, _ModesFields
from .paths import (
    MAX_BRANCHES,
    MAX_DEPTH,
    StabilityBoundaryRequest,
    _BranchFields,
    _ImperfectionFields,
    _LimitLoadFields,
)

#: Points per axis of a landscape figure by default (the data endpoint /v1/energy-landscape: 101).
LANDSCAPE_FIGURE_GRID = 61
#: Most points per axis of a critical-load map (each point is one eigen-solve).
MAX_MAP_AXIS = 41
#: Most segments compared in one torque figure.
MAX_TORQUE_SEGMENTS = 12
#: Most points per torque curve.
MAX_TORQUE_CURVE_POINTS = 2001
#: Most equilibrium panels in one shapes figure.
MAX_PANELS = 24
#: Orientations of ``/v1/plots/holding`` at most (each a rest configuration and a holding design).
MAX_GRAVITY_DIRECTIONS = 72
#: Its example chain: six segments in a vertical plane (the worked example of ``docs/model.md``).
UPRIGHT_ARM = {"n": 6, "a": 0.04, "b": 0.05, "k": 3000.0, "L0": 0.05, "mass": 0.05, "payload": 0.1}
#: Largest design value a map axis accepts (lengths and stiffnesses alike).
MIN_DESIGN_VALUE = 1.0e-6
MAX_DESIGN_VALUE = 1.0e6

ImageFormat = Literal["png", "svg"]
Dpi = Annotated[int, Field(ge=30, le=200, description=f"PNG resolution in dots per inch (30..200; default {DPI}, "
                                                       "the command line's too)"),
              BeforeValidator(s.integral)]
DesignParam = Literal["a", "b", "k", "L0"]
DesignValue = Annotated[float, Field(ge=MIN_DESIGN_VALUE, le=MAX_DESIGN_VALUE, allow_inf_nan=False)]


class _PlotRequest(BaseModel):
    format: ImageFormat | None = Field(
        None, description='"png" or "svg"; when absent the Accept header decides (image/svg+xml or image/png), '
                          "PNG by default")
    dpi: Dpi = DPI


class MapValuesRange(s.RangeIn):
    start: DesignValue
    stop: DesignValue
    num: s.Int = Field(ge=2, le=MAX_MAP_AXIS, description=f"number of values (2..{MAX_MAP_AXIS})")


DesignValues = s.list_or_range(DesignValue, MapValuesRange, 2, MAX_MAP_AXIS,
                               f"values of the parameter (> 0, strictly increasing or decreasing): a list or "
                               f"{{start, stop, num}} (2..{MAX_MAP_AXIS} values)")


class PlotCurveRequest(_PlotRequest):
    """Force-deflection curves Fx, Fy against dx with their jumps (Fig. 6)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": s.PAPER_CHAIN, "dx": {"start": 0.0, "stop": 2.0, "num": 41}, "dy": 0.0,
                      "branch": "stable"}]})

    manipulator: s.ManipulatorIn
    dx: CurveDeflections
    dy: s.Deflection = Field(0.0, description="tip deflection along y, the same at every point")
    branch: Literal["stable", "all"] = Field(
        "stable", description='"all" also draws every branch found at the first deflected point (unstable dashed)')


class PlotLandscapeRequest(_PlotRequest):
    """Energy contours E(q_i, q_j) with every equilibrium marked (n = 4, Figs. 4-5)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": s.PAPER_CHAIN, "dx": 0.1, "dy": 0.0, "pair": [0, 3]}]})

    manipulator: s.ManipulatorIn
    dx: s.TipDx
    dy: s.TipDy = 0.0
    pair: list[Annotated[int, Field(ge=0, le=3), BeforeValidator(s.integral)]] = Field(
        [0, 3], min_length=2, max_length=2, description="the two grid joints, 0-based and different")
    grid: s.Int = Field(LANDSCAPE_FIGURE_GRID, ge=2, le=s.MAX_GRID, description=(
        f"points per axis (2..{s.MAX_GRID}); default {LANDSCAPE_FIGURE_GRID}: the contours of the smooth energy "
        "at that many points and the region's boundary on a grid four times finer (a finer grid changes little "
        "that shows and costs time)"))
    span: Annotated[float, Field(gt=0, le=s.MAX_ANGLE, allow_inf_nan=False)] | None = Field(
        None, description="half-width of both axes (rad); default: the reachable region of the landscape")


class PlotShapesRequest(_PlotRequest):
    """The chain drawn in every equilibrium, coloured by stability (Table 2's shapes)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": s.PAPER_CHAIN, "dx": 0.1, "dy": 0.0}]})

    manipulator: s.ManipulatorIn
    dx: s.TipDx
    dy: s.TipDy = 0.0
    max_panels: s.Int = Field(MAX_PANELS, ge=1, le=MAX_PANELS,
                            description=f"draw at most this many equilibria, the lowest energies (1..{MAX_PANELS})")
    spring_colors: Literal["state", "tension"] = Field(
        "state", description="`state`: taut springs solid, pushing ones (linear law, shorter than their rest length) "
                             "red dashed, slack ones grey dotted; `tension`: every spring coloured by its force")


class PlotModesRequest(_PlotRequest, _ModesFields):
    """The vibration modes of an equilibrium drawn: the chain displaced along each mode both ways."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": MASSIVE_CHAIN, "dx": 1.0, "dy": 0.0}]})

    excursion: float = Field(0.3, gt=0.0, le=3.0, allow_inf_nan=False,
                             description="each mode drawn with its largest joint excursion this many rad")
    max_panels: s.Int = Field(8, ge=1, le=MAX_PANELS, description=f"draw at most this many modes, the lowest "
                                                                  f"(1..{MAX_PANELS})")


class PlotHoldingRequest(_PlotRequest):
    """The chain under its weight as its base turns: its sagged shapes and the least design holding it."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": UPRIGHT_ARM, "max_angle": 0.05, "directions": 16}]})

    manipulator: DesignManipulatorIn
    directions: s.Int = Field(12, ge=1, le=MAX_GRAVITY_DIRECTIONS,
                              description=f"gravity directions (base orientations) over a full turn "
                                          f"(1..{MAX_GRAVITY_DIRECTIONS})")
    vary: list[Literal["k", "L0"]] = Field(["k"], min_length=1, max_length=1,
                                           description="what the holding design varies (one of k, L0)")
    margin: Annotated[float, Field(ge=0, le=s.MAX_STIFFNESS, allow_inf_nan=False)] = Field(
        1e-3, description=s.MARGIN_DOC)
    max_angle: Annotated[float, Field(gt=0, lt=3.141592653589793, allow_inf_nan=False)] | None = Field(
        None, description="the sag allowed (rad); default anywhere in range")


class PlotAngleRange(s.RangeIn):
    """`num` angles (rad, |angle| <= 2 pi) from `start` to `stop` inclusive."""

    start: s.Angle
    stop: s.Angle
    num: s.Int = Field(ge=2, le=MAX_TORQUE_CURVE_POINTS, description=f"number of points (2..{MAX_TORQUE_CURVE_POINTS})")


class PlotTorqueRequest(_PlotRequest):
    """Torque-angle curves M(q) of one or several segments (Fig. 2)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"segments": [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": 0.5},
                                   {"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.5}]}]})

    segments: list[s.SegmentIn] = Field(min_length=1, max_length=MAX_TORQUE_SEGMENTS,
                                        description=f"the segments compared (1..{MAX_TORQUE_SEGMENTS})")
    q: PlotAngleRange | None = Field(
        None, description="angles {start, stop, num} (rad) for every curve; default: each segment's physical range")
    num: s.Int = Field(401, ge=2, le=MAX_TORQUE_CURVE_POINTS,
                     description="points per curve over each segment's physical range (when q is absent)")


class PlotMapRequest(_PlotRequest):
    """Critical load over two design parameters, applied uniformly to every segment."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": s.PAPER_CHAIN, "param_x": "k", "values_x": {"start": 0.5, "stop": 2.0, "num": 16},
                      "param_y": "L0", "values_y": {"start": 0.5, "stop": 2.5, "num": 21}, "boundary": "guided"}]})

    manipulator: s.ManipulatorIn
    param_x: DesignParam = Field(description="horizontal axis: a, b, k or L0")
    values_x: DesignValues
    param_y: DesignParam = Field(description="vertical axis: a, b, k or L0 (not param_x)")
    values_y: DesignValues
    boundary: Literal["guided", "free"] = Field(
        "guided", description='"guided": tip held at dy = 0 (the paper); "free": cantilever')


# ---------------------------------------------------------------------------- loading paths
#: Quantities a branch diagram puts on an axis (``tensegrity_opt.applications.plots.BRANCH_QUANTITIES``)
#: and ``q1``, ``q2``, ... (a joint angle, 1-based).
BranchQuantity = Annotated[str, Field(pattern=rf"^({'|'.join(BRANCH_QUANTITIES)}|q[1-9][0-9]{{0,2}})$")]


class PlotBranchRequest(_PlotRequest, _BranchFields):
    """A branch diagram: one branch (`/v1/branch`), or with `depth` the bifurcation diagram
    (`/v1/bifurcation-diagram`), drawn `y` against `x` in pieces of constant Morse index."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": s.PAPER_CHAIN, "start": {"q": [0.0, 0.0, 0.0, 0.0]},
                      "control": {"kind": "guided", "direction": [-1.0, 0.0]}, "t_max": 2.0}]})

    stop_at: Literal["stability_loss", "event"] | None = Field(
        None, description="one branch only: stop after the first event where stability is lost, or any event")
    orientation: Annotated[Literal[1, -1], BeforeValidator(s.integral)] = Field(
        1, description="one branch only: leave the start with t increasing (1) or decreasing (-1)")
    depth: Annotated[int, Field(ge=0, le=MAX_DEPTH), BeforeValidator(s.integral)] | None = Field(
        None, description=f"null: one branch; a number: the bifurcation diagram to this many switches (0..{MAX_DEPTH})")
    max_branches: s.Int = Field(24, ge=1, le=MAX_BRANCHES, description="with depth: at most this many branches")
    x: BranchQuantity = Field(BRANCH_DEFAULT_X, description=(
        "horizontal axis: t, fx, fy, dx, dy, x, y (tip), u (tip displacement along the control direction), phi (end "
        "angle q1 + ... + qn), energy, s (arclength) or q1..qn"))
    y: BranchQuantity = Field(BRANCH_DEFAULT_Y, description=(
        "vertical axis, as x; default phi against t: a bifurcation diagram, the axis of t cut a margin past the "
        "events"))


class PlotLimitLoadRequest(_PlotRequest, _LimitLoadFields):
    """The load path of `/v1/limit-load`, the limit point and the quasi-buckling load marked; at a bifurcation
    also the buckled arms leaving it (load against the end angle), else load against the tip displacement along
    the load."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": s.PAPER_CHAIN, "direction": [-1.0, 0.0], "boundary": "guided",
                      "start": {"q": [0.0, 0.0, 0.0, 0.0]}}]})

    arms: bool = Field(True, description=(
        "at a bifurcation, also draw the buckled arms leaving it (to their first fold or joint limit) against the "
        "end angle phi; false: the path only, against the tip displacement along the load"))


class PlotImperfectionRequest(_PlotRequest, _ImperfectionFields):
    """The imperfection-sensitivity curve of `/v1/imperfection-sensitivity`: the limit load against the amplitude,
    a marker per kind, the perfect chain's limit load as a line, the fitted small-imperfection law dashed."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": s.PAPER_CHAIN, "amplitudes": [0.0, 0.01, 0.02851, 0.061]}]})


class PlotBoundaryRequest(_PlotRequest, StabilityBoundaryRequest):
    """The stability boundary of `/v1/stability-boundary`: critical t against p, cusps marked."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": s.PAPER_CHAIN, "control": {"kind": "guided", "direction": [-1.0, 0.0]},
                      "parameter": "asymmetry", "p_min": -0.1, "p_max": 0.1}]})


# ---------------------------------------------------------------------------- control
class PlotPlanRequest(_PlotRequest, _PlanFields):
    """The plan of `/v1/control/plan` computed for the figure (the same body): rest lengths, tip path, margin."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={"examples": [PLAN_REQUEST_EXAMPLE]})


class PlotSimulationRequest(_PlotRequest, _SimulationFields):
    """The simulation of `/v1/control/simulate` computed for the figure (the same body): the hysteresis loop."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [SIMULATION_REQUEST_EXAMPLE]})


# ---------------------------------------------------------------------------- stability atlas
class PlotAtlasGridRequest(_PlotRequest, _AtlasFields):
    """The atlas of `/v1/atlas` computed for the figure (the same body)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={"examples": [ATLAS_REQUEST_EXAMPLE]})


class PlotAtlasJobRequest(_PlotRequest):
    """The atlas of a finished atlas job (`GET /v1/jobs/{id}/atlas`)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"job": "3f0c9a4e1b7d4c2a9e8f6d5c4b3a2910"}]})

    job: str = Field(min_length=1, max_length=64, description="the id of a finished job with analysis atlas over a "
                                                              "grid in dx and dy")
    edges: bool = Field(True, description="locate the switches and branch ends on the grid edges (false: the "
                                          "counts only)")


def _atlas_form(v: Any) -> str:
    return "<job>" if isinstance(v, PlotAtlasJobRequest) or (isinstance(v, dict) and "job" in v) else "<grid>"


PlotAtlasRequest = Annotated[
    Union[Annotated[PlotAtlasGridRequest, Tag("<grid>")], Annotated[PlotAtlasJobRequest, Tag("<job>")]],
    Discriminator(_atlas_form),
    Field(description='the body of /v1/atlas (plus format, dpi), or {"job": id} for a finished atlas job'),
]
