"""The least-energy equilibrium of a chain whose springs may go slack (the tension-only law), joint stops included.

Under the tension-only law (``docs/model.md``, "The spring law") a slack spring holds nothing, so a joint may
reach its mechanical stop ``|q| = pi - 2 beta`` (the triangles meet, a spring's length reaches zero) and rest on
it: an equilibrium with a *contact torque* (>= 0) at that joint. The least-energy configuration meeting the tip
constraint in the closed joint range is found by IPOPT on the smooth slack problem
(:mod:`tensegrity_opt.numerics.slack_nlp`) from several starts, then each solution is made exact and checked here:

1. the joints at a stop are read from the solution (within ``STOP_TOL`` of the bound) and set on it;
2. Newton on the free joints and the tip force (the equilibrium rows of the free joints, the tip rows) makes it
   an equilibrium to rounding; the residual is re-checked in numpy (:meth:`Manipulator.equilibrium_residual` on the
   free joints, under each spring's law: independent of CasADi);
3. a stop's contact torque is ``-sign(q_i) (dE/dq_i - (J^T F)_i)``: it must be >= 0 (else the joint would leave the
   stop: not an equilibrium there);
4. stability: the Hessian of ``E - F . tip`` reduced to the directions that keep the tip and the joints in contact
   fixed (a stop with a positive contact torque is a constraint: moving off it costs first-order energy), Morse
   index 0 with every eigenvalue above the tolerance.

The starts: ``q0`` and the
``STARTS`` lowest-energy distinct configurations of a ranked pool: ``SAMPLE_PER_JOINT * n`` seeded random
configurations of the range (a quarter of them with one joint at a stop, a quarter with two) projected onto the tip
constraint (:func:`~.seeds.project_to_target`, kinematics only), and for ``n <= RIGID_MAX`` the rigid configurations
(``n - 2`` joints on a stop, the two others solved for the tip), ranked by their energy under the springs' laws
(numpy, all at once). The least energy of the stable equilibria found is returned. This is a *measured* global
search, not a certified one: ``status`` is ``"converged"``; ``certify=True`` adds the rigorous lower bound (and the
patterns' certified set where it stays open, n <= 4) and ``method="homotopy"`` answers from that set
(:mod:`.tension_only_homotopy`). Measured against an independent brute force over the closed range (a dense grid,
polished): 333 random chains of six families, n = 2..4, deflected up to 4x (130 with slack springs, 56 on a stop),
every least energy found (``tests/model/test_spring_law.py``, ``benchmarks/spring_laws.py``).

A segment whose two springs are both slack has a free joint (no stiffness): the equilibrium is still reported where
it is isolated (the tip constraint holds it), and refused naming the segment where the joint is left undetermined
(a zero eigenvalue).
"""

from __future__ import annotations

import numpy as np

from ...errors import NoEquilibriumError, UnreachableTargetError, UnsupportedError
from ...model.loads import load_potential, loads_key
from ...model.manipulator import Manipulator
from ...numerics import distinct_rows
from ...numerics.slack_nlp import slack_nlp
from ...outcome import SolverInfo
from ...timelimit import check_time
from .equilibrium import (
    EIG_TOL,
    POLISH_ITER,
    RESIDUAL_TOL,
    STOP_TOL,
    Equilibrium,
)
from .equilibrium import (
    free_residual as _residual,
)
from .seeds import project_to_target

__all__ = ["least_energy_slack", "all_equilibria_slack",
           "stop_equilibria", "STARTS", "STOP_TOL", "SEARCH_PER_JOINT",
           "STOP_STARTS"]

#: IPOPT starts of the search taken from the ranked sample (besides q0).
STARTS = 6
#: Random configurations per joint of the ranked sample.
SAMPLE_PER_JOINT = 256
#: Every-equilibrium search: Newton starts per joint inside the range, and per joint and side on a stop.
SEARCH_PER_JOINT = 128
STOP_STARTS = 128
#: Projected starts closer than this (rad, largest joint) are one start.
START_SPACING = 0.05
#: Newton iterations of one start of the every-equilibrium search at most.
SEARCH_ITER = 60
#: Two equilibria closer than this (rad, largest joint) are one.
SAME_EQUILIBRIUM = 1e-7
#: A free joint whose Newton steps meet its stop this many times is held there.
STOP_HITS = 3
#: Newton guesses of each rigid configuration's two free joints (both elbows, from random angles).
RIGID_GUESSES = 12
#: Chains of at most this many segments also rank their rigid configurations (n - 2 joints on a stop).
RIGID_MAX = 6
#: Two ranked starts closer than this (rad, largest joint) are one.
DISTINCT = 0.15


def least_energy_slack(m: Manipulator, dx: float, dy: float, target: np.ndarray, *, q0=None,
                       local: bool = False) -> Equilibrium:
    """The least-energy stable equilibrium of ``m`` (any spring laws) with the tip on ``target``, in the closed joint
    range (module docstring). ``local``: only the solve from ``q0``."""
    nlp = slack_nlp(m.n, m.loaded)
    p, bounds = nlp.parameters(m, target), nlp.bounds(m)
    starts = [np.asarray(q0, float)] if local else _starts(m, target, q0)
    found: list[Equilibrium] = []
    statuses: dict[str, int] = {}
    refused: UnsupportedError | None = None
    for qs in starts:
        check_time("the tension-only search")
        res = nlp.solve(nlp.start(m, np.clip(qs, -m.joint_limits, m.joint_limits)), p, bounds)
        statuses[res.status] = statuses.get(res.status, 0) + 1
        if not res.success:
            continue
        try:
            eq = _classified(m, nlp, nlp.x.unpack(res.x)["q"], -res.lam_g[nlp.g["tip"]], target,
                             SolverInfo(res.status, res.iterations))
        except UnsupportedError as exc:          # a free joint left undetermined
            refused = exc
            continue
        if eq is None or not (eq.stable or local):
            continue
        found.append(eq)
    best = _least(found, q0)
    if best is None:
        if refused is not None:
            raise refused
        met = ", ".join(f"{k} x{v}" for k, v in sorted(statuses.items()))
        if set(statuses) == {"Infeasible_Problem_Detected"} and not local:
            raise UnreachableTargetError(
                f"the target for dx={dx:g}, dy={dy:g} lies within the chain's length but outside the workspace of the "
                f"closed joint range |q| <= pi - 2 beta: IPOPT found it infeasible from all {len(starts)} starts",
                field="dx", status=met)
        raise NoEquilibriumError(f"no stable equilibrium found from {len(starts)} start(s) of the tension-only search "
                                 f"(IPOPT: {met})", status="no_stable_equilibrium")
    return best


def _least(found: list[Equilibrium], q0) -> Equilibrium | None:
    """The least energy of ``found``; of equal ones (mirror images at ``dy = 0``, within ``1e-10`` relative) the one
    nearest ``q0``, else the one whose first non-zero angle is positive (as the linear law's search picks)."""
    if not found:
        return None
    e0 = min(e.energy for e in found)
    tied = [e for e in found if e.energy <= e0 + 1e-10 * max(1.0, abs(e0))]
    if q0 is not None:
        return min(tied, key=lambda e: float(np.abs(e.q - q0).max()))
    return max(tied, key=lambda e: (next((float(np.sign(v)) for v in e.q if abs(v) > 1e-9), 0.0), -e.energy))


def _starts(m: Manipulator, target: np.ndarray, q0) -> list[np.ndarray]:
    n, lim = m.n, m.joint_limits
    starts = [] if q0 is None else [np.asarray(q0, float)]
    rng = np.random.default_rng(20261207 + n)
    Q = rng.uniform(-0.98, 0.98, size=(SAMPLE_PER_JOINT * n, n)) * lim
    k = Q.shape[0] // 4                         # a quarter with one joint at (just inside) a stop, ...
    j = rng.integers(0, n, size=k)
    Q[np.arange(k), j] = rng.choice([-1.0, 1.0], size=k) * (1.0 - 1e-9) * lim[j]
    if n >= 3:                                  # ... a quarter with two (the tip then fixes the others)
        rows = np.arange(k, 2 * k)
        j2 = (j + rng.integers(1, n, size=k)) % n
        Q[rows, j] = rng.choice([-1.0, 1.0], size=k) * (1.0 - 1e-9) * lim[j]
        Q[rows, j2] = rng.choice([-1.0, 1.0], size=k) * (1.0 - 1e-9) * lim[j2]
    Q = project_to_target(m, Q, target)
    if 3 <= n <= RIGID_MAX:
        Q = np.vstack([Q, _rigid(m, target, rng)])
    given = len(starts)
    if Q.shape[0]:
        E = m.springs.energy(Q) + (load_potential(m, Q) if m.loaded else 0.0)
        for i in np.argsort(E, kind="stable"):
            if all(float(np.abs(Q[i] - s).max()) > DISTINCT for s in starts):
                starts.append(Q[i])
            if len(starts) - given >= STARTS:
                break
    if not starts:                              # no sample reaches the target: IPOPT decides (infeasible: unreachable)
        starts.extend(rng.uniform(-0.9, 0.9, size=(4, n)) * lim)
    return starts


def _project_held(m: Manipulator, Q: np.ndarray, target: np.ndarray, held: list[int]) -> np.ndarray:
    """The rows of ``Q`` moved onto ``tip(q) = target`` by minimum-norm Gauss-Newton steps in the joints not in
    ``held`` (those stay on their stops); the converged rows inside the closed range."""
    Q = np.array(Q, dtype=float, copy=True)
    free = np.array([j not in held for j in range(m.n)])
    lim = m.joint_limits
    for _ in range(30):
        k = m.tip_kinematics(Q)
        r = target - k.tip
        J = np.stack([k.Jx * free, k.Jy * free], axis=1)             # (M, 2, n)
        JJt = J @ np.transpose(J, (0, 2, 1))
        ok = np.abs(np.linalg.det(JJt)) > 1e-14
        JJt[~ok] = np.eye(2)
        step = np.transpose(J, (0, 2, 1)) @ np.linalg.solve(JJt, r[:, :, None])
        Q += np.clip(step[:, :, 0], -0.5, 0.5) * ok[:, None]
        Q = np.clip(Q, -lim, lim)
    k = m.tip_kinematics(Q)
    good = np.abs(k.tip - target).max(axis=1) < 1e-10 * float(m.b.sum())
    return Q[good]


def _rigid(m: Manipulator, target: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """The rigid configurations: ``n - 2`` joints on a stop (every choice of joints and sides), the two others solved
    for the tip by Newton (from ``RIGID_GUESSES`` guesses each; the converged ones inside the range). A projection of
    random samples moves every joint, so it seldom lands there, and the least energy may (both springs of two segments
    slack at their stops). More than ``n - 2`` joints on stops meet a target only by coincidence (a chain of round
    numbers: the paper's at ``dx = 2``), and there the tip force is not determined: not looked for."""
    from itertools import combinations as choose
    from itertools import product

    n, lim = m.n, m.joint_limits
    rows, frees = [], []
    for held in choose(range(n), n - 2):
        free = [j for j in range(n) if j not in held]
        for sides in product((-1.0, 1.0), repeat=n - 2):
            for _ in range(RIGID_GUESSES):
                q = rng.uniform(-0.9, 0.9, n) * lim
                q[list(held)] = np.array(sides) * lim[list(held)]
                rows.append(q)
                frees.append(free)
    Q, F = np.array(rows), np.array(frees)
    idx = np.arange(Q.shape[0])
    for _ in range(30):
        k = m.tip_kinematics(Q)
        r = target - k.tip                       # (M, 2)
        Jx = np.take_along_axis(k.Jx, F, axis=1)
        Jy = np.take_along_axis(k.Jy, F, axis=1)
        det = Jx[:, 0] * Jy[:, 1] - Jx[:, 1] * Jy[:, 0]
        ok = np.abs(det) > 1e-12
        det = np.where(ok, det, 1.0)
        d0 = (Jy[:, 1] * r[:, 0] - Jx[:, 1] * r[:, 1]) / det
        d1 = (-Jy[:, 0] * r[:, 0] + Jx[:, 0] * r[:, 1]) / det
        step = np.clip(np.column_stack([d0, d1]), -0.5, 0.5) * ok[:, None]
        Q[idx[:, None], F] += step
    k = m.tip_kinematics(Q)
    good = (np.abs(k.tip - target).max(axis=1) < 1e-10 * float(m.b.sum())) & np.all(np.abs(Q) <= lim, axis=1)
    return Q[good]


def _classified(m: Manipulator, nlp, q: np.ndarray, F: np.ndarray, target: np.ndarray,
                solver: SolverInfo, *, refuse_free: bool = True) -> Equilibrium | None:
    """The checked equilibrium at a solution ``(q, F)``, or None where it is not one (module docstring); a free joint
    left undetermined is refused (``refuse_free``) or returned as it is (a degenerate equilibrium)."""
    lim = m.joint_limits
    if not np.all(np.isfinite(q)) or np.any(np.abs(q) > lim * (1 + 1e-9)):
        return None
    side = np.where(q >= lim - STOP_TOL, 1.0, np.where(q <= -lim + STOP_TOL, -1.0, 0.0))
    q = np.where(side != 0.0, side * lim, q)
    free = side == 0.0
    if free.sum() < 2 and m.n >= 2:             # the tip rows need two free joints (else a rigid pose: rare)
        return None
    q, F = _polish(m, nlp, q, np.asarray(F, float), free, target)
    if q is None:
        return None
    E, g, H, tip, J = nlp.derivatives(m, q, F)
    r = g - J.T @ F
    scale = m.torque_scale
    if float(np.abs(tip - target).max()) > RESIDUAL_TOL * float(m.b.sum()) or \
            _residual(m, q, F, free) > RESIDUAL_TOL:
        return None
    contact = np.where(free, 0.0, -side * r)
    if np.any(contact < -1e-9 * scale):        # the joint would leave its stop
        return None
    contact = np.maximum(contact, 0.0)
    held = np.flatnonzero(~free)
    C = np.vstack([J, np.eye(m.n)[held]]) if held.size else J
    _, sv, Vt = np.linalg.svd(C)
    rank = int(np.sum(sv > 1e-10 * max(1.0, float(sv.max()))))
    Z = Vt[rank:].T
    w = np.linalg.eigvalsh(Z.T @ H @ Z) if Z.shape[1] else np.zeros(0)
    morse = int(np.sum(w < -EIG_TOL * scale))
    stable = morse == 0 and bool(np.all(w > EIG_TOL * scale))
    if morse == 0 and not stable and refuse_free:
        loose = [i for i in np.flatnonzero(free) if np.all(m.springs.states(q)[i] == "slack")]
        if loose:
            i = int(loose[0])
            raise UnsupportedError(
                f"both springs of segment {i} are slack at the least-energy configuration and its joint is left "
                f"undetermined (a free joint: no stiffness, and the tip constraint does not hold it); the least "
                f"energy is {E:.6g} but its configuration is not unique", field=f"segments[{i}]",
                status="free_joint")
    return Equilibrium(q=q.copy(), energy=m.potential_energy(q), force=F.copy(), morse_index=morse, stable=stable,
                       solver=solver, tip=m.tip(q), control="displacement", hessian_eigenvalues=w,
                       springs=m.springs, stops=(side != 0.0, contact), loads=loads_key(m))


def all_equilibria_slack(m: Manipulator, target: np.ndarray) -> list[Equilibrium]:
    """Every equilibrium of ``m`` (any spring laws) with the tip on ``target`` in the closed joint range that the
    search finds, with its Morse index, sorted by energy: damped Newton on the equilibrium equations under the
    springs' laws (:meth:`~tensegrity_opt.numerics.slack_nlp.SlackNLP.derivatives`) from ``SEARCH_PER_JOINT * n``
    configurations projected onto the tip, from ``STOP_STARTS`` per joint and side with that joint on its stop, and
    from the rigid configurations (``n - 2`` joints on stops); a free joint that reaches its stop during Newton is
    held there and Newton goes on (a stop equilibrium where its contact torque is >= 0). Each solution is checked
    like the least-energy one (:func:`_classified`: residuals in numpy, contact torques, the reduced Hessian).
    Complete in practice, never proven: measured equal to an independent enumeration (the constraint manifold on
    dense grids, every stop set: ``tests/support/reference_equilibria_tension.py``) on 34 chains n = 3, 4 of every
    family. More than ``n - 2`` joints on stops meet a target only by coincidence (the tip force is then not
    determined): not looked for."""
    rng = np.random.default_rng(20261208 + m.n)
    return _run_jobs(m, target, _free_jobs(m, target, rng) + _stop_jobs(m, target, rng))


def stop_equilibria(m: Manipulator, target: np.ndarray) -> list[Equilibrium]:
    """The equilibria resting on at least one joint's stop found from :func:`all_equilibria_slack`'s kind of stop
    and rigid starts only (its own random draws, no free starts: a free start that runs onto a stop can find one these
    miss; the linear law's search adds these to its open-range set, ``find_equilibria(stops=True)``: measured equal to
    the reference enumeration on 54 random linear chains)."""
    rng = np.random.default_rng(20261208 + m.n)
    return [e for e in _run_jobs(m, target, _stop_jobs(m, target, rng)) if e.at_stop.any()]


def _free_jobs(m: Manipulator, target: np.ndarray, rng: np.random.Generator) -> list[tuple[np.ndarray, frozenset]]:
    """Newton's starts with no joint held: ``SEARCH_PER_JOINT * n`` samples projected onto the tip."""
    n, lim = m.n, m.joint_limits
    Q = project_to_target(m, rng.uniform(-0.98, 0.98, size=(SEARCH_PER_JOINT * n, n)) * lim, target)
    return [(Q[r], frozenset()) for r in (np.flatnonzero(distinct_rows(Q, START_SPACING)) if Q.shape[0] else ())]


def _stop_jobs(m: Manipulator, target: np.ndarray, rng: np.random.Generator) -> list[tuple[np.ndarray, frozenset]]:
    """Newton's starts with a joint held on its stop (``STOP_STARTS`` per joint and side, half with another joint
    near its stop), and the rigid configurations (``n - 2`` joints on stops)."""
    n, lim = m.n, m.joint_limits
    jobs: list[tuple[np.ndarray, frozenset]] = []
    if n >= 3:
        for i in range(n):
            for side in (-1.0, 1.0):
                S = rng.uniform(-0.95, 0.95, size=(STOP_STARTS, n)) * lim
                half = STOP_STARTS // 2         # half with another joint near its stop (equilibria close to two)
                j2 = (i + rng.integers(1, n, size=half)) % n
                S[np.arange(half), j2] = rng.choice([-0.99, 0.99], size=half) * lim[j2]
                S[:, i] = side * lim[i]
                P = _project_held(m, S, target, [i])
                for r in np.flatnonzero(distinct_rows(P, START_SPACING)) if P.shape[0] else ():
                    jobs.append((P[r], frozenset({i})))
    if 2 <= n <= RIGID_MAX:
        for q in _rigid(m, target, rng):
            jobs.append((q, frozenset(np.flatnonzero(np.abs(q) >= lim).tolist())))
    return jobs


def _run_jobs(m: Manipulator, target: np.ndarray, jobs: list[tuple[np.ndarray, frozenset]]) -> list[Equilibrium]:
    """Damped Newton from each start (its held joints on their stops), a joint that reaches its stop then held, each
    solution classified; the distinct ones sorted by energy."""
    nlp = slack_nlp(m.n, m.loaded)
    n = m.n
    found: list[Equilibrium] = []
    for q, held in jobs:
        check_time("the tension-only search")
        for _ in range(n):                      # each pass may hold one more joint on its stop
            res = _newton(m, nlp, q, held, target)
            if res is None:
                break
            q, F, hit = res
            if hit is None:
                eq = _classified(m, nlp, q, F, target, SolverInfo("Newton_Converged", 0), refuse_free=False)
                if eq is not None and not any(float(np.abs(eq.q - e.q).max()) < SAME_EQUILIBRIUM for e in found):
                    found.append(eq)
                break
            if len(held) + 1 > n - 2:
                break
            held = held | {hit}
    return sorted(found, key=lambda e: e.energy)


def _newton(m: Manipulator, nlp, q: np.ndarray, held: frozenset, target: np.ndarray):
    """Damped Newton on the free joints and the tip force (the joints of ``held`` on their stops): ``(q, F, None)``
    at a solution, ``(q, F, j)`` where free joint ``j`` reached its stop (``q`` there), None where it fails."""
    lim = m.joint_limits
    q = np.array(q, dtype=float)
    for j in held:
        q[j] = np.sign(q[j]) * lim[j] if q[j] != 0.0 else lim[j]
    free = np.array([j not in held for j in range(m.n)])
    idx = np.flatnonzero(free)
    k = idx.size
    if k < 2 and m.n >= 2:
        return None
    _, g, _, _, J = nlp.derivatives(m, q, np.zeros(2))
    F = np.linalg.lstsq(J[:, idx].T, g[idx], rcond=None)[0]
    scale, length = m.torque_scale, float(m.b.sum())

    def residual(q, F):
        _, g, H, tip, J = nlp.derivatives(m, q, F)
        return np.concatenate([(g - J.T @ F)[idx] / scale, (tip - target) / length]), H, J

    r, H, J = residual(q, F)
    hits = np.zeros(m.n, dtype=int)
    for _ in range(SEARCH_ITER):
        norm = float(np.abs(r).max())
        if norm <= 1e-13:
            return q, F, None
        K = np.zeros((k + 2, k + 2))
        K[:k, :k] = H[np.ix_(idx, idx)] / scale
        K[:k, k:] = -J[:, idx].T / scale
        K[k:, :k] = J[:, idx] / length
        try:
            d = np.linalg.solve(K, -r)
        except np.linalg.LinAlgError:
            return None
        if not np.all(np.isfinite(d)):
            return None
        t = 1.0
        while t > 1e-4:
            qn = q.copy()
            qn[idx] += t * d[:k]
            out = np.abs(qn) > lim
            if out.any():                       # the step meets a stop: stop short of it, then (again) hold it
                j = int(np.flatnonzero(out)[np.argmax((np.abs(qn) - lim)[out])])
                frac = (lim[j] - abs(q[j])) / abs(qn[j] - q[j]) * t if qn[j] != q[j] else 0.0
                hits[j] += 1
                qs = q.copy()
                if hits[j] >= STOP_HITS:
                    qs[idx] += frac * d[:k]
                    qs[j] = np.sign(qn[j]) * lim[j]
                    return np.clip(qs, -lim, lim), F + frac * d[k:], j
                t = 0.5 * frac                  # halfway to the stop: Newton may turn before it
                if t <= 1e-4:
                    qs[j] = np.sign(qn[j]) * lim[j]
                    return np.clip(qs, -lim, lim), F, j
                continue
            Fn = F + t * d[k:]
            rn, Hn, Jn = residual(qn, Fn)
            if float(np.abs(rn).max()) < norm or t < 0.05:
                q, F, r, H, J = qn, Fn, rn, Hn, Jn
                break
            t *= 0.5
        else:
            return None
    return (q, F, None) if float(np.abs(r).max()) <= 1e-10 else None


def _polish(m: Manipulator, nlp, q: np.ndarray, F: np.ndarray, free: np.ndarray, target: np.ndarray):
    """Newton on the free joints and the tip force with the stops held: ``(q, F)`` to rounding, or ``(None, None)``."""
    idx = np.flatnonzero(free)
    k = idx.size
    scale = m.torque_scale
    for _ in range(POLISH_ITER):
        _, g, H, tip, J = nlp.derivatives(m, q, F)
        r = np.concatenate([(g - J.T @ F)[idx], tip - target])
        if float(np.abs(r[:k]).max(initial=0.0)) <= 1e-13 * scale and float(np.abs(r[k:]).max()) <= 1e-14 * m.b.sum():
            return q, F
        K = np.zeros((k + 2, k + 2))
        K[:k, :k] = H[np.ix_(idx, idx)]
        K[:k, k:] = -J[:, idx].T
        K[k:, :k] = J[:, idx]
        try:
            d = np.linalg.solve(K, -r)
        except np.linalg.LinAlgError:
            return None, None
        q = q.copy()
        q[idx] += d[:k]
        F = F + d[k:]
        if np.any(np.abs(q) > m.joint_limits) or not np.all(np.isfinite(q)):
            return None, None
        if float(np.abs(d).max()) < 1e-15:
            break
    _, g, H, tip, J = nlp.derivatives(m, q, F)
    ok = float(np.abs((g - J.T @ F)[idx]).max(initial=0.0)) <= 1e-10 * scale
    return (q, F) if ok else (None, None)


