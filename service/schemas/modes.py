"""Models of ``/v1/modes``."""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

from ..config import HARD_MAX_SEGMENTS
from .common import LOADS_OUT_DOC, Angle, ForceValue, LoadsOut, ManipulatorIn, TipDx, TipDy
from .equilibrium import EquilibriumOut

#: The example chain of ``/v1/modes``: the paper's chain with masses.
MASSIVE_CHAIN = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0, "mass": 0.1}


class _ModesFields(BaseModel):
    """The equilibrium whose modes are asked (shared by ``/v1/modes`` and its figure): a tip deflection or a tip force,
    not both (checked by the task: 422 ``invalid_parameter`` naming the field)."""

    manipulator: ManipulatorIn
    dx: TipDx | None = None
    dy: TipDy | None = None
    fx: ForceValue | None = Field(None, description="a dead tip force along x instead of the deflection "
                                                    "(force units; < 0 compresses)")
    fy: ForceValue | None = Field(None, description="the dead tip force along y (force units)")
    tip: Literal["held", "loaded"] | None = Field(
        None, description="`held`: the modes with the tip kept where it is (tangent to the tip constraint); "
                          "`loaded`: the tip free under its dead load. Default: as the equilibrium is posed (held "
                          "for dx, dy; loaded for fx, fy)")
    q0: list[Angle] | None = Field(None, max_length=HARD_MAX_SEGMENTS, description="optional nearby configuration")


class ModesRequest(_ModesFields):
    """The vibration modes of an equilibrium: the least-energy stable one for a tip deflection (`dx`, `dy`: the tip
    held), or the local minimiser under a dead tip force (`fx`, `fy`: the tip loaded)."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"manipulator": MASSIVE_CHAIN, "dx": 1.0, "dy": 0.0}]})


class ModesOut(BaseModel):
    """:meth:`tensegrity_opt.Modes.to_dict`, with the equilibrium."""

    success: bool
    status: Literal["solved", "unstable", "degenerate"] = Field(
        description="`solved`: stable, every mode vibrates; `unstable`: some w^2 < 0 (frequency null there); "
                    "`degenerate`: some w^2 ~ 0")
    message: str
    frequencies: list[float | None] = Field(description="natural frequencies w (rad/s with kg, N/m, m), ascending; "
                                                        "null where a direction does not vibrate")
    eigenvalues: list[float] = Field(description="w^2, ascending (negative: unstable directions)")
    shapes: list[list[float]] = Field(description="mode k's joint angles (row k), mass-normalised")
    tip: Literal["held", "loaded"]
    held_joints: list[bool] = Field(description="the joints held on their stop")
    total_mass: float = Field(description="the segments' masses and the payload")
    loads: LoadsOut | None = Field(description=LOADS_OUT_DOC)
    equilibrium: EquilibriumOut
