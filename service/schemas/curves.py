"""Models of ``/v1/force-deflection``."""

from __future__ import annotations

from typing import Annotated, Literal, Union

from pydantic import BaseModel, ConfigDict, Discriminator, Field, Tag

from .common import MAX_CURVE_POINTS, PAPER_CHAIN, Deflection, DeflectionRange, Force, ManipulatorIn, _list_or_range


class ForceDeflectionRequest(BaseModel):
    """Force-deflection curve by continuation along the least-energy stable branch."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": PAPER_CHAIN, "dx": {"start": 0.0, "stop": 0.5, "num": 6}, "dy": 0.0,
                      "branch": "stable"}]})

    manipulator: ManipulatorIn
    dx: Annotated[
        Union[
            Annotated[list[Deflection], Field(min_length=1, max_length=MAX_CURVE_POINTS), Tag("<list>")],
            Annotated[DeflectionRange, Tag("<range>")],
        ],
        Discriminator(_list_or_range),
        Field(description=f"deflections in the order to follow: a list or {{start, stop, num}} "
                          f"(at most {MAX_CURVE_POINTS} points)"),
    ]
    dy: Deflection = Field(0.0, description="tip deflection along y, the same at every point")
    branch: Literal["stable", "all"] = Field(
        "stable", description='"all" also returns every branch found at the first deflected point')
    reference: Literal["straight", "rest"] = Field(
        "straight", description='what dx, dy are measured from: the straight tip (the paper\'s) or "rest", the tip '
                                'of the least-energy rest configuration (a pre-bent arm unloaded: force 0 at dx = dy = 0)')


class CurvePoint(BaseModel):
    dx: float
    dy: float
    fx: float
    fy: float
    energy: float
    q: list[float]
    stable: bool
    morse_index: int
    shape: str
    branch: int = Field(description="branch identifier (-1: straight)")


class JumpOut(BaseModel):
    kind: Literal["buckling", "branch_switch"]
    dx_before: float
    dx_after: float
    force_before: Force
    force_after: Force
    branch_before: int
    branch_after: int


class BranchPoint(BaseModel):
    """A point of one followed branch; numbers are null where the branch does not exist."""

    dx: float
    dy: float
    exists: bool
    fx: float | None
    fy: float | None
    energy: float | None
    q: list[float | None]
    stable: bool
    morse_index: int = Field(description="-1 where the branch does not exist")
    shape: str


class BranchOut(BaseModel):
    id: int
    points: list[BranchPoint]


class ForceDeflectionOut(BaseModel):
    points: list[CurvePoint]
    jumps: list[JumpOut]
    branches: list[BranchOut] = Field(description='branch = "all" only (else empty)')
    reference: Literal["straight", "rest"] = Field("straight", description="what dx, dy are measured from")
    origin: list[float] = Field([0.0, 0.0], description="the reference tip's deflection from the straight tip "
                                                        "(add it to dx, dy for the deflection from straight)")
