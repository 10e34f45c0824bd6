"""The work of the requests: each task takes a request (or its plain parts), calls the library and returns its
result; it runs on an executor (:mod:`service.execution`), never on the event loop.

* :mod:`.equilibria` - single solves, every equilibrium, buckling, curves, stiffness, torque, landscape, batches;
* :mod:`.paths` - rest configurations, branches, limit loads, stability boundaries, the stability atlas;
* :mod:`.control` - design, rest-length plans, simulation, force estimates, stiffness shaping, load capacity;
* :mod:`.plots` - the figures of those results, rendered as PNG or SVG.

A result is rendered where the task ran (:func:`service.responses.render_task`: its ``to_dict()``, the one
serialiser per result type). Request names become library arguments through :mod:`service.adapters` only.
"""

from . import control, equilibria, paths, plots

__all__ = ["control", "equilibria", "paths", "plots", "loaded"]


def loaded() -> None:
    """The warm-up of a killable solver process: nothing to run; unpickling this function imported the library
    and every task (a call is sent only to a child that has them, ~1-3 s after its start)."""
