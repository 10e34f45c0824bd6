"""The numerics: the only package importing CasADi (the fence is checked by import-linter,
``pyproject.toml`` ``[tool.importlinter]``).

The analyses (:mod:`tensegrity_opt.analyses`) talk to it through three doors, never to CasADi itself:

* :func:`chain_solver` ``(m)`` -> :class:`BoundSolver`: this thread's :class:`ChainSolver` for ``m.n``
  segments bound to the manipulator — local Newton solves (:meth:`~BoundSolver.newton_kkt`,
  :meth:`~BoundSolver.newton_kkt_seeds`, :meth:`~BoundSolver.newton_force`), IPOPT
  (:meth:`~BoundSolver.minimize_displacement`, :meth:`~BoundSolver.minimize_force`), compiled
  continuation (:meth:`~BoundSolver.batch_continue`, :meth:`~BoundSolver.batch_derivs`) and derivatives
  (:meth:`~BoundSolver.evaluate`, :meth:`~BoundSolver.tangent_stiffness`,
  :meth:`~BoundSolver.kkt_parameter_jacobian`); results are numpy only (:class:`LocalResult`,
  :class:`SeedResults`, :class:`Continuation`);
* the design NLP builders :func:`buckling_design_nlp`, :func:`preload_nlp` and :func:`stiffness_nlp`
  (:mod:`.design_nlp`);
* the polynomial homotopy (:mod:`.homotopy`, PHCpack; no CasADi).

Inside: :mod:`.expressions` (the one symbolic model), :mod:`.chain_solver` (the solver per chain length),
:mod:`.newton` (the damped Newton loop and BLAS control), :mod:`.ipopt` (the equilibrium NLPs),
:mod:`.units` (rescaled units), :mod:`.results` (result types), :mod:`.kernels` (compiled C Newton
kernels), :mod:`._fast` (buffered CasADi calls).
"""

from .chain_solver import DENSE_MAX, BoundSolver, ChainSolver, chain_solver
from .ipopt import RANGE_SHRINK
from .kernels import KERNEL_MAX
from .results import Continuation, LocalResult, SeedResults

__all__ = ["ChainSolver", "BoundSolver", "chain_solver", "LocalResult", "SeedResults", "Continuation",
           "DENSE_MAX", "KERNEL_MAX", "RANGE_SHRINK", "NLPResult", "buckling_design_nlp", "preload_nlp",
           "stiffness_nlp"]


def __getattr__(name: str):
    # the design problems are built by few calls: their module is imported on first use
    if name in ("NLPResult", "buckling_design_nlp", "preload_nlp", "stiffness_nlp"):
        from . import design_nlp

        return getattr(design_nlp, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
