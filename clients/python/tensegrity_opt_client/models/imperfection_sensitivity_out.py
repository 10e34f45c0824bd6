from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.imperfection_sensitivity_out_bifurcation_type_0 import ImperfectionSensitivityOutBifurcationType0
from ..models.imperfection_sensitivity_out_boundary import ImperfectionSensitivityOutBoundary
from ..models.imperfection_sensitivity_out_imperfection import ImperfectionSensitivityOutImperfection
from ..models.imperfection_sensitivity_out_kinds_item import ImperfectionSensitivityOutKindsItem
from ..models.imperfection_sensitivity_out_perfect_kind import ImperfectionSensitivityOutPerfectKind
from ..models.imperfection_sensitivity_out_status import ImperfectionSensitivityOutStatus
from ..models.imperfection_sensitivity_out_statuses_item import ImperfectionSensitivityOutStatusesItem
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.imperfection_law_out import ImperfectionLawOut
    from ..models.limit_load_out import LimitLoadOut


T = TypeVar("T", bound="ImperfectionSensitivityOut")


@_attrs_define
class ImperfectionSensitivityOut:
    """The imperfection-sensitivity curve: per amplitude the limit load and its kind.

    Attributes:
        amplitudes (list[float]):
        bifurcation (ImperfectionSensitivityOutBifurcationType0 | None): the given chain's bifurcation by its buckled
            arms (null: its limit is not a bifurcation)
        boundary (ImperfectionSensitivityOutBoundary):
        direction (list[float]):
        imperfection (ImperfectionSensitivityOutImperfection):
        kinds (list[ImperfectionSensitivityOutKindsItem]): fold, bifurcation, joint_limit, none (stable to max_load),
            unknown (the path was cut, or time ran out before it)
        law (ImperfectionLawOut | None): the fitted small-imperfection law, where one applies
        loads (list[float | None]): the limit load per amplitude (a joint limit: the load where the stable path reaches
            it; null for kind none or unknown)
        max_load (float | None):
        message (str): what happened, in a sentence
        messages (list[str]):
        perfect_kind (ImperfectionSensitivityOutPerfectKind):
        perfect_load (float | None): the given chain's limit load
        status (ImperfectionSensitivityOutStatus): `complete`: every amplitude's path was followed to its limit point or
            its end; `partial`: some amplitude's path was cut, could not be followed or lost stability at no located limit
            point (kind unknown); `time_limit`: the time limit ran out before every amplitude was computed (those computed
            are kept)
        statuses (list[ImperfectionSensitivityOutStatusesItem]): per amplitude the limit load's status, failed (its
            chain could not be followed) or not_computed (time ran out before it)
        success (bool): whether it worked: `status` is one of complete
        limit_loads (list[LimitLoadOut | None] | None | Unset): include_limit_loads only
        perfect (LimitLoadOut | None | Unset): include_limit_loads only: the given chain's limit load
    """

    amplitudes: list[float]
    bifurcation: ImperfectionSensitivityOutBifurcationType0 | None
    boundary: ImperfectionSensitivityOutBoundary
    direction: list[float]
    imperfection: ImperfectionSensitivityOutImperfection
    kinds: list[ImperfectionSensitivityOutKindsItem]
    law: ImperfectionLawOut | None
    loads: list[float | None]
    max_load: float | None
    message: str
    messages: list[str]
    perfect_kind: ImperfectionSensitivityOutPerfectKind
    perfect_load: float | None
    status: ImperfectionSensitivityOutStatus
    statuses: list[ImperfectionSensitivityOutStatusesItem]
    success: bool
    limit_loads: list[LimitLoadOut | None] | None | Unset = UNSET
    perfect: LimitLoadOut | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        from ..models.imperfection_law_out import ImperfectionLawOut  # noqa: PLC0415
        from ..models.limit_load_out import LimitLoadOut  # noqa: PLC0415

        amplitudes = self.amplitudes

        bifurcation: None | str
        if isinstance(self.bifurcation, ImperfectionSensitivityOutBifurcationType0):
            bifurcation = self.bifurcation.value
        else:
            bifurcation = self.bifurcation

        boundary = self.boundary.value

        direction = self.direction

        imperfection = self.imperfection.value

        kinds = []
        for kinds_item_data in self.kinds:
            kinds_item = kinds_item_data.value
            kinds.append(kinds_item)

        law: dict[str, Any] | None
        if isinstance(self.law, ImperfectionLawOut):
            law = self.law.to_dict()
        else:
            law = self.law

        loads = []
        for loads_item_data in self.loads:
            loads_item: float | None
            loads_item = loads_item_data
            loads.append(loads_item)

        max_load: float | None
        max_load = self.max_load

        message = self.message

        messages = self.messages

        perfect_kind = self.perfect_kind.value

        perfect_load: float | None
        perfect_load = self.perfect_load

        status = self.status.value

        statuses = []
        for statuses_item_data in self.statuses:
            statuses_item = statuses_item_data.value
            statuses.append(statuses_item)

        success = self.success

        limit_loads: list[dict[str, Any] | None] | None | Unset
        if isinstance(self.limit_loads, Unset):
            limit_loads = UNSET
        elif isinstance(self.limit_loads, list):
            limit_loads = []
            for limit_loads_type_0_item_data in self.limit_loads:
                limit_loads_type_0_item: dict[str, Any] | None
                if isinstance(limit_loads_type_0_item_data, LimitLoadOut):
                    limit_loads_type_0_item = limit_loads_type_0_item_data.to_dict()
                else:
                    limit_loads_type_0_item = limit_loads_type_0_item_data
                limit_loads.append(limit_loads_type_0_item)

        else:
            limit_loads = self.limit_loads

        perfect: dict[str, Any] | None | Unset
        if isinstance(self.perfect, Unset):
            perfect = UNSET
        elif isinstance(self.perfect, LimitLoadOut):
            perfect = self.perfect.to_dict()
        else:
            perfect = self.perfect

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "amplitudes": amplitudes,
                "bifurcation": bifurcation,
                "boundary": boundary,
                "direction": direction,
                "imperfection": imperfection,
                "kinds": kinds,
                "law": law,
                "loads": loads,
                "max_load": max_load,
                "message": message,
                "messages": messages,
                "perfect_kind": perfect_kind,
                "perfect_load": perfect_load,
                "status": status,
                "statuses": statuses,
                "success": success,
            }
        )
        if limit_loads is not UNSET:
            field_dict["limit_loads"] = limit_loads
        if perfect is not UNSET:
            field_dict["perfect"] = perfect

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.imperfection_law_out import ImperfectionLawOut  # noqa: PLC0415
        from ..models.limit_load_out import LimitLoadOut  # noqa: PLC0415

        d = dict(src_dict)
        amplitudes = cast(list[float], d.pop("amplitudes"))

        def _parse_bifurcation(data: object) -> ImperfectionSensitivityOutBifurcationType0 | None:
            if data is None:
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                bifurcation_type_0 = ImperfectionSensitivityOutBifurcationType0(data)

                return bifurcation_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ImperfectionSensitivityOutBifurcationType0 | None, data)

        bifurcation = _parse_bifurcation(d.pop("bifurcation"))

        boundary = ImperfectionSensitivityOutBoundary(d.pop("boundary"))

        direction = cast(list[float], d.pop("direction"))

        imperfection = ImperfectionSensitivityOutImperfection(d.pop("imperfection"))

        kinds = []
        _kinds = d.pop("kinds")
        for kinds_item_data in _kinds:
            kinds_item = ImperfectionSensitivityOutKindsItem(kinds_item_data)

            kinds.append(kinds_item)

        def _parse_law(data: object) -> ImperfectionLawOut | None:
            if data is None:
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                law_type_0 = ImperfectionLawOut.from_dict(data)

                return law_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ImperfectionLawOut | None, data)

        law = _parse_law(d.pop("law"))

        loads = []
        _loads = d.pop("loads")
        for loads_item_data in _loads:

            def _parse_loads_item(data: object) -> float | None:
                if data is None:
                    return data
                return cast(float | None, data)

            loads_item = _parse_loads_item(loads_item_data)

            loads.append(loads_item)

        def _parse_max_load(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        max_load = _parse_max_load(d.pop("max_load"))

        message = d.pop("message")

        messages = cast(list[str], d.pop("messages"))

        perfect_kind = ImperfectionSensitivityOutPerfectKind(d.pop("perfect_kind"))

        def _parse_perfect_load(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        perfect_load = _parse_perfect_load(d.pop("perfect_load"))

        status = ImperfectionSensitivityOutStatus(d.pop("status"))

        statuses = []
        _statuses = d.pop("statuses")
        for statuses_item_data in _statuses:
            statuses_item = ImperfectionSensitivityOutStatusesItem(statuses_item_data)

            statuses.append(statuses_item)

        success = d.pop("success")

        def _parse_limit_loads(data: object) -> list[LimitLoadOut | None] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                limit_loads_type_0 = []
                _limit_loads_type_0 = data
                for limit_loads_type_0_item_data in _limit_loads_type_0:

                    def _parse_limit_loads_type_0_item(data: object) -> LimitLoadOut | None:
                        if data is None:
                            return data
                        try:
                            if not isinstance(data, dict):
                                raise TypeError()
                            limit_loads_type_0_item_type_0 = LimitLoadOut.from_dict(data)

                            return limit_loads_type_0_item_type_0
                        except (TypeError, ValueError, AttributeError, KeyError):
                            pass
                        return cast(LimitLoadOut | None, data)

                    limit_loads_type_0_item = _parse_limit_loads_type_0_item(limit_loads_type_0_item_data)

                    limit_loads_type_0.append(limit_loads_type_0_item)

                return limit_loads_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[LimitLoadOut | None] | None | Unset, data)

        limit_loads = _parse_limit_loads(d.pop("limit_loads", UNSET))

        def _parse_perfect(data: object) -> LimitLoadOut | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                perfect_type_0 = LimitLoadOut.from_dict(data)

                return perfect_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(LimitLoadOut | None | Unset, data)

        perfect = _parse_perfect(d.pop("perfect", UNSET))

        imperfection_sensitivity_out = cls(
            amplitudes=amplitudes,
            bifurcation=bifurcation,
            boundary=boundary,
            direction=direction,
            imperfection=imperfection,
            kinds=kinds,
            law=law,
            loads=loads,
            max_load=max_load,
            message=message,
            messages=messages,
            perfect_kind=perfect_kind,
            perfect_load=perfect_load,
            status=status,
            statuses=statuses,
            success=success,
            limit_loads=limit_loads,
            perfect=perfect,
        )

        imperfection_sensitivity_out.additional_properties = d
        return imperfection_sensitivity_out

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
