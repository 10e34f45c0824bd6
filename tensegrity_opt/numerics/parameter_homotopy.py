"""Every equilibrium by a parameter (coefficient-parameter, "cheater's") homotopy: a few paths a query.

The polynomial systems of :mod:`.homotopy` keep their *structure* for a given number of segments ``n``;
only their coefficients change from chain to chain and target to target. Every coefficient is linear in a
parameter vector ``p``:

* the displacement system (:func:`~.homotopy.polynomial_system`, unknowns ``z_1..z_n, g, h``): per segment
  the four coefficients of its torque polynomial (powers ``2, 1, -1, -2`` of
  :meth:`~tensegrity_opt.model.segment.Segment.torque_polynomial`; its ``z^0`` coefficient ``(A + B)/2`` is zero
  identically), the link lengths ``l_j`` (each one parameter, tied across the two tip equations and its
  stationarity row) and the tip target ``T`` and its conjugate ``T'`` (independent once complexified):
  ``5 n + 2`` parameters (:func:`displacement_parameters`, :func:`displacement_family`);
* the force system (:func:`~.homotopy.force_polynomial_system`, unknowns ``z_1..z_n``): the torque
  coefficients and ``c_j = l_j g``, ``d_j = l_j h``: ``6 n`` parameters (:func:`force_parameters`,
  :func:`force_family`).

So ``F(x; p)`` is linear in ``p`` and PHCpack's linear homotopy ``(1 - t) gamma F(x; p0) + t F(x; p1)`` is
``F(x; (1 - t) gamma p0 + t p1)``: every system on the path belongs to the family.

Completeness
------------
The coefficient-parameter homotopy theorem (Morgan & Sommese 1989; Sommese & Wampler, *The Numerical
Solution of Systems of Polynomials*, 2005, Thm. 7.1.1 and ch. 7.3): on the irreducible domain
``X = (C*)^n x C^2`` (``(C*)^n`` for the force system) the number of isolated roots is the same number
``N`` for all parameters off a proper algebraic subset (the generic root count of the *family*), and for
a generic start ``p0`` and all but finitely many ``gamma`` on the unit circle the ``N`` paths from the
isolated roots of ``F(x; p0)`` reach, as ``t -> 1``, every isolated root of ``F(x; p1)`` in ``X`` (with
multiplicity), for *any* target ``p1`` in the family, including targets with zero coefficients: the paths in
excess diverge (leave ``X``: ``|x| -> inf`` or some ``z_j -> 0``). PHCpack reports a path to ``z_j -> 0`` as
failed, so the chains with symmetric segments (``a = b``, ``k1 = k2``: no ``z^+-2`` torque terms; the uniform
n = 4 chain has 456 roots, not 832) get start roots of their own sub-family (:func:`structure_of`).

* ``N`` and the start roots: one generic complex instance ``p0`` per ``n`` (random phases, magnitudes of a
  typical chain), solved once by PHCpack's polyhedral homotopy (``phc -b``); the run counts only when every
  path ended, none failed, the report checked out and no two roots coincide (else a new ``p0`` is drawn).
  Generically no root has ``g = 0`` or ``h = 0`` (``n + 2`` equations in fewer unknowns), so the roots in
  the torus ``(C*)^(n+2)`` that ``phc -b`` returns are all the isolated roots in ``X``. Measured ``N`` for
  ``n = 2..5`` (equal to the mixed volume: the tied parameters do not lower the count): 8, 96, 832, 6272
  (43648 for ``n = 6``) for the displacement system, 24, 128, 704, 3840 for the force system; with every
  segment symmetric 8, 72, 456, 2488 and 16, 64, 256, 1024.
* Every query tracks the ``N`` paths on one homotopy (one ``gamma`` for all): first all together by the batched
  tracker of :mod:`.homotopy_tracker` (``TENSEGRITY_HOMOTOPY_TRACKER=phc``: by ``phc -p``, PHCpack's continuation
  from given start solutions, in ``threads`` processes over slices of the start roots). The set is certified when
  every path ended (a finite root at ``t = 1`` or diverged: "at infinity"), none failed, no two regular end points
  coincide (path jumping), and every real root inside the range polished (:func:`~.homotopy.polish_roots`).
  Singular end points (a degenerate equilibrium, several paths on one root) are kept as in :mod:`.homotopy`:
  accepted at a looser distance from the real set and polished by Newton.
* A path the first tracker did not end (the batched tracker leaves singular and ill-conditioned end points to
  PHCpack's end games), and two paths whose regular end points coincide, are tracked again by ``phc -p`` on the
  *same* homotopy (same ``gamma``) with careful settings (:data:`CAREFUL`): the same paths, followed more closely.
  If paths still fail (after :data:`ATTEMPTS` runs, each with a new ``gamma``), the full polyhedral solve
  (:func:`~.homotopy.solve_homotopy`) answers and the message says so.
* When every one of the ``N`` paths ends on a distinct regular finite root, that set is complete whatever happened
  along the paths: Bernstein's theorem bounds the isolated roots in the torus of *every* member of the family by the
  mixed volume ``N``, with multiplicity.

Sub-families: chains of identical segments tie their rows' torque coefficients; for n = 5 uniform bistable chains
256 of the 6272 paths (128 of 3840 for the force system) leave the torus (some ``z_j -> 0``) as ``t -> 1``. PHCpack
reports those paths failed (the set was uncertified); the batched tracker's end game reads their valuations
(``z_j ~ (1 - t)^w``, ``w`` rational and nonzero, agreeing at three checkpoints, with ``|z_j|`` already beyond 1e-3 or
1e3 where no real equilibrium lies) and counts them diverged, so these sets are certified. That classification is
numerical, like PHCpack's "at infinity"; a path it does not settle goes to ``phc -p`` as above.

Units: every solve runs on :func:`unit_chain` (lengths and stiffnesses rescaled by powers of two so that the mean
``b`` and the largest torque coefficient are about 1, the start parameters' magnitudes); the roots' forces are
returned in the caller's units. Without it a chain in other units ran its paths from coefficients ~1 to ones many
orders away: measured, a chain with stiffnesses times 1e-5 came back certified with no equilibrium (its small
forces read as diverging paths), lengths times 1e4 fell back to the polyhedral solve with half its paths failed.

The start roots are kept on disk per machine (:func:`start_file`: ``TENSEGRITY_CACHE_DIR`` like the compiled
kernels, a file per system kind, ``n``, structure and engine version :data:`ENGINE`); those of ``n <= 5``
ship with the package (``tensegrity_opt/numerics/homotopy_starts``). A query whose start file is missing
computes it first (one polyhedral solve of the generic instance) and stores it; the message says so.
``TENSEGRITY_HOMOTOPY_ENGINE=polyhedral`` makes every query use the polyhedral solve (comparisons, tests).
:func:`precompute` (CLI ``tensegrity-opt homotopy-precompute``) fills the cache ahead.
"""

from __future__ import annotations

import math
import os
import subprocess
import tempfile
import time
from dataclasses import dataclass, replace
from functools import lru_cache
from pathlib import Path

import numpy as np

from ..errors import HomotopyUnavailableError, InvalidParameterError, SolverError
from ..model.manipulator import Manipulator
from ..model.segment import Segment, clean_coefficients
from .build import cache_dir
from .homotopy import (
    HomotopySolve,
    _force_laurent_terms,
    _laurent_terms,
    _names,
    _residuals,
    _solve,
    _system_text,
    phc_path,
)
from .homotopy_tracker import FAILED, FINITE, INFINITE, track_batch

__all__ = ["ENGINE", "KINDS", "StartSolutions", "displacement_parameters", "displacement_family",
           "force_parameters", "force_family", "start_file", "load_start", "compute_start", "precompute",
           "track", "solve_parameter_homotopy", "solve_force_parameter_homotopy", "TORQUE_POWERS", "structure_of",
           "GENERAL", "SYMMETRIC", "TRACKERS", "tracker_name", "retarget_start", "unit_chain", "link_family",
           "link_structure", "solve_link_homotopy"]

#: The torque powers of a segment's parameters (:meth:`~tensegrity_opt.model.segment.Segment.torque_polynomial`
#: without its identically-zero ``z^0``).
TORQUE_POWERS = (2, 1, -1, -2)
#: The two system kinds: the displacement (KKT) system and the force-controlled one.
KINDS = ("displacement", "force")
#: The engine version in the start files' names: the file format and PHCpack's version (a start file of
#: another version is not used).
ENGINE = "f1-phc2.4.86"
#: The structures: a symmetric segment (``a = b`` and ``k1 = k2``) has no ``z^2``, ``z^-2`` torque terms, so
#: a chain with one lies in a sub-family with fewer roots (456 instead of 832 for the uniform n = 4 chain).
#: The general start system reaches it too, but its paths in excess end at toric infinity (some ``z_j -> 0``),
#: which PHCpack reports as failed paths: each pattern of symmetric segments has its own start roots
#: (``"general"``, ``"symmetric"`` or one letter per segment, ``g``/``s``: :func:`structure_of`).
GENERAL, SYMMETRIC = "general", "symmetric"
#: ``phc -p`` runs (each with a new ``gamma``, each with its careful re-tracking) before the polyhedral fallback.
#: The careful re-tracking fixes most paths that fail by chance (6-10 of 43648 at n = 6), not all: one n = 6 run
#: of three still had failures, and a second run (~3 min) is far cheaper than the polyhedral solve (12-21 min).
#: Paths ending at toric infinity fail in every run (uniform bistable n = 5 chains: 256 of 6272).
ATTEMPTS = 2
#: Two regular end points closer than this (max-norm, relative to ``1 + |x|``) are one root reached twice
#: (path jumping: a root may be missing).
CLUSTER_TOL = 1e-8
#: PHCpack's continuation settings for the tracking (``phc -p``'s menu: number, value); see :func:`track`.
#: Measured on the oracle chains (n = 4, 5): PHCpack's defaults take ~2.7 (n = 4) and ~5 ms (n = 5) of CPU a path,
#: these ~1.8 and ~3.4 ms (~30-45 steps, ~100-130 Newton iterations a path); larger steps, other predictors
#: or more corrector iterations were slower or made paths jump.
SETTINGS: tuple[tuple[int, float], ...] = ((4, 0.01), (21, 1e-6), (23, 1e-6), (25, 1e-6), (27, 1e-6))
#: The settings a failed or jumped path is tracked again with: steps of at most 0.02, tolerances 1e-10 along
#: the path.
CAREFUL: tuple[tuple[int, float], ...] = ((11, 0.02), (21, 1e-10), (23, 1e-10), (25, 1e-10), (27, 1e-10))
#: The first trackers of :func:`track` (``TENSEGRITY_HOMOTOPY_TRACKER``): the batched numpy tracker or ``phc -p``.
TRACKERS = ("batch", "phc")
_PACKAGED = Path(__file__).with_name("homotopy_starts")


# ----------------------------------------------------------------------------- the families
def _torque_parameters(m: Manipulator) -> np.ndarray:
    out = np.zeros((m.n, len(TORQUE_POWERS)), dtype=complex)
    for j, seg in enumerate(m.segments):
        tp = seg.torque_polynomial()
        out[j] = [tp.get(p, 0.0) for p in TORQUE_POWERS]
    return out


def displacement_parameters(m: Manipulator, target) -> np.ndarray:
    """The ``5 n + 2`` parameters of the displacement system of ``m`` for the tip at ``target``: the torque
    coefficients per segment (powers :data:`TORQUE_POWERS`), the link lengths, ``T = (x_t - b_1) + i y_t``
    and ``T' = conj(T)``."""
    T = complex(float(target[0]) - m.base_length, float(target[1]))
    return np.concatenate([_torque_parameters(m).ravel(), np.asarray(m.link_lengths, dtype=complex),
                           [T, T.conjugate()]])


def force_parameters(m: Manipulator, force) -> np.ndarray:
    """The ``6 n`` parameters of the force system of ``m`` under the tip load ``force``: the torque coefficients
    per segment, ``c_j = l_j g`` and ``d_j = l_j h`` (``g = Fx + i Fy``, ``h = conj(g)``)."""
    g = complex(float(force[0]), float(force[1]))
    l = np.asarray(m.link_lengths, dtype=complex)
    return np.concatenate([_torque_parameters(m).ravel(), l * g, l * g.conjugate()])


def _torque_rows(n: int, nv: int, p: np.ndarray) -> list[dict]:
    """``E_j' - E_{j+1}'`` (``E_n'`` last) as dicts, from the torque parameters ``p`` (n, 4); a parameter that
    is exactly zero (the ``z^+-2`` terms of a symmetric segment) leaves its monomial out."""
    def dE(j: int) -> dict:
        out = {}
        for k, pw in enumerate(TORQUE_POWERS):
            if p[j, k] == 0.0:
                continue
            e = [0] * nv
            e[j] = pw
            out[tuple(e)] = complex(p[j, k])
        return out

    dEs = [dE(j) for j in range(n)]
    rows = []
    for j in range(n):
        row = dict(dEs[j])
        if j < n - 1:
            for e, c in dEs[j + 1].items():
                row[e] = row.get(e, 0.0) - c
        rows.append(row)
    return rows


def _direction(nv: int, j: int, sign: int, extra: int | None = None) -> tuple[int, ...]:
    e = [0] * nv
    for i in range(j + 1):
        e[i] = 2 * sign
    if extra is not None:
        e[extra] += 1
    return tuple(e)


def displacement_family(n: int, p) -> list[dict]:
    """The displacement system's ``n + 2`` Laurent polynomials (dicts exponent -> coefficient; unknowns
    ``z_1..z_n, g, h``) at the parameters ``p`` (:func:`displacement_parameters`), linear in ``p``: the system
    of :func:`~.homotopy.polynomial_system` for real parameters."""
    p = np.asarray(p, dtype=complex)
    tq, l, T, Tc = p[:4 * n].reshape(n, 4), p[4 * n:5 * n], p[5 * n], p[5 * n + 1]
    return link_family(tq, l, l, T, Tc)


def link_family(torques, links, links_conj, T: complex, Tc: complex) -> list[dict]:
    """The displacement system of a chain of ``n = len(links)`` joints whose links are *complex* vectors:
    link ``j`` is ``mu_j e^{i phi_j}`` in the tip equation and ``mu'_j e^{-i phi_j}`` in its conjugate
    (``mu' = conj(mu)`` on real chains; ``mu = mu' = l_j`` is :func:`displacement_family`), and the moment of the
    tip force about it is ``(mu'_j e^{-i phi_j} g - mu_j e^{i phi_j} h) / (2i)``. ``torques`` (n, 4): each joint's
    torque coefficients (powers :data:`TORQUE_POWERS`; exact zeros leave their monomials out).

    This is the system of a chain with some joints held at fixed angles (on their stops): the links between two
    free joints fold into one rigid complex link, the links before the first free joint into the target ``T``
    (see :mod:`tensegrity_opt.analyses.equilibria.tension_only_homotopy`). Its monomials are those of the
    ``n``-joint family, and the generic start roots of that family (all ``N`` of them regular) are a generic start
    for this larger one (untied ``mu``, ``mu'``): its root count is at most the mixed volume ``N`` and is reached."""
    tq = np.asarray(torques, dtype=complex)
    n = tq.shape[0]
    nv = n + 2
    zero = (0,) * nv
    tip1: dict = {zero: -complex(T)}
    tip2: dict = {zero: -complex(Tc)}
    for j in range(n):
        tip1[_direction(nv, j, 1)] = complex(links[j])
        tip2[_direction(nv, j, -1)] = complex(links_conj[j])
    rows = _torque_rows(n, nv, tq)
    for j in range(n):
        for e, c in ((_direction(nv, j, -1, n), -complex(links_conj[j]) / 2j),
                     (_direction(nv, j, 1, n + 1), complex(links[j]) / 2j)):
            rows[j][e] = rows[j].get(e, 0.0) + c
    return [tip1, tip2] + rows


def force_family(n: int, p) -> list[dict]:
    """The force system's ``n`` Laurent polynomials (unknowns ``z_1..z_n``) at the parameters ``p``
    (:func:`force_parameters`), linear in ``p``."""
    p = np.asarray(p, dtype=complex)
    tq, c, d = p[:4 * n].reshape(n, 4), p[4 * n:5 * n], p[5 * n:6 * n]
    rows = _torque_rows(n, n, tq)
    for j in range(n):
        # e^{-+i phi_j} may be a torque monomial of the next segment (j = 0: z_1^-+2): the terms add
        for e, v in ((_direction(n, j, -1), -complex(c[j]) / 2j), (_direction(n, j, 1), complex(d[j]) / 2j)):
            rows[j][e] = rows[j].get(e, 0.0) + v
    return rows


def _family(kind: str):
    return displacement_family if kind == "displacement" else force_family


def _unknowns(kind: str, n: int) -> list[str]:
    return _names(n) if kind == "displacement" else _names(n)[:n]


def _typical_parameters(kind: str, n: int) -> np.ndarray:
    """The parameters of a typical chain (general segments of mixed sizes and preloads, tip pulled in by a
    quarter of its length, or a moderate load): the magnitudes of the random start parameters."""
    segs = []
    for j in range(n):
        a, b = 0.5 + 0.1 * (j % 3), 1.0 - 0.05 * (j % 2)
        segs.append({"a": a, "b": b, "k": [1.0 + 0.1 * j, 1.3], "L0": [1.1 * b, 0.9 * b]})
    m = Manipulator.from_dict({"segments": segs})
    if kind == "displacement":
        return displacement_parameters(m, m.target(0.3 * m.straight_length, 0.1 * m.straight_length))
    return force_parameters(m, (-0.3, 0.2))


def structure_of(m: Manipulator) -> str:
    """The structure of ``m``'s systems: ``"general"`` when no segment is symmetric, ``"symmetric"`` when all are,
    else one letter per segment (``g`` general, ``s`` symmetric: ``a = b`` and ``k1 = k2``, whose torque has no
    ``z^+-2`` terms after :func:`~tensegrity_opt.model.segment.clean_coefficients`)."""
    flags = "".join("g" if 2 in clean_coefficients(seg.torque_polynomial()) else "s" for seg in m.segments)
    return GENERAL if set(flags) == {"g"} else SYMMETRIC if set(flags) == {"s"} else flags


def _flags(structure: str, n: int) -> str:
    flags = "g" * n if structure == GENERAL else "s" * n if structure == SYMMETRIC else structure
    if len(flags) != n or set(flags) - {"g", "s"}:
        raise InvalidParameterError(f"structure must be 'general', 'symmetric' or {n} letters g/s, got "
                                    f"{structure!r}", field="structure")
    return flags


# ----------------------------------------------------------------------------- the start solutions
@dataclass(frozen=True)
class StartSolutions:
    """The isolated roots of one generic instance of a family, the start of every parameter homotopy.

    Attributes
    ----------
    kind : str
        ``"displacement"`` or ``"force"`` (:data:`KINDS`).
    n : int
        Segments.
    structure : str
        Which torque terms the family has (:func:`structure_of`).
    parameters : ndarray complex
        The generic start parameters ``p0`` (:func:`displacement_parameters` / :func:`force_parameters` layout).
    roots : ndarray (N, nv) complex
        Its ``N`` isolated roots (the generic root count of the family).
    paths : int
        Paths of the polyhedral solve that found them (its mixed volume).
    seconds : float
        Wall time of that solve.
    source : str
        Where they came from: ``"packaged"``, ``"cache"`` or ``"computed"`` (this call).
    """

    kind: str
    n: int
    structure: str
    parameters: np.ndarray
    roots: np.ndarray
    paths: int
    seconds: float
    source: str = "cache"

    @property
    def count(self) -> int:
        """``N``, the number of start roots (paths a query tracks)."""
        return int(self.roots.shape[0])


def _file_name(kind: str, n: int, structure: str) -> str:
    return f"{kind}-n{n}-{structure}-{ENGINE}.npz"


def start_file(kind: str, n: int, structure: str = GENERAL) -> Path:
    """Where the start roots of ``kind``, ``n`` and ``structure`` are cached on this machine
    (``<cache_dir>/homotopy/<kind>-n<n>-<structure>-<engine>.npz``)."""
    return cache_dir() / "homotopy" / _file_name(kind, n, structure)


def _check_kind(kind: str) -> None:
    if kind not in KINDS:
        raise InvalidParameterError(f"kind must be one of {KINDS}, got {kind!r}", field="kind")


def _read(path: Path, kind: str, n: int, structure: str, source: str) -> StartSolutions | None:
    """The start file at ``path`` checked (:func:`load_start`), kept in memory while the file is unchanged (its
    checks cost ~0.1 s at n = 5, ~1 s at n = 6: every query would pay them)."""
    try:
        st = path.stat()
    except OSError:
        return None
    return _read_checked(str(path), st.st_mtime_ns, st.st_size, st.st_ino, kind, n, structure, source)


@lru_cache(maxsize=32)
def _read_checked(path: str, mtime_ns: int, size: int, inode: int, kind: str, n: int, structure: str,
                  source: str) -> StartSolutions | None:
    try:
        with np.load(path) as f:
            start = StartSolutions(kind, n, structure, np.asarray(f["parameters"], complex),
                                   np.asarray(f["roots"], complex), int(f["paths"]), float(f["seconds"]), source)
    except (OSError, KeyError, ValueError):
        return None
    nv = len(_unknowns(kind, n))
    if start.roots.ndim != 2 or start.roots.shape[1] != nv or start.roots.shape[0] == 0:
        return None
    # the roots must solve their system (a damaged or foreign file is ignored)
    if np.max(_residuals(_family(kind)(n, start.parameters), start.roots)) > 1e-8:
        return None
    start.roots.setflags(write=False)
    start.parameters.setflags(write=False)
    return start


def load_start(kind: str, n: int, structure: str = GENERAL) -> StartSolutions | None:
    """The start roots of ``kind``, ``n`` and ``structure`` from this machine's cache, else from the package's
    data, else ``None``. A file whose roots do not solve its system (residual above ``1e-8``) is ignored."""
    _check_kind(kind)
    _flags(structure, n)
    for path, source in ((start_file(kind, n, structure), "cache"),
                         (_PACKAGED / _file_name(kind, n, structure), "packaged")):
        if path.exists():
            start = _read(path, kind, n, structure, source)
            if start is not None:
                return start
    return None


def _save(start: StartSolutions, path: Path) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=path.stem, suffix=".tmp.npz")
    os.close(fd)
    np.savez_compressed(tmp, parameters=start.parameters, roots=start.roots, paths=start.paths,
                        seconds=start.seconds)
    os.chmod(tmp, 0o644)
    os.replace(tmp, path)                   # atomic: concurrent writers leave one complete file


def compute_start(kind: str, n: int, structure: str = GENERAL, *, threads: int | None = None,
                  timeout: float | None = None, attempts: int = 4, seed: int | None = None,
                  store: bool = True) -> StartSolutions:
    """Solve a generic instance of the family ``kind`` for ``n`` segments of the ``structure`` by ``phc -b``
    and (``store``) cache its roots (:func:`start_file`).

    The start parameters are the :func:`_typical_parameters` magnitudes with random phases and a random
    factor in ``[0.5, 1.5]`` (generic with probability one), the ``z^+-2`` torque parameters of the symmetric
    segments zero. A solve counts when PHCpack's report checked out,
    no path failed or diverged, and no two roots coincide; else a new instance is drawn, up to ``attempts``.

    Raises
    ------
    SolverError
        (``RuntimeError``, status ``"phc_failed"``) when no attempt gave a clean solve.
    """
    _check_kind(kind)
    flags = _flags(structure, n)
    rng = np.random.default_rng(seed)
    names = _unknowns(kind, n)
    typical = _typical_parameters(kind, n)
    for j, f in enumerate(flags):
        if f == "s":
            typical[4 * j + TORQUE_POWERS.index(2)] = typical[4 * j + TORQUE_POWERS.index(-2)] = 0.0
    why = ""
    deadline = None if timeout is None else time.monotonic() + float(timeout)
    for _ in range(max(1, int(attempts))):
        left = None if deadline is None else max(1.0, deadline - time.monotonic())
        p0 = typical * rng.uniform(0.5, 1.5, typical.size) * np.exp(2j * np.pi * rng.random(typical.size))
        polys = _family(kind)(n, p0)
        sol = _solve(_system_text(polys, names), names, n, threads, left, 1)
        if not sol.complete or sol.at_infinity or sol.roots.shape[0] != sol.paths:
            why = f"{sol.failures} failed, {sol.at_infinity} diverged of {sol.paths} paths"
            continue
        if _clusters(sol.roots, np.ones(sol.roots.shape[0], bool)):
            why = "two roots coincide"
            continue
        start = StartSolutions(kind, n, structure, p0, sol.roots, sol.paths, sol.seconds, "computed")
        if store:
            _save(start, start_file(kind, n, structure))
        return start
    raise SolverError(f"no clean polyhedral solve of a generic {kind} system, n = {n}, {structure} ({why})",
                      status="phc_failed")


def retarget_start(start: StartSolutions, *, seed: int | None = None, threads: int | None = None,
                   store: bool = True) -> StartSolutions:
    """New start roots for the family of ``start``: its roots tracked (:func:`track`: the batched tracker, ``phc -p``
    for the paths it leaves) to a fresh generic instance drawn as in :func:`compute_start`.

    A way to renew a start file (a new ``p0``, roots to full precision) without a polyhedral solve (~12 min at
    n = 6). It counts only when every one of the ``N`` paths ended on a regular root and no two coincide: ``N``
    distinct regular roots of a system whose isolated roots are at most ``N`` (the mixed volume, Bernstein) are all
    of them, however they were reached. ``store`` caches it (:func:`start_file`).

    Raises
    ------
    SolverError
        (``RuntimeError``, status ``"phc_failed"``) when a path did not end cleanly or two coincide.
    """
    rng = np.random.default_rng(seed)
    typical = _typical_parameters(start.kind, start.n)
    zero = np.asarray(start.parameters) == 0.0
    p1 = typical * rng.uniform(0.5, 1.5, typical.size) * np.exp(2j * np.pi * rng.random(typical.size))
    p1[zero] = 0.0
    target = _family(start.kind)(start.n, p1)
    t0 = time.perf_counter()
    out = track(target, start, threads=threads, rng=rng)
    if not out.complete or out.roots.shape[0] != start.count or not out.regular.all():
        raise SolverError(f"retargeting the {start.kind} start roots (n = {start.n}, {start.structure}): "
                          f"{out.failures} failed, {out.at_infinity} diverged, {out.singular} singular of "
                          f"{start.count} paths", status="phc_failed")
    new = StartSolutions(start.kind, start.n, start.structure, p1, out.roots, start.paths,
                         time.perf_counter() - t0, "computed")
    if store:
        _save(new, start_file(start.kind, start.n, start.structure))
    return new


def precompute(max_segments: int = 5, kinds=KINDS, *, min_segments: int = 2, force: bool = False,
               structures=(GENERAL, SYMMETRIC), threads: int | None = None,
               progress=None) -> list[tuple[str, int, StartSolutions]]:
    """Compute and cache the start roots of every ``kind`` in ``kinds`` and structure in ``structures`` for
    ``n = min_segments..max_segments`` (those already cached or packaged are kept unless ``force``).
    ``progress(kind, n, start)`` is called after each. Returns ``(kind, n, start)`` per system."""
    out = []
    for kind in kinds:
        _check_kind(kind)
        for structure in structures:
            for n in range(int(min_segments), int(max_segments) + 1):
                start = None if force else load_start(kind, n, structure)
                if start is None:
                    start = compute_start(kind, n, structure, threads=threads)
                out.append((kind, n, start))
                if progress is not None:
                    progress(kind, n, start)
    return out


# ----------------------------------------------------------------------------- tracking
def _cluster_pairs(roots: np.ndarray, rows: np.ndarray) -> set[int]:
    """The rows (of ``rows``) of ``roots`` that coincide with another within :data:`CLUSTER_TOL` (max-norm,
    relative to ``1 + |x|``): one root reached by two paths (path jumping: a root may be missing)."""
    rows = np.asarray(rows, dtype=int)
    if rows.size < 2:
        return set()
    R = roots[rows]
    scale = 1.0 + np.abs(R).max(axis=1)
    # sorted along a fixed projection, neighbours compared within the tolerance window
    key = (R @ np.exp(1j * np.arange(1, R.shape[1] + 1))).real
    order = np.argsort(key)
    out: set[int] = set()
    for a in range(order.size):
        i = order[a]
        for b in range(a + 1, order.size):
            j = order[b]
            tol = CLUSTER_TOL * max(scale[i], scale[j])
            if key[j] - key[i] > tol * R.shape[1]:
                break
            if np.abs(R[j] - R[i]).max() <= tol:
                out.update((int(rows[i]), int(rows[j])))
    return out


def _clusters(roots: np.ndarray, regular: np.ndarray) -> int:
    """Regular roots that coincide with another (:func:`_cluster_pairs`)."""
    return len(_cluster_pairs(roots, np.flatnonzero(regular)))


def _script(target: str, out: str, start: str, gamma: complex, settings) -> str:
    """The answers to ``phc -p``'s dialogue: target, output, no separate solution file, start file, homotopy
    ``gamma (1 - t) Q + t P`` (relaxation ``k = 1``, accessibility constant ``gamma``), continuation settings,
    no intermediate output."""
    lines = [target, out, "n", start, "k", "1", "a", repr(gamma.real), repr(gamma.imag), "0"]
    for key, value in settings:
        lines += [str(int(key)), str(int(value)) if float(value).is_integer() else repr(float(value))]
    lines += ["0", "0"]
    return "\n".join(lines) + "\n"


def _solutions_text(roots: np.ndarray, names: list[str]) -> str:
    """Start solutions in PHCpack's format, each at ``t = 0``."""
    lines = ["THE SOLUTIONS :", f"{roots.shape[0]} {len(names)}", "=" * 75]
    zero = f"{0.0: .17E}"
    for k, r in enumerate(roots):
        lines += [f"solution {k + 1} :", f"t : {zero}  {zero}", "m : 1", "the solution for t :"]
        lines += [f" {nm} : {v.real: .17E}  {v.imag: .17E}" for nm, v in zip(names, r)]
        lines.append("== err :  0.000E+00 = rco :  1.000E+00 = res :  0.000E+00 ==")
    return "\n".join(lines) + "\n"


_NUM = r"[-+]?\d+\.\d+E[-+]\d+"


def _blocks(report: str, names: list[str], count: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, bool]:
    """Read a ``phc -p`` report of ``count`` paths in order: ``(state (count,), roots (count, nv), regular
    (count,), consistent)``. A path's state is :data:`FINITE` (ended at ``t = 1`` on a finite root, every unknown
    read), :data:`INFINITE` (phc classified it "at infinity") or :data:`FAILED` (phc's "failure", "no solution",
    "clustered", a path short of ``t = 1``, an unreadable block). ``consistent``: the solution list's declared
    size and its number of blocks equal ``count``."""
    import re

    state = np.full(count, FAILED)
    roots = np.full((count, len(names)), np.nan + 0j)
    regular = np.zeros(count, dtype=bool)
    _, sep, sols = report.rpartition("THE SOLUTIONS")
    if not sep:
        return state, roots, regular, False
    declared = re.search(r"^\s*:?\s*(\d+)\s+(\d+)\s*$", sols, flags=re.M)
    blocks = re.split(r"^solution \d+ :", sols, flags=re.M)[1:]
    consistent = declared is not None and int(declared.group(1)) == len(blocks) == count
    for k, blk in enumerate(blocks[:count]):
        t = re.search(r"^t :\s*(" + _NUM + r")\s+(" + _NUM + r")", blk, flags=re.M)
        found = re.search(r"^== err.*==\s*$", blk, flags=re.M)
        tail = found.group(0) if found else ""
        if "the solution for t" not in blk or t is None or not tail:
            continue
        if "failure" in tail or "no solution" in tail or "clustered" in tail:
            continue
        if "infinity" in tail or "infinite" in tail:
            state[k] = INFINITE
            continue
        vals = dict((v, complex(float(r), float(i))) for v, r, i in re.findall(
            r"^\s*(\w+)\s*:\s*(" + _NUM + r")\s+(" + _NUM + r")\s*$", blk.split("the solution for t :", 1)[1],
            flags=re.M))
        if abs(float(t.group(1)) - 1.0) > 1e-8 or any(v not in vals for v in names):
            continue
        state[k] = FINITE
        roots[k] = [vals[v] for v in names]
        regular[k] = "singular" not in tail
    return state, roots, regular, consistent


def _run_slices(exe: str, target_text: str, start: StartSolutions, rows: np.ndarray, k: int, gamma: complex,
                settings, deadline: float | None) -> tuple[np.ndarray, np.ndarray, np.ndarray, bool]:
    """``phc -p`` in ``k`` processes over the start roots ``rows``: per row its state, end point and regularity
    (:func:`_blocks`), and whether every report checked out (exit code 0, counts)."""
    names = _unknowns(start.kind, start.n)
    slices = [s for s in np.array_split(np.asarray(rows, dtype=int), max(1, min(k, len(rows)))) if s.size]
    start_sys = _system_text(_family(start.kind)(start.n, start.parameters), names)
    state = np.full(len(rows), FAILED)
    roots = np.full((len(rows), len(names)), np.nan + 0j)
    regular = np.zeros(len(rows), dtype=bool)
    consistent = True
    with tempfile.TemporaryDirectory(prefix="tensegrity_phcp_") as tmp:
        with open(os.path.join(tmp, "target.phc"), "w") as f:
            f.write(target_text)
        procs = []
        try:
            for i, sl in enumerate(slices):
                with open(os.path.join(tmp, f"start{i}.phc"), "w") as f:
                    f.write(start_sys + "\n" + _solutions_text(start.roots[sl], names))
                proc = subprocess.Popen([exe, "-p"], cwd=tmp, stdin=subprocess.PIPE, stdout=subprocess.DEVNULL,
                                        stderr=subprocess.DEVNULL)
                procs.append(proc)
                proc.stdin.write(_script("target.phc", f"out{i}.txt", f"start{i}.phc", gamma, settings).encode())
                proc.stdin.close()
            codes = []
            for proc in procs:
                left = None if deadline is None else max(0.0, deadline - time.monotonic())
                try:
                    codes.append(proc.wait(timeout=left))
                except subprocess.TimeoutExpired:
                    raise SolverError(f"phc -p did not finish in time (n = {start.n})", status="phc_timeout") from None
        finally:
            for proc in procs:
                if proc.poll() is None:
                    proc.kill()
                    proc.wait()
        at = 0
        for i, sl in enumerate(slices):
            path = os.path.join(tmp, f"out{i}.txt")
            if not os.path.exists(path):
                raise SolverError(f"phc -p wrote no output (exit code {codes[i]})", status="phc_failed")
            with open(path, errors="replace") as f:
                st, rt, rg, ok = _blocks(f.read(), names, sl.size)
            state[at:at + sl.size], roots[at:at + sl.size], regular[at:at + sl.size] = st, rt, rg
            consistent = consistent and ok and codes[i] == 0
            at += sl.size
    return state, roots, regular, consistent


def tracker_name() -> str:
    """The first tracker of :func:`track`: ``"batch"`` (:mod:`.homotopy_tracker`, the default) or ``"phc"`` (``phc -p``
    for every path), from ``TENSEGRITY_HOMOTOPY_TRACKER``."""
    name = os.environ.get("TENSEGRITY_HOMOTOPY_TRACKER", "").strip().lower() or "batch"
    if name not in TRACKERS:
        raise InvalidParameterError(f"TENSEGRITY_HOMOTOPY_TRACKER must be one of {TRACKERS}, got {name!r}",
                                    field="TENSEGRITY_HOMOTOPY_TRACKER")
    return name


def track(target: list[dict], start: StartSolutions, *, threads: int | None = None, timeout: float | None = None,
          gamma: complex | None = None, settings=None, careful=None, rng=None, tracker: str | None = None
          ) -> HomotopySolve:
    """Track the ``N`` start roots of ``start`` to the system ``target`` (a member of the family, Laurent polynomials
    as dicts exponent -> coefficient), all on the one homotopy ``gamma (1 - t) F(x; p0) + t F(x; p1)`` (``gamma``
    random on the unit circle unless given).

    The ``tracker`` (default :func:`tracker_name`) follows every path first: ``"batch"`` advances them together in
    numpy (:func:`~.homotopy_tracker.track_batch`), ``"phc"`` runs ``phc -p`` with ``settings`` (default
    :data:`SETTINGS`: quick) in ``threads`` processes over slices of the start roots. The paths it did not end, and
    those whose regular end points coincide with another's (path jumping), are tracked again by ``phc -p`` on the
    *same* homotopy with ``careful`` settings (default :data:`CAREFUL`: small steps, tight tolerances; PHCpack's end
    games judge singular end points and paths to infinity). A path is the same path however it is followed, so the
    end points stay those of one homotopy.

    Returns the end points as a :class:`~.homotopy.HomotopySolve` (``paths = N``; ``failures`` counts the paths
    that failed again or still coincide; ``retracked`` the paths ``phc -p`` tracked again; ``consistent`` when
    every report checked out).

    Raises
    ------
    SolverError
        (``RuntimeError``) status ``"phc_timeout"`` or ``"phc_failed"``.
    """
    exe = phc_path()
    if exe is None:
        raise HomotopyUnavailableError(
            "the homotopy method needs PHCpack's 'phc' on the PATH: install the Debian package 'phcpack' "
            "(apt-get install phcpack) or set TENSEGRITY_PHC to the executable", field="method")
    if threads is None:
        threads = max(1, min(8, len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else 1))
    rng = np.random.default_rng() if rng is None else rng
    if gamma is None:
        gamma = complex(np.exp(2j * np.pi * rng.random()))
    tracker = tracker_name() if tracker is None else tracker
    settings = SETTINGS if settings is None else settings
    careful = CAREFUL if careful is None else careful
    deadline = None if timeout is None else time.monotonic() + float(timeout)
    names = _unknowns(start.kind, start.n)
    target_text = _system_text(target, names)
    N = start.count
    t0 = time.perf_counter()
    if tracker == "batch":
        tracked = track_batch(_family(start.kind)(start.n, start.parameters), target, gamma, start.roots,
                              threads=int(threads), deadline=deadline, angles=start.n)
        state, roots, regular, consistent = tracked.state, tracked.roots, tracked.regular, True
    else:
        state, roots, regular, consistent = _run_slices(exe, target_text, start, np.arange(N), int(threads), gamma,
                                                        settings, deadline)
    bad = np.flatnonzero(state == FAILED)
    jumped = _cluster_pairs(roots, np.flatnonzero((state == FINITE) & regular))
    again = np.union1d(bad, np.array(sorted(jumped), dtype=int))
    retracked = int(again.size)
    if again.size:
        st, rt, rg, ok = _run_slices(exe, target_text, start, again, int(threads), gamma, careful, deadline)
        state[again], roots[again], regular[again] = st, rt, rg
        consistent = consistent and ok
    failed = set(np.flatnonzero(state == FAILED).tolist())
    failed |= _cluster_pairs(roots, np.flatnonzero((state == FINITE) & regular))
    fin = (state == FINITE) & ~np.isin(np.arange(N), list(failed))
    return HomotopySolve(roots=roots[fin], regular=regular[fin], paths=N, failures=len(failed),
                         at_infinity=int((state == INFINITE).sum()), singular=int((fin & ~regular).sum()),
                         seconds=time.perf_counter() - t0, threads=int(threads), attempts=1, consistent=consistent,
                         engine="parameter", retracked=retracked, tracker=tracker)


# ----------------------------------------------------------------------------- the solves
def _parameter_solve(kind: str, n: int, structure: str, target: list[dict], polyhedral, *, threads: int | None,
                     timeout: float | None, attempts: int = ATTEMPTS) -> HomotopySolve:
    """Track from the cached start roots (computing them when missing), repeat once with a new ``gamma`` when
    paths fail, else the polyhedral solve ``polyhedral(timeout)``; the result's ``note`` says which."""
    t0 = time.monotonic()
    deadline = None if timeout is None else t0 + float(timeout)

    def left() -> float | None:
        return None if deadline is None else deadline - time.monotonic()

    if os.environ.get("TENSEGRITY_HOMOTOPY_ENGINE", "").strip().lower() == "polyhedral":
        return polyhedral(timeout)
    start = load_start(kind, n, structure)
    note = ""
    if start is None:
        try:
            start = compute_start(kind, n, structure, threads=threads, timeout=timeout)
        except SolverError as exc:
            if exc.status == "phc_timeout":
                raise
            sol = polyhedral(left())
            return replace(sol, note=f"no start solutions for n = {n} ({exc}): the polyhedral solve answered")
        note = (f"; the start solutions (n = {n}, {structure}, {start.count} roots) were missing: computed now "
                f"({start.seconds:.1f} s) and stored in {start_file(kind, n, structure)}")
    best = None
    spent = 0.0
    runs = 0
    for attempt in range(max(1, int(attempts))):
        rest = left()
        if rest is not None and rest <= 0.0:
            break
        try:
            sol = track(target, start, threads=threads, timeout=rest)
        except SolverError as exc:
            if exc.status == "phc_timeout":
                raise
            note += f"; phc -p failed ({exc})"
            break
        spent += sol.seconds
        runs = attempt + 1
        sol = replace(sol, attempts=runs, seconds=spent)
        if best is None or (not sol.complete, sol.failures) < (not best.complete, best.failures):
            best = sol
        if sol.complete:
            how = "batched tracker" if sol.tracker == "batch" else "phc -p"
            again = f", {sol.retracked} paths tracked again by phc -p" if sol.retracked else ""
            return replace(sol, note=f"parameter homotopy from {start.count} start solutions "
                                     f"({structure}, {start.source}; {how}{again})" + note)
    if best is None:
        why = "phc -p did not run"
    elif best.failures:
        why = f"{best.failures} of {best.paths} paths failed or coincided in the best of {runs} runs"
    else:
        why = f"its report did not check out ({runs} runs)"
    rest = left()
    if best is not None and rest is not None and rest <= 0.0:
        return replace(best, note=f"parameter homotopy from {start.count} start solutions: {why}, no time left "
                                  "for the polyhedral fallback" + note)
    sol = polyhedral(rest)
    return replace(sol, seconds=sol.seconds + spent,
                   note=f"the parameter homotopy from {start.count} start solutions was not complete ({why}): the "
                        "full polyhedral solve answered" + note)


def unit_chain(m: Manipulator) -> tuple[Manipulator, float, float]:
    """``(m', lam, kap)``: ``m`` with its lengths multiplied by ``lam`` and its stiffnesses by ``kap`` (powers of two:
    exact), so that the mean ``b`` and the largest torque coefficient ``k (a^2 + b^2)`` are about 1, the magnitudes
    of the start parameters. The joint angles of every equilibrium are unchanged; tip targets scale by ``lam``, forces
    by ``kap lam``. The tracked paths stay well scaled whatever the caller's units (a chain in micrometres or with
    springs of 1e8 would otherwise run from start parameters about 1 to coefficients many orders away)."""
    lam = 2.0 ** -round(math.log2(float(np.mean(m.b))))
    torque = m.torque_scale * lam * lam
    kap = 2.0 ** -round(math.log2(torque))
    if lam == 1.0 and kap == 1.0:
        return m, lam, kap
    segs = [Segment(s.a * lam, s.b * lam, (s.k1 * kap, s.k2 * kap), (s.L1_0 * lam, s.L2_0 * lam)) for s in m.segments]
    return Manipulator(segs), lam, kap


def _in_units(sol: HomotopySolve, factor: float) -> HomotopySolve:
    """The roots of a displacement solve in unit-chain units back in the caller's (the force columns ``g, h``
    divided by ``factor = kap lam``)."""
    if factor == 1.0 or sol.roots.size == 0:
        return sol
    roots = np.array(sol.roots, dtype=complex)
    roots[:, -2:] /= factor
    return replace(sol, roots=roots)


def solve_parameter_homotopy(m: Manipulator, target, *, threads: int | None = None,
                             timeout: float | None = None, attempts: int = ATTEMPTS) -> HomotopySolve:
    """Every isolated root of the displacement system (:func:`~.homotopy.polynomial_system`) by the parameter
    homotopy from the cached start roots (see the module), else by the polyhedral solve
    (:func:`~.homotopy.solve_homotopy`); ``note`` says which. Same roots, errors and parameters as
    :func:`~.homotopy.solve_homotopy` (``timeout`` for the whole call). Both solve the chain in the units of
    :func:`unit_chain`; the roots come back in the caller's."""
    from .homotopy import solve_homotopy

    u, lam, kap = unit_chain(m)
    tu = np.asarray(target, dtype=float) * lam
    sol = _parameter_solve("displacement", m.n, structure_of(u), _laurent_terms(u, tu),
                           lambda left: solve_homotopy(u, tu, threads=threads, timeout=left),
                           threads=threads, timeout=timeout, attempts=attempts)
    return _in_units(sol, kap * lam)


def solve_force_parameter_homotopy(m: Manipulator, force, *, threads: int | None = None,
                                   timeout: float | None = None, attempts: int = ATTEMPTS) -> HomotopySolve:
    """Every isolated root of the force system (:func:`~.homotopy.force_polynomial_system`, ``force != 0``) by
    the parameter homotopy, else the polyhedral :func:`~.homotopy.solve_force_homotopy`; as
    :func:`solve_parameter_homotopy` (the roots, joint half-angles only, are the same in every unit)."""
    from .homotopy import solve_force_homotopy

    u, lam, kap = unit_chain(m)
    fu = np.asarray(force, dtype=float) * (kap * lam)
    return _parameter_solve("force", m.n, structure_of(u), _force_laurent_terms(u, fu),
                            lambda left: solve_force_homotopy(u, fu, threads=threads, timeout=left),
                            threads=threads, timeout=timeout, attempts=attempts)


def link_structure(torques) -> str:
    """:func:`structure_of` for :func:`link_family`'s ``torques`` (n, 4): ``s`` for a joint without ``z^+-2``
    terms (relative to its largest coefficient, below ``CLEAN_TOL``), else ``g``."""
    from ..model.segment import CLEAN_TOL

    tq = np.abs(np.asarray(torques, dtype=complex))
    big = np.maximum(tq.max(axis=1), 1e-300)
    flags = "".join("g" if max(row[0], row[3]) > CLEAN_TOL * b else "s" for row, b in zip(tq, big))
    return GENERAL if set(flags) == {"g"} else SYMMETRIC if set(flags) == {"s"} else flags


def solve_link_homotopy(torques, links, links_conj, T: complex, Tc: complex, *, threads: int | None = None,
                        timeout: float | None = None, attempts: int = ATTEMPTS) -> HomotopySolve:
    """Every isolated root of :func:`link_family` (unknowns ``z_1..z_n, g, h``) by the parameter homotopy from the
    cached start roots of the ``n``-joint displacement family (structure :func:`link_structure`), else the polyhedral
    solve of the same system; as :func:`solve_parameter_homotopy` but in the caller's units (scale the chain first:
    :func:`unit_chain`)."""
    tq = np.asarray(torques, dtype=complex)
    from ..model.segment import CLEAN_TOL

    big = np.abs(tq).max(axis=1, keepdims=True)
    tq = np.where(np.abs(tq) > CLEAN_TOL * big, tq, 0.0)
    n = tq.shape[0]
    system = link_family(tq, links, links_conj, T, Tc)
    names = _names(n)
    return _parameter_solve("displacement", n, link_structure(tq), system,
                            lambda left: _solve(_system_text(system, names), names, n, threads, left, attempts),
                            threads=threads, timeout=timeout, attempts=attempts)

