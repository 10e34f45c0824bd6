"""Domain exceptions of tensegrity_opt.

Every exception subclasses a built-in (``ValueError`` for bad input or an
ill-posed question, ``RuntimeError`` for a solve that did not produce a
result), carries a machine-readable ``code`` and, where one input is to blame,
the name of that input in ``field``.  The HTTP service maps them to answers in
one place (``service/errors.py``) using ``code``.

:class:`NonFiniteResult` is the exception to the family: not a refusal of the input but a
result that came out non-finite where its JSON form promises a number (a bug, raised by
:mod:`tensegrity_opt.serialize`), so it is an ``ArithmeticError``, not a ``TensegrityError``.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable

__all__ = [
    "TensegrityError",
    "InvalidParameterError",
    "SingularStartError",
    "UnreachableTargetError",
    "StraightNotEquilibriumError",
    "UnstableStraightError",
    "UnsupportedError",
    "SolverError",
    "NoEquilibriumError",
    "InfeasibleDesignError",
    "TimeLimitError",
    "HomotopyUnavailableError",
    "NonFiniteResult",
    "nearest_name",
    "unknown_name",
]


class TensegrityError(Exception):
    """Base of every domain exception (never raised itself)."""

    code = "tensegrity_error"

    def __init__(self, message: str, *, field: str | None = None, **details: object) -> None:
        super().__init__(message)
        self.message = message
        self.field = field
        self.details = details
        self.status = details.get("status")

    def to_dict(self) -> dict[str, object]:
        """Machine-readable form: ``code``, ``message``, ``field`` and details."""
        out: dict[str, object] = {"code": self.code, "message": self.message}
        if self.field is not None:
            out["field"] = self.field
        out.update({k: v for k, v in self.details.items() if v is not None})
        return out


class InvalidParameterError(TensegrityError, ValueError):
    """A model parameter or argument is invalid (non-finite, non-positive, wrong shape...)."""

    code = "invalid_parameter"


class SingularStartError(InvalidParameterError):
    """The start of a continuation is a singular point of its path (a fold or a branch point): the control
    parameter has no single direction of increase there (``field="start"``, code ``invalid_parameter``)."""


class UnreachableTargetError(TensegrityError, ValueError):
    """The requested tip position lies beyond the chain's reach."""

    code = "unreachable_target"


class StraightNotEquilibriumError(TensegrityError, ValueError):
    """The straight configuration is not an equilibrium (asymmetric segment preloads)."""

    code = "straight_not_equilibrium"


class UnstableStraightError(TensegrityError, ValueError):
    """The straight configuration is not stable unloaded (some joint stiffness K <= 0)."""

    code = "straight_unstable"


class UnsupportedError(TensegrityError, ValueError):
    """The question is valid in general but not for this model (e.g. a landscape with n != 4)."""

    code = "unsupported"


class SolverError(TensegrityError, RuntimeError):
    """A numerical solve did not converge; ``status`` holds the solver's return status."""

    code = "solver_failed"

    def __init__(self, message: str, *, status: str | None = None, **details: object) -> None:
        super().__init__(message, status=status, **details)


class NoEquilibriumError(SolverError):
    """Solves converged but no equilibrium of the requested kind lies inside the physical range."""

    code = "no_equilibrium"


class InfeasibleDesignError(SolverError):
    """A design or control problem has no solution; ``best`` holds the best point found (or None)."""

    code = "design_infeasible"

    def __init__(self, message: str, *, status: str | None = None, best: object = None, **details: object) -> None:
        super().__init__(message, status=status, **details)
        self.best = best


class TimeLimitError(TensegrityError, RuntimeError):
    """A time limit given by the caller was reached (:func:`tensegrity_opt.time_limit`, ``timeout=``, a
    batch deadline), or IPOPT stopped at its own wall/CPU time limit; ``status`` says which. Never a result."""

    code = "timeout"


class HomotopyUnavailableError(TensegrityError, RuntimeError):
    """The polynomial homotopy engine is not installed: PHCpack's ``phc`` (Debian package ``phcpack``)."""

    code = "homotopy_unavailable"


class NonFiniteResult(ArithmeticError):
    """A result holds NaN or an infinity where its JSON form promises a number (:mod:`tensegrity_opt.serialize`).

    Not a :class:`TensegrityError`: the input was accepted, the answer is broken (overflow or
    underflow in the model), so it is a bug to report, not a refusal (the service answers
    500 ``numerical_failure``, as for any ``ArithmeticError``).
    """

    code = "numerical_failure"


def nearest_name(name: str, choices: Iterable[str]) -> str | None:
    """The valid name ``name`` was most likely meant to be: the one equal to it but for case first (``dX`` ->
    ``dx``), else the closest (:func:`difflib.get_close_matches`, case-insensitive); ``None`` when none is close."""
    choices = [str(c) for c in choices]
    same = [c for c in choices if c.lower() == str(name).lower()]
    if same:
        return same[0]
    lowered = {c.lower(): c for c in choices}
    close = difflib.get_close_matches(str(name).lower(), list(lowered), n=1, cutoff=0.6)
    return lowered[close[0]] if close else None


def unknown_name(name: str, choices: Iterable[str], what: str = "field") -> str:
    """``"unknown field; did you mean dx?"`` (or ``"unknown field; expected one of a, b"`` when none is close): the
    words every interface uses for a name it does not know."""
    choices = list(choices)
    guess = nearest_name(name, choices)
    if guess is not None:
        return f"unknown {what}; did you mean {guess}?"
    return f"unknown {what}; expected one of {', '.join(choices)}" if choices else f"unknown {what}"
