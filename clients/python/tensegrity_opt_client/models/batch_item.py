from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

if TYPE_CHECKING:
    from ..models.equilibrium_out import EquilibriumOut
    from ..models.error_out import ErrorOut


T = TypeVar("T", bound="BatchItem")


@_attrs_define
class BatchItem:
    """The result for one target: `equilibrium` or `error` (the other is null).

    Attributes:
        dx (float):
        dy (float):
        equilibrium (EquilibriumOut | None):
        error (ErrorOut | None):
        index (int):
    """

    dx: float
    dy: float
    equilibrium: EquilibriumOut | None
    error: ErrorOut | None
    index: int
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        from ..models.equilibrium_out import EquilibriumOut  # noqa: PLC0415
        from ..models.error_out import ErrorOut  # noqa: PLC0415

        dx = self.dx

        dy = self.dy

        equilibrium: dict[str, Any] | None
        if isinstance(self.equilibrium, EquilibriumOut):
            equilibrium = self.equilibrium.to_dict()
        else:
            equilibrium = self.equilibrium

        error: dict[str, Any] | None
        if isinstance(self.error, ErrorOut):
            error = self.error.to_dict()
        else:
            error = self.error

        index = self.index

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "dx": dx,
                "dy": dy,
                "equilibrium": equilibrium,
                "error": error,
                "index": index,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.equilibrium_out import EquilibriumOut  # noqa: PLC0415
        from ..models.error_out import ErrorOut  # noqa: PLC0415

        d = dict(src_dict)
        dx = d.pop("dx")

        dy = d.pop("dy")

        def _parse_equilibrium(data: object) -> EquilibriumOut | None:
            if data is None:
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                equilibrium_type_0 = EquilibriumOut.from_dict(data)

                return equilibrium_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(EquilibriumOut | None, data)

        equilibrium = _parse_equilibrium(d.pop("equilibrium"))

        def _parse_error(data: object) -> ErrorOut | None:
            if data is None:
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                error_type_0 = ErrorOut.from_dict(data)

                return error_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(ErrorOut | None, data)

        error = _parse_error(d.pop("error"))

        index = d.pop("index")

        batch_item = cls(
            dx=dx,
            dy=dy,
            equilibrium=equilibrium,
            error=error,
            index=index,
        )

        batch_item.additional_properties = d
        return batch_item

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
