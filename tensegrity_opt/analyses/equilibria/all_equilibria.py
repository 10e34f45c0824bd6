"""Every equilibrium for a prescribed tip displacement: minima, saddles and maxima.

Two methods, one result type (:class:`EquilibriumSet`, a sorted read-only sequence of
:class:`~tensegrity_opt.Equilibrium` that also says what it claims):

``method="search"`` (default, any ``n``)
    The KKT system ``grad E(q) = J(q)^T F``, ``tip(q) = target`` (n + 2 equations in ``q, F``) is
    solved by damped Newton (CasADi residual and exact Jacobian) from many seeds: every buckling
    mode with both signs at several amplitudes, random starts, the wells of bistable segments
    (:func:`tensegrity_opt.analyses.equilibria.seeds.well_seeds`), uniform random configurations projected
    onto the tip constraint, mirror images, and IPOPT's minima (chains of up to 4 monotonic segments: only where
    Newton found nothing, ``MONOTONIC_NO_DESCENT_MAX_N``). Complete *in practice* for n <= 5: measured
    against the homotopy on 104 random multistable chains (``tests/analyses/equilibria/test_completeness.py``);
    for n >= 6 against an independent brute force (``benchmarks/search_check.py``), where it misses some;
    never certified (``status="searched"``).
``method="homotopy"`` (``n <= HOMOTOPY_MAX_N``; needs PHCpack)
    Every isolated complex root of the polynomial KKT system by PHCpack: the parameter homotopy from the
    cached roots of a generic instance (:mod:`tensegrity_opt.numerics.parameter_homotopy`), the polyhedral
    homotopy (:mod:`tensegrity_opt.numerics.homotopy`) when paths fail; the real roots inside the physical
    range, polished by Newton, then each proven by Krawczyk's test in ball arithmetic
    (:mod:`tensegrity_opt.numerics.krawczyk`: the only equilibrium in its box, real, inside the range, the boxes
    pairwise disjoint; its Morse index proven where decidable), the proofs in :attr:`EquilibriumSet.certificate`.
    ``status="certified"`` when every path ended, every real root polished and every equilibrium proven, else
    ``"uncertified"``. Which complex roots are real is decided in floating point (their distance from the real
    set against a tolerance); the certificate also proves the roots classed non-real within
    ``krawczyk.NEAR_REAL`` of the real set non-real, and the real roots within it beyond the range beyond it
    (counted there; the farther ones are classed in floating point, by that margin; measured: non-real roots lie
    0.04 or more from the real set).

Solutions outside the physical range or on a joint limit are dropped, duplicates merged, the rest
classified by the Morse index of the reduced Hessian and sorted by energy.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from ...errors import (
    InvalidParameterError,
    SolverError,
    StraightNotEquilibriumError,
    UnreachableTargetError,
)
from ...model.loads import unloaded_only
from ...model.manipulator import Manipulator
from ...numerics import KERNEL_MAX, chain_solver, distinct, distinct_indices
from ...numerics.krawczyk import IntervalCertificate, prove_equilibria
from ...outcome import Outcome, freeze
from ...timelimit import time_limit
from .equilibrium import (
    RESIDUAL_TOL,
    Equilibrium,
    check_q0,
    is_equilibrium,
    local_equilibrium,
    make_equilibrium,
    one_segment_equilibrium,
    straight_equilibrium,
)
from .seeds import projected_sample, seeds, well_seeds

__all__ = ["find_equilibria", "EquilibriumSet", "searched_set", "homotopy_set", "certify_set", "HOMOTOPY_MAX_N"]

#: Uniform random configurations projected onto the tip constraint per joint (default of ``n_projected``),
#: and their generator's seed.
#: Measured on the 104 oracle chains (n = 2..5): 60 n missed 1 equilibrium, 100 n and 150 n none;
#: running the Python Newton again from the starts the kernels did not converge found nothing more
#: and doubled the time. A start not converged in the kernels is dropped. Multistable chains of up to
#: SHORT_N segments (equilibria multiply; compiled kernels: microseconds a start) SHORT_PER_JOINT: an
#: n = 6 chain whose homotopy set has 9 equilibria showed 8 with 100 n and 1200 starts, 9 with 3000.
#: Chains beyond the compiled kernels (n > KERNEL_MAX: the Python Newton, ~1 ms a start) take
#: LONG_PER_JOINT (uniform n = 20 at dx = 0.3: 24 equilibria without the sample, 36 with 20 n in
#: 0.28 s, 38 with 100 n in 0.9 s).
PROJECTED_PER_JOINT = 100
LONG_PER_JOINT = 20
SHORT_N = 6
SHORT_PER_JOINT = 500
PROJECTED_SEED = 4242
#: Chains of monotonic segments (condition (4)) of up to this many segments skip IPOPT's descents from the mode
#: seeds in ``find_equilibria`` when the Newton search found equilibria (4-6 IPOPT solves, ~3 ms each: half the
#: time of the paper's chain). Measured on random monotonic chains (uniform, heterogeneous, asymmetric preloads;
#: dx up to 0.8 of the length, dy != 0 in 70 %): for n = 2..4 the descents added nothing (328 chains and targets,
#: 840 equilibria, the 26 empty sets the same; none either among the n <= 4 ones of 577 cases n = 2..8), and
#: the search without them equals the certified homotopy on 50 random monotonic chains n = 2..4 (87 equilibria;
#: ``tests/analyses/equilibria/test_completeness.py`` keeps two). On longer chains they added 1 stable
#: equilibrium of 3213 (n = 8, a large deflection): those keep them. Where Newton finds nothing they always
#: run: they tell an empty set from an unreachable target.
MONOTONIC_NO_DESCENT_MAX_N = 4
#: An IPOPT descent pressed against a joint limit counts as reaching the target (the evidence that the target is
#: reachable inside the range when no equilibrium lies inside it) when its tip is within this fraction of the
#: chain's straight length of the target.
TIP_TOL = 1e-6

#: Longest chain the homotopy method accepts (paths on general chains: 8, 96, 832, 6272, 43648 for
#: n = 2..6; the parameter homotopy with its batched tracker takes ~0.25 s for n = 4, ~2 s for n = 5, ~20 s for
#: n = 6 on 2 cores).
HOMOTOPY_MAX_N = 6
#: Longest chain with tension-only springs ``method="homotopy"`` takes (a homotopy per taut/slack/stop pattern
#: that may reach the target: n = 4 ~10 s on 2 cores, n = 5 minutes).
SLACK_HOMOTOPY_MAX_N = 5


@dataclass(frozen=True)
class EquilibriumSet(Outcome, Sequence):
    """Every equilibrium an analysis found, sorted, and what the set claims: a read-only sequence of
    :class:`~tensegrity_opt.Equilibrium` (``len``, iteration, indexing, slicing give a tuple, ``bool``).

    An empty set is an answer, not a failure: no equilibrium lies inside the physical range (proven when
    ``certified``); its ``message`` says so and why. Its ``status`` is the one its method gives a non-empty set
    (the search's ``searched``: complete in practice; the homotopy's ``certified``: proven).

    Attributes
    ----------
    equilibria : tuple of Equilibrium
        The equilibria, without duplicates, sorted (by energy, or the total potential under a dead load).
    method : str
        How they were found: ``"search"``, ``"homotopy"``, ``"exact"`` (the unloaded product of
        :func:`~tensegrity_opt.analyses.equilibria.rest.find_equilibria_under_force`), or ``"straight"`` /
        ``"closed_form"`` for the trivial cases.
    status : str
        What the set claims (:attr:`STATUSES`): ``certified``, ``uncertified``, ``searched`` or ``exact``;
        every one but ``uncertified`` is a success.
    message : str
        The same in a sentence: the homotopy's report (its paths, failures and real roots, and why it is not
        certified), the search's local solves, or the exact case.
    paths, failed_paths : int
        Homotopy paths tracked and failed (0 for the other methods).
    seconds : float
        Wall time of the homotopy solver (0 for the other methods).
    certificate : IntervalCertificate or None
        The homotopy's interval proofs (:class:`~tensegrity_opt.numerics.krawczyk.IntervalCertificate`: one box
        per equilibrium, in the set's order, with the proven Morse indices); ``None`` for the other methods.
    certified : bool
        The set is proven complete: ``status`` is ``certified`` or ``exact``.
    """

    STATUSES: ClassVar[dict[str, str]] = {
        "certified": "the polynomial homotopy proved the set complete: every path ended, every real root inside the "
                     "range polished onto an equilibrium, no two distinct roots merged, and every equilibrium "
                     "proven by Krawczyk's test in ball arithmetic (the only one in its box, real, inside the "
                     "range, the boxes pairwise disjoint: certificate); for tension-only springs (and stops=True), one "
                     "homotopy per taut/slack/stop pattern that may reach the target, each complete, without "
                     "interval boxes (certificate null)",
        "uncertified": "the polynomial homotopy ran but did not prove the set complete (a path failed, its report "
                       "did not check out, a real root did not polish, or two distinct roots lay closer than the "
                       "merge tolerance, or an equilibrium's interval proof failed: the message says which); every "
                       "equilibrium listed is one, others may exist",
        "searched": "the multi-start search: complete in practice (measured against the homotopy), never proven",
        "exact": "known exactly: the straight chain at full extension, a single segment, or the unloaded chain "
                 "(the product of its segments' critical points)",
    }
    SUCCESS: ClassVar[frozenset[str]] = frozenset({"certified", "searched", "exact"})

    equilibria: tuple[Equilibrium, ...]
    method: str
    status: str
    message: str
    paths: int = 0
    failed_paths: int = 0
    seconds: float = 0.0
    certificate: IntervalCertificate | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "equilibria", tuple(self.equilibria))
        freeze(self)

    @property
    def certified(self) -> bool:
        """True only when the set is proven complete: the homotopy certified it, or the case is exact."""
        return self.status in ("certified", "exact")

    def __len__(self) -> int:
        return len(self.equilibria)

    def __getitem__(self, i):
        return self.equilibria[i]

    def __iter__(self) -> Iterator[Equilibrium]:
        return iter(self.equilibria)

    def __repr__(self) -> str:
        return (f"EquilibriumSet({len(self)} equilibria, method={self.method!r}, status={self.status!r}, "
                f"paths={self.paths}, failed_paths={self.failed_paths})")

    def to_dict(self) -> dict[str, Any]:
        """JSON form (the body of ``POST /v1/equilibria`` and ``POST /v1/rest-configurations``): ``success``,
        ``status``, ``message``, ``equilibria`` (each :meth:`Equilibrium.to_dict`), ``method``, ``certified``,
        ``paths``, ``failed_paths``, ``certificate`` (:meth:`IntervalCertificate.to_dict`, ``None`` but for the
        homotopy)."""
        return {**self.outcome(), "equilibria": [e.to_dict() for e in self.equilibria], "method": self.method,
                "certified": self.certified, "paths": int(self.paths), "failed_paths": int(self.failed_paths),
                "certificate": None if self.certificate is None else self.certificate.to_dict()}


def searched_set(eqs, statuses: Mapping[str, int]) -> EquilibriumSet:
    """The :class:`EquilibriumSet` of a multi-start search: ``eqs`` (sorted) and the tally of its local
    solves' statuses (the message)."""
    tally = ", ".join(f"{k} x{v}" for k, v in sorted(statuses.items()))
    none = "no equilibrium found inside the physical joint range |q| < pi - 2 beta by " if not eqs else ""
    return EquilibriumSet(eqs, method="search", status="searched",
                          message=f"{none}the multi-start search (complete in practice, not proven); local solves: "
                                  f"{tally}")


def certify_set(m: Manipulator, eqs, sol, *, target=None, force=None) -> IntervalCertificate:
    """The interval proofs (:func:`~tensegrity_opt.numerics.krawczyk.prove_equilibria`) of the equilibria
    ``eqs`` (sorted) of the homotopy solve ``sol``: displacement control with ``target``, force control with
    ``force``; each proven Morse index is checked against the equilibrium's floating-point one, and the
    homotopy's complex roots near the real set are proven non-real."""
    Q = np.array([e.q for e in eqs], dtype=float).reshape(-1, m.n)
    morse = [e.morse_index for e in eqs]
    if target is not None:
        F = np.array([e.force for e in eqs], dtype=float).reshape(-1, 2)
        return prove_equilibria(m, Q, F, target=target, paths=sol.paths, float_morse=morse, roots=sol.roots)
    F = np.tile(np.asarray(force, dtype=float), (max(1, Q.shape[0]), 1))    # one row at least: the load
    return prove_equilibria(m, Q, F, control="force", paths=sol.paths, float_morse=morse, roots=sol.roots)


def homotopy_set(eqs, sol, polished, certificate: IntervalCertificate | None = None) -> EquilibriumSet:
    """The :class:`EquilibriumSet` of a homotopy solve ``sol``
    (:class:`~tensegrity_opt.numerics.homotopy.HomotopySolve`) whose real roots gave ``polished``
    (:class:`~tensegrity_opt.numerics.homotopy.PolishedRoots`) and whose equilibria ``eqs`` (sorted) carry the
    interval proofs ``certificate`` (:func:`certify_set`): ``certified`` when the polished roots are (every path
    ended, the report checked out, no root lost, none too close) and every equilibrium is proven, else
    ``uncertified``; the message is the polish's report (phc's runs and paths, and why not certified) and the
    certificate's."""
    proven = certificate is not None and certificate.roots_proven
    ok = polished.certified and proven
    none = "" if eqs else ("no equilibrium inside the physical joint range |q| < pi - 2 beta"
                           + (" (proven: the set is certified): " if ok else " found: "))
    report = polished.report
    if certificate is None:
        report += "; no interval proofs"
    else:
        report += ("; " if proven else "; not certified: ") + certificate.message
    return EquilibriumSet(eqs, method="homotopy", status="certified" if ok else "uncertified",
                          message=none + report, paths=sol.paths, failed_paths=sol.failures,
                          seconds=sol.seconds, certificate=certificate)


def find_equilibria(m: Manipulator, dx: float, dy: float = 0.0, *, method: str = "search", n_random: int = 16,
                    amplitudes=(0.6, 1.0, 1.6), max_modes: int = 12, extra_seeds=None,
                    dedupe_tol: float = 1e-6, n_projected: int | None = None,
                    timeout: float | None = None, stops: bool | None = None) -> EquilibriumSet:
    """All equilibria inside the physical range for the tip at ``(2 sum(b) - dx, dy)``.

    Parameters
    ----------
    m : Manipulator
    dx, dy : float
        Tip deflection (length units).
    method : {"search", "homotopy"}
        ``"search"``: multi-start Newton (fast, any ``n``, complete in practice but not certified).
        ``"homotopy"``: PHCpack's parameter homotopy on the polynomial KKT system (8, 96, 832, 6272, 43648
        paths for n = 2..6 from cached start solutions; the polyhedral solve when paths fail), certified
        (``n <= 6``; ~1.5 s of CPU for n = 4, ~20 s for n = 5, ~300 s for n = 6, on 2 cores about 0.6 of that
        in wall time on a quiet machine; pass ``timeout``). A chain with tension-only springs (``n <= 5``): one
        homotopy per taut/slack/stop pattern that may reach the target, stops included (n = 3 ~1 s, n = 4 ~10 s;
        :mod:`.tension_only_homotopy`).
    n_random : int
        Random Newton starts (fixed seed: the answer is reproducible). Search only.
    amplitudes : sequence of float
        Multiples of the eq.-23 amplitude at which each mode seeds Newton. Search only.
    max_modes : int
        At most this many buckling modes are used as seeds (all ``n - 1`` for ``n <= 13``). Search only.
    extra_seeds : iterable of array_like, optional
        More starting configurations (e.g. a previous solution). Search only.
    n_projected : int, optional
        Uniform random configurations (fixed seed) projected onto the tip constraint, Newton from each.
        Default ``500 n`` for multistable chains of up to 6 segments, ``100 n`` for other chains of up
        to 8 (a bistable n = 8 chain: ~0.7 s, some 870 equilibria of more than 1100), ``20 n`` up to 64,
        else 0. Search only.
    dedupe_tol : float
        Two solutions closer than this (max-norm of ``q``, rad) are one.
    timeout : float, optional
        Homotopy only: seconds before PHCpack is stopped (:class:`SolverError`).
    stops : bool, optional
        Include the equilibria resting on a joint's stop (the closed range; ``at_stop``, ``contact_torques``).
        Default: yes for a chain with tension-only springs (a slack spring lets a joint reach its stop) or with dead
        loads (the closed-range search answers it), no under the linear law without loads (the open range, as
        before). Under the linear law ``stops=True`` adds them: the search adds
        Newton with each joint held on either stop (:func:`~.tension_only.stop_equilibria`, measured; ~0.3-0.5 s at
        n = 4), the homotopy solves one system per free/stop pattern that may reach the target (certified, n <= 5;
        :mod:`.tension_only_homotopy`, no Krawczyk boxes). ``False`` for a tension-only chain keeps the open
        range's members of its set.

    Returns
    -------
    EquilibriumSet
        A read-only sequence without duplicates, sorted by energy (ties: ``q_1`` descending), with
        ``status`` (``searched``; ``certified`` or ``uncertified`` for the homotopy; ``exact`` for the
        straight chain and a single segment), ``message``, ``method``, ``certified``, ``paths``,
        ``failed_paths``. For the paper's chain at small ``dx > 0, dy = 0``: 2 stable U, 2 saddles ZU,
        2 maxima Z. Empty at full extension when the straight chain is not an equilibrium, and where the target
        is reachable inside the range but every equilibrium lies outside it (the search: when IPOPT's descents
        reach the target with a joint pressed against its range limit; a success, ``status`` ``searched``, the
        message saying so; the homotopy proves it, ``certified``).

    Raises
    ------
    UnreachableTargetError
        (``ValueError``) beyond the chain's reach; the search also where the target lies within the chain's
        length but outside the workspace of the physical range (IPOPT finds it infeasible from every start, as
        :func:`~tensegrity_opt.analyses.equilibria.least_energy.solve_equilibrium` does; the homotopy returns its
        certified empty set there).
    InvalidParameterError
        (``ValueError``, ``field="method"``) for an unknown method or a chain too long for the homotopy.
    HomotopyUnavailableError
        (``RuntimeError``) for ``method="homotopy"`` without PHCpack (Debian package ``phcpack``).
    SolverError
        (``RuntimeError``) when the search found no equilibrium and its solvers broke down (no descent reached
        the target: nothing tells whether one exists), or PHCpack failed.
    """
    if method not in ("search", "homotopy"):
        raise InvalidParameterError(f"method must be 'search' or 'homotopy', got {method!r}", field="method")
    target = m.check_reachable(dx, dy)
    if dx == 0.0 and dy == 0.0:
        try:
            return EquilibriumSet([straight_equilibrium(m)], method="straight", status="exact",
                                  message="full extension: the straight chain, the only configuration reaching it")
        except StraightNotEquilibriumError:
            # full extension: the straight chain is the only configuration, and not an equilibrium
            return EquilibriumSet([], method="straight", status="exact",
                                  message="full extension: the straight chain is the only configuration reaching it "
                                          "and not an equilibrium of this chain, so none exists")
    if m.n == 1:
        return EquilibriumSet([one_segment_equilibrium(m, target)], method="closed_form", status="exact",
                              message="a single segment: the target fixes its joint angle")
    if not m.paper_model or (stops and method == "homotopy"):
        found = _slack_search(m, target, method, timeout)   # tension-only; or every free/stop pattern, certified
        return found if stops is not False else _open_range(found)
    if stops:
        # the linear law's search: its open-range set first (an unreachable target ends here), then the stop
        # equilibria beside it
        try:
            inner = find_equilibria(m, dx, dy, method=method, n_random=n_random, amplitudes=amplitudes,
                                    max_modes=max_modes, extra_seeds=extra_seeds, dedupe_tol=dedupe_tol,
                                    n_projected=n_projected, timeout=timeout, stops=False)
        except SolverError as exc:              # none inside the open range: the stop equilibria may be all
            if exc.details.get("found") != 0:
                raise
            on = _slack_search(m, target, method, timeout, stops_only=True)
            if not len(on):
                raise
            return _with_stops(EquilibriumSet([], method="search", status="searched",
                                              message="no equilibrium inside the open range"), on)
        return _with_stops(inner, _slack_search(m, target, method, timeout, stops_only=True))
    if method == "homotopy":
        return _homotopy(m, target, dedupe_tol, timeout)
    results = []
    statuses: dict[str, int] = {}
    starts = [(s.q, s.force) for s in seeds(m, dx, dy, max_modes=max_modes, amplitudes=amplitudes,
                                              n_random=n_random)]
    for q in extra_seeds or ():
        starts.append((check_q0(m, q), None))
    for q, F in starts:
        res = local_equilibrium(m, target, q, F)
        statuses[res.status] = statuses.get(res.status, 0) + 1
        if is_equilibrium(m, res, target):
            results.append(res)
    # the wells of multistable chains and uniform random configurations, each projected onto the tip
    # constraint (a sample of the whole configuration manifold): Newton from all of them at once
    if n_projected is None:
        if m.n <= SHORT_N and not m.monotonic:
            per = SHORT_PER_JOINT
        else:
            per = PROJECTED_PER_JOINT if m.n <= KERNEL_MAX else LONG_PER_JOINT
        n_projected = per * m.n if m.n <= 64 else 0
    more = np.vstack([well_seeds(m, dx, dy), projected_sample(m, target, int(n_projected), PROJECTED_SEED)])
    if more.shape[0]:
        batch = chain_solver(m).newton_kkt_seeds(target, more, python_fallback=False)
        results += [batch.result(j) for j in _accepted_rows(m, batch, target, dedupe_tol)]
        statuses["Newton (projected starts)"] = more.shape[0]
    # IPOPT's minima from the mode seeds: a cheap guarantee that the stable ones are present, and where none
    # lies inside the range, the evidence that the target is reachable (or not) inside it; short monotonic chains
    # only where Newton found nothing (MONOTONIC_NO_DESCENT_MAX_N: there the descents never added an equilibrium)
    descents = []
    descend = not (results and m.monotonic and m.n <= MONOTONIC_NO_DESCENT_MAX_N)
    for s in (seeds(m, dx, dy, max_modes=2, n_random=0) if descend else ()):
        res = local_equilibrium(m, target, s.q, minimize=True)
        descents.append(res)
        if is_equilibrium(m, res, target):
            results.append(res)
    if dy == 0.0 and results and m == m.mirrored():
        # a mirror-symmetric chain at dy = 0: -q is an equilibrium whenever q is (force (Fx, -Fy))
        for r in distinct(results, dedupe_tol):
            res = local_equilibrium(m, target, -r.q, r.force * np.array([1.0, -1.0]))
            if is_equilibrium(m, res, target):
                results.append(res)
    if not results:
        return _none_found(m, target, dx, dy, statuses, descents)
    return searched_set(_sorted(m, distinct(results, dedupe_tol)), statuses)


def _none_found(m: Manipulator, target: np.ndarray, dx: float, dy: float, statuses: dict[str, int],
                descents) -> EquilibriumSet:
    """What a search that found no equilibrium inside the range answers, from IPOPT's descents (``min E`` s.t.
    ``tip = target`` inside the closed range): an empty set when one of them reached the target with a joint on
    its range limit (the target is reachable inside the range, and the configurations of least energy reaching
    it press against a limit: the equations' solutions lie outside the range); :class:`UnreachableTargetError`
    when IPOPT found the target infeasible inside the range from every start; else :class:`SolverError` (the
    solvers broke down: nothing tells whether an equilibrium exists)."""
    for res in descents:
        key = f"IPOPT {res.status}" + (" (on joint limit)" if res.on_bound else "")
        statuses[key] = statuses.get(key, 0) + 1
    tally = ", ".join(f"{k} x{v}" for k, v in sorted(statuses.items()))
    if descents and all(r.status.startswith("Infeasible_Problem_Detected") for r in descents):
        raise UnreachableTargetError(
            f"the target for dx={dx:g}, dy={dy:g} lies within the chain's length but outside the workspace of the "
            f"physical joint range |q| < pi - 2 beta: IPOPT found it infeasible from all {len(descents)} starts",
            field="dx", status=tally)
    pressed = [r for r in descents if r.on_bound and not r.status.startswith("Infeasible")
               and np.all(np.isfinite(r.q)) and np.all(np.abs(r.q) <= np.asarray(m.joint_limits) * (1 + 1e-9))
               and np.max(np.abs(m.tip(r.q) - target)) <= TIP_TOL * m.straight_length]
    if not pressed:
        raise SolverError(f"no Newton start converged inside the physical range for dx={dx:g}, dy={dy:g}",
                          status=tally, found=0)
    return EquilibriumSet([], method="search", status="searched",
                          message=f"no equilibrium inside the physical joint range |q| < pi - 2 beta for dx={dx:g}, "
                                  f"dy={dy:g}: the target is reachable inside the range, but the configurations of "
                                  "least energy reaching it press a joint against its range limit (a spring length "
                                  "reaches zero) and every equilibrium the solvers met lies outside the range (the "
                                  "multi-start search: complete in practice, not proven; method='homotopy' "
                                  f"certifies it); local solves: {tally}")


def _accepted_rows(m: Manipulator, batch, target: np.ndarray, dedupe_tol: float) -> list[int]:
    """The rows of a batch of local solves that :func:`is_equilibrium` accepts (converged, off the bounds, inside
    the open range, the residual re-checked in numpy), all rows at once, and of those the first of each group
    of coinciding rows (:func:`distinct`'s rule): the thousands of projected starts of a multistable chain
    converge to a few equilibria, each then built once."""
    Q, F = batch.q, batch.force
    with np.errstate(invalid="ignore", over="ignore"):
        ok = (batch.success & ~batch.on_bound & np.all(np.isfinite(F), axis=1)
              & np.all(np.abs(Q) < np.asarray(m.joint_limits, float), axis=1))
        rows = np.flatnonzero(ok)
        rows = rows[m.equilibrium_residuals(Q[rows], F[rows], target) <= RESIDUAL_TOL]
    return distinct_indices(Q, rows.tolist(), dedupe_tol)


def _order(e: Equilibrium) -> tuple[float, float]:
    """A set's order: by energy (to 1e-10), ties by ``q_1`` descending."""
    return round(e.energy, 10), -e.q[0]


def _sorted(m: Manipulator, results) -> list[Equilibrium]:
    eqs = [make_equilibrium(m, r, constrained=True) for r in results]
    eqs.sort(key=_order)
    return eqs


def _slack_search(m: Manipulator, target: np.ndarray, method: str, timeout: float | None, *,
                  stops_only: bool = False) -> EquilibriumSet:
    """Every equilibrium of a chain with tension-only springs (or, ``find_equilibria(stops=True)``, linear ones), in
    the closed joint range: the search (:mod:`.tension_only`; ``stops_only``: from its stop and rigid starts only) or
    the homotopy of every taut/slack/stop pattern (:mod:`.tension_only_homotopy`)."""
    if method == "homotopy":
        from .tension_only_homotopy import certified_equilibria_slack

        unloaded_only(m, "find_equilibria(method='homotopy')")
        if m.n > SLACK_HOMOTOPY_MAX_N:
            what = "chains of tension-only springs" if not m.linear_springs else "the equilibria on stops (stops=True)"
            raise InvalidParameterError(f"method='homotopy' handles {what} for up to {SLACK_HOMOTOPY_MAX_N} segments "
                                        f"(one homotopy per taut/slack/stop pattern: up to 5^n of them), got n = "
                                        f"{m.n}", field="method", spring="tension_only" if not m.linear_springs else
                                        "linear")
        with time_limit(timeout):
            eqs, report = certified_equilibria_slack(m, target, timeout=timeout)
        return EquilibriumSet(eqs, method="homotopy", status="certified" if report["certified"] else "uncertified",
                              message=report["message"], paths=report["paths"], failed_paths=report["failed_paths"],
                              seconds=report["seconds"])
    from .tension_only import all_equilibria_slack, stop_equilibria

    with time_limit(timeout):
        eqs = stop_equilibria(m, target) if stops_only else all_equilibria_slack(m, target)
    on_stop = sum(bool(e.at_stop.any()) for e in eqs)
    where = f" ({on_stop} resting on a joint's stop)" if on_stop else ""
    what = "the closed-range search (Newton under the chain's dead loads" + (" and the springs' laws" if not
                                                                              m.linear_springs else "") \
        if m.loaded else "the tension-only search (Newton under the springs' laws"
    return EquilibriumSet(eqs, method="search", status="searched",
                          message=f"{len(eqs)} equilibria{where} found by {what} over the closed joint range: complete "
                                  "in practice, not certified)")


def _with_stops(inner: EquilibriumSet, on: EquilibriumSet) -> EquilibriumSet:
    """The linear law's search set with the equilibria resting on a stop (``find_equilibria(stops=True)``): the
    open-range search's set ``inner`` joined by the stop search's ``on`` (measured)."""
    eqs = sorted([*inner, *on], key=_order)
    return EquilibriumSet(eqs, method="search", status="searched",
                          message=f"{inner.message}; with {len(on)} equilibria resting on a joint's stop (Newton with "
                                  "each joint held on either stop; complete in practice, not certified)")


def _open_range(found: EquilibriumSet) -> EquilibriumSet:
    """The members of ``found`` inside the open range (``stops=False`` for a tension-only chain)."""
    eqs = [e for e in found if not e.at_stop.any()]
    return EquilibriumSet(eqs, method=found.method, status=found.status,
                          message=f"{found.message}; {len(found) - len(eqs)} resting on a stop left out (stops=False)",
                          paths=found.paths, failed_paths=found.failed_paths, seconds=found.seconds)


def _homotopy(m: Manipulator, target: np.ndarray, dedupe_tol: float, timeout: float | None) -> EquilibriumSet:
    from ...numerics.homotopy import polish_roots, real_configurations, rest_points_at
    from ...numerics.parameter_homotopy import solve_parameter_homotopy

    if m.n > HOMOTOPY_MAX_N:
        raise InvalidParameterError(f"method='homotopy' handles chains of up to {HOMOTOPY_MAX_N} segments "
                                    f"(its path count grows ~8x a segment), got n = {m.n}", field="method")
    sol = solve_parameter_homotopy(m, target, timeout=timeout)
    q, F, inside, regular = real_configurations(m, sol)
    # F = 0 equilibria (g = h = 0) lie outside the torus the mixed volume counts: added from the
    # segments' unloaded critical points (all of them, from each torque's quartic)
    rest = rest_points_at(m, target)
    q = np.vstack([q, rest])
    F = np.vstack([F, np.zeros((rest.shape[0], 2))])
    inside = np.concatenate([inside, np.ones(rest.shape[0], dtype=bool)])
    regular = np.concatenate([regular, np.ones(rest.shape[0], dtype=bool)])
    out = polish_roots(sol, q[inside], F[inside], regular[inside],
                       polish=lambda qi, Fi: local_equilibrium(m, target, qi, Fi),
                       accept=lambda res: is_equilibrium(m, res, target),
                       root_is_equilibrium=lambda qi, Fi: (m.equilibrium_residual(qi, Fi, target) <= RESIDUAL_TOL
                                                           and m.in_range(qi)),
                       dedupe_tol=dedupe_tol, note=f" ({rest.shape[0]} with F = 0)" if rest.shape[0] else "")
    eqs = _sorted(m, out.found)
    return homotopy_set(eqs, sol, out, certify_set(m, eqs, sol, target=target))
