"""HTTP service over :mod:`tensegrity_opt` (FastAPI).

Start it with ``tensegrity-opt serve`` (:mod:`service.cli`; ``python -m service serve``) or build
the app with :func:`service.main.create_app`. The layout follows the usual FastAPI project
template: ``main`` (the app: wiring, lifespan; nothing else imports it), ``config`` (settings),
``schemas`` (request/response models), ``routes/`` (one router per area), ``deps`` (the checks
and the one dispatcher of a solve), ``errors`` (the one place where library exceptions become
HTTP answers), ``pool`` (the bounded solver thread pool), ``lane`` (the solver process of the
short requests), ``heavy`` (killable processes for the design requests), ``compute`` (the tasks:
library calls and their conversion to JSON-ready dicts), ``responses`` (the renderer), ``jobs``
(persistent sweeps). This package's ``__init__`` imports nothing, so ``service.cli`` runs the
library's commands without the service's packages.
"""
