"""tensegrity_opt: equilibria, stability, buckling and stiffness of compliant serial
manipulators built from dual-triangle tensegrity segments (Zhao, Pashkevich, Chablat).

Quick start::

    >>> import tensegrity_opt as to
    >>> m = to.Manipulator.uniform(4, a=1, b=1, k=1, L0=1)
    >>> round(to.critical_force(m).force, 6)
    -0.572793
    >>> eq = to.solve_equilibrium(m, dx=0.1)
    >>> eq.shape, eq.stable
    ('U', True)
"""

from .analyses.equilibria.all_equilibria import EquilibriumSet, find_equilibria
from .analyses.paths.atlas import StabilityAtlas, stability_atlas
from .analyses.paths.branches import Branch, trace_branch
from .analyses.paths.control import Control
from .analyses.paths.diagram import bifurcation_diagram, switch_branch
from .analyses.paths.events import BranchEvent
from .analyses.paths.boundaries import StabilityBoundary, stability_boundary
from .analyses.equilibria.buckling import Buckling, Mode, critical_force
from .analyses.paths.continuation import Tracker, solve_equilibria_batch
from .analyses.paths.curves import Curve, CurveEnd, Jump, force_deflection
from .analyses.design.follower import FollowerStep, PreloadFollower, Snap
from .analyses.design.force_sensor import ForceEstimate, estimate_tip_force
from .analyses.design.load_capacity import LoadCapacity, load_capacity
from .analyses.design.preload_control import PreloadController, PreloadPlan, PreloadStep, preloads_for_trajectory
from .analyses.design.preloads import PreloadDesign, preloads_for_critical_force, preloads_for_pose
from .analyses.design.sensitivity import critical_load_sensitivity, equilibrium_sensitivity
from .analyses.design.stiffness_shaping import StiffnessDesign, preloads_for_stiffness
from .analyses.design.strongest import Design, maximize_critical_force
from .analyses.equilibria.equilibrium import Equilibrium, solve_equilibrium_under_force
from .analyses.equilibria.landscape import Landscape, energy_landscape
from .analyses.equilibria.least_energy import solve_equilibrium
from .analyses.paths.limit_load import LimitLoad, limit_load
from .analyses.equilibria.rest import find_equilibria_under_force, rest_configuration
from .analyses.paths.simulation import Simulation, SimulationEvent, simulate
from .analyses.equilibria.stiffness import cartesian_stiffness
from .applications.sweeps import SweepResult, sweep
from .errors import (
                     HomotopyUnavailableError,
                     InfeasibleDesignError,
                     InvalidParameterError,
                     NoEquilibriumError,
                     NonFiniteResult,
                     SolverError,
                     StraightNotEquilibriumError,
                     TensegrityError,
                     TimeLimitError,
                     UnreachableTargetError,
                     UnstableStraightError,
                     UnsupportedError,
)
from .model.manipulator import Manipulator
from .model.segment import Segment
from .model.shapes import shape_label, sign_string
from .timelimit import time_limit

__version__ = "0.1.0"

__all__ = [
    "Segment", "Manipulator",
    "Equilibrium", "solve_equilibrium", "solve_equilibrium_under_force", "find_equilibria", "EquilibriumSet",
    "find_equilibria_under_force", "rest_configuration",
    "solve_equilibria_batch", "Tracker",
    "Buckling", "Mode", "critical_force",
    "Curve", "CurveEnd", "Jump", "force_deflection",
    "Control", "Branch", "BranchEvent", "trace_branch", "switch_branch", "bifurcation_diagram",
    "LimitLoad", "limit_load", "StabilityBoundary", "stability_boundary", "StabilityAtlas", "stability_atlas",
    "Simulation", "SimulationEvent", "simulate",
    "PreloadController", "PreloadStep", "PreloadPlan", "preloads_for_trajectory",
    "PreloadFollower", "FollowerStep", "Snap",
    "Design", "PreloadDesign", "maximize_critical_force", "preloads_for_critical_force", "preloads_for_pose",
    "critical_load_sensitivity", "equilibrium_sensitivity",
    "sweep", "SweepResult",
    "cartesian_stiffness", "StiffnessDesign", "preloads_for_stiffness", "LoadCapacity", "load_capacity",
    "ForceEstimate", "estimate_tip_force",
    "Landscape", "energy_landscape", "shape_label", "sign_string",
    "TensegrityError", "InvalidParameterError", "UnreachableTargetError", "StraightNotEquilibriumError",
    "UnstableStraightError", "UnsupportedError", "SolverError", "NoEquilibriumError",
    "InfeasibleDesignError", "HomotopyUnavailableError", "TimeLimitError", "NonFiniteResult", "time_limit",
    "__version__",
]
