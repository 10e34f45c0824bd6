"""Branch switching and bifurcation diagrams: :func:`switch_branch`, :func:`bifurcation_diagram`.

At a simple branch point (:mod:`.events`) the Jacobian ``[R_z, R_t]`` has a 2-dimensional null space: the
traced branch's tangent and a second direction. :func:`switch_branch` starts the bifurcating branch along
that second direction and continues it with the arclength engine of :mod:`.branches`;
:func:`bifurcation_diagram` traces a start's branch both ways and every branch reached from it through branch
points, recursively.
"""

from __future__ import annotations

import numpy as np

from ...errors import InvalidParameterError, NoEquilibriumError, TensegrityError
from ...model.manipulator import Manipulator
from ...timelimit import expired, time_limit
from .branches import Branch, continue_branch, trace_branch
from .control import Control
from .events import BranchEvent
from .problem import PathProblem, path_point

__all__ = ["switch_branch", "bifurcation_diagram"]


def switch_branch(branch: Branch, event: BranchEvent, side: int = 1, *, step: float = 0.02, **kw) -> Branch:
    """The branch bifurcating at a branch point of ``branch``, left on ``side`` (+1 or -1).

    At a simple branch point the Jacobian ``[R_z, R_t]`` has a 2-dimensional null space: the traced
    branch's tangent and a second direction ``v``; the new branch is the solution of
    ``R = 0, v . (x - x_bp) = side * step`` (then continued like :func:`trace_branch`, same keywords).
    Its ``t`` is the control parameter of ``branch``.
    """
    if not isinstance(event, BranchEvent) or event.kind != "branch_point":
        raise InvalidParameterError("event must be a branch_point of the branch", field="event")
    if side not in (1, -1):
        raise InvalidParameterError(f"side must be 1 or -1, got {side!r}", field="side")
    prob: PathProblem = branch.problem
    x = event.x
    _, Rx = prob.eval(x)
    A = Rx / prob.w
    _, _, Vt = np.linalg.svd(A)
    t0 = prob.tangent(x, _tangent_near(branch, event))
    basis = Vt[-2:]
    # the null direction orthogonal to the traced tangent
    c = basis @ t0
    v = basis[0] * c[1] - basis[1] * c[0]
    v = v / np.linalg.norm(v)
    if event.null_x is not None:
        nz = prob.point.pack(**prob.ps.layouts.z.unpack(event.null_x), t=0.0) * prob.w
        if v @ nz < 0:
            v = -v
    v = side * v
    Xbp = prob.w * x
    y = None
    for hh in (step, step / 4, step / 16):
        y, _ = prob.correct(x + hh * v / prob.w, v, float(v @ Xbp) + hh)
        if y is not None and np.linalg.norm(prob.w * y - Xbp) > 0.5 * hh:
            break
        y = None
    if y is None:
        raise NoEquilibriumError("no bifurcating branch found at this branch point", status="switch_failed")
    tau = prob.tangent(y, v)
    first = path_point(prob, x.copy(), v)
    second = path_point(prob, y, tau)
    opts = {k: kw.pop(k) for k in ("t_max", "t_min", "max_points", "max_step", "min_step", "stop_at") if k in kw}
    if kw:
        raise InvalidParameterError(f"unexpected keyword(s) {sorted(kw)}", field=sorted(kw)[0])
    opts.setdefault("max_points", 1000)
    timeout = opts.pop("timeout", None)
    with time_limit(timeout):
        return continue_branch(prob, first, t_max=opts.get("t_max"), t_min=opts.get("t_min"),
                               max_points=opts["max_points"], step=step, max_step=opts.get("max_step", 0.1),
                               min_step=opts.get("min_step", 1e-7), stop_at=opts.get("stop_at"),
                               prefix=[first, second])


def _tangent_near(branch: Branch, event: BranchEvent) -> np.ndarray:
    prob: PathProblem = branch.problem
    i = min(event.index, len(branch) - 1)
    x = prob.point.pack(q=branch.q[i], F=branch.force[i], t=branch.t[i])
    j = min(i + 1, len(branch) - 1)
    x2 = prob.point.pack(q=branch.q[j], F=branch.force[j], t=branch.t[j])
    d = (x2 - x) * prob.w
    nrm = np.linalg.norm(d)
    return d / nrm if nrm > 0 else prob.tangent(x, None)


def bifurcation_diagram(m: Manipulator, start=None, control: Control | str = "load", *, depth: int = 2,
                        max_branches: int = 24, timeout: float | None = None, **kw) -> list[Branch]:
    """Every branch connected to the start through branch points, to ``depth`` switches.

    The start's branch is traced both ways (``t`` increasing, then decreasing); at each branch point
    both sides of the bifurcating branch are traced (:func:`switch_branch`), recursively. A branch
    point met again on a later branch (the same point, within ``1e-6`` scaled) is not switched twice.
    Keywords as :func:`trace_branch` (``t_max``, ``t_min``, ``max_points``, ...; the control's own).

    Returns
    -------
    list of Branch
        The start's two halves first (``t`` up, ``t`` down), then the switched branches breadth-first;
        at most ``max_branches``.
    """
    if isinstance(depth, bool) or not isinstance(depth, (int, np.integer)) or depth < 0:
        raise InvalidParameterError(f"depth must be an integer >= 0, got {depth!r}", field="depth")
    trace_kw = {k: kw.pop(k) for k in ("t_max", "t_min", "max_points", "step", "max_step", "min_step") if k in kw}
    with time_limit(timeout):
        up = trace_branch(m, start, control, orientation=1, **trace_kw, **kw)
        branches = [up]
        try:
            branches.append(trace_branch(m, start, control, orientation=-1, **trace_kw, **kw))
        except TensegrityError:
            pass
        seen: list[np.ndarray] = []
        frontier = [(b, 0) for b in branches]
        while frontier and len(branches) < max_branches:
            br, level = frontier.pop(0)
            if level >= depth:
                continue
            for ev in br.branch_points:
                X = ev.x * br.problem.w
                if any(np.linalg.norm(X - S) < 1e-6 for S in seen):
                    continue
                seen.append(X)
                for side in (1, -1):
                    if len(branches) >= max_branches or expired():
                        break
                    try:
                        nb = switch_branch(br, ev, side, **{k: v for k, v in trace_kw.items() if k != "step"})
                    except TensegrityError:
                        continue
                    # the new branch starts at the branch point: mark it as seen from there too
                    branches.append(nb)
                    frontier.append((nb, level + 1))
    return branches
