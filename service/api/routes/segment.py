"""One segment's torque curve."""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import APIRouter, Body, Request

from ... import examples as ex
from ... import schemas as s
from ...adapters.fields import FieldContext
from ...tasks.equilibria import segment_torque_task
from ..dispatch import run_task
from ..json_bodies import JSONBodyRoute
from ..openapi import error_responses, ok_response

router = APIRouter(route_class=JSONBodyRoute, prefix="/v1", tags=["segment"])


@router.post(
    "/segment/torque", operation_id="segment_torque", response_model=s.SegmentTorqueOut,
    summary="Torque M(q), its derivative and the energy of one segment",
    description="Evaluates `Segment.torque`, `Segment.dtorque` and `Segment.energy` at the angles `q` (a list or "
                f"`{{start, stop, num}}`, at most {s.MAX_TORQUE_POINTS} points), with the joint stiffness "
                "`K = E''(0)`, whether `M(q)` is monotonic over the physical range, and that range.",
    responses={**ok_response(ex.SEGMENT_TORQUE), **error_responses(401, 413, 422, 503, 504)})
async def segment_torque(
    request: Request,
    req: Annotated[s.SegmentTorqueRequest, Body(openapi_examples={
        "list": {"summary": "three angles", "value": {"segment": {"a": 1.0, "b": 1.0, "k": 1.0, "L0": 1.0},
                                                      "q": [-0.5, 0.0, 0.5]}},
        "range": {"summary": "asymmetric springs over a range", "value": {
            "segment": {"a": 1.0, "b": 1.0, "k": [1.0, 2.0], "L0": [1.0, 1.2]},
            "q": {"start": -1.0, "stop": 1.0, "num": 5}}}})],
) -> Any:
    return await run_task(request, segment_torque_task, req, fields=FieldContext(segment=True), size_field="q")
