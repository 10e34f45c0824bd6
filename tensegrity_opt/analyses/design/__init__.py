"""Design and control: the strongest chain, preloads (for a pose, a critical load, a stiffness, a trajectory),
sensitivities, load capacity, the preload follower and the arm as a force sensor.

One module per concept:

* :mod:`.strongest` - :func:`maximize_critical_force`, :class:`Design`;
* :mod:`.preloads` - :func:`preloads_for_pose` (:class:`PreloadDesign`), :func:`preloads_for_critical_force`,
  :func:`rest_length_bounds` and the keywords every preload problem shares;
* :mod:`.sensitivity` - :func:`critical_load_sensitivity`, :func:`equilibrium_sensitivity`;
* :mod:`.stiffness_shaping` - :func:`preloads_for_stiffness`, :class:`StiffnessDesign`;
* :mod:`.load_capacity` - :func:`load_capacity`, :class:`LoadCapacity`;
* :mod:`.preload_control` - :class:`PreloadController` (:class:`PreloadStep`) and :func:`preloads_for_trajectory`
  (:class:`PreloadPlan`);
* :mod:`.follower` - :class:`PreloadFollower` (:class:`FollowerStep`, :class:`Snap`);
* :mod:`.force_sensor` - :func:`estimate_tip_force`, :class:`ForceEstimate`.
"""

from .follower import FollowerStep, PreloadFollower, Snap
from .force_sensor import ForceEstimate, estimate_tip_force
from .load_capacity import LoadCapacity, load_capacity
from .preload_control import PreloadController, PreloadPlan, PreloadStep, preloads_for_trajectory
from .preloads import OBJECTIVES, PreloadDesign, preloads_for_critical_force, preloads_for_pose, rest_length_bounds
from .sensitivity import critical_load_sensitivity, equilibrium_sensitivity
from .stiffness_shaping import StiffnessDesign, preloads_for_stiffness
from .strongest import Design, maximize_critical_force

__all__ = ["Design", "maximize_critical_force", "PreloadDesign", "preloads_for_pose", "preloads_for_critical_force",
           "rest_length_bounds", "OBJECTIVES", "critical_load_sensitivity", "equilibrium_sensitivity",
           "StiffnessDesign", "preloads_for_stiffness", "LoadCapacity", "load_capacity", "PreloadController",
           "PreloadStep", "PreloadPlan", "preloads_for_trajectory", "PreloadFollower", "FollowerStep", "Snap",
           "ForceEstimate", "estimate_tip_force"]
