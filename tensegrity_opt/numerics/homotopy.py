"""Every equilibrium of the displacement problem, certified by a polynomial homotopy (PHCpack).

The KKT system ``grad E(q) = J(q)^T F``, ``tip(q) = target`` is written as a Laurent
polynomial system in ``n + 2`` complex unknowns and handed to PHCpack's blackbox solver
(``phc -b``: polyhedral homotopy, every path from the mixed-volume start system), which returns
*every* isolated complex root. The real roots inside the physical range are the equilibria;
each is polished by the library's Newton method on the KKT system and classified by the
reduced Hessian like every other equilibrium.

Formulation
-----------
Per joint ``z_j = exp(i q_j / 2)`` (a relative *half* angle on the unit circle; ``1/z_j`` is its
conjugate on real points), and ``g = Fx + i Fy``, ``h = Fx - i Fy``. Then

* spring lengths are linear in ``(z_j, 1/z_j)``: ``cos(q/2) = (z + 1/z)/2``,
  ``sin(q/2) = (z - 1/z)/(2i)``, ``L1 = 2 (b cos(q/2) - a sin(q/2))``, ``L2 = 2 (b cos(q/2) + a sin(q/2))``;
  ``E_j'(q_j)`` has the monomials ``z_j^2, z_j, 1, 1/z_j, 1/z_j^2``;
* the absolute link direction is ``exp(i phi_j) = prod_{i <= j} z_i^2``: the two tip equations are
  ``sum_j l_j prod_{i<=j} z_i^2 = (x_t - b_1) + i y_t`` and its conjugate with ``z^-2``;
* stationarity in the sparse "difference" form: the torques of neighbouring joints differ by the
  moment of ``F`` about the link between them, ``E_j' - E_{j+1}' = l_j Im(e^{-i phi_j} G)``
  (``E_n' = l_n Im(e^{-i phi_n} G)`` at the tip), with ``Im(e^{-i phi} G) = (e^{-i phi} g - e^{i phi} h)/(2i)``.

Eliminating the absolute angles keeps the system small: ``n + 2`` unknowns instead of the
``4n + 2`` of a formulation with absolute cosines and sines and unit circles. Its mixed volume
(the number of paths) is measured as 8, 96, 832, 6272 and 43648 for ``n = 2..6`` on general
chains (8, 72, 456, 2488 when ``a = b``, which zeroes the ``z^2`` terms of symmetric segments); a
naive formulation in absolute cosines, sines and unit circles gave 32, 704 for ``n = 2, 3`` with
many failing paths. Time of this polyhedral solve on 2 cores: n = 4 ~3-8 s, n = 5 ~1-2.5 min, n = 6 ~9-12 min (the
parameter homotopy of :mod:`.parameter_homotopy`, the default, ~0.25 s, ~2 s, ~20 s). The flip
``z_j -> -z_j`` is *not* a symmetry here: it is the same segment with ``L_0 -> -L_0`` (spring
lengths negative, ``q_j + 2 pi``), whose roots are genuine roots of the polynomial system and are
dropped as outside the physical range; the 2^n sign copies of a formulation in absolute half
angles do not arise. Coefficients that vanish analytically (``a = b`` gives ``cos 2 beta = 0``)
are cleaned (relative ``1e-14``) before the system is written.

Force control
-------------
Under a dead tip load ``F`` (:func:`force_polynomial_system`, :func:`solve_force_homotopy`) ``g = Fx + i Fy``
and ``h = conj(g)`` are given numbers and the tip is free: the ``n`` stationarity rows above in the ``n``
unknowns ``z_j`` alone, no tip equations. Mixed volume 4, 24, 128, 704, 3840 for ``n = 1..5`` on general
chains; polyhedral solve on 2 cores: n = 3 ~0.3 s, n = 4 ~2-4 s, n = 5 ~15-70 s. Uniform chains of n = 5 have
128 paths to toric infinity, which PHCpack reports failed (uncertified here; the parameter homotopy's end game
counts them diverged), like the displacement system's uniform bistable chains. The
real roots are read by :func:`real_force_configurations`; ``F = 0`` needs no homotopy (the rows decouple:
each segment's :meth:`~tensegrity_opt.model.segment.Segment.critical_points`).

Certification
-------------
``certified`` (``find_equilibria(method="homotopy")``) is true only when PHCpack's report checks
out (exit code 0; declared, listed and mixed-volume counts equal), every path of the start system
ended at ``Re t = 1`` on a finite root or at infinity (no failed path, no clustered end point: two
paths on one root mean one may be missing), and every real root inside the range polished by Newton
onto an equilibrium (a singular one, computed to ~sqrt(eps), is accepted within 1e-3 of the real set
and polished). A run with failed paths is repeated with new random constants. Equilibria with
``F = 0`` (``g = h = 0``) lie outside the torus the mixed volume counts; they are added exactly from
the segments' unloaded critical points (:func:`rest_points_at`). Anything else (a failed path, a phc
error, a root whose polish fails, two distinct roots too close to separate) makes it false, never
silently true. :func:`polish_roots` does this polish and judges the certificate for both systems.

PHCpack is a system package: ``apt-get install phcpack`` (Debian/Ubuntu) puts ``phc`` on the
``PATH``; :class:`HomotopyUnavailableError` names it where it is absent.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import tempfile
import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..errors import HomotopyUnavailableError, SolverError
from ..model.combinations import combinations
from ..model.manipulator import Manipulator
from ..model.segment import clean_coefficients
from .distinct import distinct
from .results import LocalResult

__all__ = ["HomotopySolve", "HomotopyUnavailableError", "polynomial_system", "solve_homotopy", "phc_path",
           "homotopy_available", "real_configurations", "residuals", "rest_points_at", "force_polynomial_system",
           "solve_force_homotopy", "real_force_configurations", "PolishedRoots", "polish_roots"]
#: Most ``phc`` runs when paths fail (each run draws new random constants).
ATTEMPTS = 3
#: A regular root is real when ``| |z_j| - 1 |`` and ``|g - conj(h)|`` (relative) are below this;
#: a singular one (accurate to ~sqrt(eps) at a double root, worse beyond) when below the second.
REAL_TOL = 1e-6
SINGULAR_REAL_TOL = 1e-3


def phc_path() -> str | None:
    """Path of the ``phc`` executable (``TENSEGRITY_PHC`` overrides the ``PATH`` look-up), or ``None``."""
    exe = os.environ.get("TENSEGRITY_PHC") or "phc"
    return shutil.which(exe)


def homotopy_available() -> bool:
    """True when PHCpack's ``phc`` can be run."""
    return phc_path() is not None


@dataclass(frozen=True)
class HomotopySolve:
    """What PHCpack did for one polynomial system.

    Attributes
    ----------
    roots : ndarray (r, n + 2) or (r, n) complex
        Every finite root returned: ``z_1..z_n, g, h`` for the displacement system (:func:`solve_homotopy`),
        ``z_1..z_n`` for the force-controlled one (:func:`solve_force_homotopy`).
    regular : ndarray (r,) bool
        PHCpack classified the root as regular (non-singular Jacobian).
    paths : int
        Paths tracked (the mixed volume of the system).
    failures : int
        Paths that did not reach an end (any makes the result uncertified).
    at_infinity : int
        Paths that diverged (roots at infinity: not solutions).
    singular : int
        Singular finite roots.
    seconds : float
        Wall time of the ``phc`` runs.
    threads : int
    attempts : int
        ``phc`` runs made (a run with failed paths is repeated, :func:`solve_homotopy`).
    consistent : bool
        The report checked out (:func:`_parse`): exit code 0, declared, listed and mixed-volume counts equal.
    engine : str
        ``"polyhedral"`` (``phc -b`` from the mixed-volume start system) or ``"parameter"`` (``phc -p`` from the
        start roots of a generic instance, :mod:`.parameter_homotopy`).
    note : str
        How the roots were found, in words (:mod:`.parameter_homotopy`: the parameter homotopy, or why the
        polyhedral solve answered); empty for a plain polyhedral solve.
    retracked : int
        Parameter homotopy: paths tracked a second time by ``phc -p`` with careful settings (not ended or jumped the
        first time).
    tracker : str
        Parameter homotopy: what followed every path first, ``"batch"`` (:mod:`.homotopy_tracker`) or ``"phc"``
        (``phc -p``); empty for a polyhedral solve.
    """

    roots: np.ndarray
    regular: np.ndarray
    paths: int
    failures: int
    at_infinity: int
    singular: int
    seconds: float
    threads: int = 1
    attempts: int = 1
    consistent: bool = True
    engine: str = "polyhedral"
    note: str = ""
    retracked: int = 0
    tracker: str = ""

    @property
    def complete(self) -> bool:
        """Every path reached an end (no failure, no clustered end point, no path short of ``t = 1``) and
        the report is consistent."""
        return self.failures == 0 and self.consistent


# ----------------------------------------------------------------------------- the polynomial system
def _laurent_terms(m: Manipulator, target) -> list[dict[tuple[int, ...], complex]]:
    """The ``n + 2`` Laurent polynomials (dicts exponent tuple -> coefficient), unknowns ``z_1..z_n, g, h``."""
    n = m.n
    nv = n + 2
    l = m.link_lengths

    def unit(j: int, p: int) -> tuple[int, ...]:
        e = [0] * nv
        e[j] = p
        return tuple(e)

    def add(poly: dict, e: tuple[int, ...], c: complex) -> None:
        poly[e] = poly.get(e, 0.0) + c

    def dE(j: int) -> dict:
        poly: dict = {}
        for p, coef in m.segments[j].torque_polynomial().items():
            add(poly, unit(j, p), coef)
        return poly

    def direction(j: int, sign: int, extra: int | None = None) -> tuple[int, ...]:
        e = [0] * nv
        for i in range(j + 1):
            e[i] = 2 * sign
        if extra is not None:
            e[extra] += 1
        return tuple(e)

    T = complex(float(target[0]) - m.base_length, float(target[1]))
    zero = tuple([0] * nv)
    tip1: dict = {zero: -T}
    tip2: dict = {zero: -T.conjugate()}
    for j in range(n):
        add(tip1, direction(j, 1), float(l[j]))
        add(tip2, direction(j, -1), float(l[j]))
    eqs = [tip1, tip2]
    dEs = [dE(j) for j in range(n)]
    for j in range(n):
        poly = dict(dEs[j])
        if j < n - 1:
            for e, c in dEs[j + 1].items():
                add(poly, e, -c)
        # - l_j (e^{-i phi_j} g - e^{i phi_j} h) / (2i)
        add(poly, direction(j, -1, n), -float(l[j]) / 2j)
        add(poly, direction(j, 1, n + 1), float(l[j]) / 2j)
        eqs.append(poly)
    return [clean_coefficients(p) for p in eqs]


def _force_laurent_terms(m: Manipulator, force) -> list[dict[tuple[int, ...], complex]]:
    """The ``n`` Laurent polynomials of the force-controlled equilibrium, unknowns ``z_1..z_n`` only.

    The stationarity rows of :func:`_laurent_terms` with ``g = Fx + i Fy`` and ``h = conj(g)`` given
    numbers instead of unknowns, and no tip equations: ``E_j' - E_{j+1}' - l_j Im(e^{-i phi_j} G) = 0``
    (``j < n``), ``E_n' - l_n Im(e^{-i phi_n} G) = 0``, with
    ``Im(e^{-i phi} G) = (e^{-i phi} g - e^{i phi} h) / (2i)`` and ``e^{i phi_j} = prod_{i <= j} z_i^2``.
    """
    n = m.n
    l = m.link_lengths
    g = complex(float(force[0]), float(force[1]))
    h = g.conjugate()

    def add(poly: dict, e: tuple[int, ...], c: complex) -> None:
        poly[e] = poly.get(e, 0.0) + c

    def dE(j: int) -> dict:
        poly: dict = {}
        for p, coef in m.segments[j].torque_polynomial().items():
            e = [0] * n
            e[j] = p
            add(poly, tuple(e), coef)
        return poly

    def direction(j: int, sign: int) -> tuple[int, ...]:
        return tuple([2 * sign] * (j + 1) + [0] * (n - j - 1))

    dEs = [dE(j) for j in range(n)]
    eqs = []
    for j in range(n):
        poly = dict(dEs[j])
        if j < n - 1:
            for e, c in dEs[j + 1].items():
                add(poly, e, -c)
        # - l_j (e^{-i phi_j} g - e^{i phi_j} h) / (2i)
        if g != 0.0:
            add(poly, direction(j, -1), -float(l[j]) * g / 2j)
            add(poly, direction(j, 1), float(l[j]) * h / 2j)
        eqs.append(poly)
    return [clean_coefficients(p) for p in eqs]


def _names(n: int) -> list[str]:
    return [f"z{j + 1}" for j in range(n)] + ["g", "h"]


def polynomial_system(m: Manipulator, target) -> str:
    """The KKT system for the tip at ``target`` in PHCpack's input format (Laurent, complex coefficients)."""
    return _system_text(_laurent_terms(m, target), _names(m.n))


def _system_text(polys: list[dict], names: list[str]) -> str:
    """Laurent polynomials (dicts exponent tuple -> coefficient) in PHCpack's input format."""
    lines = [str(len(names))]
    for poly in polys:
        parts = []
        for e, c in sorted(poly.items()):
            mono = "*".join(names[i] + (f"**({p})" if p < 0 else (f"**{p}" if p > 1 else ""))
                            for i, p in enumerate(e) if p)
            parts.append(f"+({c.real:+.17e}{c.imag:+.17e}*i)" + ("*" + mono if mono else ""))
        lines.append(" ".join(parts) + ";")
    return "\n".join(lines) + "\n"


def force_polynomial_system(m: Manipulator, force) -> str:
    """The force-controlled equilibrium ``grad E = J^T F`` for the tip force ``force = (Fx, Fy)`` in
    PHCpack's input format: ``n`` Laurent equations in ``z_1..z_n`` (:func:`_force_laurent_terms`)."""
    return _system_text(_force_laurent_terms(m, force), _names(m.n)[:m.n])


def residuals(m: Manipulator, target, roots: np.ndarray) -> np.ndarray:
    """Max-norm residual of the polynomial system at each root (rows of ``roots``: ``z_1..z_n, g, h`` with
    ``g = Fx + i Fy``, ``h = Fx - i Fy``, as :func:`solve_homotopy` returns them), relative to the
    largest coefficient of each equation: an independent check of what PHCpack returned."""
    return _residuals(_laurent_terms(m, target), roots)


def _residuals(polys: list[dict], roots: np.ndarray) -> np.ndarray:
    """Max-norm residual (relative to each equation's largest coefficient) of ``polys`` at each row of ``roots``."""
    roots = np.asarray(roots, dtype=complex)
    out = np.zeros(roots.shape[0])
    logs = None
    for poly in polys:
        exps = np.array(list(poly.keys()), dtype=float)
        coefs = np.array(list(poly.values()))
        with np.errstate(all="ignore"):
            logs = np.log(roots.astype(complex)) if logs is None else logs
            vals = np.exp(logs @ exps.T) @ coefs
        out = np.maximum(out, np.abs(vals) / np.abs(coefs).max())
    return out


# ----------------------------------------------------------------------------- running PHCpack
_NUM = r"[-+]?\d+\.\d+E[-+]\d+"
_COUNT = re.compile(r"Number of (regular solutions|singular solutions|solutions at infinity|failures)\s*:\s*(\d+)")
_MV = re.compile(r"mixed volume\s*:\s*(\d+)")


def solve_homotopy(m: Manipulator, target, *, threads: int | None = None, timeout: float | None = None,
                   attempts: int = ATTEMPTS) -> HomotopySolve:
    """Every isolated complex root of :func:`polynomial_system` by ``phc -b`` (polyhedral homotopy).

    PHCpack draws new random constants (the gamma trick, the lifting) on every run, so a path that
    failed in one run is tracked afresh in the next: a run with failed paths is repeated, up to
    ``attempts`` runs in all, and the first run without failures (else the one with the fewest) is
    returned. Measured: 3 of 96 paths failed in one n = 3 run and none in the next five.

    Parameters
    ----------
    threads : int, optional
        ``phc -t`` tasks; default: the CPUs available (at most 8).
    timeout : float, optional
        Seconds (for all attempts together) before ``phc`` is killed (:class:`SolverError` with status
        ``"phc_timeout"``).
    attempts : int
        Most runs when paths fail.

    Raises
    ------
    HomotopyUnavailableError
        (``RuntimeError``) when ``phc`` is not installed (Debian package ``phcpack``).
    SolverError
        (``RuntimeError``) when ``phc`` fails, times out or writes no solutions.
    """
    return _solve(polynomial_system(m, target), _names(m.n), m.n, threads, timeout, attempts)


def solve_force_homotopy(m: Manipulator, force, *, threads: int | None = None, timeout: float | None = None,
                         attempts: int = ATTEMPTS) -> HomotopySolve:
    """Every isolated complex root of :func:`force_polynomial_system` (the equilibria under the dead tip
    load ``force``) by ``phc -b``, with the repeats, parameters and errors of :func:`solve_homotopy`.

    The roots are rows ``z_1..z_n``. ``force`` must not be zero: the unloaded system decouples into the
    segments' own torques (each segment's ``critical_points()`` are its real roots).
    """
    return _solve(force_polynomial_system(m, force), _names(m.n)[:m.n], m.n, threads, timeout, attempts)


def _solve(text: str, names: list[str], n: int, threads: int | None, timeout: float | None,
           attempts: int) -> HomotopySolve:
    """``phc -b`` on the system ``text`` (unknowns ``names``), repeated while paths fail (:func:`solve_homotopy`)."""
    exe = phc_path()
    if exe is None:
        raise HomotopyUnavailableError(
            "the homotopy method needs PHCpack's 'phc' on the PATH: install the Debian package 'phcpack' "
            "(apt-get install phcpack) or set TENSEGRITY_PHC to the executable", field="method")
    if threads is None:
        threads = max(1, min(8, len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else 1))
    deadline = None if timeout is None else time.monotonic() + float(timeout)
    best: HomotopySolve | None = None
    spent = 0.0
    for attempt in range(max(1, int(attempts))):
        left = None if deadline is None else deadline - time.monotonic()
        if left is not None and left <= 0.0:
            if best is not None:
                break                   # out of time for another try: the best run so far
            raise SolverError(f"phc did not finish within {timeout:g} s (n = {n})", status="phc_timeout")
        try:
            run = _run_phc(exe, text, names, n, int(threads), left)
        except SolverError:
            if best is None:
                raise
            break
        spent += run.seconds
        run = HomotopySolve(**{**run.__dict__, "attempts": attempt + 1, "seconds": spent})
        if best is None or (not run.complete, run.failures) < (not best.complete, best.failures):
            best = run
        if best.complete:
            break
    assert best is not None
    return HomotopySolve(**{**best.__dict__, "seconds": spent})


def _run_phc(exe: str, text: str, names: list[str], n: int, threads: int, timeout: float | None) -> HomotopySolve:
    """One ``phc -b`` run on the system ``text``."""
    with tempfile.TemporaryDirectory(prefix="tensegrity_phc_") as tmp:
        src, out = os.path.join(tmp, "system.phc"), os.path.join(tmp, "system.out")
        with open(src, "w") as f:
            f.write(text)
        cmd = [exe, "-b"] + ([f"-t{int(threads)}"] if threads > 1 else []) + [src, out]
        t0 = time.perf_counter()
        try:
            proc = subprocess.run(cmd, capture_output=True, timeout=timeout, cwd=tmp, stdin=subprocess.DEVNULL)
        except subprocess.TimeoutExpired:
            raise SolverError(f"phc did not finish within {timeout:g} s (n = {n})", status="phc_timeout") from None
        seconds = time.perf_counter() - t0
        if not os.path.exists(out):
            raise SolverError(f"phc wrote no output (exit code {proc.returncode}): "
                              f"{proc.stderr.decode(errors='replace')[-300:]}", status="phc_failed")
        with open(out, errors="replace") as f:
            report = f.read()
    return _parse(report, names, seconds, threads, proc.returncode)


def _parse(report: str, names: list[str], seconds: float, threads: int, returncode: int = 0) -> HomotopySolve:
    """Read phc's report: every path's end point, classified by its own line, with the totals checked.

    A report is ``consistent`` only when phc exited with 0, it states the mixed volume, the solution list's
    declared size equals the number of blocks and the mixed volume, every block ended at ``Re t = 1`` (phc
    prints a complex ``t`` whose imaginary part is not zero at the end of polyhedral paths) and
    maps every unknown by name. Clustered end points (two paths on one root: path jumping, a root may be
    missing) count as failures."""
    nv = len(names)
    head, sep, sols = report.rpartition("THE SOLUTIONS")
    if not sep:
        raise SolverError("phc's output holds no solution list", status="phc_failed")
    counts = dict((k, int(v)) for k, v in _COUNT.findall(sols))
    mv = _MV.findall(head)
    declared = re.search(r"^\s*:?\s*(\d+)\s+(\d+)\s*$", sols, flags=re.M)
    roots, regular = [], []
    blocks = re.split(r"^solution \d+ :", sols, flags=re.M)[1:]
    consistent = returncode == 0 and bool(mv) and declared is not None
    consistent = consistent and int(declared.group(1)) == len(blocks) == int(mv[-1])
    failed = infinite = 0
    for blk in blocks:
        t = re.search(r"^t :\s*(" + _NUM + r")\s+(" + _NUM + r")", blk, flags=re.M)
        found = re.search(r"^== err.*==\s*$", blk, flags=re.M)     # this end point's own classification
        tail = found.group(0) if found else ""
        if "the solution for t" not in blk or t is None or not tail:
            consistent = False
            continue
        vals = dict((k, complex(float(r), float(i))) for k, r, i in re.findall(
            r"^\s*(\w+)\s*:\s*(" + _NUM + r")\s+(" + _NUM + r")\s*$", blk.split("the solution for t :", 1)[1],
            flags=re.M))
        if "failure" in tail or "no solution" in tail or "clustered" in tail:
            failed += 1                 # a failed path's last point, or a second path on one root
            continue
        if "infinity" in tail or "infinite" in tail:
            infinite += 1
            continue
        if abs(float(t.group(1)) - 1.0) > 1e-8 or any(v not in vals for v in names):
            failed += 1                 # a path that stopped before its end (Re t < 1), or an unreadable point
            continue
        roots.append(np.array([vals[v] for v in names]))
        regular.append("singular" not in tail)
    paths = int(mv[-1]) if mv else len(blocks)
    roots_a = np.array(roots, dtype=complex).reshape(-1, nv)
    failures = max(failed, counts.get("failures", 0) + counts.get("clustered solutions", 0))
    return HomotopySolve(roots=roots_a, regular=np.array(regular, dtype=bool), paths=paths, failures=failures,
                         at_infinity=max(infinite, counts.get("solutions at infinity", 0)),
                         singular=counts.get("singular solutions", 0), seconds=seconds, threads=threads,
                         consistent=consistent)


def rest_points_at(m: Manipulator, target, *, tol: float = 1e-9) -> np.ndarray:
    """The configurations with every joint at a zero of its own torque (``F = 0`` equilibria) whose tip is
    ``target`` (rows; usually none). They have ``g = h = 0``, outside the torus where the mixed volume
    counts roots, so :func:`solve_homotopy` cannot see them: the caller adds them (a finite product of the
    segments' unloaded critical points, :meth:`~tensegrity_opt.model.segment.Segment.critical_points`)."""
    angles = [seg.critical_points() for seg in m.segments]
    if any(a.size == 0 for a in angles):
        return np.zeros((0, m.n))
    Q = combinations(angles)
    phi = np.cumsum(Q, axis=1)
    l = m.link_lengths
    tips = np.column_stack([m.base_length + (np.cos(phi) * l).sum(axis=1), (np.sin(phi) * l).sum(axis=1)])
    near = np.abs(tips - np.asarray(target, float)).max(axis=1) < tol * float(m.b.sum())
    return Q[near]


def real_configurations(m: Manipulator, solve: HomotopySolve, *, tol: float = REAL_TOL,
                        singular_tol: float = SINGULAR_REAL_TOL
                        ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The real roots as ``(q (k, n), F (k, 2), inside (k,) bool, regular (k,) bool)``: ``q_j = 2 arg z_j``
    (no wrapping: the principal argument is the half angle in ``(-pi, pi]``, and the range needs ``Re z_j > 0``),
    ``F = ((g + h)/2, (g - h)/(2i))`` of the points projected onto the real set (``|z| = 1``, ``h = conj g``);
    ``inside`` marks those in the open physical range. A regular root is real when its distance from the
    real set is below ``tol`` (regular roots come to ~1e-14); a singular one (a degenerate equilibrium,
    computed to ~sqrt(eps) or worse) when below ``singular_tol``: the callers polish every candidate."""
    n = m.n
    R = solve.roots
    if R.size == 0:
        return np.zeros((0, n)), np.zeros((0, 2)), np.zeros(0, dtype=bool), np.zeros(0, dtype=bool)
    z, g, h = R[:, :n], R[:, n], R[:, n + 1]
    fscale = max(1.0, m.torque_scale / float(m.b.sum()))
    dist = np.maximum(np.abs(np.abs(z) - 1.0).max(axis=1), np.abs(g - np.conj(h)) / np.maximum(fscale, np.abs(g)))
    real = dist < np.where(solve.regular, tol, singular_tol)
    q = 2.0 * np.angle(z[real])
    G = 0.5 * (g + np.conj(h))[real]
    F = np.column_stack([G.real, G.imag])
    inside = np.all(np.abs(q) < m.joint_limits, axis=1)
    return q, F, inside, solve.regular[real]


def real_force_configurations(m: Manipulator, solve: HomotopySolve, *, tol: float = REAL_TOL,
                              singular_tol: float = SINGULAR_REAL_TOL
                              ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The real roots of :func:`solve_force_homotopy` as ``(q (k, n), inside (k,) bool, regular (k,) bool)``:
    ``q_j = 2 arg z_j`` of the roots with ``| |z_j| - 1 |`` below ``tol`` (regular) or ``singular_tol``
    (singular), as :func:`real_configurations`; ``inside`` marks those in the open physical range."""
    n = m.n
    R = solve.roots
    if R.size == 0:
        return np.zeros((0, n)), np.zeros(0, dtype=bool), np.zeros(0, dtype=bool)
    z = R[:, :n]
    dist = np.abs(np.abs(z) - 1.0).max(axis=1)
    real = dist < np.where(solve.regular, tol, singular_tol)
    q = 2.0 * np.angle(z[real])
    inside = np.all(np.abs(q) < m.joint_limits, axis=1)
    return q, inside, solve.regular[real]


@dataclass(frozen=True)
class PolishedRoots:
    """The equilibria from the real roots of a homotopy (:func:`polish_roots`).

    Attributes
    ----------
    found : list of LocalResult
        The distinct equilibria, in the order of the roots.
    certified : bool
        Every path ended (:attr:`HomotopySolve.complete`), every real root in range polished onto an
        equilibrium, and no two distinct regular roots closer than the tolerance.
    report : str
        What happened, in words: phc's runs and paths, the real roots in range, and why the set is not
        certified.
    """

    found: list
    certified: bool
    report: str


def polish_roots(solve: HomotopySolve, q: np.ndarray, F: np.ndarray, regular: np.ndarray, *,
                 polish: Callable[[np.ndarray, np.ndarray], LocalResult], accept: Callable[[LocalResult], bool],
                 root_is_equilibrium: Callable[[np.ndarray, np.ndarray], bool], dedupe_tol: float,
                 note: str = "") -> PolishedRoots:
    """The real roots in range (``q`` (k, n), ``F`` (k, 2), ``regular`` (k,)) polished by Newton, and the
    certificate.

    Each root is polished (``polish(q, F)``); the result counts when ``accept(result)`` and it stays within
    ``1e-6`` of the root (``1e-3`` for a singular root, computed to ~sqrt(eps) or worse); else the root
    itself counts when ``root_is_equilibrium(q, F)`` (a root Newton cannot improve; solver status ``"phc_root"``);
    else it is lost. The regular ones are made distinct (:mod:`.distinct`, ``1e-9``), then with the singular
    ones at ``dedupe_tol`` (at least ``1e-4`` when there are singular ones). Distinct regular roots closer
    than ``dedupe_tol`` (merged so) or a lost root make the set uncertified. ``note`` follows the count of
    real roots in the report.
    """
    polished, lost, singular = [], 0, []
    for qi, Fi, reg in zip(q, F, regular):
        res = polish(qi, Fi)
        near = 1e-6 if reg else 1e-3            # a singular root comes to ~sqrt(eps) or worse
        if accept(res) and np.max(np.abs(res.q - qi)) < near:
            (polished if reg else singular).append(res)
        elif root_is_equilibrium(qi, Fi):
            (polished if reg else singular).append(LocalResult(qi, Fi, True, "phc_root", 0))
        else:
            lost += 1
    regular_set = distinct(polished, 1e-9)
    # distinct regular roots closer than dedupe_tol would be merged below: a near-degenerate pair the
    # certificate does not separate
    close = len(regular_set) - len(distinct(regular_set, dedupe_tol))
    found = distinct(regular_set + singular, dedupe_tol if not singular else max(dedupe_tol, 1e-4))
    why = []
    if not solve.consistent:
        why.append("phc's report did not check out")
    if lost:
        why.append(f"{lost} real roots did not polish")
    if close:
        why.append(f"{close} pairs of distinct roots closer than {dedupe_tol:g}")
    runs = f"{solve.attempts} run{'s' if solve.attempts > 1 else ''}"
    engine = "parameter homotopy" if solve.engine == "parameter" else "polyhedral homotopy"
    if solve.engine == "parameter" and solve.tracker == "batch":
        engine += ", batched tracker"
    report = (f"phc ({runs}, {engine}): {solve.paths} paths, {solve.failures} failed, {solve.at_infinity} at "
              f"infinity, {solve.singular} singular; {len(q)} real roots in range" + note
              + "".join(f"; {w}" for w in why) + (f"; {solve.note}" if solve.note else ""))
    return PolishedRoots(found, solve.complete and lost == 0 and close == 0, report)
