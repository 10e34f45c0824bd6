"""HTTP service over :mod:`tensegrity_opt` (FastAPI).

Start it with ``tensegrity-opt serve`` or build the app with
:func:`service.main.create_app`. The layout follows the usual FastAPI project
template: ``config`` (settings), ``schemas`` (request/response models),
``routes/`` (one router per area), ``errors`` (the one place where library
exceptions become HTTP answers), ``pool`` (the bounded solver thread pool),
``compute`` (library calls and conversions, run inside the pool).
"""

__all__ = ["create_app"]


def create_app(settings=None):  # pragma: no cover - thin lazy wrapper
    from .main import create_app as _create_app

    return _create_app(settings)
