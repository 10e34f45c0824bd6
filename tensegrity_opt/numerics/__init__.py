"""The numerics: the only package importing CasADi (the fence is checked by import-linter,
``pyproject.toml`` ``[tool.importlinter]``).

The analyses (:mod:`tensegrity_opt.analyses`) talk to it through these doors, never to CasADi itself:

* :func:`chain_solver` ``(m)`` -> this thread's :class:`ChainSolver` for the manipulator — local Newton
  solves (:meth:`~ChainSolver.newton_kkt`, :meth:`~ChainSolver.newton_kkt_seeds`,
  :meth:`~ChainSolver.newton_force`), IPOPT (:meth:`~ChainSolver.minimize_displacement`,
  :meth:`~ChainSolver.minimize_force`), compiled continuation (:meth:`~ChainSolver.batch_continue`,
  :meth:`~ChainSolver.batch_derivs`) and derivatives (:meth:`~ChainSolver.evaluate`,
  :meth:`~ChainSolver.tangent_stiffness`, :meth:`~ChainSolver.kkt_parameter_jacobian`); results are numpy
  only (:class:`LocalResult`, :class:`SeedResults`, :class:`Continuation`);
* the design NLP builders :func:`buckling_design_nlp`, :func:`preload_nlp` and :func:`stiffness_nlp`
  (:mod:`.design_nlp`) and the horizon problem (:mod:`.horizon_nlp`: N control steps as one NLP,
  :func:`.horizon_nlp.horizon_nlp`), each NLP with named layouts of its variables, rows and parameters
  (:class:`Layout`);
* the compiled systems of the loading paths (:func:`.path_system.path_system`) and of the control step
  (:func:`.inverse_statics.inverse_statics`), each with the named layouts of its vectors (:mod:`.layout`: the
  analyses pack and read every solver vector by name, never by offset);
* when two configurations are the same equilibrium (:mod:`.distinct`: :data:`SAME_Q`, :func:`same`,
  :func:`distinct`, :func:`distinct_rows`);
* the polynomial homotopy (:mod:`.homotopy`, PHCpack; no CasADi), with the polish of its roots
  (:func:`.homotopy.polish_roots`).

Inside: :mod:`.expressions` (the one symbolic model), :mod:`.chain_solver` (the solver per chain length),
:mod:`.newton` (the damped Newton loop and BLAS control), :mod:`.ipopt` (the equilibrium NLPs),
:mod:`.units` (rescaled units), :mod:`.results` (result types), :mod:`.kernels` (compiled C Newton
kernels), :mod:`.build` (generated C: compiled once, the virtual machine otherwise), :mod:`.per_thread`
(the per-thread cache of built CasADi objects), :mod:`.layout` (named blocks of flat vectors),
:mod:`._fast` (buffered CasADi calls).
"""

from .chain_solver import DENSE_MAX, ChainFunctions, ChainSolver, chain_functions, chain_solver
from .distinct import SAME_Q, distinct, distinct_indices, distinct_rows, same
from .ipopt import RANGE_SHRINK
from .kernels import KERNEL_MAX
from .layout import Layout
from .results import Continuation, LocalResult, SeedResults

__all__ = ["ChainSolver", "ChainFunctions", "chain_solver", "chain_functions", "LocalResult", "SeedResults",
           "Continuation", "DENSE_MAX", "KERNEL_MAX", "RANGE_SHRINK", "SAME_Q", "same", "distinct", "distinct_rows",
           "distinct_indices",
           "Layout", "NLPResult", "buckling_design_nlp", "preload_nlp", "stiffness_nlp"]


def __getattr__(name: str):
    # the design problems are built by few calls: their module is imported on first use
    if name in ("NLPResult", "buckling_design_nlp", "preload_nlp", "stiffness_nlp"):
        from . import design_nlp

        return getattr(design_nlp, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
