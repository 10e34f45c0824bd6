from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.stability_boundary_out_kind_type_0 import StabilityBoundaryOutKindType0
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.cusp_out import CuspOut


T = TypeVar("T", bound="StabilityBoundaryOut")


@_attrs_define
class StabilityBoundaryOut:
    """`StabilityBoundary.to_dict()` of the library (`tensegrity_opt.analyses.paths.boundaries`).

    Attributes:
        cusps (list[CuspOut] | None | Unset):
        force (list[Any] | None | Unset):
        kind (None | StabilityBoundaryOutKindType0 | Unset):
        p (list[float | None] | None | Unset):
        parameter (None | str | Unset):
        q (list[Any] | None | Unset):
        status (None | str | Unset):
        success (bool | None | Unset):
        t (list[float | None] | None | Unset):
    """

    cusps: list[CuspOut] | None | Unset = UNSET
    force: list[Any] | None | Unset = UNSET
    kind: None | StabilityBoundaryOutKindType0 | Unset = UNSET
    p: list[float | None] | None | Unset = UNSET
    parameter: None | str | Unset = UNSET
    q: list[Any] | None | Unset = UNSET
    status: None | str | Unset = UNSET
    success: bool | None | Unset = UNSET
    t: list[float | None] | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        cusps: list[dict[str, Any]] | None | Unset
        if isinstance(self.cusps, Unset):
            cusps = UNSET
        elif isinstance(self.cusps, list):
            cusps = []
            for cusps_type_0_item_data in self.cusps:
                cusps_type_0_item = cusps_type_0_item_data.to_dict()
                cusps.append(cusps_type_0_item)

        else:
            cusps = self.cusps

        force: list[Any] | None | Unset
        if isinstance(self.force, Unset):
            force = UNSET
        elif isinstance(self.force, list):
            force = self.force

        else:
            force = self.force

        kind: None | str | Unset
        if isinstance(self.kind, Unset):
            kind = UNSET
        elif isinstance(self.kind, StabilityBoundaryOutKindType0):
            kind = self.kind.value
        else:
            kind = self.kind

        p: list[float | None] | None | Unset
        if isinstance(self.p, Unset):
            p = UNSET
        elif isinstance(self.p, list):
            p = []
            for p_type_0_item_data in self.p:
                p_type_0_item: float | None
                p_type_0_item = p_type_0_item_data
                p.append(p_type_0_item)

        else:
            p = self.p

        parameter: None | str | Unset
        if isinstance(self.parameter, Unset):
            parameter = UNSET
        else:
            parameter = self.parameter

        q: list[Any] | None | Unset
        if isinstance(self.q, Unset):
            q = UNSET
        elif isinstance(self.q, list):
            q = self.q

        else:
            q = self.q

        status: None | str | Unset
        if isinstance(self.status, Unset):
            status = UNSET
        else:
            status = self.status

        success: bool | None | Unset
        if isinstance(self.success, Unset):
            success = UNSET
        else:
            success = self.success

        t: list[float | None] | None | Unset
        if isinstance(self.t, Unset):
            t = UNSET
        elif isinstance(self.t, list):
            t = []
            for t_type_0_item_data in self.t:
                t_type_0_item: float | None
                t_type_0_item = t_type_0_item_data
                t.append(t_type_0_item)

        else:
            t = self.t

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({})
        if cusps is not UNSET:
            field_dict["cusps"] = cusps
        if force is not UNSET:
            field_dict["force"] = force
        if kind is not UNSET:
            field_dict["kind"] = kind
        if p is not UNSET:
            field_dict["p"] = p
        if parameter is not UNSET:
            field_dict["parameter"] = parameter
        if q is not UNSET:
            field_dict["q"] = q
        if status is not UNSET:
            field_dict["status"] = status
        if success is not UNSET:
            field_dict["success"] = success
        if t is not UNSET:
            field_dict["t"] = t

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.cusp_out import CuspOut  # noqa: PLC0415

        d = dict(src_dict)

        def _parse_cusps(data: object) -> list[CuspOut] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                cusps_type_0 = []
                _cusps_type_0 = data
                for cusps_type_0_item_data in _cusps_type_0:
                    cusps_type_0_item = CuspOut.from_dict(cusps_type_0_item_data)

                    cusps_type_0.append(cusps_type_0_item)

                return cusps_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[CuspOut] | None | Unset, data)

        cusps = _parse_cusps(d.pop("cusps", UNSET))

        def _parse_force(data: object) -> list[Any] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                force_type_0 = cast(list[Any], data)

                return force_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[Any] | None | Unset, data)

        force = _parse_force(d.pop("force", UNSET))

        def _parse_kind(data: object) -> None | StabilityBoundaryOutKindType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                kind_type_0 = StabilityBoundaryOutKindType0(data)

                return kind_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | StabilityBoundaryOutKindType0 | Unset, data)

        kind = _parse_kind(d.pop("kind", UNSET))

        def _parse_p(data: object) -> list[float | None] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                p_type_0 = []
                _p_type_0 = data
                for p_type_0_item_data in _p_type_0:

                    def _parse_p_type_0_item(data: object) -> float | None:
                        if data is None:
                            return data
                        return cast(float | None, data)

                    p_type_0_item = _parse_p_type_0_item(p_type_0_item_data)

                    p_type_0.append(p_type_0_item)

                return p_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float | None] | None | Unset, data)

        p = _parse_p(d.pop("p", UNSET))

        def _parse_parameter(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        parameter = _parse_parameter(d.pop("parameter", UNSET))

        def _parse_q(data: object) -> list[Any] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                q_type_0 = cast(list[Any], data)

                return q_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[Any] | None | Unset, data)

        q = _parse_q(d.pop("q", UNSET))

        def _parse_status(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        status = _parse_status(d.pop("status", UNSET))

        def _parse_success(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        success = _parse_success(d.pop("success", UNSET))

        def _parse_t(data: object) -> list[float | None] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                t_type_0 = []
                _t_type_0 = data
                for t_type_0_item_data in _t_type_0:

                    def _parse_t_type_0_item(data: object) -> float | None:
                        if data is None:
                            return data
                        return cast(float | None, data)

                    t_type_0_item = _parse_t_type_0_item(t_type_0_item_data)

                    t_type_0.append(t_type_0_item)

                return t_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float | None] | None | Unset, data)

        t = _parse_t(d.pop("t", UNSET))

        stability_boundary_out = cls(
            cusps=cusps,
            force=force,
            kind=kind,
            p=p,
            parameter=parameter,
            q=q,
            status=status,
            success=success,
            t=t,
        )

        stability_boundary_out.additional_properties = d
        return stability_boundary_out

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
