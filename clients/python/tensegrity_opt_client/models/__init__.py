"""Contains all the data models used in inputs/outputs"""

from .active_bound_out import ActiveBoundOut
from .active_bound_out_side import ActiveBoundOutSide
from .angle_range import AngleRange
from .atlas_crossing_out import AtlasCrossingOut
from .atlas_crossing_out_kind import AtlasCrossingOutKind
from .atlas_curves_out import AtlasCurvesOut
from .atlas_out import AtlasOut
from .atlas_out_status import AtlasOutStatus
from .atlas_range import AtlasRange
from .atlas_request import AtlasRequest
from .atlas_request_method import AtlasRequestMethod
from .atlas_target_out import AtlasTargetOut
from .atlas_target_out_status import AtlasTargetOutStatus
from .atlas_unresolved_out import AtlasUnresolvedOut
from .batch_equilibrium_request import BatchEquilibriumRequest
from .batch_item import BatchItem
from .batch_out import BatchOut
from .bifurcation_diagram_out import BifurcationDiagramOut
from .bifurcation_diagram_request import BifurcationDiagramRequest
from .bounds_in import BoundsIn
from .branch_event_out import BranchEventOut
from .branch_event_out_kind import BranchEventOutKind
from .branch_event_out_spring_states_type_0_item_item import BranchEventOutSpringStatesType0ItemItem
from .branch_event_out_stability import BranchEventOutStability
from .branch_out import BranchOut
from .branch_point import BranchPoint
from .branch_point_spring_states_type_0_item_item import BranchPointSpringStatesType0ItemItem
from .branch_request import BranchRequest
from .branch_request_orientation import BranchRequestOrientation
from .branch_request_stop_at_type_0 import BranchRequestStopAtType0
from .buckling_out import BucklingOut
from .buckling_out_boundary import BucklingOutBoundary
from .buckling_request import BucklingRequest
from .buckling_request_boundary import BucklingRequestBoundary
from .control_out import ControlOut
from .control_out_kind import ControlOutKind
from .control_out_tip_type_0 import ControlOutTipType0
from .curve_end_out import CurveEndOut
from .curve_point import CurvePoint
from .curve_point_spring_states_type_0_item_item import CurvePointSpringStatesType0ItemItem
from .curve_point_status import CurvePointStatus
from .cusp_out import CuspOut
from .deflection_range import DeflectionRange
from .design_critical_force_request import DesignCriticalForceRequest
from .design_critical_force_request_boundary import DesignCriticalForceRequestBoundary
from .design_critical_force_request_bounds import DesignCriticalForceRequestBounds
from .design_critical_force_request_budget import DesignCriticalForceRequestBudget
from .design_critical_force_request_vary_item import DesignCriticalForceRequestVaryItem
from .design_out import DesignOut
from .design_out_status import DesignOutStatus
from .design_segmented_manipulator_in import DesignSegmentedManipulatorIn
from .design_uniform_manipulator_in import DesignUniformManipulatorIn
from .design_uniform_manipulator_in_spring import DesignUniformManipulatorInSpring
from .displacement_control_in import DisplacementControlIn
from .energy_bound_out import EnergyBoundOut
from .energy_bound_out_status import EnergyBoundOutStatus
from .energy_landscape_out import EnergyLandscapeOut
from .energy_landscape_request import EnergyLandscapeRequest
from .equilibria_out import EquilibriaOut
from .equilibria_out_status import EquilibriaOutStatus
from .equilibria_request import EquilibriaRequest
from .equilibria_request_method import EquilibriaRequestMethod
from .equilibrium_out import EquilibriumOut
from .equilibrium_out_kind import EquilibriumOutKind
from .equilibrium_out_spring_states_type_0_item_item import EquilibriumOutSpringStatesType0ItemItem
from .equilibrium_out_status import EquilibriumOutStatus
from .equilibrium_request import EquilibriumRequest
from .error_out import ErrorOut
from .error_out_best_type_0 import ErrorOutBestType0
from .error_out_details_type_0 import ErrorOutDetailsType0
from .field_error import FieldError
from .force import Force
from .force_deflection_out import ForceDeflectionOut
from .force_deflection_out_reference import ForceDeflectionOutReference
from .force_deflection_out_status import ForceDeflectionOutStatus
from .force_deflection_request import ForceDeflectionRequest
from .force_deflection_request_branch import ForceDeflectionRequestBranch
from .force_deflection_request_reference import ForceDeflectionRequestReference
from .force_equilibrium_request import ForceEquilibriumRequest
from .force_estimate_out import ForceEstimateOut
from .force_estimate_out_spring_states_type_0_item_item import ForceEstimateOutSpringStatesType0ItemItem
from .force_estimate_out_status import ForceEstimateOutStatus
from .force_estimate_request import ForceEstimateRequest
from .get_job_results_format_type_0 import GetJobResultsFormatType0
from .guided_control_in import GuidedControlIn
from .health import Health
from .holding_out import HoldingOut
from .holding_out_manipulator import HoldingOutManipulator
from .holding_out_spring_states_type_0_item_item import HoldingOutSpringStatesType0ItemItem
from .holding_out_status import HoldingOutStatus
from .holding_out_vary_item import HoldingOutVaryItem
from .holding_request import HoldingRequest
from .holding_request_vary_item import HoldingRequestVaryItem
from .imperfection_law_out import ImperfectionLawOut
from .imperfection_sensitivity_out import ImperfectionSensitivityOut
from .imperfection_sensitivity_out_bifurcation_type_0 import ImperfectionSensitivityOutBifurcationType0
from .imperfection_sensitivity_out_boundary import ImperfectionSensitivityOutBoundary
from .imperfection_sensitivity_out_imperfection import ImperfectionSensitivityOutImperfection
from .imperfection_sensitivity_out_kinds_item import ImperfectionSensitivityOutKindsItem
from .imperfection_sensitivity_out_perfect_kind import ImperfectionSensitivityOutPerfectKind
from .imperfection_sensitivity_out_status import ImperfectionSensitivityOutStatus
from .imperfection_sensitivity_out_statuses_item import ImperfectionSensitivityOutStatusesItem
from .imperfection_sensitivity_request import ImperfectionSensitivityRequest
from .imperfection_sensitivity_request_boundary import ImperfectionSensitivityRequestBoundary
from .imperfection_sensitivity_request_imperfection import ImperfectionSensitivityRequestImperfection
from .interval_certificate_out import IntervalCertificateOut
from .interval_certificate_out_control import IntervalCertificateOutControl
from .interval_certificate_out_status import IntervalCertificateOutStatus
from .job_created import JobCreated
from .job_created_analysis import JobCreatedAnalysis
from .job_created_status import JobCreatedStatus
from .job_list import JobList
from .job_out import JobOut
from .job_out_analysis import JobOutAnalysis
from .job_out_results_item import JobOutResultsItem
from .job_out_spec import JobOutSpec
from .job_out_status import JobOutStatus
from .job_results import JobResults
from .job_results_rows_item import JobResultsRowsItem
from .job_results_status import JobResultsStatus
from .job_spec import JobSpec
from .job_spec_analysis import JobSpecAnalysis
from .job_summary import JobSummary
from .job_summary_analysis import JobSummaryAnalysis
from .job_summary_status import JobSummaryStatus
from .jobs_health import JobsHealth
from .jobs_health_status import JobsHealthStatus
from .joint_force_in import JointForceIn
from .jump_out import JumpOut
from .jump_out_kind import JumpOutKind
from .kernels_out import KernelsOut
from .limit_load_out import LimitLoadOut
from .limit_load_out_boundary import LimitLoadOutBoundary
from .limit_load_out_branch_status import LimitLoadOutBranchStatus
from .limit_load_out_kind import LimitLoadOutKind
from .limit_load_out_spring_states_type_0_item_item import LimitLoadOutSpringStatesType0ItemItem
from .limit_load_out_status import LimitLoadOutStatus
from .limit_load_request import LimitLoadRequest
from .limit_load_request_boundary import LimitLoadRequestBoundary
from .limits import Limits
from .list_jobs_status_type_0 import ListJobsStatusType0
from .load_capacity_out import LoadCapacityOut
from .load_capacity_out_manipulator import LoadCapacityOutManipulator
from .load_capacity_out_start import LoadCapacityOutStart
from .load_capacity_out_status import LoadCapacityOutStatus
from .load_capacity_out_weakest_type_0 import LoadCapacityOutWeakestType0
from .load_capacity_request import LoadCapacityRequest
from .load_capacity_request_boundary import LoadCapacityRequestBoundary
from .load_control_in import LoadControlIn
from .loads_out import LoadsOut
from .manipulator_out import ManipulatorOut
from .map_values_range import MapValuesRange
from .mode_out import ModeOut
from .modes_out import ModesOut
from .modes_out_status import ModesOutStatus
from .modes_out_tip import ModesOutTip
from .modes_request import ModesRequest
from .modes_request_tip_type_0 import ModesRequestTipType0
from .plan_out import PlanOut
from .plan_out_method_item import PlanOutMethodItem
from .plan_out_objective import PlanOutObjective
from .plan_out_on_infeasible import PlanOutOnInfeasible
from .plan_out_on_snap import PlanOutOnSnap
from .plan_out_spring_states_type_0_item_type_0_item_item import PlanOutSpringStatesType0ItemType0ItemItem
from .plan_out_status import PlanOutStatus
from .plan_request import PlanRequest
from .plan_request_objective import PlanRequestObjective
from .plan_request_on_infeasible import PlanRequestOnInfeasible
from .plan_request_on_snap import PlanRequestOnSnap
from .plan_step_out import PlanStepOut
from .plan_step_out_method import PlanStepOutMethod
from .plan_step_out_spring_states_type_0_item_item import PlanStepOutSpringStatesType0ItemItem
from .plan_step_out_status import PlanStepOutStatus
from .plot_angle_range import PlotAngleRange
from .plot_atlas_grid_request import PlotAtlasGridRequest
from .plot_atlas_grid_request_format_type_0 import PlotAtlasGridRequestFormatType0
from .plot_atlas_grid_request_method import PlotAtlasGridRequestMethod
from .plot_atlas_job_request import PlotAtlasJobRequest
from .plot_atlas_job_request_format_type_0 import PlotAtlasJobRequestFormatType0
from .plot_boundary_request import PlotBoundaryRequest
from .plot_boundary_request_format_type_0 import PlotBoundaryRequestFormatType0
from .plot_branch_request import PlotBranchRequest
from .plot_branch_request_format_type_0 import PlotBranchRequestFormatType0
from .plot_branch_request_orientation import PlotBranchRequestOrientation
from .plot_branch_request_stop_at_type_0 import PlotBranchRequestStopAtType0
from .plot_curve_request import PlotCurveRequest
from .plot_curve_request_branch import PlotCurveRequestBranch
from .plot_curve_request_format_type_0 import PlotCurveRequestFormatType0
from .plot_holding_request import PlotHoldingRequest
from .plot_holding_request_format_type_0 import PlotHoldingRequestFormatType0
from .plot_holding_request_vary_item import PlotHoldingRequestVaryItem
from .plot_imperfection_request import PlotImperfectionRequest
from .plot_imperfection_request_boundary import PlotImperfectionRequestBoundary
from .plot_imperfection_request_format_type_0 import PlotImperfectionRequestFormatType0
from .plot_imperfection_request_imperfection import PlotImperfectionRequestImperfection
from .plot_landscape_request import PlotLandscapeRequest
from .plot_landscape_request_format_type_0 import PlotLandscapeRequestFormatType0
from .plot_limit_load_request import PlotLimitLoadRequest
from .plot_limit_load_request_boundary import PlotLimitLoadRequestBoundary
from .plot_limit_load_request_format_type_0 import PlotLimitLoadRequestFormatType0
from .plot_map_request import PlotMapRequest
from .plot_map_request_boundary import PlotMapRequestBoundary
from .plot_map_request_format_type_0 import PlotMapRequestFormatType0
from .plot_map_request_param_x import PlotMapRequestParamX
from .plot_map_request_param_y import PlotMapRequestParamY
from .plot_modes_request import PlotModesRequest
from .plot_modes_request_format_type_0 import PlotModesRequestFormatType0
from .plot_modes_request_tip_type_0 import PlotModesRequestTipType0
from .plot_plan_request import PlotPlanRequest
from .plot_plan_request_format_type_0 import PlotPlanRequestFormatType0
from .plot_plan_request_objective import PlotPlanRequestObjective
from .plot_plan_request_on_infeasible import PlotPlanRequestOnInfeasible
from .plot_plan_request_on_snap import PlotPlanRequestOnSnap
from .plot_shapes_request import PlotShapesRequest
from .plot_shapes_request_format_type_0 import PlotShapesRequestFormatType0
from .plot_shapes_request_spring_colors import PlotShapesRequestSpringColors
from .plot_simulation_request import PlotSimulationRequest
from .plot_simulation_request_format_type_0 import PlotSimulationRequestFormatType0
from .plot_simulation_request_tip import PlotSimulationRequestTip
from .plot_torque_request import PlotTorqueRequest
from .plot_torque_request_format_type_0 import PlotTorqueRequestFormatType0
from .preload_control_in import PreloadControlIn
from .preload_control_in_tip import PreloadControlInTip
from .preloads_for_load_request import PreloadsForLoadRequest
from .preloads_for_load_request_boundary import PreloadsForLoadRequestBoundary
from .preloads_out import PreloadsOut
from .preloads_out_spring_states_type_0_item_item import PreloadsOutSpringStatesType0ItemItem
from .preloads_request import PreloadsRequest
from .preloads_request_objective import PreloadsRequestObjective
from .processes_state import ProcessesState
from .processes_state_state import ProcessesStateState
from .ready import Ready
from .ready_degraded_item import ReadyDegradedItem
from .ready_processes import ReadyProcesses
from .ready_status import ReadyStatus
from .rest_configurations_request import RestConfigurationsRequest
from .rest_configurations_request_method import RestConfigurationsRequestMethod
from .rest_length_bounds_in import RestLengthBoundsIn
from .root_box_out import RootBoxOut
from .root_box_out_reason import RootBoxOutReason
from .segment_in import SegmentIn
from .segment_in_spring import SegmentInSpring
from .segment_out import SegmentOut
from .segment_torque_out import SegmentTorqueOut
from .segment_torque_request import SegmentTorqueRequest
from .segmented_manipulator_in import SegmentedManipulatorIn
from .simulation_event_out import SimulationEventOut
from .simulation_event_out_kind import SimulationEventOutKind
from .simulation_event_out_status import SimulationEventOutStatus
from .simulation_out import SimulationOut
from .simulation_out_mode import SimulationOutMode
from .simulation_out_spring_states_type_0_item_type_0_item_item import SimulationOutSpringStatesType0ItemType0ItemItem
from .simulation_out_status import SimulationOutStatus
from .simulation_request import SimulationRequest
from .simulation_request_tip import SimulationRequestTip
from .solver_info import SolverInfo
from .stability_boundary_out import StabilityBoundaryOut
from .stability_boundary_out_kind import StabilityBoundaryOutKind
from .stability_boundary_out_status import StabilityBoundaryOutStatus
from .stability_boundary_request import StabilityBoundaryRequest
from .start_deflection import StartDeflection
from .start_q import StartQ
from .stiffness_bound_in import StiffnessBoundIn
from .stiffness_bounds_in import StiffnessBoundsIn
from .stiffness_design_out import StiffnessDesignOut
from .stiffness_design_out_bounds_k import StiffnessDesignOutBoundsK
from .stiffness_design_out_manipulator import StiffnessDesignOutManipulator
from .stiffness_design_out_spring_states_type_0_item_item import StiffnessDesignOutSpringStatesType0ItemItem
from .stiffness_design_out_status import StiffnessDesignOutStatus
from .stiffness_design_request import StiffnessDesignRequest
from .stiffness_out import StiffnessOut
from .stiffness_request import StiffnessRequest
from .sweep_bounds_in import SweepBoundsIn
from .sweep_grid import SweepGrid
from .sweep_options import SweepOptions
from .sweep_options_boundary import SweepOptionsBoundary
from .sweep_options_bounds import SweepOptionsBounds
from .sweep_options_budget import SweepOptionsBudget
from .sweep_options_method import SweepOptionsMethod
from .sweep_options_vary_item import SweepOptionsVaryItem
from .sweep_point import SweepPoint
from .sweep_segmented_manipulator import SweepSegmentedManipulator
from .sweep_tension_in import SweepTensionIn
from .sweep_uniform_manipulator import SweepUniformManipulator
from .sweep_uniform_manipulator_spring import SweepUniformManipulatorSpring
from .target import Target
from .tension_bounds_in import TensionBoundsIn
from .traced_branch_out import TracedBranchOut
from .traced_branch_out_spring_states_type_0_item_type_0_item_item import (
    TracedBranchOutSpringStatesType0ItemType0ItemItem,
)
from .traced_branch_out_status import TracedBranchOutStatus
from .uniform_manipulator_in import UniformManipulatorIn
from .uniform_manipulator_in_spring import UniformManipulatorInSpring
from .version_out import VersionOut
from .wall_control_in import WallControlIn
from .weight_capacity_out import WeightCapacityOut
from .weight_capacity_out_kind import WeightCapacityOutKind
from .weight_capacity_out_reason_type_0 import WeightCapacityOutReasonType0
from .weight_capacity_out_start import WeightCapacityOutStart
from .weight_capacity_request import WeightCapacityRequest

__all__ = (
    "ActiveBoundOut",
    "ActiveBoundOutSide",
    "AngleRange",
    "AtlasCrossingOut",
    "AtlasCrossingOutKind",
    "AtlasCurvesOut",
    "AtlasOut",
    "AtlasOutStatus",
    "AtlasRange",
    "AtlasRequest",
    "AtlasRequestMethod",
    "AtlasTargetOut",
    "AtlasTargetOutStatus",
    "AtlasUnresolvedOut",
    "BatchEquilibriumRequest",
    "BatchItem",
    "BatchOut",
    "BifurcationDiagramOut",
    "BifurcationDiagramRequest",
    "BoundsIn",
    "BranchEventOut",
    "BranchEventOutKind",
    "BranchEventOutSpringStatesType0ItemItem",
    "BranchEventOutStability",
    "BranchOut",
    "BranchPoint",
    "BranchPointSpringStatesType0ItemItem",
    "BranchRequest",
    "BranchRequestOrientation",
    "BranchRequestStopAtType0",
    "BucklingOut",
    "BucklingOutBoundary",
    "BucklingRequest",
    "BucklingRequestBoundary",
    "ControlOut",
    "ControlOutKind",
    "ControlOutTipType0",
    "CurveEndOut",
    "CurvePoint",
    "CurvePointSpringStatesType0ItemItem",
    "CurvePointStatus",
    "CuspOut",
    "DeflectionRange",
    "DesignCriticalForceRequest",
    "DesignCriticalForceRequestBoundary",
    "DesignCriticalForceRequestBounds",
    "DesignCriticalForceRequestBudget",
    "DesignCriticalForceRequestVaryItem",
    "DesignOut",
    "DesignOutStatus",
    "DesignSegmentedManipulatorIn",
    "DesignUniformManipulatorIn",
    "DesignUniformManipulatorInSpring",
    "DisplacementControlIn",
    "EnergyBoundOut",
    "EnergyBoundOutStatus",
    "EnergyLandscapeOut",
    "EnergyLandscapeRequest",
    "EquilibriaOut",
    "EquilibriaOutStatus",
    "EquilibriaRequest",
    "EquilibriaRequestMethod",
    "EquilibriumOut",
    "EquilibriumOutKind",
    "EquilibriumOutSpringStatesType0ItemItem",
    "EquilibriumOutStatus",
    "EquilibriumRequest",
    "ErrorOut",
    "ErrorOutBestType0",
    "ErrorOutDetailsType0",
    "FieldError",
    "Force",
    "ForceDeflectionOut",
    "ForceDeflectionOutReference",
    "ForceDeflectionOutStatus",
    "ForceDeflectionRequest",
    "ForceDeflectionRequestBranch",
    "ForceDeflectionRequestReference",
    "ForceEquilibriumRequest",
    "ForceEstimateOut",
    "ForceEstimateOutSpringStatesType0ItemItem",
    "ForceEstimateOutStatus",
    "ForceEstimateRequest",
    "GetJobResultsFormatType0",
    "GuidedControlIn",
    "Health",
    "HoldingOut",
    "HoldingOutManipulator",
    "HoldingOutSpringStatesType0ItemItem",
    "HoldingOutStatus",
    "HoldingOutVaryItem",
    "HoldingRequest",
    "HoldingRequestVaryItem",
    "ImperfectionLawOut",
    "ImperfectionSensitivityOut",
    "ImperfectionSensitivityOutBifurcationType0",
    "ImperfectionSensitivityOutBoundary",
    "ImperfectionSensitivityOutImperfection",
    "ImperfectionSensitivityOutKindsItem",
    "ImperfectionSensitivityOutPerfectKind",
    "ImperfectionSensitivityOutStatus",
    "ImperfectionSensitivityOutStatusesItem",
    "ImperfectionSensitivityRequest",
    "ImperfectionSensitivityRequestBoundary",
    "ImperfectionSensitivityRequestImperfection",
    "IntervalCertificateOut",
    "IntervalCertificateOutControl",
    "IntervalCertificateOutStatus",
    "JobCreated",
    "JobCreatedAnalysis",
    "JobCreatedStatus",
    "JobList",
    "JobOut",
    "JobOutAnalysis",
    "JobOutResultsItem",
    "JobOutSpec",
    "JobOutStatus",
    "JobResults",
    "JobResultsRowsItem",
    "JobResultsStatus",
    "JobsHealth",
    "JobsHealthStatus",
    "JobSpec",
    "JobSpecAnalysis",
    "JobSummary",
    "JobSummaryAnalysis",
    "JobSummaryStatus",
    "JointForceIn",
    "JumpOut",
    "JumpOutKind",
    "KernelsOut",
    "LimitLoadOut",
    "LimitLoadOutBoundary",
    "LimitLoadOutBranchStatus",
    "LimitLoadOutKind",
    "LimitLoadOutSpringStatesType0ItemItem",
    "LimitLoadOutStatus",
    "LimitLoadRequest",
    "LimitLoadRequestBoundary",
    "Limits",
    "ListJobsStatusType0",
    "LoadCapacityOut",
    "LoadCapacityOutManipulator",
    "LoadCapacityOutStart",
    "LoadCapacityOutStatus",
    "LoadCapacityOutWeakestType0",
    "LoadCapacityRequest",
    "LoadCapacityRequestBoundary",
    "LoadControlIn",
    "LoadsOut",
    "ManipulatorOut",
    "MapValuesRange",
    "ModeOut",
    "ModesOut",
    "ModesOutStatus",
    "ModesOutTip",
    "ModesRequest",
    "ModesRequestTipType0",
    "PlanOut",
    "PlanOutMethodItem",
    "PlanOutObjective",
    "PlanOutOnInfeasible",
    "PlanOutOnSnap",
    "PlanOutSpringStatesType0ItemType0ItemItem",
    "PlanOutStatus",
    "PlanRequest",
    "PlanRequestObjective",
    "PlanRequestOnInfeasible",
    "PlanRequestOnSnap",
    "PlanStepOut",
    "PlanStepOutMethod",
    "PlanStepOutSpringStatesType0ItemItem",
    "PlanStepOutStatus",
    "PlotAngleRange",
    "PlotAtlasGridRequest",
    "PlotAtlasGridRequestFormatType0",
    "PlotAtlasGridRequestMethod",
    "PlotAtlasJobRequest",
    "PlotAtlasJobRequestFormatType0",
    "PlotBoundaryRequest",
    "PlotBoundaryRequestFormatType0",
    "PlotBranchRequest",
    "PlotBranchRequestFormatType0",
    "PlotBranchRequestOrientation",
    "PlotBranchRequestStopAtType0",
    "PlotCurveRequest",
    "PlotCurveRequestBranch",
    "PlotCurveRequestFormatType0",
    "PlotHoldingRequest",
    "PlotHoldingRequestFormatType0",
    "PlotHoldingRequestVaryItem",
    "PlotImperfectionRequest",
    "PlotImperfectionRequestBoundary",
    "PlotImperfectionRequestFormatType0",
    "PlotImperfectionRequestImperfection",
    "PlotLandscapeRequest",
    "PlotLandscapeRequestFormatType0",
    "PlotLimitLoadRequest",
    "PlotLimitLoadRequestBoundary",
    "PlotLimitLoadRequestFormatType0",
    "PlotMapRequest",
    "PlotMapRequestBoundary",
    "PlotMapRequestFormatType0",
    "PlotMapRequestParamX",
    "PlotMapRequestParamY",
    "PlotModesRequest",
    "PlotModesRequestFormatType0",
    "PlotModesRequestTipType0",
    "PlotPlanRequest",
    "PlotPlanRequestFormatType0",
    "PlotPlanRequestObjective",
    "PlotPlanRequestOnInfeasible",
    "PlotPlanRequestOnSnap",
    "PlotShapesRequest",
    "PlotShapesRequestFormatType0",
    "PlotShapesRequestSpringColors",
    "PlotSimulationRequest",
    "PlotSimulationRequestFormatType0",
    "PlotSimulationRequestTip",
    "PlotTorqueRequest",
    "PlotTorqueRequestFormatType0",
    "PreloadControlIn",
    "PreloadControlInTip",
    "PreloadsForLoadRequest",
    "PreloadsForLoadRequestBoundary",
    "PreloadsOut",
    "PreloadsOutSpringStatesType0ItemItem",
    "PreloadsRequest",
    "PreloadsRequestObjective",
    "ProcessesState",
    "ProcessesStateState",
    "Ready",
    "ReadyDegradedItem",
    "ReadyProcesses",
    "ReadyStatus",
    "RestConfigurationsRequest",
    "RestConfigurationsRequestMethod",
    "RestLengthBoundsIn",
    "RootBoxOut",
    "RootBoxOutReason",
    "SegmentedManipulatorIn",
    "SegmentIn",
    "SegmentInSpring",
    "SegmentOut",
    "SegmentTorqueOut",
    "SegmentTorqueRequest",
    "SimulationEventOut",
    "SimulationEventOutKind",
    "SimulationEventOutStatus",
    "SimulationOut",
    "SimulationOutMode",
    "SimulationOutSpringStatesType0ItemType0ItemItem",
    "SimulationOutStatus",
    "SimulationRequest",
    "SimulationRequestTip",
    "SolverInfo",
    "StabilityBoundaryOut",
    "StabilityBoundaryOutKind",
    "StabilityBoundaryOutStatus",
    "StabilityBoundaryRequest",
    "StartDeflection",
    "StartQ",
    "StiffnessBoundIn",
    "StiffnessBoundsIn",
    "StiffnessDesignOut",
    "StiffnessDesignOutBoundsK",
    "StiffnessDesignOutManipulator",
    "StiffnessDesignOutSpringStatesType0ItemItem",
    "StiffnessDesignOutStatus",
    "StiffnessDesignRequest",
    "StiffnessOut",
    "StiffnessRequest",
    "SweepBoundsIn",
    "SweepGrid",
    "SweepOptions",
    "SweepOptionsBoundary",
    "SweepOptionsBounds",
    "SweepOptionsBudget",
    "SweepOptionsMethod",
    "SweepOptionsVaryItem",
    "SweepPoint",
    "SweepSegmentedManipulator",
    "SweepTensionIn",
    "SweepUniformManipulator",
    "SweepUniformManipulatorSpring",
    "Target",
    "TensionBoundsIn",
    "TracedBranchOut",
    "TracedBranchOutSpringStatesType0ItemType0ItemItem",
    "TracedBranchOutStatus",
    "UniformManipulatorIn",
    "UniformManipulatorInSpring",
    "VersionOut",
    "WallControlIn",
    "WeightCapacityOut",
    "WeightCapacityOutKind",
    "WeightCapacityOutReasonType0",
    "WeightCapacityOutStart",
    "WeightCapacityRequest",
)
