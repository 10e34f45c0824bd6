"""Messages of the control stream (``/v1/control/stream``, a WebSocket; ``docs/stream.md``).

The client's messages are JSON objects with a ``type``: one ``open`` (the chain, the ``mode`` and its
options), then any number of ``step`` messages whose fields depend on the mode. They are validated as
strictly as the REST requests (numbers must be JSON numbers, NaN/Infinity refused, unknown fields
refused) with the same bounds, and refused with the same ``validation_error`` body naming the field.

The WebSocket is not in the OpenAPI document (OpenAPI does not describe WebSockets); these models are
the protocol's schema.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field

from tensegrity_opt.analyses.design.preload_control import ON_INFEASIBLE

from ..config import HARD_MAX_SEGMENTS
from .common import (
    _STRICT,
    MARGIN_DOC,
    MAX_STIFFNESS,
    TAUT_DOC,
    Angle,
    Deflection,
    ForceValue,
    Length,
    ManipulatorIn,
)
from .control import RestLengthBoundsIn as StreamBounds
from .control import Seconds
from .design import DesignManipulatorIn

#: The modes of a stream.
MODES = ("track", "preloads", "inverse")

Pair = Annotated[list[ForceValue], Field(min_length=2, max_length=2)]
Point = Annotated[list[Deflection], Field(min_length=2, max_length=2)]
RestPair = Annotated[list[Length], Field(min_length=2, max_length=2)]
Positive = Annotated[float, Field(gt=0.0, le=MAX_STIFFNESS, allow_inf_nan=False)]


# ---------------------------------------------------------------------------- dispatch
class Envelope(BaseModel):
    """What every client message has: its ``type`` (the rest is read by the model of that type)."""

    model_config = ConfigDict(strict=True, extra="ignore")
    type: Literal["open", "step"] = Field(description="`open` (first message) or `step`")


class OpenEnvelope(BaseModel):
    """What every ``open`` has: its ``mode`` (the rest is read by the model of that mode)."""

    model_config = ConfigDict(strict=True, extra="ignore")
    type: Literal["open"]
    mode: Literal["track", "preloads", "inverse"] = Field(
        description="`track`: tip deflection targets (Tracker); `preloads`: rest-length commands, the forward "
                    "equilibrium under the load (PreloadFollower); `inverse`: tip poses, the rest lengths "
                    "(PreloadController)")


# ---------------------------------------------------------------------------- open
class _Open(BaseModel):
    model_config = _STRICT
    type: Literal["open"]
    manipulator: ManipulatorIn


class TrackOpen(_Open):
    """Follow the equilibrium as the held tip moves (``tensegrity_opt.analyses.paths.continuation.Tracker``)."""

    mode: Literal["track"]
    jump: bool = Field(True, description="where the followed branch ends or turns unstable, re-solve globally "
                                         "(what the chain does: a `jump` event); false: stay on the branch "
                                         "while it exists (then `solver_failed`, status `branch_ended`)")


class PreloadsOpen(_Open):
    """Rest-length commands: the equilibrium the arm reaches along each command's transition (the last command and
    load moving linearly to the new ones, the branch followed, a `snap` event where it folds;
    ``tensegrity_opt.PreloadFollower``)."""

    mode: Literal["preloads"]
    load: Pair = Field([0.0, 0.0], description="dead tip load [fx, fy] (force units); a step may give its own")
    start: list[Angle] | None = Field(
        None, max_length=HARD_MAX_SEGMENTS,
        description="the configuration the first step starts from (rad, n angles); default: the equilibrium "
                    "under `load` reached from the least-energy rest configuration of `manipulator`")


class InverseOpen(_Open):
    """Tip poses: the rest lengths step by step (``tensegrity_opt.PreloadController``). Chains of at most 60
    segments, as ``/v1/design/preloads`` (its IPOPT fallback is that design NLP)."""

    mode: Literal["inverse"]
    manipulator: DesignManipulatorIn
    load: Pair = Field([0.0, 0.0], description="dead tip load [fx, fy] (force units); a step may give its own")
    start: list[Angle] | None = Field(
        None, max_length=HARD_MAX_SEGMENTS,
        description="the start configuration (rad, n angles) with `manipulator`'s rest lengths under `load`; "
                    "default: reached from the least-energy rest configuration")
    bounds: StreamBounds | None = Field(
        None, description="actuator bounds [lo, hi] (or {lo, hi}) on every rest length; default [0.1 b_min, 4 b_max]")
    rest_lengths0: list[RestPair] | None = Field(
        None, max_length=HARD_MAX_SEGMENTS,
        description="the arm's current rest lengths [L1_0, L2_0] per segment (n pairs, inside `bounds`): the start "
                    "is an equilibrium with them and the first step's change is measured from them; default the "
                    "manipulator's own")
    rate_limit: Positive | None = Field(
        None, description="largest speed of each rest length (length units per second): a step dt seconds after the "
                          "last changes each by at most rate_limit * dt; needs a time base (`dt` here, or each "
                          "step's `time` or `dt`)")
    dt: Seconds | None = Field(None, description="the time between steps (seconds, > 0) for a step that gives "
                                                 "neither `time` nor `dt`")
    margin: Annotated[float, Field(ge=0, le=MAX_STIFFNESS, allow_inf_nan=False)] = Field(1e-3, description=MARGIN_DOC)
    objective: Literal["change", "margin", "energy"] = Field(
        "change", description="`change`: least change from the last step (Newton, IPOPT where a bound is "
                              "active); `margin`: largest margin; `energy`: least spring energy (IPOPT)")
    weights: list[Annotated[list[Positive], Field(min_length=2, max_length=2)]] | None = Field(
        None, max_length=HARD_MAX_SEGMENTS, description="weights [w1, w2] per segment of each rest length's "
                                                        "change (objective change; default 1)")
    on_infeasible: Literal[ON_INFEASIBLE] = Field(
        "hold", description="what an infeasible step commands: `hold` the previous command, `approach` the rest "
                            "lengths of the admissible pose nearest to the target (within the bounds, the rate limit "
                            "and the margin)")
    verify: bool = Field(True, description="verify every step along its transition (`verified`): a command is sent "
                                           "only where the arm follows its branch from the last step's pose to the "
                                           "step's, stable with the margin all along; false: the end pose only")
    taut: bool = Field(False, description=TAUT_DOC)


#: The open model of each mode.
OPEN_MODELS: dict[str, type[_Open]] = {"track": TrackOpen, "preloads": PreloadsOpen, "inverse": InverseOpen}


# ---------------------------------------------------------------------------- steps
class TrackStep(BaseModel):
    """The tip held at ``(2 sum(b) - dx, dy)``."""

    model_config = _STRICT
    type: Literal["step"]
    dx: Deflection = Field(description="tip deflection along x (length units); dx > 0 shortens the chain")
    dy: Deflection = Field(0.0, description="tip deflection along y (length units)")


class PreloadsStep(BaseModel):
    """A rest-length command."""

    model_config = _STRICT
    type: Literal["step"]
    rest_lengths: list[RestPair] = Field(min_length=1, max_length=HARD_MAX_SEGMENTS,
                                         description="[L1_0, L2_0] per segment, base to tip (n pairs)")
    load: Pair | None = Field(None, description="dead tip load [fx, fy]; default the open's")


class InverseStep(BaseModel):
    """A tip pose."""

    model_config = _STRICT
    type: Literal["step"]
    target: Point = Field(description="tip position [x, y] (length units)")
    end_angle: Angle | None = Field(None, description="absolute angle of the last link (rad), optional")
    load: Pair | None = Field(None, description="dead tip load [fx, fy]; default the open's")
    time: Seconds | None = Field(
        None, description="the step's instant (seconds; the start, at the open, is time 0; after the last step's)")
    dt: Seconds | None = Field(None, description="the time since the last step (seconds, > 0); not with `time`; "
                                                 "default the open's `dt`")


#: The step model of each mode.
STEP_MODELS: dict[str, type[BaseModel]] = {"track": TrackStep, "preloads": PreloadsStep, "inverse": InverseStep}
