from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.error_out_best_type_0 import ErrorOutBestType0
    from ..models.error_out_details_type_0 import ErrorOutDetailsType0
    from ..models.field_error import FieldError


T = TypeVar("T", bound="ErrorOut")


@_attrs_define
class ErrorOut:
    """Every refusal has this shape.

    Attributes:
        code (str): machine-readable reason, e.g. validation_error, unreachable_target, straight_not_equilibrium,
            straight_unstable, too_many_segments, too_many_points, too_many_steps, solver_failed, no_equilibrium, timeout,
            overloaded, body_too_large, unauthorized
        message (str): human-readable explanation
        best (ErrorOutBestType0 | None | Unset): design_infeasible only: the best point IPOPT found
        details (ErrorOutDetailsType0 | None | Unset): extra numbers (e.g. distance and reach)
        errors (list[FieldError] | None | Unset): every schema violation (validation_error only)
        field (None | str | Unset): the input to blame, when there is one
        status (None | str | Unset): solver return status(es), for solver failures
    """

    code: str
    message: str
    best: ErrorOutBestType0 | None | Unset = UNSET
    details: ErrorOutDetailsType0 | None | Unset = UNSET
    errors: list[FieldError] | None | Unset = UNSET
    field: None | str | Unset = UNSET
    status: None | str | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        from ..models.error_out_best_type_0 import ErrorOutBestType0  # noqa: PLC0415
        from ..models.error_out_details_type_0 import ErrorOutDetailsType0  # noqa: PLC0415

        code = self.code

        message = self.message

        best: dict[str, Any] | None | Unset
        if isinstance(self.best, Unset):
            best = UNSET
        elif isinstance(self.best, ErrorOutBestType0):
            best = self.best.to_dict()
        else:
            best = self.best

        details: dict[str, Any] | None | Unset
        if isinstance(self.details, Unset):
            details = UNSET
        elif isinstance(self.details, ErrorOutDetailsType0):
            details = self.details.to_dict()
        else:
            details = self.details

        errors: list[dict[str, Any]] | None | Unset
        if isinstance(self.errors, Unset):
            errors = UNSET
        elif isinstance(self.errors, list):
            errors = []
            for errors_type_0_item_data in self.errors:
                errors_type_0_item = errors_type_0_item_data.to_dict()
                errors.append(errors_type_0_item)

        else:
            errors = self.errors

        field: None | str | Unset
        if isinstance(self.field, Unset):
            field = UNSET
        else:
            field = self.field

        status: None | str | Unset
        if isinstance(self.status, Unset):
            status = UNSET
        else:
            status = self.status

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "code": code,
                "message": message,
            }
        )
        if best is not UNSET:
            field_dict["best"] = best
        if details is not UNSET:
            field_dict["details"] = details
        if errors is not UNSET:
            field_dict["errors"] = errors
        if field is not UNSET:
            field_dict["field"] = field
        if status is not UNSET:
            field_dict["status"] = status

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.error_out_best_type_0 import ErrorOutBestType0  # noqa: PLC0415
        from ..models.error_out_details_type_0 import ErrorOutDetailsType0  # noqa: PLC0415
        from ..models.field_error import FieldError  # noqa: PLC0415

        d = dict(src_dict)
        code = d.pop("code")

        message = d.pop("message")

        def _parse_best(data: object) -> ErrorOutBestType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                best_type_0 = ErrorOutBestType0.from_dict(data)

                return best_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ErrorOutBestType0 | None | Unset, data)

        best = _parse_best(d.pop("best", UNSET))

        def _parse_details(data: object) -> ErrorOutDetailsType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                details_type_0 = ErrorOutDetailsType0.from_dict(data)

                return details_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ErrorOutDetailsType0 | None | Unset, data)

        details = _parse_details(d.pop("details", UNSET))

        def _parse_errors(data: object) -> list[FieldError] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                errors_type_0 = []
                _errors_type_0 = data
                for errors_type_0_item_data in _errors_type_0:
                    errors_type_0_item = FieldError.from_dict(errors_type_0_item_data)

                    errors_type_0.append(errors_type_0_item)

                return errors_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[FieldError] | None | Unset, data)

        errors = _parse_errors(d.pop("errors", UNSET))

        def _parse_field(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        field = _parse_field(d.pop("field", UNSET))

        def _parse_status(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        status = _parse_status(d.pop("status", UNSET))

        error_out = cls(
            code=code,
            message=message,
            best=best,
            details=details,
            errors=errors,
            field=field,
            status=status,
        )

        error_out.additional_properties = d
        return error_out

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
