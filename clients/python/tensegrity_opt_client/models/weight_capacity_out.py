from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, Literal, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.weight_capacity_out_kind import WeightCapacityOutKind
from ..models.weight_capacity_out_reason_type_0 import WeightCapacityOutReasonType0

if TYPE_CHECKING:
    from ..models.weight_capacity_out_start import WeightCapacityOutStart


T = TypeVar("T", bound="WeightCapacityOut")


@_attrs_define
class WeightCapacityOut:
    """`WeightCapacity.to_dict()`: the gravity multiple at which the rest pose first loses stability.

    Attributes:
        end_factor (float): the last multiple on the stable path
        factor (float | None): the multiple of gravity at the limit (null: none)
        kind (WeightCapacityOutKind):
        max_factor (float):
        message (str): what happened, in a sentence
        q (list[float]): the configuration there (rad)
        reason (None | WeightCapacityOutReasonType0):
        start (WeightCapacityOutStart):
        status (Literal['complete']): `complete`: the path of growing weights was followed to its first loss of
            stability, a joint's range bound or max_factor
        success (bool): whether it worked: `status` is one of complete
    """

    end_factor: float
    factor: float | None
    kind: WeightCapacityOutKind
    max_factor: float
    message: str
    q: list[float]
    reason: None | WeightCapacityOutReasonType0
    start: WeightCapacityOutStart
    status: Literal["complete"]
    success: bool
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        end_factor = self.end_factor

        factor: float | None
        factor = self.factor

        kind = self.kind.value

        max_factor = self.max_factor

        message = self.message

        q = self.q

        reason: None | str
        if isinstance(self.reason, WeightCapacityOutReasonType0):
            reason = self.reason.value
        else:
            reason = self.reason

        start = self.start.to_dict()

        status = self.status

        success = self.success

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "end_factor": end_factor,
                "factor": factor,
                "kind": kind,
                "max_factor": max_factor,
                "message": message,
                "q": q,
                "reason": reason,
                "start": start,
                "status": status,
                "success": success,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.weight_capacity_out_start import WeightCapacityOutStart  # noqa: PLC0415

        d = dict(src_dict)
        end_factor = d.pop("end_factor")

        def _parse_factor(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        factor = _parse_factor(d.pop("factor"))

        kind = WeightCapacityOutKind(d.pop("kind"))

        max_factor = d.pop("max_factor")

        message = d.pop("message")

        q = cast(list[float], d.pop("q"))

        def _parse_reason(data: object) -> None | WeightCapacityOutReasonType0:
            if data is None:
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                reason_type_0 = WeightCapacityOutReasonType0(data)

                return reason_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | WeightCapacityOutReasonType0, data)

        reason = _parse_reason(d.pop("reason"))

        start = WeightCapacityOutStart.from_dict(d.pop("start"))

        status = cast(Literal["complete"], d.pop("status"))
        if status != "complete":
            raise ValueError(f"status must match const 'complete', got '{status}'")

        success = d.pop("success")

        weight_capacity_out = cls(
            end_factor=end_factor,
            factor=factor,
            kind=kind,
            max_factor=max_factor,
            message=message,
            q=q,
            reason=reason,
            start=start,
            status=status,
            success=success,
        )

        weight_capacity_out.additional_properties = d
        return weight_capacity_out

    @property
    def additional_keys(self) -> list[str]:
        return list(self.additional_properties.keys())

    def __getitem__(self, key: str) -> Any:
        return self.additional_properties[key]

    def __setitem__(self, key: str, value: Any) -> None:
        self.additional_properties[key] = value

    def __delitem__(self, key: str) -> None:
        del self.additional_properties[key]

    def __contains__(self, key: str) -> bool:
        return key in self.additional_properties
