"""Benchmark suite of tensegrity_opt and its HTTP service: ``python -m benchmarks [--quick]``.

``baselines`` holds the plain numpy/scipy baselines, ``suite`` the cases and the report,
``http_load`` the loopback load generator. ``load_check.py`` is a separate script (service load check).
"""
