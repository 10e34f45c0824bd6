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

from . import results
from .analyses.design.follower import PreloadFollower
from .analyses.design.force_sensor import ForceEstimate, estimate_tip_force
from .analyses.design.holding import HoldingDesign, HoldingMap, holding_map, preloads_for_holding
from .analyses.design.load_capacity import LoadCapacity, WeightCapacity, load_capacity, weight_capacity
from .analyses.design.preload_control import PreloadController, PreloadPlan, plan_preloads
from .analyses.design.preloads import PreloadDesign, preloads_for_critical_force, preloads_for_pose
from .analyses.design.sensitivity import critical_load_sensitivity, equilibrium_sensitivity
from .analyses.design.stiffness_shaping import StiffnessDesign, preloads_for_stiffness
from .analyses.design.strongest import Design, maximize_critical_force
from .analyses.equilibria.all_equilibria import EquilibriumSet, find_equilibria
from .analyses.equilibria.buckling import Buckling, critical_force
from .analyses.equilibria.equilibrium import Equilibrium, solve_equilibrium_under_force
from .analyses.equilibria.landscape import Landscape, energy_landscape
from .analyses.equilibria.least_energy import solve_equilibrium
from .analyses.equilibria.lower_bound import EnergyBound, energy_lower_bound
from .analyses.equilibria.modes import Modes, modes
from .analyses.equilibria.rest import find_equilibria_under_force, rest_configuration
from .analyses.equilibria.stiffness import cartesian_stiffness
from .analyses.paths.atlas import StabilityAtlas, stability_atlas
from .analyses.paths.boundaries import StabilityBoundary, stability_boundary
from .analyses.paths.branches import Branch, trace_branch
from .analyses.paths.continuation import Tracker, solve_equilibria_batch
from .analyses.paths.control import Control
from .analyses.paths.curves import Curve, force_deflection
from .analyses.paths.diagram import bifurcation_diagram, switch_branch
from .analyses.paths.imperfection import ImperfectionSensitivity, imperfection_sensitivity
from .analyses.paths.limit_load import LimitLoad, limit_arms, limit_load
from .analyses.paths.simulation import Simulation, simulate
from .applications.sweeps import CriticalLoadMap, SweepResult, critical_load_map, sweep
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

#: The model, the main verbs by concept with the results they return, the errors. The records inside the
#: results (Mode, Jump, CurveEnd, BranchEvent, PreloadStep ...) are in :mod:`tensegrity_opt.results`.
__all__ = [
    # the model
    "Segment", "Manipulator", "shape_label", "sign_string",
    # equilibria
    "solve_equilibrium", "solve_equilibrium_under_force", "find_equilibria", "find_equilibria_under_force",
    "rest_configuration", "critical_force", "cartesian_stiffness", "energy_landscape", "energy_lower_bound", "modes",
    "Equilibrium", "EquilibriumSet", "Buckling", "Landscape", "EnergyBound", "Modes",
    # loading paths
    "solve_equilibria_batch", "Tracker", "force_deflection", "Control", "trace_branch", "switch_branch",
    "bifurcation_diagram", "limit_load", "limit_arms", "imperfection_sensitivity", "stability_boundary",
    "stability_atlas", "simulate",
    "Curve", "Branch", "LimitLoad", "ImperfectionSensitivity", "StabilityBoundary", "StabilityAtlas", "Simulation",
    # design and control
    "maximize_critical_force", "preloads_for_pose", "preloads_for_critical_force", "preloads_for_stiffness",
    "preloads_for_holding", "holding_map", "plan_preloads", "PreloadController", "PreloadFollower", "load_capacity",
    "weight_capacity",
    "estimate_tip_force",
    "critical_load_sensitivity", "equilibrium_sensitivity",
    "Design", "PreloadDesign", "StiffnessDesign", "HoldingDesign", "HoldingMap", "PreloadPlan", "LoadCapacity",
    "WeightCapacity",
    "ForceEstimate",
    # applications
    "sweep", "critical_load_map", "SweepResult", "CriticalLoadMap",
    # all result types and their records
    "results",
    # errors and the time limit
    "TensegrityError", "InvalidParameterError", "UnreachableTargetError", "StraightNotEquilibriumError",
    "UnstableStraightError", "UnsupportedError", "SolverError", "NoEquilibriumError",
    "InfeasibleDesignError", "HomotopyUnavailableError", "TimeLimitError", "NonFiniteResult", "time_limit",
    "__version__",
]
