"""Equilibria: one equilibrium, the least-energy one, every one, rest shapes, stability, buckling, stiffness,
the energy landscape. One module per concept:

* :mod:`.equilibrium` - the :class:`~.equilibrium.Equilibrium` result, local solves, the exact special cases,
  :func:`~.equilibrium.solve_equilibrium_under_force` (a local minimiser under a dead tip load);
* :mod:`.least_energy` - :func:`~.least_energy.solve_equilibrium`, the least-energy stable equilibrium for a
  tip displacement (the global search);
* :mod:`.all_equilibria` - :func:`~.all_equilibria.find_equilibria`, every equilibrium for a tip displacement
  (search or certified homotopy), and its result :class:`~.all_equilibria.EquilibriumSet`;
* :mod:`.rest` - :func:`~.rest.rest_configuration` and :func:`~.rest.find_equilibria_under_force`, every
  equilibrium under a dead tip load (exact at ``F = 0``);
* :mod:`.stability` - the Morse index (inertia of the reduced Hessian);
* :mod:`.buckling` - :func:`~.buckling.critical_force`, the critical loads and modes of the straight chain
  (:class:`~.buckling.Buckling`, :class:`~.buckling.Mode`);
* :mod:`.stiffness` - :func:`~.stiffness.cartesian_stiffness`, the tangent stiffness at an equilibrium;
* :mod:`.landscape` - :func:`~.landscape.energy_landscape`, the energy over two joint angles (n = 4;
  :class:`~.landscape.Landscape`);
* :mod:`.seeds` - the starting points of the global searches.

Every result follows the result contract (:mod:`tensegrity_opt.outcome`).
"""
