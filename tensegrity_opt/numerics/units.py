"""The units the Newton methods work in: the chain rescaled so that torques and lengths are about 1.

The Newton methods test one norm of the KKT residual, whose rows are torques (``grad E - J^T F``) and
lengths (``tip - target``), against ``1e-12`` times the torque scale ``max(1, k c^2)``. That bounds each
part relative to its own scale only while the torque scale ``T`` and the length scale ``L = sum b`` are
comparable: a chain with ``max(1, T) / min(L, T)`` above :data:`UNIT_RATIO` (slender segments ``a >> b``,
very stiff or very soft springs, tiny or huge lengths) is solved in units where both are about 1 (exact
powers of two; results are returned in the caller's units). Without it, ``a = 1e6`` accepted the
unmoved straight chain as converged 0.1 away from its target (torque scale 1e12, threshold 1).
"""

from __future__ import annotations

import math

import numpy as np

from .results import Continuation, LocalResult, SeedResults

__all__ = ["UNIT_RATIO", "torque_scale", "rescaled", "unscale_result", "unscale_seeds", "unscale_continuation"]

#: Chains with ``max(1, T) / min(L, T)`` above this ratio are solved in rescaled units.
UNIT_RATIO = 1e3


def torque_scale(params: np.ndarray, n: int) -> float:
    """``max k c^2`` of the parameter vector ``[a, b, k1, k2, ...]`` (``Manipulator.torque_scale``)."""
    a, b, k1, k2 = (params[i * n:(i + 1) * n] for i in range(4))
    return float(np.max(np.maximum(k1, k2) * (a * a + b * b)))


def rescaled(params: np.ndarray, n: int) -> tuple[float, float, np.ndarray]:
    """``(lam, kap, params')``: lengths multiplied by ``lam`` and stiffnesses by ``kap`` (powers of two, so
    the change is exact), chosen so that both the length scale ``sum b`` and the torque scale ``k c^2`` are
    about 1. Identity (``1, 1, params``) when ``max(1, T) / min(L, T) <= UNIT_RATIO`` (torque scale ``T``,
    length scale ``L``): in particular for every chain with ``T >= 1`` and ``T <= UNIT_RATIO L``; long light
    chains (``L >> T >= 1``) are not rescaled (their tip rows meet a threshold above roundoff). The
    rescaled vector is read-only."""
    torque = torque_scale(params, n)
    length = float(np.sum(params[n:2 * n]))
    if max(1.0, torque) / min(length, torque) <= UNIT_RATIO:
        return 1.0, 1.0, params
    lam = 2.0 ** -round(math.log2(length))
    kap = 2.0 ** -round(math.log2(torque * lam * lam))
    scaled = np.array(params, dtype=float)
    scaled[:2 * n] *= lam
    scaled[2 * n:4 * n] *= kap
    scaled[4 * n:6 * n] *= lam
    scaled.setflags(write=False)
    return lam, kap, scaled


def unscale_result(r: LocalResult, lam: float, kap: float) -> LocalResult:
    """A result of the rescaled problem in the caller's units."""
    e = kap * lam * lam
    return LocalResult(r.q, r.force / (kap * lam), r.success, r.status, r.iterations, r.on_bound,
                       None if r.energy is None else r.energy / e, None if r.tip is None else r.tip / lam,
                       None if r.reduced_hessian is None else r.reduced_hessian / e)


def unscale_seeds(out: SeedResults, lam: float, kap: float) -> SeedResults:
    """Seed results of the rescaled problem in the caller's units (in place)."""
    e = kap * lam * lam
    out.force /= kap * lam
    out.energy /= e
    out.tip /= lam
    if out.reduced_hessian is not None:
        out.reduced_hessian /= e
    return out


def unscale_continuation(c: Continuation, n: int, lam: float, kap: float) -> Continuation:
    """A continuation of the rescaled problem in the caller's units (``residual`` stays in the solver's)."""
    c.Z[:, n:] /= kap * lam
    return Continuation(c.Z, c.residual, None if c.energy is None else c.energy / (kap * lam * lam),
                        None if c.tip is None else c.tip / lam,
                        None if c.reduced_hessian is None else c.reduced_hessian / (kap * lam * lam),
                        c.torque_scale, c.iterations)
