"""The library's refusals as error bodies (``{"code", "message", "field", ...}``).

Library exceptions keep their ``code`` (every one is a subclass of ``TensegrityError``, which is never raised
itself), with the field as the request names it (:mod:`.fields`), the solver ``status`` of a solver failure or
time limit, the ``best`` point of an infeasible design and the other details. A numerical exception of numpy,
scipy or CasADi that the library did not turn into one of its refusals is ``numerical_failure`` (a server bug),
its message the same whatever the exception said (that goes to the server's log, not to the client).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from tensegrity_opt.errors import SolverError, TensegrityError, TimeLimitError

from .fields import FieldContext, request_field

__all__ = ["refusal_body", "plain", "NUMERICAL", "NUMERICAL_FAILURE"]

#: Failures of numpy, scipy or CasADi that the library did not turn into one of its refusals.
NUMERICAL = (ArithmeticError, np.linalg.LinAlgError, ValueError, RuntimeError)
#: Their message in an answer (the exception itself goes to the server's log).
NUMERICAL_FAILURE = ("the computation failed numerically for this input: an internal error of the server, "
                     "logged there with its details")


def plain(v: Any) -> Any:
    """``v`` as plain JSON values (numpy scalars and arrays, nested; a non-finite float is ``None``)."""
    if isinstance(v, (np.floating, float)):
        v = float(v)
        return v if math.isfinite(v) else None
    if isinstance(v, (np.integer,)):
        return int(v)
    if isinstance(v, (np.bool_,)):
        return bool(v)
    if isinstance(v, (str, int, bool)) or v is None:
        return v
    if isinstance(v, dict):
        return {str(k): plain(x) for k, x in v.items()}
    if isinstance(v, (list, tuple, np.ndarray)):
        return [plain(x) for x in v]
    return str(v)


def refusal_body(exc: BaseException, ctx: FieldContext = FieldContext()) -> dict[str, Any] | None:
    """The error body of a library refusal or a numerical failure; ``None`` for any other exception."""
    if isinstance(exc, TensegrityError):
        d = exc.to_dict()
        out: dict[str, Any] = {"code": exc.code, "message": exc.message}
        field = request_field(exc.field, ctx)
        if field:
            out["field"] = field
        if isinstance(exc, (SolverError, TimeLimitError)):
            out["status"] = str(exc.status) if exc.status is not None else None
        best = getattr(exc, "best", None)
        if isinstance(best, dict):
            out["best"] = plain(best)
        details = {k: plain(v) for k, v in d.items() if k not in ("code", "message", "field", "status")}
        if details:
            out["details"] = details
        return out
    if isinstance(exc, NUMERICAL):
        # what failed, not the text of the numerical library inside (shapes, dimensions, paths): that is logged
        return {"code": "numerical_failure", "message": NUMERICAL_FAILURE}
    return None
