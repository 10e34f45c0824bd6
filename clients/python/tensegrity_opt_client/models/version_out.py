from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar

from attrs import define as _attrs_define
from attrs import field as _attrs_field

if TYPE_CHECKING:
    from ..models.kernels_out import KernelsOut
    from ..models.limits import Limits


T = TypeVar("T", bound="VersionOut")


@_attrs_define
class VersionOut:
    """
    Attributes:
        api (str):
        auth (bool):
        kernels (KernelsOut): How the compiled Newton kernels run in this server process
            (`tensegrity_opt.numerics.kernels`).
        library_version (str):
        limits (Limits):
        service (str):
        version (str):
    """

    api: str
    auth: bool
    kernels: KernelsOut
    library_version: str
    limits: Limits
    service: str
    version: str
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        api = self.api

        auth = self.auth

        kernels = self.kernels.to_dict()

        library_version = self.library_version

        limits = self.limits.to_dict()

        service = self.service

        version = self.version

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "api": api,
                "auth": auth,
                "kernels": kernels,
                "library_version": library_version,
                "limits": limits,
                "service": service,
                "version": version,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.kernels_out import KernelsOut  # noqa: PLC0415
        from ..models.limits import Limits  # noqa: PLC0415

        d = dict(src_dict)
        api = d.pop("api")

        auth = d.pop("auth")

        kernels = KernelsOut.from_dict(d.pop("kernels"))

        library_version = d.pop("library_version")

        limits = Limits.from_dict(d.pop("limits"))

        service = d.pop("service")

        version = d.pop("version")

        version_out = cls(
            api=api,
            auth=auth,
            kernels=kernels,
            library_version=library_version,
            limits=limits,
            service=service,
            version=version,
        )

        version_out.additional_properties = d
        return version_out

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
