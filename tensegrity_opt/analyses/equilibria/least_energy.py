"""The least-energy stable equilibrium for a tip displacement (the paper's problem): the global search.

``solve_equilibrium(m, dx, dy)`` holds the tip at ``(2 sum(b) - dx, dy)`` and returns the stable
equilibrium of least energy among those found: damped Newton on the KKT system from every seed
(buckling modes with both signs, mirrors, arcs, random starts, the caller's ``q0``; on chains of
bistable segments also every combination of the segments' wells and uniform random configurations
projected onto the tip constraint), each classified by the inertia of the reduced Hessian; IPOPT
(``min E`` s.t. ``tip = target``) from every seed when Newton finds no stable one or a segment is
bistable; or, with ``method="homotopy"``, the least-energy stable member of the certified complete
set (:func:`tensegrity_opt.analyses.equilibria.all_equilibria.find_equilibria`). Measured complete on random
multistable chains against the homotopy (``tests/analyses/equilibria/test_completeness.py``);
certified only with ``method="homotopy"``.

The pieces (the :class:`~.equilibrium.Equilibrium` result, local solves, the exact special cases)
are in :mod:`.equilibrium`. Thread-safe (solvers are cached per thread).
"""

from __future__ import annotations

import math
from collections import Counter
from dataclasses import replace

import numpy as np

from ...errors import (
    InvalidParameterError,
    NoEquilibriumError,
    SolverError,
    UnreachableTargetError,
    UnsupportedError,
)
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...numerics import KERNEL_MAX, SAME_Q, LocalResult, chain_solver, distinct, distinct_indices, same
from ...outcome import SolverInfo
from .equilibrium import (
    Equilibrium,
    check_q0,
    classify_result,
    equilibrium_from,
    is_equilibrium,
    local_equilibrium,
    make_equilibrium,
    one_segment_equilibrium,
    straight_equilibrium,
)
from .lower_bound import energy_lower_bound
from .seeds import projected_sample, ranked_well_seeds, seed_starts, well_seeds
from .stability import inertia_of_reduced
from .tension_only import least_energy_slack

__all__ = ["solve_equilibrium", "search_stable", "certify_least", "WELLS_MAX"]


def solve_equilibrium(m: Manipulator, dx: float, dy: float = 0.0, *, q0=None, local: bool = False,
                      method: str = "auto", n_random: int | None = None,
                      max_modes: int | None = None, certify: bool = False, stops: bool = True) -> Equilibrium:
    """Least-energy stable equilibrium with the tip held at ``(2 sum(b) - dx, dy)``.

    Parameters
    ----------
    m : Manipulator
    dx, dy : float
        Tip deflection (length units); ``dx > 0`` shortens the chain.
    q0 : array_like (n,), optional
        A nearby configuration (continuation, control loops): a local solve from it
        is tried first and its solution competes with the global search.
    local : bool
        Only the local solve from ``q0`` (Newton on the KKT system, IPOPT as the fallback):
        the equilibrium on the branch through ``q0``, whatever its stability (read
        ``stable``). For control loops and finite differences along a branch.
    method : {"auto", "ipopt", "newton"}
        ``"auto"``: damped Newton on the KKT system from every seed, classified, the least-energy
        stable one kept — enough when every segment is monotonic (condition (4)); otherwise, or when
        Newton finds no stable equilibrium, IPOPT (``min E`` s.t. ``tip = target``) from every seed
        too, and the least-energy stable one of both. ``"ipopt"``: IPOPT from every seed only
        (slower; the methods are compared in the tests). ``"newton"``: the Newton part of
        ``"auto"`` alone — its work is bounded (at most 50 iterations per seed) and it raises
        :class:`NoEquilibriumError` where ``"auto"`` would go on with IPOPT; for monotonic chains
        it returns what ``"auto"`` returns whenever it returns. With ``local=True`` the methods
        differ only in the fallback: ``"newton"`` raises :class:`SolverError` where the others
        run IPOPT from ``q0``. ``"homotopy"``: the least-energy stable one of
        ``find_equilibria(method="homotopy")`` — *certified* (every equilibrium is known) when its
        ``status`` is ``"certified"`` (``solver.status`` ``"homotopy (certified)"``), else ``"converged"``
        (``solver.status`` says why the set is not certified); ``n <= 6``, seconds to minutes, needs PHCpack.

        On chains with bistable segments the search also starts from every combination of the
        segments' unloaded wells (up to ``WELLS_MAX``, projected onto the tip constraint); measured
        against the certified homotopy on 97 random multistable chains n = 2..5 it returned the
        least-energy stable equilibrium every time (``tests/analyses/equilibria/test_completeness.py``), and against an
        independent brute force for n = 6..10 (``benchmarks/search_check.py``). It is not certified.
    n_random, max_modes : int, optional
        Random starts and buckling-mode seeds (each used with both signs). Defaults: 8 and 6
        for chains of up to 64 segments, plus the two arc seeds of large deflections
        (:func:`tensegrity_opt.analyses.equilibria.seeds.arc_seeds`); 0 and 2 (no arcs) for longer ones, whose
        least-energy equilibria lie on the lowest modes' branches (each seed costs O(n) per iteration).
    certify : bool
        Prove the answer least: a rigorous lower bound on the energy of every configuration meeting the tip
        constraint inside the closed joint range (:func:`~.lower_bound.energy_lower_bound`: pattern boxes,
        the Lagrangian bound per box, branch and bound), carried as ``certificate`` (bound, gap, tolerance);
        ``status`` ``"certified"`` when the gap is within the tolerance. When the bound finds a lower
        configuration than the search's, it is polished by Newton and returned instead. Not with ``local``.
        Without it, chains of more than ``WELLS_MAX`` and at most ``BOUND_SEEDED_PATTERNS`` well patterns (9 to 14
        bistable segments) still run the bound's pattern sweep and one round of its Newton re-centrings
        (``BOUND_SEEDED_ROUNDS``) to find a lower configuration among all the patterns, without a certificate.
    stops : bool
        ``True`` (default): where the least-energy configurations press a joint against its range limit, the
        equilibrium resting on that stop (the closed range's search; ``at_stop``, ``contact_torques``).
        ``False``: only equilibria inside the open range, :class:`NoEquilibriumError` there (the loading-path
        analyses, which do not continue onto a stop, ask this). A tension-only chain is always searched over the
        closed range.

    Returns
    -------
    Equilibrium
        Stable (``morse_index == 0``) and of least energy among those found. When two
        mirror images tie (``dy = 0``) the one nearer ``q0`` wins, else the one with
        ``q_1 > 0``. Where the least-energy configurations press a joint against its range limit (no stable
        equilibrium inside the open range: a large deflection), the arm rests on that joint's stop
        ``|q_i| = pi - 2 beta_i``: the search of the closed range (:mod:`~.tension_only`, the same as for a
        tension-only chain) returns it with ``at_stop`` and its ``contact_torques``.

    Raises
    ------
    UnreachableTargetError
        (``ValueError``) when the target lies beyond the chain's reach (checked before any
        solve), or when IPOPT proves it infeasible within the joint range from every start.
    NoEquilibriumError, SolverError
        (``RuntimeError``) when no solve converged to a stable equilibrium inside the
        physical range; ``status`` lists the solver statuses met.

    Notes
    -----
    A chain with tension-only springs (``Segment(..., spring="tension_only")``) is solved by its own search
    (:mod:`~.tension_only`): the closed joint range, a joint may rest on its stop (``at_stop``,
    ``contact_torques``); IPOPT on the smooth slack problem from ``q0``, the linear law's answer, the stops and
    random starts, each solution made exact by Newton and checked in numpy: measured. ``certify=True`` adds the
    rigorous lower bound (each spring's curvature bounded on its taut and slack sides) and, where it stays open and
    ``n <= 4``, the least-energy stable member of the set certified by one homotopy per taut/slack/stop pattern
    (:mod:`~.tension_only_homotopy`); ``method="homotopy"`` answers from that set; other methods are refused
    (``field="method"``).
    """
    if not m.paper_model:
        return _solve_tension_only(m, dx, dy, q0=q0, local=local, method=method, certify=bool(certify),
                                   stops=bool(stops))
    return _solve_equilibrium(m, dx, dy, q0=q0, local=local, method=method, n_random=n_random, max_modes=max_modes,
                              certify=bool(certify), stops=bool(stops))


def _solve_tension_only(m: Manipulator, dx: float, dy: float, *, q0, local: bool, method: str,
                        certify: bool, stops: bool = True) -> Equilibrium:
    """:func:`solve_equilibrium` of a chain with tension-only springs or dead loads (:mod:`.tension_only`)."""

    if method not in ("auto", "ipopt", "homotopy"):
        what = "a chain with tension-only springs" if not m.linear_springs else "a chain with dead loads"
        raise UnsupportedError(f"method {method!r} models the paper's chain (linear springs, no dead load); {what} "
                               "is solved by its own search (method 'auto')"
                               + (" or its patterns' homotopy (method 'homotopy')" if not m.loaded else ""),
                               field="method", spring="linear" if m.linear_springs else "tension_only")
    if m.loaded and (method == "homotopy" or certify):
        unloaded_only(m, "solve_equilibrium(method='homotopy')" if method == "homotopy" else
                      "solve_equilibrium(certify=True)")
    target = m.check_reachable(dx, dy)
    if dx == 0.0 and dy == 0.0:
        # full extension: only the straight chain reaches it, an equilibrium where a tip force balances its torques
        # (else StraightNotEquilibriumError, as find_equilibria's empty set says)
        return straight_equilibrium(m)
    q0 = check_q0(m, q0, closed=True)           # the closed range: a start may rest on a stop
    if local and q0 is None:
        raise InvalidParameterError("local=True needs q0", field="q0")
    if method == "homotopy" and not local:
        return _least_certified(m, dx, dy, q0)
    best = least_energy_slack(m, dx, dy, target, q0=q0, local=local)
    if not stops and m.linear_springs and best.at_stop.any():
        raise NoEquilibriumError(
            "the least-energy configuration under the chain's loads rests on a joint stop "
            f"(joint {int(np.flatnonzero(best.at_stop)[0]) + 1}) and stops=False asks for the open range only",
            status="on_stop")
    if certify and not local:
        return _certify_slack(m, dx, dy, target, best)
    return best


#: Chains with tension-only springs of at most this many segments whose lower bound stays open are certified by their
#: patterns' homotopy under ``certify=True`` (n = 4 ~10 s on 2 cores).
CERTIFY_SET_MAX_N = 4


def _certify_slack(m: Manipulator, dx: float, dy: float, target: np.ndarray, best: Equilibrium) -> Equilibrium:
    """``certify=True`` for a chain with tension-only springs: the rigorous lower bound of every configuration of the
    closed range (:func:`~.lower_bound.energy_lower_bound`, each spring's curvature bounded on its taut and slack
    sides); where it stays open and ``n <= CERTIFY_SET_MAX_N`` (PHCpack present), the least-energy stable member of
    the patterns' certified set (:mod:`.tension_only_homotopy`)."""
    from ...numerics.homotopy import homotopy_available

    cert = energy_lower_bound(m, dx, dy, best.q, force=best.force)
    if cert.improved:                           # a lower configuration: polish it under the springs' laws
        try:
            cand = least_energy_slack(m, dx, dy, target, q0=np.clip(cert.q, -m.joint_limits, m.joint_limits),
                                      local=True)
            if cand.stable and cand.energy < best.energy:
                best = cand
        except (NoEquilibriumError, UnreachableTargetError, UnsupportedError):
            pass
    if cert.certified and cert.energy >= best.energy - cert.tolerance:
        return replace(best, certificate=cert, status="certified")
    if m.n <= CERTIFY_SET_MAX_N and homotopy_available():
        least = _least_certified(m, dx, dy, best.q)
        if least.status == "certified":
            return least if least.energy < best.energy - cert.tolerance else \
                replace(best, status="certified", solver=least.solver, certificate=None)
    return replace(best, certificate=cert)


def _solve_equilibrium(m: Manipulator, dx: float, dy: float, *, q0, local: bool, method: str, n_random: int | None,
                       max_modes: int | None, certify: bool | None, stops: bool = True) -> Equilibrium:
    """:func:`solve_equilibrium`; ``certify=None`` is the search alone (no lower bound of any kind)."""
    if certify is not None and not local and method in ("auto", "ipopt") and \
            (certify or (m.n >= 2 and not m.monotonic and WELLS_MAX < _pattern_count(m) <= BOUND_SEEDED_PATTERNS)):
        best = _solve_equilibrium(m, dx, dy, q0=q0, local=False, method=method, n_random=n_random,
                                  max_modes=max_modes, certify=None, stops=stops)
        if certify:
            return certify_least(m, dx, dy, best)
        # more well patterns than the search tries: the bound's pattern sweep and Newton re-centrings (a short
        # budget, no certificate) look for a lower configuration among all of them
        return _bound_polished(m, dx, dy, best, energy_lower_bound(m, dx, dy, best.q, force=best.force,
                                                                  max_seconds=math.inf, max_rounds=BOUND_SEEDED_ROUNDS,
                                                                  fine=12))[0]
    target = m.check_reachable(dx, dy)
    q0 = check_q0(m, q0)
    if local and q0 is None:
        raise InvalidParameterError("local=True needs a starting configuration q0", field="q0")
    if dx == 0.0 and dy == 0.0:
        return straight_equilibrium(m)
    if m.n == 1:
        return one_segment_equilibrium(m, target)
    if method not in ("auto", "ipopt", "newton", "homotopy"):
        raise InvalidParameterError(f"method must be 'auto', 'ipopt', 'newton' or 'homotopy', got {method!r}",
                                    field="method")
    if method == "homotopy" and not local:
        return _least_certified(m, dx, dy, q0)
    if local:
        res = local_equilibrium(m, target, q0)
        if not is_equilibrium(m, res, target, check_residual=False):
            if method == "newton":
                raise SolverError(f"Newton from q0 did not converge for dx={dx:g}, dy={dy:g}; method='auto' "
                                  "adds IPOPT", status=res.status)
            fallback = local_equilibrium(m, target, q0, minimize=True)
            if not is_equilibrium(m, fallback, target):
                raise SolverError(f"the local solve from q0 did not converge for dx={dx:g}, dy={dy:g}",
                                  status=f"newton: {res.status}; ipopt: {fallback.status}")
            res = fallback
        return make_equilibrium(m, res, constrained=True)
    short = m.n <= 64
    n_random = (8 if short else 0) if n_random is None else int(n_random)
    max_modes = (6 if short else 2) if max_modes is None else int(max_modes)
    starts = seed_starts(m, dx, dy, max_modes=max_modes, n_random=n_random, arcs=short)
    if q0 is not None:
        starts = np.vstack([q0, starts])
    descents = starts                   # where IPOPT starts (multistable chains)
    if (method == "auto" and not m.monotonic and m.n <= KERNEL_MAX and QUICK_ROUNDS
            and _pattern_count(m) <= WELLS_MAX):
        # the short way first: Newton from the seeds and the best-ranked well patterns, then the lower bound; when
        # the bound proves that candidate least, it is the answer (certified), else the whole search below
        quick = _quick_certified(m, dx, dy, target, q0, descents)
        if quick is not None:
            return quick
    if not m.monotonic and short:
        # the wells of the bistable segments (one per segment, every combination up to WELLS_MAX),
        # projected onto the tip constraint: Newton from each; IPOPT's descent from the lowest ones
        wells = well_seeds(m, dx, dy, hilltops=False, cap=WELLS_MAX)
        if _pattern_count(m) > WELLS_MAX:
            # more patterns than WELLS_MAX: those whose tip the chain reaches with the least elastic work first
            wells = np.vstack([ranked_well_seeds(m, dx, dy, RANKED_WELLS), wells])
        if wells.shape[0]:
            starts = np.vstack([starts, wells])
            order = np.argsort([m.energy(q) for q in wells], kind="stable")[:WELL_DESCENTS]
            descents = np.vstack([descents, wells[order]])
        if m.n <= KERNEL_MAX and LEAST_PROJECTED_PER_JOINT and method != "newton":
            # uniform random configurations projected onto the tip constraint (the compiled Newton:
            # microseconds a start): minima close to the joint limits that no well pattern reaches
            starts = np.vstack([starts, projected_sample(m, target, LEAST_PROJECTED_PER_JOINT * m.n,
                                                         LEAST_PROJECTED_SEED)])
    statuses: dict[str, int] = {}
    found: list[Equilibrium] = []
    if method == "auto":
        # Newton on the KKT system from every seed (every stationary point nearby, ~0.1 ms each).
        # With monotonic segments that finds the least-energy stable equilibrium (checked against
        # IPOPT from the same seeds on grids of targets, tests/analyses/equilibria/test_equilibrium.py); with
        # bistable segments (K <= 0) it often lands on saddles only, so IPOPT's descent from every
        # seed is added and the union decides.
        found, _ = search_stable(m, target, starts, statuses, minimize=False, least=True)
        if found and m.monotonic:
            return _pick(found, q0, m.torque_scale)
    if method == "newton":
        found, n_unstable = search_stable(m, target, starts, statuses, minimize=False, least=True, fallback=True)
        if found:
            return _pick(found, q0, m.torque_scale)
        raise NoEquilibriumError(f"Newton found no stable equilibrium for dx={dx:g}, dy={dy:g} from "
                                 f"{len(starts)} starts ({n_unstable} unstable ones); method='auto' adds IPOPT",
                                 status=_summary(statuses))
    stable, n_unstable = search_stable(m, target, descents, statuses, minimize=True)
    stable = found + [e for e in stable if not any(same(e.q, f.q) for f in found)]
    if stable:
        return _pick(stable, q0, m.torque_scale)
    if n_unstable:
        raise NoEquilibriumError(
            f"no stable equilibrium found for dx={dx:g}, dy={dy:g} ({n_unstable} unstable ones)",
            status=_summary(statuses))
    ipopt = {k: v for k, v in statuses.items() if not k.startswith("Newton")}
    if ipopt and all(k.startswith("Infeasible_Problem_Detected") for k in ipopt):
        raise UnreachableTargetError(
            f"the target for dx={dx:g}, dy={dy:g} lies within the chain's length but outside the workspace "
            f"of the physical joint range |q| < pi - 2 beta: IPOPT found it infeasible from all "
            f"{sum(ipopt.values())} starts", field="dx", status=_summary(statuses))
    if any(k.endswith("(on joint limit)") and not k.startswith("Infeasible") for k in ipopt):
        # the least-energy configurations press a joint against its range limit |q| = pi - 2 beta (a spring
        # length reaches zero): the arm rests on that stop (the search of the closed range, its contact torque)
        if stops:
            return least_energy_slack(m, dx, dy, target, q0=q0)
        raise NoEquilibriumError(
            f"no equilibrium inside the physical range for dx={dx:g}, dy={dy:g}: the least-energy "
            "configurations press a joint against its range limit |q| = pi - 2 beta (a spring "
            "length reaches zero; solve_equilibrium with stops=True returns the arm resting on that stop)",
            status=_summary(statuses))
    raise SolverError(f"no local solve converged inside the physical range for dx={dx:g}, dy={dy:g}",
                      status=_summary(statuses))


#: Well patterns of a multistable chain tried by Newton (every combination of the segments' wells
#: while there are at most this many), and how many of them (lowest projected energy first) IPOPT
#: also descends from.
WELLS_MAX = 256
WELL_DESCENTS = 8
#: Chains with more well patterns than WELLS_MAX also start Newton from this many patterns ranked by the
#: elastic work of moving their tip to the target (:func:`.seeds.ranked_well_seeds`).
RANKED_WELLS = 64
#: Chains of more than WELLS_MAX and at most this many well patterns also run the lower bound's pattern sweep and
#: this many rounds of its Newton re-centrings of the boxes left open (:func:`~.lower_bound.energy_lower_bound`; a
#: limit on the work, not on the time: the answer does not depend on the machine) in the default search, for a
#: lower configuration.
BOUND_SEEDED_PATTERNS = 1 << 14
BOUND_SEEDED_ROUNDS = 1
#: Multistable chains with compiled kernels (n <= KERNEL_MAX) also start Newton from this many uniform
#: random configurations per joint, projected onto the tip constraint (methods "auto" and "ipopt"; the
#: bounded "newton" method keeps the seeds and wells only) (an n = 7 chain's least-energy
#: minimum, at 99.8 % of a joint's range, was reached by none of 128 well descents, found from ~3000
#: random projected starts).
LEAST_PROJECTED_PER_JOINT = 500
LEAST_PROJECTED_SEED = 9090
#: The short way of the multistable search (method "auto", n <= KERNEL_MAX, at most WELLS_MAX well patterns):
#: Newton from the seeds and the QUICK_WELLS well patterns of least elastic work
#: (:func:`.seeds.ranked_well_seeds`), then :func:`~.lower_bound.energy_lower_bound` limited to QUICK_ROUNDS rounds
#: of its refinement and QUICK_BOXES boxes (limits on the work, not the time: the answer does not depend on the
#: machine). When the bound proves the candidate least (the gap within its tolerance) the candidate is the answer,
#: ``status`` ``"certified"`` with its ``certificate``; else the whole search runs. The bistable n = 8 chain of
#: benchmark case 9: ~8-14 ms where it certifies instead of ~300 ms. 0 rounds: never.
QUICK_WELLS = 16
QUICK_ROUNDS = 2
QUICK_BOXES = 512


def _quick_certified(m: Manipulator, dx: float, dy: float, target: np.ndarray, q0: np.ndarray | None,
                     first: np.ndarray) -> Equilibrium | None:
    """The short way of the multistable search (:data:`QUICK_ROUNDS`): the least-energy stable equilibrium Newton
    reaches from ``first`` (the seeds, and ``q0``) and the best-ranked well patterns, returned with its certificate
    when the lower bound proves it least; ``None`` otherwise (the caller runs the whole search)."""
    ranked = ranked_well_seeds(m, dx, dy, QUICK_WELLS)
    starts = np.vstack([first, ranked]) if ranked.shape[0] else first
    found, _ = search_stable(m, target, starts, {}, minimize=False, least=True)
    if not found:
        return None
    if dy == 0.0 and m == m.mirrored():
        # a mirror-symmetric chain at dy = 0: the mirror image of each least one ties with it (the whole search
        # meets both and picks by _pick's rule)
        mirrors, _ = search_stable(m, target, -np.array([e.q for e in found]), {}, minimize=False, least=True)
        found = found + [e for e in mirrors if not any(same(e.q, f.q) for f in found)]
    best = _pick(found, q0, m.torque_scale)
    cert = energy_lower_bound(m, dx, dy, best.q, force=best.force, max_seconds=math.inf, max_rounds=QUICK_ROUNDS,
                              max_boxes=QUICK_BOXES)
    if not (cert.certified and not cert.improved and cert.energy >= best.energy - cert.tolerance):
        return None
    return replace(best, certificate=cert, status="certified")


def _pattern_count(m: Manipulator) -> float:
    """The number of well patterns (one unloaded well per segment) of a chain."""
    return math.prod(float(max(1, len(s.critical_angles()[0]))) for s in m.segments)


def certify_least(m: Manipulator, dx: float, dy: float, best: Equilibrium) -> Equilibrium:
    """``best`` (the search's least-energy stable equilibrium) with the certificate of
    :func:`~.lower_bound.energy_lower_bound`; a lower configuration the bound found replaces it (Newton-polished
    and classified: kept when stable and lower)."""
    if best.status == "certified" and best.certificate is not None:
        return best                                           # the search's short way proved it already
    best, cert = _bound_polished(m, dx, dy, best, energy_lower_bound(m, dx, dy, best.q, force=best.force))
    proven = cert.certified and cert.energy >= best.energy - cert.tolerance and best.status != "exact"
    status = "certified" if proven else best.status          # "exact" (one configuration) stays exact
    return replace(best, certificate=cert, status=status)


def _bound_polished(m: Manipulator, dx: float, dy: float, best: Equilibrium, cert) -> tuple[Equilibrium, object]:
    """``best``, or the lower configuration the bound found (Newton-polished, classified; kept when stable and
    lower), with the bound."""
    if cert.improved:
        target = m.target(dx, dy)
        res = local_equilibrium(m, target, cert.q, cert.force)
        if is_equilibrium(m, res, target):
            cand = make_equilibrium(m, res, constrained=True)
            if cand.stable and cand.energy < best.energy:
                best = cand
    return best, cert


def _least_certified(m: Manipulator, dx: float, dy: float, q0: np.ndarray | None) -> Equilibrium:
    """The least-energy stable equilibrium of the homotopy's complete set (``status`` says whether
    that set is certified)."""
    from .all_equilibria import find_equilibria

    eqs = find_equilibria(m, dx, dy, method="homotopy")
    stable = [e for e in eqs if e.stable]
    label = "homotopy (certified)" if eqs.certified else f"homotopy (NOT certified: {eqs.message})"
    if not stable:
        raise NoEquilibriumError(f"no stable equilibrium exists for dx={dx:g}, dy={dy:g} ({len(eqs)} unstable ones"
                                 f"{'' if eqs.certified else ' found'}; {eqs.message})", status=label)
    best = _pick(stable, q0, m.torque_scale)
    return replace(best, solver=SolverInfo(label, best.solver.iterations),
                   status="certified" if eqs.certified else "converged")


def search_stable(m: Manipulator, target: np.ndarray, starts: list[np.ndarray], statuses: dict[str, int], *,
            minimize: bool, least: bool = False, fallback: bool | None = None) -> tuple[list[Equilibrium], int]:
    """Local solves from every start; the distinct stable equilibria and the count of unstable ones.

    ``least`` (Newton only): just the stable ones of least energy (within the tie tolerance of
    :func:`_pick`), found by classifying the converged points in order of energy until the first
    stable one; the unstable count then covers only the points classified (all of them when none
    is stable).
    """
    if not minimize:
        return _search_stable_newton(m, target, starts, statuses, least,
                                     m.monotonic if fallback is None else fallback)
    candidates: list[LocalResult] = []
    for res in (local_equilibrium(m, target, q, minimize=True) for q in starts):
        ok = is_equilibrium(m, res, target, check_residual=True)
        _count(statuses, res.status, res.on_bound, ok)
        if ok:
            candidates.append(res)
    stable: list[Equilibrium] = []
    n_unstable = 0
    for res in distinct(candidates):
        inertia, energy, tip = classify_result(m, res, True)
        if inertia.stable:
            stable.append(equilibrium_from(res, inertia, energy, tip, True, springs=m.springs))
        else:
            n_unstable += 1
    return stable, n_unstable


def _search_stable_newton(m: Manipulator, target: np.ndarray, starts, statuses: dict[str, int], least: bool,
                          fallback: bool = True) -> tuple[list[Equilibrium], int]:
    """:func:`search_stable` by Newton from every start: only converged points are looked at, only
    the distinct ones are classified (the first of each group of coinciding points, in the order of
    the starts; with ``least`` and more starts than one kernel call takes, only the rows up to the least
    stable energy are compared), only the stable ones become objects (plain
    floats: a global search has ~10-20 starts)."""
    # ``fallback=False`` (multistable chains under method "auto": hundreds of well starts, IPOPT's
    # descents after): a start the compiled Newton did not settle is dropped rather than run again by
    # the Python method (~3 ms each)
    b = chain_solver(m).newton_kkt_seeds(target, starts, SAME_Q, python_fallback=fallback)
    energy = b.energy.tolist()
    if b.distinct is not None:
        # one kernel call settled every start (all converged, no Python-method row) and compared the
        # converged points inside the range (the rule of tensegrity_opt.numerics.distinct)
        idx = np.flatnonzero(b.distinct).tolist()
        dedupe = False
        bound = int(np.count_nonzero(b.on_bound))
        _count(statuses, "Newton_Converged", False, True, len(energy) - bound)
        _count(statuses, "Newton_Converged", True, False, bound)
    else:
        on_bound = b.on_bound.tolist()
        inside = b.success & ~b.on_bound
        good = inside.tolist()
        for j in np.flatnonzero(inside & np.isnan(b.energy)).tolist():
            good[j] = is_equilibrium(m, b.result(j), target, check_residual=False)   # a Python-method row
        for (status, bound, ok), count in Counter(zip(b.status, on_bound, good)).items():
            _count(statuses, status, bound, ok, count)
        idx = [j for j, ok in enumerate(good) if ok]
        # ``least``: only the points up to the least stable energy are looked at, deduplicated as they are
        # met (below); the others: every distinct one
        dedupe = least
        if not least:
            idx = distinct_indices(b.q, idx)
    known = {}                                      # Python-method rows: classified from the model
    for j in idx:
        if energy[j] != energy[j]:
            known[j] = classify_result(m, b.result(j), True)
            energy[j] = known[j][1]
    stable: list[tuple[int, Equilibrium]] = []
    n_unstable = 0
    e_max = math.inf
    ts = m.torque_scale
    Q = b.q
    order = sorted(idx, key=energy.__getitem__) if least else idx
    if dedupe:
        # the thousands of starts of a multistable chain converge to a few points: only the rows up to the least
        # stable energy are compared, each with the points classified so far, and a new point stands for its
        # group by the group's first row in the order of the starts (the rule of tensegrity_opt.numerics.distinct:
        # the rows of a group converged to one point, their energies within rounding; searched near its energy)
        rows = np.asarray(order, dtype=int)
        e_rows = np.asarray([energy[j] for j in order])
        seen = np.empty((len(order), m.n))
        k = 0
    for j in order:
        if energy[j] > e_max:
            break                                   # beyond the least stable energy and its ties
        if dedupe:
            if k and bool(same(seen[:k], Q[j]).any()):
                continue
            seen[k] = Q[j]
            k += 1
            w = 1e-9 * max(ts, abs(energy[j]))
            near = rows[np.searchsorted(e_rows, energy[j] - w, "left"):np.searchsorted(e_rows, energy[j] + w, "right")]
            j = int(near[same(Q[near], Q[j])].min())
        inertia, e, tip = (known[j] if j in known else
                           (inertia_of_reduced(b.reduced_hessian[j], scale=ts), energy[j], b.tip[j]))
        if inertia.stable:
            if least and e_max == math.inf:
                e_max = e + _TIE * max(ts, abs(e))
            stable.append((j, Equilibrium(q=b.q[j].copy(), energy=e, force=b.force[j].copy(),
                                          morse_index=inertia.morse_index, stable=True,
                                          solver=SolverInfo(b.status[j], int(b.iterations[j])),
                                          tip=np.array(tip, dtype=float), springs=m.springs,
                                          hessian_eigenvalues=inertia.eigenvalues)))
        else:
            n_unstable += 1
    if least:                                       # the ties in the order of the starts
        stable.sort(key=lambda item: item[0])
    return [e for _, e in stable], n_unstable


def _count(statuses: dict[str, int], status: str, on_bound: bool, ok: bool, times: int = 1) -> None:
    """Tally ``times`` local solves' outcome under their status (with why they were rejected)."""
    if times <= 0:
        return
    key = status if ok else (status + (" (on joint limit)" if on_bound else " (rejected)"))
    statuses[key] = statuses.get(key, 0) + times


#: Energies within this relative distance of the least one tie (mirror images; the same point twice),
#: relative to the larger of the energy and the chain's torque scale ``k c^2`` (an energy).
_TIE = 1e-9


def _pick(stable: list[Equilibrium], q0: np.ndarray | None, scale: float) -> Equilibrium:
    e_min = min(e.energy for e in stable)
    tol = _TIE * max(scale, abs(e_min))
    best = [e for e in stable if e.energy <= e_min + tol]
    if q0 is not None:
        return min(best, key=lambda e: float(np.linalg.norm(e.q - q0)))
    pos = [e for e in best if _first_sign(e.q) > 0]
    return (pos or best)[0]


def _first_sign(q: np.ndarray) -> float:
    vals = q.tolist()
    if vals and math.isfinite(sum(vals)):           # plain floats: the common (finite) case
        t = 1e-9 * max(1e-300, max(abs(v) for v in vals))
        return next((1.0 if v > 0 else -1.0 for v in vals if abs(v) > t), 0.0)
    nz = q[np.abs(q) > 1e-9 * max(1e-300, float(np.abs(q).max()))]
    return float(np.sign(nz[0])) if nz.size else 0.0


def _summary(statuses: dict[str, int]) -> str:
    return ", ".join(f"{k} x{v}" for k, v in sorted(statuses.items()))
