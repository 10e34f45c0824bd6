"""HTTP service over :mod:`tensegrity_opt` (FastAPI).

Start it with ``tensegrity-opt serve`` (:mod:`service.cli`; ``python -m service serve``) or build the app with
:func:`service.main.create_app`. The layout follows the FastAPI project template, its layers importing
downwards only (``docs/architecture.md``): ``main`` (the app: wiring, lifespan; nothing else imports it),
``config`` (one ``BaseSettings``), ``api/`` (one router per resource in ``api/routes``, ``deps`` the checks,
``dispatch`` the one place deciding where a task runs, ``errors`` the one place failures become HTTP answers),
``sessions`` (the control stream's state), ``jobs/`` (persistent sweeps: the SQLite store and the runner),
``tasks/`` (the library calls), ``adapters/`` (request names <-> library names), ``execution/`` (the executors:
solver threads and killable solver processes behind one interface), ``responses`` (the JSON renderer),
``schemas/`` (request and response models). This package's ``__init__`` imports nothing, so ``service.cli``
runs the library's commands without the service's packages.
"""
