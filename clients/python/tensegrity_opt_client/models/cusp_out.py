from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, Literal, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

if TYPE_CHECKING:
    from ..models.force import Force


T = TypeVar("T", bound="CuspOut")


@_attrs_define
class CuspOut:
    """A cusp of a fold curve: where the fold's quadratic coefficient changes sign.

    Attributes:
        force (Force):
        kind (Literal['cusp']):
        p (float):
        q (list[float]):
        t (float):
    """

    force: Force
    kind: Literal["cusp"]
    p: float
    q: list[float]
    t: float
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        force = self.force.to_dict()

        kind = self.kind

        p = self.p

        q = self.q

        t = self.t

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "force": force,
                "kind": kind,
                "p": p,
                "q": q,
                "t": t,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.force import Force  # noqa: PLC0415

        d = dict(src_dict)
        force = Force.from_dict(d.pop("force"))

        kind = cast(Literal["cusp"], d.pop("kind"))
        if kind != "cusp":
            raise ValueError(f"kind must match const 'cusp', got '{kind}'")

        p = d.pop("p")

        q = cast(list[float], d.pop("q"))

        t = d.pop("t")

        cusp_out = cls(
            force=force,
            kind=kind,
            p=p,
            q=q,
            t=t,
        )

        cusp_out.additional_properties = d
        return cusp_out

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
