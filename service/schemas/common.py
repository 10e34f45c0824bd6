"""What every resource's models share: the input bounds, the strict integer and the bounded number types, nested
lists of one length (matrices, steps of per-segment values), the chain and segment inputs, ranges, the tip force, the
solver report and the error body.

Imports nothing from its sibling modules (they all import it).
"""

from __future__ import annotations

from typing import Annotated, Any, Literal, Union

from pydantic import AfterValidator, BaseModel, BeforeValidator, ConfigDict, Discriminator, Field, Tag
from pydantic_core import PydanticCustomError

from ..config import HARD_MAX_SEGMENTS

# ---------------------------------------------------------------------------- limits
#: Range of the lengths (a, b, L0) and spring stiffnesses accepted (caller's units). Values far
#: outside any physical design (e.g. subnormal numbers) only make the model underflow.
MIN_LENGTH = 1.0e-6
MAX_LENGTH = 1.0e6
MIN_STIFFNESS = 1.0e-6
MAX_STIFFNESS = 1.0e9
#: Largest |dx|, |dy| (length units) and |force| accepted.
MAX_DEFLECTION = 1.0e9
MAX_FORCE = 1.0e12
#: Joint angles in requests (rad): q0 and the torque-curve abscissae.
MAX_ANGLE = 6.283185307179586
#: Points of a force-deflection curve.
MAX_CURVE_POINTS = 501
#: Points per axis of an energy landscape.
MAX_GRID = 201
#: Abscissae of a segment torque curve.
MAX_TORQUE_POINTS = 10001
#: The words of a required stability margin, wherever one is accepted (one rule: absolute, torque per radian).
TAUT_DOC = ("keep every spring in tension (L > L0, strictly) at every designed pose; required for a chain with "
            "tension-only springs (there the laws agree; the moves between a plan's poses are verified under the laws)")
MARGIN_DOC = ("required stability margin: the smallest eigenvalue of the Hessian of E - F . tip in the joint angles, "
              "absolute, in torque per radian (force x length / rad) like every margin of the API; for a margin "
              "relative to the chain's torque scale max k c^2, multiply by that scale")


_STRICT = ConfigDict(strict=True, extra="forbid")


def integral(v: Any) -> Any:
    """A float with an integral value (``4.0``, ``5e2``) as the ``int`` it is: JSON Schema's ``integer``
    is any number with a zero fractional part, so ``"n": 4.0`` is valid by the document. Anything
    else goes on unchanged to the strict ``int`` check (``4.5``, ``"4"``, ``true`` are refused)."""
    if type(v) is float and v.is_integer():
        return int(v)
    return v


#: The request schema's integer: strict (no strings, no booleans) but integral floats accepted.
#: As a field's type with ``= Field(ge=..)``; inside ``Annotated`` put the ``Field`` *before* the
#: validator (``Annotated[int, Field(ge=0), BeforeValidator(integral)]``): after it, pydantic writes
#: ``ge``/``le`` into the JSON schema instead of ``minimum``/``maximum``.
Int = Annotated[int, BeforeValidator(integral)]

Length = Annotated[float, Field(ge=MIN_LENGTH, le=MAX_LENGTH, allow_inf_nan=False)]
Stiff = Annotated[float, Field(ge=MIN_STIFFNESS, le=MAX_STIFFNESS, allow_inf_nan=False)]
Deflection = Annotated[float, Field(ge=-MAX_DEFLECTION, le=MAX_DEFLECTION, allow_inf_nan=False)]
ForceValue = Annotated[float, Field(ge=-MAX_FORCE, le=MAX_FORCE, allow_inf_nan=False)]
Angle = Annotated[float, Field(ge=-MAX_ANGLE, le=MAX_ANGLE, allow_inf_nan=False)]
#: Any finite number (a bound, a required margin): the operation's own checks give its range.
Finite = Annotated[float, Field(allow_inf_nan=False)]
#: The held tip's deflection as most requests take it: ``dx: TipDx``, ``dy: TipDy = 0.0``.
TipDx = Annotated[Deflection, Field(description="tip deflection along x (length units)")]
TipDy = Annotated[Deflection, Field(description="tip deflection along y (length units)")]


def _number_or_pair(v: Any) -> str:
    return "<pair>" if isinstance(v, (list, tuple)) else "<number>"


def _pair_of(item: Any, what: str) -> Any:
    return Annotated[
        Union[
            Annotated[item, Tag("<number>")],
            Annotated[list[item], Field(min_length=2, max_length=2), Tag("<pair>")],
        ],
        Discriminator(_number_or_pair),
        Field(description=f"{what}: one number for both springs or the pair [spring 1, spring 2]"),
    ]


StiffPair = _pair_of(Stiff, "spring stiffness k (force / length)")
LengthPair = _pair_of(Length, "spring rest length L0 (length units)")


# ---------------------------------------------------------------------------- nested lists
def same_lengths(items: list[Any]) -> list[Any]:
    """``items`` unchanged when every one of them that is a list has the length of the first such list: the rows
    of a matrix, the per-segment lists of every step, the list bounds of a pair. JSON Schema cannot say it (a
    ragged nested list reaches numpy as an "inhomogeneous shape"): refused here, naming the first odd row."""
    first: tuple[int, int] | None = None
    for i, item in enumerate(items):
        if not isinstance(item, list):
            continue
        if first is None:
            first = (i, len(item))
        elif len(item) != first[1]:
            raise PydanticCustomError(
                "ragged", "the lists must all have one length: item {first} has {expected} entries, item {index} "
                          "has {actual}", {"first": first[0], "expected": first[1], "index": i, "actual": len(item)})
    return items


#: A list of lists of one length (``Annotated[list[Row], Field(...), OneLength]``; ragged: 422 on the field).
OneLength = AfterValidator(same_lengths)


def rectangular(row: Any, **field: Any) -> Any:
    """A list of ``row`` lists all of one length (a matrix, or one per-segment list per step); ``field``: the
    outer list's ``Field`` arguments (``min_length``, ``max_length``, ``description`` ...)."""
    return Annotated[list[row], Field(**field), OneLength]


# ---------------------------------------------------------------------------- bounds
def _bounds_form(v: Any) -> str:
    return "<object>" if isinstance(v, (dict, BaseModel)) else "<pair>"


def _as_pair(v: Any) -> list[Any]:
    return [v.lo, v.hi] if isinstance(v, BaseModel) else list(v)


def bounds_of(side: Any, name: str, what: str, *, object_doc: str | None = None) -> Any:
    """Bounds on one quantity, in either form every interface takes: ``[lo, hi]`` (canonical: the library's
    ``(lo, hi)``, the command line's ``LO HI``) or ``{"lo": lo, "hi": hi}`` (the object ``name``), each side a
    ``side``; both come out as the list ``[lo, hi]`` (the library reads either: ``tensegrity_opt.bounds``), two
    list sides of one length."""
    from pydantic import create_model

    obj = create_model(name, __config__=_STRICT, __doc__=object_doc or f"{what}: the object form of [lo, hi].",
                       lo=(side, Field(description="lower bound")), hi=(side, Field(description="upper bound")))
    return Annotated[
        Union[
            Annotated[list[side], Field(min_length=2, max_length=2), Tag("<pair>")],
            Annotated[obj, Tag("<object>")],
        ],
        Discriminator(_bounds_form),
        AfterValidator(_as_pair),
        OneLength,
        Field(description=f'{what}: [lo, hi] or {{"lo": lo, "hi": hi}}'),
    ]


#: ``total_length`` of a design: a length fixing ``2 sum(b)``, ``true`` to keep the initial one (``false``: free).
TotalLength = Annotated[Union[bool, Annotated[float, Field(gt=0, le=MAX_LENGTH, allow_inf_nan=False)]], Field(
    description="fix the total length 2 sum(b): a length, or true to keep the initial one (false: free)")]


# ---------------------------------------------------------------------------- manipulator
SpringLaw = Annotated[Literal["linear", "tension_only"], Field(
    description="the springs' law: `linear` (the paper's model: force k (L - L0) at every length, a spring shorter "
                "than its rest length pushes) or `tension_only` (force k max(0, L - L0): it goes slack, as a real "
                "extension spring or cable). Analyses that do not honour `tension_only` refuse it (422 "
                "`unsupported`, field `segments[i].spring`)")]


#: A mass or a rotational inertia (>= 0; the caller's units: kg and kg m^2 with N/m and m give rad/s).
Mass = Annotated[float, Field(ge=0.0, le=1e12, allow_inf_nan=False)]
MASS_DOC = ("the segment's mass (>= 0, default 0): two equal triangles whose centroids lie on the chain's axis 2b/3 "
         "from the joint; without gravity it changes no equilibrium, it sets the vibration modes (`/v1/modes`)")
INERTIA_DOC = "each triangle's rotational inertia about its centroid (>= 0, default 0; mass x length^2)"
PAYLOAD_DOC = ("a point mass at the tip (>= 0, default 0): it sets the vibration modes (`/v1/modes`) and, under "
               "`gravity`, weighs on the chain")
#: A force or acceleration vector in the chain's plane ``[x, y]``.
Vector = Annotated[list[ForceValue], Field(min_length=2, max_length=2)]
GRAVITY_DOC = ("the gravity vector [gx, gy] in the chain's plane (default none: no weight); [0, -9.81] for a chain "
               "pointing along +x in a vertical plane, any direction (a tilted base). The triangles' and the payload's "
               "weights then load the chain in every analysis that honours dead loads; the others refuse it (422 "
               "`unsupported`, field `gravity`)")
JOINT_FORCES_DOC = ("dead point forces at joints, beside the tip's load: [{\"joint\": j, \"force\": [fx, fy]}], joints "
                    "counted from 1 at the base (joint 1 is fixed: a force there does no work); analyses that do not "
                    "honour dead loads refuse them (422 `unsupported`, field `joint_forces`)")


class JointForceIn(BaseModel):
    """A dead point force at a joint."""

    model_config = ConfigDict(strict=True, extra="forbid",
                              json_schema_extra={"examples": [{"joint": 3, "force": [0.0, -0.5]}]})

    joint: Int = Field(ge=1, le=HARD_MAX_SEGMENTS, description="the joint, counted from 1 at the base (at most n)")
    force: Vector = Field(description="the force [fx, fy] (force units), fixed in direction")


class LoadsOut(BaseModel):
    """The dead loads a result was computed under (null where the chain carries none)."""

    gravity: list[float] | None = Field(description="the gravity vector [gx, gy], or null")
    payload: float = Field(description="the point mass at the tip")
    joint_forces: list[JointForceIn] = Field(description="the dead forces at joints")


LOADS_OUT_DOC = ("the dead loads this was computed under (gravity on the chain's masses, joint forces); null where "
                 "the chain carries none")


class _ChainLoads(BaseModel):
    """The chain's own loads (every form of a chain in a request takes them)."""

    payload: Mass = Field(0.0, description=PAYLOAD_DOC)
    gravity: Vector | None = Field(None, description=GRAVITY_DOC)
    joint_forces: list[JointForceIn] = Field(default_factory=list, max_length=HARD_MAX_SEGMENTS,
                                             description=JOINT_FORCES_DOC)


class SegmentIn(BaseModel):
    """One dual-triangle segment."""

    model_config = ConfigDict(strict=True, extra="forbid",
                              json_schema_extra={"examples": [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0},
                                                              {"a": 1.0, "b": 1.0, "k": [1.0, 2.0], "L0": 1.0}]})

    a: Length = Field(description="triangle half-height (length units)")
    b: Length = Field(description="triangle half-length (length units); the segment is 2b long")
    k: StiffPair = 1.0
    L0: LengthPair = 1.0
    spring: SpringLaw = "linear"
    mass: Mass = Field(0.0, description=MASS_DOC)
    inertia: Mass = Field(0.0, description=INERTIA_DOC)


class UniformManipulatorIn(_ChainLoads):
    """`n` identical segments."""

    model_config = ConfigDict(strict=True, extra="forbid",
                              json_schema_extra={"examples": [{"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}]})

    n: Int = Field(ge=1, le=HARD_MAX_SEGMENTS, description=f"number of segments (server limit "
                                                         f"TENSEGRITY_MAX_SEGMENTS, at most {HARD_MAX_SEGMENTS})")
    a: Length = Field(1.0, description="triangle half-height (length units)")
    b: Length = Field(1.0, description="triangle half-length (length units)")
    k: StiffPair = 1.0
    L0: LengthPair = 1.0
    spring: SpringLaw = "linear"
    mass: Mass = Field(0.0, description=MASS_DOC)
    inertia: Mass = Field(0.0, description=INERTIA_DOC)


class SegmentedManipulatorIn(_ChainLoads):
    """Segments listed from base to tip; they may differ in every parameter."""

    model_config = ConfigDict(strict=True, extra="forbid", json_schema_extra={
        "examples": [{"segments": [{"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}] * 4}]})

    segments: list[SegmentIn] = Field(min_length=1, max_length=HARD_MAX_SEGMENTS,
                                      description="segments from base to tip (server limit TENSEGRITY_MAX_SEGMENTS)")


def _manipulator_kind(v: Any) -> str:
    if isinstance(v, SegmentedManipulatorIn) or (isinstance(v, dict) and "segments" in v):
        return "<segments>"
    return "<uniform>"


def _manipulator_union(uniform: type, segmented: type, what: str) -> Any:
    """The request's chain: the uniform or the segmented form, told apart by ``segments``."""
    return Annotated[
        Union[Annotated[uniform, Tag("<uniform>")], Annotated[segmented, Tag("<segments>")]],
        Discriminator(_manipulator_kind),
        Field(description=f'{what}: {{"n", "a", "b", "k", "L0", "spring"}} (uniform) or {{"segments": [...]}}'),
    ]


ManipulatorIn = _manipulator_union(UniformManipulatorIn, SegmentedManipulatorIn, "the chain")


PAPER_CHAIN = {"n": 4, "a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0}


# ---------------------------------------------------------------------------- ranges
class RangeIn(BaseModel):
    """`num` evenly spaced values from `start` to `stop` inclusive (like `numpy.linspace`)."""

    model_config = _STRICT

    start: float = Field(allow_inf_nan=False)
    stop: float = Field(allow_inf_nan=False)
    num: Int = Field(ge=1)


def _list_or_range(v: Any) -> str:
    return "<range>" if isinstance(v, (dict, RangeIn)) else "<list>"


def list_or_range(item: Any, values: type[RangeIn], min_length: int, max_length: int, description: str) -> Any:
    """Values given as a list of ``item`` (``min_length..max_length`` of them) or as ``{start, stop, num}``
    (``values``, a :class:`RangeIn`), told apart by their form."""
    return Annotated[
        Union[
            Annotated[list[item], Field(min_length=min_length, max_length=max_length), Tag("<list>")],
            Annotated[values, Tag("<range>")],
        ],
        Discriminator(_list_or_range),
        Field(description=description),
    ]


class DeflectionRange(RangeIn):
    start: Deflection
    stop: Deflection
    num: Int = Field(ge=1, le=MAX_CURVE_POINTS, description=f"number of points (at most {MAX_CURVE_POINTS})")


class AngleRange(RangeIn):
    start: Angle
    stop: Angle
    num: Int = Field(ge=1, le=MAX_TORQUE_POINTS, description=f"number of points (at most {MAX_TORQUE_POINTS})")


# ---------------------------------------------------------------------------- shared answers
SpringState = Literal["taut", "slack", "pushing"]
_SPRING_DOC = {
    "spring_lengths": "each spring's length L (length units), [spring 1, spring 2] per segment",
    "spring_stretches": "L - L0 per spring (negative: shorter than its rest length)",
    "spring_forces": "each spring's force, tension positive: k (L - L0) (linear law), k max(0, L - L0) (tension-only)",
    "spring_states": "`taut` (L >= L0), `slack` (tension-only, L < L0: no force) or `pushing` (linear law, L < L0: "
                     "a compressive force a real tension spring cannot carry)",
}


class SpringStateOut(BaseModel):
    """The spring state of one configuration (n x 2 each: spring 1 then spring 2 of each segment; declared once,
    mixed into every answer that carries a configuration)."""

    spring_lengths: list[list[float]] | None = Field(description=_SPRING_DOC["spring_lengths"])
    spring_stretches: list[list[float]] | None = Field(description=_SPRING_DOC["spring_stretches"])
    spring_forces: list[list[float]] | None = Field(description=_SPRING_DOC["spring_forces"])
    spring_states: list[list[SpringState]] | None = Field(description=_SPRING_DOC["spring_states"])


class SpringSeriesOut(BaseModel):
    """The spring state of a series of configurations (points x n x 2; a point without a configuration null)."""

    spring_lengths: list[list[list[float]] | None] | None = Field(description=_SPRING_DOC["spring_lengths"]
                                                                  + ", per point")
    spring_stretches: list[list[list[float]] | None] | None = Field(description=_SPRING_DOC["spring_stretches"]
                                                                    + ", per point")
    spring_forces: list[list[list[float]] | None] | None = Field(description=_SPRING_DOC["spring_forces"]
                                                                 + ", per point")
    spring_states: list[list[list[SpringState]] | None] | None = Field(description=_SPRING_DOC["spring_states"]
                                                                       + ", per point")


class Force(BaseModel):
    fx: float = Field(description="tip force along x (force units)")
    fy: float = Field(description="tip force along y (force units)")


def outcome_model(result: type, name: str | None = None) -> type[BaseModel]:
    """The contract's three fields for the library result class ``result`` (a subclass of
    :class:`tensegrity_opt.outcome.Outcome`): ``success``, ``status`` (its closed vocabulary, each value
    described) and ``message``. A response model derives from it, so they come first, as in ``to_dict()``."""
    from typing import Literal

    from pydantic import create_model

    vocab = result.STATUSES
    ok = sorted(result.SUCCESS)
    return create_model(
        name or f"{result.__name__}Outcome",
        success=(bool, Field(description=f"whether it worked: `status` is one of {', '.join(ok)}")),
        status=(Literal[tuple(vocab)], Field(description="; ".join(f"`{k}`: {v}" for k, v in vocab.items()))),
        message=(str, Field(description="what happened, in a sentence")),
    )


class SolverInfo(BaseModel):
    status: str = Field(description="the solver's return status (IPOPT return_status, Newton status, or 'straight')")
    iterations: int | None = Field(description="iterations of the final solve (0: none needed, e.g. the straight "
                                               "chain); null: not counted - a point of the compiled continuation "
                                               "of a chain of more than 8 segments (CasADi's rootfinder does not "
                                               "report it)")


# ---------------------------------------------------------------------------- errors
class FieldError(BaseModel):
    field: str = Field(description="dotted path of the offending input, e.g. manipulator.segments[0].a")
    message: str
    type: str


class ErrorOut(BaseModel):
    """Every refusal has this shape."""

    code: str = Field(description="machine-readable reason, e.g. validation_error, unreachable_target, "
                                  "straight_not_equilibrium, straight_unstable, too_many_segments, "
                                  "too_many_points, too_many_steps, solver_failed, no_equilibrium, timeout, "
                                  "overloaded, body_too_large, unauthorized")
    message: str = Field(description="human-readable explanation")
    field: str | None = Field(None, description="the input to blame, when there is one")
    status: str | None = Field(None, description="solver return status(es), for solver failures")
    errors: list[FieldError] | None = Field(None, description="every schema violation (validation_error only)")
    details: dict[str, Any] | None = Field(None, description="extra numbers (e.g. distance and reach)")
    best: dict[str, Any] | None = Field(None, description="design_infeasible only: the best point IPOPT found")
