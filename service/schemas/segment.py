"""Models of ``/v1/segment/torque``."""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict, Field

from .common import MAX_TORQUE_POINTS, Angle, AngleRange, SegmentIn, list_or_range

#: The angles of a torque curve.
TorqueAngles = list_or_range(Angle, AngleRange, 1, MAX_TORQUE_POINTS,
                             f"joint angles (rad, |q| <= 2 pi): a list or {{start, stop, num}} "
                             f"(at most {MAX_TORQUE_POINTS} points)")


class SegmentTorqueRequest(BaseModel):
    """Torque curve `M(q)` of one segment."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"segment": {"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}, "q": [-0.5, 0.0, 0.5]},
                     {"segment": {"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0},
                      "q": {"start": -1.0, "stop": 1.0, "num": 5}}]})

    segment: SegmentIn
    q: TorqueAngles


class SegmentTorqueOut(BaseModel):
    q: list[float] = Field(description="joint angles (rad)")
    torque: list[float] = Field(description="spring torque M(q) = -dE/dq")
    dtorque: list[float] = Field(description="M'(q); the segment alone is stable where < 0")
    energy: list[float] = Field(description="segment energy E(q)")
    stiffness: float = Field(description="joint stiffness K = E''(0)")
    monotonic: bool = Field(description="M(q) decreases over the whole physical range")
    joint_limit: float = Field(description="physical range |q| < pi - 2 beta (rad)")
