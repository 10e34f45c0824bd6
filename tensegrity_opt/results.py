"""Every result type of the library in one place: the results the public functions return and the records
inside them.

The top-level namespace (``tensegrity_opt``) shows the main results next to the verbs that return them; the
records they hold (a buckling :class:`Mode`, a curve's :class:`Jump` and :class:`CurveEnd`, a branch's
:class:`BranchEvent`, a plan's :class:`PreloadStep` ...) live here. Every class that derives from
:class:`Outcome` follows the result contract (:mod:`tensegrity_opt.outcome`): ``success``, ``status`` from its
closed vocabulary ``STATUSES``, ``message``, and ``to_dict()`` carrying all three.

==========================  ===============================================  ======================================
result                      returned by                                      records inside
==========================  ===============================================  ======================================
:class:`Equilibrium`        ``solve_equilibrium``, ``..._under_force``,      :class:`SolverInfo`
                            ``rest_configuration``, ``Tracker.solve``
:class:`EquilibriumSet`     ``find_equilibria``, ``..._under_force``         :class:`Equilibrium`,
                                                                             :class:`IntervalCertificate`
(``IntervalCertificate``)   ``EquilibriumSet.certificate`` (homotopy)        :class:`RootBox`
:class:`EnergyBound`        ``energy_lower_bound``,
                            ``Equilibrium.certificate`` (``certify=True``)
:class:`Buckling`           ``critical_force``                               :class:`Mode`
:class:`Landscape`          ``energy_landscape``
:class:`Modes`              ``modes``                                        :class:`Equilibrium`
:class:`Curve`              ``force_deflection``                             :class:`Jump`, :class:`CurveEnd`
:class:`Branch`             ``trace_branch``, ``switch_branch``,             :class:`BranchEvent`
                            ``bifurcation_diagram`` (a list)
:class:`LimitLoad`          ``limit_load``                                   :class:`Branch`
|ImperfectionSens|          ``imperfection_sensitivity``                     :class:`LimitLoad`
:class:`StabilityBoundary`  ``stability_boundary``                           :class:`BoundaryPoint`
:class:`StabilityAtlas`     ``stability_atlas``                              :class:`AtlasTarget`,
                                                                             :class:`AtlasCrossing`
:class:`Simulation`         ``simulate``                                     :class:`SimulationEvent`
(``Transition``)            ``transition``                                   :class:`SimulationEvent`
:class:`Design`             ``maximize_critical_force``,                     :class:`SolverInfo`
                            ``preloads_for_critical_force``
:class:`PreloadDesign`      ``preloads_for_pose``                            :class:`SolverInfo`,
                                                                             :class:`ActiveBound`
:class:`StiffnessDesign`    ``preloads_for_stiffness``                       :class:`SolverInfo`,
                                                                             :class:`ActiveBound`
:class:`HoldingDesign`      ``preloads_for_holding``                         :class:`SolverInfo`
:class:`HoldingMap`         ``holding_map``
:class:`PreloadPlan`        ``plan_preloads``                      :class:`PreloadStep`
(``PreloadStep``)           ``PreloadController.step``
(``FollowerStep``)          ``PreloadFollower.step``                         :class:`SimulationEvent`
:class:`LoadCapacity`       ``load_capacity``                                :class:`LimitLoad`
:class:`WeightCapacity`     ``weight_capacity``                              :class:`Equilibrium`
:class:`ForceEstimate`      ``estimate_tip_force``
:class:`SweepResult`        ``sweep``
:class:`CriticalLoadMap`    ``critical_load_map``
==========================  ===============================================  ======================================

.. |ImperfectionSens| replace:: :class:`ImperfectionSensitivity`
"""

from .analyses.design.active_bounds import ActiveBound
from .analyses.design.follower import FollowerStep
from .analyses.design.force_sensor import ForceEstimate
from .analyses.design.holding import HoldingDesign, HoldingMap
from .analyses.design.load_capacity import LoadCapacity, WeightCapacity
from .analyses.design.preload_control import PreloadPlan, PreloadStep
from .analyses.design.preloads import PreloadDesign
from .analyses.design.stiffness_shaping import StiffnessDesign
from .analyses.design.strongest import Design
from .analyses.equilibria.all_equilibria import EquilibriumSet
from .analyses.equilibria.buckling import Buckling, Mode
from .analyses.equilibria.equilibrium import Equilibrium
from .analyses.equilibria.landscape import Landscape
from .analyses.equilibria.lower_bound import EnergyBound
from .analyses.equilibria.modes import Modes
from .analyses.paths.atlas import AtlasCrossing, AtlasTarget, StabilityAtlas
from .analyses.paths.boundaries import BoundaryPoint, StabilityBoundary
from .analyses.paths.branches import Branch
from .analyses.paths.curves import Curve, CurveEnd, Jump
from .analyses.paths.events import BranchEvent
from .analyses.paths.imperfection import ImperfectionSensitivity
from .analyses.paths.limit_load import LimitLoad
from .analyses.paths.simulation import Simulation, SimulationEvent
from .analyses.paths.transition import Transition
from .applications.sweeps.critical_map import CriticalLoadMap
from .applications.sweeps.results import SweepResult
from .numerics.krawczyk import IntervalCertificate, RootBox
from .outcome import Outcome, SolverInfo

__all__ = [
    "Outcome", "SolverInfo",
    "Equilibrium", "EquilibriumSet", "IntervalCertificate", "RootBox", "EnergyBound", "Buckling", "Mode", "Landscape",
    "Modes",
    "Curve", "CurveEnd", "Jump", "Branch", "BranchEvent", "LimitLoad", "ImperfectionSensitivity",
    "StabilityBoundary", "BoundaryPoint",
    "StabilityAtlas", "AtlasTarget", "AtlasCrossing", "Simulation", "SimulationEvent", "Transition",
    "Design", "PreloadDesign", "StiffnessDesign", "HoldingDesign", "HoldingMap", "ActiveBound", "PreloadPlan",
    "PreloadStep", "FollowerStep",
    "LoadCapacity", "WeightCapacity", "ForceEstimate", "SweepResult", "CriticalLoadMap",
]
