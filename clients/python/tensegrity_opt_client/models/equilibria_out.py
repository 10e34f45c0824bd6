from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.equilibria_out_status import EquilibriaOutStatus

if TYPE_CHECKING:
    from ..models.equilibrium_out import EquilibriumOut
    from ..models.interval_certificate_out import IntervalCertificateOut


T = TypeVar("T", bound="EquilibriaOut")


@_attrs_define
class EquilibriaOut:
    """Every equilibrium found and what the set claims (`tensegrity_opt.EquilibriumSet`).

    Attributes:
        certificate (IntervalCertificateOut | None): the homotopy's interval proofs of its equilibria (null for the
            other methods); `certified` needs every equilibrium proven
        certified (bool): true only when the set is proven complete (`status` `certified` or `exact`)
        equilibria (list[EquilibriumOut]): every equilibrium found, sorted by energy (under a dead load: by the total
            potential E - F . tip)
        failed_paths (int): homotopy paths that failed (any makes `certified` false)
        message (str): what happened, in a sentence
        method (str): how they were found: `search`, `homotopy`, `exact` (the unloaded chain), or `straight` /
            `closed_form` for the trivial cases
        paths (int): homotopy paths tracked (0 for the search)
        status (EquilibriaOutStatus): `certified`: the polynomial homotopy proved the set complete: every path ended,
            every real root inside the range polished onto an equilibrium, no two distinct roots merged, and every
            equilibrium proven by Krawczyk's test in ball arithmetic (the only one in its box, real, inside the range, the
            boxes pairwise disjoint: certificate); for tension-only springs (and stops=True), one homotopy per
            taut/slack/stop pattern that may reach the target, each complete, without interval boxes (certificate null);
            `uncertified`: the polynomial homotopy ran but did not prove the set complete (a path failed, its report did not
            check out, a real root did not polish, or two distinct roots lay closer than the merge tolerance, or an
            equilibrium's interval proof failed: the message says which); every equilibrium listed is one, others may exist;
            `searched`: the multi-start search: complete in practice (measured against the homotopy), never proven; `exact`:
            known exactly: the straight chain at full extension, a single segment, or the unloaded chain (the product of its
            segments' critical points)
        success (bool): whether it worked: `status` is one of certified, exact, searched
    """

    certificate: IntervalCertificateOut | None
    certified: bool
    equilibria: list[EquilibriumOut]
    failed_paths: int
    message: str
    method: str
    paths: int
    status: EquilibriaOutStatus
    success: bool
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        from ..models.interval_certificate_out import IntervalCertificateOut  # noqa: PLC0415

        certificate: dict[str, Any] | None
        if isinstance(self.certificate, IntervalCertificateOut):
            certificate = self.certificate.to_dict()
        else:
            certificate = self.certificate

        certified = self.certified

        equilibria = []
        for equilibria_item_data in self.equilibria:
            equilibria_item = equilibria_item_data.to_dict()
            equilibria.append(equilibria_item)

        failed_paths = self.failed_paths

        message = self.message

        method = self.method

        paths = self.paths

        status = self.status.value

        success = self.success

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "certificate": certificate,
                "certified": certified,
                "equilibria": equilibria,
                "failed_paths": failed_paths,
                "message": message,
                "method": method,
                "paths": paths,
                "status": status,
                "success": success,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.equilibrium_out import EquilibriumOut  # noqa: PLC0415
        from ..models.interval_certificate_out import IntervalCertificateOut  # noqa: PLC0415

        d = dict(src_dict)

        def _parse_certificate(data: object) -> IntervalCertificateOut | None:
            if data is None:
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                certificate_type_0 = IntervalCertificateOut.from_dict(data)

                return certificate_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(IntervalCertificateOut | None, data)

        certificate = _parse_certificate(d.pop("certificate"))

        certified = d.pop("certified")

        equilibria = []
        _equilibria = d.pop("equilibria")
        for equilibria_item_data in _equilibria:
            equilibria_item = EquilibriumOut.from_dict(equilibria_item_data)

            equilibria.append(equilibria_item)

        failed_paths = d.pop("failed_paths")

        message = d.pop("message")

        method = d.pop("method")

        paths = d.pop("paths")

        status = EquilibriaOutStatus(d.pop("status"))

        success = d.pop("success")

        equilibria_out = cls(
            certificate=certificate,
            certified=certified,
            equilibria=equilibria,
            failed_paths=failed_paths,
            message=message,
            method=method,
            paths=paths,
            status=status,
            success=success,
        )

        equilibria_out.additional_properties = d
        return equilibria_out

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
