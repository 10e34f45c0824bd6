"""The HTTP bodies carry the result contract: every answer that is a library result has ``success``, ``status``
(the library class's closed vocabulary, as an enum) and ``message``, required, in the committed OpenAPI document."""

from __future__ import annotations

import json
from pathlib import Path

import tensegrity_opt as to
from tensegrity_opt import results
from tensegrity_opt.analyses.paths.atlas import AtlasTarget
from tensegrity_opt.analyses.paths.curves import POINT_STATUSES, CurveEnd

SPEC = json.loads((Path(__file__).resolve().parents[2] / "openapi" / "openapi.json").read_text())
SCHEMAS = SPEC["components"]["schemas"]

#: Response schema -> the library result it is the body of.
BODIES = {
    "EquilibriumOut": to.Equilibrium, "EquilibriaOut": to.EquilibriumSet, "BucklingOut": to.Buckling,
    "EnergyLandscapeOut": to.Landscape, "ForceDeflectionOut": to.Curve, "TracedBranchOut": to.Branch,
    "LimitLoadOut": to.LimitLoad, "ImperfectionSensitivityOut": to.ImperfectionSensitivity,
    "StabilityBoundaryOut": to.StabilityBoundary, "AtlasOut": to.StabilityAtlas,
    "SimulationOut": to.Simulation, "DesignOut": to.Design, "PreloadsOut": to.PreloadDesign,
    "StiffnessDesignOut": to.StiffnessDesign, "HoldingOut": to.HoldingDesign, "PlanOut": to.PreloadPlan,
    "LoadCapacityOut": to.LoadCapacity, "WeightCapacityOut": to.WeightCapacity,
    "ForceEstimateOut": to.ForceEstimate, "CurveEndOut": results.CurveEnd, "PlanStepOut": results.PreloadStep,
    "SimulationEventOut": results.SimulationEvent, "AtlasTargetOut": results.AtlasTarget,
}
#: 200 bodies of POST /v1 that are compositions, not one library result (their parts carry the contract: a batch's
#: items, a diagram's branches, a stiffness answer's equilibrium) or a plain evaluation (the segment's torque table),
#: or a job's record.
COMPOSITIONS = {"BatchOut", "BifurcationDiagramOut", "StiffnessOut", "ModesOut",
                "SegmentTorqueOut", "JobCreated", "JobSummary"}


def _status_values(schema: dict) -> set[str]:
    st = schema["properties"]["status"]
    if "enum" in st:
        return set(st["enum"])
    if "const" in st:
        return {st["const"]}
    return {v for alt in st.get("anyOf", []) for v in alt.get("enum", [alt.get("const")])}


def test_every_result_body_has_the_three_fields_and_the_librarys_vocabulary():
    for name, cls in BODIES.items():
        schema = SCHEMAS[name]
        assert {"success", "status", "message"} <= set(schema["properties"]), name
        assert {"success", "status", "message"} <= set(schema.get("required", [])), name
        assert _status_values(schema) == set(cls.STATUSES), name


def test_every_json_answer_of_the_api_is_a_result_body_or_a_named_composition():
    for path, ops in SPEC["paths"].items():
        op = ops.get("post")
        if not path.startswith("/v1/") or op is None or path.startswith("/v1/plots/"):
            continue
        ok = op["responses"].get("200") or op["responses"].get("202")
        ref = ok["content"]["application/json"]["schema"]["$ref"].rsplit("/", 1)[-1]
        assert ref in BODIES or ref in COMPOSITIONS, (path, ref)


def test_the_http_models_carry_the_vocabularies():
    from service import schemas as s

    for model, cls in ((s.ForceDeflectionOut, to.Curve), (s.TracedBranchOut, to.Branch),
                       (s.LimitLoadOut, to.LimitLoad), (s.StabilityBoundaryOut, to.StabilityBoundary),
                       (s.AtlasOut, to.StabilityAtlas), (s.AtlasTargetOut, AtlasTarget),
                       (s.SimulationOut, to.Simulation), (s.SimulationEventOut, to.results.SimulationEvent),
                       (s.CurveEndOut, CurveEnd), (s.IntervalCertificateOut, results.IntervalCertificate)):
        assert list(model.model_fields)[:3] == ["success", "status", "message"], model
        assert set(model.model_fields["status"].annotation.__args__) == set(cls.STATUSES), model
    assert set(s.CurvePoint.model_fields["status"].annotation.__args__) == set(POINT_STATUSES)
