"""Design-space sweeps: one analysis over a grid or a list of points, serially or on Dask.

A sweep spec (JSON-friendly dict)::

    {"analysis": "buckling",                       # buckling | equilibrium | equilibria_count
                                                   # | stiffness | design | atlas
     "manipulator": {"n": 4, "a": 1, "b": 1, "k": 1, "L0": 1},   # uniform base chain (defaults shown)
     "grid": {"n": [3, 4, 5], "k": [0.5, 1, 2]},   # cartesian product, first key varies slowest
     # or "points": [{"n": 4, "dx": 0.1}, {"n": 5, "dx": 0.2}],   # an explicit list
     "options": {"boundary": "guided"}}            # see below

Parameters a point may set (``grid`` lists or ``points`` entries):

=========  ===========================  ===================================================
name       value                        used by
=========  ===========================  ===================================================
``n``      integer >= 1                 every analysis (segments of the uniform chain)
``a``      number > 0                   every analysis (triangle half-height)
``b``      number > 0                   every analysis (triangle half-length)
``k``      number > 0                   every analysis (both springs' stiffness)
``L0``     number > 0                   every analysis (both springs' rest length)
``dx``     number (default 0)           equilibrium, stiffness, equilibria_count, atlas
``dy``     number (default 0)           equilibrium, stiffness, equilibria_count, atlas
``load``   ``[fx, fy]``                 equilibrium, stiffness (tip force instead of dx/dy)
=========  ===========================  ===================================================

A constant is a one-value list (``"dx": [0.1]``). A point gives either a tip deflection
(``dx``/``dy``) or a tip force (``load``), never both. Parameters the analysis does not use
are refused. The base chain may instead be given segment by segment (pre-bent, heterogeneous):
``"manipulator": {"segments": [{"a": 1, "b": 1, "k": 1, "L0": [1.05, 0.95]}, ...]}`` (``k``, ``L0`` a number
or the two springs' pair); its points then vary only ``dx``, ``dy``, ``load``.
``"atlas"`` (over a grid in ``dx`` and ``dy``) computes every equilibrium of each target;
:func:`atlas_from_rows` then makes the :class:`~tensegrity_opt.StabilityAtlas` (its edges analysed);
its option ``method`` is ``"search"`` (default) or ``"homotopy"`` (certified counts).
``options``: ``boundary`` (``"guided"`` | ``"free"``; buckling and design),
and for ``design`` the arguments of :func:`tensegrity_opt.maximize_critical_force`:
``vary`` (default ``["k"]``), ``bounds`` (``{name: [lo, hi]}``), ``budget``
(``{name: total}``), ``total_length``, ``tension`` (``[T_min, T_max]``), ``K_min``.

Every row: ``index`` (position in :func:`expand`), the swept parameters (effective value:
a parameter a point leaves out takes the base chain's value, ``dx``/``dy`` 0 or ``None``
under a tip force), the analysis's result columns (:data:`RESULT_COLUMNS`; ``None`` where
the point failed or a value does not exist) and ``error`` (``None`` or ``"code: message"``).
A failing point never stops the sweep.

Execution: ``scheduler=None``/``"serial"`` solves in the calling thread (the library caches
its CasADi solvers per thread); ``"threads"`` in a pool of threads of this process; ``"auto"`` (the
command line's default) serially, unless a timed probe of the first points says the rest would take
more than a minute, then on a local cluster (:func:`~.scheduler.auto_scheduler`); ``"local"`` starts a
``dask.distributed.LocalCluster`` (one single-threaded worker process per core), ``"tcp://host:port"`` uses a
running Dask scheduler (a :class:`distributed.Client` is accepted too). Each Dask task solves a chunk
of points with :func:`solve_chunk` (module level, so it pickles); a worker thread builds
its solvers once and reuses them for every later chunk. Chunks stream back with
``as_completed``; ``on_result(index, row)`` runs in the calling process as each point
(Dask: each chunk) arrives.

A :class:`SweepResult` follows the result contract: ``status`` ``"complete"`` (every point solved),
``"point_errors"`` (every point has its row, some carry an error; a success too) or ``"cancelled"`` (stopped
early: not a success), ``success`` and ``message``; it is immutable (its ``rows`` and ``columns`` tuples). The rows
themselves are table lines (the point's parameters, the analysis's numbers, ``error``) and keep their columns.

:func:`critical_load_map` is the buckling analysis over a grid of two design parameters of any chain (a
heterogeneous one included), answered as a typed grid, :class:`CriticalLoadMap` (what the critical-load figure
draws).

The package, by what its modules do: :mod:`.spec` (what a spec may say, its validation),
:mod:`.plan` (the points and columns of a spec), :mod:`.evaluate` (one point: the analysis and its
row), :mod:`.results` (:class:`SweepResult`, CSV / JSON / Parquet), :mod:`.scheduler`
(:func:`sweep`: serial or Dask), :mod:`.atlas` (an atlas sweep's rows as a stability atlas) and
:mod:`.critical_map` (the critical-load map). The names below are the public interface.
"""

from __future__ import annotations

from .atlas import atlas_from_rows
from .critical_map import CriticalLoadMap, critical_load_map
from .evaluate import error_row, evaluate_point, format_error, solve_chunk
from .plan import column_types, columns, expand, plan
from .results import SweepResult, read_results, write_csv
from .scheduler import sweep
from .spec import (
           ANALYSES,
           MAX_POINTS,
           PARAMETERS,
           RESULT_COLUMNS,
           count_points,
           validate_spec,
)

__all__ = ["ANALYSES", "PARAMETERS", "RESULT_COLUMNS", "MAX_POINTS", "SweepResult", "validate_spec", "expand",
           "count_points", "columns", "column_types", "evaluate_point", "solve_chunk", "sweep", "format_error",
           "read_results", "write_csv", "plan", "error_row", "atlas_from_rows", "CriticalLoadMap",
           "critical_load_map"]
