"""The analyses: what a chain does, built on :mod:`tensegrity_opt.model` and :mod:`tensegrity_opt.numerics`.

Three concepts, one package each (each may import the ones before it, never one after):

* :mod:`.equilibria` - single equilibria and sets of them: the local solve and the :class:`Equilibrium`
  result, the least-energy search, every equilibrium, rest configurations, stability (Morse index),
  buckling, the Cartesian stiffness, the energy landscape;
* :mod:`.paths` - loading paths: natural-parameter continuation (batches, the Tracker), arclength branches
  with their events and bifurcation diagrams, force-deflection curves, limit loads, stability boundaries,
  the stability atlas, quasi-static simulation;
* :mod:`.design` - design and control: the strongest chain, every preload problem, stiffness shaping,
  load capacity, the arm as a force sensor.
"""
