"""The applications: what users run on top of the analyses - figures (:mod:`.plots`), parameter
sweeps (:mod:`.sweeps`, optionally on Dask) and the command line (:mod:`.cli`). Nothing in the
analyses imports this layer; the HTTP service (the ``service`` package) sits beside it and is never
imported by the library.
"""
