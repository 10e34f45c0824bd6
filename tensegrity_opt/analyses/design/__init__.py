"""Design and control: the strongest chain, preloads (for a pose, a critical load, a stiffness, a trajectory),
sensitivities, load capacity, the preload follower and the arm as a force sensor.

One module per concept:

* :mod:`.strongest` - :func:`maximize_critical_force`, :class:`Design`;
* :mod:`.preloads` - :func:`preloads_for_pose` (:class:`PreloadDesign`), :func:`preloads_for_critical_force`,
  :func:`rest_length_bounds` and the keywords every preload problem shares;
* :mod:`.sensitivity` - :func:`critical_load_sensitivity`, :func:`equilibrium_sensitivity`;
* :mod:`.stiffness_shaping` - :func:`preloads_for_stiffness`, :class:`StiffnessDesign`;
* :mod:`.holding` - :func:`preloads_for_holding`, :class:`HoldingDesign` (the least preload or stiffness holding a
  chain up under its own weight);
* :mod:`.load_capacity` - :func:`load_capacity`, :class:`LoadCapacity`;
* :mod:`.preload_control` - :class:`PreloadController` (:class:`PreloadStep`) and :func:`plan_preloads`
  (:class:`PreloadPlan`);
* :mod:`.follower` - :class:`PreloadFollower` (:class:`FollowerStep`);
* :mod:`.force_sensor` - :func:`estimate_tip_force`, :class:`ForceEstimate`.
"""
