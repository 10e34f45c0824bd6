"""The analyses: what a chain does, built on :mod:`tensegrity_opt.model` and
:mod:`tensegrity_opt.numerics`.

* :mod:`.equilibrium` - one equilibrium: the result type, local solves, the equilibrium under a tip force;
* :mod:`.least_energy` - the least-energy stable equilibrium for a tip target (the global search);
* :mod:`.all_equilibria` - every equilibrium for a tip target (search, or the certified homotopy);
* :mod:`.rest` - rest configurations (the exact unloaded equilibria, the least-energy well) and every
  equilibrium under a dead tip load (search, or the certified homotopy);
* :mod:`.stability` - classification by the reduced Hessian's inertia (Morse index);
* :mod:`.buckling` - the straight chain's critical loads and modes (the paper's eigenproblem);
* :mod:`.seeds` - starting points for the global search (modes, mirrors, wells, random projections);
* :mod:`.continuation` - equilibria followed along a sequence of targets (batches, the Tracker, curve branches);
* :mod:`.curves` - force-deflection curves, jumps, branches;
* :mod:`.branches` - equilibrium branches by pseudo-arclength continuation under a control (a tip
  displacement, a dead or guided load, a wall, preloads): events (folds, branch points, joint limits),
  branch switching, bifurcation diagrams;
* :mod:`.limit_load` - the load at which the dead-load path from a rest configuration loses stability
  (fold or bifurcation), the quasi-buckling load of a smooth path;
* :mod:`.boundaries` - two-parameter continuation of folds and branch points (limit loads against a
  design or control parameter, cusps);
* :mod:`.atlas` - the workspace stability atlas of the held tip: stable equilibria per target, where the
  least-energy branch switches and where stable branches end;
* :mod:`.simulation` - forward quasi-static simulation under sampled preloads and loads (or tip targets):
  the branch followed, snaps at its folds by descent, hysteresis;
* :mod:`.preload_control` - control in actuation space: rest lengths for tip poses step by step (the
  compiled least-change Newton step, IPOPT where a bound is active) and over trajectories;
* :mod:`.stiffness` - the Cartesian tangent stiffness;
* :mod:`.stiffness_design` - stiffness shaping (rest lengths for a tip pose with a desired or bounded
  Cartesian stiffness, an IPOPT NLP verified forward) and the load capacity of a pose (the limit load of the
  dead-load path from it in each direction: a polar curve);
* :mod:`.force_sensor` - the arm as a force sensor: the tip force from measured joint angles, its
  covariance and a chi-square test for loads elsewhere;
* :mod:`.landscape` - the energy over two joint angles;
* :mod:`.design` - optimal designs and preloads (maximise the critical load, choose preloads).
"""
