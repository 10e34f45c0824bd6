"""The numerics: the only package that imports CasADi (the fence is checked by import-linter,
``pyproject.toml`` ``[tool.importlinter]``).

* :mod:`.expressions` - the one symbolic model (energy, tip, KKT system) as CasADi graphs;
* :mod:`.chain_solver` - the per-chain solver: Newton on the KKT system (dense, banded, compiled
  kernels), IPOPT, the compiled continuation, derivatives; cached per thread;
* :mod:`.kernels` - the C Newton kernels generated from the symbolic model and compiled at run time;
* :mod:`.design_nlp` - the design NLPs (critical-load maximisation, preload choice);
* :mod:`.homotopy` - the polynomial homotopy engine adapter (PHCpack's ``phc``).

The analyses (:mod:`tensegrity_opt.analyses`) talk to this layer only through these modules'
public functions; they never build CasADi objects themselves.
"""
