"""Branch switching and bifurcation diagrams: :func:`switch_branch`, :func:`bifurcation_diagram`.

At a simple branch point (:mod:`.events`) the Jacobian ``[R_z, R_t]`` has a 2-dimensional null space: the
traced branch's tangent and a second direction. :func:`switch_branch` starts the bifurcating branch along
that second direction and continues it with the arclength engine of :mod:`.branches`;
:func:`bifurcation_diagram` traces a start's branch both ways and every branch reached from it through branch
points, recursively.
"""

from __future__ import annotations

import numpy as np
import scipy.optimize as so

from ...errors import InvalidParameterError, NoEquilibriumError, SingularStartError, TensegrityError
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...model.springs import linear_only
from ...timelimit import expired, time_limit
from .branches import FORCE_BOUND, Branch, _start_of, continue_branch, trace_branch
from .control import Control, as_control
from .events import BranchEvent
from .problem import PathProblem, path_point

__all__ = ["switch_branch", "bifurcation_diagram", "branches_from"]

#: Along the path of a singular start on which ``t`` stays constant, a point whose ``t`` differs from the start's by
#: more than this (scaled) means the path is not such a line (a fold): :func:`branches_from` does not leave it.
FLAT_T = 1e-8


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
    return _leave(prob, x, prob.tangent(x, _tangent_near(branch, event)), event.null_x, side, step, kw)


def _leave(prob: PathProblem, x: np.ndarray, t0: np.ndarray, null_x: np.ndarray | None, side: int, step: float,
           kw: dict) -> Branch:
    """The branch leaving the branch point ``x`` of ``prob`` along the null direction orthogonal to the traced
    tangent ``t0`` (``null_x``, the mode in ``z``, orients ``side = 1``); keywords as :func:`switch_branch`."""
    _, Rx = prob.eval(x)
    A = Rx / prob.w
    _, _, Vt = np.linalg.svd(A)
    basis = Vt[-2:]
    # the null direction orthogonal to the traced tangent
    c = basis @ t0
    v = basis[0] * c[1] - basis[1] * c[0]
    v = v / np.linalg.norm(v)
    if null_x is not None:
        nz = prob.point.pack(**prob.ps.layouts.z.unpack(null_x), t=0.0) * prob.w
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
    kw = dict(kw)
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

    The start's branch is traced both ways (``t`` increasing, then decreasing; at a singular start, the branches
    through it, :func:`branches_from`); at each branch point
    both sides of the bifurcating branch are traced (:func:`switch_branch`), recursively. A branch
    point met again on a later branch (the same point, within ``1e-6`` scaled) is not switched twice.
    Keywords as :func:`trace_branch` (``t_max``, ``t_min``, ``max_points``, ...; the control's own).

    Returns
    -------
    list of Branch
        The start's two halves first (``t`` up, ``t`` down; at the straight chain held at full reach its
        buckled arms), then the switched branches breadth-first;
        at most ``max_branches``.
    """
    unloaded_only(m, "bifurcation_diagram")
    linear_only(m, "bifurcation_diagram")
    if isinstance(depth, bool) or not isinstance(depth, (int, np.integer)) or depth < 0:
        raise InvalidParameterError(f"depth must be an integer >= 0, got {depth!r}", field="depth")
    trace_kw = {k: kw.pop(k) for k in ("t_max", "t_min", "max_points", "step", "max_step", "min_step") if k in kw}
    with time_limit(timeout):
        branches = branches_from(m, start, control, orientation=1, **trace_kw, **kw)
        try:
            branches += branches_from(m, start, control, orientation=-1, **trace_kw, **kw)
        except TensegrityError:
            pass
        if not branches:
            raise NoEquilibriumError("no branch leaves the start under this control", status="no_branch")
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


def branches_from(m: Manipulator, start=None, control: Control | str = "load", *, orientation: int = 1,
                  step: float = 0.02, **kw) -> list[Branch]:
    """The branches leaving ``start`` with ``t`` moving along ``orientation`` (+1: increasing, -1: decreasing).

    At a regular start: the one branch of :func:`trace_branch` (same keywords). At a singular start on a path
    along which ``t`` stays constant (the straight chain with its tip held at full reach: the reaction along the
    chain is free there, and the tip moves only once the chain buckles) that path is walked both ways to the
    first point where the stability of its straight shape changes (the buckling load of the held chain, a
    branch point) and the branches crossing it there are left on both sides, as :func:`switch_branch` does;
    those along which ``t`` moves along ``orientation`` are returned (the two mirror-image buckled arms,
    each starting at the branch point: the start's configuration under the critical reaction). An empty list:
    no branch leaves the start that way.

    Raises
    ------
    SingularStartError
        (``ValueError``) at a singular start of another kind (a fold of the path).
    """
    try:
        return [trace_branch(m, start, control, orientation=orientation, step=step, **kw)]
    except SingularStartError as exc:
        singular = exc
    control_kw = {k: kw.pop(k) for k in list(kw) if k not in ("t_max", "t_min", "max_points", "max_step",
                                                                 "min_step", "stop_at", "timeout")}
    timeout = kw.pop("timeout", None)
    ctl = as_control(m, control, control_kw)
    q0, F0 = _start_of(m, start, ctl)
    prob = PathProblem(m, ctl, q0, F0)
    x0, _ = prob.correct_t(prob.x0_guess, 0.0)
    _, Rx = prob.eval(x0)
    v = np.linalg.svd(Rx / prob.w)[2][-1]
    out: list[Branch] = []
    with time_limit(timeout):
        for side in (1.0, -1.0):
            x_bp = _first_change_on_line(prob, x0, side * v)
            if x_bp is None:
                continue
            for arm in (1, -1):
                try:
                    br = _leave(prob, x_bp, side * v, None, arm, step, kw)
                except NoEquilibriumError:
                    continue
                if len(br) > 1 and (br.t[1] - br.t[0]) * orientation > 0:
                    out.append(br)
    if not out and any(_off_line(prob, x0, s * v) for s in (1.0, -1.0)):
        raise singular
    return out


def _line_point(prob: PathProblem, x0: np.ndarray, v: np.ndarray, s: float) -> np.ndarray | None:
    """The point of the path through ``x0`` at scaled distance ``s`` along ``v`` (corrected), or None."""
    y, _ = prob.correct(x0 + s * v / prob.w, v, float(v @ (prob.w * x0)) + s)
    return y


def _off_line(prob: PathProblem, x0: np.ndarray, v: np.ndarray) -> bool:
    """Whether ``t`` moves along the path through ``x0`` in direction ``v`` (a fold, not a line of constant t)."""
    y = _line_point(prob, x0, v, 0.02)
    at_t = prob.point["t"]
    return y is not None and abs(float((y[at_t] - x0[at_t]) * prob.w[at_t])) > FLAT_T


def _least_reduced(prob: PathProblem, x: np.ndarray) -> float:
    """The least eigenvalue of the Hessian of ``E - F . tip`` on the joint motions that keep the held rows of
    the tip still (rank-revealing: at the straight chain held at full reach the motion along it is free),
    over the torque scale."""
    _, _, H, J, _, _ = prob.eval_all(x)
    C = prob.held_rows @ J
    if C.shape[0]:
        _, sv, Vt = np.linalg.svd(C)
        rank = int(np.sum(sv > 1e-10 * max(1.0, float(sv.max(initial=0.0)))))
        Z = Vt[rank:].T
        H = Z.T @ H @ Z
    return float(np.linalg.eigvalsh(H)[0]) / prob.m.torque_scale if H.size else 1.0


def _first_change_on_line(prob: PathProblem, x0: np.ndarray, v: np.ndarray) -> np.ndarray | None:
    """Walking from ``x0`` along ``v`` on the path through it with ``t`` constant (geometric steps up to the force
    bound), the first point where the least reduced eigenvalue changes sign (located by Brent), or None."""
    at_t = prob.point["t"]

    def point(s: float) -> np.ndarray | None:
        y = _line_point(prob, x0, v, s)
        if y is None or abs(float((y[at_t] - x0[at_t]) * prob.w[at_t])) > FLAT_T:
            return None
        return y

    g0 = _least_reduced(prob, x0)
    lo, s = 0.0, 0.02
    while s < FORCE_BOUND:
        if expired():
            return None
        y = point(s)
        if y is None:
            return None
        g = _least_reduced(prob, y)
        if g * g0 < 0.0:
            def f(u: float) -> float:
                yu = point(u)
                if yu is None:
                    raise NoEquilibriumError("the path of the start could not be followed", status="line_lost")
                return _least_reduced(prob, yu)
            try:
                return point(so.brentq(f, lo, s, xtol=1e-13 * s, rtol=4 * np.finfo(float).eps))
            except NoEquilibriumError:
                return None
        lo, g0, s = s, g if g != 0.0 else g0, 1.5 * s
    return None
