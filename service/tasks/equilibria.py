"""Tasks of the equilibrium requests: single solves, every equilibrium, buckling, curves, stiffness, the segment's
torque, the energy landscape, batches.

A task runs on an executor (a solver thread or process), never on the event loop: it takes the request (or its
plain parts), calls the library and returns the library's result (rendered by its own ``to_dict()``) or, for the
bodies that combine several, a JSON-ready dict. Library exceptions propagate unchanged (batch items are mapped
here, one error per target).
"""

from __future__ import annotations

from typing import Any

import tensegrity_opt as to
from tensegrity_opt.analyses.equilibria.equilibrium import Equilibrium
from tensegrity_opt.errors import NonFiniteResult
from tensegrity_opt.numerics import build, kernels
from tensegrity_opt.serialize import number, numbers

from .. import schemas as s
from ..adapters.fields import FieldContext
from ..adapters.inputs import build_manipulator, build_segment, manipulator, modes_pose, optional_array, values
from ..adapters.refusals import refusal_body

__all__ = ["warmup", "equilibrium_task", "force_equilibrium_task", "equilibria_task", "buckling_task",
           "force_deflection_task", "stiffness_task", "segment_torque_task", "energy_landscape_task", "batch_task",
           "build_in_background"]


def warmup() -> None:
    """Build this worker's CasADi instances for the paper's chain (first-request latency)."""
    to.solve_equilibrium(to.Manipulator.uniform(4), 0.1)


def build_in_background() -> None:
    """From now on this process compiles in the background (no request waits for the C compiler: what is not
    compiled yet runs in CasADi's virtual machine meanwhile), starting with the short chains' Newton kernels."""
    build.compile_in_background(True)
    kernels.prebuild()


def equilibrium_task(key: tuple[Any, ...], dx: float, dy: float, q0: tuple[float, ...] | None, local: bool,
                     certify: bool = False, bounded: bool = False) -> Equilibrium | None:
    """``solve_equilibrium`` of the chain ``key`` (:func:`service.adapters.inputs.equilibrium_args`).

    ``bounded``: the bounded Newton-only search (``method="newton"``), ``None`` when it finds no stable
    equilibrium (the full search then decides, IPOPT included). For the chains it is tried on
    (:func:`service.adapters.inputs.bounded_search_may_settle`: monotonic segments) ``method="auto"`` returns
    exactly the Newton-only answer whenever that finds one (and with ``local`` the same Newton solve before its
    IPOPT fallback), so the answer does not depend on which of the two ran (the service tests compare the
    bytes).
    """
    m = manipulator(key)
    q = optional_array(q0)
    if certify and not local:
        return to.solve_equilibrium(m, dx, dy, q0=q, certify=True)
    if not bounded:
        return to.solve_equilibrium(m, dx, dy, q0=q, local=local)
    try:
        return to.solve_equilibrium(m, dx, dy, q0=q, local=local, method="newton")
    except (to.NoEquilibriumError, to.SolverError):
        return None


def force_equilibrium_task(req: s.ForceEquilibriumRequest) -> Equilibrium:
    m = build_manipulator(req.manipulator)
    return to.solve_equilibrium_under_force(m, req.fx, req.fy, q0=optional_array(req.q0))


def equilibria_task(req: s.EquilibriaRequest, timeout: float | None = None) -> Any:
    """Every equilibrium; ``timeout`` bounds the homotopy's external solver (killed then, freeing the thread)."""
    m = build_manipulator(req.manipulator)
    return to.find_equilibria(m, req.dx, req.dy, method=req.method, timeout=timeout, stops=req.stops)


def buckling_task(req: s.BucklingRequest) -> Any:
    return to.critical_force(build_manipulator(req.manipulator), req.boundary)


def force_deflection_task(req: s.ForceDeflectionRequest) -> Any:
    m = build_manipulator(req.manipulator)
    return to.force_deflection(m, values(req.dx), req.dy, branch=req.branch, reference=req.reference)


def stiffness_task(req: s.StiffnessRequest) -> dict[str, Any]:
    m = build_manipulator(req.manipulator)
    eq = to.solve_equilibrium(m, req.dx, req.dy, q0=optional_array(req.q0))
    K = to.cartesian_stiffness(m, eq)
    return {"matrix": numbers(K), "equilibrium": eq.to_dict()}


def find_modes(req: Any) -> tuple[to.Manipulator, to.Modes]:
    """The chain of a modes request (``/v1/modes`` or its figure) and the modes of its equilibrium."""
    m = build_manipulator(req.manipulator)
    if modes_pose(req) == "force":
        eq = to.solve_equilibrium_under_force(m, req.fx or 0.0, req.fy or 0.0, q0=optional_array(req.q0))
    else:
        eq = to.solve_equilibrium(m, req.dx or 0.0, req.dy or 0.0, q0=optional_array(req.q0))
    return m, to.modes(m, eq, tip=req.tip)


def modes_task(req: s.ModesRequest) -> dict[str, Any]:
    _, md = find_modes(req)
    return {**md.to_dict(), "equilibrium": md.equilibrium.to_dict()}


def segment_torque_task(req: s.SegmentTorqueRequest) -> dict[str, Any]:
    seg = build_segment(req.segment)
    q = values(req.q)
    return {"q": numbers(q), "torque": numbers(seg.torque(q)), "dtorque": numbers(seg.dtorque(q)),
            "energy": numbers(seg.energy(q)), "stiffness": number(seg.stiffness), "monotonic": bool(seg.monotonic()),
            "joint_limit": number(seg.joint_limit)}


def energy_landscape_task(req: s.EnergyLandscapeRequest) -> Any:
    m = build_manipulator(req.manipulator)
    return to.energy_landscape(m, req.dx, req.dy, pair=(req.pair[0], req.pair[1]), grid=req.grid, span=req.span)


def batch_task(req: s.BatchEquilibriumRequest, deadline: float, form: str) -> dict[str, Any]:
    """Solve the targets in order (:func:`tensegrity_opt.solve_equilibria_batch`).

    With ``continuation`` each target continues the branch through the previous result (compiled
    continuation for short chains); a target that fails gets an error object and the next one starts
    from the last success. Targets not started before ``deadline`` (``time.monotonic()``) get
    ``code = "timeout"``.
    """
    m = build_manipulator(req.manipulator)
    q_prev = optional_array(req.q0)
    if q_prev is not None and (q_prev.shape != (m.n,) or not m.in_range(q_prev)):
        # A bad start would fail every target of the trajectory: refuse the request instead.
        raise to.InvalidParameterError(
            f"q0 must hold {m.n} joint angles inside the physical range |q_i| < pi - 2 beta_i", field="q0")
    targets = [(t.dx, t.dy) for t in req.targets]
    solved = to.solve_equilibria_batch(m, targets, continuation=req.continuation, q0=q_prev, deadline=deadline)
    results: list[dict[str, Any]] = []
    ok = 0
    for i, (t, r) in enumerate(zip(req.targets, solved)):
        item: dict[str, Any] = {"index": i, "dx": t.dx, "dy": t.dy, "equilibrium": None, "error": None}
        if isinstance(r, Equilibrium):
            try:
                item["equilibrium"] = r.to_dict()
                ok += 1
            except NonFiniteResult as exc:
                item["error"] = refusal_body(exc, FieldContext(manipulator=form, index=i))
        else:
            body = refusal_body(r, FieldContext(manipulator=form, index=i))
            if body is None:
                raise r
            item["error"] = body
        results.append(item)
    return {"results": results, "succeeded": ok, "failed": len(results) - ok}
