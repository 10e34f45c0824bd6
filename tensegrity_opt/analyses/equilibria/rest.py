"""Rest configurations and every equilibrium under a dead tip load.

* :func:`find_equilibria_under_force` - every equilibrium of the chain under the tip force
  ``F = (fx, fy)`` held fixed in direction and size (a dead load): the solutions of
  ``grad E(q) = J(q)^T F`` inside the open physical range, each classified by the full Hessian of
  ``E - F . tip`` (``Z = I``, ``docs/model.md``) and sorted by that total potential;
* :func:`rest_configuration` - the least-energy stable configuration of the unloaded chain.

``F = 0`` is exact: the energy is a sum of one-joint terms ``E(q) = sum_j E_j(q_j)``, so ``grad E = 0``
splits into the segments' own torque equations. Each segment's unloaded critical points
(:meth:`tensegrity_opt.model.segment.Segment.critical_points`: the real roots of a quartic united with
the torque's sign changes on a grid, polished by Newton) are found once, in the model, and the chain's
equilibria are exactly their Cartesian product,
certified. The Hessian in the relative angles is ``diag(E_j''(q_j))``, so a product point's Morse index
is the number of its factors that are maxima, and it is a minimum iff every factor is (Sylvester's law
of inertia carries this to the absolute-angle Hessian the other analyses report). A monotonic segment
contributes one point (its rest angle: ``0`` when symmetric), a bistable one (``K < 0``) three (two
wells around a hilltop), so a chain of such segments has ``3^k`` equilibria, ``2^k`` of them stable
(``k`` bistable segments). A segment may also have no well inside its range (a bistable one whose wells
lie beyond it; ``a > b`` with a spring far too long): then the chain has no stable rest configuration.
Within ~1e-9 of the torque scale of a pitchfork (``K ~ 0``) the critical points are not resolved in
double precision and come out ``"degenerate"``.

``F != 0`` couples the joints. ``method="search"`` runs damped Newton on the force equations
(:meth:`~tensegrity_opt.numerics.ChainSolver.newton_force`) from many starts and is complete in
practice, not certified; ``method="homotopy"`` (``n <= 6``, PHCpack) finds every isolated complex
root of the polynomial force system (:func:`tensegrity_opt.numerics.homotopy.solve_force_homotopy`)
and is certified when every path ended, every real root inside the range polished and every equilibrium
proven by Krawczyk's test in ball arithmetic (:mod:`tensegrity_opt.numerics.krawczyk`; the set's
``certificate``).
"""

from __future__ import annotations

import math
from collections import Counter
from dataclasses import replace
from functools import lru_cache

import numpy as np

from ...errors import InvalidParameterError, NoEquilibriumError, TensegrityError, UnsupportedError
from ...model.combinations import combination_indices, sample_combinations
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...model.springs import linear_only
from ...numerics import LocalResult, chain_solver, distinct
from ...outcome import SolverInfo
from ...timelimit import check_time
from .all_equilibria import HOMOTOPY_MAX_N, EquilibriumSet, certify_set, homotopy_set, searched_set
from .buckling import critical_force
from .equilibrium import (
    RESIDUAL_TOL,
    Equilibrium,
    free_stable,
    free_starts,
    is_equilibrium,
    least_energy_free,
    make_equilibrium,
)

__all__ = ["ANGLE_DIGITS", "ENERGY_TIE", "MAX_PRODUCT", "find_equilibria_under_force", "rest_configuration",
           "rest_points"]

#: Most equilibria the exact ``F = 0`` route returns (the product of the segments' critical points; a chain
#: of ``n`` bistable segments has ``3^n``, of which ``2^n`` are minima). Beyond it: ``stable_only=True``.
MAX_PRODUCT = 100_000
#: Energies within ``ENERGY_TIE * m.torque_scale`` of each other are a tie (equal wells).
ENERGY_TIE = 1e-9
#: Angles are compared rounded to this many decimals (rad) when ties are broken.
ANGLE_DIGITS = 9
#: ``F != 0`` search: unloaded critical points used as Newton starts (every combination up to this many,
#: else the all-first, all-last and a fixed-seed sample), random starts per joint (default of
#: ``n_random``: monotonic chains, multistable ones) and their seed, the load fractions of the
#: load-stepping from each rest minimum and the number of those minima it follows, the IPOPT starts.
#: Measured against the force homotopy on random chains of every family (n = 2..5, random loads): 100 n
#: random starts missed 2 of 207 equilibria at n = 4 (multistable chains; points within 0.1 rad of a
#: joint limit), 200 n and 300 n none; monotonic chains missed none at 25 n.
START_PATTERNS = 729
RANDOM_PER_JOINT = 100
MULTISTABLE_PER_JOINT = 300
RANDOM_SEED = 16001
LOAD_STEPS = (0.25, 0.5, 0.75, 1.0)
STEPPED_WELLS = 64
IPOPT_STARTS = 8
#: Joint-range fractions at which each free buckling mode (both signs) seeds Newton.
MODE_FRACTIONS = (0.05, 0.2, 0.5)
#: Most free buckling modes used as starts.
MAX_MODES = 12


# ----------------------------------------------------------------------------- the unloaded segments
@lru_cache(maxsize=256)
def _segment_points(m: Manipulator) -> tuple[tuple[np.ndarray, np.ndarray, np.ndarray], ...]:
    """Per segment ``(angles, E_j'' there, E_j there)``: every unloaded critical point inside the range,
    ascending (:meth:`~tensegrity_opt.model.segment.Segment.critical_points`; read-only arrays, cached per
    chain)."""
    out = []
    for seg in m.segments:
        q = seg.critical_points()
        d2 = -np.asarray(seg.dtorque(q), dtype=float).reshape(-1)
        e = np.asarray(seg.energy(q), dtype=float).reshape(-1)
        for a in (d2, e):
            a.setflags(write=False)
        out.append((q, d2, e))
    return tuple(out)


def _factor_kind(m: Manipulator, d2: np.ndarray) -> np.ndarray:
    """``+1`` minimum, ``-1`` maximum, ``0`` degenerate for second derivatives ``E_j''`` (tolerance: the
    ``rel_tol`` of :func:`tensegrity_opt.analyses.equilibria.stability.classify` times the chain's torque scale)."""
    tol = 1e-9 * m.torque_scale
    return np.where(d2 > tol, 1, np.where(d2 < -tol, -1, 0))


def rest_points(m: Manipulator, *, stable_only: bool = False) -> list[np.ndarray]:
    """Each segment's unloaded critical angles inside its range, ascending (``stable_only``: its wells only).

    The chain's ``F = 0`` equilibria are exactly the Cartesian product of these sets.
    """
    pts = []
    for q, d2, _ in _segment_points(m):
        pts.append(q[_factor_kind(m, d2) == 1].copy() if stable_only else q.copy())
    return pts


# ----------------------------------------------------------------------------- ordering and ties
def _rounded(Q: np.ndarray) -> np.ndarray:
    return np.round(np.asarray(Q, dtype=float), ANGLE_DIGITS) + 0.0      # + 0.0: no -0.0


def _tie_order(Q: np.ndarray) -> np.ndarray:
    """Order of configurations of equal energy: nearest to straight first (smallest ``max |q_i|``), then
    ``q`` lexicographically, larger ``q_1`` first (angles rounded to ``ANGLE_DIGITS`` decimals)."""
    R = _rounded(Q).reshape(len(Q), -1)
    keys = [-R[:, i] for i in range(R.shape[1] - 1, -1, -1)] + [np.abs(R).max(axis=1, initial=0.0)]
    return np.lexsort(keys)


def _order(V: np.ndarray, Q: np.ndarray, scale: float) -> np.ndarray:
    """Indices sorting by the potential ``V``, ties broken by :func:`_tie_order`.

    Ties are grouped from the lowest value up: a group holds every value within ``ENERGY_TIE * scale``
    of its first (lowest) member, so the first group is exactly the set :func:`rest_configuration`
    chooses from.
    """
    V = np.asarray(V, dtype=float)
    by_v = np.argsort(V, kind="stable")
    tol = ENERGY_TIE * scale
    out: list[int] = []
    i = 0
    while i < by_v.size:
        j = i
        while j + 1 < by_v.size and V[by_v[j + 1]] <= V[by_v[i]] + tol:
            j += 1
        group = by_v[i:j + 1]
        out.extend(group[_tie_order(Q[group])].tolist())
        i = j + 1
    return np.array(out, dtype=int)


# ----------------------------------------------------------------------------- F = 0: the exact product
def _exact_set(m: Manipulator, stable_only: bool) -> EquilibriumSet:
    segs = _segment_points(m)
    kinds = [_factor_kind(m, d2) for _, d2, _ in segs]
    pick = [np.flatnonzero(k == 1) if stable_only else np.arange(k.size) for k in kinds]
    count = math.prod(p.size for p in pick)
    if count > MAX_PRODUCT:
        what = "stable rest configurations (2^k for k bistable segments)" if stable_only else \
            "unloaded equilibria (the product of every segment's critical points)"
        hint = ("ask rest_configuration(m) for the least-energy one" if stable_only else
                "pass stable_only=True for the minima only, or ask rest_configuration(m) for the least-energy one")
        raise InvalidParameterError(f"this chain of n = {m.n} segments has {count} {what}, more than the "
                                    f"{MAX_PRODUCT} returned at once: {hint}", field="n", count=count)
    product = "the product of the segments' unloaded critical points" + (" (their wells only)" if stable_only else "")
    if count == 0:
        return EquilibriumSet([], method="exact", status="exact",
                              message=f"{product}, empty: a segment has none inside its range")
    sel = combination_indices([p.size for p in pick])              # (count, n) indices into pick
    idx = np.column_stack([pick[j][sel[:, j]] for j in range(m.n)])
    cols = range(m.n)
    Q = np.column_stack([segs[j][0][idx[:, j]] for j in cols])
    D2 = np.column_stack([segs[j][1][idx[:, j]] for j in cols])
    K = np.column_stack([kinds[j][idx[:, j]] for j in cols])
    energy = np.sum([segs[j][2][idx[:, j]] for j in cols], axis=0)
    morse = (K == -1).sum(axis=1)
    stable = (K == 1).all(axis=1)
    phi = np.cumsum(Q, axis=1)
    l = m.link_lengths
    tips = np.column_stack([m.base_length + (np.cos(phi) * l).sum(axis=1), (np.sin(phi) * l).sum(axis=1)])
    order = _order(energy, Q, m.torque_scale)
    eigs = _phi_hessian_eigenvalues(D2[order])
    zero = np.zeros(2)
    eqs = [Equilibrium(q=Q[i].copy(), energy=float(energy[i]), force=zero.copy(), morse_index=int(morse[i]),
                       stable=bool(stable[i]), solver=SolverInfo("exact", 0), tip=tips[i].copy(), control="force",
                       status="exact", springs=m.springs,
                       hessian_eigenvalues=w)
           for i, w in zip(order.tolist(), eigs)]
    return EquilibriumSet(eqs, method="exact", status="exact",
                          message=f"{product}: {count} {_PLURAL[stable_only, count == 1]}")


_PLURAL = {(True, True): "minimum", (True, False): "minima", (False, True): "point", (False, False): "points"}


def _phi_hessian_eigenvalues(D2: np.ndarray, chunk: int = 4096) -> list[np.ndarray]:
    """Eigenvalues of the unloaded Hessian in absolute angles, ``T^T diag(E'') T`` (``q = T phi``, ``T`` the
    difference matrix: tridiagonal, diagonal ``E_j'' + E_{j+1}''``, off-diagonal ``-E_{j+1}''``), per row of
    ``D2`` (the ``E_j''`` of each point): the eigenvalues every other force-controlled ``Equilibrium`` holds."""
    N, n = D2.shape
    out: list[np.ndarray] = []
    for s in range(0, N, chunk):
        d = D2[s:s + chunk]
        H = np.zeros((d.shape[0], n, n))
        ii = np.arange(n)
        H[:, ii, ii] = d + np.concatenate([d[:, 1:], np.zeros((d.shape[0], 1))], axis=1)
        if n > 1:
            H[:, ii[:-1], ii[1:]] = -d[:, 1:]
            H[:, ii[1:], ii[:-1]] = -d[:, 1:]
        out.extend(np.linalg.eigvalsh(H))
    return out


# ----------------------------------------------------------------------------- F != 0: the search
def _patterns(pts: list[np.ndarray], cap: int, seed: int) -> np.ndarray:
    """Configurations of one unloaded critical point per segment (:func:`.combinations.sample_combinations`)."""
    return sample_combinations(pts, cap, seed + len(pts))


def _mode_starts(m: Manipulator) -> np.ndarray:
    """The straight chain's free buckling modes, both signs, at ``MODE_FRACTIONS`` of the range (none when
    the free buckling problem does not apply: asymmetric preloads, a segment with ``K <= 0``)."""
    try:
        bk = critical_force(m, "free", n_modes=min(MAX_MODES, m.n))
    except (TensegrityError, np.linalg.LinAlgError):
        return np.zeros((0, m.n))
    lim = float(np.min(m.joint_limits))
    rows = []
    for md in bk.modes:
        shape = md.q / max(float(np.abs(md.q).max()), 1e-300)
        for frac in MODE_FRACTIONS:
            rows += [frac * lim * shape, -frac * lim * shape]
    return np.array(rows).reshape(-1, m.n)


def _search(m: Manipulator, force: np.ndarray, n_random: int, dedupe_tol: float) -> EquilibriumSet:
    mdl = chain_solver(m)
    statuses: Counter[str] = Counter()
    found: list[LocalResult] = []

    def newton(q0: np.ndarray, F: np.ndarray = force) -> LocalResult:
        res = mdl.newton_force(F, q0)
        statuses[res.status] += 1
        return res

    def keep(res: LocalResult) -> None:
        if is_equilibrium(m, res):
            found.append(res)

    pts = rest_points(m)
    wells = rest_points(m, stable_only=True)
    lim = m.joint_limits
    rng = np.random.default_rng(RANDOM_SEED + m.n)
    starts = np.vstack([np.zeros((1, m.n)), _patterns(pts, START_PATTERNS, RANDOM_SEED), _mode_starts(m),
                        rng.uniform(-0.95, 0.95, (int(n_random), m.n)) * lim])
    for i, q0 in enumerate(starts):
        if i % 64 == 0:
            check_time("the equilibrium search")
        keep(newton(q0))
    # load stepping: the branch through each rest minimum followed to the full load
    for q in _patterns(wells, STEPPED_WELLS, RANDOM_SEED + 1):
        for t in LOAD_STEPS:
            res = newton(q, t * force)
            if not (res.success and not res.on_bound and m.in_range(res.q)):
                break
            q = res.q
        else:
            keep(res)
    # IPOPT's minima (polished by Newton): the stable ones, whatever the basins of Newton
    check_time("the equilibrium search")
    for q0 in np.vstack([np.zeros((1, m.n)), _patterns(wells, IPOPT_STARTS - 1, RANDOM_SEED + 2)]):
        res = mdl.minimize_force(force, q0)
        statuses[res.status] += 1
        if res.success and not res.on_bound and np.all(np.isfinite(res.q)):
            pol = newton(res.q)
            if pol.success and np.max(np.abs(pol.q - res.q)) < 1e-4:
                keep(pol)
    # mirror images: -q is an equilibrium of a mirror-symmetric chain under (fx, -fy), so of this one when
    # fy = 0; elsewhere a start near another basin
    for r in distinct(found, dedupe_tol):
        keep(newton(-r.q))
    unique = distinct(found, dedupe_tol)
    eqs = [make_equilibrium(m, r, constrained=False) for r in unique]
    return searched_set(_sorted(m, eqs, force), statuses)


def _sorted(m: Manipulator, eqs: list[Equilibrium], force: np.ndarray) -> list[Equilibrium]:
    if not eqs:
        return []
    V = np.array([e.energy - float(force @ e.tip) for e in eqs])
    return [eqs[i] for i in _order(V, np.array([e.q for e in eqs]), m.torque_scale).tolist()]


# ----------------------------------------------------------------------------- F != 0: the homotopy
def _homotopy(m: Manipulator, force: np.ndarray, dedupe_tol: float, timeout: float | None) -> EquilibriumSet:
    from ...numerics.homotopy import polish_roots, real_force_configurations
    from ...numerics.parameter_homotopy import solve_force_parameter_homotopy

    if m.n > HOMOTOPY_MAX_N:
        raise InvalidParameterError(f"method='homotopy' handles chains of up to {HOMOTOPY_MAX_N} segments "
                                    f"(its path count grows ~6x a segment), got n = {m.n}", field="method")
    sol = solve_force_parameter_homotopy(m, force, timeout=timeout)
    q, inside, regular = real_force_configurations(m, sol)
    mdl = chain_solver(m)
    q = q[inside]
    out = polish_roots(sol, q, np.tile(force, (q.shape[0], 1)), regular[inside],
                       polish=lambda qi, Fi: mdl.newton_force(force, qi), accept=lambda res: is_equilibrium(m, res),
                       root_is_equilibrium=lambda qi, Fi: (m.equilibrium_residual(qi, force) <= RESIDUAL_TOL
                                                           and m.in_range(qi)),
                       dedupe_tol=dedupe_tol)
    eqs = _sorted(m, [make_equilibrium(m, r, constrained=False) for r in out.found], force)
    return homotopy_set(eqs, sol, out, certify_set(m, eqs, sol, force=force))


# ----------------------------------------------------------------------------- the public functions
def _finite(name: str, v) -> float:
    if isinstance(v, bool):
        raise InvalidParameterError(f"{name} must be a number, got {v!r}", field=name)
    try:
        x = float(v)
    except (TypeError, ValueError):
        raise InvalidParameterError(f"{name} must be a number, got {v!r}", field=name) from None
    if not math.isfinite(x):
        raise InvalidParameterError(f"{name} must be finite, got {v!r}", field=name)
    return x


def find_equilibria_under_force(m: Manipulator, fx: float = 0.0, fy: float = 0.0, *, method: str = "search",
                                stable_only: bool = False, dedupe_tol: float = 1e-6, n_random: int | None = None,
                                timeout: float | None = None) -> EquilibriumSet:
    """Every equilibrium inside the open physical range under the dead tip load ``F = (fx, fy)``.

    The solutions of ``grad E(q) = J(q)^T F`` (``docs/model.md``), each an :class:`Equilibrium` with
    ``control="force"``, ``force = (fx, fy)`` and its classification by the full Hessian of ``E - F . tip``
    (Morse index, ``stable``, ``kind``).

    Parameters
    ----------
    m : Manipulator
    fx, fy : float
        The tip force (force units, finite); ``fx < 0`` compresses. The default ``F = 0`` gives the rest
        configurations and every other unloaded equilibrium.
    method : {"search", "homotopy"}
        For ``F != 0``. ``"search"``: damped Newton on the force equations from every unloaded critical
        point (every combination up to ``START_PATTERNS``, else a fixed-seed sample), the straight chain,
        the straight chain's free buckling modes with both signs (where that problem applies),
        ``n_random`` uniform random configurations (fixed seed: reproducible), the branches of the rest
        minima followed to the load in ``LOAD_STEPS``, IPOPT's minima of ``E - F . tip`` and the mirror
        images of everything found; never certified. Measured complete (every equilibrium of the certified
        homotopy found, nothing else) on 232 random chains of every family under random loads, n = 2..5
        (662 equilibria; ``tests/analyses/equilibria/test_rest.py`` repeats a few, also against the reference
        model's Newton). ``"homotopy"``: every isolated complex root of the polynomial force system by PHCpack
        (the parameter homotopy from cached start solutions,
        :func:`tensegrity_opt.numerics.parameter_homotopy.solve_force_parameter_homotopy`, the polyhedral
        :func:`tensegrity_opt.numerics.homotopy.solve_force_homotopy` when paths fail; ``n <= 6``; paths 4, 24,
        128, 704, 3840 for n = 1..5 on general chains), the real roots inside the range polished by Newton;
        certified when every path ended, every real root polished and every equilibrium proven by Krawczyk's test
        in ball arithmetic (the set's ``certificate``)
        (uniform n = 5 chains end with failed paths: uncertified). For ``F = 0`` both give the exact set.
    stable_only : bool
        Return the stable equilibria (minima of ``E - F . tip``) only.
    dedupe_tol : float
        Two solutions closer than this (max-norm of ``q``, rad) are one (``> 0``).
    n_random : int, optional
        Uniform random Newton starts of the search (default ``100 n`` for monotonic chains, ``300 n`` for
        multistable ones: ``RANDOM_PER_JOINT``, ``MULTISTABLE_PER_JOINT``).
    timeout : float, optional
        Homotopy only: seconds before PHCpack is stopped (:class:`SolverError`).

    Returns
    -------
    EquilibriumSet
        A read-only sequence of :class:`Equilibrium` without duplicates, sorted by the *total potential*
        ``E(q) - F . tip(q)`` (the quantity a dead load makes stationary; with ``F = 0`` the elastic
        energy, which ``Equilibrium.energy`` always holds); equal potentials (within ``ENERGY_TIE *
        m.torque_scale`` of the lowest of their group) nearest to straight first (smallest
        ``max |q_i|``), then larger ``q_1`` first, then larger ``q_2`` ... (angles rounded to
        ``ANGLE_DIGITS`` decimals). ``method`` and ``status``: ``"exact"`` for ``F = 0`` (the product of
        every segment's unloaded critical points; a product point is a minimum iff each factor is, its Morse
        index the number of factors that are maxima), ``"search"`` (status ``searched``) or ``"homotopy"``
        (``certified`` or ``uncertified``). Empty when nothing was found inside the range (a load pressing
        every configuration against a joint limit; proven so only by a certified homotopy): an answer, a
        success.

    Raises
    ------
    InvalidParameterError
        (``ValueError``) a non-finite ``fx``/``fy``, an unknown ``method``, a bad ``dedupe_tol``,
        ``n_random`` or ``timeout``, a chain too long for the homotopy; ``field="n"`` when ``F = 0`` and
        the product exceeds ``MAX_PRODUCT`` points (then pass ``stable_only=True``: at most ``2^n``, or ask
        :func:`rest_configuration`).
    HomotopyUnavailableError
        (``RuntimeError``) ``method="homotopy"`` with ``F != 0`` without PHCpack (Debian ``phcpack``).
    SolverError
        (``RuntimeError``) PHCpack failed or timed out.
    TimeLimitError
        A :func:`tensegrity_opt.time_limit` expired during the search.
    """
    if not m.loaded:
        linear_only(m, "find_equilibria_under_force")
    fx, fy = _finite("fx", fx), _finite("fy", fy)
    if method not in ("search", "homotopy"):
        raise InvalidParameterError(f"method must be 'search' or 'homotopy', got {method!r}", field="method")
    if not isinstance(stable_only, (bool, np.bool_)):
        raise InvalidParameterError(f"stable_only must be True or False, got {stable_only!r}", field="stable_only")
    tol = _finite("dedupe_tol", dedupe_tol)
    if tol <= 0.0:
        raise InvalidParameterError(f"dedupe_tol must be > 0, got {dedupe_tol!r}", field="dedupe_tol")
    if n_random is None:
        n_random = (RANDOM_PER_JOINT if m.monotonic else MULTISTABLE_PER_JOINT) * m.n
    elif isinstance(n_random, bool) or not isinstance(n_random, (int, np.integer)) or n_random < 0:
        raise InvalidParameterError(f"n_random must be an integer >= 0, got {n_random!r}", field="n_random")
    if timeout is not None and not (_finite("timeout", timeout) > 0.0):
        raise InvalidParameterError(f"timeout must be > 0 seconds, got {timeout!r}", field="timeout")
    if m.loaded:
        return _loaded_set(m, np.array([fx, fy]), bool(stable_only), method)
    if fx == 0.0 and fy == 0.0:
        return _exact_set(m, bool(stable_only))
    force = np.array([fx, fy])
    if method == "homotopy":
        out = _homotopy(m, force, tol, timeout)
    else:
        out = _search(m, force, int(n_random), tol)
    if stable_only:
        keep = [i for i, e in enumerate(out) if e.stable]
        out = replace(out, equilibria=[out[i] for i in keep],
                      certificate=None if out.certificate is None else out.certificate.select(keep))
    return out


def _loaded_set(m: Manipulator, force: np.ndarray, stable_only: bool, method: str) -> EquilibriumSet:
    """:func:`find_equilibria_under_force` of a chain with dead loads: its stable equilibria found by the free-tip
    search (:func:`stable_free_equilibria`); the unstable ones are not looked for (refused by name)."""
    if method == "homotopy":
        unloaded_only(m, "find_equilibria_under_force(method='homotopy')")
    if not stable_only:
        raise UnsupportedError("under dead loads (gravity on the masses, joint forces) the equilibria with a free tip "
                               "are searched for their stable ones only: pass stable_only=True (the wells the chain "
                               "can rest in), or ask find_equilibria for every equilibrium with the tip held",
                               field="stable_only")
    eqs = stable_free_equilibria(m, force)
    on_stop = sum(bool(e.at_stop.any()) for e in eqs)
    where = f" ({on_stop} resting on a joint's stop)" if on_stop else ""
    return EquilibriumSet(eqs, method="search", status="searched",
                          message=f"{len(eqs)} stable equilibria{where} found under the chain's dead loads by local "
                                  "descents from straight, the unloaded chain's wells and random configurations of "
                                  "the closed range (measured, not certified)")


#: The stable set under dead loads with the tip free: random starts per joint besides the unloaded chain's wells.
FREE_SET_PER_JOINT = 8
#: ... and at most this many of the unloaded chain's wells (the product of its segments' wells) as starts.
FREE_SET_WELLS = 64


def stable_free_equilibria(m: Manipulator, force=(0.0, 0.0)) -> list[Equilibrium]:
    """The distinct stable equilibria of ``m`` with its tip free under the dead tip load ``force`` that the local
    solves of :func:`~.equilibrium.least_energy_free` reach from straight, the unloaded chain's stable rest
    configurations (its segments' wells: each a well the loads deform, at most ``FREE_SET_WELLS``) and
    ``FREE_SET_PER_JOINT * n``
    ranked random starts; sorted by ``E + V - F . tip``. Measured, not certified: a well no start descends into is
    missed."""
    F = np.asarray(force, dtype=float)
    starts = free_starts(m, F, FREE_SET_PER_JOINT * m.n)
    try:
        bare = Manipulator(m.segments).with_spring("linear")
        wells = find_equilibria_under_force(bare, stable_only=True)
        starts += [np.clip(e.q, -m.joint_limits, m.joint_limits) for e in list(wells)[:FREE_SET_WELLS]]
    except (NoEquilibriumError, InvalidParameterError):
        pass                                    # no well, or too many to list: the random starts only
    found, _, refused = free_stable(m, F, starts)
    if not found and refused is not None:
        raise refused
    return sorted(found, key=lambda e: e.energy - float(F @ e.tip))


def rest_configuration(m: Manipulator, *, which: str = "least_energy") -> Equilibrium:
    """The least-energy stable rest configuration (``F = 0``): a global minimum of ``E(q)`` inside the range.

    Exact and without a search: ``E`` is a sum of one-joint energies, so its minima are the products of the
    segments' wells (:func:`rest_points` with ``stable_only=True``) and the least energy is the sum of the
    segments' least well energies. A chain of monotonic segments has one well per segment (straight when
    the segments are symmetric, pre-bent with asymmetric preloads): the answer is that product.

    Ties (wells within ``ENERGY_TIE * m.torque_scale`` of the least energy, e.g. the ``2^k`` mirror images
    of a mirror-symmetric chain with ``k`` bistable segments) go to the one nearest to straight (smallest
    ``max |q_i|``), then to larger ``q_1``, then larger ``q_2``, ... (angles rounded to ``ANGLE_DIGITS``
    decimals): the first member of ``find_equilibria_under_force(m, stable_only=True)``.

    The rule is applied separably, which gives the same answer as applying it to every well of the chain
    (``2^k`` of them) without listing them: a combination of wells exceeds the least energy by the sum of
    its segments' excesses over their own least well energy, so the least ``max |q_i|`` of a tie is the
    least bound ``M`` for which the segments' least excesses among their wells with ``|q_j| <= M`` add up
    to at most the tolerance, and the lexicographically largest tie under that bound takes, segment by
    segment, the largest ``q_j`` among its wells with ``|q_j| <= M`` that still leaves the other segments a
    tie (with exactly equal wells, e.g. mirror images: simply each segment's largest well with
    ``|q_j| <= M``). It is *not* "each segment
    its own well nearest to straight": a segment takes a well farther from straight than its nearest one
    when another segment's wells fix ``max |q_i|`` anyway and the farther one has the larger ``q_j``
    (``tests/analyses/equilibria/test_rest.py`` has such a chain, and one whose near-ties add up past the tolerance).

    A chain with dead loads (weights under gravity, joint forces: the sagged shape) is no longer a sum of one-joint
    energies: its least potential ``E + V`` with the tip free is searched over the closed joint range
    (:func:`~.equilibrium.least_energy_free`: measured, ``status="converged"``; a joint may rest on its stop).

    Parameters
    ----------
    m : Manipulator
    which : {"least_energy"}
        The only rule.

    Returns
    -------
    Equilibrium
        ``control="force"``, ``force = (0, 0)``, ``stable=True``, classified by the full Hessian,
        ``status="exact"`` (``"converged"`` under dead loads).

    Raises
    ------
    InvalidParameterError
        (``ValueError``, ``field="which"``) an unknown rule.
    NoEquilibriumError
        (``RuntimeError``) some segment has no well inside its range (its unloaded energy decreases
        towards a joint limit): the chain has no stable rest configuration.
    """
    if which != "least_energy":
        raise InvalidParameterError(f"which must be 'least_energy', got {which!r}", field="which")
    if m.loaded:
        return least_energy_free(m)
    if not m.linear_springs:
        return _slack_rest(m)
    q = _least_energy_well(m)
    res = LocalResult(q, np.zeros(2), True, "exact", 0)
    return make_equilibrium(m, res, constrained=False, status="exact")


def _least_energy_well(m: Manipulator) -> np.ndarray:
    """The rule of :func:`rest_configuration` on the product of the segments' wells, without enumerating it
    (:func:`_tie_rule`)."""
    wells, energies = [], []
    for j, (q, d2, e) in enumerate(_segment_points(m)):
        stable = _factor_kind(m, d2) == 1
        if not stable.any():
            raise NoEquilibriumError(
                f"segment {j + 1} has no well inside its range (no non-degenerate minimum of its unloaded energy "
                "there): the chain has no stable rest configuration", status="no_rest_configuration")
        wells.append(q[stable])
        energies.append(e[stable])
    chosen = _tie_rule(wells, energies, ENERGY_TIE * m.torque_scale)
    return np.array([w[i] for w, i in zip(wells, chosen)])


def _tie_rule(wells: list[np.ndarray], energies: list[np.ndarray], tol: float) -> list[int]:
    """Per segment, the index of its well in the least-energy combination chosen by :func:`rest_configuration`'s rule.

    A combination of wells exceeds the least energy by the sum of its segments' excesses ``d_j`` over their
    own least well energy; it ties when that sum is at most ``tol``. The least ``max |q_i|`` of a tie is the
    least bound ``M`` (over the wells' ``|q|``) for which the segments' least excesses among their wells with
    ``|q_j| <= M`` add up to at most ``tol``; then, segment by segment, the largest ``q_j`` with ``|q_j| <= M``
    whose excess still leaves the remaining segments' least excesses within the budget. Exact for the
    product set: each step checks that a completion exists.
    """
    n = len(wells)
    rounded = [_rounded(w) for w in wells]
    excess = [e - e.min() for e in energies]

    def least(j: int, bound: float) -> float:
        ok = np.abs(rounded[j]) <= bound
        return float(excess[j][ok].min()) if ok.any() else math.inf

    for bound in np.unique(np.concatenate([np.abs(w) for w in rounded])).tolist():
        if sum(least(j, bound) for j in range(n)) <= tol:
            break
    chosen = []
    used = 0.0
    for j in range(n):
        rest = sum(least(k, bound) for k in range(j + 1, n))
        ok = (np.abs(rounded[j]) <= bound) & (used + excess[j] + rest <= tol)
        i = int(np.flatnonzero(ok)[np.argmax(rounded[j][ok])])
        chosen.append(i)
        used += float(excess[j][i])
    return chosen


def _slack_wells(m: Manipulator, j: int) -> tuple[np.ndarray, np.ndarray]:
    """Segment ``j``'s unloaded wells under its springs' laws over the *closed* range: ``(angles, energies)``.

    Inside the range the wells are the zeros of the torque of each taut/slack option (its Laurent polynomial's
    roots on the unit circle, in the option's intervals, polished by Newton on the torque) with ``E'' > 0``
    (one-sided at a spring's rest length); a stop is a well where the energy still falls towards it (the stop then
    pushes back: contact torque ``-s dE/dq(s lim) > 0``). A segment whose least energy (0) is reached on an interval
    where both springs are slack has a free joint: refused by name (:class:`UnsupportedError`, ``field`` the
    segment, status ``free_joint``)."""
    from ...model.segment import torque_coefficients
    from .tension_only_homotopy import joint_options

    seg = m.segments[j]
    tol = 1e-9 * m.torque_scale
    lim = seg.joint_limit
    qs: list[float] = []
    for o in joint_options(seg):
        if o.side:
            slope = float(-seg.torque(o.side * lim))             # dE/dq at the stop
            if o.side * slope < -tol:
                qs.append(o.side * lim)
            continue
        if o.loose:
            raise UnsupportedError(
                f"both springs of segment {j} are slack over part of its range with no tip force: its joint is free "
                "there (no stiffness) and the unloaded chain's configuration is not determined", field=f"segments[{j}]",
                status="free_joint")
        poly = torque_coefficients(seg.a, seg.b, seg.k1 * o.taut[0], seg.k2 * o.taut[1], seg.L1_0, seg.L2_0)
        roots = np.roots([poly[2], poly[1], poly[0], poly[-1], poly[-2]])
        for z in roots[(np.abs(np.abs(roots) - 1.0) < 1e-6) & (roots.real > 0.0)]:
            q = 2.0 * float(np.angle(z))
            for _ in range(3):
                d = float(seg.dtorque(q))
                if d == 0.0:
                    break
                q = q - float(seg.torque(q)) / d
            if o.contains(q) and abs(q) <= lim and float(-seg.dtorque(q)) > tol:
                qs.append(q)
    q = np.array(qs, dtype=float)
    q = np.where(np.abs(np.abs(q) - lim) <= 1e-9, np.sign(q) * lim, q)      # a well on the stop is the stop
    q = np.sort(q)
    q = q[np.concatenate([[True], np.diff(q) > 1e-9])] if q.size else q
    return q, np.asarray(seg.energy(q), dtype=float).reshape(-1)


def _slack_rest(m: Manipulator) -> Equilibrium:
    """:func:`rest_configuration` of a chain with tension-only springs: the same rule on the segments' wells under
    their laws, stops included (:func:`_slack_wells`)."""
    wells, energies = [], []
    for j in range(m.n):
        q, e = _slack_wells(m, j)
        if not q.size:
            raise NoEquilibriumError(f"segment {j + 1} has no well in its closed range under its springs' laws: the "
                                     "chain has no stable rest configuration", status="no_rest_configuration")
        wells.append(q)
        energies.append(e)
    chosen = _tie_rule(wells, energies, ENERGY_TIE * m.torque_scale)
    q = np.array([w[i] for w, i in zip(wells, chosen)])
    lim = m.joint_limits
    side = np.where(q >= lim, 1.0, np.where(q <= -lim, -1.0, 0.0))
    contact = np.where(side != 0.0, side * m.torques(q), 0.0)       # -s dE/dq = s M
    free = side == 0.0
    w = np.array([float(-m.segments[i].dtorque(q[i])) for i in np.flatnonzero(free)])
    return Equilibrium(q=q, energy=float(m.energy(q)), force=np.zeros(2), morse_index=0, stable=True,
                       solver=SolverInfo("exact", 0), tip=m.tip(q), control="force", status="exact",
                       hessian_eigenvalues=np.sort(w), springs=m.springs, stops=(side != 0.0, np.maximum(contact, 0)))


