"""Loading paths: continuation (natural and arclength), events, bifurcation diagrams, force-deflection curves,
limit loads, imperfection sensitivity, stability boundaries, the stability atlas, quasi-static simulation.

One module per concept, around one path system (:mod:`tensegrity_opt.numerics.path_system`) and one arclength
engine (:mod:`.branches`):

* :mod:`.control` - :class:`~.control.Control`, what the continuation parameter ``t`` moves;
* :mod:`.problem` - :class:`~.problem.PathProblem`, the path system of one chain under one control: corrector,
  tangent, the stability of a point;
* :mod:`.continuation` - natural-parameter continuation: :func:`~.continuation.solve_equilibria_batch` and the
  :class:`~.continuation.Tracker` (control loops);
* :mod:`.branches` - :func:`~.branches.trace_branch`, pseudo-arclength continuation, and its result
  :class:`~.branches.Branch`;
* :mod:`.events` - folds, branch points and joint limits between two points of a branch
  (:class:`~.events.BranchEvent`);
* :mod:`.diagram` - :func:`~.diagram.switch_branch` and :func:`~.diagram.bifurcation_diagram`;
* :mod:`.curves` - :func:`~.curves.force_deflection`, the force-deflection curve with its jumps
  (:class:`~.curves.Curve`);
* :mod:`.limit_load` - :func:`~.limit_load.limit_load` (:class:`~.limit_load.LimitLoad`) and
  :func:`~.limit_load.limit_arms`, the buckled arms leaving a bifurcation;
* :mod:`.imperfection` - :func:`~.imperfection.imperfection_sensitivity`
  (:class:`~.imperfection.ImperfectionSensitivity`), the limit load of the imperfect chain against the imperfection;
* :mod:`.boundaries` - :func:`~.boundaries.stability_boundary` (:class:`~.boundaries.StabilityBoundary`);
* :mod:`.atlas` - :func:`~.atlas.stability_atlas` (:class:`~.atlas.StabilityAtlas`);
* :mod:`.simulation` and :mod:`.descent` - :func:`~.simulation.simulate`, the quasi-static simulation with its
  snaps (:class:`~.simulation.Simulation`).

Every result follows the result contract (:mod:`tensegrity_opt.outcome`).
"""
